#!/usr/bin/env python
"""Benchmark ruppert's engine against Triangle (the `triangle` package) and CGAL Mesh_2.

    python scripts/bench.py                  # every workload
    python scripts/bench.py dt quad          # workloads whose name starts with "dt" or "quad"
    python scripts/bench.py quad --strategies triangle,fifo
    python scripts/bench.py --markdown docs/compare/bench.md --json docs/compare/bench.json
    python scripts/bench.py square --profile # where our time goes, phase by phase

Workloads (name: input, switches, goal):

  dt-1e5, dt-1e6   Delaunay of 10^5 / 10^6 uniform random points, no switches;
                   goal: within 1.5x Triangle's time.
  cdt-1e5          a wavy polygon with 16 wavy holes, 10^5 vertices, ``p``.
  square-q30a1e-6  quality mesh of the unit square, ``pq30a0.000001`` (about
                   1.6 million triangles); goal: within 1.5x.
  la-q30           la.poly from the `triangle` package's data folder, ``pq30``;
                   goal: within 1.5x.
  quad-12800       Barbic and Miller's quadratic example I(12800)
                   (``instrument.quadratic.example``), ``pq20``; one row per
                   strategy (``--strategies``, default all of
                   ``instrument.strategies()``); goal: the least-work strategy
                   (fewest triangles created) at least 5x faster than Triangle.
  cli-A            the command ``ruppert -pq30 A.poly`` (data/A.poly), a
                   subprocess's wall time with numba's cache warm, against
                   ``python -c`` running the `triangle` package on the same file
                   (read with ``triangle.load``, mesh, write A.1.node/.ele/.poly in
                   Triangle's formats): no Triangle command-line program is
                   installed here; goal: under 1 second.

Every engine runs on the same input in one process, interleaved (each round
runs ours, then Triangle, then CGAL), best of ``--repeat`` rounds; numba's
compilation is excluded (every kernel runs once on a tiny input first, with
the same switches and strategy).  Our engine always counts its work; its
counters (triangles created, incircle tests) are printed next to Triangle's
statistics, which come from one extra untimed run of Triangle with ``V``
(``--no-stats`` skips it).

CGAL (the ``cgal`` package's SWIG bindings) runs where it has a counterpart:
the Delaunay workloads through ``Delaunay_triangulation_2`` (one bulk insert,
which sorts the points spatially), the others through Mesh_2 exactly as
``scripts/compare.py`` runs it (``instrument.study.cgal_engine``: constrained Delaunay
triangulation, holes as seeds, ``q<angle>`` -> shape bound ``b = sin^2(angle)``,
``a<area>`` -> edge bound ``S = sqrt(4 area / sqrt 3)``).  CGAL's time runs
from the numpy array to the finished triangulation, so it includes making one
``Point_2`` per vertex in Python; reading the mesh back is not timed.  CGAL
makes a different mesh (diametral circles, circumcenters, an edge-length bound
in place of an area bound), so compare its triangle count too.

Peak memory is measured separately, each engine in a fresh subprocess
(Triangle and CGAL allocate in C, where tracemalloc cannot see), as the growth
of the process's resident set size during one run: the kernel's high-water
mark (VmHWM, reset through /proc/self/clear_refs just before the run) less the
resident size before it.  Sampling from a Python thread would not do: the
`triangle` package holds the GIL for the whole C call, so a sampler sees only
what is left after Triangle has freed its pools (67 MB of its true 156 MB at
dt-1e6).  For cli-A it is the peak resident set size of the whole command.
"""

from __future__ import annotations

import argparse
import gc
import json
import math
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


# ---------------------------------------------------------------------------------------------
# inputs


def uniform(n: int, seed: int = 1) -> dict:
    return {"vertices": np.random.default_rng(seed).random((n, 2))}


