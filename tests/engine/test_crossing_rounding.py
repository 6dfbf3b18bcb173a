"""Crossing points of segments are the exact intersections rounded once.

Crossing segments in the unit square with endpoints at x ~1e-269 and
~1e-110 (tests/differential/regressions/tiny-endpoints-enclosure.json)
enclosed another domain: vertex 14 lies 2.1e-17 to the left of segment 8;
segment 8 first crosses segment 4 at a vertex computed as r + t (l - r),
whose error (t's error times the crossed segment's length, ~1e-16) tilted
the piece so that vertex 14 fell on its other side; segment 8 was then bent
through vertex 14, which closed a 2e-17 gap between the region and the
outside (total area 0.049 against Triangle's 0.0072).  crossing.py rounds
the exact intersection once per coordinate, which keeps vertex 14 on its
side and the gap open.
"""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
import triangle

import instrument
from instrument.check import check_mesh, mesh_area
from instrument.segments.crossing import crossing_point

CASE = Path(__file__).parents[1] / "differential" / "regressions" / "tiny-endpoints-enclosure.json"


def _exact(ax, ay, bx, by, rx, ry, lx, ly):
    ax, ay, bx, by, rx, ry, lx, ly = map(Fraction, (ax, ay, bx, by, rx, ry, lx, ly))
    den = (ly - ry) * (bx - ax) - (lx - rx) * (by - ay)
    t = min(max(((by - ay) * (rx - ax) - (bx - ax) * (ry - ay)) / den, Fraction(0)), Fraction(1))
    return float(rx + t * (lx - rx)), float(ry + t * (ly - ry))


def _crossings(n, seed):
    rng = np.random.default_rng(seed)
    for k in range(n):
        s = 2.0 ** int(rng.integers(-700, 700)) if k % 3 == 0 else 1.0
        r, l = rng.uniform(-1, 1, 2), rng.uniform(-1, 1, 2)
        x = r + rng.uniform(0.001, 0.999) * (l - r)
        d = rng.uniform(-1, 1, 2)
        if k % 5 == 1:  # nearly parallel: the filter cannot certify, exact arithmetic decides
            d = (l - r) * (1 + 1e-12 * rng.uniform(-1, 1, 2))
        if k % 7 == 2:  # the crossed segment from the origin's neighbourhood (~1e-200)
            r = r * 1e-200
            x = r + rng.uniform(0.001, 0.999) * (l - r)
        if k % 11 == 3:  # the line misses the segment: t clamped to an end
            x = l + (l - r) * rng.uniform(0.01, 1)
        yield (np.r_[x - d * rng.uniform(0.1, 1), x + d * rng.uniform(0.1, 1), r, l] * s).tolist()


@pytest.mark.parametrize("seed", [1, 2])
def test_crossing_point_is_correctly_rounded(seed):
    for c in _crossings(1500, seed):
        assert crossing_point(*c) == _exact(*c), c


def _read_case():
    d = json.loads(CASE.read_text())
    v = np.array([float.fromhex(h) for h in d["input"]["vertices"]["hex"]]).reshape(d["input"]["vertices"]["shape"])
    s = np.array(d["input"]["segments"]["int"]).reshape(d["input"]["segments"]["shape"])
    return {"vertices": v, "segments": s}, d["switches"]


@pytest.mark.parametrize("switches", ["pQ", None])
def test_tiny_endpoints_keep_the_gap(switches):
    pslg, case_switches = _read_case()
    switches = switches or case_switches
    ours = instrument.triangulate(pslg, switches)
    assert check_mesh(ours, pslg=pslg, min_angle=20 if "q" in switches else None) == []
    theirs = triangle.triangulate(pslg, switches)
    assert mesh_area(ours) == pytest.approx(mesh_area(theirs), rel=1e-9)
    assert mesh_area(ours) < 0.01  # 0.049 when the gap was closed
