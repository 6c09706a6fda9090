"""In-plane flexural vibration of a thin bearing ring and its single-degree-
of-freedom stand-in.

A thin circular ring of radius R (to the centroid of its cross-section),
bending stiffness E I (bending in the plane of the ring) and mass per unit
length mu vibrates in plane, without stretching its centre line, in modes
with n = 2, 3, ... waves around the circumference at (Hoppe [1]_, Love [2]_,
Blevins [3]_)::

    omega_n = n (n^2 - 1) / sqrt(1 + n^2) * sqrt(E I / (mu R^4))        (1)

n = 0 and n = 1 are the breathing (extensional) and rigid-body modes, so
n = 2, the oval mode, is the lowest bending mode: its factor is
6 / sqrt(5) = 2.683, the 2.68 that El Had et al. [4]_ (their eqs. 3-4) use.
Their 3-DOF bearing model replaces each ring by a mass M on a spring tuned
to this frequency (their eqs. 1-2)::

    k = M omega_n^2                                                      (2)

With M = 2 pi R mu, the whole ring, (1) and (2) give
k = 2 pi n^2 (n^2 - 1)^2 / (1 + n^2) * E I / R^3, independent of the mass.

Nomenclature: E -> ``youngs_modulus`` [Pa], I -> ``second_moment`` [m^4]
(about the axis parallel to the bearing axis, b t^3 / 12 for a rectangular
section of axial width b and radial thickness t), mu -> ``mass_per_length``
[kg/m], R -> ``radius`` [m], n -> ``mode``.

References
----------
.. [1] R. Hoppe, "Vibrationen eines Ringes in seiner Ebene," J. reine angew.
   Math. 73 (1871) 158-170.
.. [2] A. E. H. Love, A Treatise on the Mathematical Theory of Elasticity,
   4th ed., Cambridge University Press, 1927 (vibrations of a circular ring).
.. [3] R. D. Blevins, Formulas for Natural Frequency and Mode Shape, Van
   Nostrand Reinhold, 1979 (in-plane modes of a circular ring).
.. [4] K. El Had, A. Hachim, A. Chouairi, M. El Ghorba, "Improved analytical
   approach of vibration behavior destined to ball bearings in the case of
   angular contact," Rev. Energy Technol. Policy Res. 1(2) (2014) 56-68.
   doi:10.18488/journal.77/2014.1.2/77.2.56.68
"""
from __future__ import annotations

import numpy as np

from ..data import InputError

__all__ = ["ring_mode_factor", "ring_flexural_frequency", "ring_modal_stiffness",
           "rectangular_ring_section"]


def _check_mode(mode):
    n = np.asarray(mode)
    if not np.issubdtype(n.dtype, np.integer) and not np.all(np.mod(n, 1.0) == 0.0):
        raise InputError(f"mode: must be an integer number of waves, got {mode!r}")
    if np.any(n < 2):
        raise InputError(f"mode: flexural modes start at n = 2 (0 and 1 are not bending modes), got {mode!r}")
    return n.astype(float)


def _positive(name, value):
    v = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(v)) or np.any(v <= 0.0):
        raise InputError(f"{name}: must be finite and > 0, got {value!r}")
    return v


def ring_mode_factor(mode=2):
    """Factor n (n^2 - 1) / sqrt(1 + n^2) of the in-plane ring mode n [-].

    Hoppe's ring frequency [1]_ (eq. 1 of the module docstring); El Had et
    al. [4]_ eq. 4 rounds its n = 2 value to 2.68.

    Parameters
    ----------
    mode : int or ndarray
        Number of waves n around the ring (>= 2).

    Returns
    -------
    float or ndarray [-]

    Examples
    --------
    The oval mode, El Had et al. eq. 4 (2.68):

    >>> round(float(ring_mode_factor(2)), 2)
    2.68
    """
    n = _check_mode(mode)
    return n * (n * n - 1.0) / np.sqrt(1.0 + n * n)


def ring_flexural_frequency(youngs_modulus, second_moment, mass_per_length, radius, mode=2):
    """Angular frequency of the in-plane bending mode n of a thin ring [rad/s].

    omega_n = n (n^2 - 1)/sqrt(1 + n^2) sqrt(E I / (mu R^4)) (Hoppe [1]_,
    Love [2]_; El Had et al. [4]_ eqs. 3-4).

    Parameters
    ----------
    youngs_modulus : float or ndarray
        E [Pa].
    second_moment : float or ndarray
        I [m^4] of the cross-section for bending in the ring's plane.
    mass_per_length : float or ndarray
        mu = rho A [kg/m].
    radius : float or ndarray
        R [m], to the centroid of the cross-section.
    mode : int
        n >= 2 (default 2, the lowest bending mode).

    Returns
    -------
    float or ndarray [rad/s]

    Notes
    -----
    Thin-ring (Euler-Bernoulli, inextensional) theory: valid while the
    radial thickness is small against R; shear and rotary inertia lower the
    frequency of thick rings.

    Examples
    --------
    With E I / (mu R^4) = 1 s^-2 the n = 2 frequency is the factor 2.68:

    >>> round(float(ring_flexural_frequency(1.0, 1.0, 1.0, 1.0)), 2)
    2.68
    """
    e = _positive("youngs_modulus", youngs_modulus)
    i = _positive("second_moment", second_moment)
    mu = _positive("mass_per_length", mass_per_length)
    r = _positive("radius", radius)
    return ring_mode_factor(mode) * np.sqrt(e * i / (mu * r ** 4))


def ring_modal_stiffness(mass, angular_frequency):
    """Stiffness k = M omega^2 of the single-DOF stand-in of a ring [N/m].

    El Had et al. [4]_ eqs. 1-2: the ring becomes a mass M on a spring whose
    natural frequency is the ring's bending frequency omega.

    Parameters
    ----------
    mass : float or ndarray
        M [kg].
    angular_frequency : float or ndarray
        omega [rad/s].

    Returns
    -------
    float or ndarray [N/m]

    Examples
    --------
    The 25 g outer ring of El Had et al. at 2e4 rad/s gives their 1e7 N/m:

    >>> float(ring_modal_stiffness(0.025, 2.0e4))
    10000000.0
    """
    m = _positive("mass", mass)
    w = _positive("angular_frequency", angular_frequency)
    return m * w * w


def rectangular_ring_section(width, thickness):
    """Area A [m^2] and second moment I = b t^3 / 12 [m^4] of a rectangular
    ring section of axial width b and radial thickness t, for bending in the
    plane of the ring.

    Examples
    --------
    >>> a, i = rectangular_ring_section(0.012, 0.002)
    >>> round(float(a) * 1e6, 1), round(float(i) * 1e12, 1)
    (24.0, 8.0)
    """
    b = _positive("width", width)
    t = _positive("thickness", thickness)
    return b * t, b * t ** 3 / 12.0
