"""The `triangle` package's sample-data helpers: ``loads``, ``load``,
``get_data`` and ``show_data``, with the same signatures and return types.

These parse Triangle's text formats from strings into the package's dicts.
They are the one place where the engine reads a file, because the package's
API has them; the full readers, with Triangle's every rule and errors that
name file and line, are ``ruppert_io.read`` (which the engine cannot import).

Sample data.  ``get_data(name)`` looks first in ``instrument/sample_data``,
which holds samples written for ruppert (``square_hole``, ``square_hole.1``,
``two_regions``, ``scatter``), then in the installed `triangle` package's
``data`` directory (``A``, ``dots``, ``face``, ``la``, ``box.1``, ...), read
where the package installed them.  Triangle's samples are not copied into this
package: they belong to Triangle's distribution (Shewchuk's non-commercial
terms) and the `triangle` wheel (LGPL), while ruppert is MIT.  Without the
`triangle` package, ``get_data("A")`` raises FileNotFoundError saying so.

Where the package misreads a file we follow Triangle's reading instead
(the decisions, each checked against the package in the tests):

* A region line ``i x y value`` (one value after x and y) means attribute
  *and* area bound ``value``, as Triangle reads it; the package gives
  ``[x, y, 0, value]``.  Five-field lines ``i x y attribute area`` give
  ``[x, y, attribute, area]`` (the package garbles them).
* An ``.edge`` file without Voronoi rays reads (the package raises
  IndexError); its markers come back as ``edge_markers`` (the package drops
  them).  Rays, as in ``.v.edge`` files, still come back as ``ray_origins``
  (R, 1) and ``ray_directions`` (R, 2), and ``edges`` holds the finite ones.
* ``.neigh`` keeps the package's key ``triangle_neighbors`` (code written for
  the package reads it), and ``instrument.triangulate`` accepts that key as
  input (it ignores it, as it ignores ``neighbors``), so a loaded dict can be
  triangulated again; the package raises KeyError there.  A missing neighbour
  stays -1 in 1-based files (the package shifts it to -2).
* The numbering base comes from the first vertex number of the ``.node`` (or
  ``.poly``) text, 0 or 1, as Triangle decides it; with no vertex text, from
  the first item number of the text itself (the package assumes 0).
* Missing optional fields (attributes, markers) are 0, as in Triangle; a
  missing required field raises ``TriangleError`` naming the text and line
  (the package reads the tokens shifted, or fails with an IndexError).
* ``get_data`` of an unknown name raises FileNotFoundError listing the
  samples (the package returns ``{}``); ``load`` of a name with no file
  returns ``{}``, as the package does.

>>> d = get_data("square_hole")
>>> sorted(d)
['holes', 'segment_markers', 'segments', 'vertex_attributes', 'vertex_markers', 'vertices']
>>> d["vertices"].shape, d["segments"].dtype
((8, 2), dtype('int32'))
>>> loads(node="3 2 0 0\\n1 0 0\\n2 1 0\\n3 0 1\\n")["vertices"].tolist()
[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]
"""

from __future__ import annotations

import importlib.util
import os
from pathlib import Path

import numpy as np

from .errors import TriangleError

__all__ = ["SAMPLE_DIR", "get_data", "load", "loads", "sample_names", "show_data"]

#: ruppert's own samples (package data).
SAMPLE_DIR = Path(__file__).with_name("sample_data")

#: The file kinds ``load`` reads, in the order ``loads`` takes them.
KINDS = ("node", "ele", "poly", "area", "edge", "neigh")


