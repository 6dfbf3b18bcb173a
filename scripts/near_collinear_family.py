#!/usr/bin/env python
"""Families of nearly collinear inputs through the differential harness.

The campaign's near-collinear failures (a chain of three points under
pucS19njQ, seven points within rounding of a line under a0.0000622S7zlQ, a
size failure of eleven such points under q30a0.000861Q) were single draws;
this script runs many inputs of the same making under the same switches and
counts the verdicts per signature, so that a fix is measured on its family
and not on its reproducer alone.

    python scripts/near_collinear_family.py --cases 200 --seed 1
    python scripts/near_collinear_family.py --family points --switches q30a0.000861Q

Families (numpy draws, reproducible from the seed):

* ``chain``: 3 to 12 points at x = k / 64 on y = slope x + c, each moved by
  up to 8 units of 2^-52 (the campaign's near-collinear-chain), joined by
  segments, inside a box half of the time;
* ``points``: 3 to 20 points (t, slope t + 0.25) with t drawn toward 0 (t =
  u^4 on a 2^-20 grid: the campaign's reproducers cluster near one end),
  plus up to two points off the line, and now and then an exact duplicate.

Prints one line per (family, switches): cases run, verdicts ok, and the
failures by signature (with the open defect of known.py that explains it,
if any).
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from tests.differential.cases import Case  # noqa: E402
from tests.differential.harness import run_case  # noqa: E402
from tests.differential.known import explaining  # noqa: E402
from tests.differential.runners import Runners  # noqa: E402

SWITCHES = {
    "chain": ("pucS19njQ", "pucQ"),
    "points": ("a0.0000622S7zlQ", "q30a0.000861Q"),
}


def chain(rng: np.random.Generator) -> dict:
    n = int(rng.integers(3, 13))
    slope = float(rng.choice([0.3, 0.1, 1.0 / 3.0, 0.7, 2.0, 0.0]))
    c = float(rng.choice([0.1, 0.2, 0.0]))
    xs = sorted({int(k) / 64.0 for k in rng.integers(1, 65, size=n)})
    if len(xs) < 2:
        xs = [0.25, 0.75]
    pts = [(x, slope * x + c + int(rng.integers(-8, 9)) * 2.0**-52) for x in xs]
    segs = [(i, i + 1) for i in range(len(pts) - 1)]
    if rng.random() < 0.5:
        b = len(pts)
        pts += [(-0.25, -0.5), (1.25, -0.5), (1.25, 3.0), (-0.25, 3.0)]
        segs += [(b + i, b + (i + 1) % 4) for i in range(4)]
    return {"vertices": pts, "segments": segs}


def points(rng: np.random.Generator) -> dict:
    n = int(rng.integers(3, 21))
    slope = float(rng.choice([0.0, 1.0, 2.0, 0.5, 0.3, -1.0]))
    ts = np.round(rng.random(n) ** 4 * 2**20) / 2**20
    pts = [(float(t), slope * float(t) + 0.25) for t in ts]
    pts += [(float(a), float(b)) for a, b in np.round(rng.random((int(rng.integers(0, 3)), 2)) * 2**20) / 2**20]
    if rng.random() < 0.2:
        pts.append(pts[int(rng.integers(0, len(pts)))])
    return {"vertices": pts}


FAMILIES = {"chain": chain, "points": points}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cases", type=int, default=200)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--family", choices=sorted(FAMILIES), action="append")
    ap.add_argument("--switches", action="append", help="instead of the family's own")
    ap.add_argument("--show", type=int, default=3, help="failing cases to print per signature")
    args = ap.parse_args(argv)
    runners = Runners()
    try:
        for fam in args.family or sorted(FAMILIES):
            for sw in args.switches or SWITCHES[fam]:
                rng = np.random.default_rng(args.seed)
                sigs: Counter = Counter()
                shown: Counter = Counter()
                ran = ok = 0
                for i in range(args.cases):
                    case = Case(family=f"near-collinear-{fam}", switches=sw, input=FAMILIES[fam](rng))
                    run = run_case(runners, case)
                    if run is None:
                        continue
                    ran += 1
                    if run.verdict.ok:
                        ok += 1
                        continue
                    for f in run.verdict.failures:
                        d = explaining(case, f, run.verdict.notes)
                        key = f.signature + (f" [{d.id}]" if d else "")
                        sigs[key] += 1
                        if shown[key] < args.show:
                            shown[key] += 1
                            print(f"  {fam} {sw} case {i}: {key}: {f.message[:160]}", flush=True)
                print(f"{fam:6} {sw:18} ran {ran}, ok {ok}; " + (", ".join(f"{k}: {v}" for k, v in sigs.most_common()) or "no failures"),
                      flush=True)
    finally:
        runners.close()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
