"""Elastohydrodynamic film thickness and the film parameter Lambda.

docs/theory/lubrication.md#film-thickness. Dimensionless groups with the rolling (entrainment)
speed u_r [m/s], the effective radius in the rolling direction R_x [m], the
effective modulus E' [Pa], viscosity eta [Pa s], pressure-viscosity
coefficient xi [m^2/N] and contact load Q [N]:

    U = eta u_r / (E' R_x),   G = xi E',   W = Q / (E' R_x^2)

Every function here is plain arithmetic on scalars or numpy arrays, and is
also compiled with ``numba.njit(cache=True)`` under the same name with a
leading underscore for the simulation kernels (one implementation).
A zero rolling speed or zero load gives h_min = 0 (boundary lubrication).

References
----------
.. [1] B. J. Hamrock and D. Dowson, "Isothermal elastohydrodynamic
   lubrication of point contacts, Part III - Fully flooded results,"
   J. Lubr. Technol. 99(2) (1977) 264-275. doi:10.1115/1.3453074
.. [2] M. Masjedi and M. M. Khonsari, "On the effect of surface roughness in
   point-contact EHL: Formulas for film thickness and asperity load,"
   Tribol. Int. 82 (2015) 228-244. doi:10.1016/j.triboint.2014.09.010
.. [3] S. Guessasma and C. Machado, Lubricants 6 (2018) 46.
   doi:10.3390/lubricants6020046
"""
from __future__ import annotations

import numpy as np
from numba.extending import register_jitable

from .._jit import kernel

__all__ = [
    "FILM_MODELS",
    "film_model_code",
    "film_thickness",
    "film_thickness_hamrock_dowson",
    "film_thickness_masjedi_khonsari",
    "film_thickness_central_hamrock_dowson",
    "film_parameter",
]

#: Film-thickness models in the order of their kernel codes.
FILM_MODELS = ("hd", "mk")
HAMROCK_DOWSON, MASJEDI_KHONSARI = 0, 1


def film_model_code(film) -> int:
    """Integer kernel code of a film model name ('hd' or 'mk')."""
    aliases = {"hd": 0, "hamrock_dowson": 0, "mk": 1, "masjedi_khonsari": 1}
    if isinstance(film, (int, np.integer)) and int(film) in (0, 1):
        return int(film)
    try:
        return aliases[str(film).lower()]
    except KeyError:
        raise ValueError(f"film: unknown film model {film!r} (valid: hd, mk)") from None


def film_thickness_hamrock_dowson(u_r, load, r_x, kappa, e_prime, eta, xi):
    """Minimum film thickness h_min [m], Hamrock & Dowson [1]_.

    h_min = 3.63 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.68 k)) R_x
    (docs/theory/lubrication.md#film-thickness, the default film model).

    Parameters
    ----------
    u_r : float or ndarray
        Rolling (entrainment) speed [m/s], mean of the two surface speeds
        relative to the contact; its magnitude is used.
    load : float or ndarray
        Contact load Q [N].
    r_x : float or ndarray
        Effective radius in the rolling direction [m].
    kappa : float or ndarray
        Ellipticity k = a/b [-].
    e_prime : float
        Effective modulus E' [Pa].
    eta : float
        Viscosity [Pa s].
    xi : float
        Pressure-viscosity coefficient [m^2/N].

    Returns
    -------
    h_min : float or ndarray [m]; 0 where u_r = 0 or Q <= 0.

    Examples
    --------
    6208 outer contact at 500 rad/s, Q = 1457 N (docs/theory/reference_cases.md expects
    Lambda_out about 2.15, i.e. h_min about 0.8 um):

    >>> h = film_thickness_hamrock_dowson(7.2475, 1457.0, 7.61e-3, 7.29, 230.77e9, 0.04, 2.3e-8)
    >>> round(float(h) * 1e6, 2)
    0.8
    """
    return film_hd_ln_g(u_r, load, r_x, kappa, e_prime, eta, np.log(xi * e_prime))


def film_hd_ln_g(u_r, load, r_x, kappa, e_prime, eta, ln_g):
    """:func:`film_thickness_hamrock_dowson` with the material parameter
    given by its logarithm, ln_g = ln G = ln(xi E'): a constant of the scene,
    which the simulation kernels compute once per force evaluation instead of
    once per contact."""
    # evaluated as exp(sum of logs): the same formula with fewer transcendental calls
    return film_hd_ln_g_k(u_r, load, r_x, film_hd_ellipticity_factor(kappa), e_prime, eta, ln_g)


#: The decay rate 0.68 of the Hamrock-Dowson film's ellipticity factor 1 - exp(-0.68 k).
HD_ELLIPTICITY_DECAY = 0.68


def film_hd_ellipticity_factor(kappa):
    """The ellipticity factor 1 - exp(-0.68 k) of :func:`film_thickness_hamrock_dowson` [-]."""
    return 1.0 - np.exp(-HD_ELLIPTICITY_DECAY * kappa)


