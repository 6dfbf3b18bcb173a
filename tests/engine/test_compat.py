"""``import instrument as triangle``: delaunay, convex_hull, voronoi, plot and
compare against the `triangle` package, and the package's own docstring examples
run on ``instrument``.

Never call the real package on input without a triangle (collinear or all
coincident points): it raises KeyError or crashes the interpreter there.
"""

from __future__ import annotations

import dataclasses
import doctest
import inspect
import subprocess
import sys
from collections import namedtuple

import numpy as np
import pytest
import triangle

import instrument
from instrument.check import check_mesh
from instrument.output import Result
from instrument.voronoi import diagram

# Sample data of the package that has vertices (bbox has none; greenland is big).
SAMPLES = ["A", "box", "diamond_02_00009", "dots", "double_hex", "double_hex2", "double_hex3",
           "ell", "face", "la", "spiral", "square_circle_hole"]


def random_sets():
    rng = np.random.default_rng(20250106)
    for n in (3, 4, 5, 17, 64, 200):
        yield f"uniform{n}", rng.random((n, 2))
    yield "gaussian", rng.normal(size=(150, 2)) * 1e3 + 5e3
    yield "grid", np.array([[x, y] for x in range(6) for y in range(5)], dtype=float)  # cocircular
    yield "collinear_plus_one", np.array([[0, 0], [1, 0], [2, 0], [3, 0], [1, 1]], dtype=float)
    p = rng.random((40, 2))
    yield "duplicates", np.vstack([p, p[[3, 7, 7, 20]]])[rng.permutation(44)]
    yield "hull_collinear", np.vstack([[[0, 0], [4, 0], [4, 4], [0, 4]],
                                       [[1, 0], [2, 0], [3, 0], [0, 2]], rng.random((10, 2)) * 4])


SETS = [*random_sets(), *((name, triangle.get_data(name)["vertices"]) for name in SAMPLES)]
IDS = [name for name, _ in SETS]


def assert_mesh_ok(mesh, pslg=None):
    problems = check_mesh(mesh, pslg)
    assert problems == [], problems[:5]


def point_mesh(pts, tris, segments=None):
    mesh = {"vertices": np.asarray(pts, dtype=np.float64), "triangles": tris}
    if segments is not None:
        mesh["segments"] = segments
    return mesh


def has_duplicates(pts) -> bool:
    return len(np.unique(np.asarray(pts, dtype=float), axis=0)) < len(pts)


def triangle_set(tris) -> set[tuple[int, ...]]:
    return {tuple(sorted(t)) for t in np.asarray(tris).tolist()}


def assert_same_rows(ours, theirs, tol):
    """The two arrays hold the same rows up to ``tol``, in any order (a greedy
    matching suffices: rows closer than tol are copies of one exact value)."""
    ours, theirs = np.asarray(ours, dtype=np.float64), np.asarray(theirs, dtype=np.float64)
    assert ours.shape == theirs.shape
    free = np.ones(len(theirs), dtype=bool)
    for i, row in enumerate(ours):
        near = free & (np.abs(theirs - row).max(axis=1) <= tol)
        assert near.any(), f"row {i} {row.tolist()} has no partner in the package's output"
        free[np.argmax(near)] = False


def voronoi_geometry(vor, tol):
    """The diagram as order-free geometry: Voronoi vertices, finite edges as
    coordinate pairs (endpoints sorted, x within tol counting as equal) and rays
    as (origin, direction)."""
    points, edges, origin, direct = vor
    ends = points[edges]  # (E, 2, 2)
    if len(ends):  # each edge from its lexicographically smaller end
        dx = ends[:, 1, 0] - ends[:, 0, 0]
        first_is_smaller = (dx > tol) | ((np.abs(dx) <= tol) & (ends[:, 0, 1] <= ends[:, 1, 1]))
        ends = np.where(first_is_smaller[:, None, None], ends, ends[:, ::-1])
    return points, ends.reshape(-1, 4), np.hstack([points[origin], direct])


