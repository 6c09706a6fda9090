"""Ball kinematics on a solved contact geometry: race control (Jones) and the
minimum-energy hypothesis (Gupta), with the slip, traction and dissipation of
both contacts.

Frame: the ball's orbit frame, turning with the ball's orbital speed
omega_m about the bearing axis, in which the ball centre c = (c_r, c_z) is at
rest. Unknowns per ball: omega_m and the ball's angular velocity w = (w_r,
w_z) in that frame (no yaw: w lies in the ball's (r, z) plane); the spin-axis
angle to the bearing axis is beta = atan2(-sigma w_r, sigma w_z), sigma =
sign(w_z) (beta = alpha when w is perpendicular to a contact line at alpha).
A race k turns at Omega_k = omega_k - omega_m in this frame.

Contact k (normal n_k from its groove centre to c, contact centre X_k = c +
R_b n_k, in-plane tangent t_k = (n_z, -n_r)): the slip of the ball against
the race along the rolling direction e_psi, at a distance y along t_k on
the pressed surface of radius R_d (:func:`~exudyn_bearing.physics.contact_slip.deformed_contact_radius`) is

    v_x(y) = v0 + omega_s y + omega_roll y^2 / (2 R_d)
    v0 = R_b (w_z n_r - w_r n_z) - Omega_k X_r
    omega_s = (w - Omega_k e_z) . n_k          spin about the normal
    omega_roll = (w - Omega_k e_z) . t_k       rolling angular speed

(rigid-body velocities of ball and race at the same point of the pressed
surface; Harris & Kotzalas [2]_), handed to
:func:`exudyn_bearing.physics.contact_slip._contact_traction` as v0, w_n =
-omega_s (its e_z is -n_k), c2 = omega_roll / (2 R_d), with the rolling
speed u = |ball + race surface speed| / 2 at the centre.

* **Race control** (Jones [1]_): pure rolling at both contact centres
  (v0_o = v0_i = 0) and no spin at the controlling race (omega_s = 0
  there): three linear equations in (omega_m, w_r, w_z). ``"auto"`` picks
  the race by Jones' criterion on the Coulomb spin moments: outer control if
  Q_o a_o E(e_o) cos(alpha_o - alpha_i) > Q_i a_i E(e_i) (Harris & Kotzalas
  [2]_). The gyroscopic moment is carried by traction at the controlling race.
* **Minimum energy** (Gupta [3]_): the kinematics that minimise the total
  dissipation P_o + P_i of the two contacts for the traction model, the
  contact loads and ellipses held fixed. Gupta scans the pure-rolling points
  x1 (outer), x2 (inner) and beta; x1, x2, beta and (omega_m, w_r, w_z) map
  one-to-one where pure-rolling points exist, and the velocities have no
  double root (two pure-rolling points on one contact give the same
  motion), so the minimisation runs over the velocities (scipy Nelder-Mead
  from the race-control point) and reports x1, x2, beta of the result. The
  minimum is checked by a finite-difference Hessian and by its six
  neighbours. The gyroscopic moment is split equally between the races
  (Harris' lambda_o = lambda_i = 1 when no race controls).

References
----------
.. [1] A. B. Jones, "Ball motion and sliding friction in ball bearings,"
   J. Basic Eng. 81 (1959) 1-12. doi:10.1115/1.4008346
.. [2] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed.,
   CRC Press, 2006, Advanced Concepts ch. 'High-speed operation' and
   'Friction in rolling element-raceway contacts'.
.. [3] P. K. Gupta, "Minimum energy hypothesis in quasi-static equilibrium
   solutions for angular contact ball bearings," Tribol. Trans. (2020).
"""
from __future__ import annotations

import math

import numpy as np
from scipy import optimize

from ..._jit import kernel
from ...physics.contact_slip import _contact_traction, pure_rolling_points, spin_moment_coulomb

__all__ = ["CONTROLS", "GEO_FIELDS", "CONTACT_FIELDS", "race_control", "jones_outer_controls", "ball_contacts",
           "minimum_energy", "traction_equilibrium", "dissipation_at_beta", "spin_axis_angle", "rolling_points",
           "axial_torque_on_ball", "cage_kinematics"]

