"""Running a case through Triangle and through ours, each in its own process.

Triangle can crash the interpreter or hang, and ours must never take the
test session down with it either, so both run in persistent child
processes (``worker.py``): started once per session, restarted after a
crash or a timeout, and every call has a deadline: its CPU time, so that
the verdict does not depend on the machine's load, with a wall-time ceiling.  ``Outcome`` is what a
call gave: a result, an exception (type and message), a crash (signal) or a
timeout.
"""

from __future__ import annotations

import os
import pickle
import select
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .cases import Case
from .families import bbox_area

WORKER = Path(__file__).with_name("worker.py")
ROOT = Path(__file__).resolve().parents[2]

TRIANGLE_TIMEOUT = 10.0
OURS_TIMEOUT = 20.0
#: a call ends after its timeout in CPU time or this many times it in wall time
WALL_FACTOR = 4.0
#: ... and a confirming call in a new process after this many times it: a
#: campaign at nice 19 on a loaded machine can get a few percent of a core
#: (2.8 s of CPU in 80 s of wall time), so the confirmation, which decides
#: whether a failure is recorded, is held to the CPU deadline; a process
#: that waits for nothing still ends
CONFIRM_WALL_FACTOR = 20.0
#: the first calls to ours import the compiled kernels (a bound for a machine under heavy load)
OURS_STARTUP_TIMEOUT = 900.0

# inputs that make ours load every kernel a case may need before any case is timed
_SQUARE = {
    "vertices": np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.5, 0.5]]),
    "segments": np.array([[0, 1], [1, 2], [2, 3], [3, 0]]),
}
_WARMUP = ("pq30a0.1enjzQ", "puiQ")


@dataclass
class Outcome:
    """What one call gave.  ``status``: ok, error, crash or timeout."""

    status: str
    result: dict | None = None
    exc_type: str = ""
    exc_mro: list = field(default_factory=list)
    message: str = ""
    traceback: str = ""
    stdout: str = ""
    seconds: float = 0.0
    warnings: list = field(default_factory=list)

    def summary(self) -> str:
        if self.status == "ok":
            r = self.result or {}
            nt = len(r.get("triangles", ()))
            return f"a mesh: {len(r.get('vertices', ()))} vertices, {nt} triangles"
        if self.status == "error":
            text = self.message.strip().splitlines()[0] if self.message.strip() else "(no message)"
            c = " ".join(self.stdout.split())[:200]
            return f"raises {self.exc_type}: {text}" + (f" [prints: {c}]" if c else "")
        return f"{self.status}: {self.message}"


