"""``cam.eccentric``: the eccentric-circle disc cam (偏心圆凸轮) — base circle, stroke, rise and return angles,
and displacement, pressure angle and velocity at a given position.

Frame: the cam's rotation centre O at the origin; a translating follower moves up (+y) along the line x = e
(e > 0: its axis right of O; D = (e, 0) is the foot of the offset); an oscillating follower's pivot Q is at
(0, a) with the arm on the ``arm`` side. The disc (radius R) has its centre A at OA from O. The drawing shows
the mechanism in the **state** position, chosen by at most one of

- ``delta``: the cam turned by δ (deg, in the sense of rotation) from the follower's lowest position;
- ``A_angle``: "the position shown" as a polar angle of O→A (deg, counter-clockwise from +x, follower up):
  0 = A to the right of O with OA perpendicular to a translating follower's guide, 90 = A straight above O;
- ``contact_angle`` (translating only): the cam touches the follower at the disc point (the roller centre
  at the pitch-circle point) on the ray from A at this angle (deg, counter-clockwise) from the ray O→A:
  0 = the far end of the line of centres (the highest point), ±90 = the ends of the diameter ⊥ OA;

then turned further by ``turn`` degrees in the sense of rotation ("after turning 90° from the shown
position"). Without a state the drawing shows the lowest position (δ = 0).

Construction (the inversion, 反转法: the cam stands still, the follower turns about O by −δ): AO extended
meets the pitch circle (R + rr about A; the disc itself for a knife) at B0, the point nearest O: r0 = OB0
(the base circle of the pitch curve; ``r0_actual`` = R − OA is the base circle of the disc itself); OA
extended meets it at B1, the farthest point. The follower's lines through B0 and B1 tangent to the offset
circle (their feet K0, K1 on the right of O→B for e > 0, on the left for e < 0: the follower's own
orientation) are its lowest and highest positions, turned back; h = K1B1 − K0B0, the rise angle is ∠K0OK1
measured against ω. The follower meets the pitch circle at B (the meeting point farther along its motion);
δ = ∠K0OD against ω, s = DB − K0B0, α = the acute angle between the normal AB (a circle's normal passes its
centre) and the guide; the instant centre P, where AB meets the line through O perpendicular to the guide,
gives v = ω·OP. The extremes of α lie where OA ⊥ the guide (feet M± on line OA) or at the ends of a stroke;
α = 0 where the follower's line passes through A (the tangents from A to the offset circle).

Flat face (perpendicular to the guide): it touches the disc where the disc's radius is parallel to the
guide, α ≡ 0, r0 = R − OA, h = 2·OA, rise and return 180°; s does not depend on R.

Oscillating roller: B is where the arm circle (Q, L) meets the pitch circle, on the arm's side of Q→A; at the
lowest and highest positions the inverted pivot Q0, Q1 lies on the circle of radius a about O at L from B0,
B1; ψ0 = ∠OQ0B0, ψmax = ∠OQ1B1 − ψ0; α is the acute angle between the normal AB and the roller's velocity
(⊥ QB). The extremes of α over the rise and the return are found on the constructed α(δ) numerically.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..cam.arm_replay import ArmReplay
from ..cam.eccentric import Oscillating, Translating, check_disc
from ..cam.eccentric_speeds import arm_maxima, arm_speeds, translating_maxima, translating_speeds
from ..cam.profile import maximise
from ..errors import GeomconError, NotAMechanism
from ..numeric import deg360
from ..geometry import (Ahead, LeftOf, Leftmost, Line, Point, RightOf, Rightmost, Segment, Upper, circle, circle_circle,
                        line_circle, line_line, point_along,
                        line_through, rotate, segment, thales_circle)
from ..geometry.measure import angle_at, signed_angle
from ..scene import Ref, Role, Scene, marks
from .base import Construction, Quantity, Recipe
from .cam_common import add_rotation
from .cam_eccentric_speeds import (arm_epsilon2, arm_epsilon2_max, arm_omega2, arm_omega2_max, guide_a_max, guide_accel,
                                   guide_v_max)
from .common import add_angle_mark, add_pivot, angle_deg, difference, length, velocity_end

UP = Point(0.0, 1.0)
STATES = ("delta", "A_angle", "contact_angle")
MARK_IN = 0.85
"""The radius of the rise and return angles' arcs about O (δ0 from K0 to K1 against ω, δ0′ back), a part of the
offset circle's: just inside it, their values find room outside the arcs (on the offset circle itself 001-29's
values sat on their arcs, the cam's profile 5 mm beyond). Drawn on the sheet of the lowest position only (no state
given: 001-29 asks the rise and return angles); a sheet of a given position is about its s and α (001-26, 001-27)."""

GIVENS = (
    Quantity("R", "mm", "radius of the disc"),
    Quantity("OA", "mm", "eccentricity: distance from the rotation centre O to the disc's centre A"),
    Quantity("follower", "choice", "knife, roller or flat (face perpendicular to the guide)", required=False,
             default="knife", minimum=None, choices=("knife", "roller", "flat")),
    Quantity("rr", "mm", "roller radius (roller followers)", required=False, default=0.0, inclusive=True),
    Quantity("e", "mm", "offset of a translating follower: > 0 puts its axis right of O (follower moving up)",
             required=False, default=0.0, minimum=None),
    Quantity("rotation", "choice", "sense of rotation of the cam", required=False, default="ccw", minimum=None,
             choices=("ccw", "cw")),
    Quantity("omega", "rad/s", "angular speed of the cam, rad/s (gives the follower's velocity v); 0 < ω ≤ 1e4 rad/s "
             "(95 000 rpm)", required=False, maximum=1e4),
    Quantity("delta", "deg", "state: cam angle turned from the lowest position", required=False, minimum=None),
    Quantity("A_angle", "deg", "state: polar angle of O→A in the figure (0: A right of O, OA ⊥ the guide)",
             required=False, minimum=None),
    Quantity("contact_angle", "deg", "state: contact on the ray from A at this angle from the ray O→A",
             required=False, minimum=None),
    Quantity("turn", "deg", "turn the state further by this cam angle (in the sense of rotation)", required=False,
             default=0.0, minimum=None),
    Quantity("a", "mm", "oscillating follower: distance from O to the arm's pivot Q", required=False),
    Quantity("L", "mm", "oscillating follower: arm length QB", required=False),
    Quantity("arm", "choice", "oscillating follower: side of the line Q→O the roller lies on", required=False,
             default="left", minimum=None, choices=("left", "right")),
    Quantity("contact_name", "choice", "translating knife or roller: the contact point's name in the problem's "
             "own figure (the statement's C or D: 001-25); B by default", required=False, default="B", minimum=None,
             choices=("B", "C", "D")),
    Quantity("far_name", "choice", "the farthest point of the line of centres (B1 by default) as the problem "
             "names it (001-25's C)", required=False, default="B1", minimum=None, choices=("B1", "C")),
)
ANSWERS = (
    Quantity("r0", "mm", "base circle radius of the pitch curve (knife, roller); of the profile (flat)"),
    Quantity("r0_actual", "mm", "base circle radius of the actual profile (the disc), R − OA; a knife edge's is r0 "
             "(its figure prints r0 only)"),
    Quantity("h", "mm", "stroke of a translating follower"),
    Quantity("psi0", "deg", "oscillating: the arm's initial angle ∠OQ0B0"),
    Quantity("psi_max", "deg", "oscillating: angular stroke"),
    Quantity("rise_angle", "deg", "cam angle of the rise (推程运动角)"),
    Quantity("return_angle", "deg", "cam angle of the return (回程运动角)"),
    Quantity("alpha_max_rise", "deg", "largest pressure angle of the rise"),
    Quantity("delta_alpha_max_rise", "deg", "cam angle (from the lowest position) where it occurs (translating)"),
    Quantity("alpha_min_rise", "deg", "smallest pressure angle of the rise (translating)"),
    Quantity("alpha_max_return", "deg", "largest pressure angle of the return"),
    Quantity("delta_alpha_max_return", "deg", "cam angle where it occurs (translating)"),
    Quantity("alpha_max", "deg", "largest pressure angle of the turn"),
    Quantity("offset_correct", "bool", "the offset lowers the rise's pressure angle (逆转右偏, 顺转左偏)"),
    Quantity("delta", "deg", "state: cam angle from the lowest position"),
    Quantity("s", "mm", "state: displacement from the lowest position (translating)"),
    Quantity("psi", "deg", "state: the arm's swing from its lowest position (oscillating)"),
    Quantity("alpha", "deg", "state: pressure angle"),
    Quantity("v", "mm/s", "state: follower velocity, mm/s (> 0 moving away from O), when omega is given"),
    Quantity("a", "mm/s²", "state: follower acceleration ω²·d²s/dδ² (translating, ω constant), when omega is given"),
    Quantity("v_max", "mm/s", "largest |v| over the turn (translating), when omega is given"),
    Quantity("a_max", "mm/s²", "largest |a| over the turn (translating), when omega is given"),
    Quantity("omega2", "rad/s", "state: the arm's angular velocity ω·dψ/dδ (> 0 swinging out), when omega is given"),
    Quantity("epsilon2", "rad/s²", "state: the arm's angular acceleration ω²·d²ψ/dδ², when omega is given"),
    Quantity("omega2_max", "rad/s", "largest |ω2| over the turn (oscillating), when omega is given"),
    Quantity("epsilon2_max", "rad/s²", "largest |ε2| over the turn (oscillating), when omega is given"),
)


# ---------------------------------------------------------------------------- validation
def _state(g: Mapping[str, Any]) -> str | None:
    given = [k for k in STATES if g.get(k) is not None]
    if len(given) > 1:
        raise NotAMechanism(f"give at most one state ({', '.join(STATES)}), got {', '.join(given)}")
    return given[0] if given else None


def _oscillating(g: Mapping[str, Any]) -> bool:
    if (g.get("a") is None) != (g.get("L") is None):
        raise NotAMechanism("an oscillating follower needs both a and L")
    return g.get("a") is not None


def twin_cam(g: Mapping[str, Any]) -> Translating | Oscillating:
    """The analytic model of the givens (validates them)."""
    rr = g.get("rr") or 0.0
    if g.get("follower", "knife") == "roller" and rr <= 0:
        raise NotAMechanism("a roller follower needs rr > 0")
    if g.get("follower", "knife") != "roller" and rr > 0:
        raise NotAMechanism(f"rr = {rr:g} given for a {g.get('follower', 'knife')} follower")
    if _oscillating(g):
        if g.get("follower", "knife") == "flat":
            raise NotAMechanism("an oscillating flat-faced follower is not supported")
        if g.get("e"):
            raise NotAMechanism(f"e = {g['e']:g} given for an oscillating follower (it has a and L)")
        if g.get("contact_angle") is not None:
            raise NotAMechanism("contact_angle is a state of translating followers only")
        return Oscillating(g["R"], g["OA"], g["a"], g["L"], rr, g.get("rotation", "ccw"), g.get("arm", "left"))
    return Translating(g["R"], g["OA"], g.get("e") or 0.0, rr, g.get("follower", "knife"), g.get("rotation", "ccw"))


def _validate(g: Mapping[str, Any]) -> list[str]:
    check_disc(g["R"], g["OA"])
    _state(g)
    twin_cam(g)
    return wrong_offset(g)


def wrong_offset(g: Mapping[str, Any]) -> list[str]:
    """The warning of a translating knife or roller whose offset lies on the wrong side for the cam's sense
    (逆转右偏，顺转左偏: :func:`offset_correct`), a design fault the Results only answered "offset on the correct
    side: no" (001-26, 001-29 cw); none for a centred, flat-faced or oscillating follower.

    >>> wrong_offset({"e": -10, "rotation": "ccw", "follower": "knife"})
    ["offset on the wrong side: e = -10 puts the follower's axis left of O on a ccw cam, which makes the rise's \
pressure angles larger (a ccw cam wants the axis right of O, a cw cam left)"]
    >>> wrong_offset({"e": 15, "rotation": "ccw", "follower": "roller"}), wrong_offset({"e": 0, "rotation": "cw"})
    ([], [])
    """
    e, rot = g.get("e") or 0.0, g.get("rotation") or "ccw"
    if not e or g.get("follower") == "flat" or g.get("a") is not None or offset_correct(e, 1.0 if rot == "ccw" else -1.0):
        return []
    return [f"offset on the wrong side: e = {e:g} puts the follower's axis {'right' if e > 0 else 'left'} of O on a "
            f"{rot} cam, which makes the rise's pressure angles larger (a ccw cam wants the axis right of O, a cw cam "
            "left)"]


# ---------------------------------------------------------------------------- step operations
def turned_against(o: Point, p: Point, q: Point, sense: float) -> float:
    """The cam angle (deg, [0, 360)) from ray o→p to ray o→q measured against the cam's rotation (the
    follower's inverted motion): clockwise for a counter-clockwise cam."""
    return deg360(math.degrees(-sense * signed_angle(p - o, q - o)))


