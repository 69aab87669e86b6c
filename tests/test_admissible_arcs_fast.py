"""admissible_arcs tests A on the θ-circle from its coordinates (``valid_xy``) instead of making a point and
calling ``is_valid`` (a speed change): the same arcs, to the bit, as the rule through points."""
import math
import random

from geomcon.geometry import Arc, Circle, Point
from geomcon.recipes.common import gamma_min_of, is_valid
from geomcon.recipes.crank_rocker_design import admissible_arcs


def _by_points(k, C1, C2, D, CD, gamma_allow):
    """The arcs as the rule through points finds them (the earlier body of admissible_arcs)."""
    def ok(t):
        A = k.at(t)
        if not is_valid(A, C1, C2, D, CD):
            return False
        return gamma_allow is None or gamma_min_of(A, D, C1, C2) >= gamma_allow

    n = 720
    ts = [2 * math.pi * i / n for i in range(n)]
    flags = [ok(t) for t in ts]
    if all(flags):
        return (Arc(k.center, k.r, 0.0, 2 * math.pi),)
    start = flags.index(False)
    arcs, t0 = [], None
    for j in range(1, n + 1):
        i, prev = (start + j) % n, (start + j - 1) % n
        if flags[i] != flags[prev]:
            a, b = ts[prev], ts[prev] + 2 * math.pi / n
            for _ in range(45):
                m = (a + b) / 2
                a, b = (m, b) if ok(m) == flags[prev] else (a, m)
            edge = (a + b) / 2
            if flags[i]:
                t0 = edge
            elif t0 is not None:
                arcs.append(Arc(k.center, k.r, t0, (edge - t0) % (2 * math.pi)))
                t0 = None
    return tuple(arcs)


def test_same_arcs_as_through_points():
    rng = random.Random(11)
    D = Point(0.0, 0.0)
    found = 0
    for _ in range(40):
        CD = rng.uniform(40, 120)
        psi = rng.uniform(20, 80)
        C1 = Point(CD * math.cos(math.radians(90 + psi / 2)), CD * math.sin(math.radians(90 + psi / 2)))
        C2 = Point(CD * math.cos(math.radians(90 - psi / 2)), CD * math.sin(math.radians(90 - psi / 2)))
        r = rng.uniform(0.6, 3.0) * math.dist((C1.x, C1.y), (C2.x, C2.y))
        mx, my = (C1.x + C2.x) / 2, (C1.y + C2.y) / 2
        h = math.sqrt(max(r * r - ((C2.x - C1.x) ** 2 + (C2.y - C1.y) ** 2) / 4, 0.0))
        k = Circle(Point(mx, my + rng.choice((-1, 1)) * h), r)
        for gamma in (None, rng.uniform(20, 50)):
            got = admissible_arcs(k, C1, C2, D, CD, gamma)
            assert got == _by_points(k, C1, C2, D, CD, gamma)
            found += len(got)
    assert found > 20          # the cases do have arcs with refined ends
