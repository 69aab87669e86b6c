"""Cam profiles from a pitch curve given parametrically by the cam angle: curvature, ρmin, the roller
profile (inner offset), the flat-faced profile (envelope of lines), loop trimming and validation.

Generic over the follower: a translating or an oscillating follower only supplies the curve.

Conventions
-----------
- Everything is drawn in the cam's frame (the inversion, 反转法): the cam centre O is the origin and
  stands still, the follower is turned about O by −δ.
- The parameter is the cam angle δ in **radians** (0 … 2π for a full turn); derivatives are per radian.
- A **pitch curve** is a function ``fn(delta) -> (x, y, x′, y′, x″, y″)`` of a float array, with exact
  derivatives, plus the ``breaks`` (radians, in (0, 2π)) where a derivative may jump (segment ends of
  the motion program). Each piece [a, b) between breaks is smooth; one-sided values at b are taken at
  ``nextafter(b, a)``.
- Signed curvature κ is positive where the curve turns counter-clockwise; ``orientation`` σ = ±1 is the
  sense in which the curve goes round O, and σκ > 0 on the **convex** parts. ρ = 1/(σκ): positive on
  convex parts, negative on concave ones.

Examples
--------
A circle of radius 40 about O traversed clockwise (the pitch curve of a dwell, cam turning CCW):

>>> def circle40(d):
...     c, s = np.cos(d), np.sin(d)
...     return 40 * s, 40 * c, 40 * c, -40 * s, -40 * s, -40 * c
>>> pc = PitchCurve(circle40)
>>> pc.orientation, round(rho_min(pc).value, 12)
(-1, 40.0)
>>> prof = roller_profile(pc, 10.0)
>>> prof.undercut, prof.trimmed, round(float(np.hypot(*prof.xy.T).max()), 9)
(False, False, 30.0)
>>> len(prof.delta) == sample_count(pc, 10.0)                 # 1e-5 of the size: 4e-4 mm
True
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, fields
from functools import lru_cache
from typing import Callable, Sequence

import numpy as np
import shapely
from shapely.geometry import LinearRing, LineString

from ..cached import cached_property
from ..errors import NotAMechanism

Curve6 = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]
CurveFn = Callable[[np.ndarray], Curve6]

TWO_PI = 2.0 * math.pi
TOLERANCE = 1e-3
"""The profile tolerance (mm) of a cam of size :data:`TOLERANCE_SIZE` (the largest distance between the
sampled profile and the exact one); it scales with the cam (:data:`TOLERANCE_REL`)."""
STRICT_TOLERANCE = 1e-5
"""Strict-mode profile tolerance (mm) of a cam of size :data:`TOLERANCE_SIZE` (:data:`STRICT_TOLERANCE_REL`)."""
TOLERANCE_SIZE = 100.0
"""The cam size (mm) at which the tolerances are :data:`TOLERANCE` and :data:`STRICT_TOLERANCE`."""
TOLERANCE_REL = TOLERANCE / TOLERANCE_SIZE
"""Default chord tolerance relative to the cam's size (1e-5: 1e-3 mm on a 100 mm cam, 10 mm on a 1000 km one)."""
STRICT_TOLERANCE_REL = STRICT_TOLERANCE / TOLERANCE_SIZE
"""Strict chord tolerance relative to the cam's size (1e-7)."""
MAX_SAMPLES = 1_000_000
"""Most points a sampled profile may have; a tolerance that needs more is refused (before any is computed)."""
JUMP_REL = 1e-9
"""A jump of the flat face's contact counts when it exceeds this fraction of the contact's range over the
turn (a law's end value f′(1) = 1.9e-16 instead of 0 is roundoff, not a velocity drop)."""
_DENSE = 1440               # samples per turn for locating extrema before refining
_GOLD = (math.sqrt(5.0) - 1.0) / 2.0
_NEAR_ENDS = np.logspace(-9.0, -2.0, 8)       # extra samples at these fractions of a piece from either end


def inverted(delta: np.ndarray, rotation: str, q: Sequence[np.ndarray], dq: Sequence[np.ndarray],
             ddq: Sequence[np.ndarray], *, cs: tuple[np.ndarray, np.ndarray] | None = None) -> Curve6:
    """A point fixed to the follower's frame, ``q(δ)``, seen from the cam: P = R(∓δ)·q (inversion).

    Parameters
    ----------
    delta : array
        Cam angles (radians).
    rotation : {"ccw", "cw"}
        The cam's sense of rotation; the follower is turned the other way, by −δ for "ccw".
    q, dq, ddq : pairs of arrays
        The point in the frame of the follower and its first and second derivatives by δ.

    Returns
    -------
    (x, y, x′, y′, x″, y″) : arrays
        P and its exact derivatives: P′ = R(q′ + kJq), P″ = R(q″ + 2kJq′ − q), k = ∓1, J the +90° turn.

    ``cs``, when given, is (cos kδ, sin kδ) computed already (:func:`turn_of`): the same numbers, not
    computed twice for the point and its relative form.

    Examples
    --------
    >>> d = np.array([math.pi / 2])
    >>> [round(float(v[0]), 12) for v in inverted(d, "ccw", (0.0 * d, 30.0 + 0 * d), (0 * d, 0 * d), (0 * d, 0 * d))]
    [30.0, 0.0, 0.0, -30.0, -30.0, -0.0]
    """
    k = -1.0 if rotation == "ccw" else 1.0
    c, s = turn_of(delta, rotation) if cs is None else cs
    (qx, qy), (dx, dy), (ex, ey) = q, dq, ddq
    vx, vy = dx - k * qy, dy + k * qx                          # q′ + kJq
    ax, ay = ex - 2.0 * k * dy - qx, ey + 2.0 * k * dx - qy    # q″ + 2kJq′ − q
    return (c * qx - s * qy, s * qx + c * qy, c * vx - s * vy, s * vx + c * vy, c * ax - s * ay, s * ax + c * ay)


_LAST_TURN: tuple = (None, "", None, None)


def turn_of(delta: np.ndarray, rotation: str) -> tuple[np.ndarray, np.ndarray]:
    """(cos kδ, sin kδ), k = −1 for a "ccw" cam, +1 for "cw": the turn of the inversion (:func:`inverted`).
    The last angles' values are kept (a search asks for the point, its relative form and the follower's
    axis at the same angles).

    >>> d = np.array([0.5, 1.0])
    >>> c, s = turn_of(d, "ccw")
    >>> bool(np.all(c == np.cos(-d))) and bool(np.all(s == np.sin(-d))) and turn_of(d.copy(), "ccw")[0] is c
    True
    """
    global _LAST_TURN
    last, rot, c, s = _LAST_TURN
    if rot == rotation and last is not None and last.shape == np.shape(delta) and np.array_equal(last, delta):
        return c, s
    k = -1.0 if rotation == "ccw" else 1.0
    c, s = np.cos(k * delta), np.sin(k * delta)
    _LAST_TURN = (np.array(delta, dtype=float), rotation, c, s)
    return c, s


def inverted_relative(delta: np.ndarray, rotation: str, dq: Sequence[np.ndarray], ddq: Sequence[np.ndarray],
                      *, cs: tuple[np.ndarray, np.ndarray] | None = None) -> tuple[np.ndarray, np.ndarray]:
    """P″ − kJP′ = R(q″ + kJq′): the acceleration of the inverted point relative to the turning frame (the
    frame's own turn taken out), formed in the follower's frame before it is turned.

    The turn of the tangent relative to the frame, P′ × (P″ − kJP′) = P′ × P″ − k|P′|², is what a pressure
    angle measured against a direction fixed in the follower's frame changes by. Formed from P″ it is a
    difference of two terms of size |P′|² (r0² for a cam whose stroke is far below its base circle: all its
    digits lost at h/r0 ~ 1e-8); formed from q′ and q″ it is as accurate as they are.

    Examples
    --------
    >>> d = np.array([0.3])
    >>> q, dq, ddq = (0 * d + 2.0, 30.0 + 0 * d), (0 * d, 0.5 + 0 * d), (0 * d, -0.1 + 0 * d)
    >>> P = inverted(d, "ccw", q, dq, ddq)
    >>> rx, ry = inverted_relative(d, "ccw", dq, ddq)
    >>> bool(np.allclose([P[4] - P[3], P[5] + P[2]], [rx, ry], rtol=1e-12))     # k = −1: −kJP′ = (−P′y, P′x)
    True
    """
    k = -1.0 if rotation == "ccw" else 1.0
    c, s = turn_of(delta, rotation) if cs is None else cs
    (dx, dy), (ex, ey) = dq, ddq
    wx, wy = ex - k * dy, ey + k * dx                          # q″ + kJq′
    return c * wx - s * wy, s * wx + c * wy


Curve1 = tuple[float, float, float, float, float, float]


def inverted1(delta: float, rotation: str, q: tuple[float, float], dq: tuple[float, float],
              ddq: tuple[float, float]) -> Curve1:
    """:func:`inverted` at one cam angle, on floats (the searches' scalar path): the same operations in the
    same order, so the same bits.

    Examples
    --------
    >>> d, q, dq, ddq = 0.7, (3.0, 30.0), (0.5, 1.5), (-0.2, 0.1)
    >>> vec = inverted(np.array([d]), "cw", *[(np.array([a]), np.array([b])) for a, b in (q, dq, ddq)])
    >>> inverted1(d, "cw", q, dq, ddq) == tuple(float(v[0]) for v in vec)
    True
    """
    k = -1.0 if rotation == "ccw" else 1.0
    c, s = math.cos(k * delta), math.sin(k * delta)
    (qx, qy), (dx, dy), (ex, ey) = q, dq, ddq
    vx, vy = dx - k * qy, dy + k * qx
    ax, ay = ex - 2.0 * k * dy - qx, ey + 2.0 * k * dx - qy
    return (c * qx - s * qy, s * qx + c * qy, c * vx - s * vy, s * vx + c * vy, c * ax - s * ay, s * ax + c * ay)


def inverted_relative1(delta: float, rotation: str, dq: tuple[float, float], ddq: tuple[float, float]
                       ) -> tuple[float, float]:
    """:func:`inverted_relative` at one cam angle, on floats (the same bits)."""
    k = -1.0 if rotation == "ccw" else 1.0
    c, s = math.cos(k * delta), math.sin(k * delta)
    (dx, dy), (ex, ey) = dq, ddq
    wx, wy = ex - k * dy, ey + k * dx
    return c * wx - s * wy, s * wx + c * wy


def sign1(x: float) -> float:
    """``np.sign`` of one float: −1, 0 or +1 (nan for nan).

    >>> sign1(-2.5), sign1(0.0), sign1(3.0), math.isnan(sign1(math.nan))
    (-1.0, 0.0, 1.0, True)
    """
    return 1.0 if x > 0.0 else (-1.0 if x < 0.0 else (0.0 if x == 0.0 else math.nan))


