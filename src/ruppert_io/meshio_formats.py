"""Writing a mesh in each of meshio's formats: what each format can hold, in one table.

meshio 5.3.5 writes some 30 formats, and its writers differ in what they take
(ecosystem.md section 1.5): some keep only triangles and print a warning for the
segments, some want 3-D points and pad them with a warning, PLY casts int64 down
with a warning, Gmsh 4.1 refuses two cell types without entity information, the
SU2, UGRID, Tecplot and H5M writers crash on input they do not expect, and a few
(TetGen, FLAC3D, CGNS) write only 3-D cells.  Rather than let each fail or print
warnings a user cannot act on, ``FORMATS`` says per format which cell blocks it
takes, whether it wants 3-D points, how markers and attributes travel, which
integer width it needs and which optional package it imports; ``mesh_for``
shapes the mesh accordingly and ``write_meshio`` writes it.

Markers travel under the names the format's own reader gives back: the
``triangle:`` names of ``meshio_plugin`` where arbitrary data is kept (VTU, VTK,
XDMF, MED, ...), ``gmsh:physical``/``gmsh:geometrical`` (and Gmsh 4.1's
``gmsh:dim_tags`` entities) for Gmsh, and one integer reference per cell
(``medit:ref``, ``su2:tag``, ``netgen:index``, ``avsucd:material``) elsewhere:
the segment marker on a segment, the first triangle attribute (when it is a
whole number) on a triangle.
"""

from __future__ import annotations

import contextlib
import importlib.util
import io
import os
import sys
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from . import writing

if TYPE_CHECKING:
    import meshio

#: The meshio cell types a Triangle mesh produces.
TRIANGLE, TRIANGLE6, LINE = "triangle", "triangle6", "line"

#: Formats a user may name that hold 2-D triangle meshes with their markers.
ALTERNATIVES = "vtu, xdmf, gmsh, medit or exodus"
#: ... and 6-node triangles.
ALTERNATIVES_O2 = "vtu, xdmf, gmsh, med or exodus"


@dataclass(frozen=True)
class Format:
    """What one meshio writer can hold, and how to hand it a Triangle mesh."""

    name: str
    #: the file name extension ruppert gives it ("" for none)
    extension: str
    #: the cell types it keeps, among triangle, triangle6 and line
    cells: frozenset[str] = frozenset({TRIANGLE, TRIANGLE6, LINE})
    #: the cell types it keeps when the triangles have 6 nodes (None: ``cells``)
    cells_o2: frozenset[str] | None = None
    #: pad the points with z = 0 (the writer wants 3-D points, or pads them itself with a warning)
    points_3d: bool = True
    #: which ``triangle:`` arrays travel: "all", "points" (its cell data does not), or "none"
    named: str = "all"
    #: the per-cell integer reference of the format (segment markers, region numbers)
    ref: str | None = None
    #: the reference array also carries the vertex markers as point data
    ref_points: bool = False
    #: Gmsh's tags: "gmsh22" (per element) or "gmsh" (4.1: one entity per tag)
    gmsh: str | None = None
    #: integer dtype of cells and integer data ("int32" for PLY, "int64" for VTK 5.1)
    int_dtype: str | None = None
    #: the optional Python package the writer imports
    needs: str | None = None
    #: keyword arguments for the writer
    kwargs: Mapping[str, Any] = field(default_factory=dict)
    #: the starts of warnings meshio prints on every write of this format
    unavoidable: tuple[str, ...] = ()
    #: meshio's reader for it (None: no reader, e.g. SVG)
    reader: str | None = None
    #: why it cannot hold a 2-D triangle mesh at all (None: it can)
    refusal: str | None = None
    #: relative precision of the coordinates it stores (0: exact)
    precision: float = 0.0
    #: significant digits the coordinates are rounded to first (the writer has no room for more)
    digits: int | None = None
    #: its reader numbers the vertices differently (a triangle soup, or Gmsh 4.1's entity order)
    renumbers: bool = False


def _formats(*rows: Format) -> dict[str, Format]:
    return {f.name: f for f in rows}


_TRI = frozenset({TRIANGLE})
_TRI_LINE = frozenset({TRIANGLE, LINE})

