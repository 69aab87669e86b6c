"""``crank_rocker.design_by_K``: a crank-rocker with time ratio K, rocker CD and its extreme positions.

Two families of exam problems:

- **positions given** (``psi``, or the directions ``phi1``, ``phi2`` of DC1, DC2 from the horizontal through D):
  the θ-circles through C1, C2 (one on D's side of C1C2, one on the far side) carry every possible A; one
  closing condition picks A on them:
  ``BC`` (F on C1A extended with AF = AC2 sees C1C2 under θ/2 and lies at C1F = 2·BC),
  ``AB`` (E on AC2 with AE = AC1 sees C1C2 under 90° + θ/2 and lies at C2E = 2·AB),
  ``AC1`` (the circle about C1 of that radius), ``frame_line`` (A on the horizontal through D), ``AD`` (the
  circle about D of that radius: the rocker, its swing and the frame given).
  K = 1 puts A on the line C1C2 itself (with ``AD`` or ``frame_line``).
- **frame given** (``AD`` and the angle ``phi`` = ∠ADC of one extreme position C1): the other extreme
  position lies on the rocker circle where a line through A at ±θ to AC1 meets it (K = 1: the line AC1's
  second meeting with the rocker circle — C1 itself would be a crank of length 0).
- **links** (no ``CD``; ``AB``, ``BC`` and ``psi`` given): the triangle AC1C2 from AC1 = BC − AB,
  AC2 = AB + BC and θ, then D on the bisector of C1C2 seeing it under ψ (:mod:`.crank_rocker_links`).

Every candidate is built; the valid ones (AB a crank by Grashof, C1 and C2 on one side of AD, so that they
really are the designed linkage's extreme positions) are the ``solutions``; the textbook's choice is the
first by :func:`preference`: C1 the folded position, then A on D's side of C1C2, then the shorter frame.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.design_by_k import rocker_design_rows, rocker_design_valid
from ..analytic.linkages import theta_from_k
from ..errors import NotAMechanism
from ..geometry import (FarthestFrom, LeftOf, Leftmost, Line, NearestTo, OtherThan, Point, RightOf, Rightmost, Segment,
                        circle, circle_circle, line_circle, line_line, line_through, midpoint, point_along, segment)
from ..scene import Ref, Role, Scene, marks
from ..scene.tape import lifted
from ..tolerance import tol
from . import crank_rocker_links
from .base import Construction, Quantity, Recipe
from .choice_words import flat_caption
from .common import (add_bar, angle_deg, best_index, folded_flag, gamma_min_of, half_difference, half_sum, is_valid,
                     length, near_flag, one, pick, preference, rebuilt_values, valid_xy)
from .theta_circle import K_MAX_OBTUSE, add_theta_step, ray_line, refuse_tiny_theta, add_seeing_circle, add_theta_circle, ray_from

GIVENS = (
    Quantity("K", "", "time-ratio coefficient, K = 1 or 1.00064 ≤ K ≤ 6282 (180° − θ ≥ 0.057°: the θ-circle's "
             "radius stays within 500 chords)", minimum=1.0, inclusive=True, maximum=K_MAX_OBTUSE),
    Quantity("CD", "mm", "rocker (all forms but the links form)", required=False),
    Quantity("psi", "deg", "rocker swing ∠C1DC2 (positions given)", required=False),
    Quantity("phi1", "deg", "direction of DC1 from the horizontal through D, counter-clockwise", required=False, minimum=None),
    Quantity("phi2", "deg", "direction of DC2 from the horizontal through D, counter-clockwise", required=False, minimum=None),
    Quantity("BC", "mm", "closing condition: coupler", required=False),
    Quantity("AB", "mm", "closing condition: crank", required=False),
    Quantity("AC1", "mm", "closing condition: distance from A to C1", required=False),
    Quantity("frame_line", "bool", "closing condition: A on the horizontal through D", required=False, default=False),
    Quantity("AD", "mm", "frame (K = 1 with positions given, or with phi)", required=False),
    Quantity("phi", "deg", "angle ∠ADC1 between the frame and the given extreme position DC1 (frame given)",
             required=False),
    Quantity("gamma_allow", "deg", "smallest admissible transmission angle", required=False),
    Quantity("H_out", "mm", "stroke of an output slider driven from the rocker by an arm DE along DC whose link "
             "EF is parallel in both extreme positions (equal pressure angles there): gives DE", required=False),
)
ANSWERS = (
    Quantity("AB", "mm", "crank"),
    Quantity("BC", "mm", "coupler"),
    Quantity("AD", "mm", "frame"),
    Quantity("CD", "mm", "rocker (as given, or designed in the links form)"),
    Quantity("psi", "deg", "rocker swing of the designed linkage"),
    Quantity("gamma_min", "deg", "smallest transmission angle of the designed linkage"),
    Quantity("theta", "deg", "180°(K − 1)/(K + 1)"),
    Quantity("K", "", "time-ratio coefficient (as given)"),
    Quantity("C1_folded", "bool", "yes when the extreme position C1 is the folded one (AC1 = BC − AB), no when it is "
             "the extended one; at K = 1 "
             "too (A, C1, C2 on one line, the folded position the nearer to A): with the frame given, C2 is the "
             "second meeting of the line AC1 with the rocker circle, never C1 itself"),
    Quantity("A_near", "bool", "yes when A lies on D's side of C1C2, no when on the far side (always yes when the "
             "frame is given)"),
    Quantity("DE", "mm", "arm of the output stage, H_out / (2 sin ψ/2) (only with H_out)"),
)
CLOSINGS = ("BC", "AB", "AC1", "frame_line", "AD")


# ----------------------------------------------------------------------------------------- problem forms
def _form(g: Mapping[str, Any]) -> tuple[str, str]:
    """("positions" | "frame" | "links", closing condition name), or a refusal naming what is missing or extra."""
    has = {k for k in ("psi", "phi1", "phi2", "phi") if g.get(k) is not None}
    closing = [k for k in CLOSINGS if g.get(k) not in (None, False)]
    if g.get("CD") is None:
        if has == {"psi"} and sorted(closing) == ["AB", "AD"]:
            if g["K"] == 1.0:
                raise NotAMechanism("the crank-and-frame form needs K > 1 (K = 1 has no θ-circle)")
            return "crank_frame", "AB+AD"
        if has != {"psi"} or sorted(closing) != ["AB", "BC"]:
            raise NotAMechanism("without CD give AB, BC and psi (the links form: rocker and frame are designed), or "
                                "AB, AD and psi (coupler and rocker are designed); otherwise give CD")
        if g["K"] == 1.0:
            raise NotAMechanism("the links form needs K > 1 (with K = 1 the extreme positions C1, C2 are collinear with A)")
        if g["AB"] >= g["BC"]:
            raise NotAMechanism(f"AB = {g['AB']:g} must be shorter than BC = {g['BC']:g} for a crank-rocker")
        return "links", "AB+BC"
    if "phi" in has:
        if has - {"phi"} or set(closing) - {"AD"} or "AD" not in closing:
            raise NotAMechanism("with phi (frame given) give AD and neither psi, phi1, phi2 nor another closing condition")
        return "frame", "AD"
    if has == {"psi"} or has == {"phi1", "phi2"}:
        wanted = ("AD", "frame_line") if g["K"] == 1.0 else ("BC", "AB", "AC1", "frame_line", "AD")
        if len(closing) != 1 or closing[0] not in wanted:
            raise NotAMechanism(f"give exactly one closing condition of {', '.join(wanted)} (got {', '.join(closing) or 'none'})")
        if closing[0] == "frame_line" and has == {"psi"}:
            raise NotAMechanism("frame_line needs the directions phi1, phi2 of the extreme positions, not only psi")
        return "positions", closing[0]
    raise NotAMechanism("give the rocker's extreme positions (psi, or phi1 and phi2), or the frame (AD and phi)")


def _validate(g: Mapping[str, Any]) -> list[str]:
    if _form(g)[0] != "positions" and g.get("H_out") is not None:
        raise NotAMechanism("H_out (the output arm DE) needs the rocker's extreme positions given (psi or phi1, phi2)")
    theta = theta_from_k(g["K"])
    refuse_tiny_theta(g["K"])
    if g["K"] > K_MAX_OBTUSE:
        raise NotAMechanism(f"K = {g['K']:g} gives θ = {theta:g}°: 180° − θ must be at least 0.057° (K ≤ {K_MAX_OBTUSE:g})")
    if g.get("psi") is not None and not 0.0 < g["psi"] < 180.0:
        raise NotAMechanism(f"psi = {g['psi']:g}° must lie in (0°, 180°)")
    if g.get("phi1") is not None and math.isclose(g["phi1"] % 360, g["phi2"] % 360):
        raise NotAMechanism(f"phi1 = phi2 = {g['phi1']:g}°: the rocker does not swing")
    return []


def extreme_positions(g: Mapping[str, Any]) -> tuple[Point, Point]:
    """C1, C2 of the positions family, D at the origin (C1 on the left when only ψ is given)."""
    CD = g["CD"]
    if g.get("psi") is not None:
        a1, a2 = 90.0 + g["psi"] / 2, 90.0 - g["psi"] / 2
    else:
        a1, a2 = g["phi1"], g["phi2"]
    return lifted(_rocker_end, CD, a1), lifted(_rocker_end, CD, a2)


def _rocker_end(CD: float, a: float) -> Point:
    """C at ``a`` degrees about D at the origin: CD·(cos a, sin a)."""
    return Point(CD * math.cos(math.radians(a)), CD * math.sin(math.radians(a)))


def _near_side(c1: Point, c2: Point) -> int:
    """+1 when D (the origin) lies to the left of C1→C2, else −1."""
    return 1 if (c2 - c1).cross(Point(0, 0) - c1) > 0 else -1


def _frame_c1(AD: float, CD: float, phi: float) -> Point:
    """C1 of the frame form: D at (AD, 0), ∠ADC1 = φ (not 180° − φ: keeps a tiny φ)."""
    return Point(AD - CD * math.cos(math.radians(phi)), CD * math.sin(math.radians(phi)))


# ----------------------------------------------------------------------------------------- step operations
def admissible_arcs(k, C1: Point, C2: Point, D: Point, CD: float, gamma_allow: float | None):
    """The arcs of a θ-circle where A gives a valid design (:func:`is_valid`, and γmin ≥ ``gamma_allow`` when
    given): the circle is sampled at 720 points and each boundary refined by bisection to 1e-12 of a turn."""
    from ..geometry import Arc

    cx, cy, r = k.center.x, k.center.y, k.r
    cos, sin = math.cos, math.sin

    def ok(t: float) -> bool:
        ax, ay = cx + r * cos(t), cy + r * sin(t)          # k.at(t), the same floats
        if not valid_xy(ax, ay, C1, C2, D, CD):
            return False
        if gamma_allow is None:
            return True
        return gamma_min_of(Point(ax, ay), D, C1, C2) >= gamma_allow

    n = 720
    ts = [2 * math.pi * i / n for i in range(n)]
    flags = [ok(t) for t in ts]
    if all(flags):
        return (Arc(k.center, k.r, 0.0, 2 * math.pi),)
    start = flags.index(False)
    arcs, t0 = [], None
    for j in range(1, n + 1):
        i = (start + j) % n
        prev = (start + j - 1) % n
        if flags[i] != flags[prev]:
            a, b = ts[prev], ts[prev] + 2 * math.pi / n
            for _ in range(45):
                m = (a + b) / 2
                a, b = (m, b) if ok(m) == flags[prev] else (a, m)
            edge = (a + b) / 2
            if flags[i]:
                t0 = edge
            elif t0 is not None:
                arcs.append(Arc(k.center, k.r, t0, (edge - t0) % (2 * math.pi)))
                t0 = None
    return tuple(arcs)


def nearer(A: Point, P: Point, Q: Point) -> Point:
    """The extreme position nearer to A (the folded one)."""
    return P if math.hypot(P.x - A.x, P.y - A.y) < math.hypot(Q.x - A.x, Q.y - A.y) else Q    # |P − A| < |Q − A|


def farther(A: Point, P: Point, Q: Point) -> Point:
    """The extreme position farther from A (the extended one)."""
    return Q if math.hypot(P.x - A.x, P.y - A.y) < math.hypot(Q.x - A.x, Q.y - A.y) else P


def _plus(theta: float, k: float, c: float) -> float:
    return k * theta + c


def _times(x: float, k: float) -> float:
    return k * x


# ----------------------------------------------------------------------------------------- construction
def construct(g: Mapping[str, Any]) -> Construction:
    """Build every candidate of the design and the drawing of the textbook's choice."""
    family, closing = _form(g)
    if family == "links":
        return crank_rocker_links.construct(g)
    if family == "crank_frame":
        from . import crank_rocker_crank_frame
        return crank_rocker_crank_frame.construct(g)
    K, CD = g["K"], g["CD"]
    sc = Scene("Crank-rocker designed by K")
    th = add_theta_step(sc, K)
    sc.add("CD", float, CD, visible=False)
    if family == "positions":
        cands = _positions_candidates(sc, g, closing, th)
    else:
        cands = _frame_candidates(sc, g, th)
    D = Ref("D")
    sols, flat = [], []
    for i, (A, P1, P2, near, *arc) in enumerate(cands, 1):
        opt = dict(optional=True, visible=False)
        sc.add(f"AB_{i}", half_difference, A, P1, P2, unit="mm", **opt)
        sc.add(f"BC_{i}", half_sum, A, P1, P2, unit="mm", **opt)
        sc.add(f"AD_{i}", length, A, D, unit="mm", **opt)
        sc.add(f"psi_{i}", angle_deg, D, P1, P2, unit="deg", **opt)
        sc.add(f"C1_folded_{i}", folded_flag, A, P1, P2, **opt)
        sc.add(f"A_near_{i}", near, A, P1, P2, D, **opt)
        sc.add(f"valid_{i}", is_valid, A, P1, P2, D, CD, arc[0] if arc else 0, **opt)
        sc.add(f"gamma_min_{i}", gamma_min_of, A, D, P1, P2, unit="deg", **opt)
        sols.append({"AB": f"AB_{i}", "BC": f"BC_{i}", "AD": f"AD_{i}", "CD": "CD", "psi": f"psi_{i}",
                     "gamma_min": f"gamma_min_{i}", "theta": "theta", "K": "K", "C1_folded": f"C1_folded_{i}",
                     "A_near": f"A_near_{i}", "_valid": f"valid_{i}"})
        flat += [Ref(f"valid_{i}"), Ref(f"C1_folded_{i}"), Ref(f"A_near_{i}"), Ref(f"AD_{i}")]
    idx = sc.add("choice", best_index, *flat, visible=False)
    # the caption names the candidate chosen and why: A = A1 (positions given) or, the frame given (001-15,
    # 001-22: A is fixed, the θ-lines meet the rocker circle at C2,1 … C2,4), C2 = C2,k
    labels = (tuple(sc.label_of(c[0]) for c in cands) if family == "positions"
              else tuple(f"C2,{i}" for i in range(1, len(cands) + 1)))
    words = sc.add("choice_words", flat_caption, "A" if family == "positions" else "C2", idx, labels, *flat,
                   visible=False) if sc.drawing else None
    _draw_choice(sc, idx, cands, th, words, frame_given=family == "frame")
    if sc.drawing and family == "positions":
        _mark_given_angles(sc, g)
    elif sc.drawing:                         # the frame given (001-15, 001-22): ψ is an answer, marked at D too
        sc.add("mark_psi", swing_mark, D, Ref("Cf"), Ref("Ce"), role=Role.ANNOTATION, style="angle", optional=True)
    if sc.drawing:                           # the other valid designs, light, with the last step
        sc.add("other_designs", other_designs, idx, D, *(x for i, c in enumerate(cands, 1)
                                                        for x in (Ref(f"valid_{i}"), c[0], c[1], c[2])), style="ghost")
    answers = {name: f"chosen_{name}" for name in ("AB", "BC", "AD", "psi", "gamma_min", "C1_folded", "A_near")}
    answers.update(CD="CD", theta="theta", K="K")
    if g.get("H_out") is not None:
        answers["DE"] = _add_output_arm(sc, g["H_out"])
        for sol in sols:
            sol["DE"] = answers["DE"]
    for name in ("AB", "BC", "AD", "psi", "gamma_min", "C1_folded", "A_near"):
        sc.add(f"chosen_{name}", pick, idx, *(Ref(s[name]) for s in sols), visible=False)
    # the values come from the candidates, the drawing reads them off later (issue 11: 001-10 showed AB, BC
    # and AD with the last candidate A2, step 23): the design chosen at its step, AB and BC at "AB = NM,
    # BC = AM", a frame not given where it is drawn
    sc.read_off("A", "chosen_gamma_min", "chosen_C1_folded", "chosen_A_near",
                *(("chosen_psi",) if family == "frame" else ()))     # the frame given: ψ is C2's (001-15)
    sc.read_off("Mchoice", "chosen_AB", "chosen_BC")
    if g.get("AD") is None:
        sc.read_off("AD_link", "chosen_AD")
    points = {"D": "D", "A": "A", "C1": "Cf", "C2": "Ce", "B1": "B1", "B2": "B2"}
    return Construction(sc, answers, points, solutions=tuple(sols),
                        no_solution=_no_solution_message(g, closing))


