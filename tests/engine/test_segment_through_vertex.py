"""A segment through an input vertex, crossed elsewhere first, passes it by as Triangle's does.

Under ``c`` the segment (-0x1.fd094p-2, -0x1.feb28p-2)-(0x1.fd094p-2,
0x1.feb28p-2) passes exactly through the input vertex (0, 0), and other
segments cross it near (0.000304, 0.000305)
(tests/differential/regressions/c-extra-segment-crossing.json).  Alone it
is split at (0, 0); with the crossings its piece from the rounded crossing
vertex no longer has (0, 0) exactly on it, and Triangle joins the far end
straight to the crossing, leaving (0, 0) off the segment.  Ours split it at
(0, 0) either way until stop 30; it now follows Triangle's rule (a vertex
is on a piece only when exactly on it: segments/recover.py's ``_side``),
which the segment pieced through (0, 0) had broken elsewhere (it closed
domains that Triangle leaves open: regressions/crossing-beside-an-end-area.json).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import triangle

import instrument
from instrument.check import check_mesh

CASE = Path(__file__).parents[1] / "differential" / "regressions" / "c-extra-segment-crossing.json"
THROUGH = 6  # the input segment through (0, 0)


def _pslg():
    d = json.loads(CASE.read_text())["input"]
    v = np.array([float.fromhex(h) for h in d["vertices"]["hex"]]).reshape(d["vertices"]["shape"])
    s = np.array(d["segments"]["int"]).reshape(d["segments"]["shape"])
    return {"vertices": v, "segments": s}


def _ends_at_origin(result):
    xy = result["vertices"]
    return sum(1 for a, b in result["segments"].tolist() if [0.0, 0.0] in (xy[a].tolist(), xy[b].tolist()))


@pytest.mark.parametrize("alone", [True, False])
def test_segment_through_input_vertex_is_split_there_alone(alone):
    pslg = _pslg()
    if alone:
        pslg = {"vertices": pslg["vertices"], "segments": pslg["segments"][[THROUGH]]}
    ours = instrument.triangulate(pslg, "pcQ")
    assert check_mesh(ours, pslg=pslg) == []
    theirs = triangle.triangulate(pslg, "pcQ")
    assert check_mesh(theirs, pslg=pslg) == []
    # split at (0, 0) alone, passed by with the crossings: both
    assert _ends_at_origin(theirs) == (2 if alone else 0)
    assert _ends_at_origin(ours) == _ends_at_origin(theirs)
    assert len(ours["segments"]) == len(theirs["segments"])
