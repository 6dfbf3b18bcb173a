"""``import instrument as triangle`` for a user of the `triangle` package:
its docstring examples with their documented output, its sample-data helpers
(``get_data``, ``load``, ``loads``, ``show_data``), ``__version__``, the
exceptions it raises, and ``V``'s statistics on stdout.

The package is called in-process only on input it handles (it can crash the
interpreter on some bad input); every error case below was tried first.
"""

from __future__ import annotations

import doctest
import importlib
import os
import warnings
from importlib.metadata import version
from pathlib import Path

import numpy as np
import pytest
import triangle

import instrument
from instrument.check import check_mesh
from instrument.errors import SizeLimitError, TriangleError

TRIANGLE_DATA = Path(triangle.__file__).parent / "data"
SAMPLE_NAMES = sorted({p.name.rsplit(".", 1)[0] for p in TRIANGLE_DATA.iterdir() if not p.name.startswith(".")})

# --------------------------------------------------------------------------
# The package's own docstring examples, run on instrument


def package_doctests() -> list[doctest.DocTest]:
    """Every docstring example of the installed package's modules."""
    finder = doctest.DocTestFinder()
    tests = []
    for name in ("triangle", "triangle.tri", "triangle.data", "triangle.plot"):
        module = importlib.import_module(name)
        tests += [t for t in finder.find(module, name) if t.examples]
    unique = {t.name: t for t in tests}  # triangle re-exports triangle.tri's functions
    return sorted(unique.values(), key=lambda t: t.name)


DOCTESTS = package_doctests()

#: Examples whose output we match only up to order: Triangle lists triangles in
#: the order of its memory pool, which the engine follows for Delaunay
#: triangulations but not yet after refinement (here: the unit square under
#: a0.2 gives Triangle's vertices and markers, and its triangles in another order).
ORDER_ONLY = {("triangle.tri.triangulate", "t['triangles'].tolist()")}


def _canonical_rows(text: str) -> list[tuple[int, ...]]:
    rows = eval(text)  # a list of lists of ints, printed by tolist()
    return sorted(tuple(np.roll(r, -int(np.argmin(r)))) for r in rows)


def checked(fn):
    """``fn`` whose every mesh goes through the checker."""

    def run(*args, **kwargs):
        result = fn(*args, **kwargs)
        if fn is instrument.triangulate:
            assert check_mesh(result) == []
        elif fn is instrument.delaunay:
            assert check_mesh({"vertices": np.asarray(args[0], float), "triangles": result}) == []
        return result

    return run


def test_the_package_has_docstring_examples():
    names = {t.name for t in DOCTESTS}
    assert {"triangle.tri.triangulate", "triangle.tri.delaunay", "triangle.tri.convex_hull", "triangle.tri.voronoi"} <= names


@pytest.mark.parametrize("test", DOCTESTS, ids=[t.name for t in DOCTESTS])
def test_package_docstring_examples_print_the_documented_output(test):
    """Each example runs with the package's names bound to instrument's and
    must print exactly what the package documents."""
    api = {name: checked(getattr(instrument, name)) if callable(getattr(instrument, name)) else getattr(instrument, name)
           for name in instrument.__all__}
    globs = {**test.globs, **{k: v for k, v in api.items() if k in test.globs}, "triangle": instrument}
    checker = doctest.OutputChecker()
    for example in test.examples:
        mode = "eval" if example.want else "exec"
        value = eval(compile(example.source, f"<{test.name}>", mode), globs)
        if not example.want:
            continue
        got = repr(value) + "\n"
        if (test.name, example.source.strip()) in ORDER_ONLY:
            assert _canonical_rows(got) == _canonical_rows(example.want), example.source
        else:
            assert checker.check_output(example.want, got, doctest.ELLIPSIS), (example.source, example.want, got)


def test_our_docstring_examples():
    for module in ("instrument.samples", "instrument.compat"):
        result = doctest.testmod(importlib.import_module(module))
        assert result.failed == 0 and result.attempted > 0, module


# --------------------------------------------------------------------------
# Sample data


def assert_same(ours: dict, theirs: dict) -> None:
    assert list(ours) == list(theirs)
    for key in ours:
        a, b = np.asarray(ours[key]), np.asarray(theirs[key])
        assert a.dtype == b.dtype and a.shape == b.shape, key
        np.testing.assert_array_equal(a, b, err_msg=key)


