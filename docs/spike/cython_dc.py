# cython: language_level=3, boundscheck=False, wraparound=False, initializedcheck=False, cdivision=True, infer_types=True
"""Spike (b): divide-and-conquer Delaunay + predicates' fast path in Cython pure-Python mode."""
import cython
import numpy as np

from instrument.predicates import _orient2d_slow as _o_slow, _incircle_slow as _i_slow

GHOST = cython.declare(cython.int, -1)
C_CREATED = cython.declare(cython.int, 0)
C_DELETED = cython.declare(cython.int, 1)
C_INCIRCLE = cython.declare(cython.int, 2)
C_ORIENT = cython.declare(cython.int, 3)
EPS = cython.declare(cython.double, 2.0**-53)
CCWERRBOUNDA = cython.declare(cython.double, (3.0 + 16.0 * EPS) * EPS)
ICCERRBOUNDA = cython.declare(cython.double, (10.0 + 96.0 * EPS) * EPS)
_ICC_A_SAFE = cython.declare(cython.double, ICCERRBOUNDA * (1.0 + 2.0**-40))
_O_LO = cython.declare(cython.double, 2.0**-960)
_I_LO = cython.declare(cython.double, 2.0**-660)
_I_SMAX = cython.declare(cython.double, 2.0**300)
_DBL_MAX = cython.declare(cython.double, 1.7976931348623157e308)

idx = cython.typedef(cython.Py_ssize_t)


@cython.cclass
class Mesh:
    xy = cython.declare(cython.double[:, ::1], visibility="public")
    corner = cython.declare(cython.int[::1], visibility="public")
    twin = cython.declare(cython.int[::1], visibility="public")
    seg = cython.declare(cython.int[::1], visibility="public")
    stamp = cython.declare(cython.int[::1], visibility="public")
    free = cython.declare(cython.int[::1], visibility="public")
    work = cython.declare(cython.longlong[::1], visibility="public")
    nvert = cython.declare(idx, visibility="public")
    nslot = cython.declare(idx, visibility="public")
    nfree = cython.declare(idx, visibility="public")
    nlive = cython.declare(idx, visibility="public")

    def __init__(self, xy, cap, work):
        self.xy = xy
        self.corner = np.full(3 * cap, GHOST, dtype=np.int32)
        self.twin = np.full(3 * cap, -1, dtype=np.int32)
        self.seg = np.full(3 * cap, -1, dtype=np.int32)
        self.stamp = np.zeros(cap, dtype=np.int32)
        self.free = np.zeros(cap, dtype=np.int32)
        self.work = work
        self.nvert = xy.shape[0]
        self.nslot = 0
        self.nfree = 0
        self.nlive = 0


# ------------------------------------------------------------ predicates
@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _orient_slow(ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
                 cx: cython.double, cy: cython.double) -> cython.double:
    with cython.gil:
        return _o_slow(ax, ay, bx, by, cx, cy)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _incircle_slow(ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
                   cx: cython.double, cy: cython.double, dx: cython.double, dy: cython.double) -> cython.double:
    with cython.gil:
        return _i_slow(ax, ay, bx, by, cx, cy, dx, dy)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def orient2d(ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
             cx: cython.double, cy: cython.double) -> cython.double:
    detleft: cython.double = (ax - cx) * (by - cy)
    detright: cython.double = (ay - cy) * (bx - cx)
    det: cython.double = detleft - detright
    detsum: cython.double = abs(detleft) + abs(detright)
    if abs(det) >= CCWERRBOUNDA * detsum:
        if (detsum >= _O_LO) & (detsum <= _DBL_MAX):
            return det
    return _orient_slow(ax, ay, bx, by, cx, cy)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def incircle(ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
             cx: cython.double, cy: cython.double, dx: cython.double, dy: cython.double) -> cython.double:
    adx: cython.double = ax - dx
    bdx: cython.double = bx - dx
    cdx: cython.double = cx - dx
    ady: cython.double = ay - dy
    bdy: cython.double = by - dy
    cdy: cython.double = cy - dy
    bdxcdy: cython.double = bdx * cdy
    cdxbdy: cython.double = cdx * bdy
    alift: cython.double = adx * adx + ady * ady
    cdxady: cython.double = cdx * ady
    adxcdy: cython.double = adx * cdy
    blift: cython.double = bdx * bdx + bdy * bdy
    adxbdy: cython.double = adx * bdy
    bdxady: cython.double = bdx * ady
    clift: cython.double = cdx * cdx + cdy * cdy
    det: cython.double = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady)
    permanent: cython.double = ((abs(bdxcdy) + abs(cdxbdy)) * alift + (abs(cdxady) + abs(adxcdy)) * blift
                                + (abs(adxbdy) + abs(bdxady)) * clift)
    if abs(det) > _ICC_A_SAFE * permanent:
        if (permanent >= _I_LO) & (alift + blift + clift <= _I_SMAX):
            return det
    return _incircle_slow(ax, ay, bx, by, cx, cy, dx, dy)


