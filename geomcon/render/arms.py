"""An angle's arc ends on lines: where no straight line drawn by the mark's step or before runs through an end of
the arc along its ray (200-03's α arcs at 9 mm on normals 5.25 mm long, 001-21's nested φ1 arc beyond its 10 mm
line, an arc widened to :data:`~geomcon.render.draw.MIN_ANGLE_RADIUS`), the mark draws that ray on, from the
vertex to :data:`ARM_BEYOND` past the arc, as the thin dashed extension an obtuse transmission angle is measured
from.

Examples
--------
>>> from geomcon.render.shapes import ArcP, Pen, Poly
>>> arc = ArcP((0.0, 0.0), 5.0, 0.0, -0.5, Pen("#000", 0.25))
>>> line = Poly(((0.0, 0.0), (10.0, 0.0)), Pen("#000", 0.35))
>>> [round(x, 3) for x in arms(arc, [line])[0].pts[1]]      # the end on the line needs none; the other gets one
[5.704, -3.116]
"""
from __future__ import annotations

import math
from dataclasses import replace
from typing import Any, Iterable

from ..scene.marks import AngleMark
from .draw import MIN_ANGLE_RADIUS, least_arc_radius
from .symbols import ARC_APART
from .shapes import ArcP, Pen, Poly

ARM_BEYOND = 1.5
"""How far (paper mm) a ray drawn on for its arc runs past the arc."""

ON_LINE = 0.05
"""How near (paper mm) a line must pass an arc's end, along its ray, to count as the line the arc ends on."""


def _covers(seg: tuple[Any, Any], c: tuple[float, float], u: tuple[float, float], r: float) -> bool:
    """Whether the straight stroke ``seg`` runs along the ray from ``c`` in direction ``u`` through the point at
    distance ``r``."""
    (x0, y0), (x1, y1) = seg
    off0 = (x0 - c[0]) * u[1] - (y0 - c[1]) * u[0]
    off1 = (x1 - c[0]) * u[1] - (y1 - c[1]) * u[0]
    if abs(off0) > ON_LINE or abs(off1) > ON_LINE:
        return False
    t0 = (x0 - c[0]) * u[0] + (y0 - c[1]) * u[1]
    t1 = (x1 - c[0]) * u[0] + (y1 - c[1]) * u[1]
    return min(t0, t1) <= r + ON_LINE and max(t0, t1) >= r - ON_LINE


def _reach(segs: list[Any], c: tuple[float, float], u: tuple[float, float], r: float) -> float:
    """How far from ``c`` along ``u`` the straight strokes that start before radius ``r`` run (0: none does)."""
    out = 0.0
    for (x0, y0), (x1, y1) in segs:
        if (abs((x0 - c[0]) * u[1] - (y0 - c[1]) * u[0]) <= ON_LINE
                and abs((x1 - c[0]) * u[1] - (y1 - c[1]) * u[0]) <= ON_LINE):
            t0 = (x0 - c[0]) * u[0] + (y0 - c[1]) * u[1]
            t1 = (x1 - c[0]) * u[0] + (y1 - c[1]) * u[1]
            if min(t0, t1) <= ON_LINE:
                out = max(out, t0, t1)
    return out


