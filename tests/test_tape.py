"""Taped constructions: a recipe recorded once with symbolic givens and replayed gives, bit for bit, what running
it again gives; a decision on a given is a guard; what a tape cannot follow keeps the planned path."""
from __future__ import annotations

import math
import random
from types import SimpleNamespace

import pytest

from geomcon.errors import Unbuildable
from geomcon.geometry import Above, Point, circle, circle_circle
from geomcon.problems import problem_from_dict
from geomcon.recipes import Construction, get_recipe
from geomcon.scene import Scene
from geomcon.scene import scene as scene_module
from geomcon.scene.tape import Escape, Sym, lifted, tracing
from geomcon.solve import Solution, solve
from geomcon.taped import _TAPES, construct_taped, is_taped, shape_of


@pytest.fixture(autouse=True)
def _fresh():
    saved_keep, saved_tapes = dict(scene_module._KEEP), dict(_TAPES)
    scene_module._KEEP.clear()
    _TAPES.clear()
    yield
    scene_module._KEEP.clear()
    scene_module._KEEP.update(saved_keep)
    _TAPES.clear()
    _TAPES.update(saved_tapes)


def _toy(g):
    """C where circles about A (radius r, or r + 1 when r ≤ AD / 2: a decision on the givens, a guard) and D
    (radius s) meet."""
    sc = Scene("toy")
    A = sc.given("A", Point(0.0, 0.0))
    D = sc.given_at("D", g["AD"], 0.0)
    r = g["r"] if g["r"] > g["AD"] / 2 else g["r"] + 1.0
    kA = sc.add("kA", circle, A, r, caption=(f"circle r = {r:g}", ""))
    kD = sc.add("kD", circle, D, g["s"])
    sc.add("C", circle_circle, kA, kD, branch=Above(A, D), caption=(f"C with r = {r:g}", ""))
    return Construction(sc, {"C": "C"}, {"C": "C"})


TOY = SimpleNamespace(name="toy", construct=_toy)


def _solve_toy(g):
    c = construct_taped(TOY, g)
    c.scene.rebuild_with(lambda: _toy(g).scene)
    return c.scene, c.scene.value("C")


def test_sym_records_arithmetic_guards_decisions_and_escapes_plain_numbers():
    a, b = Sym.given("a", 3.0), Sym.given("b", 4.0)
    s = (a * a + b * b) ** 0.5
    assert s.v == 5.0 and type(s) is Sym
    with tracing() as guards:
        assert (s > 4.0) is True and (a == b) is False and bool(a)
    assert [out for _, _, out in guards] == [True, False, True]
    for plain in (float, int, math.sin, hash, round):
        with pytest.raises(Escape):
            plain(a)
    with pytest.raises(Escape):
        _ = a < b                       # a decision outside a recording is not a guard
    assert lifted(math.hypot, a, b).v == 5.0 and lifted(math.hypot, 3.0, 4.0) == 5.0


def test_a_toy_replays_its_path_bit_for_bit_and_records_the_other_path_on_a_guard():
    rng = random.Random(7)
    taped = 0
    for i in range(60):
        g = {"AD": rng.uniform(5, 10), "r": rng.uniform(3, 8), "s": rng.uniform(6, 9)}
        sc, c = _solve_toy(g)
        want = Scene.value(_toy(g).scene, "C")
        assert repr(c) == repr(want)
        taped += is_taped(sc)
    assert taped > 40
    entries = _TAPES[shape_of("toy", {"AD": 1.0, "r": 1.0, "s": 1.0})]
    assert len(entries) == 2 and all(t is not None for t, _, _ in entries)   # both sides of r > AD/2


def test_a_taped_scene_completes_itself_before_a_caption_or_label_is_read():
    for g in ({"AD": 8.0, "r": 5.0, "s": 5.0},) * 3:
        sc, _ = _solve_toy(g)
    assert is_taped(sc)
    g = {"AD": 8.0, "r": 6.0, "s": 5.0}
    sc, _ = _solve_toy(g)
    assert is_taped(sc) and sc.caption("C")[0].startswith("C with r = 6 ")     # the new numbers, not the tape's
    assert not is_taped(sc) and sc.stats["steps_total"] == len(_toy(g).scene)
    assert sc.stats["steps_evaluated"] == 5 and sc.label_of("D") == "D"


def test_a_recipe_that_turns_a_given_into_a_plain_number_is_not_taped_and_still_right():
    def construct(g):
        sc = Scene("sine")
        A = sc.given("A", Point(0.0, 0.0))
        sc.add("P", circle, A, math.sin(g["x"]) + 2.0)
        return Construction(sc, {"P": "P"}, {})
    recipe = SimpleNamespace(name="sine", construct=construct)
    for x in (0.5, 0.7, 0.9, 1.1):
        c = construct_taped(recipe, {"x": x})
        assert not is_taped(c.scene) and c.scene.value("P").r == math.sin(x) + 2.0
    assert _TAPES[shape_of("sine", {"x": 0.0})][0][0] is None


def test_a_given_written_into_text_a_step_reads_is_not_taped():
    def construct(g):
        sc = Scene("text")
        sc.add("T", str.upper, f"x = {g['x']:g}")
        return Construction(sc, {"T": "T"}, {})
    recipe = SimpleNamespace(name="text", construct=construct)
    for x in (1.0, 2.0, 3.0):
        c = construct_taped(recipe, {"x": x})
        assert c.scene.value("T") == f"X = {x:g}"