#: Kinematic hypotheses.
CONTROLS = ("outer", "inner", "auto", "min-energy", "equilibrium")
#: Entries of the packed per-ball geometry vector ``geo``.
GEO_FIELDS = ("omega_o", "omega_i", "c_r", "c_z", "no_r", "no_z", "ni_r", "ni_z", "r_b", "rd_o", "rd_i",
              "a_o", "b_o", "q_o", "a_i", "b_i", "q_i", "hc_o", "hm_o", "hc_i", "hm_i", "u_min")
(G_WO, G_WI, G_CR, G_CZ, G_NOR, G_NOZ, G_NIR, G_NIZ, G_RB, G_RDO, G_RDI, G_AO, G_BO, G_QO, G_AI, G_BI, G_QI,
 G_HCO, G_HMO, G_HCI, G_HMI, G_UMIN) = range(len(GEO_FIELDS))
#: Per-contact results of :func:`ball_contacts` (row 0 outer, row 1 inner).
CONTACT_FIELDS = ("v0", "w_n", "c2", "u", "spin", "roll", "f_x", "f_y", "m_z", "dissipation", "qv", "m_y")
NC = len(CONTACT_FIELDS)
#: Traction equilibrium: largest relative change of the speeds in one step of the continuation in the
#: ball's inertia that stays on the branch, and the smallest step (a fold below it: no equilibrium).
CONTINUATION_JUMP = 0.2
CONTINUATION_MIN_STEP = 1e-3


@kernel
def _slip_inputs(w_r, w_z, omega_m, omega_ring, cr, nr, nz, rb, rd):
    big = omega_ring - omega_m
    x0r = cr + rb * nr
    ball = rb * (w_z * nr - w_r * nz)
    race = big * x0r
    spin = w_r * nr + w_z * nz - big * nz
    roll = w_r * nz - (w_z - big) * nr
    return ball - race, -spin, roll / (2.0 * rd), 0.5 * abs(ball + race), spin, roll


@kernel
def _ball_contacts(omega_m, w_r, w_z, v_t, geo, code, params, n_strips, n_across, out):
    """Slip and traction of both contacts of one ball; rows of ``out`` (2, NC):
    outer, inner. ``v_t``: transverse slip at both contact centres from the
    ball's yaw (pivoting) w_psi, v_t = R_b w_psi. The traction law sees the rolling speed u, at least
    ``geo[G_UMIN]`` (0: none; the dynamic engines' ``regularizing_speed`` to reproduce their least rolling
    speed); ``out`` reports u itself. Returns the total dissipation [W]."""
    total = 0.0
    for k in range(2):
        if k == 0:
            wring, nr, nz, rd, a, b, q, hc, hm = (geo[G_WO], geo[G_NOR], geo[G_NOZ], geo[G_RDO], geo[G_AO],
                                                  geo[G_BO], geo[G_QO], geo[G_HCO], geo[G_HMO])
        else:
            wring, nr, nz, rd, a, b, q, hc, hm = (geo[G_WI], geo[G_NIR], geo[G_NIZ], geo[G_RDI], geo[G_AI],
                                                  geo[G_BI], geo[G_QI], geo[G_HCI], geo[G_HMI])
        v0, wn, c2, u, spin, roll = _slip_inputs(w_r, w_z, omega_m, wring, geo[G_CR], nr, nz, geo[G_RB], rd)
        fx, fy, mz, p, qv, my = _contact_traction(a, b, q, v0, wn, c2, rd, v_t, max(u, geo[G_UMIN]), hc, hm, code,
                                                  params, n_strips, n_across)
        out[k, 0] = v0
        out[k, 1] = wn
        out[k, 2] = c2
        out[k, 3] = u
        out[k, 4] = spin
        out[k, 5] = roll
        out[k, 6] = fx
        out[k, 7] = fy
        out[k, 8] = mz
        out[k, 9] = p
        out[k, 10] = qv
        out[k, 11] = my
        total += p
    return total


def ball_contacts(kin, geo, model, n_strips, n_across):
    """Per-contact slip and traction (2, NC) for kinematics kin = (omega_m, w_r, w_z[, v_t])."""
    out = np.zeros((2, NC))
    v_t = float(kin[3]) if len(kin) > 3 else 0.0
    _ball_contacts(float(kin[0]), float(kin[1]), float(kin[2]), v_t, geo, model.code, model.vector, n_strips,
                   n_across, out)
    return out


