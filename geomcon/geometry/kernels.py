"""Float kernels of the step operations: each operation's arithmetic on plain floats, for the taped replay.

A taped construction replays the same steps on new givens (:mod:`geomcon.scene.tape`). Its compiled plan
(:mod:`geomcon.scene.compiled`) calls, for every step whose operation has a kernel here, the kernel on local
floats instead of the operation on objects: a point is two floats ``x, y``, a line ``px, py, dx, dy`` (its point
and unit direction), a ray ``ox, oy, dx, dy``, a circle ``cx, cy, r``, the candidates of an intersection the
flat tuple ``()``, ``(x, y)`` or ``(x1, y1, x2, y2)``; a number is itself. The objects are made only for what
is read (an answer that is a point, a later drawing).

A kernel is the operation, not a closed form: the same floating-point operations in the same order, line for
line (the same bits: ``tests/test_kernels.py`` holds each kernel to its object form over random and
near-degenerate arguments), and every check the object form makes — a coordinate that is not finite, a zero-length direction, a tolerance
decision, a branch rule's tie — raises as it does. A case the kernel leaves to the object form (parallel lines,
coincident circles: rare, and worded by the step) raises :class:`Fallback`; the plan then evaluates step by
step on objects, which raises or answers as before.

:data:`KERNELS` maps an operation to its kernels by the kinds of its arguments (``"P"`` point, ``"L"`` line,
``"R"`` ray, ``"C"`` circle, ``"x"`` any other value, passed as it is) and the kind of its result (``"T"`` the
candidates of an intersection); :data:`RULES` maps a branch rule's ``rule`` to its kernel, which chooses among
flat candidates given its points flat. The operations of :mod:`geomcon.recipes` register theirs beside them
(:func:`register`).

Examples
--------
>>> circle_circle_k(0.0, 0.0, 5.0, 8.0, 0.0, 5.0)
(4.0, 3.0, 4.0, -3.0)
>>> line_circle_k(-9.0, 0.0, 1.0, 0.0, 0.0, 0.0, 2.0)
(-2.0, 0.0, 2.0, 0.0)
>>> KERNELS[circle_circle][0][:2]
('CC', 'T')
"""
from __future__ import annotations

import math
from typing import Any, Callable

from .. import tolerance as _tolerance
from ..errors import AmbiguousBranch, Coincident, Degenerate
from .branch import (Above, Below, FarthestFrom, LeftOf, Leftmost, NearestTo, OtherThan, RightOf, Rightmost,
                     ToLeftOf, ToRightOf)
from .construct import (circle, circle_through3, foot, line_through, midpoint, parallel, perpendicular,
                        perpendicular_bisector, point_along, point_on_ray, ray_at_angle, thales_circle)
from .intersect import circle_circle, circle_circle_xy as circle_circle_k, line_circle, line_circle_xy as line_circle_k
from .measure import distance
from .primitives import _SAFE_NORM, Circle, Line, Point, Ray, unit_xy

_hypot, _inf = math.hypot, math.inf

Kernel = tuple[str, str, Callable[..., Any]]

KERNELS: dict[Callable[..., Any], list[Kernel]] = {}
"""operation → its kernels: (argument kinds, result kind, kernel)."""

RULES: dict[Callable[..., Any], tuple[str, Callable[..., Any]]] = {}
"""a branch rule's ``rule`` → (the kinds of its points, the kernel choosing among flat candidates)."""


class Fallback(Exception):
    """A case a kernel leaves to the object form of its operation (which decides and words it)."""


PURE: set[Callable[..., Any]] = set()
"""Kernels whose result depends on their arguments alone: no tolerance decision (``REL_TOL`` may be changed
at run time) and no other state. A compiled plan computes such a step once, when it is compiled, if every
argument is a constant of the tape (:func:`geomcon.scene.compiled.compile_plan`)."""


