"""Barbič and Miller's input I(n), on which Ruppert's algorithm can create Θ(n²) triangles.

The paper (``shared/seed/barbic-miller-quadratic-ruppert.md``, "A Quadratic Running
Time Example for Ruppert's Refinement Algorithm") builds, for an integer n and a
minimum allowed angle alpha_min, the point set of equation (2)::

    I(n) = {(i/n, 0) | i = 0..n}  ∪  {(0, a), (1, a), (1/(2n), h)}

with

* (3)  r = the smallest positive integer with 1 / ((2r+1)(2r-1)) < tan²(alpha_min),
* (4)  h = sqrt((2r+1)(2r-1)) / (2n),
* (5)  a = h + 1/h = Θ(n).

Ruppert's algorithm first encloses the input in a square of side three times the
larger span of the input, here 3a, centred at (1/2, a/2), and splits the four box
sides at their midpoints; :func:`example` returns this *extended input* E: the n+4
points, the four box corners, the four side midpoints and the eight box
subsegments, as a PSLG dict for ``instrument.triangulate(d, "p")`` or the
``triangle`` package.

Lemma 1 (equations (6)-(8)): with A = (i/n, 0), B = ((i+1)/n, 0), C = ((i+r)/n, 0),
D = ((i+r+1)/n, 0) and P = (i/n + 1/(2n), h), the angle θ of triangle CDP at P has
tan θ = 1/(2nh) = 1/sqrt((2r+1)(2r-1)), so θ < alpha_min by (3): CDP is skinny.
Its circumcenter S = ((i+r)/n + 1/(2n), h) lies at the same height h, and CDS is
congruent to ABP.  Lemma 2 (equations (9)-(11)): after adding the points
P_l = (l r/n + 1/(2n), h), 0 < l <= k, to E, every triangle
((m/n, 0), ((m+1)/n, 0), P_k) with kr <= m < n is Delaunay (the "broom").
Theorem 3 (equations (12)-(14)): splitting Δ_k = ((kr+r)/n, 0), ((kr+r+1)/n, 0), P_k
for k = 0, 1, ... inserts P_{k+1} each time and creates at least n - r(k+1) new
triangles at step k, in total at least n²/(2r) - 2n.

Vertex numbering of :func:`example` (0-based, the ``triangle`` package's)::

    i            (i/n, 0), i = 0..n                        equation (2)
    n+1, n+2     (0, a), (1, a)                            equation (2)
    n+3          P_0 = (1/(2n), h)                         equation (2)
    n+4 .. n+11  the box, counter-clockwise from its lower-left corner:
                 corner, bottom midpoint, corner, right midpoint, corner,
                 top midpoint, corner, left midpoint
    segments     (n+4+j, n+4+(j+1) % 8), j = 0..7, marker 1

Steiner points are not input vertices; the helpers that name P_k for k >= 1 by
index assume they are appended in step order after the extended input, P_k at
index ``first_steiner + k - 1`` (``first_steiner`` defaults to n+12), as an
insertion-only replay of Theorem 3 numbers them.

Where the paper as printed does not check out (the tests in
``tests/engine/test_quadratic_example.py`` pin each point):

* Theorem 3 lets k run to floor(n/r) - 1, but Δ_k uses the vertex (kr+r+1)/n, which
  exists only while kr + r + 1 <= n.  When r divides n the last step does not
  exist: there are :func:`steps` = floor((n-1)/r) scripted steps (and Steiner
  vertices), not floor(n/r).  The missing step would have added n - r(k+1) = 0 to
  sum (14), so bound (12) is unaffected.  For the same reason n >= r (Lemma 2,
  Theorem 3) leaves no step at all when n = r; this module requires n >= r + 1.
* Equation (8) prints the tangent subtraction formula with ``1 - tan·tan`` in the
  denominator; the formula is ``1 + tan·tan``, which gives the stated 1/(2nh)
  (with ``-`` the denominator is exactly 0, since (nh)² = r² - 1/4).
* Equation (11) calls the largest circumradius R_max but its right-hand side is
  the largest circumcenter height y_C of (10); the radius is
  sqrt(y_C² + 1/(4n²)), slightly larger.  The conclusion R < a/2 still holds.

Everything here is pure geometry from the paper, except :func:`replay`, which plays
Theorem 3's splits on the engine (``instrument.replay``) and checks Lemmas 1 and 2
at every step.
"""

from __future__ import annotations

import math
import numbers
import operator
from dataclasses import dataclass

import numpy as np

__all__ = [
    "ALPHA_MAX_DEG",
    "Params",
    "apex_index",
    "box_points",
    "box_segments",
    "broom",
    "delta",
    "delta_points",
    "example",
    "input_indices",
    "input_points",
    "new_point",
    "params",
    "replay",
    "smallest_r",
    "steiner_point",
    "step_lower_bound",
    "steps",
    "theorem3_bound",
]

