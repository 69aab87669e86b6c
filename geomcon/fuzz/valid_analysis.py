"""Random valid problems of the linkage-analysis family (issue 14): ``four_bar.analysis``,
``four_bar.link_ranges``, ``rotating_guide_bar.extremes`` and ``crank_rocker.best_by_K``.

Ground truth by how a case is made, by routes neither the construction nor the twin takes: a chain's type
from driving each frame joint through 3600 steps and checking that the other dyad closes (chains within
1e-3 of a Grashof or assembly boundary are drawn again), the immovable lengths of a link from the sum of the
other three, the Whitworth's quick stroke from ``atan2``.

Examples
--------
>>> import random
>>> case = GENERATORS["four_bar.analysis"](random.Random(2))
>>> case.problem["recipe"], sorted(case.expect)
('four_bar.analysis', ['grashof', 'type'])
"""
from __future__ import annotations

import math
import random

from .case import Generator, ValidCase

LINKS = ("AB", "BC", "CD", "AD")
LOOPS = {"AD": "ABCD", "AB": "BCDA", "BC": "CDAB", "CD": "DABC"}


def _length(L: dict[str, float], p: str, q: str) -> float:
    return L[p + q] if p + q in L else L[q + p]


def _turns(x: float, y: float, z: float, w: float, n: int = 3600) -> bool:
    """Drive the joint between links x and y through a full turn: does the dyad z, w close everywhere?"""
    for k in range(n):
        d = math.sqrt(x * x + y * y - 2.0 * x * y * math.cos(2.0 * math.pi * k / n))
        if not abs(z - w) <= d <= z + w:
            return False
    return True


def four_bar_analysis(rng: random.Random) -> ValidCase:
    while True:
        L = {n: rng.uniform(5.0, 200.0) for n in LINKS}
        s = sorted(L.values())
        if min(abs(s[0] + s[3] - s[1] - s[2]), abs(s[3] - s[0] - s[1] - s[2])) > 1e-3 * s[3]:
            break
    frame = rng.choice(LINKS)
    j = LOOPS[frame]
    if s[3] >= s[0] + s[1] + s[2]:
        kind = "immovable"
    else:
        def full(i: int) -> bool:
            p, prev, nxt, opp = j[i], j[i - 1], j[(i + 1) % 4], j[(i + 2) % 4]
            return _turns(_length(L, prev, p), _length(L, p, nxt), _length(L, nxt, opp), _length(L, opp, prev))
        a, b = full(0), full(3)
        kind = "double-crank" if a and b else "crank-rocker" if a or b else "double-rocker"
    given = {**L, "frame": frame}
    return ValidCase({"recipe": "four_bar.analysis", "given": given},
                     {"type": (kind, 0.0), "grashof": (s[0] + s[3] <= s[1] + s[2], 0.0)})


def four_bar_link_ranges(rng: random.Random) -> ValidCase:
    unknown = rng.choice(LINKS)
    known = {n: rng.uniform(5.0, 200.0) for n in LINKS if n != unknown}
    a, b, c = sorted(known.values())
    stuck = ((c - a - b, a + b + c),) if c > a + b else ()
    want = ((0.0, stuck[0][0]),) if stuck else ()
    want += ((a + b + c, math.inf),)
    return ValidCase({"recipe": "four_bar.link_ranges", "given": {**known, "frame": rng.choice(LINKS)}},
                     {"immovable": (want, 1e-9 * (a + b + c))})


def rotating_guide_bar(rng: random.Random) -> ValidCase:
    AC = rng.uniform(5.0, 300.0)
    AB = AC * rng.uniform(1.001, 10.0)
    given = {"AB": AB, "AC": AC}
    quick = 2.0 * math.degrees(math.atan2(math.sqrt((AB - AC) * (AB + AC)), AC))
    expect = {"phi_quick": (quick, 1e-9 * 360.0), "K": ((360.0 - quick) / quick, 1e-9 * (360.0 - quick) / quick)}
    if rng.random() < 0.5:
        given["CD"] = rng.uniform(10.0, 500.0)
        expect["S"] = (2.0 * given["CD"], 1e-9 * given["CD"])
    return ValidCase({"recipe": "rotating_guide_bar.extremes", "given": given}, expect)


def crank_rocker_best(rng: random.Random) -> ValidCase:
    """Any K, ψ and frame: the optimum's own K and θ (by definition) must come back."""
    K = rng.uniform(1.01, 3.0)
    given = {"K": K, "psi": rng.uniform(10.0, 150.0), "AD": rng.uniform(10.0, 500.0)}
    return ValidCase({"recipe": "crank_rocker.best_by_K", "given": given},
                     {"K": (K, 1e-12 * K), "theta": (180.0 * (K - 1.0) / (K + 1.0), 1e-9)})


GENERATORS: dict[str, Generator] = {
    "crank_rocker.best_by_K": crank_rocker_best,
    "four_bar.analysis": four_bar_analysis,
    "four_bar.link_ranges": four_bar_link_ranges,
    "rotating_guide_bar.extremes": rotating_guide_bar,
}
