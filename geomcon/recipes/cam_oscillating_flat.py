"""``cam.oscillating`` with a flat-faced arm (平底摆动从动件): the profile is the envelope of the face lines in
the inverted positions; closed forms in :mod:`geomcon.cam.oscillating_flat`.

Split from :mod:`.cam_oscillating`, which dispatches here when ``follower = "flat"``; the steps both share
(the inversion of the arm, the cam centre, the ψ–δ diagram) live in :mod:`.cam_common`, so neither module
imports the other's internals (cam_oscillating → cam_oscillating_flat → cam_common, no cycle).
"""
from __future__ import annotations

import math
from typing import Any, Mapping

import numpy as np

from ..numeric import deg360
from ..cam.arm_face import (_FaceSearch, _segment_pieces, face_extremes, face_nearest, face_place, face_place1,
                            face_place_and_slope, face_place_slope, face_place_slope1, flat_family)
from ..cam.oscillating_flat import END_TIE, FlatArmCam
from ..cam.profile import (Extremum, LineFamily, envelope, envelope1, envelope_rho_min, flat_profile, numpy_is_libm)
from ..errors import NotAMechanism
from ..geometry import (LeftOf, NearestTo, Point, RightOf, Segment, circle, circle_circle, line_circle, line_through,
                        segment, thales_circle)
from ..scene import Ref, Role, Scene
from .base import Construction
from ..analytic.cam_motion import follower_speeds
from .cam_common import (SCALAR_AT, add_speed_steps, ArmInversion, add_base_circle, add_cam_centre, add_motion_diagram, add_profile_steps,
                         arm_at, arm_division_angles, arm_velocity, collect, column, extremum_deg, extremum_value, flat_convex, negate,
                         pick, pressure_mark, profile_tolerance, program_of, speed_ratio, velocity_segment)
from .common import add_angle_mark, add_pivot, angle_deg


FLAT_SPEED_MIN = 1e-6
"""1 − εψ′ must stay above this: at 0 the face stops turning relative to the cam and the contact runs off to
infinity."""


def flat_cam_of(g: Mapping[str, Any]) -> FlatArmCam:
    """The flat-faced arm described by the givens."""
    return FlatArmCam(g["a"], g["r0"], g["h"], program_of(g), g.get("rotation", "ccw"), g.get("arm", "left"),
                      float(g.get("face_offset") or 0.0))


def validate_flat(g: Mapping[str, Any]) -> list[str]:
    """Refuse a flat-faced arm that cannot work (no tangent lowest position, the face turning past the
    perpendicular to A0O, the contact running off to infinity). The warnings, which cost searches of the
    twin's, are :func:`advise_flat`'s."""
    for name, why in (("L", "the face's reach is the answer face_max"), ("rr", "only a roller follower has a roller")):
        if g.get(name) is not None:
            raise NotAMechanism(f"{name} = {g[name]:g} is given for a flat-faced arm: it is not used ({why}); "
                                "leave it out")
    cam = flat_cam_of(g)
    if g.get("divisions") is not None:              # (the default divisions cannot be refused)
        arm_division_angles(g, cam)
    a, r0, f, h = cam.a, cam.r0, cam.offset, cam.h
    if r0 + f <= 0.0:
        raise NotAMechanism(f"face_offset = {f:g} ≤ −r0 = {-r0:g}: the face would lie beyond the pivot, away from "
                            "the base circle")
    if r0 + f >= a:
        raise NotAMechanism(f"r0 + face_offset = {r0 + f:g} ≥ a = {a:g}: the face cannot touch the base circle "
                            "(sin ψ0 = (r0 + f)/a)")
    psi0 = math.degrees(cam.psi0)
    if psi0 + h >= 90.0:
        raise NotAMechanism(f"ψ0 + h = {psi0:.6g}° + {h:g}° ≥ 90°: the face would turn past the perpendicular to "
                            "A0O and come back towards the cam while the arm rises")
    if cam.speed_floor() > FLAT_SPEED_MIN:         # the laws' bound clears it: no search can find it lower
        return []
    w, at = cam.speed_min()
    if w <= FLAT_SPEED_MIN:
        raise NotAMechanism(f"1 − εψ′ = {w:.6g} at δ = {at:.6g}°: the arm swings as fast as the face turns with the "
                            "cam, the contact runs off to infinity along the face")
    return []


