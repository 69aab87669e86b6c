"""Scenes: explicit references, insertion order, lazy culled evaluation, memoisation, error context,
and the rule that every two-point intersection of every recipe names its branch."""
from __future__ import annotations

import pytest

from geomcon.errors import Unbuildable
from geomcon.geometry import Above, Circle, LeftOf, Point, circle, circle_circle, line_circle
from geomcon.problems import load_problem
from geomcon.recipes import RECIPES
from geomcon.scene import Ref, Role, Scene
from geomcon.gallery import problem_files
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _two_circles(r: float = 5.0) -> Scene:
    sc = Scene("t")
    A = sc.given("A", Point(0, 0))
    D = sc.given("D", Point(8, 0))
    ca = sc.add("ca", circle, A, r, caption=("circle about A", "以 A 为圆心作圆"))
    cd = sc.add("cd", circle, D, 5.0, caption=("circle about D", "以 D 为圆心作圆"))
    sc.add("C", circle_circle, ca, cd, branch=Above(A, D), caption=("they meet at C", "两圆交于 C"))
    sc.add("far", circle, D, 1.0, role=Role.ANNOTATION)
    return sc


def test_references_must_exist_and_keys_are_unique():
    sc = Scene()
    sc.given("A", Point(0, 0))
    with pytest.raises(KeyError, match="unknown step"):
        sc.add("c", circle, Ref("B"), 1.0)
    with pytest.raises(KeyError, match="defined twice"):
        sc.given("A", Point(1, 1))


def test_evaluation_is_culled_and_memoised():
    calls = []

    def counted(c, r):
        calls.append(r)
        return Circle(c, r)

    sc = Scene()
    A = sc.given("A", Point(0, 0))
    sc.add("k1", counted, A, 1.0)
    sc.add("k2", counted, A, 2.0)
    assert sc.stats == {"steps_total": 3, "steps_evaluated": 0}
    sc.value("k1")
    sc.value("k1")
    assert calls == [1.0] and sc.stats["steps_evaluated"] == 2 and not sc.is_evaluated("k2")


def test_branch_rule_is_in_the_caption_in_both_languages():
    sc = _two_circles()
    en, zh = sc.caption("C")
    assert en == "they meet at C (above the line AD)"
    assert zh == "两圆交于 C(位于直线 AD 上方的交点)"
    assert sc.value("C") == Point(4, 3)


def test_failing_step_names_key_caption_and_numbers():
    sc = _two_circles(r=1.0)
    with pytest.raises(Unbuildable) as exc:
        sc.value("C")
    msg = str(exc.value)
    assert msg.startswith("step 'C' (they meet at C (above the line AD)): ")
    assert "distance of centres 8 > r1 + r2 = 6" in msg


def test_closure_orders_dependencies_by_insertion():
    sc = _two_circles()
    assert sc.closure(["C"]) == ["A", "D", "ca", "cd", "C"]


def test_every_two_point_intersection_of_every_recipe_names_its_branch():
    covered, intersections = set(), 0
    for f in problem_files(ROOT / "problems"):
        p = load_problem(f)
        covered.add(p.recipe)
        for s in RECIPES[p.recipe].construct(p.given).scene.steps:
            if s.op in (circle_circle, line_circle):
                assert s.branch is not None, (p.recipe, s.key)
                intersections += 1
    assert covered == set(RECIPES), "every recipe has a bundled problem"
    assert intersections > 50


def test_every_numbered_step_has_both_captions():
    for f in problem_files(ROOT / "problems"):
        p = load_problem(f)
        sc = RECIPES[p.recipe].construct(p.given).scene
        for group in sc.frames():
            en, zh = sc.caption(group[0].key)
            assert en and zh, (p.recipe, group[0].key)


def test_uncaptioned_steps_are_drawn_with_the_step_before():
    sc = RECIPES["crank_rocker.extremes"].construct({"AB": 50, "BC": 70, "CD": 80, "AD": 90}).scene
    assert sc.number("A_ground") == sc.number("A") == 1
    assert sc.number("B1C1") == sc.number("AB1") and sc.number("C1D") == sc.number("AB1")
    assert len(sc.frames()) < len(sc.visible_steps())


def test_wrong_branch_would_be_caught_by_the_points():
    # the same construction with the other branch gives the mirror image: the recipes' branch matters
    sc = _two_circles()
    mirror = Scene()
    A = mirror.given("A", Point(0, 0))
    D = mirror.given("D", Point(8, 0))
    ca = mirror.add("ca", circle, A, 5.0)
    cd = mirror.add("cd", circle, D, 5.0)
    mirror.add("C", circle_circle, ca, cd, branch=LeftOf(D, A))
    assert mirror.value("C") == Point(4, -3) != sc.value("C")
