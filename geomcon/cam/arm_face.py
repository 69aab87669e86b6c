"""The construction's searches of a flat-faced arm's contact along its face (``cam.oscillating`` with
``follower = "flat"``): the place l of the contact K on the envelope of the face lines, measured from the
pivot's foot along the arm's direction, and its slope l′, on arrays and on floats; the nearest and the
farthest contact over the turn or over a segment.

The construction asks four such searches of one family of face lines: the nearest and the farthest over the
turn (the face length), the nearest over the rise and over the return (the largest pressure angles).
They share what they compute (:class:`FaceSamples`, kept on the family, :class:`FaceFamily`): l and l′ on
the turn's samples, of which a segment's samples (taken as densely) are a run; l′ on floats at every angle a
refinement tried (the rise's nearest contact is refined on the very bracket the turn's was, by the same
steps: they are looked up); l at every place valued. Each search finds what it found alone, bit for bit
(``tests/test_cam_flat_shared.py`` against the searches with nothing shared). The analytic twin is
:mod:`geomcon.cam.oscillating_flat` (closed forms; it shares nothing with these searches).

Examples
--------
>>> from geomcon.cam.oscillating_flat import FlatArmCam
>>> from geomcon.cam.program import parse_program
>>> from geomcon.geometry import Point
>>> prog = parse_program([{"kind": "rise", "angle": 120, "law": "poly345"}, {"kind": "dwell", "angle": 60},
...                       {"kind": "return", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60}])
>>> cam = FlatArmCam(120.0, 50.0, 15.0, prog, offset=10.0)
>>> fam = flat_family(cam)
>>> lo, hi = face_extremes(fam, Point(0.0, 120.0), -1.0, cam.tau)
>>> round(lo.value, 9), round(math.degrees(lo.delta), 6), round(hi.value, 9)
(75.240689154, 75.343247, 128.399116653)
>>> face_nearest(fam, Point(0.0, 120.0), -1.0, cam.tau, prog.rise) == lo     # the same bracket, looked up
True
>>> round(float(cam.contact(math.degrees(lo.delta))), 9)                        # the twin's closed form
75.240689154
"""
from __future__ import annotations

import math
from bisect import bisect_right
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any, Callable

import numpy as np

from ..geometry import Point
from .oscillating_flat import END_TIE, FlatArmCam
from .profile import (_DENSE, FLOOR_REL, PRUNE_GAIN, PRUNE_REL, SLOPE_NOISE, Extremum, LineFamily, _best_of_pairs,
                      _rest_grids, div1, envelope, envelope1, envelope_terms, illinois1, maximise, pow1, sample_grid,
                      sample_grids)


@dataclass(frozen=True)
class FaceFamily(LineFamily):
    """The face lines of a flat-faced arm in their inverted positions (a :class:`~geomcon.cam.profile.LineFamily`)
    with what the searches of the contact along the face share: a :class:`FaceSamples` per pivot position
    (:func:`face_samples`)."""

    shared: dict = field(default_factory=dict, compare=False, repr=False)


