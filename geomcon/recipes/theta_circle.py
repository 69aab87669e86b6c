"""The θ-circle and its relatives: circles through C1, C2 from whose arc the chord is seen under a given
angle, built as the textbook does (C2P ⊥ C1C2, ∠C2C1P = 90° − β, the circle through C1, C2, P).

Examples
--------
>>> from geomcon.geometry import Point
>>> k = seeing_circle(Point(0, 0), Point(2, 0), 90.0, 1)
>>> k.center, k.r
(Point(x=1.0, y=0.0), 1.0)
>>> c = seeing_circle(Point(0, 0), Point(2, 0), 45.0, 1).center
>>> round(c.x, 12), round(c.y, 12)
(1.0, 1.0)
"""
from __future__ import annotations

import math

from ..analytic.linkages import theta_from_k
from ..errors import Degenerate
from ..geometry import (Arc, Circle, Line, Point, circle_through3, line_line, polar_angle, ray_at_angle,
                        thales_circle)
from ..geometry.kernels import (Fallback, circle_through3_k, point_k, ray_at_angle_k, register,
                                thales_circle_k)
from ..geometry.primitives import _SAFE_NORM, Ray, unit_xy
from .. import tolerance as _tolerance
from ..scene import Ref, Role, Scene


_hypot, _inf = math.hypot, math.inf

THETA_MIN_RAD = 1e-3
"""Smallest θ > 0 (0.057°, K ≈ 1.00064) a θ-circle is built for. Its radius is then about 500 chords; a line
through C1 meets it again at A nearly tangentially, so A carries an error of about ε·(R/C1C2)² of the chord:
2e-10 here, growing as 1/θ². Smaller θ are refused with the advice to give K = 1, the exact line."""


K_MAX_ACUTE: float = (270.0 - math.degrees(THETA_MIN_RAD)) / (90.0 + math.degrees(THETA_MIN_RAD))
"""Largest K (≈ 2.99745) of a design that needs θ < 90° with a usable θ-arc: at θ = 90° − 0.057° the arc QC1
of a crank-slider design is 1e-3 of the stroke high (the pivot A, the offset and the folded distance all shrink
to C1 as θ → 90°), and the guide-bar designs swing through ψ = θ < 90°."""

K_MAX_OBTUSE: float = (360.0 - math.degrees(THETA_MIN_RAD)) / math.degrees(THETA_MIN_RAD)
"""Largest K (≈ 6282) of a design whose construction sees a chord under θ or 180° − θ (crank-rocker,
slotter): at 180° − θ = 0.057° the circle's radius is 500 chords, as at the smallest θ."""


def refuse_tiny_theta(K: float) -> None:
    """Refuse 1 < K whose θ is below :data:`THETA_MIN_RAD` (K = 1 itself is handled as the line).

    >>> refuse_tiny_theta(1.0); refuse_tiny_theta(1.25)
    >>> refuse_tiny_theta(1 + 1e-6)
    Traceback (most recent call last):
    ...
    geomcon.errors.NotAMechanism: K = 1.000001 gives θ = 9e-05°: the θ-circle's radius would be 3.2e+05 times the chord C1C2 and its intersections lose accuracy; give K = 1 (the line) or K ≥ 1.00064
    """
    from ..errors import NotAMechanism
    th = math.pi * (K - 1.0) / (K + 1.0)
    if 0.0 < th < THETA_MIN_RAD:
        raise NotAMechanism(f"K = {K:.10g} gives θ = {math.degrees(th):.2g}°: the θ-circle's radius would be "
                            f"{1 / (2 * math.sin(th)):.2g} times the chord C1C2 and its intersections lose accuracy; "
                            "give K = 1 (the line) or K ≥ 1.00064")


def ray_from(origin: Point, toward: Point, angle_deg: float):
    """The ray from ``origin`` turned by ``angle_deg`` (counter-clockwise positive) from ``origin → toward``."""
    return ray_at_angle(origin, toward, math.radians(angle_deg))


def ray_line(r) -> Line:
    """The line carrying a ray, with its direction (a step operation)."""
    return r.line()


