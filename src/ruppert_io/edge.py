"""`.edge` files: mesh edges, or Voronoi edges with rays (spec §2.6, §2.8).

```
<#edges> <#markers (0|1)>
<edge#> <endpoint1> <endpoint2> [marker]
<edge#> <endpoint> -1 <dx> <dy> [marker]     # a Voronoi ray (in .v.edge files)
```
A ray's ``-1`` is literal in 0- and 1-based files alike.  Rays come back as
``edges[i, 1] == -1`` with their direction in ``normals[i]`` (zeros for finite edges;
``normals`` is present only when the file has a ray).
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from . import writing
from .lines import INT32_MAX, INT32_MIN, Block, LineReader
from .info import Info



def read_edge(
    path: str | os.PathLike[str],
    *,
    first_index: int | None = None,
    info: Info | None = None,
    nvertices: int | None = None,
) -> dict[str, np.ndarray]:
    """Read ``edges`` (E, 2) int32, ``edge_markers`` (E, 1) and ``normals`` (E, 2).

    ``first_index`` is the numbering base of the matching .node file; when None it
    is taken from the first edge's number (0 or 1, else 1), since Triangle numbers
    every item of a file set from the same base.  With ``nvertices`` every endpoint
    must name an existing vertex.  ``info`` (if given) receives the base used.
    """
    r = LineReader.open(path)
    line = r.next("the number of edges")
    count = r.count_field(line, 0, "the number of edges")
    declared = r.int_field(line, 1, "the number of edge markers", required=False)
    block = r.take(line, count, "edge")
    if first_index is None:
        first_index = r.numbering_base(block, "edge", 1)
    if info is not None:
        info.first_index = first_index
    high = first_index + nvertices - 1 if nvertices is not None else 2**31 - 1
    out = _fast_edges(block, bool(declared), first_index, high)
    return out if out is not None else _slow_edges(r, block, bool(declared), first_index, high)


def _slow_edges(
    r: LineReader, block: Block, declared: bool, first_index: int, high: int
) -> dict[str, np.ndarray]:
    """Line by line, with rays and missing markers."""
    count = len(block)
    edges = np.empty((count, 2), dtype=np.int32)
    normals = np.zeros((count, 2))
    markers = np.zeros((count, 1), dtype=np.int32)
    has_rays = False
    for i, line in enumerate(block):
        name = f"edge {first_index + i}"
        after = 3  # index of the field after the endpoints
        for j, which in enumerate(("first", "second")):
            end = r.index_field(line, 1 + j, f"the {which} endpoint of {name}")
            if j == 1 and end == -1:
                has_rays = True
                edges[i, 1] = -1
                normals[i, 0] = r.real_field(line, 3, f"the ray direction x of {name}")
                normals[i, 1] = r.real_field(line, 4, f"the ray direction y of {name}")
                after = 5
            elif first_index <= end <= high:
                edges[i, j] = end - first_index
            else:
                expected = f"a vertex number from {first_index} to {high}"
                if j == 1:
                    expected += " or -1 (a ray)"
                raise r.error(
                    line, f"{expected} for the {which} endpoint of {name}", found=str(end)
                )
        if declared:
            markers[i, 0] = r.int_field(line, after, f"the marker of {name}", required=False)
    out = {"edges": edges}
    if count and declared:
        out["edge_markers"] = markers
    if has_rays:
        out["normals"] = normals
    return out


def _fast_edges(
    block: Block, declared: bool, first_index: int, high: int
) -> dict[str, np.ndarray] | None:
    """Edges without rays, all columns at once, when every line is plain."""
    ends = block.ints(1, 3)
    if ends is None or (len(ends) and (ends.min() < first_index or ends.max() > high)):
        return None
    out = {"edges": (ends - first_index).astype(np.int32)}
    if declared and len(ends):
        marks = block.ints(3, 4)
        if marks is None or marks.min() < INT32_MIN or marks.max() > INT32_MAX:
            return None
        out["edge_markers"] = marks.astype(np.int32)
    return out


def edge_chunks(
    mesh: Mapping[str, Any], *, first_index: int = 1, markers: bool = True
) -> list[str]:
    """The text of a .edge (or .v.edge) file for ``mesh['edges']``.

    Edges whose second endpoint is -1 are written as rays with ``mesh['normals']``.
    """
    edges = writing.get(mesh, "edges", int, 2)
    if edges is None:
        raise ValueError("the mesh has no 'edges'")
    e = len(edges)
    marks = writing.get(mesh, "edge_markers", int, 1, rows=e) if markers else None
    normals = writing.get(mesh, "normals", float, 2, rows=e)
    rays = edges[:, 1] == -1
    if rays.any() and normals is None:
        raise ValueError("'edges' has rays (-1) but the mesh has no 'normals'")
    chunks = ["%d  %d\n" % (e, int(marks is not None))]
    ends = np.where(edges >= 0, edges + first_index, edges).tolist()
    norm = normals.tolist() if normals is not None else None
    tail = "  %d\n" if marks is not None else "\n"
    mark = marks[:, 0].tolist() if marks is not None else None
    for i in range(e):
        a, b = ends[i]
        # Triangle: "%4ld   %d  %d" (+ "  %d" marker); rays "%4ld   %d  %d   %.17g  %.17g".
        text = "%4d   %d  %d" % (first_index + i, a, b)
        if rays[i]:
            text += "   %.17g  %.17g" % tuple(norm[i])
        chunks.append(text + (tail % mark[i] if mark is not None else tail))
    return chunks


def write_edge(
    path: str | os.PathLike[str],
    mesh: Mapping[str, Any],
    *,
    first_index: int = 1,
    markers: bool = True,
    generated_by: str | None = None,
) -> Path:
    """Write ``mesh['edges']`` (with markers, and rays if any) as a .edge file."""
    chunks = edge_chunks(mesh, first_index=first_index, markers=markers)
    return writing.write_text(path, chunks, generated_by)
