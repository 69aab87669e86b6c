"""The mechanism symbols a teacher found missing or wrong (issue 11, review items 3, 8, 9, 19, 20, 25, 31, 37),
checked over every gallery figure: every prismatic joint is a block on its guide, blocks never overlap, every
kinematics problem shows the crank's ω, the quick-return figures mark θ."""
from __future__ import annotations

import itertools
import math
from pathlib import Path

import pytest
import shapely

from geomcon.geometry.primitives import Point, Segment
from geomcon.problems import load_problem
from geomcon.render.draw import ANGLE_RADIUS
from geomcon.render.shapes import ArcP, Poly
from geomcon.render.symbols import HATCH
from geomcon.scene.marks import AngleMark, Bearing, Ground, Guide, Rotation, Slider

from test_drawing_defects import NAMES, _members, figure, runs

PROBLEMS = Path(__file__).parent.parent / "problems"

PRISMATIC = {
    "guide_bar.extremes": ("B1", "B2", "D1", "D2"),
    "guide_bar.design_by_K": ("B1", "B2"),
    "guide_bar.kinematics": ("B",),
    "rotating_guide_bar.extremes": ("B1", "B2", "D1", "D2"),
    "shaper.design_by_K": ("B1", "B2", "E1"),
    "slotter.design_by_K": ("B1", "B2", "E"),
    "slotter.kinematics": ("B", "E"),
    "crank_slider.extremes": ("C1", "C2"),
    "crank_slider.design_by_K": ("C1", "C2"),
    "crank_slider.best_by_K": ("C1", "C2"),
    "crank_slider.kinematics": ("C",),
    "crank_slider.instant_centres": ("C",),
    "rocker_slider.three_positions": ("E1", "E2", "E3"),
    "rocker_slider.two_positions": ("E1", "E2"),
}
"""The prismatic joints of each linkage recipe with a slider: the points of its figure where a block slides
(those of them the figure draws: D1, D2 only when a lever is given, E only when the coupler is sized)."""

KINEMATICS = ("four_bar.kinematics", "crank_slider.kinematics", "guide_bar.kinematics", "slotter.kinematics")


def recipe(name: str) -> str:
    return load_problem(PROBLEMS / f"{name}.toml").recipe


def test_every_gallery_recipe_with_a_slider_is_listed():
    """A new recipe whose name says it has a slider or a guide bar cannot skip the block check below."""
    names = {recipe(n) for n in NAMES}
    sliding = {r for r in names if any(w in r for w in ("slider", "guide_bar", "shaper", "slotter"))}
    assert sliding <= set(PRISMATIC)


@pytest.mark.parametrize("name", [n for n in NAMES if recipe(n) in PRISMATIC])
def test_every_prismatic_joint_is_drawn_as_a_block(name):
    """001-04, 001-05c, 001-09, 300-02, 400-05 drew the sliders B1, B2 (and C) as bare pins: every prismatic joint
    of the figure carries a slider block centred on it (that the block runs along a drawn bar or guide is
    :func:`test_drawing_defects.test_every_slider_lies_on_a_drawn_bar_or_guide_along_its_motion`)."""
    fig = figure(name)
    size = max(fig.view.box[2] - fig.view.box[0], fig.view.box[3] - fig.view.box[1])
    blocks = [m.at for g in fig.groups for m in _members(fig.values[g.key]) if isinstance(m, Slider)]
    joints = [k for k in PRISMATIC[recipe(name)]                  # a construction point (style-point) is no joint
              if any(g.key == k and g.shapes and " style-point" not in g.classes for g in fig.groups)]
    assert joints
    for k in joints:
        assert any(abs(fig.values[k] - q) <= 1e-9 * size for q in blocks), (name, k)


