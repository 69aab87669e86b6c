"""Drawing scenes as a teacher would: an annotated SVG (figure at a nice scale, numbered construction
protocol in English and Chinese, results), one SVG per step, and a self-contained HTML step player.

Public functions: :func:`render_svg`, :func:`model_extent`, :func:`write_frames`, :func:`render_html`.
Styles are in :mod:`geomcon.render.style`.
"""
from typing import Any

_LAZY = {"render_html": ".player", "model_extent": ".svg", "render_svg": ".svg", "write_frames": ".svg"}


def __getattr__(name: str) -> Any:
    """The public functions, imported when first used: ``geomcon.render.results`` (the words of a text summary)
    loads neither svgwrite nor numpy."""
    if name in _LAZY:
        import importlib
        return getattr(importlib.import_module(_LAZY[name], __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

__all__ = ["model_extent", "render_html", "render_svg", "write_frames"]