def polygon_with_holes(n: int, holes: int = 16, seed: int = 2) -> dict:
    """A wavy outer polygon of n/2 vertices and ``holes`` wavy round holes
    sharing the other n/2, as segments; one hole point per hole."""
    rng = np.random.default_rng(seed)
    loops, centers = [], []
    outer = n // 2
    ang = np.linspace(0, 2 * np.pi, outer, endpoint=False)
    r = 1 + 0.05 * np.sin(7 * ang) + 0.2 / outer * rng.random(outer)  # noise below the spacing: simple
    loops.append(np.c_[r * np.cos(ang), r * np.sin(ang)])
    side = int(np.ceil(np.sqrt(holes)))
    per = (n - outer) // holes
    for h in range(holes):
        c = (np.array([h % side, h // side]) + 0.5) / side * 1.2 - 0.6
        a = np.linspace(0, 2 * np.pi, per, endpoint=False)
        rr = 0.25 / side * (1 + 0.1 * np.sin(5 * a))
        loops.append(c + np.c_[rr * np.cos(a), rr * np.sin(a)])
        centers.append(c)
    verts, segs, start = [], [], 0
    for loop in loops:
        k = len(loop)
        verts.append(loop)
        idx = np.arange(k) + start
        segs.append(np.c_[idx, np.roll(idx, -1)])
        start += k
    return {"vertices": np.vstack(verts), "segments": np.vstack(segs), "holes": np.array(centers)}


def unit_square() -> dict:
    return {
        "vertices": np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]),
        "segments": np.array([[0, 1], [1, 2], [2, 3], [3, 0]]),
    }


def triangle_data_file(name: str) -> Path:
    """A sample file shipped in the `triangle` package's data folder."""
    import triangle

    return Path(triangle.__file__).resolve().parent / "data" / name


def package_poly(name: str) -> dict:
    """A sample .poly of the `triangle` package, read by Triangle's rules
    (``ruppert_io.read``; the package's own loader misreads region lines)."""
    import ruppert_io

    return ruppert_io.read(triangle_data_file(name))


def quadratic(n: int) -> dict:
    from instrument.quadratic import example

    return example(n)


@dataclass(frozen=True)
class Workload:
    make: Callable[[], dict] | None  # None: a command-line workload
    opts: str
    label: str  # what the input is, for the tables
    goal: float | None = None  # ratio to Triangle's time (cli: seconds)
    cgal: bool = True  # CGAL has a counterpart
    sweep: bool = False  # one row per strategy (--strategies)
    cli_file: str = ""  # cli workloads: the input file, relative to ROOT


WORKLOADS: dict[str, Workload] = {
    "dt-1e5": Workload(lambda: uniform(10**5), "", "10^5 uniform random points", goal=1.5),
    "dt-1e6": Workload(lambda: uniform(10**6), "", "10^6 uniform random points", goal=1.5),
    "cdt-1e5": Workload(lambda: polygon_with_holes(10**5), "p", "polygon with 16 holes, 10^5 vertices"),
    "square-q30a1e-6": Workload(unit_square, "pq30a0.000001", "unit square", goal=1.5),
    "la-q30": Workload(lambda: package_poly("la.poly"), "pq30", "la.poly (triangle package)", goal=1.5),
    "quad-12800": Workload(lambda: quadratic(12800), "pq20", "quadratic example I(12800)", goal=0.2, sweep=True),
    "cli-A": Workload(None, "-pq30", "`ruppert -pq30 A.poly`, whole command", goal=1.0, cgal=False,
                      cli_file="data/A.poly"),
}


# ---------------------------------------------------------------------------------------------
# engines


def run_engine(engine: str, data: dict, opts: str, strategy: str = "triangle"):
    """One run: ours (``instrument.triangulate``), Triangle (the `triangle`
    package, as ``scripts/compare.py`` calls it) or CGAL (``run_cgal``)."""
    if engine == "ours":
        import instrument

        return instrument.triangulate(data, opts, strategy=strategy)
    if engine == "triangle":
        from instrument.study.triangle_engine import run_triangle

        return run_triangle(data, opts, repeat=1)[0]
    if engine == "cgal":
        return run_cgal(data, opts)
    raise ValueError(f"unknown engine {engine!r}")


def warm_up(engine: str, opts: str, strategy: str = "triangle") -> None:
    """Compile (or load from numba's cache) every kernel the switches use, on a
    tiny input; import the other engines (and ``instrument.study``'s runners,
    which every runner goes through), so that nothing measured later imports."""
    from instrument.study import ours_engine, triangle_engine  # noqa: F401

    if engine == "ours":
        ours_engine.warm_up(opts, strategy)
    elif engine == "triangle":
        import triangle  # noqa: F401
    elif engine == "cgal":
        from CGAL import CGAL_Mesh_2, CGAL_Triangulation_2  # noqa: F401


class CgalRun:
    """What ``run_cgal`` made: the triangulation, and how to count its triangles."""

    def __init__(self, tri, in_domain: bool, core_s: float):
        self.tri = tri
        self.in_domain = in_domain
        self.core_s = core_s  # the C++ call alone: bulk insert, or refine_mesh / init

    def triangles(self) -> int:
        """Triangles of the mesh (in the domain, for Mesh_2); iterates in Python."""
        if not self.in_domain:
            return int(self.tri.number_of_faces())
        if self.tri.dimension() != 2:
            return 0
        return sum(1 for f in self.tri.finite_faces() if f.is_in_domain())

    def __len__(self) -> int:
        return self.triangles()


def run_cgal(data: dict, opts: str) -> CgalRun:
    """CGAL's counterpart of one workload, without the read-out.

    No switches (a Delaunay triangulation): ``Delaunay_triangulation_2`` with
    one bulk insert.  Otherwise Mesh_2 as ``instrument.study.cgal_engine.run_cgal``
    does it (its building blocks, so the criteria and the domain are the same
    as in ``scripts/compare.py``)."""
    from CGAL.CGAL_Kernel import Point_2

    from instrument.study.cgal_engine import cgal_build, cgal_criteria
    from instrument.switches import parse

    xy = np.asarray(data["vertices"], dtype=np.float64).reshape(-1, 2)
    o = parse(opts)
    if not (o.p or o.c or o.quality):
        from CGAL import CGAL_Triangulation_2 as T2

        pts = [Point_2(x, y) for x, y in xy.tolist()]
        dt = T2.Delaunay_triangulation_2()
        t0 = time.perf_counter()
        dt.insert(pts)
        return CgalRun(dt, False, time.perf_counter() - t0)
    from CGAL import CGAL_Mesh_2 as M

    b, size, _ = cgal_criteria(opts)
    segs = data.get("segments") if o.p else None
    segs = None if segs is None or len(segs) == 0 else np.asarray(segs).reshape(-1, 2)
    holes = data.get("holes") if (o.p and not o.O) else None
    holes = [] if holes is None else np.asarray(holes, dtype=np.float64).reshape(-1, 2)
    cdt = cgal_build(M, Point_2, xy, segs, not o.p or o.c)
    mesher = M.Default_Delaunay_mesher_2(cdt, M.Delaunay_mesh_size_criteria_2(b, size))
    mesher.set_seeds([Point_2(float(x), float(y)) for x, y in holes], False)
    t0 = time.perf_counter()
    if o.quality:
        mesher.refine_mesh()
    else:
        mesher.init()  # marks the domain only
    return CgalRun(cdt, True, time.perf_counter() - t0)


# ---------------------------------------------------------------------------------------------
# the command-line workload

# Triangle's side of cli-A: the `triangle` package reads the file, meshes it and
# writes what Triangle's program would (.1.node, .1.ele, .1.poly), in plain Python.
TRIANGLE_CLI = r"""
import sys, os, triangle
sw, path = sys.argv[1].lstrip("-"), sys.argv[2]
base = os.path.splitext(path)[0]
d = triangle.load(os.path.dirname(path) or ".", os.path.basename(base))
out = triangle.triangulate(d, sw)
v, vm, t = out["vertices"], out["vertex_markers"].ravel(), out["triangles"]
s, sm = out["segments"], out["segment_markers"].ravel()
h = out.get("holes", [])
tail = "# Generated by triangle -" + sw + " " + path + "\n"
with open(base + ".1.node", "w") as f:
    f.write("%d  2  0  1\n" % len(v))
    f.writelines("%4d    %.17g  %.17g    %d\n" % (i + 1, x, y, m) for i, ((x, y), m) in enumerate(zip(v, vm)))
    f.write(tail)
with open(base + ".1.ele", "w") as f:
    f.write("%d  3  0\n" % len(t))
    f.writelines("%4d    %4d  %4d  %4d\n" % (i + 1, a + 1, b + 1, c + 1) for i, (a, b, c) in enumerate(t))
    f.write(tail)
with open(base + ".1.poly", "w") as f:
    f.write("0  2  0  1\n%d  1\n" % len(s))
    f.writelines("%4d    %4d  %4d    %d\n" % (i + 1, a + 1, b + 1, m) for i, ((a, b), m) in enumerate(zip(s, sm)))
    f.write("%d\n" % len(h))
    f.writelines("%4d   %.17g  %.17g\n" % (i + 1, x, y) for i, (x, y) in enumerate(h))
    f.write(tail)
"""


def cli_command(engine: str, opts: str, path: str) -> list[str]:
    if engine == "ours":
        # the script pip installed beside this interpreter: a `ruppert` found on
        # PATH may be a version manager's shim (pyenv's adds about 0.1 s)
        exe = Path(sys.executable).with_name("ruppert")
        if exe.exists():
            return [str(exe), opts, path]
        return [sys.executable, "-c", "import sys; from ruppert_io.cli import console; sys.exit(console())", opts, path]
    return [sys.executable, "-c", TRIANGLE_CLI, opts, path]


def run_cli(engine: str, opts: str, path: Path, cwd: Path) -> tuple[float, int]:
    """(wall seconds, triangles written) of one run of the command."""
    for old in cwd.glob(f"{path.stem}.1.*"):
        old.unlink()
    t0 = time.perf_counter()
    proc = subprocess.run(cli_command(engine, opts, path.name), cwd=cwd, stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True, check=False)
    wall = time.perf_counter() - t0
    if proc.returncode != 0:
        raise RuntimeError(f"{engine} command failed ({proc.returncode}): {proc.stderr.strip()[-300:]}")
    ele = cwd / f"{path.stem}.1.ele"
    n = int(ele.read_text().split(None, 1)[0]) if ele.exists() else 0
    return wall, n


# A child's maximum resident set size counts the memory of the process it was
# forked from (Linux keeps the high-water mark across exec), so the command runs
# under this small launcher, not straight from the (large) benchmark process.
MAXRSS = (
    "import os, subprocess, sys\n"
    "p = subprocess.Popen(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)\n"
    "_, status, usage = os.wait4(p.pid, 0)\n"
    "print(usage.ru_maxrss, os.waitstatus_to_exitcode(status))\n"
)


def cli_peak_mb(engine: str, opts: str, path: Path, cwd: Path) -> float:
    """Peak resident set size (MB) of one run of the command."""
    out = subprocess.run([sys.executable, "-c", MAXRSS, *cli_command(engine, opts, path.name)], cwd=cwd,
                         capture_output=True, text=True, check=True)
    kb, code = out.stdout.split()
    if int(code) != 0:
        raise RuntimeError(f"{engine} command failed ({code})")
    return int(kb) / 1024


# The least any numba program pays at start: import numba and call one cached kernel.
NUMBA_FLOOR = (
    "import numpy as np\n"
    "from numba import njit\n"
    "@njit(cache=True)\n"
    "def total(a):\n"
    "    s = 0.0\n"
    "    for x in a:\n"
    "        s += x\n"
    "    return s\n"
    "total(np.arange(4.0))\n"
)


def bench_cli(name: str, w: Workload, repeat: int, memory: bool) -> list[dict]:
    src = ROOT / w.cli_file
    with tempfile.TemporaryDirectory(prefix="ruppert-bench-") as tmp:
        cwd = Path(tmp)
        shutil.copy(src, cwd / src.name)
        (cwd / "numba_floor.py").write_text(NUMBA_FLOOR)
        alone = {"import": [sys.executable, "-c", "import ruppert_io.cli"],
                 "floor": [sys.executable, "numba_floor.py"]}
        subprocess.run(alone["floor"], cwd=cwd, check=True)  # compiles it into its cache
        for engine in ("ours", "triangle"):  # numba's cache warm, files in the page cache
            run_cli(engine, w.opts, cwd / src.name, cwd)
        best = {"ours": math.inf, "triangle": math.inf, "import": math.inf, "floor": math.inf}
        sizes = {}
        for _ in range(repeat):
            for engine in ("ours", "triangle"):
                wall, n = run_cli(engine, w.opts, cwd / src.name, cwd)
                best[engine] = min(best[engine], wall)
                sizes[engine] = n
            for what, command in alone.items():
                t0 = time.perf_counter()
                subprocess.run(command, cwd=cwd, check=True)
                best[what] = min(best[what], time.perf_counter() - t0)
        mem = {e: cli_peak_mb(e, w.opts, cwd / src.name, cwd) for e in ("ours", "triangle")} if memory else {}
    row = new_row(name, w, "triangle")
    row.update(triangles=sizes, ours_s=best["ours"], triangle_s=best["triangle"],
               ratio=best["ours"] / best["triangle"], import_s=best["import"], numba_floor_s=best["floor"])
    if memory:
        row.update(ours_mb=mem["ours"], triangle_mb=mem["triangle"],
                   memory_ratio=mem["ours"] / max(mem["triangle"], 1e-9))
    row["goal_met"] = row["ours_s"] < w.goal
    row["note"] = (f"`python -c 'import ruppert_io.cli'` alone: {best['import']:.3f} s; a script that imports numba "
                   f"and calls one cached kernel (numba's floor): {best['floor']:.3f} s. Subprocess wall time and "
                   "peak RSS of the whole command; Triangle's side: python -c with the triangle package")
    return [row]


# ---------------------------------------------------------------------------------------------
# memory


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
    with open("/proc/self/status") as f:
        kb = next(int(ln.split()[1]) for ln in f if ln.startswith("VmHWM:"))
    return kb / 1024


def peak_memory_mb(workload: str, engine: str, strategy: str = "triangle") -> float:
    """Peak growth of resident memory (MB) while one engine runs the workload
    once, in a fresh process: the high-water mark during the run less the
    resident size before it.  Where the mark cannot be reset, it is the peak
    since the process began, which the small warm-up keeps below the run's."""
    code = f"""\
import sys, json; sys.path.insert(0, {str(ROOT / "scripts")!r})
from bench import WORKLOADS, peak_rss_mb, reset_peak_rss, run_engine, rss_mb, warm_up
w = WORKLOADS[{workload!r}]; data = w.make(); engine, strategy = {engine!r}, {strategy!r}
warm_up(engine, w.opts, strategy)  # load numba's cache, import the engine
base = rss_mb(); reset_peak_rss()
out = run_engine(engine, data, w.opts, strategy)
print("PEAK_MB", json.dumps(max(peak_rss_mb() - base, 0.0)))
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    # (the SWIG bindings may print warnings to stdout at exit)
    return float(next(ln.split()[1] for ln in out.stdout.splitlines() if ln.startswith("PEAK_MB ")))


# ---------------------------------------------------------------------------------------------
# timing


def new_row(name: str, w: Workload, strategy: str) -> dict:
    return {
        "workload": name,
        "input": w.label,
        "switches": w.opts,
        "strategy": strategy,
        "triangles": {},
        "ours_s": None,
        "triangle_s": None,
        "cgal_s": None,
        "ratio": None,  # ours / Triangle
        "cgal_ratio": None,  # ours / CGAL
        "goal": w.goal,
        "goal_met": None,
        "work": {},
        "note": "",
    }


def available_strategies() -> list[str]:
    from instrument.study.ours_engine import available_strategies as names

    return names()


def bench(name: str, repeat: int, memory: bool, *, strategies: list[str] | None = None, cgal: bool = True,
          stats: bool = True, timeout: float = 60.0) -> list[dict]:
    """Time one workload; one row per strategy of ours.

    On a strategy workload (``sweep``) with ``timeout > 0`` each of our runs
    happens in a process of its own (``instrument.study.ours_engine.run_ours_isolated``,
    timed inside the child like an in-process run) that is killed after
    ``timeout`` seconds; a strategy that times out is not run again."""
    w = WORKLOADS[name]
    if w.make is None:
        return bench_cli(name, w, repeat, memory)
    strategies = (strategies or available_strategies()) if w.sweep else ["triangle"]
    isolated = w.sweep and timeout > 0
    from instrument.study.cgal_engine import has_cgal

    cgal = cgal and w.cgal and has_cgal()
    data = w.make()
    for s in strategies:
        warm_up("ours", w.opts, s)
    warm_up("triangle", w.opts)
    if cgal:
        warm_up("cgal", w.opts)
    engines = [("ours", s) for s in strategies] + [("triangle", "")] + ([("cgal", "")] if cgal else [])
    best = {e: math.inf for e in engines}
    size: dict = {}
    work: dict = {}
    failed: dict = {}
    cgal_core = math.inf
    for k in range(repeat):
        for e in engines:
            engine, strategy = e
            if e in failed:
                continue
            gc.collect()
            if engine == "ours" and isolated:
                from instrument.study.ours_engine import EngineTimeout, run_ours_isolated

                try:
                    out, counts, wall = run_ours_isolated(data, w.opts, strategy, repeat=1, timeout=timeout)
                except EngineTimeout:
                    failed[e] = f"timeout: killed after {timeout:g} s"
                    continue
                best[e] = min(best[e], wall)
                size[e], work[e] = len(out.get("triangles", ())), counts
                del out
                continue
            t0 = time.perf_counter()
            out = run_engine(engine, data, w.opts, strategy)
            best[e] = min(best[e], time.perf_counter() - t0)
            if engine == "ours":
                size[e] = len(out.get("triangles", ()))
                work[e] = dict(out.work)
            elif engine == "triangle":
                size[e] = len(out.get("triangles", ()))
            else:
                cgal_core = min(cgal_core, out.core_s)
                if k == repeat - 1:
                    size[e] = out.triangles()
            del out
    tri_stats = {}
    if stats:
        from instrument.study.triangle_engine import triangle_statistics

        gc.collect()
        tri_stats = triangle_statistics(data, w.opts)[1]
    mem = {}
    if memory:
        for e in engines:
            if e not in failed:
                mem[e] = peak_memory_mb(name, *e) if e[0] == "ours" else peak_memory_mb(name, e[0])
    rows = []
    tri_s = best[("triangle", "")]
    cgal_s = best.get(("cgal", ""))
    for s in strategies:
        e = ("ours", s)
        row = new_row(name, w, s)
        row["triangles"] = {"ours": size.get(e), "triangle": size[("triangle", "")]}
        row["triangle_s"] = tri_s
        if cgal:
            row["triangles"]["cgal"] = size[("cgal", "")]
            row["cgal_s"], row["cgal_core_s"] = cgal_s, cgal_core
        if e in failed:
            row["note"] = failed[e]
            rows.append(row)
            continue
        row["ours_s"], row["ratio"] = best[e], best[e] / tri_s
        if cgal:
            row["cgal_ratio"] = best[e] / cgal_s
        ours_work = work[e]
        row["work"] = {
            "ours": {k: ours_work.get(k) for k in ("triangles_created", "incircle_tests", "orient_tests",
                                                   "circumcenters")},
            "triangle": {k: tri_stats.get(k) for k in ("incircle_tests", "orient_tests", "circumcenters")
                         if k in tri_stats},
        }
        if memory:
            row["ours_mb"] = mem[e]
            row["triangle_mb"] = mem[("triangle", "")]
            row["memory_ratio"] = row["ours_mb"] / max(row["triangle_mb"], 1e-9)
            if cgal:
                row["cgal_mb"] = mem[("cgal", "")]
        rows.append(row)
    if w.goal is not None:
        done = [r for r in rows if r["ours_s"] is not None]
        if w.sweep and done:  # the goal is the least-work strategy's
            least = min(done, key=lambda r: (r["work"]["ours"]["triangles_created"], r["ours_s"]))
            least["least_work"] = True
            least["goal_met"] = least["ratio"] <= w.goal
        else:
            for row in done:
                row["goal_met"] = row["ratio"] <= w.goal
    return rows


# ---------------------------------------------------------------------------------------------
# profile: where our time goes


PROFILED = {
    # module attribute -> phase name (wrapped only for the duration of one profiled run)
    ("instrument.pipeline", "validate"): "validate input (Python)",
    ("instrument.pipeline", "delaunay"): "Delaunay triangulation (sort + kernel)",
    ("instrument.pipeline", "clean_segments"): "clean segments (Python)",
    ("instrument.pipeline", "recover_segments"): "segment recovery (kernel)",
    ("instrument.pipeline", "carve"): "holes, concavities, regions",
    ("instrument.pipeline", "enclose_hull"): "enclose hull",
    ("instrument.refine", "new_refiner"): "refinement setup (allocate arrays)",
    ("instrument.refine", "build_vertex_edges"): "refinement setup (vertex -> edge map kernel)",
    ("instrument.refine", "tally_encroached"): "refinement setup (encroached subsegments kernel)",
    ("instrument.refine", "refine"): "refinement kernel",
    ("instrument.refine", "grow_refiner"): "refinement: growing arrays",
    ("instrument.pipeline", "assemble"): "output assembly",
}


def profile(name: str, strategy: str = "triangle", repeat: int = 3) -> list[tuple[str, float, int]]:
    """Phases of ``instrument.triangulate`` on one workload, by wrapping the
    pipeline's pieces with timers (compiled kernels are opaque to cProfile):
    [(phase, best seconds, calls)], the total first, then each phase."""
    import importlib

    import instrument

    w = WORKLOADS[name]
    data = w.make()
    warm_up("ours", w.opts, strategy)
    spent: dict[str, float] = {}
    calls: dict[str, int] = {}

    nested = [0.0]  # time spent in wrapped calls inside the current one

    def timed(phase, fn):
        def wrapper(*a, **k):  # exclusive time: a wrapped call inside another counts once
            outer, nested[0] = nested[0], 0.0
            t0 = time.perf_counter()
            try:
                return fn(*a, **k)
            finally:
                elapsed = time.perf_counter() - t0
                spent[phase] = spent.get(phase, 0.0) + elapsed - nested[0]
                calls[phase] = calls.get(phase, 0) + 1
                nested[0] = outer + elapsed

        return wrapper

    saved = []
    for (mod, attr), phase in PROFILED.items():
        m = importlib.import_module(mod)
        if hasattr(m, attr):
            saved.append((m, attr, getattr(m, attr)))
            setattr(m, attr, timed(phase, getattr(m, attr)))
    best: dict[str, float] = {}
    try:
        for _ in range(repeat):
            spent.clear()
            calls.clear()
            gc.collect()
            t0 = time.perf_counter()
            out = instrument.triangulate(data, w.opts, strategy=strategy)
            total = time.perf_counter() - t0
            del out
            if total < best.get("total", math.inf):
                best = {"total": total, **spent}
                ncalls = dict(calls)
    finally:
        for m, attr, fn in saved:
            setattr(m, attr, fn)
    total = best.pop("total")
    rows = [("total (instrument.triangulate)", total, 1)]
    rows += [(p, s, ncalls.get(p, 0)) for p, s in best.items()]
    rows.append(("other (unwrapped Python)", total - sum(best.values()), 0))
    return rows


def print_profile(name: str, rows, strategy: str) -> None:
    total = rows[0][1]
    print(f"\nprofile of {name} ({WORKLOADS[name].opts}, strategy {strategy}), best of the runs:")
    scale, unit = (1e3, "ms") if total < 0.1 else (1.0, "s")  # small inputs in milliseconds
    for phase, s, n in rows:
        print(f"  {phase:<52} {s * scale:9.3f} {unit:<2} {100 * s / total:6.1f} %" + (f"  ({n} calls)" if n > 1 else ""))


# ---------------------------------------------------------------------------------------------
# output


def fmt_s(v) -> str:
    return "—" if v is None else (f"{v:.4f}" if v < 0.1 else f"{v:.3f}")


def fmt_x(v) -> str:
    return "—" if v is None else f"{v:.2f}"


def fmt_n(v) -> str:
    return "—" if v is None else f"{v:,}"


def fmt_mb(row, key) -> str:
    return f"{row[key]:.1f}" if row.get(key) is not None else "—"


def goal_text(row) -> str:
    g = row["goal"]
    if g is None:
        return "—"
    if row["workload"].startswith("cli"):
        target = f"< {g:g} s"
    elif g < 1:
        target = f"≤ {g:g}x ({1 / g:g}x faster), least work"
    else:
        target = f"≤ {g:g}x"
    if row["goal_met"] is None:
        return "—" if g < 1 else f"({target})"  # strategy rows: the goal is the least-work row's
    return f"{'met' if row['goal_met'] else 'MISSED'}: {target}"


COLS = ["workload", "switches", "strategy", "triangles ours / Tri / CGAL", "ours s", "Triangle s", "CGAL s",
        "ours/Tri", "ours/CGAL", "ours MB", "Tri MB", "CGAL MB", "created (ours)", "incircle ours / Tri", "goal"]


def cells(row) -> list[str]:
    t = row["triangles"]
    tri = " / ".join(fmt_n(t.get(k)) for k in ("ours", "triangle", "cgal") if k in t)
    wo = row["work"].get("ours", {})
    wt = row["work"].get("triangle", {})
    inc = f"{fmt_n(wo.get('incircle_tests'))} / {fmt_n(wt.get('incircle_tests'))}" if wo else "—"
    strategy = row["strategy"] + (" (least work)" if row.get("least_work") else "")
    ours_s = fmt_s(row["ours_s"]) if row["ours_s"] is not None or not row["note"] else row["note"].split(":")[0]
    return [row["workload"], f"`{row['switches']}`" if row["switches"] else "(none)", strategy, tri, ours_s, fmt_s(row["triangle_s"]), fmt_s(row["cgal_s"]), fmt_x(row["ratio"]),
            fmt_x(row["cgal_ratio"]), fmt_mb(row, "ours_mb"), fmt_mb(row, "triangle_mb"), fmt_mb(row, "cgal_mb"),
            fmt_n(wo.get("triangles_created")), inc, goal_text(row)]


def print_table(rows, title: str) -> None:
    try:
        from rich.console import Console
        from rich.table import Table
    except ImportError:  # plain text
        print(title)
        print(" | ".join(COLS))
        for row in rows:
            print(" | ".join(c.strip("`") for c in cells(row)))
        print("\n".join(notes(rows)))
        return
    console = Console()
    if not console.is_terminal:
        console = Console(width=max(console.width, 280))
    table = Table(title=title)
    for c in COLS:
        table.add_column(c, justify="left" if c in ("workload", "switches", "strategy", "goal") else "right",
                         overflow="fold")
    last = None
    for row in rows:
        if last is not None and row["workload"] != last:
            table.add_section()
        last = row["workload"]
        style = "bold red" if row["goal_met"] is False else ("green" if row["goal_met"] else None)
        table.add_row(*(c.strip("`") for c in cells(row)), style=style)
    console.print(table)
    for line in notes(rows):
        console.print(line, markup=False, highlight=False)


def notes(rows) -> list[str]:
    return [f"{r['workload']} [{r['strategy']}]: {r['note']}" for r in rows if r.get("note")]


def provenance() -> tuple[str, str]:
    """(the commit measured, noting uncommitted changes to the engine and file
    packages; a fingerprint of their source files as they are on disk, to
    notice a change during the run)."""
    import hashlib

    h = hashlib.sha1()
    for path in sorted(p for d in ("instrument", "ruppert_io") for p in (ROOT / d).rglob("*.py")):
        h.update(str(path.relative_to(ROOT)).encode() + b"\0" + path.read_bytes())
    code = h.hexdigest()[:8]
    try:
        def git(*args: str) -> str:
            return subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True, check=True).stdout

        head = git("rev-parse", "--short", "HEAD").strip()
        dirty = git("status", "--porcelain", "--", "instrument", "ruppert_io").strip()
    except (OSError, subprocess.CalledProcessError):
        return f"unknown commit, source {code}", code
    return f"commit {head}" + (f" with uncommitted engine changes (source {code})" if dirty else ""), code


LEGEND = (
    "Times are the best of the interleaved rounds, in seconds; ours/Tri and ours/CGAL are ratios of wall times "
    "(below 1: ours is faster). MB: growth of resident memory during one run in a fresh process (cli-A: peak "
    "resident memory of the whole command). created: triangles our engine created (the paper's work measure); "
    "incircle: our count / Triangle's statistic (one extra untimed run with V). CGAL: Delaunay_triangulation_2 "
    "bulk insert for dt-*, Mesh_2 as in scripts/compare.py otherwise (q -> b = sin^2(angle), a -> S = "
    "sqrt(4a/sqrt 3)); its time includes making the Point_2 objects in Python, and it makes a different mesh. "
    "cli-A: subprocess wall time with numba's cache warm; Triangle's side is `python -c` running the triangle "
    "package on the same file and writing the same three files (no Triangle program is installed)."
)


def write_markdown(path: Path, rows, command: str, profiles, state: str) -> None:
    lines = [f"<!-- generated by `{command}`; {state} -->", ""]
    lines.append("| " + " | ".join(COLS) + " |")
    lines.append("|" + "|".join("---" if c in ("workload", "switches", "strategy", "goal") else "---:"
                                for c in COLS) + "|")
    for row in rows:
        lines.append("| " + " | ".join(c.replace("|", "\\|") for c in cells(row)) + " |")
    lines.append("")
    lines += [f"- {n}" for n in notes(rows)]
    lines += ["", LEGEND, ""]
    for name, strategy, prof in profiles:
        total = prof[0][1]
        lines += [f"Where our time goes, {name} (`{WORKLOADS[name].opts}`, strategy {strategy}):", "",
                  "| phase | s | share |", "|---|---:|---:|"]
        lines += [f"| {p} | {s:.3f} | {100 * s / total:.1f} % |" for p, s, _ in prof]
        lines.append("")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines))


# ---------------------------------------------------------------------------------------------


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("prefix", nargs="*", help="run the workloads whose name starts with one of these")
    ap.add_argument("--repeat", type=int, default=3, help="interleaved timed rounds (best counts); default 3")
    ap.add_argument("--no-memory", action="store_true", help="skip the peak-memory subprocesses")
    ap.add_argument("--no-cgal", action="store_true", help="do not run CGAL")
    ap.add_argument("--no-stats", action="store_true", help="skip Triangle's statistics run (V)")
    ap.add_argument("--strategies", default="all",
                    help="our strategies for the strategy workloads (quad-*): all (instrument.strategies()) "
                         "or a comma list; the other workloads use 'triangle'")
    ap.add_argument("--timeout", type=float, default=60.0,
                    help="seconds per run of ours on the strategy workloads (a forked child, killed after it; a "
                         "strategy that times out is not run again); 0: in this process, no limit. Default 60")
    ap.add_argument("--profile", action="store_true",
                    help="also time our phases on the quality workloads selected (square-*, la-*)")
    ap.add_argument("--json", type=Path, help="also write the rows as JSON")
    ap.add_argument("--markdown", type=Path, help="also write the table as Markdown")
    ap.add_argument("--list", action="store_true", help="list the workloads and strategies, then stop")
    args = ap.parse_args(argv)
    if args.list:
        for n, w in WORKLOADS.items():
            print(f"{n:<16} {w.opts or '(none)':<14} {w.label}")
        print("strategies:", ", ".join(available_strategies()))
        return 0
    names = [n for n in WORKLOADS if not args.prefix or any(n.startswith(p) for p in args.prefix)]
    if not names:
        ap.error(f"no workload starts with {' or '.join(args.prefix)}; choose from {', '.join(WORKLOADS)}")
    if args.repeat < 1:
        ap.error("--repeat must be at least 1")
    known = available_strategies()
    if args.strategies == "all":
        strategies = known
    else:
        strategies = [s.strip() for s in args.strategies.split(",") if s.strip()]
        unknown = [s for s in strategies if s not in known]
        if unknown or not strategies:
            ap.error(f"unknown strategy {', '.join(unknown) or '(none)'}; choose from {', '.join(known)}")
    state, code = provenance()  # before: the work tree may change while this runs
    command = "python scripts/bench.py" + "".join(f" {a}" for a in (argv if argv is not None else sys.argv[1:]))
    rows = []
    for name in names:
        print(f"{name} ...", file=sys.stderr, flush=True)
        got = bench(name, args.repeat, not args.no_memory, strategies=strategies, cgal=not args.no_cgal,
                    stats=not args.no_stats, timeout=args.timeout)
        for row in got:
            print("  " + "  ".join(f"{c}={v}" for c, v in zip(COLS[2:], cells(row)[2:])), file=sys.stderr,
                  flush=True)
        rows.extend(got)
    now, code_now = provenance()
    if code_now != code:
        state += f"; the engine changed during the run, now {now}"
        print(f"warning: {state}", file=sys.stderr)
    print_table(rows, f"ruppert vs Triangle vs CGAL, best of {args.repeat} interleaved rounds ({state})")
    print(LEGEND)
    profiles = []
    if args.profile:
        for name in names:
            w = WORKLOADS[name]
            if w.make is not None and not w.sweep:
                prof = profile(name, "triangle", args.repeat)
                print_profile(name, prof, "triangle")
                profiles.append((name, "triangle", prof))
    if args.json:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        doc = {"command": command, "provenance": state, "repeat": args.repeat, "rows": rows,
               "profiles": [{"workload": n, "strategy": s, "phases": [{"phase": p, "s": t, "calls": c}
                                                                       for p, t, c in prof]}
                            for n, s, prof in profiles]}
        args.json.write_text(json.dumps(doc, indent=1, default=float))
    if args.markdown:
        write_markdown(args.markdown, rows, command, profiles, state)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
