"""The encroachment test does not overflow at large coordinates (issue 18).

Three points near 1e301 under D: the diametral test's dot product of two
differences ~1e301 overflowed (inf - inf = NaN, taken as encroaching), so
every Steiner point was rejected and its subsegment split: 6306 vertices and
edges that are not locally Delaunay, where the same points at 1e150 make 10.
The differences are now scaled by a power of two beyond 2^240 (and below
2^-240), so the mesh is the same at every scale. (Under q these points still
run out of precision beyond 1e210: the open defect huge-refinement-precision.)
"""

from __future__ import annotations

import numpy as np
import pytest

import instrument
from instrument.check import check_mesh

POINTS = np.array([[1.0725550023104727e299, 7.324765869437374e299], [5.1534959867112955e299, 1.7919516502016433e299],
                   [1.0338383827148751e301, 1.1824264903520333e300]])


@pytest.mark.parametrize("switches", ["DQ", "pDQ", "cDQ"])
def test_refinement_is_the_same_at_every_scale(switches):
    counts = set()
    for k in (0, -300, -500, -1000, -1900):
        pts = np.ldexp(POINTS, k)
        out = instrument.triangulate({"vertices": pts}, switches)
        assert check_mesh(out, pslg={"vertices": pts} if "p" in switches else None) == []
        counts.add(len(out["vertices"]))
    assert len(counts) == 1, counts
