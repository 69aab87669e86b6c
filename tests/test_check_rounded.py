"""check.rounded takes round()'s route for 0…300 decimals: the same floats as the text route it replaced
(f"{x:.{n}f}" read back), ties and signs included."""
from __future__ import annotations

import math
import random

from geomcon.check import DIGITS, rounded


def _by_text(x: float, scale: float) -> float:
    if x == 0 or not math.isfinite(x):
        return 0.0 if x == 0 else x
    m = max(abs(x), abs(scale))
    decimals = DIGITS - 1 - math.floor(math.log10(m))
    out = float(f"{x:.{decimals}f}") if decimals >= 0 else float(f"{x:.{DIGITS}g}")
    return out + 0.0


def test_rounded_is_the_text_route():
    rng = random.Random(11)
    cases = [(2.5e-12, 1.0), (-0.5e-11, 1.0), (0.12345678901250, 1.0), (1.0000000000005, 1.0), (-1e-17, 1.0),
             (5e-324, 5e-324), (1e-310, 1e-310), (1e300, 1.0), (123456.5, 1e-300), (2.0 / 3.0, 1e-6)]
    for _ in range(100000):
        x = rng.choice([-1.0, 1.0]) * 10 ** rng.uniform(-320, 300) * rng.random()
        if rng.random() < 0.2:
            x = rng.randint(-10 ** 15, 10 ** 15) / 2.0 ** rng.randint(0, 60)     # binary fractions: decimal ties
        cases.append((x, rng.choice([1.0, 100.0, 1e-9, 10 ** rng.uniform(-310, 300)])))
    for x, scale in cases:
        a, b = rounded(x, scale), _by_text(x, scale)
        assert a == b and math.copysign(1.0, a) == math.copysign(1.0, b), (x, scale, a, b)
