"""``guide_bar.design_by_K`` and ``shaper.design_by_K``: the oscillating guide-bar (and the six-bar of
shapers and slotters built on it) designed from the time ratio K.

The guide bar's extreme positions are the tangents from C to the crank circle, so ψ = θ and
AB = AC·sin(θ/2). Construction (A at the origin, the centre line AC vertical, C below A):

- AC given: the extreme positions are the lines through C at ±θ/2 to CA; the perpendiculars from A meet
  them at B1, B2;
- AB given: AB1 at 90° − θ/2 to AC on the crank circle, the tangent at B1 meets the centre line at C.

The shaper adds the ram: D on the guide bar at CD from C describes an arc whose chord D1D2 is the stroke H
(the line parallel to the centre line at H/2 meets CB1 at D1); the ram's guide runs through the middle of
the arc's sagitta, h = CD(1 + cos(θ/2))/2 from C, so the largest deviation of D from it, half the sagitta,
is as small as it can be; a coupler DE then meets the guide at a pressure angle of at most
asin(deviation / DE), and the shortest DE for an allowed angle is deviation / sin α.

How the drawing shows the ram. D swings only between D1 and D2, so the arc of D is drawn from D1 to D2
through T (a little beyond each), not as the whole circle about C, which claimed a path D never takes and
reached CD below C: it set the drawing's extent, and 000-02 fitted A4 only at 1:5 (now 1:2). With DE given
(or sized from alpha_allow) the ram's block E1 is drawn on its hatched guide at DE from D1. Without DE, as in
000-02, where E lies is unknown; the seed (the slotter 插床 course design) gives the link design only as a
heading, and its BASIC program's coupler BC = 46 belongs to a guide placed at x = −276.4, not through G, so it
gives no DE for this construction. So the step draws what the givens fix: the ram's guide (the line through G)
with the stroke H dimensioned on it between the feet of D1 and D2 — D1 and D2 lie one distance from the
guide, so any coupler puts the ram's ends of stroke E1, E2 at the feet shifted alike and E1E2 = D1D2 = H.
Blocks drawn "under D1, D2", as before, guessed E's place and covered the pins D1, D2.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.design_by_k import guide_bar_design, shaper_design
from ..analytic.linkages import theta_from_k
from ..errors import NotAMechanism
from ..geometry import (Ahead, Arc, FarthestFrom, Line, NearestTo, Point, circle, foot, line_circle, line_through, midpoint, perpendicular,
                        point_on_ray, reflect)
from ..scene import Ref, Role, Scene, marks
from .base import Construction, Quantity, Recipe
from .common import add_angle_mark, add_bar, add_pivot, angle_deg, length, rebuilt_values, refuse_alpha_allow
from .theta_circle import add_theta_step, ray_line, refuse_tiny_theta, meet_lines, ray_from

GUIDE_GIVENS = (
    Quantity("K", "", "time-ratio coefficient, 1.00064 ≤ K < 3 (the guide bar swings through ψ = θ < 90°)",
             minimum=1.0, maximum=3.0),
    Quantity("AC", "mm", "frame: crank pivot A to guide-bar pivot C (give AC or AB)", required=False),
    Quantity("AB", "mm", "crank (give AC or AB)", required=False),
)
GUIDE_ANSWERS = (
    Quantity("AB", "mm", "crank"),
    Quantity("AC", "mm", "frame"),
    Quantity("psi", "deg", "swing of the guide bar (= θ)"),
    Quantity("theta", "deg", "180°(K − 1)/(K + 1)"),
    Quantity("K", "", "time-ratio coefficient (as given)"),
)
SHAPER_GIVENS = GUIDE_GIVENS[:1] + (Quantity("H", "mm", "stroke of the ram (slider E)"),) + GUIDE_GIVENS[1:] + (
    Quantity("alpha_allow", "deg", "largest admissible pressure angle at the ram: gives the shortest DE (5.73e-9° ≤ α < 90°: DE within 1e10 of the length it is sized for)",
             required=False),
    Quantity("DE", "mm", "coupler, when chosen: gives the largest pressure angle", required=False),
)
SHAPER_ANSWERS = GUIDE_ANSWERS + (
    Quantity("CD", "mm", "guide bar, C to the coupler joint D"),
    Quantity("h", "mm", "distance of the ram's guide from C (middle of the sagitta of D's arc)"),
    Quantity("deviation", "mm", "largest distance of D from the ram's guide, half the sagitta"),
    Quantity("DE", "mm", "shortest coupler for alpha_allow (or the given DE)"),
    Quantity("alpha_max", "deg", "largest pressure angle at the ram with that DE"),
)


def _closing(g: Mapping[str, Any]) -> str:
    have = [k for k in ("AC", "AB") if g.get(k) is not None]
    if len(have) != 1:
        raise NotAMechanism(f"give exactly one of AC, AB (got {', '.join(have) or 'none'})")
    return have[0]


def _validate(g: Mapping[str, Any]) -> list[str]:
    _closing(g)
    th = theta_from_k(g["K"])
    refuse_tiny_theta(g["K"])
    if th >= 90.0:
        raise NotAMechanism(f"K = {g['K']:g} gives θ = {th:g}° ≥ 90°: the guide bar would swing through ψ = θ ≥ 90°, "
                            "more than a guide-bar quick-return drive is built for; use K < 3")
    refuse_alpha_allow(g.get("alpha_allow"))
    if g.get("alpha_allow") is not None and g.get("DE") is not None:
        raise NotAMechanism("give alpha_allow (to size DE) or DE (to check the pressure angle), not both")
    return []


def _scaled(x: float, k: float) -> float:
    return k * x


def _sin_ratio(dev: float, alpha_deg: float) -> float:
    return dev / math.sin(math.radians(alpha_deg))


def _pressure(dev: float, de: float) -> float:
    return math.degrees(math.asin(min(1.0, dev / de)))


def _guide_bar_part(sc: Scene, g: Mapping[str, Any]) -> tuple[Ref, Ref, Ref, Ref, Ref]:
    """A, C, B1, B2 and ψ of the guide-bar part; returns (A, C, B1, B2, theta)."""
    K = g["K"]
    th = add_theta_step(sc, K, note=("The guide bar swings through ψ = θ. ", "导杆摆角 ψ = θ;"))
    half = sc.add("half", _scaled, th, 0.5, visible=False, unit="deg")
    A = add_pivot(sc, "A", Point(0.0, 0.0), ("Crank pivot A", "曲柄转动中心 A"))
    centre = sc.add("centre", Line, A, Point(0.0, -1.0), role=Role.GIVEN, style="frame",
                    caption=("The centre line through A (vertical)", "过 A 作竖直中心线"))
    if _closing(g) == "AC":
        AC = g["AC"]
        C = add_pivot(sc, "C", (0.0, -AC), (f"Guide-bar pivot C on the centre line, AC = {AC:g}",
                                                 f"在中心线上取 AC = {AC:g} 得导杆摆动中心 C"))
        rays = []
        for i, sign in ((1, 1.0), (2, -1.0)):
            turn = sc.add(f"turn{i}", _scaled, half, sign, visible=False, unit="deg")   # B1 on the left
            rays.append(sc.add(f"g{i}", ray_from, C, A, turn, caption=(
                f"Extreme position {i} of the guide bar: through C at θ/2 to CA", f"过 C 作与 CA 成 θ/2 的导杆极限位置 {i}")))
        Bs = []
        for i, r in enumerate(rays, 1):
            line = sc.add(f"gl{i}", ray_line, r, visible=False)
            Bs.append(sc.add(f"B{i}", foot, line, A, role=Role.RESULT, style="joint", label=f"B{i}",
                             caption=(f"The perpendicular from A meets it at B{i}", f"自 A 作其垂线,垂足为 B{i}")))
        B1, B2 = Bs
        sc.add("AB", length, A, B1, role=Role.MEASUREMENT, unit="mm", caption=("Crank AB = AB1", "曲柄 AB = AB1"))
        sc.add("AC", length, A, C, visible=False, unit="mm")
    else:
        AB = g["AB"]
        if sc.drawing:
            sc.add("kB", circle, A, AB, style="path", caption=(f"Crank circle about A, AB = {AB:g}", f"以 A 为圆心、AB = {AB:g} 作曲柄圆"))
        comp = sc.add("comp", _complement_turn, half, visible=False, unit="deg")
        down = sc.given("down", Point(0.0, -1.0), visible=False)
        r1 = sc.add("rB1", ray_from, A, down, comp, caption=("Through A a ray at 90° − θ/2 to the centre line",
                                                          "过 A 作与中心线成 90° − θ/2 的射线"))
        B1 = sc.add("B1", point_on_ray, r1, AB, role=Role.RESULT, style="joint", label="B1",
                    caption=("It meets the crank circle at B1", "交曲柄圆于 B1"))
        t1 = sc.add("t1", _tangent_at, A, B1, caption=("The tangent at B1 (perpendicular to AB1)", "过 B1 作曲柄圆的切线"))
        C = sc.add("C", meet_lines, t1, centre, role=Role.RESULT, style="pivot", label="C",
                   caption=("It meets the centre line at C", "交中心线于 C"))
        if sc.drawing:
            sc.add("C_ground", marks.ground, C, -math.pi / 2, role=Role.ANNOTATION, style="ground")
        B2 = sc.add("B2", reflect, B1, centre, role=Role.RESULT, style="joint", label="B2",
                    caption=("B2, the mirror image of B1 in the centre line", "B1 关于中心线的对称点 B2"))
        sc.add("AC", length, A, C, role=Role.MEASUREMENT, unit="mm", caption=("Frame AC", "机架 AC"))
        sc.add("AB", length, A, B1, visible=False, unit="mm")
    drawing = sc.drawing                     # the cranks, sliders, right-angle marks and the ψ, θ marks only a drawing needs
    for i, B in enumerate((B1, B2), 1) if drawing else ():
        add_bar(sc, f"AB{i}", A, B, (f"Crank AB{i} ⊥ guide bar CB{i}", f"曲柄 AB{i} ⊥ 导杆 CB{i}"), style="link" if i == 1 else "link-alt")
        sc.add(f"right{i}", marks.right_angle, B, A, C, role=Role.ANNOTATION, style="right-angle")
        sc.add(f"slider_B{i}", _slider_on, B, C, role=Role.ANNOTATION, style="slider")   # the block on the guide bar
    ps = sc.add("psi", angle_deg, C, B1, B2, role=Role.MEASUREMENT, unit="deg", caption=("ψ = ∠B1CB2", "ψ = ∠B1CB2"))
    if drawing:
        add_angle_mark(sc, "mark_psi", C, B1, B2, "ψ", ps)
        add_angle_mark(sc, "mark_theta", A, B1, B2, "θ", th)   # between AB2 and AB1 extended: ∠B1AB2 = 180° − θ
    return A, C, B1, B2, th


def _slider_on(B: Point, C: Point) -> marks.Slider:
    """The slider block at B, sliding along the guide bar CB."""
    return marks.slider(B, B - C)


ARC_OVERRUN = 0.125
"""How far the arc of D runs on past D1 and D2, a fraction of its sweep ψ on each side (a compass arc drawn a
little beyond the points it joins)."""


def _arc_of_d(C: Point, D1: Point, D2: Point) -> Arc:
    """The arc D describes about C, from D2 to D1 through its top T (the shorter way round), run on by
    :data:`ARC_OVERRUN` of its sweep at each end: D swings only between D1 and D2, so the whole circle, drawn
    before, claimed a path D never takes and reached CD below C, setting the drawing's extent (000-02 fitted
    only 1:5 on A4).

    >>> a = _arc_of_d(Point(0.0, 0.0), Point(-1.0, 1.0), Point(1.0, 1.0))
    >>> round(math.degrees(a.start), 6), round(math.degrees(a.sweep), 6)
    (33.75, 112.5)
    """
    t2 = math.atan2(D2.y - C.y, D2.x - C.x)
    sweep = (math.atan2(D1.y - C.y, D1.x - C.x) - t2) % (2 * math.pi)
    if sweep > math.pi:                      # D1 lies clockwise of D2: the arc runs from D1 instead
        t2, sweep = t2 + sweep, 2 * math.pi - sweep
    over = ARC_OVERRUN * sweep
    return Arc(C, abs(D1 - C), t2 - over, sweep + 2 * over)


def _ram_guide(guide: Line, D1: Point, D2: Point, E1: Point, E2: Point) -> marks.Guide:
    """The ram's guide drawn (hatched on the side away from the coupler) over the feet of D1 and D2 and the
    ram's ends of stroke E1, E2 on it, a fifth of the stroke beyond the outermost: E2 lies beyond D2's foot by
    as much as E1 lies inside D1's, and a guide over the feet only left the block E2 off its end (001-20)."""
    a, b = foot(guide, D1), foot(guide, D2)
    u = (b - a).unit()
    ts = [(p - a).dot(u) for p in (a, b, E1, E2)]
    extra = abs(b - a) * 0.2
    side = 1 if (b - a).cross(D1 - a) < 0 else -1
    return marks.guide(a + u * (min(ts) - extra), a + u * (max(ts) + extra), side)


