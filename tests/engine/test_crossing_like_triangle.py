"""Crossing vertices are Triangle's, bit for bit, and keep the scale invariance.

Where an inserted segment crosses a subsegment, Triangle computes the vertex
in doubles along the crossed subsegment, against the end the piece is
scouted from (segments/crossing.py's ``scouted_crossing``).  Ours had
rounded the exact intersection once: the points agreed to 1e-9 but only 19
of the 19-point star's 95 crossings bit for bit, so refinement started from
other vertices.  scripts/crossing_agreement.py measures the agreement over
more inputs; here a few of each kind, under ``pc`` (the whole mesh is then
Triangle's, vertex order and triangles).  Where the double formula is
ill-conditioned or out of range, ours keeps the exact rounding: the inputs
scaled by 2^k still mesh to the scale-1 mesh times 2^k, bit for bit, far
beyond the range where Triangle's products overflow.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
import triangle

import instrument
from instrument.check import check_mesh
from instrument.segments.crossing import crossing_point, scouted_crossing

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
from scripts.crossing_agreement import random_inputs, star_inputs  # noqa: E402

STARS = dict(star_inputs(21))
CASES = [("star19-step6", STARS["star19-step6"]), ("star21-step8", STARS["star21-step8"]),
         ("star11-step3", STARS["star11-step3"])] + list(random_inputs(40, 11, 8))


def _triangles(t):
    return sorted(tuple(sorted(x)) for x in np.asarray(t).tolist())


@pytest.mark.parametrize("name, pslg", CASES, ids=[c[0] for c in CASES])
def test_crossings_are_triangles_bit_for_bit(name, pslg):
    ours = instrument.triangulate(pslg, "pcQ")
    assert check_mesh(ours, pslg=pslg) == []
    theirs = triangle.triangulate(pslg, "pcQ")
    assert np.array_equal(ours["vertices"], theirs["vertices"])
    assert _triangles(ours["triangles"]) == _triangles(theirs["triangles"])


@pytest.mark.parametrize("k", [-1060, -1000, -600, 600, 1000])
@pytest.mark.parametrize("name", ["star19-step6", "random-11-3"])
def test_crossings_scale_by_powers_of_two(name, k):
    pslg = dict(CASES)[name]
    base = instrument.triangulate(pslg, "pcQ")
    scaled = dict(pslg, vertices=np.ldexp(pslg["vertices"], k))
    out = instrument.triangulate(scaled, "pcQ")
    assert check_mesh(out, pslg=scaled) == []
    if k >= -1000:  # coordinates above the subnormal range: an exact copy
        assert np.array_equal(out["vertices"], np.ldexp(base["vertices"], k))
        assert np.array_equal(out["triangles"], base["triangles"])


def test_scouted_crossing_declines_parallel_and_outside():
    # parallel: no t
    assert scouted_crossing(0.0, 0.0, 1.0, 1.0, 0.0, 1.0, 1.0, 2.0)[0] == -1.0
    # the line misses the segment r -> l (t would be 2)
    assert scouted_crossing(0.0, 0.0, 0.0, 1.0, -2.0, 0.5, -1.0, 0.5)[0] == -1.0
    # a plain crossing: near the exact one, t strictly inside
    t, x, y = scouted_crossing(0.1, 0.0, 0.3, 1.0, 1.0, 0.2, -1.0, 0.7)
    px, py = crossing_point(0.1, 0.0, 0.3, 1.0, 1.0, 0.2, -1.0, 0.7)
    assert 0.0 < t < 1.0
    assert abs(x - px) <= 4e-16 and abs(y - py) <= 4e-16


def test_nearly_parallel_crossing_stays_valid():
    # two segments crossing at an angle of 1e-15 inside a square: the double
    # formula is ill-conditioned there, and the mesh must stay valid
    pslg = {"vertices": [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0),
                         (0.1, 0.5 - 4e-16), (0.9, 0.5 + 4e-16), (0.1, 0.5 + 4e-16), (0.9, 0.5 - 4e-16)],
            "segments": [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (6, 7)]}
    for switches in ("pQ", "pq30Q"):
        out = instrument.triangulate(pslg, switches)
        assert check_mesh(out, pslg=pslg, min_angle=30 if "q" in switches else None) == []
