"""Ball equilibrium (compiled): every ball's position and contact loads for an
inner-ring pose, and the generalized force the balls put on the ring.

Per ball (Jones [1]_, Harris & Kotzalas [2]_), in the ball's (r, z) plane at
azimuth psi: outer groove centre p_o (fixed ring), inner groove centre
p_i(psi) moved by the ring pose u = (dx, dy, dz, theta_x, theta_y) with the
small-displacement kinematics

    Delta r = dx cos psi + dy sin psi + z_i (theta_y cos psi - theta_x sin psi)
    Delta z = dz + rho_i (theta_x sin psi - theta_y cos psi)

and the ball centre c solves the two force equations

    -Q_o n_o - Q_i n_i + m omega_m^2 r_c e_r + F_to t_o + F_ti t_i = 0

with n_k = (c - p_k)/|c - p_k| (groove centre to ball centre), overlaps
delta_k = |c - p_k| - (R_ck - R_b), Q_k = K_k delta_k^(3/2) (exact Hertz
constant at the contact's angle, curvature radii taken at the undeformed
contact points as in :func:`exudyn_bearing.physics.load_distribution.static_equilibrium`),
t_k = e_psi x n_k = (n_z, -n_r) the in-plane tangent and F_tk the traction
that carries the gyroscopic moment (:mod:`.kinematics`). The centrifugal
force acts at the ball's actual orbit radius r_c. Newton's method with the
analytic Jacobian; at zero speed the start (loads equal along the groove
centre line, overlaps split by stiffness) is already the solution.

The ring gets -(the forces on the ball at the inner contact); its
generalized force is J^T f with J the matrix of the kinematics above (exact
conjugate of u, so the zero-speed stiffness is symmetric).

References
----------
.. [1] A. B. Jones, "A general theory of elastically constrained ball and
   roller bearings under arbitrary load and speed conditions," J. Basic Eng.
   82 (1960) 309-320. doi:10.1115/1.3662587
.. [2] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed.,
   CRC Press, 2006, Advanced Concepts ch. 'High-speed operation'.
"""
from __future__ import annotations

import math

import numpy as np

from ..._jit import kernel
from ...physics import hertz as _hz
from ...physics.geometry import _raceway_radii_cos

__all__ = ["BALL_FIELDS", "ring_forces"]

#: Columns of the per-ball result array of :func:`ring_forces`.
#: (k_o, k_i: the Hertz constants of the closed contacts, 0 for an open one, whose constant enters no force.)
BALL_FIELDS = ("c_r", "c_z", "q_o", "q_i", "delta_o", "delta_i", "no_r", "no_z", "ni_r", "ni_z", "k_o", "k_i",
               "converged")
(B_CR, B_CZ, B_QO, B_QI, B_DO, B_DI, B_NOR, B_NOZ, B_NIR, B_NIZ, B_KO, B_KI, B_OK) = range(len(BALL_FIELDS))
NB = len(BALL_FIELDS)
#: Length of a ball's warm start (:func:`_ball_equilibrium`): the last solution's centre (c_r, c_z), its kind,
#: the inner groove centre it was solved for (p_r, p_z), the centre's sensitivity dc/dp (2x2, row-major), whether
#: Newton's residual test passed at that centre (1) or its last step was below its floor (0), and what the outer
#: contact's solution depends on besides the centre: m omega^2, F_to, F_ti, the outer groove (rho_o, z_o), R_co, R_b
WARM_START = 17
#: ``table`` and ``start`` of :func:`_ring_forces` for direct Hertz constants and cold starts
_DIRECT = np.empty((3, 0))
_COLD = np.empty((0, WARM_START))


@kernel(no_runtime=True)
def _hertz_constant(r_x, r_y, e_prime, method, table):
    """Hertz constant K [N/m^1.5] of one contact: the direct solution (:func:`exudyn_bearing.physics.hertz._hertz`)
    when ``table`` is empty, else (k, F, E) from :func:`exudyn_bearing.physics.hertz._kfe_fast` (the exact level
    interpolated in :func:`exudyn_bearing.physics.hertz.exact_table`, relative error <= 1e-7)."""
    if table.shape[1] < 2:
        return _hz._hertz(r_x, r_y, e_prime, 0.0, method)[1]
    kappa, ell_f, ell_e = _hz._kfe_fast(r_x, r_y, method, table)
    return _hz._stiffness(kappa, ell_f, ell_e, _hz._curvature_sum_radius(r_x, r_y), e_prime)


