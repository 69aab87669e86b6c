"""Every registered recipe is complete for its three uses (issues 14 and 15's "done when", the contracts of issues
12 and 13): a worksheet statement of its own in English and Chinese that renders with each bundled problem's
givens, its declared mistakes (or a documented reason it declares none), each of them produced on a bundled
problem, and a printed name and unit for every answer.

There is no statement exemption: every form of every bundled problem has its recipe's own template (a recipe
falling back to :func:`geomcon.worksheet.statements.generic_template` — its title and a list of givens — fails).
"""
from __future__ import annotations

import re
import tomllib
from functools import lru_cache
from pathlib import Path

import pytest

from geomcon.errors import GeomconError
from geomcon.grading.diagnosis import prepare
from geomcon.grading.keyfile import key_from_json, key_from_problem
from geomcon.grading.mistakes import MISTAKES, NONE_DECLARED
from geomcon.recipes import RECIPES
from geomcon.render.results import NAMES, RECIPE_NAMES, name_of, unit_text
from geomcon.worksheet import make_worksheet
from geomcon.worksheet.roster import numbered
from geomcon.worksheet.spec import parse_spec
from geomcon.worksheet.statements import TEMPLATES, default_template, fill, number, shown_givens, template_form

ROOT = Path(__file__).resolve().parents[1]
NOT_STATED = {
    "at": "named by the asked answers (the displacement s at δ = 60°)",
    "alpha_allow": "a cam's or a linkage's warning threshold, stated where it sizes an answer (base radius, DE)",
    "alpha_allow_return": "as alpha_allow",
    "tolerance": "the profile's sampling, not part of the exercise",
    "strict": "the profile's sampling, not part of the exercise",
    "divisions": "the drawing's divisions, not part of the exercise",
    "gamma_allow": "marks the admissible arc in the drawing; the statement's answers do not depend on it",
    "H_out": "a design extension of the jaw crusher (DE), stated by that problem's own text",
    "branch": "the assembly chosen by the drawn figure",
    "driver": "named by the statement's words for the driving link",
}
"""Givens a default statement need not print, and why (every other given's value is in both languages)."""
STATED_ELSEWHERE = {("cam.base_radius", "alpha_allow"), ("cam.base_radius", "alpha_allow_return"),
                    ("shaper.design_by_K", "alpha_allow"), ("slotter.design_by_K", "alpha_allow")}
"""Where a NOT_STATED given sizes an answer: the statement must print it."""
LIST_ASK = {"four_bar.link_ranges": ["boundaries[0]", "boundaries[1]"]}
"""Recipes whose mistakes show in list answers, which a problem file's key does not grade: asked by element
in a worksheet of the problem's givens."""


@lru_cache(maxsize=None)
def problems() -> dict[str, list[tuple[str, dict]]]:
    out: dict[str, list[tuple[str, dict]]] = {}
    for f in sorted((ROOT / "problems").glob("*.toml")):
        data = tomllib.loads(f.read_text(encoding="utf-8"))
        out.setdefault(data["recipe"], []).append((f.name, data["given"]))
    return out


def test_every_recipe_has_a_bundled_problem():
    assert sorted(RECIPES) == sorted(problems())


def rendered(recipe: str, given: dict, lang: str) -> str:
    """As the worksheet's key fills a default statement: the variant's givens over the recipe's defaults."""
    defaults = {q.name: q.default for q in RECIPES[recipe].givens
                if q.name not in given and q.default is not None and q.default is not False and q.default != ()}
    template = default_template(recipe, given)[lang == "zh"]
    return fill(template, shown_givens(recipe, {**defaults, **given}, lang))


CASES = [(r, name, g) for r in sorted(RECIPES) for name, g in problems().get(r, [])]


@pytest.mark.parametrize("recipe, name, given", CASES, ids=[c[1] for c in CASES])
def test_statement_of_every_bundled_problem(recipe, name, given):
    form = template_form(recipe, given)
    assert form is not None and form in TEMPLATES.get(recipe, {}), f"{name}: no statement of its own ({form!r})"
    en, zh = rendered(recipe, given, "en"), rendered(recipe, given, "zh")
    for text in (en, zh):
        assert "{" not in text and "}" not in text
    assert en[0].isupper() and en.rstrip().endswith((".", "?")), en
    assert re.search(r"[\u4e00-\u9fff]", zh) and zh.rstrip().endswith(("。", "？", "?")), zh
    for k, v in given.items():
        if isinstance(v, bool) or (k in NOT_STATED and (recipe, k) not in STATED_ELSEWHERE):
            continue
        values = v if isinstance(v, list) and all(isinstance(x, (int, float)) for x in v) else [v]
        for x in values:
            if isinstance(x, (int, float)):
                assert number(x) in en and number(x) in zh, (k, number(x), en, zh)


