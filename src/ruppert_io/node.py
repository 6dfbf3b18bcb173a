"""`.node` files: vertices with attributes and boundary markers (spec §2.2).

```
<#vertices> <dimension=2> <#attributes> <#boundary markers (0|1)>
<vertex#> <x> <y> [attr1 ... attrk] [marker]
```
The vertex lines are shared with `.poly` files, which reuse this module.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from . import writing
from .lines import INT32_MAX, INT32_MIN, Block, Line, LineReader
from .errors import DimensionError
from .info import Info



@dataclass(frozen=True)
class VertexHeader:
    """The first line of a .node or .poly file."""

    line: Line
    count: int
    dimension: int
    attributes: int
    markers: int


def read_vertex_header(r: LineReader) -> VertexHeader:
    """Read ``<#vertices> [dim] [#attributes] [#markers]`` (missing: 2, 0, 0)."""
    line = r.next("the number of vertices")
    return VertexHeader(
        line=line,
        count=r.count_field(line, 0, "the number of vertices"),
        dimension=r.int_field(line, 1, "the dimension", required=False, default=2),
        attributes=r.count_field(line, 2, "the number of vertex attributes", default=0),
        markers=r.int_field(line, 3, "the number of boundary markers", required=False),
    )


def check_dimension(r: LineReader, header: VertexHeader) -> None:
    """Triangle refuses anything but 2-D points (TetGen files are 3-D)."""
    if header.dimension != 2:
        raise DimensionError(
            r.path,
            header.line.number,
            "dimension 2",
            problem="Triangle only works with two-dimensional meshes",
            found=str(header.dimension),
        )


def read_vertices(
    r: LineReader, header: VertexHeader, default_first_index: int
) -> tuple[dict[str, np.ndarray], int]:
    """Read the vertex lines announced by ``header``.

    Returns the arrays and the numbering base: the first vertex's number if it is
    0 or 1, else ``default_first_index``.
    """
    n, k = header.count, header.attributes
    r.check_table(header.line, n, k, "vertex attributes")
    block = r.take(header.line, n, "vertex")
    first = r.numbering_base(block, "vertex", default_first_index)
    columns = _fast_vertices(block, k, bool(header.markers))
    if columns is None:
        columns = _slow_vertices(r, block, k, bool(header.markers), first)
    xy, attributes, markers = columns
    out = {"vertices": xy}
    if n and k:
        out["vertex_attributes"] = attributes
    if n and header.markers:
        out["vertex_markers"] = markers
    return out, first


_Columns = tuple[np.ndarray, np.ndarray, np.ndarray]


def _fast_vertices(block: Block, k: int, markers: bool) -> _Columns | None:
    """All columns at once, when every line is complete and plain."""
    xy = block.reals(1, 3)
    attributes = block.reals(3, 3 + k) if k else np.zeros((len(block), 0))
    marks = block.ints(3 + k, 4 + k) if markers else np.zeros((len(block), 1), np.int64)
    if xy is None or attributes is None or marks is None:
        return None
    if marks.size and not (INT32_MIN <= marks.min() and marks.max() <= INT32_MAX):
        return None
    return xy, attributes, marks.astype(np.int32)


def _slow_vertices(
    r: LineReader, block: Block, k: int, markers: bool, first: int
) -> _Columns:
    """Line by line, with Triangle's defaults for missing optional fields."""
    n = len(block)
    xy = np.empty((n, 2))
    attributes = np.zeros((n, k))
    marks = np.zeros((n, 1), dtype=np.int32)
    for i, line in enumerate(block):
        name = f"vertex {first + i}"
        xy[i, 0] = r.real_field(line, 1, f"the x coordinate of {name}")
        xy[i, 1] = r.real_field(line, 2, f"the y coordinate of {name}")
        for j in range(k):
            attributes[i, j] = r.real_field(
                line, 3 + j, f"attribute {j + 1} of {name}", required=False
            )
        if markers:
            marks[i, 0] = r.int_field(
                line, 3 + k, f"the boundary marker of {name}", required=False
            )
    return xy, attributes, marks


def read_node(
    path: str | os.PathLike[str],
    *,
    default_first_index: int = 1,
    info: Info | None = None,
) -> dict[str, np.ndarray]:
    """Read a .node file: ``vertices`` and, if declared, attributes and markers.

    ``info`` (if given) receives the numbering base and the declared marker count.
    Raises FormatError (DimensionError for a dimension other than 2), or OSError if
    the file cannot be opened.
    """
    r = LineReader.open(path)
    header = read_vertex_header(r)
    check_dimension(r, header)
    out, first = read_vertices(r, header, default_first_index)
    if info is not None:
        info.first_index = first
        info.vertex_markers = header.markers
        info.files.append(Path(path))
        info.vertices_from = Path(path)
    return out


# -- writing ------------------------------------------------------------------


def vertex_chunks(
    mesh: Mapping[str, Any],
    *,
    first_index: int,
    markers: bool,
    header_markers: bool | None = None,
) -> list[str]:
    """The header and vertex lines of a .node file (also used inside a .poly).

    Marker columns are written when ``markers`` is true and the mesh has
    ``vertex_markers``.  ``header_markers`` overrides the header's marker field
    (the .v.node header always says 0).
    """
    xy = writing.get(mesh, "vertices", float, 2)
    if xy is None:
        raise ValueError("the mesh has no 'vertices'")
    n = len(xy)
    attr = writing.get(mesh, "vertex_attributes", float, rows=n)
    k = 0 if attr is None else attr.shape[1]
    marks = writing.get(mesh, "vertex_markers", int, 1, rows=n) if markers else None
    has_marks = marks is not None
    flag = has_marks if header_markers is None else header_markers
    # Triangle: "%ld  %d  %d  %d\n", then "%4d    %.17g  %.17g", "  %.17g" per
    # attribute, and "    %d\n" for the marker.
    chunks = ["%d  %d  %d  %d\n" % (n, 2, k, int(flag))]
    fmt = "%4d    %.17g  %.17g" + "  %.17g" * k + ("    %d\n" if has_marks else "\n")
    columns = [range(first_index, first_index + n), *xy.T.tolist()]
    if k:
        columns += attr.T.tolist()
    if has_marks:
        columns.append(marks[:, 0].tolist())
    chunks += [fmt % row for row in zip(*columns)]
    return chunks


def write_node(
    path: str | os.PathLike[str],
    mesh: Mapping[str, Any],
    *,
    first_index: int = 1,
    markers: bool = True,
    generated_by: str | None = None,
) -> Path:
    """Write ``mesh['vertices']`` (with attributes and markers) as a .node file."""
    chunks = vertex_chunks(mesh, first_index=first_index, markers=markers)
    return writing.write_text(path, chunks, generated_by)