# ------------------------------------------------------------ mesh primitives
@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def lnext(e: idx) -> idx:
    return e - 2 if e % 3 == 2 else e + 1


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def lprev(e: idx) -> idx:
    return e + 2 if e % 3 == 0 else e - 1


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def org(m: Mesh, e: idx) -> idx:
    return m.corner[lnext(e)]


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def dest(m: Mesh, e: idx) -> idx:
    return m.corner[lprev(e)]


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def bond(m: Mesh, e1: idx, e2: idx) -> cython.void:
    if e1 >= 0:
        m.twin[e1] = e2
    if e2 >= 0:
        m.twin[e2] = e1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def new_triangle(m: Mesh, a: idx, b: idx, c: idx) -> idx:
    t: idx = -1
    if m.nfree > 0:
        m.nfree -= 1
        t = m.free[m.nfree]
        m.stamp[t] = -m.stamp[t] + 1
    elif m.nslot < m.stamp.shape[0]:
        t = m.nslot
        m.nslot = t + 1
        m.stamp[t] = 1
    if t >= 0:
        m.nlive += 1
        e = 3 * t
        m.corner[e] = a
        m.corner[e + 1] = b
        m.corner[e + 2] = c
        for k in range(3):
            m.twin[e + k] = -1
            m.seg[e + k] = -1
    return t


