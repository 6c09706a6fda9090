"""Compiled step of the reduced engine (docs/theory/reduced.md): the ball centres on their normal force
balance at every step, the ball states and the inner ring advanced by a linearly implicit BDF2 step, over
the shared contact kernel :func:`exudyn_bearing.model.contact.forces`.

State (outer-ring frame = world frame, the bearing axis z):

* ``phi``, ``om`` (Z,): the orbital angle [rad] and orbital speed [rad/s] of each ball centre;
* ``wo`` (Z, 3): ball angular velocities [rad/s] in the ball's orbital frame (e_r, e_t, e_z), which turns
  with it (a steady ball has a constant ``wo``: a fixed point of the implicit step, where the world-frame
  vector turns and the step's frozen Jacobian would resist its turning); ``wb`` its world-frame value for
  the kernel;
* ``q`` (Z, 2): the centre's radius r and axial position z [m], solved from the normal force balance
  ``R_j(q) = (f_j . e_r + m_b r om_j^2, f_j . e_z) - m_b q_j'' = 0`` (f_j the contact kernel's force on ball j,
  m_b r om^2 the centrifugal force, m_b q'' the centre's radial and axial inertia as the backward difference
  ((q - q_old) / dt - qd) / dt, ``qd`` (Z, 2) the rate at the step's start: the implicit Euler step of the
  centre's normal motion, which is the balance where the contacts hold the centre and a body of its mass where
  they do not, docs/theory/reduced.md, "A lightly loaded ball"); ``q_old`` its value one step earlier;
* ``ring`` (6,): inner-ring position and velocity (it translates; its spin follows the protocol, as in the
  reference engine, :func:`~exudyn_bearing.model.engine_steps.set_inner_ring`);
* with the rigid cage, its centre, angle and their rates in the cage rows of ``xc``, ``vc``
  (:mod:`exudyn_bearing.model.layout`; :data:`N_CAGE` entries), advanced with the balls in one arrow-shaped
  linearly implicit step (:func:`_arrow_step`).

The ball centre's velocity handed to the contact kernel is r om e_t plus the radial and axial rate
``(q - q_old) / dt``: inside the step's force balance the backward difference of the equilibrium positions,
so that the normal damping of the contacts acts on the centre's actual (quasi-static) motion through the load
zone. The Coriolis term of the orbital equation, m_b (r om' + 2 r' om) = f . e_t, takes the same rate.
"""
from __future__ import annotations

import math

import numpy as np

from ..._jit import kernel
from ...model.contact import _rigid_cage, accumulate_energy, forces
from ...model.layout import (ENERGY_WORKS, HZ_GEO, NGLOBAL, P_IB, P_IC, P_MAX_OVERLAP, P_MB, P_MC, P_MR,
                             P_RB, P_RP, P_VREG)
from ...model.engine_steps import finite, finite_ring, inner_ring_force, set_inner_ring, store_sample

__all__ = ["reduced_evaluate", "run_reduced", "N_WORK", "N_CAGE", "N_CORR", "N_ADAPT", "state_count"]

#: Slots of the run's work vector ``work`` (floats kept across calls): the step's Newton iterations in total,
#: the Newton iterations of the worst step, the force evaluations in total, the steps whose force balance did
#: not converge within ``max_iter``, the balance Jacobians taken, the steps that took the speeds' and the ring's
#: Jacobians, 1 once the state of the step before is kept (``prev``, ``ring_prev``: the BDF2 step), the
#: Newton corrections of the steps of the rigid cage (:data:`N_CORR`), and 1 once a step has
#: set the centres' rates ``qd`` (the inertia of their balance).
N_WORK = 9
W_ITER, W_ITER_MAX, W_EVALS, W_UNCONVERGED, W_JAC, W_REFRESH, W_HAVE_PREV, W_CORR, W_HAVE_RATE = range(9)
#: Surface-speed perturbation [m/s] of the finite-difference Jacobian of the ball speeds (the traction's
#: low-slip slope is resolved down to slips far below the regularising speeds, 1e-3 m/s and more).
H_SPEED = 1e-6
#: Position perturbation [m] of the Jacobians of the force balance and of the ring force (1e-4 of the
#: 1e-5 m Hertz overlaps of loaded balls: the forward difference's error stays below 1e-4 of the stiffness).
H_POS = 1e-9
#: Iterations of the force balance at a call's start (before its first step), in units of ``max_iter``: a start off
#: the balance (the analytic start, the quasi-static race-control start of the ACBB-120) may need more than
#: ``max_iter`` to 1e-12 m (the modified Newton iteration converges linearly from afar) where a warm-started step
#: needs one or two.
START_ITER = 4
#: Largest correction [m] of a ball centre in one Newton iteration of its force balance (a fifth of the 1e-5 m
#: Hertz overlaps of a loaded ball: a balance whose Jacobian came from another contact state, a pocket contact
#: closing, moved a centre by tens of micrometres in one iteration before this bound).
STEP_MAX = 2e-6
#: Newton corrections of a step with the rigid cage at most: the linearly implicit step linearises the pockets'
#: forces about t_n (a contact that closes or opens within the step is seen in its state at t_n), and the
#: corrections solve the step's equations at the state reached, so that the speeds move under the forces of the
#: committed evaluation, whose powers the energy integrals take (corrected only where a contact closed or
#: opened, the caged 7208 under combined load at 20 us gained kinetic energy beyond the counted works: an energy
#: residual of -4.3 % of the drive power over 10-20 ms, tests/test_reduced_engine.py).
N_CORR = 4
#: The corrections stop once the step equations' largest speed residual is below CORR_TOL [m/s] (a surface
#: speed), or when a correction made it larger (that correction is undone).
CORR_TOL = 1e-6
#: The balance's modified Newton iteration retakes its Jacobians where a ball's residual did not shrink by at
#: least this factor over an iteration (two evaluations, every ball at once): with the Jacobian of the state the
#: iteration is quadratic, and an iteration that gains less than a factor of ten costs more evaluations to the
#: balance's tolerance than retaking them. Where a kept Jacobian no longer holds (a rigid cage's pocket contact
#: changing the stiffness of a ball's soft direction, along its grooves, within the step), the iteration
#: converged linearly at 0.2-0.5 per iteration and stopped at its limit.
SHRINK = 0.1
#: The load proxy's change that retakes the Jacobians (``jac_tol``) is relative to the ball's own proxy at the
#: last retaking, at least LOAD_FLOOR times the largest ball's.
LOAD_FLOOR = 0.1
#: The speeds' change that retakes the Jacobians: SPEED_TOL of the ball's orbital surface speed.
SPEED_TOL = 0.005
#: Orbital-angle perturbation [rad] of the forces' dependence on the ball's place in the load zone.
H_ANGLE = 1e-7

#: Entries of the step error control's vector ``adapt`` (kept across calls; its tolerance 0: the fixed step):
#: the time reached [s], the next step proposed [s], the steps that reached the last two states [s], the
#: tolerance [-], the least and the largest step [s], the run's end and the sample interval [s], the speed scale
#: [m/s], the steps rejected, the states kept in ``ys`` (at most three), the samples taken, the largest error
#: of an accepted step (or of the step that stopped the run) in units of the tolerance, the restarts (a second
#: rejection at the same time: the BDF2 restarted with a linearly implicit Euler step, the history dropped).
N_ADAPT = 15
(A_T, A_H, A_HPREV, A_HPREV2, A_TOL, A_HMIN, A_HMAX, A_TEND, A_SDT, A_U, A_NREJ, A_NHIST, A_KSAMP,
 A_ERR, A_NRESTART) = range(15)
#: Step factor limits of the error control: a step grows at most FAC_MAX times (below the 1 + sqrt(2) of the
#: variable-step BDF2's zero stability, Grigorieff 1983; Hairer, Norsett & Wanner I, Sect. III.5) and shrinks at
#: most to FAC_MIN of itself; SAFETY the usual factor on the step the estimate asks for (Hairer, Norsett &
#: Wanner I, Sect. II.4).
FAC_MAX = 2.0
FAC_MIN = 0.2
SAFETY = 0.9
#: The least growth the control takes (smaller ones keep the step; the threshold of CVODE's BDF, Hindmarsh et
#: al. 2005): a step that changes at every step for a few per cent changes the variable-step BDF2's
#: coefficients at every step.
FAC_GROW = 1.5


def state_count(z):
    """Entries of the error control's state vector for ``z`` balls (:func:`_state_vector`)."""
    return 5 * z + 6 + N_CAGE


@kernel(inline="always")
def _state_vector(phi, om, wo, ring, xc, vc, out):
    """The integrated state as one vector: per ball (phi, om, w_o) at 5 j, the inner ring's (x, v) at 5 Z, the
    rigid cage's state (:data:`N_CAGE`) at 5 Z + 6 (zeros without the cage)."""
    z = om.shape[0]
    for j in range(z):
        out[5 * j] = phi[j]
        out[5 * j + 1] = om[j]
        for k in range(3):
            out[5 * j + 2 + k] = wo[j, k]
    for k in range(6):
        out[5 * z + k] = ring[k]
    for k in range(N_CAGE):
        out[5 * z + 6 + k] = _cage_get(xc, vc, k)


