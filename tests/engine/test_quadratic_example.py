"""Barbič and Miller's input I(n) (``instrument.quadratic``), checked against the paper.

Every quantity is recomputed here from the paper's printed formulas, without the
module's helpers, and every mesh produced goes through ``check_mesh``.  Where the
paper as printed does not hold numerically, a test pins what does hold
(``test_equation_8_...``, ``test_equation_11_...``, ``test_theorem_3_...``).
"""

from __future__ import annotations

import dataclasses
import math
import runpy
from pathlib import Path

import numpy as np
import pytest
import triangle

import instrument
import ruppert_io
from instrument import quadratic
from instrument.check import check_mesh

ROOT = Path(__file__).resolve().parents[2]
ALPHAS = [20.0, 15.0, 10.0, 5.0]


# --------------------------------------------------------------------------
# the paper's formulas, written out again
# --------------------------------------------------------------------------


def paper_r(alpha_deg: float) -> int:
    """Equation (3), by counting up from 1."""
    tan2 = math.tan(math.radians(alpha_deg)) ** 2
    r = 1
    while not 1 / ((2 * r + 1) * (2 * r - 1)) < tan2:
        r += 1
    return r


def paper_r_or_skip(n: int, alpha_deg: float) -> int:
    """Equation (3)'s r, skipping the test when I(n) needs more than n points."""
    r = paper_r(alpha_deg)
    if n < r + 1:
        pytest.skip("n too small for this angle")
    return r


def paper_h(n: int, r: int) -> float:
    """Equation (4)."""
    return 1 / (2 * n) * math.sqrt((2 * r + 1) * (2 * r - 1))


def paper_a(h: float) -> float:
    """Equation (5)."""
    return h + 1 / h


def smallest_angle(p, q, s) -> tuple[float, int]:
    """Smallest angle (degrees) of a triangle and the corner (0, 1, 2) it is at."""
    pts = [np.asarray(v, dtype=float) for v in (p, q, s)]
    angles = []
    for i in range(3):
        u = pts[(i + 1) % 3] - pts[i]
        w = pts[(i + 2) % 3] - pts[i]
        angles.append(math.degrees(math.atan2(abs(u[0] * w[1] - u[1] * w[0]), u @ w)))
    i = int(np.argmin(angles))
    return angles[i], i


def circumcenter(p, q, s) -> np.ndarray:
    (ax, ay), (bx, by), (cx, cy) = p, q, s
    d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    ux = (
        (ax**2 + ay**2) * (by - cy)
        + (bx**2 + by**2) * (cy - ay)
        + (cx**2 + cy**2) * (ay - by)
    ) / d
    uy = (
        (ax**2 + ay**2) * (cx - bx)
        + (bx**2 + by**2) * (ax - cx)
        + (cx**2 + cy**2) * (bx - ax)
    ) / d
    return np.array([ux, uy])


def triangle_set(tris) -> set[frozenset[int]]:
    return {frozenset(int(v) for v in t) for t in np.asarray(tris)[:, :3]}


def mesh(pslg, engine=instrument):
    result = engine.triangulate(pslg, "p")
    problems = check_mesh(result, pslg)
    assert problems == [], problems[:5]
    return result


def with_steiner_points(n: int, k: int, alpha: float) -> dict:
    """Lemma 2's set (9): the extended input plus P_1..P_k, appended in order."""
    pslg = quadratic.example(n, alpha)
    r, h = paper_r(alpha), paper_h(n, paper_r(alpha))
    extra = np.array([(l * r / n + 1 / (2 * n), h) for l in range(1, k + 1)]).reshape(
        -1, 2
    )
    out = dict(pslg)
    out["vertices"] = np.vstack([pslg["vertices"], extra])
    out["vertex_markers"] = np.vstack(
        [pslg["vertex_markers"], np.zeros((k, 1), np.int32)]
    )
    return out


# --------------------------------------------------------------------------
# parameters, equations (3)-(5)
# --------------------------------------------------------------------------


