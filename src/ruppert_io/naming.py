"""File names: input base names and Triangle's output iteration numbers (spec §2.10)."""

from __future__ import annotations

import os
from pathlib import Path

#: Extensions of the files ``read`` understands, in the order a base name is tried.
INPUT_KINDS = ("node", "poly", "ele", "area", "edge", "neigh")

#: Every file kind ``write`` can produce, in the order Triangle writes them.
OUTPUT_KINDS = ("node", "ele", "poly", "area", "off", "edge", "v.node", "v.edge", "neigh")


def split_kind(path: str | os.PathLike[str]) -> tuple[str, str | None]:
    """Split ``"A.1.poly"`` into ``("A.1", "poly")``; no known extension: ``(path, None)``.

    ``.v.node`` / ``.v.edge`` give the kinds ``"v.node"`` / ``"v.edge"``.
    """
    name = os.fspath(path)
    for kind in ("v.node", "v.edge", *INPUT_KINDS):
        suffix = "." + kind
        if name.endswith(suffix) and len(name) > len(suffix):
            return name[: -len(suffix)], kind
    return name, None


def input_files(base: str | os.PathLike[str]) -> dict[str, Path]:
    """The existing files ``base.node``, ``base.poly``, ... by kind."""
    base = os.fspath(base)
    found = {}
    for kind in INPUT_KINDS:
        path = Path(f"{base}.{kind}")
        if path.is_file():
            found[kind] = path
    return found


def output_base(base: str | os.PathLike[str], *, no_iteration: bool = False) -> str:
    """The base name of Triangle's output files for input base name ``base``.

    The text after the last ``.`` (not counting a dot at index 0 or at the very
    end) is the iteration number if it is all digits: ``x.07`` -> ``x.8``,
    ``A.1`` -> ``A.2``.  Otherwise ``.1`` is appended: ``A`` -> ``A.1``,
    ``a.b.c`` -> ``a.b.c.1``.  Like Triangle, this looks at the whole name,
    directories included.  ``no_iteration`` (Triangle's ``-I``) keeps ``base``.
    """
    name = os.fspath(base)
    if no_iteration:
        return name
    dot = max((j for j in range(1, len(name) - 1) if name[j] == "."), default=0)
    digits = name[dot + 1 :]
    if dot and digits.isascii() and digits.isdigit():
        return f"{name[: dot + 1]}{int(digits) + 1}"
    return f"{name}.1"


def output_files(outbase: str | os.PathLike[str]) -> dict[str, Path]:
    """Every output file name for output base ``outbase``, by kind."""
    outbase = os.fspath(outbase)
    return {kind: Path(f"{outbase}.{kind}") for kind in OUTPUT_KINDS}
