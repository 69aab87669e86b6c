"""``four_bar.instant_centres`` and ``crank_slider.instant_centres``: every instant centre of velocity (速度瞬心)
of the linkage at one crank position, the two that are not joints found by Kennedy's theorem (三心定理), and the
velocity ratios read from them.

Links: 1 the crank, 2 the coupler (rod), 3 the rocker (slider), 4 the frame. The joints are centres: P14 = A,
P12 = B, P23 = C, and P34 = D for the four-bar; the slider's P34 lies at infinity, perpendicular to the guide.
Kennedy: P13 lies on the line P12P23 and on the line P14P34; P24 on P12P14 and on P23P34. Then

- four-bar: ω3/ω1 = P14P13 / P34P13 (signed along the frame; both points of AD), ω2/ω1 = P14P12 / P24P12;
- crank-slider: P34 at infinity makes the line P14P34 the perpendicular to the guide through A and P23P34 the
  perpendicular through C; the slider moves as the crank's point P13 does: vC/ω1 = −(y of P13 − y of A) along +x,
  and ω2/ω1 = P14P12 / P24P12.

A centre at infinity of the four-bar (BC ∥ AD puts P13 there, AB ∥ CD P24) is refused with its meaning (the rocker
turns at the crank's rate; the coupler translates). Twins: the velocities by the complex vector loop
(:mod:`geomcon.analytic.kinematics`), P13 and P24 placed from them independently of any intersection.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.kinematics import crank_slider, four_bar
from ..errors import Degenerate
from ..geometry import Line, Point, line_line, line_through, perpendicular
from ..scene import Role, Scene, marks
from .base import Construction, Quantity, Recipe
from .kinematics_common import PHI, add_four_bar_at, add_slider_at, four_bar_assembles, slider_assembles
from .synthesis_common import xy

BRANCH = Quantity("branch", "choice", "assembly: C left (above) or right (below) of the directed line B→D",
                  required=False, default="above", minimum=None, choices=("above", "below"))


def kennedy(l1: Line, l2: Line, name: str) -> Point:
    """Where two lines of Kennedy's theorem meet; parallel lines put the centre at infinity (refused, named)."""
    pts = line_line(l1, l2)
    if len(pts) != 1:
        raise Degenerate(f"{name} lies at infinity: its two lines are parallel"
                         + (" (the rocker turns at the crank's rate)" if name == "P13" else " (the coupler translates)"))
    return pts[0]


def ratio_along(P: Point, fixed1: Point, fixed2: Point) -> float:
    """(P − fixed1)/(P − fixed2) for three collinear points, signed: the ratio of two angular velocities whose
    common instant centre is P and whose own centres are fixed1 and fixed2."""
    ux, uy = fixed2.x - fixed1.x, fixed2.y - fixed1.y
    a = (P.x - fixed1.x) * ux + (P.y - fixed1.y) * uy
    b = (P.x - fixed2.x) * ux + (P.y - fixed2.y) * uy
    return a / b


def towards_infinity(C: Point, guide: Line, size: float) -> Point:
    """The tip of the arrow from ``C`` that points, ``size`` mm long, to a centre at infinity perpendicular
    to ``guide``, drawn on the guide's side away from the crank (−y for a guide along +x).

    >>> towards_infinity(Point(2, 0), Line(Point(0, 0), Point(1, 0)), 3.0)
    Point(x=2.0, y=-3.0)
    """
    u = guide.direction.unit()
    return C + Point(u.y, -u.x) * size


def slider_rate(P13: Point, A: Point) -> float:
    """vC/ω1: the slider moves as the crank's point P13, ω1 × (P13 − A), read along +x."""
    return -(P13.y - A.y)


# ---------------------------------------------------------------- four-bar
FOUR_GIVENS = (Quantity("AB", "mm", "crank"), Quantity("BC", "mm", "coupler"), Quantity("CD", "mm", "rocker"),
               Quantity("AD", "mm", "frame"), PHI, BRANCH)
FOUR_ANSWERS = (
    Quantity("P13", "mm[]", "instant centre of the crank and the rocker [x, y] (on AD, Kennedy)"),
    Quantity("P24", "mm[]", "instant centre of the coupler and the frame [x, y] (on AB, Kennedy)"),
    Quantity("w3_w1", "", "ω3/ω1 = P14P13/P34P13, signed"),
    Quantity("w2_w1", "", "ω2/ω1 = P14P12/P24P12, signed"),
    Quantity("i13", "", "transmission ratio ω1/ω3"),
)


