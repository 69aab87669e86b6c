"""A detail view of the mechanism at a larger standard scale, when the sheet's scale draws a link shorter than
:data:`MIN_LINK` (issue 11, review item A2).

The scale of sheet 1 is the largest that fits everything drawn, and a design by K draws the θ-circle through
C1 and C2 and its construction points P, P′ — at θ = 9.5° (001-10c) a circle ten times the mechanism's size, so
the drawing goes to 1:20 and its shortest link is 3.8 mm on paper. The construction keeps its scale (it
is what the student draws to find A), and the mechanism it finds — the links, their joints, grounds and
sliders — is drawn once more, alone, at the smallest standard scale that gives every link at least
:data:`MIN_LINK` on paper, in a free box of the sheet (:func:`geomcon.render.free_area.free_box`), framed and
captioned with its scale, as a textbook's 局部放大图.

Examples
--------
>>> from geomcon.paper import Scale
>>> str(detail_scale(2.3, Scale(1.0, 20.0))), str(detail_scale(3.8, Scale(1.0, 20.0)))
('1:2.5', '1:5')
>>> detail_scale(12.0, Scale(1.0, 1.0)) is None
True
"""
from __future__ import annotations

import math
from typing import Any, Callable, Sequence

from ..geometry.primitives import Point, Segment
from ..paper import STANDARD, Scale
from ..scene import Role, Scene, Step
from ..scene.marks import Ground, Guide, Slider
from .figure import Figure, build_figure, content_box, shown_steps
from .style import resolve_style
from .view import FIG_MARGIN, Box, grow

MIN_LINK = 10.0
"""The shortest link a drawing should show on paper (mm): shorter, a joint's circle (Ø 2.4 mm), its label and
its neighbour's pile up."""
CAPTION_H = 6.0
"""Room above the detail's drawing for its caption (paper mm)."""


def _items(v: Any) -> list[Any]:
    return list(v) if isinstance(v, (tuple, list)) else [v]


def _is_link(step: Step) -> bool:
    """Whether ``step`` draws links of the mechanism: a segment in a link's style (the links layer, the dash-dot
    frame) that is part of the construction, not an annotation drawn like one — a velocity or acceleration
    polygon's vector (400-01 ``a_nb``: a length in mm/s of the polygon's scale, not of the mechanism) or the
    ordinate of an s–δ diagram at the asked angle (001-24 ``sd_ask_ord``: a follower's displacement)."""
    style = resolve_style(step.style, step.role, "curve")
    return (style.layer == "links" or style.name == "frame") and step.role != Role.ANNOTATION


def mechanism_steps(steps: Sequence[tuple[int, Step]], values: dict[str, Any]
                    ) -> tuple[set[str], set[str], list[float]]:
    """The keys of the steps that draw the mechanism — links (the links layer and the dash-dot frame), the points
    at their ends, grounds and sliders there —, those of the guides its sliders run on, and the model lengths of
    the links.

    >>> from geomcon.recipes.crank_rocker import construct
    >>> sc = construct({"AB": 50, "BC": 70, "CD": 80, "AD": 90}).scene
    >>> steps, _ = shown_steps(sc, None)
    >>> keys, guides, lengths = mechanism_steps(steps, sc.evaluate([s.key for _, s in steps]))
    >>> {"A", "D", "A_ground"} <= keys, guides, round(min(lengths), 6)
    (True, set(), 50.0)
    """
    keys: set[str] = set()
    ends: list[Point] = []
    lengths: list[float] = []
    for _, s in steps:
        segs = [x for x in _items(values[s.key]) if isinstance(x, Segment) and x.a != x.b]
        if segs and _is_link(s):
            keys.add(s.key)
            ends += [p for x in segs for p in (x.a, x.b)]
            lengths += [math.dist((x.a.x, x.a.y), (x.b.x, x.b.y)) for x in segs]
    tol = 1e-6 * max((abs(c) for p in ends for c in (p.x, p.y)), default=1.0)

    def at_end(p: Point) -> bool:
        return any(abs(p.x - e.x) <= tol and abs(p.y - e.y) <= tol for e in ends)

    blocks = []
    for _, s in steps:
        for x in _items(values[s.key]):
            if (isinstance(x, Point) and at_end(x)) or (isinstance(x, (Ground, Slider)) and at_end(x.at)):
                keys.add(s.key)
                if isinstance(x, Slider):
                    blocks.append(x.at)
    guides = set()
    for _, s in steps:                    # the hatched guide a kept slider runs on
        for x in _items(values[s.key]):
            if isinstance(x, Guide) and any(_on(p, x.a, x.b, tol) for p in blocks):
                guides.add(s.key)
    return keys, guides, lengths


def _on(p: Point, a: Point, b: Point, tol: float) -> bool:
    """Whether ``p`` lies on the segment ``ab`` (within ``tol``)."""
    dx, dy = b.x - a.x, b.y - a.y
    n2 = dx * dx + dy * dy
    if n2 == 0.0:
        return math.hypot(p.x - a.x, p.y - a.y) <= tol
    t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / n2
    return -1e-9 <= t <= 1 + 1e-9 and abs((p.x - a.x) * dy - (p.y - a.y) * dx) / math.sqrt(n2) <= tol


def detail_scale(shortest_paper: float, scale: Scale) -> Scale | None:
    """The smallest standard scale at which a link drawn ``shortest_paper`` mm long at ``scale`` is at least
    :data:`MIN_LINK`; None when it already is (or when no standard scale up to 50:1 makes it so)."""
    if shortest_paper >= MIN_LINK:
        return None
    need = scale.factor * MIN_LINK / shortest_paper
    return next((s for s in STANDARD if s.factor >= need * (1 - 1e-12)), None)


def detail_figure(scene: Scene, fig: Figure, scale: Scale, free: Callable[[float, float], tuple | None],
                  upto: int | None = None) -> tuple[Figure, Scale, Box] | None:
    """The detail view of ``fig``'s mechanism: its figure (drawn at the detail scale, placed in the box that
    ``free(w, h)`` finds for it), the scale and the box on paper (caption included); None when every link is
    at least :data:`MIN_LINK` on paper already, or when no free box holds the detail."""
    values = fig.values
    steps = [(n, s) for n, s in shown_steps(scene, upto)[0] if s.key in values]     # those the figure draws
    keys, guides, lengths = mechanism_steps(steps, values)
    if not lengths:
        return None
    shortest = min(lengths) / fig.view.mu
    big = detail_scale(shortest, scale)
    if big is None:
        return None
    mu = big.real / big.paper
    for drawn in ((keys | guides, keys) if guides else (keys,)):     # the sliders' guides too, when they fit
        kept = [(n, s) for n, s in steps if s.key in drawn]
        box = grow(content_box(scene, kept, values), FIG_MARGIN * mu)
        w, h = (box[2] - box[0]) / mu, (box[3] - box[1]) / mu
        spot = free(w, h + CAPTION_H)
        if spot is not None:
            x, y = spot[0], spot[1]
            detail = build_figure(scene, upto, box, (x, y + CAPTION_H), mu=mu, keep=lambda s: s.key in drawn)
            return detail, big, (x, y, x + w, y + h + CAPTION_H)
    return None


__all__ = ["CAPTION_H", "MIN_LINK", "detail_figure", "detail_scale", "mechanism_steps"]
