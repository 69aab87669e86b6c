"""What a student's sheet draws of a variant, to true scale: the givens of the construction, and where their
labels go.

The givens are the scene's visible steps of role *given* (a design by K's D, C1, C2 and the rocker's two
positions DC1, DC2; an extremes problem's frame A, D, AD; a cam's centre O, base circle and the follower's
start B0), except a cam's s–δ diagram (the sheet draws its axes at a scale of their own), plus the circles
:data:`GIVEN_CIRCLES` names (the extremes problem's crank circle about A and the rocker's path about D: where
B and C move; an offset translating cam's offset circle, radius e, which the inversion method turns the
follower's axis along). Nothing the student is asked to find is drawn.

Labels are placed on paper (mm, y down) greedily in the order of the points: of 16 directions around each
point, the first whose text box overlaps no other label, no point's dot and no drawn line (a line may be
crossed only when no direction is free of it). A label that can only overlap another label or a dot is a
*collision*; a variant whose sheet would have one is rejected (``labels``).

Examples
--------
>>> from geomcon.worksheet.solving import solve_given
>>> sol = solve_given("crank_rocker.extremes", {"AB": 25, "BC": 85, "CD": 70, "AD": 70})
>>> items = given_items(sol)
>>> [(i.kind, i.label) for i in items]
[('point', 'A'), ('point', 'D'), ('segment', None), ('circle', None), ('circle', None)]
>>> placed, bad = place_labels(items, lambda x, y: (x, -y))
>>> [p.label for p in placed], bad
(['A', 'D'], [])
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Sequence

from ..geometry.primitives import Circle, Point, Polyline, Segment
from ..render.labels import text_width
from ..render.style import LABEL_SIZE as STYLE_LABEL_SIZE
from ..render.view import clip_interval
from ..scene import Role
from ..solve import Solution
from .readability import DIAGRAM_PREFIX

XY = tuple[float, float]

GIVEN_CIRCLES: dict[str, tuple[tuple[str, str], ...]] = {
    "crank_rocker.extremes": (("A", "AB"), ("D", "CD")),
    "cam.translating": (("O", "e"),),
}
"""Per recipe, circles (centre point step, radius given) drawn as givens."""

LABEL_SIZE = STYLE_LABEL_SIZE
"""Font size of a point's label on the sheet (paper mm): the figures' own, so a key's labels are as high as its sheet's."""
DOT = 0.8
"""Radius of a point's dot on paper (mm)."""
LABEL_GAP = 1.0
"""Paper mm between a dot and its label's box."""


@dataclass(frozen=True)
class Item:
    """One given drawn on the sheet, in model mm: a point (``pts`` one point, a label), a segment (two
    points), a circle (centre and radius ``r``) or a polyline."""

    kind: str
    pts: tuple[XY, ...]
    r: float = 0.0
    label: str | None = None


@dataclass(frozen=True)
class Placed:
    """A label placed on paper: the text, its box (x0, y0, x1, y1; mm, y down) and its baseline start."""

    label: str
    box: tuple[float, float, float, float]
    x: float
    y: float


def given_items(sol: Solution) -> list[Item]:
    """The givens a sheet draws for ``sol`` (see the module), in the scene's order, circles last."""
    sc = sol.drawing_scene
    out: list[Item] = []
    steps = [s for s in sc.visible_steps() if s.role == Role.GIVEN and not s.optional
             and not s.key.startswith(DIAGRAM_PREFIX)]
    values = sc.evaluate([s.key for s in steps])
    for s in steps:
        v = values[s.key]
        if isinstance(v, Point):
            out.append(Item("point", ((v.x, v.y),), label=s.label or None))
        elif isinstance(v, Segment):
            out.append(Item("segment", ((v.a.x, v.a.y), (v.b.x, v.b.y))))
        elif isinstance(v, Circle):
            out.append(Item("circle", ((v.center.x, v.center.y),), v.r))
        elif isinstance(v, Polyline):
            out.append(Item("polyline", tuple((p.x, p.y) for p in v.points)))
    given = sol.problem.given
    for centre, radius in GIVEN_CIRCLES.get(sol.recipe.name, ()):
        c, r = sc.value(centre), given.get(radius)
        if isinstance(c, Point) and isinstance(r, (int, float)) and r > 0:
            out.append(Item("circle", ((c.x, c.y),), float(r)))
    return out


