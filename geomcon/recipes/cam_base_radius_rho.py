"""``cam.base_radius`` with a curvature limit (``rho_allow``): the smallest base circle that keeps the radius of
curvature at least ρallow as well as the pressure angle within α_allow (translating followers).

- Flat-faced follower (``follower = "flat"``; its pressure angle is 0, no α limit, no offset): the profile's
  radius of curvature is ρ = r0 + s + s″ (s″ = d²s/dδ², per rad²), so r0 = ρallow − min(s + s″). The
  construction draws the (s + s″)–δ curve, finds its lowest point exactly (roots of s′ + s‴ on every smooth
  piece, :func:`geomcon.cam.kinematics.flat_curvature_floor`), lays off r0 and draws the designed profile as
  the envelope of the faces, whose smallest ρ is measured again. GATE 2020 (ME, paper 1, Q38): y = 4(2πθ −
  θ²), ρ ≥ 40 mm → min(y + y″) = −8 at θ = 0 and 2π, r0 = 48 mm.
- Knife or roller (``alpha_allow`` and ``rho_allow``): the ds/dδ–s construction gives the best offset e (or e
  as given) and the base circle r0α of the pressure-angle limit; at that offset the pitch curve's ρmin (its
  convex parts) grows with r0, and r0 is raised from r0α until ρmin = ρallow when that limit binds — the
  pressure angle only falls as r0 grows at a fixed e (tan α = |s′ − k·e|/(s0 + s), s0 = √(r0² − e²)), so r0 =
  max(r0α, r0ρ) satisfies both. The offset is the pressure angle's best one: a different offset might let
  both limits hold with a smaller circle when the curvature binds (not searched; ``e`` fixes it).

The twin: the flat floor by sampling and golden sections on :mod:`geomcon.analytic.cam_motion`'s laws; r0ρ
by bisection on cam.translating's closed-form ρmin (the construction uses the profile machinery's ρmin and
a regula falsi).
"""
from __future__ import annotations

import math
from typing import Any, Mapping

import numpy as np

from ..analytic.cam_motion import motion as twin_motion, _golden_max
from ..cam.kinematics import flat_curvature_floor
from ..cam.profile import envelope_rho_min, flat_profile
from ..cam.program import Program
from ..cam.translating import TranslatingCam
from ..errors import NotAMechanism
from ..geometry import Point, Polyline, Segment, circle, segment
from ..numeric import bisect_up, illinois
from ..scene import Ref, Role, Scene, marks
from .base import Construction
from .cam_common import add_profile_steps, add_rotation, extremum_value, inversion_sign

GROW_MAX = 1e6
"""Largest factor by which the curvature limit may grow the base circle over the pressure angle's (a limit
needing more is refused: ρallow is then far beyond the cam's size)."""


def is_rho_form(g: Mapping[str, Any]) -> bool:
    """True when the givens ask for a curvature limit (or a flat face, which needs one)."""
    return g.get("rho_allow") is not None or g.get("follower") == "flat"


def validate_rho(g: Mapping[str, Any], prog: Program) -> None:
    """Refuse what the curvature forms cannot do, naming the given."""
    if g.get("motion", "translating") == "oscillating":
        if g.get("rho_allow") is None:
            return                      # (a follower type given for an arm is refused by the recipe's validation)
        if g.get("alpha_allow") is None:
            raise NotAMechanism("alpha_allow is missing: an oscillating follower's base circle needs the allowed "
                                "pressure angle as well as rho_allow")
        if g.get("a") is not None:
            raise NotAMechanism(f"a = {g['a']:g} is given with rho_allow: the curvature limit moves the cam centre, so "
                                "the centre distance cannot stay fixed (leave a out)")
        return
    if g.get("rho_allow") is None:
        raise NotAMechanism("follower = \"flat\" needs rho_allow (the smallest radius of curvature of the profile, "
                            "mm): a translating flat face has no pressure angle to limit")
    if g.get("follower") == "flat":
        for key in ("alpha_allow", "alpha_allow_return", "e"):
            if g.get(key) is not None:
                raise NotAMechanism(f"{key} = {g[key]:g} is given for a flat-faced follower: its pressure angle is 0 "
                                    "and its offset does not change the profile (leave it out)")
        drops = [i for i in prog.impacts(g["h"]) if i.kind == "rigid" and i.jump < 0]
        if drops:
            raise NotAMechanism(f"program: the velocity drops at δ = {drops[0].angle:g}° (s′ jumps down by "
                                f"{-drops[0].jump:.6g} mm/rad): no flat face can follow it, whatever r0")
    elif g.get("alpha_allow") is None:
        raise NotAMechanism("alpha_allow is missing: a knife or roller follower's base circle needs the allowed "
                            "pressure angle (or give follower = \"flat\")")


