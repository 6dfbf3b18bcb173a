"""Markers and per-vertex/per-triangle arrays: lengths, and nonzero boundary markers.

Triangle gives boundary subsegments and their endpoints a nonzero marker
(reference 2.12, rules 3-5); the other arrays of the output dict must have a
row per vertex, subsegment or triangle.
"""

from __future__ import annotations

import numpy as np

from .view import Edges, MeshView, Problems, segment_keys


def check_markers(m: MeshView, result, e: Edges, probs: Problems):
    """Marker and attribute arrays have a row per vertex, subsegment or
    triangle; boundary subsegments and their endpoints have nonzero markers."""
    msgs = []
    vm = result.get("vertex_markers")
    sm = result.get("segment_markers")
    if vm is not None:
        vm = np.asarray(vm).reshape(-1)
        if len(vm) != m.N:
            msgs.append(f"vertex_markers has {len(vm)} entries for {m.N} vertices")
            vm = None
    if sm is not None:
        sm = np.asarray(sm).reshape(-1)
        if len(sm) != len(m.S):
            msgs.append(f"segment_markers has {len(sm)} entries for {len(m.S)} segments")
            sm = None
    for name in ("triangle_attributes", "triangle_max_area", "neighbors"):
        x = result.get(name)
        if x is not None and len(np.asarray(x)) != m.M:
            msgs.append(f"{name} has {len(np.asarray(x))} rows for {m.M} triangles")
    probs.add("array lengths", msgs)
    if not len(m.S) or not len(e.key):
        return
    # Boundary subsegments carry nonzero markers, and so do their endpoints
    # (reference 2.12 rules 3-5).
    ok, skey = segment_keys(m)
    bmask = m.topo[e.tri] & (e.twin < 0)
    bkeys = e.ukey[bmask]
    onb = ok & np.isin(skey, bkeys)
    msgs = []
    if sm is not None:
        msgs += [f"boundary segment {i} {m.S[i].tolist()} has marker 0"
                 for i in np.flatnonzero(onb & (sm == 0))]
    if vm is not None:
        ends = np.unique(m.S[onb].ravel())
        msgs += [f"vertex {int(v)} on a boundary segment has marker 0"
                 for v in ends[vm[ends] == 0]]
    probs.add("boundary markers", msgs)
