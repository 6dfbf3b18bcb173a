"""One run of the command: read the input, triangulate, write Triangle's files, report.

The order of everything printed and written is Triangle's (the file-name
rules of reference section 1.1, the phase lines, the files of section 2.10,
the statistics); engine failures become ``CliError``s.
"""

from __future__ import annotations

import argparse
import re
import sys
import time
from pathlib import Path
from typing import Any, TextIO

import numpy as np

from instrument import limits

from .. import naming, stats
from ..api import read_set, write
from ..errors import FormatError
from ..info import Info
from . import meshio_input
from .arguments import split_argv
from .errors import CliError
from .extras import meshio_formats, write_extras
from .outputs import choose_outputs, output_mesh, voronoi, with_empty_arrays
from .progress import Progress, is_terminal
from .texts import LONG_HELP, SHORT_HELP, version
from .verdict import print_verdict


def run(argv: list[str], out: TextIO, *, progress_after: float) -> int:
    """Run the command with ``argv``, printing to ``out``; return the exit
    status (failures raise ``CliError``).  On a terminal the progress display
    appears once the run has taken ``progress_after`` seconds."""
    from instrument.switches import SwitchError, parse

    cmd = split_argv(argv)
    if cmd.long.version:
        out.write(f"ruppert {version()}\n")
        return 0
    help_at = re.search(r"[hH?]", cmd.switches)
    if help_at or cmd.long.help:
        if help_at:  # Triangle stops parsing at h: earlier switches may still fail
            try:
                parse(cmd.switches[: help_at.start()], library=True)
            except SwitchError as exc:
                raise CliError(str(exc)) from None
        out.write(LONG_HELP)
        return 0
    if cmd.file is None:
        out.write(SHORT_HELP)
        return 0

    # File-name rules (reference §1.1), applied in this order; a meshio file
    # (mesh.vtu, outline.msh, ...) is read as it is, its base name named as Triangle's.
    base, implied = cmd.file, ""
    source = meshio_input.find(cmd.file)
    if source is not None:
        base = source.base
    for suffix, letters in ((".node", ""), (".poly", "p"), (".ele", "r"), (".area", "ra ")):
        if source is None and base.endswith(suffix):
            base = base[: -len(suffix)]
            implied += letters
    try:
        o = parse(f"{implied} {cmd.switches}", library=True)
    except SwitchError as exc:
        raise CliError(str(exc)) from None
    if o.r and o.I:
        raise CliError("You cannot use the -I switch when refining a triangulation.")
    formats = meshio_formats(cmd.long.formats, o.order)
    engine_kwargs = _engine_kwargs(cmd.long)
    quiet = o.Q
    say = (lambda line="": None) if quiet else (lambda line="": print(line, file=out))
    warn = (lambda line: None) if quiet else (lambda line: print(line, file=sys.stderr))

    start = time.perf_counter()
    data, info = _read_input(o, base) if source is None else meshio_input.read(source, o)
    for path in info.files:
        say(f"Opening {path}.")
    if o.r:  # reconstruction: an invalid segment is an error, not a warning
        for line in info.warnings:
            hit = re.search(r"Invalid (?:first|second) endpoint of segment (\d+)", line)
            if hit:
                raise CliError(f"Segment {hit.group(1)} has an invalid vertex index.")
    for line in info.warnings:
        warn(line)
    nvertices = len(np.asarray(data.get("vertices", np.zeros((0, 2)))).reshape(-1, 2))
    if nvertices < 3:
        raise CliError("Input must have at least three input vertices.")
    if o.j and o.N:
        warn("Warning:  -j and -N switches are somewhat incompatible.")
        warn("  If any vertices are jettisoned, the mesh needs the output .node file.")

    angle_warning = limits.angle_warning(o.min_angle) if o.q else None
    if angle_warning:  # before the run: it may be long
        warn(angle_warning)
    result, engine_ms = _triangulate(data, o, cmd.long, engine_kwargs, quiet, progress_after)
    ntriangles = len(stats.triangle_rows(result))
    for line in stats.phase_lines(o, ntriangles):
        say(line)
    if not o.r:
        for line in _duplicate_warnings(data["vertices"]):
            warn(line)
    else:  # segments that are not edges of the mesh, or end off it
        for line in getattr(result, "warnings", None) or []:
            if line != angle_warning:
                warn(line)
    say()

    # Output files (reference §2.10), in Triangle's order.
    t_out = time.perf_counter()
    outbase = naming.output_base(base, no_iteration=o.I)
    mesh = output_mesh(result, data, o)
    node_read = info.vertices_from is not None and Path(info.vertices_from).suffix == ".node"
    kinds, lines = choose_outputs(o, outbase, node_read)
    diagram = voronoi(mesh) if o.v else None
    generated_by = " ".join(["ruppert", *argv])
    try:
        write(
            outbase,
            with_empty_arrays(mesh, kinds, o.order, markers=not o.B),
            first_index=info.first_index,
            markers=not o.B,
            kinds=kinds,
            generated_by=generated_by,
            voronoi=diagram,
        )
    except OSError as exc:
        raise CliError(f"Cannot create file {exc.filename}.") from None
    for line in lines:
        say(line)
    write_extras(cmd.long, formats, outbase, mesh, result, o, say, warn)
    if o.V:
        now = time.perf_counter()
        say()
        say(f"Engine milliseconds:  {round(engine_ms)}")
        say(f"Output milliseconds:  {round(1000 * (now - t_out))}")
        say(f"Total running milliseconds:  {round(1000 * (now - start))}")

    if not quiet:
        out.write(_statistics(o, data, info, mesh, result))
    if o.C:
        print_verdict(mesh, out, quiet)
    return 0


