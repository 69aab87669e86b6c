"""The class report names each answer column as the sheets print its quantity (hlook11m's review: the teacher
read "2.gamma_min", "3.alpha_max_rise", "3.rho_min_actual" — the answers file's codes — in the rates chart and the
students' table). The code stays on hover (``title``) and in the CSV/JSON, which are the public contract."""
from __future__ import annotations

import re
from pathlib import Path

REPORT = Path(__file__).resolve().parents[1] / "gallery" / "grading_report.html"


def test_the_report_prints_symbols_not_codes():
    html = REPORT.read_text(encoding="utf-8")
    heads = re.findall(r"<th[^>]*>([^<]*)</th>", html)
    assert "2. γmin" in heads and not any(re.fullmatch(r"\d+\.\w+_\w+", h) for h in heads), heads
    assert '<th title="2.gamma_min">2. γmin</th>' in html
    bars = re.findall(r'<text x="0" y="\d+"><title>([^<]*)</title>([^<]*)</text>', html)
    assert ("2.gamma_min", "2. γmin") in bars and all(code != shown or "_" not in code for code, shown in bars)
