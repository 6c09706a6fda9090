"""Normal damping of a lubricated contact, switched by the film parameter.

docs/theory/lubrication.md#normal-damping. F_n = K delta^(3/2) + C_n(Lambda) v_n, with

* hysteretic (asperity) damping C_hyst = (3/2) alpha_e K delta^(3/2)
  (Hunt & Crossley [1]_; alpha_e = 0.08 s/m for steel);
* squeeze-film damping C_fluid = (3 pi eta a / sqrt 2) (R_b / h_min)^(3/2)
  (Guessasma & Machado [2]_, a the Hertz semi-major axis);
* Lambda <= 1 boundary: C_hyst; 1 < Lambda <= 3 mixed: the series
  combination C_hyst C_fluid / (C_hyst + C_fluid); Lambda > 3 full film:
  C_fluid. The breakpoints are parameters (``Lubricant.lambda_mixed``,
  ``Lubricant.lambda_full_film``).

References
----------
.. [1] K. H. Hunt and F. R. E. Crossley, "Coefficient of restitution
   interpreted as damping in vibroimpact," J. Appl. Mech. 42(2) (1975)
   440-445. doi:10.1115/1.3423596
.. [2] S. Guessasma and C. Machado, Lubricants 6 (2018) 46.
   doi:10.3390/lubricants6020046
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel, lazy_ufunc

__all__ = [
    "BOUNDARY", "MIXED", "FULL_FILM", "REGIME_NAMES",
    "lubrication_regime",
    "damping_hysteretic",
    "damping_fluid",
    "damping_coefficient",
    "damping_critical",
    "implicit_damping",
]

BOUNDARY, MIXED, FULL_FILM = 0, 1, 2
REGIME_NAMES = ("boundary", "mixed", "full_film")


@lazy_ufunc("int64(float64, float64, float64)")
def lubrication_regime(film_parameter, lambda_mixed, lambda_full_film):
    """Regime code of a contact: 0 boundary (Lambda <= lambda_mixed),
    1 mixed (<= lambda_full_film), 2 full film (docs/theory/lubrication.md#normal-damping).

    Examples
    --------
    >>> lubrication_regime(np.array([0.5, 1.0, 2.0, 3.0, 3.5]), 1.0, 3.0)
    array([0, 0, 1, 1, 2])
    """
    if film_parameter <= lambda_mixed:
        return BOUNDARY
    if film_parameter <= lambda_full_film:
        return MIXED
    return FULL_FILM


def damping_hysteretic(stiffness, overlap, alpha_e):
    """C_hyst = (3/2) alpha_e K delta^(3/2) [N s/m] (Hunt-Crossley [1]_).

    Parameters: K [N/m^1.5], delta [m] (clamped at 0), alpha_e [s/m].
    """
    d = np.maximum(overlap, 0.0)
    return 1.5 * alpha_e * stiffness * d * np.sqrt(d)


def damping_fluid(eta, a, r_ball, h_min):
    """C_fluid = (3 pi eta a / sqrt 2) (R_b / h_min)^(3/2) [N s/m] [2]_.

    Infinite for h_min = 0 (no film: the regime switch then uses C_hyst).
    Parameters: eta [Pa s], a semi-major axis [m], R_b [m], h_min [m].
    """
    x = r_ball / np.maximum(h_min, 1e-300)
    return 3.0 * math.pi * eta * a / math.sqrt(2.0) * x * np.sqrt(x)


_damping_hysteretic = kernel(damping_hysteretic)
_damping_fluid = kernel(damping_fluid)


@lazy_ufunc("float64(float64, float64, float64, float64, float64)")
def damping_coefficient(film_parameter, c_hyst, c_fluid, lambda_mixed, lambda_full_film):
    """Normal damping C_n(Lambda) [N s/m] of docs/theory/lubrication.md#normal-damping (table).

    Examples
    --------
    >>> damping_coefficient(np.array([0.5, 2.0, 4.0]), 10.0, 30.0, 1.0, 3.0)
    array([10. ,  7.5, 30. ])
    """
    if film_parameter <= lambda_mixed:
        return c_hyst
    if film_parameter <= lambda_full_film:
        s = c_hyst + c_fluid
        return c_hyst * c_fluid / s if s > 0.0 else 0.0
    return c_fluid


def damping_critical(effective_mass, tangent_stiffness):
    """Critical damping C = 2 sqrt(m_eff k_t) [N s/m] (docs/theory/lubrication.md#normal-damping,
    ball / cage-ball and cage-ball / guide contacts); k_t = dQ/d delta."""
    return 2.0 * np.sqrt(effective_mass * np.maximum(tangent_stiffness, 0.0))


_damping_critical = kernel(damping_critical)


def implicit_damping(damping, effective_mass, dt):
    """Step-consistent damping coefficient C / (1 + C dt / m) [N s/m].

    Backward Euler of a contact's approach speed u under its own damping,
    m u' = -C u, over one step: u_1 = u_0 / (1 + C dt / m), which the
    coefficient C / (1 + C dt / m) applied to u_0 reproduces
    (``Scenario(cage_damping="implicit")``, docs/theory/dynamics.md#implicit-cage-damping;
    the same construction as the implicit Cundall-Strack spring,
    :func:`~exudyn_bearing.physics.friction.implicit_tangential_stiffness`).
    Equal to C at dt = 0 (bit for bit: the explicit damping) and bounded by
    m / dt: under velocity Verlet a critically damped contact is then stable
    up to 1.58/omega instead of 0.83/omega
    (:func:`exudyn_bearing.model.stability.explicit_step_factor`).

    Examples
    --------
    >>> float(implicit_damping(10.0, 2.0, 0.1))
    6.666666666666667
    """
    return damping / (1.0 + damping * dt / effective_mass)


_implicit_damping = kernel(implicit_damping)
