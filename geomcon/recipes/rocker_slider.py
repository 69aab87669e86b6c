"""``rocker_slider.three_positions`` and ``rocker_slider.two_positions``: a connecting rod EF that makes a
slider's positions correspond to a rocker's positions.

Conventions: the rocker turns about the given pivot D; its marked line DK makes the angle ψ with +x,
counter-clockwise. The slider's guide is the line through G = (0, e) with direction angle α (``guide_angle``,
default 0: a horizontal guide at height e); a point of the guide is G + s·u, u = (cos α, sin α). E is the
pin of the rod on the slider, F the hinge of the rod on the rocker (the seed's lettering: 滑块 E, 摇杆上的铰链 F).

**Three positions** (the main form; the slider's pin positions E1, E2, E3 are given by s1, s2, s3): hold the
rocker in position 1 and turn the linkage about D so that each rocker position falls on DK1: the pins E2, E3
go to E2′, E3′ (turned through ψ1 − ψi). Relative to the rocker E moves on a circle about F, so F1 is the
centre of the circle through E1, E2′, E3′ — the two perpendicular bisectors; EF = E1F1, DF = DF1.

**Two positions** (a point of one link chosen: the rocker's hinge F1 is given, the slider's two positions
s1, s2 are those of any mark of the slider, and the pin E is sought on the guide line): hold the slider in
position 1 — the inversion of a slider is a translation — so F2 (F1 carried by the rocker through ψ2 − ψ1)
goes to F2′ = F2 − (s2 − s1)·u; E1 is equidistant from F1 and F2′, so the bisector of F1F2′ meets the guide
at E1. This is the second recipe because its givens differ (F1 instead of a third position).

Checks as for :mod:`geomcon.recipes.four_bar_function`: the twin solves the rod-length equations as a linear
system (:mod:`geomcon.analytic.rocker_slider`), the back-substitution drives the rocker to each ψi and
assembles the slider on the branch of position 1 (the pin ahead of or behind the hinge's foot on the guide);
``branch_ok`` and ``order_ok`` (no dead point — rod perpendicular to the guide — on the rocker's swing from
ψ1 through ψ2 to ψ3, or from ψ1 to ψ2 the short way for two positions); ``alpha_max`` is the largest pressure
angle at the slider (rod against guide) in the designed positions.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.fourbar_drive import REFUSE_CONDITION, WARN_CONDITION
from ..analytic.function_generation import check_inverted
from ..analytic.rocker_slider import (branch_of_pin, slider_position, three_hinge, three_positions, two_pin,
                                      two_positions)
from ..errors import NotAMechanism
from ..geometry import Line, Point, circle, line_circle, perpendicular_bisector, segment
from ..scene import Ref, Role, Scene, marks
from ..tolerance import REL_TOL
from .base import Construction, Quantity, Recipe
from .common import add_pivot, guide_angle_mark, guide_between, largest, length, pressure_deg
from .four_bar_function import (DRAFT_DEG, DRAFT_MM, add_inversion, as_xy, bisector_mark, count,
                                defect_warnings, first, inverse_turn, largest_shift, on_turn, polar_point,
                                same_branch, same_pairs, second, turn, turn_arc)

COMMON_GIVENS = (
    Quantity("D", "point", "the rocker's fixed pivot [x, y]"),
    Quantity("e", "mm", "the guide passes through (0, e)", minimum=None),
    Quantity("guide_angle", "deg", "direction of the guide, counter-clockwise from +x", required=False, default=0.0,
             minimum=None),
)
THREE_GIVENS = (
    COMMON_GIVENS[0],
    Quantity("psi", "deg[]", "three rocker positions: direction of the rocker's marked line DK from +x, "
             "counter-clockwise", minimum=None),
    *COMMON_GIVENS[1:],
    Quantity("s", "mm[]", "the slider pin's three positions E1, E2, E3 along the guide, from (0, e)", minimum=None),
)
TWO_GIVENS = (
    COMMON_GIVENS[0],
    Quantity("psi", "deg[]", "two rocker positions: direction of the rocker's marked line from +x", minimum=None),
    Quantity("F1", "point", "the chosen hinge of the rod on the rocker, in position 1"),
    *COMMON_GIVENS[1:],
    Quantity("s", "mm[]", "the slider's two positions along the guide (of any mark of the slider)", minimum=None),
)
FLAGS = (
    Quantity("branch_ok", "bool", "the positions lie on one assembly branch (pin on the same side of the hinge's foot)"),
    Quantity("order_ok", "bool", "the rocker's swing through the positions in order passes no dead point"),
    Quantity("alpha_max", "deg", "largest pressure angle at the slider (rod against guide) in the designed positions"),
)
THREE_ANSWERS = (
    Quantity("F1", "mm[]", "hinge of the rod on the rocker, position 1, [x, y]"),
    Quantity("DF", "mm", "rocker arm D to F"),
    Quantity("EF", "mm", "connecting rod"),
    Quantity("beta", "deg", "angle of DF from the marked line DK, counter-clockwise, 0° ≤ β < 360°"),
    *FLAGS,
    Quantity("sens_F1", "mm", "how far F1 moves per 0.1° of error in any one ψ or the guide's angle (the largest)"),
    Quantity("sens_F1_mm", "mm", "how far F1 moves per 0.1 mm of error in D, e or any s (the largest)"),
)
TWO_ANSWERS = (
    Quantity("E1", "mm[]", "the rod's pin on the slider, position 1, [x, y]"),
    Quantity("s_E1", "mm", "the pin's position along the guide, from (0, e)"),
    Quantity("EF", "mm", "connecting rod"),
    Quantity("DF", "mm", "rocker arm D to F"),
    *FLAGS,
    Quantity("sens_E1", "mm", "how far E1 moves per 0.1° of error in ψ1, ψ2 or the guide's angle (the largest)"),
    Quantity("sens_E1_mm", "mm", "how far E1 moves per 0.1 mm of error in D, F1, e or s (the largest)"),
)
REFUSE_PARALLEL = 1e-6
"""F2′ within 1e-6 (relative) of F1, or the chord F1F2′ within cos 1e-6 of perpendicular to the guide: the
pin is not determined (refused with the numbers)."""


def pin_condition(far: float, cos_: float) -> float:
    """How many mm E1 moves per mm of error in F1 or F2′, at worst: moving a chord's end by δ shifts its
    bisector by δ/2 and turns it by δ/chord, so the meeting point with the guide moves by
    (1/2 + far)·δ / cos(chord, guide), ``far`` = |E1 − midpoint| / chord. Warned and refused by the policy
    of every three-position synthesis (:data:`~geomcon.analytic.fourbar_drive.WARN_CONDITION`,
    :data:`~geomcon.analytic.fourbar_drive.REFUSE_CONDITION`).

    >>> pin_condition(0.0, 1.0), pin_condition(12.0, 0.5)
    (0.5, 25.0)
    """
    return (0.5 + far) / cos_


def _u(g: Mapping[str, Any]) -> tuple[float, float]:
    a = math.radians(g.get("guide_angle") or 0.0)
    return math.cos(a), math.sin(a)


def _pin(g: Mapping[str, Any], s: float) -> tuple[float, float]:
    ux, uy = _u(g)
    return s * ux, g["e"] + s * uy


# ----------------------------------------------------------------------------------------- validation
def _validate_three(g: Mapping[str, Any]) -> list[str]:
    count(g, ("psi", "s"), 3)
    same_pairs((g["psi"], g["s"]), "ψ, s")
    D = g["D"]
    P = []
    for p, s in zip(g["psi"], g["s"]):
        x, y = _pin(g, s)
        t = math.radians(g["psi"][0] - p)
        vx, vy = x - D[0], y - D[1]
        P.append((D[0] + vx * math.cos(t) - vy * math.sin(t), D[1] + vx * math.sin(t) + vy * math.cos(t)))
    warnings = check_inverted(P, "F1", "E1, E2′, E3′")
    _, _, U, V, _ = three_hinge(D, g["psi"], g["e"], g["guide_angle"], g["s"])
    df = math.hypot(U, V)                                  # DF of the twin, without its sensitivities
    scale = max(math.dist(P[0], P[1]), math.dist(P[1], P[2]), abs(g["e"]), math.hypot(*D))
    if df <= 1e-9 * scale:
        raise NotAMechanism(f"the hinge F1 falls on D (DF = {df:.3g}): the rocker cannot drive the rod")
    return warnings


def _validate_two(g: Mapping[str, Any]) -> list[str]:
    count(g, ("psi", "s"), 2)
    D, F1 = g["D"], g["F1"]
    if math.dist(D, F1) <= 1e-9 * max(math.hypot(*D), math.hypot(*F1), abs(g["e"]), 1e-300):
        raise NotAMechanism(f"F1 = {F1} coincides with D: the hinge must lie off the pivot")
    t = math.radians(g["psi"][1] - g["psi"][0])
    vx, vy = F1[0] - D[0], F1[1] - D[1]
    ux, uy = _u(g)
    ds = g["s"][1] - g["s"][0]
    cx = D[0] + vx * math.cos(t) - vy * math.sin(t) - ds * ux - F1[0]          # F2′ − F1
    cy = D[1] + vx * math.sin(t) + vy * math.cos(t) - ds * uy - F1[1]
    chord, scale = math.hypot(cx, cy), max(math.hypot(vx, vy), abs(ds))
    if chord <= REFUSE_PARALLEL * scale:
        raise NotAMechanism(f"F2′ coincides with F1 (chord {chord:.3g} mm, ψ2 − ψ1 = {g['psi'][1] - g['psi'][0]:g}°, "
                            f"s2 − s1 = {ds:g}): every pin on the guide works, the rod is not determined")
    cos_ = abs(cx * ux + cy * uy) / chord
    if cos_ <= REFUSE_PARALLEL:
        raise NotAMechanism(f"the chord F1F2′ is perpendicular to the guide (cos = {cos_:.3g} < {REFUSE_PARALLEL:g}): "
                            "its bisector runs along the guide and meets it nowhere")
    E1 = two_pin(D, g["psi"], F1, g["e"], g["guide_angle"], g["s"])
    far = math.dist(E1, (F1[0] + cx / 2, F1[1] + cy / 2)) / chord
    k = pin_condition(far, cos_)
    where = f"{far:.3g} chords from the chord's midpoint, cos(chord, guide) = {cos_:.3g}"
    if k >= REFUSE_CONDITION:
        raise NotAMechanism(f"the bisector of F1F2′ meets the guide almost at infinity ({where}: E1 moves {k:.3g} mm "
                            f"per mm ≥ {REFUSE_CONDITION:g}): the pin is not determined")
    if k >= WARN_CONDITION:
        return [f"the bisector of F1F2′ meets the guide far away ({where}): E1 moves up to {k:.4g} mm per mm of "
                f"drafting error (≥ {WARN_CONDITION:g})"]
    return []


# ----------------------------------------------------------------------------------------- step operations
def guide_line(e: float, alpha: float) -> Line:
    """The guide: the line through (0, e) at ``alpha`` degrees."""
    return Line(Point(0.0, e), Point(math.cos(math.radians(alpha)), math.sin(math.radians(alpha))))


def on_guide(guide: Line, s: float) -> Point:
    """The point of the guide at ``s`` from its reference point."""
    return guide.at(s)


def pin_side(F: Point, E: Point, guide: Line) -> int:
    """+1 when the pin E lies ahead of F's foot on the guide (along its direction), −1 behind, 0 at it."""
    v = (E - F).dot(guide.direction)
    return 0 if abs(v) <= REL_TOL * abs(E - F) else (1 if v > 0 else -1)


