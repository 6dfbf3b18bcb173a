#!/usr/bin/env python
"""Compare ruppert's engine with Triangle and CGAL Mesh_2 on Triangle-format inputs.

    python scripts/compare.py                          # default inputs, switches pq30
    python scripts/compare.py data/A.poly --switches p --markdown out.md --csv out.csv
    python scripts/compare.py --strategies all --plots plots/

Default inputs: the `triangle` package's sample .poly files and every file of
../shared/corpus that ``ruppert_io.read`` accepts (the deliberately malformed
ones are skipped with a note).  A point set (an input without segments) is
run with ``p`` removed from the switches, as Triangle's command line would
mesh a .node file: with ``p`` every engine eats the whole triangulation.

Per engine and input: vertices, triangles, smallest and largest angle, meshed
area, incircle and orientation tests, circumcenter computations, triangles
created (ours), wall time (best of --repeat) and the ratio to Triangle's time.
Flags on our rows: ``size`` (more than 2 % off Triangle's vertex or triangle
count), ``area`` (meshed area differs), ``angle`` (the q bound is missed
where Triangle meets it), ``error``, ``timeout`` (each run of our engine
happens in a child process killed after --timeout seconds).  Switches our engine does not implement
yet show as ``unsupported``.  The comparison itself is
``instrument.comparison.compare``; this script reads files and writes reports.
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import os
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import ruppert_io
from instrument.comparison import COLUMNS, available_strategies, compare
from instrument.switches import parse

DEFAULT_CORPUS = ROOT.parent / "shared" / "corpus"

LEGEND = (
    "Flags (our rows): size = vertex or triangle count more than 2 % off Triangle's; "
    "area = meshed area differs from Triangle's; angle = the q bound is missed where Triangle meets it; "
    "error / timeout = the engine failed / was killed after --timeout seconds. Triangle's orientation count is its printed statistic minus the one "
    "test per output triangle its statistics make. CGAL Mesh_2: q<angle> -> shape bound b = sin^2(angle), "
    "a<area> -> size bound S = sqrt(4*area/sqrt(3)) (CGAL guarantees termination only up to b = 0.125, "
    "20.7 degrees); CGAL counts no work. "
    "Times: best of the repeated runs; ratio = time / Triangle's time."
)


def package_samples() -> list[Path]:
    """The `triangle` package's sample PSLGs (its data/*.poly inputs, not its outputs)."""
    try:
        import triangle
    except ImportError:
        return []
    data = Path(triangle.__file__).resolve().parent / "data"
    return sorted(p for p in data.glob("*.poly") if "." not in p.stem)


def corpus_files(corpus: Path) -> list[Path]:
    if not corpus.is_dir():
        return []
    return sorted(p for p in corpus.iterdir() if p.is_file() and p.suffix.lower() in (".poly", ".node", ".ele", ".area"))


def input_name(path: Path, samples: set[Path]) -> str:
    return f"triangle/{path.name}" if path.resolve() in samples else path.name


def effective_switches(data: dict, switches: str) -> tuple[str, str]:
    """Drop ``p`` for a point set (no segments); returns (switches, note)."""
    segs = data.get("segments")
    if "p" in switches and (segs is None or len(segs) == 0) and "r" not in switches:
        return switches.replace("p", ""), "point set: p dropped"
    return switches, ""


def strategy_choice(text: str | None) -> list[str] | None:
    if text is None or text == "auto":
        return None
    if text == "all":
        return available_strategies()
    return [s.strip() for s in text.split(",") if s.strip()]


# ---------------------------------------------------------------------------------------------
# formatting


def fmt(key: str, value, *, empty: str = "—") -> str:
    if value is None:
        return empty
    if key == "flags":
        return ",".join(value)
    if key in ("min_angle", "max_angle"):
        return f"{value:.2f}"
    if key == "area":
        return f"{value:.6g}"
    if key == "wall_s":
        return f"{value * 1e3:.3f}"
    if key == "time_ratio":
        return f"{value:.2f}"
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)


HEADERS = {
    "input": "input",
    "switches": "switches",
    "engine": "engine",
    "status": "status",
    "vertices": "V",
    "triangles": "T",
    "min_angle": "min°",
    "max_angle": "max°",
    "area": "area",
    "incircle_tests": "incircle",
    "orient_tests": "orient",
    "circumcenters": "circumc.",
    "triangles_created": "created",
    "wall_s": "ms",
    "time_ratio": "×Tri",
    "flags": "flags",
    "note": "note",
}
TABLE_KEYS = [k for k in HEADERS if k != "note"]


def cell(row, key: str) -> str:
    if key == "engine":
        return row.label
    return fmt(key, getattr(row, key))


