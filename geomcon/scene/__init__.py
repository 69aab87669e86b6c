"""Scenes: lazy construction DAGs of steps with explicit references."""
from .marks import AngleMark, Dimension, Ground, Guide, RightAngleMark, Slider
from .scene import LeanScenes, PlanMiss, Scene, lean_scenes
from .step import Ref, Role, Step

__all__ = ["AngleMark", "Dimension", "Ground", "Guide", "LeanScenes", "PlanMiss", "Ref", "RightAngleMark", "Role", "Scene", "Slider", "Step", "lean_scenes"]
