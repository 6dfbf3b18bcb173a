#!/usr/bin/env python
"""Ours against Triangle on every star polygon {n/k}, 5 <= n <= 21 (81 inputs).

The stars are scripts/crossing_agreement.py's: n points on a circle, each
joined to the k-th after it (self-intersecting for k >= 2), the polygons of
known.py's star-size defect.  For each: Triangle's vertex count, the size
rule's bound (Triangle's largest count over the exact re-expressions of
tests/differential/reexpress.py, plus 1 % or 2 vertices) and ours.  Triangle
runs in a worker process (it can crash the interpreter); its counts are
cached in ``--cache`` so that a second sweep runs ours alone.

    python scripts/star_sweep.py                       # pq30
    python scripts/star_sweep.py --switches pq33 --max-n 17
"""

from __future__ import annotations

import argparse
import json
import multiprocessing
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from scripts.crossing_agreement import star_inputs  # noqa: E402
from tests.differential.reexpress import KINDS, transformed  # noqa: E402


def _triangle_counts(pslg: dict, switches: str) -> list[int]:
    import triangle

    return [len(triangle.triangulate(pslg if k is None else transformed(pslg, k), switches)["vertices"])
            for k in (None, *KINDS)]


def triangle_counts(pslg: dict, switches: str) -> list[int] | None:
    """Triangle's counts on the input and each re-expression (None if it crashed)."""
    with multiprocessing.get_context("fork").Pool(1) as pool:
        try:
            return pool.apply_async(_triangle_counts, (pslg, switches)).get(timeout=300)
        except Exception:  # noqa: BLE001 - a crash or a timeout: no answer
            return None


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--switches", default="pq30")
    ap.add_argument("--max-n", type=int, default=21)
    ap.add_argument("--cache", type=Path, default=Path("/tmp/star_sweep_triangle.json"))
    args = ap.parse_args(argv)
    import instrument
    from instrument.check import check_mesh

    cache = json.loads(args.cache.read_text()) if args.cache.exists() else {}
    equal = above = invalid = total = 0
    for name, pslg in star_inputs(args.max_n):
        key = f"{name} {args.switches}"
        if key not in cache:
            cache[key] = triangle_counts(pslg, args.switches)
            args.cache.write_text(json.dumps(cache))
        counts = cache[key]
        if counts is None:
            print(f"{name}: Triangle made no mesh")
            continue
        mesh = instrument.triangulate(pslg, args.switches + "Q")
        ours = len(mesh["vertices"])
        most = max(counts)
        bound = most + max(2.0, 0.01 * most)
        ok = not check_mesh(mesh, pslg, min_angle=float(args.switches.split("q")[1][:2]))
        total += 1
        equal += ours == counts[0]
        above += ours > bound
        invalid += not ok
        mark = "=" if ours == counts[0] else ("ABOVE" if ours > bound else "")
        print(f"{name:14s} Triangle {counts[0]:5d} spread {min(counts)}..{most} bound {bound:7.1f} ours {ours:5d} "
              f"{100 * (ours - counts[0]) / counts[0]:+6.1f}% {mark}{'' if ok else ' INVALID'}")
    print(f"{args.switches}: ours makes Triangle's count on {equal} of {total}; above the size rule {above}; "
          f"failing the checker {invalid}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
