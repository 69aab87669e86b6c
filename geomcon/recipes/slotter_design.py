"""``slotter.design_by_K``: the slotter's six-bar with a rotating guide bar (seed 001-19).

Crank AB about A turns the guide bar about C fully (AB > AC); the arm CD on the guide bar (B, C, D in line)
drives the slider E through the coupler DE along the path ee through C, perpendicular to AC. E is at its
extreme positions when CD lies along ee, i.e. when B is on ee: the stroke is S = 2·CD, and the crank angle
between those positions, seen from A over the chord B1B2 of B's path on ee, is 180° − θ.

Construction (C at the origin, ee horizontal, A above C): B1, B2 on ee symmetric about C; the circle through
them from whose upper arc B1B2 is seen under 180° − θ meets the perpendicular to ee at C in A; AB = AB1,
AC; CD = S/2; the centric slider CDE has its largest pressure angle with CD ⊥ ee, sin α = CD/DE, so the
shortest coupler for ``alpha_allow`` is CD / sin α. With the crank ``AB`` or the centre distance ``AC``
given instead of ``B1B2`` (the Whitworth design) the construction of :mod:`.slotter_closing` places B1, B2.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.linkages import theta_from_k
from ..errors import NotAMechanism
from ..geometry import Above, Line, Point, ToRightOf, circle, line_circle, perpendicular, point_along
from ..scene import Ref, Role, Scene, marks
from . import slotter_closing
from .base import Construction, Quantity, Recipe
from .common import add_bar, add_pivot, refuse_alpha_allow
from .theta_circle import K_MAX_OBTUSE, add_theta_step, refuse_tiny_theta, seeing_circle

GIVENS = (
    Quantity("K", "", "time-ratio coefficient, 1.00064 ≤ K ≤ 6282 (each stroke's crank angle, θ-circle "
             "chord seen under 180° − θ, at least 0.057°)", minimum=1.0, maximum=K_MAX_OBTUSE),
    Quantity("H", "mm", "stroke S of the slider E"),
    Quantity("B1B2", "mm", "distance between the two points where B's path crosses the slider's path ee "
             "(or give the crank AB, or the centre distance AC)", required=False),
    Quantity("AB", "mm", "closing condition instead of B1B2: the crank (the Whitworth design)", required=False),
    Quantity("AC", "mm", "closing condition instead of B1B2: the centre distance", required=False),
    Quantity("alpha_allow", "deg", "largest admissible pressure angle at E: gives the shortest DE (5.73e-9° ≤ α < 90°: DE within 1e10 of the length it is sized for)", required=False),
)
ANSWERS = (
    Quantity("AB", "mm", "crank"),
    Quantity("AC", "mm", "frame: crank pivot A to guide-bar pivot C"),
    Quantity("CD", "mm", "arm of the guide bar, S/2"),
    Quantity("DE", "mm", "shortest coupler for alpha_allow"),
    Quantity("theta", "deg", "180°(K − 1)/(K + 1)"),
    Quantity("K", "", "time-ratio coefficient (as given)"),
    Quantity("B1B2", "mm", "where B's path crosses ee (designed when AB or AC is given)"),
)
CLOSINGS = ("B1B2", "AB", "AC")


def _validate(g: Mapping[str, Any]) -> list[str]:
    closing = [k for k in CLOSINGS if g.get(k) is not None]
    if len(closing) != 1:
        raise NotAMechanism(f"give exactly one of B1B2, AB, AC (got {', '.join(closing) or 'none'})")
    refuse_tiny_theta(g["K"])
    refuse_alpha_allow(g.get("alpha_allow"))
    return []


def _seen(K: float) -> float:
    return 180.0 - theta_from_k(K)


def _shortest(cd: float, alpha: float) -> float:
    return cd / math.sin(math.radians(alpha))


def construct(g: Mapping[str, Any]) -> Construction:
    """Build the slotter's construction."""
    if g.get("B1B2") is None:
        sc = slotter_closing.construct(g).scene
        names = _finish(sc, g, Ref("C"), Ref("ee"), [q.name for q in ANSWERS if q.name != "DE"])
        return Construction(sc, {n: n for n in names}, {n: n for n in ("A", "C", "B1", "B2", "D1")})
    K, S, L = g["K"], g["H"], g["B1B2"]
    sc = Scene("Slotter with a rotating guide bar designed by K")
    add_theta_step(sc, K)
    C = add_pivot(sc, "C", Point(0.0, 0.0), ("Guide-bar pivot C on the slider's path ee", "导杆转动中心 C 位于滑块导路 ee 上"))
    ee = sc.add("ee", Line, C, Point(1.0, 0.0), role=Role.GIVEN, style="given", caption=("The slider's path ee", "滑块导路 ee"))
    B1 = sc.given_at("B1", -L / 2, 0.0, style="joint", caption=(f"B1, B2 on ee with B1B2 = {L:g}, C midway",
                                                                    f"在 ee 上取 B1B2 = {L:g},C 为中点"))
    B2 = sc.given_at("B2", L / 2, 0.0, style="joint")
    seen = sc.add("seen", _seen, K, visible=False, unit="deg")
    k = sc.add("kSeen", seeing_circle, B1, B2, seen, 1, style="theta-circle",
               caption=("Circle through B1, B2 seeing B1B2 under 180° − θ from above", "作对 B1B2 张角为 180° − θ 的圆(上方)"))
    n = sc.add("nC", perpendicular, ee, C, caption=("Perpendicular to ee at C", "过 C 作 ee 的垂线"))
    A = sc.add("A", line_circle, n, k, branch=Above(B1, B2), role=Role.RESULT, style="pivot", label="A",
               caption=("It meets the circle at A, the crank pivot", "交圆于曲柄转动中心 A"))
    drawing = sc.drawing                     # the cranks, marks, arm, coupler and slider only a drawing needs
    if drawing:
        sc.add("A_ground", marks.ground, A, math.pi, role=Role.ANNOTATION, style="ground")   # clear of CD′ above
    slotter_closing.measure_design(sc, A, C, B1, B2, S, beyond=" beyond C", b1b2=False)
    names = _finish(sc, g, C, ee, [q.name for q in ANSWERS if q.name not in ("DE", "B1B2")])
    return Construction(sc, {n: n for n in names}, {n: n for n in ("A", "C", "B1", "B2", "D1")})


