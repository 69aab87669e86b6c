"""The declared mistakes of issue 14's remaining forms diagnosed when grading: ``four_bar.link_ranges``,
``crank_rocker.best_by_K``, the offset guide bar (``guide_bar.extremes`` with e and L) and the slotter's
closings (``slotter.design_by_K`` on AB or AC). Each wrong value is computed here in closed form (the
textbook's formulas, or the analytic twin run on the student's wrong data), independently of the scene replay
(:mod:`geomcon.grading.mistakes`) that diagnoses it; a right answer stays right."""
from __future__ import annotations

import math

import pytest

from geomcon.analytic.crank_rocker_best import crank_rocker_best
from geomcon.analytic.guide_bar_offset import guide_bar_offset_extremes
from geomcon.analytic.linkages import k_from_theta, theta_from_k
from geomcon.grading import grade
from geomcon.grading.answers import read_answers
from geomcon.grading.keyfile import key_from_json, key_from_problem
from geomcon.grading.tables import grades_data
from geomcon.worksheet import make_worksheet
from geomcon.worksheet.roster import numbered
from geomcon.worksheet.spec import parse_spec


def verdicts(key, header: list[str], rows: list[list[float]]) -> list[dict[str, tuple[str, str]]]:
    """Grade one row of answers per student id 1, 2, …: {column: (verdict, diagnosis)} per row."""
    text = ",".join(["id"] + header) + "\n" + "".join(
        ",".join([str(i + 1)] + [repr(float(v)) for v in r]) + "\n" for i, r in enumerate(rows))
    data = grades_data(grade(key, read_answers(text.encode())))
    return [{c: (a["verdict"], a["diagnosis"]) for c, a in row["answers"].items()} for row in data["rows"]]


def problem_key(tmp_path, recipe: str, given: dict):
    f = tmp_path / "p.toml"
    f.write_text(f'recipe = "{recipe}"\n[given]\n' + "".join(f"{k} = {v!r}\n" for k, v in given.items()))
    return key_from_problem(f)


# ---------------------------------------------------------------------------------------- four_bar.link_ranges
def test_link_ranges_grashof_alone_and_the_forgotten_longest_case():
    """Seed 001-02 (AB 160, CD 240, frame AD 210, BC unknown). Right: BC between, AB + CD ≤ BC + AD, BC ≥ 190;
    BC longest, AB + BC ≤ CD + AD, BC ≤ 290; flat at 610. Grashof alone taken for a crank-rocker adds
    BC shortest, BC + CD ≤ AB + AD, BC ≤ 130 (a double-rocker: the coupler is shortest); the longest case
    forgotten leaves the crank-rocker open up to the flat chain, 610."""
    AB, CD, AD = 160.0, 240.0, 210.0
    right = [AB + CD - AD, CD + AD - AB]                      # 190, 290
    grashof_alone = [AB + AD - CD, AB + CD - AD]              # 130, 190
    forgotten = [AB + CD - AD, AB + CD + AD]                  # 190, 610
    spec = ('[[exercise]]\nrecipe = "four_bar.link_ranges"\nask = ["boundaries[0]", "boundaries[1]"]\n'
            f"[exercise.given]\nAB = {AB}\nCD = {CD}\nAD = {AD}\n")
    key = key_from_json(make_worksheet(parse_spec(spec), numbered(3)).files["key.json"])
    cols = ["1.boundaries[0]", "1.boundaries[1]"]
    got = verdicts(key, cols, [right, grashof_alone, forgotten])
    assert got[0] == {c: ("correct", "") for c in cols}
    assert got[1] == {c: ("wrong", "grashof_as_crank") for c in cols}
    assert got[2] == {cols[0]: ("correct", ""), cols[1]: ("wrong", "longest_case_forgotten")}


def test_link_ranges_unknown_crank():
    """The crank AB unknown (BC 100, CD 200, frame AD 240). Right: a crank-rocker while AB is shortest,
    AB + AD ≤ BC + CD, AB ≤ 60, then a double-rocker (the coupler BC is shortest, or Grashof fails) up to the
    flat chain at 540. Grashof alone also calls AB between BC and AD a crank-rocker: from BC + AD ≤ AB + CD,
    AB ≥ 140, so the second boundary is 140."""
    BC, CD, AD = 100.0, 200.0, 240.0
    short, flat, between = BC + CD - AD, BC + CD + AD, BC + AD - CD
    spec = ('[[exercise]]\nrecipe = "four_bar.link_ranges"\nask = ["boundaries[0]", "boundaries[1]"]\n'
            f"[exercise.given]\nBC = {BC}\nCD = {CD}\nAD = {AD}\n")
    key = key_from_json(make_worksheet(parse_spec(spec), numbered(2)).files["key.json"])
    assert [a.expected for a in key.students["1"].exercises[0].answers] == [short, flat]
    cols = ["1.boundaries[0]", "1.boundaries[1]"]
    got = verdicts(key, cols, [[short, flat], [short, between]])
    assert got[0] == {c: ("correct", "") for c in cols}
    assert got[1][cols[1]] == ("wrong", "grashof_as_crank")


