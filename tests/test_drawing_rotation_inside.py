"""No text prints inside the arc of a sense of rotation (issue 11, hlook11d's review): 16 cam figures printed the
centre's label "O" inside the ω arrow's arc, where it reads as part of the arrow. Checked over every gallery
figure as its sheet 1 draws it: the inside of each rotation arrow (the sector between its centre and the arc drawn)
meets no text's box but its own symbol's (ω inside the arc it turns along reads as the textbook's)."""
from __future__ import annotations

import math

import pytest
import shapely

from geomcon.render.draw import Context, Drawn
from geomcon.render.shapes import ArcP
from geomcon.render.style import STYLES
from geomcon.render.symbols import draw_rotation
from geomcon.render.view import View
from geomcon.scene.marks import Rotation

from test_drawing_defects import NAMES, box, figure, runs


def insides(fig) -> list[tuple[str, shapely.Geometry]]:
    """(step, sector) of each rotation arrow of a figure: its centre and its drawn arc, 48 points along it."""
    out = []
    for g in fig.groups:
        if isinstance(fig.values[g.key], Rotation):
            (arc,) = [sh for sh in g.shapes if isinstance(sh, ArcP)]
            out.append((g.key, shapely.Polygon([arc.c] + [arc.at(k / 48) for k in range(49)])))
    return out


@pytest.mark.parametrize("name", NAMES)
def test_no_text_prints_inside_a_rotation_arrow(name):
    fig = figure(name)
    inside = insides(fig)
    bad = [(g.key, runs(t), key) for key, area in inside for g in fig.groups for t in g.texts
           if g.key != key and box(t).intersects(area)]             # its own ω may sit inside its arc
    assert not bad


def test_the_gallery_draws_many_rotation_arrows():
    assert sum(len(insides(figure(n))) for n in NAMES) >= 30


def test_a_rotation_arrow_keeps_texts_out_of_its_arc():
    view = View((-20.0, -20.0, 20.0, 20.0), 1.0, (0.0, 0.0))
    for sense in (1.0, -1.0):
        from geomcon.geometry import Point
        d: Drawn = draw_rotation(Rotation(Point(0, 0), sense), STYLES["angle"], Context(view))
        (area,) = d.keep_out
        (arc,) = [sh for sh in d.shapes if isinstance(sh, ArcP)]
        sector = shapely.Polygon(area)
        assert sector.contains(shapely.Point(arc.c[0], arc.c[1] - arc.r / 2))      # above the centre
        assert math.isclose(sector.area, arc.r ** 2 * math.radians(110.0) / 2, rel_tol=0.02)