def guide_pressure(a: Point, b: Point, direction: Point) -> float:
    """Acute angle (deg) between the normal a–b and a direction."""
    x = math.degrees(angle_at(Point(0.0, 0.0), b - a, direction))
    return min(x, 180.0 - x)


def arm_pressure(a: Point, b: Point, q: Point) -> float:
    """Acute angle (deg) between the normal b–a and the roller's velocity (⊥ q–b)."""
    return abs(90.0 - math.degrees(angle_at(b, a, q)))


def follower_line(foot: Point, e: float) -> Line:
    """The follower's line with its foot on the offset circle: tangent there, oriented so that O lies on
    its left for e > 0 (axis right of O), on its right for e < 0."""
    n = foot.unit() if e > 0 else -foot.unit()
    return Line(foot, n.perp())


def tangent_foot(o: Point, p: Point, r: float, side: float) -> Point | None:
    """Where a tangent from ``p`` touches the circle about ``o`` of radius ``r``, on the right of the directed
    line o→p (side = +1) or on its left (side = −1); None when p lies inside the circle. The Thales circle on
    op meets the circle there, but that intersection (radii |op|/2 and r) carries ε·|op| into a point at r
    from o, turning it by ε·|op|/r (4e-9 rad at |op| = 1e9, r = 10); here the point is laid off at the angle
    β = atan2(√(|op|² − r²), r) from o→p, as accurate as its data.

    >>> k = tangent_foot(Point(0.0, 0.0), Point(0.0, 20.0), 10.0, 1.0)
    >>> round(k.x, 12), round(k.y, 12)                        # 60° from o→p, on its right
    (8.660254037844, 5.0)
    """
    d = p - o
    dist = abs(d)
    if dist < r:
        return None
    beta = math.atan2(math.sqrt((dist - r) * (dist + r)), r)
    return o + rotate(d.unit(), Point(0.0, 0.0), -side * beta) * r


