"""``filled``: numpy's ``full`` without most of its cost on small arrays.

``np.full`` fills through ``copyto`` and takes about 5 us even for an
empty array (numpy 2.4); an empty array's ``fill`` does the same work in
under half of that.  A small mesh allocates some twenty such tables per
``triangulate`` call (the mesh's, the subsegment records', the scratch of
each stage), where the difference was a twentieth of the run.
"""

from __future__ import annotations

import numpy as np


def filled(shape, value, dtype=np.float64) -> np.ndarray:
    """A new array of ``shape`` and ``dtype`` with every entry ``value``."""
    a = np.empty(shape, dtype=dtype)
    a.fill(value)
    return a
