"""Every format meshio can write: the mesh comes back, with the markers the format can hold.

One table (``ruppert_io.meshio_formats.FORMATS``) says what each writer takes;
these tests hold it to meshio's own writer list and read every file back with
the format's reader (SVG, which meshio cannot read, through its XML).
"""

from __future__ import annotations

import importlib.util
import xml.etree.ElementTree as ET

import meshio
import numpy as np
import pytest
from meshio._helpers import _writer_map  # meshio's writers: the list to cover

import instrument
import ruppert_io
from iohelpers import PKG_DATA
from instrument.check import check_mesh
from ruppert_io.meshio_formats import FORMATS, LINE, TRIANGLE6, FormatUnavailable, mesh_for

WRITERS = sorted(_writer_map)


def _made(opts: str) -> tuple[dict, dict]:
    pslg = ruppert_io.read(PKG_DATA / "A.poly")
    mesh = dict(instrument.triangulate(pslg, opts))
    assert check_mesh(mesh, pslg=pslg, min_angle=30) == []
    # region numbers 1 (left half) and 2 (right half), so that they travel too
    corners = mesh["vertices"][mesh["triangles"][:, :3]]
    x = corners[:, :, 0].mean(axis=1)
    mesh["triangle_attributes"] = np.where(x < np.median(x), 1.0, 2.0).reshape(-1, 1)
    return pslg, mesh


@pytest.fixture(scope="module")
def a_mesh():
    return _made("pq30")[1]


@pytest.fixture(scope="module")
def a_mesh_o2():
    return _made("pq30o2")[1]


def _usable(name: str):
    fmt = FORMATS[name]
    if fmt.refusal:
        return fmt
    if fmt.needs and importlib.util.find_spec(fmt.needs) is None:
        pytest.skip(f"writing {name} needs {fmt.needs}, which is not installed")
    return fmt


def _oriented(triangles) -> set[tuple[int, ...]]:
    """Triangles as rows rotated to start at their smallest corner (keeps orientation)."""
    out = set()
    for t in np.asarray(triangles).tolist():
        k = t[:3].index(min(t[:3]))
        corners = t[k:3] + t[:k]
        out.add(tuple(corners + ([t[3 + (k + j) % 3] for j in range(3)] if len(t) == 6 else [])))
    return out


def _vertex_map(fmt, original: np.ndarray, back: np.ndarray) -> np.ndarray:
    """For each vertex read back, the original vertex at its place (the identity
    unless the format renumbers); coordinates within the format's precision."""
    assert back.shape[1] in (2, 3)
    if back.shape[1] == 3:
        assert not back[:, 2].any()
    back = back[:, :2]
    scale = np.abs(original).max()
    tol = fmt.precision * scale
    if not fmt.renumbers:
        assert back.shape == original.shape
        assert np.allclose(back, original, rtol=0, atol=tol) if tol else np.array_equal(back, original)
        return np.arange(len(back))
    index = {tuple(p): i for i, p in enumerate(original.tolist())}
    return np.array([index[tuple(p)] for p in back.tolist()])


def _read(fmt, path) -> meshio.Mesh:
    if fmt.reader is None:  # SVG: paths "M x y L x y L x y Z", y flipped and scaled
        return _read_svg(path)
    return meshio.read(path, file_format=fmt.reader)


def _read_svg(path) -> meshio.Mesh:
    ns = "{http://www.w3.org/2000/svg}"
    root = ET.parse(path).getroot()
    cells = {"triangle": [], "line": []}
    for p in root.iter(f"{ns}path"):
        numbers = [float(x) for x in p.get("d").replace("M", " ").replace("L", " ").replace("Z", " ").split()]
        xy = np.array(numbers).reshape(-1, 2)
        cells["triangle" if len(xy) == 3 else "line"].append(xy)
    return cells


def _check_svg(mesh, cells, tol) -> None:
    v = mesh["vertices"]
    lo, hi = v.min(axis=0), v.max(axis=0)
    scale = 100 / (hi[0] - lo[0])
    for kind, key in (("triangle", "triangles"), ("line", "segments")):
        drawn = np.array(cells[kind])
        expected = v[mesh[key]].copy()
        expected[..., 1] = hi[1] + lo[1] - expected[..., 1]
        assert np.allclose(drawn, expected * scale, rtol=0, atol=1e-6 * 100 + tol)


def test_the_table_covers_every_meshio_writer():
    assert sorted(FORMATS) == WRITERS
    for fmt in FORMATS.values():
        assert fmt.reader is None or fmt.reader in meshio._helpers.reader_map


