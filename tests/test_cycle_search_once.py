"""solve_cycle searches each output's stationary points once per problem: an output listed in both
``extremes`` and ``strokes`` (and a stroke's warning) reuses the points (a speed change: the same answers)."""
import math
from collections import Counter
from pathlib import Path

import pytest

from geomcon.kinematics import result
from geomcon.kinematics.cycle import stationary_points, stroke
from geomcon.kinematics.problem import load_cycle

CYCLES = sorted((Path(__file__).resolve().parent.parent / "problems" / "cycles").glob("*.toml"))


@pytest.mark.parametrize("path", CYCLES, ids=lambda p: p.stem)
def test_each_output_searched_once(path, monkeypatch):
    calls: Counter = Counter()

    def counted(m, name, start=0.0, stop=2 * math.pi):
        calls[(name, start, stop)] += 1
        return stationary_points(m, name, start, stop)

    monkeypatch.setattr(result, "stationary_points", counted)
    monkeypatch.setattr("geomcon.kinematics.cycle.stationary_points", counted)
    r = result.solve_cycle(load_cycle(path))
    assert calls and max(calls.values()) == 1, calls
    p = r.problem
    for q in p.strokes:                  # the points handed to stroke are the ones it finds by itself
        assert stroke(p.mechanism, q, stationary_points(p.mechanism, q)) == stroke(p.mechanism, q)
