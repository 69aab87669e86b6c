"""Boxes against filled discs (a point's marker), many pairs at once, in closed form: the distance between them
and the area they share.

A marker is drawn as a circle and handed to the label placer as the 32-gon GEOS buffers a point into
(:func:`.shapes.disc_polygon`); the placer measures it as the circle it stands for (:func:`discs` finds them),
one pair a box instead of 32 box–side pairs. The distance from a box to a disc is that from the box to its
centre less the radius (0 when they meet); the area they share is the integral over x of the disc's chord
clipped to the box (:func:`box_disc_area`). A box is ``x0 ≤ x ≤ x1, y0 ≤ y ≤ y1``; a turned box is measured in
its own frame (the disc's centre turned back about the box's: a disc looks the same turned).

Examples
--------
>>> d, area = box_disc(np.array([0.0, 0.0]), np.array([0.0, 0.0]), np.array([4.0, 4.0]), np.array([2.0, 2.0]),
...                    np.array([7.0, 4.0]), np.array([1.0, 1.0]), np.array([1.0, 1.0]))
>>> d.tolist(), np.round(area, 12).tolist()          # 2 mm beside one; over half of the other
([2.0, 0.0], [0.0, 1.570796326795])
"""
from __future__ import annotations

import math

import numpy as np
import shapely

from .shapes import _ROUND

SIDES = len(_ROUND) - 1
"""Corners of a disc's polygon (:func:`.shapes.disc_polygon`: 8 a quadrant)."""


