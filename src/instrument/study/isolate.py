"""Run one engine call in a separate process with a time limit and a memory limit.

Why a separate process, and why this design (measured on the project's 2-core
machine with ``dask.distributed`` 2026.8, ``LocalCluster(n_workers=2,
threads_per_worker=1)``):

* compiled kernels (ours and Triangle's C code) cannot be interrupted from inside the
  process (signals wait for the kernel to return), and Triangle can segfault
  (a NaN coordinate, a segment at a duplicate vertex): the only reliable cut
  is to kill a process.
* Relying on Dask alone does not work reliably.  Dask has no per-task time
  limit, so a hang is never cut.  A segfault kills the worker; the nanny
  restarts it and the scheduler reruns every task that was on it.  With
  ``allowed-failures=0`` an innocent task queued on the dying worker was
  reported as ``KilledWorker`` too (one segfaulting task among 8 sleeping
  ones: 2 ``KilledWorker``, 1 lost result, 2 of 2 runs); with the default 3 the
  crash was attributed right, but the crashing task ran 4 times, each time
  taking a worker down (4.8 s against 9.7-11 s for the 9 tasks).
* So each Dask task hands its engine call to a child process of its worker
  (``pebble.ProcessPool`` with one process per calling thread, started with
  ``spawn``: no ``fork`` of a multi-threaded worker) and waits.  The pool
  kills the child when the call passes its time limit (a ``timeout`` row), and
  reports a child that died (``ProcessExpired``: a ``crash`` row naming the
  signal); either way it starts a fresh child for the next call and the Dask
  worker never notices.  Measured with the same 8 tasks plus a segfault and a
  100 s sleep cut at 2 s: every innocent task ``ok``, the crash and the
  timeout each recorded once, no worker restarted.  The child is reused
  between calls, so the engine's imports and compiled kernels are loaded once
  per child, not once per task (a fresh interpreter costs about 1.3 s).
* The memory limit is the child's address-space limit (``RLIMIT_AS``, set
  for each call): an engine that grows past it gets ``MemoryError`` (a
  ``memory`` row) instead of waking the system's out-of-memory killer.  It
  counts the interpreter and libraries too (about 0.5 GiB).

A Dask worker process is daemonic by default, and a daemonic process may not
start children: the embedded cluster sets ``distributed.worker.daemon`` to
False; workers of an existing cluster need the same
(``DASK_DISTRIBUTED__WORKER__DAEMON=False dask worker ...``).

Peak memory: before each call the child resets its resident-set high-water
mark (Linux: ``/proc/self/clear_refs``), so ``peak_mb`` is the call's own
peak (with the interpreter's baseline, ``base_mb``); elsewhere it is the
child's lifetime peak.
"""

from __future__ import annotations

import atexit
import multiprocessing
import os
import signal
import threading
import time
from dataclasses import dataclass

try:
    import resource
except ImportError:  # pragma: no cover - not on this platform
    resource = None

#: extra seconds the caller waits for a child that has not started its call
START_GRACE_S = 120.0


@dataclass
class Outcome:
    """How one isolated call ended."""

    status: str  # ok | error | unsupported | timeout | crash | memory
    value: object = None
    message: str = ""
    error_type: str = ""
    seconds: float = 0.0  # as seen by the caller, process start included
    peak_mb: float | None = None
    base_mb: float | None = None


class DaemonicWorker(RuntimeError):
    """The calling process is daemonic and may not start the engine's process."""


_local = threading.local()
_pools: list = []


def _pool(initializer=None):
    """This thread's pool of one process (a new one after a fork).  Each new
    child runs ``initializer`` (the first one given) before its first call,
    outside every call's time limit."""
    pool = getattr(_local, "pool", None)
    if pool is not None and getattr(_local, "pid", None) == os.getpid() and pool.active:
        return pool
    if multiprocessing.current_process().daemon:
        raise DaemonicWorker(
            "this process is daemonic and cannot start the engine's process: run Dask workers with "
            "distributed.worker.daemon = False (DASK_DISTRIBUTED__WORKER__DAEMON=False)"
        )
    import pebble

    pool = pebble.ProcessPool(max_workers=1, context=multiprocessing.get_context("spawn"),
                              initializer=initializer)
    _local.pool, _local.pid = pool, os.getpid()
    _pools.append(pool)
    return pool


@atexit.register
def shutdown() -> None:
    """Stop every pool this process started (their children end with them)."""
    while _pools:
        pool = _pools.pop()
        if pool.active:
            pool.stop()
            pool.join(timeout=10)
    _local.pool = None