def dead_hinges(D: Point, DF: float, EF: float, guide: Line) -> tuple[Point, ...]:
    """The hinge positions where the rod stands perpendicular to the guide: the rocker circle meets the
    two parallels to the guide at distance EF."""
    k = circle(D, DF)
    out = []
    for side in (1.0, -1.0):
        out += line_circle(Line(guide.point + guide.normal * (side * EF), guide.direction), k)
    return tuple(out)


def swing_free(D: Point, F1: Point, F2: Point, F3: Point | None, dead: tuple) -> bool:
    """True when no dead hinge lies on the rocker's swing from F1 through F2 to F3 (or from F1 to F2 the
    short way when F3 is None)."""
    if F3 is None:                          # the short way: through the middle of the shorter arc
        F3, mid = F2, (F1 - D).unit() + (F2 - D).unit()
        F2 = D + mid.unit() * abs(F1 - D) if abs(mid) > REL_TOL else D + (F1 - D).perp() * -1.0
    return not any(on_turn(D, X, F1, F2, F3) for X in dead)


def worst_pressure(guide: Line, *pairs: Point) -> float:
    """The largest pressure angle over the (F, E) pairs."""
    return largest(*(pressure_deg(F, E, guide) for F, E in zip(pairs[::2], pairs[1::2])))


