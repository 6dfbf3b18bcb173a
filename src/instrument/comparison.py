"""Compare ruppert's engine with Triangle (the `triangle` package) and CGAL Mesh_2.

``compare(tri, "pq30")`` runs one PSLG (the `triangle` package's dict) through

* our engine, once per strategy (``instrument.strategies()`` when it exists,
  else just ``"triangle"``);
* Triangle through the `triangle` package, timed with its quiet switches, plus
  one extra run with ``V`` whose statistics (incircle and orientation tests,
  circumcenter computations) are read from the C-level standard output;
* CGAL's Mesh_2 through the ``cgal`` SWIG bindings, on a constrained Delaunay
  triangulation of the same PSLG (hole points become seeds), with criteria
  converted from the switches: ``q<angle>`` -> shape bound ``b = sin^2(angle)``,
  ``a<area>`` -> edge-length bound ``S = sqrt(4 area / sqrt 3)`` (the side of
  the equilateral triangle of that area).

It returns one ``Row`` per engine (and strategy).  An engine that cannot run
the switches (our engine raises ``NotImplementedError`` for switches it does
not implement yet; CGAL has no ``r``) gets status ``"unsupported"``, one that
fails gets ``"error"``, one that is not installed ``"unavailable"``, and
with a ``timeout`` our engine runs in a forked child that is killed when it
takes longer (``"timeout"``); the comparison goes on either way.

Counts are made comparable: Triangle's printed orientation count includes one
``orient2d`` call per output triangle made by the ``V`` quality statistics
themselves, which our engine's counter (library mode, no statistics) does not
make, so ``Row.orient_tests`` for Triangle is the printed count minus the
number of output triangles; the raw figure stays in ``Row.work``.

The engine never reads files: inputs are dicts, results plain dataclasses.
"""

from __future__ import annotations

import contextlib
import ctypes
import ctypes.util
import importlib
import math
import os
import re
import sys
import tempfile
import time
import types
from collections.abc import Iterable, Mapping
from dataclasses import asdict, dataclass, field

import numpy as np

from .switches import parse

ENGINES = ("ours", "triangle", "cgal")

#: the columns of a row, in table order (``work`` and ``mesh`` are extra)
COLUMNS = (
    "input",
    "switches",
    "engine",
    "strategy",
    "status",
    "vertices",
    "triangles",
    "min_angle",
    "max_angle",
    "area",
    "incircle_tests",
    "orient_tests",
    "circumcenters",
    "triangles_created",
    "wall_s",
    "time_ratio",
    "flags",
    "note",
)

SIZE_TOLERANCE = 0.02  # relative difference in output size that raises a flag
ANGLE_TOLERANCE = 1e-6  # degrees
AREA_TOLERANCE = 1e-9  # relative difference in meshed area that raises a flag


@dataclass
class Row:
    """One engine (and strategy) on one input under one switch string."""

    input: str
    switches: str
    engine: str  # "ours", "triangle" or "cgal"
    strategy: str = ""  # ours only
    status: str = "ok"  # ok | unsupported | error | timeout | unavailable
    vertices: int | None = None
    triangles: int | None = None
    min_angle: float | None = None  # degrees
    max_angle: float | None = None
    area: float | None = None  # total area of the output triangles
    incircle_tests: int | None = None
    orient_tests: int | None = None
    circumcenters: int | None = None
    triangles_created: int | None = None  # ours only (Triangle does not count it)
    wall_s: float | None = None  # best of the timed runs
    time_ratio: float | None = None  # wall_s / Triangle's wall_s
    flags: list[str] = field(default_factory=list)
    note: str = ""
    work: dict | None = None  # ours: every counter; Triangle: the parsed statistics
    mesh: dict | None = field(default=None, repr=False, compare=False)  # kept on request

    @property
    def label(self) -> str:
        return f"ours:{self.strategy}" if self.engine == "ours" else self.engine

    def as_dict(self, *, work: bool = True) -> dict:
        """The row as plain JSON-able values (without the mesh)."""
        d = asdict(self)
        d.pop("mesh")
        if not work:
            d.pop("work")
        return d


# ---------------------------------------------------------------------------------------------
# geometry of an output mesh


