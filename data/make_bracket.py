"""Writes data/bracket.poly: an L-shaped bracket with a fillet and two bolt holes (ruppert's own sample)."""
import math
pts, segs, marks = [], [], []
def add_loop(points, marker):
    start = len(pts)
    for p in points:
        pts.append(p)
    n = len(points)
    for i in range(n):
        segs.append((start + i, start + (i + 1) % n)); marks.append(marker)
outer = [(0, 0), (7, 0), (7, 1.5), (2.5, 1.5)]
# the inner fillet: a quarter circle about (2.5, 2.5), radius 1, from (2.5, 1.5) to (1.5, 2.5)
for k in range(1, 8):
    a = -math.pi / 2 - k * (math.pi / 2) / 8
    outer.append((2.5 + math.cos(a), 2.5 + math.sin(a)))
outer += [(1.5, 2.5), (1.5, 5), (0, 5)]
add_loop(outer, 1)
holes = []
for cx, cy in ((5.5, 0.75), (0.75, 4.0)):
    add_loop([(cx + 0.4 * math.cos(2 * math.pi * k / 12), cy + 0.4 * math.sin(2 * math.pi * k / 12)) for k in range(12)], 2)
    holes.append((cx, cy))
lines = ["# bracket.poly: an L-shaped bracket with a fillet and two bolt holes (ruppert's own sample, public domain)",
         f"{len(pts)} 2 0 1"]
lines += [f"{i + 1} {x:.17g} {y:.17g} {m}" for i, ((x, y), m) in enumerate(zip(pts, [1] * len(outer) + [2] * 24))]
lines += [f"{len(segs)} 1"] + [f"{i + 1} {a + 1} {b + 1} {m}" for i, ((a, b), m) in enumerate(zip(segs, marks))]
lines += [f"{len(holes)}"] + [f"{i + 1} {x} {y}" for i, (x, y) in enumerate(holes)]
lines += ["1", "1 3.5 0.75 10 0.02"]
open(__import__("pathlib").Path(__file__).with_name("bracket.poly"), "w").write("\n".join(lines) + "\n")
