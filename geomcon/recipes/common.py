"""Step operations and drawing helpers shared by the linkage recipes.

Examples
--------
>>> from geomcon.geometry import Point
>>> round(angle_deg(Point(0, 0), Point(1, 0), Point(1, 1)), 12)
45.0
>>> round(transmission_deg(Point(0, 1), Point(0, 0), Point(1, 1)), 12)
45.0
>>> k_ratio(36.0)
1.5
"""
from __future__ import annotations

import math

from typing import Any, Mapping

from .. import tolerance as _tolerance                  # REL_TOL read at run time, as the geometry reads it
from ..analytic.design_by_k import rocker_design_valid
from ..errors import Degenerate
from ..geometry import Line, Point, angle_at, circle, point_along, segment
from ..geometry.kernels import point_k, register
from ..geometry.measure import _signed_angle_xy
from ..scene import Ref, Role, Scene
from ..scene import marks


def angle_deg(vertex: Point, a: Point, b: Point) -> float:
    """∠a-vertex-b in degrees, in [0, 180].

    >>> angle_deg(Point(0, 0), Point(1, 0), Point(0, 2))
    90.0
    """
    ox, oy = vertex.x, vertex.y                            # angle_at(vertex, a, b), one call fewer
    return math.degrees(abs(_signed_angle_xy(a.x - ox, a.y - oy, b.x - ox, b.y - oy)))


def transmission_deg(b: Point, c: Point, d: Point) -> float:
    """Transmission angle at joint ``c`` between links c–b and c–d: the acute form of ∠BCD, in degrees."""
    g = angle_deg(c, b, d)
    return min(g, 180.0 - g)


def pressure_on_guide_deg(b: Point, c: Point, guide_dir: Point) -> float:
    """Pressure angle at a slider ``c`` driven by the rod c–b, moving along ``guide_dir``: the acute angle
    between the rod and the guide's direction, in degrees."""
    a = math.degrees(angle_at(Point(0.0, 0.0), b - c, guide_dir))
    return min(a, 180.0 - a)


def complement_deg(x: float) -> float:
    """90° − x."""
    return 90.0 - x


def k_ratio(theta: float) -> float:
    """K = (180° + θ)/(180° − θ)."""
    return (180.0 + theta) / (180.0 - theta)


def length(a: Point, b: Point) -> float:
    """Distance ab (a measurement step operation).

    >>> length(Point(0, 0), Point(3, 4))
    5.0
    """
    return math.hypot(b.x - a.x, b.y - a.y)                 # distance(a, b), one call fewer


def smallest(*values: float) -> float:
    """The smallest of the values."""
    return min(values)


def difference(a: float, b: float) -> float:
    """a − b (a helper number, e.g. the radius BC − AB)."""
    return a - b


def total(a: float, b: float) -> float:
    """a + b."""
    return a + b


def rebuilt(recipe: str, given: Mapping[str, Any]) -> Scene:
    """The scene of ``recipe`` on ``given`` as a solve builds it (lean, planned, replayed from the recipe's
    tape when it has one): a design's back-substitution through the analysis recipe."""
    from ..taped import construct_taped
    from . import get_recipe
    r = get_recipe(recipe)
    sc = construct_taped(r, given).scene
    sc.rebuild_with(lambda: r.construct(given).scene)   # a step the learned plan left out completes the scene
    return sc


_RECIPES: dict[str, Any] = {}
"""The analysis recipes a back-substitution rebuilds through, by name (looked up once)."""


def _taped_rebuild(recipe: Any, given: Mapping[str, Any], keys: tuple[str, ...]) -> Any:
    global _taped_rebuild
    from ..taped import taped_rebuild                # imported when first used: the taped module imports recipes
    _taped_rebuild = taped_rebuild
    return taped_rebuild(recipe, given, keys)


