"""``geomcon gallery`` writes only the files whose bytes change: a file already as built keeps its time stamp
(and the run skips ~0.15 s of writing 16 MB again), a file that differs in any byte is written again."""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

from geomcon.fileio import changed, write_all

ROOT = Path(__file__).resolve().parents[1]


def test_changed_compares_bytes_not_text(tmp_path):
    write_all({tmp_path / "a.txt": "alpha\n", tmp_path / "b.txt": "beta\n", tmp_path / "c.txt": "γ\n"})
    (tmp_path / "b.txt").write_bytes(b"beta\r\n")                 # reads as "beta\n" with universal newlines
    (tmp_path / "sub").mkdir()
    got = changed({tmp_path / "a.txt": "alpha\n", tmp_path / "b.txt": "beta\n", tmp_path / "c.txt": "γ\n",
                   tmp_path / "d.txt": "", tmp_path / "sub": "x"})
    assert sorted(Path(p).name for p in got) == ["b.txt", "d.txt", "sub"]


def test_a_second_gallery_run_rewrites_only_what_differs(tmp_path):
    problems = tmp_path / "problems"
    problems.mkdir()
    shutil.copy(ROOT / "problems" / "001-08_crank_rocker.toml", problems)
    out = tmp_path / "out"
    run = [sys.executable, "-m", "geomcon", "gallery", "--problems", str(problems), "--out", str(out)]
    first = subprocess.run(run, capture_output=True, text=True, timeout=300)
    assert first.returncode == 0, first.stderr
    files = sorted(p for p in out.rglob("*") if p.is_file())
    assert first.stdout.startswith(f"wrote {len(files)} files to ")
    old = 1_000_000_000
    for p in files:
        os.utime(p, (old, old))
    svg = out / "001-08_crank_rocker.svg"
    svg.write_bytes(svg.read_bytes().replace(b"\n", b"\r\n"))      # the same text, other bytes
    (out / "README.md").write_text("hand edit\n", encoding="utf-8")
    second = subprocess.run(run, capture_output=True, text=True, timeout=300)
    assert second.returncode == 0, second.stderr
    assert second.stdout.startswith(f"wrote 2 files ({len(files) - 2} unchanged) to ")
    moved = sorted(p.relative_to(out).as_posix() for p in files if p.stat().st_mtime != old)
    assert moved == ["001-08_crank_rocker.svg", "README.md"]
    assert b"\r\n" not in svg.read_bytes()
