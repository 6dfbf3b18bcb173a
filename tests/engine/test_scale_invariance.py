"""Meshing at 2^k gives the mesh of scale 1 times 2^k (issue 18's precision defects).

Multiplying every coordinate by a power of two changes no rounding until a
product leaves the double range, so a mesher whose every length, area and
lens test is of bounded degree meets that degree's range long before the
coordinates do: squared lengths overflow beyond 2^511, the lens test (degree
4) beyond 2^256, and products of two orient2d values vanish near 2^-512.
Each such place now scales its operands by a power of two where they are
out of range (and computes as before where they are not), so the meshes
below are the scale-1 meshes multiplied by 2^k, bit for bit.

* recover-tiny-extent: three polygons at 6e-155 under ``p``; flipping the
  edges a segment crosses compared ``sx * sy < 0`` of two orient2d values,
  which underflowed to 0, left a crossing edge unflipped and failed.
* huge-refinement-precision: the triangle (1.19e175, 0), (0, 0), (0, 3.96e174)
  under ``pqc``: the lens test said every apex encroached (inf >= inf), the
  on-subsegment test found every vertex on every subsegment (inf <= inf),
  and the refinement ran to a PrecisionError.
"""

from __future__ import annotations

import math
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
import triangle

import instrument
from instrument.check import check_mesh
from instrument.core.predicates import incircle, orient2d

ROOT = Path(__file__).resolve().parents[2]


def _mesh_at(pslg: dict, switches: str, k: int) -> dict:
    scaled = dict(pslg, vertices=np.ldexp(pslg["vertices"], k))
    if "holes" in pslg:
        scaled["holes"] = np.ldexp(pslg["holes"], k)
    return scaled, instrument.triangulate(scaled, switches)


def _assert_scaled_copy(pslg, switches, k, min_angle=None, same=True):
    # the reference is at 2^+-50, not 1: Triangle's queue buckets a squared
    # edge below 1 by its reciprocal, whose rounding differs (Triangle's own
    # mesh of the triangle below has 6 vertices at scale 1, 7 at 4 and 2^100)
    k0 = 50 if k > 0 else -50
    _, base = _mesh_at(pslg, switches, k0)
    scaled, out = _mesh_at(pslg, switches, k)
    problems = check_mesh(out, pslg=scaled if "p" in switches else None, min_angle=min_angle)
    assert problems == [], problems
    if not same:
        return
    assert np.array_equal(out["triangles"], base["triangles"])
    assert np.array_equal(out["vertices"], np.ldexp(base["vertices"], k - k0))


def _tiny_polygons() -> dict:
    from tests.differential.cases import read_case

    case, _ = read_case(ROOT / "tests" / "differential" / "regressions" / "recover-tiny-extent-p.json")
    return {key: np.asarray(v) for key, v in case.input.items()}


@pytest.mark.parametrize("k", [0, 300, 500, -200, -300])
def test_three_polygons_near_6e_155_recover_their_segments(k):
    pslg = _tiny_polygons()  # as the campaign found it: coordinates near 2^-512
    scaled, out = _mesh_at(pslg, "pjQ", k)
    assert check_mesh(out, pslg=scaled) == []
    assert len(out["triangles"]) == 6  # Triangle's count at 2^-512 and ours at every scale
    base = instrument.triangulate(dict(pslg, vertices=np.ldexp(pslg["vertices"], 512),
                                       holes=np.ldexp(pslg["holes"], 512)), "pjQ")
    assert np.array_equal(out["triangles"], base["triangles"])
    assert np.array_equal(out["vertices"], np.ldexp(base["vertices"], k - 512))


@pytest.mark.parametrize("k", [300, 520, 580, 900, -520, -560])
def test_right_triangle_refines_as_at_scale_one(k):
    pslg = {"vertices": np.array([[1.5, 0.0], [0.0, 0.0], [0.0, 0.5], [1.5, 0.0]])}
    _assert_scaled_copy(pslg, "pqcQ", k, min_angle=20)


