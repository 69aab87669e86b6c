"""``cam.base_radius``: the smallest base circle (and the best offset) of a disc cam with a translating knife
or roller follower for an allowed pressure angle — the textbook's ds/dδ–s diagram — and the best cam centre
for an oscillating knife or roller follower (the arm's velocity images).

Construction (the diagram is drawn in the follower's frame, B0 — the lowest pitch point — at the origin, the
follower's axis vertical): every cam angle δ of a constrained part (the rise, and the return when
``alpha_allow_return`` is given) gives the point (−k·ds/dδ, s) (ds/dδ laid off perpendicular to the axis,
turned by 90° with ω: k = +1 for a counter-clockwise cam). The cam centre O may lie only where every such
point P sees the axis's direction within α_allow: below both lines through P at α_allow to the axis. So the
admissible region is bounded by the two support lines of the curve at α_allow on either side of the
vertical (their tangent points are where the curve's slope is ±1/tan α_allow); with a return limit there
are two more. The best O is the admissible point nearest B0 (the meeting point of the two tangent lines,
or the foot of the perpendicular from B0 on one of them when that foot is admissible — α_allow ≥ 45°); with
a given offset e, O is the highest admissible point on the vertical x = −e. Then r0 = OB0, s0 = the height of
B0 above O, e = the distance of O from the axis (e > 0: the axis right of O, the recipes' convention).

Oscillating follower (``motion = "oscillating"``; ``h`` is then the angular stroke in degrees, ``L`` the arm,
``arm`` and ``rotation`` as in cam.oscillating): drawn in the arm's frame, A0 at the origin and A0B0 = L along
the x axis. The arm is turned to its positions A0Bi at every sixth of the rise (and of the return when it has
a limit); on each, Ki with BiKi = L·ψ′i is laid off (towards A0 when the arm rises in the cam's sense, away
from it otherwise), so that KiO is parallel to the contact normal (:mod:`geomcon.cam.base_radius`); through Ki
the two lines at α_allow to the arm's normal bound the wedge O must lie in. O is the admissible point nearest
B0 — the smallest base circle r0 = OB0 — or, with ``a`` given, the admissible point of the circle of radius
a about A0 nearest B0; the binding positions (one, or two at a vertex of the region) are drawn with the
line KO, which makes α_allow with their normal. Answers r0, a = OA0, ψ0 = ∠OA0B0, ρmin and rr_max. With
``rho_allow`` the centre then moves perpendicular to A0B0 until the pitch curve's ρmin reaches it
(:mod:`.cam_base_radius_arm_rho`).

The roller bound: ρmin of the pitch curve of the designed cam (convex parts, exact derivatives), and the
textbook rule rr ≤ 0.8·ρmin (``rr_max``; rr < ρmin is the bare undercut limit).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Mapping

import numpy as np

from ..cam.arm_twin import ArmTwin, arm_rho_min
from ..cam.base_radius import RR_FACTOR, S0_MIN, ArmProgram, arm_best, arm_psi0, arm_reach, best_base, limits, part_motion
from ..cam.oscillating import OscillatingCam
from ..cam.profile import PitchCurve, inverted, inverted1, maximise, rho_min
from ..cam.program import Program, parse_program
from ..cam.translating import TranslatingCam
from ..errors import NotAMechanism
from ..geometry import Arc, Line, Point, Polyline, Segment, circle, line_line, rotate, segment
from ..geometry.measure import angle_at
from ..scene import Ref, Role, Scene, marks
from .base import Construction, Quantity, Recipe
from .cam_base_radius_rho import (add_rho_steps, analytic_flat_rho, construct_flat_rho, is_rho_form, margins,
                                  twin_grow, validate_rho)
from .cam_base_radius_arm_rho import arm_margins, grow_arm_centre, twin_arm_grow
from .cam_common import add_rotation
from .common import add_angle_mark, add_bar, angle_deg, length

ALPHA_MIN = 1e-6
"""Smallest allowed pressure angle (deg): the two lines at ±α_allow through a point of the diagram stay 3.5e-8
rad apart, far from the 1e-13 at which intersections call lines parallel (a base circle that large is refused
by :func:`r0_floor` for most programs anyway)."""

GIVENS = (
    Quantity("h", "mm", "stroke: mm (translating), or the arm's angular stroke ψmax in degrees (oscillating)",
             unit_when=(("motion", "oscillating", "deg"),)),
    Quantity("program", "table[]", "motion program: rise, dwells, return (a full turn)"),
    Quantity("alpha_allow", "deg", "allowed pressure angle of the rise, 1e-6° ≤ α_allow < 90° (below, the lines "
             "at ±α_allow are within 1e-8 rad of each other; an arm needs about α_allow > h/2 for the wedges to meet); "
             "required except for a flat face", required=False, minimum=ALPHA_MIN, inclusive=True, maximum=90.0),
    Quantity("alpha_allow_return", "deg", "allowed pressure angle of the return (unconstrained when absent), "
             "1e-6° ≤ α < 90°", required=False, minimum=ALPHA_MIN, inclusive=True, maximum=90.0),
    Quantity("rotation", "choice", "sense of rotation of the cam", required=False, default="ccw", minimum=None,
             choices=("ccw", "cw")),
    Quantity("e", "mm", "a fixed offset (> 0: the axis right of O); absent: the best offset", required=False,
             minimum=None),
    Quantity("motion", "choice", "the follower moves along a guide (translating) or swings on an arm (oscillating)",
             required=False, default="translating", minimum=None, choices=("translating", "oscillating")),
    Quantity("L", "mm", "oscillating: arm length A0B (pivot to roller centre or knife edge)", required=False),
    Quantity("a", "mm", "oscillating: a fixed centre distance OA0; absent: the best one", required=False),
    Quantity("arm", "choice", "oscillating: side of the line A0→O the roller lies on, as in cam.oscillating",
             required=False, default="left", minimum=None, choices=("left", "right")),
    Quantity("rho_allow", "mm", "smallest allowed radius of curvature — of the pitch curve (knife, roller, translating "
             "or oscillating; its convex parts) or of the profile (translating flat face: r0 + s + s″ ≥ ρallow)",
             required=False),
    Quantity("follower", "choice", "translating: knife or roller (the pressure-angle design) or flat (a flat face: "
             "curvature limit only, α ≡ 0)", required=False, default=None, minimum=None,
             choices=("knife", "roller", "flat")),
)
ANSWERS = (
    Quantity("r0", "mm", "smallest base circle radius of the pitch curve"),
    Quantity("e", "mm", "the offset (best, or as given): > 0 puts the follower's axis right of O"),
    Quantity("s0", "mm", "height of the lowest pitch point B0 above O, √(r0² − e²)"),
    Quantity("rho_min_pitch", "mm", "smallest radius of curvature of the pitch curve (convex parts)"),
    Quantity("rr_max", "mm", "largest roller radius by the rule rr ≤ 0.8·ρmin"),
    Quantity("a", "mm", "oscillating: the centre distance OA0 (best, or as given)"),
    Quantity("psi0", "deg", "oscillating: the arm's initial angle ψ0 = ∠OA0B0"),
    Quantity("r0_alpha", "mm", "with rho_allow (knife, roller): the base circle the pressure-angle limit alone needs"),
    Quantity("r0_rho", "mm", "with rho_allow: the base circle the curvature limit needs (at the design's offset; at "
             "least r0_alpha for a knife or roller)"),
    Quantity("rho_min_profile", "mm", "flat face: the designed profile's smallest radius of curvature, min(r0 + s + s″)"),
)


def _program(g: Mapping[str, Any]) -> Program:
    prog = parse_program(g["program"])
    if not prog.full:
        raise NotAMechanism("program: a cam needs a full turn (the segment angles must add up to 360°)")
    return prog


def _validate(g: Mapping[str, Any]) -> list[str]:
    prog = _program(g)
    if is_rho_form(g):
        validate_rho(g, prog)
        if g.get("follower") == "flat" and g.get("motion", "translating") == "translating":
            return []
    elif g.get("alpha_allow") is None:
        raise NotAMechanism("alpha_allow is missing (the allowed pressure angle of the rise, degrees)")
    if g.get("follower") is not None and g.get("motion", "translating") == "oscillating":
        raise NotAMechanism(f"follower = {g['follower']!r} is given for an oscillating follower (knife or roller arm: "
                            "leave it out)")
    for key in ("alpha_allow", "alpha_allow_return"):
        if g.get(key) is not None and not 0.0 < g[key] < 90.0:
            raise NotAMechanism(f"{key} = {g[key]:g}° must lie in (0°, 90°)")
    if g.get("motion", "translating") == "translating":
        for key in ("L", "a"):
            if g.get(key) is not None:
                raise NotAMechanism(f"{key} = {g[key]:g} is given for a translating follower: only an oscillating "
                                    "one (motion = \"oscillating\") has an arm")
        r0_floor(_program(g), g["h"], limits(_program(g), g["alpha_allow"], g.get("alpha_allow_return")))
        return []
    if g.get("L") is None:
        raise NotAMechanism("an oscillating follower needs L (the arm length A0B)")
    if g.get("e") is not None:
        raise NotAMechanism(f"e = {g['e']:g} is given for an oscillating follower: it has no offset (give a, the "
                            "centre distance, or nothing)")
    if not g["h"] < 180.0:
        raise NotAMechanism(f"h = {g['h']:g}°: an arm's angular stroke must be below 180°")
    prog = _program(g)
    arm_reach(ArmProgram(g["h"], prog, g.get("rotation", "ccw"), g.get("arm", "left")), g["L"],
              limits(prog, g["alpha_allow"], g.get("alpha_allow_return")), g.get("a"))
    return []


R0_SPAN = 1e10
"""Largest base circle of a translating follower's design, in units of h: the global span of one problem's
lengths (:data:`geomcon.problems.LENGTH_SPAN`). Beyond it the support lines at α_allow are within rounding of
the axis's direction (tan α_allow ~ h/r0) and their meeting points are lost in it."""


