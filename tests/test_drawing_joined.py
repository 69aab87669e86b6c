"""A label naming several points ("B2, C4": geomcon/render/coincident.py) is measured as it prints and read by its
parts (issue 11, hjoin11): its box holds its subscripts, and each part lies nearer its own point than any point the
label does not name.

Measured as the plain text "B2, C4" (0.74 of the size high, its baseline at the box's foot), 004-02's printed
", C4" hung its subscript 0.79 mm below the box the placer kept clear, onto B2's pin; measured against the group's
centre, 004-03's "C2, B2" at 1:20 printed ", B2" over A*'s pin, nearer A* than B2."""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
import shapely

sys.path.insert(0, str(Path(__file__).parent))
from test_drawing_defects import figure  # noqa: E402

from geomcon.geometry.primitives import Point  # noqa: E402
from geomcon.render.joined import parts_rivalled, reads_back, spans  # noqa: E402
from geomcon.render.placement import LABEL_REACH, Request, nearer_rival  # noqa: E402
from geomcon.render.shapes import SUB_DROP, Text  # noqa: E402

JOINED = ["004-02_best_by_K_1_5", "001-29_eccentric_roller_offset_cw", "001-05c_shaper_stroke_from_lever",
          "100-01_four_bar_three_positions"]
"""Figures with labels naming several points, near (", ") and coinciding (" = "), subscripts in them (004-03 and
001-06b printed "C1, C2", "M, C4" until the gallery drew them larger on A4 portrait, where each point has its own)."""


def _parts(fig) -> list[list[tuple[str, Text]]]:
    """The labels of ``fig`` printed in parts ((step key, part) each, left to right): parts are anchored at their
    start, on one baseline, each box beginning where the one before ends."""
    parts = sorted(((g.key, t) for g in fig.groups for t in g.texts
                    if t.cls.startswith("label") and t.anchor == "start"), key=lambda p: (p[1].y, p[1].box[0]))
    out: list[list[tuple[str, Text]]] = []
    for key, t in parts:
        last = out[-1][-1][1] if out else None
        if last is not None and last.y == t.y and abs(last.box[2] - t.box[0]) <= 1e-9:
            out[-1].append((key, t))
        else:
            out.append([(key, t)])
    return out


@pytest.mark.parametrize("name", JOINED)
def test_a_joined_labels_box_holds_its_subscripts(name):
    """Every part's subscript (its glyphs' foot SUB_DROP of the size below the baseline) lies within the box the
    placer kept clear: on main the joined label's baseline was its box's foot."""
    labels = _parts(figure(name))
    subs = [t for label in labels for _, t in label if any(s for _, s in t.runs)]
    assert labels and subs, "the figure prints a joined label with a subscript"
    for t in subs:
        assert t.y + SUB_DROP * t.size <= t.box[3] + 1e-9, (name, t.runs, t.y, t.box)


@pytest.mark.parametrize("name", JOINED)
def test_each_part_of_a_joined_label_lies_nearest_its_own_point(name):
    """A part of a joined label by its points (no leader: within the label's reach) lies nearer its own point
    than any point of the figure the label does not name."""
    fig = figure(name)
    pts = {k: fig.view.p(v) for k, v in fig.values.items() if isinstance(v, Point)}
    for label in _parts(fig):
        keys = {k for k, _ in label}
        mates = {pts[k] for k in keys}
        others = [p for k, p in pts.items() if k not in keys and p not in mates]
        for key, t in label:
            b = shapely.box(*t.box)
            own = b.distance(shapely.Point(pts[key]))
            if own > LABEL_REACH + 3.0:                 # a leader's text: the leader says whose it is
                continue
            near = min((b.distance(shapely.Point(p)) for p in others), default=math.inf)
            assert own < near, (name, "".join(r for r, _ in t.runs), own, near)


def test_a_part_nearer_another_point_than_its_own_rivals_the_box():
    """The rule itself: a 10 mm label "A, B" centred 2 mm above A (0, 0) and B (2, 0), a third point R at (6, 0):
    the whole box is as near the group's centre as R, but its part ", B" (from x = 4.15) lies nearer R than B."""
    parts = ((4.0, (0.0, 0.0)), (6.0, (2.0, 0.0)))
    r = Request((1.0, 0.0), 10.3, 2.0, 1.0, 0.0, rivals=((6.0, 0.0),))
    at = [(5.15, -2.0), (-5.0, -2.0)]                 # right of the group (", B" over R); left, read backwards
    assert nearer_rival(r, at) == [False, False]                      # the whole box against the centre
    assert nearer_rival(Request(**{**_fields(r), "parts": parts}), at) == [True, False]


def test_the_parts_print_where_the_rule_measures_them():
    """:func:`spans` lays out the parts as the figure prints them (figure._parts_at): forwards from the box's
    left, or read backwards ending at its right, the first name beside the points."""
    assert np.allclose(spans(0.0, 10.3, (4.0, 6.0), back=False), [(0.15, 4.15), (4.15, 10.15)])
    assert np.allclose(spans(0.0, 10.3, (4.0, 6.0), back=True), [(6.15, 10.15), (0.15, 6.15)])
    assert reads_back(-2.6, 0.0, 10.0) and not reads_back(-2.4, 0.0, 10.0)


def test_parts_rivalled_leaves_requests_without_parts_alone():
    from geomcon.render.candidates import candidates
    reqs = [Request((0.0, 0.0), 4.0, 2.0, 1.0, 0.0, rivals=((3.0, 0.0),)),
            Request((0.0, 0.0), 4.0, 2.0, 1.0, 0.0, rivals=((3.0, 0.0),), parts=((3.7, (0.0, 0.0)),))]
    c = candidates(reqs, [0, 1], (-50.0, -50.0, 50.0, 50.0))
    mine = parts_rivalled(reqs, c.starts, c.boxes)
    a, b, n = c.starts.tolist()
    assert not mine[a:b].any() and mine[b:n].any()
    assert np.array_equal(c.rivalled[b:n], mine[b:n])           # a label in parts: the parts' rule alone


def _fields(r: Request) -> dict:
    return {f: getattr(r, f) for f in r.__dataclass_fields__}
