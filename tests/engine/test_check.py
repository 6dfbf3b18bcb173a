"""Tests of the independent mesh checker ``instrument.check``.

Triangle itself (the ``triangle`` package) produces the good meshes; every kind
of damage the checker must find is then made by hand.
"""

from __future__ import annotations

import math
import time
from fractions import Fraction

import numpy as np
import pytest
import triangle
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import instrument
from instrument.check import (
    check_mesh,
    incircle_exact,
    incircle_signs,
    mesh_area,
    orient_exact,
    orient_signs,
    quality_report,
)

# --------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------


def frac_orient(a, b, c):
    a, b, c = ([Fraction(float(x)) for x in p] for p in (a, b, c))
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def frac_incircle(a, b, c, d):
    a, b, c, d = ([Fraction(float(x)) for x in p] for p in (a, b, c, d))
    adx, ady = a[0] - d[0], a[1] - d[1]
    bdx, bdy = b[0] - d[0], b[1] - d[1]
    cdx, cdy = c[0] - d[0], c[1] - d[1]
    v = ((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy)
         + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
         + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady))
    return (v > 0) - (v < 0)


def naive_incircle(a, b, c, d):
    adx, ady = a[0] - d[0], a[1] - d[1]
    bdx, bdy = b[0] - d[0], b[1] - d[1]
    cdx, cdy = c[0] - d[0], c[1] - d[1]
    v = ((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy)
         + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
         + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady))
    return int(np.sign(v))


def mesh(vertices, triangles, segments=None):
    out = {
        "vertices": np.asarray(vertices, dtype=np.float64).reshape(-1, 2),
        "triangles": np.asarray(triangles, dtype=np.int32).reshape(-1, 3),
    }
    if segments is not None:
        out["segments"] = np.asarray(segments, dtype=np.int32).reshape(-1, 2)
    return out


def copy(result):
    return {k: np.array(v) for k, v in result.items()}


def has(problems, text):
    return any(text in p for p in problems)


def edge_map(tris):
    """directed edge (a, b) -> (triangle, apex)."""
    out = {}
    for t, (a, b, c) in enumerate(np.asarray(tris)[:, :3].tolist()):
        out[(a, b)] = (t, c)
        out[(b, c)] = (t, a)
        out[(c, a)] = (t, b)
    return out


def convex_interior_edges(result):
    """(a, b, t1, c, t2, d) for interior edges whose quadrilateral is strictly convex."""
    V = result["vertices"]
    em = edge_map(result["triangles"])
    out = []
    for (a, b), (t1, c) in em.items():
        if a < b and (b, a) in em:
            t2, d = em[(b, a)]
            if orient_exact(V[c], V[a], V[d]) > 0 and orient_exact(V[d], V[b], V[c]) > 0:
                out.append((a, b, t1, c, t2, d))
    return out


def flip(result, edge):
    a, b, t1, c, t2, d = edge
    r = copy(result)
    r["triangles"][t1, :3] = (c, a, d)
    r["triangles"][t2, :3] = (d, b, c)
    return r


def pslg(name):
    return triangle.get_data(name)


# --------------------------------------------------------------------------
# exact predicates
# --------------------------------------------------------------------------


def test_orient_signs_on_near_collinear_grid():
    # robust-predicates' classic: a 32x32 grid of ulp-perturbed points near
    # the line through (12, 12) and (24, 24); naive float gets signs wrong.
    ulp = 2.0**-53
    xs = 0.5 + np.arange(32) * ulp
    a = np.array([(x, y) for x in xs for y in xs])
    b = np.tile([12.0, 12.0], (len(a), 1))
    c = np.tile([24.0, 24.0], (len(a), 1))
    got = orient_signs(a, b, c)
    want = np.array([frac_orient(p, q, r) for p, q, r in zip(a, b, c)])
    assert (got == want).all()
    naive = np.sign((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))
    assert (naive != want).any()  # the test is meaningful
    assert {-1, 0, 1} <= set(want.tolist())
    assert [orient_exact(p, q, r) for p, q, r in zip(a[:64], b[:64], c[:64])] == want[:64].tolist()


