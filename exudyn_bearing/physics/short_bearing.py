"""Stiffness and damping of a lubricant film by the short-bearing theory.

El Had et al. [1]_ (their eqs. 5-6) give the film stiffness k and damping C
of the ball-race contacts of their 3-DOF bearing model as functions of one
eccentricity ratio eps_0 = 1 - h/c (film thickness h, clearance c). Their
brackets are the direct coefficients, along the load line, of Ocvirk's
short journal bearing [2]_ (pressure-positive half of the film, L/D -> 0),
made dimensionless with the load W, the clearance c and the journal speed
omega::

    k_bar = k c / W   = (4 / W_bar) [ eps/(1-eps^2)^2 sin^2 phi
                          + 3 pi eps^2 / (4 (1-eps^2)^(5/2)) sin phi cos phi
                          + 2 eps (1+eps^2)/(1-eps^2)^3 cos^2 phi ]           (5)
    C_bar = C c w / W = (4 / W_bar) [ pi / (2 (1-eps^2)^(3/2)) sin^2 phi
                          + 4 eps/(1-eps^2)^2 sin phi cos phi
                          + pi (1+2 eps^2) / (2 (1-eps^2)^(5/2)) cos^2 phi ]  (6)

    W_bar = eps sqrt(16 eps^2 + pi^2 (1-eps^2)) / (1-eps^2)^2,
    tan phi = pi sqrt(1-eps^2) / (4 eps)         (attitude angle phi)

W_bar is the short bearing's load number, W = W_bar mu omega R L^3/(4 c^2)
(viscosity mu, journal radius R, length L). In polar coordinates along and
across the line of centres, the radial force of the short bearing is
proportional to eps^2/(1-eps^2)^2 and the tangential one to
pi eps/(4 (1-eps^2)^(3/2)); the three stiffness terms are their derivatives
(d/d eps of the radial force, the radial force over eps, the sum of the two
cross derivatives), the three damping terms the squeeze-film integrals
int cos^2, sin cos, sin^2 / (1 + eps cos theta)^3 over the film, each turned
onto the load line at phi from the line of centres. Both are identical to
the closed forms of the load-direction coefficients quoted by Friswell et
al. [3]_ (with h_0 = (pi^2 (1-eps^2) + 16 eps^2)^(-3/2))::

    k_bar = 4 h_0 [pi^2 + (32 + pi^2) eps^2 + (32 - 2 pi^2) eps^4] / (1 - eps^2)
    C_bar = 2 pi h_0 [pi^2 + 2 (24 - pi^2) eps^2 + pi^2 eps^4] / (eps sqrt(1 - eps^2))

Correction of the source: it prints the prefactor 4/(W_r lambda_k^2) as
(1-eps^2)^2 / (eps [16 eps^2 + pi^2 (1-eps^2)]^(1/2)) cos^2 phi, i.e.
without the 4 and with a stray cos^2 phi; with that factor the coefficients
are cos^2 phi / 4 times the short-bearing ones (0.088 at eps = 0.5). The
functions here use 4 / W_bar; ``printed_prefactor=True`` gives the printed
version for comparison.

Nomenclature: eps_0 -> ``eccentricity``, h -> ``film_thickness`` [m],
c -> ``clearance`` [m] (radial clearance of the journal analogy, so that
h = c (1 - eps_0) is the smallest film), W -> ``load`` [N], omega ->
``omega`` [rad/s].

References
----------
.. [1] K. El Had, A. Hachim, A. Chouairi, M. El Ghorba, "Improved analytical
   approach of vibration behavior destined to ball bearings in the case of
   angular contact," Rev. Energy Technol. Policy Res. 1(2) (2014) 56-68.
   doi:10.18488/journal.77/2014.1.2/77.2.56.68
.. [2] F. W. Ocvirk, "Short-bearing approximation for full journal
   bearings," NACA Technical Note 2808, 1952.
.. [3] M. I. Friswell, J. E. T. Penny, S. D. Garvey, A. W. Lees, Dynamics of
   Rotating Machines, Cambridge University Press, 2010, ch. 5 (short
   journal bearing coefficients).
.. [5] D. W. Childs, Turbomachinery Rotordynamics: Phenomena, Modeling, and
   Analysis, Wiley, 1993, ch. 3 (short bearing, dynamic pi-film forces).
.. [6] B. J. Hamrock, S. R. Schmid, B. O. Jacobson, Fundamentals of Fluid
   Film Lubrication, 2nd ed., Marcel Dekker, 2004, ch. 10 (Petroff's
   equation, friction of the eccentric journal).
.. [4] J. W. Lund, "Review of the concept of dynamic coefficients for fluid
   film journal bearings," J. Tribol. 109(1) (1987) 37-41. doi:10.1115/1.3261324
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel
from ..data import InputError

__all__ = ["film_eccentricity", "short_bearing_attitude_angle", "short_bearing_load_number",
           "short_bearing_stiffness", "short_bearing_damping", "film_coefficients", "short_bearing_force",
           "short_bearing_force_xy", "short_bearing_shear_torque"]


def _eps(eccentricity):
    e = np.asarray(eccentricity, dtype=float)
    if not np.all(np.isfinite(e)) or np.any(e <= 0.0) or np.any(e >= 1.0):
        raise InputError(f"eccentricity: must lie in (0, 1), got {eccentricity!r}")
    return e


def film_eccentricity(film_thickness, clearance):
    """Eccentricity ratio eps_0 = 1 - h/c of a film of thickness h in a
    clearance c [-] (El Had et al. [1]_; journal-bearing geometry
    h_min = c (1 - eps) [2]_).

    Parameters
    ----------
    film_thickness : float or ndarray
        Smallest film thickness h [m], 0 < h < c.
    clearance : float or ndarray
        Radial clearance c [m] (half the diametral clearance).

    Returns
    -------
    float or ndarray [-] in (0, 1)

    Examples
    --------
    >>> round(float(film_eccentricity(0.3e-6, 6.25e-6)), 3)
    0.952
    """
    h = np.asarray(film_thickness, dtype=float)
    c = np.asarray(clearance, dtype=float)
    if not np.all(np.isfinite(c)) or np.any(c <= 0.0):
        raise InputError(f"clearance: must be finite and > 0 (a film needs a clearance), got {clearance!r}")
    if not np.all(np.isfinite(h)) or np.any(h <= 0.0):
        raise InputError(f"film_thickness: must be finite and > 0, got {film_thickness!r}")
    if np.any(h >= c):
        raise InputError(f"film_thickness: h = {film_thickness!r} m is not smaller than the clearance "
                         f"c = {clearance!r} m (eccentricity 1 - h/c would be <= 0)")
    return 1.0 - h / c


def short_bearing_attitude_angle(eccentricity):
    """Attitude angle phi of the short bearing, between the load line and the
    line of centres [rad]: tan phi = pi sqrt(1 - eps^2) / (4 eps) [2]_ [1]_.

    Examples
    --------
    >>> round(float(np.degrees(short_bearing_attitude_angle(0.5))), 2)
    53.68
    """
    return _attitude(_eps(eccentricity))


def _attitude(e):
    """:func:`short_bearing_attitude_angle` of a checked eps (float or array; callers that solve for eps)."""
    return np.arctan2(np.pi * np.sqrt(1.0 - e * e), 4.0 * e)


def short_bearing_load_number(eccentricity):
    """Load number W_bar = eps sqrt(16 eps^2 + pi^2 (1 - eps^2)) / (1 - eps^2)^2
    of the short bearing [-]: W = W_bar mu omega R L^3 / (4 c^2) [2]_.

    Examples
    --------
    >>> round(float(short_bearing_load_number(0.5)), 4)
    3.0015
    """
    return _load_number(_eps(eccentricity))


def _load_number(e):
    """:func:`short_bearing_load_number` of a checked eps (float or array; callers that solve for eps)."""
    s = 1.0 - e * e
    return e * np.sqrt(16.0 * e * e + np.pi ** 2 * s) / (s * s)


def _prefactor(e, printed_prefactor):
    if printed_prefactor:
        # the source's printed form of 4/(W_r lambda_k^2): no 4, a stray cos^2(phi)
        return np.cos(short_bearing_attitude_angle(e)) ** 2 / short_bearing_load_number(e)
    return 4.0 / short_bearing_load_number(e)


def short_bearing_stiffness(eccentricity, printed_prefactor=False):
    """Film stiffness along the load line, k_bar = k c / W [-] (El Had et al.
    [1]_ eq. 5 with the corrected prefactor 4 / W_bar; short bearing [2]_ [3]_).

    Parameters
    ----------
    eccentricity : float or ndarray
        eps_0 in (0, 1).
    printed_prefactor : bool
        Use the source's printed prefactor (module docstring) instead of
        4 / W_bar; for comparison only.

    Returns
    -------
    float or ndarray [-]; the stiffness is k = k_bar W / c [N/m].

    Notes
    -----
    Equation (5) of the module docstring; equal to
    4 h_0 [pi^2 + (32 + pi^2) eps^2 + (32 - 2 pi^2) eps^4] / (1 - eps^2) [3]_.

    Examples
    --------
    >>> round(float(short_bearing_stiffness(0.5)), 4)
    2.9233
    """
    e = _eps(eccentricity)
    s = 1.0 - e * e
    phi = short_bearing_attitude_angle(e)
    sn, cs = np.sin(phi), np.cos(phi)
    bracket = (e / s ** 2 * sn * sn + 3.0 * np.pi * e * e / (4.0 * s ** 2.5) * sn * cs
               + 2.0 * e * (1.0 + e * e) / s ** 3 * cs * cs)
    return _prefactor(e, printed_prefactor) * bracket


def short_bearing_damping(eccentricity, printed_prefactor=False):
    """Film damping along the load line, C_bar = C c omega / W [-] (El Had
    et al. [1]_ eq. 6 with the corrected prefactor 4 / W_bar; short bearing
    [2]_ [3]_).

    Parameters
    ----------
    eccentricity : float or ndarray
        eps_0 in (0, 1).
    printed_prefactor : bool
        Use the source's printed prefactor instead of 4 / W_bar.

    Returns
    -------
    float or ndarray [-]; the damping is C = C_bar W / (c omega) [N s/m].

    Notes
    -----
    Equation (6) of the module docstring; equal to
    2 pi h_0 [pi^2 + 2 (24 - pi^2) eps^2 + pi^2 eps^4] / (eps sqrt(1 - eps^2)) [3]_.

    Examples
    --------
    >>> round(float(short_bearing_damping(0.5)), 4)
    6.6148
    """
    e = _eps(eccentricity)
    s = 1.0 - e * e
    phi = short_bearing_attitude_angle(e)
    sn, cs = np.sin(phi), np.cos(phi)
    bracket = (np.pi / (2.0 * s ** 1.5) * sn * sn + 4.0 * e / s ** 2 * sn * cs
               + np.pi * (1.0 + 2.0 * e * e) / (2.0 * s ** 2.5) * cs * cs)
    return _prefactor(e, printed_prefactor) * bracket


def film_coefficients(eccentricity, load, clearance, omega, printed_prefactor=False):
    """Dimensional film stiffness k = k_bar W / c [N/m] and damping
    C = C_bar W / (c omega) [N s/m] along the load line [1]_ [4]_.

    Parameters
    ----------
    eccentricity : float or ndarray
        eps_0 in (0, 1).
    load : float or ndarray
        Load W carried by the film [N] (> 0).
    clearance : float or ndarray
        Radial clearance c [m] (> 0).
    omega : float or ndarray
        Journal speed of the normalisation [rad/s] (> 0).
    printed_prefactor : bool
        As :func:`short_bearing_stiffness`.

    Returns
    -------
    (k [N/m], C [N s/m])

    Examples
    --------
    >>> k, c = film_coefficients(0.5, 100.0, 1e-5, 100.0)
    >>> round(float(k) / 1e7, 4), round(float(c) / 1e5, 4)
    (2.9233, 6.6148)
    """
    w = np.asarray(load, dtype=float)
    c = np.asarray(clearance, dtype=float)
    om = np.asarray(omega, dtype=float)
    for name, v, given in (("load", w, load), ("clearance", c, clearance), ("omega", om, omega)):
        if not np.all(np.isfinite(v)) or np.any(v <= 0.0):
            raise InputError(f"{name}: must be finite and > 0, got {given!r}")
    return (short_bearing_stiffness(eccentricity, printed_prefactor) * w / c,
            short_bearing_damping(eccentricity, printed_prefactor) * w / (c * om))


@kernel(inline="always")
def _half_film_integrals(eps, c0, s0):
    """The integrals I_sc, I_cc, I_ss of sin cos, cos^2, sin^2 over (1 - eps cos theta)^3 for theta from theta0
    to theta0 + pi (given by c0 = cos theta0, s0 = sin theta0), in closed form by Sommerfeld's substitution
    cos theta = (eps + cos g)/(1 + eps cos g) (tan(g/2) = sqrt((1+eps)/(1-eps)) tan(theta/2); Hamrock et
    al. [6]_ ch. 8): the integrands turn into sin g (cos g + eps)/(1-eps^2)^2, (cos g + eps)^2/(1-eps^2)^(5/2)
    and sin^2 g/(1-eps^2)^(3/2). The map is taken continuous in theta: g = theta + 2 atan(A),
    A = (k-1) sin theta / (1 + cos theta + k (1 - cos theta)), k = sqrt((1+eps)/(1-eps)) (the denominator
    is at least 2). The ends' sines and cosines follow from those of theta0 (cos and sin of theta0 + pi are
    -c0, -s0) and the rational cos(2 atan A) = (1 - A^2)/(1 + A^2), sin(2 atan A) = 2 A/(1 + A^2); the span
    g1 - g0 = pi + 2 (atan A1 - atan A0), the difference of the arc tangents taken as one
    atan2(A1 - A0, 1 + A0 A1): one arc tangent and no sine or cosine, where the angles themselves took
    thirteen trigonometric calls with the start's atan2 (the implicit land of the rigid cage takes the film
    five times a step: about a tenth of the 7208's step went there; ``python validation/studies/rigid_cage.py
    --profile``). Equal to the angle form to round-off [T: tests/test_short_bearing_force.py]. Scalars
    (compiled)."""
    s = 1.0 - eps * eps
    k = math.sqrt((1.0 + eps) / (1.0 - eps))
    a0 = (k - 1.0) * s0 / (1.0 + c0 + k * (1.0 - c0))
    a1 = -(k - 1.0) * s0 / (1.0 - c0 + k * (1.0 + c0))
    q0, q1 = 1.0 / (1.0 + a0 * a0), 1.0 / (1.0 + a1 * a1)
    cc0, ss0 = (1.0 - a0 * a0) * q0, 2.0 * a0 * q0  # cos, sin of 2 atan(A0)
    cc1, ss1 = (1.0 - a1 * a1) * q1, 2.0 * a1 * q1
    sg0, cg0 = s0 * cc0 + c0 * ss0, c0 * cc0 - s0 * ss0  # sin, cos of g0 = theta0 + 2 atan(A0)
    sg1, cg1 = -(s0 * cc1 + c0 * ss1), -(c0 * cc1 - s0 * ss1)  # of g1 = theta0 + pi + 2 atan(A1)
    span = math.pi + 2.0 * math.atan2(a1 - a0, 1.0 + a0 * a1)  # g1 - g0
    d2 = 2.0 * (sg1 * cg1 - sg0 * cg0)  # sin(2 g1) - sin(2 g0)
    rs = math.sqrt(s)
    i_sc = (0.5 * (sg1 * sg1 - sg0 * sg0) - eps * (cg1 - cg0)) / (s * s)
    i_cc = ((0.5 + eps * eps) * span + 0.25 * d2 + 2.0 * eps * (sg1 - sg0)) / (s * s * rs)
    i_ss = (0.5 * span - 0.25 * d2) / (s * rs)
    return i_sc, i_cc, i_ss


@kernel
def _short_bearing_polar(eps, eps_rate, whirl, omega_sum, scale):
    """(F_r, F_t) of :func:`short_bearing_force` for scalars, ``scale`` = mu R L^3 / c^2 (compiled; no checks)."""
    a = eps * (0.5 * omega_sum - whirl)
    b = -eps_rate
    # B = a sin + b cos = M cos(theta - theta_m), theta_m = atan2(a, b): negative on (theta_m + pi/2, + 3 pi/2),
    # whose start theta0 has cos theta0 = -sin theta_m = -a / M, sin theta0 = cos theta_m = b / M
    m = math.sqrt(a * a + b * b)
    if m == 0.0:  # no squeeze and no wedge: no pressure
        return 0.0, 0.0
    i_sc, i_cc, i_ss = _half_film_integrals(eps, -a / m, b / m)
    return scale * (a * i_sc + b * i_cc), scale * (a * i_ss + b * i_sc)


@kernel
def _short_bearing_xy(x, y, vx, vy, omega_sum, viscosity, radius, length, clearance):
    """(F_x, F_y) of :func:`short_bearing_force_xy` for scalars (compiled; no checks; eps < 1 assumed)."""
    r = math.sqrt(x * x + y * y)
    scale = viscosity * radius * length ** 3 / (clearance * clearance)
    if r < 1e-12 * clearance:
        f = -0.5 * math.pi * scale / clearance
        return f * vx, f * vy
    ux, uy = x / r, y / r
    fr, ft = _short_bearing_polar(r / clearance, (ux * vx + uy * vy) / clearance, (x * vy - y * vx) / (r * r),
                                  omega_sum, scale)
    return fr * ux - ft * uy, fr * uy + ft * ux


def _check_film(eccentricity, viscosity, radius, length, clearance, rates):
    """InputError for an eccentricity outside [0, 1), a non-positive property or a non-finite rate."""
    e = np.asarray(eccentricity, dtype=float)
    if not np.all(np.isfinite(e)) or np.any(e < 0.0) or np.any(e >= 1.0):
        raise InputError(f"eccentricity: must lie in [0, 1) (1: the film is crushed), got {eccentricity!r}")
    for name, v in (("viscosity", viscosity), ("radius", radius), ("length", length), ("clearance", clearance)):
        a = np.asarray(v, dtype=float)
        if not np.all(np.isfinite(a)) or np.any(a <= 0.0):
            raise InputError(f"{name}: must be finite and > 0, got {v!r}")
    for name, v in rates:
        if not np.all(np.isfinite(np.asarray(v, dtype=float))):
            raise InputError(f"{name}: must be finite, got {v!r}")


def short_bearing_force(eccentricity, eccentricity_rate, whirl_rate, omega_sum, viscosity, radius, length,
                        clearance):
    """Nonlinear force of a short journal-bearing film on the journal, along and across the line of centres
    [N] (Ocvirk [2]_; dynamic form of Childs [5]_ ch. 3, half film by Guembel's condition).

    The film h = c (1 - eps cos theta) (theta from the line of centres, the journal displaced by e = eps c
    towards theta = 0) between a journal and a bearing whose surfaces turn at omega_j and omega_b
    (``omega_sum`` = omega_j + omega_b); the line of centres turns at ``whirl_rate`` phi' and eps changes at
    ``eccentricity_rate`` eps'. Reynolds' equation without the circumferential pressure flow (L/D -> 0),
    integrated over the length L, gives the pressure

        P(theta) = -(mu L^3 / c^2) B(theta) / (1 - eps cos theta)^3,
        B = eps (omega_sum/2 - phi') sin theta - eps' cos theta,

    kept where it is positive (the half of the film where B < 0; the rest cavitates at ambient pressure).
    The force on the journal, F = -R int P (cos theta, sin theta) dtheta over that half, is

        F_r = (mu R L^3 / c^2) [a I_sc + b I_cc],   F_t = (mu R L^3 / c^2) [a I_ss + b I_sc],

    a = eps (omega_sum/2 - phi'), b = -eps', the integrals in closed form (:func:`_half_film_integrals`).
    Without squeeze (eps' = 0) the half film is theta in (pi, 2 pi) and

        F_r = -mu R L^3 (omega_sum - 2 phi') eps^2 / (c^2 (1 - eps^2)^2),
        F_t = pi mu R L^3 (omega_sum - 2 phi') eps / (4 c^2 (1 - eps^2)^(3/2)),

    Ocvirk's load components [2]_; the tangential one, ahead of the line of centres in the sense of
    omega_sum, is what drives whirl. For a pure squeeze (omega_sum = 2 phi') F_r = -(pi/2) mu R L^3 eps'
    (1 + 2 eps^2) / (c^2 (1 - eps^2)^(5/2)) [5]_.

    Parameters
    ----------
    eccentricity : float or ndarray
        eps in [0, 1): the film is crushed at 1 (a contact, not modelled here).
    eccentricity_rate : float or ndarray
        eps' [1/s].
    whirl_rate : float or ndarray
        phi' [rad/s], rate of the line of centres.
    omega_sum : float or ndarray
        omega_j + omega_b [rad/s], the two surfaces' angular speeds (the same sense counts positive).
    viscosity : float or ndarray
        Dynamic viscosity mu [Pa s] (> 0).
    radius, length, clearance : float or ndarray
        Journal radius R, film length L and radial clearance c [m] (> 0).

    Returns
    -------
    (F_r, F_t) [N]: along the line of centres (positive: away from the bearing centre, i.e. along the
    journal's displacement) and across it (positive: ahead of it by +90 deg).

    Examples
    --------
    >>> fr, ft = short_bearing_force(0.5, 0.0, 0.0, 100.0, 0.01, 0.03, 0.01, 1e-4)
    >>> round(float(fr), 4), round(float(ft), 4)   # -(4/9) and (pi/8) / 0.75**1.5 times mu w R L^3 / c^2 = 3
    (-1.3333, 1.8138)
    """
    _check_film(eccentricity, viscosity, radius, length, clearance,
                (("eccentricity_rate", eccentricity_rate), ("whirl_rate", whirl_rate), ("omega_sum", omega_sum)))
    scale = np.asarray(viscosity, float) * np.asarray(radius, float) * np.asarray(length, float) ** 3 \
        / np.asarray(clearance, float) ** 2
    return np.vectorize(_short_bearing_polar, otypes=[float, float])(eccentricity, eccentricity_rate, whirl_rate,
                                                                     omega_sum, scale)


def short_bearing_force_xy(x, y, vx, vy, omega_sum, viscosity, radius, length, clearance):
    """:func:`short_bearing_force` in Cartesian coordinates: the journal centre at (x, y) relative to the
    bearing centre with velocity (vx, vy) [m, m/s]; returns (F_x, F_y) [N] on the journal.

    eps = |r|/c, eps' = (r . v)/(c |r|), phi' = (x vy - y vx)/|r|^2; at the centre (r = 0) the film is
    concentric and carries no load, but a squeeze or a whirl velocity has a force there: the limit
    r -> 0 along v, F = -(pi/2) (mu R L^3 / c^3) v (the squeeze force of the concentric film [5]_), taken
    when |r| < 1e-12 c. A journal at |r| >= c (eps >= 1) is refused (``eccentricity``).

    Examples
    --------
    >>> fx, fy = short_bearing_force_xy(0.5e-4, 0.0, 0.0, 0.0, 100.0, 0.01, 0.03, 0.01, 1e-4)
    >>> round(float(fx), 4), round(float(fy), 4)
    (-1.3333, 1.8138)
    """
    c = np.asarray(clearance, dtype=float)
    _check_film(np.hypot(x, y) / c, viscosity, radius, length, clearance,
                (("vx", vx), ("vy", vy), ("omega_sum", omega_sum)))
    return np.vectorize(_short_bearing_xy, otypes=[float, float])(x, y, vx, vy, omega_sum, viscosity, radius,
                                                                  length, clearance)


def short_bearing_shear_torque(eccentricity, omega_rel, viscosity, radius, length, clearance):
    """Viscous shear torque of a full film between two cylinders [N m] on the faster surface, against its
    relative speed omega_rel = omega_j - omega_b: T = -2 pi mu R^3 L omega_rel / (c sqrt(1 - eps^2))
    (Couette shear of the eccentric film, Hamrock et al. [6]_ ch. 10; Petroff's 2 pi mu R^3 L omega / c at
    eps = 0). The film is taken full around the circumference for the shear (a land of a cage flooded with
    oil); the pressure's share of the torque, (eps c / 2) F_t [6]_, is not included: with the short
    bearing's F_t it is (L/R)^2 eps^2 / (16 (1 - eps^2)) of the shear (0.2 % at L/R = 0.3, eps = 0.5; 2.4 %
    at eps = 0.9).

    Examples
    --------
    >>> round(float(short_bearing_shear_torque(0.0, 100.0, 0.01, 0.03, 0.01, 1e-4)), 6)  # Petroff
    -0.016965
    """
    e = np.asarray(eccentricity, dtype=float)
    if not np.all(np.isfinite(e)) or np.any(e < 0.0) or np.any(e >= 1.0):
        raise InputError(f"eccentricity: must lie in [0, 1) (1: the film is crushed), got {eccentricity!r}")
    return (-2.0 * np.pi * np.asarray(viscosity, float) * np.asarray(radius, float) ** 3
            * np.asarray(length, float) * np.asarray(omega_rel, float)
            / (np.asarray(clearance, float) * np.sqrt(1.0 - e * e)))