@dataclass(frozen=True)
class PitchCurve:
    """A closed curve traced once as δ goes from 0 to 2π (see the module docstring). ``relative``, when
    given, is :func:`inverted_relative` of the same point (the follower-frame turn of the tangent).
    ``fn1`` and ``relative1``, when given, are ``fn`` and ``relative`` on one float, returning floats with the
    same bits (the scalar path: the searches then refine one angle at a time without numpy). ``still``, when
    given, are the cam angles [a, b] (radians) over which the follower rests: the curve is an arc about O
    there, of constant curvature, so :func:`rho_min`'s scalar path takes only the ends of a piece inside
    one (a dwell's samples differ only by roundoff and never decide its result)."""

    fn: CurveFn
    breaks: tuple[float, ...] = ()
    relative: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]] | None = None
    fn1: Callable[[float], Curve1] | None = None
    relative1: Callable[[float], tuple[float, float]] | None = None
    still: tuple[tuple[float, float], ...] = ()

    def pieces(self) -> list[tuple[float, float]]:
        """The smooth pieces [a, b] of the turn, in order."""
        cuts = [0.0] + sorted(b for b in self.breaks if 0.0 < b < TWO_PI) + [TWO_PI]
        return [(a, b) for a, b in zip(cuts, cuts[1:]) if b > a]

    def eval(self, delta) -> Curve6:
        """(x, y, x′, y′, x″, y″) at ``delta`` (radians)."""
        return tuple(np.asarray(v, dtype=float) for v in self.fn(np.asarray(delta, dtype=float)))

    def piece_samples(self, a: float, b: float, n: int) -> np.ndarray:
        """``n + 1`` cam angles from a to b; the last is ``nextafter(b, a)`` so that derivatives there are
        the piece's own (one-sided)."""
        d = np.linspace(a, b, n + 1)
        d[-1] = np.nextafter(b, a)
        return d

    @property
    def size(self) -> float:
        """The curve's largest distance from O (over 1440 samples): the scale of its tolerances."""
        d = np.linspace(0.0, TWO_PI, _DENSE, endpoint=False)
        x, y = self.eval(d)[:2]
        return float(np.hypot(x, y).max())

    @cached_property
    def orientation(self) -> int:
        """+1 when the curve goes counter-clockwise round O, −1 clockwise (sign of its area; computed once)."""
        d = np.linspace(0.0, TWO_PI, _DENSE, endpoint=False)
        x, y = self.eval(d)[:2]
        return 1 if float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)) > 0.0 else -1


def curvature(c6: Curve6) -> np.ndarray:
    """Signed curvature κ = (x′y″ − y′x″)/|P′|³ (counter-clockwise positive) of sampled derivatives."""
    _, _, dx, dy, ex, ey = c6
    return (dx * ey - dy * ex) / np.hypot(dx, dy) ** 3


def curvature1(c6: Curve1) -> float:
    """:func:`curvature` of one point's derivatives (floats; math's hypot and power round differently from
    numpy's in the last bit, which only the refined values see).

    >>> curvature1((0.0, 0.0, 2.0, 0.0, 0.0, 4.0))
    1.0
    """
    _, _, dx, dy, ex, ey = c6
    return (dx * ey - dy * ex) / math.hypot(dx, dy) ** 3


@dataclass(frozen=True)
class Extremum:
    """An extreme ``value`` reached at cam angle ``delta`` (radians)."""

    value: float
    delta: float

    @property
    def delta_deg(self) -> float:
        """The cam angle in degrees."""
        return math.degrees(self.delta)


REFINE = 3
"""Without a slope, the largest few local maxima of the samples of each piece are refined (a peak between
samples can overtake the best sample's, so more than one is refined)."""
SLOPE_NOISE = 1e-9
"""A slope within this fraction of its largest sampled magnitude is roundoff (no root is sought there)."""
FLOOR_REL = 2.220446049250313e-16 * 1e-3
"""The scalar root search stops at a bracket this fraction of its piece wide (:func:`illinois1`): below the
adjacent floats of every root farther than 1e-3 of the piece from δ = 0, so only roots nearer to 0 end
earlier, within ~1e-19 rad."""
FLAT_REL = 1e-13
PRUNE_GAIN = 4.0
PRUNE_REL = 1e-9
"""The scalar path refines a sampled peak only if its sample plus :data:`PRUNE_GAIN` times what the parabola
through it and its neighbours gains (:func:`parabola_gain`) comes within :data:`PRUNE_REL` of the best sample:
a peak far below cannot win (nor tie: :data:`TIE_REL` is much smaller), and a flat stretch (a dwell's constant
curvature, whose samples differ by roundoff) is not searched for nothing."""
TIE_REL = 1e-12
"""Two candidate maxima whose values agree to this relative tolerance tie; the smaller cam angle wins (a
maximum that is flat to roundoff has no better-defined place)."""


def maximise(g: Callable[[np.ndarray], np.ndarray], pieces: Sequence[tuple[float, float]],
             dense: int = _DENSE, xtol: float = 1e-11, slope: Callable[[np.ndarray], np.ndarray] | None = None,
             *, slope1: Callable[[float], float] | None = None, g1: Callable[[float], float] | None = None,
             turn: float | None = None, still: Sequence[tuple[float, float]] = ()) -> Extremum:
    """The maximum of a function smooth on each piece, and where.

    With ``slope`` (a function with the sign of g′, from exact derivatives) the candidates are the ends of
    each piece (the right end one-sided) where the slope does not lead into the piece, and the places where
    the slope changes sign from + to − between
    dense samples (denser towards the ends: 1e-2 … 1e-9 of the piece), each located by bisection on the
    slope's sign to the last bit: no comparison of values
    decides where an interior maximum lies, and a maximum at a piece's end is that end exactly. Without
    ``slope`` every local maximum of the dense samples is refined by golden-section search to ``xtol``
    radians (the value is then right to ~xtol² relative, its place only to ~1e-8 rad); of each piece the
    :data:`REFINE` largest local maxima of the samples are refined. Candidates whose
    values tie (:data:`TIE_REL`) go to the smallest cam angle.

    The scalar path: ``slope1`` (the slope on one float, with the same bits as ``slope``) refines each sign
    change one angle at a time, by the same steps as the array refinement (:func:`illinois1`), so to the same
    place; ``g1`` (g on one float) refines each sampled peak by Brent's method (:func:`brent_max1`, about a
    dozen calls where golden sections take forty-odd) to the same ``xtol``. The samples are evaluated in one
    call of ``g`` or ``slope`` for all the pieces. Without them, every step of a refinement is one array call.

    ``turn`` (radians), when given, spreads the ``dense`` samples over that angle instead of over the pieces'
    own length: a segment of a cam searched alone is then sampled as densely as the whole turn is (not
    ``dense`` times over its own few degrees).

    ``still`` (intervals [a, b], radians) marks where the follower rests and the function is constant (a
    dwell: the pitch curve an arc about O, a flat face's contact standing still on it): on the scalar paths
    a piece inside one is sampled at its ends only and gives no peaks (:func:`_rest_grids`). Its samples
    would differ only by roundoff, never refined (flat to :data:`FLAT_REL`, or a slope within its noise),
    and the earliest of tied candidates wins, which its first sample is either way.

    Examples
    --------
    >>> m = maximise(lambda d: np.sin(d) * np.exp(-d), [(0.0, 2.0), (2.0, TWO_PI)])
    >>> abs(m.delta - math.pi / 4) < 1e-7, abs(m.value - math.sin(math.pi / 4) * math.exp(-math.pi / 4)) < 1e-15
    (True, True)
    >>> m1 = maximise(lambda d: np.sin(d) * np.exp(-d), [(0.0, 2.0), (2.0, TWO_PI)],
    ...               g1=lambda d: math.sin(d) * math.exp(-d))
    >>> abs(m1.delta - math.pi / 4) < 1e-7, abs(m1.value - m.value) < 1e-16
    (True, True)
    >>> m = maximise(lambda d: np.sin(d) * np.exp(-d), [(0.0, TWO_PI)], slope=lambda d: np.cos(d) - np.sin(d))
    >>> abs(m.delta - math.pi / 4) < 1e-15
    True
    >>> maximise(lambda d: np.sin(d) * np.exp(-d), [(0.0, TWO_PI)], slope=lambda d: np.cos(d) - np.sin(d),
    ...          slope1=lambda d: math.cos(d) - math.sin(d)) == m
    True
    >>> maximise(lambda d: -(d - 1.0) ** 4, [(0.0, 1.0)], slope=lambda d: -(d - 1.0) ** 3).delta < 1.0   # flat at the end
    True
    """
    key = tuple((float(a), float(b)) for a, b in pieces)
    grids = sample_grids(key, dense, turn)
    places: list[float] = []
    scalar = slope1 is not None if slope is not None else g1 is not None
    rests = tuple(any(s0 <= 0.5 * (a + b) <= s1 for s0, s1 in still) for a, b in key) if scalar else ()
    if any(rests):                                  # the scalar paths on samples without a dwell's inside
        grids, grid = _rest_grids(key, rests, dense, turn)
        if slope is not None:
            return _maximise_by_slope1(g, key, grids, grid, slope, slope1, g1)
        return _maximise_by_g1(g, key, grids, grid, g1, xtol, rests)
    if slope is not None and slope1 is not None:    # one call for all the pieces' samples, on floats after
        return _maximise_by_slope1(g, key, grids, sample_grid(key, dense, turn), slope, slope1, g1)
    if slope is not None:
        slopes = [np.asarray(slope(d), dtype=float) for d in grids]
        noise = SLOPE_NOISE * max(float(np.nanmax(np.abs(sl), initial=0.0)) for sl in slopes)
        lo, hi, flo, fhi, floors = [], [], [], [], []
        for (a, b), d, sl in zip(pieces, grids, slopes):
            # an end is a candidate unless the slope, beyond its noise, leads into the piece (g grows there):
            # values that tie to roundoff (α nearly constant over a long piece) must not pick the wrong end
            places += [float(d[0])] if not sl[0] > noise else []
            places += [float(d[-1])] if not sl[-1] < -noise else []
            i = np.nonzero((sl[:-1] > 0.0) & (sl[1:] <= 0.0))[0]
            flat = np.maximum(np.abs(sl[i]), np.abs(sl[i + 1])) <= noise   # roundoff (a dwell): the sample stands
            places += d[i[flat]].tolist()
            i = i[~flat]
            lo += d[i].tolist()
            hi += d[i + 1].tolist()
            flo += sl[i].tolist()
            fhi += sl[i + 1].tolist()
            floors += [FLOOR_REL * (b - a)] * len(i)
        places += _bisect_all(slope, np.array(lo), np.array(hi)).tolist()
        vals = np.asarray(g(np.asarray(places)), dtype=float)
        return best_of([Extremum(float(v), x) for v, x in zip(vals, places)])
    if g1 is not None:                              # one pass over all the pieces' samples, on floats after
        return _maximise_by_g1(g, key, grids, sample_grid(key, dense, turn), g1, xtol)
    lo, hi, cands = [], [], []
    mids, fmids, gains = [], [], []
    values = _split(np.asarray(g(sample_grid(key, dense, turn)), dtype=float), grids) if g1 is not None else None
    for k, d in enumerate(grids):
        v = values[k] if values is not None else np.asarray(g(d), dtype=float)
        n = len(d) - 1
        cands += [Extremum(float(v[0]), float(d[0])), Extremum(float(v[-1]), float(d[-1]))]
        w = np.concatenate([[-np.inf], v, [-np.inf]])             # the ends compare with one neighbour
        peaks = np.nonzero((w[1:-1] >= w[:-2]) & (w[1:-1] >= w[2:]) & ((w[1:-1] > w[:-2]) | (w[1:-1] > w[2:])))[0]
        if g1 is not None and not np.isnan(v[peaks]).any():   # the REFINE highest (stable: ties by place)
            top = peaks[np.argsort(-v[peaks], kind="stable")[:REFINE]].tolist()
        else:
            top = sorted(peaks.tolist(), key=lambda j: -v[j])[:REFINE]
        for i in top:
            cands.append(Extremum(float(v[i]), float(d[i])))
            lo.append(float(d[max(i - 1, 0)]))
            hi.append(float(d[min(i + 1, n)]))
            mids.append(float(d[i]))
            fmids.append(float(v[i]))
            if g1 is not None:
                gains.append(parabola_gain(d, v, i))
    if g1 is not None:
        floor = max(c.value for c in cands if not math.isnan(c.value)) if cands else -math.inf
        floor -= PRUNE_REL * abs(floor)
        for a, x, b, fx, gain in zip(lo, mids, hi, fmids, gains):
            if fx + PRUNE_GAIN * gain >= floor and gain >= 0.0:   # else it cannot reach the best sample
                at, top = brent_max1(g1, a, x, b, fx, xtol)
                cands.append(Extremum(top, at))
    elif lo:
        x, v = _golden_all(g, np.array(lo), np.array(hi), xtol)
        cands += [Extremum(float(a), float(b)) for a, b in zip(v, x)]
    return best_of(cands)


