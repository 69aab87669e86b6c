"""``crank_slider.design_by_K``: the offset crank-slider with time ratio K and stroke H, plus one of e, AB, BC.

Construction: C1C2 = H on the guide; the θ-circle (C2P ⊥ C1C2, ∠C2C1P = 90° − θ, circle C1C2P), from whose
arc left of C1 (from C1 up to Q, where the perpendicular at C1 meets the circle again) the stroke is seen
under θ with C1 the folded position. The extra condition places A on that arc:

- e: the parallel to the guide at distance e;
- AB: E on AC2 with AE = AC1 sees C1C2 under 90° + θ/2 and lies at C2E = 2·AB, so E is where the circle about
  C2 of radius 2·AB meets that circle, and A is where C2E meets the θ-circle again;
- BC: F on C1A extended with AF = AC2 sees C1C2 under θ/2 and lies at C1F = 2·BC; A is where C1F meets the
  θ-circle again.

Then AB = EC2/2 and BC = AC2 − AB by the arcs the textbook draws (the arc about A through C1 meets AC2 at E).
K = 1 (no quick return) puts A on the line C1C2 itself (e = 0, AB = H/2) and needs BC.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.design_by_k import crank_slider_design
from ..analytic.linkages import theta_from_k
from ..errors import NotAMechanism
from ..geometry import (Above, Line, OtherThan, Point, ToLeftOf, circle, circle_circle, foot, line_circle,
                        line_through, midpoint, parallel, perpendicular, point_along, segment)
from ..scene import Ref, Role, Scene, marks
from .search import crossing, maximise
from .base import Construction, Quantity, Recipe
from .common import add_angle_mark, add_bar, along_line, angle_deg, guide_between, length, rebuilt_values
from .crank_slider import add_pressure_angles
from .theta_circle import K_MAX_ACUTE, add_theta_step, refuse_tiny_theta, add_seeing_circle, add_theta_circle, arc_from_to

GIVENS = (
    Quantity("K", "", "time-ratio coefficient, K = 1 or 1.00064 ≤ K ≤ 2.99745 (θ ≤ 89.94°: the admissible arc "
             "QC1 is H·cot θ high and vanishes at θ = 90°)", minimum=1.0, inclusive=True, maximum=K_MAX_ACUTE),
    Quantity("H", "mm", "stroke of the slider"),
    Quantity("e", "mm", "offset (give exactly one of e, AB, BC)", required=False, minimum=0.0, inclusive=True),
    Quantity("AB", "mm", "crank (give exactly one of e, AB, BC)", required=False),
    Quantity("BC", "mm", "connecting rod (give exactly one of e, AB, BC)", required=False),
    Quantity("gamma_allow", "deg", "smallest admissible transmission angle (marks the admissible arc)",
             required=False),
)
ANSWERS = (
    Quantity("AB", "mm", "crank"),
    Quantity("BC", "mm", "connecting rod"),
    Quantity("e", "mm", "offset"),
    Quantity("theta", "deg", "crank angle between the extreme positions, 180°(K − 1)/(K + 1)"),
    Quantity("K", "", "time-ratio coefficient (as given)"),
    Quantity("alpha_max", "deg", "largest pressure angle at the slider"),
    Quantity("gamma_min", "deg", "smallest transmission angle"),
    Quantity("AC1", "mm", "A to the folded extreme position, BC − AB"),
    Quantity("AC2", "mm", "A to the extended extreme position, BC + AB"),
)
CLOSING = ("e", "AB", "BC")


def _closing(g: Mapping[str, Any]) -> str:
    given = [k for k in CLOSING if g.get(k) is not None]
    if len(given) != 1:
        raise NotAMechanism(f"give exactly one of e, AB, BC (got {', '.join(given) or 'none'})")
    return given[0]


def feasible_range(K: float, H: float, which: str) -> tuple[float, float]:
    """The range of ``which`` (e, AB or BC) for which A lies on the admissible arc C1Q.

    Examples
    --------
    >>> lo, hi = feasible_range(1.5, 50, "e")
    >>> round(lo, 6), round(hi, 4)
    (0.0, 68.8191)
    """
    th = math.radians(theta_from_k(K))
    return {"e": (0.0, H / math.tan(th)),
            "AB": (H / 2 * math.tan(th / 2), H / 2),
            "BC": (H / 2, H / 2 / math.tan(th / 2))}[which]


def _validate(g: Mapping[str, Any]) -> list[str]:
    which = _closing(g)
    K, H, x = g["K"], g["H"], g[which]
    refuse_tiny_theta(g["K"])
    theta = theta_from_k(K)
    if K == 1.0:
        if which == "AB" and x != H / 2 or which == "e" and x != 0.0:
            raise NotAMechanism(f"K = 1 needs e = 0 and AB = H/2 = {H / 2:g}; give BC to close the design")
        if which != "BC":
            raise NotAMechanism("K = 1 fixes e = 0 and AB = H/2 but leaves BC free: give BC")
        if x <= H / 2:
            raise NotAMechanism(f"BC = {x:g} must exceed AB = H/2 = {H / 2:g}")
        return []
    if theta >= 90.0:
        raise NotAMechanism(f"K = {K:g} gives θ = {theta:g}° ≥ 90°: no offset crank-slider reaches it "
                            "(the offset would have to be e ≤ H·cot θ ≤ 0)")
    lo, hi = feasible_range(K, H, which)
    inside = (lo < x <= hi * (1 + 1e-12)) if which != "AB" else (lo * (1 - 1e-12) <= x < hi)
    if not inside:
        raise NotAMechanism(f"{which} = {x:g} puts A off the admissible arc of the θ-circle: "
                            f"for K = {K:g}, H = {H:g} it must lie in {'[' if which == 'AB' else '('}{lo:.6g}, "
                            f"{hi:.6g}{')' if which == 'AB' else ']'}")
    if which == "e" and math.isclose(x, hi, rel_tol=1e-12) or which == "BC" and math.isclose(x, hi, rel_tol=1e-12) \
            or which == "AB" and math.isclose(x, lo, rel_tol=1e-12):
        return [f"{which} = {x:g} is at the end Q of the admissible arc: AB + e = BC, αmax = 90°"]
    return []


def _half_plus_90(theta: float) -> float:
    return 90.0 + theta / 2.0


def _half(theta: float) -> float:
    return theta / 2.0


def _twice(x: float) -> float:
    return 2.0 * x


def _gamma_at(A: Point, C1: Point, C2: Point) -> float:
    """γmin (deg) of the crank-slider with pivot A and extreme positions C1, C2 on a horizontal guide."""
    u, v = abs(A - C1), abs(A - C2)
    a, b, e = (v - u) / 2, (v + u) / 2, abs(A.y - C1.y)
    return math.degrees(math.atan2(math.sqrt(max(0.0, (b - a - e) * (b + a + e))), a + e))


def admissible_arc(k, Q: Point, C1: Point, C2: Point, gamma_allow: float | None):
    """The arc of the θ-circle where A gives a crank-slider with C1 folded (from Q to C1), narrowed to
    γmin ≥ ``gamma_allow`` when given (γmin is 0 at both ends and rises to one maximum in between; its
    level crossings are found by bisection on the arc's angle)."""
    arc = arc_from_to(k, Q, C1)
    if gamma_allow is None:
        return arc
    def g(t: float) -> float:
        return _gamma_at(arc.at(t), C1, C2)

    tmax = maximise(g, 0.0, 1.0)
    if g(tmax) < gamma_allow:
        return None
    t0, t1 = (crossing(lambda t: g(t) >= gamma_allow, tmax, end) for end in (0.0, 1.0))
    from ..geometry import Arc
    return Arc(arc.center, arc.r, arc.start + t0 * arc.sweep, (t1 - t0) * arc.sweep)


def construct(g: Mapping[str, Any]) -> Construction:
    """Build the θ-circle construction of the crank-slider designed by K."""
    K, H = g["K"], g["H"]
    which = _closing(g)
    sc = Scene("Offset crank-slider designed by K")
    C1 = sc.given("C1", Point(0.0, 0.0), style="joint", caption=("C1, one end of the stroke", "取行程端点 C1"))
    C2 = sc.given_at("C2", H, 0.0, style="joint", caption=(f"C2 with C1C2 = H = {H:g} on the guide",
                                                               f"在导路上截取 C1C2 = H = {H:g} 得 C2"))
    gl = sc.add("guide", Line, C1, Point(1.0, 0.0), role=Role.GIVEN, style="given",
                caption=("The slider's guide through C1 and C2", "过 C1、C2 作导路"))
    th = add_theta_step(sc, K)
    if K == 1.0:
        A = _k_equals_one(sc, C1, C2, g["BC"], H)
    else:
        kT = add_theta_circle(sc, C1, C2, th, +1, side_words=("above the guide", "在导路上方"))
        n1 = sc.add("n1", perpendicular, gl, C1, caption=("Perpendicular to the guide at C1", "过 C1 作导路的垂线"))
        Q = sc.add("Q", line_circle, n1, kT, branch=OtherThan(C1), style="point", label="Q",
                   caption=("It meets the θ-circle again at Q", "交 θ 圆于 Q"))
        if sc.drawing:
            sc.add("arc_ok", admissible_arc, kT, Q, C1, C2, g.get("gamma_allow"), role=Role.ANNOTATION,
                   style="admissible", caption=(_arc_caption(g.get("gamma_allow"))))
        A = _closing_step(sc, which, g[which], C1, C2, gl, kT, th)
    finish_from_A(sc, A, C1, C2, gl, th, H)
    names = {q.name: q.name for q in ANSWERS}
    names.update(AC1="AC1_out", AC2="AC2_out")
    return Construction(sc, names, {n: n for n in ("C1", "C2", "A", "B1", "B2")})


def finish_from_A(sc: Scene, A: Ref, C1: Ref, C2: Ref, gl: Ref, th: Ref, H: float) -> None:
    """Everything after A is placed: AB and BC by the textbook's arcs, e, the designed linkage in both
    extreme positions, its pressure angles, the θ mark and the stroke's dimension."""
    drawing = sc.drawing                     # the joins, links, sliders and marks only a drawing needs
    if drawing:
        sc.add("AC1", segment, A, C1, style="construction", caption=("Join AC1", "连接 AC1"))
        sc.add("AC2s", segment, A, C2, style="construction", caption=("Join AC2", "连接 AC2"))
    u = sc.add("AC1_len", length, A, C1, visible=False, unit="mm")
    E = sc.add("Ea", point_along, A, C2, u, style="point", label="E",
               caption=("Arc about A through C1 meets AC2 at E: EC2 = 2·AB", "以 A 为圆心、AC1 为半径画弧交 AC2 于 E,EC2 = 2AB"))
    M = sc.add("M", midpoint, E, C2, style="point", label="M", caption=("Bisect EC2 at M", "作 EC2 的中点 M"))
    AB = sc.add("AB", length, E, M, role=Role.MEASUREMENT, unit="mm", caption=("AB = EM = EC2/2", "曲柄 AB = EM = EC2/2"))
    BC = sc.add("BC", length, A, M, role=Role.MEASUREMENT, unit="mm", caption=("BC = AM = AC2 − AB", "连杆 BC = AM = AC2 − AB"))
    Fa = sc.add("Fa", foot, gl, A, visible=False)
    sc.add("e", length, A, Fa, role=Role.MEASUREMENT, unit="mm", caption=("e = distance of A from the guide", "偏距 e = A 到导路的距离"))
    sc.add("AC1_out", length, A, C1, role=Role.MEASUREMENT, unit="mm", visible=False)
    sc.add("AC2_out", length, A, C2, role=Role.MEASUREMENT, unit="mm", visible=False)
    sc.read_off("AC1", "AC1_out")                # shown where they are joined, not with A (issue 11)
    sc.read_off("AC2s", "AC2_out")
    B1 = sc.add("B1", point_along, A, C1, _neg(sc, AB), role=Role.RESULT, style="joint", label="B1",
                caption=("B1 on C1A extended, AB1 = AB", "在 C1A 延长线上取 AB1 = AB"))
    B2 = sc.add("B2", point_along, A, C2, AB, role=Role.RESULT, style="joint", label="B2",
                caption=("B2 on AC2, AB2 = AB", "在 AC2 上取 AB2 = AB"))
    for i, (B, C) in enumerate(((B1, C1), (B2, C2)), 1) if drawing else ():
        style = "link" if i == 1 else "link-alt"
        how = ("folded", "重叠") if i == 1 else ("extended", "拉直")
        add_bar(sc, f"AB{i}", A, B, (f"Draw the designed linkage, {how[0]}: AB{i}C{i}", f"画出所设计机构的{how[1]}共线位置 AB{i}C{i}"), style=style)
        add_bar(sc, f"B{i}C{i}", B, C, style=style)
        sc.add(f"slider{i}", marks.slider, C, Point(1.0, 0.0), role=Role.ANNOTATION, style="slider")
    if drawing:                                  # the blocks run on a hatched guide, as in crank_slider.extremes
        sc.add("guide_mark", guide_between, C1, C2, gl, 0.2 * H, role=Role.ANNOTATION, style="guide")
    FC1 = sc.add("FC1", length, Fa, C1, visible=False, unit="mm")
    gap = sc.add("gap", slack, FC1, u, Ref("e"), visible=False, unit="mm")
    add_pressure_angles(sc, A, B1, C1, gl, AB, BC, gap)
    if drawing:
        sc.add("A_ground", marks.ground, A, -math.pi / 2, role=Role.ANNOTATION, style="ground")
    sc.add("theta_at_A", angle_deg, A, C1, C2, visible=False, unit="deg")
    if drawing:
        add_angle_mark(sc, "mark_theta", A, C1, C2, "θ", th)
        sc.add("dim_H", marks.dimension, C1, C2, "H", H, -0.15 * H, role=Role.ANNOTATION, style="dim",
               caption=("Dimension the stroke H", "标注行程 H"))


def slack(fc1: float, ac1: float, e: float) -> float:
    """BC − AB − e = AC1 − e of a design, as FC1²/(AC1 + e) (F the foot of A on the guide): no cancellation
    when A is near the end Q of the arc (AC1 → e, the rod nearly perpendicular to the guide at B3).

    >>> slack(3.0, 5.0, 4.0)
    1.0
    """
    return fc1 * fc1 / (ac1 + e)


def _neg(sc: Scene, x: Ref) -> Ref:
    return sc.add("minus_AB", _negate, x, visible=False)


def _negate(x: float) -> float:
    return -x


def _arc_caption(gamma_allow: float | None) -> tuple[str, str]:
    if gamma_allow is None:
        return ("Admissible arc QC1: a crank exists and C1 is the folded position", "A 的可行域:弧 QC1")
    return (f"Admissible arc: γmin ≥ {gamma_allow:g}°", f"A 的可行弧段(γmin ≥ {gamma_allow:g}°)")


def _closing_step(sc: Scene, which: str, x: float, C1: Ref, C2: Ref, gl: Ref, kT: Ref, th: Ref) -> Ref:
    pivot = dict(role=Role.RESULT, style="pivot", label="A")
    if which == "e":
        n1 = Ref("n1")
        Pe = sc.add("Pe", along_line, n1, x, visible=False)
        le = sc.add("le", parallel, gl, Pe, caption=(f"Parallel to the guide at distance e = {x:g}", f"作距导路 e = {x:g} 的平行线"))
        return sc.add("A", line_circle, le, kT, branch=ToLeftOf(C1), **pivot,
                      caption=("It meets the θ-circle at A", "交 θ 圆于 A"))
    if which == "AB":
        beta = sc.add("betaE", _half_plus_90, th, visible=False, unit="deg")
        kE = add_seeing_circle(sc, "kE", C1, C2, beta, +1, ("Circle through C1, C2 seeing C1C2 under 90° + θ/2",
                                                            "作对 C1C2 张角为 90° + θ/2 的圆"))
        kC = sc.add("kC2", circle, C2, _twice(x), caption=(f"Circle about C2 with radius 2·AB = {2 * x:g}",
                                                           f"以 C2 为圆心、2AB = {2 * x:g} 为半径作圆"))
        E = sc.add("E", circle_circle, kC, kE, branch=Above(C1, C2), style="point", label="E′",
                   caption=("They meet at E′ (AE′ = AC1)", "两圆交于 E′(AE′ = AC1)"))
        lE = sc.add("lE", line_through, C2, E, caption=("Draw C2E′", "连 C2E′ 并延长"))
        return sc.add("A", line_circle, lE, kT, branch=OtherThan(C2), **pivot,
                      caption=("It meets the θ-circle again at A", "交 θ 圆于 A"))
    half = sc.add("betaF", _half, th, visible=False, unit="deg")
    kF = add_seeing_circle(sc, "kF", C1, C2, half, +1, ("Circle through C1, C2 seeing C1C2 under θ/2",
                                                        "作对 C1C2 张角为 θ/2 的圆"))
    kC = sc.add("kC1", circle, C1, _twice(x), caption=(f"Circle about C1 with radius 2·BC = {2 * x:g}",
                                                       f"以 C1 为圆心、2BC = {2 * x:g} 为半径作圆"))
    F = sc.add("F", circle_circle, kC, kF, branch=ToLeftOf(C1), style="point", label="F",
               caption=("They meet at F (AF = AC2)", "两圆交于 F(AF = AC2)"))
    lF = sc.add("lF", line_through, C1, F, caption=("Draw C1F", "连 C1F"))
    return sc.add("A", line_circle, lF, kT, branch=OtherThan(C1), **pivot,
                  caption=("It meets the θ-circle again at A", "交 θ 圆于 A"))


def _k_equals_one(sc: Scene, C1: Ref, C2: Ref, BC: float, H: float) -> Ref:
    return sc.add("A", point_along, C1, C2, -(BC - H / 2), role=Role.RESULT, style="pivot", label="A",
                  caption=(f"K = 1: A on C2C1 extended with AC1 = BC − H/2 = {BC - H / 2:g}",
                           f"K = 1:A 在 C2C1 延长线上,AC1 = BC − H/2 = {BC - H / 2:g}"))


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """The closed form of :func:`geomcon.analytic.design_by_k.crank_slider_design`."""
    which = _closing(g)
    if g["K"] == 1.0:
        H, b = g["H"], g["BC"]
        a = H / 2
        gamma = math.degrees(math.atan2(math.sqrt((b - a) * (b + a)), a))
        return [{"AB": a, "BC": b, "e": 0.0, "theta": 0.0, "K": 1.0, "alpha_max": 90 - gamma, "gamma_min": gamma,
                 "AC1": b - a, "AC2": b + a}]
    return [crank_slider_design(g["K"], g["H"], **{which: g[which]})]


def back_check(g: Mapping[str, Any], ans: Mapping[str, float]) -> list[tuple[str, float, float, str]]:
    """Rebuild the designed linkage with ``crank_slider.extremes``: it must give back H, K and the condition."""
    v = rebuilt_values("crank_slider.extremes", {"AB": ans["AB"], "BC": ans["BC"], "e": ans["e"]},
                       ("H", "K", "gamma_min"))
    which = _closing(g)
    return [("H", v["H"], g["H"], "mm"), ("K", v["K"], g["K"], ""), (which, ans[which], g[which], "mm"),
            ("gamma_min", v["gamma_min"], ans["gamma_min"], "deg")]


RECIPE = Recipe(
    name="crank_slider.design_by_K",
    title="Offset crank-slider designed from K, H and one of e, AB, BC (θ-circle)",
    givens=GIVENS,
    answers=ANSWERS,
    points=("C1", "C2", "A", "B1", "B2"),
    construct=construct,
    analytic=analytic,
    validate=_validate,
    back_check=back_check,
)