# ---------------------------------------------------------------------------------------- crank_rocker.best_by_K
def _frame_gammas(AB: float, BC: float, CD: float, AD: float) -> list[float]:
    out = []
    for BD in (AD - AB, AD + AB):
        g = math.degrees(math.acos((BC ** 2 + CD ** 2 - BD ** 2) / (2 * BC * CD)))
        out.append(min(g, 180 - g))
    return out


def test_best_by_k_mistakes():
    """Issue 14's K 10/9, ψ 80°, AD 120. The line from C1 at θ instead of 90° − θ: the best design of the K
    whose θ is 90° − θ (the twin run on that K). γmin read at the other crank-on-frame position: the larger
    of the two cosine-law angles of the right design."""
    K, psi, AD = 10 / 9, 80.0, 120.0
    right = crank_rocker_best(K, psi, AD)
    wrong = crank_rocker_best(k_from_theta(90.0 - theta_from_k(K)), psi, AD)
    gammas = _frame_gammas(right["AB"], right["BC"], right["CD"], AD)
    assert min(gammas) == pytest.approx(right["gamma_min"], rel=1e-9)
    key = key_from_problem("problems/004-03_crank_rocker_best_by_K.toml")
    cols = ["AB", "CD", "gamma_min"]
    got = verdicts(key, cols, [[right[c] for c in cols], [wrong["AB"], wrong["CD"], max(gammas)],
                               [right["AB"], right["CD"], wrong["gamma_min"]]])
    assert got[0] == {c: ("correct", "") for c in cols}
    assert got[1] == {"AB": ("wrong", "theta_circle_angle"), "CD": ("wrong", "theta_circle_angle"),
                      "gamma_min": ("wrong", "other_extreme_position")}
    assert got[2]["gamma_min"] == ("wrong", "theta_circle_angle")


# ---------------------------------------------------------------------------------------- guide_bar.extremes, e and L
@pytest.mark.parametrize("AB, AC, e, L", [(60.0, 100.0, 35.0, 150.0), (100.0, 200.0, 60.0, 400.0)])
def test_offset_guide_bar_mistakes(tmp_path, AB, AC, e, L):
    """The offset left out: sin(ψ/2) = AB/AC and H = 2·L·AB/AC (the centred guide's formulas). Both parallels
    at AB + e: the extremes symmetric about AC, sin(ψ/2) = (AB + e)/AC, H = 2·L·(AB + e)/AC, θ = ψ. (ψ is even
    in e, so a small offset left out is within drafting tolerance: the instances have e near AB.)"""
    right = guide_bar_offset_extremes(AB, AC, e, L)
    psi0 = 2 * math.degrees(math.asin(AB / AC))
    psi_s = 2 * math.degrees(math.asin((AB + e) / AC))
    key = problem_key(tmp_path, "guide_bar.extremes", dict(AB=AB, AC=AC, e=e, L=L))
    cols = ["psi", "K", "H"]
    got = verdicts(key, cols, [[right["psi"], right["K"], right["H"]],
                               [psi0, k_from_theta(psi0), 2 * L * AB / AC],
                               [psi_s, k_from_theta(psi_s), 2 * L * (AB + e) / AC]])
    assert got[0] == {c: ("correct", "") for c in cols}
    assert got[1] == {c: ("wrong", "offset_forgotten") for c in cols}
    assert got[2] == {c: ("wrong", "offset_symmetric") for c in cols}


# ---------------------------------------------------------------------------------------- slotter.design_by_K
@pytest.mark.parametrize("closing", ["AB", "AC"])
def test_slotter_closing_mistakes(tmp_path, closing):
    """Whitworth design K 2, stroke 150 (θ = 60°): the crank sees B1B2 under 180° − θ, so AC = AB·sin(θ/2).
    Lines through A at θ/2 to AC: AC = AB·cos(θ/2) (crank given) or AB = AC/cos(θ/2) (centres given);
    θ answered with the stroke's crank angle 180° − θ; the arm taken as the whole stroke, CD = S."""
    K, S = 2.0, 150.0
    th = theta_from_k(K)
    h = math.radians(th / 2)
    given = dict(K=K, H=S, AB=40.0) if closing == "AB" else dict(K=K, H=S, AC=25.0)
    ask = "AC" if closing == "AB" else "AB"
    right = given["AB"] * math.sin(h) if closing == "AB" else given["AC"] / math.sin(h)
    wrong = given["AB"] * math.cos(h) if closing == "AB" else given["AC"] / math.cos(h)
    key = problem_key(tmp_path, "slotter.design_by_K", given)
    cols = [ask, "CD", "theta"]
    got = verdicts(key, cols, [[right, S / 2, th], [wrong, S, 180 - th]])
    assert got[0] == {c: ("correct", "") for c in cols}
    assert got[1] == {ask: ("wrong", "stroke_angle"), "CD": ("wrong", "arm_full_stroke"),
                      "theta": ("wrong", "theta_crank_angle")}


