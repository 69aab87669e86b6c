"""The lean writer (:func:`geomcon.render.serial.svg_string` of :class:`~geomcon.render.serial.Element`) writes
what svgwrite writes for the same element: attributes sorted by name whatever order they were set in, values
through ``str``, None and empty ones left out, values and text escaped, a text typeset (minus signs, product
dots). Its fast path (a start tag filled in from a remembered template) must not change a byte."""
from __future__ import annotations

import pytest
import svgwrite

from geomcon.render.serial import Element, svg_string

DWG = svgwrite.Drawing(profile="full", debug=False)


@pytest.mark.parametrize("attribs", [
    {"x": "1", "y": "2", "font_size": "3.5", "fill": "#000", "class_": "en"},
    {"class_": "en", "fill": "#000", "font_size": "3.5", "y": "2", "x": "1"},        # the same, set in reverse
    {"x": "1", "y": None, "fill": ""},                                               # left out
    {"font_size": 3, "opacity": 0.5, "id": "a"},                                     # not strings
    {"id": "a&b", "class_": 'q"<>', "fill": "x\ty\nz\r"},                            # escaped
    {"id": "{0}", "class_": "{"},                                                    # braces of a template
    {},
])
@pytest.mark.parametrize("text", ["", "C", "-3.5 = 2·CD & a<b"])
def test_a_lean_element_is_written_as_svgwrite_writes_it(attribs, text):
    lean = Element("tspan", text, **attribs)
    ref = DWG.tspan(text, **attribs)
    assert svg_string(lean) == svg_string(ref) == ref.tostring().replace("-3.5", "−3.5").replace("·", "⋅")


def test_a_tree_of_lean_elements_twice():
    """The second writing (templates remembered) is the first."""
    def tree() -> Element:
        g = Element("g", id="x", class_="a&b")
        t = g.add(Element("text", "C", x="1", y="2", font_size="3"))
        t.add(Element("tspan", "1", dy="0.5", font_size="2.16"))
        t.add(Element("tspan", " = -2", dy="-0.5"))
        g.add(Element("path", d="M0 0L1 1", stroke="#000", fill=None))
        g.add(Element("g"))
        return g
    ref = svgwrite.Drawing(profile="full", debug=False).g(id="x", class_="a&b")
    t = ref.add(DWG.text("C", x=["1"], y=["2"], font_size="3"))
    t.add(DWG.tspan("1", dy=["0.5"], font_size="2.16"))
    t.add(DWG.tspan(" = -2", dy=["-0.5"]))
    ref.add(DWG.path(d="M0 0L1 1", stroke="#000"))
    ref.add(DWG.g())
    first = svg_string(tree())
    assert first == svg_string(tree()) == svg_string(ref)
