# cython: language_level=3
"""Copying the mesh into the output arrays (output.py's loops, compiled).

The output is a handful of gathers over the mesh's tables: the live
triangles' corners, the kept vertices, the subsegments.  Written with numpy
they take a dozen calls each (masks, fancy indexing, cumulative sums), and
on small meshes those calls, not the copying, are the cost: a mesh of a
thousand vertices spent a tenth of ``triangulate``'s time there.  One pass
per output here does the same copies in the same order.
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.mesh import Index, Mesh, dest, in_output, org
from cython.cimports.instrument.core.subsegments import Subsegments


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def live_slots(m: Mesh, out: cython.longlong[::1]) -> Index:
    """The slots of the output triangles, in slot order, into ``out`` (room
    for ``m.nlive``); returns how many."""
    n: Index = 0
    for t in range(m.nslot):
        if in_output(m, t):
            out[n] = t
            n += 1
    return n


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def number_vertices(keep: cython.uchar[::1], new_id: cython.int[::1]) -> Index:
    """``new_id[v]``: the output number of vertex ``v``, the kept vertices
    numbered in order (a vertex left out gets the number of the kept one
    before it, as ``cumsum(keep) - 1`` does); returns how many are kept."""
    n: Index = 0
    for v in range(keep.shape[0]):
        n += keep[v] != 0
        new_id[v] = cython.cast(cython.int, n - 1)
    return n


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def kept_vertices(
    m: Mesh, keep: cython.uchar[::1], xy: cython.double[:, ::1], marker: cython.int[:, ::1],
) -> cython.void:
    """The coordinates and boundary markers of the kept vertices, in order
    (``xy`` and ``marker`` have a row for each)."""
    n: Index = 0
    for v in range(keep.shape[0]):
        if keep[v]:
            xy[n, 0] = m.xy[v, 0]
            xy[n, 1] = m.xy[v, 1]
            marker[n, 0] = m.vmark[v]
            n += 1


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def triangle_corners(
    m: Mesh, slots: cython.longlong[::1], new_id: cython.int[::1], out: cython.int[:, ::1],
) -> cython.void:
    """``out[i]``: the corners of slot ``slots[i]``, renumbered by ``new_id``."""
    t: Index
    for i in range(slots.shape[0]):
        t = slots[i]
        for k in range(3):
            out[i, k] = new_id[m.corner[3 * t + k]]


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def subsegment_rows(
    m: Mesh, segs: Subsegments, edges: cython.longlong[::1], new_id: cython.int[::1],
    ends: cython.int[:, ::1], marker: cython.int[:, ::1],
) -> cython.void:
    """``ends[i]``: (destination, origin) of subsegment edge ``edges[i]``
    renumbered by ``new_id`` (Triangle lists a subsegment made on edge
    a -> b as b -> a), and ``marker[i]`` its record's marker in ``segs``
    (the records themselves, not their marker table: a table taken from
    Python is a new memoryview to make and take apart on every call)."""
    e: Index
    for i in range(edges.shape[0]):
        e = edges[i]
        ends[i, 0] = new_id[dest(m, e)]
        ends[i, 1] = new_id[org(m, e)]
        marker[i, 0] = segs.marker[m.seg[e]]