def perpendicular_at(a: Point, b: Point) -> Line:
    """The perpendicular to ``ab`` at ``b``.

    >>> perpendicular_at(Point(0, 0), Point(2, 0)).direction
    Point(x=-0.0, y=1.0)
    """
    return Line(b, Point(-(b.y - a.y), b.x - a.x))          # (b − a).perp(), without the two Points


def meet_lines(l1, l2) -> Point:
    """The intersection of two lines (or rays' lines) that must cross.

    >>> meet_lines(Line(Point(0, 0), Point(1, 1)), Line(Point(2, 0), Point(0, 1)))
    Point(x=2.0, y=2.0)
    """
    if type(l1) is Ray:
        # line_line(l1.line(), l2) on floats: the ray's line makes its direction unit once more
        d1x, d1y = unit_xy(l1.direction.x, l1.direction.y)
        p1, d2 = l1.origin, l2.direction
        s = d1x * d2.y - d1y * d2.x
        if abs(s) > _tolerance.REL_TOL:                   # tol(1.0) in place
            wx, wy = l2.point.x - p1.x, l2.point.y - p1.y
            t = (wx * d2.y - wy * d2.x) / s
            return Point(p1.x + d1x * t, p1.y + d1y * t)
        l1 = l1.line()                                     # parallel or coincident: as line_line says
    return _meet(l1, l2)


def _meet(l1: Line, l2: Line) -> Point:
    from ..errors import NoIntersection
    l1 = l1.line() if hasattr(l1, "line") else l1
    pts = line_line(l1, l2)
    if not pts:
        raise NoIntersection("the two lines are parallel")
    return pts[0]


def complement_turn(theta_deg: float, side: int) -> float:
    """The signed turn 90° − θ towards ``side`` (+1 counter-clockwise)."""
    return side * (90.0 - theta_deg)


def seeing_circle(c1: Point, c2: Point, beta_deg: float, side: int) -> Circle:
    """The circle through c1, c2 whose arc on ``side`` (+1: left of c1→c2) sees c1c2 under ``beta_deg``."""
    if abs(beta_deg - 90.0) < 1e-12:
        return thales_circle(c1, c2)
    # meet_lines(ray_from(c1, c2, side·(90° − β)), perpendicular_at(c1, c2)) on floats: the same operations
    # (the ray's direction made unit three times, as Ray.toward, rotate_ray and Ray.line do), the same bits
    if c1 == c2:
        raise Degenerate("ray toward its own origin")
    vx, vy = c2.x - c1.x, c2.y - c1.y
    dx, dy = unit_xy(vx, vy)
    angle = math.radians(side * (90.0 - beta_deg))
    c, s = math.cos(angle), math.sin(angle)
    d1x, d1y = unit_xy(c * dx - s * dy, s * dx + c * dy)
    d1x, d1y = unit_xy(d1x, d1y)
    d2x, d2y = unit_xy(-vy, vx)                            # the perpendicular at c2: (c2 − c1) turned
    sine = d1x * d2y - d1y * d2x
    if abs(sine) <= _tolerance.REL_TOL:                    # tol(1.0); parallel: as the step operations say
        return circle_through3(c1, c2, meet_lines(ray_from(c1, c2, side * (90.0 - beta_deg)), perpendicular_at(c1, c2)))
    wx, wy = c2.x - c1.x, c2.y - c1.y
    t = (wx * d2y - wy * d2x) / sine
    return circle_through3(c1, c2, Point(c1.x + d1x * t, c1.y + d1y * t))


def arc_from_to(circle: Circle, start: Point, end: Point) -> Arc:
    """The counter-clockwise arc of ``circle`` from ``start`` to ``end``."""
    a0 = polar_angle(circle.center, start)
    sweep = (polar_angle(circle.center, end) - a0) % (2 * math.pi)
    return Arc(circle.center, circle.r, a0, sweep)


