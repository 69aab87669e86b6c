"""Step operations shared by the velocity and acceleration polygons (矢量方程图解法): pure functions of step
values, laid off in the drawing's millimetres at a polygon's scale μ (real units per drawn mm).

Examples
--------
>>> turned(Point(0, 0), Point(0, 0), Point(2, 0), 1.5, 1.0)
Point(x=0.0, y=3.0)
>>> rate(Point(0, 0), Point(0, 3), Point(0, 0), Point(2, 0), 1.0)
1.5
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..errors import Degenerate, NotAMechanism
from ..geometry import (LeftOf, Line, Point, RightOf, ToRightOf, circle, circle_circle, line_circle, line_line,
                        line_through, parallel, perpendicular, segment)
from ..scene import Ref, Role, Scene, marks
from ..scene.marks import vector
from .base import Quantity
from .common import add_bar, add_pivot, guide_between

PHI = Quantity("phi", "deg", "crank angle, counter-clockwise from +x (from A→D for the four-bar)", minimum=-360.0,
               inclusive=True, maximum=360.0)
OMEGA = Quantity("omega", "rad/s", "crank angular velocity, counter-clockwise positive (not 0)", minimum=None)
EPSILON = Quantity("epsilon", "rad/s²", "crank angular acceleration, counter-clockwise positive", required=False,
                   default=0.0, minimum=None)
SCALES = (Quantity("mu_v", "(mm/s)/mm", "scale of the velocity polygon"),
          Quantity("mu_a", "(mm/s²)/mm", "scale of the acceleration polygon"))
"""The givens of the crank's motion and the polygons' scales, shared by every kinematics recipe."""


def crank_pin(A: Point, r: float, phi_deg: float) -> Point:
    """B at distance ``r`` from A at ``phi_deg`` counter-clockwise from +x."""
    a = math.radians(phi_deg)
    return Point(A.x + r * math.cos(a), A.y + r * math.sin(a))


def pole_beside(gap: float, y: float, *pts: Point) -> Point:
    """A polygon's pole, taken in free space: ``gap`` to the right of the rightmost of ``pts``, at height ``y``
    (``gap`` includes the polygon's first side, which may point back to the left).

    >>> pole_beside(10.0, 0.0, Point(0, 0), Point(5, 3))
    Point(x=15.0, y=0.0)
    """
    return Point(max(p.x for p in pts) + gap, y)


def turned(start: Point, a: Point, b: Point, k: float, quarter: float) -> Point:
    """``start + k·(b − a)`` turned by ``quarter``·90° (quarter ∈ {0, 1, −1}): a polygon side laid off parallel or
    perpendicular to a link."""
    dx, dy = (b.x - a.x) * k, (b.y - a.y) * k
    if quarter > 0:
        dx, dy = -dy, dx
    elif quarter < 0:
        dx, dy = dy, -dx
    return Point(start.x + dx, start.y + dy)


def meet(l1: Line, l2: Line) -> Point:
    """Where a polygon's two direction lines meet (parallel lines: the polygon does not close, a dead point)."""
    pts = line_line(l1, l2)
    if len(pts) != 1:
        raise Degenerate("the two direction lines are parallel: the polygon does not close (a dead point)")
    return pts[0]


def rate(p: Point, q: Point, a: Point, b: Point, mu: float) -> float:
    """The angular rate a polygon side ``p → q`` (scale ``mu``) gives the link ``a → b``: (b − a) × (q − p) / |b − a|²,
    counter-clockwise positive (a velocity ω × r, or a tangential acceleration ε × r)."""
    rx, ry = b.x - a.x, b.y - a.y
    return mu * (rx * (q.y - p.y) - ry * (q.x - p.x)) / (rx * rx + ry * ry)


def scaled_length(p: Point, q: Point, mu: float) -> float:
    """|pq|·μ: a polygon side read as a speed or an acceleration."""
    return mu * math.hypot(q.x - p.x, q.y - p.y)


def image(b: Point, c: Point, BE: float, BC: float, angle_deg: float) -> Point:
    """The image e of E: the triangle bce similar to BCE, turned the same way (e from b at ∠cbe = ∠CBE,
    be = bc·BE/BC)."""
    a = math.radians(angle_deg)
    k = BE / BC
    dx, dy = (c.x - b.x) * k, (c.y - b.y) * k
    ca, sa = math.cos(a), math.sin(a)
    return Point(b.x + ca * dx - sa * dy, b.y + sa * dx + ca * dy)


def normal_length(w: float, mu: float) -> float:
    """A normal component ω²·r drawn at the scale μ, as a multiple of the link vector r (``turned`` multiplies by
    it): ω²/μ."""
    return w * w / mu


def accel_scale(omega: float, epsilon: float) -> float:
    """μa = |aB|/AB = √(ω⁴ + ε²): p′b′ drawn as long as AB."""
    return math.sqrt(omega ** 4 + epsilon ** 2)


def ratio(x: float, y: float) -> float:
    """x / y (a tangential component ε·r drawn at the scale μ, as a multiple of the link vector r)."""
    return x / y


def along(p: Point, q: Point, line: Line, mu: float) -> float:
    """The polygon side ``p → q`` read along ``line``'s direction at the scale ``mu`` (a slider's signed velocity or
    acceleration, a slip along a guide)."""
    d = line.direction
    return mu * ((q.x - p.x) * d.x + (q.y - p.y) * d.y)


def add_crank_velocity(sc: Scene, A: Ref, B: Ref, AB: Any, omega: Any, gap: Any, beside: tuple[Ref, ...],
                       label: str = "b") -> tuple[Ref, Ref, Ref]:
    """The velocity polygon's start: its scale μv = |ω| (so that pb is as long as AB), the pole p to the right of
    ``beside`` and b with pb ⊥ AB in the sense of ω. Returns (μv, p, b)."""
    mu_v = sc.add("mu_v", abs, omega, role=Role.MEASUREMENT, unit="(mm/s)/mm", visible=False)
    p = sc.add("p", pole_beside, gap, 0.0, *beside, style="given", label="p",    # the scale's caption here: a
               caption=(f"Velocity scale μv = |ω| = {abs(omega):g} (mm/s)/mm (pb as long as AB); "  # hidden step's
                        "velocity pole p beside the linkage",                                  # never printed
                        f"取速度比例尺 μv = |ω| = {abs(omega):g} (mm/s)/mm(使 pb 与 AB 等长),在机构旁取速度极点 p"))
    b = sc.add("b", turned, p, A, B, 1.0, 1.0 if omega > 0 else -1.0, style="point", label=label,
               caption=(f"p{label} ⊥ AB in the sense of ω: vB = ω·AB = {abs(omega) * AB:g} mm/s",
                        f"作 p{label} ⊥ AB(指向与 ω 转向一致):vB = ω·lAB = {abs(omega) * AB:g} mm/s"))
    if sc.drawing:
        sc.add("v_pb", vector, p, b, role=Role.ANNOTATION, style="vector")
        sc.add("omega1", marks.rotation, A, 1.0 if omega > 0 else -1.0, "ω1", role=Role.ANNOTATION, style="angle")
    return mu_v, p, b


def add_crank_acceleration(sc: Scene, A: Ref, B: Ref, omega: Any, epsilon: Any, gap: Any, beside: tuple[Ref, ...],
                           label: str = "b′") -> tuple[Ref, Ref, Ref]:
    """The acceleration polygon's start: its scale μa = |aB|/AB (p′b′ as long as AB), the pole p′ to the right of
    ``beside`` (the velocity polygon), the normal component ω²·AB along B→A and, when the crank accelerates, the
    tangential ε·AB ⊥ AB. Returns (μa, p′, b′)."""
    mu_a = sc.add("mu_a", accel_scale, omega, epsilon, role=Role.MEASUREMENT, unit="(mm/s²)/mm", visible=False)
    p2 = sc.add("p2", pole_beside, gap, 0.0, *beside, style="given", label="p′",
                caption=("Acceleration scale μa = |aB|/AB (p′b′ as long as AB); acceleration pole p′ beside the "
                         "velocity polygon",
                         "取加速度比例尺 μa = aB/lAB(使 p′b′ 与 AB 等长),在速度多边形旁取加速度极点 p′"))
    k_n = sc.add("k_nB", normal_length, omega, mu_a, visible=False)
    plain = epsilon == 0
    nB = sc.add("nB", turned, p2, B, A, k_n, 0.0, style="point", label=label if plain else "nB",
                caption=("p′nB ∥ BA: aBⁿ = ω²·AB, towards A", "作 p′nB ∥ BA:aBⁿ = ω²·lAB,指向 A"))
    drawing = sc.drawing
    if drawing:
        sc.add("a_pn", vector, p2, nB, role=Role.ANNOTATION, style="vector")
    if plain:
        return mu_a, p2, nB
    k_t = sc.add("k_tB", ratio, epsilon, mu_a, visible=False)
    b2 = sc.add("b2", turned, nB, A, B, k_t, 1.0, style="point", label=label,
                caption=(f"nB{label} ⊥ AB: aBᵗ = ε·AB in the sense of ε",
                         f"作 nB{label} ⊥ AB:aBᵗ = ε·lAB,指向与 ε 转向一致"))
    if drawing:
        sc.add("a_nb", vector, nB, b2, role=Role.ANNOTATION, style="vector")
        sc.add("a_pb", vector, p2, b2, role=Role.ANNOTATION, style="vector")
    return mu_a, p2, b2


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


def add_guide_velocity(sc: Scene, A: Ref, B: Ref, C: Ref, lCB: Ref, AB: Any, omega: Any, gap: Any,
                       beside: tuple[Ref, ...]) -> tuple[tuple[Ref, Ref, Ref, Ref], Ref]:
    """The guide-bar's velocity polygon (the block B2 on the crank slides on the guide CB, B3 the guide's point at
    B): pb2 ⊥ AB; the line through b2 ∥ CB meets the line through p ⊥ CB at b3; ω3 = pb3·μv/CB and the slip
    b3b2·μv along C→B (steps ``omega3``, ``v_slip``). Returns (μv, p, b2, b3)."""
    mu_v, p, b2 = add_crank_velocity(sc, A, B, AB, omega, gap, beside, label="b2")
    sl = sc.add("sl", parallel, lCB, b2, style="direction", caption=("Through b2, the direction of vB3B2 (∥ CB)", "过 b2 作 vB3B2 的方向线(∥ CB)"))
    tp = sc.add("tp", perpendicular, lCB, p, style="direction", caption=("Through p, the direction of vB3 (⊥ CB)", "过 p 作 vB3 的方向线(⊥ CB)"))
    b3 = sc.add("b3", meet, sl, tp, style="point", label="b3", caption=("They meet at b3", "两线交于 b3"))
    w3 = sc.add("omega3", rate, p, b3, C, B, mu_v, role=Role.MEASUREMENT, unit="rad/s",
                caption=("ω3 = vB3/CB = pb3·μv/CB", "ω3 = vB3/lCB = pb3·μv/lCB"))
    sc.add("v_slip", along, b3, b2, lCB, mu_v, role=Role.MEASUREMENT, unit="mm/s",
           caption=("Slip vB2B3 = b3b2·μv (signed along C→B)", "相对滑动速度 vB2B3 = b3b2·μv(沿 C→B 为正)"))
    return (mu_v, p, b2, b3), w3


def add_guide_acceleration(sc: Scene, A: Ref, B: Ref, C: Ref, lCB: Ref, omega: Any, epsilon: Any, gap: Any,
                           beside: tuple[Ref, ...], v: tuple[Ref, Ref, Ref, Ref], w3: Ref) -> tuple[Ref, ...]:
    """The guide-bar's acceleration polygon after its velocity polygon ``v`` = (μv, p, b2, b3): p′b2′ is aB2; the
    pole p′ beside ``beside``; the
    Coriolis component 2ω3·vB3B2 from b2′ to k′ (vB3B2 turned 90° in the sense of ω3); the line through k′ ∥ CB
    (aʳ) meets the line ⊥ CB through n3 (p′n3 = ω3²·CB along B→C) at b3′; ε3, a_slip and a_coriolis read off.
    Returns (μa, p′, b2′, k′, n3, b3′)."""
    mu_v, p, b2, b3 = v
    mu_a, p2, b2_ = add_crank_acceleration(sc, A, B, omega, epsilon, gap, beside, label="b2′")
    k_ = sc.add("k", coriolis_end, b2, b3, b2_, w3, mu_v, mu_a, style="point", label="k′",
                caption=("From b2′, the Coriolis component aᵏB3B2 = 2ω3·vB3B2: vB3B2 turned 90° in the sense of ω3",
                         "自 b2′ 作哥氏加速度 aᵏB3B2 = 2ω3·vB3B2,方向为 vB3B2 沿 ω3 转向转 90°"))
    rl = sc.add("rl", parallel, lCB, k_, style="direction", caption=("Through k′, the direction of aʳB3B2 (∥ CB)", "过 k′ 作 aʳB3B2 的方向线(∥ CB)"))
    k3 = sc.add("k_n3", normal_length, w3, mu_a, visible=False)
    n3 = sc.add("n3", turned, p2, B, C, k3, 0.0, style="point", label="n3",
                caption=("From p′, p′n3 ∥ BC: aB3ⁿ = ω3²·CB, towards C", "自 p′ 作 p′n3 ∥ BC:aB3ⁿ = ω3²·lCB,指向 C"))
    t3 = sc.add("t3", perpendicular, lCB, n3, style="direction", caption=("Through n3, the direction of aB3ᵗ (⊥ CB)", "过 n3 作 aB3ᵗ 的方向线(⊥ CB)"))
    b3_ = sc.add("b3a", meet, rl, t3, style="point", label="b3′", caption=("They meet at b3′", "两线交于 b3′"))
    sc.add("epsilon3", rate, n3, b3_, C, B, mu_a, role=Role.MEASUREMENT, unit="rad/s²",
           caption=("ε3 = aB3ᵗ/CB = n3b3′·μa/CB", "ε3 = aB3ᵗ/lCB = n3b3′·μa/lCB"))
    sc.add("a_slip", along, b3_, k_, lCB, mu_a, role=Role.MEASUREMENT, unit="mm/s²",
           caption=("Relative acceleration aʳB2B3 = b3′k′·μa (signed along C→B)", "相对加速度 aʳB2B3 = b3′k′·μa(沿 C→B 为正)"))
    sc.add("a_coriolis", across, k_, b2_, C, B, mu_a, role=Role.MEASUREMENT, unit="mm/s²",
           caption=("Coriolis aᵏB2B3 = k′b2′·μa (signed along C→B turned +90°)", "哥氏加速度 aᵏB2B3 = k′b2′·μa(沿 C→B 逆转 90° 为正)"))
    return mu_a, p2, b2_, k_, n3, b3_


def guide_vectors(v: tuple[Ref, ...], a: tuple[Ref, ...]) -> tuple[tuple[str, Ref, Ref], ...]:
    """The arrows of the guide-bar's polygons (``v`` from :func:`add_guide_velocity`, ``a`` from
    :func:`add_guide_acceleration`)."""
    _, p, b2, b3 = v
    _, p2, b2_, k_, n3, b3_ = a
    return (("v_pb3", p, b3), ("v_b2b3", b2, b3), ("a_b2k", b2_, k_), ("a_kb3", k_, b3_), ("a_pn3", p2, n3),
            ("a_n3b3", n3, b3_), ("a_pb3", p2, b3_))


@dataclass(frozen=True)
class RRP:
    """How an RRP dyad's polygon steps are named: the joint ``J`` it hangs from, the slider ``X``, the link number
    ``n``, the path's positive direction and words, and the keys of the two lines through the poles.

    >>> d = RRP("D", "E", "4", "+y", ("the ram's path", "滑枕导路"), ("tpE", "taE"))
    >>> d.j, d.x, d.line
    ('d', 'e', 'lDE')
    """

    J: str = "B"
    X: str = "C"
    n: str = "2"
    axis: str = "+x"
    path: tuple[str, str] = ("the guide", "导路")
    poles: tuple[str, str] = ("tp", "t3")

    @property
    def j(self) -> str:
        return self.J.lower()

    @property
    def x(self) -> str:
        return self.X.lower()

    @property
    def line(self) -> str:
        return f"l{self.J}{self.X}"


def add_rrp_velocity(sc: Scene, J: Ref, X: Ref, path: Ref, j: Ref, p: Ref, mu_v: Ref, d: RRP = RRP()) -> tuple[Ref, Ref, Ref]:
    """An RRP dyad's velocity polygon (vX = vJ + vXJ): the line through j ⊥ JX meets the line through p ∥ the
    path at x; vX read signed along the path and ωn = vXJ/JX. Returns (the line JX, x, ωn)."""
    JX, jx, n = f"{d.J}{d.X}", f"{d.j}{d.x}", d.n
    lJX = sc.add(d.line, line_through, J, X, visible=False)
    tj = sc.add(f"t{d.j}", perpendicular, lJX, j, style="direction", caption=(f"Through {d.j}, the direction of v{d.X}{d.J} (⊥ {JX})",
                                                          f"过 {d.j} 作 v{d.X}{d.J} 的方向线(⊥ {JX})"))
    tp = sc.add(d.poles[0], parallel, path, p, style="direction", caption=(f"Through p, the direction of v{d.X} (∥ {d.path[0]})",
                                                        f"过 p 作 v{d.X} 的方向线(∥ {d.path[1]})"))
    x = sc.add(d.x, meet, tj, tp, style="point", label=d.x, caption=(f"They meet at {d.x}", f"两线交于 {d.x}"))
    sc.add(f"v{d.X}", along, p, x, path, mu_v, role=Role.MEASUREMENT, unit="mm/s",
           caption=(f"Measure v{d.X} = p{d.x}·μv (signed along {d.axis})", f"量得 v{d.X} = p{d.x}·μv(沿 {d.axis} 为正)"))
    w = sc.add(f"omega{n}", rate, j, x, J, X, mu_v, role=Role.MEASUREMENT, unit="rad/s",
               caption=(f"ω{n} = v{d.X}{d.J}/{JX} = {jx}·μv/{JX} (sense: {jx} carried to {d.X})",
                        f"ω{n} = v{d.X}{d.J}/l{JX} = {jx}·μv/l{JX}(将 {jx} 移至 {d.X} 点判断转向)"))
    return lJX, x, w


def add_rrp_acceleration(sc: Scene, J: Ref, X: Ref, path: Ref, lJX: Ref, j_: Ref, p2: Ref, w: Ref, mu_a: Ref,
                         d: RRP = RRP()) -> tuple[Ref, Ref]:
    """An RRP dyad's acceleration polygon (aX = aJ + aXJⁿ + aXJᵗ): from j′ the normal ωn²·JX towards J to nn, the
    line through nn ⊥ JX meets the line through p′ ∥ the path at x′; aX read signed along the path and
    εn = nnx′/JX. Returns (nn, x′)."""
    JX, XJ, n, j, x = f"{d.J}{d.X}", f"{d.X}{d.J}", d.n, d.j, d.x
    k = sc.add(f"k_n{n}", normal_length, w, mu_a, visible=False)
    nn = sc.add(f"n{n}", turned, j_, X, J, k, 0.0, style="point", label=f"n{n}",
                caption=(f"From {j}′, {j}′n{n} ∥ {XJ}: a{XJ}ⁿ = ω{n}²·{JX}, towards {d.J}",
                         f"自 {j}′ 作 {j}′n{n} ∥ {XJ}:a{XJ}ⁿ = ω{n}²·l{JX},指向 {d.J}"))
    tn = sc.add(f"t{n}", perpendicular, lJX, nn, style="direction", caption=(f"Through n{n}, the direction of a{XJ}ᵗ (⊥ {JX})",
                                                         f"过 n{n} 作 a{XJ}ᵗ 的方向线(⊥ {JX})"))
    tp = sc.add(d.poles[1], parallel, path, p2, style="direction", caption=(f"Through p′, the direction of a{d.X} (∥ {d.path[0]})",
                                                         f"过 p′ 作 a{d.X} 的方向线(∥ {d.path[1]})"))
    x_ = sc.add(f"{x}2", meet, tn, tp, style="point", label=f"{x}′", caption=(f"They meet at {x}′", f"两线交于 {x}′"))
    sc.add(f"a{d.X}", along, p2, x_, path, mu_a, role=Role.MEASUREMENT, unit="mm/s²",
           caption=(f"Measure a{d.X} = p′{x}′·μa (signed along {d.axis})", f"量得 a{d.X} = p′{x}′·μa(沿 {d.axis} 为正)"))
    sc.add(f"epsilon{n}", rate, nn, x_, J, X, mu_a, role=Role.MEASUREMENT, unit="rad/s²",
           caption=(f"ε{n} = a{XJ}ᵗ/{JX} = n{n}{x}′·μa/{JX}", f"ε{n} = a{XJ}ᵗ/l{JX} = n{n}{x}′·μa/l{JX}"))
    return nn, x_


def rrp_vectors(p: Ref, j: Ref, x: Ref, p2: Ref, j_: Ref, nn: Ref, x_: Ref, d: RRP = RRP()) -> tuple[tuple[str, Ref, Ref], ...]:
    """The arrows of an RRP dyad's polygons."""
    return ((f"v_p{d.x}", p, x), (f"v_{d.j}{d.x}", j, x), (f"a_{d.j}n{d.n}", j_, nn), (f"a_n{d.n}{d.x}", nn, x_),
            (f"a_p{d.x}", p2, x_))


def four_bar_assembles(g: Any) -> None:
    """Refuse a four-bar that cannot be assembled at its crank angle (BD outside (|BC − CD|, BC + CD)), naming a
    dead point when BC and CD are collinear."""
    AB, BC, CD, AD, phi = g["AB"], g["BC"], g["CD"], g["AD"], g["phi"]
    d = math.hypot(AD - AB * math.cos(math.radians(phi)), AB * math.sin(math.radians(phi)))
    if not abs(BC - CD) < d < BC + CD:
        raise NotAMechanism(f"at phi = {phi:g}° the links do not assemble: BD = {d:.6g} is outside "
                            f"(|BC − CD|, BC + CD) = ({abs(BC - CD):.6g}, {BC + CD:.6g})"
                            + (" — a dead point: BC and CD collinear" if math.isclose(d, BC + CD) or
                               math.isclose(d, abs(BC - CD)) else ""))


def slider_assembles(g: Any) -> None:
    """Refuse a crank-slider whose rod cannot reach the guide at its crank angle (|y of B + e| ≥ BC)."""
    AB, BC, e, phi = g["AB"], g["BC"], g["e"], g["phi"]
    h = AB * math.sin(math.radians(phi)) + e
    if abs(h) >= BC:
        raise NotAMechanism(f"at phi = {phi:g}° B is {abs(h):.6g} from the guide, not less than BC = {BC:g}"
                            + (": the rod is perpendicular to the guide (a dead point)" if math.isclose(abs(h), BC) else ""))


CENTRE_LABELS = {"A": "A (P14)", "B": "B (P12)", "C": "C (P23)", "D": "D (P34)"}
"""A joint that is an instant centre is labelled with both names, as the textbook writes "B (P12)": links 1 the
crank, 2 the coupler, 3 the rocker (slider), 4 the frame."""


def add_four_bar_at(sc: Scene, g: Any, centres: bool = False) -> tuple[Ref, Ref, Ref, Ref]:
    """The four-bar at its crank angle: A, D, B on the crank circle, C where the circles about B and D meet on the
    side ``branch`` names, and (drawing) the frame and the links; ``centres`` names the joints as instant centres.
    Returns (A, D, B, C)."""
    AB, BC, CD, AD, phi = g["AB"], g["BC"], g["CD"], g["AD"], g["phi"]
    below = g.get("branch", "above") == "below"
    if centres:
        words = (("Fixed pivot A = P14 at the origin", "固定铰链 A 即瞬心 P14,取为原点"),
                 (f"Fixed pivot D = P34, AD = {AD:g}", f"固定铰链 D 即瞬心 P34,AD = {AD:g}"),
                 (f"Crank at φ = {phi:g}°: B = P12", f"曲柄转角 φ = {phi:g}°:B 即瞬心 P12"),
                 ("They meet at C = P23", "两圆交于 C,即瞬心 P23"), ("Draw the linkage ABCD", "画出机构 ABCD"))
    else:
        words = (("Fixed pivot A at the origin", "取固定铰链 A 为原点"),
                 (f"Fixed pivot D on the frame line, AD = {AD:g}", f"在机架线上取 D,使 AD = {AD:g}"),
                 (f"Crank at φ = {phi:g}°: B with AB = {AB:g}", f"曲柄转角 φ = {phi:g}°:取 AB = {AB:g} 得 B"),
                 ("They meet at C", "两圆交于 C"), ("Draw the linkage ABCD at this position", "画出该位置的机构 ABCD"))
    name = CENTRE_LABELS if centres else {}
    tag = "-centre" if centres else ""             # the label prints whole (geomcon.render.style: label_whole)
    A = add_pivot(sc, "A", Point(0.0, 0.0), words[0], label=name.get("A"), style="pivot" + tag)
    D = add_pivot(sc, "D", (AD, 0.0), words[1], label=name.get("D"), style="pivot" + tag)
    B = sc.add("B", crank_pin, A, AB, phi, style="joint" + tag, label=name.get("B", "B"), caption=words[2])
    kB = sc.add("kB", circle, B, BC, caption=(f"Circle about B with radius BC = {BC:g}", f"以 B 为圆心、BC = {BC:g} 为半径作圆"))
    kD = sc.add("kD", circle, D, CD, caption=(f"Circle about D with radius CD = {CD:g}", f"以 D 为圆心、CD = {CD:g} 为半径作圆"))
    C = sc.add("C", circle_circle, kB, kD, branch=RightOf(B, D) if below else LeftOf(B, D), style="joint" + tag,
               label=name.get("C", "C"), caption=words[3])
    if sc.drawing:
        sc.add("AD", segment, A, D, role=Role.GIVEN, style="frame", caption=("Draw the frame AD", "作机架 AD"))
        add_bar(sc, "AB", A, B, words[4])
        add_bar(sc, "BC", B, C)
        add_bar(sc, "CD", C, D)
    return A, D, B, C


def add_slider_at(sc: Scene, g: Any, centres: bool = False) -> tuple[Ref, Ref, Ref, Ref, Ref]:
    """The offset crank-slider at its crank angle (the guide y = −e, C to the right of B) and, drawing, its links;
    ``centres`` names the joints as instant centres. Returns (A, F, guide, B, C)."""
    AB, BC, e, phi = g["AB"], g["BC"], g["e"], g["phi"]
    if centres:
        words = (("Fixed pivot A = P14 at the origin", "固定铰链 A 即瞬心 P14,取为原点"),
                 ("The guide through F; P34 lies at infinity perpendicular to it", "过 F 作导路;P34 在垂直于导路的无穷远处"),
                 (f"Crank at φ = {phi:g}°: B = P12", f"曲柄转角 φ = {phi:g}°:B 即瞬心 P12"),
                 ("It meets the guide at C = P23", "交导路于 C,即瞬心 P23"), ("Draw the linkage ABC", "画出机构 ABC"))
    else:
        words = (("Fixed pivot A at the origin", "取固定铰链 A 为原点"),
                 ("The slider's guide through F, parallel to x", "过 F 作滑块导路(水平)"),
                 (f"Crank at φ = {phi:g}°: B with AB = {AB:g}", f"曲柄转角 φ = {phi:g}°:取 AB = {AB:g} 得 B"),
                 ("It meets the guide at C", "交导路于 C"), ("Draw the linkage ABC at this position", "画出该位置的机构 ABC"))
    name = CENTRE_LABELS if centres else {}
    tag = "-centre" if centres else ""             # the label prints whole (geomcon.render.style: label_whole)
    A = add_pivot(sc, "A", Point(0.0, 0.0), words[0], label=name.get("A"), style="pivot" + tag)
    F = sc.given_at("F", 0.0, -e, style="point", caption=(f"F with AF = e = {e:g} (below A)", f"取 AF = e = {e:g}(A 下方)"))
    gl = sc.add("guide", Line, F, Point(1.0, 0.0), role=Role.GIVEN, style="given", caption=words[1])
    B = sc.add("B", crank_pin, A, AB, phi, style="joint" + tag, label=name.get("B", "B"), caption=words[2])
    kB = sc.add("kB", circle, B, BC, caption=(f"Circle about B with radius BC = {BC:g}", f"以 B 为圆心、BC = {BC:g} 为半径作圆"))
    C = sc.add("C", line_circle, gl, kB, branch=ToRightOf(B), style="joint" + tag, label=name.get("C", "C"),
               caption=words[3])
    if sc.drawing:
        add_bar(sc, "AB", A, B, words[4])
        add_bar(sc, "BC", B, C)
        sc.add("slider", marks.slider, C, Point(1.0, 0.0), role=Role.ANNOTATION, style="slider")
        sc.add("guide_mark", guide_between, C, C, gl, 0.6 * AB, role=Role.ANNOTATION, style="guide")
    return A, F, gl, B, C


def twin_scales(g: Any) -> dict[str, float]:
    """The polygons' scales as the twins state them: μv = |ω|, μa = √(ω⁴ + ε²)."""
    return {"mu_v": abs(g["omega"]), "mu_a": math.hypot(g["omega"] ** 2, g.get("epsilon", 0.0) or 0.0)}


def add_image(sc: Scene, key: str, b: Ref, c: Ref, BE: Any, BC: Any, angle: Any, pole: Ref, mu: Ref, answer: str,
              label: str, unit: str, words: tuple[str, str, str]) -> Ref:
    """A coupler point's image in a polygon (the triangle bce similar to BCE, turned the same way) and the answer
    read from the pole to it."""
    e = sc.add(key, image, b, c, BE, BC, angle, style="point", label=label,
               caption=(f"Image {label}: triangle {words[0]} similar to BCE (image principle)",
                        f"由影像原理作 △{words[0]} ∽ △BCE 得 {label}"))
    sc.add(answer, scaled_length, pole, e, mu, role=Role.MEASUREMENT, unit=unit,
           caption=(f"Measure {answer} = {words[1]}·{words[2]}", f"量得 {answer} = {words[1]}·{words[2]}"))
    return e


__all__ = ["EPSILON", "OMEGA", "PHI", "RRP", "SCALES", "accel_scale", "across", "add_guide_acceleration",
           "add_guide_velocity", "add_rrp_acceleration", "add_rrp_velocity", "coriolis_end", "guide_vectors",
           "rrp_vectors", "add_four_bar_at", "add_image", "add_slider_at",
           "four_bar_assembles", "slider_assembles", "twin_scales", "add_crank_acceleration", "add_crank_velocity", "along", "crank_pin", "image", "meet", "normal_length", "pole_beside", "rate", "ratio",
           "scaled_length", "turned"]