def worst_pressure_mark(guide: Line, value: float, *pairs: Point) -> marks.AngleMark:
    """The mark of αmax between the rod and the guide at the slider pin of the position where the rod makes the
    largest angle with the guide (the largest pressure angle; the first such position on a tie)."""
    F, E = max(zip(pairs[::2], pairs[1::2]), key=lambda fe: pressure_deg(fe[0], fe[1], guide))
    return guide_angle_mark(E, F, guide, "αmax", value)


def slider_block(E: Point, guide: Line) -> marks.Slider:
    """The slider block at its pin."""
    return marks.Slider(E, guide.direction)


def rs_sensitivity(D: Point, guide: Line, E: tuple, P: tuple, F1: Point, psi: tuple, s: tuple) -> tuple[float, float]:
    """(per 0.1° of any ψ or α, per 0.1 mm of D, e or any s) for F1 by :func:`~.four_bar_function.centre_shift`:
    the inverted pins are P1 = E1, Pi = Ei turned about D through ψ1 − ψi."""
    zero, u = Point(0.0, 0.0), guide.direction
    rot = [psi[0] - p for p in psi]
    angle_moves = [[zero] + [(P[i] - D).perp() for i in (1, 2)]]                       # ψ1
    for i in (1, 2):                                                                    # ψ2, ψ3
        m = [zero] * 3
        m[i] = -(P[i] - D).perp()
        angle_moves.append(m)
    angle_moves.append([inverse_turn(u.perp() * s[i], rot[i]) for i in range(3)])     # α
    length_moves = [[inverse_turn(Point(0.0, 1.0), r) for r in rot]]                    # e
    for i in range(3):                                                                  # s_i
        m = [zero] * 3
        m[i] = inverse_turn(u, rot[i])
        length_moves.append(m)
    for dD in (Point(1.0, 0.0), Point(0.0, 1.0)):                                        # D
        length_moves.append([zero] + [dD - inverse_turn(dD, rot[i]) for i in (1, 2)])
    return largest_shift(F1, P, angle_moves, DRAFT_DEG), largest_shift(F1, P, length_moves, DRAFT_MM)


