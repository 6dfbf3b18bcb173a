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
from .refine.order import strategies

from .version import __version__

#: Loaded on first use (PEP 562): the sample-data functions, which the
#: ``ruppert`` command and most meshing never call, and which cost a few
#: milliseconds of every start-up.
_LAZY = {"get_data": "samples", "load": "samples", "loads": "samples", "show_data": "samples"}


def __getattr__(name: str):
    if name in _LAZY:
        from importlib import import_module

        value = getattr(import_module(f".{_LAZY[name]}", __name__), name)
        globals()[name] = value
        return value
    if name == "samples":
        from importlib import import_module

        return import_module(".samples", __name__)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

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