@kernel(no_runtime=True)
def _contact_radii(por, rco, rb, rci, nor, nir):
    """Effective radii (R_x, R_y) [m] of the outer and inner contact at the contact angles given by the normals
    (curvature radii at the undeformed contact points, ball centre at its groove-centre distance from the outer
    groove): (R_xo, R_yo, R_xi, R_yi)."""
    r_ref = por + (rco - rb) * nor
    ca_o = nor if nor > 1e-12 else 1e-12
    ca_i = -nir if -nir > 1e-12 else 1e-12
    rxo, ryo = _raceway_radii_cos(rb, rco, r_ref + rb * ca_o, ca_o, False)
    rxi, ryi = _raceway_radii_cos(rb, rci, r_ref - rb * ca_i, ca_i, True)
    return rxo, ryo, rxi, ryi


@kernel(no_runtime=True)
def _contact_constants(por, rco, rb, rci, nor, nir, e_prime, method, table, outer=True, inner=True):
    """Hertz constants K_o, K_i [N/m^1.5] at the contact angles given by the normals (:func:`_contact_radii`);
    ``table``: see :func:`_hertz_constant`; ``outer``, ``inner`` False: that contact's is not computed (0)."""
    rxo, ryo, rxi, ryi = _contact_radii(por, rco, rb, rci, nor, nir)
    ko = _hertz_constant(rxo, ryo, e_prime, method, table) if outer else 0.0
    ki = _hertz_constant(rxi, ryi, e_prime, method, table) if inner else 0.0
    return ko, ki


@kernel(no_runtime=True)
def _ball_equilibrium(pir, piz, por, poz, rci, rco, rb, m_w2, fto, fti, e_prime, method, table, out, start):
    """Solve one ball; writes the fields of BALL_FIELDS into ``out``.

    The cold start: the ball on the groove-centre line, the overlap split by the contact stiffnesses (kind 1),
    or, without overlap there but with a centrifugal force, against the outer groove (kind 2).
    ``start`` (WARM_START,) or empty: the warm start, the last solution's centre c_0, its kind (0: none), the
    inner groove centre p_0 it was solved for and the centre's sensitivity S = dc/dp = A^-1 A_i there
    (:func:`_ball_sensitivity`). With the same kind as now, Newton starts from the first-order prediction
    c_0 + S (p - p_0), and from a failed warm start over cold. The solution is the same from either start
    within Newton's tolerance (it converges on the residual); the warm start saves iterations and the cold
    start's Hertz constants when the ring pose moved little since the last call (the prediction's error is of
    the second order in the groove centre's move, about one Newton iteration fewer than from c_0 itself)."""
    lo0 = rco - rb
    li0 = rci - rb
    dr = pir - por
    dz = piz - poz
    dist = math.sqrt(dr * dr + dz * dz)
    er = dr / dist
    ez = dz / dist
    total = dist - lo0 - li0
    if total > 0.0:
        kind = 1.0
    elif m_w2 > 0.0:
        kind = 2.0
    else:  # unloaded, nothing presses it: middle of the gap on the line
        for k in range(NB):
            out[k] = 0.0
        out[B_CR] = por + (lo0 + 0.5 * total) * er
        out[B_CZ] = poz + (lo0 + 0.5 * total) * ez
        out[B_DO] = 0.5 * total
        out[B_DI] = 0.5 * total
        out[B_NOR] = er
        out[B_NOZ] = ez
        out[B_NIR] = -er
        out[B_NIZ] = -ez
        out[B_OK] = 1.0
        if start.size == WARM_START:
            start[2] = 0.0
        return
    warm = start.size == WARM_START and start[2] == kind
    exact = 0.0
    if warm and _still_free(pir, piz, li0, por, poz, rco, rb, m_w2, fto, fti, out, start):
        return
    if warm:
        ep_r = pir - start[3]
        ep_z = piz - start[4]
        exact = _ball_newton(start[0] + start[5] * ep_r + start[6] * ep_z,
                             start[1] + start[7] * ep_r + start[8] * ep_z, pir, piz, por, poz, rci, rco, rb, m_w2,
                             fto, fti, e_prime, method, table, -1.0, out)
    if not warm or out[B_OK] != 1.0:
        ko, ki = _contact_constants(por, rco, rb, rci, er, -er, e_prime, method, table)
        if kind == 1.0:
            wo = ki ** (2.0 / 3.0)
            wi = ko ** (2.0 / 3.0)
            d_o = total * wo / (wo + wi)
            cr = por + (lo0 + d_o) * er
            cz = poz + (lo0 + d_o) * ez
        else:
            d_o = (m_w2 * por / ko) ** (2.0 / 3.0)
            cr = por + lo0 + d_o
            cz = poz
        scale = 1e-9 * (ko + ki) * (1e-6 * rb) ** 1.5 + 1e-300
        exact = _ball_newton(cr, cz, pir, piz, por, poz, rci, rco, rb, m_w2, fto, fti, e_prime, method, table, scale,
                             out)
    if start.size == WARM_START:
        start[0] = out[B_CR]
        start[1] = out[B_CZ]
        start[2] = kind if out[B_OK] == 1.0 else 0.0
        start[3] = pir
        start[4] = piz
        start[5], start[6], start[7], start[8] = _ball_sensitivity(out, rci, rco, rb, m_w2, fto, fti)
        start[9] = exact
        start[10] = m_w2
        start[11] = fto
        start[12] = fti
        start[13] = por
        start[14] = poz
        start[15] = rco
        start[16] = rb


