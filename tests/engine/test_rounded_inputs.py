"""Meshing inputs whose vertices lie on segments up to rounding (issue 18, item 3).

A mesh written out and read back (``ruppert -pq30 y.poly && ruppert -q
y.1.node``) has vertices that were split points: within a unit in the last
place of the line they were split from, not on it.  Refining the point set
makes its convex hull the boundary; a hull edge that passes next to such a
vertex is encroached by it, and splitting the edge anywhere but at the
vertex lands a split point on it or next to it (a division by zero, or
"Ran out of precision"; Triangle crashes).  The engine splits at the vertex.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import instrument
import ruppert_io
from instrument.check import check_mesh, quality_report

# the shared corpus beside the checkout, or where RUPPERT_CORPUS says
CORPUS = Path(os.environ.get("RUPPERT_CORPUS", Path(__file__).resolve().parents[3] / "shared" / "corpus"))
Y_POLY = "mr-jstar__jfem__y.poly"
TRIMESH_POLY = "whtsao__Potential-Flow-Problem__trimesh.poly"
KEYS = ("vertices", "vertex_markers", "segments", "segment_markers", "holes", "regions")


def _corpus(name: str) -> dict:
    if not (CORPUS / name).is_file():
        pytest.skip("needs the shared corpus beside the checkout")
    return {k: v for k, v in ruppert_io.read(CORPUS / name).items() if k in KEYS and np.size(v)}


def _written_and_read(mesh, tmp_path: Path) -> dict:
    """The vertices of ``mesh`` after a round trip through a .node file."""
    ruppert_io.write(tmp_path / "m.1", mesh)
    return {"vertices": ruppert_io.read(tmp_path / "m.1.node")["vertices"]}


def _min_angle(opts: str) -> float:
    q = opts.split("q")[1]
    digits = ""
    for ch in q:
        if not (ch.isdigit() or ch == "."):
            break
        digits += ch
    return float(digits) if digits else 20.0


@pytest.mark.parametrize(("name", "first"), [(Y_POLY, "pq30"), (TRIMESH_POLY, "pq30"), (TRIMESH_POLY, "p"), (TRIMESH_POLY, "pq")])
@pytest.mark.parametrize("opts", ["q", "cq30", "qa0.1", "q30"])
def test_refining_a_written_mesh_as_a_point_set(tmp_path, name, first, opts):
    points = _written_and_read(instrument.triangulate(_corpus(name), first), tmp_path)
    r = instrument.triangulate(points, opts)
    # with c the hull is in the output as segments: the checker then knows
    # which small angles the hull's corners explain
    hull = instrument.triangulate(points, "c" + opts.replace("c", ""))
    assert check_mesh(r) == []
    assert check_mesh(hull, min_angle=_min_angle(opts)) == []
    assert quality_report(hull)["n_triangles"] == len(hull["triangles"])


def test_split_at_a_vertex_next_to_a_hull_edge():
    """A vertex 1e-17 inside the hull edge (0,0)-(1,0), at its midpoint:
    the hull edge is split at that vertex, not at (0.5, 0) next to it."""
    points = {"vertices": [[0, 0], [1, 0], [0.5, 1e-17], [0.5, 0.8], [0.1, 0.4], [0.9, 0.4]]}
    for opts in ("q", "cq30", "qa0.01"):
        r = instrument.triangulate(points, opts)
        assert check_mesh(r) == []
        v = np.asarray(r["vertices"])
        # no vertex was made next to the one on the edge
        near = np.hypot(v[:, 0] - 0.5, v[:, 1]) < 1e-9
        assert near.sum() == 1


def test_the_command_lines_of_the_issue(tmp_path):
    y = CORPUS / Y_POLY
    if not y.is_file():
        pytest.skip("needs the shared corpus beside the checkout")
    (tmp_path / "y.poly").write_text(y.read_text())
    run = lambda *a: subprocess.run([sys.executable, "-m", "ruppert_io.cli", *a], cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert run("-pq30", "y.poly").returncode == 0
    for opts in ("-q", "-cq30", "-qa0.1"):
        done = run(opts, "y.1.node")
        assert done.returncode == 0, done.stdout[-500:] + done.stderr[-500:]
        assert "Error" not in done.stdout + done.stderr


def test_split_at_a_vertex_next_to_an_interior_segment():
    """-rp: the segment (0.2, 0.5)-(0.8, 0.5) has a triangle on each side;
    the apex above it is one unit in the last place off its midpoint.  The
    split flips the sliver away (before: 101 vertices piled up at the
    midpoint under rpq, and rpq30 did not finish)."""
    c = [0.5, float(np.nextafter(0.5, 1.0))]
    d = {
        "vertices": [[0, 0], [1, 0], [1, 1], [0, 1], [0.2, 0.5], [0.8, 0.5], c],
        "triangles": [[5, 4, 0], [1, 5, 0], [1, 2, 5], [0, 4, 3], [4, 5, 6], [4, 6, 3], [6, 5, 2], [6, 2, 3]],
        "segments": [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5]],
    }
    pslg = {"vertices": d["vertices"], "segments": d["segments"]}
    for opts in ("rpq", "rpq30", "rpqa0.01"):
        r = instrument.triangulate(d, opts)
        assert check_mesh(r, pslg, min_angle=_min_angle(opts)) == []
        v = np.asarray(r["vertices"])
        assert (np.hypot(v[:, 0] - 0.5, v[:, 1] - 0.5) < 1e-9).sum() == 1
