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


# name -> (input builder, switches)
WORKLOADS = {
    "dt-1e5": (lambda: uniform(10**5), ""),
    "dt-1e6": (lambda: uniform(10**6), ""),
}


def run_engine(engine: str, data: dict, opts: str):
    if engine == "ours":
        import instrument

        return instrument.triangulate(data, opts)
    import triangle

    return triangle.triangulate(data, opts)


def peak_memory_mb(workload: str, engine: str) -> float:
    """Growth of max RSS (MB) while one engine runs the workload once, in a fresh process."""
    code = (
        "import sys, resource, json; sys.path.insert(0, %r)\n"
        "from bench import WORKLOADS, run_engine\n"
        "make, opts = WORKLOADS[%r]; data = make()\n"
        "run_engine(%r, {'vertices': data['vertices'][:100]}, opts)  # load numba's cache\n"
        "before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss\n"
        "run_engine(%r, data, opts)\n"
        "after = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss\n"
        "print(json.dumps((after - before) / 1024))\n"
    ) % (str(ROOT / "scripts"), workload, engine, engine)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return float(out.stdout.strip().splitlines()[-1])


def bench(name: str, repeat: int, memory: bool) -> dict:
    make, opts = WORKLOADS[name]
    data = make()
    small = {"vertices": data["vertices"][:100]}
    run_engine("ours", small, opts)  # compile / load numba's cache
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