def _maximise_by_slope1(g: Callable[[np.ndarray], np.ndarray], pieces: tuple[tuple[float, float], ...],
                        grids: Sequence[np.ndarray], grid: np.ndarray, slope: Callable[[np.ndarray], np.ndarray],
                        slope1: Callable[[float], float], g1: Callable[[float], float] | None = None) -> Extremum:
    """:func:`maximise` with a slope and its scalar form: the candidates of every piece found on the samples of
    all of them at once (``grid``, the pieces' ``grids`` concatenated), in the order of the loop over the
    pieces (each piece's ends, then the samples where a slope that is roundoff changes sign), then the roots
    refined on floats (:func:`illinois1`), valued by one call of ``g`` (or, given ``g1``, g on one float with
    the same bits, one candidate at a time: a few candidates cost less so than one numpy pass over them)
    and compared as :func:`best_of` does.

    >>> pcs = ((0.0, 2.0), (2.0, TWO_PI))
    >>> args = (lambda d: np.sin(d) * np.exp(-d), pcs)
    >>> kw = dict(slope=lambda d: np.cos(d) - np.sin(d), slope1=lambda d: math.cos(d) - math.sin(d))
    >>> m = maximise(*args, **kw)
    >>> m == _maximise_by_slope1(args[0], pcs, sample_grids(pcs, _DENSE), sample_grid(pcs, _DENSE), **kw)
    True
    """
    sl = np.asarray(slope(grid), dtype=float)
    noise = SLOPE_NOISE * max(0.0, float(np.nanmax(np.abs(sl), initial=0.0)))
    sizes = [len(d) for d in grids]
    last = np.cumsum(sizes) - 1                                # each piece's last sample
    first = last - np.array(sizes) + 1
    down = (sl[:-1] > 0.0) & (sl[1:] <= 0.0)                   # + to − between neighbouring samples
    down[last[:-1]] = False                                    # (not across the end of a piece)
    i = np.nonzero(down)[0]
    flat = np.maximum(np.abs(sl[i]), np.abs(sl[i + 1])) <= noise   # roundoff (a dwell): the sample stands
    stand, root = i[flat], i[~flat]
    cut_stand = np.searchsorted(stand, first).tolist() + [stand.size]
    stands = grid[stand].tolist()
    heads = sl[first].tolist()
    tails = sl[last].tolist()
    starts, ends = grid[first].tolist(), grid[last].tolist()
    places: list[float] = []
    for k in range(len(grids)):
        if not heads[k] > noise:
            places.append(starts[k])
        if not tails[k] < -noise:
            places.append(ends[k])
        places += stands[cut_stand[k]:cut_stand[k + 1]]
    if root.size:
        piece = np.searchsorted(last, root)                    # the piece of each root's bracket
        widths = [FLOOR_REL * (b - a) for a, b in pieces]
        for lo, hi, flo, fhi, k in zip(grid[root].tolist(), grid[root + 1].tolist(), sl[root].tolist(),
                                       sl[root + 1].tolist(), piece.tolist()):
            places.append(illinois1(slope1, lo, hi, flo, fhi, widths[k]))
    if g1 is not None:
        return _best_of_pairs([g1(x) for x in places], places)
    vals = np.asarray(g(np.asarray(places)), dtype=float).tolist()
    return _best_of_pairs(vals, places)


def _maximise_by_g1(g: Callable[[np.ndarray], np.ndarray], pieces: tuple[tuple[float, float], ...],
                    grids: Sequence[np.ndarray], grid: np.ndarray, g1: Callable[[float], float],
                    xtol: float, rests: Sequence[bool] = ()) -> Extremum:
    """:func:`maximise` without a slope, with g on one float: the same candidates as its loop over the pieces
    (each piece's ends, its :data:`REFINE` highest sampled peaks, ties by place, and those peaks refined by
    :func:`brent_max1` unless pruned), found by one numpy pass over the samples of all the pieces at once
    (``grid``), each piece's first and last sample compared with one neighbour only. The largest is chosen
    as :func:`best_of` does (whatever the candidates' order). A piece flagged in ``rests`` (the follower at
    rest: constant g) gives its ends only, no peaks.

    >>> pcs = ((0.0, 2.0), (2.0, TWO_PI))
    >>> args = (lambda d: np.sin(d) * np.exp(-d), pcs)
    >>> g1 = lambda d: math.sin(d) * math.exp(-d)
    >>> m = _maximise_by_g1(args[0], pcs, sample_grids(pcs, _DENSE), sample_grid(pcs, _DENSE), g1, 1e-11)
    >>> abs(m.delta - math.pi / 4) < 1e-7, abs(m.value - math.sin(math.pi / 4) * math.exp(-math.pi / 4)) < 1e-16
    (True, True)
    """
    v = np.asarray(g(grid), dtype=float)
    sizes = np.array([len(d) for d in grids])
    last = np.cumsum(sizes) - 1
    first = last - sizes + 1
    left = np.empty_like(v)
    left[1:] = v[:-1]
    left[first] = -np.inf                                     # the ends compare with one neighbour
    right = np.empty_like(v)
    right[:-1] = v[1:]
    right[last] = -np.inf
    peaks = np.nonzero((v >= left) & (v >= right) & ((v > left) | (v > right)))[0]   # never nan
    piece = np.searchsorted(last, peaks)
    if any(rests):
        moving = ~np.asarray(rests, dtype=bool)[piece]
        peaks, piece = peaks[moving], piece[moving]
    order = np.lexsort((peaks, -v[peaks], piece))              # by piece, highest first, ties by place
    peaks, piece = peaks[order], piece[order]
    if peaks.size:
        starts = np.searchsorted(piece, np.arange(len(grids)))
        keep = np.arange(peaks.size) - starts[piece] < REFINE
        peaks, piece = peaks[keep], piece[keep]
    values = v[first].tolist() + v[last].tolist() + v[peaks].tolist()
    places = grid[first].tolist() + grid[last].tolist() + grid[peaks].tolist()
    top = max(x for x in values if x == x)
    floor = top - PRUNE_REL * abs(top)
    firsts = first.tolist()
    for i, k, x, fx in zip(peaks.tolist(), piece.tolist(), grid[peaks].tolist(), v[peaks].tolist()):
        d, j = grids[k], i - firsts[k]
        vk = v[firsts[k]:firsts[k] + len(d)]
        gain = parabola_gain(d, vk, j)
        if fx + PRUNE_GAIN * gain >= floor and gain >= 0.0:    # else it cannot reach the best sample
            n = len(d) - 1
            at, best = brent_max1(g1, float(d[max(j - 1, 0)]), x, float(d[min(j + 1, n)]), fx, xtol)
            values.append(best)
            places.append(at)
    return _best_of_pairs(values, places)


def _best_of_pairs(values: list[float], places: list[float]) -> Extremum:
    """:func:`best_of` of the candidates (values[i], places[i]) without making them first."""
    top = -math.inf
    finite = False
    for v in values:
        if v == v:
            finite = True
            if v > top:
                top = v
    if not finite:
        return Extremum(values[0], places[0])
    lim = top - TIE_REL * abs(top)
    best_v, best_x = math.nan, math.inf
    found = False
    for v, x in zip(values, places):
        if v >= lim and (not found or x < best_x):
            best_v, best_x, found = v, x, True
    return Extremum(best_v, best_x)


def parabola_gain(d: np.ndarray, v: np.ndarray, i: int) -> float:
    """How much higher than the sample v[i] the parabola through it and its neighbours rises (0 when it
    does not bend down; at an end of the samples, the parabola through the first or last three, counted
    only when its top lies in the end cell): the scale of what refining a sampled peak can gain; −1 when
    the three samples agree to :data:`FLAT_REL` (a constant to roundoff, such as a dwell's curvature: a
    search would only find roundoff).

    >>> d = np.linspace(0.0, 1.0, 11); v = -(d - 0.33) ** 2
    >>> round(parabola_gain(d, v, 3), 12)      # the top at 0.33 is 0.0009 above the sample at 0.3
    0.0009
    """
    n = len(d) - 1
    if n < 2:
        return 0.0
    j = min(max(i, 1), n - 1)
    x0, x1, x2 = float(d[j - 1]), float(d[j]), float(d[j + 1])
    y0, y1, y2 = float(v[j - 1]), float(v[j]), float(v[j + 1])
    if max(abs(y1 - y0), abs(y1 - y2)) <= FLAT_REL * abs(y1):
        return -1.0                                 # flat to roundoff: nothing to refine
    s0, s1 = (y1 - y0) / (x1 - x0), (y2 - y1) / (x2 - x1)
    c = (s1 - s0) / (x2 - x0)
    if not c < 0.0:
        return 0.0
    b = s0 + c * (x1 - x0)                          # the parabola's slope at x1
    top = x1 - b / (2.0 * c)
    lo, hi = float(d[max(i - 1, 0)]), float(d[min(i + 1, n)])
    if not lo <= top <= hi:
        return 0.0
    return max(0.0, y1 - b * b / (4.0 * c) - float(v[i]))


@lru_cache(maxsize=256)
def sample_grids(pieces: tuple[tuple[float, float], ...], dense: int, turn: float | None = None
                 ) -> tuple[np.ndarray, ...]:
    """The samples :func:`maximise` takes of each piece: ``dense`` over the pieces (or over ``turn``
    radians, when given) shared by length (at least 16 a piece), denser towards both ends (1e-2 … 1e-9 of the
    piece), the right end one-sided. The same pieces give the same samples, so they are made once (read-only
    arrays).

    >>> g = sample_grids(((0.0, 1.0),), 16)[0]
    >>> len(g), float(g[0]), bool(g[-1] == np.nextafter(1.0, 0.0)), g.flags.writeable
    (33, 0.0, True, False)
    """
    total = sum(b - a for a, b in pieces) if turn is None else turn
    grids = []
    for a, b in pieces:
        n = max(16, int(math.ceil(dense * (b - a) / total)))
        near = (b - a) * _NEAR_ENDS                # a maximum squeezed against an end (where the slope is 0)
        d = np.unique(np.concatenate([np.linspace(a, b, n + 1), a + near, b - near]))
        d[-1] = np.nextafter(b, a)
        d.flags.writeable = False
        grids.append(d)
    return tuple(grids)