def rebuilt_values(recipe: str, given: Mapping[str, Any], keys: tuple[str, ...]) -> dict[str, Any]:
    """``rebuilt(recipe, given).evaluate(keys)``, the values only: once the recipe is taped, its tape's
    compiled rebuild of ``keys`` runs on the givens (:func:`geomcon.taped.taped_rebuild`: the tape's arithmetic
    and the plan on floats, no scene, no memo; a back-substitution reads three numbers of each designed
    linkage); any other case, or a step that fails (worded by the scene), takes the scene.

    >>> v = rebuilt_values("guide_bar.extremes", {"AB": 145.0, "AC": 290.0}, ("theta",))
    >>> round(v["theta"], 9)
    60.0
    """
    r = _RECIPES.get(recipe)
    if r is None:
        from . import get_recipe
        r = _RECIPES[recipe] = get_recipe(recipe)
    try:
        values = _taped_rebuild(r, given, keys)
        if values is not None:
            return dict(zip(keys, values))
    except Exception:                  # the scene evaluates step by step and says which step failed
        pass
    return rebuilt(recipe, given).evaluate(keys)


def add_pivot(sc: Scene, key: str, at: Point | tuple[Any, Any], caption: tuple[str, str], *,
              ground_angle: float = -math.pi / 2, label: str | None = None, style: str = "pivot") -> Ref:
    """A fixed pivot: the given point (a Point, or coordinates placed by the step: :meth:`Scene.given_at`)
    plus its hatched ground symbol; ``label`` replaces the printed name (default: ``key``), ``style`` the
    pivot's style ("pivot-centre": an instant centre too, its label printed whole)."""
    if type(at) is tuple:
        ref = sc.given_at(key, at[0], at[1], caption=caption, style=style, label=label)
    else:
        ref = sc.given(key, at, caption=caption, style=style, label=label)
    if sc.drawing:
        sc.add(f"{key}_ground", marks.ground, ref, ground_angle, role=Role.ANNOTATION, style="ground")
    return ref


def add_bar(sc: Scene, key: str, a: Ref, b: Ref, name: tuple[str, str] = ("", ""), *, style: str = "link",
            role: Role = Role.RESULT) -> Ref:
    """A link drawn as a bar between two joints (an empty caption draws it with the step before)."""
    return sc.add(key, segment, a, b, role=role, style=style, caption=name)


def transmission_mark(c: Point, b: Point, d: Point, symbol: str, value: float):
    """The mark of a transmission angle at joint ``c`` on the links c–b and c–d; when ∠BCD is obtuse its
    value is the supplement and the arc spans the acute angle from b–c extended beyond c, which the mark
    draws (:func:`geomcon.render.symbols.angle_rays`), so that the arc never ends on an undrawn line."""
    return marks.AngleMark(c, b, d, symbol, value, None)


def velocity_end(joint: Point, pivot: Point, toward: Point, size: float) -> Point:
    """The end of the velocity line of a ``joint`` turning about ``pivot``, ``size`` mm from the joint: the
    line stands perpendicular to pivot–joint on the side of ``toward`` (the acute side of the force line
    joint–toward), so that the pressure angle between them is the angle the mark spans.

    >>> velocity_end(Point(0, 0), Point(-1, 0), Point(1, 1), 2.0)
    Point(x=0.0, y=2.0)
    """
    u = (joint - pivot).unit()
    n = Point(-u.y, u.x)
    if n.dot(toward - joint) < 0.0:
        n = -n
    return joint + n * size


def add_angle_mark(sc: Scene, key: str, vertex: Ref, a: Ref, b: Ref, symbol: str, value: Ref,
                   radius: float | None = None) -> Ref:
    """The arc marking a measured angle, labelled with its value."""
    return sc.add(key, marks.angle_mark, vertex, a, b, symbol, value, radius, role=Role.ANNOTATION, style="angle")


def along_line(line, t: float, sign: float = 1.0) -> Point:
    """The point at signed distance ``sign·t`` along a line from its reference point.

    >>> along_line(Line(Point(1, 1), Point(0, 1)), 2.0, -1.0)
    Point(x=1.0, y=-1.0)
    """
    if type(line) is Line:                                 # line.at(sign·t), without its two Points
        p, d, s = line.point, line.direction, sign * t
        return Point(p.x + d.x * s, p.y + d.y * s)
    return line.at(sign * t)


