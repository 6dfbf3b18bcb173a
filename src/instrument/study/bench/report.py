"""The benchmark's report: the table (terminal and Markdown), the detail sections, JSON, and what was measured.

Every report says which code it measured (the commit, and whether the
engine's files differed from it) and how busy the machine was (the load
average when the run began and ended, and per workload when it began):
timings on a shared machine mean little without it.
"""

from __future__ import annotations

import hashlib
import json
import os
import platform
import subprocess
from pathlib import Path

from .cold import checkout_root

COLS = ["workload", "switches", "strategy", "triangles ours / Tri / CGAL", "ours s", "Triangle s", "CGAL s",
        "ours/Tri", "ours/CGAL", "ours MB", "Tri MB", "CGAL MB", "created (ours)", "incircle ours / Tri", "load",
        "goal"]
TEXT_COLS = ("workload", "switches", "strategy", "goal")

LEGEND = (
    "Times are the best of the interleaved rounds, in seconds; ours/Tri and ours/CGAL are ratios of wall times "
    "(below 1: ours is faster). MB: growth of resident memory during one run, each engine in a fresh process "
    "(cli-A and cold: peak resident memory of the whole command, as /usr/bin/time -v reports it). created: "
    "triangles our engine created (the paper's work measure); incircle: our count / Triangle's statistic (one "
    "extra untimed run with V). CGAL: Delaunay_triangulation_2 bulk insert for point sets, Mesh_2 otherwise "
    "(q -> b = sin^2(angle), a -> S = sqrt(4a/sqrt 3)); its time includes making the Point_2 objects in Python, "
    "and it makes a different mesh. cli-A: subprocess wall time of the installed ruppert script; Triangle's side "
    "is a Python script running the triangle package on the same file and writing the same three files (no "
    "Triangle program is installed). cold: the first run after pip install in a fresh venv. load: the 1-minute "
    "load average when the workload began."
)


def fmt_s(v) -> str:
    return "—" if v is None else (f"{v:.4f}" if v < 0.1 else f"{v:.3f}")


def fmt_x(v) -> str:
    return "—" if v is None else f"{v:.2f}"


def fmt_n(v) -> str:
    return "—" if v is None else f"{v:,}"


def fmt_mb(v) -> str:
    return "—" if v is None else f"{v:.1f}"


def goal_text(row) -> str:
    g = row["goal"]
    if g is None:
        return "—"
    if "startup" in row or "cold" in row:
        target = f"< {g:g} s"
    elif row.get("sweep"):
        target = f"≤ {g:g}x ({1 / g:g}x faster), least work"
    else:
        target = f"≤ {g:g}x"
    if row["goal_met"] is None:
        return "—" if row.get("sweep") else f"({target})"  # strategy rows: the goal is the least-work row's
    return f"{'met' if row['goal_met'] else 'MISSED'}: {target}"


def cells(row) -> list[str]:
    t = row["triangles"]
    tri = " / ".join(fmt_n(t.get(k)) for k in ("ours", "triangle", "cgal") if k in t)
    wo = row["work"].get("ours", {})
    wt = row["work"].get("triangle", {})
    inc = f"{fmt_n(wo.get('incircle_tests'))} / {fmt_n(wt.get('incircle_tests'))}" if wo else "—"
    strategy = row["strategy"] + (" (least work)" if row.get("least_work") else "")
    if row.get("threads") is not None:
        strategy += f", {row['threads']} threads"
    ours_s = fmt_s(row["ours_s"]) if row["ours_s"] is not None or not row["note"] else row["note"].split(":")[0]
    return [row["workload"], f"`{row['switches']}`" if row["switches"] else "(none)", strategy, tri, ours_s,
            fmt_s(row["triangle_s"]), fmt_s(row["cgal_s"]), fmt_x(row["ratio"]), fmt_x(row["cgal_ratio"]),
            fmt_mb(row.get("ours_mb")), fmt_mb(row.get("triangle_mb")), fmt_mb(row.get("cgal_mb")),
            fmt_n(wo.get("triangles_created")), inc, f"{row['load_avg'][0]:.1f}", goal_text(row)]


def notes(rows) -> list[str]:
    return [f"{r['workload']} [{r['strategy']}]: {r['note']}" for r in rows if r.get("note")]


