"""``crank_rocker.best_by_K``: the crank-rocker with time ratio K, rocker swing ψ and frame AD whose smallest
transmission angle is the largest (seed 004's parametric approach, for the crank-rocker).

Construction: the shape of a design does not depend on its size, so it is drawn with a rocker of the
frame's length (D at the origin, C1 and C2 symmetric about the vertical through D at ψ apart); every A on
the admissible arcs of the two θ-circles (a crank by Grashof, C1 and C2 on one side of AD) gives a design of
that shape; γmin is read from the points (:func:`geomcon.recipes.common.gamma_min_of`), A* maximises it along
the arcs (golden-section search, then the place where its central difference changes sign), and the design
is scaled by AD/|A*D| so that the frame is the given one.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.crank_rocker_best import crank_rocker_best
from ..errors import NotAMechanism
from ..numeric import stationary
from ..geometry import Point, segment
from ..scene import Ref, Role, Scene, marks
from .base import Construction, Quantity, Recipe
from .common import gamma_min_of, half_difference, half_sum, length, near_flag
from .crank_rocker_crank_frame import add_frame_rocker, add_unit_linkage
from .crank_rocker_design import admissible_arcs, swing_mark, theta_mark
from .search import maximise
from .theta_circle import K_MAX_OBTUSE, add_theta_circle, add_theta_step, refuse_tiny_theta

GIVENS = (
    Quantity("K", "", "time-ratio coefficient, 1.00064 ≤ K ≤ 6282", minimum=1.0, maximum=K_MAX_OBTUSE),
    Quantity("psi", "deg", "rocker swing ∠C1DC2"),
    Quantity("AD", "mm", "frame"),
)
ANSWERS = (
    Quantity("AB", "mm", "crank"),
    Quantity("BC", "mm", "coupler"),
    Quantity("CD", "mm", "rocker"),
    Quantity("gamma_min", "deg", "smallest transmission angle, maximised"),
    Quantity("theta", "deg", "180°(K − 1)/(K + 1)"),
    Quantity("K", "", "time-ratio coefficient (as given)"),
)


def _validate(g: Mapping[str, Any]) -> list[str]:
    refuse_tiny_theta(g["K"])
    if g["K"] == 1.0:
        raise NotAMechanism("K = 1 has no θ-circle (A on the line C1C2): give K > 1")
    if not 0.0 < g["psi"] < 180.0:
        raise NotAMechanism(f"psi = {g['psi']:g}° must lie in (0°, 180°)")
    return []


def best_on_arcs(D: Point, C1: Point, C2: Point, *arcs_per_side: Any) -> Point:
    """A* on the admissible arcs where γmin is largest (None when no arc is admissible)."""
    best = None
    for arcs in arcs_per_side:
        for arc in arcs:
            def f(t: float, arc=arc) -> float:
                return gamma_min_of(arc.at(t), D, C1, C2)
            t = maximise(f, 0.0, 1.0, width=1e-15)
            w = min(t, 1.0 - t) / 1.1                 # the arc's ends bound the refining bracket
            t = stationary(f, t, [r for r in (1e-2, 1e-3, 1e-4) if r <= w])
            value = f(t)
            if best is None or value > best[0]:
                best = (value, arc.at(t))
    if best is None:
        raise NotAMechanism("no point of the θ-circles gives a crank-rocker with this K and ψ")
    return best[1]


def best_words(A: Point, D: Point, C1: Point, C2: Point) -> tuple[str, str]:
    """The caption of A*: the arc it lies on (D's side of C1C2 or the far side) and the γmin it gives.

    >>> best_words(Point(0, 1), Point(0, 5), Point(-1, 0), Point(1, 0))[0].startswith("A* on the admissible arc on D's side")
    True
    """
    near = near_flag(A, C1, C2, D)
    side = ("on D's side", "D 所在一侧") if near else ("on the far side", "远离 D 的一侧")
    g = gamma_min_of(A, D, C1, C2)
    return (f"A* on the admissible arc {side[0]} of C1C2 where γmin is largest, {g:.2f}° (searched along the arcs; "
            f"* marks the best pivot)", f"在可行弧段上搜索使 γmin 最大的 A*（{side[1]}，γmin = {g:.2f}°；* 标记最佳的固定铰链）")


def _ratio(AD: float, A: Point, D: Point) -> float:
    return AD / math.hypot(A.x - D.x, A.y - D.y)


def _times(x: float, k: float) -> float:
    return x * k


def construct(g: Mapping[str, Any]) -> Construction:
    """The unit-size θ-circles, A* of the largest γmin on their admissible arcs, the design scaled to AD."""
    K, psi, AD = g["K"], g["psi"], g["AD"]
    sc = Scene("Crank-rocker by K with the largest γmin")
    th = add_theta_step(sc, K)
    D, C1, C2 = add_frame_rocker(sc, AD, psi)
    if sc.drawing:
        sc.add("chord", segment, C1, C2, style="construction", caption=("Join C1C2", "连接 C1C2"))
    arcs = []
    for s, pre, en, zh, lab in ((-1, "n", "on D's side", "D 所在一侧", "P"), (1, "f", "on the far side", "远离 D 的一侧", "P′")):
        kT = add_theta_circle(sc, C1, C2, th, s, side_words=(en, zh), prefix=pre, label=lab)
        arcs.append(sc.add(f"{pre}arcs", admissible_arcs, kT, C1, C2, D, AD, None, style="admissible",
                           caption=(f"Admissible arcs {en}: a crank, C1 and C2 on one side of AD",
                                    f"A 的可行弧段({zh})")))
    words = ("A* on the admissible arcs where γmin is largest (searched along the arcs; * marks the best pivot)",
             "在可行弧段上搜索使 γmin 最大的 A*(* 标记最佳的固定铰链)")
    A = sc.add("A", best_on_arcs, D, C1, C2, *arcs, role=Role.RESULT, style="pivot", label="A*",
               caption=Ref("A_words") if sc.drawing else words)
    if sc.drawing:                           # which arc A* lies on and its γmin: computed once A* is found
        sc.add("A_words", best_words, A, D, C1, C2, visible=False)
    if sc.drawing:
        sc.add("A_ground", marks.ground, A, -math.pi / 2, role=Role.ANNOTATION, style="ground")
    lam = sc.add("scale", _ratio, AD, A, D, role=Role.MEASUREMENT,
                 caption=(f"The frame is AD = {AD:g}: scale the design by the ratio AD/A*D",   # the value is the ratio's
                          f"使机架长为 {AD:g}:按比例 AD/A*D 缩放"))
    for name, op, args, words in (("AB", half_difference, (A, C1, C2), ("AB = (A*C_extended − A*C_folded)/2, scaled", "AB,按比例")),
                                  ("BC", half_sum, (A, C1, C2), ("BC = (A*C1 + A*C2)/2, scaled", "BC,按比例"))):
        raw = sc.add(f"{name}_unit", op, *args, visible=False, unit="mm")
        sc.add(name, _times, raw, lam, role=Role.MEASUREMENT, unit="mm", caption=words)
    sc.add("CD", _times, AD, lam, role=Role.MEASUREMENT, unit="mm", caption=("CD = AD·scale", "CD = AD × 比例"))
    sc.add("gamma_min", gamma_min_of, A, D, C1, C2, role=Role.MEASUREMENT, unit="deg",
           caption=("γmin of the design (the shape's own: scaling keeps angles)", "所设计机构的最小传动角 γmin"))
    if sc.drawing:
        for k, (P, nm) in enumerate(((C1, "C1"), (C2, "C2"))):
            sc.add(f"A{nm}", segment, A, P, style="construction", caption=(
                ("Join A* to C1, C2", "连接 A* 与 C1、C2") if k == 0 else ("", "")))
    add_unit_linkage(sc, A, D, C1, C2)
    if sc.drawing:                           # θ at A*, ψ at D, as every design-by-K figure marks them (004-03 had none)
        sc.add("mark_theta", theta_mark, A, C1, C2, th, role=Role.ANNOTATION, style="angle")
        sc.add("mark_psi", swing_mark, D, C1, C2, role=Role.ANNOTATION, style="angle")
    sc.add("AD_unit", length, A, D, visible=False, unit="mm")
    answers = {q.name: q.name for q in ANSWERS}
    return Construction(sc, answers, {"A": "A", "D": "D", "C1": "C1", "C2": "C2"})


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """The twin: the family in the rocker's length CD with the frame fixed, searched
    (:func:`geomcon.analytic.crank_rocker_best.crank_rocker_best`)."""
    r = crank_rocker_best(g["K"], g["psi"], g["AD"])
    return [{k: r[k] for k in ("AB", "BC", "CD", "gamma_min", "theta", "K")}]


def back_check(g: Mapping[str, Any], ans: Mapping[str, float]) -> list[tuple[str, float, float, str]]:
    """Rebuild with ``crank_rocker.extremes``: K, ψ and γmin must come back."""
    from .common import rebuilt_values
    v = rebuilt_values("crank_rocker.extremes", {"AB": ans["AB"], "BC": ans["BC"], "CD": ans["CD"], "AD": g["AD"]},
                       ("K", "psi", "gamma_min"))
    return [("K", v["K"], g["K"], ""), ("psi", v["psi"], g["psi"], "deg"),
            ("gamma_min", v["gamma_min"], ans["gamma_min"], "deg")]


RECIPE = Recipe(
    name="crank_rocker.best_by_K",
    title="Crank-rocker from K, ψ and the frame AD with the largest smallest transmission angle",
    givens=GIVENS,
    answers=ANSWERS,
    points=("A", "D", "C1", "C2"),
    construct=construct,
    analytic=analytic,
    validate=_validate,
    back_check=back_check,
)