def test_orient_sign_convention():
    assert orient_exact((0, 0), (1, 0), (0, 1)) == 1
    assert orient_exact((0, 0), (0, 1), (1, 0)) == -1
    assert orient_exact((0, 0), (1, 1), (3, 3)) == 0
    assert incircle_exact((0, 0), (1, 0), (0, 1), (0.5, 0.5)) == 1
    assert incircle_exact((0, 0), (1, 0), (0, 1), (1, 1)) == 0
    assert incircle_exact((0, 0), (1, 0), (0, 1), (2, 2)) == -1
    with pytest.raises((ValueError, OverflowError)):
        orient_exact((0, 0), (1, 0), (math.nan, 1))


# Four points within 1 ulp of one circle, for which the floating-point
# incircle formula returns the wrong sign (found by search, see the report).
NEAR_COCIRCULAR = [
    # a, b, c (counter-clockwise on the circle), d, exact sign
    ((1000.571378077778, 1001.85330834801), (999.6066768533065, 1001.7911304788661),
     (999.1868115420677, 1001.2336211456183), (1000.977884183231, 1000.3946553805879), 1),
    ((1001.5007130879278, 1000.72666195368), (1001.4713838265957, 1000.9337744384146),
     (1001.0940201585591, 1001.4962263424944), (1000.176331267916, 999.7450706688618), -1),
]


@pytest.mark.parametrize("a,b,c,d,sign", NEAR_COCIRCULAR)
def test_incircle_exact_beats_floating_point(a, b, c, d, sign):
    assert frac_incircle(a, b, c, d) == sign
    assert naive_incircle(a, b, c, d) == -sign  # float is wrong here
    assert incircle_exact(a, b, c, d) == sign
    assert incircle_signs([a], [b], [c], [d]).tolist() == [sign]
    # As a mesh: quadrilateral a, b, c, d with either diagonal.
    diag_ac = mesh([a, b, c, d], [(0, 1, 2), (0, 2, 3)])
    diag_bd = mesh([a, b, c, d], [(0, 1, 3), (1, 2, 3)])
    if sign > 0:  # d strictly inside circle(a, b, c): a-c is illegal, b-d legal
        assert has(check_mesh(diag_ac), "not locally Delaunay")
        assert check_mesh(diag_bd) == []
    else:  # d strictly outside: a-c is legal, b-d illegal
        assert check_mesh(diag_ac) == []
        assert has(check_mesh(diag_bd), "not locally Delaunay")


coord = st.integers(-8, 8).map(lambda k: 0.1 + k * 2.0**-52)
big = st.floats(-1e6, 1e6, allow_nan=False, allow_infinity=False)


@settings(max_examples=150, deadline=None)
@given(st.lists(st.tuples(st.one_of(coord, big), st.one_of(coord, big)), min_size=4, max_size=4))
def test_signs_match_fractions(pts):
    a, b, c, d = pts
    assert orient_exact(a, b, c) == frac_orient(a, b, c)
    assert orient_signs([a], [b], [c])[0] == frac_orient(a, b, c)
    assert incircle_exact(a, b, c, d) == frac_incircle(a, b, c, d)
    assert incircle_signs([a], [b], [c], [d])[0] == frac_incircle(a, b, c, d)


def test_extreme_magnitudes_use_the_exact_path():
    for s in (2.0**-1060, 2.0**-600, 2.0**600):
        a, b, c, d = (0, 0), (3 * s, 0), (0, 3 * s), (2 * s, 2 * s)
        assert orient_signs([a], [b], [c])[0] == 1 == orient_exact(a, b, c)
        assert incircle_signs([a], [b], [c], [d])[0] == frac_incircle(a, b, c, d) == 1
        far = (4 * s, 4 * s)
        assert incircle_signs([a], [b], [c], [far])[0] == incircle_exact(a, b, c, far) == -1


# --------------------------------------------------------------------------
# Triangle's own meshes pass
# --------------------------------------------------------------------------

GOOD = [
    ("A", "p", None), ("A", "pq20", 20), ("A", "pq30", 30), ("A", "pq30a0.001", 30),
    ("A", "pcq30", 30), ("A", "pDq30", 30), ("A", "pq30o2", 30),
    ("la", "p", None), ("la", "pq20", 20), ("la", "pq30", 30), ("la", "pcq30", 30),
    ("la", "pq33", 33), ("la", "pDq30", 30),
    ("face", "p", None), ("face", "pq30", 30), ("face", "pcq30", 30),
    ("box", "p", None), ("box", "pq30", 30), ("box", "pcq30", 30),
    ("double_hex", "pq30", 30), ("square_circle_hole", "pq30a0.001", 30),
]


