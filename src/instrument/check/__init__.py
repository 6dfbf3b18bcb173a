"""Independent checker for triangle meshes (the test oracle of ruppert).

This package judges the output of the engine without sharing any code with it:
it uses only numpy, Python integers and :mod:`math`.  Every geometric sign it
relies on is exact.  A vectorised floating-point filter (Shewchuk's stage-A
error bounds) certifies most signs, and the entries it cannot certify are
recomputed with exact integer arithmetic (every double is an integer times a
power of two).

Public API
----------
``check_mesh(result, pslg=None, min_angle=None, *, delaunay=True,
max_area=None, markers=True) -> list[str]``
    Human-readable problems; an empty list means the mesh is valid.
``quality_report(result, pslg=None, min_angle=None) -> dict``
    ``min_angle_deg``, ``max_angle_deg``, ``n_bad``, ``n_exempt``,
    ``area_total`` (plus ``n_triangles``).
``mesh_area(result) -> float``
    ``math.fsum`` of the signed triangle areas.
``orient_exact(a, b, c) -> int``, ``incircle_exact(a, b, c, d) -> int``
    Exact signs computed with integers.  ``orient_exact > 0`` iff a, b, c are
    counter-clockwise.  ``incircle_exact > 0`` iff d lies strictly inside the
    circle through the counter-clockwise a, b, c.
``orient_signs(a, b, c)``, ``incircle_signs(a, b, c, d)``
    The same signs for arrays of points of shape (n, 2), filtered and exact.

What ``check_mesh`` guarantees
------------------------------
If it returns no problem, the triangles (first three columns of
``triangles``):

* use indices in range, have three distinct corners that are pairwise
  distinct points, and are strictly counter-clockwise (exact orientation);
* no two triangles use the same corner set, and every directed edge is used
  by at most one triangle (so an undirected edge by at most two, in opposite
  directions);
* have pairwise disjoint interiors and meet only in common vertices or common
  edges: the union is an embedded simplicial complex.  Proof sketch: with all
  triangles counter-clockwise and every directed edge used once, the number
  of triangles covering a point p (not on an edge) equals the winding number
  around p of the chain of *boundary edges* (directed edges whose reverse is
  absent).  If some open region were covered twice, its frontier would
  contain a point x in the relative interior of a boundary edge, and a
  triangle other than the edge's own would contain x.  The checker therefore
  tests, exactly, every boundary edge (open segment) against every other
  triangle (closed) whose bounding box meets it (a packed tree of bounding
  boxes finds the candidates).  The same test catches hanging vertices (T-junctions).

Vertices that no triangle uses are allowed (Triangle outputs duplicate and
eaten input vertices).

Also checked:

* every row of ``segments`` (the subsegments) is an edge of some triangle;
* constrained Delaunay (``delaunay=True``): for every edge shared by two
  triangles that is not a subsegment, the opposite apex is not strictly inside
  the other triangle's circumcircle (exact incircle; cocircular is fine);
* with ``pslg``: the output vertices lying on an input segment (exactly, or
  within ON_SEGMENT_RTOL: Triangle leaves split points up to ~1 ulp off the
  line) cut it into pieces, and every piece is covered by collinear output
  subsegments, or lies outside the mesh (Triangle deletes subsegments eaten
  with holes and the exterior).  Pass ``pslg`` only when the output has
  segments (not with ``-P``);
* ``min_angle``: see ``quality_report`` for the exemptions;
* ``max_area``: area <= max_area * (1 + 1e-12);
* ``markers``: lengths of the marker and attribute arrays, and nonzero
  markers on boundary subsegments and their endpoints (reference 2.12).

Modules
-------
``exact``      the exact signs (filter, then integers);
``view``       the result read into arrays and masks, its directed edges, the
               list of problems, equal-key joins;
``boxes``      candidate pairs of overlapping boxes (a packed bounding-box
               tree, in chunks);
``structure``  triangles, edges and overlap: an embedded simplicial complex;
``delaunay``   subsegments are edges; the constrained Delaunay property;
``chains``     input segments covered by output subsegments; the output's
               segments as chains;
``quality``    angles and their exemptions, areas;
``markers``    array lengths and boundary markers;
this package   the entry points, which run the checks in a fixed order (the
               order of the problems reported).
"""

from __future__ import annotations

import math

import numpy as np

from .chains import input_chains
from .delaunay import check_delaunay, check_segments
from .exact import incircle_exact, incircle_signs, orient_exact, orient_signs
from .markers import check_markers
from .quality import SMALL_INPUT_ANGLE, check_area, classify_angles
from .structure import check_edges, check_overlap, check_triangles
from .view import Edges, MeshView, Problems, int_array