def pin_shift(E: Point, F1: Point, F2p: Point, guide: Line, d1: Point, d2: Point, dG: Point, du: Point) -> Point:
    """First-order movement of E1 = (bisector of F1F2′) ∩ guide when F1, F2′ move by d1, d2 and the guide's
    point and direction by dG, du: dE = w + dt·u with w = dG + t·du and
    dt = ((E − F1)·d1 − (E − F2′)·d2 − w·(F2′ − F1)) / (u·(F2′ − F1))."""
    u = guide.direction
    t = (E - guide.point).dot(u)
    w = dG + du * t
    chord = F2p - F1
    dt = ((E - F1).dot(d1) - (E - F2p).dot(d2) - w.dot(chord)) / u.dot(chord)
    return w + u * dt


def rs2_sensitivity(D: Point, guide: Line, E1: Point, F1: Point, F2: Point, F2p: Point, ds: float,
                    dpsi: float) -> tuple[float, float]:
    """(per 0.1° of ψ1, ψ2 or α, per 0.1 mm of D, F1, e or s) for E1 by :func:`pin_shift`."""
    zero, u = Point(0.0, 0.0), guide.direction
    n = u.perp()
    ang = [(zero, -(F2 - D).perp(), zero, zero), (zero, (F2 - D).perp(), zero, zero),     # ψ1, ψ2
           (zero, -n * ds, zero, n)]                                                     # α
    lens = [(zero, u, zero, zero), (zero, -u, zero, zero), (zero, zero, Point(0.0, 1.0), zero)]   # s1, s2, e
    for v in (Point(1.0, 0.0), Point(0.0, 1.0)):
        lens.append((zero, v - inverse_turn(v, dpsi), zero, zero))                          # D
        lens.append((v, inverse_turn(v, dpsi), zero, zero))                                 # F1
    # pin_shift on floats, its move-free parts once: the same operations in the same order (the same bits)
    ux, uy = u.x, u.y
    t = (E1.x - guide.point.x) * ux + (E1.y - guide.point.y) * uy
    cx, cy = F2p.x - F1.x, F2p.y - F1.y
    den = ux * cx + uy * cy
    e1x, e1y, e2x, e2y = E1.x - F1.x, E1.y - F1.y, E1.x - F2p.x, E1.y - F2p.y

    def shift(d1: Point, d2: Point, dG: Point, du: Point) -> float:
        wx, wy = dG.x + du.x * t, dG.y + du.y * t
        dt = ((e1x * d1.x + e1y * d1.y) - (e2x * d2.x + e2y * d2.y) - (wx * cx + wy * cy)) / den
        x, y = wx + ux * dt, wy + uy * dt
        if x - x != 0.0 or y - y != 0.0:               # not finite: the points of the vector formula refuse it
            return abs(pin_shift(E1, F1, F2p, guide, d1, d2, dG, du))
        return math.hypot(x, y)

    def big(moves, per):
        return max(shift(*m) for m in moves) * per
    return big(ang, DRAFT_DEG), big(lens, DRAFT_MM)


