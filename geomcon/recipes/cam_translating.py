"""``cam.translating``: a disc cam with a translating knife-edge, roller or flat-faced follower, drawn by the
inversion method (反转法).

Construction (O at the origin; the follower's axis vertical at x = e, moving up; δ = 0 is its lowest
position B0 on the base circle): the follower is turned about O by −δ (cam turning counter-clockwise; +δ
clockwise) to the textbook's equal divisions, its axis then tangent to the offset circle of radius |e|;
the displacement s(δ) is laid off along each inverted axis from the base circle (1′, 2′, …); the pitch
curve joins them (computed from the exact parametric form); the roller circles about it have the actual
profile as inner envelope (a flat face: the envelope of the face lines). The pressure angle is measured on
the pitch curve at its worst place (between the common normal and the follower's velocity), ρmin from the
exact derivatives. ``r0`` is the base circle of the pitch curve (knife, roller) or of the profile (flat
face, whose reference point is where its axis meets the face).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Mapping

import numpy as np

from ..numeric import deg360
from ..cam.profile import (Extremum, LineFamily, PitchCurve, contact_slope, corners, envelope, envelope1, envelope_rho_min,
                           flat_profile, frame_pressure_angle_slope, frame_pressure_angle_slope1, inverted, inverted1,
                           pressure_angle1,
                           inverted_relative, inverted_relative1, maximise, pressure_angle, rho_min, roller_profile, turn_of)
from ..cam.program import Program, parse_program
from ..cam.translating import TranslatingCam
from ..errors import NotAMechanism
from ..geometry import Point, Segment, circle, distance, segment
from ..scene import Ref, Role, Scene
from ..scene import marks
from .base import Construction, Quantity, Recipe
from ..analytic.cam_motion import follower_speeds
from .cam_common import (OMEGA, PRESSURE_ANSWERS, SPEED_ANSWERS, add_speed_steps, AT, PROGRAM, ROTATION, STRICT, TOL, add_base_circle, add_cam_centre, add_motion_diagram,
                         add_profile_steps, add_roller_circles, at_least, division_angles, extremum_deg, extremum_value,
                         flat_convex, negate, pick,
                         inversion_sign, minus, normal_segment, pitch_polyline, pressure_mark,
                         profile_tolerance, program_breaks, require_full, turned)

GIVENS = (
    Quantity("follower", "choice", "follower type", minimum=None, choices=("knife", "roller", "flat")),
    Quantity("r0", "mm", "base circle radius (of the pitch curve; of the profile for a flat face)"),
    Quantity("h", "mm", "stroke of the follower"),
    PROGRAM,
    Quantity("e", "mm", "offset: e > 0 puts the follower's axis right of O (follower moving up)", required=False,
             default=0.0, minimum=None),
    Quantity("rr", "mm", "roller radius (roller followers only)", required=False, default=None),
    ROTATION,
    AT,
    Quantity("alpha_allow", "deg", "allowed pressure angle (a warning when exceeded), 0 < α_allow ≤ 90°", required=False,
             default=None, maximum=90.0),
    TOL,
    STRICT,
    OMEGA,
)
ANSWERS = (
    Quantity("h", "mm", "stroke, measured between the lowest and highest inverted positions"),
    *PRESSURE_ANSWERS,
    Quantity("rho_min_actual", "mm", "of the actual profile: ρmin − rr (roller), min(r0 + s + s″) (flat); a knife "
             "edge's profile is the pitch curve: ρmin itself (its figure prints ρmin only)"),
    Quantity("undercut", "bool", "the profile cannot reproduce the motion (rr ≥ ρmin; flat face not convex); always "
             "false for a knife edge (no roller: its figure does not print it); a flat face's figure prints `convex` "
             "instead (the same condition)"),
    Quantity("convex", "bool", "flat face: r0 + s + s″ > 0 everywhere and no velocity drop"),
    Quantity("face_width_left", "mm", "flat face: reach of the contact left of the axis, max(e − k·s′)"),
    Quantity("face_width_right", "mm", "flat face: reach of the contact right of the axis, max(k·s′ − e)"),
    Quantity("face_width", "mm", "flat face: the face length the contact sweeps (left + right)"),
    Quantity("s", "mm[]", "displacement at the cam angles of `at`"),
    Quantity("alpha", "deg[]", "pressure angle at the cam angles of `at`"),
    *SPEED_ANSWERS,
)
RISE_WARN = 3.0
"""A warning when ρmin of the pitch curve is below this many roller radii."""


def _givens(g: Mapping[str, Any]) -> tuple[Program, float, float, float, float, str, str]:
    prog = parse_program(g["program"])
    return prog, float(g["h"]), float(g["r0"]), float(g.get("e") or 0.0), float(g.get("rr") or 0.0), \
        g.get("rotation", "ccw"), g["follower"]


def _validate(g: Mapping[str, Any]) -> list[str]:
    prog, h, r0, e, rr, rot, follower = _givens(g)
    require_full(prog)
    if prog.ret is None:
        raise NotAMechanism("program: a cam needs a return segment (the follower must come back down)")
    if follower != "roller" and g.get("rr") is not None:
        raise NotAMechanism(f"rr = {rr:g} is given for a {follower} follower: only a roller follower has a roller")
    if follower == "roller" and g.get("rr") is None:
        raise NotAMechanism("a roller follower needs rr (the roller radius)")
    if follower != "flat" and abs(e) >= r0:
        raise NotAMechanism(f"offset |e| = {abs(e):g} ≥ r0 = {r0:g}: the follower's axis misses the base circle")
    if rr >= r0:
        raise NotAMechanism(f"rr = {rr:g} ≥ r0 = {r0:g}: the actual profile's base circle r0 − rr would vanish")
    return []


def _advise(g: Mapping[str, Any]) -> list[str]:
    """The warnings that cost a search (ρmin, convex corners, α_max against the allowance): made only when the
    warnings are asked for."""
    prog, h, r0, e, rr, rot, follower = _givens(g)
    out = []
    flat = follower == "flat"
    cam = _twin_cam(g, TranslatingCam(prog, h, r0, 0.0 if flat else e, rot))   # the checks' searches, if made
    if follower == "roller":
        rho = cam.rho_min_pitch()
        if rr >= rho:
            out.append(f"undercut: rr = {rr:g} ≥ ρmin = {rho:.4g} of the pitch curve; the profile is trimmed and "
                       "the follower's motion is distorted there (增大基圆或减小滚子半径)")
        elif rho < RISE_WARN * rr:
            out.append(f"ρmin = {rho:.4g} of the pitch curve is below {RISE_WARN:g}·rr = {RISE_WARN * rr:g}: "
                       f"the actual profile's ρa = {rho - rr:.4g} is small (wear, contact stress)")
    if follower in ("knife", "roller"):
        curve = _pitch_curve(prog, h, e, math.sqrt(r0 * r0 - e * e), inversion_sign(rot))
        convex = [c for c in corners(curve) if c.turn > 0]
        if convex:
            at = ", ".join(f"{math.degrees(c.delta):g}°" for c in convex)
            out.append(f"the pitch curve has a convex corner at δ = {at} (velocity drop, rigid impact)"
                       + (": the roller cannot follow it exactly there" if follower == "roller" else ""))
    rho_flat = cam.flat_rho_min() if flat else math.inf
    if flat and not (rho_flat > 0.0 and not _s_drops(prog, h)):
        out.append(f"the flat face cannot follow the motion: min(r0 + s + s″) = {rho_flat:.4g}"
                   + (" and the velocity drops suddenly (s′ jumps down)" if _s_drops(prog, h) else "")
                   + "; the profile is trimmed (增大基圆 r0)")
    allow = g.get("alpha_allow")
    for part in ("rise", "return") if allow is not None and not flat else ():
        a, where = cam.alpha_max(part)
        if a > allow:
            out.append(f"α_max of the {part} = {a:.3f}° exceeds alpha_allow = {allow:g}° (at δ = {where:.3f}°)")
    return out


_LAST_TWIN: tuple = (None, None, None)
"""(the givens, a copy of them, the twin's cam) of the last :func:`analytic`: its searches are handed on to
the warnings of the same solve (:func:`_advise` on the same givens), so that a solve makes them once."""


def _twin_cam(g: Mapping[str, Any], cam: TranslatingCam) -> TranslatingCam:
    """The cam of the last :func:`analytic` when it was made for these very givens (the same object, unchanged)
    and is this cam; else ``cam``."""
    given, copy, twin = _LAST_TWIN
    if given is g and twin == cam and copy == dict(g):
        return twin
    return cam


def _s_drops(prog: Program, h: float) -> bool:
    return any(i.kind == "rigid" and i.jump < 0 for i in prog.impacts(h))


# ---------------------------------------------------------------------------------------------- the curves
def _pitch_curve(prog: Program, h: float, e: float, s0: float, inv: float) -> PitchCurve:
    """The pitch curve: the follower's point (e, s0 + s) turned about O by inv·δ, exact derivatives."""
    rotation = "ccw" if inv < 0 else "cw"
    last: list = [None, None]                  # the last angles and their motion: a slope asks for both forms

    def motion(d):                             # (s, s′, s″) and the turn's (cos, sin) at d, once
        if last[0] is not None and last[0].shape == d.shape and np.array_equal(last[0], d):
            return last[1]
        m = (prog.motion(h, d, radians=True), turn_of(d, rotation))
        last[0], last[1] = np.array(d, dtype=float), m
        return m

    def fn(d):
        (s, v, a), cs = motion(d)
        z = np.zeros_like(d)
        return inverted(d, rotation, (e + z, s0 + s), (z, v), (z, a), cs=cs)

    def relative(d):
        (_, v, a), cs = motion(d)
        z = np.zeros_like(d)
        return inverted_relative(d, rotation, (z, v), (z, a), cs=cs)

    motion1, ex = prog.motion1, e + 0.0                 # the scalar path (the same bits; e + 0 as e + zeros)
    last1 = [math.nan, (0.0, 0.0, 0.0)]

    def fn1(d):
        s, v, a = m = motion1(h, d, True)
        last1[0], last1[1] = d, m
        return inverted1(d, rotation, (ex, s0 + s), (0.0, v), (0.0, a))

    def relative1(d):
        _, v, a = last1[1] if d == last1[0] else motion1(h, d, True)
        return inverted_relative1(d, rotation, (0.0, v), (0.0, a))

    k = inv + 0.0                              # the inversion's k (−1 for a ccw cam) as in turn_of

    def axis_slope(d):                         # α′ against the axis, formed in the follower's frame (no turn)
        s, v, a = prog.motion(h, d, radians=True)
        px, py = -k * (s0 + s), v + k * e          # P′ = q′ + kJq, q = (e, s0 + s)
        return (px * a - py * (-k * v)) / (px * px + py * py) * np.sign(py * px)   # rel = q″ + kJq′ = (−kv, a)

    return _TranslatingPitch(fn, program_breaks(prog), relative, fn1, relative1, axis_slope=axis_slope)


_CURVES: dict = {}
"""(program, h, e, s0, inv and their signs) → the pitch curve :func:`shared_pitch_curve` made for them."""


def shared_pitch_curve(prog: Program, h: float, e: float, s0: float, inv: float) -> PitchCurve:
    """:func:`_pitch_curve`, one object per cam in a process: the pitch curve of equal program, h, e, s0 and
    turn is the same curve (a roller's radius is not in it), so the searches kept on it (:func:`rho_min`,
    :func:`curve_worst_alpha`) are made once — a worksheet's drafting ends rr ± δ and its nominal variant, a
    variant graded again. The curve is frozen and its searches pure; its closures' one-entry memos are keyed by
    their input. Signed zeros are told apart (e = −0.0 is not e = 0.0 to the bit)."""
    key = (prog, h, e, s0, inv, tuple(math.copysign(1.0, x) for x in (h, e, s0, inv)))
    curve = _CURVES.get(key)
    if curve is None:
        if len(_CURVES) >= 256:
            _CURVES.clear()
        curve = _CURVES[key] = _pitch_curve(prog, h, e, s0, inv)
    return curve


def curve_worst_alpha(curve: PitchCurve, inv: float, start_deg: float, end_deg: float) -> Extremum:
    """:func:`worst_alpha`, kept on the curve (a pure search of a frozen curve): made once per curve and range."""
    memo = curve.__dict__.setdefault("_worst_alpha", {})
    key = (inv, start_deg, end_deg)
    if key not in memo:
        memo[key] = worst_alpha(curve, inv, start_deg, end_deg)
    return memo[key]


@dataclass(frozen=True)
class _TranslatingPitch(PitchCurve):
    """A translating follower's pitch curve with ``axis_slope``: the pressure angle's slope against the
    follower's axis (:func:`~geomcon.cam.profile.frame_pressure_angle_slope`) formed in the follower's frame
    before any turn: P′ × rel and the signs of P′·u and P′ × u are the same in every frame, so the search's
    samples need no cos, sin or turned vectors (the refinement's scalar path keeps the turned form)."""

    axis_slope: Callable[[np.ndarray], np.ndarray] | None = None


def _face_family(prog: Program, h: float, r0: float, inv: float) -> LineFamily:
    """The flat face's lines: normal n = (cos φ, sin φ), φ = 90° + inv·δ, at distance p = r0 + s from O."""

    last: list = [None, None]                  # the last angles and their lines (a search asks twice)

    def fn(d):
        if last[0] is not None and last[0].shape == np.shape(d) and np.array_equal(last[0], d):
            return last[1]
        s, v, a = prog.motion(h, d, radians=True)
        z = np.zeros_like(d)
        out = math.pi / 2 + inv * d, inv + z, z, r0 + s, v, a
        last[0], last[1] = np.array(d, dtype=float), out
        return out

    motion1, half_pi, dphi = prog.motion1, math.pi / 2, inv + 0.0

    def fn1(d):                                # the same on one float (the same bits)
        s, v, a = motion1(h, d, True)
        return half_pi + inv * d, dphi, 0.0, r0 + s, v, a

    return LineFamily(fn, program_breaks(prog), fn1)


def _axis(inv: float, d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Unit direction of the follower's motion in its inverted position: (−sin(inv·δ), cos(inv·δ)), from the
    inversion's turn (:func:`~geomcon.cam.profile.turn_of`, k = inv: the same numbers, computed once)."""
    c, s = turn_of(d, "ccw" if inv < 0 else "cw")
    return -s, c


def worst_alpha(curve: PitchCurve, inv: float, start_deg: float, end_deg: float) -> Extremum:
    """The largest pressure angle (deg) over cam angles [start, end), measured on the pitch curve between
    the normal and the follower's velocity, and where (radians)."""

    def g(d):
        return np.degrees(pressure_angle(curve.eval(d), *_axis(inv, d)))

    def slope(d):                 # the axis turns with the follower's frame: its relative turn, no cancellation
        return frame_pressure_angle_slope(curve.eval(d), curve.relative(d), *_axis(inv, d))

    fast = getattr(curve, "axis_slope", None)

    fn1, rel1 = curve.fn1, curve.relative1

    def slope1(d):                # the same on one float (the refinement's scalar path)
        return frame_pressure_angle_slope1(fn1(d), rel1(d), -math.sin(inv * d), math.cos(inv * d))

    def g1(d):                    # g on one float (the candidates' values): the same bits
        return math.degrees(pressure_angle1(fn1(d), -math.sin(inv * d), math.cos(inv * d)))

    scalar = fn1 is not None and rel1 is not None
    return maximise(g, [(math.radians(start_deg), math.radians(end_deg))], slope=fast or slope,
                    slope1=slope1 if scalar else None, g1=g1 if scalar else None)


def alphas_at(curve: PitchCurve, inv: float, at: tuple[float, ...]) -> tuple[float, ...]:
    """Pressure angles (deg) at the cam angles ``at`` (deg), measured on the pitch curve."""
    d = np.radians(np.asarray(at, dtype=float))
    return tuple(float(x) for x in np.degrees(pressure_angle(curve.eval(d), *_axis(inv, d))))


def flat_alphas_at(fam: LineFamily, inv: float, at: tuple[float, ...]) -> tuple[float, ...]:
    """Pressure angles (deg) of the flat face at ``at``: between the face's normal and the velocity."""
    d = np.radians(np.asarray(at, dtype=float))
    phi = fam.eval(d)[0]
    ux, uy = _axis(inv, d)
    return tuple(float(x) for x in np.degrees(np.arctan2(np.abs(np.cos(phi) * uy - np.sin(phi) * ux),
                                                         np.abs(np.cos(phi) * ux + np.sin(phi) * uy))))


def displacements(O: Point, prog: Program, h: float, e: float, s0: float, inv: float, at: tuple[float, ...]) -> tuple[float, ...]:
    """s at ``at``: the distance from the base circle to the inverted follower point, along the inverted axis
    (the points (e, s0) and (e, s0 + s) and the axis (0, 1) turned about O by inv·δ, all angles at once)."""
    d = np.asarray(at, dtype=float)
    s = prog.motion(h, d)[0]
    c, sn = np.cos(inv * np.radians(d)), np.sin(inv * np.radians(d))
    cx, cy = c * e - sn * s0 + O.x, sn * e + c * s0 + O.y
    bx, by = c * e - sn * (s0 + s) + O.x, sn * e + c * (s0 + s) + O.y
    return tuple(float(v) for v in (bx - cx) * -sn + (by - cy) * c)


def stroke(C: Point, B: Point) -> float:
    """The stroke read off the inversion: |CB| at the end of the rise."""
    return distance(C, B)


def face_extents(fam: LineFamily, prog: Program, h: float, r0: float, e: float, inv: float) -> tuple[float, float]:
    """(left, right) reach of the contact along the face from the follower's axis, measured on the envelope."""

    def offset(d):
        if fam.fn1 is not None and d.size <= 16:    # a few candidates: one by one on the scalar path
            return np.array([offset1(x) for x in d.tolist()])
        x, y, _, _ = envelope(fam, d)
        s = prog.motion(h, d, radians=True)[0]
        c, sn = np.cos(inv * d), np.sin(inv * d)
        ax, ay = c * e - sn * (r0 + s), sn * e + c * (r0 + s)          # the axis on the face
        return (x - ax) * c + (y - ay) * sn                            # along the turned +x

    def offset1(d):                      # the same on one float (the same bits)
        x, y, _, _ = envelope1(fam.fn1(d))
        s = prog.motion1(h, d, True)[0]
        c, sn = math.cos(inv * d), math.sin(inv * d)
        ax, ay = c * e - sn * (r0 + s), sn * e + c * (r0 + s)
        return (x - ax) * c + (y - ay) * sn

    last: list = [None, None]

    def slope(d):                        # the axis's own place on the face is fixed: only λ moves, t = −x̂
        if last[0] is None or last[0].shape != d.shape or not np.array_equal(last[0], d):
            last[0], last[1] = np.array(d, dtype=float), -contact_slope(fam, d)   # both searches: once
        return last[1]

    def slope1(d):
        _, dphi, ddphi, _, dp, ddp = fam.fn1(d)
        return -((ddp * dphi - dp * ddphi) / (dphi * dphi))

    scalar = fam.fn1 is not None
    right = maximise(offset, fam.pieces(), slope=slope, slope1=slope1 if scalar else None).value
    left = maximise(lambda d: -offset(d), fam.pieces(), slope=lambda d: -slope(d),
                    slope1=(lambda d: -slope1(d)) if scalar else None).value
    return max(0.0, left), max(0.0, right)


def pick(pair: tuple[float, float], i: int) -> float:
    """One member of a pair."""
    return pair[i]


def worst_point(O: Point, prog: Program, h: float, e: float, s0: float, inv: float, w: Extremum) -> Point:
    """The inverted follower point at the worst cam angle."""
    return turned(Point(e, s0 + float(prog.motion(h, w.delta, radians=True)[0])), O, inv, w.delta_deg)


def worst_normal(curve: PitchCurve, w: Extremum) -> Point:
    """The pitch curve's normal at the worst cam angle."""
    c6 = curve.eval(np.array([w.delta]))
    return Point(-float(c6[3][0]), float(c6[2][0]))


def worst_axis(inv: float, w: Extremum) -> Point:
    """The follower's velocity direction at the worst cam angle."""
    ux, uy = _axis(inv, np.array([w.delta]))
    return Point(float(ux[0]), float(uy[0]))


def axis_segment(P: Point, u: Point, back: float, ahead: float) -> Segment:
    """The follower's axis through P: ``back`` behind, ``ahead`` in front."""
    return Segment(P - u * back, P + u * ahead)


def face_segment(B: Point, O: Point, inv: float, delta_deg: float, left: float, right: float) -> Segment:
    """The flat face through B in its inverted position, reaching ``left`` and ``right`` of the axis."""
    x = turned(Point(1.0, 0.0), Point(0.0, 0.0), inv, delta_deg)
    return Segment(B - x * left, B + x * right)


def contact_offset(fam: LineFamily, prog: Program, h: float, r0: float, e: float, inv: float, delta_deg: float) -> float:
    """Where the face touches the envelope at cam angle ``delta_deg``: its place along the turned +x from the
    follower's axis (negative: left of the axis)."""
    d = math.radians(delta_deg)
    x, y, _, _ = envelope(fam, np.array([d]))
    s = float(prog.motion(h, np.array([d]), radians=True)[0][0])
    c, sn = math.cos(inv * d), math.sin(inv * d)
    return float((x[0] - (c * e - sn * (r0 + s))) * c + (y[0] - (sn * e + c * (r0 + s))) * sn)


def inverted_face(B: Point, O: Point, fam: LineFamily, prog: Program, h: float, r0: float, e: float, inv: float,
                  delta_deg: float) -> Segment:
    """The face in its inverted position at ``delta_deg``: 0.3·r0 each side of the axis, and out past its contact
    by 0.1·r0 where the contact lies farther (200-02's faces 3′–6′ stopped short of the envelope touching them)."""
    c = contact_offset(fam, prog, h, r0, e, inv, delta_deg)
    return face_segment(B, O, inv, delta_deg, max(0.3 * r0, 0.1 * r0 - c), max(0.3 * r0, c + 0.1 * r0))


def _start_follower(sc: Scene, follower: str, e: float, s0: float, h: float, rr: float, r0: float, B0,
                    O=None, inv: float = 1.0, ext=None) -> None:
    """The follower in its lowest position, all its parts in one step: stem, guide, and its roller or its face
    (``ext``: the face's reach left and right of the axis, :func:`face_extents` — 200-02's face appeared at step
    13, eight steps after its stem)."""
    top = Point(e, s0 + h + 0.55 * r0 + rr)
    face = ("The follower in its lowest position, its face as wide as the contact reaches (lL left, lR right of "
            "the axis: measured on the profile at the end)", "从动件处于最低位置,平底宽度取接触点的最远位置"
            "(导路左侧 lL、右侧 lR,作出廓线后量得)")
    sc.add("stem", segment, B0 if follower != "roller" else Point(e, s0 + rr), top, style="link", role=Role.RESULT,
           caption=face if follower == "flat" else ("The follower in its lowest position", "从动件处于最低位置"))
    sc.add("guide", marks.bearing, Point(e, s0 + h + 0.35 * r0 + rr), Point(0.0, 1.0), role=Role.ANNOTATION,
           style="guide")                           # the stem's guide: one symbol for every cam
    if follower == "roller":
        sc.add("roller_start", circle, B0, rr, style="link", role=Role.RESULT)
    if follower == "flat":                  # drawn as wide as the Results will say (lL, lR), with its stem
        left = sc.add("face_left_drawn", pick, ext, 0, visible=False)
        right = sc.add("face_right_drawn", pick, ext, 1, visible=False)
        sc.add("face_start", face_segment, B0, O, inv, 0.0, left, right, style="link", role=Role.RESULT)


def construct(g: Mapping[str, Any]) -> Construction:
    """Build the inversion."""
    prog, h, r0, e, rr, rot, follower = _givens(g)
    require_full(prog)
    inv, flat = inversion_sign(rot), follower == "flat"
    s0 = r0 if flat else math.sqrt((r0 - e) * (r0 + e))
    tol = profile_tolerance(g, r0 + h + rr)
    at = tuple(g.get("at") or ())
    turn_en, turn_zh = ("clockwise", "顺时针") if inv < 0 else ("counter-clockwise", "逆时针")
    sc = Scene(f"Disc cam with a translating {follower} follower: inversion")
    O = add_cam_centre(sc, -inv)
    add_base_circle(sc, O, r0, ("profile", "实际廓线") if flat else ("pitch curve", "理论廓线"))
    if e != 0.0:
        sc.add("offset_circle", circle, O, abs(e), style="path",
               caption=(f"Offset circle of radius |e| = {abs(e):g}", f"以 O 为圆心、|e| = {abs(e):g} 为半径作偏距圆"))
    B0 = sc.given("B0", Point(e, s0), label="B0", style="joint",
                  caption=(f"B0: the follower's lowest point, on its axis x = e = {e:g}",
                           f"B0:从动件最低位置,导路 x = e = {e:g}"))
    drawing = sc.drawing                    # the follower, the s–δ diagram and the turned axes: drawing only
    if flat:                                # the face's family and reach: the follower's face is drawn with it
        fam = sc.given("faces", _face_family(prog, h, r0, inv), visible=False)
        ext = sc.add("face_ext", face_extents, fam, prog, h, r0, e, inv, visible=False)
    if drawing:
        _start_follower(sc, follower, e, s0, h, rr, r0, B0, O, inv, ext if flat else None)
    divs = division_angles(prog)
    R = r0 + h + rr
    add_motion_diagram(sc, prog, h, Point(R + 0.45 * R, s0), 3.0 * R, 1.0, divs)
    # the inversion: the follower's axis turned about O by −δ (ccw cam) to every division
    foot = Point(e, 0.0)
    for i, dv in enumerate(divs, 1) if drawing else ():
        K = sc.add(f"K{i}", turned, foot, O, inv, dv, visible=False)
        E = sc.add(f"E{i}", turned, Point(e, s0 + h + 0.12 * r0), O, inv, dv, visible=False)
        sc.add(f"L{i}", segment, K, E, style="construction",
               caption=(f"Turn the follower about O {turn_en} (−ω) to the divisions 1, 2, …: its axis stays tangent "
                        f"to the offset circle" if e else f"Turn the follower about O {turn_en} (−ω) to the divisions 1, 2, …",
                        f"按 −ω 方向({turn_zh})将从动件导路绕 O 转到各等分位置 1, 2, …" + ("(与偏距圆相切)" if e else "")) if i == 1 else ("", ""))
    Bs, Cs = [], []
    for i, dv in enumerate(divs, 1):
        s = prog.motion1(h, dv)[0]
        Cs.append(sc.add(f"C{i}", turned, B0, O, inv, dv, visible=False))
        Bs.append(sc.add(f"B{i}", turned, Point(e, s0 + s), O, inv, dv, style="division", label=f"{i}′",
                         caption=("Lay off the displacements s1, s2, … from the base circle along the inverted axes: "
                                  "points 1′, 2′, …", "在各反转导路上自基圆量取位移 s1, s2, …,得 1′, 2′, …") if i == 1 else ("", "")))
    rise_end = divs.index(round(prog.rise.end, 9)) if round(prog.rise.end, 9) in divs else None
    if rise_end is None:
        raise NotAMechanism("program: the rise must end before 360°")
    sc.add("h", stroke, Cs[rise_end], Bs[rise_end], role=Role.MEASUREMENT, unit="mm", visible=False)
    answers = {"h": "h", "rho_min_actual": "rho_min_actual", "undercut": "undercut",
               "alpha_max_rise": "alpha_max_rise", "alpha_max_return": "alpha_max_return"}
    ret = prog.ret
    if flat:
        rho = sc.add("rho_flat", envelope_rho_min, fam, visible=False)
        sc.add("rho_min_actual", extremum_value, rho, role=Role.MEASUREMENT, unit="mm", visible=False)
        sc.add("convex", flat_convex, fam, rho, visible=False)
        sc.add("undercut", negate, sc_ref("convex"), visible=False)
        sc.add("alpha_max_rise", float, 0.0, visible=False)
        sc.add("alpha_max_return", float, 0.0, visible=False)
        answers.update({k: k for k in ("face_width_left", "face_width_right", "face_width", "convex")})
        for i, (B, dv) in enumerate(zip(Bs, divs)):
            sc.add(f"F{i + 1}", inverted_face, B, O, fam, prog, h, r0, e, inv, dv, style="path",
                   caption=("Draw the face in each inverted position, perpendicular to the axis (long enough to "
                            "reach its contact with the envelope)",
                            "过 1′, 2′, … 作各反转位置的平底(垂直于导路,长度足以到达其与包络线的切点)")
                   if i == 0 else ("", ""))
        add_profile_steps(sc, flat_profile, (fam, tol),
                          ("Draw the envelope of the faces: the actual profile", "作各平底直线的包络线,即凸轮的实际廓线"))
        # measured once the envelope is drawn (the face drawn with its stem is that wide): shown at this step
        sc.add("face_width_left", pick, ext, 0, role=Role.MEASUREMENT, unit="mm",
               caption=("lL: the contact's farthest reach left of the axis, measured on the envelope",
                        "在包络线上量得接触点在导路左侧的最远距离 lL"))
        sc.add("face_width_right", pick, ext, 1, role=Role.MEASUREMENT, unit="mm",
               caption=("lR: its farthest reach right of the axis", "接触点在导路右侧的最远距离 lR"))
        sc.add("face_width", sum, ext, role=Role.MEASUREMENT, unit="mm",
               caption=("L = lL + lR: the face's width, as drawn in the lowest position",
                        "平底宽度 L = lL + lR(最低位置的平底按此宽度画出)"))
        if at:
            sc.add("s", displacements, O, prog, h, e, s0, inv, at, visible=False)
            sc.add("alpha", flat_alphas_at, fam, inv, at, visible=False)
    else:
        curve = sc.given("pitch", shared_pitch_curve(prog, h, e, s0, inv), visible=False)
        sc.add("pitch_curve", pitch_polyline, curve, style="frame" if follower == "roller" else "link",
               role=Role.RESULT,
               caption=("Join 1′, 2′, … by a smooth curve: the pitch curve" +
                        (" (the profile of a knife edge)" if follower == "knife" else ""),
                        "将 1′, 2′, … 连成光滑曲线,即理论廓线" + ("(尖顶从动件的实际廓线)" if follower == "knife" else "")))
        rho = sc.add("rho_pitch", rho_min, curve, visible=False)
        sc.add("rho_min_pitch", extremum_value, rho, role=Role.MEASUREMENT, unit="mm", visible=False)
        answers["rho_min_pitch"] = "rho_min_pitch"
        sc.add("rho_min_actual", minus, sc_ref("rho_min_pitch"), rr, role=Role.MEASUREMENT, unit="mm", visible=False)
        sc.add("undercut", at_least, rr, sc_ref("rho_min_pitch"), visible=False) if follower == "roller" else \
            sc.add("undercut", bool, False, visible=False)
        for part, seg in (("rise", prog.rise), ("return", ret)):
            if seg is None:
                sc.add(f"alpha_max_{part}", float, 0.0, visible=False)
                continue
            w = sc.add(f"worst_{part}", curve_worst_alpha, curve, inv, seg.start, seg.end, visible=False)
            sc.add(f"alpha_max_{part}", extremum_value, w, role=Role.MEASUREMENT, unit="deg", visible=False)
            sc.add(f"delta_alpha_max_{part}", extremum_deg, w, role=Role.MEASUREMENT, unit="deg", visible=False)
            answers[f"delta_alpha_max_{part}"] = f"delta_alpha_max_{part}"
        if follower == "roller":
            add_roller_circles(sc, Bs, rr)
            add_profile_steps(sc, roller_profile, (curve, rr, tol),
                              ("Draw the inner envelope of the roller circles: the actual profile",
                               "作滚子圆族的内包络线,即凸轮的实际廓线"))
        else:
            add_profile_steps(sc, roller_profile, (curve, 0.0, tol), ("", ""), style="link")
        _mark_worst(sc, O, prog, h, e, s0, inv, r0, curve)
        if at:
            sc.add("s", displacements, O, prog, h, e, s0, inv, at, visible=False)
            sc.add("alpha", alphas_at, curve, inv, at, visible=False)
    if at:
        answers.update({"s": "s", "alpha": "alpha"})
        sc.read_off("sd_curve", "s")         # read off the s–δ curve, not shown with the cam centre (issue 11)
        if drawing and len(at) == 1:
            _mark_asked(sc, O, prog, h, e, s0, inv, at[0], Point(R + 0.45 * R, s0), 3.0 * R / 360.0)
    add_speed_steps(sc, answers, g, prog, h, angular=False)
    return Construction(sc, answers, {"O": "O", "B0": "B0"})


def _mark_asked(sc: Scene, O, prog: Program, h: float, e: float, s0: float, inv: float, delta: float,
                origin: Point, per_deg: float) -> None:
    """The one position a problem asks about (001-24: s at δ = 100°) marked where a student looks for it: the
    follower's axis turned by −δ with s dimensioned from the base circle, and the ordinate at δ in the s–δ
    diagram, ticked with δ."""
    sv = prog.motion1(h, delta)[0]
    C = sc.add("ask_C", turned, Point(e, s0), O, inv, delta, visible=False)
    B = sc.add("ask_B", turned, Point(e, s0 + sv), O, inv, delta, style="joint", label=f"B({delta:g}°)",
               caption=(f"The asked position δ = {delta:g}°: the axis turned by −δ, s laid off from the base circle",
                        f"所求位置 δ = {delta:g}°:导路反转 −δ,自基圆量取位移 s"))
    value = sc.add("ask_s", pick, Ref("s"), 0, visible=False)
    sc.add("ask_dim", marks.dimension, C, B, "s", value, 0.12 * s0, role=Role.ANNOTATION, style="dim")
    foot = sc.given("sd_ask_foot", Point(origin.x + delta * per_deg, origin.y), label=f"{delta:g}°", style="tick")
    top = sc.given("sd_ask_top", Point(origin.x + delta * per_deg, origin.y + sv), visible=False)
    sc.add("sd_ask_ord", segment, foot, top, style="link-alt", role=Role.ANNOTATION,
           caption=(f"…and in the s–δ diagram the ordinate at δ = {delta:g}°", f"位移线图中 δ = {delta:g}° 处的纵坐标"))


def sc_ref(key: str) -> Ref:
    """A reference to an earlier step."""
    return Ref(key)


def _mark_worst(sc: Scene, O, prog: Program, h: float, e: float, s0: float, inv: float, r0: float, curve) -> None:
    """The largest pressure angle of the rise and of the return, each marked where it occurs (B1*, B2*; B* when
    there is one), with the name of the answer it shows (αmax, α′max): before, only the larger of the two was
    marked, as α, so that a worksheet asking for the rise's αmax showed the return's beside its box."""
    parts = [p for p in ("rise", "return") if f"worst_{p}" in sc]
    for part in parts:
        zh = "推程" if part == "rise" else "回程"
        name = "B*" if len(parts) == 1 else f"B{1 if part == 'rise' else 2}*"
        symbol = "αmax" if part == "rise" else "α′max"
        w = sc_ref(f"worst_{part}")
        P = sc.add(f"P_alpha_{part}", worst_point, O, prog, h, e, s0, inv, w, style="joint", label=name,
                   caption=(f"The {part}'s largest pressure angle {symbol}: position {name} (* marks the position of "
                            "the largest α)", f"{zh}最大压力角 {symbol} 的位置 {name}(* 标记压力角最大的位置)"))
        n = sc.add(f"n_alpha_{part}", worst_normal, curve, w, visible=False)
        u = sc.add(f"u_alpha_{part}", worst_axis, inv, w, visible=False)
        size = 0.35 * r0
        sc.add(f"normal_alpha_{part}", normal_segment, P, n, size, style="construction",
               caption=(f"Common normal n–n at {name}", f"过 {name} 作公法线 n–n"))
        sc.add(f"axis_alpha_{part}", axis_segment, P, u, 0.2 * r0, size, style="construction")
        sc.add(f"mark_alpha_{part}", pressure_mark, P, n, u, sc_ref(f"alpha_max_{part}"), 0.25 * r0, symbol,
               role=Role.ANNOTATION, style="angle")


def analytic(g: Mapping[str, Any]) -> list[dict[str, Any]]:
    """The closed forms of :mod:`geomcon.cam.translating`."""
    prog, h, r0, e, rr, rot, follower = _givens(g)
    at = tuple(g.get("at") or ())
    flat = follower == "flat"
    cam = TranslatingCam(prog, h, r0, 0.0 if flat else e, rot)
    global _LAST_TWIN
    _LAST_TWIN = (g, dict(g), cam)                 # its searches serve this solve's warnings too
    out: dict[str, Any] = {"h": h}
    if flat:
        left, right = TranslatingCam(prog, h, r0, e, rot).face_extent()
        rho = cam.flat_rho_min()
        convex = rho > 0.0 and not _s_drops(prog, h)
        out.update({"alpha_max_rise": 0.0, "alpha_max_return": 0.0, "rho_min_actual": rho, "convex": convex,
                    "undercut": not convex, "face_width_left": left, "face_width_right": right,
                    "face_width": left + right})
        if at:
            out["s"] = tuple(float(x) for x in prog.motion(h, np.asarray(at, dtype=float))[0])
            out["alpha"] = tuple(0.0 for _ in at)
        out.update(follower_speeds(g, angular=False))
        return [out]
    rho = cam.rho_min_pitch()
    out.update({"rho_min_pitch": rho, "rho_min_actual": rho - rr, "undercut": follower == "roller" and rr >= rho})
    for part, seg in (("rise", prog.rise), ("return", prog.ret)):
        if seg is None:
            out[f"alpha_max_{part}"] = 0.0
            continue
        a, d = cam.alpha_max(part)
        out[f"alpha_max_{part}"], out[f"delta_alpha_max_{part}"] = a, deg360(d)
    if at:
        out["s"] = tuple(float(x) for x in prog.motion(h, np.asarray(at, dtype=float))[0])
        out["alpha"] = tuple(float(x) for x in cam.alpha(np.asarray(at, dtype=float)))
    out.update(follower_speeds(g, angular=False))
    return [out]


RECIPE = Recipe(
    name="cam.translating",
    title="Disc cam, translating follower (knife, roller, flat face): profile by inversion, α, ρmin, undercut",
    givens=GIVENS,
    answers=ANSWERS,
    points=("O", "B0"),
    construct=construct,
    analytic=analytic,
    validate=_validate,
    advise=_advise,
)