def advise_flat(g: Mapping[str, Any]) -> list[str]:
    """The flat-faced arm's warnings (the profile reaching the pivot, α_max against the allowance, a profile
    the face cannot follow): made only when the warnings are asked for, never for answers alone; the searches
    the checks' twin made for these givens are not made again."""
    cam = flat_cam_of(g)
    given, copy, twin = _LAST_TWIN
    if given is g and twin == cam and copy == dict(g):
        cam = twin
    a = cam.a
    out = []
    d = np.linspace(0.0, 360.0, 3601)
    reach = float(np.hypot(*cam.contact_point(d)).max())
    if reach >= a:
        out.append(f"the profile reaches about {reach:.4g} mm from O, beyond the arm's pivot (a = {a:g}): it would "
                   "hit the pivot")
    allow = {"rise": g.get("alpha_allow"), "return": g.get("alpha_allow_return") or g.get("alpha_allow")}
    for part in [p for p in ("rise", "return") if allow[p] is not None]:
        alpha, where = cam.worst_pressure(part)
        if alpha > allow[part]:
            out.append(f"α_max of the {part} = {alpha:.3f}° exceeds the allowance {allow[part]:g}° (at δ = {where:.3f}°)")
    rho, where = cam.rho_min()
    jumps = cam.backward_jumps()
    if rho <= 0.0 or jumps:
        back = ", ".join(f"{d:g}° ({j:.4g} mm)" for j, d in jumps)
        out.append(f"the flat face cannot follow the motion: ρmin of the profile = {rho:.4g} mm at δ = {where:.4g}°"
                   + (f"; the contact jumps back along the face at δ = {back} (ψ′ drops suddenly)" if jumps else "")
                   + "; the profile is trimmed (增大基圆 r0)")
    return out


_LAST_TWIN: tuple = (None, None, None)
"""(the givens, a copy of them, the twin's cam) of the last :func:`analytic_flat`, whose searches the warnings
of the same solve (:func:`advise_flat` on the same, unchanged givens) take over."""


def face_length(lo: Extremum, hi: Extremum) -> float:
    """The face length from the pivot's foot covering every contact: max(l_max, 0) − min(l_min, 0)."""
    return max(hi.value, 0.0) - min(lo.value, 0.0)


def envelope_point(fam: LineFamily, delta_deg: float) -> Point:
    """The contact point (on the envelope) at cam angle ``delta_deg``."""
    x, y = envelope(fam, np.array([math.radians(delta_deg)]))[:2]
    return Point(float(x[0]), float(y[0]))


def face_normal(fam: LineFamily, delta_deg: float) -> Point:
    """The face's unit normal (away from O) at cam angle ``delta_deg``."""
    beta = float(fam.eval(np.array([math.radians(delta_deg)]))[0][0])
    return Point(math.cos(beta), math.sin(beta))


def face_pressure_deg(A: Point, K: Point, n: Point) -> float:
    """Pressure angle (deg) of a flat face: the acute angle between the face normal ``n`` at the contact K and
    K's velocity as a point of the arm (⊥ A0′K).

    Examples
    --------
    >>> face_pressure_deg(Point(0, 0), Point(30, 0), Point(0, 1))          # face through the pivot
    0.0
    >>> round(face_pressure_deg(Point(0, 0), Point(30, -10), Point(0, 1)), 9)  # face 10 below the pivot
    18.434948823
    """
    v = (K - A).perp()
    return math.degrees(math.atan2(abs(n.cross(v)), abs(n.dot(v))))


