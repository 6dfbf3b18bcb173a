#!/usr/bin/env python
"""Which of Triangle's triangle splits were of triangles that were not bad.

Triangle checks a queued bad-triangle record against its triangle by
pointers: the triangle record and its three vertices.  A vertex that is
rejected (it encroached a subsegment) has already had the bad triangles of
its star queued; its memory goes back to the pool and the next vertex (the
split point of that subsegment) takes it.  If a queued record's triangle
record then holds the same three vertex pointers again, the record matches
and Triangle splits a triangle that may meet the angle bound.

This script reads Triangle's ``-VV`` log (the `triangle` package, run in a
child process whose standard output is the log), replays its vertex pool
(LIFO reuse of freed slots: rejected, deleted and violating vertices), and
for every split triangle whose smallest angle is above the bound says
whether one of its vertices sits in a slot a rejected or deleted vertex
left (and, for comparison, how often that holds for the bad triangles split):

    python scripts/triangle_revivals.py                    # la.poly, pq30
    python scripts/triangle_revivals.py path/to/y.poly --switches pq30
"""

from __future__ import annotations

import argparse
import math
import re
import subprocess
import sys
from pathlib import Path

import triangle

ROOT = Path(__file__).resolve().parents[1]
POINT = re.compile(r"\(([-+\d.eE]+), ([-+\d.eE]+)\)")

# the child: Triangle's log goes to its standard output
CHILD = (
    "import sys, triangle, ruppert_io\n"
    "d = ruppert_io.read(sys.argv[1])\n"
    "d = {k: v for k, v in d.items() if not (hasattr(v, 'size') and v.size == 0)}\n"
    "triangle.triangulate(d, sys.argv[2])\n"
)


def triangle_log(path: Path, switches: str) -> list[str]:
    out = subprocess.run(
        [sys.executable, "-c", CHILD, str(path), switches + "VV"],
        capture_output=True,
        text=True,
        check=True,
        cwd=ROOT,
    )
    return out.stdout.splitlines()


def smallest_angle(corners: list[tuple[float, float]]) -> float:
    angles = []
    for k in range(3):
        (ax, ay), (bx, by), (cx, cy) = (
            corners[k],
            corners[(k + 1) % 3],
            corners[(k + 2) % 3],
        )
        ux, uy, vx, vy = bx - ax, by - ay, cx - ax, cy - ay
        cos = (ux * vx + uy * vy) / math.hypot(ux, uy) / math.hypot(vx, vy)
        angles.append(math.degrees(math.acos(max(-1.0, min(1.0, cos)))))
    return min(angles)


class VertexPool:
    """Triangle's vertex pool as its log shows it, keyed by printed coordinates
    (input vertices are never freed, so only new ones need slots)."""

    def __init__(self) -> None:
        self.slot: dict[str, int] = {}
        self.free: list[int] = []
        self.fresh = 0
        self.freed_by: dict[int, str] = {}  # slot -> how its last occupant left

    def take(self, point: str) -> None:
        self.slot[point] = self.free.pop() if self.free else self._fresh()

    def _fresh(self) -> int:
        self.fresh += 1
        return self.fresh - 1

    def give_back(self, point: str, why: str) -> None:
        s = self.slot.pop(point)
        self.free.append(s)
        self.freed_by[s] = why


def analyse(
    lines: list[str], theta: float
) -> tuple[int, int, list[tuple[int, float, list[str]]]]:
    """(triangle splits, how many of those of bad triangles have a vertex in
    a slot a rejected vertex left, [(split number, smallest angle, how the
    reused slots among its vertices were freed)] for the splits of good
    triangles)."""
    pool = VertexPool()
    pending = None  # a circumcenter inserted, not yet known to stay
    splitting_triangle = False
    splits = 0
    bad_reused = 0
    good = []
    for i, line in enumerate(lines):
        if line.startswith("  Splitting this triangle"):
            pending = None  # the previous circumcenter stayed
            splitting_triangle = True
            splits += 1
            text = POINT.findall(lines[i + 1])
            corners = [(float(x), float(y)) for x, y in text]
            angle = smallest_angle(corners)
            reused = [
                pool.freed_by[pool.slot[f"{x},{y}"]]
                for x, y in text
                if pool.slot.get(f"{x},{y}") in pool.freed_by
            ]
            if angle > theta + 0.01:  # the log rounds coordinates
                good.append((splits, angle, reused))
            elif "rejected" in reused:
                bad_reused += 1
        elif line.startswith("  Splitting subsegment"):
            if pending is not None:  # walked into a subsegment: freed without a word
                pool.give_back(pending, "violating")
            pending = None
            splitting_triangle = False
        elif line.startswith("  Inserting"):
            x, y = POINT.findall(line)[0]
            pool.take(f"{x},{y}")
            pending = f"{x},{y}" if splitting_triangle else None
        elif line.startswith("  Rejecting"):
            x, y = POINT.findall(line)[0]
            pool.give_back(f"{x},{y}", "rejected")
            pending = None
        elif line.startswith("  Deleting ("):
            x, y = POINT.findall(line)[0]
            pool.give_back(f"{x},{y}", "deleted")
    return splits, bad_reused, good


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument(
        "input",
        nargs="?",
        default=str(Path(triangle.__file__).parent / "data" / "la.poly"),
    )
    ap.add_argument("--switches", default="pq30")
    args = ap.parse_args(argv)
    m = re.search(r"q([\d.]*)", args.switches)
    theta = float(m.group(1) or 20) if m else 0.0
    splits, bad_reused, good = analyse(
        triangle_log(Path(args.input), args.switches), theta
    )
    print(
        f"{Path(args.input).name} -{args.switches}: {splits} triangle splits, {len(good)} of triangles "
        f"whose smallest angle is above {theta:g} degrees"
    )
    for n, angle, reused in good:
        where = ", ".join(reused) if reused else "none"
        print(
            f"  split {n}: smallest angle {angle:.2f}; vertices in slots freed by: {where}"
        )
    explained = sum(1 for _, _, reused in good if "rejected" in reused)
    print(
        f"{explained} of {len(good)} have a vertex in a slot a rejected vertex left; of the "
        f"{splits - len(good)} splits of bad triangles, {bad_reused} do"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
