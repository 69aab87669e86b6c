"""Rules over every chart of the gallery (hlook11 items 14, 15, 22): the motion charts (``*_motion.svg`` of a cam
problem), the law charts (``law_*.svg``), the cycle plots (``*_motion.svg``, ``*_motion-2.svg`` … of a cycle
problem) and the displacement sheets (the ``-2`` sheet holding a cam's s–δ diagram).

- no two texts of a chart overlap ("softsoft" at 0°, 5°, 10°; tick labels "170180");
- every chart is one A4 page (002-01 was 1600×5939 px), with the drawings' title block;
- no number in e-notation ("1e+04", "2.5e+06");
- an oscillating follower's chart is in ψ and degrees, never "s (mm)" (200-12, 200-20);
- the title block holds the problem's title, never the file name ("000-04_slotter_cam_psi0: s–δ, …");
- a cycle plot's min/max notes lie inside their panel's frame ("max 1225 at 9.256°" on the top frame);
- a sheet with a cam's s–δ diagram (its own or beside the cam) ticks δ in degrees and h on the ordinate, and its "δ: 360° = N mm" is what the drawn
  axis measures on paper.
"""
from __future__ import annotations

import re
import tomllib
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from geomcon.render.charts import box_of
from geomcon.render.labels import text_width
from geomcon.render.zh import zh_brackets

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"
SVG = "{http://www.w3.org/2000/svg}"


def _problems() -> dict[str, dict]:
    return {p.stem: tomllib.loads(p.read_text(encoding="utf-8")) for p in (ROOT / "problems").glob("*.toml")}


PROBLEMS = _problems()
CYCLES = {p.stem: tomllib.loads(p.read_text(encoding="utf-8")) for p in (ROOT / "problems" / "cycles").glob("*.toml")}
CAM_CHARTS = sorted(f"{pid}_motion.svg" for pid, d in PROBLEMS.items() if "program" in d.get("given", d))
LAW_CHARTS = sorted(p.name for p in GALLERY.glob("law_*.svg"))
CYCLE_CHARTS = sorted(p.name for pid in CYCLES for p in GALLERY.glob(f"{CYCLES[pid].get('id', pid)}_motion*.svg"))
CHARTS = CAM_CHARTS + LAW_CHARTS + CYCLE_CHARTS
DIAGRAM_SHEETS = sorted(p.name for p in GALLERY.glob("[0-9]*.svg") if ("diagram-head" in p.read_text(encoding="utf-8")
                                                                       or "step-sd_curve" in p.read_text(encoding="utf-8")))
"""The sheets that draw a cam's s–δ (ψ–δ) diagram: its own sheet 2, or sheet 1 beside the cam (200-01, 001-24 …)."""
E_NOTATION = re.compile(r"\d(?:\.\d+)?e[+-]?\d", re.I)


def _root(name: str) -> ET.Element:
    return ET.fromstring((GALLERY / name).read_text(encoding="utf-8"))


def _num(v: str | None, default: float = 0.0) -> float:
    return float(v) if v not in (None, "") else default


def texts(root: ET.Element) -> list[tuple[str, tuple[float, float, float, float], ET.Element]]:
    """Every text element: its words and its box on paper (each tspan's width at its own size)."""
    out = []
    for t in root.iter(f"{SVG}text"):
        size = _num(t.get("font-size"), 3.0)
        parts = [(t.text or "", size)] + [(s.text or "", _num(s.get("font-size"), size)) for s in t.iter(f"{SVG}tspan")]
        words = "".join(p for p, _ in parts)
        if not words.strip():
            continue
        width = sum(text_width(p, sz) for p, sz in parts)
        out.append((words, box_of(_num(t.get("x")), _num(t.get("y")), size, width, t.get("text-anchor") or "start"), t))
    return out


