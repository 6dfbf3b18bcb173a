"""How big a refinement may grow: a warning for angles that rarely terminate,
and a vertex limit that stops a run with a clear error instead of letting it
exhaust the memory.

Triangle's documentation: refinement is guaranteed to terminate for minimum
angles up to about 28.6 degrees and usually succeeds up to about 34; above
that it often refines forever (``-q40`` on A.poly does).  ``angle_warning``
says so when a run asks for more than 34 degrees.

The vertex limit of a run (``vertex_limit``), unless the caller sets one
(``max_vertices=`` in Python, ``--max-vertices`` on the command line).  It
counts every vertex the run makes, the ones refinement deletes again
included (they take memory until the end):

    max(F, 1,000 x (input vertices + segments))
    + 4 x (area of the domain) / (smallest area bound)      [with a, a bare a, or ra]
    where F is 1,000,000 with an angle bound (q) and 4,000,000 without,
    raised to the input vertices + S with a Steiner budget -S,
    and never above the memory ceiling: half the machine's memory at
    512 bytes a vertex.

Why these numbers: meshes without an area bound come out at up to 80
vertices per input vertex over the corpus and the package's samples at q30
(so 1,000 leaves a wide margin), and under an area bound A at 1.2-1.6
triangles, so about 0.8 vertices, per A of domain (so 4 per A leaves five
times that); refinement uses 290-420 bytes a vertex at its peak (measured:
``pq30a1e-6`` on the unit square, ``pq40S300000`` on A.poly).  The
1,000,000 floor is about four seconds and 400 MB of work (six points
within rounding of a line under ``pq34a0.000899cvi``, a sliver of area
~1e-17 that only the floor bounds: 1.9 s of CPU since stop 33, 14 s while
its split points' cavities grew into fans across the sliver), and no rule
of the input's size tells such an input from one whose mesh is
legitimately that large, so the limit stays the same for it.  Without an
angle bound refinement cannot go on for ever (it splits only triangles
above their area bound and encroached subsegments), so the floor there is
four times higher, about ten seconds and 2 GB: a chain of segments within
rounding of a line under an area bound alone (``pa0.000000000000000199cjz``,
tests/engine/test_limits.py) is graded by its encroached subsegments, not
by its area of 5e-16, and Triangle and ours both make about 1,546,670
vertices of it.  A run that passes the limit stops with ``SizeLimitError``
(the kernel hands control back at least every 16,384 steps, splits of
subsegments included); an area bound whose expected mesh already passes it
fails before refining.
"""

from __future__ import annotations

import math
import os

from .errors import SizeLimitError

__all__ = [
    "GUARANTEED_ANGLE",
    "USUAL_ANGLE",
    "angle_warning",
    "check_expected",
    "expected_vertices",
    "memory_ceiling",
    "vertex_limit",
]

#: Triangle's documentation: termination is guaranteed up to this minimum angle ...
GUARANTEED_ANGLE = 28.6
#: ... and usually happens up to this one.
USUAL_ANGLE = 34.0

MIN_LIMIT = 1_000_000
#: The floor of a run without an angle bound, which ends on every input.
MIN_LIMIT_WITHOUT_ANGLE = 4_000_000
VERTICES_PER_INPUT = 1_000
VERTICES_PER_AREA_BOUND = 4.0
#: Measured: a mesh under an area bound A has about 0.8 vertices per A of domain.
EXPECTED_VERTICES_PER_AREA_BOUND = 0.8
BYTES_PER_VERTEX = 512


def angle_warning(min_angle: float) -> str | None:
    """Triangle-style warning line for a minimum angle above ``USUAL_ANGLE``."""
    if not min_angle > USUAL_ANGLE:
        return None
    return (
        f"Warning:  A minimum angle of {min_angle:g} degrees is above {USUAL_ANGLE:g}; refinement is "
        f"guaranteed to terminate only up to {GUARANTEED_ANGLE:g} degrees and usually does up to "
        f"{USUAL_ANGLE:g}, so it may run until the vertex limit."
    )


def memory_ceiling() -> int:
    """The most vertices half of this machine's memory holds during refinement."""
    try:
        memory = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (ValueError, OSError, AttributeError):  # no sysconf (Windows): assume 8 GiB
        memory = 8 << 30
    return max(MIN_LIMIT, memory // 2 // BYTES_PER_VERTEX)


def expected_vertices(domain_area: float, area_bound: float | None) -> float:
    """About how many vertices a mesh of ``domain_area`` under ``area_bound`` has."""
    if not area_bound or area_bound <= 0 or not domain_area > 0:
        return 0.0
    return EXPECTED_VERTICES_PER_AREA_BOUND * domain_area / area_bound


def vertex_limit(
    *,
    n_input: int,
    domain_area: float,
    area_bound: float | None,
    steiner_budget: int = -1,
    angle_bound: bool = True,
    ceiling: int | None = None,
) -> int:
    """The default vertex limit (see the module's text).  ``n_input``: input
    vertices plus segments; ``area_bound``: the smallest area bound of the
    run, or None; ``steiner_budget``: -S's number (-1: none);
    ``angle_bound``: whether the run has a minimum angle (q)."""
    floor = MIN_LIMIT if angle_bound else MIN_LIMIT_WITHOUT_ANGLE
    limit = max(floor, VERTICES_PER_INPUT * n_input)
    if area_bound and area_bound > 0 and domain_area > 0:
        extra = VERTICES_PER_AREA_BOUND * domain_area / area_bound
        limit = limit + int(min(extra, 2**62))
    if steiner_budget >= 0:
        limit = max(limit, n_input + steiner_budget)
    return int(min(limit, memory_ceiling() if ceiling is None else ceiling))


def check_expected(limit: int, domain_area: float, area_bound: float | None, *, explain: str) -> None:
    """Fail before refining when the area bound alone asks for more than ``limit``."""
    want = expected_vertices(domain_area, area_bound)
    if want > limit:
        raise SizeLimitError(
            f"A maximum area of {area_bound:g} over a domain of area {domain_area:g} needs about "
            f"{_count(want)} vertices, more than the limit of {limit:,} ({explain}); "
            f"use a larger area bound, -S, or --max-vertices (max_vertices= in Python)."
        )


def stopped(vertices: int, limit: int, min_angle: float, *, explain: str) -> SizeLimitError:
    """The error for a run that passed its limit."""
    why = explain
    if min_angle > USUAL_ANGLE:
        why += f"; a minimum angle of {min_angle:g} degrees is above {USUAL_ANGLE:g}, where refinement usually ends"
    return SizeLimitError(
        f"Refinement stopped at {vertices:,} vertices (limit {limit:,}; {why}): "
        f"use -S, a smaller angle, or --max-vertices (max_vertices= in Python)."
    )


def _count(x: float) -> str:
    return f"{x:,.0f}" if x < 1e15 else f"{x:.3g}"


def explain(default: bool) -> str:
    """Where the limit came from, for messages."""
    if not default:
        return "set by max_vertices"
    return "derived from the input's size and area bound"

