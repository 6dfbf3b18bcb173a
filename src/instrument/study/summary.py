"""Tables and plots of a sweep's dataset: ``python -m instrument.study.sweep summary DATASET``.

Everything here reads the dataset (``instrument.study.dataset.read``), never a
run in progress, so a summary can be made again at any time, of a sweep
that was interrupted, resumed or run elsewhere.

* ``summary.md`` / ``summary.csv``: per switches and engine (ours per
  strategy): how many rows of each status; how many meshes miss the ``q``
  angle bound where Triangle meets it ("below q"); median output vertices per input
  vertex; median work per output vertex (triangles created, incircle tests);
  median size against Triangle's on the same input (output vertices, ours /
  Triangle's); total wall time of the engine and of the tasks; largest peak
  memory.  Then every row that is not ``ok``, and the inputs not read.
* ``rows.csv``: every row (the counters of ``work`` as JSON).
* ``work-per-vertex.png``: triangles created and incircle tests per output
  vertex, per strategy (one box per strategy, over the inputs).
* ``sizes-vs-triangle.png``: our output vertices against Triangle's, per
  strategy, one point per input.
"""

from __future__ import annotations

import argparse
import csv
import json
import statistics
import sys
from collections import defaultdict
from pathlib import Path

from . import dataset

STATUSES = ("ok", "timeout", "crash", "memory", "error", "unsupported", "unavailable", "skipped")
HEADER = ("switches", "engine", "rows", *STATUSES, "below q", "out/in vertices", "created/vertex", "incircle/vertex",
          "vertices/Triangle's", "engine s", "task s", "peak MiB")
ANGLE_TOLERANCE = 1e-6  # degrees


def label(row: dict) -> str:
    return f"{row['engine']}:{row['strategy']}" if row.get("strategy") else row["engine"]


def _median(values) -> float | None:
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None


def _per(a, b):
    return a / b if a is not None and b else None


def triangle_reference(rows: list[dict]) -> dict[tuple, dict]:
    """Triangle's ok row per (input, digest, switches)."""
    return {(r["input"], r["digest"], r["switches"]): r for r in rows if r["engine"] == "triangle" and r["status"] == "ok"}


def misses_bound(row: dict) -> bool:
    """Is the row's smallest angle below its ``q`` bound?"""
    from instrument.switches import parse

    o = parse(row.get("ran_switches") or row["switches"])
    return bool(o.q) and row.get("min_angle") is not None and row["min_angle"] < o.min_angle - ANGLE_TOLERANCE


def aggregate(rows: list[dict]) -> list[dict]:
    """One line per (switches, engine label), in a stable order."""
    ref = triangle_reference(rows)
    groups: dict[tuple, list[dict]] = defaultdict(list)
    for r in rows:
        groups[(r["switches"], label(r))].append(r)
    order = {"triangle": 0, "cgal": 2}
    out = []
    for (sw, lab), rs in sorted(groups.items(), key=lambda kv: (kv[0][0], order.get(kv[0][1], 1), kv[0][1])):
        ok = [r for r in rs if r["status"] == "ok"]
        line = {"switches": sw, "engine": lab, "rows": len(rs)}
        for s in STATUSES:
            line[s] = sum(r["status"] == s for r in rs)
        line["below q"] = sum(misses_bound(r) and not misses_bound(ref.get((r["input"], r["digest"], r["switches"]), r))
                              for r in ok if r["engine"] != "triangle")
        line["out/in vertices"] = _median(_per(r["vertices"], r["input_vertices"]) for r in ok)
        line["created/vertex"] = _median(_per(r["triangles_created"], r["vertices"]) for r in ok)
        line["incircle/vertex"] = _median(_per(r["incircle_tests"], r["vertices"]) for r in ok)
        line["vertices/Triangle's"] = _median(
            _per(r["vertices"], ref[(r["input"], r["digest"], r["switches"])]["vertices"])
            for r in ok if (r["input"], r["digest"], r["switches"]) in ref)
        line["engine s"] = sum(r["wall_s"] or 0.0 for r in ok)
        line["task s"] = sum(r["task_s"] or 0.0 for r in rs)
        peaks = [r["peak_mb"] for r in ok if r["peak_mb"] is not None]
        line["peak MiB"] = max(peaks) if peaks else None
        out.append(line)
    return out


