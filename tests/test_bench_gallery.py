"""The bench's gallery rows (issue 11's speed targets) report what they time: a row per figure asked, the
targets compared as stated, the table naming each row. (Correctness only: times are reported, never asserted.)"""
from __future__ import annotations

from geomcon.bench.gallery import (FIGURE_TARGET, GALLERY_TARGET, FigureRow, GalleryRow, gallery_table,
                                   measure_figures)


def test_targets_compare_as_stated():
    assert GalleryRow(GALLERY_TARGET, 5.0, 1.0, 3).met and not GalleryRow(GALLERY_TARGET + 1e-9, 5.0, 1.0, 3).met
    assert FigureRow("x", "r", 1.0, FIGURE_TARGET).met and not FigureRow("x", "r", 0.0, 2 * FIGURE_TARGET).met


def test_figure_rows_time_the_figures_asked():
    rows = measure_figures(1, ("001-08", "no-such-problem"))
    assert [(r.problem, r.recipe) for r in rows] == [("001-08", "crank_rocker.extremes")]
    assert rows[0].seconds >= rows[0].figure > 0.0          # the sheets include sheet 1's figure


def test_table_names_every_row():
    text = gallery_table(GalleryRow(3.4, 6.9, 1.5, 3), [FigureRow("001-24", "cam.translating", 0.0905, 0.0412)])
    assert "geomcon gallery --check" in text and "3.40 s wall" in text and "≤ 3 s (SHORT)" in text
    assert "001-24 cam.translating" in text and "41.2 ms" in text and "≤ 40 ms (SHORT)" in text
    assert "its sheets (SVG)" in text and "90.5 ms" in text
    assert "load 1.5, best of 3" in text
    assert "geomcon gallery" not in gallery_table(None, [])


def test_every_figure_row_times_each_problems_sheet_one():
    from geomcon.bench.gallery import SpreadRow, measure_all_figures

    row = measure_all_figures(1, ("001-08", "001-24", "no-such-problem"))
    assert row.count == 2 and row.slowest.startswith(("001-08", "001-24")) and row.worst >= row.median > 0.0
    assert measure_all_figures(1, ("no-such-problem",)) is None
    text = gallery_table(None, [], SpreadRow(93, 6, "001-24_cam", 0.0662, 0.0212))
    assert "93 problems: median; slowest 001-24_cam" in text and "21.2 ms; 66.2 ms" in text
    assert "6 over 40 ms (SHORT)" in text
    assert SpreadRow.of({"a": 0.01, "b": 0.03}).median == 0.02 and SpreadRow.of({"a": 0.04}).met
