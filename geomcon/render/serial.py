"""svgwrite elements as text, written directly: the very string ``element.tostring()`` gives, without building an
ElementTree first (that detour was about a seventh of the gallery's time).

``svgwrite``'s ``tostring`` turns every element into an ``xml.etree`` element (attributes sorted by name, values
through ``str``, empty and None ones left out) and serialises the tree. :func:`svg_string` writes the same
text in one walk, escaping with ElementTree's own functions; an element class whose ``get_xml`` it does not
know is serialised by svgwrite itself, so the output is always ``tostring()``'s.

The bulk of a sheet (the figure's paths, circles and texts, the protocol's lines, their groups: some 800 elements
a sheet) is made of :class:`Element`: a plain tag, attributes and children that :func:`svg_string` writes as
svgwrite writes its element of the same tag and attributes, without svgwrite's per-element set-up (a parameter
object, attribute checks, name translation through ``__setitem__``: about a tenth of the gallery's time). The
document, its style and the title block stay svgwrite's.

Examples
--------
>>> import svgwrite
>>> dwg = svgwrite.Drawing(size=("10mm", "5mm"), profile="full", debug=False)
>>> _ = dwg.defs.add(dwg.style("a > b {}"))
>>> g = dwg.add(dwg.g(id="x", class_="a&b"))
>>> t = g.add(dwg.text("C", insert=(1, 2)))
>>> _ = t.add(dwg.tspan("1", dy=["0.5"]))
>>> _ = g.add(dwg.polyline([(0, 0), (1.5, 2)], fill="none"))
>>> _ = g.add(dwg.path(d="M0 0L1 1", stroke="#000"))
>>> svg_string(dwg) == dwg.tostring()
True
>>> lean = Element("g", id="x", class_="a&b")
>>> t = lean.add(Element("text", "C", x="1", y="2"))
>>> _ = t.add(Element("tspan", "1", dy="0.5"))
>>> _ = lean.add(Element("polyline", points="0,0 1.5,2", fill="none"))
>>> _ = lean.add(Element("path", d="M0 0L1 1", stroke="#000"))
>>> svg_string(lean) == svg_string(g)
True
"""
from __future__ import annotations

import functools
from typing import Any
from xml.etree import ElementTree

from svgwrite.base import BaseElement
from svgwrite.container import Script
from svgwrite.drawing import Drawing
from svgwrite.etree import CDATA_TPL
from svgwrite.path import Path
from svgwrite.shapes import Polyline
from svgwrite.text import TSpan
from svgwrite.utils import strlist

from .minus import MINUS, minus_signs

_attrib = ElementTree._escape_attrib      # type: ignore[attr-defined]  # ElementTree's own escaping
_escape_cdata = ElementTree._escape_cdata        # type: ignore[attr-defined]

PRODUCT_DOT = ("·", "⋅")
"""A product's dot as a sheet prints it: U+22C5 (the dot operator), not U+00B7 (the middle dot), which the CJK font
that sets every text draws full-width, as a Japanese "・" (001-09's title read "S = 2・CD"). Every "·" of the
project's texts is a product (ω·AB, 2·acos, pb3·μ); the JSON and the terminal keep it."""

def typeset(text: str) -> str:
    """A text as a sheet prints it: a product's dot (:data:`PRODUCT_DOT`), a negative number's sign
    (:func:`minus_signs`).

    >>> typeset("S = 2·CD"), typeset("ω3 = -3.351 rad/s")
    ('S = 2⋅CD', 'ω3 = −3.351 rad/s')
    """
    return minus_signs(text.replace(*PRODUCT_DOT))

@functools.lru_cache(maxsize=16384)
def _cdata(text: str) -> str:
    """A text's character data as written: :func:`typeset`, escaped. Remembered (a pure function of the text):
    a gallery writes some 60 000 runs of text, most of them written before ("1", " = ", a step's number)."""
    return _escape_cdata(typeset(text))

_PLAIN = BaseElement.get_xml
_KNOWN = {Drawing.get_xml, Polyline.get_xml, Path.get_xml, TSpan.get_xml, Script.get_xml}

class Element:
    """An SVG element as :func:`svg_string` writes it: ``tag``, character data ``text`` (a text or tspan's; ""
    for none) and attributes named as svgwrite names them (``class_`` → ``class``, ``stroke_width`` →
    ``stroke-width``), each a string (or None: left out, as svgwrite leaves it out); children by :meth:`add`.

    It answers what the renderer asks of an svgwrite element (``attribs``, ``elements``, ``add``,
    ``tostring``), and ``svg_string`` writes it byte for byte as the svgwrite element of the same tag, text and
    attributes (the module's example), inside an svgwrite document or alone.
    """

    __slots__ = ("elementname", "text", "attribs", "elements")

    def __init__(self, tag: str, text: str = "", **attribs: str | None) -> None:
        self.elementname = tag
        self.text = text
        names = _NAMES
        try:
            self.attribs = {names[k]: v for k, v in attribs.items()}
        except KeyError:
            for k in attribs:
                if k not in names:
                    names[k] = k.rstrip("_").replace("_", "-")
            self.attribs = {names[k]: v for k, v in attribs.items()}
        self.elements: list[Any] = []

    @classmethod
    def named(cls, tag: str, attribs: dict[str, str | None], text: str = "") -> Element:
        """The element of ``tag`` with ``attribs`` named as written (``class``, ``stroke-width``: no keyword names
        to translate; the dict is the element's own) and character data ``text``: what the renderer makes
        ~80 000 times a gallery, a fifth of the cost of keywords translated one by one.

        >>> Element.named("text", {"class": "en", "font-size": "3"}, "C").tostring()
        '<text class="en" font-size="3">C</text>'
        """
        el = cls.__new__(cls)
        el.elementname = tag
        el.text = text
        el.attribs = attribs
        el.elements = []
        return el

    def add(self, element: Any) -> Any:
        """Append a child; returns it."""
        self.elements.append(element)
        return element

    def tostring(self) -> str:
        """The element's text (:func:`svg_string`)."""
        return svg_string(self)

    def get_xml(self) -> ElementTree.Element:
        """The element as ElementTree's (for an svgwrite parent serialised by svgwrite itself, as ``get_xml``
        of svgwrite's elements: attributes sorted, the empty ones left out)."""
        xml = ElementTree.Element(self.elementname)
        for key, value in sorted(self.attribs.items()):
            if value is not None and str(value):
                xml.set(key, str(value))
        if self.text:
            xml.text = self.text
        for child in self.elements:
            xml.append(child.get_xml())
        return xml