@pytest.mark.parametrize("name,opts,angle", GOOD)
def test_triangle_meshes_pass(name, opts, angle):
    d = pslg(name)
    r = triangle.triangulate(d, opts)
    assert check_mesh(r, d, angle) == []
    assert check_mesh(r, None, angle) == []  # the exemption also works without the PSLG


def test_empty_mesh_is_fine():
    d = pslg("box")
    r = triangle.triangulate(d, "p")
    assert "triangles" not in r
    assert check_mesh(r, d, 30) == []
    assert mesh_area(r) == 0.0


def test_A_pq30_needs_no_exemption():
    d = pslg("A")
    rep = quality_report(triangle.triangulate(d, "pq30"), d, 30)
    assert rep["n_bad"] == 0 and rep["n_exempt"] == 0
    assert rep["min_angle_deg"] >= 30


@pytest.mark.parametrize("opts,angle", [("pq30", 30), ("pq20", 20), ("pq33", 33)])
def test_la_passes_only_thanks_to_the_exemption(opts, angle):
    d = pslg("la")  # a 4.09 degree input angle
    r = triangle.triangulate(d, opts)
    rep = quality_report(r, d, angle)
    assert rep["n_bad"] > 0 and rep["n_exempt"] == rep["n_bad"]
    assert rep["min_angle_deg"] < 5
    assert check_mesh(r, d, angle) == []


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("opts,angle", [("", None), ("q30", 30), ("cq25", 25), ("q20a0.01", 20)])
def test_random_points_pass(seed, opts, angle):
    pts = np.random.default_rng(seed).random((300, 2))
    r = triangle.triangulate({"vertices": pts}, opts)
    assert check_mesh(r, {"vertices": pts}, angle) == []


# --------------------------------------------------------------------------
# damaged meshes are caught
# --------------------------------------------------------------------------


@pytest.fixture(scope="module")
def rand_mesh():
    pts = np.random.default_rng(7).random((400, 2))
    return triangle.triangulate({"vertices": pts}, "")


@pytest.fixture(scope="module")
def A30():
    d = pslg("A")
    return d, triangle.triangulate(d, "pq30")


def test_flipped_orientation(rand_mesh):
    r = copy(rand_mesh)
    r["triangles"][5] = r["triangles"][5][::-1]
    p = check_mesh(r)
    assert has(p, "triangle 5 ") and has(p, "is clockwise")
    assert has(p, "directed edge")


