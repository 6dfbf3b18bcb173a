# cython: language_level=3
"""Refinement's state: its configuration, and what the loop keeps between calls.

``Config`` is fixed when the run starts (switches, strategy, Steiner
points); ``Refiner`` is everything the loop changes: where it is, the
bad-triangle queue, the encroached-subsegment pool, an insertion's scratch
and the trace.  The kernel stops whenever an array is full and resumes
after the driver (``refine/__init__.py``) has grown it, so all of it lives
here, by name, rather than in the kernel's locals.
"""

from __future__ import annotations

import math

import numpy as np

import cython

from ..counters import NAMES
from .order import TRIANGLE

#: Triangle's bucket queue has 4096 FIFO lists; ours goes on past its
#: finest one (order.wide_bucket) to every squared edge between doubles,
#: in lists set up as they are first needed (queues.bucket_make_ready).
TRIANGLE_BUCKETS = 4096
NBUCKETS = 10496

if not cython.compiled:  # compiled, these are state.pxd's enum
    T_SEGMENT, T_CIRCUMCENTER, T_OFFCENTER, T_REJECTED, T_DELETED = range(5)  # trace rows' kinds
#: Trace rows' kinds, by name.
TRACE_KINDS = ("segment", "circumcenter", "offcenter", "rejected", "deleted")


@cython.cclass
class Config:
    """What the switches and options ask of a run (see state.pxd for each field)."""

    def __init__(self, o, strategy: int, offcenter: bool, python_test: bool):
        theta = math.radians(o.min_angle) if o.q else 0.0
        good = math.cos(theta) ** 2
        self.strategy = strategy
        self.diametral = o.D
        self.keep_segments = o.Y
        self.fixed_area = o.max_area > 0
        self.max_area = o.max_area
        self.regional_area = o.var_area
        self.offcenter = offcenter
        self.angle_test = o.q and o.min_angle > 0
        self.builtin_user = o.u and not python_test  # a Python test runs between kernel rounds instead
        self.good_angle = good
        self.lens = (2.0 * good - 1.0) ** 2
        # the off-center sits at 0.95 of the distance where the edge subtends theta
        self.off_constant = 0.475 * math.sqrt((1.0 + math.cos(theta)) / (1.0 - math.cos(theta))) if theta > 0 else 0.0
        self.key_unit = 1.0  # new_refiner sets it from the mesh's extent


@cython.cclass
class Refiner:
    """The refinement loop's state (see state.pxd for each field)."""

    def __init__(self, cfg: Config, *, budget: int, slots: int, queue: int, records: int, trace: bool):
        self.work_begun = np.zeros(len(NAMES), dtype=np.int64)
        # The queue, the pool and the scratch are written before they are
        # read (entries below hsize / log_length / enc_fresh; the scratch
        # within one step): uninitialised memory, which spares a small run
        # zeroing half a megabyte (the allocation took a tenth of la.poly's
        # refinement setup) and a large one nothing (fresh pages are zero).
        self.hkey = np.empty(queue)
        self.hseq = np.empty(queue, dtype=np.int64)
        self.htri = np.empty(queue, dtype=np.int32)  # slots and stamps are int32 in the mesh too
        self.hstamp = np.empty(queue, dtype=np.int32)
        # the buckets must be empty (-1) before a run; Triangle's 4,096 are made
        # so here, the finer ones past them (order.wide_bucket) when first used
        # (queues.bucket_make_ready: setting all 10,496 cost 7 % on a square)
        self.bucket = np.empty((2, NBUCKETS), dtype=np.int64)
        self.bucket[:, :TRIANGLE_BUCKETS] = -1
        self.bucket_ready = TRIANGLE_BUCKETS
        # written before read, as the queue; room for a rejected insertion's
        # fan per four slots (la.poly under pq30 keeps 262 rows at 2,392
        # slots: with 256 it paid a NEED_ROOM round, a tenth of a millisecond)
        self.ghost = np.empty((max(256, slots // 4), 5), dtype=np.int64)
        self.enc = np.empty((records, 4), dtype=np.int64)
        self.cav = np.empty(slots, dtype=np.int64)
        self.fan = np.empty(slots, dtype=np.int64)
        self.bnd = np.empty((slots, 5), dtype=np.int64)
        self.bval = np.empty((slots, 2))
        self.carry = np.empty(slots)
        self.lineage = np.empty((slots, 4), dtype=np.int64)
        self.fan_rec = np.empty((slots, 3), dtype=np.int64)
        self.flips = np.empty((slots, 2), dtype=np.int64)
        # kept between steps, read only where its checks hold (ghosts.note_born)
        self.born = np.zeros((slots, 3), dtype=np.int64)
        self.orient = np.zeros((slots, 3), dtype=np.int64)  # (ghosts.records_known)
        self.trace = np.zeros((1024 if trace else 0, 5), dtype=np.int64)
        self.restart(cfg, budget)

    def restart(self, cfg: Config, budget: int) -> None:
        """Start a run under ``cfg`` with ``budget`` Steiner points, on the
        arrays as they are: every field but the arrays gets its first value.
        The arrays are written before they are read, but for the buckets,
        which must all be empty (-1): so they are when the refiner is new,
        and after ``queues.queue_clear``, which a refiner reused for another
        run (refine.new_refiner) takes first."""
        self.cfg = cfg
        self.phase = 0
        self.budget = budget
        self.current = -1
        self.current_stamp = 0
        self.current_key = 0.0
        self.since_pause = 0
        self.need = 0
        self.error_org = -1
        self.error_dest = -1
        self.error_apex = -1
        self.hsize = 0
        self.seq = 0
        self.top_bucket = -1
        self.log_length = 0
        self.compact_at = 0
        self.nghost = 0
        self.ghost_swapped = False
        self.orient_ready = False
        self.nflips = 0
        self.enc_live = 0
        self.enc_fresh = 0
        self.enc_free = -1
        self.enc_cursor = 0
        self.enc_low = 0
        self.enc_busy = False
        self.acute_slot = -1
        self.acute = 0
        self.ntrace = 0

    @property
    def bucketed(self) -> bool:
        return self.cfg.strategy == TRIANGLE

    def queue_capacity(self) -> int:
        return self.hkey.shape[0]


# The step and trace helpers: compiled, state.pxd's inline definitions (the
# splits call them on every step); the same functions for the pure-Python mode.
if not cython.compiled:

    def step_begins(r: Refiner, work) -> None:
        """Remember the work counters as a step (a split) begins."""
        for i in range(work.shape[0]):
            r.work_begun[i] = work[i]

    def step_undone(r: Refiner, work) -> None:
        """A step that returns NEED_ROOM changed nothing and runs again once the
        arrays have grown: put its tests back out of the counters, so that the
        counts do not depend on how much room the arrays started with."""
        for i in range(work.shape[0]):
            work[i] = r.work_begun[i]

    def trace_full(r: Refiner) -> bool:
        """The trace (if on) lacks room for the rows one more step may write."""
        return r.trace.shape[0] > 0 and r.ntrace + 64 > r.trace.shape[0]

    def trace_row(r: Refiner, kind: int, created: int, deleted: int, steps: int, queue: int) -> None:
        """Append a trace row (if the trace is on)."""
        i = r.ntrace
        if i < r.trace.shape[0]:
            r.trace[i, 0] = kind
            r.trace[i, 1] = created
            r.trace[i, 2] = deleted
            r.trace[i, 3] = steps
            r.trace[i, 4] = queue
            r.ntrace = i + 1
