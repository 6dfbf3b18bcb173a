"""A segment through an input vertex is split there, crossings or not.

Under ``c`` the segment (-0x1.fd094p-2, -0x1.feb28p-2)-(0x1.fd094p-2,
0x1.feb28p-2) passes exactly through the input vertex (0, 0), and other
segments cross it near (0.000304, 0.000305)
(tests/differential/regressions/c-extra-segment-crossing.json).  Triangle
alone splits it at (0, 0), but with the crossings it joins the far end
straight to the rounded crossing vertex and leaves (0, 0) off the segment;
ours splits it at (0, 0) either way (docs/differential.md).
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
def test_segment_through_input_vertex_is_split_there(alone):
    pslg = _pslg()
    if alone:
        pslg = {"vertices": pslg["vertices"], "segments": pslg["segments"][[THROUGH]]}
    ours = instrument.triangulate(pslg, "pcQ")
    assert check_mesh(ours, pslg=pslg) == []
    assert _ends_at_origin(ours) == 2
    theirs = triangle.triangulate(pslg, "pcQ")
    assert check_mesh(theirs, pslg=pslg) == []
    # Triangle: split at (0, 0) alone, passed by with the crossings
    assert _ends_at_origin(theirs) == (2 if alone else 0)
    assert len(ours["segments"]) == len(theirs["segments"]) + (0 if alone else 1)