@pytest.mark.parametrize("name", SAMPLE_NAMES)
def test_get_data_reads_the_packages_samples_as_the_package_does(name):
    ours, theirs = instrument.get_data(name), triangle.get_data(name)
    assert_same(ours, instrument.load(str(TRIANGLE_DATA), name))
    if "regions" in theirs:
        # la.poly's region lines give one value, which Triangle reads as the
        # attribute and the area bound (the package: attribute 0); la.1.poly's,
        # written by Triangle, give both (the package garbles them)
        np.testing.assert_array_equal(ours["regions"], region_lines(TRIANGLE_DATA / f"{name}.poly"))
        ours, theirs = dict(ours), dict(theirs)
        del ours["regions"], theirs["regions"]
    assert_same(ours, theirs)


def region_lines(path: Path) -> np.ndarray:
    """The last section of a .poly file, read by Triangle's rule."""
    lines = [line.split("#")[0].split() for line in path.read_text().splitlines()]
    lines = [f for f in lines if f]
    count = next(int(f[0]) for f in reversed(lines) if len(f) == 1)
    rows = [[float(v) for v in f[1:5]] for f in lines[-count:]]
    return np.array([r if len(r) == 4 else r + [r[2]] for r in rows])


def test_region_attributes_come_through_as_triangle_reads_them():
    """`pq30A` on la.poly gives the regional attributes Triangle's CLI gives
    (0.05, 0.2, ...); the package's reader makes them all 0."""
    d = instrument.get_data("la")
    r = instrument.triangulate(d, "pq30A")
    assert check_mesh(r, d, min_angle=None) == []
    assert set(np.unique(r["triangle_attributes"])) <= set(d["regions"][:, 2]) | {0.0}
    assert len(np.unique(r["triangle_attributes"])) > 2


OUR_SAMPLES = ["scatter", "square_hole", "square_hole.1", "two_regions"]


def test_our_samples_are_listed_first_and_read_by_the_package_too():
    names = instrument.samples.sample_names()
    assert names[: len(OUR_SAMPLES)] == OUR_SAMPLES
    assert set(SAMPLE_NAMES) <= set(names)
    for name in OUR_SAMPLES:
        ours = dict(instrument.get_data(name))
        theirs = triangle.load(str(instrument.samples.SAMPLE_DIR), name)
        if name == "two_regions":  # five-field region lines, which the package garbles
            np.testing.assert_array_equal(ours.pop("regions"), [[0.5, 0.5, 1, 0.01], [2, 0.5, 2, 0.1]])
            del theirs["regions"]
        assert_same(ours, theirs)


@pytest.mark.parametrize(
    ("name", "opts", "angle", "area"),
    [("square_hole", "pq30", 30, None), ("two_regions", "pq30Aa", 30, 0.1), ("scatter", "q30", 30, None),
     ("square_hole.1", "rq30a0.1", 30, 0.1)],
)
def test_our_samples_mesh(name, opts, angle, area):
    d = instrument.get_data(name)
    r = instrument.triangulate(d, opts)
    assert check_mesh(r, d if "p" in opts else None, min_angle=angle, max_area=area) == []
    t = triangle.triangulate(d, opts)
    assert abs(len(r["vertices"]) - len(t["vertices"])) <= 0.25 * len(t["vertices"])


def test_two_regions_attributes_and_areas():
    r = instrument.triangulate(instrument.get_data("two_regions"), "pq30Aa")
    xy, tri, attr = r["vertices"], r["triangles"], r["triangle_attributes"][:, 0]
    left = xy[tri].mean(axis=1)[:, 0] < 1
    assert set(attr[left]) == {1.0} and set(attr[~left]) == {2.0}
    u, w = xy[tri[:, 1]] - xy[tri[:, 0]], xy[tri[:, 2]] - xy[tri[:, 0]]
    area = 0.5 * np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0])
    assert area[left].max() <= 0.01 * (1 + 1e-12) and area[~left].max() <= 0.1 * (1 + 1e-12)


def test_unknown_sample(monkeypatch):
    with pytest.raises(FileNotFoundError, match="no sample named 'nope'.*square_hole"):
        instrument.get_data("nope")
    assert instrument.load(str(TRIANGLE_DATA), "nope") == {} == triangle.load(str(TRIANGLE_DATA), "nope")
    # without the triangle package, Triangle's own samples are not there, and the error says why
    monkeypatch.setattr(instrument.samples, "_triangle_data_dir", lambda: None)
    with pytest.raises(FileNotFoundError, match="`triangle` package, which is not installed"):
        instrument.get_data("A")
    assert instrument.get_data("square_hole")["vertices"].shape == (8, 2)


