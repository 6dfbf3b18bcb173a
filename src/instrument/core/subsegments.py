# cython: language_level=3
"""Subsegment records: one per constrained edge piece.

A constrained edge carries the number of its record in ``Mesh.seg`` (on
both sides).  The record keeps what the piece inherits from the input
segment it lies on: the boundary marker, the input segment's index (-1 for
hull segments made by ``-c`` or for refinement), and the end vertices of the
segment as it was first recovered (refinement's small-angle rule measures
from them).  Splitting a subsegment gives one half a new record, as
Triangle does.
"""

from __future__ import annotations

import numpy as np

from .filled import filled

import cython
from cython.cimports.instrument.core.mesh import Index


def _widened(a, rows: int, fill):
    a = np.asarray(a)
    out = filled((rows,) + a.shape[1:], fill, a.dtype)
    out[: a.shape[0]] = a
    return out


@cython.cclass
class Subsegments:
    """The record table (see the module docstring); ``count`` rows are in use."""

    def __init__(self, capacity: int):
        capacity = max(int(capacity), 1)
        self.marker = np.zeros(capacity, dtype=np.int32)
        self.source = filled(capacity, -1, np.int32)
        self.ends = filled((capacity, 2), -1, np.int32)
        self.count = 0

    @property
    def capacity(self) -> int:
        return self.marker.shape[0]

    def grow(self, room: int) -> None:
        """Make room for at least ``room`` more records (doubling)."""
        want = self.count + int(room)
        if want <= self.marker.shape[0]:
            return
        cap = max(2 * self.marker.shape[0], want)
        self.marker = _widened(self.marker, cap, 0)
        self.source = _widened(self.source, cap, -1)
        self.ends = _widened(self.ends, cap, -1)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def new_record(s: Subsegments, marker: cython.int, source: cython.int, a: Index, b: Index) -> Index:
    """A new record on the segment from ``a`` to ``b``; -1 if the table is full."""
    r: Index = s.count
    if r >= s.marker.shape[0]:
        return -1
    s.count = r + 1
    s.marker[r] = marker
    s.source[r] = source
    s.ends[r, 0] = cython.cast(cython.int, a)
    s.ends[r, 1] = cython.cast(cython.int, b)
    return r
