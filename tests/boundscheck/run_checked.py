"""Run meshing cases in a bounds-checked build (a child process of the tests).

Reads a JSON list of cases from stdin, each ``{"input": {...}, "opts": "...",
"kwargs": {...}}`` with arrays as nested lists, runs ``instrument.triangulate``
on each, and prints one JSON object: per case the counts of the result (or
the exception's type and message), and every exception a kernel raised and
Python had to ignore (an index out of bounds, in this build).
"""

import json
import sys

ignored = []


def _record(unraisable):
    ignored.append(f"{type(unraisable.exc_value).__name__}: {unraisable.exc_value} in {unraisable.object!r}")


sys.unraisablehook = _record

import numpy as np  # noqa: E402

import instrument  # noqa: E402
from instrument import purepython  # noqa: E402
from instrument.core import mesh  # noqa: E402

out = {"compiled": purepython.is_compiled(mesh), "cases": []}
for case in json.loads(sys.stdin.read()):
    tri = {k: np.asarray(v) for k, v in case["input"].items()}
    before = len(ignored)
    try:
        r = instrument.triangulate(tri, case["opts"], **case.get("kwargs", {}))
        row = {k: list(np.shape(v)) for k, v in r.items()}
    except Exception as exc:  # an error is an outcome here; the parent judges it
        row = {"error": f"{type(exc).__name__}: {exc}"}
    row["ignored"] = ignored[before:]
    out["cases"].append(row)
print(json.dumps(out))
