"""One result on every machine: the committed gallery does not depend on which SIMD paths numpy takes.

numpy dispatches its vectorised sin, cos, exp… to the best instruction set the CPU has (AVX2, AVX-512 …), and
those paths round differently in the last bits. geomcon writes numbers at their quantity's scale (12 digits)
and check errors above a noise floor only, so the gallery must come out byte-identical when every dispatched
path this CPU has is switched off (``NPY_DISABLE_CPU_FEATURES``). On a CPU with AVX-512 this proves the
AVX-512 paths harmless; on one with AVX2 only, the AVX2 paths; on a baseline-only CPU there is nothing to
switch off and the test is skipped.
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def dispatched_features() -> list[str]:
    """The SIMD targets numpy dispatches to that this CPU has (numpy 1.x and 2.x)."""
    try:
        from numpy._core import _multiarray_umath as m
    except ImportError:                                  # numpy 1.x
        from numpy.core import _multiarray_umath as m    # type: ignore[no-redef]
    return [f for f in m.__cpu_dispatch__ if m.__cpu_features__.get(f)]


def test_gallery_is_identical_without_the_dispatched_simd_paths():
    features = dispatched_features()
    if not features:
        pytest.skip("this CPU runs numpy's baseline only: no SIMD path to switch off")
    env = {**os.environ, "NPY_DISABLE_CPU_FEATURES": " ".join(features)}
    r = subprocess.run([sys.executable, "-m", "geomcon.cli", "gallery", "--check"], cwd=ROOT, env=env,
                       capture_output=True, text=True, timeout=900)
    assert r.returncode == 0, f"with {features} disabled: {r.stderr[-2000:]}"


def test_json_numbers_carry_no_last_bit_noise():
    from geomcon.check import error_text, rounded

    assert rounded(12.505586093412345, 1.0) == rounded(12.505586093412347, 1.0)
    assert rounded(3.5e-15, 90.0) == rounded(-2.2e-16, 90.0) == 0.0
    assert error_text(3.55e-15, 12.5) == error_text(5.33e-15, 12.5) == error_text(0.0, 12.5) == 0.0


@pytest.mark.parametrize("name", sorted(p.name for p in (ROOT / "problems").glob("*.toml")))
def test_a_problems_json_does_not_depend_on_earlier_solves(name):
    """The first solve of a problem in a process is planned (and tapes the recipe); later ones replay the tape:
    the JSON, its ``stats`` included, is the same either way (a replayed scene once counted a step the recipe
    evaluates while building, 100-01's branch side, as not evaluated: 40 steps instead of 41)."""
    from geomcon.gallery import to_json_text
    from geomcon.problems import load_problem
    from geomcon.solve import solve

    p = load_problem(ROOT / "problems" / name)
    first, second, third = (to_json_text(solve(p)) for _ in range(3))
    assert first == second == third