#: meshio 5.3.5's writers, by the names meshio gives them.
FORMATS: dict[str, Format] = _formats(
    Format("abaqus", ".inp", points_3d=False, named="none", reader="abaqus"),
    Format("ansys", ".msh", cells=_TRI, named="none", reader="ansys"),
    Format("avsucd", ".avs", cells=_TRI_LINE, named="points", ref="avsucd:material", reader="avsucd"),
    Format("cgns", ".cgns", reader="cgns", needs="h5py",
           refusal="meshio's CGNS writer writes tetrahedra only"),
    Format("dolfin-xml", ".xml", cells=_TRI, points_3d=False, named="none", reader="dolfin-xml",
           unavoidable=("DOLFIN XML is a legacy format",)),
    Format("exodus", ".e", points_3d=False, named="points", needs="netCDF4", reader="exodus"),
    Format("flac3d", ".f3grid", reader="flac3d",
           refusal="FLAC3D holds 3-D zones only (tetrahedra, hexahedra, ...)"),
    # ASCII Gmsh with data is broken under NumPy 2 (it writes "np.float64(1.0)")
    Format("gmsh", ".msh", gmsh="gmsh", kwargs={"binary": True}, reader="gmsh", renumbers=True),
    # meshio 5.3.5 cannot read Gmsh 2.2's ElementData back (it splits it by the wrong lengths)
    Format("gmsh22", ".msh", named="points", gmsh="gmsh22", kwargs={"binary": True}, reader="gmsh"),
    Format("h5m", ".h5m", cells=_TRI_LINE, named="points", needs="h5py", reader="h5m"),
    Format("hmf", ".hmf", named="points", needs="h5py", reader="hmf",
           unavoidable=("Experimental file format",)),
    Format("mdpa", ".mdpa", named="none", reader="mdpa"),
    Format("med", ".med", points_3d=False, needs="h5py", reader="med"),
    Format("medit", ".mesh", cells=_TRI_LINE, points_3d=False, named="none",
           ref="medit:ref", ref_points=True, reader="medit"),
    # 16-column fields: meshio prints 12 digits and fails (an assert) when a
    # negative number then needs 17 columns, so the coordinates get 10 digits
    Format("nastran", ".bdf", named="none", reader="nastran", precision=1e-9, digits=10),
    Format("netgen", ".vol", points_3d=False, named="none", ref="netgen:index", reader="netgen"),
    Format("neuroglancer", "", cells=_TRI, named="none", reader="neuroglancer", precision=1e-7),
    Format("obj", ".obj", cells=_TRI, named="none", reader="obj"),
    Format("off", ".off", cells=_TRI, named="none", reader="off"),
    Format("permas", ".post", cells=_TRI_LINE, named="none", reader="permas"),
    Format("ply", ".ply", cells=_TRI_LINE, named="points", int_dtype="int32", reader="ply"),
    Format("stl", ".stl", cells=_TRI, named="none", reader="stl", renumbers=True),
    Format("su2", ".su2", cells=_TRI_LINE, points_3d=False, named="none", ref="su2:tag", reader="su2"),
    Format("svg", ".svg", cells=_TRI_LINE, points_3d=False, named="none", reader=None,
           kwargs={"float_fmt": ".6f"}, precision=1e-6),
    Format("tecplot", ".dat", cells=_TRI, named="points", reader="tecplot"),
    Format("tetgen", ".node", reader="tetgen",
           refusal="TetGen's .node/.ele hold tetrahedra only"),
    Format("triangle", ".node", points_3d=False, reader="triangle"),
    # the name picks the encoding: ".b8.ugrid" is big-endian binary; meshio's ASCII
    # UGRID is broken under NumPy 2 (it writes "np.int64(125)")
    Format("ugrid", ".b8.ugrid", cells=_TRI, named="none", reader="ugrid"),  # its writer crashes on cell data
    Format("vtk", ".vtk", int_dtype="int64", reader="vtk"),
    Format("vtk42", ".vtk", reader="vtk"),
    Format("vtk51", ".vtk", int_dtype="int64", reader="vtk"),
    Format("vtu", ".vtu", reader="vtu"),
    Format("wkt", ".wkt", cells=_TRI, named="none", reader="wkt", renumbers=True),
    # a mixed topology with 6-node triangles is not read back (meshio has no code 36 there)
    Format("xdmf", ".xdmf", points_3d=False, needs="h5py", reader="xdmf", cells_o2=frozenset({TRIANGLE6})),
)


