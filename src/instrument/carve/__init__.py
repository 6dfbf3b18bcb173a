"""Carving, the pipeline's third stage (``-p`` without ``-r``): remove the
concavities (unless ``-c``) and the holes (unless ``-O``), then spread the
regional attributes (``-A``) and area bounds (a bare ``-a``) over the
triangles of each region.  The kernels are in infect.py.
"""

from __future__ import annotations

import numpy as np

from ..state import MeshState
from ..switches import Options
from .infect import infect_hull, locate_points, plague, spread_regions, start_hull_edge


def carve(ms: MeshState, o: Options, holes: np.ndarray | None, regions: np.ndarray | None, xy_in: np.ndarray) -> None:
    """Remove concavities and holes, then spread regions (see the module docstring)."""
    m = ms.mesh
    m.add_constraint_tables()
    slots = m.triangle_capacity
    has_regions = regions is not None and len(regions) > 0
    has_holes = holes is not None and len(holes) > 0 and not o.O
    start = start_hull_edge(m)  # hole and region points must lie strictly left of its line
    if has_regions or has_holes:  # the input's bounding box, for locating their points
        # column by column: numpy's reduction along axis 0 of an (n, 2) array is
        # about fifty times slower (6 ms at 10^5 vertices)
        lo = np.array([xy_in[:, 0].min(), xy_in[:, 1].min()])
        hi = np.array([xy_in[:, 0].max(), xy_in[:, 1].max()])
    found_regions = None
    if has_regions:
        found_regions = np.zeros((len(regions), 2), dtype=np.int64)
        locate_points(m, np.ascontiguousarray(regions[:, :2]), lo, hi, found_regions, start)
    queue = np.empty(slots, dtype=np.int64)  # (the kernels write each entry before reading it)
    n = 0
    if not o.c:
        n = infect_hull(m, ms.segs, queue, start)
    if has_holes:
        tflag = np.asarray(m.tflag)
        found = np.zeros((len(holes), 2), dtype=np.int64)
        locate_points(m, np.ascontiguousarray(holes), lo, hi, found, start)
        for t in found[found[:, 0] >= 0, 0]:
            if not tflag[t]:
                tflag[t] = 1
                queue[n] = t
                n += 1
    plague(m, ms.segs, queue, n)
    if found_regions is not None and (o.A or o.var_area):
        seen = np.zeros(slots, dtype=np.int64)
        if o.A:
            m.add_attributes(np.zeros(m.nslot))
            spread_regions(m, found_regions, np.ascontiguousarray(regions[:, 2]), m.attribute, seen, queue)
        if o.var_area:
            m.add_area_bounds(np.full(m.nslot, -1.0))
            seen[:] = 0
            spread_regions(m, found_regions, np.ascontiguousarray(regions[:, 3]), m.area_bound, seen, queue)