@pytest.mark.parametrize("name", NAMES)
def test_no_two_slider_blocks_overlap(name):
    """000-02 drew the blocks B1, D1 (and B2, D2) on top of each other, 001-09 the blocks B1, D1 touching: the
    blocks of a figure are disjoint on paper."""
    fig = figure(name)
    blocks = [shapely.Polygon(sh.pts) for g in fig.groups if isinstance(fig.values[g.key], Slider)
              for sh in g.shapes if isinstance(sh, Poly) and sh.closed]
    assert not [(a, b) for a, b in itertools.combinations(blocks, 2) if a.intersects(b)]


@pytest.mark.parametrize("name", [n for n in NAMES if recipe(n) in KINEMATICS])
def test_every_kinematics_figure_shows_the_crank_omega(name):
    """000-03, 400-01…400-03 gave ω but drew no arrow: the input crank carries ω1 at its pivot A, turning the way
    the given ω's sign says."""
    fig = figure(name)
    problem = load_problem(PROBLEMS / f"{name}.toml")
    (rot,) = [fig.values[g.key] for g in fig.groups if isinstance(fig.values[g.key], Rotation)]
    assert rot.at == fig.values["A"]
    assert rot.sense == (1.0 if problem.given["omega"] > 0 else -1.0)
    (group,) = [g for g in fig.groups if g.key == "omega1"]
    assert [runs(t) for t in group.texts] == ["ω1"]
    assert sum(isinstance(s, ArcP) for s in group.shapes) == 1


@pytest.mark.parametrize("name", ["001-09_slotter_rotating_guide_bar_stroke", "300-02_whitworth_khurmi_5_4"])
def test_the_rotating_guide_bar_marks_theta(name):
    """001-09 and 300-02 gave θ in the Results but marked only φ_quick: θ is marked at A between AB2 and B1A
    extended, with the value the Results print."""
    fig = figure(name)
    (m,) = [fig.values[g.key] for g in fig.groups if g.key == "mark_theta"]
    assert isinstance(m, AngleMark)
    assert abs(m.value - (180.0 - fig.values["phi_quick"])) < 1e-9
    assert [runs(t) for g in fig.groups if g.key == "mark_theta" for t in g.texts] == [f"θ={m.value:.2f}°"]


def _pie(arc: ArcP, own: bool = False) -> shapely.Polygon:
    """The sector an angle mark's arc marks: its vertex and the arc; of an arc of the mark's ``own`` radius beyond
    ANGLE_RADIUS, the band 1 mm either side of it (001-29's δ0 and δ0′ make up the whole turn about O inside the
    offset circle: O's ground stands well inside their arcs, on none of them)."""
    n = max(4, int(abs(arc.sweep) / math.radians(10.0)) + 1)
    if own and arc.r > ANGLE_RADIUS:
        return shapely.LineString([arc.at(i / n) for i in range(n + 1)]).buffer(1.0)
    return shapely.Polygon([arc.c] + [arc.at(i / n) for i in range(n + 1)])


NO_GROUND = {("200-19_base_radius_alpha_and_rho", "O_design"), ("200-20_oscillating_base_radius_rho", "O_design")}
"""O′, the centre the pressure-angle rule alone would give, shown beside the chosen O for comparison: a point
of the construction, not a pivot of the mechanism drawn."""


@pytest.mark.parametrize("name", NAMES)
def test_every_fixed_pivot_has_a_ground_symbol(name):
    """D in 001-15 and 001-22, A* in 004-03 and O in 200-18 were plain circles: every fixed pivot of a figure
    carries a ground symbol."""
    fig = figure(name)
    grounds = [fig.values[g.key].at for g in fig.groups if isinstance(fig.values[g.key], Ground)]
    size = max(fig.view.box[2] - fig.view.box[0], fig.view.box[3] - fig.view.box[1])
    pivots = [g.key for g in fig.groups if isinstance(fig.values[g.key], Point) and g.shapes
              and " style-pivot" in g.classes and (name, g.key) not in NO_GROUND]
    for k in pivots:
        assert any(abs(fig.values[k] - q) <= 1e-9 * size for q in grounds), (name, k)


