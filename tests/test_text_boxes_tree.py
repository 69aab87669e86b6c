""":func:`geomcon.render.charts.text_boxes` of an element tree is that of the tree written out: the boxes of the
figure's texts that a cam's s–δ marks keep clear of are read from the tree without writing and parsing it."""
from __future__ import annotations

import svgwrite

from geomcon.render.charts import text_boxes
from geomcon.render.serial import Element, svg_string
from geomcon.render.shapes import add_runs


def _tree() -> Element:
    root = Element("g", id="figure")
    layer = root.add(Element("g", id="layer-a"))
    t = layer.add(Element.named("text", {"x": "10", "y": "20", "font-size": "2.5", "text-anchor": "middle"}))
    add_runs(t, (("s = -3.5·h", False), ("max", True), (" & <x>", False)), 2.5)
    layer.add(Element("text", "", x="1", y="2"))                        # empty: no box
    layer.add(Element("text", "90°", x="4", font_size=None, text_anchor=""))   # attributes left out
    layer.add(Element("path", d="M0 0L1 1"))
    deep = root.add(Element("g")).add(Element("g"))
    deep.add(Element("text", "C", x="7.5", y="-2", font_size="3.6", text_anchor="end"))
    return root


def test_a_tree_is_read_as_it_is_written():
    tree = _tree()
    boxes = text_boxes(tree)
    assert len(boxes) == 3
    assert boxes == text_boxes(svg_string(tree))


def test_a_tree_holding_an_svgwrite_element_is_read_from_its_text():
    tree = _tree()
    tree.add(svgwrite.Drawing(profile="full", debug=False).text("-12 mm", insert=("3", "4"), font_size="3"))
    assert text_boxes(tree) == text_boxes(svg_string(tree))
    assert len(text_boxes(tree)) == 4