def axial_torque_on_ball(contact, c_r, r_b, nr, nz):
    """Torque about the bearing axis [N m] that one contact's traction exerts on the ball: the
    rolling-direction force F_x at the contact radius c_r + R_b n_r, the spin moment M_z about
    e_z = -n and the curvature moment M_y about t = (n_z, -n_r) (``contact`` a row of
    :func:`ball_contacts`). Its reaction acts on the race, so it is the torque that drives the race:
    in a steady orbit sum_k torque_k omega_k = the contacts' dissipation (the balls take no power)."""
    return (contact[6] * (c_r + r_b * nr) - contact[8] * nz - contact[11] * nr)


def spin_axis_angle(w_r, w_z):
    """beta [rad]: angle of the ball's spin axis to the bearing axis (module docstring)."""
    sigma = -1.0 if w_z < 0.0 else 1.0
    return math.atan2(-sigma * w_r, sigma * w_z)


def race_control(geo, race):
    """(omega_m, w_r, w_z) of race control by ``race`` ('outer' or 'inner'): pure rolling at both
    contact centres and no spin at the controlling race (Jones)."""
    rows, rhs = [], []
    for k, (wring, nr, nz) in enumerate(((geo[G_WO], geo[G_NOR], geo[G_NOZ]), (geo[G_WI], geo[G_NIR], geo[G_NIZ]))):
        x0r = geo[G_CR] + geo[G_RB] * nr
        rows.append([x0r, -geo[G_RB] * nz, geo[G_RB] * nr])          # v0 = 0
        rhs.append(wring * x0r)
        if (race == "outer") == (k == 0):
            rows.append([nz, nr, nz])                                # omega_s = 0
            rhs.append(wring * nz)
    return np.linalg.solve(np.array(rows), np.array(rhs))


def jones_outer_controls(geo):
    """Jones' criterion: True if the outer race controls, Q_o a_o E_o cos(alpha_o - alpha_i) > Q_i a_i E_i."""
    a_o = math.atan2(geo[G_NOZ], geo[G_NOR])
    a_i = math.atan2(-geo[G_NIZ], -geo[G_NIR])
    m_o = float(spin_moment_coulomb(1.0, geo[G_QO], geo[G_AO], geo[G_BO])) if geo[G_QO] > 0 else 0.0
    m_i = float(spin_moment_coulomb(1.0, geo[G_QI], geo[G_AI], geo[G_BI])) if geo[G_QI] > 0 else 0.0
    return m_o * math.cos(a_o - a_i) > m_i


def rolling_points(contacts, geo):
    """Pure-rolling points (x1 outer, x2 inner) [m]: the one nearest each contact centre, NaN where the
    contact slides everywhere."""
    res = []
    for k, a in ((0, geo[G_AO]), (1, geo[G_AI])):
        v0, wn, c2 = contacts[k, 0], contacts[k, 1], contacts[k, 2]
        pts = pure_rolling_points(a, v0, wn, c2) if a > 0 else np.array([])
        res.append(float(pts[np.argmin(np.abs(pts))]) if pts.size else math.nan)
    return res


def _check_minimum(f, x, h):
    """Finite-difference Hessian eigenvalues (relative to f(x)) and whether all axis neighbours (2 n) are higher."""
    f0 = f(x)
    n = x.size
    hess = np.zeros((n, n))
    higher = True
    for i in range(n):
        ei = np.zeros(n)
        ei[i] = h
        fp, fm = f(x + ei), f(x - ei)
        higher &= bool(fp >= f0 and fm >= f0)
        hess[i, i] = (fp - 2.0 * f0 + fm) / (h * h)
        for j in range(i + 1, n):
            ej = np.zeros(n)
            ej[j] = h
            hess[i, j] = hess[j, i] = (f(x + ei + ej) - f(x + ei - ej) - f(x - ei + ej) + f(x - ei - ej)) / (
                4.0 * h * h)
    eig = np.linalg.eigvalsh(hess) / max(abs(f0), 1e-300)
    return eig, higher


