"""The translating twin's parabolic search refines the four highest sample peaks, ties by place, picked by a
stable argsort instead of sorting every peak with a key function (a dwell's flat samples are all peaks):
the same four, in the same order."""
from __future__ import annotations

import numpy as np

from geomcon.cam.translating import _peaks


def test_four_highest_peaks_as_the_keyed_sort():
    rng = np.random.default_rng(1)
    for _ in range(3000):
        n = int(rng.integers(3, 60))
        v = rng.integers(-3, 3, n).astype(float)
        if rng.random() < 0.3:
            v[rng.integers(0, n)] = np.nan
        if rng.random() < 0.5:
            v[(v == 0) & (rng.random(n) < 0.5)] = -0.0          # signed zeros tie with zeros
        w, found = v.tolist(), _peaks(v)
        peaks = np.array(found, dtype=np.intp)
        assert peaks[np.argsort(-v[peaks], kind="stable")[:4]].tolist() == sorted(found, key=lambda j: -w[j])[:4]
