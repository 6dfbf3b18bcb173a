"""ruppert's engine: Delaunay triangulation and Ruppert refinement that count their work.

``import instrument as triangle`` gives the `triangle` package's API.
"""

from .compat import convex_hull, delaunay, voronoi
from .driver import triangulate
from .output import Result
from .plot import compare, comparev, plot, work
from .strategies import strategies

__all__ = ["Result", "compare", "comparev", "convex_hull", "delaunay", "plot", "strategies", "triangulate", "voronoi", "work"]