def film_hd_ln_g_k(u_r, load, r_x, factor_k, e_prime, eta, ln_g):
    """:func:`film_hd_ln_g` with its ellipticity factor given
    (:func:`film_hd_ellipticity_factor`), which the contact kernel keeps with
    the Hertz constants of a contact (a function of k only)."""
    u, w = film_groups(u_r, load, r_x, e_prime, eta)
    on = (load > 0.0) * (u_r != 0.0)  # no load or no rolling: no film
    return on * film_hd_from_exponent(np.exp(film_hd_exponent(np.log(u), np.log(w), ln_g)), factor_k, r_x)


@register_jitable  # callable from compiled code too: film_hd_ln_g_k and the contact kernel share it
def film_groups(u_r, load, r_x, e_prime, eta):
    """The dimensionless speed U = eta |u_r| / (E' R_x) and load W = Q / (E' R_x^2) of the film relations,
    each at least 1e-300 (their logarithms stay finite; the relations switch the film off at zero speed
    or load)."""
    c = 1.0 / (e_prime * r_x)  # U = eta u_r c, W = Q E' c^2: one division, off the kernels' chain of u_r and Q
    return np.maximum(eta * np.abs(u_r) * c, 1e-300), np.maximum(load, 1e-300) * (e_prime * c * c)


@register_jitable  # callable from compiled code too: film_hd_ln_g_k and the contact kernel share it
def film_hd_exponent(ln_u, ln_w, ln_g):
    """The exponent E = 0.68 ln U + 0.49 ln G - 0.073 ln W of :func:`film_thickness_hamrock_dowson`
    (h_min = 3.63 exp(E) (1 - exp(-0.68 k)) R_x) from the logarithms of the groups [-]."""
    return 0.68 * ln_u + 0.49 * ln_g - 0.073 * ln_w


@register_jitable  # callable from compiled code too: film_hd_ln_g_k and the contact kernel share it
def film_hd_from_exponent(exp_e, factor_k, r_x):
    """h_min = 3.63 exp(E) (1 - exp(-0.68 k)) R_x [m] of :func:`film_thickness_hamrock_dowson` from
    exp(E) (:func:`film_hd_exponent`), the ellipticity factor (:func:`film_hd_ellipticity_factor`)
    and R_x; the contact kernel evaluates exp(E) and the logarithms from per-contact anchors
    (``model.contact._exp_anchored``)."""
    return 3.63 * exp_e * factor_k * r_x


def film_thickness_masjedi_khonsari(u_r, load, r_x, kappa, e_prime, eta, xi):
    """Minimum film thickness h_min [m], a reading of Masjedi & Khonsari [2]_.

    The smooth-surface minimum-film fit as the digital-twin DEM paper prints
    it, h_min/R_x = 1.637 U^(0.711k - 0.023) G^(0.65k - 0.045)
    W^(-0.09k - 0.15) (1 - 0.974 exp(-0.676 k)), cannot be meant literally:
    with k about 9 the speed exponent would be about 6.4 and h_min near
    zero. Each of the three exponents has the pattern "a k - b", read here
    as a lost superscript, a k^-b::

        h_min / R_x = 1.637 U^(0.711 k^-0.023) G^(0.65 k^-0.045)
                      W^(-0.09 k^-0.15) (1 - 0.974 exp(-0.676 k))

    (an earlier version read the load exponent as -0.09 k^+0.15, which
    breaks the pattern). Theory and numbers:
    docs/theory/lubrication.md#masjedi-khonsari-reading.

    Parameters as :func:`film_thickness_hamrock_dowson`.

    Examples
    --------
    Speed and load exponents at the 6208 outer contact (k = 7.2486), fitted
    from the function itself; the reading predicts 0.711 k^-0.023 and
    -0.09 k^-0.15:

    >>> k, e_p = 7.2486, 230.77e9
    >>> h = lambda u, q: float(film_thickness_masjedi_khonsari(u, q, 7.61e-3, k, e_p, 0.04, 2.3e-8))
    >>> round(float(np.log10(h(10.0, 1457.0) / h(1.0, 1457.0))), 4)
    0.6793
    >>> round(float(np.log10(h(7.25, 5000.0) / h(7.25, 500.0))), 4)
    -0.0669
    """
    return film_mk_ln_g(u_r, load, r_x, kappa, e_prime, eta, np.log(xi * e_prime))


def film_mk_ln_g(u_r, load, r_x, kappa, e_prime, eta, ln_g):
    """:func:`film_thickness_masjedi_khonsari` with ln_g = ln(xi E') given
    (as :func:`film_hd_ln_g`)."""
    c = 1.0 / (e_prime * r_x)  # U = eta u_r c, W = Q E' c^2: one division, off the kernels' chain of u_r and Q
    ln_u = np.log(np.maximum(eta * np.abs(u_r) * c, 1e-300))
    ln_w = np.log(np.maximum(load, 1e-300) * (e_prime * c * c))
    ln_k = np.log(kappa)
    on = (load > 0.0) * (u_r != 0.0)
    return on * (1.637 * np.exp(0.711 * np.exp(-0.023 * ln_k) * ln_u
                                + 0.65 * np.exp(-0.045 * ln_k) * ln_g
                                - 0.09 * np.exp(-0.15 * ln_k) * ln_w)
                 * (1.0 - 0.974 * np.exp(-0.676 * kappa)) * r_x)