@kernel(inline="always")
def _speed_scales(p, z, out):
    """Weights of the state vector's entries in the error norm: the speeds as surface speeds (the orbital speeds
    and the cage's angular speed times the pitch radius, the balls' angular velocities times their radius, the
    ring's and the cage's velocities as they are) and 0 for the positions and angles."""
    for i in range(out.shape[0]):
        out[i] = 0.0
    for j in range(z):
        out[5 * j + 1] = p[P_RP]
        for k in range(3):
            out[5 * j + 2 + k] = p[P_RB]
    for k in range(3):
        out[5 * z + 3 + k] = 1.0
        out[5 * z + 6 + 4 + k] = 1.0
    out[5 * z + 6 + 7] = p[P_RP]


@kernel(internal=True)
def reduced_evaluate(t, dt, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb, tb, fc,
                     fr, fring, glob, diag, cage_load, want, res, acc, defect_path, ellipse_path, loss_path):
    """Forces of the reduced state at time t: the ball centres (r cos phi, r sin phi, z) moving at
    r om e_t + (q - q_old) / dt, the contact kernel's forces, then per ball the residual of the normal force
    balance ``res`` (Z, 2) [N] and the accelerations ``acc`` (Z, 4): om' [rad/s^2] and w' (3) [rad/s^2];
    ``fring`` the force that accelerates the inner ring. Returns the kernel's largest overlap ratio."""
    z = phi.shape[0]
    mb = p[P_MB]
    inv_dt = 1.0 / dt
    for j in range(z):
        c = math.cos(phi[j])
        s = math.sin(phi[j])
        r = q[j, 0]
        rd = (q[j, 0] - q_old[j, 0]) * inv_dt
        zd = (q[j, 1] - q_old[j, 1]) * inv_dt
        xb[j, 0] = r * c
        xb[j, 1] = r * s
        xb[j, 2] = q[j, 1]
        vb[j, 0] = rd * c - r * om[j] * s
        vb[j, 1] = rd * s + r * om[j] * c
        vb[j, 2] = zd
        wb[j, 0] = wo[j, 0] * c - wo[j, 1] * s
        wb[j, 1] = wo[j, 0] * s + wo[j, 1] * c
        wb[j, 2] = wo[j, 2]
    set_inner_ring(t, p, ring, rings, defect_path)
    worst = forces(p, table, xb, vb, wb, xc, vc, rings, hist, hist, dt, hz, fb, tb, fc, fr, glob, diag, cage_load,
                   want, defect_path, ellipse_path, loss_path)
    inner_ring_force(p, fr, fring)
    inv_ib = 1.0 / p[P_IB]
    for j in range(z):
        c = math.cos(phi[j])
        s = math.sin(phi[j])
        r = q[j, 0]
        rd = (q[j, 0] - q_old[j, 0]) * inv_dt
        f_r = fb[j, 0] * c + fb[j, 1] * s
        f_t = -fb[j, 0] * s + fb[j, 1] * c
        res[j, 0] = f_r + mb * r * om[j] * om[j]
        res[j, 1] = fb[j, 2]
        acc[j, 0] = (f_t - 2.0 * mb * rd * om[j]) / (mb * r)
        # w_o' = A^T T / I - om e_z x w_o in the orbital frame (e_r, e_t, e_z), which turns with the ball
        acc[j, 1] = (tb[j, 0] * c + tb[j, 1] * s) * inv_ib + om[j] * wo[j, 1]
        acc[j, 2] = (-tb[j, 0] * s + tb[j, 1] * c) * inv_ib - om[j] * wo[j, 0]
        acc[j, 3] = tb[j, 2] * inv_ib
    return worst


@kernel(no_runtime=True, internal=True)
def _solve_small(a, b, n):
    """Solve a x = b in place (b becomes x) for the n x n matrix a (overwritten) by Gaussian elimination
    with partial pivoting; returns False when a pivot vanishes."""
    for k in range(n):
        piv = k
        big = abs(a[k, k])
        for i in range(k + 1, n):
            if abs(a[i, k]) > big:
                big = abs(a[i, k])
                piv = i
        if big == 0.0 or not math.isfinite(big):
            return False
        if piv != k:
            for m in range(n):
                a[k, m], a[piv, m] = a[piv, m], a[k, m]
            b[k], b[piv] = b[piv], b[k]
        for i in range(k + 1, n):
            f = a[i, k] / a[k, k]
            for m in range(k, n):
                a[i, m] -= f * a[k, m]
            b[i] -= f * b[k]
    for k in range(n - 1, -1, -1):
        s = b[k]
        for m in range(k + 1, n):
            s -= a[k, m] * b[m]
        b[k] = s / a[k, k]
    return True


@kernel(no_runtime=True, internal=True)
def _implicit_step(jm, f, y, y_prev, n, gam, dt, bdf2, a, d):
    """One linearly implicit step of y' = f(y) for the n states ``y`` (updated in place; ``y_prev`` takes y_n):
    BDF2 (``gam`` 2/3, ``bdf2`` True), one Newton step of y_{n+1} - 4/3 y_n + 1/3 y_{n-1} = gam dt f(y_{n+1})
    from the extrapolation 2 y_n - y_{n-1} with f there f_n + J (y_n - y_{n-1}); or Euler (``gam`` 1, ``bdf2``
    False), (I - dt J) dy = dt f_n. ``jm`` the n x n Jacobian J, ``f`` f_n (overwritten), ``a``, ``d`` scratch.
    Returns False when the step's matrix is singular."""
    for i in range(n):
        d[i] = y[i] - y_prev[i] if bdf2 else 0.0
    for i in range(n):
        fi = f[i]
        for k in range(n):
            fi += jm[i, k] * d[k]
            a[i, k] = -gam * dt * jm[i, k]
        a[i, i] += 1.0
        f[i] = gam * dt * fi - gam * d[i]
    if not _solve_small(a, f, n):
        return False
    for i in range(n):
        y_prev[i] = y[i]
        y[i] += d[i] + f[i]
    return True


#: Entries of the rigid cage's state vector ``yc``: its centre (x, y, z) [m] and angle [rad], then their rates
#: [m/s, rad/s] (the reference engine's cage rows ``xc[0]``, ``xc[1, 0]``, ``vc[0]``, ``vc[1, 0]``).
N_CAGE = 8


@kernel(inline="always")
def _cage_get(xc, vc, k):
    """Entry k of the rigid cage's state vector (:data:`N_CAGE`) from the cage rows."""
    if k < 3:
        return xc[0, k]
    if k == 3:
        return xc[1, 0]
    if k < 7:
        return vc[0, k - 4]
    return vc[1, 0]


@kernel(inline="always")
def _cage_add(xc, vc, k, h):
    """Add h to entry k of the rigid cage's state vector in the cage rows."""
    if k < 3:
        xc[0, k] += h
    elif k == 3:
        xc[1, 0] += h
    elif k < 7:
        vc[0, k - 4] += h
    else:
        vc[1, 0] += h


@kernel(inline="always")
def _cage_accelerations(p, fc, out):
    """The rigid cage's accelerations (x'', y'', z'' [m/s^2], angle'' [rad/s^2]) from the contact kernel's cage
    rows (``fc[1, 0]`` the moment scaled by m_c / I_c, :func:`~exudyn_bearing.model.contact._rigid_cage`)."""
    inv = 1.0 / p[P_MC]
    out[0] = fc[0, 0] * inv
    out[1] = fc[0, 1] * inv
    out[2] = fc[0, 2] * inv
    out[3] = fc[1, 0] * inv


@kernel(internal=True)
def _pocket_shares(p, xb, vb, wb, xc, vc, rings, fbp, tbp, fcp, frp, globp, clp, out):
    """Each ball's share of the rigid cage's accelerations ``out`` (Z, 4) through its pocket contact, from the
    contact kernel's pocket code (:func:`~exudyn_bearing.model.contact._rigid_cage`, on scratch arrays): the
    pocket's force G_j on ball j acts on the cage as -G_j at the contact point p_j, so the cage's share is
    -G_j / m_c and its moment about the axis -((x_j - x_c) x G_j + R_b n x t)_z / I_c, R_b n x t the
    friction's moment on the ball (the pocket's normal force has none). Differences of these shares give the
    cage rows of the Jacobian per ball, where perturbing every ball at once gives only their sum in the cage's
    own force."""
    z = xb.shape[0]
    for j in range(z):
        for d in range(3):
            fbp[j, d] = 0.0
            tbp[j, d] = 0.0
    _rigid_cage(p, xb, vb, wb, xc, vc, rings, fbp, tbp, fcp, frp, globp, clp, False)
    inv_m = 1.0 / p[P_MC]
    inv_i = 1.0 / p[P_IC]
    for j in range(z):
        gx, gy = fbp[j, 0], fbp[j, 1]
        out[j, 0] = -gx * inv_m
        out[j, 1] = -gy * inv_m
        out[j, 2] = -fbp[j, 2] * inv_m
        out[j, 3] = -((xb[j, 0] - xc[0, 0]) * gy - (xb[j, 1] - xc[0, 1]) * gx + tbp[j, 2]) * inv_i


