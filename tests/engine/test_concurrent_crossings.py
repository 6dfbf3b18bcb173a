"""Segments concurrent within rounding: recovery never gives up.

Five segments, the last three of which end at, or pass through, the
crossing of two others computed in doubles, moved by up to 2 ulps (the
concurrent-segments family of tests/differential/families.py; found by a
sweep of 1,500 such inputs at stop 32).  Triangle crashes on the first
three; ours raised "could not recover segment" (the fourth: a folded mesh)
and now makes a mesh that passes the exact checker under every switch
string the sweep used.

- ``_THROUGH_AN_END``: a piece starting at the crossing beside an input end
  took, within rounding, the crossing vertex of two other segments two ulps
  away for a vertex on it, and the walk's crossed edges were not those of
  the segment to it (recover._crossed_exactly: the segment to it runs
  exactly through that input end, along the other segments' chain).
- ``_BESIDE_THE_CROSSING`` (scale 1) and ``_BESIDE_THE_CROSSING_1E100``: a
  segment's input end lies one ulp from the crossing of the first two;
  Triangle's flips for the second left a pocket waiting beside that end,
  and the crossing vertex, on the pocket's side of it, folded the mesh
  (recover._near_crossed: the piece goes to that end by exact flips, and
  the crossing is that end).
- ``_PAST_THE_SUBSEGMENT``: two input ends 7 ulps apart on either side of the
  crossing; the second segment's halves through the crossing passed one of
  them on the other side than the segment itself, beside the pocket
  Triangle's flips left there, and the mesh folded ("segments cross at
  points too close together"; Triangle meshes it, 11 vertices, ours 10:
  the one crossing is that end).
"""

from __future__ import annotations

import numpy as np
import pytest

import instrument
from instrument.check import check_mesh

_THROUGH_AN_END = [
    ("0x1.c000000000000p-2", "0x1.3800000000000p-1"), ("0x1.a800000000000p-1", "0x1.458742fc63209p-1"),
    ("0x1.94cd8cf14e8bfp-1", "0x1.d9de0ad3ae942p-1"), ("0x1.ba7d1daf53688p-2", "0x1.dee379b141944p-3"),
    ("0x1.446cf7353c4f9p-1", "0x1.3ecb006037105p-1"), ("0x1.0e6bd8b44edcap-2", "0x1.f0c9097629f00p-2"),
    ("0x1.3e37ced236c58p-3", "0x1.adec37881edecp-2"), ("0x1.1ca5fd5af576cp+0", "0x1.a69fe4fc5eb0ep-1"),
    ("0x1.35d659b45d379p-1", "0x1.a000000000000p-2"), ("0x1.530394b61b6cbp-1", "0x1.ad9600c06e226p-1"),
]
_BESIDE_THE_CROSSING = [
    ("0x1.25031684b3440p-1", "0x1.25409e9b58480p-7"), ("0x1.02cd8d7e9a930p-3", "0x1.c800000000000p-1"),
    ("0x1.28391e5389348p-4", "0x1.b486b7630ba10p-5"), ("0x1.3f7158631661fp-1", "0x1.fb089d9b32207p-1"),
    ("0x1.e000000000000p-1", "0x1.bae47930ff73ep-2"), ("-0x1.1dd6f7cb89608p-2", "0x1.17ee484df971fp-1"),
    ("0x1.5114841a3b4fep-2", "0x1.f56084e6792bfp-2"), ("0x1.31e039abc4409p-1", "0x1.34bbed7697042p-2"),
    ("0x1.dffffffffffffp-1", "0x1.bae47930ff73fp-2"), ("0x1.3f5c2c4affd8dp-1", "0x1.5f2fafc5fb4acp-1"),
]
_BESIDE_THE_CROSSING_1E100 = [
    ("0x1.86e800b96350fp+330", "0x1.19593a7c3e597p+331"), ("0x1.cc4239d537ff7p+331", "0x1.c931e8ab87173p+330"),
    ("0x1.68b0656924dfcp+331", "0x1.b07aab2922982p+330"), ("0x1.0007780e22b0dp+330", "0x1.20d41c20d78ccp+332"),
    ("0x1.50ea3731c4586p+331", "0x1.fa56389b11793p+330"), ("0x1.245ed85be4067p+332", "0x1.86a022a1f419ap+331"),
    ("0x1.50ea3731c4587p+331", "0x1.fa56389b11790p+330"), ("0x1.4165ede1feacap+329", "0x1.ec07b818335a1p+331"),
    ("0x1.adc364f327f20p+331", "0x1.ab21bba1ace4fp+330"), ("0x1.e82212e0c17d5p+330", "0x1.24c55aca3b069p+331"),
]

_PAST_THE_SUBSEGMENT = [
    ("0x1.51c510de9ba10p-3", "0x1.8000000000000p-4"), ("0x1.cf96863c0ff50p-2", "0x1.e1bcbd4eebc8ap-2"),
    ("0x1.7000000000000p-1", "0x1.7000000000000p-1"), ("0x1.54a8825ed050cp-1", "0x1.b561178098922p-1"),
    ("0x1.62b3bc975abadp-1", "0x1.91be430363816p-1"), ("0x1.74f2989d43caep-1", "0x1.fa96861d7939bp-1"),
    ("0x1.12fb357ed8f20p-3", "0x1.56225ff37f6a0p-3"), ("0x1.405455e77f9c9p+0", "0x1.66f9f704f393ep+0"),
    ("0x1.62b3bc975abadp-1", "0x1.91be43036380fp-1"), ("0x1.a000000000000p-3", "0x1.d5a3fe8b3b2f8p-3"),
]


def _input(points) -> dict:
    return {"vertices": np.array([[float.fromhex(x), float.fromhex(y)] for x, y in points]),
            "segments": np.arange(len(points), dtype=np.int32).reshape(-1, 2)}


@pytest.mark.parametrize("switches", ["pQ", "pcQ", "pjQ", "pDQ"])
@pytest.mark.parametrize("points", [_THROUGH_AN_END, _BESIDE_THE_CROSSING, _BESIDE_THE_CROSSING_1E100,
                                    _PAST_THE_SUBSEGMENT],
                         ids=["through-an-end", "beside-the-crossing", "beside-the-crossing-1e100", "past-the-subsegment"])
def test_concurrent_segments_are_recovered(points, switches):
    inp = _input(points)
    out = instrument.triangulate(inp, switches)
    assert check_mesh(out, pslg=inp) == []