STROKE_OFFSET = 0.12
"""How far the stroke's dimension line stands off the ram's guide, a fraction of the stroke H, towards A: on the
guide's hatched side, clear of D1, D2 and the arc of D on the other."""


def _stroke_on_guide(guide: Line, D1: Point, D2: Point, H: float) -> marks.Dimension:
    """The ram's stroke H dimensioned on its guide between the feet of D1 and D2, standing off towards the
    guide's hatched side (away from D).

    D1 and D2 lie at one distance from the guide (the chord D1D2 is parallel to it), so a coupler DE of any
    length puts the ram's ends of stroke E1, E2 at the feet shifted alike: E1E2 = D1D2 = H. Where E lies needs
    DE, which this problem does not give; a block drawn "under D" (as before) guessed it and covered D1, D2.

    >>> d = _stroke_on_guide(Line(Point(0.0, 0.0), Point(1.0, 0.0)), Point(-50.0, -5.0), Point(50.0, -5.0), 100.0)
    >>> d.a, d.b, d.offset, d.text
    (Point(x=-50.0, y=0.0), Point(x=50.0, y=0.0), 12.0, 'H=100.00')
    """
    a, b = foot(guide, D1), foot(guide, D2)
    away = 1.0 if (b - a).cross(D1 - a) < 0 else -1.0          # the dimension's left of a→b is away from D
    return marks.dimension(a, b, "H", abs(b - a), away * STROKE_OFFSET * H)