def pressure_deg(b: Point, c: Point, guide) -> float:
    """Pressure angle at a slider ``c`` pushed by the rod c–b along ``guide`` (a Line): the acute angle
    between the rod and the guide, in degrees."""
    return pressure_on_guide_deg(b, c, guide.direction)


def largest(*values: float) -> float:
    """The largest of the values."""
    return max(values)


def guide_angle_mark(c: Point, b: Point, guide, symbol: str, value: float, radius: float | None = None):
    """Angle mark at slider ``c`` between the rod c→b and the guide, on the side where the angle is acute."""
    d = guide.direction
    if (b - c).dot(d) < 0:
        d = -d
    return marks.AngleMark(c, b, c + d, symbol, value, radius)


def guide_between(p: Point, q: Point, guide, margin: float, side: int = -1):
    """A hatched guide along ``guide`` covering the projections of ``p`` and ``q`` plus ``margin``."""
    u = guide.direction
    t = sorted(((p - guide.point).dot(u), (q - guide.point).dot(u)))
    return marks.Guide(guide.at(t[0] - margin), guide.at(t[1] + margin), side)


def add_collinear_extremes(sc: Scene, A: Ref, path: Ref, AB: float, BC: float, branch, meet,
                           path_name: tuple[str, str]) -> tuple[Ref, Ref, Ref, Ref]:
    """The two extreme positions where crank and coupler are collinear.

    The circle about A of radius BC − AB meets the path of C (``meet(circle, path)``, ``path`` first for a
    line) at C1 (folded), the circle of radius BC + AB at C2 (extended); B1 lies on C1A extended beyond A and
    B2 on AC2, both at AB from A. Returns ``(B1, C1, B2, C2)``.
    """
    en, zh = path_name
    cs = []
    for i, (r_key, op, r, sign, how_en, how_zh) in enumerate((("r1", difference, "BC − AB", -1, "folded", "重叠"),
                                                              ("r2", total, "BC + AB", 1, "extended", "拉直")), 1):
        radius = sc.add(r_key, op, BC, AB, visible=False, unit="mm")
        value = op(BC, AB)
        k = sc.add(f"k{i}", circle, A, radius, caption=(f"Circle about A with radius {r} = {value:g}",
                                                        f"以 A 为圆心、{r} = {value:g} 为半径作圆"))
        args = (path, k) if meet.__name__ == "line_circle" else (k, path)
        C = sc.add(f"C{i}", meet, *args, branch=branch, role=Role.RESULT, style="joint", label=f"C{i}",
                   caption=(f"It meets {en} at C{i}: crank and coupler {how_en}", f"交{zh}于 C{i}(曲柄与连杆{how_zh}共线)"))
        cs.append(C)
    C1, C2 = cs
    B1 = sc.add("B1", point_along, A, C1, -AB, role=Role.RESULT, style="joint", label="B1",
                caption=("B1 on the extension of C1A beyond A, AB1 = AB", "在 C1A 的延长线上截取 AB1 = AB"))
    B2 = sc.add("B2", point_along, A, C2, AB, role=Role.RESULT, style="joint", label="B2",
                caption=("B2 on AC2, AB2 = AB", "在 AC2 上截取 AB2 = AB"))
    return B1, C1, B2, C2


def add_theta_and_K(sc: Scene, A: Ref, C1: Ref, C2: Ref) -> Ref:
    """θ = ∠C1AC2 and K = (180° + θ)/(180° − θ) as measurement steps; returns θ."""
    th = sc.add("theta", angle_deg, A, C1, C2, role=Role.MEASUREMENT, unit="deg",
                caption=("Measure θ = ∠C1AC2", "量得极位夹角 θ = ∠C1AC2"))
    sc.add("K", k_ratio, th, role=Role.MEASUREMENT,
           caption=("K = (180° + θ)/(180° − θ)", "行程速比系数 K = (180° + θ)/(180° − θ)"))
    return th


