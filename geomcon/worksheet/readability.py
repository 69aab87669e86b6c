"""What a variant's construction looks like on paper, from the evaluated scene: its extent, the crossing
angle of every intersection the student constructs, and the distances between its labelled points.

- **Extent**: the steps of the chosen solution (what its answers and named points are computed from) and the
  visible given and result steps (the mechanism as drawn, a cam's base circle, pitch curve and profile),
  evaluated in the full scene; points, segments' ends and sampled curves count, and a given or result circle
  (a base circle, a roller) counts whole when it is no larger than the figure of those points; construction
  circles are compass arcs drawn near the points they find. Candidates of other solutions are left out, and so
  is a cam's s–δ diagram (steps ``sd_…``), which the sheet draws beside the figure at a scale of its own, and a
  roller or knife cam's actual profile, which lies inside its pitch curve.
- **Crossings**: every step of the chosen solution whose value is a point and whose first two arguments are
  curves (circle, line, ray, segment): circle–circle, line–circle, line–line intersections. The crossing angle
  is the angle between the two curves' tangents at the point, folded into [0°, 90°]. Issue 12 asks for ≥ 20°.
- **Labelled points**: the named points of the chosen solution (:attr:`Solution.points`); issue 12 asks for
  ≥ 4 mm between any two on paper.

Label collisions need the placed labels of a drawing and are not checked here.

Examples
--------
>>> from geomcon.worksheet.solving import solve_given
>>> sol = solve_given("crank_rocker.extremes", {"AB": 50, "BC": 70, "CD": 80, "AD": 90})
>>> [(k, round(a, 1)) for k, _, a in crossings(sol, ["theta"])]
[('C1', 66.0), ('C2', 48.6)]
>>> [(k, round(a, 1)) for k, _, a in crossings(sol, ["gamma_min"])]     # γmin's positions too
[('C1', 66.0), ('C2', 48.6), ('Cg1', 30.0), ('Cg2', 42.2)]
>>> [round(x, 1) for x in extent(sol)]
[-50.0, -40.6, 90.0, 80.0]
>>> closest_points(sol)[:2]
('A', 'C1')
"""
from __future__ import annotations

import math
from typing import Any, Iterable

from ..geometry.primitives import Circle, Line, Point, Polyline, Ray, Segment
from ..scene import Ref, Role
from ..solve import Solution
from .solving import chosen_map

MIN_CROSSING = 20.0
"""Smallest crossing angle (degrees) of an intersection the student constructs."""
MIN_POINT_GAP = 4.0
"""Smallest distance (paper mm) between two labelled points."""
DIAGRAM_PREFIX = "sd_"
"""Key prefix of a cam scene's s–δ diagram steps (drawn beside the figure, not in its extent)."""


def _chosen_keys(sol: Solution, names: Iterable[str] | None = None) -> list[str]:
    """The keys of the chosen solution's answers (those in ``names``, or all) and, for a recipe with one
    solution, its named points (a multi-solution recipe's named points pick among every candidate)."""
    wanted = None if names is None else set(names)
    keys = [k for n, k in chosen_map(sol).items() if n != "_valid" and (wanted is None or n in wanted)]
    return keys + ([] if sol.construction.solutions else list(sol.construction.points.values()))


def chosen_closure(sol: Solution, names: Iterable[str] | None = None) -> list[str]:
    """Every step the chosen solution's answers (those in ``names``, or all) and named points are computed
    from, in evaluation order, in the full scene (the lean answers' scene is completed, keeping its values)."""
    sc = sol.drawing_scene
    return sc.closure(_chosen_keys(sol, names))


def _tangent(curve: Any, at: Point) -> Point | None:
    if isinstance(curve, Circle):
        r = at - curve.center
        return r.perp() if abs(r) > 0 else None
    if isinstance(curve, (Line, Ray)):
        return curve.direction
    if isinstance(curve, Segment):
        d = curve.b - curve.a
        return d if abs(d) > 0 else None
    return None


