"""What the cam-sheet tests read from the gallery (tests/test_cam_flat_sheet.py, tests/test_cam_knife_sheet.py):
the problems of one follower, a sheet's text without its markup, and every sheet and player of a problem."""
from __future__ import annotations

import re
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
GALLERY, PROBLEMS = ROOT / "gallery", ROOT / "problems"


def with_follower(kind: str) -> list[str]:
    """The stems of the bundled problems whose ``follower`` is ``kind`` and that the gallery holds."""
    out = []
    for p in sorted(PROBLEMS.glob("*.toml")):
        data = tomllib.loads(p.read_text(encoding="utf-8"))
        if data.get("given", {}).get("follower") == kind and (GALLERY / f"{p.stem}.json").exists():
            out.append(p.stem)
    return out


def text(path: Path) -> str:
    """A gallery file's text with its markup stripped (subscripts join their base)."""
    return re.sub(r"<[^>]*>", "", path.read_text(encoding="utf-8"))


def printed_off_sheet(stem: str, words: tuple[str, ...]) -> list[str]:
    """``file: word`` for each of ``words`` a sheet, s–v–a sheet or player of ``stem`` prints (none expected)."""
    files = [f for f in sorted(GALLERY.glob(f"{stem}*")) if f.suffix in (".svg", ".html")
             and re.fullmatch(re.escape(stem) + r"(-\d+|_motion(-\d+)?)?", f.stem)]
    assert files, stem
    return [f"{f.name}: {w}" for f in files for w in words if w in text(f)]
