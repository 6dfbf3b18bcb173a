"""`.off` files (Triangle's ``-g``): vertices and triangles for Geomview (spec §2.9).

```
OFF
<#vertices>  <#triangles>  <#edges>
 x  y  0
 3   i  j  k          # always 0-based
```
Write-only, like in Triangle.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from . import writing


def count_edges(triangles: np.ndarray) -> int:
    """Number of distinct edges among the triangles' three corners."""
    if len(triangles) == 0:
        return 0
    t = triangles[:, :3]
    pairs = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    return len(np.unique(np.sort(pairs, axis=1), axis=0))


def off_chunks(mesh: Mapping[str, Any]) -> list[str]:
    """The text of a .off file (the edge count is Triangle's third header field)."""
    xy = writing.get(mesh, "vertices", float, 2)
    if xy is None:
        raise ValueError("the mesh has no 'vertices'")
    triangles = writing.get(mesh, "triangles", int)
    if triangles is None or triangles.size == 0:
        triangles = np.zeros((0, 3), dtype=np.int64)
    chunks = ["OFF\n%d  %d  %d\n" % (len(xy), len(triangles), count_edges(triangles))]
    chunks += [" %.17g  %.17g  %.17g\n" % (x, y, 0.0) for x, y in xy.tolist()]
    chunks += [" 3   %4d  %4d  %4d\n" % tuple(t) for t in triangles[:, :3].tolist()]
    return chunks


def write_off(
    path: str | os.PathLike[str], mesh: Mapping[str, Any], *, generated_by: str | None = None
) -> Path:
    """Write the vertices and triangles (corners only) as a .off file."""
    return writing.write_text(path, off_chunks(mesh), generated_by)
