"""svgwrite imported for the gallery without ``urllib.request`` and ``svgwrite.data.svgparser`` (never run by
geomcon): the parent of a gallery build with workers (its serial part: the preload before the fork) imports
neither, and ``sys.modules`` holds no stand-in (the grading job's ``xml.sax.saxutils`` imports
``urllib.request`` in its worker, for real)."""
from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

PROBE = """
import sys
from pathlib import Path
from geomcon.gallery import build_gallery
files = build_gallery(Path(sys.argv[1]), jobs=2)
assert "001-08_crank_rocker.svg" in files
print(sorted(m for m in ("urllib.request", "svgwrite.data.svgparser", "http.client") if m in sys.modules))
import urllib.request
print(hasattr(urllib.request, "Request"))
"""


def test_the_gallery_parent_imports_neither_urllib_request_nor_the_svg_parser(tmp_path):
    shutil.copy(ROOT / "problems" / "001-08_crank_rocker.toml", tmp_path)
    r = subprocess.run([sys.executable, "-c", PROBE, str(tmp_path)], cwd=ROOT, capture_output=True, text=True,
                       timeout=300)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines() == ["[]", "True"]          # none imported; the real module comes on demand
