"""Divide and conquer on several threads, with the sequential run's result.

The recursion's top levels become a tree of groups: its leaves are cut and
triangulated at once, each on its own thread, and each merge runs as soon
as both its halves are done.  A group only touches its own rows of the
points, its own vertices' ``hull_at`` entries, and triangle slots no other
group takes, so the threads need no locks; the kernels release the GIL.

The result is the sequential run's, slot for slot: every group of ``k``
points uses ``divconq.group_slots(k)`` slots, known in advance, so each
leaf and each merge starts allocating at the slot the sequential run would
have reached there (its left half's slots, then its right half's, then the
merge's two ghosts).  The work counters are the sums of the threads' own.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..core.mesh import Mesh
from . import divconq

if TYPE_CHECKING:
    from concurrent.futures import ThreadPoolExecutor

#: Below this many points per leaf, threads cost more than they save.
MIN_LEAF = 1 << 14


@dataclass(frozen=True)
class Group:
    """A group of the recursion: rows ``lo .. hi-1``, cut in ``frame``; its
    triangles take slots from ``first_slot`` on.  A leaf has no halves."""

    lo: int
    hi: int
    frame: int
    first_slot: int
    halves: tuple[Group, Group] | None = None

    @property
    def merge_slot(self) -> int:
        """The first slot of the merge of the halves (after both halves' slots)."""
        left, right = self.halves
        return self.first_slot + divconq.group_slots(left.hi - left.lo) + divconq.group_slots(right.hi - right.lo)


def plan(n: int, alternate: bool, threads: int) -> Group:
    """The top of the recursion on ``n`` points, cut into at least
    ``threads`` leaves where they stay above ``MIN_LEAF`` points."""
    levels = max(0, math.ceil(math.log2(max(threads, 1))))

    def group(lo: int, hi: int, frame: int, first_slot: int, level: int) -> Group:
        if level == 0 or hi - lo < 2 * MIN_LEAF:
            return Group(lo, hi, frame, first_slot)
        mid = lo + ((hi - lo) >> 1)
        child = 1 - frame if alternate else 0
        left = group(lo, mid, child, first_slot, level - 1)
        right = group(mid, hi, child, first_slot + divconq.group_slots(mid - lo), level - 1)
        return Group(lo, hi, frame, first_slot, (left, right))

    return group(0, n, 0, 0, levels)


def workers(top: Group) -> ThreadPoolExecutor:
    """A pool for ``cut_order`` and ``triangulate`` on the tree: one thread
    for each right half (the caller's thread takes the left halves), so
    that a thread waiting for its right half never waits for a free thread.
    (concurrent.futures is imported here, not at the top: most runs are too
    small for threads, and it costs every start-up several milliseconds.)"""
    from concurrent.futures import ThreadPoolExecutor

    def right_halves(g: Group) -> int:
        return 0 if g.halves is None else 1 + right_halves(g.halves[0]) + right_halves(g.halves[1])

    return ThreadPoolExecutor(max_workers=max(1, right_halves(top)), thread_name_prefix="divconq")


def cut_order(
    xy: np.ndarray, ids: np.ndarray, alternate: bool, top: Group, pool: ThreadPoolExecutor, pts: np.ndarray | None = None
) -> np.ndarray:
    """``divconq.cut_order`` with the tree's groups cut at once (``ids``
    sorted in frame 0, and ``pts``, as there)."""
    if pts is None:
        pts = np.ascontiguousarray(xy[ids], dtype=np.float64)
    if alternate:
        _cut(pts, ids, top, pool, True)
    return pts


def _cut(pts: np.ndarray, ids: np.ndarray, g: Group, pool: ThreadPoolExecutor, top: bool) -> None:
    if g.halves is None:
        divconq.cut_group(pts, ids, g.lo, g.hi, g.frame)
        return
    if not top:  # the top group is in frame 0 order already
        divconq.split_group(pts, ids, g.lo, g.hi, g.frame)
    right = pool.submit(_cut, pts, ids, g.halves[1], pool, False)
    _cut(pts, ids, g.halves[0], pool, False)
    right.result()


def triangulate(m: Mesh, top: Group, alternate: bool, pool: ThreadPoolExecutor) -> None:
    """Triangulate the points of ``m`` in cut order (``top`` covering all of
    them, at least two) as ``divconq.triangulate_sorted`` does."""
    hull_at = np.full(top.hi - top.lo, -1, dtype=np.int32)
    parts: list[Mesh] = []
    _build(m, hull_at, top, alternate, pool, parts)
    m.nslot = top.first_slot + divconq.group_slots(top.hi - top.lo)
    m.nlive += sum(part.nlive for part in parts)
    work = np.asarray(m.work)
    for part in parts:
        work += np.asarray(part.work)


def _build(m: Mesh, hull_at: np.ndarray, g: Group, alternate: bool, pool: ThreadPoolExecutor, parts: list[Mesh]):
    """Triangulate group ``g`` on a partner mesh of ``m`` (one per leaf and
    per merge, kept in ``parts`` for their counts); returns its extremes."""
    part = m.partner()
    parts.append(part)  # list.append is atomic under the GIL
    if g.halves is None:
        part.nslot = g.first_slot
        return divconq.triangulate_group(part, hull_at, g.lo, g.hi, g.frame, alternate)
    right = pool.submit(_build, m, hull_at, g.halves[1], alternate, pool, parts)
    left = _build(m, hull_at, g.halves[0], alternate, pool, parts)
    right_found = right.result()
    part.nslot = g.merge_slot
    return divconq.merge_groups(part, hull_at, left, right_found, g.frame)
