# cython: language_level=3
"""The Delaunay triangulation of a deleted vertex's star in expected time
linear in its degree (Chew's randomized algorithm), for the stars too large
for the scan.

Chew's deletion re-triangulates a free vertex's star polygon. The scan
(``deletion._fill_polygon``: for each base edge, the vertex whose circle
through it holds no other vertex of its side, then both sides) tests every
vertex of a side once per base edge, which is quadratic in the degree when
the sides split unevenly: free vertices inside a sliver reach degrees in
the hundreds, and their stars' triangulations are zigzags whose every
split takes one vertex off (regressions/mixed-scale-sliver-deletion.json,
once the defect mixed-scale-slow: 48.8 million incircle tests). This module
makes the same triangulation another way:

1. Take the star's vertices out of the polygon in a random order, each one
   only while the deleted vertex v stays strictly inside the polygon of
   those left (its two neighbours then turn less than a half-turn around
   v), down to a triangle; one that cannot go yet waits for a later pass.
2. Put them back in the reverse order. Each polygon on the way is
   star-shaped from v, and (lifting map) its Delaunay triangulation is the
   triangles of the Delaunay triangulation of its vertices whose circles
   hold v; putting p back between q and r removes the triangles whose
   circles hold p, which are connected to the edge q r, and joins p to
   their rim (Bowyer and Watson). Taken back in a random order, a vertex
   meets O(1) triangles in expectation (backward analysis), so the whole
   costs O(k) incircle tests for degree k.
3. Ties. Where four or more vertices are cocircular the scan takes, of the
   vertices on the emptiest circle, the last in chain order (as Triangle
   does): it triangulates each cocircular face as a fan from the face's
   first vertex.  Flipping every cocircular edge towards its
   quadrilateral's first vertex reaches that fan (each flip lowers the
   first vertex of one diagonal).
4. Check, with the exact predicates: every triangle counter-clockwise and
   every inner edge locally Delaunay. Such a triangulation is the polygon's
   constrained Delaunay triangulation; the scan's, when it is a
   triangulation at all, is too (each of its circles is empty of the
   vertices of its side), with the same faces, all of whose cocircular
   vertices it fans the same way, so the two are the same triangles. A star
   for which the steps above do not give such a triangulation (one that is
   not Delaunay, a degenerate one) is left to the scan: ``delaunay_star``
   returns -1 and the caller scans.

The triangulation is local: vertex i is the polygon's chain position i (the
caller's ``chain``: position 0, then the others clockwise, so position i's
counter-clockwise successor is i - 1), and local triangle t has corners
``tv[3 t .. 3 t + 2]`` counter-clockwise with the mesh's conventions (edge
3 t + s is opposite corner s: lnext, lprev apply) and twins ``nb[3 t + s]``
(-1 on the polygon's boundary).
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.mesh import Index, lnext, lprev
from cython.cimports.instrument.core.predicates import incircle, orient2d
from cython.cimports.instrument.counters import C_INCIRCLE, C_ORIENT


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _holds(xy: cython.double[:, ::1], chain: cython.longlong[:], tv: cython.longlong[:], t: Index, p: Index,
           work: cython.longlong[::1]) -> cython.bint:
    """Local triangle t's circle holds position p strictly inside."""
    a: Index = chain[tv[3 * t]]
    b: Index = chain[tv[3 * t + 1]]
    c: Index = chain[tv[3 * t + 2]]
    q: Index = chain[p]
    work[C_INCIRCLE] += 1
    return incircle(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[c, 0], xy[c, 1], xy[q, 0], xy[q, 1]) > 0.0


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _link(nb: cython.longlong[:], e: Index, f: Index) -> cython.void:
    nb[e] = f
    if f >= 0:
        nb[f] = e


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _take_out(xy: cython.double[:, ::1], chain: cython.longlong[:], n: Index, vx: cython.double, vy: cython.double,
              nxt: cython.longlong[:], prv: cython.longlong[:], order: cython.longlong[:], seq: cython.longlong[:],
              work: cython.longlong[::1]) -> cython.bint:
    """Step 1: ``seq[0 .. n - 4]`` the positions taken out, in order
    (``prv``/``nxt`` keep each one's neighbours as it went), and the three
    left linked counter-clockwise. False if no vertex could go (v on a
    diagonal of a quadrilateral, or not inside the polygon at all)."""
    i: Index
    j: Index
    p: Index
    a: Index
    b: Index
    for i in range(n):
        nxt[i] = i - 1 if i > 0 else n - 1
        prv[i] = i + 1 if i < n - 1 else 0
        order[i] = i
    x: cython.longlong = 12345 + n  # a fixed seed: runs repeat (the result does not depend on it)
    for i in range(n - 1, 0, -1):  # Fisher and Yates
        x = (x * 1103515245 + 12345) & 0x7FFFFFFF
        j = (x >> 8) % (i + 1)
        p = order[i]
        order[i] = order[j]
        order[j] = p
    left: Index = n
    waiting: Index = n
    taken: Index = 0
    kept: Index
    while left > 3:
        kept = 0
        for i in range(waiting):
            p = order[i]
            if left > 3:
                a = chain[prv[p]]
                b = chain[nxt[p]]
                work[C_ORIENT] += 1
                if orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], vx, vy) > 0.0:
                    nxt[prv[p]] = nxt[p]
                    prv[nxt[p]] = prv[p]
                    seq[taken] = p
                    taken += 1
                    left -= 1
                    continue
            order[kept] = p
            kept += 1
        if kept == waiting:
            return False
        waiting = kept
    return True


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _put_back(xy: cython.double[:, ::1], chain: cython.longlong[:], p: Index, q: Index, r: Index,
              tv: cython.longlong[:], nb: cython.longlong[:], ntri: Index, bedge: cython.longlong[:],
              mark: cython.longlong[:], stack: cython.longlong[:], rim_org: cython.longlong[:],
              rim_twin: cython.longlong[:], cavity: cython.longlong[:], stamp: Index,
              work: cython.longlong[::1]) -> Index:
    """Step 2 for one vertex: p goes back between q and r (the boundary edge
    q -> r is ``bedge[q]``). The triangles whose circles hold p, found from
    the one on q -> r, give way to p joined to their rim from r around to q
    (or, if there are none, to the triangle q, p, r). Returns the number of
    local triangles after, or -1 if the cavity is not a tree of triangles."""
    eqr: Index = bedge[q]
    t0: Index = eqr // 3
    ncav: Index = 0
    nrim: Index = 0
    sp: Index = 0
    f: Index
    g: Index
    tg: Index
    if _holds(xy, chain, tv, t0, p, work):
        mark[t0] = stamp
        cavity[0] = t0
        ncav = 1
        stack[0] = lprev(eqr)
        stack[1] = lnext(eqr)  # on top: the rim runs from r first
        sp = 2
        while sp > 0:
            sp -= 1
            f = stack[sp]
            g = nb[f]
            if g >= 0:
                tg = g // 3
                if mark[tg] == stamp:  # reached twice: not a tree (cannot happen in a triangulated polygon)
                    return -1
                if _holds(xy, chain, tv, tg, p, work):
                    mark[tg] = stamp
                    cavity[ncav] = tg
                    ncav += 1
                    stack[sp] = lprev(g)
                    stack[sp + 1] = lnext(g)
                    sp += 2
                    continue
            rim_org[nrim] = tv[lnext(f)]
            rim_twin[nrim] = g
            nrim += 1
    else:
        rim_org[0] = r
        rim_twin[0] = eqr
        nrim = 1
    # p joined to the rim a_0 = r, a_1, ..., a_nrim = q: triangle (a, b, p)
    # per rim edge a -> b, in the cavity's slots and one new slot
    t: Index
    a: Index
    b: Index
    i: Index
    before: Index = -1  # the previous triangle's edge b -> p
    for i in range(nrim):
        if i < ncav:
            t = cavity[i]
        else:
            t = ntri
            ntri += 1
        a = rim_org[i]
        b = rim_org[i + 1] if i + 1 < nrim else q
        tv[3 * t] = a
        tv[3 * t + 1] = b
        tv[3 * t + 2] = p
        _link(nb, 3 * t + 2, rim_twin[i])  # a -> b
        if rim_twin[i] < 0:
            bedge[a] = 3 * t + 2
        if before < 0:  # p -> r, a boundary edge now
            nb[3 * t + 1] = -1
            bedge[p] = 3 * t + 1
        else:
            _link(nb, 3 * t + 1, before)
        before = 3 * t
    nb[before] = -1  # q -> p
    bedge[q] = before
    return ntri


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _flip(tv: cython.longlong[:], nb: cython.longlong[:], tie: cython.longlong[:], e: Index, f: Index) -> cython.void:
    """Replace the diagonal of e's and its twin f's triangles, (x, a, b) and
    (y, b, a), with x y: the triangles become (x, a, y) and (y, b, x). The
    outer edges keep their ``tie`` flags; the new diagonal is cocircular."""
    t: Index = e // 3
    u: Index = f // 3
    x: Index = tv[e]
    a: Index = tv[lnext(e)]
    b: Index = tv[lprev(e)]
    y: Index = tv[f]
    t1: Index = nb[lnext(e)]  # b -> x
    t2: Index = nb[lprev(e)]  # x -> a
    u1: Index = nb[lnext(f)]  # a -> y
    u2: Index = nb[lprev(f)]  # y -> b
    s1: cython.longlong = tie[lnext(e)]
    s2: cython.longlong = tie[lprev(e)]
    r1: cython.longlong = tie[lnext(f)]
    r2: cython.longlong = tie[lprev(f)]
    tv[3 * t] = x
    tv[3 * t + 1] = a
    tv[3 * t + 2] = y
    tv[3 * u] = y
    tv[3 * u + 1] = b
    tv[3 * u + 2] = x
    _link(nb, 3 * t, u1)
    _link(nb, 3 * t + 2, t2)
    _link(nb, 3 * u, t1)
    _link(nb, 3 * u + 2, u2)
    _link(nb, 3 * t + 1, 3 * u + 1)
    tie[3 * t] = r1
    tie[3 * t + 2] = s2
    tie[3 * u] = s1
    tie[3 * u + 2] = r2
    tie[3 * t + 1] = 1
    tie[3 * u + 1] = 1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _settle(xy: cython.double[:, ::1], chain: cython.longlong[:], ntri: Index, tv: cython.longlong[:],
            nb: cython.longlong[:], tie: cython.longlong[:], work: cython.longlong[::1]) -> cython.bint:
    """Steps 3 and 4: check every triangle counter-clockwise and every inner
    edge locally Delaunay, flagging the cocircular ones in ``tie`` (a flip
    inside a cocircular face keeps the face's circle, so the flags stay true
    without new tests), then flip flagged edges towards their
    quadrilateral's last position until none is left. False if a check
    fails (or, which the flips' progress rules out, they do not end)."""
    a: Index
    b: Index
    c: Index
    x: Index
    y: Index
    f: Index
    t: Index
    e: Index
    s: cython.double
    for t in range(ntri):
        a = chain[tv[3 * t]]
        b = chain[tv[3 * t + 1]]
        c = chain[tv[3 * t + 2]]
        work[C_ORIENT] += 1
        if orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[c, 0], xy[c, 1]) <= 0.0:
            return False
    ties: Index = 0
    for e in range(3 * ntri):
        f = nb[e]
        if f < 0:
            tie[e] = 0
        if f < e:  # each inner edge once (and not the boundary's)
            continue
        x = chain[tv[e]]
        a = chain[tv[lnext(e)]]
        b = chain[tv[lprev(e)]]
        y = chain[tv[f]]
        work[C_INCIRCLE] += 1
        s = incircle(xy[x, 0], xy[x, 1], xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[y, 0], xy[y, 1])
        if s > 0.0:
            return False
        tie[e] = 1 if s == 0.0 else 0
        tie[f] = tie[e]
        ties += tie[e]
    flipped: cython.bint = ties > 0
    rounds: Index = 0
    while flipped:
        if rounds > ntri * ntri:
            return False
        rounds += 1
        flipped = False
        for e in range(3 * ntri):
            f = nb[e]
            if f < e or tie[e] == 0:
                continue
            if min(tv[e], tv[f]) < min(tv[lnext(e)], tv[lprev(e)]):
                _flip(tv, nb, tie, e, f)
                flipped = True
    return True


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def delaunay_star(xy: cython.double[:, ::1], chain: cython.longlong[:], n: Index, vx: cython.double,
                  vy: cython.double, tv: cython.longlong[:], nb: cython.longlong[:], links: cython.longlong[:],
                  aux: cython.longlong[:], rim: cython.longlong[:], work: cython.longlong[::1]) -> Index:
    """Triangulate the star polygon ``chain[0 .. n - 1]`` (the mesh's
    vertices around the deleted vertex at (vx, vy), clockwise from
    ``chain[0]``) into ``tv``/``nb`` as the scan would (module docstring).
    Returns the local edge on the base, position 0 -> n - 1, or -1 if the
    star is left to the scan. Scratch: ``tv``, ``nb``, ``links``, ``aux``
    and ``rim`` each with at least 4 n entries; the tests go into ``work``."""
    nxt: cython.longlong[:] = links[0:n]
    prv: cython.longlong[:] = links[n : 2 * n]
    order: cython.longlong[:] = links[2 * n : 3 * n]
    seq: cython.longlong[:] = links[3 * n : 4 * n]
    bedge: cython.longlong[:] = aux[0:n]
    mark: cython.longlong[:] = aux[n : 2 * n]
    stack: cython.longlong[:] = aux[2 * n : 3 * n]
    cavity: cython.longlong[:] = aux[3 * n : 4 * n]
    rim_org: cython.longlong[:] = rim[0 : 2 * n]
    rim_twin: cython.longlong[:] = rim[2 * n : 4 * n]
    i: Index
    e: Index
    if n < 3 or not _take_out(xy, chain, n, vx, vy, nxt, prv, order, seq, work):
        return -1
    # the triangle left
    a: Index = order[0]
    b: Index = nxt[a]
    c: Index = nxt[b]
    tv[0] = a
    tv[1] = b
    tv[2] = c
    nb[0] = -1
    nb[1] = -1
    nb[2] = -1
    bedge[a] = 2
    bedge[b] = 0
    bedge[c] = 1
    for i in range(n):
        mark[i] = 0
    ntri: Index = 1
    p: Index
    for i in range(n - 4, -1, -1):
        p = seq[i]
        nxt[prv[p]] = p
        prv[nxt[p]] = p
        ntri = _put_back(xy, chain, p, prv[p], nxt[p], tv, nb, ntri, bedge, mark, stack, rim_org, rim_twin,
                         cavity, i + 1, work)
        if ntri < 0:
            return -1
    if ntri != n - 2 or not _settle(xy, chain, ntri, tv, nb, aux, work):
        return -1
    for e in range(3 * ntri):  # the flips may have moved the base
        if nb[e] < 0 and tv[lnext(e)] == 0 and tv[lprev(e)] == n - 1:
            return e
    return -1