@pytest.mark.parametrize("recipe", sorted(RECIPES))
def test_declared_mistakes_or_a_reason(recipe):
    declared = MISTAKES.get(recipe, ())
    reason = NONE_DECLARED.get(recipe, "")
    assert bool(declared) != bool(reason), "declare mistakes or say why there are none, not both"
    if reason:
        assert len(reason) > 60
    for m in declared:
        assert m.en and m.zh and re.search(r"[\u4e00-\u9fff]", m.zh), m.code


def _keys(recipe: str):
    for name, given in problems()[recipe]:
        try:
            yield key_from_problem(ROOT / "problems" / name)
        except GeomconError:
            pass                         # a problem whose drafting tolerance leaves the domain: not a key
        if recipe in LIST_ASK:
            body = "".join(f"{k} = {v!r}\n".replace("'", '"') for k, v in given.items())
            spec = f'[[exercise]]\nrecipe = "{recipe}"\nask = {LIST_ASK[recipe]!r}\n[exercise.given]\n{body}'
            yield key_from_json(make_worksheet(parse_spec(spec.replace("'", '"')), numbered(1)).files["key.json"])


@pytest.mark.parametrize("recipe", sorted(MISTAKES))
def test_every_declared_mistake_is_produced_on_a_bundled_problem(recipe):
    """A declaration that no variant can produce is dead (issue 13's C1_C2 question, asked of every recipe):
    each declared code is among the alternatives of some bundled problem's answers."""
    seen = set()
    for key in _keys(recipe):
        for st in key.students.values():
            for ex in st.exercises:
                seen |= {a.code for alts in prepare(ex).alts.values() for a in alts}
    assert {m.code for m in MISTAKES[recipe]} <= seen


@pytest.mark.parametrize("recipe", sorted(RECIPES))
def test_every_answer_has_a_printed_name_and_unit(recipe):
    for q in RECIPES[recipe].answers:
        assert (recipe, q.name) in RECIPE_NAMES or q.name in NAMES, q.name
        n = name_of(q.name, recipe)
        # a yes/no answer has no symbol; design by K writes its two flags as 1/0 (unit ratio since issue 3)
        assert (n.symbol or q.unit == "bool" or q.name in ("C1_folded", "A_near")) and n.en and n.zh, q.name
        unit_text(q.unit)                                    # every unit prints
        assert q.unit in ("", "deg", "bool", "choice") or unit_text(q.unit).strip(), (q.name, q.unit)


NOT_A_KEY = {
    "001-01_crank_rocker_change_point.toml": "a change-point chain: AB ± its drafting error leaves the crank "
                                             "condition, so the drawing cannot determine the answers",
}
"""(100-03 and 100-04 were here, 'A drafted alone leaves the domain': their givens B1, B2, B3 lie at one distance
from A; a rigid body's points are drafted as a body since, tests/test_worksheet_rigid.py.)"""
NO_SCALAR = {"001-02_four_bar_link_ranges.toml": "its answers are lists; a problem file's key grades scalars only "
                                                 "(a worksheet asks boundaries[i])"}


@pytest.mark.parametrize("name", [c[1] for c in CASES])
def test_every_bundled_problem_is_a_key(name):
    """``geomcon check PROBLEM.toml``: a cam whose ``at`` was left out (the default ()) was refused, 'given at
    must be a non-empty list' (200-03, 000-04, 000-08), because the validated default went back into the
    drafting solves as a given. The exceptions say why."""
    if name in NOT_A_KEY:
        with pytest.raises(GeomconError, match="drafting error leaves the domain"):
            key_from_problem(ROOT / "problems" / name)
        return
    key = key_from_problem(ROOT / "problems" / name)
    assert bool(key.columns) == (name not in NO_SCALAR)