def minimum_energy(geo, model, n_strips, n_across, start, omega_m=None):
    """Kinematics that minimise P_o + P_i (Gupta's hypothesis) from ``start`` = (omega_m, w_r, w_z).

    With ``omega_m`` given (a ball its cage pocket holds at the cage speed: docs/theory/quasistatic.md, "The
    rigid cage") the orbital speed is that one and the minimum is over the ball's spin (w_r, w_z) alone; else
    over all three (Gupta 2020).

    Returns (kinematics (3,), check dict with ``hessian_eigenvalues`` (relative, in the scaled
    variables), ``neighbours_higher``, ``is_minimum``, ``evaluations``)."""
    start = np.asarray(start, float)[:3].copy()
    if omega_m is not None:
        start[0] = float(omega_m)
    scale = max(abs(start[0]), math.hypot(start[1], start[2]), 1e-12)
    code, vec = model.code, model.vector
    out = np.zeros((2, NC))
    held = omega_m is not None
    x0 = (start[1:] if held else start) / scale
    f0 = _ball_contacts(start[0], start[1], start[2], 0.0, geo, code, vec, n_strips, n_across, out)
    norm = f0 if f0 > 0 else 1.0

    def kin(x):
        return np.concatenate([[start[0]], x * scale]) if held else x * scale

    def f(x):
        k = kin(x)
        return _ball_contacts(k[0], k[1], k[2], 0.0, geo, code, vec, n_strips, n_across, out) / norm

    n = x0.size
    simplex = np.vstack([x0] + [x0 + 2e-3 * np.eye(n)[i] for i in range(n)])
    res = optimize.minimize(f, x0, method="Nelder-Mead",
                            options={"initial_simplex": simplex, "xatol": 1e-11, "fatol": 1e-13, "maxiter": 6000,
                                     "maxfev": 12000})
    eig, higher = _check_minimum(f, res.x, 1e-5)
    check = {"hessian_eigenvalues": eig.tolist(), "neighbours_higher": higher,
             "is_minimum": bool(higher and eig.min() > 0.0), "evaluations": int(res.nfev),
             "converged": bool(res.success)}
    return kin(res.x), check