# ------------------------------------------------------------------------------ crank-rocker designs
# The candidates of a crank-rocker designed by K (positions, frame and links forms) and the textbook's
# choice among them; shared by ``crank_rocker_design`` and ``crank_rocker_links``.
# The candidates' step operations below run for every candidate of every solve: plain float arithmetic in the
# order of the vector formulas in their comments (abs(Q − A) is hypot(Q.x − A.x, Q.y − A.y)): the same bits.
def half_difference(A: Point, P: Point, Q: Point) -> float:
    """|AQ − AP| / 2: the crank of a design whose extreme positions are P and Q.

    >>> half_difference(Point(0, 0), Point(3, 4), Point(0, 13))
    4.0
    """
    ax, ay = A.x, A.y                                      # abs(abs(Q − A) − abs(P − A)) / 2
    return abs(math.hypot(Q.x - ax, Q.y - ay) - math.hypot(P.x - ax, P.y - ay)) / 2.0


def half_sum(A: Point, P: Point, Q: Point) -> float:
    """(AP + AQ) / 2: the coupler.

    >>> half_sum(Point(0, 0), Point(3, 4), Point(0, 13))
    9.0
    """
    ax, ay = A.x, A.y                                      # (abs(P − A) + abs(Q − A)) / 2
    return (math.hypot(P.x - ax, P.y - ay) + math.hypot(Q.x - ax, Q.y - ay)) / 2.0


def folded_flag(A: Point, P1: Point, P2: Point) -> float:
    """1.0 when P1 is the folded extreme position (nearer to A).

    >>> folded_flag(Point(0, 0), Point(3, 4), Point(0, 13))
    1.0
    """
    ax, ay = A.x, A.y                                      # abs(P1 − A) < abs(P2 − A)
    return 1.0 if math.hypot(P1.x - ax, P1.y - ay) < math.hypot(P2.x - ax, P2.y - ay) else 0.0


def near_flag(A: Point, C1: Point, C2: Point, D: Point) -> float:
    """1.0 when A and D lie on the same side of the line C1C2.

    >>> near_flag(Point(0, 1), Point(-1, 0), Point(1, 0), Point(5, 2)), near_flag(Point(0, -1), Point(-1, 0), Point(1, 0), Point(5, 2))
    (1.0, 0.0)
    """
    ux, uy = C2.x - C1.x, C2.y - C1.y                      # u = C2 − C1; u × (A − C1) · u × (D − C1) > 0
    cx, cy = C1.x, C1.y
    return 1.0 if (ux * (A.y - cy) - uy * (A.x - cx)) * (ux * (D.y - cy) - uy * (D.x - cx)) > 0 else 0.0


ALPHA_ALLOW_MIN = math.degrees(math.asin(1e-10))
"""The smallest ``alpha_allow`` (5.73e-9°) of the slotter and the shaper: the shortest coupler DE = x / sin α
(x the arm or the deviation it is sized for) stays within 1e10 of x, the global ratio of lengths (a subnormal
α made sin α = 0 and DE a division by zero)."""


def refuse_alpha_allow(alpha: float | None) -> None:
    """Refuse ``alpha_allow`` outside [:data:`ALPHA_ALLOW_MIN`, 90°), naming the limit.

    >>> refuse_alpha_allow(5e-324)
    Traceback (most recent call last):
    ...
    geomcon.errors.NotAMechanism: alpha_allow = 4.94066e-324° is below 5.72958e-09°: the shortest coupler DE = x / sin α would exceed 1e10 times x
    """
    from ..errors import NotAMechanism

    if alpha is None:
        return
    if not 0 < alpha < 90:
        raise NotAMechanism(f"alpha_allow = {alpha:g}° must lie in (0°, 90°)")
    if alpha < ALPHA_ALLOW_MIN:
        raise NotAMechanism(f"alpha_allow = {alpha:g}° is below {ALPHA_ALLOW_MIN:g}°: the shortest coupler "
                            "DE = x / sin α would exceed 1e10 times x")


def one(*_: Any) -> float:
    """1.0 (A_near of the frame family)."""
    return 1.0


