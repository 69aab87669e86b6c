"""Step operations and drawing helpers shared by the cam recipes (inversion method, 反转法).

Conventions: the cam centre O at the origin, the cam held still and the follower turned about O by −δ
(``inv = −1`` for a cam turning counter-clockwise, +1 clockwise: every inverted point is ``rotate(p, O,
inv·δ)``). Cam angles in degrees in the givens and the steps' captions, radians inside the profile
machinery (:mod:`geomcon.cam.profile`).

A cam recipe names the step holding its manufactured profile ``"profile"`` (a
:class:`~geomcon.cam.profile.Profile`): ``geomcon solve --profile-csv`` writes it.

Examples
--------
>>> from geomcon.cam.program import parse_program
>>> prog = parse_program([{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
...                       {"kind": "return", "angle": 90, "law": "uniform"}, {"kind": "dwell", "angle": 90}])
>>> division_angles(prog)
(15.0, 30.0, 45.0, 60.0, 75.0, 90.0, 105.0, 120.0, 180.0, 195.0, 210.0, 225.0, 240.0, 255.0, 270.0)
>>> inversion_sign("ccw"), inversion_sign("cw")
(-1.0, 1.0)
"""
from __future__ import annotations

import math
from typing import Any, Callable, Sequence

import numpy as np

from ..numeric import deg360
from ..cam.oscillating import ArmMotion, levels, segment_motion, segment_motion1
from ..cam.profile import (Extremum, LineFamily, PitchCurve, Profile, STRICT_TOLERANCE_REL, TOLERANCE_REL, numpy_is_libm,
                           backward_jumps)
from ..cam.diagrams import DiagramAxes
from ..cam.program import Program, parse_program
from ..errors import NotAMechanism, ProblemError
from ..geometry import Point, Polyline, Segment, circle, rotate, segment
from ..scene import Ref, Role, Scene
from ..scene import marks
from .base import Quantity
from .common import add_pivot

PROFILE_KEY = "profile"
"""The step key of a cam recipe's manufactured profile (a :class:`~geomcon.cam.profile.Profile`)."""
DRAW_POINTS = 1500
"""Largest number of points of a curve as drawn (the profile itself keeps all its samples)."""

ROTATION = Quantity("rotation", "choice", "sense of rotation of the cam", required=False, default="ccw",
                    minimum=None, choices=("ccw", "cw"))
PROGRAM = Quantity("program", "table[]", "motion program: [{kind = rise|dwell|return, angle = deg, law = …}, …] "
                   "over 360°", minimum=None)
AT = Quantity("at", "deg[]", "cam angles at which to report s and α", required=False, default=(), minimum=None,
              inclusive=True)
TOL = Quantity("tolerance", "mm", "largest chord error of the sampled profile (default 1e-5 of the cam's size: "
               "1e-3 mm on a 100 mm cam; a profile needing more than 1e6 points is refused)", required=False,
               default=None)
STRICT = Quantity("strict", "bool", f"strict profile tolerance ({STRICT_TOLERANCE_REL:g} of the cam's size: "
                  "1e-5 mm on a 100 mm cam)", required=False, default=False, minimum=None)

OMEGA = Quantity("omega", "rad/s", "angular speed of the cam, rad/s (gives the follower's velocity and acceleration); "
                 "0 < ω ≤ 1e4 rad/s (95 000 rpm)", required=False, maximum=1e4)
SPEED_ANSWERS = (
    Quantity("v", "mm/s[]", "with omega: follower velocity ω·ds/dδ at the cam angles of `at` (> 0 moving away from O)"),
    Quantity("a", "mm/s²[]", "with omega: follower acceleration ω²·d²s/dδ² at the cam angles of `at` (ω constant)"),
    Quantity("v_max", "mm/s", "with omega: largest |v| over the turn (exact: at a root of s″ or an end)"),
    Quantity("a_max", "mm/s²", "with omega: largest |a| over the turn (exact; one-sided at the ends of pieces; a "
             "uniform law's infinite accelerations at its rigid impacts are not counted)"),
)
"""The follower's speeds of a translating cam when ω is given (:mod:`geomcon.cam.kinematics`)."""
ARM_SPEED_ANSWERS = (
    Quantity("omega2", "rad/s[]", "with omega: the arm's angular velocity ω·dψ/dδ at the cam angles of `at` (> 0 "
             "swinging out, away from its lowest position)"),
    Quantity("epsilon2", "rad/s²[]", "with omega: the arm's angular acceleration ω²·d²ψ/dδ² at the cam angles of `at`"),
    Quantity("omega2_max", "rad/s", "with omega: largest |ω2| over the turn (exact)"),
    Quantity("epsilon2_max", "rad/s²", "with omega: largest |ε2| over the turn (exact; one-sided at the ends of pieces)"),
)
"""The arm's angular speeds of an oscillating cam when ω is given."""