def test_edge_flip_is_not_delaunay(rand_mesh):
    edges = convex_interior_edges(rand_mesh)
    assert edges
    r = flip(rand_mesh, edges[len(edges) // 2])
    p = check_mesh(r)
    assert p and all("not locally Delaunay" in x for x in p), p
    assert check_mesh(r, delaunay=False) == []


def test_removed_subsegment_edge(A30):
    d, r0 = A30
    r = copy(r0)
    a, b = r["segments"][3]
    em = edge_map(r["triangles"])
    t = em.get((a, b), em.get((b, a)))[0]
    r["triangles"] = np.delete(r["triangles"], t, axis=0)
    p = check_mesh(r, d, 30)
    assert has(p, "segment 3 ") and has(p, "is not an edge of any triangle")


def test_flipped_interior_subsegment():
    d = pslg("la")  # la has interior segments between regions
    r0 = triangle.triangulate(d, "pq30")
    segs = {tuple(sorted(s)) for s in r0["segments"].tolist()}
    edge = next(e for e in convex_interior_edges(r0) if (e[0], e[1]) in segs)
    r = flip(r0, edge)
    p = check_mesh(r, d, None, delaunay=False, markers=False)
    assert has(p, "is not an edge of any triangle")


def test_duplicate_triangle(rand_mesh):
    r = copy(rand_mesh)
    r["triangles"] = np.vstack([r["triangles"], r["triangles"][10][[1, 2, 0]]])
    p = check_mesh(r)
    assert has(p, "duplicate triangles [10, ")


def test_out_of_range_index(rand_mesh):
    for bad in (len(rand_mesh["vertices"]), -1):
        r = copy(rand_mesh)
        r["triangles"][0, 1] = bad
        assert has(check_mesh(r), "triangle 0 has a vertex index out of range")


def test_repeated_corner_and_zero_area(rand_mesh):
    r = copy(rand_mesh)
    r["triangles"][0, 1] = r["triangles"][0, 0]
    assert has(check_mesh(r), "repeats a corner")
    z = mesh([(0, 0), (1, 1), (3, 3), (0, 5)], [(0, 1, 2), (0, 2, 3)])
    assert has(check_mesh(z), "zero area")


def test_overlapping_separate_triangle(rand_mesh):
    r = copy(rand_mesh)
    n = len(r["vertices"])
    r["vertices"] = np.vstack([r["vertices"], [(0.3, 0.3), (0.6, 0.31), (0.4, 0.7)]])
    r["triangles"] = np.vstack([r["triangles"], [(n, n + 1, n + 2)]])
    r["vertex_markers"] = np.vstack([r["vertex_markers"], [[0], [0], [0]]])
    p = check_mesh(r)
    assert p and all("meets the interior of boundary edge" in x for x in p if "more" not in x)


def test_overlapping_triangle_on_existing_vertices(A30):
    d, r0 = A30
    r = copy(r0)
    em = edge_map(r["triangles"])
    (a, b), (t, c) = next(iter(em.items()))
    r["triangles"] = np.vstack([r["triangles"], [(a, b, c)]])
    assert has(check_mesh(r, d, 30), "duplicate triangles")
    # a triangle over an interior edge, made of that edge's two apexes
    a, b, t1, c, t2, dd = convex_interior_edges(r0)[0]
    r = copy(r0)
    r["triangles"] = np.vstack([r["triangles"], [(c, a, dd)]])
    p = check_mesh(r, d, 30)
    assert has(p, "directed edge") or has(p, "shared by 3 triangles")


def test_crossing_slivers_are_caught():
    # No vertex and no edge midpoint of either triangle lies in the other.
    m = mesh([(0, 0), (10, 0), (0, 1), (2, -10), (2.1, -10), (2, 3)], [(0, 1, 2), (3, 4, 5)])
    assert has(check_mesh(m, delaunay=False), "meets the interior of boundary edge")


def test_double_cover_around_a_vertex():
    # 12 triangles wind twice around the centre: every edge is shared properly,
    # all triangles are counter-clockwise, yet they overlap.
    pts = [(0.0, 0.0)] + [((1 + 0.05 * k) * math.cos(k * math.pi / 3),
                           (1 + 0.05 * k) * math.sin(k * math.pi / 3)) for k in range(12)]
    tris = [(0, 1 + k, 1 + (k + 1) % 12) for k in range(12)]
    p = check_mesh(mesh(pts, tris), delaunay=False)
    assert p and all("meets the interior of boundary edge" in x for x in p), p


def test_stacked_copies_overlap(A30):
    _, r0 = A30
    n = len(r0["vertices"])
    r = {
        "vertices": np.vstack([r0["vertices"], r0["vertices"] + 1e-3]),
        "triangles": np.vstack([r0["triangles"], r0["triangles"] + n]),
    }
    assert has(check_mesh(r, delaunay=False), "meets the interior of boundary edge")


def test_hanging_vertex():
    pts = [(0, 0), (2, 0), (2, 2), (0, 2), (1, 1)]  # 4 lies on the edge 0-2
    p = check_mesh(mesh(pts, [(0, 1, 2), (0, 4, 3), (4, 2, 3)]))
    assert has(p, "meets the interior of boundary edge (2, 0)")


def test_pinched_vertex_is_valid():
    m = mesh([(0, 0), (1, 0), (0, 1), (-1, 0), (0, -1)], [(0, 1, 2), (0, 3, 4)])
    assert check_mesh(m) == []


def test_coincident_vertices():
    pts = [(0, 0), (1, 0), (0, 1), (1, 0), (0, 1), (1, 1)]
    p = check_mesh(mesh(pts, [(0, 1, 2), (3, 5, 4)]))
    assert has(p, "have the same coordinates")


def test_skinny_triangles_without_small_input_angles(A30):
    d = pslg("A")
    r = triangle.triangulate(d, "p")
    p = check_mesh(r, d, 30)
    assert p and all("no small input angle" in x or "more" in x for x in p)
    assert quality_report(r, d, 30)["n_exempt"] == 0
    # a square split into two triangles plus a sliver at a 90 degree corner
    m = mesh([(0, 0), (1, 0), (1, 1), (0, 1), (1, 0.05)],
             [(0, 1, 4), (0, 4, 2), (0, 2, 3)], [(0, 1), (1, 4), (4, 2), (2, 3), (3, 0)])
    p = check_mesh(m, None, 20, delaunay=False)
    assert has(p, "triangle 0 ") and has(p, "no small input angle")


def test_small_input_angle_exempts_only_the_wedge():
    # Segments 0-1 and 0-2 meet at J = 0 at 11.3 degrees.  Triangle 0 fills
    # the wedge and is exempt (rule a); triangle 1 is skinny at vertices 1
    # and 2, where the segments meet at 106.7 degrees.
    pts = [(0, 0), (10, 0), (10, 2), (10.3, 1)]
    m = mesh(pts, [(0, 1, 2), (1, 3, 2)], [(0, 1), (0, 2), (1, 3), (3, 2)])
    rep = quality_report(m, None, 20)
    assert rep["n_bad"] == 2 and rep["n_exempt"] == 1
    p = check_mesh(m, None, 20, delaunay=False)
    assert not has(p, "triangle 0 ") and has(p, "triangle 1 ")
    # A 40 degree wedge split in two at J: 20 degrees at J is not forced when
    # the bound (30) is below the wedge angle, but is when the bound is 45.
    c, s = math.cos(math.radians(40)), math.sin(math.radians(40))
    c2, s2 = math.cos(math.radians(20)), math.sin(math.radians(20))
    m = mesh([(0, 0), (1, 0), (1.2 * c2, 1.2 * s2), (c, s)], [(0, 1, 2), (0, 2, 3)],
             [(0, 1), (0, 3), (1, 2), (2, 3)])
    assert quality_report(m, None, 30)["n_exempt"] == 0
    assert quality_report(m, None, 45)["n_exempt"] == 2


def test_mpw_shell_rule():
    # J = 0 with segments along 0 and 40 degrees; 1 and 2 lie on them at the
    # same distance 1 from J (a shell).  Triangle 1 is bad (27.4 degrees at
    # vertex 5), opposite its shortest edge 1-2: Miller-Pav-Walkington.
    c, s = math.cos(math.radians(40)), math.sin(math.radians(40))
    pts = [(0, 0), (1, 0), (c, s), (2.5, 0), (2.5 * c, 2.5 * s), (2.2, 0.8)]
    tris = [(0, 1, 2), (1, 5, 2), (1, 3, 5), (5, 4, 2)]
    segs = [(0, 1), (1, 3), (0, 2), (2, 4), (3, 5), (5, 4)]
    inp = {"vertices": np.array([pts[0], pts[3], pts[4], pts[5]], float),
           "segments": np.array([(0, 1), (0, 2), (1, 3), (3, 2)])}
    m = mesh(pts, tris, segs)
    assert check_mesh(m, inp) == []
    for given_pslg in (inp, None):
        rep = quality_report(m, given_pslg, 30)
        assert rep["n_bad"] == 1 and rep["n_exempt"] == 1
        assert check_mesh(m, given_pslg, 30) == []
    # vertex 2 moved off the shell by 1%: no longer exempt
    pts[2] = (1.01 * c, 1.01 * s)
    m = mesh(pts, tris, segs)
    rep = quality_report(m, inp, 30)
    assert rep["n_bad"] == 1 and rep["n_exempt"] == 0
    assert has(check_mesh(m, inp, 30), "triangle 1 ")
    # vertex 1 an input vertex (not a Steiner point): no longer exempt
    pts[2] = (c, s)
    inp2 = {"vertices": np.array([pts[0], pts[3], pts[4], pts[5], pts[1]], float),
            "segments": np.array([(0, 4), (4, 1), (0, 2), (1, 3), (3, 2)])}
    assert quality_report(mesh(pts, tris, segs), inp2, 30)["n_exempt"] == 0


def test_cocircular_grids_any_diagonal():
    rng = np.random.default_rng(3)
    n = 12
    for scale, shift in ((1.0, 0.0), (0.125, 1024.0), (2.0**-30, -3.0)):
        g = np.array([(i, j) for j in range(n) for i in range(n)], float) * scale + shift
        r = triangle.triangulate({"vertices": g}, "")
        assert check_mesh(r) == []
        tris = []
        for j in range(n - 1):
            for i in range(n - 1):
                a, b, c, d = j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i
                tris += [(a, b, c), (a, c, d)] if rng.random() < 0.5 else [(a, b, d), (b, c, d)]
        assert check_mesh(mesh(g, tris)) == []
    # a unit square is cocircular: both diagonals are legal; raise one corner
    # by 2**-40 and only one diagonal stays legal
    sq = [(0, 0), (1, 0), (1, 1), (0, 1)]
    d02, d13 = [(0, 1, 2), (0, 2, 3)], [(0, 1, 3), (1, 2, 3)]
    assert check_mesh(mesh(sq, d02)) == [] and check_mesh(mesh(sq, d13)) == []
    sq[3] = (0, 1 + 2.0**-40)
    assert check_mesh(mesh(sq, d02)) == []
    assert has(check_mesh(mesh(sq, d13)), "edge {1, 3} is not locally Delaunay")


def test_max_area():
    d = pslg("A")
    r = triangle.triangulate(d, "pq30a0.001")
    assert check_mesh(r, d, 30, max_area=0.001) == []
    p = check_mesh(r, d, 30, max_area=0.0005)
    assert has(p, "> 0.0005")


def test_area_sum():
    sq = {"vertices": np.array([(0, 0), (1, 0), (1, 1), (0, 1)], float),
          "segments": np.array([(0, 1), (1, 2), (2, 3), (3, 0)])}
    r = triangle.triangulate(sq, "pq30a0.001")
    assert abs(mesh_area(r) - 1.0) <= 2.0**-50
    assert quality_report(r, sq, 30)["area_total"] == mesh_area(r)
    d = pslg("A")
    assert abs(mesh_area(triangle.triangulate(d, "pq30")) - mesh_area(triangle.triangulate(d, "p"))) < 1e-15


def test_input_segment_missing_from_subsegments(A30):
    d, r0 = A30
    r = copy(r0)
    r["segments"] = np.delete(r["segments"], 4, axis=0)
    r["segment_markers"] = np.delete(r["segment_markers"], 4, axis=0)
    p = check_mesh(r, d, 30)
    assert has(p, "is not a chain of collinear subsegments")
    assert check_mesh(r, None, 30) == []  # without the PSLG nothing is missing


def test_steiner_vertex_off_its_segment():
    d = pslg("la")
    r0 = triangle.triangulate(d, "pq30")
    n_in = len(d["vertices"])
    em = edge_map(r0["triangles"])
    # a Steiner vertex on an interior segment (triangles on both sides)
    a, b = next((a, b) for a, b in r0["segments"].tolist()
                if a >= n_in and (a, b) in em and (b, a) in em)
    r = copy(r0)
    r["vertices"][a] += 1e-5
    p = check_mesh(r, d, None, delaunay=False)
    assert has(p, "is not a chain of collinear subsegments")


def test_eaten_segments_may_be_missing():
    # A square with a dangling segment outside it and one inside it: Triangle
    # deletes the outer one with the exterior, keeps the inner one.
    d = {"vertices": np.array([(0, 0), (1, 0), (1, 1), (0, 1), (2, 2), (3, 2.5),
                               (0.2, 0.2), (0.6, 0.3)], float),
         "segments": np.array([(0, 1), (1, 2), (2, 3), (3, 0), (2, 4), (4, 5), (6, 7)])}
    r = triangle.triangulate(d, "pq30")
    assert check_mesh(r, d, 30) == []
    s = {tuple(sorted(x)) for x in r["segments"].tolist()}
    assert (2, 4) not in s and (4, 5) not in s
    inner = next(i for i, x in enumerate(r["segments"].tolist()) if 6 in x or 7 in x)
    r2 = copy(r)
    r2["segments"] = np.delete(r2["segments"], inner, axis=0)
    r2["segment_markers"] = np.delete(r2["segment_markers"], inner, axis=0)
    assert has(check_mesh(r2, d, 30, delaunay=False), "input segment 6 ")


def test_markers(A30):
    d, r0 = A30
    r = copy(r0)
    v = int(r["segments"][0, 0])
    r["vertex_markers"][v] = 0
    r["segment_markers"][0] = 0
    p = check_mesh(r, d, 30)
    assert has(p, f"vertex {v} on a boundary segment has marker 0")
    assert has(p, "boundary segment 0 ")
    assert check_mesh(r, d, 30, markers=False) == []
    r["vertex_markers"] = r["vertex_markers"][:-1]
    assert has(check_mesh(r, d), "vertex_markers has")


@pytest.mark.parametrize("k", [-1000, -600, -100, 100, 600, 1000])
def test_power_of_two_scaling_changes_nothing(A30, k):
    # Exact scaling keeps every sign; the filters must hand such magnitudes
    # to the exact path (no underflow or overflow in the products).
    d, r0 = A30
    r = copy(r0)
    r["vertices"] = np.ldexp(r["vertices"], k)
    ds = dict(d, vertices=np.ldexp(d["vertices"], k))
    assert check_mesh(r, ds, 30) == []
    bad = copy(r)
    edge = convex_interior_edges(r0)[0]
    assert has(check_mesh(flip(bad, edge), ds, None), "not locally Delaunay")


def test_malformed_arrays():
    assert check_mesh({"vertices": np.zeros((3, 3))})
    assert check_mesh({"vertices": np.zeros((3, 2)), "triangles": np.zeros((2, 4), int)})


# --------------------------------------------------------------------------
# properties
# --------------------------------------------------------------------------


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.tuples(st.integers(0, 6), st.integers(0, 6)), min_size=3, max_size=40, unique=True),
       st.integers(0, 2**31))
