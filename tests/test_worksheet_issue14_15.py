"""Issues 14 and 15's recipes as worksheet exercises: for each form a spec of 3 students goes through
``geomcon worksheet`` (exit 0, a key, sheets with the recipe's own statement), and ``geomcon check`` grades a
class in which student 1 answers right and student 2 makes one of the recipe's declared mistakes (its value as
the key's replay gives it: that those values are the textbook's wrong values is tested against closed forms in
test_grading_design_mistakes.py, test_grading_kinematics.py, test_grading_linkage_analysis.py and
test_grading_cams.py): student 1 is all correct, student 2's answer is wrong with that diagnosis.

Every recipe of the two issues is a worksheet exercise; what a worksheet cannot ask is refused with a reason
(an interval of ``four_bar.link_ranges`` or the word ``type`` of ``four_bar.analysis``: the student gives numbers,
``boundaries[i]`` or θ, ψ, K).
"""
from __future__ import annotations

import json

import pytest

from geomcon.cli import main
from geomcon.grading.diagnosis import prepare
from geomcon.grading.keyfile import key_from_json
from geomcon.grading.mistakes import mistakes_of
from geomcon.recipes import get_recipe

PROGRAM = ('[{kind = "rise", angle = 120, law = "cosine"}, {kind = "dwell", angle = 30}, '
           '{kind = "return", angle = 60, law = "cosine"}, {kind = "dwell", angle = 150}]')
HANDBOOK = ('[{kind = "rise", angle = 120, law = "modified_trapezoid"}, {kind = "dwell", angle = 40}, '
            '{kind = "return", angle = 110, law = "double_harmonic"}, {kind = "dwell", angle = 90}]')
FLAT = ('[{kind = "rise", angle = 180, law = "poly", coefficients = [0, 2, -1]}, '
        '{kind = "return", angle = 180, law = "poly", coefficients = [0, 0, 1]}]')
SPECS = {   # form: (recipe, ask, givens)
    # issue 14: linkage analysis
    "analysis": ("four_bar.analysis", ["psi", "K", "gamma_min"], "AB = [40, 45, 50]\nBC = 70\nCD = 80\nAD = 90"),
    "link_ranges": ("four_bar.link_ranges", ["boundaries[0]", "boundaries[1]"], "AB = [150, 160, 170]\nCD = 240\nAD = 210"),
    "guide_offset_lever": ("guide_bar.extremes", ["psi", "H"], "AB = 60\nAC = [100, 105, 110]\ne = 35\nL = 150"),
    "guide_offset": ("guide_bar.extremes", ["theta", "K"], "AB = 60\nAC = [100, 105, 110]\ne = 35"),
    "whitworth": ("rotating_guide_bar.extremes", ["phi_slow", "K"], "AB = 75\nAC = [40, 45, 50]\nCD = 150"),
    # issue 14: design
    "design_crank_frame": ("crank_rocker.design_by_K", ["BC", "CD"], "K = 1.5\nAB = [30, 35, 40]\nAD = 120\npsi = 60"),
    "design_frame_swing": ("crank_rocker.design_by_K", ["AB", "BC"], "K = 1.4\nCD = [70, 75, 80]\npsi = 45\nAD = 100"),
    "best_by_K": ("crank_rocker.best_by_K", ["AB", "gamma_min"], "K = [1.2, 1.25, 1.3]\npsi = 80\nAD = 120"),
    "slotter_AB": ("slotter.design_by_K", ["AC", "CD", "theta"], "K = 2\nH = 150\nAB = [40, 45, 50]"),
    "slotter_AC": ("slotter.design_by_K", ["AB", "CD"], "K = 2\nH = 150\nAC = [20, 25, 30]"),
    # issue 14: cams
    "cam_speeds": ("cam.translating", ["v_max", "a_max"],
                   f'follower = "roller"\nr0 = 35\nrr = 10\nh = [40, 45, 50]\nrotation = "cw"\nomega = 10\nprogram = {PROGRAM}'),
    "cam_handbook_laws": ("cam.translating", ["v_max", "a_max"],
                          f'follower = "roller"\nr0 = 45\ne = 8\nrr = 8\nh = [16, 18, 20]\nomega = 30\nprogram = {HANDBOOK}'),
    "base_radius_flat": ("cam.base_radius", ["r0"], f'follower = "flat"\nh = [30, 35, 40]\nrho_allow = 40\nprogram = {FLAT}'),
    # issue 15: one position
    "four_bar_polygons": ("four_bar.kinematics", ["vC", "vE"],
                          "AB = 50\nBC = 70\nCD = 80\nAD = 90\nphi = [55, 60, 65]\nomega = 10\nepsilon = 20\nBE = 40\nangle_CBE = 30"),
    "slider_polygons": ("crank_slider.kinematics", ["vC", "aC"], "AB = 120\nBC = 250\ne = 60\nphi = [25, 30, 35]\nomega = 2\nepsilon = 3"),
    "coriolis": ("guide_bar.kinematics", ["omega3", "epsilon3"], "AB = 145\nAC = 290\nphi = [25, 30, 35]\nomega = 5"),
    "four_bar_centres": ("four_bar.instant_centres", ["w3_w1"], "AB = 50\nBC = 70\nCD = 80\nAD = 90\nphi = [55, 60, 65]"),
    "slider_centres": ("crank_slider.instant_centres", ["vC_w1"], "AB = 120\nBC = 250\ne = 60\nphi = [25, 30, 35]"),
}


