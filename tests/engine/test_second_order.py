"""Second-order triangles (o2): the layout against the `triangle` package.

Two kinds of evidence:

* the layout rule (``instrument.secondorder.midpoints``) applied to Triangle's
  own first-order output and edge list gives exactly the package's ``o2``
  output: numbering, order, coordinates, attributes and markers, bit for bit;
* the engine's ``o2`` output is that rule applied to its own mesh, passes the
  checker, has Triangle's node counts wherever its corner mesh has Triangle's
  size, and equals the package's output wherever the corner meshes are equal.
"""

from __future__ import annotations

import csv
import os
from pathlib import Path

import numpy as np
import pytest
import triangle

import instrument
import ruppert_io
from instrument.check import check_mesh
from instrument.pipeline import INPUT_KEYS
from instrument.secondorder import midpoints

CORPUS = Path(os.environ.get("RUPPERT_CORPUS", Path(__file__).resolve().parents[3] / "shared" / "corpus"))

POLYS = ["A", "face", "la", "double_hex", "double_hex2", "double_hex3", "square_circle_hole"]
NODES = ["dots", "spiral", "ell", "diamond_02_00009"]


def engine_input(d: dict) -> dict:
    return {k: v for k, v in d.items() if k in INPUT_KEYS and np.size(v)}


def corpus_files(kind: str) -> list[str]:
    if not (CORPUS / "REFERENCE.tsv").is_file():  # a checkout without shared/ beside it
        return []
    rows = csv.DictReader(open(CORPUS / "REFERENCE.tsv"), delimiter="\t")
    return sorted({r["file"] for r in rows if r["status"] == "ok" and r["file"].endswith(kind)})


def cases():
    """(id, input, switches without o2) over the samples and the corpus."""
    out = []
    for name in POLYS:
        for opts in ("pq30", "p"):
            out.append((f"{name}-{opts}", lambda name=name: engine_input(triangle.get_data(name)), opts))
    for name in NODES:
        for opts in ("", "q30"):
            out.append((f"{name}-{opts or 'dt'}", lambda name=name: engine_input(triangle.get_data(name)), opts))
    a1 = lambda: engine_input(triangle.triangulate(engine_input(triangle.get_data("A")), "pq20"))  # noqa: E731
    out += [("A.1-rpq30", a1, "rpq30"), ("A.1-r", a1, "r"), ("A.1-rq30a0.002", a1, "rq30a0.002")]
    for f in corpus_files(".poly"):
        for opts in ("pq30", "p"):
            out.append((f"{f}-{opts}", lambda f=f: engine_input(ruppert_io.read(CORPUS / f)), opts))
    for f in corpus_files(".node"):
        out.append((f"{f}-dt", lambda f=f: engine_input(ruppert_io.read(CORPUS / f)), ""))
    return out


CASES = cases()
IDS = [c[0] for c in CASES]

ENGINE_CASES = [pytest.param(*c, id=c[0]) for c in CASES]


def apply_rule(first_order: dict, with_edges: dict) -> dict:
    """``first_order``'s o2 output by the rule, from its ``e`` output."""
    extra = midpoints(
        first_order["triangles"],
        with_edges["edges"],
        first_order["vertices"],
        first=len(first_order["vertices"]),
        attributes=first_order.get("vertex_attributes"),
        edge_markers=with_edges["edge_markers"],
    )
    out = dict(first_order)
    out["triangles"] = extra.triangles
    out["vertices"] = np.vstack([first_order["vertices"], extra.vertices])
    out["vertex_markers"] = np.vstack([first_order["vertex_markers"], extra.vertex_markers.reshape(-1, 1)])
    if "vertex_attributes" in first_order:
        out["vertex_attributes"] = np.vstack([first_order["vertex_attributes"], extra.vertex_attributes])
    return out


def assert_same(a: dict, b: dict) -> None:
    assert set(a) == set(b)
    for key in a:
        np.testing.assert_array_equal(a[key], b[key], err_msg=key)
        assert np.asarray(a[key]).dtype == np.asarray(b[key]).dtype, key


@pytest.mark.parametrize(("name", "make", "opts"), CASES, ids=IDS)
def test_the_rule_is_triangles_layout(name, make, opts):
    """The rule, on Triangle's own mesh, gives Triangle's o2 output exactly."""
    d = make()
    first = triangle.triangulate(d, opts)
    if "triangles" not in first:
        pytest.skip("Triangle made no triangle")
    ruled = apply_rule(first, triangle.triangulate(d, opts + "e"))
    assert_same(ruled, triangle.triangulate(d, opts + "o2"))


def _by_corners(mesh: dict) -> dict:
    """Each triangle, keyed by its corner coordinates from its lowest corner
    (rows may come in another order and start at another corner), mapped to
    the coordinates and markers of its three midpoints in the same rotation."""
    xy = mesh["vertices"]
    marks = mesh["vertex_markers"][:, 0]
    out = {}
    for row in mesh["triangles"]:
        corners = [tuple(xy[v]) for v in row[:3]]
        k = corners.index(min(corners))
        rot = [(k + i) % 3 for i in range(3)]
        mids = tuple((tuple(xy[row[3 + i]]), int(marks[row[3 + i]])) for i in rot)
        out[tuple(corners[i] for i in rot)] = mids
    return out


