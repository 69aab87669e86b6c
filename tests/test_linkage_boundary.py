"""Linkage designs at their boundaries: the largest θ of the best crank-slider, a given extreme position within
rounding of the frame line (tiny φ, Grashof boundary), closed forms near the end Q of the θ-arc, and the fuzz
generators without mpmath."""
from __future__ import annotations

import math
import subprocess
import sys

import mpmath
import pytest

from geomcon.analytic import design_by_k as dk
from geomcon.analytic.linkages import crank_rocker_extremes, crank_rocker_gamma_from_positions
from geomcon.problems import problem_from_dict
from geomcon.solve import solve


def _solve(recipe: str, given: dict):
    return solve(problem_from_dict({"recipe": recipe, "given": given}, name="test"))


def _mp_best_gamma(K: float, H: float) -> tuple[mpmath.mpf, mpmath.mpf]:
    """(a*, γmin) of crank_slider.best_by_K at 50 digits: bisection where the two working-stroke angles meet."""
    with mpmath.workdps(50):
        th = mpmath.pi * (mpmath.mpf(K) - 1) / (mpmath.mpf(K) + 1)
        Hm = mpmath.mpf(H)

        def parts(a):
            P = (Hm - 2 * a) * (Hm + 2 * a) / (4 * mpmath.sin(th / 2) ** 2)
            u = (mpmath.sqrt(4 * a * a + 4 * P) - 2 * a) / 2
            v = u + 2 * a
            e = u * v * mpmath.sin(th) / Hm
            b, d = (u + v) / 2, abs(a - e)
            glob = mpmath.atan2(mpmath.sqrt((b - a - e) * (b + a + e)), a + e)
            return mpmath.atan2(mpmath.sqrt((u - e) * (u + e)), e), mpmath.atan2(mpmath.sqrt((b - d) * (b + d)), d), glob

        x0, x1 = Hm / 2 * mpmath.tan(th / 2), Hm / 2
        for _ in range(200):
            m = (x0 + x1) / 2
            f, n, _g = parts(m)
            x0, x1 = (m, x1) if f < n else (x0, m)
        return x0, mpmath.degrees(parts(x0)[2])


@pytest.mark.parametrize("K,H", [(2.9974549490348155, 6.9117848668269435), (2.9974325062697793, 746.8630366835754),
                                 (2.9973776463749813, 1394094.0393916278), (1.5, 100.0)])
def test_best_by_K_near_the_largest_theta(K, H):
    """Near θ = 90° A* lies 1e-6·H from C1; its γmin (~3e-5°) agrees with a 50-digit optimum."""
    sol = _solve("crank_slider.best_by_K", {"K": K, "H": H})
    assert sol.ok
    a_exact, g_exact = _mp_best_gamma(K, H)
    for values in (sol.answers, sol.analytic[0]):
        assert values["AB"] == pytest.approx(float(a_exact), rel=1e-12)
        assert values["gamma_min"] == pytest.approx(float(g_exact), rel=1e-7, abs=1e-13)


def test_design_closed_forms_near_Q_do_not_cancel():
    """FC1 of the e, AB and BC forms against 50 digits, A 1e-9 of the arc from Q."""
    K, H = 1.8, 100.0
    th = math.radians(dk.theta_from_k(K))
    with mpmath.workdps(50):
        t = mpmath.pi * (mpmath.mpf(K) - 1) / (mpmath.mpf(K) + 1)
        e_hi = H / mpmath.tan(t)
        e = float(e_hi * (1 - mpmath.mpf("1e-9")))
        c = mpmath.mpf(e) * (H / mpmath.tan(t) - e)
        X = (-H + mpmath.sqrt(H * H + 4 * c)) / 2
        u = mpmath.sqrt(X * X + mpmath.mpf(e) ** 2)
        v = mpmath.sqrt((X + H) ** 2 + mpmath.mpf(e) ** 2)
        gamma = mpmath.degrees(mpmath.atan2(X * mpmath.sqrt((v + e) / (u + e)), (v - u) / 2 + e))
    r = dk.crank_slider_design(K, H, e=e)
    assert dk._foot_from_e(H, th, e) == pytest.approx(float(X), rel=1e-6)
    assert r["gamma_min"] == pytest.approx(float(gamma), rel=1e-6)
    for which in ("AB", "BC"):
        r2 = dk.crank_slider_design(K, H, **{which: r[which]})
        assert r2["gamma_min"] == pytest.approx(float(gamma), rel=1e-5), which