def mesh_stats(vertices, triangles) -> tuple[float | None, float | None, float | None]:
    """(smallest angle, largest angle, total area) of a triangle mesh, angles in
    degrees; ``None`` each when there are no triangles."""
    if triangles is None or len(triangles) == 0:
        return None, None, None
    xy = np.asarray(vertices, dtype=np.float64)
    t = np.asarray(triangles)[:, :3]
    p = xy[t]  # (T, 3, 2)
    e = np.roll(p, -1, axis=1) - p  # e[k] = p[k+1] - p[k]
    cross = e[:, 0, 0] * e[:, 1, 1] - e[:, 0, 1] * e[:, 1, 0]
    area = 0.5 * float(np.abs(cross).sum())
    # angle at corner k, between e[k] and -e[k-1]
    a = e
    b = -np.roll(e, 1, axis=1)
    dot = (a * b).sum(axis=2)
    crs = np.abs(a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0])
    ang = np.degrees(np.arctan2(crs, dot))
    return float(ang.min()), float(ang.max()), area


# ---------------------------------------------------------------------------------------------
# our engine


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


_WARMED: set[str] = set()
_AREA = re.compile(r"a[0-9]*\.?[0-9]*(?:[eE][-+]?[0-9]+)?")

_WARM_INPUT = {
    "vertices": [[0, 0], [3, 0], [3, 2], [0, 2], [1, 0.5], [2, 0.5], [2, 1.5], [1, 1.5], [1.5, 1.9]],
    "segments": [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]],
    "holes": [[1.5, 1.0]],
}


def _warm_up(opts: str, strategy: str) -> None:
    """Run our engine once on a tiny input so numba's compilation (or cache
    loading) is not timed."""
    opts = _AREA.sub("", opts)  # the code path is the same; a small area on this box would be slow
    key = f"{opts}\0{strategy}"
    if key in _WARMED:
        return
    _WARMED.add(key)
    import instrument

    with contextlib.suppress(Exception):
        instrument.triangulate(_WARM_INPUT, opts, strategy=strategy)


def run_ours(tri: dict, opts: str, strategy: str = "triangle", *, seed: int = 0, repeat: int = 3):
    """Time our engine: (result, best wall time)."""
    import instrument

    _warm_up(opts, strategy)
    best = math.inf
    out = None
    for _ in range(max(1, repeat)):
        t0 = time.perf_counter()
        out = instrument.triangulate(tri, opts, strategy=strategy, seed=seed)
        best = min(best, time.perf_counter() - t0)
    return out, best


class EngineTimeout(RuntimeError):
    """Our engine did not finish within the time limit (it was killed)."""


def _ours_child(conn, tri, opts, strategy, seed, repeat):
    try:
        out, wall = run_ours(tri, opts, strategy, seed=seed, repeat=repeat)
        conn.send(("ok", dict(out), dict(getattr(out, "work", {}) or {}), wall))
    except NotImplementedError as exc:
        conn.send(("unsupported", _error(exc)))
    except BaseException as exc:  # noqa: BLE001  (reported to the parent)
        conn.send(("error", _error(exc)))
    finally:
        conn.close()


def run_ours_isolated(tri: dict, opts: str, strategy: str = "triangle", *, seed: int = 0, repeat: int = 3,
                      timeout: float = 60.0):
    """``run_ours`` in a forked child that is killed after ``timeout`` seconds
    (numba code cannot be interrupted in-process): (result dict, work, best wall
    time).  Raises ``EngineTimeout``, ``NotImplementedError`` or ``RuntimeError``.
    Without ``fork`` (Windows) it runs in this process, with no limit."""
    import multiprocessing

    try:
        ctx = multiprocessing.get_context("fork")
    except ValueError:  # pragma: no cover - no fork on this platform
        out, wall = run_ours(tri, opts, strategy, seed=seed, repeat=repeat)
        return dict(out), dict(getattr(out, "work", {}) or {}), wall
    _warm_up(opts, strategy)  # here, so that every child inherits the compiled kernels
    recv, send = ctx.Pipe(duplex=False)
    child = ctx.Process(target=_ours_child, args=(send, tri, opts, strategy, seed, repeat), daemon=True)
    child.start()
    send.close()
    try:
        if not recv.poll(timeout):
            child.kill()
            raise EngineTimeout(f"no result within {timeout:g} s (killed)")
        try:
            msg = recv.recv()
        except EOFError:
            child.join()
            raise RuntimeError(f"the engine's process died (exit code {child.exitcode})") from None
    finally:
        recv.close()
        child.join()
    if msg[0] == "unsupported":
        raise NotImplementedError(msg[1])
    if msg[0] == "error":
        raise RuntimeError(msg[1])
    return msg[1], msg[2], msg[3]


