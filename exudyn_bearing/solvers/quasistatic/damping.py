"""Equivalent viscous damping matrix of the bearing at the operating point,
and the stiffness matrix by the same analytic condensation.

Per contact: the normal damping of the package's contact model,
:mod:`exudyn_bearing.physics.damping` (the relations the DEM contact kernel
uses, :func:`exudyn_bearing.model.contact._lubrication`), at the contact's
load Q, overlap delta, Hertz semi-major axis a and minimum film h_min of the
quasi-static solution:

* hysteretic C_hyst = (3/2) alpha_e K delta^(3/2) (Hunt & Crossley [1]_);
* squeeze film C_fluid = (3 pi eta a / sqrt 2) (R_b / h_min)^(3/2)
  (Guessasma & Machado [2]_);
* switched by Lambda = h_min / sigma: C_hyst at Lambda <= lambda_mixed
  (boundary; also every contact at zero speed, where h_min = 0), the series
  combination C_hyst C_fluid / (C_hyst + C_fluid) in the mixed regime,
  C_fluid in full film.

h_min is the Hamrock-Dowson minimum film of the solution (race-control
rolling speed; :func:`exudyn_bearing.physics.ehl.film_thickness_hamrock_dowson`).
The damper acts along the contact normal n (the DEM kernel's force
F_n = Q + C_n d(delta)/dt).

Condensation of each ball (its two in-plane coordinates c = (c_r, c_z)),
with the ball's inertia neglected (valid well below the ball's own
resonance on its two contacts, sqrt(k/m_b) ~ 1e5-1e6 rad/s for these
bearings). In the ball's (r, z) plane, per contact k the force on the ball
F_k = -Q_k n_k + F_tk t_k depends on c - p_k, p_k the groove centre; its
Jacobians are

    A_k = dF_k/dc = -k_n n n^T - (Q/L)(I - n n^T) + (F_t/L) R (I - n n^T),
    B_k = dF_k/dc' = -C_n n n^T,

k_n = (3/2) K delta^(1/2) the Hertz tangent stiffness, L = |c - p_k|, R the
quarter turn [[0, 1], [-1, 0]]; the centrifugal force m omega_m^2 c_r adds
M = diag(m omega_m^2, 0). The ball follows the inner groove centre p (the
ring moves it by J du, J the 2x5 matrix of :mod:`.balls`) with
dc = A^-1 A_i dp, A = A_o + A_i + M, so the force on the ring at one ball,
f = -F_i, has the dynamic stiffness (Laplace variable s)

    D(s) = A_i(s) (A(s)^-1 A_i(s) - I),   A_k(s) = A_k + s B_k,

and the ring's stiffness and damping are K = sum J^T D(0) J and
C = sum J^T D'(0) J, the first-order (low-frequency) terms: for collinear
contacts D'(0) = (C_i k_o^2 + C_o k_i^2) / (k_i + k_o)^2, the two
Kelvin-Voigt contacts in series. Neglected: the dependence of the Hertz
constant on the contact angle (the central-difference matrix of
:mod:`.stiffness` includes it; the two stiffness matrices agree to 3e-9 of
the largest entry at zero contact angle and 2e-5 to 5e-4 with contact
angles, tests/test_stiffness.py), the balls' inertia, friction (its
tangential forces are not a viscous term of this model; the DEM check in
validation/stiffness_checks.py measures what it adds) and the higher powers
of s, which change K and C by O((omega C_n/k_n)^2): C_n/k_n is about 1e-6 s
for the 6208's contacts, 4e-3 at 10 kHz.

References
----------
.. [1] K. H. Hunt and F. R. E. Crossley, "Coefficient of restitution
   interpreted as damping in vibroimpact," J. Appl. Mech. 42(2) (1975)
   440-445. doi:10.1115/1.3423596
.. [2] S. Guessasma and C. Machado, Lubricants 6 (2018) 46.
   doi:10.3390/lubricants6020046
.. [3] A. B. Jones, J. Basic Eng. 82 (1960) 309-320 (the ring kinematics J).

Theory notes: docs/theory/vibration.md, "Linearised bearing".
"""
from __future__ import annotations

import math

import numpy as np

from ...physics import damping as _dmp
from .balls import B_CR, B_CZ, B_DI, B_DO, B_KI, B_KO, B_NIR, B_NIZ, B_NOR, B_NOZ, B_QI, B_QO

__all__ = ["CONTACT_DAMPING_FIELDS", "contact_damping", "ring_jacobian", "condensed_matrices"]

#: Per-contact damping fields of :func:`contact_damping` (each with suffix _inner / _outer).
CONTACT_DAMPING_FIELDS = ("c_normal", "c_hysteretic", "c_squeeze", "film_parameter", "regime")

_R90 = np.array([[0.0, 1.0], [-1.0, 0.0]])