def r0_floor(prog: Program, h: float, lims: list) -> float:
    """A lower bound of the base circle whatever the offset, refused beyond :data:`R0_SPAN`·h.

    A cam angle with velocity s′ in a part limited to tan α_allow = t needs s0 ≥ |s′ − k·e|/t − s. Two such
    angles (of the same part or of the rise and the return) with s′1 > s′2 cannot both have |s′i − k·e| below
    (s′1 − s′2)·ti/(t1 + t2), so r0 ≥ s0 ≥ (s′1 − s′2)/(t1 + t2) − h for any e. The extreme s′ of each part
    are taken on a grid (values the motion really takes, so the bound stays a bound).

    Examples
    --------
    >>> from geomcon.cam.base_radius import limits
    >>> prog = parse_program([{"kind": "rise", "angle": 180, "law": "cosine"}, {"kind": "dwell", "angle": 180}])
    >>> r0_floor(prog, 10.0, limits(prog, 45.0)) == 0.0        # the limit binds nowhere near the bound
    True
    >>> try:
    ...     r0_floor(prog, 10.0, limits(prog, 1e-12))
    ... except NotAMechanism as exc:
    ...     print(str(exc).split(",")[0])
    alpha_allow = 1e-12° needs a base circle r0 ≥ 1.43239e+14 mm
    """
    parts = []
    for lim in lims:
        d = np.linspace(lim.lo, lim.hi, 257)
        d[-1] = np.nextafter(lim.hi, lim.lo)
        v = prog.motion(h, d, radians=True)[1]
        parts.append((float(np.min(v)), float(np.max(v)), lim))
    out, worst = 0.0, None
    for _, hi, a in parts:
        for lo, _, b in parts:
            floor = (hi - lo) / (a.t + b.t) - h
            if floor > out:
                out, worst = floor, (a, b)
    if out > R0_SPAN * h:
        names = " and ".join(dict.fromkeys(
            f"{'alpha_allow' if x.part == 'rise' else 'alpha_allow_return'} = {math.degrees(math.atan(x.t)):g}°"
            for x in worst))
        span = f"{R0_SPAN:g}".replace("e+", "e")
        raise NotAMechanism(f"{names} need{'s' if ' and ' not in names else ''} a base circle r0 ≥ {out:g} mm, more "
                            f"than {span}·h (h = {h:g}): the lines at α_allow are within rounding of the axis — allow "
                            "a larger pressure angle")
    return out