# --------------------------------------------------------------------------
# signatures and types


@pytest.mark.parametrize("name", ["delaunay", "convex_hull", "voronoi", "plot", "compare", "comparev"])
def test_same_signature_as_the_package(name):
    assert inspect.signature(getattr(instrument, name)) == inspect.signature(getattr(triangle, name))
    assert name in instrument.__all__


def test_types_shapes_dtypes():
    pts = [[0, 0], [0, 1], [0.5, 0.5], [1, 1], [1, 0]]
    t = instrument.delaunay(pts)
    assert isinstance(t, np.ndarray) and t.dtype == np.int32 and t.shape == (4, 3)
    h = instrument.convex_hull(pts)
    assert h.dtype == np.int32 and h.shape == (4, 2)
    ours, theirs = instrument.voronoi(pts), triangle.voronoi(pts)
    assert isinstance(ours, tuple) and len(ours) == 4
    for a, b in zip(ours, theirs):
        assert (a.dtype, a.shape, a.ndim) == (b.dtype, b.shape, b.ndim)
    assert_mesh_ok(point_mesh(pts, t, h))


# --------------------------------------------------------------------------
# against the package


@pytest.mark.parametrize("name,pts", SETS, ids=IDS)
def test_delaunay_matches_package(name, pts):
    ours, theirs = instrument.delaunay(pts), triangle.delaunay(pts)
    assert ours.dtype == theirs.dtype == np.int32
    assert ours.shape == theirs.shape
    assert_mesh_ok(point_mesh(pts, ours))
    if name.startswith(("uniform", "gaussian")):  # general position: one Delaunay triangulation
        assert triangle_set(ours) == triangle_set(theirs)
    xy = np.asarray(pts, dtype=float)
    # the same points are used (a duplicate may be represented by another copy)
    assert np.array_equal(np.unique(xy[ours.ravel()], axis=0), np.unique(xy[theirs.ravel()], axis=0))


@pytest.mark.parametrize("name,pts", SETS, ids=IDS)
def test_convex_hull_matches_package(name, pts):
    ours, theirs = instrument.convex_hull(pts), triangle.convex_hull(pts)
    assert ours.dtype == theirs.dtype == np.int32
    assert_mesh_ok(point_mesh(pts, instrument.delaunay(pts), ours))
    if has_duplicates(pts):  # Triangle keeps another copy of a duplicate: compare places
        xy = np.asarray(pts, dtype=float)
        assert np.array_equal(xy[ours], xy[theirs])
    else:  # same segments, same direction, same order
        assert np.array_equal(ours, theirs)


@pytest.mark.parametrize("name,pts", SETS, ids=IDS)
def test_voronoi_matches_package(name, pts):
    assert_mesh_ok(instrument.triangulate({"vertices": pts}))  # the mesh voronoi is built on
    ours, theirs = instrument.voronoi(pts), triangle.voronoi(pts)
    for a, b in zip(ours, theirs):
        assert (a.dtype, a.shape) == (b.dtype, b.shape)
    points, edges, origin, direct = ours
    assert len(points) == len(instrument.delaunay(pts))
    assert edges.size == 0 or (edges.min() >= 0 and edges.max() < len(points))
    assert origin.size == 0 or origin.max() < len(points)
    scale = max(float(np.abs(points).max(initial=0.0)), 1.0)
    tol = 1e-9 * scale
    for a, b in zip(voronoi_geometry(ours, tol), voronoi_geometry(theirs, tol)):
        assert_same_rows(a, b, tol)
    # directions are hull edges turned outward, exactly as Triangle computes them
    assert set(map(tuple, direct.tolist())) == set(map(tuple, theirs[3].tolist()))