def register(op: Callable[..., Any], kinds: str, result: str, kernel: Callable[..., Any], *,
             pure: bool = False) -> None:
    """Give ``op`` the kernel ``kernel`` for arguments of ``kinds`` and a result of kind ``result``; ``pure``
    when it reads no tolerance and no state (:data:`PURE`).

    >>> register(abs, "x", "x", abs); KERNELS[abs]
    [('x', 'x', <built-in function abs>)]
    >>> del KERNELS[abs]
    """
    KERNELS.setdefault(op, []).append((kinds, result, kernel))
    if pure:
        PURE.add(kernel)


def _bad(x: float, y: float) -> Degenerate:
    return Degenerate(f"point with a non-finite coordinate ({x}, {y})")


# ------------------------------------------------------------------------------------------- objects
def make_point(x: float, y: float) -> Point:
    """The Point of two kernel floats (already finite floats: stored as they are)."""
    p = _NEW(Point)
    _PX(p, x)
    _PY(p, y)
    return p


def make_line(px: float, py: float, dx: float, dy: float) -> Line:
    """The Line of four kernel floats (its direction is unit already: not made unit again)."""
    ln = _NEW(Line)
    _LP(ln, make_point(px, py))
    _LD(ln, make_point(dx, dy))
    return ln


def make_ray(ox: float, oy: float, dx: float, dy: float) -> Ray:
    """The Ray of four kernel floats."""
    r = _NEW(Ray)
    _RO(r, make_point(ox, oy))
    _RD(r, make_point(dx, dy))
    return r


def make_circle(cx: float, cy: float, r: float) -> Circle:
    """The Circle of three kernel floats."""
    c = _NEW(Circle)
    _CC(c, make_point(cx, cy))
    _CR(c, r)
    return c


def make_points(c: tuple) -> tuple[Point, ...]:
    """The candidates of an intersection as Points."""
    return tuple([make_point(c[i], c[i + 1]) for i in range(0, len(c), 2)])


_NEW = object.__new__
_PX, _PY = Point.__dict__["x"].__set__, Point.__dict__["y"].__set__
_LP, _LD = Line.__dict__["point"].__set__, Line.__dict__["direction"].__set__
_RO, _RD = Ray.__dict__["origin"].__set__, Ray.__dict__["direction"].__set__
_CC, _CR = Circle.__dict__["center"].__set__, Circle.__dict__["r"].__set__

MAKERS: dict[str, Callable[..., Any]] = {"P": make_point, "L": make_line, "R": make_ray, "C": make_circle,
                                         "T": make_points}
"""kind → the object of its floats."""

SIZES = {"P": 2, "L": 4, "R": 4, "C": 3, "x": 1, "T": 1}
"""kind → how many locals hold a value of it."""

TYPES = {"P": Point, "L": Line, "R": Ray, "C": Circle}
"""kind → the type of its object."""

FIELDS = {"P": (".x", ".y"), "L": (".point.x", ".point.y", ".direction.x", ".direction.y"),
          "R": (".origin.x", ".origin.y", ".direction.x", ".direction.y"),
          "C": (".center.x", ".center.y", ".r")}
"""kind → how its floats are read off its object."""


# ------------------------------------------------------------------------------------------- points, lines
def point_k(x: Any, y: Any) -> tuple[float, float]:
    """``Point(x, y)``."""
    x = float(x)
    y = float(y)
    if x - x != 0.0 or y - y != 0.0:
        raise _bad(x, y)
    return x, y


def line_k(px: float, py: float, dx: float, dy: float) -> tuple[float, float, float, float]:
    """``Line(point, direction)``: the direction made unit."""
    ux, uy = unit_xy(dx, dy)
    return px, py, ux, uy


def circle_k(cx: float, cy: float, r: Any) -> tuple[float, float, float]:
    """``circle(center, r)``."""
    r = float(r)
    if not 0.0 < r < math.inf:
        raise Degenerate(f"circle about ({cx:.6g}, {cy:.6g}) with radius {r:.6g}")
    return cx, cy, r


def line_through_k(ax: float, ay: float, bx: float, by: float) -> tuple[float, float, float, float]:
    """``line_through(a, b)``: ``Line(a, b − a)``."""
    if ax == bx and ay == by:
        raise Degenerate(f"line through two coincident points ({ax:.6g}, {ay:.6g})")
    dx, dy = bx - ax, by - ay
    if dx - dx != 0.0 or dy - dy != 0.0:
        raise _bad(dx, dy)
    ux, uy = unit_xy(dx, dy)
    return ax, ay, ux, uy


