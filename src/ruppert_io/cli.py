"""The ``ruppert`` command line: Triangle 1.6's interface, plus a few long options.

    ruppert [-switches] input_file[.node|.poly|.ele|.area] [--long-options]

Triangle-style switch groups (``-pq30a0.1``, ``-p -q30``, before or after the file
name) are parsed with ``instrument.switches.parse``; the long options with argparse.
This module is the only place that turns exceptions into exit statuses: every
failure is one ``Error:`` line on stderr and exit status 1 (130 when interrupted).
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import dataclasses
import io
import json
import os
import re
import sys
import time
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any, TextIO

import numpy as np

from instrument import limits

from . import naming, stats
from .api import read_set, write
from .errors import FormatError
from .info import Info

# --------------------------------------------------------------------------
# Texts
# --------------------------------------------------------------------------

USAGE = "ruppert [-prq__a__uAcDjevngBPNEIOXzo_YS__iFlsCQVh] input_file"

SHORT_HELP = f"""{USAGE}
    -p  Triangulates a Planar Straight Line Graph (.poly file).
    -r  Refines a previously generated mesh.
    -q  Quality mesh generation.  A minimum angle may be specified.
    -a  Applies a maximum triangle area constraint.
    -u  Applies a user-defined triangle constraint.
    -A  Applies attributes to identify triangles in certain regions.
    -c  Encloses the convex hull with segments.
    -D  Conforming Delaunay:  all triangles are truly Delaunay.
    -j  Jettison unused vertices from output .node file.
    -e  Generates an edge list.
    -v  Generates a Voronoi diagram.
    -n  Generates a list of triangle neighbors.
    -g  Generates an .off file for Geomview.
    -B  Suppresses output of boundary information.
    -P  Suppresses output of .poly file.
    -N  Suppresses output of .node file.
    -E  Suppresses output of .ele file.
    -I  Suppresses mesh iteration numbers.
    -O  Ignores holes in .poly file.
    -X  Suppresses use of exact arithmetic.
    -z  Numbers all items starting from zero (rather than one).
    -o2 Generates second-order subparametric elements.
    -Y  Suppresses boundary segment splitting.
    -S  Specifies maximum number of added Steiner points.
    -i  Uses incremental method, rather than divide-and-conquer.
    -F  Uses Fortune's sweepline algorithm, rather than d-and-c.
    -l  Uses vertical cuts only, rather than alternating cuts.
    -s  Force segments into mesh by splitting (instead of using CDT).
    -C  Check consistency of final mesh.
    -Q  Quiet:  No terminal output except errors.
    -V  Verbose:  Detailed information on what I'm doing.
    -h  Help:  Detailed instructions for ruppert.
Long options: --strategy NAME  --steiner offcenter|circumcenter  --seed N
    --work-json PATH  --trace PATH  --format FMT[,FMT...]  --progress
    --max-vertices N  --threads N  --version
"""

LONG_HELP = f"""ruppert: a two-dimensional quality mesh generator and Delaunay triangulator
that behaves like J. R. Shewchuk's Triangle 1.6 and counts its own work.

Usage:
    {USAGE} [long options]

The input is a set of points (file.node), a planar straight line graph
(file.poly), or an earlier mesh to refine (file.node + file.ele, with -r).
Naming file.poly turns on -p, file.ele turns on -r, and file.area turns on -r
with per-triangle area bounds read from file.area.  Output goes to the input's
name with the next iteration number: A.poly gives A.1.node, A.1.ele, A.1.poly;
refining A.1 gives A.2.*.  Files are numbered from 0 or 1, as the input is.

