"""Issue 11: the θ-circle designs' step "The textbook's choice of A" did not say which of the candidates A1…A4
(labelled in the drawing) was chosen. The caption is computed from the choice: it names the candidate's label
drawn at the chosen point and the reason by the recipe's order of preference, in English and in Chinese (with
full-width punctuation)."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from geomcon.geometry import Point
from geomcon.problems import load_problem
from geomcon.recipes.choice_words import Candidate, choice_caption
from geomcon.solve import solve

PROBLEMS = Path(__file__).resolve().parent.parent / "problems"

CHOICES = {                       # problem → the step whose caption states the choice, the chosen point
    "001-10_crank_rocker_design_coupler": ("A", "A"),
    "001-10b_crank_rocker_design_frame_and_swing": ("A", "A"),
    "001-10c_crank_rocker_design_crank_and_frame": ("AD_design", None),     # the frame drawn from the chosen A
    "001-11_jaw_crusher_design": ("A", "A"),
    "001-12_crank_rocker_frame_line": ("A", "A"),
    "001-16_jaw_crusher_AC1": ("A", "A"),
    "001-17b_crank_rocker_redesign_swing": ("D", "D"),
}


def _scene(name):
    return solve(load_problem(PROBLEMS / f"{name}.toml")).scene.complete()


@pytest.mark.parametrize("name", sorted(CHOICES))
def test_the_choice_names_the_candidate_drawn_at_the_chosen_point(name):
    sc = _scene(name)
    step, point = CHOICES[name]
    chosen = sc.value(point) if point else sc.value(step).a
    assert isinstance(chosen, Point)
    at = [s.label for s in sc.steps if s.style == "candidate" and s.label
          and isinstance(v := sc.value(s.key), Point) and abs(v - chosen) <= 1e-9 * max(1.0, abs(chosen))]
    others = [s.label for s in sc.steps if s.style == "candidate" and s.label and s.label not in at]
    assert len(at) == 1, at
    en, zh = sc.caption(step)
    m_en = re.match(r"The textbook's choice: (\w+) = (\S+) \(", en)
    m_zh = re.match(r"教材取 (\w+) = (\S+)（", zh)
    assert m_en and m_zh, (en, zh)
    assert m_en.group(2) == m_zh.group(2) == at[0], (en, zh, at)
    assert m_en.group(1) == m_zh.group(1) == (point or "A")
    for lab in others:                   # another candidate is named only as another solution, after the reason
        assert f"= {lab} " not in en and f"= {lab}（" not in zh
    assert not set("(),;:") & set(zh.split("= ", 1)[1]), zh            # full-width punctuation in Chinese


def test_the_reason_is_the_first_preference_that_differs():
    cands = [Candidate("A1", True, (-1, -1, 300.0)), Candidate("A2", True, (-1, -1, 250.0)),
             Candidate("A3", False, None)]
    en, zh = choice_caption("A", cands, 1)
    assert en == "The textbook's choice: A = A2 (the shorter frame AD; A1 is another solution)"
    assert zh == "教材取 A = A2（机架 AD 较短；A1 为另一解）"
    assert choice_caption("A", cands, None)[0].endswith("no candidate is a valid design")
    assert choice_caption("A", [Candidate("A", True, (0, 0, 1.0))], 0)[0] == "The textbook's choice: A (the only valid point)"


@pytest.mark.parametrize("n", [2, 3, 4])
def test_a_drawing_of_another_solution_names_the_candidate_it_draws(n):
    """--solution n fixes the choice after the construction is built: the caption follows it."""
    other = solve(load_problem(PROBLEMS / "001-16_jaw_crusher_AC1.toml")).as_solution(n)
    sc = other.scene
    chosen = sc.value("A")
    at = [s.label for s in sc.steps if s.style == "candidate" and s.label
          and isinstance(v := sc.value(s.key), Point) and abs(v - chosen) <= 1e-9 * max(1.0, abs(chosen))]
    en, zh = sc.caption("A")
    assert at and at[0] != "A1"
    assert en == f"The solution drawn: A = {at[0]} (the textbook's choice is A1)", en
    assert zh == f"本图取 A = {at[0]}（教材取 A1）", zh


def test_the_best_design_names_its_arc_and_gamma():
    """004-03's A*: its caption names the label drawn there, the θ-circle's arc it lies on and its γmin."""
    from geomcon.recipes.common import near_flag
    sol = solve(load_problem(PROBLEMS / "004-03_crank_rocker_best_by_K.toml"))
    sc = sol.scene.complete()
    en, zh = sc.caption("A")
    near = near_flag(*(sc.value(k) for k in ("A", "C1", "C2", "D")))
    assert en.startswith(f"{sc['A'].label} on the admissible arc {'on D' if near else 'on the far side'}"), en
    assert f"{sol.answers['gamma_min']:.2f}°" in en and f"γmin = {sol.answers['gamma_min']:.2f}°" in zh
    assert "（D 所在一侧，" in zh if near else "（远离 D 的一侧，" in zh


@pytest.mark.parametrize("name", ["001-15_crank_rocker_frame_and_position", "001-22_crank_rocker_frame_and_position_b"])
def test_the_frame_given_design_names_the_c2_chosen_and_why(name):
    """The frame given (001-15, 001-22): A is fixed and the candidates are C2,1 … C2,4 where the θ-lines meet the
    rocker circle. The choice's step said "The textbook's choice of A (the other valid points are candidates)"
    and each candidate's "It meets the rocker circle at a candidate C2"; they name the C2,k chosen and why, and
    each candidate by its label (or that its line misses the circle: the figure has no C2,1, C2,2 there)."""
    sol = solve(load_problem(PROBLEMS / f"{name}.toml"))
    sc = sol.scene.complete()
    chosen = sc.value("P2c")
    at = [f"C2,{n}" for n in range(1, 5)
          if isinstance(v := sc.value(f"C2_{n}"), Point) and abs(v - chosen) <= 1e-9 * max(1.0, abs(chosen))]
    assert len(at) == 1
    en, zh = sc.caption("A")
    assert en.startswith(f"The textbook's choice: C2 = {at[0]} (C1 folded") and "another solution" in en, en
    assert zh.startswith(f"教材取 C2 = {at[0]}（C1 为重叠共线位置") and "为另一解" in zh, zh
    for n in range(1, 5):               # 001-15, 001-22: the counter-clockwise θ-line misses the rocker circle
        cen, czh = sc.caption(f"C2_{n}")
        if sc.value(f"C2_{n}") is None:
            assert cen.startswith(f"The line misses the rocker circle: no candidate C2,{n} ("), cen
            assert czh.startswith(f"该直线与摇杆圆不相交：无候选点 C2,{n}("), czh
        else:
            assert cen.startswith(f"It meets the rocker circle at the candidate C2,{n} ("), cen
            assert czh.startswith(f"交摇杆圆于候选点 C2,{n}("), czh
        assert "a candidate C2" not in cen
    other = sol.as_solution(2).scene.complete()
    assert other.caption("A")[0].startswith("The solution drawn: C2 = ")


def test_a_candidate_s_two_indices_print_as_one_subscript():
    from geomcon.render.labels import label_runs, rich_runs
    assert rich_runs("at the candidate C2,4 (the intersection") == (
        ("at the candidate C", False), ("2,4", True), (" (the intersection", False))     # not C₂ ",4"
    assert label_runs("C2,4")[1] == ("2,4", True)
    assert rich_runs("K = 1.4, H = 100") == (("K = 1.4, H = 100", False),)        # a list of values is not one
