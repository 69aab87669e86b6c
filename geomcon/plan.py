"""Planned solving: the scenes a recipe builds follow the evaluation plan learned by earlier solves."""
from __future__ import annotations

from typing import Any, Callable, TypeVar

from .scene import LeanScenes, PlanMiss
from .scene.scene import _LEAN

T = TypeVar("T")


def planned(plan: str, fn: Callable[..., T], *args: Any) -> T:
    """``fn(*args)`` with the scenes it builds lean and following the evaluation plan ``plan`` (a recipe's
    name); when a scene needs a step the plan left out, ``fn`` runs again with scenes that teach the plan.

    Examples
    --------
    >>> from geomcon.recipes import get_recipe
    >>> r = get_recipe("guide_bar.extremes")
    >>> c = planned(r.name, r.construct, {"AB": 145.0, "AC": 290.0})
    >>> c.scene.lean, round(c.scene.value("theta"), 9)
    (True, 60.0)
    """
    token = _LEAN.set((plan, False))            # LeanScenes(plan), without the object (a solve validates with it)
    try:
        return fn(*args)
    except PlanMiss:
        pass
    finally:
        _LEAN.reset(token)
    with LeanScenes(plan, learn=True):
        return fn(*args)
