"""The study: ruppert's engine measured against Triangle and CGAL, runnable from an installed ruppert.

Each part runs as ``python -m instrument.study.NAME --help``:

* ``engines``: one input through the engine runners (ours per strategy;
  Triangle through the `triangle` package with its ``V`` statistics read from
  C's standard output; CGAL's Mesh_2 through the ``cgal`` bindings when they
  are installed), printed as JSON rows;
* ``sweep``: a grid of inputs x switches x strategies x engines as tasks on
  ``dask.distributed`` (an embedded ``LocalCluster`` or ``--scheduler``), each
  task isolated with a time and a memory limit, rows written to a resumable
  Parquet dataset; ``sweep summary DATASET`` makes tables and plots from it;
* ``compare``: the same inputs through every engine, as one table (sizes that
  match while the work differs);
* ``quadratic``: Barbič and Miller's quadratic example I(n): Theorem 3's
  script, every strategy, Triangle and CGAL, fitted slopes and figures;
* ``bench``: the benchmark: fixed workloads (Delaunay of 10^5 to 10^7
  points, a PSLG, quality meshes, the ``ruppert`` command warm and after a
  fresh install) against Triangle and CGAL, time and peak memory.

The engine (``instrument``) and the ``ruppert`` command never import this
package; ``engines`` and its runners need only numpy and the engines
themselves, the rest needs the ``study`` extra (``pip install "ruppert[study]"``:
dask, distributed, pyarrow, pebble, matplotlib, rich).
"""
