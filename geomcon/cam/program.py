"""A cam's motion program: rise, dwells and return over one turn, and the follower's motion s(δ) it gives.

A problem file gives the program as a list of tables::

    h = 16
    program = [{kind = "rise", angle = 150, law = "parabolic"},
               {kind = "dwell", angle = 30},
               {kind = "return", angle = 120, law = "uniform"},
               {kind = "dwell", angle = 60}]

The angles are cam angles in degrees and must add up to 360°. ``h`` is the stroke: mm for a translating
follower, degrees for an oscillating one; s comes out in the unit of h, its derivatives per radian of cam
angle. A segment owns the half-open interval [start, end) of cam angle; δ = 360° belongs to the last one.
A rise or return may also use the handbook laws (``double_harmonic``, ``modified_trapezoid``,
``modified_sine``), a polynomial in the normalised angle x = (δ − start)/angle, ``{kind = "rise", angle = 120,
law = "poly", coefficients = [0, 0, 0, 10, -15, 6]}`` (f = Σ c_k x^k), or a table of normalised points
``{…, law = "table", points = [[0, 0], [0.5, 0.5], [1, 1]]}`` joined by a clamped cubic spline
(:mod:`geomcon.cam.custom_laws`). A program without a return may be shorter than a turn (a motion-law exercise); cam profiles need
:attr:`Program.full`.

Examples
--------
>>> p = parse_program([{"kind": "rise", "angle": 150, "law": "parabolic"}, {"kind": "dwell", "angle": 30},
...                    {"kind": "return", "angle": 120, "law": "uniform"}, {"kind": "dwell", "angle": 60}])
>>> round(float(p.motion(15.0, 100.0)[0]), 4)       # seed 001-24: s at δ = 100°
11.6667
>>> [(e.angle, e.kind) for e in p.impacts(15.0)]
[(0.0, 'soft'), (75.0, 'soft'), (150.0, 'soft'), (180.0, 'rigid'), (300.0, 'rigid')]
"""
from __future__ import annotations

import math
from bisect import bisect_right
from collections import abc
from dataclasses import dataclass
from ..cached import cached_property
from typing import Any, Mapping, Sequence

import numpy as np

from ..errors import NotAMechanism
from .custom_laws import PARAM_KEY, PARAMETRISED, custom_law
from .laws import Law, law

PARAM_KEYS = tuple(PARAM_KEY.values())
PARAM_LAW = {v: k for k, v in PARAM_KEY.items()}

KINDS = ("rise", "dwell", "return")
FULL_TURN_REL = 1e-9
"""The segment angles must add up to 360° to this relative tolerance."""
MIN_ANGLE = 1e-6
"""Smallest segment angle (deg): above the tolerance of the full turn (FULL_TURN_REL·360° = 3.6e-7°), which a
smaller segment would be lost in (a rise over 1e-12° drew a cam whose stroke rounded away)."""
MAX_SEGMENTS = 64
"""Most segments a program may have (a textbook program has at most a handful; the rest would be dwells)."""


_F64 = np.float64
SCALAR_MAX = 16
"""Arrays of at most this many angles are evaluated one angle at a time (:meth:`Program.motion1`, the same
bits): below it the array machinery costs more than the arithmetic."""
_BELOW_HALF = math.nextafter(0.5, 0.0)


@dataclass(frozen=True)
class Segment:
    """One part of the program: ``kind`` rise | dwell | return over ``angle`` degrees from ``start``."""

    kind: str
    start: float
    angle: float
    law: Law | None = None

    @property
    def end(self) -> float:
        """Cam angle (deg) where the segment ends."""
        return self.start + self.angle


@dataclass(frozen=True)
class Impact:
    """A shock of the follower at cam angle ``angle`` (deg): ``rigid`` (velocity jumps) or ``soft``
    (acceleration jumps), with the jump's size (in the units of h per rad, per rad²)."""

    angle: float
    kind: str
    jump: float


