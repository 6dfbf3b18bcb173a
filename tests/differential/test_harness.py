"""The harness's own rules: a Triangle answer that new processes do not
give again is no reference (harness.run_case)."""

from __future__ import annotations

import numpy as np

from instrument import triangulate
from tests.differential.cases import Case
from tests.differential.harness import run_case, same_outcome
from tests.differential.runners import Outcome

# the campaign's case (seed 2611): vertex 4 repeats vertex 2 and segment [4, 3]
# repeats [2, 3]; in a worker that had run other cases Triangle answered 4
# vertices and 2 triangles under pjQ, where a new process segfaults (every
# triangle is outside the open segments: ours, like Triangle on such input
# without the duplicate, answers nothing under j)
CASE = Case(
    family="duplicate-points",
    switches="pjQ",
    input={
        "vertices": np.array([[0.39802439, 0.81384865], [0.39493422, 0.17664078], [0.42624922, 0.54232054],
                              [0.32520246, 0.51390576], [0.42624922, 0.54232054]]),
        "segments": np.array([[0, 1], [2, 3], [4, 3]], dtype=np.int32),
    },
)

# a valid mesh that is not the answer: the convex hull's (c), as a worker's
# stale heap might have made it
STALE = Outcome("ok", result=triangulate(CASE.input, "pcjQ"))


class FakeRunners:
    """Triangle's persistent worker answers ``persistent``; new processes
    ``fresh`` (one outcome, or a list answered in turn); ours runs in-process."""

    def __init__(self, persistent: Outcome, fresh):
        self.persistent, self.fresh, self.fresh_calls = persistent, fresh, 0

    def materialize(self, case):
        return case

    def run_triangle(self, tri, opts):
        return self.persistent

    def run_triangle_fresh(self, tri, opts):
        self.fresh_calls += 1
        return self.fresh[self.fresh_calls - 1] if isinstance(self.fresh, list) else self.fresh

    def run_ours(self, tri, opts):
        return Outcome("ok", result=triangulate(tri, opts))

    run_ours_fresh = run_ours


def test_answer_a_new_process_does_not_give_is_no_reference():
    fake = FakeRunners(STALE, Outcome("crash", message="signal 11"))
    run = run_case(fake, CASE, confirmations=0)
    assert fake.fresh_calls == 2
    assert run.verdict.ok, run.verdict.failures
    assert "triangle_not_reproducible" in run.verdict.notes


def test_reproduced_answer_stays_the_reference():
    fake = FakeRunners(STALE, STALE)
    run = run_case(fake, CASE, confirmations=0)
    assert fake.fresh_calls == 2
    assert not run.verdict.ok  # ours (no triangles) against a reproducible 2-triangle answer


def test_answer_new_processes_disagree_on_is_no_reference():
    # duplicate points at segment ends: Triangle reads freed memory, and new
    # processes crash or answer (a case of the overlap survey under pzjQ)
    fake = FakeRunners(STALE, [STALE, Outcome("crash", message="signal 11")])
    run = run_case(fake, CASE, confirmations=0)
    assert fake.fresh_calls == 2
    assert run.verdict.ok, run.verdict.failures
    assert "triangle_not_reproducible" in run.verdict.notes


def test_same_outcome_compares_arrays():
    a = Outcome("ok", result={"vertices": np.zeros((2, 2))})
    assert same_outcome(a, Outcome("ok", result={"vertices": np.zeros((2, 2))}))
    assert not same_outcome(a, Outcome("ok", result={"vertices": np.ones((2, 2))}))
    assert not same_outcome(a, Outcome("crash"))


def test_a_call_times_out_on_its_cpu_time_and_the_worker_starts_again():
    """A run past its budget ends as a timeout that says what it used, and
    the next call starts a new worker (runners.Worker)."""
    from tests.differential.runners import Worker

    square = {"vertices": np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]),
              "segments": np.array([[0, 1], [1, 2], [2, 3], [3, 0]], dtype=np.int32)}
    w = Worker("ours", timeout=0.05, startup_timeout=600.0)
    try:
        out = w.call(square, "pq30a0.0000001Q")  # seconds of refinement
        assert out.status == "timeout" and "CPU" in out.message, out.summary()
        again = w.call(square, "pQ", timeout=600.0)
        assert again.status == "ok" and len(again.result["triangles"]) == 2
    finally:
        w.stop()