def test_the_gallery_has_grounds_to_check():
    assert sum(isinstance(figure(n).values[g.key], Ground) for n in NAMES for g in figure(n).groups) >= 80


CROWDED_GROUNDS = {("001-31b_eccentric_oscillating_roller_speeds", "Q_ground")}
"""Left (after merging hfmt11): Q's angle marks in 001-31b leave no direction clear; the ground takes the one
that meets least. To be fixed by placing the mark, not by hiding the ground."""


@pytest.mark.parametrize("name", NAMES)
def test_no_ground_symbol_lies_in_an_angle_or_across_the_frame_line(name):
    """300-02 and 001-19 drew A's ground inside the φ_quick (180° − θ) arc, 001-10's hatch crossed the frame
    line AD: away from its hinge a ground symbol meets no angle mark's sector (vertex to arc) and no frame
    line (links: :func:`test_drawing_defects.test_no_ground_symbol_crosses_a_link`)."""
    fig = figure(name)
    pies = [_pie(sh, any(m.radius for m in ms)) for g in fig.groups
            for ms in [[m for m in _members(fig.values[g.key]) if isinstance(m, AngleMark)]] if ms
            for sh in g.shapes if isinstance(sh, ArcP)]
    frames = [shapely.LineString(sh.pts) for g in fig.groups if " style-frame" in g.classes      # the frame AD,
              and isinstance(fig.values[g.key], Segment) for sh in g.shapes      # not a centre line through A
              if isinstance(sh, Poly) and len(sh.pts) == 2]
    for g in fig.groups:
        v = fig.values[g.key]
        if isinstance(v, Ground):
            hinge = shapely.Point(fig.view.p(v.at)).buffer(1.7)
            symbol = shapely.union_all([shapely.LineString(sh.pts) for sh in g.shapes]).difference(hinge)
            if (name, g.key) not in CROWDED_GROUNDS:
                assert not [p for p in pies if symbol.intersects(p)], (name, g.key)
            assert not [f for f in frames if symbol.intersects(f)], (name, g.key)


@pytest.mark.parametrize("name", NAMES)
def test_every_ground_hatch_stands_at_45_degrees_to_its_base(name):
    """001-31's hatch looked mangled: in every ground symbol the base is the longest stroke and each hatch
    stroke makes 45° with it."""
    fig = figure(name)
    for g in fig.groups:
        if isinstance(fig.values[g.key], Ground):
            legs, base, *hatch = g.shapes
            (a, b) = base.pts
            bu = ((b[0] - a[0]), (b[1] - a[1]))
            for h in hatch:
                (p, q) = h.pts
                hu = (q[0] - p[0], q[1] - p[1])
                cos = abs(bu[0] * hu[0] + bu[1] * hu[1]) / math.hypot(*bu) / math.hypot(*hu)
                assert abs(cos - math.sqrt(0.5)) < 1e-9, (name, g.key)


TRANSLATING = [n for n in NAMES if recipe(n) in ("cam.translating", "cam.eccentric")
               and any(g.key == "stem" for g in figure(n).groups)]        # an oscillating arm has no stem


@pytest.mark.parametrize("name", TRANSLATING)
def test_every_translating_follower_has_one_guide_symbol(name):
    """001-23a/b, 200-02, 200-17 drew the stem's guide as chevrons (arrow feathers), 001-24, 200-01… as a chevron
    bearing, 001-25…29 as a wall on one side, 001-30 none: every translating follower's stem carries exactly
    one guide, the bearing symbol (two hatched walls, their strokes parallel), and no other guide mark."""
    fig = figure(name)
    bearings = [fig.values[g.key] for g in fig.groups if isinstance(fig.values[g.key], Bearing)]
    assert len(bearings) == 1
    assert not [g.key for g in fig.groups if isinstance(fig.values[g.key], Guide)]
    (group,) = [g for g in fig.groups if isinstance(fig.values[g.key], Bearing)]
    strokes = {round(math.degrees(math.atan2(sh.pts[1][1] - sh.pts[0][1], sh.pts[1][0] - sh.pts[0][0])) % 180.0, 6)
               for sh in group.shapes if sh.pen.width == HATCH}
    assert len(strokes) == 1                        # parallel on both sides: never mirrored into chevrons