def _fmt(v) -> str:
    if v is None:
        return "—"
    if isinstance(v, float):
        return f"{v:.3g}" if abs(v) < 1000 else f"{v:,.0f}"
    return str(v)


def markdown(rows: list[dict], catalog: list[dict], source: str = "") -> str:
    lines = [f"# Sweep summary{f': `{source}`' if source else ''}", ""]
    keys = {r["key"] for r in rows}
    inputs_n = len({(r["input"], r["digest"]) for r in rows})
    lines.append(f"{len(keys)} rows over {inputs_n} inputs.  Medians are over the inputs where the row is `ok`; "
                 "times are sums.  vertices/Triangle's: output vertices over Triangle's on the same input and switches.")
    lines.append("")
    agg = aggregate(rows)
    shown = [h for h in HEADER if h not in STATUSES or h == "ok" or any(a[h] for a in agg)]
    lines.append("| " + " | ".join(shown) + " |")
    lines.append("|" + "|".join("---" if h in ("switches", "engine") else "---:" for h in shown) + "|")
    for a in agg:
        lines.append("| " + " | ".join(_fmt(a[h]) for h in shown) + " |")
    bad = [r for r in rows if r["status"] != "ok"]
    if bad:
        lines += ["", "Rows that are not `ok`:", "", "| input | switches | engine | status | message |", "|---|---|---|---|---|"]
        for r in sorted(bad, key=lambda r: (r["status"], r["input"], r["switches"], label(r))):
            msg = (r["message"] or "").replace("|", "\\|")
            lines.append(f"| {r['input']} | {r['switches']} | {label(r)} | {r['status']} | {msg} |")
    unread = [c for c in catalog if c.get("status") != "ok"]
    if unread:
        lines += ["", "Inputs not read:", ""]
        lines += [f"- `{c['label']}`: {c.get('reason', '')}" for c in unread]
    return "\n".join(lines) + "\n"