def is_valid(A: Point, P1: Point, P2: Point, D: Point, CD: float, arc_side: int = 0) -> bool:
    """A crank-rocker with extreme positions P1, P2, by the shared rule
    :func:`geomcon.analytic.design_by_k.rocker_design_valid` (AB a crank by Grashof, P1 and P2 strictly on
    one side of AD); with ``arc_side`` ±1, A must also lie strictly on that side of P1→P2 — the arc of its
    θ-circle that sees P1P2 under θ (the rest of the circle sees it under 180° − θ).

    >>> is_valid(Point(0, 0), Point(20, 60), Point(100, 79.37), Point(90, 0), 80.0, -1)
    True
    """
    return valid_xy(A.x, A.y, P1, P2, D, CD, arc_side)


def valid_xy(ax: float, ay: float, P1: Point, P2: Point, D: Point, CD: float, arc_side: int = 0) -> bool:
    """:func:`is_valid` of A = (``ax``, ``ay``), without making the point (a θ-circle's admissible arcs test
    ~900 points of it: :func:`geomcon.recipes.crank_rocker_design.admissible_arcs`).

    >>> valid_xy(0.0, 0.0, Point(20, 60), Point(100, 79.37), Point(90, 0), 80.0, -1)
    True
    """
    ux, uy = D.x - ax, D.y - ay                            # u = D − A
    AD = math.hypot(ux, uy)
    if AD == 0.0:
        return False
    d1, d2 = math.hypot(P1.x - ax, P1.y - ay), math.hypot(P2.x - ax, P2.y - ay)
    a, b = abs(d2 - d1) / 2.0, (d1 + d2) / 2.0             # half_difference, half_sum
    if arc_side:
        cx, cy = P2.x - P1.x, P2.y - P1.y                  # chord = P2 − P1; chord × (A − P1)
        if arc_side * (cx * (ay - P1.y) - cy * (ax - P1.x)) <= _tolerance.REL_TOL * math.hypot(cx, cy) * max(b, CD, AD):
            return False
    return rocker_design_valid(a, b, CD, AD, (ux * (P1.y - ay) - uy * (P1.x - ax)) / AD,
                               (ux * (P2.y - ay) - uy * (P2.x - ax)) / AD)


def excess_by_foot(V: Point, P: Point, Q: Point) -> float:
    """|VP| + |VQ| − |PQ| measured with the foot F of V on PQ: when F lies inside PQ it is
    h²/(|VP| + |PF|) + h²/(|VQ| + |QF|) (h = |VF|), which keeps its digits when V is nearly on PQ;
    otherwise the angle at V is acute and the plain difference does not cancel. PF is taken as
    (V − P)·(Q − P)/|PQ|, never divided by |PQ|² (which underflows to 0 when P and Q are 1e-200 apart, as
    a subnormal rocker angle puts them).

    >>> round(excess_by_foot(Point(1, 1e-9), Point(0, 0), Point(2, 0)), 30)
    1e-18
    """
    x, y = math.hypot(P.x - V.x, P.y - V.y), math.hypot(Q.x - V.x, Q.y - V.y)
    pqx, pqy = Q.x - P.x, Q.y - P.y
    z = math.hypot(pqx, pqy)
    if z == 0.0:
        return x + y
    wx, wy = V.x - P.x, V.y - P.y                       # (V − P)·PQ and PQ × (V − P), as floats
    s = (wx * pqx + wy * pqy) / z
    if not 0.0 < s < z:
        return x + y - z
    h = abs(pqx * wy - pqy * wx) / z
    return h * h / (x + s) + h * h / (y + (z - s))


def gamma_min_of(A: Point, D: Point, P1: Point, P2: Point) -> float:
    """γmin of the designed linkage with pivots A, D and extreme positions P1, P2, read at the two positions
    with the crank along the frame: the triangle B C D there has sides BC, CD, AD ∓ AB, and each of its
    excesses (two sides minus the third) is one of the triangles A D C_folded, A D C_extended (e.g.
    BC + (AD − AB) − CD = AC_f + AD − DC_f), measured by :func:`excess_by_foot`; then
    tan²(γ/2) = E_BC·E_CD/(perimeter·E_BD). Near the Grashof boundary an extreme position lies within rounding
    of the frame line: its excess, O(h²), survives in the points but not in the lengths AB, BC (γ ∝ h)."""
    return min(frame_gammas(A, D, P1, P2))


