"""The whole-cycle bench record and its gallery figure: a measured run kept as data, drawn deterministically;
a malformed record is refused in one line and the gallery writes nothing."""
import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from geomcon.bench.cycle import measure_cycle
from geomcon.bench.cycle_record import cycle_figure, load_record, parse_record, record_of, record_text

ROOT = Path(__file__).resolve().parents[1]


def test_committed_record_parses_and_draws_every_method():
    rec = load_record(ROOT / "problems" / "cycles" / "bench_record.json")
    svg = cycle_figure(rec)
    for row in rec["rows"][1:]:
        assert row["method"] in svg
    assert cycle_figure(rec) == svg                     # deterministic


def test_a_measured_run_makes_a_record_that_round_trips():
    rows = measure_cycle(n=20_000, repeat=1, pylinkage=False)
    rec = record_of(rows, "test")
    back = parse_record(json.loads(record_text(rec)))
    assert back == rec
    assert all(r["vs_pylinkage"] is None for r in rec["rows"])       # pylinkage not measured: no ratio invented
    assert rec["rows"][0]["cos_sin"] == 1.0
    assert all(r["rel_error"] < 1e-12 for r in rec["rows"][1:])


@pytest.mark.parametrize("bad, key", [
    ({"rows": []}, "measured"),
    ({"measured": "x", "rows": []}, "rows"),
    ({"measured": "x", "rows": [{"method": "m"}]}, "rows[0]"),
    ({"measured": "x", "rows": [{"method": "m", "n": 10, "m_per_s": -1, "vs_pylinkage": None, "cos_sin": None,
                                 "rel_error": None}]}, "rows[0].m_per_s"),
    ({"measured": "x", "rows": [{"method": "m", "n": 10, "m_per_s": 1, "vs_pylinkage": "2", "cos_sin": None,
                                 "rel_error": None}]}, "rows[0].vs_pylinkage"),
])
def test_malformed_records_are_refused_naming_the_key(bad, key):
    with pytest.raises(ValueError, match=key.replace("[", r"\[").replace("]", r"\]")):
        parse_record(bad)


def test_gallery_refuses_a_bad_record_in_one_line_and_writes_nothing(tmp_path):
    problems = tmp_path / "problems"
    (problems / "cycles").mkdir(parents=True)
    shutil.copy(ROOT / "problems" / "001-05_guide_bar.toml", problems)
    (problems / "cycles" / "bench_record.json").write_text('{"measured": 1, "rows": []}', encoding="utf-8")
    out = tmp_path / "g"
    r = subprocess.run([sys.executable, "-m", "geomcon", "gallery", "--problems", str(problems), "--out", str(out)],
                       capture_output=True, text=True)
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and "bench_record.json: " in lines[0]
    assert "measured" in lines[0] and "Traceback" not in r.stderr
    assert not out.exists()
