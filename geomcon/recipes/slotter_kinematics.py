"""``slotter.kinematics``: the slotting machine's six-bar (seed 000, 插床) at one crank position — velocity and
acceleration polygons (矢量方程图解法), the guide bar's with its Coriolis component, then the ram's.

The linkage (the seed's O2, A, O4, B, C are A, B, C, D, E here, its links 2…6 are 1…5): the crank AB turns about
A at the origin; the block pinned to it at B slides on the guide bar, which turns about C at (−AC, 0); the guide
bar's arm CD lies beyond C (B, C, D in line, C between); the coupler DE drives the ram E along the vertical path
x = −(AC + CF) (F its foot on the frame line), E above D (``branch = "above"``) or below.

Velocities: ``vB3 = vB2 + vB3B2`` as in ``guide_bar.kinematics`` (pb2 ⊥ AB; b2's line ∥ CB meets p's line ⊥ CB at
b3); D's image d on the line pb3 beyond p, pd = pb3·CD/CB (影像原理); ``vE = vD + vED`` — d's line ⊥ DE meets p's
line ∥ the path at e. Accelerations: ``aB3ⁿ + aB3ᵗ = aB2 + aᵏB3B2 + aʳB3B2`` with the Coriolis component from b2′
(vB3B2 turned 90° in the sense of ω3) to k′, the line ∥ CB through k′ meeting the line ⊥ CB through n3 at b3′;
d′ on p′b3′ beyond p′; ``aE = aD + aEDⁿ + aEDᵗ`` — from d′ the normal ω4²·DE towards D to n4, the line ⊥ DE
through n4 meets p′'s line ∥ the path at e′. ω4 = de·μv/DE, ε4 = n4e′·μa/DE; vE, aE signed along +y (up).

The twin: :func:`geomcon.analytic.kinematics.slotter` (the loops differentiated exactly); the whole-cycle solver
:mod:`geomcon.kinematics` is a third route (tests).
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.kinematics import slotter
from ..errors import NotAMechanism
from ..geometry import Above, Below, Line, Point, circle, line_circle, line_through, point_along, segment
from ..scene import Role, Scene, marks
from ..scene.marks import vector
from .base import Construction, Quantity, Recipe
from .common import add_bar, add_pivot
from .guide_bar import _block_along
from .slider_kinematics import _gap, _omega
from .kinematics_common import (EPSILON, OMEGA, PHI, RRP, SCALES, add_guide_acceleration, add_guide_velocity,
                                add_rrp_acceleration, add_rrp_velocity, crank_pin, guide_vectors, rrp_vectors,
                                scaled_length, twin_scales)

GIVENS = (
    Quantity("AB", "mm", "crank (the seed's O2A)"),
    Quantity("AC", "mm", "frame: the guide bar's pivot C to the left of A (O2O4)"),
    Quantity("CD", "mm", "the guide bar's arm, beyond C from the block B (O4B)"),
    Quantity("DE", "mm", "coupler from the arm to the ram (BC)"),
    Quantity("CF", "mm", "the ram's vertical path x = −(AC + CF): its distance beyond C (negative: towards A)",
              minimum=None),
    PHI, OMEGA, EPSILON,
    Quantity("branch", "choice", "the ram E above or below D", required=False, default="above",
             choices=("above", "below")),
)
ANSWERS = (
    Quantity("omega3", "rad/s", "angular velocity of the guide bar (counter-clockwise positive)"),
    Quantity("epsilon3", "rad/s²", "angular acceleration of the guide bar"),
    Quantity("v_slip", "mm/s", "velocity of the block B2 along the guide bar, signed along C→B"),
    Quantity("a_slip", "mm/s²", "relative acceleration of B2 along the guide bar, signed along C→B"),
    Quantity("a_coriolis", "mm/s²", "Coriolis acceleration 2·ω3·v_slip of B2 relative to the guide bar, signed "
             "along C→B turned +90°"),
    Quantity("vB3", "mm/s", "speed of the guide bar's point B3 under the block"),
    Quantity("vD", "mm/s", "speed of the arm's end D"),
    Quantity("aD", "mm/s²", "acceleration of the arm's end D (magnitude)"),
    Quantity("omega4", "rad/s", "angular velocity of the coupler DE"),
    Quantity("epsilon4", "rad/s²", "angular acceleration of the coupler DE"),
    Quantity("vE", "mm/s", "velocity of the ram E, signed along +y"),
    Quantity("aE", "mm/s²", "acceleration of the ram E, signed along +y"),
) + SCALES

RAM = RRP("D", "E", "4", "+y", ("the ram's path", "滑枕导路"), ("tpE", "taE"))
"""How the ram's dyad names its polygon steps."""


