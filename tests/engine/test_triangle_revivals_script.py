"""``scripts/triangle_revivals.py``: Triangle's splits of good triangles, from its -VV log."""

from __future__ import annotations

from pathlib import Path

import pytest
from scripthelpers import load_script

triangle = pytest.importorskip("triangle")


def load():
    return load_script("triangle_revivals")


# A log in Triangle's -VV wording: a circumcenter is rejected, the subsegment's
# midpoint takes its slot, and an equilateral triangle at the midpoint is split.
LOG = """\
  Splitting this triangle at its circumcenter:
    (0, 0) (1, 0) (0.5, 0.2)
  Inserting (0.5, -0.5).
  Rejecting (0.5, -0.5).
  Splitting subsegment (0, 0) (1, 0) at (0.5, 0).
  Inserting (0.5, 0).
  Splitting this triangle at its circumcenter:
    (0, 0) (2, 0) (1, 1.7320508)
  Inserting (1, 0.577).
  Splitting this triangle at its circumcenter:
    (0.5, 0) (1.5, 0) (1, 0.8660254)
  Inserting (1, 0.3).
  Splitting subsegment (3, 0) (4, 0) at (3.5, 0).
  Inserting (3.5, 0).
  Deleting (1, 0.577).
""".splitlines()


def test_replays_the_vertex_pool_from_the_log():
    mod = load()
    splits, bad_reused, good = mod.analyse(LOG, 30.0)
    assert splits == 3
    assert bad_reused == 0  # the first split's triangle has no reused vertex
    # the equilateral triangles are good; only the one at the midpoint has a reused slot
    assert [(n, reused) for n, _, reused in good] == [(2, []), (3, ["rejected"])]


def test_pool_reuses_the_slot_freed_last():
    mod = load()
    pool = mod.VertexPool()
    for p in ("a", "b", "c"):
        pool.take(p)
    pool.give_back("a", "rejected")
    pool.give_back("c", "deleted")
    pool.take("d")
    pool.take("e")
    assert pool.slot == {"b": 1, "d": 2, "e": 0}
    assert pool.freed_by == {0: "rejected", 2: "deleted"}


def test_la_poly_every_good_split_has_a_rejected_vertex_slot(capsys):
    mod = load()
    assert mod.main([str(Path(triangle.__file__).parent / "data" / "la.poly")]) == 0
    out = capsys.readouterr().out
    assert "672 triangle splits, 10 of triangles" in out
    assert "10 of 10 have a vertex in a slot a rejected vertex left" in out
