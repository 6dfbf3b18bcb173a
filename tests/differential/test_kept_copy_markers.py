"""The oracle's rule for duplicates of different markers under ``j``
(oracles.kept_copy_markers): only the kept copy is output, and which copy
Triangle keeps follows its random pivots."""

from __future__ import annotations

import numpy as np

from .cases import Case
from .oracles import kept_copy_markers

SQUARE = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.5, 0.5], [0.5, 0.5]])


def _case(markers) -> Case:
    return Case("dup-markers-j", "pjQ", {"vertices": SQUARE, "vertex_markers": np.array(markers)})


def _result(center_marker: int) -> dict:
    return {"vertices": SQUARE[:5], "vertex_markers": np.array([[1], [1], [1], [1], [center_marker]])}


def test_either_copy_kept():
    # copies with markers 3 and 4: Triangle kept the second, ours the first
    assert kept_copy_markers(_case([1, 1, 1, 1, 3, 4]), _result(4), _result(3)) == ([4], [3])


def test_kept_copy_of_marker_zero_gains_one_marker():
    # copies with markers 0 and 5: the copy of marker 0 gains one marker in the mesh (here 7)
    assert kept_copy_markers(_case([1, 1, 1, 1, 0, 5]), _result(7), _result(5)) == ([7], [5])


def test_two_gained_markers_are_compared_as_they_are():
    # a kept copy of marker 0 gains one marker, the same in both meshes: 7 against 8 is a difference
    assert kept_copy_markers(_case([1, 1, 1, 1, 0, 5]), _result(7), _result(8)) == ([], [])


def test_a_marker_no_copy_has_is_compared_as_it_is():
    # copies with markers 3 and 4 (neither 0): a 9 comes from neither
    assert kept_copy_markers(_case([1, 1, 1, 1, 3, 4]), _result(9), _result(3)) == ([], [])


def test_no_mixed_duplicates():
    assert kept_copy_markers(_case([1, 1, 1, 1, 3, 3]), _result(3), _result(3)) == ([], [])
