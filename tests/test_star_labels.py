"""Every starred label of the gallery says what its star means (issue 11, hcam11k): a student reading B1*, K2* or A*
on a sheet did not know that * marks the position of the largest pressure angle (cam.translating), the point K of a
binding arm position (cam.base_radius, oscillating), the best pivot (crank_rocker.best_by_K,
crank_slider.best_by_K). The key is in the caption of the step that draws the label, or of a step before it, in
English ("* marks …") and Chinese ("* 标记…"), and that caption names the label."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from geomcon.problems import load_problem
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"


def _starred() -> list[str]:
    """The gallery problems whose sheets print a star (the scan is of the printed text, so that a new starred
    label anywhere in the gallery joins the test)."""
    out = []
    for j in sorted(GALLERY.glob("*.json")):
        svg = j.with_suffix(".svg")
        if svg.exists() and "*" in re.sub(r"<[^>]*>", "", svg.read_text(encoding="utf-8").split("<![CDATA[")[0]
                                          + svg.read_text(encoding="utf-8").split("]]>")[-1]):
            out.append(j.stem)
    return out


STARRED = _starred()


def _star_labels(sc) -> list[tuple[str, int]]:
    """(label, frame) of every drawn step whose label has a star."""
    out = []
    for k, group in enumerate(sc.frames(), 1):
        for s in group:
            if s.label and "*" in s.label and sc.value(s.key) is not None:
                out.append((s.label, k))
    return out


def test_every_kind_of_star_in_the_gallery_is_found():
    labels = set()
    for pid in STARRED:
        labels |= {lab for lab, _ in _star_labels(solve(load_problem(ROOT / "problems" / f"{pid}.toml"))
                                                  .drawing_scene)}
    assert {"B1*", "B2*", "K1*", "K2*", "A*"} <= labels, labels
    assert {"004-02_best_by_K_1_5", "004-03_crank_rocker_best_by_K", "200-12_oscillating_base_radius",
            "200-01_cam_roller_offset", "200-03_cam_roller_undercut"} <= set(STARRED)


@pytest.mark.parametrize("pid", STARRED)
def test_a_starred_label_s_key_is_in_a_caption_by_its_step(pid: str):
    sc = solve(load_problem(ROOT / "problems" / f"{pid}.toml")).drawing_scene
    stars = _star_labels(sc)
    assert stars, f"{pid} prints a star but draws no starred label"
    captions = [(k, sc.caption(group[0].key)) for k, group in enumerate(sc.frames(), 1)]
    for label, frame in stars:
        keyed = [k for k, (en, zh) in captions if k <= frame and label in en and label in zh
                 and re.search(r"\* marks \w", en) and re.search(r"\* 标记\S", zh)]
        assert keyed, f"{pid}: {label} (step {frame}) has no key for its star in its step's caption or before"
