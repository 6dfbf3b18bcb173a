"""meshio integration: the ``"triangle"`` format and dict <-> meshio.Mesh conversion.

meshio 5.3.5 maps ``.node``/``.ele`` to its TetGen reader, which stops the process
(``SystemExit``) on a 2-D file.  ``register()`` puts ``"triangle"`` first for
``.node``, ``.ele`` and ``.poly``; the reader raises ``meshio.ReadError`` for files
that are not 2-D so that genuine TetGen files still fall through to TetGen.

Mesh data travels as ``triangle:``-prefixed arrays: point data ``triangle:marker``
and ``triangle:attr1..k`` (vertex markers and attributes); cell data
``triangle:marker`` (segment markers, on the ``line`` block), ``triangle:attr1..k``
and ``triangle:max_area`` (on the triangle block).  Blocks a name does not belong
to get zeros.  Segments are a ``line`` cell block.  Holes, regions, edges and
neighbours have no place in meshio that every writer accepts, so they are dropped.

Importing meshio takes 70-90 ms, about a tenth of the ``ruppert`` command's start-up,
so ``ruppert_io`` does not import it: ``register_when_imported()`` registers the
format at once if meshio is already loaded, and otherwise right after meshio's own
import, whoever triggers it.
"""

from __future__ import annotations

import importlib.abc
import importlib.util
import os
import re
import sys
from collections.abc import Mapping
from importlib.machinery import ModuleSpec
from types import ModuleType
from typing import TYPE_CHECKING, Any

import numpy as np

from . import naming, writing
from .api import read_set, write
from .errors import DimensionError
from .meshio_formats import REFERENCES

if TYPE_CHECKING:
    import meshio

FORMAT = "triangle"
EXTENSIONS = (".node", ".ele", ".poly")
PREFIX = "triangle:"

# Triangle's -o2 node k+3 lies opposite corner k: [c0, c1, c2, m12, m20, m01].
# meshio/VTK use [c0, c1, c2, m01, m12, m20].
TRIANGLE6_TO_VTK = [0, 1, 2, 5, 3, 4]
VTK_TO_TRIANGLE6 = [0, 1, 2, 4, 5, 3]

_ATTR = re.compile(re.escape(PREFIX) + r"attr([1-9][0-9]*)$")


def register() -> None:
    """Register the ``"triangle"`` format with meshio, ahead of TetGen (idempotent)."""
    import meshio

    meshio.register_format(FORMAT, list(EXTENSIONS), _read, {FORMAT: _write})
    for ext in EXTENSIONS:
        formats = meshio.extension_to_filetypes[ext]
        while FORMAT in formats:
            formats.remove(FORMAT)
        formats.insert(0, FORMAT)


def register_when_imported() -> None:
    """``register()`` now if meshio is loaded, else as soon as it is imported."""
    if "meshio" in sys.modules:
        register()
    elif not any(isinstance(f, _RegisterAfterImport) for f in sys.meta_path):
        sys.meta_path.insert(0, _RegisterAfterImport())


