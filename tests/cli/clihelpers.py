"""Helpers for the command-line tests: Triangle's own console output, sections of it."""

from __future__ import annotations

import ctypes
import os
import tempfile
from pathlib import Path

import numpy as np
import triangle
from triangle.tri import translate_frw, translate_inv, triang

TRIANGLE_DATA = Path(triangle.__file__).parent / "data"
_DEFAULT_CORPUS = Path(__file__).resolve().parents[3] / "shared" / "corpus"
CORPUS = Path(os.environ.get("RUPPERT_CORPUS", _DEFAULT_CORPUS))

# Reference §3.8: Triangle 1.6 on A.poly with -pq30V, verbatim.
A_PQ30_STATISTICS = """
Statistics:

  Input vertices: 29
  Input segments: 29
  Input holes: 1

  Mesh vertices: 76
  Mesh triangles: 87
  Mesh edges: 163
  Mesh exterior boundary edges: 65
  Mesh interior boundary edges: 0
  Mesh subsegments (constrained edges): 65

"""

A_PQ30_QUALITY = """Mesh quality statistics:

  Smallest area:        0.0001472   |  Largest area:        0.0058858
  Shortest edge:         0.014881   |  Longest edge:           0.1455
  Shortest altitude:     0.011314   |  Largest aspect ratio:    2.907

  Triangle aspect ratio histogram:
  1.1547 - 1.5       :        16    |     15 - 25         :         0
     1.5 - 2         :        42    |     25 - 50         :         0
       2 - 2.5       :        22    |     50 - 100        :         0
     2.5 - 3         :         7    |    100 - 300        :         0
       3 - 4         :         0    |    300 - 1000       :         0
       4 - 6         :         0    |   1000 - 10000      :         0
       6 - 10        :         0    |  10000 - 100000     :         0
      10 - 15        :         0    | 100000 -            :         0
  (Aspect ratio is longest edge divided by shortest altitude)

  Smallest angle:          30.059   |  Largest angle:          110.38

  Angle histogram:
      0 -  10 degrees:         0    |     90 - 100 degrees:        17
     10 -  20 degrees:         0    |    100 - 110 degrees:         5
     20 -  30 degrees:         0    |    110 - 120 degrees:         2
     30 -  40 degrees:        51    |    120 - 130 degrees:         0
     40 -  50 degrees:        47    |    130 - 140 degrees:         0
     50 -  60 degrees:        43    |    140 - 150 degrees:         0
     60 -  70 degrees:        42    |    150 - 160 degrees:         0
     70 -  80 degrees:        29    |    160 - 170 degrees:         0
     80 -  90 degrees:        25    |    170 - 180 degrees:         0

"""

A_PQ30_ALGORITHMIC = """Algorithmic statistics:

  Number of incircle tests: 428
  Number of 2D orientation tests: 579
  Number of triangle circumcenter computations: 38

"""


def triangle_console(data: dict, opts: str) -> tuple[str, dict]:
    """Run Triangle (library mode, no Q) with ``opts + 'V'``; return what it printed
    on file descriptor 1 and its output mesh with the `triangle` package's keys."""
    saved = os.dup(1)
    with tempfile.TemporaryFile(mode="w+") as f:
        os.dup2(f.fileno(), 1)
        try:
            out, _ = triang({translate_inv[k]: v for k, v in data.items()}, "z" + opts + "V")
        finally:
            ctypes.CDLL(None).fflush(None)
            os.dup2(saved, 1)
            os.close(saved)
        f.seek(0)
        text = f.read()
    return text, {translate_frw[k]: np.asarray(v) for k, v in out.items()}


def section(text: str, start: str, end: str | None) -> str:
    """The text from the line ``start`` up to (not including) the line ``end``."""
    i = text.index(start)
    j = text.index(end, i) if end is not None else len(text)
    return text[i:j]
