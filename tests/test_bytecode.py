"""``geomcon gallery`` keeps its byte-code in the user's cache folder when Python is told not to write it beside
the sources (``PYTHONDONTWRITEBYTECODE``): the checkout is left exactly as it was, and a second run reads the
compiled modules instead of compiling them again."""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

from geomcon.bytecode import bytecode_cached

ROOT = Path(__file__).resolve().parents[1]


def _tree(folder: Path) -> dict[str, int]:
    return {p.relative_to(folder).as_posix(): p.stat().st_mtime_ns for p in folder.rglob("*")}


def test_the_gallery_caches_its_byte_code_outside_the_checkout(tmp_path):
    problems = tmp_path / "problems"
    problems.mkdir()
    shutil.copy(ROOT / "problems" / "001-08_crank_rocker.toml", problems)
    env = {**os.environ, "PYTHONDONTWRITEBYTECODE": "1", "XDG_CACHE_HOME": str(tmp_path / "cache")}
    env.pop("PYTHONPYCACHEPREFIX", None)
    argv = [sys.executable, "-m", "geomcon", "gallery", "--problems", str(problems), "--out", str(tmp_path / "out")]
    before = _tree(ROOT / "geomcon")
    assert subprocess.run(argv, cwd=ROOT, env=env, capture_output=True, timeout=300).returncode == 0
    assert _tree(ROOT / "geomcon") == before                      # no __pycache__ written into the checkout
    mirrored = tmp_path / "cache" / "geomcon" / "pycache" / (ROOT / "geomcon").relative_to(ROOT.anchor)
    cached = {p.name.split(".")[0]: p for p in mirrored.rglob("*.pyc")}
    assert {"gallery", "svg", "placement", "solve"} <= set(cached)
    stamps = {name: p.stat().st_mtime_ns for name, p in cached.items()}
    assert subprocess.run(argv, cwd=ROOT, env=env, capture_output=True, timeout=300).returncode == 0
    assert {name: p.stat().st_mtime_ns for name, p in cached.items()} == stamps    # read again, not rewritten


def test_the_settings_come_back_after_the_command(tmp_path):
    before = (sys.pycache_prefix, sys.dont_write_bytecode)
    sys.dont_write_bytecode = True
    try:
        with bytecode_cached(tmp_path):
            assert (sys.pycache_prefix, sys.dont_write_bytecode) == (before[0] or str(tmp_path), False)
        assert (sys.pycache_prefix, sys.dont_write_bytecode) == (before[0], True)
    finally:
        sys.pycache_prefix, sys.dont_write_bytecode = before
