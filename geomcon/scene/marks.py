"""Drawing marks: the notation a textbook adds to a figure (angle arcs, dimensions, ground and slider
symbols). They are plain frozen values produced by annotation steps, so they are computed only when a
drawing is asked for.

Examples
--------
>>> from geomcon.geometry import Point
>>> m = AngleMark(Point(0, 0), Point(1, 0), Point(0, 1), "θ", 90.0)
>>> m.text
'θ=90.00°'
"""
from __future__ import annotations

import math

from ..geometry.primitives import Point, Segment
from ..values import Frozen, store

class AngleMark(Frozen):
    """The arc marking the angle at ``vertex`` from ray vertex→a to ray vertex→b (the smaller angle).

    ``radius`` is in model mm; None lets the renderer choose it.
    """

    __slots__ = _FIELDS = ("vertex", "a", "b", "symbol", "value", "radius")
    vertex: Point
    a: Point
    b: Point
    symbol: str
    value: float
    radius: float | None

    def __init__(self, vertex: Point, a: Point, b: Point, symbol: str, value: float, radius: float | None = None) -> None:
        store(self, "vertex", vertex)
        store(self, "a", a)
        store(self, "b", b)
        store(self, "symbol", symbol)
        store(self, "value", value)
        store(self, "radius", radius)

    @property
    def text(self) -> str:
        """The printed label, e.g. ``θ=12.51°``; an angle of 0 has no arc to label, and says why after its value
        (001-01's γ1 = 0: coupler and rocker in one line), the symbol first as for any angle.

        >>> AngleMark(Point(0, 0), Point(1, 0), Point(2, 0), "γ1", -1e-12).text
        'γ1=0° (collinear)'
        """
        if abs(self.value) < 0.005:
            return f"{self.symbol}=0° (collinear)"
        return f"{self.symbol}={self.value:.2f}°"


class RightAngleMark(Frozen):
    """The small square marking a right angle at ``vertex`` between rays vertex→a and vertex→b."""

    __slots__ = _FIELDS = ("vertex", "a", "b")
    vertex: Point
    a: Point
    b: Point

    def __init__(self, vertex: Point, a: Point, b: Point) -> None:
        store(self, "vertex", vertex)
        store(self, "a", a)
        store(self, "b", b)


class Dimension(Frozen):
    """A linear dimension of ``a``–``b`` drawn parallel to it, ``offset`` mm to the left of a→b."""

    __slots__ = _FIELDS = ("a", "b", "symbol", "value", "offset")
    a: Point
    b: Point
    symbol: str
    value: float
    offset: float

    def __init__(self, a: Point, b: Point, symbol: str, value: float, offset: float) -> None:
        store(self, "a", a)
        store(self, "b", b)
        store(self, "symbol", symbol)
        store(self, "value", value)
        store(self, "offset", offset)

    @property
    def text(self) -> str:
        """The printed label, e.g. ``H=101.74``."""
        return f"{self.symbol}={self.value:.2f}"


class Ground(Frozen):
    """The hatched ground symbol of a fixed pivot at ``at``, the ground lying towards ``angle`` (rad)."""

    __slots__ = _FIELDS = ("at", "angle")
    at: Point
    angle: float

    def __init__(self, at: Point, angle: float = -math.pi / 2) -> None:
        store(self, "at", at)
        store(self, "angle", angle)


class Slider(Frozen):
    """A slider block centred at ``at`` moving along unit-free ``direction``."""

    __slots__ = _FIELDS = ("at", "direction")
    at: Point
    direction: Point

    def __init__(self, at: Point, direction: Point) -> None:
        store(self, "at", at)
        store(self, "direction", direction)


class Guide(Frozen):
    """A straight guide from ``a`` to ``b`` hatched on its left (``side`` = +1) or right (−1)."""

    __slots__ = _FIELDS = ("a", "b", "side")
    a: Point
    b: Point
    side: int

    def __init__(self, a: Point, b: Point, side: int = -1) -> None:
        store(self, "a", a)
        store(self, "b", b)
        store(self, "side", side)


class Bearing(Frozen):
    """The guide of a translating follower's stem: two short hatched bearing blocks either side of the stem,
    centred at ``at``, the stem running along ``direction`` (the same symbol for every cam)."""

    __slots__ = _FIELDS = ("at", "direction")
    at: Point
    direction: Point

    def __init__(self, at: Point, direction: Point) -> None:
        store(self, "at", at)
        store(self, "direction", direction)


def bearing(at: Point, direction: Point) -> Bearing:
    """Build a :class:`Bearing` (an annotation step operation).

    >>> bearing(Point(0, 0), Point(0, 1)).direction
    Point(x=0.0, y=1.0)
    """
    return Bearing(at, direction)


class Rotation(Frozen):
    """The sense of rotation of a part turning about ``at`` (a cam's ω): an arc with an arrowhead,
    counter-clockwise for ``sense`` > 0, clockwise for ``sense`` < 0, marked ``symbol``."""

    __slots__ = _FIELDS = ("at", "sense", "symbol")
    at: Point
    sense: float
    symbol: str

    def __init__(self, at: Point, sense: float, symbol: str = "ω") -> None:
        store(self, "at", at)
        store(self, "sense", sense)
        store(self, "symbol", symbol)


def rotation(at: Point, sense: float, symbol: str = "ω") -> Rotation:
    """Build a :class:`Rotation` arrow (an annotation step operation).

    >>> rotation(Point(0, 0), -1.0).sense
    -1.0
    """
    return Rotation(at, sense, symbol)


def angle_mark(vertex: Point, a: Point, b: Point, symbol: str, value: float, radius: float | None = None) -> AngleMark:
    """Build an :class:`AngleMark` (an annotation step operation)."""
    return AngleMark(vertex, a, b, symbol, value, radius)


def dimension(a: Point, b: Point, symbol: str, value: float, offset: float) -> Dimension:
    """Build a :class:`Dimension` (an annotation step operation)."""
    return Dimension(a, b, symbol, value, offset)


def ground(at: Point, angle: float = -math.pi / 2) -> Ground:
    """Build a :class:`Ground` symbol (an annotation step operation)."""
    return Ground(at, angle)


def slider(at: Point, direction: Point) -> Slider:
    """Build a :class:`Slider` block (an annotation step operation)."""
    return Slider(at, direction)


def guide(a: Point, b: Point, side: int = -1) -> Guide:
    """Build a :class:`Guide` (an annotation step operation)."""
    return Guide(a, b, side)


def right_angle(vertex: Point, a: Point, b: Point) -> RightAngleMark:
    """Build a :class:`RightAngleMark` (an annotation step operation)."""
    return RightAngleMark(vertex, a, b)


class Vector(Segment):
    """A vector of a velocity or acceleration polygon: the segment ``a → b`` drawn with an arrowhead at ``b``
    (a :class:`Segment` in all but its name, as a frozen dataclass without fields of its own would be)."""

    __slots__ = _FIELDS = ()


def vector(a: Point, b: Point) -> Vector:
    """Build a :class:`Vector` (a polygon's side, an annotation step operation)."""
    return Vector(a, b)
