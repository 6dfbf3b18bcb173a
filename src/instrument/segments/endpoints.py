# cython: language_level=3
"""The input segments' endpoints, checked in one pass (``clean_segments``),
and the test for repeated segments (``merge_duplicates``).

With numpy the checks were some twenty calls on arrays of the segments'
size (masks for each kind of bad endpoint, the duplicate mapping, the
coincidence test, the compaction); on inputs of a few hundred segments the
calls cost more than recovering the segments.
"""

from __future__ import annotations

import cython

if not cython.compiled:
    Index = cython.Py_ssize_t

# ``check_endpoints``'s verdict on each segment; compiled, endpoints.pxd's enum
if not cython.compiled:
    KEPT = 0
    BAD_FIRST = 1  # the first endpoint is not a vertex
    BAD_SECOND = 2  # the second endpoint is not a vertex
    COINCIDENT = 3  # both endpoints are at the same place


@cython.ccall
def check_endpoints(
    seg: cython.longlong[:, ::1], dup: cython.longlong[::1], xy: cython.double[:, ::1],
    rows: cython.longlong[:, ::1], verdict: cython.schar[::1],
) -> Index:
    """Each segment ``seg[i]`` with endpoints among the ``xy.shape[0]``
    vertices (an endpoint that duplicates another vertex mapped to the copy
    ``dup`` names) and at two places becomes a row (a, b, i) of ``rows``;
    ``verdict[i]`` says why a segment was left out.  Returns the rows made."""
    n: Index = xy.shape[0]
    kept: Index = 0
    a: Index
    b: Index
    with cython.nogil:
        for i in range(seg.shape[0]):
            a = seg[i, 0]
            b = seg[i, 1]
            if a < 0 or a >= n:
                verdict[i] = BAD_FIRST
                continue
            if b < 0 or b >= n:
                verdict[i] = BAD_SECOND
                continue
            if dup[a] >= 0:
                a = dup[a]
            if dup[b] >= 0:
                b = dup[b]
            if xy[a, 0] == xy[b, 0] and xy[a, 1] == xy[b, 1]:
                verdict[i] = COINCIDENT
                continue
            verdict[i] = KEPT
            rows[kept, 0] = a
            rows[kept, 1] = b
            rows[kept, 2] = i
            kept += 1
    return kept


@cython.ccall
def pair_keys(rows: cython.longlong[:, ::1], keys: cython.longlong[::1]) -> cython.bint:
    """``keys[i]``: one number for the unordered endpoint pair of ``rows[i]``
    (equal keys, equal pairs); False, with ``keys`` unfinished, if an
    endpoint is too large for the key."""
    lo: cython.longlong
    hi: cython.longlong
    with cython.nogil:
        for i in range(rows.shape[0]):
            lo = min(rows[i, 0], rows[i, 1])
            hi = max(rows[i, 0], rows[i, 1])
            if lo < 0 or hi > 2147483647:
                return False
            keys[i] = (lo << 31) | hi
    return True


@cython.ccall
def all_different(sorted_keys: cython.longlong[::1]) -> cython.bint:
    """No two neighbours of ``sorted_keys`` are equal."""
    with cython.nogil:
        for i in range(1, sorted_keys.shape[0]):
            if sorted_keys[i] == sorted_keys[i - 1]:
                return False
    return True
