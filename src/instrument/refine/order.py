# cython: language_level=3
"""Which bad triangle is split next: strategies by name, an id each, and
their priority keys.

Every strategy (``strategies()`` names them) is one priority key
per queued triangle (smaller is served first; ties go to the earlier
entry), computed by ``priority`` when the triangle is queued, so the hot
loop never calls back into Python.  A binary heap serves them, except
Triangle's order, whose key is its bucket number negated: that one is
served from 4096 FIFO lists, as Triangle does (queues.py), in the same
order and in constant time; and from more lists past Triangle's finest one
for squared edges beyond the doubles' range (``wide_bucket``), which
Triangle's formula would put all into its last list.
"""

from __future__ import annotations

import math

import cython

_DBL_MAX = 1.7976931348623157e308

if not cython.compiled:  # compiled, these are order.pxd's enum
    TRIANGLE, WORST_ANGLE, FIFO, LIFO, RANDOM, LARGEST, SMALLEST, ADVERSARY = range(8)

_DESCRIPTIONS = {
    "triangle": (TRIANGLE, "Triangle 1.6's order: 4096 FIFO buckets by squared shortest edge, finest first"),
    "worst-angle": (WORST_ANGLE, "smallest minimum angle first (CGAL's order)"),
    "fifo": (FIFO, "first queued, first split"),
    "lifo": (LIFO, "last queued, first split"),
    "random": (RANDOM, "uniformly random among the queued triangles (seeded)"),
    "largest": (LARGEST, "largest circumradius first"),
    "smallest": (SMALLEST, "smallest circumradius first"),
    "adversary": (ADVERSARY, "greedy: the split that would create the most triangles, measured when queued"),
}


def strategies() -> dict[str, str]:
    """Strategy names with one line each, in a stable order."""
    return {name: text for name, (_, text) in _DESCRIPTIONS.items()}


def strategy_id(name: str) -> int:
    """The id of strategy ``name`` (ValueError naming the choices if there is none)."""
    try:
        return _DESCRIPTIONS[name][0]
    except KeyError:
        raise ValueError(f"unknown strategy {name!r}; choose one of {', '.join(_DESCRIPTIONS)}") from None


# The keys: compiled, order.pxd's inline definitions (every queued triangle
# needs one); the same functions for the pure-Python mode.
if not cython.compiled:

    def triangle_bucket(key: float) -> int:
        """Triangle's bucket (0..4095) for a squared shortest edge ``key``.

        ``L = key`` or ``1 / key``, whichever is at least 1, written ``2^e f`` with
        ``f`` in (1, 2]; ``x = 2e + [f > sqrt 2]``; bucket ``2047 - x`` for
        ``key >= 1`` and ``2048 + x`` below.  Higher buckets are served first.
        """
        if key <= 0.0 or key != key:
            return 4095
        big = key >= 1.0
        length = key if big else 1.0 / key
        if not length <= _DBL_MAX:  # infinite
            return 0 if big else 4095
        # frexp: length = mant * 2**ex with mant in [0.5, 1); shift to f in (1, 2]
        mant, ex = math.frexp(length)
        f = 2.0 * mant
        e = ex - 1
        if f == 1.0 and e > 0:  # exact power of two: f = 2, one exponent lower
            f = 2.0
            e -= 1
        x = 2 * e + (1 if f > math.sqrt(2.0) else 0)
        if x > 2047:
            x = 2047
        return 2047 - x if big else 2048 + x

    TOP_BUCKET = 4095
    WIDE_BUCKETS = 10496

    def wide_bucket(dx: float, dy: float, unit_exp: int) -> int:
        """The bucket of the squared length of ``(dx, dy) * 2^unit_exp`` where
        that square leaves the doubles: ``triangle_bucket``'s formula with
        ``x`` going on past 2047 (order.pxd says how)."""
        big = max(abs(dx), abs(dy))
        if not (big > 0.0 and big <= _DBL_MAX):
            return TOP_BUCKET
        eb = math.frexp(big)[1]
        sx = math.ldexp(dx, -eb)
        sy = math.ldexp(dy, -eb)
        mant, e = math.frexp(1.0 / (sx * sx + sy * sy))
        f = 2.0 * mant
        e = e - 1 - 2 * (eb + unit_exp)
        if f == 1.0 and e > 0:
            f = 2.0
            e -= 1
        x = 2 * e + (1 if f > math.sqrt(2.0) else 0)
        if x < 0:
            return 2047
        return 2048 + min(x, WIDE_BUCKETS - 2049)

    def priority(strategy: int, min_edge2: float, cos2_min_angle: float, circumradius2: float,
                 created_estimate: int, seq: int, rnd: float) -> float:
        """The queue key of a bad triangle (smaller first); ``seq`` breaks ties."""
        if strategy == TRIANGLE:
            return -float(triangle_bucket(min_edge2))
        if strategy == WORST_ANGLE:
            return -cos2_min_angle
        if strategy == FIFO:
            return 0.0
        if strategy == LIFO:
            return -float(seq)
        if strategy == RANDOM:
            return rnd
        if strategy == LARGEST:
            return -circumradius2
        if strategy == SMALLEST:
            return circumradius2
        return -float(created_estimate)  # ADVERSARY
