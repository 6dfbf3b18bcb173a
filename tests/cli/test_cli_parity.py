"""The command line's share of issue 18: --version, Triangle's headers for
empty files, six-node output (-o2) read back by the `triangle` package and
meshio, and clear limits (switch values out of range, the vertex limit, the
angle warning, the progress display on a terminal)."""

from __future__ import annotations

import io
import os
import pty
import select
import subprocess
import sys
import time
from importlib.metadata import version
from pathlib import Path

import meshio
import numpy as np
import pytest
import triangle

import instrument
import ruppert_io
from instrument.check import check_mesh
from ruppert_io import cli

RUPPERT = Path(sys.executable).with_name("ruppert")


def error_line(capsys, rc: int) -> str:
    err = capsys.readouterr().err
    assert rc == 1, err
    lines = [line for line in err.splitlines() if line.startswith("Error:")]
    assert len(lines) == 1 and "Traceback" not in err, err
    return lines[0]


def test_version(capsys):
    assert cli.main(["--version"]) == 0
    assert capsys.readouterr().out == f"ruppert {version('ruppert')}\n"
    assert instrument.__version__ == version("ruppert")


# --------------------------------------------------------------------------
# Empty meshes: Triangle's headers declare the marker column unless -B


EATEN = """4 2 0 0
1 0 0
2 1 0
3 1 1
4 0 1
0 0
1
1 0.5 0.5
"""


@pytest.mark.parametrize(("switches", "marks"), [("-penQ", "1"), ("-penQB", "0")])
def test_empty_mesh_headers(workdir, switches, marks):
    (workdir / "eaten.poly").write_text(EATEN)
    assert cli.main([switches, "eaten.poly"]) == 0
    assert (workdir / "eaten.1.edge").read_text().splitlines()[0] == f"0  {marks}"
    poly = (workdir / "eaten.1.poly").read_text().splitlines()
    assert poly[0] == f"0  2  0  {marks}" and poly[1] == f"0  {marks}"
    assert (workdir / "eaten.1.ele").read_text().splitlines()[0] == "0  3  0"


# --------------------------------------------------------------------------
# -o2


def test_o2_files(workdir, capsys):
    assert cli.main(["-pq30o2", "A.poly"]) == 0
    out = capsys.readouterr().out
    assert "Adding vertices for second-order triangles." in out
    assert "  Mesh vertices: 239\n" in out and "  Mesh triangles: 87\n" in out
    node = (workdir / "A.1.node").read_text().splitlines()
    ele = (workdir / "A.1.ele").read_text().splitlines()
    assert node[0] == "239  2  1  1" and ele[0] == "87  6  0"
    assert len(ele[1].split()) == 7
    ours = instrument.triangulate(ruppert_io.read(workdir / "A.poly"), "pq30o2")
    # the triangle package's reader reads our files, and ours reads them the same
    for loaded in (triangle.load(str(workdir), "A.1"), ruppert_io.read(workdir / "A.1")):
        for key in ("vertices", "vertex_attributes", "vertex_markers", "triangles", "segments"):
            np.testing.assert_array_equal(np.asarray(loaded[key]).reshape(np.shape(ours[key])), ours[key], err_msg=key)
    assert check_mesh(ruppert_io.read(workdir / "A.1"), ruppert_io.read(workdir / "A.poly"), min_angle=30) == []


def test_o2_refined_again(workdir):
    assert cli.main(["-pq30o2Q", "A.poly"]) == 0
    assert cli.main(["-rq30a0.002o2Q", "A.1"]) == 0
    mesh = ruppert_io.read(workdir / "A.2")
    assert mesh["triangles"].shape[1] == 6
    assert check_mesh(mesh, min_angle=30, max_area=0.002) == []
    theirs = triangle.triangulate(
        {k: ruppert_io.read(workdir / "A.1")[k] for k in ("vertices", "vertex_markers", "vertex_attributes", "triangles")},
        "rq30a0.002o2",
    )
    assert len(mesh["vertices"]) == pytest.approx(len(theirs["vertices"]), rel=0.1)


def test_o2_through_meshio(workdir):
    """-o2 --format vtu writes VTK's quadratic triangles (meshio's triangle6):
    corners, then the midpoints of edges 01, 12, 20."""
    assert cli.main(["-pq30o2Q", "A.poly", "--format", "vtu"]) == 0
    m = meshio.read(workdir / "A.1.vtu")
    cells = m.cells_dict["triangle6"]
    assert cells.shape == (87, 6)
    p = m.points[:, :2]
    np.testing.assert_array_equal(p[cells[:, 3]], 0.5 * (p[cells[:, 0]] + p[cells[:, 1]]))
    np.testing.assert_array_equal(p[cells[:, 4]], 0.5 * (p[cells[:, 1]] + p[cells[:, 2]]))
    assert meshio.read(workdir / "A.1.node").cells_dict["triangle6"].shape == (87, 6)


