"""What the study runs on: files, folders, the `triangle` package's samples, and generated families.

An ``Input`` names one PSLG: a Triangle-format file (read with
``ruppert_io.read``), a member of a generated family (``quadratic``: Barbič and
Miller's I(n) at angle alpha, ``instrument.quadratic.example``), or a dict
given from Python.  Its ``digest`` (SHA-256 of the file's bytes, of the
family's parameters, or of the arrays) is part of a sweep row's key, so an
edited file is measured again.

Command-line spellings (``parse_input``): a file, a folder (its ``.poly``,
``.node``, ``.ele`` and ``.area`` files), ``samples`` (the `triangle`
package's sample PSLGs), or a family such as ``quadratic:n=100,200:alpha=20,30``.

A family may measure its outputs: for I(n), ``script_points`` counts the
scripted points P_1 .. P_s of Theorem 3 that a mesh holds (all of them: the
mesher played the script).
"""

from __future__ import annotations

import hashlib
import itertools
import json
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

SUFFIXES = (".poly", ".node", ".ele", ".area")
FAMILIES = ("quadratic",)


@dataclass(frozen=True)
class Input:
    """One input of a sweep."""

    label: str  # shown in tables
    family: str  # "file", "data" or a generated family's name
    source: str = ""  # the file's path, or the family's spec
    params: tuple = ()  # sorted (name, value) pairs of a generated input
    digest: str = ""
    data: dict | None = field(default=None, compare=False, hash=False, repr=False)

    @property
    def param_dict(self) -> dict:
        return dict(self.params)


def _sha(payload: bytes) -> str:
    return hashlib.sha256(payload).hexdigest()[:16]


def data_digest(data: Mapping) -> str:
    """A digest of a PSLG dict's arrays (key order does not matter)."""
    h = hashlib.sha256()
    for k in sorted(data):
        v = data[k]
        if v is None:
            continue
        a = np.ascontiguousarray(v)
        h.update(k.encode())
        h.update(str(a.dtype).encode() + str(a.shape).encode())
        h.update(a.tobytes())
    return h.hexdigest()[:16]


def file_input(path: Path, label: str | None = None) -> Input:
    path = Path(path)
    try:
        digest = _sha(path.read_bytes())
    except OSError:
        digest = ""
    return Input(label or path.name, "file", str(path), (), digest)


def family_input(family: str, **params) -> Input:
    if family not in FAMILIES:
        raise ValueError(f"unknown family {family!r}; choose from {', '.join(FAMILIES)}")
    if family == "quadratic":
        n, alpha = int(params["n"]), float(params.get("alpha", 20.0))
        params = {"n": n, "alpha": alpha}
        label = f"I(n={n},alpha={alpha:g})"
    pairs = tuple(sorted(params.items()))
    spec = json.dumps([family, pairs])
    return Input(label, family, spec, pairs, _sha(spec.encode()))


def data_input(label: str, data: Mapping) -> Input:
    """An input given as a dict (the `triangle` package's keys)."""
    return Input(label, "data", "", (), data_digest(data), dict(data))


def package_samples() -> list[Path]:
    """The `triangle` package's sample PSLGs (its data/*.poly inputs, not its outputs)."""
    try:
        import triangle
    except ImportError:
        return []
    data = Path(triangle.__file__).resolve().parent / "data"
    return sorted(p for p in data.glob("*.poly") if "." not in p.stem)


def folder_files(folder: Path) -> list[Path]:
    if not folder.is_dir():
        return []
    return sorted(p for p in folder.iterdir() if p.is_file() and p.suffix.lower() in SUFFIXES)


def _numbers(text: str, kind) -> list:
    return [kind(x) for x in text.split(",") if x.strip()]


