"""The azimuth of a bearing's radial load (``loadAngle``), shared by the ball element and the bearing levels."""
from __future__ import annotations

import math

import numpy as np

from ..data.errors import check_plausible

__all__ = ["LOAD_ANGLE_RANGE", "check_load_angle", "load_rotation"]

#: ``loadAngle`` [rad] is accepted in [-LOAD_ANGLE_RANGE, LOAD_ANGLE_RANGE] (one turn either way)
LOAD_ANGLE_RANGE = 2.0 * math.pi


def check_load_angle(value) -> float:
    """``loadAngle`` [rad] of every level and the ball element: finite, within one turn either way
    (a value in degrees beyond that says so)."""
    return check_plausible("loadAngle", value, -LOAD_ANGLE_RANGE, LOAD_ANGLE_RANGE, "rad",
                           "the azimuth of the radial load is in radians", ((math.radians, "deg"),))


def load_rotation(angle) -> np.ndarray:
    """3x3 rotation about the bearing axis z by ``angle`` [rad]: from the solvers' axes (radial load along
    +x) to the outer-ring frame where the radial load points at ``loadAngle``."""
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
