"""The benchmark's command line: choose the workloads, run them, report."""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from . import __doc__ as OVERVIEW
from . import report
from .workloads import WORKLOADS, select


def build_parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="python -m instrument.study.bench", description=OVERVIEW,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("workloads", nargs="*",
                    help="names or prefixes of the workloads to run (default: every one that is not opt-in); "
                         "an opt-in workload (cold, dt-1e7, *-tiny) runs only when named in full")
    ap.add_argument("--cold", action="store_true", help="also run the cold workload (minutes: a pip install)")
    ap.add_argument("--all", action="store_true",
                    help="every workload, the opt-in ones too (cold, dt-1e7), but not the tests' stand-ins (*-tiny)")
    ap.add_argument("--source", help="cold: what to pip install (a checkout, an sdist, a wheel or a requirement; "
                                     "default: a copy of the checkout this ruppert runs from)")
    ap.add_argument("--repeat", type=int, default=3, help="interleaved timed rounds (best counts); default 3")
    ap.add_argument("--threads", type=int,
                    help="passed to instrument.triangulate(..., threads=N); an error if this engine has no such "
                         "argument")
    ap.add_argument("--no-memory", action="store_true", help="skip the peak-memory processes")
    ap.add_argument("--no-cgal", action="store_true", help="do not run CGAL")
    ap.add_argument("--no-stats", action="store_true", help="skip Triangle's statistics run (V)")
    ap.add_argument("--strategies", default="all",
                    help="our strategies for the strategy workloads (quad-*): all (instrument.strategies()) "
                         "or a comma list; the other workloads use 'triangle'")
    ap.add_argument("--timeout", type=float, default=60.0,
                    help="seconds per run of ours on the strategy workloads (a separate process, killed after "
                         "it; a strategy that times out is not run again); 0: in this process, no limit. "
                         "Default 60")
    ap.add_argument("--profile", action="store_true",
                    help="also time our stages on the in-process workloads selected")
    ap.add_argument("--json", type=Path, help="also write the rows as JSON")
    ap.add_argument("--markdown", type=Path, help="also write the report as Markdown")
    ap.add_argument("--list", action="store_true", help="list the workloads and strategies, then stop")
    return ap


def check_threads(ap: argparse.ArgumentParser, threads: int | None) -> None:
    from ..ours_engine import engine_options

    if threads is None:
        return
    if threads < 1:
        ap.error("--threads must be at least 1")
    try:
        engine_options(threads)
    except TypeError as exc:
        ap.error(f"--threads: {exc}; this engine runs on one thread only")


def main(argv: list[str] | None = None) -> int:
    from .timing import available_strategies

    ap = build_parser()
    args = ap.parse_args(argv)
    if args.list:
        for n, w in WORKLOADS.items():
            print(f"{n:<16} {w.opts or '(none)':<14} {w.label}{'  (opt-in)' if w.opt_in else ''}")
        print("strategies:", ", ".join(available_strategies()))
        return 0
    try:
        names = select(args.workloads, cold=args.cold, everything=args.all)
    except ValueError as exc:
        ap.error(str(exc))
    if args.repeat < 1:
        ap.error("--repeat must be at least 1")
    check_threads(ap, args.threads)
    known = available_strategies()
    if args.strategies == "all":
        strategies = known
    else:
        strategies = [s.strip() for s in args.strategies.split(",") if s.strip()]
        unknown = [s for s in strategies if s not in known]
        if unknown or not strategies:
            ap.error(f"unknown strategy {', '.join(unknown) or '(none)'}; choose from {', '.join(known)}")
    state, code = report.provenance()  # before: the work tree may change while this runs
    given = argv if argv is not None else sys.argv[1:]
    meta = {"command": "python -m instrument.study.bench" + "".join(f" {a}" for a in given),
            "machine": report.machine(), "load_start": list(os.getloadavg()), "repeat": args.repeat,
            "threads": args.threads}
    rows = []
    for name in names:
        print(f"{name} ... (load average {report.fmt_load(os.getloadavg())})", file=sys.stderr, flush=True)
        try:
            got = run_workload(name, args, strategies)
        except (RuntimeError, ValueError, OSError) as exc:  # a failed install or command: say so, go on
            print(f"  {name} failed: {exc}", file=sys.stderr, flush=True)
            continue
        for row in got:
            print("  " + "  ".join(f"{c}={v}" for c, v in zip(report.COLS[2:], report.cells(row)[2:])),
                  file=sys.stderr, flush=True)
        rows.extend(got)
    profiles = []
    if args.profile:
        from .stages import profile

        for name in names:
            w = WORKLOADS[name]
            if w.in_process and not w.sweep:
                profiles.append((name, w.opts, "triangle", profile(name, "triangle", args.repeat, args.threads)))
    meta["load_end"] = list(os.getloadavg())
    now, code_now = report.provenance()
    if code_now != code:
        state += f"; the engine changed during the run, now {now}"
        print(f"warning: {state}", file=sys.stderr)
    meta["provenance"] = state
    report.print_report(rows, f"ruppert vs Triangle vs CGAL, best of {args.repeat} interleaved rounds ({state}; "
                              f"load average {report.fmt_load(meta['load_start'])} at the start)", profiles)
    if args.json:
        report.write_json(args.json, rows, meta, profiles)
    if args.markdown:
        report.write_markdown(args.markdown, rows, meta, profiles)
    return 0 if len({r["workload"] for r in rows}) == len(names) else 1


def run_workload(name: str, args, strategies: list[str]) -> list[dict]:
    w = WORKLOADS[name]
    if w.cold:
        from .cold import bench_cold

        return bench_cold(name, source=args.source)
    if not w.in_process:
        from .commands import bench_command

        return bench_command(name, args.repeat)
    from .timing import bench_in_process

    return bench_in_process(name, args.repeat, not args.no_memory, strategies=strategies, cgal=not args.no_cgal,
                            stats=not args.no_stats, timeout=args.timeout, threads=args.threads)
