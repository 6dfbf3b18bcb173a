"""A subsegment split at an existing vertex that lies on it within rounding
(splits._split_at_apex) leaves a Delaunay mesh: the flip that puts the vertex
on the segment is refused where its new edge would not be locally Delaunay
(an ordinary split is made instead), and is followed by Lawson's flips around
the vertex (cavity.legalize_fan; regressions/near-collinear-chain-apex-flip-
far-edge.json is the case that needs them).

The input is a campaign case (seed 2701, crossing segments with vertices
within 2.6e-17 of other segments) scaled to unit size: one Steiner point
(S5: the four crossings use four) split the segment 22-23 at input vertex 20
and left edge {3, 27} not locally Delaunay."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import instrument
from instrument.check import check_mesh

CASE = Path(__file__).parents[1] / "differential" / "regressions" / "split-at-vertex-not-delaunay.json"


def _input(scale_exponent: int) -> dict:
    d = json.loads(CASE.read_text())["input"]
    xy = np.array([float.fromhex(h) for h in d["vertices"]["hex"]]).reshape(-1, 2)
    segs = np.array(d["segments"]["int"]).reshape(-1, 2)
    return {"vertices": np.ldexp(xy, scale_exponent), "segments": segs}


@pytest.mark.parametrize("switches", ["pq5cS5Q", "pq5cQ", "pqcQ", "pq5cAQ"])
@pytest.mark.parametrize("scale_exponent", [0, 664])
def test_split_at_vertex_keeps_the_mesh_delaunay(switches, scale_exponent):
    tri = _input(scale_exponent)
    result = instrument.triangulate(tri, switches)
    assert check_mesh(result, pslg=tri) == []
    if switches == "pq5cS5Q":
        assert len(result["vertices"]) == 29  # 24 input, 4 crossings, the one Steiner point



# a split at an apex with Lawson's flips after it (near-collinear-chain-apex-flip-far-edge.json had one
# until the first subsegment splits took Triangle's records, which changed its refinement's order)
FLIPS_AFTER = Path(__file__).parents[1] / "differential" / "regressions" / "near-collinear-chain-apex-flips-halves.json"

HALVES_DRIVER = r"""
import json, sys
from instrument import purepython
from instrument.counters import C_FLIP
from instrument.core.mesh import NO_SEG
from instrument.refine import splits
from tests.differential.cases import Case
import instrument
assert not purepython.is_compiled(splits)
checked, flips = [], []
check = splits.check_subsegment
def spy(r, m, e):
    checked.append((int(e), bool(e >= 0 and m.seg[e] != NO_SEG)))
    return check(r, m, e)
splits.check_subsegment = spy
split_at_apex = splits._split_at_apex
def counted(r, m, segs, e, f, triangles):
    before, n = m.work[C_FLIP], len(checked)
    status = split_at_apex(r, m, segs, e, f, triangles)
    flips.append((int(m.work[C_FLIP] - before), checked[n:]))
    return status
splits._split_at_apex = counted
case = Case.from_json(json.load(open(sys.argv[1])))
instrument.triangulate(case.input, case.switches)
print(json.dumps(flips))
"""


def test_split_at_vertex_with_flips_pools_its_halves():
    """After Lawson's flips around the vertex (legalize_fan) the split finds
    its halves again by their ends, c -> u and w -> c: u was read as the
    origin of c -> u (c itself), find_edge(c, c) gave -1, and the half was
    pooled as edge -1 (a read before the arrays: a segmentation fault in
    chains refined to 165,000 vertices under pucQ).  Run as Python, where
    the calls can be watched."""
    env = dict(os.environ, RUPPERT_PURE_PYTHON="1")
    done = subprocess.run([sys.executable, "-c", HALVES_DRIVER, str(FLIPS_AFTER)], env=env, cwd=Path(__file__).parents[2],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    splits = json.loads(done.stdout.strip().splitlines()[-1])
    with_flips = [checked for flips, checked in splits if flips > 1]  # the flip o d -> c y, then legalize_fan's
    assert with_flips
    for checked in with_flips:
        assert all(e >= 0 and is_subsegment for e, is_subsegment in checked[-2:]), checked
