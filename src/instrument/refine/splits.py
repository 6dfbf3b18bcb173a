# cython: language_level=3
"""Ruppert's Delaunay refinement with Triangle's rules: the splits and the loop.

The loop (Triangle's ``enforcequality``): split every encroached subsegment;
queue every bad triangle; then repeatedly take the next bad triangle (the
strategy's priority decides which), compute its off-center or circumcenter
and insert it, unless the point lies across a subsegment or inside a
subsegment's diametral lens (circle with -D), in which case the subsegment
is pooled and split instead.

``refine`` is resumable: it returns ``NEED_ROOM`` when an array is full
(nothing half done; the driver grows it and calls again), ``PAUSE`` now and
then (so that Python can see Ctrl-C and report progress), ``PRECISION``
when a subsegment is too short to split, and ``DONE``.

(About 760 lines: the two kinds of split and the loop that orders them share
the room checks and the undo of an interrupted step; the pieces each split
uses live in cavity, criteria, encroach, deletion and queues.)
"""

from __future__ import annotations

import numpy as np

from ..core.filled import filled

import cython
from cython.cimports.instrument.core.insert import flip, splits_cleanly
from cython.cimports.instrument.core.locate import LOC_BLOCKED, LOC_FAILED, LOC_INSIDE, LOC_ON_EDGE, LOC_ON_VERTEX, line_walk, precise_walk
from cython.cimports.instrument.core.mesh import NO_EDGE, NO_SEG, V_FREE, V_SEGMENT, Index, Mesh, is_ghost, kill_triangle, lnext, lprev
from cython.cimports.instrument.core.navigate import edge_around, find_edge, remember_corners, vertex_edge
from cython.cimports.instrument.core.predicates import incircle, orient2d
from cython.cimports.instrument.core.scaling import scaled_dot, scaled_pair, scaled_triple, unit_scale
from cython.cimports.instrument.core.status import DONE, FAILED, NEED_ROOM, PAUSE, PRECISION
from cython.cimports.instrument.core.subsegments import Subsegments, new_record
from cython.cimports.instrument.counters import (
    C_CIRCUMCENTER,
    C_ORIENT,
    C_DELETED,
    C_DUPLICATE,
    C_FLIP,
    C_QUEUE_POP,
    C_REJECTED,
    C_SEGMENT_SPLIT,
    C_STALE_POP,
    C_STEINER,
    C_UNDONE,
    C_WALK,
)
from cython.cimports.instrument.refine.cavity import (
    collect_cavity,
    legalize_fan,
    fill_cavity,
    forget_cavity,
    has_room,
    inherit,
    inherited,
    mark_both,
    new_vertex,
    order_rim,
)
from cython.cimports.instrument.refine.criteria import queue_rejected_fan, steiner_point, test_fan, test_triangle
from cython.cimports.instrument.refine.deletion import chew_delete
from cython.cimports.instrument.refine.encroach import check_subsegment, enc_edge, enc_free, enc_push, in_lens, may_split, queue_side
from cython.cimports.instrument.refine.ghosts import insertion_records, note_born, records_known, rejected_bounds, rejected_fan_records, requeued, revive_ghosts
from cython.cimports.instrument.refine.inplace import split_in_place
from cython.cimports.instrument.refine.order import TRIANGLE
from cython.cimports.instrument.refine.queues import ghost_room, ghost_slot, ghosts_made, queue_clear, queue_compact, queue_pop, queue_push, queue_used
from cython.cimports.instrument.refine.state import T_CIRCUMCENTER, T_OFFCENTER, T_REJECTED, T_SEGMENT, Refiner, step_begins, step_undone, trace_full, trace_row
from cython.cimports.libc.math import fabs, floor, hypot, log2, nextafter, sqrt

#: steps (queue pops, subsegment splits) between two PAUSEs, so that the
#: driver sees Ctrl-C and the vertex limit at least that often
PAUSE_EVERY = cython.declare(Index, 1 << 14)

#: A vertex this close to a subsegment's line (relative to the largest
#: coordinate of the three points on each axis) lies on it up to rounding: a
#: few units in the last place, where split points that were moved onto the
#: line once and printed with 17 digits land.
ON_SEGMENT = cython.declare(cython.double, 2.0**-50)

#: half a unit in the last place, relative
HALF_ULP = cython.declare(cython.double, 2.0**-53)

#: A split vertex's distance from a subsegment's end is a power of two up
#: to this (relative; in log2 units), and a split point this close to a
#: vertex (relative to its largest coordinate) lies beside it: both far
#: above rounding's 2^-52 and far below any distinct shell or vertex.
SHELL_ROUNDING = cython.declare(cython.double, 2.0**-36)