def arc_point_from_end(arc: Arc, end: Point, s: float) -> Point:
    """The point of ``arc`` a fraction ``s`` of its sweep back from its end ``end`` (s = 0: ``end``), formed as
    ``end`` plus the chord 2r·sin(δ/2) (δ = s·sweep): accurate relative to its distance from ``end`` — the
    centre's coordinates, r from ``end``, are not subtracted, so a point 1e-9 of r from the end keeps its digits.

    >>> from geomcon.geometry import Arc
    >>> p = arc_point_from_end(Arc(Point(0.0, 0.0), 1.0, 0.0, math.pi / 2), Point(0.0, 1.0), 0.5)
    >>> round(p.x, 12), round(p.y, 12)
    (0.707106781187, 0.707106781187)
    """
    half = s * arc.sweep / 2.0
    phi = polar_angle(arc.center, end) - half
    chord = 2.0 * arc.r * math.sin(half)
    return Point(end.x + chord * math.sin(phi), end.y - chord * math.cos(phi))


def theta_of_k(K: float) -> float:
    """θ = 180°(K − 1)/(K + 1) (a step operation): the twin's formula, imported once (an import statement in
    the step cost more than the step)."""
    return theta_from_k(K)


def add_theta_step(sc: Scene, K: float, *, note: tuple[str, str] = ("", "")) -> Ref:
    """The first step of every design by K: θ from K (measured, numbered), and K itself as a hidden answer.

    The caption ends with the formula, so that the measured value appended to it reads ``θ = 180°(K − 1)/(K + 1)
    = 16.364°`` (not ``K = 1.2 = 16.364°``); ``note`` (a sentence) goes before it."""
    th = sc.add("theta", theta_of_k, K, role=Role.MEASUREMENT, unit="deg",
                caption=(f"{note[0]}With K = {K:g}: θ = 180°(K − 1)/(K + 1)",
                         f"{note[1]}K = {K:g},极位夹角 θ = 180°(K − 1)/(K + 1)"))
    sc.add("K", float, K, role=Role.MEASUREMENT, visible=False)
    return th


def add_theta_circle(sc: Scene, C1: Ref, C2: Ref, theta: Ref, side: int, *, side_words: tuple[str, str],
                     prefix: str = "", label: str = "P") -> Ref:
    """Add the textbook's steps (C2P ⊥ C1C2, ∠C2C1P = 90° − θ, circle C1C2P); return the circle.

    ``side`` +1 puts P (and the arc from which C1C2 is seen under θ) on the left of C1→C2. ``prefix`` keeps
    the keys of a second θ-circle apart; the perpendicular at C2 is shared.
    """
    en, zh = side_words
    n2 = Ref("n2") if "n2" in sc else sc.add("n2", perpendicular_at, C1, C2,
                                              caption=("Perpendicular to C1C2 at C2", "过 C2 作 C1C2 的垂线"))
    compl = sc.add(f"{prefix}compl", complement_turn, theta, side, visible=False, unit="deg")
    rP = sc.add(f"{prefix}rP", ray_from, C1, C2, compl,
                caption=(f"From C1 draw a line at 90° − θ to C1C2, {en}", f"过 C1 作与 C1C2 成 90° − θ 的直线({zh})"))
    P = sc.add(f"{prefix}P", meet_lines, rP, n2, style="point", label=label,
               caption=(f"The two lines meet at {label}", f"两线交于 {label}"))
    return sc.add(f"{prefix}kTheta", circle_through3, C1, C2, P, style="theta-circle",
                  caption=(f"The circle through C1, C2, {label}: from its arc {en} C1C2 is seen under θ",
                           f"作 △C1C2{label} 的外接圆(其{' ' * zh[:1].isascii()}{zh}的圆弧上各点对 C1C2 张角为 θ)"))


def add_seeing_circle(sc: Scene, key: str, C1: Ref, C2: Ref, beta: Ref, side: int, caption: tuple[str, str]) -> Ref:
    """A circle through C1, C2 seeing the chord under ``beta`` (a step value, degrees) on ``side``."""
    return sc.add(key, seeing_circle, C1, C2, beta, side, caption=caption)


__all__ = ["add_seeing_circle", "add_theta_circle", "arc_from_to", "arc_point_from_end", "meet_lines", "perpendicular_at", "ray_from",
           "seeing_circle", "Role"]


