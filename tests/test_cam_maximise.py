"""maximise with a slope and its scalar form, all pieces' candidates found at once, against the loop over the
pieces it replaces (written out here as it was): the same candidates in the same order, the same extremum,
on smooth functions, slopes that are roundoff over a stretch (a dwell), slopes with nan, ties and the flat
faces' searches."""
from __future__ import annotations

import math

import numpy as np
import pytest

from geomcon.cam.profile import (FLOOR_REL, SLOPE_NOISE, TWO_PI, Extremum, best_of, illinois1, maximise, sample_grids)


def _loop_maximise(g, pieces, slope, slope1, dense: int = 1440) -> Extremum:
    """maximise's slope branch with slope1 as it was: a loop over the pieces."""
    grids = sample_grids(tuple((float(a), float(b)) for a, b in pieces), dense)
    slopes = np.split(np.asarray(slope(np.concatenate(grids)), dtype=float), np.cumsum([len(d) for d in grids])[:-1].tolist())
    noise = SLOPE_NOISE * max(float(np.nanmax(np.abs(sl), initial=0.0)) for sl in slopes)
    places, lo, hi, flo, fhi, floors = [], [], [], [], [], []
    for (a, b), d, sl in zip(pieces, grids, slopes):
        places += [float(d[0])] if not sl[0] > noise else []
        places += [float(d[-1])] if not sl[-1] < -noise else []
        i = np.nonzero((sl[:-1] > 0.0) & (sl[1:] <= 0.0))[0]
        flat = np.maximum(np.abs(sl[i]), np.abs(sl[i + 1])) <= noise
        places += d[i[flat]].tolist()
        i = i[~flat]
        lo += d[i].tolist()
        hi += d[i + 1].tolist()
        flo += sl[i].tolist()
        fhi += sl[i + 1].tolist()
        floors += [FLOOR_REL * (b - a)] * len(i)
    places += [illinois1(slope1, *bracket) for bracket in zip(lo, hi, flo, fhi, floors)]
    vals = np.asarray(g(np.asarray(places)), dtype=float)
    return best_of([Extremum(float(v), x) for v, x in zip(vals, places)])


def _pieces(rng: np.random.Generator) -> list[tuple[float, float]]:
    cuts = np.sort(rng.uniform(0.0, TWO_PI, int(rng.integers(0, 6))))
    edges = [0.0, *cuts.tolist(), TWO_PI]
    return [(a, b) for a, b in zip(edges, edges[1:]) if b > a]


def _same(a: Extremum, b: Extremum) -> bool:
    return (a.value == b.value or (math.isnan(a.value) and math.isnan(b.value))) and a.delta == b.delta


@pytest.mark.parametrize("seed", range(40))
def test_all_pieces_at_once_equal_the_loop(seed):
    rng = np.random.default_rng(seed)
    k, w, c = rng.uniform(0.5, 6.0, 3), rng.uniform(-3, 3, 3), rng.uniform(-1, 1, 3)
    flat_from, flat_to = np.sort(rng.uniform(0.0, TWO_PI, 2))
    kind = seed % 4

    pcs = _pieces(rng)
    jump = rng.uniform(-2, 2, len(pcs))                        # the slope jumps at the breaks (kinks of g)
    starts = [a for a, _ in pcs]

    def g1(d: float) -> float:
        return sum(ci * math.sin(ki * d + wi) for ki, wi, ci in zip(k, w, c))

    def s1(d: float) -> float:
        v = sum(ci * ki * math.cos(ki * d + wi) for ki, wi, ci in zip(k, w, c))
        v += float(jump[max(0, int(np.searchsorted(starts, d, side="right")) - 1)]) if seed % 8 >= 4 else 0.0
        if kind == 1 and flat_from <= d <= flat_to:            # a dwell: roundoff of either sign
            return math.sin(1e6 * d) * 1e-18
        if kind == 2 and flat_from <= d <= flat_to:            # nan over a stretch
            return math.nan
        if kind == 3:                                          # steps: ties and zeros between samples
            return math.floor(v * 2.0) / 2.0
        return v

    asked: list = []

    def g(d: np.ndarray) -> np.ndarray:
        asked.append(np.asarray(d, dtype=float).tolist())         # the candidates, in their order
        return np.array([g1(x) for x in asked[-1]])

    def slope(d: np.ndarray) -> np.ndarray:
        return np.array([s1(x) for x in np.asarray(d, dtype=float).tolist()])

    for sign in (1.0, -1.0):
        new = maximise(lambda d: sign * g(d), pcs, slope=lambda d: sign * slope(d), slope1=lambda d: sign * s1(d))
        old = _loop_maximise(lambda d: sign * g(d), pcs, lambda d: sign * slope(d), lambda d: sign * s1(d))
        assert _same(new, old) and asked[-1] == asked[-2]
        asked.clear()


def test_flat_faces_searches_equal_the_loop():
    from geomcon.cam.oscillating_flat import FlatArmCam
    from geomcon.cam.program import parse_program
    from geomcon.geometry import Point
    from geomcon.recipes import cam_oscillating_flat as osc_flat
    rng = np.random.default_rng(11)
    for law_r, law_t in (("cycloidal", "uniform"), ("poly345", "cosine"), ("parabolic", "cycloidal")):
        rise = float(rng.uniform(80, 150))
        prog = parse_program([{"kind": "rise", "angle": rise, "law": law_r}, {"kind": "dwell", "angle": 30.0},
                              {"kind": "return", "angle": 100.0, "law": law_t},
                              {"kind": "dwell", "angle": 230.0 - rise}])
        cam = FlatArmCam(100.0, 40.0, 12.0, prog, offset=float(rng.uniform(-8, 8)))
        fam = osc_flat.flat_family(cam)
        A0, inv, tau = Point(0.0, 100.0), -float(cam.sigma), cam.tau

        def place(d):
            return osc_flat.face_place(fam, A0, inv, tau, np.array(d, dtype=float))

        def slope(d):
            return osc_flat.face_place_slope(fam, A0, inv, tau, np.array(d, dtype=float))

        def slope1(d):
            return osc_flat.face_place_slope1(fam, A0, inv, tau, d)

        pcs = fam.pieces()
        assert _same(maximise(place, pcs, slope=slope, slope1=slope1), _loop_maximise(place, pcs, slope, slope1))
        assert _same(maximise(lambda d: -place(d), pcs, slope=lambda d: -slope(d), slope1=lambda d: -slope1(d)),
                     _loop_maximise(lambda d: -place(d), pcs, lambda d: -slope(d), lambda d: -slope1(d)))
