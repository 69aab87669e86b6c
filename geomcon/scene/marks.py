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
from dataclasses import dataclass

from ..geometry.primitives import Point, Segment


@dataclass(frozen=True, slots=True)
class AngleMark:
    """The arc marking the angle at ``vertex`` from ray vertex→a to ray vertex→b (the smaller angle).

    ``radius`` is in model mm; None lets the renderer choose it.
    """

    vertex: Point
    a: Point
    b: Point
    symbol: str
    value: float
    radius: float | None = None

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


@dataclass(frozen=True, slots=True)
class RightAngleMark:
    """The small square marking a right angle at ``vertex`` between rays vertex→a and vertex→b."""

    vertex: Point
    a: Point
    b: Point


@dataclass(frozen=True, slots=True)
class Dimension:
    """A linear dimension of ``a``–``b`` drawn parallel to it, ``offset`` mm to the left of a→b."""

    a: Point
    b: Point
    symbol: str
    value: float
    offset: float

    @property
    def text(self) -> str:
        """The printed label, e.g. ``H=101.74``."""
        return f"{self.symbol}={self.value:.2f}"


@dataclass(frozen=True, slots=True)
class Ground:
    """The hatched ground symbol of a fixed pivot at ``at``, the ground lying towards ``angle`` (rad)."""

    at: Point
    angle: float = -math.pi / 2


@dataclass(frozen=True, slots=True)
class Slider:
    """A slider block centred at ``at`` moving along unit-free ``direction``."""

    at: Point
    direction: Point


@dataclass(frozen=True, slots=True)
class Guide:
    """A straight guide from ``a`` to ``b`` hatched on its left (``side`` = +1) or right (−1)."""

    a: Point
    b: Point
    side: int = -1


@dataclass(frozen=True, slots=True)
class Bearing:
    """The guide of a translating follower's stem: two short hatched bearing blocks either side of the stem,
    centred at ``at``, the stem running along ``direction`` (the same symbol for every cam)."""

    at: Point
    direction: Point


def bearing(at: Point, direction: Point) -> Bearing:
    """Build a :class:`Bearing` (an annotation step operation).

    >>> bearing(Point(0, 0), Point(0, 1)).direction
    Point(x=0.0, y=1.0)
    """
    return Bearing(at, direction)


@dataclass(frozen=True, slots=True)
class Rotation:
    """The sense of rotation of a part turning about ``at`` (a cam's ω): an arc with an arrowhead,
    counter-clockwise for ``sense`` > 0, clockwise for ``sense`` < 0, marked ``symbol``."""

    at: Point
    sense: float
    symbol: str = "ω"


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


@dataclass(frozen=True, slots=True)
class Vector(Segment):
    """A vector of a velocity or acceleration polygon: the segment ``a → b`` drawn with an arrowhead at ``b``."""


def vector(a: Point, b: Point) -> Vector:
    """Build a :class:`Vector` (a polygon's side, an annotation step operation)."""
    return Vector(a, b)
