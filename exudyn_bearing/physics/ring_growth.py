"""Growth of bearing rings at speed and temperature: rotating annular disc,
shrink-fit pressure and its loss with speed, uniform thermal expansion.

Each ring is treated as an annular disc in plane stress (thin in the axial
direction, free faces), the classical model of a rotating bearing ring and of
a press fit (Timoshenko & Goodier [1]_ sec. 28 and 32; applied to rolling
bearings in Harris & Kotzalas [2]_, "bearing internal clearance" and
"high-speed operation"). All lengths are radii [m]; displacements are radial,
positive outward.

* :func:`rotating_disc_displacement`: free annular disc (inner radius b,
  outer radius c) spinning at omega, u(r) of [1]_ sec. 32;
* :func:`thin_ring_displacement`: its limit b -> c, rho omega^2 r^3 / E;
* :func:`lame_displacement`: disc under pressures on its two edges (Lame,
  [1]_ sec. 28);
* :func:`fit_pressure`: interface pressure of an inner ring shrunk on a
  (hollow or solid) shaft of the same material, falling with speed because
  the ring's bore grows more than the shaft's surface, zero once the fit has
  loosened; :func:`fit_loosening_speed` is that speed;
* :func:`inner_ring_raceway_growth`: raceway growth of an inner ring from
  rotation and fit together;
* :func:`thermal_growth`: uniform thermal expansion alpha dT L.

References
----------
.. [1] S. P. Timoshenko and J. N. Goodier, Theory of Elasticity, 3rd ed.,
   McGraw-Hill, 1970, sec. 28 (thick cylinder) and 32 (rotating disks).
.. [2] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed.,
   CRC Press, 2006 (Essential Concepts ch. 'Bearing internal clearance';
   Advanced Concepts ch. 'High-speed operation').
"""
from __future__ import annotations

import numpy as np

__all__ = ["rotating_disc_displacement", "thin_ring_displacement", "lame_displacement", "fit_pressure",
           "fit_loosening_speed", "inner_ring_raceway_growth", "thermal_growth"]


def rotating_disc_displacement(r, inner_radius, outer_radius, omega, density, youngs_modulus, poisson_ratio):
    """Radial displacement u(r) [m] of a free annular disc spinning at omega.

    Plane stress, free edges, Timoshenko & Goodier [1]_ sec. 32.

    Parameters
    ----------
    r : float or ndarray
        Radius at which u is wanted [m], inner_radius <= r <= outer_radius.
    inner_radius, outer_radius : float
        b (0 for a solid disc) and c [m].
    omega : float or ndarray
        Spin speed [rad/s].
    density, youngs_modulus, poisson_ratio : float
        rho [kg/m^3], E [Pa], nu [-].

    Returns
    -------
    u : float or ndarray [m], outward.

    Notes
    -----
    With the stresses sigma_r = (3 + nu)/8 rho omega^2 (b^2 + c^2 - b^2 c^2/r^2 - r^2)
    and sigma_t = (3 + nu)/8 rho omega^2 (b^2 + c^2 + b^2 c^2/r^2 - (1 + 3 nu)/(3 + nu) r^2),
    u = r (sigma_t - nu sigma_r)/E::

        u(r) = (3 + nu)(1 - nu) rho omega^2 r / (8 E)
               * [b^2 + c^2 + (1 + nu)/(1 - nu) b^2 c^2 / r^2 - (1 + nu)/(3 + nu) r^2]

    As b -> c it tends to rho omega^2 r^3 / E (:func:`thin_ring_displacement`).

    Examples
    --------
    ACBB-120 inner ring (bore radius 60 mm, raceway radius 67.18 mm, M-50)
    at 25,000 rpm, at the raceway [um]:

    >>> w = 25000 * 2 * np.pi / 60
    >>> round(float(rotating_disc_displacement(67.18e-3, 60e-3, 67.18e-3, w, 7830, 203e9, 0.28)) * 1e6, 1)
    66.9
    """
    r = np.asarray(r, float)
    b2 = np.square(inner_radius)
    c2 = np.square(outer_radius)
    nu = poisson_ratio
    with np.errstate(divide="ignore", invalid="ignore"):
        hole = np.where(r > 0.0, (1.0 + nu) / (1.0 - nu) * b2 * c2 / np.where(r > 0.0, r * r, 1.0), 0.0)
    bracket = b2 + c2 + hole - (1.0 + nu) / (3.0 + nu) * r * r
    return (3.0 + nu) * (1.0 - nu) * density * np.square(omega) * r / (8.0 * youngs_modulus) * bracket


