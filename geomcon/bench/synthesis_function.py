"""Benchmark cases of ``four_bar.function_generation`` and ``rocker_slider.three_positions``: the same
inversion construction replayed in sympy.geometry (exact rational arithmetic once the sines and cosines of
the given degrees are taken to 50 digits; the hinge as the meet of two ``perpendicular_bisector`` lines),
evaluated to 30 digits.

``CASES`` is a list of ``(recipe name, given dict, sympy function)``; each sympy function takes the given
dict and returns ``{answer: float}`` for the length answers (and the hinge's coordinates as ``C1`` / ``F1``),
to be compared with the engine's answers. sympy is imported inside the functions (an optional dependency).

Examples
--------
>>> name, given, fn = CASES[0]
>>> name
'four_bar.function_generation'
>>> r = fn(given)                                   # doctest: +SKIP
>>> round(r["BC"], 6)                               # doctest: +SKIP
90.000331
"""
from __future__ import annotations

from typing import Any, Callable, Mapping


def _q(x: float):
    import sympy as sp
    return sp.nsimplify(x, rational=True)


def _cs(x: float):
    """cos and sin of ``x`` degrees to 50 digits, as exact rationals (exact trigonometry of rational degrees
    would cost tens of seconds per case in sympy)."""
    import sympy as sp
    t = sp.pi * _q(x) / 180
    return sp.Rational(sp.N(sp.cos(t), 50)), sp.Rational(sp.N(sp.sin(t), 50))


def _turn(P, D, deg: float):
    """P turned about D through ``deg`` degrees (translate, rotate by the rational cos/sin, translate back)."""
    from sympy.geometry import Point
    c, s = _cs(deg)
    v = P - D
    return Point(D.x + c * v.x - s * v.y, D.y + s * v.x + c * v.y)


def _centre(P1, P2, P3):
    """The meet of the perpendicular bisectors of P1P2 and P2P3 (sympy.geometry)."""
    from sympy.geometry import Segment
    return Segment(P1, P2).perpendicular_bisector().intersection(Segment(P2, P3).perpendicular_bisector())[0]


def _num(x) -> float:
    import sympy as sp
    return float(sp.N(x, 30))


def sympy_function_generation(g: Mapping[str, Any]) -> dict[str, float]:
    """C1, BC, CD: crank pins B2, B3 turned about D through ψ1 − ψi, C1 the bisectors' meet."""
    from sympy.geometry import Point

    AD, AB = _q(g["AD"]), _q(g["AB"])
    D = Point(AD, 0)
    B = [Point(AB * c, AB * s) for c, s in map(_cs, g["phi"])]
    P = [B[0]] + [_turn(B[i], D, g["psi"][0] - g["psi"][i]) for i in (1, 2)]
    C1 = _centre(*P)
    return {"C1": (_num(C1.x), _num(C1.y)), "BC": _num(C1.distance(B[0])), "CD": _num(C1.distance(D))}


def sympy_rocker_slider(g: Mapping[str, Any]) -> dict[str, float]:
    """F1, DF, EF: slider pins E2, E3 turned about D through ψ1 − ψi, F1 the bisectors' meet."""
    from sympy.geometry import Point

    D = Point(_q(g["D"][0]), _q(g["D"][1]))
    ca, sa = _cs(g.get("guide_angle", 0.0) or 0.0)
    E = [Point(_q(s) * ca, _q(g["e"]) + _q(s) * sa) for s in g["s"]]
    P = [E[0]] + [_turn(E[i], D, g["psi"][0] - g["psi"][i]) for i in (1, 2)]
    F1 = _centre(*P)
    return {"F1": (_num(F1.x), _num(F1.y)), "DF": _num(F1.distance(D)), "EF": _num(F1.distance(E[0]))}


CASES: list[tuple[str, dict[str, Any], Callable[[Mapping[str, Any]], dict[str, float]]]] = [
    ("four_bar.function_generation", {"AD": 100, "AB": 30, "phi": [40, 90, 140], "psi": [92.16, 105.09, 125.96]},
     sympy_function_generation),
    ("four_bar.function_generation", {"AD": 80, "AB": 30, "phi": [55.359, 90.0, 124.641],
                                      "psi": [89.755, 62.982, 51.35]}, sympy_function_generation),
    ("rocker_slider.three_positions", {"D": [0, 0], "psi": [60, 80, 100], "e": 45, "s": [159.81, 139.65, 118.82]},
     sympy_rocker_slider),
    ("rocker_slider.three_positions", {"D": [40, 30], "psi": [70, 95, 120], "e": 0, "guide_angle": 15,
                                       "s": [-27.96, -48.85, -74.74]}, sympy_rocker_slider),
]
"""(recipe, given, sympy construction): the bundled problems 100-05 … 100-08."""
