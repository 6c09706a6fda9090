"""Elliptic Hertz point contact (ball / raceway) and sphere / sphere contact.

docs/theory/hertz.md. Three interchangeable fidelity levels for the ellipticity
k = a/b and the complete elliptic integrals F (first kind) and E (second kind):

* ``"exact"`` (level 1): k solved from the exact Hertz relation with complete
  elliptic integrals (computed by the arithmetic-geometric mean, checked
  against ``scipy.special.ellipk/ellipe`` in the tests), the reference;
* ``"hamrock_brewe"`` (level 2): the Hamrock-Brewe curve fits;
* ``"simplified"`` (level 3): the fits of the DEM papers, with the corrected
  F = pi/2 + (pi/2 - 1) ln a_r (both papers print 1 + ..., a typo).

Errors of the fits against level 1 for 1 <= R_y/R_x <= 40 (the ball-bearing
range; measured and asserted by ``tests/test_hertz.py``):

===============  =====  =====  =====  =====  =====
level            K      k      a      b      p_max
===============  =====  =====  =====  =====  =====
hamrock_brewe    9 %    3.5 %  3 %    1 %    2.5 %
simplified       4 %    4 %    3 %    1.5 %  2 %
===============  =====  =====  =====  =====  =====

(Hamrock-Brewe's largest K error is at the circular limit R_y = R_x, where
its F fit gives 1.528 instead of pi/2.)

Scalar kernels (``_name``) are ``numba.njit(cache=True)`` and shared by both
simulation engines; the public functions broadcast over numpy arrays.

Nomenclature (docs/theory/hertz.md -> argument): R_x -> ``r_x``, R_y -> ``r_y``,
E' -> ``e_prime``, Q -> ``load``, delta -> ``overlap``, k -> ``kappa``,
F -> ``ell_f``, E -> ``ell_e``.

References
----------
.. [1] B. J. Hamrock and D. E. Brewe, "Simplified solution for stresses and
   deformations," J. Lubr. Technol. 105(2) (1983) 171-177. doi:10.1115/1.3254558
.. [2] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed.,
   CRC Press, 2006, ch. 6.
.. [3] S. Guessasma and C. Machado, "Three-Dimensional DEM Modelling of Ball
   Bearing with Lubrication Regime Prediction," Lubricants 6 (2018) 46.
   doi:10.3390/lubricants6020046
.. [4] K. L. Johnson, Contact Mechanics, Cambridge University Press, 1985, ch. 4.
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .._jit import kernel

__all__ = [
    "METHODS",
    "method_code",
    "reduced_modulus",
    "material_reduced_modulus",
    "complete_elliptic_integrals",
    "ellipticity",
    "curvature_sum_radius",
    "hertz_stiffness",
    "contact_ellipse",
    "hertz_contact",
    "HertzContact",
    "sphere_sphere_stiffness",
    "tangent_stiffness",
    "exact_table",
]

#: Fidelity levels, in the order of their integer codes used by the kernels.
METHODS = ("exact", "hamrock_brewe", "simplified")
EXACT, HAMROCK_BREWE, SIMPLIFIED = 0, 1, 2
_HALF_PI = 0.5 * math.pi


def method_code(method) -> int:
    """Integer code of a fidelity level name (or pass an int through)."""
    if isinstance(method, (int, np.integer)) and 0 <= int(method) < len(METHODS):
        return int(method)
    try:
        return METHODS.index(method)
    except ValueError:
        raise ValueError(f"method: unknown Hertz method {method!r} (valid: {', '.join(METHODS)})") from None


def reduced_modulus(e1, nu1, e2=None, nu2=None):
    """Effective modulus E' = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) [Pa].

    Hamrock & Dowson's definition [1]_ (docs/theory/hertz.md); for two equal
    materials E' = E / (1 - nu^2), which is twice Johnson's E* [4]_.
    ``e2, nu2`` default to ``e1, nu1``.

    Examples
    --------
    >>> round(float(reduced_modulus(210e9, 0.3)) / 1e9, 2)
    230.77
    """
    e2 = e1 if e2 is None else e2
    nu2 = nu1 if nu2 is None else nu2
    return 2.0 / ((1.0 - np.square(nu1)) / e1 + (1.0 - np.square(nu2)) / e2)


def material_reduced_modulus(material) -> float:
    """E' [Pa] of a material against itself, E / (1 - nu^2)
    (:func:`reduced_modulus` of ``material.youngs_modulus`` and
    ``material.poisson_ratio``; ball and rings of one material).

    Examples
    --------
    >>> from exudyn_bearing import catalog
    >>> round(material_reduced_modulus(catalog["6208"].material) / 1e9, 2)
    230.77
    """
    return float(reduced_modulus(material.youngs_modulus, material.poisson_ratio))


@kernel
def _ellipke(m):
    """Complete elliptic integrals K(m), E(m) of parameter m = e^2 in [0, 1).

    Arithmetic-geometric mean (Abramowitz & Stegun 17.6), converged to
    machine precision in about six iterations for m < 1 - 1e-12.
    """
    a = 1.0
    b = math.sqrt(1.0 - m)
    c2sum = 0.5 * m  # 2^(n-1) c_n^2 with c_0^2 = m, n = 0
    p = 0.5
    for _ in range(40):
        an = 0.5 * (a + b)
        cn = 0.5 * (a - b)
        b = math.sqrt(a * b)
        a = an
        p *= 2.0
        c2sum += p * cn * cn
        if abs(cn) < 1e-16 * a:
            break
    kk = math.pi / (2.0 * a)
    return kk, kk * (1.0 - c2sum)


def complete_elliptic_integrals(m):
    """K(m) and E(m) [-] of parameter m = e^2 (scipy's convention).

    Arithmetic-geometric mean, Abramowitz & Stegun 17.6.
    """
    m = np.asarray(m, dtype=float)
    out_k = np.empty(m.shape)
    out_e = np.empty(m.shape)
    for idx in np.ndindex(m.shape):
        out_k[idx], out_e[idx] = _ellipke(float(m[idx]))
    return out_k, out_e


@kernel
def _aspect_from_kappa(kappa):
    """R_y/R_x as a function of k >= 1 (exact Hertz): returns (a_r, F, E).

    From Harris & Kotzalas eq. 6.27, F(rho) = ((k^2+1) E - 2 F)/((k^2-1) E)
    with F(rho) = (a_r - 1)/(a_r + 1), rearranged to
    a_r = (k^2 E - F) / (F - E), with modulus e^2 = 1 - 1/k^2.
    """
    m = 1.0 - 1.0 / (kappa * kappa)
    kk, ee = _ellipke(m)
    return (kappa * kappa * ee - kk) / (kk - ee), kk, ee


@kernel
def _kfe_exact(ratio):
    """Exact (k, F, E) for a_r = R_y/R_x >= 1: Newton on ln k from the
    Hamrock-Brewe start, on ln a_r(ln k), which is close to linear."""
    if ratio < 1.0 + 1e-9:
        return 1.0, _HALF_PI, _HALF_PI
    target = math.log(ratio)
    start = 1.0339 * ratio ** 0.636  # (a conditional, not max(): numba compiled max for 0.08 s of a cold start)
    x = math.log(start if start > 1.0 + 1e-6 else 1.0 + 1e-6)
    kk = _HALF_PI
    ee = _HALF_PI
    for _ in range(50):
        kappa = math.exp(x)
        ar, kk, ee = _aspect_from_kappa(kappa)
        f0 = math.log(ar) - target
        h = 1e-6
        ar2, _k2, _e2 = _aspect_from_kappa(math.exp(x + h))
        slope = (math.log(ar2) - math.log(ar)) / h
        step = f0 / slope
        x -= step
        if x < 1e-9:
            x = 1e-9
        if abs(step) < 1e-13:
            break
    kappa = math.exp(x)
    ar, kk, ee = _aspect_from_kappa(kappa)
    return kappa, kk, ee


@kernel
def _kfe_hamrock_brewe(ratio):
    """Hamrock & Brewe [1]: k = 1.0339 a_r^0.636, E = 1.0003 + 0.5968/a_r,
    F = 1.5277 + 0.6023 ln a_r."""
    return 1.0339 * ratio ** 0.636, 1.5277 + 0.6023 * math.log(ratio), 1.0003 + 0.5968 / ratio


@kernel
def _kfe_simplified(ratio):
    """DEM papers' fits [3], F corrected: k = a_r^(2/pi),
    E = 1 + (pi/2 - 1)/a_r, F = pi/2 + (pi/2 - 1) ln a_r."""
    return (ratio ** (2.0 / math.pi), _HALF_PI + (_HALF_PI - 1.0) * math.log(ratio),
            1.0 + (_HALF_PI - 1.0) / ratio)


#: Grid of the tabulated exact solution: ln(R_y/R_x) in [0, ln 1e4].
_TABLE_N = 8001
_TABLE_LNMAX = math.log(1e4)


def exact_table():
    """Tabulated exact (ln k, F, E) on a uniform grid of ln(R_y/R_x).

    Used by the simulation kernels as the ``"exact"`` level: linear
    interpolation on this grid reproduces the direct solution within 1e-7
    (relative; asserted in tests/test_hertz.py) at a fraction of its cost.
    Returns an array of shape (3, N).
    """
    global _EXACT_TABLE
    if _EXACT_TABLE is None:
        x = np.linspace(0.0, _TABLE_LNMAX, _TABLE_N)
        t = np.empty((3, _TABLE_N))
        for i, xi in enumerate(x):
            k, f, e = _kfe_exact(math.exp(xi))
            t[0, i], t[1, i], t[2, i] = math.log(k), f, e
        _EXACT_TABLE = t
    return _EXACT_TABLE


_EXACT_TABLE = None


@kernel
def _kfe_table_ln(ln_ratio, table):
    """(ln k, F, E) at ln a_r (a_r = R_y/R_x >= 1) by linear interpolation of :func:`exact_table`: the
    table's part of :func:`_kfe_tabulated`, for a caller that has ln a_r and takes exp(ln k) itself (the
    contact kernel, from its per-contact anchors)."""
    n = table.shape[1]
    x = ln_ratio / _TABLE_LNMAX * (n - 1)
    if x >= n - 1:
        x = n - 1.000001
    i = int(x)
    w = x - i
    lk = table[0, i] + w * (table[0, i + 1] - table[0, i])
    f = table[1, i] + w * (table[1, i + 1] - table[1, i])
    e = table[2, i] + w * (table[2, i + 1] - table[2, i])
    return lk, f, e


@kernel
def _kfe_tabulated(ratio, table):
    """(k, F, E) for a_r = R_y/R_x >= 1 by linear interpolation of :func:`exact_table`."""
    lk, f, e = _kfe_table_ln(math.log(ratio), table)
    return math.exp(lk), f, e


@kernel
def _axes_ratio(r_x, r_y):
    """a_r = R_y/R_x or R_x/R_y, whichever is >= 1 (the argument of the k, F, E relations)."""
    return r_y / r_x if r_y >= r_x else r_x / r_y


@kernel
def _kfe_fast(r_x, r_y, method, table):
    """Kernel version of :func:`_kfe`: the exact level from the table."""
    ratio = _axes_ratio(r_x, r_y)
    if method == EXACT:
        return _kfe_tabulated(ratio, table)
    elif method == HAMROCK_BREWE:
        return _kfe_hamrock_brewe(ratio)
    return _kfe_simplified(ratio)


@kernel
def _kfe(r_x, r_y, method):
    """(k, F, E) with k = major/minor >= 1, for either orientation."""
    ratio = _axes_ratio(r_x, r_y)
    if method == EXACT:
        return _kfe_exact(ratio)
    elif method == HAMROCK_BREWE:
        return _kfe_hamrock_brewe(ratio)
    return _kfe_simplified(ratio)


@kernel
def _curvature_sum_radius(r_x, r_y):
    """R = R_x R_y / (R_x + R_y) [m]."""
    return r_x * r_y / (r_x + r_y)


@kernel
def _stiffness(kappa, ell_f, ell_e, r, e_prime):
    """K = pi k E' sqrt(2 E R / (9 F^3)) [N/m^1.5] (docs/theory/hertz.md).

    Evaluated as sqrt(R (2 E / (9 F^3))): the factor of k, F, E (cached per
    contact by the contact kernel) is off the dependency chain of R there."""
    return math.pi * kappa * e_prime * math.sqrt(r * (2.0 * ell_e / (9.0 * ell_f ** 3)))


@kernel
def _semi_axes(kappa, ell_e, r, e_prime, load):
    """Semi-axes a (major) and b (minor) [m] for a load Q [N]:
    a = (6 k^2 E Q R / (pi E'))^(1/3), b = (6 E Q R / (pi k E'))^(1/3)."""
    if load <= 0.0:
        return 0.0, 0.0
    c = 6.0 * ell_e * load * r / (math.pi * e_prime)
    return (kappa * kappa * c) ** (1.0 / 3.0), (c / kappa) ** (1.0 / 3.0)


@kernel
def _semi_axes_overlap(kappa, ell_f, ell_e, r, overlap):
    """Semi-axes a (major) and b (minor) [m] at an overlap delta [m]:
    b = sqrt(2 E R delta / F), a = k b.

    :func:`_semi_axes` at the Hertz load of that overlap, Q = K delta^1.5
    with K of :func:`_stiffness` (docs/theory/hertz.md): with
    delta = F (9/(2 E R))^(1/3) (Q/(pi k E'))^(2/3) [1]_, b^2 =
    (6 E Q R/(pi k E'))^(2/3) = 2 E R delta / F. One square root instead of
    two cube roots (the contact kernel evaluates it for every closed
    contact and step)."""
    if overlap <= 0.0:
        return 0.0, 0.0
    b = math.sqrt(r * overlap * (2.0 * ell_e / ell_f))
    return kappa * b, b


@kernel
def _hertz(r_x, r_y, e_prime, overlap, method):
    """Full Hertz state at an overlap delta [m].

    Returns (Q, K, kappa, a, b, p_max, k_n): load [N], stiffness K
    [N/m^1.5], ellipticity a/b [-] (< 1 when R_y < R_x), semi-axis a across
    the rolling direction (along y) and b along it [m], peak pressure [Pa] and
    tangent stiffness dQ/d delta = 1.5 K sqrt(delta) [N/m].
    """
    kappa, ell_f, ell_e = _kfe(r_x, r_y, method)
    r = _curvature_sum_radius(r_x, r_y)
    kstiff = _stiffness(kappa, ell_f, ell_e, r, e_prime)
    if overlap <= 0.0:
        ell = kappa if r_y >= r_x else 1.0 / kappa
        return 0.0, kstiff, ell, 0.0, 0.0, 0.0, 0.0
    sq = math.sqrt(overlap)
    load = kstiff * overlap * sq
    major, minor = _semi_axes(kappa, ell_e, r, e_prime, load)
    if r_y >= r_x:
        a, b, ell = major, minor, kappa
    else:
        a, b, ell = minor, major, 1.0 / kappa
    pmax = 1.5 * load / (math.pi * a * b)
    return load, kstiff, ell, a, b, pmax, 1.5 * kstiff * sq


# -- public, broadcasting API --------------------------------------------
class HertzContact(NamedTuple):
    """Result of :func:`hertz_contact` (arrays broadcast to the inputs)."""

    load: np.ndarray        #: Q [N]
    overlap: np.ndarray     #: delta [m]
    stiffness: np.ndarray   #: K [N/m^1.5]
    kappa: np.ndarray       #: ellipticity a/b [-]
    a: np.ndarray           #: semi-axis across the rolling direction [m]
    b: np.ndarray           #: semi-axis along the rolling direction [m]
    p_max: np.ndarray       #: peak pressure [Pa]


def ellipticity(r_x, r_y, method="exact"):
    """Ellipticity k and elliptic integrals F, E of a point contact.

    Parameters
    ----------
    r_x, r_y : float or ndarray
        Effective radii in and across the rolling direction [m].
    method : {"exact", "hamrock_brewe", "simplified"}
        Fidelity level (docs/theory/hertz.md) [1]_ [3]_.

    Returns
    -------
    kappa, ell_f, ell_e : ndarray
        k = major/minor semi-axis (>= 1), F and E [-].

    Examples
    --------
    6208 inner contact, R_y/R_x = 32.8 (docs/theory/hertz.md: k = 9.37, F = 3.63):

    >>> k, f, e = ellipticity(4.990e-3, 163.8e-3)
    >>> round(float(k), 2), round(float(f), 2), round(float(e), 3)
    (9.37, 3.63, 1.018)
    """
    code = method_code(method)
    rx, ry = np.broadcast_arrays(np.asarray(r_x, float), np.asarray(r_y, float))
    out = np.empty((3,) + rx.shape)
    for idx in np.ndindex(rx.shape):
        out[(slice(None),) + idx] = _kfe(float(rx[idx]), float(ry[idx]), code)
    return out[0], out[1], out[2]


def curvature_sum_radius(r_x, r_y):
    """R = R_x R_y / (R_x + R_y) [m] (docs/theory/hertz.md)."""
    return np.asarray(r_x) * r_y / (np.asarray(r_x) + r_y)


def hertz_stiffness(r_x, r_y, e_prime, method="exact"):
    """Hertz load-deflection constant K of Q = K delta^(3/2) [N/m^1.5].

    K = pi k E' sqrt(2 E R / (9 F^3)) (Hamrock & Brewe [1]_, Harris [2]_;
    docs/theory/hertz.md with the corrected constant).

    Parameters
    ----------
    r_x, r_y : float or ndarray
        Effective radii [m].
    e_prime : float or ndarray
        Effective modulus E' [Pa] (:func:`reduced_modulus`).
    method : str
        Fidelity level.

    Examples
    --------
    >>> round(float(hertz_stiffness(4.990e-3, 163.8e-3, 230.77e9)) / 1e10, 2)
    3.25
    """
    return hertz_contact(r_x, r_y, e_prime, overlap=0.0, method=method).stiffness


def contact_ellipse(r_x, r_y, e_prime, load, method="exact"):
    """Semi-axes a (across rolling), b (along rolling) [m] and p_max [Pa].

    a = (6 k^2 E Q R/(pi E'))^(1/3), b = (6 E Q R/(pi k E'))^(1/3),
    p_max = 3 Q/(2 pi a b) [1]_ (docs/theory/hertz.md).
    """
    c = hertz_contact(r_x, r_y, e_prime, load=load, method=method)
    return c.a, c.b, c.p_max


def hertz_contact(r_x, r_y, e_prime, load=None, overlap=None, method="exact") -> HertzContact:
    """Elliptic Hertz contact for a given load or a given overlap.

    Exactly one of ``load`` [N] and ``overlap`` [m] is given; non-positive
    values mean no contact (zero load, zero ellipse). Formulas of
    docs/theory/hertz.md [1]_ [2]_; ``method`` selects the fidelity level.

    Returns
    -------
    HertzContact
        load, overlap, stiffness, kappa, a, b, p_max (broadcast arrays).
    """
    if (load is None) == (overlap is None):
        raise ValueError("hertz_contact: give exactly one of load and overlap")
    code = method_code(method)
    given = np.asarray(load if overlap is None else overlap, float)
    rx, ry, em, g = np.broadcast_arrays(np.asarray(r_x, float), np.asarray(r_y, float),
                                        np.asarray(e_prime, float), given)
    out = np.empty((7,) + rx.shape)
    for idx in np.ndindex(rx.shape):
        if overlap is None:
            kappa, ell_f, ell_e = _kfe(float(rx[idx]), float(ry[idx]), code)
            kst = _stiffness(kappa, ell_f, ell_e, _curvature_sum_radius(rx[idx], ry[idx]), em[idx])
            d = (g[idx] / kst) ** (2.0 / 3.0) if g[idx] > 0.0 else 0.0
        else:
            d = float(g[idx])
        q, kst, ell, a, b, pm, _kn = _hertz(float(rx[idx]), float(ry[idx]), float(em[idx]), d, code)
        out[(slice(None),) + idx] = (q, max(d, 0.0), kst, ell, a, b, pm)
    return HertzContact(*[o[()] if o.ndim == 0 else o for o in out])


def sphere_sphere_stiffness(r1, r2, e_prime):
    """Hertz constant of two spheres, Q = K delta^(3/2) [N/m^1.5].

    K = (4/3) E* sqrt(R_eq), E* = E'/2, R_eq = r1 r2 / (r1 + r2)
    (Johnson [4]_ eq. 4.22; docs/theory/hertz.md). For equal steels this is
    4 G sqrt(R_eq) / (3 (1 - nu)). Scalars or numpy arrays; jitted as
    ``_sphere_sphere_stiffness`` for the engines.
    """
    return 2.0 / 3.0 * e_prime * np.sqrt(r1 * r2 / (r1 + r2))


_sphere_sphere_stiffness = kernel(sphere_sphere_stiffness)


def ball_in_pocket_stiffness(ball_radius, pocket_clearance, cylindrical, e_prime, method="exact"):
    """Hertz constant K of a ball in a cage pocket, Q = K delta^(3/2) [N/m^1.5]: a sphere R_b inside the
    concave surface of radius R_b + c_p (docs/theory/cage.md#pockets). Across a cylindrical pocket's axis
    the curvature sum is 1/R_b - 1/(R_b + c_p), so R = R_b (R_b + c_p) / c_p; along the axis the pocket is
    straight, R = R_b; a spherical pocket conforms in both directions (Johnson, Contact Mechanics, ch. 4:
    the relative curvatures of the two surfaces). :func:`hertz_stiffness` of these radii.

    >>> round(float(ball_in_pocket_stiffness(6.3e-3, 0.25e-3, True, 230e9)) / 1e9, 2)
    33.54
    >>> k_flat = ball_in_pocket_stiffness(6.3e-3, 1e3, False, 230e9)   # a huge spherical pocket: a plane
    >>> bool(abs(k_flat / sphere_sphere_stiffness(6.3e-3, 1e12, 230e9) - 1.0) < 1e-5)
    True
    """
    conform = ball_radius * (ball_radius + pocket_clearance) / pocket_clearance
    return hertz_stiffness(conform, ball_radius if cylindrical else conform, e_prime, method)


def tangent_stiffness(stiffness, load):
    """Tangent (linearised) stiffness dQ/d delta of a Hertz point contact at
    the load Q [N/m].

    From Q = K delta^(3/2): dQ/d delta = 1.5 K delta^(1/2) = 1.5 K^(2/3) Q^(1/3)
    (Harris & Kotzalas [2]_, load-deflection relation; docs/theory/hertz.md).
    Used for the stable-step estimate. Scalars or numpy arrays; loads below
    zero count as zero.
    """
    return 1.5 * np.cbrt(np.asarray(stiffness, float) ** 2 * np.maximum(load, 0.0))