@pytest.mark.parametrize("k", [300, 480, 520, 700, -300, -480])
def test_lens_and_exemption_tests_are_scale_free(k):
    a = triangle.get_data("A")
    s = np.abs(a["vertices"]).max()
    pslg = {"vertices": a["vertices"] / s, "segments": a["segments"], "holes": a["holes"] / s}
    # beyond 2^511 some degree-2 step still rounds differently (83 vertices
    # against 78 at 2^520): valid, not yet the same mesh
    _assert_scaled_copy(pslg, "pq30Q", k, min_angle=30, same=abs(k) <= 480)


# ---------------------------------------------------------------------------
# The predicates' wide-range path (coordinates 2^465 or more apart in one call)
# ---------------------------------------------------------------------------
def _exact_incircle(ax, ay, bx, by, cx, cy, dx, dy):
    ax, ay, bx, by, cx, cy, dx, dy = map(Fraction, (ax, ay, bx, by, cx, cy, dx, dy))
    adx, ady, bdx, bdy, cdx, cdy = ax - dx, ay - dy, bx - dx, by - dy, cx - dx, cy - dy
    return ((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
            + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady))


def _exact_orient(ax, ay, bx, by, cx, cy):
    ax, ay, bx, by, cx, cy = map(Fraction, (ax, ay, bx, by, cx, cy))
    return (ax - cx) * (by - cy) - (ay - cy) * (bx - cx)


def _sign(x) -> int:
    return int(x > 0) - int(x < 0)


def test_wide_range_signs_are_exact():
    rng = np.random.default_rng(18)
    cases = [
        # three points 1e-152 apart, a fourth 1e139 away (undecided from the far one)
        (3.97e-153, 8.74e-153, 7.99e-152, 8.5e-152, 8.5e-152, 1.66e-151, 0.0, 1.78e139),
        (0.0, 0.0, 8.07e177, 0.0, 6.3e-182, 6.71e-182, 6.71e-182, 1.31e-181),
        (0.0, 0.0, 2.0**600, 2.0**-600, 2.0**601, 2.0**-599, 1.0, 1.0),
    ]
    for i in range(400):
        c = rng.uniform(0.5, 1, 8) * np.exp2(rng.integers(-1000, 1000, 8))
        if i % 2:  # a cluster: some points 2^-900 of the others
            c = np.where(rng.random(8) < 0.5, c * 2.0**-900, c)
        c *= rng.choice([-1.0, 1.0, 0.0], size=8, p=[0.45, 0.45, 0.1])
        cases.append(tuple(float(v) for v in c))
    for c in cases:
        assert _sign(incircle(*c)) == _sign(_exact_incircle(*c)), c
        assert _sign(orient2d(*c[:6])) == _sign(_exact_orient(*c[:6])), c
    # exact degeneracies the filter cannot decide, through the integer fallback
    big, small = 2.0**600, 2.0**-600
    assert orient2d(0.0, 0.0, big, small, 2 * big, 2 * small) == 0
    assert incircle(65.0 * big, 0.0, 0.0, 65.0 * big, -65.0 * big, 0.0, 0.0, -65.0 * big) == 0
    assert orient2d(0.0, 0.0, 1e300, 1e-300, -1e-300, 1e300) == 1.7976931348623157e308
    assert orient2d(0.0, 0.0, 1e-300, 0.0, 1e300, 1e-300) == 5e-324
    assert math.isfinite(incircle(1e-300, 0.0, 0.0, 1e300, -1e300, 0.0, 0.0, -1e-300))


CROSSING_NEAR_2_TO_MINUS_1000 = {
    # a square of side 1.5 * 2^-997 with a segment through its corner (0, 0) crossed
    # by a horizontal one 1.5 * 2^-1004 above it, near but not at that corner
    "vertices": [[0.0, 0.0], [1.5 * 2.0**-997, 0.0], [1.5 * 2.0**-997, 1.5 * 2.0**-997], [0.0, 1.5 * 2.0**-997],
                 [1.5 * 2.0**-1003, 1.5 * 2.0**-998], [-1.5 * 2.0**-1003, -1.5 * 2.0**-998],
                 [2.0**-1009, 1.5 * 2.0**-1004], [1.5 * 2.0**-997, 1.5 * 2.0**-1004]],
    "segments": [[1, 2], [2, 3], [3, 0], [4, 5], [6, 7]],
}


