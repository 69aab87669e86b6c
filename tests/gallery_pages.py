"""The page the gallery printed a problem on (A4, landscape unless portrait draws larger:
:func:`geomcon.gallery.problem_sheets`), read from the committed sheet 1, so that a test replaying a gallery sheet
lays it out on the same page without rendering both orientations (``test_gallery.py`` fails when the gallery is
stale)."""
from __future__ import annotations

import re
from pathlib import Path

from geomcon.gallery import gallery_page

GALLERY = Path(__file__).resolve().parents[1] / "gallery"


def page_of(stem: str, lang: str | None = None):
    """The :class:`~geomcon.render.page.PageSpec` of the gallery's ``<stem>.svg`` (``stem`` the problem file's
    stem), in ``lang`` when given: portrait when the sheet is taller than wide."""
    head = (GALLERY / f"{stem}.svg").read_text(encoding="utf-8")[:600]
    w, h = (float(v) for v in re.search(r'viewBox="0 0 ([\d.]+) ([\d.]+)"', head).groups())
    page = gallery_page(lang)
    return page if (h > w) == (page.orientation == "portrait") else page.__class__(
        page.paper, "portrait" if h > w else "landscape", page.lang)
