"""`.ele` files: triangles with attributes (spec §2.4).

```
<#triangles> <nodes per triangle (>= 3; 3 or 6 on output)> <#attributes>
<tri#> <n1> <n2> <n3> [n4 n5 n6 ...] [attr ...]
```
With 6 nodes, nodes 4, 5, 6 are the midpoints of the edges opposite corners 1, 2, 3.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from . import writing
from .lines import Block, LineReader


def read_ele(
    path: str | os.PathLike[str], *, first_index: int = 1, nvertices: int | None = None
) -> dict[str, np.ndarray]:
    """Read ``triangles`` (M, nodes) int32 and ``triangle_attributes`` (M, k).

    ``first_index`` is the numbering base of the .node file; every node index must
    name one of its ``nvertices`` vertices (not checked when None, except that it
    may not fall below the base).  Indices are returned 0-based.
    """
    r = LineReader.open(path)
    line = r.next("the number of triangles")
    count = r.count_field(line, 0, "the number of triangles")
    corners = r.int_field(line, 1, "the number of nodes per triangle", required=False, default=3)
    if corners < 3:
        raise r.error(
            line,
            "at least 3 nodes per triangle",
            problem=f"Triangles in {r.path} must have at least 3 vertices",
            found=str(corners),
        )
    k = r.count_field(line, 2, "the number of triangle attributes", default=0)
    r.check_table(line, count, corners, "nodes per triangle")
    r.check_table(line, count, k, "triangle attributes")
    block = r.take(line, count, "triangle")
    # Without the vertex count, still keep indices within int32.
    high = first_index + nvertices - 1 if nvertices is not None else 2**31 - 1
    triangles = block.ints(1, 1 + corners)
    attributes = block.reals(1 + corners, 1 + corners + k) if k else np.zeros((count, 0))
    fast = (
        triangles is not None
        and attributes is not None
        and (count == 0 or (triangles.min() >= first_index and triangles.max() <= high))
    )
    if fast:
        triangles = (triangles - first_index).astype(np.int32)
    else:
        triangles, attributes = _slow_ele(r, block, corners, k, first_index, high)
    out = {"triangles": triangles}
    if count and k:
        out["triangle_attributes"] = attributes
    return out


def _slow_ele(
    r: LineReader, block: Block, corners: int, k: int, first_index: int, high: int
) -> tuple[np.ndarray, np.ndarray]:
    """Line by line, reporting the first bad field."""
    triangles = np.empty((len(block), corners), dtype=np.int32)
    attributes = np.zeros((len(block), k))
    for i, line in enumerate(block):
        name = f"triangle {first_index + i}"
        for j in range(corners):
            index = r.index_field(line, 1 + j, f"vertex {j + 1} of {name}")
            if not first_index <= index <= high:
                raise r.error(
                    line,
                    f"a vertex number from {first_index} to {high}",
                    problem=f"Triangle {first_index + i} has an invalid vertex index",
                    found=str(index),
                )
            triangles[i, j] = index - first_index
        for j in range(k):
            attributes[i, j] = r.real_field(
                line, 1 + corners + j, f"attribute {j + 1} of {name}", required=False
            )
    return triangles, attributes


def ele_chunks(mesh: Mapping[str, Any], *, first_index: int = 1) -> list[str]:
    """The text of a .ele file for ``mesh['triangles']`` (and its attributes)."""
    triangles = writing.get(mesh, "triangles", int)
    if triangles is None:
        raise ValueError("the mesh has no 'triangles'")
    m, corners = triangles.shape
    if m == 0 and corners < 3:  # e.g. an empty 1-D list
        corners = 3
    if corners < 3:
        raise ValueError(f"'triangles' needs at least 3 columns, got {corners}")
    attr = writing.get(mesh, "triangle_attributes", float, rows=m)
    k = 0 if attr is None else attr.shape[1]
    # Triangle: "%ld  %d  %d\n", then "%4ld    %4d  %4d  %4d" (six %4d with -o2)
    # and "  %.17g" per attribute.
    chunks = ["%d  %d  %d\n" % (m, corners, k)]
    fmt = "%4d    " + "  ".join(["%4d"] * corners) + "  %.17g" * k + "\n"
    columns = [range(first_index, first_index + m), *(triangles + first_index).T.tolist()]
    if k:
        columns += attr.T.tolist()
    chunks += [fmt % row for row in zip(*columns)]
    return chunks


def write_ele(
    path: str | os.PathLike[str],
    mesh: Mapping[str, Any],
    *,
    first_index: int = 1,
    generated_by: str | None = None,
) -> Path:
    """Write ``mesh['triangles']`` (3 or 6 nodes each) as a .ele file."""
    return writing.write_text(path, ele_chunks(mesh, first_index=first_index), generated_by)
