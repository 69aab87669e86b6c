"""A worksheet variant leaves room for its whole construction (review hlook11m, worksheet sheets/1 and key/1:
the θ-circle and its arc ran off the sheet, F_n's construction lines to the frame's corner): the key's full
construction (every drawn part of the chosen solution: points, segments, circles drawn whole, compass arcs)
lies inside the drawing frame below the answer boxes, nothing of it cut; a variant whose construction fits at no
standard scale is rejected (``fit``), never cut. Seeded random variants of every recipe the statements know."""
from __future__ import annotations

import math
import random
import tomllib
from dataclasses import replace
from pathlib import Path

import pytest

from geomcon.paper import PAPERS
from geomcon.recipes import get_recipe
from geomcon.worksheet.accept import FIGURE_MARGIN, judge
from geomcon.worksheet.assign import Assignment
from geomcon.worksheet.key_extent import key_box, key_content
from geomcon.worksheet.key_pages import key_keep, key_room, key_view
from geomcon.worksheet.roster import numbered
from geomcon.worksheet.solving import solve_given
from geomcon.worksheet.sheets import make_pages
from geomcon.worksheet.spec import _exercise, parse_spec
from geomcon.worksheet.statements import TEMPLATES

ROOT = Path(__file__).resolve().parents[1]
EPS = 1e-6
SEED = 1127
TRIES = 8
"""Random pool indices judged per recipe."""


def _problem(recipe: str) -> dict:
    """The given of the first problem file of ``recipe``; for a recipe with rigid point givens, the first whose
    construction does not warn (its numbers are not spread, its points only turned: 100-03's rounded K would warn
    in every variant, and a worksheet refuses a warned construction as ``borderline``)."""
    for path in sorted((ROOT / "problems").glob("*.toml")):
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        if data.get("recipe") == recipe:
            if get_recipe(recipe).rigid and solve_given(recipe, data["given"]).construction_warnings:
                continue
            return data["given"]
    raise LookupError(recipe)


TURNS = (-6.0, 0.0, 6.0)
"""Degrees a rigid link's free point is turned about its anchor in the spread of a point given."""


def _turned(rigid, given: dict) -> dict:
    """Three choices of each rigid link's point that nothing rides on: turned about its anchor by :data:`TURNS`
    (the link keeps its length, so every combination is as rigid as the problem's data)."""
    anchors = {p: a for group in rigid for a, p in group if given.get(a) is not None and given.get(p) is not None}
    out = {}
    for p, a in anchors.items():
        if p in anchors.values():
            continue
        (ax, ay), (px, py) = given[a], given[p]
        out[p] = [[ax + math.cos(math.radians(t)) * (px - ax) - math.sin(math.radians(t)) * (py - ay),
                   ay + math.sin(math.radians(t)) * (px - ax) + math.cos(math.radians(t)) * (py - ay)] for t in TURNS]
    return out


def _spread(v):
    """Five values about a number given (0.8 … 1.25 ×), the rest as it is."""
    if isinstance(v, bool) or not isinstance(v, (int, float)) or v == 0:
        return v
    if isinstance(v, int):
        return sorted({max(1, round(v * k)) for k in (0.8, 0.9, 1.0, 1.1, 1.25)})
    return sorted({float(f"{v * k:.3g}") for k in (0.8, 0.9, 1.0, 1.1, 1.25)})


def _exercise_of(recipe: str, scale: str | None = None):
    r = get_recipe(recipe)
    ask = [q.name for q in r.answers if q.unit not in ("choice", "bool") and not q.unit.endswith("[]")][:2]
    ask = ask or [f"{q.name}[0]" for q in r.answers if q.unit == "mm[]"][:1]
    given = _problem(recipe)
    data = {"recipe": recipe, "ask": ask, "given": {k: _spread(v) for k, v in given.items()} | _turned(r.rigid, given),
            "max_tol_rel": 0.5}                # the layout is under test here, not the drafting tolerance
    if scale is not None:
        data["scale"] = scale
    return _exercise(data, 1)


def _accepted(recipe: str):
    ex = _exercise_of(recipe)
    rng = random.Random(f"{SEED}-{recipe}")
    out = []
    for i in rng.sample(range(ex.pool), min(TRIES, ex.pool)):
        v = judge(ex, i, PAPERS["A4"])
        if v.reason is None:
            out.append(v)
    assert out, f"no variant of {recipe} accepted among {min(TRIES, ex.pool)}"
    return ex, out


def _pages(ex, variants):
    spec = replace(parse_spec('title = "fit"\n[[exercise]]\nrecipe = "crank_rocker.extremes"\nask = ["theta"]\n'
                              '[exercise.given]\nAB = 50\nBC = 70\nCD = 80\nAD = 90\n'), exercises=(ex,))
    students = numbered(len(variants))
    a = Assignment(tuple(students), tuple((v,) for v in variants), ())
    return [p for p in make_pages(spec, a, "en") if p.part != "sd"]


@pytest.mark.parametrize("recipe", sorted(TEMPLATES))
def test_the_key_s_whole_construction_lies_inside_the_frame(recipe):
    """Every accepted random variant: the key's construction at the sheet's scale (content, circles drawn whole,
    compass arcs) with its margin lies in the frame below the answer boxes, so the key's view is not cut."""
    ex, variants = _accepted(recipe)
    for p in _pages(ex, variants):
        f = p.lay.scale.factor
        whole = key_box(key_content(p.sol), 1.0 / f)
        (x0, y0), (x1, y1) = p.lay.to_paper(whole[0], whole[3]), p.lay.to_paper(whole[2], whole[1])
        rx0, ry0, rx1, ry1 = key_room(p)
        m = FIGURE_MARGIN - EPS
        assert x0 - m >= rx0 and y0 - m >= ry0 and x1 + m <= rx1 and y1 + m <= ry1, \
            (recipe, p.variant.index, str(p.lay.scale), (x0, y0, x1, y1), (rx0, ry0, rx1, ry1))
        view = key_view(p, key_keep(p.sol))
        grown = (whole[0] - FIGURE_MARGIN / f, whole[1] - FIGURE_MARGIN / f,
                 whole[2] + FIGURE_MARGIN / f, whole[3] + FIGURE_MARGIN / f)
        assert all(math.isclose(a, b, abs_tol=1e-6 * (1 + abs(b))) for a, b in zip(view, grown)), (recipe, view, grown)


GALLERY_1 = ('[[exercise]]\nrecipe = "crank_rocker.design_by_K"\nask = ["AB", "AD"]\nmax_tol_rel = 0.1\n{scale}[exercise.given]\n'
             'K = 1.4\nCD = 100\npsi = 40\nBC = 100\n')
"""The gallery's worksheet key/1 of the review: its θ-circle ran off an A4 sheet at 1:1."""


def test_a_construction_that_does_not_fit_the_spec_s_scale_is_rejected_not_cut():
    """At the spec's 1:1 the θ-circle (about 208 mm across with its compass arcs) fits no A4 orientation: the
    variant is rejected ``fit`` (the student's givens alone would fit); at a free scale it is drawn at 1:2."""
    fixed = parse_spec(GALLERY_1.format(scale='scale = "1:1"\n')).exercises[0]
    v = judge(fixed, 0, PAPERS["A4"])
    assert v.reason == "fit", v
    assert "key's construction" in v.detail
    free = judge(parse_spec(GALLERY_1.format(scale="")).exercises[0], 0, PAPERS["A4"])
    assert free.reason is None and str(free.scale) == "1:2", free
    assert judge(fixed, 0, PAPERS["A3"]).reason is None          # A3 holds it at 1:1