class Worker:
    """One persistent child process running ``engine`` ("triangle" or "ours")."""

    def __init__(self, engine: str, timeout: float, startup_timeout: float | None = None,
                 wall_factor: float = WALL_FACTOR):
        self.engine = engine
        self.timeout = timeout
        self.startup_timeout = startup_timeout or timeout
        self.wall_factor = wall_factor
        self.proc: subprocess.Popen | None = None
        self.restarts = 0
        self._stderr = None

    def _start(self) -> None:
        self._stderr = tempfile.TemporaryFile()
        env = dict(os.environ)
        env["PYTHONPATH"] = str(ROOT) + os.pathsep + env.get("PYTHONPATH", "")
        self.proc = subprocess.Popen(
            [sys.executable, str(WORKER), self.engine],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=self._stderr,
            env=env,
        )
        if self.engine == "ours":
            for opts in _WARMUP:
                out = self._call(_SQUARE, opts, self.startup_timeout)
                if out.status in ("crash", "timeout"):
                    raise RuntimeError(f"ours' worker failed to start on {opts!r}: {out.summary()}")

    def stop(self) -> None:
        if self.proc is not None:
            self.proc.kill()
            self.proc.wait()
            self.proc = None

    def call(self, tri: dict, opts: str, timeout: float | None = None) -> Outcome:
        if self.proc is None or self.proc.poll() is not None:
            if self.proc is not None:
                self.restarts += 1
            self._start()
        return self._call(tri, opts, timeout or self.timeout)

    def _stderr_tail(self) -> str:
        try:
            self._stderr.seek(0)
            return self._stderr.read()[-600:].decode("utf-8", "replace")
        except (OSError, ValueError):
            return ""

    def _call(self, tri: dict, opts: str, timeout: float) -> Outcome:
        body = pickle.dumps((tri, opts), protocol=pickle.HIGHEST_PROTOCOL)
        t0 = time.perf_counter()
        cpu0 = self._cpu_seconds()
        try:
            self.proc.stdin.write(len(body).to_bytes(8, "little") + body)
            self.proc.stdin.flush()
            head = self._read(8, t0, cpu0, timeout)
            reply = pickle.loads(self._read(int.from_bytes(head, "little"), t0, cpu0, timeout + 5.0))
        except TimeoutError:
            cpu = self._cpu_seconds() - cpu0
            self.stop()
            return Outcome("timeout", message=f"no answer within {timeout:g} s of CPU time "
                           f"({cpu:.1f} s CPU, {time.perf_counter() - t0:.1f} s wall)",
                           seconds=time.perf_counter() - t0)
        except (EOFError, BrokenPipeError, OSError):
            code = self.proc.wait()
            tail = self._stderr_tail()
            self.proc = None
            return Outcome("crash", message=f"exit code {code}; stderr: {tail.strip()[-300:]}",
                           seconds=time.perf_counter() - t0)
        return Outcome(
            reply["status"],
            result=reply.get("result"),
            exc_type=reply.get("exc_type", ""),
            exc_mro=reply.get("exc_mro", []),
            message=reply.get("message", ""),
            traceback=reply.get("traceback", ""),
            stdout=reply.get("stdout", ""),
            seconds=reply.get("seconds", 0.0),
            warnings=reply.get("warnings", []),
        )

    def _cpu_seconds(self) -> float:
        """The worker's CPU time so far (user and system), or -1 where
        /proc cannot tell (the deadline is then on wall time alone)."""
        try:
            with open(f"/proc/{self.proc.pid}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
            return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
        except (OSError, ValueError, IndexError, AttributeError):
            return -1.0

    def _read(self, n: int, t0: float, cpu0: float, timeout: float) -> bytes:
        """n bytes of the reply, waiting while the call has used less than
        ``timeout`` seconds of CPU time (on a loaded machine a call's wall
        time can be many times its CPU time, and a hang is a run that goes
        on computing), and at most ``wall_factor`` times that in wall time (a
        worker that waits for nothing also ends)."""
        fd = self.proc.stdout.fileno()
        buf = b""
        while len(buf) < n:
            wall = time.perf_counter() - t0
            cpu = self._cpu_seconds() - cpu0 if cpu0 >= 0 else wall
            if cpu >= timeout or wall >= self.wall_factor * timeout:
                raise TimeoutError
            ready, _, _ = select.select([fd], [], [], min(1.0, max(timeout - cpu, 0.05)))
            if not ready:
                continue
            chunk = os.read(fd, min(n - len(buf), 1 << 20))
            if not chunk:
                raise EOFError
            buf += chunk
        return buf


class Runners:
    """A Triangle worker and an ours worker for one session."""

    def __init__(self, triangle_timeout: float = TRIANGLE_TIMEOUT, ours_timeout: float = OURS_TIMEOUT):
        self.triangle = Worker("triangle", triangle_timeout)
        self.ours = Worker("ours", ours_timeout, OURS_STARTUP_TIMEOUT)
        self.ours_timeout = ours_timeout

    def close(self) -> None:
        self.triangle.stop()
        self.ours.stop()

    def materialize(self, case: Case) -> Case | None:
        """A case whose input is complete: for a generated ``r`` case, the mesh
        Triangle makes of the PSLG with ``premesh``, with per-triangle area
        bounds.  None when Triangle makes no mesh of it."""
        if not case.premesh:
            return case
        out = self.triangle.call(case.input, case.premesh)
        if out.status != "ok" or len(out.result.get("triangles", ())) == 0:
            return None
        r = out.result
        tri = {"vertices": r["vertices"], "triangles": r["triangles"]}
        for key in ("vertex_markers", "segments", "segment_markers", "holes"):
            if key in r:
                tri[key] = r[key]
        box = bbox_area(case.input)
        f = np.resize(np.asarray(case.area_factors or (0.0,), dtype=np.float64), len(tri["triangles"]))
        tri["triangle_max_area"] = np.where(f > 0, f * box, -1.0).reshape(-1, 1)
        meta = dict(case.meta, premesh=case.premesh)
        return Case(family=case.family, switches=case.switches, input=tri, meta=meta)

    def run_triangle(self, tri: dict, opts: str) -> Outcome:
        return self.triangle.call(tri, opts)

    def run_ours(self, tri: dict, opts: str) -> Outcome:
        return self.ours.call(tri, opts)

    def run_ours_fresh(self, tri: dict, opts: str) -> Outcome:
        """Ours in a new process: a failure seen in the persistent worker is
        confirmed here, so an earlier case that corrupted the worker's heap
        cannot be blamed on this one."""
        return _fresh(Worker("ours", self.ours_timeout, OURS_STARTUP_TIMEOUT, CONFIRM_WALL_FACTOR), tri, opts)

    def run_triangle_fresh(self, tri: dict, opts: str) -> Outcome:
        """Triangle in a new process: on some inputs (a segment from a
        duplicate vertex Triangle has dropped) its answer depends on what its
        process's heap held before, and the same input gives a mesh in the
        persistent worker and a segmentation fault in a new one."""
        return _fresh(Worker("triangle", self.triangle.timeout, wall_factor=CONFIRM_WALL_FACTOR), tri, opts)


def _fresh(w: Worker, tri: dict, opts: str) -> Outcome:
    """One call in the new worker ``w``, then its exit: a call that returned
    but corrupted the heap (which often aborts only at exit) is a crash."""
    try:
        out = w.call(tri, opts)
        if w.proc is not None:
            w.proc.stdin.close()
            try:
                code = w.proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                code = None
            if code != 0 and out.status != "crash":
                tail = w._stderr_tail().strip()[-300:]
                return Outcome("crash", result=out.result, message=f"exit code {code} after the call returned "
                               f"{out.summary()}; stderr: {tail}", seconds=out.seconds)
        return out
    finally:
        w.stop()
