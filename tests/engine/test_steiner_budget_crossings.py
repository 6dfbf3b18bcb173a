"""-S counts the vertices where segments cross, as Triangle does.

The five-pointed star (a pentagram drawn as five crossing segments) has
five crossing vertices; under pa0.0086S<n> Triangle adds max(0, n - 5)
refinement vertices (counts read off the `triangle` package 20250106):
the crossings are never refused, they only use up the budget.
"""

from __future__ import annotations

import numpy as np
import pytest

import instrument
from instrument.check import check_mesh

STAR = {
    "vertices": np.array([[1.0, 0.5], [0.75, 1.0], [0.09375, 0.75], [0.09375, 0.1875], [0.75, 0.0234375]]),
    "segments": np.array([[0, 2], [1, 3], [2, 4], [3, 0], [4, 1]]),
}


@pytest.mark.parametrize("budget, vertices", [(0, 10), (3, 10), (5, 10), (6, 11), (7, 12), (8, 13)])
def test_crossings_use_up_the_budget(budget, vertices):
    r = instrument.triangulate(STAR, f"pa0.0086S{budget}Q")
    assert check_mesh(r, pslg=STAR) == []
    assert len(r["vertices"]) == vertices


def test_without_budget_the_area_bound_is_met():
    r = instrument.triangulate(STAR, "pa0.0086Q")
    assert check_mesh(r, pslg=STAR, max_area=0.0086) == []
    assert len(r["vertices"]) > 13
