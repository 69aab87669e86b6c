"""``slotter.design_by_K`` closing on the crank ``AB`` or on the centre distance ``AC`` instead of ``B1B2``
(the Whitworth design: stroke, crank and K given).

Construction: the crank sees the chord B1B2 of its path on the slider's path ee under 180° − θ, and A lies on
the perpendicular to ee through C. With the centre distance given (C at the origin, A above it at AC), the
lines through A at 90° − θ/2 on either side of AC meet ee at B1 and B2; with the crank given (A at the
origin), B1 and B2 lie on those lines at AB from A, ee is the line B1B2 and C the foot of A on it. Then
AB = AB1, AC, B1B2 are measured and the arm CD = S/2 drives E as in the B1B2 form.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.linkages import theta_from_k
from ..geometry import Line, Point, foot, line_line, line_through, point_along, point_on_ray, ray_at_angle, segment
from ..scene import Role, Scene, marks
from .base import Construction
from .common import add_angle_mark, add_bar, add_pivot, angle_deg, length
from .theta_circle import add_theta_step, ray_line


def _half_turn(K: float, sign: float) -> float:
    """±(90° − θ/2) in radians: the turn from A→C to A→B1 (+) or A→B2 (−)."""
    return sign * math.radians(90.0 - theta_from_k(K) / 2.0)


def _frame(sc: Scene, A: Any, C: Any) -> None:
    """The frame AC and A's ground symbol (a drawing's)."""
    if sc.drawing:
        sc.add("A_ground", marks.ground, A, math.pi, role=Role.ANNOTATION, style="ground")
        sc.add("AC_frame", segment, A, C, style="frame", role=Role.GIVEN)


SIDES = (("left", "左"), ("right", "右"))
"""Where the lines of B1 and B2 lie (A above ee: B1 turned clockwise from A→C, to the left)."""


def _first(points: tuple[Point, ...]) -> Point:
    return points[0]


def construct(g: Mapping[str, Any]) -> Construction:
    """A first (crank given) or C first (centre distance given); B1, B2 at ±(90° − θ/2) from AC."""
    K, S = g["K"], g["H"]
    sc = Scene("Slotter with a rotating guide bar designed by K (crank or centre distance given)")
    add_theta_step(sc, K)
    drawing = sc.drawing
    turns = [sc.add(f"turn{i}", _half_turn, K, s, visible=False) for i, s in ((1, -1.0), (2, 1.0))]
    if g.get("AC") is not None:
        AC = g["AC"]
        C = add_pivot(sc, "C", Point(0.0, 0.0), ("Guide-bar pivot C on the slider's path ee", "导杆转动中心 C 位于滑块导路 ee 上"))
        A = sc.given_at("A", 0.0, AC, style="pivot", caption=(f"Crank pivot A above C, AC = {AC:g}",
                                                               f"在 C 上方取曲柄转动中心 A,AC = {AC:g}"))
        _frame(sc, A, C)                     # with A (it was drawn with B2)
        ee = sc.add("ee", Line, C, Point(1.0, 0.0), role=Role.GIVEN, style="given", caption=("The slider's path ee", "滑块导路 ee"))
        # both lines first, then where each meets ee: a line drawn at the step whose caption draws it (issue 11)
        rays = [sc.add(f"rB{i}", ray_at_angle, A, C, t, caption=(
                (f"Lines through A at 90° − θ/2 to AC on either side", "过 A 作与 AC 成 90° − θ/2 的两直线") if i == 1 else ("", "")))
                for i, t in enumerate(turns, 1)]
        Bs = [sc.add(f"B{i}", _first, sc.add(f"meet{i}", line_line, sc.add(f"lB{i}", ray_line, r, visible=False), ee,
                                             visible=False),
                     role=Role.RESULT, style="joint", label=f"B{i}",
                     caption=(f"The {side[0]} line meets ee at B{i}", f"{side[1]}侧直线交 ee 于 B{i}"))
              for i, (r, side) in enumerate(zip(rays, SIDES), 1)]
    else:
        AB = g["AB"]
        A = sc.given("A", Point(0.0, 0.0), style="pivot", caption=("Crank pivot A", "曲柄转动中心 A"))
        down = sc.given("down", Point(0.0, -1.0), visible=False)
        rays = [sc.add(f"rB{i}", ray_at_angle, A, down, t, caption=(
                (f"Lines through A at 90° − θ/2 to the vertical on either side", "过 A 作与铅垂线成 90° − θ/2 的两直线")
                if i == 1 else ("", ""))) for i, t in enumerate(turns, 1)]
        Bs = [sc.add(f"B{i}", point_on_ray, r, AB, role=Role.RESULT, style="joint", label=f"B{i}",
                     caption=(f"B{i} on the {side[0]} line at AB = {AB:g} from A", f"在{side[1]}侧直线上截取 AB = {AB:g} 得 B{i}"))
              for i, (r, side) in enumerate(zip(rays, SIDES), 1)]
        ee = sc.add("ee", line_through, Bs[0], Bs[1], role=Role.CONSTRUCTION, style="given",
                    caption=("The slider's path ee: the line B1B2", "滑块导路 ee:直线 B1B2"))
        C = sc.add("C", foot, ee, A, role=Role.RESULT, style="pivot", label="C",
                   caption=("The foot of A on ee: the guide-bar pivot C", "A 在 ee 上的垂足即导杆转动中心 C"))
        if drawing:
            sc.add("C_ground", marks.ground, C, -math.pi / 2, role=Role.ANNOTATION, style="ground")
        _frame(sc, A, C)
    B1, B2 = Bs
    measure_design(sc, A, C, B1, B2, S, beyond="", b1b2=True)
    return Construction(sc, {}, {n: n for n in ("A", "C", "B1", "B2", "D1")})



def measure_design(sc: Scene, A: Any, C: Any, B1: Any, B2: Any, S: float, *, beyond: str, b1b2: bool) -> None:
    """The steps every slotter design ends with: AB, AC (and B1B2), the crank's extreme positions and the
    angle of one stroke, the arm CD = S/2 along CB2 (``beyond``: the words placing D)."""
    drawing = sc.drawing
    sc.add("AB", length, A, B1, role=Role.MEASUREMENT, unit="mm", caption=("Crank AB = AB1", "曲柄 AB = AB1"))
    sc.add("AC", length, A, C, role=Role.MEASUREMENT, unit="mm", caption=("Frame AC", "机架 AC"))
    if b1b2:
        sc.add("B1B2", length, B1, B2, role=Role.MEASUREMENT, unit="mm", caption=("B1B2 on ee", "ee 上的 B1B2"))
    if drawing:
        add_bar(sc, "AB1", A, B1, ("The crank in the two extreme positions", "曲柄的两个极限位置"))
        add_bar(sc, "AB2", A, B2, style="link-alt")
    ang = sc.add("crank_angle", angle_deg, A, B1, B2, role=Role.MEASUREMENT, unit="deg",
                 caption=("Crank angle of one stroke ∠B1AB2 = 180° − θ", "一个行程的曲柄转角 ∠B1AB2 = 180° − θ"))
    if drawing:
        add_angle_mark(sc, "mark_B1AB2", A, B1, B2, "180°−θ", ang)
    D1 = sc.add("D1", point_along, C, B2, S / 2, role=Role.RESULT, style="joint", label="D1",
                caption=(f"D on the guide bar{beyond}, CD = S/2 = {S / 2:g}: E's extreme positions on ee",
                         f"导杆上取 CD = S/2 = {S / 2:g}(D 在 ee 上时滑块处于极限位置)"))
    sc.add("CD", length, C, D1, role=Role.MEASUREMENT, unit="mm", caption=("Arm CD", "导杆臂长 CD"))
    if drawing:
        add_bar(sc, "CD1", C, D1, style="link")
        for i, B in enumerate((B1, B2), 1):     # the guide bar along ee carries the crank pin's block at B
            add_bar(sc, f"CB{i}", C, B, (("The guide bar along ee at each extreme, the block B on it",
                                          "极限位置时导杆沿 ee,滑块 B 在导杆上") if i == 1 else ("", "")),
                    style="link" if i == 1 else "link-alt")
            sc.add(f"slider_B{i}", _block_along, B, C, role=Role.ANNOTATION, style="slider")


def _block_along(b: Point, c: Point) -> marks.Slider:
    """The block at ``b`` sliding along the guide bar c–b."""
    return marks.Slider(b, b - c)
