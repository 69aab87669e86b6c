"""Statement templates: every form of the four worksheet recipes fills in both languages, nothing evaluated."""
from __future__ import annotations

import pytest

from geomcon.paper import PAPERS
from geomcon.worksheet.accept import judge
from geomcon.worksheet.key import statement
from geomcon.worksheet.spec import parse_spec
from geomcon.worksheet.statements import TEMPLATES, fill, template_form

PROGRAM = ('[{kind = "rise", angle = 120, law = "cosine"}, {kind = "dwell", angle = 60}, '
           '{kind = "return", angle = 90, law = "cycloidal"}, {kind = "dwell", angle = 90}]')
FORMS = {
    ("crank_rocker.design_by_K", "psi+BC"): ("K = 1.25\nCD = 90\npsi = 40\nBC = 95", ["AB", "AD"]),
    ("crank_rocker.design_by_K", "psi+AB"): ("K = 1.25\nCD = 90\npsi = 40\nAB = 26", ["BC", "AD"]),
    ("crank_rocker.design_by_K", "psi+AC1"): ("K = 1.25\nCD = 90\npsi = 40\nAC1 = 70", ["AB", "BC"]),
    ("crank_rocker.design_by_K", "phi1+frame_line"): ("K = 1.25\nCD = 90\nphi1 = 60\nphi2 = 110\nframe_line = true",
                                                      ["AB", "AD"]),
    ("crank_rocker.design_by_K", "frame"): ("K = 1.5\nCD = 75\nAD = 100\nphi = 45", ["AB", "BC"]),
    ("crank_rocker.design_by_K", "links"): ("K = 1.25\nAB = 30\nBC = 90\npsi = 40", ["CD", "AD"]),
    ("crank_rocker.extremes", ""): ("AB = 50\nBC = 70\nCD = 80\nAD = 90", ["theta", "psi", "gamma_min"]),
    ("crank_slider.design_by_K", "e"): ("K = 1.5\nH = 50\ne = 20", ["AB", "BC"]),
    ("crank_slider.design_by_K", "AB"): ("K = 1.5\nH = 50\nAB = 30", ["BC", "e"]),
    ("crank_slider.design_by_K", "BC"): ("K = 1.5\nH = 50\nBC = 80", ["AB", "e"]),
    ("cam.translating", "centric"): (f'follower = "knife"\nr0 = 40\nh = 20\nprogram = {PROGRAM}', ["alpha_max_rise"]),
    ("cam.translating", "offset"): (f'follower = "roller"\nr0 = 40\nh = 20\ne = 10\nrr = 10\nat = [60]\n'
                                    f'program = {PROGRAM}', ["alpha_max_rise", "s[0]"]),
}


def test_every_template_is_covered():
    assert {(r, f) for r, forms in TEMPLATES.items() for f in forms} >= set(FORMS)


@pytest.mark.parametrize("key", sorted(FORMS))
def test_default_statement_of_each_form(key):
    recipe, form = key
    given, ask = FORMS[key]
    spec = parse_spec(f'[[exercise]]\nrecipe = "{recipe}"\nask = {ask!r}\n[exercise.given]\n{given}\n'.replace("'", '"'))
    ex = spec.exercises[0]
    assert template_form(recipe, ex.given_of(0)) == form
    v = judge(ex, 0, PAPERS["A3"])
    if v.reason is not None:                    # a statement does not need an accepted variant: fake one
        from geomcon.worksheet.accept import Accepted
        v = Accepted(0, ex.given_of(0), None, None, (), False)
    en, zh = statement(ex, v, "en"), statement(ex, v, "zh")
    assert "{" not in en + zh and "}" not in en + zh
    assert en.startswith(("Design", "A ")) and en.rstrip().endswith(".")
    assert zh.endswith("。") and "，" in zh and "," not in zh.replace(", ", "")   # full-width punctuation
    for name in given.splitlines():
        value = name.split(" = ")[1]
        if value[:1].isdigit():
            assert value in en and value in zh


def test_fill_never_evaluates():
    assert fill("{a}{{b}}", {"a": "{x.__class__}"}) == "{x.__class__}{b}"
    assert fill("{a.__class__} {0} {a!r}", {"a": "1"}) == "{a.__class__} {0} {a!r}"    # not a placeholder: text
    with pytest.raises(KeyError):
        fill("{b}", {"a": "1"})