def midpoint_k(ax: float, ay: float, bx: float, by: float) -> tuple[float, float]:
    """``midpoint(a, b)``."""
    x, y = (ax + bx) / 2.0, (ay + by) / 2.0
    if x - x != 0.0 or y - y != 0.0:
        raise _bad(x, y)
    return x, y


def perpendicular_k(px: float, py: float, dx: float, dy: float, tx: float, ty: float
                    ) -> tuple[float, float, float, float]:
    """``perpendicular(line, through)``: ``Line(through, (−dy, dx))``, the direction made unit again."""
    ux, uy = unit_xy(-dy, dx)
    return tx, ty, ux, uy


def parallel_k(px: float, py: float, dx: float, dy: float, tx: float, ty: float
               ) -> tuple[float, float, float, float]:
    """``parallel(line, through)``: ``Line(through, direction)``, the direction made unit again."""
    ux, uy = unit_xy(dx, dy)
    return tx, ty, ux, uy


def perpendicular_bisector_k(ax: float, ay: float, bx: float, by: float) -> tuple[float, float, float, float]:
    """``perpendicular_bisector(a, b)``: ``Line(midpoint(a, b), (b − a).perp())``."""
    if ax == bx and ay == by:
        raise Degenerate(f"perpendicular bisector of a zero-length chord at ({ax:.6g}, {ay:.6g})")
    mx, my = midpoint_k(ax, ay, bx, by)
    vx, vy = bx - ax, by - ay
    if vx - vx != 0.0 or vy - vy != 0.0:
        raise _bad(vx, vy)
    ux, uy = unit_xy(-vy, vx)
    return mx, my, ux, uy


def foot_k(px: float, py: float, dx: float, dy: float, qx: float, qy: float) -> tuple[float, float]:
    """``foot(line, p)``: ``line.at((p − point)·direction)``."""
    wx, wy = qx - px, qy - py
    if wx - wx != 0.0 or wy - wy != 0.0:
        raise _bad(wx, wy)
    t = wx * dx + wy * dy
    sx, sy = dx * t, dy * t
    if sx - sx != 0.0 or sy - sy != 0.0:
        raise _bad(sx, sy)
    x, y = px + sx, py + sy
    if x - x != 0.0 or y - y != 0.0:
        raise _bad(x, y)
    return x, y


def point_along_k(ox: float, oy: float, tx: float, ty: float, dist: Any) -> tuple[float, float]:
    """``point_along(origin, toward, dist)``."""
    if ox == tx and oy == ty:
        raise Degenerate("ray toward its own origin")
    dx, dy = tx - ox, ty - oy
    n = _hypot(dx, dy)
    ux, uy = (dx / n, dy / n) if _SAFE_NORM <= n < _inf else unit_xy(dx, dy)
    x, y = ox + ux * dist, oy + uy * dist
    if type(x) is not float or type(y) is not float or x - x != 0.0 or y - y != 0.0:
        return point_k(x, y)
    return x, y


def point_on_ray_k(ox: float, oy: float, dx: float, dy: float, dist: Any) -> tuple[float, float]:
    """``point_on_ray(ray, dist)``: ``origin + direction·dist``."""
    sx, sy = point_k(dx * dist, dy * dist)
    return point_k(ox + sx, oy + sy)


def ray_at_angle_k(ox: float, oy: float, tx: float, ty: float, angle: float) -> tuple[float, float, float, float]:
    """``ray_at_angle(origin, toward, angle)``."""
    if ox == tx and oy == ty:
        raise Degenerate("ray toward its own origin")
    dx, dy = tx - ox, ty - oy                     # unit_xy in place where the length is in range: the same bits
    n = _hypot(dx, dy)
    dx, dy = (dx / n, dy / n) if _SAFE_NORM <= n < _inf else unit_xy(dx, dy)
    c, s = math.cos(angle), math.sin(angle)
    x, y = c * dx - s * dy, s * dx + c * dy
    if x - x != 0.0 or y - y != 0.0:
        raise _bad(x, y)
    n = _hypot(x, y)
    return (ox, oy, x / n, y / n) if _SAFE_NORM <= n < _inf else (ox, oy, *unit_xy(x, y))


