"""``four_bar.kinematics``: velocities and accelerations of a four-bar at one crank position, by the vector
polygons (矢量方程图解法: 速度多边形、加速度多边形, and the image principle 影像原理 for a coupler point).

Construction (A at the origin, D on +x, C on the side ``branch`` names, as in ``crank_rocker.extremes``):

1. The linkage at the crank angle φ: B on the crank circle, C where the circle about B (radius BC) meets the
   rocker circle about D.
2. The velocity polygon, from a pole p beside the linkage at the scale μv = |ω| (mm/s)/mm, so that pb is as
   long as AB: ``vC = vB + vCB``: pb ⊥ AB in the sense of ω; the line through b ⊥ BC (the direction of vCB)
   meets the line through p ⊥ CD (the direction of vC) at c. Then ω2 = vCB/BC and ω3 = vC/CD, their senses
   read by carrying bc to C about B and pc to C about D.
3. The acceleration polygon, from a pole p′ beside the velocity polygon at μa = |aB|/AB (mm/s²)/mm:
   ``aC = aB + aCBⁿ + aCBᵗ = aCⁿ + aCᵗ``: p′b′ is aB (normal ω²·AB along B→A, plus the tangential ε·AB ⊥ AB
   when the crank accelerates); from b′ the normal component aCBⁿ = ω2²·BC along C→B ends at n2, the line
   through n2 ⊥ BC carries aCBᵗ; from p′ the normal component aCⁿ = ω3²·CD along C→D ends at n3, the line
   through n3 ⊥ CD carries aCᵗ; the two lines meet at c′. ε2 = n2c′/BC, ε3 = n3c′/CD.
4. A coupler point E (given BE and ∠CBE): its image e in each polygon makes the triangle bce (b′c′e′) similar
   to BCE and turned the same way (the image principle); vE = pe·μv, aE = p′e′·μa.

Every answer is measured on the polygons (lengths times the scale, senses by the turn of the polygon side
against the link); the twin is the complex vector loop differentiated exactly
(:func:`geomcon.analytic.kinematics.four_bar`).
"""
from __future__ import annotations

from typing import Any, Mapping

from ..analytic.kinematics import four_bar
from ..errors import NotAMechanism
from ..geometry import line_through, perpendicular, segment
from ..scene import Role, Scene
from ..scene.marks import vector
from .base import Construction, Quantity, Recipe
from .common import add_bar
from .kinematics_common import (EPSILON, OMEGA, PHI, SCALES, add_crank_acceleration, add_crank_velocity, add_four_bar_at,
                                add_image, four_bar_assembles, image, meet, normal_length, rate, scaled_length, turned,
                                twin_scales)

GIVENS = (
    Quantity("AB", "mm", "crank"),
    Quantity("BC", "mm", "coupler"),
    Quantity("CD", "mm", "rocker"),
    Quantity("AD", "mm", "frame"),
    PHI, OMEGA, EPSILON,
    Quantity("branch", "choice", "assembly: C left (above) or right (below) of the directed line B→D",
             required=False, default="above", minimum=None, choices=("above", "below")),
    Quantity("BE", "mm", "coupler point E: its distance from B", required=False, default=None),
    Quantity("angle_CBE", "deg", "coupler point E: ∠CBE, counter-clockwise from B→C", required=False, default=0.0,
             minimum=-360.0, inclusive=True, maximum=360.0),
)
ANSWERS = (
    Quantity("omega2", "rad/s", "angular velocity of the coupler BC (counter-clockwise positive)"),
    Quantity("omega3", "rad/s", "angular velocity of the rocker CD (counter-clockwise positive)"),
    Quantity("epsilon2", "rad/s²", "angular acceleration of the coupler BC"),
    Quantity("epsilon3", "rad/s²", "angular acceleration of the rocker CD"),
    Quantity("vC", "mm/s", "speed of C, pc·μv"),
    Quantity("aC", "mm/s²", "acceleration of C, p′c′·μa"),
    Quantity("vE", "mm/s", "speed of the coupler point E (when BE is given)"),
    Quantity("aE", "mm/s²", "acceleration of the coupler point E (when BE is given)"),
) + SCALES


