"""Property tests: exact round trips of random meshes; no crash on mutated bytes."""

from __future__ import annotations

import time

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from iohelpers import PKG_DATA, assert_same_mesh

import ruppert_io
from ruppert_io import FormatError

# Each example cleans the directory it uses, so sharing tmp_path is safe.
TMP_PATH_OK = [HealthCheck.function_scoped_fixture]

finite = st.floats(allow_nan=False, allow_infinity=False, width=64)
int32 = st.integers(-(2**31), 2**31 - 1)


def _matrix(draw, rows, cols, elements):
    return [[draw(elements) for _ in range(cols)] for _ in range(rows)]


@st.composite
def meshes(draw):
    """A random mesh dict with every key ruppert_io reads, 0-based."""
    n = draw(st.integers(0, 8))
    xy = np.array(_matrix(draw, n, 2, finite), dtype=np.float64).reshape(n, 2)
    mesh = {"vertices": xy}
    k = draw(st.integers(0, 3))
    if n and k:
        mesh["vertex_attributes"] = np.array(_matrix(draw, n, k, finite)).reshape(n, k)
    if n and draw(st.booleans()):
        mesh["vertex_markers"] = np.array(_matrix(draw, n, 1, int32), dtype=np.int32)
    if draw(st.booleans()):
        index = st.integers(0, max(n - 1, 0))
        pairs = _matrix(draw, draw(st.integers(0, 6)), 2, index) if n else []
        # Segments joining two vertices at one place are skipped with a warning.
        pairs = [p for p in pairs if not np.array_equal(xy[p[0]], xy[p[1]])]
        mesh["segments"] = np.array(pairs, dtype=np.int32).reshape(-1, 2)
        if pairs and draw(st.booleans()):
            mesh["segment_markers"] = np.array(_matrix(draw, len(pairs), 1, int32), dtype=np.int32)
        h = draw(st.integers(0, 3))
        mesh["holes"] = np.array(_matrix(draw, h, 2, finite)).reshape(h, 2)
        r = draw(st.integers(0, 3))
        if r:
            mesh["regions"] = np.array(_matrix(draw, r, 4, finite)).reshape(r, 4)
    if n and draw(st.booleans()):
        m, corners = draw(st.integers(0, 5)), draw(st.sampled_from([3, 6]))
        mesh["triangles"] = np.array(
            _matrix(draw, m, corners, st.integers(0, n - 1)), dtype=np.int32
        ).reshape(m, corners)
        kt = draw(st.integers(0, 2))
        if m and kt:
            mesh["triangle_attributes"] = np.array(_matrix(draw, m, kt, finite)).reshape(m, kt)
        if draw(st.booleans()):
            mesh["triangle_max_area"] = np.array(_matrix(draw, m, 1, finite)).reshape(m, 1)
        if draw(st.booleans()):
            nb = st.integers(-1, m - 1)
            mesh["neighbors"] = np.array(_matrix(draw, m, 3, nb), dtype=np.int32).reshape(m, 3)
    if n and draw(st.booleans()):
        e = draw(st.integers(0, 5))
        edges = np.array(_matrix(draw, e, 2, st.integers(0, n - 1)), dtype=np.int32).reshape(e, 2)
        mesh["edges"] = edges
        if e and draw(st.booleans()):
            mesh["edge_markers"] = np.array(_matrix(draw, e, 1, int32), dtype=np.int32)
        if e and draw(st.booleans()):  # Voronoi-style rays
            rays = np.array([draw(st.booleans()) for _ in range(e)])
            if rays.any():
                edges[rays, 1] = -1
                normals = np.array(_matrix(draw, e, 2, finite)).reshape(e, 2)
                normals[~rays] = 0.0
                mesh["normals"] = normals
    return mesh


@settings(max_examples=150, deadline=None, suppress_health_check=TMP_PATH_OK)
@given(mesh=meshes(), first=st.sampled_from([0, 1]))
def test_random_meshes_round_trip_bit_exactly(tmp_path, mesh, first):
    base = tmp_path / "r"
    for old in tmp_path.iterdir():
        old.unlink()
    ruppert_io.write(base, mesh, first_index=first)
    back, info = ruppert_io.read_with_info(base)
    assert info.warnings == []
    if len(mesh["vertices"]):  # with no vertices the base cannot come from them
        assert info.first_index == first
    assert_same_mesh(mesh, back)


# Small valid file sets; each mutated file is read with its unmutated siblings.
SEEDS = {
    "A.1.node": (PKG_DATA / "A.1.node").read_bytes(),
    "A.1.ele": (PKG_DATA / "A.1.ele").read_bytes(),
    "A.1.poly": (PKG_DATA / "A.1.poly").read_bytes(),
    "A.poly": (PKG_DATA / "A.poly").read_bytes(),
    "box.poly": (PKG_DATA / "box.poly").read_bytes(),
    "bbox.1.area": (PKG_DATA / "bbox.1.area").read_bytes(),
    "diamond_02_00009.1.v.edge": (PKG_DATA / "diamond_02_00009.1.v.edge").read_bytes(),
    "x.neigh": b"3 3\n1 2 -1 3\n2 1 -1 -1\n3 1 -1 -1\n",
    "x.edge": b"3 1\n1 1 2 1\n2 2 3 0\n3 3 1 1\n",
}
SIBLINGS = ["A.1.node", "A.1.ele", "A.1.poly", "bbox.1.node", "bbox.1.ele",
            "diamond_02_00009.1.v.node"]

tokens = st.sampled_from(
    [b"#", b"\0", b"\n", b"\r", b" ", b"\t", b"-", b".", b"0", b"010", b"0x", b"-inf", b"+nan",
     b"1e999", b"99999999999999999999", b"9223372036854775807", b"2147483648", b"-1", b"1000000000000", b"\xff\xfe", b"e", b","]
)


@st.composite
def mutations(draw):
    name = draw(st.sampled_from(sorted(SEEDS)))
    data = bytearray(SEEDS[name])
    for _ in range(draw(st.integers(1, 4))):
        where = draw(st.integers(0, len(data)))
        action = draw(st.sampled_from(["flip", "insert", "delete", "truncate", "token"]))
        if action == "flip" and where < len(data):
            data[where] = draw(st.integers(0, 255))
        elif action == "insert":
            data[where:where] = draw(st.binary(min_size=1, max_size=8))
        elif action == "delete":
            del data[where : where + draw(st.integers(1, 40))]
        elif action == "truncate":
            del data[where:]
        else:
            data[where:where] = draw(tokens)
    return name, bytes(data)


@settings(max_examples=400, deadline=None, suppress_health_check=TMP_PATH_OK)
@given(case=mutations())
def test_mutated_files_parse_or_raise_format_error(tmp_path, case):
    name, data = case
    for sibling in SIBLINGS:
        target = tmp_path / sibling
        if not target.exists():
            target.write_bytes((PKG_DATA / sibling).read_bytes())
    (tmp_path / "A.node").unlink(missing_ok=True)
    path = tmp_path / name
    path.write_bytes(data)
    start = time.perf_counter()
    try:
        ruppert_io.read(path)
    except FormatError as e:
        assert e.path == str(path) or e.path.endswith(".node")
        assert e.line is None or e.line >= 1
    finally:
        (tmp_path / name).unlink()
        assert time.perf_counter() - start < 2.0
