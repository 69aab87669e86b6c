"""The cams' searches that only need a value (ρmin of a base-radius design, the sampling step of a roller's
profile, a flat face's bend and contact extremes, the support lines of α_allow) refine on the scalar path
(Brent on floats, :func:`geomcon.cam.profile.brent_max1`), never by golden sections on arrays: the same ``xtol``
in a third of the calls, the same values (the gallery's bytes do not move).

Each test fails on the tree before this change: there every one of these searches ran
:func:`geomcon.cam.profile._golden_all`.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from geomcon.cam import profile
from geomcon.cam.program import parse_program
from geomcon.problems import load_problem
from geomcon.recipes import cam_base_radius as cbr
from geomcon.recipes import cam_translating as transl
from geomcon.solve import solve

PROBLEMS = Path(__file__).resolve().parent.parent / "problems"


@pytest.fixture
def golden_calls(monkeypatch):
    """The number of golden-section searches on arrays run while the test runs."""
    calls = []
    real = profile._golden_all

    def counted(*args, **kwargs):
        calls.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(profile, "_golden_all", counted)
    return calls


@pytest.mark.parametrize("stem", ["200-19_base_radius_alpha_and_rho", "200-20_oscillating_base_radius_rho",
                                  "200-18_base_radius_flat_gate2020", "200-10_base_radius_centred"])
def test_base_radius_designs_search_on_floats(stem, golden_calls):
    sol = solve(load_problem(PROBLEMS / f"{stem}.toml"))
    assert sol.ok
    assert golden_calls == []


@pytest.mark.parametrize("stem", ["000-07_slotter_cam_actual_profile", "200-01_cam_roller_offset",
                                  "200-02_cam_flat_face"])
def test_drawn_profiles_sample_on_floats(stem, golden_calls):
    sol = solve(load_problem(PROBLEMS / f"{stem}.toml"))
    sol.drawing_scene.evaluate([s.key for s in sol.drawing_scene.steps])
    assert golden_calls == []


def test_pitch_rho_min_is_the_array_search_value():
    """The design's ρmin (scalar refinement) against a dense sampling of the same curvature: never below the
    samples' best, and within the refinement's reach of it."""
    prog = parse_program([{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
                          {"kind": "return", "angle": 90, "law": "cycloidal"}, {"kind": "dwell", "angle": 90}])
    h, e, s0 = 20.0, 8.0, 35.0
    rho = cbr.pitch_rho_min(prog, h, "ccw", e, s0)
    curve = transl._pitch_curve(prog, h, e, s0, -1.0)
    d = np.linspace(0.0, profile.TWO_PI, 200001)[:-1]
    k = curve.orientation * profile.curvature(curve.eval(d))
    dense = 1.0 / float(k.max())
    assert rho <= dense * (1 + 1e-12)
    assert math.isclose(rho, dense, rel_tol=1e-8)


def test_equal_cams_share_one_profile_and_a_curve_one_rho_min(monkeypatch):
    """The slotter's problems draw one cam: its actual profile is made once in a process (cam.oscillating keeps
    it per cam, roller and tolerance), and a pitch curve's ρmin is searched once (the recipe's ρmin step, then
    the roller profile, read it)."""
    from geomcon.recipes.cam_common import PROFILE_KEY

    a = solve(load_problem(PROBLEMS / "000-06_slotter_cam_pitch_points.toml")).drawing_scene.value(PROFILE_KEY)
    b = solve(load_problem(PROBLEMS / "000-07_slotter_cam_actual_profile.toml")).drawing_scene.value(PROFILE_KEY)
    assert a is b and a.trimmed
    searches = []
    real = profile.maximise
    monkeypatch.setattr(profile, "maximise", lambda *args, **kw: searches.append(1) or real(*args, **kw))
    curve = transl._pitch_curve(parse_program([{"kind": "rise", "angle": 180, "law": "cosine"},
                                               {"kind": "return", "angle": 180, "law": "cosine"}]), 10.0, 0.0, 40.0, -1.0)
    first = profile.rho_min(curve)
    assert profile.rho_min(curve) is first and len(searches) == 1
