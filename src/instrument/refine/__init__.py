"""Quality refinement, the pipeline's fourth stage (``q``, ``a``, ``u``, ``D``).

The kernels (splits.py and the modules it uses) run Ruppert's algorithm
with Triangle's rules until no triangle is bad; this driver sets up their
state from the switches, grows the mesh and the state when they ask for
room, lets Python in when they pause (Ctrl-C, progress, the vertex limit),
runs a Python ``triunsuitable`` between their rounds, and turns their
outcomes into results or errors.

Modules, in the order they build on each other:

* ``order``: the strategies' priority keys;
* ``state``: the run's ``Config`` and the loop's ``Refiner``;
* ``queues``: the bad-triangle queue (a heap, or Triangle's buckets);
* ``ghosts``: Triangle's triangle records through an insertion (which of a
  rejected Steiner point's queued triangles it serves again);
* ``encroach``: the diametral-lens test and the encroached-subsegment pool;
* ``cavity``: inserting a vertex (Bowyer-Watson cavity, rim, fan);
* ``criteria``: the bad-triangle test and the Steiner point;
* ``deletion``: Chew's deletion of free vertices;
* ``splits``: splitting subsegments and bad triangles, and the loop.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from .. import limits
from ..core.mesh import V_DEAD
from ..core.filled import filled
from ..core.navigate import build_vertex_edges, turn_vertex_edges
from ..core.scaling import half_extent
from ..core.status import DONE, PAUSE, PRECISION
from ..errors import TriangleError
from ..state import MeshState
from .order import strategy_id
from ..switches import Options
from .criteria import queue_triangles
from .queues import queue_clear, queue_used
from .splits import refine, tally_encroached
from .state import TRACE_KINDS, Config, Refiner

STEINER = ("offcenter", "circumcenter")

TRACE_DTYPE = np.dtype(
    [("kind", "U12"), ("created", "i8"), ("deleted", "i8"), ("walk_steps", "i8"), ("queue_length", "i8")]
)

# Measured: q20-q34 meshes under a fixed area bound A come out at 1.2-1.6 triangles per A
# of domain (the unit square pq30a1e-6: 1,584,789), so room for 1.7 per A is rarely grown.
TRIANGLES_PER_AREA_BOUND = 1.7
PRESIZE_LIMIT = 1 << 26  # triangles: beyond this, grow on demand
SMALL_MESH = 1 << 15  # triangles: below this, refinement starts with room for four times the vertices


class PrecisionError(TriangleError):
    """Triangle's "Ran out of precision" failure: segments too short to split."""


