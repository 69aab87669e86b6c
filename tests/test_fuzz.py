"""The seeded fuzz at CI size: hostile mutations of every bundled problem, and random valid problems of every
generator family checked against their twins and their ground truth. Every failure count must be 0.

A longer run is ``geomcon fuzz --hostile 10000 --valid 10000`` (the README quotes its counts).
"""
from __future__ import annotations

from pathlib import Path

import pytest

from geomcon.fuzz.runner import FAILURES, all_generators, run_hostile, run_valid
from geomcon.gallery import problem_files

ROOT = Path(__file__).resolve().parents[1]
SEED = 2026

HOSTILE = 260
"""Mutants in CI: four per bundled problem (a fifth of them also drawn)."""

VALID = 25
"""Random valid problems per generator in CI."""


def _assert_clean(report) -> None:
    bad = {k: report.examples.get(k) for k in FAILURES if report.counts.get(k)}
    assert not bad, bad


def test_hostile_files_follow_the_exit_code_contract():
    report = run_hostile(problem_files(ROOT / "problems"), HOSTILE, SEED)
    _assert_clean(report)
    assert report.counts.get("refusal", 0) > HOSTILE // 2 and report.counts.get("solved", 0) > 0


GENERATORS = all_generators()


def test_every_recipe_family_has_a_generator():
    from geomcon.recipes import RECIPES

    recipes_of = {name for name in RECIPES if any(g.startswith(name) for g in GENERATORS)}
    assert recipes_of == set(RECIPES), sorted(set(RECIPES) - recipes_of)


@pytest.mark.parametrize("name", sorted(GENERATORS))
def test_random_valid_problems_agree_with_twin_and_truth(name):
    report = run_valid({name: GENERATORS[name]}, VALID, SEED)
    _assert_clean(report)
    assert report.counts.get("solved", 0) + report.counts.get("refusal", 0) == VALID
