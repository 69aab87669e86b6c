"""``crank_slider.kinematics`` and ``guide_bar.kinematics``: velocities and accelerations at one crank position by
the vector polygons (矢量方程图解法), the conventions of ``crank_slider.extremes`` and ``guide_bar.extremes``.

Crank-slider (A at the origin, the guide the line y = −e, the slider C to the right of B):
``vC = vB + vCB`` — pb ⊥ AB; the line through b ⊥ BC meets the line through p parallel to the guide at c;
``aC = aB + aCBⁿ + aCBᵗ`` — p′b′ is aB; b′n2 = ω2²·BC along C→B; the line through n2 ⊥ BC meets the line through p′
parallel to the guide at c′. vC and aC are read signed along +x; ω2 = vCB/BC, ε2 = n2c′/BC.

Guide-bar (A at the origin, the guide's pivot C at (0, −AC); the block pinned to the crank at B slides on the
guide CB; points of the crank and block are B2, the coincident point of the guide B3):
``vB3 = vB2 + vB3B2`` — pb2 ⊥ AB; the line through b2 parallel to CB (the slip) meets the line through p ⊥ CB at
b3; ω3 = vB3/CB. ``aB3ⁿ + aB3ᵗ = aB2 + aᵏB3B2 + aʳB3B2`` — p′b2′ is aB2; the Coriolis component
aᵏB3B2 = 2·ω3·vB3B2, its direction vB3B2 turned 90° in the sense of ω3, from b2′ to k′; the line through k′
parallel to CB (aʳ); from p′ the normal ω3²·CB along B→C to n3 and the line through n3 ⊥ CB; the two lines meet
at b3′. ε3 = n3b3′/CB; the slip v_slip, a_slip of B2 along C→B and the Coriolis term a_coriolis (of B2 relative
to the guide, along C→B turned +90°) are read off the polygons.

The twins: :func:`geomcon.analytic.kinematics.crank_slider` and :func:`~geomcon.analytic.kinematics.guide_bar`.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.kinematics import crank_slider, guide_bar
from ..errors import NotAMechanism
from ..geometry import Point, line_through, parallel, perpendicular, segment
from ..scene import Role, Scene
from ..scene.marks import vector
from .base import Construction, Quantity, Recipe
from .common import add_bar, add_pivot
from .guide_bar import _block_along
from .kinematics_common import (EPSILON, OMEGA, PHI, SCALES, add_crank_acceleration, add_crank_velocity, add_slider_at,
                                along, slider_assembles,
                                crank_pin, meet, normal_length, rate, turned, twin_scales)

def _omega(g: Mapping[str, Any]) -> None:
    if g["omega"] == 0:
        raise NotAMechanism("omega = 0: the crank does not turn, the polygons have no scale")


def _gap(*lengths: Any) -> Any:
    """Free space between the linkage and a polygon, with room for the crank's side (as long as AB) pointing back."""
    return sum(lengths) / 6.0 + lengths[0]


# ---------------------------------------------------------------- crank-slider
SLIDER_GIVENS = (Quantity("AB", "mm", "crank"), Quantity("BC", "mm", "connecting rod"),
                 Quantity("e", "mm", "offset: the guide is the line y = −e", minimum=None), PHI, OMEGA, EPSILON)
SLIDER_ANSWERS = (
    Quantity("omega2", "rad/s", "angular velocity of the rod BC (counter-clockwise positive)"),
    Quantity("epsilon2", "rad/s²", "angular acceleration of the rod BC"),
    Quantity("vC", "mm/s", "velocity of the slider, signed along +x"),
    Quantity("aC", "mm/s²", "acceleration of the slider, signed along +x"),
) + SCALES


def _slider_validate(g: Mapping[str, Any]) -> list[str]:
    _omega(g)
    slider_assembles(g)
    return []