def test_loads_where_the_package_fails():
    node = "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n"
    # a mesh .edge file (no rays): the package raises IndexError
    edge = "3 1\n1 1 2 1\n2 2 3 0\n3 3 1 1\n"
    with pytest.raises(IndexError):
        triangle.loads(node=node, edge=edge)
    d = instrument.loads(node=node, edge=edge)
    assert d["edges"].tolist() == [[0, 1], [1, 2], [2, 0]] and d["edges"].dtype == np.intc
    assert d["edge_markers"].tolist() == [[1], [0], [1]]
    # .neigh in a 1-based file: -1 stays -1 (the package makes it -2)
    neigh = "2 3\n1 -1 2 -1\n2 1 -1 -1\n"
    assert triangle.loads(node=node, neigh=neigh)["triangle_neighbors"].tolist() == [[-2, 1, -2], [0, -2, -2]]
    assert instrument.loads(node=node, neigh=neigh)["triangle_neighbors"].tolist() == [[-1, 1, -1], [0, -1, -1]]
    # five-field region lines: x y attribute area
    poly = node.replace("4 2 0 0", "4 2 0 0") + "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n2\n1 0.25 0.5 7 0.5\n2 0.75 0.5 3\n"
    assert instrument.loads(poly=poly)["regions"].tolist() == [[0.25, 0.5, 7.0, 0.5], [0.75, 0.5, 3.0, 3.0]]
    # missing optional fields are 0, as in Triangle
    assert instrument.loads(node="3 2 1 1\n1 0 0\n2 1 0 5\n3 0 1 5 2\n")["vertex_markers"].tolist() == [[0], [0], [2]]


def test_loads_rays_like_the_package():
    text = (TRIANGLE_DATA / "dots.1.v.edge").read_text()
    node = (TRIANGLE_DATA / "dots.1.v.node").read_text()
    assert_same(instrument.loads(node=node, edge=text), triangle.loads(node=node, edge=text))


def test_loaded_neighbors_triangulate_again():
    """The package's own load -> triangulate round trip fails on triangle_neighbors."""
    d = {**instrument.get_data("square_hole.1")}
    d["triangle_neighbors"] = np.full((len(d["triangles"]), 3), -1, dtype=np.intc)
    with pytest.raises(KeyError):
        triangle.triangulate(d, "r")
    r = instrument.triangulate(d, "r")
    assert check_mesh(r) == [] and len(r["triangles"]) == len(d["triangles"])


@pytest.mark.parametrize(
    ("kind", "text", "fragment"),
    [
        ("node", "3 2 0 0\n1 0 0\n2 1\n3 0 1\n", "line 3 of the node text: vertex 2 has 1 of its 2 numbers"),
        ("node", "3 2 0 0\n1 0 0\n", "ends after 1 of its 3 vertex lines"),
        ("node", "3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n", "two-dimensional"),
        ("node", "3 2 0 0\n1 0 0\n2 x 0\n3 0 1\n", "'x' is not a number"),
        ("ele", "1 3 0\n1 1 2\n", "triangle 1 has 2 of its 3 numbers"),
    ],
)
def test_loads_errors_name_the_text_and_line(kind, text, fragment):
    with pytest.raises(TriangleError, match=fragment):
        instrument.loads(**{kind: text})


def test_show_data(monkeypatch):
    mpl = pytest.importorskip("matplotlib")
    mpl.use("Agg", force=True)
    import matplotlib.pyplot as plt

    shown = []
    monkeypatch.setattr(plt, "show", lambda: shown.append(plt.gcf()))
    for name in ("A", "square_hole", "two_regions"):
        instrument.show_data(name)
        assert shown[-1].axes and shown[-1].axes[0].collections
        plt.close("all")
    with warnings.catch_warnings():  # the package's own, headless
        warnings.simplefilter("ignore")
        triangle.show_data("A")
    plt.close("all")


def test_version():
    assert instrument.__version__ == version("ruppert")
    assert isinstance(triangle.__version__, str)


# --------------------------------------------------------------------------
# Exceptions: where the package raises RuntimeError, TriangleError is one

