"""Shrinking a failing case directly on its input (delta debugging).

The campaign generates cases with Hypothesis but does not let it shrink
(one slow shrink, e.g. of a hang, would stall generation); it shrinks each
distinct failure afterwards with ``shrink``: drop switch letters, then
chunks of vertices (segments renumbered, those using a dropped vertex
dropped), segments, holes and regions, then round coordinates to short
binary fractions, keeping every change after which the same failure
signature still occurs.  Given meshes (``r`` cases) keep their vertices and
triangles; only their switches and segments shrink.
"""

from __future__ import annotations

import math
import re
import time
from collections.abc import Callable

import numpy as np

from .cases import Case

_TOKEN = re.compile(r"o2|[qaS][0-9.]*|Y+|[A-Za-z]")
_PER_VERTEX = ("vertex_markers", "vertex_attributes")
_PER_SEGMENT = ("segment_markers",)


def _tokens(switches: str) -> list[str]:
    return _TOKEN.findall(switches)


def _with(case: Case, **changes) -> Case:
    return Case(
        family=case.family,
        switches=changes.get("switches", case.switches),
        input=changes.get("input", case.input),
        premesh=None,
        meta=dict(case.meta),
    )


def drop_vertices(tri: dict, drop: np.ndarray) -> dict | None:
    """``tri`` without the vertices ``drop`` (a boolean mask); segments that
    use one go, the others are renumbered.  None if fewer than 3 remain."""
    keep = ~drop
    if keep.sum() < 3:
        return None
    new_id = np.cumsum(keep) - 1
    out = {k: np.array(v, copy=True) for k, v in tri.items()}
    out["vertices"] = out["vertices"][keep]
    for key in _PER_VERTEX:
        if key in out:
            out[key] = out[key][keep]
    if "segments" in out and len(out["segments"]):
        s = out["segments"].astype(np.int64)
        ok = keep[s].all(axis=1)
        out["segments"] = new_id[s[ok]].astype(np.int32)
        for key in _PER_SEGMENT:
            if key in out:
                out[key] = out[key][ok]
    return out


def drop_rows(tri: dict, key: str, drop: np.ndarray) -> dict:
    out = dict(tri)
    out[key] = np.asarray(tri[key])[~drop]
    if key == "segments":
        for k in _PER_SEGMENT:
            if k in out:
                out[k] = np.asarray(tri[k])[~drop]
    if not len(out[key]) and key in ("holes", "regions", "segment_markers"):
        del out[key]
    return out


def _chunks(n: int):
    """Masks that drop halves, quarters, ... then single rows."""
    size = max(n // 2, 1)
    while True:
        for start in range(0, n, size):
            mask = np.zeros(n, dtype=bool)
            mask[start : start + size] = True
            yield mask
        if size == 1:
            return
        size = max(size // 2, 1)


def _round(x: float, bits: int) -> float:
    if x == 0 or not math.isfinite(x):
        return x
    m, e = math.frexp(x)
    return math.ldexp(round(m * (1 << bits)) / (1 << bits), e)


def shrink(case: Case, fails: Callable[[Case], bool], budget: float = 60.0) -> tuple[Case, int]:
    """The smallest variant of ``case`` found within ``budget`` seconds for
    which ``fails`` still holds, and the number of trials run."""
    deadline = time.perf_counter() + budget
    trials = 0

    def attempt(candidate: Case | None) -> bool:
        nonlocal trials
        if candidate is None or time.perf_counter() > deadline:
            return False
        trials += 1
        try:
            return fails(candidate)
        except Exception:  # a candidate the harness cannot run is no reproducer
            return False

    given_mesh = "triangles" in case.input
    progress = True
    while progress and time.perf_counter() < deadline:
        progress = False
        toks = _tokens(case.switches)
        for i, t in enumerate(toks):
            if t == "Q":
                continue
            cand = _with(case, switches="".join(toks[:i] + toks[i + 1 :]))
            if attempt(cand):
                case, progress = cand, True
                break
        if progress:
            continue
        for key in ("holes", "regions", "segments") + (() if given_mesh else ("vertices",)):
            rows = case.input.get(key)
            if rows is None or not len(rows):
                continue
            for mask in _chunks(len(rows)):
                if mask.shape[0] != len(case.input.get(key, ())):
                    break  # rows dropped meanwhile: start this key again next round
                inp = drop_vertices(case.input, mask) if key == "vertices" else drop_rows(case.input, key, mask)
                if inp is not None and attempt(_with(case, input=inp)):
                    case, progress = _with(case, input=inp), True
            if progress:
                break
        if progress or given_mesh:
            continue
        for bits in (2, 4, 8, 16, 26):
            v = np.asarray(case.input["vertices"], dtype=np.float64)
            r = np.vectorize(lambda x, b=bits: _round(x, b))(v)
            if np.array_equal(r, v):
                continue
            inp = dict(case.input, vertices=r)
            if attempt(_with(case, input=inp)):
                case, progress = _with(case, input=inp), True
                break
    return case, trials