def thin_ring_displacement(radius, omega, density, youngs_modulus):
    """Radial growth of a thin rotating ring, rho omega^2 r^3 / E [m].

    The hoop stress of a thin ring is rho omega^2 r^2 (Timoshenko & Goodier
    [1]_ sec. 32, limit of the annular disc as its width goes to zero).

    Examples
    --------
    A ring of radius 67 mm (M-50) at 2618 rad/s: tens of micrometres.

    >>> round(float(thin_ring_displacement(67e-3, 2618.0, 7830, 203e9)) * 1e6, 1)
    79.5
    """
    return density * np.square(omega) * np.power(radius, 3) / youngs_modulus


def lame_displacement(r, inner_radius, outer_radius, p_inner, p_outer, youngs_modulus, poisson_ratio):
    """Radial displacement u(r) [m] of an annular disc under edge pressures.

    Lame's solution in plane stress (Timoshenko & Goodier [1]_ sec. 28):
    u(r) = [(p_i b^2 - p_o c^2)(1 - nu) r + (p_i - p_o) b^2 c^2 (1 + nu)/r] / (E (c^2 - b^2)),
    with p_i on the bore (radius b > 0) and p_o on the outer edge (radius c), both
    positive in compression [Pa].

    Examples
    --------
    Thin-walled limit: u = p r^2/(E t) = 50 um for a ring of radius 0.1 m,
    wall 1 mm, p = 1 MPa, E = 200 GPa:

    >>> round(float(lame_displacement(0.1, 0.0995, 0.1005, 1e6, 0.0, 200e9, 0.3)) * 1e6, 1)
    49.8
    """
    r = np.asarray(r, float)
    b2 = np.square(inner_radius)
    c2 = np.square(outer_radius)
    nu = poisson_ratio
    return ((p_inner * b2 - p_outer * c2) * (1.0 - nu) * r + (p_inner - p_outer) * b2 * c2 * (1.0 + nu) / r) / (
        youngs_modulus * (c2 - b2))


def _fit_compliance(bore_radius, ring_outer_radius, shaft_inner_radius, youngs_modulus):
    """Radial interference per unit pressure [m/Pa] of ring on shaft (same material):
    b/E [(c^2 + b^2)/(c^2 - b^2) + (b^2 + a^2)/(b^2 - a^2)] (the nu terms cancel)."""
    a2, b2, c2 = np.square(shaft_inner_radius), np.square(bore_radius), np.square(ring_outer_radius)
    return bore_radius / youngs_modulus * ((c2 + b2) / (c2 - b2) + (b2 + a2) / (b2 - a2))


def _speed_loss(bore_radius, ring_outer_radius, shaft_inner_radius, omega, density, youngs_modulus, poisson_ratio):
    """Radial interference lost at speed [m]: free growth of the ring's bore minus that of the shaft surface."""
    ring = rotating_disc_displacement(bore_radius, bore_radius, ring_outer_radius, omega, density, youngs_modulus,
                                      poisson_ratio)
    shaft = rotating_disc_displacement(bore_radius, shaft_inner_radius, bore_radius, omega, density,
                                       youngs_modulus, poisson_ratio)
    return ring - shaft


