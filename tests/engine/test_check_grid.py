"""The checker's candidate pairs (check/grid.py) against all pairs: every pair
of overlapping boxes is found, at ordinary scales, over hundreds of decades,
and with zero-size and enormous boxes."""

from __future__ import annotations

import numpy as np
import pytest

from instrument.check import grid
from instrument.check.grid import box_pairs


def brute(tbox, ebox):
    t = tbox[:, None, :]
    e = ebox[None, :, :]
    hit = (t[..., 0] <= e[..., 1]) & (e[..., 0] <= t[..., 1]) & (t[..., 2] <= e[..., 3]) & (e[..., 2] <= t[..., 3])
    return set(zip(*np.nonzero(hit)))


def boxes(rng, n, scale_lo, scale_hi):
    """Boxes at random positions and sizes, log-uniform over the given exponents."""
    centre = rng.choice([-1.0, 1.0], size=(n, 2)) * np.ldexp(1.0, rng.integers(scale_lo, scale_hi, size=(n, 2)))
    centre *= rng.random((n, 2))
    half = np.ldexp(rng.random((n, 2)), rng.integers(scale_lo - 5, scale_hi, size=(n, 2)))
    half[rng.random(n) < 0.05] = 0.0  # zero-size boxes (a zero-length edge)
    lo, hi = centre - half, centre + half
    return np.column_stack([lo[:, 0], hi[:, 0], lo[:, 1], hi[:, 1]])


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("scales", [(-3, 3), (-1000, -900), (-600, 600), (-1070, 1020)])
def test_box_pairs_finds_every_overlap(seed, scales):
    rng = np.random.default_rng(seed)
    tbox, ebox = boxes(rng, 300, *scales), boxes(rng, 250, *scales)
    # nested boxes sharing corners: the overlaps a graded mesh has near its finest point
    k = np.arange(1, 60, dtype=float)
    nest = np.column_stack([np.zeros_like(k), np.ldexp(1.0, -k.astype(int) * 8), np.zeros_like(k),
                            np.ldexp(1.0, -k.astype(int) * 8)])
    tbox, ebox = np.concatenate([tbox, nest]), np.concatenate([ebox, nest[::2]])
    pt, pe = box_pairs(tbox, ebox)
    assert set(zip(pt.tolist(), pe.tolist())) == brute(tbox, ebox)


def test_huge_boxes_whose_width_overflows():
    big = np.array([[-1e308, 1e308, -1e308, 1e308], [0.0, 1.0, 0.0, 1.0]])
    small = np.array([[0.5, 0.5, 0.5, 0.5], [1e300, 1.5e300, 0.0, 1.0], [-2.0, -1.0, -2.0, -1.0]])
    pt, pe = box_pairs(big, small)
    assert set(zip(pt.tolist(), pe.tolist())) == brute(big, small)


def test_a_graded_cluster_is_not_quadratic(monkeypatch):
    """5,000 boxes shrinking geometrically towards the origin (a mesh graded
    over 600 decades): each overlaps a few of its neighbours, so the
    candidates are linear in number (they were all pairs of the finest cell)."""
    k = np.arange(5_000)
    size = np.ldexp(1.0, -(k // 5))  # five boxes per size, sizes halving, from 1 down to 2^-999
    x = size * (1 + (k % 5))
    box = np.column_stack([x, x + size, x, x + size])
    candidates = []

    def counting(*args):
        a, b = join(*args)
        candidates.append(len(a))
        return a, b

    join = grid.join_keys
    monkeypatch.setattr(grid, "join_keys", counting)
    pt, pe = box_pairs(box, box)
    assert len(pt) < 20 * len(box)
    assert sum(candidates) < 100 * len(box)  # the finest fixed cell held 4,850 of them: 23 million pairs
