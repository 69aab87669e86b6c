"""Answer checking (issue 13): a synthetic class built from a worksheet key, every verdict, diagnosis code and
score asserted. The wrong values are computed here from the recipes' analytic twins (independent of the
scene replays that diagnose them): the other intersection of C1 is θ' = ∠C1AD + ∠C2AD, the other design by K
is the twin's second solution, K inverted is (180 − θ)/(180 + θ), the other crank-on-frame position is
max(γ1, γ2), the pitch curve's ρmin is the twin's ``rho_min_pitch``."""
from __future__ import annotations

import csv
import io
import json
import math
from decimal import Decimal

import pytest

from geomcon.grading import grade
from geomcon.grading.answers import read_answers
from geomcon.grading.example import CLASS_SPEC
from geomcon.grading.keyfile import key_from_json
from geomcon.grading.tables import grades_csv, grades_data
from geomcon.problems import validate_given
from geomcon.recipes import get_recipe
from geomcon.worksheet import make_worksheet
from geomcon.worksheet.roster import numbered
from geomcon.worksheet.spec import parse_spec
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
COLS = ["1.AB", "1.AD", "2.theta", "2.K", "2.psi", "2.gamma_min", "3.rho_min_actual", "3.alpha_max_rise"]


@pytest.fixture(scope="module")
def key_text() -> str:
    return make_worksheet(parse_spec(CLASS_SPEC), numbered(6)).files["key.json"]


@pytest.fixture(scope="module")
def key(key_text):
    return key_from_json(key_text)


def twin(key, sid: str, n: int) -> list[dict]:
    ex = next(e for e in key.students[sid].exercises if e.n == n)
    r = get_recipe(ex.recipe)
    return r.analytic(validate_given(r, ex.given))


def exp(key, sid: str, col: str):
    return key.students[sid].answer(col)


def csv_bytes(rows: list[list[str]], header=("id", "name", *COLS)) -> bytes:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(header)
    w.writerows(rows)
    return buf.getvalue().encode()


@pytest.fixture(scope="module")
def graded(key):
    e = lambda sid, c: exp(key, sid, c)                    # noqa: E731
    rows = []
    rows.append(["1", "exact"] + [repr(e("1", c).expected) for c in COLS])
    # student 2: construction mistakes
    t2 = twin(key, "2", 2)[0]
    theta_other = t2["angle_C1AD"] + t2["angle_C2AD"]
    k_follow = (180 + theta_other) / (180 - theta_other)
    rows.append(["2", "mistakes A", repr(e("2", "1.AD").expected), repr(twin(key, "2", 1)[1]["AD"]),
                 repr(theta_other), repr(k_follow), repr(t2["theta"]), repr(max(t2["gamma_1"], t2["gamma_2"])),
                 repr(twin(key, "2", 3)[0]["rho_min_pitch"]), ""])
    # student 3: reading slips, a teacher's diagnosis, garbage and injection
    t3 = twin(key, "3", 2)[0]
    g31 = next(ex for ex in key.students["3"].exercises if ex.n == 1).given
    rows.append(["3", "@SUM(A1)", repr(2 * e("3", "1.AB").expected), repr(e("3", "1.AB").expected + g31["BC"]),
                 repr(math.radians(t3["theta"])), repr((180 - t3["theta"]) / (180 + t3["theta"])), repr(-t3["psi"]),
                 "abc", '=HYPERLINK("http://x")',
                 f"{e('3', '3.alpha_max_rise').expected + 0.9 * e('3', '3.alpha_max_rise').tol:.6f}".replace(".", ",")])
    # student 4: tolerance edges and units
    a4 = {c: e("4", c) for c in COLS}
    boundary = str(a4["2.psi"].exact + a4["2.psi"].tol_exact)
    rows.append(["4", "<script>alert(1)</script>", repr(a4["1.AB"].expected + 0.9 * a4["1.AB"].tol),
                 repr(a4["1.AD"].expected + 1.1 * a4["1.AD"].tol), f"{math.radians(a4['2.theta'].expected):.12f} rad",
                 "1", boundary, repr(a4["2.gamma_min"].expected - a4["2.gamma_min"].tol - 0.01),
                 f"{a4['3.rho_min_actual'].expected / 10:.6f} cm", "+1+2"])
    # students 5 and 6: follow-through refused for nonsense, granted within 3 tolerances
    for sid, off in (("5", 20.0), ("6", 2.0)):
        th = e(sid, "2.theta").expected + off * e(sid, "2.theta").tol
        rows.append([sid, "ft", "", "", repr(th), repr((180 + th) / (180 - th)), "", "", "", ""])
    rows.append(["1", "again"] + [""] * len(COLS))            # a duplicate id
    rows.append(["7", "ghost"] + ["1"] * len(COLS))           # not in the key
    data = csv_bytes(rows) + b"8,short\n"                     # malformed: 2 cells
    book = grade(key, read_answers(data))
    return book


