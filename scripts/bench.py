#!/usr/bin/env python
"""Benchmark ruppert's engine against Triangle (the `triangle` package).

    python scripts/bench.py            # every workload
    python scripts/bench.py dt         # workloads whose name starts with "dt"

Both engines run on the same input in one process, interleaved, best of
``--repeat`` runs; numba's compilation is excluded (every kernel runs once
first).  Peak memory is measured separately, each engine in a fresh
subprocess (Triangle allocates in C, where tracemalloc cannot see), as the
growth of the process's maximum resident set size during one run.
"""

from __future__ import annotations

import argparse
import gc
import json
import resource
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


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


# name -> (input builder, switches)
WORKLOADS = {
    "dt-1e5": (lambda: uniform(10**5), ""),
    "dt-1e6": (lambda: uniform(10**6), ""),
    "cdt-1e5": (lambda: polygon_with_holes(10**5), "p"),
}


def run_engine(engine: str, data: dict, opts: str):
    if engine == "ours":
        import instrument

        return instrument.triangulate(data, opts)
    import triangle

    return triangle.triangulate(data, opts)


def peak_memory_mb(workload: str, engine: str) -> float:
    """Peak growth of resident memory (MB) while one engine runs the workload
    once, in a fresh process, sampled every millisecond from /proc."""
    code = (
        "import sys, json, threading, time; sys.path.insert(0, %r)\n"
        "from bench import WORKLOADS, polygon_with_holes, run_engine, rss_mb\n"
        "make, opts = WORKLOADS[%r]; data = make()\n"
        "run_engine(%r, polygon_with_holes(200), opts)  # load numba's cache\n"
        "base = rss_mb(); peak = [base]; done = []\n"
        "def watch():\n"
        "    while not done:\n"
        "        peak[0] = max(peak[0], rss_mb()); time.sleep(0.001)\n"
        "th = threading.Thread(target=watch); th.start()\n"
        "out = run_engine(%r, data, opts)\n"
        "peak[0] = max(peak[0], rss_mb()); done.append(1); th.join()\n"
        "print(json.dumps(peak[0] - base))\n"
    ) % (str(ROOT / "scripts"), workload, engine, engine)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return float(out.stdout.strip().splitlines()[-1])


def rss_mb() -> float:
    """Current resident set size of this process in MB."""
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * resource.getpagesize() / 2**20


def bench(name: str, repeat: int, memory: bool) -> dict:
    make, opts = WORKLOADS[name]
    data = make()
    run_engine("ours", polygon_with_holes(200), opts)  # compile / load numba's cache
    best = {"ours": float("inf"), "triangle": float("inf")}
    sizes = {}
    for _ in range(repeat):
        for engine in ("ours", "triangle"):
            gc.collect()
            t0 = time.perf_counter()
            out = run_engine(engine, data, opts)
            best[engine] = min(best[engine], time.perf_counter() - t0)
            sizes[engine] = len(out.get("triangles", ()))
            del out
    row = {
        "workload": name,
        "switches": opts,
        "triangles": sizes,
        "ours_s": best["ours"],
        "triangle_s": best["triangle"],
        "ratio": best["ours"] / best["triangle"],
    }
    if memory:
        row["ours_mb"] = peak_memory_mb(name, "ours")
        row["triangle_mb"] = peak_memory_mb(name, "triangle")
        row["memory_ratio"] = row["ours_mb"] / max(row["triangle_mb"], 1e-9)
    return row


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("prefix", nargs="*", help="run the workloads whose name starts with one of these")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--no-memory", action="store_true", help="skip the peak-memory subprocesses")
    ap.add_argument("--json", type=Path, help="also write the rows as JSON")
    args = ap.parse_args(argv)
    names = [n for n in WORKLOADS if not args.prefix or any(n.startswith(p) for p in args.prefix)]
    rows = []
    print(f"{'workload':<10} {'triangles':>10} {'ours s':>9} {'Triangle s':>11} {'ratio':>6} {'ours MB':>8} {'Tri MB':>8} {'mem ratio':>9}")
    for name in names:
        row = bench(name, args.repeat, not args.no_memory)
        rows.append(row)
        mem = (
            f"{row['ours_mb']:8.1f} {row['triangle_mb']:8.1f} {row['memory_ratio']:9.2f}"
            if "ours_mb" in row
            else ""
        )
        print(
            f"{name:<10} {row['triangles']['ours']:>10} {row['ours_s']:9.3f} {row['triangle_s']:11.3f}"
            f" {row['ratio']:6.2f} {mem}",
            flush=True,
        )
    if args.json:
        args.json.write_text(json.dumps(rows, indent=2))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
