"""The oscillating cam construction's shortened searches against the full ones, on random cams: the same bits.

- α_max of a segment by one pass over its pieces, maxima only (:func:`geomcon.cam.arm_alpha.segment_max_one_pass`)
  against :meth:`~geomcon.cam.oscillating.ArmMotion.segment_max` refining every sign change of the same slope;
- ρmin of the pitch curve with its dwells sampled at their ends only (``PitchCurve.still``) against the same
  search over every sample.
"""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from geomcon.cam.oscillating import OscillatingCam
from geomcon.cam.profile import rho_min
from random_programs import random_program

SEEDS = range(24)


def _cam(rng: np.random.Generator) -> OscillatingCam:
    """A random arm cam (rise, dwell, return, dwell, any laws, now and then a dwell left out) that assembles."""
    prog = random_program(rng)
    dist = float(rng.uniform(80, 160))
    return OscillatingCam(dist, float(rng.uniform(0.75, 1.0)) * dist, float(rng.uniform(0.3, 0.45)) * dist,
                          float(rng.uniform(3, 30)), prog, str(rng.choice(["ccw", "cw"])), str(rng.choice(["left", "right"])))


@pytest.mark.parametrize("seed", SEEDS)
def test_alpha_one_pass_is_the_full_search(seed):
    cam = _cam(np.random.default_rng(seed))
    for kind in ("rise", "return"):
        full = cam.segment_max(kind, cam.pressure_of, cam.tan_slope, cam._tan_slope1())
        assert cam.worst_pressure(kind) == full


@pytest.mark.parametrize("seed", SEEDS)
def test_rho_min_without_the_dwells_inside(seed):
    cam = _cam(np.random.default_rng(seed))
    curve = cam.pitch_curve(scalar=True)
    assert curve.still
    assert rho_min(curve) == rho_min(dataclasses.replace(cam.pitch_curve(scalar=True), still=()))
