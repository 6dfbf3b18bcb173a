"""Real-world inputs under the switch strings a finite-element user writes.

    python -m tests.differential.realworld --out /tmp/realworld

Every readable file of ``shared/corpus/`` and of the ``triangle`` package's
sample data, crossed with everyday switch strings (``pq30``, ``pq30a`` with an
area scaled to the input, ``pq30Aa`` with its regions, ``pqD``, ``pq30YY``,
``pq30S50``, ``pq30o2``, ``pc``, ``pq30i``, ``r`` refinement of Triangle's own
``-p`` mesh with per-triangle bounds, ...), each judged by the harness's
oracles against Triangle (both in worker processes, as in the campaign).
Failures are written as case files that ``promote`` keeps as regressions,
shrunk when ``--shrink`` is given.  The generated families draw small
synthetic inputs; these are the inputs people mesh.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

from .campaign import slug
from .cases import Case, write_case
from .families import bbox_area, decimal
from .harness import run_case
from .known import explaining
from .runners import Runners
from .shrink import shrink

ROOT = Path(__file__).resolve().parents[2]
CORPUS = Path("/work/shared/corpus")
#: whole-mesh inputs (.ele) are refined only: r switches
MESH_SWITCHES = ("r", "rq30", "rq30a", "ra{a}", "rq30a{a}", "rpq30a", "rD", "ru", "rq33", "rq30a{a2}")
#: {a} (1 %) and {a2} (0.1 %) are area bounds, fractions of the bounding-box area
PSLG_SWITCHES = (
    "p", "pq", "pq30", "pq33", "pq30a{a}", "pq30Aa", "pq30Aa{a}", "pA", "pqD", "pq30Y", "pq30YY", "pq30S50",
    "pq30o2", "pq30e", "pq30n", "pq30v", "pc", "pcq", "pq30i", "pq30F", "pq30l", "pq30u", "pq30ua{a}",
    "pq30j", "pq34", "pq20a{a}o2en", "pcq30a{a}", "pDa{a}", "pq25", "pq28.6", "pq32", "pq30a{a2}", "pqa", "pq30YYa{a}",
)
POINT_SWITCHES = ("", "q", "q30", "q30a{a}", "q30a{a2}", "D", "c", "cq30", "i", "F", "l", "v", "e", "n", "o2", "Y", "u",
                  "q33", "cq25a{a}")
#: r refinement of Triangle's own mesh: (premesh, switches, per-triangle area factors)
REFINE = (
    ("pQ", "rpq30aQ", (0.01, 0.002, -1.0)),
    ("pq30Q", "rpaQ", (0.005,)),
    ("pq30Q", "raQ", (0.02, 0.0, 0.002)),
    ("pQ", "rq30aQ", (0.01,)),
)


def sample_dir() -> Path:
    import triangle

    return Path(triangle.__file__).parent / "data"


def inputs() -> list[tuple[str, dict]]:
    """(name, input dict) of every file the readers accept."""
    from ruppert_io import read

    files = sorted(CORPUS.glob("*.poly")) + sorted(CORPUS.glob("*.node"))
    d = sample_dir()
    files += sorted(p for p in d.glob("*.poly") if p.name.count(".") == 1)
    files += sorted(p for p in d.glob("*.node") if p.name.count(".") == 1 and not (d / (p.stem + ".poly")).exists())
    out = []
    for path in files:
        try:
            tri = read(path)
        except Exception as exc:  # malformed on purpose (README.md of the corpus)
            print(f"skip {path.name}: {type(exc).__name__}: {str(exc)[:80]}", flush=True)
            continue
        if path.suffix == ".node" and (d / (path.stem + ".ele")).exists() and path.parent == d:
            tri = read(d / (path.stem + ".ele"))  # a whole mesh: refined with r
        # an empty hole or region list (a .poly with 0 holes) makes the triangle
        # package fail (IndexError: out of bounds on buffer access), so that
        # Triangle's answer would be no reference: leave such lists out
        tri = {k: np.asarray(v) for k, v in tri.items() if not (k in ("holes", "regions") and len(v) == 0)}
        out.append((f"{path.parent.name}/{path.name}", tri))
    return out


def area_for(tri: dict, frac: float = 0.01) -> str:
    return decimal(float(f"{bbox_area(tri) * frac:.3g}"))


def cases_for(name: str, tri: dict) -> list[Case]:
    a, a2 = area_for(tri), area_for(tri, 0.001)
    if "triangles" in tri:
        sws = MESH_SWITCHES
    elif "segments" in tri and len(tri["segments"]):
        sws = PSLG_SWITCHES
    else:
        sws = POINT_SWITCHES
    out = [Case(family="realworld", switches=sw.format(a=a, a2=a2) + "Q", input=tri, meta={"file": name}) for sw in sws]
    if "segments" in tri and "triangles" not in tri:
        for pre, sw, factors in REFINE:
            out.append(Case(family="realworld", switches=sw, input=tri, premesh=pre, area_factors=factors,
                            meta={"file": name}))
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", type=Path, default=Path("realworld-campaign"))
    ap.add_argument("--only", default="", help="substring of the file names to run")
    ap.add_argument("--shrink", type=float, default=0.0, help="seconds of shrinking per failure (0: none)")
    ap.add_argument("--ours-timeout", type=float, default=60.0)
    args = ap.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    runners = Runners(ours_timeout=args.ours_timeout)
    t0 = time.perf_counter()
    summary = {"cases": 0, "failures": [], "skipped": 0}
    try:
        for name, tri in inputs():
            if args.only not in name:
                continue
            for case in cases_for(name, tri):
                run = run_case(runners, case)
                summary["cases"] += 1
                if run is None:
                    summary["skipped"] += 1
                    continue
                if run.verdict.ok:
                    continue
                known = [explaining(run.case, f, run.verdict.notes) for f in run.verdict.failures]
                sigs = run.verdict.signatures()
                tag = slug(f"{Path(name).stem}-{case.switches}")
                line = {"file": name, "switches": case.switches, "premesh": case.premesh, "signatures": sigs,
                        "known": [d.id if d else None for d in known], "case": tag,
                        "failures": [f"{f.signature}: {f.message[:300]}" for f in run.verdict.failures]}
                summary["failures"].append(line)
                print(json.dumps(line), flush=True)
                kept = run.case
                if args.shrink > 0 and not all(known):
                    def fails(c, sigs=set(sigs)):
                        r = run_case(runners, c, confirmed={}, confirmations=0)
                        return r is not None and bool(sigs & set(r.verdict.signatures()))
                    kept, _ = shrink(run.case, fails, args.shrink)
                write_case(args.out / f"{tag}.json", kept, signature=sigs[0],
                           triangle=run.triangle.summary(), ours=run.ours.summary(),
                           failures=line["failures"])
            print(f"{name}: done, {summary['cases']} cases, {time.perf_counter() - t0:.0f} s", flush=True)
    finally:
        runners.close()
        summary["seconds"] = round(time.perf_counter() - t0, 1)
        (args.out / "summary.json").write_text(json.dumps(summary, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
