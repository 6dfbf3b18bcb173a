"""`.area` files: one maximum-area constraint per triangle (spec §2.5).

```
<#triangles>
<tri#> <max area>          # <= 0 or missing: unconstrained
```
Triangle only reads them (``-r`` with a bare ``-a``); we also write them so that a
mesh with ``triangle_max_area`` round-trips.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from . import writing
from .lines import LineReader


def read_area(
    path: str | os.PathLike[str],
    *,
    first_index: int = 1,
    ntriangles: int | None = None,
    ele_path: str | os.PathLike[str] | None = None,
) -> dict[str, np.ndarray]:
    """Read ``triangle_max_area`` (M, 1) float64; a missing value reads as -1.

    When ``ntriangles`` is given (the .ele count) the file must list that many
    triangles, as Triangle requires.  ``first_index`` only numbers the triangles in
    error messages (the triangle numbers in the file are ignored, as in Triangle).
    """
    r = LineReader.open(path)
    line = r.next("the number of triangles")
    count = r.count_field(line, 0, "the number of triangles")
    if ntriangles is not None and count != ntriangles:
        ele = os.fspath(ele_path) if ele_path is not None else "the .ele file"
        raise r.error(
            line,
            f"{ntriangles} triangles, as in {ele}",
            problem=f"{ele} and {r.path} disagree on number of triangles",
            found=str(count),
        )
    block = r.take(line, count, "triangle")
    areas = block.reals(1, 2)
    if areas is None:
        areas = np.empty((count, 1))
        for i, line in enumerate(block):
            areas[i, 0] = r.real_field(
                line,
                1,
                f"the maximum area of triangle {first_index + i}",
                required=False,
                default=-1.0,
            )
    return {"triangle_max_area": areas}


def area_chunks(mesh: Mapping[str, Any], *, first_index: int = 1) -> list[str]:
    """The text of a .area file for ``mesh['triangle_max_area']``."""
    areas = writing.get(mesh, "triangle_max_area", float, 1)
    if areas is None:
        raise ValueError("the mesh has no 'triangle_max_area'")
    numbers = range(first_index, first_index + len(areas))
    return ["%d\n" % len(areas)] + [
        "%4d    %.17g\n" % row for row in zip(numbers, areas[:, 0].tolist())
    ]


def write_area(
    path: str | os.PathLike[str],
    mesh: Mapping[str, Any],
    *,
    first_index: int = 1,
    generated_by: str | None = None,
) -> Path:
    """Write ``mesh['triangle_max_area']`` as a .area file."""
    return writing.write_text(path, area_chunks(mesh, first_index=first_index), generated_by)
