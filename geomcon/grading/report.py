"""``report.html``: the class report — a score histogram and the per-answer correct rate as inline SVG, the
most common diagnoses with counts and one sentence each, and the table of students (a plain HTML table:
printable, and sortable by clicking a column head where scripts run; without them it stays in input order).
Every text from the answers file or the key is HTML-escaped; the page loads nothing from elsewhere.
"""
from __future__ import annotations

import re
from collections import Counter
from html import escape

from . import Gradebook
from .diagnosis import WORDS
from .mistakes import MISTAKES
from .tables import num

BINS = 10
_CSS = """
body{font:14px/1.4 system-ui,'Noto Sans CJK SC',sans-serif;margin:2em;color:#222}
h1{font-size:1.4em} h2{font-size:1.15em;margin-top:1.6em}
table{border-collapse:collapse} th,td{border:1px solid #bbb;padding:2px 6px;text-align:left}
th{background:#eee;cursor:pointer} td.n{text-align:right} tr.bad td{background:#fdecea}
.correct{color:#1a7f37} .wrong{color:#b42318} .blank,.unreadable{color:#777}
svg text{font:11px system-ui,sans-serif}
@media print{body{margin:0} th{cursor:auto} svg{max-width:100%} tr{page-break-inside:avoid}}
"""
_SORT = """
document.querySelectorAll('table.sortable th').forEach(function(th, i){th.addEventListener('click', function(){
 var t = th.closest('table'), b = t.tBodies[0], rows = Array.from(b.rows), up = th.dataset.dir !== 'up';
 rows.sort(function(a, c){var x = a.cells[i].dataset.v || a.cells[i].textContent, y = c.cells[i].dataset.v || c.cells[i].textContent;
  var p = parseFloat(x), q = parseFloat(y); var r = (!isNaN(p) && !isNaN(q)) ? p - q : x.localeCompare(y);
  return up ? r : -r;});
 th.dataset.dir = up ? 'up' : 'down'; rows.forEach(function(r){b.appendChild(r);});});});
"""


def _sentence(code: str, seen: dict[str, str]) -> str:
    """One sentence for a code: the shared words, a recipe's declaration, else (a teacher's code) the words
    of its first occurrence."""
    if code in WORDS:
        return WORDS[code][0]
    for ms in MISTAKES.values():
        for m in ms:
            if m.code == code:
                return m.en
    return seen.get(code, "")


def histogram_svg(scores: list[float], max_score: float) -> str:
    """Bars of how many students scored in each tenth of the maximum score."""
    counts = [0] * BINS
    for s in scores:
        k = min(int(BINS * s / max_score), BINS - 1) if max_score > 0 else 0
        counts[k] += 1
    top = max(counts + [1])
    w, h, bw = 420, 180, 36
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" id="histogram" width="{w}" height="{h + 40}" '
           f'viewBox="0 -12 {w} {h + 52}" role="img" aria-label="score histogram">']
    for i, c in enumerate(counts):
        bh = round(h * c / top, 2)
        x = 30 + i * (bw + 3)
        lo = num(round(max_score * i / BINS, 2))
        out.append(f'<rect class="bar" x="{x}" y="{h - bh + 10}" width="{bw}" height="{bh}" fill="#4a78b8" data-count="{c}"/>')
        out.append(f'<text x="{x + bw / 2}" y="{h + 24}" text-anchor="middle">{lo}</text>')
        if c:
            out.append(f'<text x="{x + bw / 2}" y="{h - bh + 6}" text-anchor="middle">{c}</text>')
    out.append(f'<line x1="28" y1="{h + 10}" x2="{w - 4}" y2="{h + 10}" stroke="#333"/></svg>')
    return "".join(out)


def column_label(key, column: str) -> str:
    """An answer column as a sheet prints its quantity: ``2.gamma_min`` → ``2. γmin``, ``1.AB`` → ``1. AB``,
    a yes/no answer by its words in the key's language (the column's code stays the answers file's contract;
    the report shows it on hover). A column of no known exercise keeps its code.

    >>> from types import SimpleNamespace as N
    >>> key = N(lang="en", students={"1": N(exercises=(N(n=2, recipe="crank_rocker.extremes"),))})
    >>> column_label(key, "2.gamma_min"), column_label(key, "2.xs[1]"), column_label(key, "7.AB")
    ('2. γmin', '2. xs[1]', '7.AB')
    """
    from ..render.results import name_of

    m = re.fullmatch(r"(\d+)\.(\w+)(\[\d+\])?", column)
    if m is None:
        return column
    n, name, index = int(m.group(1)), m.group(2), m.group(3) or ""
    recipe = next((e.recipe for s in key.students.values() for e in s.exercises if e.n == n), None)
    if recipe is None:
        return column
    nm = name_of(name, recipe)
    words = nm.symbol or (nm.zh if key.lang == "zh" else nm.en) or name
    return f"{n}. {words}{index}"


