"""Ruppert's Delaunay refinement with Triangle's rules (kernels).

The loop (Triangle's ``enforcequality``): split every encroached subsegment;
queue every bad triangle; then repeatedly take the next bad triangle (the
strategy's priority decides which), compute its off-center or circumcenter
and insert it, unless the point lies across a subsegment or inside a
subsegment's diametral lens (circle with -D), in which case the subsegment is
queued and split instead.

Insertion is Bowyer-Watson in the constrained triangulation: the cavity is
every triangle reachable from the point's triangle without crossing a
subsegment whose circumcircle strictly contains the point.  Its incircle
tests are exactly the ones Lawson's flips would make, so the counts compare
with Triangle's, and an encroaching point is rejected before the mesh is
touched (Triangle inserts it and undoes the flips).  ``triangles_created``
of an insertion is the new vertex's degree, the paper's measure.

All state lives in arrays (see ``Refiner``), so the kernel can stop when an
array is full and resume after the driver grows it.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .cdt import R_NREC, _edge, _org_edge, _remember, edge_around, new_record, set_parent
from .insert import flip
from .counters import (
    C_CIRCUMCENTER,
    C_CREATED,
    C_DELETED,
    C_DELETED_VERTEX,
    C_DUPLICATE,
    C_INCIRCLE,
    C_QUEUE_POP,
    C_REJECTED,
    C_SEGMENT_SPLIT,
    C_STALE_POP,
    C_STEINER,
    C_UNDONE,
    C_WALK,
)
from .jit import kernel, kernel_inline
from .locate import (
    LOC_BLOCKED,
    LOC_INSIDE,
    LOC_ON_EDGE,
    LOC_ON_VERTEX,
    LOC_FAILED,
    line_walk,
    next_random,
    precise_walk,
)
from .mesh import (
    NO_EDGE,
    NO_SEG,
    S_NLIVE,
    S_NSLOT,
    S_NVERT,
    bond,
    kill_triangle,
    lnext,
    lprev,
    new_triangle,
    spare_triangles,
)
from .predicates import incircle, orient2d
from .strategies import ADVERSARY, RANDOM, TRIANGLE, priority

# vertex types
V_INPUT = 0
V_SEGMENT = 1
V_FREE = 2
V_DEAD = 3  # a deleted free vertex (dropped from the output)

# kernel status
DONE = 0
NEED_ROOM = 1
PRECISION = 2
PAUSE = 3  # a slice of work is done: the driver may check for Ctrl-C and call again

PAUSE_EVERY = 1 << 14  # bad triangles taken per slice

# trace kinds
T_SEGMENT, T_CIRCUMCENTER, T_OFFCENTER, T_REJECTED, T_DELETED = range(5)

# ipar slots
I_STRATEGY = 0
I_D = 1  # diametral circles
I_Y = 2  # 1: no splits of boundary subsegments, 2: of any
I_FIXAREA = 3
I_VARAREA = 4
I_BUDGET = 5  # Steiner points left, -1 = unlimited
I_OFFCENTER = 6
I_ANGLE = 7  # the angle test is on
I_HSIZE = 8  # heap entries
I_SEQ = 9  # heap insertions so far
I_ECURSOR = 10  # encroached pool: the slot the current pass is at
I_EFRESH = 11  # encroached pool: slots ever used
I_NTRACE = 12
I_PHASE = 13  # 0 split initial encroachments, 1 tally triangles, 2 main loop
I_ERRV = 14  # precision error: the subsegment's end vertices
I_ERRW = 15
I_CURRENT = 16  # triangle being split, kept across a NEED_ROOM (-1 none)
I_CURSTAMP = 17  # and its stamp when it was queued
I_USER = 18  # the -u size test: 0 off, 1 Triangle's built-in one (a Python one runs between calls)
I_ELIVE = 19  # encroached pool: live records
I_EFREE = 20  # encroached pool: last freed slot, -1 none (freed slots chain through column 1)
I_SLICE = 21  # bad triangles taken since the last PAUSE
I_NEED = 22  # with NEED_ROOM: the triangles (and queue entries) one step needs
I_HLIMIT = 23  # compact the heap when it grows past this (twice its size after the last compaction)
I_EBUSY = 24  # split_encroached is under way (resume at I_ECURSOR); else it starts a pass at slot 0
I_BTOP = 25  # bucket queue (strategy triangle): the highest non-empty bucket, -1 none
I_BLOG = 26  # bucket queue: entries in its log (live, served and stale)
I_NPAR = 27

NBUCKETS = 4096

P_GOODANGLE = 0  # cos^2 of the minimum angle
P_LENS = 1  # (2 cos^2 - 1)^2: the lens test
P_OFFCONSTANT = 2
P_MAXAREA = 3
P_CURKEY = 4  # key of the entry being split
P_NPAR = 5


class Refiner(NamedTuple):
    """Refinement state beside the mesh."""

    ipar: np.ndarray  # (I_NPAR,) int64
    par: np.ndarray  # (P_NPAR,) float64
    vtype: np.ndarray  # (V,) int8 V_*
    area: np.ndarray  # (T,) float64 area bound per triangle slot, <= 0 none (no rows: no bounds)
    attr: np.ndarray  # (T,) float64 regional attribute per triangle slot (no rows: no attributes)
    hkey: np.ndarray  # (H,) queued bad triangles: key,
    hseq: np.ndarray  # insertion number (ties: earlier first; the bucket queue: next entry),
    htri: np.ndarray  # triangle slot,
    hstamp: np.ndarray  # and its stamp when queued
    bucket: np.ndarray  # (2, NBUCKETS) int64 the bucket queue's first and last entries, -1 empty
    enc: np.ndarray  # (E, 4) int64 pool of encroached subsegments: ends (-1: free slot), edge, its triangle's stamp
    cav: np.ndarray  # (T,) int64 scratch: cavity triangles
    fan: np.ndarray  # (T,) int64 scratch: the triangles an insertion made
    seen: np.ndarray  # (T,) int8 scratch: 1 in the cavity, 2 tested outside
    bnd: np.ndarray  # (T, 5) int64 scratch: cavity boundary edge (twin, org, dest, record, edge)
    bval: np.ndarray  # (T, 2) float64 scratch: area bound and attribute it passes on
    carry: np.ndarray  # (T,) float64 scratch: the area bound each cavity triangle passes on (see _cavity)
    vslot: np.ndarray  # (V,) int64 scratch: new triangle starting at a vertex, -1
    trace: np.ndarray  # (N, 5) int64 rows: kind, created, deleted, walk steps, queue length (N = 0: off)


# ------------------------------------------------------------------ queues
#
# The bad triangles wait in a binary heap ordered by (key, insertion number),
# except under strategy "triangle", whose keys are Triangle's 4096 bucket
# numbers: there, as in Triangle, a FIFO list per bucket queues and serves in
# constant time.  Both orders are the same; the buckets are just faster.
#
# The bucket lists live in an append-only log (entries linked through
# ``hseq``; -1 ends a list, POPPED marks an entry served): a push writes the
# next entry in order, so the writes stream through memory, and a
# compaction is one sweep in log order, which within a bucket is FIFO order.
# (A free list of served entries made every push a cache miss.)

POPPED = -2


@kernel_inline
def _bucketed(r):
    return r.ipar[I_STRATEGY] == TRIANGLE


@kernel_inline
def queue_used(r):
    """Queue entries in use: the heap's size, or the bucket log's length
    (served and stale entries included, until a compaction)."""
    return r.ipar[I_BLOG] if _bucketed(r) else r.ipar[I_HSIZE]


@kernel
def queue_clear(r):
    """Empty the queue."""
    r.ipar[I_HSIZE] = 0
    r.ipar[I_BTOP] = -1
    r.ipar[I_BLOG] = 0
    r.bucket[:, :] = -1


@kernel
def _heap_less(r, i, j):
    if r.hkey[i] != r.hkey[j]:
        return r.hkey[i] < r.hkey[j]
    return r.hseq[i] < r.hseq[j]


@kernel
def _heap_swap(r, i, j):
    r.hkey[i], r.hkey[j] = r.hkey[j], r.hkey[i]
    r.hseq[i], r.hseq[j] = r.hseq[j], r.hseq[i]
    r.htri[i], r.htri[j] = r.htri[j], r.htri[i]
    r.hstamp[i], r.hstamp[j] = r.hstamp[j], r.hstamp[i]


@kernel_inline
def _bucket_append(r, i):
    """Link entry ``i`` at the tail of its bucket (key = -bucket)."""
    b = int(-r.hkey[i])
    r.hseq[i] = -1
    tail = r.bucket[1, b]
    if tail >= 0:
        r.hseq[tail] = i
    else:
        r.bucket[0, b] = i
    r.bucket[1, b] = i
    if b > r.ipar[I_BTOP]:
        r.ipar[I_BTOP] = b


@kernel_inline
def heap_push(r, key, t, stamp):
    """Queue triangle ``t`` (the caller made sure there is room)."""
    if _bucketed(r):
        i = r.ipar[I_BLOG]
        r.ipar[I_BLOG] = i + 1
        r.ipar[I_HSIZE] += 1
        r.ipar[I_SEQ] += 1
        r.hkey[i] = key
        r.htri[i] = t
        r.hstamp[i] = stamp
        _bucket_append(r, i)
        return
    i = r.ipar[I_HSIZE]
    r.ipar[I_HSIZE] = i + 1
    r.hkey[i] = key
    r.hseq[i] = r.ipar[I_SEQ]
    r.ipar[I_SEQ] += 1
    r.htri[i] = t
    r.hstamp[i] = stamp
    while i > 0:
        up = (i - 1) // 2
        if not _heap_less(r, i, up):
            break
        _heap_swap(r, i, up)
        i = up


@kernel
def _sift_down(r, i, n):
    while True:
        c = 2 * i + 1
        if c >= n:
            break
        if c + 1 < n and _heap_less(r, c + 1, c):
            c += 1
        if not _heap_less(r, c, i):
            break
        _heap_swap(r, i, c)
        i = c


@kernel
def heap_pop(r):
    """Take the first entry off the queue and return its slot, whose fields
    stay readable until the next push (the next compaction for buckets)."""
    n = r.ipar[I_HSIZE] - 1
    r.ipar[I_HSIZE] = n
    if _bucketed(r):
        b = r.ipar[I_BTOP]
        i = r.bucket[0, b]
        nxt = r.hseq[i]
        r.bucket[0, b] = nxt
        if nxt < 0:
            r.bucket[1, b] = -1
            while b >= 0 and r.bucket[0, b] < 0:
                b -= 1
            r.ipar[I_BTOP] = b
        r.hseq[i] = POPPED
        return i
    _heap_swap(r, 0, n)
    _sift_down(r, 0, n)
    return n


@kernel
def heap_compact(r, m):
    """Drop the stale entries (triangles split or gone since they were
    queued; in the bucket log also the served ones), keeping the order of
    the rest; without this, an order that
    re-queues the same region (``smallest`` on I(n)) keeps quadratically
    many dead entries."""
    if _bucketed(r):
        r.bucket[:, :] = -1
        r.ipar[I_BTOP] = -1
        n = 0
        for i in range(r.ipar[I_BLOG]):
            if r.hseq[i] != POPPED and m.stamp[r.htri[i]] == r.hstamp[i]:
                r.hkey[n] = r.hkey[i]
                r.htri[n] = r.htri[i]
                r.hstamp[n] = r.hstamp[i]
                _bucket_append(r, n)
                n += 1
        r.ipar[I_BLOG] = n
        r.ipar[I_HSIZE] = n
        return
    # (key, insertion number) orders entries totally: rebuilding the heap
    # leaves the pop order of the rest unchanged
    n = 0
    for i in range(r.ipar[I_HSIZE]):
        if m.stamp[r.htri[i]] == r.hstamp[i]:
            r.hkey[n] = r.hkey[i]
            r.hseq[n] = r.hseq[i]
            r.htri[n] = r.htri[i]
            r.hstamp[n] = r.hstamp[i]
            n += 1
    r.ipar[I_HSIZE] = n
    for i in range(n // 2 - 1, -1, -1):
        _sift_down(r, i, n)


@kernel_inline
def _enc_len(r):
    return r.ipar[I_ELIVE]


@kernel_inline
def _enc_push(r, m, e):
    """Queue subsegment edge ``e``, by its ends and by its id: the id finds it
    even at a vertex where two parts of the domain touch (rotating about
    such a vertex does not reach every edge).

    The queue is a pool, as Triangle's: a record takes the slot freed last
    (or a fresh one), and passes visit the slots in order, so a record in a
    reused slot behind the pass waits for the next pass."""
    i = r.ipar[I_EFREE]
    if i >= 0:
        r.ipar[I_EFREE] = r.enc[i, 1]
    else:
        i = r.ipar[I_EFRESH]
        r.ipar[I_EFRESH] += 1
    r.enc[i, 0] = m.corner[lnext(e)]
    r.enc[i, 1] = m.corner[lprev(e)]
    r.enc[i, 2] = e
    r.enc[i, 3] = m.stamp[e // 3]
    r.ipar[I_ELIVE] += 1


@kernel
def _enc_free(r, i):
    r.enc[i, 0] = -1
    r.enc[i, 1] = r.ipar[I_EFREE]
    r.ipar[I_EFREE] = i
    r.ipar[I_ELIVE] -= 1


@kernel
def _enc_edge(r, m, work, vtri, i, state):
    """The subsegment edge of queue entry ``i``, or -1 if it is gone."""
    u = r.enc[i, 0]
    v = r.enc[i, 1]
    e = r.enc[i, 2]
    if not (m.stamp[e // 3] == r.enc[i, 3] and m.corner[lnext(e)] == u and m.corner[lprev(e)] == v):
        e = _edge(m, work, vtri, u, v, state)
    if e < 0 or m.seg[e] == NO_SEG:
        return -1
    return e


# ------------------------------------------------------------- encroachment


@kernel_inline
def _in_lens(r, xy, e0, e1, ax, ay):
    """Does the point (ax, ay) lie in the diametral lens (or circle with -D)
    of ``e0 e1``?"""
    ux, uy = xy[e0, 0] - ax, xy[e0, 1] - ay
    vx, vy = xy[e1, 0] - ax, xy[e1, 1] - ay
    dot = ux * vx + uy * vy
    if dot >= 0.0:
        return False
    if r.ipar[I_D]:
        return True
    return dot * dot >= r.par[P_LENS] * (ux * ux + uy * uy) * (vx * vx + vy * vy)


@kernel_inline
def _may_split(r, m, e):
    """-Y keeps boundary subsegments whole, -YY every subsegment."""
    y = r.ipar[I_Y]
    return y == 0 or (y == 1 and m.twin[e] != NO_EDGE)


@kernel_inline
def _queue_side(r, m, e, hit):
    """Queue subsegment edge ``e`` (whose own apex encroaches if ``hit``) on
    an encroaching side: the other side if its apex encroaches, as Triangle
    orients its records, since the side decides where shells are measured
    from.  Returns whether it is encroached."""
    tw = m.twin[e]
    if tw != NO_EDGE:
        b = m.corner[tw]
        if _in_lens(r, m.xy, m.corner[lnext(e)], m.corner[lprev(e)], m.xy[b, 0], m.xy[b, 1]):
            e = tw
            hit = True
    if hit and _may_split(r, m, e):
        _enc_push(r, m, e)
    return hit


@kernel_inline
def check_subsegment(r, m, e):
    """Queue subsegment edge ``e`` if an apex on either side encroaches it."""
    a = m.corner[e]
    return _queue_side(r, m, e, _in_lens(r, m.xy, m.corner[lnext(e)], m.corner[lprev(e)], m.xy[a, 0], m.xy[a, 1]))


# ------------------------------------------------------------- bad triangles


@kernel
def _shape(xy, a, b, c):
    """Squared shortest edge, cos^2 of the smallest angle, twice the area,
    squared circumradius, and the shortest edge's end vertices."""
    la = (xy[b, 0] - xy[c, 0]) ** 2 + (xy[b, 1] - xy[c, 1]) ** 2  # opposite a
    lb = (xy[c, 0] - xy[a, 0]) ** 2 + (xy[c, 1] - xy[a, 1]) ** 2
    lc = (xy[a, 0] - xy[b, 0]) ** 2 + (xy[a, 1] - xy[b, 1]) ** 2
    if lc < la and lc < lb:  # shortest a-b, smallest angle at c
        q, u, v, mn, l1, l2 = c, a, b, lc, la, lb
    elif la < lb:
        q, u, v, mn, l1, l2 = a, b, c, la, lb, lc
    else:
        q, u, v, mn, l1, l2 = b, c, a, lb, lc, la
    dot = (xy[u, 0] - xy[q, 0]) * (xy[v, 0] - xy[q, 0]) + (xy[u, 1] - xy[q, 1]) * (xy[v, 1] - xy[q, 1])
    cos2 = dot * dot / (l1 * l2)
    if dot < 0.0:  # an obtuse smallest angle cannot happen; keep the sign meaningful
        cos2 = -cos2
    area2 = (xy[b, 0] - xy[a, 0]) * (xy[c, 1] - xy[a, 1]) - (xy[b, 1] - xy[a, 1]) * (xy[c, 0] - xy[a, 0])
    circ2 = la * lb * lc / (area2 * area2) / 4.0 if area2 != 0.0 else np.inf
    return mn, cos2, area2, circ2, u, v


