"""The shortcuts that make small inputs fast change nothing a user sees.

* ``refine.starting_room``: a small input under ``q`` reserves room for the
  whole refinement in the first stage; the result must be the general
  path's (the default room of 16, grown on demand), mesh and counts;
* the one-pass kernels that replaced numpy statements: the output's
  gathers (``core.gather``), the input segments' checks and the test for
  repeated segments (``segments.endpoints``), the sorted points' ties and
  duplicates (``delaunay.distinct``): each is compared with the numpy
  statement of the same rule it replaced.

Every mesh goes through the exact checker.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import triangle

import ruppert_io
from instrument import counters, pipeline, refine, triangulate
from instrument.check import check_mesh
from instrument.delaunay.distinct import has_x_ties, mark_duplicates
from instrument.output import assemble
from instrument.segments import clean_segments, merge_duplicates
from instrument.switches import parse

DATA = Path(__file__).resolve().parents[2] / "data"


def _input(name: str) -> dict:
    d = ruppert_io.read(DATA / name) if name.endswith(".poly") else triangle.get_data(name)
    return {k: v for k, v in d.items() if k in pipeline.INPUT_KEYS and v is not None and np.size(v)}


def _messy() -> dict:
    """A square with a hole, a duplicate vertex, a repeated segment (both
    directions, one with a marker), a segment with an invalid endpoint and
    one whose endpoints coincide."""
    v = [[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [3, 1], [3, 3], [1, 3], [4, 0], [2, 0.5]]
    s = [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4], [2, 1], [0, 12], [1, 8]]
    return {
        "vertices": np.array(v, dtype=float), "segments": np.array(s),
        "segment_markers": np.array([0, 0, 0, 0, 0, 0, 0, 0, 5, 0, 0]), "holes": np.array([[2.0, 2.0]]),
    }


def _general(inp: dict, switches: str):
    """``triangulate``'s stages with the default room (no reservation)."""
    o = parse(switches)
    work = counters.new_work()
    ms = pipeline.mesh_input(pipeline.validate(inp, o), o, work)
    refine.run(ms, o)
    return assemble(ms, pipeline.validate(inp, o), o), counters.as_dict(work), ms.warnings


CASES = [
    ("la", "pq30"), ("la", "pq20"), ("la", "pq33j"), ("la", "pq30eno2"), ("la", "pq30a0.5"),
    ("face", "pq30"), ("face", "pq25YA"), ("A", "pq30"), ("A", "pq28e"), ("dots", "cq30"),
    ("bracket.poly", "pq30"), ("quadratic-100.poly", "pq30n"), ("messy", "pq30"), ("messy", "pq20j"),
]


@pytest.mark.parametrize("name, switches", CASES)
def test_reserved_room_gives_the_general_result(name, switches):
    inp = _messy() if name == "messy" else _input(name)
    assert refine.starting_room(len(inp["vertices"]), parse(switches)) > 16 or "a" in switches
    got = triangulate(inp, switches)
    want, work, warnings = _general(inp, switches)
    assert got.work == work
    assert got.warnings == warnings
    assert sorted(got) == sorted(want)
    for key in want:
        assert np.array_equal(got[key], want[key]), key
        assert got[key].dtype == want[key].dtype, key
    assert check_mesh(got) == []


# ---------------------------------------------------------------- the kernels


def _numpy_clean(segments, xy, dup):
    """The rule of ``clean_segments`` as numpy statements (its former body)."""
    n = xy.shape[0]
    seg = np.asarray(segments, dtype=np.int64).reshape(-1, 2)
    a, b = seg[:, 0], seg[:, 1]
    bad_first = (a < 0) | (a >= n)
    bad_second = ~bad_first & ((b < 0) | (b >= n))
    ok = ~(bad_first | bad_second)
    a, b = np.where(ok, a, 0), np.where(ok, b, 0)
    a, b = np.where(dup[a] >= 0, dup[a], a), np.where(dup[b] >= 0, dup[b], b)
    coincident = ok & (xy[a, 0] == xy[b, 0]) & (xy[a, 1] == xy[b, 1])
    warnings = []
    for i in np.flatnonzero(~ok | coincident):
        kind = "first endpoint" if bad_first[i] else "second endpoint" if bad_second[i] else "coincident"
        warnings.append((int(i), kind))
    keep = np.flatnonzero(ok & ~coincident)
    return np.stack([a[keep], b[keep], keep], axis=1), warnings


