"""Plane geometry: frozen primitives, constructions, the intersection contract, branch rules, measures."""
from .branch import Above, Ahead, Below, Branch, FarthestFrom, LeftOf, Leftmost, NearestTo, OtherThan, RightOf, Rightmost, ToLeftOf, ToRightOf, Upper
from .construct import (circle, circle_through3, foot, line_through, midpoint, parallel, perpendicular,
                        perpendicular_bisector, point_along, point_on_ray, ray_at_angle, reflect, rotate,
                        rotate_ray, segment, thales_circle)
from .intersect import circle_circle, line_circle, line_line
from .measure import angle_at, angle_between, distance, line_angle, polar_angle, signed_angle, signed_distance
from .primitives import Arc, Circle, Line, Point, Polyline, Ray, Segment

__all__ = [
    "Above", "Ahead", "Arc", "Below", "Branch", "Circle", "FarthestFrom", "LeftOf", "Leftmost", "Line", "NearestTo", "OtherThan",
    "Point", "Polyline", "Ray", "RightOf", "Rightmost", "Segment", "ToLeftOf", "ToRightOf", "Upper", "angle_at", "angle_between", "circle", "circle_circle",
    "circle_through3", "distance", "foot", "line_angle", "line_circle", "line_line", "line_through",
    "midpoint", "parallel", "perpendicular", "perpendicular_bisector", "point_along", "point_on_ray",
    "polar_angle", "ray_at_angle", "reflect", "rotate", "rotate_ray", "segment", "signed_angle",
    "signed_distance", "thales_circle",
]
