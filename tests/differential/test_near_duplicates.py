"""Triangle's near-duplicate crossing vertices and the triangles only they make
(oracles.near_duplicates_merged): Triangle's mesh of
regressions/crossing-overlap-near-duplicate-triangle.json, written out."""

from __future__ import annotations

import numpy as np

from .oracles import near_duplicate_merges, near_duplicates_merged

# input vertex 7 and the two roundings of one crossing, an ulp above and below y = 0.0004024505615234375
SLIVER = {
    "vertices": np.array([[0.00019168853759765625, 0.0004024505615234375],
                          [0.0004057442618915759, 0.00040245056152343755],
                          [0.0004057442618915758, 0.00040245056152343745],
                          [0.5, 0.5]]),
    "triangles": np.array([[0, 2, 1]]),
    "segments": np.array([[1, 2], [0, 1], [0, 2]]),
}


def test_the_triangle_of_two_near_duplicates_goes_with_what_only_it_had():
    assert near_duplicate_merges(SLIVER) == 1
    assert near_duplicates_merged(SLIVER, jettison=True) == {"vertices": 0, "triangles": 0, "segments": 0}
    # without j every vertex stays, the two near-duplicates as one
    assert near_duplicates_merged(SLIVER, jettison=False) == {"vertices": 3, "triangles": 0, "segments": 0}


def test_o2_nodes_of_the_merged_triangle_leave_the_count():
    mid = [(SLIVER["vertices"][a] + SLIVER["vertices"][b]) / 2 for a, b in ((2, 1), (1, 0), (0, 2))]
    o2 = {"vertices": np.vstack([SLIVER["vertices"], mid]), "triangles": np.array([[0, 2, 1, 4, 5, 6]]),
          "segments": SLIVER["segments"]}
    assert near_duplicates_merged(o2, jettison=True)["vertices"] == 0
    assert near_duplicates_merged(o2, jettison=False) == {"vertices": 3, "triangles": 0, "segments": 0}


def test_a_mesh_without_near_duplicates_is_left_alone():
    square = {"vertices": np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]),
              "triangles": np.array([[0, 1, 2], [0, 2, 3]])}
    assert near_duplicates_merged(square, jettison=False) is None
