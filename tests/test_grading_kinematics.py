"""The kinematics recipes' declared mistakes diagnosed when grading (issue 13's contract for issue 15's recipes).
The wrong values are computed here from the closed forms (geomcon.analytic.kinematics), independently of the
scene replays that diagnose them: the Coriolis term left out moves ε3 by 2·ω3·v_slip/CB (and reversed by twice
that), the normal component ω2²·BC left out of the four-bar's polygon is a different closure (solved here with the
closed form's own equations), a mirrored image is E at −∠CBE, and ω1/ω3 is the reciprocal of ω3/ω1."""
from __future__ import annotations

import cmath
import math

import pytest

from geomcon.analytic.kinematics import four_bar, guide_bar, slotter
from geomcon.grading import grade
from geomcon.grading.answers import read_answers
from geomcon.grading.keyfile import key_from_problem
from geomcon.grading.tables import grades_data
from geomcon.problems import load_problem

ROOT = __import__("pathlib").Path(__file__).resolve().parents[1]


def _graded(problem: str, header: list[str], rows: list[list[float]]) -> dict:
    key = key_from_problem(ROOT / "problems" / problem)
    text = ",".join(["id"] + header) + "\n" + "".join(
        ",".join([str(i + 1)] + [repr(v) for v in r]) + "\n" for i, r in enumerate(rows))
    return grades_data(grade(key, read_answers(text.encode())))


def test_guide_bar_coriolis_mistakes():
    g = load_problem(ROOT / "problems/400-03_guide_bar_coriolis.toml").given
    r = guide_bar(g["AB"], g["AC"], g["phi"], g["omega"], g["epsilon"])
    shift = 2 * r["omega3"] * r["v_slip"] / r["CB"]
    data = _graded("400-03_guide_bar_coriolis.toml", ["epsilon3"],
                   [[r["epsilon3"]], [r["epsilon3"] + shift], [r["epsilon3"] + 2 * shift]])
    got = [row["answers"]["epsilon3"] for row in data["rows"]]
    assert got[0]["verdict"] == "correct"
    assert (got[1]["verdict"], got[1]["diagnosis"]) == ("wrong", "coriolis_omitted")
    assert (got[2]["verdict"], got[2]["diagnosis"]) == ("wrong", "coriolis_direction")
    assert "Coriolis" in got[1]["diagnosis_en"]


def _four_bar_without_n2(g: dict) -> float:
    """ε3 when ω2²·BC is left out: the tangential directions closed on the other normal component only."""
    r = four_bar(g["AB"], g["BC"], g["CD"], g["AD"], g["phi"], g["omega"], g["epsilon"], BE=g["BE"],
                 angle_CBE=g["angle_CBE"])
    t2 = cmath.exp(1j * math.radians(r["theta2"]))
    t3 = cmath.exp(1j * math.radians(r["theta3"]))
    aB = g["AB"] * (1j * g["epsilon"] - g["omega"] ** 2) * cmath.exp(1j * math.radians(g["phi"]))
    rest = aB + r["omega3"] ** 2 * g["CD"] * t3          # the missing term: − ω2²·BC·t2
    s = (t2 * t3.conjugate()).imag
    return (-rest / 1j * t2.conjugate()).imag / (g["CD"] * s)


def test_four_bar_mistakes():
    g = dict(load_problem(ROOT / "problems/400-01_four_bar_velocity_polygons.toml").given)
    r = four_bar(g["AB"], g["BC"], g["CD"], g["AD"], g["phi"], g["omega"], g["epsilon"], BE=g["BE"],
                 angle_CBE=g["angle_CBE"])
    mirrored = four_bar(g["AB"], g["BC"], g["CD"], g["AD"], g["phi"], g["omega"], g["epsilon"], BE=g["BE"],
                        angle_CBE=-g["angle_CBE"])
    data = _graded("400-01_four_bar_velocity_polygons.toml", ["epsilon3", "vE"],
                   [[r["epsilon3"], r["vE"]], [_four_bar_without_n2(g), mirrored["vE"]]])
    right, wrong = (row["answers"] for row in data["rows"])
    assert right["epsilon3"]["verdict"] == right["vE"]["verdict"] == "correct"
    assert (wrong["epsilon3"]["verdict"], wrong["epsilon3"]["diagnosis"]) == ("wrong", "normal_omitted")
    assert (wrong["vE"]["verdict"], wrong["vE"]["diagnosis"]) == ("wrong", "image_mirrored")