def _numpy_merge(rows, markers):
    """The rule of ``merge_duplicates`` with numpy's unique alone."""
    lo, hi = np.minimum(rows[:, 0], rows[:, 1]), np.maximum(rows[:, 0], rows[:, 1])
    _, first, inverse = np.unique(np.stack([lo, hi], axis=1), axis=0, return_index=True, return_inverse=True)
    inverse = inverse.ravel()
    markers = markers.copy()
    group = np.zeros(first.shape[0], dtype=np.int32)
    for i in range(rows.shape[0] - 1, -1, -1):
        if markers[rows[i, 2]]:
            group[inverse[i]] = markers[rows[i, 2]]
    keep = np.sort(first)
    kept = rows[keep]
    markers[kept[:, 2]] = np.where(markers[kept[:, 2]] == 0, group[inverse[keep]], markers[kept[:, 2]])
    return kept, markers


@pytest.mark.parametrize("seed", range(20))
def test_segment_kernels_follow_the_numpy_rules(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(3, 40))
    xy = rng.integers(0, 6, size=(n, 2)).astype(float)  # a small grid: many duplicates
    _, first, inverse = np.unique(xy, axis=0, return_index=True, return_inverse=True)
    keeper = first[inverse.ravel()]
    dup = np.where(keeper == np.arange(n), -1, keeper).astype(np.int64)
    segs = rng.integers(-2, n + 2, size=(int(rng.integers(0, 60)), 2))
    warnings = []
    rows = clean_segments(segs, xy, dup, warnings)
    want_rows, want_warnings = _numpy_clean(segs, xy, dup)
    assert np.array_equal(rows, want_rows.reshape(-1, 3))
    assert [int(w.split("segment ")[1].split()[0]) for w in warnings] == [i for i, _ in want_warnings]
    for w, (_, kind) in zip(warnings, want_warnings):
        assert kind in w
    if rows.shape[0]:
        markers = rng.integers(0, 3, size=segs.shape[0]).astype(np.int32)
        kept, kept_markers = merge_duplicates(rows, markers)
        want_kept, want_markers = _numpy_merge(rows, markers)
        assert np.array_equal(kept, want_kept)
        assert np.array_equal(kept_markers, want_markers)


@pytest.mark.parametrize("seed", range(20))
def test_sorted_point_kernels_follow_the_numpy_rules(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(1, 50))
    xy = np.ascontiguousarray(rng.integers(0, 5 + seed, size=(n, 2)).astype(float))
    order = np.argsort(xy[:, 0]).astype(np.int64)
    xs = xy[order, 0]
    assert has_x_ties(xy, order) == bool(np.any(xs[1:] == xs[:-1]))
    order = np.lexsort((xy[:, 1], xy[:, 0])).astype(np.int64)
    dup = np.full(n, -1, dtype=np.int64)
    count = mark_duplicates(xy, order, dup)
    s = xy[order]
    new = np.ones(n, dtype=bool)
    new[1:] = (s[1:, 0] != s[:-1, 0]) | (s[1:, 1] != s[:-1, 1])
    keeper = order[np.maximum.accumulate(np.where(new, np.arange(n), 0))]
    want = np.full(n, -1, dtype=np.int64)
    want[order[~new]] = keeper[~new]
    assert count == int((~new).sum())
    assert np.array_equal(dup, want)
