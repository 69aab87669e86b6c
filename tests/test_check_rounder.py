"""check.rounder(scale): rounded(x, scale) for many x at one scale with the digits worked out once (a speed
change for the cycle plots and animation): the same floats as rounded, for every x."""
import math
import random

from geomcon.check import rounded, rounder


def _either(fn, x):
    try:
        return fn(x)
    except ArithmeticError as exc:
        return type(exc)


def test_rounder_is_rounded():
    rng = random.Random(5)
    scales = [1.0, 360.0, 100.0, 123.456, 1e-6, 7e5, 1e300, 5e-324, 0.0, -3.0, math.inf, math.nan]
    xs = [0.0, -0.0, math.inf, -math.inf, math.nan, 1e-17, 2.0 / 3.0]
    xs += [rng.uniform(-1, 1) * 10.0 ** rng.randint(-20, 20) for _ in range(3000)]
    for sc in scales:
        r = rounder(sc)
        for x in xs + [sc, -sc, math.nextafter(sc, 0.0), math.nextafter(sc, math.inf)]:
            a, b = _either(r, x), _either(lambda y: rounded(y, sc), x)
            if isinstance(a, type) or isinstance(b, type):
                assert a == b, (sc, x, a, b)        # the same error (an infinite scale), or none
                continue
            assert (a == b and math.copysign(1.0, a) == math.copysign(1.0, b)) or (a != a and b != b), (sc, x, a, b)
