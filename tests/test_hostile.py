"""Hostile problem files: every signature of issue 9's fuzz is a clean exit 2 with one line, nothing written.

Each case runs the real command in-process and is judged by the same rules as ``geomcon fuzz``.
"""
from __future__ import annotations

import json
import os
import stat
import threading
import time
from pathlib import Path

import pytest

from geomcon.cli import main, one_line

ROOT = Path(__file__).resolve().parents[1]

CRANK = 'recipe = "crank_rocker.extremes"\n[given]\nAB = 50\nBC = 70\nCD = 80\nAD = 90\n'
CAM = ('recipe = "cam.translating"\n[given]\nfollower = "knife"\nr0 = 40\nh = 20\n'
       'program = [{kind = "rise", angle = 180, law = "cosine"}, {kind = "return", angle = 180, law = "cosine"}]\n')


def _refused(tmp_path: Path, capsys, text: str | bytes, *extra: str, name: str = "p.toml", words: str = "") -> str:
    """Run ``solve --json`` (plus ``extra``) on a file; assert exit 2, one line naming the file, nothing on stdout,
    nothing written; return the message."""
    p = tmp_path / name
    p.write_bytes(text if isinstance(text, bytes) else text.encode("utf-8"))
    out = tmp_path / "out"
    before = sorted(tmp_path.rglob("*"))
    rc = main(["solve", str(p), "--json", *extra])
    cap = capsys.readouterr()
    assert rc == 2, (rc, cap.err)
    lines = cap.err.split("\n")
    assert len(lines) == 2 and lines[1] == "" and lines[0].startswith(f"error: {one_line(str(p))}: "), cap.err
    assert cap.out == ""
    assert sorted(tmp_path.rglob("*")) == before, "a refused run wrote something"
    assert not out.exists() or not any(out.rglob("*.tmp"))
    assert words in lines[0], lines[0]
    return lines[0]


@pytest.mark.parametrize("text, words", [
    (CRANK.replace("AB = 50", "AB = " + str(2 ** 1030)), "out of range"),
    (CRANK.replace("AB = 50", "AB = " + "9" * 5000), "malformed TOML"),
    (CRANK.replace("AB = 50", "AB = " + "[" * 500 + "]" * 500), "nested more than"),
    (CRANK.replace("AB = 50", "AB = nan"), "not a finite number"),
    (CRANK.replace("AB = 50", "AB = 1e-15"), "too small"),
    (CRANK.replace("AB = 50", "AB = 1.8e9"), "out of range"),
    ('recipe = "guide_bar.extremes"\n[given]\nAB = 1e-6\nAC = 1e5\n', "times smaller"),
    ('recipe = "four_bar.three_positions_fixed_pivots"\n[given]\nA = [0, 0]\nD = [1e-15, 0]\nB1 = [0.02, 0.015]\n'
     'B2 = [0, 0.025]\nB3 = [-0.02, 0.015]\ncoupler_angles = [10, 0, 0]\n', "the distance AD"),
    ('recipe = "slotter.design_by_K"\n[given]\nK = 1e12\nH = 100\nB1B2 = 50\n', "K"),
    ('recipe = "four_bar.function_generation"\n[given]\nAD = 1e300\nAB = 30\nphi = [0, 30, 60]\npsi = [60, 75, 90]\n',
     "out of range"),
    (CAM.replace("r0 = 40", "r0 = 9223372036854775807"), "out of range"),
    ('recipe = "cam.eccentric"\n[given]\nR = 40\nOA = 10\nomega = 1.8e308\n', "omega"),
    (CAM + "[published]\ns = 12.5\n", "published 's'"),
    (CRANK + "[published]\ntheta = [12.5, 13]\n", "published 'theta'"),
    (CRANK + "[published]\nzz = 1\n", "not an answer"),
    ('title = "a\\u0001b"\n' + CRANK, "control character"),
    (CRANK.replace("[given]", "[given]\n\"a\\nb\" = 1"), "unknown given 'a\\nb'"),
    ('recipe = "crank_rocker.extremes\\nX"\n[given]\nAB = 1\n', "unknown recipe"),
])
def test_hostile_values_are_one_line_refusals(tmp_path, capsys, text, words):
    _refused(tmp_path, capsys, text, words=words)


