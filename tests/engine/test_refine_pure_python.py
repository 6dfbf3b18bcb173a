"""The refinement kernels run as plain Python (``RUPPERT_PURE_PYTHON=1``)
give the compiled kernels' mesh and work counters.

The helpers every refinement step calls (the quality test's pieces, the
queue's push, the encroachment tests of a subsegment side, the bucket key)
are written twice: in the ``.pxd`` files, so that every kernel inlines them,
and in the ``.py`` files for the pure-Python mode (docs/architecture.md).
This keeps the two copies from drifting apart: four strategies' keys (the
buckets, a heap), area bounds, Chew's deletion and off-centers are exercised.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

import numpy as np
import pytest
import triangle as triangle_package

import instrument
from instrument.check import check_mesh

RUNS = [
    ("la", "pq30", "triangle"),
    ("la", "pq25a200", "worst-angle"),
    ("A", "pq30a0.5", "largest"),
    ("A", "pq33", "fifo"),
]

DRIVER = r"""
import json, sys
import numpy as np
import triangle
import instrument
from instrument import purepython
from instrument.refine import splits
name, opts, strategy = sys.argv[1:4]
assert not purepython.is_compiled(splits)
r = instrument.triangulate(triangle.get_data(name), opts, strategy=strategy)
print(json.dumps({"arrays": {k: np.asarray(v).tolist() for k, v in r.items()}, "work": dict(r.work)}))
"""


@pytest.mark.parametrize("name, opts, strategy", RUNS)
def test_refinement_runs_as_python(name, opts, strategy):
    env = dict(os.environ, RUPPERT_PURE_PYTHON="1")
    done = subprocess.run([sys.executable, "-c", DRIVER, name, opts, strategy], env=env,
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr[-2000:]
    pure = json.loads(done.stdout.strip().splitlines()[-1])
    compiled = instrument.triangulate(triangle_package.get_data(name), opts, strategy=strategy)
    assert check_mesh(compiled) == []
    assert pure["work"] == dict(compiled.work)
    assert sorted(pure["arrays"]) == sorted(compiled)
    for key, value in compiled.items():
        np.testing.assert_array_equal(np.asarray(pure["arrays"][key]), value, err_msg=key)
