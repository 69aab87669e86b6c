"""Named branch rules: how a construction chooses one of two intersection points.

A textbook never says "the first solution"; it says "the intersection above the frame", "the one nearer to
D", "the other intersection than C1". Each rule here is a small frozen object that holds the points it
refers to (plain points, or :class:`geomcon.scene.Ref` before a scene resolves them), chooses among the
candidates of an intersection, and describes itself in English and Chinese for the step's caption.

A rule that cannot tell the candidates apart raises :class:`~geomcon.errors.AmbiguousBranch`; a single
(tangent) candidate is returned as it is, since both branches meet there.

Examples
--------
>>> from geomcon.geometry.primitives import Point
>>> cands = (Point(4, 3), Point(4, -3))
>>> LeftOf(Point(0, 0), Point(8, 0)).choose(cands)
Point(x=4.0, y=3.0)
>>> Below(Point(0, 0), Point(8, 0)).choose(cands)
Point(x=4.0, y=-3.0)
>>> NearestTo(Point(4, -10)).choose(cands)
Point(x=4.0, y=-3.0)
>>> OtherThan(Point(4, 3)).choose(cands)
Point(x=4.0, y=-3.0)
>>> LeftOf("A", "D").describe()
('left of the directed line A→D', '位于有向线 A→D 左侧的交点')
"""
from __future__ import annotations

import math
from typing import Any, Callable

from ..errors import AmbiguousBranch
from .. import tolerance as _tolerance
from ..tolerance import tol
from ..values import Frozen, store
from .primitives import Point, unit_xy


def _name(x: Any, label: Callable[[Any], str] | None) -> str:
    if label is not None:
        return label(x)
    if isinstance(x, Point):
        return f"({x.x:.4g}, {x.y:.4g})"
    return str(getattr(x, "key", x))


def _pick(cands: tuple[Point, ...], score: Callable[[Point], float], what: str) -> Point:
    """Return the candidate with the larger score; refuse when the scores tie within tolerance."""
    if len(cands) == 1:
        return cands[0]
    if len(cands) != 2:
        raise AmbiguousBranch(f"{what}: expected 1 or 2 candidates, got {len(cands)}")
    c0, c1 = cands
    return _larger(c0, c1, score(c0), score(c1), what)


def _larger(c0: Point, c1: Point, s0: float, s1: float, what: str) -> Point:
    """Of two candidates with scores ``s0``, ``s1``, the one with the larger score; refuse a tie within
    tolerance (``tol(scale, |s0|, |s1|)``, its arithmetic in place: every scale here is ≥ 0)."""
    scale = max(math.hypot(c0.x - c1.x, c0.y - c1.y), 1e-300)
    if abs(s0 - s1) <= _tolerance.REL_TOL * max(scale, abs(s0), abs(s1)):
        raise AmbiguousBranch(f"{what}: both intersections qualify equally (scores {s0:.6g}, {s1:.6g})")
    return c0 if s0 > s1 else c1


def _direction_xy(a: Point, b: Point, what: str) -> tuple[float, float]:
    """The unit direction ``a → b`` of a rule's dividing line; a zero-length one makes the rule undecidable."""
    dx, dy = b.x - a.x, b.y - a.y
    if dx == 0.0 and dy == 0.0:
        raise AmbiguousBranch(f"{what}: the dividing line through ({a.x:.6g}, {a.y:.6g}) has zero length")
    return unit_xy(dx, dy)


class Branch(Frozen):
    """Base of the rules: a small frozen value whose fields (``__match_args__``, none, ``p``, or ``a`` and ``b``)
    are points or references; equal, hashed and shown as a frozen dataclass of those fields would be.

    The rules are written out (:class:`geomcon.values.Frozen`) rather than made by
    :func:`dataclasses.dataclass`, which compiles each class's methods when the module is imported (about
    1 ms a class: the twelve rules were a tenth of a whole ``geomcon solve``).

    Examples
    --------
    >>> r = Above("A", "D")
    >>> r, r == Above("A", "D"), r == Below("A", "D"), hash(r) == hash(("A", "D"))
    (Above(a='A', b='D'), True, False, True)
    >>> r.a = "B"
    Traceback (most recent call last):
    ...
    dataclasses.FrozenInstanceError: cannot assign to field 'a'
    """

    __match_args__: tuple[str, ...] = ()

    def __init__(self) -> None:
        pass

    def choose(self, cands: tuple[Point, ...]) -> Point:
        """The candidate this rule names, its fields being points."""
        return self.rule(cands, *self.refs())

    @staticmethod
    def rule(cands: tuple[Point, ...], *points: Point) -> Point:  # pragma: no cover - abstract
        """Choose among ``cands`` given the rule's points (a scene passes resolved references, making no
        new rule object per evaluation)."""
        raise NotImplementedError

    def describe(self, label: Callable[[Any], str] | None = None) -> tuple[str, str]:  # pragma: no cover
        raise NotImplementedError

    def refs(self) -> tuple[Any, ...]:
        """The rule's points (or references), in field order."""
        return self._values()

    def with_points(self, points: tuple[Point, ...]) -> Branch:
        """The same rule with its fields replaced by resolved points."""
        return type(self)(*points)  # type: ignore[call-arg]


