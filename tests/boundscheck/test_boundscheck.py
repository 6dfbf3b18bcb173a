"""Meshing paths under a bounds-checked build of the engine.

Kernels run without bounds checks, so an out-of-range write would corrupt
the heap silently; here the same kernels, built with checks
(checked_build.py), run the paths where per-triangle and per-vertex tables
matter most (regions, attributes, area bounds, ``-r`` with bounds, growth
during refinement) and every out-of-range index fails the test.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import triangle

from checked_build import checked_tree
from tests.differential.cases import decode_input

HERE = Path(__file__).resolve().parent
REGRESSIONS = HERE.parent / "differential" / "regressions"

SQUARE = {"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]], "segments": [[0, 1], [1, 2], [2, 3], [3, 0]]}
TWO_REGIONS = {
    "vertices": [[0, 0], [1, 0], [2, 0], [2, 1], [1, 1], [0, 1]],
    "segments": [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0], [1, 4]],
    "regions": [[0.5, 0.5, 1.0, 0.01], [1.5, 0.5, 2.0, 0.05]],
}


def _package(name: str, keys=None) -> dict:
    d = triangle.get_data(name)
    return {k: v.tolist() for k, v in d.items() if len(v) and (keys is None or k in keys)}


def _cases() -> list[dict]:
    mesh_keys = ("vertices", "vertex_markers", "triangles", "triangle_max_area", "segments", "segment_markers")
    cases = [
        {"input": dict(SQUARE, regions=[[0.5, 0.5, 7.0, 0.0]]), "opts": "pAa0.01"},
        {"input": dict(SQUARE, regions=[[0.5, 0.5, 7.0, 0.0]]), "opts": "pAa0.01"},  # twice in one process
        {"input": TWO_REGIONS, "opts": "pqAa"},
        {"input": TWO_REGIONS, "opts": "pqAa0.01"},
        {"input": TWO_REGIONS, "opts": "pq30Aa0.003"},
        {"input": _package("la"), "opts": "pq30a0.5a"},
        {"input": _package("A"), "opts": "pq30A"},
        {"input": _package("face"), "opts": "pq30D"},
        {"input": _package("dots"), "opts": "q30"},
        {"input": _package("bbox.1", mesh_keys), "opts": "rpaa.5"},
        {"input": _package("bbox.1", mesh_keys), "opts": "rpa"},
        {"input": _package("spiral.1"), "opts": "rq30"},
        {"input": _package("box.2"), "opts": "rpq30a0.05"},
    ]
    for strategy in ("worst-angle", "adversary", "random"):
        cases.append({"input": _package("la"), "opts": "pq25", "kwargs": {"strategy": strategy}})
    # 8 points within rounding of a line (campaign seed 2801): under pDc a hull
    # subsegment is split at a chain vertex and the flips after it lost the
    # halves' edges (splits._split_at_apex read the wrong end of one), so the
    # next step wrote through edge -1 and the process segfaulted.  The run may
    # end in a PrecisionError (Triangle does not finish it); it must stay in
    # bounds.
    chain = decode_input(json.loads((REGRESSIONS / "apex-split-flip-lost-halves.json").read_text())["input"])
    cases.append({"input": {k: v.tolist() for k, v in chain.items()},
                  "opts": "pDceviQ", "may_fail": True})
    return cases


def _run_checked(cases: list[dict], timeout: float = 600) -> dict:
    env = dict(os.environ, PYTHONPATH=str(checked_tree()))
    env.pop("RUPPERT_PURE_PYTHON", None)
    proc = subprocess.run(
        [sys.executable, str(HERE / "run_checked.py")], input=json.dumps(cases),
        capture_output=True, text=True, env=env, timeout=timeout, cwd=HERE,
    )
    assert proc.returncode == 0, proc.stderr[-3000:]
    return json.loads(proc.stdout)


def test_meshing_paths_stay_in_bounds():
    cases = _cases()
    out = _run_checked(cases)
    assert out["compiled"]
    problems = [(c["opts"], row) for c, row in zip(cases, out["cases"])
                if row["ignored"] or ("error" in row and not c.get("may_fail"))]
    assert not problems, problems


def test_the_checked_build_catches_an_out_of_range_index():
    """The check itself: a kernel handed a stack too short for its work
    reports the index instead of writing past the end."""
    env = dict(os.environ, PYTHONPATH=str(checked_tree()))
    code = (
        "import sys, numpy as np\n"
        "seen = []\n"
        "sys.unraisablehook = lambda u: seen.append(type(u.exc_value).__name__)\n"
        "from instrument.core.mesh import Mesh\n"
        "from instrument.core.insert import split_triangle, star_edges\n"
        "m = Mesh(np.array([[0., 0.], [1., 0.], [0., 1.], [.2, .2]]), 8)\n"
        "np.asarray(m.corner)[:3] = [0, 1, 2]; np.asarray(m.stamp)[0] = 1; m.nslot = 1; m.nlive = 1\n"
        "t = split_triangle(m, 0, 3)\n"
        "star_edges(m, t, np.zeros(1, dtype=np.int64))\n"
        "print(seen)\n"
    )
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120, cwd=HERE)
    assert proc.returncode == 0, proc.stderr
    assert "IndexError" in proc.stdout, (proc.stdout, proc.stderr)
