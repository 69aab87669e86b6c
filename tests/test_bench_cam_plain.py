"""The scalar cam reference of ``geomcon bench`` computes the same answers as the cam recipes (correctness only:
times are reported by the bench, never asserted here)."""
from __future__ import annotations

from pathlib import Path

import pytest

from geomcon.bench.cam_plain import CAM_PLAIN, covered, pieces, translating_plain
from geomcon.problems import load_problem
from geomcon.solve import solve

PROBLEMS = sorted(p for p in (Path(__file__).resolve().parents[1] / "problems").glob("*.toml")
                  if load_problem(p).recipe in CAM_PLAIN)


def _close(x, y) -> bool:
    if isinstance(x, bool) or isinstance(y, bool):
        return x == y
    return abs(x - y) <= 1e-9 * max(1.0, abs(y))


def test_the_bundled_cams_are_found():
    assert len(PROBLEMS) >= 10 and sum(covered(load_problem(p).recipe, load_problem(p).given) for p in PROBLEMS) >= 10


@pytest.mark.parametrize("path", PROBLEMS, ids=lambda p: p.stem)
def test_the_scalar_reference_gives_the_recipes_answers(path):
    p = load_problem(path)
    if not covered(p.recipe, p.given):
        with pytest.raises(ValueError, match="covers"):
            CAM_PLAIN[p.recipe](p.given)
        return
    want = solve(p).answers
    got = CAM_PLAIN[p.recipe](p.given)
    assert {"alpha_max_rise", "delta_alpha_max_rise", "alpha_max_return", "rho_min_pitch", "undercut"} <= set(got)
    assert set(got) <= set(want) and set(want) - set(got) <= {"profile_x", "profile_y"}
    for k, v in got.items():
        pairs = zip(v, want[k]) if isinstance(v, tuple) else [(v, want[k])]
        assert all(_close(x, y) for x, y in pairs), (k, v, want[k])


def test_a_program_is_split_into_smooth_pieces():
    prog = [{"kind": "rise", "angle": 90, "law": "parabolic"}, {"kind": "dwell", "angle": 90},
            {"kind": "return", "angle": 180, "law": "cycloidal"}]
    ps = pieces(prog, 10.0)
    assert [k for k, *_ in ps] == ["rise", "rise", "dwell", "return"]
    s, v, _ = ps[1][3](ps[1][2])                          # the rise's end: the full stroke, at rest
    assert s == pytest.approx(10.0) and v == pytest.approx(0.0, abs=1e-12)
    assert ps[3][3](ps[3][2])[0] == pytest.approx(0.0, abs=1e-12)


def test_an_offset_moves_the_largest_pressure_angle():
    prog = [{"kind": "rise", "angle": 180, "law": "uniform"}, {"kind": "return", "angle": 180, "law": "uniform"}]
    g = {"follower": "knife", "r0": 40.0, "h": 20.0, "rotation": "ccw", "program": prog}
    centred, right = translating_plain({**g, "e": 0.0}), translating_plain({**g, "e": 10.0})
    assert right["alpha_max_rise"] < centred["alpha_max_rise"] < right["alpha_max_return"]    # 逆转右偏