@kernel
def _segment_of(m, vtri, v):
    """The record of some subsegment at vertex ``v`` (-1 if none)."""
    e0 = _org_edge(m, vtri, v)
    e = edge_around(m, e0, -1) if e0 >= 0 else -1
    return m.seg[e] if e >= 0 else -1


@kernel
def _same(xy, u, v):
    return xy[u, 0] == xy[v, 0] and xy[u, 1] == xy[v, 1]


@kernel
def _small_input_angle(m, segs, r, vtri, u, v, state, work):
    """Miller, Pav and Walkington's exemption: the shortest edge ``u v`` joins
    two segment vertices on segments that meet at a vertex J, at nearly the
    same distance from J (the same concentric shell)."""
    if r.vtype[u] != V_SEGMENT or r.vtype[v] != V_SEGMENT:
        return False
    s1 = _segment_of(m, vtri, u)
    s2 = _segment_of(m, vtri, v)
    if s1 < 0 or s2 < 0:
        return False
    xy = m.xy
    a1, b1 = segs.ends[s1, 0], segs.ends[s1, 1]
    a2, b2 = segs.ends[s2, 0], segs.ends[s2, 1]
    # a shared end, compared by coordinates (in either direction: Triangle
    # relies on its subsegments' orientation, our records keep the input's)
    j = -1
    if _same(xy, b1, a2) or _same(xy, b1, b2):
        j = b1
    elif _same(xy, a1, b2) or _same(xy, a1, a2):
        j = a1
    if j < 0:
        return False
    d1 = (xy[u, 0] - xy[j, 0]) ** 2 + (xy[u, 1] - xy[j, 1]) ** 2
    d2 = (xy[v, 0] - xy[j, 0]) ** 2 + (xy[v, 1] - xy[j, 1]) ** 2
    return 0.999 * d2 < d1 < 1.001 * d2