ALPHA_MAX_DEG = 34.0
"""Largest minimum angle accepted, in degrees.

The construction and Theorem 3's scripted splits need only alpha_min > 0
(Section 2), but alpha_min is also the bound Ruppert's algorithm refines to when
the script is over.  Ruppert proves termination below 20.7 degrees (the paper
quotes "smaller than 20"), Triangle's variant (off-centers, lenses) up to 28.6
degrees, and in practice Triangle finishes up to about 33-34 degrees (spec
4.8.6); the issue's sweep goes to 33.  So 0 < alpha_deg <= 34 is accepted.  For
alpha > 30 degrees r = 1; at exactly 30 degrees r = 2, because r = 1 would give
θ = 30 degrees, not skinny (tan² 30° = 1/3 is also what floating point
computes)."""


@dataclass(frozen=True)
class Params:
    """The parameters of I(n): ``r`` (equation (3)), ``h`` (4) and ``a`` (5)."""

    n: int
    alpha_deg: float
    r: int
    h: float
    a: float

    @property
    def theta_deg(self) -> float:
        """Angle of every Δ_k at its apex, in degrees: tan θ = 1/(2nh) (equation (8))."""
        return math.degrees(math.atan(1.0 / (2 * self.n * self.h)))

    @property
    def steps(self) -> int:
        """Number of scripted steps of Theorem 3 that exist: floor((n-1)/r) (see :func:`steps`)."""
        return (self.n - 1) // self.r

    @property
    def first_steiner(self) -> int:
        """Default index of P_1: the first index after the n + 12 extended-input vertices."""
        return self.n + 12


def _alpha(alpha_deg: float) -> float:
    if isinstance(alpha_deg, bool) or not isinstance(alpha_deg, numbers.Real):
        raise TypeError(f"alpha_deg must be a number of degrees, not {alpha_deg!r}")
    alpha = float(alpha_deg)
    if not 0.0 < alpha <= ALPHA_MAX_DEG:  # also rejects nan
        raise ValueError(
            f"alpha_deg must satisfy 0 < alpha_deg <= {ALPHA_MAX_DEG:g} (the paper's "
            f"alpha_min > 0, where Ruppert's algorithm still finishes in practice), got {alpha_deg!r}"
        )
    return alpha


def as_integer(value: object, name: str) -> int:
    """``value`` as an int (anything with __index__, not a bool), else TypeError naming it."""
    if isinstance(value, bool):
        raise TypeError(f"{name} must be an integer, not {value!r}")
    try:
        return operator.index(value)
    except TypeError:
        raise TypeError(f"{name} must be an integer, not {value!r}") from None


def smallest_r(alpha_deg: float = 20.0) -> int:
    """Equation (3): the smallest positive integer r with 1/((2r+1)(2r-1)) < tan²(alpha).

    Raises ValueError unless 0 < alpha_deg <= ALPHA_MAX_DEG (TypeError for a
    non-number).
    """
    tan2 = math.tan(math.radians(_alpha(alpha_deg))) ** 2
    # 4r² - 1 > 1/tan² gives a first guess; the loops settle it on the printed test.
    r = max(1, math.floor(math.sqrt((1.0 / tan2 + 1.0) / 4.0)) - 1)
    while r > 1 and 1.0 / ((2 * r - 1) * (2 * r - 3)) < tan2:
        r -= 1
    while not 1.0 / ((2 * r + 1) * (2 * r - 1)) < tan2:
        r += 1
    return r


def params(n: int, alpha_deg: float = 20.0) -> Params:
    """The parameters r, h, a of I(n) for minimum angle ``alpha_deg`` (equations (3)-(5)).

    ``n`` must be an integer >= r + 1: Δ_0 of Theorem 3 uses the vertex ((r+1)/n, 0)
    (the paper's n >= r gives no step when n = r).  Raises ValueError otherwise,
    and for an angle outside 0 < alpha_deg <= ALPHA_MAX_DEG; TypeError for a
    non-integer n or a non-number angle.
    """
    r = smallest_r(alpha_deg)
    n = as_integer(n, "n")
    if n < r + 1:
        raise ValueError(
            f"n must be >= r + 1 = {r + 1} for alpha_deg={alpha_deg!r} (r = {r} by "
            f"equation (3); Delta_0 needs the vertex ((r+1)/n, 0)), got n={n}"
        )
    h = math.sqrt((2 * r + 1) * (2 * r - 1)) / (2 * n)
    return Params(n=n, alpha_deg=float(alpha_deg), r=r, h=h, a=h + 1.0 / h)