# ---------------------------------------------------------------------------------------------- flat face
def floor_curve(prog: Program, h: float, origin: Point, width: float, n: int = 720) -> Polyline:
    """The curve (δ/360°·width, s + s″) from ``origin``, over the turn."""
    d = np.linspace(0.0, 2.0 * math.pi, n + 1)
    d[-1] = np.nextafter(2.0 * math.pi, 0.0)
    s, _, a = prog.motion(h, d, radians=True)
    return Polyline(tuple(Point(origin.x + width * x / (2 * math.pi), origin.y + y)
                          for x, y in zip(d.tolist(), (s + a).tolist())))


def floor_of(prog: Program, h: float) -> tuple[float, float]:
    """(min(s + s″), δ deg)."""
    return flat_curvature_floor(prog, h)


def floor_point(floor: tuple[float, float], origin: Point, width: float) -> Point:
    """The lowest point of the (s + s″)–δ curve."""
    return Point(origin.x + width * floor[1] / 360.0, origin.y + floor[0])


def flat_r0(rho_allow: float, floor: tuple[float, float]) -> float:
    """r0 = ρallow − min(s + s″), refused when not positive (ρallow below −min(s + s″) needs no base circle)."""
    r0 = rho_allow - floor[0]
    if not r0 > 0.0:
        raise NotAMechanism(f"rho_allow = {rho_allow:g} − min(s + s″) = {floor[0]:.6g} gives r0 = {r0:.6g} ≤ 0: "
                            "the limit does not bound the base circle")
    return r0


def faces(prog: Program, h: float, r0: float, inv: float):
    """The designed cam's face lines (cam.translating's family)."""
    from .cam_translating import _face_family
    return _face_family(prog, h, r0, inv)


def _floor_axes(sc: Scene, prog: Program, h: float, origin: Point, width: float) -> None:
    """The (s + s″)–δ diagram's ordinate through its origin, named and ticked at the curve's highest and lowest
    values, and the δ axis named and ticked at 90°, 180°, 270°: the diagram says what it plots (ρ = r0 + s + s″ of
    a flat face is least where s + s″ is) and at what size."""
    ys = [p.y - origin.y for p in floor_curve(prog, h, origin, width, 360).points]
    lo, hi = min(ys + [0.0]), max(ys + [0.0])
    pad = 0.06 * width
    top = origin + Point(0.0, hi + pad)
    sc.add("floor_axis", segment, origin + Point(0.0, lo - pad), top, role=Role.ANNOTATION, style="given",
           caption=("Its ordinate s + s″ (mm): the flat face's ρ = r0 + s + s″ is least where s + s″ is",
                    "纵轴 s + s″(mm):平底从动件凸轮廓线 ρ = r0 + s + s″,其最小处即 s + s″ 最小处"))
    sc.given("floor_axis_name", top, label="s + s″ (mm)", style="point")
    sc.given("floor_delta_name", origin + Point(width, 0.0), label="δ", style="point")
    for deg in (90, 180, 270):      # 200-18 ticked 180° alone: the δ axis reads in quarters, as the s–δ charts do
        sc.given(f"floor_tick_{deg}", origin + Point(deg / 360.0 * width, 0.0), label=f"{deg}°", style="tick")
    for name, y in (("hi", hi), ("lo", lo)):   # and its ordinate had no value: the curve's highest and lowest
        if abs(y) > 1e-9 * (hi - lo):          # ordinates ticked with their values (mm), left of the axis
            sc.given(f"floor_value_{name}", origin + Point(0.0, y), label=_mm(y), style="row-start")


def _mm(y: float) -> str:
    """An ordinate's value as the chart prints it, one decimal, a true minus sign.

    >>> _mm(39.4784), _mm(-8.0)
    ('39.5', '−8.0')
    """
    return f"{y:.1f}".replace("-", "−")


