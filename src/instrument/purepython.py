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

import importlib
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


class _CimportAliases(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Makes ``from cython.cimports.instrument.x import f`` (a cimport,
    compiled) a plain import of ``instrument.x`` in Python.  Cython's own
    stand-in module does this only for ``libc``, not for packages."""

    PREFIX = "cython.cimports."

    def find_spec(self, name, path=None, target=None):
        if name.startswith(self.PREFIX + PACKAGE) and name != self.PREFIX + "libc":
            return importlib.machinery.ModuleSpec(name, self, is_package=True)
        return None

    def create_module(self, spec):
        return importlib.import_module(spec.name[len(self.PREFIX):])

    def exec_module(self, module):
        pass


def enable() -> None:
    """Load every ``instrument`` submodule imported from now on from source."""
    if not any(isinstance(f, _SourceFinder) for f in sys.meta_path):
        sys.meta_path.insert(0, _SourceFinder())
    _alias_cimports()


def _alias_cimports() -> None:
    import cython  # noqa: F401  (installs cython.cimports, which the aliases extend)

    stand_in = sys.modules.get("cython.cimports")
    if stand_in is not None and "__spec__" not in vars(stand_in):
        stand_in.__spec__ = None  # the import system reads a parent's __spec__
    if not any(isinstance(f, _CimportAliases) for f in sys.meta_path):
        sys.meta_path.insert(0, _CimportAliases())


def load_source(name: str):
    """A fresh module object for ``name`` run from its ``.py`` file, whatever
    the mode (for tests of a kernel module's internals, which compiled code
    does not expose).  Only for modules that import no other kernel module."""
    _alias_cimports()
    # in the pure-Python mode the module may already be loaded from its .py
    # by this module's finder, whose spec names no origin: its file does
    loaded = sys.modules.get(name)
    origin = getattr(loaded, "__file__", None) or importlib.util.find_spec(name).origin
    path = Path(origin).with_suffix("").with_suffix(".py")
    loader = importlib.machinery.SourceFileLoader(f"{name}.__source__", str(path))
    module = importlib.util.module_from_spec(importlib.util.spec_from_loader(loader.name, loader))
    loader.exec_module(module)
    return module


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