def test_small_integer_point_sets(points, seed):
    pts = np.array(points, float)
    if abs(np.linalg.matrix_rank(pts[1:] - pts[0])) < 2:
        return  # all collinear: Triangle fails
    r = triangle.triangulate({"vertices": pts}, "")
    assert check_mesh(r) == []
    t = np.random.default_rng(seed).integers(len(r["triangles"]))
    bad = copy(r)
    bad["triangles"][t] = bad["triangles"][t][[0, 2, 1]]
    assert has(check_mesh(bad), f"triangle {t} ")


# --------------------------------------------------------------------------
# speed
# --------------------------------------------------------------------------


def test_speed_100k_triangles():
    pts = np.random.default_rng(0).random((50_500, 2))
    r = triangle.triangulate({"vertices": pts}, "")
    assert len(r["triangles"]) > 100_000
    t0 = time.perf_counter()
    p = check_mesh(r, min_angle=None)
    elapsed = time.perf_counter() - t0
    print(f"check_mesh on {len(r['triangles'])} triangles: {elapsed:.2f} s")
    assert p == []
    assert elapsed < 5.0


def test_a_vertex_a_hair_from_a_segment_end_does_not_fake_a_gap():
    """A segment touching the unit square only at its corner (1, 0), beside an
    input vertex at (1, 1e-50) on the square's side: both within the
    checker's tolerance of the segment's line and at the same rounded position
    along it.  Their exact order decides the pieces; Triangle's mesh and ours
    (the same triangles) are valid."""
    v = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.5, 0.5], [0.5, -0.5], [1.0, 1e-50]])
    pslg = {"vertices": v, "segments": np.array([[0, 1], [1, 2], [2, 3], [3, 0], [4, 5]])}
    assert check_mesh(instrument.triangulate(pslg, "pQ"), pslg) == []
    assert check_mesh(triangle.triangulate(pslg, "pQ"), pslg) == []


