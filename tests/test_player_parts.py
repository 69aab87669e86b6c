"""Each part of a drawing appears in the player (and in ``--steps`` frame k) at the step that constructs it, not
one step early with the step before it (issue 11, hsheet11k's player review in headless Chromium): an unnumbered
step right before a numbered one drawn from it goes with that step (:meth:`geomcon.scene.Scene.frames`).

Found driving every gallery player: 300-01 showed the label vB and the α mark on the velocity at step 23
("Pressure angle α = 90° − γ"), the vector vB only at step 24; every cam with an s–δ diagram (20) showed the
division tick 1 with "Plot s(δ)", one step before "Divide the δ axis …"; 001-03, 001-03b and 300-01 drew one of
the two circles of "circles … meet at B′" with the step before."""
from __future__ import annotations

import re
import shutil
import subprocess
from functools import lru_cache
from pathlib import Path

import pytest

from geomcon.problems import load_problem
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


@lru_cache(maxsize=None)
def _scene(stem: str):
    return solve(load_problem(ROOT / "problems" / f"{stem}.toml")).drawing_scene


def _step_of(sc, start: str) -> int:
    """The number of the step whose English caption starts with ``start``."""
    found = [i for i, g in enumerate(sc.frames(), 1) if sc.caption(g[0].key)[0].startswith(start)]
    assert len(found) == 1, (start, found)
    return found[0]


@pytest.mark.parametrize("stem", ["200-01_cam_roller_offset", "200-02_cam_flat_face", "001-23a_cam_knife_uniform",
                                  "000-04_slotter_cam_psi0", "200-07_oscillating_flat_face"])
def test_the_first_division_tick_appears_with_the_step_that_divides_the_axis(stem):
    sc = _scene(stem)
    divide, plot = _step_of(sc, "Divide the δ axis"), _step_of(sc, "Plot ")
    assert plot < divide
    assert sc.number("sd_div1") == sc.number("sd_ord1") == divide
    assert sc.number("sd_div2") == divide


def test_the_velocity_its_label_and_its_angle_mark_appear_with_the_step_that_draws_the_velocity():
    sc = _scene("300-01_four_bar_double_rocker_pressure_angle")
    vector = _step_of(sc, "The velocity vB of B")
    assert sc.number("v_end") == sc.number("v_line") == sc.number("mark_alpha") == vector
    assert sc.number("alpha") == vector - 1


@pytest.mark.parametrize("stem, meet, circles", [
    ("300-01_four_bar_double_rocker_pressure_angle", "Cg1", ("kBg1", "kCg1")),
    ("300-01_four_bar_double_rocker_pressure_angle", "Cphi", ("kBphi", "kCphi")),
    ("001-03_four_bar_inversions", "Cg1", ("kBg1", "kCg1")),
    ("001-03b_four_bar_frame_AB", "Cg2", ("kBg2", "kCg2"))])
def test_the_circles_that_meet_appear_with_the_step_where_they_meet(stem, meet, circles):
    sc = _scene(stem)
    assert "meet" in sc.caption(meet)[0]
    assert {sc.number(c) for c in circles} == {sc.number(meet)}


def test_a_point_the_step_before_names_stays_with_it():
    """001-19: "B1, B2 on ee with B1B2 = 308, C midway" draws both, though the next step is drawn from B2."""
    sc = _scene("001-19_slotter_rotating_guide_bar")
    assert sc.number("B2") == sc.number("B1")


def test_no_part_of_any_gallery_drawing_appears_before_what_it_is_drawn_from():
    for path in sorted((ROOT / "problems").glob("*.toml")):
        sc = _scene(path.stem)
        frame = {s.key: i for i, g in enumerate(sc.frames(), 1) for s in g}
        for key, k in frame.items():
            early = [d for d in sc[key].deps() if frame.get(d, 0) > k]
            assert not early, (path.stem, key, k, early)