# ---------------------------------------------------------------------------- step operations
def diagram_points(prog: Program, h: float, k: float, lo: float, hi: float, n: int = 240) -> Polyline:
    """The curve (−k·s′, s) over cam angles [lo, hi] (radians)."""
    d = np.linspace(lo, hi, n + 1)
    d[-1] = np.nextafter(hi, lo)
    s, v, _ = prog.motion(h, d, radians=True)
    return Polyline(tuple(Point(-k * x, y) for x, y in zip(v.tolist(), s.tolist())))


def support_line(prog: Program, h: float, k: float, lo: float, hi: float, t: float, side: float) -> Line:
    """The support line of the curve at α_allow on one side: direction (side·t, 1), through the point where
    s − side·X/t is smallest (golden-section on the exact (s, s′); the tangent point)."""
    def g(d):
        s, v, _ = prog.motion(h, d, radians=True)
        return -(s - side * (-k * v) / t)

    def g1(d: float) -> float:                  # g on one float (the same bits): Brent refines the peak
        s, v, _ = prog.motion1(h, d, True)
        return -(s - side * (-k * v) / t)
    top = maximise(g, [(lo, hi)], dense=2048, g1=g1)
    s, v, _ = prog.motion(h, top.delta, radians=True)
    return Line(Point(-k * float(v), float(s)), Point(side * t, 1.0))


def below_all(p: Point, lines: tuple[Line, ...], scale: float) -> bool:
    """True when p lies on or below every line (the admissible side, away from the curve)."""
    for ln in lines:
        d = ln.direction
        size = max(scale, abs(p.x), abs(p.y), abs(ln.point.x), abs(ln.point.y))
        if p.y - (ln.point.y + (p.x - ln.point.x) * d.y / d.x) > 1e-12 * size * (1.0 + abs(d.y / d.x)):
            return False
    return True


def nearest_admissible(origin: Point, lines: tuple[Line, ...], e: float | None, scale: float) -> Point:
    """The admissible point nearest ``origin`` (feet on the lines and their meeting points), or with a given
    offset the highest admissible point of the vertical through (−e, 0)."""
    if e is not None:
        vert = Line(Point(-e, 0.0), Point(0.0, 1.0))
        pts = [line_line(vert, ln)[0] for ln in lines]
        return min(pts, key=lambda p: p.y)
    cands = [ln.at((origin - ln.point).dot(ln.direction)) for ln in lines]
    for i, a in enumerate(lines):
        for b in lines[i + 1:]:
            cands += list(line_line(a, b))
    ok = [p for p in cands if below_all(p, lines, scale)]
    return min(ok, key=lambda p: abs(p - origin))


def pitch_rho_min(prog: Program, h: float, rotation: str, e: float, s0: float) -> float:
    """ρmin of the designed pitch curve (convex parts), from the inversion with exact derivatives; refined on
    the scalar path (``fn1``: the same operations on one float, so the same bits as ``fn``)."""
    def fn(d):
        s, v, a = prog.motion(h, d, radians=True)
        z = np.zeros_like(s)
        return inverted(d, rotation, (z + e, s0 + s), (z, v), (z, a))

    motion1, ex = prog.motion1, e + 0.0          # e + 0 as z + e

    def fn1(d):
        s, v, a = motion1(h, d, True)
        return inverted1(d, rotation, (ex, s0 + s), (0.0, v), (0.0, a))
    breaks = []
    for seg in prog.segments:
        breaks.append(math.radians(seg.end))
        if seg.law is not None and seg.law.name == "parabolic":
            breaks.append(math.radians(seg.start + seg.angle / 2))
    return rho_min(PitchCurve(fn, tuple(b for b in breaks if 0 < b < 2 * math.pi), fn1=fn1)).value


def height_above(O: Point, h: float, alpha_allow: float) -> float:
    """s0 = the height of B0 above O; refused at or below S0_MIN·h (the base circle all but touches the
    offset circle: the limit α_allow hardly constrains the cam)."""
    if not -O.y > S0_MIN * h:
        raise NotAMechanism(f"the centre puts B0 at s0 = {-O.y:.6g} mm ≤ {S0_MIN:g}·h from the offset circle's "
                            f"tangent point: no proper cam — the limit α_allow = {alpha_allow:g}° hardly constrains it")
    return -O.y