def _overlap(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def test_the_gallery_has_its_charts():
    assert len(CAM_CHARTS) >= 20 and len(LAW_CHARTS) >= 8 and len(CYCLE_CHARTS) >= 2 and len(DIAGRAM_SHEETS) >= 5
    assert all((GALLERY / n).exists() for n in CHARTS)


@pytest.mark.parametrize("name", CHARTS)
def test_no_two_texts_of_a_chart_overlap(name):
    found = texts(_root(name))
    bad = [(a[0], b[0]) for i, a in enumerate(found) for b in found[i + 1:] if _overlap(a[1], b[1])]
    assert not bad, bad[:5]


@pytest.mark.parametrize("name", CHARTS)
def test_every_chart_is_an_a4_page_with_a_title_block_and_text_of_2_5_mm(name):
    root = _root(name)
    size = (root.get("width"), root.get("height"))
    assert size in (("210mm", "297mm"), ("297mm", "210mm")), size
    assert root.find(f".//{SVG}g[@id='title-block']") is not None
    small = [(w, t.get("font-size")) for w, _, t in texts(root) if _num(t.get("font-size"), 3.0) < 2.5]
    assert not small, small[:5]


@pytest.mark.parametrize("name", CHARTS + DIAGRAM_SHEETS)
def test_no_number_of_a_chart_is_in_e_notation(name):
    shown = [w for w, _, _ in texts(_root(name)) if E_NOTATION.search(w)]
    assert not shown, shown


@pytest.mark.parametrize("name", CAM_CHARTS)
def test_a_cam_chart_is_titled_by_its_problem_and_an_arm_reads_psi_in_degrees(name):
    pid = name.removesuffix("_motion.svg")
    data = PROBLEMS[pid]
    words = [w for w, _, _ in texts(_root(name))]
    title = next(w for w, _, t in texts(_root(name)) if "tb-0-0" in (t.get("class") or ""))
    assert title == zh_brackets(data["title"]) and pid not in title      # 等速（…） in full-width brackets
    heads = [w for w, _, t in texts(_root(name)) if "panel-head" in (t.get("class") or "")]
    if "arm" in data.get("given", data):
        assert heads == ["ψ (°)", "dψ/dδ (°/rad)", "d²ψ/dδ² (°/rad²)"], heads
        assert not any("mm" in w for w in heads + [w for w in words if w.startswith("Motion diagrams")])
    else:
        assert heads == ["s (mm)", "ds/dδ (mm/rad)", "d²s/dδ² (mm/rad²)"], heads


@pytest.mark.parametrize("name", CYCLE_CHARTS)
def test_a_cycle_plot_is_titled_typeset_and_its_notes_lie_inside_their_panel(name):
    pid = name.split("_motion")[0]
    data = next(d for k, d in CYCLES.items() if d.get("id", k) == pid)
    root = _root(name)
    found = texts(root)
    title = next(w for w, _, t in found if "tb-0-0" in (t.get("class") or ""))
    assert title == zh_brackets(data["title"])
    heads = [t for _, _, t in found if "panel-head" in (t.get("class") or "")]
    assert heads and all(t.find(f"{SVG}tspan") is not None for t in heads)      # a symbol with its subscript
    assert not any(re.search(r"\.(angle|omega|epsilon|[xy]|v[xy]|a[xy])\b|gamma\(|\(deg\)", w) for w, _, _ in found)
    for g in root.iter(f"{SVG}g"):
        if not (g.get("id") or "").startswith("panel-"):
            continue
        frame = g.find(f"{SVG}rect")
        x, y, w, h = (float(frame.get(k)) for k in ("x", "y", "width", "height"))
        for words, b, _ in texts(g):
            if words.startswith(("max ", "min ")):
                assert x < b[0] and b[2] < x + w and y < b[1] and b[3] < y + h, (words, b, (x, y, w, h))


@pytest.mark.parametrize("name", DIAGRAM_SHEETS)
def test_a_displacement_sheet_ticks_degrees_and_h_and_states_a_true_scale_for_each_axis(name):
    root = _root(name)
    found = texts(root)
    ticks = {w: b for w, b, t in found if "delta-tick" in (t.get("class") or "")}
    # every 90°; one that would cover a label of the figure (001-24: 90° under "100°") is left out
    assert {"0°", "360°"} <= set(ticks) <= {"0°", "90°", "180°", "270°", "360°"} and len(ticks) >= 4, ticks
    assert [w for w, _, t in found if "h-tick" in (t.get("class") or "")]
    statement = next(w for w, _, t in found if "diagram-scales" in (t.get("class") or ""))
    m = re.match(r"δ: 360° = ([\d.]+) mm;\s+(s 1:\d+(?:\.\d+)?|ψ: 10° = [\d.]+ mm)$", statement)
    assert m, statement
    measured = (ticks["360°"][0] + ticks["360°"][2]) / 2 - (ticks["0°"][0] + ticks["0°"][2]) / 2
    assert float(m.group(1)) == pytest.approx(measured, rel=1e-3)
    in_degrees = m.group(2).startswith("ψ")
    assert (root.find(f".//{SVG}path[@id='scale-bar']") is None) == in_degrees     # a length bar only for s in mm
