"""Our engine as one of the study's engines: ``instrument.triangulate``, timed.

Loading the compiled kernels is never timed: ``warm_up`` runs the engine
once on a tiny input with the same switches and strategy first.
Every engine's runner times ``repeat`` runs and keeps the best, but stops
after a run of more than ``LONG_RUN_S`` seconds (its noise is small then).
"""

from __future__ import annotations

import contextlib
import math
import re
import time
import types
from collections.abc import Mapping

LONG_RUN_S = 5.0  # no more timed runs after one this long
_WARMED: set[str] = set()
_AREA = re.compile(r"a[0-9]*\.?[0-9]*(?:[eE][-+]?[0-9]+)?")

_WARM_INPUT = {
    "vertices": [[0, 0], [3, 0], [3, 2], [0, 2], [1, 0.5], [2, 0.5], [2, 1.5], [1, 1.5], [1.5, 1.9]],
    "segments": [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]],
    "holes": [[1.5, 1.0]],
}


def available_strategies() -> list[str]:
    """Strategy names of our engine: ``instrument.strategies()`` if it exists
    (a mapping, a list of names or of (name, description) pairs, or text with
    one strategy per line), else ``["triangle"]``."""
    import instrument

    fn = getattr(instrument, "strategies", None)
    if isinstance(fn, types.ModuleType):  # the submodule, not (yet) the function
        fn = getattr(fn, "strategies", None)
    if fn is None:
        return ["triangle"]
    listed = fn() if callable(fn) else fn
    if isinstance(listed, Mapping):
        names = [str(k) for k in listed]
    elif isinstance(listed, str):
        names = [ln.split()[0].rstrip(":") for ln in listed.splitlines() if ln.strip()]
    else:
        names = []
        for item in listed:
            if isinstance(item, str):
                names.append(item.split()[0].rstrip(":"))
            elif isinstance(item, (tuple, list)):
                names.append(str(item[0]))
            else:
                names.append(str(getattr(item, "name", item)))
    return names or ["triangle"]


def engine_options(threads: int | None = None) -> dict:
    """Keyword arguments for ``instrument.triangulate`` beyond switches and
    strategy: ``threads`` only when given (an engine without the keyword
    still runs every other call).  Raises ``TypeError`` when ``threads`` is
    given and this engine's ``triangulate`` does not take it."""
    if threads is None:
        return {}
    import inspect

    import instrument

    if "threads" not in inspect.signature(instrument.triangulate).parameters:
        raise TypeError("this ruppert's instrument.triangulate takes no 'threads' argument")
    return {"threads": int(threads)}


def warm_up(opts: str, strategy: str = "triangle", threads: int | None = None) -> None:
    """Run our engine once on a tiny input so that loading the compiled
    kernels (and importing what they use) is not timed; once per switches,
    strategy and thread count."""
    opts = _AREA.sub("", opts)  # the code path is the same; a small area on this box would be slow
    key = f"{opts}\0{strategy}\0{threads}"
    if key in _WARMED:
        return
    _WARMED.add(key)
    import instrument

    kw = engine_options(threads)
    with contextlib.suppress(Exception):
        instrument.triangulate(_WARM_INPUT, opts, strategy=strategy, **kw)


def run_ours(tri: dict, opts: str, strategy: str = "triangle", *, seed: int = 0, repeat: int = 3,
             threads: int | None = None):
    """Time our engine: (result, best wall time of ``repeat`` runs).
    ``threads``: passed to ``instrument.triangulate`` (``engine_options``)."""
    import instrument

    kw = engine_options(threads)
    warm_up(opts, strategy, threads)
    best = math.inf
    out = None
    for _ in range(max(1, repeat)):
        out = None  # the previous run's output goes before the next one is made
        t0 = time.perf_counter()
        out = instrument.triangulate(tri, opts, strategy=strategy, seed=seed, **kw)
        best = min(best, time.perf_counter() - t0)
        if best > LONG_RUN_S:
            break
    return out, best


def measure(data: dict, switches: str, *, strategy: str = "triangle", seed: int = 0, repeat: int = 3,
            params: Mapping | None = None) -> dict:
    """The study's engine interface: output mesh, best wall time, every counter."""
    out, wall = run_ours(data, switches, strategy, seed=seed, repeat=repeat)
    return {"mesh": out, "wall_s": wall, "work": dict(getattr(out, "work", {}) or {})}


class EngineTimeout(RuntimeError):
    """Our engine did not finish within the time limit (its process was killed)."""


def run_ours_isolated(tri: dict, opts: str, strategy: str = "triangle", *, seed: int = 0, repeat: int = 3,
                      timeout: float = 60.0, threads: int | None = None):
    """``run_ours`` in a separate process killed after ``timeout`` seconds
    (``instrument.study.isolate``): (result dict, work, best wall time).
    Raises ``EngineTimeout``, ``NotImplementedError`` or ``RuntimeError``."""
    from . import isolate

    outcome = isolate.call(_ours_plain, (tri, opts, strategy, seed, repeat, threads), time_limit=timeout)
    if outcome.status == "ok":
        return outcome.value
    if outcome.status == "timeout":
        raise EngineTimeout(outcome.message)
    if outcome.error_type == "NotImplementedError":
        raise NotImplementedError(outcome.message)
    raise RuntimeError(outcome.message)


def _ours_plain(tri, opts, strategy, seed, repeat, threads=None):
    """``run_ours`` with plain values, to cross a process boundary."""
    out, wall = run_ours(tri, opts, strategy, seed=seed, repeat=repeat, threads=threads)
    return dict(out), dict(getattr(out, "work", {}) or {}), wall
