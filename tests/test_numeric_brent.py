"""geomcon.numeric.brent_root (Brent's zeroin, scipy.optimize.brentq's algorithm, written here): roots to the
last units against 50-digit mpmath references, the brackets' ends, flat (multiple) roots, sign conventions,
refusals, and its use for extrema: the maxima of cams turning either way, at the ends of a segment and flat."""
from __future__ import annotations

import math
import random

import mpmath
import pytest

from geomcon.numeric import brent_root

mpmath.mp.dps = 50


def _counted(f):
    calls = []

    def g(x):
        calls.append(x)
        return f(x)
    return g, calls


@pytest.mark.parametrize("f, mf, a, b", [
    (math.cos, mpmath.cos, 1.0, 2.0),
    (lambda x: x ** 3 - 2.0, lambda x: x ** 3 - 2, 0.0, 2.0),
    (lambda x: math.exp(x) - 10.0, lambda x: mpmath.exp(x) - 10, 0.0, 5.0),
    (lambda x: math.tan(x) - x, lambda x: mpmath.tan(x) - x, 4.0, 4.6),
    (lambda x: x * math.exp(-x) - 0.1, lambda x: x * mpmath.exp(-x) - mpmath.mpf("0.1"), 0.0, 1.0),
])
def test_roots_to_the_last_units_in_few_calls(f, mf, a, b):
    g, calls = _counted(f)
    x = brent_root(g, a, b)
    ref = mpmath.findroot(mf, (a + b) / 2 if f is not math.cos else 1.5)
    assert abs(mpmath.mpf(x) - ref) <= 4 * math.ulp(float(ref)), (x, ref)
    assert len(calls) <= 14
    assert brent_root(f, b, a) == pytest.approx(x, abs=4 * math.ulp(x))     # either order of the ends


def test_given_end_values_are_not_computed_again():
    g, calls = _counted(math.cos)
    brent_root(g, 1.0, 2.0, math.cos(1.0), math.cos(2.0))
    assert 1.0 not in calls and 2.0 not in calls


def test_a_root_at_an_end_is_that_end():
    assert brent_root(lambda x: x - 1.0, 1.0, 3.0) == 1.0
    assert brent_root(lambda x: x - 3.0, 1.0, 3.0) == 3.0


def test_no_bracket_is_refused():
    with pytest.raises(ValueError, match="no sign change"):
        brent_root(lambda x: x * x + 1.0, -1.0, 1.0)


def test_flat_and_multiple_roots_end_within_the_tolerance():
    """A triple root (f ~ x³: flat) and a function that is 0 only at one float: the bracket closes anyway."""
    g, calls = _counted(lambda x: (x - 0.3) ** 3)
    x = brent_root(g, 0.0, 1.0, xtol=1e-13)
    assert abs(x - 0.3) <= 1e-13 and len(calls) <= 3 * 45          # at worst three steps per halving
    step = brent_root(lambda x: -1.0 if x < 0.7 else 1.0, 0.0, 1.0)  # a jump: the place of the jump
    assert abs(step - 0.7) <= 4 * math.ulp(0.7)


def test_absolute_tolerance_stops_early():
    g, calls = _counted(math.cos)
    x = brent_root(g, 1.0, 2.0, xtol=1e-3, rtol=0.0)
    assert abs(x - math.pi / 2) < 1e-3
    many = len(calls)
    calls.clear()
    brent_root(g, 1.0, 2.0)
    assert many <= len(calls)


@pytest.mark.parametrize("seed", range(30))
def test_random_cubics_against_mpmath(seed):
    rng = random.Random(seed)
    r = rng.uniform(-10, 10)
    c1, c2 = rng.uniform(-5, 5), rng.uniform(0.1, 5)

    def f(x):
        return (x - r) * ((x - c1) ** 2 + c2)
    x = brent_root(f, r - rng.uniform(0.1, 20), r + rng.uniform(0.1, 20))
    assert abs(x - r) <= 8 * math.ulp(r) + 1e-300


# ---------------------------------------------------------------------------------------- extrema by the slope
def _max_by_slope(g, slope, lo, hi, n=64):
    """The largest g on [lo, hi]: the ends and every root of the slope (grid + Brent)."""
    xs = [lo + (hi - lo) * i / n for i in range(n + 1)]
    cands = [lo, hi]
    for a, b in zip(xs, xs[1:]):
        sa, sb = slope(a), slope(b)
        if sa == 0.0:
            cands.append(a)
        elif sb != 0.0 and (sa > 0.0) != (sb > 0.0):
            cands.append(brent_root(slope, a, b, sa, sb))
    return max(cands, key=g)


def test_extremum_at_a_segment_end_and_flat_extremum():
    """sin on [0, 1]: the maximum is the right end (no root inside); the cosine law's f′ = (π/2)·sin πx has
    its flat maximum inside at ½; x⁴ is flat (f′ = 4x³) at its minimum, found as the end 0 of −x⁴."""
    assert _max_by_slope(math.sin, math.cos, 0.0, 1.0) == 1.0
    x = _max_by_slope(lambda t: math.pi / 2 * math.sin(math.pi * t), lambda t: math.pi ** 2 / 2 * math.cos(math.pi * t), 0.0, 1.0)
    assert abs(x - 0.5) <= 2 * math.ulp(0.5)
    assert _max_by_slope(lambda t: -t ** 4, lambda t: -4 * t ** 3, 0.0, 1.0) == 0.0


@pytest.mark.parametrize("rotation", ["ccw", "cw"])
def test_eccentric_cam_speed_maxima_both_senses(rotation):
    """A translating roller on an eccentric disc, turning either way: the largest |v| and |a| from the
    construction's polygons (grid + Brent) against a 50-digit mpmath search of the exact motion."""
    from geomcon.geometry import Point
    from geomcon.recipes.cam_eccentric_speeds import guide_a_max, guide_v_max
    E, Rp, e, omega = 10.0, 40.0, 7.0, 3.0
    sense = 1.0 if rotation == "ccw" else -1.0
    A = Point(E, 0.0)

    def y(phi):
        return E * mpmath.sin(phi) + mpmath.sqrt(Rp ** 2 - (e - E * mpmath.cos(phi)) ** 2)

    def ref(k):
        d = lambda p: mpmath.diff(y, p, k)            # noqa: E731
        best = 0
        for i in range(72):
            lo, hi = 2 * mpmath.pi * i / 72, 2 * mpmath.pi * (i + 1) / 72
            dl, dh = mpmath.diff(y, lo, k + 1), mpmath.diff(y, hi, k + 1)
            if dl * dh < 0:
                best = max(best, abs(d(mpmath.findroot(lambda p: mpmath.diff(y, p, k + 1), (lo, hi), solver="anderson"))))
        return float(best * omega ** k)
    assert guide_v_max(A, Point(e, 0.0), Rp, False, Rp, sense, omega) == pytest.approx(ref(1), rel=1e-13)
    assert guide_a_max(A, Point(e, 0.0), Rp, False, Rp, sense, omega) == pytest.approx(ref(2), rel=1e-12)
