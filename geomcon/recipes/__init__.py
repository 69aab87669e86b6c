"""The recipe registry: every textbook construction geomcon can replay, by public name.

Examples
--------
>>> "crank_rocker.extremes" in RECIPES
True
>>> get_recipe("crank_rocker.extremes").answers[0].name
'theta'
"""
from __future__ import annotations

from ..errors import ProblemError
from . import (cam_base_radius, cam_eccentric, cam_oscillating, cam_translating, crank_rocker, crank_rocker_design,
               crank_slider, crank_slider_best, crank_slider_design, four_bar_fixed_pivots, four_bar_function,
               four_bar_positions, guide_bar, guide_bar_design, rocker_slider, slotter_design)
from .base import Construction, Quantity, Recipe

RECIPES: dict[str, Recipe] = {r.name: r for r in (
    # extreme positions (issue 2) and design by K (issue 3)
    crank_rocker.RECIPE, crank_rocker_design.RECIPE, crank_slider.RECIPE, crank_slider_design.RECIPE,
    crank_slider_best.RECIPE, guide_bar.RECIPE, guide_bar_design.GUIDE_RECIPE, guide_bar_design.SHAPER_RECIPE,
    slotter_design.RECIPE,
    # three-position synthesis (issue 4)
    four_bar_positions.RECIPE, four_bar_fixed_pivots.RECIPE, four_bar_function.RECIPE, rocker_slider.THREE,
    rocker_slider.TWO,
    # cams by inversion (issue 5)
    cam_translating.RECIPE, cam_oscillating.RECIPE, cam_eccentric.RECIPE, cam_base_radius.RECIPE,
)}


def get_recipe(name: str) -> Recipe:
    """The recipe called ``name``; an unknown name raises :class:`ProblemError` listing the known ones."""
    try:
        return RECIPES[name]
    except KeyError:
        raise ProblemError(f"unknown recipe '{name}' (known: {', '.join(sorted(RECIPES))})") from None


__all__ = ["Construction", "Quantity", "RECIPES", "Recipe", "get_recipe"]
