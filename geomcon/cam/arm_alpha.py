"""The construction's search for an arm's largest pressure angle on one segment: every smooth piece of the
segment sampled in one array call, the maxima refined on floats, the candidates valued in one call.

It finds what :meth:`geomcon.cam.oscillating.ArmMotion.segment_max` finds with ``maxima_only`` (the same
samples, the same brackets refined by the same Brent steps, the same candidates compared in the same order,
so the same bits), in three numpy passes a segment instead of three a piece and without remaking the samples
on every call. The analytic twin keeps ``segment_max``, its own search.

Examples
--------
>>> from geomcon.cam.program import parse_program
>>> from geomcon.cam.oscillating import OscillatingCam
>>> prog = parse_program([{"kind": "rise", "angle": 10, "law": "parabolic"}, {"kind": "dwell", "angle": 160},
...                       {"kind": "return", "angle": 10, "law": "parabolic"}, {"kind": "dwell", "angle": 180}])
>>> cam = OscillatingCam(a=150.0, L=132.0, r0=50.0, h=20.0, program=prog)
>>> rise = prog.segments[0]
>>> segment_max_one_pass(rise, 0.0, cam.h, cam.pressure_of, cam.tan_slope, cam._tan_slope1()) == cam.segment_max(
...     "rise", cam.pressure_of, cam.tan_slope, cam._tan_slope1())    # every sign change refined there
True
"""
from __future__ import annotations

import math
from functools import lru_cache
from typing import Callable

import numpy as np

from ..numeric import brent_root
from .oscillating import GRID, ROOT_XTOL, Motion, piece_grid, pieces, segment_motion, segment_motion1
from .program import Segment

Motion1 = tuple[float, float, float, float]


@lru_cache(maxsize=64)
def segment_samples(cuts: tuple[tuple[float, float], ...], n: int = GRID) -> tuple[np.ndarray, tuple[int, ...]]:
    """The samples (fractions of the segment) of every piece in ``cuts`` as :func:`~geomcon.cam.oscillating._roots`
    takes them (``n`` from each piece's start to just below its end, denser towards both ends), concatenated
    in one read-only array, and the index where each piece's samples end (made once for the same pieces).

    >>> xs, ends = segment_samples(((0.0, 0.5), (0.5, 1.0)))
    >>> ends, float(xs[0]), float(xs[ends[0]]), xs.flags.writeable
    ((254, 508), 0.0, 0.5, False)
    """
    parts = []
    for x0, x1 in cuts:
        near = (x1 - x0) * np.logspace(-9.0, -3.0, 7)
        parts.append(np.unique(np.concatenate([piece_grid(x0, x1, n), x0 + near, np.nextafter(x1, x0) - near])))
    xs = np.concatenate(parts)
    xs.flags.writeable = False
    return xs, tuple(np.cumsum([p.size for p in parts]).tolist())


def segment_max_one_pass(seg: Segment, level: float, h: float, g: Callable[[Motion], np.ndarray],
                         slope: Callable[[Motion], np.ndarray], slope1: Callable[[Motion1], float]
                         ) -> tuple[float, float]:
    """(max of ``g``, δ in degrees) over the segment ``seg`` (ψ = ``level`` deg at its start, stroke ``h``
    deg): the ends of each smooth piece and, inside, the places where ``slope`` (with the exact sign of
    dg/dδ) turns from + to −, refined by Brent's method on ``slope1`` (the slope of one motion of
    :func:`~geomcon.cam.oscillating.segment_motion1`). Ties (within 1e-13) go to the smaller cam angle, the candidates compared piece by piece as
    :meth:`~geomcon.cam.oscillating.ArmMotion.segment_max` compares them."""
    cuts = pieces(seg)
    xs, ends = segment_samples(cuts)
    s = slope(segment_motion(seg, level, h, xs))
    down = (s[:-1] > 0) & (s[1:] < 0)
    down[[e - 1 for e in ends[:-1]]] = False                  # not across the end of a piece
    idx = np.nonzero(down)[0]
    owner = np.searchsorted(np.asarray(ends), idx, side="right").tolist()
    found: list[list[float]] = [[] for _ in cuts]

    def fn1(x: float) -> float:
        return slope1(segment_motion1(seg, level, h, x))

    for k, a, b, ga, gb in zip(owner, xs[idx].tolist(), xs[idx + 1].tolist(), s[idx].tolist(), s[idx + 1].tolist()):
        found[k].append(brent_root(fn1, a, b, ga, gb, xtol=ROOT_XTOL))
    cands = [x for (x0, x1), roots in zip(cuts, found) for x in roots + [x0, x1]]
    m = segment_motion(seg, level, h, cands)
    best = (-math.inf, 0.0)
    for a, delta in zip(g(m), np.degrees(m.delta)):
        if a > best[0] + 1e-13 or (abs(a - best[0]) <= 1e-13 and delta < best[1]):
            best = (float(a), float(delta))
    return best
