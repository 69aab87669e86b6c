"""cam.base_radius for oscillating arms (issue 9): the best centre inside the admissible interval of centre
distances, the twin's far-end rays, tangency of the circle with the region, hostile limits and scales, and the brute-force fuzz generator."""
from __future__ import annotations

import math
import random
import warnings

import numpy as np
import pytest

from geomcon.cam.base_radius import ArmTwin, arm_best
from geomcon.cam.oscillating import OscillatingCam
from geomcon.cam.program import parse_program
from geomcon.errors import GeomconError
from geomcon.fuzz.valid_base_radius import GENERATORS, _arm_best
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

P4 = [{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
      {"kind": "return", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60}]
# fuzz seed 200047: the optimum lies on the far side of the ray from A0 (a < L cos ψ0), where the old twin
# only ever moved outwards (its r0 was 46.596 against the true 45.984)
FAR_SIDE = {"motion": "oscillating", "L": 91.75327003870989, "h": 30.833398548328077, "alpha_allow": 44.14103809608493,
            "rotation": "ccw", "arm": "right",
            "program": [{"kind": "rise", "angle": 64.89367763347944, "law": "cycloidal"},
                        {"kind": "dwell", "angle": 16.882741746483486},
                        {"kind": "return", "angle": 159.64411875970848, "law": "poly345"},
                        {"kind": "dwell", "angle": 118.57946186032858}]}
# fuzz seed 200050: the best centre is where the circle about A0 touches the region (the arc is one point);
# it was refused with "ψ0 ≥ 26.174° and ψ0 ≤ 26.174°"
TANGENT = {"motion": "oscillating", "L": 140.64764102036543, "h": 33.76891190469442, "alpha_allow": 29.969541856826602,
           "rotation": "ccw", "arm": "right", "alpha_allow_return": 68.4226473822168,
           "program": [{"kind": "rise", "angle": 113.22957484111106, "law": "cycloidal"},
                       {"kind": "dwell", "angle": 12.217625603765292},
                       {"kind": "return", "angle": 134.39829506036565, "law": "poly345"},
                       {"kind": "dwell", "angle": 100.15450449475799}]}

# fuzz --seed 77, case 120: the rise binds at the parabolic law's midpoint, a corner of ψ′; the brute force's
# parabolic peak lift rounded that corner into a vertex 0.0085 mm too high (it expected r0 41.12927, the
# construction's 41.12078 is admissible and smallest)
CORNER = {"motion": "oscillating", "L": 151.42938680163394, "h": 32.640306892613644,
          "alpha_allow": 43.12403842773959, "rotation": "cw", "arm": "left",
          "program": [{"kind": "rise", "angle": 96.6368870587166, "law": "parabolic"},
                      {"kind": "dwell", "angle": 79.84775285623796},
                      {"kind": "return", "angle": 125.4073167788987, "law": "poly345"},
                      {"kind": "dwell", "angle": 58.10804330614677}]}


def _solve(**given):
    return solve(problem_from_dict({"recipe": "cam.base_radius", "given": given}, name="t"))


def _over(g, a, psi0_deg):
    """Largest α − α_allow (deg) of the cam at (a, ψ0), by cam.oscillating's tan route on a dense grid."""
    cam = OscillatingCam(a, g["L"], 1.0, g["h"], parse_program(g["program"]), g.get("rotation", "ccw"),
                         g.get("arm", "left"))
    m = cam.motion
    over = -math.inf
    for part, allow in (("rise", g["alpha_allow"]), ("return", g.get("alpha_allow_return"))):
        if allow is None:
            continue
        seg = next(s for s in cam.program.segments if s.kind == part)
        d = np.linspace(seg.start, np.nextafter(seg.end, 0), 20001)
        mo = m(d)
        phi = math.radians(psi0_deg) + mo.psi
        n = g["L"] * (1 - cam.eps * mo.d1) - a * np.cos(phi)
        over = max(over, float(np.max(np.degrees(np.arctan2(np.abs(n), a * np.sin(phi))))) - allow)
    return over


@pytest.mark.parametrize("given", [FAR_SIDE, TANGENT, CORNER], ids=["far-side", "tangent", "corner"])
def test_fuzz_regressions_agree_with_brute_force(given):
    sol = _solve(**given)
    assert sol.ok, [c for c in sol.checks if not c["ok"]]
    brute = _arm_best(given, 3201)
    assert sol.answers["r0"] == pytest.approx(brute[0], rel=1e-7)
    assert _over(given, sol.answers["a"], sol.answers["psi0"]) <= 1e-9


def test_corner_binding_r0_is_admissible_and_smallest():
    """The seed-77 case binds at the corner of ψ′; no nearby (a, smallest ψ0) does better, and the brute force
    (its grid cut at the corner) agrees to its own grid error."""
    sol = _solve(**CORNER)
    r0, a, psi0 = sol.answers["r0"], sol.answers["a"], sol.answers["psi0"]
    assert r0 == pytest.approx(41.1207811, abs=1e-6)
    assert -1e-6 <= _over(CORNER, a, psi0) <= 1e-9           # admissible, and the limit is active
    assert _over(CORNER, a, psi0 - 1e-4) > 0                  # a smaller ψ0 at this a is not
    for f in (0.99, 1.01):                                    # nor a smaller r0 at a nearby distance
        lo, hi = 0.0, psi0 + 5.0
        for _ in range(40):
            lo, hi = (lo, (lo + hi) / 2) if _over(CORNER, f * a, (lo + hi) / 2) <= 0 else ((lo + hi) / 2, hi)
        r = math.sqrt((f * a) ** 2 + CORNER["L"] ** 2 - 2 * f * a * CORNER["L"] * math.cos(math.radians(hi)))
        assert r > r0
    assert _arm_best(CORNER, 1601)[0] == pytest.approx(r0, rel=1e-9)


def test_no_common_point_is_refused_with_numbers():
    g = {"motion": "oscillating", "L": 100.0, "h": 20.0, "alpha_allow": 8.0, "program": P4}
    with pytest.raises(GeomconError, match=r"no centre keeps the pressure angle within the limit.*h = 20°"):
        _solve(**g).answers


@pytest.mark.parametrize("given", [
    {"h": 20, "program": P4, "alpha_allow": 0.001},
    {"h": 20, "program": P4, "alpha_allow": 30, "alpha_allow_return": 0.001},       # was min() of an empty list
    {"h": 1e-6, "program": P4, "alpha_allow": 30},
    {"h": 1e9, "program": P4, "alpha_allow": 30},
    {"motion": "oscillating", "L": 1e-6, "h": 20, "program": P4, "alpha_allow": 30},
    {"motion": "oscillating", "L": 1e9, "h": 20, "program": P4, "alpha_allow": 30},
    {"motion": "oscillating", "L": 100, "h": 20, "program": P4, "alpha_allow": 30, "a": 1e9},
    {"motion": "oscillating", "L": 100, "h": 1e-6, "program": P4, "alpha_allow": 30},
    {"motion": "oscillating", "L": 100, "h": 20, "program": P4, "alpha_allow": 10.5},
], ids=["alpha-1e-3", "return-1e-3", "h-1e-6", "h-1e9", "L-1e-6", "L-1e9", "a-1e9", "arm-h-1e-6", "tangent-far"])
def test_hostile_values_solve_without_warnings(given):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sol = _solve(**given)
        assert sol.ok, [c for c in sol.checks if not c["ok"]]


@pytest.mark.parametrize("given, words", [
    ({"h": 20, "program": P4, "alpha_allow": 89.999}, ["s0 =", "≤ 1e-09·h", "hardly constrains"]),
    ({"motion": "oscillating", "L": 100, "h": 20, "program": P4, "alpha_allow": 89.999}, ["ψ0 =", "hardly constrains"]),
    ({"motion": "oscillating", "L": 100, "h": 20, "program": P4, "alpha_allow": 0.001}, ["no centre keeps"]),
    ({"motion": "oscillating", "L": 100, "h": 20, "program": P4, "alpha_allow": 30, "alpha_allow_return": 90.5},
     ["'alpha_allow_return'", "≤ 90"]),
])
def test_hostile_values_refused_clearly(given, words):
    with pytest.raises(GeomconError) as exc:
        sol = _solve(**given)
        sol.answers
        sol.checks
    assert "\n" not in str(exc.value)
    for w in words:
        assert w in str(exc.value)


def test_twin_given_a_on_the_region_s_far_side():
    """At a given a the twin finds the lower end of the admissible arc from the excess alone."""
    prog = parse_program(FAR_SIDE["program"])
    kw = dict(alpha_allow=FAR_SIDE["alpha_allow"], rotation="ccw", arm="right")
    for a in (70.0, 90.0, 140.0):
        main = arm_best(prog, FAR_SIDE["h"], FAR_SIDE["L"], a=a, **kw)
        twin = ArmTwin(prog, FAR_SIDE["h"], FAR_SIDE["L"], **kw).best(a)
        assert main["psi0"] == pytest.approx(twin["psi0"], rel=1e-9)


@pytest.mark.parametrize("name", sorted(GENERATORS))
def test_fuzz_generators(name):
    """A few random valid problems of each generator: solved, checks pass, the brute-force r0 (and ψ0) met."""
    for i in range(8):
        case = GENERATORS[name](random.Random(900 + i))
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            sol = solve(problem_from_dict(case.problem, name="fuzz"))
            assert sol.ok, (case.problem, [c for c in sol.checks if not c["ok"]])
        for key, (value, tol) in case.expect.items():
            assert abs(sol.answers[key] - value) <= tol, (case.problem, key, sol.answers[key], value, tol)