def flat_family(cam: FlatArmCam) -> FaceFamily:
    """The face in its inverted positions as lines X·n = p: normal angle β = θA + τ(φ − 90°) (θA = 90° − σδ the
    polar angle of A0′), p = a sin φ − f, exact derivatives from the motion."""

    last: list = [None, None]                  # the last angles and their lines (a search asks twice)

    def fn(d):
        if last[0] is not None and last[0].shape == np.shape(d) and np.array_equal(last[0], d):
            return last[1]
        m = cam.motion_rad(d)
        phi = cam.psi0 + m.psi
        c, s = np.cos(phi), np.sin(phi)
        out = (math.pi / 2 - cam.sigma * d + cam.tau * (phi - math.pi / 2), -cam.sigma + cam.tau * m.d1,
               cam.tau * m.d2, cam.a * s - cam.offset, cam.a * c * m.d1, cam.a * (c * m.d2 - s * m.d1 ** 2))
        last[0], last[1] = np.array(d, dtype=float), out
        return out

    psi0, sigma, tau, a, f = cam.psi0, cam.sigma, cam.tau, cam.a, cam.offset
    motion1, h, rad, half_pi = cam.program.motion1, cam.h, math.radians, math.pi / 2

    seen: dict[float, tuple] = {}            # every angle's lines once (the pressure angle and the contact
                                               # at `at`, a refined place and its value, ask for the same)

    def fn1(d):                                # the same on one float (the same bits; ψ′² as a product)
        out = seen.get(d)
        if out is not None:
            return out
        sv, v, acc = motion1(h, d, True)
        psi, d1, d2 = rad(sv), rad(v), rad(acc)
        phi = psi0 + psi
        c, s = math.cos(phi), math.sin(phi)
        out = seen[d] = (half_pi - sigma * d + tau * (phi - half_pi), -sigma + tau * d1, tau * d2, a * s - f,
                         a * c * d1, a * (c * d2 - s * (d1 * d1)))
        return out

    return FaceFamily(fn, cam.breaks(), fn1, still=cam.rests())


def _pivot_path(A0: Point, inv: float, d: np.ndarray) -> tuple[np.ndarray, ...]:
    """A0′ = A0 turned by inv·δ about O (the origin) and its derivative by δ."""
    c, s = np.cos(inv * d), np.sin(inv * d)
    x, y = c * A0.x - s * A0.y, s * A0.x + c * A0.y
    return x, y, -inv * y, inv * x


def face_place(fam: LineFamily, A0: Point, inv: float, tau: int, d) -> np.ndarray:
    """The contact's place along the face, measured on the envelope: (K − A0′)·u, u = −τ·(−sin β, cos β) the
    arm's direction along the face (δ in radians)."""
    d = np.asarray(d, dtype=float)
    x, y = envelope(fam, d)[:2]
    beta = fam.eval(d)[0]
    ax, ay = _pivot_path(A0, inv, d)[:2]
    return (x - ax) * tau * np.sin(beta) - (y - ay) * tau * np.cos(beta)


def face_place_slope(fam: LineFamily, A0: Point, inv: float, tau: int, d) -> np.ndarray:
    """d/dδ of :func:`face_place` from the envelope: K slides along the face at ρ·β′ (t·u = −τ), u turns at β′
    (u′ = β′·τ·n), A0′ moves: l′ = −τρβ′ + τβ′(K − A0′)·n − A0′′·u."""
    return face_place_and_slope(fam, A0, inv, tau, d)[1]


def face_place_and_slope(fam: LineFamily, A0: Point, inv: float, tau: int, d) -> tuple[np.ndarray, np.ndarray]:
    """(:func:`face_place`, :func:`face_place_slope`) at ``d`` from one evaluation of the envelope's terms
    (:func:`~geomcon.cam.profile.envelope_terms`, kept on the family for a search's samples), each by its own
    operations (the same bits as either alone).

    >>> from geomcon.cam.oscillating_flat import FlatArmCam
    >>> from geomcon.cam.program import parse_program
    >>> prog = parse_program([{"kind": "rise", "angle": 150, "law": "cycloidal"}, {"kind": "dwell", "angle": 30},
    ...                       {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60}])
    >>> fam = flat_family(FlatArmCam(100.0, 40.0, 15.0, prog))
    >>> d = np.linspace(0.1, 6.2, 40)
    >>> l, dl = face_place_and_slope(fam, Point(0.0, 100.0), -1.0, -1, d)
    >>> l.tolist() == face_place(fam, Point(0.0, 100.0), -1.0, -1, d).tolist()
    True
    """
    d = np.asarray(d, dtype=float)
    t = envelope_terms(fam, d)
    c, s, x, y, db = t.c, t.s, t.x, t.y, t.dphi
    ax, ay, vx, vy = _pivot_path(A0, inv, d)
    dx, dy = x - ax, y - ay                     # (K − A0′, once for both: the same numbers)
    place = dx * tau * s - dy * tau * c
    return place, -tau * t.rho * db + tau * db * (dx * c + dy * s) - tau * (vx * s - vy * c)


