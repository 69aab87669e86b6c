"""A step caption too long for its box is cut short on its last line, its rest set as it was written: Chinese
words join without a space (the wrapped lines were joined with spaces: "以 O 为圆心 作基圆"), Latin words with
one, and no opening mark is left before the "…" (issue 11, hsheet11g item f)."""
from __future__ import annotations

import re
from pathlib import Path

import pytest
import svgwrite

from geomcon.problems import load_problem
from geomcon.render.page import zh_punct
from geomcon.render.svg import step_captions_group
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
HAN = "\u3400-\u9fff\uf900-\ufaff"


def _cut_lines(pid: str, lang: str, width: float) -> list[tuple[str, str]]:
    """(caption, last line) of every step whose caption is cut short in a 2-line box ``width`` mm wide."""
    sc = solve(load_problem(ROOT / "problems" / f"{pid}.toml")).drawing_scene
    g = step_captions_group(svgwrite.Drawing(), sc, (0.0, 0.0, width, 9.0), lang)
    out = []
    for k, group in enumerate(sc.frames(), 1):
        lines = ["".join(el.itertext()) if hasattr(el, "itertext") else re.sub(r"<[^>]+>", "", el.tostring())
                 for el in g.elements if el.attribs.get("data-step") == str(k)]
        if lines and lines[-1].endswith("…"):
            en, zh = sc.caption(group[0].key)
            out.append((f"{en} {zh_punct(zh) if zh else ''}", lines[-1]))
    return out


@pytest.mark.parametrize("pid, lang, width", [("000-02_slotter_guide_bar_check", "zh", 40.0),
                                              ("001-02_four_bar_link_ranges", "zh", 60.0),
                                              ("001-04_guide_bar_offset", "zh", 40.0),
                                              ("001-17b_crank_rocker_redesign_swing", "zh", 40.0),
                                              ("000-06_slotter_cam_pitch_points", "both", 60.0)])
def test_a_cut_caption_joins_chinese_words_without_a_space(pid, lang, width):
    """Before: "（圆上各点对 AC 张 直…" (000-02 at 40 mm), "仍为曲柄摇杆 机构）；…" (001-02 at 60 mm)."""
    cut = _cut_lines(pid, lang, width)
    assert cut
    for caption, last in cut:
        for a, b in re.findall(rf"([{HAN}，、；：）]) ([{HAN}（])", last):
            assert f"{a} {b}" in caption, (last, caption)        # a space only where the caption has one
        assert last[-2] not in "(（[［【「『《“‘", last
