"""The printed tables of ``geomcon bench``: aligned plain-text columns.

Examples
--------
>>> print(format_table(("name", "value"), [("a", "1"), ("bcd", "10")], "lr"))
name  value
----  -----
a         1
bcd      10
>>> fmt_seconds(0.000123), fmt_seconds(0.0456), fmt_bytes(2048), fmt_error(0.0)
('123 µs', '45.6 ms', '2.0 KiB', '0')
"""
from __future__ import annotations

from typing import Sequence

from .measure import DrawRow, ErrorRow

UNITS = {"theta": "°", "psi": "°", "H": " mm"}
SYMBOLS = {"theta": "θ", "psi": "ψ", "H": "H"}


def format_table(headers: Sequence[str], rows: Sequence[Sequence[str]], align: str) -> str:
    """Columns padded to their widest cell; ``align`` has one ``l`` or ``r`` per column."""
    widths = [max(len(str(c)) for c in col) for col in zip(headers, *rows)]

    def line(cells: Sequence[str]) -> str:
        out = [str(c).ljust(w) if a == "l" else str(c).rjust(w) for c, w, a in zip(cells, widths, align)]
        return "  ".join(out).rstrip()

    return "\n".join([line(headers), line(["-" * w for w in widths])] + [line(r) for r in rows])


def fmt_seconds(s: float | None) -> str:
    """A duration with three significant digits in s, ms or µs."""
    if s is None:
        return "n/a"
    for unit, k in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6)):
        if s >= k or unit == "µs":
            return f"{s / k:.3g} {unit}"
    raise AssertionError  # pragma: no cover


def fmt_bytes(b: int) -> str:
    """A size in B, KiB or MiB."""
    if b < 1024:
        return f"{b} B"
    if b < 1024 ** 2:
        return f"{b / 1024:.1f} KiB"
    return f"{b / 1024 ** 2:.1f} MiB"


def fmt_error(e: float) -> str:
    """An error in two significant digits, exact zero as ``0``."""
    return "0" if e == 0 else f"{e:.1e}"


def _second(row: ErrorRow) -> str:
    q = row.case.quantities[1]
    return f"{fmt_error(row.errors[q])}{UNITS[q]} ({SYMBOLS[q]})"


def extremes_table(rows: Sequence[ErrorRow]) -> str:
    """Part (a): one line per method and size, per problem."""
    headers = ("problem", "method", "N", "time (best)", "peak mem", "|Δθ|", "|Δψ| or |ΔH|", "max rel err")
    body = [(r.case.label, r.method, "" if r.n is None else f"{r.n:,}", fmt_seconds(r.seconds),
             fmt_bytes(r.peak_bytes), fmt_error(r.errors["theta"]) + "°", _second(r), fmt_error(r.rel_error))
            for r in rows]
    return format_table(headers, body, "llrrrrrr")


def _steps(row: DrawRow) -> str:
    done = "—" if row.steps_evaluated is None else str(row.steps_evaluated)
    return f"{done} of {row.steps_total}"


def drawing_table(rows: Sequence[DrawRow]) -> str:
    """Part (b): answers only vs answers and drawing."""
    headers = ("problem", "asked for", "time (best)", "steps evaluated", "note")
    body = [(r.case.label, r.output, fmt_seconds(r.seconds), _steps(r), r.note) for r in rows]
    return format_table(headers, body, "llrrl")


def report(extremes: Sequence[ErrorRow], drawing: Sequence[DrawRow], *, quick: bool) -> str:
    """Both tables with their headings and reading notes."""
    mode = " (--quick: fewer repetitions, N ≤ 36,000)" if quick else ""
    return "\n".join([
        f"(a) extreme positions: construction vs crank sweep, errors against the analytic twin{mode}",
        "",
        extremes_table(extremes),
        "",
        "A sweep's |Δθ| is at most about one step, 360°/N, but where in that range it falls is luck (the",
        "guide-bar's θ = 60° is a whole number of steps for N = 360·10^k, so θ comes out exact there, not for",
        "N = 10⁶); ψ and H err by O(1/N²). Time is the best of several runs; the construction's includes",
        "building the scene.",
        "",
        "(b) a fresh solve asked for answers only vs for answers and the SVG drawing",
        "",
        drawing_table(drawing),
    ]) + "\n"