FACE_MARGIN = 3.0
"""mm added each side of the contact's excursion on a drawn face: the textbooks' face length L = l′max + l″max +
(5~7) mm (平底长度), its middle shared between the two ends."""


def face_reach(fam, prog: Program, h: float, r0: float, inv: float) -> tuple[float, float]:
    """(left, right): how far the contact runs along the face each side of the axis over the turn
    (cam.translating's :func:`~geomcon.recipes.cam_translating.face_extents`, a centred follower)."""
    from .cam_translating import face_extents
    return face_extents(fam, prog, h, r0, 0.0, inv)


def _flat_follower(sc: Scene, r0: Ref, prog: Program, h: float, reach: Ref) -> None:
    """The flat-faced follower at δ = 0 on the designed cam: the face at s(0) above the base circle, covering the
    contact's excursion ``reach`` (left, right of the axis) with :data:`FACE_MARGIN` to spare at each end (the face
    just covering it lay on 200-18's straight piece of profile, end to end, and could not be seen), its stem and
    guide."""
    s_start = float(prog.motion1(h, 0.0)[0])
    K = sc.add("face_contact", lambda r: Point(0.0, r + s_start), r0, visible=False)
    sc.add("face", lambda k, lr: Segment(k + Point(-lr[0] - FACE_MARGIN, 0.0), k + Point(lr[1] + FACE_MARGIN, 0.0)),
           K, reach, role=Role.RESULT, style="link",
           caption=(f"The flat-faced follower at δ = 0: its face covers the contact's excursion along it over the turn "
                    f"(max |s′| each side of the axis) and {FACE_MARGIN:g} mm more at each end, as the textbooks' "
                    f"L = l′ + l″ + 5~7 mm asks (l′, l″ the contact's reach each side)",
                    f"δ = 0 时的平底从动件:平底覆盖一周中接触点沿平底的移动范围(导路两侧各 max |s′|),两端各再加 "
                    f"{FACE_MARGIN:g} mm,即 L = l′ + l″ + 5~7 mm(l′、l″ 为两侧接触点的最远距离)"))
    sc.add("stem", lambda k, r: Segment(k, k + Point(0.0, 0.9 * r)), K, r0, role=Role.RESULT, style="link")
    sc.add("guide_mark", lambda k, r: marks.bearing(k + Point(0.0, 0.65 * r), Point(0.0, 1.0)), K, r0,
           role=Role.ANNOTATION, style="guide")      # the two bearing walls of every translating follower (a wall on one side was a slider's guide)


def construct_flat_rho(g: Mapping[str, Any], prog: Program) -> Construction:
    """The (s + s″)–δ curve, its lowest point, r0 = ρallow − min, the base circle and the designed profile."""
    h, rho_allow = g["h"], g["rho_allow"]
    inv = inversion_sign(g.get("rotation", "ccw"))
    sc = Scene("Base circle of a flat-faced follower from the curvature limit")
    O = sc.given("O", Point(0.0, 0.0), style="pivot", label="O", caption=("O: the cam's centre", "O:凸轮回转中心"))
    add_rotation(sc, O, 1.0 if g.get("rotation", "ccw") == "ccw" else -1.0, ground=True)
    size = rho_allow + h
    origin = Point(1.6 * size, 0.0)
    width = 3.0 * size
    sc.add("delta_axis", segment, origin, origin + Point(width, 0.0), style="frame",
           caption=("The δ axis (one turn)", "δ 轴(一周)"))
    sc.add("floor_curve", floor_curve, prog, h, origin, width, style="path",
           caption=("Plot s + d²s/dδ² against δ: a flat face's ρ = r0 + s + s″", "作 s + d²s/dδ²–δ 曲线:平底从动件凸轮廓线 ρ = r0 + s + s″"))
    floor = sc.add("floor", floor_of, prog, h, visible=False)
    if sc.drawing:
        _floor_axes(sc, prog, h, origin, width)
    sc.add("floor_point", floor_point, floor, origin, width, style="joint", label="min(s + s″)",
           caption=("Its lowest point (exact: a root of s′ + s‴ or an end of a piece)", "其最低点(精确:s′ + s‴ 的根或分段端点)"))
    r0 = sc.add("r0", flat_r0, rho_allow, floor, role=Role.MEASUREMENT, unit="mm",
                caption=(f"r0 = ρ_allow − min(s + s″) with ρ_allow = {rho_allow:g}", f"r0 = ρ_allow − min(s + s″),ρ_allow = {rho_allow:g}"))
    sc.add("r0_rho", float, r0, visible=False)
    sc.add("base", circle, O, r0, style="theta-circle", caption=("Draw the base circle", "作基圆"))
    if sc.drawing:
        sc.add("dim_r0", lambda o, r: marks.Dimension(o, o + Point(-r, -r) * math.sqrt(0.5), "r0", r, 0.0), O, r0,
               role=Role.ANNOTATION, style="dim")
    fam = sc.add("faces", faces, prog, h, r0, inv, visible=False)
    add_profile_steps(sc, flat_profile, (fam, 1e-5 * (size + h)),
                      ("The designed profile: the envelope of the faces", "所设计凸轮廓线:平底直线族的包络线"))
    rho = sc.add("rho_profile", envelope_rho_min, fam, visible=False)
    sc.add("rho_min_profile", extremum_value, rho, role=Role.MEASUREMENT, unit="mm",
           caption=("Its smallest radius of curvature, measured on the envelope", "在包络线上量得其最小曲率半径"))
    if sc.drawing:                          # the follower on the designed cam, its face as wide as the contact runs
        _flat_follower(sc, r0, prog, h, sc.add("face_reach", face_reach, fam, prog, h, r0, inv, visible=False))
    names = ("r0", "r0_rho", "rho_min_profile")
    return Construction(sc, {n: n for n in names}, {"O": "O"})


