# cython: language_level=3
"""What makes a triangle bad, and where a bad triangle is split.

A triangle is bad (Triangle's ``testtriangle``) when it is larger than the
fixed area bound (``-a<A>``), than its own bound (a bare ``-a``), fails
Triangle's sample user test (``-u``), or has an angle below the minimum
(``-q``) -- unless its shortest edge joins two segment vertices at the same
distance from the vertex where their segments meet (Miller, Pav and
Walkington's exemption for small input angles).  A bad triangle is queued
under the strategy's key (order.py) and split at its off-center (when
closer) or circumcenter (``steiner_point``).
"""

from __future__ import annotations

import math

import cython
from cython.cimports.instrument.core.mesh import NO_SEG, V_FREE, V_SEGMENT, Index, Mesh, lnext, lprev, next_random
from cython.cimports.instrument.core.navigate import edge_around, origin_edge
from cython.cimports.instrument.core.predicates import orient2d
from cython.cimports.instrument.core.scaling import scaled_pair, unit_scale
from cython.cimports.libc.math import fabs, frexp
from cython.cimports.instrument.core.subsegments import Subsegments
from cython.cimports.instrument.refine.cavity import collect_cavity, forget_cavity, inherited
from cython.cimports.instrument.refine.encroach import check_subsegment, queue_side
from cython.cimports.instrument.refine.order import ADVERSARY, LARGEST, RANDOM, SMALLEST, TOP_BUCKET, TRIANGLE, priority, triangle_bucket, wide_bucket
from cython.cimports.instrument.refine.queues import bucket_make_ready, queue_push, queue_push_ghost
from cython.cimports.instrument.refine.state import Refiner

_INF = cython.declare(cython.double, float("inf"))

