"""Run the engine's kernels as plain Python, from their sources.

The kernels are compiled when the package is built (see ``setup.py``); each
compiled module sits beside the ``.py`` file it was made from, and Python
imports the compiled one.  With the environment variable
``RUPPERT_PURE_PYTHON=1`` set before ``instrument`` is imported, every
module of the package is loaded from its ``.py`` file instead: the same
code, run by the interpreter (about a hundred times slower), so that a
debugger, ``print`` and coverage see inside the kernels, and array indexing
is checked by numpy.  It needs the ``cython`` package, whose pure-Python
stand-ins the kernels import.

Without that variable a package whose kernels were never compiled (a bare
source checkout) refuses to import, rather than run a hundred times slower
without a word.
"""

from __future__ import annotations

import importlib.abc
import importlib.machinery
import importlib.util
import os
import sys
from pathlib import Path

ENV = "RUPPERT_PURE_PYTHON"
PACKAGE = "instrument"


def requested() -> bool:
    """True if the environment asks for the pure-Python kernels."""
    return os.environ.get(ENV, "") not in ("", "0")


class _SourceFinder(importlib.abc.MetaPathFinder):
    """Finds ``instrument.*`` modules as ``.py`` files only."""

    def find_spec(self, name, path=None, target=None):
        if not name.startswith(PACKAGE + ".") or not path:
            return None
        leaf = name.rpartition(".")[2]
        for entry in path:
            candidate = Path(entry) / f"{leaf}.py"
            if candidate.is_file():
                loader = importlib.machinery.SourceFileLoader(name, str(candidate))
                return importlib.util.spec_from_file_location(name, candidate, loader=loader)
        return None  # a subpackage: the ordinary finders handle its __init__.py


def enable() -> None:
    """Load every ``instrument`` submodule imported from now on from source."""
    if not any(isinstance(f, _SourceFinder) for f in sys.meta_path):
        sys.meta_path.insert(0, _SourceFinder())


def is_compiled(module) -> bool:
    """True if ``module`` was loaded from a compiled extension."""
    return isinstance(getattr(module, "__loader__", None), importlib.machinery.ExtensionFileLoader)


def require_compiled(module) -> None:
    """Refuse to run kernels as Python by accident (see the module docstring)."""
    if not requested() and not is_compiled(module):
        raise ImportError(
            f"ruppert's engine is not compiled ({module.__name__} was found as Python source): "
            f"install the package (pip install .), or set {ENV}=1 to run the kernels as plain Python"
        )