def has_diagram(sol: Solution) -> bool:
    """Whether the variant is a cam with a motion program (its sheet draws s–δ axes)."""
    g = sol.problem.given
    return isinstance(g.get("program"), (list, tuple)) and g.get("h") is not None


def given_gap(items: Sequence[Item]) -> tuple[str, str, float] | None:
    """The two labelled given points closest together (model mm), or None for fewer than two; two labels of
    one point (within 1e-9 of the drawing's size) count once."""
    pts = [(i.label, i.pts[0]) for i in items if i.kind == "point" and i.label]
    size = max((abs(c) for _, p in pts for c in p), default=1.0)
    best = None
    for k, (n1, p1) in enumerate(pts):
        for n2, p2 in pts[k + 1:]:
            d = math.hypot(p1[0] - p2[0], p1[1] - p2[1])
            if d > 1e-9 * size and (best is None or d < best[2]):
                best = (n1, n2, d)
    return best


def _overlap(a: tuple[float, float, float, float], b: tuple[float, float, float, float]) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _hits_segment(box: tuple[float, float, float, float], p: XY, q: XY) -> bool:
    """Whether segment pq crosses the box (:func:`geomcon.render.view.clip_interval`)."""
    return clip_interval(p, (q[0] - p[0], q[1] - p[1]), box, 0.0, 1.0) is not None


def _hits_circle(box: tuple[float, float, float, float], c: XY, r: float) -> bool:
    """Whether the circle's line (not its disc) passes through the box."""
    nx, ny = min(max(c[0], box[0]), box[2]), min(max(c[1], box[1]), box[3])
    near = math.hypot(nx - c[0], ny - c[1])
    far = max(math.hypot(x - c[0], y - c[1]) for x in (box[0], box[2]) for y in (box[1], box[3]))
    return near <= r <= far


def label_box(x: float, y: float, label: str, angle: float) -> tuple[tuple[float, float, float, float], float, float]:
    """The box and baseline start of ``label`` put beside the dot at paper (x, y) in direction ``angle``
    (radians, paper orientation)."""
    w, h = text_width(label, LABEL_SIZE), LABEL_SIZE * 0.8
    ux, uy = math.cos(angle), math.sin(angle)
    reach = DOT + LABEL_GAP + (abs(ux) * w + abs(uy) * h) / 2      # the box's half extent along the direction
    cx, cy = x + ux * reach, y + uy * reach
    box = (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
    return box, box[0], box[3] - 0.05 * LABEL_SIZE


def place_labels(items: Sequence[Item], to_paper: Callable[[float, float], XY]) -> tuple[list[Placed], list[str]]:
    """Place the labels of ``items``' points on paper (``to_paper`` maps model to paper mm); returns the
    placed labels and the labels that collide with another label or a dot (see the module)."""
    dots = [to_paper(*i.pts[0]) for i in items if i.kind == "point"]
    segs = [(to_paper(*a), to_paper(*b)) for i in items if i.kind in ("segment", "polyline")
            for a, b in zip(i.pts, i.pts[1:])]
    circles = []
    for i in items:
        if i.kind == "circle":
            c = to_paper(*i.pts[0])
            e = to_paper(i.pts[0][0] + i.r, i.pts[0][1])
            circles.append((c, math.hypot(e[0] - c[0], e[1] - c[1])))
    dot_boxes = [(x - DOT, y - DOT, x + DOT, y + DOT) for x, y in dots]
    placed: list[Placed] = []
    bad: list[str] = []
    for i in items:
        if i.kind != "point" or not i.label:
            continue
        x, y = to_paper(*i.pts[0])
        best = None
        for k in range(16):
            ang = -math.pi / 4 + k * math.pi / 8
            box, bx, by = label_box(x, y, i.label, ang)
            hard = any(_overlap(box, p.box) for p in placed) or any(_overlap(box, d) for d in dot_boxes)
            soft = sum(_hits_segment(box, p, q) for p, q in segs) + sum(_hits_circle(box, c, r) for c, r in circles)
            cost = (hard, soft)
            if best is None or cost < best[0]:
                best = (cost, box, bx, by)
            if cost == (False, 0):
                break
        assert best is not None
        if best[0][0]:
            bad.append(i.label)
        placed.append(Placed(i.label, best[1], best[2], best[3]))
    return placed, bad


__all__ = ["DOT", "GIVEN_CIRCLES", "Item", "LABEL_SIZE", "Placed", "given_gap", "given_items", "has_diagram", "label_box", "place_labels"]