def worst_place(nearest: Extremum) -> float:
    """The cam angle (deg) of the nearest contact (:func:`face_nearest`): the largest α = atan(|f|/l)."""
    return deg360(nearest.delta_deg)


def offset_pressure_deg(f: float, nearest: Extremum) -> float:
    """α (deg) at the nearest contact of a segment (:func:`face_nearest`): atan2(|f|, l_min)."""
    return math.degrees(math.atan2(abs(f), nearest.value))


def face_foot(A: Point, D: Point, O: Point, f: float) -> Point:
    """The foot F of the pivot A on the face: A moved by ``f`` towards O across the arm's direction A→D."""
    u = (D - A).unit()
    m = u.perp()
    if m.dot(O - A) < 0.0:
        m = -m
    return A + m * f


def face_segment(A: Point, D: Point, O: Point, f: float, reach: float) -> Segment:
    """The face drawn from its foot F out to ``reach`` along the arm's direction A→D."""
    F = face_foot(A, D, O, f)
    return Segment(F, F + (D - A).unit() * reach)


def face_span(A: Point, D: Point, O: Point, f: float, lo: float, hi: float) -> Segment:
    """The face as long as :func:`face_length` says: from min(``lo``, 0) to max(``hi``, 0) along the arm's
    direction A→D, measured from the pivot's foot F (the drawn face's length is the answer L)."""
    F = face_foot(A, D, O, f)
    u = (D - A).unit()
    return Segment(F + u * min(lo, 0.0), F + u * max(hi, 0.0))


def same_point(p: Point) -> Point:
    """The point itself (a labelled copy of a hidden step)."""
    return p


def grown(x: float, k: float) -> float:
    """k·x (a drawing length)."""
    return k * x


def instant_centre(A: Point, O: Point, k: float) -> Point:
    """The relative instant centre P of cam and arm on A0′O: A0′P = a/(1 − k), k = εψ′."""
    return A + (O - A) * (1.0 / (1.0 - k))


def through(P: Point, Q: Point, extra: float) -> Segment:
    """The segment P→Q drawn ``extra`` beyond both ends."""
    u = (Q - P).unit() * extra
    return Segment(P - u, Q + u)


def lists_flat(cam: FlatArmCam, at: tuple[float, ...]) -> dict[str, tuple[float, ...]]:
    """The twin's ψ, α, l at the cam angles ``at``."""
    m = cam.motion(np.asarray(at, dtype=float))
    return {"psi": collect(*np.degrees(m.psi)), "alpha": collect(*cam.pressure_of(m)),
            "face_contact": collect(*cam.contact_of(m))}