class _Text:
    """The item lines of one text: comments and blank lines dropped, each
    line split into fields, with the line numbers kept for error messages."""

    def __init__(self, kind: str, text: str):
        self.kind = kind
        self.lines = []
        for number, line in enumerate(text.splitlines(), start=1):
            fields = line.split("#", 1)[0].split()
            if fields:
                self.lines.append((number, fields))
        self.at = 0

    def error(self, number: int | None, what: str) -> TriangleError:
        where = f"line {number} of the {self.kind} text" if number else f"the {self.kind} text"
        return TriangleError(f"{where}: {what}")

    def header(self, what: str, defaults: tuple[int, ...], *, required: bool = True) -> tuple[int, ...]:
        """A count line; fields it leaves out take ``defaults``.  At the end of
        the text an optional count is 0."""
        if self.at >= len(self.lines):
            if required:
                raise self.error(None, f"ends before {what}")
            return (0,) + defaults[1:]
        number, fields = self.lines[self.at]
        self.at += 1
        values = list(defaults)
        for i in range(min(len(fields), len(values))):
            values[i] = _integer(self, number, fields[i], what)
        if values[0] < 0:
            raise self.error(number, f"{what} is negative ({values[0]})")
        return tuple(values)

    def base(self, base: list) -> int:
        """The numbering base: the vertex text's, else the item number of the
        next line here if it is 0 or 1, else 1 (Triangle's default)."""
        if base[0] is not None:
            return base[0]
        try:
            first = int(self.lines[self.at][1][0])
        except (IndexError, ValueError):
            return 1
        return first if first in (0, 1) else 1

    def items(self, count: int, what: str, need: int, width: int) -> list[tuple[int, list[str]]]:
        """The next ``count`` item lines as (line number, the fields after the
        item number), each with at least ``need`` fields, cut to ``width``."""
        if self.at + count > len(self.lines):
            raise self.error(None, f"ends after {len(self.lines) - self.at} of its {count} {what} lines")
        out = []
        for number, fields in self.lines[self.at : self.at + count]:
            values = fields[1 : 1 + width]
            if len(values) < need:
                raise self.error(number, f"{what} {fields[0]} has {len(values)} of its {need} numbers")
            out.append((number, values))
        self.at += count
        return out

    def reals(self, rows, width: int, fill: float = 0.0) -> np.ndarray:
        """Rows of real fields, missing ones ``fill``."""
        out = np.full((len(rows), width), fill, dtype=np.float64)
        for i, (number, values) in enumerate(rows):
            for j, v in enumerate(values[:width]):
                try:
                    out[i, j] = float(v)
                except ValueError:
                    raise self.error(number, f"{v!r} is not a number") from None
        return out

    def integers(self, rows, width: int, start: int = 0) -> np.ndarray:
        """Rows of integer fields ``start`` to ``start + width``, missing ones 0."""
        out = np.zeros((len(rows), width), dtype=np.int64)
        for i, (number, values) in enumerate(rows):
            for j, v in enumerate(values[start : start + width]):
                out[i, j] = _integer(self, number, v, "an index or marker")
        return out


def _integer(t: _Text, number: int, field: str, what: str) -> int:
    """An integer field; a real with an integer value (``3.0``) is accepted."""
    try:
        return int(field)
    except ValueError:
        try:
            value = float(field)
        except ValueError:
            raise t.error(number, f"{what} is not a number: {field!r}") from None
        if not value.is_integer():
            raise t.error(number, f"{what} is not an integer: {field!r}") from None
        return int(value)


def _shift(a: np.ndarray, base: int) -> np.ndarray:
    """0-based int32 indices; -1 (none, as in .neigh and rays) stays -1."""
    return np.ascontiguousarray(np.where(a >= 0, a - base, a).astype(np.intc))


def _vertices(t: _Text, data: dict, base: list) -> None:
    """A vertex section (.node, or the first of a .poly); sets the base."""
    n, dim, nattr, nmark = t.header("the vertex count", (0, 2, 0, 0))
    if n == 0:
        return
    if dim != 2:
        raise t.error(t.lines[t.at - 1][0], f"Triangle only works with two-dimensional meshes, not {dim}")
    first = t.lines[t.at][1][0] if t.at < len(t.lines) else ""
    base[0] = int(first) if first in ("0", "1") else 1  # the vertex section read last decides
    rows = t.items(n, "vertex", 2, 2 + nattr + nmark)
    values = t.reals(rows, 2 + nattr + nmark)
    data["vertices"] = np.ascontiguousarray(values[:, :2])
    if nattr > 0:
        data["vertex_attributes"] = np.ascontiguousarray(values[:, 2 : 2 + nattr])
    if nmark > 0:
        data["vertex_markers"] = np.ascontiguousarray(t.integers(rows, 1, 2 + nattr).astype(np.intc))


