"""geomcon.paper: standard scales and the largest one that fits."""
from __future__ import annotations

import random

import pytest

from geomcon.paper import ISO_5455, PAPERS, STANDARD, Scale, best_fit, choose_scale


def test_series_sorted_and_iso_included():
    assert list(STANDARD) == sorted(STANDARD, key=lambda s: s.factor)
    assert set(ISO_5455) <= set(STANDARD)
    names = {str(s) for s in ISO_5455}
    assert {"1:2", "1:5", "1:10", "1:20", "1:50", "1:100", "1:1", "2:1", "5:1", "10:1", "20:1", "50:1"} <= names
    assert "1:2.5" in {str(s) for s in STANDARD} and "1:2.5" not in names


def test_choose_scale_is_the_largest_that_fits():
    rng = random.Random(5)
    for _ in range(2000):
        ext = (10 ** rng.uniform(-1, 4), 10 ** rng.uniform(-1, 4))
        area = (rng.uniform(50, 400), rng.uniform(50, 400))
        margin = rng.uniform(0, 10)
        try:
            s = choose_scale(ext, area, margin=margin)
        except ValueError:
            small = STANDARD[0]
            assert small.to_paper(ext[0]) > area[0] - 2 * margin or small.to_paper(ext[1]) > area[1] - 2 * margin
            continue
        assert s.to_paper(ext[0]) <= area[0] - 2 * margin and s.to_paper(ext[1]) <= area[1] - 2 * margin
        bigger = [t for t in STANDARD if t > s]
        if bigger:
            t = bigger[0]
            assert t.to_paper(ext[0]) > area[0] - 2 * margin or t.to_paper(ext[1]) > area[1] - 2 * margin


def test_exact_fit_counts_and_parse():
    assert str(choose_scale((360.0, 100.0), (180.0, 100.0))) == "1:2"
    assert Scale.parse("1:2.5") == Scale(1.0, 2.5)
    with pytest.raises(ValueError):
        Scale.parse("1/2")
    with pytest.raises(ValueError):
        Scale.parse("0:1")


def test_best_fit_orientation():
    s, sheet = best_fit((100.0, 400.0), PAPERS["A4"])
    assert sheet.orientation == "portrait" and str(s) == "1:2"
    s, sheet = best_fit((400.0, 100.0), PAPERS["A4"])
    assert sheet.orientation == "landscape" and str(s) == "1:2"
    s, sheet = best_fit((100.0, 100.0), PAPERS["A3"])        # a tie: portrait
    assert sheet.orientation == "portrait"