def steps(n: int, alpha_deg: float = 20.0) -> int:
    """Number of scripted steps of Theorem 3 that exist: floor((n-1)/r).

    As printed, Theorem 3 splits Δ_k for k = 0 .. floor(n/r) - 1, but Δ_k has the
    vertex ((kr+r+1)/n, 0), an input point only while kr + r + 1 <= n.  So when r
    divides n the last printed step does not exist and floor(n/r) - 1 steps remain;
    otherwise floor((n-1)/r) = floor(n/r).  This is also the number of Steiner
    vertices the script inserts.
    """
    return params(n, alpha_deg).steps


def input_indices(n: int) -> dict[str, int | range]:
    """Vertex indices of :func:`example`, by role (see the module docstring).

    ``bottom``: range of the points (i/n, 0), i = 0..n (index i); ``top_left`` and
    ``top_right``: (0, a) and (1, a); ``apex``: P_0 = (1/(2n), h); ``box``: range of
    the 8 box points; ``first_steiner``: n + 12, the default index of P_1.
    """
    n = as_integer(n, "n")
    if n < 1:
        raise ValueError(f"n must be >= 1, got {n}")
    return {
        "bottom": range(n + 1),
        "top_left": n + 1,
        "top_right": n + 2,
        "apex": n + 3,
        "box": range(n + 4, n + 12),
        "first_steiner": n + 12,
    }


def input_points(n: int, alpha_deg: float = 20.0) -> np.ndarray:
    """The n + 4 points of equation (2), float64 (n+4, 2), in the module's numbering.

    Rows 0..n are (i/n, 0); rows n+1, n+2 are (0, a), (1, a); row n+3 is
    P_0 = (1/(2n), h).
    """
    p = params(n, alpha_deg)
    pts = np.zeros((n + 4, 2))
    pts[: n + 1, 0] = [i / n for i in range(n + 1)]
    pts[n + 1] = (0.0, p.a)
    pts[n + 2] = (1.0, p.a)
    pts[n + 3] = (1.0 / (2 * n), p.h)
    return pts


def box_points(n: int, alpha_deg: float = 20.0) -> np.ndarray:
    """The 8 box points of the extended input (Section 2), float64 (8, 2).

    The box has side 3a and centre (1/2, a/2), so it spans x in [1/2 - 3a/2,
    1/2 + 3a/2] and y in [-a, 2a].  Order: counter-clockwise from the lower-left
    corner, alternating corners and side midpoints (indices n+4 .. n+11 of
    :func:`example`).  The three points of each side share one coordinate
    exactly, so each side is exactly straight.
    """
    a = params(n, alpha_deg).a
    x0, xm, x1 = 0.5 - 1.5 * a, 0.5, 0.5 + 1.5 * a
    y0, ym, y1 = -a, 0.5 * a, 2.0 * a
    return np.array(
        [(x0, y0), (xm, y0), (x1, y0), (x1, ym), (x1, y1), (xm, y1), (x0, y1), (x0, ym)]
    )


def box_segments(n: int) -> np.ndarray:
    """The 8 box subsegments (Section 2) as int32 (8, 2) vertex indices of :func:`example`."""
    j = np.arange(8)
    return (np.c_[j, (j + 1) % 8] + n + 4).astype(np.int32)


def example(n: int, alpha_deg: float = 20.0) -> dict[str, np.ndarray]:
    """The paper's extended input E for I(n) as a PSLG dict (``triangle`` package keys).

    ``vertices`` float64 (n+12, 2): the n + 4 points of equation (2), then the box of
    side 3a centred at (1/2, a/2) (corners and side midpoints, counter-clockwise
    from the lower-left corner); ``vertex_markers`` int32 (n+12, 1): 0 for the
    input points, 1 for the box; ``segments`` int32 (8, 2): the eight box
    subsegments; ``segment_markers`` int32 (8, 1): 1.  See the module docstring
    for the numbering.  Raises ValueError for n < r + 1 or an angle outside
    0 < alpha_deg <= ALPHA_MAX_DEG.
    """
    vertices = np.vstack([input_points(n, alpha_deg), box_points(n, alpha_deg)])
    markers = np.zeros((n + 12, 1), dtype=np.int32)
    markers[n + 4 :] = 1
    return {
        "vertices": np.ascontiguousarray(vertices, dtype=np.float64),
        "vertex_markers": markers,
        "segments": box_segments(n),
        "segment_markers": np.ones((8, 1), dtype=np.int32),
    }


def _step(p: Params, k: int, last: int, what: str) -> int:
    k = as_integer(k, "k")
    if not 0 <= k <= last:
        raise ValueError(
            f"{what} exists for 0 <= k <= {last} when n={p.n}, r={p.r} "
            f"(steps = floor((n-1)/r) = {p.steps}), got k={k}"
        )
    return k