@pytest.mark.parametrize("alpha", ALPHAS + [1.0, 0.25, 19.99, 30.0, 33.0])
@pytest.mark.parametrize("n", [31, 100, 1000])
def test_params_are_equations_3_to_5(alpha, n):
    r = paper_r_or_skip(n, alpha)
    p = quadratic.params(n, alpha)
    assert (p.n, p.alpha_deg, p.r) == (n, alpha, r)
    assert quadratic.smallest_r(alpha) == r
    # r is the smallest: r - 1 fails (3)
    tan2 = math.tan(math.radians(alpha)) ** 2
    assert r == 1 or not 1 / ((2 * r - 1) * (2 * r - 3)) < tan2
    assert math.isclose(p.h, paper_h(n, r), rel_tol=1e-15)
    assert math.isclose(p.a, paper_a(paper_h(n, r)), rel_tol=1e-15)
    # tan(theta) = 1/(2nh), equation (8)
    assert math.isclose(
        math.tan(math.radians(p.theta_deg)), 1 / (2 * n * p.h), rel_tol=1e-12
    )
    assert p.theta_deg < alpha


def test_params_at_20_degrees():
    # tan^2(20 deg) = 0.1325; r = 1 gives 1/3, r = 2 gives 1/15
    p = quadratic.params(10)
    assert p.r == 2
    assert p.h == pytest.approx(math.sqrt(15) / 20)
    assert p.a == pytest.approx(math.sqrt(15) / 20 + 20 / math.sqrt(15))
    with pytest.raises(dataclasses.FrozenInstanceError):
        p.r = 3


def test_a_grows_linearly_with_n():
    # equation (5): a = h + 1/h = Theta(n); at 20 degrees 1/h = 2n/sqrt(15)
    ratios = [quadratic.params(n).a / n for n in (100, 1000, 10000)]
    assert ratios == pytest.approx([2 / math.sqrt(15)] * 3, rel=1e-2)


# --------------------------------------------------------------------------
# the extended input
# --------------------------------------------------------------------------


@pytest.mark.parametrize("alpha", ALPHAS)
@pytest.mark.parametrize("n", [7, 8, 50])
def test_example_is_the_extended_input(n, alpha):
    r = paper_r_or_skip(n, alpha)
    h = paper_h(n, r)
    a = paper_a(h)
    d = quadratic.example(n, alpha)
    v, s = d["vertices"], d["segments"]
    assert v.dtype == np.float64 and v.shape == (n + 4 + 8, 2)
    assert s.dtype == np.int32 and s.shape == (8, 2)
    assert d["vertex_markers"].dtype == np.int32 and d["vertex_markers"].shape == (
        n + 12,
        1,
    )
    assert d["segment_markers"].dtype == np.int32 and d["segment_markers"].shape == (
        8,
        1,
    )
    # equation (2), in the documented numbering
    expected = [(i / n, 0.0) for i in range(n + 1)] + [
        (0.0, a),
        (1.0, a),
        (1 / (2 * n), h),
    ]
    np.testing.assert_allclose(v[: n + 4], expected, rtol=1e-15, atol=0)
    np.testing.assert_array_equal(quadratic.input_points(n, alpha), v[: n + 4])
    idx = quadratic.input_indices(n)
    assert list(idx["bottom"]) == list(range(n + 1))
    assert v[idx["top_left"]].tolist() == pytest.approx([0.0, a], rel=1e-15)
    assert v[idx["top_right"]].tolist() == pytest.approx([1.0, a], rel=1e-15)
    assert v[idx["apex"]].tolist() == pytest.approx([1 / (2 * n), h], rel=1e-15)
    assert list(idx["box"]) == list(range(n + 4, n + 12))
    assert idx["first_steiner"] == len(v)
    # the box: side 3 * max(horizontal span 1, vertical span a) = 3a, centre (1/2, a/2)
    assert a > 1
    box = v[n + 4 :]
    np.testing.assert_array_equal(quadratic.box_points(n, alpha), box)
    side = 3 * a
    lo = np.array([0.5 - side / 2, a / 2 - side / 2])
    hi = np.array([0.5 + side / 2, a / 2 + side / 2])
    corners = {(lo[0], lo[1]), (hi[0], lo[1]), (hi[0], hi[1]), (lo[0], hi[1])}
    mids = {(0.5, lo[1]), (hi[0], a / 2), (0.5, hi[1]), (lo[0], a / 2)}
    got = [tuple(p) for p in box]
    for want in corners | mids:
        assert any(np.allclose(p, want, rtol=1e-14, atol=1e-14) for p in got), want
    np.testing.assert_allclose(box.mean(axis=0), (0.5, a / 2), rtol=1e-14)
    # the 8 subsegments: one closed cycle over the box points, each half a side
    ends = sorted(int(x) for x in s.ravel())
    assert ends == sorted(list(range(n + 4, n + 12)) * 2)
    succ = {int(p): int(q) for p, q in s}
    walk, cur = [], n + 4
    for _ in range(8):
        walk.append(cur)
        cur = succ[cur]
    assert cur == n + 4 and sorted(walk) == list(range(n + 4, n + 12))
    lengths = np.hypot(*(v[s[:, 1]] - v[s[:, 0]]).T)
    np.testing.assert_allclose(lengths, side / 2, rtol=1e-14)
    # markers: box vertices and subsegments are boundary
    assert d["vertex_markers"][: n + 4].ravel().tolist() == [0] * (n + 4)
    assert d["vertex_markers"][n + 4 :].ravel().tolist() == [1] * 8
    assert d["segment_markers"].ravel().tolist() == [1] * 8