@kernel(internal=True)
def _arrow_step(jphi, jb, acc0, phi, om, wo, prev, jbc, jcb, jcc, ac0, xc, vc, cage_prev, gam, dt, bdf2, a5, b5, d5,
                ya, xa, dca, rc, a8, corr, resb, resc):
    """One linearly implicit step (as :func:`_implicit_step`: BDF2, or Euler where ``bdf2`` is False) of the
    balls' (phi, om, w_o) and the rigid cage's state (:data:`N_CAGE`) together. The system's matrix
    A = I - gam dt J is arrow-shaped: per ball the 5 x 5 block A_j (its speeds' Jacobian, ``jphi``, ``jb``),
    its coupling to the cage B_j = -gam dt dy_j'/dy_c (``jbc`` (Z, 4, 8)) and the cage's to it
    C_j = -gam dt dy_c'/dy_j (``jcb`` (Z, 4, 5)), and the cage's block A_c (``jcc`` (4, 8), the kinematic rows
    x' = v). The balls' blocks are eliminated (Schur complement): S = A_c - sum_j C_j A_j^-1 B_j,
    S D_c = r_c - sum_j C_j A_j^-1 r_j, then D_j = A_j^-1 (r_j - B_j D_c); ``acc0`` (Z, 4) and ``ac0`` (4) the
    accelerations at t_n. Updates the states and their previous values in place; returns False when a matrix
    is singular. With ``corr`` a Newton correction of the step just taken instead: the right-hand sides are
    minus the step equations' residuals ``resb`` (Z, 5), ``resc`` (8) (:func:`_step_residual`), the states
    move by the solution, their previous values stay. ``a5`` (5, 5), ``b5``, ``d5`` (5), ``ya`` (Z, 5, 8),
    ``xa`` (Z, 5), ``dca``, ``rc`` (8), ``a8`` (8, 8) scratch."""
    z = phi.shape[0]
    g = gam * dt
    nc = N_CAGE
    for i in range(nc):
        dca[i] = _cage_get(xc, vc, i) - cage_prev[i] if (bdf2 and not corr) else 0.0
    # the cage's right-hand side g (f_c + J_cc d_c) - gam d_c (the balls' share J_cj d_j added below) and the
    # cage's block A_c = I - g J_cc
    for i in range(nc):
        for k in range(nc):
            a8[i, k] = 0.0
        a8[i, i] = 1.0
    for i in range(4):
        a8[i, 4 + i] -= g
        rc[i] = g * (_cage_get(xc, vc, 4 + i) + dca[4 + i]) - gam * dca[i]
        fi = ac0[i]
        for k in range(nc):
            fi += jcc[i, k] * dca[k]
            a8[4 + i, k] -= g * jcc[i, k]
        rc[4 + i] = g * fi - gam * dca[4 + i]
    if corr:
        for i in range(nc):
            rc[i] = -resc[i]
    for j in range(z):
        # d_j and the ball's right-hand side r_j = g (f_j + J_jj d_j + J_jc d_c) - gam d_j
        use = bdf2 and not corr
        d5[0] = phi[j] - prev[j, 0] if use else 0.0
        d5[1] = om[j] - prev[j, 1] if use else 0.0
        for k in range(3):
            d5[2 + k] = wo[j, k] - prev[j, 2 + k] if use else 0.0
        b5[0] = g * (om[j] + d5[1]) - gam * d5[0]
        for i in range(4):
            fi = acc0[j, i] + jphi[j, i] * d5[0]
            for k in range(4):
                fi += jb[j, i, k] * d5[1 + k]
            for k in range(nc):
                fi += jbc[j, i, k] * dca[k]
            b5[1 + i] = g * fi - gam * d5[1 + i]
        if corr:
            for i in range(5):
                b5[i] = -resb[j, i]
        else:
            for i in range(4):
                for k in range(5):
                    rc[4 + i] += g * jcb[j, i, k] * d5[k]
        # X_j = A_j^-1 r_j and Y_j = A_j^-1 B_j, column by column
        for col in range(nc + 1):
            for i in range(5):
                for k in range(5):
                    a5[i, k] = 0.0
                a5[i, i] = 1.0
            a5[0, 1] -= g
            for i in range(4):
                a5[1 + i, 0] -= g * jphi[j, i]
                for k in range(4):
                    a5[1 + i, 1 + k] -= g * jb[j, i, k]
            if col == 0:
                for i in range(5):
                    xa[j, i] = b5[i]
                ok = _solve_small(a5, xa[j], 5)
            else:
                for i in range(5):
                    ya[j, i, col - 1] = 0.0 if i == 0 else -g * jbc[j, i - 1, col - 1]
                for i in range(5):
                    d5[i] = ya[j, i, col - 1]
                ok = _solve_small(a5, d5, 5)
                for i in range(5):
                    ya[j, i, col - 1] = d5[i]
            if not ok:
                return False
        # S -= C_j Y_j, s -= C_j X_j (C_j = -g J_cj: the cage's acceleration rows only)
        for i in range(4):
            for k in range(nc):
                acc_ = 0.0
                for m in range(5):
                    acc_ += jcb[j, i, m] * ya[j, m, k]
                a8[4 + i, k] += g * acc_
            acc_ = 0.0
            for m in range(5):
                acc_ += jcb[j, i, m] * xa[j, m]
            rc[4 + i] += g * acc_
    if not _solve_small(a8, rc, nc):
        return False
    for j in range(z):
        for i in range(5):
            dj = xa[j, i]
            for k in range(nc):
                dj -= ya[j, i, k] * rc[k]
            xa[j, i] = dj
        if corr:
            phi[j] += xa[j, 0]
            om[j] += xa[j, 1]
            for k in range(3):
                wo[j, k] += xa[j, 2 + k]
            continue
        dd = phi[j] - prev[j, 0] if bdf2 else 0.0
        prev[j, 0] = phi[j]
        phi[j] += dd + xa[j, 0]
        dd = om[j] - prev[j, 1] if bdf2 else 0.0
        prev[j, 1] = om[j]
        om[j] += dd + xa[j, 1]
        for k in range(3):
            dd = wo[j, k] - prev[j, 2 + k] if bdf2 else 0.0
            prev[j, 2 + k] = wo[j, k]
            wo[j, k] += dd + xa[j, 2 + k]
    for i in range(nc):
        if not corr:
            cage_prev[i] = _cage_get(xc, vc, i)
        _cage_add(xc, vc, i, dca[i] + rc[i])
    return True


@kernel(internal=True)
def _filter_estimate(est, z, jphi, jb, jbc, jcb, jcc, j6, ring_free, cage_free, gam, h, a5, d5, a6, d6, b5, ya, xa, dca,
                     rca, a8, f_phi, f_om, f_wo, f_xc, f_vc, prev, cage_prev, acc0, ac0, resb, resc):
    """The error estimate ``est`` (the state vector's layout, :func:`_state_vector`) replaced by
    (I - gam h J)^-1 est with the step's Jacobians: per ball (its 5 x 5 block), the ring (its 6 x 6, ``j6``),
    or with the rigid cage the balls and the cage together through :func:`_arrow_step`'s correction (right-hand
    side -resb, -resc on a zero state). Returns False where a matrix is singular."""
    g = gam * h
    if cage_free:
        for j in range(z):
            f_phi[j] = 0.0
            f_om[j] = 0.0
            for k in range(5):
                resb[j, k] = -est[5 * j + k]
            for k in range(3):
                f_wo[j, k] = 0.0
        for r in range(f_xc.shape[0]):
            for k in range(3):
                f_xc[r, k] = 0.0
                f_vc[r, k] = 0.0
        for k in range(N_CAGE):
            resc[k] = -est[5 * z + 6 + k]
        if not _arrow_step(jphi, jb, acc0, f_phi, f_om, f_wo, prev, jbc, jcb, jcc, ac0, f_xc, f_vc, cage_prev, gam, h,
                           True, a5, b5, d5, ya, xa, dca, rca, a8, True, resb, resc):
            return False
        for j in range(z):
            est[5 * j] = f_phi[j]
            est[5 * j + 1] = f_om[j]
            for k in range(3):
                est[5 * j + 2 + k] = f_wo[j, k]
        for k in range(N_CAGE):
            est[5 * z + 6 + k] = _cage_get(f_xc, f_vc, k)
    else:
        for j in range(z):
            for i in range(5):
                for k in range(5):
                    a5[i, k] = 0.0
                a5[i, i] = 1.0
                d5[i] = est[5 * j + i]
            a5[0, 1] -= g
            for i in range(4):
                a5[1 + i, 0] -= g * jphi[j, i]
                for k in range(4):
                    a5[1 + i, 1 + k] -= g * jb[j, i, k]
            if not _solve_small(a5, d5, 5):
                return False
            for i in range(5):
                est[5 * j + i] = d5[i]
    if ring_free:
        for i in range(6):
            for k in range(6):
                a6[i, k] = -g * j6[i, k]
            a6[i, i] += 1.0
            d6[i] = est[5 * z + i]
        if not _solve_small(a6, d6, 6):
            return False
        for i in range(6):
            est[5 * z + i] = d6[i]
    return True


