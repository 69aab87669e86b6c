"""Answer checking's files: the command (exit codes, nothing written for an unusable file), the Moodle bank
(well-formed, Moodle's question XML structure), the class report (escaped, drawn, sortable and printable in
headless Chromium), the teacher's diagnosis grammar and the spec's [exercise.diagnose]."""
from __future__ import annotations

import base64
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from geomcon.cli import main
from geomcon.errors import ProblemError
from geomcon.grading import grade
from geomcon.grading.answers import read_answers
from geomcon.grading.example import CLASS_SPEC
from geomcon.grading.expr import parse
from geomcon.grading.keyfile import key_from_json
from geomcon.grading.moodle import moodle_xml
from geomcon.grading.report import report_html
from geomcon.worksheet import make_worksheet
from geomcon.worksheet.roster import numbered
from geomcon.worksheet.spec import parse_spec

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
ONE_ANSWER = """
title = "Guide bar <θ>"
[[exercise]]
recipe = "guide_bar.extremes"
ask = ["theta"]
points = [2]
[exercise.given]
AB = {min = 100, max = 140, step = 10}
AC = 290
"""


@pytest.fixture(scope="module")
def key_file(tmp_path_factory) -> Path:
    p = tmp_path_factory.mktemp("key") / "key.json"
    p.write_text(make_worksheet(parse_spec(CLASS_SPEC), numbered(4)).files["key.json"], encoding="utf-8")
    return p


def _answers(tmp: Path, text: str, encoding: str = "utf-8") -> Path:
    p = tmp / "answers.csv"
    p.write_bytes(text.encode(encoding))
    return p


def test_check_writes_every_file_and_exits_0(key_file, tmp_path, capsys):
    ans = _answers(tmp_path, "id,name,2.theta,2.K\n1,<b>Li</b>,1,x\n2,王,,\n")
    out = tmp_path / "out"
    assert main(["check", str(key_file), str(ans), "--out", str(out)]) == 0
    names = sorted(str(p.relative_to(out)) for p in out.rglob("*") if p.is_file())
    assert names == ["feedback/1.txt", "feedback/2.txt", "grades.csv", "grades.json", "report.html"]
    fb = (out / "feedback" / "2.txt").read_text(encoding="utf-8")
    assert "Not answered" in fb and "未作答" in fb                    # the sheet is in both languages
    assert "<b>Li</b>" not in (out / "report.html").read_text(encoding="utf-8")
    assert "graded 2 of 2 rows" in capsys.readouterr().out