def fitted(arc: ArcP, strokes: Iterable[Poly], others: Iterable[float] = ()) -> tuple[ArcP, list[Poly]]:
    """The arc of an angle made to end on lines: as it is when both ends lie on drawn straight strokes along their
    rays; else drawn smaller, :data:`ARM_BEYOND` inside the shorter line, when that keeps it
    :data:`~geomcon.render.draw.MIN_ANGLE_RADIUS` or more (200-03's α arcs) and
    :data:`~geomcon.render.symbols.ARC_APART` off the radii ``others`` of the other arcs about its vertex (001-21's
    φ1, φ2 arcs, drawn smaller onto its ψ arc); else as it is (the layout set the marks at one vertex apart), with
    the rays it lacks drawn on past it (thin, dashed, in the arc's ink)."""
    segs = [s.pts for s in strokes if len(s.pts) == 2 and not s.closed]
    ends = []
    for t in (0.0, 1.0):
        e = arc.at(t)
        ends.append(((e[0] - arc.c[0]) / arc.r, (e[1] - arc.c[1]) / arc.r))
    bare = [u for u in ends if not any(_covers(s, arc.c, u, arc.r) for s in segs)]
    if not bare:
        return arc, []
    floor = max(MIN_ANGLE_RADIUS, min(least_arc_radius(arc.sweep), arc.r))
    r = min(_reach(segs, arc.c, u, arc.r) for u in ends) - ARM_BEYOND
    if r >= floor and _clear(r, others) and all(any(_covers(s, arc.c, u, r) for s in segs) for u in ends):
        return replace(arc, r=r), []
    k = arc.r + ARM_BEYOND
    return arc, [Poly((arc.c, (arc.c[0] + u[0] * k, arc.c[1] + u[1] * k)), Pen(arc.pen.stroke, 0.18, (1.2, 0.8)))
                 for u in bare]


def _clear(r: float, others: Iterable[float]) -> bool:
    """Whether an arc of radius ``r`` lies :data:`ARC_APART` or more off every radius of ``others``.

    >>> _clear(8.5, [9.0]), _clear(8.5, [12.5, 16.0]), _clear(7.0, [9.0])
    (False, True, True)
    """
    return all(abs(x - r) >= ARC_APART - 1e-9 for x in others)


def arms(arc: ArcP, strokes: Iterable[Poly]) -> list[Poly]:
    """The rays of an angle's ``arc`` to draw on, its radius kept: one for each end of the arc no straight stroke
    of ``strokes`` runs through along its ray (thin, dashed, in the arc's ink)."""
    segs = [s.pts for s in strokes if len(s.pts) == 2 and not s.closed]
    out = []
    for t in (0.0, 1.0):
        e = arc.at(t)
        u = ((e[0] - arc.c[0]) / arc.r, (e[1] - arc.c[1]) / arc.r)
        if not any(_covers(s, arc.c, u, arc.r) for s in segs):
            k = arc.r + ARM_BEYOND
            out.append(Poly((arc.c, (arc.c[0] + u[0] * k, arc.c[1] + u[1] * k)), Pen(arc.pen.stroke, 0.18, (1.2, 0.8))))
    return out


def _marks(v: Any) -> bool:
    if isinstance(v, (tuple, list)):
        return any(_marks(x) for x in v)
    return isinstance(v, AngleMark)


def add_arms(groups: list[Any], values: dict[str, Any]) -> tuple[list[Poly], dict[tuple[float, float], Any]]:
    """Make every angle mark's arc of a figure's step drawings (:class:`~geomcon.render.figure.StepDrawing`) end on
    lines (:func:`fitted`), counting the straight strokes of every step of the figure: a line a later step draws
    (001-10b's links, drawn after θ is marked) is not drawn twice. Returns the rays added and, for each arc drawn
    smaller, its old middle (where its text was anchored) and the new one."""
    strokes = [sh for g in groups for sh in g.shapes if isinstance(sh, Poly) and len(sh.pts) == 2]
    rays, moved = [], {}
    found = [(g, i, arc) for g in groups if _marks(values[g.key]) for i, arc in enumerate(g.shapes)
             if isinstance(arc, ArcP) and abs(arc.sweep) > math.radians(0.2)]
    radii = {id(arc): arc.r for _, _, arc in found}       # each arc's radius, its final one once fitted
    for g, i, arc in found:
        others = [radii[id(a)] for _, _, a in found if a is not arc and math.dist(a.c, arc.c) < 1e-6]
        new, more = fitted(arc, strokes, others)
        if new is not arc:
            g.shapes[i] = new
            radii[id(arc)] = new.r
            moved[arc.at(0.5)] = new.at(0.5)
        g.shapes += more
        rays += more
    return rays, moved


__all__ = ["ARM_BEYOND", "add_arms", "arms"]