def slider_construct(g: Mapping[str, Any]) -> Construction:
    """Build the crank-slider at φ and its velocity and acceleration polygons."""
    AB, BC, e, omega = g["AB"], g["BC"], g["e"], g["omega"]
    epsilon = g.get("epsilon", 0.0) or 0.0
    sc = Scene("Crank-slider: velocity and acceleration polygons")
    A, F, gl, B, C = add_slider_at(sc, g)
    gap = _gap(AB, BC, abs(e))
    mu_v, p, b = add_crank_velocity(sc, A, B, AB, omega, gap, (A, F, B, C))
    lBC = sc.add("lBC", line_through, B, C, visible=False)
    tb = sc.add("tb", perpendicular, lBC, b, caption=("Through b, the direction of vCB (⊥ BC)", "过 b 作 vCB 的方向线(⊥ BC)"))
    tp = sc.add("tp", parallel, gl, p, caption=("Through p, the direction of vC (∥ the guide)", "过 p 作 vC 的方向线(∥ 导路)"))
    c = sc.add("c", meet, tb, tp, style="point", label="c", caption=("They meet at c", "两线交于 c"))
    sc.add("vC", along, p, c, gl, mu_v, role=Role.MEASUREMENT, unit="mm/s",
           caption=("Measure vC = pc·μv (signed along +x)", "量得 vC = pc·μv(沿 +x 为正)"))
    w2 = sc.add("omega2", rate, b, c, B, C, mu_v, role=Role.MEASUREMENT, unit="rad/s",
                caption=("ω2 = vCB/BC = bc·μv/BC (sense: bc carried to C)", "ω2 = vCB/lBC = bc·μv/lBC(将 bc 移至 C 点判断转向)"))
    mu_a, p2, b2 = add_crank_acceleration(sc, A, B, omega, epsilon, gap, (p, b, c))
    k2 = sc.add("k_n2", normal_length, w2, mu_a, visible=False)
    n2 = sc.add("n2", turned, b2, C, B, k2, 0.0, style="point", label="n2",
                caption=("From b′, b′n2 ∥ CB: aCBⁿ = ω2²·BC, towards B", "自 b′ 作 b′n2 ∥ CB:aCBⁿ = ω2²·lBC,指向 B"))
    t2 = sc.add("t2", perpendicular, lBC, n2, caption=("Through n2, the direction of aCBᵗ (⊥ BC)", "过 n2 作 aCBᵗ 的方向线(⊥ BC)"))
    t3 = sc.add("t3", parallel, gl, p2, caption=("Through p′, the direction of aC (∥ the guide)", "过 p′ 作 aC 的方向线(∥ 导路)"))
    c2 = sc.add("c2", meet, t2, t3, style="point", label="c′", caption=("They meet at c′", "两线交于 c′"))
    sc.add("aC", along, p2, c2, gl, mu_a, role=Role.MEASUREMENT, unit="mm/s²",
           caption=("Measure aC = p′c′·μa (signed along +x)", "量得 aC = p′c′·μa(沿 +x 为正)"))
    sc.add("epsilon2", rate, n2, c2, B, C, mu_a, role=Role.MEASUREMENT, unit="rad/s²",
           caption=("ε2 = aCBᵗ/BC = n2c′·μa/BC", "ε2 = aCBᵗ/lBC = n2c′·μa/lBC"))
    if sc.drawing:
        for key, a, z in (("v_pc", p, c), ("v_bc", b, c), ("a_bn2", b2, n2), ("a_n2c", n2, c2), ("a_pc", p2, c2)):
            sc.add(key, vector, a, z, role=Role.ANNOTATION, style="vector")
    names = ("omega2", "epsilon2", "vC", "aC", "mu_v", "mu_a")
    return Construction(sc, {n: n for n in names}, {n: n for n in ("A", "B", "C")})


def slider_analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """The complex vector loop, differentiated exactly."""
    eps = g.get("epsilon", 0.0) or 0.0
    r = crank_slider(g["AB"], g["BC"], g["e"], g["phi"], g["omega"], eps)
    return [{"omega2": r["omega2"], "epsilon2": r["epsilon2"], "vC": r["vC"], "aC": r["aC"], **twin_scales(g)}]


SLIDER = Recipe(
    name="crank_slider.kinematics",
    title="Crank-slider: velocity and acceleration polygons at one crank position",
    givens=SLIDER_GIVENS, answers=SLIDER_ANSWERS, points=("A", "B", "C"),
    construct=slider_construct, analytic=slider_analytic, validate=_slider_validate,
)


# ---------------------------------------------------------------- guide-bar
GUIDE_GIVENS = (Quantity("AB", "mm", "crank"), Quantity("AC", "mm", "frame: the guide's pivot C below A"),
                PHI, OMEGA, EPSILON)
