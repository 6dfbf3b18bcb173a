"""Time instrument.triangulate on n random points: best of k, wall and CPU."""
import sys, time, resource
import numpy as np
import instrument
n = int(float(sys.argv[1])); k = int(sys.argv[2]) if len(sys.argv) > 2 else 5
opts = sys.argv[3] if len(sys.argv) > 3 else "Q"
pts = np.random.default_rng(1).random((n, 2))
instrument.triangulate({"vertices": pts[:1000]}, opts)  # warm (numba compiles on first use)
best_w = best_c = 1e9
for _ in range(k):
    c0 = time.process_time(); w0 = time.perf_counter()
    r = instrument.triangulate({"vertices": pts}, opts)
    best_w = min(best_w, time.perf_counter() - w0); best_c = min(best_c, time.process_time() - c0)
print(f"n={n} opts={opts} triangles={len(r['triangles'])} wall={best_w:.3f}s cpu={best_c:.3f}s")
