"""The 600-decade input under pq32.5AeiQ, meshed and checked in full.

    python scripts/check_600_decades.py

``hang-pq32.5Aei-regions`` (tests/engine/test_mixed_scale_refinement.py):
ends at 0 and 1e300, free vertices near 1e-302.  The engine grades it from
1e-304 to 1e300 (284,865 vertices in about 1 s); the exact checker then
takes about 10 s CPU and 0.5 GB, too long for the suite, which checks the
same input under q10 and q20.  Prints the sizes, the CPU times and the
checker's problems; exits 1 if there is any.  The checker gets what the
differential harness gives it at this extent: the input as PSLG, no angle
or area bound (Triangle's answer is no reference beyond 2^200).
"""

from __future__ import annotations

import resource
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import numpy as np  # noqa: E402

import instrument  # noqa: E402
from instrument.check import check_mesh  # noqa: E402
from tests.engine.test_mixed_scale_refinement import REGIONS_CASE  # noqa: E402


def main() -> int:
    hexes = lambda xs, n: np.array([float.fromhex(x) for x in xs]).reshape(-1, n)  # noqa: E731
    pslg = {"vertices": hexes(REGIONS_CASE["vertices"], 2),
            "segments": np.array(REGIONS_CASE["segments"]).reshape(-1, 2),
            "regions": hexes(REGIONS_CASE["regions"], 4)}
    t = time.process_time()
    mesh = instrument.triangulate(pslg, "pq32.5AeiQ")
    meshed = time.process_time() - t
    t = time.process_time()
    problems = check_mesh(mesh, pslg=pslg)
    checked = time.process_time() - t
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"{len(mesh['vertices'])} vertices, {len(mesh['triangles'])} triangles: meshed in {meshed:.1f} s, "
          f"checked in {checked:.1f} s CPU, peak RSS {rss:.0f} MB; {len(problems)} problems")
    for line in problems[:20]:
        print(line)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
