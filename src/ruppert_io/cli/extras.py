"""The files the long options add to Triangle's: meshio formats, ``--work-json``, ``--trace``.

meshio is imported only when ``--format`` asks for it: it costs a tenth of
the command's start-up; json and csv likewise only for the files that use
them (a few milliseconds of every start-up otherwise).  What each format
holds, and how a mesh is shaped for it, is ``ruppert_io.meshio_formats``'s table.
"""

from __future__ import annotations

import contextlib
import io
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from .errors import CliError


#: Header of a --trace file when the engine returned no trace (no refinement ran).
TRACE_HEADER = ("kind", "created", "deleted", "walk_steps", "queue_length")


def write_extras(long, formats, outbase: str, mesh, result, o, say, warn) -> None:
    """The long options' files: meshio formats, --work-json, --trace."""
    for fmt, ext, note in formats:
        if note:
            warn(note)
        path = f"{outbase}{ext}"
        _write_meshio(path, mesh, fmt, o)
        say(f"Writing {path}.")
    if long.work_json:
        import json

        work = dict(getattr(result, "work", {}) or {})
        _write_file(long.work_json, json.dumps(work, indent=2) + "\n")
        say(f"Writing {long.work_json}.")
    if long.trace:
        _write_trace(long.trace, getattr(result, "trace", None))
        say(f"Writing {long.trace}.")


def meshio_formats(requested: list[str], order: int = 1) -> list[tuple[str, str, str | None]]:
    """(meshio format, extension, warning) for each --format value.

    Checked before the run, so that a format that cannot hold the mesh (a 3-D
    one, a missing package, no 6-node triangles for -o2) stops the command
    before it writes anything.
    """
    from ..meshio_formats import FORMATS, TRIANGLE6, FormatUnavailable, check_available, find

    chosen = []
    for fmt in (f.strip() for value in requested for f in value.split(",")):
        if not fmt:
            continue
        note = None
        if fmt.lower() == "msh":
            note = ("Warning:  meshio's format 'msh' is ANSYS; writing Gmsh 2.2 "
                    "('gmsh22') instead.")
            fmt = "gmsh22"
        try:
            row = find(fmt)
            check_available(row)
        except FormatUnavailable as exc:
            raise CliError(str(exc)) from None
        if order == 2 and TRIANGLE6 not in (row.cells_o2 or row.cells):
            from ..meshio_formats import ALTERNATIVES_O2

            raise CliError(f"{fmt} has no 6-node triangles (-o2); write {ALTERNATIVES_O2} instead.")
        chosen.append((fmt, FORMATS[fmt].extension, note))
    return chosen


def _write_meshio(path: str, mesh: Mapping[str, Any], fmt: str, o) -> None:
    from ..meshio_formats import write_meshio

    try:
        with contextlib.redirect_stderr(io.StringIO()) if o.Q else contextlib.nullcontext():
            write_meshio(path, mesh, fmt)
    except OSError as exc:
        raise CliError(f"Cannot create file {exc.filename or path}.") from None
    except ValueError as exc:  # FormatUnavailable, or a writer's own complaint
        raise CliError(str(exc)) from None


def _write_file(path: str, text: str) -> None:
    try:
        Path(path).write_text(text)
    except OSError as exc:
        raise CliError(f"Cannot create file {exc.filename or path}.") from None


def _write_trace(path: str, trace) -> None:
    """One CSV row per insertion attempt: the engine's trace (a structured
    array), or just the header when the run inserted nothing."""
    import csv

    header = TRACE_HEADER if trace is None else trace.dtype.names
    rows = [] if trace is None else trace.tolist()
    try:
        with open(path, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(header)
            w.writerows(rows)
    except OSError as exc:
        raise CliError(f"Cannot create file {exc.filename or path}.") from None
