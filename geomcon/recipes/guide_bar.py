"""``guide_bar.extremes``: the extreme positions of the oscillating guide-bar (crank AB about A, guide
bar about C, frame AC, AB < AC).

Construction (A at the origin, C below A at distance AC): the guide bar is at an extreme position when it
is tangent to the crank circle, i.e. when ∠ABC = 90°; so the circle on AC as diameter meets the crank circle
at B1 and B2. ψ = ∠B1CB2 and θ = the angle between AB2 and B1A extended (θ = ψ).
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.linkages import guide_bar_extremes
from ..errors import NotAMechanism
from ..geometry import Point, ToLeftOf, ToRightOf, circle, circle_circle, point_along, segment, thales_circle
from ..scene import Role, Scene, marks
from . import guide_bar_offset as offset
from .base import Construction, Quantity, Recipe
from .common import add_angle_mark, add_bar, add_pivot, angle_deg, k_ratio

GIVENS = (
    Quantity("AB", "mm", "crank"),
    Quantity("AC", "mm", "frame: distance between the crank pivot A and the guide-bar pivot C"),
) + offset.GIVENS
ANSWERS = (
    Quantity("theta", "deg", "crank angle between the extreme positions"),
    Quantity("psi", "deg", "swing of the guide bar, ∠B1CB2"),
    Quantity("K", "", "time-ratio coefficient"),
) + offset.ANSWERS


def _offset(g: Mapping[str, Any]) -> bool:
    """An offset guide or a lever given: the construction of :mod:`.guide_bar_offset`."""
    return bool(g.get("e")) or g.get("L") is not None


def _validate(g: Mapping[str, Any]) -> list[str]:
    if _offset(g):
        return offset.validate(g)
    if g["AB"] >= g["AC"]:
        raise NotAMechanism(f"AB = {g['AB']:g} ≥ AC = {g['AC']:g}: the guide bar turns fully (rotating "
                            "guide-bar), it has no extreme positions")
    return []


def construct(g: Mapping[str, Any]) -> Construction:
    """Build the tangent-position construction."""
    if _offset(g):
        return offset.construct(g)
    AB, AC = g["AB"], g["AC"]
    sc = Scene("Oscillating guide-bar: extreme positions")
    A = add_pivot(sc, "A", Point(0.0, 0.0), ("Crank pivot A at the origin", "取曲柄转动中心 A 为原点"))
    C = add_pivot(sc, "C", (0.0, -AC), (f"Guide-bar pivot C below A, AC = {AC:g}", f"在 A 下方取 C,使 AC = {AC:g}"))
    drawing = sc.drawing                     # the links, blocks, marks only a drawing needs
    if drawing:
        sc.add("AC", segment, A, C, role=Role.GIVEN, style="frame", caption=("Draw the frame AC", "作机架 AC"))
    kB = sc.add("kB", circle, A, AB, style="path", caption=(f"The path of B: circle about A with radius AB = {AB:g}",
                                                            f"以 A 为圆心、AB = {AB:g} 为半径作 B 点轨迹圆"))
    kT = sc.add("kT", thales_circle, A, C, caption=("Circle on AC as diameter (it sees AC at 90°)",
                                                    "以 AC 为直径作圆(圆上各点对 AC 张直角)"))
    B1 = sc.add("B1", circle_circle, kB, kT, branch=ToLeftOf(A), role=Role.RESULT, style="joint", label="B1",
                caption=("It meets the crank circle at B1: CB1 tangent to the crank circle", "交曲柄圆于 B1(CB1 与曲柄圆相切)"))
    B2 = sc.add("B2", circle_circle, kB, kT, branch=ToRightOf(A), role=Role.RESULT, style="joint", label="B2",
                caption=("and at B2", "及 B2"))
    L = AC + AB
    for i, B in enumerate((B1, B2), 1) if drawing else ():
        style = "link" if i == 1 else "link-alt"
        E = sc.add(f"E{i}", point_along, C, B, L, visible=False)
        add_bar(sc, f"AB{i}", A, B, (f"Extreme position {i}: crank AB{i}, guide bar CB{i}", f"极限位置 {i}:曲柄 AB{i}、导杆 CB{i}"), style=style)
        add_bar(sc, f"CE{i}", C, E, style=style)
        sc.add(f"slider{i}", _block_along, B, C, role=Role.ANNOTATION, style="slider")
        sc.add(f"right{i}", marks.right_angle, B, A, C, role=Role.ANNOTATION, style="right-angle")
    B1x = sc.add("B1x", point_along, A, B1, -AB, visible=False)
    if drawing:
        sc.add("ext1", segment, A, B1x, style="construction", caption=("Extend B1A beyond A", "延长 B1A"))
    ps = sc.add("psi", angle_deg, C, B1, B2, role=Role.MEASUREMENT, unit="deg",
                caption=("Measure the swing ψ = ∠B1CB2", "量得导杆摆角 ψ = ∠B1CB2"))
    th = sc.add("theta", angle_deg, A, B1x, B2, role=Role.MEASUREMENT, unit="deg",
                caption=("Measure θ between AB2 and B1A extended", "量得极位夹角 θ(AB2 与 B1A 延长线的夹角)"))
    sc.add("K", k_ratio, th, role=Role.MEASUREMENT, caption=("K = (180° + θ)/(180° − θ)", "K = (180° + θ)/(180° − θ)"))
    if drawing:
        add_angle_mark(sc, "mark_psi", C, B1, B2, "ψ", ps)
        add_angle_mark(sc, "mark_theta", A, B1x, B2, "θ", th)
    return Construction(sc, {q.name: q.name for q in ANSWERS[:3]}, {n: n for n in ("A", "C", "B1", "B2")})


def _block_along(b: Point, c: Point) -> marks.Slider:
    return marks.Slider(b, b - c)


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """The twin sin(ψ/2) = AB/AC (offset: cos β = (e ± AB)/AC)."""
    if _offset(g):
        return offset.analytic(g)
    return [guide_bar_extremes(g["AB"], g["AC"])]


RECIPE = Recipe(
    name="guide_bar.extremes",
    title="Oscillating guide-bar: θ, ψ, K",
    givens=GIVENS,
    answers=ANSWERS,
    points=("A", "C", "B1", "B2"),
    construct=construct,
    analytic=analytic,
    validate=_validate,
)
del math