def test_docstring_example_values():
    """The package's documented answers that do not depend on triangle order."""
    pts = [[0, 0], [0, 1], [0.5, 0.5], [1, 1], [1, 0]]
    assert triangle_set(instrument.delaunay(pts)) == triangle_set([[1, 0, 2], [2, 4, 3], [4, 2, 0], [2, 3, 1]])
    assert instrument.convex_hull([[0, 0], [0, 1], [1, 1], [1, 0]]).tolist() == [[3, 0], [2, 3], [1, 2], [0, 1]]
    points, edges, origin, direct = instrument.voronoi(pts)
    assert sorted(points.tolist()) == sorted([[0.0, 0.5], [1.0, 0.5], [0.5, 0.0], [0.5, 1.0]])
    assert sorted(direct.tolist()) == sorted([[-1.0, 0.0], [1.0, 0.0], [0.0, -1.0], [0.0, 1.0]])
    assert len(edges) == 4 and sorted(origin.tolist()) == [0, 1, 2, 3]
    assert_mesh_ok(point_mesh(pts, instrument.delaunay(pts)))


def test_engine_voronoi_is_triangles_on_our_mesh():
    """``instrument.voronoi.diagram`` gives bit for bit what Triangle's -v gives
    for the same mesh (fed to it with r)."""
    from triangle.tri import triang

    pts = triangle.get_data("dots")["vertices"]
    mesh = instrument.triangulate({"vertices": pts, "vertex_attributes": pts[:, :1] * 2})
    assert_mesh_ok(mesh)
    _, vor = triang({"pointlist": mesh["vertices"], "pointattributelist": mesh["vertex_attributes"],
                     "trianglelist": mesh["triangles"]}, "zQrv")
    ours = diagram(mesh)
    assert np.array_equal(ours["vertices"], vor["pointlist"])
    assert np.array_equal(ours["vertex_attributes"], vor["pointattributelist"])
    assert np.array_equal(ours["edges"], vor["edgelist"])
    assert np.array_equal(ours["normals"], vor["normlist"])


# --------------------------------------------------------------------------
# degenerate input (the package cannot be called on most of it)


@pytest.mark.parametrize("pts", [
    [[0, 0], [1, 0], [2, 0], [3, 0]],
    [[0, 0], [1, 1], [2, 2], [1, 1], [0, 0]],
    [[0, 0], [0, 0], [0, 0]],
    [[0, 0], [1, 0], [0, 0], [1, 0]],
], ids=["collinear", "collinear_duplicates", "one_point", "two_points"])
def test_no_triangle_gives_empty_arrays(pts):
    """Where the package raises KeyError or crashes, the answer is empty."""
    assert_mesh_ok(instrument.triangulate({"vertices": pts}))
    t = instrument.delaunay(pts)
    assert (t.shape, t.dtype) == ((0, 3), np.int32)
    h = instrument.convex_hull(pts)
    assert (h.shape, h.dtype) == ((0, 2), np.int32)
    points, edges, origin, direct = instrument.voronoi(pts)
    assert (points.shape, points.dtype) == ((0, 2), np.float64)
    assert (edges.shape, edges.dtype) == ((0, 2), np.int32)
    assert (origin.shape, origin.dtype) == ((0,), np.int32)
    assert (direct.shape, direct.dtype) == ((0, 2), np.float64)


@pytest.mark.parametrize("fn", ["delaunay", "convex_hull", "voronoi"])
def test_fewer_than_three_vertices_raise_like_the_package(fn):
    pts = [[0, 0], [1, 1]]
    with pytest.raises(ValueError) as theirs:
        getattr(triangle, fn)(pts)
    with pytest.raises(ValueError) as ours:
        getattr(instrument, fn)(pts)
    assert str(ours.value) == str(theirs.value)


def test_single_triangle_and_duplicated_corners():
    pts = [[0, 0], [2, 0], [0, 1], [2, 0], [0, 0]]
    t = instrument.delaunay(pts)
    assert_mesh_ok(point_mesh(pts, t))
    assert len(t) == len(triangle.delaunay(pts)) == 1
    points, edges, origin, direct = instrument.voronoi(pts)
    assert points.shape == (1, 2) and edges.shape == (0, 2) and origin.tolist() == [0, 0, 0]
    np.testing.assert_allclose(points, [[1.0, 0.5]])
    assert sorted(direct.tolist()) == sorted(triangle.voronoi(pts)[3].tolist())