def foot_on_OA(o: Point, a: Point, e: float, sign: float) -> Point:
    """The point of line OA at distance |e| from O, on the side of A (sign = +1) or opposite (−1)."""
    return o + (a - o).unit() * (sign * abs(e))


def state_A(R: float, E: float, Rp: float, e: float, sense: float, flat: bool, state: str | None, value: float,
            turn: float) -> Point:
    """Where A is drawn: the state position (see the module docstring), by the inversion's geometry."""
    O = Point(0.0, 0.0)
    if state == "A_angle":
        A = Point(E * math.cos(math.radians(value)), E * math.sin(math.radians(value)))
    elif state == "contact_angle":
        Aref = Point(E, 0.0)
        K = rotate(Aref + Point(Rp, 0.0), Aref, math.radians(value))
        if flat:
            up = signed_angle(K - Aref, UP)
        elif e == 0.0:
            up = signed_angle(K, UP)
        else:
            foot = RightOf(O, K) if e > 0 else LeftOf(O, K)
            F = foot.choose(circle_circle(thales_circle(O, K), circle(O, abs(e))))
            up = signed_angle(F, Point(e, 0.0))
        A = rotate(Aref, O, up)
    else:   # the lowest position: the follower's axis meets the base circle at B0, A lies on B0O extended
        if flat:
            B0 = Point(0.0, R - E)       # a flat face is lowest when it touches the disc straight above O
        else:
            B0 = Ahead(Point(e, 0.0), Point(e, 1.0)).choose(line_circle(Line(Point(e, 0.0), UP), circle(O, Rp - E)))
        A = O + (O - B0).unit() * E
        if state == "delta":
            A = rotate(A, O, sense * math.radians(value))
    return rotate(A, O, sense * math.radians(turn))


def velocity(A: Point, B: Point, sense: float, omega: float, delta: float, rise: float) -> float:
    """v = ω·OP with P where the normal AB meets the line through O perpendicular to the guide (the
    relative instant centre); positive when that cam point moves up (away from O). At the ends of the
    stroke (δ = 0 or the rise angle, as measured) the follower is at rest: P is O itself, and the
    intersection would only give roundoff of the cam's size."""
    if delta in (0.0, rise):
        return 0.0
    P = line_line(line_through(A, B) if A != B else Line(A, UP), Line(Point(0.0, 0.0), Point(1.0, 0.0)))[0]
    return sense * omega * P.x


def largest_in(values: tuple[float, ...], deltas: tuple[float, ...], lo: float, hi: float, pick: str) -> tuple:
    """(value, δ) of the largest (``pick`` = "max") or smallest value whose δ lies in [lo, hi]."""
    rows = [(v, d) for v, d in zip(values, deltas) if lo - 1e-9 <= d <= hi + 1e-9]
    return max(rows) if pick == "max" else min(rows)


def first(pair: tuple) -> float:
    """The value of a (value, δ) pair."""
    return pair[0]


def second(pair: tuple) -> float:
    """The δ of a (value, δ) pair."""
    return pair[1]


def second_in_turn(pair: tuple) -> float:
    """The δ of a (value, δ) pair in [0°, 360°): the return's end (δ = 360° of the candidates) is 0°, the start
    of the next rise, as the textbook states it (001-26, 001-29 cw printed δ(α′max) = 360°)."""
    return deg360(pair[1])


def offset_correct(e: float, sense: float) -> bool:
    """逆转右偏, 顺转左偏: the axis on the side where the instant centre lies during the rise."""
    return e * sense > 0


def complement_turn(x: float) -> float:
    """360° − x."""
    return 360.0 - x


def arm_angle(q: Point, o: Point, b: Point) -> float:
    """∠OQB (deg)."""
    return angle_deg(q, o, b)


def add_base_circle(sc: Scene, O: Ref, A: Ref, pitch: Ref, roller: bool, far: str = "B1",
                    called: str = "") -> tuple[Ref, Ref]:
    """The line of centres AO meets the pitch circle at B0 (nearest O: r0 = OB0, the base circle) and B1
    (farthest, labelled ``far``: empty when the contact point, labelled itself, lies there; the captions call
    it ``called``, else ``far``, else B1: 001-25's sheet labels it C, the statement's name); for a roller, the
    disc at E0 (r0_actual = OE0). Returns (B0, B1)."""
    name = called or far or "B1"
    lineAO = sc.add("lineAO", line_through, A, O, style="construction", caption=("Draw the line of centres AO", "作中心线 AO"))
    # B0, E0 and B1 are laid off from O along the line of centres (|OB0| = Rp − OA …): the same points as the
    # line meeting the circles, but their direction from O is exact even when OB0 ≪ R (OA → R), where an
    # intersection's ε·R error would turn OB0 by ε·R/r0 and with it every angle measured from B0
    Rp = sc.add("Rp_len", lambda c: c.r, pitch, visible=False)
    OA = sc.add("OA_len", length, O, A, visible=False)
    away = sc.add("A_opposite", lambda o, a: o + (o - a), O, A, visible=False)
    B0 = sc.add("B0", point_along, O, away, sc.add("OB0_len", difference, Rp, OA, visible=False), style="point",
                label="B0", caption=("AO extended meets the pitch curve at B0, its point nearest O (OB0 = Rp − OA)",
                                     "AO 延长交理论廓线于 B0(离 O 最近,OB0 = Rp − OA)"))
    r0 = sc.add("r0", length, O, B0, role=Role.MEASUREMENT, unit="mm",
                caption=("r0 = OB0: the base circle", "基圆半径 r0 = OB0"))
    sc.add("base", circle, O, r0, style="theta-circle", caption=("Draw the base circle", "作基圆"))
    if roller:
        R = sc.add("R_len", lambda c: c.r, Ref("disc"), visible=False)
        E0 = sc.add("E0", point_along, O, away, sc.add("OE0_len", difference, R, OA, visible=False), style="point",
                    label="E0", caption=("AO extended meets the disc at E0", "AO 延长交实际廓线于 E0"))
        sc.add("r0_actual", length, O, E0, role=Role.MEASUREMENT, unit="mm",
               caption=("r0 of the actual profile = OE0 = R − OA", "实际廓线基圆半径 OE0 = R − OA"))
    else:
        sc.add("r0_actual", length, O, B0, role=Role.MEASUREMENT, unit="mm", visible=False)
    B1 = sc.add("B1", point_along, O, A, sc.add("OB1_len", lambda r, d: r + d, Rp, OA, visible=False), style="point",
                label=far, caption=(f"OA extended meets it at {name}, its farthest point (O{name} = Rp + OA)",
                                     f"OA 延长交理论廓线于 {name}(离 O 最远,O{name} = Rp + OA)"))
    return B0, B1


