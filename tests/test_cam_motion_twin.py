"""The motion twin's maxima (geomcon.analytic.cam_motion): the ends of every smooth piece and the roots of the
next derivative, f‴ written in the twin too; f‴ against central differences of the twin's own f″ inside the
pieces, and the maxima against 50-digit mpmath for the laws with closed forms."""
from __future__ import annotations

import math

import mpmath
import pytest

from geomcon.analytic import cam_motion

LAWS = [{"law": n} for n in ("uniform", "parabolic", "cosine", "cycloidal", "poly345", "double_harmonic",
                             "modified_trapezoid", "modified_sine")] + [
    {"law": "poly", "coefficients": [0, 0, 0, 0, 35, -84, 70, -20]},
    {"law": "table", "points": [[0, 0], [0.2, 0.06], [0.4, 0.33], [0.6, 0.68], [0.8, 0.94], [1, 1]]},
]


@pytest.mark.parametrize("row", LAWS, ids=lambda r: r["law"])
def test_third_derivative_against_differences_of_the_second(row):
    edges = cam_motion._smooth_pieces(row)
    for a, b in zip(edges, edges[1:]):
        for t in (0.13, 0.5, 0.87):
            x, h = a + (b - a) * t, 1e-6 * (b - a)
            fd = (cam_motion.normalised(row, x + h)[2] - cam_motion.normalised(row, x - h)[2]) / (2 * h)
            assert cam_motion.third(row, x) == pytest.approx(fd, rel=1e-6, abs=1e-6)


def test_maxima_against_mpmath():
    """Peaks of f′ and f″ of 3-4-5, the 4-5-6-7 polynomial (x = ½ ± 1/(2√5) for f″), the double harmonic and
    the cycloidal law, against their closed forms' stationary points at 50 digits."""
    mpmath.mp.dps = 50
    cases = {
        "poly345": lambda x: 10 * x ** 3 - 15 * x ** 4 + 6 * x ** 5,
        "cycloidal": lambda x: x - mpmath.sin(2 * mpmath.pi * x) / (2 * mpmath.pi),
        "double_harmonic": lambda x: (1 - mpmath.cos(mpmath.pi * x)) / 2 - (1 - mpmath.cos(2 * mpmath.pi * x)) / 8,
        "poly": lambda x: 35 * x ** 4 - 84 * x ** 5 + 70 * x ** 6 - 20 * x ** 7,
    }
    for name, f in cases.items():
        row = next(r for r in LAWS if r["law"] == name)
        for k in (1, 2):
            grid = [mpmath.mpf(i) / 200 for i in range(201)]
            best = max(abs(mpmath.diff(f, x, k)) for x in grid)
            for i in range(200):
                lo, hi = grid[i], grid[i + 1]
                if mpmath.diff(f, lo, k + 1) * mpmath.diff(f, hi, k + 1) < 0:
                    r = mpmath.findroot(lambda x: mpmath.diff(f, x, k + 1), (lo, hi), solver="anderson")
                    best = max(best, abs(mpmath.diff(f, r, k)))
            got = cam_motion._segment_max(dict(row, kind="rise", angle=90), k)
            assert abs(got - float(best)) <= 1e-14 * float(best), (name, k, got, best)   # the forms rounded


@pytest.mark.parametrize("kind", ["rise", "return"])
def test_program_maxima_scale_with_h_and_the_angle(kind):
    prog = [{"kind": kind if kind == "rise" else "rise", "angle": 150, "law": "cosine"},
            {"kind": "return", "angle": 210, "law": "modified_sine"}]
    vm, am = cam_motion.maxima(prog, 10.0)
    ms = cam_motion._segment_max({"law": "modified_sine"}, 1), cam_motion._segment_max({"law": "modified_sine"}, 2)
    assert vm == pytest.approx(max(10 * math.pi / 2 / math.radians(150), 10 * ms[0] / math.radians(210)), rel=1e-15)
    assert am == pytest.approx(max(10 * math.pi ** 2 / 2 / math.radians(150) ** 2, 10 * ms[1] / math.radians(210) ** 2), rel=1e-15)
