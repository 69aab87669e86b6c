"""Points drawn on one spot get one label: ``"B0 = B"`` where they coincide, ``"E, B2"`` where they merely lie
closer than a label's height on paper (two labels there print on top of each other or on the other's marker:
001-29's "B0"/"B" and "D"/"K0", 001-31's "Q0 Q", 000-02's "T", "M", "G" on a pile of three dots, 001-10b's "N"
under B2's pin).

The label is placed as one text about the group, and printed in parts: each name (with the sign before it) in the
step that draws its point, so that the step player never shows a name before its point exists and the label never
moves when the next name appears.

Points that coincide (the same point reached twice: 200-12's B0, the rise's first and the return's last position;
001-13's C1 and N) share one marker, the largest of them (:func:`shared_markers`): a dot drawn in a hinge's circle
reads as a second point where there is one. A point near another but apart keeps its marker, and a dot is drawn
above the hinges (:func:`dots_above`), so that no hinge's white disc hides a point of the construction (001-10b's N,
0.3 mm from B2's centre, was under B2's circle).

Examples
--------
>>> from geomcon.geometry import Point
>>> from geomcon.render.view import View
>>> view = View((0.0, 0.0, 100.0, 100.0), 1.0, (0.0, 0.0))
>>> pts = [("B0", "B0", Point(10, 10), 1.25), ("K", "K", Point(50, 50), 0.55), ("B", "B", Point(10, 10), 1.25)]
>>> [(g.keys, g.text) for g in groups_of(pts, view)]
[(('B0', 'B'), 'B0 = B')]
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Collection

from ..geometry.primitives import Point
from .labels import Runs, label_runs
from .style import LABEL_SIZE
from .view import View

XY = tuple[float, float]

LABEL_HEIGHT = 0.74 * LABEL_SIZE
"""The height (paper mm) of a point's label without a subscript: points closer than this share one label."""

SAME, NEAR = " = ", ", "
"""What joins two names of one label: the points coincide (within 1e-9 of the drawing's size), or are only near."""


