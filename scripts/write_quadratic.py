#!/usr/bin/env python
"""Write Barbič and Miller's quadratic example as a Triangle .poly file.

    python scripts/write_quadratic.py 100 --alpha 20 -o data/quadratic-100

writes ``data/quadratic-100.poly``: the extended input of I(n) (the n + 4 points of
the paper's equation (2), the box of side 3a with its corners and side midpoints,
the eight box subsegments), from ``instrument.quadratic.example``.  The .poly
carries its vertices itself (no .node).  ``ruppert -p data/quadratic-100.poly``
then triangulates it.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import ruppert_io
from instrument import quadratic


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description="Write the extended input of Barbic and Miller's I(n) as a .poly file."
    )
    parser.add_argument("n", type=int, help="number of bottom intervals (n >= r + 1)")
    parser.add_argument(
        "--alpha",
        type=float,
        default=20.0,
        help="minimum angle alpha_min in degrees, 0 < alpha <= 34 (default 20; r = 1 above 30)",
    )
    parser.add_argument(
        "-o",
        "--output",
        help="output base name, '.poly' is appended (default data/quadratic-N)",
    )
    parser.add_argument(
        "-z", action="store_true", help="number vertices from 0 (Triangle's -z)"
    )
    args = parser.parse_args(argv)
    try:
        pslg = quadratic.example(args.n, args.alpha)
    except ValueError as exc:
        parser.error(str(exc))
    base = args.output or str(ROOT / "data" / f"quadratic-{args.n}")
    base = base.removesuffix(".poly")
    p = quadratic.params(args.n, args.alpha)
    note = (
        f"write_quadratic.py {args.n} --alpha {args.alpha:g}: "
        f"r={p.r} h={p.h!r} a={p.a!r} steps={p.steps}"
    )
    for path in ruppert_io.write(
        base,
        pslg,
        kinds=("poly",),
        first_index=0 if args.z else 1,
        generated_by=note,
    ):
        print(path)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