def film_thickness_central_hamrock_dowson(u_r, load, r_x, kappa, e_prime, eta, xi):
    """Central film thickness h_c [m], Hamrock & Dowson [1]_.

    h_c = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k)) R_x, the film
    over the flat part of the contact that carries the shear of the traction
    models (:mod:`exudyn_bearing.physics.traction`). Parameters as
    :func:`film_thickness_hamrock_dowson`.

    Examples
    --------
    The 6208 outer contact of :func:`film_thickness_hamrock_dowson` (h_c above h_min):

    >>> h = film_thickness_central_hamrock_dowson(7.2475, 1457.0, 7.61e-3, 7.29, 230.77e9, 0.04, 2.3e-8)
    >>> round(float(h) * 1e6, 2)
    0.99
    """
    c = 1.0 / (e_prime * r_x)  # U = eta u_r c, W = Q E' c^2: one division, off the kernels' chain of u_r and Q
    ln_u = np.log(np.maximum(eta * np.abs(u_r) * c, 1e-300))
    ln_w = np.log(np.maximum(load, 1e-300) * (e_prime * c * c))
    on = (load > 0.0) * (u_r != 0.0)
    return on * (2.69 * np.exp(0.67 * ln_u + 0.53 * np.log(xi * e_prime) - 0.067 * ln_w)
                 * (1.0 - 0.61 * np.exp(-0.73 * kappa)) * r_x)


_film_central_hd = kernel(film_thickness_central_hamrock_dowson)


_film_hd_ln_g_k = kernel(film_hd_ln_g_k)


_film_hd_ellipticity_factor = kernel(film_hd_ellipticity_factor)


@kernel
def _film_hd_ln_g(u_r, load, r_x, kappa, e_prime, eta, ln_g):
    """Kernel of :func:`film_hd_ln_g`."""
    return _film_hd_ln_g_k(u_r, load, r_x, _film_hd_ellipticity_factor(kappa), e_prime, eta, ln_g)
_film_mk_ln_g = kernel(film_mk_ln_g)


@kernel
def _film_thickness_ln_g(model, u_r, load, r_x, kappa, e_prime, eta, ln_g):
    """Kernel dispatch on the film model code (0 HD, 1 MK); ln_g = ln(xi E')
    (:func:`film_hd_ln_g`)."""
    if model == MASJEDI_KHONSARI:
        return _film_mk_ln_g(u_r, load, r_x, kappa, e_prime, eta, ln_g)
    return _film_hd_ln_g(u_r, load, r_x, kappa, e_prime, eta, ln_g)


@kernel
def _film_thickness_ln_g_k(model, u_r, load, r_x, kappa, factor_k, e_prime, eta, ln_g):
    """:func:`_film_thickness_ln_g` with the HD ellipticity factor given
    (``factor_k`` = :func:`film_hd_ellipticity_factor` of ``kappa``; a
    negative value: not given, computed here; MK ignores it)."""
    if model == MASJEDI_KHONSARI or factor_k < 0.0:
        return _film_thickness_ln_g(model, u_r, load, r_x, kappa, e_prime, eta, ln_g)
    return _film_hd_ln_g_k(u_r, load, r_x, factor_k, e_prime, eta, ln_g)


@kernel
def _film_thickness(model, u_r, load, r_x, kappa, e_prime, eta, xi):
    """Kernel dispatch on the film model code (0 HD, 1 MK)."""
    return _film_thickness_ln_g(model, u_r, load, r_x, kappa, e_prime, eta, np.log(xi * e_prime))


def film_thickness(u_r, load, r_x, kappa, e_prime, eta, xi, film="hd"):
    """h_min [m] with the model named by ``film`` ('hd' default, or 'mk')."""
    if film_model_code(film) == MASJEDI_KHONSARI:
        return film_thickness_masjedi_khonsari(u_r, load, r_x, kappa, e_prime, eta, xi)
    return film_thickness_hamrock_dowson(u_r, load, r_x, kappa, e_prime, eta, xi)


def film_parameter(h_min, composite_roughness):
    """Film parameter Lambda = h_min / (c sqrt(sigma_1^2 + sigma_2^2)) [-].

    docs/theory/lubrication.md#film-thickness [3]_: with c = 1.25, sigma_race = 3e-7 m and smooth
    balls the denominator is 3.75e-7 m (``Lubricant.composite_roughness``).

    Examples
    --------
    >>> film_parameter(7.5e-7, 3.75e-7)
    2.0
    """
    return h_min / composite_roughness


_film_parameter = kernel(film_parameter)