@kernel
def builtin_unsuitable(xy, o, d, a):
    """Triangle's sample ``triunsuitable``: the longest edge squared exceeds
    0.05 (x^2 + y^2) + 0.02 at the origin vertex ``o``."""
    od = (xy[o, 0] - xy[d, 0]) ** 2 + (xy[o, 1] - xy[d, 1]) ** 2
    da = (xy[d, 0] - xy[a, 0]) ** 2 + (xy[d, 1] - xy[a, 1]) ** 2
    ao = (xy[a, 0] - xy[o, 0]) ** 2 + (xy[a, 1] - xy[o, 1]) ** 2
    return max(od, da, ao) > 0.05 * (xy[o, 0] ** 2 + xy[o, 1] ** 2) + 0.02


@kernel_inline
def _bounds(r, t):
    """Triangle slot ``t``'s area bound and regional attribute, which a new
    triangle inherits: (-1, 0) when the run has none (the arrays have no rows)."""
    area = r.area[t] if r.area.shape[0] else -1.0
    attr = r.attr[t] if r.attr.shape[0] else 0.0
    return area, attr


@kernel_inline
def _flip_bound(a, b):
    """The area bound both triangles of one of Triangle's insertion flips
    get from bounds ``a`` and ``b``: their mean, or none (-1) if either has
    none (found by experiment: see reconstruct.py)."""
    return 0.5 * (a + b) if a > 0.0 and b > 0.0 else -1.0


@kernel_inline
def _set_bounds(r, t, area, attr):
    if r.area.shape[0]:
        r.area[t] = area
    if r.attr.shape[0]:
        r.attr[t] = attr


@kernel_inline
def _queue(r, m, work, t, mn, cos2, circ2, state):
    """Put bad triangle ``t`` on the heap under the strategy's priority."""
    strategy = r.ipar[I_STRATEGY]
    created = _would_create(r, m, work, t) if strategy == ADVERSARY else 0
    rnd = 0.0
    if strategy == RANDOM:  # only then: the walks share this generator
        next_random(state)
        rnd = float(state[0])
    key = priority(strategy, mn, cos2, circ2, created, r.ipar[I_SEQ], rnd)
    heap_push(r, key, t, m.stamp[t])


@kernel_inline
def test_triangle(r, m, segs, vtri, work, t, state):
    """Queue triangle ``t`` if it is too big or too skinny (Triangle's
    ``testtriangle``); the caller made sure the heap has room."""
    xy = m.xy
    a, b, c = m.corner[3 * t], m.corner[3 * t + 1], m.corner[3 * t + 2]
    mn, cos2, area2, circ2, u, v = _shape(xy, a, b, c)
    bad = False
    if r.ipar[I_FIXAREA] and 0.5 * area2 > r.par[P_MAXAREA]:
        bad = True
    bound = _bounds(r, t)[0]
    if not bad and r.ipar[I_VARAREA] and bound > 0.0 and 0.5 * area2 > bound:
        bad = True
    if not bad and r.ipar[I_USER] == 1 and builtin_unsuitable(xy, b, c, a):  # handle 3 t: org, dest, apex
        bad = True
    if not bad and r.ipar[I_ANGLE] and cos2 > r.par[P_GOODANGLE]:
        # the shortest edge is not a subsegment and its ends lie on segments
        # meeting at a small angle: leave it alone
        k = 0
        for kk in range(3):
            if m.corner[3 * t + kk] != u and m.corner[3 * t + kk] != v:
                k = kk
        exempt = m.seg[3 * t + k] == NO_SEG and _small_input_angle(m, segs, r, vtri, u, v, state, work)
        bad = not exempt
    if bad:
        _queue(r, m, work, t, mn, cos2, circ2, state)


@kernel
def queue_triangles(r, m, work, ts, state):
    """Queue the live triangles ``ts`` (a user's size test found them
    unsuitable); the caller made sure the heap has room."""
    xy = m.xy
    for i in range(ts.shape[0]):
        t = ts[i]
        if m.stamp[t] > 0:
            mn, cos2, _, circ2, _, _ = _shape(xy, m.corner[3 * t], m.corner[3 * t + 1], m.corner[3 * t + 2])
            _queue(r, m, work, t, mn, cos2, circ2, state)


# ---------------------------------------------------------- new vertices


