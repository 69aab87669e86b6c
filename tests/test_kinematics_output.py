"""`geomcon cycle`: the table, plots, animation and JSON it writes, its refusals of bad or hostile problem
files (exit 2, one line, nothing written), and the animation driven in headless Chromium."""
from __future__ import annotations

import csv
import io
import json
import re
import shutil
import subprocess
import xml.dom.minidom
from pathlib import Path

import numpy as np
import pytest

from geomcon.cli import main
from geomcon.kinematics.problem import load_cycle
from geomcon.kinematics.quantities import value
from geomcon.kinematics.result import solve_cycle

ROOT = Path(__file__).resolve().parent.parent
SLOTTER = ROOT / "problems" / "cycles" / "000-09_slotter_cycle.toml"
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


def test_cycle_writes_table_plots_animation(tmp_path, capsys):
    out = {k: tmp_path / f"x.{k}" for k in ("csv", "svg", "html")}
    assert main(["cycle", str(SLOTTER), *sum(([f"--{k}", str(v)] for k, v in out.items()), [])]) == 0
    text = capsys.readouterr().out
    assert "stroke(C.y) = 100" in text and "K(C.y) = 1.80249" in text
    rows = list(csv.DictReader(io.StringIO(out["csv"].read_text())))
    assert len(rows) == 181 and list(rows[0]) == ["phi_deg", "O4B.angle", "O4B.omega", "O4B.epsilon", "BC.omega",
                                                   "BC.epsilon", "C.y", "C.vy", "C.ay"]
    r = solve_cycle(load_cycle(SLOTTER))
    yc = np.array([float(x["C.y"]) for x in rows])
    assert np.max(np.abs(yc - value(r.cycle.state, "C.y"))) < 1e-9
    xml.dom.minidom.parseString(out["svg"].read_text())            # well-formed
    page = out["html"].read_text()
    assert page.startswith("<!DOCTYPE html>") and "<script src" not in page


def test_cycle_json_is_standard_and_deterministic(capsys):
    assert main(["cycle", str(SLOTTER), "--json"]) == 0
    first = capsys.readouterr().out
    data = json.loads(first)
    assert data["answers"]["stroke(C.y)"] == 100.0 and data["kind"] == "cycle"
    assert [s["kind"] for s in data["stationary"]] == ["min", "max"]
    assert main(["cycle", str(SLOTTER), "--json"]) == 0
    assert capsys.readouterr().out == first


def _refused(tmp_path: Path, capsys, text: str, needle: str) -> None:
    p = tmp_path / "bad.toml"
    p.write_text(text, encoding="utf-8")
    out = tmp_path / "out.csv"
    assert main(["cycle", str(p), "--csv", str(out)]) == 2
    cap = capsys.readouterr()
    assert cap.out == "" and cap.err.count("\n") == 1 and cap.err.startswith(f"error: {p}: ")
    assert needle in cap.err, cap.err
    assert not out.exists() and not list(tmp_path.glob("*.tmp"))


BASE = SLOTTER.read_text(encoding="utf-8")


@pytest.mark.parametrize("edit, needle", [
    (lambda t: t.replace("length = 46", "length = 8"), "dyad 'C' cannot be assembled"),
    (lambda t: t.replace("length = 46", "length = nan"), "not a finite number"),
    (lambda t: t.replace("branch = 1\nlink = \"BC\"", "branch = 2\nlink = \"BC\""), "must be 1 or -1"),
    (lambda t: t.replace('p = "B"', 'p = "Q"'), "point 'Q' is not placed before it"),
    (lambda t: t.replace("step = 2", "step = 2\nspeed = 3"), "unknown key 'speed'"),
    (lambda t: t.replace("step = 2", "step = 0.0001"), "below the smallest step"),
    (lambda t: t.replace("step = 2", "step = 7"), "does not divide"),
    (lambda t: t.replace('"C.ay"]', '"C.zz"]'), "a point has the fields"),
    (lambda t: t.replace('type = "RRP"', 'type = "RRRR"'), "type must be one of"),
    (lambda t: t.replace('name = "B"', 'name = "B\\u0001"'), "must be a name"),
    (lambda t: t.replace("omega = 4.8147", "omega = 0"), "must not be 0"),
    (lambda t: t.replace('"stroke(C.y)" = 100', '"stroke(C.x)" = 100'), "not an answer of this problem"),
    (lambda t: t + "\n[[mechanism.extra]]\n", "unknown key 'extra'"),
    (lambda t: t.replace("columns = [", "columns = [" + '"C.y", ' * 70), "at most 64"),
    (lambda t: t.replace("kind = \"cycle\"", "kind = \"solve\""), 'kind must be "cycle"'),
])
def test_bad_problems_are_refused_with_one_line(tmp_path, capsys, edit, needle):
    text = edit(BASE)
    assert text != BASE
    _refused(tmp_path, capsys, text, needle)


def test_dead_point_message_names_the_crank_angles(tmp_path, capsys):
    text = BASE.replace("length = 46", "length = 8")
    p = tmp_path / "dead.toml"
    p.write_text(text, encoding="utf-8")
    assert main(["cycle", str(p)]) == 2
    err = capsys.readouterr().err
    angles = [float(x) for x in re.findall(r"(\d+\.\d{6})°", err)]
    assert len(angles) >= 2
    # at each reported angle the margin of dyad C is zero: BC = 8 reaches the guide exactly
    from geomcon.kinematics.chain import solve_chain
    m = load_cycle(SLOTTER).mechanism
    import dataclasses
    m = dataclasses.replace(m, chain=(*m.chain[:2], dataclasses.replace(m.chain[2], length=8.0)))
    st = solve_chain(m, np.radians(angles))
    assert np.all(np.abs(st.margins["C"]) < 1e-6)


def test_oversized_and_non_regular_files_are_refused(tmp_path, capsys):
    big = tmp_path / "big.toml"
    big.write_text(BASE + "#" * (1 << 20), encoding="utf-8")
    assert main(["cycle", str(big)]) == 2
    assert "at most 1048576 bytes" in capsys.readouterr().err
    assert main(["cycle", str(tmp_path)]) == 2
    assert "a directory" in capsys.readouterr().err


@pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium not installed (apt-get install chromium)")
def test_animation_in_headless_chromium_shows_the_frame_asked_for(tmp_path):
    r = solve_cycle(load_cycle(SLOTTER))
    from geomcon.kinematics.animation import animation_html, scene_data
    page = tmp_path / "anim.html"
    page.write_text(animation_html(r), encoding="utf-8")
    k = 57
    out = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--dump-dom",
                          page.as_uri() + f"#frame={k}"], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-500:]
    dom = out.stdout
    assert f'data-frame="{k}"' in dom
    frame = scene_data(r)["frames"][k]
    assert f"φ = {frame['phi']:g}°" in dom
    circle = re.search(r'<circle[^>]*data-point="C"[^>]*>', dom).group(0)
    cx, cy = (float(re.search(rf'{a}="([^"]+)"', circle).group(1)) for a in ("cx", "cy"))
    assert (cx, cy) == tuple(frame["p"]["C"])
    assert abs(complex(cx, cy) - complex(r.cycle.state.points["C"].p[k])) < 1e-9 * 300
    trace = re.search(r'<polyline[^>]*data-point="C"[^>]*>', dom)
    assert trace and trace.group(0).count(",") >= 180
