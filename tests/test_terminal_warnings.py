"""The warnings ``geomcon solve`` prints in the terminal name what they quote as the figure does (issue 11: the
terminal said "published theta = 25 is doubtful" and "教材答案 theta = 25 存疑" where the figure says
"published θ = 25"): every warning of every gallery problem, in English and in Chinese."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from geomcon.cli import _summary
from geomcon.problems import load_problem
from geomcon.recipes import get_recipe
from geomcon.render.labels import plain_text
from geomcon.render.results import name_of
from geomcon.render.warning_words import warning_lines
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
WARNED = sorted(p.stem for p in (ROOT / "problems").glob("*.toml")
                if (ROOT / "gallery" / f"{p.stem}.json").exists()
                and json.loads((ROOT / "gallery" / f"{p.stem}.json").read_text(encoding="utf-8")).get("warnings"))


def _terminal(text: str) -> list[str]:
    return [ln.strip().removeprefix("warning: ").removeprefix("警告：") for ln in text.splitlines()
            if ln.strip().startswith(("warning: ", "警告："))]


def test_the_gallery_has_warned_problems():
    assert len(WARNED) >= 15


@pytest.mark.parametrize("stem", WARNED)
def test_terminal_warnings_name_answers_and_allowances_as_the_figure_does(stem):
    sol = solve(load_problem(ROOT / "problems" / f"{stem}.toml"))
    recipe = get_recipe(sol.recipe.name)
    raw = {q.name for q in recipe.answers if name_of(q.name).symbol not in ("", q.name, q.name.replace("_", " "))}
    for lang in ("en", "zh", "both"):
        lines = _terminal(_summary(sol, lang))
        assert lines == [plain_text(w) for w in warning_lines(sol.warnings, lang)], lang
        for line in lines:
            quoted = re.findall(r"(?:^published |^教材答案 )(\w+)", line)
            assert not set(quoted) & raw, (lang, line)
            assert "alpha_allow" not in line and "gamma_allow" not in line, (lang, line)


def test_a_doubtful_theta_is_theta_in_the_terminal(tmp_path):
    text = (ROOT / "problems" / "001-08_crank_rocker.toml").read_text(encoding="utf-8")
    path = tmp_path / "doubt.toml"
    path.write_text(re.sub(r"(?m)^theta = 12\.5$", "theta = 25", text), encoding="utf-8")
    out = _summary(solve(load_problem(path)), "both")
    assert "warning: published θ = 25 is doubtful" in out and "警告：教材答案 θ = 25 存疑" in out, out
    assert "theta" not in out