def print_table(rows, skipped: list[tuple[str, str]], switches: str) -> None:
    from rich.console import Console
    from rich.table import Table

    console = Console()
    if not console.is_terminal:
        console = Console(width=max(console.width, 240))
    table = Table(title=f"ruppert vs Triangle vs CGAL Mesh_2 ({switches})", show_lines=False)
    numeric = {"vertices", "triangles", "min_angle", "max_angle", "area", "incircle_tests", "orient_tests",
               "circumcenters", "triangles_created", "wall_s", "time_ratio"}
    for key in TABLE_KEYS:
        table.add_column(HEADERS[key], justify="right" if key in numeric else "left", overflow="fold")
    last = None
    for row in rows:
        if last is not None and row.input != last:
            table.add_section()
        last = row.input
        style = "bold red" if row.flags else ("yellow" if row.status != "ok" else None)
        table.add_row(*(cell(row, k) for k in TABLE_KEYS), style=style)
    console.print(table)
    notes: dict[tuple[str, str], list[str]] = {}
    for r in rows:
        if r.note:
            notes.setdefault((r.input, r.note), []).append(r.label)
    if notes or skipped:
        console.print("[bold]Notes[/bold]")
    for (name, note), labels in notes.items():
        every = len(labels) == sum(r.input == name for r in rows)
        who = "all engines" if every else ", ".join(labels)
        console.print(f"  {name} [{who}]: {note}", markup=False, highlight=False)
    for name, why in skipped:
        console.print(f"  skipped {name}: {why}", markup=False, highlight=False)
    console.print(LEGEND, style="dim", markup=False, highlight=False)


def write_markdown(path: Path, rows, skipped, switches: str) -> None:
    keys = TABLE_KEYS + ["note"]
    lines = [f"# ruppert vs Triangle vs CGAL Mesh_2, switches `{switches}`", ""]
    lines.append("| " + " | ".join(HEADERS[k] for k in keys) + " |")
    lines.append("|" + "|".join("---:" if k not in ("input", "switches", "engine", "status", "flags", "note") else "---"
                                 for k in keys) + "|")
    for row in rows:
        cells = [cell(row, k).replace("|", "\\|") for k in keys]
        if row.flags:
            cells = [f"**{c}**" if c and c != "—" else c for c in cells]
        lines.append("| " + " | ".join(cells) + " |")
    lines.append("")
    if skipped:
        lines.append("Skipped inputs:")
        lines.append("")
        lines.extend(f"- `{name}`: {why}" for name, why in skipped)
        lines.append("")
    lines.append(LEGEND)
    path.write_text("\n".join(lines) + "\n")