def _bar_end(C: Point, B: Point, D: Point) -> Point:
    """The end of the guide bar from C: the farther of the slider's pin B and the arm's end D, so that the
    drawn bar carries both (D lies between C and B when CD < CB)."""
    return D if abs(D - C) >= abs(B - C) else B


def _d_beyond_b(g: Mapping[str, Any]) -> bool:
    """Whether D1 lies beyond B1 from C (CD = H/(2 sin θ/2) > CB1), from the givens: chooses the caption's
    wording only."""
    half = math.radians(theta_from_k(g["K"]) / 2)
    cb = g["AC"] * math.cos(half) if g.get("AC") is not None else g["AB"] / math.tan(half)
    return g["H"] / (2 * math.sin(half)) > cb


def _complement_turn(half: float) -> float:
    return -(90.0 - half)


def _tangent_at(center: Point, p: Point) -> Line:
    return Line(p, (p - center).perp())


def guide_construct(g: Mapping[str, Any]) -> Construction:
    """Build the guide-bar design."""
    sc = Scene("Oscillating guide-bar designed by K")
    A, C, B1, B2, _ = _guide_bar_part(sc, g)
    for i, B in enumerate((B1, B2), 1) if sc.drawing else ():
        add_bar(sc, f"CB{i}", C, B, style="link" if i == 1 else "link-alt")
    return Construction(sc, {q.name: q.name for q in GUIDE_ANSWERS}, {n: n for n in ("A", "C", "B1", "B2")})