def traction_equilibrium(geo, model, n_strips, n_across, start, inertia, omega_m=None, pocket_friction=0.0,
                         pocket_film=None):
    """Kinematics at which the traction of both contacts holds the ball in a
    steady orbit, without a kinematic hypothesis: (omega_m, w_r, w_z, v_t)
    with v_t = R_b w_psi the transverse slip of the ball's yaw (pivoting), from

    * the gyroscopic moment: R_b (F_y,o + F_y,i) = J omega_m w_r, the moment
      about e_psi that turns the spin axis with the orbit, carried by the
      transverse tractions F_y along t_k = e_psi x n_k (Harris & Kotzalas
      [2]_); for given (omega_m, w_r, w_z) it fixes v_t (the root nearest
      zero: the traction rises from zero with the slip);
    * no net traction along the orbit (a cageless ball): F_x,o + F_x,i = 0;
    * the in-plane moment: sum_k F_x,k R_b (-n_z, n_r) - M_z,k (n_r, n_z)
      + M_y,k (n_z, -n_r) = (-J omega_m w_psi, 0) (the rolling-direction
      tractions at their levers, the spin moments about the contact normals
      and the curvature moments about t_k, r and z components, turn the yaw
      component of the spin with the orbit).

    These are the ball's Newton-Euler equations in a steady orbit (all balls
    alike, as under thrust): a dynamic run with the same traction model
    settles there. The three outer equations are solved with scipy's hybrid
    Powell method from ``start`` (omega_m, w_r, w_z[, v_t]), v_t inside by
    Brent's method. Returns (kinematics (4,), check dict with the scaled
    residual, convergence and whether the gyroscopic moment could be held).

    In a cage (``omega_m`` given: the cage's orbital speed, docs/theory/quasistatic.md#the-rigid-cage)
    the orbital speed is not an unknown: the pocket force Q_p = -(F_x,o + F_x,i) along the orbit
    (positive pushing the ball forward) takes the place of the no-net-traction equation, and the pocket's
    Coulomb friction mu_c |Q_p| (``pocket_friction``) at the contact point R_b e_psi from the centre,
    against the ball's surface speed R_b |w| there (the ball's centre moves with its pocket), adds the
    moment -mu_c |Q_p| R_b w / |w| to the in-plane moments; (w_r, w_z) are solved. The check dict then
    also has ``pocket_force`` [N].

    ``pocket_film`` (docs/theory/quasistatic.md#the-pocket-film): a callable (omega_m, w_r, w_z, Q_p) ->
    (contact force [N], m_r, m_z [N m]) of the pocket's oil film (:class:`.pocket_film.PocketFilm`): its moment
    on the ball joins the in-plane moments, and the friction acts on the contact force it leaves (with the
    cage), or Q_p = 0 (a cageless ball floating in its pocket)."""
    start = np.asarray(start, float)
    scale = max(abs(start[0]), math.hypot(start[1], start[2]), 1e-12)
    rb = geo[G_RB]
    out = np.zeros((2, NC))
    code, vec = model.code, model.vector
    qref = max(geo[G_QO], geo[G_QI], 1e-12)
    normals = ((geo[G_NOR], geo[G_NOZ]), (geo[G_NIR], geo[G_NIZ]))
    held = [True]

    j_eff = [inertia]

    def gyro(v_t, wm, wr, wz):
        _ball_contacts(wm, wr, wz, v_t, geo, code, vec, n_strips, n_across, out)
        return (rb * (out[0, 7] + out[1, 7]) - j_eff[0] * wm * wr) / (rb * qref)

    def pivot(wm, wr, wz):
        g0 = gyro(0.0, wm, wr, wz)
        if g0 == 0.0:
            return 0.0
        direction = 1.0 if g0 > 0.0 else -1.0   # the tractions oppose the slip: g falls as v_t grows
        u = max(0.5 * (abs(out[0, 3]) + abs(out[1, 3])), 1e-9)
        lo, step = 0.0, 1e-6 * u
        while step <= u:
            hi = direction * step
            if gyro(hi, wm, wr, wz) * g0 < 0.0:
                return optimize.brentq(gyro, lo, hi, args=(wm, wr, wz), xtol=1e-12 * u, rtol=1e-12)
            lo, step = hi, 2.0 * step
        held[0] = False                          # gross pivoting: the moment is not held up to s = 1
        return direction * u

    caged = omega_m is not None
    unknowns = slice(1, 3) if caged else slice(0, 3)

    def speeds(x):
        if caged:
            return omega_m, x[0] * scale, x[1] * scale
        return x[0] * scale, x[1] * scale, x[2] * scale

    def resid(x):
        wm, wr, wz = speeds(x)
        v_t = pivot(wm, wr, wz)
        _ball_contacts(wm, wr, wz, v_t, geo, code, vec, n_strips, n_across, out)
        f_x = out[0, 6] + out[1, 6]
        m_r = m_z = 0.0
        for k in range(2):
            nr, nz = normals[k]
            m_r += -out[k, 6] * rb * nz - out[k, 8] * nr + out[k, 11] * nz
            m_z += out[k, 6] * rb * nr - out[k, 8] * nz - out[k, 11] * nr
        m_r += j_eff[0] * wm * v_t / rb          # = -(-J omega_m w_psi), w_psi = v_t / R_b
        contact = abs(f_x)
        if pocket_film is not None:  # the film's moment; the friction on the contact force it leaves
            contact, film_r, film_z = pocket_film(wm, wr, wz, -f_x if caged else 0.0)
            m_r += film_r
            m_z += film_z
        if caged:  # the pocket force -f_x balances the tractions; its friction brakes the ball's spin
            w = math.hypot(wr, wz)
            if w > 0.0:
                m_r -= pocket_friction * contact * rb * wr / w
                m_z -= pocket_friction * contact * rb * wz / w
            return np.array([m_r / rb, m_z / rb]) / qref
        return np.array([f_x, m_r / rb, m_z / rb]) / qref

    # continuation in the ball's inertia (0 -> J): without the gyroscopic
    # moments the start (race control or minimum energy) is close to the
    # solution; the full equations then have further roots with gross
    # transverse sliding that kills the in-plane tractions, which a direct
    # solve from far away can land on. The step adapts: a step is taken only
    # when the root solver converges and stays on the branch (speeds change
    # by less than CONTINUATION_JUMP); otherwise it is halved. When the step
    # falls below CONTINUATION_MIN_STEP the branch has turned back (a fold in
    # the inertia): the traction the ball's loads can give cannot hold its
    # gyroscopic moment in a steady orbit, and the ball has no traction
    # equilibrium (``converged`` False, ``held_fraction`` < 1).
    def solve_at(frac, x0):
        j_eff[0] = frac * inertia
        sol = optimize.root(resid, x0, method="hybr", options={"xtol": 1e-13})
        err = float(np.max(np.abs(resid(sol.x))))
        ok = bool(err < 1e-8 and np.all(np.isfinite(sol.x)))
        return sol.x, ok, err, int(sol.nfev)

    # a start that is already near the equilibrium (the previous iteration's) is solved directly
    x0 = start[unknowns] / scale
    x, ok, err, evaluations = solve_at(1.0, x0)
    near = float(np.max(np.abs(x - x0)) / max(np.max(np.abs(x0)), 1e-300))
    if ok and near < 1e-3:
        frac, ok0 = 1.0, True
    else:
        x, ok, err, nfev = solve_at(0.0, x0)
        frac, step = 0.0, 0.25
        evaluations += nfev
        ok0 = ok
    while ok0 and frac < 1.0 and step >= CONTINUATION_MIN_STEP:
        f_new = min(1.0, frac + step)
        x_new, ok, _, nfev = solve_at(f_new, x)
        evaluations += nfev
        jump = float(np.max(np.abs(x_new - x)) / max(np.max(np.abs(x)), 1e-300))
        if ok and jump < CONTINUATION_JUMP:
            x, frac, step = x_new, f_new, 1.5 * step
        else:
            step *= 0.5
    j_eff[0] = frac * inertia
    held[0] = True
    res = resid(x)
    wm, wr, wz = speeds(x)
    v_t = pivot(wm, wr, wz)
    converged = bool(ok0 and frac == 1.0 and np.max(np.abs(res)) < 1e-8)
    j_eff[0] = inertia
    check = {"converged": converged, "residual": float(np.max(np.abs(resid(x)))), "evaluations": evaluations,
             "gyroscopic_moment_held": bool(held[0] and converged), "held_fraction": float(frac if ok0 else 0.0)}
    if caged:
        _ball_contacts(wm, wr, wz, v_t, geo, code, vec, n_strips, n_across, out)
        check["pocket_force"] = float(-(out[0, 6] + out[1, 6]))
    return np.array([wm, wr, wz, v_t]), check


