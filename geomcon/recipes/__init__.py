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
from . import (crank_rocker, crank_rocker_design, crank_slider, crank_slider_best, crank_slider_design, guide_bar,
               guide_bar_design, slotter_design)
from .base import Construction, Quantity, Recipe

RECIPES: dict[str, Recipe] = {r.name: r for r in (crank_rocker.RECIPE, crank_rocker_design.RECIPE, crank_slider.RECIPE,
                                                crank_slider_design.RECIPE, crank_slider_best.RECIPE,
                                                guide_bar.RECIPE, guide_bar_design.GUIDE_RECIPE,
                                                guide_bar_design.SHAPER_RECIPE, slotter_design.RECIPE)}


def get_recipe(name: str) -> Recipe:
    """The recipe called ``name``; an unknown name raises :class:`ProblemError` listing the known ones."""
    try:
        return RECIPES[name]
    except KeyError:
        raise ProblemError(f"unknown recipe '{name}' (known: {', '.join(sorted(RECIPES))})") from None


__all__ = ["Construction", "Quantity", "RECIPES", "Recipe", "get_recipe"]