# --------------------------------------------------------------------------
# the package's docstring examples, run on instrument


def _checked_api():
    """instrument's functions, each sending the meshes it makes through check_mesh."""

    def triangulate(tri, opts=""):
        result = instrument.triangulate(tri, opts)
        assert_mesh_ok(result)
        return result

    def delaunay(pts):
        tris = instrument.delaunay(pts)
        assert_mesh_ok(point_mesh(pts, tris))
        return tris

    def convex_hull(pts):
        segs = instrument.convex_hull(pts)
        assert_mesh_ok(point_mesh(pts, instrument.delaunay(pts), segs))
        return segs

    def voronoi(pts):
        assert_mesh_ok(instrument.triangulate({"vertices": pts}))
        return instrument.voronoi(pts)

    api = {name: getattr(instrument, name) for name in instrument.__all__}
    api.update(triangulate=triangulate, delaunay=delaunay, convex_hull=convex_hull, voronoi=voronoi)
    return api


def _package_doctests():
    finder = doctest.DocTestFinder(recurse=False)
    tests = []
    for name in sorted(dir(triangle)):
        obj = getattr(triangle, name)
        if name.startswith("_") or not callable(obj) or inspect.isclass(obj):
            continue
        tests += [t for t in finder.find(obj, name) if t.examples]
    return tests


DOCTESTS = _package_doctests()


def test_the_package_has_docstring_examples():
    assert {t.name for t in DOCTESTS} >= {"triangulate", "delaunay", "convex_hull", "voronoi"}


def _shape(value):
    if isinstance(value, tuple):
        return tuple(_shape(v) for v in value)
    return np.shape(value)


@pytest.mark.parametrize("test", DOCTESTS, ids=[t.name for t in DOCTESTS])
def test_package_docstring_examples_on_instrument(test):
    """Each example runs in two namespaces: the package's (whose printed output
    must be the documented one) and one where the package's names are
    instrument's; the outputs must have the same sizes."""
    theirs = dict(test.globs)
    ours = dict(test.globs)
    ours.update({k: v for k, v in _checked_api().items() if k in ours or k in instrument.__all__})
    checker = doctest.OutputChecker()
    for ex in test.examples:
        mode = "eval" if ex.want else "exec"
        code = compile(ex.source, f"<{test.name} docstring>", mode)
        value_theirs = eval(code, theirs)  # the package's own examples
        if ex.want:
            assert checker.check_output(ex.want, repr(value_theirs) + "\n", 0), (
                f"extraction problem: the package printed {value_theirs!r}, documented {ex.want!r}")
        try:
            value_ours = eval(code, ours)
        except NotImplementedError as exc:
            pytest.skip(f"{ex.source.strip()!r} needs a switch instrument.triangulate does not have yet: {exc}")
        if ex.want:
            assert _shape(value_ours) == _shape(value_theirs), ex.source


# --------------------------------------------------------------------------
# plots (Agg backend)


@pytest.fixture
def plt():
    mpl = pytest.importorskip("matplotlib")
    mpl.use("Agg", force=True)
    from matplotlib import pyplot

    yield pyplot
    pyplot.close("all")


def test_import_does_not_import_matplotlib():
    code = "import sys, instrument; sys.exit('matplotlib' in sys.modules)"
    assert subprocess.run([sys.executable, "-c", code], check=False).returncode == 0