Switches are single letters; they may be grouped (-pq30a0.1) or separate
(-p -q30 -a0.1), and may come before or after the file name.  Numbers follow
q, a, S and o directly.  Unlike Triangle, the numbers after q and a may carry an
exponent: -a1e-4 is a maximum area of 0.0001.

  What to triangulate
    -p      Read a planar straight line graph (.poly): vertices, segments,
            holes and regional attributes/area bounds; build a constrained
            Delaunay triangulation (conforming with -q, -a, -u, -D or -s).
    -r      Refine the mesh in file.node and file.ele (and file.poly with -p,
            file.area with a bare -a).  Cannot be combined with -I.
    -c      Also enclose the convex hull with segments.
    -O      Ignore the holes listed in the .poly file.

  Quality
    -q[deg] Add Steiner points until no angle is below deg (default 20).
            Termination is guaranteed up to about 28.6 degrees.
    -a[A]   Bound triangle areas by A; a bare -a uses the area bounds of the
            .poly regions (or of the .area file with -r).  Both may be given.
    -u      Refine triangles that fail the user test (Triangle's stock test).
    -D      Conforming Delaunay: every triangle is truly Delaunay.
    -Y      Do not split boundary segments; -YY: do not split any segment.
    -S[n]   Add at most n Steiner points (no number: none).
    -s      Recover segments by splitting them rather than by flipping.
    -X      Do not use exact arithmetic (for comparison only).
    -i -l   Incremental Delaunay; vertical cuts only (-F: divide and conquer).

  Output
    -A      Give each triangle the attribute of the region it lies in.
    -j      Leave unused vertices (duplicates, eaten vertices) out of .node.
    -e      Write the edges (.edge).
    -v      Write the Voronoi diagram (.v.node, .v.edge).
    -n      Write the triangles' neighbours (.neigh).
    -g      Write a Geomview file (.off).
    -o2     Write six-node (second-order) triangles.
    -B      Write no boundary markers.
    -P -N -E  Do not write the .poly / .node / .ele file.
    -I      Write to the input's name without iteration number (the .node and
            .poly files that were read are not overwritten).
    -z      Number items from 0 when the input does not say.

  Console
    -Q      Quiet: print only warnings' absence and errors.
    -V      Verbose: also print the quality statistics (areas, edges, aspect
            ratios, angle histograms), Triangle's algorithmic statistics, and
            every work counter of the engine ("Work statistics").
    -C      Check the final mesh: consistency and the Delaunay property.
    -h      Print this text.

