"""Real inputs: the triangle package's data folder and the shared corpus.

Counts must equal what Triangle read (corpus REFERENCE.tsv); files Triangle rejects
must raise FormatError naming file and line; everything must round-trip exactly.
"""

from __future__ import annotations

import numpy as np
import pytest
import triangle

from iohelpers import CORPUS, PKG_DATA, assert_same_mesh, corpus_reference, pkg_files

import ruppert_io
from ruppert_io import FormatError, naming

REFERENCE = corpus_reference()
CORPUS_OK = sorted(name for name, ref in REFERENCE.items() if not ref["reject"])
CORPUS_REJECT = sorted(name for name, ref in REFERENCE.items() if ref["reject"])


@pytest.mark.skipif(not CORPUS.is_dir(), reason="shared corpus not found beside the checkout")
def test_reference_covers_the_corpus():
    files = sorted(p.name for p in CORPUS.iterdir() if p.suffix in (".node", ".poly"))
    assert sorted(REFERENCE) == files
    assert CORPUS_REJECT == [
        "CGAL__cgal__fish.poly",
        "ssalinasfe__Polylla-Mesh__2x2RPDisk_1000.poly",
        "tnakaicode__jburkardt-data__example3d.poly",
    ]


@pytest.mark.parametrize("name", CORPUS_OK)
def test_corpus_counts_match_triangle(name):
    d, info = ruppert_io.read_with_info(CORPUS / name)
    got = tuple(len(d.get(k, ())) for k in ("vertices", "segments", "holes", "regions"))
    assert got == REFERENCE[name]["counts"]
    assert info.warnings == []


@pytest.mark.parametrize(
    "name, line, message",
    [
        ("CGAL__cgal__fish.poly", 39, "unexpected end of file; expected the number of holes"),
        (
            "ssalinasfe__Polylla-Mesh__2x2RPDisk_1000.poly",
            1007,
            "unexpected end of file; expected the number of holes",
        ),
        (
            "tnakaicode__jburkardt-data__example3d.poly",
            11,
            "Triangle only works with two-dimensional meshes; expected dimension 2, found 3",
        ),
    ],
)
@pytest.mark.skipif(not CORPUS.is_dir(), reason="shared corpus not found beside the checkout")
def test_corpus_rejects(name, line, message):
    assert name in CORPUS_REJECT
    with pytest.raises(FormatError) as e:
        ruppert_io.read(CORPUS / name)
    assert e.value.path == str(CORPUS / name) and e.value.line == line
    assert str(e.value) == f"{CORPUS / name}, line {line}: {message}"


@pytest.mark.skipif(not CORPUS.is_dir(), reason="shared corpus not found beside the checkout")
def test_corpus_quirks():
    # 0-based files (spec: the first vertex number decides).
    for name in ("Kristianped__Triangle__test.poly", "mr-jstar__jfem__y.poly"):
        assert ruppert_io.read_with_info(CORPUS / name)[1].first_index == 0
    # "105 2": any nonzero segment-marker count means one marker column.
    airfoil = CORPUS / "tnakaicode__jburkardt-data__airfoil_exterior.poly"
    d, info = ruppert_io.read_with_info(airfoil)
    assert info.segment_markers == 2 and d["segment_markers"].shape == (105, 1)
    # Region lines with one value use it as attribute and area (cheekujodhpur: 128 such).
    regions = ruppert_io.read(CORPUS / "cheekujodhpur__2dgrpt__input.poly")["regions"]
    assert np.array_equal(regions[:, 2], regions[:, 3])
    # Large vertex markers are kept (hex.poly uses vertex ids as markers).
    hexd = ruppert_io.read(CORPUS / "IngInx747__Delaunay-refinement__hex.poly")
    assert hexd["vertex_markers"][0, 0] == 3082


