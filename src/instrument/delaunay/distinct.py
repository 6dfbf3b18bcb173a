# cython: language_level=3
"""Ties and exact duplicates among points sorted by x (``delaunay``'s first
step), one pass each.

With numpy these were eight calls on arrays of the input's size (shifted
comparisons, a mask, an accumulate); on inputs of a few hundred points
those calls cost more than divide and conquer itself.
"""

from __future__ import annotations

import cython

if not cython.compiled:
    Index = cython.Py_ssize_t


@cython.ccall
def has_x_ties(xy: cython.double[:, ::1], order: cython.longlong[::1]) -> cython.bint:
    """Do two points next to each other in ``order`` have the same x?"""
    with cython.nogil:
        for i in range(1, order.shape[0]):
            if xy[order[i], 0] == xy[order[i - 1], 0]:
                return True
    return False


@cython.ccall
def mark_duplicates(xy: cython.double[:, ::1], order: cython.longlong[::1], dup: cython.longlong[::1]) -> Index:
    """For points sorted by (x, y) in ``order``: ``dup[order[i]]`` = the first
    point of the run of equal points ``order[i]`` belongs to, for every point
    but that first one (whose entry is left as it is); returns how many
    points were marked."""
    count: Index = 0
    first: Index = 0
    with cython.nogil:
        for i in range(1, order.shape[0]):
            if xy[order[i], 0] == xy[order[first], 0] and xy[order[i], 1] == xy[order[first], 1]:
                dup[order[i]] = order[first]
                count += 1
            else:
                first = i
    return count