@pytest.mark.parametrize("n", [3, 4, 7, 20, 100, 1000])
def test_instrument_and_triangle_agree_on_the_example(n):
    d = quadratic.example(n)
    ours = mesh(d, instrument)
    theirs = mesh(d, triangle)
    assert (
        len(ours["vertices"]) == len(theirs["vertices"]) == n + 12
    )  # no Steiner points
    assert len(ours["triangles"]) == len(theirs["triangles"])
    # Euler: 2N - 2 - (vertices on the hull); the hull is the box with its 8 points
    assert len(ours["triangles"]) == 2 * (n + 12) - 2 - 8
    assert triangle_set(ours["triangles"]) == triangle_set(theirs["triangles"])


def test_box_subsegments_are_never_encroached():
    # Theorem 3's proof: every point of the script lies outside the diametral
    # circles of the eight subsegments, so only skinny triangles get split.
    for alpha in ALPHAS:
        for n in (paper_r(alpha) + 1, 10, 60):
            p = quadratic.params(n, alpha)
            d = with_steiner_points(n, p.steps, alpha)
            v = d["vertices"]
            inner = np.delete(v, np.arange(n + 4, n + 12), axis=0)
            for i, j in d["segments"]:
                centre = (v[i] + v[j]) / 2
                radius = np.hypot(*(v[j] - v[i])) / 2
                assert np.all(np.hypot(*(inner - centre).T) > radius)


# --------------------------------------------------------------------------
# Lemma 1 and Delta_0
# --------------------------------------------------------------------------


@pytest.mark.parametrize("alpha", ALPHAS)
@pytest.mark.parametrize("n", [3, 4, 5, 6, 7, 8, 9, 12, 13])
def test_delta_0_is_in_the_delaunay_triangulation(n, alpha):
    r = paper_r(alpha)
    if n < r + 1:
        with pytest.raises(ValueError):
            quadratic.example(n, alpha)
        return
    d = quadratic.example(n, alpha)
    tris = triangle_set(mesh(d)["triangles"])
    # Delta_0 = ((r/n, 0), ((r+1)/n, 0), (1/(2n), h)): input vertices r, r+1, n+3
    assert quadratic.delta(n, 0, alpha) == (r, r + 1, n + 3)
    assert frozenset((r, r + 1, n + 3)) in tris
    # Lemma 2 with k = 0: the whole broom over the bottom row is Delaunay
    for m in range(n):
        assert frozenset((m, m + 1, n + 3)) in tris
    assert triangle_set(quadratic.broom(n, 0, alpha)) == {
        frozenset((m, m + 1, n + 3)) for m in range(n)
    }


