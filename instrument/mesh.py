"""The triangulation as flat arrays, and the primitives that read and edit it.

Conventions (written down once, here, and used everywhere else)
----------------------------------------------------------------
* Triangle ``t`` has corners ``corner[3t], corner[3t+1], corner[3t+2]`` in
  counter-clockwise order.
* Edge ``e = 3t + k`` is the edge *opposite* corner ``k``: its apex is
  ``corner[e]``, it runs from ``org(e) = corner[lnext(e)]`` to
  ``dest(e) = corner[lprev(e)]``, and the apex lies to its left.  This is
  Triangle's handle convention, so neighbour ``k`` of a triangle is the one
  across the edge opposite corner ``k`` (the ``.neigh`` convention).
* ``twin[e]`` is the same edge seen from the neighbouring triangle (reversed),
  or ``NO_EDGE`` on the boundary of the mesh.
* ``seg[e]`` is the subsegment id of a constrained edge (the same on both
  sides), or ``NO_SEG``.
* ``GHOST`` (-1) is the vertex at infinity.  While a Delaunay triangulation is
  built, every convex-hull edge has a ghost triangle ``(a, b, GHOST)`` on its
  outer side, so that points outside the hull are handled by the same code as
  points inside it (Triangle's "outer space", CGAL's infinite vertex).
* ``stamp[t] > 0`` for a live triangle; killing negates it and reviving adds
  one, so a queue entry ``(t, stamp)`` is current iff ``stamp[t]`` still
  equals the stored value.  Dead slots are kept on the ``free`` stack and
  reused last-in first-out, as Triangle's pools do.

Scalars that kernels change live in ``size`` (see the ``S_*`` indices), so a
whole mesh is one NamedTuple that numba passes by reference.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .jit import kernel, kernel_inline

GHOST = -1
NO_EDGE = -1
NO_SEG = -1

# Slots of Mesh.size.
S_NVERT = 0  # vertices in use (xy rows)
S_NSLOT = 1  # triangle slots ever used (high-water mark)
S_NFREE = 2  # dead slots on the free stack
S_NLIVE = 3  # live triangles (ghosts included)

# Kernel status codes.
OK = 0
NEED_CAPACITY = 1


class Mesh(NamedTuple):
    xy: np.ndarray  # (V, 2) float64 vertex coordinates
    corner: np.ndarray  # (3T,) int32 corner vertex ids, ccw
    twin: np.ndarray  # (3T,) int32 the same edge in the neighbour, or NO_EDGE
    seg: np.ndarray  # (3T,) int32 subsegment id, or NO_SEG
    stamp: np.ndarray  # (T,) int32 >0 alive, <=0 dead
    free: np.ndarray  # (T,) int32 stack of dead slots
    size: np.ndarray  # (4,) int64, see S_*


def new_mesh(xy: np.ndarray, max_triangles: int) -> Mesh:
    """Allocate a mesh holding the vertices ``xy`` and room for ``max_triangles``."""
    xy = np.ascontiguousarray(xy, dtype=np.float64)
    cap = max(int(max_triangles), 4)
    size = np.zeros(4, dtype=np.int64)
    size[S_NVERT] = xy.shape[0]
    return Mesh(
        xy=xy,
        corner=np.full(3 * cap, GHOST, dtype=np.int32),
        twin=np.full(3 * cap, NO_EDGE, dtype=np.int32),
        seg=np.full(3 * cap, NO_SEG, dtype=np.int32),
        stamp=np.zeros(cap, dtype=np.int32),
        free=np.zeros(cap, dtype=np.int32),
        size=size,
    )


def grow_triangles(m: Mesh, min_capacity: int, *, exact: bool = False) -> Mesh:
    """Return a copy of ``m`` with room for at least ``min_capacity`` triangles
    (at least double the old room, so repeated growth is amortised, unless
    ``exact``)."""
    old = m.stamp.shape[0]
    cap = int(min_capacity) if exact else max(2 * old, int(min_capacity))
    if cap <= old:
        return m

    def widen(a, fill, per):
        out = np.full(per * cap, fill, dtype=a.dtype)
        out[: a.shape[0]] = a
        return out

    return m._replace(
        corner=widen(m.corner, GHOST, 3),
        twin=widen(m.twin, NO_EDGE, 3),
        seg=widen(m.seg, NO_SEG, 3),
        stamp=widen(m.stamp, 0, 1),
        free=widen(m.free, 0, 1),
    )


def grow_vertices(m: Mesh, min_capacity: int, *, exact: bool = False) -> Mesh:
    """Return a copy of ``m`` with room for at least ``min_capacity`` vertices."""
    cap = int(min_capacity) if exact else max(2 * m.xy.shape[0], int(min_capacity))
    if cap <= m.xy.shape[0]:
        return m
    xy = np.zeros((cap, 2), dtype=np.float64)
    xy[: m.xy.shape[0]] = m.xy
    return m._replace(xy=xy)


# ---------------------------------------------------------------- navigation


@kernel_inline
def lnext(e):
    """The next edge counter-clockwise in the same triangle."""
    return e - 2 if e % 3 == 2 else e + 1


@kernel_inline
def lprev(e):
    """The previous edge counter-clockwise in the same triangle."""
    return e + 2 if e % 3 == 0 else e - 1


@kernel_inline
def org(m, e):
    return m.corner[lnext(e)]


@kernel_inline
def dest(m, e):
    return m.corner[lprev(e)]


@kernel_inline
def apex(m, e):
    return m.corner[e]


@kernel_inline
def is_ghost(m, t):
    return m.corner[3 * t] == GHOST or m.corner[3 * t + 1] == GHOST or m.corner[3 * t + 2] == GHOST


@kernel_inline
def alive(m, t):
    return m.stamp[t] > 0


@kernel_inline
def bond(m, e1, e2):
    """Make edges ``e1`` and ``e2`` (either may be NO_EDGE) each other's twin."""
    if e1 >= 0:
        m.twin[e1] = e2
    if e2 >= 0:
        m.twin[e2] = e1