def swing_mark(D: Point, C1: Point | None, C2: Point | None) -> marks.AngleMark | None:
    """The swing ψ = ∠C1DC2 at D (none when the design has no solution)."""
    if C1 is None or C2 is None:
        return None
    return marks.angle_mark(D, C1, C2, "ψ", angle_deg(D, C1, C2))


def direction_mark(D: Point, C: Point | None, symbol: str) -> marks.AngleMark | None:
    """The direction of DC from the horizontal through D (counter-clockwise, as ``phi1``/``phi2`` give it),
    marked when it lies in (0°, 180°): the arc spans the smaller angle.

    >>> direction_mark(Point(0, 0), Point(0, 2), "φ1").text
    'φ1=90.00°'
    """
    if C is None:
        return None
    a = math.degrees(math.atan2(C.y - D.y, C.x - D.x)) % 360.0
    return marks.angle_mark(D, D + Point(1.0, 0.0), C, symbol, a) if 1e-9 < a < 180.0 - 1e-9 else None


def _mark_given_angles(sc: Scene, g: Mapping[str, Any]) -> None:
    """001-13, 001-14, 001-21 give the rocker's swing ψ or the directions of DC1, DC2 from the frame line: the
    figure marks them at D where the design starts (the horizontal through D is drawn when A lies on it)."""
    D, C1, C2 = Ref("D"), Ref("Cf"), Ref("Ce")
    sc.add("mark_psi", swing_mark, D, C1, C2, role=Role.ANNOTATION, style="angle", optional=True)
    if g.get("frame_line") and g.get("phi1") is not None:
        sc.add("mark_phi1", direction_mark, D, C1, "φ1", role=Role.ANNOTATION, style="angle", optional=True)
        sc.add("mark_phi2", direction_mark, D, C2, "φ2", role=Role.ANNOTATION, style="angle", optional=True)


