"""``crank_rocker.design_by_K``, links form: crank AB and coupler BC kept, K and the swing ψ prescribed; the
rocker CD and the frame AD are sought (seed 001-17, part 2).

The extreme positions seen from A are fixed by the givens alone: AC1 = BC − AB (folded), AC2 = AB + BC
(extended) and ∠C1AC2 = θ, so the triangle AC1C2 is drawn first (two sides and the included angle). D sees
C1C2 under ψ and is equidistant from C1 and C2: it is the apex of the isosceles triangle on C1C2 with apex
angle ψ, on either side of the chord: from C1 a line at 90° − ψ/2 to C1C2 meets the perpendicular bisector of
C1C2 at D. Two candidates, D on A's side of C1C2 or on the far side; both are crank-rockers when Grashof
holds and C1, C2 lie on one side of AD.

Examples
--------
>>> sols = analytic({"K": 1.2, "AB": 30.0, "BC": 80.0, "psi": 40.0})
>>> [round(s["AD"], 6) for s in sols], round(sols[0]["CD"], 6)
([98.31558, 134.835253], 92.984074)
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.design_by_k import angle_deg_at, rocker_design_valid
from ..analytic.linkages import crank_rocker_gamma_from_positions, theta_from_k
from ..geometry import Point, perpendicular_bisector, point_along, segment
from ..scene import Ref, Role, Scene, marks
from .base import Construction
from .choice_words import flat_caption
from .common import add_bar, angle_deg, best_index, gamma_min_of, is_valid, length, near_flag, pick
from .theta_circle import add_theta_step, complement_turn, meet_lines, ray_from

SIDES = ((1, "on A's side of C1C2", "与 A 同侧"), (-1, "on the far side of C1C2", "在 C1C2 另一侧"))


def _half(x: float) -> float:
    return x / 2.0


def construct(g: Mapping[str, Any]) -> Construction:
    """Both candidates D and the drawing of the textbook's choice (see the module docstring)."""
    K, AB, BC, psi = g["K"], g["AB"], g["BC"], g["psi"]
    sc = Scene("Crank-rocker designed by K: new rocker and frame for the same crank and coupler")
    th = add_theta_step(sc, K)
    sc.add("AB_given", float, AB, visible=False)
    sc.add("BC_given", float, BC, visible=False)
    A = sc.given("A", Point(0.0, 0.0), style="pivot", caption=("Fixed pivot A of the crank", "曲柄固定铰链 A"))
    drawing = sc.drawing                     # the joins, right-angle mark, links and marks only a drawing needs
    if drawing:
        sc.add("A_ground", marks.ground, A, -math.pi / 2, role=Role.ANNOTATION, style="ground")
    C2 = sc.given_at("C2", AB + BC, 0.0, style="joint", caption=(
        f"Extended extreme position: AC2 = AB + BC = {AB + BC:g}", f"拉直共线位置:AC2 = AB + BC = {AB + BC:g}"))
    if drawing:
        sc.add("AC2s", segment, A, C2, style="construction")
    r1 = sc.add("rC1", ray_from, A, C2, th, caption=("Through A a line at θ to AC2", "过 A 作与 AC2 成 θ 角的直线"))
    C1 = sc.add("C1", _on_ray, r1, BC - AB, style="joint", label="C1", caption=(
        f"Folded extreme position on it: AC1 = BC − AB = {BC - AB:g}", f"在其上取折叠共线位置 AC1 = BC − AB = {BC - AB:g}"))
    if drawing:
        sc.add("AC1s", segment, A, C1, style="construction")
        sc.add("chord", segment, C1, C2, style="construction", caption=("Join C1C2", "连接 C1C2"))
    m = sc.add("bis", perpendicular_bisector, C1, C2, caption=("The perpendicular bisector of C1C2: DC1 = DC2",
                                                              "作 C1C2 的中垂线(DC1 = DC2)"))
    if drawing:
        mid = sc.add("Mchord", _mid, C1, C2, visible=False)
        sc.add("bis_mark", marks.right_angle, mid, C2, sc.add("Mup", _up, C1, C2, visible=False), role=Role.ANNOTATION)
    half = sc.add("psi_half", _half, psi, visible=False, unit="deg")
    a_side = sc.add("a_side", _side_of, C1, C2, A, visible=False)
    cands = []
    for i, (s, en, zh) in enumerate(SIDES, 1):
        turn = sc.add(f"turnD_{i}", _signed_complement, half, a_side, s, visible=False, unit="deg")
        r = sc.add(f"rD_{i}", ray_from, C1, C2, turn, caption=(f"From C1 a line at 90° − ψ/2 to C1C2, {en}",
                                                               f"过 C1 作与 C1C2 成 90° − ψ/2 的直线({zh})"))
        cands.append(sc.add(f"D_{i}", meet_lines, r, m, style="candidate", label=f"D{i}", caption=(
            f"It meets the bisector at D{i}: ∠C1D{i}C2 = ψ", f"交中垂线于 D{i},∠C1D{i}C2 = ψ")))
    sols, flat = [], []
    for i, D in enumerate(cands, 1):
        opt = dict(optional=True, visible=False)
        sc.add(f"CD_{i}", length, D, C1, unit="mm", **opt)
        sc.add(f"AD_{i}", length, A, D, unit="mm", **opt)
        sc.add(f"psi_{i}", angle_deg, D, C1, C2, unit="deg", **opt)
        sc.add(f"A_near_{i}", near_flag, A, C1, C2, D, **opt)
        sc.add(f"valid_{i}", is_valid, A, C1, C2, D, Ref(f"CD_{i}"), **opt)
        sc.add(f"gamma_min_{i}", gamma_min_of, A, D, C1, C2, unit="deg", **opt)
        sols.append({"AB": "AB_given", "BC": "BC_given", "AD": f"AD_{i}", "CD": f"CD_{i}", "psi": f"psi_{i}",
                     "gamma_min": f"gamma_min_{i}", "theta": "theta", "K": "K", "C1_folded": "one",
                     "A_near": f"A_near_{i}", "_valid": f"valid_{i}"})
        flat += [Ref(f"valid_{i}"), 1.0, Ref(f"A_near_{i}"), Ref(f"AD_{i}")]
    sc.add("one", float, 1.0, visible=False)
    idx = sc.add("choice", best_index, *flat, visible=False)
    names = ("AD", "CD", "psi", "gamma_min", "A_near")
    for name in names:
        sc.add(f"chosen_{name}", pick, idx, *(Ref(s[name]) for s in sols), visible=False)
    words = sc.add("choice_words", flat_caption, "D", idx, tuple(sc.label_of(c) for c in cands), *flat,
                   visible=False) if sc.drawing else None
    _draw_choice(sc, idx, A, C1, C2, cands, th, AB, words)
    # the design is chosen at D's step and its frame drawn after it (001-17b showed AD, CD, γmin with the last
    # candidate D2, issue 11)
    sc.read_off("D", "chosen_CD", "chosen_gamma_min", "chosen_A_near")
    sc.read_off("AD_link", "chosen_AD")
    answers = {name: f"chosen_{name}" for name in names}
    answers.update(AB="AB_given", BC="BC_given", theta="theta", K="K", C1_folded="one")
    points = {"A": "A", "D": "D", "C1": "C1", "C2": "C2", "B1": "B1", "B2": "B2"}
    return Construction(sc, answers, points, solutions=tuple(sols), no_solution=(
        f"no valid crank-rocker: neither apex D on the bisector of C1C2 (ψ = {psi:g}°) gives AB = {AB:g} a crank "
        "with C1, C2 on one side of AD"))