Long options (ruppert's own):
    --strategy NAME     Order in which bad triangles are split (default
                        "triangle", Triangle 1.6's order).
    --steiner offcenter|circumcenter
                        Where a bad triangle is split (default offcenter).
    --seed N            Seed of randomised strategies (default 0).
    --work-json PATH    Write the work counters as JSON.
    --trace PATH        Write one CSV row per vertex insertion.
    --format FMT        Also write the mesh with meshio, e.g. vtu, gmsh22,
                        xdmf, vtk (comma-separated for several).  "msh" means
                        Gmsh 2.2 here (meshio would take it as ANSYS).
    --progress          Show the progress display from the start (on a
                        terminal it appears anyway once a run has taken
                        about a second; never with -Q or when stderr is not
                        a terminal).
    --max-vertices N    Stop refinement with an error once the mesh has more
                        than N vertices.  The default is derived from the
                        input: max(1,000,000, 1,000 per input vertex and
                        segment), plus 4 per maximum area of domain with -a,
                        raised to the input plus -S's budget, and at most
                        what half of this machine's memory holds.  An area
                        bound whose mesh needs more fails at once.
    --threads N         Threads for the Delaunay triangulation of a large
                        input (default: every core this process may use).
                        The mesh and the work counts are the same on any
                        number.
    --version           Print ruppert's version.

A minimum angle above 34 degrees prints a warning: Triangle's documentation
says refinement is guaranteed to terminate up to 28.6 degrees and usually
does up to 34; above that it may refine until the vertex limit.

Exit status: 0 on success, 1 on an error (one line starting with "Error:"),
130 when interrupted.
"""

#: What -C prints (Triangle's sentences; its exact -C output is not in our reference).
CHECK_TEXT = {
    "consistency": "Checking consistency of mesh...",
    "consistent": "  In my considered opinion, the mesh is fine.",
    "delaunay": "Checking Delaunay property of mesh...",
    "is_delaunay": "  By virtue of my perceptive intelligence, I declare the mesh Delaunay.",
    "problem": "  !! !! {}",
    "count": "  !! !! !! !! Precisely {} problem{} found.",
}

#: Header of a --trace file when the engine returned no trace (no refinement ran).
TRACE_HEADER = ("kind", "created", "deleted", "walk_steps", "queue_length")


#: meshio formats whose extension meshio's table does not give.
FORMAT_EXTENSIONS = {"gmsh22": ".msh", "gmsh": ".msh", "vtk42": ".vtk", "vtk51": ".vtk"}

_LONG_WITH_VALUE = ("--strategy", "--steiner", "--seed", "--work-json", "--trace", "--format", "--max-vertices", "--threads")
_LONG_FLAGS = ("--progress", "--help", "--version")

#: A run shows its progress on a terminal once it has taken this long (seconds).
PROGRESS_AFTER = 1.0


class CliError(Exception):
    """A failure reported as one ``Error:`` line and exit status 1."""


class _ArgumentParser(argparse.ArgumentParser):
    def error(self, message: str):  # argparse would print usage and exit 2
        raise CliError(message)


def _long_parser() -> argparse.ArgumentParser:
    p = _ArgumentParser(prog="ruppert", add_help=False, allow_abbrev=False)
    p.add_argument("--strategy", default="triangle")
    p.add_argument("--steiner", default="offcenter", choices=("offcenter", "circumcenter"))
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--work-json", dest="work_json", default=None)
    p.add_argument("--trace", default=None)
    p.add_argument("--format", dest="formats", action="append", default=[])
    p.add_argument("--progress", action="store_true")
    p.add_argument("--max-vertices", dest="max_vertices", type=_positive_int, default=None)
    p.add_argument("--threads", type=_positive_int, default=None)
    p.add_argument("--help", action="store_true")
    p.add_argument("--version", action="store_true")
    return p


def _positive_int(text: str) -> int:
    try:
        value = int(text.replace("_", "").replace(",", ""))
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
    if value <= 0:
        raise argparse.ArgumentTypeError(f"must be positive, not {value}")
    return value


def version() -> str:
    """The installed distribution's version (the engine's ``__version__``),
    read without importing the engine."""
    from importlib.metadata import PackageNotFoundError
    from importlib.metadata import version as dist_version

    try:
        return dist_version("ruppert")
    except PackageNotFoundError:
        return "0+unknown"


# --------------------------------------------------------------------------
# Entry point
# --------------------------------------------------------------------------


def console() -> int:
    """The ``ruppert`` command: ``main`` in a process of its own."""
    return main()


def main(argv: Sequence[str] | None = None) -> int:
    """Run ruppert with ``argv`` (default: ``sys.argv[1:]``); return the exit status."""
    argv = list(sys.argv[1:] if argv is None else argv)
    try:
        return _run(argv, sys.stdout)
    except CliError as exc:
        _error(str(exc))
        return 1
    except KeyboardInterrupt:
        print("Error: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # e.g. `ruppert -V x | head`: stop quietly
        try:
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        except (OSError, ValueError, AttributeError):
            pass
        return 1
    except MemoryError:
        _error("Out of memory.")
        return 1
    except Exception as exc:  # a bug: still one line, never a traceback
        if os.environ.get("RUPPERT_DEBUG"):
            raise
        _error(f"internal error ({type(exc).__name__}): {exc}")
        return 1


def _error(message: str) -> None:
    message = " ".join(str(message).split()) or "unknown error"
    print(f"Error:  {message}", file=sys.stderr)


@dataclasses.dataclass
class _Command:
    switches: str  # the switch text, one leading dash removed per group
    file: str | None
    long: argparse.Namespace
    argv: list[str]


def _split(argv: list[str]) -> _Command:
    groups, files, long_tokens = [], [], []
    it = iter(argv)
    only_files = False
    for arg in it:
        if only_files:
            files.append(arg)
        elif arg == "--":
            only_files = True
        elif arg.startswith("--"):
            name = arg.split("=", 1)[0]
            if name in _LONG_WITH_VALUE and "=" not in arg:
                value = next(it, None)
                if value is None:
                    raise CliError(f"argument {name}: expected one argument")
                arg = f"{name}={value}"
            long_tokens.append(arg)
        elif arg.startswith("-"):
            groups.append(arg[1:])
        else:
            files.append(arg)
    long = _long_parser().parse_args(long_tokens)
    # A space between groups keeps "-q -30" from reading as "-q30", as in Triangle.
    return _Command(" ".join(groups), files[-1] if files else None, long, argv)


# --------------------------------------------------------------------------
# The run
# --------------------------------------------------------------------------


def _run(argv: list[str], out: TextIO) -> int:
    from instrument.switches import SwitchError, parse

    cmd = _split(argv)
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

    # File-name rules (reference §1.1), applied in this order.
    base, implied = cmd.file, ""
    for suffix, letters in ((".node", ""), (".poly", "p"), (".ele", "r"), (".area", "ra ")):
        if base.endswith(suffix):
            base = base[: -len(suffix)]
            implied += letters
    try:
        o = parse(f"{implied} {cmd.switches}", library=True)
    except SwitchError as exc:
        raise CliError(str(exc)) from None
    if o.r and o.I:
        raise CliError("You cannot use the -I switch when refining a triangulation.")
    formats = _meshio_formats(cmd.long.formats)
    engine_kwargs = _engine_kwargs(cmd.long)
    quiet = o.Q
    say = (lambda line="": None) if quiet else (lambda line="": print(line, file=out))
    warn = (lambda line: None) if quiet else (lambda line: print(line, file=sys.stderr))

    start = time.perf_counter()
    data, info = _read_input(o, base)
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
    result, engine_ms = _triangulate(data, o, cmd.long, engine_kwargs, quiet)
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
    mesh = _output_mesh(result, data, o)
    node_read = info.vertices_from is not None and Path(info.vertices_from).suffix == ".node"
    kinds, lines = _choose_outputs(o, outbase, node_read)
    voronoi = _voronoi(mesh) if o.v else None
    generated_by = " ".join(["ruppert", *argv])
    try:
        write(
            outbase,
            _with_empty_arrays(mesh, kinds, o.order, markers=not o.B),
            first_index=info.first_index,
            markers=not o.B,
            kinds=kinds,
            generated_by=generated_by,
            voronoi=voronoi,
        )
    except OSError as exc:
        raise CliError(f"Cannot create file {exc.filename}.") from None
    for line in lines:
        say(line)
    _write_extras(cmd.long, formats, outbase, mesh, result, o, say, warn)
    if o.V:
        now = time.perf_counter()
        say()
        say(f"Engine milliseconds:  {round(engine_ms)}")
        say(f"Output milliseconds:  {round(1000 * (now - t_out))}")
        say(f"Total running milliseconds:  {round(1000 * (now - start))}")

    if not quiet:
        out.write(_statistics(o, data, info, mesh, result))
    if o.C:
        _check(mesh, out, quiet)
    return 0


def _write_extras(long, formats, outbase: str, mesh, result, o, say, warn) -> None:
    """The long options' files: meshio formats, --work-json, --trace."""
    for fmt, ext, note in formats:
        if note:
            warn(note)
        path = f"{outbase}{ext}"
        _write_meshio(path, mesh, fmt, o)
        say(f"Writing {path}.")
    if long.work_json:
        work = dict(getattr(result, "work", {}) or {})
        _write_file(long.work_json, json.dumps(work, indent=2) + "\n")
        say(f"Writing {long.work_json}.")
    if long.trace:
        _write_trace(long.trace, getattr(result, "trace", None))
        say(f"Writing {long.trace}.")


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


def _triangulate(data, o, long, kwargs, quiet):
    import instrument
    from instrument.pipeline import INPUT_KEYS

    tri = {}
    for key in sorted(INPUT_KEYS):
        value = data.get(key)
        if value is not None and np.size(value):
            tri[key] = value
    opts = engine_switches(o)
    t0 = time.perf_counter()
    progress = _Progress(enabled=not quiet and _is_terminal(sys.stderr), eager=long.progress)
    try:
        with progress:
            result = instrument.triangulate(tri, opts, progress=progress, **kwargs)
    except NotImplementedError as exc:
        raise CliError(str(exc) or "not implemented yet") from None
    except (ValueError, RuntimeError, KeyError) as exc:
        raise CliError(str(exc).strip("'\"")) from None
    return result, 1000 * (time.perf_counter() - t0)


def _is_terminal(stream) -> bool:
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):
        return False


