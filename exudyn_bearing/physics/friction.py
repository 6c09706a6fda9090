"""Friction coefficient of a lubricated contact and regularised Coulomb friction.

docs/theory/lubrication.md#normal-damping, docs/theory/lubrication.md#film-thickness, docs/theory/tangential.md. mu(Lambda) is the Stribeck-curve fit of the DEM
papers [1]_: mu_boundary (0.1) for Lambda <= lambda_mixed (1), falling
linearly to mu_full_film (0.01) at lambda_full_film (3), constant beyond.

References
----------
.. [1] S. Guessasma and C. Machado, Lubricants 6 (2018) 46.
   doi:10.3390/lubricants6020046
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel, lazy_ufunc

__all__ = ["friction_coefficient", "regularized_coulomb", "sphere_tangential_mass", "implicit_tangential_stiffness"]


@lazy_ufunc("float64(float64, float64, float64, float64, float64)")
def friction_coefficient(film_parameter, mu_boundary, mu_full_film,
                         lambda_mixed, lambda_full_film):
    """mu(Lambda) [-], linear between the breakpoints (docs/theory/lubrication.md#normal-damping).

    Examples
    --------
    >>> friction_coefficient(np.array([0.5, 2.0, 5.0]), 0.1, 0.01, 1.0, 3.0)
    array([0.1  , 0.055, 0.01 ])
    """
    if film_parameter <= lambda_mixed:
        return mu_boundary
    if film_parameter >= lambda_full_film:
        return mu_full_film
    s = (film_parameter - lambda_mixed) / (lambda_full_film - lambda_mixed)
    return mu_boundary + s * (mu_full_film - mu_boundary)


def regularized_coulomb(slip_speed, normal_force, mu, regularizing_speed):
    """History-free friction force magnitude [N]: mu F_n min(|v|/v_reg, 1).

    A linear ramp below the regularising speed v_reg [m/s] (as Exudyn's
    ``frictionProportionalZone``); docs/theory/tangential.md's cheaper alternative
    to the Cundall-Strack spring. The force opposes the slip velocity.
    """
    return mu * np.maximum(normal_force, 0.0) * np.minimum(np.abs(slip_speed) / regularizing_speed, 1.0)


_regularized_coulomb = kernel(regularized_coulomb)


def sphere_tangential_mass(mass):
    """Effective mass [kg] of a free solid sphere for a tangential force at
    its surface: 1/m_t = 1/m + R^2/I with I = 2/5 m R^2, so m_t = m / 3.5
    (rigid-body dynamics of the sphere; the inertia the Cundall-Strack spring
    of docs/theory/tangential.md acts on)."""
    return mass / 3.5


_sphere_tangential_mass = kernel(sphere_tangential_mass)


def implicit_tangential_stiffness(stiffness, dt, tangential_mass):
    """Step-consistent tangential spring K_t / (1 + K_t dt^2 / m_t) [N/m].

    The Cundall-Strack spring (docs/theory/tangential.md) evaluated with the spring
    displacement of the end of the step (backward Euler on the contact-point
    mass m_t): bounded by m_t / dt^2, so the spring sets no step limit, and
    equal to K_t as dt -> 0 (``Scenario(tangential="implicit")``).
    """
    return stiffness / (1.0 + stiffness * dt * dt / tangential_mass)


_implicit_tangential_stiffness = kernel(implicit_tangential_stiffness)
