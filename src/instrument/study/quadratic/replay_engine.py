"""Theorem 3's script as an engine of the study: ``instrument.quadratic.replay`` on I(n).

The row's strategy is the one that finishes the refinement after the scripted
phase (``then``).  ``work`` holds every counter of the whole run plus the
scripted phase's own: ``scripted_created`` (triangles created by the scripted
splits, the quantity Theorem 3 bounds), ``steps``, ``scripted_incircle`` and
``scripted_orient``.  The time includes the per-step checks of Lemmas 1 and 2.
"""

from __future__ import annotations

import time
from collections.abc import Mapping


def measure(data: dict, switches: str, *, strategy: str = "triangle", seed: int = 0, repeat: int = 1,
            params: Mapping | None = None) -> dict:
    """Theorem 3's scripted run on I(n), finished by ``strategy``.  The
    script is deterministic, so ``seed`` (every engine's parameter) is
    unused."""
    from instrument import quadratic

    params = dict(params or {})
    if "n" not in params:
        raise ValueError("the replay engine runs on the quadratic family only (I(n): quadratic:n=...)")
    n, alpha = int(params["n"]), float(params.get("alpha", 20.0))
    then = strategy or "triangle"
    t0 = time.perf_counter()
    res = quadratic.replay(n, alpha, then=then)
    wall = time.perf_counter() - t0
    work = dict(res.work)
    work.update(scripted_created=int(res.steps.sum()), steps=len(res.steps),
                scripted_incircle=int(res.scripted_work["incircle_tests"]),
                scripted_orient=int(res.scripted_work["orient_tests"]))
    return {"mesh": res, "wall_s": wall, "work": work, "note": f"then={then}; time includes the per-step checks"}