def _pivot_path1(A0: Point, inv: float, d: float) -> tuple[float, float, float, float]:
    """:func:`_pivot_path` at one cam angle, on floats (the same bits)."""
    c, s = math.cos(inv * d), math.sin(inv * d)
    x, y = c * A0.x - s * A0.y, s * A0.x + c * A0.y
    return x, y, -inv * y, inv * x


def face_place1(fam: LineFamily, A0: Point, inv: float, tau: int, d: float) -> float:
    """:func:`face_place` at one cam angle, on floats, from the family's scalar form (the same bits)."""
    f6 = fam.fn1(d)
    x, y = envelope1(f6)[:2]
    beta = f6[0]
    ax, ay = _pivot_path1(A0, inv, d)[:2]
    return (x - ax) * tau * math.sin(beta) - (y - ay) * tau * math.cos(beta)


def face_place_slope1(fam: LineFamily, A0: Point, inv: float, tau: int, d: float) -> float:
    """:func:`face_place_slope` at one cam angle, on floats, from the family's scalar form (the same bits).

    >>> from geomcon.cam.oscillating_flat import FlatArmCam
    >>> from geomcon.cam.program import parse_program
    >>> prog = parse_program([{"kind": "rise", "angle": 150, "law": "cycloidal"}, {"kind": "dwell", "angle": 30},
    ...                       {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60}])
    >>> fam = flat_family(FlatArmCam(100.0, 40.0, 15.0, prog))
    >>> d = np.array([0.4, 1.9, 3.7])
    >>> vec = face_place_slope(fam, Point(0.0, 100.0), -1.0, -1, d)
    >>> [face_place_slope1(fam, Point(0.0, 100.0), -1.0, -1, x) for x in d.tolist()] == vec.tolist()
    True
    """
    f6 = fam.fn1(d)
    x, y, _, rho = envelope1(f6)
    beta, db = f6[0], f6[1]
    ax, ay, vx, vy = _pivot_path1(A0, inv, d)
    c, s = math.cos(beta), math.sin(beta)
    return -tau * rho * db + tau * db * ((x - ax) * c + (y - ay) * s) - tau * (vx * s - vy * c)


def _segment_pieces(fam: LineFamily, seg: Any, pieces: list[tuple[float, float]] | None = None
                    ) -> list[tuple[float, float]]:
    """The smooth pieces of the turn (``pieces``, default the family's) that make up the segment ``seg``."""
    lo, hi = math.radians(seg.start), math.radians(seg.end)
    return [(a, b) for a, b in (fam.pieces() if pieces is None else pieces) if a >= lo - 1e-12 and b <= hi + 1e-12]


def face_extremes(fam: LineFamily, A0: Point, inv: float, tau: int, seg: Any = None) -> tuple[Extremum, Extremum]:
    """(nearest, farthest) place of the contact along the face over a segment (default: the turn)."""
    search = _FaceSearch(fam, A0, inv, tau, seg)
    return search.nearest(), search.farthest()


def face_nearest(fam: LineFamily, A0: Point, inv: float, tau: int, seg: Any) -> Extremum:
    """The nearest place of the contact along the face over a segment (the largest α = atan(|f|/l)): the
    first of :func:`face_extremes` without searching the farthest, which a segment's α does not need."""
    return _FaceSearch(fam, A0, inv, tau, seg).nearest()


