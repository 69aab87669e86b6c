"""Seed 000-03: the slotter's velocity and acceleration polygons as printed in the seed's section 七, audited.

Every printed arithmetic step is recomputed from its own printed operands (what it claims, what it gives), the
position the polygons were drawn at is reconstructed from the printed position-only ratios, and the problem file
at that position reports the exact values and the printed ones' deviations."""
from __future__ import annotations

import math
from pathlib import Path

from geomcon.analytic.kinematics import slotter
from geomcon.problems import load_problem
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
PROBLEM = ROOT / "problems/000-03_slotter_velocity_polygons.toml"
MACHINE = {"AB": 70, "AC": 161, "CD": 115, "DE": 46, "CF": 115.4, "omega": 4.8147, "branch": "above"}


def test_printed_crank_speed_is_n_50_not_the_machines_46():
    assert round(2 * 3.14 * 50 / 60, 3) == 5.233                    # printed, with π = 3.14 and n = 50
    assert round(2 * 3.14 * 46 / 60, 4) == 4.8147                   # the program's W1 and the cycle diagram's n2 = 46
    assert round(2 * math.pi * 46 / 60, 4) == 4.8171


def test_printed_VA2_needs_a_45_mm_crank():
    assert round(35 * 2 * math.pi * 50 / 60, 2) == 183.26            # printed 236
    assert round(236 / (2 * math.pi * 50 / 60), 2) == 45.07          # the crank length 236 needs
    assert round(70 * 4.8147, 2) == 337.03                           # the machine's crank pin speed


def test_printed_aA2_is_the_rounded_omega_of_n_46():
    assert math.isclose(4.8 ** 2 * 70, 1612.8)                        # printed 1612.8
    assert round((2 * math.pi * 50 / 60) ** 2 * 70, 1) == 1919.1      # what its formula (n = 50) gives
    assert round(4.8147 ** 2 * 70, 1) == 1622.7


def test_printed_aB_beta_and_ac():
    assert round(181 / 213 * 1612.8, 1) == 1370.5                     # right as arithmetic
    assert round(1370.5 / 95.610, 3) == 14.334                         # β printed 14.33
    assert round(18.906 * 14.33, 2) == 270.92                          # printed 260.734
    assert round(260.734 / 14.33, 3) == 18.195                         # the drawn length the printed ac needs


def _r1(phi: float) -> float:
    r = slotter(phi=phi, **MACHINE)
    return r["vB3"] / (MACHINE["omega"] * MACHINE["AB"])


def _root(lo: float, hi: float) -> float:
    f = lambda x: _r1(x) - 220 / 236
    for _ in range(100):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if (f(lo) > 0) == (f(mid) > 0) else (lo, mid)
    return lo


def test_the_position_is_where_the_first_printed_polygon_step_holds():
    a, b = _root(160, 175), _root(185, 200)                           # vA2 downwards: 90° < φ < 270°
    assert round(a, 2) == 167.83 and round(b, 2) == 192.17
    phi = load_problem(PROBLEM).given["phi"]
    assert phi == round(b, 2)
    # of the two, the one nearer the printed vC/vB = 290/330
    ratio = lambda x: abs(slotter(phi=x, **MACHINE)["vE"]) / slotter(phi=x, **MACHINE)["vD"]
    assert abs(ratio(b) - 290 / 330) < abs(ratio(a) - 290 / 330)
    assert round(ratio(b), 4) == 0.9813 and round(ratio(a), 4) == 0.9938


def test_printed_vB_over_vA4_is_out_of_reach():
    # vB/vA4 = O4B/O4A; O4A is at least 161 − 70 = 91 mm, so the ratio is at most 115/91 < 1.5
    best = max(slotter(phi=x / 10, **MACHINE)["vD"] / slotter(phi=x / 10, **MACHINE)["vB3"] for x in range(1, 3600))
    assert best <= 115 / 91 + 1e-12 and round(115 / 91, 4) == 1.2637
    assert round(115 / 1.5, 1) == 76.7


def test_problem_audits_the_printed_values():
    sol = solve(load_problem(PROBLEM))
    assert sol.ok
    rows = {r["quantity"]: r for r in sol.published}
    assert set(rows) == {"vB3", "vD", "vE", "aD", "aE", "omega3"}
    ex = slotter(phi=192.17, **MACHINE)
    for name, row in rows.items():
        assert math.isclose(row["exact"], ex[name], rel_tol=1e-6), (name, row)
    assert round(ex["vB3"], 2) == 314.16 and round(ex["vD"], 2) == 385.41 and round(ex["vE"], 2) == 378.18
    assert round(ex["aD"], 1) == 2154.3 and round(ex["aE"], 1) == -2026.3 and round(ex["omega3"], 4) == -3.3514
    assert all(row["doubtful"] for row in rows.values())             # none of the printed values holds
