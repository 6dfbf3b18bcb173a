# cython: language_level=3
"""Segment recovery kernels: from a Delaunay triangulation to a constrained one.

Segments are inserted in input order from a work stack of pieces ``(a, b,
segment)`` kept in a ``Recovery``, so the kernel can stop when the mesh is
full and resume after the driver grows it.  One piece is recovered as
follows.

1. Turn around ``a`` to the triangle the ray ``a -> b`` enters.  If the edge
   ``a b`` exists, mark it.  If a vertex ``v`` lies exactly on the ray
   (exact orientation), mark ``a v`` and continue with ``v -> b``.
2. Otherwise walk along the segment through the triangles it crosses,
   collecting the crossed edges.  The walk stops at ``b``, at a vertex
   exactly on the segment (the rest becomes a new piece), or at a
   subsegment it would cross.
3. Crossing a subsegment: the two segments intersect.  The intersection point
   (computed along the crossed subsegment) becomes a new vertex that splits
   it; the piece is replaced by ``a -> p`` and ``p -> b``.  Within rounding
   of an end of the subsegment the point is Triangle's, beside that end, or
   that end itself with a copy of it in the output, as Triangle outputs such
   a point twice (``_split_at_crossing``).
4. Otherwise flip the crossed edges away (Sloan's algorithm: flip any
   crossed edge whose quadrilateral is strictly convex, until none crosses;
   one always is), mark the segment, and restore the constrained Delaunay
   property by Lawson flips of the new edges.  Flipping, unlike deleting the
   crossed triangles and re-filling the two sides, needs no assumption about
   the shape of the crossed region (it can wrap around a vertex whose whole
   star it crosses).

Every constrained edge piece has its own subsegment record (marker, input
segment); ``Mesh.seg[e]`` holds the record number on both sides of the edge.

(About 800 lines: the four steps above share the walk along the segment and
its tolerance, and split across modules they would call each other
indirectly for every crossed edge.)
"""

from __future__ import annotations

import numpy as np

import cython
from cython.cimports.instrument.core.insert import (
    flip, flip_in_place, lawson, lawson_in_place, should_flip, split_edge, split_edge_in_place, split_triangle,
    splits_after_a_flip, splits_cleanly, star_edges,
)
from cython.cimports.instrument.core.locate import LOC_INSIDE, LOC_ON_EDGE, LOC_ON_VERTEX, walk
from cython.cimports.instrument.core.mesh import NO_EDGE, NO_SEG, Index, Mesh, lnext, lprev, next_hull_edge, set_parent, spare_triangles
from cython.cimports.instrument.core.navigate import find_edge, remember_corners, vertex_edge
from cython.cimports.instrument.core.predicates import dot_sign, incircle, orient2d
from cython.cimports.instrument.core.scaling import crossing_terms, unit_scale
from cython.cimports.instrument.core.status import DONE, FAILED, NEED_BUFFER, NEED_ROOM
from cython.cimports.instrument.core.subsegments import Subsegments, new_record
from cython.cimports.instrument.segments.crossing import crossing_point, scouted_crossing
from cython.cimports.instrument.counters import C_INCIRCLE, C_ORIENT, C_STEINER
from cython.cimports.libc.math import fabs, nextafter, sqrt

# what recovering one piece found (_recover)
_PIECE_DONE = cython.declare(cython.int, 0)  # the piece is a subsegment now
_PIECE_CONTINUES = cython.declare(cython.int, 1)  # a vertex on it: go on from there
_PIECE_CROSSES = cython.declare(cython.int, 2)  # it crosses a subsegment (the caller splits it)
_PIECE_FAILED = cython.declare(cython.int, 3)
_PIECE_BUFFER = cython.declare(cython.int, 4)  # the scratch buffer is too small (nothing changed)
_PIECE_SHORTENED = cython.declare(cython.int, 5)  # b's end of it is a subsegment now: go on towards the vertex
_PIECE_COPIED = cython.declare(cython.int, 6)  # as CONTINUES, the vertex copied at the crossing of a subsegment


