"""Triangle's switch strings ("pq30a0.1zQ") parsed into an ``Options`` value.

Switches are single characters tested one at a time; unknown characters and
digits that belong to no number are ignored, as Triangle does.  One
deliberate difference: the numbers after ``q`` and ``a`` may carry an
exponent, so ``a1e-4`` means a maximum area of 0.0001.  Triangle reads it as
area 1 plus the ``-e`` switch, which silently ruins meshes (its users write
``f"a{x}"`` and Python prints small areas with exponents).
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass

from .errors import TriangleError

_NUMBER = re.compile(r"[0-9.]*")
_FLOAT_PREFIX = re.compile(r"[0-9]*\.?[0-9]*")
_EXPONENT = re.compile(r"[eE][-+]?[0-9]+")


class SwitchError(TriangleError):
    """A switch string that Triangle would reject (e.g. a non-positive area);
    the `triangle` package reports these as RuntimeError, so it is both."""


@dataclass(frozen=True)
class Options:
    p: bool = False  # read a PSLG
    r: bool = False  # refine an existing mesh
    q: bool = False  # quality: minimum angle
    min_angle: float = 0.0
    max_area: float = -1.0  # fixed area bound, -1 = none
    var_area: bool = False  # per-region / per-triangle area bounds
    u: bool = False  # user test triunsuitable
    A: bool = False  # regional attributes
    c: bool = False  # enclose the convex hull with segments
    D: bool = False  # conforming Delaunay (diametral circles)
    j: bool = False  # jettison unused vertices
    e: bool = False  # edges output
    v: bool = False  # Voronoi output
    n: bool = False  # neighbours output
    g: bool = False  # .off output
    B: bool = False  # no boundary markers
    P: bool = False  # no .poly output
    N: bool = False  # no .node output
    E: bool = False  # no .ele output
    I: bool = False  # no iteration numbers
    O: bool = False  # ignore holes
    X: bool = False  # no exact arithmetic
    z: bool = False  # number from zero
    order: int = 1  # o2: second-order triangles
    Y: int = 0  # no Steiner points on boundary (1) or any (2) segment
    S: int = -1  # Steiner point budget, -1 = unlimited
    i: bool = False  # incremental Delaunay
    F: bool = False  # sweepline Delaunay
    l: bool = False  # vertical cuts only
    s: bool = False  # conforming segment recovery by splitting
    C: bool = False  # check the final mesh
    Q: bool = False  # quiet
    V: int = 0  # verbosity
    h: bool = False  # help
    w: bool = False  # weighted (accepted, ignored)
    W: bool = False

    @property
    def quality(self) -> bool:
        """Triangle's "quality" flag: the refinement stage runs."""
        return self.q or self.max_area > 0 or self.var_area or self.u or self.D

    @property
    def uses_segments(self) -> bool:
        return self.p or self.r or self.quality or self.c

    @property
    def good_angle(self) -> float:
        """cos^2 of the minimum angle (Triangle's goodangle)."""
        c = math.cos(math.radians(self.min_angle))
        return c * c

    @property
    def off_constant(self) -> float:
        """Distance of the off-center from the shortest edge, over its length."""
        c = math.cos(math.radians(self.min_angle))
        if c == 1.0:
            return 0.0
        return 0.475 * math.sqrt((1.0 + c) / (1.0 - c))


def _read_float(s: str, i: int) -> tuple[float | None, int]:
    """Read Triangle's ``[0-9.]`` run after a switch, plus an optional exponent."""
    run = _NUMBER.match(s, i).group()
    if not run:
        return None, i
    end = i + len(run)
    prefix = _FLOAT_PREFIX.match(run).group()
    value = float(prefix) if prefix.strip(".") else 0.0
    if prefix == run:
        exp = _EXPONENT.match(s, end)
        if exp and prefix.strip("."):
            value = float(prefix + exp.group())
            end = exp.end()
    return value, end


def parse(opts: str, *, library: bool = True) -> Options:
    """Parse a switch string.  ``library`` mode scans from the first character
    (the Python API); the command line strips one leading dash per argument.
    ``Options`` is immutable, so a string seen before is parsed once."""
    return _parse(opts) if isinstance(opts, str) else _parse.__wrapped__(opts)


@functools.lru_cache(maxsize=256)
def _parse(s: str) -> Options:
    f: dict = {}  # the switches seen, as Options' fields
    i = 0
    while i < len(s):
        ch = s[i]
        i += 1
        start = i  # where a switch's number starts
        if ch == "q":
            f["q"] = True
            value, i = _read_float(s, i)
            if value is not None and not math.isfinite(value):
                raise SwitchError(f"Minimum angle {s[start:i]} is out of range (it overflows a double).")
            f["min_angle"] = 20.0 if value is None else value
        elif ch == "a":
            value, i = _read_float(s, i)
            if value is None:
                f["var_area"] = True
            else:
                if not value > 0.0:
                    raise SwitchError("Maximum area must be greater than zero.")
                if not math.isfinite(value):
                    raise SwitchError(f"Maximum area {s[start:i]} is out of range (it overflows a double).")
                f["max_area"] = value
        elif ch == "S":
            digits = re.match(r"[0-9]*", s[i:]).group()
            f["S"] = int(digits) if digits else 0
            i += len(digits)
        elif ch == "o":
            if i < len(s) and s[i] == "2":
                f["order"] = 2
                i += 1
        elif ch == "Y":
            f["Y"] = f.get("Y", 0) + 1
        elif ch == "V":
            f["V"] = f.get("V", 0) + 1
        elif ch in "hH?":
            f["h"] = True
        elif ch == "L":
            f["D"] = True
        elif ch in "prucADjevngBPNEIOXziFlsCQwW":
            f[ch] = True
    if not f.get("r") and not f.get("p"):
        f["var_area"] = False  # variable areas need regions or an .area file
    if f.get("r") or not f.get("p"):
        f["A"] = False
    return Options(**f)