def parse_input(text: str) -> list[Input]:
    """Inputs from one command-line word (see the module's docstring)."""
    if text == "samples":
        return [file_input(p, f"triangle/{p.name}") for p in package_samples()]
    head, _, rest = text.partition(":")
    if head in FAMILIES and rest:
        grid: dict[str, list] = {}
        for part in rest.split(":"):
            name, eq, values = part.partition("=")
            if not eq:
                raise ValueError(f"{text!r}: expected name=v1,v2,... after {head}:")
            grid[name.strip()] = _numbers(values, int if name.strip() == "n" else float)
        if "n" not in grid:
            raise ValueError(f"{text!r}: the {head} family needs n=...")
        names = sorted(grid)
        return [family_input(head, **dict(zip(names, combo, strict=True)))
                for combo in itertools.product(*(grid[k] for k in names))]
    path = Path(text)
    if path.is_dir():
        return [file_input(p) for p in folder_files(path)]
    if path.exists():
        return [file_input(path)]
    raise ValueError(f"no such file, folder or family: {text!r}")


def parse_inputs(words: Iterable[str]) -> list[Input]:
    out: list[Input] = []
    for w in words:
        out.extend(parse_input(w))
    return out


def load(inp: Input) -> dict:
    """The PSLG of an input.  Raises ``ruppert_io.FormatError`` or ``OSError`` for a bad file."""
    if inp.family == "data":
        return dict(inp.data)
    if inp.family == "file":
        import ruppert_io

        return ruppert_io.read(inp.source)
    if inp.family == "quadratic":
        from instrument import quadratic

        p = inp.param_dict
        return quadratic.example(int(p["n"]), float(p["alpha"]))
    raise ValueError(f"unknown family {inp.family!r}")


def counts(data: Mapping) -> dict[str, int]:
    """Sizes of a PSLG: vertices, segments, holes, regions."""
    return {k: 0 if data.get(k) is None else len(data[k]) for k in ("vertices", "segments", "holes", "regions")}


def switches_for(template: str, inp: Input) -> str | None:
    """The switches for this input: ``{name}`` in ``template`` takes the input's
    parameter (``pq{alpha}``); None when the input has no such parameter."""
    if "{" not in template:
        return template
    try:
        return template.format(**{k: f"{v:g}" if isinstance(v, float) else v for k, v in inp.params})
    except (KeyError, IndexError):
        return None


def effective_switches(data: Mapping, switches: str) -> tuple[str, str]:
    """Drop ``p`` for a point set (no segments), as Triangle's command line
    meshes a .node file: with ``p`` every engine eats the whole triangulation.
    Returns (switches, note)."""
    segs = data.get("segments")
    if "p" in switches and (segs is None or len(segs) == 0) and "r" not in switches:
        return switches.replace("p", ""), "point set: p dropped"
    return switches, ""


# ---------------------------------------------------------------------------------------------
# what a family measures on an output


def script_points(vertices, n: int, alpha: float) -> int:
    """How many of the scripted points P_1 .. P_s (equation (9)) are vertices of
    a mesh, to 1e-9 of the spacing: all of them means the mesher played Theorem 3."""
    from instrument import quadratic

    p = quadratic.params(n, alpha)
    if p.steps == 0:
        return 0
    want = (2.0 * np.arange(1, p.steps + 1) * p.r + 1.0) / (2.0 * n)
    v = np.asarray(vertices, dtype=np.float64).reshape(-1, 2)
    xs = np.sort(v[np.abs(v[:, 1] - p.h) <= 1e-9 * p.h, 0])
    if xs.size == 0:
        return 0
    i = np.clip(np.searchsorted(xs, want), 1, max(1, xs.size - 1))
    gap = np.minimum(np.abs(xs[i - 1] - want), np.abs(xs[np.minimum(i, xs.size - 1)] - want))
    return int((gap <= 1e-9 / n).sum())


def metrics(family: str, params: Mapping, mesh: Mapping) -> dict[str, float]:
    """The family's own measures of an output mesh (none for files)."""
    if family == "quadratic" and mesh.get("vertices") is not None:
        n, alpha = int(params["n"]), float(params["alpha"])
        return {"script_points": float(script_points(mesh["vertices"], n, alpha)),
                "steiner_points": float(len(mesh["vertices"]) - (n + 12))}
    return {}
