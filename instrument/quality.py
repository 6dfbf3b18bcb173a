"""Driving the refinement kernel: set it up from the switches, grow its arrays
when it asks, turn its precision failure into Triangle's error."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from . import cdt
from . import refine as rf
from .mesh import S_NSLOT, rotate_corners
from .pslg import Mesher, _widen
from .strategies import strategy_id
from .switches import Options

STEINER = ("offcenter", "circumcenter")

_TRACE_KINDS = ("segment", "circumcenter", "offcenter", "rejected", "deleted")


class PrecisionError(RuntimeError):
    """Triangle's "Ran out of precision" failure: segments too short to split."""


def new_refiner(
    ms: Mesher, o: Options, strategy: str, steiner: str, trace: bool, python_test: bool = False
) -> rf.Refiner:
    """The refinement kernel's state for mesh ``ms`` under switches ``o``: every
    vertex so far an input vertex, the queues empty (``rf.tally_encroached``
    and ``finish`` fill them).  ``python_test``: a Python ``triunsuitable``
    runs between kernel rounds, so the kernel's own ``-u`` test stays off."""
    m = ms.m
    slots = m.stamp.shape[0]
    nvcap = m.xy.shape[0]
    ipar = np.zeros(rf.I_NPAR, dtype=np.int64)
    par = np.zeros(rf.P_NPAR)
    ipar[rf.I_STRATEGY] = strategy_id(strategy)
    ipar[rf.I_D] = int(o.D)
    ipar[rf.I_Y] = o.Y
    ipar[rf.I_FIXAREA] = int(o.max_area > 0)
    ipar[rf.I_VARAREA] = int(o.var_area)
    ipar[rf.I_BUDGET] = o.S
    ipar[rf.I_OFFCENTER] = int(steiner == "offcenter")
    ipar[rf.I_ANGLE] = int(o.q and o.min_angle > 0)
    ipar[rf.I_USER] = int(o.u and not python_test)  # a Python test runs between kernel rounds instead
    ipar[rf.I_CURRENT] = -1
    ipar[rf.I_EFREE] = -1
    ipar[rf.I_BTOP] = -1
    theta = math.radians(o.min_angle) if o.q else 0.0
    good = math.cos(theta) ** 2
    par[rf.P_GOODANGLE] = good
    par[rf.P_LENS] = (2.0 * good - 1.0) ** 2
    # the off-center sits at 0.95 of the distance where the edge subtends theta
    par[rf.P_OFFCONSTANT] = 0.475 * math.sqrt((1.0 + math.cos(theta)) / (1.0 - math.cos(theta))) if theta > 0 else 0.0
    par[rf.P_MAXAREA] = o.max_area
    vtype = np.zeros(nvcap, dtype=np.int8)
    area, attr = _region_tables(ms)
    return rf.Refiner(
        ipar=ipar,
        par=par,
        vtype=vtype,
        area=area,
        attr=attr,
        hkey=np.zeros(slots + 16),
        hseq=np.zeros(slots + 16, dtype=np.int64),
        htri=np.zeros(slots + 16, dtype=np.int64),
        hstamp=np.zeros(slots + 16, dtype=np.int64),
        bucket=np.full((2, rf.NBUCKETS), -1, dtype=np.int64),
        enc=np.zeros((2 * int(ms.segs.size[cdt.R_NREC]) + 64, 4), dtype=np.int64),  # room for every subsegment
        cav=np.zeros(slots, dtype=np.int64),
        fan=np.zeros(slots, dtype=np.int64),
        seen=np.zeros(slots, dtype=np.int8),
        bnd=np.zeros((slots, 5), dtype=np.int64),
        bval=np.zeros((slots, 2)),
        carry=np.zeros(slots),
        vslot=np.full(nvcap, -1, dtype=np.int64),
        trace=np.zeros((1024 if trace else 0, 5), dtype=np.int64),
    )


def _region_tables(ms: Mesher) -> tuple[np.ndarray, np.ndarray]:
    """The Mesher's per-slot area bounds and attributes, which the kernel
    reads and writes in place: no rows when the run has none (16 bytes a
    triangle saved).  Kernels index them by any slot of the mesh, so they
    must be exactly as long as the mesh's slot arrays; ``Mesher.grow``
    keeps them so."""
    slots = ms.m.stamp.shape[0]
    tables = []
    for table in (ms.region_area, ms.region_attr):
        if table is None:
            table = np.zeros(0)
        elif table.shape[0] != slots:  # an invariant: better an error than a write past the end
            raise RuntimeError(f"internal error: a per-triangle table has {table.shape[0]} rows for {slots} slots")
        tables.append(table)
    return tables[0], tables[1]