def construct_flat(g: Mapping[str, Any]) -> Construction:
    """The inversion for a flat-faced arm: the face's tangent lowest position by the Thales circle on OA0, the
    face turned to the divisions, the envelope, the contact's reach along the face, the worst α."""
    cam = flat_cam_of(g)
    a, r0, f, h, prog = cam.a, cam.r0, cam.offset, cam.h, cam.program
    inv = -float(cam.sigma)
    back = ("clockwise", "顺时针") if cam.sigma > 0 else ("counter-clockwise", "逆时针")
    sc = Scene("Disc cam with an oscillating flat-faced follower: inversion")
    drawing = sc.drawing                    # the faces of the divisions, the worst positions: drawing only
    O = add_cam_centre(sc, float(cam.sigma))
    A0 = add_pivot(sc, "A0", Point(0.0, a), (f"Arm pivot A0 with OA0 = a = {a:g}", f"摆杆转轴 A0,OA0 = a = {a:g}"),
                   ground_angle=math.pi / 2)
    if drawing:
        sc.add("OA0", segment, O, A0, role=Role.GIVEN, style="frame")
    base = add_base_circle(sc, O, r0, ("profile", "实际廓线"))
    th = sc.add("thales", thales_circle, O, A0, style="construction",
                caption=("Circle on OA0 as diameter (its points see OA0 under a right angle)",
                         "以 OA0 为直径作圆(其上各点对 OA0 张直角)"))
    side = RightOf(A0, O) if cam.tau < 0 else LeftOf(A0, O)
    if f:
        kf = sc.add("kF", circle, O, r0 + f, style="construction",
                    caption=(f"Circle about O with radius r0 + f = {r0 + f:g} (the face is f = {f:g} from the pivot)",
                             f"以 O 为圆心、r0 + f = {r0 + f:g} 为半径作圆(平底距转轴 f = {f:g})"))
        T1 = sc.add("T1", circle_circle, th, kf, branch=side, style="point", label="T′",
                    caption=("It meets the circle on OA0 at T′: A0T′ is the arm's direction in the lowest position",
                             "交 OA0 为直径的圆于 T′:A0T′ 为摆杆最低位置的方向"))
        sc.add("T0", line_circle, sc.add("OT1", line_through, O, T1, visible=False), base, branch=NearestTo(T1),
                    role=Role.RESULT, style="joint", label="T0",
                    caption=("OT′ meets the base circle at T0: the face touches it there in its lowest position",
                             "OT′ 交基圆于 T0:平底最低位置与基圆切于 T0"))
    else:
        T1 = sc.add("T0", circle_circle, th, base, branch=side, role=Role.RESULT, style="joint", label="T0",
                    caption=("It meets the base circle at T0: A0T0 is the face in its lowest position, tangent to the "
                             "base circle", "交基圆于 T0:A0T0 即平底的最低位置,与基圆相切"))
    psi0 = sc.add("psi0", angle_deg, A0, O, T1, role=Role.MEASUREMENT, unit="deg",
                  caption=(f"Measure ψ0 = ∠OA0T{'′' if f else '0'}: sin ψ0 = (r0 + f)/a",
                           f"量得初始摆角 ψ0 = ∠OA0T{'′' if f else '0'}(sin ψ0 = (r0 + f)/a)"))
    if drawing:                              # the arm's lowest direction, the ray ψ0 is measured to
        sc.add("A0T", segment, A0, T1, style="construction")
    add_angle_mark(sc, "mark_psi0", A0, O, T1, "ψ0", psi0)
    fam = sc.given("faces", flat_family(cam), visible=False)
    tau = cam.tau
    ext = sc.add("face_ext", face_extremes, fam, A0, inv, tau, visible=False)
    sc.add("face_min", extremum_value, sc.add("face_lo", pick, ext, 0, visible=False), role=Role.MEASUREMENT,
           unit="mm", visible=False)
    sc.add("face_max", extremum_value, sc.add("face_hi", pick, ext, 1, visible=False), role=Role.MEASUREMENT,
           unit="mm", visible=False)
    sc.add("face_length", face_length, Ref("face_lo"), Ref("face_hi"), role=Role.MEASUREMENT, unit="mm",
           visible=False)
    sc.read_off("face0", "face_length")      # "… the face length L": with it, not with A0 at step 2 (issue 11)
    if drawing:
        reach = sc.add("face_reach", grown, Ref("face_max"), 1.12, visible=False)
        sc.add("face0", face_span, A0, T1, O, f, Ref("face_min"), Ref("face_max"), style="link", role=Role.RESULT,
               caption=("The flat face in its lowest position, from the pivot's foot out to the farthest contact "
                        "l_max: the face length L", "平底的最低位置:自摆杆垂足至最远接触点 l_max,即平底长度 L"))
        if f:
            sc.add("arm0", segment, A0, sc.add("F0", face_foot, A0, T1, O, f, visible=False), style="link")
        sc.add("kA", circle, O, a, style="construction",
               caption=(f"Circle about O with radius a = {a:g}: the path of A0 in the inversion",
                        f"以 O 为圆心、a = {a:g} 为半径作圆(反转后 A0 的轨迹)"))
    inv_pos = ArmInversion(sc, cam, O, A0, T1)
    divs = arm_division_angles(g, cam) if drawing else ()
    R = a
    add_motion_diagram(sc, prog, h, Point(1.25 * R, -0.6 * R), 2.4 * R, 0.4 * R / h, divs, symbol="ψ", unit="°")
    n = len(divs)
    ends = []                   # the pivots 1′ … n′ all at the step that divides the circle, then the faces
    for i, d in enumerate(divs, 1):
        A, _, D = inv_pos.position(f"d{i}", d, visible=False)
        sc.add(f"pivot_d{i}", same_point, A, style="division", label=f"{i}′", caption=(
            f"Divide the circle of radius a {back[0]} (−ω) from A0 as the cam angles of the divisions: 1′ … {n}′; "
            "turn A0T′ with them and lay off ψ1, ψ2, … of the ψ–δ diagram at 1′, 2′, … (the arm's directions)",
            f"自 A0 沿 −ω 方向({back[1]})按各分点的凸轮转角等分半径为 a 的圆,得 1′ … {n}′;A0T′ 随之反转,"
            "并在 1′, 2′, … 处量取 ψ–δ 线图中的摆角 ψ1, ψ2, …(摆杆方向)") if i == 1 else ("", ""))
        ends.append((A, D))
    for i, (A, D) in enumerate(ends, 1):
        sc.add(f"face_d{i}", face_segment, A, D, O, f, reach, style="path", caption=(
            f"Draw the face in each inverted position, {abs(f):g} from 1′, 2′, … along the arm's direction"
            if f else "Draw the face along the arm's direction from 1′, 2′, …: the inverted face lines",
            "在各反转位置作平底直线" + (f"(距 1′, 2′, … 为 f = {abs(f):g})" if f else "(过 1′, 2′, …,沿摆杆方向)"))
            if i == 1 else ("", ""))
    top = prog.rise.end
    At, Ct, Dt = inv_pos.position("top", top, visible=False)
    sc.add("psi_max", angle_deg, At, Ct, Dt, role=Role.MEASUREMENT, unit="deg",
           caption=(f"Measure the stroke ψmax at the end of the rise, δ = {top:g}°",
                    f"量得推程终点(δ = {top:g}°)的最大摆角 ψmax"))
    add_profile_steps(sc, flat_profile, (fam, profile_tolerance(g, a)),
                      ("Draw the envelope of the face lines: the actual profile", "作各平底直线的包络线,即凸轮的实际廓线"))
    rho = sc.add("rho_flat", envelope_rho_min, fam, visible=False)
    sc.add("rho_min_actual", extremum_value, rho, role=Role.MEASUREMENT, unit="mm", visible=False)
    sc.add("convex", flat_convex, fam, rho, visible=False)
    sc.add("undercut", negate, Ref("convex"), visible=False)
    answers = {q: q for q in ("psi_max", "psi0", "rho_min_actual", "undercut", "convex", "face_min", "face_max",
                              "face_length")}
    for part, zh in (("rise", "推程"), ("return", "回程")):
        seg = prog.rise if part == "rise" else prog.ret
        e = sc.add(f"face_ext_{part}", face_nearest, fam, A0, inv, tau, seg, visible=False)
        sc.add(f"alpha_max_{part}", offset_pressure_deg, f, e, role=Role.MEASUREMENT, unit="deg", visible=False)
        answers[f"alpha_max_{part}"] = f"alpha_max_{part}"
        if f:
            sc.add(f"delta_alpha_max_{part}", worst_place, e, role=Role.MEASUREMENT, unit="deg", visible=False)
            answers[f"delta_alpha_max_{part}"] = f"delta_alpha_max_{part}"
    if drawing:
        _mark_flat(sc, cam, fam, inv_pos, O, f)
    at = tuple(g.get("at") or ())
    if at:                          # every position of `at` in one step (1000 angles: one evaluation)
        pos = sc.add("at_positions", arm_at, A0, T1, cam, at, visible=False)
        sc.add("psi", column, pos, "psi", role=Role.MEASUREMENT, visible=False)
        sc.add("alpha", face_pressures_at, fam, pos, role=Role.MEASUREMENT, visible=False)
        sc.add("face_contact", face_places_at, fam, A0, inv, tau, at, role=Role.MEASUREMENT, visible=False)
        answers.update({k: k for k in ("psi", "alpha", "face_contact")})
        sc.read_off("sd_curve", "psi")       # read off the ψ–δ curve and the envelope (issue 11: step 6, 2)
        sc.read_off("profile_curve", "alpha", "face_contact")
    add_speed_steps(sc, answers, g, prog, h, angular=True)
    return Construction(sc, answers, {"O": "O", "A0": "A0", "T0": "T0"})