@lru_cache(maxsize=256)
def sample_grid(pieces: tuple[tuple[float, float], ...], dense: int, turn: float | None = None) -> np.ndarray:
    """The samples of :func:`sample_grids` in one read-only array (their concatenation, made once): the array
    :func:`maximise` evaluates all the pieces' samples on, the same object for the same pieces, so that what
    is computed on it can be kept (:func:`envelope_terms`).

    >>> d = sample_grid(((0.0, 1.0), (1.0, 2.0)), 32)
    >>> d is sample_grid(((0.0, 1.0), (1.0, 2.0)), 32), bool(np.all(d == np.concatenate(sample_grids(((0.0, 1.0), (1.0, 2.0)), 32))))
    (True, True)
    """
    d = np.concatenate(sample_grids(pieces, dense, turn))
    d.flags.writeable = False
    return d


def _split(values: np.ndarray, grids: Sequence[np.ndarray]) -> list[np.ndarray]:
    """``values`` of the concatenated ``grids``, cut back into one array per grid."""
    return np.split(values, np.cumsum([len(d) for d in grids])[:-1].tolist())


def illinois1(slope1: Callable[[float], float], lo: float, hi: float, flo: float, fhi: float,
              floor: float = 0.0) -> float:
    """The place where ``slope1`` changes sign from + (at lo, value flo) to − or 0 (at hi, value fhi), to the
    last bit, on floats: the steps of :func:`_bisect_all` (Illinois regula falsi, a plain halving every third
    step and wherever the secant leaves the bracket), ending when lo and hi are adjacent floats; the answer
    is hi. One step more: when an end has come to the root and its value is so small that the secant rounds
    onto it (it then never moves, and the other end only halves towards it: forty-odd calls), the next point
    is taken a few units of the last place inside from that end, which closes the bracket at once; when
    that point is still on the end's side (a root a little farther, or a slope that is 0 over a few units),
    the next such step reaches twice as far. At most :data:`_NUDGES` such steps are taken; the plain halving
    every third step bounds the worst case. ``floor`` (> 0) also ends the search when the bracket is no wider
    than it: near δ = 0 adjacent floats are ~1e-32 apart, and a root there (a law starting at rest) would
    take fifty halvings more than the same root at δ = 1, whose adjacent floats are wider than the floor.

    >>> x = illinois1(math.cos, 1.0, 2.0, math.cos(1.0), math.cos(2.0))
    >>> bool(x == _bisect_all(np.cos, np.array([1.0]), np.array([2.0]))[0]), math.cos(x) <= 0.0 < math.cos(math.nextafter(x, 0.0))
    (True, True)
    >>> calls = []
    >>> x = illinois1(lambda t: calls.append(t) or math.cos(t), 1.0, 2.0, math.cos(1.0), math.cos(2.0))
    >>> len(calls) < 15
    True
    """
    kept, step, reach, nudges = 0, 0, 1.0, _NUDGES
    while True:
        m = 0.5 * (lo + hi)
        den = fhi - flo
        side = 0                                    # +1: a step inside from hi, −1: from lo
        if step % 3 != 2 and den != 0.0:
            secant = hi - fhi * (hi - lo) / den
            if lo < secant < hi:                    # (a nan or infinite secant fails this test)
                m = secant
            elif secant == secant and nudges:      # it rounds onto an end: step just inside from that end
                nudges -= 1
                tol = reach * _NUDGE * max(abs(lo), abs(hi), _TINY)
                inside = hi - tol if secant >= hi else lo + tol
                if lo < inside < hi:
                    m, side = inside, (1 if secant >= hi else -1)
        if not lo < m < hi or hi - lo <= floor:
            return hi                               # lo and hi are adjacent: the halving sits on an end
        fm = slope1(m)
        up = fm > 0.0
        # a step inside that lands on its own end's side found no sign change: the next one reaches twice as far
        reach = reach * 2.0 if (side > 0 and not up) or (side < 0 and up) else (1.0 if side else reach)
        if up:
            lo, flo = m, fm
            if kept > 0:
                fhi = 0.5 * fhi
            kept = 1
        else:
            hi, fhi = m, fm
            if kept < 0:
                flo = 0.5 * flo
            kept = -1
        step += 1


_NUDGES = 6
"""At most this many steps inside from an end per root (a slope that is only roundoff there would make them
no better than halvings, and costlier)."""
_NUDGE = 4.0 * 2.220446049250313e-16
_TINY = 2.2250738585072014e-308


_CGOLD = 0.3819660112501051     # 2 − the golden ratio


def brent_max1(g1: Callable[[float], float], a: float, x: float, b: float, fx: float,
               xtol: float = 1e-11) -> tuple[float, float]:
    """Brent's method for a maximum of ``g1`` in [a, b] from the point x inside (g1(x) = fx higher than at the
    ends, as at a sampled peak): parabolic steps through the three best points, golden sections when they
    fail, until the bracket is about ``xtol`` wide. Returns (the place, the value), the best point found.
    A nan or a division by zero counts as lower than any number.

    >>> x, v = brent_max1(lambda t: math.sin(t) * math.exp(-t), 0.0, 0.8, 2.0, math.sin(0.8) * math.exp(-0.8))
    >>> abs(x - math.pi / 4) < 1e-8, abs(v - math.sin(math.pi / 4) * math.exp(-math.pi / 4)) < 1e-16
    (True, True)
    """
    def f(t: float) -> float:                       # minimised: −g1
        try:
            y = -g1(t)
        except ZeroDivisionError:
            return math.inf
        return y if y == y else math.inf

    fx = -fx if fx == fx else math.inf
    v = w = x
    fv = fw = fx
    d = e = 0.0
    while True:
        xm = 0.5 * (a + b)
        tol1 = 0.25 * xtol + 4.0 * _EPS * abs(x)
        tol2 = 2.0 * tol1
        if abs(x - xm) <= tol2 - 0.5 * (b - a):
            return x, -fx
        golden = True
        if abs(e) > tol1:                           # try the parabola through x, w, v
            r = (x - w) * (fx - fv)
            q = (x - v) * (fx - fw)
            p = (x - v) * q - (x - w) * r
            q = 2.0 * (q - r)
            if q > 0.0:
                p = -p
            q = abs(q)
            etemp, e = e, d
            if abs(p) < abs(0.5 * q * etemp) and q * (a - x) < p < q * (b - x):
                d = p / q
                u = x + d
                if u - a < tol2 or b - u < tol2:
                    d = math.copysign(tol1, xm - x)
                golden = False
        if golden:
            e = (a - x) if x >= xm else (b - x)
            d = _CGOLD * e
        u = x + d if abs(d) >= tol1 else x + math.copysign(tol1, d)
        fu = f(u)
        if fu <= fx:
            if u >= x:
                a = x
            else:
                b = x
            v, w, x = w, x, u
            fv, fw, fx = fw, fx, fu
        else:
            if u < x:
                a = u
            else:
                b = u
            if fu <= fw or w == x:
                v, w, fv, fw = w, u, fw, fu
            elif fu <= fv or v == x or v == w:
                v, fv = u, fu


_EPS = 2.220446049250313e-16


def best_of(cands: Sequence[Extremum]) -> Extremum:
    """The largest of candidate extrema; ties (:data:`TIE_REL`) go to the smallest cam angle."""
    finite = [c for c in cands if not math.isnan(c.value)]
    if not finite:
        return cands[0]
    top = max(c.value for c in finite)
    return min((c for c in finite if c.value >= top - TIE_REL * abs(top)), key=lambda c: c.delta)


