"""Exudyn ball-bearing element (imports exudyn). Users create it with
:func:`exudyn_bearing.CreateBallBearing`, which adds ``results()``."""
from .element import BallBearingElement

__all__ = ["BallBearingElement"]
