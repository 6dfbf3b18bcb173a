"""Two hole points exactly at two input vertices, against Triangle.

Each point alone is ambiguous in Triangle (located.py): its sampled walk
puts a point at a vertex into any of the triangles around it, and a point
at a hull vertex is ignored when it lies on the hull edge Triangle's point
location starts from, which segment insertion moves.  Two such points
combine those choices independently (``scripts/hole_start_edge.py``; the
case that showed it is ``regressions/hole-at-two-vertices.json``).  Every
mesh of ours must pass the exact checker and agree with Triangle's mesh for
some combination, as the harness judges it.

``RUPPERT_HOLES_EXAMPLES=1000`` runs that many random cases instead of the
fixed (derandomized) sample (``RUPPERT_DIFF_SEED`` picks the seed).
"""

from __future__ import annotations

import os

from hypothesis import HealthCheck, given, seed, settings

from instrument.check import check_mesh

from .families import hole_pair_cases
from .harness import run_case
from .located import points_to_place
from .oracles import read_switches

DEFAULT_EXAMPLES = 20
EXAMPLES = int(os.environ.get("RUPPERT_HOLES_EXAMPLES", DEFAULT_EXAMPLES))
SEED = int(os.environ.get("RUPPERT_DIFF_SEED", "0"))


@settings(max_examples=EXAMPLES, deadline=None, derandomize=EXAMPLES == DEFAULT_EXAMPLES and not SEED,
          database=None, suppress_health_check=list(HealthCheck))
@seed(SEED)
@given(case=hole_pair_cases())
def test_two_holes_at_vertices_agree_with_triangle(runners, case):
    assert len(points_to_place(case)) >= 2  # both points are judged as placed or left out
    run = run_case(runners, case, confirmed={}, confirmations=1)
    assert run is not None
    assert run.ours.status == "ok", run.ours.summary()
    sw = read_switches(case.switches)
    problems = check_mesh(run.ours.result, pslg=case.input, min_angle=sw.angle if sw.q else None)
    assert problems == [], problems[:5]
    assert run.verdict.ok, [f"{f.signature}: {f.message[:300]}" for f in run.verdict.failures]
