"""The mesh's tables and primitives (instrument.core.mesh)."""

from __future__ import annotations

import numpy as np
import pytest

from instrument.core.mesh import GHOST, NO_EDGE, NO_SEG, Mesh, remove_ghosts, set_parent, interpolate_attributes
from meshkit import problems, triangulated


def test_a_new_mesh_has_every_table_at_its_capacity():
    m = Mesh(np.zeros((5, 2)), 10, vertices=8, parents=True, area_bounds=True, attributes=True)
    a = m.arrays()
    assert m.nvert == 5 and m.vertex_capacity == 8 and m.triangle_capacity == 10
    for name in ("xy", "vmark", "vtri", "vtype", "parent", "vslot"):
        assert a[name].shape[0] == 8, name
    for name in ("stamp", "free", "area_bound", "attribute", "tflag"):
        assert a[name].shape[0] == 10, name
    for name in ("corner", "twin", "seg"):
        assert a[name].shape[0] == 30, name
    assert (a["corner"] == GHOST).all() and (a["twin"] == NO_EDGE).all() and (a["seg"] == NO_SEG).all()


def test_growth_widens_every_table_together_and_keeps_contents():
    m = triangulated(np.random.default_rng(1).random((30, 2)), extra_vertices=0, extra_triangles=0)
    m.add_area_bounds(np.full(m.nslot, 0.5))
    m.add_attributes(np.arange(m.nslot, dtype=float))
    before = {k: v.copy() for k, v in m.arrays().items()}
    m.grow_triangles(m.spare() + 100)
    m.grow_vertices(50)
    a = m.arrays()
    for name in ("stamp", "free", "area_bound", "attribute", "tflag"):
        assert a[name].shape[0] == m.triangle_capacity, name
        np.testing.assert_array_equal(a[name][: before[name].shape[0]], before[name])
    for name in ("xy", "vmark", "vtri", "vtype", "vslot"):
        assert a[name].shape[0] == m.vertex_capacity, name
        np.testing.assert_array_equal(a[name][: before[name].shape[0]], before[name])
    assert (a["area_bound"][before["area_bound"].shape[0]:] == -1.0).all()
    assert problems(m) == []


def test_tables_a_run_does_not_use_stay_empty_through_growth():
    m = Mesh(np.zeros((3, 2)), 4)
    m.grow_triangles(100)
    m.grow_vertices(100)
    assert m.arrays()["area_bound"].shape[0] == 0 and m.arrays()["parent"].shape[0] == 0


def test_remove_ghosts_leaves_the_hull_open():
    m = triangulated([[0, 0], [1, 0], [0, 1], [1, 1]])
    twin = m.arrays()["twin"]
    assert (twin[: 3 * m.nslot][np.repeat(m.arrays()["stamp"][: m.nslot] > 0, 3)] == NO_EDGE).sum() == 4
    assert remove_ghosts(m) == 0  # none left
    assert problems(m) == []


def test_parents_interpolate_attributes_in_creation_order():
    m = Mesh(np.zeros((5, 2)), 4, parents=True)
    set_parent(m, 3, 0, 1, 2, 0.5, 0.25)  # a0 + 0.5 (a1 - a0) + 0.25 (a2 - a0)
    set_parent(m, 4, 3, 0, 3, 1.0, 0.0)  # a0 of vertex 3 + 1 (a0 of 0 - a3): vertex 0's
    out = np.zeros((5, 1))
    out[:3, 0] = [0.0, 4.0, 8.0]
    interpolate_attributes(m, out, 3)
    assert out[3, 0] == 0.0 + 0.5 * 4.0 + 0.25 * 8.0
    assert out[4, 0] == 0.0


def test_a_run_without_attribute_records_ignores_set_parent():
    m = Mesh(np.zeros((3, 2)), 4)
    set_parent(m, 2, 0, 1, 0, 0.5, 0.0)  # no table: nothing written, no error
    assert m.arrays()["parent"].shape == (0, 5)