def face_samples(fam: LineFamily, A0: Point, inv: float, tau: int) -> "FaceSamples":
    """The :class:`FaceSamples` of ``fam`` with the pivot at ``A0`` (turning by ``inv``·δ, arm sense ``tau``):
    made once and kept on a :class:`FaceFamily`, so that every search of the family shares it; a plain
    family gets a new one (nothing shared)."""
    shared = getattr(fam, "shared", None)
    if shared is None:
        return FaceSamples(fam, A0, inv, tau)
    key = (A0.x, A0.y, inv, tau)
    found = shared.get(key)
    if found is None:
        found = shared[key] = FaceSamples(fam, A0, inv, tau)
    return found


def face_slope1(fam: LineFamily, A0: Point, inv: float, tau: int) -> Callable[[float], float]:
    """:func:`face_place_slope1` with envelope1 and the pivot's path written out (the same operations in the
    same order: the same bits, a third fewer calls); ``fam`` must have its scalar form ``fn1``."""
    fn1, x0, y0 = fam.fn1, A0.x, A0.y
    cos, sin = math.cos, math.sin

    def slope1(d: float) -> float:
        beta, db, ddb, p, dp, ddp = fn1(d)
        lam = dp / db if db != 0.0 else div1(dp, db)
        rho = p + div1(ddp * db - dp * ddb, pow1(db, 3.0))
        c, s = cos(beta), sin(beta)
        x, y = p * c - lam * s, p * s + lam * c
        ci, si = cos(inv * d), sin(inv * d)
        ax, ay = ci * x0 - si * y0, si * x0 + ci * y0
        vx, vy = -inv * ay, inv * ax
        return -tau * rho * db + tau * db * ((x - ax) * c + (y - ay) * s) - tau * (vx * s - vy * c)

    return slope1


