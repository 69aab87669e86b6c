"""Small frozen value objects of plane geometry: Point, Line, Ray, Segment, Circle, Arc, Polyline.

Each validates itself when built (finite coordinates, unit directions, positive radii) and never changes
afterwards. Operations on them are free functions in the neighbouring modules.

Examples
--------
>>> p = Point(3.0, 4.0)
>>> abs(p)
5.0
>>> Line.through(Point(0, 0), Point(2, 0)).direction
Point(x=1.0, y=0.0)
>>> Circle(Point(0, 0), 2.0).r
2.0
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import Degenerate


_SAFE_NORM = 2.0 ** -969
"""Below this length a vector's components may be subnormal and lose relative precision."""


def unit_xy(x: float, y: float) -> tuple[float, float]:
    """The vector (x, y) scaled to length 1, as two floats (the scalar core of :meth:`Point.unit`).

    >>> unit_xy(3.0, 4.0)
    (0.6, 0.8)
    """
    n = math.hypot(x, y)
    if n == 0.0:
        raise Degenerate("direction of a zero-length vector")
    if not _SAFE_NORM <= n < math.inf:
        m = max(abs(x), abs(y))
        x, y = x / m, y / m
        n = math.hypot(x, y)
    return x / n, y / n


def _finite(*values: float) -> bool:
    return all(math.isfinite(v) for v in values)


@dataclass(frozen=True, slots=True, init=False)
class Point:
    """A point (or a free vector) of the plane, in mm.

    Examples
    --------
    >>> Point(1, 2) + Point(3, 4)
    Point(x=4.0, y=6.0)
    >>> Point(1, 0).perp()
    Point(x=-0.0, y=1.0)
    """

    x: float
    y: float

    def __init__(self, x: float, y: float) -> None:
        # the hot path of every construction: coordinates stored through the slots' descriptors (a frozen
        # dataclass's generated __init__ costs three times as much); x − x is 0 exactly when x is finite
        x = float(x)
        y = float(y)
        if x - x != 0.0 or y - y != 0.0:
            raise Degenerate(f"point with a non-finite coordinate ({x}, {y})")
        _POINT_X(self, x)
        _POINT_Y(self, y)

    def __add__(self, other: Point) -> Point:
        return Point(self.x + other.x, self.y + other.y)

    def __sub__(self, other: Point) -> Point:
        return Point(self.x - other.x, self.y - other.y)

    def __mul__(self, k: float) -> Point:
        return Point(self.x * k, self.y * k)

    __rmul__ = __mul__

    def __truediv__(self, k: float) -> Point:
        return Point(self.x / k, self.y / k)

    def __neg__(self) -> Point:
        return Point(-self.x, -self.y)

    def __abs__(self) -> float:
        return math.hypot(self.x, self.y)

    def dot(self, other: Point) -> float:
        """Scalar product."""
        return self.x * other.x + self.y * other.y

    def cross(self, other: Point) -> float:
        """z-component of the vector product: > 0 when ``other`` lies counter-clockwise of ``self``."""
        return self.x * other.y - self.y * other.x

    def perp(self) -> Point:
        """This vector turned by +90° (counter-clockwise)."""
        return Point(-self.y, self.x)

    def unit(self) -> Point:
        """This vector scaled to length 1; a zero vector raises :class:`Degenerate`.

        A vector whose length overflows (components near 1e308) or whose components are subnormal is
        first divided by its largest component, so that the result still has length 1.

        Examples
        --------
        >>> Point(3e-320, 4e-320).unit(), Point(1.5e308, 1.5e308).unit()
        (Point(x=0.6, y=0.8), Point(x=0.7071067811865475, y=0.7071067811865475))
        """
        x, y = unit_xy(self.x, self.y)
        return Point(x, y)

    def tuple(self) -> tuple[float, float]:
        """``(x, y)``."""
        return (self.x, self.y)


_POINT_X = Point.__dict__["x"].__set__
_POINT_Y = Point.__dict__["y"].__set__


@dataclass(frozen=True, slots=True, init=False)
class Line:
    """The infinite line through ``point`` with unit ``direction`` (the direction orients it).

    "Left of the line" means on the counter-clockwise side of its direction.

    >>> Line(Point(1, 2), Point(0, 3))
    Line(point=Point(x=1.0, y=2.0), direction=Point(x=0.0, y=1.0))
    """

    point: Point
    direction: Point

    def __init__(self, point: Point, direction: Point) -> None:
        # the fields stored through the slots' descriptors, the direction made unit as Point.unit does (a
        # dataclass __init__ with a __post_init__ and object.__setattr__ cost twice as much)
        x, y = unit_xy(direction.x, direction.y)
        _LINE_POINT(self, point)
        _LINE_DIRECTION(self, Point(x, y))

    @staticmethod
    def through(a: Point, b: Point) -> Line:
        """The line through ``a`` and ``b``, directed from ``a`` to ``b``."""
        if a == b:
            raise Degenerate(f"line through two coincident points ({a.x:.6g}, {a.y:.6g})")
        return Line(a, b - a)

    @property
    def normal(self) -> Point:
        """Unit normal pointing to the left of the direction."""
        return self.direction.perp()

    def at(self, t: float) -> Point:
        """The point at signed distance ``t`` from ``point`` along the direction."""
        return self.point + self.direction * t


