"""A subsegment split whose rounded point would make a flat triangle (issue 18).

Four points, two of them 4.2e-193 apart at x = 0.00143909...: the free input
vertex D = (x0, 4.2e-193) lies inside the hull next to its corner C = (x0, 0)
and encroaches every piece of the hull edge from C that refinement makes, so
the pieces shrink towards C. Near 5e-17 from C the split point rounds onto the
vertical line x = x0 through C and D, and the fan of the split held the flat
triangle (C, D, P): a zero-area triangle in the output (Triangle's own mesh
of this input has one too). D then lies on the piece within the rounding the
split points themselves have, and the piece is split at D instead, which
ends the encroachment. Where no such vertex explains it, refinement runs out
of precision (a clear error) rather than output a flat triangle.
"""

from __future__ import annotations

import numpy as np
import pytest

import instrument
from instrument.check import check_mesh
from instrument.refine import PrecisionError

X0 = 0.0014390945434570312
POINTS = np.array([[0.00027942657470703125, 0.24972057342529297], [1.0, -0.75], [X0, 0.0], [X0, 4.2272262896050957e-193]])


@pytest.mark.parametrize("area", ["0.005", "0.05", "0.5"])
def test_area_refinement_next_to_a_tiny_gap_is_valid(area):
    out = instrument.triangulate({"vertices": POINTS}, f"a{area}Q")
    assert check_mesh(out, max_area=float(area)) == []
    # D is a vertex of the mesh, on the hull chain from C
    assert any((out["vertices"] == POINTS[3]).all(axis=1))


def test_quality_refinement_runs_out_of_precision_clearly():
    # a bad triangle on the 4e-193 edge C D cannot be split in doubles (nor by Triangle)
    with pytest.raises(PrecisionError, match="Ran out of precision"):
        instrument.triangulate({"vertices": POINTS}, "qQ")


def test_with_more_points_around():
    # the campaign's original: 19 collinear-family points, za0.005iQ (Triangle's mesh is valid)
    pts = np.array([
        [0.0163116455078125, 0.2336883544921875], [0.013470649719238281, 0.23652935028076172],
        [0.7917699813842773, -0.5417699813842773], [0.0010213851928710938, 0.2489786148071289],
        [0.00040912628173828125, 0.24959087371826172], [0.9999990463256836, -0.7499990463256836],
        [0.0009326934814453125, 0.2490673065185547], [1.0, -0.75], [0.0048618316650390625, 0.24513816833496094],
        [0.00054931640625, 0.24945068359375], [0.0019598007202148438, 0.24804019927978516],
        [0.0199737548828125, 0.2300262451171875], [0.00027942657470703125, 0.24972057342529297],
        [0.012432098388671875, 0.23756790161132812], [0.10851573944091797, 0.14148426055908203],
        [0.0029420852661132812, 0.24705791473388672], [1.0, -0.75], [X0, 0.0], [X0, 4.2272262896050957e-193],
    ])
    for switches in ("za0.005iQ", "a0.005Q"):
        out = instrument.triangulate({"vertices": pts}, switches)
        assert check_mesh(out, max_area=0.005) == []


@pytest.mark.parametrize(("area", "vertices"), [("0.00000000000000000501", 153), ("0.00000000000000001", 77), ("0.0000000000000001", 11)])
def test_a_sliver_is_split_along_its_length(area, vertices):
    """A sliver of length 1 and width 1e-15: the midpoint (0.5, -5e-16) of
    one long side was taken as lying on the other long side within rounding
    (a tolerance of units in the last place of the largest coordinate, 1,
    where the y coordinates round 1e-31 apart), and the split there failed:
    PrecisionError. Triangle meshes it with 153, 77 and 11 vertices; so does
    ours now."""
    sliver = {"vertices": np.array([[0.0, 0.0], [1.0, 2.6226043701171877e-18], [1.0, -1e-15]]),
              "segments": np.array([[0, 1], [1, 2], [2, 0]])}
    out = instrument.triangulate(sliver, f"pa{area}Q")
    assert check_mesh(out, pslg=sliver, max_area=float(area)) == []
    assert len(out["vertices"]) == vertices


# Two points 2^-1022 apart on the line x = XD (where the next double is 2e-19
# away) beside two near 1 and one at 2^-149: the shortest edge of every
# needle on that pair is too short beside XD for any point off it, so no mesh
# of doubles has the angle. The needles' off-centers, computed again from
# their shortest edge's ends, rounded onto the edge; the walk from that edge
# called such a point inside, and the edge was halved without end (2^52
# doubles deep), each split's walk a little longer: 2.4 million walk steps at
# 3,000 vertices, the run hours from the vertex limit (the differential
# harness's campaign: regressions/denormal-needle-midpoint-precision.json;
# Triangle crashes).
XD = 0.0014896392822265625
DENORMAL_PAIR = np.array([[XD, 0.0], [0.09136676788330078, 0.11895487684143616],
                          [1.049041748046875e-05, 2.0**-149], [XD, 2.0**-1022]])


@pytest.mark.parametrize("switches", ["qQ", "q10Q", "q30Q", "cq20Q", "q10a0.001Q"])
def test_a_needle_on_a_denormal_edge_runs_out_of_precision(switches):
    # (-S: were the split point placed again, the run ends with a mesh, fast)
    with pytest.raises(PrecisionError, match="shortest edge is too short"):
        instrument.triangulate({"vertices": DENORMAL_PAIR}, switches + "S1000")


