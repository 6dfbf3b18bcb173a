"""Triangle's output files: which ones a run writes, and the mesh they are written from.

The engine's result leaves out what the command decides (empty arrays, the
input's holes and regions, markers with ``-B``); these functions complete it
the way Triangle writes its files (reference section 2.10).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from .. import naming


def output_mesh(result, data, o) -> dict[str, Any]:
    """The engine's result, completed with what Triangle writes but the engine may omit."""
    mesh = dict(result)
    if o.p:
        for key in ("holes", "regions"):
            if key not in mesh and data.get(key) is not None and np.size(data[key]):
                mesh[key] = data[key]
    if o.r:
        mesh.pop("regions", None)  # Triangle does not read them when refining
    if o.B:
        for key in ("vertex_markers", "segment_markers", "edge_markers"):
            mesh.pop(key, None)
    if not (o.p or o.c):
        mesh.pop("segments", None)  # Triangle writes none, and counts hull subsegments
    return mesh


def with_empty_arrays(
    mesh: Mapping[str, Any], kinds: list[str], order: int, *, markers: bool = True
) -> dict[str, Any]:
    """``mesh`` with empty arrays for the files to write whose data the engine
    left out (it leaves out empty arrays, as the `triangle` package does).
    Empty marker arrays too: Triangle's .poly and .edge headers declare a
    marker column unless -B (``0  1``), even when there is no row."""
    mark = [("segment_markers", (0, 1), np.int32)] if markers else []
    needs = {
        "ele": [("triangles", (0, 6 if order == 2 else 3), np.int32)],
        "off": [("triangles", (0, 6 if order == 2 else 3), np.int32)],
        "poly": [("segments", (0, 2), np.int32), *mark, ("holes", (0, 2), np.float64)],
        "edge": [("edges", (0, 2), np.int32), *([("edge_markers", (0, 1), np.int32)] if markers else [])],
        "neigh": [("neighbors", (0, 3), np.int32)],
    }
    out = dict(mesh)
    for kind in kinds:
        for key, shape, dtype in needs.get(kind, ()):
            if out.get(key) is None:
                out[key] = np.zeros(shape, dtype=dtype)
    return out


def choose_outputs(o, outbase: str, node_read: bool) -> tuple[list[str], list[str]]:
    """Which files to write, and the console lines about them, in Triangle's order."""
    names = naming.output_files(outbase)
    kinds, lines = [], []

    def take(kind: str) -> None:
        kinds.append(kind)
        lines.append(f"Writing {names[kind]}.")

    if o.N or (o.I and node_read):
        lines.append("NOT writing a .node file.")
    else:
        take("node")
    if o.E:
        lines.append("NOT writing an .ele file.")
    else:
        take("ele")
    if o.p or o.c:
        if o.P or o.I:
            lines.append("NOT writing a .poly file.")
        else:
            take("poly")
    extras = (("g", "off"), ("e", "edge"), ("v", "v.node"), ("v", "v.edge"), ("n", "neigh"))
    for switch, kind in extras:
        if getattr(o, switch):
            take(kind)
    return kinds, lines


def voronoi(mesh: Mapping[str, Any]) -> dict[str, np.ndarray]:
    """Triangle's Voronoi diagram of a mesh, as ``write`` wants it (the engine computes it)."""
    from instrument.voronoi import diagram

    return diagram(mesh)
