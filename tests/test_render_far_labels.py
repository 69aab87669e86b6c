"""A point's label still on a given or construction line by its point and with its leader is tried farther off,
with a leader, past its near points (hlook11m's review: 000-02's "G" sat on the ram's guide, T and M 2 mm above
and below it; every clear place with a leader lay nearer M than G, which the placer read as M's label). With a
leader the label is read as its point's wherever it lands: only a point within
:data:`geomcon.render.figure.LED_RIVAL_REACH` (5 mm) of its box (where it would pass for that point's own label) rivals
it there (:attr:`geomcon.render.placement.Request.rival_reach`), and the place is taken only when it is clear of
every line."""
from __future__ import annotations

import math
import sys
from pathlib import Path

import shapely

from geomcon.render.figure import LED_RIVAL_REACH
from geomcon.render.clearance import ENOUGH
from geomcon.render.placement import Placer, Request

sys.path.insert(0, str(Path(__file__).parent))
from test_drawing_defects import box, figure, runs  # noqa: E402


def _g(reach: float) -> tuple[tuple[float, float], float]:
    """Where a 2.7 mm label of a point on a line goes, two points 2 mm above and below it (000-02's T, G, M)."""
    line = (shapely.LineString([(-30.0, 0.0), (30.0, 0.0)]), "guide", 0.0, 1.0)
    p = Placer([line], (-40.0, -40.0, 40.0, 40.0))
    req = Request((0.0, 0.0), 2.7, 2.7, 0.95, -math.pi / 4, rivals=((0.0, -2.0), (0.0, 2.0)), lead=0.95,
                  distances=(0.0, 1.0, 2.0, 3.0, 4.5, 6.0, 8.0, 10.0), rival_reach=reach)
    return p.best(req, "G")


def test_a_led_label_passes_its_near_points_only_with_a_leader():
    _, score = _g(math.inf)
    assert score < 0.0                              # by any rule of nearness: on the line or nearer T or M
    (x, y), score = _g(LED_RIVAL_REACH)
    assert score >= 0.0 and abs(y) > 1.35            # off the line, with a leader
    b = shapely.box(x - 1.35, y - 1.35, x + 1.35, y + 1.35)
    assert min(b.distance(shapely.Point(0.0, s)) for s in (-2.0, 2.0)) > LED_RIVAL_REACH


def test_000_02_prints_g_off_the_rams_guide_with_a_leader():
    fig = figure("000-02_slotter_design_by_K")
    (g,) = [g for g in fig.groups if g.key == "G"]
    (label,) = [t for t in g.texts if runs(t) == "G"]
    lines = [(h.key, sh) for h in fig.groups if h.layer in ("given", "construction") and h.key != "G"
             for sh in h.shapes if not hasattr(sh, "runs")]
    from geomcon.render.shapes import obstacle
    assert not [k for k, sh in lines if obstacle(sh).intersects(box(label))]
    assert any(len(getattr(sh, "pts", ())) == 2 and sh.pen.width == 0.15 for sh in g.shapes)    # its leader


def test_past_rivals_keeps_only_the_places_a_near_point_took():
    line = (shapely.LineString([(-30.0, 0.0), (30.0, 0.0)]), "guide", 0.0, 1.0)
    p = Placer([line], (-40.0, -40.0, 40.0, 40.0))
    req = Request((0.0, 0.0), 2.7, 2.7, 0.95, -math.pi / 4, rivals=((0.0, -2.0), (0.0, 2.0)), lead=0.95,
                  distances=(0.0, 1.0, 2.0, 3.0, 4.5, 6.0, 8.0, 10.0))
    far = p.past_rivals(req, "G", LED_RIVAL_REACH)
    assert far is not None and far.rival_reach == LED_RIVAL_REACH and len(far.candidates) == len(far.costs) > 0
    for x, y in far.candidates:                     # nearer T or M than G, but beyond reach of both
        b = shapely.box(x - 1.35, y - 1.35, x + 1.35, y + 1.35)
        near = min(b.distance(shapely.Point(0.0, s)) for s in (-2.0, 2.0))
        assert near < b.distance(shapely.Point(0.0, 0.0)) and near > LED_RIVAL_REACH
    assert p.past_rivals(req, "G", LED_RIVAL_REACH, floor=ENOUGH) is None       # none can score more than that
    alone = Request((0.0, 0.0), 2.7, 2.7, 0.95, -math.pi / 4, lead=0.95)
    assert p.past_rivals(alone, "G", LED_RIVAL_REACH) is None                   # no near point: nothing to pass