def twin_floor(program: Any, h: float) -> float:
    """min(s + s″) over the turn by the twin's laws: samples every 0.05°, golden sections about the lowest few
    (and the one-sided segment ends)."""
    def g(d):
        s, _, a = twin_motion(program, h, d)
        return -(s + a)

    ends, start = [], 0.0
    for row in program:
        ends += [start, math.nextafter(start + float(row["angle"]), start)]
        start += float(row["angle"])
    grid = np.linspace(0.0, 360.0, 7201).tolist()
    vals = [g(d) for d in grid]
    best = max(max(vals), *(g(d) for d in ends))
    for i in sorted(range(len(grid)), key=lambda i: -vals[i])[:6]:
        best = max(best, _golden_max(g, grid[max(i - 1, 0)], grid[min(i + 1, len(grid) - 1)]))
    return -best


def analytic_flat_rho(g: Mapping[str, Any], prog: Program) -> list[dict[str, float]]:
    r0 = g["rho_allow"] - twin_floor(g["program"], g["h"])
    rho = TranslatingCam(prog, g["h"], r0, 0.0, g.get("rotation", "ccw")).flat_rho_min()
    return [{"r0": r0, "r0_rho": r0, "rho_min_profile": rho}]


# ---------------------------------------------------------------------------------------------- knife, roller
def grow_for_rho(prog: Program, h: float, rotation: str, e: float, r0_alpha: float, rho_allow: float) -> float:
    """The smallest r0 ≥ r0α with ρmin(pitch) ≥ ρallow at the offset e: r0α when it already holds, else the
    root of ρmin(r0) = ρallow by regula falsi (Illinois) between r0α and a doubled bracket."""
    from .cam_base_radius import pitch_rho_min

    def f(r0: float) -> float:
        return pitch_rho_min(prog, h, rotation, e, math.sqrt((r0 - e) * (r0 + e))) - rho_allow

    lo, flo = r0_alpha, f(r0_alpha)
    if flo >= 0.0:
        return r0_alpha
    hi = 2.0 * lo
    fhi = f(hi)
    while fhi < 0.0:
        if hi > GROW_MAX * r0_alpha:
            raise NotAMechanism(f"rho_allow = {rho_allow:g} needs a base circle over {GROW_MAX:g} times the pressure "
                                f"angle's r0 = {r0_alpha:.6g}")
        lo, flo, hi = hi, fhi, 2.0 * hi
        fhi = f(hi)
    return illinois(f, lo, flo, hi, fhi)