_NAMES: dict[str, str] = {}
"""Keyword names as attribute names (``class_`` → ``class``, ``stroke_width`` → ``stroke-width``), as
:class:`Element` met them."""

def svg_string(element: Any) -> str:
    """The text of ``element.tostring()`` (an svgwrite element and everything in it)."""
    out: list[str] = []
    _write(element, out)
    return "".join(out)

def _write(el: Any, out: list[str]) -> None:
    if type(el) is Element:
        _write_lean(el, out)
        return
    get_xml = type(el).get_xml
    if get_xml is not _PLAIN and get_xml not in _KNOWN:
        out.append(el.tostring())              # a class this module does not know: as svgwrite writes it
        return
    if isinstance(el, Drawing):
        el.attribs.update({"xmlns": "http://www.w3.org/2000/svg", "xmlns:xlink": "http://www.w3.org/1999/xlink",
                           "xmlns:ev": "http://www.w3.org/2001/xml-events", "baseProfile": el.profile,
                           "version": el.version})
    elif isinstance(el, Polyline):
        el.attribs["points"] = el.points_to_string(el.points)
    elif isinstance(el, Path):
        el.attribs["d"] = str(strlist(el.commands, " "))
    tag = el.elementname
    out.append("<" + tag)
    value_to_string = el.value_to_string
    for key, value in sorted(el.attribs.items()):
        if value is not None:
            value = value_to_string(value)
            if value:
                out.append(f' {key}="{_attrib(value)}"')
    text = str(el.text) if isinstance(el, TSpan) else ""
    content = el._content if isinstance(el, Script) else ""
    if not (text or el.elements or content):
        out.append(" />")
        return
    out.append(">")
    if text:
        out.append(_cdata(text))
    for child in el.elements:
        _write(child, out)
    if content:
        out.append(CDATA_TPL % content)
    out.append(f"</{tag}>")

def _write_lean(el: Element, out: list[str]) -> None:
    """:func:`_write` of an :class:`Element`: as svgwrite's element (values through ``str``, the empty left out).

    Its start tag is its tag and attribute names' template (:func:`_template`: the names sorted once) filled with
    the values, when every value is a non-empty string that needs no escaping (all but a few of a gallery's
    elements); otherwise written attribute by attribute (:func:`_start`)."""
    attribs = el.attribs
    values = tuple(attribs.values())
    try:
        joined = "\0".join(values)            # a TypeError: a None or a value that is not a string
    except TypeError:
        joined = None
    tags = _TEMPLATES.get((el.elementname, tuple(attribs)))
    if tags is None:
        tags = _template(el.elementname, tuple(attribs))
    if joined is None or "" in values or _attrib(joined) is not joined:
        head = _start(el)
    else:
        head = tags[0].format(*values) if values else tags[0]
    text, children = el.text, el.elements
    if not (text or children):
        out.append(head + " />")
        return
    if not children:
        out.append(head + ">" + _cdata(text) + tags[1])
        return
    out.append(head + ">")
    if text:
        out.append(_cdata(text))
    for child in children:
        if type(child) is Element:
            _write_lean(child, out)
        else:
            _write(child, out)
    out.append(tags[1])


def _start(el: Element) -> str:
    """An :class:`Element`'s start tag (without its closing ``>``), attribute by attribute: names sorted, values
    through ``str`` and escaped, None and empty ones left out (as svgwrite writes them)."""
    parts = ["<" + el.elementname]
    for key, value in sorted(el.attribs.items()):
        if value is not None:
            value = value if type(value) is str else str(value)
            if value:
                parts.append(f' {key}="{_attrib(value)}"')
    return "".join(parts)


def _template(tag: str, names: tuple[str, ...]) -> tuple[str, str]:
    """The start tag of ``tag`` with attributes ``names`` (in the order set) as a :meth:`str.format` template of
    their values (names sorted, as svgwrite writes them; without the closing ``>``), and the end tag.
    Remembered: a gallery's elements have some 200 such sets of names."""
    def plain(s: str) -> str:
        return s.replace("{", "{{").replace("}", "}}")
    order = sorted(range(len(names)), key=names.__getitem__)
    head = "<" + plain(tag) + "".join(f' {plain(names[i])}="{{{i}}}"' for i in order)
    out = _TEMPLATES[tag, names] = (head if names else "<" + tag, f"</{tag}>")
    return out


_TEMPLATES: dict[tuple[str, tuple[str, ...]], tuple[str, str]] = {}
""":func:`_template` of the tags and attribute names met."""


__all__ = ["Element", "MINUS", "PRODUCT_DOT", "minus_signs", "svg_string", "typeset"]