def shaper_construct(g: Mapping[str, Any]) -> Construction:
    """Build the shaper design: guide-bar part, then the ram's stroke, guide and coupler."""
    H = g["H"]
    sc = Scene("Shaper six-bar designed by K")
    A, C, B1, B2, th = _guide_bar_part(sc, g)
    centre = Ref("centre")
    off = sc.add("off", Line, sc.given_at("Hh", -H / 2, 0.0, visible=False), Point(0.0, 1.0), caption=(
        f"The line parallel to the centre line at H/2 = {H / 2:g}", f"作与中心线相距 H/2 = {H / 2:g} 的平行线"))
    ray1 = sc.add("cb1", line_through, C, B1, visible=False)
    where = (("It meets CB1 extended at D1 (beyond B1): D1D2 = H", "交 CB1 延长线于 D1(在 B1 之外),D1D2 = H")
             if _d_beyond_b(g) else
             ("It meets CB1 at D1 (between C and B1): D1D2 = H", "交 CB1 于 D1(在 C 与 B1 之间),D1D2 = H"))
    D1 = sc.add("D1", meet_lines, ray1, off, role=Role.RESULT, style="joint", label="D1", caption=where)
    D2 = sc.add("D2", reflect, D1, centre, role=Role.RESULT, style="joint", label="D2",
                caption=("D2, the mirror image of D1", "D1 的对称点 D2"))
    CD = sc.add("CD", length, C, D1, role=Role.MEASUREMENT, unit="mm", caption=("Guide bar CD = CD1", "导杆长 CD = CD1"))
    drawing = sc.drawing                     # the guide bars, the arc of D, the coupler and the slider only a drawing needs
    for i, (B, D) in enumerate(((B1, D1), (B2, D2)), 1) if drawing else ():
        end = sc.add(f"bar_end{i}", _bar_end, C, B, D, visible=False)
        add_bar(sc, f"CD{i}", C, end, (f"Guide bar CD{i}, carrying the slider B{i}", f"导杆 CD{i}(滑块 B{i} 在其上)")
                if i == 1 else ("", ""), style="link" if i == 1 else "link-alt")
    if drawing:
        sc.add("arcD", _arc_of_d, C, D1, D2, style="path", caption=("The arc of D about C, from D1 to D2",
                                                                     "D 点绕 C 的轨迹圆弧 D1D2"))
    T = sc.add("T", line_circle, centre, sc.add("kCD", circle, C, CD, visible=False), branch=Ahead(C, A), style="point",
               label="T", caption=("The arc's top T on the centre line", "圆弧与中心线的交点 T"))
    M = sc.add("Mchord", midpoint, D1, D2, style="point", label="M", caption=("The chord's midpoint M", "弦 D1D2 的中点 M"))
    G = sc.add("G", midpoint, T, M, style="point", label="G", caption=("G halves the sagitta TM", "取弓高 TM 的中点 G"))
    guide = sc.add("ram_guide", perpendicular, centre, G, role=Role.RESULT, style="given",
                   caption=("The ram's guide through G, perpendicular to the centre line", "过 G 作垂直于中心线的滑块导路"))
    sc.add("h", length, C, G, role=Role.MEASUREMENT, unit="mm", caption=("h = CG", "导路位置 h = CG"))
    dev = sc.add("deviation", length, G, M, role=Role.MEASUREMENT, unit="mm",
                 caption=("Largest deviation of D from the guide: GM = GT", "D 偏离导路的最大距离 GM = GT"))
    chosen = g.get("alpha_allow") is not None or g.get("DE") is not None     # DE known: the ram's block E1 drawn
    if drawing and not chosen:                  # E's place unknown: the guide's line and the stroke on it
        sc.add("dim_H", _stroke_on_guide, guide, D1, D2, H, role=Role.ANNOTATION, style="dim", caption=(
            "The ram's stroke H on its guide, between the feet of D1 and D2 (whatever the coupler DE, the ram's ends "
            "of stroke lie D1D2 = H apart)",
            "滑枕行程 H 标在导路上 D1、D2 的垂足之间(连杆 DE 取任何长度,滑枕两极限位置之距均为 D1D2 = H)"))
    if g.get("alpha_allow") is not None:
        DE = sc.add("DE", _sin_ratio, dev, g["alpha_allow"], role=Role.MEASUREMENT, unit="mm",
                    caption=(f"Shortest coupler DE = GM / sin αallow, αallow = {g['alpha_allow']:g}°",
                             f"最短连杆 DE = GM / sin[α],[α] = {g['alpha_allow']:g}°"))
    elif g.get("DE") is not None:
        DE = sc.add("DE", float, g["DE"], role=Role.MEASUREMENT, unit="mm", caption=(f"Coupler DE = {g['DE']:g}", f"连杆 DE = {g['DE']:g}"))
    else:
        DE = None
    if DE is not None:
        sc.add("alpha_max", _pressure, dev, DE, role=Role.MEASUREMENT, unit="deg",
               caption=("Largest pressure angle at the ram, asin(GM / DE)", "滑块最大压力角 asin(GM/DE)"))
        if drawing:
            kE = sc.add("kE", circle, D1, DE, visible=False)
            E1 = sc.add("E1", line_circle, guide, kE, branch=NearestTo(G), role=Role.RESULT, style="joint", label="E1",
                        caption=("E1 on the guide at DE from D1", "以 D1 为圆心、DE 为半径画弧交导路于 E1"))
            add_bar(sc, "D1E1", D1, E1, ("Coupler D1E1", "连杆 D1E1"))
            sc.add("slider_E1", marks.slider, E1, Point(1.0, 0.0), role=Role.ANNOTATION, style="slider")
            # the ram's other end of stroke: D2's position drawn with its coupler and block, as D1's (001-20 drew
            # the ram at E1 only while h, f and αmax are read over the whole stroke E1E2)
            kE2 = sc.add("kE2", circle, D2, DE, visible=False)
            E2 = sc.add("E2", line_circle, guide, kE2, branch=FarthestFrom(G), role=Role.RESULT, style="joint",
                        label="E2", caption=("E2 on the guide at DE from D2: E1E2 = D1D2 = H",
                                             "以 D2 为圆心、DE 为半径画弧交导路于 E2,E1E2 = D1D2 = H"))
            add_bar(sc, "D2E2", D2, E2, style="link-alt")
            sc.add("slider_E2", marks.slider, E2, Point(1.0, 0.0), role=Role.ANNOTATION, style="slider")
            sc.add("ram_guide_mark", _ram_guide, guide, D1, D2, E1, E2, role=Role.ANNOTATION, style="guide",
                   caption=("The ram's guide over the stroke", "滑枕(刨头)导路"))
    names = [q.name for q in SHAPER_ANSWERS if DE is not None or q.name not in ("DE", "alpha_max")]
    return Construction(sc, {n: n for n in names}, {n: n for n in ("A", "C", "B1", "B2", "D1", "D2")})


