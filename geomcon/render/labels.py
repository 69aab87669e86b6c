"""Point labels as textbooks print them (C1 → C with subscript 1), placed off the lines.

Placement is greedy and deterministic: for each label, in step order, sixteen directions around its point
are tried and the one whose text centre keeps the largest clearance from the drawn curves, the points and
the labels already placed wins (the first in direction order on a tie).

Examples
--------
>>> split_label("C1")
('C', '1', '')
>>> split_label("B′")
('B', '', '′')
>>> best_offset((0.0, 0.0), [((-10.0, 0.0), (10.0, 0.0))], [], [], 3.0)[1] != 0.0
True
"""
from __future__ import annotations

import math
import re
from typing import Sequence

_LABEL = re.compile(r"^([^\d′″‴'*]+)(\d*)(.*)$")
DIRECTIONS = [(math.cos(math.radians(a)), math.sin(math.radians(a)))
              for a in (45, 135, 225, 315, 90, 0, 180, 270, 22.5, 67.5, 112.5, 157.5, 202.5, 247.5, 292.5, 337.5)]

Seg = tuple[tuple[float, float], tuple[float, float]]
Circ = tuple[tuple[float, float], float]


def split_label(label: str) -> tuple[str, str, str]:
    """(letters, subscript digits, rest) of a point label."""
    m = _LABEL.match(label)
    return (m.group(1), m.group(2), m.group(3)) if m else (label, "", "")


def _dist_seg(p: tuple[float, float], s: Seg) -> float:
    (ax, ay), (bx, by) = s
    dx, dy = bx - ax, by - ay
    L2 = dx * dx + dy * dy
    t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / L2))
    return math.hypot(p[0] - ax - t * dx, p[1] - ay - t * dy)


def best_offset(p: tuple[float, float], segs: Sequence[Seg], circles: Sequence[Circ],
                taken: Sequence[tuple[float, float]], dist: float) -> tuple[float, float]:
    """The label offset (paper mm, y down) for a point at ``p`` with the most clearance."""
    best, best_score = DIRECTIONS[0], -1.0
    for dx, dy in DIRECTIONS:
        c = (p[0] + dx * dist, p[1] - dy * dist)
        score = min([_dist_seg(c, s) for s in segs] + [abs(math.hypot(c[0] - o[0], c[1] - o[1]) - r) for o, r in circles]
                    + [math.hypot(c[0] - q[0], c[1] - q[1]) * 0.6 for q in taken] + [10.0])
        if score > best_score + 1e-9:
            best, best_score = (dx, dy), score
    return (best[0] * dist, -best[1] * dist)
