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
from .oracles import Failure, read_switches


@dataclass(frozen=True)
class Defect:
    id: str
    description: str
    matches: Callable[[Case, Failure], bool]


def _coords(case: Case) -> np.ndarray:
    v = np.abs(np.asarray(case.input["vertices"], dtype=np.float64)).ravel()
    return v[v > 0]


def tiny(case: Case) -> bool:
    """Some nonzero coordinate below 2^-200 (as in the ~1e-300 and mixed-scale inputs)."""
    v = _coords(case)
    return bool(v.size and v.min() < 2.0**-200)


def huge(case: Case) -> bool:
    """Some coordinate above 2^200."""
    v = _coords(case)
    return bool(v.size and v.max() > 2.0**200)


def _kind(f: Failure, *kinds: str) -> bool:
    return f.kind in kinds


DEFECTS = [
    Defect(
        "o2-ignored",
        "o2 is ignored: ours returns 3-node triangles and no midpoint nodes",
        lambda c, f: _kind(f, "o2"),
    ),
    Defect(
        "zero-division-tiny",
        "ZeroDivisionError in refinement when coordinates are tiny (below ~2^-200, e.g. the unit square * 2^-269 under pq30)",
        lambda c, f: f.signature == "ours-exception:ZeroDivisionError" and tiny(c),
    ),
    Defect(
        "zero-division-star",
        "ZeroDivisionError in refinement of self-intersecting stars at ordinary scale (19-point star, step 6, under pq30)",
        lambda c, f: f.signature == "ours-exception:ZeroDivisionError" and not tiny(c) and read_switches(c.switches).q,
    ),
    Defect(
        "huge-coordinates",
        "at ~2^512 ours' geometry breaks: segments are not recovered (RuntimeError where Triangle meshes), or are "
        "bent through a vertex off them (the unit square's centre under p: half the square silently lost)",
        lambda c, f: huge(c) and f.kind in ("ours-error-where-triangle-meshes", "phantom-segment", "dropped-vertex",
                                           "boundary-not-segment", "area-total"),
    ),
    Defect(
        "regions-heap",
        "regions with A and an area bound corrupt the heap (a crash, at exit or in a later call)",
        lambda c, f: f.kind == "ours-crash" and "regions" in c.input,
    ),
    Defect(
        "collinear-chain-p",
        "nearly collinear segment chains fail under p ('could not recover segment') where Triangle meshes",
        lambda c, f: f.kind == "ours-error-where-triangle-meshes" and "could not recover segment" in f.message and not huge(c),
    ),
]

BY_ID = {d.id: d for d in DEFECTS}


def explaining(case: Case, failure: Failure) -> Defect | None:
    """The open defect that explains ``failure`` on ``case``, if any."""
    for d in DEFECTS:
        if d.matches(case, failure):
            return d
    return None
