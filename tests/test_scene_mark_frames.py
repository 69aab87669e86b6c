"""A mark appears in the player no earlier than what it is drawn on (issue 11, hram11): θ = 180°(K − 1)/(K + 1) is
step 1 of every design by K, and its mark, drawn with the measurement it shows, stood at step 1 about a vertex and
lines not yet drawn (21 players, 000-02's among them, showed a floating arc at their first step)."""
from __future__ import annotations

from pathlib import Path

import pytest

from geomcon.problems import load_problem
from geomcon.scene import Ref, Role
from geomcon.solve import solve

PROBLEMS = sorted((Path(__file__).resolve().parents[1] / "problems").glob("*.toml"))


def _refs(v) -> list[str]:
    """The steps a step's arguments refer to (Refs, also inside tuples, lists and dicts)."""
    if type(v) is Ref:
        return [v.key]
    if isinstance(v, (tuple, list)):
        return [k for x in v for k in _refs(x)]
    if isinstance(v, dict):
        return [k for x in v.values() for k in _refs(x)]
    return []


@pytest.mark.parametrize("path", PROBLEMS, ids=lambda p: p.stem)
def test_no_annotation_is_drawn_before_the_steps_it_stands_on(path):
    sc = solve(load_problem(path)).drawing_scene
    frames = sc.frames()
    where = {s.key: i for i, group in enumerate(frames, 1) for s in group}
    late = []
    for i, group in enumerate(frames, 1):
        for s in group:
            if s.role is Role.ANNOTATION:
                deps = [d for d in _refs((s.args, s.kwargs)) if d in where]
                late += [(s.key, i, d, where[d]) for d in deps if where[d] > i]
    assert not late


def test_the_slotters_theta_mark_comes_with_its_lines():
    """000-02: θ's mark comes with B2 (step 9), the last of A, B1, B2 it stands on, not at step 1."""
    sc = solve(load_problem(Path(__file__).resolve().parents[1] / "problems" / "000-02_slotter_design_by_K.toml")).drawing_scene
    where = {s.key: i for i, group in enumerate(sc.frames(), 1) for s in group}
    assert where["theta"] == 1
    assert where["mark_theta"] == max(where["A"], where["B1"], where["B2"]) == where["B2"]
