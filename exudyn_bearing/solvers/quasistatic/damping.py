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
validation/consistency/stiffness_checks.py measures what it adds) and the higher powers
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

from ..._jit import kernel
from ...physics.damping import _damping_fluid, _damping_hysteretic, damping_coefficient, lubrication_regime
from ...physics.ehl import _film_hd_ln_g
from ...physics.hertz import _curvature_sum_radius, _kfe_fast, _semi_axes_overlap
from .balls import (B_CR, B_CZ, B_DI, B_DO, B_KI, B_KO, B_NIR, B_NIZ, B_NOR, B_NOZ, B_QI, B_QO, _condense,
                    _contact_jacobians, _contact_radii, _mul)

__all__ = ["CONTACT_DAMPING_FIELDS", "contact_damping", "ring_jacobian", "condensed_matrices", "normal_damping",
           "ball_condensation", "ring_damping_force"]

#: Per-contact damping fields of :func:`contact_damping` (each with suffix _inner / _outer).
CONTACT_DAMPING_FIELDS = ("c_normal", "c_hysteretic", "c_squeeze", "film_parameter", "regime")



@kernel(no_runtime=True)
def normal_damping(q, delta, k, major, h, r_ball, alpha_e, eta, sigma, lambda_mixed, lambda_full_film):
    """Normal damping of one contact (module docstring; the law of
    :mod:`exudyn_bearing.physics.damping`, switched as in the DEM kernel's
    :func:`exudyn_bearing.model.contact._lubrication_film`).

    q [N], delta [m], k [N/m^1.5]: load, overlap and Hertz constant; major [m]: semi-major axis; h [m]: minimum
    film (0: none); r_ball [m]; alpha_e [s/m]; eta [Pa s]; sigma [m]: composite roughness; the Lambda breakpoints.
    Returns (C_n, C_hyst, C_fluid, Lambda, regime) [N s/m, N s/m, N s/m, -, code]: C_fluid 0 without a film
    (unbounded there; the regime is then boundary), all zero and regime -1 for an open contact (q <= 0).
    """
    if q <= 0.0:
        return 0.0, 0.0, 0.0, 0.0, -1
    c_h = _damping_hysteretic(k, delta, alpha_e)
    h = max(h, 0.0)
    lam = h / sigma
    regime = lubrication_regime(lam, lambda_mixed, lambda_full_film)
    if h <= 0.0:
        return c_h, c_h, 0.0, lam, regime
    c_f = _damping_fluid(eta, major, r_ball, h)
    return damping_coefficient(lam, c_h, c_f, lambda_mixed, lambda_full_film), c_h, c_f, lam, regime


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
        res = np.array([normal_damping(float(q[j]), float(d[j]), float(k[j]), float(a[j]), float(h[j]), r_ball,
                                       alpha_e, lub.viscosity, lub.composite_roughness, lub.lambda_mixed,
                                       lub.lambda_full_film) for j in range(len(q))]).reshape(-1, 5)
        out[f"c_normal_{tag}"] = res[:, 0]
        out[f"c_hysteretic_{tag}"] = res[:, 1]
        out[f"c_squeeze_{tag}"] = np.where(res[:, 2] > 0.0, res[:, 2], np.nan)  # NaN: no film or no contact
        out[f"film_parameter_{tag}"] = np.maximum(np.asarray(h, float), 0.0) / lub.composite_roughness
        out[f"regime_{tag}"] = res[:, 4]
    return out


def ring_jacobian(psi, rho_i, z_i):
    """J (2, 5): in-plane motion (Delta r, Delta z) of the inner groove centre
    at azimuth psi per ring DOF (delta_x, delta_y, delta_a, tilt_x, tilt_y)
    (:mod:`.balls`, Jones [3]_)."""
    c, s = math.cos(psi), math.sin(psi)
    return np.array([[c, s, 0.0, -z_i * s, z_i * c],
                     [0.0, 0.0, 1.0, rho_i * s, -rho_i * c]])


