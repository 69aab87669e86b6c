"""Start-up: the registry is lazy, so solving a linkage problem loads neither the cam modules nor numpy,
shapely or svgwrite (they cost more than the rest of a solve); a cam problem loads what it needs."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
HEAVY = ("numpy", "shapely", "svgwrite", "geomcon.cam")

PROBE = """
import contextlib, io, sys
from geomcon.cli import main
with contextlib.redirect_stdout(io.StringIO()):
    rc = main(["solve", sys.argv[1], *sys.argv[2:]])
print(rc, " ".join(m for m in {heavy!r} if m in sys.modules))
""".format(heavy=HEAVY)


def _loaded(problem: str, *flags: str) -> tuple[int, set[str]]:
    out = subprocess.run([sys.executable, "-c", PROBE, str(ROOT / "problems" / problem), *flags],
                         capture_output=True, text=True, check=True, cwd=ROOT).stdout.split()
    return int(out[0]), set(out[1:])


@pytest.mark.parametrize("problem", ["001-08_crank_rocker.toml", "001-18_crank_slider_design_by_K.toml",
                                     "001-10_crank_rocker_design_coupler.toml", "001-05_guide_bar.toml",
                                     "004-02_best_by_K_1_5.toml", "100-03_four_bar_fixed_pivots_coupler_point.toml",
                                     "100-05_four_bar_function_generation.toml", "100-08_rocker_slider_inclined_guide.toml"])
def test_a_linkage_solve_loads_no_numpy_shapely_svgwrite_or_cams(problem):
    for flags in ((), ("--json",)):
        rc, heavy = _loaded(problem, *flags)
        assert rc == 0 and heavy == set(), (flags, heavy)


def test_a_drawing_and_a_cam_load_what_they_need(tmp_path):
    assert _loaded("001-08_crank_rocker.toml", "--svg", str(tmp_path / "a.svg"))[1] >= {"svgwrite"}
    rc, heavy = _loaded("200-01_cam_roller_offset.toml", "--json")
    assert rc == 0 and {"numpy", "geomcon.cam"} <= heavy


def test_python_dash_m_geomcon_is_the_command():
    out = subprocess.run([sys.executable, "-m", "geomcon", "recipes"], capture_output=True, text=True, cwd=ROOT)
    assert out.returncode == 0 and "crank_rocker.extremes" in out.stdout
