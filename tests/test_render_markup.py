"""The SVG markup is written byte for byte as svgwrite and ElementTree wrote it (attributes sorted,
escaped, empty ones left out, ``/>`` for empty elements, CDATA for the style sheet)."""
from __future__ import annotations

import random

import pytest

from geomcon.render.markup import Element, defs_of, style_sheet, svg_root

svgwrite = pytest.importorskip("svgwrite")

TEXTS = ["", "A", "C1", "θ=12.51°", "a < b & c > d", 'say "hi"', "tab\tand\nnew line", "作图步骤", "x'y"]


def test_elements_are_written_as_svgwrite_wrote_them():
    rng = random.Random(3)
    D = svgwrite.Drawing(profile="full", debug=False)
    for _ in range(400):
        attrs = {k: rng.choice(TEXTS + ["0.3", "#1a1a1a", None])
                 for k in rng.sample(["fill", "stroke_width", "class_", "id", "font_size", "stroke"], 4)}
        text, x, y = rng.choice(TEXTS), rng.choice(["0", "1.5", "-2"]), rng.choice(["3", "4.25"])
        ours, theirs = Element("text", text, x=x, y=y, **attrs), D.text(text, insert=(x, y), **attrs)
        for _ in range(rng.randint(0, 3)):
            t = rng.choice(TEXTS)
            ours.add(Element("tspan", t, dy=rng.choice(["0.5", "-0.5"]), font_size="2"))
            theirs.add(D.tspan(t, dy=[ours.elements[-1].attribs["dy"]], font_size="2"))
        g, gg = Element("g", id="g", class_="step"), D.g(id="g", class_="step")
        g.add(ours)
        gg.add(theirs)
        g.add(Element("path", d="M0 0L1 1", fill="none"))
        gg.add(D.path(d="M0 0L1 1", fill="none"))
        g.add(Element("circle", cx="1", cy="2", r="0.5"))
        gg.add(D.circle(center=("1", "2"), r="0.5"))
        g.attribs["data-step"] = "3"
        gg.attribs["data-step"] = "3"
        assert g.tostring() == gg.tostring()


def test_a_drawing_is_written_as_svgwrite_wrote_it():
    ours = svg_root("100mm", "50mm", "0 0 100 50")
    ours.attribs["font-family"] = "Noto Sans, sans-serif"
    defs_of(ours).add(style_sheet(".a { fill: red; }\n"))
    ours.add(Element("rect", x=0, y=0, width="100", height="50", fill="#fff", id="paper"))
    theirs = svgwrite.Drawing(size=("100mm", "50mm"), viewBox="0 0 100 50", profile="full", debug=False)
    theirs.attribs["font-family"] = "Noto Sans, sans-serif"
    theirs.defs.add(theirs.style(".a { fill: red; }\n"))
    theirs.add(theirs.rect(insert=(0, 0), size=("100", "50"), fill="#fff", id="paper"))
    assert ours.tostring() == theirs.tostring()