class _RegisterAfterImport(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """A one-shot import hook: loads meshio with its own loader, then registers."""

    def find_spec(self, name: str, path: Any = None, target: Any = None) -> ModuleSpec | None:
        if name != "meshio":
            return None
        sys.meta_path.remove(self)
        spec = importlib.util.find_spec(name)  # the finders that would have found it
        if spec is not None and spec.loader is not None:
            self._loader = spec.loader
            spec.loader = self
        return spec

    def create_module(self, spec: ModuleSpec) -> ModuleType | None:
        return self._loader.create_module(spec)

    def exec_module(self, module: ModuleType) -> None:
        self._loader.exec_module(module)
        register()


def _read(filename: str | os.PathLike[str]) -> meshio.Mesh:
    """meshio reader: the named file with its .node/.poly/.ele/.area siblings."""
    base, _ = naming.split_kind(filename)
    files = naming.input_files(base)
    files = {k: p for k, p in files.items() if k in ("node", "poly", "ele", "area")}
    try:
        mesh = read_set(files)
    except DimensionError as exc:
        import meshio

        raise meshio.ReadError(str(exc)) from exc
    return to_meshio(mesh)


def _write(filename: str | os.PathLike[str], mesh: meshio.Mesh, **kwargs: Any) -> None:
    """meshio writer: ``x.node`` writes x.node, x.ele and (with segments) x.poly."""
    base, _ = naming.split_kind(filename)
    write(base, from_meshio(mesh), **kwargs)


def to_meshio(
    mesh: Mapping[str, Any], *, pad_3d: bool = False, file_format: str | None = None
) -> meshio.Mesh:
    """A meshio.Mesh from a dict with the ``triangle`` package's keys.

    Triangles become a ``triangle`` (or, with 6 nodes, ``triangle6`` in VTK node
    order) block, segments a ``line`` block.  ``pad_3d`` adds z = 0, which VTU and
    most other writers want.  ``file_format`` (a meshio format name) shapes the
    mesh for that writer instead (``meshio_formats.mesh_for``: its cell blocks,
    points, marker names), so that ``meshio.write(path, m, file_format=...)`` writes
    it without warnings; ``ruppert_io.write_meshio`` does both.
    """
    if file_format is not None:
        from .meshio_formats import mesh_for

        return mesh_for(mesh, file_format)
    xy = writing.get(mesh, "vertices", float, 2)
    if xy is None:
        raise ValueError("the mesh has no 'vertices'")
    n = len(xy)
    points = np.column_stack([xy, np.zeros(n)]) if pad_3d else xy
    blocks: list[tuple[str, np.ndarray]] = []
    # name -> {block type -> per-cell array}; other blocks get zeros
    per_block: dict[str, dict[str, np.ndarray]] = {}
    triangles = writing.get(mesh, "triangles", int)
    if triangles is not None and len(triangles):
        if triangles.shape[1] == 6:
            blocks.append(("triangle6", triangles[:, TRIANGLE6_TO_VTK]))
        elif triangles.shape[1] == 3:
            blocks.append(("triangle", triangles))
        else:
            raise ValueError(f"meshio has no {triangles.shape[1]}-node triangle")
        m = len(triangles)
        kind = blocks[-1][0]
        attr = writing.get(mesh, "triangle_attributes", float, rows=m)
        for j in range(0 if attr is None else attr.shape[1]):
            per_block[f"{PREFIX}attr{j + 1}"] = {kind: attr[:, j]}
        area = writing.get(mesh, "triangle_max_area", float, 1, rows=m)
        if area is not None:
            per_block[f"{PREFIX}max_area"] = {kind: area[:, 0]}
    segments = writing.get(mesh, "segments", int, 2)
    if segments is not None and len(segments):
        blocks.append(("line", segments))
        marks = writing.get(mesh, "segment_markers", int, 1, rows=len(segments))
        if marks is not None:
            per_block[f"{PREFIX}marker"] = {"line": marks[:, 0]}
    cell_data = {
        name: [
            arrays.get(kind, np.zeros(len(cells), dtype=next(iter(arrays.values())).dtype))
            for kind, cells in blocks
        ]
        for name, arrays in per_block.items()
    }
    point_data = {}
    marks = writing.get(mesh, "vertex_markers", int, 1, rows=n)
    if marks is not None:
        point_data[f"{PREFIX}marker"] = marks[:, 0]
    attr = writing.get(mesh, "vertex_attributes", float, rows=n)
    for j in range(0 if attr is None else attr.shape[1]):
        point_data[f"{PREFIX}attr{j + 1}"] = attr[:, j]
    import meshio

    return meshio.Mesh(points, blocks, point_data=point_data, cell_data=cell_data)


def from_meshio(m: meshio.Mesh) -> dict[str, np.ndarray]:
    """A dict with the ``triangle`` package's keys from a meshio.Mesh.

    Accepts 2-D points, or 3-D points with z = 0.  ``triangle``/``triangle6`` blocks
    become ``triangles`` (6-node ones back in Triangle's order), ``line`` blocks
    ``segments``; ``vertex`` blocks are ignored and other cell types refused
    (ValueError).  ``triangle:`` data arrays become markers and attributes;
    without them, the formats' own per-cell references (``gmsh:physical``,
    ``medit:ref``, ... see ``meshio_formats.REFERENCES``) become segment markers
    and (when not all 0) the triangles' one attribute, and ``medit:ref`` on the
    points the vertex markers.
    """
    points = np.asarray(m.points, dtype=np.float64)
    if points.ndim != 2 or points.shape[1] not in (2, 3):
        raise ValueError(f"points must be (N, 2) or (N, 3), got {points.shape}")
    if points.shape[1] == 3:
        if np.any(points[:, 2] != 0):
            raise ValueError("the mesh is not planar: some points have z != 0")
        points = points[:, :2]
    out: dict[str, np.ndarray] = {"vertices": np.ascontiguousarray(points)}
    tris, lines = [], []
    tri_data: dict[str, list[np.ndarray]] = {}
    line_marks: list[np.ndarray] = []
    reference = next((name for name in REFERENCES if name in m.cell_data), None)
    tri_refs: list[np.ndarray] = []
    for i, block in enumerate(m.cells):
        data = np.asarray(block.data)
        if block.type in ("triangle", "triangle6"):
            tris.append(data[:, VTK_TO_TRIANGLE6] if block.type == "triangle6" else data)
            for name, arrays in m.cell_data.items():
                if name == f"{PREFIX}max_area" or _ATTR.match(name):
                    tri_data.setdefault(name, []).append(np.asarray(arrays[i]).reshape(-1))
            if reference:
                tri_refs.append(np.asarray(m.cell_data[reference][i]).reshape(-1))
        elif block.type == "line":
            lines.append(data)
            marks = m.cell_data.get(f"{PREFIX}marker", m.cell_data.get(reference))
            if marks is not None:
                line_marks.append(np.asarray(marks[i]).reshape(-1))
        elif block.type != "vertex":
            raise ValueError(f"Triangle meshes have no {block.type!r} cells")
    if tris:
        widths = {t.shape[1] for t in tris}
        if len(widths) > 1:
            raise ValueError("cannot mix 3-node and 6-node triangles")
        out["triangles"] = np.concatenate(tris).astype(np.int32)
        attrs = sorted((int(_ATTR.match(k).group(1)), k) for k in tri_data if _ATTR.match(k))
        if attrs:
            out["triangle_attributes"] = np.column_stack(
                [np.concatenate(tri_data[k]) for _, k in attrs]
            ).astype(np.float64)
        elif tri_refs and np.any(np.concatenate(tri_refs)):
            # a region number (Gmsh's physical tag, Medit's reference) is Triangle's attribute
            out["triangle_attributes"] = np.concatenate(tri_refs).astype(np.float64).reshape(-1, 1)
        if f"{PREFIX}max_area" in tri_data:
            out["triangle_max_area"] = np.concatenate(tri_data[f"{PREFIX}max_area"]).reshape(-1, 1)
    if lines:
        out["segments"] = np.concatenate(lines).astype(np.int32)
        if line_marks:
            out["segment_markers"] = np.concatenate(line_marks).astype(np.int32).reshape(-1, 1)
    marks = m.point_data.get(f"{PREFIX}marker", m.point_data.get("medit:ref"))
    if marks is not None:
        out["vertex_markers"] = np.asarray(marks).astype(np.int32).reshape(-1, 1)
    attrs = sorted((int(_ATTR.match(k).group(1)), k) for k in m.point_data if _ATTR.match(k))
    if attrs:
        out["vertex_attributes"] = np.column_stack(
            [np.asarray(m.point_data[k], dtype=np.float64).reshape(-1) for _, k in attrs]
        )
    return out
