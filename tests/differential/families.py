"""Hypothesis strategies: input families crossed with Triangle switch strings.

Every family draws its geometry in about the unit square from integers and
floats that Hypothesis can shrink (dyadic grid coordinates shrink towards 0,
counts towards their minimum), then a ``scale`` (unit, exact powers of two
down to 2^-1000 and up to 2^1000, inexact powers of ten, or both magnitudes
in one input) is applied to vertices, holes and regions alike.  ``cases()``
pairs an input with a switch string valid for its kind: a point set, a PSLG
(``p``), or a mesh for ``r`` that Triangle makes first (``Case.premesh``).

Area values in switches are fractions of the input's bounding-box area,
written in plain decimals (Triangle reads no exponent), so meshes stay small.
"""

from __future__ import annotations

import math
from decimal import Decimal

import numpy as np
from hypothesis import strategies as st

from .cases import Case

GRID_BITS = 20
GRID = 1 << GRID_BITS

#: families whose input is a point set (no segments)
POINT_FAMILIES = ("points-random", "points-lattice", "points-cocircular", "points-duplicates", "points-collinear")
#: families whose input is a PSLG
PSLG_FAMILIES = (
    "polygon-holes",
    "star",
    "sliver",
    "near-collinear-chain",
    "regions",
    "crossing-segments",
    "concurrent-segments",
    "duplicate-points",
    "hole-points-off",
)
FAMILIES = POINT_FAMILIES + PSLG_FAMILIES + ("mesh",)

# ---------------------------------------------------------------- coordinates

grid_unit = st.integers(0, GRID).map(lambda i: i / GRID)
float_unit = st.floats(0.0, 1.0, allow_nan=False, allow_infinity=False, allow_subnormal=False)
unit = st.one_of(grid_unit, float_unit)


def _xy(draw, n_min, n_max, coord=unit):
    n = draw(st.integers(n_min, n_max))
    return [(draw(coord), draw(coord)) for _ in range(n)]


def _star_shape(draw, centre, r_min, r_max, n_min=3, n_max=16):
    """A simple (star-shaped around ``centre``) polygon with concavities."""
    n = draw(st.integers(n_min, n_max))
    # distinct sorted angles: n slots of a circle, each jittered inside its slot
    jit = [draw(st.integers(0, 7)) / 8.0 for _ in range(n)]
    radii = [r_min + (r_max - r_min) * draw(st.integers(0, 16)) / 16.0 for _ in range(n)]
    pts = []
    for k in range(n):
        a = 2.0 * math.pi * (k + 0.1 + 0.8 * jit[k]) / n
        pts.append((centre[0] + radii[k] * math.cos(a), centre[1] + radii[k] * math.sin(a)))
    return pts


def _cycle(first, n):
    return [(first + i, first + (i + 1) % n) for i in range(n)]


def _markers(draw, n):
    """Markers: mostly none; otherwise small integers, zero included."""
    if draw(st.booleans()):
        return None
    return [draw(st.integers(0, 3)) for _ in range(n)]


# ---------------------------------------------------------------- families


@st.composite
def points_random(draw):
    return {"vertices": _xy(draw, 3, 40)}


@st.composite
def points_lattice(draw):
    nx, ny = draw(st.integers(2, 7)), draw(st.integers(2, 7))
    step = draw(st.sampled_from([1.0, 0.5, 0.1, 1.0 / 3.0]))
    pts = [(i * step, j * step) for i in range(nx) for j in range(ny)]
    keep = draw(st.lists(st.booleans(), min_size=len(pts), max_size=len(pts)))
    if sum(keep) >= 3 and draw(st.booleans()):
        pts = [p for p, k in zip(pts, keep) if k]
    return {"vertices": pts}


@st.composite
def points_cocircular(draw):
    n = draw(st.integers(3, 24))
    pts = [(0.5 + 0.5 * math.cos(2 * math.pi * k / n), 0.5 + 0.5 * math.sin(2 * math.pi * k / n)) for k in range(n)]
    if draw(st.booleans()):
        pts.append((0.5, 0.5))
    return {"vertices": pts}