def face_pressures_at(fam: LineFamily, pos: dict) -> tuple[float, ...]:
    """:func:`face_pressure_deg` at every position of :func:`~.cam_common.arm_at`: the contact K on the
    envelope, the face normal, K's velocity ⊥ A0′K."""
    if fam.fn1 is not None and len(pos["delta"]) <= SCALAR_AT and numpy_is_libm("arctan2"):
        return tuple(_face_pressure1(fam, d, ax, ay)
                     for d, ax, ay in zip(pos["delta"].tolist(), pos["Ax"].tolist(), pos["Ay"].tolist()))
    d = np.radians(pos["delta"])
    kx, ky = envelope(fam, d)[:2]
    beta = fam.eval(d)[0]
    nx, ny = np.cos(beta), np.sin(beta)
    vx, vy = -(ky - pos["Ay"]), kx - pos["Ax"]
    return tuple(float(v) for v in np.degrees(np.arctan2(np.abs(nx * vy - ny * vx), np.abs(nx * vx + ny * vy))))


def _face_pressure1(fam: LineFamily, delta: float, ax: float, ay: float) -> float:
    """:func:`face_pressures_at` at one position (cam angle in degrees, A0′), on floats: the same operations."""
    f6 = fam.fn1(math.radians(delta))
    kx, ky = envelope1(f6)[:2]
    nx, ny = math.cos(f6[0]), math.sin(f6[0])
    vx, vy = -(ky - ay), kx - ax
    return math.degrees(math.atan2(abs(nx * vy - ny * vx), abs(nx * vx + ny * vy)))


