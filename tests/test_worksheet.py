"""geomcon worksheet (issue 12): spec → accepted variants → key.json."""
from __future__ import annotations

import json
import math
import time
from decimal import Decimal
from pathlib import Path

import pytest

from geomcon.check import rounded
from geomcon.cli import main
from geomcon.paper import PAPERS, STANDARD, Scale
from geomcon.problems import problem_from_dict
from geomcon.recipes import get_recipe
from geomcon.solve import solve
from geomcon.worksheet import make_worksheet
from geomcon.worksheet.accept import judge
from geomcon.worksheet.assign import assign
from geomcon.worksheet.drafting import shifts
from geomcon.worksheet.key import plain
from geomcon.worksheet.roster import Student, numbered, parse_roster
from geomcon.worksheet.spec import AnswerRef, Grid, load_spec, parse_spec

DATA = Path(__file__).parent / "data"
SPEC = DATA / "worksheet_class.toml"


@pytest.fixture(scope="module")
def class40():
    """The sample spec (design by K, extremes, cam) for a class of 40: the key, parsed, and the time taken."""
    spec = load_spec(SPEC)
    t = time.perf_counter()
    w = make_worksheet(spec, numbered(40))
    seconds = time.perf_counter() - t
    print(f"\nworksheet: class of 40, 3 exercises: {seconds:.2f} s; " + "; ".join(w.summary))
    return spec, w, json.loads(w.files["key.json"])


