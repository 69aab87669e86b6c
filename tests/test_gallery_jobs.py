"""``geomcon gallery --jobs N``: the problems run on several processes, and the files are the same bytes for any N;
a refusal in a worker is the same one line as without workers."""
from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from geomcon.errors import GeomconError, Unbuildable
from geomcon.gallery import build_gallery
from geomcon.workers import run_ordered

ROOT = Path(__file__).resolve().parents[1]
SOME = ["001-08_crank_rocker", "000-02_slotter_design_by_K", "200-01_cam_roller_offset", "100-01_four_bar_three_positions"]


def _refuse(file: str) -> None:
    err = Unbuildable("k", "a step", GeomconError("no circle"))      # a constructor pickling cannot call again
    err.file = file  # type: ignore[attr-defined]
    raise err


def test_results_come_back_in_submission_order_whatever_the_workers():
    jobs = [(pow, (i, 3)) for i in range(9)]
    assert run_ordered(jobs, 1) == run_ordered(jobs, 2) == run_ordered(jobs, 5) == [i ** 3 for i in range(9)]


def test_a_workers_refusal_is_raised_with_its_message_and_file():
    with pytest.raises(GeomconError, match=r"step 'k' \(a step\): no circle") as info:
        run_ordered([(pow, (2, 2)), (_refuse, ("bad.toml",)), (_refuse, ("later.toml",))], 2)
    assert info.value.file == "bad.toml"


def test_jobs_below_one_are_refused():
    with pytest.raises(ValueError):
        run_ordered([(pow, (2, 2))], 0)


def test_the_gallery_is_the_same_bytes_for_any_number_of_workers(tmp_path):
    for pid in SOME:
        shutil.copy(ROOT / "problems" / f"{pid}.toml", tmp_path)
    one = build_gallery(tmp_path, jobs=1)
    assert list(one) == list(build_gallery(tmp_path, jobs=3))        # the same files in the same order …
    assert one == build_gallery(tmp_path, jobs=3)                    # … with the same text
    assert all(f"{pid}.svg" in one for pid in SOME)


def test_a_refused_problem_is_one_line_with_workers(tmp_path):
    shutil.copy(ROOT / "problems" / "001-08_crank_rocker.toml", tmp_path)
    (tmp_path / "zz_bad.toml").write_text('recipe = "crank_rocker.extremes"\n[given]\nAB = 100\nBC = 20\nCD = 30\n'
                                          'AD = 40\n', encoding="utf-8")
    for jobs in ("1", "2"):
        r = subprocess.run([sys.executable, "-m", "geomcon", "gallery", "--problems", str(tmp_path), "--out",
                            str(tmp_path / "out"), "--jobs", jobs], capture_output=True, text=True, timeout=300)
        assert r.returncode == 2 and r.stdout == ""
        assert r.stderr.count("\n") == 1 and r.stderr.startswith(f"error: {tmp_path / 'zz_bad.toml'}: ")
        assert not (tmp_path / "out").exists()


def test_files_compared_in_the_workers_are_none_when_the_folder_holds_their_bytes(tmp_path):
    """``build_gallery(against=DIR)``: each worker compares the files it made with DIR's, so an unchanged file's
    text never travels back (None); a changed, missing or CRLF copy keeps its text, for any number of workers,
    and ``stale_files`` names exactly those (a file is current only byte for byte, as ``geomcon gallery``
    writes it)."""
    from geomcon.gallery import stale_files
    problems, out = tmp_path / "p", tmp_path / "out"
    problems.mkdir()
    for pid in SOME[:2]:
        shutil.copy(ROOT / "problems" / f"{pid}.toml", problems)
    built = build_gallery(problems, jobs=1)
    for name, text in built.items():
        (out / name).parent.mkdir(parents=True, exist_ok=True)
        (out / name).write_bytes(text.encode("utf-8"))
    (out / "001-08_crank_rocker.svg").write_bytes(built["001-08_crank_rocker.svg"].encode() + b" ")
    (out / "001-08_crank_rocker.json").write_bytes(built["001-08_crank_rocker.json"].replace("\n", "\r\n").encode())
    (out / "README.md").unlink()
    moved = {"001-08_crank_rocker.svg", "001-08_crank_rocker.json", "README.md"}
    for jobs in (1, 2):
        marked = build_gallery(problems, jobs=jobs, against=out)
        assert list(marked) == list(built)
        assert {n for n, t in marked.items() if t is not None} == moved
        assert all(marked[n] == built[n] for n in moved)
    assert stale_files(problems, out, jobs=2) == sorted(moved)
