"""A linkage drawing's marks are readable and each names a result (issue 11, session l, hlook11m's review).

Each test here failed on the gallery before the fix it guards:

- 300-01 (four_bar.analysis, the rocker CD drives) marked γ1 = 73.74° at B′, the driver along the frame line,
  but no Results row printed it: γmin = 0 is read at the dead points, where the driver that cannot turn fully
  stops. A γi mark at a frame-line position is drawn only where γmin is read from it.
- 001-20 (shaper by K, DE given) drew the ram at E1 only, while h, f and αmax are read over the whole stroke:
  D2's coupler and block E2 were missing.
- 001-03b (four_bar.analysis, frame AB, a double-crank) drew its linkage solid with the crank BC′ along the frame
  line over BA: one line B–C′, crank and frame not told apart. The solid position is the one turned away.
"""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import pytest

from geomcon.problems import load_problem
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
FOUR_BAR = sorted(p.stem for p in (ROOT / "problems").glob("*.toml")
                  if 'recipe = "four_bar.analysis"' in p.read_text(encoding="utf-8"))


@lru_cache(maxsize=None)
def _scene(stem: str):
    return solve(load_problem(ROOT / "problems" / f"{stem}.toml")).drawing_scene


@pytest.mark.parametrize("stem", FOUR_BAR)
def test_a_frame_line_gamma_is_marked_only_where_gamma_min_is_read(stem):
    sc = _scene(stem)
    marked = [float(sc.value(f"gamma_{i}")) for i in (1, 2) if f"mark_gamma_{i}" in sc]
    if marked:
        assert min(marked) == pytest.approx(float(sc.value("gamma_min"))), (stem, marked)


def test_four_bar_problems_found():
    assert "300-01_four_bar_double_rocker_pressure_angle" in FOUR_BAR


@pytest.mark.parametrize("stem", [p.stem for p in sorted((ROOT / "problems").glob("*.toml"))
                                  if 'recipe = "shaper.design_by_K"' in p.read_text(encoding="utf-8")
                                  and "DE = " in p.read_text(encoding="utf-8")])
def test_a_shaper_with_its_coupler_draws_the_ram_at_both_ends_of_stroke(stem):
    sc = _scene(stem)
    assert "E2" in sc and "D2E2" in sc and "slider_E2" in sc, stem
    E1, E2, D1, D2 = (sc.value(k) for k in ("E1", "E2", "D1", "D2"))
    assert abs(E2 - E1) == pytest.approx(abs(D2 - D1))             # the ram moves by the stroke H
    assert (E1 - D1).dot(E2 - D2) > 0                             # the coupler keeps its side
    guide = sc.value("ram_guide_mark")
    u = (guide.b - guide.a).unit()
    for E in (E1, E2):                                            # both blocks lie on the drawn guide
        assert 0 < (E - guide.a).dot(u) < abs(guide.b - guide.a)


@pytest.mark.parametrize("stem", FOUR_BAR)
def test_no_solid_link_lies_on_the_frame(stem):
    sc = _scene(stem)
    frame = sc.value("frame")
    u = (frame.b - frame.a).unit()
    span = abs(frame.b - frame.a)
    for st in sc.steps:
        if st.style != "link" or not st.key.startswith(("g1_", "g2_")):
            continue
        seg = sc.value(st.key)
        ends = [p - frame.a for p in (seg.a, seg.b)]
        if all(abs(u.cross(q)) < 1e-6 * span for q in ends):             # along the frame line: must not overlap it
            lo, hi = sorted(q.dot(u) for q in ends)
            assert min(hi, span) - max(lo, 0.0) < 1e-6 * span, (stem, st.key)