# ---------------------------------------------------------------------------------------------
# Triangle (the `triangle` package)

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


def _triangle_input(tri: dict) -> tuple[dict, list[str]]:
    from triangle.tri import translate_inv

    known = {translate_inv[k]: v for k, v in _nonempty(tri).items() if k in translate_inv}
    dropped = sorted(k for k in tri if k not in translate_inv)
    return known, dropped


def triangle_statistics(tri: dict, opts: str) -> tuple[dict, dict[str, int], str]:
    """Run Triangle with ``V`` (and without ``Q``), capturing what it prints
    from C: (output dict, parsed statistics, raw text)."""
    from triangle.tri import translate_frw, triang

    c_in, _ = _triangle_input(tri)
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
    return out, best


# ---------------------------------------------------------------------------------------------
# CGAL Mesh_2


def cgal_criteria(opts: str) -> tuple[float, float, list[str]]:
    """CGAL's ``Delaunay_mesh_size_criteria_2(b, S)`` for Triangle's switches,
    plus notes on what cannot be carried over.

    * ``q<angle>``: CGAL's shape bound B = circumradius / shortest edge
      satisfies sin(min angle) = 1 / (2B), and ``b`` sets B = sqrt(1 / (4b)),
      so ``b = sin^2(angle)`` (0 without ``q``: no shape bound).  CGAL
      guarantees termination up to b = 0.125 (20.7 degrees) only; like
      Triangle beyond its 28.6 degrees, it usually finishes anyway.
    * ``a<area>``: CGAL bounds edge length, not area; ``S`` is the side of the
      equilateral triangle of that area, ``sqrt(4 area / sqrt 3)`` (0 without
      ``a``: no size bound).
    """
    o = parse(opts)
    notes = []
    b = math.sin(math.radians(o.min_angle)) ** 2 if o.q else 0.0
    size = math.sqrt(4.0 * o.max_area / math.sqrt(3.0)) if o.max_area > 0 else 0.0
    if o.var_area:
        notes.append("per-region/per-triangle areas ignored")
    if o.u:
        notes.append("u (triunsuitable) ignored")
    if o.D:
        notes.append("D ignored (CGAL: diametral circles, constrained Delaunay)")
    if o.S >= 0 or o.Y:
        notes.append("Steiner limits (S/Y) ignored")
    return b, size, notes


def _cgal_build(M, Point_2, xy, segs, hull: bool):
    cdt = M.Mesh_2_Constrained_Delaunay_triangulation_2()
    vh = [cdt.insert(Point_2(float(x), float(y))) for x, y in xy]
    if segs is not None:
        for a, b in segs:
            a, b = int(a), int(b)
            if 0 <= a < len(vh) and 0 <= b < len(vh) and a != b:
                cdt.insert_constraint(vh[a], vh[b])
    if hull and cdt.dimension() == 2:
        inf = cdt.infinite_vertex()
        pairs = []
        for f in cdt.all_faces():
            if not cdt.is_infinite(f):
                continue
            i = f.index(inf)
            p, q = f.vertex((i + 1) % 3).point(), f.vertex((i + 2) % 3).point()
            pairs.append((Point_2(p.x(), p.y()), Point_2(q.x(), q.y())))
        for p, q in pairs:
            cdt.insert_constraint(p, q)
    return cdt