def other_designs(idx: int | None, D: Point, *flat: Any) -> tuple[Segment, ...]:
    """The valid designs other than the drawn one (candidate ``idx``), each in its folded extreme position:
    crank A–B1, coupler B1–C1 and the frame A–D (``flat`` holds valid, A, C1, C2 per candidate; the folded
    position is the one nearer A, AB half the difference of AC)."""
    out: list[Segment] = []
    for i in range(0, len(flat), 4):
        valid, A, P1, P2 = flat[i:i + 4]
        if not valid or i // 4 == idx or A is None or P1 is None or P2 is None:
            continue
        cf, ce = (P1, P2) if abs(P1 - A) <= abs(P2 - A) else (P2, P1)
        ab = (abs(ce - A) - abs(cf - A)) / 2
        b1 = A + (A - cf).unit() * ab if cf != A else A
        out += [Segment(A, b1), Segment(b1, cf), Segment(A, D)]
    return tuple(s for s in out if s.a != s.b)


def _add_output_arm(sc: Scene, H: float) -> str:
    """The output stage: E1, E2 on DC1, DC2 extended with E1E2 = H (similar triangles DC1C2 ~ DE1E2, so
    E1E2 ∥ C1C2 and the link EF, parallel in both extremes, moves the slider by H); returns the DE step."""
    D, C1, C2 = Ref("D"), Ref("Cf"), Ref("Ce")
    DE = sc.add("DE", _scaled, D, C1, C2, H, unit="mm", visible=False, optional=True)
    if not sc.drawing:                       # the arm's ends and links only a drawing needs
        return "DE"
    E1 = sc.add("E1", point_along, D, C1, DE, style="joint", label="E1", optional=True, caption=(
        f"Output arm: E1, E2 on DC1, DC2 with E1E2 ∥ C1C2 and E1E2 = H = {H:g}: DE = H/(2 sin ψ/2)",
        f"输出摇臂:在 DC1、DC2 上取 E1、E2,使 E1E2 ∥ C1C2 且 E1E2 = H = {H:g}"))
    E2 = sc.add("E2", point_along, D, C2, DE, style="joint", label="E2", optional=True)
    sc.add("DE1", segment, D, E1, style="link", optional=True)
    sc.add("DE2", segment, D, E2, style="link-alt", optional=True)
    sc.add("E1E2", segment, E1, E2, style="construction", optional=True)
    return "DE"