def arm_end(g: Mapping[str, Any]) -> tuple[float, float]:
    """D = C − CD·(B − C)/CB and the horizontal distance from D across to the ram's path (positive: path to the
    left of D); refuses B on C.

    >>> [round(x, 9) for x in arm_end({"AB": 70, "AC": 161, "CD": 115, "CF": 115.4, "phi": 0})]
    [-276.0, -0.4]
    """
    a = math.radians(g["phi"])
    bx, by = g["AB"] * math.cos(a) + g["AC"], g["AB"] * math.sin(a)
    s = math.hypot(bx, by)
    if math.isclose(g["AB"], g["AC"]) and math.isclose(math.remainder(g["phi"] - 180.0, 360.0), 0.0, abs_tol=1e-9):
        raise NotAMechanism(f"at phi = {g['phi']:g}° B lies on C (AB = AC = {g['AB']:g}): the guide bar's "
                            "direction is undefined")
    dx = -g["AC"] - g["CD"] * bx / s
    return dx, -(g["AC"] + g["CF"]) - dx


def _validate(g: Mapping[str, Any]) -> list[str]:
    _omega(g)
    _, h = arm_end(g)
    if abs(h) >= g["DE"]:
        raise NotAMechanism(f"at phi = {g['phi']:g}° D is {abs(h):.6g} from the ram's path, not less than "
                            f"DE = {g['DE']:g}" + (": the coupler is perpendicular to the path (a dead point)"
                                                   if math.isclose(abs(h), g["DE"]) else ""))
    return []


def arm_image(pole: Point, q: Point, C: Point, B: Point, D: Point) -> Point:
    """The image of D in a polygon whose side pole→q is the guide bar's point at B: D, C, B on one link turning
    about C, so d = pole + (q − pole)·(CD·CB)/CB² (signed: beyond the pole when C lies between B and D).

    >>> arm_image(Point(0, 0), Point(0, 2), Point(0, 0), Point(1, 0), Point(-3, 0))
    Point(x=0.0, y=-6.0)
    """
    bx, by = B.x - C.x, B.y - C.y
    k = ((D.x - C.x) * bx + (D.y - C.y) * by) / (bx * bx + by * by)
    return Point(pole.x + k * (q.x - pole.x), pole.y + k * (q.y - pole.y))