def _on_ray(r, d: float) -> Point:
    """The point at distance ``d`` along ray ``r``."""
    return r.at(d)


def _mid(a: Point, b: Point) -> Point:
    return (a + b) * 0.5


def _up(a: Point, b: Point) -> Point:
    return (a + b) * 0.5 + (b - a).perp()


def _side_of(c1: Point, c2: Point, p: Point) -> int:
    """+1 when ``p`` lies left of c1→c2, else −1."""
    return 1 if (c2 - c1).cross(p - c1) > 0 else -1


def _signed_complement(half_psi: float, a_side: int, s: int) -> float:
    """The turn 90° − ψ/2 from C1→C2 towards A's side (s = +1) or away from it (s = −1)."""
    return complement_turn(half_psi, a_side * s)


def _draw_choice(sc: Scene, idx: Ref, A: Ref, C1: Ref, C2: Ref, cands: list, th: Ref, AB: float,
                 caption: Ref | None = None) -> None:
    """The chosen design drawn in both extreme positions: D, B1, B2 and the rocker CD; ``caption`` names the
    candidate chosen (a drawing's; a lean scene's step keeps a fixed one)."""
    D = sc.add("D", pick, idx, *cands, role=Role.RESULT, style="pivot", label="D",
               caption=caption or ("The textbook's choice of D (the other valid point is a candidate)",
                                   "取 D(另一可行点为备选解)"))
    drawing = sc.drawing                     # the ground symbol, links and marks only a drawing needs
    if drawing:
        sc.add("D_ground", marks.ground, D, -math.pi / 2, role=Role.ANNOTATION, style="ground", optional=True)
        sc.add("AD_link", segment, A, D, style="frame", optional=True, caption=("The frame AD", "机架 AD"))
    B1 = sc.add("B1", point_along, A, C1, -AB, role=Role.RESULT, style="joint", label="B1", optional=True,
                caption=("B1 beyond A on the folded line, B2 on the extended line (AB as given)", "在两共线位置上取 B1、B2"))
    B2 = sc.add("B2", point_along, A, C2, AB, role=Role.RESULT, style="joint", label="B2", optional=True)
    if not drawing:
        return
    for i, (B, C) in enumerate(((B1, C1), (B2, C2)), 1):
        style = "link" if i == 1 else "link-alt"
        add_bar(sc, f"AB{i}", A, B, (f"Draw the designed linkage in extreme position {i}", f"画出所设计机构的极限位置 {i}"),
                style=style)
        add_bar(sc, f"B{i}C{i}", B, C, style=style)
        add_bar(sc, f"C{i}D_design", C, D, style=style)
    sc.add("mark_theta", marks.angle_mark, A, C1, C2, "θ", th, role=Role.ANNOTATION, style="angle", optional=True)
    sc.add("mark_psi", marks.angle_mark, D, C1, C2, "ψ", Ref("chosen_psi"), role=Role.ANNOTATION, style="angle",
           optional=True)


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """Closed form: C1C2 by the law of cosines, CD = C1C2/(2 sin ψ/2), D at h = C1C2/(2 tan ψ/2) from the
    chord's midpoint M; A's foot on the chord lies (AC2² − AC1²)/(2·C1C2) from M and A is 2·area/C1C2 from the
    chord, so AD = √(s² + (d ∓ h)²). Valid designs only, by the rule shared with the construction
    (:func:`geomcon.analytic.design_by_k.rocker_design_valid`: Grashof crank, C1 and C2 on one side of AD)."""
    K, a, b, psi = g["K"], g["AB"], g["BC"], g["psi"]
    th = theta_from_k(K)
    u, v = b - a, b + a
    # C1C2² = (v − u)² + 2uv(1 − cos θ) = 4a² + 4uv·sin²(θ/2): no cancellation for small θ
    chord = math.sqrt(4 * a * a + 4 * u * v * math.sin(math.radians(th) / 2) ** 2)
    half = math.radians(psi) / 2
    cd, h = chord / (2 * math.sin(half)), chord / (2 * math.tan(half))
    s = (v - u) * (v + u) / (2 * chord)
    d = u * v * math.sin(math.radians(th)) / chord
    # chord on the x axis, M at the origin, C1 = (−c/2, 0), C2 = (c/2, 0), A = (−s, d), D = (0, ±h)
    c1, c2, A = (-chord / 2, 0.0), (chord / 2, 0.0), (-s, d)
    out = []
    for near, Dy in ((True, h), (False, -h)):
        ux, uy = 0.0 - A[0], Dy - A[1]
        ad = math.hypot(ux, uy)
        h1 = (ux * (c1[1] - A[1]) - uy * (c1[0] - A[0])) / ad
        h2 = (ux * (c2[1] - A[1]) - uy * (c2[0] - A[0])) / ad
        if not rocker_design_valid(a, b, cd, ad, h1, h2):
            continue
        gmin = crank_rocker_gamma_from_positions(A, (0.0, Dy), c1, c2)    # γmin from the points, not the lengths
        psi_d = angle_deg_at((0.0, Dy), c1, c2)                          # ψ of the points as well
        out.append({"AB": a, "BC": b, "AD": ad, "CD": cd, "psi": psi_d, "gamma_min": gmin,
                    "theta": th, "K": K, "C1_folded": True, "A_near": near})
    return out
