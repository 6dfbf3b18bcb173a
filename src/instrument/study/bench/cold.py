"""The ``cold`` workload: what a new user waits for, from ``pip install`` to a second mesh.

In a temporary directory: a fresh virtual environment (``python -m venv``, no
system site packages), ``pip install`` of the checkout (the ordinary install,
which compiles the engine's kernels with Cython), then ``ruppert -pq30 A.poly``
twice, each timed with its peak memory; then, for reference, ``pip install
triangle==20250106`` in the same environment and the `triangle` package's
script (``triangle_command.py``) twice.  pip uses its cache as it would for
the user (downloads and the build dependencies' wheels come from it; a wheel
built from a local folder is never cached, so the kernels are always
compiled).

The checkout is copied first (git's tracked and untracked, not ignored
files, as they are on disk: no build folder, no compiled module), so the
install builds from nothing and leaves the checkout as it was.  ``--source``
may name another checkout, an sdist, a wheel or a requirement instead.

It takes minutes (the compile alone is about a CPU minute), so it runs only
when asked for (``--cold``, or the name ``cold``).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from .commands import Environment, importtime, prepare, run_side, startup
from .timing import new_row
from .workloads import WORKLOADS

TRIANGLE_REQUIREMENT = "triangle==20250106"
#: seconds for one pip install or venv (a hang fails the workload instead of waiting forever)
STEP_TIMEOUT_S = 3600.0
#: variables that would point the new environment's Python somewhere else
FOREIGN = ("PYTHONPATH", "PYTHONHOME", "PYTHONSTARTUP", "VIRTUAL_ENV", "PYTHONUSERBASE", "RUPPERT_PURE_PYTHON",
           "RUPPERT_BOUNDSCHECK")


def checkout_root() -> Path | None:
    """The source checkout this ruppert runs from (an editable install), or None."""
    import instrument

    root = Path(instrument.__file__).resolve().parents[2]
    return root if (root / "pyproject.toml").is_file() and (root / "setup.py").is_file() else None


def source_files(root: Path) -> list[Path]:
    """The checkout's files, relative to it: git's tracked and untracked files
    that are not ignored, as they are on disk; without git, every file but
    build products (compiled modules, generated C, build folders, caches)."""
    try:
        out = subprocess.run(["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"], cwd=root,
                             capture_output=True, check=True, timeout=60).stdout
        names = [Path(n) for n in out.decode().split("\0") if n]
        return [n for n in names if (root / n).is_file()]  # deleted, not yet committed
    except (OSError, subprocess.SubprocessError):
        skip_dirs = {".git", "build", "dist", "__pycache__", ".pytest_cache", ".hypothesis"}
        return [p.relative_to(root) for p in root.rglob("*") if p.is_file()
                and not skip_dirs & set(p.relative_to(root).parts)
                and not p.name.endswith((".so", ".pyd", ".c")) and ".egg-info" not in str(p)]


def copy_source(root: Path, dest: Path) -> Path:
    for rel in source_files(root):
        (dest / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(root / rel, dest / rel)
    return dest


def clean_environ() -> dict:
    """This process's environment without what would make the new
    environment's Python or pip look elsewhere."""
    env = {k: v for k, v in os.environ.items() if k not in FOREIGN}
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    return env


