"""(d) Three-position synthesis: the engine's construction against the same construction in sympy.geometry
(exact arithmetic, evaluated to 30 digits), run time and error against the recipe's analytic twin side by side.

Each case is one line of :data:`CASES`: ``(recipe name, given dict, sympy function)``; the sympy function
takes the given dict and returns ``{answer name: value}`` for the answers it replays, and those answers are
compared. sympy is an optional dependency (the ``test`` extra); without it this part is not measured.

Examples
--------
>>> sorted(sympy_three_positions(CASES[0][1]))
['AB', 'AD', 'BC', 'CD']
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Mapping

from .clock import clock


def _sympy_points(g: Mapping[str, Any], *names: str) -> list:
    import sympy as sp
    from sympy.geometry import Point
    return [Point(sp.nsimplify(g[n][0]), sp.nsimplify(g[n][1])) for n in names]


def _n(x) -> float:
    import sympy as sp
    return float(sp.N(x, 30))


def sympy_three_positions(g: Mapping[str, Any]) -> dict[str, float]:
    """``four_bar.three_positions``: A and D as the centres of sympy circles through the three positions."""
    from sympy.geometry import Circle

    B1, B2, B3, C1, C2, C3 = _sympy_points(g, "B1", "B2", "B3", "C1", "C2", "C3")
    A, D = Circle(B1, B2, B3).center, Circle(C1, C2, C3).center
    return {"AB": _n(A.distance(B1)), "BC": _n(B1.distance(C1)), "CD": _n(D.distance(C1)), "AD": _n(A.distance(D))}


def sympy_fixed_pivots(g: Mapping[str, Any]) -> dict[str, float]:
    """``four_bar.three_positions_fixed_pivots``: D carried onto position 1 by the exact rotation taking the
    coupler line B_iK_i to B1K1 (cos and sin from unit vectors, or from the given angles), C1 the centre of the
    sympy circle through D, D2′, D3′ (given angles enter as the exact values of their float cosines and sines)."""
    import sympy as sp
    from sympy.geometry import Circle, Point

    A, D, B1, B2, B3 = _sympy_points(g, "A", "D", "B1", "B2", "B3")
    Bs = [B1, B2, B3]
    if g.get("K1") is not None:
        Ks = _sympy_points(g, "K1", "K2", "K3")
        us = [((K - B) / sp.sqrt((K - B).dot(K - B))) for B, K in zip(Bs, Ks)]
    else:
        # the floats cos α, sin α made exact (symbolic cos(π/18) makes the circle's centre take seconds)
        us = [Point(sp.Rational(math.cos(math.radians(a))), sp.Rational(math.sin(math.radians(a))))
              for a in g["coupler_angles"]]
    copies = []
    for B, u in zip(Bs[1:], us[1:]):
        c, s = u.dot(us[0]), u.x * us[0].y - u.y * us[0].x        # the turn from B_iK_i to B1K1
        v = D - B
        copies.append(Point(B1.x + c * v.x - s * v.y, B1.y + s * v.x + c * v.y))
    C1 = Circle(D, *copies).center
    return {"BC": _n(B1.distance(C1)), "CD": _n(D.distance(C1))}


CASES: list[tuple[str, dict[str, Any], Callable[[Mapping[str, Any]], dict[str, float]]]] = [
    ("four_bar.three_positions", {"B1": [0, 0], "C1": [0, 50], "B2": [-20, 35], "C2": [10, 75], "B3": [-20, 85],
                                  "C3": [30, 85]}, sympy_three_positions),
    ("four_bar.three_positions_fixed_pivots", {"A": [0, 0], "D": [50.5, 0], "B1": [14.4, 10.8], "B2": [0, 18],
                                               "B3": [-14.4, 10.8], "K1": [19.11, 35.35], "K2": [10.56, 40.66],
                                               "K3": [-3.69, 33.39]}, sympy_fixed_pivots),
    ("four_bar.three_positions_fixed_pivots", {"A": [0, 0], "D": [80, 0], "B1": [20, 15], "B2": [0, 25],
                                               "B3": [-20, 15], "coupler_angles": [10, 0, 0]}, sympy_fixed_pivots),
]
"""The synthesis cases: (recipe, given, sympy replay of its construction). Add one line per case."""

from .synthesis_function import CASES as _FUNCTION_CASES  # noqa: E402  (function generation, rocker–slider)

CASES += _FUNCTION_CASES


@dataclass(frozen=True)
class SynthesisRow:
    """One case by one route: seconds (best of the repeats) and the largest |error| against the twin."""

    recipe: str
    method: str
    seconds: float
    max_error: float
    quantities: tuple[str, ...]


def engine_answers(recipe: str, given: Mapping[str, Any], names: tuple[str, ...]) -> dict[str, float]:
    """The answers ``names`` by geomcon's construction (answers only, no drawing)."""
    from ..problems import validate_given
    from ..recipes import get_recipe

    r = get_recipe(recipe)
    g = validate_given(r, given)
    c = r.construct(g)
    vals = c.scene.evaluate([c.answers[n] for n in names])
    return {n: _plain(vals[c.answers[n]]) for n in names}


def _plain(v: Any) -> Any:
    """A length as a float, a point (hinge coordinates) as a tuple of floats."""
    return tuple(float(x) for x in v) if isinstance(v, (tuple, list)) else float(v)


def _error(a: Any, b: Any) -> float:
    """|a − b|, the largest component's for points."""
    if isinstance(a, (tuple, list)):
        return max(abs(float(x) - float(y)) for x, y in zip(a, b))
    return abs(float(a) - float(b))


def twin_answers(recipe: str, given: Mapping[str, Any]) -> dict[str, Any]:
    """The recipe's analytic twin."""
    from ..problems import validate_given
    from ..recipes import get_recipe

    r = get_recipe(recipe)
    return r.analytic(validate_given(r, given))[0]


def measure_synthesis(repeat: int = 3) -> list[SynthesisRow] | None:
    """Both routes on every case of :data:`CASES`; None when sympy is not installed."""
    try:
        import sympy  # noqa: F401
    except ImportError:
        return None
    rows = []
    for recipe, given, fn in CASES:
        twin = twin_answers(recipe, given)
        names = tuple(fn(given))
        routes = (("geomcon", lambda: engine_answers(recipe, given, names), repeat * 20),
                  ("sympy.geometry", lambda: fn(given), repeat))
        for method, run, n in routes:
            best, got = float("inf"), {}
            for _ in range(n):
                t0 = clock()
                got = run()
                best = min(best, clock() - t0)
            rows.append(SynthesisRow(recipe, method, best, max(_error(got[k], twin[k]) for k in names), names))
    return rows


def synthesis_table(rows: list[SynthesisRow] | None) -> str:
    """The printed table of part (d)."""
    if rows is None:
        return "(d) synthesis vs sympy.geometry: not measured (sympy is not installed: pip install sympy)"
    lines = ["(d) three-position synthesis: the engine vs the same construction in sympy.geometry", "",
             f"{'recipe':<38}  {'method':<15}  {'time (best)':>11}  {'max |Δ| mm':>10}  quantities",
             f"{'-' * 38}  {'-' * 15}  {'-' * 11}  {'-' * 10}  {'-' * 10}"]
    for r in rows:
        t = f"{r.seconds * 1e3:.3g} ms" if r.seconds < 1 else f"{r.seconds:.3g} s"
        lines.append(f"{r.recipe:<38}  {r.method:<15}  {t:>11}  {r.max_error:>10.1e}  {' '.join(r.quantities)}")
    return "\n".join(lines)