@pytest.mark.parametrize(("name", "make", "opts"), ENGINE_CASES)
def test_engine_second_order_like_triangle(name, make, opts):
    d = make()
    ours = instrument.triangulate(d, opts + "o2")
    theirs = triangle.triangulate(d, opts + "o2")
    first = instrument.triangulate(d, opts)
    if "triangles" not in first:
        assert "triangles" not in ours and len(ours.get("vertices", [])) == len(first.get("vertices", []))
        return
    # the checker on the corners, with the PSLG and the angle asked for
    pslg = d if "p" in opts and "r" not in opts else None
    assert check_mesh(ours, pslg, min_angle=30.0 if "q30" in opts else None) == []
    # the engine's layout is the rule on its own mesh
    assert_same(ours, apply_rule(first, instrument.triangulate(d, opts + "e")))
    nv, nt = len(first["vertices"]), len(first["triangles"])
    edges = (3 * nt + int(np.count_nonzero(np.bincount(_edge_ids(first["triangles"])) == 1))) // 2
    assert len(ours["vertices"]) == nv + edges
    # Triangle's node counts wherever the corner mesh has Triangle's size
    t1 = triangle.triangulate(d, opts)
    if (len(t1["vertices"]), len(t1["triangles"])) == (nv, nt):
        assert len(ours["vertices"]) == len(theirs["vertices"])
        assert ours["triangles"].shape == theirs["triangles"].shape == (nt, 6)
    # Triangle's layout wherever the corner meshes are the same
    if _identical(first, t1):
        assert_same(ours, theirs)
    elif np.array_equal(first["vertices"], t1["vertices"]) and _same_triangles(first, t1):
        # the same mesh, triangles (or segments) listed in another order
        assert _by_corners(ours) == _by_corners(theirs)


def _identical(a: dict, b: dict) -> bool:
    return set(a) == set(b) and all(np.array_equal(a[k], b[k]) for k in a)


def _edge_ids(t: np.ndarray) -> np.ndarray:
    a, b = t[:, [0, 1, 2]].ravel(), t[:, [1, 2, 0]].ravel()
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    return np.unique(lo * (int(t.max()) + 1) + hi, return_inverse=True)[1]


def _same_triangles(a: dict, b: dict) -> bool:
    canon = lambda t: sorted(tuple(np.roll(r, -int(np.argmin(r)))) for r in t.tolist())  # noqa: E731
    return canon(np.asarray(a["triangles"])) == canon(np.asarray(b["triangles"]))


def test_the_brief_numbers():
    """`ruppert -pq30o2 A.poly`: Triangle writes 87 six-node triangles on 239 vertices."""
    r = instrument.triangulate(triangle.get_data("A"), "pq30o2")
    assert r["triangles"].shape == (87, 6) and len(r["vertices"]) == 239
    assert r["triangles"].dtype == np.int32 and r["vertex_attributes"].shape == (239, 1)


def test_switches_that_drop_keys():
    """E keeps the midpoints among the vertices; N and B drop what they drop."""
    d = triangle.get_data("A")
    for opts in ("pq30o2E", "pq30o2N", "pq30o2B", "pq30o2P", "pq30o2j", "pq30o2en"):
        ours, theirs = instrument.triangulate(d, opts), triangle.triangulate(d, opts)
        assert {k: np.shape(v) for k, v in ours.items()} == {k: np.shape(v) for k, v in theirs.items()}, opts


def test_duplicates_stay_before_the_midpoints():
    rng = np.random.default_rng(5)
    p = rng.random((30, 2))
    d = {"vertices": np.vstack([p, p[[3, 5]]])}
    for opts in ("o2", "jo2", "q30o2", "q30jo2"):
        ours, theirs = instrument.triangulate(d, opts), triangle.triangulate(d, opts)
        assert len(ours["vertices"]) == len(theirs["vertices"]), opts
        assert check_mesh(ours) == []
        # the unused duplicates keep their places without j
        if "j" not in opts:
            np.testing.assert_array_equal(ours["vertices"][:32], d["vertices"])


def test_no_triangle_no_midpoint():
    d = {"vertices": [[0, 0], [1, 0], [2, 0]]}
    r = instrument.triangulate(d, "o2")
    assert "triangles" not in r and len(r["vertices"]) == 3


def test_refining_a_second_order_mesh_again():
    """ro2 on a 6-node mesh: the old midpoints go, new ones come last."""
    made = triangle.triangulate(triangle.get_data("A"), "pq30o2")
    d = {k: made[k] for k in ("vertices", "vertex_markers", "vertex_attributes", "triangles")}
    for opts in ("ro2", "rq30a0.002o2"):
        ours, theirs = instrument.triangulate(d, opts), triangle.triangulate(d, opts)
        assert check_mesh(ours) == []
        assert ours["triangles"].shape[1] == 6
        assert len(ours["vertices"]) == len(theirs["vertices"]), opts
    np.testing.assert_array_equal(instrument.triangulate(d, "ro2")["vertices"], made["vertices"])
