"""Issue 11: the numbers of a crowded row (a cam's divisions 1′, 2′, …; the ticks 1, 2, … of its s–δ axis) were
left out where they would cover each other (27 in the gallery's sheets, 59 when the cam and its diagram shared a
sheet). Every one is now printed: a crowded cluster's numbers stand in order on a line beside it, each joined to
its point by a leader (:mod:`geomcon.render.rows`). Checked over every figure the gallery prints."""
from __future__ import annotations

import functools
import math
import itertools
from pathlib import Path

import pytest
import shapely
from shapely import affinity

import geomcon.render.svg as svg_module
from geomcon.geometry.primitives import Point
from gallery_pages import page_of
from geomcon.problems import load_problem
from geomcon.render.figure import Figure, merged_labels, shown_steps
from geomcon.render.placement import LABEL_REACH
from geomcon.render.rows import FAN_REACH, clusters, fans, row_centre, spread, thinned
from geomcon.render.shapes import Poly, Text
from geomcon.solve import solve

PROBLEMS = Path(__file__).resolve().parents[1] / "problems"
NAMES = [p.stem for p in sorted(PROBLEMS.glob("*.toml"))]


@functools.lru_cache(maxsize=None)
def printed(name: str) -> tuple[tuple[Figure, dict[str, str | None]], ...]:
    """Every figure the gallery prints for a problem (the drawing sheet, and a cam's s–δ sheet) with the label
    each drawn step asks for (None: a candidate point whose label the result beside it carries)."""
    sol = solve(load_problem(PROBLEMS / f"{name}.toml"))
    out = []
    real = svg_module.build_figure

    def capture(sc, upto=None, viewbox=None, origin=(0.0, 0.0), target=None, mu=None, keep=None, room=None,
                sketch=None):
        fig = real(sc, upto, viewbox, origin, **({} if target is None else {"target": target}), mu=mu, keep=keep,
                   room=room, sketch=sketch)
        steps, _ = shown_steps(sc, upto, keep)
        labels = {s.key: s.label for _, s in steps}
        labels.update(merged_labels(steps, fig.values, fig.view.box))
        out.append((fig, labels))
        return fig

    svg_module.build_figure = capture
    try:
        sol.sheets(page_of(name))
    finally:
        svg_module.build_figure = real
    return tuple(out)


def _box(t: Text) -> shapely.Geometry:
    """A text's box on paper, turned as the text is."""
    b = shapely.box(*t.box)
    return affinity.rotate(b, t.rotate, origin=b.centroid) if t.rotate else b


def _runs(t: Text) -> str:
    return "".join(s for s, _ in t.runs)


@pytest.mark.parametrize("name", NAMES)
def test_every_labelled_point_of_a_printed_figure_has_its_label(name):
    """No division number (nor any other point's label) is left out of a sheet the gallery prints, but the
    numbers of an s–δ axis's crowded run, thinned (checked by the test below)."""
    for fig, labels in printed(name):
        missing = [g.key for g in fig.groups if isinstance(fig.values[g.key], Point) and g.shapes
                   and labels.get(g.key) and not any(t.cls.startswith("label") for t in g.texts)
                   and " style-tick-division" not in g.classes]
        assert not missing, missing


@pytest.mark.parametrize("name", NAMES)
def test_a_spread_out_number_is_tied_to_its_point_by_a_leader(name):
    """A number on a crowded row's line of labels lies within FAN_REACH of its point, and its leader runs from
    its point's marker to its box; a label by its point lies within LABEL_REACH; no two texts overlap."""
    for fig, _ in printed(name):
        texts = [t for g in fig.groups for t in g.texts]
        for a, b in itertools.combinations(texts, 2):
            assert _box(a).intersection(_box(b)).area <= 1e-9, (_runs(a), _runs(b))
        for g in fig.groups:
            v = fig.values[g.key]
            if not isinstance(v, Point):
                continue
            p = shapely.Point(fig.view.p(v))
            for t in g.texts:
                box = shapely.box(*t.box)
                if t.anchor == "start" and t.cls.startswith("label"):
                    continue        # a part of a label naming points on one spot: checked whole below
                if t.cls == "label fan":
                    assert box.distance(p) <= FAN_REACH, (g.key, _runs(t))
                    leaders = [s for s in g.shapes if isinstance(s, Poly) and len(s.pts) == 2
                               and shapely.Point(s.pts[0]).distance(p) <= 1.75     # off a pivot's marker
                               and shapely.Point(s.pts[1]).distance(box) <= 0.5]
                    assert len(leaders) == 1, (g.key, _runs(t))
                elif t.cls == "label":
                    assert box.distance(p) <= LABEL_REACH + 1e-9, (g.key, _runs(t))
        parts = [(t, fig.view.p(fig.values[g.key])) for g in fig.groups for t in g.texts
                 if t.anchor == "start" and t.cls.startswith("label")]
        for t, _ in parts:                  # the whole label a part belongs to lies near a point it names
            whole = [(u, c) for u, c in parts if u.y == t.y and u.box[2] >= t.box[0] - 20 and u.box[0] <= t.box[2] + 20]
            box = shapely.box(min(u.box[0] for u, _ in whole), t.box[1], max(u.box[2] for u, _ in whole), t.box[3])
            reach = FAN_REACH if t.cls == "label fan" else LABEL_REACH
            assert min(box.distance(shapely.Point(c)) for _, c in whole) <= reach, _runs(t)