#: The per-cell integer references that readers give back, in the order ``from_meshio`` looks for them.
REFERENCES: tuple[str, ...] = ("gmsh:physical", *dict.fromkeys(f.ref for f in FORMATS.values() if f.ref))

#: UGRID's binary encodings, named in the file name before ".ugrid".
_UGRID_BINARY = ("b8", "b4", "lb8", "lb4", "r8", "r4", "lr8", "lr4", "b8l", "lb8l")


class FormatUnavailable(ValueError):
    """The format cannot hold this mesh, or its writer needs a package that is missing."""


def find(name: str) -> Format:
    """The table row of format ``name``; FormatUnavailable for an unknown one."""
    fmt = FORMATS.get(name)
    if fmt is None:
        raise FormatUnavailable(f"Unknown output format {name!r}; meshio writes {', '.join(sorted(FORMATS))}.")
    return fmt


def check_available(fmt: Format) -> None:
    """Raise FormatUnavailable if ``fmt`` cannot hold a triangle mesh or its package is missing."""
    if fmt.refusal:
        raise FormatUnavailable(
            f"{fmt.name} cannot hold a 2-D triangle mesh: {fmt.refusal}. Write {ALTERNATIVES} instead."
        )
    if fmt.needs and importlib.util.find_spec(fmt.needs) is None:
        raise FormatUnavailable(
            f"Writing {fmt.name} needs the Python package {fmt.needs}: "
            f"pip install {fmt.needs} (or pip install 'ruppert[formats]')."
        )


def format_of_path(path: str | os.PathLike[str]) -> Format:
    """The format ruppert writes for a file name: ``.msh`` is Gmsh 2.2 (meshio's first is ANSYS)."""
    name = os.fspath(path)
    if name.endswith(".msh"):
        return FORMATS["gmsh22"]
    import meshio

    for ext, names in sorted(meshio.extension_to_filetypes.items(), key=lambda kv: -len(kv[0])):
        if name.endswith(ext) and names[0] in FORMATS:
            return FORMATS[names[0]]
    raise FormatUnavailable(f"Cannot tell the format of {name} from its extension; name one.")


def mesh_for(mesh: Mapping[str, Any], fmt: Format | str) -> meshio.Mesh:
    """A meshio.Mesh of ``mesh`` (a dict with the ``triangle`` package's keys) shaped for ``fmt``.

    Cell blocks the format does not take are left out (segments for the
    triangle-only formats), which loses nothing the format could hold; 6-node
    triangles where the format has none raise FormatUnavailable, since dropping
    them would leave no mesh.
    """
    import meshio

    from .meshio_plugin import to_meshio

    fmt = find(fmt) if isinstance(fmt, str) else fmt
    check_available(fmt)
    generic = to_meshio(mesh, pad_3d=fmt.points_3d)
    kinds = [block.type for block in generic.cells]
    if TRIANGLE6 in kinds and TRIANGLE6 not in fmt.cells:
        raise FormatUnavailable(f"{fmt.name} has no 6-node triangles (-o2); write {ALTERNATIVES_O2} instead.")
    takes = fmt.cells_o2 if TRIANGLE6 in kinds and fmt.cells_o2 is not None else fmt.cells
    keep = [i for i, kind in enumerate(kinds) if kind in takes]
    cells = [(kinds[i], np.asarray(generic.cells[i].data)) for i in keep]
    point_data: dict[str, np.ndarray] = {}
    cell_data: dict[str, list[np.ndarray]] = {}
    if fmt.named in ("all", "points"):
        point_data.update(generic.point_data)
    if fmt.named == "all":
        cell_data.update({name: [arrays[i] for i in keep] for name, arrays in generic.cell_data.items()})
    refs = [_references(mesh, kind, len(data)) for kind, data in cells]
    if fmt.ref:
        cell_data[fmt.ref] = refs
        marks = writing.get(mesh, "vertex_markers", int, 1, rows=len(generic.points))
        if fmt.ref_points:
            point_data[fmt.ref] = np.zeros(len(generic.points), np.int64) if marks is None else marks[:, 0]
    points = generic.points
    if fmt.digits:
        points = np.array([float(f"{v:.{fmt.digits - 1}e}") for v in points.ravel()]).reshape(points.shape)
    if fmt.gmsh:
        cells, cell_data, point_data = _gmsh_tags(fmt.gmsh, len(points), cells, refs, cell_data, point_data)
    if "gmsh:dim_tags" in point_data:
        points, cells, point_data = _entity_order(points, cells, point_data)
    if fmt.int_dtype:
        cells = [(kind, data.astype(fmt.int_dtype)) for kind, data in cells]
        point_data = {k: _int_as(v, fmt.int_dtype) for k, v in point_data.items()}
        cell_data = {k: [_int_as(v, fmt.int_dtype) for v in arrays] for k, arrays in cell_data.items()}
    m = meshio.Mesh(points, cells, point_data=point_data, cell_data=cell_data)
    if fmt.name == "su2":
        _as_pairs(m)
    return m


