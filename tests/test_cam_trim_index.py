"""trim_loops finds each kept point's place on the raw polyline by one sort and binary search
(profile._row_index) instead of a dictionary of ~16 k tuples (000-07: 18 of its 21 ms): the same indices, the
last of equal points, −0.0 equal to 0.0 and nan equal to nothing, as the dictionary had them."""
from __future__ import annotations

import numpy as np

from geomcon.cam.profile import PitchCurve, _row_index, roller_profile


def _by_dict(table: np.ndarray, rows: np.ndarray) -> np.ndarray:
    index = {tuple(p): i for i, p in enumerate(table.tolist())}
    return np.array([index.get(tuple(p), -1) for p in rows.tolist()])


def test_row_index_is_the_dictionary_lookup():
    rng = np.random.default_rng(3)
    for _ in range(300):
        n = int(rng.integers(1, 400))
        table = rng.integers(-3, 3, size=(n, 2)).astype(float) * rng.choice([1.0, 0.5, 1e-300])
        table[rng.integers(0, n, 5)] *= -1.0                 # signed zeros among the repeats
        if rng.random() < 0.2:
            table[0, 1] = np.nan
        k = int(rng.integers(1, 300))
        rows = np.concatenate([table[rng.integers(0, n, k)], rng.integers(-3, 3, size=(k, 2)).astype(float)])
        assert (_row_index(table, rows) == _by_dict(table, rows)).all()


def test_trimmed_profile_as_by_the_dictionary(monkeypatch):
    """An undercut roller (ρmin 18 < rr 20): the trimmed ring and its cam angles are those the dictionary's
    indices give."""
    from geomcon.cam import profile

    def ellipse(d):
        return 50 * np.cos(d), 30 * np.sin(d), -50 * np.sin(d), 30 * np.cos(d), -50 * np.cos(d), -30 * np.sin(d)

    p = roller_profile(PitchCurve(ellipse), 20.0)
    monkeypatch.setattr(profile, "_row_index", _by_dict)
    q = roller_profile(PitchCurve(ellipse), 20.0)
    assert p.trimmed and p.ring().is_simple
    assert np.array_equal(p.xy, q.xy) and np.array_equal(p.delta, q.delta)