# ---------------------------------------------------------------------------- construction
def construct(g: Mapping[str, Any]) -> Construction:
    """The ds/dδ–s diagram, the support lines at α_allow, the best O and the base circle (translating), or
    the arm's positions with their velocity-image points (oscillating, :func:`construct_arm`)."""
    if g.get("motion", "translating") == "oscillating":
        return construct_arm(g)
    if g.get("follower") == "flat":
        return construct_flat_rho(g, _program(g))
    prog, h = _program(g), g["h"]
    rotation = g.get("rotation", "ccw")
    k = 1.0 if rotation == "ccw" else -1.0
    sc = Scene("Base circle from the ds/dδ–s diagram")
    B0 = sc.given("B0", Point(0.0, 0.0), style="joint", caption=("B0: the follower's lowest pitch point",
                                                                 "B0:从动件最低位置(理论廓线)"))
    sc.add("axis", Line, B0, Point(0.0, 1.0), role=Role.GIVEN, style="frame",
           caption=("The follower's axis through B0, s upwards", "过 B0 作导路,s 向上"))
    parts = [("rise", prog.rise, g["alpha_allow"])]
    if g.get("alpha_allow_return") is not None and prog.ret is not None:
        parts.append(("return", prog.ret, g["alpha_allow_return"]))
    lines = []
    for part, seg, allow in parts:
        lo, hi, t = math.radians(seg.start), math.radians(seg.end), math.tan(math.radians(allow))
        zh = "推程" if part == "rise" else "回程"
        sc.add(f"curve_{part}", diagram_points, prog, h, k, lo, hi, style="path",
               caption=(f"Lay off ds/dδ across the axis at every s of the {part}: the curve (ds/dδ, s)",
                        f"{zh}各点沿垂直导路方向量取 ds/dδ(顺 ω 转 90°),得 ds/dδ–s 曲线"))
        for side, name in ((1.0, "a"), (-1.0, "b")):
            lines.append(sc.add(f"line_{part}_{name}", support_line, prog, h, k, lo, hi, t, side,
                                style="admissible",
                                caption=(f"The line at α_allow = {allow:g}° to the axis touching the curve",
                                         f"作与导路成 [α] = {allow:g}° 且与曲线相切的直线")
                                if name == "a" else ("…and the one on the other side", "及另一侧的切线")))
    scale = h + max(abs(p.x) for p in diagram_points(prog, h, k, 0.0, 2 * math.pi, 720).points)
    O = sc.add("O", nearest_admissible, B0, tuple(lines), g.get("e"), scale, role=Role.RESULT, style="pivot",
               label="O", caption=("The admissible point nearest B0 is the best centre O" if g.get("e") is None else
                                   f"The highest admissible point at e = {g['e']:g} from the axis: the centre O",
                                   "可行域内离 B0 最近的点即最佳回转中心 O" if g.get("e") is None else
                                   "在偏距 e 处可行域的最高点即回转中心 O"))
    add_rotation(sc, O, k, ground=True)
    r0 = sc.add("r0", length, O, B0, role=Role.MEASUREMENT, unit="mm",
                caption=("r0 = OB0", "基圆半径 r0 = OB0"))
    sc.add("base", circle, O, r0, style="theta-circle", caption=("Draw the base circle", "作基圆"))
    sc.add("OB0", segment, O, B0, style="construction", caption=("", ""))
    e = sc.add("e", lambda o: -o.x, O, role=Role.MEASUREMENT, unit="mm",
               caption=("e = the distance of O from the axis (> 0: the axis right of O)", "偏距 e(导路在 O 右侧为正)"))
    s0 = sc.add("s0", height_above, O, h, g["alpha_allow"], role=Role.MEASUREMENT, unit="mm",
                caption=("s0 = height of B0 above O",
                                                                                   "s0:B0 在 O 上方的高度"))
    rho = sc.add("rho_min_pitch", pitch_rho_min, prog, h, rotation, e, s0, role=Role.MEASUREMENT, unit="mm",
                 caption=("ρmin of the pitch curve (convex parts, exact derivatives)", "理论廓线最小曲率半径 ρmin"))
    sc.add("rr_max", lambda r: RR_FACTOR * r, rho, role=Role.MEASUREMENT, unit="mm",
           caption=("rr ≤ 0.8·ρmin", "滚子半径 rr ≤ 0.8ρmin"))
    limited = g.get("rho_allow") is not None        # the pressure angle's r0 is then r0,α, not the answer
    sc.add("dim_r0", r0_dimension, O, B0, r0, "r0,α" if limited else "r0", 0.08 * scale, not limited,
           role=Role.ANNOTATION, style="dim")
    if sc.drawing:
        _diagram_axes(sc, prog, h, k, B0, O, e, None if limited else s0, scale)
    names = ("r0", "e", "s0", "rho_min_pitch", "rr_max")
    answers = {n: n for n in names}
    if g.get("rho_allow") is not None:
        add_rho_steps(sc, answers, g, prog)
    return Construction(sc, answers, {"O": "O", "B0": "B0"})


R0_APART = 0.25
"""|e| below this fraction of r0 puts r0's dimension OB0 on top of s0's (the height of B0 above O, dimensioned
along the axis beside it): r0 is then dimensioned along the radius at :data:`R0_RADIUS` instead."""
R0_RADIUS = 200.0
"""Direction (deg, from +x) of the radius r0 is dimensioned on when OB0 lies along the axis: down-left, off the
ds/dδ diagram above B0, the pressure-angle lines through the region below O and the ω arrow beside O."""


def r0_dimension(O: Point, B0: Point, r0: float, symbol: str, offset: float, with_s0: bool) -> marks.Dimension:
    """r0 dimensioned along OB0, beside it; or, when s0 is dimensioned along the axis and OB0 nearly lies on it
    (|e| < :data:`R0_APART`·r0: 200-10 printed r0 and s0 on one segment, the one over the other), along the radius
    at :data:`R0_RADIUS` (a textbook's radius dimension of the base circle)."""
    if with_s0 and abs(B0.x - O.x) < R0_APART * r0:
        t = math.radians(R0_RADIUS)
        return marks.Dimension(O, Point(O.x + r0 * math.cos(t), O.y + r0 * math.sin(t)), symbol, r0, 0.0)
    return marks.Dimension(O, B0, symbol, r0, offset)


def away_from(O: Point) -> float:
    """The sign of the offset that dimensions a height along the follower's axis (x = 0, upwards) on the side of
    the axis away from O: O's side held its dimension lines and the arrow ω (200-09's s0 ended by O, under ω;
    200-19's s0 ran through O). O on the axis: its left, as before.

    >>> away_from(Point(-7.0, -12.0)), away_from(Point(5.0, -3.0)), away_from(Point(0.0, -20.0))
    (-1.0, 1.0, 1.0)
    """
    return -1.0 if O.x < 0.0 else 1.0


def foot_on_axis(O: Point) -> Point:
    """The foot of the perpendicular from O to the follower's axis x = 0."""
    return Point(0.0, O.y)