def cage_kinematics(geo, omega_m, race="outer"):
    """Kinematics (omega_m, w_r, w_z, 0) of a ball that the cage carries at the orbital speed
    ``omega_m``: the ball rolls at the centre of its outer contact (v0_o = 0) without spin there
    (omega_s,o = 0), as it rolls on the race that centrifugal force presses it against. The choice
    of the quasi-static solver for a ball without a traction equilibrium of its own (a contact
    without load: nothing drives it; or a gyroscopic moment its loads cannot hold). ``race="inner"``:
    the same at the inner contact (race control by the inner race at the cage's speed)."""
    wring, nr, nz = ((geo[G_WO], geo[G_NOR], geo[G_NOZ]) if race == "outer" else
                     (geo[G_WI], geo[G_NIR], geo[G_NIZ]))
    x0r = geo[G_CR] + geo[G_RB] * nr
    a = np.array([[-geo[G_RB] * nz, geo[G_RB] * nr], [nr, nz]])
    rhs = np.array([(wring - omega_m) * x0r, (wring - omega_m) * nz])
    w_r, w_z = np.linalg.solve(a, rhs)
    return np.array([omega_m, w_r, w_z, 0.0])


def dissipation_at_beta(geo, model, n_strips, n_across, beta, start):
    """Least dissipation [W] with the spin axis held at ``beta`` [rad] (minimised over omega_m and
    the ball speed), and the kinematics (3,) that give it: the curve of Gupta's Fig. 9."""
    scale = max(abs(start[0]), math.hypot(start[1], start[2]), 1e-12)
    code, vec = model.code, model.vector
    out = np.zeros((2, NC))
    sb, cb = math.sin(beta), math.cos(beta)
    w0 = start[1] * sb - start[2] * cb       # speed along the axis (sin beta, -cos beta)

    def kin(x):
        return x[0] * scale, x[1] * scale * sb, -x[1] * scale * cb

    def f(x):
        k = kin(x)
        return _ball_contacts(k[0], k[1], k[2], 0.0, geo, code, vec, n_strips, n_across, out)

    x0 = np.array([start[0], w0]) / scale
    simplex = np.vstack([x0, x0 + [2e-3, 0.0], x0 + [0.0, 2e-3]])
    res = optimize.minimize(f, x0, method="Nelder-Mead",
                            options={"initial_simplex": simplex, "xatol": 1e-11, "fatol": 1e-14, "maxfev": 8000})
    return float(res.fun), np.array(kin(res.x))