def test_instant_centre_ratio_inverted():
    g = load_problem(ROOT / "problems/400-04_four_bar_instant_centres.toml").given
    w3 = four_bar(g["AB"], g["BC"], g["CD"], g["AD"], g["phi"], 1.0)["omega3"]
    # asked alone, and together (then each is also the other's value: swapped is as honest a reading)
    a = _graded("400-04_four_bar_instant_centres.toml", ["w3_w1"], [[1 / w3]])["rows"][0]["answers"]
    b = _graded("400-04_four_bar_instant_centres.toml", ["i13"], [[w3]])["rows"][0]["answers"]
    assert (a["w3_w1"]["diagnosis"], b["i13"]["diagnosis"]) == ("ratio_inverted", "ratio_inverted")
    both = _graded("400-04_four_bar_instant_centres.toml", ["w3_w1", "i13"], [[1 / w3, w3]])["rows"][0]["answers"]
    assert both["w3_w1"]["diagnosis"] in ("ratio_inverted", "swapped") and both["w3_w1"]["verdict"] == "wrong"


def _ram_aE(r: dict, DE: float, aD: complex) -> float:
    """The ram's acceleration closed from D's acceleration ``aD``: aE = aD + (iε4 − ω4²)·DE·t4, vertical."""
    t4 = cmath.exp(1j * math.radians(r["theta4"]))
    rest = aD - r["omega4"] ** 2 * DE * t4
    e4 = rest.real / (DE * t4.imag)
    return rest.imag + e4 * DE * t4.real


def test_slotter_mistakes():
    """At 000-03's position: the Coriolis term left out or reversed (ε3), the guide's normal ω3²·CB left out (the
    slip's acceleration loses it), D's image d′ on b3′'s side (aD reversed, the ram's polygon closed on it)."""
    g = load_problem(ROOT / "problems/000-03_slotter_velocity_polygons.toml").given
    r = slotter(g["AB"], g["AC"], g["CD"], g["DE"], g["CF"], g["phi"], g["omega"], g["epsilon"], g["branch"])
    aD = complex(r["aDx"], r["aDy"])
    assert math.isclose(_ram_aE(r, g["DE"], aD), r["aE"], rel_tol=1e-12)
    shift = 2 * r["omega3"] * r["v_slip"] / r["CB"]
    data = _graded("000-03_slotter_velocity_polygons.toml", ["epsilon3", "a_slip", "aE"],
                   [[r["epsilon3"], r["a_slip"], r["aE"]],
                    [r["epsilon3"] + shift, r["a_slip"] - r["CB"] * r["omega3"] ** 2, _ram_aE(r, g["DE"], -aD)],
                    [r["epsilon3"] + 2 * shift, r["a_slip"], r["aE"]]])
    right, wrong, other = (row["answers"] for row in data["rows"])
    assert right["epsilon3"]["verdict"] == right["a_slip"]["verdict"] == right["aE"]["verdict"] == "correct"
    assert (wrong["epsilon3"]["verdict"], wrong["epsilon3"]["diagnosis"]) == ("wrong", "coriolis_omitted")
    assert (wrong["a_slip"]["verdict"], wrong["a_slip"]["diagnosis"]) == ("wrong", "normal_omitted")
    assert (wrong["aE"]["verdict"], wrong["aE"]["diagnosis"]) == ("wrong", "image_same_side")
    assert (other["epsilon3"]["verdict"], other["epsilon3"]["diagnosis"]) == ("wrong", "coriolis_direction")
