"""``ruppert -r``: refining a mesh read from .node/.ele (+ .poly, + .area) files."""

from __future__ import annotations

import re

import numpy as np
import pytest
import triangle

import ruppert_io
from instrument.check import check_mesh
from ruppert_io import cli


def stat(out: str, label: str) -> int:
    return int(re.search(rf"^  {re.escape(label)}: (\d+)$", out, re.MULTILINE).group(1))


def one_error(capsys, rc: int) -> str:
    err = capsys.readouterr().err
    assert rc == 1
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("Error:"), err
    return lines[0]


def areas(m: dict) -> np.ndarray:
    p = np.asarray(m["vertices"])[np.asarray(m["triangles"])[:, :3]]
    u, v = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    return 0.5 * (u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])


def first_mesh(workdir, capsys) -> dict:
    assert cli.main(["-Q", "-pq30", "A.poly"]) == 0
    capsys.readouterr()
    return ruppert_io.read(workdir / "A.1")


def test_refine_A_after_pq30(workdir, capsys):
    a1 = first_mesh(workdir, capsys)
    assert cli.main(["-rq30a0.5", "A.1"]) == 0
    out = capsys.readouterr().out
    assert "Opening A.1.node.\nOpening A.1.ele.\nReconstructing mesh.\n" in out
    assert "Writing A.2.node.\nWriting A.2.ele.\n" in out
    assert not (workdir / "A.2.poly").exists()  # no -p, no -c: no .poly
    assert stat(out, "Input triangles") == len(a1["triangles"])
    a2 = ruppert_io.read(workdir / "A.2")
    assert check_mesh(a2, min_angle=30) == []
    # the A.1 mesh is already fine at 30 degrees and area 0.5: nothing changes
    np.testing.assert_array_equal(a2["triangles"], a1["triangles"])
    assert stat(out, "Mesh subsegments (constrained edges)") == stat(out, "Mesh exterior boundary edges")


def test_refine_further_matches_triangle(workdir, capsys):
    a1 = first_mesh(workdir, capsys)
    assert cli.main(["-Q", "-rpq30a0.001", "A.1"]) == 0
    a2 = ruppert_io.read(workdir / "A.2")
    assert (workdir / "A.2.poly").is_file()
    assert check_mesh(a2, min_angle=30, max_area=0.001) == []
    given = {k: a1[k] for k in ("vertices", "vertex_markers", "triangles", "segments", "segment_markers", "holes")}
    theirs = triangle.triangulate(given, "rpq30a0.001")
    assert abs(len(a2["vertices"]) - len(theirs["vertices"])) <= max(3, 0.02 * len(theirs["vertices"]))
    # and once more, from A.2 to A.3
    assert cli.main(["-Q", "-rq33", "A.2.ele"]) == 0
    assert check_mesh(ruppert_io.read(workdir / "A.3"), min_angle=33) == []


def test_area_file(workdir, capsys):
    a1 = first_mesh(workdir, capsys)
    n = len(a1["triangles"])
    bound = np.where(np.arange(n) % 2, 2e-4, -1.0)
    lines = [f"{n}"] + [f"{i + 1}  {b:.17g}" for i, b in enumerate(bound)]
    (workdir / "A.1.area").write_text("\n".join(lines) + "\n")
    assert cli.main(["-Q", "A.1.area"]) == 0  # .area turns on -r and a bare -a
    a2 = ruppert_io.read(workdir / "A.2")
    assert check_mesh(a2) == []
    assert len(a2["vertices"]) > len(a1["vertices"])
    (workdir / "A.1.area").write_text("\n".join([f"{n - 1}", *lines[1:-1]]) + "\n")
    line = one_error(capsys, cli.main(["-ra", "A.1"]))
    assert "disagree on number of triangles" in line


def test_r_with_I_is_an_error(workdir, capsys):
    first_mesh(workdir, capsys)
    line = one_error(capsys, cli.main(["-rI", "A.1"]))
    assert line == "Error:  You cannot use the -I switch when refining a triangulation."
    assert not (workdir / "A.2.node").exists()


def test_bad_meshes_are_one_error_line(workdir, capsys):
    first_mesh(workdir, capsys)
    ele = (workdir / "A.1.ele").read_text().splitlines()
    # list the first triangle's corners clockwise
    num, a, b, c = ele[1].split()[:4]
    ele[1] = f"{num}  {a}  {c}  {b}"
    (workdir / "A.1.ele").write_text("\n".join(ele) + "\n")
    line = one_error(capsys, cli.main(["-rq", "A.1"]))
    assert "triangle 0 is clockwise" in line
    # -rp: a segment with an invalid index is an error, not a warning
    first_mesh(workdir, capsys)
    poly = (workdir / "A.1.poly").read_text().splitlines()
    fields = poly[2].split()
    poly[2] = f"{fields[0]}  9999  {fields[2]}  {fields[3]}"
    (workdir / "A.1.poly").write_text("\n".join(poly) + "\n")
    line = one_error(capsys, cli.main(["-rp", "A.1"]))
    assert line == "Error:  Segment 1 has an invalid vertex index."


def test_segments_off_the_mesh_are_warned_about(workdir, capsys):
    first_mesh(workdir, capsys)
    poly = (workdir / "A.1.poly").read_text().splitlines()
    nseg = int(poly[1].split()[0])
    # a segment from the first vertex to the last one: not an edge
    nvert = int((workdir / "A.1.node").read_text().split()[0])
    poly[1] = f"{nseg + 1}  1"
    poly.insert(2 + nseg, f"{nseg + 1}  1  {nvert}  7")
    (workdir / "A.1.poly").write_text("\n".join(poly) + "\n")
    assert cli.main(["-rp", "A.1"]) == 0
    err = capsys.readouterr().err
    assert re.search(r"Warning:  Segment \d+ (is not an edge of the mesh|does not lie in the mesh)", err), err
    assert check_mesh(ruppert_io.read(workdir / "A.2")) == []


@pytest.mark.parametrize("switches", ["-r", "-rq", "-rpq30", "-rc", "-rqDj", "-ra0.01Y", "-rS5q"])
def test_switch_combinations(workdir, capsys, switches):
    first_mesh(workdir, capsys)
    assert cli.main(["-Q", switches, "A.1"]) == 0
    a2 = ruppert_io.read(workdir / "A.2")
    assert check_mesh(a2) == []
    assert (workdir / "A.2.poly").exists() == ("p" in switches or "c" in switches)