def _scaled(D: Point, C1: Point, C2: Point, H: float) -> float:
    """DE with E1E2 = H on the rays DC1, DC2: CD·H/C1C2."""
    return abs(C1 - D) * H / abs(C2 - C1)


def _no_solution_message(g: Mapping[str, Any], closing: str) -> str:
    value = g.get(closing)
    return (f"no valid crank-rocker: no point of the θ-circles meets {closing} = {value} with AB a crank "
            "(Grashof) and C1, C2 on one side of AD")


def _positions_candidates(sc: Scene, g: Mapping[str, Any], closing: str, th: Ref) -> list:
    CD = g["CD"]
    c1, c2 = extreme_positions(g)
    symmetric = g.get("psi") is not None
    D = sc.given("D", Point(0.0, 0.0), style="pivot", caption=("Fixed pivot D of the rocker", "摇杆固定铰链 D"))
    drawing = sc.drawing                     # the rocker's bars and the chord only a drawing needs
    if drawing:
        sc.add("D_ground", marks.ground, D, -math.pi / 2, role=Role.ANNOTATION, style="ground")
    C1 = sc.given("C1", c1, style="joint", caption=(f"Extreme position DC1, CD = {CD:g}", f"作摇杆极限位置 DC1,CD = {CD:g}"))
    C2 = sc.given("C2", c2, style="joint", caption=("Extreme position DC2: the rocker swings through ψ = ∠C1DC2",
                                                    "作摇杆另一极限位置 DC2,摆角 ψ = ∠C1DC2"))
    if drawing:
        add_bar(sc, "DC1", D, C1, role=Role.GIVEN)
        add_bar(sc, "DC2", D, C2, role=Role.GIVEN)
        sc.add("chord", segment, C1, C2, style="construction", caption=("Join C1C2", "连接 C1C2"))
    near_side = 1 if lifted(_near_side, c1, c2) > 0 else -1
    xaxis = None
    if closing == "frame_line":
        xaxis = sc.add("xaxis", Line, D, Point(1.0, 0.0), role=Role.GIVEN, style="frame",
                       caption=("The frame line: the horizontal through D", "机架线:过 D 的水平线"))
    opt = dict(optional=True, style="candidate")
    out = []
    if g["K"] == 1.0:
        lc = sc.add("lC", line_through, C1, C2, caption=("K = 1: A lies on the line C1C2", "K = 1:A 在 C1C2 连线上"))
        if closing == "frame_line":
            out.append((sc.add("A_1", _meet_or_none, lc, xaxis, label="A", **opt,
                               caption=("It meets the frame line at A", "交机架线于 A")), C1, C2, one))
        else:
            kAD = sc.add("kAD", circle, D, g["AD"], caption=(f"Circle about D with radius AD = {g['AD']:g}",
                                                            f"以 D 为圆心、AD = {g['AD']:g} 为半径作圆"))
            rules = [(NearestTo(C1), "A")] + ([] if symmetric else [(NearestTo(C2), "A′")])
            for j, (rule, lab) in enumerate(rules, 1):
                out.append((sc.add(f"A_{j}", line_circle, lc, kAD, branch=rule, label=lab, **opt,
                                   caption=(f"It meets the line C1C2 at {lab}", f"交 C1C2 连线于 {lab}")), C1, C2, one))
        return out
    sides = ((near_side, "n", "on D's side", "D 所在一侧", "P"), (-near_side, "f", "on the far side", "远离 D 的一侧", "P′"))
    shared: dict[str, Ref] = {}
    n = 0
    for s, pre, en, zh, lab in sides:
        kT = add_theta_circle(sc, C1, C2, th, s, side_words=(en, zh), prefix=pre, label=lab)
        # an annotation (a lean scene skips it) that callers read from a solution's scene: not left out
        sc.add(f"{pre}arcs_ok", admissible_arcs, kT, C1, C2, D, CD, g.get("gamma_allow"), role=Role.ANNOTATION,
               style="admissible", caption=(f"Admissible arcs {en}: a crank, C1 and C2 on one side of AD"
                                            + (f", γmin ≥ {g['gamma_allow']:g}°" if g.get("gamma_allow") else ""),
                                            f"A 的可行弧段({zh})"))
        side_rule = LeftOf(C1, C2) if s > 0 else RightOf(C1, C2)
        if closing == "BC":
            half = sc.add(f"{pre}half", _times, th, 0.5, visible=False, unit="deg")
            kF = add_seeing_circle(sc, f"{pre}kF", C1, C2, half, s, (f"Circle seeing C1C2 under θ/2, {en}",
                                                                    f"作对 C1C2 张角为 θ/2 的圆({zh})"))
            if "kC1" not in shared:
                shared["kC1"] = sc.add("kC1", circle, C1, 2 * g["BC"], caption=(
                    f"Circle about C1 with radius 2·BC = {2 * g['BC']:g}", f"以 C1 为圆心、2BC = {2 * g['BC']:g} 为半径作圆"))
            rules = [(FarthestFrom(C2), "F")] + ([] if symmetric else [(NearestTo(C2), "F*")])
            for rule, flab in rules:
                n += 1
                F = sc.add(f"F_{n}", circle_circle, shared["kC1"], kF, branch=rule, label=f"{flab}{pre}", **opt,
                           caption=(f"They meet at {flab}{pre}: AF = AC2 (the other end)", f"两圆交于 {flab}{pre}"))
                lF = sc.add(f"lF_{n}", line_through, C1, F, optional=True, caption=(f"Join C1 and {flab}{pre}", f"连接 C1 与 {flab}{pre}"))
                out.append((sc.add(f"A_{n}", line_circle, lF, kT, branch=OtherThan(C1), label=f"A{n}", **opt,
                                   caption=(f"It meets the θ-circle again at A{n}", f"交 θ 圆于 A{n}")), C1, C2, near_flag, s))
        elif closing == "AB":
            beta = sc.add(f"{pre}beta", _plus, th, 0.5, 90.0, visible=False, unit="deg")
            kE = add_seeing_circle(sc, f"{pre}kE", C1, C2, beta, s, (f"Circle seeing C1C2 under 90° + θ/2, {en}",
                                                                    f"作对 C1C2 张角为 90° + θ/2 的圆({zh})"))
            ends = [(C2, C1, "kC2", "C2")] + ([] if symmetric else [(C1, C2, "kC1", "C1")])
            for far_end, near_end, kkey, nm in ends:
                if kkey not in shared:
                    shared[kkey] = sc.add(kkey, circle, far_end, 2 * g["AB"], caption=(
                        f"Circle about {nm} with radius 2·AB = {2 * g['AB']:g}", f"以 {nm} 为圆心、2AB = {2 * g['AB']:g} 为半径作圆"))
                n += 1
                folded = "C1" if nm == "C2" else "C2"
                E = sc.add(f"E_{n}", circle_circle, shared[kkey], kE, branch=side_rule, label=f"E{n}", **opt,
                           caption=(f"On A{nm}, with AE{n} = A{folded} (the folded distance), the circles meet at E{n}",
                                    f"E{n} 在 A{nm} 上且 AE{n} = A{folded}:两圆交于 E{n}"))
                lE = sc.add(f"lE_{n}", line_through, far_end, E, optional=True, caption=(f"Join {nm}E{n}", f"连接 {nm}E{n}"))
                out.append((sc.add(f"A_{n}", line_circle, lE, kT, branch=OtherThan(far_end), label=f"A{n}", **opt,
                                   caption=(f"It meets the θ-circle again at A{n}", f"交 θ 圆于 A{n}")), C1, C2, near_flag, s))
        elif closing == "AC1":
            if "kA" not in shared:
                shared["kA"] = sc.add("kA", circle, C1, g["AC1"], caption=(
                    f"Circle about C1 with radius AC1 = {g['AC1']:g}", f"以 C1 为圆心、AC1 = {g['AC1']:g} 为半径作圆"))
            for rule in (FarthestFrom(C2), NearestTo(C2)):
                n += 1
                out.append((sc.add(f"A_{n}", circle_circle, shared["kA"], kT, branch=rule, label=f"A{n}", **opt,
                                   caption=(f"It meets the θ-circle at A{n}", f"交 θ 圆于 A{n}")), C1, C2, near_flag, s))
        elif closing == "AD":            # the frame given with the swing: A on the circle of radius AD about D
            if "kAD" not in shared:
                shared["kAD"] = sc.add("kAD", circle, D, g["AD"], caption=(
                    f"Circle about D with radius AD = {g['AD']:g}", f"以 D 为圆心、AD = {g['AD']:g} 为半径作圆"))
            for rule in (NearestTo(C1),) + (() if symmetric else (FarthestFrom(C1),)):
                n += 1
                out.append((sc.add(f"A_{n}", circle_circle, shared["kAD"], kT, branch=rule, label=f"A{n}", **opt,
                                   caption=(f"It meets the θ-circle at A{n}", f"交 θ 圆于 A{n}")), C1, C2, near_flag, s))
        else:  # frame_line
            for rule in (Leftmost(), Rightmost()):
                n += 1
                out.append((sc.add(f"A_{n}", line_circle, xaxis, kT, branch=rule, label=f"A{n}", **opt,
                                   caption=(f"The frame line meets the θ-circle at A{n}", f"机架线交 θ 圆于 A{n}")), C1, C2, near_flag, s))
    return out


