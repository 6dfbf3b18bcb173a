"""Reading and writing whole file sets: the public ``read`` and ``write``.

Key convention of the returned dicts (the ``triangle`` package's keys, shapes and
dtypes, 0-based indices): a file's main array is always present, possibly with 0
rows -- ``vertices`` (.node/.poly), ``segments`` and ``holes`` (.poly),
``triangles`` (.ele), ``triangle_max_area`` (.area), ``edges`` (.edge),
``neighbors`` (.neigh).  Secondary arrays -- attributes, markers, ``regions``,
``normals`` -- appear only when the file declares them and they have rows.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

import numpy as np

from . import naming
from .area import area_chunks, read_area
from .edge import edge_chunks, read_edge
from .ele import ele_chunks, read_ele
from .info import Info
from .writing import write_text
from .neigh import neigh_chunks, read_neigh
from .node import read_node, vertex_chunks
from .off import off_chunks
from .poly import poly_chunks, read_poly

__all__ = ["Info", "read", "read_with_info", "write", "write_voronoi"]


def read(path: str | os.PathLike[str]) -> dict[str, np.ndarray]:
    """Read a Triangle file, or every file of a base name.

    ``path`` is a ``.node``, ``.poly``, ``.ele`` (its ``.node`` is read too),
    ``.area``, ``.edge`` or ``.neigh`` file, or a base name such as ``"A.1"``, for
    which every existing ``A.1.{node,poly,ele,area,edge,neigh}`` is read.  Raises
    FormatError for bad contents and OSError for a missing file.
    """
    return read_with_info(path)[0]


def read_with_info(
    path: str | os.PathLike[str], *, default_first_index: int = 1
) -> tuple[dict[str, np.ndarray], Info]:
    """Like ``read``, and also return an Info with the numbering base and warnings.

    ``default_first_index`` is the base used when the first vertex is numbered
    neither 0 nor 1 (Triangle's ``-z`` makes it 0).

    A lone ``.area``, ``.edge`` or ``.neigh`` file gives only its own keys; the
    numbering base then comes from the sibling ``.node`` if there is one (for
    ``x.v.edge``: ``x.v.node``), else from the file's own first item number.
    """
    base, kind = naming.split_kind(path)
    info = Info(first_index=default_first_index)
    if kind is None:
        files = naming.input_files(base)
        if not files:
            raise FileNotFoundError(
                f"no file {base} nor any of {base}.{{{','.join(naming.INPUT_KINDS)}}}"
            )
        return read_set(files, default_first_index=default_first_index, info=info), info
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"cannot access file {path}")
    if kind in ("node", "v.node"):
        return read_node(path, default_first_index=default_first_index, info=info), info
    if kind == "poly":
        return read_poly(path, default_first_index=default_first_index, info=info), info
    if kind == "ele":
        node = Path(f"{base}.node")
        out = read_node(node, default_first_index=default_first_index, info=info)
        out.update(_ele(path, info, len(out["vertices"])))
        return out, info
    if kind == "area":
        info.files.append(path)
        return read_area(path), info
    # .edge / .v.edge / .neigh: numbering base from the sibling vertex file if any.
    node = Path(f"{base}.v.node" if kind == "v.edge" else f"{base}.node")
    nvertices = first = None
    if node.is_file():
        nodes = Info()
        vertices = read_node(node, default_first_index=default_first_index, info=nodes)
        nvertices = len(vertices["vertices"])
        first = nodes.first_index
    info.files.append(path)
    if kind in ("edge", "v.edge"):
        return read_edge(path, first_index=first, nvertices=nvertices, info=info), info
    return read_neigh(path, first_index=first, info=info), info


def _ele(path: Path, info: Info, nvertices: int) -> dict[str, np.ndarray]:
    info.files.append(path)
    return read_ele(path, first_index=info.first_index, nvertices=nvertices)


def read_set(
    files: Mapping[str, Path], *, default_first_index: int = 1, info: Info | None = None
) -> dict[str, np.ndarray]:
    """Read the files of one base name, given by kind (see ``naming.input_files``).

    A .poly that lists its vertices wins over the .node; one that lists 0 reads it.
    """
    info = info if info is not None else Info(first_index=default_first_index)
    if "poly" in files:
        out = read_poly(files["poly"], default_first_index=default_first_index, info=info)
    elif "node" in files:
        out = read_node(files["node"], default_first_index=default_first_index, info=info)
    else:
        missing = next(iter(files.values())).with_suffix(".node")
        raise FileNotFoundError(f"cannot access file {missing}")
    nvertices = len(out["vertices"])
    ntriangles = None
    if "ele" in files:
        out.update(_ele(files["ele"], info, nvertices))
        ntriangles = len(out["triangles"])
    if "area" in files:
        info.files.append(files["area"])
        out.update(
            read_area(
                files["area"],
                first_index=info.first_index,
                ntriangles=ntriangles,
                ele_path=files.get("ele"),
            )
        )
    if "edge" in files:
        info.files.append(files["edge"])
        out.update(read_edge(files["edge"], first_index=info.first_index, nvertices=nvertices))
    if "neigh" in files:
        info.files.append(files["neigh"])
        out.update(
            read_neigh(files["neigh"], first_index=info.first_index, ntriangles=ntriangles)
        )
    return out


def write(
    base: str | os.PathLike[str],
    mesh: Mapping[str, Any],
    *,
    first_index: int = 1,
    markers: bool = True,
    kinds: Iterable[str] | None = None,
    generated_by: str | None = None,
    voronoi: Mapping[str, Any] | None = None,
) -> list[Path]:
    """Write ``mesh`` as ``base.node``, ``base.ele``, ... in Triangle's formats.

    Args:
        base: output base name, e.g. ``"A.1"`` (see ``naming.output_base``).
        mesh: a dict with the ``triangle`` package's keys, 0-based.
        first_index: numbering base of the files (0 or 1, Triangle's ``-z``).
        markers: write marker columns for the markers the mesh has (False is
            Triangle's ``-B``).
        kinds: which files, among ``naming.OUTPUT_KINDS``; by default ``node``
            (if ``vertices``), ``ele`` (``triangles``), ``poly`` (``segments``,
            ``holes`` or ``regions``), ``area`` (``triangle_max_area``), ``edge``
            (``edges``), ``v.node``/``v.edge`` (if ``voronoi`` is given) and
            ``neigh`` (``neighbors``).  ``off`` only on request.
        generated_by: text for Triangle's last line ``# Generated by <text>``.
        voronoi: the Voronoi diagram (``vertices``, ``vertex_attributes``,
            ``edges`` with -1 for rays, ``normals``) for ``.v.node``/``.v.edge``.

    A ``.poly`` written with a ``.node`` uses Triangle's 0-vertex form; written
    without one it carries the vertices itself.  Files are written in Triangle's
    order and returned in that order.  Raises ValueError for an unknown kind or a
    kind whose data is missing.
    """
    chosen = _default_kinds(mesh, voronoi) if kinds is None else set(kinds)
    unknown = chosen - set(naming.OUTPUT_KINDS)
    if unknown:
        raise ValueError(
            f"unknown output kinds {sorted(unknown)}; choose from {naming.OUTPUT_KINDS}"
        )
    if chosen & {"v.node", "v.edge"} and voronoi is None:
        raise ValueError("writing .v.node/.v.edge needs the voronoi= dict")
    names = naming.output_files(base)
    opts = {"first_index": first_index}
    makers = {
        "node": lambda: vertex_chunks(mesh, markers=markers, **opts),
        "ele": lambda: ele_chunks(mesh, **opts),
        "poly": lambda: poly_chunks(
            mesh, markers=markers, with_vertices="node" not in chosen, **opts
        ),
        "area": lambda: area_chunks(mesh, **opts),
        "off": lambda: off_chunks(mesh),
        "edge": lambda: edge_chunks(mesh, markers=markers, **opts),
        "v.node": lambda: vertex_chunks(voronoi, markers=False, header_markers=False, **opts),
        "v.edge": lambda: edge_chunks(voronoi, markers=False, **opts),
        "neigh": lambda: neigh_chunks(mesh, **opts),
    }
    # Build every text before writing any file, so bad input leaves no partial set.
    texts = [(kind, makers[kind]()) for kind in naming.OUTPUT_KINDS if kind in chosen]
    return [write_text(names[kind], chunks, generated_by) for kind, chunks in texts]


def write_voronoi(
    base: str | os.PathLike[str],
    voronoi: Mapping[str, Any],
    *,
    first_index: int = 1,
    generated_by: str | None = None,
) -> list[Path]:
    """Write ``base.v.node`` and ``base.v.edge`` from a Voronoi dict (see ``write``)."""
    return write(
        base,
        {},
        first_index=first_index,
        kinds=("v.node", "v.edge"),
        generated_by=generated_by,
        voronoi=voronoi,
    )


def _default_kinds(mesh: Mapping[str, Any], voronoi: Mapping[str, Any] | None) -> set[str]:
    kinds = set()
    present = {key for key, value in mesh.items() if value is not None}
    if "vertices" in present:
        kinds.add("node")
    if "triangles" in present:
        kinds.add("ele")
    if present & {"segments", "holes", "regions"}:
        kinds.add("poly")
    if "triangle_max_area" in present:
        kinds.add("area")
    if "edges" in present:
        kinds.add("edge")
    if "neighbors" in present:
        kinds.add("neigh")
    if voronoi is not None:
        kinds |= {"v.node", "v.edge"}
    return kinds