def _diagram_axes(sc: Scene, prog: Program, h: float, k: float, B0: Ref, O: Ref, e: Ref, s0: Ref | None,
                  scale: float) -> None:
    """The ds/dδ–s diagram as a diagram: the s axis (the follower's axis) and the ds/dδ axis through B0 with
    their names, ticks at s = h and at the curve's widest ds/dδ on either side, and the offset e and the height
    s0 of B0 above O dimensioned (e's side read from the figure: O left or right of the axis); ``s0`` None
    leaves s0 to the curvature limit's centre O′ (:func:`~.cam_base_radius_rho.add_rho_steps`)."""
    xs = [p.x for p in diagram_points(prog, h, k, 0.0, 2 * math.pi, 720).points]
    lo, hi = min(xs + [0.0]), max(xs + [0.0])
    pad = 0.08 * scale
    sc.add("ds_axis", segment, Point(lo - pad, 0.0), Point(hi + pad, 0.0), role=Role.ANNOTATION, style="given",
           caption=("The ds/dδ axis through B0, across the follower's axis (mm: ds/dδ per radian)",
                    "过 B0 作 ds/dδ 轴(垂直于导路)"))
    sc.given("ds_axis_name", Point(hi + pad, 0.0), label="ds/dδ", style="point")
    sc.given("s_axis_name", Point(0.0, h + 2 * pad), label="s", style="point")
    sc.given("tick_h", Point(0.0, h), label="h", style="tick")
    for side, x in (("l", lo), ("r", hi)):
        if abs(x) > 1e-9 * scale:
            sc.given(f"tick_ds_{side}", Point(x, 0.0), label=f"{abs(x):.1f}", style="tick")
    F = sc.add("O_foot", foot_on_axis, O, visible=False)
    sc.add("dim_e", lambda o, f, v: marks.Dimension(f, o, "e", v, 0.06 * scale) if abs(v) > 1e-9 * scale
           else None, O, F, e, role=Role.ANNOTATION, style="dim", optional=True,
           caption=("e: O's distance from the follower's axis (O left of the axis: e > 0)",
                    "偏距 e:O 到导路的距离(O 在导路左侧为正)"))
    if s0 is not None:                   # a curvature limit moves the centre: s0 is dimensioned at O′ instead
        sc.add("dim_s0", lambda f, b, v, o: marks.Dimension(f, b, "s0", v, 0.1 * scale * away_from(o)), F, B0, s0, O,
               role=Role.ANNOTATION, style="dim")


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """Minimise r0(e)² = e² + s0(e)² (:mod:`geomcon.cam.base_radius`); ρmin from cam.translating's closed form.
    Oscillating: :class:`~geomcon.cam.base_radius.ArmTwin`, ρmin by cam.oscillating's complex route."""
    prog = _program(g)
    if g.get("motion", "translating") == "oscillating":
        out = ArmTwin(prog, g["h"], g["L"], alpha_allow=g["alpha_allow"], rotation=g.get("rotation", "ccw"),
                      arm=g.get("arm", "left"), alpha_allow_return=g.get("alpha_allow_return")).best(g.get("a"))
        if g.get("rho_allow") is not None:
            out = {**out, **twin_arm_grow(g, out)}
        cam = arm_cam(g, out["a"], out["r0"], out["psi0"])
        rho = arm_rho_min(cam)
        return [{**out, "rho_min_pitch": rho, "rr_max": RR_FACTOR * rho}]
    if g.get("follower") == "flat":
        return analytic_flat_rho(g, prog)
    out = best_base(prog, g["h"], alpha_allow=g["alpha_allow"], rotation=g.get("rotation", "ccw"),
                    alpha_allow_return=g.get("alpha_allow_return"), e=g.get("e"))
    if g.get("rho_allow") is not None:
        r0 = twin_grow(prog, g["h"], g.get("rotation", "ccw"), out["e"], out["r0"], g["rho_allow"])
        out = {**out, "r0_alpha": out["r0"], "r0_rho": r0, "r0": r0, "s0": math.sqrt((r0 - out["e"]) * (r0 + out["e"]))}
    rho = TranslatingCam(prog, g["h"], out["r0"], out["e"], g.get("rotation", "ccw")).rho_min_pitch()
    return [{**out, "rho_min_pitch": rho, "rr_max": RR_FACTOR * rho}]


def back_check(g: Mapping[str, Any], ans: Mapping[str, float]) -> list[tuple[str, float, float, str]]:
    """The designed cam's largest pressure angles (cam.translating's closed form): the active limit is
    reached exactly, the other is not exceeded (oscillating: cam.oscillating's α_max)."""
    prog = _program(g)
    if g.get("motion", "translating") == "oscillating":
        cam = arm_cam(g, ans["a"], ans["r0"], ans["psi0"])
        if g.get("rho_allow") is not None:
            return [("the limits' smallest relative margin (0: one active, none exceeded)", arm_margins(g, cam), 0.0, "")]
        over = cam.worst_pressure("rise")[0] - g["alpha_allow"]
        if g.get("alpha_allow_return") is not None and prog.ret is not None:
            over = max(over, cam.worst_pressure("return")[0] - g["alpha_allow_return"])
        return [("alpha_max − alpha_allow (the active limit)", over, 0.0, "deg")]
    if g.get("follower") == "flat":
        rho = TranslatingCam(prog, g["h"], ans["r0"], 0.0, g.get("rotation", "ccw")).flat_rho_min()
        return [("rho_min_profile − rho_allow (the active limit)", rho - g["rho_allow"], 0.0, "mm")]
    if g.get("rho_allow") is not None:
        return [("the limits' smallest relative margin (0: one active, none exceeded)",
                 margins(g, prog, ans["r0"], ans["e"]), 0.0, "")]
    cam = TranslatingCam(prog, g["h"], ans["r0"], ans["e"], g.get("rotation", "ccw"))
    over = cam.alpha_max("rise")[0] - g["alpha_allow"]
    if g.get("alpha_allow_return") is not None:
        over = max(over, cam.alpha_max("return")[0] - g["alpha_allow_return"])
    return [("alpha_max − alpha_allow (the active limit)", over, 0.0, "deg")]


# ---------------------------------------------------------------------------- oscillating follower
@dataclass(frozen=True)
class ArmCamAt(OscillatingCam):
    """cam.oscillating's cam placed by its initial arm angle ``psi0_deg`` instead of recovering ψ0 from the
    triangle a, L, r0 (which loses digits when r0 ≪ L or a ≫ L: the designed centre is known by a and ψ0)."""

    psi0_deg: float = 0.0

    @property
    def psi0(self) -> float:
        """Initial arm angle ψ0 (rad), as designed."""
        return math.radians(self.psi0_deg)


