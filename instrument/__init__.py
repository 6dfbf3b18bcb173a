"""ruppert's engine: Delaunay triangulation and Ruppert refinement that count their work.

``import instrument as triangle`` gives the `triangle` package's API.
"""

from .driver import triangulate
from .output import Result

__all__ = ["triangulate", "Result"]