def _status_of(exc: BaseException) -> str:
    if isinstance(exc, MemoryError):
        return "memory"
    if isinstance(exc, NotImplementedError):
        return "unsupported"
    return "error"


def describe(exc: BaseException) -> str:
    """``Type: first line of the message``."""
    text = str(exc).strip().splitlines()
    return f"{type(exc).__name__}: {text[0] if text else ''}".rstrip(": ")


def call(fn, args: tuple = (), kwargs: dict | None = None, *, time_limit: float | None = None,
         memory_limit: int | None = None, initializer=None) -> Outcome:
    """``fn(*args, **kwargs)`` in this thread's child process.

    ``time_limit``: seconds from the start of the call in the child (None: no
    limit).  ``memory_limit``: bytes of address space (None or 0: no limit).
    ``initializer``: run by each new child before its first call (imports,
    compiled kernels), so that loading them is not timed.  ``fn``, its
    arguments and ``initializer`` must be picklable (importable by name).
    Never raises for what the call does: the outcome says it.
    """
    import pebble

    t0 = time.perf_counter()
    try:
        future = _pool(initializer).schedule(_in_child, args=(fn, args, kwargs or {}, memory_limit or 0), timeout=time_limit)
    except DaemonicWorker as exc:
        return Outcome("error", message=str(exc), error_type="DaemonicWorker")
    wait = None if time_limit is None else time_limit + START_GRACE_S
    try:
        got = future.result(timeout=wait)
    except pebble.ProcessExpired as exc:
        return Outcome("crash", message=f"the engine's process died: {_signal_name(exc.exitcode)}",
                       error_type="ProcessExpired", seconds=time.perf_counter() - t0)
    except TimeoutError as exc:
        if exc.__cause__ is not None:  # raised by fn itself, in the child
            return Outcome("error", message=describe(exc), error_type=type(exc).__name__,
                           seconds=time.perf_counter() - t0)
        future.cancel()  # the caller's own wait ran out: the child is killed too
        return Outcome("timeout", message=f"no result within {time_limit:g} s (killed)", error_type="TimeoutError",
                       seconds=time.perf_counter() - t0)
    except BaseException as exc:  # noqa: BLE001  (what fn raised, re-raised here: an outcome)
        if isinstance(exc, KeyboardInterrupt):
            raise
        return Outcome(_status_of(exc), message=describe(exc), error_type=type(exc).__name__,
                       seconds=time.perf_counter() - t0)
    value, peak_mb, base_mb = got
    return Outcome("ok", value=value, seconds=time.perf_counter() - t0, peak_mb=peak_mb, base_mb=base_mb)


def _signal_name(exitcode: int | None) -> str:
    if exitcode is None:
        return "no exit code"
    if exitcode < 0:
        try:
            name = signal.Signals(-exitcode).name
        except ValueError:
            name = f"signal {-exitcode}"
        return f"killed by {name}" + (" (out of memory?)" if name == "SIGKILL" else "")
    return f"exit code {exitcode}"


# ---------------------------------------------------------------------------------------------
# in the child


def _in_child(fn, args, kwargs, memory_limit: int):
    """Run ``fn`` under the memory limit; (value, peak MiB, baseline MiB)."""
    _set_memory_limit(memory_limit)
    base = _reset_peak()
    try:
        value = fn(*args, **kwargs)
        return value, _peak_mb(), base
    finally:
        _set_memory_limit(0)


def _set_memory_limit(limit: int) -> None:
    if resource is None:
        return
    _, hard = resource.getrlimit(resource.RLIMIT_AS)
    soft = hard if limit <= 0 else (limit if hard == resource.RLIM_INFINITY else min(limit, hard))
    resource.setrlimit(resource.RLIMIT_AS, (soft, hard))


def _status_mb(field: str) -> float | None:
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith(field + ":"):
                    return int(line.split()[1]) / 1024.0
    except OSError:
        return None
    return None


def _reset_peak() -> float | None:
    """Reset the resident-set high-water mark where the system allows; the current resident set (MiB)."""
    try:
        with open("/proc/self/clear_refs", "w") as f:
            f.write("5")
    except OSError:
        pass
    return _status_mb("VmRSS")


def _peak_mb() -> float | None:
    peak = _status_mb("VmHWM")
    if peak is None and resource is not None:
        kb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        peak = kb / 1024.0 if os.uname().sysname == "Linux" else kb / 2**20
    return peak