def test_the_slotter_cam_numbers_all_its_divisions():
    """000-04 (a rise of 10° in five divisions, a return likewise): its 11 pivot positions 1′ … 11′ are all
    printed, the crowded ones spread out with leaders (1′ stood between two dots); its ψ–δ axis, 2.5° a division,
    numbers every 2nd or 4th division of each crowded run, each under its own tick (1 … 11 spread out with
    leaders still crowded the axis)."""
    (cam, _), (diagram, _) = printed("000-04_slotter_cam_psi0")[:2]
    cam_numbers = sorted(_runs(t) for g in cam.groups if g.key.startswith("A_d") for t in g.texts)
    ticks = [_runs(t) for g in diagram.groups if g.key.startswith("sd_div") for t in g.texts]
    assert cam_numbers == sorted(f"{i}′" for i in range(1, 12))
    assert ticks[0] == "1" and "6" in ticks and 3 <= len(ticks) < 11
    fanned = [t for g in cam.groups for t in g.texts if t.cls == "label fan"]
    assert len(fanned) >= 8


@pytest.mark.parametrize("name", NAMES)
def test_an_s_delta_axis_numbers_its_divisions_apart_and_under_their_ticks(name):
    """000-07's ψ–δ axis printed 1–5 and 6–11 on top of each other, then spread out with leaders, still
    crowded: each division's number is printed by its own tick (no leader, within LABEL_REACH, nearer its tick
    than any other), clear of every other text; where they would not fit, every 2nd (4th) of a crowded run only,
    its first number always, and never more than 3 left out in a row."""
    for fig, _ in printed(name):
        row = [(int(g.key[6:]), fig.view.p(fig.values[g.key]), g.texts) for g in fig.groups
               if g.key.startswith("sd_div")]
        if not row:
            continue
        others = [t for g in fig.groups for t in g.texts]
        shown = []
        for n, p, texts in row:
            assert len(texts) <= 1, n
            for t in texts:
                box = _box(t)
                assert t.cls == "label" and _runs(t) == str(n), (n, t.cls)
                assert box.distance(shapely.Point(p)) <= LABEL_REACH + 1e-9, n
                nearest = min(row, key=lambda r: box.distance(shapely.Point(r[1])))
                assert nearest[0] == n or box.distance(shapely.Point(nearest[1])) == box.distance(shapely.Point(p)), n
                assert all(_box(u).intersection(box).area <= 1e-9 for u in others if u is not t), n
                shown.append(n)
        assert shown and shown[0] == row[0][0], shown
        assert all(b - a <= 4 for a, b in zip(shown, shown[1:])), shown


def test_thinned_keeps_every_second_or_fourth_of_a_crowded_run():
    assert thinned([(3.0 * x, 0.0) for x in range(5)], [(2.0, 2.0)] * 5, 0.6) == [0, 1, 2, 3, 4]     # room
    assert thinned([(2.0 * x, 0.0) for x in range(5)], [(2.0, 2.0)] * 5, 0.6) == [0, 2, 4]
    assert thinned([(1.0 * x, 0.0) for x in range(6)], [(2.0, 2.0)] * 6, 0.6) == [0, 4]


def test_spread_keeps_order_and_room_and_moves_least():
    xs = spread([0.0, 0.1, 0.2, 10.0], [1.0, 1.0, 1.0, 1.0], 0.6)
    assert xs == sorted(xs) and all(b - a >= 2.6 - 1e-12 for a, b in zip(xs, xs[1:]))
    assert xs[3] == 10.0 and abs(sum(xs[:3]) - 0.3) < 1e-12        # a pooled block keeps its mean


def test_a_fan_lies_beyond_every_point_of_its_cluster_on_the_side_asked():
    pts = [(0.0, 0.0), (1.0, 0.2), (2.0, 0.3), (3.0, 0.2)]
    assert clusters(pts, [(3.0, 2.7)] * 4, 0.6) == [[0, 1, 2, 3]]
    for fan in fans(pts, [(3.0, 2.7)] * 4, 0.55, (0.0, 1.0)):
        side = [c[1] - 1.35 for c in fan.centres] if fan.side == 1 else [-(c[1] + 1.35) for c in fan.centres]
        assert min(side) >= 0.3 + 0.55 + fan.offset - 1.0, fan      # beyond the row (chord nearly level)


@pytest.mark.parametrize("name", [n for n in NAMES if n.startswith(("001-23", "001-24", "200-0", "200-1"))])
def test_a_cam_s_divisions_are_numbered_outside_the_row(name):
    """A textbook numbers a cam's divisions outside the profile, along their rays. With the s–δ diagram beside
    the cam the numbers of its far side went inside, next to their neighbours' points (200-16's 6′, 15′, 19′):
    every division's number now lies farther from the row's centre than its point."""
    for fig, _ in printed(name):
        row = [(fig.view.p(fig.values[g.key]), t) for g in fig.groups for t in g.texts
               if "style-division" in g.classes and t.cls.startswith("label")]
        centre = row_centre([p for p, _ in row])
        if centre is None:
            continue
        for p, t in row:
            cx, cy = (t.box[0] + t.box[2]) / 2, (t.box[1] + t.box[3]) / 2
            assert math.dist((cx, cy), centre) > math.dist(p, centre), (name, _runs(t))


def test_the_worksheet_key_numbers_every_division_inside_its_figure():
    """The key's cam (exercise 3) touches its figure's left edge: numbering outside the profile only put 13′ off
    the figure (x < 0, clipped); where outside has no room the number goes all round its point instead."""
    import re
    svg = (PROBLEMS.parent / "gallery" / "worksheet" / "key" / "1-3.svg").read_text(encoding="utf-8")
    numbers = {t: float(x) for x, t in re.findall(r'<text class="label[^"]*"[^>]*? x="([-\d.]+)"[^>]*><tspan>(\d+′)</tspan>', svg)}
    assert sorted(numbers, key=lambda t: int(t[:-1])) == [f"{i}′" for i in range(1, 16)]
    assert min(numbers.values()) > 0.0