def frame_gammas(A: Point, D: Point, P1: Point, P2: Point) -> tuple[float, float]:
    """The transmission angles of :func:`gamma_min_of`'s two crank-on-frame positions (crank folded back onto
    the frame, crank extended along it), each reduced to ≤ 90°."""
    ax, ay = A.x, A.y
    d1, d2 = math.hypot(P1.x - ax, P1.y - ay), math.hypot(P2.x - ax, P2.y - ay)     # abs(P1 − A), abs(P2 − A)
    Cf, Ce = (P1, P2) if d1 < d2 else (P2, P1)
    a, b = abs(d2 - d1) / 2.0, (d1 + d2) / 2.0                                       # half_difference, half_sum
    c, d = math.hypot(Cf.x - D.x, Cf.y - D.y), math.hypot(ax - D.x, ay - D.y)
    out = []
    for e_b, e_c, e_bd, per in ((excess_by_foot(D, A, Ce), excess_by_foot(A, D, Cf), excess_by_foot(Ce, A, D), b + c + d - a),
                                (excess_by_foot(D, A, Cf), excess_by_foot(A, D, Ce), excess_by_foot(Cf, A, D), b + c + d + a)):
        g = math.degrees(2.0 * math.atan2(math.sqrt(max(0.0, e_b * e_c)), math.sqrt(max(0.0, per * e_bd))))
        out.append(min(g, 180.0 - g))
    return out[0], out[1]


def preference(sol: Mapping[str, float]) -> tuple[float, float, float]:
    """The textbook's order of solutions: C1 folded first, then A on D's side, then the shorter frame."""
    return (-sol["C1_folded"], -sol["A_near"], sol["AD"])