def guide_analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """sin(θ/2) = AB/AC."""
    return [guide_bar_design(g["K"], AC=g.get("AC"), AB=g.get("AB"))]


def shaper_analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """H = 2·CD·sin(θ/2), h = CD(1 + cos(θ/2))/2, DE = deviation / sin α."""
    r = shaper_design(g["K"], g["H"], AC=g.get("AC"), AB=g.get("AB"), alpha_allow=g.get("alpha_allow"))
    if g.get("alpha_allow") is not None:
        r["DE"] = r.pop("DE_min")
        r["alpha_max"] = g["alpha_allow"]
    elif g.get("DE") is not None:
        r["DE"] = g["DE"]
        r["alpha_max"] = math.degrees(math.asin(min(1.0, r["deviation"] / g["DE"])))
    return [r]


def guide_back_check(g: Mapping[str, Any], ans: Mapping[str, float]) -> list[tuple[str, float, float, str]]:
    """Rebuild with ``guide_bar.extremes``: K and ψ must come back."""
    return _guide_rows(g, ans, _rebuilt(ans))


def _rebuilt(ans: Mapping[str, float]) -> dict[str, float]:
    """K and ψ of the designed guide-bar, rebuilt as a solve builds ``guide_bar.extremes`` (its tape once
    recorded: :func:`~geomcon.recipes.common.rebuilt_values`), not by running its recipe again each time."""
    return rebuilt_values("guide_bar.extremes", {"AB": ans["AB"], "AC": ans["AC"]}, ("K", "psi"))


