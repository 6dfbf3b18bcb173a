#!/usr/bin/env python
"""Where ours' refinement parts from Triangle's: the bad triangles each queues and splits.

Triangle (the `triangle` package) prints its queue events under -VVV
("Queueing bad triangle:", "Splitting this triangle at its circumcenter:",
"Inserting (x, y).", "Rejecting ...", "Splitting subsegment ..."); this
script runs it in a subprocess and parses them.  Ours has no such output,
so ours runs uncompiled (RUPPERT_PURE_PYTHON=1, in a subprocess too) with
the refinement kernels' module-level calls wrapped to record the same
events: every triangle queued (as the org, dest, apex of the handle it is
queued with) and every triangle split.  The first split that differs,
and where each side queued the two triangles concerned, locate the step
where the two refinements part.

    python scripts/queue_trace.py tests/differential/regressions/q34-fifo-order-size.json
    python scripts/queue_trace.py --poly A.poly --switches pq30

Coordinates are compared as Triangle prints them (%.12g).  Slow: ours runs
uncompiled (seconds per thousand insertions).
"""

from __future__ import annotations

import argparse
import os
import pickle
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

_TRIANGLE = """
import pickle, sys, triangle
inp, sw = pickle.load(open(sys.argv[1], 'rb'))
triangle.triangulate(inp, sw + 'VVV')
"""

_OURS = """
import os, pickle, sys
os.environ['RUPPERT_PURE_PYTHON'] = '1'
import instrument
import instrument.refine as driver
from instrument.refine import criteria, splits
from instrument.core.mesh import lnext, lprev
from instrument.core.status import NEED_ROOM

events, current = [], [None]

def g(m, v):
    return '(%.12g, %.12g)' % (m.xy[v, 0], m.xy[v, 1])

def wrap_push(push):
    def queued(r, key, t, stamp):  # handle 3 t: org, dest, apex are corners 1, 2, 0
        m = current[0]
        events.append(('Q', ' '.join(g(m, m.corner[3 * t + k]) for k in (1, 2, 0))))
        return push(r, key, t, stamp)
    return queued

def wrap_refine(refine):
    def refining(r, m, segs):
        current[0] = m
        return refine(r, m, segs)
    return refining

def wrap_split(split):
    def splitting(r, m, segs, h):
        what = ' '.join(g(m, m.corner[x]) for x in (lnext(h), lprev(h), h))
        at = len(events)
        events.append(('S', what))  # before the triangles its insertion queues, as Triangle prints it
        status = split(r, m, segs, h)
        if status == NEED_ROOM:  # a step that ran out of room changed nothing and runs again
            del events[at:]
        return status
    return splitting

def wrap_ghost(push):
    def queued(r, key, org, dest, v, *record):  # a rejected point's fan triangle (v: the point, until it is rejected)
        m = current[0]
        events.append(('Q', ' '.join(g(m, x) for x in (org, dest, v))))
        return push(r, key, org, dest, v, *record)
    return queued

criteria.queue_push = wrap_push(criteria.queue_push)
criteria.queue_push_ghost = wrap_ghost(criteria.queue_push_ghost)
splits.split_bad_triangle = wrap_split(splits.split_bad_triangle)
driver.refine = wrap_refine(splits.refine)
inp, sw = pickle.load(open(sys.argv[1], 'rb'))
instrument.triangulate(inp, sw)
pickle.dump(events, open(sys.argv[2], 'wb'))
"""