# ---------------------------------------------------------------------------- construction
def construct(g: Mapping[str, Any]) -> Construction:
    """Build the eccentric cam's construction at the state position."""
    if _oscillating(g):
        return _construct_oscillating(g)
    R, E, e = g["R"], g["OA"], g.get("e") or 0.0
    follower, rr = g.get("follower", "knife"), g.get("rr") or 0.0
    sense = 1.0 if g.get("rotation", "ccw") == "ccw" else -1.0
    flat = follower == "flat"
    Rp = R + rr if follower == "roller" else R
    st = _state(g)
    sc = Scene("Eccentric-circle cam")
    O = add_pivot(sc, "O", Point(0.0, 0.0), ("Rotation centre O of the cam", "凸轮回转中心 O"))
    add_rotation(sc, O, sense)
    how = {"delta": (f"turned by δ = {g.get('delta')}° from the lowest position", f"自最低位置转过 δ = {g.get('delta')}°"),
           "A_angle": (f"as shown: O→A at {g.get('A_angle')}° from the horizontal", f"如图:O→A 与水平线成 {g.get('A_angle')}°"),
           "contact_angle": (f"touching the follower at {g.get('contact_angle')}° from the ray O→A about A",
                             f"与从动件在 A 处自 OA 射线转 {g.get('contact_angle')}° 的点接触"),
           None: ("at the follower's lowest position", "位于从动件最低位置")}[st]
    A = sc.given("A", state_A(R, E, Rp, e, sense, flat, st, g.get(st) if st else 0.0, g.get("turn") or 0.0),
                 caption=(f"Disc centre A at OA = {E:g} from O, {how[0]}", f"圆盘中心 A,OA = {E:g},{how[1]}"),
                 style="joint")
    sc.add("OA_seg", segment, O, A, role=Role.RESULT, style="link", caption=("", ""))
    sc.add("disc", circle, A, R, role=Role.RESULT, style="link",
           caption=(f"The cam: the circle about A with radius R = {R:g}", f"凸轮廓线:以 A 为圆心、R = {R:g} 的圆"))
    pitch = sc.add("pitch", circle, A, Rp, style="path",
                   caption=(f"Pitch curve: the circle about A with radius R + rr = {Rp:g}",
                            f"理论廓线:以 A 为圆心、R + rr = {Rp:g} 的圆")) if follower == "roller" else Ref("disc")
    contact = g.get("contact_name") or "B"
    ft = "D" if contact != "D" else "F"              # the offset's foot: D unless the statement names the contact D
    D = sc.given("D", Point(e, 0.0), style="point", label=ft if e else "",
                 caption=(f"Foot {ft} of the follower's axis, O{ft} = e = {e:g}", f"导路垂足 {ft},O{ft} = e = {e:g}")
                 if e else ("", ""))                  # centred: the axis passes O (001-25 named a foot D at O)
    axis = sc.add("axis", Line, D, UP, role=Role.GIVEN, style="frame",
                  caption=(f"The follower's guide through {ft}, perpendicular to O{ft}", f"过 {ft} 作导路(垂直于 O{ft})")
                  if e else ("The follower's guide through O (centred: e = 0)", "过 O 作导路(对心:e = 0)"))
    if e:
        sc.add("offset_circle", circle, O, abs(e), style="construction",
               caption=(f"Offset circle about O with radius |e| = {abs(e):g}", f"以 O 为圆心、|e| = {abs(e):g} 为半径作偏距圆"))
    at_far = st == "contact_angle" and (g.get("contact_angle") or 0.0) % 360.0 == 0.0 and not flat and not e
    far = "" if at_far else g.get("far_name") or "B1"
    fb = far or contact                              # the farthest point's name in the captions (h, the rise angle)
    B0, B1 = add_base_circle(sc, O, A, pitch, follower == "roller", far, fb)
    if flat:
        return _finish_flat(sc, g, O, A, D, axis, B0, B1, sense)
    if e:
        side = 1.0 if e > 0 else -1.0               # the tangent point right of O→B for e > 0, left for e < 0
        K0 = sc.add("K0", tangent_foot, O, B0, abs(e), side, style="point", label="K0",
                    caption=("The follower through B0 tangent to the offset circle at K0: its lowest position, turned back",
                             "过 B0 作偏距圆切线,切点 K0:从动件最低位置(反转后)"))
        K1 = sc.add("K1", tangent_foot, O, B1, abs(e), side, style="point", label="K1",
                    caption=(f"…and through {fb}, foot K1: its highest position", f"过 {fb} 作切线,切点 K1:最高位置"))
        ref0, ref1 = K0, K1
        low = sc.add("low_len", length, K0, B0, visible=False, unit="mm")
        high = sc.add("high_len", length, K1, B1, visible=False, unit="mm")
    else:
        ref0, ref1 = B0, B1
        low = sc.add("low_len", length, O, B0, visible=False, unit="mm")
        high = sc.add("high_len", length, O, B1, visible=False, unit="mm")
    sc.add("K0B0", segment, ref0 if e else O, B0, style="ghost", caption=("", ""))
    sc.add("K1B1", segment, ref1 if e else O, B1, style="ghost", caption=("", ""))
    sc.add("h", difference, high, low, role=Role.MEASUREMENT, unit="mm",
           caption=(f"h = K1{fb} − K0B0" if e else f"h = O{fb} − OB0", f"行程 h = K1{fb} − K0B0" if e else f"行程 h = O{fb} − OB0"))
    rise = sc.add("rise_angle", turned_against, O, ref0, ref1, sense, role=Role.MEASUREMENT, unit="deg",
                  caption=("Rise angle: ∠K0OK1 against ω" if e else f"Rise angle: ∠B0O{fb} against ω",
                           "推程运动角:逆 ω 方向量 ∠K0OK1" if e else f"推程运动角 ∠B0O{fb}(逆 ω)"))
    back = sc.add("return_angle", complement_turn, rise, role=Role.MEASUREMENT, unit="deg", visible=False)
    if e and st is None:            # the cam's own angles on the sheet of its lowest position (no state asked)
        sc.add("OK0", segment, O, ref0, style="construction", caption=("", ""))      # the rays the arcs end on
        sc.add("OK1", segment, O, ref1, style="construction", caption=("", ""))
        for key, a, b, sym, v in (("mark_rise", ref0, ref1, "δ0", rise), ("mark_return", ref1, ref0, "δ0′", back)):
            add_angle_mark(sc, key, O, a, b, sym, v, MARK_IN * abs(e))
    B = sc.add("B", line_circle, axis, pitch, branch=Upper(), role=Role.RESULT, style="joint",
               label=contact, caption=(f"The follower meets the pitch curve at {contact}",
                                       f"导路交理论廓线于 {contact}(从动件位置)"))
    if follower == "roller":
        sc.add("roller", circle, B, rr, role=Role.RESULT, style="link", caption=("", ""))
    top = sc.add("top", lambda b, k: b + UP * k, B, 0.6 * R, visible=False)
    sc.add("stem", segment, B, top, role=Role.RESULT, style="link", caption=("", ""))
    sc.add("guide_mark", lambda b: marks.bearing(b + UP * (0.45 * R), UP), B, role=Role.ANNOTATION,  # clear of
           style="guide")                                                       # α's arc above B (_alpha_mark)
    sc.add("delta", turned_against, O, ref0, D if e else B, sense, role=Role.MEASUREMENT, unit="deg",
           caption=(f"Cam angle from the lowest position: δ = ∠K0O{ft} against ω" if e else f"δ = ∠B0O{contact} against ω",
                    f"自最低位置的凸轮转角 δ = ∠K0O{ft}(逆 ω)" if e else f"凸轮转角 δ = ∠B0O{contact}(逆 ω)"))
    DB = sc.add("DB", length, D if e else O, B, visible=False, unit="mm")
    s = sc.add("s", difference, DB, low, role=Role.MEASUREMENT, unit="mm",
               caption=(f"Displacement s = {ft}{contact} − K0B0" if e else f"s = O{contact} − OB0",
                        f"位移 s = {ft}{contact} − K0B0" if e else f"位移 s = O{contact} − OB0"))
    sc.add("normal", line_through, A, B, style="construction",
           caption=(f"The normal at {contact} passes the centre A", f"{contact} 点法线过圆心 A"))
    al = sc.add("alpha", guide_pressure, A, B, UP, role=Role.MEASUREMENT, unit="deg",
                caption=(f"Pressure angle α between the normal A{contact} and the guide", f"压力角 α:法线 A{contact} 与导路所夹锐角"))
    sc.add("mark_alpha", _alpha_mark, B, A, O, al, follower == "roller", role=Role.ANNOTATION, style="angle")
    sc.add("dim_s", lambda b, v, lo: marks.Dimension(b - UP * v, b, "s", v, 0.35 * R), B, s, low,
           role=Role.ANNOTATION, style="dim", caption=("Dimension s from the lowest position", "标注位移 s"))
    answers = {n: n for n in ("r0", "r0_actual", "h", "rise_angle", "return_angle", "delta", "s", "alpha")}
    if g.get("omega") is not None:
        sc.add("v", velocity, A, B, sense, g["omega"], Ref("delta"), Ref("rise_angle"), role=Role.MEASUREMENT, unit="mm/s",
               caption=("Instant centre P: AB meets the line through O ⊥ the guide; v = ω·OP",
                        "瞬心 P:AB 与过 O 垂直于导路的直线之交点;v = ω·OP"))
        answers["v"] = "v"
        answers.update(_add_guide_speeds(sc, A, D, Rp, False, R, sense, g["omega"]))
    answers.update(_alpha_extremes(sc, O, A, pitch, B0, B1, ref0, e, sense, rise))
    if e:
        sc.add("offset_correct", offset_correct, e, sense, role=Role.MEASUREMENT, visible=False)
        answers["offset_correct"] = "offset_correct"
    points = {"O": "O", "A": "A", "B": "B", "B0": "B0", "B1": "B1"}
    return Construction(sc, answers, points)