def contact_damping(balls, a_inner, a_outer, h_inner, h_outer, r_ball, alpha_e, lubricant):
    """Normal damping of every ball / race contact [N s/m] (module docstring).

    Parameters
    ----------
    balls : array (Z, NB)
        Per-ball table of :func:`.balls.ring_forces`.
    a_inner, a_outer : array (Z,)
        Hertz semi-major axes [m].
    h_inner, h_outer : array (Z,)
        Minimum film thickness [m] (0: no film, boundary).
    r_ball : float
        Ball radius [m].
    alpha_e : float
        Hunt-Crossley coefficient [s/m].
    lubricant : Lubricant
        Viscosity, composite roughness and the Lambda breakpoints.

    Returns
    -------
    dict with ``c_normal_inner`` ... ``regime_outer`` (Z,) arrays
    (:data:`CONTACT_DAMPING_FIELDS`; regime codes 0 boundary, 1 mixed,
    2 full film, -1 no contact).
    """
    out = {}
    lub = lubricant
    for tag, q, d, k, a, h in (("inner", balls[:, B_QI], balls[:, B_DI], balls[:, B_KI], a_inner, h_inner),
                               ("outer", balls[:, B_QO], balls[:, B_DO], balls[:, B_KO], a_outer, h_outer)):
        q = np.asarray(q, float)
        h = np.maximum(np.asarray(h, float), 0.0)
        loaded = q > 0.0
        c_h = np.where(loaded, _dmp.damping_hysteretic(k, d, alpha_e), 0.0)
        lam = h / lub.composite_roughness
        regime = np.where(loaded, _dmp.lubrication_regime(lam, lub.lambda_mixed, lub.lambda_full_film), -1)
        # no film (h = 0): C_fluid is unbounded and the regime is boundary, where C_n = C_hyst
        c_f = np.where(h > 0.0, _dmp.damping_fluid(lub.viscosity, np.asarray(a, float), r_ball,
                                                   np.where(h > 0.0, h, 1.0)), np.inf)
        c_n = _dmp.damping_coefficient(lam, c_h, c_f, lub.lambda_mixed, lub.lambda_full_film)
        out[f"c_normal_{tag}"] = np.where(loaded, c_n, 0.0)
        out[f"c_hysteretic_{tag}"] = c_h
        out[f"c_squeeze_{tag}"] = np.where(np.isfinite(c_f), c_f, np.nan)
        out[f"film_parameter_{tag}"] = lam
        out[f"regime_{tag}"] = regime.astype(float)
    return out


def ring_jacobian(psi, rho_i, z_i):
    """J (2, 5): in-plane motion (Delta r, Delta z) of the inner groove centre
    at azimuth psi per ring DOF (delta_x, delta_y, delta_a, tilt_x, tilt_y)
    (:mod:`.balls`, Jones [3]_)."""
    c, s = math.cos(psi), math.sin(psi)
    return np.array([[c, s, 0.0, -z_i * s, z_i * c],
                     [0.0, 0.0, 1.0, rho_i * s, -rho_i * c]])


def _contact_jacobians(n, q, k_t, length, f_t, c_n):
    """A = dF/dc and B = dF/dc' of one contact's force on the ball (module docstring)."""
    nn = np.outer(n, n)
    perp = np.eye(2) - nn
    a = -k_t * nn - (q / length) * perp + (f_t / length) * (_R90 @ perp)
    b = -c_n * nn
    return a, b


def condensed_matrices(psi, geom, u, balls, m_w2, fto, fti, c_inner, c_outer):
    """Stiffness and damping of the ring (5x5 each) by condensing every ball
    (module docstring).

    Parameters
    ----------
    psi : array (Z,)
        Ball azimuths [rad].
    geom : OperatingGeometry
    u : array (5,)
        Ring pose of the solution.
    balls : array (Z, NB)
        Per-ball table at that pose.
    m_w2 : array (Z,)
        m omega_m^2 of every ball [N/m].
    fto, fti : array (Z,)
        Tangential (gyroscopic) traction at the outer and inner contact [N].
    c_inner, c_outer : array (Z,)
        Normal damping of the contacts [N s/m].

    Returns
    -------
    (K, C): K = -dG/du [N/m, N/rad, N, N m/rad], C = -dG/du' [N s/m, ...],
    G the balls' generalized force on the ring.
    """
    kk = np.zeros((5, 5))
    cc = np.zeros((5, 5))
    eye = np.eye(2)
    for j in range(psi.size):
        qi, qo = balls[j, B_QI], balls[j, B_QO]
        if qi <= 0.0:
            continue  # the ring does not touch this ball
        cr, cz = balls[j, B_CR], balls[j, B_CZ]
        di, do = balls[j, B_DI], balls[j, B_DO]
        ni = np.array([balls[j, B_NIR], balls[j, B_NIZ]])
        no = np.array([balls[j, B_NOR], balls[j, B_NOZ]])
        jac = ring_jacobian(psi[j], geom.rho_i, geom.z_i)
        pir, piz = np.array([geom.rho_i, geom.z_i]) + jac @ np.asarray(u, float)
        li = math.hypot(cr - pir, cz - piz)
        lo = math.hypot(cr - geom.rho_o, cz - geom.z_o)
        kti = 1.5 * balls[j, B_KI] * math.sqrt(di)
        a_i, b_i = _contact_jacobians(ni, qi, kti, li, fti[j], c_inner[j])
        if qo > 0.0:
            kto = 1.5 * balls[j, B_KO] * math.sqrt(do)
            a_o, b_o = _contact_jacobians(no, qo, kto, lo, fto[j], c_outer[j])
        else:
            a_o, b_o = np.zeros((2, 2)), np.zeros((2, 2))
        a = a_o + a_i + np.diag([m_w2[j], 0.0])
        b = b_o + b_i
        ainv = np.linalg.inv(a)
        x = ainv @ a_i
        d0 = a_i @ (x - eye)
        d1 = b_i @ (x - eye) + a_i @ (-ainv @ b @ x + ainv @ b_i)
        kk += jac.T @ d0 @ jac
        cc += jac.T @ d1 @ jac
    return kk, cc