@kernel(no_runtime=True)
def _still_free(pir, piz, li0, por, poz, rco, rb, m_w2, fto, fti, out, start):
    """A ball's last solution (``out``, warm start ``start`` of :func:`_ball_equilibrium`) is its solution again
    when its inner contact was open and stays open at the new inner groove centre (pir, piz), no traction acts at
    it (F_ti = 0, then and now: its direction would move), and the rest of the residual of :func:`_ball_newton`
    is unchanged (the same m omega^2, F_to, outer groove, R_co and R_b, and Newton's residual test passed at that
    centre): then the forces on the ball, its centre and the outer contact are those of the last solution (the
    same residual, the same test), and only the open inner contact's normal and gap move. Writes those and the
    warm start's groove centre; returns whether it applied (a ball outside the load zone, held by its
    centrifugal force, costs no Hertz constant and no iteration)."""
    if not (start[9] == 1.0 and fti == 0.0 and start[12] == 0.0 and out[B_QI] == 0.0 and out[B_OK] == 1.0
            and out[B_CR] == start[0] and out[B_CZ] == start[1] and m_w2 == start[10] and fto == start[11]
            and por == start[13] and poz == start[14] and rco == start[15] and rb == start[16]):
        return False
    br = start[0] - pir
    bz = start[1] - piz
    li = math.sqrt(br * br + bz * bz)
    if li - li0 > 0.0:
        return False
    out[B_NIR] = br / li
    out[B_NIZ] = bz / li
    out[B_DI] = li - li0
    start[3] = pir
    start[4] = piz
    return True


@kernel(inline="always")
def _mul(a, b):
    """Product of two 2x2 matrices (row-major 4-tuples)."""
    return (a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3])


@kernel(inline="always")
def _contact_jacobians(nr, nz, q, k_t, length, f_t, c_n):
    """A = dF/dc and B = dF/dc' (row-major 4-tuples) of one contact's force on the ball, F = -Q n + F_t t
    (:mod:`.damping`: A = -k_t n n^T - (Q/L)(I - n n^T) + (F_t/L) R (I - n n^T), B = -C_n n n^T; the terms of
    :func:`_ball_newton`'s Jacobian)."""
    p11, p12, p22 = 1.0 - nr * nr, -nr * nz, 1.0 - nz * nz  # I - n n^T
    g = q / length
    t = f_t / length  # (F_t/L) R (I - n n^T), R = [[0, 1], [-1, 0]]
    a = (-k_t * nr * nr - g * p11 + t * p12, -k_t * nr * nz - g * p12 + t * p22,
         -k_t * nr * nz - g * p12 - t * p11, -k_t * nz * nz - g * p22 - t * p12)
    b = (-c_n * nr * nr, -c_n * nr * nz, -c_n * nr * nz, -c_n * nz * nz)
    return a, b


