"""``rotating_guide_bar.extremes``: the Whitworth quick-return (rotating guide-bar, crank AB longer than the
frame AC) and the ram it drives.

Construction (A at the origin, C below A at AC; the ram's guide through C perpendicular to AC, the
textbook's arrangement): the guide bar turns fully with the crank; the ram is at an extreme when the bar's arm
CD lies along the ram's guide, i.e. when the crank pin B is on that line: the crank circle meets the line at
B1 and B2. The crank turns through φ_quick = ∠B1AB2 (the arc past C) while the ram makes one stroke and
through φ_slow = 360° − φ_quick for the other; θ = 180° − φ_quick, K = φ_slow/φ_quick. With the arm CD the
ends D1, D2 lie on CB1, CB2 at CD from C, and the ram's stroke is S = D1D2 = 2·CD.
"""
from __future__ import annotations

from typing import Any, Mapping

from ..analytic.guide_bar_offset import rotating_guide_bar_extremes
from ..errors import NotAMechanism
from ..geometry import Leftmost, Point, Rightmost, circle, line_circle, line_through, point_along, segment
from ..scene import Role, Scene, marks
from .base import Construction, Quantity, Recipe
from .common import add_angle_mark, add_bar, add_pivot, angle_deg, difference, length, stroke_dimension

GIVENS = (
    Quantity("AB", "mm", "crank (longer than the frame: the guide bar turns fully)"),
    Quantity("AC", "mm", "frame: distance between the crank pivot A and the guide bar's pivot C"),
    Quantity("CD", "mm", "the guide bar's arm driving the ram (its guide through C, perpendicular to AC)",
             required=False),
)
ANSWERS = (
    Quantity("theta", "deg", "crank angle between the ram's extreme positions, 180° − φ_quick"),
    Quantity("K", "", "time-ratio coefficient φ_slow/φ_quick"),
    Quantity("phi_slow", "deg", "the crank's turn during the slow (working) stroke"),
    Quantity("phi_quick", "deg", "the crank's turn during the quick (return) stroke, ∠B1AB2"),
    Quantity("S", "mm", "the ram's stroke D1D2 = 2·CD"),
)


def _validate(g: Mapping[str, Any]) -> list[str]:
    if g["AB"] <= g["AC"]:
        raise NotAMechanism(f"AB = {g['AB']:g} ≤ AC = {g['AC']:g}: the guide bar only swings (oscillating guide-bar, "
                            "guide_bar.extremes); a rotating guide-bar needs the crank longer than the frame")
    return []


def _block(at: Point, c: Point, cr: Point) -> marks.Slider:
    """A slider block at ``at`` moving along the guide c→cr."""
    return marks.Slider(at, cr - c)


def _farther(c: Point, b: Point, d: Point) -> Point:
    """The guide bar's end from C: the farther of the block's pin B and the arm's end D (the bar carries both)."""
    return d if abs(d - c) >= abs(b - c) else b


def _ratio(slow: float, quick: float) -> float:
    return slow / quick


def _full_turn(x: float) -> float:
    return 360.0 - x