# ----------------------------------------------------------------------------------------- float kernels
def ray_from_k(ox: float, oy: float, tx: float, ty: float, angle_deg: float) -> tuple[float, float, float, float]:
    """:func:`ray_from` on floats (:mod:`geomcon.geometry.kernels`)."""
    return ray_at_angle_k(ox, oy, tx, ty, math.radians(angle_deg))


def perpendicular_at_k(ax: float, ay: float, bx: float, by: float) -> tuple[float, float, float, float]:
    """:func:`perpendicular_at` on floats."""
    dx, dy = -(by - ay), bx - ax
    if dx - dx != 0.0 or dy - dy != 0.0:
        raise Degenerate(f"point with a non-finite coordinate ({dx}, {dy})")
    n = _hypot(dx, dy)
    return (bx, by, dx / n, dy / n) if _SAFE_NORM <= n < _inf else (bx, by, *unit_xy(dx, dy))


def meet_ray_line_k(ox: float, oy: float, rx: float, ry: float, px: float, py: float, dx: float, dy: float
                    ) -> tuple[float, float]:
    """:func:`meet_lines` of a ray and a line on floats (parallel ones are left to the object form)."""
    n = _hypot(rx, ry)                                # unit_xy in place where in range: the same bits
    d1x, d1y = (rx / n, ry / n) if _SAFE_NORM <= n < _inf else unit_xy(rx, ry)
    s = d1x * dy - d1y * dx
    if abs(s) > _tolerance.REL_TOL:                   # tol(1.0) in place
        wx, wy = px - ox, py - oy
        t = (wx * dy - wy * dx) / s
        x, y = ox + d1x * t, oy + d1y * t
        if x - x != 0.0 or y - y != 0.0:
            raise Degenerate(f"point with a non-finite coordinate ({x}, {y})")
        return x, y
    raise Fallback("parallel")


def meet_line_line_k(ax: float, ay: float, ux: float, uy: float, bx: float, by: float, vx: float, vy: float
                     ) -> tuple[float, float]:
    """:func:`meet_lines` of two lines on floats (line_line's arithmetic; parallel ones are left to the object
    form)."""
    wx, wy = point_k(bx - ax, by - ay)
    s = ux * vy - uy * vx
    if abs(s) <= _tolerance.REL_TOL:                  # tol(1.0)
        raise Fallback("parallel")
    t = (wx * vy - wy * vx) / s
    sx, sy = point_k(ux * t, uy * t)
    return point_k(ax + sx, ay + sy)


def seeing_circle_k(ax: float, ay: float, bx: float, by: float, beta_deg: float, side: int
                    ) -> tuple[float, float, float]:
    """:func:`seeing_circle` on floats."""
    if abs(beta_deg - 90.0) < 1e-12:
        return thales_circle_k(ax, ay, bx, by)
    if ax == bx and ay == by:
        raise Degenerate("ray toward its own origin")
    vx, vy = bx - ax, by - ay
    dx, dy = unit_xy(vx, vy)
    angle = math.radians(side * (90.0 - beta_deg))
    c, s = math.cos(angle), math.sin(angle)
    d1x, d1y = unit_xy(c * dx - s * dy, s * dx + c * dy)
    d1x, d1y = unit_xy(d1x, d1y)
    d2x, d2y = unit_xy(-vy, vx)
    sine = d1x * d2y - d1y * d2x
    if abs(sine) <= _tolerance.REL_TOL:
        raise Fallback("parallel")
    wx, wy = bx - ax, by - ay
    t = (wx * d2y - wy * d2x) / sine
    px, py = point_k(ax + d1x * t, ay + d1y * t)
    return circle_through3_k(ax, ay, bx, by, px, py)


register(ray_from, "PPx", "R", ray_from_k, pure=True)
register(perpendicular_at, "PP", "L", perpendicular_at_k, pure=True)
register(meet_lines, "RL", "P", meet_ray_line_k)
register(meet_lines, "LL", "P", meet_line_line_k)
register(seeing_circle, "PPxx", "C", seeing_circle_k)
