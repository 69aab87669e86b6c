"""Random full-turn motion programs shared by the cam search tests (the same draws in the same order)."""

from __future__ import annotations

import numpy as np

from geomcon.cam.laws import LAW_NAMES
from geomcon.cam.program import parse_program


def random_program(rng: np.random.Generator):
    """A random full-turn program: rise, dwell, return, dwell, any laws, now and then a dwell left out.

    Examples
    --------
    >>> prog = random_program(np.random.default_rng(0))
    >>> round(sum(seg.angle for seg in prog.segments), 9)
    360.0
    """
    a = rng.dirichlet([2, 1, 2, 1]) * 360.0
    a[-1] = 360.0 - a[:-1].sum()
    kinds = ["rise", "dwell", "return", "dwell"]
    if rng.uniform() < 0.25:
        a[2] += a[1]
        a, kinds = np.delete(a, 1), kinds[:1] + kinds[2:]
    return parse_program([{"kind": k, "angle": float(x), **({"law": str(rng.choice(LAW_NAMES))} if k != "dwell" else {})}
                          for k, x in zip(kinds, a)])