def _bisect_all(slope: Callable[[np.ndarray], np.ndarray], lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """For every bracket [lo, hi] with slope(lo) > 0 ≥ slope(hi): the place where the slope's sign changes, to
    the last bit (lo and hi adjacent floats; the answer is hi), all brackets at once (one call of ``slope`` per
    step).

    The steps are the Illinois variant of regula falsi on the slope's values (superlinear: about ten calls
    instead of bisection's fifty-odd), with a plain halving every third step and wherever the secant leaves
    the bracket, so that each bracket still at least halves every three steps and ends between adjacent
    floats, where bisection would have ended.

    >>> x = _bisect_all(lambda d: np.cos(d), np.array([1.0]), np.array([2.0]))[0].item()
    >>> x, bool(math.cos(x) <= 0.0 < math.cos(math.nextafter(x, 0.0)))     # the sign changes just below x
    (1.5707963267948968, True)
    """
    lo, hi = lo.astype(float), hi.astype(float)
    if not lo.size:
        return hi
    flo = np.asarray(slope(lo), dtype=float)
    fhi = np.asarray(slope(hi), dtype=float)
    kept = np.zeros(lo.shape)                 # +1: lo moved last time, −1: hi moved (Illinois halves the other)
    step = 0
    while True:
        half = 0.5 * (lo + hi)
        with np.errstate(all="ignore"):
            secant = hi - fhi * (hi - lo) / (fhi - flo)
        use = (step % 3 != 2) & np.isfinite(secant) & (lo < secant) & (secant < hi)
        m = np.where(use, secant, half)
        live = (lo < m) & (m < hi)
        if not live.any():
            m = half                           # the secant sits on an end: halve, or stop when adjacent
            live = (lo < m) & (m < hi)
            if not live.any():
                break
        fm = np.asarray(slope(m), dtype=float)
        up = live & (fm > 0.0)
        down = live & ~(fm > 0.0)
        lo, flo = np.where(up, m, lo), np.where(up, fm, flo)
        hi, fhi = np.where(down, m, hi), np.where(down, fm, fhi)
        fhi = np.where(up & (kept > 0), 0.5 * fhi, fhi)
        flo = np.where(down & (kept < 0), 0.5 * flo, flo)
        kept = np.where(up, 1.0, np.where(down, -1.0, kept))
        step += 1
    return hi


def _golden_all(g, lo: np.ndarray, hi: np.ndarray, xtol: float) -> tuple[np.ndarray, np.ndarray]:
    """Golden-section search for a maximum in every interval [lo, hi] at once (one call of ``g`` per step
    on all intervals); returns the places and the values."""
    x1, x2 = hi - _GOLD * (hi - lo), lo + _GOLD * (hi - lo)
    f1, f2 = np.asarray(g(x1), dtype=float), np.asarray(g(x2), dtype=float)
    while np.any(hi - lo > xtol):
        left = f1 >= f2                                    # the maximum is in [lo, x2], else in [x1, hi]
        lo, hi = np.where(left, lo, x1), np.where(left, x2, hi)
        xn = np.where(left, hi - _GOLD * (hi - lo), lo + _GOLD * (hi - lo))
        fn = np.asarray(g(xn), dtype=float)
        x1, f1, x2, f2 = (np.where(left, xn, x2), np.where(left, fn, f2), np.where(left, x1, xn),
                          np.where(left, f1, fn))
    top = f1 >= f2
    return np.where(top, x1, x2), np.where(top, f1, f2)


def pressure_angle(c6: Curve6, ux: np.ndarray, uy: np.ndarray) -> np.ndarray:
    """Pressure angle (radians, 0 … π/2) between the curve's normal at the contact and the follower's
    velocity direction (ux, uy): atan2(|T·u|, |T×u|), T the tangent.

    Examples
    --------
    >>> one, zero = np.ones(1), np.zeros(1)
    >>> c6 = (zero, zero, one, one, zero, zero)            # tangent at 45°
    >>> round(float(np.degrees(pressure_angle(c6, zero, one))[0]), 12)
    45.0
    """
    _, _, dx, dy = c6[:4]
    return np.arctan2(np.abs(dx * ux + dy * uy), np.abs(dx * uy - dy * ux))


def pressure_angle1(c6: Curve1, ux: float, uy: float) -> float:
    """:func:`pressure_angle` of one point (floats): the same operations, and atan2 is the C library's in
    both, so the same bits.

    >>> c6 = (0.0, 30.0, -30.0, 0.5, 0.0, 0.0)
    >>> arr = pressure_angle(tuple(np.array([v]) for v in c6), 0.1, 1.0)
    >>> pressure_angle1(c6, 0.1, 1.0) == float(arr[0])
    True
    """
    _, _, dx, dy = c6[:4]
    return math.atan2(abs(dx * ux + dy * uy), abs(dx * uy - dy * ux))


def pressure_angle_slope(c6: Curve6, ux: np.ndarray, uy: np.ndarray, omega: np.ndarray | float) -> np.ndarray:
    """dα/dδ of :func:`pressure_angle` when the direction u turns at ``omega`` rad per rad of cam angle:
    (κ|P′| − ω)·sign((T·u)(T×u))."""
    _, _, dx, dy = c6[:4]
    return (curvature(c6) * np.hypot(dx, dy) - omega) * np.sign((dx * ux + dy * uy) * (dx * uy - dy * ux))


def frame_pressure_angle_slope(c6: Curve6, rel: tuple[np.ndarray, np.ndarray], ux: np.ndarray,
                               uy: np.ndarray) -> np.ndarray:
    """dα/dδ of :func:`pressure_angle` for a direction u fixed in the follower's (turning) frame, from the
    relative acceleration ``rel`` (:func:`inverted_relative`): (P′ × rel)/|P′|²·sign((T·u)(T×u)) — the same
    as :func:`pressure_angle_slope` with ω the frame's turn, without its cancellation of κ|P′| against ω
    (whose rounding, ε·|ω|, swamps α′ ~ (h/r0)² of a small stroke on a large base circle).

    Examples
    --------
    >>> d = np.linspace(0.2, 1.0, 5)
    >>> q, dq, ddq = (0 * d, 30.0 + np.sin(d)), (0 * d, np.cos(d)), (0 * d, -np.sin(d))
    >>> c6, rel = inverted(d, "cw", q, dq, ddq), inverted_relative(d, "cw", dq, ddq)
    >>> ux, uy = -np.sin(d), np.cos(d)                       # the axis, turned with the frame (k = +1)
    >>> bool(np.allclose(frame_pressure_angle_slope(c6, rel, ux, uy), pressure_angle_slope(c6, ux, uy, 1.0)))
    True
    """
    _, _, dx, dy = c6[:4]
    rx, ry = rel
    return (dx * ry - dy * rx) / (dx * dx + dy * dy) * np.sign((dx * ux + dy * uy) * (dx * uy - dy * ux))


def frame_pressure_angle_slope1(c6: Curve1, rel: tuple[float, float], ux: float, uy: float) -> float:
    """:func:`frame_pressure_angle_slope` at one point, on floats (the same bits; a tangent of length 0 gives
    nan, as the array path's 0/0 does).

    >>> c6, rel = (0.0, 30.0, -30.0, 0.5, 0.0, 0.0), (0.2, -0.1)
    >>> arr = frame_pressure_angle_slope(tuple(np.array([v]) for v in c6), tuple(np.array([v]) for v in rel), 0.1, 1.0)
    >>> frame_pressure_angle_slope1(c6, rel, 0.1, 1.0) == float(arr[0])
    True
    """
    _, _, dx, dy = c6[:4]
    rx, ry = rel
    den = dx * dx + dy * dy
    if den == 0.0:
        return math.nan
    return (dx * ry - dy * rx) / den * sign1((dx * ux + dy * uy) * (dx * uy - dy * ux))


def rho_min(curve: PitchCurve) -> Extremum:
    """The smallest radius of curvature of the convex parts of ``curve`` (inf if none), and where.

    Examples
    --------
    >>> def ellipse(d):
    ...     return 50 * np.cos(d), 30 * np.sin(d), -50 * np.sin(d), 30 * np.cos(d), -50 * np.cos(d), -30 * np.sin(d)
    >>> round(rho_min(PitchCurve(ellipse)).value, 12)     # b²/a
    18.0
    """
    known = curve.__dict__.get("_rho_min")       # a curve's own: computed once (a recipe's ρmin step, then its
    if known is not None:                        # roller profile, read it; the curve is frozen, the search pure)
        return known
    fn1 = curve.fn1
    if fn1 is None:
        sigma = curve.orientation
        top = maximise(lambda d: sigma * curvature(curve.eval(d)), curve.pieces())
        out = curve.__dict__["_rho_min"] = Extremum(1.0 / top.value if top.value > 0.0 else math.inf, top.delta)
        return out
    sense: list[int] = []

    def g(d):                   # the first call samples the whole turn: its points also give the orientation
        c6 = curve.eval(d)
        if not sense:
            sense.append(_sense(curve, d, c6))
        return sense[0] * curvature(c6)

    top = maximise(g, curve.pieces(), g1=lambda d: sense[0] * curvature1(fn1(d)), still=curve.still)
    out = curve.__dict__["_rho_min"] = Extremum(1.0 / top.value if top.value > 0.0 else math.inf, top.delta)
    return out


@lru_cache(maxsize=256)
def _rest_grids(pieces: tuple[tuple[float, float], ...], rests: tuple[bool, ...], dense: int = _DENSE,
                turn: float | None = None) -> tuple[tuple[np.ndarray, ...], np.ndarray]:
    """:func:`sample_grids` of ``pieces`` and their concatenation, each piece where the
    follower rests (``rests``) cut down to its first and last sample (read-only arrays, made once). The other
    pieces keep their samples, so their candidates are the same.

    >>> grids, grid = _rest_grids(((0.0, 1.0), (1.0, 2.0)), (False, True))
    >>> len(grids[1]), bool(np.all(grids[0] == sample_grids(((0.0, 1.0), (1.0, 2.0)), _DENSE)[0])), grid.size
    (2, True, 739)
    """
    grids = tuple(d[[0, -1]] if rest else d for d, rest in zip(sample_grids(pieces, dense, turn), rests))
    for d in grids:
        d.flags.writeable = False
    grid = np.concatenate(grids)
    grid.flags.writeable = False
    return grids, grid


DECISIVE = 0.25
"""The Riemann sum of a curve's area decides its orientation for good (kept as :attr:`PitchCurve.orientation`,
so that later steps do not sample the curve again) when it is at least this fraction of the sum of its terms'
sizes: a curve going round O (every cam's pitch curve) gives 1; only a curve that nearly cancels itself out
is left to the property's own samples."""


def _sense(curve: PitchCurve, d: np.ndarray, c6: Curve6) -> int:
    """The curve's orientation (:attr:`PitchCurve.orientation`) from samples of the whole turn in order with
    their exact derivatives: the sign of ∮(x y′ − y x′) dδ, twice the enclosed area (Riemann sum), unless the
    orientation is known already or the sum does not decide it (then the property's samples do). A sum far
    from a tie (:data:`DECISIVE`) is kept as the curve's orientation.

    >>> def circle40(d):
    ...     c, s = np.cos(d), np.sin(d)
    ...     return 40 * s, 40 * c, 40 * c, -40 * s, -40 * s, -40 * c
    >>> d = np.linspace(0.0, TWO_PI, 100)
    >>> _sense(PitchCurve(circle40), d, circle40(d)), PitchCurve(circle40).orientation
    (-1, -1)
    """
    known = curve.__dict__.get("orientation")
    if known is not None:
        return known
    x, y, dx, dy = c6[:4]
    terms = (x * dy - y * dx)[:-1] * np.diff(d)
    area = float(np.sum(terms))
    if not (area != 0.0 and math.isfinite(area)):
        return curve.orientation
    sense = 1 if area > 0.0 else -1
    if abs(area) > DECISIVE * float(np.sum(np.abs(terms))):   # far from a tie: the property's own samples
        curve.__dict__["orientation"] = sense                  # (1440, shoelace) cannot decide otherwise
    return sense


def rho_min_concave(curve: PitchCurve) -> Extremum:
    """The smallest |ρ| on the concave parts of ``curve`` (inf if it has none), and where."""
    sigma = curve.orientation
    fn1 = curve.fn1
    top = maximise(lambda d: -sigma * curvature(curve.eval(d)), curve.pieces(),
                   g1=None if fn1 is None else lambda d: -sigma * curvature1(fn1(d)))
    return Extremum(1.0 / top.value if top.value > 0.0 else math.inf, top.delta)


@dataclass(frozen=True)
class Corner:
    """A corner of the pitch curve at a break (a velocity jump of the follower): ``turn`` is the jump of the
    tangent direction (radians), positive when it turns the convex way (the roller then cannot follow it
    exactly)."""

    delta: float
    turn: float


def corners(curve: PitchCurve, *, rel: float = 1e-12) -> tuple[Corner, ...]:
    """The corners of the curve: breaks where the tangent direction jumps by more than ``rel`` radians."""
    sigma, out = curve.orientation, []
    for b in [0.0] + sorted(curve.breaks):
        before = curve.eval(np.array([np.nextafter(b if b > 0.0 else TWO_PI, 0.0)]))
        after = curve.eval(np.array([b]))
        t0, t1 = (before[2][0], before[3][0]), (after[2][0], after[3][0])
        turn = math.atan2(t0[0] * t1[1] - t0[1] * t1[0], t0[0] * t1[0] + t0[1] * t1[1])
        if abs(turn) > rel:
            out.append(Corner(b, sigma * turn))
    return tuple(out)


def sample_count(curve: PitchCurve, rr: float = 0.0, tolerance: float | None = None) -> int:
    """The number of profile samples over a turn so that every chord of the roller profile (offset ``rr``)
    is within ``tolerance`` of the exact curve.

    A chord c on radius ρ deviates by c²/8ρ. With samples Δδ apart, c ≈ |P_a′|Δδ and ρ = ρ_a, the offset
    curve's radius of curvature; |P_a′|²/ρ_a = |P′|²·|κ|·|1 − rr·σκ|, so
    Δδ = √(8·tolerance / max(|P′|²·|κ|·|1 − rr·σκ|)) — set by the sharpest bend (ρmin), not fixed.
    ``tolerance = None``: :data:`TOLERANCE_REL` of the curve's size. More than :data:`MAX_SAMPLES` samples
    are refused (:class:`NotAMechanism` naming the cap) before any is computed.
    """
    tolerance = curve_tolerance(curve, tolerance)
    return sum(_counts(curve.pieces(), _sample_step(curve, rr, tolerance)))


def curve_tolerance(curve: PitchCurve, tolerance: float | None) -> float:
    """``tolerance``, or :data:`TOLERANCE_REL` of the curve's size when it is None."""
    return TOLERANCE_REL * curve.size if tolerance is None else tolerance


def _sample_step(curve: PitchCurve, rr: float, tolerance: float) -> float:
    """The sample spacing of the offset by ``rr`` (:func:`_step` of the largest |P′|²·|κ|·|1 − rr·σ·κ|), the
    peaks refined by Brent on floats when the curve has its scalar form (``fn1``): the same search to the same
    ``xtol`` as golden sections on arrays, in a third of the calls."""
    sigma = curve.orientation

    def bend(d):
        c6 = curve.eval(d)
        k = curvature(c6)
        return (c6[2] ** 2 + c6[3] ** 2) * np.abs(k) * np.abs(1.0 - rr * sigma * k)

    fn1 = curve.fn1

    def bend1(d: float) -> float:                   # bend on one float (squares as products, as numpy's)
        c6 = fn1(d)
        k = curvature1(c6)
        return (c6[2] * c6[2] + c6[3] * c6[3]) * abs(k) * abs(1.0 - rr * sigma * k)

    return _step(maximise(bend, curve.pieces(), g1=None if fn1 is None else bend1).value, tolerance)


def _step(bend: float, tolerance: float) -> float:
    """Largest sample spacing (radians) keeping the chord error ≤ tolerance where |P′|²/ρ ≤ ``bend``."""
    if not tolerance > 0.0:
        raise NotAMechanism(f"tolerance must be > 0 mm, got {tolerance!r}")
    return math.sqrt(8.0 * tolerance / bend) if bend > 0.0 else math.inf


def _counts(pieces, step: float) -> list[int]:
    """Samples per piece (both ends) at most ``step`` apart; more than :data:`MAX_SAMPLES` in all are
    refused before anything is allocated."""
    need = sum(max(2.0, (b - a) / step) + 1.0 for a, b in pieces) if step > 0.0 else math.inf
    if not need <= MAX_SAMPLES:
        raise NotAMechanism(f"the profile tolerance needs {need:.3g} samples, more than the cap of {MAX_SAMPLES}; "
                            "give a larger tolerance")
    return [max(2, int(math.ceil((b - a) / step))) + 1 for a, b in pieces]


def _angles(pieces, step: float) -> list[np.ndarray]:
    """The sample angles of each piece, at most ``step`` apart, both ends included (the right end
    one-sided)."""
    out = []
    for (a, b), n in zip(pieces, _counts(pieces, step)):
        d = np.linspace(a, b, n)
        d[-1] = np.nextafter(b, a)
        out.append(d)
    return out


@dataclass(frozen=True)
class Profile:
    """A sampled cam profile.

    Attributes
    ----------
    xy : (N, 2) array
        The profile as a closed ring (last point not repeated), in δ order, loops trimmed.
    delta : (N,) array
        The cam angle (radians) of each point (of the pitch point whose roller or face touches there).
    raw : (M, 2) array
        The offset before trimming (with the roller arcs filling the gaps at corners).
    trimmed : bool
        True when loops (undercut, corners) had to be cut away.
    undercut : bool
        True when the follower cannot be reproduced: rr ≥ ρmin on a convex part (roller) or the envelope
        is not convex (flat face).
    tolerance : float
        The chord tolerance (mm) the sampling honours.
    """

    xy: np.ndarray
    delta: np.ndarray
    raw: np.ndarray
    trimmed: bool
    undercut: bool
    tolerance: float
    info: dict = field(default_factory=dict)

    def ring(self) -> LinearRing:
        """The profile as a shapely ring."""
        return LinearRing(self.xy)

    def csv(self) -> str:
        """``x,y,delta`` lines (mm, mm, degrees) with a header: the profile for manufacture."""
        rows = ["x_mm,y_mm,delta_deg"]
        rows += [f"{x:.9f},{y:.9f},{math.degrees(d):.9f}" for (x, y), d in zip(self.xy, self.delta)]
        return "\n".join(rows) + "\n"


def _arc(center, r, a0: float, a1: float, chord: float) -> np.ndarray:
    """Points strictly inside the shorter arc from polar angle a0 to a1 about ``center``."""
    if r == 0.0:
        return np.empty((0, 2))
    sweep = math.remainder(a1 - a0, TWO_PI)
    need = abs(sweep) * r / chord
    if not need <= MAX_SAMPLES:
        raise NotAMechanism(f"the roller's arc at a corner needs {need:.3g} points, more than the cap of "
                            f"{MAX_SAMPLES}; give a larger tolerance")
    n = max(1, int(math.ceil(need)))
    t = a0 + sweep * np.arange(1, n) / n
    return np.column_stack([center[0] + r * np.cos(t), center[1] + r * np.sin(t)])


def roller_profile(curve: PitchCurve, rr: float, tolerance: float | None = None) -> Profile:
    """The actual profile of a roller of radius ``rr``: the pitch curve offset by rr along the exact unit
    normal towards the cam centre (the inner envelope of the roller circles), sampled per
    :func:`sample_count` (``tolerance = None``: :data:`TOLERANCE_REL` of the curve's size); at a corner of the pitch curve the gap is bridged by the roller's arc, and loops
    (undercut, convex corners) are trimmed with shapely. ``rr = 0`` gives the pitch curve itself (a knife
    edge's profile).

    Examples
    --------
    >>> def ellipse(d):
    ...     return 50 * np.cos(d), 30 * np.sin(d), -50 * np.sin(d), 30 * np.cos(d), -50 * np.cos(d), -30 * np.sin(d)
    >>> p = roller_profile(PitchCurve(ellipse), 20.0)     # ρmin = 18 < rr: loops at the ends of the long axis
    >>> p.undercut, p.trimmed, p.ring().is_simple
    (True, True, True)
    """
    if not rr >= 0.0:
        raise NotAMechanism(f"roller radius rr must be ≥ 0 mm, got {rr!r}")
    tolerance = curve_tolerance(curve, tolerance)
    sigma, pieces = curve.orientation, curve.pieces()
    angles = _angles(pieces, _sample_step(curve, rr, tolerance))
    count = sum(len(d) for d in angles)
    chord = math.sqrt(8.0 * tolerance * max(rr, tolerance))
    xs, ds = [], []
    for d in angles:
        x, y, dx, dy = curve.eval(d)[:4]
        speed = np.hypot(dx, dy)
        nx, ny = -sigma * dy / speed, sigma * dx / speed       # unit normal towards the inside
        pts = np.column_stack([x + rr * nx, y + rr * ny])
        if xs:                                                  # bridge the corner with the roller's arc
            c = (x[0], y[0])
            prev = xs[-1][-1]
            a0, a1 = math.atan2(prev[1] - c[1], prev[0] - c[0]), math.atan2(pts[0, 1] - c[1], pts[0, 0] - c[0])
            arc = _arc(c, rr, a0, a1, chord)
            xs.append(arc)
            ds.append(np.full(len(arc), d[0]))
        xs.append(pts)
        ds.append(d)
    first, last = xs[0][0], xs[-1][-1]
    c = curve.eval(np.array([0.0]))
    arc = _arc((c[0][0], c[1][0]), rr, math.atan2(last[1] - c[1][0], last[0] - c[0][0]),
               math.atan2(first[1] - c[1][0], first[0] - c[0][0]), chord)
    xs.append(arc)
    ds.append(np.full(len(arc), TWO_PI))
    raw, delta = np.vstack(xs), np.concatenate(ds)
    rmin = rho_min(curve)
    undercut = rr >= rmin.value
    xy, dl, trimmed = trim_loops(raw, delta)
    return Profile(xy, dl, raw, trimmed, undercut, tolerance,
                   {"rho_min_pitch": rmin, "samples": count, "corners": corners(curve)})


def trim_loops(raw: np.ndarray, delta: np.ndarray) -> tuple[np.ndarray, np.ndarray, bool]:
    """Cut the loops of a self-intersecting closed polyline: node it with shapely, polygonize the pieces and
    keep the boundary of the largest face (the cam body; loops are the small faces cut off).

    Returns the ring's points (δ order, last not repeated), the cam angle of each (from the nearest place
    on the raw polyline) and whether anything was cut.
    """
    keep = np.ones(len(raw), dtype=bool)
    keep[1:] = np.any(np.diff(raw, axis=0) != 0.0, axis=1)
    raw, delta = raw[keep], delta[keep]
    if LinearRing(raw).is_simple:
        return raw, delta, False
    faces = list(shapely.polygonize([shapely.unary_union(LineString(np.vstack([raw, raw[:1]])))]).geoms)
    body = max(faces, key=lambda f: f.area)
    pts = np.asarray(body.exterior.coords)[:-1]
    idx = _row_index(raw, pts).astype(float)
    known = idx >= 0
    if known.sum() < 3:
        raise NotAMechanism("the cam profile collapses: its loops leave no body (roller far too large)")
    pos = np.arange(len(pts), dtype=float)
    # the cut points (crossings) get the place of their neighbours on the ring
    idx = np.interp(pos, pos[known], idx[known], period=len(pts))
    if np.median(np.diff(idx[known])) < 0:
        pts, idx = pts[::-1], idx[::-1]
    start = int(np.argmin(idx))
    pts, idx = np.roll(pts, -start, axis=0), np.roll(idx, -start)
    return pts, np.interp(idx, np.arange(len(raw)), delta), True


def _row_index(table: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """For each point of ``rows`` (k, 2) the index of an equal point of ``table`` (n, 2), −1 where there is
    none; of several equal points the last, as a dictionary of the points' tuples keeps it (equal as floats:
    −0.0 is 0.0, nan is nothing). One sort and one binary search, not n + k tuples.

    >>> _row_index(np.array([[0.0, 1.0], [2.0, 3.0], [0.0, 1.0]]), np.array([[-0.0, 1.0], [2.0, 3.0], [5.0, 5.0]]))
    array([ 2,  1, -1])
    """
    keys = np.ascontiguousarray(table, dtype=float).view(np.complex128).ravel()   # x + iy: sorted by x, then y
    want = np.ascontiguousarray(rows, dtype=float).view(np.complex128).ravel()
    order = np.argsort(keys, kind="stable")                                  # equal points in index order
    ranked = keys[order]
    at = np.searchsorted(ranked, want, side="right") - 1                     # the last of the equal ones
    hit = at >= 0
    hit[hit] = ranked[at[hit]] == want[hit]
    return np.where(hit, order[np.maximum(at, 0)], -1)


def validate_roller(profile: Profile, curve: PitchCurve, rr: float, *, count: int = 720) -> dict:
    """Check a roller profile: the ring is simple, and every roller circle (centres sampled on the pitch
    curve) touches it: distance centre–profile = rr within the tolerance (interference would be less;
    a roller that lifts off at an undercut or a convex corner more).

    Returns ``{"simple", "max_interference", "max_lift", "lift_at"}`` (mm, and the cam angles in radians of
    the centres that lift off by more than the tolerance).
    """
    d = np.linspace(0.0, TWO_PI, count, endpoint=False)
    x, y = curve.eval(d)[:2]
    ring = profile.ring()
    dist = shapely.distance(shapely.points(np.column_stack([x, y])), ring)
    lift = dist - rr
    return {"simple": bool(ring.is_simple), "max_interference": float(max(0.0, -lift.min())),
            "max_lift": float(max(0.0, lift.max())), "lift_at": d[lift > profile.tolerance]}


# ------------------------------------------------------------------ flat faces: envelopes of lines
LineFn = Callable[[np.ndarray], tuple[np.ndarray, ...]]


@dataclass(frozen=True)
class LineFamily:
    """A one-parameter family of lines X·n(δ) = p(δ), n = (cos φ, sin φ) pointing away from the cam body:
    ``fn(delta) -> (φ, φ′, φ″, p, p′, p″)`` (radians, derivatives by δ), with ``breaks`` as for
    :class:`PitchCurve`. The face of a flat-faced follower in its inverted positions is such a family.
    ``fn1``, when given, is ``fn`` on one float returning floats with the same bits (the scalar path)."""

    fn: LineFn
    breaks: tuple[float, ...] = ()
    fn1: Callable[[float], tuple[float, float, float, float, float, float]] | None = None
    memo: dict = field(default_factory=dict, compare=False, repr=False)
    """What :func:`envelope_terms` computed on the last few read-only sample arrays (:func:`sample_grid`): the
    searches over the turn share those samples."""
    still: tuple[tuple[float, float], ...] = ()
    """The cam angles [a, b] (radians) where the follower rests: the lines turn about O at a constant distance,
    their envelope an arc about O (see :func:`maximise`)."""

    def pieces(self) -> list[tuple[float, float]]:
        """The smooth pieces of the turn."""
        return PitchCurve(lambda d: d, self.breaks).pieces()

    @property
    def size(self) -> float:
        """The lines' largest distance from O (over 1440 samples): the scale of their tolerances."""
        return float(np.abs(self.eval(np.linspace(0.0, TWO_PI, _DENSE, endpoint=False))[3]).max())

    def eval(self, delta) -> tuple[np.ndarray, ...]:
        """(φ, φ′, φ″, p, p′, p″) at ``delta`` (radians)."""
        return tuple(np.asarray(v, dtype=float) for v in self.fn(np.asarray(delta, dtype=float)))


def envelope(fam: LineFamily, delta) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Contact points of the envelope of the lines, where each line touches it.

    With t = dn/dφ = (−sin φ, cos φ) and ' = d/dδ: X = p·n + λ·t, λ = p′/φ′ (the contact's place along the
    line from the foot of the perpendicular from O), and the envelope's radius of curvature
    ρ = p + d²p/dφ² = p + (p″φ′ − p′φ″)/φ′³ (> 0 where the profile is convex).

    Returns (x, y, λ, ρ).

    Examples
    --------
    Circle of radius 30 as the envelope of its tangents:

    >>> fam = LineFamily(lambda d: (d, 1 + 0 * d, 0 * d, 30 + 0 * d, 0 * d, 0 * d))
    >>> [round(float(v[0]), 12) for v in envelope(fam, np.array([0.0]))]
    [30.0, 0.0, 0.0, 30.0]
    """
    t = envelope_terms(fam, delta)
    return t.x, t.y, t.lam, t.rho


@dataclass(frozen=True)
class EnvelopeTerms:
    """The lines (φ, φ′, φ″, p, p′, p″) at some cam angles and what :func:`envelope` forms from them: cos φ,
    sin φ, λ, ρ and the contact point (x, y)."""

    phi: np.ndarray
    dphi: np.ndarray
    ddphi: np.ndarray
    p: np.ndarray
    dp: np.ndarray
    ddp: np.ndarray
    c: np.ndarray
    s: np.ndarray
    lam: np.ndarray
    rho: np.ndarray
    x: np.ndarray
    y: np.ndarray


def envelope_terms(fam: LineFamily, delta) -> EnvelopeTerms:
    """The terms of :func:`envelope` at ``delta`` (radians), by its operations. On a read-only array (the
    samples of a search, :func:`sample_grid`) they are kept on the family: the searches of the turn that
    sample it (the contact's extremes, ρmin) compute them once.

    >>> fam = LineFamily(lambda d: (d, 1 + 0 * d, 0 * d, 30 + 0 * d, 0 * d, 0 * d))
    >>> d = sample_grid(((0.0, TWO_PI),), 64)
    >>> envelope_terms(fam, d) is envelope_terms(fam, d), float(envelope_terms(fam, d).rho.min())
    (True, 30.0)
    """
    d = np.asarray(delta, dtype=float)
    keep = not d.flags.writeable and d.base is None        # read-only and owning its numbers: they stay
    if keep:
        hit = fam.memo.get(id(d))
        if hit is not None and hit[0] is d:
            return hit[1]
        run = _memo_run(fam, d)
        if run is not None:
            return _keep_terms(fam, d, run)
    phi, dphi, ddphi, p, dp, ddp = fam.eval(d)
    lam = dp / dphi
    rho = p + (ddp * dphi - dp * ddphi) / dphi ** 3
    c, s = np.cos(phi), np.sin(phi)
    out = EnvelopeTerms(phi, dphi, ddphi, p, dp, ddp, c, s, lam, rho, p * c - lam * s, p * s + lam * c)
    return _keep_terms(fam, d, out) if keep else out


def _keep_terms(fam: LineFamily, d: np.ndarray, out: EnvelopeTerms) -> EnvelopeTerms:
    if len(fam.memo) >= _MEMO_GRIDS:
        fam.memo.clear()
    fam.memo[id(d)] = (d, out)                   # (d kept with it: its id is not reused while it is here)
    return out


def _memo_run(fam: LineFamily, d: np.ndarray) -> EnvelopeTerms | None:
    """The terms at ``d`` cut from those kept for a larger sample array that holds ``d`` as a run of
    consecutive samples (a segment's samples within the turn's, taken as densely: :func:`maximise` with
    ``turn``), or None. Each term is elementwise, so the cut holds the numbers computing them at ``d`` gives.

    >>> fam = LineFamily(lambda d: (d, 1 + 0 * d, 0 * d, 30 + 0 * d, 0 * d, 0 * d))
    >>> pcs = ((0.0, 1.0), (1.0, TWO_PI))
    >>> whole, part = sample_grid(pcs, 64), sample_grid(pcs[1:], 64, TWO_PI - 1.0 + 1.0)
    >>> t = envelope_terms(fam, whole)
    >>> bool(np.all(envelope_terms(fam, part).x == t.x[-part.size:]))
    True
    """
    n = d.size
    if d.ndim != 1 or not n:
        return None
    for grid, terms in list(fam.memo.values()):
        i = int(np.searchsorted(grid, d[0]))
        if grid.ndim == 1 and i + n <= grid.size and grid[i] == d[0] and np.array_equal(grid[i:i + n], d):
            return EnvelopeTerms(*(getattr(terms, f.name)[i:i + n] for f in fields(EnvelopeTerms)))
    return None


_MEMO_GRIDS = 4
"""Sample arrays whose envelope terms a family keeps (the turn's and each segment's searches)."""


def contact_slope(fam: LineFamily, delta) -> np.ndarray:
    """dλ/dδ = (p″φ′ − p′φ″)/φ′² of the contact's place λ = p′/φ′ along the line (:func:`envelope`).

    Examples
    --------
    >>> fam = LineFamily(lambda d: (d, 1 + 0 * d, 0 * d, 30 + 0 * d, 2 * d, 2 + 0 * d))
    >>> float(contact_slope(fam, np.array([0.3]))[0])
    2.0
    """
    _, dphi, ddphi, _, dp, ddp = fam.eval(delta)
    return (ddp * dphi - dp * ddphi) / dphi ** 2


def envelope1(f6: tuple[float, float, float, float, float, float]) -> tuple[float, float, float, float]:
    """:func:`envelope` of one line's (φ, φ′, φ″, p, p′, p″), on floats: the same operations (φ′³ by numpy's
    power on one element, which math's pow does not always match), so the same bits.

    >>> fam = LineFamily(lambda d: (d, 1.3 + 0 * d, 0.2 + 0 * d, 30 + np.sin(d), np.cos(d), -np.sin(d)))
    >>> d = np.array([0.7])
    >>> envelope1(tuple(float(v[0]) for v in fam.eval(d))) == tuple(float(v[0]) for v in envelope(fam, d))
    True
    """
    phi, dphi, ddphi, p, dp, ddp = f6
    lam = div1(dp, dphi)
    rho = p + div1(ddp * dphi - dp * ddphi, pow1(dphi, 3.0))
    c, s = math.cos(phi), math.sin(phi)
    return p * c - lam * s, p * s + lam * c, lam, rho


def div1(a: float, b: float) -> float:
    """a / b as numpy divides floats: ±inf or nan for a zero divisor instead of an exception.

    >>> div1(1.0, 4.0), div1(-1.0, 0.0), math.isnan(div1(0.0, 0.0))
    (0.25, -inf, True)
    """
    if b != 0.0:
        return a / b
    if a == 0.0 or a != a:
        return math.nan
    return math.copysign(math.inf, a) * math.copysign(1.0, b)


def pow1(x: float, y: float) -> float:
    """x ** y as numpy computes it on arrays, for one float. numpy's float64 power is the C library's ``pow``
    where its plain (baseline) loop runs, which is what :func:`math.pow` calls: then math's (a tenth of a
    microsecond instead of two); where numpy dispatches a SIMD loop of its own (SVML on AVX-512, not always the
    C library's bits), for other exponents than 3 and 1.5 (numpy squares for 2, takes the root for 0.5, the
    reciprocal for −1) and where math raises instead of returning inf or nan, numpy's on a one-element array.

    >>> pow1(1.1, 3.0) == float((np.array([1.1]) ** 3.0)[0]), pow1(1e200, 3.0), math.isnan(pow1(-2.0, 1.5))
    (True, inf, True)
    """
    one = np.empty(1)
    one[0] = x
    if y == 3.0 or y == 1.5:
        if numpy_is_libm("power"):              # (numpy squares, roots and inverts for 2, 0.5, −1)
            try:
                return math.pow(x, y)
            except (OverflowError, ValueError):
                pass
        elif 1e-100 < x < 1e100:                # nothing to overflow, underflow or be invalid: no floating-point
            return float(np.power(one, y)[0])   # error to silence (the same call; errstate costs twice the power)
    with np.errstate(all="ignore"):
        return float(np.power(one, y)[0])


def atan2_1(y: float, x: float) -> float:
    """``np.arctan2`` of one pair of floats: :func:`math.atan2` where numpy's float64 loop is the C library's
    atan2 (:func:`numpy_is_libm`), else numpy's on one-element arrays.

    >>> atan2_1(1.0, -1.0) == float(np.arctan2(np.array([1.0]), np.array([-1.0]))[0])
    True
    """
    if numpy_is_libm("arctan2"):
        return math.atan2(y, x)
    return float(np.arctan2(np.array([y]), np.array([x]))[0])


_LIBM: dict[str, bool] = {}
"""Whether numpy's float64 loop of a ufunc is the C library's function (decided once per ufunc)."""


def numpy_is_libm(name: str) -> bool:
    """Whether numpy's float64 loop of the ufunc ``name`` ("power" for the exponents 3 and 1.5, "arctan2",
    "arccos", "arcsin") is
    the C library's function, which :mod:`math` calls: numpy reports it dispatches its baseline loop
    (``numpy.lib.introspect``; a SIMD loop of its own, such as SVML on AVX-512, rounds differently), and a few
    hundred values agree. Decided once.

    >>> numpy_is_libm("power") in (True, False)
    True
    """
    known = _LIBM.get(name)
    if known is not None:
        return known
    ok = False
    try:
        from numpy.lib.introspect import opt_func_info
        info = opt_func_info(func_name=f"^{name}$", signature="float64")[name]
        ok = bool(info) and all(str(v.get("current", "")).startswith("baseline") for v in info.values())
    except Exception:                               # an older numpy without the report: numpy's own
        ok = False
    if ok:
        x = np.random.default_rng(0).uniform(1e-3, 1e3, 256)
        if name == "power":
            for v, y in ((x, 1.5), (x, 3.0), (-x, 3.0)):
                ok = ok and all(math.pow(a, y) == b for a, b in zip(v.tolist(), (v ** y).tolist()))
        elif name == "arctan2":
            u = x * np.resize([1.0, -1.0, -1.0, 1.0], 256)
            v = x[::-1] * np.resize([1.0, 1.0, -1.0, -1.0], 256)
            ok = all(math.atan2(a, b) == c for a, b, c in zip(u.tolist(), v.tolist(), np.arctan2(u, v).tolist()))
        elif name in ("arccos", "arcsin"):
            u = np.random.default_rng(1).uniform(-1.0, 1.0, 256)
            f = math.acos if name == "arccos" else math.asin
            ok = all(f(a) == b for a, b in zip(u.tolist(), getattr(np, name)(u).tolist()))
        else:
            ok = False
    _LIBM[name] = ok
    return ok


def envelope_rho_min(fam: LineFamily) -> Extremum:
    """The smallest radius of curvature ρ of the envelope over the turn (≤ 0: not convex), and where (with
    the family's scalar form, its peaks refined by Brent on floats: :func:`maximise`)."""
    fn1 = fam.fn1

    def g1(d: float) -> float:                      # −ρ of envelope1(fn1(d)), by its operations
        _, dphi, ddphi, p, dp, ddp = fn1(d)
        return -(p + div1(ddp * dphi - dp * ddphi, pow1(dphi, 3.0)))

    low = maximise(lambda d: -envelope(fam, d)[3], fam.pieces(), g1=None if fn1 is None else g1, still=fam.still)
    return Extremum(-low.value, low.delta)


def flat_profile(fam: LineFamily, tolerance: float | None = None) -> Profile:
    """The profile cut by a flat face: the envelope of the family, sampled so that every chord is within
    ``tolerance`` (|X′|²/ρ = |ρ|·φ′²), loops of a non-convex envelope (ρ < 0 somewhere: the face cannot
    follow the motion) trimmed. ``info`` holds ``rho_min`` (an :class:`Extremum` of ρ), ``lam_min`` and
    ``lam_max`` (the contact's extreme places along the face, Extremum each). ``tolerance = None``:
    :data:`TOLERANCE_REL` of the family's size (the largest distance of a line from O).

    Examples
    --------
    >>> fam = LineFamily(lambda d: (d, 1 + 0 * d, 0 * d, 30 + 0 * d, 0 * d, 0 * d))
    >>> p = flat_profile(fam)
    >>> p.undercut, round(p.info["rho_min"].value, 12)
    (False, 30.0)
    """
    pieces = fam.pieces()
    if tolerance is None:
        tolerance = TOLERANCE_REL * fam.size
    rmin = envelope_rho_min(fam)
    fn1 = fam.fn1                      # the peaks refined by Brent on floats when the family has its scalar form

    def bend1(d: float) -> float:
        f6 = fn1(d)
        return abs(envelope1(f6)[3]) * (f6[1] * f6[1])

    bend = maximise(lambda d: np.abs(envelope(fam, d)[3]) * fam.eval(d)[1] ** 2, pieces,
                    g1=None if fn1 is None else bend1).value
    angles = np.concatenate(_angles(pieces, _step(bend, tolerance)))
    count = len(angles)
    x, y = envelope(fam, angles)[:2]
    raw = np.column_stack([x, y])
    xy, dl, trimmed = trim_loops(raw, angles)
    hi = maximise(lambda d: envelope(fam, d)[2], pieces, g1=None if fn1 is None else lambda d: envelope1(fn1(d))[2])
    lo = maximise(lambda d: -envelope(fam, d)[2], pieces, g1=None if fn1 is None else lambda d: -envelope1(fn1(d))[2])
    back = backward_jumps(fam)
    return Profile(xy, dl, raw, trimmed, rmin.value <= 0.0 or bool(back), tolerance,
                   {"rho_min": rmin, "lam_max": hi, "lam_min": Extremum(-lo.value, lo.delta), "samples": count,
                    "backward_jumps": back})


def backward_jumps(fam: LineFamily) -> tuple[Extremum, ...]:
    """Breaks where the contact jumps back along the face (a velocity drop of the follower, e.g. the end
    of a uniform rise): the envelope then has a loop there, and the face cannot reproduce the motion.
    Each as an :class:`Extremum` (the jump, mm, and the cam angle). A jump counts when it exceeds
    :data:`JUMP_REL` of the contact's range over the turn (sampled at 1440 places and every break).

    Examples
    --------
    >>> fam = LineFamily(lambda d: (d, 1 + 0 * d, 0 * d, 30 + 0 * d, np.where(d < 1.0, 5.0, 0.0), 0 * d), (1.0,))
    >>> [(round(j.value, 12), j.delta) for j in backward_jumps(fam)]
    [(-5.0, 1.0)]
    """
    cuts = [0.0] + [x for x in sorted(fam.breaks) if 0.0 < x < TWO_PI]
    after = np.array(cuts)
    before = np.nextafter(np.array([b if b > 0.0 else TWO_PI for b in cuts]), 0.0)
    if fam.fn1 is not None:                     # the first look's few angles on floats (the same bits)
        angles = cuts + before.tolist()
        kept = _kept_lines(fam, angles)         # (the pieces' ends: samples of a search over the turn)
        if kept is None:
            ends = [fam.fn1(x) for x in angles]                    # λ = p′/φ′ as envelope1 divides
            lams, dphis = [div1(f6[4], f6[1]) for f6 in ends], [f6[1] for f6 in ends]
        else:
            lams, dphis = kept
        la, lb = lams[:len(cuts)], lams[len(cuts):]
        jumps = [(b, (x1 - x0) * math.copysign(1.0, w)) for b, x0, x1, w in zip(cuts, lb, la, dphis)]
        part = [v for v in la + lb if v == v]
        more = iter(_EVERY_90TH)                # a part of the range, grown a sample at a time: every part is
        while True:                             # within the whole range, so once no jump counts against it, none does
            low = max(part) - min(part) if part else math.nan
            if all(j >= -JUMP_REL * low for _, j in jumps):
                return ()
            x = next(more, None)
            if x is None:
                break
            f6 = fam.fn1(x)
            v = div1(f6[4], f6[1])
            if v == v:
                part.append(v)
        lam = np.array(la + lb)
    else:
        lam = envelope(fam, np.concatenate([after, before]))[2]
        la, lb = lam[:len(cuts)], lam[len(cuts):]
        dphi = fam.eval(after)[1]
        jumps = [(b, (x1 - x0) * math.copysign(1.0, w)) for b, x0, x1, w in zip(cuts, lb.tolist(), la.tolist(),
                                                                                dphi.tolist())]
        part = np.concatenate([lam, envelope(fam, np.array(_EVERY_90TH))[2]])   # the breaks and every 90th sample:
        low = float(np.nanmax(part) - np.nanmin(part)) if not np.isnan(part).all() else math.nan   # a part of the range
        if all(j >= -JUMP_REL * low for _, j in jumps):
            return ()                               # no jump counts even against a part of the range: done
    grid = np.linspace(0.0, TWO_PI, _DENSE, endpoint=False)      # (made only when the first look fails)
    lam = np.concatenate([lam, envelope(fam, grid)[2]])
    span = float(np.nanmax(lam) - np.nanmin(lam))
    return tuple(Extremum(float(jump), b) for b, jump in jumps if jump < -JUMP_REL * span)


def _kept_lines(fam: LineFamily, angles: list[float]) -> tuple[list[float], list[float]] | None:
    """(λ, φ′) at ``angles`` from the envelope terms ``fam`` keeps for a sample array holding every one of
    them (:func:`envelope_terms`: a search over the turn samples each piece's ends), or None. λ = p′/φ′ there
    is numpy's division, which :func:`div1` matches: the numbers the scalar path computes.

    >>> fam = LineFamily(lambda d: (d, 1 + 0 * d, 0 * d, 30 + 0 * d, np.sin(d), 0 * d), (1.0,))
    >>> d = sample_grid(((0.0, 1.0), (1.0, TWO_PI)), 64)
    >>> _kept_lines(fam, [1.0]) is None, envelope_terms(fam, d) is not None, _kept_lines(fam, [1.0])
    (True, True, ([0.8414709848078965], [1.0]))
    """
    for grid, terms in list(fam.memo.values()):
        if grid.ndim != 1 or not grid.size:
            continue
        idx = np.minimum(np.searchsorted(grid, angles), grid.size - 1)
        if bool(np.all(grid[idx] == angles)):
            return terms.lam[idx].tolist(), terms.dphi[idx].tolist()
    return None


_EVERY_90TH = np.linspace(0.0, TWO_PI, _DENSE, endpoint=False)[::90].tolist()
"""The samples of the turn :func:`backward_jumps` looks at first (every 90th of :data:`_DENSE`; on floats one at
a time, until the range they span clears every jump: a flat face's breaks all have λ = 0 when the follower
starts and stops at rest, so their jumps, roundoff such as −1.6e-29 mm, need one sample inside a segment)."""


def chord_error(profile_xy: np.ndarray, pitch_dense: np.ndarray, rr: float) -> float:
    """The largest deviation (mm) of a closed roller profile from the exact envelope, measured without the
    envelope itself: every point of the exact inner envelope lies at distance rr from the pitch curve, so
    the error of a vertex or edge midpoint is |distance to the pitch curve − rr| (``pitch_dense``: exact
    pitch points, much denser than the profile; rr = 0 measures a knife edge's profile).
    """
    mid = 0.5 * (profile_xy + np.roll(profile_xy, -1, axis=0))
    pts = shapely.points(np.vstack([profile_xy, mid]))
    ends = np.stack([pitch_dense, np.roll(pitch_dense, -1, axis=0)], axis=1)
    pieces = shapely.linestrings(ends)                  # one short segment each: the nearest is found by a tree
    tree = shapely.STRtree(pieces)
    which, _ = tree.query_nearest(pts, return_distance=True, all_matches=False)
    dist = shapely.distance(pts[which[0]], pieces[which[1]])
    return float(np.abs(dist - rr).max())


__all__ = ["PitchCurve", "LineFamily", "Profile", "Extremum", "Corner", "inverted", "curvature", "maximise", "contact_slope",
           "rho_min", "rho_min_concave", "pressure_angle", "pressure_angle_slope", "frame_pressure_angle_slope",
           "inverted_relative", "turn_of", "inverted1", "inverted_relative1", "curvature1", "frame_pressure_angle_slope1",
           "illinois1", "brent_max1", "sign1", "sample_grids", "sample_grid", "envelope_terms", "EnvelopeTerms", "envelope1", "pow1", "atan2_1", "numpy_is_libm", "div1", "corners", "sample_count",
           "roller_profile", "flat_profile", "envelope", "envelope_rho_min", "backward_jumps", "trim_loops", "validate_roller",
           "chord_error", "best_of", "curve_tolerance", "TOLERANCE", "STRICT_TOLERANCE", "TOLERANCE_REL",
           "STRICT_TOLERANCE_REL", "MAX_SAMPLES"]