def write_csv(path: Path, agg: list[dict]) -> None:
    with path.open("w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(HEADER))
        w.writeheader()
        w.writerows(agg)


def write_rows_csv(path: Path, rows: list[dict]) -> None:
    cols = [c for c in dataset.COLUMNS]
    with path.open("w", newline="") as f:
        w = csv.writer(f)
        w.writerow(cols)
        for r in rows:
            w.writerow([json.dumps(r[c], sort_keys=True) if isinstance(r[c], dict) else ("" if r[c] is None else r[c])
                        for c in cols])


def plot_work(rows: list[dict], path: Path) -> bool:
    """Triangles created and incircle tests per output vertex, per strategy (boxes over the inputs)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    switches = sorted({r["switches"] for r in rows})
    ok = [r for r in rows if r["status"] == "ok" and r["vertices"]]
    if not ok:
        return False
    fig, axes = plt.subplots(2, len(switches), figsize=(max(6.0, 5.5 * len(switches)), 8), squeeze=False)
    for j, sw in enumerate(switches):
        for i, (key, title) in enumerate((("triangles_created", "triangles created per output vertex"),
                                          ("incircle_tests", "incircle tests per output vertex"))):
            ax = axes[i, j]
            labels = sorted({label(r) for r in ok if r["switches"] == sw and r[key] is not None})
            data = [[r[key] / r["vertices"] for r in ok if r["switches"] == sw and label(r) == lab and r[key] is not None]
                    for lab in labels]
            if data:
                ax.boxplot(data, showfliers=True)
                ax.set_xticks(range(1, len(labels) + 1), labels, rotation=45, ha="right", fontsize=8)
            ax.set_yscale("log")
            ax.set_title(f"{title} ({sw})", fontsize=10)
            ax.grid(True, axis="y", which="both", alpha=0.25)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


def plot_sizes(rows: list[dict], path: Path) -> bool:
    """Our output vertices against Triangle's on the same input, per strategy."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ref = triangle_reference(rows)
    pairs = [(r, ref[(r["input"], r["digest"], r["switches"])]) for r in rows
             if r["engine"] != "triangle" and r["status"] == "ok" and (r["input"], r["digest"], r["switches"]) in ref]
    pairs = [(r, t) for r, t in pairs if r["vertices"] and t["vertices"]]
    if not pairs:
        return False
    switches = sorted({r["switches"] for r, _ in pairs})
    fig, axes = plt.subplots(1, len(switches), figsize=(max(6.0, 6 * len(switches)), 5.5), squeeze=False)
    markers = "osD^v<>ph*X"
    for j, sw in enumerate(switches):
        ax = axes[0, j]
        labels = sorted({label(r) for r, _ in pairs if r["switches"] == sw})
        for k, lab in enumerate(labels):
            xs = [t["vertices"] for r, t in pairs if r["switches"] == sw and label(r) == lab]
            ys = [r["vertices"] for r, t in pairs if r["switches"] == sw and label(r) == lab]
            ax.scatter(xs, ys, s=14, marker=markers[k % len(markers)], label=lab, alpha=0.75)
        lo = min(min(t["vertices"], r["vertices"]) for r, t in pairs)
        hi = max(max(t["vertices"], r["vertices"]) for r, t in pairs)
        ax.plot([lo, hi], [lo, hi], "k:", lw=1)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("Triangle's output vertices")
        ax.set_ylabel("output vertices")
        ax.set_title(f"output size against Triangle's ({sw})", fontsize=10)
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.25)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


def is_current(source: Path, out: Path) -> bool:
    """Whether ``out`` holds a summary written after the last part of ``source``
    (with its plots), so that writing it again would give the same files."""
    parts = dataset.parts(source)
    files = [Path(out) / name for name in ("summary.md", "summary.csv", "rows.csv")]
    if not parts or not all(f.exists() for f in files):
        return False
    newest_part = max(p.stat().st_mtime for p in parts + [Path(source) / "inputs.json"] if p.exists())
    return min(f.stat().st_mtime for f in files) >= newest_part


def write(source: Path, out: Path, *, plots: bool = True) -> list[Path]:
    """Write the summary of the dataset ``source`` into ``out``; the files written."""
    rows = dataset.read(source)
    if not rows:
        return []
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    written = [out / "summary.md", out / "summary.csv", out / "rows.csv"]
    written[0].write_text(markdown(rows, dataset.read_inputs(source), str(source)))
    write_csv(written[1], aggregate(rows))
    write_rows_csv(written[2], rows)
    if plots:
        for name, fn in (("work-per-vertex.png", plot_work), ("sizes-vs-triangle.png", plot_sizes)):
            if fn(rows, out / name):
                written.append(out / name)
    return written


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m instrument.study.sweep summary", description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__.split("\n\n", 2)[2])
    ap.add_argument("dataset", type=Path, help="the sweep's dataset directory")
    ap.add_argument("--out", type=Path, help="where to write (default DATASET/summary)")
    ap.add_argument("--no-plots", action="store_true")
    ap.add_argument("--quiet", action="store_true", help="do not print the Markdown table")
    args = ap.parse_args(argv)
    if not dataset.parts(args.dataset):
        print(f"Error: {args.dataset} holds no sweep rows", file=sys.stderr)
        return 1
    out = args.out or args.dataset / "summary"
    written = write(args.dataset, out, plots=not args.no_plots)
    if not args.quiet:
        print(written[0].read_text())
    print("wrote " + ", ".join(str(p) for p in written), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
