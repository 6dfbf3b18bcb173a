"""Build ruppert: compile the engine's kernels with Cython.

Kernels are ordinary Python modules written in Cython's pure-Python mode
(typed with ``cython`` annotations, beside a ``.pxd`` that declares what
other modules use).  A module is compiled when its first line is a
``# cython:`` directive comment; everything else is installed as Python.
Without the compiled modules the same files run as plain Python
(``RUPPERT_PURE_PYTHON=1``; slow, for debugging).

The flags are part of the engine's correctness: ``-ffp-contract=off`` keeps
the C compiler from fusing a*b+c into one rounding (the exact predicates'
error-free transformations need every operation rounded on its own), and
no fast-math option is ever used.

``RUPPERT_BOUNDSCHECK=1`` builds every kernel with bounds checking (each
index into an array is checked, an out-of-range one is reported instead of
corrupting memory); the test suite builds such a copy to run a part of the
suite under it.
"""

import os
from pathlib import Path

from Cython.Build import cythonize
from setuptools import Extension, setup

ROOT = Path(__file__).resolve().parent
SRC = ROOT / "src"
CHECKED = os.environ.get("RUPPERT_BOUNDSCHECK") == "1"


def kernel_modules():
    """(dotted name, path relative to the project) of every module to compile."""
    for path in sorted((SRC / "instrument").rglob("*.py")):
        with path.open() as f:
            if f.readline().startswith("# cython:"):
                rel = path.relative_to(SRC).with_suffix("")
                yield ".".join(rel.parts), str(path.relative_to(ROOT))


DIRECTIVES = {
    "language_level": 3,
    "boundscheck": CHECKED,
    "wraparound": False,
    "initializedcheck": CHECKED,
    "cdivision": True,
    "infer_types": True,
    "embedsignature": True,
}
FLAGS = ["-O3", "-ffp-contract=off", "-fno-math-errno"] + (["-O1"] if CHECKED else [])

# Cython's support code for typed memoryviews (tens of thousands of lines of
# C) is generated once, into this module, instead of into every kernel module.
SHARED = "instrument._cython_shared"
extensions = [Extension(name, [path], extra_compile_args=FLAGS) for name, path in kernel_modules()]
extensions.append(Extension(SHARED, sources=["src/instrument/_cython_shared.c"], extra_compile_args=FLAGS))
JOBS = os.cpu_count() or 1
setup(
    ext_modules=cythonize(
        extensions, compiler_directives=DIRECTIVES, nthreads=JOBS, quiet=True, shared_utility_qualified_name=SHARED
    ),
    options={"build_ext": {"parallel": JOBS}},  # the C compiler on every core, as cythonize
)