class FaceSamples:
    """What the searches of the contact's place along the face of one family share (see the module
    docstring): l and l′ on the kept sample arrays (read-only, owning their numbers, increasing: the searches'
    :func:`~geomcon.cam.profile.sample_grid`), the first computed, a later one that is a run of a kept one cut
    from it (each term is elementwise: the cut holds the numbers computing them there gives); l′ on floats at
    every angle tried; l at every place valued (a kept sample's value, else on floats, else by the array
    form: the same bits).

    >>> from geomcon.cam.oscillating_flat import FlatArmCam
    >>> from geomcon.cam.profile import sample_grid
    >>> from geomcon.cam.program import parse_program
    >>> prog = parse_program([{"kind": "rise", "angle": 150, "law": "cycloidal"}, {"kind": "dwell", "angle": 30},
    ...                       {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60}])
    >>> fam = flat_family(FlatArmCam(100.0, 40.0, 15.0, prog))
    >>> s = face_samples(fam, Point(0.0, 100.0), -1.0, -1)
    >>> s is face_samples(fam, Point(0.0, 100.0), -1.0, -1)
    True
    >>> turn = sample_grid(tuple(fam.pieces()), 1440)
    >>> rise = sample_grid(tuple(fam.pieces()[:1]), 1440, sum(b - a for a, b in fam.pieces()))
    >>> l, dl = s.arrays(turn)
    >>> alone = face_place_and_slope(fam, Point(0.0, 100.0), -1.0, -1, np.array(rise))[1]
    >>> s.arrays(rise)[1].tolist() == dl[:rise.size].tolist() == alone.tolist()
    True
    >>> s.place1(0.4) == face_place1(fam, Point(0.0, 100.0), -1.0, -1, 0.4)
    True
    >>> s.place1(float(turn[7])) == float(l[7])
    True
    """

    def __init__(self, fam: LineFamily, A0: Point, inv: float, tau: int) -> None:
        self.fam, self.A0, self.inv, self.tau = fam, A0, inv, tau
        self.scalar = fam.fn1 is not None
        self._kept: list[tuple[np.ndarray, np.ndarray, np.ndarray]] = []     # (samples, l, l′)
        self._slopes: dict[float, float] = {}
        self._places: dict[float, float] = {}
        self._raw1 = face_slope1(fam, A0, inv, tau) if self.scalar else None
        self._turn_slopes: _TurnSlopes | None = None
        self.pieces = fam.pieces()
        """The smooth pieces of the turn."""
        self.turn = sum(b - a for a, b in self.pieces)
        """Their total length (radians), over which a segment's samples are spread."""

    def arrays(self, d: np.ndarray, ordered: bool = False) -> tuple[np.ndarray, np.ndarray]:
        """(l, l′) at the samples ``d`` (radians; ``ordered``: known to increase, a search's samples)."""
        for grid, pl, sl in self._kept:
            if grid is d:
                return pl, sl
        keep = type(d) is np.ndarray and d.ndim == 1 and d.size > 1 and not d.flags.writeable and d.base is None
        if keep:
            n, first = d.size, d[0]
            for grid, pl, sl in self._kept:
                i = int(grid.searchsorted(first))
                if i + n <= grid.size and grid[i] == first and np.array_equal(grid[i:i + n], d):
                    out = (pl[i:i + n], sl[i:i + n])
                    self._kept.append((d, *out))
                    return out
        pl, sl = face_place_and_slope(self.fam, self.A0, self.inv, self.tau, d)
        if keep and (ordered or bool(np.all(d[1:] > d[:-1]))):
            self._kept.append((d, pl, sl))
        return pl, sl

    def slope(self, d: np.ndarray) -> np.ndarray:
        """l′ at the samples ``d``."""
        return self.arrays(d)[1]

    def slope1(self, sign: float) -> Callable[[float], float]:
        """``sign``·l′ at one cam angle on floats (:func:`face_slope1`), each angle computed once."""
        memo, raw = self._slopes, self._raw1

        def fn(d: float) -> float:
            v = memo.get(d)
            if v is None:
                v = memo[d] = raw(d)
            return sign * v

        return fn

    def _turn(self) -> "_TurnSlopes":
        """The turn's samples as :func:`~geomcon.cam.profile.maximise` takes them for a search over the whole
        turn (a dwell's piece cut to its ends), l′ there and what the searches read of it, made once."""
        if self._turn_slopes is None:
            key = tuple((float(a), float(b)) for a, b in self.pieces)
            grids, grid = _grids(key, self.fam.still, None)
            self._turn_slopes = _TurnSlopes(key, grids, grid, *self.arrays(grid, ordered=True))
        return self._turn_slopes

    def extreme(self, pcs: list[tuple[float, float]], sign: float, turn: float | None = None) -> Extremum:
        """The largest ``sign``·l over the pieces ``pcs`` and where: what :func:`~geomcon.cam.profile.maximise`
        finds with the slope ``sign``·l′, its scalar form and l on floats (``turn``: the pieces sampled as
        densely as that angle), by the same steps on the same samples — the ends of each piece unless the
        slope leads into it, the samples where a slope that is roundoff changes sign, and the + → − sign
        changes refined by :func:`~geomcon.cam.profile.illinois1`, compared by the same rule — found on the
        turn's l′, computed once for the four searches (a segment's samples are a run of the turn's).

        One step less: a sign change whose bracket [lo, hi] cannot rise to within
        :data:`~geomcon.cam.profile.PRUNE_REL` of the best candidate found so far — its ends' values plus
        :data:`~geomcon.cam.profile.PRUNE_GAIN` times the largest sampled |l′| times hi − lo stay below; the
        brackets are refined highest reach first — is not refined (as :func:`~geomcon.cam.profile.maximise`
        prunes the sampled peaks it refines without a slope). Such a candidate is below the tie rule's reach
        (TIE_REL ≪ PRUNE_REL), so the result is the same; it saves the refinements of roundoff, such as the
        sign change a sample or two from the start of a law that leaves rest (l′ ∝ δ there; 200-07's farthest
        contact: 14 scalar slopes).

        >>> from geomcon.cam.oscillating_flat import FlatArmCam
        >>> from geomcon.cam.program import parse_program
        >>> prog = parse_program([{"kind": "rise", "angle": 150, "law": "parabolic"}, {"kind": "dwell", "angle": 30},
        ...                       {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60}])
        >>> fam = flat_family(FlatArmCam(100.0, 40.0, 15.0, prog, offset=4.0))
        >>> s = face_samples(fam, Point(0.0, 100.0), -1.0, -1)
        >>> kw = dict(slope=lambda d: -s.slope(d), slope1=s.slope1(-1.0), still=fam.still)
        >>> s.extreme(fam.pieces(), -1.0) == maximise(lambda d: -s.place(d), fam.pieces(), **kw)
        True
        """
        key = tuple((float(a), float(b)) for a, b in pcs)
        base = self._turn()
        grids, grid = _grids(key, self.fam.still, turn)
        at = _run_at(base.key, key, self.fam.still, turn)
        if at is None:                                  # not a run of the turn's samples: the general search
            return maximise(lambda d: sign * self.place(d), pcs, slope=lambda d: sign * self.slope(d),
                            slope1=self.slope1(sign), g1=lambda x: sign * self.place1(x), turn=turn,
                            still=self.fam.still)
        sl, xs, pl = base.sl, base.grid, base.pl
        n = sum(len(d) for d in grids)
        top = max(0.0, base.top(at, at + n))              # the largest |l′| of the samples
        noise = SLOPE_NOISE * top
        firsts, j = [], at
        for d in grids:
            firsts.append(j)
            j += len(d)
        lasts = [f + len(d) - 1 for f, d in zip(firsts, grids)]
        changes = base.rising if sign > 0.0 else base.falling    # + → − of sign·l′, with the pair's larger |l′|
        at_samples: list[int] = []                                    # candidates that are samples (their l kept)
        roots: list[tuple[int, int]] = []
        for k, (f, last) in enumerate(zip(firsts, lasts)):
            if not sign * float(sl[f]) > noise:
                at_samples.append(f)
            if not sign * float(sl[last]) < -noise:
                at_samples.append(last)
            for i, size in changes.get(base.piece_of(f), ()):
                if f <= i < last:
                    if size <= noise:                  # roundoff (a dwell): the sample stands
                        at_samples.append(i)
                    else:
                        roots.append((i, k))
        places = xs[at_samples].tolist()
        values = [sign * v for v in pl[at_samples].tolist()]
        if roots:
            slope1, place1 = self.slope1(sign), self.place1
            best = max((v for v in values if v == v), default=math.nan)
            floor = best - PRUNE_REL * abs(best)
            rise = PRUNE_GAIN * top
            reach = []                                  # how high each bracket can rise
            for i, k in roots:
                lo, hi = float(xs[i]), float(xs[i + 1])
                reach.append(max(sign * float(pl[i]), sign * float(pl[i + 1])) + rise * (hi - lo))
            found: dict[int, tuple[float, float]] = {}
            for n in sorted(range(len(roots)), key=lambda n: -reach[n] if reach[n] == reach[n] else math.inf):
                if reach[n] < floor:
                    continue                        # cannot come near the best candidate: not refined
                i, k = roots[n]
                a, b = key[k]
                x = illinois1(slope1, float(xs[i]), float(xs[i + 1]), sign * float(sl[i]), sign * float(sl[i + 1]),
                              FLOOR_REL * (b - a))
                v = sign * place1(x)
                found[n] = (x, v)
                if v == v and not v <= best:
                    best = v
                    floor = best - PRUNE_REL * abs(best)
            for n in sorted(found):                     # in the order of the sign changes, as maximise lists them
                places.append(found[n][0])
                values.append(found[n][1])
        return _best_of_pairs(values, places)

    def _known(self, x: float) -> float | None:
        v = self._places.get(x)
        if v is None:
            for grid, pl, _ in self._kept:
                i = int(grid.searchsorted(x))
                if i < grid.size and grid[i] == x:
                    v = self._places[x] = float(pl[i])
                    break
        return v

    def place1(self, x: float) -> float:
        """l at one cam angle (radians): a kept sample's value, else on floats (the same bits), once."""
        v = self._known(x)
        if v is None:
            v = face_place1(self.fam, self.A0, self.inv, self.tau, x) if self.scalar else \
                float(face_place(self.fam, self.A0, self.inv, self.tau, np.array([x]))[0])
            self._places[x] = v
        return v

    def place(self, d: np.ndarray) -> np.ndarray:
        """l at the cam angles ``d``: :meth:`place1` of each, or the array form for more than 16 not known."""
        d = np.asarray(d, dtype=float)
        xs = d.reshape(-1).tolist()
        vals = [self._known(x) for x in xs]
        rest = [k for k, v in enumerate(vals) if v is None]
        if rest:
            todo = [xs[k] for k in rest]
            if self.scalar and len(todo) <= 16:
                new = [face_place1(self.fam, self.A0, self.inv, self.tau, x) for x in todo]
            else:
                new = face_place(self.fam, self.A0, self.inv, self.tau, np.array(todo)).tolist()
            for k, x, v in zip(rest, todo, new):
                vals[k] = self._places[x] = v
        return np.array(vals, dtype=float).reshape(d.shape)