def test_plot_every_key(plt):
    la = triangle.get_data("la")
    mesh = instrument.triangulate(la, "pAen")
    assert_mesh_ok(mesh, la)
    assert {"regions", "triangle_attributes", "edges", "segments"} <= set(mesh)
    fig, ax = plt.subplots()
    instrument.plot(ax, labels=True, markers=True, **mesh)
    fig.canvas.draw()
    assert not ax.get_xaxis().get_visible()
    a = triangle.get_data("A")
    mesh = instrument.triangulate(a, "p")
    assert_mesh_ok(mesh, a)
    o2 = dict(mesh, triangles=np.hstack([mesh["triangles"], mesh["triangles"]]))  # (T, 6) columns
    instrument.plot(plt.figure().add_subplot(), **o2)
    instrument.plot(plt.figure().add_subplot(), vertices=[[0, 0], [1, 0], [0, 1]])  # lists work


def test_compare_like_the_package_docs(plt):
    """The package's documented usage: compare(plt, points, Voronoi diagram)."""
    pts = triangle.get_data("dots")["vertices"]
    assert_mesh_ok(instrument.triangulate({"vertices": pts}))
    points, edges, ray_origins, ray_directions = instrument.voronoi(pts)
    A = {"vertices": pts}
    B = {"vertices": points, "edges": edges, "ray_origins": ray_origins, "ray_directions": ray_directions}
    instrument.compare(plt, A, B)
    fig = plt.gcf()
    assert len(fig.axes) == 2
    assert fig.axes[1].axis() == pytest.approx(fig.axes[0].axis())
    fig.canvas.draw()
    mesh = instrument.triangulate({"vertices": pts}, "c")
    assert_mesh_ok(mesh)
    instrument.comparev(plt, A, mesh)
    assert len(plt.gcf().axes) == 2
    instrument.compare(plt.figure(), A, mesh, figsize=(4, 2))  # a Figure works too


def _traced(trace):
    r = instrument.triangulate({"vertices": triangle.get_data("spiral")["vertices"]})
    assert_mesh_ok(r)
    r.trace = trace
    return r


Row = namedtuple("Row", "step kind x y triangles_created")


@dataclasses.dataclass
class DRow:
    step: int
    triangles_created: int


@pytest.mark.parametrize("trace", [
    [{"step": 0, "kind": "vertex", "x": 0.0, "y": 0.0, "triangles_created": 3},
     {"step": 1, "kind": "segment", "x": 1.0, "y": 0.0, "triangles_created": 4}],
    [Row(0, "circumcenter", 0.0, 0.0, 5), Row(1, "midpoint", 0.5, 0.5, 2)],
    [DRow(0, 3), DRow(1, 6)],
    np.array([(0, 3), (1, 4)], dtype=[("step", "i8"), ("triangles_created", "i8")]),
    np.array([[0, 3], [1, 4], [2, 6]]),
    [[0, 3], [1, 4]],
    {"step": [0, 1, 2], "triangles_created": [3, 4, 4]},
], ids=["dicts", "namedtuples", "dataclasses", "structured", "array", "lists", "columns"])
def test_work_plots_a_trace(plt, trace):
    fig, ax = plt.subplots()
    assert instrument.work(ax, _traced(trace)) is ax
    assert ax.get_lines()
    fig.canvas.draw()


def test_work_picks_a_column(plt):
    _fig, ax = plt.subplots()
    trace = {"step": [0, 1], "flips": [2, 5], "triangles_created": [3, 4]}
    instrument.work(ax, _traced(trace), key="flips")
    assert ax.get_ylabel() == "flips"
    with pytest.raises(ValueError, match="no column"):
        instrument.work(ax, _traced(trace), key="nope")


@pytest.mark.parametrize("trace", [None, [], np.zeros((0, 5)), {}], ids=["none", "empty", "empty_array", "no_columns"])
def test_work_without_trace_raises(plt, trace):
    _fig, ax = plt.subplots()
    with pytest.raises(ValueError, match="no trace.*trace=True"):
        instrument.work(ax, _traced(trace))
    with pytest.raises(ValueError, match="no trace"):
        instrument.work(ax, {"vertices": [[0, 0], [1, 0], [0, 1]]})  # a plain dict has no trace


def test_result_is_what_work_reads():
    assert "trace" in Result().__dict__
