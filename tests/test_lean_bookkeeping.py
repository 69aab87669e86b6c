"""Issue 10: the solve's bookkeeping cuts keep every value (the gallery is the wider regression test)."""
from __future__ import annotations

import math

import pytest

from geomcon.analytic.design_by_k import rocker_design
from geomcon.errors import NoIntersection
from geomcon.geometry import Point, circle, circle_circle
from geomcon.geometry.branch import Below, LeftOf
from geomcon.scene.compiled import compile_plan
from geomcon.scene.step import Ref


def _rec() -> dict[str, tuple]:
    """Two circles and their two intersections chosen by two rules (B1, B2), as a tape records them."""
    calls = []

    def counted(a, b):
        calls.append(1)
        return circle_circle(a, b)

    meta = (("", ""), None, "", None, True, "")
    rec = {
        "A": (lambda: Point(0.0, 0.0), (), {}, 0, None, (), False, [], meta),
        "D": (lambda: Point(8.0, 0.0), (), {}, 0, None, (), False, [], meta),
        "kA": (circle, (Ref("A"), 5.0), {}, 1, None, (), False, ["A"], meta),
        "kD": (circle, (Ref("D"), 5.0), {}, 1, None, (), False, ["D"], meta),
    }
    left, right = LeftOf(Ref("A"), Ref("D")), Below(Ref("A"), Ref("D"))
    rec["B1"] = (counted, (Ref("kA"), Ref("kD")), {}, 1, left, left.refs(), False, ["kA", "kD", "A", "D"], meta)
    rec["B2"] = (counted, (Ref("kA"), Ref("kD")), {}, 1, right, right.refs(), False, ["kA", "kD", "A", "D"], meta)
    return rec, calls


def test_branches_of_one_intersection_share_one_call() -> None:
    rec, calls = _rec()
    run = compile_plan(rec, ("B1", "B2"), frozenset())
    memo: dict = {}
    run(memo)
    assert len(calls) == 1
    cands = circle_circle(circle(Point(0, 0), 5.0), circle(Point(8, 0), 5.0))
    assert memo["B1"] == LeftOf(Point(0, 0), Point(8, 0)).choose(cands) == Point(4.0, 3.0)
    assert memo["B2"] == Below(Point(0, 0), Point(8, 0)).choose(cands) == Point(4.0, -3.0)
    assert memo["B1"] != memo["B2"]


def test_shared_intersection_that_misses_raises() -> None:
    rec, calls = _rec()
    rec["kA"] = (circle, (Ref("A"), 1.0), {}, 1, None, (), False, ["A"], rec["kA"][8])
    run = compile_plan(rec, ("B2",), frozenset())
    with pytest.raises(NoIntersection):
        run({})


@pytest.mark.parametrize("closing", [{"BC": 260.0}, {"AB": 60.0}])
def test_folded_only_is_the_filter_after(closing) -> None:
    c1 = (290.0 * math.cos(math.radians(106.0)), 290.0 * math.sin(math.radians(106.0)))
    c2 = (290.0 * math.cos(math.radians(74.0)), 290.0 * math.sin(math.radians(74.0)))
    every = rocker_design(1.25, 290.0, c1, c2, **closing)
    assert any(not s["c1_folded"] for s in every)            # the filter has something to drop
    assert rocker_design(1.25, 290.0, c1, c2, c1_folded_only=True, **closing) == [s for s in every if s["c1_folded"]]


def test_plan_of_constants_only() -> None:
    """A plan whose other steps are constants (nothing computed to pass on) still compiles and fills."""
    meta = (("", ""), None, "", None, True, "")
    from geomcon.scene.step import constant
    rec = {"A": (constant, (Point(1.0, 2.0),), {}, 0, None, (), False, [], meta),
           "B": (constant, (Ref("A"),), {}, 1, None, (), False, ["A"], meta)}
    run = compile_plan(rec, ("B",), frozenset())
    memo: dict = {}
    fill, values = run(memo)
    fill(memo, values)
    assert memo == {"A": Point(1.0, 2.0), "B": Point(1.0, 2.0)} and list(memo) == ["A", "B"]


def test_empty_request_compiles() -> None:
    """A request of no steps (a recipe whose answers all come from the tape's own arithmetic) is a plan too."""
    run = compile_plan({}, (), frozenset())
    memo: dict = {}
    assert run(memo) is None and memo == {}