def distance_k(ax: float, ay: float, bx: float, by: float) -> float:
    """``distance(a, b)``."""
    return math.hypot(bx - ax, by - ay)


# ------------------------------------------------------------------------------------------- circles
def circle_through3_k(ax: float, ay: float, bx: float, by: float, cx: float, cy: float
                      ) -> tuple[float, float, float]:
    """``circle_through3(a, b, c)``: two perpendicular bisectors met; collinear points are left to the object
    form (it words the refusal)."""
    abx, aby = bx - ax, by - ay
    cbx, cby = cx - bx, cy - by
    cax, cay = cx - ax, cy - ay
    span = _hypot(abx, aby)                            # max() of the three written as its comparisons: the
    h = _hypot(cbx, cby)                               # first of equal values kept, a NaN never taken after
    if h > span:                                       # the first (the same float, without the call)
        span = h
    h = _hypot(cax, cay)
    if h > span:
        span = h
    # Decide collinearity first: two coincident points (a == c) are collinear with any third, and their
    # bisectors would coincide rather than fail to meet.
    if abs(abx * cay - aby * cax) <= _tolerance.REL_TOL * span * span:     # tol(span)·span in place: span ≥ 0
        raise Fallback("collinear")
    n = _hypot(aby, abx)                                # unit_xy(−aby, abx), in place where in range
    d1x, d1y = (-aby / n, abx / n) if _SAFE_NORM <= n < _inf else unit_xy(-aby, abx)
    n = _hypot(cby, cbx)
    d2x, d2y = (-cby / n, cbx / n) if _SAFE_NORM <= n < _inf else unit_xy(-cby, cbx)
    m1x, m1y = (ax + bx) / 2.0, (ay + by) / 2.0
    m2x, m2y = (bx + cx) / 2.0, (by + cy) / 2.0
    wx, wy = m2x - m1x, m2y - m1y
    sine = d1x * d2y - d1y * d2x
    if abs(sine) <= _tolerance.REL_TOL:                 # tol(1.0): parallel (or coincident) bisectors, collinear
        raise Fallback("collinear")
    t = (wx * d2y - wy * d2x) / sine
    ox, oy = m1x + d1x * t, m1y + d1y * t
    if ox - ox != 0.0 or oy - oy != 0.0:
        raise _bad(ox, oy)
    r = _hypot(ax - ox, ay - oy)
    if not 0.0 < r < _inf:
        raise Degenerate(f"circle about ({ox:.6g}, {oy:.6g}) with radius {r:.6g}")
    return ox, oy, r


def thales_circle_k(ax: float, ay: float, bx: float, by: float) -> tuple[float, float, float]:
    """``thales_circle(a, b)``."""
    mx, my = midpoint_k(ax, ay, bx, by)
    return circle_k(mx, my, math.hypot(bx - ax, by - ay) / 2.0)


# ------------------------------------------------------------------------------------------- branch rules
def _larger_k(c: tuple, s0: float, s1: float, what: str) -> tuple[float, float]:
    # max(hypot(…), 1e-300) and max(scale, |s0|, |s1|) written as comparisons, as max() makes them (the first
    # of equal values kept, a NaN never taken after the first): the same floats without its call
    x0, y0, x1, y1 = c
    h = _hypot(x0 - x1, y0 - y1)
    m = 1e-300 if 1e-300 > h else h
    a = abs(s0)
    if a > m:
        m = a
    a = abs(s1)
    if a > m:
        m = a
    if abs(s0 - s1) <= _tolerance.REL_TOL * m:
        raise AmbiguousBranch(f"{what}: both intersections qualify equally (scores {s0:.6g}, {s1:.6g})")
    return (x0, y0) if s0 > s1 else (x1, y1)


def _one(c: tuple, what: str) -> tuple[float, float]:
    if len(c) == 2:
        return c                                          # type: ignore[return-value]
    raise AmbiguousBranch(f"{what}: expected 1 or 2 candidates, got {len(c) // 2}")


