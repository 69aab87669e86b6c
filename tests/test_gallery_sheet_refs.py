"""A protocol step that draws or reads a cam's s–δ (ψ–δ) diagram names the sheet the diagram is on, when the
diagram has a sheet of its own (hlook11 item 47: 200-05-3 step 8 said where the diagram was drawn but not on
which sheet): over the gallery, every protocol entry whose English mentions the diagram says "sheet N", N the
number of the sheet headed "Displacement diagram", and no entry names another sheet."""
from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"
_ENTRY = re.compile(r'<g class="proto[^"]*" data-step="\d+" id="proto-[^"]*">(.*?)</g>', re.S)


def _english(entry: str) -> str:
    lines = re.findall(r'<text [^>]*class="en"[^>]*>(.*?)</text>', entry, re.S)
    return " ".join(re.sub(r"<[^>]+>", "", ln) for ln in lines)


def _sheets(stem: str) -> dict[int, str]:
    out = {1: (GALLERY / f"{stem}.svg").read_text(encoding="utf-8")}
    for p in GALLERY.glob(f"{stem}-*.svg"):
        m = re.fullmatch(re.escape(stem) + r"-(\d+)", p.stem)
        if m:
            out[int(m.group(1))] = p.read_text(encoding="utf-8")
    return out


def test_protocol_entries_about_the_diagram_name_its_sheet():
    checked = 0
    for js in sorted(GALLERY.glob("*.json")):
        if not (GALLERY / f"{js.stem}.svg").exists():
            continue
        sheets = _sheets(js.stem)
        own = [n for n, s in sheets.items() if 'class="diagram-head"' in s]
        for n, svg in sheets.items():
            for entry in _ENTRY.findall(svg):
                en = _english(entry)
                if "diagram" not in en:
                    continue
                named = re.findall(r"sheet (\d+)", en)
                if own:
                    assert named == [str(own[0])], (js.stem, n, en)
                    checked += 1
                else:
                    assert not named, (js.stem, n, en)       # the diagram is beside the cam on sheet 1
    assert checked >= 20