GUIDE_ANSWERS = (
    Quantity("omega3", "rad/s", "angular velocity of the guide (counter-clockwise positive)"),
    Quantity("epsilon3", "rad/s²", "angular acceleration of the guide"),
    Quantity("v_slip", "mm/s", "velocity of the block B2 along the guide, signed along C→B"),
    Quantity("a_slip", "mm/s²", "relative acceleration of B2 along the guide, signed along C→B"),
    Quantity("a_coriolis", "mm/s²", "Coriolis acceleration 2·ω3·v_slip of B2 relative to the guide, signed along "
             "C→B turned +90°"),
) + SCALES


def _guide_validate(g: Mapping[str, Any]) -> list[str]:
    _omega(g)
    AB, AC, phi = g["AB"], g["AC"], g["phi"]
    if math.isclose(AB, AC) and math.isclose(math.remainder(phi + 90.0, 360.0), 0.0, abs_tol=1e-9):
        raise NotAMechanism(f"at phi = {phi:g}° B lies on C (AB = AC = {AB:g}): the guide's direction is undefined")
    return []


def coriolis_end(b2: Point, b3: Point, b2_: Point, w3: float, mu_v: float, mu_a: float) -> Point:
    """k′ = b2′ + aᵏB3B2/μa, with aᵏB3B2 = 2·ω3 × vB3B2 (vB3B2 = (b3 − b2)·μv turned 90° in the sense of ω3)."""
    k = 2.0 * w3 * mu_v / mu_a
    dx, dy = (b3.x - b2.x) * k, (b3.y - b2.y) * k
    return Point(b2_.x - dy, b2_.y + dx)


def across(p: Point, q: Point, a: Point, b: Point, mu: float) -> float:
    """The polygon side ``p → q`` read along the direction a→b turned +90°, at the scale ``mu``."""
    dx, dy = b.x - a.x, b.y - a.y
    n = math.hypot(dx, dy)
    return mu * ((q.y - p.y) * dx - (q.x - p.x) * dy) / n