def _alpha_mark(b: Point, a: Point, o: Point, value: float, roller: bool) -> marks.AngleMark:
    """The pressure angle α of a translating follower at B, between the guide and the normal AB: below B, between
    the guide's axis and the normal towards A, as before; but for a roller whose normal runs down towards O's side
    of the guide, above B, between the stem (B's velocity) and the normal beyond B (the cam's force on B). There,
    below B, the angle lies inside the disc, its profile crossing it a roller radius from B, and its value found
    room only on the profile (001-29 printed α=36.87° across it); above B only the stem and the guide's bearing are
    near (the bearing sits at 0.45 R, clear of the arc). A knife's profile leaves the angle below B at B, and a
    normal running down across the guide from O (001-27) leaves its value room beside the guide.

    >>> m = _alpha_mark(Point(25.0, 20.0), Point(-6.0, -12.0), Point(0.0, 0.0), 36.87, True)  # A on O's side
    >>> m.a - m.vertex, m.b - m.vertex
    (Point(x=0.0, y=1.0), Point(x=31.0, y=32.0))
    >>> m = _alpha_mark(Point(10.0, 50.0), Point(20.0, 0.0), Point(0.0, 0.0), 31.0, True)     # A across the guide
    >>> m.b
    Point(x=20.0, y=0.0)
    """
    up = b - a if (b - a).y >= 0.0 else a - b             # the normal's direction up from B
    above = roller and (a.x - b.x) * (o.x - b.x) > 0.0
    return marks.AngleMark(b, b + UP, b + up if above else b - up, "α", value)


def _alpha_extremes(sc: Scene, O: Ref, A: Ref, pitch: Ref, B0: Ref, B1: Ref, ref0: Ref, e: float, sense: float,
                    rise: Ref) -> dict[str, str]:
    """The candidate positions of α's extremes: the ends of the strokes, the follower ⊥ OA (feet M± on line
    OA, or the lines through O ⊥ OA when e = 0), and the follower through A (α = 0); α and δ at each."""
    vals = [sc.add(f"alpha_B{k}", lambda a, b, seg: guide_pressure(a, b, seg.b - seg.a), A, Bk, Ref(f"K{k}B{k}"),
                   role=Role.MEASUREMENT, unit="deg", visible=False) for k, Bk in (("0", B0), ("1", B1))]
    rise_d, ret_d = [0.0, rise], [360.0, rise]
    for tag, sign in (("p", 1.0), ("m", -1.0)):
        if e:
            M = sc.add(f"M{tag}", foot_on_OA, O, A, e, sign, visible=False)
            ln = sc.add(f"perp{tag}", follower_line, M, e, visible=False)
        else:
            ln = sc.add(f"perp{tag}", lambda o, a, sg: Line(o, (a - o).perp() * sg), O, A, sign, visible=False)
        p0 = sc.add(f"perp{tag}_0", lambda l: l.point, ln, visible=False)
        p1 = sc.add(f"perp{tag}_1", lambda l: l.at(1.0), ln, visible=False)
        Bm = sc.add(f"Bperp{tag}", line_circle, ln, pitch, branch=Ahead(p0, p1), visible=False)
        vals.append(sc.add(f"alpha_perp{tag}", lambda a, b, l: guide_pressure(a, b, l.direction), A, Bm, ln,
                           role=Role.MEASUREMENT, unit="deg", visible=False))
        d = sc.add(f"delta_perp{tag}", turned_against, O, ref0, Ref(f"M{tag}") if e else Bm, sense, visible=False)
        rise_d.append(d)
        ret_d.append(d)
    if e:
        for i in range(2):                          # the tangents from A: left of O→A, then right
            N = sc.add(f"N{i}", tangent_foot, O, A, abs(e), -1.0 if i == 0 else 1.0, optional=True, visible=False)
            vals.append(sc.add(f"alpha_N{i}", lambda n: 0.0 if n is not None else 90.0, N, visible=False))
            d = sc.add(f"delta_N{i}", lambda o, k, n, sg: turned_against(o, k, n, sg) if n is not None else -1.0,
                       O, ref0, N, sense, visible=False)
            rise_d.append(d)
            ret_d.append(d)
    vt = sc.add("alpha_cands", lambda *v: tuple(v), *vals, visible=False)
    dt = sc.add("delta_cands", lambda *v: tuple(v), *rise_d, visible=False)
    drt = sc.add("delta_cands_ret", lambda *v: tuple(v), *ret_d, visible=False)
    rmax = sc.add("rise_max", largest_in, vt, dt, 0.0, rise, "max", visible=False)
    rmin = sc.add("rise_min", largest_in, vt, dt, 0.0, rise, "min", visible=False)
    tmax = sc.add("ret_max", largest_in, vt, drt, rise, 360.0, "max", visible=False)
    sc.add("alpha_max_rise", first, rmax, role=Role.MEASUREMENT, unit="deg",
           caption=("Largest rise pressure angle: at an end of the rise or with OA ⊥ the guide",
                    "推程最大压力角:在推程起止位置或 OA ⊥ 导路时"))
    sc.add("delta_alpha_max_rise", second, rmax, role=Role.MEASUREMENT, unit="deg", visible=False)
    sc.add("alpha_min_rise", first, rmin, role=Role.MEASUREMENT, unit="deg", visible=False)
    sc.add("alpha_max_return", first, tmax, role=Role.MEASUREMENT, unit="deg",
           caption=("Largest return pressure angle, likewise", "回程最大压力角(同理)"))
    sc.add("delta_alpha_max_return", second_in_turn, tmax, role=Role.MEASUREMENT, unit="deg", visible=False)
    sc.add("alpha_max", max, Ref("alpha_max_rise"), Ref("alpha_max_return"), role=Role.MEASUREMENT, unit="deg",
           visible=False)
    return {n: n for n in ("alpha_max_rise", "delta_alpha_max_rise", "alpha_min_rise", "alpha_max_return",
                           "delta_alpha_max_return", "alpha_max")}