def test_shell_distances_600_decades_apart_are_compared_without_overflow():
    # Miller-Pav-Walkington's test compares the squared distances of a short
    # edge's ends from the corner J their segments share: 1e50 and 1e250 from
    # J here, a ratio whose square overflowed (an OverflowError out of
    # check_mesh on a 1e-304 .. 1e300 mesh refined under pYqc)
    V = np.array([[0, 0], [1e50, 0], [1e300, 0], [1e300, 1e300], [0, 1e300], [0, 1e250]])
    mesh = {"vertices": V, "triangles": np.array([[0, 1, 5], [1, 2, 5], [5, 2, 3], [5, 3, 4]]),
            "segments": np.array([[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0]])}
    pslg = {"vertices": V[[0, 2, 3, 4]], "segments": np.array([[0, 1], [1, 2], [2, 3], [3, 0]])}
    problems = check_mesh(mesh, pslg=pslg, min_angle=20, delaunay=False)
    assert [p.split(" has ")[0] for p in problems] == ["triangle 0 [0, 1, 5]", "triangle 1 [1, 2, 5]"]


@pytest.mark.parametrize("x0, other_segment", [(2.0**-1022, False), (2.0**-1022, True), (2.0**-126, True)])
def test_an_input_vertex_beside_a_segment_may_be_passed_by_or_through(x0, other_segment):
    """An input vertex x0 inside the side x = 0 of the unit square, an ulp
    (in y) from where a segment crosses that side: within the checker's
    tolerance of the segment, not exactly on it.  Triangle and ours leave it
    off the segment (the same mesh); the checker counted it as a node of the
    segment, projected beyond the crossing, and found an uncovered piece.  A
    chain through it (subsegments ending there) is still checked as one, and
    a missing subsegment is still found.  Where the vertex is also the end of
    another segment (to (0.5, 0.5)), a subsegment ends there, but not along
    the segment passing by, so the vertex is still not a node of that segment
    (campaign seed 3201 found it at 2^-126, a checker failure of both
    Triangle's mesh and ours)."""
    v = np.array([[x0, float.fromhex("0x1.3638p-7")], [0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0],
                  [3.8433074951171875e-4, 4.0435791015625e-4], [-3.8433074951171875e-4, 1.8529891967773434e-2]]
                 + ([[0.5, 0.5]] if other_segment else []))
    segments = [[1, 2], [2, 3], [3, 4], [4, 1], [5, 6]] + ([[0, 7]] if other_segment else [])
    pslg = {"vertices": v, "segments": np.array(segments)}
    ours, theirs = instrument.triangulate(pslg, "pQ"), triangle.triangulate(pslg, "pQ")
    assert check_mesh(ours, pslg) == [] and check_mesh(theirs, pslg) == []
    assert sorted(map(sorted, ours["triangles"].tolist())) == sorted(map(sorted, theirs["triangles"].tolist()))
    crossing = len(v)  # the first vertex after the input's: the crossing on x = 0
    cut = dict(ours, segments=np.array([s for s in ours["segments"].tolist() if sorted(s) != [5, crossing]]))
    assert any("not a chain of collinear subsegments" in p for p in check_mesh(cut, pslg))


