"""Compare ruppert's engine with Triangle and CGAL Mesh_2 on Triangle-format inputs.

    python -m instrument.study.compare                          # the triangle package's samples, switches pq30
    python -m instrument.study.compare data/bracket.poly --switches p --markdown out.md --csv out.csv
    python -m instrument.study.compare --corpus ../shared/corpus --strategies all --plots plots/

Default inputs: the `triangle` package's sample .poly files, and every file of
``--corpus`` that ``ruppert_io.read`` accepts (the deliberately malformed ones
are listed as skipped).  A point set (an input without segments) is run with
``p`` removed from the switches, as Triangle's command line would mesh a
.node file: with ``p`` every engine eats the whole triangulation.

Per engine and input: vertices, triangles, smallest and largest angle, meshed
area, incircle and orientation tests, circumcenter computations, triangles
created (ours), wall time (best of --repeat) and the ratio to Triangle's time.
Flags on our rows: ``size`` (more than 2 % off Triangle's vertex or triangle
count), ``area`` (meshed area differs), ``angle`` (the q bound is missed
where Triangle meets it), ``error``, ``timeout``, ``crash``, ``memory``.
Switches our engine does not implement yet show as ``unsupported``.

The runs are the tasks of a sweep (``instrument.study.sweep``): on an
embedded Dask cluster by default (one process worker per core; times taken
side by side are noisier than ``--workers 1``), on an existing one with
``--scheduler``, or one after the other with ``--sequential``; each in a
process of its own, killed after ``--timeout`` seconds.  ``--dataset`` keeps
the rows (and makes a second run skip what is there).

``compare(tri, opts)`` is the same comparison in this process, for one input
given as a dict.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
from collections.abc import Iterable, Mapping
from dataclasses import asdict, dataclass, field
from pathlib import Path

from ..switches import parse
from . import engines as runners
from .ours_engine import available_strategies

ENGINES = ("ours", "triangle", "cgal")

#: the columns of a row, in table order (``work`` and ``mesh`` are extra)
COLUMNS = (
    "input",
    "switches",
    "engine",
    "strategy",
    "status",
    "vertices",
    "triangles",
    "min_angle",
    "max_angle",
    "area",
    "incircle_tests",
    "orient_tests",
    "circumcenters",
    "triangles_created",
    "wall_s",
    "time_ratio",
    "flags",
    "note",
)

SIZE_TOLERANCE = 0.02  # relative difference in output size that raises a flag
ANGLE_TOLERANCE = 1e-6  # degrees
AREA_TOLERANCE = 1e-9  # relative difference in meshed area that raises a flag
FAILED = ("error", "timeout", "crash", "memory")


@dataclass
class Row:
    """One engine (and strategy) on one input under one switch string."""

    input: str
    switches: str
    engine: str  # "ours", "triangle" or "cgal"
    strategy: str = ""  # ours only
    status: str = "ok"  # ok | unsupported | unavailable | error | timeout | crash | memory
    vertices: int | None = None
    triangles: int | None = None
    min_angle: float | None = None  # degrees
    max_angle: float | None = None
    area: float | None = None  # total area of the output triangles
    incircle_tests: int | None = None
    orient_tests: int | None = None
    circumcenters: int | None = None
    triangles_created: int | None = None  # ours only (Triangle does not count it)
    wall_s: float | None = None  # best of the timed runs
    time_ratio: float | None = None  # wall_s / Triangle's wall_s
    flags: list[str] = field(default_factory=list)
    note: str = ""
    work: dict | None = None  # ours: every counter; Triangle: the parsed statistics
    mesh: dict | None = field(default=None, repr=False, compare=False)  # kept on request

    @property
    def label(self) -> str:
        return f"ours:{self.strategy}" if self.engine == "ours" else self.engine

    def as_dict(self, *, work: bool = True) -> dict:
        """The row as plain JSON-able values (without the mesh)."""
        d = asdict(self)
        d.pop("mesh")
        if not work:
            d.pop("work")
        return d


def row_from_record(rec: Mapping, *, name: str | None = None, switches: str | None = None) -> Row:
    """A ``Row`` from what ``engines.measure`` or a sweep's dataset holds."""
    status = rec.get("status", "ok")
    row = Row(name or rec["input"], switches or rec.get("ran_switches") or rec["switches"], rec["engine"],
              strategy=rec.get("strategy") or "", status=status)
    notes = [x for x in (rec.get("note"), rec.get("message")) if x]
    row.note = "; ".join(notes)
    if status == "ok":
        for k in ("vertices", "triangles", "min_angle", "max_angle", "area", "incircle_tests", "orient_tests",
                  "circumcenters", "triangles_created", "wall_s"):
            setattr(row, k, rec.get(k))
        row.work = dict(rec.get("work") or {})
        if row.engine == "triangle" and "incircle_tests" not in row.work and "statistics" not in row.note:
            row.note = "; ".join([*notes, "statistics not captured"])
        row.mesh = rec.get("mesh")
    return row


