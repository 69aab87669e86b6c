"""The cams' drawn polylines are built from Python floats (``tolist``), not row by row from numpy arrays
(each row a view, each number a numpy scalar: 4.5 times the cost for a profile's 1500 points): the same
points, plain floats."""
from __future__ import annotations

import numpy as np

from geomcon.cam.profile import PitchCurve, roller_profile
from geomcon.recipes.cam_common import pitch_polyline, profile_polyline


def _ellipse(d):
    return 50 * np.cos(d), 30 * np.sin(d), -50 * np.sin(d), 30 * np.cos(d), -50 * np.cos(d), -30 * np.sin(d)


def test_pitch_and_profile_polylines_hold_the_samples():
    curve = PitchCurve(_ellipse)
    pl = pitch_polyline(curve, 360)
    x, y = curve.eval(np.linspace(0.0, 2.0 * np.pi, 360, endpoint=False))[:2]
    assert [p.tuple() for p in pl.points] == list(zip(x.tolist(), y.tolist()))
    prof = roller_profile(curve, 5.0)
    drawn = profile_polyline(prof)
    step = max(1, len(prof.xy) // 1500)
    assert [p.tuple() for p in drawn.points] == [tuple(r) for r in prof.xy[::step].tolist()]
    assert all(type(p.x) is float and type(p.y) is float for p in drawn.points)
