"""``crank_rocker.design_by_K`` with the crank, the frame and the swing given (``K AB AD psi`` → BC, CD).

Construction: the shape of a design does not depend on its size, so it is drawn with a rocker of the
frame's length (D at the origin, C1 and C2 symmetric about the vertical through D at ψ apart); every A on the
admissible arcs of the two θ-circles gives a design of that shape, whose crank-to-frame ratio
(AC2 − AC1)/(2·AD′) varies along the arcs. The points where it equals AB/AD (sampled along each arc, each
change of sign bisected) are the solutions, each scaled by AD/AD′; C1 is taken as the folded position (the
mirror point is the same design).
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.design_by_k_crank_frame import crank_frame_designs
from ..geometry import Point, segment
from ..scene import Ref, Role, Scene, marks
from ..scene.tape import lifted
from .base import Construction
from .choice_words import flat_caption
from .common import angle_deg, folded_flag, gamma_min_of, half_difference, half_sum, near_flag
from .crank_rocker_design import _rocker_end, admissible_arcs, swing_mark, theta_mark
from .search import crossing
from .theta_circle import add_theta_circle, add_theta_step

SLOTS = 6
"""Candidate designs kept (the ratio meets AB/AD at most a few times along the arcs)."""
CD_MAX = 100.0
"""Designs whose rocker exceeds 100 frames are not sought (twin alike): A then lies within 1 % of the
frame's length from D on the unit drawing, the Grashof margin is a few parts in 10⁵ of the links and the
ratio's difference AC2 − AC1 loses the digits the back-substitution needs."""


def _ratio_roots(D: Point, C1: Point, C2: Point, ratio: float, *arcs_per_side: Any) -> tuple[Point, ...]:
    """The points of the admissible arcs where (AC_far − AC_near)/(2·AD′) = ratio, C1 folded."""
    def f(arc, t: float) -> float:
        A = arc.at(t)
        return half_difference(A, C1, C2) / math.hypot(A.x - D.x, A.y - D.y) - ratio

    out = []
    for arcs in arcs_per_side:
        for arc in arcs:
            n = 720
            ts = [i / n for i in range(n + 1)]
            vals = [f(arc, t) for t in ts]
            for i in range(n):
                if vals[i] == 0.0 or vals[i] * vals[i + 1] < 0.0:
                    t = ts[i] if vals[i] == 0.0 else crossing(lambda x, arc=arc, s=vals[i] > 0: (f(arc, x) > 0) == s,
                                                              ts[i], ts[i + 1])
                    A = arc.at(t)
                    rocker = math.hypot(C1.x - D.x, C1.y - D.y)
                    if folded_flag(A, C1, C2) and rocker <= CD_MAX * math.hypot(A.x - D.x, A.y - D.y):
                        out.append(A)
    return tuple(out)


def _nth(points: tuple[Point, ...], i: int) -> Point | None:
    return points[i] if i < len(points) else None


def _scaled(AD: float, A: Point, D: Point, x: float) -> float:
    return x * AD / math.hypot(A.x - D.x, A.y - D.y)


def _given(AD: float) -> float:
    return AD


def sees_theta(A: Point, C1: Point, C2: Point, theta: float) -> bool:
    """True when A sees the chord C1C2 under θ: a θ-circle's points see it under θ on one arc and 180° − θ on the
    other, and a point of the other arc is a design of another K ((180° + (180° − θ))/(180° − (180° − θ)))."""
    return abs(angle_deg(A, C1, C2) - theta) <= abs(angle_deg(A, C1, C2) - (180.0 - theta))


def add_frame_rocker(sc: Scene, AD: Any, psi: Any) -> tuple[Any, Any, Any]:
    """D and a rocker as long as the frame AD in its two extreme positions DC1, DC2 (ψ apart, symmetric about
    the vertical through D): the unit drawing on which the forms closing on the frame find A. Returns (D, C1, C2)."""
    D = sc.given("D", Point(0.0, 0.0), style="pivot", caption=("Fixed pivot D of the rocker", "摇杆固定铰链 D"))
    if sc.drawing:
        sc.add("D_ground", marks.ground, D, -math.pi / 2, role=Role.ANNOTATION, style="ground")
    C1 = sc.given("C1", lifted(_rocker_end, AD, 90.0 + psi / 2.0), style="joint",
                  caption=(f"A rocker of the frame's length {AD:g}: extreme position DC1", f"取摇杆长等于机架长 {AD:g}:极限位置 DC1"))
    C2 = sc.given("C2", lifted(_rocker_end, AD, 90.0 - psi / 2.0), style="joint",
                  caption=(f"and DC2, ψ = ∠C1DC2 = {psi:g}°", f"及 DC2,ψ = ∠C1DC2 = {psi:g}°"))
    if sc.drawing:
        sc.add("DC1", segment, D, C1, role=Role.GIVEN, style="link")
        sc.add("DC2", segment, D, C2, role=Role.GIVEN, style="link")
    return D, C1, C2


