"""Points drawn on one spot get one label: ``"B0 = B"`` where they coincide, ``"E, B2"`` where they merely lie
closer than a label's height on paper (two labels there print on top of each other or on the other's marker:
001-29's "B0"/"B" and "D"/"K0", 001-31's "Q0 Q", 000-02's "T", "M", "G" on a pile of three dots, 001-10b's "N"
under B2's pin).

The label is placed as one text about the group, and printed in parts: each name (with the sign before it) in the
step that draws its point, so that the step player never shows a name before its point exists and the label never
moves when the next name appears.

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
    box = view.box
    eps = 1e-9 * max(box[2] - box[0], box[3] - box[1])
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


__all__ = ["LABEL_HEIGHT", "NEAR", "SAME", "Together", "groups_of"]
