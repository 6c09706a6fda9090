"""Bearing levels without ball DOFs for Exudyn: the quasi-static solver's
physics as force elements between two ring markers.

* :class:`~.element.QuasiStaticBearing` (``model="quasistatic"``): at every
  evaluation the quasi-static ball equilibrium (:mod:`..balls`: exact groove
  geometry, Hertz at every ball's current azimuth, tilt, centrifugal and
  gyroscopic loads, ring growth at the current speed) for the rings'
  relative pose, with the balls advanced by the kinematic cage angle, plus
  the contact damping of those balls' state (:mod:`..damping`);
* :class:`~.linear.LinearBearing` (``model="linear"``): the 5x5 stiffness
  and damping of :func:`..coefficients.bearing_coefficients` interpolated in
  the current speed, about the operating point they were computed at.

The linear level is an ``ObjectConnectorRigidBodySpringDamper`` connector with a
``springForceTorqueUserFunction`` (one compiled call per evaluation), which
Exudyn's implicit solvers run with the connector's numerical Jacobian; so is
the quasi-static level with ``formulation="connector"``. Its default node
formulation (:mod:`.nodes`) is an ``ObjectGenericODE2`` on the ring nodes with
the level's own Jacobian, one call for the bearings between the same nodes.
They live in the quasi-static solver's package because they evaluate its
ball equilibrium and coefficient tables (no solver imports another).
The entry point is :func:`exudyn_bearing.CreateBallBearing` (``model=``).
Theory: docs/theory/levels.md.
"""
from .base import LEVEL_OPTIONS, LevelBearing
from .element import QuasiStaticBearing
from .linear import LinearBearing

__all__ = ["LEVEL_OPTIONS", "LevelBearing", "LinearBearing", "QuasiStaticBearing"]