def _meet_or_none(l1: Line, l2: Line) -> Point | None:
    """The crossing of two lines, or None when they are parallel."""
    pts = line_line(l1, l2)
    return pts[0] if pts else None


def _frame_candidates(sc: Scene, g: Mapping[str, Any], th: Ref) -> list:
    CD, AD, phi = g["CD"], g["AD"], g["phi"]
    A = sc.given("A_0", Point(0.0, 0.0), style="pivot", label="A", caption=("Fixed pivot A", "固定铰链 A"))
    D = sc.given_at("D", AD, 0.0, style="pivot", caption=(f"Fixed pivot D with AD = {AD:g}", f"取 AD = {AD:g} 得固定铰链 D"))
    drawing = sc.drawing                     # the frame, the rocker's bar and the join only a drawing needs
    if drawing:
        sc.add("AD_frame", segment, A, D, role=Role.GIVEN, style="frame", caption=("The frame AD", "机架 AD"))
        sc.add("D_ground", marks.ground, D, -math.pi / 2, role=Role.ANNOTATION, style="ground")
    c = lifted(_frame_c1, AD, CD, phi)
    C1 = sc.given("C1", c, style="joint", caption=(f"The given extreme position DC1 at ∠ADC1 = {phi:g}°",
                                                   f"作已知极限位置 DC1,∠ADC1 = {phi:g}°"))
    if drawing:
        add_bar(sc, "DC1", D, C1, ("Rocker DC1", "摇杆 DC1"), role=Role.GIVEN)
    kD = sc.add("kD", circle, D, CD, caption=(f"Circle about D with radius CD = {CD:g}", f"以 D 为圆心、CD = {CD:g} 为半径作圆"))
    if drawing:
        sc.add("AC1s", segment, A, C1, style="construction", caption=("Join AC1", "连接 AC1"))
    out = []
    senses = ((1.0, "counter-clockwise", "逆时针"),) if g["K"] == 1.0 else ((1.0, "counter-clockwise", "逆时针"),
                                                                          (-1.0, "clockwise", "顺时针"))
    n = 0
    for sign, en, zh in senses:
        turn = sc.add(f"turn{int(sign)}", _times, th, sign, visible=False, unit="deg")
        r = sc.add(f"ray{int(sign)}", ray_from, A, C1, turn, caption=(f"Through A a line at θ to AC1, turned {en}",
                                                                      f"过 A 作与 AC1 成 θ 角的直线({zh})"))
        line = sc.add(f"line{int(sign)}", ray_line, r, visible=False)
        # K = 1: the line is AC1 itself and meets the rocker circle at C1 and at C2 (a candidate C2 = C1 would
        # be a crank of length 0 and no swing; rounding made it a "design" whose C1_folded was a coin toss)
        rules = (OtherThan(C1),) if g["K"] == 1.0 else (NearestTo(A), FarthestFrom(A))
        for rule in rules:              # the branch's words follow: "(the intersection nearer to A)"
            n += 1
            words = (sc.add(f"C2_words_{n}", candidate_words, line, kD, n, visible=False) if drawing
                     else candidate_words(None, None, n))
            Cn = sc.add(f"C2_{n}", line_circle, line, kD, branch=rule, label=f"C2,{n}", optional=True, style="candidate",
                        caption=words)
            ok = sc.add(f"ahead_{n}", _ahead, A, r, Cn, optional=True, visible=False)
            out.append((A, C1, ok, one))
    return out