def construct(g: Mapping[str, Any]) -> Construction:
    """Build the slotter at φ and its velocity and acceleration polygons."""
    AB, AC, CD, DE, CF, phi, omega = (g[k] for k in ("AB", "AC", "CD", "DE", "CF", "phi", "omega"))
    epsilon = g.get("epsilon", 0.0) or 0.0
    above = g.get("branch", "above") != "below"
    sc = Scene("Slotter: velocity and acceleration polygons of the guide bar and the ram")
    A = add_pivot(sc, "A", Point(0.0, 0.0), ("Crank pivot A at the origin", "取曲柄转动中心 A 为原点"))
    C = add_pivot(sc, "C", (-AC, 0.0), (f"Guide-bar pivot C to the left of A, AC = {AC:g}",
                                        f"在 A 左侧取导杆转动中心 C,AC = {AC:g}"))
    F = sc.given_at("F", -(AC + CF), 0.0, style="point", caption=(f"F on the frame line with CF = {CF:g} beyond C",
                                                                 f"在机架线上 C 外侧取 CF = {CF:g} 得 F"))
    path = sc.add("path", Line, F, Point(0.0, 1.0), role=Role.GIVEN, style="given",
                  caption=("The ram's path through F, vertical", "过 F 作滑枕导路(铅垂)"))
    B = sc.add("B", crank_pin, A, AB, phi, style="joint", label="B",
               caption=(f"Crank at φ = {phi:g}°: B with AB = {AB:g}", f"曲柄转角 φ = {phi:g}°:取 AB = {AB:g} 得 B"))
    lCB = sc.add("lCB", line_through, C, B, style="direction", caption=("The guide bar CB through the block B", "过滑块 B 作导杆 CB"))
    D = sc.add("D", point_along, C, B, -CD, style="joint", label="D",
               caption=(f"The arm's end D beyond C: CD = {CD:g}", f"在导杆上 C 的另一侧取 CD = {CD:g} 得 D"))
    kD = sc.add("kD", circle, D, DE, caption=(f"Circle about D with radius DE = {DE:g}", f"以 D 为圆心、DE = {DE:g} 为半径作圆"))
    side = Above(C, A) if above else Below(C, A)
    E = sc.add("E", line_circle, path, kD, branch=side, style="joint", label="E",
               caption=("It meets the path at the ram E", "交导路于滑枕 E"))
    drawing = sc.drawing
    if drawing:
        add_bar(sc, "AB", A, B, ("Draw the crank AB, the guide bar DCB, the coupler DE and the ram",
                                 "画出曲柄 AB、导杆 DCB、连杆 DE 与滑枕"))
        sc.add("DB", segment, D, B, role=Role.RESULT, style="link")
        sc.add("block", _block_along, B, C, role=Role.ANNOTATION, style="slider")
        add_bar(sc, "DE", D, E)
        sc.add("ram", marks.slider, E, Point(0.0, 1.0), role=Role.ANNOTATION, style="slider")
    gap = _gap(AB, AC, CD, DE)
    v, w3 = add_guide_velocity(sc, A, B, C, lCB, AB, omega, gap, (A, B, C, D, E, F))
    mu_v, p, b2, b3 = v
    d = sc.add("d", arm_image, p, b3, C, B, D, style="point", label="d",
               caption=("Image d of D: pd = pb3·CD/CB on the line b3p beyond p (image principle)",
                        "由影像原理得 d:在 b3p 延长线上取 pd = pb3·CD/CB"))
    sc.add("vB3", scaled_length, p, b3, mu_v, role=Role.MEASUREMENT, unit="mm/s",
           caption=("Measure vB3 = pb3·μv", "量得 vB3 = pb3·μv"))
    sc.add("vD", scaled_length, p, d, mu_v, role=Role.MEASUREMENT, unit="mm/s",
           caption=("Measure vD = pd·μv", "量得 vD = pd·μv"))
    lDE, e, w4 = add_rrp_velocity(sc, D, E, path, d, p, mu_v, RAM)
    acc = add_guide_acceleration(sc, A, B, C, lCB, omega, epsilon, gap, (p, b2, b3, d, e), v, w3)
    mu_a, p2, b3_ = acc[0], acc[1], acc[5]
    d_ = sc.add("d2", arm_image, p2, b3_, C, B, D, style="point", label="d′",
                caption=("Image d′ of D: p′d′ = p′b3′·CD/CB on the line b3′p′ beyond p′",
                         "由影像原理得 d′:在 b3′p′ 延长线上取 p′d′ = p′b3′·CD/CB"))
    sc.add("aD", scaled_length, p2, d_, mu_a, role=Role.MEASUREMENT, unit="mm/s²",
           caption=("Measure aD = p′d′·μa", "量得 aD = p′d′·μa"))
    n4, e_ = add_rrp_acceleration(sc, D, E, path, lDE, d_, p2, w4, mu_a, RAM)
    if drawing:
        arrows = guide_vectors(v, acc) + (("v_pd", p, d), ("a_pd", p2, d_)) + rrp_vectors(p, d, e, p2, d_, n4, e_, RAM)
        for key, a, z in arrows:
            sc.add(key, vector, a, z, role=Role.ANNOTATION, style="vector")
    names = [q.name for q in ANSWERS]
    return Construction(sc, {n: n for n in names}, {n: n for n in ("A", "B", "C", "D", "E")})


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """The loops differentiated exactly (:func:`geomcon.analytic.kinematics.slotter`)."""
    r = slotter(g["AB"], g["AC"], g["CD"], g["DE"], g["CF"], g["phi"], g["omega"], g.get("epsilon", 0.0) or 0.0,
                g.get("branch", "above"))
    return [{**{q.name: r[q.name] for q in ANSWERS if q.name in r}, **twin_scales(g)}]


RECIPE = Recipe(
    name="slotter.kinematics",
    title="Slotter (guide bar and ram): velocity and acceleration polygons at one crank position",
    givens=GIVENS, answers=ANSWERS, points=("A", "B", "C", "D", "E"),
    construct=construct, analytic=analytic, validate=_validate,
)

__all__ = ["ANSWERS", "GIVENS", "RAM", "RECIPE", "arm_end", "arm_image"]
