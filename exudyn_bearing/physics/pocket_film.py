"""The oil film between a ball and its cage pocket (docs/theory/cage.md#pocket-oil-film).

A ball inside its pocket's clearance is separated from the pocket wall by oil. Two forces of that film push
the ball away from the wall, both rigid-surface, constant-viscosity (isoviscous-rigid) lubrication, since the
pocket's film is thick against the surfaces' elastic deformation at these loads:

* the **hydrodynamic** force of the oil the surfaces drag into the converging gap at the entraining speed u
  (the mean of the two surfaces' speeds relative to the contact). Brewe, Hamrock & Taylor [1]_ fitted the
  minimum film of a rigid ellipsoid on a plane in the isoviscous-rigid regime as

      H_hat = (h / R_x) (W / U)^2 = 128 alpha_r lambda_b^2 [0.131 atan(alpha_r / 2) + 1.683]^2,
      lambda_b = (1 + 2 / (3 alpha_r))^-1,

  with U = eta u / (E' R_x), W = w / (E' R_x^2) and alpha_r = R_y / R_x the ratio of the radii across and
  along the entraining direction (Hamrock, Schmid & Jacobson [2]_, the isoviscous-rigid regime of the
  film-thickness map); solved for the load, w = eta |u| R_x sqrt(H_hat R_x / h), independent of E' as a rigid
  film must be;
* the **squeeze** force of the oil pressed out of the gap when the ball approaches the wall at v = -dh/dt:
  for a sphere of radius R approaching a plane, F = 6 pi eta R^2 v / h, the lubrication limit of Brenner's
  exact solution [3]_ (and of Reynolds' equation for the gap h + r^2 / (2R)). A pocket's wall conforms to
  the ball (a cylindrical pocket in one direction, a spherical one in both), which raises the force; the
  sphere-on-plane value is therefore a lower bound for the pocket, and the kernel uses it. When the ball
  moves away from the wall the film cavitates and carries no tension (half-Sommerfeld): no squeeze force.

Both diverge as h -> 0; the dynamic engines evaluate them at a film no thinner than the surfaces' composite
roughness, where the pocket's Hertz contact takes over (:mod:`exudyn_bearing.model.contact`).

References
----------
.. [1] D. E. Brewe, B. J. Hamrock and C. M. Taylor, "Effect of geometry on hydrodynamic film thickness,"
   J. Lubr. Technol. 101(2) (1979) 231-239. doi:10.1115/1.3453332
.. [2] B. J. Hamrock, S. R. Schmid and B. O. Jacobson, Fundamentals of Fluid Film Lubrication, 2nd ed.,
   Marcel Dekker, 2004 (the film-thickness formulas of the four regimes of fluid-film lubrication, the
   isoviscous-rigid one Brewe, Hamrock & Taylor's).
.. [3] H. Brenner, "The slow motion of a sphere through a viscous fluid towards a plane surface,"
   Chem. Eng. Sci. 16 (1961) 242-251. doi:10.1016/0009-2509(61)80035-3
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel

__all__ = ["isoviscous_rigid_film_constant", "hydrodynamic_film_load", "hydrodynamic_film_force",
           "squeeze_film_force", "squeeze_film_damping", "pocket_film_radii"]


def isoviscous_rigid_film_constant(radius_ratio):
    """H_hat = 128 alpha_r lambda_b^2 [0.131 atan(alpha_r / 2) + 1.683]^2 [-], lambda_b = (1 + 2 / (3
    alpha_r))^-1: the dimensionless minimum film (h / R_x) (W / U)^2 of a rigid ellipsoid on a plane in the
    isoviscous-rigid regime, Brewe, Hamrock & Taylor's fit [1]_ (module docstring); ``radius_ratio``
    alpha_r = R_y / R_x > 0.

    Examples
    --------
    >>> round(float(isoviscous_rigid_film_constant(1.0)), 2)   # a sphere on a plane
    140.11
    """
    a = np.asarray(radius_ratio, float)
    lam = 1.0 / (1.0 + 2.0 / (3.0 * a))
    return 128.0 * a * lam * lam * (0.131 * np.arctan(0.5 * a) + 1.683) ** 2


def hydrodynamic_film_load(viscosity, entraining_speed, r_x, h_hat, film_thickness):
    """w = eta |u| R_x sqrt(H_hat R_x / h) [N]: the load a rigid isoviscous film of minimum thickness h [m]
    carries at the entraining speed u [m/s] (the mean of the surfaces' speeds), R_x [m] the radius along u,
    ``h_hat`` the film constant H_hat of :func:`isoviscous_rigid_film_constant` (Brewe, Hamrock & Taylor [1]_
    solved for the load). ``viscosity`` eta [Pa s]. Scalars or arrays (also compiled: ``_hydrodynamic_film_load``)."""
    return viscosity * np.abs(entraining_speed) * r_x * np.sqrt(h_hat * r_x / film_thickness)


def hydrodynamic_film_force(viscosity, entraining_speed, r_x, radius_ratio, film_thickness):
    """:func:`hydrodynamic_film_load` [N] for the radius ratio ``radius_ratio`` = R_y / R_x."""
    return hydrodynamic_film_load(viscosity, entraining_speed, r_x, isoviscous_rigid_film_constant(radius_ratio),
                                  np.asarray(film_thickness, float))


def squeeze_film_damping(viscosity, radius, film_thickness):
    """C = 6 pi eta R^2 / h [N s/m]: the squeeze film's force per approach speed of a sphere of radius R [m]
    at the gap h [m] from a plane (Brenner's lubrication limit [3]_); ``viscosity`` eta [Pa s]. Scalars or
    arrays (also compiled: ``_squeeze_film_damping``)."""
    return 6.0 * math.pi * viscosity * radius * radius / film_thickness


def squeeze_film_force(viscosity, radius, film_thickness, approach_speed):
    """F = 6 pi eta R^2 v / h [N] for a sphere approaching a plane at v = -dh/dt > 0 [m/s]; 0 when it moves
    away (the film cavitates, half-Sommerfeld). :func:`squeeze_film_damping` times max(v, 0)."""
    return squeeze_film_damping(viscosity, radius, film_thickness) * np.maximum(approach_speed, 0.0)


def pocket_film_radii(ball_radius, pocket_clearance, cylindrical):
    """(R_x [m], alpha_r [-]) of the film between a ball of radius R_b and its pocket wall (radius R_b +
    c_p), the entraining direction taken along a cylindrical pocket's axis, where the wall is straight
    (R_x = R_b, the ball rolling about the bearing's axis; across it the wall conforms, R_y = R_b (R_b +
    c_p) / c_p); a spherical pocket conforms in both directions (R_x = R_y = R_b (R_b + c_p) / c_p)."""
    rb, c = float(ball_radius), float(pocket_clearance)
    conform = rb * (rb + c) / c
    if cylindrical:
        return rb, conform / rb
    return conform, 1.0


_hydrodynamic_film_load = kernel(hydrodynamic_film_load, no_runtime=True, inline="always")
_squeeze_film_damping = kernel(squeeze_film_damping, no_runtime=True, inline="always")
