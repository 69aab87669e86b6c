"""Drawing scenes as a teacher would: an annotated SVG (figure at a nice scale, numbered construction
protocol in English and Chinese, results), one SVG per step, and a self-contained HTML step player.

Public functions: :func:`render_svg`, :func:`model_extent`, :func:`write_frames`, :func:`render_html`.
Styles are in :mod:`geomcon.render.style`.
"""
from .player import render_html
from .svg import model_extent, render_svg, write_frames

__all__ = ["model_extent", "render_html", "render_svg", "write_frames"]
