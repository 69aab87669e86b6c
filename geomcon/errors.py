"""The error hierarchy: every refusal geomcon makes is a :class:`GeomconError`.

Messages are one line and name the step, file or key and the numbers involved, so that the CLI can print
them as they are (``error: <file>: <message>``) and a user can act on them without a traceback.
"""
from __future__ import annotations


class GeomconError(ValueError):
    """Root of every error geomcon raises on purpose."""


class NoIntersection(GeomconError):
    """Two curves that a construction intersects do not meet."""


class Coincident(GeomconError):
    """Two lines or two circles coincide, so their intersection is not a finite set of points."""


class Degenerate(GeomconError):
    """A primitive cannot be built: a zero-length direction, a zero radius, three collinear points..."""


class AmbiguousBranch(GeomconError):
    """A named branch rule cannot tell two candidate points apart (both lie on its dividing line)."""


class Unbuildable(GeomconError):
    """A construction step failed; the message names the step key, its caption and the cause.

    Parameters
    ----------
    key : str
        The step's key in its scene.
    caption : str
        The step's English caption.
    cause : GeomconError
        The geometric error that stopped the step.
    """

    def __init__(self, key: str, caption: str, cause: Exception) -> None:
        self.key = key
        self.caption = caption
        self.cause = cause
        super().__init__(f"step '{key}' ({caption}): {cause}")


class ProblemError(GeomconError):
    """A problem file or its given values are unusable (unreadable, unknown recipe, bad value...)."""


class NotAMechanism(GeomconError):
    """Given lengths describe no mechanism of the requested kind (e.g. AB is not a crank)."""
