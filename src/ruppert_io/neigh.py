"""`.neigh` files: the three neighbours of each triangle (spec §2.7).

```
<#triangles> 3
<tri#> <nbr1> <nbr2> <nbr3>     # nbr_i is across the edge opposite corner i; -1: none
```
The ``-1`` is literal in 0- and 1-based files alike.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from . import writing
from .lines import LineReader
from .info import Info



def read_neigh(
    path: str | os.PathLike[str],
    *,
    first_index: int | None = None,
    info: Info | None = None,
    ntriangles: int | None = None,
) -> dict[str, np.ndarray]:
    """Read ``neighbors`` (M, 3) int32, 0-based, -1 for none.

    ``first_index`` is the numbering base of the file set; when None it is taken
    from the first triangle's number (0 or 1, else 1).  When ``ntriangles`` is given
    (the .ele count) the file must list that many triangles.  ``info`` (if given)
    receives the base used.
    """
    r = LineReader.open(path)
    line = r.next("the number of triangles")
    count = r.count_field(line, 0, "the number of triangles")
    if ntriangles is not None and count != ntriangles:
        raise r.error(line, f"{ntriangles} triangles, as in the .ele file", found=str(count))
    per = r.int_field(
        line, 1, "the number of neighbours per triangle", required=False, default=3
    )
    if per != 3:
        raise r.error(line, "3 neighbours per triangle", found=str(per))
    block = r.take(line, count, "triangle")
    if first_index is None:
        first_index = r.numbering_base(block, "triangle", 1)
    if info is not None:
        info.first_index = first_index
    values = block.ints(1, 4)
    if values is not None:
        ok = (values == -1) | ((values >= first_index) & (values < first_index + count))
        if ok.all():
            shifted = np.where(values == -1, -1, values - first_index)
            return {"neighbors": shifted.astype(np.int32)}
    neighbors = np.empty((count, 3), dtype=np.int32)
    for i, line in enumerate(block):
        name = f"triangle {first_index + i}"
        for j in range(3):
            value = r.index_field(line, 1 + j, f"neighbour {j + 1} of {name}")
            if value == -1:
                neighbors[i, j] = -1
            elif first_index <= value < first_index + count:
                neighbors[i, j] = value - first_index
            else:
                last = first_index + count - 1
                expected = f"-1 or a triangle number from {first_index} to {last}"
                raise r.error(
                    line, f"{expected} for neighbour {j + 1} of {name}", found=str(value)
                )
    return {"neighbors": neighbors}


def neigh_chunks(mesh: Mapping[str, Any], *, first_index: int = 1) -> list[str]:
    """The text of a .neigh file for ``mesh['neighbors']``."""
    neighbors = writing.get(mesh, "neighbors", int, 3)
    if neighbors is None:
        raise ValueError("the mesh has no 'neighbors'")
    m = len(neighbors)
    shifted = np.where(neighbors >= 0, neighbors + first_index, -1).T.tolist()
    # Triangle: "%ld  %d\n" (M, 3), then "%4ld    %d  %d  %d\n".
    return ["%d  %d\n" % (m, 3)] + [
        "%4d    %d  %d  %d\n" % row for row in zip(range(first_index, first_index + m), *shifted)
    ]


def write_neigh(
    path: str | os.PathLike[str],
    mesh: Mapping[str, Any],
    *,
    first_index: int = 1,
    generated_by: str | None = None,
) -> Path:
    """Write ``mesh['neighbors']`` as a .neigh file."""
    return writing.write_text(path, neigh_chunks(mesh, first_index=first_index), generated_by)