# ---------------------------------------------------------------------------------------------
# detail sections, as (title, header, rows of cells)


def startup_section(row) -> tuple[str, list[str], list[list[str]]]:
    """The command's start-up: the whole command and the floors, then the big
    items of importtime (with their parents, indented)."""
    def ms(v) -> str:
        return f"{1000 * v:.1f}"

    which = "first run after the install" if "cold" in row else "best of the rounds"
    body = [[f"`ruppert {row['switches']} A.poly` ({which})", ms(row["ours_s"]), "", fmt_mb(row["ours_mb"])]]
    body += [[f"`{what}`", ms(v["s"]), "", fmt_mb(v["mb"])] for what, v in row["startup"].items()]
    for item in row.get("importtime", []):
        depth = len(item["path"]) - 1
        body.append([f"{'. ' * depth}import `{item['path'][-1]}`", f"{item['cumulative_ms']:.1f}",
                     f"{item['self_ms']:.1f}", ""])
    where = " (in the fresh venv)" if "cold" in row else ""
    title = (f"Start-up of {row['workload']}{where}: the command, what it pays before meshing (best of the "
             "rounds), then `python -X importtime -c \"import ruppert_io.cli\"` (least of 3 runs; imports of 5 ms "
             "or more, four levels deep)")
    return title, ["what", "ms", "self ms", "peak MB"], body


def cold_section(row) -> tuple[str, list[str], list[list[str]]]:
    c = row["cold"]
    body = [
        ["`python -m venv` (no system site packages)", fmt_s(c["venv_s"]), "", "", ""],
        ["`pip install` ruppert (compiles the engine) / `pip install triangle==20250106`", fmt_s(c["install_s"]), "",
         fmt_s(c["triangle_install_s"]), ""],
        ["first run", fmt_s(c["first"]["s"]), fmt_mb(c["first"]["mb"]), fmt_s(c["triangle_first"]["s"]),
         fmt_mb(c["triangle_first"]["mb"])],
        ["second run", fmt_s(c["second"]["s"]), fmt_mb(c["second"]["mb"]), fmt_s(c["triangle_second"]["s"]),
         fmt_mb(c["triangle_second"]["mb"])],
    ]
    title = f"Cold start ({row['workload']}): `ruppert {row['switches']} A.poly` in a fresh venv"
    return title, ["step", "ruppert s", "ruppert peak MB", "Triangle's script s", "Triangle's script peak MB"], body


def profile_section(name: str, opts: str, strategy: str, prof) -> tuple[str, list[str], list[list[str]]]:
    total = prof[0][1]
    scale, unit = (1e3, "ms") if total < 0.1 else (1.0, "s")
    body = [[p, f"{s * scale:.3f}", f"{100 * s / total:.1f} %", str(n) if n > 1 else ""] for p, s, n in prof]
    switches = f"`{opts}`" if opts else "no switches"
    return f"Where our time goes, {name} ({switches}, strategy {strategy}), best of the runs", \
        ["stage", unit, "share", "calls"], body


def sections(rows, profiles) -> list[tuple[str, list[str], list[list[str]]]]:
    out = []
    for row in rows:
        if "cold" in row:
            out.append(cold_section(row))
        if "startup" in row:
            out.append(startup_section(row))
    out += [profile_section(*p) for p in profiles]
    return out


# ---------------------------------------------------------------------------------------------
# output


def print_report(rows, title: str, profiles=()) -> None:
    """The table and the sections on the terminal (rich when it is installed)."""
    try:
        from rich.console import Console
        from rich.table import Table
    except ImportError:
        print(title)
        print(" | ".join(COLS))
        for row in rows:
            print(" | ".join(c.strip("`") for c in cells(row)))
        print("\n".join(notes(rows)))
        for stitle, header, body in sections(rows, profiles):
            print(f"\n{stitle}\n" + " | ".join(header))
            print("\n".join(" | ".join(c.replace("`", "") for c in line) for line in body))
        print(LEGEND)
        return
    console = Console()
    if not console.is_terminal:
        console = Console(width=max(console.width, 280))
    table = Table(title=title)
    for c in COLS:
        table.add_column(c, justify="left" if c in TEXT_COLS else "right", overflow="fold")
    last = None
    for row in rows:
        if last is not None and row["workload"] != last:
            table.add_section()
        last = row["workload"]
        style = "bold red" if row["goal_met"] is False else ("green" if row["goal_met"] else None)
        table.add_row(*(c.strip("`") for c in cells(row)), style=style)
    console.print(table)
    for line in notes(rows):
        console.print(line, markup=False, highlight=False)
    for stitle, header, body in sections(rows, profiles):
        t = Table(title=stitle)
        for i, h in enumerate(header):
            t.add_column(h, justify="left" if i == 0 else "right")
        for line in body:
            t.add_row(*(c.replace("`", "") for c in line))
        console.print(t)
    console.print(LEGEND, markup=False, highlight=False)