def test_a_failing_step_of_a_taped_scene_reports_the_planned_path_s_message():
    for g in ({"AD": 8.0, "r": 5.0, "s": 5.0},) * 3:
        _solve_toy(g)
    g = {"AD": 8.0, "r": 5.5, "s": 20.0}    # r > AD / 2, the taped path, but the circles do not meet
    c = construct_taped(TOY, g)
    assert is_taped(c.scene)
    c.scene.rebuild_with(lambda: _toy(g).scene)
    with pytest.raises(Unbuildable) as taped:
        c.scene.value("C")
    plain = _toy(g).scene
    with pytest.raises(Unbuildable) as full:
        plain.value("C")
    assert str(taped.value) == str(full.value) and "r = 5.5 " in str(taped.value)


TAPED_CASES = {
    "crank_rocker.extremes": lambda r: {"AB": r.uniform(20, 40), "BC": r.uniform(60, 80), "CD": r.uniform(60, 80),
                                        "AD": r.uniform(70, 90), "branch": r.choice(["above", "below"])},
    "crank_slider.extremes": lambda r: {"AB": r.uniform(20, 40), "BC": r.uniform(80, 120),
                                        "e": r.choice([0.0, r.uniform(0, 30)])},
    "guide_bar.extremes": lambda r: {"AB": r.uniform(20, 60), "AC": r.uniform(70, 150)},
    "crank_slider.design_by_K": lambda r: {"K": r.uniform(1.05, 1.8), "H": r.uniform(20, 80), "e": r.uniform(0, 30)},
    "crank_rocker.design_by_K": lambda r: {"K": r.uniform(1.1, 1.5), "CD": r.uniform(250, 350),
                                           "psi": r.uniform(25, 45),
                                           **({"AB": r.uniform(50, 100)} if r.random() < 0.5
                                              else {"BC": r.uniform(220, 300)})},
    "crank_slider.best_by_K": lambda r: {"K": r.uniform(1.1, 1.6), "H": r.uniform(30, 80)},
}


@pytest.mark.parametrize("name", sorted(TAPED_CASES))
def test_taped_solves_equal_full_solves_bit_for_bit(name):
    """Random variants: answers, points, checks, warnings, stats and the JSON of a taped solve equal a full
    scene's (or the same refusal), and most solves after the first few are taped."""
    rng = random.Random(11)
    recipe = get_recipe(name)
    taped = solved = 0
    for _ in range(40):
        problem = problem_from_dict({"recipe": name, "given": TAPED_CASES[name](rng)}, name="v")
        try:
            lean = solve(problem)
            was_taped = is_taped(lean.scene)
            got = (lean.solution_values, lean.points, lean.checks, lean.warnings, lean.to_json())
        except ValueError as exc:
            got, was_taped = str(exc), False
        try:
            warnings = recipe.validate(problem.given) if recipe.validate else []
            full = Solution(problem, recipe, recipe.construct(problem.given), warnings)
            want = (full.solution_values, full.points, full.checks, full.warnings, full.to_json())
        except ValueError as exc:
            want = str(exc)
        assert repr(got) == repr(want)
        taped += was_taped
        solved += not isinstance(want, str)
    assert solved >= 10 and taped >= solved // 2


def test_a_taped_solution_draws_the_same_svg_as_a_fresh_one():
    g = {"AB": 50, "BC": 70, "CD": 80, "AD": 90}
    for _ in range(3):
        s = solve(problem_from_dict({"recipe": "crank_rocker.extremes", "given": g}, name="d"))
        s.answers
    assert is_taped(s.scene)
    _TAPES.clear()
    scene_module._KEEP.clear()
    fresh = solve(problem_from_dict({"recipe": "crank_rocker.extremes", "given": g}, name="d"))
    assert s.svg() == fresh.svg()


def test_a_taped_scene_that_completes_itself_while_evaluating_keeps_what_it_computes():
    """Points outside the plan: the scene completes itself in the middle of an evaluation, whose values must
    land in the scene's memo (stats count them, as for a planned scene)."""
    g = {"AB": 30.0, "BC": 100.0, "e": 10.0}
    problem = problem_from_dict({"recipe": "crank_slider.extremes", "given": g}, name="p")
    for _ in range(3):
        s = solve(problem)
        s.answers                                            # the plan: the answers only
    assert is_taped(s.scene)
    assert set(s.points) == {"A", "B1", "C1", "B2", "C2"}
    assert not is_taped(s.scene) and all(s.scene.is_evaluated(k) for k in s.points)
    full = Solution(problem, s.recipe, s.recipe.construct(problem.given), [])
    full.answers, full.points
    assert s.stats == full.stats


def test_a_replayed_scene_can_complete_itself_outside_a_solution():
    """A back-substitution rebuilds the designed linkage through the analysis recipe's tape; a failing step
    there must be worded with its own numbers, so the replayed scene completes itself without a Solution."""
    r = get_recipe("crank_rocker.extremes")
    for g in ({"AB": 50.0, "BC": 70.0, "CD": 80.0, "AD": 90.0},) * 3:
        c = construct_taped(r, g)
        c.scene.value("theta")
    c = construct_taped(r, {"AB": 30.0, "BC": 70.0, "CD": 80.0, "AD": 90.0})
    assert is_taped(c.scene)
    assert c.scene.caption("D")[0].startswith("Fixed pivot D on the frame line, AD = 90")
    assert not is_taped(c.scene)