def run_cgal(tri: dict, opts: str, *, repeat: int = 3):
    """Mesh with CGAL: (mesh dict with vertices/triangles, best wall time, notes).

    The time covers inserting the points and constraints from Python and the
    meshing, not the read-out.  Without a refinement switch the CDT is only
    marked (``init()``: the domain from the seeds), not refined."""
    from CGAL import CGAL_Mesh_2 as M
    from CGAL.CGAL_Kernel import Point_2

    o = parse(opts)
    if o.r:
        raise NotImplementedError("r (refine a given mesh) has no CGAL counterpart here")
    b, size, notes = cgal_criteria(opts)
    xy = np.asarray(tri["vertices"], dtype=np.float64).reshape(-1, 2)
    segs = tri.get("segments") if o.p else None
    segs = None if segs is None or len(segs) == 0 else np.asarray(segs).reshape(-1, 2)
    hull = not o.p or o.c  # Triangle treats the hull as segments then
    holes = tri.get("holes") if (o.p and not o.O) else None
    holes = [] if holes is None else np.asarray(holes, dtype=np.float64).reshape(-1, 2)
    if o.A:
        notes.append("regional attributes (A) ignored")
    best = math.inf
    cdt = None
    for _ in range(max(1, repeat)):
        t0 = time.perf_counter()
        cdt = _cgal_build(M, Point_2, xy, segs, hull)
        mesher = M.Default_Delaunay_mesher_2(cdt, M.Delaunay_mesh_size_criteria_2(b, size))
        mesher.set_seeds([Point_2(float(x), float(y)) for x, y in holes], False)
        if o.quality:
            mesher.refine_mesh()
        else:
            mesher.init()  # marks the domain only
        best = min(best, time.perf_counter() - t0)
    index: dict[tuple[float, float], int] = {}
    pts = []
    for v in cdt.finite_vertices():
        p = v.point()
        index[(p.x(), p.y())] = len(pts)
        pts.append((p.x(), p.y()))
    tris = []
    if cdt.dimension() == 2:
        for f in cdt.finite_faces():
            if f.is_in_domain():
                tris.append([index[(f.vertex(i).point().x(), f.vertex(i).point().y())] for i in range(3)])
    segs = []
    if cdt.dimension() == 2:
        for f, i in cdt.finite_edges():
            if cdt.is_constrained((f, i)):
                p, q = f.vertex((i + 1) % 3).point(), f.vertex((i + 2) % 3).point()
                segs.append([index[(p.x(), p.y())], index[(q.x(), q.y())]])
    mesh = {
        "vertices": np.array(pts, dtype=np.float64).reshape(-1, 2),
        "triangles": np.array(tris, dtype=np.int32).reshape(-1, 3),
        "segments": np.array(segs, dtype=np.int32).reshape(-1, 2),
    }
    return mesh, best, notes


# ---------------------------------------------------------------------------------------------
# the comparison


def _fill_mesh(row: Row, out: Mapping, keep: bool) -> None:
    verts = out.get("vertices")
    tris = out.get("triangles")
    row.vertices = 0 if verts is None else len(verts)
    row.triangles = 0 if tris is None else len(tris)
    row.min_angle, row.max_angle, row.area = mesh_stats(verts, tris)
    if row.area is None:
        row.area = 0.0
    if keep:
        row.mesh = {
            k: np.asarray(out[k]) for k in ("vertices", "triangles", "segments") if out.get(k) is not None
        }


def _fill_work(row: Row, work: Mapping) -> None:
    """The counters a row shows (Triangle's statistics have no triangles created)."""
    row.work = dict(work)
    row.incircle_tests = work.get("incircle_tests")
    row.orient_tests = work.get("orient_tests")
    row.circumcenters = work.get("circumcenters")
    row.triangles_created = work.get("triangles_created")


def _error(exc: BaseException) -> str:
    text = str(exc).strip().splitlines()
    return f"{type(exc).__name__}: {text[0] if text else ''}".rstrip(": ")


def has_cgal() -> bool:
    """Are CGAL's Python bindings (the ``cgal`` package) installed?"""
    import importlib.util

    return importlib.util.find_spec("CGAL") is not None


def _importable(row: Row, module: str) -> bool:
    """Can ``module`` be imported?  If not, ``row`` says why."""
    try:
        importlib.import_module(module)
    except ImportError as exc:
        row.status, row.note = "unavailable", _error(exc)
        return False
    return True


