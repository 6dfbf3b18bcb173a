"""Open defects of ours that the differential harness found, and which
failures each explains.

The generated test does not fail on a failure that an open defect here
explains (so the suite stays green while the defect is open), and every
regression case that names a defect is an ``xfail(strict=True)`` with its
one-line description.  When a defect is fixed, its regression cases pass
unexpectedly: remove the defect here and the ``defect`` field from them.

A matcher must be narrow: it names the failure kind and the input or
switch feature that the defect's reproducers share, so a new defect of the
same kind elsewhere still fails the generated test.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from .cases import Case
from .oracles import Failure, extreme_scale, read_switches


@dataclass(frozen=True)
class Defect:
    id: str
    description: str
    #: (case, failure, notes of the verdict) -> whether this defect explains the failure
    matches: Callable[[Case, Failure, dict], bool]


def _kind(f: Failure, *kinds: str) -> bool:
    return f.kind in kinds


def has_duplicates(case: Case) -> bool:
    v = np.asarray(case.input["vertices"], dtype=np.float64)
    return len(np.unique(v, axis=0)) < len(v)


def nearly_collinear(case: Case, rtol: float = 1e-9) -> bool:
    """Two input segments that share an endpoint and turn by a nonzero angle
    below ``rtol`` radians (or a vertex that close to, but not on, a segment's line)."""
    v = np.asarray(case.input["vertices"], dtype=np.float64)
    segs = np.asarray(case.input.get("segments", np.zeros((0, 2))), dtype=np.int64).reshape(-1, 2)
    if not len(segs) or not np.isfinite(v).all():
        return False
    a, b = v[segs[:, 0]], v[segs[:, 1]]
    d = b - a
    length = np.hypot(d[:, 0], d[:, 1])
    with np.errstate(all="ignore"):
        cross = d[:, None, 0] * (v[None, :, 1] - a[:, None, 1]) - d[:, None, 1] * (v[None, :, 0] - a[:, None, 0])
        dist = np.abs(cross) / length[:, None]
        near = (dist > 0) & (dist < rtol * length[:, None])
    return bool(near.any())


def hole_on_segment(case: Case) -> bool:
    """A hole point exactly on an input segment (its endpoints included)."""
    from instrument.check import orient_exact

    holes = np.asarray(case.input.get("holes", np.zeros((0, 2))), dtype=np.float64).reshape(-1, 2)
    v = np.asarray(case.input["vertices"], dtype=np.float64)
    segs = np.asarray(case.input.get("segments", np.zeros((0, 2))), dtype=np.int64).reshape(-1, 2)
    for h in holes.tolist():
        for a, b in segs.tolist():
            pa, pb = v[a].tolist(), v[b].tolist()
            inside = min(pa[0], pb[0]) <= h[0] <= max(pa[0], pb[0]) and min(pa[1], pb[1]) <= h[1] <= max(pa[1], pb[1])
            if inside and orient_exact(pa, pb, h) == 0:
                return True
    return False


def triangle_empty(notes: dict) -> bool:
    return ", 0 triangles" in str(notes.get("triangle", ""))


DEFECTS = [
    Defect(
        "star-size",
        "self-intersecting stars under q: ours makes about twice Triangle's vertices (the 19-point star, step 6, "
        "under pq30: 2388 against 1217; it raised ZeroDivisionError before the scaled quality test)",
        lambda c, f, n: f.kind == "size" and c.family == "star" and read_switches(c.switches).q,
    ),
    Defect(
        "duplicate-copy",
        "divide and conquer keeps a different copy of a duplicate point than Triangle, whose choice follows its "
        "randomized quicksort (ours keeps the lowest index), so a hull marker 1 lands on another copy: e.g. "
        "[[0,0],[1,1],[0,0]] under Q gives Triangle [0, 0, 1], ours [1, 0, 0]",
        lambda c, f, n: has_duplicates(c) and not read_switches(c.switches).i and f.kind == "markers"
        and f.detail in ("input-vertex", "vertex_markers", "outside-domain"),
    ),
]

DEFECTS += [
    Defect(
        "hole-on-segment-incremental",
        "under i, a hole or region point exactly on a hull segment (or vertex): Triangle ignores it when it lies "
        "on its start hull edge, which after incremental insertion is the edge arriving at input vertex 0 only "
        "when that vertex is on the hull (otherwise not known); and which side of an interior segment it eats "
        "follows Triangle's point location",
        lambda c, f, n: hole_on_segment(c) and read_switches(c.switches).i and f.kind in (
            "count", "area-total", "markers", "size", "region-area", "region-attribute", "attributes"),
    ),
]

DEFECTS += [
    Defect(
        "markers-outside-domain",
        "boundary markers of input vertices in no triangle (eaten with the exterior, or every triangle eaten) "
        "differ from Triangle's (Triangle marks some endpoints of eaten segments 1)",
        lambda c, f, n: f.kind == "markers" and f.detail == "outside-domain",
    ),
]

DEFECTS += [
    Defect(
        "size-excess",
        "under a fixed area bound without q, ours uses more vertices than Triangle beyond Triangle's own "
        "re-expression spread (4 points, a0.00156: 57 against 51, re-expressions at most 52; cause not isolated)",
        lambda c, f, n: f.kind == "size" and read_switches(c.switches).area is not None
        and not read_switches(c.switches).q,
    ),
]

DEFECTS += [
    Defect(
        "huge-refinement-precision",
        "refinement above 2^512 overflows: (1.19e175, 0), (0, 0), (0, 3.96e174) under pqc raise PrecisionError "
        "(the shell split's length sqrt(dx^2 + dy^2) is inf, the split point NaN; with hypot there the "
        "refinement runs away to the vertex limit, so other products overflow too); Triangle's quality test "
        "overflows and keeps the one triangle",
        lambda c, f, n: extreme_scale(c) and read_switches(c.switches).q
        and f.kind == "ours-error-where-triangle-meshes" and "PrecisionError" in f.message,
    ),
]

BY_ID = {d.id: d for d in DEFECTS}


def explaining(case: Case, failure: Failure, notes: dict | None = None) -> Defect | None:
    """The open defect that explains ``failure`` on ``case``, if any."""
    for d in DEFECTS:
        if d.matches(case, failure, notes or {}):
            return d
    return None
