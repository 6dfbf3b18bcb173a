"""The checker's candidate pairs (check/boxes.py) against all pairs: every pair
of overlapping boxes is found, once, at ordinary scales, over hundreds of
decades, with zero-size, enormous and infinite boxes, and in bounded chunks;
and a quadrant graded over 600 decades costs node visits in proportion to
the boxes and their true overlaps."""

from __future__ import annotations

import numpy as np
import pytest

from instrument.check import boxes as boxes_module
from instrument.check.boxes import BoxTree, box_pairs, octagons, overlapping


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
    assert len(pt) == len(brute(tbox, ebox))  # each pair once
    pe, pt = box_pairs(ebox, tbox[:100])  # the tree on the other side
    assert set(zip(pt.tolist(), pe.tolist())) == brute(tbox[:100], ebox)


def test_huge_boxes_whose_width_overflows():
    big = np.array([[-1e308, 1e308, -1e308, 1e308], [0.0, 1.0, 0.0, 1.0]])
    small = np.array([[0.5, 0.5, 0.5, 0.5], [1e300, 1.5e300, 0.0, 1.0], [-2.0, -1.0, -2.0, -1.0]])
    pt, pe = box_pairs(big, small)
    assert set(zip(pt.tolist(), pe.tolist())) == brute(big, small)


def test_infinite_and_subnormal_extents():
    """Segment boxes widened by a tolerance may reach +-inf; boxes may be subnormal or 2^+-1000."""
    tiny = 5e-324
    a = np.array([[-np.inf, np.inf, -np.inf, np.inf], [-np.inf, 0.0, 0.0, 0.0], [0.0, tiny, 0.0, tiny],
                  [2.0**1000, np.inf, -1.0, 1.0], [-2.0**-1000, 2.0**-1000, 2.0**1000, 2.0**1000],
                  [np.nextafter(0.0, 1.0), 2 * tiny, -tiny, -tiny]])
    b = np.array([[0.0, 0.0, 0.0, 0.0], [tiny, tiny, tiny, tiny], [-np.inf, -1e308, -1.0, 1.0],
                  [1e308, 1e308, 0.0, 0.0], [0.0, 0.0, 2.0**1000, np.inf], [2 * tiny, 3 * tiny, -np.inf, -tiny],
                  [-np.inf, np.inf, 2.0**1001, 2.0**1001]])
    for x, y in ((a, b), (b, a)):
        pt, pe = box_pairs(x, y)
        assert sorted(zip(pt.tolist(), pe.tolist())) == sorted(brute(x, y))


@pytest.mark.parametrize("seed", range(3))
def test_pairs_come_in_bounded_chunks(monkeypatch, seed):
    rng = np.random.default_rng(seed)
    tbox, ebox = boxes(rng, 400, -20, 20), boxes(rng, 300, -20, 20)
    ebox[:5] = [-1e300, 1e300, -1e300, 1e300]  # every box meets these: 2,000 pairs
    monkeypatch.setattr(boxes_module, "LIMIT", 64)
    chunks = list(overlapping(tbox, ebox))
    assert max(len(a) for a, _ in chunks) <= 64
    got = [(int(a), int(b)) for ca, cb in chunks for a, b in zip(ca, cb)]
    assert len(got) == len(set(got)) and set(got) == brute(tbox, ebox)


def graded_quadrant(levels=2000, per=12):
    """Boxes of a quadrant graded towards its corner at the origin, as the
    600-decade mesh is: at every scale 2^1000 .. 2^-999 an arc of ``per``
    boxes from the x axis to the y axis, the first touching y = 0 and the
    last x = 0 (so any box holding both arms of one scale holds the corner)."""
    k = np.repeat(np.arange(levels), per)
    j = np.tile(np.arange(per), levels)
    r = np.ldexp(1.0, 1000 - k)
    th = (j + 0.5) / per * (np.pi / 2)
    cx, cy, h = r * np.cos(th), r * np.sin(th), 0.4 * r
    box = np.column_stack([cx - h, cx + h, cy - h, cy + h])
    box[j == 0, 2] = 0.0
    box[j == per - 1, 0] = 0.0
    return np.maximum(box, 0.0)


def test_a_graded_quadrant_is_output_sensitive():
    """The 600-decade input's mesh is graded towards the corner of a
    quadrant.  Its boxes (24,000 here) meet ~8 others each; the former
    multi-level grid listed 192 million candidates for a third of them as
    queries, sort-tile-recursive packing and a Morton order of the doubles'
    bits visit thousands of nodes per query.  The polar packing order keeps
    the visits (the whole cost of the descent) within a small multiple of
    the boxes plus the true overlaps."""
    box = graded_quadrant()
    queries = box[::3]
    tree = BoxTree(box)
    pairs = [(int(q), int(b)) for cq, cb in tree.query(queries) for q, b in zip(cq, cb)]
    t = queries[:, None, :]
    assert len(pairs) == len(set(pairs))
    hits = sum(int(((t[i:i + 500, :, 0] <= box[None, :, 1]) & (box[None, :, 0] <= t[i:i + 500, :, 1])
                    & (t[i:i + 500, :, 2] <= box[None, :, 3]) & (box[None, :, 2] <= t[i:i + 500, :, 3])).sum())
               for i in range(0, len(queries), 500))
    assert len(pairs) == hits
    assert tree.visits < 20 * (len(box) + len(pairs))


@pytest.mark.parametrize("scale", [0, 300, 1000, 1023, -1000, -1074])
def test_octagons_hold_the_exact_sums(scale):
    """The diagonal ranges of ``octagons`` hold x + y and x - y exactly
    (Fractions), through overflow and the subnormals."""
    from fractions import Fraction

    rng = np.random.default_rng(scale & 0xFFFF)
    with np.errstate(over="ignore"):  # beyond the largest double: clipped to it below
        pts = np.ldexp(rng.standard_normal((200, 3, 2)), scale + rng.integers(-3, 4, (200, 3, 2)))
        pts[:20] = np.ldexp(rng.integers(-7, 8, (20, 3, 2)).astype(float), scale)
    pts[20:40, :, 1] = -pts[20:40, :, 0]  # x + y = 0 exactly
    pts = np.clip(np.nan_to_num(pts), -np.finfo(float).max, np.finfo(float).max)
    h = octagons(pts)
    for row, p in zip(h, pts):
        for x, y in p:
            for lo, hi, v in ((row[4], row[5], Fraction(x) + Fraction(y)), (row[6], row[7], Fraction(x) - Fraction(y))):
                assert (lo == -np.inf or Fraction(lo) <= v) and (hi == np.inf or v <= Fraction(hi))


def test_octagons_of_triangles_spanning_a_graded_corner():
    """Triangles (r, 0), (0, r), (r / 2, 0) at every scale hold the origin in
    their boxes but not in their octagons: an edge near the origin meets
    only the few that reach it."""
    r = np.ldexp(1.0, np.arange(1000, -1000, -1))
    z = np.zeros_like(r)
    tri = np.stack([np.column_stack([r, z]), np.column_stack([z, r]), np.column_stack([r / 2, z])], 1)
    edge = np.array([[[0.0, 0.0], [2.0**-990, 0.0]]])
    pt, pe = box_pairs(octagons(tri)[:, :4], octagons(edge)[:, :4])
    assert len(pt) == len(r)
    pt, pe = box_pairs(octagons(tri), octagons(edge))
    assert sorted(pt.tolist()) == list(range(len(r) - 11, len(r)))  # r <= 2^-989
