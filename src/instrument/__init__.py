"""ruppert's engine: Delaunay triangulation and Ruppert refinement that count their work.

``import instrument as triangle`` gives the `triangle` package's API.
"""

from . import purepython

if purepython.requested():
    purepython.enable()
from .core import predicates as _predicates  # noqa: E402  (the kernels must be built)

purepython.require_compiled(_predicates)

from .compat import convex_hull, delaunay, voronoi
from .driver import triangulate
from .output import Result
from .plot import compare, comparev, plot, work
from .strategies import strategies

__all__ = ["Result", "compare", "comparev", "convex_hull", "delaunay", "plot", "strategies", "triangulate", "voronoi", "work"]