@pytest.mark.parametrize("alpha", ALPHAS + [1.0])
@pytest.mark.parametrize("n", [3, 10, 101])
def test_delta_0_is_skinny(n, alpha):
    r = paper_r_or_skip(n, alpha)
    h = paper_h(n, r)
    corners = [(r / n, 0.0), ((r + 1) / n, 0.0), (1 / (2 * n), h)]
    np.testing.assert_allclose(quadratic.delta_points(n, 0, alpha), corners, rtol=1e-15)
    angle, at = smallest_angle(*corners)
    assert at == 2  # the smallest angle is theta, at P (opposite the short side CD)
    assert angle < alpha
    # equation (8): tan(theta) = 1/(2nh)
    assert math.tan(math.radians(angle)) == pytest.approx(1 / (2 * n * h), rel=1e-12)
    assert angle == pytest.approx(quadratic.params(n, alpha).theta_deg, rel=1e-12)


@pytest.mark.parametrize("alpha", ALPHAS)
def test_lemma_1_circumcenter_and_congruence(alpha):
    n = 40
    r = paper_r(alpha)
    h = paper_h(n, r)
    for k in range(quadratic.steps(n, alpha)):
        i = k * r
        A, B = np.array([i / n, 0.0]), np.array([(i + 1) / n, 0.0])
        C, D = np.array([(i + r) / n, 0.0]), np.array([(i + r + 1) / n, 0.0])
        P = np.array([i / n + 1 / (2 * n), h])
        np.testing.assert_allclose(
            quadratic.delta_points(n, k, alpha), [C, D, P], rtol=1e-14
        )
        S = circumcenter(C, D, P)
        want = ((i + r) / n + 1 / (2 * n), h)
        np.testing.assert_allclose(S, want, rtol=1e-12)
        np.testing.assert_allclose(quadratic.new_point(n, k, alpha), want, rtol=1e-14)
        np.testing.assert_allclose(
            quadratic.steiner_point(n, k + 1, alpha), want, rtol=1e-14
        )
        theta, _ = smallest_angle(C, D, P)
        theta_ab, _ = smallest_angle(A, B, P)  # theta' at P, ABP is isosceles
        assert theta_ab == pytest.approx(2 * theta, rel=1e-10)
        # CDS congruent to ABP: same side lengths
        sides = sorted(np.hypot(*(x - y)) for x, y in ((A, B), (B, P), (P, A)))
        sides_s = sorted(np.hypot(*(x - y)) for x, y in ((C, D), (D, S), (S, C)))
        np.testing.assert_allclose(sides_s, sides, rtol=1e-12)


# --------------------------------------------------------------------------
# Lemma 2 and Theorem 3, statically: the point sets (9) for every k
# --------------------------------------------------------------------------


@pytest.mark.parametrize("alpha", [20.0, 10.0])
@pytest.mark.parametrize("n", [7, 12, 25])
def test_lemma_2_broom_for_every_step(n, alpha):
    p = quadratic.params(n, alpha)
    r = p.r
    for k in range(p.steps + 1):
        result = mesh(with_steiner_points(n, k, alpha))
        tris = triangle_set(result["triangles"])
        apex = n + 3 if k == 0 else n + 12 + k - 1
        assert quadratic.apex_index(n, k) == apex
        broom = {frozenset((m, m + 1, apex)) for m in range(k * r, n)}
        assert broom <= tris, (k, sorted(map(sorted, broom - tris)))
        assert triangle_set(quadratic.broom(n, k, alpha)) == broom
        if k < p.steps:  # Delta_k is in this mesh (Theorem 3)
            assert frozenset(quadratic.delta(n, k, alpha)) in tris
            assert quadratic.delta(n, k, alpha) == (k * r + r, k * r + r + 1, apex)
        if k >= 1:  # step k - 1 created at least n - rk triangles at P_k
            around = sum(apex in t for t in tris)
            assert around >= n - r * k == quadratic.step_lower_bound(n, k - 1, alpha)