def crank_end(A: Point, C1: Point, C2: Point, extended: bool) -> Point:
    """The crank pin B of the unit drawing in an extreme position: on the folded line beyond A (away from the
    nearer of C1, C2), or on the extended line towards the farther, AB = (AC_far − AC_near)/2 from A."""
    near, far = (C1, C2) if abs(C1 - A) <= abs(C2 - A) else (C2, C1)
    ab = (abs(far - A) - abs(near - A)) / 2.0
    u = ((far - A) if extended else (A - near)).unit()
    return A + u * ab


def add_unit_linkage(sc: Scene, A: Any, D: Any, C1: Any, C2: Any, optional: bool = False,
                     labels: tuple[str | None, str | None] = ("B1", "B2"),
                     caption: tuple[str, str] | Ref = ("The frame AD", "机架 AD")) -> None:
    """The designed linkage drawn solid on the unit drawing in both extreme positions: the crank AB, the
    coupler BC and the frame AD (the rocker DC1, DC2 is drawn already); a figure that shows only the
    construction leaves the answer undrawn (drawing only). ``labels`` names the crank pins (None: unlabelled,
    where the drawing is too small for two more names); ``caption`` is the frame's step's (a :class:`Ref`:
    the step computing it)."""
    if not sc.drawing:
        return
    opt = dict(optional=True) if optional else {}
    sc.add("AD_design", segment, A, D, role=Role.RESULT, style="frame", caption=caption, **opt)
    for i, extended in enumerate((False, True), 1):
        near = sc.add(f"Cn{i}", _pick_c, A, C1, C2, extended, visible=False, **opt)
        B = sc.add(f"B{i}", crank_end, A, C1, C2, extended, role=Role.RESULT, style="joint", label=labels[i - 1],
                   caption=((f"The crank pins B1 (folded) and B2 (extended), AB = (AC_far − AC_near)/2",
                             "曲柄销 B1(重叠共线)与 B2(拉直共线),AB = (AC远 − AC近)/2") if i == 1 else ("", "")), **opt)
        style = "link" if i == 1 else "link-alt"
        sc.add(f"AB{i}_design", segment, A, B, role=Role.RESULT, style=style, **opt)
        sc.add(f"B{i}C{i}_design", segment, B, near, role=Role.RESULT, style=style, **opt)


def _pick_c(A: Point, C1: Point, C2: Point, extended: bool) -> Point:
    """The nearer of C1, C2 to A (the folded position), or the farther (the extended one)."""
    near, far = (C1, C2) if abs(C1 - A) <= abs(C2 - A) else (C2, C1)
    return far if extended else near


