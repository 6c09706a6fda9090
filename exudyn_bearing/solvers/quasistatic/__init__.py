"""Quasi-static ball-bearing solver (Jones / Harris equilibrium, race control
or Gupta's minimum-energy kinematics, rings grown by speed and temperature).

Modules, each one step: :mod:`.geometry` (grooves at the operating point),
:mod:`.balls` (compiled ball equilibrium and ring forces), :mod:`.ring`
(5-DOF inner-ring equilibrium), :mod:`.kinematics` (race control, minimum
energy, slip and dissipation), :mod:`.stiffness` (5x5 stiffness matrix),
:mod:`.damping` (the contacts' normal damping and the 5x5 damping matrix),
:mod:`.solution` (the record and its JSON), :mod:`.solve`
(:func:`solve_quasistatic`), :mod:`.coefficients` (stiffness and damping over
speeds, :func:`bearing_coefficients`). Theory: docs/theory/quasistatic.md,
docs/theory/vibration.md.
"""
from .solution import UNITS, QuasiStaticSolution
from .solve import beta_scan, solve_quasistatic
from .coefficients import bearing_coefficients

__all__ = ["solve_quasistatic", "beta_scan", "bearing_coefficients", "QuasiStaticSolution", "UNITS"]
