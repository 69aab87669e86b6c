"""``guide_bar.extremes`` with an offset guide ``e`` and a lever ``L``: construction against the twin on
random instances (e below, equal to and above AB), the crank condition (seed 001-04), the shaper's stroke."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.errors import NotAMechanism
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

R = "guide_bar.extremes"


def _solve(**given):
    return solve(problem_from_dict({"recipe": R, "given": given}, name="t"))


def _ok(sol, rel=1e-9):
    assert sol.checks
    for row in sol.checks:
        assert row["ok"], row
        scale = sol.length_scale if row["unit"] == "mm" else 1.0
        assert abs(row["construction"] - row["analytic"]) <= rel * max(abs(row["analytic"]), scale), row


@pytest.mark.parametrize("i", range(60))
def test_random_offset_guide_bars_match_the_twin(i):
    rng = random.Random(14300 + i)
    AB = rng.uniform(5, 100)
    e = rng.choice([rng.uniform(0, AB), rng.uniform(AB, 3 * AB), AB])
    AC = (AB + e) * rng.uniform(1.001, 4.0)
    given = dict(AB=AB, AC=AC, e=e)
    if rng.random() < 0.5:
        given["L"] = AC * rng.uniform(1.0, 3.0)
    sol = _solve(**given)
    _ok(sol)
    p = {k: complex(*v) for k, v in sol.points.items()}
    for b in ("B1", "B2"):
        assert abs(abs(p[b] - p["A"]) - AB) <= 1e-9 * AC
    assert sol.answers["theta"] == pytest.approx(sol.answers["psi"], rel=1e-9)


def _guide_distance(sol, i):
    """Distance from C of the guide line through B_i parallel to the bar C→T_i (must be e)."""
    s = sol.scene
    C, T, B = (complex(*s.value(k).tuple()) for k in ("C", f"T{i}", f"B{i}"))
    u = (T - C) / abs(T - C)
    return abs(((B - C) * u.conjugate()).imag)


@pytest.mark.parametrize("e", [4.0, 10.0, 40.0, 55.0])
def test_extreme_guides_touch_both_circles(e):
    sol = _solve(AB=40, AC=40 + e + 30, e=e)
    _ok(sol)
    for i in (1, 2) if e != 40.0 else (1,):
        assert _guide_distance(sol, i) == pytest.approx(e, rel=1e-12)


def test_zero_offset_agrees_with_the_plain_guide_bar():
    plain = _solve(AB=145, AC=290).answers
    lever = _solve(AB=145, AC=290, L=500).answers
    for k in ("theta", "psi", "K"):
        assert lever[k] == pytest.approx(plain[k], rel=1e-12)
    assert lever["H"] == pytest.approx(2 * 500 * math.sin(math.radians(30)), rel=1e-12)


def test_shaper_crank_100_centres_200_lever_400():
    a = _solve(AB=100, AC=200, L=400).answers
    assert a["K"] == pytest.approx(2.0, rel=1e-12) and a["H"] == pytest.approx(400.0, rel=1e-12)


@pytest.mark.parametrize("given, words", [
    (dict(AB=40, AC=50, e=10), ["not a crank", "AC = 50 ≤ AB + e = 40 + 10 = 50"]),     # seed 001-04: AC > 50
    (dict(AB=40, AC=45, e=10), ["not a crank"]),
    (dict(AB=40, AC=20, e=10), ["rotating", "AB − e = 30"]),
])
def test_crank_condition_seed_001_04(given, words):
    with pytest.raises(NotAMechanism) as exc:
        _solve(**given)
    for w in words:
        assert w in str(exc.value)


def test_statement_forms():
    from geomcon.worksheet.statements import default_template, fill, shown_givens, template_form
    for g, form in ((dict(AB=40, AC=60), ""), (dict(AB=40, AC=60, e=10), "offset"), (dict(AB=100, AC=200, L=400), "lever"),
                    (dict(AB=40, AC=60, e=10, L=150), "offset+lever")):
        assert template_form(R, g) == form
        en, zh = (fill(t, shown_givens(R, g, lang)) for t, lang in zip(default_template(R, g), ("en", "zh")))
        assert "{" not in en + zh and zh.endswith("。")
        for v in g.values():
            assert str(v) in en and str(v) in zh


def _drawn_links(sol):
    """(style, a, b) of every visible segment drawn as a link (a bar of the mechanism), as complex numbers."""
    from geomcon.geometry.primitives import Segment
    out = []
    for st in sol.scene.visible_steps():
        v = sol.scene.value(st.key)
        if isinstance(v, Segment) and st.style.startswith("link"):
            out.append((st.style, complex(*v.a.tuple()), complex(*v.b.tuple())))
    return out


@pytest.mark.parametrize("given", [dict(AB=40, AC=60, e=10),                 # seed 001-04
                                   dict(AB=40, AC=150, e=25, L=170), dict(AB=20, AC=90, e=35)])
def test_offset_bars_hang_from_c_by_an_arm_of_length_e(given):
    """001-04 drew the two guide bars floating beside C: the arm of length e from C to each bar's foot was
    missing. Each drawn bar through B_i lies at distance e from C, and a link of its style joins C to its foot
    (the rigid L of arm and bar a textbook draws)."""
    sol = _solve(**given)
    e = given["e"]
    p = {k: complex(*v) for k, v in sol.points.items()}
    C, A = p["C"], p["A"]
    links = _drawn_links(sol)
    tol = 1e-9 * given["AC"]
    for i in (1, 2):
        B = p[f"B{i}"]
        bars = [(s, a, b) for s, a, b in links
                if abs(a - A) > tol and abs(b - A) > tol and abs(((B - a) * (b - a).conjugate()).imag) <= tol * abs(b - a)]
        assert len(bars) == 1, (i, bars)
        style, a, b = bars[0]
        u = (b - a) / abs(b - a)
        assert abs(((C - a) * u.conjugate()).imag) == pytest.approx(e, rel=1e-9)       # the bar's line at e from C
        foot = a + ((C - a) * u.conjugate()).real * u
        arms = [(s, x, y) for s, x, y in links if max(abs(x - C), abs(y - foot)) <= tol
                or max(abs(y - C), abs(x - foot)) <= tol]
        assert arms and arms[0][0] == style, (i, links)
        assert abs(arms[0][2] - arms[0][1]) == pytest.approx(e, rel=1e-9)
        assert min(abs(a - foot), abs(b - foot)) <= tol                    # the bar starts at the arm's end: an L


def test_no_arm_without_offset():
    """e = 0: the bar passes through C, and no zero-length arm is drawn."""
    sol = _solve(AB=100, AC=200, L=400)
    assert all(abs(b - a) > 1e-9 for _, a, b in _drawn_links(sol))