def steiner_point(n: int, k: int, alpha_deg: float = 20.0) -> tuple[float, float]:
    """P_k = (k r/n + 1/(2n), h), equation (9); P_0 = (1/(2n), h) is the input point of (2).

    P_k for k >= 1 is the circumcenter inserted by step k - 1 (Lemma 1).  Valid for
    0 <= k <= steps(n).  The x coordinate is computed as (2kr + 1)/(2n), one
    rounding.
    """
    p = params(n, alpha_deg)
    k = _step(p, k, p.steps, "P_k")
    return ((2 * k * p.r + 1) / (2 * n), p.h)


def new_point(n: int, k: int, alpha_deg: float = 20.0) -> tuple[float, float]:
    """The point step k inserts: the circumcenter of Δ_k, ((k+1) r/n + 1/(2n), h).

    Lemma 1 (with i = kr): the circumcenter S of CDP lies on the bisector of CD,
    x = (i+r)/n + 1/(2n), and at height h because CDS is congruent to ABP.  This is
    P_{k+1} of equation (9).  Valid for 0 <= k < steps(n).
    """
    p = params(n, alpha_deg)
    k = _step(p, k, p.steps - 1, "step k")
    return steiner_point(n, k + 1, alpha_deg)


def apex_index(n: int, k: int, *, first_steiner: int | None = None) -> int:
    """Index of P_k: n + 3 for k = 0 (an input vertex), else ``first_steiner + k - 1``.

    ``first_steiner`` is the index the first Steiner point gets (default n + 12, the
    first index after the extended input of :func:`example`).  Raises ValueError for
    a negative or non-integer k.
    """
    k = as_integer(k, "k")
    if k < 0:
        raise ValueError(f"k must be >= 0, got {k}")
    if k == 0:
        return n + 3
    return (n + 12 if first_steiner is None else first_steiner) + k - 1


def delta(
    n: int, k: int, alpha_deg: float = 20.0, *, first_steiner: int | None = None
) -> tuple[int, int, int]:
    """Vertex indices (C, D, P) of Δ_k, counter-clockwise (Lemma 1, Theorem 3).

    Δ_k has the vertices C = ((kr+r)/n, 0), D = ((kr+r+1)/n, 0) (input indices
    kr + r and kr + r + 1) and P = P_k = (kr/n + 1/(2n), h), which is Lemma 1's
    C, D, P with i = kr.  P is indexed by :func:`apex_index`.  Valid for
    0 <= k < steps(n).
    """
    p = params(n, alpha_deg)
    k = _step(p, k, p.steps - 1, "Delta_k")
    c = k * p.r + p.r
    return (c, c + 1, apex_index(n, k, first_steiner=first_steiner))


def delta_points(n: int, k: int, alpha_deg: float = 20.0) -> np.ndarray:
    """Coordinates of Δ_k's vertices (C, D, P), float64 (3, 2), same order as :func:`delta`."""
    c, d, _ = delta(n, k, alpha_deg)
    return np.array([(c / n, 0.0), (d / n, 0.0), steiner_point(n, k, alpha_deg)])


def broom(
    n: int, k: int, alpha_deg: float = 20.0, *, first_steiner: int | None = None
) -> np.ndarray:
    """Lemma 2's triangles for P_k, int32 (n - kr, 3), counter-clockwise.

    The rows (m, m+1, P_k) for kr <= m < n: after inserting P_1..P_k these are all
    Delaunay.  For k >= 1 they are the triangles (13) that step k - 1 creates.
    Valid for 0 <= k <= steps(n).
    """
    p = params(n, alpha_deg)
    k = _step(p, k, p.steps, "P_k")
    m = np.arange(k * p.r, n)
    apex = np.full_like(m, apex_index(n, k, first_steiner=first_steiner))
    return np.c_[m, m + 1, apex].astype(np.int32)


def step_lower_bound(n: int, k: int, alpha_deg: float = 20.0) -> int:
    """Theorem 3: step k creates at least n - r(k+1) triangles (the broom (13)).

    Valid for 0 <= k < steps(n).
    """
    p = params(n, alpha_deg)
    k = _step(p, k, p.steps - 1, "step k")
    return n - p.r * (k + 1)


def theorem3_bound(n: int, alpha_deg: float = 20.0) -> float:
    """Equation (12): the scripted steps create at least n²/(2r) - 2n triangles.

    Sum (14) taken over the steps that exist (:func:`steps`) still reaches it.
    """
    p = params(n, alpha_deg)
    return n * n / (2 * p.r) - 2 * n


def __getattr__(name: str):
    """``quadratic.replay`` is ``instrument.replay.replay`` (Theorem 3 on the
    engine), loaded on first use: that module imports this one."""
    if name == "replay":
        from .replay import replay

        return replay
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