# The package's loader reads these files correctly except for its known bugs
# (regions misparsed, empty holes omitted, no .edge without rays, .neigh keys).
PKG_BASES = sorted({naming.split_kind(p.name)[0] for p in pkg_files() if ".v." not in p.name})
LOADER_KEYS = (
    "vertices",
    "vertex_attributes",
    "vertex_markers",
    "segments",
    "segment_markers",
    "triangles",
    "triangle_attributes",
    "triangle_max_area",
)


INT_KEYS = ("segments", "triangles", "edges", "neighbors")


@pytest.mark.parametrize("path", pkg_files(), ids=lambda p: p.name)
def test_package_data_reads(path):
    d = ruppert_io.read(path)
    assert d, path
    for key, value in d.items():
        is_int = key in INT_KEYS or key.endswith("markers")
        assert value.dtype == (np.int32 if is_int else np.float64), key
        assert value.ndim == 2


@pytest.mark.parametrize("base", PKG_BASES)
def test_package_data_agrees_with_triangle_load(base):
    ours = ruppert_io.read(PKG_DATA / base)
    theirs = triangle.load(str(PKG_DATA), base)
    for key in LOADER_KEYS:
        assert (key in ours) == (key in theirs), key
        if key in ours:
            assert np.array_equal(ours[key], theirs[key]) and ours[key].dtype == theirs[key].dtype
    if len(ours.get("holes", ())):
        assert np.array_equal(ours["holes"], theirs["holes"])


def test_package_regions_read_as_triangle_does():
    # la.poly: "1  6  -0.2  0.05" is x, y and one value used as attribute and area.
    regions = ruppert_io.read(PKG_DATA / "la.poly")["regions"]
    assert regions[0].tolist() == [6, -0.2, 0.05, 0.05]


ROUND_TRIP = [(PKG_DATA, b) for b in PKG_BASES] + [
    (CORPUS, naming.split_kind(n)[0]) for n in CORPUS_OK
]


@pytest.mark.parametrize("folder, base", ROUND_TRIP, ids=[b for _, b in ROUND_TRIP])
def test_round_trip_and_triangle_load(folder, base, tmp_path):
    original = ruppert_io.read(folder / base)
    for first in (0, 1):
        out = tmp_path / f"out{first}"
        paths = ruppert_io.write(out, original, first_index=first, generated_by="pytest")
        assert all(p.read_text().endswith("# Generated by pytest\n") for p in paths)
        again, info = ruppert_io.read_with_info(out)
        assert info.first_index == first
        assert_same_mesh(original, again)
        loaded = triangle.load(str(tmp_path), f"out{first}")
        for key in LOADER_KEYS:
            if key in original:
                assert np.array_equal(loaded[key], original[key]), key


def _generated_by(path):
    last = path.read_bytes().rstrip(b"\n").rsplit(b"\n", 1)[-1]
    prefix = b"# Generated by "
    return last[len(prefix) :].decode() if last.startswith(prefix) else None


TRIANGLE_OUTPUTS = [p for p in pkg_files() + sorted(PKG_DATA.glob("*.v.*")) if _generated_by(p)]


@pytest.mark.parametrize("path", TRIANGLE_OUTPUTS, ids=lambda p: p.name)
def test_triangle_outputs_are_reproduced_byte_for_byte(path, tmp_path):
    base, kind = naming.split_kind(path)
    out = tmp_path / "copy"
    if kind in ("v.node", "v.edge"):
        vor = {**ruppert_io.read(base + ".v.node"), **ruppert_io.read(base + ".v.edge")}
        [written] = ruppert_io.write(
            out, {}, kinds=[kind], voronoi=vor, generated_by=_generated_by(path)
        )
    else:
        mesh = ruppert_io.read(base)
        kinds = ["node", kind] if kind == "poly" else [kind]
        written = ruppert_io.write(out, mesh, kinds=kinds, generated_by=_generated_by(path))[-1]
    if path.name.startswith("dots.1.v."):
        # Printed by a C library that pads %.17g with zeros past the exact digits
        # (0.016920000000000040 for glibc's ...039); the values are the same.
        assert_same_mesh(ruppert_io.read(written), ruppert_io.read(path))
    else:
        assert written.read_bytes() == path.read_bytes()