@kernel(no_runtime=True)
def ball_condensation(no_r, no_z, q_o, k_to, l_o, f_to, c_o, ni_r, ni_z, q_i, k_ti, l_i, f_ti, c_i, m_w2):
    """Dynamic stiffness of one ball between the rings, D(0) and D'(0) (module docstring; row-major 4-tuples).

    Per contact (outer, inner): the normal n (groove centre to ball centre), load Q [N], tangent stiffness
    k_t = dQ/d delta [N/m], groove-centre distance L = |c - p| [m], tangential traction F_t [N] and normal
    damping C_n [N s/m]; m_w2 = m omega_m^2 [N/m]. An open outer contact: Q_o = k_to = C_o = F_to = 0."""
    a_o, b_o = _contact_jacobians(no_r, no_z, q_o, k_to, l_o, f_to, c_o)
    a_i, b_i = _contact_jacobians(ni_r, ni_z, q_i, k_ti, l_i, f_ti, c_i)
    b = (b_o[0] + b_i[0], b_o[1] + b_i[1], b_o[2] + b_i[2], b_o[3] + b_i[3])
    ainv, x = _condense(a_o, a_i, m_w2)
    xmi = (x[0] - 1.0, x[1], x[2], x[3] - 1.0)
    d0 = _mul(a_i, xmi)
    bx = _mul(b, x)
    ab = _mul(_mul(a_i, ainv), (b_i[0] - bx[0], b_i[1] - bx[1], b_i[2] - bx[2], b_i[3] - bx[3]))
    bi = _mul(b_i, xmi)
    d1 = (bi[0] + ab[0], bi[1] + ab[1], bi[2] + ab[2], bi[3] + ab[3])
    return d0, d1


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
    for j in range(psi.size):
        qi, qo = balls[j, B_QI], balls[j, B_QO]
        if qi <= 0.0:
            continue  # the ring does not touch this ball
        cr, cz = balls[j, B_CR], balls[j, B_CZ]
        jac = ring_jacobian(psi[j], geom.rho_i, geom.z_i)
        pir, piz = np.array([geom.rho_i, geom.z_i]) + jac @ np.asarray(u, float)
        li = math.hypot(cr - pir, cz - piz)
        lo = math.hypot(cr - geom.rho_o, cz - geom.z_o)
        kti = 1.5 * balls[j, B_KI] * math.sqrt(balls[j, B_DI])
        kto, fo, co = ((1.5 * balls[j, B_KO] * math.sqrt(balls[j, B_DO]), fto[j], c_outer[j]) if qo > 0.0
                       else (0.0, 0.0, 0.0))
        d0, d1 = ball_condensation(balls[j, B_NOR], balls[j, B_NOZ], max(qo, 0.0), kto, lo, fo, co, balls[j, B_NIR],
                                   balls[j, B_NIZ], qi, kti, li, fti[j], c_inner[j], m_w2[j])
        kk += jac.T @ np.reshape(d0, (2, 2)) @ jac
        cc += jac.T @ np.reshape(d1, (2, 2)) @ jac
    return kk, cc


@kernel(no_runtime=True)
def _state_damping(q, delta, k, r_x, r_y, u_r, r_ball, e_prime, method, table, alpha_e, eta, ln_g, sigma,
                   lambda_mixed, lambda_full_film):
    """:func:`normal_damping` of one contact at its current state: semi-major axis from the overlap
    (:func:`exudyn_bearing.physics.hertz._semi_axes_overlap`) and the Hamrock-Dowson minimum film at the rolling
    speed u_r [m/s] (the film of :func:`.solve.solve_quasistatic`); ``table``: Hertz constants as in
    :func:`.balls._hertz_constant`; ln_g = ln(xi E')."""
    kappa, ell_f, ell_e = _kfe_fast(r_x, r_y, method, table)
    major = _semi_axes_overlap(kappa, ell_f, ell_e, _curvature_sum_radius(r_x, r_y), delta)[0]
    h = _film_hd_ln_g(u_r, q, r_x, kappa, e_prime, eta, ln_g)
    return normal_damping(q, delta, k, major, h, r_ball, alpha_e, eta, sigma, lambda_mixed, lambda_full_film)[0]


