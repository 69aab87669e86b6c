"""``cam.base_radius``: the smallest base circle (and the best offset) of a disc cam with a translating knife
or roller follower for an allowed pressure angle — the textbook's ds/dδ–s diagram.

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

The roller bound: ρmin of the pitch curve of the designed cam (convex parts, exact derivatives), and the
textbook rule rr ≤ 0.8·ρmin (``rr_max``; rr < ρmin is the bare undercut limit).
"""
from __future__ import annotations

import math
from typing import Any, Mapping

import numpy as np

from ..cam.base_radius import RR_FACTOR, best_base
from ..cam.profile import PitchCurve, inverted, maximise, rho_min
from ..cam.program import Program, parse_program
from ..cam.translating import TranslatingCam
from ..errors import NotAMechanism
from ..geometry import Line, Point, Polyline, circle, line_line, segment
from ..scene import Role, Scene, marks
from .base import Construction, Quantity, Recipe
from .common import length

GIVENS = (
    Quantity("h", "mm", "stroke"),
    Quantity("program", "table[]", "motion program: rise, dwells, return (a full turn)"),
    Quantity("alpha_allow", "deg", "allowed pressure angle of the rise"),
    Quantity("alpha_allow_return", "deg", "allowed pressure angle of the return (unconstrained when absent)",
             required=False),
    Quantity("rotation", "choice", "sense of rotation of the cam", required=False, default="ccw", minimum=None,
             choices=("ccw", "cw")),
    Quantity("e", "mm", "a fixed offset (> 0: the axis right of O); absent: the best offset", required=False,
             minimum=None),
)
ANSWERS = (
    Quantity("r0", "mm", "smallest base circle radius of the pitch curve"),
    Quantity("e", "mm", "the offset (best, or as given): > 0 puts the follower's axis right of O"),
    Quantity("s0", "mm", "height of the lowest pitch point B0 above O, √(r0² − e²)"),
    Quantity("rho_min_pitch", "mm", "smallest radius of curvature of the pitch curve (convex parts)"),
    Quantity("rr_max", "mm", "largest roller radius by the rule rr ≤ 0.8·ρmin"),
)


def _program(g: Mapping[str, Any]) -> Program:
    prog = parse_program(g["program"])
    if not prog.full:
        raise NotAMechanism("program: a cam needs a full turn (the segment angles must add up to 360°)")
    return prog


def _validate(g: Mapping[str, Any]) -> list[str]:
    _program(g)
    for key in ("alpha_allow", "alpha_allow_return"):
        if g.get(key) is not None and not 0.0 < g[key] < 90.0:
            raise NotAMechanism(f"{key} = {g[key]:g}° must lie in (0°, 90°)")
    return []


# ---------------------------------------------------------------------------- step operations
def diagram_points(prog: Program, h: float, k: float, lo: float, hi: float, n: int = 240) -> Polyline:
    """The curve (−k·s′, s) over cam angles [lo, hi] (radians)."""
    d = np.linspace(lo, hi, n + 1)
    d[-1] = np.nextafter(hi, lo)
    s, v, _ = prog.motion(h, d, radians=True)
    return Polyline(tuple(Point(-k * float(x), float(y)) for x, y in zip(v, s)))


def support_line(prog: Program, h: float, k: float, lo: float, hi: float, t: float, side: float) -> Line:
    """The support line of the curve at α_allow on one side: direction (side·t, 1), through the point where
    s − side·X/t is smallest (golden-section on the exact (s, s′); the tangent point)."""
    def g(d):
        s, v, _ = prog.motion(h, d, radians=True)
        return -(s - side * (-k * v) / t)
    top = maximise(g, [(lo, hi)], dense=2048)
    s, v, _ = prog.motion(h, top.delta, radians=True)
    return Line(Point(-k * float(v), float(s)), Point(side * t, 1.0))