def _unit_between(ax: float, ay: float, bx: float, by: float, what: str) -> tuple[float, float]:
    dx, dy = bx - ax, by - ay
    if dx == 0.0 and dy == 0.0:
        raise AmbiguousBranch(f"{what}: the dividing line through ({ax:.6g}, {ay:.6g}) has zero length")
    return unit_xy(dx, dy)


def to_left_of_k(c: tuple, px: float, py: float) -> tuple[float, float]:
    """``ToLeftOf(p)``."""
    if len(c) != 4:
        return _one(c, "to the left of a point")
    return _larger_k(c, px - c[0], px - c[2], "to the left of a point")


def to_right_of_k(c: tuple, px: float, py: float) -> tuple[float, float]:
    """``ToRightOf(p)``."""
    if len(c) != 4:
        return _one(c, "to the right of a point")
    return _larger_k(c, c[0] - px, c[2] - px, "to the right of a point")


def _apart(qx: float, qy: float, px: float, py: float) -> float:
    dx, dy = qx - px, qy - py                             # abs(q − p), the difference a Point
    if dx - dx != 0.0 or dy - dy != 0.0:
        raise _bad(dx, dy)
    return math.hypot(dx, dy)


def farthest_from_k(c: tuple, px: float, py: float, what: str = "farthest from a point") -> tuple[float, float]:
    """``FarthestFrom(p)`` (and ``OtherThan(p)``: the one farther from it)."""
    if len(c) != 4:
        return _one(c, what)
    return _larger_k(c, _apart(c[0], c[1], px, py), _apart(c[2], c[3], px, py), what)


def other_than_k(c: tuple, px: float, py: float) -> tuple[float, float]:
    """``OtherThan(p)``."""
    return farthest_from_k(c, px, py, "other than a known point")


def nearest_to_k(c: tuple, px: float, py: float) -> tuple[float, float]:
    """``NearestTo(p)``."""
    if len(c) != 4:
        return _one(c, "nearest to a point")
    return _larger_k(c, -_apart(c[0], c[1], px, py), -_apart(c[2], c[3], px, py), "nearest to a point")


def left_of_k(c: tuple, ax: float, ay: float, bx: float, by: float) -> tuple[float, float]:
    """``LeftOf(a, b)``."""
    what = "left of a directed line"
    dx, dy = _unit_between(ax, ay, bx, by, what)
    if len(c) != 4:
        return _one(c, what)
    return _larger_k(c, dx * (c[1] - ay) - dy * (c[0] - ax), dx * (c[3] - ay) - dy * (c[2] - ax), what)


def right_of_k(c: tuple, ax: float, ay: float, bx: float, by: float) -> tuple[float, float]:
    """``RightOf(a, b)``."""
    what = "right of a directed line"
    dx, dy = _unit_between(ax, ay, bx, by, what)
    if len(c) != 4:
        return _one(c, what)
    return _larger_k(c, -(dx * (c[1] - ay) - dy * (c[0] - ax)), -(dx * (c[3] - ay) - dy * (c[2] - ax)), what)


def _upward_normal_k(ax: float, ay: float, bx: float, by: float) -> tuple[float, float]:
    dx, dy = bx - ax, by - ay
    if dx == 0.0 and dy == 0.0:
        raise AmbiguousBranch(f"above/below a line: the dividing line through ({ax:.6g}, {ay:.6g}) has zero length")
    n = _hypot(dx, dy)                            # unit_xy in place where the length is in range: the same bits
    dx, dy = (dx / n, dy / n) if _SAFE_NORM <= n < _inf else unit_xy(dx, dy)
    if abs(dx) <= _tolerance.REL_TOL:             # the normal (−dy, dx) is horizontal
        raise AmbiguousBranch("above/below a vertical line is undefined: use left/right of a directed line")
    return (-dy, dx) if dx > 0 else (dy, -dx)


def above_k(c: tuple, ax: float, ay: float, bx: float, by: float) -> tuple[float, float]:
    """``Above(a, b)``."""
    nx, ny = _upward_normal_k(ax, ay, bx, by)
    return above_n_k(c, ax, ay, nx, ny)


