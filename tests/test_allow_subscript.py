"""An allowed bound is subscripted like the bounds it is compared with (αallow beside αmax, ρallow beside ρmin):
hlook11m found 001-19's protocol step 16 printing "sin αallow, αallow = 10°" flat while its results print αmax."""
from __future__ import annotations

import re
from pathlib import Path

from geomcon.render.labels import rich_runs

GALLERY = Path(__file__).parent.parent / "gallery"


def test_allow_after_a_greek_letter_is_a_subscript():
    assert rich_runs("CD / sin αallow, αallow = 10°")[:2] == (("CD / sin α", False), ("allow", True))
    assert rich_runs("ρallow = 40") == (("ρ", False), ("allow", True), (" = 40", False))
    assert rich_runs("allowance, an allowed angle") == (("allowance, an allowed angle", False),)


def test_no_sheet_prints_an_allowed_bound_flat():
    flat = re.compile(r">[^<]*[α-ω]′?allow")
    hits = [p.name for p in sorted(GALLERY.glob("*.svg")) + sorted(GALLERY.glob("*.html"))
            if flat.search(p.read_text(encoding="utf-8"))]
    assert not hits, hits
