"""The benchmark: ruppert's engine against Triangle (the `triangle` package) and CGAL Mesh_2.

    python -m instrument.study.bench                  # every workload that is not opt-in
    python -m instrument.study.bench dt cdt           # workloads whose name starts with "dt" or "cdt"
    python -m instrument.study.bench dt-1e7 --repeat 1 --no-cgal
    python -m instrument.study.bench cli-A --cold     # the command, warm and after a fresh install
    python -m instrument.study.bench quad --strategies triangle,fifo
    python -m instrument.study.bench square --profile # where our time goes, stage by stage
    python -m instrument.study.bench --markdown bench.md --json bench.json

Workloads (name: input, switches, goal):

  dt-1e5, dt-1e6   Delaunay of 10^5 / 10^6 uniform random points, no switches;
                   goal: at most 0.8x / 0.6x Triangle's time.
  dt-1e7           10^7 points (opt-in: about 5 GB at its peak, minutes).
  cdt-1e5          a wavy polygon with 16 wavy holes, 10^5 vertices, ``p``;
                   goal: at most 0.8x.
  square-q30a1e-6  quality mesh of the unit square, ``pq30a0.000001`` (about
                   1.6 million triangles); goal: at most 0.8x.
  la-q30           la.poly from the `triangle` package's data folder, ``pq30``;
                   goal: at most 1.0x.
  quad-12800       Barbič and Miller's quadratic example I(12800), ``pq20``; one
                   row per strategy (``--strategies``); goal: the least-work
                   strategy at least 5x faster than Triangle.
  cli-A            the command ``ruppert -pq30 A.poly`` (the `triangle`
                   package's A.poly), a subprocess, against a Python script
                   running the `triangle` package on the same file; with the
                   command's start-up broken down; goal: under 1 second.
  cold             (opt-in, ``--cold``) a fresh venv, ``pip install`` of the
                   checkout, then the command twice, and Triangle's script
                   twice after ``pip install triangle``.
  *-tiny           (opt-in) small stand-ins for the tests.

How each is measured: ``timing`` (in-process workloads), ``memory`` (peak
memory), ``commands`` (cli-A), ``cold``; the report in ``report``.  The
benchmark needs the `triangle` package and, for peak memory and the strategy
workloads' time limit, ``pebble`` (the ``study`` extra); CGAL runs where its
bindings (the ``cgal`` package) are installed.
"""
