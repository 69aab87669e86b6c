"""Issue 11 (hflat11): a flat-faced follower's face is drawn as wide as the Results say. 200-02 drew its face 0.45·r0
= 13.5 mm each side of the axis while the Results print lL = 19.324, lR = 10.279 mm (a student measuring the drawn
face got a wrong answer); 200-07 drew its face 1.12·l_max long against l_face = l_max; 200-18 drew ±0.9·r0 (±43.2
mm) where the contact runs ±8π = ±25.13 mm along the face (s′ jumps from −8π to 8π mm/rad at θ = 0).

Read from the sheet-1 SVG of the gallery, at the sheet's scale: the face's ends lie where the Results put them,
within 0.05 paper mm."""
from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest

from geomcon.paper import Scale

GALLERY = Path(__file__).resolve().parents[1] / "gallery"
TOL = 0.05                                   # paper mm


def _sheet(pid: str) -> tuple[str, dict, Scale]:
    svg = (GALLERY / f"{pid}.svg").read_text(encoding="utf-8")
    answers = json.loads((GALLERY / f"{pid}.json").read_text(encoding="utf-8"))["answers"]
    scale = Scale.parse(re.search(r'class="tb tb-2-0"[^>]*>[^<]*?(\d+(?:\.\d+)?:\d+(?:\.\d+)?)<', svg).group(1))
    return svg, answers, scale


def _group(svg: str, key: str) -> str:
    m = re.search(rf'<g [^>]*id="step-{re.escape(key)}"[^>]*>(.*?)</g>', svg)
    assert m, f"step-{key} is not drawn"
    return m.group(1)


def _segment(svg: str, key: str) -> tuple[complex, complex]:
    """The two ends (paper mm, as x + iy) of the one straight path of a drawn step."""
    m = re.fullmatch(r"M([-\d.]+) ([-\d.]+)L([-\d.]+) ([-\d.]+)",
                     re.search(r'<path class="ink" d="([^"]*)"', _group(svg, key)).group(1))
    assert m, f"step-{key} is not one straight segment"
    x1, y1, x2, y2 = map(float, m.groups())
    return complex(x1, y1), complex(x2, y2)


def _centre(svg: str, key: str) -> complex:
    m = re.search(r'<circle class="ink" cx="([-\d.]+)" cy="([-\d.]+)"', _group(svg, key))
    return complex(float(m.group(1)), float(m.group(2)))


@pytest.mark.parametrize("pid", ["200-02_cam_flat_face", "200-17_cam_table_law"])
def test_translating_face_reaches_lL_left_and_lR_right_of_the_axis(pid):
    svg, ans, scale = _sheet(pid)
    a, b = sorted(_segment(svg, "face_start"), key=lambda p: p.real)
    B0 = _centre(svg, "B0")                  # the face's reference point, on the follower's axis
    assert abs(a.imag - B0.imag) <= TOL and abs(b.imag - B0.imag) <= TOL
    assert abs((B0.real - a.real) - scale.to_paper(ans["face_width_left"])) <= TOL
    assert abs((b.real - B0.real) - scale.to_paper(ans["face_width_right"])) <= TOL


def test_200_07_oscillating_face_runs_from_the_pivot_s_foot_to_l_max():
    svg, ans, scale = _sheet("200-07_oscillating_flat_face")
    assert ans["face_min"] > 0.0             # every contact ahead of the foot F: the face is [F, l_max]
    _, F = _segment(svg, "arm0")             # the arm from A0 to the face's foot F
    ends = _segment(svg, "face0")
    near, far = sorted(ends, key=lambda p: abs(p - F))
    assert abs(near - F) <= TOL
    assert abs(abs(far - F) - scale.to_paper(ans["face_max"])) <= TOL
    assert abs(abs(far - near) - scale.to_paper(ans["face_length"])) <= TOL
    worst = re.findall(r'id="step-(wface_[a-z]+)"', svg)    # the face in the worst positions (K1, K2): as long
    assert worst                                             # (they were 1.12·l_max too)
    for key in worst:
        a, b = _segment(svg, key)
        assert abs(abs(b - a) - scale.to_paper(ans["face_length"])) <= TOL, key


def test_200_18_face_covers_the_contact_s_excursion_of_8_pi_each_side():
    """Plus the textbooks' margin, 3 mm at each end (L = l′max + l″max + (5~7) mm): the face just covering the
    excursion lay on the profile's straight piece end to end and could not be seen."""
    svg, ans, scale = _sheet("200-18_base_radius_flat_gate2020")
    a, b = sorted(_segment(svg, "face"), key=lambda p: p.real)
    O = _centre(svg, "O")                    # a centred follower: the axis through O
    reach = scale.to_paper(8.0 * math.pi + 3.0)    # y = 4(2πθ − θ²): y′ = 8(π − θ), ±8π at θ = 0 and 2π
    assert abs((O.real - a.real) - reach) <= TOL
    assert abs((b.real - O.real) - reach) <= TOL


@pytest.mark.parametrize("pid, OA", [("001-30_eccentric_flat_offset", 50.0), ("001-30b_eccentric_flat_R60", 50.0)])
def test_eccentric_face_covers_the_contact_s_run_of_oa_each_side_of_o(pid, OA):
    """001-30 drew the face 0.3·R past K and F (from 1 to 74 mm right of O): the contact, always straight above the
    disc's centre A, runs OA = 50 mm either side of O over a turn — the face now spans exactly that."""
    svg, _, scale = _sheet(pid)
    a, b = sorted(_segment(svg, "face_seg"), key=lambda p: p.real)
    O = _centre(svg, "O")
    assert abs((O.real - a.real) - scale.to_paper(OA)) <= TOL
    assert abs((b.real - O.real) - scale.to_paper(OA)) <= TOL


@pytest.mark.parametrize("pid", ["200-02_cam_flat_face", "200-17_cam_table_law"])
def test_every_inverted_face_reaches_the_envelope_it_touches(pid):
    """200-02's dashed faces at 3′–6′ (0.3·r0 = 9 mm each side) stopped short of the profile, whose contact lies up
    to lL = 19.3 mm left of the axis: the envelope touched their extensions. Each drawn face now meets the drawn
    profile (within 0.05 paper mm)."""
    import shapely

    from test_drawing_defects import figure

    fig = figure(pid)
    profile = shapely.LineString([(p.x, p.y) for p in fig.values["profile_curve"].points])
    faces = [k for k in fig.values if re.fullmatch(r"F\d+", k)]
    assert len(faces) >= 12
    for k in faces:
        seg = fig.values[k]
        assert shapely.LineString([(seg.a.x, seg.a.y), (seg.b.x, seg.b.y)]).distance(profile) <= TOL * fig.view.mu, k
