"""A teacher's second look at issue 11: the figure shows what its problem asks. Every point the title names is
labelled in the figure (001-25 asked for the contact points C and D and drew B, B1 and a "D" on the cam centre),
and the quantity a question asks for at the drawn position is marked there (300-01 asked for the pressure angle
and marked only γ; 400-04 asked for the six instant centres and named two)."""
from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
from test_drawing_defects import NAMES, _members, figure, runs  # noqa: E402

from geomcon.problems import load_problem  # noqa: E402
from geomcon.scene.marks import AngleMark, Dimension  # noqa: E402

PROBLEMS = Path(__file__).parent.parent / "problems"
QUANTITIES = {"K", "H", "S", "R", "GATE"}
"""Capitals of a title that are quantities or words, not points (K = 1.4, the stroke H, S = 2·CD, R = 60 mm)."""


def title_points(title: str) -> set[str]:
    """The point names a title writes: single points (C1, P34) and those of a link or chord (CD, OA, B1B2).

    >>> sorted(title_points("contact at C and at D; the ram's stroke S = 2·CD, B1B2 = 2S, K = 1.5"))
    ['B1', 'B2', 'C', 'D']
    """
    out: set[str] = set()
    for tok in re.findall(r"(?<![\w′])(?:[A-Z]\d*)+(?![\w′])", title.removeprefix("A ")):
        if tok not in QUANTITIES:
            out |= set(re.findall(r"[A-Z]\d*", tok))
    return out


def labels(name: str) -> set[str]:
    """Every point name printed in a figure's labels ("B (P12)" names B and P12), by its point or with a leader."""
    fig = figure(name)
    return {p for g in fig.groups for t in g.texts if t.cls.startswith("label") for p in re.findall(r"[A-Z]\d*", runs(t))}


NO_FIGURE_OF_POINTS = {"001-02_four_bar_link_ranges"}
"""A table of link-length ranges, not a drawing of the linkage: its title's AB, CD are lengths."""


@pytest.mark.parametrize("name", [n for n in NAMES if n not in NO_FIGURE_OF_POINTS])
def test_every_point_the_title_names_is_labelled(name):
    """A bare letter of a link (CD) is a point drawn in any of its positions (C1, C2); a numbered one (C1,
    P34) is labelled with exactly that name."""
    title = load_problem(PROBLEMS / f"{name}.toml").title
    shown = labels(name)
    missing = {p for p in title_points(title)
               if p not in shown and (len(p) > 1 or not any(q.startswith(p) for q in shown))}
    assert not missing, (title, missing)


ASKED = {
    "300-01_four_bar_double_rocker_pressure_angle": {"α", "γ"},
    "001-24_cam_displacement_at_100": {"s"},
    "200-16_cam_poly_4567": {"s"},
    "001-31_eccentric_oscillating_roller": {"ψ0", "ψ0+ψmax", "α"},
    "001-31b_eccentric_oscillating_roller_speeds": {"ψ0", "ψ0+ψ", "α"},
    "200-09_base_radius_cycloidal": {"r0", "e", "s0"},
    "200-10_base_radius_centred": {"r0", "s0"},
    "200-11_base_radius_rise_and_return": {"r0", "e", "s0"},
    "200-19_base_radius_alpha_and_rho": {"r0", "r0,α", "e", "s0"},
    "200-18_base_radius_flat_gate2020": {"r0"},
    "001-13_radar_antenna_K1": {"ψ"},
    "001-14_crank_rocker_K1_frame_angles": {"ψ", "φ1", "φ2"},
    "001-21_cutter_drive_K1": {"ψ", "φ1", "φ2"},
    "100-07_rocker_slider_three_positions": {"αmax"},
    "100-08_rocker_slider_inclined_guide": {"αmax"},
    "100-09_rocker_slider_two_positions": {"αmax"},
}
"""The quantities a problem asks for at its drawn position, as the figure must mark them (angle or dimension)."""