@kernel
def steiner_point(r, m, h):
    """The off-center (when closer) or circumcenter of the triangle of
    handle ``h`` (an edge: org, dest, apex as ``mesh`` defines them), and
    its barycentric parameters (xi, eta) relative to (org, dest, apex).

    Computed from the handle's corners in Triangle's order: a bad triangle
    is split from handle ``3 t`` (apex at corner 0, where an insertion puts
    the new vertex, as in the handle Triangle queues), which gives Triangle's
    rounding, so the same Steiner points."""
    xy = m.xy
    o, d, a = m.corner[lnext(h)], m.corner[lprev(h)], m.corner[h]
    ox, oy = xy[o, 0], xy[o, 1]
    xdo, ydo = xy[d, 0] - ox, xy[d, 1] - oy
    xao, yao = xy[a, 0] - ox, xy[a, 1] - oy
    dodist = xdo * xdo + ydo * ydo
    aodist = xao * xao + yao * yao
    dadist = (xy[d, 0] - xy[a, 0]) ** 2 + (xy[d, 1] - xy[a, 1]) ** 2
    denom = 0.5 / orient2d(xy[d, 0], xy[d, 1], xy[a, 0], xy[a, 1], ox, oy)
    dx = (yao * dodist - ydo * aodist) * denom
    dy = (xdo * aodist - xao * dodist) * denom
    off = False
    c = r.par[P_OFFCONSTANT]
    if r.ipar[I_OFFCENTER] and c > 0.0:
        if dodist < aodist and dodist < dadist:
            fx, fy = 0.5 * xdo - c * ydo, 0.5 * ydo + c * xdo
            if fx * fx + fy * fy < dx * dx + dy * dy:
                dx, dy, off = fx, fy, True
        elif aodist < dadist:
            fx, fy = 0.5 * xao + c * yao, 0.5 * yao - c * xao
            if fx * fx + fy * fy < dx * dx + dy * dy:
                dx, dy, off = fx, fy, True
        else:
            ex, ey = xy[a, 0] - xy[d, 0], xy[a, 1] - xy[d, 1]
            fx, fy = 0.5 * ex - c * ey, 0.5 * ey + c * ex
            if fx * fx + fy * fy < (dx - xdo) ** 2 + (dy - ydo) ** 2:
                dx, dy, off = xdo + fx, ydo + fy, True
    xi = (yao * dx - xao * dy) * (2.0 * denom)
    eta = (xdo * dy - ydo * dx) * (2.0 * denom)
    return ox + dx, oy + dy, xi, eta, off


# ---------------------------------------------------------------- cavities


@kernel
def _cavity(r, m, work, px, py, t0, t1, skip):
    """Collect the cavity of point (px, py) from triangles ``t0`` (and ``t1``
    if >= 0), not crossing subsegments or edge ``skip`` (and its twin).

    Returns ``(ntri, nbnd)``: ``r.cav[:ntri]`` the triangles, ``r.bnd[:nbnd]``
    the boundary edges as (outer twin, org, dest, record), each with the
    area bound and attribute its new triangle takes in ``r.bval``.  Leaves
    ``r.seen`` set on the triangles in ``r.cav[:ntest]``; call ``_unsee``.

    The attribute is the inner triangle's.  The area bound is the one
    Triangle's insertion (a 1-3 or 2-4 split, then Lawson flips) leaves on
    that edge's new triangle: the split copies the bound of ``t0`` (or
    ``t1``), each flip gives both of its triangles ``_flip_bound`` of the
    two.  The cavity's triangles form a tree rooted at ``t0`` (and ``t1``)
    and each flip crosses one tree edge, so the bound is that fold along
    the path from the root, whatever the order of the flips:
    ``r.carry[i]`` holds it for ``cav[i]``.
    """
    xy = m.xy
    cav = r.cav
    carry = r.carry
    n = 1
    cav[0] = t0
    carry[0] = _bounds(r, t0)[0]
    r.seen[t0] = 1
    if t1 >= 0:
        cav[1] = t1
        carry[1] = _bounds(r, t1)[0]
        r.seen[t1] = 1
        n = 2
    tested = cav.shape[0]  # triangles tested outside go at the end of cav
    nb = 0
    i = 0
    skip_twin = m.twin[skip] if skip >= 0 else -2
    while i < n:
        t = cav[i]
        passed = carry[i]
        i += 1
        for k in range(3):
            e = 3 * t + k
            if e == skip or e == skip_twin:
                continue
            tw = m.twin[e]
            outside = tw == NO_EDGE or m.seg[e] != NO_SEG
            if not outside:
                u = tw // 3
                if r.seen[u] == 1:
                    continue
                if r.seen[u] == 0:
                    a, b, c = m.corner[3 * u], m.corner[3 * u + 1], m.corner[3 * u + 2]
                    work[C_INCIRCLE] += 1
                    if incircle(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[c, 0], xy[c, 1], px, py) > 0.0:
                        r.seen[u] = 1
                        cav[n] = u
                        carry[n] = _flip_bound(passed, _bounds(r, u)[0])  # the flip across e
                        n += 1
                        continue
                    r.seen[u] = 2
                    tested -= 1
                    cav[tested] = u
                outside = True
            r.bnd[nb, 0] = tw
            r.bnd[nb, 1] = m.corner[lnext(e)]
            r.bnd[nb, 2] = m.corner[lprev(e)]
            r.bnd[nb, 3] = m.seg[e]
            r.bnd[nb, 4] = e
            r.bval[nb, 0] = passed
            r.bval[nb, 1] = _bounds(r, t)[1]
            nb += 1
    for j in range(tested, cav.shape[0]):
        r.seen[cav[j]] = 0
    return n, nb


@kernel
def _unsee(r, n):
    for i in range(n):
        r.seen[r.cav[i]] = 0


@kernel
def _would_create(r, m, work, t):
    """Triangles a split of ``t`` would create (the adversary's greed)."""
    px, py, _, _, _ = steiner_point(r, m, 3 * t)
    if math.isnan(px) or math.isnan(py):
        return 0
    n, nb = _cavity(r, m, work, px, py, t, -1, -1)
    _unsee(r, n)
    return nb


@kernel
def _order_rim(r, nb, first):
    """Put the cavity's rim ``r.bnd[:nb]`` in counter-clockwise order from
    the edge leaving vertex ``first``: the order in which Triangle's flips
    meet the new vertex's triangles, so bad triangles and encroached
    subsegments are queued in its order."""
    bnd, bval, slot = r.bnd, r.bval, r.vslot
    for j in range(nb):
        slot[bnd[j, 1]] = j
    want = first
    for pos in range(nb):
        j = slot[want]
        if j < 0:
            break
        if j != pos:
            for c in range(bnd.shape[1]):
                bnd[j, c], bnd[pos, c] = bnd[pos, c], bnd[j, c]
            for c in range(bval.shape[1]):
                bval[j, c], bval[pos, c] = bval[pos, c], bval[j, c]
            slot[bnd[j, 1]] = j
            slot[bnd[pos, 1]] = pos
        want = bnd[pos, 2]
    for j in range(nb):
        slot[bnd[j, 1]] = -1


@kernel
def _fill_cavity(r, m, work, vtri, p, n, nb):
    """Replace the cavity by the fan of triangles from ``p`` to its boundary
    (listed in ``r.fan[:nb]``)."""
    for i in range(n):
        t = r.cav[i]
        r.seen[t] = 0
        kill_triangle(m, t)
    work[C_DELETED] += n
    for j in range(nb):
        u = r.bnd[j, 1]
        v = r.bnd[j, 2]
        t = new_triangle(m, p, u, v)
        work[C_CREATED] += 1
        bond(m, 3 * t, r.bnd[j, 0])  # (new_triangle left the other edges unlinked)
        m.seg[3 * t] = r.bnd[j, 3]
        _set_bounds(r, t, r.bval[j, 0], r.bval[j, 1])
        r.vslot[u] = t
        r.fan[j] = t
        _remember(m, vtri, t)
    for j in range(nb):  # link the fan: edge v -> p of (p, u, v) to p -> v of the next
        u = r.bnd[j, 1]
        v = r.bnd[j, 2]
        t = r.vslot[u]
        nxt = r.vslot[v]
        if nxt >= 0:
            bond(m, 3 * t + 1, 3 * nxt + 2)
    for j in range(nb):
        r.vslot[r.bnd[j, 1]] = -1