def discs(geoms: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Which of ``geoms`` (an object array) are discs as :func:`.shapes.disc_polygon` (GEOS's ``buffer(r, 8)``)
    makes them, and their centres and radii: a polygon without holes whose 32 corners lie, to 1e-9 of its size,
    at ``c + r · (cos, sin)`` of GEOS's angles in GEOS's order (the centre read off the corners at angle 0 and
    −90°, which GEOS computes exactly).

    >>> i, cx, cy, r = discs(np.array([shapely.Point(3.0, 4.0).buffer(0.5, 8), shapely.box(0, 0, 1, 1)]))
    >>> i.tolist(), cx.tolist(), cy.tolist(), r.tolist()
    ([0], [3.0], [4.0], [0.5])
    """
    z = np.zeros(0)
    if not len(geoms):
        return np.zeros(0, dtype=np.intp), z, z, z
    cand = np.flatnonzero((shapely.get_type_id(geoms) == 3) & (shapely.get_num_coordinates(geoms) == SIDES + 1))
    if len(cand):
        cand = cand[shapely.get_num_interior_rings(geoms[cand]) == 0]
    if not len(cand):
        return cand, z, z, z
    xy = shapely.get_coordinates(geoms[cand]).reshape(len(cand), SIDES + 1, 2)
    cx, cy = xy[:, SIDES // 4, 0], xy[:, 0, 1]
    r = xy[:, 0, 0] - cx
    want = np.stack([cx, cy], axis=1)[:, None, :] + r[:, None, None] * _ROUND[None, :, :]
    size = 1.0 + np.abs(cx) + np.abs(cy) + np.abs(r)
    ok = (r > 0.0) & (np.abs(xy - want).max(axis=(1, 2)) <= 1e-9 * size)
    return cand[ok], cx[ok], cy[ok], r[ok]


def _chord_integral(u: np.ndarray, r: np.ndarray) -> np.ndarray:
    """∫₀ᵘ √(r² − t²) dt for −r ≤ u ≤ r: half of u·√(r² − u²) + r²·asin(u / r)."""
    root = np.sqrt(np.maximum(r * r - u * u, 0.0))
    return 0.5 * (u * root + r * r * np.arcsin(np.clip(u / r, -1.0, 1.0)))


def _quadrant(x: np.ndarray, y: np.ndarray, r: np.ndarray) -> np.ndarray:
    """∫ from −r to x of clip(y, −h(t), h(t)) dt, h(t) = √(r² − t²): the disc (centre 0) below the height y,
    less that above −y, left of x. Where |t| ≥ w = √(r² − y²) the chord is clipped to ±h(t), between to y
    (the three integrals of h in one call: a few numpy calls for every corner of every pair)."""
    x = np.clip(x, -r, r)
    y = np.clip(y, -r, r)
    w = np.sqrt(np.maximum(r * r - y * y, 0.0))
    n = len(x)
    h = _chord_integral(np.concatenate([np.minimum(x, -w), np.maximum(x, w), w]), np.concatenate([r, r, r]))
    left = h[:n] + 0.25 * math.pi * r * r              # ∫ from −r: less the integral to −r, −πr²/4
    right = h[n:2 * n] - h[2 * n:]
    return np.sign(y) * (left + right) + y * (np.clip(x, -w, w) + w)


def box_disc_area(x0, y0, x1, y1, cx, cy, r) -> np.ndarray:
    """Area each box shares with each disc (arrays of one length): the four corners' :func:`_quadrant` in
    one call.

    >>> box_disc_area(*[np.array([v]) for v in (-2.0, -2.0, 2.0, 2.0, 0.0, 0.0, 1.0)]).tolist() == [math.pi]
    True
    >>> np.round(box_disc_area(*[np.array([v]) for v in (0.0, 0.0, 5.0, 5.0, 0.0, 0.0, 2.0)]), 12).tolist()
    [3.14159265359]
    """
    ax0, ax1, ay0, ay1 = x0 - cx, x1 - cx, y0 - cy, y1 - cy
    n = len(ax0)
    q = _quadrant(np.concatenate([ax1, ax0, ax1, ax0]), np.concatenate([ay1, ay1, ay0, ay0]), np.tile(r, 4))
    area = (q[:n] - q[n:2 * n]) - (q[2 * n:3 * n] - q[3 * n:])
    return np.maximum(area, 0.0)


def box_disc(x0, y0, x1, y1, cx, cy, r) -> tuple[np.ndarray, np.ndarray]:
    """Distance from each box to each disc (0 where they meet) and the area they share (0 where they do not)."""
    gx = np.maximum(np.maximum(x0 - cx, cx - x1), 0.0)
    gy = np.maximum(np.maximum(y0 - cy, cy - y1), 0.0)
    apart = np.sqrt(gx * gx + gy * gy) - r
    area = np.zeros(len(apart))
    hit = np.flatnonzero(apart <= 0.0)
    if len(hit):
        area[hit] = box_disc_area(x0[hit], y0[hit], x1[hit], y1[hit], cx[hit], cy[hit], r[hit])
    return np.maximum(apart, 0.0), area


def disc_gap(box: shapely.Geometry, cx: float, cy: float, r: float) -> tuple[float, float]:
    """The distance from a box (a shapely rectangle, turned or not) to a disc by GEOS (to its centre, less the
    radius: negative when they meet), and the area they share in closed form (the box in its own frame): the
    definition :func:`box_disc` follows, one pair at a time.

    >>> disc_gap(shapely.box(0.0, 0.0, 4.0, 2.0), 7.0, 1.0, 1.0)
    (2.0, 0.0)
    """
    apart = float(shapely.distance(box, shapely.Point(cx, cy))) - r
    if apart > 0.0:
        return apart, 0.0
    xy = shapely.get_coordinates(box)[:4]
    mx, my = xy.mean(axis=0).tolist()
    ex, ey = (xy[1] - xy[0]).tolist()
    fx, fy = (xy[2] - xy[1]).tolist()
    a, b = math.hypot(ex, ey), math.hypot(fx, fy)
    ux, uy = ex / a, ey / a
    px, py = cx - mx, cy - my                           # the centre in the box's frame (sides a along u, b across)
    u, v = px * ux + py * uy, py * ux - px * uy
    one = [np.array([t]) for t in (-a / 2, -b / 2, a / 2, b / 2, u, v, r)]
    return apart, float(box_disc_area(*one)[0])
