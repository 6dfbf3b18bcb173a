"""The command workloads: ``ruppert -pq30 A.poly`` against the `triangle` package's script, as processes.

Each side is a whole process, timed from its start to its exit with its peak
resident memory (``instrument.study.bench.memory.run_command``).  Ours is the
``ruppert`` script installed beside the interpreter (a ``ruppert`` found on
PATH may be a version manager's shim, which adds about 0.1 s); Triangle's is
``python triangle_command.py`` (no Triangle program is installed here: the
script reads the file with the `triangle` package, meshes it and writes the
same three files).

Beside the command the workload times what any such command pays before it
meshes anything (after the command's rounds, not interleaved with them): the interpreter alone (``python -c pass``), numpy's import
(the engine's one required dependency) and ``import ruppert_io.cli``; and it
breaks the last one down with ``python -X importtime``.
"""

from __future__ import annotations

import math
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

from .memory import CommandRun, run_command
from .timing import new_row
from .workloads import WORKLOADS, triangle_data_file

#: the script that stands in for Triangle's program
TRIANGLE_SCRIPT = Path(__file__).with_name("triangle_command.py")
#: per run of a command, seconds (a hang fails the workload instead of the benchmark)
COMMAND_TIMEOUT_S = 600.0


@dataclass(frozen=True)
class Environment:
    """Where the commands run: a Python interpreter and its ``ruppert``
    command, and the environment variables they get (None: this process's)."""

    python: Path
    variables: dict | None = None

    @property
    def ruppert(self) -> list[str]:
        exe = self.python.with_name("ruppert")
        if exe.exists():
            return [str(exe)]
        return [str(self.python), "-c", "import sys; from ruppert_io.cli import console; sys.exit(console())"]


def this_environment() -> Environment:
    return Environment(Path(sys.executable))


def prepare(workdir: Path, input_name: str) -> Path:
    """Copy the input file (from the `triangle` package's data) and
    Triangle's script into ``workdir``; the input's path there."""
    src = triangle_data_file(input_name)
    shutil.copy(src, workdir / src.name)
    shutil.copy(TRIANGLE_SCRIPT, workdir / TRIANGLE_SCRIPT.name)
    return workdir / src.name


def side_argv(engine: str, env: Environment, opts: str, path: Path) -> list[str]:
    """The command line of one side, run in the input's folder."""
    if engine == "ours":
        return [*env.ruppert, opts, path.name]
    if engine == "triangle":
        return [str(env.python), TRIANGLE_SCRIPT.name, opts, path.name]
    raise ValueError(f"unknown engine {engine!r}")


def run_side(engine: str, env: Environment, opts: str, path: Path) -> tuple[CommandRun, int]:
    """One run of one side: (time and peak memory, triangles it wrote)."""
    cwd = path.parent
    for old in cwd.glob(f"{path.stem}.1.*"):
        old.unlink()
    run = run_command(side_argv(engine, env, opts, path), cwd, timeout=COMMAND_TIMEOUT_S, env=env.variables)
    ele = cwd / f"{path.stem}.1.ele"
    n = int(ele.read_text().split(None, 1)[0]) if ele.exists() else 0
    return run, n


def floors(env: Environment) -> dict[str, list[str]]:
    """What every run of the command pays before meshing, each as a command of its own."""
    py = str(env.python)
    return {
        "python -c pass": [py, "-c", "pass"],
        "python -c 'import numpy'": [py, "-c", "import numpy"],
        "python -c 'import ruppert_io.cli'": [py, "-c", "import ruppert_io.cli"],
    }


def startup(env: Environment, cwd: Path, repeat: int) -> dict[str, dict[str, float]]:
    """The floors (``floors``), each the best of ``repeat`` runs, with its peak memory (the largest)."""
    got = {}
    for what, argv in floors(env).items():
        runs = [run_command(argv, cwd, timeout=COMMAND_TIMEOUT_S, env=env.variables) for _ in range(repeat)]
        got[what] = {"s": min(r.wall_s for r in runs), "mb": max(r.peak_mb for r in runs)}
    return got


