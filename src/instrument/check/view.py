"""What the checks read: the result's arrays normalised, its directed edges, and
the list of problems they report.

``MeshView`` turns the ``triangle`` package's output dict into arrays and
masks once (indices in range, distinct corners, finite coordinates, exact
orientation), so that every check can skip what an earlier one already
reported instead of failing on it.  ``Problems`` caps the messages per kind
of problem, so that a badly broken mesh gives a readable report.
``join_keys`` pairs up rows with equal keys (vertex ids, edge keys).
"""

from __future__ import annotations

import itertools

import numpy as np

from .exact import orient_xy


#: Largest number of messages reported per kind of problem.
MAX_MESSAGES = 20


class Problems:
    """The problems found so far, as lines of text, at most MAX_MESSAGES per kind."""

    def __init__(self):
        self.lines: list[str] = []

    def add(self, what: str, items, total: int | None = None):
        """Report ``items`` (a list, or an iterable of ``total`` messages of
        which only the first MAX_MESSAGES are formatted)."""
        if total is None:
            items = list(items)
            total = len(items)
        if not total:
            return
        self.lines.extend(itertools.islice(items, MAX_MESSAGES))
        if total > MAX_MESSAGES:
            self.lines.append(f"... and {total - MAX_MESSAGES} more: {what}")


def int_array(x, cols):
    """``x`` as an int64 array; empty input as shape (0, cols) whatever its shape."""
    a = np.asarray(x)
    if a.size == 0:
        return np.zeros((0, cols), dtype=np.int64)
    return a.astype(np.int64, copy=False)


class MeshView:
    """Normalised arrays plus the per-triangle validity masks."""

    def __init__(self, result, probs: Problems):
        self.ok = False
        v = np.asarray(result.get("vertices", np.zeros((0, 2))), dtype=np.float64)
        if v.size == 0:
            v = np.zeros((0, 2))
        if v.ndim != 2 or v.shape[1] != 2:
            probs.add("shape", [f"vertices must have shape (N, 2), got {v.shape}"])
            return
        self.V = v
        self.N = n = len(v)
        t = int_array(result.get("triangles", np.zeros((0, 3))), 3)
        if t.ndim != 2 or t.shape[1] not in (3, 6):
            probs.add("shape", [f"triangles must have shape (M, 3) or (M, 6), got {t.shape}"])
            return
        self.T = t[:, :3]
        self.M = len(self.T)
        s = int_array(result.get("segments", np.zeros((0, 2))), 2)
        if s.ndim != 2 or s.shape[1] != 2:
            probs.add("shape", [f"segments must have shape (S, 2), got {s.shape}"])
            return
        self.S = s
        self.ok = True

        T = self.T
        inrange = ((T >= 0) & (T < n)).all(axis=1)
        self.inrange = inrange
        Tc = np.where(inrange[:, None], T, 0)
        self.Tc = Tc
        distinct = (Tc[:, 0] != Tc[:, 1]) & (Tc[:, 1] != Tc[:, 2]) & (Tc[:, 0] != Tc[:, 2])
        self.topo = inrange & distinct  # usable for edge topology
        finite_v = np.isfinite(v).all(axis=1)
        self.finite = finite_v[Tc].all(axis=1)
        P = v[Tc]  # (M, 3, 2); rows with bad indices hold vertex 0, masked later
        self.P = P
        geo = self.topo & self.finite
        self.orient = np.zeros(self.M, dtype=np.int8)
        idx = np.flatnonzero(geo)
        if idx.size:
            q = P[idx]
            self.orient[idx] = orient_xy(
                q[:, 0, 0], q[:, 0, 1], q[:, 1, 0], q[:, 1, 1], q[:, 2, 0], q[:, 2, 1]
            )
        self.geo = geo
        self.good = geo & (self.orient > 0)


class Edges:
    """Directed edges of the topologically usable triangles."""

    def __init__(self, m: MeshView):
        idx = np.flatnonzero(m.topo)
        t = m.Tc[idx]
        self.tri = np.concatenate([idx, idx, idx])
        self.a = np.concatenate([t[:, 0], t[:, 1], t[:, 2]])
        self.b = np.concatenate([t[:, 1], t[:, 2], t[:, 0]])
        self.apex = np.concatenate([t[:, 2], t[:, 0], t[:, 1]])
        n = np.int64(max(m.N, 1))
        self.n = n
        self.key = self.a * n + self.b
        self.twin_key = self.b * n + self.a
        lo = np.minimum(self.a, self.b)
        hi = np.maximum(self.a, self.b)
        self.ukey = lo * n + hi
        order = np.argsort(self.key, kind="stable")
        self.sorted_key = self.key[order]
        self.order = order
        # Position of the twin directed edge, or -1.
        pos = np.searchsorted(self.sorted_key, self.twin_key)
        pos = np.minimum(pos, max(len(self.key) - 1, 0))
        if len(self.key):
            has = self.sorted_key[pos] == self.twin_key
            self.twin = np.where(has, order[pos], -1)
        else:
            self.twin = np.zeros(0, dtype=np.int64)


def segment_keys(m: MeshView):
    """(valid, key) per subsegment: valid when its indices are in range and
    distinct; key = lo * N + hi, comparable with ``Edges.ukey``."""
    S = m.S
    ok = ((S >= 0) & (S < m.N)).all(axis=1) & (S[:, 0] != S[:, 1])
    lo = np.minimum(S[:, 0], S[:, 1])
    hi = np.maximum(S[:, 0], S[:, 1])
    return ok, lo * np.int64(max(m.N, 1)) + hi


def join_keys(a_obj, a_key, b_obj, b_key):
    """Every (a, b) pair with equal keys (any sortable dtype): a sort and
    two binary searches, so linear in the pairs after the sort."""
    order = np.argsort(b_key, kind="stable")
    bk = b_key[order]
    bo = b_obj[order]
    lo = np.searchsorted(bk, a_key, "left")
    hi = np.searchsorted(bk, a_key, "right")
    cnt = hi - lo
    tot = int(cnt.sum())
    if tot == 0:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    first = np.cumsum(cnt) - cnt
    pos = np.arange(tot) - np.repeat(first, cnt) + np.repeat(lo, cnt)
    return np.repeat(a_obj, cnt), bo[pos]
