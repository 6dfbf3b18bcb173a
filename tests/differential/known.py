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
from .oracles import Failure, ordinary_scale, read_switches


@dataclass(frozen=True)
class Defect:
    id: str
    description: str
    #: (case, failure, notes of the verdict) -> whether this defect explains the failure
    matches: Callable[[Case, Failure, dict], bool]


def _coords(case: Case) -> np.ndarray:
    v = np.abs(np.asarray(case.input["vertices"], dtype=np.float64)).ravel()
    return v[v > 0]


def tiny_extent(case: Case) -> bool:
    """Every coordinate below 2^-400 in magnitude."""
    v = np.abs(np.asarray(case.input["vertices"], dtype=np.float64))
    return bool(v.size and v.max() < 2.0**-400)


def huge(case: Case) -> bool:
    """Some coordinate above 2^200."""
    v = _coords(case)
    return bool(v.size and v.max() > 2.0**200)


DEFECTS = [
    Defect(
        "star-size",
        "self-intersecting stars under q: ours is a few percent above Triangle's re-expression spread (the "
        "19-point star, step 6, under pq30: 1255 against 1217, bound 1244; it was 2388 while crossing pieces kept "
        "the input segment's ends). What remains follows the crossing vertices: ours makes them in another order "
        "and rounds some one unit in the last place differently (x 0.7734740790612135 against Triangle's ...133), "
        "so the refinement starts from other vertices",
        lambda c, f, n: f.kind == "size" and c.family == "star" and read_switches(c.switches).q,
    ),
]

DEFECTS += [
    Defect(
        "incremental-order",
        "under i, ours (a randomized incremental method) leaves the first triangulation's triangles in another "
        "order and rotation than Triangle's incremental method, and under u (whose test reads the triangle's "
        "origin) the refinement then takes other steps: 7 points under uYiQ give 34 vertices against 26. Given the "
        "same triangles in the same order (-r), ours and Triangle make the same mesh (26 and 26; 34 and 34 from "
        "ours' order)",
        lambda c, f, n: f.kind == "size" and read_switches(c.switches).i and read_switches(c.switches).u,
    ),
]

DEFECTS += [
    Defect(
        "queue-order-size",
        "bad triangles in one of Triangle's 4096 buckets are served first in, first out, and ours queues some "
        "of them in another order (the fan of an insertion from another first edge, or the initial queue in "
        "another pool order), so the meshes part and ours can end a few percent above Triangle's spread: 4 "
        "points under q34 part at Steiner point 63 (two triangles of bucket 2084 from one insertion, 179 "
        "vertices against 127; identical meshes up to q33.9); the airfoil_exterior corpus file under pq30 parts "
        "at point 22 (bucket 2057, from the initial queue: 382 against 366), and its r refinement of Triangle's "
        "-p mesh likewise",
        lambda c, f, n: f.kind == "size" and (c.family == "realworld" or read_switches(c.switches).angle >= 34),
    ),
    Defect(
        "mixed-scale-slow",
        "quality refinement of inputs spanning 1e-303 to 1e300 (a lattice at 1e300 with two points near 1e-303 "
        "under nq28.6cp; cocircular points likewise under qe) computes most predicates in exact fractions: ~1500 "
        "vertices in 20 s, slower as it goes, so the 20-second deadline is missed (Triangle crashes on most of "
        "them; where it meshes, its quality test overflowed)",
        lambda c, f, n: f.kind == "ours-timeout" and not ordinary_scale(c.input),
    ),
]

DEFECTS += [
    Defect(
        "huge-sliver-overrefined",
        "quality refinement of a 0.6-degree sliver at 1e300 ((0, 0), (1e300, 1.5e294), (1e300, -1e298) under "
        "qpi) makes 27281 vertices where the same input scaled to ~1 makes 89 (refinement is not scale-invariant "
        "up there), and the exact checker's box join on that mesh lists 662 million candidate pairs "
        "(MemoryError, 4.9 GiB)",
        lambda c, f, n: huge(c) and read_switches(c.switches).q and f.kind == "checker-error",
    ),
]

DEFECTS += [
    Defect(
        "mixed-scale-Y-invalid",
        "quality refinement without splitting hull segments (Y) of points spanning 1e-306 to 1e299 makes an "
        "invalid mesh: (0, 2.5e299), (9.5e293, 0), (0, 0), (0, 9.5e-307) under qYQ give 10799 vertices with "
        "clockwise triangles and coincident vertices (25 checker problems; under qQ the mesh is valid); found "
        "by the generated test, seed 26 (regressions/mixed-scale-Y-invalid.json); the refinement kernels were "
        "left to their own helper",
        lambda c, f, n: f.kind == "invalid-mesh" and read_switches(c.switches).q and read_switches(c.switches).Y > 0
        and not ordinary_scale(c.input),
    ),
]

BY_ID = {d.id: d for d in DEFECTS}


def explaining(case: Case, failure: Failure, notes: dict | None = None) -> Defect | None:
    """The open defect that explains ``failure`` on ``case``, if any."""
    for d in DEFECTS:
        if d.matches(case, failure, notes or {}):
            return d
    return None