def bench_command(name: str, repeat: int, *, env: Environment | None = None, importtime_runs: int = 3) -> list[dict]:
    """Time a command workload: best of ``repeat`` rounds (ours, then
    Triangle's script), after one untimed run of each side (the files in the
    page cache); then the start-up floors and ``importtime``.  Peak memory is
    the largest of the runs'."""
    import tempfile

    w = WORKLOADS[name]
    env = env or this_environment()
    row = new_row(name, w, "triangle")
    best: dict[str, float] = {}
    peak: dict[str, float] = {}
    sizes: dict[str, int] = {}
    with tempfile.TemporaryDirectory(prefix="ruppert-bench-") as tmp:
        path = prepare(Path(tmp), w.command)
        for engine in ("ours", "triangle"):
            run_side(engine, env, w.opts, path)
        for _ in range(repeat):
            for engine in ("ours", "triangle"):
                run, sizes[engine] = run_side(engine, env, w.opts, path)
                best[engine] = min(best.get(engine, math.inf), run.wall_s)
                peak[engine] = max(peak.get(engine, 0.0), run.peak_mb)
        row["startup"] = startup(env, Path(tmp), repeat)
    row.update(triangles=sizes, ours_s=best["ours"], triangle_s=best["triangle"],
               ratio=best["ours"] / best["triangle"], ours_mb=peak["ours"], triangle_mb=peak["triangle"],
               memory_ratio=peak["ours"] / peak["triangle"])
    row["importtime"] = (importtime(env.python, "ruppert_io.cli", runs=importtime_runs, variables=env.variables)
                         if importtime_runs else [])
    if w.goal is not None:
        row["goal_met"] = row["ours_s"] < w.goal
    row["note"] = ("whole command, subprocess wall time and peak RSS; Triangle's side: "
                   "python triangle_command.py with the triangle package")
    return [row]


# ---------------------------------------------------------------------------------------------
# python -X importtime


@dataclass
class ImportNode:
    name: str
    self_us: int
    cumulative_us: int
    children: list


def parse_importtime(text: str) -> list[ImportNode]:
    """The import tree ``python -X importtime`` prints to standard error
    (children come before their parent, indented two spaces a level): the
    top-level imports, in order."""
    pending: dict[int, list[ImportNode]] = {}
    for line in text.splitlines():
        if not line.startswith("import time:"):
            continue
        fields = line[len("import time:"):].split("|")
        if len(fields) != 3 or not fields[0].strip().isdigit():
            continue  # the header
        raw = fields[2][1:]  # one space after the bar, then two per level
        depth = (len(raw) - len(raw.lstrip(" "))) // 2
        node = ImportNode(raw.strip(), int(fields[0]), int(fields[1]), pending.pop(depth + 1, []))
        pending.setdefault(depth, []).append(node)
    return pending.get(0, [])


def importtime(python: Path, module: str, *, runs: int = 3, min_ms: float = 5.0, depth: int = 4,
               variables: dict | None = None) -> list[dict]:
    """The big items of ``python -X importtime -c "import MODULE"``: every
    import of at most ``depth`` levels that took ``min_ms`` or more
    (cumulative), with its parent chain, as the least of ``runs`` runs
    (the machine's noise only adds)."""
    least: dict[tuple[str, ...], tuple[int, int]] = {}
    order: list[tuple[str, ...]] = []
    for _ in range(runs):
        proc = subprocess.run([str(python), "-X", "importtime", "-c", f"import {module}"], capture_output=True,
                              text=True, timeout=COMMAND_TIMEOUT_S, check=True, env=variables)
        stack = [((), n) for n in reversed(parse_importtime(proc.stderr))]
        while stack:  # depth first, in import order
            parents, node = stack.pop()
            key = (*parents, node.name)
            if key not in least:
                order.append(key)
                least[key] = (node.cumulative_us, node.self_us)
            else:
                least[key] = (min(least[key][0], node.cumulative_us), min(least[key][1], node.self_us))
            if len(key) < depth:
                stack.extend((key, child) for child in reversed(node.children))
    return [{"path": list(k), "cumulative_ms": least[k][0] / 1000, "self_ms": least[k][1] / 1000}
            for k in order if least[k][0] >= min_ms * 1000]
