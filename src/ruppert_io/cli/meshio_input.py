"""The command's input from a mesh file in one of meshio's formats (VTU, Gmsh, Medit, ...).

``ruppert -rq30 mesh.vtu`` refines the mesh in ``mesh.vtu``; ``ruppert -p
outline.msh`` triangulates the line cells of ``outline.msh`` as a PSLG.  The
file is read this way only when it exists and its extension is meshio's, not
Triangle's (``.node``, ``.poly``, ``.ele``, ``.area``, ``.edge``, ``.neigh``
keep Triangle's rules exactly).  The switches pick what is used, as Triangle's
would pick files: the points always (the ``.node``), the line cells as segments
with ``-p`` (the ``.poly``), the triangles with ``-r`` (the ``.ele``) and their
``triangle:max_area`` with ``-ra`` (the ``.area``).  Markers come back through
``from_meshio``.  Output files are named from the base name, as Triangle would
(``mesh.vtu`` -> ``mesh.1.node``).
"""

from __future__ import annotations

import contextlib
import io
import os
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .. import naming
from ..info import Info
from .errors import CliError


@dataclass(frozen=True)
class MeshioInput:
    """A meshio file named on the command line: its path, base name and candidate readers."""

    path: Path
    base: str
    formats: tuple[str, ...]


def find(name: str) -> MeshioInput | None:
    """The meshio file ``name`` names, or None when Triangle's file-name rules apply."""
    if naming.split_kind(name)[1] is not None or not os.path.isfile(name):
        return None
    suffixes = "".join(Path(name).suffixes).lower()
    if not suffixes:
        return None
    import meshio

    # the longest extension that matches (".vol.gz" before ".gz")
    for ext in sorted(meshio.extension_to_filetypes, key=len, reverse=True):
        if name.lower().endswith(ext) and len(name) > len(ext):
            formats = [f for f in meshio.extension_to_filetypes[ext] if f != "triangle"]
            if ext == ".msh":  # meshio lists ANSYS first; Gmsh's .msh is far more common
                formats.sort(key=lambda f: f != "gmsh")
            if formats:
                return MeshioInput(Path(name), name[: -len(ext)], tuple(formats))
    return None


def read(source: MeshioInput, o) -> tuple[dict[str, np.ndarray], Info]:
    """The arrays Triangle would read for switches ``o``, taken from the meshio file."""
    from ..meshio_plugin import from_meshio

    m = _read_mesh(source)
    try:
        mesh = from_meshio(m)
    except ValueError as exc:
        raise CliError(f"Cannot use {source.path}: {exc}.") from None
    info = Info(first_index=0 if o.z else 1)
    info.files.append(source.path)
    info.vertices_from = source.path
    keys = ["vertices", "vertex_markers", "vertex_attributes"]
    if o.p:
        keys += ["segments", "segment_markers"]
    if o.r:
        if "triangles" not in mesh:
            raise CliError(f"{source.path} has no triangles to refine (-r).")
        if mesh["triangles"].shape[1] != 3:
            raise CliError(f"{source.path} has 6-node triangles; -r refines 3-node ones.")
        keys += ["triangles", "triangle_attributes"]
        if o.var_area:
            keys.append("triangle_max_area")
    data = {k: mesh[k] for k in keys if k in mesh}
    if o.p:
        data.setdefault("segments", np.zeros((0, 2), np.int32))
    return data, info


def _read_mesh(source: MeshioInput):
    """Try the extension's readers in turn, as meshio does, but without its
    printing and its ``sys.exit`` when none of them can read the file (named
    one at a time, meshio lets the reader's exception through)."""
    import meshio

    problems = []
    for fmt in source.formats:
        said = io.StringIO()
        try:
            with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(said):
                mesh = meshio.read(source.path, file_format=fmt)
        except OSError as exc:
            raise CliError(f"Cannot access file {exc.filename or source.path}.") from None
        except (Exception, SystemExit) as exc:  # readers raise all sorts; some exit
            text = str(exc).strip() if not isinstance(exc, SystemExit) else ""
            text = text or " ".join(said.getvalue().split()).removeprefix("Error: ") or type(exc).__name__
            problems.append(f"as {fmt}: {text}")
            continue
        sys.stderr.write(said.getvalue())  # a reader's warnings about a file it did read
        return mesh
    raise CliError(f"Cannot read {source.path} ({'; '.join(problems)}).")