# The tolerances stay attributes of this package, where the docstrings name them.
from .chains import ON_SEGMENT_RTOL  # noqa: F401
from .quality import ANGLE_RTOL, AREA_RTOL, MPW_RATIO  # noqa: F401
from .view import MAX_MESSAGES  # noqa: F401

__all__ = [
    "check_mesh",
    "quality_report",
    "mesh_area",
    "orient_exact",
    "incircle_exact",
    "orient_signs",
    "incircle_signs",
    "SMALL_INPUT_ANGLE",
]


def check_mesh(result, pslg=None, min_angle=None, *, delaunay=True, max_area=None,
               markers=True) -> list[str]:
    """Check a mesh in the ``triangle`` package's output format.

    result     dict with ``vertices`` (N, 2), ``triangles`` (M, 3) or (M, 6)
               (a missing key means an empty mesh), optional ``segments``
               (the constrained subsegments) and markers.
    pslg       the input dict; every input segment must appear as a chain of
               collinear output subsegments (see ON_SEGMENT_RTOL), except for
               pieces lying outside the mesh (eaten with holes/exterior).
    min_angle  degrees; triangles below it are problems unless a small input
               angle explains them (see ``quality_report``).
    delaunay   check the constrained Delaunay property (exact incircle) on
               every edge that is shared by two triangles and is not a segment.
    max_area   every triangle's area must be <= max_area * (1 + 1e-12).
    markers    check array lengths, and that boundary subsegments and their
               endpoints have nonzero markers (when markers are present).

    Returns a list of human-readable problems; empty means valid.
    """
    probs = Problems()
    m = MeshView(result, probs)
    if not m.ok:
        return probs.lines
    check_triangles(m, probs)
    e = Edges(m)
    check_edges(m, e, probs)
    check_overlap(m, e, probs)
    check_segments(m, e, probs)
    if delaunay:
        check_delaunay(m, e, probs)
    pslg_chains = input_chains(m, pslg, probs) if pslg is not None else None
    if min_angle is not None:
        classify_angles(m, pslg, min_angle, probs, pslg_chains)
    if max_area is not None:
        check_area(m, max_area, probs)
    if markers:
        check_markers(m, result, e, probs)
    return probs.lines


def quality_report(result, pslg=None, min_angle=None) -> dict:
    """Angle statistics of the strictly counter-clockwise triangles.

    n_bad     triangles whose smallest angle is below min_angle (relative
              tolerance 1e-9), exempt ones included;
    n_exempt  those of them explained by a small input angle:
      (a) the smallest angle is at a corner J, J is the apex of a wedge
          between two angularly consecutive segments at J whose angle is
          below both SMALL_INPUT_ANGLE (60 degrees) and min_angle (so every
          triangle at J inside it has a bad angle at J), and the triangle
          lies inside that wedge;
      (b) Miller-Pav-Walkington (reference 4.8.4): an edge of minimum length
          (relative 1e-12) that is not a subsegment joins two Steiner
          points lying on two different segments that share an endpoint J,
          with squared distances to J equal within a factor 1 +- 0.001.
      Segments are the maximal straight chains of output subsegments (cut at
      input vertices when ``pslg`` is given, since input vertices are not
      Steiner points), plus, when ``pslg`` is given, the input segments with
      the output vertices on them (so J is the input segment's endpoint even
      when other segments cross it, as in Triangle).
    """
    m = MeshView(result, Problems())
    if not m.ok:
        raise ValueError("malformed mesh arrays")
    idx, ang, bad_t, exempt_t = classify_angles(m, pslg, min_angle, None)
    return {
        "n_triangles": int(idx.size),
        "min_angle_deg": float(ang.min()) if idx.size else float("nan"),
        "max_angle_deg": float(ang.max()) if idx.size else float("nan"),
        "n_bad": len(bad_t) + len(exempt_t),
        "n_exempt": len(exempt_t),
        "area_total": mesh_area(result),
    }


def mesh_area(result) -> float:
    """math.fsum of the signed areas of the triangles (first three columns)."""
    v = np.asarray(result.get("vertices", np.zeros((0, 2))), dtype=np.float64).reshape(-1, 2)
    t = int_array(result.get("triangles", np.zeros((0, 3))), 3)
    if not len(t):
        return 0.0
    P = v[t[:, :3]]
    u = P[:, 1] - P[:, 0]
    w = P[:, 2] - P[:, 0]
    return math.fsum((0.5 * (u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0])).tolist())