def candidate_words(line: Line | None, circle: Any, n: int) -> tuple[str, str]:
    """The step of candidate C2,n (the frame given): where the θ-line meets the rocker circle, or that it misses
    it (001-15's counter-clockwise line passes the circle: "meets … at C2,1" named a point the figure lacks);
    ``line`` None: the words of a step that meets it (a lean scene's).

    >>> from geomcon.geometry import Circle
    >>> candidate_words(Line(Point(0, 5), Point(1, 0)), Circle(Point(0, 0), 1.0), 1)
    ('The line misses the rocker circle: no candidate C2,1', '该直线与摇杆圆不相交：无候选点 C2,1')
    >>> candidate_words(Line(Point(0, 0), Point(1, 0)), Circle(Point(0, 0), 1.0), 2)[0]
    'It meets the rocker circle at the candidate C2,2'
    """
    if line is None or line_circle(line, circle):
        return f"It meets the rocker circle at the candidate C2,{n}", f"交摇杆圆于候选点 C2,{n}"
    return f"The line misses the rocker circle: no candidate C2,{n}", f"该直线与摇杆圆不相交：无候选点 C2,{n}"


def _ahead(A: Point, r, C: Point) -> Point | None:
    """C when it lies on the ray (in front of A), else None: the line meets the circle behind A too."""
    return C if (C - A).dot(r.direction) > 0 else None