def construct(g: Mapping[str, Any]) -> Construction:
    """The crank circle meets the ram's guide through C at the extreme positions B1, B2."""
    AB, AC, CD = g["AB"], g["AC"], g.get("CD")
    sc = Scene("Rotating guide-bar (Whitworth): the ram's extreme positions")
    A = add_pivot(sc, "A", Point(0.0, 0.0), ("Crank pivot A at the origin", "取曲柄转动中心 A 为原点"))
    C = add_pivot(sc, "C", (0.0, -AC), (f"Guide-bar pivot C below A, AC = {AC:g}", f"在 A 下方取 C,使 AC = {AC:g}"))
    drawing = sc.drawing
    if drawing:
        sc.add("AC", segment, A, C, role=Role.GIVEN, style="frame", caption=("Draw the frame AC", "作机架 AC"))
    kB = sc.add("kB", circle, A, AB, style="path", caption=(f"The path of B: circle about A with radius AB = {AB:g}",
                                                            f"以 A 为圆心、AB = {AB:g} 为半径作 B 点轨迹圆"))
    Cr = sc.add("Cr", Point, 1.0, -AC, visible=False)
    guide = sc.add("guide", line_through, C, Cr, style="construction",
                   caption=("The ram's guide: the line through C perpendicular to AC", "滑枕导路:过 C 垂直于 AC 的直线"))
    B1 = sc.add("B1", line_circle, guide, kB, branch=Leftmost(), role=Role.RESULT, style="joint", label="B1",
                caption=("It meets the crank circle at B1: the bar along the guide, the ram at one extreme",
                         "交曲柄圆于 B1:导杆与导路重合,滑枕处于一极限位置"))
    B2 = sc.add("B2", line_circle, guide, kB, branch=Rightmost(), role=Role.RESULT, style="joint", label="B2",
                caption=("and at B2: the other extreme", "及 B2:另一极限位置"))
    if drawing:
        add_bar(sc, "AB1", A, B1, ("Crank positions AB1, AB2", "曲柄位置 AB1、AB2"))
        add_bar(sc, "AB2", A, B2, style="link-alt")
        for i, B in enumerate((B1, B2), 1):      # B's block on the guide bar, which lies along the guide here
            if CD is None:
                add_bar(sc, f"CB{i}", C, B, style="link" if i == 1 else "link-alt")
            sc.add(f"slider{i}", _block, B, C, Cr, role=Role.ANNOTATION, style="slider")
    quick = sc.add("phi_quick", angle_deg, A, B1, B2, role=Role.MEASUREMENT, unit="deg",
                   caption=("The quick stroke: the crank turns through φ_quick = ∠B1AB2 (past C)",
                            "空回行程曲柄转角 φ_quick = ∠B1AB2(经过 C 一侧)"))
    slow = sc.add("phi_slow", _full_turn, quick, role=Role.MEASUREMENT, unit="deg",
                  caption=("The working stroke: φ_slow = 360° − φ_quick", "工作行程曲柄转角 φ_slow = 360° − φ_quick"))
    th = sc.add("theta", difference, 180.0, quick, role=Role.MEASUREMENT, unit="deg",
           caption=("θ = 180° − φ_quick", "极位夹角 θ = 180° − φ_quick"))
    sc.add("K", _ratio, slow, quick, role=Role.MEASUREMENT, caption=("K = φ_slow/φ_quick", "K = φ_slow/φ_quick"))
    answers = {q.name: q.name for q in ANSWERS[:4]}
    points = {n: n for n in ("A", "C", "B1", "B2")}
    if CD is not None:
        Ds = [sc.add(f"D{i}", point_along, C, B, CD, role=Role.RESULT, style="joint", label=f"D{i}",
                     caption=(f"The arm's end D{i} on CB{i} at CD = {CD:g} from C", f"在 CB{i} 上截取 CD = {CD:g} 得 D{i}"))
              for i, B in enumerate((B1, B2), 1)]
        if drawing:
            for i, (B, D) in enumerate(zip((B1, B2), Ds), 1):
                end = sc.add(f"bar_end{i}", _farther, C, B, D, visible=False)
                add_bar(sc, f"CD{i}", C, end, style="link" if i == 1 else "link-alt")
                sc.add(f"ram{i}", _block, D, C, Cr, role=Role.ANNOTATION, style="slider", caption=(
                    "The ram at its ends of stroke at D1 and D2 (there the coupler DE lies along the stroke line, so E "
                    "moves by D1D2)", "滑枕位于行程两端 D1、D2 处(此时连杆 DE 沿导路,E 的行程等于 D1D2)") if i == 1 else ("", ""))
        S = sc.add("S", length, Ds[0], Ds[1], role=Role.MEASUREMENT, unit="mm",
                   caption=("The ram's stroke S = D1D2", "滑枕行程 S = D1D2"))
        if drawing:
            sc.add("dim_S", stroke_dimension, Ds[0], Ds[1], A, "S", S, role=Role.ANNOTATION, style="dim",
                   caption=("Dimension the stroke S", "标注行程 S"))
        answers["S"] = "S"
        points |= {"D1": "D1", "D2": "D2"}
    if drawing:
        add_angle_mark(sc, "mark_quick", A, B1, B2, "φ_quick", quick)
        B1x = sc.add("B1x", point_along, A, B1, -AB, visible=False)
        sc.add("ext1", segment, A, B1x, style="construction", caption=("θ between AB2 and B1A extended",
                                                                       "极位夹角 θ:AB2 与 B1A 延长线的夹角"))
        add_angle_mark(sc, "mark_theta", A, B1x, B2, "θ", th)
    return Construction(sc, answers, points)


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """The twin φ_quick = 2·acos(AC/AB) (:func:`geomcon.analytic.guide_bar_offset.rotating_guide_bar_extremes`)."""
    return [rotating_guide_bar_extremes(g["AB"], g["AC"], g.get("CD"))]


RECIPE = Recipe(
    name="rotating_guide_bar.extremes",
    title="Rotating guide-bar (Whitworth): the ram's extreme positions, θ, K, stroke",
    givens=GIVENS,
    answers=ANSWERS,
    points=("A", "C", "B1", "B2", "D1", "D2"),
    construct=construct,
    analytic=analytic,
    validate=_validate,
)