@kernel
def _room(r, m, nb):
    """Enough room to add a vertex and ``nb`` triangles and queue them?  If
    not, says how much is needed (``I_NEED``) for the driver."""
    ok = (
        m.size[S_NVERT] < m.xy.shape[0]
        and spare_triangles(m) >= nb + 2
        and queue_used(r) + nb + 2 <= r.hkey.shape[0]
        and _enc_len(r) + nb + 4 <= r.enc.shape[0]
    )
    if not ok:
        r.ipar[I_NEED] = max(r.ipar[I_NEED], nb + 4)
    return ok


@kernel
def _trace_full(r):
    """The trace (if on) lacks room for the rows one more step may write."""
    return r.trace.shape[0] > 0 and r.ipar[I_NTRACE] + 64 > r.trace.shape[0]


@kernel
def _trace(r, kind, created, deleted, steps, queue):
    i = r.ipar[I_NTRACE]
    if i < r.trace.shape[0]:
        r.trace[i, 0] = kind
        r.trace[i, 1] = created
        r.trace[i, 2] = deleted
        r.trace[i, 3] = steps
        r.trace[i, 4] = queue
        r.ipar[I_NTRACE] = i + 1


@kernel
def _new_vertex(m, r, vmark, parent, px, py, kind, marker, p0, p1, p2, s, t):
    v = m.size[S_NVERT]
    m.size[S_NVERT] = v + 1
    m.xy[v, 0] = px
    m.xy[v, 1] = py
    r.vtype[v] = kind
    vmark[v] = marker
    set_parent(parent, v, p0, p1, p2, s, t)
    return v


@kernel
def _test_fan(r, m, segs, vtri, work, nb, triflaws, state):
    """Quality-test the new triangles ``r.fan[:nb]`` (if ``triflaws``) and
    queue the encroached subsegments on the fan's rim."""
    for j in range(nb):
        t = r.fan[j]
        if triflaws:
            test_triangle(r, m, segs, vtri, work, t, state)
        if m.seg[3 * t] != NO_SEG:
            check_subsegment(r, m, 3 * t)


# ------------------------------------------------------------ splitting


@kernel
def _mark(m, e, rec):
    m.seg[e] = rec
    if m.twin[e] != NO_EDGE:
        m.seg[m.twin[e]] = rec


@kernel
def _fill_polygon(r, m, work, vtri, chain, outer, outer_seg, count, stack):
    """Triangulate the polygon ``chain[0..count-1]`` whose other vertices lie
    left of ``chain[0] -> chain[count-1]``: each base edge takes the vertex
    whose circle through it holds no other candidate (the constrained
    Delaunay choice), then both sides recurse.  ``outer[i]`` is the outside
    twin of the polygon edge ``chain[i] chain[i+1]``.  New triangles go on
    ``r.fan``; returns (base edge of the first, how many)."""
    xy = m.xy
    root = -1
    made = 0
    stack[0] = 0
    stack[1] = count - 1
    stack[2] = -1
    sp = 1
    while sp > 0:
        sp -= 1
        i = stack[3 * sp]
        j = stack[3 * sp + 1]
        pe = stack[3 * sp + 2]
        if j == i + 1:  # a polygon edge: link to the outside
            bond(m, pe, outer[i])
            m.seg[pe] = outer_seg[i]
            continue
        ci = chain[i]
        cj = chain[j]
        k = i + 1
        for q in range(i + 2, j):
            work[C_INCIRCLE] += 1
            ck = chain[k]
            cq = chain[q]
            if incircle(xy[ci, 0], xy[ci, 1], xy[cj, 0], xy[cj, 1], xy[ck, 0], xy[ck, 1], xy[cq, 0], xy[cq, 1]) > 0.0:
                k = q
        t = new_triangle(m, chain[k], ci, cj)
        work[C_CREATED] += 1
        r.fan[made] = t
        made += 1
        _remember(m, vtri, t)
        if pe < 0:
            root = 3 * t
        else:
            bond(m, 3 * t, pe)
        stack[3 * sp] = i
        stack[3 * sp + 1] = k
        stack[3 * sp + 2] = 3 * t + 2
        stack[3 * sp + 3] = k
        stack[3 * sp + 4] = j
        stack[3 * sp + 5] = 3 * t + 1
        sp += 2
    return root, made


@kernel
def delete_free_vertex(r, m, segs, vtri, work, e0, state):
    """Remove the free vertex ``v`` at the origin of edge ``e0`` (Chew's
    rule: ``v`` sits in the diametral circle of the subsegment opposite it
    in ``e0``'s triangle) and re-triangulate its star from that subsegment
    as the base, as Triangle does.  Returns False (nothing changed) if
    ``v`` is on the boundary or the scratch space is short.

    Area bounds and attributes (found by experiment, see reconstruct.py):
    Triangle's deletion flips move the triangles' values without averaging,
    so the triangle on the base keeps the value of the star triangle on the
    base, and every other new triangle, with apex ``w[k]`` over its base,
    the value of the star triangle ``(v, w[k-1], w[k])``."""
    v = m.corner[lnext(e0)]
    # the star, counter-clockwise: w[i] = dest of the i-th edge out of v
    w = r.cav  # vertices
    outer = r.bnd[:, 0]  # outside twin of w[i] -> w[i+1]
    tris = r.bnd[:, 1]
    rec = r.bnd[:, 3]  # record of w[i] -> w[i+1]
    area = r.bval[:, 0]
    attr = r.bval[:, 1]
    d = 0
    e = e0
    for _ in range(m.stamp.shape[0]):
        if d + 2 >= w.shape[0] // 4:
            return False
        t = e // 3
        w[d] = m.corner[lprev(e)]
        outer[d] = m.twin[lnext(e)]  # edge dest -> apex, opposite v
        rec[d] = m.seg[lnext(e)]
        tris[d] = t
        area[d], attr[d] = _bounds(r, t)
        d += 1
        nxt = m.twin[lprev(e)]
        if nxt == NO_EDGE:
            return False
        e = nxt
        if e == e0:
            break
    if d < 3 or spare_triangles(m) < d or queue_used(r) + d + 2 > r.hkey.shape[0]:
        return False
    # the polygon w0 .. w[d-1]; base w0 -> w1, chain w0, w[d-1], ..., w1
    half = w.shape[0] // 2
    chain = w[half:]
    ring = r.fan  # outside twins in chain order (fan is overwritten later)
    ring_seg = r.vslot  # and records (vslot is all -1 between insertions)
    chain[0] = w[0]
    for i in range(1, d):
        chain[i] = w[d - i]
    # chain edge (chain[i], chain[i+1]) is the star's edge w[d-1-i] -> w[d-i]
    for i in range(d - 1):
        ring[i] = outer[(d - 1 - i) % d]
        ring_seg[i] = rec[(d - 1 - i) % d]
    base_outer = outer[0]
    base_seg = rec[0]
    for i in range(d):
        kill_triangle(m, tris[i])
    work[C_DELETED] += d
    area0 = area[0]
    attr0 = attr[0]
    for i in range(d):  # the outside twins move to w's place: fan is the fill's output
        w[i] = ring[i] if i < d - 1 else -1
    # the fill's stack (3 per level, d levels at most) in bnd's free column
    for i in range(d - 1):  # records too: vslot must be all -1 again after
        rec[i] = ring_seg[i]
        ring_seg[i] = -1
    root, made = _fill_polygon(r, m, work, vtri, chain, w, rec, d, r.bnd[:, 2])
    bond(m, root, base_outer)
    m.seg[root] = base_seg
    # vslot is all -1 again here: map each star vertex to its place (chain[i]
    # = w[d - i]; w0 closes the polygon, as place d)
    slot = r.vslot
    slot[chain[0]] = d
    for i in range(1, d):
        slot[chain[i]] = d - i
    # the values by apex (see the docstring); fill triangles are (apex, base org, base dest)
    _set_bounds(r, r.fan[0], area0, attr0)  # the base triangle (the fill makes it first)
    for i in range(1, made):
        k = slot[m.corner[3 * r.fan[i]]]
        _set_bounds(r, r.fan[i], area[k - 1], attr[k - 1])
    # Triangle tests the new triangles as its flips make them, in post-order
    # of the polygon's split (the side from w1 first), the base triangle
    # last: sorted by the place of their last vertex (base org), then of
    # their first (base dest) downwards.  w[:made - 1] is free now.
    order = w
    for i in range(1, made):
        t = r.fan[i]
        hi = slot[m.corner[3 * t + 1]]
        lo = slot[m.corner[3 * t + 2]]
        j = i - 1
        while j > 0:
            u = order[j - 1]
            uhi = slot[m.corner[3 * u + 1]]
            if uhi < hi or (uhi == hi and slot[m.corner[3 * u + 2]] > lo):
                break
            order[j] = u
            j -= 1
        order[j] = t
    slot[chain[0]] = -1
    for i in range(1, d):
        slot[chain[i]] = -1
    # Triangle's base triangle keeps the deleted vertex's base triangle and
    # its handle: (new apex, w0, w1) as org, dest, apex, so handle 3 t
    _turn_back(m, vtri, r.fan[0])
    order[made - 1] = r.fan[0]
    for i in range(made):  # back to fan: the adversary's test overwrites cav
        r.fan[i] = order[i]
    r.vtype[v] = V_DEAD
    work[C_DELETED_VERTEX] += 1
    _trace(r, T_DELETED, made, d, 0, r.ipar[I_HSIZE])
    if r.ipar[I_Y] == 0:
        for i in range(made):
            test_triangle(r, m, segs, vtri, work, r.fan[i], state)
    return True