class _LineRule(Branch):
    """A rule over the line (or direction) through two points ``a`` and ``b``."""

    __match_args__ = _FIELDS = ("a", "b")
    a: Any
    b: Any

    def __init__(self, a: Any, b: Any) -> None:
        store(self, "a", a)
        store(self, "b", b)


class _PointRule(Branch):
    """A rule relative to one point ``p``."""

    __match_args__ = _FIELDS = ("p",)
    p: Any

    def __init__(self, p: Any) -> None:
        store(self, "p", p)



class LeftOf(_LineRule):
    """The intersection on the left of the directed line ``a → b``."""

    @staticmethod
    def rule(cands: tuple[Point, ...], a: Point, b: Point) -> Point:
        """Choose among ``cands`` given the rule's resolved points."""
        dx, dy = _direction_xy(a, b, "left of a directed line")
        return _pick(cands, lambda p: dx * (p.y - a.y) - dy * (p.x - a.x), "left of a directed line")

    def describe(self, label=None) -> tuple[str, str]:
        a, b = _name(self.a, label), _name(self.b, label)
        return (f"left of the directed line {a}→{b}", f"位于有向线 {a}→{b} 左侧的交点")


class RightOf(_LineRule):
    """The intersection on the right of the directed line ``a → b``."""

    @staticmethod
    def rule(cands: tuple[Point, ...], a: Point, b: Point) -> Point:
        """Choose among ``cands`` given the rule's resolved points."""
        dx, dy = _direction_xy(a, b, "right of a directed line")
        return _pick(cands, lambda p: -(dx * (p.y - a.y) - dy * (p.x - a.x)), "right of a directed line")

    def describe(self, label=None) -> tuple[str, str]:
        a, b = _name(self.a, label), _name(self.b, label)
        return (f"right of the directed line {a}→{b}", f"位于有向线 {a}→{b} 右侧的交点")


def _upward_normal(a: Point, b: Point) -> tuple[float, float]:
    dx, dy = b.x - a.x, b.y - a.y                # _direction_xy(a, b, "above/below a line"), one call fewer
    if dx == 0.0 and dy == 0.0:
        raise AmbiguousBranch(f"above/below a line: the dividing line through ({a.x:.6g}, {a.y:.6g}) has zero length")
    dx, dy = unit_xy(dx, dy)
    nx, ny = -dy, dx                          # the direction turned by +90°
    if abs(ny) <= _tolerance.REL_TOL:          # tol(1.0)
        raise AmbiguousBranch("above/below a vertical line is undefined: use left/right of a directed line")
    return (nx, ny) if ny > 0 else (-nx, -ny)


class Above(_LineRule):
    """The intersection above the line ``ab`` (on the side of +y)."""

    @staticmethod
    def rule(cands: tuple[Point, ...], a: Point, b: Point) -> Point:
        """Choose among ``cands`` given the rule's resolved points."""
        nx, ny = _upward_normal(a, b)
        if len(cands) == 2:                   # the score of _pick's lambda below, in place
            c0, c1 = cands
            ax, ay = a.x, a.y
            return _larger(c0, c1, nx * (c0.x - ax) + ny * (c0.y - ay), nx * (c1.x - ax) + ny * (c1.y - ay),
                           "above a line")
        return _pick(cands, lambda p: nx * (p.x - a.x) + ny * (p.y - a.y), "above a line")

    def describe(self, label=None) -> tuple[str, str]:
        a, b = _name(self.a, label), _name(self.b, label)
        return (f"above the line {a}{b}", f"位于直线 {a}{b} 上方的交点")


class Below(_LineRule):
    """The intersection below the line ``ab`` (on the side of −y)."""

    @staticmethod
    def rule(cands: tuple[Point, ...], a: Point, b: Point) -> Point:
        """Choose among ``cands`` given the rule's resolved points."""
        nx, ny = _upward_normal(a, b)
        if len(cands) == 2:                   # the score of _pick's lambda below, in place
            c0, c1 = cands
            ax, ay = a.x, a.y
            return _larger(c0, c1, -(nx * (c0.x - ax) + ny * (c0.y - ay)), -(nx * (c1.x - ax) + ny * (c1.y - ay)),
                           "below a line")
        return _pick(cands, lambda p: -(nx * (p.x - a.x) + ny * (p.y - a.y)), "below a line")

    def describe(self, label=None) -> tuple[str, str]:
        a, b = _name(self.a, label), _name(self.b, label)
        return (f"below the line {a}{b}", f"位于直线 {a}{b} 下方的交点")


