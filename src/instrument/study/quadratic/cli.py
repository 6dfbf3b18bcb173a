"""Reproduce Barbič and Miller's quadratic example I(n), and measure every strategy on it.

    python -m instrument.study.quadratic --out docs/quadratic   # the full run (about 15 minutes)
    python -m instrument.study.quadratic --quick                # n <= 1600, a minute or two
    python -m instrument.study.quadratic --max-n 3200 --alphas 20 --strategies triangle,worst-angle --no-cgal

For n = 100, 200, 400, ... at alpha = 20 degrees (``--max-n``, default 25,600) and
a shorter sweep at the other ``--alphas`` (default 10, 30, 33; ``--sweep-max-n``):

* Theorem 3's adversary on our engine (``instrument.quadratic.replay``: the
  scripted splits of Δ_0, Δ_1, ..., checked against Lemmas 1 and 2 at every
  step, then finished with strategy ``triangle``): n, r, input size, Steiner
  points, output size, triangles created in the scripted phase and in total,
  the bound n²/(2r) - 2n, incircle and orientation tests;
* the same input (``quadratic.example``, switches ``pq<alpha>``) meshed by
  our engine with every strategy (``--strategies``), up to
  ``--strategy-max-n`` (default 51,200);
* Triangle 1.6 (the ``triangle`` package) on the same input: its size, time
  and its own statistics (incircle and orientation tests, captured from its
  ``V`` output), and how many of the scripted points P_1 .. P_s its output
  holds (all of them: it played the script);
* CGAL's Mesh_2 (``cgal`` package, if installed): size and time.

The runs are tasks of a sweep (``instrument.study.sweep``): on an embedded
Dask cluster by default (one process worker per core), on an existing one
with ``--scheduler``, or one after the other with ``--sequential``.  Every
run happens in a process of its own killed after ``--timeout`` seconds (our
strategies) or ``--long-timeout`` (the replay, Triangle and CGAL, which are
quadratic) and limited to ``--memory-gib``; a series that did not finish is
not run at larger n.  ``--dataset`` keeps the runs (a second run skips what
is there).

Writes to ``--out``: ``results.md`` (every table and the findings),
``README-section.md`` (the section the project README shows), ``replay.csv``,
``runs.csv``, ``slopes.csv``, ``summary.json``, and the figures ``work``,
``broom``, ``steps`` and ``orders`` as PNG and SVG.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import instrument
from instrument import quadratic

from ..cgal_engine import has_cgal
from ..sweep import add_cluster_options
from .fit import least_work, slopes
from .report import print_summary, write_reports
from .runs import measure


def parse_args(argv, *, default_out: Path | None = None):
    ap = argparse.ArgumentParser(prog="python -m instrument.study.quadratic", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--max-n", type=int, default=25_600, help="largest n of the replay table at the first angle (default 25600)")
    ap.add_argument("--strategy-max-n", type=int, default=51_200,
                    help="largest n of the strategy, Triangle and CGAL runs at the first angle (default 51200)")
    ap.add_argument("--sweep-max-n", type=int, default=3_200, help="largest n at the other angles (default 3200)")
    ap.add_argument("--alphas", default="20,10,30,33", help="minimum angles in degrees, the first is the main one (default 20,10,30,33)")
    ap.add_argument("--strategies", default="all", help="comma-separated strategies of ours, or 'all' (default)")
    ap.add_argument("--then", default="triangle", help="strategy that finishes the replay (default triangle)")
    ap.add_argument("--timeout", type=float, default=60.0, help="seconds per run of our strategies (default 60)")
    ap.add_argument("--long-timeout", type=float, default=1200.0, help="seconds per replay, Triangle or CGAL run (default 1200)")
    ap.add_argument("--memory-gib", type=float, default=6.0,
                    help="address-space limit of each run's process in GiB, 0 for none (default 6)")
    ap.add_argument("--repeat", type=int, default=3, help="timed runs per engine, the best counts (default 3)")
    ap.add_argument("--scan-max-n", type=int, default=200,
                    help="run Triangle for every n = 10..this at the first angle: which n does it play the script for (default 200)")
    ap.add_argument("--no-cgal", action="store_true", help="skip CGAL")
    ap.add_argument("--no-triangle", action="store_true", help="skip Triangle")
    ap.add_argument("--no-figures", action="store_true", help="skip the figures")
    ap.add_argument("--quick", action="store_true", help="a short run: n <= 1600 (800 in the sweep), one timed run")
    ap.add_argument("--out", type=Path, default=default_out or Path("quadratic-study"),
                    help=f"output directory (default {default_out or 'quadratic-study'})")
    ap.add_argument("--dataset", type=Path, help="keep the runs in this sweep dataset (a second run skips what is there)")
    add_cluster_options(ap)
    args = ap.parse_args(argv)
    if args.quick:
        args.max_n = min(args.max_n, 1600)
        args.strategy_max_n = min(args.strategy_max_n, 1600)
        args.sweep_max_n = min(args.sweep_max_n, 800)
        args.repeat = 1
    args.strategy_max_n = max(args.strategy_max_n, 100)
    if not args.no_cgal and not has_cgal():
        print("CGAL's bindings are not installed (pip install cgal): no CGAL runs", flush=True)
        args.no_cgal = True
    try:
        args.alphas = [float(a) for a in args.alphas.split(",") if a.strip()]
        for a in args.alphas:
            quadratic.params(1000, a)
    except ValueError as exc:
        ap.error(f"--alphas: {exc}")
    names = list(instrument.strategies())
    args.strategies = names if args.strategies == "all" else [s.strip() for s in args.strategies.split(",") if s.strip()]
    bad = [s for s in args.strategies + [args.then] if s not in names]
    if bad:
        ap.error(f"unknown strategies {bad}; choose from {', '.join(names)}")
    return args


def main(argv: list[str] | None = None, *, default_out: Path | None = None) -> int:
    args = parse_args(argv, default_out=default_out)
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="ruppert-quadratic-") as tmp:
        rows = measure(args, args.dataset or Path(tmp))
    alpha = args.alphas[0]
    sl = slopes(rows, args.alphas, args.strategies, args.then)
    best = least_work(rows, alpha, args.strategies)
    if not args.no_figures:
        import matplotlib

        matplotlib.use("Agg")
        from .plots import plot_broom, plot_orders, plot_steps, plot_work

        plot_work(rows, sl, alpha, args.strategies, args.then, out)
        plot_broom(out)
        plot_steps(out)
        plot_orders(out, best["strategy"] if best else "worst-angle")
    write_reports(args, rows, sl, best, out, argv)
    print_summary(args, sl, best)
    print(f"wrote {out} in {time.perf_counter() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