@dataclass(frozen=True, slots=True)
class Together:
    """Labelled points drawn closer than :data:`LABEL_HEIGHT`: their step keys and names in step order (the first
    step places the label), what comes before each name (nothing, :data:`SAME` or :data:`NEAR`), the points on
    paper and their markers' radii."""

    keys: tuple[str, ...]
    names: tuple[str, ...]
    joins: tuple[str, ...]
    at: tuple[XY, ...]
    radii: tuple[float, ...]

    @property
    def text(self) -> str:
        """The whole label, e.g. ``"B0 = B"``."""
        return "".join(j + n for j, n in zip(self.joins, self.names) if n)

    def parts(self) -> tuple[tuple[str, Runs], ...]:
        """(step key, runs) of each printed part: the first name, then each further name with its sign (a name
        printed already is not repeated)."""
        return tuple((k, ((j, False),) + label_runs(n) if j else label_runs(n))
                     for k, j, n in zip(self.keys, self.joins, self.names) if n)

    def anchor(self) -> tuple[XY, float]:
        """The middle of the points on paper and the room its label keeps from it (every marker, 0.4 mm clear)."""
        xs, ys = [p[0] for p in self.at], [p[1] for p in self.at]
        c = ((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2)
        return c, max(math.dist(c, p) + r for p, r in zip(self.at, self.radii)) + 0.4


def groups_of(points: list[tuple[str, str, Point, float]], view: View) -> list[Together]:
    """The groups of two or more of ``points`` — (step key, label, model point, marker radius on paper), in step
    order — lying pairwise closer than :data:`LABEL_HEIGHT` on paper: each point joins the first group all of whose
    members are that near (a chain of near points never makes one long label), else starts its own."""
    eps = same_spot(view.box)
    groups: list[list[tuple[str, str, Point, float]]] = []
    for p in points:
        q = view.p(p[2])
        for g in groups:
            if all(math.dist(q, view.p(m[2])) < LABEL_HEIGHT for m in g):
                g.append(p)
                break
        else:
            groups.append([p])
    out = []
    for g in groups:
        if len(g) < 2:
            continue
        names, joins = [], []
        for i, (_, label, p, _) in enumerate(g):
            names.append("" if label in names else label)
            joins.append("" if i == 0 else SAME if abs(p - g[i - 1][2]) <= eps else NEAR)
        out.append(Together(tuple(m[0] for m in g), tuple(names), tuple(joins), tuple(view.p(m[2]) for m in g),
                            tuple(m[3] for m in g)))
    return out


def same_spot(box: tuple[float, float, float, float]) -> float:
    """The model distance within which two points of a drawing of model ``box`` coincide: 1e-9 of its size (the
    join :data:`SAME` of their names and their shared marker use this one rule)."""
    return 1e-9 * max(box[2] - box[0], box[3] - box[1])


def shared_markers(points: list[tuple[str, Point, float]], eps: float, current: Collection[str] = ()) -> set[str]:
    """The step keys of ``points`` — (step key, model point, marker radius on paper), in step order — whose marker
    another point at the same spot (within ``eps``) draws: of points that coincide only the largest marker, the
    first of equal ones, is drawn; the current step's points keep their own (a step player shows what it finds).

    >>> pts = [("B0", Point(0, 0), 1.25), ("C", Point(0.5, 0), 0.55), ("B6", Point(0, 0), 0.55),
    ...        ("T", Point(0, 0), 1.25)]
    >>> sorted(shared_markers(pts, 1e-9)), sorted(shared_markers(pts, 1e-9, current={"B6"}))
    (['B6', 'T'], ['T'])
    """
    order = sorted(range(len(points)), key=lambda i: points[i][1].x)       # a sweep along x: coinciding are adjacent
    out: set[str] = set()
    for n, i in enumerate(order):
        p = points[i][1]
        for j in order[n + 1:]:
            q = points[j][1]
            if q.x - p.x > eps:
                break
            if abs(q.y - p.y) <= eps and abs(p - q) <= eps:
                ri, rj = points[i][2], points[j][2]
                lose = j if (ri > rj or (ri == rj and i < j)) else i        # the larger marker, the first of equal
                out.add(points[lose][0])
    return out - set(current)


def dots_above(groups: list, hollow: Callable[[object], bool]) -> list:
    """``groups`` (one layer's step drawings, in step order) with the hinges' (``hollow``) first, then the rest, each
    in its order: a dot near a hinge is drawn on its circle, not under its white disc.

    >>> dots_above(["dot A", "pin B", "dot C", "pin D"], lambda g: g.startswith("pin"))
    ['pin B', 'pin D', 'dot A', 'dot C']
    """
    return [g for g in groups if hollow(g)] + [g for g in groups if not hollow(g)]


PIN_GAP = 0.3
"""Least paper mm between a hinge's circle and another point's marker: closer, the two read as one blot (the rule
``tests/knots.py`` checks)."""


def tightest(markers: list[tuple[Point, XY, float, bool]]) -> tuple[float, float, tuple[Point, Point]] | None:
    """Of the point markers — (model point, centre on paper, radius, hollow) — the hinge and the dot (a construction
    point on a hinge) drawn closer than their radii and :data:`PIN_GAP`, two distinct points (the markers of points
    that coincide are one), that need the most enlarging to stand apart: (their distance on paper, the distance
    they need, the two model points); None when every dot keeps :data:`PIN_GAP` from the hinges. Two hinges that
    meet so are one too (200-16's follower positions B1* and B(75°), 2.5 mm apart at 1:2): the mechanism's
    knot of hinges (:func:`.detail.knot`) is found first, where the mechanism has one.

    >>> m = [(Point(0, 0), (0.0, 0.0), 1.25, True), (Point(0.7, 0), (0.7, 0.0), 0.55, False),
    ...      (Point(9, 0), (9.0, 0.0), 0.55, False)]
    >>> d, need, (p, q) = tightest(m)
    >>> round(d, 9), round(need, 9), p, q
    (0.7, 2.1, Point(x=0.0, y=0.0), Point(x=0.7, y=0.0))
    >>> d, need, _ = tightest([(Point(0, 0), (0.0, 0.0), 1.25, True), (Point(2.5, 0), (2.5, 0.0), 1.25, True)])
    >>> round(d, 9), round(need, 9)
    (2.5, 2.8)
    """
    best = None
    hinges = [m for m in markers if m[3]]
    for i, (p, a, r, _) in enumerate(hinges):
        for q, b, s, _ in [m for m in markers if not m[3]] + hinges[i + 1:]:
            need = r + s + PIN_GAP
            if abs(a[0] - b[0]) < need and abs(a[1] - b[1]) < need:
                d = math.dist(a, b)
                if 1e-3 < d < need and (best is None or need / d > best[1] / best[0]):
                    best = (d, need, (p, q))
    return best


__all__ = ["LABEL_HEIGHT", "NEAR", "PIN_GAP", "SAME", "Together", "dots_above", "groups_of", "same_spot",
           "shared_markers", "tightest"]