def above_n_k(c: tuple, ax: float, ay: float, nx: float, ny: float) -> tuple[float, float]:
    """``Above(a, b)`` given the line's upward normal ``_upward_normal_k(a, b)``."""
    if len(c) != 4:
        return _one(c, "above a line")
    x0, y0, x1, y1 = c
    return _larger_k(c, nx * (x0 - ax) + ny * (y0 - ay), nx * (x1 - ax) + ny * (y1 - ay), "above a line")


def below_k(c: tuple, ax: float, ay: float, bx: float, by: float) -> tuple[float, float]:
    """``Below(a, b)``."""
    nx, ny = _upward_normal_k(ax, ay, bx, by)
    return below_n_k(c, ax, ay, nx, ny)


def below_n_k(c: tuple, ax: float, ay: float, nx: float, ny: float) -> tuple[float, float]:
    """``Below(a, b)`` given the line's upward normal ``_upward_normal_k(a, b)``."""
    if len(c) != 4:
        return _one(c, "below a line")
    x0, y0, x1, y1 = c
    return _larger_k(c, -(nx * (x0 - ax) + ny * (y0 - ay)), -(nx * (x1 - ax) + ny * (y1 - ay)), "below a line")


def leftmost_k(c: tuple) -> tuple[float, float]:
    """``Leftmost()``."""
    if len(c) != 4:
        return _one(c, "the left one")
    return _larger_k(c, -c[0], -c[2], "the left one")


def rightmost_k(c: tuple) -> tuple[float, float]:
    """``Rightmost()``."""
    if len(c) != 4:
        return _one(c, "the right one")
    return _larger_k(c, c[0], c[2], "the right one")


for _op, _kinds, _out, _k in (
        (Point, "xx", "P", point_k), (Line, "PP", "L", line_k), (circle, "Px", "C", circle_k),
        (line_through, "PP", "L", line_through_k), (midpoint, "PP", "P", midpoint_k),
        (perpendicular, "LP", "L", perpendicular_k), (parallel, "LP", "L", parallel_k),
        (perpendicular_bisector, "PP", "L", perpendicular_bisector_k), (foot, "LP", "P", foot_k),
        (point_along, "PPx", "P", point_along_k), (point_on_ray, "Rx", "P", point_on_ray_k),
        (ray_at_angle, "PPx", "R", ray_at_angle_k), (distance, "PP", "x", distance_k),
        (circle_through3, "PPP", "C", circle_through3_k), (thales_circle, "PP", "C", thales_circle_k),
        (line_circle, "LC", "T", line_circle_k), (circle_circle, "CC", "T", circle_circle_k)):
    # the circumcircle and the two intersections decide by the tolerance: not pure
    register(_op, _kinds, _out, _k, pure=_k not in (circle_through3_k, line_circle_k, circle_circle_k))

for _rule, _kinds, _k in ((ToLeftOf.rule, "P", to_left_of_k), (ToRightOf.rule, "P", to_right_of_k),
                          (FarthestFrom.rule, "P", farthest_from_k), (OtherThan.rule, "P", other_than_k),
                          (NearestTo.rule, "P", nearest_to_k), (LeftOf.rule, "PP", left_of_k),
                          (RightOf.rule, "PP", right_of_k), (Above.rule, "PP", above_k),
                          (Below.rule, "PP", below_k), (Leftmost.rule, "", leftmost_k),
                          (Rightmost.rule, "", rightmost_k)):
    RULES[_rule] = (_kinds, _k)

SPLIT: dict[Callable[..., Any], tuple[Callable[..., Any], Callable[..., Any], int]] = {
    Above.rule: (_upward_normal_k, above_n_k, 2), Below.rule: (_upward_normal_k, below_n_k, 2)}
"""a branch rule's ``rule`` → its kernel in two parts: ``(prep, choose, n)`` with ``kernel(c, *pts) ==
choose(c, *pts[:n], *prep(*pts))``; a compiled plan makes ``prep`` once for the steps that choose by the same
points (the four branches of a crank-rocker's extremes each above or below the frame line)."""