class Ahead(_LineRule):
    """The intersection farther along the direction ``a → b`` (e.g. "on the slider's side of A")."""

    @staticmethod
    def rule(cands: tuple[Point, ...], a: Point, b: Point) -> Point:
        """Choose among ``cands`` given the rule's resolved points."""
        d = (b - a).unit()
        return _pick(cands, lambda p: d.dot(p - a), "ahead along a direction")

    def describe(self, label=None) -> tuple[str, str]:
        a, b = _name(self.a, label), _name(self.b, label)
        return (f"the intersection farther along {a}→{b}", f"沿 {a}→{b} 方向较远的交点")


class ToRightOf(_PointRule):
    """The intersection to the right of point ``p`` in the drawing (larger x), as a figure is read."""

    @staticmethod
    def rule(cands: tuple[Point, ...], p: Point) -> Point:
        """Choose among ``cands`` given the rule's resolved points."""
        if len(cands) == 2:                   # the score of _pick's lambda below, in place
            c0, c1 = cands
            return _larger(c0, c1, c0.x - p.x, c1.x - p.x, "to the right of a point")
        return _pick(cands, lambda q: q.x - p.x, "to the right of a point")

    def describe(self, label=None) -> tuple[str, str]:
        p = _name(self.p, label)
        return (f"the intersection to the right of {p}", f"位于 {p} 右侧的交点")


class ToLeftOf(_PointRule):
    """The intersection to the left of point ``p`` in the drawing (smaller x)."""

    @staticmethod
    def rule(cands: tuple[Point, ...], p: Point) -> Point:
        """Choose among ``cands`` given the rule's resolved points."""
        if len(cands) == 2:                   # the score of _pick's lambda below, in place
            c0, c1 = cands
            return _larger(c0, c1, p.x - c0.x, p.x - c1.x, "to the left of a point")
        return _pick(cands, lambda q: p.x - q.x, "to the left of a point")

    def describe(self, label=None) -> tuple[str, str]:
        p = _name(self.p, label)
        return (f"the intersection to the left of {p}", f"位于 {p} 左侧的交点")


class Leftmost(Branch):
    """The left one of the two intersections in the drawing (smaller x)."""

    @staticmethod
    def rule(cands: tuple[Point, ...]) -> Point:
        """Choose among ``cands`` given the rule's resolved points."""
        return _pick(cands, lambda q: -q.x, "the left one")

    def describe(self, label=None) -> tuple[str, str]:
        return ("the left intersection", "左侧的交点")


class Upper(Branch):
    """The upper one of the two intersections in the drawing (larger y): a vertical guide's point above the
    other, said as a textbook says it (001-25…001-29 printed "the intersection farther along D→D + ↑").

    >>> Upper().choose((Point(0.0, -2.0), Point(0.0, 3.0))), Upper().describe()
    (Point(x=0.0, y=3.0), ('the upper intersection', '上方的交点'))
    """

    @staticmethod
    def rule(cands: tuple[Point, ...]) -> Point:
        """Choose among ``cands`` given the rule's resolved points."""
        return _pick(cands, lambda q: q.y, "the upper one")

    def describe(self, label=None) -> tuple[str, str]:
        return ("the upper intersection", "上方的交点")


class Rightmost(Branch):
    """The right one of the two intersections in the drawing (larger x)."""

    @staticmethod
    def rule(cands: tuple[Point, ...]) -> Point:
        """Choose among ``cands`` given the rule's resolved points."""
        return _pick(cands, lambda q: q.x, "the right one")

    def describe(self, label=None) -> tuple[str, str]:
        return ("the right intersection", "右侧的交点")


class NearestTo(_PointRule):
    """The intersection nearest to point ``p``."""

    @staticmethod
    def rule(cands: tuple[Point, ...], p: Point) -> Point:
        """Choose among ``cands`` given the rule's resolved points."""
        return _pick(cands, lambda q: -abs(q - p), "nearest to a point")

    def describe(self, label=None) -> tuple[str, str]:
        p = _name(self.p, label)
        return (f"the intersection nearer to {p}", f"离 {p} 较近的交点")


class FarthestFrom(_PointRule):
    """The intersection farthest from point ``p``."""

    @staticmethod
    def rule(cands: tuple[Point, ...], p: Point) -> Point:
        """Choose among ``cands`` given the rule's resolved points."""
        return _pick(cands, lambda q: abs(q - p), "farthest from a point")

    def describe(self, label=None) -> tuple[str, str]:
        p = _name(self.p, label)
        return (f"the intersection farther from {p}", f"离 {p} 较远的交点")


class OtherThan(_PointRule):
    """The intersection other than the known point ``p`` (the one farther from it)."""

    @staticmethod
    def rule(cands: tuple[Point, ...], p: Point) -> Point:
        """Choose among ``cands`` given the rule's resolved points."""
        return _pick(cands, lambda q: abs(q - p), "other than a known point")

    def describe(self, label=None) -> tuple[str, str]:
        p = _name(self.p, label)
        return (f"the intersection other than {p}", f"异于 {p} 的另一交点")
