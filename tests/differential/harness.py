"""One differential case from start to verdict, shared by the tests and the campaign.

``run_case`` materializes the case (Triangle makes the mesh an ``r`` case
refines), runs Triangle and ours, and judges.  A failure seen in the
persistent worker of ours is confirmed in a fresh process, because a case
that corrupts the worker's heap can make a later, innocent case crash; when
the persistent worker crashed but the fresh run is fine, the previous case
is run fresh too, so the crash is charged to the case that caused it.
Triangle's answer, when ours fails against it, is confirmed in a fresh
process as well: on some inputs it reads what its heap held before, and an
answer a new process does not give (or crashes on) is no reference.
A signature confirmed ``CONFIRMATIONS`` times in a session is not
confirmed again (each fresh process costs seconds of kernel loading).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from . import located
from .cases import Case
from .oracles import Verdict, judge, used_vertices
from .reexpress import KINDS, transformed
from .runners import Outcome, Runners


CONFIRMATIONS = 3


@dataclass
class Run:
    case: Case  # materialized
    verdict: Verdict
    triangle: Outcome
    ours: Outcome
    #: (case, verdict) of the previous case when it, not this one, broke the worker
    culprit: tuple | None = None
    notes: dict = field(default_factory=dict)


def spread_counts(runners: Runners, case: Case) -> list[int]:
    """Triangle's used-vertex counts over the exact re-expressions of the input."""
    counts = []
    for kind in KINDS:
        out = runners.run_triangle(transformed(case.input, kind), case.switches)
        if out.status == "ok" and len(out.result.get("triangles", ())):
            counts.append(used_vertices(out.result))
    return counts


def judge_outcomes(runners: Runners, case: Case, tri: Outcome, ours: Outcome) -> Verdict:
    verdict = judge(case, tri, ours, spread=lambda: spread_counts(runners, case))
    if verdict.ok or ours.status != "ok" or not located.points_to_place(case):
        return verdict
    # a hole or region point exactly at a vertex (under i: on a segment):
    # Triangle's answer is that of the point in one of the triangles it touches
    # (or, on the hull, left out), which one its sampled walk and where its
    # start edge was left decide (located.py); ours
    # passes if it agrees in every check with one
    bare = {k: v for k, v in case.input.items() if k not in ("holes", "regions")}
    cdt = runners.run_triangle(bare, located.cdt_switches(case.switches))
    if cdt.status != "ok":
        return verdict
    judged = []  # many placements give the same mesh: each is judged once
    for alt in located.alternatives(case, cdt.result):
        alt_tri = runners.run_triangle(alt.input, alt.switches)
        if alt_tri.status != "ok" or any(same_mesh(alt_tri, seen) for seen in judged):
            continue
        judged.append(alt_tri)
        alt_verdict = judge(case, alt_tri, ours, spread=lambda alt=alt: spread_counts(runners, alt))
        if alt_verdict.ok:
            alt_verdict.notes["point_placed"] = {
                "triangle": tri.summary(), "moved": {k: np.asarray(alt.input[k]).tolist() for k in ("holes", "regions")
                                                     if k in alt.input}}
            return alt_verdict
    verdict.notes["point_placed"] = "ours agrees with Triangle for no placement around the vertex"
    return verdict


def same_outcome(a: Outcome, b: Outcome) -> bool:
    """Whether two runs gave the same status and, when ok, equal arrays."""
    if a.status != b.status:
        return False
    if a.status != "ok":
        return True
    ra, rb = a.result, b.result
    return ra.keys() == rb.keys() and all(np.array_equal(np.asarray(ra[k]), np.asarray(rb[k]), equal_nan=True)
                                         for k in ra)


def same_mesh(a: Outcome, b: Outcome) -> bool:
    """Whether two runs that both made a mesh made the same one (the hole
    and region points they copy to the output aside)."""
    ra = {k: v for k, v in a.result.items() if k not in ("holes", "regions")}
    rb = {k: v for k, v in b.result.items() if k not in ("holes", "regions")}
    return same_outcome(Outcome("ok", ra), Outcome("ok", rb))


def run_case(runners: Runners, case: Case, previous: Case | None = None, confirmed: dict | None = None,
             confirmations: int = CONFIRMATIONS) -> Run | None:
    """Run ``case``; None when it cannot be made (Triangle makes no mesh to refine).
    ``confirmed`` counts the fresh confirmations per signature so far."""
    case = runners.materialize(case)
    if case is None:
        return None
    tri = runners.run_triangle(case.input, case.switches)
    ours = runners.run_ours(case.input, case.switches)
    verdict = judge_outcomes(runners, case, tri, ours)
    if not verdict.ok and tri.status == "ok":
        # Triangle's answer is a reference only if new processes give it too:
        # the persistent worker's history can change it (its random state), and
        # on some inputs it reads freed memory, so new processes crash or differ
        first = runners.run_triangle_fresh(case.input, case.switches)
        second = runners.run_triangle_fresh(case.input, case.switches)
        if first.status == "ok" and same_outcome(first, second):
            fresh = first
        else:  # no reference: judged as where Triangle crashes
            fresh = Outcome("crash", message=f"Triangle's answer is not reproducible: in new processes "
                            f"{first.summary()}, then {second.summary()}")
        if not same_outcome(tri, fresh):
            tri = fresh
            verdict = judge_outcomes(runners, case, tri, ours)
            verdict.notes["triangle_not_reproducible"] = "the persistent worker's answer is not new processes'"
    run = Run(case, verdict, tri, ours)
    if verdict.ok:
        return run
    if confirmed is not None and ours.status != "crash":
        if all(confirmed.get(sig, 0) >= confirmations for sig in verdict.signatures()):
            return run
    fresh = runners.run_ours_fresh(case.input, case.switches)
    fresh_verdict = judge_outcomes(runners, case, tri, fresh)
    if confirmed is not None:
        for sig in fresh_verdict.signatures():
            confirmed[sig] = confirmed.get(sig, 0) + 1
    if fresh_verdict.ok:
        run.notes["persistent_worker_only"] = verdict.signatures()
        if ours.status == "crash" and previous is not None:
            prev = runners.materialize(previous)
            if prev is not None:
                p_tri = runners.run_triangle(prev.input, prev.switches)
                p_ours = runners.run_ours_fresh(prev.input, prev.switches)
                p_verdict = judge_outcomes(runners, prev, p_tri, p_ours)
                if not p_verdict.ok:
                    run.culprit = (prev, p_verdict, p_tri, p_ours)
    return Run(case, fresh_verdict, tri, fresh, run.culprit, run.notes)
