"""The arrays' starting room changes nothing a user sees: kernels that run out
of room stop, the driver grows the arrays and they start the step again, so
the mesh, the work counters and the trace must be the same whatever room the
run began with (a step that stops must not count its tests twice, a full
queue must not be compacted early, Chew's deletion must not be skipped for
want of scratch space)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import triangle

import ruppert_io
from instrument import counters, pipeline, refine
from instrument.check import check_mesh
from instrument.output import assemble
from instrument.switches import parse

DATA = Path(__file__).resolve().parents[2] / "data"


def _input(name: str) -> dict:
    d = ruppert_io.read(DATA / name) if name.endswith(".poly") else triangle.get_data(name)
    return {k: v for k, v in d.items() if k in pipeline.INPUT_KEYS and v is not None and np.size(v)}


def _run(inp: dict, switches: str, strategy: str, room: int, grown: int):
    o = parse(switches + "Q")
    work = counters.new_work()
    ms = pipeline.mesh_input(pipeline.validate(inp, o), o, work, room=room)
    if grown:
        ms.grow(vertices=grown, triangles=2 * grown, records=grown)
    rows = refine.run(ms, o, strategy=strategy, steiner="offcenter", trace=True)
    out = assemble(ms, pipeline.validate(inp, o), o)
    return out, counters.as_dict(work), np.asarray(rows.tolist(), dtype=object)


@pytest.mark.parametrize(
    "name, switches, strategy",
    [
        ("la", "pq30", "triangle"),
        ("la", "pq30a0.5", "smallest"),
        ("face", "pq33", "worst-angle"),
        ("dots", "cq30", "triangle"),
        ("quadratic-100.poly", "pq30", "adversary"),  # Chew's deletion once skipped with little room
    ],
)
def test_mesh_counts_and_trace_do_not_depend_on_the_starting_room(name, switches, strategy):
    inp = _input(name)
    runs = [_run(inp, switches, strategy, room, grown) for room, grown in ((1, 0), (16, 0), (37, 0), (16, 100_000))]
    first_mesh, first_work, first_trace = runs[0]
    assert check_mesh(first_mesh) == []
    for mesh, work, trace in runs[1:]:
        assert work == first_work
        assert np.array_equal(trace, first_trace)
        assert sorted(mesh) == sorted(first_mesh)
        for key in first_mesh:
            assert np.array_equal(mesh[key], first_mesh[key]), key


def _triangulate(inp: dict, switches: str, strategy: str):
    import instrument

    r = instrument.triangulate(inp, switches + "Q", strategy=strategy, threads=1)
    return r, r.work


def test_a_reused_refiner_changes_nothing():
    """Small runs reuse the refiner a finished run left (refine._spares):
    whatever that run was (another order, another input, a Steiner budget
    that ended it with the queue still full), the next mesh and its counts
    are those a new refiner gives."""
    cases = [
        ("la", "pq30", "triangle"),
        ("la", "pq30S40", "triangle"),  # ends with entries still queued
        ("face", "pq33", "worst-angle"),  # a heap, not buckets
        ("dots", "cq30", "triangle"),
        ("la", "pq30a0.5", "smallest"),
        ("la", "pq30", "triangle"),
    ]
    fresh = []
    for name, switches, strategy in cases:
        refine._spares.clear()
        fresh.append(_triangulate(_input(name), switches, strategy))
    refine._spares.clear()
    for (name, switches, strategy), (first_mesh, first_work) in zip(cases, fresh):
        mesh, work = _triangulate(_input(name), switches, strategy)
        assert refine._spares, "the run left its refiner for the next"
        assert work == first_work
        assert sorted(mesh) == sorted(first_mesh)
        for key in first_mesh:
            assert np.array_equal(mesh[key], first_mesh[key]), key
