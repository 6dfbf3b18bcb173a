"""Theorem 3's adversary, played on the engine: the scripted splits of I(n).

Barbič and Miller (``shared/seed/barbic-miller-quadratic-ruppert.md``) prove
that Ruppert's algorithm may create Θ(n²) triangles on I(n) by naming the
order of the splits: Δ_0, Δ_1, ... (Theorem 3).  :func:`replay` plays that
order on the engine's own refinement state, with every counter on, then
lets a strategy finish the refinement:

1. the pipeline of ``triangulate(example(n), "pq<alpha>")`` up to the
   refinement: Delaunay triangulation, the eight box subsegments, the
   refinement state (``refine.new_refiner``), the encroachment tally
   (which must find nothing: Theorem 3's proof);
2. the scripted phase: for k = 0, 1, ..., find Δ_k = (C, D, P_k) in the mesh
   and split it with the engine's own ``split_bad_triangle`` (walk, cavity,
   Bowyer-Watson fill, quality tests of the new triangles), inserting its
   circumcenter as Ruppert's algorithm does (the paper's rule; off-centers
   are off for this phase);
3. the finishing phase: the engine's refinement loop under strategy
   ``then`` (and ``steiner``), exactly as ``triangulate`` runs it.

At every step the mesh is held to the paper (a :class:`ReplayError` says
where it departs): Lemma 1 -- Δ_k is in the mesh and skinny (its angle at
P_k is θ < alpha), the new point is ((k+1)r/n + 1/(2n), h), triangle CDS is
in the mesh and congruent to ABP; Lemma 2 -- the broom (m, m+1, P_{k+1}),
(k+1)r <= m < n, is in the mesh (for k = 0 also the broom of P_0 in the
initial mesh); no subsegment is encroached; step k creates at least
n - r(k+1) triangles.

Theorem 3 as printed runs k to floor(n/r) - 1, but Δ_k needs the input
vertex kr + r + 1 <= n: when r divides n the last printed step does not
exist, and the replay makes ``quadratic.steps(n)`` = floor((n-1)/r) steps
(the missing step's share of sum (14) is n - r(k+1) = 0, so bound (12)
stands).

Work is counted by the engine's counters (``Result.work``, the same names as
``triangulate``'s); the look-ups that find Δ_k for the check are the
adversary's knowledge, not refinement work, and count into a scratch array.
"""

from __future__ import annotations

import math

import numpy as np

from . import counters, quadratic, refine
from .core.navigate import build_vertex_edges, find_edge
from .core.status import NEED_ROOM
from .output import assemble
from .pipeline import mesh_input, validate
from .refine.order import FIFO
from .refine.queues import queue_clear
from .refine.splits import split_bad_triangle, tally_encroached
from .refine.order import strategy_id
from .switches import parse

__all__ = ["ReplayError", "replay"]

NOT_FOUND = -1

#: Relative tolerance of the coordinate and congruence checks: the circumcenters
#: are computed in floating point (measured: a few units in the last place).
RTOL = 1e-9


class ReplayError(RuntimeError):
    """The mesh departs from Barbič and Miller's Lemma 1, Lemma 2 or Theorem 3."""