def _finish(sc: Scene, g: Mapping[str, Any], C: Ref, ee: Ref, names: list[str]) -> list[str]:
    """The shortest coupler DE for ``alpha_allow`` (and its drawing); returns the answer names."""
    S = g["H"]
    drawing = sc.drawing
    if g.get("alpha_allow") is not None:
        a = g["alpha_allow"]
        if drawing:
            Dt = sc.add("Dt", point_along, C, sc.given("up", Point(0.0, 1.0), visible=False), S / 2, style="joint",
                        label="D′", caption=("CD ⊥ ee: the largest pressure angle at E", "CD ⊥ ee 时滑块压力角最大"))
        DE = sc.add("DE", _shortest, Ref("CD"), a, role=Role.MEASUREMENT, unit="mm",
                    caption=(f"Shortest coupler DE = CD / sin αallow, αallow = {a:g}°", f"最短连杆 DE = CD / sin[α],[α] = {a:g}°"))
        if drawing:
            kE = sc.add("kE", circle, Dt, DE, visible=False)
            E = sc.add("E", line_circle, ee, kE, branch=ToRightOf(Dt), role=Role.RESULT, style="joint", label="E′",
                       caption=("E′ on ee at DE from D′", "以 D′ 为圆心、DE 为半径交 ee 于 E′"))
            add_bar(sc, "DtE", Dt, E, style="link")
            add_bar(sc, "CDt", C, Dt, style="link")       # the arm D′E′ hangs from: drawn as the link it is
            sc.add("slider_E", marks.slider, E, Point(1.0, 0.0), role=Role.ANNOTATION, style="slider")
        names.append("DE")
    return names


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """AB = (B1B2/2)/cos(θ/2), AC = (B1B2/2)·tan(θ/2), CD = S/2, DE = CD / sin α."""
    th = theta_from_k(g["K"])
    c, sn = math.cos(math.radians(th / 2)), math.sin(math.radians(th / 2))
    if g.get("B1B2") is not None:
        half = g["B1B2"] / 2
        out = {"AB": half / c, "AC": half * sn / c}
    else:                                            # the right triangle A C B1: AC = AB·sin(θ/2)
        AB = g["AB"] if g.get("AB") is not None else g["AC"] / sn
        out = {"AB": AB, "AC": AB * sn, "B1B2": 2.0 * AB * c}
    out.update(CD=g["H"] / 2, theta=th, K=g["K"])
    if g.get("alpha_allow") is not None:
        out["DE"] = out["CD"] / math.sin(math.radians(g["alpha_allow"]))
    return [out]


def back_check(g: Mapping[str, Any], ans: Mapping[str, float]) -> list[tuple[str, float, float, str]]:
    """From AB and AC alone: B meets ee where the crank angle between the two crossings gives K back, and the
    crossings are B1B2 apart."""
    half = math.sqrt((ans["AB"] - ans["AC"]) * (ans["AB"] + ans["AC"]))
    crank = 2 * math.degrees(math.atan2(half, ans["AC"]))
    closing = next(k for k in CLOSINGS if g.get(k) is not None)
    rebuilt = {"B1B2": 2 * half, "AB": ans["AB"], "AC": ans["AC"]}[closing]
    return [("K", (360 - crank) / crank, g["K"], ""), (closing, rebuilt, g[closing], "mm"),
            ("H", 2 * ans["CD"], g["H"], "mm")]


RECIPE = Recipe(
    name="slotter.design_by_K",
    title="Slotter with a rotating guide bar and a centric slider, designed from K, the stroke and B1B2",
    givens=GIVENS, answers=ANSWERS, points=("A", "C", "B1", "B2", "D1"),
    construct=construct, analytic=analytic, validate=_validate, back_check=back_check,
)