def run(
    ms: MeshState,
    o: Options,
    *,
    strategy: str = "triangle",
    steiner: str = "offcenter",
    trace: bool = False,
    triunsuitable: Callable | None = None,
    max_vertices: int | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> np.ndarray | None:
    """Refine ``ms`` in place under ``o``; returns the trace (one record per
    insertion attempt) if asked.

    With ``o.u`` and a Python ``triunsuitable``, the kernel refines until
    nothing is bad, then the callable judges every triangle made since, the
    unsuitable ones are queued and the kernel goes on, until a round finds
    none: the hot loop never calls Python.

    ``max_vertices`` bounds the mesh (None: ``limits.vertex_limit``'s
    default); passing it raises ``SizeLimitError``.  ``progress(vertices,
    limit)`` is called whenever the kernel hands back control (every few
    thousand splits)."""
    if steiner not in STEINER:
        raise ValueError(f"steiner must be one of {', '.join(STEINER)}, not {steiner!r}")
    if steiner_budget(ms, o) == 0:
        return np.zeros(0, dtype=TRACE_DTYPE) if trace else None
    user = triunsuitable if o.u else None
    bound = _smallest_area_bound(ms, o)
    domain = _domain_area(ms) if bound else 0.0  # the limit depends on the domain only under an area bound
    if max_vertices is None:
        n_input = ms.n_input + ms.segs.count
        limit = limits.vertex_limit(n_input=n_input, domain_area=domain, area_bound=bound,
                                    steiner_budget=steiner_budget(ms, o), angle_bound=o.q)
    else:
        limit = int(max_vertices)
    why = limits.explain(max_vertices is None)
    limits.check_expected(limit, domain, bound, explain=why)
    _presize(ms, o, domain, limit)
    r = new_refiner(ms, o, strategy, steiner, trace, user is not None)
    # The refiner splits and tests a triangle from handle 3 t (org, dest,
    # apex = corners 1, 2, 0), the handle Triangle queues for the triangles
    # an insertion makes, which the kernels store with the new vertex at
    # corner 0.  The mesh so far holds its triangles in output order (org,
    # dest, apex of Triangle's orientation 0), and Triangle tests those from
    # orientation 0: turn them so that handle 3 t is that one too.  The
    # handle decides the Steiner point's rounding, where the walk starts, the
    # order of the new triangles, and Triangle's -u test at its org; with the
    # turn, -r with area bounds makes Triangle's meshes (bbox.1).  At the end
    # every triangle turns the other way: the untouched ones back to their
    # order, the new ones to (org, dest, apex) of handle 3 t.  (Triangle's
    # flips move corners between its records, so no one order is its output
    # order for every new triangle; this one matches more of them: 75 of
    # double_hex's 198 under pq, against 56 with the new vertex first.)
    ms.mesh.rotate_corners(2)
    build_vertex_edges(ms.mesh)
    tally_encroached(r, ms.mesh, ms.segs)
    guard = _Guard(limit, o.min_angle if o.q else 0.0, why, progress)
    try:
        finish(ms, r, user, guard)
    except PrecisionError as exc:
        if o.q and o.min_angle > limits.USUAL_ANGLE:  # the likely cause, and what to change
            raise PrecisionError(
                f"{exc}\n  A minimum angle of {o.min_angle:g} degrees is above {limits.USUAL_ANGLE:g}, where "
                f"refinement usually ends: use a smaller angle, or -S to bound the Steiner points."
            ) from None
        raise
    ms.mesh.rotate_corners(1)
    turn_vertex_edges(ms.mesh, 1)  # (the hints refinement kept, renumbered: no rebuild)
    if trace:
        return _trace_table(np.asarray(r.trace)[: r.ntrace])
    _spare(r)
    return None


def steiner_budget(ms: MeshState, o: Options) -> int:
    """The Steiner points refinement may still add under ``-S`` (-1: no limit).

    The vertices segment recovery made where segments cross use up the
    budget, as in Triangle (pa0.0086S5 on a five-pointed star: its five
    crossings leave nothing for refinement, and S3 leaves nothing either:
    the crossings are never refused, the budget just stops at 0)."""
    if o.S < 0:
        return -1
    return max(0, o.S - (ms.mesh.nvert - ms.n_input))


#: Inputs whose extent lies within 2^+-KEY_RANGE key Triangle's buckets by
#: their squared edges as they are, as Triangle does.
KEY_RANGE = 400


def key_unit(xy, n: int | None = None) -> float:
    """The power of two by which edges are measured for Triangle's queue
    buckets: 1 for an input whose extent lies within 2^+-KEY_RANGE, else one
    that brings the extent to about 1.

    A bucket is the binary exponent of a squared shortest edge, clipped to
    the doubles' range: beyond 2^+-512 every edge's square over- or
    underflowed to the first or last bucket, the order turned into one first
    in, first out list, and A.poly under pq30 gave 85 vertices (76 at any
    scale in range); 4-point-set polygons at 1e-201 under q34 ran to the
    vertex limit where the same input times 2^667 gives 188.  Measured in
    these units, a mesh is one mesh times the scale (a power of two), and in
    range nothing changes.  Edges whose squares in these units are still
    below the doubles' range (a mesh graded from 1e-301 to 1e300) go on past
    Triangle's finest bucket (criteria._triangle_key, order.wide_bucket).
    ``xy``: the vertices' rows (C-contiguous float64), of which the first
    ``n`` count (default: all)."""
    half = half_extent(xy, len(xy) if n is None else n)
    if half == 0.0:
        return 1.0
    exponent = math.frexp(half)[1] + 1  # the extent lies in [2^(exponent-1), 2^exponent)
    if -KEY_RANGE < exponent <= KEY_RANGE:
        return 1.0
    return math.ldexp(1.0, -exponent)


def new_refiner(ms: MeshState, o: Options, strategy: str, steiner: str, trace: bool, python_test: bool = False) -> Refiner:
    """The refinement kernel's state for mesh ``ms`` under switches ``o``:
    the queues empty (``tally_encroached`` and ``finish`` fill them).
    ``python_test``: a Python ``triunsuitable`` runs between kernel rounds,
    so the kernel's own ``-u`` test stays off."""
    m = ms.mesh
    m.add_constraint_tables()
    slots = m.triangle_capacity
    cfg = Config(o, strategy_id(strategy), steiner == "offcenter", python_test)
    cfg.key_unit = key_unit(m.xy, m.nvert)
    # The queue is compacted only when it holds more than twice the live
    # triangles (see splits.refine), so a mesh that fills its slots fills a
    # queue of twice as many entries: room for them at once, in zeros the
    # OS maps only as the queue reaches them, spares doubling (and copying)
    # it late in the run (100 ms of 2 s on the unit square under a1e-6).
    queue = 2 * slots + 4096 + 64
    records = 2 * ms.segs.count + 64  # room for every subsegment
    r = None if trace else _reused(slots, queue, records)
    if r is not None:
        r.restart(cfg, steiner_budget(ms, o))
        return r
    return Refiner(cfg, budget=steiner_budget(ms, o), slots=slots, queue=queue, records=records, trace=trace)


#: Refiners of finished small runs (``SPARE_SLOTS`` triangle slots at most,
#: ``SPARES`` of them), which the next runs take instead of allocating their
#: own: a refiner's twenty arrays cost as much to make as a small run's
#: whole segment recovery (95k instructions; a single triangle's run is some
#: 700k).  A run takes one off the list and puts it back when it is done, so
#: two runs never share one (list.pop and append are atomic).  The arrays
#: are at least as large as a new refiner's would be, and no result depends
#: on their room (tests/unit/test_room.py).
_spares: list[Refiner] = []
SPARE_SLOTS = 1 << 12
SPARES = 2


def _reused(slots: int, queue: int, records: int) -> Refiner | None:
    """A spare refiner with room for ``slots``, ``queue`` and ``records``, emptied, or None."""
    try:
        r = _spares.pop()
    except IndexError:
        return None
    if r.cav.shape[0] < slots or r.hkey.shape[0] < queue or r.enc.shape[0] < records:
        return None  # (too small: dropped, and a new one made)
    queue_clear(r)
    # a new run's state: no slot's Triangle orientation known until its
    # first list (ghosts.records_known; the last run's rows could match a
    # new slot's stamp and corner), the ghosts' names read as written
    r.orient_ready = False
    r.ghost_swapped = False
    return r


def _spare(r: Refiner) -> None:
    """Keep the refiner of a finished run for the next, if it is small and the list is not full."""
    if r.trace.shape[0] == 0 and r.cav.shape[0] <= SPARE_SLOTS and len(_spares) < SPARES:
        _spares.append(r)


def grow_refiner(ms: MeshState, r: Refiner) -> None:
    """After the kernel's NEED_ROOM: grow (doubling) whatever it ran out of,
    in the mesh and in ``r``."""
    need = max(64, r.need)
    r.need = 0
    ms.grow(vertices=16, triangles=need, records=16)
    slots = ms.mesh.triangle_capacity
    heap = r.hkey.shape[0]
    if heap < queue_used(r) + need or heap < slots + 16:
        heap = max(2 * heap, slots + 16)
        for name in ("hkey", "hseq", "htri", "hstamp"):
            setattr(r, name, _widened(getattr(r, name), heap, 0))
    if r.ghost.shape[0] < r.nghost + need:  # a rejected insertion's entries (queues.queue_push_ghost)
        r.ghost = _widened(r.ghost, 2 * r.ghost.shape[0] + need, 0)
    if r.born.shape[0] < slots:  # kept between steps (ghosts.note_born)
        r.born = _widened(r.born, slots, 0)
    if r.orient.shape[0] < slots:  # kept between steps (ghosts.records_known)
        r.orient = _widened(r.orient, slots, 0)
    enc = r.enc.shape[0]
    if enc < r.enc_live + need:  # a pool: slots keep their places
        r.enc = _widened(r.enc, 2 * enc + need, 0)
    if r.trace.shape[0] and r.ntrace + 64 > r.trace.shape[0]:
        r.trace = _widened(r.trace, 2 * r.trace.shape[0], 0)
    # The cavity's scratch holds nothing between steps (a NEED_ROOM step
    # changed nothing and starts again): fresh zeros, which the OS maps
    # lazily, instead of copies that touch every page.
    for name in ("cav", "fan", "bnd", "bval", "carry", "lineage", "fan_rec", "flips"):
        if getattr(r, name).shape[0] < slots:  # (the memoryview's shape: no array made to ask)
            a = np.asarray(getattr(r, name))
            setattr(r, name, np.zeros((slots,) + a.shape[1:], dtype=a.dtype))


def _widened(a, rows: int, fill) -> np.ndarray:
    """``a`` with ``rows`` rows, the new ones set to ``fill``; zeros come
    from the OS's lazily mapped pages, which the new rows touch only when used."""
    a = np.asarray(a)
    shape = (rows,) + a.shape[1:]
    out = np.zeros(shape, dtype=a.dtype) if fill == 0 else filled(shape, fill, a.dtype)
    out[: a.shape[0]] = a
    return out


class _Guard:
    """Between kernel calls: report progress, stop at the vertex limit."""

    def __init__(self, limit: int, min_angle: float, why: str, progress: Callable[[int, int], None] | None):
        self.limit = limit
        self.min_angle = min_angle
        self.why = why
        self.progress = progress

    def __call__(self, ms: MeshState) -> None:
        n = ms.n_vertices
        if self.progress is not None:
            self.progress(n, self.limit)
        if n > self.limit:
            raise limits.stopped(n, self.limit, self.min_angle, explain=self.why)


def _domain_area(ms: MeshState) -> float:
    """The area the mesh covers (its live triangles), for the size limit:
    summed on coordinates scaled by a power of two (exact) so that no
    product overflows or underflows at any finite scale; inf when the area
    itself is beyond the largest double (near 2^1024 per side)."""
    m = ms.mesh
    corner = np.asarray(m.corner).reshape(-1, 3)[m.live_triangles()]
    if corner.shape[0] == 0:
        return 0.0
    xy = np.asarray(m.xy)[: m.nvert]
    shift = int(np.frexp(np.abs(xy).max())[1])
    p = np.ldexp(xy, -shift)[corner]
    u = p[:, 1] - p[:, 0]
    w = p[:, 2] - p[:, 0]
    area = 0.5 * float(np.sum(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]))
    with np.errstate(over="ignore"):
        return float(np.ldexp(area, 2 * shift))