# ---------------------------------------------------------------- allocation


@kernel
def new_triangle(m, a, b, c):
    """Allocate a triangle with corners ``(a, b, c)``; return its slot or -1 if full.

    Single exit on purpose: numba passes the Mesh tuple with reference counts
    on each of its arrays, and LLVM only inlines (and so drops those counts
    from) small functions without early returns.  The same holds for every
    helper called in the insertion loop.
    """
    t = -1
    if m.size[S_NFREE] > 0:
        m.size[S_NFREE] -= 1
        t = m.free[m.size[S_NFREE]]
        m.stamp[t] = -m.stamp[t] + 1
    elif m.size[S_NSLOT] < m.stamp.shape[0]:
        t = m.size[S_NSLOT]
        m.size[S_NSLOT] = t + 1
        m.stamp[t] = 1
    if t >= 0:
        m.size[S_NLIVE] += 1
        e = 3 * t
        m.corner[e] = a
        m.corner[e + 1] = b
        m.corner[e + 2] = c
        for k in range(3):
            m.twin[e + k] = NO_EDGE
            m.seg[e + k] = NO_SEG
    return t


@kernel
def kill_triangle(m, t):
    """Free slot ``t``; queue entries that remember its stamp become stale."""
    m.stamp[t] = -m.stamp[t]
    m.free[m.size[S_NFREE]] = t
    m.size[S_NFREE] += 1
    m.size[S_NLIVE] -= 1


@kernel
def spare_triangles(m):
    """How many triangles can still be allocated without growing."""
    return m.size[S_NFREE] + m.stamp.shape[0] - m.size[S_NSLOT]


# ---------------------------------------------------------------- read-out


def live_triangles(m: Mesh, ghosts: bool = False) -> np.ndarray:
    """Slots of live triangles in slot order (ghosts excluded unless asked)."""
    n = int(m.size[S_NSLOT])
    live = m.stamp[:n] > 0
    if not ghosts:
        c = m.corner[: 3 * n].reshape(-1, 3)
        live &= (c >= 0).all(axis=1)
    return np.flatnonzero(live).astype(np.int64)


def rotate_corners(m: Mesh, shift: int) -> None:
    """Renumber every triangle's corners in place: new corner ``k`` is old
    corner ``(k + shift) % 3`` (so each triangle keeps its orientation),
    with its edges' twins and subsegments.  Edge ids held elsewhere (a
    vertex's edge, queued edges) are invalid afterwards."""
    n = int(m.size[S_NSLOT])
    if n == 0 or shift % 3 == 0:
        return
    k = np.arange(3 * n) % 3
    old = np.arange(3 * n) - k + (k + shift) % 3  # the old edge each new edge id takes over
    twin = m.twin[old]
    j = twin % 3
    m.twin[: 3 * n] = np.where(twin >= 0, twin - j + (j - shift) % 3, twin)
    m.corner[: 3 * n] = m.corner[old]
    m.seg[: 3 * n] = m.seg[old]