@lru_cache(maxsize=256)
def _grids(key: tuple[tuple[float, float], ...], still: tuple[tuple[float, float], ...], turn: float | None
           ) -> tuple[tuple[np.ndarray, ...], np.ndarray]:
    """The samples of each piece and all of them in one array, as :func:`~geomcon.cam.profile.maximise`'s
    scalar paths take them (the same read-only arrays: they are made once)."""
    rests = tuple(any(s0 <= 0.5 * (a + b) <= s1 for s0, s1 in still) for a, b in key)
    if any(rests):
        return _rest_grids(key, rests, _DENSE, turn)
    return sample_grids(key, _DENSE, turn), sample_grid(key, _DENSE, turn)


@lru_cache(maxsize=256)
def _run_at(turn_key: tuple[tuple[float, float], ...], key: tuple[tuple[float, float], ...],
            still: tuple[tuple[float, float], ...], turn: float | None) -> int | None:
    """Where the samples of the pieces ``key`` (spread as densely as ``turn``) start as a run of whole pieces
    of the samples of the turn's pieces ``turn_key``, or None: a function of the pieces alone (both sample
    arrays are :func:`_grids`', made from them), found once per pair (a search over a segment reads its l′
    off the turn's).

    >>> pcs = ((0.0, 1.0), (1.0, 3.0), (3.0, 6.0))
    >>> _run_at(pcs, pcs, (), None), _run_at(pcs, pcs[1:2], (), 6.0), _run_at(pcs, ((0.5, 1.0),), (), 6.0)
    (0, 257, None)
    """
    grids, grid = _grids(turn_key, still, None)
    seg = _grids(key, still, turn)[1]
    if seg is grid:
        return 0
    firsts = np.cumsum([0] + [len(d) for d in grids][:-1]).tolist()
    n, first = seg.size, float(seg[0])
    i = int(grid.searchsorted(first))
    return i if i in firsts and i + n <= grid.size and np.array_equal(grid[i:i + n], seg) else None