@cython.cclass
class Recovery:
    """The work of ``insert_segments``, kept between its calls: the input
    rows (a, b, input segment) and how many have been taken, a stack of
    pieces (the top is next; a row is pushed when the stack is empty, so
    the pieces a split leaves come before the next row, as if every row
    had been stacked up front, without copying them all), the input
    segments' markers, a scratch buffer, and a count of pieces handled
    against a bound (rounded crossing points that re-route each other must
    not loop for ever).  Vertices from ``plain`` on are crossing vertices
    (rounded); ``ends`` holds each input segment's two endpoints;
    ``copies`` the first ``ncopies`` rows (copy, vertex) of the crossing
    vertices made as copies of an input vertex, outside the mesh (where
    Triangle outputs a crossing twice: ``_split_at_crossing``)."""

    def __init__(self, rows, markers, buffer: int, plain: int = 0):
        rows = np.ascontiguousarray(np.asarray(rows, dtype=np.int64).reshape(-1, 3))
        self.rows = rows
        self.plain = plain
        if rows.shape[0] and _numbered_in_order(self.rows):  # every input row: no scatter
            ends = np.ascontiguousarray(rows[:, :2])
        else:
            ends = np.full((int(rows[:, 2].max()) + 1 if rows.shape[0] else 1, 2), -1, dtype=np.int64)
            ends[rows[:, 2]] = rows[:, :2]
        self.ends = ends
        self.taken = 0
        self.pieces = np.zeros((64, 3), dtype=np.int64)
        self.top = 0
        self.markers = np.ascontiguousarray(markers, dtype=np.int32)
        self.buf = np.zeros(buffer, dtype=np.int64)
        self.handled = 0
        self.inputs = rows.shape[0]
        self.copies = np.zeros((4, 2), dtype=np.int64)
        self.ncopies = 0

    def grow_pieces(self) -> None:
        """Room for the next pieces and the next copy, where they are short of it."""
        if self.top + 4 > self.pieces.shape[0]:
            grown = np.zeros((2 * self.pieces.shape[0], 3), dtype=np.int64)
            grown[: self.pieces.shape[0]] = self.pieces
            self.pieces = grown
        if self.ncopies >= self.copies.shape[0]:
            grown = np.zeros((2 * self.copies.shape[0], 2), dtype=np.int64)
            grown[: self.copies.shape[0]] = self.copies
            self.copies = grown

    @property
    def copied(self) -> np.ndarray:
        """The rows (copy, vertex) of the copies made so far."""
        return np.array(self.copies[: self.ncopies], dtype=np.int64).reshape(-1, 2)

    def grow_buffer(self) -> None:
        self.buf = np.zeros(2 * self.buf.shape[0], dtype=np.int64)

    @property
    def current(self) -> tuple[int, int, int]:
        """The piece on top of the stack (a, b, input segment): the one
        ``insert_segments`` stopped at."""
        p = np.asarray(self.pieces)[self.top - 1]
        return int(p[0]), int(p[1]), int(p[2])


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _numbered_in_order(rows: cython.longlong[:, ::1]) -> cython.bint:
    """Row i is input segment i, for every row (Recovery's usual case; a
    loop here rather than numpy's array_equal against an arange, which
    with its conversions cost a tenth of a small run's recovery)."""
    for i in range(rows.shape[0]):
        if rows[i, 2] != i:
            return False
    return True


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def mark_subsegment(
    m: Mesh, segs: Subsegments, e: Index, marker: cython.int, source: cython.int, against: cython.bint
) -> cython.void:
    """Make edge ``e`` (both sides) a subsegment of input segment ``source``.

    A new edge gets a new record, whose ends run along ``e`` (from its
    origin to its destination), or against it if ``against``: ``e`` is
    then the twin of the edge Triangle makes the subsegment on.  The
    record's direction decides which side of it refinement tests first
    (splits.first_side), as Triangle's record does (found by comparing the
    encroached subsegments it queues first: tests/engine/test_pool_order.py).  An edge that already is a subsegment (a duplicate
    segment) keeps its record, taking ``marker`` if its own is 0.
    Endpoints whose marker is 0 take the subsegment's.
    """
    old: Index = m.seg[e]
    if old == NO_SEG:
        if against:
            old = new_record(segs, marker, source, m.corner[lprev(e)], m.corner[lnext(e)])
        else:
            old = new_record(segs, marker, source, m.corner[lnext(e)], m.corner[lprev(e)])
        m.seg[e] = cython.cast(cython.int, old)
        if m.twin[e] != NO_EDGE:
            m.seg[m.twin[e]] = cython.cast(cython.int, old)
    elif segs.marker[old] == 0:
        segs.marker[old] = marker
    mk: cython.int = segs.marker[old]
    o: Index = m.corner[lnext(e)]
    d: Index = m.corner[lprev(e)]
    if m.vmark[o] == 0:
        m.vmark[o] = mk
    if m.vmark[d] == 0:
        m.vmark[d] = mk


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _within_rounding(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double, px: cython.double, py: cython.double,
    s: cython.double,
) -> cython.bint:
    """Is ``p``, whose exact orientation against the line a -> b is ``s``,
    within a few units in the last place of that line?  The tolerance is
    relative to the coordinates and to the length of ``a b``; where those
    magnitudes could overflow or underflow its products (squared lengths
    pass DBL_MAX near 2^512) the test runs on the points scaled by an exact
    power of two, which leaves the comparison's outcome as it is in exact
    arithmetic."""
    mx: cython.double = max(max(fabs(ax), fabs(ay)), max(fabs(bx), fabs(by)))
    f: cython.double
    if not (mx <= 2.0**240 and mx >= 2.0**-240):
        f = unit_scale(mx)
        ax *= f
        ay *= f
        bx *= f
        by *= f
        px *= f
        py *= f
        s = orient2d(ax, ay, bx, by, px, py)
    length: cython.double = sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay))
    tol: cython.double = 2.0**-48 * (fabs(ax) + fabs(ay) + fabs(bx) + fabs(by))
    return fabs(s) <= tol * length


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _side(m: Mesh, a: Index, b: Index, y: Index, plain: Index, sa: Index, sb: Index) -> cython.double:
    """orient2d of vertex ``y`` against the piece a -> b, but 0 for a point
    the piece must end at although rounding put it a few units in the last
    place off the piece's line.

    Vertices below ``plain`` are the input's: their coordinates are exact,
    and an input vertex is on a piece of an input segment (``sa >= 0``)
    only when exactly on it, as in Triangle.  A rounded crossing vertex
    starts pieces that are off their segment's line, and an input vertex
    exactly on that segment is then passed by, an ulp or so away, as
    Triangle passes it by: the piece can then cross that vertex's own
    segments beside it (``_split_at_crossing``) or miss them.  (Taking it,
    as ours did, made other meshes than Triangle's: a segment pieced
    through it closed a domain that Triangle leaves open, or crossed a
    segment that Triangle's misses: regressions/crossing-beside-an-end-area.json
    and crossing-beside-an-end-count.json.)  The tolerance applies only to
    crossing vertices (``plain`` or above, their coordinates rounded), and
    to the pieces of hull segments (``sa < 0``): a crossing vertex near the
    line of another segment through the same point is taken to be on it,
    or later segments would cross again a rounding error away."""
    xy = m.xy
    ax: cython.double = xy[a, 0]
    ay: cython.double = xy[a, 1]
    bx: cython.double = xy[b, 0]
    by: cython.double = xy[b, 1]
    px: cython.double = xy[y, 0]
    py: cython.double = xy[y, 1]
    s: cython.double = orient2d(ax, ay, bx, by, px, py)
    if s == 0.0:
        return s
    if a < plain and b < plain and y < plain:
        return s  # exact input: the exact sign
    if not _within_rounding(ax, ay, bx, by, px, py, s):
        return s
    if y >= plain or sa < 0:
        return 0.0
    return s  # an input vertex: on the piece only when exactly on it


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _ahead(xy: cython.double[:, ::1], a: Index, b: Index, v: Index) -> cython.bint:
    """For ``v`` on the line ``a -> b`` (up to ``_side``'s tolerance): is it
    ``b`` or between ``a`` and ``b``?  A vertex past ``b`` (or behind ``a``)
    is not on the segment: with the tolerance it can look collinear while
    both ``a b`` and ``a v`` are edges (the guitar outline: taking it marked
    an edge that is no segment and left the segment's own edge unmarked).
    Decided by its exact projection on the line (``_within_subsegment``), as
    the checker decides which vertices a segment's chain passes: compared
    along the line's dominant axis, a crossing vertex an ulp beside ``a``
    was ahead while its projection lies behind ``a``, and the piece ``a v``
    left the segment's chain (regressions/concurrent-crossings-end-chain.json)."""
    if v == b:
        return True
    return _within_subsegment(xy, a, b, xy[v, 0], xy[v, 1])


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _next_around(m: Mesh, e: Index, direction: cython.int) -> Index:
    """The next triangle's edge around the origin of ``e`` (the piece's start):
    counter-clockwise for direction 0, clockwise for 1; NO_EDGE at the hull."""
    tw: Index
    if direction == 0:
        return m.twin[lprev(e)]
    tw = m.twin[e]
    return NO_EDGE if tw == NO_EDGE else lnext(tw)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _turn_to_edge(m: Mesh, b: Index, e0: Index, plain: Index) -> tuple[Index, cython.int]:
    """``turn_to``'s answer where the piece is an edge already, found by
    vertex numbers alone: ``(e, where)`` for the first triangle of
    ``turn_to``'s turn (counter-clockwise, then clockwise from ``e0``) with
    ``b`` as a corner, or ``(-1, -1)`` if there is none, or if a
    crossing vertex (``plain`` or above) comes first.

    Among input vertices (exact orientations) ``turn_to`` stops at that
    triangle and no earlier: no vertex lies strictly inside the edge
    ``a b`` and no triangle's wedge at ``a`` holds the edge's direction
    strictly inside it, as the mesh is a triangulation.  A crossing vertex
    could pass ``_side``'s tolerance, so the turn gives up there.  Most
    segments of large inputs are edges of the Delaunay triangulation, and
    this spares their orientation tests (none is made, so none is counted)."""
    e: Index
    d: Index
    x: Index
    nxt: Index
    for direction in range(2):
        e = e0
        for _ in range(m.stamp.shape[0]):
            d = m.corner[lprev(e)]
            x = m.corner[e]
            if d == b:
                return e, 1
            if d >= plain:
                return -1, -1
            if x == b:
                return e, 2
            if x >= plain:
                return -1, -1
            nxt = _next_around(m, e, direction)
            if nxt == NO_EDGE or nxt == e0:
                break
            e = nxt
    return -1, -1


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _behind_side(m: Mesh, a: Index, b: Index, v: Index) -> cython.double:
    """The exact orientation of ``v`` against ``a -> b``, for a vertex that
    ``_side`` takes to be on the line but that lies behind ``a`` (or past
    ``b``): it cannot be on the piece, so its wedge is decided exactly.
    With ``_side``'s 0 the turn skipped the one triangle whose wedge at
    ``a`` holds the piece's direction, and found none: a crossing vertex a
    few ulps from ``a`` is within rounding of every line through ``a``,
    whatever its direction (regressions/concurrent-crossings-recovery-error.json:
    segment 2 ends within 2 ulps of the crossing of segments 0 and 1, which
    lies below its end, its direction to the upper right)."""
    xy = m.xy
    m.work[C_ORIENT] += 1
    return orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[v, 0], xy[v, 1])


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def turn_to(m: Mesh, a: Index, b: Index, e0: Index, plain: Index, sa: Index, sb: Index) -> tuple[Index, cython.int]:
    """Turn around ``a`` (from edge ``e0``, origin ``a``) to the edge ``e``
    (origin ``a``) whose triangle contains the start of the ray ``a -> b``.

    Returns ``(e, where)``: where = 0 if ``b`` is strictly inside the wedge
    (the ray crosses the edge opposite ``a``), 1 if ``dest(e)`` lies on the
    ray, 2 if ``apex(e)`` lies on the ray; (-1, -1) if no triangle is found.
    "On the ray" is ``_side``'s: ``plain``, ``sa`` and ``sb`` as there.
    """
    xy = m.xy
    e: Index
    d: Index
    x: Index
    nxt: Index
    od: cython.double
    ox: cython.double
    where: cython.int
    if a < plain and b < plain:
        e, where = _turn_to_edge(m, b, e0, plain)
        if e >= 0:  # found by vertex numbers: no orientation test was made (the counter counts calls)
            return e, where
    for direction in range(2):  # counter-clockwise, then clockwise from e0
        e = e0
        for _ in range(m.stamp.shape[0]):
            d = m.corner[lprev(e)]
            x = m.corner[e]
            m.work[C_ORIENT] += 2
            od = -_side(m, a, b, d, plain, sa, sb)
            ox = -_side(m, a, b, x, plain, sa, sb)
            if od == 0.0 and _ahead(xy, a, b, d):
                return e, 1
            if ox == 0.0 and _ahead(xy, a, b, x):
                return e, 2
            # a corner on the line but not ahead is not on the piece: where the
            # other corner's side makes the wedge a candidate, its exact side
            if od == 0.0 and ox < 0.0:
                od = -_behind_side(m, a, b, d)
            elif ox == 0.0 and od > 0.0:
                ox = -_behind_side(m, a, b, x)
            if od > 0.0 and ox < 0.0:
                return e, 0
            nxt = _next_around(m, e, direction)
            if nxt == NO_EDGE or nxt == e0:
                break
            e = nxt
    return -1, -1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _recover(
    m: Mesh, segs: Subsegments, a: Index, b: Index, marker: cython.int, source: cython.int, buf: cython.longlong[::1],
    plain: Index, sa: Index, sb: Index,
) -> tuple[cython.int, Index, Index]:
    """Recover one piece ``a -> b`` of input segment ``source``.

    Returns ``(kind, v, e)`` with kind one of the ``_PIECE_*`` values:
    continue with ``v -> b``, or the piece crosses subsegment edge ``e``
    (right -> left of ``v`` -> the other end), ``v`` the end the crossing is
    computed from (Triangle's choice, measured from its crossing vertices:
    scripts/crossing_agreement.py).  That is ``a`` where the edge facing
    ``a`` is the subsegment; else ``b`` where the edge facing ``b`` is one
    (looked for only once the walk has met a subsegment, so a piece that
    crosses none costs what it did); else ``a`` with the first subsegment
    the walk meets.  ``plain``, ``sa``, ``sb``: as for ``_side`` (the
    source's endpoints).
    """
    xy = m.xy
    e0: Index = vertex_edge(m, a)
    if e0 < 0:
        return _PIECE_FAILED, -1, -1
    e: Index
    where: cython.int
    e, where = turn_to(m, a, b, e0, plain, sa, sb)
    if e < 0:
        return _PIECE_FAILED, -1, -1
    d: Index
    x: Index
    if where == 1:  # dest(e) on the ray
        d = m.corner[lprev(e)]
        mark_subsegment(m, segs, e, marker, source, False)  # Triangle makes it on a -> d
        return (_PIECE_DONE if d == b else _PIECE_CONTINUES), d, -1
    if where == 2:  # apex(e) on the ray: the edge apex -> a is lprev(e)
        x = m.corner[e]
        mark_subsegment(m, segs, lprev(e), marker, source, True)  # Triangle makes it on a -> x
        return (_PIECE_DONE if x == b else _PIECE_CONTINUES), x, -1
    # Triangle looks from b's end too before recovering the piece: an edge
    # from b along the segment, or a subsegment across it at b
    eb: Index
    wb: cython.int
    if m.seg[lnext(e)] == NO_SEG:
        eb = vertex_edge(m, b)
        if eb >= 0:
            eb, wb = turn_to(m, b, a, eb, plain, sa, sb)
            if eb >= 0 and wb == 1:
                d = m.corner[lprev(eb)]
                mark_subsegment(m, segs, eb, marker, source, False)
                return (_PIECE_DONE if d == a else _PIECE_SHORTENED), d, -1
            if eb >= 0 and wb == 2:
                x = m.corner[eb]
                mark_subsegment(m, segs, lprev(eb), marker, source, True)
                return (_PIECE_DONE if x == a else _PIECE_SHORTENED), x, -1
            if eb >= 0 and wb == 0 and m.seg[lnext(eb)] != NO_SEG:
                return _PIECE_CROSSES, b, lnext(eb)
    # Walk through the crossed triangles, queueing the crossed edges as
    # vertex pairs (right, left): flips change edge ids, not vertex pairs.
    n: Index = buf.shape[0] // 4
    qr: cython.longlong[::1] = buf[0:n]
    ql: cython.longlong[::1] = buf[n : 2 * n]
    stack: cython.longlong[::1] = buf[2 * n :]
    nq: Index = 0
    c: Index = lnext(e)  # the crossed edge, right -> left
    end: Index = -1
    tw: Index
    y: Index
    s: cython.double
    fuzzy: cython.bint = False  # a vertex taken to be on the piece within rounding only
    crosses: cython.bint
    copied: cython.bint = False  # end is Triangle's crossing with a subsegment, made a copy of end
    taken: cython.bint = False  # end is an input end of a subsegment the piece crosses beside it
    ct: cython.double
    csx: cython.double
    csy: cython.double
    px: cython.double
    py: cython.double
    tol: cython.double
    while end < 0:
        if m.seg[c] != NO_SEG:
            if nq == 0:
                return _PIECE_CROSSES, a, c
            # Triangle's crossing exactly at an input end of c (it outputs
            # the point twice: _split_at_crossing): the piece goes to that
            # end, by flips that leave no pocket waiting for a vertex on c
            # (Triangle's flips would, and no vertex comes)
            px, py, tol = _rounded_crossing(m, a, b, c)
            y, ct, csx, csy = _beside_end(m, a, b, c, plain, px, py, tol)
            if y >= 0 and csx == xy[y, 0] and csy == xy[y, 1]:
                end = y
                fuzzy = True
                _place_crossing(m, segs, m.seg[c], m.nvert, csx, csy, m.corner[lnext(c)], m.corner[lprev(c)], ct)
                copied = True
            elif y >= 0 and (not _beside_splits(m, a, c, y, csx, csy) or _flips_start_past(m, a, b, y, sa, sb)):
                # a crossing beside that end where Triangle's point would not
                # split c cleanly: _split_at_crossing takes the end itself,
                # and the piece goes to it the same way (after Triangle's
                # flips their pocket would wait for a vertex on the piece,
                # and none comes: regressions/crossing-beside-an-end-fold.json);
                # or where Triangle's flips start on the far side of that end
                # and never meet c (regressions/through-vertex-after-crossing.json)
                end = y
                fuzzy = True
                taken = True
            elif y < 0:
                # a vertex the walk passed within rounding of the crossing
                # (and of no end of c) that the crossing would put on its
                # wrong side (_near_crossed): the crossing is that vertex, as
                # _split_at_crossing takes a vertex near it, and the piece
                # goes to it by exact flips.  After Triangle's flips the
                # pocket beside it would wait for a vertex on its far side,
                # and the one that comes, an ulp from it, lies on its near
                # side: the mesh folds (tests/engine/test_concurrent_crossings.py)
                y = _near_crossed(m, a, b, c, qr, ql, nq, px, py, tol)
                if y >= 0:
                    end = y
                    fuzzy = True
            break
        tw = m.twin[c]
        if tw == NO_EDGE:
            return _PIECE_FAILED, -1, -1
        if nq >= n:
            return _PIECE_BUFFER, -1, -1
        qr[nq] = m.corner[lnext(c)]
        ql[nq] = m.corner[lprev(c)]
        nq += 1
        y = m.corner[tw]
        if y == b:
            s = 0.0
        else:
            m.work[C_ORIENT] += 1
            s = _side(m, a, b, y, plain, sa, sb)
        if s > 0.0:
            c = lnext(tw)
        elif s < 0.0:
            c = lprev(tw)
        else:  # y is b, or a vertex exactly on the segment
            end = y
            if y != b:
                m.work[C_ORIENT] += 1
                fuzzy = orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[y, 0], xy[y, 1]) != 0.0
    if not fuzzy:  # Triangle's way, which leaves its records where Triangle's are
        e, crosses = _constrained_edge(m, e, b, plain, sa, sb, stack)
        if e < 0:
            return _PIECE_FAILED, -1, -1
        if crosses:
            return _PIECE_CROSSES, a, e
        mark_subsegment(m, segs, e, marker, source, False)  # e: end -> a, as Triangle's
        return (_PIECE_DONE if end == b else _PIECE_CONTINUES), end, -1
    if copied or taken:  # the edges a -> b crossed that a -> end crosses too (not those at end)
        nq = _crossing_only(m, a, end, qr, ql, nq)
    flipped: cython.bint = _flip_out(m, a, end, qr, ql, nq, n, stack)
    if not (copied or taken) and not (flipped and (find_edge(m, a, end) >= 0 or find_edge(m, end, a) >= 0)):
        # end is within rounding of the piece's line only, and the walk's
        # edges were not those that a -> end crosses: those, exactly, in the
        # mesh the flips left (a triangulation still, Delaunay again first)
        if flipped and not restore_delaunay(m, stack):
            return _PIECE_FAILED, -1, -1
        end, nq = _crossed_exactly(m, a, end, qr, ql, n)
        if nq == -2:
            return _PIECE_BUFFER, -1, -1
        if nq < 0:
            return _PIECE_FAILED, -1, -1
        flipped = _flip_out(m, a, end, qr, ql, nq, n, stack)
    if not flipped:
        return _PIECE_FAILED, -1, -1
    e = find_edge(m, a, end)
    if e >= 0:
        mark_subsegment(m, segs, e, marker, source, True)  # (Triangle would make it on end -> a)
    else:  # a hull edge with the mesh on its other side (a copy's piece can run along the hull)
        e = find_edge(m, end, a)
        if e < 0:
            return _PIECE_FAILED, -1, -1
        mark_subsegment(m, segs, e, marker, source, False)
    if not restore_delaunay(m, stack):
        return _PIECE_FAILED, -1, -1
    if copied:
        return _PIECE_COPIED, end, -1
    return (_PIECE_DONE if end == b else _PIECE_CONTINUES), end, -1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _near_crossed(
    m: Mesh, a: Index, b: Index, c: Index, qr: cython.longlong[::1], ql: cython.longlong[::1], nq: Index,
    px: cython.double, py: cython.double, tol: cython.double,
) -> Index:
    """The first vertex of the ``nq`` queued edges (crossed by the piece
    ``a b`` before it meets subsegment edge ``c``; ``qr`` right of the
    piece, ``ql`` left) within ``tol`` of the crossing ``(px, py)``, other
    than ``a``, ``b`` and the ends of ``c``, whose side the crossing
    changes (``_side_changes``), for the crossing rounded once or
    Triangle's (``scouted_crossing``); -1 if there is none.

    Triangle's flips leave the pocket on that vertex's side waiting for a
    vertex on the piece, and one that puts it on the line from ``a`` or
    past it, or across the halves of ``c``, can only fold the mesh.  A
    vertex as near whose sides stay is passed by, as Triangle passes it
    (its own crossing vertex beside it)."""
    xy = m.xy
    right: Index = m.corner[lnext(c)]
    left: Index = m.corner[lprev(c)]
    v: Index
    side: cython.double
    t: cython.double = -1.0
    sx: cython.double = 0.0
    sy: cython.double = 0.0
    scouted: cython.bint = False
    for i in range(2 * nq):
        v = qr[i // 2] if i % 2 == 0 else ql[i // 2]
        if v == a or v == b or v == right or v == left or not _near(xy, v, px, py, tol):
            continue
        if not scouted:
            t, sx, sy = scouted_crossing(
                xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[right, 0], xy[right, 1], xy[left, 0], xy[left, 1]
            )
            scouted = True
        side = -1.0 if i % 2 == 0 else 1.0
        if _side_changes(m, a, right, left, v, side, px, py):
            return v
        if t >= 0.0 and _side_changes(m, a, right, left, v, side, sx, sy):
            return v
    return -1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _side_changes(
    m: Mesh, a: Index, right: Index, left: Index, v: Index, side: cython.double, px: cython.double,
    py: cython.double,
) -> cython.bint:
    """Does vertex ``v``, on ``side`` of the piece from ``a`` (-1 right, 1
    left), lie on the line from ``a`` to the crossing ``p`` or beyond it, or
    do the two halves of the subsegment right -> left split at ``p`` pass
    it on another side than the subsegment does?"""
    xy = m.xy
    m.work[C_ORIENT] += 1
    if side * orient2d(xy[a, 0], xy[a, 1], px, py, xy[v, 0], xy[v, 1]) <= 0.0:
        return True
    m.work[C_ORIENT] += 3
    s: cython.double = orient2d(xy[right, 0], xy[right, 1], xy[left, 0], xy[left, 1], xy[v, 0], xy[v, 1])
    s1: cython.double = orient2d(xy[right, 0], xy[right, 1], px, py, xy[v, 0], xy[v, 1])
    s2: cython.double = orient2d(px, py, xy[left, 0], xy[left, 1], xy[v, 0], xy[v, 1])
    return (s > 0.0) != (s1 > 0.0) or (s < 0.0) != (s1 < 0.0) or (s > 0.0) != (s2 > 0.0) or (s < 0.0) != (s2 < 0.0)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _crossed_exactly(
    m: Mesh, a: Index, end: Index, qr: cython.longlong[::1], ql: cython.longlong[::1], n: Index,
) -> tuple[Index, Index]:
    """``(v, nq)``: the edges (vertex pairs, right -> left, in order from
    ``a``) that the segment ``a end`` crosses, exactly, queued in ``qr``,
    ``ql`` (room for ``n``), up to ``v``: ``end``, or the first vertex
    exactly on the segment between its ends (the piece goes through it).
    ``nq = -1`` where that segment meets a subsegment or the boundary
    first (or the turn finds no triangle), -2 where the queue is too short.

    The walk along ``a -> b`` took ``end`` within rounding of that line
    only, and its crossed edges are not those of ``a end`` where ``end``
    lies near ``a``: a vertex a few ulps away is within rounding of every
    line through ``a``, whatever its direction, and Sloan's flips cannot
    recover a segment from edges it does not cross (campaign sweep: three
    segments within 2 ulps of one point, the third's piece from its
    crossing beside one end to the crossing of the other two, which lies
    behind that end exactly on their line)."""
    e0: Index = vertex_edge(m, a)
    if e0 < 0:
        return end, -1
    e: Index
    where: cython.int
    e, where = turn_to(m, a, end, e0, m.nvert, -1, -1)  # every vertex below "plain": exact
    if e < 0:
        return end, -1
    if where == 1:
        return m.corner[lprev(e)], 0
    if where == 2:
        return m.corner[e], 0
    xy = m.xy
    nq: Index = 0
    c: Index = lnext(e)
    tw: Index
    y: Index
    s: cython.double
    while True:
        tw = m.twin[c]
        if m.seg[c] != NO_SEG or tw == NO_EDGE:
            return end, -1
        if nq >= n:
            return end, -2
        qr[nq] = m.corner[lnext(c)]
        ql[nq] = m.corner[lprev(c)]
        nq += 1
        y = m.corner[tw]
        if y == end:
            return end, nq
        m.work[C_ORIENT] += 1
        s = orient2d(xy[a, 0], xy[a, 1], xy[end, 0], xy[end, 1], xy[y, 0], xy[y, 1])
        if s == 0.0:
            return y, nq
        c = lnext(tw) if s > 0.0 else lprev(tw)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _crossing_only(
    m: Mesh, a: Index, b: Index, qr: cython.longlong[::1], ql: cython.longlong[::1], nq: Index,
) -> Index:
    """Keep, in order, the first ``nq`` queued edges (vertex pairs) that
    cross the segment ``a b`` strictly (an end on each side, neither of
    them ``a`` or ``b``); returns how many.  The walk queued the edges
    crossed by a piece that ends beside ``b`` (its line within rounding of
    ``b``): some end at ``b``, which Sloan's flips would turn for ever."""
    xy = m.xy
    k: Index = 0
    u: Index
    v: Index
    su: cython.double
    sv: cython.double
    for i in range(nq):
        u = qr[i]
        v = ql[i]
        if u == a or u == b or v == a or v == b:
            continue
        m.work[C_ORIENT] += 2
        su = orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[u, 0], xy[u, 1])
        sv = orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[v, 0], xy[v, 1])
        if (su < 0.0 and sv > 0.0) or (su > 0.0 and sv < 0.0):
            qr[k] = u
            ql[k] = v
            k += 1
    return k


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _flip_here(m: Mesh, e: Index) -> cython.void:
    """``flip_in_place`` (Triangle's record rewrite), then the corners' hints."""
    tw: Index = m.twin[e]
    flip_in_place(m, e)
    remember_corners(m, e // 3)
    remember_corners(m, tw // 3)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _edge_in_slot(m: Mesh, t: Index, u: Index, v: Index) -> Index:
    """The edge ``u -> v`` of slot ``t``, or -1."""
    for k in range(3):
        if m.corner[3 * t + (k + 1) % 3] == u and m.corner[3 * t + (k + 2) % 3] == v:
            return 3 * t + k
    return -1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _fix_side(m: Mesh, t0: Index, left: cython.bint, stack: cython.longlong[::1]) -> cython.bint:
    """Make one side of a segment being recovered constrained Delaunay
    again, after the flip that brought the origin ``v`` of edge ``t0`` into
    the fan around the segment's first end (Triangle's stack-based method
    for the pocket on that side, its ``delaunayfixup``): ``v`` is treated as
    just inserted, in the sector of ``t0``'s triangle only.

    Across the edge opposite ``v`` lies a triangle with far vertex ``f``.
    Nothing is done at a mesh boundary or a subsegment, nor where the
    corner of the pocket next to ``v`` (on the ``left`` side or the right
    one) is reflex as seen with ``f``: the inverted triangle there waits
    for a later vertex.  Otherwise the edge flips if the far triangle is
    inverted (a waiting one, now unstacked) or if ``f`` is inside the
    circle of ``t0``'s triangle; then both triangles the flip leaves at
    ``v`` are treated the same way, the one on ``t0``'s side first (depth
    first, by an explicit stack of edges, which stay valid: flips rewrite
    slots in place).  Edges whose origin is ``v`` keep their slot through
    the flips, so the caller finds ``t0``'s edge again there.  False if
    ``stack`` is too short (it holds one edge per pocket triangle at most)."""
    xy = m.xy
    n: Index = 1
    stack[0] = t0
    t: Index
    near: Index
    far: Index
    nv: Index
    lv: Index
    rv: Index
    fv: Index
    while n > 0:
        n -= 1
        t = stack[n]
        near = lnext(t)
        far = m.twin[near]
        if far == NO_EDGE or m.seg[near] != NO_SEG:
            continue
        nv = m.corner[near]
        lv = m.corner[lnext(near)]
        rv = m.corner[lprev(near)]
        fv = m.corner[far]
        m.work[C_ORIENT] += 1
        if left:
            if orient2d(xy[nv, 0], xy[nv, 1], xy[lv, 0], xy[lv, 1], xy[fv, 0], xy[fv, 1]) <= 0.0:
                continue  # lv is reflex: the pocket waits
        elif orient2d(xy[fv, 0], xy[fv, 1], xy[rv, 0], xy[rv, 1], xy[nv, 0], xy[nv, 1]) <= 0.0:
            continue  # rv is reflex
        m.work[C_ORIENT] += 1
        if orient2d(xy[rv, 0], xy[rv, 1], xy[lv, 0], xy[lv, 1], xy[fv, 0], xy[fv, 1]) > 0.0:
            # the far triangle is not inverted: flip only if not locally Delaunay
            m.work[C_INCIRCLE] += 1
            if incircle(xy[lv, 0], xy[lv, 1], xy[fv, 0], xy[fv, 1], xy[rv, 0], xy[rv, 1], xy[nv, 0], xy[nv, 1]) <= 0.0:
                continue
        if n + 2 > stack.shape[0]:
            return False
        _flip_here(m, near)
        stack[n] = far  # now (v, f, rv), origin v
        stack[n + 1] = lprev(t)  # now (v, lv, f), origin v: first
        n += 2
    return True


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _constrained_edge(
    m: Mesh, e: Index, b: Index, plain: Index, sa: Index, sb: Index, stack: cython.longlong[::1]
) -> tuple[Index, cython.bint]:
    """Recover the segment from ``a`` = org(``e``) towards ``b`` as Triangle
    does, flipping in place (``flip_in_place``): ``e``'s triangle is the one
    the segment leaves ``a`` through, crossing edge lnext(``e``).

    Each crossed edge is flipped, which brings the vertex beyond it into a
    fan around ``a``; the pocket on that vertex's side of the segment is
    fixed (``_fix_side``), and the walk goes on with the next crossed edge
    of the fan, until the vertex brought in is ``b`` or lies on the
    segment (``_side``), when both sides are fixed, or the next edge to
    cross is a subsegment.  The caller checked that the walk meets no
    vertex on the segment within rounding only.  Returns ``(f, False)``
    with ``f`` the edge from the last vertex brought in to ``a`` (the one
    to mark), or ``(f, True)`` with ``f`` the subsegment edge the segment
    crosses (right -> left, apex ``a``); ``(-1, False)`` if ``stack`` was
    too short."""
    a: Index = m.corner[lnext(e)]
    f: Index = lnext(e)
    f2: Index
    far: Index
    t: Index
    s: cython.double
    _flip_here(m, f)  # f: far -> a now
    while True:
        far = m.corner[lnext(f)]
        if far == b:
            s = 0.0
        else:
            m.work[C_ORIENT] += 1
            s = _side(m, a, b, far, plain, sa, sb)
        f2 = lnext(m.twin[f])  # far -> the vertex clockwise of a around far
        if s == 0.0:
            t = f // 3
            if not _fix_side(m, f, False, stack):
                return -1, False
            if not _fix_side(m, f2, True, stack):
                return -1, False
            return _edge_in_slot(m, t, far, a), False
        if s > 0.0:  # far is left of the segment: the next crossed edge is right -> far
            if not _fix_side(m, f2, True, stack):
                return -1, False
            f = lprev(f)
        else:  # far is right: the next crossed edge is far -> left
            t = f // 3
            if not _fix_side(m, f, False, stack):
                return -1, False
            f = lnext(m.twin[_edge_in_slot(m, t, far, a)])
        if m.seg[f] != NO_SEG:
            return f, True
        _flip_here(m, f)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _flip_and_remember(m: Mesh, e: Index) -> Index:
    t1: Index = flip(m, e)
    remember_corners(m, t1)
    remember_corners(m, m.twin[3 * t1 + 1] // 3)
    return t1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _flip_out(
    m: Mesh, a: Index, b: Index, qr: cython.longlong[::1], ql: cython.longlong[::1], nq: Index, n: Index,
    stack: cython.longlong[::1],
) -> cython.bint:
    """Flip every queued edge (a circular queue of ``nq`` vertex pairs that
    cross ``a b``) until none crosses; new edges that do not cross go on
    ``stack`` (from ``stack[0]`` = count) for the Delaunay pass."""
    xy = m.xy
    ax: cython.double = xy[a, 0]
    ay: cython.double = xy[a, 1]
    bx: cython.double = xy[b, 0]
    by: cython.double = xy[b, 1]
    stack[0] = 0
    head: Index = 0
    left: Index = nq
    tries: Index = 0
    u: Index
    v: Index
    e: Index
    x: Index
    y: Index
    k: Index
    convex: cython.bint
    sx: cython.double
    sy: cython.double
    while left > 0:
        tries += 1
        if tries > 4 * nq * nq + 64:  # Sloan's loop always finds a flip
            return False
        u = qr[head]
        v = ql[head]
        head = (head + 1) % n
        left -= 1
        e = find_edge(m, u, v)
        if e < 0:
            return False
        x = m.corner[e]
        y = m.corner[m.twin[e]]
        # the flipped triangles (x, u, y) and (x, y, v) must be counter-clockwise
        m.work[C_ORIENT] += 2
        convex = (
            orient2d(xy[x, 0], xy[x, 1], xy[u, 0], xy[u, 1], xy[y, 0], xy[y, 1]) > 0.0
            and orient2d(xy[x, 0], xy[x, 1], xy[y, 0], xy[y, 1], xy[v, 0], xy[v, 1]) > 0.0
        )
        if not convex:
            qr[(head + left) % n] = u
            ql[(head + left) % n] = v
            left += 1
            continue
        _flip_and_remember(m, e)
        m.work[C_ORIENT] += 2
        sx = orient2d(ax, ay, bx, by, xy[x, 0], xy[x, 1])
        sy = orient2d(ax, ay, bx, by, xy[y, 0], xy[y, 1])
        # signs compared, not their product: orient2d's values are of degree
        # 2, and near 2^-512 two of them multiply to 0 (a crossing edge left
        # unflipped, and the segment could not be recovered)
        if x != a and x != b and y != a and y != b and ((sx < 0.0 and sy > 0.0) or (sx > 0.0 and sy < 0.0)):
            # still crosses: queue it again, right end first
            if sx < 0.0:
                qr[(head + left) % n] = x
                ql[(head + left) % n] = y
            else:
                qr[(head + left) % n] = y
                ql[(head + left) % n] = x
            left += 1
        else:
            k = stack[0]
            if 2 * k + 3 > stack.shape[0]:
                return False
            stack[2 * k + 1] = x
            stack[2 * k + 2] = y
            stack[0] = k + 1
    return True


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def restore_delaunay(m: Mesh, stack: cython.longlong[::1]) -> cython.bint:
    """Lawson's flips over the edges (vertex pairs) on ``stack`` (count in
    ``stack[0]``, pairs after it) until every unconstrained one is locally
    Delaunay; each flip queues its quadrilateral's four sides.  False if the
    stack is too short."""
    k: Index = stack[0]
    u: Index
    v: Index
    e: Index
    x: Index
    y: Index
    while k > 0:
        k -= 1
        u = stack[2 * k + 1]
        v = stack[2 * k + 2]
        e = find_edge(m, u, v)
        if e < 0 or not should_flip(m, e):  # flipped away since, or fine
            continue
        x = m.corner[e]
        y = m.corner[m.twin[e]]
        if 2 * (k + 4) + 1 > stack.shape[0]:
            return False
        _flip_and_remember(m, e)
        # the quadrilateral x, u, y, v: its sides x-u, u-y, y-v, v-x
        stack[2 * k + 1] = x
        stack[2 * k + 2] = u
        stack[2 * k + 3] = u
        stack[2 * k + 4] = y
        stack[2 * k + 5] = y
        stack[2 * k + 6] = v
        stack[2 * k + 7] = v
        stack[2 * k + 8] = x
        k += 4
    return True


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _near(xy: cython.double[:, ::1], v: Index, px: cython.double, py: cython.double, tol: cython.double) -> cython.bint:
    return fabs(xy[v, 0] - px) <= tol and fabs(xy[v, 1] - py) <= tol


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _rounded_crossing(m: Mesh, a: Index, b: Index, c: Index) -> tuple[cython.double, cython.double, cython.double]:
    """``(px, py, tol)``: where segment ``a b`` crosses subsegment edge ``c``,
    exactly, rounded once, and the tolerance within which a vertex is taken
    for that point: relative to the point, with a floor of one subnormal
    unit (an absolute 1e-300 took every vertex of an input near 1e-300 for
    the crossing)."""
    xy = m.xy
    left: Index = m.corner[lprev(c)]
    right: Index = m.corner[lnext(c)]
    px: cython.double
    py: cython.double
    px, py = crossing_point(
        xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[right, 0], xy[right, 1], xy[left, 0], xy[left, 1]
    )
    return px, py, 2.0**-48 * (fabs(px) + fabs(py)) + 2.0**-1074


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _inside(xy: cython.double[:, ::1], u: Index, w: Index, v: Index) -> cython.bint:
    """Does ``v`` lie strictly between ``u`` and ``w`` along the line
    ``u -> w`` (its projection on the line, exactly)?  A vertex taken for a
    crossing becomes an inner vertex of a segment's chain, and a chain is
    straight only if its vertices come in order along the segment."""
    return _within_subsegment(xy, u, w, xy[v, 0], xy[v, 1])


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def crossing_parameter(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
    rx: cython.double, ry: cython.double, lx: cython.double, ly: cython.double,
) -> cython.double:
    """Where the line a -> b crosses the segment r -> l, as the parameter
    t in [0, 1] along r -> l (0.5 if they are parallel).

    t is a ratio of two cross products of coordinate differences, of degree
    2: near 2^512 they overflow (inf / inf), and differences below about
    2^-537 leave nothing above the subnormal range (0 / 0, or all bits
    lost).  Where the differences are out of the safe range they are scaled
    by an exact power of two first, which leaves the ratio unchanged."""
    num: cython.double
    den: cython.double
    num, den = crossing_terms(ax, ay, bx, by, rx, ry, lx, ly, ax, ay)
    t: cython.double = 0.5
    if den != 0.0:
        t = num / den
        t = min(max(t, 0.0), 1.0)
    return t


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _scouted_fits(
    m: Mesh, c: Index, right: Index, left: Index, sx: cython.double, sy: cython.double,
    px: cython.double, py: cython.double, tol: cython.double,
) -> cython.bint:
    """May the crossing be Triangle's point ``s`` rather than ``p``, the exact
    crossing rounded once?  Only where ``s`` is within 2^-40 of ``p``'s
    magnitude (far off means the formula lost its bits: nearly parallel
    segments, an underflow, a crossing near the origin), farther than ``_near``'s
    tolerance from both ends of ``c`` (a crossing within rounding of an end
    is that end, as the exact path decides), and in the closed union of the
    two triangles beside ``c`` (so the split stays local as the exact point's
    does)."""
    xy = m.xy
    if not (fabs(sx) <= 1.7976931348623157e308 and fabs(sy) <= 1.7976931348623157e308):
        return False
    # of p's own magnitude: a crossing 1e-147 from an end, at (3e-146,
    # 4e-147) on a segment of length 1, is off by 1e-17 in doubles, which
    # there passes the end (three such pairs could not be recovered)
    big: cython.double = max(fabs(px), fabs(py))
    if fabs(sx - px) > 2.0**-40 * big or fabs(sy - py) > 2.0**-40 * big:
        return False
    if _near(xy, right, sx, sy, tol) or _near(xy, left, sx, sy, tol):
        return False
    rx: cython.double = xy[right, 0]
    ry: cython.double = xy[right, 1]
    lx: cython.double = xy[left, 0]
    ly: cython.double = xy[left, 1]
    x: Index
    m.work[C_ORIENT] += 1
    if orient2d(rx, ry, lx, ly, sx, sy) >= 0.0:  # c's own side (or on c): its triangle (x, right, left)
        x = m.corner[c]
    else:
        if m.twin[c] == NO_EDGE:
            return False
        x = m.corner[m.twin[c]]  # the triangle (x, left, right)
        rx, lx = lx, rx
        ry, ly = ly, ry
    m.work[C_ORIENT] += 2
    return (orient2d(xy[x, 0], xy[x, 1], rx, ry, sx, sy) >= 0.0
            and orient2d(lx, ly, xy[x, 0], xy[x, 1], sx, sy) >= 0.0)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _place_crossing(m: Mesh, segs: Subsegments, r: Index, nv: Index, px: cython.double, py: cython.double,
                    right: Index, left: Index, t: cython.double) -> cython.void:
    """Make vertex ``nv`` at (px, py), the crossing at parameter ``t`` of
    subsegment ``right -> left`` (record ``r``), whichever way it is then
    inserted."""
    m.xy[nv, 0] = px
    m.xy[nv, 1] = py
    set_parent(m, nv, right, left, right, t, 0.0)
    m.nvert = nv + 1
    m.vmark[nv] = segs.marker[r]
    m.work[C_STEINER] += 1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _within_subsegment(
    xy: cython.double[:, ::1], r: Index, l: Index, sx: cython.double, sy: cython.double,
) -> cython.bint:
    """Does the point s project strictly between ``r`` and ``l`` (exactly)?
    Triangle's crossing beside an end E of ``r l`` can round past E (t
    rounded to 1, then the coordinate an ulp beyond): the crossed segment's
    chain would go back at s (the pairs of
    tests/differential/test_near_end_crossings.py that cross 1e-21 from an
    end beside a zero coordinate; Triangle's meshes fail the checker
    there), and E is taken instead."""
    rx: cython.double = xy[r, 0]
    ry: cython.double = xy[r, 1]
    lx: cython.double = xy[l, 0]
    ly: cython.double = xy[l, 1]
    return dot_sign(rx, ry, sx, sy, rx, ry, lx, ly) > 0 and dot_sign(sx, sy, lx, ly, rx, ry, lx, ly) > 0


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _an_ulp_off(ex: cython.double, ey: cython.double, sx: cython.double, sy: cython.double) -> cython.bint:
    """Is s at least half an ulp of E's larger coordinate away from E (in
    one coordinate)?  Triangle's crossing closer than that to E (E beside
    a zero coordinate: (-0.56, 2e-124) an end, the crossing segment along
    y = 0, Triangle's point (-0.56, 0)) is E for ours, as before:
    refinement cannot place vertices between two so close (ours raised
    PrecisionError under pcq; tests/differential/test_near_end_crossings.py,
    whose pairs cross 1e-300..1e-10 from an end), and Triangle's vertex
    there is a near-duplicate that the oracles merge."""
    big: cython.double = max(fabs(ex), fabs(ey))
    half: cython.double = 0.5 * (nextafter(big, 2.0e308) - big)
    return fabs(sx - ex) >= half or fabs(sy - ey) >= half


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _beside_splits(
    m: Mesh, a: Index, c: Index, end: Index, sx: cython.double, sy: cython.double,
) -> cython.bint:
    """Will Triangle's crossing ``s`` beside input vertex ``end`` (an end of
    subsegment edge ``c``, which the piece from ``a`` crosses after other
    edges) split ``c`` cleanly once Triangle's flips have brought ``a`` to
    it?  ``_split_at_crossing``'s test, asked before those flips: ``s`` an
    ulp or more off ``end``, strictly inside ``c``, inside the two triangles
    beside ``c`` now (so no vertex lies between ``c`` and its two pieces
    through ``s``) and inside the triangle (``a``, right, left) that the
    flips leave beside it, whose apex is then ``a``.

    The flips fold the mesh until a vertex on the piece comes: the pocket
    they leave on each side waits for it (``_fix_side``).  Where the answer
    is no, ``_split_at_crossing`` takes ``end`` for the crossing, and no
    vertex comes.  Both tests are needed: the flipped triangle overlaps the
    pocket, and a pocket vertex within rounding of ``c``'s line can lie in
    it between ``c`` and ``s`` (campaign seed 3031: Triangle's own mesh is
    folded there, its triangle of that vertex, the crossing before and
    ``s`` inverted)."""
    xy = m.xy
    right: Index = m.corner[lnext(c)]
    left: Index = m.corner[lprev(c)]
    if not (_an_ulp_off(xy[end, 0], xy[end, 1], sx, sy) and _within_subsegment(xy, right, left, sx, sy)):
        return False
    if not splits_cleanly(m, c, sx, sy):
        return False
    m.work[C_ORIENT] += 2
    return (orient2d(sx, sy, xy[left, 0], xy[left, 1], xy[a, 0], xy[a, 1]) > 0.0
            and orient2d(xy[a, 0], xy[a, 1], xy[right, 0], xy[right, 1], sx, sy) > 0.0)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _flips_start_past(m: Mesh, a: Index, b: Index, end: Index, sa: Index, sb: Index) -> cython.bint:
    """Do Triangle's flips for the piece ``a -> b`` start on the far side of
    input vertex ``end``, a neighbour of ``a`` that the piece passes within
    rounding (the walk met a subsegment of ``end``'s beside it)?

    The piece is what is left of its input segment ``a -> f`` after the
    segment was met from ``f``'s side (a crossing there, or a vertex on it):
    Triangle turned around ``a`` towards ``f`` first, found no subsegment
    facing it, and recovers the rest from that triangle, towards ``b`` now.
    Where ``end`` lies strictly between the rays ``a -> b`` and ``a -> f``,
    the edge ``a end`` parts that triangle from the one the piece leaves
    ``a`` through: the flips go round ``end`` on ``f``'s side, never meet its
    subsegment, and leave a fold at ``end`` (campaign seed 3101: the piece
    (-0.268, 0.677) -> (0.119, 0.0150) passes 4e-17 beside the end (0.0238,
    0.178) of a segment it crosses; Triangle's pcQ mesh has the clockwise
    triangle (``end``, ``a``, ``b``) and no vertex on that segment).  Ours
    takes ``end`` on the piece, which keeps Triangle's vertices and a valid
    mesh."""
    f: Index
    if a == sa and sb >= 0:
        f = sb
    elif a == sb and sa >= 0:
        f = sa
    else:
        return False
    if b == f or (find_edge(m, a, end) < 0 and find_edge(m, end, a) < 0):
        return False
    xy = m.xy
    m.work[C_ORIENT] += 2
    s_piece: cython.double = orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[end, 0], xy[end, 1])
    s_far: cython.double = orient2d(xy[a, 0], xy[a, 1], xy[f, 0], xy[f, 1], xy[end, 0], xy[end, 1])
    return (s_piece > 0.0 and s_far < 0.0) or (s_piece < 0.0 and s_far > 0.0)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _beside_end(
    m: Mesh, a: Index, b: Index, c: Index, plain: Index, px: cython.double, py: cython.double, tol: cython.double,
) -> tuple[Index, cython.double, cython.double, cython.double]:
    """``(E, t, sx, sy)``: where segment ``a b`` (walked from ``a``) crosses
    subsegment edge ``c`` within rounding of an input vertex ``E`` ending
    ``c``, that vertex, with Triangle's crossing (``scouted_crossing``: t
    along ``c``, the point s); ``E = -1`` elsewhere.  "Within rounding" is
    ``tol`` about the exact crossing rounded once, ``(px, py)``
    (``_rounded_crossing``'s).  Where the crossing is within rounding of an
    end of ``a b`` too, only if s lies strictly inside ``a b`` (exactly,
    along it), so that ``a b``'s chain through s goes forward.  Else E, an
    ulp beside that end and off ``a b``'s line, was taken onto ``a b``
    where Triangle puts its own crossing vertex, and refinement split the
    piece between the two, an ulp long, at a midpoint behind the end
    (regressions/concurrent-crossings-invalid-pdq.json)."""
    xy = m.xy
    left: Index = m.corner[lprev(c)]
    right: Index = m.corner[lnext(c)]
    near_right: cython.bint = _near(xy, right, px, py, tol)
    near_left: cython.bint = _near(xy, left, px, py, tol)
    near_piece: cython.bint = _near(xy, a, px, py, tol) or _near(xy, b, px, py, tol)
    t: cython.double
    sx: cython.double
    sy: cython.double
    if near_right == near_left:
        return -1, -1.0, 0.0, 0.0
    end: Index = right if near_right else left
    if end >= plain:
        return -1, -1.0, 0.0, 0.0
    t, sx, sy = scouted_crossing(
        xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[right, 0], xy[right, 1], xy[left, 0], xy[left, 1]
    )
    if t < 0.0 or (near_piece and not _within_subsegment(xy, a, b, sx, sy)):
        return -1, -1.0, 0.0, 0.0
    return end, t, sx, sy


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _split_at_crossing(
    m: Mesh, segs: Subsegments, a: Index, b: Index, c: Index, stack: cython.longlong[::1],
    marker: cython.int, source: cython.int, plain: Index,
) -> tuple[Index, cython.bint, cython.bint, cython.bint]:
    """Make a vertex where segment ``a b`` crosses subsegment edge ``c``
    (right -> left of ``a -> b``), ``a`` the end the piece was walked from.

    Returns ``(v, reroute, marked, copied)``, ``v = -1`` if the tables are
    full; ``copied``: see below (Triangle's rule beside an end).  The
    crossing point is Triangle's (``scouted_crossing``: along ``c`` from its
    right end, in doubles, against ``b``) where that lands within 2^-40 of
    the coordinates' magnitude of the exact crossing and in one of the two
    triangles beside ``c``, not at a corner; elsewhere (nearly parallel
    segments, a crossing within rounding of an end, an overflow) it is the
    exact one rounded once (crossing.py).  Either is inserted where it
    actually lies:
    exactly on ``c`` it splits ``c``; anywhere else (or on an existing
    vertex) ``reroute`` is True and the caller re-routes ``c`` through it.
    The mesh stays a valid triangulation either way; forcing a rounded
    point onto ``c`` could fold it.  Where it would not (the four triangles
    the split of ``c`` makes are counter-clockwise, as they are unless the
    point rounded out of the two triangles beside ``c``), ``c`` is split
    at it as Triangle splits it (``split_edge_in_place``, then
    ``lawson_in_place``: its records where Triangle's are; the half from
    ``c``'s right end gets the new record), and the piece from the point
    to ``a`` is marked at once (``marked``; with ``marker`` and ``source``),
    as Triangle marks it: the caller goes on from the point.  A point within a few units in the last
    place of one of the four endpoints (or of a corner of the triangle it
    falls in, or of the apexes of ``c``) is taken to be that vertex: a
    crossing vertex made earlier is only nearly on its lines, so later
    segments through the same point would otherwise cross them again a
    rounding error away, for ever.

    The tolerance is relative to the point's coordinates, so near one end
    of a segment several vertices can be within it, and the one taken must
    become an inner vertex of the segment(s) rerouted through it: an end of
    ``c`` must lie strictly between ``a`` and ``b`` along ``a -> b``; ``a``
    or ``b``, strictly between the ends of ``c`` along ``c``; any other
    vertex, both.  The first that does is taken (the four ends first);
    only when none does is the first one near taken, as before.  (Two
    segments crossing 2^-497 from the end of one, at (2^-20, 2^-499): the
    rounded crossing was within 2^-68 of the other's end (2^-20, 0), which
    was taken; it lies behind (2^-20, 2^-499) along the first segment, and
    the first segment's chain went back through it.  The geometry always
    leaves a choice: if an end of ``c`` near the crossing lies behind ``a``
    along ``a -> b``, then ``a`` lies strictly inside ``c``, for segments
    that are not parallel.)

    Beside an end: where the exact crossing is within that tolerance of
    an input vertex ``E`` that ends ``c`` (and of no end of ``a b``),
    Triangle's rule is followed, as measured from its output (a segment
    passing 0, 1, 2 ulps beside another's end, either side, at scales
    2^-1000..2^1000: scripts/crossing_beside_an_end.py).  Triangle knows
    no tolerance: a vertex is on a segment only when exactly on it, and
    a segment that crosses ``c`` at all, however near ``E``, makes a
    crossing vertex at Triangle's doubles point (``scouted_crossing``),
    which splits ``c``.  That point, one or two ulps beside ``E``, is
    used where it splits ``c`` cleanly (Triangle's vertex and pieces);
    where t rounds so that it lands on ``E`` exactly, Triangle inserts a
    second vertex at ``E``'s coordinates and outputs the point twice:
    here the segment goes through ``E`` and the copy is made as a vertex
    outside the mesh (``copied``; the caller records it, and it takes
    ``E``'s marker at the end, as Triangle's copy shares ``E``'s
    subsegments), so the output has Triangle's vertices while the mesh
    stays a valid one.  A point rounded out of the triangles beside ``c``
    across one side of theirs is Triangle's all the same where Triangle's
    flips after the split turn that side and leave a valid mesh
    (``splits_after_a_flip``: a sliver beside ``c`` at ``E``,
    regressions/through-vertex-after-crossing-count.json); elsewhere ``E``
    is taken as before.  Where the piece crossed other edges before ``c``,
    ``_recover`` decides that before Triangle's flips (``_beside_splits``)
    and recovers the piece to ``E`` itself.
    """
    xy = m.xy
    nv: Index = m.nvert
    r: Index = m.seg[c]
    left: Index = m.corner[lprev(c)]
    right: Index = m.corner[lnext(c)]
    # the exact crossing rounded once, and the tolerance about it
    px: cython.double
    py: cython.double
    tol: cython.double
    px, py, tol = _rounded_crossing(m, a, b, c)
    # an end near the exact crossing is chosen by the rule above, from the
    # exact crossing: Triangle's doubles point is used only away from them
    # (taken first, it left some pairs crossing 1e-147 from an end unrecoverable)
    near_right: cython.bint = _near(xy, right, px, py, tol)
    near_left: cython.bint = _near(xy, left, px, py, tol)
    near_a: cython.bint = _near(xy, a, px, py, tol)
    near_b: cython.bint = _near(xy, b, px, py, tol)
    t: cython.double
    sx: cython.double
    sy: cython.double
    t, sx, sy = scouted_crossing(
        xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[right, 0], xy[right, 1], xy[left, 0], xy[left, 1]
    )
    # an input vertex ending c that the crossing is within rounding of (and of no end of a b)
    end: Index
    bt: cython.double
    bx: cython.double
    by: cython.double
    end, bt, bx, by = _beside_end(m, a, b, c, plain, px, py, tol)
    beside: cython.bint = False  # Triangle's point beside end, where it splits c cleanly
    if end >= 0:
        if bx == xy[end, 0] and by == xy[end, 1]:  # Triangle's copy of end
            _place_crossing(m, segs, r, nv, bx, by, right, left, bt)
            return end, False, False, True
        if (_an_ulp_off(xy[end, 0], xy[end, 1], bx, by) and _within_subsegment(xy, right, left, bx, by)
                and (splits_cleanly(m, c, bx, by) or splits_after_a_flip(m, c, bx, by))):
            beside = True
            t = bt
            px = bx
            py = by
    if beside:
        pass
    elif not (near_right or near_left or near_a or near_b) and t > 0.0 and _scouted_fits(m, c, right, left, sx, sy, px, py, tol):
        px = sx
        py = sy
        tol = 2.0**-48 * (fabs(px) + fabs(py)) + 2.0**-1074
    else:  # t only for the attributes
        t = crossing_parameter(
            xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[right, 0], xy[right, 1], xy[left, 0], xy[left, 1]
        )
    if not beside:
        if near_right and _inside(xy, a, b, right):
            return right, False, False, False
        if near_left and _inside(xy, a, b, left):
            return left, False, False, False
        if near_a and _inside(xy, right, left, a):
            return a, True, False, False
        if near_b and _inside(xy, right, left, b):
            return b, True, False, False
        if near_right:
            return right, False, False, False
        if near_left:
            return left, False, False, False
        if near_a:
            return a, True, False, False
        if near_b:
            return b, True, False, False
    status: cython.int
    e: Index
    if splits_cleanly(m, c, px, py) or beside:
        half0: Index = new_record(segs, segs.marker[r], segs.source[r], segs.ends[r, 0], segs.ends[r, 1])
        if half0 < 0:
            return -1, False, False, False
        _place_crossing(m, segs, r, nv, px, py, right, left, t)
        lawson_in_place(m, split_edge_in_place(m, c, nv, cython.cast(cython.int, half0), 2))
        _ends_at(segs, r, half0, left, right, nv)
        if segs.ends[half0, 0] == nv and segs.ends[half0, 1] == right:  # Triangle's new record runs right -> p
            segs.ends[half0, 0] = cython.cast(cython.int, right)
            segs.ends[half0, 1] = cython.cast(cython.int, nv)
        e = find_edge(m, nv, a)
        if e < 0:
            return -1, False, False, False
        mark_subsegment(m, segs, e, marker, source, False)  # e: p -> a, as Triangle's
        return nv, False, True, False
    status, e = walk(m, c // 3, px, py, 4 * m.stamp.shape[0] + 64)
    if status == LOC_ON_VERTEX:
        return m.corner[lnext(e)], True, False, False
    if status != LOC_INSIDE and status != LOC_ON_EDGE:
        # rounded off the mesh (c is on the boundary): use c's nearer end
        return (right if t < 0.5 else left), False, False, False
    # as near another vertex (one nearly on both lines: a corner of the
    # triangle it falls in, or across c from it): that vertex
    near_v: Index
    first_near: Index = -1
    for k in range(5):
        if k < 3:
            near_v = m.corner[3 * (e // 3) + k]
        elif k == 3:
            near_v = m.corner[c]
        elif m.twin[c] != NO_EDGE:
            near_v = m.corner[m.twin[c]]
        else:
            break
        if _near(xy, near_v, px, py, tol):
            if _inside(xy, a, b, near_v) and _inside(xy, right, left, near_v):
                return near_v, True, False, False
            if first_near < 0:
                first_near = near_v
    if first_near >= 0:
        return first_near, True, False, False
    half: Index = new_record(segs, segs.marker[r], segs.source[r], segs.ends[r, 0], segs.ends[r, 1])
    if half < 0:
        return -1, False, False, False
    _place_crossing(m, segs, r, nv, px, py, right, left, t)
    reroute: cython.bint = True
    first: Index
    split: Index
    on_line: Index
    e_org: Index
    e_dest: Index
    if status == LOC_INSIDE:
        first = split_triangle(m, e // 3, nv)
    else:
        reroute = e != c and e != m.twin[c]
        split = m.seg[e]
        e_org = m.corner[lnext(e)]
        e_dest = m.corner[lprev(e)]
        on_line = split_edge(m, e, nv)  # edge nv -> dest(e), first new triangle
        if split != NO_SEG:  # the half nv -> dest(e) gets the new record
            m.seg[on_line] = cython.cast(cython.int, half)
            if m.twin[on_line] != NO_EDGE:
                m.seg[m.twin[on_line]] = cython.cast(cython.int, half)
            _ends_at(segs, split, half, e_org, e_dest, nv)
        first = on_line // 3
    n: Index = star_edges(m, first, stack)
    last: Index = lawson(m, stack, n)
    remember_corners(m, last)
    return nv, reroute, False, False


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _ends_at(segs: Subsegments, kept: Index, half: Index, o: Index, d: Index, p: Index) -> cython.void:
    """A crossing at ``p`` splits the subsegment ``o d`` into ``o p`` (record
    ``kept``) and ``p d`` (record ``half``): each half is a segment of its
    own from then on, ending at ``p``, as the pieces of a segment recovered
    through a vertex are (and as Triangle moves the segment's ends to the
    crossing).  Refinement's small-angle rule measures shells from those
    ends: with the input segment's ends kept instead, the four subsegments
    at a crossing share no end, the thin triangles between two of them on
    the same shell stay bad, and splits chase the crossing vertex down to
    the last bit (a 19-point star under q30: 2388 vertices for Triangle's
    1217).  The order of each record's ends is kept."""
    a: Index = segs.ends[kept, 0]
    b: Index = segs.ends[kept, 1]
    if not ((a == o and b == d) or (a == d and b == o)):
        return  # not the piece's own ends: leave them
    if a == o:
        segs.ends[kept, 1] = cython.cast(cython.int, p)
        segs.ends[half, 0] = cython.cast(cython.int, p)
        segs.ends[half, 1] = cython.cast(cython.int, d)
    else:
        segs.ends[kept, 0] = cython.cast(cython.int, p)
        segs.ends[half, 0] = cython.cast(cython.int, d)
        segs.ends[half, 1] = cython.cast(cython.int, p)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def insert_segments(m: Mesh, segs: Subsegments, work: Recovery) -> cython.int:
    """Recover every piece on ``work``'s stack (the top is next), taking
    the next input row whenever the stack is empty.

    Returns DONE, NEED_ROOM or NEED_BUFFER (grow and call again: nothing was
    half done) or FAILED.  The pieces handled are bounded by the segments
    and vertices, so that rounded crossing points that re-route each other
    cannot loop for ever.
    """
    pieces: cython.longlong[:, ::1] = work.pieces
    buf: cython.longlong[::1] = work.buf
    ends: cython.longlong[:, ::1] = work.ends
    sa: Index
    sb: Index
    sp: Index
    a: Index
    b: Index
    src: Index
    kind: cython.int
    v: Index
    c: Index
    r: Index
    cr: Index
    cl: Index
    p: Index
    reroute: cython.bint
    marked: cython.bint
    copied: cython.bint
    src_c: Index
    marker: cython.int
    e1: Index
    e2: Index
    rows: cython.longlong[:, ::1] = work.rows
    while True:
        if work.top == 0:  # (the stack always has room for one)
            if work.taken == rows.shape[0]:
                break
            pieces[0, 0] = rows[work.taken, 0]
            pieces[0, 1] = rows[work.taken, 1]
            pieces[0, 2] = rows[work.taken, 2]
            work.top = 1
            work.taken += 1
        if work.handled > 8 * (work.inputs + m.nvert) + 1024:
            return FAILED
        work.handled += 1
        if (
            m.nvert >= m.xy.shape[0]
            or spare_triangles(m) < 8
            or segs.count + 2 > segs.marker.shape[0]
            or work.top + 4 > pieces.shape[0]
            or work.ncopies >= work.copies.shape[0]
        ):
            return NEED_ROOM
        sp = work.top - 1
        a = pieces[sp, 0]
        b = pieces[sp, 1]
        src = pieces[sp, 2]
        marker = 1 if src < 0 else work.markers[src]  # -c hull segments have no input row
        sa = -1
        sb = -1
        if 0 <= src < ends.shape[0]:
            sa = ends[src, 0]
            sb = ends[src, 1]
        kind, v, c = _recover(m, segs, a, b, marker, cython.cast(cython.int, src), buf, work.plain, sa, sb)
        if kind == _PIECE_DONE:
            work.top = sp
        elif kind == _PIECE_CONTINUES:
            pieces[sp, 0] = v
        elif kind == _PIECE_COPIED:  # the copy is the last vertex made
            work.copies[work.ncopies, 0] = m.nvert - 1
            work.copies[work.ncopies, 1] = v
            work.ncopies += 1
            pieces[sp, 0] = v
        elif kind == _PIECE_SHORTENED:
            pieces[sp, 1] = v
        elif kind == _PIECE_BUFFER:
            work.handled -= 1
            return NEED_BUFFER
        elif kind == _PIECE_CROSSES:
            r = m.seg[c]
            cr = m.corner[lnext(c)]
            cl = m.corner[lprev(c)]
            e1 = v
            e2 = b if v == a else a
            p, reroute, marked, copied = _split_at_crossing(
                m, segs, e1, e2, c, buf, marker, cython.cast(cython.int, src), work.plain
            )
            if p < 0:
                return NEED_ROOM
            if copied:
                work.copies[work.ncopies, 0] = m.nvert - 1
                work.copies[work.ncopies, 1] = p
                work.ncopies += 1
            if marked:  # the piece from p to e1 is a subsegment: go on from p
                if e1 == a:
                    pieces[sp, 0] = p
                else:
                    pieces[sp, 1] = p
                continue
            if reroute:
                # re-route the crossed subsegment through p: free the edge
                # and queue its two halves as pieces of its own segment
                c = find_edge(m, cr, cl)  # its id may have changed
                if c < 0:
                    return FAILED
                m.seg[c] = NO_SEG
                if m.twin[c] != NO_EDGE:
                    m.seg[m.twin[c]] = NO_SEG
                # freed, the edge may no longer be Delaunay
                buf[0] = 1
                buf[1] = cr
                buf[2] = cl
                if not restore_delaunay(m, buf):
                    return FAILED
                src_c = segs.source[r]
                pieces[sp + 1, 0] = cr
                pieces[sp + 1, 1] = p
                pieces[sp + 1, 2] = src_c
                pieces[sp + 2, 0] = p
                pieces[sp + 2, 1] = cl
                pieces[sp + 2, 2] = src_c
                sp += 2
            elif p == a or p == b:  # cannot happen: c never ends at a or b
                return FAILED
            if p != a and p != b:
                # the piece on e1's side first, then the rest (a piece of
                # its own: its crossings are found from its ends as above,
                # which is where Triangle goes on from)
                if e1 == a:
                    pieces[sp + 1, 0] = a  # a -> p first
                    pieces[sp + 1, 1] = p
                    pieces[work.top - 1, 0] = p  # p -> b later
                else:
                    pieces[sp + 1, 0] = p  # p -> b first
                    pieces[sp + 1, 1] = b
                    pieces[work.top - 1, 1] = p  # a -> p later
                pieces[sp + 1, 2] = src
                sp += 1
            work.top = sp + 1
        else:
            return FAILED
    return DONE


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def mark_hull(m: Mesh, segs: Subsegments, source: cython.int, start: Index) -> cython.bint:
    """-c (or refinement of a point set): every boundary edge becomes a
    subsegment with marker 1; one that already is keeps its record but takes
    marker 1 if its own is 0.  Returns False if records ran out (call again
    after growing them: the edges marked keep their records).

    The edges are taken around the hull counter-clockwise from boundary
    edge ``start``, the one Triangle's outer-space handle holds
    (carve/infect.py's start_hull_edge), as Triangle makes their records,
    so the records come in Triangle's order (the encroached ones are
    queued in that order); a boundary the walk does not reach (there is
    one hull) is marked in slot order."""
    e: Index = start
    f: Index
    for _ in range(3 * m.nslot):
        if e < 0:
            break
        if segs.count >= segs.marker.shape[0]:
            return False
        mark_subsegment(m, segs, e, 1, source, False)
        f = next_hull_edge(m, e)
        e = f if f != start else NO_EDGE
    for t in range(m.nslot):
        if m.stamp[t] <= 0:
            continue
        for k in range(3):
            e = 3 * t + k
            if m.twin[e] == NO_EDGE and m.seg[e] == NO_SEG:
                if segs.count >= segs.marker.shape[0]:
                    return False
                mark_subsegment(m, segs, e, 1, source, False)
    return True


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def count_inverted(m: Mesh) -> Index:
    """Live finite triangles that are not strictly counter-clockwise (exact)."""
    xy = m.xy
    bad: Index = 0
    a: Index
    b: Index
    c: Index
    for t in range(m.nslot):
        if m.stamp[t] <= 0:
            continue
        a, b, c = m.corner[3 * t], m.corner[3 * t + 1], m.corner[3 * t + 2]
        if a < 0 or b < 0 or c < 0:
            continue
        if orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[c, 0], xy[c, 1]) <= 0.0:
            bad += 1
    return bad