PRESSURE_ANSWERS = (
    Quantity("alpha_max_rise", "deg", "largest pressure angle during the rise"),
    Quantity("delta_alpha_max_rise", "deg", "cam angle where it occurs"),
    Quantity("alpha_max_return", "deg", "largest pressure angle during the return"),
    Quantity("delta_alpha_max_return", "deg", "cam angle where it occurs"),
    Quantity("rho_min_pitch", "mm", "smallest radius of curvature of the convex parts of the pitch curve"),
)
"""The answers every inversion-drawn cam shares: the worst pressure angles of rise and return, where they occur,
and ρmin of the pitch curve."""


def profile_csv(scene: Scene, recipe: str) -> str:
    """The CSV text of a scene's manufactured profile (``x_mm,y_mm,delta_deg``); a scene without one raises
    :class:`~geomcon.errors.ProblemError`."""
    if PROFILE_KEY not in scene:
        raise ProblemError(f"recipe {recipe} has no cam profile to export (--profile-csv is for cam recipes)")
    return scene.value(PROFILE_KEY).csv()


def profile_tolerance(g, size: float) -> float:
    """The profile tolerance (mm) the givens ask for on a cam of ``size`` mm: ``strict`` wins over
    ``tolerance``; by default :data:`~geomcon.cam.profile.TOLERANCE_REL` of the size (every tolerance scales
    with the cam).

    >>> profile_tolerance({}, 100.0), profile_tolerance({"strict": True}, 100.0), profile_tolerance({"tolerance": 0.5}, 1.0)
    (0.001, 1e-05, 0.5)
    """
    if g.get("strict"):
        return STRICT_TOLERANCE_REL * size
    given = g.get("tolerance")
    return TOLERANCE_REL * size if given is None else float(given)


def inversion_sign(rotation: str) -> float:
    """−1 for a cam turning counter-clockwise (the follower is turned clockwise, by −δ), +1 for cw."""
    return -1.0 if rotation == "ccw" else 1.0


def division_angles(program: Program, max_step: float = 15.0) -> tuple[float, ...]:
    """The textbook's equal divisions: each rise and return cut into equal parts of at most ``max_step``
    degrees, dwells only at their ends; the cam angles (deg) of the division points after δ = 0, up to the
    start of the last dwell (or 360°)."""
    out: list[float] = []
    for seg in program.segments:
        n = 1 if seg.kind == "dwell" else max(1, int(math.ceil(seg.angle / max_step - 1e-9)))
        out += [seg.start + seg.angle * i / n for i in range(1, n + 1)]
    return tuple(round(d, 9) for d in out if d < 360.0 - 1e-9)


def require_full(program: Program) -> None:
    """Refuse a program that does not fill the turn (a cam needs all 360°)."""
    if not program.full:
        end = program.segments[-1].end
        raise NotAMechanism(f"program: the segment angles add up to {end:g}°; a cam profile needs 360° "
                            f"(add a dwell of {360.0 - end:g}°)")


def program_breaks(program: Program) -> tuple[float, ...]:
    """Where the follower's motion has a jump of s′ or s″, in radians (the breaks of the pitch curve): the
    segment boundaries and the middle of every parabolic segment (its acceleration changes sign there)."""
    cuts = [s.start for s in program.segments[1:]]
    cuts += [s.start + s.angle / 2 for s in program.segments if s.law is not None and s.law.name == "parabolic"]
    return tuple(sorted(math.radians(c) for c in cuts))


