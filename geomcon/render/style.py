"""The drawing styles: one table from style name to stroke, width (paper mm), dash and fill.

Given elements are medium black, construction lines thin and light, results bold; every recipe names its
styles from this table (see :mod:`geomcon.recipes`).

Examples
--------
>>> stroke_of("link")["stroke-width"]
0.7
>>> stroke_of("no-such-style", role="construction")["stroke"]
'#9aa0a6'
"""
from __future__ import annotations

FONT = "Noto Sans CJK SC, Noto Sans, DejaVu Sans, sans-serif"
INK = "#1a1a1a"
LIGHT = "#9aa0a6"
ALT = "#1c4e80"
HIGHLIGHT = "#d9480f"

STYLES: dict[str, dict] = {
    "given": {"stroke": INK, "stroke-width": 0.35},
    "frame": {"stroke": INK, "stroke-width": 0.3, "stroke-dasharray": "6 1.2 1 1.2"},
    "construction": {"stroke": LIGHT, "stroke-width": 0.18},
    "theta-circle": {"stroke": "#5f7f9f", "stroke-width": 0.25},
    "path": {"stroke": LIGHT, "stroke-width": 0.2, "stroke-dasharray": "1.5 1"},
    "link": {"stroke": INK, "stroke-width": 0.7},
    "link-alt": {"stroke": ALT, "stroke-width": 0.7},
    "ghost": {"stroke": "#7d8590", "stroke-width": 0.3, "stroke-dasharray": "2 1"},
    "admissible": {"stroke": "#2f9e44", "stroke-width": 1.6, "stroke-opacity": 0.45},
    "angle": {"stroke": INK, "stroke-width": 0.25},
    "right-angle": {"stroke": INK, "stroke-width": 0.25},
    "dim": {"stroke": INK, "stroke-width": 0.2},
    "ground": {"stroke": INK, "stroke-width": 0.3},
    "slider": {"stroke": INK, "stroke-width": 0.45},
    "guide": {"stroke": INK, "stroke-width": 0.35},
}
ROLE_DEFAULT = {
    "given": "given",
    "construction": "construction",
    "result": "link",
    "measurement": "construction",
    "annotation": "dim",
}
POINT_RADIUS = {"pivot": 1.1, "joint": 0.9, "point": 0.45, "given": 0.55, "candidate": 0.7}


def stroke_of(style: str, *, role: str = "construction") -> dict:
    """SVG presentation attributes of a style (falling back on the role's default)."""
    return dict(STYLES.get(style) or STYLES[ROLE_DEFAULT.get(role, "construction")])


CSS = f"""
text {{ font-family: {FONT}; fill: {INK}; }}
.label {{ font-size: 3.6px; font-style: italic; }}
.mark-text {{ font-size: 3px; }}
.protocol {{ font-size: 2.9px; }}
.protocol .zh {{ fill: #5c6370; font-size: 2.6px; }}
.title {{ font-size: 5px; font-weight: bold; }}
.info {{ font-size: 2.9px; }}
.current line, .current circle, .current path, .current polyline, .current polygon {{ stroke: {HIGHLIGHT}; }}
.current text, text.current {{ fill: {HIGHLIGHT}; }}
.future {{ display: none; }}
"""
