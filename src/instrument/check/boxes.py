"""Candidate pairs of overlapping bounding boxes or octagons: a packed tree.

The overlap and segment checks test exact predicates on pairs (triangle,
segment) or (point, segment) whose closed boxes meet; testing all pairs
would be quadratic.  The boxes of the larger side go into a tree of
bounding boxes packed bottom-up (groups of ``FAN`` consecutive boxes in a
sort order, then groups of ``FAN`` groups, ...), and the boxes of the other
side descend it together, level by level, in vectorised batches.  A pair is
reported once, and only if the closed boxes overlap: the descent compares
coordinates and nothing else (no arithmetic), so it is exact at any scale,
with subnormals and with infinite extents (a segment box widened by a
tolerance may reach +-inf).  Memory stays bounded: a batch whose next
expansion would exceed ``LIMIT`` pairs is split, and the pairs come out in
chunks (``overlapping``), which the checks test and drop one at a time.

Why this sort order.  A query costs as many node visits as there are nodes
whose box meets it, so the nodes' boxes must not be much larger than what
they hold.  Meshes graded over hundreds of decades are graded towards the
origin (near any other point p the doubles are no finer than 2^-52 |p|, so
a mesh can grade over at most ~16 decades there).  Around the origin every
ordering that only looks at coordinates in turn fails:

* the former multi-level grid put a triangle of size 2^L in a cell of that
  size, and the cell holding the origin held every finer triangle too:
  113 million candidates for the 600-decade mesh (18,842 boundary edges
  against 550,886 triangles, 102,932 true overlaps);
* sort-tile-recursive packing (strips of x, then y) and median kd-splits
  cut a quadrant graded towards its corner into L-shaped sets (both arms,
  along the x and along the y axis, at one range of scales), whose boxes
  contain the corner and so every finer query: STR expanded 211 million
  (edge, node) pairs at one level before memory ran out, median splits
  visit 22 million nodes;
* a Morton order of the doubles' bit patterns (a log scale) puts the two
  arms at one scale side by side: 461 leaves met by one edge near the
  origin, 109 million visits.

So the order is polar first: 16 angular sectors (the quadrant, and three
lines at 22.5, 45 and 67.5 degrees within it), then the binary exponent of
the centre's max-norm (a shell), and within a (sector, shell) class a
Morton order of the centres relative to the class's extent, refined in
the runs it leaves tied (a class spans at most ~52 binary levels of
grading, so two or three rounds of 31 bits suffice).  A sector's boxes do
not reach the origin unless they are that close to it; a run of the order
only straddles sectors 15 times per tree level.  On the 600-decade mesh the
boundary edges visit 3.5 million nodes and boxes (0.3 s), 34 per pair; on
10^5 random points under q30, 2,846 hull edges visit 259,154 (17 per
pair).  The order only affects the cost, never which pairs are found.

Boxes can be octagons (``octagons``: the ranges of x + y and x - y too,
rounded outward), for the segment-triangle join: a mesh whose triangles
span a graded corner from one axis to the other has boxes that all hold
the corner, true overlaps that no exact test needs (8 million under q10 on
the 600-decade input; 20,056 with octagons).  The point-segment join of
``chains`` keeps boxes (its segment boxes are widened by a tolerance, and
there are few segments).
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np

#: Children per node.  Measured on the 600-decade mesh and on 10^5 random
#: points: 4 and 8 are alike, 16 and more visit more nodes than they save.
FAN = 8
#: The most (query, node) pairs a batch expands into at once.
LIMIT = 1 << 16

_LARGEST = np.finfo(np.float64).max
_SECTOR_TANGENTS = (0.41421356237309503, 1.0, 2.414213562373095)  # tan 22.5, 45, 67.5 degrees
_ZERO_SHELL = -1100  # below the exponent of the smallest subnormal


def _centres(box: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Centres of the boxes, finite (only the order uses them)."""
    with np.errstate(all="ignore"):
        cx = 0.5 * box[:, 0] + 0.5 * box[:, 1]
        cy = 0.5 * box[:, 2] + 0.5 * box[:, 3]
    return (np.clip(np.nan_to_num(cx), -_LARGEST, _LARGEST),
            np.clip(np.nan_to_num(cy), -_LARGEST, _LARGEST))


def _spread(v: np.ndarray) -> np.ndarray:
    """The low 32 bits of v on the even bits of a 64-bit word."""
    v = v & np.uint64(0xFFFFFFFF)
    for shift, mask in ((16, 0x0000FFFF0000FFFF), (8, 0x00FF00FF00FF00FF), (4, 0x0F0F0F0F0F0F0F0F),
                        (2, 0x3333333333333333), (1, 0x5555555555555555)):
        v = (v | (v << np.uint64(shift))) & np.uint64(mask)
    return v


def _runs(*keys: np.ndarray) -> np.ndarray:
    """Start of every run of equal key tuples in sorted arrays."""
    n = len(keys[0])
    new = np.zeros(n, bool)
    new[0] = True
    for k in keys:
        new[1:] |= k[1:] != k[:-1]
    return np.flatnonzero(new)


