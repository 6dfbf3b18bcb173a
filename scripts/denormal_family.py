#!/usr/bin/env python
"""Point sets mixing subnormal and tiny coordinates with ones near 1, through
the differential harness.

The campaign's denormal-walk-timeout (14 points with coordinates 2^-1022,
2^-149 and 2^-126 beside ones near 1, under q10: ours ran to the 20 s
deadline, Triangle crashed) was a single draw; this script runs many inputs
of the same making, so that a fix is measured on its family and not on its
reproducer alone.  Beside the harness's verdict it checks every mesh of
ours with the exact checker under the angle bound (the harness asks that
only where Triangle's own mesh meets it, and here Triangle mostly crashes),
and lists the runs of ours slower than ``--slow`` seconds (wall time, as the
harness's worker measures it).

    python scripts/denormal_family.py --cases 150 --seed 4

Draws (numpy, reproducible from the seed): 4 to 16 points uniform in the
unit square; each coordinate is, with probability 1/4, one of 0, 2^-1022,
2^-1023, 2^-1030, 2^-1060, 2^-1074, 3 x 2^-1074, 2^-500, 2^-149, 2^-126 or
2^-24, and with probability 1/5 rounded to a float32 and scaled by 2^-k
(k < 12); then up to 3 copies of a point moved along one axis by one of
those tiny amounts (or set to one); two times in five, 1 to 6 segments along
a random path (closed half of the time) under p or pc, else no segments
under nothing or c; an angle from q, q5, q10, q15, q20, q25, q28.6, q30.

Prints one line per outcome (ours, Triangle) with its count, the failing
cases (harness verdict or checker problems), and the slow runs.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from instrument.check import check_mesh  # noqa: E402
from tests.differential.cases import Case  # noqa: E402
from tests.differential.harness import run_case  # noqa: E402
from tests.differential.known import explaining  # noqa: E402
from tests.differential.oracles import read_switches  # noqa: E402
from tests.differential.runners import Runners  # noqa: E402

TINY = (0.0, 2.0**-1022, 2.0**-1074, 3 * 2.0**-1074, 2.0**-1060, 2.0**-1030, 2.0**-1023,
        2.0**-149, 2.0**-126, 2.0**-24, 2.0**-500)
ANGLES = ("q", "q5", "q10", "q15", "q20", "q25", "q28.6", "q30")


def draw(rng: np.random.Generator) -> Case:
    """One case of the family."""
    n = int(rng.integers(4, 17))
    pts = rng.random((n, 2)).tolist()
    for p in pts:
        for k in (0, 1):
            u = rng.random()
            if u < 0.25:
                p[k] = float(rng.choice(TINY))
            elif u < 0.45:
                p[k] = float(np.float32(p[k])) * 2.0 ** -int(rng.integers(0, 12))
    for _ in range(int(rng.integers(0, 4))):  # pairs a tiny distance apart along an axis
        q = list(pts[int(rng.integers(0, n))])
        k = int(rng.integers(0, 2))
        tiny = float(rng.choice(TINY[1:]))
        q[k] = q[k] + tiny if rng.random() < 0.7 else float(rng.choice(TINY))
        pts.append(q)
    tri = {"vertices": np.array(pts, dtype=np.float64)}
    angle = str(rng.choice(ANGLES))
    if rng.random() < 0.4:
        m = len(pts)
        order = rng.permutation(m).tolist()
        k = int(rng.integers(1, min(6, m - 1) + 1))
        segs = [[order[j], order[j + 1]] for j in range(k)]
        if rng.random() < 0.5:
            segs.append([order[k], order[0]])
        tri["segments"] = np.array(segs, dtype=np.int64)
        switches = str(rng.choice(["p", "pc"])) + angle + "Q"
    else:
        switches = str(rng.choice(["", "c"])) + angle + "Q"
    return Case(family="points-denormal", switches=switches, input=tri, meta={"scale": "denormal"})


def mesh_problems(case: Case, result: dict) -> list[str]:
    """The exact checker's problems with a mesh of ours, under the case's angle bound."""
    sw = read_switches(case.switches)
    return check_mesh(result, pslg=case.input if sw.p else None, min_angle=sw.angle if sw.q else None)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cases", type=int, default=150)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--slow", type=float, default=1.0, help="list runs of ours slower than this (seconds)")
    args = ap.parse_args(argv)
    rng = np.random.default_rng(args.seed)
    outcomes: Counter = Counter()
    slow = []
    runners = Runners()
    try:
        for i in range(args.cases):
            case = draw(rng)
            run = run_case(runners, case)
            if run is None:
                continue
            ours, tri = run.ours, run.triangle
            outcomes[(ours.exc_type if ours.status == "error" else ours.status,
                      tri.exc_type if tri.status == "error" else tri.status)] += 1
            problems = mesh_problems(run.case, ours.result) if ours.status == "ok" else []
            if ours.seconds > args.slow:
                slow.append(f"case {i} {case.switches}: {ours.seconds:.2f} s, {ours.summary()}")
            for f in run.verdict.failures:
                d = explaining(run.case, f, run.verdict.notes)
                print(f"  case {i} {case.describe()}: {f.signature}{f' [{d.id}]' if d else ''}: {f.message[:200]}",
                      flush=True)
            if problems:
                print(f"  case {i} {case.describe()}: checker: {problems[:2]}", flush=True)
    finally:
        runners.close()
    for (o, t), k in outcomes.most_common():
        print(f"ours {o:16} Triangle {t:16} {k}")
    print(f"slower than {args.slow:g} s: {len(slow)}")
    for line in slow:
        print("  " + line)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
