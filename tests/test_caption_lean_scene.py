"""A caption is read from a solution's scene whatever the process solved before: after earlier solves of the
same recipe taught it a plan or a tape, the scene is lean and keeps only the steps its answers need, and
``Scene.caption`` of a skipped step raised KeyError (found by hlink11n: 400-05's 'vC_w1' after
tests/test_player_parts.py had solved it; order-dependent)."""
from __future__ import annotations

from pathlib import Path

from geomcon.problems import load_problem
from geomcon.solve import solve

PROBLEM = Path(__file__).resolve().parents[1] / "problems" / "400-05_crank_slider_instant_centres.toml"


def test_a_lean_scene_reads_every_caption():
    first = solve(load_problem(PROBLEM)).scene
    keys = list(first.complete()._rec)
    for _ in range(3):                                   # later solves follow the plan, then the tape
        sc = solve(load_problem(PROBLEM)).scene
        for key in keys:
            en, zh = sc.caption(key)
            assert isinstance(en, str) and isinstance(zh, str)