def loads(node=None, ele=None, poly=None, area=None, edge=None, neigh=None) -> dict:
    """A dict of the `triangle` package's keys from the texts of Triangle's
    files (``.node``, ``.ele``, ``.poly``, ``.area``, ``.edge``, ``.neigh``),
    with 0-based indices, as ``triangle.loads`` returns it.  Empty sections
    give no key.  See the module's text for where it reads differently."""
    data: dict = {}
    base: list = [None]
    if node:
        _vertices(_Text("node", node), data, base)
    if ele:
        t = _Text("ele", ele)
        m, corners, nattr = t.header("the triangle count", (0, 3, 0))
        if corners < 3:
            raise t.error(t.lines[0][0], f"triangles must have at least 3 vertices, not {corners}")
        if m:
            b = t.base(base)
            rows = t.items(m, "triangle", corners, corners + nattr)
            data["triangles"] = _shift(t.integers(rows, corners), b)
            if nattr:
                tail = [(number, values[corners:]) for number, values in rows]
                data["triangle_attributes"] = t.reals(tail, nattr)
    if poly:
        t = _Text("poly", poly)
        _vertices(t, data, base)
        s, smark = t.header("the segment count", (0, 0))
        if s:
            b = t.base(base)
            rows = t.items(s, "segment", 2, 3 if smark else 2)
            ints = t.integers(rows, 3 if smark else 2)
            data["segments"] = _shift(ints[:, :2], b)
            if smark:
                data["segment_markers"] = np.ascontiguousarray(ints[:, 2:3].astype(np.intc))
        (h,) = t.header("the hole count", (0,), required=False)
        if h:
            data["holes"] = t.reals(t.items(h, "hole", 2, 2), 2)
        (r,) = t.header("the region count", (0,), required=False)
        if r:
            rows = t.items(r, "region", 3, 4)
            regions = t.reals(rows, 4)
            # one value after x and y: Triangle takes it as attribute and area bound
            short = np.array([len(values) < 4 for _, values in rows])
            regions[short, 3] = regions[short, 2]
            data["regions"] = regions
    if area:
        t = _Text("area", area)
        (m,) = t.header("the triangle count", (0,))
        if m:
            data["triangle_max_area"] = t.reals(t.items(m, "area bound", 0, 1), 1, fill=-1.0)
    if edge:
        t = _Text("edge", edge)
        e, emark = t.header("the edge count", (0, 0))
        if e:
            b = t.base(base)
            rows = t.items(e, "edge", 2, 4 + bool(emark))
            ends = t.integers([(n, v[:2]) for n, v in rows], 2)
            rays = ends[:, 1] == -1
            if rays.any():  # Voronoi rays: origin, -1, direction
                bad = [n for (n, v), ray in zip(rows, rays) if ray and len(v) < 4]
                if bad:
                    raise t.error(bad[0], "a ray (second endpoint -1) needs a direction dx dy")
                data["ray_origins"] = _shift(ends[rays, :1], b)
                data["ray_directions"] = t.reals([(n, v[2:4]) for (n, v), ray in zip(rows, rays) if ray], 2)
            if (~rays).any():
                data["edges"] = _shift(ends[~rays], b)
                if emark:
                    finite = [(n, v[2:3]) for (n, v), ray in zip(rows, rays) if not ray]
                    data["edge_markers"] = np.ascontiguousarray(t.integers(finite, 1).astype(np.intc))
            if rays.any() or (~rays).any():
                # keep the package's key order: edges first
                data.update({k: data.pop(k) for k in ("ray_origins", "ray_directions") if k in data})
    if neigh:
        t = _Text("neigh", neigh)
        m, k = t.header("the triangle count", (0, 3))
        if m:
            b = t.base(base)
            data["triangle_neighbors"] = _shift(t.integers(t.items(m, "triangle", k, k), k), b)
    return data


def load(directory, name) -> dict:
    """Read whichever of ``name.node``, ``.ele``, ``.poly``, ``.area``,
    ``.edge`` and ``.neigh`` exist in ``directory`` (``{}`` if none does)."""
    texts = {}
    for kind in KINDS:
        path = os.path.join(directory, f"{name}.{kind}")
        if os.path.exists(path):
            with open(path) as f:
                texts[kind] = f.read()
    return loads(**texts)


def _triangle_data_dir() -> Path | None:
    """The installed `triangle` package's ``data`` directory, found without
    importing the package."""
    try:
        spec = importlib.util.find_spec("triangle")
    except (ImportError, ValueError):
        return None
    if spec is None or not spec.submodule_search_locations:
        return None
    path = Path(next(iter(spec.submodule_search_locations))) / "data"
    return path if path.is_dir() else None


def _names(directory: Path | None) -> set[str]:
    if directory is None:
        return set()
    names = set()
    for path in directory.iterdir():
        for kind in KINDS:
            if path.name.endswith(f".{kind}"):
                names.add(path.name[: -len(kind) - 1])
    return names


def sample_names() -> list[str]:
    """The names ``get_data`` knows: ruppert's samples, then the `triangle`
    package's if it is installed."""
    ours = sorted(_names(SAMPLE_DIR))
    return ours + sorted(_names(_triangle_data_dir()) - set(ours))


def get_data(name) -> dict:
    """A sample by name (see the module's text for where samples come from):
    ``get_data("square_hole")``, or ``get_data("A")`` with the `triangle`
    package installed."""
    for directory in (SAMPLE_DIR, _triangle_data_dir()):
        if directory is not None and name in _names(directory):
            return load(directory, name)
    hint = "" if _triangle_data_dir() is not None else (
        "; Triangle's own samples (A, dots, face, la, ...) come with the `triangle` package, which is not installed"
    )
    raise FileNotFoundError(f"no sample named {name!r}: choose from {', '.join(sample_names())}{hint}")


def show_data(name) -> None:
    """Plot a sample with matplotlib and show it, as ``triangle.show_data`` does."""
    import matplotlib.pyplot as plt

    from .plot import plot

    plot(plt.axes(), **get_data(name))
    plt.show()