class FreshVenv:
    """A new virtual environment under ``root`` for the cold workload: each
    step returns its wall time; ``environment`` is where the commands run."""

    def __init__(self, root: Path, source: str):
        self.root = root
        self.source = source
        self.dir = root / "venv"
        self.log = root / "pip.log"
        self.variables = clean_environ()

    @property
    def environment(self) -> Environment:
        return Environment(self.dir / "bin" / "python", self.variables)

    def _run(self, argv: list[str], what: str) -> float:
        t0 = time.perf_counter()
        with self.log.open("a") as log:
            log.write(f"$ {' '.join(argv)}\n")
            log.flush()
            proc = subprocess.run(argv, stdout=log, stderr=subprocess.STDOUT, cwd=self.root, env=self.variables,
                                  timeout=STEP_TIMEOUT_S, check=False)
        wall = time.perf_counter() - t0
        if proc.returncode != 0:
            tail = self.log.read_text(errors="replace").strip().splitlines()[-15:]
            raise RuntimeError(f"{what} failed (exit {proc.returncode}):\n" + "\n".join(tail))
        return wall

    def create(self) -> float:
        return self._run([sys.executable, "-m", "venv", str(self.dir)], "python -m venv")

    def install(self, requirement: str) -> float:
        python = str(self.environment.python)
        return self._run([python, "-m", "pip", "install", requirement], f"pip install {requirement}")

    def install_ruppert(self) -> float:
        return self.install(self.source)

    def install_triangle(self) -> float:
        return self.install(TRIANGLE_REQUIREMENT)


def resolve_source(source: str | None, workdir: Path) -> str:
    """What pip installs: a copy of the checkout (``source`` None: the one this
    ruppert runs from; or a folder given), or ``source`` as it is (an sdist, a
    wheel, a requirement).  Raises ``ValueError`` when there is no checkout."""
    if source is None:
        root = checkout_root()
        if root is None:
            raise ValueError("cold: this ruppert was not installed from a checkout; give --source "
                             "(a checkout, an sdist, a wheel or a requirement)")
    else:
        root = Path(source)
        if not root.is_dir():
            return source
    return str(copy_source(root.resolve(), workdir / "ruppert-source"))


def bench_cold(name: str = "cold", *, source: str | None = None, make_environment=FreshVenv,
               workdir: Path | None = None, startup_repeat: int = 3) -> list[dict]:
    """Run the cold workload: one row, the first runs as its times, every step
    in ``row["cold"]``; then, in the same environment, the command's start-up
    floors (best of ``startup_repeat``; 0: none) and ``importtime``.

    ``make_environment(root, source)`` makes the environment (``FreshVenv``;
    the tests give one that installs nothing)."""
    w = WORKLOADS[name]
    row = new_row(name, w, "triangle")
    with tempfile.TemporaryDirectory(prefix="ruppert-cold-", dir=workdir) as tmp:
        root = Path(tmp)
        requirement = resolve_source(source, root)
        venv = make_environment(root, requirement)
        steps: dict = {"venv_s": venv.create(), "install_s": venv.install_ruppert()}
        env = venv.environment
        run_dir = root / "run"
        run_dir.mkdir()
        path = prepare(run_dir, w.command)
        sizes = {}
        for which in ("first", "second"):
            run, sizes["ours"] = run_side("ours", env, w.opts, path)
            steps[which] = {"s": run.wall_s, "mb": run.peak_mb}
        steps["triangle_install_s"] = venv.install_triangle()
        for which in ("first", "second"):
            run, sizes["triangle"] = run_side("triangle", env, w.opts, path)
            steps[f"triangle_{which}"] = {"s": run.wall_s, "mb": run.peak_mb}
        floors = startup(env, run_dir, startup_repeat) if startup_repeat else {}
        imports = importtime(env.python, "ruppert_io.cli", runs=3, variables=env.variables) if startup_repeat else []
    row.update(triangles=sizes, ours_s=steps["first"]["s"], triangle_s=steps["triangle_first"]["s"],
               ours_mb=steps["first"]["mb"], triangle_mb=steps["triangle_first"]["mb"])
    row["ratio"] = row["ours_s"] / row["triangle_s"]
    row["memory_ratio"] = row["ours_mb"] / row["triangle_mb"]
    row["cold"] = steps
    if floors:
        row["startup"], row["importtime"] = floors, imports
    row["note"] = (f"fresh venv {steps['venv_s']:.1f} s, pip install {steps['install_s']:.1f} s; first run "
                   f"{steps['first']['s']:.3f} s, second {steps['second']['s']:.3f} s; Triangle's script after pip "
                   f"install {TRIANGLE_REQUIREMENT} ({steps['triangle_install_s']:.1f} s)")
    return [row]