def face_over_turn(O: Point, F: Point, E: float) -> Segment:
    """The flat face through F (⊥ the vertical guide) as long as the contact's excursion over a turn: the contact
    lies straight above the disc's centre A, whose abscissa runs O.x ± OA (and the face reaches the axis at F)."""
    return Segment(Point(min(O.x - E, F.x), F.y), Point(max(O.x + E, F.x), F.y))


def _finish_flat(sc: Scene, g: Mapping[str, Any], O: Ref, A: Ref, D: Ref, axis: Ref, B0: Ref, B1: Ref,
                 sense: float) -> Construction:
    """The flat face: it touches the disc where the disc's radius is parallel to the guide (above A)."""
    R = g["R"]
    vA = sc.add("vA", Line, A, UP, style="construction",
                caption=("The line through A parallel to the guide", "过 A 作导路的平行线"))
    K = sc.add("K", line_circle, vA, Ref("disc"), branch=Upper(), role=Role.RESULT, style="joint", label="K",
               caption=("It meets the disc at K: the contact point", "交圆盘于接触点 K"))
    F = sc.add("F", lambda l1, l2: line_line(l1, l2)[0], axis, sc.add("face_line", Line, K, Point(1.0, 0.0), visible=False),
               style="point", label="F", caption=("The face through K ⊥ the guide meets the axis at F",
                                                  "过 K 作平底(⊥ 导路),交导路于 F"))
    sc.add("face_seg", face_over_turn, O, F, g["OA"], role=Role.RESULT, style="link",
           caption=("The face long enough for every contact of the turn: K stays straight above A, so it runs OA "
                    "either side of O", "平底长度覆盖一周中的所有接触点:K 始终在 A 的正上方,故在 O 两侧各移动 OA"))
    sc.add("stem", lambda f: segment(f, f + UP * (0.6 * R)), F, role=Role.RESULT, style="link", caption=("", ""))
    sc.add("guide_mark", lambda f: marks.bearing(f + UP * (0.4 * R), UP), F, role=Role.ANNOTATION, style="guide")
    rise = sc.add("rise_angle", turned_against, O, B0, B1, sense, role=Role.MEASUREMENT, unit="deg",
                  caption=("Rise angle ∠B0OB1 against ω (the face ⊥ OB0 lowest, ⊥ OB1 highest)",
                           "推程运动角 ∠B0OB1(逆 ω;平底 ⊥ OB0 最低,⊥ OB1 最高)"))
    sc.add("return_angle", complement_turn, rise, role=Role.MEASUREMENT, unit="deg", visible=False)
    r0 = Ref("r0")
    sc.add("h", lambda b1, b0: abs(b1) - abs(b0), B1, B0, role=Role.MEASUREMENT, unit="mm",
           caption=("h = OB1 − OB0", "行程 h = OB1 − OB0"))
    Oup = sc.add("O_up", lambda o: o + UP, O, visible=False)
    sc.add("delta", turned_against, O, B0, Oup, sense, role=Role.MEASUREMENT, unit="deg",
           caption=("δ = angle from OB0 to the guide's direction, against ω", "凸轮转角 δ:自 OB0 至导路方向(逆 ω)"))
    DF = sc.add("DF", length, D, F, visible=False, unit="mm")
    s = sc.add("s", difference, DF, r0, role=Role.MEASUREMENT, unit="mm",
               caption=("s = DF − r0", "位移 s = DF − r0"))
    sc.add("alpha", guide_pressure, A, K, UP, role=Role.MEASUREMENT, unit="deg",
                caption=("α between the normal KA and the guide: 0", "压力角 α(法线 KA 平行于导路)= 0"))
    sc.add("dim_s", lambda f, v: marks.Dimension(f - UP * v, f, "s", v, 0.35 * R), F, s,
           role=Role.ANNOTATION, style="dim", caption=("Dimension s", "标注位移 s"))
    answers = {n: n for n in ("r0", "r0_actual", "h", "rise_angle", "return_angle", "delta", "s", "alpha")}
    answers.update({"alpha_max_rise": "alpha", "alpha_max_return": "alpha", "alpha_min_rise": "alpha",
                    "alpha_max": "alpha"})
    if g.get("omega") is not None:
        sc.add("v", velocity, A, K, sense, g["omega"], Ref("delta"), Ref("rise_angle"), role=Role.MEASUREMENT, unit="mm/s",
               caption=("Instant centre P below A on the line through O ⊥ the guide; v = ω·OP",
                        "瞬心 P(法线与过 O 垂直导路之线的交点);v = ω·OP"))
        answers["v"] = "v"
        answers.update(_add_guide_speeds(sc, A, D, R, True, R, sense, g["omega"]))
    return Construction(sc, answers, {"O": "O", "A": "A", "K": "K", "F": "F"})


def _add_guide_speeds(sc: Scene, A: Ref, D: Ref, Rp: float, flat: bool, R: float, sense: float,
                      omega: float) -> dict[str, str]:
    """a at the drawn position and v_max, a_max over the turn, from the equivalent linkage's velocity,
    acceleration and jerk polygons (:mod:`.cam_eccentric_speeds`)."""
    args = (A, D, Rp, flat, R, sense, omega)
    sc.add("a", guide_accel, *args, role=Role.MEASUREMENT, unit="mm/s²",
           caption=("a from the acceleration polygon of the equivalent crank-slider O–A–B (AB = R + rr)",
                    "a:高副低代为曲柄滑块 O–A–B,作加速度多边形"))
    sc.add("v_max", guide_v_max, *args, role=Role.MEASUREMENT, unit="mm/s",
           caption=("vmax over the turn: the velocity polygon where a = 0", "vmax:整周速度多边形,取 a = 0 处"))
    sc.add("a_max", guide_a_max, *args, role=Role.MEASUREMENT, unit="mm/s²",
           caption=("amax over the turn: where the jerk is 0", "整周最大加速度 amax:取跃度为 0 处"))
    return {"a": "a", "v_max": "v_max", "a_max": "a_max"}


