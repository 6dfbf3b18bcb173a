# cython: language_level=3
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
* ``seg[e]`` is the subsegment record of a constrained edge (the same on both
  sides), or ``NO_SEG``.
* ``GHOST`` (-1) is the vertex at infinity.  While a Delaunay triangulation is
  built, every convex-hull edge has a ghost triangle ``(a, b, GHOST)`` on its
  outer side, so that points outside the hull are handled by the same code as
  points inside it (Triangle's "outer space", CGAL's infinite vertex).
* ``stamp[t] > 0`` for a live triangle; killing negates it and reviving adds
  one, so a queue entry ``(t, stamp)`` is current iff ``stamp[t]`` still
  equals the stored value.  Dead slots are kept on the ``free`` stack and
  reused last-in first-out, as Triangle's pools do.

One object, ``Mesh``, holds every array indexed by a vertex or by a
triangle slot: the stages add no side tables of their own.  Growing the mesh
(``grow_vertices``, ``grow_triangles``) therefore grows every such array at
once, and no kernel can index a table that growth left behind.  Optional
tables (per-triangle area bounds and attributes, the vertices' attribute
records, and the constraint tables ``seg``, ``vtri`` and ``vslot`` that a
plain Delaunay triangulation does without) have no rows when the run does
not use them, and grow only if they have rows.  Kernels never allocate:
when a mesh is full they report it, and the Python side grows the mesh and
calls them again.

