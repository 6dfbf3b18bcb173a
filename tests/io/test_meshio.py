"""The meshio plugin and dict <-> meshio.Mesh conversion (ecosystem.md §1)."""

from __future__ import annotations

import subprocess
import sys

import meshio
import numpy as np
import pytest
import triangle
import vtk
from vtk.util.numpy_support import vtk_to_numpy

from iohelpers import PKG_DATA, assert_same_mesh

import ruppert_io
from ruppert_io.meshio_plugin import TRIANGLE6_TO_VTK, VTK_TO_TRIANGLE6


@pytest.fixture(scope="module")
def a_o2():
    """A.poly meshed by the triangle package with 6-node triangles."""
    return triangle.triangulate(ruppert_io.read(PKG_DATA / "A.poly"), "pq30o2")


def test_triangle_comes_before_tetgen():
    for ext in (".node", ".ele", ".poly"):
        assert meshio.extension_to_filetypes[ext][0] == "triangle"
    ruppert_io.meshio_plugin.register()  # idempotent
    assert meshio.extension_to_filetypes[".node"].count("triangle") == 1
    assert "tetgen" in meshio.extension_to_filetypes[".node"]


@pytest.mark.parametrize("order", ["ruppert_io first", "meshio first"])
def test_the_format_is_registered_whichever_is_imported_first(order):
    """ruppert_io does not load meshio itself, yet meshio always knows the format."""
    first, second = ("ruppert_io", "meshio") if order == "ruppert_io first" else ("meshio", "ruppert_io")
    code = (
        f"import sys, {first}\n"
        "loaded = 'meshio' in sys.modules\n"
        f"import {second}, meshio\n"
        "print(loaded, meshio.extension_to_filetypes['.node'][0])\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == [str(first == "meshio"), "triangle"]


def test_meshio_reads_a_triangle_node_with_its_ele():
    m = meshio.read(PKG_DATA / "A.1.node")
    assert len(m.points) == 29
    assert len(m.cells_dict["triangle"]) == 29
    assert len(m.cells_dict["line"]) == 29  # the segments of A.1.poly
    assert m.point_data["triangle:marker"].shape == (29,)
    assert m.point_data["triangle:attr1"].shape == (29,)
    expected = ruppert_io.read(PKG_DATA / "A.1.ele")["triangles"]
    assert np.array_equal(m.cells_dict["triangle"], expected)


def test_meshio_still_reads_tetgen_files(tmp_path, capsys):
    (tmp_path / "tet.node").write_text("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n")
    (tmp_path / "tet.ele").write_text("1 4 0\n1 1 2 3 4\n")
    m = meshio.read(tmp_path / "tet.node")
    assert m.points.shape == (4, 3)
    assert m.cells_dict["tetra"].tolist() == [[0, 1, 2, 3]]
    # meshio prints the reason our reader declined.
    assert "two-dimensional" in capsys.readouterr().out
    # Our reader itself declines with ReadError (meshio's cue to try the next format).
    with pytest.raises(meshio.ReadError, match="two-dimensional"):
        meshio._helpers.reader_map["triangle"](str(tmp_path / "tet.ele"))


def test_meshio_write_and_read_triangle_format(tmp_path, a_o2):
    meshio.write(tmp_path / "m.node", ruppert_io.to_meshio(a_o2))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.ele", "m.node", "m.poly"]
    back = ruppert_io.read(tmp_path / "m")
    assert np.array_equal(back["triangles"], a_o2["triangles"])
    assert np.array_equal(back["segment_markers"], a_o2["segment_markers"])


def test_bad_triangle_file_is_not_swallowed_by_meshio(tmp_path):
    (tmp_path / "bad.node").write_text("3 2 0 0\n1 0 0\n2 1\n3 0 1\n")
    with pytest.raises(ruppert_io.FormatError, match="line 3"):
        meshio.read(tmp_path / "bad.node")


def test_o2_node_order(a_o2):
    m = ruppert_io.to_meshio(a_o2)
    [t6] = [b.data for b in m.cells if b.type == "triangle6"]
    p = m.points
    mid = lambda a, b: (p[t6[:, a]] + p[t6[:, b]]) / 2  # noqa: E731
    # meshio/VTK order: corners, then mid01, mid12, mid20.
    assert np.allclose(p[t6[:, 3]], mid(0, 1))
    assert np.allclose(p[t6[:, 4]], mid(1, 2))
    assert np.allclose(p[t6[:, 5]], mid(2, 0))
    t6 = a_o2["triangles"]
    assert np.array_equal(t6[:, TRIANGLE6_TO_VTK][:, VTK_TO_TRIANGLE6], t6)


def test_round_trip_through_meshio(a_o2):
    keys = ("vertices", "vertex_markers", "vertex_attributes", "triangles", "segments")
    mesh = {k: a_o2[k] for k in (*keys, "segment_markers")}
    mesh["triangle_attributes"] = np.arange(2 * len(mesh["triangles"]), dtype=float).reshape(-1, 2)
    mesh["triangle_max_area"] = np.full((len(mesh["triangles"]), 1), 0.5)
    for pad in (False, True):
        assert_same_mesh(ruppert_io.from_meshio(ruppert_io.to_meshio(mesh, pad_3d=pad)), mesh)


def test_from_meshio_refuses_what_triangle_cannot_hold():
    with pytest.raises(ValueError, match="not planar"):
        ruppert_io.from_meshio(meshio.Mesh(np.eye(3), [("triangle", [[0, 1, 2]])]))
    with pytest.raises(ValueError, match="quad"):
        ruppert_io.from_meshio(meshio.Mesh(np.eye(4)[:, :2], [("quad", [[0, 1, 2, 3]])]))


def _vtk_read(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


@pytest.mark.parametrize("order", ["pq30", "pq30o2"])
def test_vtu_is_read_by_vtk(tmp_path, order):
    t = triangle.triangulate(ruppert_io.read(PKG_DATA / "A.poly"), order)
    path = tmp_path / "a.vtu"
    meshio.write(path, ruppert_io.to_meshio(t, pad_3d=True))
    grid = _vtk_read(path)
    n, m, s = len(t["vertices"]), len(t["triangles"]), len(t["segments"])
    points = vtk_to_numpy(grid.GetPoints().GetData())
    assert np.array_equal(points[:, :2], t["vertices"]) and not points[:, 2].any()
    # Cells: the triangles, then the segments, with VTK's types and node order.
    types = [grid.GetCellType(i) for i in range(grid.GetNumberOfCells())]
    tri_type = vtk.VTK_TRIANGLE if order == "pq30" else vtk.VTK_QUADRATIC_TRIANGLE
    assert types == [tri_type] * m + [vtk.VTK_LINE] * s
    cells = []
    for i in range(m + s):
        cell = grid.GetCell(i)
        cells.append([cell.GetPointId(j) for j in range(cell.GetNumberOfPoints())])
    expected_tris = t["triangles"][:, TRIANGLE6_TO_VTK] if order == "pq30o2" else t["triangles"]
    assert cells[:m] == expected_tris.tolist()
    assert cells[m:] == t["segments"].tolist()
    pd, cd = grid.GetPointData(), grid.GetCellData()
    assert np.array_equal(vtk_to_numpy(pd.GetArray("triangle:marker")), t["vertex_markers"][:, 0])
    assert np.array_equal(vtk_to_numpy(pd.GetArray("triangle:attr1")), t["vertex_attributes"][:, 0])
    seg_marks = vtk_to_numpy(cd.GetArray("triangle:marker"))
    assert np.array_equal(seg_marks[m:], t["segment_markers"][:, 0]) and not seg_marks[:m].any()