def _smallest_area_bound(ms: MeshState, o: Options) -> float | None:
    """The smallest area bound of the run: -a's number, or the smallest
    regional / per-triangle bound of a bare -a."""
    bounds = [o.max_area] if o.max_area > 0 else []
    if o.var_area and ms.mesh.area_bound.shape[0]:  # (the table as an array only when it is read)
        live = np.asarray(ms.mesh.area_bound)[ms.mesh.live_triangles()]
        live = live[np.isfinite(live) & (live > 0)]
        if live.size:
            bounds.append(float(live.min()))
    return min(bounds) if bounds else None


def starting_room(n_input: int, o: Options) -> int:
    """Vertices the first stages should reserve beyond the input's ``n_input``
    (``pipeline.mesh_input``'s ``room``), so that refinement rarely grows
    the mesh.  Under ``q`` without a fixed area bound a small input ends
    with up to about seven times its vertices, counting the ones Chew's rule
    deletes (la.poly under pq30: 141 to 941 vertex rows): room for that from
    the start saves the copies of every table that ``_presize`` and each
    later doubling make, which on such inputs cost a tenth of the run.
    Anything else starts small and ``_presize`` or growth makes the room.
    (Results do not depend on the room: tests/unit/test_room.py.)"""
    if o.quality and not o.max_area > 0 and 2 * n_input < SMALL_MESH:
        return 7 * n_input + 64
    return 16


