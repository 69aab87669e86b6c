"""The pages made from a key print its title in the key's language (issue 11, hsmall11m): the grading report,
the Moodle bank, the feedback texts and key.json kept the English title for a worksheet made in zh or both.
key.json keeps ``title`` (the spec's, a public contract) and adds the spec's ``title_zh``; a loaded key's
:meth:`~geomcon.grading.keyfile.Key.heading` gives the title as ``problems.title_in`` does for its language."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from geomcon.grading import grade
from geomcon.grading.answers import read_answers
from geomcon.grading.feedback import feedback_text
from geomcon.grading.keyfile import key_from_json, key_from_problem
from geomcon.grading.moodle import moodle_xml
from geomcon.grading.report import report_html
from geomcon.grading.tables import grades_data

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"
EN, ZH = "Grading example — linkages and a cam", "评分示例——连杆机构与凸轮"


def _key(lang: str, zh: str = "五点") -> str:
    given = {"B1": [0, 0], "B2": [-20, 35], "B3": [-20, 85], "C1": [0, 50], "C2": [10, 75], "C3": [30, 85]}
    return json.dumps({"title": "Points", **({"title_zh": zh} if zh else {}), "lang": lang, "students": [
        {"id": "1", "exercises": [{"n": 1, "recipe": "four_bar.three_positions", "given": given,
                                   "answers": {"AB": {"value": 87.7, "tol": 0.5}}}]}]})


@pytest.mark.parametrize("lang, want", [("en", "Points"), ("zh", "五点"), ("both", "Points  五点")])
def test_a_key_s_heading_is_in_its_language(lang, want):
    assert key_from_json(_key(lang)).heading() == want


def test_a_key_without_a_chinese_title_keeps_the_english_one():
    assert key_from_json(_key("zh", zh="")).heading() == "Points"


@pytest.mark.parametrize("lang, want", [("zh", "五点"), ("both", "Points  五点")])
def test_the_report_the_bank_and_the_feedback_print_it(lang, want):
    key = key_from_json(_key(lang))
    book = grade(key, read_answers(b"id,1.AB\n1,87.7\n"))
    assert f"<h1>{want}</h1>" in report_html(book)
    bank = moodle_xml(key, figures=False)
    assert f"$course$/top/{want}/Exercise 1" in bank and f"<name><text>{want} — 1 — " in bank
    text = feedback_text(book.rows[0], key.title, key.lang, key.title_zh)
    assert text.splitlines()[0] == ("Points" if lang == "both" else "五点")
    assert "五点" in text.splitlines()
    assert grades_data(book)["title_zh"] == "五点" and grades_data(book)["title"] == "Points"


def test_a_problem_key_carries_the_problem_s_chinese_title():
    key = key_from_problem(ROOT / "problems" / "001-08_crank_rocker.toml")
    assert key.title_zh.startswith("曲柄摇杆机构") and key.heading() == key.title and key.heading("zh") == key.title_zh


def test_the_gallery_s_graded_example_prints_both_titles():
    data = json.loads((GALLERY / "grading_key.json").read_text(encoding="utf-8"))
    assert (data["title"], data["title_zh"], data["lang"]) == (EN, ZH, "both")
    assert f"<h1>{EN}  {ZH}</h1>" in (GALLERY / "grading_report.html").read_text(encoding="utf-8")
    assert f"$course$/top/{EN}  {ZH}/Exercise 1" in (GALLERY / "grading_bank.xml").read_text(encoding="utf-8")
    feedback = (GALLERY / "grading_feedback_2.txt").read_text(encoding="utf-8").splitlines()
    assert feedback[0] == EN and ZH in feedback
