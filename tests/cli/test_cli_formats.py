"""--format for every meshio writer, and meshio files as the command's input."""

from __future__ import annotations

import importlib.util
import shutil

import meshio
import numpy as np
import pytest
from meshio._helpers import _writer_map  # meshio's writers: the list to cover

import ruppert_io
from instrument.check import check_mesh
from ruppert_io import cli
from ruppert_io.meshio_formats import FORMATS


def _errors(capsys) -> list[str]:
    return [line for line in capsys.readouterr().err.splitlines() if line.strip()]


@pytest.mark.filterwarnings("ignore:overflow encountered:RuntimeWarning")
@pytest.mark.parametrize("name", sorted(_writer_map))
def test_every_format_from_the_command_line(name, workdir, capsys):
    fmt = FORMATS[name]
    if fmt.needs and importlib.util.find_spec(fmt.needs) is None:
        pytest.skip(f"writing {name} needs {fmt.needs}, which is not installed")
    before = set(workdir.iterdir())
    status = cli.main(["-pq30", "A.poly", "--format", name])
    out, err = capsys.readouterr()
    if fmt.refusal:  # 3-D cells only: one Error line naming alternatives, nothing written
        assert status == 1
        assert err.splitlines() == [err.strip()] and err.startswith("Error:  ")
        assert "cannot hold a 2-D triangle mesh" in err and "vtu" in err
        assert set(workdir.iterdir()) == before
        return
    assert status == 0 and err == ""  # no meshio warnings
    path = workdir / f"A.1{fmt.extension}"
    assert f"Writing {path.name}." in out
    if fmt.reader is not None:
        back = ruppert_io.from_meshio(meshio.read(path, file_format=fmt.reader))
        assert len(back["triangles"]) == len(ruppert_io.read(workdir / "A.1.ele")["triangles"])


def test_a_missing_package_is_named_before_the_run(workdir, capsys, monkeypatch):
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda n, *a: None if n == "netCDF4" else real(n, *a))
    assert cli.main(["-pq30", "A.poly", "--format", "exodus"]) == 1
    [line] = _errors(capsys)
    assert "pip install netCDF4" in line and "ruppert[formats]" in line
    assert not (workdir / "A.1.node").exists()


def test_o2_where_the_format_has_no_six_node_triangles(workdir, capsys):
    assert cli.main(["-pq30o2", "A.poly", "--format", "stl"]) == 1
    [line] = _errors(capsys)
    assert "6-node" in line and "vtu" in line
    assert not (workdir / "A.1.node").exists()


# --------------------------------------------------------------------------
# meshio files as input
# --------------------------------------------------------------------------


@pytest.fixture
def a_mesh_files(workdir):
    """A.poly meshed with -pq30, written as Triangle's files and as vtu, Gmsh 2.2,
    Gmsh 4.1 and Medit meshes (and A.1.node etc. for comparison)."""
    assert cli.main(["-Qpq30", "A.poly", "--format", "vtu,gmsh22,medit"]) == 0
    shutil.move("A.1.msh", "A22.msh")
    assert cli.main(["-Qpq30", "A.poly", "--format", "gmsh"]) == 0
    shutil.move("A.1.msh", "A41.msh")
    return workdir


@pytest.mark.parametrize("name", ["A.1.vtu", "A22.msh", "A41.msh", "A.1.mesh"])
def test_refine_a_meshio_mesh(name, a_mesh_files, capsys):
    assert cli.main(["-rq32a0.002", name]) == 0
    out = capsys.readouterr().out
    base = name.rsplit(".", 1)[0]
    outbase = ruppert_io.naming.output_base(base)
    assert f"Opening {name}." in out and f"Writing {outbase}.node." in out
    mesh = ruppert_io.read(outbase)
    source = ruppert_io.from_meshio(meshio.read(name, file_format="gmsh" if name.endswith(".msh") else None))
    assert check_mesh(mesh, min_angle=32, max_area=0.002) == []
    assert len(mesh["triangles"]) > len(source["triangles"])
    # the segments and their markers came along (-r keeps the mesh's boundary)
    assert np.all(mesh["vertex_markers"][np.unique(mesh["segments"])] != 0) if "segments" in mesh else True