# ---------------------------------------------------------------------------------------- crank_rocker.design_by_K, C1_C2
def test_c1_c2_exchanged_is_diagnosed():
    """Issue 13 left ``C1_C2`` (the given extreme position taken as the extended one) declared but produced by
    no test. It occurs wherever the data fix C1 and the design still has both readings: the frame form
    (001-15: K 1.5, CD 75, AD 100, ∠ADC1 45°). Closed form: A at the origin, D at (AD, 0), C1 at 45° above
    the frame from D; C2 on the rocker circle on the ray from A at θ to AC1 (t² − 2t·AD·cos β + AD² − CD² = 0);
    AB = |AC2 − AC1|/2, BC = (AC1 + AC2)/2. The textbook's C1 is the folded position (AC1 < AC2); the other
    root has AC1 > AC2: C1 taken as the extended position."""
    K, CD, AD, phi = 1.5, 75.0, 100.0, 45.0
    th = theta_from_k(K)
    c1 = (AD - CD * math.cos(math.radians(phi)), CD * math.sin(math.radians(phi)))
    ac1, b1 = math.hypot(*c1), math.atan2(c1[1], c1[0])
    designs = {}
    for s in (1, -1):
        b = b1 + s * math.radians(th)
        p = AD * math.cos(b)
        q = p * p - (AD * AD - CD * CD)
        for t in ((p - math.sqrt(q), p + math.sqrt(q)) if q >= 0 else ()):
            if t > 0:
                designs[ac1 < t] = (abs(t - ac1) / 2, (t + ac1) / 2)
    key = key_from_problem("problems/001-15_crank_rocker_frame_and_position.toml")
    got = verdicts(key, ["AB", "BC"], [list(designs[True]), list(designs[False])])
    assert got[0] == {"AB": ("correct", ""), "BC": ("correct", "")}
    assert got[1] == {"AB": ("wrong", "C1_C2"), "BC": ("wrong", "C1_C2")}


# ---------------------------------------------------------------------------------------- the gaps test_recipes_complete found
def test_guide_bar_design_theta_not_halved():
    """001-05b (K 2, AC 290): the extreme positions at ±θ/2 to CA give AB = AC·sin(θ/2) = 145; drawn at ±θ,
    AB = AC·sin θ."""
    th = math.radians(theta_from_k(2.0))
    key = key_from_problem("problems/001-05b_guide_bar_design_by_K.toml")
    got = verdicts(key, ["AB"], [[290 * math.sin(th / 2)], [290 * math.sin(th)]])
    assert got == [{"AB": ("correct", "")}, {"AB": ("wrong", "theta_not_halved")}]


def test_function_generation_inversion_direction():
    """100-05: the points turned the wrong way about D are the design of ψ mirrored about ψ1 (2ψ1 − ψi): the
    twin run on those angles."""
    from geomcon.analytic.function_generation import function_generation
    phi, psi = [40, 90, 140], [92.16, 105.09, 125.96]
    right = function_generation(100, 30, phi, psi)
    wrong = function_generation(100, 30, phi, [2 * psi[0] - p for p in psi])
    key = key_from_problem("problems/100-05_four_bar_function_generation.toml")
    got = verdicts(key, ["BC", "CD"], [[right["BC"], right["CD"]], [wrong["BC"], wrong["CD"]]])
    assert got == [{"BC": ("correct", ""), "CD": ("correct", "")},
                   {"BC": ("wrong", "inversion_direction"), "CD": ("wrong", "inversion_direction")}]


def test_crank_slider_instant_centre_mistakes():
    """400-05 (AB 120, BC 250, e 60, φ 30°): ω2/ω1 from the vector loop, inverted ω1/ω2; vC/ω1 read at P24,
    where AB extended meets the perpendicular to the guide through C: P24 = (xC, xC·tan φ), so −xC·tan φ."""
    from geomcon.analytic.kinematics import crank_slider
    r = crank_slider(120, 250, 60, 30, 1.0)
    key = key_from_problem("problems/400-05_crank_slider_instant_centres.toml")
    got = verdicts(key, ["w2_w1", "vC_w1"], [[r["omega2"], r["vC"]],
                                             [1 / r["omega2"], -r["xC"] * math.tan(math.radians(30))]])
    assert got == [{"w2_w1": ("correct", ""), "vC_w1": ("correct", "")},
                   {"w2_w1": ("wrong", "ratio_inverted"), "vC_w1": ("wrong", "wrong_centre")}]