@kernel
def _turn_back(m, vtri, t):
    """Rotate triangle ``t``'s corners (a, b, c) to (c, a, b), with its
    edges (edge k moves with corner k) and its neighbours' links."""
    e = 3 * t
    c0, c1, c2 = m.corner[e], m.corner[e + 1], m.corner[e + 2]
    w0, w1, w2 = m.twin[e], m.twin[e + 1], m.twin[e + 2]
    s0, s1, s2 = m.seg[e], m.seg[e + 1], m.seg[e + 2]
    m.corner[e], m.corner[e + 1], m.corner[e + 2] = c2, c0, c1
    m.seg[e], m.seg[e + 1], m.seg[e + 2] = s2, s0, s1
    bond(m, e, w2)
    bond(m, e + 1, w0)
    bond(m, e + 2, w1)
    _remember(m, vtri, t)


@kernel
def _chew_delete(r, m, segs, vtri, work, e, state):
    """Before splitting subsegment ``e``: delete free vertices inside its
    diametral circle on a side where no other segment meets it.  Returns
    False if there was no room (nothing changed on that side)."""
    u = m.corner[lnext(e)]
    v = m.corner[lprev(e)]
    for side in range(2):
        if side == 0:
            f = e
        else:  # found afresh: deletions on the first side re-make e's triangle
            f = _edge(m, work, vtri, v, u, state)
        if f < 0:  # (NO_EDGE too)
            continue
        if m.seg[lnext(f)] != NO_SEG or m.seg[lprev(f)] != NO_SEG:
            continue
        for _ in range(m.stamp.shape[0]):
            o = m.corner[lnext(f)]
            d = m.corner[lprev(f)]
            a = m.corner[f]
            if r.vtype[a] != V_FREE:
                break
            xy = m.xy
            dot = (xy[o, 0] - xy[a, 0]) * (xy[d, 0] - xy[a, 0]) + (xy[o, 1] - xy[a, 1]) * (xy[d, 1] - xy[a, 1])
            if dot >= 0.0:
                break
            if queue_used(r) + 64 > r.hkey.shape[0]:
                return False
            if not delete_free_vertex(r, m, segs, vtri, work, lprev(f), state):  # the edge a -> o
                break
            f = _edge(m, work, vtri, o, d, state)  # the same side again
            if f < 0:
                return True
    return True


