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


# ----------------------------------------------------------------------------------------------------
# A plain `geomcon solve` (text to stdout) loads only what it runs.

TEXT_ONLY_HEAVY = ("geomcon.gallery", "shutil", "json", "geomcon.render.warning_words")
"""What a text solve of a problem without warnings never needs: the gallery module and json (--json), shutil
(argparse's formatters read the width without it), the warning words (only for a warning to translate)."""

PROBE_TEXT = """
import contextlib, io, sys
from geomcon.cli import main
with contextlib.redirect_stdout(io.StringIO()) as out:
    rc = main(["solve", sys.argv[1]])
print(rc, "warning" in out.getvalue(), " ".join(m for m in {heavy!r} if m in sys.modules))
""".format(heavy=HEAVY + TEXT_ONLY_HEAVY)


@pytest.mark.parametrize("problem", ["001-08_crank_rocker.toml", "001-18_crank_slider_design_by_K.toml",
                                     "001-05_guide_bar.toml", "100-05_four_bar_function_generation.toml"])
def test_a_text_solve_loads_neither_numpy_shapely_nor_the_gallery(problem):
    out = subprocess.run([sys.executable, "-c", PROBE_TEXT, str(ROOT / "problems" / problem)],
                         capture_output=True, text=True, check=True, cwd=ROOT).stdout.split()
    warned = out[1] == "True"                 # a warning is said in Chinese too: its words are loaded then
    assert out[0] == "0" and set(out[2:]) == ({"geomcon.render.warning_words"} if warned else set()), out


def test_the_help_width_is_shutils(monkeypatch):
    import shutil

    from geomcon.cli import help_width
    for columns in (None, "100", "37", "0", "-5", "wide", ""):
        if columns is None:
            monkeypatch.delenv("COLUMNS", raising=False)
        else:
            monkeypatch.setenv("COLUMNS", columns)
        assert help_width() == shutil.get_terminal_size().columns - 2, columns


ARGVS = (["solve", "a.toml"], ["solve", "a.toml", "--json", "--lang", "zh", "--solution", "2", "--portrait"],
         ["solve", "a.toml", "--svg", "x.svg", "--paper", "A3", "--steps", "d", "--html", "p.html"],
         ["cycle", "c.toml", "--csv", "t.csv"], ["recipes", "--json"], ["gallery", "--check", "--jobs", "2"],
         ["bench", "--quick"], ["fuzz", "--valid", "3", "--only", "cam"], ["worksheet", "s.toml", "--out", "d", "--count", "3"],
         ["check", "k.json", "a.csv", "--out", "d"], ["moodle", "k.json", "--out", "b.xml", "--no-figures"])


@pytest.mark.parametrize("argv", ARGVS, ids=lambda a: " ".join(a[:2]))
def test_the_parser_of_one_command_parses_as_the_whole_parser(argv):
    from geomcon.cli import build_parser
    assert vars(build_parser(argv).parse_args(argv)) == vars(build_parser().parse_args(argv))


@pytest.mark.parametrize("argv", [["solve", "--help"], ["cycle", "-h"], ["worksheet", "--help"], ["--help"],
                                  ["solve", "a.toml", "--bogus"], ["solve"], ["solve", "a", "--paper", "A5"],
                                  ["nonesuch"], [], ["gallery", "--jobs", "0"]])
def test_the_parser_of_one_command_says_what_the_whole_parser_says(argv, capsys, monkeypatch):
    from geomcon.cli import build_parser
    monkeypatch.setenv("COLUMNS", "100")
    said = []
    for parser in (build_parser(argv), build_parser()):
        with pytest.raises(SystemExit) as stop:
            parser.parse_args(argv)
        said.append((stop.value.code, capsys.readouterr()))
    assert said[0] == said[1] and said[0][1] != ("", "")