class _TurnSlopes:
    """l and l′ on the turn's samples, each piece's first sample, and every place where l′ changes sign between
    neighbouring samples of a piece (+ → − and − → +), with the larger |l′| of the two: what a search reads
    (a few numpy passes; the few places read one by one)."""

    def __init__(self, key: tuple[tuple[float, float], ...], grids: tuple[np.ndarray, ...], grid: np.ndarray,
                 pl: np.ndarray, sl: np.ndarray) -> None:
        self.key, self.grid, self.pl, self.sl = key, grid, pl, sl
        """The turn's pieces (the key of its samples, :func:`_grids`), its samples, l and l′ there."""
        sizes = [len(d) for d in grids]
        self.firsts = np.cumsum([0] + sizes[:-1]).tolist()
        self.rising: dict[int, list[tuple[int, float]]] = {}
        self.falling: dict[int, list[tuple[int, float]]] = {}
        sign = np.sign(sl)                               # (nan where l′ is: such a pair is neither below)
        for i in np.flatnonzero(sign[1:] != sign[:-1]).tolist():
            a, b = float(sl[i]), float(sl[i + 1])
            if a > 0.0 and b <= 0.0:
                self.rising.setdefault(self.piece_of(i), []).append((i, max(abs(a), abs(b))))
            elif a < 0.0 and b >= 0.0:
                self.falling.setdefault(self.piece_of(i), []).append((i, max(abs(a), abs(b))))
        self._abs: np.ndarray | None = None
        self._tops: dict[tuple[int, int], float] = {}

    def piece_of(self, i: int) -> int:
        """The piece of the turn holding sample ``i``."""
        return bisect_right(self.firsts, i) - 1

    def top(self, i0: int, i1: int) -> float:
        """The largest |l′| of samples i0 … i1 − 1 (nan ignored; 0 if none)."""
        key = (i0, i1)
        v = self._tops.get(key)
        if v is None:
            if self._abs is None:
                self._abs = np.abs(self.sl)
            v = self._tops[key] = float(np.fmax.reduce(self._abs[i0:i1], initial=0.0))    # (np.nanmax's own)
        return v