def best_index(*flat: Any) -> int | None:
    """Index of the preferred valid candidate; ``flat`` holds (valid, C1_folded, A_near, AD) per candidate."""
    best = None
    for i in range(0, len(flat), 4):
        valid, f, n, ad = flat[i:i + 4]
        if valid:
            key = preference({"C1_folded": f, "A_near": n, "AD": ad})
            if best is None or key < best[0]:
                best = (key, i // 4)
    return None if best is None else best[1]


def pick(i: int | None, *values: Any) -> Any:
    """The ``i``-th value (None when there is no valid candidate)."""
    return None if i is None else values[i]


# ----------------------------------------------------------------------------------------- float kernels
def length_k(ax: float, ay: float, bx: float, by: float) -> float:
    """:func:`length` on floats (:mod:`geomcon.geometry.kernels`)."""
    return math.hypot(bx - ax, by - ay)


def angle_deg_k(ox: float, oy: float, ax: float, ay: float, bx: float, by: float) -> float:
    """:func:`angle_deg` on floats: :func:`~geomcon.geometry.measure._signed_angle_xy` in place (its −π made
    π does not change the absolute value)."""
    ux, uy, vx, vy = ax - ox, ay - oy, bx - ox, by - oy
    if _hypot(ux, uy) == 0.0 or _hypot(vx, vy) == 0.0:
        raise Degenerate("angle of a zero-length vector")
    return _degrees(abs(_atan2(ux * vy - uy * vx, ux * vx + uy * vy)))


def transmission_deg_k(bx: float, by: float, cx: float, cy: float, dx: float, dy: float) -> float:
    """:func:`transmission_deg` on floats (``min(g, 180° − g)`` as a comparison: the same float)."""
    ux, uy, vx, vy = bx - cx, by - cy, dx - cx, dy - cy
    if _hypot(ux, uy) == 0.0 or _hypot(vx, vy) == 0.0:
        raise Degenerate("angle of a zero-length vector")
    g = _degrees(abs(_atan2(ux * vy - uy * vx, ux * vx + uy * vy)))
    t = 180.0 - g
    return t if t < g else g


_hypot, _atan2, _degrees = math.hypot, math.atan2, math.degrees


def along_line_k(px: float, py: float, dx: float, dy: float, t: float, sign: float = 1.0) -> tuple[float, float]:
    """:func:`along_line` of a Line on floats."""
    s = sign * t
    return point_k(px + dx * s, py + dy * s)


def along_ray_k(ox: float, oy: float, dx: float, dy: float, t: float, sign: float = 1.0) -> tuple[float, float]:
    """:func:`along_line` of a Ray on floats (``ray.at(sign·t)``)."""
    sx, sy = point_k(dx * (sign * t), dy * (sign * t))
    return point_k(ox + sx, oy + sy)


def half_difference_k(ax: float, ay: float, px: float, py: float, qx: float, qy: float) -> float:
    """:func:`half_difference` on floats."""
    return abs(math.hypot(qx - ax, qy - ay) - math.hypot(px - ax, py - ay)) / 2.0


def half_sum_k(ax: float, ay: float, px: float, py: float, qx: float, qy: float) -> float:
    """:func:`half_sum` on floats."""
    return (math.hypot(px - ax, py - ay) + math.hypot(qx - ax, qy - ay)) / 2.0


def folded_flag_k(ax: float, ay: float, px: float, py: float, qx: float, qy: float) -> float:
    """:func:`folded_flag` on floats."""
    return 1.0 if math.hypot(px - ax, py - ay) < math.hypot(qx - ax, qy - ay) else 0.0


def near_flag_k(ax: float, ay: float, c1x: float, c1y: float, c2x: float, c2y: float, dx: float, dy: float) -> float:
    """:func:`near_flag` on floats."""
    ux, uy = c2x - c1x, c2y - c1y
    return 1.0 if (ux * (ay - c1y) - uy * (ax - c1x)) * (ux * (dy - c1y) - uy * (dx - c1x)) > 0 else 0.0


def pressure_deg_k(bx: float, by: float, cx: float, cy: float, px: float, py: float, dx: float, dy: float) -> float:
    """:func:`pressure_deg` on floats (the rod ``b − c`` a Point, its angle with the guide's direction measured
    from the origin, as :func:`pressure_on_guide_deg` does)."""
    wx, wy = point_k(bx - cx, by - cy)
    a = math.degrees(abs(_signed_angle_xy(wx - 0.0, wy - 0.0, dx - 0.0, dy - 0.0)))
    return min(a, 180.0 - a)


for _op, _kinds, _out, _k in ((length, "PP", "x", length_k), (pressure_deg, "PPL", "x", pressure_deg_k),
                              (pressure_deg, "PPR", "x", pressure_deg_k), (angle_deg, "PPP", "x", angle_deg_k),
                              (transmission_deg, "PPP", "x", transmission_deg_k),
                              (along_line, "Lx", "P", along_line_k), (along_line, "Lxx", "P", along_line_k),
                              (along_line, "Rx", "P", along_ray_k), (along_line, "Rxx", "P", along_ray_k),
                              (half_difference, "PPP", "x", half_difference_k),
                              (half_sum, "PPP", "x", half_sum_k), (folded_flag, "PPP", "x", folded_flag_k),
                              (near_flag, "PPPP", "x", near_flag_k)):
    register(_op, _kinds, _out, _k, pure=True)                  # none decides by the tolerance


STROKE_STAND_OFF = 0.12
"""How far a stroke's dimension line stands off the line of its ends, a fraction of the stroke."""


def stroke_dimension(a: Point, b: Point, away: Point, symbol: str, value: float) -> marks.Dimension:
    """The stroke ``symbol`` = ``value`` dimensioned between its ends ``a`` and ``b``, standing off on the side away
    from ``away`` (the crank's pivot: the mechanism lies there): 001-05c printed H = 400 and 001-09, 300-02
    S = 160, 300 without a dimension on the drawing, where 000-02 and the crank-sliders dimension theirs.

    >>> d = stroke_dimension(Point(-50.0, 10.0), Point(50.0, 10.0), Point(0.0, 0.0), "S", 100.0)
    >>> d.offset, (d.b - d.a).unit().perp().y * d.offset > 0          # above the ends, away from the pivot below
    (12.0, True)
    """
    n = (b - a).unit().perp()
    side = 1.0 if n.dot(a - away) >= 0.0 else -1.0
    return marks.dimension(a, b, symbol, value, side * STROKE_STAND_OFF * abs(b - a))