@kernel(internal=True)
def _step_residual(phi, om, wo, prev, prev2, acc, xc, vc, cage_prev, cage_prev2, ac, gam, dt, resb, resc, rp, rb):
    """Residuals of the step equations of :func:`_arrow_step` at the state reached, ``resb`` (Z, 5) and
    ``resc`` (8): (y - y_n) - (1 - gam) (y_n - y_{n-1}) - gam dt f(y), f the committed evaluation there
    (``acc`` (Z, 4) the balls' accelerations, ``ac`` (4) the cage's), y_n the states before the step (``prev``,
    ``cage_prev``), y_{n-1} the ones before that (``prev2``, ``cage_prev2``; BDF2, gam 2/3; Euler: gam 1).
    Returns the largest residual of a speed as a surface speed [m/s] (the orbital speeds and the cage's angular
    speed times the pitch radius ``rp``, the ball's angular velocity times its radius ``rb``)."""
    z = phi.shape[0]
    c1 = 1.0 - gam
    g = gam * dt
    for j in range(z):
        resb[j, 0] = (phi[j] - prev[j, 0]) - c1 * (prev[j, 0] - prev2[j, 0]) - g * om[j]
        resb[j, 1] = (om[j] - prev[j, 1]) - c1 * (prev[j, 1] - prev2[j, 1]) - g * acc[j, 0]
        for k in range(3):
            resb[j, 2 + k] = (wo[j, k] - prev[j, 2 + k]) - c1 * (prev[j, 2 + k] - prev2[j, 2 + k]) - g * acc[j, 1 + k]
    for i in range(N_CAGE):
        y = _cage_get(xc, vc, i)
        f = _cage_get(xc, vc, 4 + i) if i < 4 else ac[i - 4]
        resc[i] = (y - cage_prev[i]) - c1 * (cage_prev[i] - cage_prev2[i]) - g * f
    big = 0.0
    for j in range(z):
        big = max(big, abs(resb[j, 1]) * rp)
        for k in range(3):
            big = max(big, abs(resb[j, 2 + k]) * rb)
    for i in range(4, 7):
        big = max(big, abs(resc[i]))
    return max(big, abs(resc[7]) * rp)


@kernel(inline="always")
def _add_inertia(q, q_old, qref, dt, m, res):
    """Add the inertia of each ball centre's radial and axial motion to its force balance ``res`` (Z, 2) [N]:
    -m ((q - q_old) / dt - qref) / dt, the backward difference of the centre's rate (q - q_old) / dt against its
    rate ``qref`` (Z, 2) [m/s] at the step's start (m the ball's mass; docs/theory/reduced.md, "A lightly loaded
    ball")."""
    for j in range(q.shape[0]):
        for c in range(2):
            res[j, c] -= m * ((q[j, c] - q_old[j, c]) / dt - qref[j, c]) / dt


@kernel(internal=True)
def _balance(t, dt, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb, tb, fc, fr, fring,
             glob, diag, cage_load, res, acc, g, r0, done, tol, max_iter, work, fresh, qref, inertia, defect_path,
             ellipse_path, loss_path):
    """The balls' normal force balance (:func:`_balance_sampled` without the sample's diagnostics)."""
    return _balance_sampled(t, dt, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb, tb,
                            fc, fr, fring, glob, diag, cage_load, res, acc, g, r0, done, tol, max_iter, work, fresh,
                            False, qref, inertia, defect_path, ellipse_path, loss_path)


@kernel(internal=True)
def _balance_sampled(t, dt, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb, tb, fc, fr,
                     fring, glob, diag, cage_load, res, acc, g, r0, done, tol, max_iter, work, fresh, want, qref,
                     inertia, defect_path, ellipse_path, loss_path):
    """Solve the normal force balance of every ball for q (warm start: q on entry) by Newton's method with
    the per-ball 2 x 2 Jacobians ``g`` (Z, 2, 2) of dR/dq, taken by differences (one evaluation per
    component, every ball perturbed at once: balls couple only through the rings, held here) at the first
    iteration when ``fresh``, else kept from an earlier step, and retaken at an iteration where the residual
    of a ball not yet converged did not shrink by SHRINK (modified Newton). With ``inertia`` 1 the balance
    carries the centres' radial and axial inertia against their rates ``qref`` (Z, 2) [m/s] at the step's start
    (:func:`_add_inertia`; ``g`` keeps the contacts' stiffness alone and the iteration inverts G - m_b / dt^2):
    a ball that its contacts hold less stiffly than m_b / dt^2 (a lightly loaded ball, one with a contact open)
    moves as a body of its mass, and one whose contacts are all open flies on with its rate under its force (one
    correction: its residual is linear) and then stays put for the step (the rule of docs/theory/reduced.md, "A
    lightly loaded ball"); with ``inertia`` 0 (a run's start, the level's frozen balance) the balance alone, and
    where G is not negative definite the iteration adds m_b / dt^2 to the stiffness it inverts (a ball without
    contact moves by its force from rest over one step, dq = R dt^2 / m_b). A loaded ball has converged where
    the correction its residual asks for is below ``tol`` [m], and that correction is left out (its centre
    stays where it was evaluated): an iteration in which every ball converged and none moved (and which took
    no Jacobian) ends the balance on the evaluation just made, without evaluating the forces once more. Left
    out rather than applied without an evaluation, so that the committed evaluation is at the state: the next
    step's Jacobians are differences about it (a development run that applied them moved the 6208 radial's
    drive power at 100 us by -4 %, its jphi taken about a state 1e-12 m off its committed evaluation). Leaves
    the forces of the final q evaluated (the step's committed evaluation; with ``want`` with the kernel's
    diagnostics for a sample, every iteration's evaluation taking them, as any may be the last).
    Returns (iterations, converged, worst overlap ratio)."""
    z = phi.shape[0]
    k_min = p[P_MB] / (dt * dt)
    for j in range(z):
        done[j] = 0.0
    it = 0
    converged = False
    worst = 0.0
    need_jac = fresh
    while True:
        worst = reduced_evaluate(t, dt, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz,
                                 fb, tb, fc, fr, fring, glob, diag, cage_load, want, res, acc, defect_path,
                                 ellipse_path, loss_path)
        work[W_EVALS] += 1.0
        if inertia > 0.0:
            _add_inertia(q, q_old, qref, dt, inertia * p[P_MB], res)
        if converged or it >= max_iter or not math.isfinite(worst):
            break
        for j in range(z):
            if it > 0 and done[j] < 0.5 and (res[j, 0] * res[j, 0] + res[j, 1] * res[j, 1]
                                             > SHRINK * SHRINK * (r0[j, 0] * r0[j, 0] + r0[j, 1] * r0[j, 1])):
                need_jac = True  # a kept Jacobian that no longer serves
            r0[j, 0] = res[j, 0]
            r0[j, 1] = res[j, 1]
        clean = True  # the arrays hold the evaluation at the present q (no perturbed evaluation since)
        if need_jac:
            need_jac = False
            clean = False
            work[W_JAC] += 1.0
            for c in range(2):
                for j in range(z):
                    q[j, c] += H_POS
                reduced_evaluate(t, dt, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz,
                                 fb, tb, fc, fr, fring, glob, diag, cage_load, False, res, acc, defect_path,
                                 ellipse_path, loss_path)
                work[W_EVALS] += 1.0
                if inertia > 0.0:
                    _add_inertia(q, q_old, qref, dt, inertia * p[P_MB], res)
                for j in range(z):
                    q[j, c] -= H_POS
                    g[j, 0, c] = (res[j, 0] - r0[j, 0]) / H_POS
                    g[j, 1, c] = (res[j, 1] - r0[j, 1]) / H_POS
                    # g keeps the contacts' stiffness alone (the ring's condensation adds the inertia itself)
                    g[j, c, c] += inertia * k_min
        it += 1
        converged = True
        moved = False
        for j in range(z):
            if done[j] > 0.5:
                continue
            # dq = -G^-1 R, G = dR/dq, negative definite where the contacts hold the ball; where it is not
            # (no contact, or a contact just closing), -(G - k_min I)^-1 R
            a11 = g[j, 0, 0] - inertia * k_min
            a12 = g[j, 0, 1]
            a21 = g[j, 1, 0]
            a22 = g[j, 1, 1] - inertia * k_min
            det = a11 * a22 - a12 * a21
            if not (det > 1e-6 * k_min * k_min and a11 + a22 < 0.0):
                a11 -= k_min
                a22 -= k_min
                det = a11 * a22 - a12 * a21
            d0 = -(a22 * r0[j, 0] - a12 * r0[j, 1]) / det
            d1 = -(a11 * r0[j, 1] - a21 * r0[j, 0]) / det
            size = math.sqrt(d0 * d0 + d1 * d1)
            # hz[.., HZ_GEO + 6]: the overlaps of the last evaluation (after a Jacobian, of q perturbed by H_POS)
            open_contacts = hz[j, 0, HZ_GEO + 6] <= 0.0 and hz[j, 1, HZ_GEO + 6] <= 0.0
            if size < tol and not open_contacts:
                # converged: the correction below tol is left out, so that the evaluation just made is at the
                # state (the Jacobians of the next step are differences about it)
                done[j] = 1.0
                continue
            if size > STEP_MAX:  # a trust region: the linearisation holds over a fraction of the overlaps
                d0 *= STEP_MAX / size
                d1 *= STEP_MAX / size
            q[j, 0] += d0
            q[j, 1] += d1
            moved = True
            if open_contacts:
                done[j] = 1.0  # free: moved once from rest, then held for the step
            else:
                converged = False
        if converged and not moved and clean:
            break  # the evaluation at the present q is the committed one
    work[W_ITER] += it
    if it > work[W_ITER_MAX]:
        work[W_ITER_MAX] = it
    if not converged:
        work[W_UNCONVERGED] += 1.0
    return it, converged, worst


