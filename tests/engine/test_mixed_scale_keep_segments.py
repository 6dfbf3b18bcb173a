"""Quality refinement under Y at extreme mixed scales makes valid meshes (issue 18).

Points spanning 1e-307 to 1e299 under ``qY`` made meshes with clockwise
triangles and coincident vertices (regressions/mixed-scale-Y-invalid.json,
found by the generated differential test, seed 26).  The first bad step:
a needle (0, 1e-306), (2e-305, 6e-305), (2e-304, 4e-304) beside the hull edge
x = 0, whose off-center lies across that hull edge at x = -1.4e-304.  Its
barycentric parameters (which pick the edge the walk starts from) came out
finite but meaningless (1e17, rounded from sides 1e-306 long), the walk
started from an edge the point lay across, found it "inside" the triangle
it lies outside of, and the new vertex's fan folded over the hull.  Now the
start edge is checked exactly (splits.split_bad_triangle) and every new
vertex must lie strictly left of each edge of its cavity's rim.  Without Y
the off-center is not reached the same way (the hull's own splits come
first), which is why only Y and YY showed it; other point sets of this kind
ran out of precision or into the vertex limit instead of ending.

Triangle does not refine these inputs at all (its quality test overflows),
so the bound is not asked for, only a valid mesh.
"""

from __future__ import annotations

import numpy as np
import pytest

import instrument
from instrument.check import check_mesh

POINT_SETS = {
    # the regression: (0, 2.5e299), (9.5e293, 0), (0, 0), (0, 9.5e-307)
    "regression": [("0x0.0p+0", "0x1.7e43c8800759cp+994"), ("0x1.7e43c8800759cp+976", "0x0.0p+0"),
                   ("0x0.0p+0", "0x0.0p+0"), ("0x0.0p+0", "0x1.56e1fc2f8f359p-1017")],
    # the same shape at 1e251 .. 1e-277 (8096 vertices, 24 checker problems before)
    "axes-1e263": [("0x0.0p+0", "0x1.a253e4adfe840p+834"), ("0x1.39aeee1640acfp+875", "0x0.0p+0"),
                   ("0x0.0p+0", "0x0.0p+0"), ("0x0.0p+0", "0x1.9b6be45f1424bp-918")],
    # ... and at 1e254 .. 1e-306 (a PrecisionError before)
    "axes-1e254": [("0x0.0p+0", "0x1.0d0e61d441b4cp+846"), ("0x1.2cc53e97638e4p+669", "0x0.0p+0"),
                   ("0x0.0p+0", "0x0.0p+0"), ("0x0.0p+0", "0x1.7319c4d011005p-1015")],
    # a 1e-276 pair beside the origin, hull to 1e297 (4263 vertices, 25 problems before)
    "corner-pair": [("0x0.0p+0", "0x0.0p+0"), ("0x1.63a4cd2ef47a6p+986", "0x0.0p+0"),
                    ("0x0.0p+0", "0x1.5f5702b79b8f3p-308"), ("0x1.ce13074608b20p-916", "0x1.88cf361811bdcp-913"),
                    ("0x1.ce13074608b20p-916", "0x0.0p+0")],
    # ... with the third hull vertex at 1e117 (the vertex limit, a million vertices, before)
    "corner-pair-1e117": [("0x0.0p+0", "0x0.0p+0"), ("0x1.4c0ed28111cb9p+931", "0x0.0p+0"),
                          ("0x0.0p+0", "0x1.40d1f937c738ep+390"), ("0x1.58b93eb18a838p-875", "0x1.d7b2a499926e6p-874"),
                          ("0x1.58b93eb18a838p-875", "0x0.0p+0")],
    # scattered signs, 1e-261 .. 1e285 (one clockwise triangle before)
    "scattered": [("-0x1.6743552ac70d2p-866", "0x1.f96bfd0c65c76p+948"), ("-0x1.f96bfd0c65c76p+948", "0x1.11c57ec36d273p-459"),
                  ("0x1.11c57ec36d273p-459", "0x0.0p+0"), ("-0x1.11c57ec36d273p-459", "-0x1.6743552ac70d2p-866"),
                  ("0x1.6743552ac70d2p-866", "-0x1.6743552ac70d2p-866")],
}


def _pslg(name: str, switches: str) -> dict:
    vertices = np.array([[float.fromhex(x), float.fromhex(y)] for x, y in POINT_SETS[name]])
    pslg = {"vertices": vertices}
    if "p" in switches:  # the hull as segments
        pslg["segments"] = instrument.triangulate({"vertices": vertices}, "cQ")["segments"]
    return pslg


@pytest.mark.parametrize("switches", ["qYQ", "qYYQ", "pqYQ"])
@pytest.mark.parametrize("name", sorted(POINT_SETS))
def test_mixed_scale_quality_under_y_is_valid(name, switches):
    pslg = _pslg(name, switches)
    result = instrument.triangulate(pslg, switches)
    assert check_mesh(result, pslg=pslg) == []
    assert len(result["vertices"]) > len(pslg["vertices"])  # refinement ran


@pytest.mark.parametrize("budget", range(6, 12))
def test_each_step_around_the_first_bad_one_is_valid(budget):
    """The regression's eighth Steiner point was the one across the hull."""
    pslg = _pslg("regression", "qYQ")
    result = instrument.triangulate(pslg, f"qYQS{budget}")
    assert check_mesh(result, pslg=pslg) == []