class _Progress:
    """The progress display on a terminal (stderr), with rich: it appears
    once the run has taken ``PROGRESS_AFTER`` seconds (at once with
    ``--progress``) and shows the refinement's vertices against the limit.
    The engine calls it whenever its kernel hands back control."""

    def __init__(self, *, enabled: bool, eager: bool):
        self.enabled = enabled
        self.eager = eager
        self.start = time.perf_counter()
        self.status = None

    def __enter__(self):
        if self.enabled and self.eager:
            self._show("Meshing...")
        return self

    def __exit__(self, *exc) -> None:
        if self.status is not None:
            self.status.stop()
            self.status = None

    def __call__(self, vertices: int, limit: int) -> None:
        if not self.enabled:
            return
        text = f"Refining: {vertices:,} vertices (limit {limit:,})"
        if self.status is not None:
            self.status.update(text)
        elif time.perf_counter() - self.start >= PROGRESS_AFTER:
            self._show(text)

    def _show(self, text: str) -> None:
        from rich.console import Console  # only for runs that show it (rich comes with meshio)

        self.status = Console(stderr=True).status(text)
        self.status.start()


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


def _output_mesh(result, data, o) -> dict[str, Any]:
    """The engine's result, completed with what Triangle writes but the engine may omit."""
    mesh = dict(result)
    if o.p:
        for key in ("holes", "regions"):
            if key not in mesh and data.get(key) is not None and np.size(data[key]):
                mesh[key] = data[key]
    if o.r:
        mesh.pop("regions", None)  # Triangle does not read them when refining
    if o.B:
        for key in ("vertex_markers", "segment_markers", "edge_markers"):
            mesh.pop(key, None)
    if not (o.p or o.c):
        mesh.pop("segments", None)  # Triangle writes none, and counts hull subsegments
    return mesh