@st.composite
def points_duplicates(draw):
    pts = _xy(draw, 3, 20)
    extra = draw(st.lists(st.integers(0, len(pts) - 1), min_size=1, max_size=8))
    return {"vertices": pts + [pts[i] for i in extra]}


@st.composite
def points_collinear(draw):
    n = draw(st.integers(3, 20))
    slope = draw(st.sampled_from([0.0, 1.0, 2.0, 0.5, 0.3, -1.0]))
    ts = [draw(grid_unit) for _ in range(n)]
    pts = [(t, slope * t + 0.25) for t in ts]
    pts += _xy(draw, 0, 2)  # none (all collinear) or a few off the line
    return {"vertices": pts}


@st.composite
def polygon_holes(draw):
    r_out = draw(st.sampled_from([0.3, 0.4, 0.5]))
    outer = _star_shape(draw, (0.5, 0.5), r_out * 0.6, r_out)
    pts, segs, holes = list(outer), _cycle(0, len(outer)), []
    nh = draw(st.integers(0, 3))
    r_in = r_out * 0.6
    for h in range(nh):
        a = 2 * math.pi * h / max(nh, 1)
        c = (0.5 + 0.55 * r_in * math.cos(a), 0.5 + 0.55 * r_in * math.sin(a)) if nh > 1 else (0.5, 0.5)
        hole = _star_shape(draw, c, 0.1 * r_in, 0.3 * r_in, 3, 8)
        segs += _cycle(len(pts), len(hole))
        pts += hole
        holes.append(c)
    tri = {"vertices": pts, "segments": segs}
    if holes:
        tri["holes"] = holes
    sm = _markers(draw, len(segs))
    if sm is not None:
        tri["segment_markers"] = sm
    vm = _markers(draw, len(pts))
    if vm is not None:
        tri["vertex_markers"] = vm
    return tri


