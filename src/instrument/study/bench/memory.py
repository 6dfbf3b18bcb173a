"""Peak memory: of one engine call (in a fresh process), and of a whole command.

An engine call's peak is the growth of its process's resident set during the
call: the kernel's high-water mark (VmHWM, reset through
``/proc/self/clear_refs`` just before the call) less the resident size before
it.  Triangle and CGAL allocate in C, where tracemalloc cannot see, and a
sampling thread would not do either: the `triangle` package holds the GIL
for its whole C call, so a sampler sees only what is left after Triangle has
freed its pools (67 MB of its true 156 MB at dt-1e6).  Each call runs in a
fresh process (``instrument.study.isolate``, a new child each time) that
makes the workload's input itself, so no memory an earlier engine left in
the allocator hides this one's, and the benchmark's own copy of the input
is not sent across.

A command's peak is its maximum resident set size as ``/usr/bin/time -v``
reports it (``getrusage(RUSAGE_CHILDREN).ru_maxrss``).  The command runs
under a small launcher rather than straight from the benchmark: Linux keeps
a process's high-water mark across ``exec``, so a child forked (or vforked)
from the large benchmark process would report the benchmark's size.
"""

from __future__ import annotations

import json
import resource
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path


def rss_mb() -> float:
    """Current resident set size of this process in MB."""
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * resource.getpagesize() / 2**20


def reset_peak_rss() -> bool:
    """Reset the kernel's high-water mark of this process's resident set
    (Linux 4.0 and later); False where that is not possible."""
    try:
        with open("/proc/self/clear_refs", "w") as f:
            f.write("5")
        return True
    except OSError:
        return False


def peak_rss_mb() -> float:
    """The high-water mark of this process's resident set in MB (since the
    last ``reset_peak_rss``, or since the process began)."""
    try:
        with open("/proc/self/status") as f:
            kb = next(int(ln.split()[1]) for ln in f if ln.startswith("VmHWM:"))
    except (OSError, StopIteration):
        kb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    return kb / 1024


def call_growth_mb(workload: str, engine: str, strategy: str = "triangle", threads: int | None = None) -> float:
    """In the current process: make the workload's input, warm the engine up,
    then run it once and return the growth of the resident set (MB) during
    that run.  Where the mark cannot be reset it is the peak since the process
    began, which the small warm-up keeps below the run's."""
    from . import engines
    from .workloads import WORKLOADS

    w = WORKLOADS[workload]
    data = w.make()
    engines.warm_up(engine, w.opts, strategy, threads)
    base = rss_mb()
    reset_peak_rss()
    out = engines.run_once(engine, data, w.opts, strategy, threads)
    peak = peak_rss_mb()
    del out
    return max(peak - base, 0.0)


def engine_peak_mb(workload: str, engine: str, strategy: str = "triangle", threads: int | None = None, *,
                   time_limit: float | None = None) -> float:
    """``call_growth_mb`` in a fresh process (``instrument.study.isolate``).
    Raises ``RuntimeError`` when that process fails or passes ``time_limit``."""
    from .. import isolate

    isolate.shutdown()  # the next call starts a new process: nothing left from an earlier engine
    outcome = isolate.call(call_growth_mb, (workload, engine, strategy, threads), time_limit=time_limit)
    isolate.shutdown()  # and gives its memory back now
    if outcome.status != "ok":
        raise RuntimeError(f"{outcome.status}: {outcome.message}")
    return float(outcome.value)


# Run a command, wait for it, and print its wall time, exit status and the
# maximum resident set size of its process (it is the launcher's only child).
LAUNCHER = """\
import json, resource, subprocess, sys, time
t0 = time.perf_counter()
p = subprocess.Popen(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
_, err = p.communicate()
wall = time.perf_counter() - t0
kb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
print(json.dumps({"wall_s": wall, "maxrss_kb": kb, "code": p.returncode, "stderr": err.decode(errors="replace")[-2000:]}))
"""


@dataclass
class CommandRun:
    """One run of a command: wall time (from starting it to its exit, as its
    launcher saw it) and peak resident memory (MB)."""

    wall_s: float
    peak_mb: float


class CommandFailed(RuntimeError):
    """The measured command exited with a nonzero status."""


def run_command(argv: list[str], cwd: Path, *, timeout: float | None = None, env: dict | None = None) -> CommandRun:
    """Run ``argv`` in ``cwd`` under the launcher: its wall time and peak memory."""
    proc = subprocess.run([sys.executable, "-c", LAUNCHER, *argv], cwd=cwd, capture_output=True, text=True,
                          timeout=timeout, env=env, check=False)
    if proc.returncode != 0:
        raise RuntimeError(f"the launcher failed: {proc.stderr.strip()[-500:]}")
    got = json.loads(proc.stdout.strip().splitlines()[-1])
    if got["code"] != 0:
        tail = got["stderr"].strip().splitlines()[-1:] or [""]
        raise CommandFailed(f"{' '.join(map(str, argv[:3]))} ... exited with {got['code']}: {tail[0]}")
    return CommandRun(got["wall_s"], got["maxrss_kb"] / 1024)