def translate(p: Point, guide: Line, ds: float) -> Point:
    """``p`` moved by ``ds`` along the guide."""
    return p + guide.direction * ds


def meet_guide(bis: Line, guide: Line) -> Point:
    """The bisector meets the guide (refused as parallel by the validation)."""
    from .theta_circle import meet_lines
    return meet_lines(bis, guide)


# ----------------------------------------------------------------------------------------- constructions
def _setup(sc: Scene, g: Mapping[str, Any]) -> tuple[Ref, Ref]:
    D = add_pivot(sc, "D", Point(*g["D"]), (f"Fixed pivot D of the rocker at ({g['D'][0]:g}, {g['D'][1]:g})",
                                             f"摇杆固定铰链 D ({g['D'][0]:g}, {g['D'][1]:g})"))
    guide = sc.add("guide", guide_line, g["e"], g["guide_angle"], role=Role.GIVEN, style="given",
                   caption=(f"The slider's guide through (0, {g['e']:g}) at {g['guide_angle']:g}°",
                            f"滑块导路:过 (0, {g['e']:g}),倾角 {g['guide_angle']:g}°"))
    return D, guide


def _rocker_lines(sc: Scene, D: Ref, psi, r: float) -> list[Ref]:
    K = []
    for i, p in enumerate(psi, 1):
        K.append(sc.add(f"K{i}", polar_point, D, r, p, role=Role.GIVEN, style="point", label=f"K{i}",
                        caption=(f"Rocker position DK{i} at ψ{i} = {p:g}°", f"作摇杆位置 DK{i},ψ{i} = {p:g}°")))
        if sc.drawing:
            sc.add(f"DK{i}", segment, D, K[-1], role=Role.GIVEN, style="given")
    return K


