"""Every warning of every gallery problem is printed in at least one of its gallery figures (issue 11: 002-01's
"'F.x' has 4 extremes per turn: K is not defined" was only in the terminal and the JSON; a drawing's sheet
has a Warnings block, the cycle's plot sheets and page now have one too)."""
from __future__ import annotations

import html
import json
import re
import xml.etree.ElementTree as ET
from pathlib import Path

from geomcon.problems import load_problem
from geomcon.render.labels import plain_text
from geomcon.render.serial import typeset
from geomcon.render.warning_words import warning_lines
from geomcon.solve import solve

GALLERY = Path(__file__).resolve().parents[1] / "gallery"
SVG = "{http://www.w3.org/2000/svg}"


def _words(s: str) -> str:
    """``s`` without its spaces: a line wrapped inside Chinese text has no space at the break."""
    return "".join(s.split())


def _figure_text(path: Path) -> str:
    """Every text of a gallery SVG (its text elements, tspans joined) or HTML page (tags dropped), one space
    between elements: what a reader sees, whatever the lines it was wrapped into."""
    if path.suffix == ".svg":
        root = ET.fromstring(path.read_text(encoding="utf-8"))
        return _words(" ".join("".join(t.itertext()) for t in root.iter(f"{SVG}text")))
    return _words(html.unescape(re.sub(r"<[^>]+>", " ", path.read_text(encoding="utf-8"))))


def _warned() -> dict[str, list[str]]:
    out = {}
    for j in sorted(GALLERY.glob("*.json")):
        data = json.loads(j.read_text(encoding="utf-8"))
        if isinstance(data, dict) and data.get("warnings"):
            out[j.stem] = data["warnings"]
    return out


def _listed_at(stem: str) -> dict[str, tuple[float, ...]] | None:
    """The cam angles of the problem's list answers (a warning names a list's entry as ``ψ(6°)``), or None for
    a gallery page that is not a problem's."""
    path = GALLERY.parent / "problems" / f"{stem}.toml"
    return solve(load_problem(path)).listed_at() if path.exists() else None


def test_every_warning_is_in_one_of_its_problem_s_figures():
    warned = _warned()
    assert len(warned) >= 15 and "002-01_conveyor_cycle" in warned
    missing = []
    for stem, warnings in warned.items():
        own = re.compile(re.escape(stem) + r"(-\d+|_motion(-\d+)?|_cycle)?\.(svg|html)$")
        texts = [_figure_text(p) for p in GALLERY.iterdir() if own.match(p.name)]
        assert texts, stem
        at = _listed_at(stem) if any("[" in w for w in warnings) else None
        for w in warnings:
            line = _words(typeset(plain_text(warning_lines([w], "en", at)[0])))  # "3·rr" prints "3⋅rr"
            if not any(line in t for t in texts):
                missing.append((stem, line))
    assert not missing, missing


def test_a_full_sheet_of_panels_makes_room_for_the_warnings_on_a_second_sheet():
    """Five panels fill an A4 sheet: with warnings the panels are shared out over two sheets and the Warnings
    block stands under the last panel, inside the chart area."""
    from dataclasses import replace

    from geomcon.kinematics.plots import AREA, cycle_plot_sheets
    from geomcon.kinematics.problem import demo_problem
    from geomcon.kinematics.result import solve_cycle

    r = solve_cycle(demo_problem(step=5, columns=["C.x", "C.vx", "C.ax", "BC.angle", "BC.omega"]))
    assert len(cycle_plot_sheets(r)) == 1
    warned = replace(r, warnings=("'C.x' has 4 extremes per turn: K is not defined (a test warning)",) * 3)
    sheets = cycle_plot_sheets(warned)
    assert len(sheets) == 2 and re.search(r"Sheet\s+第 2/2 张", _figure_text_of(sheets[1]))
    root = ET.fromstring(sheets[-1])
    block = root.find(f".//{SVG}g[@id='warnings']")
    ys = [float(t.get("y")) for t in block.iter(f"{SVG}text")]
    assert len(ys) == 4 and AREA[1] < min(ys) and max(ys) <= AREA[3]
    assert all(root.find(f".//{SVG}g[@id='warnings']") is None for root in map(ET.fromstring, sheets[:-1]))


def _figure_text_of(svg: str) -> str:
    return " ".join("".join(t.itertext()) for t in ET.fromstring(svg).iter(f"{SVG}text"))
