"""The command line: every bad-input class gives one line ``error: <file>: <what>``, exit code 2, no
traceback and no output file; good input gives the JSON contract; laziness and determinism."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from geomcon.cli import main

ROOT = Path(__file__).resolve().parents[1]
GOOD = """recipe = "crank_rocker.extremes"
title = "t"
[given]
AB = 50
BC = 70
CD = 80
AD = 90
[published]
theta = 12.5
"""


def _write(tmp_path: Path, text: str, name: str = "p.toml") -> Path:
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def _run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "geomcon.cli", *args], capture_output=True, text=True, cwd=ROOT)


BAD = {
    "malformed TOML": ("recipe = \n[given", "malformed TOML"),
    "unknown recipe": ('recipe = "four_bar.nonsense"\n[given]\nAB = 1\n', "unknown recipe 'four_bar.nonsense'"),
    "no recipe": ("[given]\nAB = 1\n", "missing key 'recipe'"),
    "unknown top key": (GOOD + "\n[extra]\nx = 1\n", "unknown key 'extra'"),
    "missing given": (GOOD.replace("AD = 90\n", ""), "missing given 'AD'"),
    "extra given": (GOOD.replace("AD = 90\n", "AD = 90\nXY = 3\n"), "unknown given 'XY'"),
    "non-numeric": (GOOD.replace("AD = 90", 'AD = "ninety"'), "given 'AD' must be a number, got 'ninety'"),
    "boolean": (GOOD.replace("AD = 90", "AD = true"), "given 'AD' must be a number, got True"),
    "NaN": (GOOD.replace("AD = 90", "AD = nan"), "given 'AD' is not a finite number (nan)"),
    "infinite": (GOOD.replace("AD = 90", "AD = inf"), "given 'AD' is not a finite number (inf)"),
    "negative": (GOOD.replace("AB = 50", "AB = -50"), "given 'AB' must be > 0, got -50"),
    "zero": (GOOD.replace("AB = 50", "AB = 0"), "given 'AB' must be > 0, got 0"),
    "negative offset": ('recipe = "crank_slider.extremes"\n[given]\nAB = 5\nBC = 20\ne = -1\n', "given 'e' must be ≥ 0, got -1"),
    "bad choice": (GOOD + "", None),
    "published not an answer": (GOOD.replace("theta = 12.5", "H = 3"), "published 'H' is not an answer"),
    "published non-numeric": (GOOD.replace("theta = 12.5", 'theta = "x"'), "published 'theta' must be a number"),
    "not a crank": (GOOD.replace("AD = 90", "AD = 95").replace("AB = 50", "AB = 60"), "AB is not a crank (Grashof)"),
    "cannot assemble": (GOOD.replace("AD = 90", "AD = 900"), "cannot be assembled: AD = 900"),
    "rotating guide bar": ('recipe = "guide_bar.extremes"\n[given]\nAB = 300\nAC = 290\n', "rotating guide-bar"),
}
BAD["bad choice"] = (GOOD.replace("AD = 90\n", 'AD = 90\nbranch = "left"\n'), "given 'branch' must be one of above, below")


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_input_is_one_line_exit_2_and_no_output(case, tmp_path, capsys):
    text, expected = BAD[case]
    p = _write(tmp_path, text)
    out_svg, out_html, steps = tmp_path / "o.svg", tmp_path / "o.html", tmp_path / "frames"
    code = main(["solve", str(p), "--json", "--svg", str(out_svg), "--html", str(out_html), "--steps", str(steps)])
    cap = capsys.readouterr()
    assert code == 2
    assert cap.out == ""
    lines = cap.err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {p}: "), cap.err
    assert expected in lines[0]
    assert "Traceback" not in cap.err
    assert not out_svg.exists() and not out_html.exists() and not steps.exists()
    assert not list(tmp_path.glob(".*tmp"))


def test_unreadable_file_and_directory(tmp_path, capsys):
    for path in (tmp_path / "missing.toml", tmp_path):
        assert main(["solve", str(path)]) == 2
        err = capsys.readouterr().err
        assert err.startswith(f"error: {path}: cannot read the file") and err.count("\n") == 1


def test_not_utf8(tmp_path, capsys):
    p = tmp_path / "latin.toml"
    p.write_bytes(b'recipe = "caf\xe9"\n')
    assert main(["solve", str(p)]) == 2
    assert "not UTF-8" in capsys.readouterr().err


def test_subprocess_shows_no_traceback(tmp_path):
    p = _write(tmp_path, GOOD.replace("AB = 50", "AB = -1"))
    r = _run("solve", str(p), "--json")
    assert r.returncode == 2 and r.stdout == "" and "Traceback" not in r.stderr
    assert r.stderr.strip() == f"error: {p}: given 'AB' must be > 0, got -1"


def test_json_contract_and_laziness(tmp_path, capsys):
    p = _write(tmp_path, GOOD)
    assert main(["solve", str(p), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    for key in ("problem", "recipe", "answers", "points", "solutions", "checks", "published", "warnings", "stats"):
        assert key in data
    assert data["recipe"] == "crank_rocker.extremes" and data["problem"] == "p"
    assert set(data["answers"]) >= {"theta", "psi", "K", "gamma_min"}
    assert set(data["points"]) == {"A", "D", "B1", "C1", "B2", "C2"}
    assert data["solutions"] == [data["answers"]]
    assert all(set(c) >= {"quantity", "construction", "analytic", "abs_error", "tol", "unit", "ok"} and c["ok"] for c in data["checks"])
    (pub,) = data["published"]
    assert set(pub) == {"quantity", "published", "exact", "deviation", "rel_deviation", "doubtful"}
    assert pub["doubtful"] is False
    assert pub["quantity"] == "theta" and pub["deviation"] == pytest.approx(12.5 - 12.5055860934, abs=1e-9)
    st = data["stats"]
    assert 0 < st["steps_evaluated"] < st["steps_total"]


def test_answers_compute_no_annotation():
    from geomcon.problems import load_problem
    from geomcon.scene import Role
    from geomcon.solve import solve

    sol = solve(load_problem(ROOT / "problems" / "001-08_crank_rocker.toml"))
    sol.to_json()
    annotations = [s.key for s in sol.scene.steps if s.role is Role.ANNOTATION]
    assert annotations and not any(sol.scene.is_evaluated(k) for k in annotations)


def test_outputs_are_deterministic(tmp_path, capsys):
    p = _write(tmp_path, GOOD)
    outs = []
    for i in range(2):
        d = tmp_path / f"run{i}"
        assert main(["solve", str(p), "--json", "--svg", str(d / "a.svg"), "--html", str(d / "a.html"),
                     "--steps", str(d / "steps")]) == 0
        outs.append((capsys.readouterr().out, *(f.read_bytes() for f in sorted(d.rglob("*")) if f.is_file())))
    assert outs[0] == outs[1]
    assert len(outs[0]) > 4


def test_steps_writes_one_frame_per_numbered_step(tmp_path, capsys):
    from geomcon.problems import load_problem
    from geomcon.solve import solve

    p = _write(tmp_path, GOOD)
    assert main(["solve", str(p), "--steps", str(tmp_path / "f")]) == 0
    n = len(solve(load_problem(p)).scene.frames())
    assert len(list((tmp_path / "f").glob("step-*.svg"))) == n


def test_recipes_lists_every_recipe(capsys):
    assert main(["recipes", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert {"crank_rocker.extremes", "crank_slider.extremes", "guide_bar.extremes"} <= set(data)
    assert list(data["crank_slider.extremes"]["given"]) == ["AB", "BC", "e"]
    assert "H" in data["crank_slider.extremes"]["answers"]


def test_every_bundled_problem_agrees_with_its_twin():
    from geomcon.gallery import problem_files
    from geomcon.problems import load_problem
    from geomcon.solve import solve

    files = problem_files(ROOT / "problems")
    assert len(files) >= 7
    for f in files:
        sol = solve(load_problem(f))
        assert sol.ok, (f.name, [c for c in sol.checks if not c["ok"]])
        assert sol.stats["steps_evaluated"] < sol.stats["steps_total"]


def test_gallery_is_fresh():
    from geomcon.gallery import stale_files

    stale = stale_files(ROOT / "problems", ROOT / "gallery")
    assert not stale, f"gallery is stale, run `geomcon gallery`: {stale}"


def test_recipes_prints_units_defaults_and_meanings(capsys):
    assert main(["recipes"]) == 0
    out = capsys.readouterr().out
    givens = [line for block in out.split("  answers:") if "  given:" in block
              for line in block.split("  given:")[1].splitlines()]           # the answers follow, listed alike
    rotation = [line for line in givens if line.split()[:1] == ["rotation"]]
    assert rotation and all("default ccw" in line and "ccw|cw" in line for line in rotation)
    ab = [line for line in givens if line.split()[:1] == ["AB"]]
    assert all(" mm " in line for line in ab) and {line.split()[2] for line in ab} == {"required", "optional"}
    assert main(["recipes", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["cam.translating"]["given"]["rotation"]["default"] == "ccw"


def test_diagrams_writes_a_cam_problem_s_motion_sheet_and_refuses_a_linkage(tmp_path, capsys):
    out = tmp_path / "d"
    assert main(["solve", str(ROOT / "problems" / "200-01_cam_roller_offset.toml"), "--diagrams", str(out)]) == 0
    sheet = (out / "200-01_cam_roller_offset_motion.svg").read_text(encoding="utf-8")
    assert sheet == (ROOT / "gallery" / "200-01_cam_roller_offset_motion.svg").read_text(encoding="utf-8")
    capsys.readouterr()
    bad = tmp_path / "e"
    assert main(["solve", str(ROOT / "problems" / "001-08_crank_rocker.toml"), "--diagrams", str(bad)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("error: ") and "--diagrams" in err and err.count("\n") == 1 and not bad.exists()


def test_the_summary_says_how_many_solutions_there_are_and_lists_the_others(capsys):
    assert main(["solve", str(ROOT / "problems" / "001-10_crank_rocker_design_coupler.toml")]) == 0
    out = capsys.readouterr().out
    assert "2 valid solutions; the one above is the textbook's choice (solution 1)" in out
    assert "solution 2: AB = 66.981 mm, BC = 260.000 mm, AD = 467.640 mm" in out
    assert "C1 folded: yes, A on D's side of C1C2: no" in out       # yes/no answers as the figure words them
    assert main(["solve", str(ROOT / "problems" / "001-08_crank_rocker.toml")]) == 0
    assert "valid solutions" not in capsys.readouterr().out


def test_a_printed_answer_beyond_drafting_accuracy_is_doubtful_in_text_json_and_figure(tmp_path, capsys):
    p = _write(tmp_path, GOOD.replace("theta = 12.5", "theta = 25"))
    assert main(["solve", str(p)]) == 0                   # a printed answer never fails the solve
    out = capsys.readouterr().out
    assert "θ = 12.506° (= analytic; textbook 25, +99.91 %, doubtful)" in out
    assert "published θ = 25 is doubtful" in out
    assert main(["solve", str(p), "--json", "--svg", str(tmp_path / "f.svg")]) == 0
    (pub,) = json.loads(capsys.readouterr().out)["published"]
    assert pub["doubtful"] is True and pub["rel_deviation"] == 0.9991
    assert "doubtful" in (tmp_path / "f.svg").read_text(encoding="utf-8")


def test_warnings_are_shown_in_the_figure_every_frame_and_the_player(tmp_path, capsys):
    p = _write(tmp_path, GOOD.replace("theta = 12.5", "theta = 25"))
    assert main(["solve", str(p), "--svg", str(tmp_path / "f.svg"), "--html", str(tmp_path / "f.html"),
                 "--steps", str(tmp_path / "frames")]) == 0
    shown = [(tmp_path / "f.svg").read_text(encoding="utf-8"), (tmp_path / "f.html").read_text(encoding="utf-8"),
             *(f.read_text(encoding="utf-8") for f in sorted((tmp_path / "frames").glob("*.svg"))[:2])]
    for text in shown:
        assert "Warnings  警告" in text and "published θ = 25 is doubtful" in text
    clean = _write(tmp_path, GOOD, name="clean.toml")
    assert main(["solve", str(clean), "--svg", str(tmp_path / "c.svg")]) == 0
    assert "Warnings" not in (tmp_path / "c.svg").read_text(encoding="utf-8")


def test_the_summary_reads_as_the_figure_in_the_language_asked(tmp_path, capsys):
    """The terminal prints the Results block's lines (θ = 12.506° …, not theta = 12.5056° ✓ twin) and the
    warnings in the language of --lang: English, Chinese (警告：…, full-width) or both."""
    p = _write(tmp_path, GOOD.replace("theta = 12.5", "theta = 25"))
    assert main(["solve", str(p), "--lang", "en"]) == 0
    en = capsys.readouterr().out
    assert "  θ = 12.506° (= analytic; textbook 25, +99.91 %, doubtful)\n" in en and "✓ twin" not in en
    assert "\n  theta =" not in en and "警告" not in en and "  warning: published θ = 25 is doubtful" in en
    assert main(["solve", str(p), "--lang", "zh"]) == 0
    zh = capsys.readouterr().out
    assert "  极位夹角 θ = 12.506°（与解析解一致；教材 25，+99.91 %，存疑）" in zh
    assert "  警告：教材答案 θ = 25 存疑：与精确值 12.506 相差 +99.91 %，超出作图精度（±3 %）" in zh
    assert "warning:" not in zh
    assert main(["solve", str(p)]) == 0                  # --lang both, the default
    both = capsys.readouterr().out
    assert "warning: published θ = 25" in both and "警告：教材答案 θ = 25" in both
    assert main(["solve", str(p), "--json"]) == 0        # JSON keeps its keys and English warnings: a contract
    data = json.loads(capsys.readouterr().out)
    assert data["warnings"][0].startswith("published theta = 25 is doubtful") and "theta" in data["answers"]


def test_warnings_in_the_figure_follow_lang(tmp_path, capsys):
    p = _write(tmp_path, GOOD.replace("theta = 12.5", "theta = 25"))
    for lang, has, lacks in (("zh", "教材答案 θ = 25 存疑", "published θ"),
                             ("en", "published θ = 25 is doubtful", "教材答案"),
                             ("both", "教材答案 θ = 25 存疑", None)):
        out = tmp_path / f"{lang}.svg"
        assert main(["solve", str(p), "--svg", str(out), "--html", str(tmp_path / f"{lang}.html"), "--lang", lang]) == 0
        capsys.readouterr()
        for f in (out, tmp_path / f"{lang}.html"):
            text = f.read_text(encoding="utf-8")
            assert has in text and (lacks is None or lacks not in text), (lang, f.name)
        sheet = out.read_text(encoding="utf-8")
        assert ("图幅 A4 横向" in sheet) == (lang == "zh") and ("Warnings" in sheet) == (lang != "zh")


def test_the_process_command_freezes_what_is_left_before_the_exit(monkeypatch, capsys):
    """``main()`` run as the process's command (no ``argv``) freezes every object before returning, so that the
    interpreter's last collection does not walk every module imported (~70 ms of a gallery's exit); called with
    ``argv`` (as here, in tests) it leaves the collector alone."""
    import gc
    assert gc.get_freeze_count() == 0
    assert main(["recipes"]) == 0
    assert gc.get_freeze_count() == 0
    monkeypatch.setattr(sys, "argv", ["geomcon", "recipes"])
    try:
        assert main() == 0
        assert gc.get_freeze_count() > 0
    finally:
        gc.unfreeze()
    capsys.readouterr()