# --------------------------------------------------------------------------
# Limits


@pytest.mark.parametrize(
    ("switches", "fragment"),
    [
        ("-pq1e400", "Minimum angle 1e400 is out of range"),
        ("-pa1e400", "Maximum area 1e400 is out of range"),
        ("-pq30a1e-30", "needs about"),
        ("-pa1e-400", "Maximum area must be greater than zero"),
    ],
)
def test_out_of_range_values(workdir, capsys, switches, fragment):
    line = error_line(capsys, cli.main([switches, "A.poly"]))
    assert fragment in line


def test_area_beyond_the_limit_fails_before_refining(workdir, capsys):
    line = error_line(capsys, cli.main(["-pq30a1e-30", "A.poly"]))
    assert "more than the limit of" in line and "--max-vertices" in line
    assert not (workdir / "A.1.node").exists()


def test_vertex_limit(workdir, capsys):
    rc = cli.main(["-pq40", "A.poly", "--max-vertices", "20000"])
    err = capsys.readouterr().err
    assert rc == 1
    lines = err.splitlines()
    assert lines[0].startswith("Warning:  A minimum angle of 40 degrees is above 34")
    assert lines[-1].startswith("Error:  Refinement stopped at ") and "(limit 20,000" in lines[-1]
    assert "use -S, a smaller angle, or --max-vertices" in lines[-1]
    assert not (workdir / "A.1.node").exists()


def test_quiet_keeps_the_error_only(workdir, capsys):
    rc = cli.main(["-pq40Q", "A.poly", "--max-vertices", "20000"])
    err = capsys.readouterr().err
    assert rc == 1 and err.splitlines() == [err.splitlines()[-1]] and err.startswith("Error:")


@pytest.mark.parametrize("value", ["0", "-5", "many"])
def test_bad_max_vertices(workdir, capsys, value):
    line = error_line(capsys, cli.main(["-pq30", "A.poly", f"--max-vertices={value}"]))
    assert "--max-vertices" in line


def test_no_warning_up_to_34_degrees(workdir, capsys):
    assert cli.main(["-pq34", "A.poly"]) == 0
    assert "Warning" not in capsys.readouterr().err
    mesh = ruppert_io.read(workdir / "A.1")
    assert check_mesh(mesh, ruppert_io.read(workdir / "A.poly"), min_angle=34) == []


def test_steiner_budget_still_ends_a_steep_angle(workdir, capsys):
    assert cli.main(["-pq40S200", "A.poly"]) == 0
    assert "Warning:  A minimum angle of 40" in capsys.readouterr().err
    mesh = ruppert_io.read(workdir / "A.1")
    assert len(mesh["vertices"]) <= 29 + 200
    assert check_mesh(mesh, ruppert_io.read(workdir / "A.poly")) == []


# --------------------------------------------------------------------------
# Progress on a terminal


class FakeTerminal(io.StringIO):
    def isatty(self) -> bool:
        return True


@pytest.mark.parametrize(("tty", "extra", "shown"), [(True, [], True), (True, ["-Q"], False), (False, [], False)])
def test_progress_shows_on_a_terminal_only(workdir, monkeypatch, tty, extra, shown):
    err = FakeTerminal() if tty else io.StringIO()
    monkeypatch.setattr(sys, "stderr", err)
    monkeypatch.setattr(cli, "PROGRESS_AFTER", 0.0)
    assert cli.main(["-pq30a0.0005", *extra, "A.poly"]) == 0
    assert ("Refining:" in err.getvalue()) == shown


def test_progress_appears_by_itself_in_a_real_terminal(tmp_path):
    """A run of a few seconds on a pseudo-terminal shows the display unasked.
    The limit keeps refinement well past PROGRESS_AFTER even on a fast machine
    (700,000 vertices took under a second on CI; 2.5 million take about 4 s
    and 1 GB here)."""
    (tmp_path / "A.poly").write_bytes((Path(triangle.__file__).parent / "data" / "A.poly").read_bytes())
    main, side = pty.openpty()
    proc = subprocess.Popen(
        [str(RUPPERT), "-pq40", "A.poly", "--max-vertices", "2500000"],
        cwd=tmp_path,
        stdin=subprocess.DEVNULL,
        stdout=subprocess.DEVNULL,
        stderr=side,
        env={**os.environ, "TERM": "xterm"},
    )
    os.close(side)
    seen = b""
    deadline = time.monotonic() + 300
    while time.monotonic() < deadline:
        ready, _, _ = select.select([main], [], [], 1.0)
        if ready:
            try:
                chunk = os.read(main, 65536)
            except OSError:  # the other side closed
                break
            if not chunk:
                break
            seen += chunk
        elif proc.poll() is not None:
            break
    proc.wait(timeout=60)
    os.close(main)
    text = seen.decode(errors="replace")
    assert proc.returncode == 1
    assert "Refining:" in text and "(limit 2,500,000)" in text
    assert "Error:  Refinement stopped at" in text
