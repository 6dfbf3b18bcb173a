"""One timed call of an engine on an in-process workload, through the study's runners.

``ours``: ``instrument.triangulate`` (``instrument.study.ours_engine``);
``triangle``: the `triangle` package as its users call it
(``instrument.study.triangle_engine``); ``cgal``: CGAL's counterpart
(``instrument.study.cgal_engine``): for a point set without switches,
``Delaunay_triangulation_2`` with one bulk insert, else Mesh_2 as the study
runs it (constrained Delaunay triangulation, holes as seeds, ``q<angle>`` ->
``b = sin^2(angle)``, ``a<area>`` -> ``S = sqrt(4 area / sqrt 3)``), timed
without reading the mesh back.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from ..cgal_engine import delaunay_cgal, domain_triangles, mesh_cgal
from ..ours_engine import run_ours, warm_up as warm_up_ours
from ..triangle_engine import run_triangle
from ...switches import parse


@dataclass
class Call:
    """How long one engine call took, what it counted, and how to count its
    triangles (which holds on to the output: drop the ``Call`` when done)."""

    wall_s: float
    triangles: Callable[[], int]  # for CGAL's Mesh_2, those in the domain (iterates in Python)
    work: dict = field(default_factory=dict)


def delaunay_only(opts: str) -> bool:
    """No segments, no quality: CGAL's counterpart is a plain Delaunay triangulation."""
    o = parse(opts)
    return not (o.p or o.c or o.quality)


def warm_up(engine: str, opts: str, strategy: str = "triangle", threads: int | None = None) -> None:
    """Load what the engine needs (our compiled kernels, on a tiny input with
    the same switches; the other packages' modules) so that nothing timed imports."""
    if engine == "ours":
        warm_up_ours(opts, strategy, threads)
    elif engine == "triangle":
        import triangle  # noqa: F401
    elif engine == "cgal":
        from CGAL import CGAL_Kernel, CGAL_Mesh_2, CGAL_Triangulation_2  # noqa: F401
    else:
        raise ValueError(f"unknown engine {engine!r}")


def run_once(engine: str, data: dict, opts: str, strategy: str = "triangle", threads: int | None = None) -> Call:
    """One timed run of ``engine`` on ``data``."""
    if engine == "ours":
        out, wall = run_ours(data, opts, strategy, repeat=1, threads=threads)
        return Call(wall, lambda: len(out.get("triangles", ())), dict(getattr(out, "work", {}) or {}))
    if engine == "triangle":
        out, wall = run_triangle(data, opts, repeat=1)
        return Call(wall, lambda: len(out.get("triangles", ())))
    if engine == "cgal":
        if delaunay_only(opts):
            dt, wall = delaunay_cgal(data["vertices"], repeat=1)
            return Call(wall, lambda: int(dt.number_of_faces()))
        cdt, wall, _ = mesh_cgal(data, opts, repeat=1)
        return Call(wall, lambda: domain_triangles(cdt))
    raise ValueError(f"unknown engine {engine!r}")
