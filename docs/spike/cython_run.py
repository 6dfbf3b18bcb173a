import time, numpy as np, sys
from instrument.mesh import new_mesh
from instrument.divconq import cut_order, triangulate_sorted
from instrument import counters
import dc
n = int(sys.argv[1]) if len(sys.argv) > 1 else 10**6
rng = np.random.default_rng(1)
xy = rng.random((n, 2))
order = np.argsort(xy[:, 0], kind="stable")
ids = order.astype(np.int64)
pts = cut_order(xy, ids, True)
for name in ["jit", "cy", "jit", "cy", "jit", "cy"]:
    room = np.empty((n, 2)); room[:] = pts
    w = counters.new_work()
    if name == "jit":
        m = new_mesh(room, 2 * n + 8); m.size[0] = n
        t = time.perf_counter()
        triangulate_sorted(m, w, n, True)
        el = time.perf_counter() - t
        corner = m.corner
    else:
        m = dc.Mesh(room, 2 * n + 8, w)
        t = time.perf_counter()
        dc.triangulate_sorted(m, n, True)
        el = time.perf_counter() - t
        corner = np.asarray(m.corner)
    print(name, round(el, 3), w[:4], hash(corner.tobytes()))