@pytest.mark.parametrize("switches", ["q10Q", "q30Q"])
def test_a_needle_on_a_denormal_edge_under_circumcenters_runs_out_of_precision(switches):
    # the needle's 0.5 / area overflows, so its circumcenter was NaN, the
    # split skipped as a duplicate, and a mesh with 0-degree needles returned.
    # Since the needle's circumcenter is computed from its short edge's ends
    # (criteria._needle_circumcenter) it is placed, half the needle's length
    # away; the needles it leaves on the pair encroach the hull subsegment
    # (XD, 0) (XD, 2^-1022), halved to adjacent doubles: a segment too short
    # to split (the pair has no mesh of doubles with the angle either way)
    with pytest.raises(PrecisionError, match="a segment to a smaller size"):
        instrument.triangulate({"vertices": DENORMAL_PAIR}, switches + "S1000", steiner="circumcenter")


@pytest.mark.parametrize("switches", ["q10Q", "qQ"])
def test_a_needle_whose_split_point_rounds_onto_its_corner_runs_out_of_precision(switches):
    # the needle alone: its off-center, computed from the far corner, rounds
    # onto the corner (XD, 0); skipped as a duplicate, the needle was returned
    # with its 0-degree angle.  Its shortest edge is a hull subsegment, which
    # the rounded point encroaches: the subsegment is split (as Triangle
    # treats a point on a subsegment) down to adjacent doubles, and the
    # error names that segment
    needle = {"vertices": DENORMAL_PAIR[[0, 2, 3]]}
    with pytest.raises(PrecisionError, match=r"split a segment to a smaller size(.|\n)*segment \(0\.00148963928223, "):
        instrument.triangulate(needle, switches)


def test_the_denormal_pair_under_an_area_bound_alone_is_valid():
    out = instrument.triangulate({"vertices": DENORMAL_PAIR}, "a0.0001Q")
    assert check_mesh(out, max_area=0.0001) == []
    assert any((out["vertices"] == DENORMAL_PAIR[3]).all(axis=1))


# A needle whose short edge, 2.3e-271 long near the origin, has its far corner
# 3.4e-27 away: its longest edge is in range, so the circumcenter was computed
# unscaled, where the short edge's square (4e-542) and every product placing
# the circumcenter along it vanish to 0; the circumcenter then won against
# the off-center at the short edge's org, and the split ran out of precision
# (the needle of FAR_CORNER_CASE in test_mixed_scale_refinement.py, here
# inside two points 1e-26 away).  Doubles hold its off-center and its
# circumcenter, computed from the short edge's ends (criteria.steiner_point).
FAR_NEEDLE = np.array([[2.0113627935003086e-271, -3.733237141971085e-272], [0.0, -7.46647428394217e-272],
                       [-5.252429815216489e-148, -3.44324249045832e-27], [1e-26, 1e-27], [-1e-26, 1e-27]])


@pytest.mark.parametrize(("switches", "angle", "steiner"), [
    ("qQ", 20.0, "offcenter"), ("q30Q", 30.0, "offcenter"), ("qQ", 20.0, "circumcenter"),
])
def test_a_needle_beside_a_far_corner_is_split_where_doubles_hold_the_point(switches, angle, steiner):
    out = instrument.triangulate({"vertices": FAR_NEEDLE}, switches, steiner=steiner)
    assert check_mesh(out, min_angle=angle) == []


def test_an_ulp_sized_triangle_beside_crossing_segments_is_left_as_triangle_leaves_it():
    """Two segments crossing at 5 degrees near 2^-101 and a free input vertex
    2e-48 from the crossing, within rounding of one of them (pq20c): the
    vertex encroaches the pieces at the crossing, which are halved down to
    ulps, and so are the triangles between them, as in Triangle's mesh.  A
    triangle 1 ulp by 16 (about 4 degrees) had its off-center rounded onto
    its shortest edge, and refinement ran out of precision; Triangle skips
    the point as a duplicate vertex and makes 4,171 vertices.  Ours now skips
    it too (a needle, the angle zero to 1e-6 degrees, still runs out of
    precision: above)."""
    v = np.array([[float.fromhex(x) for x in p] for p in [
        ("0x1.0506000000000p-106", "0x1.4300000000000p-112"), ("0x1.0580000000000p-111", "0x1.f300000000000p-111"),
        ("0x1.0506000000000p-106", "0x1.620349ed411b5p-103"), ("0x1.0000000000000p-120", "0x1.5000000000000p-116"),
        ("0x1.f300000000000p-111", "0x1.620349ed411b5p-103"), ("-0x1.964b64e770940p-111", "-0x1.5e0b5727bafe2p-103"),
        ("0x1.72d26c623dafep-114", "0x1.fbf962c30e9fep-111"), ("0x1.b5d0400000000p-103", "0x1.0506000000000p-106"),
    ]])
    pslg = {"vertices": v, "segments": np.array([[2, 3], [4, 5]])}
    out = instrument.triangulate(pslg, "pq20cQ")
    assert check_mesh(out, pslg=pslg) == []
    assert out.work["duplicate_vertices"] > 0
    assert 4000 < len(out["vertices"]) < 4300
