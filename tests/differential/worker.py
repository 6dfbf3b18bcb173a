"""A child process that triangulates on request: Triangle or ours.

    python worker.py triangle|ours

Requests and replies are length-prefixed pickles on stdin and on the
process's original standard output; file descriptor 1 is pointed at a
scratch file instead, so the C text Triangle prints (its error messages,
even with ``Q``) is captured per call and cannot garble the replies.  A
crash (segfault, abort, heap corruption) ends the process: the parent sees
the pipe close and restarts it (``runners.Worker``).
"""

from __future__ import annotations

import ctypes
import os
import pickle
import struct
import sys
import tempfile
import time
import traceback

HEADER = struct.Struct("<Q")


def _read_exact(f, n: int) -> bytes | None:
    buf = b""
    while len(buf) < n:
        chunk = f.read(n - len(buf))
        if not chunk:
            return None
        buf += chunk
    return buf


def _plain(result) -> dict:
    import numpy as np

    return {k: np.asarray(v) for k, v in dict(result).items()}


def main(engine: str) -> int:
    proto = os.fdopen(os.dup(1), "wb", buffering=0)
    scratch = tempfile.TemporaryFile()
    os.dup2(scratch.fileno(), 1)
    sys.stdout = sys.stderr
    libc = ctypes.CDLL(None)
    if engine == "triangle":
        import triangle

        run = triangle.triangulate
    else:
        import instrument

        run = instrument.triangulate
    stdin = sys.stdin.buffer
    while True:
        head = _read_exact(stdin, HEADER.size)
        if head is None:
            return 0
        tri, opts = pickle.loads(_read_exact(stdin, HEADER.unpack(head)[0]))
        scratch.seek(0)
        scratch.truncate()
        t0 = time.perf_counter()
        reply = {}
        try:
            result = run(tri, opts)
            reply["status"] = "ok"
            reply["result"] = _plain(result)
            reply["warnings"] = list(getattr(result, "warnings", []))
        except Exception as exc:  # every kind is reported; the oracle judges which are allowed
            reply["status"] = "error"
            reply["exc_type"] = type(exc).__name__
            reply["exc_mro"] = [c.__name__ for c in type(exc).__mro__]
            reply["message"] = str(exc)
            reply["traceback"] = traceback.format_exc(limit=-6)
        reply["seconds"] = time.perf_counter() - t0
        libc.fflush(None)
        scratch.seek(0)
        reply["stdout"] = scratch.read(4000).decode("utf-8", "replace")
        body = pickle.dumps(reply, protocol=pickle.HIGHEST_PROTOCOL)
        proto.write(HEADER.pack(len(body)) + body)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