def below_all(p: Point, lines: tuple[Line, ...], scale: float) -> bool:
    """True when p lies on or below every line (the admissible side, away from the curve)."""
    for ln in lines:
        d = ln.direction
        if p.y - (ln.point.y + (p.x - ln.point.x) * d.y / d.x) > 1e-12 * scale:
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
    """ρmin of the designed pitch curve (convex parts), from the inversion with exact derivatives."""
    def fn(d):
        s, v, a = prog.motion(h, d, radians=True)
        z = np.zeros_like(s)
        return inverted(d, rotation, (z + e, s0 + s), (z, v), (z, a))
    breaks = []
    for seg in prog.segments:
        breaks.append(math.radians(seg.end))
        if seg.law is not None and seg.law.name == "parabolic":
            breaks.append(math.radians(seg.start + seg.angle / 2))
    return rho_min(PitchCurve(fn, tuple(b for b in breaks if 0 < b < 2 * math.pi))).value


# ---------------------------------------------------------------------------- construction
def construct(g: Mapping[str, Any]) -> Construction:
    """The ds/dδ–s diagram, the support lines at α_allow, the best O and the base circle."""
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
    r0 = sc.add("r0", length, O, B0, role=Role.MEASUREMENT, unit="mm",
                caption=("r0 = OB0", "基圆半径 r0 = OB0"))
    sc.add("base", circle, O, r0, style="theta-circle", caption=("Draw the base circle", "作基圆"))
    sc.add("OB0", segment, O, B0, style="construction", caption=("", ""))
    e = sc.add("e", lambda o: -o.x, O, role=Role.MEASUREMENT, unit="mm",
               caption=("e = the distance of O from the axis (> 0: the axis right of O)", "偏距 e(导路在 O 右侧为正)"))
    s0 = sc.add("s0", lambda o: -o.y, O, role=Role.MEASUREMENT, unit="mm", caption=("s0 = height of B0 above O",
                                                                                   "s0:B0 在 O 上方的高度"))
    rho = sc.add("rho_min_pitch", pitch_rho_min, prog, h, rotation, e, s0, role=Role.MEASUREMENT, unit="mm",
                 caption=("ρmin of the pitch curve (convex parts, exact derivatives)", "理论廓线最小曲率半径 ρmin"))
    sc.add("rr_max", lambda r: RR_FACTOR * r, rho, role=Role.MEASUREMENT, unit="mm",
           caption=("rr ≤ 0.8·ρmin", "滚子半径 rr ≤ 0.8ρmin"))
    sc.add("dim_r0", lambda o, b, v: marks.Dimension(o, b, "r0", v, 0.08 * scale), O, B0, r0, role=Role.ANNOTATION,
           style="dim")
    names = ("r0", "e", "s0", "rho_min_pitch", "rr_max")
    return Construction(sc, {n: n for n in names}, {"O": "O", "B0": "B0"})


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """Minimise r0(e)² = e² + s0(e)² (:mod:`geomcon.cam.base_radius`); ρmin from cam.translating's closed form."""
    prog = _program(g)
    out = best_base(prog, g["h"], alpha_allow=g["alpha_allow"], rotation=g.get("rotation", "ccw"),
                    alpha_allow_return=g.get("alpha_allow_return"), e=g.get("e"))
    rho = TranslatingCam(prog, g["h"], out["r0"], out["e"], g.get("rotation", "ccw")).rho_min_pitch()
    return [{**out, "rho_min_pitch": rho, "rr_max": RR_FACTOR * rho}]


def back_check(g: Mapping[str, Any], ans: Mapping[str, float]) -> list[tuple[str, float, float, str]]:
    """The designed cam's largest pressure angles (cam.translating's closed form): the active limit is
    reached exactly, the other is not exceeded."""
    prog = _program(g)
    cam = TranslatingCam(prog, g["h"], ans["r0"], ans["e"], g.get("rotation", "ccw"))
    over = cam.alpha_max("rise")[0] - g["alpha_allow"]
    if g.get("alpha_allow_return") is not None:
        over = max(over, cam.alpha_max("return")[0] - g["alpha_allow_return"])
    return [("alpha_max − alpha_allow (the active limit)", over, 0.0, "deg")]


RECIPE = Recipe(
    name="cam.base_radius",
    title="Disc cam, translating follower: smallest base circle and best offset for an allowed pressure angle",
    givens=GIVENS,
    answers=ANSWERS,
    points=("O", "B0"),
    construct=construct,
    analytic=analytic,
    validate=_validate,
    back_check=back_check,
)
