"""Where the parts of a label naming several points print in its box, and the nearness rule for each part.

A label naming points drawn closer than a label's height (:mod:`.coincident`: "B2, C4") prints in parts, each
name with its point's step. Its box is placed about the group as one text, but a reader takes each name for the
point it lies nearest: each part keeps nearer its own point than any other point of the figure, the group's
other points aside (they are named by the same label). Measured against the group's centre instead, 004-03's
"C2, B2" at 1:20 printed ", B2" over A*'s pin, nearer A* than B2.

Examples
--------
>>> [(round(a, 9), round(b, 9)) for a, b in spans(0.0, 10.3, (4.0, 6.0), back=False)]
[(0.15, 4.15), (4.15, 10.15)]
>>> [(round(a, 9), round(b, 9)) for a, b in spans(0.0, 10.3, (4.0, 6.0), back=True)]    # backwards: the first
[(6.15, 10.15), (0.15, 6.15)]
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Sequence

import numpy as np

from .boxgeom import box_point

if TYPE_CHECKING:
    from .clearance import Boxes
    from .placement import Request

XY = tuple[float, float]

PAD = 0.15
"""Paper mm between a label's box and its text, each side (the box is the text's width + 0.3)."""


def reads_back(cx: float, anchor_x: float, width: float) -> bool:
    """Whether a joined label centred at ``cx`` reads backwards ("K0 = D" for "D = K0"): its box lies mostly left
    of its points (centred more than a quarter of its ``width`` left of the group's ``anchor_x``), so that its
    first name, shown alone until the next point is drawn, stands beside them.

    >>> reads_back(-3.0, 0.0, 10.0), reads_back(-2.0, 0.0, 10.0)      # the first name ends by the points
    (True, False)
    """
    return cx < anchor_x - width / 4


def spans(x0: float, x1: float, widths: Sequence[float], back: bool) -> list[tuple[float, float]]:
    """The paper x span of each part (``widths``, in the order of its names) of a label whose box runs from ``x0``
    to ``x1``: left to right from ``x0`` + :data:`PAD`, or, read backwards, the last name first, ending at ``x1``
    − :data:`PAD`."""
    out: list[tuple[float, float]] = [(0.0, 0.0)] * len(widths)
    order = range(len(widths) - 1, -1, -1) if back else range(len(widths))
    x = x1 - PAD - sum(widths[i] for i in order) if back else x0 + PAD
    for i in order:
        out[i] = (x, x + widths[i])
        x += widths[i]
    return out


def parts_rivalled(reqs: Sequence[Request], starts: np.ndarray, boxes: Boxes) -> np.ndarray:
    """Whether each candidate box lies so that a part of its request's label (:attr:`.Request.parts`) is nearer
    one of the request's ``rivals`` than that part's own point (box-to-point distances as
    :func:`.boxgeom.box_point` measures them); False for the requests without parts. A joined label is never
    turned: its boxes are their bounds."""
    out = np.zeros(len(boxes), dtype=bool)
    for i, r in enumerate(reqs):
        if not r.parts or not r.rivals:
            continue
        a, b = int(starts[i]), int(starts[i + 1])
        x0, y0, x1, y1 = boxes.x0[a:b], boxes.y0[a:b], boxes.x1[a:b], boxes.y1[a:b]
        back = boxes.cx[a:b] < r.anchor[0] - r.width / 4            # :func:`reads_back`, for every candidate
        widths = np.array([w for w, _ in r.parts])
        before = np.concatenate(([0.0], np.cumsum(widths)[:-1]))     # the parts' offsets, read forwards
        after = np.sum(widths) - before - widths                     # and backwards
        rx = np.array([q[0] for q in r.rivals])[None, :]
        ry = np.array([q[1] for q in r.rivals])[None, :]
        bad = np.zeros(b - a, dtype=bool)
        for k, (w, (px, py)) in enumerate(r.parts):
            lo = np.where(back, x1 - PAD - np.sum(widths) + after[k], x0 + PAD + before[k])
            own = box_point(lo, y0, lo + w, y1, px, py)
            other = box_point(lo[:, None], y0[:, None], (lo + w)[:, None], y1[:, None], rx, ry).min(axis=1)
            bad |= other < own
        out[a:b] = bad
    return out


__all__ = ["PAD", "parts_rivalled", "reads_back", "spans"]
