"""Quality refinement far from unit scale (issue 18, item 8).

The bad-triangle test's cos^2 of the smallest angle is of degree 4 over
degree 4, the circumcenter of degree 3 over 2: with edges beyond about 2^256
(or below 2^-256) the products overflowed or underflowed, every triangle
looked perfect and ``pq30`` left 26-degree angles at 2^300 and 2^-300.
criteria.py now scales those computations by an exact power of two where
the edges call for it (and leaves ordinary magnitudes untouched).
"""

from __future__ import annotations

import numpy as np
import pytest

import instrument
from instrument.check import check_mesh

POINTS = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.3, 0.6]])
SIDES = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])


@pytest.mark.parametrize("exponent", [-520, -400, -300, 0, 300, 400, 510])
def test_minimum_angle_met_at_any_scale(exponent):
    pslg = {"vertices": POINTS * 2.0**exponent, "segments": SIDES}
    result = instrument.triangulate(pslg, "pq30Q")
    assert check_mesh(result, pslg=pslg, min_angle=30) == []
    assert len(result["vertices"]) > 5


@pytest.mark.parametrize("exponent", [-400, 300, 500])
def test_area_bound_met_at_any_scale(exponent):
    s = 2.0**exponent
    pslg = {"vertices": POINTS * s, "segments": SIDES}
    bound = 0.01 * s * s
    result = instrument.triangulate(pslg, f"pq30a{bound!r}Q")
    assert check_mesh(result, pslg=pslg, min_angle=30, max_area=bound) == []
