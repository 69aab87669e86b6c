"""``guide_bar.extremes`` with an offset guide (``e``) or a lever (``L``): the extreme positions of an
oscillating guide-bar whose guide line runs at the distance e from the pivot C, and the shaper's ram stroke.

Construction (A at the origin, C below A at AC): the guide line touches the circle of radius e about C; at
an extreme position it touches the crank circle too, so it is a common tangent of the two circles. Its
parallel through C lies at AB + e (one extreme) and |AB − e| (the other) from A: the circle on AC as
diameter meets the circles of those radii about A at T1 and T2, the feet of A on the parallels; B1, B2 lie
on AT1, AT2 at the crank's length from A, and the guide lines through them are parallel to CT1, CT2. ψ is
the angle between CT1 and CT2, θ the angle between AB2 and B1A extended (θ = ψ: the crank is perpendicular
to the guide at both extremes). With the lever CD = L the ends D1, D2 lie on the bar's lines at L from C,
and a ram driven from D moves H = D1D2 = 2·L·sin(ψ/2) (the shaper). The drawing shows each extreme bar as
the textbook's rigid L: the arm of length e from C, perpendicular to the guide, to the guide's foot, then
the guide itself.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.guide_bar_offset import guide_bar_offset_extremes
from ..errors import NotAMechanism
from ..geometry import Point, ToLeftOf, ToRightOf, circle, circle_circle, point_along, rotate, segment, thales_circle
from ..scene import Role, Scene, marks
from .base import Construction, Quantity
from .common import add_angle_mark, add_bar, add_pivot, angle_deg, k_ratio, length, stroke_dimension, total

GIVENS = (
    Quantity("e", "mm", "offset of the guide line from the guide bar's pivot C (0: the guide passes through C)",
             required=False, inclusive=True),
    Quantity("L", "mm", "length of the guide bar CD (the shaper's slotted lever): the stroke H of a ram at D",
             required=False),
)
ANSWERS = (Quantity("H", "mm", "stroke of the lever's end D between the extreme positions, 2·L·sin(ψ/2)"),)


def validate(g: Mapping[str, Any]) -> list[str]:
    """The crank condition AC > AB + e (seed 001-04), with the rotating case named."""
    AB, AC, e = g["AB"], g["AC"], g.get("e") or 0.0
    if AC <= AB + e:
        if AC < AB - e:
            raise NotAMechanism(f"AC = {AC:g} < AB − e = {AB - e:g}: the guide bar turns fully (rotating guide-bar, "
                                "rotating_guide_bar.extremes); it has no extreme positions")
        raise NotAMechanism(f"AB is not a crank: AC = {AC:g} ≤ AB + e = {AB:g} + {e:g} = {AB + e:g} (the crank pin "
                            "would have to pass within e of C)")
    return []


def construct(g: Mapping[str, Any]) -> Construction:
    """The common tangents of the crank circle and the offset circle."""
    AB, AC, e, L = g["AB"], g["AC"], g.get("e") or 0.0, g.get("L")
    sc = Scene("Offset oscillating guide-bar: extreme positions")
    A = add_pivot(sc, "A", Point(0.0, 0.0), ("Crank pivot A at the origin", "取曲柄转动中心 A 为原点"))
    C = add_pivot(sc, "C", (0.0, -AC), (f"Guide-bar pivot C below A, AC = {AC:g}", f"在 A 下方取 C,使 AC = {AC:g}"))
    drawing = sc.drawing
    if drawing:
        sc.add("AC", segment, A, C, role=Role.GIVEN, style="frame", caption=("Draw the frame AC", "作机架 AC"))
        sc.add("kB", circle, A, AB, style="path", caption=(f"The path of B: circle about A with radius AB = {AB:g}",
                                                         f"以 A 为圆心、AB = {AB:g} 为半径作 B 点轨迹圆"))
        if e > 0:
            sc.add("ke", circle, C, e, caption=(f"The guide line touches the circle about C with radius e = {e:g}",
                                                f"导路与以 C 为圆心、e = {e:g} 为半径的圆相切"))
    kT = sc.add("kT", thales_circle, A, C, caption=("Circle on AC as diameter (it sees AC at 90°)",
                                                    "以 AC 为直径作圆(圆上各点对 AC 张直角)"))
    Bs, Ts = [], []
    for i, (r, words, right) in enumerate(((AB + e, ("AB + e", "AB + e"), True),
                                           (abs(AB - e), ("|AB − e|", "|AB − e|"), e > AB)), 1):
        if i == 2 and AB == e:                   # the parallel through C passes through A: B2 ⊥ AC at A
            Ts.append(A)
            Bs.append(sc.add("B2", point_along, A, sc.add("T2", rotate, C, A, -math.pi / 2, visible=False), AB,
                             role=Role.RESULT, style="joint", label="B2",
                             caption=("AB = e: B2 on the perpendicular to AC at A", "AB = e:B2 在过 A 垂直于 AC 的直线上")))
            continue
        rad = sc.add(f"r{i}", total if i == 1 else _abs_diff, AB, e, visible=False, unit="mm")
        kr = sc.add(f"kr{i}", circle, A, rad, caption=(f"Circle about A with radius {words[0]} = {r:g}",
                                                       f"以 A 为圆心、{words[1]} = {r:g} 为半径作圆"))
        T = sc.add(f"T{i}", circle_circle, kT, kr, branch=ToRightOf(A) if right else ToLeftOf(A), style="point",
                   label=f"T{i}", caption=(f"It meets the circle on AC at T{i}: CT{i} is the bar's line through C",
                                           f"交 AC 上的圆于 T{i}:CT{i} 为过 C 的导杆方向"))
        Ts.append(T)
        sign = 1.0 if i == 1 or AB > e else -1.0
        Bs.append(sc.add(f"B{i}", point_along, A, T, sign * AB, role=Role.RESULT, style="joint", label=f"B{i}",
                         caption=(f"B{i} on AT{i} at AB from A: the guide through B{i} ∥ CT{i} touches both circles",
                                  f"在 AT{i} 上截取 AB 得 B{i}:过 B{i} 平行于 CT{i} 的导路与两圆相切")))
    B1, B2 = Bs
    T1, T2 = Ts                       # the bar's direction at each extreme: C→T_i (the guide through B_i ∥ it)
    ps = sc.add("psi", angle_deg, C, T1, T2, role=Role.MEASUREMENT, unit="deg",
                caption=("Measure the swing ψ = ∠T1CT2", "量得导杆摆角 ψ = ∠T1CT2"))
    B1x = sc.add("B1x", point_along, A, B1, -AB, visible=False)
    if drawing:
        sc.add("ext1", segment, A, B1x, style="construction", caption=("Extend B1A beyond A", "延长 B1A"))
        for i, B in enumerate(Bs, 1):
            add_bar(sc, f"AB{i}", A, B, (f"Extreme position {i}: crank AB{i}", f"极限位置 {i}:曲柄 AB{i}"),
                    style="link" if i == 1 else "link-alt")
    th = sc.add("theta", angle_deg, A, B1x, B2, role=Role.MEASUREMENT, unit="deg",
                caption=("Measure θ between AB2 and B1A extended", "量得极位夹角 θ(AB2 与 B1A 延长线的夹角)"))
    sc.add("K", k_ratio, th, role=Role.MEASUREMENT, caption=("K = (180° + θ)/(180° − θ)", "K = (180° + θ)/(180° − θ)"))
    answers = {"theta": "theta", "psi": "psi", "K": "K"}
    points = {"A": "A", "C": "C", "B1": "B1", "B2": "B2"}
    Ds = []
    reach = L if L is not None else AC + AB
    for i, T in enumerate((T1, T2), 1):
        D = sc.add(f"D{i}", point_along, C, T, reach, role=Role.RESULT if L is not None else Role.CONSTRUCTION,
                   style="joint" if L is not None else "point", label=f"D{i}" if L is not None else None,
                   visible=L is not None,          # without a lever only the dashed line CT's far end: no point
                   caption=((f"The lever's end D{i} at L = {L:g} from C along CT{i}", f"在 CT{i} 上截取 CD{i} = L = {L:g}")
                            if L is not None else ("", "")))
        Ds.append(D)
        if drawing:
            B = Bs[i - 1]
            G = sc.add(f"G{i}", _guide_end, C, T, B, reach, visible=False)
            F = sc.add(f"G0{i}", _guide_end, C, T, B, 0.0, visible=False)        # the foot of C on the guide
            link = "link" if i == 1 else "link-alt"
            if e > 0:                     # the arm CF ⊥ the guide, length e: with the guide a rigid L about C
                sc.add(f"arm{i}", segment, C, F, style=link, role=Role.RESULT)
            sc.add(f"guide{i}", segment, F, G, style=link, role=Role.RESULT)
            sc.add(f"CD{i}", segment, C, D, style="ghost", role=Role.CONSTRUCTION)
            sc.add(f"slider{i}", _block_along, B, C, T, role=Role.ANNOTATION, style="slider")   # B's block on the bar
    if L is not None:
        if drawing:
            sc.add("D1D2", segment, Ds[0], Ds[1], style="construction", caption=("Join D1D2", "连接 D1D2"))
            for i, D in enumerate(Ds, 1):        # the ram's block at the lever's end, moving along D1D2
                sc.add(f"ram{i}", _ram_block, D, Ds[0], Ds[1], role=Role.ANNOTATION, style="slider")
        H = sc.add("H", length, Ds[0], Ds[1], role=Role.MEASUREMENT, unit="mm",
                   caption=("The ram's stroke H = D1D2", "滑枕行程 H = D1D2"))
        if drawing:
            sc.add("dim_H", stroke_dimension, Ds[0], Ds[1], A, "H", H, role=Role.ANNOTATION, style="dim",
                   caption=("Dimension the stroke H", "标注行程 H"))
        answers["H"] = "H"
        points |= {"D1": "D1", "D2": "D2"}
    if drawing:
        add_angle_mark(sc, "mark_psi", C, T1, T2, "ψ", ps)
        add_angle_mark(sc, "mark_theta", A, B1x, B2, "θ", th)
    return Construction(sc, answers, points)


def _block_along(b: Point, c: Point, t: Point) -> marks.Slider:
    """The slider block at ``b`` on the guide bar, whose line is parallel to c→t."""
    return marks.Slider(b, t - c)


def _ram_block(d: Point, d1: Point, d2: Point) -> marks.Slider:
    """The ram's block at the lever's end ``d``, sliding along the stroke D1D2."""
    return marks.Slider(d, d2 - d1)


def _abs_diff(a: float, b: float) -> float:
    return abs(a - b)


def _guide_end(c: Point, t: Point, b: Point, dist: float) -> Point:
    """The point at ``dist`` along the guide through ``b`` parallel to c→t, from the foot of ``c`` on it (the
    guide drawn from where the offset e meets it to the bar's length)."""
    ux, uy = t.x - c.x, t.y - c.y
    n = math.hypot(ux, uy)
    ux, uy = ux / n, uy / n
    s = (b.x - c.x) * ux + (b.y - c.y) * uy
    fx, fy = b.x - s * ux, b.y - s * uy                       # the foot of C on the guide line
    return Point(fx + dist * ux, fy + dist * uy)


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """The twin cos β = (e ± AB)/AC (:func:`geomcon.analytic.guide_bar_offset.guide_bar_offset_extremes`)."""
    return [guide_bar_offset_extremes(g["AB"], g["AC"], g.get("e") or 0.0, g.get("L"))]