def write_meshio(
    path: str | os.PathLike[str], mesh: Mapping[str, Any], file_format: str | None = None
) -> Path:
    """Write ``mesh`` (the ``triangle`` package's keys) to ``path`` in a meshio format.

    ``file_format`` defaults to the one of the extension (``.msh``: Gmsh 2.2).
    Raises FormatUnavailable when the format cannot hold the mesh or needs a
    missing package (before writing anything), OSError when the file cannot be
    made, and any other writer error as ValueError; a failed write leaves no file.
    Warnings meshio prints on every write of a format (e.g. "DOLFIN XML is a legacy
    format") are dropped; any other goes to stderr as meshio printed it.
    """
    import meshio

    fmt = format_of_path(path) if file_format is None else find(file_format)
    if fmt.name == "ugrid" and not os.fspath(path).endswith(tuple(f".{t}.ugrid" for t in _UGRID_BINARY)):
        raise FormatUnavailable(
            f"Name the UGRID file {Path(path).stem}.b8.ugrid (or .lb8.ugrid, ...): meshio picks "
            "the encoding from the name, and its ASCII UGRID is broken under NumPy 2."
        )
    m = mesh_for(mesh, fmt)
    path = Path(path)
    existed = path.exists()
    captured = io.StringIO()
    try:
        with contextlib.redirect_stderr(captured):
            meshio.write(path, m, file_format=fmt.name, **fmt.kwargs)
    except BaseException as exc:
        if not existed:
            with contextlib.suppress(OSError):
                path.unlink()
        if isinstance(exc, (OSError, FormatUnavailable, KeyboardInterrupt, MemoryError)):
            raise
        raise ValueError(f"meshio could not write {path} as {fmt.name}: {exc}") from exc
    finally:
        _pass_on(captured.getvalue(), fmt.unavoidable)
    return path


def _pass_on(text: str, unavoidable: tuple[str, ...]) -> None:
    """Print what meshio printed, less the warnings it prints on every write of the format."""
    kept, dropping = [], False
    for line in text.splitlines(keepends=True):
        if line.startswith("Warning:"):
            dropping = any(line[len("Warning:"):].lstrip().startswith(u) for u in unavoidable)
        if not dropping:
            kept.append(line)
    if kept:
        sys.stderr.write("".join(kept))


def _int_as(values: np.ndarray, dtype: str) -> np.ndarray:
    values = np.asarray(values)
    return values.astype(dtype) if np.issubdtype(values.dtype, np.integer) else values


def _references(mesh: Mapping[str, Any], kind: str, count: int) -> np.ndarray:
    """One integer per cell: the segment marker of a segment, the first triangle
    attribute of a triangle when every one is a whole number; else 0."""
    if kind == LINE:
        marks = writing.get(mesh, "segment_markers", int, 1, rows=count)
        return np.zeros(count, np.int64) if marks is None else marks[:, 0]
    attr = writing.get(mesh, "triangle_attributes", float, rows=count)
    if attr is None or attr.shape[1] == 0:
        return np.zeros(count, np.int64)
    first = attr[:, 0]
    whole = np.all(np.isfinite(first)) and np.array_equal(first, np.round(first))
    if not whole or (first.size and np.abs(first).max() >= 2**31):
        return np.zeros(count, np.int64)
    return first.astype(np.int64)