def grow_refiner(ms: Mesher, r: rf.Refiner) -> rf.Refiner:
    """After the kernel's NEED_ROOM: grow (doubling) whatever it ran out of,
    and only that, in the mesh and in ``r``; returns the grown refiner."""
    need = max(64, int(r.ipar[rf.I_NEED]))
    r.ipar[rf.I_NEED] = 0
    _hand_back(ms, r)  # so that ms.grow widens the tables the kernel filled
    ms.grow(vertices=16, triangles=need, records=16)
    slots = ms.m.stamp.shape[0]
    nvcap = ms.m.xy.shape[0]
    grown = {}
    heap = r.hkey.shape[0]
    if heap < rf.queue_used(r) + need:  # stale and served entries first
        rf.heap_compact(r, ms.m)
    if heap < rf.queue_used(r) + need or heap < slots + 16:
        heap = max(2 * heap, slots + 16)
        grown |= {k: _widen(getattr(r, k), heap, 0) for k in ("hkey", "hseq", "htri", "hstamp")}
    enc = r.enc.shape[0]
    if enc < int(r.ipar[rf.I_ELIVE]) + need:  # a pool: slots keep their places
        grown["enc"] = _widen(r.enc, 2 * enc + need, 0)
    trace = r.trace
    if trace.shape[0] and r.ipar[rf.I_NTRACE] + 64 > trace.shape[0]:
        grown["trace"] = _widen(trace, 2 * trace.shape[0], 0)
    per_vertex = {"vtype": 0, "vslot": -1}
    grown |= {k: _widen(getattr(r, k), nvcap, fill) for k, fill in per_vertex.items() if getattr(r, k).shape[0] < nvcap}
    grown["area"], grown["attr"] = _region_tables(ms)
    # Cavity scratch holds nothing between steps (a NEED_ROOM step changed
    # nothing and starts again), and ``seen`` is all zero then: fresh zeros,
    # which the OS maps lazily, instead of copies that touch every page.
    for k in ("cav", "fan", "seen", "bnd", "bval", "carry"):
        a = getattr(r, k)
        if a.shape[0] < slots:
            grown[k] = np.zeros((slots,) + a.shape[1:], dtype=a.dtype)
    return r._replace(**grown)


def _hand_back(ms: Mesher, r: rf.Refiner) -> None:
    """Give the Mesher the refiner's current per-slot tables (the same
    arrays unless a growth replaced one)."""
    if ms.region_area is not None:
        ms.region_area = r.area
    if ms.region_attr is not None:
        ms.region_attr = r.attr


def run(
    ms: Mesher,
    o: Options,
    *,
    strategy: str = "triangle",
    steiner: str = "offcenter",
    trace: bool = False,
    triunsuitable: Callable | None = None,
) -> np.ndarray | None:
    """Refine ``ms`` in place under ``o``; returns the trace rows if asked.

    With ``o.u`` and a Python ``triunsuitable``, the kernel refines until
    nothing is bad, then the callable judges every triangle made since, the
    unsuitable ones are queued and the kernel goes on, until a round finds
    none: the hot loop never calls Python."""
    if steiner not in STEINER:
        raise ValueError(f"steiner must be one of {', '.join(STEINER)}, not {steiner!r}")
    if o.S == 0:
        return np.zeros(0, dtype=TRACE_DTYPE) if trace else None
    user = triunsuitable if o.u else None
    _presize(ms, o)
    r = new_refiner(ms, o, strategy, steiner, trace, user is not None)  # every vertex so far: V_INPUT (0)
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
    rotate_corners(ms.m, 2)
    cdt.build_vertex_edges(ms.m, ms.vtri)
    rf.tally_encroached(r, ms.m, ms.segs)
    r = finish(ms, r, user)
    rotate_corners(ms.m, 1)
    cdt.build_vertex_edges(ms.m, ms.vtri)
    return _trace_table(r.trace[: int(r.ipar[rf.I_NTRACE])]) if trace else None


# Measured: q20-q34 meshes under a fixed area bound A come out at 1.2-1.6 triangles per A
# of domain (the unit square pq30a1e-6: 1,584,789), so room for 1.7 per A is rarely grown.
TRIANGLES_PER_AREA_BOUND = 1.7
PRESIZE_LIMIT = 1 << 26  # triangles: beyond this, grow on demand