def _positions(sc: Scene, D: Ref, guide: Ref, F: list, E: list) -> None:
    for i, (Fi, Ei) in enumerate(zip(F, E), 1) if sc.drawing else ():          # a drawing's steps only
        style = ("pos1", "pos2", "pos3")[i - 1]                  # positions 2, 3 lighter, blocks in their tone
        sc.add(f"DF{i}", segment, D, Fi, role=Role.RESULT, style=style,
               caption=(f"The designed linkage in position {i}: DF{i}E{i}", f"所设计机构的第 {i} 位置 DF{i}E{i}"))
        sc.add(f"F{i}E{i}", segment, Fi, Ei, role=Role.RESULT, style=style)
        sc.add(f"slider{i}", slider_block, Ei, guide, role=Role.ANNOTATION, style=("slider", "slider-2", "slider-3")[i - 1])


def _flags(sc: Scene, D: Ref, guide: Ref, F: list, E: list, DF: Ref, EF: Ref, margin: float) -> tuple[str, ...]:
    sides = [sc.add(f"side{i}", pin_side, Fi, Ei, guide, visible=False) for i, (Fi, Ei) in enumerate(zip(F, E), 1)]
    sc.add("branch_ok", same_branch, *sides, role=Role.MEASUREMENT, visible=False)
    dead = sc.add("dead", dead_hinges, D, DF, EF, guide, visible=False)
    sc.add("order_ok", swing_free, D, F[0], F[1], F[2] if len(F) > 2 else None, dead, role=Role.MEASUREMENT,
           visible=False)
    sc.add("dead_at", dead_hinge_text, D, dead, visible=False)
    pairs = [x for pair in zip(F, E) for x in pair]
    amax = sc.add("alpha_max", worst_pressure, guide, *pairs, role=Role.MEASUREMENT, unit="deg",
                  caption=("αmax: the largest angle between rod and guide in the positions", "最大压力角(连杆与导路夹角)"))
    if sc.drawing:
        sc.add("mark_alpha", worst_pressure_mark, guide, amax, *pairs, role=Role.ANNOTATION, style="angle")
        sc.add("guide_mark", guide_between, E[0], E[-1], guide, margin, role=Role.ANNOTATION, style="guide")
    n = len(F)
    keys = {f"side{i}": f"side{i}" for i in range(1, n + 1)}
    keys.update(branch_ok="branch_ok", order_ok="order_ok", dead_at="dead_at")
    return defect_warnings(sc, keys, [f"position {i}" for i in range(1, n + 1)],     # pin_side's +1, −1, 0:
                           "pin E against the foot of F on the guide", ("ahead", "behind", "at it"))   # not left/right


def dead_hinge_text(D: Point, dead: tuple) -> str:
    """The rocker directions DF of the dead points, for a warning."""
    from ..geometry import polar_angle
    return ", ".join(f"DF at {math.degrees(polar_angle(D, X)):.4g}°" for X in dead) or "none"


def construct_three(g: Mapping[str, Any]) -> Construction:
    """The inversion of the slider's pins into the rocker's position 1."""
    psi, s = g["psi"], g["s"]
    sc = Scene("Rocker–slider: three corresponding positions, inversion about D")
    D, guide = _setup(sc, g)
    E = [sc.add(f"E{i}", on_guide, guide, si, role=Role.GIVEN, style="joint", label=f"E{i}",
                caption=(f"Slider pin E{i} at s{i} = {si:g}", f"滑块铰链位置 E{i},s{i} = {si:g}"))
         for i, si in enumerate(s, 1)]
    span = max(abs(s[0] - s[1]), abs(s[1] - s[2]), abs(s[0] - s[2]))
    K = _rocker_lines(sc, D, psi, 0.5 * span)
    F, P = add_inversion(sc, D, E, K[0], psi, ("E", "K", "F"),
                         (("the rod's hinge on the rocker", "连杆在摇杆上的铰链"), ("EF", "连杆"), ("DF", "")))
    F1, DF, EF = F[0], Ref("DF"), Ref("EF")
    _positions(sc, D, guide, F, E)
    warns = _flags(sc, D, guide, F, E, DF, EF, 0.3 * span)
    sens = sc.add("sens", rs_sensitivity, D, guide, tuple(E), tuple(P), F1, tuple(psi), tuple(s), visible=False)
    sc.add("sens_F1", first, sens, visible=False)
    sc.add("sens_F1_mm", second, sens, visible=False)
    answers = {q.name: q.name for q in THREE_ANSWERS}
    answers["F1"] = "F1_xy"
    points = {"D": "D", "E1": "E1", "E2": "E2", "E3": "E3", "E2'": "E2p", "E3'": "E3p", "F1": "F1", "F2": "F2",
              "F3": "F3"}
    return Construction(sc, answers, points, warnings=warns)


