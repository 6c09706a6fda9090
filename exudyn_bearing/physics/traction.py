"""Traction coefficient of a lubricated ball / race contact: four models.

The traction coefficient mu = tau / p [-] at one point of a contact, from the
local slip speed |v| [m/s], the rolling (entrainment) speed u [m/s], the
local Hertz pressure p [Pa] and the film thickness [m]. The slide-to-roll
ratio is s = |v| / u. The models (their parameters are data:
:class:`exudyn_bearing.data.TractionModel`, the catalogue section
``traction_models``):

* ``constant`` (:func:`traction_constant`): Coulomb mu, optionally linear in
  s below a regularising slide-to-roll ratio s_r (Jones [1]_ assumes a
  constant mu in his race-control analysis);
* ``curve`` (:func:`traction_curve`): mu(s) = (A + B s) exp(-C s) + D, the
  form of the traction-slip relation used in ADORE (Gupta [2]_), rising from
  zero (A = -D) to a maximum and falling to D, as EHL traction does once
  shear heating sets in;
* ``ehl`` (:func:`traction_ehl`): Newtonian film tau_N = eta(p) |v| / h with
  Barus' pressure-viscosity eta = eta_0 exp(xi p) (Hamrock & Dowson [3]_),
  Carreau-type shear thinning tau_e = tau_N (1 + (tau_N/G)^2)^((n-1)/2)
  (Gupta [4]_ eq. 6, after Bair [5]_) and a limiting shear stress
  tau_L = Lambda_L p (Bair & Winer [6]_), joined smoothly by
  tau = tau_e / sqrt(1 + (tau_e/tau_L)^2); isothermal (no falling branch);
* ``lambda`` (:func:`traction_lambda`): the DEM papers' mu(Lambda)
  (Guessasma & Machado [7]_), Lambda = h_min / composite roughness, with the
  Coulomb law of ``constant``.

Compiled use
------------
``_traction(code, params, slip, u_roll, pressure, h_central, h_min)`` is the
scalar numba kernel behind all four (``code`` = index in
:data:`exudyn_bearing.data.TRACTION_KINDS`, ``params`` the float64 array
:attr:`~exudyn_bearing.data.TractionModel.vector`). It allocates nothing and
costs one ``exp`` (curve), ``exp`` + ``log1p`` + ``exp`` + ``sqrt`` (ehl) or
a few comparisons (constant, lambda): it is called once per strip point by
:func:`exudyn_bearing.physics.contact_slip._contact_traction`.

References
----------
.. [1] A. B. Jones, "Ball motion and sliding friction in ball bearings,"
   J. Basic Eng. 81 (1959) 1-12. doi:10.1115/1.4008346
.. [2] P. K. Gupta, Advanced Dynamics of Rolling Elements, Springer, 1984.
.. [3] B. J. Hamrock and D. Dowson, Ball Bearing Lubrication, Wiley, 1981.
.. [4] P. K. Gupta, "Minimum energy hypothesis in quasi-static equilibrium
   solutions for angular contact ball bearings," Tribol. Trans. (2020).
.. [5] S. Bair, High Pressure Rheology for Quantitative Elastohydrodynamics,
   2nd ed., Elsevier, 2019.
.. [6] S. Bair and W. O. Winer, "A rheological model for elastohydrodynamic
   contacts based on primary laboratory data," J. Lubr. Technol. 101 (1979)
   258-265. doi:10.1115/1.3453342
.. [7] S. Guessasma and C. Machado, Lubricants 6 (2018) 46.
   doi:10.3390/lubricants6020046
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel
from ..data import TRACTION_KINDS, TractionModel, get_traction_model

__all__ = ["traction_constant", "traction_curve", "traction_ehl", "traction_lambda", "traction_coefficient",
           "CONSTANT", "CURVE", "EHL", "LAMBDA"]

CONSTANT, CURVE, EHL, LAMBDA = (TRACTION_KINDS.index(k) for k in ("constant", "curve", "ehl", "lambda"))
#: Rolling speed below which the slide-to-roll ratio is taken as |v| / 1e-9 m/s (gross sliding).
_U_MIN = 1e-9


@kernel
def _traction_constant(srr, mu, regularizing_srr):
    if srr <= 0.0:
        return 0.0
    if regularizing_srr > 0.0 and srr < regularizing_srr:
        return mu * srr / regularizing_srr
    return mu


def traction_constant(srr, mu, regularizing_srr=0.0):
    """Coulomb traction coefficient [-]: mu for s > 0 (mu s/s_r below s_r if s_r > 0), 0 at s = 0.

    Jones' race-control analysis assumes this law [1]_.

    Parameters
    ----------
    srr : float or ndarray
        Slide-to-roll ratio s = |v|/u >= 0 [-].
    mu : float
        Friction coefficient [-].
    regularizing_srr : float
        s_r >= 0 [-] (0: pure Coulomb).

    Examples
    --------
    >>> traction_constant(np.array([0.0, 0.005, 0.1]), 0.1, 0.01).tolist()
    [0.0, 0.05, 0.1]
    """
    return np.vectorize(_traction_constant, otypes=[float])(srr, mu, regularizing_srr)


@kernel
def _traction_curve(srr, a, b, c, d):
    return (a + b * srr) * math.exp(-c * srr) + d


def traction_curve(srr, A, B, C, D):
    """Traction-slip curve mu(s) = (A + B s) exp(-C s) + D [-] (the form of ADORE, Gupta [2]_).

    Parameters
    ----------
    srr : float or ndarray
        Slide-to-roll ratio s >= 0 [-].
    A, B, C, D : float
        Curve parameters [-]; A = -D starts the curve at zero, its maximum is
        at s = 1/C - A/B, its large-slip value D.

    Notes
    -----
    d mu/ds = (B - C (A + B s)) exp(-C s) vanishes at s* = 1/C - A/B.

    Examples
    --------
    The catalogue's illustrative ester curve (A = -0.02, B = 2, C = 40, D = 0.02)
    at its maximum s* = 1/40 + 0.01 = 0.035:

    >>> round(float(traction_curve(0.035, -0.02, 2.0, 40.0, 0.02)), 4)
    0.0323
    """
    return np.vectorize(_traction_curve, otypes=[float])(srr, A, B, C, D)


@kernel
def _traction_ehl(slip, pressure, film, viscosity, pressure_viscosity, shear_modulus, exponent, limiting):
    if pressure <= 0.0 or slip <= 0.0:
        return 0.0
    tau_l = limiting * pressure
    if film <= 0.0:
        return limiting
    ln_tn = math.log(viscosity * slip / film) + pressure_viscosity * pressure
    r = math.exp(ln_tn) / shear_modulus
    if r > 1e100:
        ln_fac = 2.0 * (ln_tn - math.log(shear_modulus))
    else:
        ln_fac = math.log1p(r * r)
    tau_e = math.exp(ln_tn + 0.5 * (exponent - 1.0) * ln_fac)
    q = tau_l / tau_e
    return tau_l / math.sqrt(1.0 + q * q) / pressure


def traction_ehl(slip, pressure, film, viscosity, pressure_viscosity, shear_modulus, thinning_exponent,
                 limiting_shear_coefficient):
    """EHL traction coefficient tau/p [-] of a shear-thinning film with a limiting shear stress.

    Newtonian shear stress tau_N = eta_0 exp(xi p) |v| / h (Barus viscosity,
    Hamrock & Dowson [3]_), Carreau-type thinning as Gupta [4]_ eq. 6
    (Bair [5]_), limiting shear stress Lambda_L p (Bair & Winer [6]_).

    Parameters
    ----------
    slip : float or ndarray
        Local slip speed |v| [m/s].
    pressure : float or ndarray
        Local pressure p [Pa].
    film : float or ndarray
        Film thickness h [m] (the central film of the contact).
    viscosity : float
        eta_0 at ambient pressure and the operating temperature [Pa s].
    pressure_viscosity : float
        xi [1/Pa].
    shear_modulus : float
        G, the stress at which thinning sets in [Pa].
    thinning_exponent : float
        n in (0, 1] [-] (1: Newtonian).
    limiting_shear_coefficient : float
        Lambda_L = tau_L / p [-].

    Notes
    -----
    tau_e = tau_N (1 + (tau_N/G)^2)^((n-1)/2),
    tau = tau_e / sqrt(1 + (tau_e/tau_L)^2), tau_L = Lambda_L p; evaluated in
    logarithms so that exp(xi p) cannot overflow. Isothermal: the coefficient
    rises with slip to Lambda_L and does not fall.

    Examples
    --------
    Newtonian film far below the limits: tau = eta v / h exactly (xi = 0):

    >>> round(float(traction_ehl(0.1, 1e9, 1e-6, 1e-3, 0.0, 1e9, 1.0, 0.1)) * 1e9, 6)
    100.0
    """
    return np.vectorize(_traction_ehl, otypes=[float])(slip, pressure, film, viscosity, pressure_viscosity,
                                                       shear_modulus, thinning_exponent,
                                                       limiting_shear_coefficient)


@kernel
def _traction_lambda(srr, film_min, mu_b, mu_f, lam1, lam3, roughness, regularizing_srr):
    lam = film_min / roughness
    if lam <= lam1:
        mu = mu_b
    elif lam >= lam3:
        mu = mu_f
    else:
        mu = mu_b + (lam - lam1) / (lam3 - lam1) * (mu_f - mu_b)
    return _traction_constant(srr, mu, regularizing_srr)


def traction_lambda(srr, film_min, mu_boundary, mu_full_film, lambda_mixed, lambda_full_film,
                    composite_roughness, regularizing_srr=0.0):
    """The DEM papers' Coulomb coefficient mu(Lambda) [-] (Guessasma & Machado [7]_).

    Lambda = h_min / composite roughness; mu_boundary up to lambda_mixed,
    linear to mu_full_film at lambda_full_film, constant beyond; applied as
    :func:`traction_constant` with that mu.

    Examples
    --------
    Lambda = 2, halfway between 0.1 and 0.01:

    >>> round(float(traction_lambda(0.05, 7.5e-7, 0.1, 0.01, 1.0, 3.0, 3.75e-7)), 3)
    0.055
    """
    return np.vectorize(_traction_lambda, otypes=[float])(srr, film_min, mu_boundary, mu_full_film, lambda_mixed,
                                                          lambda_full_film, composite_roughness,
                                                          regularizing_srr)


@kernel(inline="always", no_runtime=True)
def _inverse_rolling_speed(u_roll):
    """1 / max(|u|, 1e-9 m/s): the factor from slip speed to slide-to-roll ratio."""
    u = abs(u_roll)
    return 1.0 / (u if u > _U_MIN else _U_MIN)


@kernel(inline="always", no_runtime=True)
def _traction(code, params, slip, u_roll, pressure, h_central, h_min):
    """Traction coefficient mu = tau/p [-] of model ``code`` with parameter vector ``params``.

    slip |v| [m/s] >= 0, u_roll [m/s] (its magnitude is used), pressure p [Pa],
    central and minimum film thickness [m]. No allocation.
    """
    return _traction_srr(code, params, slip, slip * _inverse_rolling_speed(u_roll), pressure, h_central, h_min)


@kernel(inline="always", no_runtime=True)
def _traction_srr(code, params, slip, srr, pressure, h_central, h_min):
    """:func:`_traction` with the slide-to-roll ratio already formed (the strip loop forms
    1/u once per contact)."""
    if code == CURVE:
        if slip <= 0.0:
            return 0.0
        return _traction_curve(srr, params[0], params[1], params[2], params[3])
    if code == EHL:
        return _traction_ehl(slip, pressure, h_central, params[0], params[1], params[2], params[3], params[4])
    if code == LAMBDA:
        return _traction_lambda(srr, h_min, params[0], params[1], params[2], params[3], params[4], params[5])
    return _traction_constant(srr, params[0], params[1])


def traction_coefficient(model, slip, rolling_speed, pressure=0.0, film_central=0.0, film_min=0.0):
    """Traction coefficient [-] of a catalogue or custom :class:`TractionModel`.

    Parameters
    ----------
    model : TractionModel or str
        The model or its catalogue name.
    slip, rolling_speed : float or ndarray
        |v| and u [m/s].
    pressure : float or ndarray
        Local pressure [Pa] (``ehl``).
    film_central, film_min : float or ndarray
        Film thickness [m]: central (``ehl``) and minimum (``lambda``).

    Examples
    --------
    >>> round(float(traction_coefficient("ester_curve_illustrative", 0.035, 1.0)), 4)
    0.0323
    """
    m: TractionModel = get_traction_model(model)
    code, vec = m.code, m.vector
    f = np.vectorize(lambda v, u, p, hc, hm: _traction(code, vec, v, u, p, hc, hm), otypes=[float])
    return f(slip, rolling_speed, pressure, film_central, film_min)