def default_strategies(opts: str) -> list[str]:
    """Every strategy when the switches refine (``q``, ``a``, ``u``, ``D``,
    ``r``), else only ``triangle``: the strategy only orders refinement."""
    o = parse(opts)
    return available_strategies() if (o.quality or o.r) else ["triangle"]


def compare(
    tri: dict,
    opts: str = "p",
    *,
    name: str = "input",
    strategies: Iterable[str] | None = None,
    engines: Iterable[str] = ENGINES,
    repeat: int = 3,
    seed: int = 0,
    keep_meshes: bool = False,
) -> list[Row]:
    """Run ``tri`` under the switch string ``opts`` through the chosen engines,
    in this process (no isolation: the sweep isolates; see the module's docstring).

    ``strategies``: our engine's strategies (``None``: ``default_strategies``).
    ``repeat``: timed runs per engine (the best counts).  ``keep_meshes``: store
    each output's vertices, triangles and segments in ``Row.mesh``.
    """
    chosen = tuple(engines)
    unknown = set(chosen) - set(ENGINES)
    if unknown:
        raise ValueError(f"unknown engine(s) {sorted(unknown)}; choose from {ENGINES}")
    strategies = list(strategies) if strategies is not None else default_strategies(opts)
    rows = []
    for engine in order_engines(chosen):
        for strategy in (strategies if engine == "ours" else [""]):
            rec = runners.measure(engine, tri, opts, strategy=strategy, seed=seed, repeat=repeat, keep_mesh=keep_meshes)
            rows.append(row_from_record({**rec, "input": name, "switches": opts, "engine": engine, "strategy": strategy}))
    finish(rows, opts)
    return rows


def order_engines(chosen: Iterable[str]) -> list[str]:
    """Triangle first (the reference), then ours, then CGAL."""
    return [e for e in ("triangle", "ours", "cgal") if e in set(chosen)]


def finish(rows: list[Row], opts: str) -> None:
    """Time ratios to Triangle's time and flags, for the rows of one input."""
    tri = next((r for r in rows if r.engine == "triangle" and r.status == "ok"), None)
    base = tri.wall_s if tri is not None else None
    for row in rows:
        if base and row.wall_s is not None:
            row.time_ratio = row.wall_s / base
    flag_rows(rows, opts)


def flag_rows(rows: list[Row], opts: str) -> None:
    """Set ``flags`` on our engine's rows: ``size`` (vertices or triangles differ
    from Triangle's by more than 2 %), ``area`` (meshed area differs), ``angle``
    (a ``q`` bound is not met, unless Triangle's own smallest angle misses it
    too, as happens next to small input angles), and a failure's status."""
    o = parse(opts)
    ref = next((r for r in rows if r.engine == "triangle" and r.status == "ok"), None)
    for row in rows:
        if row.engine != "ours":
            continue
        if row.status in FAILED:
            row.flags.append(row.status)
        if row.status != "ok":
            continue
        if ref is not None:
            for attr in ("vertices", "triangles"):
                mine, theirs = getattr(row, attr), getattr(ref, attr)
                if abs(mine - theirs) > SIZE_TOLERANCE * theirs:
                    row.flags.append("size")
                    break
            if abs(row.area - ref.area) > AREA_TOLERANCE * max(abs(ref.area), 1e-300):
                row.flags.append("area")
        if o.q and row.min_angle is not None and row.min_angle < o.min_angle - ANGLE_TOLERANCE:
            ref_ok = ref is not None and ref.min_angle is not None and ref.min_angle < o.min_angle - ANGLE_TOLERANCE
            if not ref_ok:
                row.flags.append("angle")


# ---------------------------------------------------------------------------------------------
# the command line: a sweep, then the table


def strategy_choice(text: str | None, switches: str) -> list[str]:
    if text is None or text == "auto":
        return default_strategies(switches)
    if text == "all":
        return available_strategies()
    return [s.strip() for s in text.split(",") if s.strip()]


def default_inputs(corpus: Path | None) -> list:
    from . import inputs

    chosen = inputs.parse_input("samples")
    if corpus is not None:
        chosen += [inputs.file_input(p) for p in inputs.folder_files(corpus)]
    return chosen