def construct_two(g: Mapping[str, Any]) -> Construction:
    """The inversion of the rocker's hinge into the slider's position 1 (a translation along the guide)."""
    psi, s = g["psi"], g["s"]
    ds = s[1] - s[0]
    sc = Scene("Rocker–slider: two positions, hinge on the rocker chosen")
    D, guide = _setup(sc, g)
    drawing = sc.drawing                     # the slider's marks, joins, arc and bisector mark only a drawing needs
    for i, si in enumerate(s, 1) if drawing else ():
        sc.add(f"S{i}", on_guide, guide, si, role=Role.GIVEN, style="point", label=f"S{i}",
               caption=(f"Slider position {i}: its mark at s{i} = {si:g}", f"滑块第 {i} 位置:标记点 s{i} = {si:g}"))
    F1 = sc.given("F1", Point(*g["F1"]), style="joint", caption=("The chosen hinge F1 on the rocker", "选定摇杆上的铰链 F1"))
    if drawing:
        sc.add("DF1_given", segment, D, F1, role=Role.GIVEN, style="given")
    F2 = sc.add("F2", turn, F1, D, psi[1] - psi[0], role=Role.RESULT, style="joint", label="F2",
                caption=(f"The rocker carries F1 to F2 (ψ2 − ψ1 = {psi[1] - psi[0]:g}°)", "摇杆带 F1 转到 F2"))
    if drawing:
        sc.add("arcF", turn_arc, D, F1, psi[1] - psi[0], style="construction")
    F2p = sc.add("F2p", translate, F2, guide, -ds, style="point", label="F2′",
                 caption=(f"Hold the slider in position 1: move F2 by s1 − s2 = {-ds:g} along the guide to F2′",
                          f"反转(滑块固定于位置 1):将 F2 沿导路平移 s1 − s2 = {-ds:g} 得 F2′"))
    if drawing:
        sc.add("F2F2p", segment, F2, F2p, style="construction")
        sc.add("chord1", segment, F1, F2p, style="construction", caption=("Join F1F2′", "连接 F1F2′"))
    bis = sc.add("bis1", perpendicular_bisector, F1, F2p, style="construction",
                 caption=("Draw the perpendicular bisector of F1F2′", "作 F1F2′ 的中垂线"))
    if drawing:
        sc.add("bis1_mark", bisector_mark, F1, F2p, role=Role.ANNOTATION, style="right-angle")
    E1 = sc.add("E1", meet_guide, bis, guide, role=Role.RESULT, style="joint", label="E1",
                caption=("It meets the guide at E1, the rod's pin on the slider", "中垂线交导路于 E1,即滑块上的铰链"))
    E2 = sc.add("E2", translate, E1, guide, ds, role=Role.RESULT, style="joint", label="E2",
                caption=("The slider carries E1 to E2", "滑块带 E1 到 E2"))
    EF = sc.add("EF", length, E1, F1, role=Role.MEASUREMENT, unit="mm", caption=("Measure EF = E1F1", "量得连杆 EF = E1F1"))
    DF = sc.add("DF", length, D, F1, role=Role.MEASUREMENT, unit="mm", visible=False)
    sc.add("s_E1", guide_coordinate, guide, E1, role=Role.MEASUREMENT, unit="mm", visible=False)
    sc.add("E1_xy", as_xy, E1, visible=False)
    _positions(sc, D, guide, [F1, F2], [E1, E2])
    warns = _flags(sc, D, guide, [F1, F2], [E1, E2], DF, EF, 0.3 * max(abs(ds), math.dist(g["D"], g["F1"])))
    sens = sc.add("sens", rs2_sensitivity, D, guide, E1, F1, F2, F2p, ds, psi[1] - psi[0], visible=False)
    sc.add("sens_E1", first, sens, visible=False)
    sc.add("sens_E1_mm", second, sens, visible=False)
    answers = {q.name: q.name for q in TWO_ANSWERS}
    answers["E1"] = "E1_xy"
    points = {"D": "D", "F1": "F1", "F2": "F2", "F2'": "F2p", "E1": "E1", "E2": "E2"}
    return Construction(sc, answers, points, warnings=warns)


