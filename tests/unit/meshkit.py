"""Small meshes for the unit tests, and a structural check of a Mesh."""

from __future__ import annotations

import numpy as np

from instrument import counters
from instrument.core.mesh import GHOST, NO_EDGE, Mesh
from instrument.core.predicates import orient2d
from instrument.delaunay import delaunay


def triangulated(points, *, extra_vertices: int = 16, extra_triangles: int = 64) -> Mesh:
    """The Delaunay triangulation of ``points`` as a Mesh with room to spare."""
    m, _ = delaunay(
        np.asarray(points, dtype=np.float64), counters.new_work(),
        extra_vertices=extra_vertices, extra_triangles=extra_triangles,
    )
    return m


def live(m: Mesh) -> np.ndarray:
    return m.live_triangles()


def problems(m: Mesh) -> list[str]:
    """What is wrong with the mesh's structure: twins that are not mutual or
    do not join the same two vertices, subsegment records that differ on the
    two sides of an edge, triangles not strictly counter-clockwise, counts
    that disagree with the slots."""
    a = m.arrays()
    corner, twin, seg, stamp, xy = a["corner"], a["twin"], a["seg"], a["stamp"], a["xy"]
    out = []
    alive = 0
    for t in range(m.nslot):
        if stamp[t] <= 0:
            continue
        alive += 1
        c = corner[3 * t : 3 * t + 3]
        if GHOST not in c and orient2d(*xy[c[0]], *xy[c[1]], *xy[c[2]]) <= 0:
            out.append(f"triangle {t} {tuple(c)} is not counter-clockwise")
        for k in range(3):
            e = 3 * t + k
            tw = twin[e]
            if tw == NO_EDGE:
                continue
            if stamp[tw // 3] <= 0:
                out.append(f"edge {e} has a dead twin {tw}")
                continue
            if twin[tw] != e:
                out.append(f"edge {e}: twin {tw} points back to {twin[tw]}")
            ends = (corner[3 * t + (k + 1) % 3], corner[3 * t + (k + 2) % 3])
            u = tw // 3
            j = tw % 3
            back = (corner[3 * u + (j + 1) % 3], corner[3 * u + (j + 2) % 3])
            if ends != back[::-1]:
                out.append(f"edge {e} runs {ends}, its twin {tw} runs {back}")
            if seg[e] != seg[tw]:
                out.append(f"edge {e} is subsegment {seg[e]}, its twin {seg[tw]}")
    if alive != m.nlive:
        out.append(f"{alive} live slots, nlive says {m.nlive}")
    return out


def refiner(switches: str = "q", *, slots: int = 64, queue: int = 64):
    """Refinement's state for a unit test: switches ``switches``, Triangle's
    queue order, ``slots`` rows of insertion scratch."""
    from instrument.refine.order import strategy_id
    from instrument.refine.state import Config, Refiner
    from instrument.switches import parse

    cfg = Config(parse(switches), strategy_id("triangle"), True, False)
    return Refiner(cfg, budget=-1, slots=slots, queue=queue, records=16, trace=False)


def slot_of(m: Mesh, corners) -> int:
    """The live triangle whose corners are ``corners`` (in any rotation)."""
    want = set(int(c) for c in corners)
    corner = m.arrays()["corner"]
    found = [int(t) for t in m.live_triangles() if set(corner[3 * t : 3 * t + 3].tolist()) == want]
    assert len(found) == 1, f"{sorted(want)}: {found}"
    return found[0]


def corner_sets(m: Mesh) -> set[frozenset]:
    """Each live triangle as the set of its corners."""
    corner = m.arrays()["corner"]
    return {frozenset(corner[3 * t : 3 * t + 3].tolist()) for t in m.live_triangles()}


def as_result(m: Mesh) -> dict:
    """The mesh as ``instrument.check.check_mesh`` reads a result: its
    vertices and live triangles, and its subsegments (edges with a record)."""
    a = m.arrays()
    tris = m.live_triangles()
    out = {
        "vertices": a["xy"][: m.nvert].copy(),
        "triangles": a["corner"].reshape(-1, 3)[tris].astype(np.int32),
    }
    if m.has_constraint_tables:
        seg = a["seg"]
        edges = {
            tuple(sorted((int(a["corner"][3 * t + (k + 1) % 3]), int(a["corner"][3 * t + (k + 2) % 3]))))
            for t in tris for k in range(3) if seg[3 * t + k] >= 0
        }
        if edges:
            out["segments"] = np.array(sorted(edges), dtype=np.int32)
    return out