def _with_empty_arrays(
    mesh: Mapping[str, Any], kinds: list[str], order: int, *, markers: bool = True
) -> dict[str, Any]:
    """``mesh`` with empty arrays for the files to write whose data the engine
    left out (it leaves out empty arrays, as the `triangle` package does).
    Empty marker arrays too: Triangle's .poly and .edge headers declare a
    marker column unless -B (``0  1``), even when there is no row."""
    mark = [("segment_markers", (0, 1), np.int32)] if markers else []
    needs = {
        "ele": [("triangles", (0, 6 if order == 2 else 3), np.int32)],
        "off": [("triangles", (0, 6 if order == 2 else 3), np.int32)],
        "poly": [("segments", (0, 2), np.int32), *mark, ("holes", (0, 2), np.float64)],
        "edge": [("edges", (0, 2), np.int32), *([("edge_markers", (0, 1), np.int32)] if markers else [])],
        "neigh": [("neighbors", (0, 3), np.int32)],
    }
    out = dict(mesh)
    for kind in kinds:
        for key, shape, dtype in needs.get(kind, ()):
            if out.get(key) is None:
                out[key] = np.zeros(shape, dtype=dtype)
    return out


def _choose_outputs(o, outbase: str, node_read: bool) -> tuple[list[str], list[str]]:
    """Which files to write, and the console lines about them, in Triangle's order."""
    names = naming.output_files(outbase)
    kinds, lines = [], []

    def take(kind: str) -> None:
        kinds.append(kind)
        lines.append(f"Writing {names[kind]}.")

    if o.N or (o.I and node_read):
        lines.append("NOT writing a .node file.")
    else:
        take("node")
    if o.E:
        lines.append("NOT writing an .ele file.")
    else:
        take("ele")
    if o.p or o.c:
        if o.P or o.I:
            lines.append("NOT writing a .poly file.")
        else:
            take("poly")
    extras = (("g", "off"), ("e", "edge"), ("v", "v.node"), ("v", "v.edge"), ("n", "neigh"))
    for switch, kind in extras:
        if getattr(o, switch):
            take(kind)
    return kinds, lines


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