def _mp_frame_designs(K, CD, AD, phi):
    """(AB, BC, ψ, γmin) of every candidate of the frame form at 50 digits (law of cosines)."""
    out = []
    with mpmath.workdps(50):
        K, CD, AD, phi = (mpmath.mpf(x) for x in (K, CD, AD, phi))
        th = 180 * (K - 1) / (K + 1)
        x1, y1 = AD - CD * mpmath.cos(mpmath.radians(phi)), CD * mpmath.sin(mpmath.radians(phi))
        w1, al = mpmath.sqrt(x1 * x1 + y1 * y1), mpmath.degrees(mpmath.atan2(y1, x1))

        def tri(x, y, z):
            c = (x * x + y * y - z * z) / (2 * x * y)
            return mpmath.degrees(mpmath.acos(c)) if abs(c) <= 1 else None

        for beta in (al + th, al - th):
            cb = mpmath.cos(mpmath.radians(beta))
            disc = (AD * cb) ** 2 - (AD * AD - CD * CD)
            if disc < 0:
                continue
            for w in (AD * cb - mpmath.sqrt(disc), AD * cb + mpmath.sqrt(disc)):
                if w <= 0:
                    continue
                a, b = abs(w - w1) / 2, (w + w1) / 2
                x2, y2 = w * cb, w * mpmath.sin(mpmath.radians(beta))
                psi = abs(mpmath.degrees(mpmath.atan2(abs(y2), AD - x2)) - phi)
                g = [tri(b, CD, AD - a), tri(b, CD, AD + a)]
                if None in g:
                    continue
                out.append((a, b, psi, min(min(x, 180 - x) for x in g)))
    return out


@pytest.mark.parametrize("given", [
    {"K": 3.7174422822758837, "CD": 880.5295658799082, "AD": 601.2499486246012, "phi": 4.437086020057823e-07},
    {"K": 1.3037556629654277, "CD": 292.88371320989046, "AD": 553.0768737580605, "phi": 8.437273210394218e-07},
    {"K": 2.522373753853364, "CD": 5.199520335284188, "AD": 4.298487137477005, "phi": 3.8331753552536633e-07},
])
def test_frame_form_with_C1_within_rounding_of_the_frame(given):
    """φ ~ 4e-7° puts C1 1e-8·CD from the frame (Grashof boundary): ψ keeps φ and γmin (∝ φ) is not 0."""
    sol = _solve("crank_rocker.design_by_K", given)
    assert sol.ok
    ref = _mp_frame_designs(**given)
    for s in sol.solution_values:
        a, b, psi, g = min(ref, key=lambda r: abs(float(r[0]) - s["AB"]) + abs(float(r[1]) - s["BC"]))
        assert s["psi"] == pytest.approx(float(psi), abs=1e-11)
        assert s["gamma_min"] == pytest.approx(float(g), rel=1e-6)
        assert s["gamma_min"] > 0


@pytest.mark.parametrize("given", [
    {"K": 1.749536152208343, "AB": 0.6184977345296637, "BC": 5.418230387753274, "psi": 77.15035767247751},
    {"K": 1.8147674317666065, "CD": 3.900169673634354, "phi1": 96.69738943387954, "phi2": 1.9923927401625745e-06,
     "BC": 6.139444455973878},
    {"K": 1.6108323529993502, "AB": 10.240138875690814, "BC": 106.76110523398944, "psi": 14.133599879803809},
    {"K": 1.3457023794529452, "CD": 269.94705676212556, "phi1": 179.99999922965574, "phi2": 155.03661990965875,
     "AB": 26.03740706156077},
    {"K": 1.643494625021028, "CD": 27.410832063007497, "psi": 30.868668185260482, "AB": 4.7694096796785725},
])
def test_designs_at_the_grashof_boundary_pass_their_checks(given):
    """Random designs stated from a linkage at the Grashof boundary (fuzz): every check passes."""
    sol = _solve("crank_rocker.design_by_K", given)
    assert sol.ok, [r for r in sol.checks if not r["ok"]]


def test_gamma_from_positions_matches_the_extremes():
    """Away from the boundary γmin from the points is the law-of-cosines value of the lengths."""
    for a, b, c, d in ((50, 70, 80, 90), (20, 100, 60, 95), (1, 3, 2.5, 3.2)):
        ex = crank_rocker_extremes(a, b, c, d)
        f = b - a
        Cf = (f * math.cos(math.radians(ex["angle_C1AD"])), f * math.sin(math.radians(ex["angle_C1AD"])))
        x = b + a
        Ce = (x * math.cos(math.radians(ex["angle_C2AD"])), x * math.sin(math.radians(ex["angle_C2AD"])))
        assert crank_rocker_gamma_from_positions((0.0, 0.0), (float(d), 0.0), Cf, Ce) == pytest.approx(
            ex["gamma_min"], abs=1e-10)


def test_fuzz_generators_run_without_mpmath():
    """mpmath is a test extra: without it the linkage generators state problems in floats and expect nothing."""
    code = ("import sys, random; sys.modules['mpmath'] = None\n"
            "from geomcon.fuzz.valid_linkages import GENERATORS, exact\n"
            "cases = [g(random.Random(i)) for g in GENERATORS.values() for i in range(5)]\n"
            "assert not exact() and all(c.expect == {} for c in cases), cases\n"
            "print(len(cases))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "45"