def packing_order(box: np.ndarray, rounds: int = 3) -> np.ndarray:
    """The order in which the boxes are packed (see the module docstring)."""
    cx, cy = _centres(box)
    ax, ay = np.abs(cx), np.abs(cy)
    sector = (cx < 0) * 8 + (cy < 0) * 4
    with np.errstate(over="ignore"):  # t * ax may be inf: the comparison stays right
        for t in _SECTOR_TANGENTS:
            sector = sector + (ay > t * ax)
    norm = np.maximum(ax, ay)
    shell = np.where(norm > 0, np.frexp(norm)[1], _ZERO_SHELL)
    order = np.lexsort((shell, sector))
    starts = _runs(sector[order], shell[order])
    for _ in range(rounds):
        size = np.diff(np.append(starts, len(order)))
        if not len(size) or size.max() <= FAN:
            break
        group = np.repeat(np.arange(len(starts)), size)
        x, y = cx[order], cy[order]
        x0, y0 = np.minimum.reduceat(x, starts), np.minimum.reduceat(y, starts)
        with np.errstate(all="ignore"):
            half = np.maximum(0.5 * np.maximum.reduceat(x, starts) - 0.5 * x0,
                              0.5 * np.maximum.reduceat(y, starts) - 0.5 * y0)[group]
            u = np.where(half > 0, (0.5 * x - 0.5 * x0[group]) / half, 0.0)
            v = np.where(half > 0, (0.5 * y - 0.5 * y0[group]) / half, 0.0)
        top = 2.0**31 - 1
        u = np.clip(np.nan_to_num(u) * 2.0**31, 0, top).astype(np.uint64)
        v = np.clip(np.nan_to_num(v) * 2.0**31, 0, top).astype(np.uint64)
        code = (_spread(u) << np.uint64(1)) | _spread(v)
        sub = np.lexsort((code, group))
        order = order[sub]
        starts = _runs(group[sub], code[sub])
    return order


def octagons(points: np.ndarray) -> np.ndarray:
    """Bounding octagons of point sets (n, k, 2): rows xmin, xmax, ymin, ymax,
    then the ranges of x + y and of x - y, widened by one unit in the last
    place each way so that they hold the exact sums (round to nearest errs by
    half of one; an overflow gives inf, the right side).

    Boxes alone are too weak a filter for meshes whose triangles span a
    graded corner: under q10 the 600-decade input's mesh (4,024 triangles)
    has one or two triangles per scale with a vertex on each axis, (r, 0),
    (0, r), (r', 0), whose boxes all hold the origin, so its 4,014 boundary
    edges met 8 million boxes; their ranges of x + y, [r', r], do not reach
    the edges near the origin.
    """
    x, y = points[..., 0], points[..., 1]
    with np.errstate(over="ignore", invalid="ignore"):
        s, d = x + y, x - y
        return np.column_stack([
            x.min(1), x.max(1), y.min(1), y.max(1),
            np.nextafter(s.min(1), -np.inf), np.nextafter(s.max(1), np.inf),
            np.nextafter(d.min(1), -np.inf), np.nextafter(d.max(1), np.inf),
        ])


class BoxTree:
    """Boxes (rows xmin, xmax, ymin, ymax) or octagons (``octagons``) packed
    into a tree of bounding boxes (or octagons)."""

    def __init__(self, box: np.ndarray):
        self.items = packing_order(box)
        level = box[self.items]
        self.leaves = level
        self.levels = []  # from the leaves' parents up to the root: each node's box
        self.visits = 0  # (query, node or box) pairs compared so far: the cost of the queries
        while True:
            starts = np.arange(0, len(level), FAN)
            level = np.column_stack([
                (np.maximum if c % 2 else np.minimum).reduceat(level[:, c], starts) for c in range(level.shape[1])
            ])
            self.levels.append(level)
            if len(level) == 1:
                break

    def query(self, qbox: np.ndarray) -> Iterator[tuple[np.ndarray, np.ndarray]]:
        """Chunks of (query row, box row) whose closed boxes overlap, each pair once."""
        nq = len(qbox)
        top = len(self.levels) - 1
        stack = [(top, np.arange(nq), np.zeros(nq, np.int64))]
        while stack:
            lev, q, node = stack.pop()
            below = self.levels[lev - 1] if lev > 0 else self.leaves
            lo = node * FAN
            cnt = np.minimum(lo + FAN, len(below)) - lo
            tot = int(cnt.sum())
            if tot > LIMIT and len(q) > 1:
                half = len(q) // 2
                stack.append((lev, q[half:], node[half:]))
                stack.append((lev, q[:half], node[:half]))
                continue
            first = np.cumsum(cnt) - cnt
            child = np.arange(tot) - np.repeat(first - lo, cnt)
            q = np.repeat(q, cnt)
            self.visits += tot
            qb, cb = qbox[q], below[child]
            meet = (qb[:, 0] <= cb[:, 1]) & (cb[:, 0] <= qb[:, 1]) & (qb[:, 2] <= cb[:, 3]) & (cb[:, 2] <= qb[:, 3])
            for c in range(4, cb.shape[1], 2):  # octagons: the diagonal ranges too
                meet &= (qb[:, c] <= cb[:, c + 1]) & (cb[:, c] <= qb[:, c + 1])
            q, child = q[meet], child[meet]
            if lev > 0:
                if len(q):
                    stack.append((lev - 1, q, child))
            elif len(q):
                yield q, self.items[child]


def overlapping(abox: np.ndarray, bbox: np.ndarray) -> Iterator[tuple[np.ndarray, np.ndarray]]:
    """Chunks of (a, b) row pairs whose closed boxes (rows xmin, xmax, ymin,
    ymax) or octagons (both sides made by ``octagons``) overlap, every such
    pair exactly once.  The tree holds the larger
    side; the other side's boxes are the queries."""
    if not len(abox) or not len(bbox):
        return
    if len(abox) >= len(bbox):
        for qb, ia in BoxTree(abox).query(bbox):
            yield ia, qb
    else:
        yield from BoxTree(bbox).query(abox)


def box_pairs(abox: np.ndarray, bbox: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """All (a, b) row pairs whose closed boxes overlap, at once."""
    parts = list(overlapping(abox, bbox))
    if not parts:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    return np.concatenate([a for a, _ in parts]), np.concatenate([b for _, b in parts])
