"""``cam.oscillating``: the disc cam of an oscillating (swinging-arm) follower by the inversion method (反转法).

Construction (conventions of :mod:`geomcon.cam.oscillating`: O at the origin, the arm's pivot A0 on +y at
OA0 = a, the roller on the ``arm`` side of A0→O): the arm's circle of radius L about A0 meets the base circle
at B0, the start of the rise, and ψ0 = ∠OA0B0. Holding the cam still, the frame turns by −δ about O: at the
textbook's equal divisions of the rise and the return the pivot comes to A0′ on the circle of radius a
(labelled 1′, 2′, …), the initial arm A0B0 to A0′C (C on the base circle), and the displacement ψ(δ) is laid
off at A0′ from A0′C by turning C about A0′ through ψ in the arm's rise sense: the pitch point B. Every point
is a rotation of a given one. The pitch curve joins them; for a roller the actual profile is the inner
envelope of the roller circles (:func:`geomcon.cam.profile.roller_profile`). The pressure angle is measured
at its worst positions: the contact normal passes through the relative instant centre P of cam and arm on
the line OA0′, A0′P = a/(1 − εψ′), and α is its angle with the roller's velocity (perpendicular to the arm).

The analytic twin uses the closed forms by separate routes: ψ0 by the half-angle formula, α and its worst
place from the complex form of the tangent, ρmin from the complex form of the curvature.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

import numpy as np

from ..numeric import deg360
from ..cam.oscillating import OscillatingCam, psi0_rad
from ..cam.profile import rho_min, roller_profile
from ..errors import NotAMechanism
from ..geometry import LeftOf, Point, RightOf, circle, circle_circle, segment
from ..scene import Ref, Role, Scene
from .base import Construction, Quantity, Recipe
from ..analytic.cam_motion import follower_speeds
from .cam_common import (ARM_SPEED_ANSWERS, OMEGA, PRESSURE_ANSWERS, add_speed_steps, AT, PROGRAM, ROTATION, STRICT, TOL, ArmInversion, add_base_circle,
                         add_cam_centre, add_motion_diagram, add_profile_steps, add_roller_circles, arm_division_angles,
                         arm_at, arm_contacts, arm_pressures, arm_velocity, at_least, collect, column,
                         extremum_value, laid_off, minus, normal_segment, pick, place_deg,
                         pitch_polyline, pressure_mark_clear, profile_tolerance, program_of, speed_ratio, turned,
                         velocity_segment)
from .cam_oscillating_flat import advise_flat, analytic_flat, construct_flat, validate_flat
from .common import add_angle_mark, add_bar, add_pivot, angle_deg

GIVENS = (
    Quantity("follower", "choice", "follower type", minimum=None, choices=("knife", "roller", "flat")),
    Quantity("a", "mm", "centre distance OA0 from the cam centre to the arm's pivot"),
    Quantity("L", "mm", "arm length A0B (pivot to roller centre or knife edge; not for a flat face)", required=False),
    Quantity("r0", "mm", "base-circle radius of the pitch curve (of the profile for a flat face)"),
    Quantity("h", "deg", "angular stroke ψmax of the arm"),
    PROGRAM,
    Quantity("rr", "mm", "roller radius (roller followers only)", required=False, default=None),
    Quantity("face_offset", "mm", "flat face: its distance from the pivot A0, towards the cam (0: through A0)",
             required=False, default=None, minimum=None),
    ROTATION,
    Quantity("arm", "choice", "side of the line A0→O the roller lies on (A0 drawn above O)", required=False,
             default="left", minimum=None, choices=("left", "right")),
    AT,
    Quantity("alpha_allow", "deg", "allowed pressure angle on the rise (a warning when exceeded), 0 < α ≤ 90°",
             required=False, maximum=90.0),
    Quantity("alpha_allow_return", "deg", "allowed pressure angle on the return (default alpha_allow), 0 < α ≤ 90°",
             required=False, maximum=90.0),
    Quantity("divisions", "count", "equal divisions of the rise and of the return in the drawing, a whole number from 1 "
             "to 24 (default: parts of at most 15°)", required=False, maximum=24.0),
    TOL,
    STRICT,
    OMEGA,
)
ANSWERS = (
    Quantity("psi_max", "deg", "angular stroke ψmax, measured between the arm's first and top positions"),
    Quantity("psi0", "deg", "initial arm angle ψ0 = ∠OA0B0"),
    *PRESSURE_ANSWERS,
    Quantity("rho_min_actual", "mm", "of the actual profile: ρmin − rr (roller; ≤ 0 when undercut); a knife edge's "
             "profile is the pitch curve: ρmin itself (its figure prints ρmin only)"),
    Quantity("undercut", "bool", "rr ≥ ρmin: the roller cannot reproduce the motion (profile trimmed); always false "
             "for a knife edge (no roller: its figure does not print it); flat face: not `convex` (its figure prints "
             "`convex` only)"),
    Quantity("psi", "deg[]", "arm angle ψ at the cam angles of `at`"),
    Quantity("alpha", "deg[]", "pressure angle α at the cam angles of `at`"),
    Quantity("pitch_x", "mm[]", "x of the pitch point (cam frame) at the cam angles of `at`"),
    Quantity("pitch_y", "mm[]", "y of the pitch point (cam frame) at the cam angles of `at`"),
    Quantity("profile_x", "mm[]", "x of the actual profile's point (roller) at the cam angles of `at`"),
    Quantity("profile_y", "mm[]", "y of the actual profile's point (roller) at the cam angles of `at`"),
    Quantity("convex", "bool", "flat face: the profile's ρ > 0 everywhere and the contact never jumps back"),
    Quantity("face_min", "mm", "flat face: nearest place of the contact along the face from the pivot's foot"),
    Quantity("face_max", "mm", "flat face: farthest place of the contact along the face from the pivot's foot"),
    Quantity("face_length", "mm", "flat face: the face length the contact sweeps from the pivot's foot, "
             "max(face_max, 0) − min(face_min, 0)"),
    Quantity("face_contact", "mm[]", "flat face: place of the contact along the face at the cam angles of `at`"),
    *ARM_SPEED_ANSWERS,
)
POINTS = ("O", "A0", "B0")
ROLLER_WARN = 3.0
"""A warning when ρmin of the pitch curve is below this many roller radii (the profile's curvature is sharp)."""


# ---------------------------------------------------------------------------------------------- givens

def cam_of(g: Mapping[str, Any]) -> OscillatingCam:
    """The knife or roller cam described by the givens."""
    return OscillatingCam(g["a"], g["L"], g["r0"], g["h"], program_of(g), g.get("rotation", "ccw"),
                          g.get("arm", "left"))


def _validate(g: Mapping[str, Any]) -> list[str]:
    """Refuse cams that cannot be assembled (the warnings, which cost searches, are :func:`_advise`'s; a
    flat-faced arm's validation makes both)."""
    if g["follower"] == "flat":
        return validate_flat(g)
    if g.get("L") is None:
        raise NotAMechanism(f"a {g['follower']} arm needs L (the arm length A0B)")
    if g.get("face_offset") is not None:
        raise NotAMechanism(f"face_offset = {g['face_offset']:g} is given for a {g['follower']} follower: only a "
                            "flat-faced arm has a face")
    a, L, r0, h = g["a"], g["L"], g["r0"], g["h"]
    cam = cam_of(g)
    if g.get("divisions") is not None:              # (the default divisions cannot be refused)
        arm_division_angles(g, cam)
    if r0 >= a + L:
        raise NotAMechanism(f"r0 = {r0:g} ≥ a + L = {a + L:g}: the arm cannot reach the base circle")
    if r0 <= abs(a - L):
        raise NotAMechanism(f"r0 = {r0:g} ≤ |a − L| = {abs(a - L):g}: the arm's circle about A0 does not cross "
                            "the base circle (no initial position, ψ0 undefined)")
    if r0 >= a:
        raise NotAMechanism(f"r0 = {r0:g} ≥ a = {a:g}: the arm's pivot A0 lies inside the base circle")
    psi0 = math.degrees(psi0_rad(a, L, r0))
    if psi0 + h >= 180.0:
        raise NotAMechanism(f"ψ0 + h = {psi0:.6g}° + {h:g}° ≥ 180°: the arm would swing through the line A0O")
    roller = g["follower"] == "roller"
    rr = g.get("rr")
    if roller and rr is None:
        raise NotAMechanism("a roller follower needs rr (the roller radius)")
    if not roller and rr is not None:
        raise NotAMechanism(f"rr = {rr:g} is given for a knife-edge follower: only a roller follower has a roller")
    rr = rr or 0.0
    if rr >= r0:
        raise NotAMechanism(f"rr = {rr:g} ≥ r0 = {r0:g}: the actual profile's base circle r0 − rr would vanish")
    return []


def _advise(g: Mapping[str, Any]) -> list[str]:
    """The warnings that cost a search (the arm hitting its pivot, α_max against the allowance, undercut): made
    only when the warnings are asked for (a flat-faced arm's: :func:`advise_flat`)."""
    if g["follower"] == "flat":
        return advise_flat(g)
    a, L, r0, h = g["a"], g["L"], g["r0"], g["h"]
    cam = cam_of(g)
    psi0 = math.degrees(psi0_rad(a, L, r0))
    roller = g["follower"] == "roller"
    rr = g.get("rr") or 0.0
    out = []
    r_top = math.sqrt(a * a + L * L - 2.0 * a * L * math.cos(math.radians(psi0 + h)))
    if r_top - rr >= a:
        out.append(f"the cam reaches {r_top - rr:.4g} mm from O at the top of the stroke, beyond the arm's pivot "
                   f"(a = {a:g}): it would hit the pivot")
    allow = {"rise": g.get("alpha_allow"), "return": g.get("alpha_allow_return") or g.get("alpha_allow")}
    for part in [p for p in ("rise", "return") if allow[p] is not None]:
        alpha, at = _shared(cam, part, lambda: cam.worst_pressure(part))
        if alpha > allow[part]:
            out.append(f"α_max of the {part} = {alpha:.3f}° exceeds the allowance {allow[part]:g}° (at δ = {at:.3f}°)")
    if roller:
        low = _shared(cam, "rho", lambda: rho_min(cam.pitch_curve(scalar=True)))
        rho, at = low.value, low.delta_deg
        if rr >= rho:
            out.append(f"undercut: rr = {rr:g} ≥ ρmin = {rho:.4g} of the pitch curve (at δ = {at:.4g}°); the profile "
                       "is trimmed and the follower's motion is distorted there (增大基圆或减小滚子半径)")
        elif rho < ROLLER_WARN * rr:
            out.append(f"ρmin = {rho:.4g} of the pitch curve is below {ROLLER_WARN:g}·rr = {ROLLER_WARN * rr:g}: "
                       f"the actual profile's ρa = {rho - rr:.4g} is small (wear, contact stress)")
    return out


# ---------------------------------------------------------------------------------------------- step ops
def arm_normal(A: Point, B: Point, O: Point, k: float) -> Point:
    """Direction of the contact normal at the roller centre B of an arm pivoted at A: towards the relative
    instant centre P of cam and arm on the line A→O, AP = |AO|/(1 − k) (k = the arm's angular velocity over
    the cam's, signed), written without the division, (O − A) + (1 − k)(A − B), so that it stays finite
    when P goes to infinity."""
    return (O - A) + (A - B) * (1.0 - k)


def arm_pressure_deg(A: Point, B: Point, O: Point, k: float) -> float:
    """Pressure angle (deg) at the roller centre B of an arm pivoted at A: the acute angle between the
    contact normal (:func:`arm_normal`) and the roller's velocity, perpendicular to AB.

    Examples
    --------
    >>> round(arm_pressure_deg(Point(0, 0), Point(0, -10), Point(0, -20), 0.0), 12)   # B on AO: normal ⊥ v
    90.0
    >>> round(arm_pressure_deg(Point(0, 100), Point(-30, 60), Point(0, 0), 0.0), 9)  # dwell: normal through O
    26.565051177
    """
    n, v = arm_normal(A, B, O, k), (B - A).perp()
    return math.degrees(math.atan2(abs(n.cross(v)), abs(n.dot(v))))


_SHARED: dict = {}
"""(cam, what) → the construction's search (α_max and its place of a part, ρmin of the pitch curve), written
when the construction makes it and read by the warnings (:func:`_advise`), which would make the same search."""


def _shared(cam: OscillatingCam, what: str, compute):
    """The construction's result ``what`` for this cam (equal cams, equal results) if it has been made, else
    ``compute()``, kept."""
    out = _SHARED.get((cam, what))
    return _keep(cam, what, compute()) if out is None else out


def _keep(cam: OscillatingCam, what: str, value):
    if len(_SHARED) >= 64:
        _SHARED.clear()
    _SHARED[(cam, what)] = value
    return value


def worst(cam: OscillatingCam, part: str) -> tuple[float, float]:
    """(α_max, δ) of the rise or the return (closed form, exact-derivative search); kept for the warnings."""
    return _keep(cam, part, cam.worst_pressure(part))


def pitch_rho_min(curve, cam: OscillatingCam):
    """ρmin of the pitch curve (:func:`~geomcon.cam.profile.rho_min`), kept for the warnings."""
    return _keep(cam, "rho", rho_min(curve))


def cam_profile(curve, rr: float, tol: float, cam: OscillatingCam):
    """The actual profile (:func:`~geomcon.cam.profile.roller_profile` of ``curve``, the pitch curve of ``cam``)
    for this cam, roller and tolerance, made once in a process: equal cams have equal pitch curves, so equal
    profiles (the slotter's five problems 000-04 … 000-08 draw one cam). A pure function of its arguments,
    read and never changed by its users."""
    return _shared(cam, ("profile", rr, tol), lambda: roller_profile(curve, rr, tol))


def coord(p: Point, axis: int) -> float:
    """x (axis 0) or y (axis 1) of a point."""
    return p.x if axis == 0 else p.y


def collect_all(values) -> tuple[float, ...]:
    """An array as a list answer."""
    return tuple(float(v) for v in values)


# ---------------------------------------------------------------------------------------------- construction
def construct(g: Mapping[str, Any]) -> Construction:
    """Build the inversion construction."""
    if g["follower"] == "flat":
        return construct_flat(g)
    cam = cam_of(g)
    a, L, r0, h, prog = cam.a, cam.L, cam.r0, cam.h, cam.program
    roller = g["follower"] == "roller"
    rr = float(g.get("rr") or 0.0)
    back = ("clockwise", "顺时针") if cam.sigma > 0 else ("counter-clockwise", "逆时针")
    sc = Scene(f"Disc cam with an oscillating {g['follower']} follower: inversion")
    drawing = sc.drawing                    # the arcs and ghost arms of the divisions: drawing only
    O = add_cam_centre(sc, float(cam.sigma))
    A0 = add_pivot(sc, "A0", Point(0.0, a), (f"Arm pivot A0 with OA0 = a = {a:g}", f"摆杆转轴 A0,OA0 = a = {a:g}"),
                   ground_angle=math.pi / 2)
    sc.add("OA0", segment, O, A0, role=Role.GIVEN, style="frame")
    base = add_base_circle(sc, O, r0)
    kL = sc.add("kL0", circle, A0, L, caption=(f"Arc about A0 with radius L = {L:g}", f"以 A0 为圆心、L = {L:g} 为半径作弧"))
    side = RightOf(A0, O) if cam.tau < 0 else LeftOf(A0, O)
    B0 = sc.add("B0", circle_circle, kL, base, branch=side, role=Role.RESULT, style="joint", label="B0",
                caption=("It meets the base circle at B0: the arm's lowest position A0B0",
                         "交基圆于 B0,得摆杆起始位置 A0B0"))
    add_bar(sc, "arm0", A0, B0)
    if roller and drawing:                  # the roller belongs to the follower: drawn with its arm (200-05 had none)
        sc.add("roller_start", circle, B0, rr, style="link", role=Role.RESULT)
    psi0 = sc.add("psi0", angle_deg, A0, O, B0, role=Role.MEASUREMENT, unit="deg",
                  caption=("Measure ψ0 = ∠OA0B0", "量得初始摆角 ψ0 = ∠OA0B0"))
    add_angle_mark(sc, "mark_psi0", A0, O, B0, "ψ0", psi0, 0.55 * L)   # clear of the inverted arms at A0 (000-04)
    sc.add("kA", circle, O, a, caption=(f"Circle about O with radius a = {a:g}: the path of A0 in the inversion",
                                        f"以 O 为圆心、a = {a:g} 为半径作圆(反转后 A0 的轨迹)"))
    inv = ArmInversion(sc, cam, O, A0, B0)
    divs = arm_division_angles(g, cam)
    R = max(a, r0 + math.radians(h) * L + rr)
    add_motion_diagram(sc, prog, h, Point(1.55 * R, -0.5 * R), 3.0 * R, 0.5 * R / h, divs, symbol="ψ", unit="°")
    n = len(divs)
    Bs = []
    if drawing:                 # the divisions' inverted positions (pivot, arm, pitch point): drawing only
        As = [sc.add(f"A_d{i}", turned, A0, O, -float(cam.sigma), d, label=f"{i}′", style="division", caption=(
            f"Divide the circle of radius a {back[0]} (−ω) from A0 as the cam angles of the divisions: 1′ … {n}′ "
            "(the pivot's inverted positions)",
            f"自 A0 沿 −ω 方向({back[1]})按各分点的凸轮转角等分半径为 a 的圆,得 1′ … {n}′(摆杆转轴的反转位置)")
            if i == 1 else ("", "")) for i, d in enumerate(divs, 1)]
        Cs = []
        for i, (A, d) in enumerate(zip(As, divs), 1):
            Cs.append(sc.add(f"C_d{i}", turned, B0, O, -float(cam.sigma), d, style="point", caption=(
                f"Arcs of radius L about 1′ … {n}′ meet the base circle at C1 … C{n} (the arm's initial position "
                "turned with the frame)", f"以 1′ … {n}′ 为圆心、L 为半径作弧交基圆于 C1 … C{n}(摆杆起始位置随机架反转)")
                if i == 1 else ("", "")))
            sc.add(f"arc_d{i}", circle, A, L)
        for i, (A, C, d) in enumerate(zip(As, Cs, divs), 1):
            Bs.append(sc.add(f"B_d{i}", laid_off, C, A, cam, d, style="point", caption=(
                "Lay off the arm angles ψ1, ψ2, … of the ψ–δ diagram at 1′, 2′, …: ∠CiA0′Bi = ψi, A0′Bi = L, "
                "points B1 … B" + str(n), "在 1′, 2′, … 处量取 ψ–δ 线图中的摆角 ψ1, ψ2, …:∠Ci A0′ Bi = ψi,得 B1 … B"
                + str(n)) if i == 1 else ("", "")))
            sc.add(f"arm_d{i}", segment, A, Bs[-1], style="ghost")
    top = prog.rise.end
    At, Ct, Bt = inv.position("top", top, visible=False)
    sc.add("psi_max", angle_deg, At, Ct, Bt, role=Role.MEASUREMENT, unit="deg",
           caption=(f"Measure the stroke ψmax = ∠CA0′B at the end of the rise, δ = {top:g}°",
                    f"量得推程终点(δ = {top:g}°)的最大摆角 ψmax = ∠CA0′B"))
    curve = sc.given("pitch", cam.pitch_curve(scalar=True), visible=False)
    sc.add("pitch_curve", pitch_polyline, curve, style="frame" if roller else "link", role=Role.RESULT,
           caption=("Join B1, B2, … by a smooth curve: the pitch curve" + ("" if roller else " (the knife edge's profile)"),
                    "将 B1、B2 … 连成光滑曲线,即理论廓线" + ("" if roller else "(尖顶从动件的实际廓线)")))
    rho = sc.add("rho_pitch", pitch_rho_min, curve, cam, visible=False)
    sc.add("rho_min_pitch", extremum_value, rho, role=Role.MEASUREMENT, unit="mm",
           caption=("ρmin of the pitch curve, from its exact derivatives", "由精确导数求理论廓线的最小曲率半径 ρmin"))
    sc.add("rho_min_actual", minus, Ref("rho_min_pitch"), rr, role=Role.MEASUREMENT, unit="mm", visible=False)
    sc.add("undercut", at_least, rr, Ref("rho_min_pitch"), visible=False) if roller else \
        sc.add("undercut", bool, False, visible=False)
    tol = profile_tolerance(g, max(a, r0 + rr))
    if roller:
        add_roller_circles(sc, Bs, rr)
        add_profile_steps(sc, cam_profile, (curve, rr, tol, cam),
                          ("Draw the inner envelope of the roller circles: the actual profile",
                           "作滚子圆族的内包络线,即凸轮的实际廓线"))
    else:
        add_profile_steps(sc, cam_profile, (curve, 0.0, tol, cam), ("", ""), style="link")
    answers = {q: q for q in ("psi_max", "psi0", "rho_min_pitch", "rho_min_actual", "undercut")}
    for part, zh in (("rise", "推程"), ("return", "回程")):
        w = sc.add(f"worst_{part}", worst, cam, part, visible=False)
        where = sc.add(f"delta_alpha_max_{part}", place_deg, w, role=Role.MEASUREMENT, unit="deg", visible=False)
        A, _, B = inv.position(f"w_{part}", where, caption=(
            f"The {part}'s worst position (largest α): the arm A0′B and the common normal at B, through the relative "
            "instant centre P of cam and arm on OA0′ (A0′P = a/(1 − εψ′))",
            f"{zh}压力角最大的位置:摆杆 A0′B;过 B 的公法线通过凸轮与摆杆的相对瞬心 P(在 OA0′ 上,A0′P = a/(1 − εψ′))"))
        if drawing:                         # the arm, the common normal and B's velocity: drawing only
            add_bar(sc, f"warm_{part}", A, B, style="link-alt")
        k = sc.add(f"k_{part}", speed_ratio, cam, where, part, visible=False)
        if drawing:
            n = sc.add(f"n_{part}", arm_normal, A, B, O, k, visible=False)
            v = sc.add(f"v_{part}", arm_velocity, A, B, cam.tau if part == "rise" else -cam.tau, visible=False)
            sc.add(f"normal_{part}", normal_segment, B, n, 0.6 * L, style="path")
            sc.add(f"velocity_{part}", velocity_segment, B, v, 0.45 * L, style="ghost")
        al = sc.add(f"alpha_max_{part}", arm_pressure_deg, A, B, O, k, role=Role.MEASUREMENT, unit="deg",
                    caption=(f"α between the normal and the velocity of B (⊥ A0′B): the {part}'s "
                             + ("α_max" if part == "rise" else "α′_max"),
                             f"法线与 B 点速度方向(⊥ A0′B)之夹角:{zh}最大压力角"))
        if drawing:
            sc.add(f"mark_alpha_{part}", pressure_mark_clear, B, n, v, al, 0.3 * L,
                   "αmax" if part == "rise" else "α′max", O, r0, 0.05 * L, role=Role.ANNOTATION, style="angle")
        answers[f"alpha_max_{part}"] = f"alpha_max_{part}"
        answers[f"delta_alpha_max_{part}"] = f"delta_alpha_max_{part}"
    at = tuple(g.get("at") or ())
    if at:                          # every position of `at` in one step (1000 angles: one evaluation)
        pos = sc.add("at_positions", arm_at, Point(0.0, a), B0, cam, at, visible=False)
        sc.add("at_alpha", arm_pressures, pos, cam.eps, visible=False)
        cols = {"psi": (pos, "psi"), "alpha": (Ref("at_alpha"), None), "pitch_x": (pos, "Bx"), "pitch_y": (pos, "By")}
        if roller:
            sc.add("at_contacts", lambda p, e, c, r: dict(zip(("x", "y"), arm_contacts(p, e, c, r))), pos, cam.eps,
                   curve, rr, visible=False)
            cols.update(profile_x=(Ref("at_contacts"), "x"), profile_y=(Ref("at_contacts"), "y"))
        for name, (ref, key) in cols.items():
            sc.add(name, column if key else collect_all, ref, *((key,) if key else ()), role=Role.MEASUREMENT,
                   visible=False)
            answers[name] = name
        # read off the ψ–δ curve, the pitch curve and the profile, not shown with the arm's pivot (issue 11)
        sc.read_off("sd_curve", "psi")
        sc.read_off("pitch_curve", "alpha", "pitch_x", "pitch_y")
        sc.read_off("profile_curve", "profile_x", "profile_y")
    add_speed_steps(sc, answers, g, prog, h, angular=True)
    return Construction(sc, answers, {p: p for p in POINTS})


# ---------------------------------------------------------------------------------------------- twin
def analytic(g: Mapping[str, Any]) -> list[dict[str, Any]]:
    """The closed forms by their separate routes (see the module docstring)."""
    if g["follower"] == "flat":
        return analytic_flat(g)
    cam = cam_of(g)
    roller = g["follower"] == "roller"
    rr = float(g.get("rr") or 0.0)
    rho = cam.rho_min(cam.convex_curvature_complex, cam.convex_curvature_complex1())[0]
    out: dict[str, Any] = {
        "psi_max": math.degrees(float(cam.motion(cam.program.rise.end).psi)),
        "psi0": math.degrees(cam.psi0),
        "rho_min_pitch": float(rho), "rho_min_actual": float(rho - rr), "undercut": bool(rr >= rho),
    }
    for kind in ("rise", "return"):
        alpha, where = cam.worst_pressure(kind, route="arg")
        out[f"alpha_max_{kind}"], out[f"delta_alpha_max_{kind}"] = alpha, deg360(where)
    at = tuple(g.get("at") or ())
    if at:
        d = np.asarray(at, dtype=float)
        m = cam.motion(d)
        x, y = cam.pitch_of(m)[:2]
        out.update(psi=collect(*np.degrees(m.psi)), alpha=collect(*cam.pressure_arg(m)), pitch_x=collect(*x),
                   pitch_y=collect(*y))
        if roller:
            px, py = cam.roller_contact(d, rr)
            out.update(profile_x=collect(*px), profile_y=collect(*py))
    out.update(follower_speeds(g, angular=True))
    return [out]


RECIPE = Recipe(
    name="cam.oscillating",
    title="Disc cam with an oscillating follower: inversion, ψ0, pressure angle, ρmin, undercut",
    givens=GIVENS,
    answers=ANSWERS,
    points=POINTS,
    construct=construct,
    analytic=analytic,
    validate=_validate,
    advise=_advise,
)
