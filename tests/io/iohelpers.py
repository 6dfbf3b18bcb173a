"""Shared inputs and checks for the ruppert_io tests (a uniquely named module, so
that it cannot clash with other test folders' conftest.py)."""

from __future__ import annotations

import csv
import os
from pathlib import Path

import numpy as np
import triangle

PKG_DATA = Path(os.path.dirname(triangle.__file__)) / "data"
# The shared corpus sits next to the repository (/work/main -> /work/shared/corpus).
_DEFAULT_CORPUS = Path(__file__).resolve().parents[3] / "shared" / "corpus"
CORPUS = Path(os.environ.get("RUPPERT_CORPUS", _DEFAULT_CORPUS))

INPUT_SUFFIXES = (".node", ".poly", ".ele", ".area", ".edge", ".neigh")


def pkg_files() -> list[Path]:
    """Every input file in the triangle package's data folder."""
    return sorted(p for p in PKG_DATA.iterdir() if p.suffix in INPUT_SUFFIXES)


def corpus_reference() -> dict[str, dict]:
    """Per corpus file: Triangle's reading result from REFERENCE.tsv.

    ``counts`` is (vertices, segments, holes, regions) when Triangle read the file;
    ``reject`` is True when every row failed while reading it.  (A .node file run
    with -p fails only because its .poly is missing, which is no reading failure.)
    """
    rows: dict[str, list[dict]] = {}
    if not (CORPUS / "REFERENCE.tsv").is_file():  # a checkout without shared/ beside it
        return {}
    with open(CORPUS / "REFERENCE.tsv", newline="") as f:
        for row in csv.DictReader(f, delimiter="\t"):
            if row["parser"] in ("strict", "cli"):
                rows.setdefault(row["file"], []).append(row)
    out = {}
    for name, group in rows.items():
        read = [r for r in group if r["in_vertices"] != ""]
        counts = {
            tuple(int(r[k]) for k in ("in_vertices", "in_segments", "in_holes", "in_regions"))
            for r in read
        }
        assert len(counts) <= 1, f"REFERENCE.tsv disagrees with itself on {name}"
        out[name] = {
            "counts": counts.pop() if counts else None,
            "reject": not read,
            "note": " | ".join(sorted({r["note"] for r in group if r["note"]})),
        }
    return out


def assert_same_mesh(a: dict, b: dict) -> None:
    """Same keys, dtypes, shapes and bit-identical values."""
    assert sorted(a) == sorted(b)
    for key in a:
        x, y = np.asarray(a[key]), np.asarray(b[key])
        assert x.dtype == y.dtype, key
        assert x.shape == y.shape, key
        if x.dtype.kind == "f":
            assert np.array_equal(x.view(np.uint64), y.view(np.uint64)), key
        else:
            assert np.array_equal(x, y), key