def test_another_sides_vertices_near_a_segment_crossing_beside_a_corner_are_not_its_nodes():
    """A segment from an ulp outside the unit square's corner (1, 1) into it
    crosses the top side 7 ulps beside the corner.  Under pq the right side is
    split towards the corner (1 - 2^-40 ... 1 - 2^-48): those vertices, exactly
    on x = 1, are within the checker's tolerance of the segment's line and came
    before the crossing along it, after its end outside the mesh, so a piece
    from that end seemed to cross the mesh (Triangle's mesh and ours, the same
    150 vertices; regressions/concurrent-crossings-fold-pq.json).  They are
    nodes of the right side only; the crossing stays a node of the segment,
    and a missing subsegment beside it is still found."""
    v = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0],
                  [float.fromhex("0x1.ffffffffffffcp-1"), float.fromhex("0x1.0000000000002p+0")], [0.3125, 0.71875]])
    pslg = {"vertices": v, "segments": np.array([[0, 1], [1, 2], [2, 3], [3, 0], [4, 5]])}
    ours, theirs = instrument.triangulate(pslg, "pqQ"), triangle.triangulate(pslg, "pqQ")
    assert check_mesh(ours, pslg) == [] and check_mesh(theirs, pslg) == []
    assert np.array_equal(ours["vertices"], theirs["vertices"])
    V = ours["vertices"]
    crossing = next(i for i, (x, y) in enumerate(V.tolist()) if y == 1.0 and 0.5 < x < 1.0 and 1.0 - x < 1e-14)
    along = next(s for s in ours["segments"].tolist() if crossing in s and V[sum(s) - crossing][1] < 1.0)
    cut = dict(ours, segments=np.array([s for s in ours["segments"].tolist() if s != along]))
    assert any("input segment 4 " in p and "not a chain of collinear subsegments" in p for p in check_mesh(cut, pslg))
