"""The link-ranges chart names its rows and its axis in both languages, as its Results name them (hlook11m's
review: 001-02's rows "crank-rocker", "not a mechanism" and the axis "BC (mm)" were English only on a bilingual
sheet, and "not a mechanism" stood beside the Results' "immovable")."""
from __future__ import annotations

import re

from cam_sheets import GALLERY

from geomcon.render.results import name_of


def test_001_02_rows_and_axis_carry_their_chinese_names():
    svg = (GALLERY / "001-02_four_bar_link_ranges.svg").read_text(encoding="utf-8")
    texts = {re.sub(r"<[^>]*>", "", t) for t in re.findall(r"<text\b[^>]*>(.*?)</text>", svg, re.S)}
    for name, zh in (("crank_rocker", "曲柄摇杆"), ("double_crank", "双曲柄"), ("double_rocker", "双摇杆"),
                     ("immovable", "不能运动"), ("grashof_ranges", "满足杆长条件")):
        assert f"{name_of(name).symbol} {zh}" in texts, name
    assert "BC (mm) 杆长" in texts and "not a mechanism" not in texts