def compare(
    tri: dict,
    opts: str = "p",
    *,
    name: str = "input",
    strategies: Iterable[str] | None = None,
    engines: Iterable[str] = ENGINES,
    repeat: int = 3,
    seed: int = 0,
    keep_meshes: bool = False,
    timeout: float | None = None,
) -> list[Row]:
    """Run ``tri`` under the switch string ``opts`` through the chosen engines.

    ``strategies``: our engine's strategies to run; ``None`` means all of
    ``available_strategies()`` when the switches refine (``q``, ``a``, ``u``,
    ``D``, ``r``), and only ``"triangle"`` otherwise (the strategy only orders
    refinement, so the runs would be identical).  ``repeat``: timed runs per
    engine (the best counts).  ``keep_meshes``: store each output's vertices,
    triangles and segments in ``Row.mesh`` (for plots).  ``timeout``: run each
    of our engine's runs in a forked child killed after that many seconds
    (status ``"timeout"``); ``None`` runs them in this process.
    """
    engines = tuple(engines)
    unknown = set(engines) - set(ENGINES)
    if unknown:
        raise ValueError(f"unknown engine(s) {sorted(unknown)}; choose from {ENGINES}")
    o = parse(opts)
    refines = o.quality or o.r
    if strategies is None:
        strategies = available_strategies() if refines else ["triangle"]
    strategies = list(strategies)
    rows: list[Row] = []

    tri_row = None
    if "triangle" in engines:
        tri_row = Row(name, opts, "triangle")
        if _importable(tri_row, "triangle"):
            try:
                out, tri_row.wall_s = run_triangle(tri, opts, repeat=repeat)
                _fill_mesh(tri_row, out, keep_meshes)
                _, stats, _ = triangle_statistics(tri, opts)
                _fill_work(tri_row, stats)
                if "incircle_tests" not in stats:
                    tri_row.note = "statistics not captured"
                dropped = _triangle_input(tri)[1]
                if dropped:
                    tri_row.note = (tri_row.note + "; " if tri_row.note else "") + f"keys dropped: {dropped}"
            except Exception as exc:  # noqa: BLE001  (Triangle's RuntimeError, KeyError, ...: a row, not a crash)
                tri_row.status, tri_row.note = "error", _error(exc)
        rows.append(tri_row)

    if "ours" in engines:
        for strategy in strategies:
            row = Row(name, opts, "ours", strategy=strategy)
            try:
                if timeout is None:
                    out, row.wall_s = run_ours(tri, opts, strategy, seed=seed, repeat=repeat)
                    work = dict(getattr(out, "work", {}) or {})
                else:
                    out, work, row.wall_s = run_ours_isolated(
                        tri, opts, strategy, seed=seed, repeat=repeat, timeout=timeout
                    )
            except NotImplementedError as exc:
                row.status, row.note = "unsupported", _error(exc)
            except EngineTimeout as exc:
                row.status, row.note = "timeout", str(exc)
            except Exception as exc:  # noqa: BLE001  (any failure is reported in the row)
                row.status, row.note = "error", _error(exc)
            else:
                _fill_mesh(row, out, keep_meshes)
                _fill_work(row, work)
            rows.append(row)

    if "cgal" in engines:
        row = Row(name, opts, "cgal")
        if _importable(row, "CGAL.CGAL_Mesh_2"):
            try:
                mesh, row.wall_s, notes = run_cgal(tri, opts, repeat=repeat)
            except NotImplementedError as exc:
                row.status, row.note = "unsupported", _error(exc)
            except Exception as exc:  # noqa: BLE001  (any failure is reported in the row)
                row.status, row.note = "error", _error(exc)
            else:
                _fill_mesh(row, mesh, keep_meshes)
                row.note = "; ".join(notes)
        rows.append(row)

    base = tri_row.wall_s if tri_row is not None and tri_row.status == "ok" else None
    for row in rows:
        if base and row.wall_s is not None:
            row.time_ratio = row.wall_s / base
    flag_rows(rows, opts)
    return rows


def flag_rows(rows: list[Row], opts: str) -> None:
    """Set ``flags`` on our engine's rows: ``size`` (vertices or triangles differ
    from Triangle's by more than 2 %), ``area`` (meshed area differs), ``angle``
    (a ``q`` bound is not met, unless Triangle's own smallest angle misses it
    too, as happens next to small input angles), ``error``, ``timeout``."""
    o = parse(opts)
    ref = next((r for r in rows if r.engine == "triangle" and r.status == "ok"), None)
    for row in rows:
        if row.engine != "ours":
            continue
        if row.status in ("error", "timeout"):
            row.flags.append(row.status)
        if row.status != "ok":
            continue
        if ref is not None:
            for attr in ("vertices", "triangles"):
                mine, theirs = getattr(row, attr), getattr(ref, attr)
                if abs(mine - theirs) > SIZE_TOLERANCE * theirs:
                    row.flags.append("size")
                    break
            if abs(row.area - ref.area) > AREA_TOLERANCE * max(abs(ref.area), 1e-300):
                row.flags.append("area")
        if o.q and row.min_angle is not None and row.min_angle < o.min_angle - ANGLE_TOLERANCE:
            ref_ok = ref is not None and ref.min_angle is not None and ref.min_angle < o.min_angle - ANGLE_TOLERANCE
            if not ref_ok:
                row.flags.append("angle")


# ---------------------------------------------------------------------------------------------
