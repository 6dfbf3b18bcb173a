"""Matplotlib pictures of meshes and of the work that made them.

``plot(ax, **mesh)``, ``compare(plt, A, B)`` and ``comparev(plt, A, B)`` take
the same arguments as the `triangle` package's functions of those names, so
user code written for ``triangle`` runs unchanged; ``work(ax, result)`` plots
a result's per-insertion trace.

matplotlib is imported inside the functions that need it, so that
``import instrument`` does not import it.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

__all__ = ["compare", "comparev", "plot", "work"]

#: Trace columns tried, in order, as the work of one insertion.
WORK_COLUMNS = ("triangles_created", "work", "created")


def plot(ax, **kw):
    """Draw the keys of a `triangle`-style dict that it knows on the Axes ``ax``:
    ``vertices`` (black dots), ``segments`` (thick red), ``triangles`` (black
    edges), ``holes`` (red crosses), ``edges`` (thin black, plus Voronoi rays
    when ``ray_origins`` and ``ray_directions`` are given), ``regions`` (blue
    stars labelled with their attribute) and ``triangle_attributes`` (magenta
    labels at the centroids).  ``labels=True`` writes vertex numbers and
    ``markers=True`` vertex markers.  The axes are hidden and the aspect is equal.
    """
    ax.set_aspect("equal")
    xy = _xy(kw.get("vertices"))
    if xy is not None:
        _vertices(ax, xy, kw)
        if kw.get("segments") is not None:
            _lines(ax, xy, kw["segments"], color="r", linewidth=3, zorder=0)
        if kw.get("triangles") is not None:
            tris = np.asarray(kw["triangles"], dtype=np.int64)
            if tris.size:
                # second-order triangles (o2) list their corners first
                ax.triplot(xy[:, 0], xy[:, 1], tris.reshape(len(tris), -1)[:, :3], "ko-")
        if kw.get("edges") is not None:
            _lines(ax, xy, kw["edges"], color="k", linewidth=0.5)
            if kw.get("ray_origins") is not None and kw.get("ray_directions") is not None:
                _rays(ax, xy, kw["ray_origins"], kw["ray_directions"])
        if kw.get("triangle_attributes") is not None and kw.get("triangles") is not None:
            _triangle_attributes(ax, xy, kw["triangles"], kw["triangle_attributes"])
    if kw.get("holes") is not None:
        holes = _xy(kw["holes"])
        if holes is not None and len(holes):
            ax.scatter(holes[:, 0], holes[:, 1], marker="x", color="r")
    if kw.get("regions") is not None:
        _regions(ax, kw["regions"])
    ax.get_xaxis().set_visible(False)
    ax.get_yaxis().set_visible(False)


def compare(plt, A, B, figsize=(6, 3)):
    """Draw meshes ``A`` and ``B`` side by side in a new figure with the same
    limits.  ``plt`` is the pyplot module (as for the package) or a Figure."""
    _pair(plt, A, B, figsize, (1, 2), "sharey")


def comparev(plt, A, B, figsize=(3, 6)):
    """Like ``compare``, with ``A`` above ``B``."""
    _pair(plt, A, B, figsize, (2, 1), "sharex")


def work(ax, result, *, key=None):
    """Plot the work of each insertion recorded in ``result.trace`` (one row per
    insertion, from ``triangulate(..., trace=True)``) on the Axes ``ax``.

    The work is the column ``key``, by default the first of ``WORK_COLUMNS``
    the trace has (else its last column); insertions are numbered by a ``step``
    column when there is one, and coloured by a ``kind`` column when there is
    one.  Returns ``ax``.  Raises ``ValueError`` when there is no trace.
    """
    trace = getattr(result, "trace", None)
    cols = _trace_columns(trace)
    if not cols or not len(next(iter(cols.values()))):
        raise ValueError(
            "result has no trace (no per-insertion rows): run "
            "instrument.triangulate(..., trace=True) to record one"
        )
    if key is None:
        key = next((k for k in WORK_COLUMNS if k in cols), list(cols)[-1])
    if key not in cols:
        raise ValueError(f"the trace has no column {key!r}; it has {', '.join(map(str, cols))}")
    y = np.asarray(cols[key], dtype=np.float64)
    x = np.asarray(cols["step"], dtype=np.float64) if "step" in cols else np.arange(len(y), dtype=np.float64)
    kinds = cols.get("kind")
    if kinds is None:
        ax.plot(x, y, ".", markersize=3, color="k")
    else:
        kinds = np.asarray([str(k) for k in kinds])
        for name in dict.fromkeys(kinds):  # first-seen order, stable colours
            sel = kinds == name
            ax.plot(x[sel], y[sel], ".", markersize=3, label=name)
        ax.legend(loc="best", fontsize="small")
    ax.set_xlabel("insertion")
    ax.set_ylabel(str(key))
    ax.set_title(f"{len(y)} insertions, {y.sum():g} {key} in all", fontsize="small")
    return ax


# --------------------------------------------------------------------------
# drawing pieces


def _xy(a):
    if a is None:
        return None
    a = np.asarray(a, dtype=np.float64)
    return a.reshape(-1, 2) if a.size else np.zeros((0, 2))


def _vertices(ax, xy, kw) -> None:
    if len(xy):
        ax.scatter(xy[:, 0], xy[:, 1], color="k")
    if kw.get("labels"):
        for i, (x, y) in enumerate(xy):
            ax.text(x, y, str(i))
    if kw.get("markers") and kw.get("vertex_markers") is not None:
        vm = np.asarray(kw["vertex_markers"]).reshape(len(xy), -1)
        for (x, y), m in zip(xy, vm):
            ax.text(x, y, " ".join(str(int(v)) for v in m))


def _lines(ax, xy, pairs, **style) -> None:
    from matplotlib.collections import LineCollection

    pairs = np.asarray(pairs, dtype=np.int64).reshape(-1, 2)
    pairs = pairs[(pairs >= 0).all(axis=1)]  # -1 ends (rays) have no coordinates
    if len(pairs):
        ax.add_collection(LineCollection(xy[pairs], **style))
        ax.autoscale_view()


def _rays(ax, xy, origins, directions) -> None:
    """Rays long enough to leave the picture, without changing its limits."""
    from matplotlib.collections import LineCollection

    origins = np.asarray(origins, dtype=np.int64).ravel()
    d = np.asarray(directions, dtype=np.float64).reshape(-1, 2)
    if not len(origins):
        return
    lim = ax.axis()
    span = max(lim[1] - lim[0], lim[3] - lim[2], 1e-300)
    length = np.hypot(d[:, 0], d[:, 1])
    scale = np.where(length > 0, 10.0 * span / np.where(length > 0, length, 1.0), 0.0)
    start = xy[origins]
    ends = start + scale[:, None] * d
    ax.add_collection(LineCollection(np.stack([start, ends], axis=1), color="k", linewidth=0.5))
    ax.axis(lim)


def _regions(ax, regions) -> None:
    r = np.asarray(regions, dtype=np.float64)
    if not r.size:
        return
    r = r.reshape(len(r), -1)
    ax.scatter(r[:, 0], r[:, 1], marker="*", color="b")
    if r.shape[1] > 2:
        for x, y, attr in r[:, :3]:
            ax.text(x, y, f" {attr:g}", color="b", va="center")


def _triangle_attributes(ax, xy, triangles, attributes) -> None:
    t = np.asarray(triangles, dtype=np.int64)
    if not t.size:
        return
    t = t.reshape(len(t), -1)[:, :3]
    a = np.asarray(attributes, dtype=np.float64).reshape(len(t), -1)[:, 0]
    c = xy[t].mean(axis=1)
    ax.scatter(c[:, 0], c[:, 1], marker=".", color="m", zorder=1)
    for (x, y), v in zip(c, a):
        ax.text(x, y, f" {v:g}", color="m", zorder=1, va="center")


def _pair(plt, A, B, figsize, grid, share) -> None:
    if hasattr(plt, "add_subplot") and not hasattr(plt, "subplot"):  # a Figure
        fig = plt
        fig.set_size_inches(*figsize)
    else:
        fig = plt.figure(figsize=figsize)
    ax1 = fig.add_subplot(*grid, 1)
    plot(ax1, **A)
    lim = ax1.axis()
    ax2 = fig.add_subplot(*grid, 2, **{share: ax1})
    plot(ax2, **B)
    ax2.axis(lim)
    fig.tight_layout()


# --------------------------------------------------------------------------
# traces


def _trace_columns(trace) -> dict:
    """A trace in any tabular shape as {column name: values}; {} when absent.

    Accepted: a structured or 2-D array, a DataFrame, a mapping of columns, or
    a sequence of rows (mappings, named tuples, dataclasses or plain sequences;
    unnamed columns are called col0, col1, ...)."""
    if trace is None:
        return {}
    if hasattr(trace, "columns") and hasattr(trace, "__getitem__"):  # a DataFrame
        return {str(c): np.asarray(trace[c]) for c in trace.columns}
    if isinstance(trace, np.ndarray):
        if trace.dtype.names:
            return {n: trace[n] for n in trace.dtype.names}
        if not trace.size:
            return {}
        a = trace.reshape(len(trace), -1) if trace.ndim else trace.reshape(1, 1)
        return {f"col{i}": a[:, i] for i in range(a.shape[1])}
    if isinstance(trace, Mapping):
        return {str(k): np.asarray(v) for k, v in trace.items()}
    rows = list(trace)
    if not rows:
        return {}
    first = rows[0]
    if isinstance(first, Mapping):
        return {str(k): np.asarray([r.get(k) for r in rows]) for k in first}
    if hasattr(first, "_fields"):
        return {k: np.asarray([getattr(r, k) for r in rows]) for k in first._fields}
    if hasattr(first, "__dataclass_fields__"):
        return {k: np.asarray([getattr(r, k) for r in rows]) for k in first.__dataclass_fields__}
    table = [list(r) if isinstance(r, (list, tuple, np.ndarray)) else [r] for r in rows]
    width = len(table[0])
    return {f"col{i}": np.asarray([r[i] for r in table]) for i in range(width)}