def _draw_choice(sc: Scene, idx: Ref, cands: list, th: Ref, caption: Ref | None = None, *,
                 frame_given: bool = False) -> None:
    """The textbook's choice drawn as the result: A, B1, B2 and both extreme positions of the linkage;
    ``caption`` the step naming the candidate chosen (a drawing's; a lean scene's step keeps fixed words);
    ``frame_given``: the frame AD is drawn already (not drawn again)."""
    fixed_A = len({c[0].key for c in cands}) == 1          # frame given: A is a given point, labelled already
    A = sc.add("A", pick, idx, *(c[0] for c in cands), role=Role.RESULT, style="pivot", label=None if fixed_A else "A",
               caption=caption or ("The textbook's choice of A (the other valid points are candidates)",
                                   "取 A(其余可行点为备选解)"))
    P1 = sc.add("P1c", pick, idx, *(c[1] for c in cands), visible=False)    # pick itself handles None:
    P2 = sc.add("P2c", pick, idx, *(c[2] for c in cands), visible=False)    # not optional

    Cf = sc.add("Cf", nearer, A, P1, P2, visible=False, optional=True)
    Ce = sc.add("Ce", farther, A, P1, P2, visible=False, optional=True)
    drawing = sc.drawing                     # the joins, links, ground symbol and θ mark only a drawing needs
    if drawing:
        sc.add("A_ground", marks.ground, A, -math.pi / 2, role=Role.ANNOTATION, style="ground", optional=True)
        sc.add("ACf", segment, A, Cf, style="construction", optional=True, caption=("Join A to both extreme positions", "连接 A 与两极限位置"))
        sc.add("ACe", segment, A, Ce, style="construction", optional=True, caption=("", ""), visible=False)
    u = sc.add("u_len", length, A, Cf, visible=False, optional=True)
    E = sc.add("Echoice", point_along, A, Ce, u, style="point", label="N", optional=True,
               caption=("The arc about A through the folded position meets the other line at N", "以 A 为圆心、AC(折叠)为半径画弧交另一连线于 N"))
    M = sc.add("Mchoice", midpoint, E, Ce, style="point", label="M", optional=True,
               caption=("Bisect N and the extended position at M: AB = NM, BC = AM", "平分得 M:AB = NM,BC = AM"))
    AB = sc.add("AB_draw", length, E, M, visible=False, optional=True)
    if drawing and not frame_given:          # the frame given (001-15, 001-22) is drawn already: not twice
        sc.add("AD_link", segment, A, Ref("D"), style="frame", optional=True, caption=("The frame AD", "机架 AD"))
    mAB = sc.add("mAB", _times, AB, -1.0, visible=False, optional=True)
    B1 = sc.add("B1", point_along, A, Cf, mAB, role=Role.RESULT, style="joint", label="B1", optional=True,
                caption=("B1 beyond A on the folded line, AB1 = AB", "在折叠共线位置上取 AB1 = AB"))
    B2 = sc.add("B2", point_along, A, Ce, AB, role=Role.RESULT, style="joint", label="B2", optional=True,
                caption=("B2 on the extended line, AB2 = AB", "在拉直共线位置上取 AB2 = AB"))
    for i, (B, C) in enumerate(((B1, Cf), (B2, Ce)), 1) if drawing else ():
        style = "link" if i == 1 else "link-alt"
        sc.add(f"AB{i}", segment, A, B, role=Role.RESULT, style=style, optional=True,
               caption=(f"Draw the designed linkage in extreme position {i}", f"画出所设计机构的极限位置 {i}"))
        sc.add(f"B{i}C{i}", segment, B, C, role=Role.RESULT, style=style, optional=True)
        sc.add(f"C{i}D_design", segment, C, Ref("D"), role=Role.RESULT, style=style, optional=True)
    if drawing:
        sc.add("mark_theta", theta_mark, A, Cf, Ce, th, role=Role.ANNOTATION, style="angle", optional=True)


def theta_mark(A: Point, C1: Point, C2: Point, theta: float) -> marks.AngleMark | None:
    """The θ arc at A between the two extreme positions (none when θ = 0: K = 1 has nothing to mark)."""
    return marks.angle_mark(A, C1, C2, "θ", theta) if theta > 0 else None


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """Every valid design by trilateration (:func:`geomcon.analytic.design_by_k.rocker_design`), sorted by
    :func:`preference`."""
    family, closing = _form(g)
    if family == "links":
        return sorted(crank_rocker_links.analytic(g), key=preference)
    if family == "crank_frame":
        from . import crank_rocker_crank_frame
        return sorted(crank_rocker_crank_frame.analytic(g), key=preference)
    K, CD = g["K"], g["CD"]
    if family != "positions":
        keep = ("AB", "BC", "AD", "CD", "psi", "gamma_min", "theta", "K", "C1_folded", "A_near")
        out = sorted(({k: s[k] if k in ("C1_folded", "A_near") else float(s[k]) for k in keep}       # flags: yes/no
                      for s in _frame_family_twin(g)), key=preference)
    else:
        c1, c2 = _extreme_xy(g)
        # ψ given (and the closing condition symmetric): the mirror images are the same designs
        rows = rocker_design_rows(K, CD, c1, c2, g.get("psi") is not None and closing != "AC1", {closing: g[closing]})
        (c1x, c1y), (c2x, c2y) = c1, c2
        ux, uy = c2x - c1x, c2y - c1y
        d_side = ux * (0.0 - c1y) - uy * (0.0 - c1x)       # which side of the line c1→c2 D (the origin) lies
        th, cd, k = float(theta_from_k(K)), float(CD), float(K)
        out = sorted(({"AB": a, "BC": b, "AD": ad, "CD": cd, "psi": psi, "gamma_min": gamma, "theta": th, "K": k,
                       "C1_folded": bool(folded),      # K = 1: A on the line C1C2 counts as near
                       "A_near": K == 1.0 or (ux * (ay - c1y) - uy * (ax - c1x)) * d_side > 0}
                      for a, b, ad, ax, ay, folded, psi, gamma in rows), key=preference)
    if g.get("H_out") is not None:
        for s in out:
            s["DE"] = g["H_out"] / (2.0 * math.sin(math.radians(s["psi"]) / 2.0))
    return out


