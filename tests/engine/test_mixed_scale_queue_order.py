"""Triangle's queue order holds below its finest bucket (order.wide_bucket).

regressions/y-mixed-scale-one-bucket-rejections.json (campaign seed 2801): a
1e300 square, a hull corner below it (so the hull edge from the origin may
not be split under Y), segments crossing it, and free vertices at 1e-301 ..
1e-304 near the origin.  The bottom side is split on power-of-two shells
down to the small vertices, a chain of about 2,000 vertices; every vertex
inserted beside it has a fan of up to 1,000 needles to the chain, whose
off-centers lie across the hull edge and are rejected.  Triangle serves its
4096 buckets (squared shortest edges, half an octave each) finest first, so
the small triangle next to the new vertex comes up first and its split
replaces the fan: the needles go stale unserved.  Squared edges below
2^-1023.5 (in units of the input's extent, refine.key_unit) all fell into
Triangle's last bucket, served first in, first out: each fan's needles came
first, each rejected after a walk across the fan.  868,550 rejected points
for 3,755 inserted ones, 343 M walk steps, 11.5 s CPU; Triangle crashes on
the input.  The buckets now go on past Triangle's last (2 per octave of the
squared edge, to every squared edge between doubles), which changes nothing
where Triangle's buckets hold (golden: 0 of 450 cases differ).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from instrument import triangulate
from instrument.check import check_mesh

CASE = Path(__file__).resolve().parents[1] / "differential" / "regressions" / "y-mixed-scale-one-bucket-rejections.json"


def _pslg() -> dict:
    d = json.loads(CASE.read_text())["input"]
    vertices = np.array([float.fromhex(x) for x in d["vertices"]["hex"]]).reshape(d["vertices"]["shape"])
    segments = np.array(d["segments"]["int"]).reshape(d["segments"]["shape"])
    return {"vertices": vertices, "segments": segments}


def test_fans_of_needles_are_not_served_first_in_first_out():
    pslg = _pslg()
    out = triangulate(pslg, "pYqcQ")
    work = out.work
    # a few rejections per vertex, as at sane scales (before: 139 per vertex)
    assert work["rejected_vertices"] <= 3 * work["steiner_points"], work
    assert work["walk_steps"] <= 1000 * work["steiner_points"], work
    # (Y keeps the hull edge whole: the needles along it stay, so no angle bound)
    assert check_mesh(out, pslg=pslg) == []
