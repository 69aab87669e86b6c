"""Lean and planned scenes: the evaluation plan learned on one solve only ever saves work on the next one; it
never changes a value, and a scene whose shape changed completes itself or is built again."""
from __future__ import annotations

import random

import pytest

from geomcon.geometry import Above, Point, circle, circle_circle
from geomcon.problems import problem_from_dict
from geomcon.recipes import get_recipe
from geomcon.scene import LeanScenes, PlanMiss, Role, Scene
from geomcon.scene import scene as scene_module
from geomcon.solve import Solution, planned, solve


def _toy(g: dict) -> Scene:
    """A scene whose shape depends on the givens: C is found from circle kA or from circle kB."""
    sc = Scene("toy")
    A = sc.given("A", Point(0.0, 0.0))
    D = sc.given("D", Point(g["AD"], 0.0))
    kA = sc.add("kA", circle, A, g["r"])
    kB = sc.add("kB", circle, A, g["r"] + 1.0)
    kD = sc.add("kD", circle, D, g["r"])
    sc.add("C", circle_circle, kA if g["small"] else kB, kD, branch=Above(A, D))
    sc.add("unused", circle, D, 1.0)
    if sc.drawing:
        sc.add("mark", repr, A, role=Role.ANNOTATION)
        sc.add("bar", circle, D, 2.0)                      # drawing-only: a lean scene never adds it
    return sc


def _full_value(g: dict):
    return _toy(g).value("C")


@pytest.fixture(autouse=True)
def _fresh_plans():
    saved = dict(scene_module._KEEP)
    scene_module._KEEP.clear()
    yield
    scene_module._KEEP.clear()
    scene_module._KEEP.update(saved)


def test_first_solve_learns_and_second_skips_what_it_did_not_need():
    g = {"AD": 8.0, "r": 5.0, "small": True}
    first = planned("toy", _toy, g)
    assert first.unplanned() and first.value("C") == _full_value(g)
    second = planned("toy", _toy, g)
    assert not second.unplanned()
    assert "unused" in second and "kB" in second                       # counted (skipped) ...
    assert second.stats["steps_total"] == first.stats["steps_total"]
    assert second.value("C") == first.value("C")
    assert len(second) < len(first)                                    # ... but not stored


def test_a_changed_shape_is_refused_by_the_plan_and_built_again():
    small = {"AD": 8.0, "r": 5.0, "small": True}
    big = {"AD": 8.0, "r": 5.0, "small": False}
    planned("toy", _toy, small).value("C")                              # learns C from kA
    sc = planned("toy", _toy, big)                                      # the plan skipped kB, which C now needs
    with pytest.raises(PlanMiss):
        sc.value("C")
    assert planned("toy", lambda g: _toy(g).value("C"), big) == _full_value(big)   # planned() retries, learning
    again = planned("toy", _toy, big)
    assert not again.unplanned() and again.value("C") == _full_value(big)


def test_a_scene_that_can_rebuild_completes_itself_and_keeps_its_values():
    g = {"AD": 8.0, "r": 5.0, "small": True}
    planned("toy", _toy, g).value("C")
    sc = planned("toy", _toy, g)
    sc.rebuild_with(lambda: _toy(g))
    c = sc.value("C")
    assert not sc.drawing and sc.is_evaluated("C")
    assert sc.value("unused").r == 1.0                                 # a skipped step: the scene completes
    assert sc.drawing and "mark" in [s.key for s in sc.steps] and sc.is_evaluated("C") and sc.value("C") is c


def test_a_scene_that_completes_itself_while_culling_leaves_no_plan_for_lean_scenes_of_its_old_shape():
    g = {"AD": 8.0, "r": 5.0, "small": True}
    planned("toy", _toy, g).value("C")
    first, second = planned("toy", _toy, g), planned("toy", _toy, g)     # the same lean shape
    first.rebuild_with(lambda: _toy(g))
    assert first.evaluate(["C", "unused"])["unused"].r == 1.0             # completes itself while culling
    second.rebuild_with(lambda: _toy(g))
    assert second.evaluate(["C", "unused"])["C"] == first.value("C")       # its own plan, not the full scene's