LINKAGES = [n for n in NAMES if not recipe(n).startswith("cam.") and recipe(n) != "four_bar.link_ranges"]


@pytest.mark.parametrize("name", LINKAGES)
def test_every_linkage_figure_draws_its_links_solid(name):
    """001-10c and 004-03 drew only C1, C2, D and the candidates A, 001-03b only dashed triangles: every linkage
    figure draws its moving links solid in at least one position (three for a four-bar, two for the others)."""
    fig = figure(name)
    solid = [sh for g in fig.groups if g.layer == "links" and " style-vector" not in g.classes for sh in g.shapes
             if isinstance(sh, Poly) and len(sh.pts) == 2 and not sh.pen.dash]
    four = recipe(name).startswith(("four_bar.", "crank_rocker."))
    assert len(solid) >= (3 if four else 2), name


@pytest.mark.parametrize("name", [n for n in NAMES if recipe(n).startswith("rocker_slider.")])
def test_each_position_block_has_its_link_tone(name):
    """100-07: the three rods F_iE_i ran over each other's blocks: positions 2 and 3 are lighter, and each block
    is drawn in the tone of its own rod."""
    fig = figure(name)
    tone = {g.key: sh.pen.stroke for g in fig.groups for sh in g.shapes if isinstance(sh, Poly)}
    n = sum(1 for g in fig.groups if g.key.startswith("slider") and g.key[6:].isdigit())
    assert n >= 2
    assert len({tone[f"F{i}E{i}"] for i in range(1, n + 1)}) == n
    for i in range(1, n + 1):
        assert tone[f"slider{i}"] == tone[f"F{i}E{i}"]


KNOWN_CLOSE_RODS = {
    "100-07_rocker_slider_three_positions": "its three rods F_iE_i lie 3.1°, 6.2°, 6.2° off the guide (α_max = 6.22°, the "
    "design's best): rod F1E1 runs 0.3–1.5 mm above the guide over the blocks E3 and E2 at 1:1. Looked at (issue 11, "
    "hsmall11m): the positions are told apart by tone (pos1 black, pos2/pos3 lighter, each block in its rod's tone) "
    "and each rod ends at its own pin; thin or dashed positions would hide the links the sheet asks for, and any "
    "offset would draw a rod off its pin. The overlap is the geometry's: a rocker–slider with α ≤ 6.2° has it",
}
"""Rocker–slider figures whose rods run within :data:`ROD_ANGLE` of the guide, with why they are drawn as they are."""

ROD_ANGLE = 10.0
"""Degrees: rods nearer the guide than this run over each other's blocks on paper."""


@pytest.mark.parametrize("name", [n for n in NAMES if recipe(n).startswith("rocker_slider.")])
def test_a_rocker_slider_s_rods_stand_off_the_guide_or_are_known(name):
    fig = figure(name)
    rods = [sh for g in fig.groups if g.key[:1] == "F" and "E" in g.key for sh in g.shapes
            if isinstance(sh, Poly) and len(sh.pts) == 2]
    assert rods, name
    guide = math.radians(float(load_problem(PROBLEMS / f"{name}.toml").given.get("guide_angle") or 0.0))
    least = min(abs(math.degrees(math.asin(abs(math.sin(-math.atan2(q[1] - p[1], q[0] - p[0]) - guide)))))
                for p, q in (r.pts for r in rods))                       # paper y runs down: the angle's sign turns
    assert (least < ROD_ANGLE) == (name in KNOWN_CLOSE_RODS), (name, round(least, 2))