#: A triangle whose shortest edge is below this fraction of its longest is a
#: needle (an angle below 2^-299 radians): split at its off-center, computed
#: from that edge's ends (steiner_point).
NEEDLE = cython.declare(cython.double, 2.0**-300)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _shape_scaled(
    bcx: cython.double, bcy: cython.double, cax: cython.double, cay: cython.double, abx: cython.double,
    aby: cython.double, a: Index, b: Index, c: Index, f: cython.double, circ: cython.bint,
) -> tuple[cython.double, cython.double, cython.double, cython.double, Index, Index]:
    """``_shape`` from the edge vectors (b - c, c - a, a - b) scaled by the
    power of two ``f``; the results in the mesh's units."""
    bcx *= f
    bcy *= f
    cax *= f
    cay *= f
    abx *= f
    aby *= f
    la: cython.double = bcx * bcx + bcy * bcy
    lb: cython.double = cax * cax + cay * cay
    lc: cython.double = abx * abx + aby * aby
    u: Index
    v: Index
    mn: cython.double
    l1: cython.double
    l2: cython.double
    dot: cython.double
    if la < lb and la < lc:  # smallest angle at a: a->b, a->c
        u, v, mn, l1, l2 = b, c, la, lb, lc
        dot = -(abx * cax + aby * cay)
    elif lb < lc:  # smallest angle at b: b->c, b->a
        u, v, mn, l1, l2 = c, a, lb, lc, la
        dot = -(bcx * abx + bcy * aby)
    else:  # shortest a-b, smallest angle at c: vectors c->a, c->b
        u, v, mn, l1, l2 = a, b, lc, la, lb
        dot = -(cax * bcx + cay * bcy)
    cos2: cython.double = dot * dot / (l1 * l2)
    if dot < 0.0:
        cos2 = -cos2
    area2: cython.double = aby * cax - abx * cay  # (b - a) x (c - a)
    circ2: cython.double = 0.0
    if circ:
        circ2 = la * lb * lc / (area2 * area2) / 4.0 if area2 != 0.0 else _INF
    g: cython.double = 1.0 / (f * f) if f <= 2.0**511 and f >= 2.0**-511 else 0.0
    if g == 0.0:  # 1/f^2 is no double: scale back in two steps
        return mn / f / f, cos2, area2 / f / f, circ2 / f / f, u, v
    return mn * g, cos2, area2 * g, circ2 * g, u, v


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _shape(m: Mesh, a: Index, b: Index, c: Index, circ: cython.bint) -> tuple[cython.double, cython.double, cython.double, cython.double, Index, Index]:
    """Squared shortest edge, cos^2 of the smallest angle, twice the area,
    squared circumradius (only if ``circ``, else 0: a division that only the
    circumradius orders need, see ``_needs_circumradius``), and the shortest
    edge's end vertices.

    cos^2 is of degree 4 over degree 4 and the circumradius of degree 6 over
    4: with edges beyond about 2^160 or below 2^-160 the products overflow
    or leave the normal range (at 2^300 every triangle looked perfect, and
    meshes kept 26-degree angles under q30).  There the edge vectors are
    scaled by an exact power of two first (``unit_scale``), the degree-0
    cos^2 is used as it is and the rest is scaled back; in range nothing
    changes."""
    bcx: cython.double = m.xy[b, 0] - m.xy[c, 0]
    bcy: cython.double = m.xy[b, 1] - m.xy[c, 1]
    cax: cython.double = m.xy[c, 0] - m.xy[a, 0]
    cay: cython.double = m.xy[c, 1] - m.xy[a, 1]
    abx: cython.double = m.xy[a, 0] - m.xy[b, 0]
    aby: cython.double = m.xy[a, 1] - m.xy[b, 1]
    la: cython.double = bcx * bcx + bcy * bcy  # opposite a
    lb: cython.double = cax * cax + cay * cay
    lc: cython.double = abx * abx + aby * aby
    # The range test is on the largest component, ``big`` in [2^-160, 2^160].
    # The longest squared edge in [2^-319, 2^320] implies it (big^2 is at most
    # that square, rounded, and at least half of it; each bound a power of
    # two, rounding cannot cross it), so the squares the test needs anyway
    # settle it for every ordinary triangle, and ``big`` (eleven operations
    # on every test) is taken only outside that range.
    longest: cython.double = max(max(la, lb), lc)
    big: cython.double
    if not (longest <= 2.0**320 and longest >= 2.0**-319):
        big = max(max(max(fabs(bcx), fabs(bcy)), max(fabs(cax), fabs(cay))), max(fabs(abx), fabs(aby)))
        if not (big <= 2.0**160 and big >= 2.0**-160):
            return _shape_scaled(bcx, bcy, cax, cay, abx, aby, a, b, c, unit_scale(big), circ)
    u: Index
    v: Index
    mn: cython.double
    l1: cython.double
    l2: cython.double
    dot: cython.double
    # the dot products of the two edges at the smallest angle, from the edge
    # vectors (negating is exact: the same roundings as from the coordinates).
    # Ties go as in Triangle's testtriangle, whose handle is (org b, dest c,
    # apex a): the edge opposite the apex first, then the one opposite the
    # org, then the dest.  (Tested c's edge first, ours took another of two
    # equal edges: in the 12-point star, step 4, under q30, the isosceles
    # triangle (0.19587, 0.61309) (0.25, 0.61309) (0.22294, 0.62871) has two
    # edges of one length, one a subsegment and the other joining two
    # segments on one shell about their crossing; Triangle takes the
    # subsegment and splits the triangle, ours took the other and exempted
    # it: 266 vertices against Triangle's 267.)
    if la < lb and la < lc:  # at a: a->b, a->c
        u, v, mn, l1, l2 = b, c, la, lb, lc
        dot = -(abx * cax + aby * cay)
    elif lb < lc:  # at b: b->c, b->a
        u, v, mn, l1, l2 = c, a, lb, lc, la
        dot = -(bcx * abx + bcy * aby)
    else:  # shortest a-b, smallest angle at c: c->a, c->b
        u, v, mn, l1, l2 = a, b, lc, la, lb
        dot = -(cax * bcx + cay * bcy)
    cos2: cython.double = dot * dot / (l1 * l2)
    if dot < 0.0:  # an obtuse smallest angle cannot happen; keep the sign meaningful
        cos2 = -cos2
    area2: cython.double = aby * cax - abx * cay  # (b - a) x (c - a)
    circ2: cython.double = 0.0
    if circ:
        circ2 = la * lb * lc / (area2 * area2) / 4.0 if area2 != 0.0 else _INF
    return mn, cos2, area2, circ2, u, v


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _needs_circumradius(r: Refiner) -> cython.bint:
    """Only the circumradius orders key the queue on it (order.priority)."""
    return r.cfg.strategy == LARGEST or r.cfg.strategy == SMALLEST


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _segment_of(m: Mesh, v: Index) -> Index:
    """The record of some subsegment at vertex ``v`` (-1 if none)."""
    e0: Index = origin_edge(m, v)
    e: Index = edge_around(m, e0, -1) if e0 >= 0 else -1
    return m.seg[e] if e >= 0 else -1


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _same(m: Mesh, u: Index, v: Index) -> cython.bint:
    return m.xy[u, 0] == m.xy[v, 0] and m.xy[u, 1] == m.xy[v, 1]


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _small_input_angle(m: Mesh, segs: Subsegments, u: Index, v: Index) -> cython.bint:
    """Miller, Pav and Walkington's exemption: the shortest edge ``u v`` joins
    two segment vertices on segments that meet at a vertex J, at nearly the
    same distance from J (the same concentric shell)."""
    if m.vtype[u] != V_SEGMENT or m.vtype[v] != V_SEGMENT:
        return False
    s1: Index = _segment_of(m, u)
    s2: Index = _segment_of(m, v)
    if s1 < 0 or s2 < 0:
        return False
    a1: Index = segs.ends[s1, 0]
    b1: Index = segs.ends[s1, 1]
    a2: Index = segs.ends[s2, 0]
    b2: Index = segs.ends[s2, 1]
    # a shared end, compared by coordinates in either direction.  Triangle
    # finds each segment by rotating about the end away from the triangle
    # to its first subsegment, and compares d1 = o2 or o1 = d2 as read from
    # that side; both rotations find the halves on the same side of the
    # edge (towards J or away from it), and its records hold their ends in
    # the direction they run along the line (a split's and a crossing's
    # halves too), so one end reads J as the org and the other as the dest
    # whenever the segments share it.  (Checked under q30 on 45 stars {n/k}
    # (7 <= n <= 19) whose meshes are Triangle's: of 3,040 triangles below
    # 30 degrees that this test exempts, Triangle's -VVV queued none;
    # models in which one half of a crossing holds J the other way part
    # from Triangle within 55 splits on the 12-point star, step 4.)
    j: Index = -1
    if _same(m, b1, a2) or _same(m, b1, b2):
        j = b1
    elif _same(m, a1, b2) or _same(m, a1, a2):
        j = a1
    if j < 0:
        return False
    ux: cython.double = m.xy[u, 0] - m.xy[j, 0]
    uy: cython.double = m.xy[u, 1] - m.xy[j, 1]
    vx: cython.double = m.xy[v, 0] - m.xy[j, 0]
    vy: cython.double = m.xy[v, 1] - m.xy[j, 1]
    # squares overflow beyond 2^511 (inf < inf: no exemption) and vanish
    # below 2^-537: out of range, compare the vectors scaled by a power of two
    ux, uy, vx, vy = scaled_pair(ux, uy, vx, vy, 2.0**240)
    d1: cython.double = ux * ux + uy * uy
    d2: cython.double = vx * vx + vy * vy
    return 0.999 * d2 < d1 < 1.001 * d2


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def builtin_unsuitable(m: Mesh, o: Index, d: Index, a: Index) -> cython.bint:
    """Triangle's sample ``triunsuitable``: the longest edge squared exceeds
    0.05 (x^2 + y^2) + 0.02 at the origin vertex ``o``."""
    od: cython.double = (m.xy[o, 0] - m.xy[d, 0]) * (m.xy[o, 0] - m.xy[d, 0]) + (m.xy[o, 1] - m.xy[d, 1]) * (m.xy[o, 1] - m.xy[d, 1])
    da: cython.double = (m.xy[d, 0] - m.xy[a, 0]) * (m.xy[d, 0] - m.xy[a, 0]) + (m.xy[d, 1] - m.xy[a, 1]) * (m.xy[d, 1] - m.xy[a, 1])
    ao: cython.double = (m.xy[a, 0] - m.xy[o, 0]) * (m.xy[a, 0] - m.xy[o, 0]) + (m.xy[a, 1] - m.xy[o, 1]) * (m.xy[a, 1] - m.xy[o, 1])
    return max(od, da, ao) > 0.05 * (m.xy[o, 0] * m.xy[o, 0] + m.xy[o, 1] * m.xy[o, 1]) + 0.02


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _needle_circumcenter(
    px: cython.double, py: cython.double, qx: cython.double, qy: cython.double, wx: cython.double, wy: cython.double,
) -> tuple[cython.double, cython.double]:
    """The circumcenter of a needle whose short edge is p q, apex w: the
    midpoint of p q plus k times the edge turned left, with k from the
    apex's vector u = w - p and the edge e = q - p each scaled by its own
    power of two (``g``, ``h``), so that no product leaves the doubles'
    range however far apart the two scales are:
    k = (|u|^2 - u.e) / (2 e x u) = (|u_s|^2 / g - u_s.e_s / h) / (2 e_s x u_s).
    Infinite or NaN where the circumcenter is beyond the doubles."""
    ex: cython.double = qx - px
    ey: cython.double = qy - py
    ux: cython.double = wx - px
    uy: cython.double = wy - py
    h: cython.double = unit_scale(max(fabs(ex), fabs(ey)))
    g: cython.double = unit_scale(max(fabs(ux), fabs(uy)))
    esx: cython.double = ex * h
    esy: cython.double = ey * h
    usx: cython.double = ux * g
    usy: cython.double = uy * g
    k: cython.double = ((usx * usx + usy * usy) / g - (usx * esx + usy * esy) / h) / (2.0 * orient2d(esx, esy, usx, usy, 0.0, 0.0))
    return px + 0.5 * ex - k * esy, py + 0.5 * ey + k * esx


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def steiner_point(r: Refiner, m: Mesh, h: Index) -> tuple[cython.double, cython.double, cython.double, cython.double, cython.bint]:
    """The off-center (when closer) or circumcenter of the triangle of
    handle ``h`` (an edge: org, dest, apex as ``mesh`` defines them), and
    its barycentric parameters (xi, eta) relative to (org, dest, apex), and
    whether it is the off-center.

    Computed from the handle's corners in Triangle's order: a bad triangle
    is split from handle ``3 t`` (apex at corner 0, where an insertion puts
    the new vertex, as in the handle Triangle queues), which gives Triangle's
    rounding, so the same Steiner points."""
    o: Index = m.corner[lnext(h)]
    d: Index = m.corner[lprev(h)]
    a: Index = m.corner[h]
    ox: cython.double = m.xy[o, 0]
    oy: cython.double = m.xy[o, 1]
    xdo: cython.double = m.xy[d, 0] - ox
    ydo: cython.double = m.xy[d, 1] - oy
    xao: cython.double = m.xy[a, 0] - ox
    yao: cython.double = m.xy[a, 1] - oy
    xda: cython.double = m.xy[d, 0] - m.xy[a, 0]
    yda: cython.double = m.xy[d, 1] - m.xy[a, 1]
    # The circumcenter is of degree 3 over 2: with edges beyond 2^160 or
    # below 2^-160 its products overflow or leave the normal range.  There
    # the edge vectors are scaled by an exact power of two f (identical
    # roundings, as no product leaves the range then) and the offset
    # scaled back at the end; in range f is 1 and nothing changes.
    f: cython.double = 1.0
    xdo0: cython.double = xdo  # unscaled, for an off-center (see below)
    ydo0: cython.double = ydo
    xao0: cython.double = xao
    yao0: cython.double = yao
    xda0: cython.double = xda
    yda0: cython.double = yda
    big: cython.double = max(max(fabs(xdo), fabs(ydo)), max(fabs(xao), fabs(yao)))
    if not (big <= 2.0**160 and big >= 2.0**-160) and big > 0.0:
        f = unit_scale(big)
        xdo *= f
        ydo *= f
        xao *= f
        yao *= f
        xda *= f
        yda *= f
    dodist: cython.double = xdo * xdo + ydo * ydo
    aodist: cython.double = xao * xao + yao * yao
    dadist: cython.double = xda * xda + yda * yda
    denom: cython.double
    if f == 1.0:
        denom = 0.5 / orient2d(m.xy[d, 0], m.xy[d, 1], m.xy[a, 0], m.xy[a, 1], ox, oy)
    else:
        denom = 0.5 / orient2d(xdo, ydo, xao, yao, 0.0, 0.0)
    dx: cython.double = (yao * dodist - ydo * aodist) * denom
    dy: cython.double = (xdo * aodist - xao * dodist) * denom
    off: cython.bint = False
    c: cython.double = r.cfg.off_constant
    fx: cython.double
    fy: cython.double
    ex: cython.double
    ey: cython.double
    which: cython.int = 0  # the off-center's edge: 1 o-d, 2 o-a, 3 d-a
    # A needle whose circumcenter is beyond the doubles (its area vanished
    # beside its edges: 0 at 1e-302 from an axis 1e300 long) gives NaN here;
    # its off-center, half an edge from that edge, is closer than any point
    # at infinity.  (Left NaN, the split was skipped as a duplicate and the
    # needle stayed, a bad triangle in the mesh and in every later cavity.)
    # So it is under circumcenters too (steiner="circumcenter"): there the
    # needle 2^-1022 wide at x = 0.00149 beside an edge 0.0003 long
    # (tests/engine/test_split_point_rounding.py), whose 0.5 / area overflows,
    # stayed in a mesh returned as if it met the angle.
    far: cython.bint = dx != dx or dy != dy
    # A needle (shortest edge below 2^-300 of the longest, by the edges'
    # largest components, which need no products): its circumcenter is
    # about half a long edge away, its off-center within three short edges
    # of the short edge, so the off-center it is (as the squares below
    # would decide, were they in range).  The squares of the short edge and the products
    # that place the circumcenter along it vanish below the doubles' range
    # even where the long edges are in it (an edge 2e-271 long beside a
    # corner 3.4e-27 away: all 0, the circumcenter "closer" at the org, a
    # split point on the org, and a PrecisionError for a needle whose
    # off-center doubles hold), so the needle's short edge is the one of
    # least largest component, and its off-center is computed from its own
    # ends (below), not from the far corner.
    n1: cython.double = max(fabs(xdo0), fabs(ydo0))
    n2: cython.double = max(fabs(xao0), fabs(yao0))
    n3: cython.double = max(fabs(xda0), fabs(yda0))
    longest: cython.double = max(max(n1, n2), n3)
    # (an edge beyond the doubles, 1e308 - -1e308, is no needle's: as before)
    needle: cython.bint = longest <= 1.7976931348623157e308 and min(min(n1, n2), n3) < NEEDLE * longest
    # ... and so is its circumcenter (under circumcenters, or where the
    # off-center is not closer), from the short edge's ends and each scale
    # apart: the formula above vanishes to the short edge's org
    cx: cython.double = 0.0
    cy: cython.double = 0.0
    if needle:
        if n1 <= n2 and n1 <= n3:
            cx, cy = _needle_circumcenter(ox, oy, m.xy[d, 0], m.xy[d, 1], m.xy[a, 0], m.xy[a, 1])
        elif n2 <= n3:
            cx, cy = _needle_circumcenter(ox, oy, m.xy[a, 0], m.xy[a, 1], m.xy[d, 0], m.xy[d, 1])
        else:
            cx, cy = _needle_circumcenter(m.xy[d, 0], m.xy[d, 1], m.xy[a, 0], m.xy[a, 1], ox, oy)
        far = not (fabs(cx) <= 1.7976931348623157e308 and fabs(cy) <= 1.7976931348623157e308)
        if not far:
            dx = (cx - ox) * f
            dy = (cy - oy) * f
    if (r.cfg.offcenter or far) and c > 0.0:
        if (dodist < aodist and dodist < dadist) if not needle else (n1 < n2 and n1 < n3):
            fx = 0.5 * xdo - c * ydo
            fy = 0.5 * ydo + c * xdo
            if fx * fx + fy * fy < dx * dx + dy * dy or far or needle:
                dx, dy, off, which = fx, fy, True, 1
        elif (aodist < dadist) if not needle else n2 < n3:
            fx = 0.5 * xao + c * yao
            fy = 0.5 * yao - c * xao
            if fx * fx + fy * fy < dx * dx + dy * dy or far or needle:
                dx, dy, off, which = fx, fy, True, 2
        else:
            ex = -xda
            ey = -yda
            fx = 0.5 * ex - c * ey
            fy = 0.5 * ey + c * ex
            if fx * fx + fy * fy < (dx - xdo) * (dx - xdo) + (dy - ydo) * (dy - ydo) or far or needle:
                dx, dy, off, which = xdo + fx, ydo + fy, True, 3
    xi: cython.double = (yao * dx - xao * dy) * (2.0 * denom)
    eta: cython.double = (xdo * dy - ydo * dx) * (2.0 * denom)
    if (f != 1.0 or needle) and off:
        # from the unscaled edge (degree 1: nothing overflows): an edge that
        # is tiny beside the triangle's longest vanishes when scaled, and its
        # off-center would land on its end (1e-303 edges under 1e300 ones);
        # where nothing vanished the result is the scaled one's, bit for bit
        # (but for the edge d-a, see there)
        if which == 1:
            dx = 0.5 * xdo0 - c * ydo0
            dy = 0.5 * ydo0 + c * xdo0
        elif which == 2:
            dx = 0.5 * xao0 + c * yao0
            dy = 0.5 * yao0 - c * xao0
        else:
            # from d itself: with o far from d (1e226 against 1e64), o +
            # ((d - o) + offset) loses the offset, or d (1e299 against 1e-302)
            return m.xy[d, 0] + (0.5 * -xda0 - c * -yda0), m.xy[d, 1] + (0.5 * -yda0 + c * -xda0), xi, eta, off
    elif needle and not far:
        return cx, cy, xi, eta, off
    elif f != 1.0:
        dx = dx / f
        dy = dy / f
    return ox + dx, oy + dy, xi, eta, off


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _would_create(r: Refiner, m: Mesh, t: Index) -> Index:
    """Triangles a split of ``t`` would create (the adversary's greed)."""
    px: cython.double
    py: cython.double
    xi: cython.double
    eta: cython.double
    off: cython.bint
    px, py, xi, eta, off = steiner_point(r, m, 3 * t)
    if px != px or py != py:  # NaN
        return 0
    n: Index
    nb: Index
    n, nb = collect_cavity(r, m, px, py, t, -1, -1)
    forget_cavity(r, m, n)
    return nb


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _triangle_key(r: Refiner, m: Mesh, mn: cython.double, u: Index, v: Index) -> cython.double:
    """Triangle's queue key (its bucket, negated) for a bad triangle whose
    shortest edge is ``u v``, squared ``mn`` (in the mesh's units).

    The bucket is of the edge in the run's units (state.Config.key_unit):
    scaled by a power of two before squaring, so it neither over- nor
    underflows where the input's extent does not.  An edge whose square in
    those units is still below the doubles' range (2^-537 beside an extent
    of 1: a mesh graded over 600 orders of magnitude, from 1e-301 features
    to a 1e300 square) would fall into Triangle's finest bucket with every
    other such edge, which then serves them first in, first out: there the
    bucket goes on past Triangle's last (order.wide_bucket), so that the
    finest triangles are still split first.  (In one FIFO bucket, each
    vertex inserted beside a fan of 900 needles from a chain of split
    points was followed by 900 rejected off-centers before the triangle
    that replaced the fan came up: 868,550 rejections for 3,755 vertices.)"""
    unit: cython.double = r.cfg.key_unit
    dx: cython.double
    dy: cython.double
    if unit != 1.0:
        dx = m.xy[u, 0] * unit - m.xy[v, 0] * unit
        dy = m.xy[u, 1] * unit - m.xy[v, 1] * unit
        mn = dx * dx + dy * dy
    b: cython.int = triangle_bucket(mn)
    e: cython.int = 0
    if b == TOP_BUCKET and mn == mn:
        if cython.compiled:
            frexp(unit, cython.address(e))
        else:
            e = math.frexp(unit)[1]
        b = wide_bucket(m.xy[u, 0] - m.xy[v, 0], m.xy[u, 1] - m.xy[v, 1], e - 1)
        if b >= r.bucket_ready:
            bucket_make_ready(r, b)
    return -cython.cast(cython.double, b)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _queue(
    r: Refiner, m: Mesh, t: Index, mn: cython.double, cos2: cython.double, circ2: cython.double, u: Index, v: Index,
) -> cython.void:
    """Put bad triangle ``t`` (shortest edge ``u v``, squared ``mn``) on the
    queue under the strategy's priority.  (Not inline: kept out of ``_test``,
    which is then small enough for the compiler to inline into ``test_fan``.)"""
    strategy: cython.int = r.cfg.strategy
    if strategy == TRIANGLE:
        queue_push(r, _triangle_key(r, m, mn, u, v), t, m.stamp[t])
        return
    created: Index = _would_create(r, m, t) if strategy == ADVERSARY else 0
    rnd: cython.double = 0.0
    if strategy == RANDOM:  # only then: the walks share this generator
        next_random(m)
        rnd = cython.cast(cython.double, m.rng)
    key: cython.double = priority(strategy, mn, cos2, circ2, created, r.seq, rnd)
    queue_push(r, key, t, m.stamp[t])


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def test_triangle(r: Refiner, m: Mesh, segs: Subsegments, t: Index) -> cython.void:
    """Queue triangle ``t`` if it is too big or too skinny (Triangle's
    ``testtriangle``); the caller made sure the queue has room."""
    _test(r, m, segs, t)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _test(r: Refiner, m: Mesh, segs: Subsegments, t: Index) -> cython.void:
    """``test_triangle``, inline: ``test_fan`` runs it on every new
    triangle, where the call's entry and exit cost a tenth of the test."""
    a: Index = m.corner[3 * t]
    b: Index = m.corner[3 * t + 1]
    c: Index = m.corner[3 * t + 2]
    mn: cython.double
    cos2: cython.double
    area2: cython.double
    circ2: cython.double
    u: Index
    v: Index
    mn, cos2, area2, circ2, u, v = _shape(m, a, b, c, _needs_circumradius(r))
    bad: cython.bint = False
    if r.cfg.fixed_area and 0.5 * area2 > r.cfg.max_area:
        bad = True
    bound: cython.double
    attr: cython.double
    if not bad and r.cfg.regional_area:
        bound, attr = inherited(m, t)
        if bound > 0.0 and 0.5 * area2 > bound:
            bad = True
    if not bad and r.cfg.builtin_user and builtin_unsuitable(m, b, c, a):  # handle 3 t: org, dest, apex
        bad = True
    k: Index
    exempt: cython.bint
    if not bad and r.cfg.angle_test and cos2 > r.cfg.good_angle:
        # the shortest edge is not a subsegment and its ends lie on segments
        # meeting at a small angle: leave it alone
        k = 2 if u == a else (0 if u == b else 1)  # the corner opposite u v (_shape: a b, b c or c a)
        exempt = m.seg[3 * t + k] == NO_SEG and _small_input_angle(m, segs, u, v)
        bad = not exempt
    if bad:
        _queue(r, m, t, mn, cos2, circ2, u, v)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def queue_triangles(r: Refiner, m: Mesh, ts: cython.longlong[::1]) -> cython.void:
    """Queue the live triangles ``ts`` (a user's size test found them
    unsuitable); the caller made sure the queue has room."""
    t: Index
    mn: cython.double
    cos2: cython.double
    area2: cython.double
    circ2: cython.double
    u: Index
    v: Index
    for i in range(ts.shape[0]):
        t = ts[i]
        if m.stamp[t] > 0:
            mn, cos2, area2, circ2, u, v = _shape(m, m.corner[3 * t], m.corner[3 * t + 1], m.corner[3 * t + 2], _needs_circumradius(r))
            _queue(r, m, t, mn, cos2, circ2, u, v)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def test_fan(r: Refiner, m: Mesh, segs: Subsegments, nb: Index, triangles: cython.bint, apex_clear: cython.bint) -> cython.void:
    """Quality-test the new triangles ``r.fan[:nb]`` (if ``triangles``) and
    pool the encroached subsegments on the fan's rim.  ``apex_clear``: the
    fan's apex (corner 0) is known to lie outside every rim subsegment's
    lens (a bad triangle's split tested exactly that, with the same
    arguments, before it inserted the point), so only the far sides' apices
    are tested."""
    t: Index
    for j in range(nb):
        t = r.fan[j]
        if triangles:
            _test(r, m, segs, t)
        if m.seg[3 * t] != NO_SEG:
            if apex_clear:
                queue_side(r, m, 3 * t, False)
            else:
                check_subsegment(r, m, 3 * t)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _fan_triangle_bad(
    r: Refiner, m: Mesh, segs: Subsegments, a: Index, b: Index, c: Index, bound: cython.double, rim_seg: cython.bint,
) -> tuple[cython.bint, cython.double, Index, Index]:
    """``test_triangle``'s verdict on a triangle that is not in the mesh:
    corners (apex ``a``, org ``b``, dest ``c``) as the slot's would be,
    its area bound ``bound``, and whether its edge b c (opposite the apex)
    is a subsegment (the other two are new edges).  Returns (bad, squared
    shortest edge, the shortest edge's ends)."""
    mn: cython.double
    cos2: cython.double
    area2: cython.double
    circ2: cython.double
    u: Index
    v: Index
    mn, cos2, area2, circ2, u, v = _shape(m, a, b, c, False)
    if r.cfg.fixed_area and 0.5 * area2 > r.cfg.max_area:
        return True, mn, u, v
    if r.cfg.regional_area and bound > 0.0 and 0.5 * area2 > bound:
        return True, mn, u, v
    if r.cfg.builtin_user and builtin_unsuitable(m, b, c, a):
        return True, mn, u, v
    if r.cfg.angle_test and cos2 > r.cfg.good_angle:
        # the shortest edge is a subsegment only if it is the rim edge b c
        if (u == b or u == c) and (v == b or v == c) and rim_seg:
            return True, mn, u, v
        return not _small_input_angle(m, segs, u, v), mn, u, v
    return False, mn, u, v


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def queue_rejected_fan(r: Refiner, m: Mesh, segs: Subsegments, nb: Index, px: cython.double, py: cython.double) -> cython.void:
    """Triangle inserts a Steiner point, queueing the bad triangles of its
    fan as its flips make them, before it finds that the point encroaches
    a subsegment and undoes the insertion; the entries stay in its queue
    (queues.queue_push_ghost).  Ours rejects before touching the mesh: queue
    the fan that point (px, py) would have had on the rim ``r.bnd[:nb]``,
    in ``r.fan[:nb]``'s order (cavity.order_rim), as ghosts for the vertex
    made next, each with its record and orientation in ``r.fan_rec[:nb]``
    (ghosts.rejected_fan_records).  Triangle's order only (its buckets);
    the caller made sure there is room (cavity.has_room, queues.ghost_room)."""
    if r.cfg.strategy != TRIANGLE:
        return
    # the point stands in as the next vertex (there is room: has_room), as
    # Triangle's own record does until the rejection frees it
    p: Index = m.nvert
    x0: cython.double = m.xy[p, 0]
    y0: cython.double = m.xy[p, 1]
    kind: cython.int = m.vtype[p]
    m.xy[p, 0] = px
    m.xy[p, 1] = py
    m.vtype[p] = V_FREE
    k: Index
    bad: cython.bint
    mn: cython.double
    u: Index
    v: Index
    for j in range(nb):
        k = r.fan[j]
        bad, mn, u, v = _fan_triangle_bad(r, m, segs, p, r.bnd[k, 1], r.bnd[k, 2], r.bval[k, 0], r.bnd[k, 3] != NO_SEG)
        if bad:
            queue_push_ghost(r, _triangle_key(r, m, mn, u, v), r.bnd[k, 1], r.bnd[k, 2], p, r.fan_rec[j, 0], r.fan_rec[j, 1])
    m.xy[p, 0] = x0
    m.xy[p, 1] = y0
    m.vtype[p] = kind