def _mark_arm_angles(sc: Scene, O: Ref, Q: Ref, B: Ref, A: Ref, Qs: list, Bs: tuple, p0: Ref, L: float,
                     moved: bool) -> None:
    """The angles 001-31 asks for, marked where they are measured: ψ0 = ∠OQ0B0 at the lowest position,
    ψ0 + ψmax = ∠OQ1B1 at the highest, ψ0 + ψ = ∠OQB at the drawn one (when ψ ≠ 0, else Q is Q0), and α at B
    between the normal BA and B's velocity (⊥ QB)."""
    for k, (Qk, Bk) in enumerate(zip(Qs, Bs)):
        sc.add(f"Q{k}O", segment, Qk, O, style="ghost", caption=("", ""))
    add_angle_mark(sc, "mark_psi0", Qs[0], O, Bs[0], "ψ0", p0)
    sc.add("psi_high", arm_angle, Qs[1], O, Bs[1], visible=False)
    add_angle_mark(sc, "mark_psi_high", Qs[1], O, Bs[1], "ψ0+ψmax", Ref("psi_high"))
    if moved:
        sc.add("QO", segment, Q, O, style="ghost", caption=("", ""))
        add_angle_mark(sc, "mark_psi_now", Q, O, B, "ψ0+ψ", Ref("psi_now"))
    sc.add("normal_BA", segment, B, A, style="path",
           caption=("The normal at the contact runs through the disc's centre A", "接触点公法线过圆盘中心 A"))
    V = sc.add("v_B_end", velocity_end, B, Q, A, 0.3 * L, visible=False)
    sc.add("v_B", segment, B, V, style="ghost", caption=("", ""))
    add_angle_mark(sc, "mark_alpha", B, A, V, "α", Ref("alpha"))


def _construct_oscillating(g: Mapping[str, Any]) -> Construction:
    """The oscillating roller (or knife) follower."""
    R, E, a, L = g["R"], g["OA"], g["a"], g["L"]
    rr = g.get("rr") or 0.0
    sense = 1.0 if g.get("rotation", "ccw") == "ccw" else -1.0
    left = g.get("arm", "left") == "left"
    Rp = R + rr
    st = _state(g)
    sc = Scene("Eccentric-circle cam, oscillating follower")
    O = add_pivot(sc, "O", Point(0.0, 0.0), ("Rotation centre O of the cam", "凸轮回转中心 O"))
    add_rotation(sc, O, sense)
    Q = add_pivot(sc, "Q", Point(0.0, a), (f"Arm pivot Q at a = {a:g} above O", f"摆杆回转中心 Q,OQ = a = {a:g}"))
    A = sc.given("A", _osc_A(E, Rp, a, L, left, sense, st, g.get(st) if st else 0.0, g.get("turn") or 0.0),
                 style="joint", caption=(f"Disc centre A at OA = {E:g} from O", f"圆盘中心 A,OA = {E:g}"))
    sc.add("OA_seg", segment, O, A, role=Role.RESULT, style="link", caption=("", ""))
    sc.add("disc", circle, A, R, role=Role.RESULT, style="link",
           caption=(f"The cam: the circle about A with radius R = {R:g}", f"凸轮:以 A 为圆心、R = {R:g} 的圆"))
    pitch = sc.add("pitch", circle, A, Rp, style="path", caption=(f"Pitch circle about A, R + rr = {Rp:g}",
                                                                  f"理论廓线:以 A 为圆心、R + rr = {Rp:g} 的圆")) \
        if rr else Ref("disc")
    armc = sc.add("arm_circle", circle, Q, L, style="construction",
                  caption=(f"Arc about Q with radius L = {L:g}", f"以 Q 为圆心、L = {L:g} 为半径作弧"))
    side = RightOf if left else LeftOf
    B = sc.add("B", circle_circle, armc, pitch, branch=side(Q, A), role=Role.RESULT, style="joint", label="B",
               caption=("It meets the pitch circle at the roller centre B", "交理论廓线于滚子中心 B"))
    sc.add("arm", segment, Q, B, role=Role.RESULT, style="link", caption=("", ""))
    if rr:
        sc.add("roller", circle, B, rr, role=Role.RESULT, style="link", caption=("", ""))
    B0, B1 = add_base_circle(sc, O, A, pitch, bool(rr))
    kq = sc.add("pivot_circle", circle, O, a, style="construction",
                caption=(f"Circle about O through Q (radius a = {a:g}): the inverted pivot's path",
                         f"以 O 为圆心、a = {a:g} 为半径作圆(反转后摆杆中心轨迹)"))
    rule = LeftOf if left else RightOf
    Qs = []
    for k, Bk in (("0", B0), ("1", B1)):
        c = sc.add(f"kL{k}", circle, Bk, L, visible=False)
        Qk = sc.add(f"Q{k}", circle_circle, kq, c, branch=rule(Bk, A), style="point", label=f"Q{k}",
                    caption=(f"Arc about B{k} with radius L meets it at Q{k}: the arm's {'lowest' if k == '0' else 'highest'} position",
                             f"以 B{k} 为圆心、L 为半径作弧交之于 Q{k}:摆杆{'最低' if k == '0' else '最高'}位置"))
        sc.add(f"Q{k}B{k}", segment, Qk, Bk, style="ghost", caption=("", ""))
        Qs.append(Qk)
    p0 = sc.add("psi0", arm_angle, Qs[0], O, B0, role=Role.MEASUREMENT, unit="deg",
                caption=("Initial arm angle ψ0 = ∠OQ0B0", "初始位置角 ψ0 = ∠OQ0B0"))
    p1 = sc.add("psi1", arm_angle, Qs[1], O, B1, visible=False)
    sc.add("psi_max", difference, p1, p0, role=Role.MEASUREMENT, unit="deg",
           caption=("Angular stroke ψmax = ∠OQ1B1 − ψ0", "最大摆角 ψmax = ∠OQ1B1 − ψ0"))
    rise = sc.add("rise_angle", turned_against, O, Qs[0], Qs[1], sense, role=Role.MEASUREMENT, unit="deg",
                  caption=("Rise angle ∠Q0OQ1 against ω", "推程运动角 ∠Q0OQ1(逆 ω)"))
    sc.add("return_angle", complement_turn, rise, role=Role.MEASUREMENT, unit="deg", visible=False)
    sc.add("delta", turned_against, O, Qs[0], Q, sense, role=Role.MEASUREMENT, unit="deg",
           caption=("δ = ∠Q0OQ against ω", "凸轮转角 δ = ∠Q0OQ(逆 ω)"))
    pq = sc.add("psi_now", arm_angle, Q, O, B, visible=False)
    sc.add("psi", difference, pq, p0, role=Role.MEASUREMENT, unit="deg",
           caption=("Swing ψ = ∠OQB − ψ0", "摆角 ψ = ∠OQB − ψ0"))
    al = sc.add("alpha", arm_pressure, A, B, Q, role=Role.MEASUREMENT, unit="deg",
                caption=("α between the normal AB and B's velocity (⊥ QB)", "压力角 α:法线 AB 与 B 点速度(⊥ QB)所夹锐角"))
    if sc.drawing:
        moved = bool(st and g.get(st)) or bool(g.get("turn"))      # not at the lowest position: Q ≠ Q0
        _mark_arm_angles(sc, O, Q, B, A, Qs, (B0, B1), p0, L, moved)
    for part in ("rise", "return"):
        sc.add(f"alpha_max_{part}", _osc_alpha_max, Qs[0], A, O, B0, L, Rp, left, sense, rise, part,
               role=Role.MEASUREMENT, unit="deg",
               caption=(f"Largest {part} pressure angle, replaying the inversion over the {part}",
                        f"{'推' if part == 'rise' else '回'}程最大压力角(反转逐点作图)"))
    sc.add("alpha_max", max, Ref("alpha_max_rise"), Ref("alpha_max_return"), role=Role.MEASUREMENT, unit="deg",
           visible=False)
    names = ["r0", "r0_actual", "psi0", "psi_max", "rise_angle", "return_angle", "alpha_max_rise",
             "alpha_max_return", "alpha_max", "delta", "psi", "alpha"]
    if g.get("omega") is not None:
        args = (A, Q, L, Rp, left, sense, g["omega"])
        if sc.drawing:
            nAB = sc.add("normal_AB", line_through, A, B, style="construction",
                         caption=("The normal at the contact: the line AB", "接触点公法线:直线 AB"))
            lOQ = sc.add("line_OQ", line_through, O, Q, style="construction", caption=("", ""))
            sc.add("P", _meeting, nAB, lOQ, style="point", label="P", optional=True,
                   caption=("…meets the line of centres OQ at the instant centre P", "交中心线 OQ 于瞬心 P"))
        sc.add("omega2", arm_omega2, *args, role=Role.MEASUREMENT, unit="rad/s",
               caption=("The normal AB meets OQ at the instant centre P: ω2 = ω·OP/QP",
                        "法线 AB 交 OQ 于瞬心 P:ω2 = ω·OP/QP"))
        sc.add("epsilon2", arm_epsilon2, *args, role=Role.MEASUREMENT, unit="rad/s²",
               caption=("ε2: the acceleration polygon of the equivalent four-bar O–A–B–Q",
                        "ε2:高副低代为四杆机构 O–A–B–Q,作加速度多边形"))
        sc.add("omega2_max", arm_omega2_max, *args, role=Role.MEASUREMENT, unit="rad/s",
               caption=("ω2,max: the velocity polygon where ε2 = 0", "ω2,max:取 ε2 = 0 处"))
        sc.add("epsilon2_max", arm_epsilon2_max, *args, role=Role.MEASUREMENT, unit="rad/s²",
               caption=("ε2,max: where dε2/dt = 0", "ε2,max:取 dε2/dt = 0 处"))
        names += ["omega2", "epsilon2", "omega2_max", "epsilon2_max"]
    return Construction(sc, {n: n for n in names}, {"O": "O", "Q": "Q", "A": "A", "B": "B", "B0": "B0", "B1": "B1"})


