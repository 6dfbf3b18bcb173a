"""The bad-triangle queue and the encroached-subsegment pool (instrument.refine.queues, encroach)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from instrument.core.mesh import Mesh
from instrument.refine.encroach import enc_edge, enc_free, enc_push, in_lens
from instrument.refine.order import strategy_id, triangle_bucket, wide_bucket
from instrument.refine.queues import queue_clear, queue_compact, queue_pop, queue_push, queue_used
from instrument.refine.state import NBUCKETS, Config, Refiner
from instrument.switches import parse
from meshkit import triangulated


def _queue(strategy: str, capacity: int = 64):
    """A refiner holding only a bad-triangle queue, and a mesh of 16 slots."""
    cfg = Config(parse("q"), strategy_id(strategy), True, False)
    r = Refiner(cfg, budget=-1, slots=0, queue=capacity, records=0, trace=False)
    return r, Mesh(np.zeros((3, 2)), 16)


@pytest.mark.parametrize("strategy", ["triangle", "fifo"])
def test_bucket_queue_serves_finest_first_fifo_within_and_compacts_in_order(strategy):
    # Triangle's queue (spec 4.8.4): squared shortest edges 1.3 and 1.0 share
    # bucket 2047, 0.5 is in 2049, 0.25 in 2051; the highest bucket goes first.
    r, m = _queue(strategy)
    stamp = np.asarray(m.stamp)
    keys = [1.3, 0.5, 1.0, 0.25, 0.5, 2.0, 0.25]
    for t, key in enumerate(keys):
        queue_push(r, -float(triangle_bucket(key)) if strategy == "triangle" else 0.0, t, 1)
    # triangles 4 and 0 die: compaction must drop them and keep the order of the rest
    stamp[:7] = [0, 1, 1, 1, 0, 1, 1]
    queue_compact(r, m)
    order = [int(r.htri[queue_pop(r)]) for _ in range(r.hsize)]
    assert order == ([3, 6, 1, 2, 5] if strategy == "triangle" else [1, 2, 3, 5, 6])
    assert queue_used(r) == (5 if strategy == "triangle" else 0)  # served entries stay in the log
    stamp[:7] = 1
    queue_compact(r, m)  # until the next compaction
    assert queue_used(r) == 0
    queue_push(r, -2047.0 if strategy == "triangle" else 0.0, 9, 1)
    assert int(r.htri[queue_pop(r)]) == 9 and r.hsize == 0



@pytest.mark.parametrize("strategy", ["worst-angle", "largest", "lifo", "random"])
def test_heap_serves_smallest_key_first_and_ties_in_queueing_order(strategy):
    r, _ = _queue(strategy)
    keys = [3.0, 1.0, 2.0, 1.0, 0.5, 1.0]
    for t, key in enumerate(keys):
        queue_push(r, key, t, 1)
    order = [int(r.htri[queue_pop(r)]) for _ in range(len(keys))]
    assert order == [4, 1, 3, 5, 2, 0]
    assert r.hsize == 0 and queue_used(r) == 0


def test_queue_clear_empties_both_kinds():
    for strategy in ("triangle", "fifo"):
        r, _ = _queue(strategy)
        queue_push(r, -2047.0 if strategy == "triangle" else 0.0, 3, 1)
        queue_clear(r)
        assert r.hsize == 0 and queue_used(r) == 0 and r.top_bucket == -1


def _refiner(o: str = "q30", records: int = 8):
    cfg = Config(parse(o), strategy_id("triangle"), True, False)
    return Refiner(cfg, budget=-1, slots=0, queue=16, records=records, trace=False)


def test_lens_is_narrower_than_the_diametral_circle():
    m = triangulated([[0, 0], [2, 0], [1, 0.5], [1, 3]])
    r, rd = _refiner("q30"), _refiner("q30D")
    # (1, 0.5) sees (0, 0)-(2, 0) at 2 atan(2) = 126.9 degrees, (1, 0.9) at 96:
    # both inside the diametral circle (> 90), only the first inside the
    # 30-degree lens (> 180 - 2 x 30 = 120)
    assert in_lens(rd, m, 0, 1, 1.0, 0.5)
    assert in_lens(r, m, 0, 1, 1.0, 0.5)
    assert in_lens(rd, m, 0, 1, 1.0, 0.9) and not in_lens(r, m, 0, 1, 1.0, 0.9)  # 96 degrees
    assert not in_lens(rd, m, 0, 1, 1.0, 1.1)


def test_pool_reuses_the_slot_freed_last_and_finds_a_moved_edge():
    m = triangulated([[0, 0], [2, 0], [2, 2], [0, 2]])
    r = _refiner()
    edges = [e for e in range(3 * m.nslot) if m.arrays()["stamp"][e // 3] > 0][:3]
    for e in edges:
        enc_push(r, m, e)
    assert r.enc_live == 3 and r.enc_fresh == 3
    enc_free(r, 0)
    enc_free(r, 2)
    enc_push(r, m, edges[0])
    assert np.flatnonzero(np.asarray(r.enc)[:3, 0] >= 0).tolist() == [1, 2]  # slot 0 is still free
    assert np.asarray(r.enc)[2, 2] == edges[0]  # the slot freed last (2) was taken
    # not a subsegment: the pool's record says it is gone
    assert enc_edge(r, m, 2) == -1
    m.arrays()["seg"][edges[0]] = 0
    assert enc_edge(r, m, 2) == edges[0]


def _bucket_by_frexp(key: float) -> int:
    """Triangle's bucket from frexp, as order.py's pure-Python copy computes it."""
    if key <= 0.0 or key != key:
        return 4095
    big = key >= 1.0
    length = key if big else 1.0 / key
    if not length <= 1.7976931348623157e308:
        return 0 if big else 4095
    mant, ex = math.frexp(length)
    f, e = 2.0 * mant, ex - 1
    if f == 1.0 and e > 0:
        f, e = 2.0, e - 1
    x = min(2 * e + (1 if f > math.sqrt(2.0) else 0), 2047)
    return 2047 - x if big else 2048 + x


def test_bucket_reads_the_same_exponent_and_fraction_as_frexp():
    # the compiled bucket reads the key's bits (order.pxd): the same bucket
    # as frexp for every kind of double, around sqrt 2 and powers of two too
    rng = np.random.default_rng(5)
    keys = list(np.ldexp(rng.random(20000) + 0.5, rng.integers(-1074, 1024, 20000)))
    s2 = math.sqrt(2.0)
    for e in range(-1074, 1024, 7):
        for base in (1.0, s2, np.nextafter(s2, 0.0), np.nextafter(s2, 3.0), np.nextafter(1.0, 2.0), np.nextafter(2.0, 0.0)):
            keys.append(math.ldexp(base, e))
    keys += [0.0, -1.0, 5e-324, 1.7976931348623157e308, math.inf, -math.inf, math.nan, 1.0, 2.0, 0.5]
    for key in keys:
        assert triangle_bucket(float(key)) == _bucket_by_frexp(float(key)), key


def test_wide_bucket_is_triangles_where_its_buckets_hold_and_goes_on_past_them():
    # order.wide_bucket: the bucket of |(dx, dy) 2^u|^2 without squaring out of
    # range.  Where Triangle's bucket does not saturate it is Triangle's; a
    # power of two 2^k on the edge moves it 4k buckets (two per octave of the
    # square), also past Triangle's last bucket, 4095, where every squared
    # edge below 2^-1023.5 used to land (one first in, first out list)
    rng = np.random.default_rng(11)
    s2 = math.sqrt(2.0)
    for _ in range(4000):
        dx, dy = (rng.random(2) - 0.5) * np.ldexp(1.0, int(rng.integers(-400, 0)))
        key = dx * dx + dy * dy
        b = triangle_bucket(key)
        assert 2048 <= b < 4095
        assert wide_bucket(dx, dy, 0) == b, (dx, dy)
        for k in (300, 600, 1000):  # finer edges (while they are normal doubles), and finer units
            if min(abs(dx), abs(dy)) >= math.ldexp(1.0, k - 1020):
                assert wide_bucket(math.ldexp(dx, -k), math.ldexp(dy, -k), 0) == b + 4 * k
            assert wide_bucket(dx, dy, -k) == b + 4 * k
    # around sqrt 2 and the powers of two, against triangle_bucket too
    for e in range(-500, -10, 3):
        for base in (1.0, s2, np.nextafter(s2, 0.0), np.nextafter(s2, 3.0), np.nextafter(1.0, 2.0), np.nextafter(2.0, 0.0)):
            dx = math.sqrt(math.ldexp(float(base), 2 * e))  # (dx, 0) squares to about 2^2e base
            b = triangle_bucket(dx * dx)
            assert wide_bucket(dx, 0.0, 0) == b
            assert wide_bucket(math.ldexp(dx, -500), 0.0, 0) == b + 2000
    # the finest edges between doubles, in the finest units, stay in the table
    assert wide_bucket(5e-324, 0.0, -1025) < NBUCKETS
    assert wide_bucket(0.0, 0.0, 0) == 4095  # (no edge)
