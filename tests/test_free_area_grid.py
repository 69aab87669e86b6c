"""The free-room search reads a grid of boxes' counts by outer indexing (:func:`_grid_counts`): the same counts
as the box-by-box look-up (:func:`_counts`) over the meshgrid of the same positions, on random rasters and
random (also non-integer) grids, so FreeRoom.find finds the same boxes."""
from __future__ import annotations

import numpy as np

from geomcon.render.free_area import CLEAR, _counts, _grid_counts, _table


def test_grid_counts_equal_the_box_by_box_counts():
    rng = np.random.default_rng(11)
    for _ in range(200):
        ny, nx = rng.integers(5, 60, 2)
        grid = (rng.random((ny, nx)) < rng.random() * 0.2).astype(np.int32)
        table = _table(grid)
        region = (float(rng.uniform(-5, 30)), float(rng.uniform(-5, 30)), 0.0, 0.0)
        region = (region[0], region[1], region[0] + nx, region[1] + ny)
        xs = region[0] + rng.uniform(-3, nx + 3) + 2.0 * np.arange(rng.integers(1, 20))
        ys = region[1] + rng.uniform(-3, ny + 3) + 2.0 * np.arange(rng.integers(1, 20))
        w, h = rng.uniform(0, 30, 2)
        gx, gy = (a.ravel() for a in np.meshgrid(xs, ys))
        one = _counts(table, region, gx - CLEAR, gy - CLEAR, gx + w + CLEAR, gy + h + CLEAR)
        grid_n = _grid_counts(table, region, xs - CLEAR, ys - CLEAR, xs + w + CLEAR, ys + h + CLEAR)
        assert grid_n.tolist() == one.tolist()