# ---------------------------------------------------------------------------------------------- step operations
def turned(p: Point, O: Point, inv: float, delta_deg: float) -> Point:
    """``p`` turned about O by inv·δ: a point of the follower in its inverted position."""
    return rotate(p, O, inv * math.radians(delta_deg))


def pitch_polyline(curve: PitchCurve, n: int = 720) -> Polyline:
    """The pitch curve drawn through ``n`` exact points."""
    d = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    x, y = curve.eval(d)[:2]
    return Polyline(tuple(map(Point, x.tolist(), y.tolist())), closed=True)      # floats, not numpy scalars


def profile_polyline(profile: Profile) -> Polyline:
    """The profile as drawn (at most :data:`DRAW_POINTS` of its points)."""
    step = max(1, len(profile.xy) // DRAW_POINTS)
    xy = profile.xy[::step]
    return Polyline(tuple(map(Point, xy[:, 0].tolist(), xy[:, 1].tolist())), closed=True)   # not row by row


def extremum_value(e: Extremum) -> float:
    """The value of an extremum (a measurement step)."""
    return e.value


def extremum_deg(e: Extremum) -> float:
    """The place of an extremum, in degrees of cam angle in [0°, 360°) (a return's end is 0°, not 360°)."""
    return deg360(e.delta_deg)


def minus(a: float, b: float) -> float:
    """a − b."""
    return a - b


def at_least(a: float, b: float) -> bool:
    """a ≥ b."""
    return a >= b


def positive(a: float) -> bool:
    """a > 0."""
    return a > 0.0


def lifted_tuple(fn: Callable[..., float], *args: Any) -> tuple[float, ...]:
    """``fn`` evaluated at each member of the last argument (a tuple): a list answer."""
    *fixed, xs = args
    return tuple(float(fn(*fixed, x)) for x in xs)


def pressure_mark(P: Point, normal: Point, velocity: Point, value: float, size: float,
                  symbol: str = "α") -> marks.AngleMark:
    """The pressure-angle mark at the contact P between the common normal and the follower's velocity
    (the normal's sense chosen so that the marked angle is the acute α), printed as ``symbol`` (αmax, α′max:
    what the answer it shows is called)."""
    n = normal.unit()
    if n.dot(velocity) < 0.0:
        n = -n
    return marks.AngleMark(P, P + n * size, P + velocity.unit() * size, symbol, value, None)


RENDERED_BAND = (0.6, 0.55, 0.5, 0.45, 0.4)
"""The radii (parts of the mark's ``size``) the renderer may draw a pressure-angle arc at: about 0.6·size, drawn
smaller to clear a point of the figure inside the angle (000-04…08's α′max: 0.49·size, 1.99 mm of paper off the base
circle where 0.6·size kept 2.46 mm)."""


def pressure_mark_clear(P: Point, normal: Point, velocity: Point, value: float, size: float, symbol: str,
                        centre: Point, r0: float, gap: float) -> marks.AngleMark:
    """:func:`pressure_mark`, its arc kept ``gap`` (model mm) off the base circle (``centre``, ``r0``): where the arc
    the renderer would draw (about 0.6·``size`` from P) runs along the base circle within ``gap`` — 200-06's α′max
    arc ran nearly tangent to it, 0.2 mm inside; 000-04's, shrunk by the renderer off a point, 1.99 mm of paper — it
    is drawn at the nearest radius from 0.6 to 1.4·``size`` that keeps ``gap`` off it all along (within the drawn
    normal and velocity lines), else at 0.5, 0.4 or 0.3·``size``; else as the renderer chooses.

    >>> B, n, v = Point(53.48, 7.0), Point(-17.78, -16.12), Point(-23.47, -5.01)        # 200-06's return
    >>> round(pressure_mark_clear(B, n, v, 30.15, 24.0, "α′max", Point(0.0, 0.0), 40.0, 4.0).radius, 1)
    26.4
    >>> pressure_mark_clear(B, n, v, 30.15, 24.0, "α′max", Point(0.0, 0.0), 20.0, 4.0).radius is None   # clear
    True
    """
    m = pressure_mark(P, normal, velocity, value, size, symbol)
    a0 = math.atan2(m.a.y - P.y, m.a.x - P.x)
    sweep = (math.atan2(m.b.y - P.y, m.b.x - P.x) - a0 + math.pi) % (2 * math.pi) - math.pi
    t = a0 + sweep * np.linspace(0.0, 1.0, 33)

    def clearance(rho: float) -> float:
        return float(np.min(np.abs(np.hypot(P.x + rho * np.cos(t) - centre.x, P.y + rho * np.sin(t) - centre.y) - r0)))
    if min(clearance(k * size) for k in RENDERED_BAND) >= gap:
        return m
    for k in (*(0.6 + 0.1 * i for i in range(9)), 0.5, 0.4, 0.3):         # larger first: a small arc may be clamped
        if clearance(k * size) >= gap:
            return marks.AngleMark(m.vertex, m.a, m.b, symbol, value, k * size)
    return m


def normal_segment(P: Point, normal: Point, size: float) -> Segment:
    """The common normal through P, ``size`` either side."""
    n = normal.unit() * size
    return Segment(P - n, P + n)


# ---------------------------------------------------------------------------------------------- drawing helpers
def add_cam_centre(sc: Scene, sense: float) -> Ref:
    """The cam centre O (a fixed pivot at the origin) and the arrow of its sense of rotation ω
    (``sense`` > 0: counter-clockwise)."""
    O = add_pivot(sc, "O", Point(0.0, 0.0), ("Cam centre O", "凸轮回转中心 O"))
    add_rotation(sc, O, sense)
    return O


def add_rotation(sc: Scene, O: Ref, sense: float, ground: bool = False) -> None:
    """The arrow ω of the cam's sense of rotation about O, drawn with O (drawing only); ``ground`` adds O's
    ground symbol (a centre found by the construction, not given by :func:`~.common.add_pivot`)."""
    if sc.drawing:
        sc.add("omega", marks.rotation, O, 1.0 if sense > 0 else -1.0, role=Role.ANNOTATION, style="angle")
        if ground:
            sc.add("O_ground", marks.ground, O, -math.pi / 2, role=Role.ANNOTATION, style="ground")


def add_base_circle(sc: Scene, O: Ref, r0: float, what: tuple[str, str] = ("pitch curve", "理论廓线")) -> Ref:
    """The base circle r0 about O."""
    return sc.add("base_circle", circle, O, r0, style="given", role=Role.GIVEN,
                  caption=(f"Base circle of the {what[0]}, r0 = {r0:g}", f"以 O 为圆心、r0 = {r0:g} 作{what[1]}的基圆"))


def add_division_labels(sc: Scene, key: str, points: Sequence[Ref], labels: Sequence[str], caption: tuple[str, str],
                        style: str = "point") -> None:
    """Label a row of points already built (the first step carries the caption)."""
    for i, (p, lab) in enumerate(zip(points, labels)):
        sc.add(f"{key}{i}", _same, p, style=style, label=lab, caption=caption if i == 0 else ("", ""))


def _same(p: Point) -> Point:
    return p


def add_motion_diagram(sc: Scene, program: Program, h: float, origin: Point, width: float, scale: float,
                       divisions: Sequence[float], *, symbol: str = "s", unit: str = "mm") -> None:
    """The s–δ diagram beside the cam, in model mm: δ axis ``width`` long for 360°, s drawn ``scale`` mm
    per unit of h (1 for a translating follower: the displacements carry over with the compasses), the
    curve, and the division lines 1, 2, … from the δ axis up to the curve. Drawing only: a lean scene (answers)
    does not get these steps (:attr:`~geomcon.scene.Scene.drawing`)."""
    if not sc.drawing:
        return
    per_deg = width / 360.0

    def at(d: float, s: float) -> Point:
        return Point(origin.x + d * per_deg, origin.y + s * scale)

    top = h * scale * 1.25
    sc.given("sd_axes", DiagramAxes(origin.x, origin.y, per_deg, scale, h, symbol, unit), visible=False)
    sc.add("sd_delta_axis", segment, origin, at(372.0, 0.0), style="given", role=Role.ANNOTATION,
           caption=(f"Displacement diagram {symbol}–δ: δ axis, 360° = {width:.4g} mm",     # on the cam's sheet or
                    f"作位移线图 {symbol}–δ:δ 轴,360° 对应 {width:.4g} mm"))            # the next: no "beside"
    sc.add("sd_s_axis", segment, origin, Point(origin.x, origin.y + top), style="given", role=Role.ANNOTATION)
    sc.given("sd_delta_label", at(372.0, 0.0), label="δ", visible=True, style="point")
    sc.given("sd_s_label", Point(origin.x, origin.y + top), label=f"{symbol} ({unit})" if unit else symbol, style="point")
    sc.add("sd_curve", diagram_curve, program, h, origin, per_deg, scale, style="link", role=Role.RESULT,
           caption=(f"Plot {symbol}(δ) of the motion program", f"按运动规律画出 {symbol}(δ) 曲线"))
    for i, dv in enumerate(divisions, 1):
        sv = program.motion1(h, dv)[0]
        foot = sc.given(f"sd_div{i}", at(dv, 0.0), label=str(i), style="tick-division")
        if abs(sv) * scale > 1e-9 * width:
            sc.add(f"sd_ord{i}", segment, foot, at(dv, sv), style="construction",
                   caption=("Divide the δ axis as the cam angle and erect the ordinates 1, 2, … (the displacements)",
                            "将 δ 轴按凸轮转角等分,作各分点的纵坐标 1, 2, …(即各位移)") if i == 1 else ("", ""))


def diagram_curve(program: Program, h: float, origin: Point, per_deg: float, scale: float) -> Polyline:
    """The s–δ curve of :func:`add_motion_diagram` through 721 points (every ½°), computed when it is drawn (an
    answer never needs it).

    >>> prog = parse_program([{"kind": "rise", "angle": 180, "law": "uniform"}, {"kind": "return", "angle": 180, "law": "uniform"}])
    >>> c = diagram_curve(prog, 10.0, Point(0.0, 0.0), 0.5, 2.0)
    >>> len(c.points), c.points[360].tuple()
    (721, (90.0, 20.0))
    """
    d = np.linspace(0.0, 360.0, 721)
    s = program.motion(h, d)[0]
    ox, oy = origin.x, origin.y
    return Polyline(tuple(Point(ox + a * per_deg, oy + b * scale) for a, b in zip(d.tolist(), s.tolist())))


def add_profile_steps(sc: Scene, make: Callable[..., Profile], args: tuple, caption: tuple[str, str],
                      style: str = "link") -> Ref:
    """The manufactured profile: a step :data:`PROFILE_KEY` holding the :class:`Profile` (computed only when
    drawn or exported) and a step drawing it."""
    prof = sc.add(PROFILE_KEY, make, *args, visible=False)
    sc.add("profile_curve", profile_polyline, prof, style=style, role=Role.RESULT, caption=caption)
    return prof


def add_roller_circles(sc: Scene, centres: Sequence[Ref], rr: float) -> None:
    """A few roller circles about pitch points (their inner envelope is the actual profile); drawing only."""
    if not sc.drawing:
        return
    for i, c in enumerate(centres):
        sc.add(f"roller{i}", circle, c, rr, style="path",
               caption=(f"Roller circles of radius rr = {rr:g} about points of the pitch curve",
                        f"以理论廓线上各点为圆心、rr = {rr:g} 为半径作一系列滚子圆") if i == 0 else ("", ""))


# ---------------------------------------------------------------------------------------------- arm followers
# (shared by cam.oscillating's roller/knife arm and its flat-faced arm)
def program_of(g: Mapping[str, Any]) -> Program:
    """The motion program of the givens, checked to fill the turn with a return."""
    prog = parse_program(g["program"])
    require_full(prog)
    if prog.ret is None:
        raise NotAMechanism("program: a cam needs a return segment (the arm must swing back)")
    return prog


def arm_division_angles(g: Mapping[str, Any], cam: ArmMotion) -> tuple[float, ...]:
    """The cam angles (deg) of the drawing's divisions: ``divisions`` equal parts of the rise and of the
    return when given, else the shared rule (parts of at most 15°, dwell ends)."""
    n = g.get("divisions")
    if n is None:
        return division_angles(cam.program)
    if n != int(n) or not 1 <= n <= 24:
        raise NotAMechanism(f"divisions must be a whole number from 1 to 24, got {n:g}")
    out = {seg.start + seg.angle * i / int(n) for seg in cam.program.segments if seg.kind != "dwell"
           for i in range(int(n) + 1)}
    return tuple(sorted(d for d in out if 0.0 < d < 360.0))


def laid_off(C: Point, A: Point, cam: ArmMotion, delta_deg: float) -> Point:
    """The pitch point: C (the arm's initial end in its inverted position) turned about A0′ by ψ(δ) in the
    arm's rise sense."""
    return rotate(C, A, cam.tau * math.radians(cam.program.motion1(cam.h, float(delta_deg))[0]))   # (motion's bits)


def speed_ratio(cam: ArmMotion, delta_deg: float, part: str | None = None) -> float:
    """k = εψ′(δ): the arm's angular velocity over the cam's, signed (same sense positive); with ``part``
    ("rise", "return") the value inside that segment (one-sided at its ends, where ψ′ may jump)."""
    if part is None:                        # (on floats: the bits of motion and segment_motion)
        return cam.eps * math.radians(cam.program.motion1(cam.h, float(delta_deg))[1])
    k = next(i for i, s in enumerate(cam.program.segments) if s.kind == part)
    seg = cam.program.segments[k]
    x = min(max((delta_deg - seg.start) / seg.angle, 0.0), 1.0)
    return cam.eps * segment_motion1(seg, levels(cam.program, cam.h)[k], cam.h, float(x))[2]


def arm_velocity(A: Point, B: Point, sense: int) -> Point:
    """The roller's velocity direction at B: perpendicular to the arm AB, turned the way the arm swings
    (``sense`` = +1 counter-clockwise, −1 clockwise)."""
    return (B - A).perp() * sense


def velocity_segment(B: Point, v: Point, size: float) -> Segment:
    """The roller's direction of motion drawn from B, ``size`` long."""
    return Segment(B, B + v.unit() * size)


def pick(pair: tuple[float, float], i: int) -> float:
    """One member of a pair."""
    return pair[i]


def place_deg(worst: tuple[float, float]) -> float:
    """The cam angle (deg) of a (value, δ) worst position, in [0°, 360°): a return's end is 0°, not 360°."""
    return deg360(worst[1])


def collect(*values: Any) -> tuple[float, ...]:
    """The values as a tuple (a list answer)."""
    return tuple(float(v) for v in values)


def negate(b: bool) -> bool:
    """not b."""
    return not b


def flat_convex(fam: LineFamily, rho: Extremum) -> bool:
    """The flat face's profile is convex: ρ > 0 everywhere and the contact never jumps back."""
    return rho.value > 0.0 and not backward_jumps(fam)


class ArmInversion:
    """Adds the steps of one inverted position: pivot A0′, initial arm end C, pitch point B."""

    def __init__(self, sc: Scene, cam: ArmMotion, O: Ref, A0: Ref, B0: Ref) -> None:
        self.sc, self.cam, self.O, self.A0, self.B0 = sc, cam, O, A0, B0

    def position(self, key: str, delta: Any, *, label: str | None = None, caption: tuple[str, str] = ("", ""),
                 visible: bool = True) -> tuple[Ref, Ref, Ref]:
        """(A0′, C, B) at cam angle ``delta`` (deg, a number or a reference)."""
        sc, inv = self.sc, -float(self.cam.sigma)
        A = sc.add(f"A_{key}", turned, self.A0, self.O, inv, delta, label=label, style="point", caption=caption,
                   visible=visible)
        C = sc.add(f"C_{key}", turned, self.B0, self.O, inv, delta, style="point", visible=visible)
        B = sc.add(f"B_{key}", laid_off, C, A, self.cam, delta, style="point", visible=visible)
        return A, C, B


# ---------------------------------------------------------------------------------------------- arms at many angles
def _turn(x: np.ndarray, y: np.ndarray, cx, cy, ang: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Points (x, y) turned about (cx, cy) by ``ang`` radians: :func:`~geomcon.geometry.rotate`, elementwise."""
    c, s = np.cos(ang), np.sin(ang)
    vx, vy = x - cx, y - cy
    return cx + c * vx - s * vy, cy + s * vx + c * vy


def arm_positions(A0: Point, B0: Point, cam: ArmMotion, at: tuple[float, ...]) -> dict[str, np.ndarray]:
    """The inversion at every cam angle of ``at`` (deg) at once, as :class:`ArmInversion` builds one position:
    the pivot A0 and the arm's lowest end B0 turned about O by −σδ (A0′, C), then C turned about A0′ by ψ(δ)
    in the arm's rise sense (B); with ψ, ψ′ (rad) and the measured ∠CA0′B (deg). One step holds all the
    angles, so a list of 1000 angles costs one evaluation, not thousands of steps.

    Examples
    --------
    >>> from geomcon.cam.oscillating import OscillatingCam
    >>> prog = parse_program([{"kind": "rise", "angle": 180, "law": "uniform"}, {"kind": "return", "angle": 180, "law": "uniform"}])
    >>> cam = OscillatingCam(100.0, 80.0, 40.0, 20.0, prog)
    >>> pos = arm_positions(Point(0.0, 100.0), Point(-30.0, 20.0), cam, (90.0,))
    >>> round(float(pos["psi"][0]), 9), [round(float(pos[k][0]), 9) for k in ("Ax", "Ay")]
    (10.0, [100.0, 0.0])
    """
    if len(at) <= SCALAR_AT and numpy_is_libm("arctan2"):   # a few angles: one by one on floats
        rows = [_arm_position1(A0, B0, cam, float(x)) for x in at]
        return {k: np.array([r[i] for r in rows], dtype=float) for i, k in enumerate(_ARM_KEYS)}
    d = np.asarray(at, dtype=float)
    turn = -float(cam.sigma) * np.radians(d)
    ax, ay = _turn(np.full_like(d, A0.x), np.full_like(d, A0.y), 0.0, 0.0, turn)
    cx, cy = _turn(np.full_like(d, B0.x), np.full_like(d, B0.y), 0.0, 0.0, turn)
    m = cam.motion(d)
    bx, by = _turn(cx, cy, ax, ay, cam.tau * m.psi)
    ux, uy, vx, vy = cx - ax, cy - ay, bx - ax, by - ay
    psi = np.degrees(np.arctan2(np.abs(ux * vy - uy * vx), ux * vx + uy * vy))
    return {"Ax": ax, "Ay": ay, "Cx": cx, "Cy": cy, "Bx": bx, "By": by, "psi": psi, "d1": m.d1}


SCALAR_AT = 16
"""Up to this many cam angles of ``at``, the positions are computed one by one on floats (a numpy call on a
few numbers costs more than the arithmetic)."""
_ARM_KEYS = ("Ax", "Ay", "Cx", "Cy", "Bx", "By", "psi", "d1")


def _turn1(x: float, y: float, cx: float, cy: float, ang: float) -> tuple[float, float]:
    """:func:`_turn` of one point, on floats (the same operations)."""
    c, s = math.cos(ang), math.sin(ang)
    vx, vy = x - cx, y - cy
    return cx + c * vx - s * vy, cy + s * vx + c * vy


def _arm_position1(A0: Point, B0: Point, cam: ArmMotion, d: float) -> tuple[float, ...]:
    """One position of :func:`arm_positions` on floats, by its operations in their order (the same bits where
    numpy's arctan2 is the C library's), as (Ax, Ay, Cx, Cy, Bx, By, ψ, ψ′)."""
    turn = -float(cam.sigma) * math.radians(d)
    ax, ay = _turn1(A0.x, A0.y, 0.0, 0.0, turn)
    cx, cy = _turn1(B0.x, B0.y, 0.0, 0.0, turn)
    s, v, _ = cam.program.motion1(cam.h, d)
    bx, by = _turn1(cx, cy, ax, ay, cam.tau * math.radians(s))
    ux, uy, vx, vy = cx - ax, cy - ay, bx - ax, by - ay
    psi = math.degrees(math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy))
    return ax, ay, cx, cy, bx, by, psi, math.radians(v)


def arm_pressures(pos: dict[str, np.ndarray], eps: int) -> np.ndarray:
    """α (deg) at every position: :func:`arm_pressure_deg` elementwise — the normal (O − A0′) + (A0′ − B)(1 − k),
    k = εψ′, through the relative instant centre, against B's velocity ⊥ A0′B."""
    k = eps * pos["d1"]
    nx, ny = -pos["Ax"] + (pos["Ax"] - pos["Bx"]) * (1.0 - k), -pos["Ay"] + (pos["Ay"] - pos["By"]) * (1.0 - k)
    vx, vy = -(pos["By"] - pos["Ay"]), pos["Bx"] - pos["Ax"]
    return np.degrees(np.arctan2(np.abs(nx * vy - ny * vx), np.abs(nx * vx + ny * vy)))


def arm_contacts(pos: dict[str, np.ndarray], eps: int, curve: PitchCurve, rr: float) -> tuple[np.ndarray, np.ndarray]:
    """The roller's contact with the profile at every position: on the common normal through B (towards the
    relative instant centre), rr from B, on the side of the pitch curve's tangent where the cam body lies (left
    of the tangent for a curve going counter-clockwise round O)."""
    k = eps * pos["d1"]
    nx, ny = -pos["Ax"] + (pos["Ax"] - pos["Bx"]) * (1.0 - k), -pos["Ay"] + (pos["Ay"] - pos["By"]) * (1.0 - k)
    size = np.hypot(nx, ny)
    nx, ny = nx / size, ny / size
    d = np.radians(np.asarray(pos["delta"], dtype=float))
    if curve.fn1 is not None and d.size <= SCALAR_AT:     # a few angles: the tangents on floats (only a side is read)
        tx, ty = np.array([curve.fn1(x)[2:4] for x in d.tolist()], dtype=float).reshape(-1, 2).T
    else:
        tx, ty = curve.eval(d)[2:4]
    side = np.where(curve.orientation * (-ty * nx + tx * ny) >= 0.0, 1.0, -1.0)
    return pos["Bx"] + side * rr * nx, pos["By"] + side * rr * ny


def arm_at(A0: Point, B0: Point, cam: ArmMotion, at: tuple[float, ...]) -> dict[str, np.ndarray]:
    """:func:`arm_positions` with the cam angles kept (``delta``, deg)."""
    out = arm_positions(A0, B0, cam, at)
    out["delta"] = np.asarray(at, dtype=float)
    return out


def column(table: dict[str, np.ndarray], key: str) -> tuple[float, ...]:
    """One column of a table of arrays as a list answer."""
    return tuple(float(v) for v in table[key])


def add_speed_steps(sc: Scene, answers: dict[str, str], g, program: Program, h: float, *, angular: bool) -> None:
    """With ``omega`` given: the follower's speeds at ``at`` and their exact maxima over the turn
    (:func:`geomcon.cam.kinematics.speeds_at`, :func:`~geomcon.cam.kinematics.speed_maxima`): v, a, v_max,
    a_max of a translating follower, or ω2, ε2 and their maxima of an arm (``angular``, h in degrees)."""
    omega = g.get("omega")
    if omega is None:
        return
    from ..cam.kinematics import speed_maxima, speeds_at
    names = ("omega2", "epsilon2", "omega2_max", "epsilon2_max") if angular else ("v", "a", "v_max", "a_max")
    k = math.pi / 180.0 if angular else 1.0
    sc.add("speed_maxima", speed_maxima, program, h, float(omega), k, visible=False)
    for name, i in ((names[2], 0), (names[3], 2)):
        sc.add(name, pick, Ref("speed_maxima"), i, role=Role.MEASUREMENT, unit="", visible=False)
        answers[name] = name
    at = tuple(g.get("at") or ())
    if at:
        sc.add("speeds_at", speeds_at, program, h, float(omega), at, k, visible=False)
        for name, i in ((names[0], 0), (names[1], 1)):
            sc.add(name, pick, Ref("speeds_at"), i, role=Role.MEASUREMENT, unit="", visible=False)
            answers[name] = name