def _validate(g: Mapping[str, Any]) -> list[str]:
    if g["omega"] == 0:
        raise NotAMechanism("omega = 0: the crank does not turn, the polygons have no scale")
    four_bar_assembles(g)
    return []


def construct(g: Mapping[str, Any]) -> Construction:
    """Build the linkage at φ and its velocity and acceleration polygons."""
    AB, BC, CD, AD, omega = g["AB"], g["BC"], g["CD"], g["AD"], g["omega"]
    epsilon = g.get("epsilon", 0.0) or 0.0
    BE = g.get("BE")
    ang = g.get("angle_CBE", 0.0) or 0.0
    sc = Scene("Four-bar: velocity and acceleration polygons")
    A, D, B, C = add_four_bar_at(sc, g)
    drawing = sc.drawing
    E = None
    if BE is not None:
        E = sc.add("E", image, B, C, BE, BC, ang, style="joint", label="E",
                   caption=(f"Coupler point E: BE = {BE:g}, ∠CBE = {ang:g}°", f"连杆上的点 E:BE = {BE:g},∠CBE = {ang:g}°"))
        if drawing:
            add_bar(sc, "BE", B, E, ("Draw the coupler triangle BCE", "画出连杆三角形 BCE"))
            add_bar(sc, "CE", C, E)

    # ---- velocity polygon: vC = vB + vCB
    gap = (AB + BC + CD + AD) / 8.0 + AB      # free space, and room for pb (as long as AB) pointing back
    pts = (A, D, B, C) if E is None else (A, D, B, C, E)
    mu_v, p, b = add_crank_velocity(sc, A, B, AB, omega, gap, pts)
    lBC = sc.add("lBC", line_through, B, C, visible=False)
    lCD = sc.add("lCD", line_through, C, D, visible=False)
    tb = sc.add("tb", perpendicular, lBC, b, style="direction", caption=("Through b, the direction of vCB (⊥ BC)", "过 b 作 vCB 的方向线(⊥ BC)"))
    tp = sc.add("tp", perpendicular, lCD, p, style="direction", caption=("Through p, the direction of vC (⊥ CD)", "过 p 作 vC 的方向线(⊥ CD)"))
    c = sc.add("c", meet, tb, tp, style="point", label="c", caption=("They meet at c", "两线交于 c"))
    sc.add("vC", scaled_length, p, c, mu_v, role=Role.MEASUREMENT, unit="mm/s",
           caption=("Measure vC = pc·μv", "量得 vC = pc·μv"))
    w2 = sc.add("omega2", rate, b, c, B, C, mu_v, role=Role.MEASUREMENT, unit="rad/s",
                caption=("ω2 = vCB/BC = bc·μv/BC (sense: bc carried to C turns BC about B)",
                         "ω2 = vCB/lBC = bc·μv/lBC(将 bc 移至 C 点判断转向)"))
    w3 = sc.add("omega3", rate, p, c, D, C, mu_v, role=Role.MEASUREMENT, unit="rad/s",
                caption=("ω3 = vC/CD = pc·μv/CD (sense: pc carried to C turns CD about D)",
                         "ω3 = vC/lCD = pc·μv/lCD(将 pc 移至 C 点判断转向)"))
    e = None
    if E is not None:
        e = add_image(sc, "e", b, c, BE, BC, ang, p, mu_v, "vE", "e", "mm/s", ("bce", "pe", "μv"))
    if drawing:
        sc.add("v_pc", vector, p, c, role=Role.ANNOTATION, style="vector")
        sc.add("v_bc", vector, b, c, role=Role.ANNOTATION, style="vector")
        if e is not None:
            sc.add("v_pe", vector, p, e, role=Role.ANNOTATION, style="vector")
            sc.add("v_bce", segment, b, e, role=Role.ANNOTATION, style="ghost")
            sc.add("v_ce", segment, c, e, role=Role.ANNOTATION, style="ghost")

    # ---- acceleration polygon: aB + aCBⁿ + aCBᵗ = aCⁿ + aCᵗ
    mu_a, p2, b2 = add_crank_acceleration(sc, A, B, omega, epsilon, gap, (p, b, c) if e is None else (p, b, c, e))
    k2 = sc.add("k_n2", normal_length, w2, mu_a, visible=False)
    n2 = sc.add("n2", turned, b2, C, B, k2, 0.0, style="point", label="n2",
                caption=("From b′, b′n2 ∥ CB: aCBⁿ = ω2²·BC, towards B", "自 b′ 作 b′n2 ∥ CB:aCBⁿ = ω2²·lBC,指向 B"))
    k3 = sc.add("k_n3", normal_length, w3, mu_a, visible=False)
    n3 = sc.add("n3", turned, p2, C, D, k3, 0.0, style="point", label="n3",
                caption=("From p′, p′n3 ∥ CD: aCⁿ = ω3²·CD, towards D", "自 p′ 作 p′n3 ∥ CD:aCⁿ = ω3²·lCD,指向 D"))
    t2 = sc.add("t2", perpendicular, lBC, n2, style="direction", caption=("Through n2, the direction of aCBᵗ (⊥ BC)", "过 n2 作 aCBᵗ 的方向线(⊥ BC)"))
    t3 = sc.add("t3", perpendicular, lCD, n3, style="direction", caption=("Through n3, the direction of aCᵗ (⊥ CD)", "过 n3 作 aCᵗ 的方向线(⊥ CD)"))
    c2 = sc.add("c2", meet, t2, t3, style="point", label="c′", caption=("They meet at c′", "两线交于 c′"))
    sc.add("aC", scaled_length, p2, c2, mu_a, role=Role.MEASUREMENT, unit="mm/s²",
           caption=("Measure aC = p′c′·μa", "量得 aC = p′c′·μa"))
    sc.add("epsilon2", rate, n2, c2, B, C, mu_a, role=Role.MEASUREMENT, unit="rad/s²",
           caption=("ε2 = aCBᵗ/BC = n2c′·μa/BC", "ε2 = aCBᵗ/lBC = n2c′·μa/lBC"))
    sc.add("epsilon3", rate, n3, c2, D, C, mu_a, role=Role.MEASUREMENT, unit="rad/s²",
           caption=("ε3 = aCᵗ/CD = n3c′·μa/CD", "ε3 = aCᵗ/lCD = n3c′·μa/lCD"))
    e2 = None
    if E is not None:
        e2 = add_image(sc, "e2", b2, c2, BE, BC, ang, p2, mu_a, "aE", "e′", "mm/s²", ("b′c′e′", "p′e′", "μa"))
    if drawing:
        sc.add("a_bn2", vector, b2, n2, role=Role.ANNOTATION, style="vector")
        sc.add("a_n2c", vector, n2, c2, role=Role.ANNOTATION, style="vector")
        sc.add("a_pn3", vector, p2, n3, role=Role.ANNOTATION, style="vector")
        sc.add("a_n3c", vector, n3, c2, role=Role.ANNOTATION, style="vector")
        sc.add("a_pc", vector, p2, c2, role=Role.ANNOTATION, style="vector")
        if e2 is not None:
            sc.add("a_pe", vector, p2, e2, role=Role.ANNOTATION, style="vector")
    names = ["omega2", "omega3", "epsilon2", "epsilon3", "vC", "aC", "mu_v", "mu_a"] + (["vE", "aE"] if E is not None else [])
    answers = {n: n for n in names}
    points = {n: n for n in ("A", "D", "B", "C")}
    if E is not None:
        points["E"] = "E"
    return Construction(sc, answers, points)


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """The complex vector loop, differentiated exactly."""
    r = four_bar(g["AB"], g["BC"], g["CD"], g["AD"], g["phi"], g["omega"], g.get("epsilon", 0.0) or 0.0,
                 branch=g.get("branch", "above"), BE=g.get("BE"), angle_CBE=g.get("angle_CBE", 0.0) or 0.0)
    out = {k: r[k] for k in ("omega2", "omega3", "epsilon2", "epsilon3", "vC", "aC")}
    out.update(twin_scales(g))
    if g.get("BE") is not None:
        out["vE"], out["aE"] = r["vE"], r["aE"]
    return [out]


RECIPE = Recipe(
    name="four_bar.kinematics",
    title="Four-bar: velocity and acceleration polygons at one crank position",
    givens=GIVENS,
    answers=ANSWERS,
    points=("A", "D", "B", "C"),
    construct=construct,
    analytic=analytic,
    validate=_validate,
)

__all__ = ["RECIPE"]