def markdown_table(header: list[str], body: list[list[str]], text_cols=None) -> list[str]:
    text_cols = text_cols if text_cols is not None else {header[0]}
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" if h in text_cols else "---:" for h in header) + "|"]
    lines += ["| " + " | ".join(c.replace("|", "\\|") for c in line) + " |" for line in body]
    return lines


def write_markdown(path: Path, rows, meta: dict, profiles=()) -> None:
    lines = [f"<!-- generated by `{meta['command']}` -->", "",
             f"Measured: {meta['provenance']}; {meta['machine']}; load average (1, 5, 15 min) "
             f"{fmt_load(meta['load_start'])} at the start, {fmt_load(meta['load_end'])} at the end.", ""]
    lines += markdown_table(COLS, [cells(r) for r in rows], set(TEXT_COLS))
    lines.append("")
    lines += [f"- {n}" for n in notes(rows)]
    lines += ["", LEGEND, ""]
    for title, header, body in sections(rows, profiles):
        lines += [f"{title}:", ""] + markdown_table(header, body) + [""]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines))


def write_json(path: Path, rows, meta: dict, profiles=()) -> None:
    doc = {**meta, "rows": rows,
           "profiles": [{"workload": n, "switches": o, "strategy": s,
                         "stages": [{"stage": p, "s": t, "calls": c} for p, t, c in prof]}
                        for n, o, s, prof in profiles]}
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(doc, indent=1, default=float))


def fmt_load(load) -> str:
    return " / ".join(f"{x:.2f}" for x in load)


# ---------------------------------------------------------------------------------------------
# what was measured


def machine() -> str:
    """CPU model and count, memory, Python: the facts a reader needs to weigh the figures."""
    model = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            model = next((ln.split(":", 1)[1].strip() for ln in f if ln.startswith("model name")), model)
    except OSError:
        pass
    mem = ""
    try:
        with open("/proc/meminfo") as f:
            kb = int(next(ln.split()[1] for ln in f if ln.startswith("MemTotal:")))
        mem = f", {kb / 2**20:.0f} GiB"
    except (OSError, StopIteration, ValueError):
        pass
    return f"{os.cpu_count()} CPUs ({model}){mem}, Python {platform.python_version()}"


def provenance() -> tuple[str, str]:
    """(the code measured: the commit, noting uncommitted changes to the engine
    and file packages, or the installed version; a fingerprint of their
    source files as they are now, to notice a change during the run)."""
    import instrument

    src = Path(instrument.__file__).resolve().parents[1]
    h = hashlib.sha1()
    for pkg in ("instrument", "ruppert_io"):
        for path in sorted((src / pkg).rglob("*.p[yx]*")):
            if path.suffix in (".py", ".pxd", ".pyx"):
                h.update(str(path.relative_to(src)).encode() + b"\0" + path.read_bytes())
    code = h.hexdigest()[:8]
    root = checkout_root()
    if root is None:
        return f"ruppert {instrument.__version__} (installed), source {code}", code
    try:
        def git(*args: str) -> str:
            return subprocess.run(["git", *args], cwd=root, capture_output=True, text=True, check=True,
                                  timeout=60).stdout

        head = git("rev-parse", "--short", "HEAD").strip()
        dirty = git("status", "--porcelain", "--", "src/instrument", "src/ruppert_io", "setup.py",
                    "pyproject.toml").strip()
    except (OSError, subprocess.SubprocessError):
        return f"a checkout of unknown commit, source {code}", code
    return f"commit {head}" + (f" with uncommitted engine changes (source {code})" if dirty else ""), code