def face_places_at(fam: LineFamily, A0: Point, inv: float, tau: int, at: tuple[float, ...]) -> tuple[float, ...]:
    """:func:`face_place` at the cam angles ``at`` (deg); a few of them one by one on floats (the same bits)."""
    if fam.fn1 is not None and len(at) <= SCALAR_AT:
        return tuple(face_place1(fam, A0, inv, tau, math.radians(float(x))) for x in at)
    return tuple(float(v) for v in face_place(fam, A0, inv, tau, np.radians(np.asarray(at, dtype=float))))


def _mark_flat(sc: Scene, cam: FlatArmCam, fam: Ref, inv_pos: "ArmInversion", O: Ref, f: float) -> None:
    """The worst positions: the face, the contact K, the relative instant centre P, the common normal KP and,
    for an offset face, α between the normal and K's velocity (⊥ A0′K). A face through the pivot has α ≡ 0:
    the position of the farthest contact is shown instead."""
    parts = ("rise", "return") if f else ("far",)
    size = 0.3 * cam.a
    for part in parts:
        if part == "far":
            where = sc.add("delta_far", extremum_deg, Ref("face_hi"), visible=False)
            cap = ("The farthest contact K (l_max): the common normal at K is perpendicular to the face and "
                   "passes through the relative instant centre P on OA0′ (A0′P = a/(1 − εψ′)); K's velocity is "
                   "along it too, so α = 0 for a face through the pivot",
                   "最远接触点 K(l_max):过 K 的公法线垂直于平底并通过凸轮与摆杆的相对瞬心 P(在 OA0′ 上,"
                   "A0′P = a/(1 − εψ′));K 点速度亦沿此线,平底过转轴时压力角恒为 0")
        else:                       # the rise's K1, P1 and the return's K2, P2: one name for each point
            where = Ref(f"delta_alpha_max_{part}")
            n = "1" if part == "rise" else "2"
            cap = (f"The {part}'s worst position (nearest contact K{n}): the common normal K{n}P{n} through the relative "
                   f"instant centre P{n} on OA0′ (A0′P{n} = a/(1 − εψ′)), K{n}'s velocity ⊥ A0′K{n}, α between them "
                   "(tan α = |f|/l)",
                   f"{'推程' if part == 'rise' else '回程'}压力角最大的位置(接触点 K{n} 最近):公法线 K{n}P{n} 通过相对瞬心 "
                   f"P{n}(在 OA0′ 上,A0′P{n} = a/(1 − εψ′)),K{n} 点速度 ⊥ A0′K{n},二者夹角即 α(tan α = |f|/l)")
        tag = "" if part == "far" else ("1" if part == "rise" else "2")
        A, _, D = inv_pos.position(f"w_{part}", where, caption=cap)
        sc.add(f"wface_{part}", face_span, A, D, O, f, Ref("face_min"), Ref("face_max"), style="link-alt")  # the face L long
        K = sc.add(f"K_{part}", envelope_point, fam, where, style="joint", label=f"K{tag}")
        k = sc.add(f"k_{part}", speed_ratio, cam, where, None if part == "far" else part, visible=False)
        P = sc.add(f"P_{part}", instant_centre, A, O, k, style="point", label=f"P{tag}")
        sc.add(f"normal_{part}", through, K, P, 0.15 * size, style="path")
        sc.add(f"arm_{part}", segment, A, K, style="ghost")
        if f:
            nv = sc.add(f"n_{part}", face_normal, fam, where, visible=False)
            v = sc.add(f"v_{part}", arm_velocity, A, K, cam.tau if part == "rise" else -cam.tau, visible=False)
            sc.add(f"velocity_{part}", velocity_segment, K, v, size, style="ghost")
            sc.add(f"mark_alpha_{part}", pressure_mark, K, nv, v, Ref(f"alpha_max_{part}"), 0.6 * size,
                   "αmax" if part == "rise" else "α′max", role=Role.ANNOTATION, style="angle")