def guide_construct(g: Mapping[str, Any]) -> Construction:
    """Build the guide-bar at φ and its velocity and acceleration polygons (with the Coriolis component)."""
    AB, AC, phi, omega = g["AB"], g["AC"], g["phi"], g["omega"]
    epsilon = g.get("epsilon", 0.0) or 0.0
    sc = Scene("Guide-bar: velocity and acceleration polygons, Coriolis acceleration")
    A = add_pivot(sc, "A", Point(0.0, 0.0), ("Crank pivot A at the origin", "取曲柄转动中心 A 为原点"))
    C = add_pivot(sc, "C", (0.0, -AC), (f"Guide pivot C below A, AC = {AC:g}", f"在 A 下方取导杆转动中心 C,AC = {AC:g}"))
    B = sc.add("B", crank_pin, A, AB, phi, style="joint", label="B",
               caption=(f"Crank at φ = {phi:g}°: B with AB = {AB:g}", f"曲柄转角 φ = {phi:g}°:取 AB = {AB:g} 得 B"))
    lCB = sc.add("lCB", line_through, C, B, caption=("The guide CB through the block B", "过滑块 B 作导杆 CB"))
    drawing = sc.drawing
    if drawing:
        add_bar(sc, "AB", A, B, ("Draw the crank AB and the guide", "画出曲柄 AB 与导杆"))
        sc.add("CB", segment, C, B, role=Role.RESULT, style="link")
        sc.add("block", _block_along, B, C, role=Role.ANNOTATION, style="slider")
    gap = _gap(AB, AC)
    mu_v, p, b2 = add_crank_velocity(sc, A, B, AB, omega, gap, (A, B, C), label="b2")
    sl = sc.add("sl", parallel, lCB, b2, caption=("Through b2, the direction of vB3B2 (∥ CB)", "过 b2 作 vB3B2 的方向线(∥ CB)"))
    tp = sc.add("tp", perpendicular, lCB, p, caption=("Through p, the direction of vB3 (⊥ CB)", "过 p 作 vB3 的方向线(⊥ CB)"))
    b3 = sc.add("b3", meet, sl, tp, style="point", label="b3", caption=("They meet at b3", "两线交于 b3"))
    w3 = sc.add("omega3", rate, p, b3, C, B, mu_v, role=Role.MEASUREMENT, unit="rad/s",
                caption=("ω3 = vB3/CB = pb3·μv/CB", "ω3 = vB3/lCB = pb3·μv/lCB"))
    sc.add("v_slip", along, b3, b2, lCB, mu_v, role=Role.MEASUREMENT, unit="mm/s",
           caption=("Slip vB2B3 = b3b2·μv (signed along C→B)", "相对滑动速度 vB2B3 = b3b2·μv(沿 C→B 为正)"))
    mu_a, p2, b2_ = add_crank_acceleration(sc, A, B, omega, epsilon, gap, (p, b2, b3), label="b2′")
    k_ = sc.add("k", coriolis_end, b2, b3, b2_, w3, mu_v, mu_a, style="point", label="k′",
                caption=("From b2′, the Coriolis component aᵏB3B2 = 2ω3·vB3B2: vB3B2 turned 90° in the sense of ω3",
                         "自 b2′ 作哥氏加速度 aᵏB3B2 = 2ω3·vB3B2,方向为 vB3B2 沿 ω3 转向转 90°"))
    rl = sc.add("rl", parallel, lCB, k_, caption=("Through k′, the direction of aʳB3B2 (∥ CB)", "过 k′ 作 aʳB3B2 的方向线(∥ CB)"))
    k3 = sc.add("k_n3", normal_length, w3, mu_a, visible=False)
    n3 = sc.add("n3", turned, p2, B, C, k3, 0.0, style="point", label="n3",
                caption=("From p′, p′n3 ∥ BC: aB3ⁿ = ω3²·CB, towards C", "自 p′ 作 p′n3 ∥ BC:aB3ⁿ = ω3²·lCB,指向 C"))
    t3 = sc.add("t3", perpendicular, lCB, n3, caption=("Through n3, the direction of aB3ᵗ (⊥ CB)", "过 n3 作 aB3ᵗ 的方向线(⊥ CB)"))
    b3_ = sc.add("b3a", meet, rl, t3, style="point", label="b3′", caption=("They meet at b3′", "两线交于 b3′"))
    sc.add("epsilon3", rate, n3, b3_, C, B, mu_a, role=Role.MEASUREMENT, unit="rad/s²",
           caption=("ε3 = aB3ᵗ/CB = n3b3′·μa/CB", "ε3 = aB3ᵗ/lCB = n3b3′·μa/lCB"))
    sc.add("a_slip", along, b3_, k_, lCB, mu_a, role=Role.MEASUREMENT, unit="mm/s²",
           caption=("Relative acceleration aʳB2B3 = b3′k′·μa (signed along C→B)", "相对加速度 aʳB2B3 = b3′k′·μa(沿 C→B 为正)"))
    sc.add("a_coriolis", across, k_, b2_, C, B, mu_a, role=Role.MEASUREMENT, unit="mm/s²",
           caption=("Coriolis aᵏB2B3 = k′b2′·μa (signed along C→B turned +90°)", "哥氏加速度 aᵏB2B3 = k′b2′·μa(沿 C→B 逆转 90° 为正)"))
    if drawing:
        for key, a, z in (("v_pb3", p, b3), ("v_b2b3", b2, b3), ("a_b2k", b2_, k_), ("a_kb3", k_, b3_),
                          ("a_pn3", p2, n3), ("a_n3b3", n3, b3_), ("a_pb3", p2, b3_)):
            sc.add(key, vector, a, z, role=Role.ANNOTATION, style="vector")
    names = ("omega3", "epsilon3", "v_slip", "a_slip", "a_coriolis", "mu_v", "mu_a")
    return Construction(sc, {n: n for n in names}, {n: n for n in ("A", "B", "C")})


def guide_analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """The vector loop in the guide's frame, differentiated exactly."""
    eps = g.get("epsilon", 0.0) or 0.0
    r = guide_bar(g["AB"], g["AC"], g["phi"], g["omega"], eps)
    return [{**{k: r[k] for k in ("omega3", "epsilon3", "v_slip", "a_slip", "a_coriolis")}, **twin_scales(g)}]


GUIDE = Recipe(
    name="guide_bar.kinematics",
    title="Guide-bar: velocity and acceleration polygons with the Coriolis component",
    givens=GUIDE_GIVENS, answers=GUIDE_ANSWERS, points=("A", "B", "C"),
    construct=guide_construct, analytic=guide_analytic, validate=_guide_validate,
)

__all__ = ["GUIDE", "SLIDER", "across", "coriolis_end"]
