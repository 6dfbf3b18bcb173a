"""Reading each file kind: Triangle's defaults, warnings and errors (spec §2.2-2.8)."""

from __future__ import annotations

import numpy as np
import pytest

import ruppert_io
from ruppert_io import FormatError, read, read_with_info
from ruppert_io.errors import DimensionError

SQUARE_NODE = "4 2 1 1\n1 0 0 0.5 7\n2 1 0 0.25 0\n3 1 1 0 -3\n4 0 1 1 1\n"


def test_node_keys_shapes_dtypes(write_file):
    d = read(write_file("sq.node", SQUARE_NODE))
    assert sorted(d) == ["vertex_attributes", "vertex_markers", "vertices"]
    assert d["vertices"].dtype == np.float64 and d["vertices"].shape == (4, 2)
    assert d["vertex_attributes"].shape == (4, 1)
    assert d["vertex_markers"].dtype == np.int32
    assert d["vertex_markers"][:, 0].tolist() == [7, 0, -3, 1]


def test_node_header_defaults_and_missing_optional_fields(write_file):
    d = read(write_file("a.node", "3\n1 0 0\n2 1 0\n3 0 1\n"))
    assert sorted(d) == ["vertices"]
    # Markers declared but missing read 0; missing attributes read 0.
    d = read(write_file("b.node", "3 2 2 1\n1 0 0 5\n2 1 0\n3 0 1 1 2 9\n"))
    assert d["vertex_attributes"].tolist() == [[5, 0], [0, 0], [1, 2]]
    assert d["vertex_markers"][:, 0].tolist() == [0, 0, 9]


def test_extra_columns_are_ignored(write_file):
    # Like the corpus unicorn.node: the header declares nothing, lines carry more.
    d = read(write_file("u.node", "3 2 0 0\n1 2 0 0\n2 3 0.5 0\n3 4 4 0\n"))
    assert sorted(d) == ["vertices"] and d["vertices"][2].tolist() == [4, 4]


@pytest.mark.parametrize(
    "first, base", [("0", 0), ("1", 1), ("7", 1), ("0x0", 0), ("-0", 0), ("1.9", 1)]
)
def test_numbering_base_comes_from_the_first_vertex(write_file, tmp_path, first, base):
    # Later vertex numbers are ignored; the base applies to every index.
    write_file("t.node", f"3 2 0 0\n{first} 0 0\n9 1 0\n9 0 1\n")
    write_file("t.ele", f"1 3 0\n5 {base + 2} {base} {base + 1}\n")
    d, info = read_with_info(tmp_path / "t")
    assert info.first_index == base
    assert d["triangles"].tolist() == [[2, 0, 1]]


def test_default_first_index_applies_to_other_first_numbers(write_file):
    path = write_file("t.node", "3 2 0 0\n7 0 0\n8 1 0\n9 0 1\n")
    assert read_with_info(path, default_first_index=0)[1].first_index == 0
    path = write_file("z.node", "3 2 0 0\n1 0 0\n8 1 0\n9 0 1\n")
    assert read_with_info(path, default_first_index=0)[1].first_index == 1


def test_octal_counts_like_strtol(write_file):
    # "010" is 8 vertices, as C's strtol(base 0) reads it.
    lines = "".join(f"{i} {i} {i * i}\n" for i in range(1, 9))
    assert len(read(write_file("o.node", "010 2 0 0\n" + lines))["vertices"]) == 8