@kernel(inline="always")
def _condense(a_o, a_i, m_w2):
    """(A^-1, A^-1 A_i) of a ball (row-major 4-tuples): A = A_o + A_i + diag(m omega_m^2, 0) the Jacobian of the
    forces on the ball, A^-1 A_i = dc/dp its centre's move per move of the inner groove centre (equilibrium
    A dc - A_i dp = 0); zeros where A is singular."""
    a = (a_o[0] + a_i[0] + m_w2, a_o[1] + a_i[1], a_o[2] + a_i[2], a_o[3] + a_i[3])
    det = a[0] * a[3] - a[1] * a[2]
    if det == 0.0:
        return (0.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0)
    ainv = (a[3] / det, -a[1] / det, -a[2] / det, a[0] / det)
    return ainv, _mul(ainv, a_i)


@kernel(no_runtime=True)
def _ball_sensitivity(out, rci, rco, rb, m_w2, fto, fti):
    """dc/dp (row-major 4-tuple) of a solved ball (``out``: its BALL_FIELDS): :func:`_condense` with the contacts'
    Jacobians at the solution (:func:`_contact_jacobians`; an open contact only its traction's term, as in the
    residual of :func:`_ball_newton`)."""
    do = out[B_DO]
    di = out[B_DI]
    kto = 1.5 * out[B_KO] * math.sqrt(do) if do > 0.0 else 0.0
    kti = 1.5 * out[B_KI] * math.sqrt(di) if di > 0.0 else 0.0
    a_o = _contact_jacobians(out[B_NOR], out[B_NOZ], out[B_QO], kto, rco - rb + do, fto, 0.0)[0]
    a_i = _contact_jacobians(out[B_NIR], out[B_NIZ], out[B_QI], kti, rci - rb + di, fti, 0.0)[0]
    return _condense(a_o, a_i, m_w2)[1]


@kernel(no_runtime=True)
def _ball_newton(cr, cz, pir, piz, por, poz, rci, rco, rb, m_w2, fto, fti, e_prime, method, table, scale, out):
    """Newton's method for one ball's centre (cr, cz) from the given start (:func:`_ball_equilibrium`); ``scale``
    [N]: the residual's absolute floor (< 0: from the Hertz constants at the start). Returns 1.0 if the residual
    test passed at the centre written (0.0: the last step was below its floor, or no convergence)."""
    lo0 = rco - rb
    li0 = rci - rb
    ok = 0.0
    step_max = 0.02 * rb
    qo = qi = 0.0
    nor = noz = nir = niz = 0.0
    do = di = 0.0
    ko = ki = 0.0
    exact = 0.0
    for it in range(80):
        # outer contact
        ar = cr - por
        az = cz - poz
        lo = math.sqrt(ar * ar + az * az)
        nor = ar / lo
        noz = az / lo
        do = lo - lo0
        # inner contact
        br = cr - pir
        bz = cz - piz
        li = math.sqrt(br * br + bz * bz)
        nir = br / li
        niz = bz / li
        di = li - li0
        # Hertz constants at the current contact angles (stale ones would make the converged state
        # depend on the iteration history)
        if scale < 0.0:
            ko, ki = _contact_constants(por, rco, rb, rci, nor, nir, e_prime, method, table)
            scale = 1e-9 * (ko + ki) * (1e-6 * rb) ** 1.5 + 1e-300
        else:  # an open contact's constant enters no force
            ko, ki = _contact_constants(por, rco, rb, rci, nor, nir, e_prime, method, table, do > 0.0, di > 0.0)
        qo = ko * do * math.sqrt(do) if do > 0.0 else 0.0
        qi = ki * di * math.sqrt(di) if di > 0.0 else 0.0
        kqo = 1.5 * ko * math.sqrt(do) if do > 0.0 else 0.0
        kqi = 1.5 * ki * math.sqrt(di) if di > 0.0 else 0.0
        # residual: forces on the ball
        rr = -qo * nor - qi * nir + m_w2 * cr + fto * noz + fti * niz
        rz = -qo * noz - qi * niz - fto * nor - fti * nir
        if abs(rr) + abs(rz) <= 1e-13 * (qo + qi + m_w2 * cr + abs(fto) + abs(fti)) + scale:
            ok = 1.0
            exact = 1.0
            break
        # Jacobian d(residual)/dc
        go = qo / lo
        gi = qi / li
        j11 = -(kqo * nor * nor + go * (1.0 - nor * nor)) - (kqi * nir * nir + gi * (1.0 - nir * nir)) + m_w2
        j12 = -(kqo * nor * noz - go * nor * noz) - (kqi * nir * niz - gi * nir * niz)
        j22 = -(kqo * noz * noz + go * (1.0 - noz * noz)) - (kqi * niz * niz + gi * (1.0 - niz * niz))
        # tangential forces turn with the normals: d t/dc = R90 (I - n n^T)/|c - p|, R90 = [[0, 1], [-1, 0]]
        fo = fto / lo
        fi = fti / li
        j11 += fo * (-noz * nor) + fi * (-niz * nir)
        j12 += fo * (1.0 - noz * noz) + fi * (1.0 - niz * niz)
        j21 = -(kqo * nor * noz - go * nor * noz) - (kqi * nir * niz - gi * nir * niz) \
            - fo * (1.0 - nor * nor) - fi * (1.0 - nir * nir)
        j22 += fo * (nor * noz) + fi * (nir * niz)
        det = j11 * j22 - j12 * j21
        if det == 0.0:
            break
        sr = -(j22 * rr - j12 * rz) / det
        sz = -(-j21 * rr + j11 * rz) / det
        norm = math.sqrt(sr * sr + sz * sz)
        if norm > step_max:
            sr *= step_max / norm
            sz *= step_max / norm
        cr += sr
        cz += sz
        if norm < 1e-17:
            ok = 1.0
            break
    out[B_CR] = cr
    out[B_CZ] = cz
    out[B_QO] = qo
    out[B_QI] = qi
    out[B_DO] = do
    out[B_DI] = di
    out[B_NOR] = nor
    out[B_NOZ] = noz
    out[B_NIR] = nir
    out[B_NIZ] = niz
    out[B_KO] = ko if do > 0.0 else 0.0
    out[B_KI] = ki if di > 0.0 else 0.0
    out[B_OK] = ok
    return exact