def _presize(ms: Mesher, o: Options) -> None:
    """Under a fixed area bound the mesh size is predictable: make room for
    it at once rather than doubling (and copying) a dozen times."""
    if not o.max_area > 0:
        return
    from .check import mesh_area  # only here: the command's start-up does not need the checker

    m = ms.m
    n = int(m.size[S_NSLOT])
    c = m.corner[: 3 * n].reshape(-1, 3)
    area = mesh_area({"vertices": m.xy, "triangles": c[(m.stamp[:n] > 0) & (c.min(axis=1) >= 0)]})  # no ghosts
    want = min(TRIANGLES_PER_AREA_BOUND * area / o.max_area, PRESIZE_LIMIT)
    if want > 2 * n:  # vertices: about half the triangles, and the free vertices Chew's rule deletes
        ms.grow(vertices=int(0.7 * want), triangles=int(want))


def _judge(m, user: Callable, judged: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Ask ``user(org, dest, apex, area)`` about every live triangle it has
    not seen; returns the updated stamps and the unsuitable slots."""
    n = int(m.size[S_NSLOT])
    stamp = m.stamp[:n]
    if judged.shape[0] < n:
        judged = _widen(judged, n, 0)
    fresh = np.flatnonzero((stamp > 0) & (stamp != judged[:n]))
    judged[fresh] = stamp[fresh]
    xy = m.xy
    bad = []
    for t in fresh:
        # Triangle asks about the handle it tests: org, dest, apex are corners
        # 1, 2, 0 of a slot (see run: handle 3 t)
        o, d, a = (xy[m.corner[3 * t + k]] for k in (1, 2, 0))
        area = 0.5 * ((d[0] - o[0]) * (a[1] - o[1]) - (d[1] - o[1]) * (a[0] - o[0]))
        if user(o.copy(), d.copy(), a.copy(), area):
            bad.append(t)
    return judged, np.asarray(bad, dtype=np.int64)


def finish(ms: Mesher, r: rf.Refiner, user: Callable | None = None) -> rf.Refiner:
    """Run the refinement kernel to the end: grow its arrays when it asks,
    let Python in when it pauses (Ctrl-C), consult ``user`` when it is done,
    and turn a precision failure into Triangle's error.  Leaves the
    per-triangle results on ``ms``; returns the final refiner."""
    judged = np.zeros(0, dtype=ms.m.stamp.dtype)  # the stamp each slot had when the callable judged it
    while True:
        status = rf.refine(r, ms.m, ms.segs, ms.vmark, ms.parent, ms.vtri, ms.work, ms.state)
        if status == rf.DONE and user is not None and r.ipar[rf.I_BUDGET] != 0:
            judged, bad = _judge(ms.m, user, judged)
            while r.hkey.shape[0] < rf.queue_used(r) + bad.shape[0] + 16:
                r = grow_refiner(ms, r)
            rf.queue_triangles(r, ms.m, ms.work, bad, ms.state)
            if bad.shape[0]:
                continue
        if status == rf.DONE:
            break
        if status == rf.PAUSE:  # back in Python now and then, so Ctrl-C works
            continue
        if status == rf.PRECISION:
            a, b = int(r.ipar[rf.I_ERRV]), int(r.ipar[rf.I_ERRW])
            xy = ms.m.xy
            raise PrecisionError(
                f"Ran out of precision at ({xy[a, 0]:.12g}, {xy[a, 1]:.12g}).\n"
                f"I attempted to split a segment to a smaller size than\n"
                f"  can be accommodated by the finite precision of\n"
                f"  floating point arithmetic.\n"
                f"  (segment ({xy[a, 0]:.12g}, {xy[a, 1]:.12g}) to ({xy[b, 0]:.12g}, {xy[b, 1]:.12g}))"
            )
        r = grow_refiner(ms, r)
    _hand_back(ms, r)
    ms.dead = np.flatnonzero(r.vtype[: ms.n_vertices] == rf.V_DEAD)
    return r


TRACE_DTYPE = np.dtype(
    [("kind", "U12"), ("created", "i8"), ("deleted", "i8"), ("walk_steps", "i8"), ("queue_length", "i8")]
)


def _trace_table(rows: np.ndarray) -> np.ndarray:
    """One record per insertion attempt: kind (segment, circumcenter,
    offcenter, rejected, deleted), triangles created and deleted, walk steps,
    bad triangles queued afterwards."""
    out = np.zeros(rows.shape[0], dtype=TRACE_DTYPE)
    out["kind"] = np.array(_TRACE_KINDS)[rows[:, 0]] if rows.shape[0] else []
    for i, name in enumerate(TRACE_DTYPE.names[1:], start=1):
        out[name] = rows[:, i]
    return out