def _gmsh_tags(version, npoints, cells, refs, cell_data, point_data):
    """Gmsh's physical and geometrical tags (and for 4.1 its node entities).

    The reference of a cell is its physical tag; cells of one dimension and one
    physical tag form one geometrical entity, numbered from 1 per dimension.
    Gmsh 2.2 stores both tags per element.  Gmsh 4.1 stores them per entity, so
    each entity becomes its own cell block, and every node needs the entity it
    belongs to (``gmsh:dim_tags``): the meshio writer declares an entity only
    through the nodes, so each entity gets one of its own nodes first (a
    matching), then every other node goes to the lowest-dimensional entity that
    uses it.
    """
    geometrical = []
    for data, ref in zip(cells, refs):
        _, inverse = np.unique(ref, return_inverse=True)
        geometrical.append(inverse.reshape(-1).astype(np.int64) + 1)
    if version == "gmsh22":
        cell_data = {**cell_data, "gmsh:physical": list(refs), "gmsh:geometrical": geometrical}
        return cells, cell_data, point_data
    blocks, phys, geom, split_data = [], [], [], {name: [] for name in cell_data}
    for i, ((kind, data), ref, geo) in enumerate(zip(cells, refs, geometrical)):
        for tag in np.unique(geo):
            rows = np.flatnonzero(geo == tag)
            blocks.append((kind, data[rows]))
            phys.append(ref[rows])
            geom.append(geo[rows])
            for name, arrays in cell_data.items():
                split_data[name].append(np.asarray(arrays[i])[rows])
    dims = [1 if kind == LINE else 2 for kind, _ in blocks]
    owner = _node_owners(npoints, [data for _, data in blocks], dims)
    dim_tags = np.array([[dims[b], geom[b][0]] for b in owner], dtype=np.int64).reshape(-1, 2)
    cell_data = {**split_data, "gmsh:physical": phys, "gmsh:geometrical": geom}
    return blocks, cell_data, {**point_data, "gmsh:dim_tags": dim_tags}


def _entity_order(points, cells, point_data):
    """Renumber the nodes in the order Gmsh 4.1 lists them, entity by entity.

    meshio's reader returns the nodes in file order and ignores their tags for
    NodeData, so a file whose tags are not 1, 2, 3, ... in file order comes back
    with its point data on the wrong nodes.  Numbered in file order, every
    reader sees the same mesh.
    """
    dim_tags = point_data["gmsh:dim_tags"]
    order = np.lexsort((np.arange(len(points)), dim_tags[:, 1], dim_tags[:, 0]))
    new = np.empty_like(order)
    new[order] = np.arange(len(order))
    cells = [(kind, new[data]) for kind, data in cells]
    point_data = {name: np.asarray(values)[order] for name, values in point_data.items()}
    return points[order], cells, point_data


def _node_owners(npoints: int, blocks: list[np.ndarray], dims: list[int]) -> np.ndarray:
    """The cell block each node is assigned to: each block owns at least one of
    its nodes (augmenting paths); the rest go to the lowest-dimensional block
    using them, unused nodes to the first block of the highest dimension."""
    owner = np.full(npoints, -1, dtype=np.int64)
    nodes = [np.unique(b) for b in blocks]

    def claim(b: int, seen: set[int]) -> bool:
        for v in nodes[b]:
            if v in seen:
                continue
            seen.add(int(v))
            if owner[v] < 0 or claim(int(owner[v]), seen):
                owner[v] = b
                return True
        return False

    for b in range(len(blocks)):
        if not claim(b, set()):
            raise FormatUnavailable(
                "Gmsh 4.1 cannot give each segment marker its own entity in this mesh "
                "(more marker groups than vertices to hold them); write gmsh22 instead."
            )
    for b in sorted(range(len(blocks)), key=lambda b: dims[b]):
        free = nodes[b][owner[nodes[b]] < 0]
        owner[free] = b
    if len(blocks):
        top = max(range(len(blocks)), key=lambda b: (dims[b], -b))
        owner[owner < 0] = top
    return owner


def _as_pairs(m: meshio.Mesh) -> None:
    """Make ``m``'s cell blocks unpack as ``(type, data)`` pairs too: meshio 5.3.5's
    SU2 writer unpacks them so when it writes the boundary markers."""
    import meshio

    class PairCellBlock(meshio.CellBlock):
        def __iter__(self):
            return iter((self.type, self.data))

    m.cells = [PairCellBlock(b.type, b.data) for b in m.cells]
