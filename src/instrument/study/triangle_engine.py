"""Triangle (the `triangle` package) as one of the study's engines.

``run_triangle`` times the package as its users call it (quiet switches);
``triangle_statistics`` runs it once more with ``V`` and reads the statistics
Triangle prints from C (incircle and orientation tests, circumcenter
computations) by redirecting file descriptor 1.

Counts are made comparable: Triangle's printed orientation count includes one
``orient2d`` call per output triangle made by the ``V`` quality statistics
themselves, which our engine's counter (library mode, no statistics) does not
make, so ``orient_tests`` is the printed count minus the number of output
triangles; the raw figure stays as ``orient_tests_printed``.

The package can crash the interpreter on bad input (a NaN coordinate, a
segment at a duplicate vertex): the sweep runs it in a separate process.
"""

from __future__ import annotations

import contextlib
import ctypes
import ctypes.util
import math
import os
import re
import sys
import tempfile
import time
from collections.abc import Mapping

import numpy as np

from .ours_engine import LONG_RUN_S

_EXP_NUMBER = re.compile(r"([qa])([0-9]*\.?[0-9]*)([eE][-+]?[0-9]+)")


def triangle_switches(opts: str) -> str:
    """``opts`` for Triangle: numbers after ``q``/``a`` written with an exponent
    (which our engine accepts) become plain decimals, because Triangle reads
    ``a1e-4`` as area 1 plus the ``e`` switch."""

    def plain(m: re.Match) -> str:
        if not m.group(2).strip("."):
            return m.group(0)
        value = float(m.group(2) + m.group(3))
        return m.group(1) + np.format_float_positional(value, trim="-")

    return _EXP_NUMBER.sub(plain, opts)


def _libc_fflush() -> None:
    """Flush C's stdio buffers (Triangle prints with printf)."""
    try:
        libc = ctypes.CDLL(None)
    except OSError:  # pragma: no cover - platforms without a global namespace
        name = ctypes.util.find_library("c")
        if not name:
            return
        libc = ctypes.CDLL(name)
    libc.fflush(None)


@contextlib.contextmanager
def capture_c_stdout():
    """Redirect file descriptor 1 (C's stdout) to a temporary file for the
    duration of the block; yields a list that holds the captured text after."""
    captured: list[str] = []
    with contextlib.suppress(Exception):
        sys.stdout.flush()
    _libc_fflush()
    saved = os.dup(1)
    with tempfile.TemporaryFile() as tmp:
        os.dup2(tmp.fileno(), 1)
        try:
            yield captured
        finally:
            _libc_fflush()
            os.dup2(saved, 1)
            os.close(saved)
            tmp.seek(0)
            captured.append(tmp.read().decode("utf-8", errors="replace"))


_STAT_PATTERNS = {
    "incircle_tests": r"Number of incircle tests:\s*(\d+)",
    "orient3d_tests": r"Number of 3D orientation tests:\s*(\d+)",
    "orient_tests_printed": r"Number of 2D orientation tests:\s*(\d+)",
    "circumcenters": r"Number of triangle circumcenter computations:\s*(\d+)",
    "hyperbola_tests": r"Number of right-of-hyperbola tests:\s*(\d+)",
    "circletop_tests": r"Number of circle top computations:\s*(\d+)",
    "mesh_vertices": r"Mesh vertices:\s*(\d+)",
    "mesh_triangles": r"Mesh triangles:\s*(\d+)",
    "mesh_edges": r"Mesh edges:\s*(\d+)",
    "mesh_subsegments": r"Mesh subsegments \(constrained edges\):\s*(\d+)",
    "max_encroached_subsegments": r"Maximum number of encroached subsegments:\s*(\d+)",
    "max_bad_triangles": r"Maximum number of bad triangles:\s*(\d+)",
}


def parse_triangle_statistics(text: str) -> dict[str, int]:
    """The counters of Triangle's ``V`` statistics block, by our names (absent
    lines are left out, except the circumcenter count, which Triangle prints
    only when it is nonzero).  ``orient_tests`` is the printed 2-D orientation
    count minus the one call per output triangle that the quality statistics
    make."""
    stats: dict[str, int] = {}
    for key, pattern in _STAT_PATTERNS.items():
        m = re.search(pattern, text)
        if m:
            stats[key] = int(m.group(1))
    if "incircle_tests" in stats or "orient3d_tests" in stats:
        stats.setdefault("circumcenters", 0)
        if "orient_tests_printed" in stats:
            stats["orient_tests"] = stats["orient_tests_printed"] - stats.get("mesh_triangles", 0)
    return stats


def _nonempty(tri: dict) -> dict:
    """The keys the `triangle` package can take: it fails on empty arrays
    (``holes`` of shape (0, 2), say), which mean the same as absent keys."""
    return {k: v for k, v in tri.items() if v is not None and np.asarray(v).size}


def triangle_input(tri: dict) -> tuple[dict, list[str]]:
    from triangle.tri import translate_inv

    known = {translate_inv[k]: v for k, v in _nonempty(tri).items() if k in translate_inv}
    dropped = sorted(k for k in tri if k not in translate_inv)
    return known, dropped


def triangle_statistics(tri: dict, opts: str) -> tuple[dict, dict[str, int], str]:
    """Run Triangle with ``V`` (and without ``Q``), capturing what it prints
    from C: (output dict, parsed statistics, raw text)."""
    from triangle.tri import translate_frw, triang

    c_in, _ = triangle_input(tri)
    sw = re.sub(r"[QV]", "", triangle_switches(opts))
    with capture_c_stdout() as text:
        out, _ = triang(c_in, f"z{{{sw}}}V")
    raw = text[0] if text else ""
    return {translate_frw[k]: v for k, v in out.items()}, parse_triangle_statistics(raw), raw


def run_triangle(tri: dict, opts: str, *, repeat: int = 3):
    """Time the `triangle` package (quiet, as its users call it): (result, best wall time)."""
    import triangle

    data = _nonempty(tri)
    sw = triangle_switches(opts)
    best = math.inf
    out = None
    for _ in range(max(1, repeat)):
        t0 = time.perf_counter()
        out = triangle.triangulate(data, sw)
        best = min(best, time.perf_counter() - t0)
        if best > LONG_RUN_S:
            break
    return out, best



def measure(data: dict, switches: str, *, strategy: str = "", seed: int = 0, repeat: int = 3,
            params: Mapping | None = None) -> dict:
    """The study's engine interface: output mesh, best wall time, the ``V`` statistics."""
    out, wall = run_triangle(data, switches, repeat=repeat)
    _, stats, _ = triangle_statistics(data, switches)
    notes = [] if "incircle_tests" in stats else ["statistics not captured"]
    dropped = triangle_input(data)[1]
    if dropped:
        notes.append(f"keys dropped: {dropped}")
    return {"mesh": out, "wall_s": wall, "work": stats, "note": "; ".join(notes)}