# ------------------------------------------------------------ divconq
@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _less(a1: cython.double, a2: cython.double, b1: cython.double, b2: cython.double) -> cython.bint:
    return a1 < b1 or (a1 == b1 and a2 < b2)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _before(xy: cython.double[:, ::1], a: idx, b: idx, f: idx) -> cython.bint:
    g = 1 - f
    return _less(xy[a, f], xy[a, g], xy[b, f], xy[b, g])


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _next_ccw(m: Mesh, h: idx) -> idx:
    return lprev(m.twin[lprev(h)])


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _prev_cw(m: Mesh, h: idx) -> idx:
    return lnext(m.twin[lnext(h)])


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _ghost(m: Mesh, hull_at: cython.int[::1], a: idx, b: idx) -> idx:
    g = new_triangle(m, b, a, GHOST)
    h = 3 * g + 2
    hull_at[a] = h
    return h


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _link(m: Mesh, h1: idx, h2: idx) -> cython.void:
    bond(m, lprev(h1), lnext(h2))


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _two(m: Mesh, hull_at: cython.int[::1], a: idx, b: idx) -> cython.void:
    h_ba = _ghost(m, hull_at, b, a)
    h_ab = _ghost(m, hull_at, a, b)
    bond(m, h_ab, h_ba)
    _link(m, h_ab, h_ba)
    _link(m, h_ba, h_ab)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _three(m: Mesh, hull_at: cython.int[::1], a: idx, b: idx, c: idx) -> cython.void:
    xy = m.xy
    m.work[C_ORIENT] += 1
    s = orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[c, 0], xy[c, 1])
    if s == 0.0:
        h_ab = _ghost(m, hull_at, a, b)
        h_bc = _ghost(m, hull_at, b, c)
        h_cb = _ghost(m, hull_at, c, b)
        h_ba = _ghost(m, hull_at, b, a)
        bond(m, h_ab, h_ba)
        bond(m, h_bc, h_cb)
        _link(m, h_ab, h_bc)
        _link(m, h_bc, h_cb)
        _link(m, h_cb, h_ba)
        _link(m, h_ba, h_ab)
        return
    if s < 0.0:
        b, c = c, b
    t = new_triangle(m, a, b, c)
    m.work[C_CREATED] += 1
    h_ab = _ghost(m, hull_at, a, b)
    h_bc = _ghost(m, hull_at, b, c)
    h_ca = _ghost(m, hull_at, c, a)
    bond(m, 3 * t + 2, h_ab)
    bond(m, 3 * t + 0, h_bc)
    bond(m, 3 * t + 1, h_ca)
    _link(m, h_ab, h_bc)
    _link(m, h_bc, h_ca)
    _link(m, h_ca, h_ab)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _below(xy: cython.double[:, ::1], a: idx, b: idx, p: idx) -> cython.bint:
    return orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[p, 0], xy[p, 1]) < 0.0


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _above(xy: cython.double[:, ::1], a: idx, b: idx, p: idx) -> cython.bint:
    return orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[p, 0], xy[p, 1]) > 0.0


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _inside(xy: cython.double[:, ::1], a: idx, b: idx, c: idx, d: idx) -> cython.bint:
    return incircle(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[c, 0], xy[c, 1], xy[d, 0], xy[d, 1]) > 0.0


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _unhull(m: Mesh, hull_at: cython.int[::1], h: idx, left: cython.bint) -> idx:
    t_in: idx = m.twin[h]
    x: idx = m.corner[t_in]
    u = dest(m, h)
    w = org(m, h)
    n_ux: idx = m.twin[lprev(t_in)]
    n_xw: idx = m.twin[lnext(t_in)]
    before: idx = m.twin[lnext(h)]
    after: idx = m.twin[lprev(h)]
    s_ux: idx
    s_xw: idx
    if left:
        s_ux, s_xw = h, t_in
    else:
        s_ux, s_xw = t_in, h
    k = s_ux % 3
    g = s_ux - k
    m.corner[g + k] = u
    m.corner[g + (k + 1) % 3] = GHOST
    m.corner[g + (k + 2) % 3] = x
    h_ux = g + (k + 1) % 3
    k = s_xw % 3
    g = s_xw - k
    m.corner[g + k] = w
    m.corner[g + (k + 1) % 3] = x
    m.corner[g + (k + 2) % 3] = GHOST
    h_xw = g + (k + 2) % 3
    bond(m, h_ux, n_ux)
    bond(m, h_xw, n_xw)
    if left:
        bond(m, lprev(h_xw), after)
    else:
        bond(m, lnext(h_ux), before)
    _link(m, h_ux, h_xw)
    hull_at[u] = h_ux
    hull_at[x] = h_xw
    return h_ux if left else h_xw


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _clear(m: Mesh, hull_at: cython.int[::1], g: idx, ll: idx, lr: idx, left: cython.bint) -> idx:
    cand: idx
    while m.corner[m.twin[g]] != GHOST:
        cand = org(m, g) if left else dest(m, g)
        m.work[C_INCIRCLE] += 1
        if not _inside(m.xy, ll, lr, cand, m.corner[m.twin[g]]):
            break
        g = _unhull(m, hull_at, g, left)
        m.work[C_DELETED] += 1
    return g


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _merge(m: Mesh, hull_at: cython.int[::1], l: idx, r: idx) -> idx:
    xy = m.xy
    hl: idx = hull_at[l]
    hr: idx = hull_at[r]
    moved: cython.bint = True
    while moved:
        moved = False
        pl = _prev_cw(m, hl)
        m.work[C_ORIENT] += 1
        if _below(xy, l, r, dest(m, pl)):
            hl = pl
            l = dest(m, pl)
            moved = True
        m.work[C_ORIENT] += 1
        if _below(xy, l, r, org(m, hr)):
            r = org(m, hr)
            hr = _next_ccw(m, hr)
            moved = True
    gl = hl
    gr = _prev_cw(m, hr)
    outer = _prev_cw(m, hl)
    g = new_triangle(m, l, GHOST, r)
    bottom = 3 * g + 1
    hull_at[l] = bottom
    _link(m, outer, bottom)
    _link(m, bottom, hr)
    base = bottom
    ll = l
    lr = r
    while True:
        ul = org(m, gl)
        ur = dest(m, gr)
        m.work[C_ORIENT] += 2
        left_ok = _above(xy, ll, lr, ul)
        right_ok = _above(xy, ll, lr, ur)
        if left_ok:
            gl = _clear(m, hull_at, gl, ll, lr, True)
            ul = org(m, gl)
        if right_ok:
            gr = _clear(m, hull_at, gr, ll, lr, False)
            ur = dest(m, gr)
        if not left_ok and not right_ok:
            break
        take_left = left_ok
        if left_ok and right_ok:
            m.work[C_INCIRCLE] += 1
            take_left = not _inside(xy, ul, ll, lr, ur)
        m.work[C_CREATED] += 1
        if take_left:
            nxt = _next_ccw(m, gl)
            m.corner[gl] = lr
            bond(m, lnext(gl), base)
            base = lprev(gl)
            gl = nxt
            ll = ul
        else:
            nxt = _prev_cw(m, gr)
            m.corner[gr] = ll
            bond(m, lprev(gr), base)
            base = lnext(gr)
            gr = nxt
            lr = ur
    top = _ghost(m, hull_at, lr, ll)
    bond(m, top, base)
    _link(m, gr, top)
    _link(m, top, gl)
    return top


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _find_hull_edge(m: Mesh, hull_at: cython.int[::1], v: idx, h: idx) -> cython.void:
    g: idx = hull_at[v]
    if m.corner[g] != GHOST or dest(m, g) != v:
        while dest(m, h) != v:
            h = _next_ccw(m, h)
        hull_at[v] = h


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _first(xy: cython.double[:, ::1], a: idx, b: idx, f: idx) -> idx:
    return b if _before(xy, b, a, f) else a


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _last(xy: cython.double[:, ::1], a: idx, b: idx, f: idx) -> idx:
    return b if _before(xy, a, b, f) else a


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _base(m: Mesh, hull_at: cython.int[::1], lo: idx, hi: idx, out: cython.longlong[::1]) -> cython.void:
    xy = m.xy
    if hi - lo == 2:
        _two(m, hull_at, lo, lo + 1)
    else:
        _three(m, hull_at, lo, lo + 1, lo + 2)
    out[0] = lo
    out[1] = hi - 1
    out[2] = lo
    out[3] = lo
    for v in range(lo + 1, hi):
        out[2] = _first(xy, out[2], v, 1)
        out[3] = _last(xy, out[3], v, 1)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _build(m: Mesh, hull_at: cython.int[::1], n: idx, alternate: cython.bint,
           frames: cython.longlong[:, ::1], found: cython.longlong[:, ::1]) -> cython.void:
    xy = m.xy
    frames[0, 0] = 0
    frames[0, 1] = n
    frames[0, 2] = 0
    frames[0, 3] = 0
    top: idx = 1
    nfound: idx = 0
    lo: idx
    hi: idx
    f: idx
    stage: idx
    while top > 0:
        lo, hi, f, stage = frames[top - 1, 0], frames[top - 1, 1], frames[top - 1, 2], frames[top - 1, 3]
        if hi - lo <= 3:
            _base(m, hull_at, lo, hi, found[nfound])
            nfound += 1
            top -= 1
        elif stage < 2:
            frames[top - 1, 3] = stage + 1
            mid = lo + ((hi - lo) >> 1)
            frames[top, 0] = lo if stage == 0 else mid
            frames[top, 1] = mid if stage == 0 else hi
            frames[top, 2] = 1 - f if alternate else 0
            frames[top, 3] = 0
            top += 1
        else:
            a = found[nfound - 2]
            b = found[nfound - 1]
            if f == 0:
                top_edge = _merge(m, hull_at, a[1], b[0])
            else:
                top_edge = _merge(m, hull_at, a[3], b[2])
            a[0] = _first(xy, a[0], b[0], 0)
            a[1] = _last(xy, a[1], b[1], 0)
            a[2] = _first(xy, a[2], b[2], 1)
            a[3] = _last(xy, a[3], b[3], 1)
            for k in range(4):
                _find_hull_edge(m, hull_at, a[k], top_edge)
            nfound -= 1
            top -= 1


def triangulate_sorted(m: Mesh, n: idx, alternate: cython.bint) -> None:
    if n >= 2:
        hull_at = np.full(n, -1, dtype=np.int32)
        frames = np.zeros((130, 4), dtype=np.int64)
        found = np.zeros((130, 4), dtype=np.int64)
        hv: cython.int[::1] = hull_at
        fv: cython.longlong[:, ::1] = frames
        gv: cython.longlong[:, ::1] = found
        with cython.nogil:
            _build(m, hv, n, alternate, fv, gv)
