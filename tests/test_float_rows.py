"""The checks' float fast path (``solve._float_rows``, ``solve._cost``) writes ``check_row``'s arithmetic in place
for speed (issue 10): a written-again formula is held here to the original, by repr, over random and special
values (zeros, ties, subnormals, huge, NaN, ±inf), so the two cannot drift apart."""
from __future__ import annotations

import math
import random

from geomcon.check import check_row
from geomcon.solve import _cost, _float_rows

SPECIAL = [0.0, -0.0, 1.0, -1.0, 5e-324, 1e-300, 1e300, -1e300, math.inf, -math.inf, math.nan, 12.5, 12.5 + 1e-14]


def _value(rng: random.Random) -> float:
    r = rng.random()
    if r < 0.25:
        return rng.choice(SPECIAL)
    if r < 0.5:
        return rng.uniform(-1e3, 1e3)
    return rng.uniform(-1, 1) * 10.0 ** rng.randint(-12, 12)


def test_float_rows_equal_check_row_and_the_cost_over_random_answers():
    rng = random.Random(20261126)
    units = ("mm", "deg", "")
    compared = 0
    for _ in range(20000):
        names = [f"q{i}" for i in range(rng.randint(1, 5))]
        pairs = tuple((n, rng.choice(units)) for n in names)
        scales = {u: rng.choice([1.0, 100.0, 1e-6, 1e-300]) for u in units}
        built = {n: _value(rng) for n in names}
        exact = {n: _value(rng) for n in names if rng.random() < 0.9}
        got = _float_rows(built, exact, pairs, scales, "s1.")
        if any(built[n] == exact.get(n) == math.inf for n in names):
            assert got is None
            continue
        assert got is not None
        rows, shown, worst, declared = got
        want = [check_row("s1." + n, built[n], exact[n], scales[u], u) for n, u in pairs if n in exact]
        assert repr(rows) == repr(want)
        assert shown == [n for n, _ in pairs if n in exact] and declared == len(names)
        by_name = {n: scales[u] for n, u in pairs}
        assert repr(worst) == repr(_cost(built, exact, by_name, None))
        compared += len(rows)
    assert compared > 40000
