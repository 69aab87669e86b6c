"""The whole-cycle bench measures what it says: geomcon's chain and pylinkage sweep the same four-bar on the
same branch, and geomcon's positions are exact (correctness only: times are reported, never asserted)."""
from __future__ import annotations

import importlib.util

from geomcon.bench.cycle import cycle_table, measure_cycle


def test_cycle_bench_rows_are_exact_and_comparable():
    rows = measure_cycle(n=20_000, repeat=1)
    assert rows[0].method == "numpy cos + sin of the N angles" and rows[0].n == 20_000
    geo = [r for r in rows if r.method.startswith("geomcon")]
    assert len(geo) == 5 and all(r.rel_error < 1e-13 and r.n == 20_000 for r in geo)   # fast and reference
    assert "× cos+sin" in cycle_table(rows) and "\nnumpy cos + sin of the N angles" in cycle_table(rows)
    pyl = [r for r in rows if r.method.startswith("pylinkage")]
    if importlib.util.find_spec("pylinkage"):
        assert pyl and all(r.rel_error < 1e-8 for r in pyl)          # the same linkage, the same branch
        assert "vs pylinkage" in cycle_table(rows) and "1.00×" in cycle_table(rows)
    else:
        assert not pyl and "pylinkage was not measured" in cycle_table(rows)
