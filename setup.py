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

extensions = [Extension(name, [path], extra_compile_args=FLAGS) for name, path in kernel_modules()]
setup(
    ext_modules=cythonize(extensions, compiler_directives=DIRECTIVES, nthreads=os.cpu_count() or 1, quiet=True),
)
