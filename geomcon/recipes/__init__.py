"""The recipe registry: every textbook construction geomcon can replay, by public name.

The registry is lazy: it knows each recipe's module by name and imports a recipe only when it is asked for, so
solving a linkage problem never imports the cam modules (nor numpy, nor shapely).

Examples
--------
>>> "crank_rocker.extremes" in RECIPES
True
>>> get_recipe("crank_rocker.extremes").answers[0].name
'theta'
"""
from __future__ import annotations

from importlib import import_module
from typing import Iterator, Mapping

from ..errors import ProblemError
from .base import Construction, Quantity, Recipe

_WHERE: dict[str, tuple[str, str]] = {
    # extreme positions (issue 2) and design by K (issue 3)
    "crank_rocker.extremes": ("crank_rocker", "RECIPE"),
    "crank_rocker.design_by_K": ("crank_rocker_design", "RECIPE"),
    "crank_slider.extremes": ("crank_slider", "RECIPE"),
    "crank_slider.design_by_K": ("crank_slider_design", "RECIPE"),
    "crank_slider.best_by_K": ("crank_slider_best", "RECIPE"),
    "crank_rocker.best_by_K": ("crank_rocker_best", "RECIPE"),
    "guide_bar.extremes": ("guide_bar", "RECIPE"),
    "guide_bar.design_by_K": ("guide_bar_design", "GUIDE_RECIPE"),
    "shaper.design_by_K": ("guide_bar_design", "SHAPER_RECIPE"),
    "slotter.design_by_K": ("slotter_design", "RECIPE"),
    # linkage analysis (issue 14)
    "four_bar.analysis": ("four_bar_analysis", "RECIPE"),
    "four_bar.link_ranges": ("four_bar_link_ranges", "RECIPE"),
    "rotating_guide_bar.extremes": ("rotating_guide_bar", "RECIPE"),
    # three-position synthesis (issue 4)
    "four_bar.three_positions": ("four_bar_positions", "RECIPE"),
    "four_bar.three_positions_fixed_pivots": ("four_bar_fixed_pivots", "RECIPE"),
    "four_bar.function_generation": ("four_bar_function", "RECIPE"),
    "rocker_slider.three_positions": ("rocker_slider", "THREE"),
    "rocker_slider.two_positions": ("rocker_slider", "TWO"),
    # cams by inversion (issue 5)
    "cam.translating": ("cam_translating", "RECIPE"),
    "cam.oscillating": ("cam_oscillating", "RECIPE"),
    "cam.eccentric": ("cam_eccentric", "RECIPE"),
    "cam.base_radius": ("cam_base_radius", "RECIPE"),
    # kinematic analysis at one position (issue 15)
    "four_bar.kinematics": ("four_bar_kinematics", "RECIPE"),
    "crank_slider.kinematics": ("slider_kinematics", "SLIDER"),
    "guide_bar.kinematics": ("slider_kinematics", "GUIDE"),
    "four_bar.instant_centres": ("instant_centres", "FOUR"),
    "crank_slider.instant_centres": ("instant_centres", "SLIDER"),
    "slotter.kinematics": ("slotter_kinematics", "RECIPE"),
}
"""Public recipe name → (module of :mod:`geomcon.recipes`, attribute holding its :class:`Recipe`)."""


class Registry(Mapping[str, Recipe]):
    """A read-only mapping name → :class:`Recipe` that imports a recipe's module on first access.

    Examples
    --------
    >>> reg = Registry({"guide_bar.extremes": ("guide_bar", "RECIPE")})
    >>> list(reg), reg["guide_bar.extremes"].name
    (['guide_bar.extremes'], 'guide_bar.extremes')
    """

    def __init__(self, where: Mapping[str, tuple[str, str]]) -> None:
        self._where = dict(where)
        self._loaded: dict[str, Recipe] = {}

    def __getitem__(self, name: str) -> Recipe:
        recipe = self._loaded.get(name)
        if recipe is None:
            module, attr = self._where[name]
            recipe = getattr(import_module(f"{__name__}.{module}"), attr)
            if recipe.name != name:
                raise AssertionError(f"registry entry {name!r} holds recipe {recipe.name!r}")
            self._loaded[name] = recipe
        return recipe

    def __iter__(self) -> Iterator[str]:
        return iter(self._where)

    def __len__(self) -> int:
        return len(self._where)

    def __contains__(self, name: object) -> bool:
        return name in self._where


RECIPES: Registry = Registry(_WHERE)


def get_recipe(name: str) -> Recipe:
    """The recipe called ``name``; an unknown name raises :class:`ProblemError` listing the known ones."""
    if name not in RECIPES:
        raise ProblemError(f"unknown recipe '{name}' (known: {', '.join(sorted(RECIPES))})")
    return RECIPES[name]


__all__ = ["Construction", "Quantity", "RECIPES", "Recipe", "Registry", "get_recipe"]
