"""ruppert's engine: Delaunay triangulation and Ruppert refinement that count their work.

``import instrument as triangle`` gives the `triangle` package's API.
"""

from . import purepython

if purepython.requested():
    purepython.enable()
from .core import predicates as _predicates  # noqa: E402  (the kernels must be built)

purepython.require_compiled(_predicates)

from .compat import convex_hull, delaunay, voronoi
from .pipeline import triangulate
from .errors import SizeLimitError, TriangleError
from .output import Result
from .plot import compare, comparev, plot, work
from .samples import get_data, load, loads, show_data
from .refine.order import strategies

from .version import __version__

__all__ = [
    "Result",
    "SizeLimitError",
    "TriangleError",
    "__version__",
    "compare",
    "comparev",
    "convex_hull",
    "delaunay",
    "get_data",
    "load",
    "loads",
    "plot",
    "show_data",
    "strategies",
    "triangulate",
    "voronoi",
    "work",
]