def _check(mesh, out: TextIO, quiet: bool) -> None:
    """-C: the mesh checker's verdict, in Triangle's words."""
    from instrument.check import check_mesh

    def report(header: str, fine: str, problems: list[str]) -> None:
        if not quiet:
            print(CHECK_TEXT[header], file=out)
        if problems:
            for p in problems:
                print(CHECK_TEXT["problem"].format(p), file=out)
            n = len(problems)
            print(CHECK_TEXT["count"].format(n, "" if n == 1 else "s"), file=out)
        elif not quiet:
            print(CHECK_TEXT[fine], file=out)

    consistency = check_mesh(mesh, delaunay=False)
    everything = check_mesh(mesh)
    report("consistency", "consistent", consistency)
    report("delaunay", "is_delaunay", [p for p in everything if p not in consistency])


# --------------------------------------------------------------------------
# Extra outputs
# --------------------------------------------------------------------------


def _meshio_formats(requested: list[str]) -> list[tuple[str, str, str | None]]:
    """(meshio format, extension, warning) for each --format value."""
    if not any(f.strip() for value in requested for f in value.split(",")):
        return []  # without --format meshio stays unloaded (a tenth of the command's start-up)
    import meshio

    # meshio names its formats only through its extension table (public);
    # a format in it that meshio cannot write fails at the write, as a CliError
    known = sorted({f for fmts in meshio.extension_to_filetypes.values() for f in fmts} | set(FORMAT_EXTENSIONS))
    chosen = []
    for fmt in (f.strip() for value in requested for f in value.split(",")):
        if not fmt:
            continue
        note = None
        if fmt.lower() == "msh":
            note = ("Warning:  meshio's format 'msh' is ANSYS; writing Gmsh 2.2 "
                    "('gmsh22') instead.")
            fmt = "gmsh22"
        if fmt not in known:
            raise CliError(f"Unknown output format {fmt!r}; meshio knows {', '.join(known)}.")
        ext = FORMAT_EXTENSIONS.get(fmt)
        if ext is None:
            ext = next(
                (e for e, fmts in meshio.extension_to_filetypes.items() if fmt in fmts), f".{fmt}"
            )
        chosen.append((fmt, ext, note))
    return chosen


def _write_meshio(path: str, mesh: Mapping[str, Any], fmt: str, o) -> None:
    import meshio

    from .meshio_plugin import to_meshio

    try:
        m = to_meshio(mesh, pad_3d=fmt != "triangle")
        if fmt.startswith("gmsh"):  # Gmsh wants tags; without them meshio warns
            for tag in ("gmsh:physical", "gmsh:geometrical"):
                m.cell_data.setdefault(tag, [np.zeros(len(b.data), dtype=int) for b in m.cells])
        with contextlib.redirect_stderr(io.StringIO()) if o.Q else contextlib.nullcontext():
            meshio.write(path, m, file_format=fmt)
    except OSError as exc:
        raise CliError(f"Cannot create file {exc.filename or path}.") from None
    except Exception as exc:  # meshio writers raise all sorts
        raise CliError(f"Cannot write {path} as {fmt}: {exc}") from None


def _write_file(path: str, text: str) -> None:
    try:
        Path(path).write_text(text)
    except OSError as exc:
        raise CliError(f"Cannot create file {exc.filename or path}.") from None


def _write_trace(path: str, trace) -> None:
    """One CSV row per insertion attempt: the engine's trace (a structured
    array), or just the header when the run inserted nothing."""
    header = TRACE_HEADER if trace is None else trace.dtype.names
    rows = [] if trace is None else trace.tolist()
    try:
        with open(path, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(header)
            w.writerows(rows)
    except OSError as exc:
        raise CliError(f"Cannot create file {exc.filename or path}.") from None


def _voronoi(mesh: Mapping[str, Any]) -> dict[str, np.ndarray]:
    """Triangle's Voronoi diagram of a mesh, as ``write`` wants it (the engine computes it)."""
    from instrument.voronoi import diagram

    return diagram(mesh)


if __name__ == "__main__":
    raise SystemExit(main())