def verdicts(row):
    return [(g.column, g.verdict, g.diagnosis, g.points) for g in row.answers]


def test_exact_answers_are_correct_with_full_points(graded):
    r = graded.rows[0]
    assert all(g.verdict == "correct" and g.diagnosis == "" for g in r.answers)
    assert r.score == r.max_score == 15


def test_construction_mistakes_are_named(graded):
    assert verdicts(graded.rows[1]) == [
        ("1.AB", "wrong", "swapped", 1.5), ("1.AD", "wrong", "far_theta_circle", 0.0),
        ("2.theta", "wrong", "other_branch", 0.0), ("2.K", "wrong", "follow_through", 1.0),
        ("2.psi", "wrong", "theta_psi", 0.0), ("2.gamma_min", "wrong", "other_extreme_position", 0.0),
        ("3.rho_min_actual", "wrong", "pitch_vs_actual", 0.0), ("3.alpha_max_rise", "blank", "", 0.0)]
    assert graded.rows[1].score == 2.5
    theta = graded.rows[1].answers[2]
    assert "'C1'" in theta.en                       # the step is named


def test_reading_slips_teacher_diagnosis_garbage_and_injection(graded):
    assert verdicts(graded.rows[2]) == [
        ("1.AB", "wrong", "scale", 1.5), ("1.AD", "wrong", "AC2_for_AD", 0.0),
        ("2.theta", "wrong", "degrees_radians", 1.0), ("2.K", "wrong", "K_inverted", 0.0),
        ("2.psi", "wrong", "sign", 1.0), ("2.gamma_min", "unreadable", "", 0.0),
        ("3.rho_min_actual", "unreadable", "", 0.0), ("3.alpha_max_rise", "correct", "", 1.0)]
    assert graded.rows[2].score == 4.5


def test_tolerance_edges_units_and_rounding(graded):
    assert verdicts(graded.rows[3]) == [
        ("1.AB", "correct", "", 3.0), ("1.AD", "wrong", "", 0.0), ("2.theta", "correct", "", 2.0),
        ("2.K", "wrong", "rounding", 0.5), ("2.psi", "correct", "", 2.0), ("2.gamma_min", "wrong", "", 0.0),
        ("3.rho_min_actual", "correct", "", 1.0), ("3.alpha_max_rise", "unreadable", "", 0.0)]
    assert graded.rows[3].score == 8.5
    psi = graded.rows[3].answers[4]
    assert psi.deviation == float(psi.tol)             # exactly one tolerance away: correct


def test_follow_through_only_from_a_plausible_earlier_answer(graded):
    nonsense, near = graded.rows[4], graded.rows[5]
    assert verdicts(nonsense)[2:4] == [("2.theta", "wrong", "", 0.0), ("2.K", "wrong", "", 0.0)]
    assert verdicts(near)[2:4] == [("2.theta", "wrong", "", 0.0), ("2.K", "wrong", "follow_through", 1.0)]


def test_duplicates_unknown_ids_and_malformed_rows_are_kept_and_flagged(graded):
    dup, ghost, short = graded.rows[6], graded.rows[7], graded.rows[8]
    assert dup.duplicate and all(g.verdict == "blank" for g in dup.answers)
    assert ghost.problem.endswith("is not in the key") and all(g.verdict == "unreadable" for g in ghost.answers)
    assert short.problem == "line 10: 2 cells where the header has 10" and short.line == 10
    assert all(g.verdict == "unreadable" for g in short.answers)
    assert any("repeats line 2" in n for n in graded.notes)