def rates_svg(rates: list[tuple[str, float]], labels: dict[str, str] | None = None) -> str:
    """A horizontal bar per answer column: the share of the class that got it right (each column named by
    ``labels`` when given: :func:`column_label`)."""
    w, row = 480, 20
    h = row * len(rates) + 10
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" id="rates" width="{w}" height="{h}" viewBox="0 0 {w} {h}" '
           'role="img" aria-label="correct rate per answer">']
    for i, (col, r) in enumerate(rates):
        y = 5 + i * row
        out.append(f'<text x="0" y="{y + 13}"><title>{escape(col)}</title>{escape((labels or {}).get(col, col))}</text>')
        out.append(f'<rect x="120" y="{y}" width="{round(300 * r, 2)}" height="{row - 4}" fill="#1a7f37" '
                   f'data-rate="{r:.4f}"/>')
        out.append(f'<text x="{126 + 300 * r:.2f}" y="{y + 13}">{100 * r:.0f} %</text>')
    out.append("</svg>")
    return "".join(out)


def report_html(book: Gradebook) -> str:
    """report.html's text (see the module)."""
    rows = book.rows
    graded = [r for r in rows if not r.problem]
    max_score = max((r.max_score for r in graded), default=0.0)
    rates = []
    for c in book.columns:
        gs = [g for r in graded for g in r.answers if g.column == c]
        rates.append((c, sum(g.verdict == "correct" for g in gs) / len(gs) if gs else 0.0))
    codes = Counter(g.diagnosis for r in graded for g in r.answers if g.diagnosis)
    seen: dict[str, str] = {}
    labels = {c: column_label(book.key, c) for c in book.columns}
    for r in graded:
        for g in r.answers:
            if g.diagnosis and g.diagnosis not in seen:
                seen[g.diagnosis] = g.en
    title = escape(book.key.heading() or "Class report")          # in the key's language (both: "English  中文")
    mean = sum(r.score for r in graded) / len(graded) if graded else 0.0
    lang = "zh" if book.key.lang == "zh" else "en"
    out = ["<!DOCTYPE html>", f'<html lang="{lang}"><head><meta charset="utf-8">', f"<title>{title} — grades</title>",
           f"<style>{_CSS}</style></head><body>", f"<h1>{title}</h1>",
           f'<p id="summary">{len(rows)} rows, {len(graded)} graded; mean score {num(round(mean, 2))} of '
           f"{num(max_score)}.</p>",
           "<h2>Scores</h2>", histogram_svg([r.score for r in graded], max_score),
           "<h2>Correct rate per answer</h2>", rates_svg(rates, labels),
           "<h2>Most common mistakes</h2>"]
    if codes:
        out.append('<table id="diagnoses"><thead><tr><th>diagnosis</th><th>count</th><th>what it means</th></tr></thead><tbody>')
        for code, n in sorted(codes.items(), key=lambda kv: (-kv[1], kv[0])):
            out.append(f"<tr><td>{escape(code)}</td><td class=\"n\">{n}</td><td>{escape(_sentence(code, seen))}</td></tr>")
        out.append("</tbody></table>")
    else:
        out.append("<p>No diagnosed mistakes.</p>")
    if book.notes:
        out.append("<h2>Notes</h2><ul id=\"notes\">" + "".join(f"<li>{escape(n)}</li>" for n in book.notes[:200])
                   + (f"<li>… {len(book.notes) - 200} more</li>" if len(book.notes) > 200 else "") + "</ul>")
    out.append("<h2>Students</h2>")
    out.append('<table id="students" class="sortable"><thead><tr><th>line</th><th>id</th><th>name</th><th>score</th>'
               + "".join(f'<th title="{escape(c)}">{escape(labels[c])}</th>' for c in book.columns)
               + "</tr></thead><tbody>")
    for r in rows:
        by = {g.column: g for g in r.answers}
        cls = ' class="bad"' if r.problem or r.duplicate else ""
        cells = [f'<td class="n">{r.line}</td>', f"<td>{escape(r.id)}</td>", f"<td>{escape(r.name)}</td>",
                 f'<td class="n" data-v="{num(r.score)}">{num(r.score)} / {num(r.max_score)}</td>']
        for c in book.columns:
            g = by.get(c)
            if g is None:
                cells.append("<td></td>")
                continue
            shown = g.verdict if g.verdict != "wrong" else (g.diagnosis or "wrong")
            cells.append(f'<td class="{g.verdict}" title="{escape(g.text[:80])}">{escape(shown)}</td>')
        out.append(f"<tr{cls}>" + "".join(cells) + "</tr>")
    out.append("</tbody></table>")
    out.append(f"<script>{_SORT}</script></body></html>")
    return "\n".join(out) + "\n"


__all__ = ["column_label", "histogram_svg", "rates_svg", "report_html"]
