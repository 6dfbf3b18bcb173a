#!/usr/bin/env python
"""How many of ours' crossing vertices are Triangle's, bit for bit.

Under ``p`` alone the only vertices either mesher adds to a set of
segments are the points where segments cross, so the vertices beyond the
input's are exactly the crossing vertices.  This script meshes random
crossing-segment inputs (segments with endpoints uniform in the unit square)
and stars (n points on a circle, segment i -> i + k) with ours and with
Triangle (the `triangle` package, in a worker process: it can crash on bad
input) under ``p`` and counts ours' crossing vertices whose coordinates are
also, bit for bit, a crossing vertex of Triangle's mesh.  Both meshers make
the same crossings (one per crossing pair of segments, where no three meet),
so agreement is a statement about how each rounds them.

    python scripts/crossing_agreement.py                   # 300 random inputs and every star n <= 21
    python scripts/crossing_agreement.py --random 1000 --seed 7 --max-segments 6
    python scripts/crossing_agreement.py --stars-only -v   # per star
"""

from __future__ import annotations

import argparse
import multiprocessing
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def random_inputs(n: int, seed: int, max_segments: int):
    """``n`` sets of 2 to ``max_segments`` segments, endpoints uniform in the unit square."""
    rng = np.random.default_rng(seed)
    for k in range(n):
        m = int(rng.integers(2, max_segments + 1))
        pts = rng.uniform(0.0, 1.0, (2 * m, 2))
        yield f"random-{seed}-{k}", {"vertices": pts, "segments": np.arange(2 * m).reshape(m, 2)}


def star_inputs(max_n: int = 21):
    """Every star {n/k} with 5 <= n <= max_n and 2 <= k < n / 2 (k = 1 is the convex polygon)."""
    for n in range(5, max_n + 1):
        a = 2 * np.pi * np.arange(n) / n
        pts = np.c_[0.5 + 0.5 * np.cos(a), 0.5 + 0.5 * np.sin(a)]
        for k in range(2, (n + 1) // 2):
            segs = np.array([(i, (i + k) % n) for i in range(n)])
            yield f"star{n}-step{k}", {"vertices": pts, "segments": segs}


def _triangle_steiner(pslg: dict, switches: str):
    import triangle

    out = triangle.triangulate(pslg, switches)
    return np.asarray(out["vertices"])[len(pslg["vertices"]):]


def triangle_steiner(pslg: dict, switches: str):
    """Triangle's added vertices, computed in a worker process (None if it crashed)."""
    ctx = multiprocessing.get_context("fork")
    with ctx.Pool(1) as pool:
        try:
            return pool.apply_async(_triangle_steiner, (pslg, switches)).get(timeout=60)
        except Exception:  # noqa: BLE001 - a crash or a timeout: no answer
            return None


def compare(pslg: dict, switches: str, theirs=None) -> tuple[int, int, int]:
    """(ours' added vertices, those also Triangle's bit for bit, Triangle's added vertices)."""
    import instrument

    if theirs is None:
        theirs = triangle_steiner(pslg, switches)
    ours = np.asarray(instrument.triangulate(pslg, switches)["vertices"])[len(pslg["vertices"]):]
    if theirs is None:
        return len(ours), 0, -1
    tset = {(float(x), float(y)) for x, y in theirs}
    same = sum((float(x), float(y)) in tset for x, y in ours)
    return len(ours), same, len(theirs)


def _theirs_batch(items, switches):
    """Triangle's added vertices for every input, in one worker process."""
    import triangle

    return [np.asarray(triangle.triangulate(p, switches)["vertices"])[len(p["vertices"]):] for _, p in items]


def measure(items, switches: str, verbose: bool = False) -> tuple[int, int, int]:
    ctx = multiprocessing.get_context("fork")
    with ctx.Pool(1) as pool:
        theirs_all = pool.apply_async(_theirs_batch, (items, switches)).get(timeout=600)
    total = [0, 0, 0]
    for (name, pslg), theirs in zip(items, theirs_all):
        n_ours, same, n_theirs = compare(pslg, switches, theirs)
        total[0] += n_ours
        total[1] += same
        total[2] += n_theirs
        if verbose:
            print(f"{name}: ours {n_ours}, bit for bit {same}, Triangle's {n_theirs}")
    return tuple(total)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--random", type=int, default=300, help="random crossing-segment inputs (default 300)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--max-segments", type=int, default=8)
    ap.add_argument("--max-star", type=int, default=21, help="stars with up to this many points")
    ap.add_argument("--stars-only", action="store_true")
    ap.add_argument("--random-only", action="store_true")
    ap.add_argument("--switches", default="pQ")
    ap.add_argument("-v", "--verbose", action="store_true", help="one line per input")
    args = ap.parse_args(argv)
    groups = []
    if not args.stars_only:
        groups.append(("random", list(random_inputs(args.random, args.seed, args.max_segments))))
    if not args.random_only:
        groups.append(("stars", list(star_inputs(args.max_star))))
    for label, items in groups:
        ours, same, theirs = measure(items, args.switches, args.verbose)
        print(f"{label}: {len(items)} inputs under {args.switches}: ours {ours} crossing vertices, "
              f"{same} bit for bit Triangle's ({100.0 * same / max(ours, 1):.1f} %); Triangle's {theirs}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