@kernel(internal=True)
def _speed_jacobians(t, dt, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb, tb, fc,
                      fr, fring, glob, diag, cage_load, res, acc, acc0, ac0, sh0, sh1, ac1, fbp, tbp, fcp, frp, globp,
                      clp, jphi, jb, jcb, jbc, jcc, h_om, h_w, h_cage, pockets, want_no, work, defect_path,
                      ellipse_path, loss_path):
    """Step (2) of :func:`run_reduced`: the Jacobians of the balls' (om', w') in (phi, om, w) (``jphi``, ``jb``)
    and, with ``pockets`` (the rigid cage), the cage's rows and columns (``jcb``, ``jbc``, ``jcc``; the pockets'
    shares :func:`_pocket_shares`), by differences about the state evaluated last, whose accelerations are
    ``acc0``, ``ac0`` and pocket shares ``sh0``."""
    z = phi.shape[0]
    nc = N_CAGE
    # (2) ball-speed Jacobians: component k of every ball at once; and the forces' dependence on the
    # orbital angle (the load zone's geometry the ball moves through)
    # with the cage, the balls and the cage turned together (the pockets' gaps unchanged: the load zone's
    # geometry alone); the column of phi_j is this joint column less the cage angle's, taken below, so that
    # the pockets' stiffness in them cancels exactly where balls and cage turn alike (a step turns them by
    # om dt, thousands of times the pockets' overlaps)
    for j in range(z):
        phi[j] += H_ANGLE
    if pockets:
        xc[1, 0] += H_ANGLE
    reduced_evaluate(t, dt, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb,
                     tb, fc, fr, fring, glob, diag, cage_load, want_no, res, acc, defect_path, ellipse_path,
                     loss_path)
    work[W_EVALS] += 1.0
    if pockets:
        _pocket_shares(p, xb, vb, wb, xc, vc, rings, fbp, tbp, fcp, frp, globp, clp, sh1)
        xc[1, 0] -= H_ANGLE
        for j in range(z):
            for i in range(4):
                jcb[j, i, 0] = (sh1[j, i] - sh0[j, i]) / H_ANGLE
    for j in range(z):
        phi[j] -= H_ANGLE
        for i in range(4):
            jphi[j, i] = (acc[j, i] - acc0[j, i]) / H_ANGLE
    for k in range(4):
        h = h_om if k == 0 else h_w
        for j in range(z):
            if k == 0:
                om[j] += h
            else:
                wo[j, k - 1] += h
        reduced_evaluate(t, dt, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb, tb,
                         fc, fr, fring, glob, diag, cage_load, want_no, res, acc, defect_path, ellipse_path,
                         loss_path)
        work[W_EVALS] += 1.0
        if pockets:
            _pocket_shares(p, xb, vb, wb, xc, vc, rings, fbp, tbp, fcp, frp, globp, clp, sh1)
            for j in range(z):
                for i in range(4):
                    jcb[j, i, 1 + k] = (sh1[j, i] - sh0[j, i]) / h
        for j in range(z):
            if k == 0:
                om[j] -= h
            else:
                wo[j, k - 1] -= h
            for i in range(4):
                jb[j, i, k] = (acc[j, i] - acc0[j, i]) / h
    # the cage's entries: every ball's acceleration and the cage's (balls, ring held)
    if pockets:
        for k in range(nc):
            _cage_add(xc, vc, k, h_cage[k])
            reduced_evaluate(t, dt, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist,
                             hz, fb, tb, fc, fr, fring, glob, diag, cage_load, want_no, res, acc,
                             defect_path, ellipse_path, loss_path)
            work[W_EVALS] += 1.0
            _cage_add(xc, vc, k, -h_cage[k])
            _cage_accelerations(p, fc, ac1)
            for i in range(4):
                jcc[i, k] = (ac1[i] - ac0[i]) / h_cage[k]
                for j in range(z):
                    jbc[j, i, k] = (acc[j, i] - acc0[j, i]) / h_cage[k]
            if k == 3:  # the columns of phi_j: the joint rotation's less the cage angle's
                _cage_add(xc, vc, k, h_cage[k])
                _pocket_shares(p, xb, vb, wb, xc, vc, rings, fbp, tbp, fcp, frp, globp, clp, sh1)
                _cage_add(xc, vc, k, -h_cage[k])
                for j in range(z):
                    for i in range(4):
                        jphi[j, i] -= jbc[j, i, 3]
                        jcb[j, i, 0] -= (sh1[j, i] - sh0[j, i]) / h_cage[3]


@kernel(inline="always")
def _copy_step_state(phi, om, wo, q, q_old, prev, ring, ring_prev, xc, vc, cage_prev,
                     d_phi, d_om, d_wo, d_q, d_q_old, d_prev, d_ring, d_ring_prev, d_xc, d_vc, d_cage_prev):
    """Copy the integrated state at t_n (the balls' angles, speeds, force-balance unknowns and BDF history, the
    ring's, the cage's) into the ``d_`` arrays: the step control keeps it before a step and restores it when
    the step is rejected."""
    for j in range(phi.shape[0]):
        d_phi[j] = phi[j]
        d_om[j] = om[j]
        for k in range(wo.shape[1]):
            d_wo[j, k] = wo[j, k]
        for k in range(q.shape[1]):
            d_q[j, k] = q[j, k]
            d_q_old[j, k] = q_old[j, k]
        for k in range(prev.shape[1]):
            d_prev[j, k] = prev[j, k]
    for k in range(ring.shape[0]):
        d_ring[k] = ring[k]
        d_ring_prev[k] = ring_prev[k]
    for r in range(2):
        for k in range(3):
            d_xc[r, k] = xc[r, k]
            d_vc[r, k] = vc[r, k]
    for k in range(cage_prev.shape[0]):
        d_cage_prev[k] = cage_prev[k]


