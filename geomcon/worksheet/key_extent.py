"""What an answer key draws of a variant, and the model box it takes: the full construction of the chosen
solution (every step but another solution's and a cam's s–δ diagram, :func:`key_keep`), its content box
(:func:`~geomcon.render.figure.content_box`) and the compass arcs drawn through its points
(:func:`compass_extent`), whose sweep depends on the scale (:func:`key_box`).

A variant is laid out around this box (:func:`~.accept.fit_construction`), so that the key's whole
construction, not only the givens the student starts from, lies on the sheet: a θ-circle, the construction
lines of its centre and every compass arc stay inside the frame.

Examples
--------
>>> from geomcon.worksheet.solving import solve_given
>>> sol = solve_given("crank_rocker.design_by_K", {"K": 1.4, "CD": 100, "psi": 40, "BC": 100})
>>> c = key_content(sol)
>>> [round(x, 1) for x in key_box(c, 1.0)]
[-139.7, -98.5, 68.4, 103.1]
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable

from ..geometry.primitives import Circle, Point
from ..render.draw import COMPASS_HALF, compass_parts
from ..render.figure import content_box, shown_steps
from ..render.style import resolve_style
from ..scene import Role, Step
from ..solve import Solution
from .readability import DIAGRAM_PREFIX, extent
from .solving import chosen_map

Box = tuple[float, float, float, float]


@dataclass(frozen=True)
class KeyContent:
    """The steps a key draws (frame number, step), their values and their content box (model mm, without the
    compass arcs, which depend on the scale)."""

    steps: tuple[tuple[int, Step], ...]
    values: dict[str, Any]
    box: Box

def other_solutions(sol: Solution) -> frozenset[str]:
    """The steps only another solution than the textbook's choice needs (its candidate points, θ-circle,
    lines …), and every construction or annotation step drawn from one of them (their admissible arcs, the
    ghost of the other designs). The student constructs the chosen solution alone (the sheet's model box,
    :func:`~.readability.extent`, leaves the others out), so the key draws it alone. A given or result step
    (the chosen pivot ``A`` picked among the candidates) is never one of them.

    >>> from geomcon.worksheet.solving import solve_given
    >>> sol = solve_given("crank_rocker.design_by_K", {"K": 1.4, "CD": 100, "psi": 40, "BC": 100})
    >>> sorted(k for k in other_solutions(sol) if k.startswith(("A", "F", "f")))
    ['AB_2', 'AD_2', 'A_2', 'A_near_2', 'F_2', 'fP', 'farcs_ok', 'fcompl', 'fhalf', 'fkF', 'fkTheta', 'frP']
    >>> other_solutions(solve_given("crank_rocker.extremes", {"AB": 50, "BC": 70, "CD": 80, "AD": 90}))
    frozenset()
    """
    c = sol.construction
    if not c.solutions:
        return frozenset()
    sc = sol.drawing_scene
    chosen = chosen_map(sol)
    mine = set(sc.closure([k for n, k in chosen.items() if n != "_valid"]))
    out = {k for m in c.solutions if m is not chosen
           for k in sc.closure([k for n, k in m.items() if n != "_valid"])} - mine
    for s in sc.visible_steps():                   # in evaluation order: a step's arguments come first
        if s.key not in mine and s.role not in (Role.GIVEN, Role.RESULT) and any(k in out for k in s.deps()):
            out.add(s.key)
    return frozenset(out)


def key_keep(sol: Solution) -> Callable[[Step], bool]:
    """Which steps the key's figure draws: every step but a cam's s–δ diagram (``sd_…``, drawn beside the cam
    at a scale of its own, outside the sheet's model box) and another solution's construction
    (:func:`other_solutions`)."""
    drop = other_solutions(sol)
    return lambda step: not step.key.startswith(DIAGRAM_PREFIX) and step.key not in drop


def compass_extent(steps: list[tuple[int, Step]], values: dict[str, Any], mu: float
                   ) -> tuple[float, float, float, float] | None:
    """The model box of the compass arcs drawn at scale ``mu`` (model mm per paper mm): the short arcs of each
    compass-style circle through the drawn points on it (:func:`~geomcon.render.draw.compass_parts`, as
    :func:`~geomcon.render.draw.draw_circle` draws them), sampled every 1/16 of their sweep; None for none.

    >>> steps = [(1, Step("kC", print)), (2, Step("P", print))]        # a construction circle, a point on it
    >>> box = compass_extent(steps, {"kC": Circle(Point(0, 0), 100.0), "P": Point(100.0, 0.0)}, 1.0)
    >>> [round(x, 3) for x in box]
    [99.396, -10.978, 100.0, 10.978]
    """
    pts = tuple(v for v in values.values() if isinstance(v, Point))
    out: list[Point] = []
    for _, s in steps:
        c = values[s.key]
        if not isinstance(c, Circle) or c.r <= 0 or not resolve_style(s.style, s.role, "curve").compass:
            continue
        half = max(math.radians(6.0), min(math.pi, COMPASS_HALF / (c.r / mu)))
        for start, sweep in compass_parts(c, pts, half):
            out += [c.center + Point(math.cos(a), math.sin(a)) * c.r
                    for a in (start + sweep * i / 16 for i in range(17))]
    if not out:
        return None
    return (min(p.x for p in out), min(p.y for p in out), max(p.x for p in out), max(p.y for p in out))

def key_content(sol: Solution, keep: Callable[[Step], bool] | None = None) -> KeyContent:
    """The steps the key of ``sol`` draws (``keep``, by default :func:`key_keep`), evaluated, and their
    content box: :func:`~geomcon.render.figure.content_box` and every circle drawn whole (not as compass arcs),
    however large: the key shows a θ-circle whole, never cut by the frame."""
    sc = sol.drawing_scene
    steps, _ = shown_steps(sc, None, key_keep(sol) if keep is None else keep)
    values = sc.evaluate([s.key for _, s in steps])
    x0, y0, x1, y1 = content_box(sc, steps, values)
    for _, s in steps:                      # a circle drawn whole (a θ-circle, a path) counts whole, however large
        v = values[s.key]
        for c in (v if isinstance(v, (tuple, list)) else (v,)):
            if isinstance(c, Circle) and c.r > 0 and not resolve_style(s.style, s.role, "curve").compass:
                x0, y0 = min(x0, c.center.x - c.r), min(y0, c.center.y - c.r)
                x1, y1 = max(x1, c.center.x + c.r), max(y1, c.center.y + c.r)
    return KeyContent(tuple(steps), values, (x0, y0, x1, y1))


def key_box(c: KeyContent, mu: float) -> Box:
    """The model box of the key's construction drawn at ``mu`` model mm per paper mm: its content box and its
    compass arcs (an arc through a point at the content's edge reaches beyond it)."""
    cb = c.box
    arcs = compass_extent(list(c.steps), c.values, mu)
    if arcs is None:
        return cb
    return (min(cb[0], arcs[0]), min(cb[1], arcs[1]), max(cb[2], arcs[2]), max(cb[3], arcs[3]))



def union(a: Box, b: Box) -> Box:
    """The box holding boxes ``a`` and ``b``."""
    return (min(a[0], b[0]), min(a[1], b[1]), max(a[2], b[2]), max(a[3], b[3]))


def drawn_box(sol: Solution, names: list[str], content: KeyContent) -> Box:
    """The scale-free part of :func:`figure_box`: what the student draws for the answers ``names``
    (:func:`~.readability.extent`) and the key's content box (``content``). The circles the sheet draws as
    givens (a crank's circle, a rocker's whole path) are not in it: where one is larger than the construction it
    ends on the frame line (:func:`~.sheets.circle_room`), the student needs only its arcs near the construction."""
    return union(extent(sol, names), content.box)


def figure_box(sol: Solution, names: list[str], factor: float, content: KeyContent | None = None,
               drawn: Box | None = None) -> Box:
    """The model box a variant's sheet lays out at scale ``factor`` (paper mm per model mm): every part of the
    sheet and of its key (:func:`drawn_box`) and the key's compass arcs at that scale (:func:`key_box`).
    ``content`` (:func:`key_content` of ``sol``) and ``drawn`` (:func:`drawn_box`) when computed already."""
    c = key_content(sol) if content is None else content
    return union(drawn_box(sol, names, c) if drawn is None else drawn, key_box(c, 1.0 / factor))


__all__ = ["KeyContent", "compass_extent", "drawn_box", "figure_box", "key_box", "key_content", "key_keep", "other_solutions",
           "union"]