The primitives below are compiled from ``mesh.pxd`` (where every kernel
inlines them); the definitions at the end of this file are the same
functions for the pure-Python mode.
"""

from __future__ import annotations

import numpy as np

import cython

from ..counters import new_work
from .filled import filled

if not cython.compiled:  # compiled, these are mesh.pxd's
    Index = cython.Py_ssize_t  # a vertex, triangle slot or edge number
    GHOST = -1  # the vertex at infinity
    NO_EDGE = -1  # no twin: the edge is on the boundary of the mesh
    NO_SEG = -1  # the edge is not a subsegment
    # kinds of vertex (Mesh.vtype), as refinement classifies them
    V_INPUT = 0
    V_SEGMENT = 1  # made by splitting a subsegment
    V_FREE = 2  # made by splitting a triangle
    V_DEAD = 3  # a free vertex deleted again (left out of the output)

#: Columns of Mesh.parent: a new vertex's attributes are
#: a0 + s (a1 - a0) + t (a2 - a0) of vertices p0, p1, p2 (p0 < 0: zeros).
PARENT_COLUMNS = 5

#: The tables a mesh has no rows of (see Mesh.__init__): one empty table
#: per type, taken as a typed memoryview once, here.  A table set from an
#: array is a new memoryview to make (some 4k instructions: the buffer,
#: its format, the checks); set from one of these it is a reference.
_NO_INTS = cython.declare(cython.int[::1], np.empty(0, dtype=np.int32))
_NO_LONGS = cython.declare(cython.longlong[::1], np.empty(0, dtype=np.int64))
_NO_DOUBLES = cython.declare(cython.double[::1], np.empty(0))
_NO_PARENTS = cython.declare(cython.double[:, ::1], np.empty((0, PARENT_COLUMNS)))  # a mesh without attribute records


def _widened(a, rows: int, fill):
    """``a`` with ``rows`` rows, the new ones set to ``fill``.  Zeros come
    from the OS's lazily mapped pages: the room a mesh grows by is touched
    only as it is used (numpy's fill writes every page at once)."""
    a = np.asarray(a)
    shape = (rows,) + a.shape[1:]
    out = np.zeros(shape, dtype=a.dtype) if fill == 0 else filled(shape, fill, a.dtype)
    out[: a.shape[0]] = a
    return out


@cython.cclass
class Mesh:
    """A triangulation being built: vertices, triangle slots and every
    per-vertex and per-triangle table (see the module docstring and
    ``mesh.pxd`` for each array's meaning)."""

    def __init__(
        self,
        xy,
        triangles: int,
        *,
        vertices: int | None = None,
        parents: bool = False,
        area_bounds: bool = False,
        attributes: bool = False,
        constraints: bool = True,
        work=None,
    ):
        """A mesh with no triangles, holding the vertices ``xy`` (which it
        copies), with room for ``vertices`` vertices in all (default: just
        those) and ``triangles`` triangle slots, and the optional tables
        asked for (``constraints``: see ``add_constraint_tables``)."""
        xy = np.asarray(xy, dtype=np.float64).reshape(-1, 2)
        n = xy.shape[0]
        cap = max(n, int(vertices if vertices is not None else n), 1)
        slots = max(int(triangles), 4)
        self.xy = _widened(xy, cap, 0.0)
        # (if statements, not conditional expressions: an array and a typed
        # memoryview would meet as a Python object, and be taken anew)
        if parents:
            self.parent = filled((cap, PARENT_COLUMNS), -1.0)
        else:
            self.parent = _NO_PARENTS
        # The 1-D tables of one kind (per vertex or per triangle) that always
        # grow together come from one block per type and starting value, each
        # table a slice of its block: a small run's mesh made fifteen arrays
        # and took each as a typed memoryview, which cost more than the
        # copying (slicing a typed memoryview costs next to nothing).  Growth
        # replaces every table of a block at once (grow_*), so no old block
        # outlives it; tables without rows share one empty table per type
        # (_NO_INTS and the others: a slice of no rows would keep its block
        # alive).  The blocks of zeros stay lazily mapped, as the tables were.
        links: cython.int[::1] = filled((9 if constraints else 6) * slots, -1, np.int32)
        self.corner = links[0 : 3 * slots]
        self.twin = links[3 * slots : 6 * slots]
        if constraints:
            self.seg = links[6 * slots : 9 * slots]
        else:
            self.seg = _NO_INTS
        counts: cython.int[::1] = np.zeros(2 * slots, dtype=np.int32)
        self.stamp = counts[0:slots]
        self.free = counts[slots : 2 * slots]
        self.tflag = np.zeros(slots, dtype=np.int8)
        self.vmark = np.zeros(cap, dtype=np.int32)
        self.vtype = np.zeros(cap, dtype=np.int8)
        hints: cython.longlong[::1]
        if constraints:
            hints = filled(2 * cap, -1, np.int64)
            self.vtri = hints[0:cap]
            self.vslot = hints[cap : 2 * cap]
        else:
            self.vtri = _NO_LONGS
            self.vslot = _NO_LONGS
        if area_bounds:
            self.area_bound = filled(slots, -1.0)
        else:
            self.area_bound = _NO_DOUBLES
        if attributes:
            self.attribute = np.zeros(slots)
        else:
            self.attribute = _NO_DOUBLES
        self.nvert = n
        self.nslot = 0
        self.nfree = 0
        self.nlive = 0
        self.work = new_work() if work is None else work
        self.rng = 12345
        # the hull edge Triangle's outer-space handle holds: each
        # triangulator sets it, and the in-place flips and splits move it
        # as Triangle's bonds to outer space do (carve/infect.py's
        # start_hull_edge reads it)
        self.outer_space_edge = NO_EDGE

    def partner(self) -> Mesh:
        """A mesh over the same tables with counts and work of its own, for a
        thread that builds a part of the triangulation in slots and vertices
        no other thread touches (``delaunay``'s parallel divide and
        conquer).  Its counts start at zero; set ``nslot`` to the first slot
        it may take."""
        other = Mesh.__new__(Mesh)
        for name in (
            "xy", "vmark", "vtri", "vtype", "parent", "vslot", "corner", "twin", "seg",
            "stamp", "free", "area_bound", "attribute", "tflag",
        ):  # fmt: skip
            setattr(other, name, getattr(self, name))
        other.nvert = self.nvert
        other.nslot = 0
        other.nfree = 0
        other.nlive = 0
        other.work = new_work()
        other.rng = self.rng
        other.outer_space_edge = NO_EDGE
        return other

    # ------------------------------------------------------------ capacity

    @property
    def vertex_capacity(self) -> int:
        return self.xy.shape[0]

    @property
    def triangle_capacity(self) -> int:
        return self.stamp.shape[0]

    def grow_vertices(self, room: int, *, exact: bool = False) -> None:
        """Make room for at least ``room`` more vertices (doubling, so that
        repeated growth is amortised, unless ``exact``), in every
        per-vertex table."""
        want = self.nvert + int(room)
        cap = want if exact else max(2 * self.xy.shape[0], want)
        if want <= self.xy.shape[0]:
            return
        self.xy = _widened(self.xy, cap, 0.0)
        self.vmark = _widened(self.vmark, cap, 0)
        self.vtype = _widened(self.vtype, cap, 0)
        if self.parent.shape[0]:
            self.parent = _widened(self.parent, cap, -1.0)
        if self.has_constraint_tables:
            self.vtri = _widened(self.vtri, cap, -1)
            self.vslot = _widened(self.vslot, cap, -1)

    def grow_triangles(self, room: int, *, exact: bool = False) -> None:
        """If fewer than ``room`` triangles can be allocated, add room for
        ``room`` more (at least doubling, so that repeated growth is
        amortised, unless ``exact``), in every per-triangle table."""
        if self.spare() >= room:
            return
        old = self.stamp.shape[0]
        want = old + int(room)
        cap = want if exact else max(2 * old, want)
        self.corner = _widened(self.corner, 3 * cap, GHOST)
        self.twin = _widened(self.twin, 3 * cap, NO_EDGE)
        if self.has_constraint_tables:
            self.seg = _widened(self.seg, 3 * cap, NO_SEG)
        self.stamp = _widened(self.stamp, cap, 0)
        self.free = _widened(self.free, cap, 0)
        if self.area_bound.shape[0]:
            self.area_bound = _widened(self.area_bound, cap, -1.0)
        if self.attribute.shape[0]:
            self.attribute = _widened(self.attribute, cap, 0.0)
        self.tflag = _widened(self.tflag, cap, 0)

    def spare(self) -> int:
        """Triangles that can still be allocated without growing."""
        return self.nfree + self.stamp.shape[0] - self.nslot

    @property
    def has_constraint_tables(self) -> bool:
        return self.seg.shape[0] > 0

    def add_constraint_tables(self) -> None:
        """Give the mesh the tables that segment recovery, carving and
        refinement use, unless it has them: ``seg`` (every edge
        unconstrained), ``vtri`` (no hints yet) and ``vslot`` (clear).  A
        plain Delaunay triangulation never needs them, and without them its
        mesh takes a third less memory; every stage that reads them calls
        this first, and ``new_triangle`` writes ``seg`` only when it has rows."""
        if self.has_constraint_tables:
            return
        self.seg = filled(3 * self.stamp.shape[0], NO_SEG, np.int32)
        self.vtri = filled(self.xy.shape[0], -1, np.int64)
        self.vslot = filled(self.xy.shape[0], -1, np.int64)

    def add_area_bounds(self, bounds) -> None:
        """Start the per-triangle area bounds with ``bounds`` (one per slot in use)."""
        self.area_bound = _widened(np.asarray(bounds, dtype=np.float64), self.stamp.shape[0], -1.0)

    def add_attributes(self, values) -> None:
        """Start the per-triangle attributes with ``values`` (one per slot in use)."""
        self.attribute = _widened(np.asarray(values, dtype=np.float64), self.stamp.shape[0], 0.0)

    # ------------------------------------------------------------ read-out

    def live_triangles(self, ghosts: bool = False) -> np.ndarray:
        """Slots of live triangles in slot order (ghosts excluded unless asked)."""
        n = self.nslot
        live = np.asarray(self.stamp)[:n] > 0
        if not ghosts:
            c = np.asarray(self.corner)[: 3 * n].reshape(-1, 3)
            live &= (c[:, 0] >= 0) & (c[:, 1] >= 0) & (c[:, 2] >= 0)  # (all(axis=1) is several times slower)
        return np.flatnonzero(live).astype(np.int64, copy=False)

    def rotate_corners(self, shift: int) -> None:
        """Renumber every triangle's corners in place: new corner ``k`` is
        old corner ``(k + shift) % 3`` (each triangle keeps its orientation),
        with its edges' twins and subsegments.  Edge numbers held elsewhere
        (the vertices' edge hints, queued edges) are stale afterwards."""
        if self.nslot == 0 or shift % 3 == 0:
            return
        self.add_constraint_tables()
        turn_corners(self, shift % 3)

    def arrays(self) -> dict:
        """The tables as numpy arrays (views, not copies), by name."""
        names = (
            "xy", "vmark", "vtri", "vtype", "parent", "vslot", "corner", "twin", "seg",
            "stamp", "free", "area_bound", "attribute", "tflag", "work",
        )  # fmt: skip
        return {name: np.asarray(getattr(self, name)) for name in names}


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def remove_ghosts(m: Mesh) -> Index:
    """Delete every ghost triangle, leaving NO_EDGE across the hull.  Returns the hull size."""
    hull: Index = 0
    tw: Index
    for t in range(m.nslot):
        if m.stamp[t] <= 0:
            continue
        for k in range(3):
            if m.corner[3 * t + k] == GHOST:
                tw = m.twin[3 * t + k]
                if tw != NO_EDGE:
                    m.twin[tw] = NO_EDGE
                    hull += 1
                kill_triangle(m, t)
                break
    return hull


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def least_hull_edge(m: Mesh) -> Index:
    """The hull edge leaving the hull vertex with the least (x, y), or
    NO_EDGE without one: where Triangle's outer space points after divide
    and conquer, so both the removal of its ghosts
    (``remove_ghosts_around_hull``) and the search for that handle where
    none is known (carve/infect.py's ``start_hull_edge``) start there.  A
    hull edge is the twin of a ghost's edge opposite its ghost corner, or,
    once the ghosts are gone, an edge without a twin; either way the scan
    reads each slot's corners and twins in order.  Where every point is
    collinear, the ghosts' edges face each other and the one found is a
    ghost's."""
    xy = m.xy
    best: Index = NO_EDGE
    best_v: Index = -1
    e: Index
    h: Index
    v: Index
    for t in range(m.nslot):
        if m.stamp[t] <= 0:
            continue
        for k in range(3):
            e = 3 * t + k
            if m.corner[e] == GHOST:  # a ghost: its edge e runs against the hull edge
                h = m.twin[e]
                v = m.corner[lprev(e)]
            elif m.twin[e] == NO_EDGE:
                h = e
                v = m.corner[lnext(e)]
            else:
                continue
            if best_v < 0 or xy[v, 0] < xy[best_v, 0] or (xy[v, 0] == xy[best_v, 0] and xy[v, 1] < xy[best_v, 1]):
                best = h
                best_v = v
    return best


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def remove_ghosts_around_hull(m: Mesh) -> Index:
    """``remove_ghosts`` in the order Triangle deletes its ghosts after
    divide and conquer: around the hull counter-clockwise, from the ghost
    of the hull edge that leaves the least vertex in (x, y) order.  The
    order is that of the free stack, so it decides which slots the next
    triangles made take (the last ghost deleted first): found by comparing
    Triangle's output order where segment recovery splits edges
    (tests/engine/test_pool_order.py).  A ghost's finite edge ``h``
    (opposite its ghost corner) runs against its hull edge, from the hull
    edge's head to its tail; the next ghost counter-clockwise holds
    ``lprev(twin[lprev(h)])``.  Returns the hull size."""
    outer: Index = least_hull_edge(m)
    if outer == NO_EDGE:
        return remove_ghosts(m)  # (no ghosts: nothing to remove)
    start: Index = m.twin[outer]
    # the hull edge leaving the least vertex is where Triangle's outer space
    # points (none when every point is collinear: the ghosts face each other)
    m.outer_space_edge = outer if not is_ghost(m, outer // 3) else NO_EDGE
    hull: Index = 0
    h: Index = start
    nxt: Index
    tw: Index
    for _ in range(m.nslot):
        nxt = lprev(m.twin[lprev(h)])
        tw = m.twin[h]
        if tw != NO_EDGE:
            m.twin[tw] = NO_EDGE
            hull += 1
        kill_triangle(m, h // 3)
        h = nxt
        if h == start or m.stamp[h // 3] <= 0:
            break
    return hull + remove_ghosts(m)  # (none should be left)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def relabel_corners(m: Mesh, label: cython.longlong[::1]) -> cython.void:
    """Vertex ``v`` becomes ``label[v]`` in the corners of every slot used
    (ghost corners stay): in place, where numpy would hold several copies
    of the corner table at once."""
    v: Index
    for e in range(3 * m.nslot):
        v = m.corner[e]
        if v >= 0:
            m.corner[e] = cython.cast(cython.int, label[v])


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def turn_corners(m: Mesh, shift: Index) -> cython.void:
    """``Mesh.rotate_corners`` for ``shift`` 1 or 2, in one pass over the
    slots (numpy's version took 0.18 s and several copies of the tables at
    1.6 million triangles): new corner ``k`` is old corner ``(k + shift) %
    3``; a twin, an edge of a triangle turned the same way, is renumbered
    to match (shift 1: edge k becomes k - 1, that is lprev; shift 2: lnext).
    The shift picks one of two fixed permutations per slot (refinement
    turns every triangle before and after, and remainders per corner cost
    more than the moves)."""
    e: Index
    c0: cython.int
    c1: cython.int
    c2: cython.int
    w0: Index
    w1: Index
    w2: Index
    s0: cython.int
    s1: cython.int
    s2: cython.int
    for t in range(m.nslot):
        e = 3 * t
        c0 = m.corner[e]
        c1 = m.corner[e + 1]
        c2 = m.corner[e + 2]
        w0 = m.twin[e]
        w1 = m.twin[e + 1]
        w2 = m.twin[e + 2]
        s0 = m.seg[e]
        s1 = m.seg[e + 1]
        s2 = m.seg[e + 2]
        if shift == 1:  # (c1, c2, c0)
            c0, c1, c2 = c1, c2, c0
            s0, s1, s2 = s1, s2, s0
            w0, w1, w2 = w1, w2, w0
        else:  # (c2, c0, c1)
            c0, c1, c2 = c2, c0, c1
            s0, s1, s2 = s2, s0, s1
            w0, w1, w2 = w2, w0, w1
        m.corner[e] = c0
        m.corner[e + 1] = c1
        m.corner[e + 2] = c2
        m.seg[e] = s0
        m.seg[e + 1] = s1
        m.seg[e + 2] = s2
        m.twin[e] = _turned(w0, shift)
        m.twin[e + 1] = _turned(w1, shift)
        m.twin[e + 2] = _turned(w2, shift)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _turned(w: Index, shift: Index) -> cython.int:
    """Twin edge ``w`` renumbered in its triangle turned by ``shift``."""
    if w < 0:
        return cython.cast(cython.int, w)
    return cython.cast(cython.int, lprev(w) if shift == 1 else lnext(w))


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def set_parent(m: Mesh, v: Index, p0: Index, p1: Index, p2: Index, s: cython.double, t: cython.double) -> cython.void:
    """Record that new vertex ``v``'s attributes are a0 + s (a1 - a0) + t (a2 - a0)
    of vertices p0, p1, p2 (the output stage interpolates them); nothing
    when the run has no vertex attributes (the table has no rows)."""
    if v < m.parent.shape[0]:
        m.parent[v, 0] = p0
        m.parent[v, 1] = p1
        m.parent[v, 2] = p2
        m.parent[v, 3] = s
        m.parent[v, 4] = t


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def interpolate_attributes(m: Mesh, out: cython.double[:, ::1], first: Index) -> cython.void:
    """Fill the attribute rows ``out[first:]`` of vertices the engine added,
    each from its parents' rows as ``set_parent`` recorded them; a vertex
    without a record (p0 < 0) keeps zeros.  Vertices come in creation order,
    so parents are filled first."""
    p0: Index
    p1: Index
    p2: Index
    s: cython.double
    t: cython.double
    a0: cython.double
    for v in range(first, out.shape[0]):
        p0 = cython.cast(Index, m.parent[v, 0])
        if p0 < 0:
            continue
        p1 = cython.cast(Index, m.parent[v, 1])
        p2 = cython.cast(Index, m.parent[v, 2])
        s = m.parent[v, 3]
        t = m.parent[v, 4]
        for k in range(out.shape[1]):
            a0 = out[p0, k]
            out[v, k] = a0 + s * (out[p1, k] - a0) + t * (out[p2, k] - a0)


# ---------------------------------------------------------------- pure Python
# The primitives of mesh.pxd, for the pure-Python mode (compiled, mesh.pxd's
# inline definitions are used instead).

if not cython.compiled:

    def lnext(e):
        """The next edge counter-clockwise in the same triangle."""
        return e - 2 if e % 3 == 2 else e + 1

    def lprev(e):
        """The previous edge counter-clockwise in the same triangle."""
        return e + 2 if e % 3 == 0 else e - 1

    def org(m, e):
        return m.corner[lnext(e)]

    def dest(m, e):
        return m.corner[lprev(e)]

    def apex(m, e):
        return m.corner[e]

    def next_hull_edge(m, e):
        """The hull edge after hull edge ``e`` counter-clockwise (no ghosts):
        it leaves ``e``'s destination, found by turning around that vertex."""
        f = lnext(e)
        while m.twin[f] != NO_EDGE:
            f = lnext(m.twin[f])
        return f

    def is_ghost(m, t):
        return m.corner[3 * t] == GHOST or m.corner[3 * t + 1] == GHOST or m.corner[3 * t + 2] == GHOST

    def alive(m, t):
        return m.stamp[t] > 0

    def in_output(m, t):
        """Alive and no ghost: a triangle the output lists."""
        return m.stamp[t] > 0 and m.corner[3 * t] >= 0 and m.corner[3 * t + 1] >= 0 and m.corner[3 * t + 2] >= 0

    def bond(m, e1, e2):
        """Make edges ``e1`` and ``e2`` (either may be NO_EDGE) each other's twin."""
        if e1 >= 0:
            m.twin[e1] = e2
        if e2 >= 0:
            m.twin[e2] = e1

    def new_triangle(m, a, b, c):
        """Allocate a triangle with corners ``(a, b, c)``; return its slot or -1 if full."""
        t = -1
        if m.nfree > 0:
            m.nfree -= 1
            t = int(m.free[m.nfree])
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
                m.twin[e + k] = NO_EDGE
                if m.seg.shape[0] > 0:
                    m.seg[e + k] = NO_SEG
        return t

    def kill_triangle(m, t):
        """Free slot ``t``; queue entries that remember its stamp become stale."""
        m.stamp[t] = -m.stamp[t]
        m.free[m.nfree] = t
        m.nfree += 1
        m.nlive -= 1

    def spare_triangles(m):
        """How many triangles can still be allocated without growing."""
        return m.nfree + m.stamp.shape[0] - m.nslot

    def next_random(m):
        """Advance the walks' generator and return 0, 1 or 2."""
        m.rng = (m.rng * 1103515245 + 12345) & 0x7FFFFFFF
        return (m.rng >> 16) % 3