def rows_of_sweep(path: Path, tasks, *, keep_meshes: bool) -> list[Row]:
    """The comparison's rows, from the sweep's dataset, in the grid's order."""
    import numpy as np

    from . import dataset

    by_key = {r["key"]: r for r in dataset.read(path)}
    rows: list[Row] = []
    groups: dict[tuple, list[Row]] = {}
    for t in tasks:
        rec = by_key.get(t.key)
        if rec is None:
            continue
        row = row_from_record(rec)
        f = dataset.mesh_path(path, t.key)
        if keep_meshes and f.is_file():
            with np.load(f) as z:
                row.mesh = {k: z[k] for k in z.files}
        rows.append(row)
        groups.setdefault((t.input.label, t.input.digest), []).append(row)
    for g in groups.values():
        finish(g, g[0].switches)
    return rows


def main(argv: list[str] | None = None, *, default_corpus: Path | None = None) -> int:
    from . import compare_report, sweep

    ap = argparse.ArgumentParser(prog="python -m instrument.study.compare", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("inputs", nargs="*", type=Path, help="Triangle-format files (default: samples and --corpus)")
    ap.add_argument("--switches", default="pq30", help="Triangle's switches (library form, no dash); default pq30")
    ap.add_argument("--strategies", default="auto",
                    help="our strategies: all, a comma list, or auto (all when the switches refine, else triangle)")
    ap.add_argument("--engines", default="ours,triangle,cgal", help="comma list of ours, triangle, cgal")
    ap.add_argument("--repeat", type=int, default=3, help="timed runs per engine (best counts)")
    ap.add_argument("--seed", type=int, default=0, help="seed for our engine (random strategy)")
    ap.add_argument("--timeout", type=float, default=120.0, help="seconds per engine run, in a process of its own (0: no limit)")
    ap.add_argument("--corpus", type=Path, default=default_corpus, help="a folder of inputs added to the default inputs")
    ap.add_argument("--dataset", type=Path, help="keep the runs in this sweep dataset (a second run skips what is there)")
    ap.add_argument("--markdown", type=Path, help="write a Markdown table")
    ap.add_argument("--csv", type=Path, help="write CSV")
    ap.add_argument("--json", type=Path, help="write JSON (with every work counter)")
    ap.add_argument("--plots", type=Path, help="directory for meshes side by side and work per strategy (PNG)")
    ap.add_argument("--quiet", action="store_true", help="no terminal table, no progress bar")
    sweep.add_cluster_options(ap)
    args = ap.parse_args(argv)

    from . import inputs

    try:
        parse(args.switches)
        memory = sweep.memory_bytes(args.memory_limit)
    except ValueError as exc:
        ap.error(str(exc))
    chosen = [inputs.file_input(p) for p in args.inputs] if args.inputs else default_inputs(args.corpus)
    if not chosen:
        ap.error("no inputs (give files, or install the triangle package / provide --corpus)")
    samples = {p.resolve() for p in inputs.package_samples()}
    chosen = [inputs.file_input(Path(i.source), f"triangle/{Path(i.source).name}")
              if Path(i.source).resolve() in samples else i for i in chosen]
    engine_names = [e.strip() for e in args.engines.split(",") if e.strip()]
    unknown = set(engine_names) - set(ENGINES)
    if unknown:
        ap.error(f"unknown engine(s) {sorted(unknown)}; choose from {', '.join(ENGINES)}")
    g = sweep.grid(chosen, [args.switches], engine_names=order_engines(engine_names),
                   strategies=strategy_choice(args.strategies, args.switches), seed=args.seed, repeat=args.repeat,
                   time_limit=args.timeout or None, memory_limit=memory, keep_mesh=args.plots is not None)
    skipped = [(c["label"], f"unreadable ({c['reason']})") for c in g.catalog if c["status"] != "ok"]
    with tempfile.TemporaryDirectory(prefix="ruppert-compare-") as tmp:
        path = args.dataset or Path(tmp)
        try:
            sweep.run(g, path, scheduler=args.scheduler, workers=args.workers, sequential=args.sequential,
                      progress=not args.quiet)
        except sweep.SweepError as exc:
            print(f"Error: {exc}", file=sys.stderr)
            return 1
        rows = rows_of_sweep(path, g.tasks, keep_meshes=args.plots is not None)
    if args.plots is not None:
        args.plots.mkdir(parents=True, exist_ok=True)
        by_input: dict[str, list[Row]] = {}
        for r in rows:
            by_input.setdefault(r.input, []).append(r)
        for name, group in by_input.items():
            compare_report.plot_input(args.plots, name, group)
    if not args.quiet:
        compare_report.print_table(rows, skipped, args.switches)
    if args.markdown:
        compare_report.write_markdown(args.markdown, rows, skipped, args.switches)
    if args.csv:
        compare_report.write_csv(args.csv, rows, COLUMNS)
    if args.json:
        compare_report.write_json(args.json, rows, skipped, args.switches)
    return 0


if __name__ == "__main__":
    os.environ.setdefault("MPLBACKEND", "Agg")
    sys.exit(main())