@st.composite
def star(draw):
    n = draw(st.integers(5, 21))
    k = draw(st.integers(1, n // 2))
    pts = [(0.5 + 0.5 * math.cos(2 * math.pi * i / n), 0.5 + 0.5 * math.sin(2 * math.pi * i / n)) for i in range(n)]
    return {"vertices": pts, "segments": [(i, (i + k) % n) for i in range(n)]}


@st.composite
def sliver(draw):
    eps = 10.0 ** -draw(st.integers(1, 15)) * draw(st.sampled_from([1.0, 3.0, 7.0]))
    x = draw(grid_unit)
    kind = draw(st.sampled_from(["sliver", "needle", "quad"]))
    if kind == "sliver":
        pts = [(0.0, 0.0), (1.0, 0.0), (x, eps)]
    elif kind == "needle":
        pts = [(0.0, 0.0), (1.0, eps * x), (1.0, -eps)]
    else:
        pts = [(0.0, 0.0), (1.0, 0.0), (1.0 + eps, eps), (eps, eps)]
    return {"vertices": pts, "segments": _cycle(0, len(pts))}


@st.composite
def near_collinear_chain(draw):
    n = draw(st.integers(3, 12))
    slope = draw(st.sampled_from([0.3, 0.1, 1.0 / 3.0, 0.7, 2.0, 0.0]))
    c = draw(st.sampled_from([0.1, 0.2, 0.0]))
    xs = sorted({draw(st.integers(1, 64)) / 64.0 for _ in range(n)})
    if len(xs) < 2:
        xs = [0.25, 0.75]
    # within ~1e-15 of the line: rounding of slope * x + c, plus a few ulps
    pts = [(x, slope * x + c + draw(st.integers(-8, 8)) * 2.0**-52) for x in xs]
    segs = [(i, i + 1) for i in range(len(pts) - 1)]
    if draw(st.booleans()):  # inside a box, so the chain splits a domain
        b = len(pts)
        pts += [(-0.25, -0.5), (1.25, -0.5), (1.25, 3.0), (-0.25, 3.0)]
        segs += _cycle(b, 4)
    return {"vertices": pts, "segments": segs}


@st.composite
def regions(draw):
    nx, ny = draw(st.integers(1, 3)), draw(st.integers(1, 3))
    pts = [(i / nx, j / ny) for i in range(nx + 1) for j in range(ny + 1)]
    idx = {(i, j): i * (ny + 1) + j for i in range(nx + 1) for j in range(ny + 1)}
    segs = []
    for i in range(nx + 1):
        for j in range(ny):
            if i in (0, nx) or draw(st.booleans()):
                segs.append((idx[i, j], idx[i, j + 1]))
    for j in range(ny + 1):
        for i in range(nx):
            if j in (0, ny) or draw(st.booleans()):
                segs.append((idx[i, j], idx[i + 1, j]))
    rows = []
    for i in range(nx):
        for j in range(ny):
            if draw(st.integers(0, 4)) == 0:
                continue
            fx = (1 + draw(st.integers(0, 6))) / 8.0
            fy = (1 + draw(st.integers(0, 6))) / 8.0
            attr = float(draw(st.integers(-3, 9)))
            area = draw(st.sampled_from([0.0, -1.0, 0.5, 0.05, 0.01, 0.003])) / (nx * ny)
            rows.append(((i + fx) / nx, (j + fy) / ny, attr, area))
    if not rows:
        rows = [(0.5 / nx, 0.5 / ny, 1.0, 0.01)]
    if draw(st.integers(0, 5)) == 0:  # a region point outside the domain
        rows.append((1.5, 0.5, 5.0, 0.001))
    tri = {"vertices": pts, "segments": segs, "regions": rows}
    if draw(st.integers(0, 3)) == 0:  # and a hole in one cell
        tri["holes"] = [(0.5 / nx + 1.0 / (16 * nx), 0.5 / ny + 1.0 / (16 * ny))]
    return tri


@st.composite
def crossing_segments(draw):
    pts = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    segs = _cycle(0, 4) if draw(st.booleans()) else []
    for _ in range(draw(st.integers(1, 8))):
        kind = draw(st.sampled_from(["random", "overlap", "through-vertex"]))
        b = len(pts)
        if kind == "random":
            pts += [(draw(unit), draw(unit)), (draw(unit), draw(unit))]
            segs.append((b, b + 1))
        elif kind == "overlap":  # collinear pieces of one line, overlapping
            y = draw(grid_unit)
            t = sorted(draw(grid_unit) for _ in range(4))
            pts += [(t[0], y), (t[2], y), (t[1], y), (t[3], y)]
            segs += [(b, b + 1), (b + 2, b + 3)]
        else:  # a segment through an existing vertex
            v = draw(st.integers(0, b - 1))
            d = (draw(grid_unit) - 0.5, draw(grid_unit) - 0.5)
            pts += [(pts[v][0] - d[0], pts[v][1] - d[1]), (pts[v][0] + d[0], pts[v][1] + d[1])]
            segs.append((b, b + 1))
    return {"vertices": pts, "segments": segs}


def _rounded_crossing(p, q, r, t):
    """Where segments p q and r t cross, computed in doubles as a user's
    program would (None if they are parallel): the point lies within rounding
    of both lines, on either side of each."""
    d1 = (q[0] - p[0], q[1] - p[1])
    d2 = (t[0] - r[0], t[1] - r[1])
    den = d1[0] * d2[1] - d1[1] * d2[0]
    if den == 0.0:
        return None
    a = ((r[0] - p[0]) * d2[1] - (r[1] - p[1]) * d2[0]) / den
    return (p[0] + a * d1[0], p[1] + a * d1[1])


@st.composite
def concurrent_segments(draw):
    """Segments that meet another two where those cross: ending at, or
    passing through, their crossing computed in doubles (a drawing whose
    program joined lines at their computed intersection), or another
    segment's end, and moved from it by a few units in the last place.  The three are concurrent within
    rounding, so the crossing Triangle makes lies an ulp or two from the
    third segment's end or line (campaign cases of stop 30 and 31: a
    TriangleError where Triangle meshes)."""
    pts = [(draw(unit), draw(unit)) for _ in range(4)]
    segs = [(0, 1), (2, 3)]
    if draw(st.booleans()):
        pts += [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
        segs += _cycle(4, 4)
    for _ in range(draw(st.integers(1, 3))):
        if draw(st.integers(0, 2)) == 0:  # beside an end: the point is an existing segment's end
            x = pts[draw(st.sampled_from(segs))[draw(st.integers(0, 1))]]
        else:
            i, j = draw(st.sampled_from([(a, b) for a in range(len(segs)) for b in range(a + 1, len(segs))]))
            x = _rounded_crossing(pts[segs[i][0]], pts[segs[i][1]], pts[segs[j][0]], pts[segs[j][1]])
        if x is None or not all(math.isfinite(c) and abs(c) < 4.0 for c in x):
            continue
        k = draw(st.integers(-2, 2))
        x = (x[0] + k * math.ulp(x[0]), x[1] + draw(st.integers(-2, 2)) * math.ulp(x[1]))
        far = (draw(unit), draw(unit))
        b = len(pts)
        if draw(st.booleans()):  # ending there
            pts += [x, far]
        else:  # passing through, on to the mirror of ``far``
            pts += [far, (2.0 * x[0] - far[0], 2.0 * x[1] - far[1])]
        segs.append((b, b + 1))
    return {"vertices": pts, "segments": segs}


@st.composite
def duplicate_points(draw):
    base = draw(polygon_holes())
    pts, segs = list(base["vertices"]), [tuple(s) for s in base["segments"]]
    n = len(pts)
    for _ in range(draw(st.integers(1, 5))):
        i = draw(st.integers(0, n - 1))
        pts.append(pts[i])
        if draw(st.booleans()):  # a segment that uses the copy
            j = draw(st.integers(0, n - 1))
            segs.append((len(pts) - 1, j))
    out = {k: v for k, v in base.items() if k not in ("vertex_markers", "segment_markers")}
    out.update(vertices=pts, segments=segs)
    return out


@st.composite
def hole_points_off(draw):
    base = draw(polygon_holes())
    pts = base["vertices"]
    holes = list(base.get("holes", []))
    for _ in range(draw(st.integers(1, 3))):
        kind = draw(st.sampled_from(["on-segment", "on-vertex", "outside"]))
        if kind == "on-segment":
            a, b = base["segments"][draw(st.integers(0, len(base["segments"]) - 1))]
            t = draw(st.sampled_from([0.5, 0.25, 0.125]))
            holes.append((pts[a][0] + t * (pts[b][0] - pts[a][0]), pts[a][1] + t * (pts[b][1] - pts[a][1])))
        elif kind == "on-vertex":
            holes.append(pts[draw(st.integers(0, len(pts) - 1))])
        else:
            holes.append((draw(st.sampled_from([-1.0, 2.0, 0.5])), draw(st.sampled_from([-1.0, 2.0]))))
    out = dict(base)
    out["holes"] = holes
    return out


@st.composite
def holes_at_two_vertices(draw):
    """polygon-holes' polygons (without their own hole points, now and then)
    with two hole points exactly at two distinct input vertices; one of them,
    one time in three, at the least (x, y) vertex, where ours' start edge for
    locating them begins (located.py).  Not among ``FAMILIES`` (it would
    change every seed's draws): ``test_holes_at_vertices`` draws it."""
    base = draw(polygon_holes())
    pts = base["vertices"]
    n = len(pts)
    first = min(range(n), key=lambda k: pts[k]) if draw(st.integers(0, 2)) == 0 else draw(st.integers(0, n - 1))
    second = draw(st.integers(0, n - 2))
    second += second >= first
    holes = list(base.get("holes", [])) if draw(st.booleans()) else []
    picks = [pts[first], pts[second]]
    holes += picks if draw(st.booleans()) else picks[::-1]
    out = dict(base)
    out["holes"] = holes
    return out


_GENERATORS = {
    "points-random": points_random,
    "points-lattice": points_lattice,
    "points-cocircular": points_cocircular,
    "points-duplicates": points_duplicates,
    "points-collinear": points_collinear,
    "polygon-holes": polygon_holes,
    "star": star,
    "sliver": sliver,
    "near-collinear-chain": near_collinear_chain,
    "regions": regions,
    "crossing-segments": crossing_segments,
    "concurrent-segments": concurrent_segments,
    "duplicate-points": duplicate_points,
    "hole-points-off": hole_points_off,
    "holes-at-two-vertices": holes_at_two_vertices,
}

# ---------------------------------------------------------------- scale


@st.composite
def scale(draw):
    """(label, factor, tiny): the factor applied to every coordinate and, for
    "mixed", tiny points to add near the origin."""
    kind = draw(st.sampled_from(["unit"] * 6 + ["pow2"] * 2 + ["pow10"] * 2 + ["mixed"]))
    if kind == "unit":
        return "unit", 1.0, 0
    if kind == "pow2":
        k = draw(st.one_of(st.integers(-1000, 1000), st.sampled_from([-269, 512, -512, 600, -600, 1000, -1000])))
        return f"2^{k}", math.ldexp(1.0, k), 0
    if kind == "pow10":
        k = draw(st.sampled_from([-300, -200, -100, -30, -10, 10, 30, 100, 200, 300]))
        return f"1e{k}", 10.0**k, 0
    return "mixed", 1e300, draw(st.integers(1, 4))


def _apply_scale(draw, tri: dict, label: str, factor: float, tiny: int) -> dict:
    out = dict(tri)
    for key in ("vertices", "holes", "regions"):
        if key in out:
            a = np.array(out[key], dtype=np.float64)
            a[:, :2] *= factor
            if key == "regions":  # areas scale with the square of the factor
                with np.errstate(over="ignore", under="ignore"):
                    a[:, 3] = np.where(a[:, 3] > 0, a[:, 3] * factor * factor, a[:, 3])
                if not np.isfinite(a[:, 3]).all():
                    a[:, 3] = 0.0
            out[key] = a
    if tiny:  # both magnitudes in one input: points ~1e-300 next to ~1e300
        extra = np.array([(draw(grid_unit) * 1e-300, draw(grid_unit) * 1e-300) for _ in range(tiny)])
        out["vertices"] = np.vstack([out["vertices"], extra])
        if "vertex_markers" in out:
            out["vertex_markers"] = list(out["vertex_markers"]) + [0] * tiny
    return out


def _arrays(tri: dict) -> dict:
    out = {}
    for k, v in tri.items():
        if k in ("segments", "segment_markers", "vertex_markers"):
            out[k] = np.array(v, dtype=np.int32).reshape(-1, 2 if k == "segments" else 1)
        else:
            out[k] = np.array(v, dtype=np.float64)
    return out


# ---------------------------------------------------------------- switches


def bbox_area(tri: dict) -> float:
    v = np.asarray(tri["vertices"], dtype=np.float64)
    w = float(v[:, 0].max() - v[:, 0].min())
    h = float(v[:, 1].max() - v[:, 1].min())
    return w * h if w > 0 and h > 0 else w * w + h * h


def decimal(x: float) -> str:
    """``x`` in plain decimal digits (no exponent): what Triangle can read."""
    s = format(Decimal(repr(x)), "f")
    return s


def area_value(draw, tri: dict) -> str | None:
    """An area bound, a fraction of the bounding-box area, as switch digits,
    or None when that area is not a normal double (extreme scales)."""
    box = bbox_area(tri)
    frac = draw(st.sampled_from([0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001]))
    a = box * frac
    if not (1e-280 < a < 1e280):
        return None
    return decimal(float(f"{a:.3g}"))


def _moderate(tri: dict) -> bool:
    v = np.abs(np.asarray(tri["vertices"], dtype=np.float64))
    return bool(v.max() <= 1e3 and v.max() >= 1e-3)


@st.composite
def switches(draw, tri: dict, kind: str, *, has_areas: bool = False) -> str:
    """A switch string valid for ``kind`` ("points", "pslg", "mesh")."""
    tokens = []
    if kind == "pslg":
        tokens.append("p")
    elif kind == "points" and draw(st.integers(0, 4)) == 0:
        tokens.append("p")  # a PSLG without segments
    elif kind == "mesh":
        tokens.append("r")
        if "segments" in tri and draw(st.booleans()):
            tokens.append("p")
    refine = draw(st.sampled_from(["none", "none", "q", "q", "qa", "a", "D", "u", "bare-a"]))
    if refine == "u" and not _moderate(tri):
        refine = "q"
    if refine == "bare-a" and not has_areas:
        refine = "a"
    if refine in ("q", "qa"):
        angle = draw(st.sampled_from(["", "0", "5", "10", "20", "20.7", "25", "28.6", "30", "32.5", "34"]))
        tokens.append("q" + angle)
    if refine in ("a", "qa"):
        a = area_value(draw, tri)
        if a is not None:
            tokens.append("a" + a)
        elif refine == "a":
            tokens.append("q")
    if refine == "D":
        tokens.append("D")
        if draw(st.booleans()):
            tokens.append("q")
    if refine == "u":
        tokens.append("u")
    if refine == "bare-a":
        tokens.append("a")
        if draw(st.booleans()):
            tokens.append("q")
        if draw(st.booleans()) and (a := area_value(draw, tri)) is not None:
            tokens.append("a" + a)
    refining = refine != "none"
    if kind == "pslg" and "regions" in tri and draw(st.booleans()):
        tokens.append("A")
    if kind != "mesh" and draw(st.integers(0, 4)) == 0:
        tokens.append("c")
    if refining and draw(st.integers(0, 6)) == 0:
        tokens.append(draw(st.sampled_from(["Y", "YY"])))
    if refining and draw(st.integers(0, 8)) == 0:
        tokens.append("S" + str(draw(st.integers(0, 40))))
    for letter, weight in (("o2", 12), ("e", 4), ("n", 4), ("v", 8), ("j", 4), ("z", 4), ("i", 6), ("l", 6)):
        if draw(st.integers(0, weight - 1)) == 0:
            tokens.append(letter)
    tokens = draw(st.permutations(tokens)) if draw(st.booleans()) else tokens
    return "".join(tokens) + "Q"


# ---------------------------------------------------------------- cases


@st.composite
def cases(draw, families=FAMILIES) -> Case:
    family = draw(st.sampled_from(families))
    if family == "mesh":
        return draw(mesh_cases())
    tri = draw(_GENERATORS[family]())
    label, factor, tiny = draw(scale())
    tri = _arrays(_apply_scale(draw, tri, label, factor, tiny))
    kind = "points" if family in POINT_FAMILIES else "pslg"
    has_areas = "regions" in tri and bool((tri["regions"][:, 3] > 0).any())
    sw = draw(switches(tri, kind, has_areas=has_areas))
    return Case(family=family, switches=sw, input=tri, meta={"scale": label})


@st.composite
def mesh_cases(draw) -> Case:
    """A PSLG that Triangle meshes first (``premesh``), with per-triangle area
    bounds, to be refined with ``r``."""
    base = draw(st.sampled_from(["polygon-holes", "regions", "crossing-segments", "star"]))
    tri = _arrays(draw(_GENERATORS[base]()))
    label, factor, tiny = draw(st.sampled_from([("unit", 1.0, 0), ("2^-40", 2.0**-40, 0), ("1e10", 1e10, 0)]))
    tri = _arrays(_apply_scale(draw, tri, label, factor, tiny))
    premesh = draw(st.sampled_from(["p", "pq", "pq30", "pq20a" + (area_value(draw, tri) or "")]))
    factors = tuple(draw(st.lists(st.sampled_from([-1.0, 0.0, 0.5, 0.1, 0.02, 0.005]), min_size=1, max_size=5)))
    sw = draw(switches(tri, "mesh", has_areas=True))
    return Case(family="mesh", switches=sw, input=tri, premesh=premesh + "Q", area_factors=factors,
                meta={"scale": label, "base": base})


#: switch strings for ``hole_pair_cases``: each triangulation method, the hull
#: closed by ``c``, and refinement after carving
HOLE_PAIR_SWITCHES = ("pQ", "pQ", "plQ", "piQ", "pcQ", "pzjQ", "pq30Q", "pDQ", "pneo2Q")


@st.composite
def hole_pair_cases(draw) -> Case:
    """``holes_at_two_vertices`` at scale 1 under one of ``HOLE_PAIR_SWITCHES``."""
    tri = _arrays(draw(holes_at_two_vertices()))
    return Case(family="holes-at-two-vertices", switches=draw(st.sampled_from(HOLE_PAIR_SWITCHES)), input=tri,
                meta={"scale": "unit"})