def arm_cam(g: Mapping[str, Any], a: float, r0: float, psi0: float) -> OscillatingCam:
    """The designed oscillating cam (centre distance a, base circle r0, initial arm angle ψ0 in degrees)."""
    return ArmCamAt(a, g["L"], r0, g["h"], _program(g), g.get("rotation", "ccw"), g.get("arm", "left"), psi0)


def arm_position(B0: Point, A0: Point, tau: float, psi_deg: float) -> Point:
    """The arm's end turned about A0 from A0B0 through ψ in its rise sense (τ = +1 ccw)."""
    return rotate(B0, A0, tau * math.radians(psi_deg))


def velocity_image(A0: Point, B: Point, k: float) -> Point:
    """K on the arm A0B with BK = k·L towards A0 (k = εψ′): the line through O parallel to the contact
    normal meets the arm there (triangles A0KO and A0BP, P the relative instant centre, A0P = a/(1 − k))."""
    return A0 + (B - A0) * (1.0 - k)


def image_curve(motion: ArmProgram, A0: Point, B0: Point, lo: float, hi: float, n: int = 240) -> Polyline:
    """The velocity-image points K(δ) over cam angles [lo, hi] (deg)."""
    d = np.linspace(lo, hi, n + 1)
    d[-1] = np.nextafter(hi, lo)
    m = motion.motion(d)
    return Polyline(tuple(velocity_image(A0, arm_position(B0, A0, motion.tau, math.degrees(p)), motion.eps * v)
                          for p, v in zip(m.psi.tolist(), m.d1.tolist())))


def wedge_ray(A0: Point, B: Point, K: Point, alpha: float, side: float, tau: float, O: Point) -> Segment:
    """One side of the admissible wedge at K: from K at α_allow (deg) to the arm's normal on O's side,
    turned towards B (side = +1) or towards A0 (side = −1); drawn 1.3·KO long."""
    u = (B - A0).unit()
    n = u.perp() * -tau                                    # the normal towards O's side
    t = math.tan(math.radians(alpha))
    return Segment(K, K + (n + u * (side * t)).unit() * (1.3 * abs(O - K)))


def best_arm_centre(prog: Program, g: Mapping[str, Any], A0: Point, B0: Point) -> Point:
    """The admissible centre O nearest B0 (or at the given distance a): :func:`arm_best`, laid off from A0
    at ψ0 from A0B0 on the side away from the swing."""
    out = arm_best(prog, g["h"], g["L"], alpha_allow=g["alpha_allow"], rotation=g.get("rotation", "ccw"),
                   arm=g.get("arm", "left"), alpha_allow_return=g.get("alpha_allow_return"), a=g.get("a"))
    tau = 1.0 if g.get("arm", "left") == "right" else -1.0
    return A0 + (rotate(B0, A0, -tau * math.radians(out["psi0"])) - A0).unit() * out["a"]


def binding_positions(prog: Program, g: Mapping[str, Any], a: float) -> tuple[tuple[str, float], ...]:
    """(part, δ) of the positions whose wedge bounds O: the binding one at a, and at a kink of r0(a) (two
    positions binding at once) the one binding just beside it."""
    motion = ArmProgram(g["h"], prog, g.get("rotation", "ccw"), g.get("arm", "left"))
    lims = limits(prog, g["alpha_allow"], g.get("alpha_allow_return"))
    out = []
    for x in ((a,) if g.get("a") is not None else (a * (1 - 1e-7), a * (1 + 1e-7))):
        _, part, at, _ = arm_psi0(motion, g["L"], x, lims)
        if not any(p == part and abs(d - at) < 1e-3 for p, d in out):
            out.append((part, at))
    return tuple(out)


def arc_through(C: Point, P: Point, half: float) -> Arc:
    """The arc about C through P, ``half`` radians either side of it."""
    d = P - C
    return Arc(C, abs(d), math.atan2(d.y, d.x) - half, 2 * half)


def same_point(p: Point) -> Point:
    """The point itself (computed ahead of its step in the protocol)."""
    return p


def binding_words(binds: tuple) -> tuple[str, str]:
    """The caption of the binding arms: what they are, and the key of their starred points K1* (K2*).

    >>> binding_words((("rise", 10.0),))[0]
    "The binding position of the arm, where the region's boundary passes through O: its point K1* (* marks a binding position)"
    >>> binding_words((("rise", 10.0), ("return", 200.0)))[1]
    '起作用的摆杆位置：可行域边界在该处通过 O，其 K 点为 K1*、K2*（* 标记起作用的位置）'
    """
    two = len(binds) > 1
    return (f"The binding position{'s' if two else ''} of the arm, where the region's boundary passes through O: "
            f"{'their points K1*, K2*' if two else 'its point K1*'} (* marks a binding position)",
            f"起作用的摆杆位置：可行域边界在该处通过 O，其 K 点为 {'K1*、K2*' if two else 'K1*'}（* 标记起作用的位置）")


def pick_position(binds: tuple[tuple[str, float], ...], j: int) -> tuple[str, float] | None:
    """The j-th binding position, or None."""
    return binds[j] if j < len(binds) else None


def beyond(P: Point, Q: Point, extra: float) -> Segment:
    """The segment PQ extended beyond Q by ``extra``·|PQ|."""
    return Segment(P, Q + (Q - P) * extra)


def binding_image(A0: Point, B0: Point, motion: ArmProgram, pos: tuple[str, float]) -> Point:
    """K at a binding position (part, δ) (one-sided motion inside its part)."""
    m = part_motion(motion, *pos)
    B = arm_position(B0, A0, motion.tau, math.degrees(float(m.psi[0])))
    return velocity_image(A0, B, motion.eps * float(m.d1[0]))


def binding_arm(A0: Point, B0: Point, motion: ArmProgram, pos: tuple[str, float]) -> Segment:
    """The arm A0Bi at a binding position (part, δ)."""
    m = part_motion(motion, *pos)
    return segment(A0, arm_position(B0, A0, motion.tau, math.degrees(float(m.psi[0]))))


