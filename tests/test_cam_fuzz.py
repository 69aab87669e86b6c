"""Issue 9 for the cams: random valid problems solve with exit 0 and the known answers; the large-scale flat
face, extreme scales without numpy warnings, the size limits (program segments, profile samples, ω), cheap
`at` lists, and no import cycle between the oscillating recipe modules."""
from __future__ import annotations

import ast
import math
import random
import warnings
from pathlib import Path

import numpy as np
import pytest

from geomcon.cam.profile import MAX_SAMPLES, PitchCurve, sample_count
from geomcon.errors import GeomconError, NotAMechanism, ProblemError
from geomcon.fuzz.valid_cams import GENERATORS
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

PROGRAM = [{"kind": "rise", "angle": 150, "law": "cosine"}, {"kind": "dwell", "angle": 30},
           {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60}]


def _solve(recipe: str, given: dict):
    return solve(problem_from_dict({"recipe": recipe, "given": given}, name="t"))


@pytest.mark.parametrize("recipe", sorted(GENERATORS))
@pytest.mark.parametrize("seed", range(12))
def test_random_valid_cams_solve_with_their_known_answers(recipe, seed):
    case = GENERATORS[recipe](random.Random(9000 + seed))
    with warnings.catch_warnings():
        warnings.simplefilter("error")                    # no RuntimeWarning for valid input
        try:
            sol = _solve(recipe, case.problem["given"])
            assert sol.ok, [r for r in sol.checks if not r["ok"]]
            answers = sol.answers
        except GeomconError:
            assert case.may_refuse
            return
    for name, (value, tol) in case.expect.items():
        got = answers[name]
        if isinstance(value, tuple):
            assert len(got) == len(value) and all(abs(a - b) <= tol for a, b in zip(got, value)), (name, got, value)
        else:
            assert abs(got - value) <= tol, (name, got, value)


@pytest.mark.parametrize("k", [1.0, 1e5])
def test_flat_faces_decide_convexity_alike_at_every_scale(k):
    # a cosine law ends with f′(1) ≈ 2e-16, not 0: at r0 = 1.8e6 that roundoff was taken for a velocity drop
    tr = _solve("cam.translating", {"follower": "flat", "r0": 18 * k, "h": 6.1 * k, "program": PROGRAM})
    osc = _solve("cam.oscillating", {"follower": "flat", "a": 60 * k, "r0": 18 * k, "h": 6.1, "program": PROGRAM})
    assert tr.ok and osc.ok
    assert tr.answers["convex"] is True and tr.answers["undercut"] is False
    assert osc.answers["convex"] is True


@pytest.mark.parametrize("k", [1e-7, 1e7])
def test_extreme_scales_solve_and_draw_without_warnings(k):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for given in ({"follower": "roller", "r0": 40 * k, "h": 20 * k, "rr": 10 * k, "program": PROGRAM},
                      {"follower": "knife", "r0": 40 * k, "h": 20 * k, "e": 10 * k, "program": PROGRAM}):
            sol = _solve("cam.translating", given)
            assert sol.ok
            prof = sol.scene.value("profile")
            assert prof.ring().is_simple and len(prof.xy) < 20_000      # the sample count is scale-free
        sol = _solve("cam.oscillating", {"follower": "flat", "a": 60 * k, "r0": 20 * k, "h": 15, "program": PROGRAM})
        assert sol.ok and len(sol.scene.value("profile").xy) < 20_000


def test_a_profile_needing_more_samples_than_the_cap_is_refused_before_sampling():
    def circle(d):
        c, s = np.cos(d), np.sin(d)
        return 40 * s, 40 * c, 40 * c, -40 * s, -40 * s, -40 * c
    with pytest.raises(NotAMechanism, match=f"cap of {MAX_SAMPLES}"):
        sample_count(PitchCurve(circle), 0.0, 1e-12)


def test_programs_are_linear_in_segments_and_limited():
    dwells = [{"kind": "dwell", "angle": 1.0}] * 60
    prog = [{"kind": "rise", "angle": 100, "law": "uniform"}] + dwells + [{"kind": "return", "angle": 200, "law": "cosine"}]
    sol = _solve("cam.translating", {"follower": "knife", "r0": 40, "h": 20, "program": prog})
    assert sol.ok and sol.answers["h"] == pytest.approx(20, rel=1e-12)
    with pytest.raises(NotAMechanism, match="at most 64"):
        _solve("cam.translating", {"follower": "knife", "r0": 40, "h": 20,
                                   "program": prog[:1] + dwells + dwells[:10] + prog[-1:]})


def test_a_thousand_at_angles_cost_a_few_steps():
    at = [i * 0.359 for i in range(1000)]
    sol = _solve("cam.oscillating", {"follower": "roller", "a": 120, "L": 100, "r0": 40, "h": 20, "rr": 8,
                                     "program": PROGRAM, "at": at})
    assert sol.ok and len(sol.answers["psi"]) == 1000 and len(sol.answers["profile_x"]) == 1000
    assert sol.stats["steps_total"] < 400


def test_omega_has_a_documented_maximum():
    with pytest.raises(ProblemError, match="≤ 10000"):
        _solve("cam.eccentric", {"R": 60, "OA": 20, "omega": 1e5})
    sol = _solve("cam.eccentric", {"R": 60, "OA": 20, "omega": 1e4, "delta": 30})
    assert sol.ok and math.isfinite(sol.answers["v"])


def test_the_oscillating_recipe_modules_do_not_import_each_other_both_ways():
    src = Path(__file__).parents[1] / "geomcon" / "recipes" / "cam_oscillating_flat.py"
    names = {n.module for n in ast.walk(ast.parse(src.read_text(encoding="utf-8"))) if isinstance(n, ast.ImportFrom)}
    assert "cam_oscillating" not in names and "cam_translating" not in names