def scripted_split(r, ms, look: np.ndarray, look_rng: list[int], c: int, d: int, p: int) -> int:
    """Split triangle (c, d, p) with Ruppert's rule, as the refinement loop
    splits a bad triangle.  Returns ``NOT_FOUND`` if no live triangle has the
    edge c -> d with apex p, else ``split_bad_triangle``'s status (DONE, or
    NEED_ROOM: nothing changed).

    The look-up counts into ``look`` and walks with its own generator
    (``look_rng[0]``), not the run's.  The bad-triangle queue is emptied
    first: the scripted phase never serves it, and the finishing phase
    re-tallies every triangle."""
    m = ms.mesh
    work, rng = m.work, m.rng
    m.work, m.rng = look, look_rng[0]
    try:
        e = find_edge(m, c, d)
    finally:
        look_rng[0] = m.rng
        m.work, m.rng = work, rng
    if e < 0 or m.corner[e] != p:
        return NOT_FOUND
    queue_clear(r)
    # computed from the handle with origin at the slot's corner 0 (the
    # new vertex for a triangle an insertion made): I(n) is full of
    # cocircular trapezoids, so P_k's last bits decide Delaunay ties,
    # and this rounding is the one tests/engine/test_replay.py checks
    # step by step against Triangle's triangulation from scratch
    return split_bad_triangle(r, m, ms.segs, 3 * (e // 3) + 2)


def _angles(xy: np.ndarray) -> np.ndarray:
    """Angles (degrees) at the three corners of the triangle ``xy`` (3, 2)."""
    out = np.zeros(3)
    for i in range(3):
        u = xy[(i + 1) % 3] - xy[i]
        w = xy[(i + 2) % 3] - xy[i]
        out[i] = math.degrees(math.atan2(abs(u[0] * w[1] - u[1] * w[0]), float(u @ w)))
    return out


def _sides(xy: np.ndarray) -> np.ndarray:
    return np.sort([math.dist(xy[i], xy[(i + 1) % 3]) for i in range(3)])


def _close(a, b, scale: float) -> bool:
    return bool(np.all(np.abs(np.asarray(a, dtype=float) - np.asarray(b, dtype=float)) <= RTOL * scale))


def _broom_missing(fan_corners: np.ndarray, apex: int, lo: int, n: int) -> np.ndarray:
    """The m in lo..n-1 for which (apex, m, m+1) is not among ``fan_corners``
    (rows of corners starting at the apex, counter-clockwise)."""
    rows = fan_corners[fan_corners[:, 0] == apex]
    u, w = rows[:, 1], rows[:, 2]
    hit = np.zeros(n + 1, dtype=bool)
    ok = (w == u + 1) & (u >= lo) & (u < n)
    hit[u[ok]] = True
    return np.flatnonzero(~hit[lo:n]) + lo


def _live_corners(m) -> np.ndarray:
    return np.asarray(m.corner).reshape(-1, 3)[m.live_triangles()]


def _apex_first(c: np.ndarray, apex: int) -> np.ndarray:
    """Rows rotated so that ``apex`` (where present) is the first corner."""
    out = c.copy()
    for k in (1, 2):
        sel = c[:, k] == apex
        out[sel] = np.roll(c[sel], -k, axis=1)
    return out


def replay(
    n: int,
    alpha_deg: float = 20.0,
    *,
    then: str | None = "triangle",
    steiner: str = "offcenter",
    stop_after: int | None = None,
):
    """Split Δ_0, Δ_1, ... of I(n) in Theorem 3's order, then finish with ``then``.

    ``then``: the strategy that finishes the refinement (a name of
    ``instrument.strategies()``), or ``None`` to stop after the scripted phase
    (the mesh is then not of quality: Δ_k's successors are still skinny).
    ``steiner``: the finishing phase's new points ("offcenter", Triangle's, or
    "circumcenter"); the scripted steps always insert circumcenters, as in the
    paper.  ``stop_after``: play only that many scripted steps (default: all
    ``quadratic.steps(n, alpha_deg)``).

    Returns a ``Result`` (the ``triangle`` package's keys, as
    ``triangulate(example(n, alpha_deg), "pq<alpha>")`` would) with ``work``
    (every counter, setup and finishing included), ``steps`` (int64 array:
    triangles created by scripted step k), ``scripted_work`` (the counters of
    the scripted phase alone), ``setup_work`` (before it: Delaunay
    triangulation and subsegments) and ``params`` (``quadratic.Params``).
    Step k inserts vertex ``n + 12 + k``.  Raises
    ``ReplayError`` where the mesh departs from Lemma 1, Lemma 2 or Theorem 3.
    """
    p = quadratic.params(n, alpha_deg)
    if then is not None:
        strategy_id(then)
    if steiner not in refine.STEINER:
        raise ValueError(f"steiner must be one of {', '.join(refine.STEINER)}, not {steiner!r}")
    total = p.steps
    if stop_after is not None:
        stop_after = quadratic.as_integer(stop_after, "stop_after")
        if not 0 <= stop_after <= total:
            raise ValueError(f"stop_after must be in 0..{total} (the steps that exist for n={n}, r={p.r}), got {stop_after}")
        total = stop_after

    o = parse(f"pq{float(alpha_deg)!r}")
    tri = quadratic.example(n, alpha_deg)
    inp = validate(tri, o)
    work = counters.new_work()
    ms = mesh_input(inp, o, work)
    if ms.n_vertices != n + 12 or int(work[counters.C_STEINER]):
        raise ReplayError("the extended input did not triangulate to its own n + 12 vertices")

    r = refine.new_refiner(ms, o, then or "fifo", "circumcenter", False)
    r.cfg.strategy = FIFO  # cheap keys while the queue is unused
    build_vertex_edges(ms.mesh)
    tally_encroached(r, ms.mesh, ms.segs)
    if r.enc_live:
        raise ReplayError("a box subsegment is encroached in the extended input (Theorem 3: none is)")
    setup = work.copy()

    # Lemma 2, k = 0: the broom of P_0 is in the initial triangulation
    apex0 = quadratic.apex_index(n, 0)
    corners = _apex_first(_live_corners(ms.mesh), apex0)
    missing = _broom_missing(corners, apex0, 0, n)
    if missing.size:
        raise ReplayError(f"Lemma 2 (k = 0): triangle ({missing[0]}, {missing[0] + 1}, P_0) is not in the initial mesh")

    look = counters.new_work()
    look_rng = [12345]
    steps = np.zeros(total, dtype=np.int64)

    def xy_bottom(i: int) -> tuple[float, float]:
        return (i / n, 0.0)

    first = ms.n_vertices  # P_1's index
    for k in range(total):
        c, d, apex = quadratic.delta(n, k, alpha_deg, first_steiner=first)
        m = ms.mesh
        xy = np.asarray(m.xy)
        # Lemma 1: Δ_k is skinny, its angle at P_k is θ
        tri_xy = np.array([xy_bottom(c), xy_bottom(d), xy[apex]])
        ang = _angles(tri_xy)
        # (for r = 1 the angle at D is θ too: Δ_k is isosceles)
        smallest = ang[2] <= ang.min() * (1.0 + RTOL)
        if not (ang[2] < alpha_deg and smallest) or not math.isclose(ang[2], p.theta_deg, rel_tol=RTOL):
            raise ReplayError(
                f"Lemma 1, step {k}: Delta_{k} has the angle {ang[2]!r} at P_{k}, not theta = {p.theta_deg!r} < {alpha_deg!r}"
            )
        created0 = int(work[counters.C_CREATED])
        steiner0 = int(work[counters.C_STEINER])
        while True:
            status = scripted_split(r, ms, look, look_rng, c, d, apex)
            if status != NEED_ROOM:
                break
            refine.grow_refiner(ms, r)
        if status == NOT_FOUND:
            raise ReplayError(f"Lemma 2, step {k}: Delta_{k} = ({c}, {d}, P_{k}) is not in the mesh")
        xy = np.asarray(m.xy)
        nb = int(work[counters.C_CREATED]) - created0
        v = m.nvert - 1
        if int(work[counters.C_STEINER]) != steiner0 + 1 or v != first + k:
            raise ReplayError(f"step {k}: the circumcenter of Delta_{k} was not inserted (rejected or a duplicate)")
        if r.enc_live:
            raise ReplayError(f"step {k}: P_{k + 1} encroaches a box subsegment (Theorem 3: it cannot)")
        steps[k] = nb
        # Lemma 1: the new point is S = ((k+1) r/n + 1/(2n), h), and CDS is congruent to ABP
        want = quadratic.new_point(n, k, alpha_deg)
        if not _close(xy[v], want, 1.0 / n):
            raise ReplayError(f"Lemma 1, step {k}: the circumcenter is {tuple(xy[v])}, not {want}")
        fan = _apex_first(np.asarray(m.corner).reshape(-1, 3)[np.asarray(r.fan)[:nb]], v)
        cds = np.array([xy_bottom(c), xy_bottom(d), xy[v]])
        abp = np.array([xy_bottom(k * p.r), xy_bottom(k * p.r + 1), xy[apex]])
        if not _close(_sides(cds), _sides(abp), 1.0 / n):
            raise ReplayError(f"Lemma 1, step {k}: CDS {_sides(cds)} is not congruent to ABP {_sides(abp)}")
        # Lemma 2: the broom of P_{k+1} (CDS is its first triangle) was created by this step
        missing = _broom_missing(fan, v, (k + 1) * p.r, n)
        if missing.size:
            raise ReplayError(f"Lemma 2, step {k}: triangle ({missing[0]}, {missing[0] + 1}, P_{k + 1}) is not in the mesh")
        if nb < quadratic.step_lower_bound(n, k, alpha_deg):
            raise ReplayError(f"Theorem 3, step {k}: {nb} triangles created, fewer than n - r(k+1)")
    scripted = work - setup

    if then is not None:
        r.cfg.strategy = strategy_id(then)
        r.cfg.offcenter = steiner == "offcenter"
        queue_clear(r)
        refine.finish(ms, r)  # the engine's refinement loop from where the script left it
    result = assemble(ms, inp, o)
    result.work = counters.as_dict(work)
    result.steps = steps
    result.scripted_work = counters.as_dict(scripted)
    result.setup_work = counters.as_dict(setup)
    result.params = p
    result.warnings = ms.warnings
    return result