@pytest.mark.parametrize("form", sorted(SPECS))
def test_worksheet_and_check(form, tmp_path):
    recipe, ask, given = SPECS[form]
    spec = tmp_path / "spec.toml"
    spec.write_text(f'title = "{form}"\n[[exercise]]\nrecipe = "{recipe}"\nask = {json.dumps(ask)}\n'
                    f"[exercise.given]\n{given}\n", encoding="utf-8")
    out = tmp_path / "out"
    assert main(["worksheet", str(spec), "--out", str(out), "--count", "3"]) == 0
    key_text = (out / "key.json").read_text(encoding="utf-8")
    data = json.loads(key_text)
    assert len(data["students"]) == 3 and len(list((out / "sheets").glob("*.svg"))) >= 3
    title = get_recipe(recipe).title
    for st in data["students"]:
        statement = st["exercises"][0]["statement"]
        assert not statement["en"].startswith(title) and "{" not in statement["en"] + statement["zh"]
    key = key_from_json(key_text)
    declared = {m.code for m in mistakes_of(recipe)}
    rows = []
    for sid in ("1", "2"):
        ex = key.students[sid].exercises[0]
        values = {a.column: a.expected for a in ex.answers}
        if sid == "2":
            alts = prepare(ex).alts
            column, alt = next((c, a) for c in values for a in alts[c] if a.code in declared)
            values[column] = alt.value
        rows.append(",".join([sid] + [repr(v) for v in values.values()]))
    columns = [a.column for a in key.students["1"].exercises[0].answers]
    answers = tmp_path / "answers.csv"
    answers.write_text(",".join(["id"] + columns) + "\n" + "\n".join(rows) + "\n", encoding="utf-8")
    assert main(["check", str(out / "key.json"), str(answers), "--out", str(tmp_path / "graded")]) == 0
    graded = json.loads((tmp_path / "graded" / "grades.json").read_text(encoding="utf-8"))["rows"]
    assert all(a["verdict"] == "correct" for a in graded[0]["answers"].values())
    wrong = graded[1]["answers"]
    assert (wrong[column]["verdict"], wrong[column]["diagnosis"]) == ("wrong", alt.code)
    assert all(a["verdict"] == "correct" for c, a in wrong.items() if c != column)


@pytest.mark.parametrize("recipe, ask, words", [
    ("four_bar.link_ranges", "crank_rocker[0]", "'boundaries[0]'"),
    ("four_bar.analysis", "type", "a word"),
])
def test_what_a_worksheet_cannot_ask_is_refused(recipe, ask, words, tmp_path, capsys):
    spec = tmp_path / "spec.toml"
    spec.write_text(f'[[exercise]]\nrecipe = "{recipe}"\nask = ["{ask}"]\n[exercise.given]\n'
                    "AB = 160\nCD = 240\nAD = 210\n" + ("BC = 200\n" if recipe == "four_bar.analysis" else ""),
                    encoding="utf-8")
    assert main(["worksheet", str(spec), "--out", str(tmp_path / "out"), "--count", "2"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("error: ") and words in err and "not a number" in err
    assert not (tmp_path / "out").exists()