def write_csv(path: Path, rows) -> None:
    with path.open("w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for row in rows:
            d = row.as_dict(work=False)
            w.writerow(["" if d[k] is None else (";".join(d[k]) if k == "flags" else d[k]) for k in COLUMNS])


def write_json(path: Path, rows, skipped, switches: str) -> None:
    def clean(v):
        if isinstance(v, float) and not math.isfinite(v):
            return None
        return v

    doc = {
        "switches": switches,
        "rows": [{k: clean(v) for k, v in r.as_dict().items()} for r in rows],
        "skipped": [{"input": n, "reason": why} for n, why in skipped],
    }
    path.write_text(json.dumps(doc, indent=1, default=int))


# ---------------------------------------------------------------------------------------------
# plots


def safe(name: str) -> str:
    return re.sub(r"[^A-Za-z0-9._-]+", "_", name)


def plot_input(directory: Path, name: str, rows) -> list[Path]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.collections import LineCollection

    written = []
    ours = [r for r in rows if r.engine == "ours"]
    first = next((r for r in ours if r.status == "ok"), ours[0] if ours else None)
    panels = [r for r in (first, *[r for r in rows if r.engine in ("triangle", "cgal")]) if r is not None]
    if panels:
        fig, axes = plt.subplots(1, len(panels), figsize=(4.5 * len(panels), 4.5), squeeze=False)
        for ax, row in zip(axes[0], panels):
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
            mesh = row.mesh or {}
            tris = mesh.get("triangles")
            if row.status == "ok" and tris is not None and len(tris):
                xy = mesh["vertices"]
                ax.triplot(xy[:, 0], xy[:, 1], tris[:, :3], color="k", lw=0.4)
                segs = mesh.get("segments")
                if segs is not None and len(segs):
                    ax.add_collection(LineCollection(xy[np.asarray(segs)], colors="r", linewidths=0.8))
                ax.set_title(f"{row.label}\nV {row.vertices}  T {row.triangles}  min {fmt('min_angle', row.min_angle)}°",
                             fontsize=9)
            else:
                ax.text(0.5, 0.5, row.status if row.status != "ok" else "no triangles", ha="center", va="center",
                        transform=ax.transAxes)
                ax.set_title(row.label, fontsize=9)
        fig.suptitle(f"{name} ({rows[0].switches})", fontsize=10)
        fig.tight_layout()
        out = directory / f"{safe(name)}.meshes.png"
        fig.savefig(out, dpi=110)
        plt.close(fig)
        written.append(out)

    bars = [r for r in rows if r.engine in ("ours", "triangle") and r.status == "ok"]
    if bars:
        metrics = ["triangles_created", "incircle_tests", "orient_tests", "circumcenters"]
        fig, ax = plt.subplots(figsize=(min(12.0, max(5.0, 0.6 * len(bars) * len(metrics))), 4))
        width = 0.8 / len(bars)
        for i, row in enumerate(bars):
            vals = [getattr(row, m) or 0 for m in metrics]
            ax.bar([j + i * width for j in range(len(metrics))], vals, width, label=row.label)
        ax.set_xticks([j + 0.4 - width / 2 for j in range(len(metrics))])
        ax.set_xticklabels(["triangles created", "incircle", "orient", "circumcenters"])
        ax.set_ylabel("count")
        ax.set_title(f"work per strategy: {name} ({rows[0].switches})", fontsize=10)
        ax.legend(fontsize=8)
        fig.tight_layout()
        out = directory / f"{safe(name)}.work.png"
        fig.savefig(out, dpi=110)
        plt.close(fig)
        written.append(out)
    return written


# ---------------------------------------------------------------------------------------------


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("inputs", nargs="*", type=Path, help="Triangle-format files (default: samples and corpus)")
    ap.add_argument("--switches", default="pq30", help="Triangle's switches (library form, no dash); default pq30")
    ap.add_argument("--strategies", default="auto",
                    help="our strategies: all, a comma list, or auto (all when the switches refine, else triangle)")
    ap.add_argument("--engines", default="ours,triangle,cgal", help="comma list of ours, triangle, cgal")
    ap.add_argument("--repeat", type=int, default=3, help="timed runs per engine (best counts)")
    ap.add_argument("--seed", type=int, default=0, help="seed for our engine (random strategy)")
    ap.add_argument("--timeout", type=float, default=120.0,
                    help="seconds per run of our engine, in a child process (0: no limit, in this process)")
    ap.add_argument("--corpus", type=Path, default=DEFAULT_CORPUS, help="corpus directory for the default inputs")
    ap.add_argument("--markdown", type=Path, help="write a Markdown table")
    ap.add_argument("--csv", type=Path, help="write CSV")
    ap.add_argument("--json", type=Path, help="write JSON (with every work counter)")
    ap.add_argument("--plots", type=Path, help="directory for meshes side by side and work per strategy (PNG)")
    ap.add_argument("--quiet", action="store_true", help="no terminal table")
    args = ap.parse_args(argv)

    try:
        parse(args.switches)
    except ValueError as exc:
        ap.error(f"--switches: {exc}")
    samples = {p.resolve() for p in package_samples()}
    inputs = list(args.inputs) or sorted(samples) + corpus_files(args.corpus)
    if not inputs:
        ap.error("no inputs (give files, or install the triangle package / provide --corpus)")
    strategies = strategy_choice(args.strategies)
    engines = [e.strip() for e in args.engines.split(",") if e.strip()]

    rows, skipped = [], []
    for k, path in enumerate(inputs, 1):
        name = input_name(path, samples)
        if not args.quiet:
            print(f"[{k}/{len(inputs)}] {name}", file=sys.stderr, flush=True)
        try:
            data = ruppert_io.read(path)
        except ruppert_io.FormatError as exc:
            skipped.append((name, f"unreadable ({exc})"))
            continue
        except OSError as exc:
            skipped.append((name, f"cannot open ({exc.strerror or exc})"))
            continue
        switches, note = effective_switches(data, args.switches)
        got = compare(data, switches, name=name, strategies=strategies, engines=engines, repeat=args.repeat,
                      seed=args.seed, keep_meshes=args.plots is not None,
                      timeout=args.timeout if args.timeout > 0 else None)
        if note:
            for r in got:
                r.note = f"{note}; {r.note}" if r.note else note
        rows.extend(got)
        if args.plots is not None:
            args.plots.mkdir(parents=True, exist_ok=True)
            plot_input(args.plots, name, got)

    if not args.quiet:
        print_table(rows, skipped, args.switches)
    if args.markdown:
        write_markdown(args.markdown, rows, skipped, args.switches)
    if args.csv:
        write_csv(args.csv, rows)
    if args.json:
        write_json(args.json, rows, skipped, args.switches)
    return 0


if __name__ == "__main__":
    os.environ.setdefault("MPLBACKEND", "Agg")
    raise SystemExit(main())
