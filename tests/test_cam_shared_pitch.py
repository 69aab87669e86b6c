"""cam.translating: one pitch curve per cam in a process, its ρmin and α_max searched once. A roller's radius
is not in the pitch curve, so a worksheet's drafting ends rr ± δ share the nominal variant's searches (a speed
change: the same answers, bit for bit, as a curve made afresh)."""
import math

import geomcon.cam.profile as profile
import geomcon.recipes.cam_translating as transl
from geomcon.worksheet.solving import solve_given

PROGRAM = [{"kind": "rise", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60},
           {"kind": "return", "angle": 90, "law": "cycloidal"}, {"kind": "dwell", "angle": 90}]
ASKED = ("rho_min_actual", "alpha_max_rise", "alpha_max_return", "rho_min_pitch")


def _given(rr, e=12.0):
    return {"follower": "roller", "r0": 45.0, "e": e, "rr": rr, "h": 25.0, "program": PROGRAM}


def _answers(sol):
    return {k: sol.construction.scene.value(k) for k in ASKED}


def test_rr_ends_share_the_searches(monkeypatch):
    transl._CURVES.clear()
    searches = []
    real = profile.maximise
    monkeypatch.setattr(profile, "maximise", lambda *a, **k: searches.append(1) or real(*a, **k))
    monkeypatch.setattr(transl, "maximise", lambda *a, **k: searches.append(1) or real(*a, **k))
    nominal = _answers(solve_given("cam.translating", _given(10.0)))
    first = len(searches)
    assert first >= 3                          # ρmin, α_max of the rise and of the return
    ends = [_answers(solve_given("cam.translating", _given(rr))) for rr in (11.0, 9.0)]
    assert len(searches) == first              # the same curve: no search again
    for rr, got in zip((11.0, 9.0), ends):
        assert got["rho_min_pitch"] == nominal["rho_min_pitch"]
        assert got["rho_min_actual"] == nominal["rho_min_pitch"] - rr
        assert got["alpha_max_rise"] == nominal["alpha_max_rise"]


def test_shared_answers_are_those_of_a_fresh_curve(monkeypatch):
    transl._CURVES.clear()
    shared = [_answers(solve_given("cam.translating", _given(rr, e))) for rr in (10.0, 8.0) for e in (12.0, 0.0, -0.0)]
    monkeypatch.setattr(transl, "shared_pitch_curve", transl._pitch_curve)
    monkeypatch.setattr(transl, "curve_worst_alpha", transl.worst_alpha)
    fresh = [_answers(solve_given("cam.translating", _given(rr, e))) for rr in (10.0, 8.0) for e in (12.0, 0.0, -0.0)]
    for a, b in zip(shared, fresh):
        for k in ASKED:
            assert a[k] == b[k] or (math.isnan(a[k]) and math.isnan(b[k])), k


def test_signed_zero_offsets_are_two_curves():
    transl._CURVES.clear()
    prog = transl.parse_program(PROGRAM)
    assert transl.shared_pitch_curve(prog, 25.0, 0.0, 45.0, -1.0) is transl.shared_pitch_curve(prog, 25.0, 0.0, 45.0, -1.0)
    assert transl.shared_pitch_curve(prog, 25.0, 0.0, 45.0, -1.0) is not transl.shared_pitch_curve(prog, 25.0, -0.0, 45.0, -1.0)
