"""`.poly` files: a planar straight-line graph (spec §2.3).

```
<#vertices> <dim> <#attributes> <#markers>     # 0 vertices: they come from base.node
<vertex lines as in .node>
<#segments> <#markers (0|1)>
<segment#> <endpoint1> <endpoint2> [marker]
<#holes>
<hole#> <x> <y>
[<#regions>]                                   # optional section
[<region#> <x> <y> <attribute> [<max area>]]
```
As in Triangle, a segment naming a vertex that does not exist, or joining two
vertices at the same place, is skipped with a warning; every other problem is a
FormatError.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from . import writing
from .lines import INT32_MAX, INT32_MIN, Block, Line, LineReader
from .errors import FormatError
from .info import Info
from .node import check_dimension, read_node, read_vertex_header, read_vertices, vertex_chunks


def read_poly(
    path: str | os.PathLike[str],
    *,
    default_first_index: int = 1,
    info: Info | None = None,
) -> dict[str, np.ndarray]:
    """Read a .poly file (and ``base.node`` when it lists 0 vertices).

    Returns ``vertices`` (with attributes and markers if declared), ``segments``,
    ``holes`` (both always present, possibly with 0 rows), ``segment_markers`` if
    declared, and ``regions`` (R, 4) = x, y, attribute, max area if the optional
    regional section lists any.  Indices are 0-based.  ``info`` receives the
    numbering base, declared marker counts and warnings.
    """
    info = info if info is not None else Info()
    path = Path(path)
    r = LineReader.open(path)
    info.files.append(path)
    header = read_vertex_header(r)
    if header.count == 0:
        out = _read_companion_node(r, header.line, path, default_first_index, info)
    else:
        check_dimension(r, header)
        out, info.first_index = read_vertices(r, header, default_first_index)
        info.vertex_markers = header.markers
        info.vertices_from = path
    out.update(_read_segments(r, out["vertices"], info))
    out["holes"] = _read_holes(r, info.first_index)
    if not r.at_end():
        regions = _read_regions(r, info.first_index)
        if len(regions):
            out["regions"] = regions
    return out


def _read_companion_node(
    r: LineReader, line: Line, path: Path, default_first_index: int, info: Info
) -> dict[str, np.ndarray]:
    """A .poly listing 0 vertices takes them, and their header, from base.node."""
    node_path = path.with_suffix(".node")
    try:
        return read_node(node_path, default_first_index=default_first_index, info=info)
    except OSError as exc:
        raise FormatError(
            r.path,
            line.number,
            f"the vertices in {node_path} (this file lists 0 vertices)",
            problem=f"cannot access file {node_path} ({exc.strerror or exc})",
        ) from exc


def _read_segments(r: LineReader, xy: np.ndarray, info: Info) -> dict[str, np.ndarray]:
    line = r.next("the number of segments")
    count = r.count_field(line, 0, "the number of segments")
    declared = r.int_field(line, 1, "the number of segment markers", required=False)
    info.segment_markers = declared
    block = r.take(line, count, "segment")
    first, n = info.first_index, len(xy)
    segments = block.ints(1, 3)
    markers = block.ints(3, 4) if declared else np.zeros((count, 1), np.int64)
    fast = segments is not None and markers is not None
    if fast and count:
        ends = segments - first
        fast = (
            ends.min() >= 0
            and ends.max() < n
            and markers.min() >= INT32_MIN
            and markers.max() <= INT32_MAX
            and not np.all(xy[ends[:, 0]] == xy[ends[:, 1]], axis=1).any()
        )
    if fast:
        segments = (segments - first).astype(np.int32)
        markers = markers.astype(np.int32)
    else:
        segments, markers = _slow_segments(r, block, bool(declared), xy, info)
    out = {"segments": segments}
    if len(segments) and declared:
        out["segment_markers"] = markers
    return out


def _slow_segments(
    r: LineReader, block: Block, declared: bool, xy: np.ndarray, info: Info
) -> tuple[np.ndarray, np.ndarray]:
    """Line by line: Triangle warns about bad segments and skips them."""
    first, n = info.first_index, len(xy)
    segments = np.empty((len(block), 2), dtype=np.int32)
    markers = np.zeros((len(block), 1), dtype=np.int32)
    kept = 0
    for i, line in enumerate(block):
        number = first + i
        ends = [
            r.index_field(line, j, f"the {name} endpoint of segment {number}")
            for j, name in ((1, "first"), (2, "second"))
        ]
        marker = 0
        if declared:
            marker = r.int_field(line, 3, f"the marker of segment {number}", required=False)
        a, b = ends[0] - first, ends[1] - first
        if not 0 <= a < n:
            warning = f"Invalid first endpoint of segment {number}"
        elif not 0 <= b < n:
            warning = f"Invalid second endpoint of segment {number}"
        elif xy[a, 0] == xy[b, 0] and xy[a, 1] == xy[b, 1]:
            warning = f"Endpoints of segment {number} are coincident"
        else:
            segments[kept] = a, b
            markers[kept, 0] = marker
            kept += 1
            continue
        info.warnings.append(f"Warning:  {warning} in {r.path}.")
    return segments[:kept], markers[:kept]


def _read_holes(r: LineReader, first: int) -> np.ndarray:
    line = r.next("the number of holes")
    count = r.count_field(line, 0, "the number of holes")
    block = r.take(line, count, "hole")
    holes = block.reals(1, 3)
    if holes is None:
        holes = np.empty((count, 2))
        for i, line in enumerate(block):
            name = f"hole {first + i}"
            holes[i, 0] = r.real_field(line, 1, f"the x coordinate of {name}")
            holes[i, 1] = r.real_field(line, 2, f"the y coordinate of {name}")
    return holes


def _read_regions(r: LineReader, first: int) -> np.ndarray:
    line = r.next("the number of regions")
    count = r.count_field(line, 0, "the number of regions")
    block = r.take(line, count, "region")
    regions = np.empty((count, 4))
    for i, line in enumerate(block):
        name = f"region {first + i}"
        regions[i, 0] = r.real_field(line, 1, f"the x coordinate of {name}")
        regions[i, 1] = r.real_field(line, 2, f"the y coordinate of {name}")
        value = r.real_field(line, 3, f"the regional attribute or area constraint of {name}")
        regions[i, 2] = value
        # Triangle uses a lone value as both the attribute and the area bound.
        regions[i, 3] = r.real_field(
            line, 4, f"the area constraint of {name}", required=False, default=value
        )
    return regions


# -- writing ------------------------------------------------------------------


def poly_chunks(
    mesh: Mapping[str, Any],
    *,
    first_index: int = 1,
    markers: bool = True,
    with_vertices: bool = False,
) -> list[str]:
    """The text of a .poly file.

    Without ``with_vertices`` it starts with Triangle's ``0  2  <#attr>  <markers>``
    header (the vertices live in the .node file written alongside).
    """
    if with_vertices:
        chunks = vertex_chunks(mesh, first_index=first_index, markers=markers)
    else:
        attr = writing.get(mesh, "vertex_attributes", float)
        k = 0 if attr is None else attr.shape[1]
        has_marks = markers and mesh.get("vertex_markers") is not None
        chunks = ["%d  %d  %d  %d\n" % (0, 2, k, int(has_marks))]
    segments = writing.get(mesh, "segments", int, 2)
    if segments is None:
        segments = np.zeros((0, 2), dtype=np.int64)
    s = len(segments)
    seg_marks = writing.get(mesh, "segment_markers", int, 1, rows=s) if markers else None
    chunks.append("%d  %d\n" % (s, int(seg_marks is not None)))
    numbers = range(first_index, first_index + s)
    ends = (segments + first_index).T.tolist()
    if seg_marks is not None:
        rows = zip(numbers, *ends, seg_marks[:, 0].tolist())
        chunks += ["%4d    %4d  %4d    %4d\n" % row for row in rows]
    else:
        chunks += ["%4d    %4d  %4d\n" % row for row in zip(numbers, *ends)]
    holes = writing.get(mesh, "holes", float, 2)
    holes = np.zeros((0, 2)) if holes is None else holes
    chunks.append("%d\n" % len(holes))
    numbers = range(first_index, first_index + len(holes))
    chunks += ["%4d   %.17g  %.17g\n" % row for row in zip(numbers, *holes.T.tolist())]
    regions = writing.get(mesh, "regions", float, 4)
    if regions is not None and len(regions):
        chunks.append("%d\n" % len(regions))
        numbers = range(first_index, first_index + len(regions))
        chunks += [
            "%4d   %.17g  %.17g  %.17g  %.17g\n" % row
            for row in zip(numbers, *regions.T.tolist())
        ]
    return chunks


def write_poly(
    path: str | os.PathLike[str],
    mesh: Mapping[str, Any],
    *,
    first_index: int = 1,
    markers: bool = True,
    with_vertices: bool = False,
    generated_by: str | None = None,
) -> Path:
    """Write segments, holes and regions (and the vertices if ``with_vertices``)."""
    chunks = poly_chunks(
        mesh, first_index=first_index, markers=markers, with_vertices=with_vertices
    )
    return writing.write_text(path, chunks, generated_by)
