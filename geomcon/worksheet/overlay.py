"""The key's overlay: how far from its exact place a careful drawing may put each point the student constructs.

The points a student constructs are the chosen solution's named points that are not givens (a design by K's
A, B1, B2; an extremes problem's C1, C2, B1, B2) and the scene's other labelled points of role construction
or result that are drawn (P, the ghost positions B′, C′, a cam's pitch points 1′ … 15′ and B*), one name per
place. Each is propagated like an answer (:mod:`.drafting`): for each drafted given, the point's shift is the
central difference of its position over the given's drafting interval, d_i = (p(g_i + δ_i) − p(g_i − δ_i)) / 2,
and the radius is the root-sum-square of the shifts' lengths and of the ±0.5 mm on paper with which the point
itself is placed: r = √(Σ |d_i|² f² + 0.5²) paper mm at scale factor f. A cam program's boundaries are left
out: moving one renumbers the division points (a segment of 120.5° is divided otherwise than one of 120°), so
a pitch point has no counterpart to compare with; a boundary laid off 0.5° wrong turns a point by at most
0.5° about the cam's centre.

Examples
--------
>>> from geomcon.worksheet.solving import solve_given
>>> sol = solve_given("crank_rocker.extremes", {"AB": 25, "BC": 85, "CD": 70, "AD": 70})
>>> r = position_tolerances(sol, {"AB": 25, "BC": 85, "CD": 70, "AD": 70}, 1.0)
>>> sorted(r)[:4], round(r["C1"], 2)
(['B1', 'B2', 'B′', 'B′′'], 1.14)
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..errors import GeomconError
from ..geometry.primitives import Point
from ..scene import Role
from ..solve import Solution
from .drafting import PAPER_MM, drafted
from .readability import DIAGRAM_PREFIX
from .solving import solve_given

Where = dict[str, tuple[float, float]]


def point_keys(sol: Solution) -> dict[str, str]:
    """Name → step key of every point the student constructs (see the module), in the scene's order."""
    sc = sol.drawing_scene
    given = {s.key for s in sc.visible_steps() if s.role == Role.GIVEN}
    givens = sc.evaluate(sorted(given))
    given_at = {(p.x, p.y) for p in givens.values() if isinstance(p, Point)}
    named = {n: k for n, k in sol.construction.points.items() if k not in given}
    steps = [s for s in sc.visible_steps() if s.role in (Role.CONSTRUCTION, Role.RESULT) and not s.optional
             and s.label and not s.key.startswith(DIAGRAM_PREFIX)]
    values = sc.evaluate(list(named.values()) + [s.key for s in steps])
    out: dict[str, str] = {}
    seen: list[Point] = []
    size = sol.length_scale
    for name, key in [*named.items(), *((str(s.label), s.key) for s in steps)]:
        v = values[key]
        if not isinstance(v, Point) or (v.x, v.y) in given_at or name in out:
            continue
        if any(abs(v - q) <= 1e-9 * size for q in seen):
            continue
        out[name] = key
        seen.append(v)
    return out


def constructed_points(sol: Solution, keys: Mapping[str, str] | None = None) -> Where:
    """Name → model position of every point the student constructs (those of ``keys``: name → step key, by
    default :func:`point_keys`). Evaluated in the solution's scene as it is: a lean scene (a drafting end's)
    completes itself only when a point is a step it skipped, and gives the same values as the full one."""
    keys = point_keys(sol) if keys is None else keys
    values = sol.scene.evaluate(list(keys.values()))
    return {n: (values[k].x, values[k].y) for n, k in keys.items() if isinstance(values[k], Point)}


def position_tolerances(sol: Solution, given: Mapping[str, Any], factor: float,
                        solved: Mapping[str, tuple[Solution, Solution]] | None = None,
                        keys: Mapping[str, str] | None = None) -> dict[str, float]:
    """Name → radius (paper mm) of the tolerance circle of each constructed point of ``sol`` (solved from the
    raw givens ``given``) drawn at scale ``factor`` (paper mm per real mm); see the module. A drafting end that
    loses a point (the mechanism ends within the drawing's accuracy) leaves that point's term out: the
    variant's answers were judged determinable, the overlay is a guide.

    ``solved``: drafted quantity → its two ends' solutions, as judging the variant's tolerances solved them
    (:attr:`.accept.Solved.ends`), read instead of solving again; ``keys``: :func:`point_keys` of ``sol`` when
    known."""
    keys = point_keys(sol) if keys is None else keys
    nominal = constructed_points(sol, keys)
    sums = {k: 0.0 for k in nominal}
    for d in drafted(sol.recipe.name, given, factor):
        if " boundary " in d.name:          # a cam's division points are renumbered when a segment grows
            continue
        pair = solved.get(d.name) if solved is not None else None
        ends = []
        for i, g in enumerate((d.plus, d.minus)):
            try:
                end = pair[i] if pair is not None else solve_given(sol.recipe.name, g)
                ends.append(constructed_points(end, keys))
            except (GeomconError, KeyError):
                ends.append({})
        for k in nominal:
            if k in ends[0] and k in ends[1]:
                dx = (ends[0][k][0] - ends[1][k][0]) / 2
                dy = (ends[0][k][1] - ends[1][k][1]) / 2
                sums[k] += (dx * dx + dy * dy) * factor * factor
    return {k: math.sqrt(s + PAPER_MM ** 2) for k, s in sums.items()}


__all__ = ["constructed_points", "point_keys", "position_tolerances"]