_LINE_POINT = Line.__dict__["point"].__set__
_LINE_DIRECTION = Line.__dict__["direction"].__set__


@dataclass(frozen=True, slots=True, init=False)
class Ray:
    """The half-line from ``origin`` in unit ``direction``.

    >>> Ray(Point(0, 0), Point(3, 4)).direction
    Point(x=0.6, y=0.8)
    """

    origin: Point
    direction: Point

    def __init__(self, origin: Point, direction: Point) -> None:
        x, y = unit_xy(direction.x, direction.y)           # as Line: Point.unit's arithmetic, set in place
        _RAY_ORIGIN(self, origin)
        _RAY_DIRECTION(self, Point(x, y))

    @staticmethod
    def toward(origin: Point, through: Point) -> Ray:
        """The ray from ``origin`` through ``through``."""
        if origin == through:
            raise Degenerate("ray toward its own origin")
        return Ray(origin, through - origin)

    def line(self) -> Line:
        """The supporting line, with the ray's direction."""
        return Line(self.origin, self.direction)

    def at(self, t: float) -> Point:
        """The point at distance ``t`` from the origin."""
        return self.origin + self.direction * t


_RAY_ORIGIN = Ray.__dict__["origin"].__set__
_RAY_DIRECTION = Ray.__dict__["direction"].__set__


@dataclass(frozen=True, slots=True)
class Segment:
    """The segment from ``a`` to ``b``."""

    a: Point
    b: Point

    @property
    def length(self) -> float:
        """Length of the segment."""
        return abs(self.b - self.a)

    def line(self) -> Line:
        """The supporting line, directed from ``a`` to ``b``."""
        return Line.through(self.a, self.b)

    def midpoint(self) -> Point:
        """Midpoint of the segment."""
        return Point((self.a.x + self.b.x) / 2.0, (self.a.y + self.b.y) / 2.0)


@dataclass(frozen=True, slots=True, init=False)
class Circle:
    """The circle of centre ``center`` and radius ``r`` > 0."""

    center: Point
    r: float

    def __init__(self, center: Point, r: float) -> None:
        r = float(r)
        if not 0.0 < r < math.inf:
            raise Degenerate(f"circle about ({center.x:.6g}, {center.y:.6g}) with radius {r:.6g}")
        _CIRCLE_CENTER(self, center)
        _CIRCLE_R(self, r)

    def at(self, angle: float) -> Point:
        """The point at polar ``angle`` (radians, counter-clockwise from +x)."""
        return Point(self.center.x + self.r * math.cos(angle), self.center.y + self.r * math.sin(angle))


_CIRCLE_CENTER = Circle.__dict__["center"].__set__
_CIRCLE_R = Circle.__dict__["r"].__set__


@dataclass(frozen=True, slots=True)
class Arc:
    """The counter-clockwise arc of a circle from polar angle ``start`` sweeping ``sweep`` radians (≥ 0)."""

    center: Point
    r: float
    start: float
    sweep: float

    def __post_init__(self) -> None:
        if not (math.isfinite(self.r) and self.r > 0 and _finite(self.start, self.sweep) and self.sweep >= 0):
            raise Degenerate(f"arc with radius {self.r:.6g} and sweep {self.sweep:.6g}")

    @property
    def circle(self) -> Circle:
        """The full circle the arc lies on."""
        return Circle(self.center, self.r)

    def at(self, fraction: float) -> Point:
        """The point at ``fraction`` (0 … 1) of the arc."""
        return self.circle.at(self.start + fraction * self.sweep)


@dataclass(frozen=True, slots=True)
class Polyline:
    """A chain of points (a sampled curve: pitch curve, cam profile, coupler path), optionally closed.

    Examples
    --------
    >>> Polyline((Point(0, 0), Point(1, 0), Point(1, 1))).length
    2.0
    """

    points: tuple[Point, ...]
    closed: bool = False

    def __post_init__(self) -> None:
        if len(self.points) < 2:
            raise Degenerate(f"polyline with {len(self.points)} point(s)")

    @property
    def length(self) -> float:
        """Total length (including the closing edge when closed)."""
        pts = self.points + (self.points[:1] if self.closed else ())
        return sum(abs(b - a) for a, b in zip(pts, pts[1:]))
