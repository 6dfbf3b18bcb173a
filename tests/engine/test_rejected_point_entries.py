"""A rejected Steiner point's queued triangles, served where Triangle serves them.

Triangle inserts a Steiner point, queueing the bad triangles of its fan,
before it finds that the point encroaches a subsegment and undoes the
insertion; the entries stay queued.  The subsegment's split point takes the
rejected vertex's record, and an entry whose triangle record that insertion
fills with the same triangle (the split point in place of the rejected
one), in the same orientation, is served again in its old place, ahead of
everything queued since (refine/ghosts.py models which).  Two point sets
whose refinement parted from Triangle's there (the campaign's; their
regression files replay them against Triangle) now make its meshes.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import instrument
from instrument.check import check_mesh

REGRESSIONS = Path(__file__).resolve().parents[1] / "differential" / "regressions"


def _points(name: str) -> tuple[np.ndarray, str]:
    d = json.loads((REGRESSIONS / name).read_text())
    v = np.array([float.fromhex(h) for h in d["input"]["vertices"]["hex"]]).reshape(-1, 2)
    return v, d["switches"]


# Triangle (the package, 20250106) makes these many vertices; before the
# model ours made 179 and 1285
@pytest.mark.parametrize("name, angle, triangle_vertices", [
    ("q34-fifo-order-size.json", 34.0, 127),
    ("points-q32.5-stale-record-size.json", 32.5, 1243),
])
def test_revived_entries_make_triangles_mesh(name, angle, triangle_vertices):
    v, switches = _points(name)
    r = instrument.triangulate({"vertices": v}, switches)
    assert check_mesh(r, pslg={"vertices": v}, min_angle=angle) == []
    assert len(r["vertices"]) == triangle_vertices