def guide_coordinate(guide: Line, p: Point) -> float:
    """The position of ``p`` along the guide, from its reference point."""
    return (p - guide.point).dot(guide.direction)


# ----------------------------------------------------------------------------------------- twins, back-checks
def analytic_three(g: Mapping[str, Any]) -> list[dict[str, Any]]:
    """The rod-length equations as a linear system (:func:`geomcon.analytic.rocker_slider.three_positions`)."""
    return [three_positions(g["D"], g["psi"], g["e"], g["guide_angle"], g["s"])]


def analytic_two(g: Mapping[str, Any]) -> list[dict[str, Any]]:
    """The pin from the equal-rod condition (:func:`geomcon.analytic.rocker_slider.two_positions`)."""
    return [two_positions(g["D"], g["psi"], g["F1"], g["e"], g["guide_angle"], g["s"])]


def _drive(g: Mapping[str, Any], F1: tuple[float, float], EF: float, pins: list[float]) -> list[tuple[str, float, float, str]]:
    """Turn the rocker to each ψi, assemble the slider on the branch of position 1 (or, for a position designed
    on the other branch, on its own: ``s[i].own_branch``) and read the pin's position; a rod that cannot
    reach the guide reads the foot of F (the nearest position: a finite s that misses, never NaN)."""
    D, psi, al = g["D"], g["psi"], g["guide_angle"]
    Fs = []
    for p in psi:
        t = math.radians(p - psi[0])
        vx, vy = F1[0] - D[0], F1[1] - D[1]
        Fs.append((D[0] + vx * math.cos(t) - vy * math.sin(t), D[1] + vx * math.sin(t) + vy * math.cos(t)))
    sides = [branch_of_pin(F, _pin(g, s), al) for F, s in zip(Fs, pins)]
    rows = []
    for i, (F, s) in enumerate(zip(Fs, pins)):
        side = sides[0] if sides[i] == sides[0] else sides[i]
        got, _ = slider_position(F, EF, g["e"], al, side)    # out of reach: the foot, the nearest (finite) s
        rows.append((f"s[{i}]" if side == sides[0] else f"s[{i}].own_branch", got, s, "mm"))
    return rows


def back_check_three(g: Mapping[str, Any], ans: Mapping[str, Any]) -> list[tuple[str, float, float, str]]:
    """The slider must come back to s1, s2, s3."""
    return _drive(g, ans["F1"], ans["EF"], list(g["s"]))


def back_check_two(g: Mapping[str, Any], ans: Mapping[str, Any]) -> list[tuple[str, float, float, str]]:
    """The pin must come to s_E1 and s_E1 + s2 − s1."""
    t = ans["s_E1"]
    return _drive(g, g["F1"], ans["EF"], [t, t + g["s"][1] - g["s"][0]])


THREE = Recipe(
    name="rocker_slider.three_positions",
    title="Rocker–slider: a rod making three rocker positions correspond to three slider positions (inversion about D)",
    givens=THREE_GIVENS, answers=THREE_ANSWERS,
    points=("D", "E1", "E2", "E3", "E2'", "E3'", "F1", "F2", "F3"),
    construct=construct_three, analytic=analytic_three, validate=_validate_three, back_check=back_check_three,
)
TWO = Recipe(
    name="rocker_slider.two_positions",
    title="Rocker–slider: two corresponding positions with the rocker's hinge chosen (slider held fixed)",
    givens=TWO_GIVENS, answers=TWO_ANSWERS,
    points=("D", "F1", "F2", "F2'", "E1", "E2"),
    construct=construct_two, analytic=analytic_two, validate=_validate_two, back_check=back_check_two,
)
