"""Exact re-expressions of a Triangle input: the same geometry, other incidentals.

Mirroring (x -> -x or y -> -y), swapping the axes, a half turn, and reversing
the segment list or each segment's direction change no coordinate's value
(only signs and places), so the domain, its segments, holes and regions are
the same set; yet Triangle's refinement order depends on such incidentals,
and its mesh size moves with them.  The size oracle of the differential
harness and ``scripts/triangle_spread.py`` both measure that spread with
these helpers.
"""

from __future__ import annotations

import numpy as np

#: every re-expression ``transformed`` knows
KINDS = ("mirror", "mirror-y", "swap-xy", "half-turn", "reverse-segments", "flip-segments")

_POINT_KEYS = ("vertices", "holes", "regions")
_ORIENTATION_REVERSING = ("mirror", "mirror-y", "swap-xy")


def transformed(tri: dict, kind: str) -> dict:
    """The same input as ``tri``, re-expressed exactly by ``kind`` (one of ``KINDS``).

    A re-expression that reverses orientation also reverses the corner order
    of given triangles (for ``r``), so they stay counter-clockwise."""
    if kind not in KINDS:
        raise ValueError(f"unknown re-expression {kind!r}; one of {', '.join(KINDS)}")
    out = {k: np.array(v, copy=True) for k, v in tri.items()}
    for key in _POINT_KEYS:
        if key in out and out[key].size:
            pts = out[key]
            if kind == "mirror":
                pts[:, 0] = -pts[:, 0]
            elif kind == "mirror-y":
                pts[:, 1] = -pts[:, 1]
            elif kind == "half-turn":
                pts[:, :2] = -pts[:, :2]
            elif kind == "swap-xy":
                pts[:, [0, 1]] = pts[:, [1, 0]]
    if kind in _ORIENTATION_REVERSING and "triangles" in out and out["triangles"].size:
        t = out["triangles"]
        t[:, [1, 2]] = t[:, [2, 1]]
        if t.shape[1] == 6:  # the midpoint opposite corner k sits in column 3 + k
            t[:, [4, 5]] = t[:, [5, 4]]
    if "segments" in out and out["segments"].size:
        if kind == "reverse-segments":
            out["segments"] = out["segments"][::-1].copy()
            if "segment_markers" in out:
                out["segment_markers"] = out["segment_markers"][::-1].copy()
        elif kind == "flip-segments":
            out["segments"] = out["segments"][:, ::-1].copy()
    return out