class _FaceSearch:
    """The searches of the contact's place along the face over a segment or the turn (what they compute
    shared by :func:`face_samples`)."""

    def __init__(self, fam: LineFamily, A0: Point, inv: float, tau: int, seg: Any) -> None:
        self.fam, self.A0, self.inv, self.tau, self.seg = fam, A0, inv, tau, seg
        self.samples = face_samples(fam, A0, inv, tau)
        self.pcs = self.samples.pieces if seg is None else _segment_pieces(fam, seg, self.samples.pieces)
        self.turn = None if seg is None else self.samples.turn
        """A segment is sampled as densely as the turn (its samples are then a run of the turn search's)."""
        self.scalar = fam.fn1 is not None

    def place(self, d: np.ndarray) -> np.ndarray:
        """l at ``d`` (:meth:`FaceSamples.place`)."""
        return self.samples.place(d)

    def slope(self, d: np.ndarray) -> np.ndarray:
        """l′ at the samples ``d`` (:meth:`FaceSamples.slope`)."""
        return self.samples.slope(d)

    def _slope1(self, sign: float) -> Callable[[float], float] | None:
        """sign·:func:`face_place_slope1` on floats (:meth:`FaceSamples.slope1`), or None without ``fn1``."""
        return self.samples.slope1(sign) if self.scalar else None

    def farthest(self) -> Extremum:
        s = self.samples
        if self.scalar:
            return s.extreme(self.pcs, 1.0)
        return maximise(s.place, self.pcs, slope=s.slope, still=self.fam.still)

    def nearest(self) -> Extremum:
        s = self.samples
        if self.scalar:
            lo = s.extreme(self.pcs, -1.0, self.turn)
        else:
            lo = maximise(lambda d: -s.place(d), self.pcs, slope=lambda d: -s.slope(d), turn=self.turn,
                          still=self.fam.still)
        if self.seg is not None:            # a minimum as flat as roundoff at an end of the segment: the end
            pcs = self.pcs
            for d in (pcs[0][0], math.nextafter(pcs[-1][1], pcs[-1][0])):
                lv = s.place1(d)
                if lv <= -lo.value + END_TIE * self.A0.y:
                    lo = Extremum(-lv, d)
                    break
        return Extremum(-lo.value, lo.delta)
