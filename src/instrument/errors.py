"""``TriangleError``: the one exception type for input the engine cannot mesh.

The `triangle` package reports Triangle's failures (``r`` without triangles, a
non-positive area bound, an invalid vertex index, ...) as ``RuntimeError``,
and a few checks of its own (fewer than three vertices, unreadable numbers)
as ``ValueError``.  Code written for the package catches one or the other, and
code written for this engine may catch ``ValueError`` (the Python convention
for bad arguments).  ``TriangleError`` derives from both, so every
``except`` clause of either kind keeps working after ``import instrument as
triangle``.  Every input error ``instrument.triangulate`` raises is a
``TriangleError`` (or a subclass), except an unknown input key, which is a
``KeyError`` as in the package.
"""

from __future__ import annotations

__all__ = ["TriangleError", "SizeLimitError"]


class TriangleError(ValueError, RuntimeError):
    """Input that Triangle (and so this engine) cannot triangulate or refine."""


class SizeLimitError(TriangleError):
    """Refinement would outgrow the vertex limit (``max_vertices``): raised
    instead of running until memory is exhausted (``instrument.limits``)."""