@pytest.mark.parametrize(
    "text, line, message",
    [
        ("3 2 0 0\n1 0 0\n2 1\n3 0 1\n", 3, "expected the y coordinate of vertex 2"),
        ("3 2 0 0\n1 0 0\n2\n3 0 1\n", 3, "expected the x coordinate of vertex 2"),
        ("3 2 0 0\n1 0 0\n2 1 0\n", 4, "unexpected end of file; expected 3 vertex lines"),
        ("1000000000000 2 0 0\n1 0 0\n", 3, "unexpected end of file; expected 1000000000000"),
        ("-3 2 0 0\n", 1, "expected the number of vertices in [0, "),
        ("3 2 -1 0\n", 1, "expected the number of vertex attributes in [0, "),
        ("3 2 0 0\n1 0 0\n2 -inf 0\n3 0 1\n", 3, "a finite number for the x coordinate"),
        ("3 2 0 0\n1 0 0\n2 1 +nan\n3 0 1\n", 3, "a finite number for the y coordinate"),
        ("3 2 0 1\n1 0 0 99999999999\n2 1 0\n3 0 1\n", 2, "the boundary marker of vertex 1 in"),
        ("", 1, "unexpected end of file; expected the number of vertices"),
    ],
)
def test_node_errors(write_file, text, line, message):
    path = write_file("bad.node", text)
    with pytest.raises(FormatError) as e:
        read(path)
    assert e.value.line == line and e.value.path == str(path)
    assert str(e.value).startswith(f"{path}, line {line}: ")
    assert message in str(e.value)


def test_three_d_is_a_dimension_error(write_file):
    path = write_file("t.node", "# tetgen\n4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n")
    with pytest.raises(DimensionError) as e:
        read(path)
    assert isinstance(e.value, FormatError) and e.value.line == 2
    assert "Triangle only works with two-dimensional meshes" in str(e.value)