# meshio's STL reader overflows a uint32 while it tells ASCII from binary (harmless)
@pytest.mark.filterwarnings("ignore:overflow encountered:RuntimeWarning")
@pytest.mark.parametrize("name", WRITERS)
def test_every_format_round_trips(name, a_mesh, tmp_path, capfd):
    fmt = _usable(name)
    path = tmp_path / f"a{fmt.extension}"
    if fmt.refusal:
        with pytest.raises(FormatUnavailable, match="cannot hold a 2-D triangle mesh.*vtu"):
            ruppert_io.write_meshio(path, a_mesh, name)
        assert list(tmp_path.iterdir()) == []
        return
    capfd.readouterr()
    ruppert_io.write_meshio(path, a_mesh, name)
    out, err = capfd.readouterr()
    assert (out, err) == ("", "")  # no meshio warnings
    back = _read(fmt, path)
    if fmt.reader is None:
        _check_svg(a_mesh, back, 0)
        return
    got = ruppert_io.from_meshio(back)
    new_to_old = _vertex_map(fmt, a_mesh["vertices"], back.points)
    assert _oriented(new_to_old[got["triangles"]]) == _oriented(a_mesh["triangles"])
    if LINE in fmt.cells:
        assert sorted(map(tuple, np.sort(new_to_old[got["segments"]], axis=1).tolist())) == sorted(
            map(tuple, np.sort(a_mesh["segments"], axis=1).tolist())
        )
    carried = fmt.named != "none" or fmt.ref or fmt.gmsh
    if fmt.named != "none" or fmt.ref_points:
        marks = np.empty_like(a_mesh["vertex_markers"])
        marks[new_to_old] = got["vertex_markers"]
        assert np.array_equal(marks, a_mesh["vertex_markers"])
    if carried and LINE in fmt.cells and (fmt.named == "all" or fmt.ref or fmt.gmsh):
        by_segment = dict(zip(map(tuple, np.sort(new_to_old[got["segments"]], axis=1).tolist()),
                              got["segment_markers"][:, 0].tolist()))
        expected = dict(zip(map(tuple, np.sort(a_mesh["segments"], axis=1).tolist()),
                            a_mesh["segment_markers"][:, 0].tolist()))
        assert by_segment == expected
    if fmt.named == "all" or fmt.ref in ("medit:ref", "netgen:index", "avsucd:material") or fmt.gmsh:
        # the regions' attributes 1 and 2, triangle by triangle
        got_attr = {t: a for t, a in zip(_oriented_rows(new_to_old[got["triangles"]]), got["triangle_attributes"][:, 0])}
        want = {t: a for t, a in zip(_oriented_rows(a_mesh["triangles"]), a_mesh["triangle_attributes"][:, 0])}
        assert got_attr == want and set(want.values()) == {1.0, 2.0}


def _oriented_rows(triangles):
    return [min((t[k], t[(k + 1) % 3], t[(k + 2) % 3]) for k in range(3)) for t in np.asarray(triangles)[:, :3].tolist()]


@pytest.mark.parametrize("name", [n for n in WRITERS if TRIANGLE6 in FORMATS[n].cells and not FORMATS[n].refusal])
def test_six_node_triangles_round_trip(name, a_mesh_o2, tmp_path, capfd):
    fmt = _usable(name)
    path = tmp_path / f"a{fmt.extension}"
    ruppert_io.write_meshio(path, a_mesh_o2, name)
    assert capfd.readouterr() == ("", "")
    back = meshio.read(path, file_format=fmt.reader)
    got = ruppert_io.from_meshio(back)
    new_to_old = _vertex_map(fmt, a_mesh_o2["vertices"], back.points)
    assert got["triangles"].shape[1] == 6
    assert _oriented(new_to_old[got["triangles"]]) == _oriented(a_mesh_o2["triangles"])


@pytest.mark.parametrize("name", [n for n in WRITERS if TRIANGLE6 not in (FORMATS[n].cells_o2 or FORMATS[n].cells)])
def test_six_node_triangles_where_the_format_has_none(name, a_mesh_o2, tmp_path):
    with pytest.raises(FormatUnavailable, match=r"6-node triangles|cannot hold"):
        ruppert_io.write_meshio(tmp_path / f"a{FORMATS[name].extension}", a_mesh_o2, name)
    assert list(tmp_path.iterdir()) == []


def test_gmsh41_entities_carry_the_physical_tags(a_mesh):
    m = mesh_for(a_mesh, "gmsh")
    dim_tags = m.point_data["gmsh:dim_tags"]
    for block, phys, geo in zip(m.cells, m.cell_data["gmsh:physical"], m.cell_data["gmsh:geometrical"]):
        assert len(set(phys.tolist())) == 1 and len(set(geo.tolist())) == 1
        dim = 1 if block.type == "line" else 2
        # the writer declares an entity only through a node that belongs to it
        assert np.any((dim_tags[:, 0] == dim) & (dim_tags[:, 1] == geo[0]))
    # nodes in file order (entity by entity), so every reader numbers them alike
    assert np.all(np.diff(dim_tags[:, 0] * 10**6 + dim_tags[:, 1]) >= 0)


def test_a_missing_optional_package_is_named(monkeypatch, a_mesh, tmp_path):
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda n, *a: None if n == "h5py" else real(n, *a))
    with pytest.raises(FormatUnavailable, match=r"needs the Python package h5py: pip install h5py"):
        ruppert_io.write_meshio(tmp_path / "a.xdmf", a_mesh)


def test_the_extension_picks_the_format(a_mesh, tmp_path):
    ruppert_io.write_meshio(tmp_path / "a.msh", a_mesh)  # Gmsh 2.2, not meshio's first (ANSYS)
    assert (tmp_path / "a.msh").read_bytes().startswith(b"$MeshFormat\n2.2 1")
    with pytest.raises(FormatUnavailable, match="b8.ugrid"):
        ruppert_io.write_meshio(tmp_path / "a.ugrid", a_mesh)


def test_to_meshio_shapes_for_a_format(a_mesh, tmp_path, capfd):
    m = ruppert_io.to_meshio(a_mesh, file_format="obj")
    assert [b.type for b in m.cells] == ["triangle"] and m.points.shape[1] == 3
    meshio.write(tmp_path / "a.obj", m)
    assert capfd.readouterr().err == ""