def _guide_rows(g: Mapping[str, Any], ans: Mapping[str, float], v: Mapping[str, float]) -> list[tuple[str, float, float, str]]:
    return [("K", v["K"], g["K"], ""), ("psi", v["psi"], ans["psi"], "deg")]


def shaper_back_check(g: Mapping[str, Any], ans: Mapping[str, float]) -> list[tuple[str, float, float, str]]:
    """Guide-bar part rebuilt by ``guide_bar.extremes`` (once: K and ψ); the stroke 2·CD·sin(ψ/2) must give
    H back."""
    v = _rebuilt(ans)
    rows = _guide_rows(g, ans, v)
    rows.append(("H", 2 * ans["CD"] * math.sin(math.radians(v["psi"] / 2)), g["H"], "mm"))
    return rows


GUIDE_RECIPE = Recipe(
    name="guide_bar.design_by_K",
    title="Oscillating guide-bar designed from K and AC or AB",
    givens=GUIDE_GIVENS, answers=GUIDE_ANSWERS, points=("A", "C", "B1", "B2"),
    construct=guide_construct, analytic=guide_analytic, validate=_validate, back_check=guide_back_check,
)
SHAPER_RECIPE = Recipe(
    name="shaper.design_by_K",
    title="Shaper / slotter guide-bar six-bar designed from K, the stroke H and AC or AB",
    givens=SHAPER_GIVENS, answers=SHAPER_ANSWERS, points=("A", "C", "B1", "B2", "D1", "D2"),
    construct=shaper_construct, analytic=shaper_analytic, validate=_validate, back_check=shaper_back_check,
)
