"""``crank_slider.extremes``: the extreme positions of an offset crank-slider.

Construction (A at the origin, the guide the horizontal line at distance e below A, the slider to the right
of A): the circles about A of radii BC − AB and BC + AB meet the guide at C1 (folded) and C2 (extended);
H = C1C2, θ = ∠C1AC2. The largest pressure angle at the slider occurs with the crank perpendicular to the
guide on the far side (B3); over the slow stroke the largest is at C1 or with the crank towards the guide (B4).
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.linkages import crank_slider_extremes
from ..errors import NotAMechanism
from ..geometry import Line, Point, ToRightOf, circle, line_circle, perpendicular, segment
from ..scene import Ref, Role, Scene, marks
from ..scene.tape import lifted
from ..tolerance import is_zero
from .base import Construction, Quantity, Recipe
from .common import (add_angle_mark, add_bar, add_collinear_extremes, add_pivot, add_theta_and_K, along_line,
                     complement_deg, guide_angle_mark, guide_between, largest, length, pressure_deg)

GIVENS = (
    Quantity("AB", "mm", "crank"),
    Quantity("BC", "mm", "connecting rod"),
    Quantity("e", "mm", "offset: distance of the guide from A", minimum=0.0, inclusive=True),
)
ANSWERS = (
    Quantity("H", "mm", "stroke C1C2"),
    Quantity("theta", "deg", "crank angle between the extreme positions, ∠C1AC2"),
    Quantity("K", "", "time-ratio coefficient"),
    Quantity("alpha_max", "deg", "largest pressure angle at the slider (crank perpendicular to the guide, far side)"),
    Quantity("gamma_min", "deg", "smallest transmission angle, 90° − αmax"),
    Quantity("gamma_min_fast", "deg", "smallest transmission angle over the fast stroke (crank turning 180° − θ)"),
    Quantity("gamma_min_slow", "deg", "smallest transmission angle over the slow stroke (crank turning 180° + θ)"),
)


def crank_condition(AB: float, BC: float, e: float) -> list[str]:
    """Refuse a crank-slider whose AB cannot turn fully (AB + e > BC); warn at equality.

    Examples
    --------
    >>> crank_condition(50, 120, 20)
    []
    """
    if AB + e > BC and not is_zero(AB + e - BC, BC):
        raise NotAMechanism(f"AB is not a crank: AB + e = {AB:g} + {e:g} = {AB + e:g} > BC = {BC:g}")
    if is_zero(AB + e - BC, BC):
        return [f"AB + e = BC = {BC:g}: the rod is perpendicular to the guide at one position (αmax = 90°)"]
    return []


def _validate(g: Mapping[str, Any]) -> list[str]:
    return crank_condition(g["AB"], g["BC"], g["e"])


def _gap(AB: float, BC: float, e: float) -> float:
    """BC − AB − e, correctly rounded (the margin of the largest pressure angle)."""
    return math.fsum((BC, -AB, -e))


def construct(g: Mapping[str, Any]) -> Construction:
    """Build the extreme-position construction of the offset crank-slider."""
    AB, BC, e = g["AB"], g["BC"], g["e"]
    sc = Scene("Offset crank-slider: extreme positions")
    A = add_pivot(sc, "A", Point(0.0, 0.0), ("Fixed pivot A at the origin", "取固定铰链 A 为原点"))
    F = sc.given_at("F", 0.0, -e, style="point",
                    caption=(f"F below A with AF = e = {e:g}", f"在 A 下方取 AF = e = {e:g}"))
    gl = sc.add("guide", Line, F, Point(1.0, 0.0), role=Role.GIVEN, style="given",
                caption=("The slider's guide through F, perpendicular to AF", "过 F 作导路(垂直于 AF)"))
    drawing = sc.drawing                     # the links, sliders, marks and dimensions only a drawing needs
    if drawing and e > 0:
        # dimension on the left of F→A, away from the crank and the slider
        sc.add("dim_e", marks.dimension, F, A, "e", e, 0.25 * (BC + AB) / 2, role=Role.ANNOTATION, style="dim",
               caption=("Dimension the offset e", "标注偏距 e"))
    B1, C1, B2, C2 = add_collinear_extremes(sc, A, gl, AB, BC, ToRightOf(A), line_circle, ("the guide", "导路"))
    for i, (B, C) in enumerate(((B1, C1), (B2, C2)), 1) if drawing else ():
        style = "link" if i == 1 else "link-alt"
        how = ("folded", "重叠") if i == 1 else ("extended", "拉直")
        add_bar(sc, f"AB{i}", A, B, (f"Draw the {how[0]} position AB{i}C{i}", f"画出{how[1]}共线位置 AB{i}C{i}"), style=style)
        add_bar(sc, f"B{i}C{i}", B, C, style=style)
        sc.add(f"slider{i}", marks.slider, C, Point(1.0, 0.0), role=Role.ANNOTATION, style="slider")
    if drawing:
        sc.add("guide_mark", guide_between, C1, C2, gl, 0.2 * (BC + AB) / 2, role=Role.ANNOTATION, style="guide")
        sc.add("AC2", segment, A, C2, style="construction", caption=("Join AC2", "连接 AC2"))
    H = sc.add("H", length, C1, C2, role=Role.MEASUREMENT, unit="mm",
               caption=("Measure the stroke H = C1C2", "量得滑块行程 H = C1C2"))
    th = add_theta_and_K(sc, A, C1, C2)
    add_pressure_angles(sc, A, B1, C1, gl, AB, BC, lifted(_gap, AB, BC, e))
    if drawing:
        add_angle_mark(sc, "mark_theta", A, C1, C2, "θ", th)
        sc.add("dim_H", marks.dimension, C1, C2, "H", H, -0.3 * (BC + AB) / 2, role=Role.ANNOTATION, style="dim",
               caption=("Dimension the stroke H", "标注行程 H"))
    names = [q.name for q in ANSWERS]
    return Construction(sc, {n: n for n in names}, {n: n for n in ("A", "B1", "C1", "B2", "C2")})


def pressure_from_gap(BC: float, gap: float) -> float:
    """The pressure angle (deg) at the slider with the crank perpendicular to the guide, away from it: B is
    BC − gap from the guide, so cos α = √(gap·(2BC − gap))/BC. The gap is passed in, formed without
    cancellation, so that α near 90° (the rod nearly perpendicular to the guide, gap → 0) keeps its accuracy
    instead of going through the near-tangent circle about B3.

    >>> round(pressure_from_gap(5.0, 1.0), 12), pressure_from_gap(5.0, 0.0)
    (53.130102354156, 90.0)
    """
    gap = max(0.0, gap)
    return math.degrees(math.atan2(BC - gap, math.sqrt(gap * (2.0 * BC - gap))))


def add_pressure_angles(sc: Scene, A: Ref, B1: Ref, C1: Ref, gl: Ref, AB, BC, gap) -> Ref:
    """The pressure angles that decide γmin: crank perpendicular to the guide away from it (B3, the largest
    of the cycle, in the fast stroke) and towards it (B4), and the folded position C1 (slow stroke).

    ``AB`` and ``BC`` are numbers or references to measured lengths; ``gap`` is BC − AB − e (a number or a
    reference), how far B3 stays short of the guide by the rod's length, formed by the caller without
    cancellation: αmax is measured from it (:func:`pressure_from_gap`). Adds ``alpha_max``, ``gamma_min``,
    ``gamma_min_fast``, ``gamma_min_slow`` and the αmax angle mark; returns ``gamma_min``.
    """
    drawing = sc.drawing
    nA = sc.add("nA", perpendicular, gl, A, caption=("Perpendicular to the guide through A", "过 A 作导路的垂线"))
    pos = {}
    for i, (sign, en, zh) in ((3, (1.0, "away from the guide", "远离导路")), (4, (-1.0, "towards the guide", "指向导路"))):
        if i == 3 and not drawing:           # C3 is drawn; αmax is measured from the gap
            continue
        B = sc.add(f"B{i}", along_line, nA, AB, sign, style="point", label=f"B{i}",
                   caption=(f"Crank perpendicular to the guide, {en}: B{i}", f"曲柄垂直于导路且{zh}:B{i}"))
        kB = sc.add(f"kB{i}", circle, B, BC, caption=(f"Circle about B{i} with radius BC", f"以 B{i} 为圆心、BC 为半径作圆"))
        C = sc.add(f"C{i}", line_circle, gl, kB, branch=ToRightOf(B), style="point", label=f"C{i}",
                   caption=(f"It meets the guide at C{i}", f"交导路于 C{i}"))
        if drawing:
            add_bar(sc, f"AB{i}", A, B, style="ghost", role=Role.CONSTRUCTION)
            add_bar(sc, f"B{i}C{i}", B, C, style="ghost", role=Role.CONSTRUCTION)
        pos[i] = (B, C)
    a3 = sc.add("alpha_3", pressure_from_gap, BC, gap, role=Role.MEASUREMENT, unit="deg",
                caption=("Pressure angle at C3 (largest of the cycle): cos α = √(g(2BC − g))/BC, B3 short of "
                         "the guide by g = BC − AB − e", "C3 处压力角(全周最大):cos α = √(g(2BC − g))/BC"))
    a4 = sc.add("alpha_4", pressure_deg, *pos[4], gl, role=Role.MEASUREMENT, unit="deg",
                caption=("Pressure angle at C4", "C4 处压力角"))
    a1 = sc.add("alpha_1", pressure_deg, B1, C1, gl, role=Role.MEASUREMENT, unit="deg",
                caption=("Pressure angle at C1", "C1 处压力角"))
    sc.add("alpha_max", largest, a3, role=Role.MEASUREMENT, unit="deg", visible=False)
    sc.add("gamma_min", complement_deg, a3, role=Role.MEASUREMENT, unit="deg",
           caption=("γmin = 90° − αmax", "最小传动角 γmin = 90° − αmax"))
    sc.add("gamma_min_fast", complement_deg, a3, role=Role.MEASUREMENT, unit="deg", visible=False)
    slow = sc.add("alpha_slow", largest, a1, a4, role=Role.MEASUREMENT, unit="deg", visible=False)
    sc.add("gamma_min_slow", complement_deg, slow, role=Role.MEASUREMENT, unit="deg",
           caption=("Slow stroke: γmin = 90° − max(α at C1, α at C4)", "慢行程最小传动角 = 90° − max(α1, α4)"))
    if drawing:
        sc.add("mark_alpha", guide_angle_mark, *reversed(pos[3]), gl, "αmax", a3, role=Role.ANNOTATION, style="angle")
    return Ref("gamma_min")


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """The right-triangle twin."""
    return [crank_slider_extremes(g["AB"], g["BC"], g["e"])]


RECIPE = Recipe(
    name="crank_slider.extremes",
    title="Offset crank-slider: stroke H, θ, K, αmax, γmin",
    givens=GIVENS,
    answers=ANSWERS,
    points=("A", "B1", "C1", "B2", "C2"),
    construct=construct,
    analytic=analytic,
    validate=_validate,
)