@pytest.mark.parametrize(
    "name, text",
    [
        ("h.node", "3 2 1000000000 0\n1 0 0\n2 1 0\n3 0 1\n"),
        ("z.node", "0 2 9223372036854775807 0\n"),  # even with no rows
        ("z.ele", "0 3 9223372036854775807\n"),
        ("c.ele", "0 2147483647 0\n"),
    ],
)
def test_huge_column_counts_fail_without_allocating(write_file, name, text):
    write_file("z.node", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n")
    write_file("c.node", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n")
    with pytest.raises(FormatError, match="at most .* (attributes|nodes per triangle)"):
        read(write_file(name, text))


POLY = """# a square with a hole and two regions
4 2 0 1
1 0 0 1
2 2 0 1
3 2 2 1
4 0 2 1
5 1
1 1 2 10
2 2 3
3 3 4 30
4 4 1 40
5 1 9 50
1
1 1 1
2
1 0.5 0.5 3
2 1.5 1.5 -2 0.25
"""


def test_poly_sections_and_invalid_segment_warning(write_file):
    path = write_file("sq.poly", POLY)
    d, info = read_with_info(path)
    assert d["segments"].tolist() == [[0, 1], [1, 2], [2, 3], [3, 0]]
    assert d["segment_markers"][:, 0].tolist() == [10, 0, 30, 40]
    assert d["holes"].tolist() == [[1, 1]]
    # A lone value is both the regional attribute and the area bound.
    assert d["regions"].tolist() == [[0.5, 0.5, 3, 3], [1.5, 1.5, -2, 0.25]]
    assert info.warnings == [f"Warning:  Invalid second endpoint of segment 5 in {path}."]
    assert (info.first_index, info.vertex_markers, info.segment_markers) == (1, 1, 1)


def test_poly_coincident_and_invalid_first_endpoints(write_file):
    text = "3 2 0 0\n1 0 0\n2 1 0\n3 0 0\n3 0\n1 1 3\n2 0 2\n3 1 2\n0\n"
    path = write_file("c.poly", text)
    d, info = read_with_info(path)
    assert d["segments"].tolist() == [[0, 1]]
    assert info.warnings == [
        f"Warning:  Endpoints of segment 1 are coincident in {path}.",
        f"Warning:  Invalid first endpoint of segment 2 in {path}.",
    ]


def test_poly_empty_sections_keep_segments_and_holes_keys(write_file):
    d = read(write_file("e.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 1\n0\n"))
    assert sorted(d) == ["holes", "segments", "vertices"]
    assert d["segments"].shape == (0, 2) and d["segments"].dtype == np.int32
    assert d["holes"].shape == (0, 2) and d["holes"].dtype == np.float64
    # An empty region section adds nothing.
    assert "regions" not in read(write_file("f.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n0\n0\n"))


def test_poly_with_zero_vertices_reads_the_node_file(write_file):
    write_file("z.node", "3 2 1 1\n0 0 0 4 1\n1 1 0 5 2\n2 0 1 6 3\n")
    path = write_file("z.poly", "0 2 0 0\n1 0\n0 0 2\n0\n")
    d, info = read_with_info(path)
    # The .node header wins: attributes, markers and the 0-based numbering.
    assert info.first_index == 0 and info.vertices_from.name == "z.node"
    assert d["vertex_attributes"][:, 0].tolist() == [4, 5, 6]
    assert d["segments"].tolist() == [[0, 2]]


def test_poly_with_zero_vertices_and_no_node_file(write_file):
    path = write_file("lonely.poly", "0 2 0 0\n0 0\n0\n")
    with pytest.raises(FormatError, match="cannot access file .*lonely.node") as e:
        read(path)
    assert e.value.line == 1


@pytest.mark.parametrize(
    "tail, line, message",
    [
        ("", 6, "unexpected end of file; expected the number of segments"),
        ("1 0\n", 7, "unexpected end of file; expected 1 segment lines"),
        ("1 0\n1\n0\n", 7, "expected the first endpoint of segment 1"),
        ("1 0\n1 1\n0\n", 7, "expected the second endpoint of segment 1"),
        ("0 0\n", 7, "unexpected end of file; expected the number of holes"),
        ("0 0\n1\n1 0.5\n", 8, "expected the y coordinate of hole 1"),
        ("0 0\n0\n1\n1 0.5 0.5\n", 9, "the regional attribute or area constraint of region 1"),
        ("0 0\n0\n2\n1 0.5 0.5 1\n", 10, "unexpected end of file; expected 2 region lines"),
        ("0 0\n-1\n", 7, "expected the number of holes in [0, "),
    ],
)
def test_poly_errors(write_file, tail, line, message):
    path = write_file("p.poly", "# head\n3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n" + tail)
    with pytest.raises(FormatError) as e:
        read(path)
    assert e.value.line == line, str(e.value)
    assert message in str(e.value)


def test_ele_reads_its_node_and_six_node_triangles(write_file):
    write_file("m.node", "4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n")
    path = write_file("m.ele", "1 6 2\n0 0 1 2 3 3 3 0.5\n")
    d = read(path)
    assert d["triangles"].dtype == np.int32 and d["triangles"].tolist() == [[0, 1, 2, 3, 3, 3]]
    assert d["triangle_attributes"].tolist() == [[0.5, 0.0]]
    assert len(d["vertices"]) == 4


@pytest.mark.parametrize(
    "ele, message",
    [
        ("1 2 0\n1 1 2\n", "Triangles in .* must have at least 3 vertices"),
        ("1 3 0\n1 1 2\n", "expected vertex 3 of triangle 1$"),
        (
            "1 3 0\n1 1 2 5\n",
            "Triangle 1 has an invalid vertex index; expected a vertex number from 1 to 4, found 5",
        ),
        ("1 3 0\n1 0 1 2\n", "found 0"),
        ("2 3 0\n1 1 2 3\n", "unexpected end of file"),
        ("1 3 1\n1 1 2 3 -nan\n", "a finite number for attribute 1 of triangle 1, found '-nan'"),
    ],
)
def test_ele_errors(write_file, ele, message):
    write_file("m.node", "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n")
    path = write_file("m.ele", ele)
    with pytest.raises(FormatError, match=message):
        read(path)


def test_ele_without_node_is_an_os_error(write_file):
    with pytest.raises(FileNotFoundError):
        read(write_file("orphan.ele", "0 3 0\n"))


def test_area_missing_value_and_count_mismatch(write_file, tmp_path):
    write_file("a.node", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n")
    write_file("a.ele", "1 3 0\n1 1 2 3\n")
    write_file("a.area", "1\n1\n")
    assert read(tmp_path / "a")["triangle_max_area"].tolist() == [[-1.0]]
    write_file("a.area", "2\n1 0.5\n2 0.25\n")
    with pytest.raises(FormatError, match="a.ele and .*a.area disagree on number of triangles"):
        read(tmp_path / "a")
    # Alone, the .area is read without the check.
    areas = read(write_file("a.area", "2\n1 0.5\n2 -1\n"))["triangle_max_area"]
    assert areas.tolist() == [[0.5], [-1.0]]


def test_edge_file_with_markers(write_file):
    write_file("e.node", "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n")
    path = write_file("e.edge", "3 1\n0 0 1 1\n1 1 2\n2 2 0 5\n")
    d = read(path)
    assert d["edges"].tolist() == [[0, 1], [1, 2], [2, 0]]
    assert d["edge_markers"][:, 0].tolist() == [1, 0, 5]
    assert "normals" not in d
    with pytest.raises(FormatError, match="a vertex number from 0 to 2"):
        read(write_file("e.edge", "1 0\n0 0 3\n"))


def test_voronoi_edge_rays(write_file):
    # Triangle's sample for the triangle (0,0), (1,0), (0,1), 0-based (spec §2.8).
    write_file("tri0.1.v.node", "1  2  0  0\n   0    0.5  0.5\n")
    edges = "3  0\n   0   0  -1   0  -1\n   1   0  -1   1  1\n   2   0  -1   -1  0\n"
    path = write_file("tri0.1.v.edge", edges)
    d = read(path)
    assert d["edges"].tolist() == [[0, -1]] * 3
    assert d["normals"].tolist() == [[0, -1], [1, 1], [-1, 0]]
    assert read(str(path)[: -len(".v.edge")] + ".v")["edges"].tolist() == [[0, -1]] * 3


def test_lone_edge_and_neigh_take_their_own_base(write_file):
    d = read(write_file("x.edge", "2 0\n1 1 2\n2 2 3\n"))
    assert d["edges"].tolist() == [[0, 1], [1, 2]]
    d = read(write_file("x.neigh", "2 3\n0 1 -1 -1\n1 -1 0 -1\n"))
    assert d["neighbors"].dtype == np.int32
    assert d["neighbors"].tolist() == [[1, -1, -1], [-1, 0, -1]]


@pytest.mark.parametrize(
    "text, message",
    [
        ("1 4\n1 -1 -1 -1\n", "expected 3 neighbours per triangle, found 4"),
        ("1 3\n1 2 -1 -1\n", "-1 or a triangle number from 1 to 1 for neighbour 1 of triangle 1"),
        ("1 3\n1 -1 -1\n", "expected neighbour 3 of triangle 1$"),
    ],
)
def test_neigh_errors(write_file, text, message):
    with pytest.raises(FormatError, match=message):
        read(write_file("n.neigh", text))


def test_base_name_reads_every_file(write_file, tmp_path):
    write_file("s.node", "3 2 0 1\n1 0 0 1\n2 1 0 1\n3 0 1 1\n")
    write_file("s.ele", "1 3 0\n1 1 2 3\n")
    write_file("s.area", "1\n1 0.5\n")
    write_file("s.edge", "3 1\n1 1 2 1\n2 2 3 1\n3 3 1 1\n")
    write_file("s.neigh", "1 3\n1 -1 -1 -1\n")
    d, info = read_with_info(tmp_path / "s")
    assert sorted(d) == [
        "edge_markers", "edges", "neighbors", "triangle_max_area", "triangles",
        "vertex_markers", "vertices",
    ]
    assert [p.suffix for p in info.files] == [".node", ".ele", ".area", ".edge", ".neigh"]
    write_file("s.area", "2\n1 0.5\n2 1\n")
    with pytest.raises(FormatError, match="disagree"):
        read(tmp_path / "s")


def test_missing_files_are_os_errors(tmp_path):
    with pytest.raises(FileNotFoundError):
        read(tmp_path / "nothing")
    with pytest.raises(FileNotFoundError):
        read(tmp_path / "nothing.node")


def test_public_names():
    assert issubclass(ruppert_io.FormatError, ValueError)
    for name in ("read", "write", "FormatError", "to_meshio", "from_meshio", "read_with_info"):
        assert hasattr(ruppert_io, name)


def test_info_reports_the_base_of_a_lone_index_file(write_file):
    assert read_with_info(write_file("y.neigh", "1 3\n0 -1 -1 -1\n"))[1].first_index == 0
    write_file("w.node", "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n")
    d, info = read_with_info(write_file("w.edge", "1 0\n7 0 2\n"))
    assert info.first_index == 0 and d["edges"].tolist() == [[0, 2]]