def construct(g: Mapping[str, Any]) -> Construction:
    """The unit-size θ-circles; A where the crank-to-frame ratio is AB/AD; each design scaled to AD."""
    K, AB, AD, psi = g["K"], g["AB"], g["AD"], g["psi"]
    sc = Scene("Crank-rocker designed by K from the crank, the frame and the swing")
    th = add_theta_step(sc, K)
    D, C1, C2 = add_frame_rocker(sc, AD, psi)
    arcs = []
    for s, pre, en, zh, lab in ((-1, "n", "on D's side", "D 所在一侧", "P"), (1, "f", "on the far side", "远离 D 的一侧", "P′")):
        kT = add_theta_circle(sc, C1, C2, th, s, side_words=(en, zh), prefix=pre, label=lab)
        arcs.append(sc.add(f"{pre}arcs", admissible_arcs, kT, C1, C2, D, AD, None, style="admissible",
                           caption=(f"Admissible arcs {en}: a crank, C1 and C2 on one side of AD", f"A 的可行弧段({zh})")))
    ratio = sc.add("ratio", _ratio_of, AB, AD, visible=False)
    roots = sc.add("roots", _ratio_roots, D, C1, C2, ratio, *arcs, visible=False,
                   caption=("", ""))
    sols = []
    opt = dict(optional=True, visible=False)
    for i in range(SLOTS):
        A = sc.add(f"A_{i + 1}", _nth, roots, i, optional=True, style="candidate", label=f"A{i + 1}",
                   caption=((f"The points of the arcs where (AC2 − AC1)/(2·AD′) = AB/AD = {AB:g}/{AD:g}",
                             f"在可行弧段上找 (AC2 − AC1)/(2AD′) = AB/AD 的点") if i == 0 else ("", "")))
        for name, op, args in (("AB", _scaled, (AD, A, D, sc.add(f"ab_{i}", half_difference, A, C1, C2, **opt))),
                               ("BC", _scaled, (AD, A, D, sc.add(f"bc_{i}", half_sum, A, C1, C2, **opt))),
                               ("CD", _scaled, (AD, A, D, AD))):
            sc.add(f"{name}_{i}", op, *args, unit="mm", **opt)
        sc.add(f"AD_{i}", _given, AD, unit="mm", **opt)
        sc.add(f"psi_{i}", angle_deg, D, C1, C2, unit="deg", **opt)
        sc.add(f"gamma_min_{i}", gamma_min_of, A, D, C1, C2, unit="deg", **opt)
        sc.add(f"C1_folded_{i}", folded_flag, A, C1, C2, **opt)
        sc.add(f"A_near_{i}", near_flag, A, C1, C2, D, **opt)
        sc.add(f"valid_{i}", sees_theta, A, C1, C2, th, **opt)
        sols.append({"AB": f"AB_{i}", "BC": f"BC_{i}", "AD": f"AD_{i}", "CD": f"CD_{i}", "psi": f"psi_{i}",
                     "gamma_min": f"gamma_min_{i}", "theta": "theta", "K": "K", "C1_folded": f"C1_folded_{i}",
                     "A_near": f"A_near_{i}", "_valid": f"valid_{i}"})
    # solution 1 drawn as a linkage; B2 unnamed: on the small unit drawing its name would sit nearer A2
    words = sc.add("choice_words", _drawn_words, 0, tuple(f"A{i + 1}" for i in range(SLOTS)),
                   *(Ref(f"{k}_{i}") for i in range(SLOTS) for k in ("valid", "C1_folded", "A_near", "AD")),
                   visible=False) if sc.drawing else ("The frame AD", "机架 AD")
    add_unit_linkage(sc, Ref("A_1"), D, C1, C2, optional=True, labels=("B1", None), caption=words)
    # the design drawn is chosen at its frame's step, its crank and coupler measured with the crank pins (001-10c
    # showed them with the candidates, step 14, issue 11)
    sc.read_off("AD_design", "CD_0", "gamma_min_0", "C1_folded_0", "A_near_0")
    sc.read_off("B1", "AB_0", "BC_0")
    if sc.drawing:                          # the designed linkage's crank pivot is a fixed pivot, not only a candidate
        sc.add("A_ground", marks.ground, Ref("A_1"), -math.pi / 2, role=Role.ANNOTATION, style="ground", optional=True)
        # θ and ψ are answers: marked where they are measured, θ at A between the extreme positions, ψ at D
        # (001-10c marked neither; the detail view, which draws the mechanism large, shows them too)
        sc.add("mark_theta", theta_mark, Ref("A_1"), C1, C2, th, role=Role.ANNOTATION, style="angle", optional=True)
        sc.add("mark_psi", swing_mark, D, C1, C2, role=Role.ANNOTATION, style="angle", optional=True)
    return Construction(sc, dict(sols[0]), {"D": "D", "C1": "C1", "C2": "C2"}, solutions=tuple(sols),
                        no_solution=f"no crank-rocker with K = {K:g}, ψ = {psi:g}° has the crank AB = {AB:g} on the frame AD = {AD:g}")


def _drawn_words(idx: int, labels: tuple[str, ...], *flat: Any) -> tuple[str, str]:
    """The frame's step of the design drawn (A1, the first by :func:`preference`: the roots come on D's side
    first, every one folded, AD given) naming it and the other solutions (:mod:`.choice_words`; 001-10c did
    not say which of A1, A2 it drew)."""
    en, zh = flat_caption("A", idx if flat[0] else None, labels, *flat)
    return f"{en}: draw its frame AD", f"{zh}：作机架 AD"


def _ratio_of(AB: float, AD: float) -> float:
    return AB / AD


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """The twin: the designs in closed form, a quadratic in BC² (at most two roots)
    (:func:`geomcon.analytic.design_by_k_crank_frame.crank_frame_designs`)."""
    return crank_frame_designs(g["K"], g["AB"], g["AD"], g["psi"], cd_max=CD_MAX)
