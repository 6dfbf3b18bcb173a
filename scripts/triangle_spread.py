#!/usr/bin/env python
"""How far Triangle's own mesh size moves when the input is only re-expressed.

Triangle's refinement serves bad triangles in an order that depends on
incidental things: which of two equal keys was queued first, the orientation
of a triangle record, the slot a freed record is reused from.  Mirroring the
input (x -> -x), swapping the axes, or reversing the segment list changes none
of the geometry, and every coordinate stays exact, yet it changes those
incidentals.  This script meshes each input and its re-expressions with
Triangle (the `triangle` package) and reports the vertex counts, flagging the
ones more than 2% (or 3 vertices) away from the original: the spread that any
mesher not replaying Triangle byte for byte must expect.

    python scripts/triangle_spread.py                      # samples and corpus, pq30
    python scripts/triangle_spread.py --switches pq20 A.poly
    python scripts/triangle_spread.py --markdown docs/compare/triangle-spread.md
    python scripts/triangle_spread.py --all --ours --switches pq33    # and ours against the size rule
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import triangle  # noqa: E402

import ruppert_io  # noqa: E402
from tests.differential.reexpress import KINDS, transformed  # noqa: E402

DEFAULT_CORPUS = ROOT.parent / "shared" / "corpus"
TRANSFORMS = ("mirror", "swap-xy", "reverse-segments")


def default_inputs(corpus: Path) -> list[Path]:
    data = Path(triangle.__file__).parent / "data"
    samples = sorted(p for p in data.glob("*.poly"))
    extra = sorted(corpus.glob("*.poly")) if corpus.is_dir() else []
    return samples + extra


def off(n: int, ref: int) -> bool:
    return abs(n - ref) > max(3, 0.02 * ref)


def spread(path: Path, switches: str, kinds=TRANSFORMS, ours: bool = False) -> dict | None:
    """Vertex counts of Triangle's meshes of ``path`` and its re-expressions,
    or None if Triangle makes no mesh of it.  ``ours``: also our count, the
    size rule's bound (Triangle's largest count + 1 % or 2 vertices) and the
    exact checker's verdict on our mesh (the angle of ``q``, the area of
    ``a``, the input as PSLG)."""
    try:
        tri = {k: v for k, v in ruppert_io.read(path).items() if np.size(v)}
    except ruppert_io.FormatError:
        return None
    opts = switches if "regions" in tri else switches.replace("A", "")
    base = triangle.triangulate(tri, opts)
    if "triangles" not in base:
        return None
    row = {"input": path.name, "switches": opts, "original": len(base["vertices"])}
    for kind in kinds:
        row[kind] = len(triangle.triangulate(transformed(tri, kind), opts)["vertices"])
    if ours:
        import instrument
        from instrument.check import check_mesh
        from instrument.switches import parse

        o = parse(opts)
        mesh = instrument.triangulate(tri, opts)
        most = max(row[k] for k in ("original", *kinds))
        row["ours"] = len(mesh["vertices"])
        row["bound"] = most + max(2.0, 0.01 * most)
        # the angle bound where Triangle meets it (under -Y/-YY, or above
        # about 34 degrees, it need not: its unsplit boundary keeps small angles)
        angle = o.min_angle if o.q else None
        if angle is not None and any("minimum angle" in p for p in check_mesh(base, None, min_angle=angle)):
            angle = None
        row["valid"] = not check_mesh(mesh, tri if o.p else None, min_angle=angle,
                                      max_area=o.max_area if o.max_area > 0 else None)
    return row


def markdown(rows: list[dict], switches: str, kinds=TRANSFORMS) -> str:
    lines = [
        f"Triangle's vertex count under `{switches}` for each input and its exact re-expressions "
        "(`*`: more than 2% or 3 vertices from the original).",
        "",
        "| input | original | " + " | ".join(kinds) + " |",
        "|---|---:|" + "---:|" * len(kinds),
    ]
    ours = bool(rows) and "ours" in rows[0]
    if ours:
        lines[2] = lines[2].rstrip() + " ours | rule |"
        lines[3] = lines[3] + "---:|---|"
    for r in rows:
        cells = [f"{r[k]}{'*' if off(r[k], r['original']) else ''}" for k in kinds]
        if ours:
            verdict = ("within" if r["ours"] <= r["bound"] else "ABOVE") + ("" if r["valid"] else ", INVALID")
            cells += [str(r["ours"]), verdict]
        lines.append(f"| {r['input']} | {r['original']} | " + " | ".join(cells) + " |")
    counts = {k: sum(off(r[k], r["original"]) for r in rows) for k in kinds}
    changed = sum(any(off(r[k], r["original"]) for k in kinds) for r in rows)
    lines += [
        "",
        f"Inputs off by more than 2%: " + ", ".join(f"{k} {n}" for k, n in counts.items())
        + f"; under at least one re-expression: {changed} of {len(rows)}.",
    ]
    if ours:
        above = sum(r["ours"] > r["bound"] for r in rows)
        invalid = sum(not r["valid"] for r in rows)
        lines.append(f"Ours above the size rule (Triangle's largest count + 1 % or 2 vertices): {above} of "
                     f"{len(rows)}; failing the exact checker: {invalid}.")
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("inputs", nargs="*", type=Path, help="Triangle-format .poly files (default: samples and corpus)")
    ap.add_argument("--switches", default="pq30", help="Triangle switches (default pq30; A is dropped without regions)")
    ap.add_argument("--corpus", type=Path, default=DEFAULT_CORPUS)
    ap.add_argument("--markdown", type=Path, help="also write the table here")
    ap.add_argument("--all", action="store_true", help=f"every re-expression ({', '.join(KINDS)})")
    ap.add_argument("--ours", action="store_true",
                    help="also mesh with ruppert and judge it by the size rule and the exact checker")
    args = ap.parse_args(argv)
    kinds = KINDS if args.all else TRANSFORMS
    rows = [r for p in (args.inputs or default_inputs(args.corpus))
            if (r := spread(p, args.switches, kinds, ours=args.ours))]
    text = markdown(rows, args.switches, kinds)
    print(text, end="")
    if args.markdown:
        args.markdown.parent.mkdir(parents=True, exist_ok=True)
        args.markdown.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