def triangle_events(inp: dict, switches: str, timeout: float = 600) -> list[tuple[str, str]]:
    """Triangle's queue events: ('Q', triangle) queued, ('S', triangle) split,
    ('I', point) insertion attempted, ('R', line) rejected, ('G', line)
    subsegment split; a triangle is "(org) (dest) (apex)" of its handle."""
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "in.pkl"
        path.write_bytes(pickle.dumps((inp, switches)))
        out = subprocess.run([sys.executable, "-c", _TRIANGLE, str(path)], capture_output=True, text=True,
                             timeout=timeout).stdout
    lines = out.splitlines()
    events = []
    for i, line in enumerate(lines):
        if line.startswith("  Queueing bad triangle:"):
            events.append(("Q", lines[i + 1].strip()))
        elif line.startswith("  Splitting this triangle at"):
            events.append(("S", lines[i + 1].strip()))
        elif line.startswith("  Inserting ("):
            events.append(("I", line.strip()))
        elif line.startswith("  Rejecting"):
            events.append(("R", line.strip()))
        elif line.startswith("  Splitting subsegment"):
            events.append(("G", line.strip()))
    return events


def ours_events(inp: dict, switches: str, timeout: float = 1800) -> list[tuple[str, str]]:
    """Ours' events: ('Q', triangle) queued, ('S', triangle) split."""
    with tempfile.TemporaryDirectory() as d:
        src, dst = Path(d) / "in.pkl", Path(d) / "out.pkl"
        src.write_bytes(pickle.dumps((inp, switches)))
        env = dict(os.environ, RUPPERT_PURE_PYTHON="1")
        subprocess.run([sys.executable, "-c", _OURS, str(src), str(dst)], check=True, timeout=timeout, env=env)
        return pickle.loads(dst.read_bytes())


def canonical(tri: str) -> str:
    """A triangle's three points from the smallest, keeping their cyclic order."""
    pts = re.findall(r"\([^)]*\)", tri)
    k = pts.index(min(pts))
    return " ".join(pts[k:] + pts[:k])


def first_parting(theirs: list, ours: list) -> int | None:
    """The index of the first split (among the 'S' events) whose triangle differs."""
    t = [e[1] for e in theirs if e[0] == "S"]
    o = [e[1] for e in ours if e[0] == "S"]
    for i, (a, b) in enumerate(zip(t, o)):
        if canonical(a) != canonical(b):
            return i
    return None if len(t) == len(o) else min(len(t), len(o))


def report(inp: dict, switches: str) -> str:
    theirs, ours = triangle_events(inp, switches), ours_events(inp, switches)
    t_splits = [e[1] for e in theirs if e[0] == "S"]
    o_splits = [e[1] for e in ours if e[0] == "S"]
    lines = [f"splits: Triangle {len(t_splits)}, ours {len(o_splits)}"]
    i = first_parting(theirs, ours)
    if i is None:
        return "\n".join(lines + ["the same triangles are split in the same order"])
    lines.append(f"first split that differs: number {i}")
    if i < len(t_splits) and i < len(o_splits):
        lines += [f"  Triangle splits {t_splits[i]}", f"  ours splits     {o_splits[i]}"]
        wanted = {canonical(t_splits[i]): "Triangle's", canonical(o_splits[i]): "ours'"}
        for name, events in (("Triangle", theirs), ("ours", ours)):
            for j, (kind, what) in enumerate(events):
                if kind in "QS" and canonical(what) in wanted:
                    lines.append(f"  {name} event {j}: {'queued' if kind == 'Q' else 'split'} {wanted[canonical(what)]} "
                                 f"choice as {what}")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("case", nargs="?", type=Path, help="a differential case file (tests/differential/regressions/*.json)")
    ap.add_argument("--poly", type=Path, help="a Triangle-format input file instead")
    ap.add_argument("--switches", help="the switches (default: the case's, without Q)")
    args = ap.parse_args(argv)
    if args.poly:
        import ruppert_io

        inp = {k: v for k, v in ruppert_io.read(args.poly).items() if len(v)}
        switches = args.switches or "pq30"
    elif args.case:
        sys.path.insert(0, str(ROOT))
        from tests.differential.cases import read_case

        case, _ = read_case(args.case)
        if case.premesh:
            sys.exit("an r case made from a premesh: write its materialized input first (promote does)")
        inp, switches = case.input, args.switches or case.switches.replace("Q", "")
    else:
        ap.error("give a case file or --poly")
    print(report(inp, switches))
    return 0


if __name__ == "__main__":
    sys.exit(main())
