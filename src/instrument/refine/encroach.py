# cython: language_level=3
"""Encroached subsegments: the lens test and the pool they wait in.

A subsegment is encroached when a vertex lies in its diametral lens (the
points that see it at more than 180 - 2 theta degrees; its diametral
circle with -D).  The pool is Triangle's: a record takes the slot freed
last (or a fresh one), and passes visit the slots in order, so a record in
a reused slot behind the pass waits for the next pass.  A record keeps the
subsegment's end vertices and its edge; the edge id finds it fast while its
triangle is unchanged, the ends find it again otherwise (even at a vertex
where two parts of the domain touch, where rotating about the vertex does
not reach every edge).
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.mesh import NO_EDGE, NO_SEG, Index, Mesh, lnext, lprev
from cython.cimports.instrument.core.navigate import find_edge
from cython.cimports.instrument.core.scaling import scaled_pair
from cython.cimports.instrument.refine.state import Refiner


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def enc_push(r: Refiner, m: Mesh, e: Index) -> cython.void:
    """Pool subsegment edge ``e`` (the caller made sure there is room)."""
    i: Index = r.enc_free
    if i >= 0:
        r.enc_free = r.enc[i, 1]
    else:
        i = r.enc_fresh
        r.enc_fresh += 1
    r.enc[i, 0] = m.corner[lnext(e)]
    r.enc[i, 1] = m.corner[lprev(e)]
    r.enc[i, 2] = e
    r.enc[i, 3] = m.stamp[e // 3]
    r.enc_live += 1
    if i < r.enc_low:
        r.enc_low = i


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def enc_free(r: Refiner, i: Index) -> cython.void:
    r.enc[i, 0] = -1
    r.enc[i, 1] = r.enc_free
    r.enc_free = i
    r.enc_live -= 1


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def enc_edge(r: Refiner, m: Mesh, i: Index) -> Index:
    """The subsegment edge of pool record ``i``, or -1 if it is gone."""
    u: Index = r.enc[i, 0]
    v: Index = r.enc[i, 1]
    e: Index = r.enc[i, 2]
    if not (m.stamp[e // 3] == r.enc[i, 3] and m.corner[lnext(e)] == u and m.corner[lprev(e)] == v):
        e = find_edge(m, u, v)
    if e < 0 or m.seg[e] == NO_SEG:
        return -1
    return e


# The tests every new subsegment side and rim edge takes: compiled,
# encroach.pxd's inline definitions; the same functions for the pure-Python mode.
if not cython.compiled:

    def may_split(r: Refiner, m: Mesh, e: Index) -> bool:
        """-Y keeps boundary subsegments whole, -YY every subsegment."""
        y = r.cfg.keep_segments
        return y == 0 or (y == 1 and m.twin[e] != NO_EDGE)

    def queue_side(r: Refiner, m: Mesh, e: Index, hit: bool) -> bool:
        """Pool subsegment edge ``e`` (whose own apex encroaches if ``hit``) on
        an encroaching side: the other side if its apex encroaches, as Triangle
        orients its records, since the side decides where shells are measured
        from.  Returns whether it is encroached."""
        tw = m.twin[e]
        if tw != NO_EDGE:
            b = m.corner[tw]
            if in_lens(r, m, m.corner[lnext(e)], m.corner[lprev(e)], m.xy[b, 0], m.xy[b, 1]):
                e = tw
                hit = True
        if hit and may_split(r, m, e):
            enc_push(r, m, e)
        return hit

    def check_subsegment(r: Refiner, m: Mesh, e: Index) -> bool:
        """Pool subsegment edge ``e`` if an apex on either side encroaches it."""
        a = m.corner[e]
        return queue_side(r, m, e, in_lens(r, m, m.corner[lnext(e)], m.corner[lprev(e)], m.xy[a, 0], m.xy[a, 1]))

    def in_lens(r: Refiner, m: Mesh, e0: Index, e1: Index, ax: float, ay: float) -> bool:
        """Does the point (ax, ay) lie in the diametral lens (or circle with -D)
        of ``e0 e1``?"""
        xy = m.xy
        ux = xy[e0, 0] - ax
        uy = xy[e0, 1] - ay
        vx = xy[e1, 0] - ax
        vy = xy[e1, 1] - ay
        # the lens test is of degree 4: beyond 2^+-120 it over- or underflows
        # (at 2^300 both sides were infinite and every apex encroached; at 1e301
        # a dot product was inf - inf = NaN, taken as encroaching: 3 points under
        # D made 6306 vertices where the same points at 1e150 make 10); there the
        # vectors are scaled by a power of two, which changes no result
        ux, uy, vx, vy = scaled_pair(ux, uy, vx, vy, 2.0**120)
        dot = ux * vx + uy * vy
        if dot >= 0.0:
            return False
        if r.cfg.diametral:
            return True
        return dot * dot >= r.cfg.lens * (ux * ux + uy * uy) * (vx * vx + vy * vy)
