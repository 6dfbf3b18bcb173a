# cython: language_level=3
"""Work counters: one int64 array, always on, with a name for every slot.

Kernels increment ``work[C_NAME]``; ``as_dict`` gives the Python view that
``Result.work`` exposes.  What is counted, and where:

* ``triangles_created`` / ``triangles_deleted``: finite triangles that appear
  in / disappear from the mesh.  For one Delaunay insertion the count created
  equals the number of triangles incident to the new vertex afterwards,
  whatever the implementation (the paper's measure), so a flip counts one
  created and one deleted.  ``created - deleted`` is always the number of
  triangles in the mesh.  Ghost triangles (outside the hull) are not counted.
* ``incircle_tests`` / ``orient_tests``: every call of the exact predicate, as
  Triangle's statistics count them.
* ``walk_steps``: triangles visited by point location.
* ``flips``: edge flips of any kind.

The counts (and the trace) do not depend on how much room the arrays had:
a refinement step that stops because an array is full takes its tests back
out of the counters before the driver grows the array and the step runs
again (``tests/unit/test_room.py``).
"""

from __future__ import annotations

import numpy as np

import cython

NAMES = (
    "triangles_created",
    "triangles_deleted",
    "incircle_tests",
    "orient_tests",
    "circumcenters",
    "flips",
    "walk_steps",
    "segment_splits",
    "steiner_points",
    "rejected_vertices",
    "deleted_vertices",
    "queue_pops",
    "stale_pops",
    "duplicate_vertices",
    "undone_triangles",
)

# The slots; compiled, they are counters.pxd's enum (the tests check both agree).
if not cython.compiled:
    (
        C_CREATED,
        C_DELETED,
        C_INCIRCLE,
        C_ORIENT,
        C_CIRCUMCENTER,
        C_FLIP,
        C_WALK,
        C_SEGMENT_SPLIT,
        C_STEINER,
        C_REJECTED,
        C_DELETED_VERTEX,
        C_QUEUE_POP,
        C_STALE_POP,
        C_DUPLICATE,
        C_UNDONE,
    ) = range(len(NAMES))


def new_work() -> np.ndarray:
    return np.zeros(len(NAMES), dtype=np.int64)


def as_dict(work: np.ndarray) -> dict[str, int]:
    """The counters by name, as Python ints (``tolist`` converts them all
    in one call: indexing the array slot by slot made a numpy scalar per
    counter, some 15k instructions of a one-triangle run's 600k)."""
    return dict(zip(NAMES, work.tolist()))