def fit_pressure(interference, bore_radius, ring_outer_radius, omega=0.0, shaft_inner_radius=0.0, *,
                 density, youngs_modulus, poisson_ratio):
    """Shrink-fit pressure between an inner ring and its shaft at speed [Pa].

    Ring (bore radius b, outer radius c) and shaft (hollow, bore a, or solid,
    a = 0) of one material. At rest the diametral interference I gives the
    pressure p = (I/2) / C with the compliance C of both Lame discs
    ([1]_ sec. 28, [2]_); at speed the ring's bore grows more than the shaft
    surface (:func:`rotating_disc_displacement` of each), which takes
    Delta u(omega) off the radial interference, so
    p(omega) = max(0, (I/2 - Delta u(omega)) / C): it falls with omega^2 and
    is zero once the fit has loosened (:func:`fit_loosening_speed`).

    Parameters
    ----------
    interference : float
        Diametral interference I >= 0 [m] (shaft diameter minus bore diameter).
    bore_radius, ring_outer_radius, shaft_inner_radius : float
        b, c, a [m] (a = 0: solid shaft).
    omega : float or ndarray
        Common speed of shaft and ring [rad/s].
    density, youngs_modulus, poisson_ratio : float
        Material of ring and shaft.

    Notes
    -----
    C = b/E [(c^2 + b^2)/(c^2 - b^2) + (b^2 + a^2)/(b^2 - a^2)].

    Examples
    --------
    20 um on a 120 mm bore (ACBB-120 inner ring, solid shaft), at rest and at 25,000 rpm [MPa]:

    >>> kw = dict(density=7830, youngs_modulus=203e9, poisson_ratio=0.28)
    >>> round(float(fit_pressure(20e-6, 60e-3, 67.18e-3, **kw)) / 1e6, 1)
    3.4
    >>> float(fit_pressure(20e-6, 60e-3, 67.18e-3, 25000 * np.pi / 30, **kw))
    0.0
    """
    c = _fit_compliance(bore_radius, ring_outer_radius, shaft_inner_radius, youngs_modulus)
    loss = _speed_loss(bore_radius, ring_outer_radius, shaft_inner_radius, omega, density, youngs_modulus,
                       poisson_ratio)
    return np.maximum(0.5 * np.asarray(interference, float) - loss, 0.0) / c


def fit_loosening_speed(interference, bore_radius, ring_outer_radius, shaft_inner_radius=0.0, *,
                        density, youngs_modulus, poisson_ratio):
    """Speed at which a shrink fit loses all pressure [rad/s] (:func:`fit_pressure` = 0).

    The interference lost grows with omega^2, so omega_loose = sqrt((I/2) / Delta u(1 rad/s)).

    Examples
    --------
    >>> kw = dict(density=7830, youngs_modulus=203e9, poisson_ratio=0.28)
    >>> round(float(fit_loosening_speed(20e-6, 60e-3, 67.18e-3, **kw)) * 30 / np.pi)  # rpm
    10318
    """
    unit = _speed_loss(bore_radius, ring_outer_radius, shaft_inner_radius, 1.0, density, youngs_modulus,
                       poisson_ratio)
    return np.sqrt(0.5 * np.asarray(interference, float) / unit)


def inner_ring_raceway_growth(raceway_radius, bore_radius, omega, interference=0.0, shaft_inner_radius=0.0, *,
                              density, youngs_modulus, poisson_ratio):
    """Radial growth of an inner ring's raceway [m] from rotation and shaft fit.

    The ring is the annular disc from its bore b to its raceway radius c (the
    shoulders are left out: a choice that slightly overstates the growth).
    u = u_rot(c) + u_fit(c), with u_rot of :func:`rotating_disc_displacement`
    and u_fit the Lame displacement at c of the fit pressure
    :func:`fit_pressure` on the bore, 2 p b^2 c / (E (c^2 - b^2)).

    Examples
    --------
    ACBB-120 at 25,000 rpm without a fit [um] (the rotating disc alone):

    >>> kw = dict(density=7830, youngs_modulus=203e9, poisson_ratio=0.28)
    >>> round(float(inner_ring_raceway_growth(67.18e-3, 60e-3, 25000 * np.pi / 30, **kw)) * 1e6, 1)
    66.9
    """
    rot = rotating_disc_displacement(raceway_radius, bore_radius, raceway_radius, omega, density, youngs_modulus,
                                     poisson_ratio)
    p = fit_pressure(interference, bore_radius, raceway_radius, omega, shaft_inner_radius, density=density,
                     youngs_modulus=youngs_modulus, poisson_ratio=poisson_ratio)
    fit = lame_displacement(raceway_radius, bore_radius, raceway_radius, p, 0.0, youngs_modulus, poisson_ratio)
    return rot + fit


def thermal_growth(length, thermal_expansion, temperature_rise):
    """Uniform thermal expansion of a length (radius, groove radius, ball radius) [m].

    Delta L = alpha dT L for a body at uniform temperature, free to expand
    (linear thermoelasticity, Timoshenko & Goodier [1]_ ch. 13; used for
    bearing rings and balls in Harris & Kotzalas [2]_).

    Examples
    --------
    A 67 mm raceway radius of M-50 (12.3e-6 1/K) heated by 199 K [um]:

    >>> round(float(thermal_growth(67e-3, 12.3e-6, 199.0)) * 1e6, 1)
    164.0
    """
    return np.asarray(thermal_expansion, float) * temperature_rise * length