#: ... and its distance from the line is below this fraction of its distance
#: from the nearer end (an angle below 2^-30 radians seen from that end).
ALONG_SEGMENT = cython.declare(cython.double, 2.0**-30)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _on_segment_points(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
    px: cython.double, py: cython.double, slack: cython.double,
) -> cython.bint:
    """Does the point p lie on the segment a b up to rounding, between its
    ends?  ``slack``: HALF_ULP, or 0 where p is on another segment (below)."""
    ex: cython.double = bx - ax
    ey: cython.double = by - ay
    cx: cython.double = px - ax
    cy: cython.double = py - ay
    # Rounding moves a point by units in the last place of each coordinate,
    # and a move along x shifts it off the line by |ey| / length of that: the
    # tolerance takes each axis's largest coordinate times the other
    # component; and a vertex within half a unit in the last place of the
    # largest coordinate is on it in any case (no split point can be placed
    # between it and the line). One scale for both axes admitted the midpoint
    # of a sliver's other long side, 5e-16 below a segment along the x axis
    # of length 1, whose y coordinates round 1e-31 apart: the split at it
    # failed (PrecisionError, where Triangle meshes the sliver).
    xscale: cython.double = max(fabs(ax), fabs(bx), fabs(px))
    yscale: cython.double = max(fabs(ay), fabs(by), fabs(py))
    length: cython.double = sqrt(ex * ex + ey * ey)
    cross: cython.double = ex * cy - ey * cx
    dot: cython.double = ex * cx + ey * cy
    tol: cython.double = ON_SEGMENT * (xscale * fabs(ey) + yscale * fabs(ex)) + slack * max(xscale, yscale) * length
    if not (fabs(cross) <= tol and 0.0 < dot < ex * ex + ey * ey):
        return False
    # ... and near the line next to its own distance from the ends: the units
    # in the last place above are of the largest coordinate, which at mixed
    # scales (ends at 1e300 and 0, c at 2e-302) admit a vertex at 45 degrees
    # to the segment; the split at it made a subsegment off the segment that
    # refinement chased forever.  The distance comes from the exact orient2d
    # and the lengths from hypot, which neither overflow nor vanish.
    dist: cython.double = fabs(orient2d(ax, ay, bx, by, px, py)) / hypot(ex, ey)
    near: cython.double = min(hypot(cx, cy), hypot(px - bx, py - by))
    return dist <= ALONG_SEGMENT * near


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _on_subsegment(m: Mesh, a: Index, b: Index, c: Index, loose: cython.bint) -> cython.bint:
    """Does vertex ``c`` lie on the segment ``a b`` up to rounding, between
    its ends?  ``loose``: a free vertex within half an ulp of the largest
    coordinate counts as on it too (see below for when)."""
    # squares overflow beyond 2^511 (every vertex lay on every subsegment)
    # and vanish below 2^-537: out of range, the test runs on the points
    # scaled by a power of two (exact upward; downward only bits below
    # 2^-1000 of the extent go); in range f is 1, which changes nothing
    big: cython.double = max(max(fabs(m.xy[b, 0] - m.xy[a, 0]), fabs(m.xy[b, 1] - m.xy[a, 1])),
                             max(fabs(m.xy[c, 0] - m.xy[a, 0]), fabs(m.xy[c, 1] - m.xy[a, 1])))
    f: cython.double = 1.0
    if not (big <= 2.0**240 and big >= 2.0**-240) and big > 0.0:
        f = unit_scale(big)
    ax: cython.double = m.xy[a, 0] * f
    ay: cython.double = m.xy[a, 1] * f
    bx: cython.double = m.xy[b, 0] * f
    by: cython.double = m.xy[b, 1] * f
    cx: cython.double = m.xy[c, 0] * f
    cy: cython.double = m.xy[c, 1] * f
    # Half an ulp of the largest coordinate is far more than rounding on the
    # other axis at mixed scales.  Beside a segment x = 2.2e-278 running up
    # to y = 5.6e25 it is 6e9 in x: every vertex of the domain's side x = 0
    # lay "on" the segment, the splits at them bent it onto that side and
    # the strip between the two was lost.  Beside a hull edge from (0, 0) to
    # (3e-198, 0.92) it took a free vertex 5.5e-38 away as on it, and the
    # splits there made twice Triangle's mesh, which splits at the midpoint.
    # So the slack serves only a free vertex (none on another segment), and
    # the caller asks for it only where the vertex must join the subsegment:
    # under an angle bound (no triangle between the two can be good: a vertex
    # 4.9e-11 beside a hull edge at y = 1e180, where the next double along the
    # edge is 1e164 away, left needles whose off-centers rounded onto their
    # own edges), or once the subsegment is too short for a split point.
    # The turn about c, which costs c's degree, comes last: a vertex far
    # from the subsegment (the apex of a fan of 9,350 triangles over two
    # segments 1e-188 radians apart, each of whose pieces' splits asked)
    # made every split cost that much.  (On the line without the slack, c
    # is on it with the slack too.)
    if not loose:
        return _on_segment_points(ax, ay, bx, by, cx, cy, 0.0)
    if not _on_segment_points(ax, ay, bx, by, cx, cy, HALF_ULP):
        return False
    if _on_segment_points(ax, ay, bx, by, cx, cy, 0.0):
        return True
    e0: Index = vertex_edge(m, c)
    return e0 < 0 or edge_around(m, e0, -1) < 0


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _on_later_shell(m: Mesh, a: Index, c: Index, shell: cython.double) -> cython.bint:
    """Is vertex ``c`` a split vertex whose distance from the end ``a`` is a
    power of two (up to rounding) no more than half ``shell``, the distance
    of a split point on a power-of-two shell around ``a``?  The shells of
    the later splits between ``a`` and that point then come to it."""
    if m.vtype[c] != V_SEGMENT or shell <= 0.0:
        return False
    rc: cython.double = hypot(m.xy[c, 0] - m.xy[a, 0], m.xy[c, 1] - m.xy[a, 1])
    if not (2.0 * rc <= shell * (1.0 + SHELL_ROUNDING)):
        return False
    lg: cython.double = log2(rc)  # NaN or infinite for a zero distance: not a shell
    return fabs(lg - floor(lg + 0.5)) <= SHELL_ROUNDING


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _beside_rim(r: Refiner, m: Mesh, nb: Index, px: cython.double, py: cython.double) -> cython.bint:
    """Does a vertex of the cavity's rim (``nb`` edges) lie within rounding
    of the point (px, py)?"""
    near: cython.double = SHELL_ROUNDING * max(fabs(px), fabs(py))
    u: Index
    for j in range(nb):
        u = r.bnd[j, 1]
        if fabs(m.xy[u, 0] - px) <= near and fabs(m.xy[u, 1] - py) <= near:
            return True
    return False


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _on_boundary(m: Mesh, x: Index) -> cython.bint:
    """Does the origin of edge ``x`` have a boundary edge (one without a
    live triangle across) anywhere around it?"""
    y: Index = x
    tw: Index
    for _ in range(m.stamp.shape[0]):
        tw = m.twin[lprev(y)]  # the edge into the origin, seen from the next triangle
        if tw == NO_EDGE or is_ghost(m, tw // 3):
            return True
        y = tw
        if y == x:
            return False
    return True


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _split_at_apex(r: Refiner, m: Mesh, segs: Subsegments, e: Index, f: Index, triangles: cython.bint) -> cython.int:
    """Split subsegment edge ``e`` (org o, dest d) at the existing vertex
    ``c``, the apex of its side ``f`` (``e`` or its twin), which lies on it
    within rounding: the sliver ``(o, d, c)`` goes (with a triangle on the
    other side, flipping ``o d`` to ``c y``; without one, deleting the
    sliver), and ``c o`` and ``c d`` become the two halves, as a split's
    would.  No vertex is made.  Returns DONE, NEED_ROOM or FAILED (nothing
    changed): the sliver cannot go, because it has no triangle across ``e``
    to flip with and is an ear of the mesh (deleting it would leave ``c``
    hanging by one edge), or the flip would fold.  That is no loss of
    precision: a split point on ``e`` can still be placed (three nearly
    collinear vertices whose hull is the sliver itself, Triangle meshes
    them under -pcu), so the caller splits as usual."""
    o: Index = m.corner[lnext(e)]
    d: Index = m.corner[lprev(e)]
    c: Index = m.corner[f]
    g: Index = m.twin[f]
    n_c0: Index = m.twin[lprev(f)]  # the neighbours across the sliver's other edges
    n_c1: Index = m.twin[lnext(f)]
    # Deleting the sliver (no triangle across e) makes c o and c d boundary
    # edges: not if it is an ear of the mesh (c would hang by one edge) or
    # c is on the boundary already (the domain would be pinched at c, two
    # boundary chains through one vertex: seven points within rounding of a
    # line, whose hull's two sides each took the other's vertices until the
    # sliver left between them had no split point inside).
    bad: cython.bint = g == NO_EDGE and (n_c0 == NO_EDGE or n_c1 == NO_EDGE or _on_boundary(m, lprev(f)))
    u: Index
    w: Index
    y: Index
    if g != NO_EDGE:  # the flip must leave two counter-clockwise triangles
        u = m.corner[lnext(f)]
        w = m.corner[lprev(f)]
        y = m.corner[g]
        bad = not (
            orient2d(m.xy[c, 0], m.xy[c, 1], m.xy[u, 0], m.xy[u, 1], m.xy[y, 0], m.xy[y, 1]) > 0.0
            and orient2d(m.xy[c, 0], m.xy[c, 1], m.xy[y, 0], m.xy[y, 1], m.xy[w, 0], m.xy[w, 1]) > 0.0
        )
        # ... and the new edge c y locally Delaunay: where y too lies near
        # the line o d (a chain of nearly collinear points), w lay inside the
        # circle through c, u, y, which every later cavity takes for granted
        # (an invalid mesh: check_mesh's "not locally Delaunay").  (The far
        # triangle's other edges are not asked: the flip beside an interior
        # segment (tests/engine/test_rounded_inputs.py) leaves one of them
        # out of Delaunay for a while, and refusing it piles vertices up at c.)
        bad = bad or incircle(m.xy[c, 0], m.xy[c, 1], m.xy[u, 0], m.xy[u, 1], m.xy[y, 0], m.xy[y, 1], m.xy[w, 0], m.xy[w, 1]) > 0.0
    if bad:
        return FAILED
    # room to queue every triangle around c after the flips that make the
    # mesh Delaunay again (legalize_fan), and to pool the subsegments facing c
    room: Index = m.nlive + 4
    if segs.count >= segs.marker.shape[0] or queue_used(r) + room > r.hkey.shape[0] or r.enc_live + room > r.enc.shape[0]:
        r.need = max(r.need, room)
        step_undone(r, m.work)
        return NEED_ROOM
    rec: Index = m.seg[e]
    half: Index = new_record(segs, segs.marker[rec], segs.source[rec], segs.ends[rec, 0], segs.ends[rec, 1])
    if m.vmark[c] == 0:
        m.vmark[c] = segs.marker[rec]
    if m.vtype[c] == V_FREE:
        m.vtype[c] = V_SEGMENT
    made: Index = 0
    h0: Index
    h1: Index
    t1: Index
    t2: Index
    area: cython.double
    attr: cython.double
    if g != NO_EDGE:
        # the two triangles on the far side take the far side's bound and attribute
        area, attr = inherited(m, g // 3)
        t1 = flip(m, f)  # (c, u, y) and (c, y, w) for f = u -> w
        t2 = m.twin[3 * t1 + 1] // 3
        inherit(m, t1, area, attr)
        remember_corners(m, t1)
        inherit(m, t2, area, attr)
        remember_corners(m, t2)
        h0 = 3 * t1 + 2  # c - u
        h1 = 3 * t2 + 1  # w - c
        r.fan[0] = t1
        r.fan[1] = t2
        made = 2
    else:
        kill_triangle(m, f // 3)
        m.work[C_DELETED] += 1
        m.twin[n_c0] = NO_EDGE
        m.twin[n_c1] = NO_EDGE
        remember_corners(m, n_c0 // 3)
        remember_corners(m, n_c1 // 3)
        h0 = n_c0
        h1 = n_c1
    # the half at o keeps the record, the half at d takes the new one (as a
    # split); a half that is already a subsegment with a marker (c is a hull
    # vertex under c, and the half a hull edge) keeps it, as where two input
    # segments overlap the first one's nonzero marker stays: overwritten, the
    # hull's marker 1 became the segment's 0 on the boundary
    u = m.corner[lnext(h0)]
    w = m.corner[lprev(h0)]
    if m.seg[h0] == NO_SEG or segs.marker[m.seg[h0]] == 0:
        mark_both(m, h0, rec if u == o or w == o else half)
    u = m.corner[lnext(h1)]
    w = m.corner[lprev(h1)]
    if m.seg[h1] == NO_SEG or segs.marker[m.seg[h1]] == 0:
        mark_both(m, h1, rec if u == o or w == o else half)
    m.work[C_SEGMENT_SPLIT] += 1
    flips: Index = 0
    made0: Index = made
    if made:
        # the flip o d -> c y leaves c's new edges to test: a vertex beside
        # them may lie inside their triangles' circles (c was only within
        # rounding of o d), and a mesh left so is not Delaunay
        u = m.corner[lprev(h0)]  # h0 = c -> u (its destination)
        w = m.corner[lnext(h1)]  # h1 = w -> c (its origin)
        flips = m.work[C_FLIP]
        made = legalize_fan(r, m, made)
        flips = m.work[C_FLIP] - flips
        if flips:
            h0 = find_edge(m, c, u)
            h1 = find_edge(m, w, c)
    for i in range(made):
        if triangles:
            test_triangle(r, m, segs, r.fan[i])
    if flips:  # (without flips the rim is the far triangle's, as before: c faces none of it anew)
        test_fan(r, m, segs, made, False, False)
    check_subsegment(r, m, h0)
    check_subsegment(r, m, h1)
    trace_row(r, T_SEGMENT, made0 + 2 * flips, 1 + made0 + 2 * flips, 0, r.hsize)
    return DONE


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _across_line(m: Mesh, o: Index, d: Index, px: cython.double, py: cython.double) -> tuple[cython.bint, cython.double, cython.double]:
    """The neighbour of the point (px, py), a double away on either axis or
    both, that lies on the line o d or nearest to it on its other side:
    ``(True, x, y)``, or ``(False, px, py)`` if the point is on the line or
    none of its neighbours is across.  Exact tests Triangle does not make:
    not counted."""
    side: cython.double = orient2d(m.xy[o, 0], m.xy[o, 1], m.xy[d, 0], m.xy[d, 1], px, py)
    if side == 0.0:
        return False, px, py
    best: cython.double = -1.0
    bx: cython.double = px
    by: cython.double = py
    qx: cython.double
    qy: cython.double
    q: cython.double
    for i in range(3):  # (px, px - ulp, px + ulp) against the same in y
        qx = px if i == 0 else nextafter(px, -2.0e308 if i == 1 else 2.0e308)
        for j in range(3):
            qy = py if j == 0 else nextafter(py, -2.0e308 if j == 1 else 2.0e308)
            if (i == 0 and j == 0) or not (fabs(qx) <= 1.7976931348623157e308 and fabs(qy) <= 1.7976931348623157e308):
                continue
            q = orient2d(m.xy[o, 0], m.xy[o, 1], m.xy[d, 0], m.xy[d, 1], qx, qy)
            if (q <= 0.0 if side > 0.0 else q >= 0.0) and (best < 0.0 or fabs(q) < best):
                best = fabs(q)
                bx = qx
                by = qy
    return best >= 0.0, bx, by


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _bent_away(m: Mesh, e: Index, px: cython.double, py: cython.double) -> Index:
    """The side of interior subsegment edge ``e`` (``e`` or its twin) that
    the split point (px, py) has been rounded away from and lies outside the
    circumcircle of, or -1 (almost always: the point lies exactly on the
    line o d, inside both sides' circles).

    A split point rounded off the line toward one apex while the other apex
    lies near the line too (a chain of nearly collinear points) can fall
    outside the far triangle's circle.  Taking that triangle into the cavity
    anyway (as a point on the edge would) makes the spoke to its apex not
    locally Delaunay; the constrained Delaunay mesh keeps o d as an edge,
    with the thin triangle (o, d, p) beside it (Triangle's own -p of the
    vertices and pieces made so, tests/engine/test_split_bent.py).  A point
    on the circle keeps the old cavity (both meshes are Delaunay).  Exact
    tests Triangle does not make: not counted."""
    tw: Index = m.twin[e]
    o: Index = m.corner[lnext(e)]
    d: Index = m.corner[lprev(e)]
    side: cython.double = orient2d(m.xy[o, 0], m.xy[o, 1], m.xy[d, 0], m.xy[d, 1], px, py)
    if side == 0.0:
        return -1
    far: Index = tw if side > 0.0 else e  # e's apex is left of o -> d
    a: Index = m.corner[far]
    b: Index = m.corner[lnext(far)]
    c: Index = m.corner[lprev(far)]
    if incircle(m.xy[a, 0], m.xy[a, 1], m.xy[b, 0], m.xy[b, 1], m.xy[c, 0], m.xy[c, 1], px, py) < 0.0:
        return far
    return -1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _split_cavity(r: Refiner, m: Mesh, e: Index, px: cython.double, py: cython.double) -> tuple[Index, Index, Index]:
    """The cavity of a split point (px, py) of subsegment edge ``e``:
    ``(far, n, nb)``, ``far`` the side _bent_away keeps (or -1) and ``n``,
    ``nb`` collect_cavity's counts."""
    tw: Index = m.twin[e]
    far: Index = _bent_away(m, e, px, py) if tw != NO_EDGE else -1
    n: Index
    nb: Index
    if far >= 0:
        n, nb = collect_cavity(r, m, px, py, m.twin[far] // 3, -1, -1)
    else:
        n, nb = collect_cavity(r, m, px, py, e // 3, tw // 3 if tw != NO_EDGE else -1, e)
    return far, n, nb


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def acute_ends(m: Mesh, e: Index) -> cython.int:
    """Which ends of subsegment edge ``e`` another subsegment meets in a
    triangle on either side: 1 its origin, 2 its destination (Triangle's
    ``acuteorg`` and ``acutedest``)."""
    tw: Index = m.twin[e]
    acute_org: cython.bint = m.seg[lprev(e)] != NO_SEG
    acute_dest: cython.bint = m.seg[lnext(e)] != NO_SEG
    if tw != NO_EDGE:
        acute_org = acute_org or m.seg[lnext(tw)] != NO_SEG
        acute_dest = acute_dest or m.seg[lprev(tw)] != NO_SEG
    return (1 if acute_org else 0) | (2 if acute_dest else 0)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def split_subsegment(r: Refiner, m: Mesh, segs: Subsegments, e: Index, triangles: cython.bint, acute: cython.int) -> cython.int:
    """Split subsegment edge ``e`` at its midpoint or on a power-of-two shell
    around an end shared with another segment (``acute``: ``acute_ends`` of
    ``e`` as it was before Chew's deletions, -1: as it is now).  Returns
    DONE, NEED_ROOM (nothing changed) or PRECISION."""
    step_begins(r, m.work)
    o: Index = m.corner[lnext(e)]
    d: Index = m.corner[lprev(e)]
    tw: Index = m.twin[e]
    if acute < 0:
        acute = acute_ends(m, e)
    acute_org: cython.bint = (acute & 1) != 0
    acute_dest: cython.bint = (acute & 2) != 0
    # Triangle's record runs the other way along e, from e0 = d to e1 = o;
    # computing from its ends gives its rounding, so the same vertices
    e0: Index = d
    e1: Index = o
    acute0: cython.bint = acute_dest
    acute1: cython.bint = acute_org
    ex: cython.double = m.xy[e1, 0] - m.xy[e0, 0]
    ey: cython.double = m.xy[e1, 1] - m.xy[e0, 1]
    split: cython.double = 0.5
    length: cython.double
    p2: cython.double
    shell: cython.double = 0.0  # the split point's distance from e1 (acute1) or e0, on a shell
    big: cython.double = 0.0
    f: cython.double
    if acute0 or acute1:
        # squares overflow beyond 2^511 and lose every bit below 2^-537 (a
        # zero length made the shell loop run p2 down to 0 and split = NaN):
        # out of range, measure the scaled vector (exact powers of two)
        big = max(fabs(ex), fabs(ey))
        if big <= 2.0**480 and big >= 2.0**-480:
            length = sqrt(ex * ex + ey * ey)
        else:
            f = unit_scale(big)
            length = sqrt((ex * f) * (ex * f) + (ey * f) * (ey * f)) / f
        p2 = 1.0
        while length > 3.0 * p2:
            p2 *= 2.0
        while length < 1.5 * p2:
            p2 *= 0.5
        # a power of two from the acute end; with both acute, from e1
        split = p2 / length
        shell = p2
        if acute1:
            split = 1.0 - split
    px: cython.double = m.xy[e0, 0] + split * ex
    py: cython.double = m.xy[e0, 1] + split * ey
    # one correction toward the segment's line (not out of range, where the
    # squared length is subnormal or infinite and orient2d's value saturates:
    # at 1e-162 their quotient moved the point onto an end)
    den: cython.double = ex * ex + ey * ey
    mult: cython.double = orient2d(m.xy[e0, 0], m.xy[e0, 1], m.xy[e1, 0], m.xy[e1, 1], px, py) / den
    big = max(fabs(ex), fabs(ey))
    if mult != 0.0 and den != 0.0 and mult == mult and big <= 2.0**480 and big >= 2.0**-480:
        px += mult * ey
        py += mult * -ex
    # A vertex can lie on the subsegment within rounding, not exactly (a split
    # point an earlier run wrote out, read back as an input vertex): it is
    # then the apex on its side (any other triangle there would contain it).
    # Splitting elsewhere leaves it encroaching every piece it lies on, the
    # pieces shrink towards it until a split point lands on it or next to it,
    # and the mesh gets a copy of it or slivers and runs out of precision
    # (Triangle crashes).  Split at that vertex instead.
    # (Where the apex cannot take the split, the split point is placed as
    # usual: the rim check below keeps the fan from folding.)
    # Under an angle bound, or where the subsegment is too short for a split
    # point (it rounds onto an end), a free apex within half an ulp of it
    # takes the split too (_on_subsegment); failing that, a split point on
    # an end runs out of precision.
    # Except a split vertex of another segment on a power-of-two shell
    # around the acute end this split's shell is measured from, no farther
    # than half the split point's: the later splits of the piece between
    # that end and the split point, on the halved shells, come to it, and
    # take it then (it is the apex there, at the split point).  Two
    # segments meeting at an end at an angle within rounding (a chain inside
    # a sliver's hull) are split on the same shells around it; taking the
    # other's shell vertex at once (3/4 along a hull subsegment, where
    # Triangle splits at its shell 1/2) joined the two and grew fans of
    # thousands of triangles from single vertices across the sliver.  If the
    # split point lands beside a vertex of its cavity (one that is not its
    # apex: that vertex would then encroach every piece beside it, the
    # pieces shrinking towards it until precision ran out), the apex takes
    # the split after all.
    status: cython.int
    cornered: cython.bint = (px == m.xy[o, 0] and py == m.xy[o, 1]) or (px == m.xy[d, 0] and py == m.xy[d, 1])
    loose: cython.bint = cornered or r.cfg.angle_test
    later: Index = -1  # the side whose apex a later split takes
    apex_side: Index
    for k in range(2):
        apex_side = e if k == 0 else tw
        if apex_side == NO_EDGE or not _on_subsegment(m, o, d, m.corner[apex_side], loose):
            continue
        if not cornered and _on_later_shell(m, e1 if acute1 else e0, m.corner[apex_side], shell):
            if later < 0:
                later = apex_side
            continue
        status = _split_at_apex(r, m, segs, e, apex_side, triangles)
        if status != FAILED:
            return status
    if cornered:
        r.error_org = o
        r.error_dest = d
        return PRECISION
    # The cavity takes both sides of e, as a point on it would, unless the
    # point was rounded off the line and outside the far side's circle: then
    # that side stays, and e with it, no longer a subsegment (_bent_away).
    # The split point, rounded, may land on or beyond the line of a rim edge:
    # a hull segment's pieces shrink towards its end C (to ~1e-17 beside
    # coordinates ~1e-3), encroached by an input vertex D 4e-193 from C, and
    # the point rounds onto the line C D. The fan would hold a flat or
    # inverted triangle (Triangle outputs it). That rim edge joins an end to
    # the apex D, which then lies on the subsegment within the rounding the
    # split points themselves have: split at D instead (the encroachment
    # ends).  Otherwise the point may have been rounded off the line into a
    # sliver beside e and out of it (a thin triangle that _bent_away kept,
    # whose far edge became a subsegment of the hull): the next double
    # across the line is tried once (_across_line), and failing that the
    # split runs out of precision.
    apex_e: Index = m.corner[e]
    apex_t: Index = m.corner[tw] if tw != NO_EDGE else -1
    u: Index
    w: Index
    far: Index = -1
    n: Index = 0
    nb: Index = 0
    folded: cython.bint = False
    moved: cython.bint
    for attempt in range(2):
        far, n, nb = _split_cavity(r, m, e, px, py)
        folded = False
        for j in range(nb):
            u = r.bnd[j, 1]
            w = r.bnd[j, 2]
            if orient2d(px, py, m.xy[u, 0], m.xy[u, 1], m.xy[w, 0], m.xy[w, 1]) <= 0.0:
                folded = True
                break
        if not folded:
            if later >= 0 and _beside_rim(r, m, nb, px, py):
                forget_cavity(r, m, n)
                status = _split_at_apex(r, m, segs, e, later, triangles)
                if status != FAILED:
                    return status
                far, n, nb = _split_cavity(r, m, e, px, py)
            break
        forget_cavity(r, m, n)
        if attempt > 0:
            break
        status = FAILED
        if u == apex_e or w == apex_e:
            status = _split_at_apex(r, m, segs, e, e, triangles)
        elif apex_t >= 0 and (u == apex_t or w == apex_t):
            status = _split_at_apex(r, m, segs, e, tw, triangles)
        if status != FAILED:
            return status
        moved, px, py = _across_line(m, o, d, px, py)
        if not moved:
            break
    if folded:
        r.error_org = o
        r.error_dest = d
        return PRECISION
    if not has_room(r, m, nb) or segs.count >= segs.marker.shape[0]:
        forget_cavity(r, m, n)
        step_undone(r, m.work)
        return NEED_ROOM
    # before the first list, an ordinary split (both sides in the cavity) is
    # made in Triangle's records (inplace.py)
    if not triangles and far < 0 and splits_cleanly(m, e, px, py):
        forget_cavity(r, m, n)
        split_in_place(r, m, segs, e, px, py, e0, e1, split)
        return DONE
    order_rim(r, m, nb, d)  # Triangle circles the new vertex from e's destination
    # Triangle's records through the split: a rejected or deleted vertex's
    # queued triangles this vertex remakes (ghosts.py)
    records: cython.bint = False
    revived: cython.bint = False
    if r.cfg.strategy == TRIANGLE:
        records = insertion_records(r, m, e, True, nb)
        revived = revive_ghosts(r, m, records, nb, m.twin[e] != NO_EDGE)
    rec: Index = m.seg[e]
    half: Index = new_record(segs, segs.marker[rec], segs.source[rec], segs.ends[rec, 0], segs.ends[rec, 1])
    v: Index = new_vertex(m, px, py, V_SEGMENT, segs.marker[rec], e0, e1, e0, split, 0.0)
    fill_cavity(r, m, v, n, nb)
    if revived:
        ghosts_made(r, m, v)
    t: Index
    # the halves as edges on the side e was on, v -> d and o -> v, if the fan
    # has them (what find_edge would find: the fan is linked around v)
    eb: Index = -1
    ea: Index = -1
    for j in range(nb):  # the halves: spokes to o and d (edge 2 of (v, o|d, x), edge 1 of (v, x, o|d))
        t = r.fan[j]
        if far >= 0 and m.seg[3 * t] == rec and (m.corner[3 * t + 1] == o or m.corner[3 * t + 1] == d) and (
                m.corner[3 * t + 2] == o or m.corner[3 * t + 2] == d):
            mark_both(m, 3 * t, NO_SEG)  # the thin triangle's o d: an edge now, its pieces the subsegments
        for k in range(1, 3):
            w = m.corner[3 * t + k]
            if w == o or w == d:
                mark_both(m, 3 * t + 3 - k, rec if w == o else half)
                if w == d and k == 1:
                    eb = 3 * t + 2
                elif w == o and k == 2:
                    ea = 3 * t + 1
    m.work[C_SEGMENT_SPLIT] += 1
    m.work[C_STEINER] += 1
    if r.budget > 0:
        r.budget -= 1
    queued: Index = r.log_length
    test_fan(r, m, segs, nb, triangles, False)
    if r.cfg.strategy == TRIANGLE:
        note_born(r, m, records, nb, queued)
    # the halves themselves
    if eb >= 0:
        check_subsegment(r, m, eb)
    if ea >= 0:
        check_subsegment(r, m, ea)
    trace_row(r, T_SEGMENT, nb, n, 0, r.hsize)
    return DONE


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def split_encroached(r: Refiner, m: Mesh, segs: Subsegments, triangles: cython.bint) -> cython.int:
    """Split pooled encroached subsegments until none is left (or the budget
    is spent), in passes over the pool.  Returns DONE, NEED_ROOM, PAUSE
    (every ``PAUSE_EVERY`` steps; call again to go on) or PRECISION."""
    if not r.enc_busy:  # each call starts at the pool's first slot, as Triangle's does
        r.enc_busy = True
        r.enc_cursor = 0
    i: Index
    e: Index
    u: Index
    v: Index
    status: cython.int
    fresh: Index
    ok: cython.bint
    low: cython.bint
    while r.enc_live > 0 and r.budget != 0:
        # over the free slots to the next record, in a loop of its own: the
        # pool is mostly free slots, and each call scans it from the start
        # (from enc_low: la.poly under pq30 has three quarters of the slots
        # a call would scan below its first record)
        i = max(r.enc_cursor, r.enc_low)
        low = i == r.enc_low
        fresh = r.enc_fresh
        while i < fresh and r.enc[i, 0] < 0:
            i += 1
        if low:  # the first record
            r.enc_low = i
        r.enc_cursor = i
        if i >= fresh:  # the next pass
            r.enc_cursor = 0
            continue
        if trace_full(r):
            return NEED_ROOM
        e = enc_edge(r, m, i)
        if e >= 0:
            r.enc[i, 3] = m.stamp[e // 3]
        if e >= 0 and r.acute_slot != i:
            # Triangle looks at the ends before Chew's deletions: a deletion
            # can leave a triangle whose other edge at an end is a
            # subsegment (the hull's, say), which must not turn a midpoint
            # split into a shell split (kept across a NEED_ROOM, when some
            # deletions may be done)
            r.acute = acute_ends(m, e)
            r.acute_slot = i
        if e >= 0 and not r.cfg.diametral:
            u = r.enc[i, 0]
            v = r.enc[i, 1]
            ok = chew_delete(r, m, segs, e)  # (each deletion settles the ghosts: ghosts.deletion_ghosts)
            if not ok:
                return NEED_ROOM
            if m.stamp[e // 3] != r.enc[i, 3] or m.corner[lnext(e)] != u:  # a deletion re-made it
                e = find_edge(m, u, v)
        if e >= 0:  # (else split or gone since it was pooled)
            status = split_subsegment(r, m, segs, e, triangles, r.acute)
            if status != DONE:
                return status
        r.acute_slot = -1
        enc_free(r, i)
        r.enc_cursor = i + 1
        # a pause between two splits (the pool's pass resumes at the cursor):
        # splitting the input's subsegments alone can take the mesh far past
        # the vertex limit between two growths of the arrays (a sliver of
        # near-collinear segments: 1,372,556 vertices for a limit of 1,000,000)
        r.since_pause += 1
        if r.since_pause >= PAUSE_EVERY and r.enc_live > 0 and r.budget != 0:
            r.since_pause = 0
            return PAUSE
    r.enc_busy = False
    return DONE


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _start_edge(m: Mesh, h: Index, px: cython.double, py: cython.double) -> tuple[Index, cython.int, Index]:
    """Where a walk to (px, py) from handle ``h``'s triangle starts, by
    exact orientations: (an edge the point is left of, LOC_FAILED, -1), or
    (-, LOC_BLOCKED, the subsegment or boundary edge the point is across)."""
    k: Index = h
    o: Index
    d: Index
    tw: Index
    for _ in range(3):
        o = m.corner[lnext(k)]
        d = m.corner[lprev(k)]
        m.work[C_ORIENT] += 1
        if orient2d(m.xy[o, 0], m.xy[o, 1], m.xy[d, 0], m.xy[d, 1], px, py) < 0.0:
            tw = m.twin[k]
            if m.seg[k] != NO_SEG or tw == NO_EDGE or is_ghost(m, tw // 3):
                return h, LOC_BLOCKED, k
            return tw, LOC_FAILED, -1
        k = lnext(k)
    return h, LOC_FAILED, -1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _side_of(m: Mesh, e: Index, px: cython.double, py: cython.double) -> cython.double:
    """The side of edge ``e`` the point (px, py) lies on, as orient2d's sign
    (exact): negative right of it, zero on its line.  A check Triangle does
    not make, so not counted among the orientation tests."""
    o: Index = m.corner[lnext(e)]
    d: Index = m.corner[lprev(e)]
    return orient2d(m.xy[o, 0], m.xy[o, 1], m.xy[d, 0], m.xy[d, 1], px, py)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _collapsed(m: Mesh, h: Index, px: cython.double, py: cython.double) -> Index:
    """The shortest edge of handle ``h``'s triangle if the point (px, py)
    is not strictly on the triangle's side of it, else -1.

    The angle opposite the shortest edge is the smallest, below 60 degrees,
    so the circumcenter and every off-center (on the edge's bisector, between
    its midpoint and the circumcenter) lie strictly on the triangle's side.
    A point that is not has been rounded there: the edge is so short next to
    its coordinates (4e-13 long at y = 1e180, where the next double is 1e164
    away) that the bisector's offset is lost, the point lands on the edge
    itself, and the split leaves two triangles of the same shape, forever.
    Edges are compared as scaled vectors (powers of two), so that squares
    neither overflow nor vanish beside the triangle's longest edge; with
    every component within 2^+-160 the squares are exact multiples of the
    scaled ones, so no scaling is needed to compare them (the ordinary
    case: a call of unit_scale and six products the fewer)."""
    a: Index = m.corner[h]  # apex
    b: Index = m.corner[lnext(h)]  # org
    c: Index = m.corner[lprev(h)]  # dest
    bcx: cython.double = m.xy[c, 0] - m.xy[b, 0]
    bcy: cython.double = m.xy[c, 1] - m.xy[b, 1]
    cax: cython.double = m.xy[a, 0] - m.xy[c, 0]
    cay: cython.double = m.xy[a, 1] - m.xy[c, 1]
    abx: cython.double = m.xy[b, 0] - m.xy[a, 0]
    aby: cython.double = m.xy[b, 1] - m.xy[a, 1]
    bcx, bcy, cax, cay, abx, aby = scaled_triple(bcx, bcy, cax, cay, abx, aby, 2.0**160)
    la: cython.double = bcx * bcx + bcy * bcy  # opposite a: edge h
    lb: cython.double = cax * cax + cay * cay  # opposite b: edge lnext(h)
    lc: cython.double = abx * abx + aby * aby  # opposite c: edge lprev(h)
    edge: Index = h
    if lb < la and lb <= lc:
        edge = lnext(h)
    elif lc < la and lc < lb:
        edge = lprev(h)
    u: Index = m.corner[lnext(edge)]
    v: Index = m.corner[lprev(edge)]
    if orient2d(m.xy[u, 0], m.xy[u, 1], m.xy[v, 0], m.xy[v, 1], px, py) > 0.0:
        return -1
    return edge


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _needle(m: Mesh, e: Index) -> cython.bint:
    """The angle opposite edge ``e`` (its triangle's shortest edge: the
    smallest angle) has a sine below 2^-26 (1e-6 degrees).  The two edges
    at that angle are the longer ones, within a factor 2 of each other, so
    one power-of-two scale keeps both squares in range."""
    a: Index = m.corner[e]
    u: Index = m.corner[lnext(e)]
    v: Index = m.corner[lprev(e)]
    ux: cython.double = m.xy[u, 0] - m.xy[a, 0]
    uy: cython.double = m.xy[u, 1] - m.xy[a, 1]
    vx: cython.double = m.xy[v, 0] - m.xy[a, 0]
    vy: cython.double = m.xy[v, 1] - m.xy[a, 1]
    ux, uy, vx, vy = scaled_pair(ux, uy, vx, vy, 2.0**240)
    return fabs(orient2d(0.0, 0.0, ux, uy, vx, vy)) < 2.0**-26 * sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy))


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _reject_at(r: Refiner, m: Mesh, e: Index, steps: cython.longlong) -> cython.int:
    """Reject a Steiner point that lies on or across edge ``e`` (its walk
    stopped there, or it rounded onto it): where ``e`` is a subsegment the
    point encroaches it, and it is pooled if it may be split.  DONE, or
    NEED_ROOM (nothing changed)."""
    if m.seg[e] != NO_SEG and may_split(r, m, e):
        if r.enc_live + 1 > r.enc.shape[0]:
            step_undone(r, m.work)
            return NEED_ROOM
        enc_push(r, m, e)
    m.work[C_REJECTED] += 1
    trace_row(r, T_REJECTED, 0, 0, steps, r.hsize)
    return DONE


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def split_bad_triangle(r: Refiner, m: Mesh, segs: Subsegments, h: Index) -> cython.int:
    """Insert the off-center or circumcenter of handle ``h``'s triangle
    unless it is across a subsegment or encroaches one (then the subsegment
    is pooled).  A point that cannot be placed strictly inside its cavity
    (on a vertex, or rounded onto or across an edge) leaves the triangle
    unsplit.  Returns DONE, NEED_ROOM (nothing changed) or PRECISION (the
    point rounded onto the triangle's shortest edge, that edge is not a
    subsegment, which it would encroach, and the triangle is a needle: see
    _collapsed and _needle)."""
    step_begins(r, m.work)
    t: Index = h // 3
    px: cython.double
    py: cython.double
    xi: cython.double
    eta: cython.double
    off: cython.bint
    a: Index
    b: Index
    c: Index
    steps0: cython.longlong
    status: cython.int
    e: Index
    start: Index
    steps: cython.longlong
    bad_edge: Index = -1
    side: cython.double
    finite: cython.bint
    for attempt in range(2):
        px, py, xi, eta, off = steiner_point(r, m, h)
        m.work[C_CIRCUMCENTER] += 1
        a = m.corner[h]  # apex
        b = m.corner[lnext(h)]  # org
        c = m.corner[lprev(h)]  # dest
        if px != px or py != py:  # NaN
            m.work[C_DUPLICATE] += 1
            return DONE
        if (
            (px == m.xy[a, 0] and py == m.xy[a, 1])
            or (px == m.xy[b, 0] and py == m.xy[b, 1])
            or (px == m.xy[c, 0] and py == m.xy[c, 1])
        ):
            # on a corner: rounded there, as no off-center or circumcenter
            # lies at one.  On an end of the shortest edge it is that edge's
            # collapse (below): computed again from the edge's ends, or
            # PRECISION for a needle (skipped otherwise).  (Skipped as a duplicate, the needle (0.00149, 0)
            # (0.00149, 2^-1022) (1.05e-5, 2^-149) stayed in a mesh returned
            # under q10 with its 0-degree angle.)  Elsewhere (the far corner)
            # the split is skipped, as Triangle skips a duplicate vertex.
            bad_edge = _collapsed(m, h, px, py)
            if bad_edge < 0:
                m.work[C_DUPLICATE] += 1
                return DONE
            if bad_edge == h:
                break
            h = bad_edge
            continue
        steps0 = m.work[C_WALK]
        # Triangle's walk from the handle, or from the edge before it when that
        # puts the point on the inner side of the first edge
        start = lprev(h) if eta < xi else h
        status = LOC_FAILED
        e = -1
        finite = fabs(xi) <= 1.7976931348623157e308 and fabs(eta) <= 1.7976931348623157e308
        side = _side_of(m, start, px, py) if finite else 0.0
        if not finite or side < 0.0:
            # NaN parameters (a needle spanning 1e-304 .. 1e300), or finite ones
            # that rounding has made meaningless (1e17 for a triangle with sides
            # from 1e-306 to 1e-304, which picked an edge the off-center lay
            # across): the walk needs the point left of its first edge (else it
            # finds it "inside" the triangle it lies outside of, and the new
            # vertex's fan folds over that edge), and an off-center can lie
            # across any edge of its triangle, even a subsegment (outside the
            # domain)
            start, status, e = _start_edge(m, h, px, py)
            side = 0.0  # (the new start's side: asked below if the walk stays there)
        if status != LOC_BLOCKED:
            status, e = precise_walk(m, start, px, py, m.stamp.shape[0] + 64)
        if status == LOC_FAILED:
            status, e = line_walk(m, t, px, py, 4 * m.stamp.shape[0] + 64)
        steps = m.work[C_WALK] - steps0
        # outside its own triangle (rare), or on the line of the edge the walk
        # started from (which the walk does not test, and calls inside): make
        # sure rounding has not put the point on or behind the shortest edge,
        # which no off-center or circumcenter is (see _collapsed); such a
        # split makes the same bad triangle again, smaller, without end.  (14
        # points under q10 with two of them 2^-1022 apart on the line x =
        # 0.00149: every needle's off-center, computed again from its
        # shortest edge's ends, rounded onto that edge, the walk from it
        # called the point inside, and the edge was halved over and over,
        # toward the 2^52 doubles between the two: no mesh of doubles has a
        # 10-degree angle there, regressions/denormal-needle-midpoint-precision.json)
        bad_edge = -1
        if not (status == LOC_INSIDE and e // 3 == t) or (
            status == LOC_INSIDE and e == start and side == 0.0 and _side_of(m, start, px, py) == 0.0
        ):
            bad_edge = _collapsed(m, h, px, py)
        if bad_edge < 0 or bad_edge == h:
            break
        # computed from a corner far from the shortest edge (0.5 beside an edge
        # 1.5e-38 long near 1e-38), the point lost its offset from that edge:
        # once more from the edge's own ends (the same point, other roundings;
        # Triangle meshes such triangles)
        h = bad_edge
    if bad_edge >= 0 and m.seg[bad_edge] != NO_SEG:
        # rounded onto (or across) a subsegment: the point encroaches it, as
        # Triangle finds (its walk stops there), so the subsegment is split
        # where it may be and the point rejected.  Under -Y a hull subsegment
        # stays whole and so does its triangle: the points (2^-126, 1)
        # (1.5 * 2^-399, 1) (3.66e-4, 0.125) under q25Y, one triangle, as
        # Triangle's (regressions/hull-needle-rounds-onto-subsegment.json)
        return _reject_at(r, m, bad_edge, 0)
    if bad_edge >= 0 and not _needle(m, bad_edge):
        # no double lies off the shortest edge (an ulp or two long): the
        # point rounded onto an end of it (Triangle frees a new vertex equal
        # to a corner of its triangle as a duplicate) or onto or across its
        # line (Triangle inserts it there, which makes the same triangle
        # again).  Skipped as a duplicate: the triangle stays, with its
        # angle of a few degrees.  Two segments crossing at 5 degrees near
        # 2^-101, a free vertex 2e-48 from the crossing within rounding of
        # one of them: their pieces are halved towards the crossing down to
        # ulps, the triangles between them down to ulp-sized ones (as
        # Triangle's), and refinement ran out of precision where Triangle
        # meshes (regressions/concurrent-crossings-vertex-on-segment-precision.json).
        # A needle (the angle zero to 1e-6 degrees, whose shortest edge has
        # no double between its ends) is not returned so: out of precision
        m.work[C_DUPLICATE] += 1
        return DONE
    if bad_edge >= 0:
        r.error_org = m.corner[lnext(bad_edge)]
        r.error_dest = m.corner[lprev(bad_edge)]
        r.error_apex = m.corner[bad_edge]
        return PRECISION
    if status == LOC_BLOCKED or (status == LOC_ON_EDGE and m.seg[e] != NO_SEG):
        return _reject_at(r, m, e, steps)
    if status == LOC_ON_VERTEX or (status != LOC_INSIDE and status != LOC_ON_EDGE):
        m.work[C_DUPLICATE] += 1
        return DONE
    start: Index = e // 3
    second: Index = -1
    if status == LOC_ON_EDGE and m.twin[e] != NO_EDGE:
        second = m.twin[e] // 3
    n: Index
    nb: Index
    n, nb = collect_cavity(r, m, px, py, start, second, -1)
    if not has_room(r, m, nb) or not ghost_room(r, nb):
        forget_cavity(r, m, n)
        step_undone(r, m.work)
        return NEED_ROOM
    # Triangle's flips circle the new vertex from the located edge's origin
    # (its destination when the point is on it)
    order_rim(r, m, nb, m.corner[lprev(e)] if status == LOC_ON_EDGE else m.corner[lnext(e)])
    # a point inside a subsegment's lens is rejected; the subsegment is split
    encroached: Index = 0
    k: Index
    for j in range(nb):  # in the rim's order
        k = r.fan[j]
        if r.bnd[k, 3] != NO_SEG and queue_side(r, m, r.bnd[k, 4], in_lens(r, m, r.bnd[k, 1], r.bnd[k, 2], px, py)):
            encroached += 1
    if encroached:
        ghosts: cython.bint = r.cfg.strategy == TRIANGLE
        bounds: cython.bint = m.area_bound.shape[0] > 0
        if (ghosts or bounds) and rejected_fan_records(r, m, e, status == LOC_ON_EDGE, nb):
            if ghosts:
                queue_rejected_fan(r, m, segs, nb, px, py)  # Triangle queued them before it rejected the point
            if bounds:
                rejected_bounds(r, m, e, status == LOC_ON_EDGE)  # its flips' means stay
        forget_cavity(r, m, n)
        m.work[C_REJECTED] += 1
        m.work[C_UNDONE] += nb
        trace_row(r, T_REJECTED, 0, 0, steps, r.hsize)
        return DONE
    # The fan must be counter-clockwise: the point strictly left of every rim
    # edge (exact).  With the start edge checked above the walk's answer is
    # exact, and the cavity of a constrained Delaunay mesh is star-shaped
    # from a point inside it, so this holds unless the point lies on the
    # start edge's own line (the walk then calls it inside the triangle) or
    # the mesh is not exactly constrained Delaunay (_split_at_apex flips with
    # orientation tests only).  Should either put the point on or across a
    # rim edge, or on a rim vertex, the triangle stays unsplit (a Steiner
    # point that could not be placed, counted with those that fell on a
    # vertex) and refinement goes on with a valid mesh.  Triangle makes no
    # such test: these orientations are not counted.
    for j in range(nb):
        if orient2d(px, py, m.xy[r.bnd[j, 1], 0], m.xy[r.bnd[j, 1], 1], m.xy[r.bnd[j, 2], 0], m.xy[r.bnd[j, 2], 1]) <= 0.0:
            forget_cavity(r, m, n)
            m.work[C_DUPLICATE] += 1
            return DONE
    # Triangle's records through the insertion, for a deletion of this
    # vertex (ghosts.note_born).  This vertex takes the vertex record of a
    # point rejected just before (under -Y/-YY nothing is split after one),
    # and Triangle serves again that point's queued triangles it remakes in
    # their records (ghosts.revive_ghosts): la.poly under pq30YYa4.79 splits
    # one so, and the rq34YY regression (free-vertex-revival) parts without.
    # The entries so served are split whether bad or not, and their points
    # mostly rejected, each queueing its fan for the next vertex made: on
    # the corpus's trimesh.poly under pq30YY Triangle rejects 176,300 points
    # for 234 vertices, 158,000 of them after its last vertex, all served
    # from the 6,358 points rejected before it.  The loop is bounded as
    # Triangle's is: between two vertices made, only entries live when the
    # first was made can be served (a rejected point's wait for the next),
    # so each run of rejections ends, and vertices are bounded as before.
    records: cython.bint = False
    revived: cython.bint = False
    if r.cfg.strategy == TRIANGLE:
        records = insertion_records(r, m, e, status == LOC_ON_EDGE, nb)
        revived = revive_ghosts(r, m, records, nb, status != LOC_ON_EDGE or m.twin[e] != NO_EDGE)
    # attributes: barycentric in (org, dest, apex)
    v: Index = new_vertex(m, px, py, V_FREE, 0, b, c, a, xi, eta)
    fill_cavity(r, m, v, n, nb)
    if revived:
        ghosts_made(r, m, v)
    m.work[C_STEINER] += 1
    if r.budget > 0:
        r.budget -= 1
    queued: Index = r.log_length
    test_fan(r, m, segs, nb, True, True)  # (the point is in no rim subsegment's lens: tested above)
    if r.cfg.strategy == TRIANGLE:
        note_born(r, m, records, nb, queued)
    trace_row(r, T_OFFCENTER if off else T_CIRCUMCENTER, nb, n, steps, r.hsize)
    return DONE


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def check_subsegments(r: Refiner, m: Mesh, edges: cython.longlong[::1]) -> cython.void:
    """Pool the encroached ones of subsegment ``edges``; the caller made
    room for all of them."""
    for i in range(edges.shape[0]):
        check_subsegment(r, m, edges[i])


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def refine(r: Refiner, m: Mesh, segs: Subsegments) -> cython.int:
    """Triangle's refinement loop, resumable: returns DONE, NEED_ROOM (grow the
    arrays and call again), PAUSE (call again) or PRECISION."""
    status: cython.int
    t: Index
    stamp: cython.longlong
    i: Index
    live: Index
    while True:
        if r.phase == 0:  # encroached subsegments of the input
            status = split_encroached(r, m, segs, False)
            if status != DONE:
                return status
            r.phase = 1
        if r.phase == 1:  # every triangle's quality
            if r.hkey.shape[0] < m.nslot + 16:
                return NEED_ROOM
            queue_clear(r)
            if r.cfg.strategy == TRIANGLE:
                records_known(r, m)
            for tt in range(m.nslot):
                if m.stamp[tt] > 0:
                    test_triangle(r, m, segs, tt)
            r.phase = 2
        if trace_full(r):
            return NEED_ROOM
        if r.current >= 0:  # the popped triangle (again after a NEED_ROOM)
            if queue_used(r) + 1 > r.hkey.shape[0]:  # room to queue it again
                r.need = max(r.need, 1)
                return NEED_ROOM
            t = r.current
            stamp = r.current_stamp
            if m.stamp[t] == stamp:
                status = split_bad_triangle(r, m, segs, 3 * t)
                if status != DONE:
                    return status
            r.current = -1
            if r.enc_live > 0:  # split the subsegments first, then try again
                # (room: checked above, and a split leaves two spare)
                queue_push(r, r.current_key, t, stamp)
                if r.cfg.strategy == TRIANGLE:
                    requeued(r, t)
                status = split_encroached(r, m, segs, True)
                if status != DONE:
                    return status
        if r.enc_live > 0:
            status = split_encroached(r, m, segs, True)
            if status != DONE:
                return status
        if r.hsize == 0 or r.budget == 0:
            return DONE
        # compact when stale entries outnumber live triangles (never because
        # the queue is full: that would make the counts and the trace depend
        # on how much room it started with; a full queue grows instead)
        live = m.nlive
        if queue_used(r) > max(r.compact_at, 2 * live + 4096):
            queue_compact(r, m)
            r.compact_at = 2 * queue_used(r) + 4096  # amortised: never twice in a row
            if r.hsize == 0:
                # every entry left was stale: hsize counted them until now,
                # and popping an empty queue read before the bucket table
                # (5 points from 1e-303 to 1e300 under q25n crashed)
                return DONE
        # Pop to the next current entry.  Most entries are stale (la.poly:
        # 2,026 of 2,696), and a stale pop changes nothing the checks above
        # read but the queue's size: pop again here, without them.
        while True:
            if r.since_pause >= PAUSE_EVERY:
                r.since_pause = 0
                return PAUSE
            r.since_pause += 1
            i = queue_pop(r)
            t = r.htri[i]
            stamp = r.hstamp[i]
            if t < 0:  # a rejected insertion's entry: its triangle, if remade (queues.ghost_slot)
                t = ghost_slot(r, m, -1 - t)
                stamp = m.stamp[t] if t >= 0 else 0
            m.work[C_QUEUE_POP] += 1
            if t >= 0 and m.stamp[t] == stamp:
                break
            m.work[C_STALE_POP] += 1
            if r.hsize == 0:
                return DONE
        r.current_key = r.hkey[i]
        r.current = t
        r.current_stamp = stamp


def tally_encroached(r: Refiner, m: Mesh, segs: Subsegments) -> None:
    """Pool every encroached subsegment, in the order the subsegments were
    made (Triangle's pool order), each edge once."""
    first = filled(segs.count, -1, np.int64)
    check_subsegments(r, m, first[: first_side(m, segs, first)])


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def first_side(m: Mesh, segs: Subsegments, first: cython.longlong[::1]) -> Index:
    """One side of each live subsegment record, in record order, in
    ``first[:n]``; returns n.  The side is the lowest edge number among the
    record's sides that run along its ends (the edge it was made on) or
    have no twin (the only side).  ``first`` comes filled with -1, one row
    per record: each record's side is found in its row, and the rows found
    are then moved up in place (done here, in one pass, rather than by
    numpy's mask and copy: those were a tenth of a one-triangle run's
    refinement set-up)."""
    t: Index
    k: Index
    rec: Index
    org: Index
    dest: Index
    a: Index
    b: Index
    along: cython.bint
    for e in range(3 * m.nslot):
        rec = m.seg[e]
        t = e // 3
        if rec == NO_SEG or m.stamp[t] <= 0 or first[rec] >= 0:
            continue
        k = e - 3 * t
        org = m.corner[3 * t + (k + 1) % 3]
        dest = m.corner[3 * t + (k + 2) % 3]
        a = segs.ends[rec, 0]
        b = segs.ends[rec, 1]
        # (scaled: at 2^-540 the products vanished, no side was along, and no
        # interior subsegment was ever tested for encroachment)
        along = scaled_dot(m.xy[dest, 0] - m.xy[org, 0], m.xy[dest, 1] - m.xy[org, 1], m.xy[b, 0] - m.xy[a, 0], m.xy[b, 1] - m.xy[a, 1]) > 0.0
        if along or m.twin[e] == NO_EDGE:
            first[rec] = e
    n: Index = 0
    for rec in range(first.shape[0]):
        if first[rec] >= 0:
            first[n] = first[rec]
            n += 1
    return n
