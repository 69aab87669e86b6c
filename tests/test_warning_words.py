"""Warnings in Chinese (issue 11): every rule translates an example of its warning, every warning of the bundled
problems has its Chinese sentence, and the Chinese uses full-width punctuation."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from geomcon.render.warning_words import RULES, printed_words, warning_lines, warning_zh

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = [
    "published theta = 25 is doubtful: it deviates from the exact 12.5056 by +99.91 %, beyond drafting accuracy (±3 %)",
    "solution 2: γmin = 32.86° is below gamma_allow = 40°",
    "γmin = 32.86° is below gamma_allow = 40°",
    "check failed: theta construction 12.5 vs analytic 12.6",
    "C1_folded: construction 1.0, analytic 0.0 — the data lie on the boundary where it changes (it flips within a "
    "relative change of 1e-06)",
    "theta is ill-conditioned: it moves 2.5e+03 times the relative change of the givens; construction and twin agree "
    "to 1e-10 (allowed 3e-09)",
    "α_max of the return = 36.71° exceeds alpha_allow = 30° (at δ = 230.3°)",
    "α_max of the rise = 82.15° exceeds the allowance 45° (at δ = 5°)",
    "undercut: rr = 5 ≥ ρmin = 1.455 of the pitch curve (at δ = 170.1°); the profile is trimmed and the follower's "
    "motion is distorted there (增大基圆或减小滚子半径)",
    "undercut: rr = 20 ≥ ρmin = 17.11 of the pitch curve; the profile is trimmed and the follower's motion is "
    "distorted there (增大基圆或减小滚子半径)",
    "ρmin = 23.31 of the pitch curve is below 3·rr = 30: the actual profile's ρa = 13.31 is small (wear, contact stress)",
    "the pitch curve has a convex corner at δ = 120°, 180° (velocity drop, rigid impact): the roller cannot follow it "
    "exactly there",
    "the flat face cannot follow the motion: min(r0 + s + s″) = -3.2 and the velocity drops suddenly (s′ jumps down); "
    "the profile is trimmed (增大基圆 r0)",
    "the flat face cannot follow the motion: ρmin of the profile = -2.1 mm at δ = 95°; the contact jumps back along "
    "the face at δ = 100° (ψ′ drops suddenly); the profile is trimmed (增大基圆 r0)",
    "the profile reaches about 130 mm from O, beyond the arm's pivot (a = 120): it would hit the pivot",
    "the cam reaches 125 mm from O at the top of the stroke, beyond the arm's pivot (a = 120): it would hit the pivot",
    "branch defect: the three positions are not on one assembly branch (C on different sides of B→D: C1 left, C2 left, "
    "C3 right); no continuous motion of the linkage passes all three",
    "branch defect: the designed positions lie on different assembly branches (side of C from B→D: position 1: left, "
    "position 2: right, position 3: left); they cannot all be reached without taking the linkage apart",
    "branch defect: the designed positions lie on different assembly branches (pin E against the foot of F on the "
    "guide: position 1: ahead, position 2: behind, position 3: ahead); they cannot all be reached without taking "
    "the linkage apart",
    "order defect: the input meets a dead point turning from B1 through B2 to B3 (crank angles 10°, 50°, 90°; AB is "
    "not a crank), so the positions are not reached in the given order by one motion",
    "order defect: the input's motion from position 1 through 2 to 3 passes a dead point (γ = 0 at φ = 40°); the "
    "positions are not reached in the given order",
    "Grashof equality s + l = p + q: a change-point linkage (all links can be collinear)",
    "Grashof equality s + l = p + q = 140: a change-point chain (the links can all be collinear, γ = 0 there)",
    "Grashof equality AB + BC = CD + AD = 65: a change-point linkage (links can all be collinear, γmin = 0)",
    "the longest link 200 ≥ the sum of the other three 150: the chain cannot move (immovable)",
    "AB + e = BC = 80: the rod is perpendicular to the guide at one position (αmax = 90°)",
    "AB = 30 is at the end Q of the admissible arc: AB + e = BC, αmax = 90°",
    "B1 = (0, 0), B2 = (1, 0), B3 = (2, 0.1) are nearly collinear: R/h_min = 120 ≥ 100, the fixed pivot A moves up "
    "to 12 mm per 0.1 mm of drafting error",
    "the inverted points B1, B2′, B3′ are nearly collinear (R/h_min = 150 ≥ 100): C1 moves up to 150 mm per mm of "
    "error in one of them",
    "the bisector of F1F2′ meets the guide far away (x = 900): E1 moves up to 130 mm per mm of drafting error (≥ 100)",
    "K is not one point of a rigid coupler: B1K1 = 24.9977319, B2K2 = 24.999784 differ by 0.00251 mm (drafting "
    "error?): only the directions B_iK_i, the coupler's angles, are used",
    "the coupler is not rigid: B1C1 = 50, B2C2 = 50.01, B3C3 = 50 differ by 0.01 mm (drafted data?): each C_i is slid "
    "along B_iC_i to the mean BC = 50.0033 mm",
    "'F.x' has 4 extremes per turn: K is not defined (stroke = largest maximum − smallest minimum)",
    "printed H = 100 is off the exact 99.8",
    "offset on the wrong side: e = -10 puts the follower's axis left of O on a ccw cam, which makes the rise's "
    "pressure angles larger (a ccw cam wants the axis right of O, a cw cam left)",
]
HALF = re.compile(r"[\u4e00-\u9fff][,;:?!()]|[,;:?!()][\u4e00-\u9fff]")


@pytest.mark.parametrize("warning", EXAMPLES)
def test_each_example_is_translated_with_its_numbers(warning):
    zh = warning_zh(warning)
    assert zh is not None and not HALF.search(zh), zh
    for number in re.findall(r"-?\d+(?:\.\d+)?", warning):
        assert number in zh, (number, zh)
    assert not re.search(r"\b(the|is|of|at δ|left|right|side|position|ahead|behind|pin|foot)\b", zh), zh


def test_every_rule_has_an_example():
    used = {i for w in EXAMPLES for i, (p, _, _) in enumerate(RULES) if re.fullmatch(p, w)}
    assert used == set(range(len(RULES)))


def test_every_warning_of_the_bundled_problems_is_translated():
    seen = {w for f in (ROOT / "gallery").glob("*.json") for w in json.loads(f.read_text(encoding="utf-8")).get("warnings", [])}
    assert len(seen) > 30
    assert [w for w in sorted(seen) if warning_zh(w) is None] == []


def test_lines_by_language():
    w = [EXAMPLES[6], "a sentence no rule knows"]
    en, zh = printed_words(EXAMPLES[6]), printed_words(warning_zh(EXAMPLES[6]), zh=True)
    assert warning_lines(w, "en") == [en, w[1]]
    assert warning_lines(w, "zh") == [zh, "a sentence no rule knows"]
    assert warning_lines(w, "both") == [en, zh, "a sentence no rule knows"]


def test_a_figure_prints_the_identifiers_a_warning_quotes_as_symbols():
    """Issue 11: the figure printed ``alpha_allow`` and ``published profile_x[0]`` raw. It prints them as the Results
    block does (α with the subscript allow, [α] in Chinese; x[0] of the profile points); JSON keeps the English."""
    lines = warning_lines(["α_max of the return = 36.71° exceeds alpha_allow = 30° (at δ = 230.3°)",
                           "published profile_x[0] = -26.825 is doubtful: it deviates from the exact -42.6357 by "
                           "+37.08 %, beyond drafting accuracy (±3 %)"], "both")
    assert lines[0].startswith("α′_max of the return = 36.71° exceeds α_allow = 30°")
    assert "超过许用压力角 [α] = 30°" in lines[1]
    assert lines[2].startswith("published xa[0] (profile points) = -26.825")
    assert lines[3].startswith("教材答案 xa[0]（实际廓线点） = -26.825")
    assert not any(re.search(r"[a-z]_[a-z]", t) for t in lines[1::2])
