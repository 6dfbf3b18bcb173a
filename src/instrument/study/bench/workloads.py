"""The benchmark's workloads: what each one runs, on which input, with which switches.

A workload is either in-process (``make`` builds the input dict; every engine
runs on it in one process) or a command (``command`` names the input file; the
``ruppert`` command runs against a Python script running the `triangle`
package on the same file).  The ``cold`` workload is a command workload that
first builds a fresh virtual environment (``instrument.study.bench.cold``).

Some workloads run only when named in full (``opt_in``): ``cold`` takes
minutes (a pip install that compiles the engine), ``dt-1e7`` several GB of
memory, and the ``*-tiny`` ones exist for the tests (a fresh process sees
them, unlike a dict patched in by a test).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

import numpy as np


def uniform(n: int, seed: int = 1) -> dict:
    """n uniform random points in the unit square."""
    return {"vertices": np.random.default_rng(seed).random((n, 2))}


def polygon_with_holes(n: int, holes: int = 16, seed: int = 2) -> dict:
    """A wavy outer polygon of n/2 vertices and ``holes`` wavy round holes
    sharing the other n/2, as segments; one hole point per hole."""
    rng = np.random.default_rng(seed)
    loops, centers = [], []
    outer = n // 2
    ang = np.linspace(0, 2 * np.pi, outer, endpoint=False)
    r = 1 + 0.05 * np.sin(7 * ang) + 0.2 / outer * rng.random(outer)  # noise below the spacing: simple
    loops.append(np.c_[r * np.cos(ang), r * np.sin(ang)])
    side = int(np.ceil(np.sqrt(holes)))
    per = (n - outer) // holes
    for h in range(holes):
        c = (np.array([h % side, h // side]) + 0.5) / side * 1.2 - 0.6
        a = np.linspace(0, 2 * np.pi, per, endpoint=False)
        rr = 0.25 / side * (1 + 0.1 * np.sin(5 * a))
        loops.append(c + np.c_[rr * np.cos(a), rr * np.sin(a)])
        centers.append(c)
    verts, segs, start = [], [], 0
    for loop in loops:
        k = len(loop)
        verts.append(loop)
        idx = np.arange(k) + start
        segs.append(np.c_[idx, np.roll(idx, -1)])
        start += k
    return {"vertices": np.vstack(verts), "segments": np.vstack(segs), "holes": np.array(centers)}


def unit_square() -> dict:
    return {
        "vertices": np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]),
        "segments": np.array([[0, 1], [1, 2], [2, 3], [3, 0]]),
    }


def triangle_data_file(name: str) -> Path:
    """A sample file shipped in the `triangle` package's data folder (the
    benchmark needs the package anyway, and an installed ruppert has no
    checkout's ``data/`` beside it)."""
    import triangle

    return Path(triangle.__file__).resolve().parent / "data" / name


def package_poly(name: str) -> dict:
    """A sample .poly of the `triangle` package, read by Triangle's rules
    (``ruppert_io.read``; the package's own loader misreads region lines)."""
    import ruppert_io

    return ruppert_io.read(triangle_data_file(name))


def quadratic(n: int) -> dict:
    from instrument.quadratic import example

    return example(n)


@dataclass(frozen=True)
class Workload:
    label: str  # what the input is, for the tables
    opts: str  # Triangle's switches (library form for in-process workloads, "-pq30" for commands)
    make: Callable[[], dict] | None = None  # in-process workloads: the input
    command: str = ""  # command workloads: a file of the `triangle` package's data folder
    cold: bool = False  # a command workload run in a fresh virtual environment after installing ruppert
    goal: float | None = None  # ratio to Triangle's time (commands: seconds)
    cgal: bool = True  # CGAL has a counterpart
    sweep: bool = False  # one row per strategy (--strategies)
    opt_in: bool = False  # runs only when named in full

    @property
    def in_process(self) -> bool:
        return self.make is not None


#: goals: issue 21's (faster than Triangle on every workload)
WORKLOADS: dict[str, Workload] = {
    "dt-1e5": Workload("10^5 uniform random points", "", lambda: uniform(10**5), goal=0.8),
    "dt-1e6": Workload("10^6 uniform random points", "", lambda: uniform(10**6), goal=0.6),
    "dt-1e7": Workload("10^7 uniform random points", "", lambda: uniform(10**7), opt_in=True),
    "cdt-1e5": Workload("polygon with 16 holes, 10^5 vertices", "p", lambda: polygon_with_holes(10**5), goal=0.8),
    "square-q30a1e-6": Workload("unit square", "pq30a0.000001", unit_square, goal=0.8),
    "la-q30": Workload("la.poly (triangle package)", "pq30", lambda: package_poly("la.poly"), goal=1.0),
    "quad-12800": Workload("quadratic example I(12800)", "pq20", lambda: quadratic(12800), goal=0.2, sweep=True),
    "cli-A": Workload("`ruppert -pq30 A.poly`, whole command", "-pq30", command="A.poly", goal=1.0, cgal=False),
    "cold": Workload("fresh venv: pip install, then `ruppert -pq30 A.poly` twice", "-pq30", command="A.poly",
                     cold=True, cgal=False, opt_in=True),
    # small stand-ins of the same kinds, for the tests
    "dt-tiny": Workload("300 uniform random points", "", lambda: uniform(300), goal=1.5, opt_in=True),
    "cdt-tiny": Workload("polygon with 4 holes, 400 vertices", "p", lambda: polygon_with_holes(400, holes=4),
                         opt_in=True),
    "square-tiny": Workload("unit square", "pq30a0.01", unit_square, goal=1.5, opt_in=True),
    "quad-tiny": Workload("quadratic example I(40)", "pq20", lambda: quadratic(40), goal=0.2, sweep=True,
                          opt_in=True),
}


def is_stand_in(name: str) -> bool:
    """A small stand-in for the tests."""
    return name.endswith("-tiny")


def select(names: Iterable[str], *, cold: bool = False, everything: bool = False) -> list[str]:
    """The workloads to run, in ``WORKLOADS``' order: each argument is a full
    name or a prefix (``dt`` selects dt-1e5 and dt-1e6); no argument selects
    every workload that is not opt-in.  An opt-in workload runs only when
    named in full (or ``cold`` for ``cold``; ``everything``: every workload
    but the tests' stand-ins).  Raises ``ValueError`` for an argument that
    selects nothing."""
    names = list(names)
    chosen = {n for n in WORKLOADS if not is_stand_in(n)} if everything else set()
    for arg in names:
        hit = [n for n, w in WORKLOADS.items() if n == arg or (n.startswith(arg) and not w.opt_in)]
        if not hit:
            raise ValueError(f"no workload is named or starts with {arg!r}; choose from {', '.join(WORKLOADS)}")
        chosen.update(hit)
    if not names and not everything:
        chosen = {n for n, w in WORKLOADS.items() if not w.opt_in}
    if cold:
        chosen.add("cold")
    return [n for n in WORKLOADS if n in chosen]
