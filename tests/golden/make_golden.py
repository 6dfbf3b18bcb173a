"""Record (or check) the engine's output, bit for bit, over a fixed grid of
inputs x switches x strategies: ``golden.json`` maps each case to a SHA-256
of every output array (dtype, shape, bytes), the work counters and the trace.

    python tests/golden/make_golden.py            # rewrite golden.json
    python tests/golden/make_golden.py --check    # compare, list what differs

Each input's cases run in a child process, so a case that crashes the
interpreter is recorded as ``crash`` instead of ending the run.  Cases
whose result is an exception record the exception's type.  The grid reads
the `triangle` package's sample files (Triangle's own, which this repository
does not ship), this repository's ``data/`` (ruppert's own inputs) and the
shared corpus beside the checkout when it is there, or where
``RUPPERT_CORPUS`` says.  Cases whose input is missing are skipped by the
test; here ``--check`` names how many were not run and exits 2, and a
rewrite refuses (it would drop them): a helper's worktree has no corpus
beside it, and a check there once passed 224 cases unseen.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import subprocess
import os
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
CORPUS = Path(os.environ.get("RUPPERT_CORPUS") or REPO.parent / "shared" / "corpus")
GOLDEN = HERE / "golden.json"

POINT_SWITCHES = ["", "c", "i", "l", "en", "cq30", "q20", "jq30"]
PSLG_SWITCHES = ["p", "pc", "pA", "pn", "pq30", "pq20", "pq30D", "pq33", "pq30Y", "pq30YY", "pq30S40", "pq20i", "pq30a{area}"]
MESH_SWITCHES = ["r", "rq30", "rpq30", "rq25a0.01"]
STRATEGIES = ["triangle", "worst-angle", "fifo", "lifo", "random", "largest", "smallest", "adversary"]


def _package_data() -> Path:
    import triangle

    return Path(triangle.__file__).parent / "data"


def inputs() -> dict[str, Path]:
    """Input name -> base path (without extension) or file."""
    pkg = _package_data()
    out = {}
    for f in sorted(pkg.iterdir()):
        if f.suffix == ".poly" and not f.name.endswith(".1.poly") and f.stem.count(".") == 0:
            out[f"pkg:{f.stem}.poly"] = f
        if f.suffix == ".node" and f.stem.count(".") == 0 and not (pkg / f"{f.stem}.poly").exists() and f.stem != "greenland":
            out[f"pkg:{f.stem}.node"] = f
        if f.suffix == ".ele" and f.stem in ("A.1", "box.2", "double_hex2.1", "la.1", "face.1", "spiral.1", "ell"):
            out[f"pkg:{f.stem}.ele"] = f
    for f in sorted((REPO / "data").iterdir()):
        if f.suffix in (".poly", ".node"):
            out[f"data:{f.name}"] = f
    if CORPUS.is_dir():
        for f in sorted(CORPUS.iterdir()):
            if f.suffix in (".poly", ".node") and "guitar" not in f.name and "ttimeu10000" not in f.name:
                out[f"corpus:{f.name}"] = f
    return out


def cases_for(name: str, path: Path) -> list[tuple[str, str, str]]:
    """(switches, strategy, steiner) for one input."""
    if path.suffix == ".node":
        return [(s, "triangle", "offcenter") for s in POINT_SWITCHES]
    if path.suffix == ".ele":
        return [(s, "triangle", "offcenter") for s in MESH_SWITCHES]
    out = [(s, "triangle", "offcenter") for s in PSLG_SWITCHES]
    if any(k in name for k in ("A.poly", "la.poly", "face.poly", "quadratic-100")):
        out += [("pq30", s, "offcenter") for s in STRATEGIES[1:]]
        out += [("pq25", "triangle", "circumcenter"), ("pq30", "worst-angle", "circumcenter")]
    return out


def digest(result) -> dict:
    h = {}
    for key in sorted(result):
        a = np.ascontiguousarray(result[key])
        h[key] = hashlib.sha256(f"{a.dtype.str}{a.shape}".encode() + a.tobytes()).hexdigest()[:16]
    h["work"] = hashlib.sha256(json.dumps(result.work, sort_keys=True).encode()).hexdigest()[:16]
    if result.trace is not None:
        t = np.asarray(result.trace)
        h["trace"] = hashlib.sha256(t.tobytes()).hexdigest()[:16]
    return h


def _read(path: Path) -> dict:
    import ruppert_io

    d = ruppert_io.read(path)
    if path.suffix == ".ele":
        poly = path.with_suffix(".poly")
        if poly.exists():
            p = ruppert_io.read(poly)
            for k in ("segments", "segment_markers", "holes"):
                if k in p and len(p[k]):
                    d[k] = p[k]
    from instrument.pipeline import INPUT_KEYS

    return {k: v for k, v in d.items() if k in INPUT_KEYS and v is not None and np.size(v)}


def run_input(args) -> dict:
    """All cases of one input, in this (child) process."""
    name, path = args
    import instrument

    try:
        d = _read(Path(path))
    except ValueError as exc:  # FormatError: an input the reader rejects is not a case
        return {f"{name} | unreadable": {"error": type(exc).__name__}}
    span = np.ptp(d["vertices"], axis=0)
    area = f"{float(span[0] * span[1]) / 300:.3g}"  # a bound that makes a few hundred triangles
    out = {}
    for switches, strategy, steiner in cases_for(name, Path(path)):
        key = f"{name} | {switches} | {strategy} | {steiner}"
        trace = switches == "pq30" and strategy == "triangle"
        try:
            r = instrument.triangulate(d, switches.format(area=area) + "Q", strategy=strategy, steiner=steiner, trace=trace)
            out[key] = digest(r)
        except Exception as exc:  # recorded, not raised: the outcome is part of today's behaviour
            out[key] = {"error": type(exc).__name__}
    return out


def run_all(verbose: bool = False) -> dict:
    out = {}
    for name, path in sorted(inputs().items()):
        try:
            child = subprocess.run(
                [sys.executable, __file__, "--one", name, str(path)], capture_output=True, text=True, timeout=300
            )
            got = json.loads(child.stdout) if child.returncode == 0 else None
        except subprocess.TimeoutExpired:
            got = None
        if got is None:
            got = {f"{name} | {s} | {g} | {st}": {"error": "crash"} for s, g, st in cases_for(name, path)}
        if verbose:
            print(name, sum("error" not in v for v in got.values()), "of", len(got), file=sys.stderr)
        out.update(got)
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="compare with golden.json instead of rewriting it")
    ap.add_argument("--one", nargs=2, metavar=("NAME", "PATH"), help=argparse.SUPPRESS)
    ap.add_argument("-v", action="store_true", help="say how each input went")
    a = ap.parse_args()
    if a.one:
        print(json.dumps(run_input(tuple(a.one))))
        return 0
    now = run_all(a.v)
    old = json.loads(GOLDEN.read_text()) if GOLDEN.exists() else {}
    # a case whose input is missing here (the corpus is not beside this
    # checkout) was not run: a check would pass it unseen, and a rewrite drop it
    missing = sorted(k for k in old if k not in now)
    where = f"their input is missing: is the corpus at {CORPUS}? set RUPPERT_CORPUS"
    if not a.check:
        if missing:
            print(f"not written: {len(missing)} of {len(old)} cases were not run ({where})")
            return 2
        GOLDEN.write_text(json.dumps(now, indent=1, sort_keys=True) + "\n")
        print(f"{len(now)} cases written to {GOLDEN}")
        return 0
    bad = [k for k in old if k in now and old[k] != now[k]]
    for k in bad:
        diff = sorted(f for f in set(old[k]) | set(now[k]) if old[k].get(f) != now[k].get(f))
        print(f"DIFFERS {k}: {', '.join(diff)}")
    print(f"{len(bad)} of {len(old)} cases differ")
    if missing:
        print(f"{len(missing)} of {len(old)} cases not run ({where})")
        return 2
    return 1 if bad else 0


if __name__ == "__main__":
    sys.path.insert(0, str(REPO))
    os.environ.setdefault("PYTHONHASHSEED", "0")
    raise SystemExit(main())
