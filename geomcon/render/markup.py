"""A small SVG element tree, written out byte for byte as svgwrite (``debug=False``) and ElementTree wrote it.

Attribute names come from keywords as svgwrite spelled them (``class_`` → ``class``, ``stroke_width`` →
``stroke-width``) or are set directly (``xml:space``); values are written with ``str``, ``None`` and empty
ones left out, sorted by name, escaped as ElementTree escapes them. An element with neither text nor
children closes as ``<tag … />``; a style sheet is one CDATA section.

Examples
--------
>>> g = Element("g", id="a&b")
>>> _ = g.add(Element("path", d="M0 0L1 1", stroke_width="0.3", class_="ink", fill=None))
>>> _ = g.add(Element("text", "x < y", x="1", y=""))
>>> g.tostring()
'<g id="a&amp;b"><path class="ink" d="M0 0L1 1" stroke-width="0.3" /><text x="1">x &lt; y</text></g>'
"""
from __future__ import annotations

from typing import Any, Callable


class Element:
    """An SVG element: ``tag``, ``attribs`` (SVG names), child ``elements``, character ``text`` and, for a
    style sheet, ``cdata``."""

    __slots__ = ("tag", "text", "cdata", "attribs", "elements")

    def __init__(self, tag: str, text: str = "", *, cdata: str = "", **attribs: Any):
        self.tag = tag
        self.text = text
        self.cdata = cdata
        self.attribs = {_NAMES.get(k) or _name(k): v for k, v in attribs.items()}
        self.elements: list[Element] = []

    def add(self, element: Element) -> Element:
        """Append a child; returns it."""
        self.elements.append(element)
        return element

    def tostring(self) -> str:
        """The element and its children as XML text."""
        out: list[str] = []
        self._write(out.append)
        return "".join(out)

    def _write(self, write: Callable[[str], Any]) -> None:
        write("<" + self.tag)
        for name, value in sorted(self.attribs.items()):
            if value is not None:
                value = str(value)
                if value:
                    write(f' {name}="{escape_attrib(value)}"')
        if self.text or self.elements or self.cdata:
            write(">")
            if self.text:
                write(escape_text(self.text))
            if self.cdata:
                write(f"<![CDATA[{self.cdata}]]>")
            for el in self.elements:
                el._write(write)
            write(f"</{self.tag}>")
        else:
            write(" />")


_NAMES: dict[str, str] = {}


def _name(keyword: str) -> str:
    """The SVG name of a keyword, as svgwrite spelled it: ``class_`` → ``class``, ``stroke_width`` →
    ``stroke-width``."""
    _NAMES[keyword] = out = keyword.rstrip("_").replace("_", "-")
    return out


def escape_text(text: str) -> str:
    """Character data escaped as ElementTree escapes it (``&``, ``<``, ``>``)."""
    if "&" in text:
        text = text.replace("&", "&amp;")
    if "<" in text:
        text = text.replace("<", "&lt;")
    if ">" in text:
        text = text.replace(">", "&gt;")
    return text


def escape_attrib(text: str) -> str:
    """An attribute value escaped as ElementTree (Python 3.11) escapes it.

    >>> escape_attrib('a "b" <c>\\n&')
    'a &quot;b&quot; &lt;c&gt;&#10;&amp;'
    """
    if "&" in text:
        text = text.replace("&", "&amp;")
    if "<" in text:
        text = text.replace("<", "&lt;")
    if ">" in text:
        text = text.replace(">", "&gt;")
    if '"' in text:
        text = text.replace('"', "&quot;")
    if "\r" in text:
        text = text.replace("\r", "&#13;")
    if "\n" in text:
        text = text.replace("\n", "&#10;")
    if "\t" in text:
        text = text.replace("\t", "&#09;")
    return text


def svg_root(width: str, height: str, view_box: str, profile: str = "full") -> Element:
    """The ``<svg>`` element as ``svgwrite.Drawing(size=(width, height), viewBox=…, profile=…)`` wrote it,
    with its ``<defs>`` as first child (:func:`defs_of`)."""
    root = Element("svg", width=width, height=height, viewBox=view_box)
    root.attribs.update({"xmlns": "http://www.w3.org/2000/svg", "xmlns:xlink": "http://www.w3.org/1999/xlink",
                         "xmlns:ev": "http://www.w3.org/2001/xml-events", "baseProfile": profile, "version": "1.1"})
    root.add(Element("defs"))
    return root


def defs_of(root: Element) -> Element:
    """The ``<defs>`` element of a :func:`svg_root`."""
    return root.elements[0]


def style_sheet(css: str) -> Element:
    """A ``<style type="text/css">`` element holding ``css`` as CDATA."""
    return Element("style", cdata=css, type="text/css")
