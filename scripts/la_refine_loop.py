#!/usr/bin/env python
"""Run ``triangulate(triangle.get_data("la"), "pq30")`` in a loop and print the
process time per run of the whole call and of the refinement kernel.

For measuring the kernel on a shared machine, where wall times are noisy:
instruction counts are the steadier figure, e.g.::

    valgrind --tool=callgrind --toggle-collect='__pyx_f_10instrument_6refine_6splits_refine' \\
        python scripts/la_refine_loop.py 50 5
    callgrind_annotate callgrind.out.<pid>

(the ``Collected`` line is the kernel's instructions over warm-up and measured
runs).  The kernel's time is taken by wrapping the ``refine`` that
``instrument.refine`` calls (a measurement aid only; nothing else changes).

Usage: ``python scripts/la_refine_loop.py [RUNS [WARMUP]]`` (default 50 5).
"""

import sys
import time

import triangle

import instrument
import instrument.refine as refine_driver


def main() -> int:
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 50
    warmup = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    spent = [0.0]
    kernel = refine_driver.refine

    def timed(*args):
        t0 = time.process_time()
        try:
            return kernel(*args)
        finally:
            spent[0] += time.process_time() - t0

    refine_driver.refine = timed
    data = triangle.get_data("la")
    for _ in range(warmup):
        instrument.triangulate(data, "pq30")
    spent[0] = 0.0
    t0 = time.process_time()
    for _ in range(runs):
        out = instrument.triangulate(data, "pq30")
    t1 = time.process_time()
    print(f"{len(out['triangles'])} triangles; per run: total {(t1 - t0) / runs * 1e6:.1f} us, "
          f"kernel {spent[0] / runs * 1e6:.1f} us (process time)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