def add_rho_steps(sc: Scene, answers: dict[str, str], g: Mapping[str, Any], prog: Program) -> None:
    """After the pressure angle's construction (steps O, r0, e): r0 grown for the curvature limit, the final
    centre and base circle, s0, ρmin and rr_max of the designed cam."""
    from .cam_base_radius import RR_FACTOR, away_from, pitch_rho_min
    h, rot, rho_allow = g["h"], g.get("rotation", "ccw"), g["rho_allow"]
    B0 = Ref("B0")
    sc.add("r0_alpha", float, Ref("r0"), role=Role.MEASUREMENT, unit="mm", visible=False)
    r0 = sc.add("r0_design", grow_for_rho, prog, h, rot, Ref("e"), Ref("r0"), rho_allow, role=Role.MEASUREMENT,
                unit="mm", caption=(f"Grow r0 at this offset until ρmin of the pitch curve reaches ρallow = {rho_allow:g} "
                                    "(α only falls as r0 grows)",
                                    f"保持偏距增大 r0,直至理论廓线 ρmin 达到 ρallow = {rho_allow:g}(r0 增大时 α 只减小)"))
    sc.add("r0_rho", lambda r, ra: r if r > ra else ra, r0, Ref("r0"), visible=False)
    s0 = sc.add("s0_design", lambda r, e: math.sqrt((r - e) * (r + e)), r0, Ref("e"), role=Role.MEASUREMENT, unit="mm",
                visible=False)
    O = sc.add("O_design", lambda e, s: Point(-e, -s), Ref("e"), s0, role=Role.RESULT, style="pivot", label="O′",
               caption=("The designed centre O′ (on the vertical through O)", "设计所得回转中心 O′(在过 O 的铅垂线上)"))
    sc.add("base_design", circle, O, r0, style="theta-circle", caption=("Its base circle", "其基圆"))
    sc.add("O_B0_design", segment, O, B0, style="construction")
    sc.add("dim_r0_design", lambda o, b, v: marks.Dimension(o, b, "r0", v, -0.3 * v), O, B0, r0,
           role=Role.ANNOTATION, style="dim", caption=("The answer r0 = O′B0 (the curvature limit decides)",
                                                       "所求基圆半径 r0 = O′B0(由曲率半径限制决定)"))
    F = sc.add("O_design_foot", lambda o: Point(0.0, o.y), O, visible=False)
    sc.add("dim_s0_design", lambda f, b, v, o: marks.Dimension(f, b, "s0", v, 0.3 * v * away_from(o)), F, B0, s0, O,
           role=Role.ANNOTATION, style="dim")
    rho = sc.add("rho_design", pitch_rho_min, prog, h, rot, Ref("e"), s0, role=Role.MEASUREMENT, unit="mm",
                 caption=("ρmin of the designed pitch curve", "所设计理论廓线的 ρmin"))
    sc.add("rr_max_design", lambda r: RR_FACTOR * r, rho, role=Role.MEASUREMENT, unit="mm", visible=False)
    answers.update({"r0": "r0_design", "s0": "s0_design", "rho_min_pitch": "rho_design", "rr_max": "rr_max_design",
                    "r0_alpha": "r0_alpha", "r0_rho": "r0_rho"})


def twin_grow(prog: Program, h: float, rotation: str, e: float, r0_alpha: float, rho_allow: float) -> float:
    """:func:`grow_for_rho` by bisection on cam.translating's closed-form ρmin."""
    def f(r0: float) -> float:
        return TranslatingCam(prog, h, r0, e, rotation).rho_min_pitch() - rho_allow

    if f(r0_alpha) >= 0.0:
        return r0_alpha
    lo, hi = r0_alpha, 2.0 * r0_alpha
    while f(hi) < 0.0:
        lo, hi = hi, 2.0 * hi
    return bisect_up(f, lo, hi)


def margins(g: Mapping[str, Any], prog: Program, r0: float, e: float) -> float:
    """The smallest relative margin of the limits on the designed cam: (α_allow − α_max)/α_allow of the rise
    (and return when limited) and (ρmin − ρallow)/ρallow; 0 when the design is the smallest (one limit
    active), never negative."""
    cam = TranslatingCam(prog, g["h"], r0, e, g.get("rotation", "ccw"))
    out = [(g["alpha_allow"] - cam.alpha_max("rise")[0]) / g["alpha_allow"],
           (cam.rho_min_pitch() - g["rho_allow"]) / g["rho_allow"]]
    if g.get("alpha_allow_return") is not None:
        out.append((g["alpha_allow_return"] - cam.alpha_max("return")[0]) / g["alpha_allow_return"])
    return min(out)