def binding_mark(A0: Point, B0: Point, motion: ArmProgram, pos: tuple[str, float], K: Point,
                 O: Point) -> tuple[Segment, marks.AngleMark]:
    """The arm's normal at K and the angle from it to the binding line K→O: the allowance of its part
    (α_allow of the rise or of the return), marked with its value so that the two lines tell apart."""
    arm = binding_arm(A0, B0, motion, pos)
    n = (arm.b - arm.a).unit().perp()
    if n.dot(O - K) < 0:
        n = -n
    reach = abs(O - K) * 0.5
    return (Segment(K - n * (0.15 * reach), K + n * reach),
            marks.angle_mark(K, K + n * reach, O, "α", math.degrees(angle_at(K, K + n, O))))


def construct_arm(g: Mapping[str, Any]) -> Construction:
    """The arm's positions, the velocity-image points K, the wedges at α_allow, the best O and r0."""
    prog, h, L = _program(g), g["h"], g["L"]
    motion = ArmProgram(h, prog, g.get("rotation", "ccw"), g.get("arm", "left"))
    tau, eps = float(motion.tau), float(motion.eps)
    sc = Scene("Base circle of an oscillating-follower cam from the arm's velocity images")
    A0 = sc.given("A0", Point(0.0, 0.0), style="pivot", caption=("A0: the arm's pivot", "A0:摆杆转轴"))
    if sc.drawing:
        sc.add("A0_ground", marks.ground, A0, -math.pi / 2, role=Role.ANNOTATION, style="ground")
    B0 = sc.given("B0", Point(tau * L, 0.0), style="joint", caption=(
        f"A0B0 = L = {L:g}: the arm at the start of the rise", f"A0B0 = L = {L:g}:推程起始时的摆杆"))
    add_bar(sc, "arm0", A0, B0)
    O = sc.add("O_best", best_arm_centre, prog, g, A0, B0, visible=False)
    parts = [("rise", prog.rise, g["alpha_allow"])]
    if g.get("alpha_allow_return") is not None and prog.ret is not None:
        parts.append(("return", prog.ret, g["alpha_allow_return"]))
    same = eps > 0
    for part, seg, allow in parts:
        zh = "推程" if part == "rise" else "回程"
        divs = [seg.start + seg.angle * i / 6 for i in range(7)]
        divs[-1] = float(np.nextafter(seg.end, seg.start))
        # the steps in the order the captions tell them, each part at its own steps: every arm position, then
        # every point K and their curve, then every wedge (200-12 and 200-20 drew positions 1–6 and their K with
        # the wedges, after "Turn the arm …" and "lay off BiKi …", and the return's without steps of their own)
        away = same == (part == "return")    # K beyond B: the arm swings against the cam's sense in this part
        Bs, Ks = [], []
        for i, d in enumerate(divs):
            m = part_motion(motion, part, d)
            psi = math.degrees(float(m.psi[0]))
            Bs.append(sc.add(f"B_{part}{i}", arm_position, B0, A0, tau, psi, style="point", caption=(
                f"Turn the arm about A0 to its {part} positions A0B1, A0B2, … (ψ at every sixth of the {part})",
                f"将摆杆绕 A0 转到{zh}各位置 A0B1、A0B2 …(按{zh}角六等分取 ψ)") if i == 0 else ("", "")))
            sc.add(f"arm_{part}{i}", segment, A0, Bs[-1], style="ghost")
        for i, (d, B) in enumerate(zip(divs, Bs)):
            k = eps * float(part_motion(motion, part, d).d1[0])
            Ks.append(sc.add(f"K_{part}{i}", velocity_image, A0, B, k, style="point", caption=(
                "On each A0Bi lay off BiKi = L·|ψ′i| (ψ′ = dψ/dδ) " + (
                    f"away from A0 (the arm swings against the cam's sense in the {part})" if away else
                    f"towards A0 (the arm swings with the cam's sense in the {part})"),
                "在各 A0Bi 上截取 BiKi = L·|ψ′i|(ψ′ = dψ/dδ)," + (
                    f"背离 A0({zh}中摆杆与凸轮反向转动)" if away else f"向 A0 方向({zh}中摆杆与凸轮同向转动)"))
                if i == 0 else ("", "")))
        sc.add(f"K_curve_{part}", image_curve, motion, A0, B0, seg.start, seg.end, style="path")
        for i, (B, K) in enumerate(zip(Bs, Ks)):
            for side in (1.0, -1.0):
                sc.add(f"wedge_{part}{i}_{'ab'[side < 0]}", wedge_ray, A0, B, K, allow, side, tau, O,
                       style="construction", caption=(
                           f"Through every Ki draw the two lines at α_allow = {allow:g}° to the arm's normal: O must lie "
                           f"between them ({part})", f"过各 Ki 作与摆杆法线成 [α] = {allow:g}° 的两直线,O 须在其间({zh})")
                       if i == 0 and side > 0 else ("", ""))
    O = sc.add("O", same_point, O, role=Role.RESULT, style="pivot", label="O", caption=(
        ("The admissible point nearest B0 is the best centre O" if g.get("a") is None else
         f"The admissible point of the circle of radius a = {g['a']:g} about A0 nearest B0: the centre O"),
        ("可行域内离 B0 最近的点即最佳凸轮中心 O" if g.get("a") is None else
         f"以 A0 为圆心、a = {g['a']:g} 为半径的圆在可行域内离 B0 最近的点即凸轮中心 O")))
    add_rotation(sc, O, 1.0 if g.get("rotation", "ccw") == "ccw" else -1.0, ground=True)
    if g.get("a") is not None:
        sc.add("a_arc", arc_through, A0, O, 0.35, style="construction")
    a = sc.add("a", length, O, A0, role=Role.MEASUREMENT, unit="mm", caption=("a = OA0", "中心距 a = OA0"))
    sc.add("OA0", segment, O, A0, style="frame")
    binds = sc.add("binding", binding_positions, prog, g, a, visible=False)
    if sc.drawing:                              # the caption names the starred points there are (K1*, or K1*, K2*)
        sc.add("bind_words", binding_words, binds, visible=False)
    for j in range(2):
        pos = sc.add(f"bind{j}", pick_position, binds, j, visible=False)
        sc.add(f"bind_arm{j}", binding_arm, A0, B0, motion, pos, style="link-alt", optional=True,
               caption=(Ref("bind_words") if sc.drawing else binding_words(((), ()))) if j == 0 else ("", ""))
        K = sc.add(f"bind_K{j}", binding_image, A0, B0, motion, pos, style="joint", label=f"K{j + 1}*", optional=True)
        sc.add(f"bind_line{j}", beyond, K, O, 0.25, style="admissible", optional=True)
        sc.add(f"bind_mark{j}", binding_mark, A0, B0, motion, pos, K, O, role=Role.ANNOTATION, style="angle",
               optional=True)
    r0 = sc.add("r0", length, O, B0, role=Role.MEASUREMENT, unit="mm", caption=("r0 = OB0", "基圆半径 r0 = OB0"))
    sc.add("base", circle, O, r0, style="theta-circle", caption=("Draw the base circle", "作基圆"))
    sc.add("OB0", segment, O, B0, style="construction")
    psi0 = sc.add("psi0", angle_deg, A0, O, B0, role=Role.MEASUREMENT, unit="deg",
                  caption=("ψ0 = ∠OA0B0", "初始摆角 ψ0 = ∠OA0B0"))
    add_angle_mark(sc, "mark_psi0", A0, O, B0, "ψ0", psi0)
    rho = sc.add("rho_min_pitch", lambda o_a, r, p: rho_min(arm_cam(g, o_a, r, p).pitch_curve(scalar=True)).value, a, r0, psi0,
                 role=Role.MEASUREMENT, unit="mm", caption=("ρmin of the pitch curve of the designed cam",
                                                            "所得凸轮理论廓线的最小曲率半径 ρmin"))
    sc.add("rr_max", lambda r: RR_FACTOR * r, rho, role=Role.MEASUREMENT, unit="mm",
           caption=("rr ≤ 0.8·ρmin", "滚子半径 rr ≤ 0.8ρmin"))
    names = ("r0", "a", "psi0", "rho_min_pitch", "rr_max")
    answers = {n: n for n in names}
    if g.get("rho_allow") is not None:
        _add_arm_rho_steps(sc, answers, g, O, A0, B0)
    return Construction(sc, answers, {"O": "O", "A0": "A0", "B0": "B0"})


