"""Drawing scenes: annotated SVG, step frames and a self-contained HTML step player."""
from .player import render_html
from .svg import model_extent, render_svg, write_frames

__all__ = ["model_extent", "render_html", "render_svg", "write_frames"]
