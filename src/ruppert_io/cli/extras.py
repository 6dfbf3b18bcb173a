"""The files the long options add to Triangle's: meshio formats, ``--work-json``, ``--trace``.

meshio is imported only when ``--format`` asks for it: it costs a tenth of
the command's start-up; json and csv likewise only for the files that use
them (a few milliseconds of every start-up otherwise).
"""

from __future__ import annotations

import contextlib
import io
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from .errors import CliError


#: Header of a --trace file when the engine returned no trace (no refinement ran).
TRACE_HEADER = ("kind", "created", "deleted", "walk_steps", "queue_length")


#: meshio formats whose extension meshio's table does not give.
FORMAT_EXTENSIONS = {"gmsh22": ".msh", "gmsh": ".msh", "vtk42": ".vtk", "vtk51": ".vtk"}


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


def meshio_formats(requested: list[str]) -> list[tuple[str, str, str | None]]:
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

    from ..meshio_plugin import to_meshio

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