@kernel(no_runtime=True)
def _ring_forces(u, psi, rho_i, z_i, rho_o, z_o, rci, rco, rb, m_w2, fto, fti, e_prime, method, table, start, balls,
                 gen, cos_psi, sin_psi):
    """All balls for the ring pose u (5,); per-ball results into ``balls`` (Z, NB),
    generalized force of the balls on the ring into ``gen`` (5,), cos and sin of the balls' azimuths psi into
    ``cos_psi``, ``sin_psi`` (Z,) (the damping's, :func:`.damping.ring_damping_force`, takes them from there).
    ``table``: Hertz constants (:func:`_hertz_constant`; shape (3, 0): direct); ``start`` (Z, WARM_START): the
    balls' warm starts (:func:`_ball_equilibrium`; shape (0, WARM_START): cold starts)."""
    for k in range(5):
        gen[k] = 0.0
    warm = start.shape[0] == psi.size
    cold = start.reshape(-1)[:0]  # an empty warm start (no allocation: the kernel runs without numba's runtime)
    for j in range(psi.size):
        c = math.cos(psi[j])
        s = math.sin(psi[j])
        cos_psi[j] = c
        sin_psi[j] = s
        pir = rho_i + u[0] * c + u[1] * s + z_i * (u[4] * c - u[3] * s)
        piz = z_i + u[2] + rho_i * (u[3] * s - u[4] * c)
        _ball_equilibrium(pir, piz, rho_o, z_o, rci, rco, rb, m_w2[j], fto[j], fti[j], e_prime, method, table,
                          balls[j], start[j] if warm else cold)
        q = balls[j, B_QI]
        nr = balls[j, B_NIR]
        nz = balls[j, B_NIZ]
        # force of the ball on the ring: +Q_i n_i - F_ti t_i, t_i = (n_z, -n_r)
        fr = q * nr - fti[j] * nz
        fz = q * nz + fti[j] * nr
        gen[0] += fr * c
        gen[1] += fr * s
        gen[2] += fz
        gen[3] += -z_i * s * fr + rho_i * s * fz
        gen[4] += z_i * c * fr - rho_i * c * fz


def ring_forces(u, psi, geom, m_w2, fto, fti, e_prime, method):
    """Python wrapper of the compiled ball loop: (generalized force (5,), balls (Z, NB)); direct Hertz
    constants, cold starts."""
    z = psi.size
    balls = np.zeros((z, NB))
    gen = np.zeros(5)
    _ring_forces(np.asarray(u, float), psi, geom.rho_i, geom.z_i, geom.rho_o, geom.z_o, geom.r_ci, geom.r_co,
                 geom.r_b, m_w2, fto, fti, e_prime, method, _DIRECT, _COLD, balls, gen, np.empty(z), np.empty(z))
    return gen, balls