@kernel(no_runtime=True)
def ring_damping_force(rates, cos_psi, sin_psi, rho_i, z_i, rho_o, z_o, rci, rco, rb, balls, m_w2, fto, fti, w_orbit,
                       w_ring, e_prime, method, table, alpha_e, eta, ln_g, sigma, lambda_mixed, lambda_full_film, out,
                       mats):
    """Damping force of the balls on the inner ring at their current state, -C u' with C = sum_j J^T D'(0) J
    (module docstring), into ``out`` (5,) [N, N m]; with ``mats`` of size 50 also the ring's stiffness
    K = sum_j J^T D(0) J (row-major, mats[:25]) and damping C (mats[25:]) of the same condensation
    (:func:`condensed_matrices`' K and C at the balls' current state; size 0: not computed).

    rates: u' (5,), the pose rates (the ring's velocity and tilt rates against the outer ring); cos_psi, sin_psi
    (Z,) (cos and sin of the balls' azimuths psi), balls (Z, NB), m_w2, fto, fti (Z,): the ball set as
    :func:`.balls._ring_forces` left it for the current pose; the
    grooves (rho_i, z_i, rho_o, z_o, R_ci, R_co, R_b) [m]; w_orbit, w_ring [rad/s]: the balls' orbital speed and
    the inner ring's speed against the outer ring, which give each contact's rolling speed |w_race - w_orbit| r
    (pure rolling at the contact centre, radius r = c_r + R_b n_r); e_prime, method, table: the Hertz constants'
    (:func:`.balls._hertz_constant`); the contact damping law's parameters (:func:`normal_damping`;
    ln_g = ln(xi E')). A ball that does not touch the inner ring adds nothing. Neglected, as in
    :func:`condensed_matrices`: the approach the ball's orbit past a displaced ring adds (a force of order
    C_n e omega_c, e the ring's displacement, 0.5 N per ball for the 6208 at 3000 N and 500 rad/s)."""
    for k in range(5):
        out[k] = 0.0
    both = mats.size == 50
    if both:
        for k in range(50):
            mats[k] = 0.0
    for j in range(cos_psi.size):
        qi = balls[j, B_QI]
        if qi <= 0.0:
            continue
        qo = balls[j, B_QO]
        cr = balls[j, B_CR]
        nor, noz, nir, niz = balls[j, B_NOR], balls[j, B_NOZ], balls[j, B_NIR], balls[j, B_NIZ]
        di, do = balls[j, B_DI], balls[j, B_DO]
        rxo, ryo, rxi, ryi = _contact_radii(rho_o, rco, rb, rci, nor, nir)
        ci = _state_damping(qi, di, balls[j, B_KI], rxi, ryi, abs(w_ring - w_orbit) * (cr + rb * nir), rb, e_prime,
                            method, table, alpha_e, eta, ln_g, sigma, lambda_mixed, lambda_full_film)
        kti = 1.5 * balls[j, B_KI] * math.sqrt(di)
        if qo > 0.0:
            co = _state_damping(qo, do, balls[j, B_KO], rxo, ryo, abs(w_orbit) * (cr + rb * nor), rb, e_prime,
                                method, table, alpha_e, eta, ln_g, sigma, lambda_mixed, lambda_full_film)
            kto = 1.5 * balls[j, B_KO] * math.sqrt(do)
            f_to = fto[j]
        else:
            qo = co = kto = f_to = 0.0
        d0, d1 = ball_condensation(nor, noz, qo, kto, rco - rb + do, f_to, co, nir, niz, qi, kti, rci - rb + di,
                                   fti[j], ci, m_w2[j])
        c = cos_psi[j]
        s = sin_psi[j]
        if both:  # J^T D J, J the ring Jacobian of ring_jacobian
            jr = (c, s, 0.0, -z_i * s, z_i * c)
            jz = (0.0, 0.0, 1.0, rho_i * s, -rho_i * c)
            for a in range(5):
                ka_r = jr[a] * d0[0] + jz[a] * d0[2]
                ka_z = jr[a] * d0[1] + jz[a] * d0[3]
                ca_r = jr[a] * d1[0] + jz[a] * d1[2]
                ca_z = jr[a] * d1[1] + jz[a] * d1[3]
                for b in range(5):
                    mats[5 * a + b] += ka_r * jr[b] + ka_z * jz[b]
                    mats[25 + 5 * a + b] += ca_r * jr[b] + ca_z * jz[b]
        # J u': the inner groove centre's velocity in the ball's plane; the force -D'(0) J u', returned by J^T
        vr = rates[0] * c + rates[1] * s + z_i * (rates[4] * c - rates[3] * s)
        vz = rates[2] + rho_i * (rates[3] * s - rates[4] * c)
        fr = -(d1[0] * vr + d1[1] * vz)
        fz = -(d1[2] * vr + d1[3] * vz)
        out[0] += fr * c
        out[1] += fr * s
        out[2] += fz
        out[3] += -z_i * s * fr + rho_i * s * fz
        out[4] += z_i * c * fr - rho_i * c * fz