@pytest.mark.parametrize("k", [0, 100, 300, 1000])
def test_a_crossing_near_2_to_minus_1000_is_a_vertex_of_its_own(k):
    """Segment recovery took a crossing point within an absolute 1e-300 of a
    vertex to be that vertex: near 1e-300 the horizontal segment was bent
    through the corner (0, 0) and the mesh was invalid."""
    inp = {"vertices": np.ldexp(np.array(CROSSING_NEAR_2_TO_MINUS_1000["vertices"]), k),
           "segments": np.array(CROSSING_NEAR_2_TO_MINUS_1000["segments"])}
    r = instrument.triangulate(inp, "pQ")
    assert check_mesh(r, pslg=inp) == []
    assert len(r["vertices"]) == 9  # the crossing vertex
    assert sorted(map(sorted, r["segments"].tolist())) == [[0, 3], [0, 8], [2, 3], [2, 7], [4, 8], [6, 8], [7, 8]]


@pytest.mark.parametrize("switches, angle", [("pq30Q", 30), ("pq33Q", 33)])
def test_the_mesh_is_one_mesh_times_the_scale(switches, angle):
    """A.poly times 2^k is one mesh times 2^k (vertices, triangles and work
    counters) from 2^-300 to 2^300 and another from 2^520 to 2^900 and
    2^-520 to 2^-1000, with the same counts.  Beyond 2^+-512 squared
    lengths over- or underflow: Chew's deletion tested the sign of a dot
    product and point location picked its direction from another, and both
    now scale (core.scaling.scaled_dot); Triangle's queue buckets keyed on
    squared shortest edges, which all fell into the first or last bucket (85
    vertices against 76 under pq30), and are now measured in a unit that
    brings an input's extent to about 1 where it lies beyond 2^+-400
    (refine.key_unit).  In range nothing changes: Triangle's keys."""
    A = triangle.get_data("A")
    meshes = []
    for k in (0, 300, 520, 700, 900, -300, -520, -600, -1000):
        inp = {**A, "vertices": np.ldexp(A["vertices"], k), "holes": np.ldexp(A["holes"], k)}
        r = instrument.triangulate(inp, switches)
        assert check_mesh(r, pslg=inp, min_angle=angle) == []
        meshes.append((k, np.ldexp(r["vertices"], -k), r["triangles"], r.work))
    # within 2^+-480 or so every step computes as at scale 1; beyond, the
    # quality test and the Steiner point scale each triangle by its own power
    # of two, which rounds some points an ulp apart from scale 1's: one
    # mesh (bit for bit) per side, and the same counts on both
    inside = [m for m in meshes if abs(m[0]) <= 300]
    beyond = [m for m in meshes if abs(m[0]) > 300]
    for group in (inside, beyond):
        for k, v, t, w in group[1:]:
            assert np.array_equal(v, group[0][1]) and np.array_equal(t, group[0][2]) and w == group[0][3], k
    assert len(inside[0][1]) == len(beyond[0][1]) and len(inside[0][2]) == len(beyond[0][2])


INTERIOR_SEGMENT = {
    # a unit square with an interior segment that the vertex above it encroaches
    "vertices": [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.2, 0.5], [0.8, 0.5], [0.5, 0.53]],
    "segments": [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5]],
}


@pytest.mark.parametrize("k", [-540, -600, -1000])
@pytest.mark.parametrize("switches", ["pqQ", "pDQ"])
def test_interior_subsegments_are_pooled_at_any_scale(switches, k):
    """Refinement pools the encroached subsegments of the input by one side
    of each, the side running along its segment (refine.splits.first_side):
    below 2^-537 that dot product vanished, no interior subsegment had such
    a side, and none was pooled (under pDQ 10 vertices against 11 at scale
    1; the bent split of tests/engine/test_split_bent.py never happened at
    1e-200).  The mesh, and the work counted, are scale 2^-50's times 2^k."""
    pslg = {"vertices": np.array(INTERIOR_SEGMENT["vertices"]), "segments": np.array(INTERIOR_SEGMENT["segments"])}
    _, base = _mesh_at(pslg, switches, -50)
    scaled, out = _mesh_at(pslg, switches, k)
    assert check_mesh(out, pslg=scaled, min_angle=20 if "q" in switches else None) == []
    assert np.array_equal(out["triangles"], base["triangles"])
    assert np.array_equal(out["vertices"], np.ldexp(base["vertices"], k + 50))
    assert out.work == base.work