def _add_arm_rho_steps(sc: Scene, answers: dict[str, str], g: Mapping[str, Any], O, A0, B0) -> None:
    """The centre moved perpendicular to A0B0 until ρmin of the pitch curve reaches ρallow; the designed a, r0,
    ψ0, ρmin and rr_max measured again (:mod:`.cam_base_radius_arm_rho`)."""
    rho_allow = g["rho_allow"]
    sc.add("r0_alpha", float, Ref("r0"), role=Role.MEASUREMENT, unit="mm", visible=False)
    sc.add("a_alpha", float, Ref("a"), unit="mm", visible=False)          # the pressure angle's design, for the
    sc.add("psi0_alpha", float, Ref("psi0"), unit="deg", visible=False)   # declared mistake 'centre_not_moved'
    Od = sc.add("O_design", grow_arm_centre, g, O, A0, B0, role=Role.RESULT, style="pivot", label="O′", caption=(
        f"Move O perpendicular to A0B0, away from B0, until ρmin of the pitch curve reaches ρallow = {rho_allow:g}: "
        "the designed centre O′",
        f"沿垂直于 A0B0 的方向(远离 B0)移动 O,直至理论廓线 ρmin 达到 ρallow = {rho_allow:g}:所得凸轮中心 O′"))
    sc.add("O_path", segment, O, Od, style="construction")
    r0 = sc.add("r0_design", length, Od, B0, role=Role.MEASUREMENT, unit="mm", caption=("r0 = O′B0", "基圆半径 r0 = O′B0"))
    sc.add("r0_rho", lambda r, ra: r if r > ra else ra, r0, Ref("r0"), visible=False)
    sc.add("base_design", circle, Od, r0, style="theta-circle", caption=("Its base circle", "其基圆"))
    sc.add("O_B0_design", segment, Od, B0, style="construction")
    sc.add("O_A0_design", segment, Od, A0, style="frame")
    a = sc.add("a_design", length, Od, A0, role=Role.MEASUREMENT, unit="mm", caption=("a = O′A0", "中心距 a = O′A0"))
    psi0 = sc.add("psi0_design", angle_deg, A0, Od, B0, role=Role.MEASUREMENT, unit="deg",
                  caption=("ψ0 = ∠O′A0B0", "初始摆角 ψ0 = ∠O′A0B0"))
    add_angle_mark(sc, "mark_psi0_design", A0, Od, B0, "ψ0′", psi0)
    rho = sc.add("rho_design", lambda o_a, r, p: rho_min(arm_cam(g, o_a, r, p).pitch_curve(scalar=True)).value, a, r0, psi0,
                 role=Role.MEASUREMENT, unit="mm", caption=("ρmin of the designed pitch curve", "所设计理论廓线的 ρmin"))
    sc.add("rr_max_design", lambda r: RR_FACTOR * r, rho, role=Role.MEASUREMENT, unit="mm", visible=False)
    answers.update({"r0": "r0_design", "a": "a_design", "psi0": "psi0_design", "rho_min_pitch": "rho_design",
                    "rr_max": "rr_max_design", "r0_alpha": "r0_alpha", "r0_rho": "r0_rho"})


RECIPE = Recipe(
    name="cam.base_radius",
    title="Disc cam: smallest base circle for an allowed pressure angle (translating: best offset; oscillating: best "
          "centre)",
    givens=GIVENS,
    answers=ANSWERS,
    points=("O", "B0"),
    construct=construct,
    analytic=analytic,
    validate=_validate,
    back_check=back_check,
)