@kernel
def split_subsegment(r, m, segs, vmark, parent, vtri, work, e, triflaws, state):
    """Split subsegment edge ``e`` at its midpoint or on a power-of-two shell
    around an end shared with another segment.  Returns DONE, NEED_ROOM
    (nothing changed) or PRECISION."""
    xy = m.xy
    o = m.corner[lnext(e)]
    d = m.corner[lprev(e)]
    tw = m.twin[e]
    acute_org = m.seg[lprev(e)] != NO_SEG
    acute_dest = m.seg[lnext(e)] != NO_SEG
    if tw != NO_EDGE:
        acute_org = acute_org or m.seg[lnext(tw)] != NO_SEG
        acute_dest = acute_dest or m.seg[lprev(tw)] != NO_SEG
    # Triangle's record runs the other way along e, from e0 = d to e1 = o;
    # computing from its ends gives its rounding, so the same vertices
    e0, e1 = d, o
    acute0, acute1 = acute_dest, acute_org
    ex, ey = xy[e1, 0] - xy[e0, 0], xy[e1, 1] - xy[e0, 1]
    split = 0.5
    if acute0 or acute1:
        length = np.sqrt(ex * ex + ey * ey)
        p2 = 1.0
        while length > 3.0 * p2:
            p2 *= 2.0
        while length < 1.5 * p2:
            p2 *= 0.5
        # a power of two from the acute end; with both acute, from e1
        split = p2 / length
        if acute1:
            split = 1.0 - split
    px = xy[e0, 0] + split * ex
    py = xy[e0, 1] + split * ey
    # one correction toward the segment's line
    den = ex * ex + ey * ey
    mult = orient2d(xy[e0, 0], xy[e0, 1], xy[e1, 0], xy[e1, 1], px, py) / den
    if mult != 0.0 and den != 0.0 and not math.isnan(mult):
        px += mult * ey
        py += mult * -ex
    if (px == xy[o, 0] and py == xy[o, 1]) or (px == xy[d, 0] and py == xy[d, 1]):
        r.ipar[I_ERRV] = o
        r.ipar[I_ERRW] = d
        return PRECISION
    # A vertex can lie on the subsegment within rounding, not exactly (a split
    # point an earlier run wrote out, read back as an input vertex): it is
    # then the apex on its side (any other triangle there would contain it).
    # Splitting elsewhere leaves it encroaching every piece it lies on, the
    # pieces shrink towards it until a split point lands on it or next to it,
    # and the mesh gets a copy of it or slivers and runs out of precision
    # (Triangle crashes).  Split at that vertex instead.
    f = -1
    if _on_subsegment(xy, o, d, m.corner[e]):
        f = e
    elif tw != NO_EDGE and _on_subsegment(xy, o, d, m.corner[tw]):
        f = tw
    if f >= 0:
        return _split_at_apex(r, m, segs, vmark, vtri, work, e, f, triflaws, state)
    t1 = tw // 3 if tw != NO_EDGE else -1
    n, nb = _cavity(r, m, work, px, py, e // 3, t1, e)
    if not _room(r, m, nb) or segs.size[R_NREC] >= segs.marker.shape[0]:
        _unsee(r, n)
        return NEED_ROOM
    _order_rim(r, nb, d)  # Triangle circles the new vertex from e's destination
    rec = m.seg[e]
    half = new_record(segs, segs.marker[rec], segs.source[rec], segs.ends[rec, 0], segs.ends[rec, 1])
    v = _new_vertex(m, r, vmark, parent, px, py, V_SEGMENT, segs.marker[rec], e0, e1, e0, split, 0.0)
    _fill_cavity(r, m, work, vtri, v, n, nb)
    for j in range(nb):  # the halves: spokes to o and d (edge 2 of (v, o|d, x), edge 1 of (v, x, o|d))
        t = r.fan[j]
        for k in range(1, 3):
            w = m.corner[3 * t + k]
            if w == o or w == d:
                _mark(m, 3 * t + 3 - k, rec if w == o else half)
    work[C_SEGMENT_SPLIT] += 1
    work[C_STEINER] += 1
    if r.ipar[I_BUDGET] > 0:
        r.ipar[I_BUDGET] -= 1
    _test_fan(r, m, segs, vtri, work, nb, triflaws, state)
    # the halves themselves, on the side e was on
    eb = _edge(m, work, vtri, v, d, state)
    if eb >= 0:
        check_subsegment(r, m, eb)
    ea = _edge(m, work, vtri, o, v, state)
    if ea >= 0:
        check_subsegment(r, m, ea)
    _trace(r, T_SEGMENT, nb, n, 0, r.ipar[I_HSIZE])
    return DONE


# A vertex this close to a subsegment's line (relative to the largest
# coordinate of the three points) lies on it up to rounding: a few units in
# the last place, where split points that were moved onto the line once and
# printed with 17 digits land.
ON_SEGMENT = 2.0**-50


@kernel
def _on_subsegment(xy, a, b, c):
    """Does vertex ``c`` lie on the segment ``a b`` up to rounding, between its
    ends?"""
    ex, ey = xy[b, 0] - xy[a, 0], xy[b, 1] - xy[a, 1]
    cx, cy = xy[c, 0] - xy[a, 0], xy[c, 1] - xy[a, 1]
    scale = max(abs(xy[a, 0]), abs(xy[a, 1]), abs(xy[b, 0]), abs(xy[b, 1]), abs(xy[c, 0]), abs(xy[c, 1]))
    cross = ex * cy - ey * cx
    dot = ex * cx + ey * cy
    return abs(cross) <= ON_SEGMENT * scale * math.sqrt(ex * ex + ey * ey) and 0.0 < dot < ex * ex + ey * ey


@kernel
def _split_at_apex(r, m, segs, vmark, vtri, work, e, f, triflaws, state):
    """Split subsegment edge ``e`` (org o, dest d) at the existing vertex
    ``c``, the apex of its side ``f`` (``e`` or its twin), which lies on it
    within rounding: the sliver ``(o, d, c)`` goes (with a triangle on the
    other side, flipping ``o d`` to ``c y``; without one, deleting the
    sliver), and ``c o`` and ``c d`` become the two halves, as a split's
    would.  No vertex is made.  Returns DONE, NEED_ROOM or PRECISION."""
    o = m.corner[lnext(e)]
    d = m.corner[lprev(e)]
    c = m.corner[f]
    g = m.twin[f]
    n_c0 = m.twin[lprev(f)]  # the neighbours across the sliver's other edges
    n_c1 = m.twin[lnext(f)]
    bad = g == NO_EDGE and (n_c0 == NO_EDGE or n_c1 == NO_EDGE)  # a sliver ear of the mesh
    if g != NO_EDGE:  # the flip must leave two counter-clockwise triangles
        xy = m.xy
        u, w, y = m.corner[lnext(f)], m.corner[lprev(f)], m.corner[g]
        bad = not (
            orient2d(xy[c, 0], xy[c, 1], xy[u, 0], xy[u, 1], xy[y, 0], xy[y, 1]) > 0.0
            and orient2d(xy[c, 0], xy[c, 1], xy[y, 0], xy[y, 1], xy[w, 0], xy[w, 1]) > 0.0
        )
    if bad:  # nothing to split at: Triangle's error
        r.ipar[I_ERRV] = o
        r.ipar[I_ERRW] = d
        return PRECISION
    if segs.size[R_NREC] >= segs.marker.shape[0] or queue_used(r) + 4 > r.hkey.shape[0] or _enc_len(r) + 4 > r.enc.shape[0]:
        r.ipar[I_NEED] = max(r.ipar[I_NEED], 4)
        return NEED_ROOM
    rec = m.seg[e]
    half = new_record(segs, segs.marker[rec], segs.source[rec], segs.ends[rec, 0], segs.ends[rec, 1])
    if vmark[c] == 0:
        vmark[c] = segs.marker[rec]
    if r.vtype[c] == V_FREE:
        r.vtype[c] = V_SEGMENT
    made = 0
    if g != NO_EDGE:
        # the two triangles on the far side take the far side's bound and attribute
        area, attr = _bounds(r, g // 3)
        t1 = flip(m, work, f)  # (c, u, y) and (c, y, w) for f = u -> w
        t2 = m.twin[3 * t1 + 1] // 3
        for t in (t1, t2):
            _set_bounds(r, t, area, attr)
            _remember(m, vtri, t)
        h0 = 3 * t1 + 2  # c - u
        h1 = 3 * t2 + 1  # w - c
        r.fan[0] = t1
        r.fan[1] = t2
        made = 2
    else:
        kill_triangle(m, f // 3)
        work[C_DELETED] += 1
        m.twin[n_c0] = NO_EDGE
        m.twin[n_c1] = NO_EDGE
        _remember(m, vtri, n_c0 // 3)
        _remember(m, vtri, n_c1 // 3)
        h0 = n_c0
        h1 = n_c1
    # the half at o keeps the record, the half at d takes the new one (as a split)
    for h in (h0, h1):
        u = m.corner[lnext(h)]
        w = m.corner[lprev(h)]
        _mark(m, h, rec if u == o or w == o else half)
    work[C_SEGMENT_SPLIT] += 1
    for i in range(made):
        if triflaws:
            test_triangle(r, m, segs, vtri, work, r.fan[i], state)
    check_subsegment(r, m, h0)
    check_subsegment(r, m, h1)
    _trace(r, T_SEGMENT, made, 1 + made, 0, r.ipar[I_HSIZE])
    return DONE


@kernel
def split_encroached(r, m, segs, vmark, parent, vtri, work, triflaws, state):
    """Split queued encroached subsegments until none is left (or the budget
    is spent), in passes over the pool.  Returns DONE, NEED_ROOM or
    PRECISION."""
    if not r.ipar[I_EBUSY]:  # each call starts at the pool's first slot, as Triangle's does
        r.ipar[I_EBUSY] = 1
        r.ipar[I_ECURSOR] = 0
    while _enc_len(r) > 0 and r.ipar[I_BUDGET] != 0:
        i = r.ipar[I_ECURSOR]
        if i >= r.ipar[I_EFRESH]:  # the next pass
            r.ipar[I_ECURSOR] = 0
            continue
        if r.enc[i, 0] < 0:
            r.ipar[I_ECURSOR] = i + 1
            continue
        if _trace_full(r):
            return NEED_ROOM
        e = _enc_edge(r, m, work, vtri, i, state)
        if e >= 0:
            r.enc[i, 3] = m.stamp[e // 3]
        if e >= 0 and not r.ipar[I_D]:
            u = r.enc[i, 0]
            v = r.enc[i, 1]
            if not _chew_delete(r, m, segs, vtri, work, e, state):
                return NEED_ROOM
            if m.stamp[e // 3] != r.enc[i, 3] or m.corner[lnext(e)] != u:  # a deletion re-made it
                e = _edge(m, work, vtri, u, v, state)
        if e >= 0:  # (else split or gone since it was queued)
            status = split_subsegment(r, m, segs, vmark, parent, vtri, work, e, triflaws, state)
            if status != DONE:
                return status
        _enc_free(r, i)
        r.ipar[I_ECURSOR] = i + 1
    r.ipar[I_EBUSY] = 0
    return DONE


@kernel
def split_bad_triangle(r, m, segs, vmark, parent, vtri, work, h, state):
    """Insert the off-center or circumcenter of handle ``h``'s triangle
    unless it is across a subsegment or encroaches one (then the subsegment
    is queued).  Returns DONE or NEED_ROOM (nothing changed)."""
    xy = m.xy
    t = h // 3
    px, py, xi, eta, off = steiner_point(r, m, h)
    work[C_CIRCUMCENTER] += 1
    a, b, c = m.corner[h], m.corner[lnext(h)], m.corner[lprev(h)]  # apex, org, dest
    if math.isnan(px) or math.isnan(py) or (px == xy[a, 0] and py == xy[a, 1]) or (px == xy[b, 0] and py == xy[b, 1]) or (
        px == xy[c, 0] and py == xy[c, 1]
    ):
        work[C_DUPLICATE] += 1
        return DONE
    steps0 = work[C_WALK]
    # Triangle's walk from the handle, or from the edge before it when that
    # puts the point on the inner side of the first edge
    status, e = precise_walk(m, work, lprev(h) if eta < xi else h, px, py, m.stamp.shape[0] + 64)
    if status == LOC_FAILED:
        status, e = line_walk(m, work, t, px, py, 4 * m.stamp.shape[0] + 64)
    steps = work[C_WALK] - steps0
    if status == LOC_BLOCKED or (status == LOC_ON_EDGE and m.seg[e] != NO_SEG):
        if m.seg[e] != NO_SEG and _may_split(r, m, e):
            if _enc_len(r) + 1 > r.enc.shape[0]:
                return NEED_ROOM
            _enc_push(r, m, e)
        work[C_REJECTED] += 1
        _trace(r, T_REJECTED, 0, 0, steps, r.ipar[I_HSIZE])
        return DONE
    if status == LOC_ON_VERTEX or (status != LOC_INSIDE and status != LOC_ON_EDGE):
        work[C_DUPLICATE] += 1
        return DONE
    start = e // 3
    second = -1
    if status == LOC_ON_EDGE and m.twin[e] != NO_EDGE:
        second = m.twin[e] // 3
    n, nb = _cavity(r, m, work, px, py, start, second, -1)
    if not _room(r, m, nb):
        _unsee(r, n)
        return NEED_ROOM
    # Triangle's flips circle the new vertex from the located edge's origin
    # (its destination when the point is on it)
    _order_rim(r, nb, m.corner[lprev(e)] if status == LOC_ON_EDGE else m.corner[lnext(e)])
    # a point inside a subsegment's lens is rejected; the subsegment is split
    xy = m.xy
    encroached = 0
    for j in range(nb):
        if r.bnd[j, 3] != NO_SEG and _in_lens(r, xy, r.bnd[j, 1], r.bnd[j, 2], px, py):
            encroached += 1
            _queue_side(r, m, r.bnd[j, 4], True)
    if encroached:
        _unsee(r, n)
        work[C_REJECTED] += 1
        work[C_UNDONE] += nb
        _trace(r, T_REJECTED, 0, 0, steps, r.ipar[I_HSIZE])
        return DONE
    # attributes: barycentric in (org, dest, apex)
    v = _new_vertex(m, r, vmark, parent, px, py, V_FREE, 0, b, c, a, xi, eta)
    _fill_cavity(r, m, work, vtri, v, n, nb)
    work[C_STEINER] += 1
    if r.ipar[I_BUDGET] > 0:
        r.ipar[I_BUDGET] -= 1
    _test_fan(r, m, segs, vtri, work, nb, 1, state)
    _trace(r, T_OFFCENTER if off else T_CIRCUMCENTER, nb, n, steps, r.ipar[I_HSIZE])
    return DONE


def tally_encroached(r, m, segs):
    """Queue every encroached subsegment, in the order the subsegments were
    made (Triangle's pool order), each edge once."""
    n = int(m.size[S_NSLOT])
    e = np.flatnonzero(m.seg[: 3 * n] != NO_SEG)
    e = e[m.stamp[e // 3] > 0]
    # one side per subsegment: the one its record's ends run along (the
    # edge it was made on), else the only one
    rec = m.seg[e]
    xy = m.xy
    k = e % 3
    org, dest = m.corner[e - k + (k + 1) % 3], m.corner[e - k + (k + 2) % 3]
    ends = segs.ends[rec]
    along = np.einsum("ij,ij->i", xy[dest] - xy[org], xy[ends[:, 1]] - xy[ends[:, 0]]) > 0
    first = along | (m.twin[e] == NO_EDGE)
    e = e[first]
    e = e[np.unique(m.seg[e], return_index=True)[1]]
    _tally(r, m, e)


@kernel
def _tally(r, m, edges):
    """Queue the encroached ones of subsegment ``edges``; the caller made
    room for all of them."""
    for i in range(edges.shape[0]):
        check_subsegment(r, m, edges[i])


@kernel
def refine(r, m, segs, vmark, parent, vtri, work, state):
    """Triangle's refinement loop, resumable: returns DONE, NEED_ROOM (grow the
    arrays and call again), PAUSE (call again) or PRECISION."""
    while True:
        if r.ipar[I_PHASE] == 0:  # encroached subsegments of the input
            status = split_encroached(r, m, segs, vmark, parent, vtri, work, 0, state)
            if status != DONE:
                return status
            r.ipar[I_PHASE] = 1
        if r.ipar[I_PHASE] == 1:  # every triangle's quality
            if r.hkey.shape[0] < m.size[S_NSLOT] + 16:
                return NEED_ROOM
            queue_clear(r)
            for t in range(m.size[S_NSLOT]):
                if m.stamp[t] > 0:
                    test_triangle(r, m, segs, vtri, work, t, state)
            r.ipar[I_PHASE] = 2
        if _trace_full(r):
            return NEED_ROOM
        if r.ipar[I_CURRENT] >= 0:  # the popped triangle (again after a NEED_ROOM)
            if queue_used(r) + 1 > r.hkey.shape[0]:  # room to queue it again
                r.ipar[I_NEED] = max(r.ipar[I_NEED], 1)
                return NEED_ROOM
            t = r.ipar[I_CURRENT]
            stamp = r.ipar[I_CURSTAMP]
            if m.stamp[t] == stamp:
                status = split_bad_triangle(r, m, segs, vmark, parent, vtri, work, 3 * t, state)
                if status != DONE:
                    return status
            r.ipar[I_CURRENT] = -1
            if _enc_len(r) > 0:  # split the subsegments first, then try again
                # (room: checked above, and a split leaves two spare)
                heap_push(r, r.par[P_CURKEY], t, stamp)
                status = split_encroached(r, m, segs, vmark, parent, vtri, work, 1, state)
                if status != DONE:
                    return status
        if _enc_len(r) > 0:
            status = split_encroached(r, m, segs, vmark, parent, vtri, work, 1, state)
            if status != DONE:
                return status
        if r.ipar[I_HSIZE] == 0 or r.ipar[I_BUDGET] == 0:
            return DONE
        # compact when stale entries outnumber live triangles, or before the queue must grow
        live = m.size[S_NLIVE]
        if queue_used(r) > max(r.ipar[I_HLIMIT], min(2 * live + 4096, r.hkey.shape[0] - 1024)):
            heap_compact(r, m)
            r.ipar[I_HLIMIT] = 2 * queue_used(r) + 4096  # amortised: never twice in a row
        if r.ipar[I_SLICE] >= PAUSE_EVERY:
            r.ipar[I_SLICE] = 0
            return PAUSE
        r.ipar[I_SLICE] += 1
        i = heap_pop(r)
        t = r.htri[i]
        work[C_QUEUE_POP] += 1
        if m.stamp[t] != r.hstamp[i]:
            work[C_STALE_POP] += 1
            continue
        r.par[P_CURKEY] = r.hkey[i]
        r.ipar[I_CURRENT] = t
        r.ipar[I_CURSTAMP] = r.hstamp[i]