def _presize(ms: MeshState, o: Options, area: float, limit: int) -> None:
    """Under a fixed area bound the mesh size is predictable: make room for
    it at once rather than doubling (and copying) a dozen times (never for
    more than the vertex limit allows).  Otherwise a small mesh gets room
    for four times its vertices: quality alone multiplies them by 1 to 6 on
    the sample and corpus inputs (la.poly under pq30: 141 to 860), and one
    allocation costs less than the five or six doublings it saves; a large
    one grows on demand.  (Results do not depend on the room:
    tests/unit/test_room.py.)"""
    n = ms.mesh.nslot
    if not o.max_area > 0:
        if n < SMALL_MESH:
            ms.grow(vertices=3 * ms.mesh.nvert + 64, triangles=6 * n + 128, records=3 * ms.segs.count + 64)
        return
    want = min(TRIANGLES_PER_AREA_BOUND * area / o.max_area, PRESIZE_LIMIT, 2.0 * limit)
    if want > 2 * n:  # vertices: about half the triangles, and the free vertices Chew's rule deletes
        ms.grow(vertices=int(0.7 * want), triangles=int(want))


def _judge(ms: MeshState, user: Callable, judged: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Ask ``user(org, dest, apex, area)`` about every live triangle it has
    not seen; returns the updated stamps and the unsuitable slots."""
    m = ms.mesh
    n = m.nslot
    stamp = np.asarray(m.stamp)[:n]
    if judged.shape[0] < n:
        judged = _widened(judged, n, 0)
    fresh = np.flatnonzero((stamp > 0) & (stamp != judged[:n]))
    judged[fresh] = stamp[fresh]
    xy = np.asarray(m.xy)
    corner = np.asarray(m.corner)
    bad = []
    for t in fresh:
        # Triangle asks about the handle it tests: org, dest, apex are corners
        # 1, 2, 0 of a slot (see run: handle 3 t)
        o, d, a = (xy[corner[3 * t + k]] for k in (1, 2, 0))
        area = 0.5 * ((d[0] - o[0]) * (a[1] - o[1]) - (d[1] - o[1]) * (a[0] - o[0]))
        if user(o.copy(), d.copy(), a.copy(), area):
            bad.append(t)
    return judged, np.asarray(bad, dtype=np.int64)


def finish(ms: MeshState, r: Refiner, user: Callable | None = None, guard: Callable[[MeshState], None] | None = None) -> None:
    """Run the refinement kernel to the end: grow its arrays when it asks,
    let Python in when it pauses (Ctrl-C), consult ``user`` when it is done,
    and turn a precision failure into Triangle's error.  ``guard(ms)`` runs
    each time the kernel hands back control, before anything grows (it may
    raise to stop the run).  Records the deleted vertices on ``ms``."""
    m = ms.mesh
    judged = np.zeros(0, dtype=np.int32)  # the stamp each slot had when the callable judged it
    while True:
        status = refine(r, m, ms.segs)
        if guard is not None and status != DONE:
            guard(ms)
        if status == DONE and user is not None and r.budget != 0:
            judged, bad = _judge(ms, user, judged)
            while r.hkey.shape[0] < queue_used(r) + bad.shape[0] + 16:
                r.need = max(r.need, bad.shape[0] + 16)
                grow_refiner(ms, r)
            queue_triangles(r, m, bad)
            if bad.shape[0]:
                continue
        if status == DONE:
            break
        if status == PAUSE:  # back in Python now and then, so Ctrl-C works
            continue
        if status == PRECISION:
            raise _precision_error(m, r.error_org, r.error_dest, r.error_apex)
        grow_refiner(ms, r)
    ms.dead = (np.asarray(m.vtype)[: m.nvert] == V_DEAD).nonzero()[0]  # (flatnonzero, without its wrappers)


def _precision_error(m, a: int, b: int, apex: int = -1) -> PrecisionError:
    xy = np.asarray(m.xy)
    if apex >= 0:  # a bad triangle whose split point rounds onto its shortest edge
        return PrecisionError(
            f"Ran out of precision at ({xy[a, 0]:.12g}, {xy[a, 1]:.12g}).\n"
            f"I attempted to split a bad triangle whose shortest edge is too short\n"
            f"  beside its coordinates for a new vertex to be placed off that edge\n"
            f"  in floating point arithmetic (the coordinates span too many orders of magnitude).\n"
            f"  (edge ({xy[a, 0]:.12g}, {xy[a, 1]:.12g}) to ({xy[b, 0]:.12g}, {xy[b, 1]:.12g}),"
            f" third vertex ({xy[apex, 0]:.12g}, {xy[apex, 1]:.12g}))"
        )
    return PrecisionError(
        f"Ran out of precision at ({xy[a, 0]:.12g}, {xy[a, 1]:.12g}).\n"
        f"I attempted to split a segment to a smaller size than\n"
        f"  can be accommodated by the finite precision of\n"
        f"  floating point arithmetic.\n"
        f"  (segment ({xy[a, 0]:.12g}, {xy[a, 1]:.12g}) to ({xy[b, 0]:.12g}, {xy[b, 1]:.12g}))"
    )


def _trace_table(rows: np.ndarray) -> np.ndarray:
    """One record per insertion attempt: kind (segment, circumcenter,
    offcenter, rejected, deleted), triangles created and deleted, walk steps,
    bad triangles queued afterwards."""
    out = np.zeros(rows.shape[0], dtype=TRACE_DTYPE)
    out["kind"] = np.array(TRACE_KINDS)[rows[:, 0]] if rows.shape[0] else []
    for i, name in enumerate(TRACE_DTYPE.names[1:], start=1):
        out[name] = rows[:, i]
    return out