@kernel
def run_reduced(n_steps, t0, dt, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb, tb,
                fc, fr, fring, glob, diag, cage_load, tol, max_iter, sample_every, step0, s_t, s_glob, s_diag,
                s_cage, s_xb, s_vb, s_wb, s_xc, s_vc, s_ring, work, ring_free, jac_every, jac_tol, ring_every, prev, ring_prev,
                cage_free, cage_prev, n_corr, adapt, ys, h_log, qd, defect_path=True, ellipse_path=True,
                loss_path=True):
    """``n_steps`` steps of the reduced engine from t0 (module docstring; docs/theory/reduced.md).

    Each step from t_n: (1) the forces at t_n (the balls on their balance of the last step); the Jacobians of
    (2) and (3) are retaken at a chunk's first step, after ``jac_every`` steps, where a ball's load proxy
    (the overlaps^1.5 of its contacts) moved by more than ``jac_tol`` of its own since (at least
    :data:`LOAD_FLOOR` of the largest ball's), and where a ball's speeds moved by more than :data:`SPEED_TOL`
    of its orbital surface speed, else kept (the ring's at every ``ring_every``-th retaking);
    (2) the per-ball Jacobian of (om', w') in (phi, om, w) by differences, one evaluation per component with
    every ball perturbed at once (phi: the ball's place in the load zone, whose geometry the step would otherwise take
    one step late); (3) with ``ring_free``, the inner ring's 3 x 3 stiffness K, condensed over the balls'
    force balance, and damping C (balls held) by differences; (4) linearly implicit BDF2 of each ball's
    (phi, om, w_o) and of the ring's (x, v): one Newton step of y_{n+1} - 4/3 y_n + 1/3 y_{n-1} =
    2/3 dt f(y_{n+1}) from the extrapolation 2 y_n - y_{n-1}, with f there f_n + J (y_n - y_{n-1}) (no force
    evaluation beyond the step's), linearly implicit Euler where the state before is not yet kept (``prev``
    (Z, 5), ``ring_prev`` (6), flag in ``work``); (5) the balls' force balance at t_{n+1} (:func:`_balance`)
    with the centres' inertia against their rates at t_n (kept in ``qd`` (Z, 2) [m/s], which a later call's first
    balance re-solving the last step's takes again; the run's first balance and first step start from rest),
    warm started by the extrapolation 2 q_n - q_{n-1}, its Jacobians retaken with those of (2) and else kept
    (:func:`_balance_sampled`; a step that ends on a sample takes the diagnostics in its evaluations). With
    ``cage_free`` (the rigid cage) the cage's state
    (:data:`N_CAGE`, in the cage rows of ``xc``, ``vc``; ``cage_prev`` its value one step earlier) is advanced
    with the balls in one arrow-shaped linearly implicit step (:func:`_arrow_step`), its Jacobians by
    differences at (2) (:func:`_speed_jacobians`): every ball's acceleration and the cage's in the cage's 8
    entries (one evaluation each, every ball's column at once) and the cage's in each ball's state (the
    pockets' shares, :func:`_pocket_shares`, in the evaluations of (2)); a pocket contact that closed or opened
    since the last step retakes them, and the step gets up to ``n_corr`` Newton corrections of its equations at
    the state reached while their residual is above :data:`CORR_TOL` (with the Jacobians retaken there where a
    pocket contact closed or opened over the step, else with the step's matrix). The energy
    integrals take the committed evaluation of each
    step; every ``sample_every``-th step (counted from ``step0``) goes to the sample buffers (as
    :func:`~exudyn_bearing.solvers.reference.integrators.run_verlet`).
    Returns (steps done, samples written, status): 0 ok, 1 non-finite state, 2 runaway overlap."""
    z = phi.shape[0]
    mb = p[P_MB]
    mr = p[P_MR]
    res = np.zeros((z, 2))
    acc = np.zeros((z, 4))
    acc0 = np.zeros((z, 4))
    jb = np.zeros((z, 4, 4))
    jphi = np.zeros((z, 4))
    g = np.zeros((z, 2, 2))
    r0 = np.zeros((z, 2))
    done = np.zeros(z)
    fb0 = np.zeros((z, 3))
    bmat = np.zeros((z, 3, 3))
    fring0 = np.zeros(3)
    kr = np.zeros((3, 3))
    cr = np.zeros((3, 3))
    q_n = np.zeros((z, 2))
    proxy = np.zeros(z)
    load_ref = np.zeros(z)
    spd_ref = np.zeros((z, 4))
    since = 0
    n_ref = 0
    a5 = np.zeros((5, 5))
    b5 = np.zeros(5)
    j5 = np.zeros((5, 5))
    y5 = np.zeros(5)
    d5 = np.zeros(5)
    a6 = np.zeros((6, 6))
    # the rigid cage: its Jacobians, its accelerations at t_n, the pockets' shares and the step's scratch
    nc = N_CAGE
    jbc = np.zeros((z, 4, nc))
    jcb = np.zeros((z, 4, 5))
    jcc = np.zeros((4, nc))
    ac0 = np.zeros(4)
    ac1 = np.zeros(4)
    sh0 = np.zeros((z, 4))
    sh1 = np.zeros((z, 4))
    fbp = np.zeros((z, 3))
    tbp = np.zeros((z, 3))
    fcp = np.zeros((z, 3))
    frp = np.zeros((2, 6))
    globp = np.zeros(NGLOBAL)
    clp = np.zeros((z, 2))
    ya = np.zeros((z, 5, nc))
    xa = np.zeros((z, 5))
    dca = np.zeros(nc)
    rca = np.zeros(nc)
    a8 = np.zeros((nc, nc))
    h_cage = np.zeros(nc)
    pocket_on = np.zeros(z)
    prev2 = np.zeros((z, 5))
    cage_prev2 = np.zeros(nc)
    resb = np.zeros((z, 5))
    resc = np.zeros(nc)
    keep_b = np.zeros((z, 5))
    keep_q = np.zeros((z, 2))
    keep_c = np.zeros(nc)
    acc_b = np.zeros((z, 4))
    ac_b = np.zeros(4)
    sh_b = np.zeros((z, 4))
    for k in range(3):
        h_cage[k] = H_POS
        h_cage[4 + k] = H_SPEED
    h_cage[3] = H_ANGLE  # as the balls' angle: the joint rotation below takes the same difference
    h_cage[7] = H_SPEED / p[P_RP]
    b6 = np.zeros(6)
    j6 = np.zeros((6, 6))
    d6 = np.zeros(6)
    n_samp = np.int64(0)
    want_no = np.bool_(False)
    want_yes = np.bool_(True)
    h_om = H_SPEED / np.mean(q[:, 0])  # a surface speed of H_SPEED at the pitch circle
    h_w = H_SPEED / p[P_RB]            # and on the ball's surface
    h_v = H_SPEED
    # the first step's Jacobians of the force balance; from a start off the balance (the analytic start, a
    # quasi-static start under another hypothesis than the dynamics') the iteration converges linearly from afar
    # and may take more than max_iter: START_ITER times as many here
    # the step error control (``adapt``, :data:`N_ADAPT`; its tolerance 0: the fixed step dt): the time reached,
    # the step proposed, the two steps before, and the speeds of the last three accepted states in ``ys``
    adaptive = adapt[A_TOL] > 0.0
    nv = ys.shape[1]
    y_new = np.zeros(nv)
    est = np.zeros(nv)
    wgt = np.zeros(nv)
    _speed_scales(p, z, wgt)
    f_phi = np.zeros(z)
    f_om = np.zeros(z)
    f_wo = np.zeros((z, 3))
    f_xc = np.zeros_like(xc)
    f_vc = np.zeros_like(vc)
    keep_phi = np.zeros(z)
    keep_om = np.zeros(z)
    keep_wo = np.zeros((z, 3))
    keep_q2 = np.zeros((z, 2))
    keep_qo = np.zeros((z, 2))
    keep_prev = np.zeros((z, 5))
    keep_ring = np.zeros(6)
    keep_rp = np.zeros(6)
    keep_xc = np.zeros((2, 3))
    keep_vc = np.zeros((2, 3))
    keep_cp = np.zeros(nc)
    glob_n = np.zeros(NGLOBAL)
    t_now = t0
    hs = dt  # the step that reached the state at t_n (the centres' rate (q_n - q_{n-1}) / hs)
    h = dt
    if adaptive:
        t_now = adapt[A_T]
        hs = adapt[A_HPREV]
        h = adapt[A_H]
        if adapt[A_NHIST] < 0.5:
            _state_vector(phi, om, wo, ring, xc, vc, ys[0])
            adapt[A_NHIST] = 1.0
    # the first step's Jacobians of the force balance; from a start off the balance (the analytic start, a
    # quasi-static start under another hypothesis than the dynamics') the iteration converges linearly from afar
    # and may take more than max_iter: START_ITER times as many here
    # the centres' inertia against their rates at the last balance's start (qd), once a step has taken them: a
    # later call re-solves its last balance; a run's start solves the balance itself
    inertia0 = 1.0 if work[W_HAVE_RATE] > 0.5 else 0.0
    it, ok, worst = _balance(t_now, hs, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb,
                             tb, fc, fr, fring, glob, diag, cage_load, res, acc, g, r0, done, tol,
                             START_ITER * max_iter, work, want_yes, qd, inertia0, defect_path, ellipse_path, loss_path)
    step = 0
    force_jac = False
    rejected = 0  # rejections at the present t_n
    h_prop = h
    while step < n_steps:
        ratio = 1.0
        land = False
        sample_here = False
        if adaptive:
            # the step: the proposal, at most the largest, landing on the next sample time (or t_end) in equal
            # steps (a step may stretch to 1 / SAFETY of the proposal to land), so that the steps stay constant
            # between samples where the proposal does
            t_samp = (adapt[A_KSAMP] + 1.0) * adapt[A_SDT]
            t_end = adapt[A_TEND]
            if t_now >= t_end - 1e-9 * adapt[A_SDT]:
                break
            target = t_samp
            sample_here = True
            if t_samp > t_end + 1e-9 * adapt[A_SDT]:
                target = t_end
                sample_here = False
            h = min(h, adapt[A_HMAX])
            h_prop = h
            rem = target - t_now
            n_left = math.ceil(rem / min(h / SAFETY, adapt[A_HMAX]) - 1e-9)
            if n_left <= 1:
                h = rem
                land = True
            else:
                h = rem / n_left
            t = t_now
            t1 = target if land else t_now + h
            ratio = h / hs
            # save the state at t_n (a rejected step goes back to it)
            _copy_step_state(phi, om, wo, q, q_old, prev, ring, ring_prev, xc, vc, cage_prev,
                             keep_phi, keep_om, keep_wo, keep_q2, keep_qo, keep_prev, keep_ring, keep_rp, keep_xc,
                             keep_vc, keep_cp)
            for k in range(NGLOBAL):
                glob_n[k] = glob[k]  # the powers of the committed evaluation at t_n
        else:
            t = t0 + step * dt
            t1 = t0 + (step + 1) * dt
        # (1) the committed forces at t_n are those of the last balance (acc, fb, fring)
        for j in range(z):
            for k in range(4):
                acc0[j, k] = acc[j, k]
            for d in range(3):
                fb0[j, d] = fb[j, d]
        for d in range(3):
            fring0[d] = fring[d]
        if cage_free:
            _cage_accelerations(p, fc, ac0)
        # the Jacobians of steps (2), (3): kept for up to jac_every steps, retaken sooner where a ball's load
        # proxy (overlaps^1.5 of both contacts) moved by more than jac_tol of its own at the last retaking (at
        # least LOAD_FLOOR of the largest ball's)
        big = 0.0
        moved = 0.0
        for j in range(z):
            pj = 0.0
            for race in range(2):
                d = hz[j, race, HZ_GEO + 6]
                if d > 0.0:
                    pj += d * math.sqrt(d)
            proxy[j] = pj
            if load_ref[j] > big:
                big = load_ref[j]
        for j in range(z):
            change = abs(proxy[j] - load_ref[j])
            scale = max(load_ref[j], LOAD_FLOOR * big)
            if change > 0.0:
                moved = max(moved, change / scale if scale > 0.0 else math.inf)
        # and where a ball's speeds (orbital speed at the pitch radius, angular velocity at the ball's surface)
        # moved by more than SPEED_TOL of its orbital surface speed (at least the regularising speed) since: the
        # traction's slopes follow the rolling speed (a run-up)
        sped = 0.0
        for j in range(z):
            u = max(abs(spd_ref[j, 0]) * p[P_RP], p[P_VREG])
            du = abs(om[j] - spd_ref[j, 0]) * p[P_RP]
            for k in range(3):
                du = max(du, abs(wo[j, k] - spd_ref[j, 1 + k]) * p[P_RB])
            sped = max(sped, du / u)
        refresh = (since >= jac_every or moved > jac_tol or sped > SPEED_TOL or step == 0 or force_jac)
        force_jac = False
        # the rigid cage: a pocket contact that closed or opened since the last step retakes the Jacobians (the
        # pockets' shares at t_n, sh0, serve the Jacobians below)
        pockets = cage_free
        if pockets:
            _pocket_shares(p, xb, vb, wb, xc, vc, rings, fbp, tbp, fcp, frp, globp, clp, sh0)
            for j in range(z):
                touch = 1.0 if fbp[j, 0] != 0.0 or fbp[j, 1] != 0.0 or fbp[j, 2] != 0.0 else 0.0
                if touch != pocket_on[j]:
                    refresh = True
                    pocket_on[j] = touch
        since += 1
        if refresh:
            since = 1
            work[W_REFRESH] += 1.0
            for j in range(z):
                load_ref[j] = proxy[j]
                spd_ref[j, 0] = om[j]
                for k in range(3):
                    spd_ref[j, 1 + k] = wo[j, k]
            _speed_jacobians(t, hs, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings,
                             hist, hz, fb, tb, fc, fr, fring, glob, diag, cage_load, res, acc, acc0, ac0,
                             sh0, sh1, ac1, fbp, tbp, fcp, frp, globp, clp, jphi, jb, jcb, jbc, jcc, h_om,
                             h_w, h_cage, pockets, want_no, work, defect_path, ellipse_path, loss_path)
            # (3) the ring's stiffness (condensed over the balls' balance) and damping, at every ring_every-th
            # retaking of the Jacobians
            n_ref += 1
            if ring_free and (n_ref - 1) % ring_every == 0:
                for k in range(3):
                    ring[k] += H_POS
                    reduced_evaluate(t, hs, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb,
                                     tb, fc, fr, fring, glob, diag, cage_load, want_no, res, acc, defect_path,
                                     ellipse_path, loss_path)
                    work[W_EVALS] += 1.0
                    ring[k] -= H_POS
                    for i in range(3):
                        kr[i, k] = (fring[i] - fring0[i]) / H_POS
                    for j in range(z):
                        for i in range(3):
                            bmat[j, i, k] = (fb[j, i] - fb0[j, i]) / H_POS
                    ring[3 + k] += h_v
                    reduced_evaluate(t, hs, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb,
                                     tb, fc, fr, fring, glob, diag, cage_load, want_no, res, acc, defect_path,
                                     ellipse_path, loss_path)
                    work[W_EVALS] += 1.0
                    ring[3 + k] -= h_v
                    for i in range(3):
                        cr[i, k] = (fring[i] - fring0[i]) / h_v
                # K += sum_j B_j E_j (-(G_j - k_min I)^-1) E_j^T B_j: dF_ring/dx_b = B_j = dF_b/dx_ring (the contact
                # force depends on x_b - x_ring; the ring takes its reaction), the balls' q re-solved
                k_min = mb / (h * h)
                for j in range(z):
                    c = math.cos(phi[j])
                    s = math.sin(phi[j])
                    # E^T B (2 x 3): rows e_r . B, e_z . B
                    e0 = (c * bmat[j, 0, 0] + s * bmat[j, 1, 0], c * bmat[j, 0, 1] + s * bmat[j, 1, 1],
                          c * bmat[j, 0, 2] + s * bmat[j, 1, 2])
                    e1 = (bmat[j, 2, 0], bmat[j, 2, 1], bmat[j, 2, 2])
                    a11 = g[j, 0, 0] - k_min
                    a12 = g[j, 0, 1]
                    a21 = g[j, 1, 0]
                    a22 = g[j, 1, 1] - k_min
                    det = a11 * a22 - a12 * a21
                    # M = -(G - k_min I)^-1 (2 x 2)
                    m11 = -a22 / det
                    m12 = a12 / det
                    m21 = a21 / det
                    m22 = -a11 / det
                    for k in range(3):
                        y0 = m11 * e0[k] + m12 * e1[k]  # dq_r / dx_ring_k
                        y1 = m21 * e0[k] + m22 * e1[k]  # dq_z / dx_ring_k
                        # B E y: E y = y0 e_r + y1 e_z
                        ux, uy, uz = y0 * c, y0 * s, y1
                        for i in range(3):
                            kr[i, k] += bmat[j, i, 0] * ux + bmat[j, i, 1] * uy + bmat[j, i, 2] * uz
        # (4) the ball states y = (phi, om, w_o) and the ring (x, v): linearly implicit BDF2 from the second step
        # (one Newton step of y_{n+1} - 4/3 y_n + 1/3 y_{n-1} = 2/3 dt f(y_{n+1}) from the extrapolation y_n + D,
        # D = y_n - y_{n-1}, f there taken as f_n + J D), linearly implicit Euler at the first
        bdf2 = work[W_HAVE_PREV] > 0.5
        gam = 2.0 / 3.0 if bdf2 else 1.0
        if bdf2 and ratio != 1.0:
            # the variable-step BDF2 (step ratio w = h_n / h_{n-1}): y_{n+1} - y_n - w (1 - gam) (y_n - y_{n-1}) =
            # gam h_n f(y_{n+1}), gam = (1 + w) / (1 + 2 w), from the extrapolation y_n + w (y_n - y_{n-1}): the
            # constant-step code with y_{n-1} replaced by y_n - w (y_n - y_{n-1}) (docs/theory/reduced.md)
            gam = (1.0 + ratio) / (1.0 + 2.0 * ratio)
            for j in range(z):
                prev[j, 0] = phi[j] - ratio * (phi[j] - prev[j, 0])
                prev[j, 1] = om[j] - ratio * (om[j] - prev[j, 1])
                for k in range(3):
                    prev[j, 2 + k] = wo[j, k] - ratio * (wo[j, k] - prev[j, 2 + k])
            for k in range(6):
                ring_prev[k] = ring[k] - ratio * (ring[k] - ring_prev[k])
            for k in range(nc):
                y_k = _cage_get(xc, vc, k)
                cage_prev[k] = y_k - ratio * (y_k - cage_prev[k])
        if cage_free:
            for j in range(z):
                for i in range(5):
                    prev2[j, i] = prev[j, i]
            for i in range(nc):
                cage_prev2[i] = cage_prev[i]
            if not _arrow_step(jphi, jb, acc0, phi, om, wo, prev, jbc, jcb, jcc, ac0, xc, vc, cage_prev, gam, h,
                               bdf2, a5, b5, d5, ya, xa, dca, rca, a8, False, resb, resc):
                return step, n_samp, 1
        for j in range(z):
            if cage_free:
                break
            y5[0] = phi[j]
            y5[1] = om[j]
            for d in range(3):
                y5[2 + d] = wo[j, d]
            for i in range(5):
                for k in range(5):
                    j5[i, k] = 0.0
            j5[0, 1] = 1.0  # phi' = om
            for i in range(4):
                j5[1 + i, 0] = jphi[j, i]
                for k in range(4):
                    j5[1 + i, 1 + k] = jb[j, i, k]
            b5[0] = om[j]
            for i in range(4):
                b5[1 + i] = acc0[j, i]
            if not _implicit_step(j5, b5, y5, prev[j], 5, gam, h, bdf2, a5, d5):
                return step, n_samp, 1
            phi[j] = y5[0]
            om[j] = y5[1]
            for d in range(3):
                wo[j, d] = y5[2 + d]
        if ring_free:
            for i in range(6):
                for k in range(6):
                    j6[i, k] = 0.0
            for i in range(3):
                j6[i, 3 + i] = 1.0  # x' = v
                for k in range(3):
                    j6[3 + i, k] = kr[i, k] / mr
                    j6[3 + i, 3 + k] = cr[i, k] / mr
                b6[i] = ring[3 + i]
                b6[3 + i] = fring0[i] / mr
            if not _implicit_step(j6, b6, ring, ring_prev, 6, gam, h, bdf2, a6, d6):
                return step, n_samp, 1
        work[W_HAVE_PREV] = 1.0
        # (5) the balls' force balance at t_{n+1} with the centres' inertia (their rate at t_n in qd; at the run's
        # first step from rest), warm started by extrapolation
        for j in range(z):
            for c in range(2):
                qd[j, c] = (q[j, c] - q_old[j, c]) / hs if work[W_HAVE_RATE] > 0.5 else 0.0
                q_n[j, c] = q[j, c]
                if ratio == 1.0:
                    q[j, c] = 2.0 * q[j, c] - q_old[j, c]
                else:
                    q[j, c] = q[j, c] + ratio * (q[j, c] - q_old[j, c])
                q_old[j, c] = q_n[j, c]
        # a step that ends on a sample takes the kernel's diagnostics in the balance's committed evaluation; the
        # balance's Jacobians are retaken with the speeds' (else kept: the balance retakes them where an iteration
        # gains less than SHRINK)
        if adaptive:
            sample_due = sample_here and land and n_samp < s_t.shape[0]
        else:
            sample_due = (step0 + step + 1) % sample_every == 0 and n_samp < s_t.shape[0]
        sampled = sample_due
        work[W_HAVE_RATE] = 1.0
        it, ok, worst = _balance_sampled(t1, h, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist,
                                         hz, fb, tb, fc, fr, fring, glob, diag, cage_load, res, acc, g, r0, done, tol,
                                         max_iter, work, refresh, sample_due, qd, 1.0, defect_path, ellipse_path,
                                         loss_path)
        # the rigid cage: Newton corrections of the step's equations at the state reached, each followed by the
        # balls' balance, while their largest speed residual with the committed evaluation is above CORR_TOL (the
        # linearly implicit step's one Newton step leaves the pockets' nonlinearity within the step out: the
        # speeds then moved under other forces than those counted in the energy integrals, which a step's end
        # evaluation takes); where a pocket contact closed or opened over the step the Jacobians are retaken at
        # the state reached, else the step's matrix serves (a chord iteration)
        if cage_free and n_corr > 0:
            _pocket_shares(p, xb, vb, wb, xc, vc, rings, fbp, tbp, fcp, frp, globp, clp, sh1)
            changed = False
            for j in range(z):
                touch = 1.0 if fbp[j, 0] != 0.0 or fbp[j, 1] != 0.0 or fbp[j, 2] != 0.0 else 0.0
                if touch != pocket_on[j]:
                    changed = True
            last = 1e300
            for _c in range(n_corr + 1):
                _cage_accelerations(p, fc, ac1)
                size = _step_residual(phi, om, wo, prev, prev2, acc, xc, vc, cage_prev, cage_prev2, ac1, gam, h,
                                      resb, resc, p[P_RP], p[P_RB])
                if size > last:  # the correction did not serve: back to the state before it
                    for j in range(z):
                        phi[j] = keep_b[j, 0]
                        om[j] = keep_b[j, 1]
                        for k in range(3):
                            wo[j, k] = keep_b[j, 2 + k]
                        q[j, 0] = keep_q[j, 0]
                        q[j, 1] = keep_q[j, 1]
                    for i in range(nc):
                        _cage_add(xc, vc, i, keep_c[i] - _cage_get(xc, vc, i))
                    it, ok, worst = _balance(t1, h, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc,
                                             rings, hist, hz, fb, tb, fc, fr, fring, glob, diag, cage_load, res,
                                             acc, g, r0, done, tol, max_iter, work, want_no, qd, 1.0,
                                             defect_path, ellipse_path, loss_path)
                    break
                if size < CORR_TOL or _c == n_corr:
                    break
                last = size
                for j in range(z):
                    keep_b[j, 0] = phi[j]
                    keep_b[j, 1] = om[j]
                    for k in range(3):
                        keep_b[j, 2 + k] = wo[j, k]
                    keep_q[j, 0] = q[j, 0]
                    keep_q[j, 1] = q[j, 1]
                for i in range(nc):
                    keep_c[i] = _cage_get(xc, vc, i)
                # where a pocket contact closed or opened, Newton's matrix at the state reached (the step's came
                # from t_n, where the contact was in its other state): the Jacobians retaken about it
                if changed:
                    for j in range(z):
                        for i in range(4):
                            acc_b[j, i] = acc[j, i]
                    for i in range(4):
                        ac_b[i] = ac1[i]
                    _pocket_shares(p, xb, vb, wb, xc, vc, rings, fbp, tbp, fcp, frp, globp, clp, sh_b)
                    _speed_jacobians(t1, h, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings,
                                     hist, hz, fb, tb, fc, fr, fring, glob, diag, cage_load, res, acc, acc_b, ac_b,
                                     sh_b, sh1, ac1, fbp, tbp, fcp, frp, globp, clp, jphi, jb, jcb, jbc, jcc, h_om,
                                     h_w, h_cage, True, want_no, work, defect_path, ellipse_path, loss_path)
                if not _arrow_step(jphi, jb, acc0, phi, om, wo, prev, jbc, jcb, jcc, ac0, xc, vc, cage_prev, gam,
                                   h, bdf2, a5, b5, d5, ya, xa, dca, rca, a8, True, resb, resc):
                    return step, n_samp, 1
                work[W_CORR] += 1.0
                sampled = False  # the corrections' balances evaluate without the diagnostics
                it, ok, worst = _balance(t1, h, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings,
                                         hist, hz, fb, tb, fc, fr, fring, glob, diag, cage_load, res, acc, g, r0,
                                         done, tol, max_iter, work, want_no, qd, 1.0, defect_path, ellipse_path,
                                         loss_path)
        if adaptive:
            # the local error of the step (docs/theory/reduced.md): gam h_n^2 (h_n + h_{n-1}) times the third
            # divided difference of the state over the last four states, filtered by the step's matrix
            # (I - gam h J)^-1 (Shampine's filter: a stiff mode's share damped as the step damps it), its speeds
            # against tolerance x speed scale
            _state_vector(phi, om, wo, ring, xc, vc, y_new)
            err = 0.0
            estimated = adapt[A_NHIST] > 2.5
            if estimated:
                h1 = hs
                h2 = adapt[A_HPREV2]
                for i in range(nv):
                    d1a = (y_new[i] - ys[0, i]) / h
                    d1b = (ys[0, i] - ys[1, i]) / h1
                    d1c = (ys[1, i] - ys[2, i]) / h2
                    d3 = ((d1a - d1b) / (h + h1) - (d1b - d1c) / (h1 + h2)) / (h + h1 + h2)
                    est[i] = gam * h * h * (h + h1) * d3
                if not _filter_estimate(est, z, jphi, jb, jbc, jcb, jcc, j6, ring_free, cage_free, gam, h, a5, d5, a6,
                                        d6, b5, ya, xa, dca, rca, a8, f_phi, f_om, f_wo, f_xc, f_vc, prev, cage_prev,
                                        acc0, ac0, resb, resc):
                    err = 1e300
                for i in range(nv):
                    e = abs(est[i]) * wgt[i]
                    if e > err:
                        err = e
                err /= adapt[A_TOL] * adapt[A_U]
            if not math.isfinite(err):
                err = 1e300
            if err > 1.0:
                if min(h, h_prop) <= adapt[A_HMIN] * (1.0 + 1e-9):
                    adapt[A_T] = t_now
                    adapt[A_ERR] = err
                    return step, n_samp, 3
                # rejected: back to t_n, its forces evaluated again (the committed evaluation of the last step),
                # a smaller step with the Jacobians retaken at t_n
                adapt[A_NREJ] += 1.0
                _copy_step_state(keep_phi, keep_om, keep_wo, keep_q2, keep_qo, keep_prev, keep_ring, keep_rp,
                                 keep_xc, keep_vc, keep_cp, phi, om, wo, q, q_old, prev, ring, ring_prev, xc, vc,
                                 cage_prev)
                reduced_evaluate(t, hs, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb,
                                 tb, fc, fr, fring, glob, diag, cage_load, want_no, res, acc, defect_path,
                                 ellipse_path, loss_path)
                work[W_EVALS] += 1.0
                h = max(adapt[A_HMIN], h * max(FAC_MIN, SAFETY * err ** (-1.0 / 3.0)))
                force_jac = True
                rejected += 1
                if rejected >= 2:
                    # a smaller step did not bring the estimate under the tolerance: the history the estimate
                    # and the BDF2 take is not smooth on the scale of the step (a start off the balance of the
                    # speeds, an impact); restart from t_n: a linearly implicit Euler step, then BDF2, the
                    # estimate again from the fourth state on
                    work[W_HAVE_PREV] = 0.0
                    adapt[A_NHIST] = 1.0
                    adapt[A_NRESTART] += 1.0
                    rejected = 0
                continue
            # accepted: the speeds' history, the step's size, the next step's proposal (no growth right after a
            # rejection)
            for i in range(nv):
                ys[2, i] = ys[1, i]
                ys[1, i] = ys[0, i]
                ys[0, i] = y_new[i]
            if adapt[A_NHIST] < 2.5:
                adapt[A_NHIST] += 1.0
            adapt[A_HPREV2] = hs
            if step < h_log.shape[0]:
                h_log[step] = h
            if not estimated:  # no estimate yet (the first two steps): the first step dt kept
                fac = 1.0
            elif err <= 0.0:
                fac = FAC_MAX
            else:
                fac = min(FAC_MAX, max(FAC_MIN, SAFETY * err ** (-1.0 / 3.0)))
                if 1.0 < fac < FAC_GROW:  # small growths left out (CVODE's threshold): steps that stay put
                    fac = 1.0
            if rejected > 0 and fac > 1.0:
                fac = 1.0
            rejected = 0
            if err > adapt[A_ERR]:
                adapt[A_ERR] = err
            hs = h
            h = h * fac
            t_now = t1
            adapt[A_T] = t_now
            adapt[A_HPREV] = hs
            adapt[A_H] = h
        if adaptive:
            # the energy integrals by the trapezoidal rule over the step: the steps follow the motion (short where
            # a ball enters the load zone), so the fixed step's rectangle at the step's end would weight the
            # powers by where the steps fall
            accumulate_energy(glob, 0.5 * hs)
            for k in ENERGY_WORKS:
                glob_n[k] = glob[k]
            accumulate_energy(glob_n, 0.5 * hs)
            for k in ENERGY_WORKS:
                glob[k] = glob_n[k]
        else:
            accumulate_energy(glob, dt)
        if adaptive and sample_here and land:
            adapt[A_KSAMP] += 1.0
        if sample_due:
            if not sampled:  # the state's forces with the diagnostics (the balance's committed evaluation had none)
                h_sample = hs if adaptive else h
                reduced_evaluate(t1, h_sample, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist,
                                 hz, fb, tb, fc, fr, fring, glob, diag, cage_load, want_yes, res, acc, defect_path,
                                 ellipse_path, loss_path)
                work[W_EVALS] += 1.0
            store_sample(n_samp, t1, glob, diag, cage_load, xb, vb, wb, xc, vc, ring,
                   s_t, s_glob, s_diag, s_cage, s_xb, s_vb, s_wb, s_xc, s_vc, s_ring)
            n_samp += 1
            if not (finite(xb) and finite(vb) and finite(wb) and finite_ring(ring) and finite(xc) and finite(vc)):
                return step + 1, n_samp, 1
        step += 1
        if worst > p[P_MAX_OVERLAP] or not math.isfinite(worst):
            return step, n_samp, 2
    if not (finite(q) and finite(wo) and finite_ring(ring) and finite(xc) and finite(vc)):
        return step, n_samp, 1
    return step, n_samp, 0
