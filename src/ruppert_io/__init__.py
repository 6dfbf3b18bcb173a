"""ruppert_io: Triangle's file formats, and meshio conversion, for ruppert.

``read``/``write`` handle ``.node``, ``.poly``, ``.ele``, ``.area``, ``.edge``,
``.neigh`` (and write ``.v.node``, ``.v.edge``, ``.off``) exactly as Triangle 1.6
reads and prints them, with the ``triangle`` package's dict keys.  Importing this
package registers the meshio format ``"triangle"`` for ``.node``/``.ele``/``.poly``
(when meshio itself is imported, so that the ``ruppert`` command need not load it);
``write_meshio`` writes a mesh in any of meshio's formats, shaped for each.
"""

from .api import Info, read, read_with_info, write, write_voronoi
from .errors import FormatError
from .meshio_formats import FormatUnavailable, write_meshio
from .meshio_plugin import from_meshio, register, register_when_imported, to_meshio

__all__ = [
    "FormatError",
    "FormatUnavailable",
    "Info",
    "from_meshio",
    "read",
    "read_with_info",
    "to_meshio",
    "write",
    "write_meshio",
    "write_voronoi",
]

register_when_imported()