def _extreme_xy(g: Mapping[str, Any]) -> tuple[tuple[float, float], tuple[float, float]]:
    """:func:`extreme_positions` as two tuples of floats (the same arithmetic, no Point; a coordinate that is
    not finite is refused by the Points, as there)."""
    CD = g["CD"]
    if g.get("psi") is not None:
        a1, a2 = 90.0 + g["psi"] / 2, 90.0 - g["psi"] / 2
    else:
        a1, a2 = g["phi1"], g["phi2"]
    r1, r2 = math.radians(a1), math.radians(a2)
    x1, y1, x2, y2 = CD * math.cos(r1), CD * math.sin(r1), CD * math.cos(r2), CD * math.sin(r2)
    if x1 - x1 != 0.0 or y1 - y1 != 0.0 or x2 - x2 != 0.0 or y2 - y2 != 0.0:
        return tuple(p.tuple() for p in extreme_positions(g))      # type: ignore[return-value]
    return (float(x1), float(y1)), (float(x2), float(y2))


def _frame_family_twin(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """Frame given: |AC2| = w from w² − 2w·AD·cos β + AD² − CD² = 0 with β = ∠C1AD ± θ (law of cosines);
    valid by :func:`geomcon.analytic.design_by_k.rocker_design_valid`. K = 1 (θ = 0): C2 is the other meeting
    of the line AC1 with the rocker circle, |AC2| = (AD² − CD²)/|AC1| (the power of A); C1 itself is no
    candidate (AB = 0, ψ = 0), as in the construction.

    ψ = |∠ADC2 − ∠ADC1| from the given φ = ∠ADC1 and C2 = w·(cos β, sin β) itself, not from the designed
    lengths: with C1 within 1e-8 of the frame line (φ ≈ 4e-7°) AC1 = |AD − CD| + O(φ²) holds φ only below
    its last bit, and ψ read back from AB, BC, CD, AD (the extremes' law of cosines) loses φ entirely; γmin,
    ∝ φ there, likewise comes from the positions."""
    from ..analytic.linkages import crank_rocker_gamma_from_positions
    CD, AD, phi, K = g["CD"], g["AD"], g["phi"], g["K"]
    th = theta_from_k(K)
    x1 = AD - CD * math.cos(math.radians(phi))
    y1 = CD * math.sin(math.radians(phi))
    w1 = math.hypot(x1, y1)
    alpha1 = math.degrees(math.atan2(y1, x1))           # ∠C1AD, C1 above the frame
    adc1 = math.degrees(math.atan2(abs(y1), CD * math.cos(math.radians(phi))))   # φ itself, folded into [0°, 180°]
    out = []
    for beta in ({alpha1 + th, alpha1 - th} if th else {alpha1}):
        cb = math.cos(math.radians(beta))
        if th == 0.0:                                   # K = 1: the other root of the line AC1, AC1·AC2 = power of A
            roots: tuple[float, ...] = ((AD - CD) * (AD + CD) / w1,)
        else:
            disc = (AD * cb) ** 2 - (AD - CD) * (AD + CD)
            if disc < 0:
                continue
            root = math.sqrt(disc)
            roots = ((AD - CD) * (AD + CD) / (AD * cb + root) if AD * cb + root != 0 else 0.0, AD * cb + root)
        for w in roots:
            if w <= 0:
                continue
            a, b = abs(w - w1) / 2, (w + w1) / 2
            if not rocker_design_valid(a, b, CD, AD, y1, w * math.sin(math.radians(beta))):
                continue
            y2 = w * math.sin(math.radians(beta))
            adc2 = math.degrees(math.atan2(abs(y2), AD - w * math.cos(math.radians(beta))))
            c1, c2 = (x1, y1), (w * math.cos(math.radians(beta)), y2)
            gmin = crank_rocker_gamma_from_positions((0.0, 0.0), (AD, 0.0), *((c1, c2) if w1 < w else (c2, c1)))
            out.append({"AB": a, "BC": b, "AD": AD, "CD": CD, "psi": abs(adc2 - adc1), "gamma_min": gmin,
                        "theta": th, "K": K, "C1_folded": w1 < w, "A_near": True})
    return out


def back_check(g: Mapping[str, Any], ans: Mapping[str, float]) -> list[tuple[str, float, float, str]]:
    """Rebuild with ``crank_rocker.extremes``: K, ψ (when given) and γmin must come back."""
    v = rebuilt_values("crank_rocker.extremes", {"AB": ans["AB"], "BC": ans["BC"], "CD": ans["CD"], "AD": ans["AD"]},
                       ("K", "psi", "gamma_min"))
    rows = [("K", v["K"], g["K"], ""), ("gamma_min", v["gamma_min"], ans["gamma_min"], "deg"),
            ("psi", v["psi"], ans["psi"], "deg")]
    if g.get("psi") is not None:
        rows.append(("psi_given", v["psi"], g["psi"], "deg"))
    return rows


RECIPE = Recipe(
    name="crank_rocker.design_by_K",
    title="Crank-rocker designed from K, the rocker's extreme positions and one closing condition",
    givens=GIVENS,
    answers=ANSWERS,
    points=("D", "A", "C1", "C2", "B1", "B2"),
    construct=construct,
    analytic=analytic,
    validate=_validate,
    back_check=back_check,
    order=preference,
)