def _four_validate(g: Mapping[str, Any]) -> list[str]:
    four_bar_assembles(g)
    return []


def _inverse(x: float) -> float:
    if x == 0.0:
        raise Degenerate("ω3 = 0: the rocker is at an extreme position, the transmission ratio ω1/ω3 is infinite")
    return 1.0 / x


def four_construct(g: Mapping[str, Any]) -> Construction:
    """The linkage at φ, its joints as centres, P13 and P24 by Kennedy's theorem, the ratios measured."""
    sc = Scene("Four-bar: instant centres by Kennedy's theorem")
    A, D, B, C = add_four_bar_at(sc, g, centres=True)
    lBC = sc.add("lBC", line_through, B, C, caption=("Extend BC (P12P23)", "延长 BC(P12P23 连线)"))
    lAD = sc.add("lAD", line_through, A, D, caption=("Extend AD (P14P34)", "延长 AD(P14P34 连线)"))
    P13 = sc.add("P13", kennedy, lBC, lAD, "P13", style="point", label="P13",
                 caption=("Kennedy: P13 where P12P23 meets P14P34", "三心定理:P12P23 与 P14P34 的交点为 P13"))
    lAB = sc.add("lAB", line_through, A, B, caption=("Extend AB (P14P12)", "延长 AB(P14P12 连线)"))
    lDC = sc.add("lDC", line_through, D, C, caption=("Extend DC (P34P23)", "延长 DC(P34P23 连线)"))
    P24 = sc.add("P24", kennedy, lAB, lDC, "P24", style="point", label="P24",
                 caption=("Kennedy: P24 where P14P12 meets P34P23", "三心定理:P14P12 与 P34P23 的交点为 P24"))
    w3 = sc.add("w3_w1", ratio_along, P13, A, D, role=Role.MEASUREMENT,
                caption=("ω3/ω1 = P14P13/P34P13 (same sense when P13 lies outside AD)",
                         "ω3/ω1 = P14P13/P34P13(P13 在 AD 之外时同向)"))
    sc.add("w2_w1", ratio_along, B, A, P24, role=Role.MEASUREMENT,
           caption=("ω2/ω1 = P14P12/P24P12", "ω2/ω1 = P14P12/P24P12"))
    sc.add("i13", _inverse, w3, role=Role.MEASUREMENT, caption=("Transmission ratio i13 = ω1/ω3", "传动比 i13 = ω1/ω3"))
    sc.add("P13_xy", xy, P13, visible=False)
    sc.add("P24_xy", xy, P24, visible=False)
    answers = {"P13": "P13_xy", "P24": "P24_xy", "w3_w1": "w3_w1", "w2_w1": "w2_w1", "i13": "i13"}
    return Construction(sc, answers, {n: n for n in ("A", "D", "B", "C", "P13", "P24")})


def four_analytic(g: Mapping[str, Any]) -> list[dict[str, Any]]:
    """The velocity ratios from the vector loop; P13 on AD where ω1·x = ω3·(x − AD), P24 where the coupler's
    velocity vanishes: B − (B − A)·ω1/ω2."""
    r = four_bar(g["AB"], g["BC"], g["CD"], g["AD"], g["phi"], 1.0, branch=g.get("branch", "above"))
    w2, w3 = r["omega2"], r["omega3"]
    x13 = w3 * g["AD"] / (w3 - 1.0)
    a = math.radians(g["phi"])
    bx, by = g["AB"] * math.cos(a), g["AB"] * math.sin(a)
    return [{"P13": (x13, 0.0), "P24": (bx - bx / w2, by - by / w2), "w3_w1": w3, "w2_w1": w2, "i13": 1.0 / w3}]


FOUR = Recipe(
    name="four_bar.instant_centres",
    title="Four-bar: instant centres (Kennedy's theorem) and velocity ratios",
    givens=FOUR_GIVENS, answers=FOUR_ANSWERS, points=("A", "D", "B", "C", "P13", "P24"),
    construct=four_construct, analytic=four_analytic, validate=_four_validate,
)


# ---------------------------------------------------------------- crank-slider
SLIDER_GIVENS = (Quantity("AB", "mm", "crank"), Quantity("BC", "mm", "connecting rod"),
                 Quantity("e", "mm", "offset: the guide is the line y = −e", minimum=None), PHI)
