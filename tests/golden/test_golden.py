"""The engine's output, bit for bit, against ``golden.json`` (see make_golden.py).

Every array of the result, the work counters and the trace are compared by
hash over a fixed grid of inputs x switches x strategies.  A change that
alters meshes on purpose rewrites the file (``python
tests/golden/make_golden.py``) and says why in its commit.
"""

from __future__ import annotations

import json

import pytest

import make_golden as g

GOLDEN = json.loads(g.GOLDEN.read_text())
INPUTS = g.inputs()
BY_INPUT: dict[str, dict] = {}
for _key, _value in GOLDEN.items():
    BY_INPUT.setdefault(_key.split(" | ")[0], {})[_key] = _value


@pytest.mark.parametrize("name", sorted(BY_INPUT))
def test_output_is_bit_for_bit_the_recorded_one(name):
    if name not in INPUTS:
        pytest.skip("input not available here (the shared corpus sits beside the checkout)")
    now = g.run_input((name, str(INPUTS[name])))
    differs = {k: sorted(f for f in set(v) | set(now.get(k, {})) if v.get(f) != now.get(k, {}).get(f))
               for k, v in BY_INPUT[name].items() if now.get(k) != v}
    assert not differs, differs
