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
from ..geometry import Point, line_through, segment
from ..scene import Role, Scene
from ..scene.marks import vector
from .base import Construction, Quantity, Recipe
from .common import add_bar, add_pivot
from .guide_bar import _block_along
from .kinematics_common import (EPSILON, OMEGA, PHI, SCALES, across, add_crank_acceleration, add_crank_velocity,
                                add_guide_acceleration, add_guide_velocity, add_rrp_acceleration, add_rrp_velocity,
                                add_slider_at, coriolis_end, crank_pin, guide_vectors, rrp_vectors, slider_assembles,
                                twin_scales)

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
    gap = _gap(AB, BC, abs(e)) + 0.6 * AB        # the guide's hatch reaches 0.6·AB beyond C (add_slider_at)
    mu_v, p, b = add_crank_velocity(sc, A, B, AB, omega, gap, (A, F, B, C))
    lBC, c, w2 = add_rrp_velocity(sc, B, C, gl, b, p, mu_v)
    mu_a, p2, b2 = add_crank_acceleration(sc, A, B, omega, epsilon, gap, (p, b, c))
    n2, c2 = add_rrp_acceleration(sc, B, C, gl, lBC, b2, p2, w2, mu_a)
    if sc.drawing:
        for key, a, z in rrp_vectors(p, b, c, p2, b2, n2, c2):
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


def guide_construct(g: Mapping[str, Any]) -> Construction:
    """Build the guide-bar at φ and its velocity and acceleration polygons (with the Coriolis component)."""
    AB, AC, phi, omega = g["AB"], g["AC"], g["phi"], g["omega"]
    epsilon = g.get("epsilon", 0.0) or 0.0
    sc = Scene("Guide-bar: velocity and acceleration polygons, Coriolis acceleration")
    A = add_pivot(sc, "A", Point(0.0, 0.0), ("Crank pivot A at the origin", "取曲柄转动中心 A 为原点"))
    C = add_pivot(sc, "C", (0.0, -AC), (f"Guide pivot C below A, AC = {AC:g}", f"在 A 下方取导杆转动中心 C,AC = {AC:g}"))
    B = sc.add("B", crank_pin, A, AB, phi, style="joint", label="B",
               caption=(f"Crank at φ = {phi:g}°: B with AB = {AB:g}", f"曲柄转角 φ = {phi:g}°:取 AB = {AB:g} 得 B"))
    lCB = sc.add("lCB", line_through, C, B, style="direction", caption=("The guide CB through the block B", "过滑块 B 作导杆 CB"))
    drawing = sc.drawing
    if drawing:
        add_bar(sc, "AB", A, B, ("Draw the crank AB and the guide", "画出曲柄 AB 与导杆"))
        sc.add("CB", segment, C, B, role=Role.RESULT, style="link")
        sc.add("block", _block_along, B, C, role=Role.ANNOTATION, style="slider")
    gap = _gap(AB, AC)
    v, w3 = add_guide_velocity(sc, A, B, C, lCB, AB, omega, gap, (A, B, C))
    acc = add_guide_acceleration(sc, A, B, C, lCB, omega, epsilon, gap, v[1:], v, w3)
    if drawing:
        for key, a, z in guide_vectors(v, acc):
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