@dataclass(frozen=True)
class Program:
    """The validated segments of one turn, in order from δ = 0."""

    segments: tuple[Segment, ...]

    @property
    def full(self) -> bool:
        """True when the segments fill the whole turn (a cam); a rise alone may be shorter (a motion-law
        exercise), and the follower then stays at the top after it."""
        return abs(self.segments[-1].end - 360.0) <= FULL_TURN_REL * 360.0

    @property
    def rise(self) -> Segment:
        """The (first) rise segment."""
        return next(s for s in self.segments if s.kind == "rise")

    @property
    def ret(self) -> Segment | None:
        """The (first) return segment, if any."""
        return next((s for s in self.segments if s.kind == "return"), None)

    @cached_property
    def _table(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Segment starts (deg, rad) and the follower's level (in units of h) at each start."""
        level, levels = 0.0, []
        for seg in self.segments:
            levels.append(level)
            level += {"rise": 1.0, "return": -1.0}.get(seg.kind, 0.0)
        starts = [s.start for s in self.segments]
        return np.array(starts), np.radians(starts), np.array(levels)

    def motion(self, h: float, delta, *, radians: bool = False) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(s, ds/dδ, d²s/dδ²) at cam angles ``delta`` (deg, scalar or array, taken modulo 360°); s in the
        unit of ``h``, derivatives per radian of cam angle. With ``radians=True`` the angles are radians
        (modulo 2π) and the segment ends are compared in radians, so that ``nextafter`` of an end in
        radians stays in the segment it approaches (one-sided values for the profile machinery).

        A parabolic segment's halves are told apart by comparing δ with its middle, conv(start + angle/2) —
        the same number as the break of :func:`geomcon.recipes.cam_common.program_breaks` — so that a piece
        starting there gets the decelerating half even when (δ − start)/angle rounds below ½.

        The segment of each angle is found by bisection on the segment starts, and each law is evaluated
        once on the angles of its segment: the cost is linear in the number of angles whatever the number
        of segments.
        """
        conv = math.radians if radians else float
        turn = conv(360.0)
        if type(delta) is float:                    # one angle: the scalar path, numpy scalars out
            s, v, a = self._motion1(h, delta, radians)
            return _F64(s), _F64(v), _F64(a)
        raw = np.asarray(delta, dtype=float)
        if raw.size == 1:
            return tuple(np.full(raw.shape, v) for v in self._motion1(h, float(raw.reshape(-1)[0]), radians))
        if raw.size <= SCALAR_MAX:                  # a few angles (the candidates of a search): one by one
            out = np.array([self.motion1(h, x, radians) for x in raw.reshape(-1).tolist()]).reshape(-1, 3)
            return tuple(out[:, i].reshape(raw.shape) for i in range(3))
        shape = raw.shape
        raw = raw.reshape(-1)
        starts_deg, starts_rad, levels = self._table
        starts = starts_rad if radians else starts_deg
        if bool(np.all(raw[1:] >= raw[:-1])) and 0.0 <= raw[0] and raw[-1] < turn and \
                (raw[0] != 0.0 or math.copysign(1.0, raw[0]) > 0.0):
            # sorted within the turn (every grid): the reduction leaves them as they are; slices, not masks
            s, v, a = self._motion_sorted(h, raw, starts, radians)
            return s.reshape(shape), v.reshape(shape), a.reshape(shape)
        d = np.mod(raw, turn)
        d = np.where((d == 0.0) & (raw > 0.0), turn, d)
        if bool(np.all(d[1:] >= d[:-1])):           # sorted once reduced (a grid that ends at the full turn)
            s, v, a = self._motion_sorted(h, d, starts, radians)
            return s.reshape(shape), v.reshape(shape), a.reshape(shape)
        idx = np.searchsorted(starts, d, side="right") - 1
        idx = np.clip(idx, 0, len(self.segments) - 1)
        s = levels[idx] * h
        v, a = np.zeros_like(d), np.zeros_like(d)
        for i in np.unique(idx).tolist():
            seg = self.segments[i]
            if seg.kind == "dwell":
                continue
            inside = idx == i
            start, span = conv(seg.start), math.radians(seg.angle)
            x = np.clip((d[inside] - start) / conv(seg.angle), 0.0, 1.0)
            if seg.law.name == "parabolic":       # the half is decided on δ against the break itself
                second = d[inside] >= conv(seg.start + seg.angle / 2)
                x = np.where(second, np.maximum(x, 0.5), np.minimum(x, np.nextafter(0.5, 0.0)))
            f, f1, f2 = seg.law.derivatives(x)
            sign = 1.0 if seg.kind == "rise" else -1.0
            s[inside] = s[inside] + sign * h * f
            v[inside] = sign * h * f1 / span
            a[inside] = sign * h * f2 / span ** 2
        past = d > conv(self.segments[-1].end)
        if np.any(past):
            final = levels[-1] + {"rise": 1.0, "return": -1.0}.get(self.segments[-1].kind, 0.0)
            s = np.where(past, final * h, s)
            v, a = np.where(past, 0.0, v), np.where(past, 0.0, a)
        return s.reshape(shape), v.reshape(shape), a.reshape(shape)

    def _motion_sorted(self, h: float, d: np.ndarray, starts: np.ndarray, radians: bool
                       ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """:meth:`motion` of sorted angles ``d`` (already reduced to the turn): each segment's angles are one
        slice (found by bisecting the angles at the segment starts), evaluated by the same operations as the
        array path's, so the same bits."""
        turn, _, rows, last_end, final = self._rows1[radians]
        n = d.size
        edges = [0, *np.searchsorted(d, starts[1:], side="left").tolist(), n]
        s, v, a = np.empty_like(d), np.zeros_like(d), np.zeros_like(d)
        for (level, sign, start, angle, mid, fn1, span2, span), seg, j0, j1 in zip(rows, self.segments, edges, edges[1:]):
            if j0 == j1:
                continue
            base = level * h
            if fn1 is None:
                s[j0:j1] = base
                continue
            dd = d[j0:j1]
            x = np.clip((dd - start) / angle, 0.0, 1.0)
            if mid is not None:                     # the half is decided on δ against the break itself
                x = np.where(dd >= mid, np.maximum(x, 0.5), np.minimum(x, _BELOW_HALF))
            f, f1, f2 = seg.law.derivatives(x)
            s[j0:j1] = base + sign * h * f
            v[j0:j1] = sign * h * f1 / span
            a[j0:j1] = sign * h * f2 / span2
        if d[-1] > last_end:                        # past a program shorter than a turn: at the top, at rest
            past = d > last_end
            s[past], v[past], a[past] = final * h, 0.0, 0.0
        return s, v, a

    def motion1(self, h: float, delta: float, radians: bool = False) -> tuple[float, float, float]:
        """:meth:`motion` at one angle (a float), as three floats: the scalar path the searches use (a numpy
        call on one number costs a hundred times the arithmetic). The same arithmetic as the array path, in
        the same order, so the same bits.

        Examples
        --------
        >>> p = parse_program([{"kind": "rise", "angle": 180, "law": "cosine"}, {"kind": "return", "angle": 180, "law": "poly345"}])
        >>> p.motion1(10.0, 100.0) == tuple(float(v[1]) for v in p.motion(10.0, np.array([10.0, 100.0])))
        True
        >>> p.motion1(10.0, math.radians(270.0), radians=True)[0] == float(p.motion(10.0, 270.0)[0])
        True
        """
        turn, starts, rows, last_end, final = self._rows1[radians]
        d = delta % turn
        if d == 0.0 and delta > 0.0:
            d = turn
        if d > last_end:
            return final * h, 0.0, 0.0
        i = bisect_right(starts, d) - 1
        level, sign, start, angle, mid, fn1, span2, span = rows[i if i > 0 else 0]
        if fn1 is None:
            return level * h, 0.0, 0.0
        x = (d - start) / angle
        x = 0.0 if x < 0.0 else (1.0 if x > 1.0 else x)
        if mid is not None:                         # the parabolic law's half, decided on δ against the break
            x = (x if x > 0.5 else 0.5) if d >= mid else (x if x < _BELOW_HALF else _BELOW_HALF)
        f, f1, f2 = fn1(x)
        return level * h + sign * h * f, sign * h * f1 / span, sign * h * f2 / span2

    def _motion1(self, h: float, raw: float, radians: bool) -> tuple[float, float, float]:
        """:meth:`motion1` (the name the array path uses)."""
        return self.motion1(h, raw, radians)

    @cached_property
    def _rows1(self) -> dict[bool, tuple]:
        """For :meth:`motion1`, in degrees (False) and radians (True): the turn, the segment starts, per segment
        (level, sign, start, angle, parabolic middle or None, the law's scalar form or None for a dwell,
        span², span) with every conversion done once (the same numbers the array path converts each time),
        the end of the last segment and the level after it."""
        out = {}
        levels = self._table[2].tolist()
        last = self.segments[-1]
        final = levels[-1] + {"rise": 1.0, "return": -1.0}.get(last.kind, 0.0)
        for radians in (False, True):
            conv = math.radians if radians else float
            rows = []
            for seg, level in zip(self.segments, levels):
                dwell = seg.kind == "dwell"
                span = math.radians(seg.angle)
                mid = conv(seg.start + seg.angle / 2) if not dwell and seg.law.name == "parabolic" else None
                rows.append((level, 1.0 if seg.kind == "rise" else -1.0, conv(seg.start), conv(seg.angle), mid,
                             None if dwell else seg.law.fn1, span ** 2, span))
            out[radians] = (conv(360.0), [conv(s.start) for s in self.segments], rows, conv(last.end), final)
        return out

    def impacts(self, h: float) -> list[Impact]:
        """Every jump of velocity (rigid impact) or acceleration (soft impact) over the turn, including the
        middle of a parabolic segment, from the one-sided end values of neighbouring segments."""
        out = []
        segs = self.segments if self.full else self.segments + (Segment("dwell", self.segments[-1].end, 1.0),)
        for i, seg in enumerate(segs):
            prev = segs[i - 1] if self.full or i else Segment("dwell", 0.0, seg.angle)
            v0, a0 = _end_values(prev, h, at_end=True)
            v1, a1 = _end_values(seg, h, at_end=False)
            scale = abs(h) / math.radians(min(seg.angle, prev.angle))
            if abs(v1 - v0) > 1e-9 * scale:
                out.append(Impact(seg.start % 360.0, "rigid", v1 - v0))
            elif abs(a1 - a0) > 1e-9 * scale / math.radians(min(seg.angle, prev.angle)):
                out.append(Impact(seg.start % 360.0, "soft", a1 - a0))
            if seg.law is not None and seg.law.name == "parabolic":
                sign = 1.0 if seg.kind == "rise" else -1.0
                out.append(Impact(seg.start + seg.angle / 2, "soft", -8.0 * sign * h / math.radians(seg.angle) ** 2))
        return sorted(out, key=lambda e: e.angle)


def _end_values(seg: Segment, h: float, *, at_end: bool) -> tuple[float, float]:
    """(ds/dδ, d²s/dδ²) at the start or end of a segment (one-sided)."""
    if seg.kind == "dwell":
        return 0.0, 0.0
    _, f1, f2 = seg.law.derivatives(1.0 if at_end else 0.0)
    sign = 1.0 if seg.kind == "rise" else -1.0
    span = math.radians(seg.angle)
    return sign * h * float(f1) / span, sign * h * float(f2) / span ** 2


def _angle(value: Any, where: str) -> float:
    """A segment's angle through the checks every given number passes (a number, finite, within the range of
    angles: :func:`geomcon.problems.check_number`), then ≥ :data:`MIN_ANGLE`.

    >>> _angle(2 ** 1100, "program[0].angle")
    Traceback (most recent call last):
    ...
    geomcon.errors.ProblemError: program[0].angle is out of range (an integer of 332 digits)
    >>> _angle(4000, "program[1].angle")
    Traceback (most recent call last):
    ...
    geomcon.errors.ProblemError: program[1].angle = 4000° is out of range: an angle is at most 3600° in size
    """
    if value is None:
        raise NotAMechanism(f"{where} is missing (degrees of cam rotation)")
    t = type(value)
    if (t is float or t is int) and MIN_ANGLE <= value <= _DEG_MAX:  # a plain angle in range: what the checks
        return float(value)                                           # pass, as they return it
    from ..problems import check_number            # here: geomcon.problems imports the recipes, which import us
    angle = check_number("deg", value, where)
    if not angle >= MIN_ANGLE:
        raise NotAMechanism(f"{where} must be ≥ {MIN_ANGLE:g}° (degrees of cam rotation), got {angle:g}")
    return angle


_DEG_MAX = 3600.0
"""The largest angle :func:`geomcon.problems.check_number` lets through (``RANGES["deg"]``; a test keeps them
equal)."""


def parse_program(tables: Sequence[Mapping[str, Any]], *, key: str = "program") -> Program:
    """Validate a program given as tables (see the module docstring); a bad entry raises
    :class:`NotAMechanism` naming ``program[i]`` and the value. The same tables (by content, every value with
    its type) give the same :class:`Program`, parsed once (a solve's validation and construction, the twin
    and the warnings each ask for it; a program is immutable).

    >>> spec = [{"kind": "rise", "angle": 180, "law": "cosine"}, {"kind": "return", "angle": 180, "law": "cycloidal"}]
    >>> parse_program(spec) is parse_program([dict(t) for t in spec])
    True
    >>> parse_program(spec) == _parse_program(spec, "program")
    True
    >>> parse_program(spec) is parse_program([{**spec[0], "angle": 180.0}, spec[1]])    # 180.0 is not the int 180
    False
    """
    try:
        memo = (_content(tables), key)
        hit = _PARSED.get(memo)
    except TypeError:                               # a value that cannot be a key: parsed every time
        return _parse_program(tables, key)
    if hit is None:
        if len(_PARSED) >= _PARSED_MAX:
            _PARSED.clear()
        hit = _PARSED[memo] = _parse_program(tables, key)
    return hit


_PARSED: dict[tuple, Program] = {}
_PARSED_MAX = 256


def _content(v: Any) -> Any:
    """A hashable image of ``v`` that tells apart every value that could parse differently: a mapping's items
    and a sequence's members by content, each leaf with its type (1, 1.0 and True are equal and hash alike).

    >>> _content([{"angle": 1}]) != _content([{"angle": 1.0}]) != _content([{"angle": True}])
    True
    """
    t = type(v)
    if t is list or t is tuple:
        return ("[", tuple([_content(x) for x in v]))
    if t is dict or isinstance(v, abc.Mapping):
        return ("{", tuple([(k, type(x), x) if type(x) in _LEAVES else (k, _content(x)) for k, x in v.items()]))
    hash(v)
    return (t, v)


_LEAVES = frozenset({str, int, float, bool, type(None)})


def _parse_program(tables: Sequence[Mapping[str, Any]], key: str) -> Program:
    """:func:`parse_program` without the memo."""
    if len(tables) > MAX_SEGMENTS:
        raise NotAMechanism(f"{key} has {len(tables)} segments; at most {MAX_SEGMENTS}")
    segs, start = [], 0.0
    rises = returns = 0
    for i, t in enumerate(tables):
        where = f"{key}[{i}]"
        extra = [k for k in t if k not in ("kind", "angle", "law", *PARAM_KEYS)]
        if extra:
            raise NotAMechanism(f"{where}: unknown key '{extra[0]}' (a segment takes kind, angle, law; "
                                "coefficients for law = \"poly\", points for law = \"table\")")
        stray = [k for k in PARAM_KEYS if k in t and t.get("law") != PARAM_LAW[k]]
        if stray:
            raise NotAMechanism(f"{where}: {stray[0]} is given for law = {t.get('law')!r}: only law = "
                                f"\"{PARAM_LAW[stray[0]]}\" takes it")
        kind = t.get("kind")
        if kind not in KINDS:
            raise NotAMechanism(f"{where}: kind must be one of {', '.join(KINDS)}, got {kind!r}")
        angle = _angle(t.get("angle"), f"{where}.angle")
        if kind == "dwell":
            if "law" in t:
                raise NotAMechanism(f"{where}: a dwell has no law (got law = {t['law']!r})")
            lw = None
        else:
            if not isinstance(t.get("law"), str):
                raise NotAMechanism(f"{where}: a {kind} needs law = one of uniform, parabolic, cosine, cycloidal, "
                                    "poly345, double_harmonic, modified_trapezoid, modified_sine, poly, table")
            if t["law"] in PARAMETRISED:
                lw = custom_law(t["law"], t, where)
            else:
                try:
                    lw = law(t["law"])
                except NotAMechanism as exc:
                    raise NotAMechanism(f"{where}: {exc}") from None
        rises += kind == "rise"
        returns += kind == "return"
        segs.append(Segment(kind, start, float(angle), lw))
        start += float(angle)
    if not segs:
        raise NotAMechanism(f"{key} is empty")
    if rises != 1 or returns > 1:
        raise NotAMechanism(f"{key}: one rise and at most one return per turn, got {rises} rise(s) and {returns} return(s)")
    if returns == 1 and [s.kind for s in segs if s.kind != "dwell"] != ["rise", "return"]:
        raise NotAMechanism(f"{key}: the return must follow the rise")
    if abs(start - 360.0) > FULL_TURN_REL * 360.0 and not (returns == 0 and start < 360.0):
        raise NotAMechanism(f"{key}: the segment angles add up to {start:g}°, not 360°")
    return Program(tuple(segs))