def crossing_angle(a: Any, b: Any, at: Point) -> float | None:
    """The angle (degrees, 0 … 90) at which curves ``a`` and ``b`` cross at ``at``; None when either is not a
    curve.

    >>> crossing_angle(Circle(Point(0, 0), 5), Circle(Point(8, 0), 5), Point(4, 3))
    73.73979529168804
    >>> crossing_angle(Line(Point(0, 0), Point(1, 0)), Circle(Point(0, 0), 1), Point(1, 0))
    90.0
    """
    u, v = _tangent(a, at), _tangent(b, at)
    if u is None or v is None:
        return None
    ang = math.degrees(math.atan2(abs(u.cross(v)), u.dot(v)))
    return min(ang, 180.0 - ang)


def crossings(sol: Solution, names: Iterable[str] | None = None) -> list[tuple[str, str, float]]:
    """(step key, its English caption, crossing angle) of every intersection the chosen solution's answers
    ``names`` (or all its answers) and its named points are constructed from."""
    sc = sol.drawing_scene
    out = []
    for key in chosen_closure(sol, names):
        step = sc[key]
        if len(step.args) < 2:
            continue
        value = sc.value(key)
        if not isinstance(value, Point):
            continue
        a, b = (sc.value(x.key) if type(x) is Ref else x for x in step.args[:2])
        ang = crossing_angle(a, b, value)
        if ang is not None:
            out.append((key, sc.caption(key)[0], ang))
    return out


def _points_of(v: Any) -> Iterable[Point]:
    if isinstance(v, Point):
        yield v
    elif isinstance(v, Segment):
        yield v.a
        yield v.b
    elif isinstance(v, Polyline):
        yield from v.points


def extent(sol: Solution, names: Iterable[str] | None = None) -> tuple[float, float, float, float]:
    """The model box (xmin, ymin, xmax, ymax) of the construction the student draws for the answers ``names``
    (or all), see the module."""
    sc = sol.drawing_scene
    keys = set(chosen_closure(sol, names))
    for s in sc.visible_steps():
        if (s.role in (Role.GIVEN, Role.RESULT) and not s.optional) and not s.key.startswith(DIAGRAM_PREFIX):
            keys.add(s.key)
    keys = {k for k in keys if not k.startswith(DIAGRAM_PREFIX)}
    if "pitch_curve" in keys and sol.problem.given.get("follower") != "flat":
        keys.discard("profile_curve")        # inside the pitch curve (a roller's offset inward); 20× its cost
    values = sc.evaluate(sorted(keys))
    pts = [p for v in values.values() if v is not None for p in _points_of(v)]
    whole = [v for k, v in values.items() if isinstance(v, Circle) and sc[k].role in (Role.GIVEN, Role.RESULT)]
    if not pts:
        pts = [c.center for c in whole] or [Point(0.0, 0.0)]
    x0, y0 = min(p.x for p in pts), min(p.y for p in pts)
    x1, y1 = max(p.x for p in pts), max(p.y for p in pts)
    size = max(x1 - x0, y1 - y0)
    for c in whole:
        if c.r <= size or size == 0.0:
            x0, y0 = min(x0, c.center.x - c.r), min(y0, c.center.y - c.r)
            x1, y1 = max(x1, c.center.x + c.r), max(y1, c.center.y + c.r)
    rr = sol.problem.given.get("rr") if sol.problem.given.get("follower") == "roller" else None
    if rr and "pitch_curve" in keys:
        r = float(rr)                        # the roller drawn at each pitch point reaches rr beyond the curve
        x0, y0, x1, y1 = x0 - r, y0 - r, x1 + r, y1 + r
    return (x0, y0, x1, y1)


def closest_points(sol: Solution) -> tuple[str, str, float] | None:
    """The two named points of the chosen solution closest together (model mm), or None for fewer than two.
    Two names of one point (an eccentric cam's contact B at its start B0: within 1e-9 of the length scale) are
    one labelled point ("B, B0"), not two crowded ones."""
    pts = sorted(sol.points.items())
    same = 1e-9 * sol.length_scale
    best = None
    for i, (n1, p1) in enumerate(pts):
        for n2, p2 in pts[i + 1:]:
            d = math.hypot(p1[0] - p2[0], p1[1] - p2[1])
            if d <= same:
                continue
            if best is None or d < best[2]:
                best = (n1, n2, d)
    return best


__all__ = ["DIAGRAM_PREFIX", "MIN_CROSSING", "MIN_POINT_GAP", "chosen_closure", "closest_points", "crossing_angle",
           "crossings", "extent"]