def _dom(page: Path, fragment: str) -> str:
    out = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--dump-dom",
                          page.as_uri() + fragment], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-500:]
    return out.stdout


def _hidden(dom: str, group_id: str) -> bool:
    tag = re.search(rf'<g\b[^>]*\bid="{group_id}"[^>]*>', dom)
    assert tag, group_id
    cls = re.search(r'class="([^"]*)"', tag.group(0))
    return "future" in (cls.group(1).split() if cls else [])


@pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium not installed (apt-get install chromium)")
def test_the_player_shows_vB_and_its_alpha_mark_with_the_vector(tmp_path):
    """300-01's gallery player in headless Chromium: at the step "Pressure angle α = 90° − γ" (23, 24 since the
    dead point's joint Bd1 is a step) neither the end point vB nor the α mark shows (the vector is not drawn
    yet); at the next step all three do."""
    page = tmp_path / "300-01.html"
    page.write_text((ROOT / "gallery" / "300-01_four_bar_double_rocker_pressure_angle.html").read_text(encoding="utf-8"),
                    encoding="utf-8")
    k = _step_of(_scene("300-01_four_bar_double_rocker_pressure_angle"), "Pressure angle α = 90° − γ")
    before, at = _dom(page, f"#step={k}"), _dom(page, f"#step={k + 1}")
    assert f'id="count">step {k} / ' in before and f'id="count">step {k + 1} / ' in at
    for group in ("step-v_end", "step-mark_alpha", "step-v_line"):
        assert _hidden(before, group) and not _hidden(at, group), group


@pytest.mark.parametrize("stem", ["200-12_oscillating_base_radius", "200-20_oscillating_base_radius_rho"])
@pytest.mark.parametrize("part", ["rise", "return"])
def test_the_arm_positions_and_their_points_K_appear_with_the_steps_that_construct_them(stem, part):
    """The oscillating follower's base radius: the arm positions 1–6 at "Turn the arm … positions", their points
    K (and the curve through them) at "lay off BiKi", the lines at α_allow after them. On the base positions 1–6
    and their K came with the wedges, one and two steps late, and the return's had no step of their own."""
    sc = _scene(stem)
    turn = _step_of(sc, f"Turn the arm about A0 to its {part} positions")
    lay = _step_of(sc, f"On each A0Bi lay off BiKi = L·|ψ′i| (ψ′ = dψ/dδ) {'away' if part == 'rise' else 'towards'}")
    wedge = sc.number(f"wedge_{part}0_a")
    assert sc.caption(f"wedge_{part}0_a")[0].startswith("Through every Ki draw the two lines")
    assert sc.caption(f"wedge_{part}0_a")[0].endswith(f"({part})") and sc.caption(f"K_{part}0")[0].endswith(f"in the {part})")
    assert turn + 1 == lay == wedge - 1
    for i in range(7):
        assert sc.number(f"B_{part}{i}") == sc.number(f"arm_{part}{i}") == turn
        assert sc.number(f"K_{part}{i}") == lay
        assert sc.number(f"wedge_{part}{i}_a") == sc.number(f"wedge_{part}{i}_b") == wedge
    assert sc.number(f"K_curve_{part}") == lay


def test_both_lines_of_001_19b_appear_with_the_step_that_draws_them():
    """001-19b: "Lines through A at 90° − θ/2 to the vertical on either side" drew one line; the other came two
    steps later with "B2 on it". Both lines now at their step; B1 and B2 each say on which line they lie."""
    sc = _scene("001-19b_slotter_whitworth_crank_given")
    lines = _step_of(sc, "Lines through A at 90° − θ/2")
    assert sc.number("rB1") == sc.number("rB2") == lines
    assert sc.number("B1") == _step_of(sc, "B1 on the left line") == lines + 1
    assert sc.number("B2") == _step_of(sc, "B2 on the right line") == lines + 2
    assert sc.value("B1").x < sc.value("A").x < sc.value("B2").x
