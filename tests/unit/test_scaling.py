"""core.scaling's helpers against their definitions in plain Python."""

from __future__ import annotations

import math
import random

import numpy as np

from instrument.core.scaling import half_extent, unit_scale
from instrument.refine import key_unit


def _unit_scale(m: float) -> float:
    """The definition: the power of two f with m f in [0.5, 1), at most 2^1000."""
    if not (m > 0.0 and m <= 1.7976931348623157e308):
        return 1.0
    return math.ldexp(1.0, -max(math.frexp(m)[1], -1000))


def test_unit_scale_is_frexp_and_ldexp_for_every_kind_of_double():
    values = [0.0, -0.0, -1.0, math.inf, -math.inf, math.nan, 5e-324, 2.2250738585072014e-308,
              2.225073858507201e-308, 1.7976931348623157e308, 0.5, 0.75, 1.0]
    for k in range(-1080, 1025):  # every exponent, at both ends of its binade
        for f in (0.5, 0.75, 0.9999999999999999):
            values.append(math.ldexp(f, k))
    rng = random.Random(7)
    values += [rng.random() * 10.0 ** rng.randint(-323, 307) for _ in range(20_000)]
    for v in values:
        assert unit_scale(v) == _unit_scale(v), v


def test_half_extent_and_key_unit():
    rng = np.random.default_rng(3)
    for scale in (1.0, 1e-300, 1e300, 2.0**-600, 2.0**700):
        xy = rng.standard_normal((50, 2)) * scale
        want = max(xy[:, 0].max() / 2 - xy[:, 0].min() / 2, xy[:, 1].max() / 2 - xy[:, 1].min() / 2)
        assert half_extent(xy, 50) == want
        assert half_extent(xy, 1) == 0.0
    assert half_extent(np.zeros((0, 2)), 0) == 0.0
    assert key_unit(np.array([[0.0, 0.0], [1.0, 2.0]])) == 1.0
    assert key_unit(np.zeros((0, 2))) == 1.0
    assert key_unit(np.array([[1e300, 0.0], [-1e300, 5.0]])) == math.ldexp(1.0, -math.frexp(1e300)[1] - 1)
    assert key_unit(np.array([[1e300, 0.0], [-1e300, 5.0], [3e300, 0.0]]), 2) == key_unit(
        np.array([[1e300, 0.0], [-1e300, 5.0]]))
