""":func:`geomcon.render.view.fmt` remembers the numbers it printed: a number prints the same whether met first,
again, or after an equal number of another type, and the memory is bounded."""
from __future__ import annotations

import random

import numpy as np

from geomcon.render import view
from geomcon.render.view import fmt


def _plain(x: float) -> str:
    s = f"{x:.3f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def test_fmt_prints_as_before_first_and_again():
    rng = random.Random(5)
    xs = [round(rng.uniform(-500, 500), rng.choice([0, 1, 2, 3, 4, 7])) for _ in range(5000)]
    xs += [0.0, -0.0, -0.0004, 0.0005, -0.0005, 1e-12, 1e21, float("inf"), float("-inf"), 0.0625, 2.0625]
    for x in xs + xs[::-1]:
        assert fmt(x) == _plain(x), x


def test_equal_numbers_of_other_types_print_alike():
    view._FMT.clear()
    assert fmt(-0.0) == "0" and fmt(0.0) == "0" and fmt(0) == "0"
    assert fmt(2) == fmt(2.0) == fmt(np.float64(2.0)) == "2"
    assert fmt(np.array(3.25)) == "3.25" and fmt(float("nan")) == "nan"


def test_the_memory_is_bounded():
    view._FMT.clear()
    for i in range(view._FMT_MAX + 10):
        fmt(i / 7)
    assert len(view._FMT) <= view._FMT_MAX
