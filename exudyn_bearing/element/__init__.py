"""Exudyn ball-bearing element (imports exudyn)."""
from .builder import BallBearingElement, CreateBallBearing

__all__ = ["BallBearingElement", "CreateBallBearing"]