def _engine_kwargs(long: argparse.Namespace) -> dict[str, Any]:
    import instrument

    kwargs: dict[str, Any] = {"strategy": long.strategy, "seed": long.seed, "steiner": long.steiner}
    names = list(instrument.strategies())
    if long.strategy not in names:
        raise CliError(f"Unknown strategy {long.strategy!r}; choose from {', '.join(names)}.")
    if long.trace:
        kwargs["trace"] = True
    if long.max_vertices is not None:
        kwargs["max_vertices"] = long.max_vertices
    if long.threads is not None:
        kwargs["threads"] = long.threads
    return kwargs


def _read_input(o, base: str) -> tuple[dict[str, np.ndarray], Info]:
    """Read the files Triangle reads for these switches (reference §1.3, §2)."""
    files = {"poly": Path(f"{base}.poly")} if o.p else {"node": Path(f"{base}.node")}
    if o.r:
        files["ele"] = Path(f"{base}.ele")
        if o.var_area:
            files["area"] = Path(f"{base}.area")
    first = 0 if o.z else 1
    info = Info(first_index=first)
    try:
        data = read_set(files, default_first_index=first, info=info)
    except FormatError as exc:
        cause = exc.__cause__
        if isinstance(cause, OSError) and cause.filename:  # a .poly's missing .node
            raise CliError(f"Cannot access file {cause.filename}.") from None
        raise CliError(str(exc)) from None
    except OSError as exc:
        raise CliError(f"Cannot access file {exc.filename or base}.") from None
    return data, info


def engine_switches(o) -> str:
    """The library-mode switch string for ``instrument.triangulate``.

    Output-only and console switches (B, P, N, E, I, g, z, V, C) are left out: the
    command line decides what to write and prints the statistics itself, which
    needs the whole mesh.  Numbers come last, after all letters, so that no letter
    can be read as part of a number.
    """
    letters = "Q" + "".join(ch for ch in "pruAcDjevnXOiFlswW" if getattr(o, ch))
    letters += "Y" * o.Y
    if o.order == 2:
        letters += "o2"
    if o.q:
        letters += f"q{o.min_angle!r}"
    if o.max_area > 0:
        letters += f"a{o.max_area!r}"
    if o.var_area:
        letters += "a"
    if o.S >= 0:
        letters += f"S{o.S}"
    return letters


def _triangulate(data, o, long, kwargs, quiet, progress_after):
    import instrument
    from instrument.pipeline import INPUT_KEYS

    tri = {}
    for key in sorted(INPUT_KEYS):
        value = data.get(key)
        if value is not None and np.size(value):
            tri[key] = value
    opts = engine_switches(o)
    t0 = time.perf_counter()
    progress = Progress(enabled=not quiet and is_terminal(sys.stderr), eager=long.progress, after=progress_after)
    try:
        with progress:
            result = instrument.triangulate(tri, opts, progress=progress, **kwargs)
    except NotImplementedError as exc:
        raise CliError(str(exc) or "not implemented yet") from None
    except (ValueError, RuntimeError, KeyError) as exc:
        raise CliError(str(exc).strip("'\"")) from None
    return result, 1000 * (time.perf_counter() - t0)


def _duplicate_warnings(vertices) -> list[str]:
    xy = np.asarray(vertices, dtype=np.float64).reshape(-1, 2)
    if len(xy) < 2:
        return []
    order = np.lexsort((xy[:, 1], xy[:, 0]))
    s = xy[order]
    dup = np.flatnonzero(np.all(s[1:] == s[:-1], axis=1)) + 1
    return [
        "Warning:  A duplicate vertex at (%.12g, %.12g) appeared and was ignored." % tuple(s[i])
        for i in dup
    ]


def _statistics(o, data, info: Info, mesh, result) -> str:
    counts = stats.mesh_counts(mesh, refine=o.r)
    skipped = sum(1 for w in info.warnings if re.search(r"\bsegment \d+\b", w))
    text = stats.statistics_block(
        counts,
        input_vertices=len(np.asarray(data["vertices"]).reshape(-1, 2)),
        input_triangles=len(stats.triangle_rows(data)),
        input_segments=len(np.asarray(data.get("segments", np.zeros((0, 2)))).reshape(-1, 2))
        + skipped,
        input_holes=len(np.asarray(data.get("holes", np.zeros((0, 2)))).reshape(-1, 2)),
        poly=o.p,
        refine=o.r,
    )
    if o.V:
        work = dict(getattr(result, "work", {}) or {})
        text += stats.format_quality(stats.quality_statistics(mesh))
        text += stats.format_algorithmic(work, counts.triangles, voronoi=o.v)
        text += stats.format_work(work)
    return text