def test_refining_a_vtu_is_refining_its_triangle_files(a_mesh_files, capsys):
    """The same mesh, the same run: the .vtu gives what A.1.node/A.1.ele give."""
    assert cli.main(["-Qrq32a0.002", "A.1"]) == 0
    triangle_files = ruppert_io.read("A.2")
    assert cli.main(["-Qrq32a0.002", "A.1.vtu"]) == 0
    from_vtu = ruppert_io.read("A.2")
    for key in ("vertices", "triangles", "vertex_markers"):
        assert np.array_equal(triangle_files[key], from_vtu[key]), key


@pytest.mark.parametrize("name", ["A22.msh", "A41.msh", "A.1.mesh", "A.1.vtu"])
def test_line_cells_are_a_pslg(name, a_mesh_files, capsys):
    """-p on a mesh file: its line cells are the segments (holes do not travel
    through meshio, so the hole of A is meshed)."""
    source = ruppert_io.from_meshio(meshio.read(name, file_format="gmsh" if name.endswith(".msh") else None))
    assert cli.main(["-Qpq30", name]) == 0
    outbase = ruppert_io.naming.output_base(name.rsplit(".", 1)[0])
    mesh = ruppert_io.read(outbase)
    pslg = {k: source[k] for k in ("vertices", "segments", "segment_markers", "vertex_markers")}
    assert check_mesh(mesh, pslg=pslg, min_angle=30) == []


def test_a_line_mesh_as_the_outline(workdir, capsys):
    """An outline drawn as line cells (as Gmsh writes a 1-D mesh) meshes with -p."""
    square = np.array([[0, 0], [2, 0], [2, 1], [0, 1.0]])
    lines = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])
    m = meshio.Mesh(np.column_stack([square, np.zeros(4)]), [("line", lines)],
                    cell_data={"gmsh:physical": [np.array([1, 2, 3, 4])], "gmsh:geometrical": [np.arange(1, 5)]})
    meshio.write("outline.msh", m, file_format="gmsh22", binary=True)
    assert cli.main(["-pq30a0.05", "outline.msh"]) == 0
    out = capsys.readouterr().out
    assert "Writing outline.1.node." in out and "Writing outline.1.poly." in out
    mesh = ruppert_io.read("outline.1")
    pslg = {"vertices": square, "segments": lines, "segment_markers": np.array([[1], [2], [3], [4]])}
    assert check_mesh(mesh, pslg=pslg, min_angle=30, max_area=0.05) == []
    assert set(mesh["segment_markers"][:, 0].tolist()) == {1, 2, 3, 4}


def test_points_only_are_a_point_set(workdir, capsys):
    rng = np.random.default_rng(3)
    xy = rng.random((30, 2))
    meshio.write("cloud.vtu", meshio.Mesh(np.column_stack([xy, np.zeros(30)]), [("vertex", np.arange(30).reshape(-1, 1))]))
    assert cli.main(["-Q", "cloud.vtu"]) == 0
    mesh = ruppert_io.read("cloud.1")
    assert np.array_equal(mesh["vertices"], xy)
    assert check_mesh(mesh, pslg={"vertices": xy}) == []


@pytest.mark.parametrize(
    "argv, fragment",
    [
        (["-r", "cloud.vtu"], "has no triangles to refine"),
        (["-p", "quads.vtu"], "'quad'"),
        (["-p", "junk.vtu"], "Cannot read junk.vtu"),
        (["-p", "missing.vtu"], "Cannot access file missing.vtu.poly."),  # Triangle's rule: no such file
    ],
)
def test_bad_meshio_inputs(argv, fragment, workdir, capsys):
    square = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.0]])
    meshio.write("cloud.vtu", meshio.Mesh(square, [("vertex", np.arange(4).reshape(-1, 1))]))
    meshio.write("quads.vtu", meshio.Mesh(square, [("quad", np.array([[0, 1, 2, 3]]))]))
    (workdir / "junk.vtu").write_text("not xml\n")
    assert cli.main(argv) == 1
    [line] = _errors(capsys)
    assert line.startswith("Error:  ") and fragment in line
