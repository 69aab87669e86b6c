"""``crank_slider.best_by_K``: the offset crank-slider with time ratio K and stroke H whose working stroke has
the largest smallest transmission angle (the parametric design of seed 004).

Every A on the admissible arc QC1 of the θ-circle gives a crank-slider with K and H; the working stroke is
the slow one, C1 → C2, so the crank must turn counter-clockwise (A above the guide, slider to the right) and
the cycle's smallest transmission angle (crank perpendicular to the guide, away from it) then falls in the
return stroke. In the working stroke the smallest transmission angle is the smaller of the one at the
folded position C1 and the one with the crank perpendicular to the guide, towards it. A* maximises it; it is
found by a golden-section search along the arc (0 ≤ t ≤ 1 from Q to C1), limited to ``e_min ≤ e ≤ e_max``.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.design_by_k import crank_slider_best
from ..analytic.linkages import theta_from_k
from ..errors import NotAMechanism
from ..geometry import Line, OtherThan, Point, line_circle, perpendicular, polar_angle
from ..scene import Role, Scene
from .search import crossing, maximise
from .base import Construction, Quantity, Recipe
from .common import rebuilt_values
from .crank_slider_design import admissible_arc, finish_from_A
from .theta_circle import (K_MAX_ACUTE, add_theta_step, add_theta_circle, arc_from_to,
                           refuse_tiny_theta)

GIVENS = (
    Quantity("K", "", "time-ratio coefficient, 1.00064 ≤ K ≤ 2.99745 (θ ≤ 89.94°: the admissible arc QC1 is "
             "H·cot θ high and vanishes at θ = 90°)", minimum=1.0, maximum=K_MAX_ACUTE),
    Quantity("H", "mm", "stroke of the slider"),
    Quantity("e_min", "mm", "smallest admissible offset", required=False, default=0.0, minimum=0.0, inclusive=True),
    Quantity("e_max", "mm", "largest admissible offset", required=False),
)
ANSWERS = (
    Quantity("AB", "mm", "crank"),
    Quantity("BC", "mm", "connecting rod"),
    Quantity("e", "mm", "offset"),
    Quantity("gamma_w_min", "deg", "smallest transmission angle of the working (slow) stroke, maximised"),
    Quantity("gamma_min", "deg", "smallest transmission angle of the cycle (in the return stroke)"),
    Quantity("alpha_max", "deg", "largest pressure angle of the cycle"),
    Quantity("theta", "deg", "180°(K − 1)/(K + 1)"),
    Quantity("K", "", "time-ratio coefficient (as given)"),
)


def _validate(g: Mapping[str, Any]) -> list[str]:
    refuse_tiny_theta(g["K"])
    th = theta_from_k(g["K"])
    if th >= 90.0:
        raise NotAMechanism(f"K = {g['K']:g} gives θ = {th:g}° ≥ 90°: no offset crank-slider reaches it")
    e_hi = g["H"] / math.tan(math.radians(th))
    e_max = g.get("e_max")
    if e_max is not None and e_max < g.get("e_min", 0.0):
        raise NotAMechanism(f"e_max = {e_max:g} is below e_min = {g['e_min']:g}")
    if g.get("e_min", 0.0) >= e_hi:
        raise NotAMechanism(f"e_min = {g['e_min']:g} leaves no admissible offset: e < H·cot θ = {e_hi:.6g}")
    return []


def working_gamma(A: Point, C1: Point, C2: Point) -> float:
    """γ_w,min (deg) for pivot A: the smaller transmission angle at the folded position and with the crank
    perpendicular to the guide, towards it (the guide through C1 and C2 horizontal). At the folded position
    tan γ = FC1/e (F the foot of A); with the crank towards the guide cos γ = |a − e|/b, and b − |a − e| is
    AC1 + e or AC2 − e, formed as such (no cancellation when the rod is nearly along the crank)."""
    return _working_gamma_xy(A.x, A.y, C1.x, C1.y, C2.x, C2.y)


def _working_gamma_xy(ax: float, ay: float, c1x: float, c1y: float, c2x: float, c2y: float) -> float:
    """:func:`working_gamma` on floats (abs(A − C1) is hypot(A.x − C1.x, A.y − C1.y)): the same bits."""
    u, v = math.hypot(ax - c1x, ay - c1y), math.hypot(ax - c2x, ay - c2y)
    a, b, e = (v - u) / 2, (v + u) / 2, abs(ay - c1y)
    g_fold = math.atan2(abs(ax - c1x), e)
    d = abs(a - e)
    gap = u + e if a >= e else v - e
    g_near = math.atan2(math.sqrt(max(0.0, gap * (b + d))), d)
    return math.degrees(min(g_fold, g_near))


def best_on_arc(k, Q: Point, C1: Point, C2: Point, e_min: float, e_max: float | None) -> Point:
    """A* on the arc QC1: golden-section search of :func:`working_gamma` within the offset band.

    Points are placed back from C1 along the arc (:func:`arc_point_from_end`, parameter s = 0 at C1 and 1 at
    Q): near θ = 90° A lies within 1e-6 of the stroke from C1, where points formed from the circle's centre
    would carry the centre's rounding (ε·H) into FC1 and misplace the kink of γ_w,min. The search runs to
    the resolution of s itself (relative, not 4e-16 of the arc)."""
    arc = arc_from_to(k, Q, C1)
    # arc_point_from_end(arc, C1, s) and working_gamma on floats (the same operations: the same bits); the
    # polar angle of C1 seen from the centre is the same for every s
    c1x, c1y, c2x, c2y = C1.x, C1.y, C2.x, C2.y
    sweep, r2, a0 = arc.sweep, 2.0 * arc.r, polar_angle(arc.center, C1)

    def xy(s: float) -> tuple[float, float]:
        half = s * sweep / 2.0
        phi = a0 - half
        chord = r2 * math.sin(half)
        return c1x + chord * math.sin(phi), c1y - chord * math.cos(phi)

    def at(s: float) -> Point:
        return Point(*xy(s))

    def e_at(s: float) -> float:
        return abs(xy(s)[1] - c1y)

    def gamma(s: float) -> float:
        x, y = xy(s)
        return _working_gamma_xy(x, y, c1x, c1y, c2x, c2y)

    # e rises from C1 (s = 0) to Q (s = 1): the band e_min ≤ e ≤ e_max is an interval of s
    s1 = crossing(lambda s: e_at(s) <= e_max, 0.0, 1.0) if e_max is not None and e_max < e_at(1.0) else 1.0
    s0 = crossing(lambda s: e_at(s) < e_min, 0.0, 1.0) if e_min > 0 else 0.0
    return at(maximise(gamma, s0, s1, width=0.0, iterations=400))


def construct(g: Mapping[str, Any]) -> Construction:
    """θ-circle, admissible arc, A* by search along the arc, then the design's measuring steps."""
    K, H = g["K"], g["H"]
    sc = Scene("Offset crank-slider: best working-stroke transmission angle for K")
    C1 = sc.given("C1", Point(0.0, 0.0), style="joint", caption=("C1, one end of the stroke", "取行程端点 C1"))
    C2 = sc.given_at("C2", H, 0.0, style="joint", caption=(f"C2 with C1C2 = H = {H:g}", f"截取 C1C2 = H = {H:g} 得 C2"))
    gl = sc.add("guide", Line, C1, Point(1.0, 0.0), role=Role.GIVEN, style="given",
                caption=("The slider's guide through C1 and C2", "过 C1、C2 作导路"))
    th = add_theta_step(sc, K)
    kT = add_theta_circle(sc, C1, C2, th, +1, side_words=("above the guide", "在导路上方"))
    n1 = sc.add("n1", perpendicular, gl, C1, caption=("Perpendicular to the guide at C1", "过 C1 作导路的垂线"))
    Q = sc.add("Q", line_circle, n1, kT, branch=OtherThan(C1), style="point", label="Q",
               caption=("It meets the θ-circle again at Q", "交 θ 圆于 Q"))
    if sc.drawing:                           # the admissible arc only a drawing needs
        sc.add("arc_ok", admissible_arc, kT, Q, C1, C2, None, role=Role.ANNOTATION, style="admissible",
               caption=("Admissible arc QC1: every A on it gives K and H", "A 的可行弧 QC1:其上任一点均满足 K、H"))
    A = sc.add("A", best_on_arc, kT, Q, C1, C2, g.get("e_min") or 0.0, g.get("e_max"), role=Role.RESULT,
               style="pivot", label="A*",
               caption=("A* on QC1 with the largest working-stroke γmin (golden-section search; * marks the best "
                        "pivot; the crank turns counter-clockwise so that C1 → C2 is the slow working stroke)",
                        "在弧 QC1 上求工作行程最小传动角最大的点 A*(* 标记最佳的固定铰链;曲柄逆时针转,C1→C2 为慢速工作行程)"))
    finish_from_A(sc, A, C1, C2, gl, th, H)
    names = {q.name: q.name for q in ANSWERS}
    names["gamma_w_min"] = "gamma_min_slow"
    return Construction(sc, names, {n: n for n in ("C1", "C2", "A", "B1", "B2")})


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """Bisection on the crank where the two working-stroke angles are equal (independent of the arc)."""
    e_max = g.get("e_max")
    return [crank_slider_best(g["K"], g["H"], e_min=g.get("e_min") or 0.0,
                              e_max=math.inf if e_max is None else e_max)]


def back_check(g: Mapping[str, Any], ans: Mapping[str, float]) -> list[tuple[str, float, float, str]]:
    """Rebuild with ``crank_slider.extremes``: H, K and the slow stroke's γmin come back."""
    v = rebuilt_values("crank_slider.extremes", {"AB": ans["AB"], "BC": ans["BC"], "e": ans["e"]},
                       ("H", "K", "gamma_min_slow"))
    return [("H", v["H"], g["H"], "mm"), ("K", v["K"], g["K"], ""), ("gamma_w_min", v["gamma_min_slow"], ans["gamma_w_min"], "deg")]


RECIPE = Recipe(
    name="crank_slider.best_by_K",
    title="Offset crank-slider for K and H with the best working-stroke transmission angle (seed 004)",
    givens=GIVENS, answers=ANSWERS, points=("C1", "C2", "A", "B1", "B2"),
    construct=construct, analytic=analytic, validate=_validate, back_check=back_check,
)