SQUARE = {"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]]}

#: (input, switches): every one raises RuntimeError in the package (tried).
RUNTIME_ERRORS = [
    (SQUARE, "r"),  # r without triangles
    (SQUARE, "pa0"),  # a non-positive area
    ({**SQUARE, "triangles": [[0, 1, 9]]}, "r"),  # an invalid vertex index
    ({**SQUARE, "triangles": [[0, 1]]}, "r"),  # two corners
    ({**SQUARE, "vertex_markers": [1, 2]}, "p"),  # markers for two of four vertices
    ({**SQUARE, "triangles": [[0, 1, 2], [0, 2, 3]], "segments": [[0, 7]]}, "rp"),  # a segment off the mesh
]


@pytest.mark.parametrize(("tri", "opts"), RUNTIME_ERRORS)
def test_runtime_errors_are_triangle_errors(tri, opts):
    with pytest.raises(RuntimeError):
        triangle.triangulate(tri, opts)
    for kind in (RuntimeError, ValueError, TriangleError):
        with pytest.raises(kind):
            instrument.triangulate(tri, opts)


def test_value_errors_stay_value_errors():
    for fn in (triangle.triangulate, instrument.triangulate):
        with pytest.raises(ValueError, match="at least three vertices"):
            fn({"vertices": [[0, 0], [1, 0]]}, "p")
    with pytest.raises(TriangleError):
        instrument.triangulate({"vertices": [[0, 0], [1, 0]]}, "p")


def test_unknown_keys_are_key_errors_as_in_the_package():
    for fn in (triangle.triangulate, instrument.triangulate):
        with pytest.raises(KeyError):
            fn({**SQUARE, "foo": 1}, "p")


@pytest.mark.parametrize("opts", ["pq1e400", "pa1e400"])
def test_overflowing_switch_values(opts):
    with pytest.raises(TriangleError, match="out of range"):
        instrument.triangulate(SQUARE, opts)


def test_error_classes():
    assert issubclass(TriangleError, ValueError) and issubclass(TriangleError, RuntimeError)
    assert issubclass(SizeLimitError, TriangleError)
    from instrument.refine import PrecisionError
    from instrument.switches import SwitchError

    assert issubclass(SwitchError, TriangleError) and issubclass(PrecisionError, TriangleError)
    assert instrument.TriangleError is TriangleError and instrument.SizeLimitError is SizeLimitError


# --------------------------------------------------------------------------
# V prints Triangle's statistics

# Reference §3.8: Triangle's library mode on A.poly with pzq30V (phase lines,
# then the array lines, then the statistics block), verbatim.
A_PQ30V_HEAD = """Constructing Delaunay triangulation by divide-and-conquer method.
Recovering segments in Delaunay triangulation.
Removing unwanted triangles.
Adding Steiner points to enforce quality.

Writing vertices.
Writing triangles.
Writing segments.

Statistics:

  Input vertices: 29
  Input segments: 29
  Input holes: 1

  Mesh vertices: 76
  Mesh triangles: 87
  Mesh edges: 163
  Mesh exterior boundary edges: 65
  Mesh interior boundary edges: 0
  Mesh subsegments (constrained edges): 65

Mesh quality statistics:
"""


def test_v_prints_the_statistics(capfd):
    r = instrument.triangulate(instrument.get_data("A"), "pq30V")
    out = capfd.readouterr().out
    assert out.startswith(A_PQ30V_HEAD)
    assert "Algorithmic statistics:" in out and "Work statistics:" in out
    assert f"  Triangles created: {r.work['triangles_created']}\n" in out
    assert check_mesh(r, instrument.get_data("A"), min_angle=30) == []


def test_v_with_o2_counts_the_midpoints(capfd):
    instrument.triangulate(instrument.get_data("A"), "pq30o2V")
    out = capfd.readouterr().out
    assert "Adding vertices for second-order triangles.\n" in out and "  Mesh vertices: 239\n" in out


def test_quiet_and_no_v_print_nothing(capfd):
    for opts in ("pq30", "pq30QV", "pq40S50"):
        instrument.triangulate(instrument.get_data("A"), opts)
    assert capfd.readouterr().out == ""


def test_library_code_never_prints():
    """One console write in the library: statistics.emit, for V."""
    root = Path(instrument.__file__).parent
    for path in root.glob("*.py"):
        text = path.read_text()
        assert "print(" not in text.replace("# print(", ""), path.name
        assert text.count("sys.stdout.write(") == (1 if path.name == "statistics.py" else 0), path.name
    assert os.path.isdir(root / "sample_data")