@pytest.mark.parametrize("text, message", [
    (b"name,1.AB\nLi,3\n", "no 'id' column"),
    (b"id,id,1.AB\n", "repeats the column"),
    (b"id,foo\n1,2\n", "no column names an answer"),
    (b"\x80\xff\x80\xff", "not text"),
    (b"", "empty"),
])
def test_an_unusable_answers_file_exits_2_with_one_line_and_writes_nothing(key_file, tmp_path, capsys, text, message):
    ans = tmp_path / "a.csv"
    ans.write_bytes(text)
    out = tmp_path / "out"
    assert main(["check", str(key_file), str(ans), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith(f"error: {ans}: ") and message in err
    assert not out.exists()


def test_a_file_beyond_the_size_limit_is_refused_unread(key_file, tmp_path, capsys):
    from geomcon.grading.answers import MAX_BYTES
    ans = tmp_path / "big.csv"
    with open(ans, "wb") as f:
        f.truncate(MAX_BYTES + 1)                   # sparse: nothing to read
    assert main(["check", str(key_file), str(ans), "--out", str(tmp_path / "o")]) == 2
    assert "at most 33554432 (32 MiB)" in capsys.readouterr().err


def test_a_bad_key_exits_2(tmp_path, capsys):
    k = tmp_path / "key.json"
    k.write_text('{"students": [{"id": "1", "exercises": [{"n": 1, "recipe": "nope", "answers": {}}]}]}')
    ans = _answers(tmp_path, "id,1.AB\n1,2\n")
    assert main(["check", str(k), str(ans), "--out", str(tmp_path / "o")]) == 2
    assert "not a geomcon key" in capsys.readouterr().err


def test_moodle_bank_follows_moodles_question_xml(key_file, tmp_path):
    out = tmp_path / "bank.xml"
    assert main(["moodle", str(key_file), "--out", str(out)]) == 0
    root = ET.parse(out).getroot()
    assert root.tag == "quiz"
    qs = list(root)
    cats = [q for q in qs if q.get("type") == "category"]
    assert [c.find("category/text").text.rsplit("/", 1)[1] for c in cats] == ["Exercise 1", "Exercise 2", "Exercise 3"]
    key = key_from_json(key_file.read_text(encoding="utf-8"))
    cloze = [q for q in qs if q.get("type") == "cloze"]
    assert len(cloze) == len({(s.variant.split("-")[ex.n - 1], ex.n) for s in key.students.values() for ex in s.exercises})
    for q in cloze:
        text = q.find("questiontext/text").text
        fields = re.findall(r"\{(\d+):NUMERICAL:=([^:~]+):([^#~]+)#", text)
        assert len(fields) in (2, 4)
        f = q.find("questiontext/file")
        assert f.get("encoding") == "base64" and f"@@PLUGINFILE@@/{f.get('name')}" in text
        svg = base64.b64decode(f.text).decode()
        ET.fromstring(svg)
        assert 'id="step-mark_theta"' not in svg     # θ's mark would sit at A, the answer's vertex
        labels = " ".join(re.findall(r">([^<]+)<", svg))
        for _, value, _ in fields:                  # the givens figure holds no answer
            if not float(value).is_integer():
                assert f"{float(value):.2f}" not in labels and f"{float(value):.3f}" not in labels
    first = next(q for q in cloze if "AC2_for_AD" in q.find("questiontext/text").text)
    assert "%0%" in first.find("questiontext/text").text and "%50%" in first.find("questiontext/text").text


def test_moodle_numerical_question_for_a_single_answer():
    key = key_from_json(make_worksheet(parse_spec(ONE_ANSWER), numbered(2)).files["key.json"])
    root = ET.fromstring(moodle_xml(key, figures=False).encode())
    num = [q for q in root if q.get("type") == "numerical"]
    assert len(num) == 2
    for q, s in zip(num, key.students.values()):
        a = s.exercises[0].answers[0]
        right = q.find("answer[@fraction='100']")
        assert float(right.find("text").text) == a.expected and float(right.find("tolerance").text) == a.tol
        assert q.find("defaultgrade").text == "2"
        assert [u.find("unit_name").text for u in q.findall("units/unit")] == ["°", "deg"]
        wrong = q.findall("answer[@fraction='0']")
        assert wrong and all(w.find("feedback/text").text for w in wrong)
    assert "&lt;θ&gt;" in moodle_xml(key, figures=False)


def _book(key_file):
    key = key_from_json(key_file.read_text(encoding="utf-8"))
    text = "id,name,2.theta\n" + "".join(f"{sid},<i>n{sid}</i>,{key.students[sid].answer('2.theta').expected}\n"
                                         for sid in key.students) + "1,x,abc\n"
    return grade(key, read_answers(text.encode()))


def test_report_escapes_and_draws(key_file):
    html = report_html(_book(key_file))
    assert "<i>" not in html and "&lt;i&gt;n1&lt;/i&gt;" in html
    assert html.count('class="bar"') == 10 and 'id="rates"' in html
    ET.fromstring(re.search(r"<svg.*?</svg>", html, re.S).group(0))


@pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium not installed (apt-get install chromium)")
def test_report_in_headless_chromium(key_file, tmp_path):
    page = tmp_path / "report.html"
    page.write_text(report_html(_book(key_file)), encoding="utf-8")
    out = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--dump-dom", page.as_uri()],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-500:]
    dom = out.stdout
    assert dom.count('class="bar"') == 10
    body = dom[dom.index('id="students"'):]
    assert body.count("<tr") == 1 + 5                # the head and every row
    pdf = tmp_path / "report.pdf"
    out = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", f"--print-to-pdf={pdf}",
                          "--no-pdf-header-footer", page.as_uri()], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0 and pdf.read_bytes().startswith(b"%PDF")


@pytest.mark.parametrize("text", ["__import__('os')", "AB.__class__", "1 +", "(1", "lambda: 1", "AB[0]", "x" * 201,
                                  "1 " * 70, "exec(1)"])
def test_expressions_are_parsed_never_evaluated(text):
    with pytest.raises(ValueError):
        parse(text, {"AB", "BC"})


def test_expression_arithmetic():
    e = parse("sqrt(AB^2 + BC^2) / 2 - -cos(60)", {"AB", "BC"})
    assert e({"AB": 3.0, "BC": 4.0}) == pytest.approx(3.0)
    with pytest.raises(ValueError, match="division by zero|float division"):
        parse("AB / (BC - BC)")({"AB": 1.0, "BC": 2.0})


@pytest.mark.parametrize("diagnose, message", [
    ('AD = {code = "x", expr = "AB + nope"}', "unknown name 'nope'"),
    ('BC = {code = "x", expr = "AB"}', "not an asked answer"),
    ('AD = {code = "9x", expr = "AB"}', "must be a word"),
    ('AD = {code = "x"}', "must be {code"),
    ('AD = {code = "x", expr = "AB", what = 1}', "must be {code"),
])
def test_spec_diagnose_refusals(diagnose, message):
    spec = CLASS_SPEC
    start = spec.index("[exercise.diagnose]")
    end = spec.index("\n", spec.index("\n", start) + 1)
    bad = spec[:start] + "[exercise.diagnose]\n" + diagnose + spec[end:]
    with pytest.raises(ProblemError, match=re.escape(message)):
        parse_spec(bad)


def test_key_json_carries_the_teachers_diagnosis(key_file):
    import json
    data = json.loads(key_file.read_text(encoding="utf-8"))
    assert data["exercises"][0]["diagnose"]["AD"][0]["code"] == "AC2_for_AD"
    assert "diagnose" not in data["exercises"][1]


def test_the_bench_row_grades_what_it_says():
    from geomcon.bench.grading import measure_grading
    r = measure_grading(rows=300, students=3)
    assert (r.rows, r.answers, r.variants) == (300, 1800, 6)
    assert 0 < r.diagnosed < r.answers and r.rate > 0


def test_outputs_are_deterministic(key_file, tmp_path):
    from geomcon.grading.example import synthetic_answers
    from geomcon.grading.tables import grades_csv, grades_json
    key = key_from_json(key_file.read_text(encoding="utf-8"))
    data = synthetic_answers(key, rows=40).encode()
    runs = []
    for _ in range(2):
        book = grade(key, read_answers(data))
        runs.append((grades_csv(book), grades_json(book), report_html(book)))
    assert runs[0] == runs[1]