def marked(name: str) -> set[str]:
    fig = figure(name)
    return {m.symbol for g in fig.groups for m in _members(fig.values[g.key]) if isinstance(m, (AngleMark, Dimension))}


@pytest.mark.parametrize("name", sorted(ASKED))
def test_the_asked_quantities_are_marked_in_the_figure(name):
    assert ASKED[name] <= marked(name)


@pytest.mark.parametrize("name", [n for n in NAMES if n.startswith(("100-07", "100-08", "100-09"))])
def test_a_rocker_slider_marks_its_largest_pressure_angle_at_the_worst_slider(name):
    """100-08 answered αmax = 38.093° with no mark in the figure: the arc between rod and guide is drawn at the pin
    E of the position whose rod is most inclined to the guide, with the answer's value."""
    from geomcon.solve import solve
    sol = solve(load_problem(PROBLEMS / f"{name}.toml"))
    fig = figure(name)
    m = next(m for g in fig.groups for m in _members(fig.values[g.key]) if isinstance(m, AngleMark) and m.symbol == "αmax")
    assert abs(m.value - sol.answers["alpha_max"]) < 1e-9
    pins = [fig.values[k] for k in ("E1", "E2", "E3") if k in fig.values]
    assert any(abs(m.vertex - E) < 1e-9 for E in pins)


def test_the_eccentric_arm_marks_psi0_plus_psimax_as_the_exact_angle_rounded_once():
    """001-31's review read "ψ0+ψmax = 49.99°" as a sum of rounded parts short of 50°. It is not: the arm at its
    highest has |OB1| = Rp + OA = 70 = L, so ∠OQ1B1 = acos(a / 2L) = acos(9/14) = 49.9948°, measured in the figure
    and printed rounded once (16.195° + 33.800° = 49.995°); the mark equals ψ0 + ψmax and that angle."""
    import math
    from geomcon.solve import solve
    sol = solve(load_problem(PROBLEMS / "001-31_eccentric_oscillating_roller.toml"))
    fig = figure("001-31_eccentric_oscillating_roller")
    m = next(m for g in fig.groups for m in _members(fig.values[g.key]) if isinstance(m, AngleMark)
             and m.symbol == "ψ0+ψmax")
    exact = math.degrees(math.acos(90.0 / (2 * 70.0)))
    assert abs(m.value - exact) < 1e-9 and abs(sol.answers["psi0"] + sol.answers["psi_max"] - exact) < 1e-9
    shown = [runs(t) for g in fig.groups if g.key == "mark_psi_high" for t in g.texts]
    assert shown == ["ψ0+ψmax=49.99°"]


@pytest.mark.parametrize("name", [n for n in NAMES if n.startswith(("200-09", "200-10", "200-11", "200-19"))])
def test_r0_and_s0_are_dimensioned_apart(name):
    """200-10 (a centred follower: s0 = r0 along the same segment OB0) dimensioned r0 and s0 on that one segment,
    2 mm apart, the one over the other: two dimensions of one figure either run in directions 15° or more apart or
    lie 5 paper mm or more apart, and their texts do not overlap."""
    import itertools
    import math
    import shapely
    from shapely import affinity

    def turned(t):
        b = shapely.box(*t.box)
        return affinity.rotate(b, t.rotate, origin=b.centroid) if t.rotate else b
    fig = figure(name)
    dims = [(g, m) for g in fig.groups for m in _members(fig.values[g.key]) if isinstance(m, Dimension)]
    for (g1, m1), (g2, m2) in itertools.combinations(dims, 2):
        a1, b1, a2, b2 = (fig.view.p(p) for p in (m1.a, m1.b, m2.a, m2.b))
        t1 = math.atan2(b1[1] - a1[1], b1[0] - a1[0])
        t2 = math.atan2(b2[1] - a2[1], b2[0] - a2[0])
        turn = abs((t1 - t2 + math.pi / 2) % math.pi - math.pi / 2)
        apart = shapely.LineString([a1, b1]).distance(shapely.LineString([a2, b2]))
        off = abs(m1.offset - m2.offset) / fig.view.mu
        assert turn >= math.radians(15) or apart >= 5.0 or off >= 5.0, (m1.symbol, m2.symbol)
        for u in g1.texts:
            for v in g2.texts:
                assert turned(u).intersection(turned(v)).area <= 1e-9, (m1.symbol, m2.symbol)