def test_grades_csv_contract_and_injection(graded):
    text = grades_csv(graded)
    rows = list(csv.reader(io.StringIO(text)))
    fields = ("value", "expected", "deviation", "tol", "verdict", "diagnosis", "points")
    assert rows[0] == ["id", "name", "score", "max_score"] + [f"{c}.{f}" for c in COLS for f in fields]
    assert len(rows) == 1 + len(graded.rows)
    assert [r[0] for r in rows[1:]] == ["1", "2", "3", "4", "5", "6", "1", "7", "8"]
    for r in rows[1:]:
        for cell in r:
            assert cell[:1] not in "=+@" or cell == ""
            assert not cell.startswith("-") or float(cell) < 0
    third = dict(zip(rows[0], rows[3]))
    assert third["name"] == "'@SUM(A1)" and third["3.rho_min_actual.value"] == "'=HYPERLINK(\"http://x\")"
    assert dict(zip(rows[0], rows[4]))["3.alpha_max_rise.value"] == "'+1+2"
    data = grades_data(graded)
    assert data["rows"][1]["answers"]["2.K"]["diagnosis"] == "follow_through"
    json.dumps(data, allow_nan=False)


ENC_ROWS = "id,name,2.theta\n{sid},李明,\"{v}\"\n"


@pytest.mark.parametrize("encoding", ["utf-8", "utf-8-sig", "gbk", "gb18030", "utf-16"])
def test_encodings_and_decimal_comma(key, encoding):
    a = exp(key, "1", "2.theta")
    text = ENC_ROWS.format(sid="1", v=f"{a.expected:.4f}".replace(".", ","))
    sheet = read_answers(text.encode(encoding))
    assert sheet.rows[0].name == "李明"
    book = grade(key, sheet)
    g = next(g for g in book.rows[0].answers if g.column == "2.theta")
    assert g.verdict == "correct" and g.points == 2


def test_semicolons_with_unquoted_decimal_commas(key):
    a = exp(key, "1", "2.theta")
    value = f"{a.expected:.3f}".replace(".", ",")
    sheet = read_answers(f"id;2.theta\n1;{value} °\n".encode())
    g = next(g for g in grade(key, sheet).rows[0].answers if g.column == "2.theta")
    assert g.verdict == "correct"


def test_rows_beyond_the_limit_are_refused():
    from geomcon.errors import ProblemError
    with pytest.raises(ProblemError, match="more than 3 rows"):
        read_answers(b"id,1.AB\n1,2\n2,2\n3,2\n4,2\n", max_rows=3)


def test_a_problem_file_is_a_key_for_every_row():
    from geomcon.grading.keyfile import key_from_problem
    key = key_from_problem(ROOT / "problems" / "001-08_crank_rocker.toml")
    theta = key.students["*"].answer("theta").expected
    t = (180 - theta) / (180 + theta)
    book = grade(key, read_answers(f"id,theta,K\na,{theta},{t}\nb,{theta + 40},\n".encode()))
    assert verdicts(book.rows[0]) == [("theta", "correct", "", 1.0), ("K", "wrong", "K_inverted", 0.0)]
    assert book.rows[1].answers[0].verdict == "wrong" and book.rows[1].max_score == 2


def test_within_decides_decimal_boundaries():
    from geomcon.grading.cells import read_cell
    from geomcon.grading.credit import within
    from geomcon.grading.keyfile import Answer
    from geomcon.worksheet.spec import AnswerRef
    a = Answer("x", 1, AnswerRef("x", "x", None, "mm"), 0.3, Decimal("0.3"), 0.1, Decimal("0.1"), 1.0)
    assert within(read_cell("0.4", "mm"), a)[0] and within(read_cell("0,2", "mm"), a)[0]
    assert not within(read_cell("0.4000000001", "mm"), a)[0]
    assert within(read_cell("0.04 cm", "mm"), a)[0]


def test_a_point_answer_is_graded_by_distance():
    given = {"B1": [0, 0], "B2": [-20, 35], "B3": [-20, 85], "C1": [0, 50], "C2": [10, 75], "C3": [30, 85]}
    key = key_from_json(json.dumps({"title": "points", "students": [{"id": "1", "exercises": [
        {"n": 1, "recipe": "four_bar.three_positions", "given": given,
         "answers": {"A": {"value": [64.375, 60.0], "tol": 1.0, "points": 2}, "AB": {"value": 87.7, "tol": 0.5}}}]}]}))
    rows = "id,1.A\n1,\"(64,9; 60,7)\"\n1,\"64.375, 61.1\"\n1,64.375\n"
    book = grade(key, read_answers(rows.encode()))
    assert [verdicts(r)[0] for r in book.rows] == [("1.A", "correct", "", 2.0), ("1.A", "wrong", "", 0.0),
                                                   ("1.A", "unreadable", "", 0.0)]
    assert book.rows[0].answers[0].deviation == pytest.approx(math.hypot(0.525, 0.7))
    assert "64.9;60.7" in grades_csv(book)