SLIDER_ANSWERS = (
    Quantity("P13", "mm[]", "instant centre of the crank and the slider [x, y]"),
    Quantity("P24", "mm[]", "instant centre of the rod and the frame [x, y]"),
    Quantity("vC_w1", "mm", "slider velocity per unit crank speed vC/ω1 (mm/s per rad/s), signed along +x"),
    Quantity("w2_w1", "", "ω2/ω1 = P14P12/P24P12, signed"),
)


def _slider_validate(g: Mapping[str, Any]) -> list[str]:
    slider_assembles(g)
    return []


def slider_construct(g: Mapping[str, Any]) -> Construction:
    """The crank-slider at φ; P34 at infinity (⊥ the guide); P13 and P24 by Kennedy's theorem."""
    sc = Scene("Crank-slider: instant centres by Kennedy's theorem")
    A, F, gl, B, C = add_slider_at(sc, g, centres=True)
    lBC = sc.add("lBC", line_through, B, C, caption=("Extend BC (P12P23)", "延长 BC(P12P23 连线)"))
    nA = sc.add("nA", perpendicular, gl, A, caption=("Through A ⊥ the guide (P14P34)", "过 A 作导路的垂线(P14P34 连线)"))
    P13 = sc.add("P13", kennedy, lBC, nA, "P13", style="point", label="P13",
                 caption=("Kennedy: P13 where P12P23 meets P14P34", "三心定理:P12P23 与 P14P34 的交点为 P13"))
    lAB = sc.add("lAB", line_through, A, B, caption=("Extend AB (P14P12)", "延长 AB(P14P12 连线)"))
    nC = sc.add("nC", perpendicular, gl, C, caption=("Through C ⊥ the guide (P23P34)", "过 C 作导路的垂线(P23P34 连线)"))
    P24 = sc.add("P24", kennedy, lAB, nC, "P24", style="point", label="P24",
                 caption=("Kennedy: P24 where P14P12 meets P23P34", "三心定理:P14P12 与 P23P34 的交点为 P24"))
    if sc.drawing:
        # P34 has no point on the paper: an arrow from C along its direction (⊥ the guide), named at its tip
        tip = sc.add("P34", towards_infinity, C, gl, 0.2 * g["BC"], style="point-centre", label="P34 (∞)",
                     role=Role.CONSTRUCTION)
        sc.add("P34_arrow", marks.vector, C, tip, role=Role.CONSTRUCTION, style="vector",
               caption=("P34 lies at infinity perpendicular to the guide: the arrow points to it",
                        "P34 位于垂直于导路的无穷远处(箭头所指方向)"))
    sc.add("vC_w1", slider_rate, P13, A, role=Role.MEASUREMENT, unit="mm",
           caption=("The slider moves as the crank's point P13 (signed along +x): vC/ω1 = ±P14P13",
                    "滑块与曲柄上 P13 点速度相同(沿 +x 为正):vC/ω1 = ±P14P13"))
    sc.add("w2_w1", ratio_along, B, A, P24, role=Role.MEASUREMENT,
           caption=("ω2/ω1 = P14P12/P24P12", "ω2/ω1 = P14P12/P24P12"))
    sc.add("P13_xy", xy, P13, visible=False)
    sc.add("P24_xy", xy, P24, visible=False)
    answers = {"P13": "P13_xy", "P24": "P24_xy", "vC_w1": "vC_w1", "w2_w1": "w2_w1"}
    return Construction(sc, answers, {n: n for n in ("A", "B", "C", "P13", "P24")})


def slider_analytic(g: Mapping[str, Any]) -> list[dict[str, Any]]:
    """From the vector loop: P13 on the perpendicular through A at height −vC/ω1, P24 = B − (B − A)·ω1/ω2."""
    r = crank_slider(g["AB"], g["BC"], g["e"], g["phi"], 1.0)
    w2 = r["omega2"]
    a = math.radians(g["phi"])
    bx, by = g["AB"] * math.cos(a), g["AB"] * math.sin(a)
    return [{"P13": (0.0, -r["vC"]), "P24": (bx - bx / w2, by - by / w2), "vC_w1": r["vC"], "w2_w1": w2}]


SLIDER = Recipe(
    name="crank_slider.instant_centres",
    title="Crank-slider: instant centres (Kennedy's theorem, P34 at infinity) and velocity ratios",
    givens=SLIDER_GIVENS, answers=SLIDER_ANSWERS, points=("A", "B", "C", "P13", "P24"),
    construct=slider_construct, analytic=slider_analytic, validate=_slider_validate,
)

__all__ = ["FOUR", "SLIDER", "kennedy", "ratio_along", "slider_rate"]