def test_the_crank_slider_shows_its_centre_at_infinity_and_every_joint_as_a_centre():
    """400-05: the six centres of a crank-slider are A, B, C (P14, P12, P23), P13 and P24 by Kennedy and P34 at
    infinity, named at the tip of an arrow perpendicular to the guide; 400-04 names its four joints likewise."""
    assert {"P12", "P14", "P23", "P13", "P24", "P34"} <= labels("400-05_crank_slider_instant_centres")
    assert {"P12", "P14", "P23", "P34", "P13", "P24"} <= labels("400-04_four_bar_instant_centres")
    fig = figure("400-05_crank_slider_instant_centres")
    tip, C = fig.values["P34"], fig.values["C"]
    assert abs(tip.x - C.x) < 1e-9 and tip.y < C.y


@pytest.mark.parametrize("name", [n for n in NAMES if n.startswith(("200-09", "200-10", "200-11", "200-19"))])
def test_the_ds_ddelta_s_diagram_has_named_axes_and_ticks(name):
    """200-09…11, 19: the diagram the base circle is read from has its two axes named and ticks at h and at
    the curve's widest ds/dδ; the final r0 of 200-19 (curvature-limited) is dimensioned from O′, r0,α from O."""
    fig = figure(name)
    shown = {runs(t) for g in fig.groups for t in g.texts}
    assert {"ds/dδ", "s", "h"} <= shown
    assert any(g.key.startswith("tick_ds_") for g in fig.groups)
    if name.startswith("200-19"):
        dims = {m.symbol: m for g in fig.groups for m in _members(fig.values[g.key]) if isinstance(m, Dimension)}
        assert dims["r0"].a == fig.values["O_design"] and dims["r0,α"].a == fig.values["O"]


def test_the_flat_face_curvature_diagram_says_what_it_plots():
    """200-18: the right-hand curve is the (s + s″)–δ diagram: its ordinate and δ axis are named, its lowest
    point (where ρ = r0 + s + s″ is least) is named, and the follower is drawn on the designed cam."""
    fig = figure("200-18_base_radius_flat_gate2020")
    shown = {runs(t) for g in fig.groups for t in g.texts}
    assert {"s + s″ (mm)", "δ", "min(s + s″)"} <= shown
    assert {"face", "stem", "guide_mark"} <= {g.key for g in fig.groups}


@pytest.mark.parametrize("name", NAMES)
def test_an_angle_of_zero_is_a_note_not_a_bare_number(name):
    """001-01 printed "γ1=0.00°" with no arc beside C2: an angle mark of 0 says the lines are collinear, after its
    value ("γ1=0° (collinear)", as the review asked: the symbol first, as for every angle)."""
    fig = figure(name)
    for g in fig.groups:
        for m in _members(fig.values[g.key]):
            if isinstance(m, AngleMark) and abs(m.value) < 0.005:
                assert [runs(t) for t in fig.groups[fig.groups.index(g)].texts] == [f"{m.symbol}=0° (collinear)"]


def test_the_double_rocker_on_frame_cd_marks_its_dead_points_and_names_its_links_right():
    """001-03c: γmin = 0 at the dead points is marked there; the frame CD is never called a turning link."""
    fig = figure("001-03c_four_bar_frame_CD")
    assert sum(1 for g in fig.groups if g.key.startswith("mark_gamma_dead")) == 2
    from geomcon.render.results import name_of
    assert name_of("output_crank", "four_bar.analysis").en == "the link at the second pivot is a crank"
    assert name_of("output_crank", "four_bar.three_positions").en == "CD turns fully"