def test_a_drawing_only_step_a_lean_scene_never_added_completes_it():
    g = {"AD": 8.0, "r": 5.0, "small": True}
    planned("toy", _toy, g).value("C")
    for ask in (lambda sc: sc.value("bar").r, lambda sc: sc["bar"].key, lambda sc: "bar" in sc):
        sc = planned("toy", _toy, g)
        sc.rebuild_with(lambda: _toy(g))
        c = sc.value("C")
        assert ask(sc) in (2.0, "bar", True)
        assert sc.drawing and sc.value("C") is c
    with LeanScenes():
        lean = _toy(g)
    assert "bar" not in lean
    with pytest.raises(KeyError):
        lean.value("bar")                                  # no rebuild: nothing to complete from


def test_a_lean_scene_without_rebuild_refuses_skipped_annotations():
    with LeanScenes():
        sc = _toy({"AD": 8.0, "r": 5.0, "small": True})
    assert sc.lean and not sc.drawing and "mark" not in sc
    with pytest.raises(PlanMiss):
        sc.complete()


RECIPE_CASES = {
    "crank_rocker.extremes": lambda r: {"AB": r.uniform(20, 40), "BC": r.uniform(60, 80), "CD": r.uniform(60, 80),
                                        "AD": r.uniform(70, 90), "branch": r.choice(["above", "below"])},
    "crank_slider.design_by_K": lambda r: {"K": r.uniform(1.05, 1.8), "H": r.uniform(20, 80), "e": r.uniform(0, 30)},
    # two forms in one run: the scene's shape changes between variants, the plan must follow
    "crank_rocker.design_by_K": lambda r: {"K": r.uniform(1.1, 1.5), "CD": r.uniform(250, 350),
                                           "psi": r.uniform(25, 45),
                                           **({"AB": r.uniform(50, 100)} if r.random() < 0.5
                                              else {"BC": r.uniform(220, 300)})},
}


@pytest.mark.parametrize("name", sorted(RECIPE_CASES))
def test_planned_solves_equal_full_solves_bit_for_bit(name):
    """Random variants solved in a row (each following the plan the others taught) against the same variant
    solved on a full scene with no plan: identical answers, points and checks, or the same refusal."""
    rng = random.Random(2026)
    recipe = get_recipe(name)
    solved = 0
    for _ in range(30):
        problem = problem_from_dict({"recipe": name, "given": RECIPE_CASES[name](rng)}, name="v")
        try:
            lean = solve(problem)
            got = (lean.solution_values, lean.points, lean.checks)
        except ValueError as exc:
            got = str(exc)
        try:
            warnings = recipe.validate(problem.given) if recipe.validate else []
            full = Solution(problem, recipe, recipe.construct(problem.given), warnings)   # full scene, no plan
            assert full.scene.drawing and full.scene.unplanned()
            want = (full.solution_values, full.points, full.checks)
        except ValueError as exc:
            want = str(exc)
        assert got == want
        solved += not isinstance(want, str)
    assert solved >= 10


def test_the_order_plans_are_learned_in_changes_no_byte_of_the_json():
    """Solved after each other in any order (each following plans the others taught), the bundled problems
    give their gallery JSON byte for byte."""
    from pathlib import Path

    from geomcon.gallery import problem_files, to_json_text
    from geomcon.problems import load_problem

    root = Path(__file__).resolve().parents[1]
    files = [f for f in problem_files(root / "problems") if f.name[:3] in ("001", "004", "100")]
    rng = random.Random(3)
    for order in (files[::-1], rng.sample(files, len(files))):
        scene_module._KEEP.clear()
        for f in order:
            sol = solve(load_problem(f))
            assert to_json_text(sol) == (root / "gallery" / f"{sol.problem.id}.json").read_text(), f.name


def test_an_angle_mark_is_drawn_with_the_step_that_measures_it():
    """001-08: the marks of θ, ψ and the γs are added last but appear in the frames of their measurements."""
    from geomcon.problems import load_problem
    from pathlib import Path
    sol = solve(load_problem(Path(__file__).resolve().parents[1] / "problems" / "001-08_crank_rocker.toml"))
    sc = sol.drawing_scene
    for mark, measured in (("mark_theta", "theta"), ("mark_psi", "psi"), ("mark_gamma_1", "gamma_1"),
                           ("mark_gamma_2", "gamma_2")):
        assert sc.number(mark) == sc.number(measured) < len(sc.frames())