def test_published_answer_of_another_form_is_refused(tmp_path, capsys):
    text = ('recipe = "cam.base_radius"\n[given]\nh = 20\nalpha_allow = 30\n'
            'program = [{kind = "rise", angle = 180, law = "cosine"}, {kind = "return", angle = 180, law = "cosine"}]\n'
            '[published]\npsi0 = 10\n')
    _refused(tmp_path, capsys, text, words="published 'psi0'")


def test_sizes_are_limited_up_front(tmp_path, capsys):
    dwells = ", ".join(['{kind = "dwell", angle = 0.3}'] * 1000)
    prog = CAM.replace('program = [', f'program = [{dwells}, ')
    t0 = time.perf_counter()
    _refused(tmp_path, capsys, prog, words="program")
    for n, words in ((1001, "at most 1000"), (100000, "at most")):
        at = CAM.replace("h = 20", "h = 20\nat = [" + ", ".join(str(i * 360 / n) for i in range(n)) + "]")
        _refused(tmp_path, capsys, at, words=words)
    _refused(tmp_path, capsys, CRANK + "# " + "x" * (1 << 20) + "\n", words="at most")
    assert time.perf_counter() - t0 < 10


def test_devices_and_fifos_are_refused_without_reading(tmp_path, capsys):
    assert main(["solve", "/dev/zero"]) == 2
    assert capsys.readouterr().err.startswith("error: /dev/zero: cannot read the file: not a regular file")
    fifo = tmp_path / "f.toml"
    os.mkfifo(fifo)
    done = []
    t = threading.Thread(target=lambda: done.append(main(["solve", str(fifo)])), daemon=True)
    t.start()
    t.join(5)
    assert done == [2], "reading a FIFO blocked"


def test_a_file_name_with_a_newline_stays_on_one_line(tmp_path, capsys):
    msg = _refused(tmp_path, capsys, CRANK.replace("AB = 50", "AB = -1"), name="a\nb.toml")
    assert "a\\nb.toml" in msg


def test_nothing_is_written_when_one_output_cannot_be(tmp_path, capsys):
    (tmp_path / "out").mkdir()
    (tmp_path / "out" / "DIR").mkdir()
    _refused(tmp_path, capsys, CRANK, "--svg", str(tmp_path / "out" / "o.svg"), "--html", str(tmp_path / "out" / "DIR"),
             words="--html")
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["DIR"]
    (tmp_path / "file").write_text("x")
    _refused(tmp_path, capsys, CRANK, "--steps", str(tmp_path / "file"), words="--steps")


def test_numpy_never_writes_to_stderr(tmp_path, capsys):
    p = tmp_path / "cam.toml"
    p.write_text(CAM.replace("r0 = 40", "r0 = 1e9").replace("h = 20", "h = 5e8"))
    rc = main(["solve", str(p), "--json"])
    err = capsys.readouterr().err
    assert rc in (0, 2) and err.count("\n") == (rc == 2), err


def test_byte_order_mark_is_accepted_and_outputs_honour_the_umask(tmp_path, capsys):
    p = tmp_path / "bom.toml"
    p.write_bytes(b"\xef\xbb\xbf" + CRANK.encode())
    old = os.umask(0o022)
    try:
        assert main(["solve", str(p), "--svg", str(tmp_path / "a.svg")]) == 0
    finally:
        os.umask(old)
    capsys.readouterr()
    assert stat.S_IMODE((tmp_path / "a.svg").stat().st_mode) == 0o644


def test_json_is_standard_even_for_a_zero_exact_answer(tmp_path, capsys):
    p = tmp_path / "z.toml"
    p.write_text('recipe = "crank_slider.extremes"\n[given]\nAB = 30\nBC = 90\ne = 0\n[published]\ntheta = 1\n')
    assert main(["solve", str(p), "--json"]) == 0
    text = capsys.readouterr().out
    data = json.loads(text, parse_constant=lambda c: pytest.fail(f"non-standard JSON {c}"))
    assert data["published"][0]["rel_deviation"] is None