def analytic_flat(g: Mapping[str, Any]) -> list[dict[str, Any]]:
    """The flat-faced arm's closed forms (:mod:`geomcon.cam.oscillating_flat`)."""
    global _LAST_TWIN
    cam = flat_cam_of(g)
    _LAST_TWIN = (g, dict(g), cam)                 # its searches serve this solve's warnings too
    (lo, _), (hi, _) = cam.contact_extremes()
    rho = cam.rho_min()[0]
    convex = rho > 0.0 and not cam.backward_jumps()
    out: dict[str, Any] = {
        "psi_max": math.degrees(float(cam.motion(cam.program.rise.end).psi)), "psi0": math.degrees(cam.psi0),
        "rho_min_actual": rho, "convex": convex, "undercut": not convex, "face_min": lo, "face_max": hi,
        "face_length": max(hi, 0.0) - min(lo, 0.0)}
    for kind in ("rise", "return"):
        alpha, where = cam.worst_pressure(kind)
        out[f"alpha_max_{kind}"] = alpha
        if cam.offset:
            out[f"delta_alpha_max_{kind}"] = deg360(where)
    at = tuple(g.get("at") or ())
    if at:
        out.update(lists_flat(cam, at))
    out.update(follower_speeds(g, angular=True))
    return [out]
