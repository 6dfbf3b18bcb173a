"""The state every stage of the pipeline shares while a mesh is built.

``MeshState`` holds the mesh (``core.mesh.Mesh``: vertices, triangles and
every per-vertex and per-triangle table), the subsegment records, and what
the stages learn about the input on the way: which input vertices
duplicate others, the warnings Triangle would print, which vertices
refinement deleted.  Kernels never allocate; when one reports
``NEED_ROOM`` its driver calls ``grow`` and calls it again.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .core.mesh import Mesh
from .core.subsegments import Subsegments


@dataclass
class MeshState:
    """The mesh being built and what the stages learned about the input."""

    mesh: Mesh
    segs: Subsegments
    n_input: int  # input vertices (the first rows of the mesh's vertices)
    dup: np.ndarray  # per input vertex: -1, or the input vertex it duplicates
    n_triangles_initial: int  # triangles the input's triangulation had (0: collinear input)
    warnings: list[str] = field(default_factory=list)
    dead: np.ndarray | None = None  # vertices refinement deleted (left out of the output)
    # rows (copy, vertex): crossings segment recovery made as copies of an
    # input vertex, outside the mesh (Triangle outputs such a crossing twice)
    copies: np.ndarray | None = None

    @property
    def work(self) -> np.ndarray:
        """The work counters (the mesh counts its own work)."""
        return np.asarray(self.mesh.work)

    @property
    def n_vertices(self) -> int:
        return self.mesh.nvert

    @property
    def collinear(self) -> bool:
        """True if the input vertices had no triangulation at all."""
        return self.n_triangles_initial == 0

    def grow(self, vertices: int = 0, triangles: int = 0, records: int = 0) -> None:
        """Make room for at least that many more of each (doubling)."""
        if vertices:
            self.mesh.grow_vertices(vertices)
        if triangles:
            self.mesh.grow_triangles(triangles)
        if records:
            self.segs.grow(records)