def test_lemma_2_circle_bounds():
    # proof of Lemma 2: circumcircles of the brooms stay below height a and far
    # from the box points
    for alpha in ALPHAS:
        for n in (3 * paper_r(alpha), 50, 300):
            r, h = paper_r(alpha), paper_h(n, paper_r(alpha))
            a = paper_a(h)
            box = quadratic.box_points(n, alpha)
            for k in range(quadratic.steps(n, alpha) + 1):
                for m in range(k * r, n):
                    corners = [
                        (m / n, 0.0),
                        ((m + 1) / n, 0.0),
                        (k * r / n + 1 / (2 * n), h),
                    ]
                    c = circumcenter(*corners)
                    y10 = (4 * (m - k * r) ** 2 + 4 * h * h * n * n - 1) / (
                        8 * h * n * n
                    )
                    assert c[1] == pytest.approx(y10, rel=1e-9)  # equation (10)
                    R = math.hypot(*(c - corners[0]))
                    assert c[1] < R < a / 2
                    assert np.all(np.hypot(*(box - c).T) >= a)


# --------------------------------------------------------------------------
# where the paper as printed does not hold numerically
# --------------------------------------------------------------------------


@pytest.mark.parametrize("alpha", ALPHAS)
def test_equation_8_needs_plus_in_the_tangent_subtraction_formula(alpha):
    n = 17
    r = paper_r(alpha)
    h = paper_h(n, r)
    t_sum = (r + 0.5) / (n * h)  # tan(theta + theta''), equation (7)
    t_pp = (r - 0.5) / (n * h)  # tan(theta'')
    theta = math.atan(t_sum) - math.atan(t_pp)
    # the true subtraction formula gives the paper's result 1/(2nh)
    assert (t_sum - t_pp) / (1 + t_sum * t_pp) == pytest.approx(
        1 / (2 * n * h), rel=1e-12
    )
    assert math.tan(theta) == pytest.approx(1 / (2 * n * h), rel=1e-12)
    # as printed, with "1 - tg tg", the denominator vanishes ((nh)^2 = r^2 - 1/4)
    assert abs(1 - t_sum * t_pp) < 1e-12


@pytest.mark.parametrize("alpha", ALPHAS)
@pytest.mark.parametrize("n", [3, 10, 1000])
def test_equation_11_is_the_centre_height_not_the_radius(n, alpha):
    r = paper_r_or_skip(n, alpha)
    h = paper_h(n, r)
    a = paper_a(h)
    printed = (4 * (n - 1) ** 2 + 4 * h * h * n * n - 1) / (8 * h * n * n)  # (11)
    corners = [((n - 1) / n, 0.0), (1.0, 0.0), (1 / (2 * n), h)]  # k = 0, m = n - 1
    c = circumcenter(*corners)
    radius = math.hypot(*(c - corners[0]))
    assert c[1] == pytest.approx(printed, rel=1e-12)  # (11) is y_C of (10)
    assert radius > printed  # the true R_max is larger ...
    assert radius == pytest.approx(math.hypot(printed, 1 / (2 * n)), rel=1e-12)
    assert radius < a / 2  # ... and the lemma's conclusion still holds


@pytest.mark.parametrize("alpha", [20.0, 10.0])
def test_theorem_3_last_printed_step_exists_only_if_r_does_not_divide_n(alpha):
    r = paper_r(alpha)
    for n in range(r + 1, 80):
        printed = n // r  # k = 0 .. floor(n/r) - 1
        existing = [k for k in range(printed) if k * r + r + 1 <= n]
        assert quadratic.steps(n, alpha) == len(existing) == (n - 1) // r
        assert len(existing) == (printed - 1 if n % r == 0 else printed)
        with pytest.raises(ValueError, match="Delta_k exists for 0 <= k"):
            quadratic.delta(n, len(existing), alpha)
        # the missing step would add n - r(k+1) = 0, so (12) holds with (14) over
        # the existing steps
        total = sum(n - r * (k + 1) for k in existing)
        assert total >= n * n / (2 * r) - 2 * n == quadratic.theorem3_bound(n, alpha)
        assert total == sum(quadratic.step_lower_bound(n, k, alpha) for k in existing)
        # every Steiner point of the existing steps lies in [0, 1] x [0, a]
        assert all(0 < quadratic.new_point(n, k, alpha)[0] < 1 for k in existing)


