"""The version of ruppert, written here only: ``pyproject.toml`` reads it
when the package is built, and ``instrument.__version__`` is this (reading the
installed distribution's metadata instead cost every command about 15 ms of
imports)."""

__version__ = "0.6.0"