def _meeting(l1: Line, l2: Line) -> Point | None:
    """Where two lines meet, None when they are parallel (the instant centre at infinity)."""
    try:
        pts = line_line(l1, l2)
    except GeomconError:
        return None
    return pts[0] if pts else None


def _osc_A(E: float, Rp: float, a: float, L: float, left: bool, sense: float, st: str | None, value: float,
           turn: float) -> Point:
    """A at the state: given directly, or the lowest position (B0 where the arm circle meets the base circle
    on the arm's side, A on B0O extended) turned by δ."""
    O = Point(0.0, 0.0)
    if st == "A_angle":
        A = Point(E * math.cos(math.radians(value)), E * math.sin(math.radians(value)))
    else:
        Q = Point(0.0, a)
        B0 = (Leftmost() if left else Rightmost()).choose(circle_circle(circle(O, Rp - E), circle(Q, L)))
        A = O + (O - B0).unit() * E
        if st == "delta":
            A = rotate(A, O, sense * math.radians(value))
    return rotate(A, O, sense * math.radians(turn))


def _osc_alpha_max(Q0: Point, A: Point, O: Point, B0: Point, L: float, Rp: float, left: bool, sense: float,
                   rise: float, part: str) -> float:
    """The largest α over a stroke: the pivot turned back by δ about O (inversion), B where its arc meets
    the pitch circle, α measured; maximised over δ."""
    arm = osc_arm(Q0, A, O, L, Rp, left, sense)
    lo, hi = (0.0, math.radians(rise)) if part == "rise" else (math.radians(rise), 2 * math.pi)
    # 720 samples a turn (the stroke's share of them), peaks refined by Brent
    return maximise(arm.alpha, [(lo, hi)], dense=720, g1=arm.alpha1, turn=2 * math.pi).value


def osc_arm(Q0: Point, A: Point, O: Point, L: float, Rp: float, left: bool, sense: float) -> ArmReplay:
    """The replay of the inversion on floats and arrays (:class:`~geomcon.cam.arm_replay.ArmReplay`, the same
    bits), with the geometry's own replay (the pivot turned back by δ about O, B where its arc meets the
    pitch circle on the arm's side, α measured) where it steps aside."""
    side = RightOf if left else LeftOf
    kp = circle(A, Rp)

    def alpha_at(d: float) -> float:
        Qd = rotate(Q0, O, -sense * d)
        B = side(Qd, A).choose(circle_circle(circle(Qd, L), kp))
        return arm_pressure(A, B, Qd)

    return ArmReplay(Q0.x, Q0.y, O.x, O.y, A.x, A.y, L, Rp, left, sense, alpha_at)


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """The closed forms of :mod:`geomcon.cam.eccentric`."""
    cam = twin_cam(g)
    out = cam.cycle()
    st = _state(g)
    kw = {st: g[st]} if st else {}
    phi = cam.phi_from(turn=g.get("turn") or 0.0, **kw)
    omega = g.get("omega")
    if isinstance(cam, Translating):
        out.update(cam.state(phi, omega))
        if omega is not None:
            out["a"] = translating_speeds(cam, phi, omega)[1]
            out["v_max"], out["a_max"] = translating_maxima(cam, omega)
    else:
        out.update(cam.state(phi))
        if omega is not None:
            out["omega2"], out["epsilon2"] = arm_speeds(cam, phi, omega)
            out["omega2_max"], out["epsilon2_max"] = arm_maxima(cam, omega)
    return [out]


RECIPE = Recipe(
    name="cam.eccentric",
    title="Eccentric-circle cam: r0, h, rise and return angles, s, α, v at a position",
    givens=GIVENS,
    answers=ANSWERS,
    points=("O", "A", "B", "B0", "B1"),
    construct=construct,
    analytic=analytic,
    validate=_validate,
)
