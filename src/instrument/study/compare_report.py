"""How ``compare`` shows its rows: a terminal table, Markdown, CSV, JSON, and plots.

Kept apart from the comparison itself (``instrument.study.compare``) so that
what is measured and how it is written change separately.
"""

from __future__ import annotations

import csv
import json
import math
import re
from pathlib import Path

LEGEND = (
    "Flags (our rows): size = vertex or triangle count more than 2 % off Triangle's; "
    "area = meshed area differs from Triangle's; angle = the q bound is missed where Triangle meets it; "
    "error / timeout / crash / memory = the engine failed / was killed after --timeout seconds / killed its process / outgrew --memory-limit. Triangle's orientation count is its printed statistic minus the one "
    "test per output triangle its statistics make. CGAL Mesh_2: q<angle> -> shape bound b = sin^2(angle), "
    "a<area> -> size bound S = sqrt(4*area/sqrt(3)) (CGAL guarantees termination only up to b = 0.125, "
    "20.7 degrees); CGAL counts no work. "
    "Times: best of the repeated runs; ratio = time / Triangle's time."
)


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


def write_csv(path: Path, rows, columns) -> None:
    with path.open("w", newline="") as f:
        w = csv.writer(f)
        w.writerow(columns)
        for row in rows:
            d = row.as_dict(work=False)
            w.writerow(["" if d[k] is None else (";".join(d[k]) if k == "flags" else d[k]) for k in columns])


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
        for ax, row in zip(axes[0], panels, strict=False):
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