# ------------------------------------------------------------------------------------------------ refusals
BAD = {
    "unknown recipe": ('[[exercise]]\nrecipe = "crank_rocker.nope"\nask = ["AB"]\n', "unknown recipe 'crank_rocker.nope'"),
    "not value list or range": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n[exercise.given]\n'
                                'AB = {lo = 1}\nAC = 290\n', "given 'AB'"),
    "word for a number": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n[exercise.given]\n'
                          'AB = "long"\nAC = 290\n', "given 'AB' must be a number, a list of numbers"),
    "empty range": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n[exercise.given]\n'
                    'AB = {min = 140, max = 100, step = 5}\nAC = 290\n', "empty range: max = 100 < min = 140"),
    "empty list": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n[exercise.given]\n'
                   'AB = []\nAC = 290\n', "given 'AB' is an empty list"),
    "ask non-answer": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["AB2"]\n[exercise.given]\n'
                       'AB = 100\nAC = 290\n', "ask[0]: 'AB2' is not an answer of guide_bar.extremes"),
    "require min > max": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n[exercise.given]\n'
                          'AB = 100\nAC = 290\n[exercise.require]\ntheta = {min = 90, max = 80}\n',
                          "require 'theta': unsatisfiable: min = 90 > max = 80"),
    "require never met": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n[exercise.given]\n'
                          'AB = {min = 100, max = 140, step = 10}\nAC = 290\n[exercise.require]\ntheta = {min = 90}\n',
                          "unsatisfiable [exercise.require]"),
    "require non-answer": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n[exercise.given]\n'
                           'AB = 100\nAC = 290\n[exercise.require]\nphi = {min = 1}\n', "'phi' is not an answer"),
    "unknown given": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n[exercise.given]\n'
                      'AB = 100\nAX = 290\n', "unknown given 'AX'"),
    "statement names an answer": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n'
                                  'statement = "θ = {theta}"\n[exercise.given]\nAB = 100\nAC = 290\n', "names {theta}"),
    "statement evaluates": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n'
                            'statement = "{AB.__class__}"\n[exercise.given]\nAB = 100\nAC = 290\n', "names {AB.__class__}"),
    "huge grid": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n[exercise.given]\n'
                  'AB = {min = 0.001, max = 1000, step = 0.001}\nAC = 290\n', "at most 100000"),
    "astronomic grid": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n[exercise.given]\n'
                        'AB = {min = 0, max = 1e300, step = 1e-300}\nAC = 290\n', "about 1.00e+600 values"),
    "a date in a program of a list": ('[[exercise]]\nrecipe = "cam.translating"\nask = ["h"]\n[exercise.given]\n'
                                      'follower = "knife"\nr0 = 40\nh = 20\nprogram = [[{kind = "rise", angle = '
                                      '1979-05-27}], [{kind = "rise", angle = 360, law = "cosine"}]]\n',
                                      "program'[0][0].angle must be a number or a word"),
    "points count": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\npoints = [1, 2]\n'
                     '[exercise.given]\nAB = 100\nAC = 290\n', "'points' must list one number per asked answer (1)"),
    "no mechanism at all": ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n[exercise.given]\n'
                            'AB = [300, 310]\nAC = 290\n', "no acceptable variant among the 2 tried"),
    "no exercise": ('title = "x"\n', "at least one [[exercise]]"),
    "unknown top key": ('titel = "x"\n[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n',
                        "unknown key 'titel'"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_specs_refused_in_one_line_nothing_written(case, tmp_path, capsys):
    text, needle = BAD[case]
    spec = tmp_path / "bad.toml"
    spec.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    rc = main(["worksheet", str(spec), "--out", str(out), "--count", "3"])
    err = capsys.readouterr()
    assert rc == 2
    lines = err.err.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {spec}: "), err.err
    assert needle in lines[0]
    assert err.out == ""
    assert not out.exists()


def test_bad_class_list_refused(tmp_path, capsys):
    cls = tmp_path / "class.csv"
    cls.write_text("id,name\n1,A\n1,B\n", encoding="utf-8")
    rc = main(["worksheet", str(SPEC), "--out", str(tmp_path / "o"), "--students", str(cls)])
    err = capsys.readouterr().err
    assert rc == 2 and err.startswith(f"error: {cls}: ") and "line 3: id '1' again (first on line 2)" in err
    assert not (tmp_path / "o").exists()


# ------------------------------------------------------------------------------------------------ the class
def test_class_of_40(class40):
    spec, w, key = class40
    assert [e["recipe"] for e in key["exercises"]] == [e.recipe for e in spec.exercises]
    assert len(key["students"]) == 40
    assert set(key) >= {"title", "seed", "geomcon", "spec_sha256", "students"}
    assert key["seed"] == 2026 and key["spec_sha256"] == spec.sha256
    for st in w.assignment.stats:                    # every exercise reports its acceptance
        assert st.accepted + sum(st.rejected.values()) == st.tried and st.shared == 0
    for s in key["students"]:
        assert set(s) >= {"id", "name", "variant", "exercises"}
        for e in s["exercises"]:
            assert set(e) >= {"n", "recipe", "given", "scale", "answers"}
            assert Scale.parse(e["scale"]) in STANDARD
            for a in e["answers"].values():
                assert set(a) >= {"value", "unit", "tol", "points"}


def test_no_two_students_share_a_variant(class40):
    _, w, key = class40
    for j in range(3):
        idx = [v[j].index for v in w.assignment.variants]
        assert len(set(idx)) == len(idx)
    assert len({s["variant"] for s in key["students"]}) == 40


def _options(spec_ex, name):
    """The values a slot may take (None for a fixed given)."""
    for s in spec_ex.slots:
        if s.path == (name,):
            return [s.value(k) for k in range(s.count)]
    return None


def test_givens_on_their_grids_exactly(class40):
    spec, _, key = class40
    for s in key["students"]:
        for ex, e in zip(spec.exercises, s["exercises"]):
            for name, v in e["given"].items():
                opts = _options(ex, name)
                if opts is None:
                    if name != "program":
                        assert v == ex.given[name]
                    continue
                assert any(v == o and type(plain(o)) is type(v) for o in opts), (name, v)
    g = Grid(Decimal("1.2"), Decimal("0.05"), 5)
    assert [g.value(k) for k in range(5)] == [1.2, 1.25, 1.3, 1.35, 1.4]      # decimal, not 1.2 + 3 * 0.05


def test_every_accepted_variant_resolved_agrees_with_the_twin(class40):
    _, _, key = class40
    for s in key["students"]:
        for e in s["exercises"]:
            rec = get_recipe(e["recipe"])
            sol = solve(problem_from_dict({"recipe": e["recipe"], "given": e["given"]}, name="re"))
            twins = rec.analytic(sol.problem.given)
            assert sol.ok
            for name, a in e["answers"].items():
                ref = AnswerRef(name, name.split("[")[0], int(name[:-1].split("[")[1]) if "[" in name else None,
                                a["unit"])
                mine = ref.of(sol.answers)
                assert a["value"] == rounded(mine, sol.unit_scale(a["unit"]))
                scale = sol.unit_scale(a["unit"])
                best = min(abs(ref.of(t) - a["value"]) for t in twins if ref.of(t) is not None)
                assert best <= 1e-9 * max(abs(a["value"]), scale), (e["recipe"], name, a["value"], best)


def test_require_bounds_hold_and_tolerances_within_5_percent(class40):
    _, w, key = class40
    for s, variants in zip(key["students"], w.assignment.variants):
        e = s["exercises"][1]                            # crank_rocker.extremes, gamma_min ≥ 30
        sol = solve(problem_from_dict({"recipe": e["recipe"], "given": e["given"]}, name="re"))
        assert sol.answers["gamma_min"] >= 30
        for e, v in zip(s["exercises"], variants):
            for a in v.answers:
                assert 0 < a.drafting_tol <= 0.05 * abs(a.value)
                assert e["answers"][a.ref.text]["tol"] == float(f"{a.tol:.2g}")     # 2 significant digits


def test_statements_filled_and_hold_no_answer(class40):
    _, _, key = class40
    for s in key["students"]:
        for e in s["exercises"]:
            st = e["statement"]
            assert set(st) == {"en", "zh"} and all(st.values())
            assert "{" not in st["en"] and "{" not in st["zh"]
            for a in e["answers"].values():
                for shown in (f"{a['value']:.2f}", f"{a['value']:.3f}", f"{a['value']:.4f}"):
                    if shown.rstrip("0").rstrip(".") not in {f"{x:g}" for x in _numbers(e["given"])}:
                        assert shown not in st["en"] and shown not in st["zh"]


def _numbers(v):
    if isinstance(v, dict):
        for x in v.values():
            yield from _numbers(x)
    elif isinstance(v, list):
        for x in v:
            yield from _numbers(x)
    elif isinstance(v, (int, float)) and not isinstance(v, bool):
        yield v


# ------------------------------------------------------------------------------------------------ determinism
def test_same_spec_and_class_same_bytes(tmp_path, capsys):
    spec = tmp_path / "s.toml"
    spec.write_text(SPEC.read_text(encoding="utf-8"), encoding="utf-8")
    cls = tmp_path / "class.csv"
    cls.write_bytes("id,name\n2023001,张三\n2023002,李四\n2023003,王五\n".encode("gb18030"))
    outs = []
    for k in range(2):
        out = tmp_path / f"out{k}"
        assert main(["worksheet", str(spec), "--out", str(out), "--students", str(cls)]) == 0
        outs.append(((out / "key.json").read_bytes(), (out / "variants.csv").read_bytes()))
    capsys.readouterr()
    assert outs[0] == outs[1]
    key = json.loads(outs[0][0])
    assert [s["name"] for s in key["students"]] == ["张三", "李四", "王五"]


def test_adding_a_student_changes_no_one_elses_variant():
    spec = load_spec(SPEC)
    small = [Student(f"2023{i:03d}", f"S{i}") for i in range(1, 9)]
    a = assign(spec, small, PAPERS["A4"])
    b = assign(spec, small + [Student("2023999", "new")], PAPERS["A4"])
    assert [[v.index for v in row] for row in a.variants] == [[v.index for v in row] for row in b.variants[:8]]
    c = assign(spec, numbered(9), PAPERS["A4"])
    d = assign(spec, numbered(10), PAPERS["A4"])
    assert [[v.index for v in row] for row in c.variants] == [[v.index for v in row] for row in d.variants[:9]]


def test_variant_depends_on_seed_and_id_not_on_wording():
    base = ('title = "T"\n[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n{extra}[exercise.given]\n'
            'AB = {{min = 100, max = 200, step = 1}}\nAC = 290\n')
    one = parse_spec(base.format(extra=""))
    two = parse_spec(base.format(extra='statement = "Guide bar AB = {AB}, AC = {AC}."\npoints = [4]\n')
                     .replace('title = "T"', 'title = "Other"'))
    cls = numbered(5)
    ia = [v[0].index for v in assign(one, cls, PAPERS["A4"]).variants]
    assert ia == [v[0].index for v in assign(two, cls, PAPERS["A4"]).variants]
    assert ia != [v[0].index for v in assign(one, cls, PAPERS["A4"], seed=7).variants]


def test_small_pool_shares_only_when_exhausted():
    spec = parse_spec('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n[exercise.given]\n'
                      'AB = [100, 120, 140]\nAC = 290\n')
    a = assign(spec, numbered(5), PAPERS["A4"])
    idx = [v[0].index for v in a.variants]
    assert sorted(set(idx[:3])) == [0, 1, 2] and a.stats[0].shared == 2


# ------------------------------------------------------------------------------------------------ acceptance
def test_several_solutions_need_the_choice_named():
    text = ('[[exercise]]\nrecipe = "crank_rocker.design_by_K"\nask = ["AB", "AD"]\n{st}[exercise.given]\n'
            'K = 1.25\nCD = 90\npsi = 40\nBC = 95\n')
    named = parse_spec(text.format(st="")).exercises[0]
    assert judge(named, 0, PAPERS["A4"]).several
    own = parse_spec(text.format(st='statement = "K = {K}, CD = {CD}."\n')).exercises[0]
    assert judge(own, 0, PAPERS["A4"]).reason == "several_solutions"
    own_named = parse_spec(text.format(st='statement = "K = {K}, CD = {CD}. {choice}"\n')).exercises[0]
    assert judge(own_named, 0, PAPERS["A4"]).reason is None


def test_drafting_worked_check_of_issue_12():
    """CD 75, AD 100, ∠ADC1 45°, K 1.5: 0.5° of θ moves AB by 0.22 mm on one design, 0.03 mm on the other."""
    g = {"K": 1.5, "CD": 75, "AD": 100, "phi": 45}
    sol = solve(problem_from_dict({"recipe": "crank_rocker.design_by_K", "given": g}, name="w"))
    ab = AnswerRef("AB", "AB", None, "mm")
    moved = sorted(abs(shifts("crank_rocker.design_by_K", g, (ab,), {"AB": s["AB"]}, 1.0)["K (θ)"]["AB"])
                   for s in sol.solution_values)
    assert [round(x, 2) for x in moved] == [0.03, 0.22]


def test_fixed_scale_rejects_what_does_not_fit():
    text = ('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\nscale = "{s}"\n[exercise.given]\n'
            'AB = 100\nAC = 290\n')
    assert judge(parse_spec(text.format(s="5:1")).exercises[0], 0, PAPERS["A4"]).reason == "fit"
    assert str(judge(parse_spec(text.format(s="1:5")).exercises[0], 0, PAPERS["A4"]).scale) == "1:5"


def test_class_list_encodings():
    rows = "id,name\n2023001,张三\n2023002,李四\n"
    for raw in (rows.encode("utf-8"), b"\xef\xbb\xbf" + rows.encode("utf-8"), rows.encode("gbk"),
                rows.encode("gb18030"), rows.encode("utf-16")):
        assert parse_roster(raw) == (Student("2023001", "张三"), Student("2023002", "李四"))
    assert parse_roster(b"ID;Name;class\n7;Ann;3\n") == (Student("7", "Ann"),)
    for bad in (b"name\nAnn\n", b"id\n\xff\xfe\x00", b"id,name\n,Ann\n", b""):
        with pytest.raises(Exception):
            parse_roster(bad)
    assert math.isfinite(len(numbered(2000)))


def _toml(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, (int, float)):
        return repr(v)
    if isinstance(v, list):
        return "[" + ", ".join(_toml(x) for x in v) + "]"
    return "{" + ", ".join(f"{k} = {_toml(x)}" for k, x in v.items()) + "}"


def test_every_bundled_problem_is_judged_without_error():
    """Each bundled problem as a one-variant exercise of its recipe: accepted or rejected with a reason, never
    an exception (every recipe's scene goes through the extent, crossing and drafting code)."""
    import tomllib
    from geomcon.worksheet.accept import REASONS
    seen = {}
    for f in sorted((Path(__file__).parents[1] / "problems").glob("*.toml")):
        d = tomllib.loads(f.read_text(encoding="utf-8"))
        rec = get_recipe(d["recipe"])
        ask = [q.name for q in rec.answers if q.unit in ("mm", "deg", "", "rad/s", "mm/s")][:2] or [
            f"{q.name}[0]" for q in rec.answers if q.unit in ("mm[]", "deg[]")][:1]    # lists only: their first
        given = "\n".join(f"{k} = {_toml(v)}" for k, v in d.get("given", {}).items())
        ex = parse_spec(f'[[exercise]]\nrecipe = "{d["recipe"]}"\nask = {json.dumps(ask)}\n[exercise.given]\n{given}\n'
                        ).exercises[0]
        v = judge(ex, 0, PAPERS["A4"])
        assert v.reason is None or v.reason in REASONS
        seen.setdefault(d["recipe"], []).append(v.reason)
    assert len(seen) >= 15 and sum(r is None for rs in seen.values() for r in rs) >= 20
