# cython: language_level=3
"""What a kernel reports when it returns: one set of outcomes for all of them.

Kernels never allocate and never raise.  A kernel that runs out of room
stops before changing anything it cannot finish, returns ``NEED_ROOM`` (or
``NEED_BUFFER``), and the Python side grows the mesh or the buffer and
calls it again; the other outcomes the Python side turns into results or
errors.
"""

from __future__ import annotations

import cython

if not cython.compiled:  # compiled, these are status.pxd's enum
    DONE = 0  # finished
    NEED_ROOM = 1  # grow the mesh (or a table) and call again
    NEED_BUFFER = 2  # grow the scratch buffer and call again
    FAILED = 3  # gave up: the input cannot be handled this way
    PRECISION = 4  # a point the algorithm must make is not representable
    PAUSE = 5  # a slice of work is done; call again (lets Python see Ctrl-C)

NAMES = {DONE: "done", NEED_ROOM: "need room", NEED_BUFFER: "need buffer", FAILED: "failed", PRECISION: "precision", PAUSE: "pause"}
