"""The whole-cycle bench as a record and a figure: the rows of one full ``geomcon bench`` run kept as JSON
(``problems/cycles/bench_record.json``, written by ``geomcon bench --cycle-record FILE``) and drawn as a bar
chart for the gallery (``bench_cycle.svg``).

Timings differ from run to run, so the gallery never measures: it draws the committed record, and its bytes
depend on that file alone. A new full run rewrites the record; the gallery then changes with it, and the
stale-gallery test says so.

Examples
--------
>>> rows = [CycleRow(NUMPY, 1000, 0.001, 1e6, float("nan")),
...         CycleRow("geomcon positions", 1000, 0.002, 5e5, 1e-16),
...         CycleRow("pylinkage step_fast (numba)", 1000, 0.004, 2.5e5, 1e-11)]
>>> rec = record_of(rows, "a test run")
>>> [r["vs_pylinkage"] for r in rec["rows"]]
[4.0, 2.0, 1.0]
>>> parse_record(rec)["rows"][1]["cos_sin"]
2.0
>>> svg = cycle_figure(rec)
>>> svg.startswith("<svg") and "2.00× pylinkage" in svg
True
"""
from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any, Mapping

from .cycle import NUMPY, CycleRow

RECORD = Path("cycles") / "bench_record.json"
"""Where the record lives, under ``problems/``."""
MAX_BYTES = 64_000
"""A record larger than this is refused (it holds a dozen rows)."""
_FIELDS = ("method", "n", "m_per_s", "vs_pylinkage", "cos_sin", "rel_error")


def _reference(rows: list[CycleRow], pred) -> CycleRow | None:
    return next((r for r in rows if pred(r.method)), None)


def record_of(rows: list[CycleRow], measured: str) -> dict[str, Any]:
    """The JSON record of a bench run's cycle rows: per row the rate in M positions/s, its ratio to
    pylinkage's positions (None where pylinkage was not measured) and its time over numpy's cos + sin."""
    pl = _reference(rows, lambda m: m.startswith("pylinkage step_fast") and "kinematics" not in m)
    base = _reference(rows, lambda m: m == NUMPY)
    out = []
    for r in rows:
        out.append({"method": r.method, "n": r.n, "m_per_s": round(r.rate / 1e6, 3),
                    "vs_pylinkage": round(r.rate / pl.rate, 3) if pl else None,
                    "cos_sin": round(r.seconds / base.seconds, 3) if base else None,
                    "rel_error": None if math.isnan(r.rel_error) else float(f"{r.rel_error:.2g}")})
    return {"measured": measured, "rows": out}


def record_text(record: Mapping[str, Any]) -> str:
    """The record as the committed file holds it (sorted keys, two-space indent, final newline)."""
    return json.dumps(record, ensure_ascii=False, indent=2, sort_keys=True) + "\n"


def parse_record(data: Any, where: str = "bench record") -> dict[str, Any]:
    """Check a record's shape and types (a file is data, never code); raise ValueError naming the key."""
    if not isinstance(data, dict) or not isinstance(data.get("measured"), str) or not isinstance(data.get("rows"), list):
        raise ValueError(f"{where}: needs 'measured' (text) and 'rows' (a list)")
    if not 1 <= len(data["rows"]) <= 32:
        raise ValueError(f"{where}: 'rows' holds {len(data['rows'])} rows (1 to 32)")
    for i, row in enumerate(data["rows"]):
        if not isinstance(row, dict) or set(row) != set(_FIELDS) or not isinstance(row["method"], str):
            raise ValueError(f"{where}: rows[{i}] needs exactly the keys {', '.join(_FIELDS)}")
        for key in _FIELDS[1:]:
            v = row[key]
            if key in ("m_per_s", "n") and not (isinstance(v, (int, float)) and not isinstance(v, bool) and v > 0):
                raise ValueError(f"{where}: rows[{i}].{key} = {v!r} is not a positive number")
            if v is not None and not (isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)):
                raise ValueError(f"{where}: rows[{i}].{key} = {v!r} is not a number")
    return data


def load_record(path: Path) -> dict[str, Any]:
    """Read and check the record at ``path`` (at most :data:`MAX_BYTES`)."""
    raw = Path(path).read_bytes()
    if len(raw) > MAX_BYTES:
        raise ValueError(f"{path}: {len(raw)} bytes, more than {MAX_BYTES}")
    return parse_record(json.loads(raw.decode("utf-8")), str(path))


W, ROW, LEFT, TOP, BAR_W = 1180, 34, 330, 70, 380
MM = 0.25
"""Millimetres of paper per unit: the chart is 295 mm wide (A4 landscape), its smallest text (11 units) 2.75 mm."""
FONT = "DejaVu Sans, Arial, Helvetica, sans-serif"


def cycle_figure(record: Mapping[str, Any]) -> str:
    """A horizontal bar chart of the record: M positions/s per row (numpy's cos + sin row left out: it is the
    yardstick, not a method), each bar labelled with its rate, its ratio to pylinkage and to cos + sin."""
    import svgwrite

    rows = [r for r in record["rows"] if r["method"] != NUMPY]
    top = max(r["m_per_s"] for r in rows)
    h = TOP + ROW * len(rows) + 86
    d = svgwrite.Drawing(size=(f"{W * MM:g}mm", f"{h * MM:g}mm"), viewBox=f"0 0 {W} {h}", debug=False)
    d.add(d.rect((0, 0), (W, h), fill="white"))
    t = {"font_family": FONT, "fill": "#222"}
    d.add(d.text("Whole cycle: four-bar 50/70/80/90, positions per second over the same N crank angles",
                 insert=(20, 28), font_size=16, font_weight="bold", **t))
    d.add(d.text("bars: million positions per second (longer is faster); × cos+sin: time over numpy's cos + sin "
                 "of the N angles in the same run", insert=(20, 50), font_size=12, **t))
    for i, r in enumerate(rows):
        y = TOP + i * ROW
        colour = "#1f6fb4" if r["method"].startswith("geomcon") else "#c8372d"
        d.add(d.text(r["method"], insert=(LEFT - 10, y + 17), font_size=12, text_anchor="end", **t))
        d.add(d.rect((LEFT, y + 4), (max(1.0, BAR_W * r["m_per_s"] / top), ROW - 10), fill=colour))
        parts = [f"{r['m_per_s']:.1f} M/s"]
        if r["vs_pylinkage"] is not None:
            parts.append(f"{r['vs_pylinkage']:.2f}× pylinkage")
        if r["cos_sin"] is not None:
            parts.append(f"{r['cos_sin']:.2f}× cos+sin")
        if r["rel_error"] is not None:
            parts.append(f"|C − twin| {r['rel_error']:.1e}")
        x = LEFT + BAR_W * r["m_per_s"] / top + 8
        d.add(d.text(" · ".join(parts), insert=(x, y + 17), font_size=11, **t))
    n = rows[0]["n"]
    d.add(d.text(f"N = {n:,} float64, CPU time, best of repeats.", insert=(20, h - 54), font_size=11, **t))
    d.add(d.text(f"Measured: {record['measured'][:160]}", insert=(20, h - 36), font_size=11, **t))
    d.add(d.text("A record of one full `geomcon bench` run (problems/cycles/bench_record.json): the gallery draws "
                 "it, it does not time anything.", insert=(20, h - 18), font_size=11, **t))
    return d.tostring()


__all__ = ["MAX_BYTES", "RECORD", "cycle_figure", "load_record", "parse_record", "record_of", "record_text"]
