"""Spike (a): numba.pycc AOT of divide-and-conquer Delaunay + predicates."""
import time, sys
t0 = time.perf_counter()
from numba.pycc import CC
from numba import njit, types
import numpy as np
from instrument.mesh import Mesh
from instrument.divconq import triangulate_sorted

cc = CC("dt_aot")
cc.output_dir = "."

@cc.export("dt", "void(f8[:,::1], i4[::1], i4[::1], i4[::1], i4[::1], i4[::1], i8[::1], i8[::1], i8, b1)")
def dt(xy, corner, twin, seg, stamp, free, size, work, n, alternate):
    m = Mesh(xy, corner, twin, seg, stamp, free, size)
    triangulate_sorted(m, work, n, alternate)

if __name__ == "__main__":
    cc.compile()
    print("build seconds", time.perf_counter() - t0)