def test_n_equal_to_r_allowed_by_the_paper_has_no_step():
    r = paper_r(20.0)
    # Lemma 2 and Theorem 3 say n >= r, but Delta_0 needs the vertex index r + 1
    with pytest.raises(ValueError, match=r"n must be >= r \+ 1 = 3"):
        quadratic.example(r)
    assert quadratic.steps(r + 1) == 1


# --------------------------------------------------------------------------
# argument checks, the .poly writer
# --------------------------------------------------------------------------


@pytest.mark.parametrize("n", [0, 1, 2, -5])
def test_too_small_n_is_rejected(n):
    with pytest.raises(ValueError, match=r"n must be >= r \+ 1 = 3 .*got n="):
        quadratic.example(n)


@pytest.mark.parametrize("n", [2.5, "10", True, None])
def test_non_integer_n_is_rejected(n):
    with pytest.raises(TypeError, match="n must be an integer"):
        quadratic.example(n)


@pytest.mark.parametrize("alpha", [0.0, -1.0, 34.5, 45.0, float("nan"), float("inf")])
def test_alpha_outside_the_range_is_rejected(alpha):
    with pytest.raises(ValueError, match="0 < alpha_deg <= 34"):
        quadratic.example(10, alpha)


@pytest.mark.parametrize(("alpha", "r"), [(20.5, 2), (30.0, 2), (30.01, 1), (33.0, 1), (34.0, 1)])
def test_angles_above_20_degrees_for_the_sweep(alpha, r):
    # the construction needs only alpha > 0; at exactly 30 degrees r = 1 would
    # give theta = 30 degrees (tan^2 = 1/3 exactly, also in floating point)
    assert quadratic.smallest_r(alpha) == paper_r(alpha) == r
    p = quadratic.params(40, alpha)
    assert p.theta_deg < alpha


@pytest.mark.parametrize("alpha", ["20", None, True])
def test_non_number_alpha_is_rejected(alpha):
    with pytest.raises(TypeError, match="number of degrees"):
        quadratic.example(10, alpha)


def test_numpy_integer_n_is_accepted():
    assert quadratic.example(np.int64(9))["vertices"].shape == (21, 2)


def test_step_indices_are_checked():
    with pytest.raises(ValueError, match="step k exists"):
        quadratic.new_point(10, quadratic.steps(10))
    with pytest.raises(ValueError):
        quadratic.delta(10, -1)
    with pytest.raises(ValueError):
        quadratic.apex_index(10, -1)
    with pytest.raises(ValueError):
        quadratic.steiner_point(10, quadratic.steps(10) + 1)


def test_write_quadratic_script_round_trips(tmp_path):
    script = runpy.run_path(
        str(ROOT / "scripts" / "write_quadratic.py"), run_name="script"
    )
    assert script["main"](["12", "--alpha", "15", "-o", str(tmp_path / "q")]) == 0
    back = ruppert_io.read(tmp_path / "q.poly")
    want = quadratic.example(12, 15.0)
    np.testing.assert_array_equal(
        back["vertices"], want["vertices"]
    )  # %.17g round-trips
    np.testing.assert_array_equal(back["segments"], want["segments"])
    mesh(back)


def test_data_file_is_the_example_for_n_100():
    back = ruppert_io.read(ROOT / "data" / "quadratic-100.poly")
    want = quadratic.example(100)
    np.testing.assert_array_equal(back["vertices"], want["vertices"])
    np.testing.assert_array_equal(back["segments"], want["segments"])
