"""scripts/denormal_family.py: its draws, and ours on a few of them.

The family is the campaign's denormal-walk-timeout made many times (points
with coordinates 2^-1022, subnormals and 2^-149 beside ones near 1).  Each
draw must end with a mesh the exact checker passes under the angle bound or
with a clear error: ``PrecisionError`` where a shortest edge is too short
beside its coordinates for any point off it, or ``SizeLimitError`` where
refinement goes on (small input angles; bounded here by ``max_vertices`` so
that the test stays fast).
"""

from __future__ import annotations

import numpy as np
import pytest

import instrument
from instrument.refine import PrecisionError

from scripthelpers import load_script

family = load_script("denormal_family")


def test_draws_are_reproducible_and_mix_tiny_coordinates():
    a = [family.draw(np.random.default_rng(7)) for _ in range(3)]
    b = [family.draw(np.random.default_rng(7)) for _ in range(3)]
    for x, y in zip(a, b):
        assert x.switches == y.switches
        assert np.array_equal(x.input["vertices"], y.input["vertices"])
    rng = np.random.default_rng(1)
    cases = [family.draw(rng) for _ in range(40)]
    v = np.concatenate([c.input["vertices"] for c in cases])
    assert (np.abs(v[v != 0]) < 2.0**-1021).any()  # subnormals
    assert any("segments" in c.input for c in cases) and any("segments" not in c.input for c in cases)


@pytest.mark.parametrize("seed", [1, 3])  # (seed 2 starts with known.py's denormal-deletion-cycles)
def test_ours_meshes_or_stops_clearly(seed):
    rng = np.random.default_rng(seed)
    for _ in range(8):
        case = family.draw(rng)
        try:
            out = instrument.triangulate(case.input, case.switches, max_vertices=20_000)
        except (PrecisionError, instrument.SizeLimitError):
            continue
        assert family.mesh_problems(case, out) == [], case.describe()
