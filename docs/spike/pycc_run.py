import time, numpy as np, sys
from instrument.mesh import new_mesh
from instrument.divconq import cut_order, triangulate_sorted
from instrument import counters
import dt_aot
n = int(sys.argv[1]) if len(sys.argv) > 1 else 10**6
rng = np.random.default_rng(1)
xy = rng.random((n, 2))
order = np.argsort(xy[:, 0], kind="stable")
ids = order.astype(np.int64)
pts = cut_order(xy, ids, True)
def mk():
    room = np.empty((n, 2)); room[:] = pts
    m = new_mesh(room, 2 * n + 8); m.size[0] = n
    return m
for name in ["jit", "aot", "jit", "aot"]:
    m = mk(); w = counters.new_work()
    t = time.perf_counter()
    if name == "jit":
        triangulate_sorted(m, w, n, True)
    else:
        dt_aot.dt(m.xy, m.corner, m.twin, m.seg, m.stamp, m.free, m.size, w, n, True)
    el = time.perf_counter() - t
    print(name, round(el, 3), int(m.size[3]), w[:4], hash(m.corner.tobytes()))
