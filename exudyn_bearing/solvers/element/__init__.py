"""Exudyn ball-bearing element (imports exudyn). Users create it with
:func:`exudyn_bearing.CreateBallBearing`, which adds ``results()``;
:func:`filter_exudyn_notes` keeps Exudyn's known-benign notes off the console."""
from .console import filter_exudyn_notes
from .element import BallBearingElement

__all__ = ["BallBearingElement", "filter_exudyn_notes"]
