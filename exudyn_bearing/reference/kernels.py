"""Compiled kernels of the DEM reference engine (numba, cache=True).

One force evaluation for the whole bearing per call, over flat float64
arrays; the physics relations come from :mod:`exudyn_bearing.physics`
(the same kernels the Exudyn element uses). No allocation in the hot loop.

State
-----
``xb, vb, wb`` (Z, 3): ball centre, velocity, angular velocity (world frame);
``xc, vc`` (Z, 3): cage balls (cage ball k sits between balls k and k+1);
``ring`` (6,): inner-ring position and velocity (it translates; its spin is
prescribed); ``hist`` (Z, 2, 3): Cundall-Strack tangential displacement of
the inner (0) and outer (1) contact of every ball.

Contact diagnostics (``diag``, (Z, 2, NDIAG)) are written when requested, in
the order of :data:`DIAG_FIELDS`.
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel

from ..physics.damping import (_damping_critical, _damping_fluid, _damping_hysteretic, damping_coefficient,
                               lubrication_regime)
from ..physics.ehl import _film_thickness
from ..physics.friction import (_implicit_tangential_stiffness, _regularized_coulomb, _sphere_tangential_mass,
                                friction_coefficient)
from ..physics.geometry import _groove_geometry, _raceway_radii_cos
from ..physics.hertz import _curvature_sum_radius, _kfe_fast, _semi_axes, _stiffness

# -- parameter vector layout ----------------------------------------------
(P_Z, P_RB, P_RCI, P_RCO, P_RHO_I, P_ZG_I, P_RHO_O, P_ZG_O, P_RZ, P_RP, P_RGUIDE,
 P_EPRIME, P_MB, P_IB, P_MZ, P_MR, P_ALPHA_E, P_ETA, P_XI, P_SIGMA, P_L1, P_L3, P_MU_B, P_MU_F,
 P_HERTZ, P_FILM, P_LUB, P_MU_DRY, P_FRIC, P_VREG, P_KT_RATIO, P_CAGE, P_FR, P_FA,
 P_W_MAX, P_T_UP, P_T_STEADY, P_T_DOWN, P_K_BZ, P_K_BB, P_K_GUIDE, P_DT, P_AXIAL_FREE,
 P_MAX_OVERLAP, P_KT_IMPLICIT, P_LAW, P_LAW_K, P_LAW_N, P_LAW_D, N_PARAMS) = range(50)

FRIC_HISTORY, FRIC_REGULARIZED, FRIC_NONE = 0, 1, 2
#: Ball / raceway contact laws: elliptic Hertz with the Lambda-switched
#: lubrication of PHYSICS.md (default), or the power law k delta^n + d
#: d(delta)/dt with constant mu of Exudyn's ObjectContactSphereTorus (for
#: the peer check against exudyn.machines.CreateBallBearing).
LAW_HERTZ, LAW_POWER = 0, 1

#: Fields of the per-contact diagnostics, in order.
DIAG_FIELDS = ("load", "overlap", "contact_angle", "a", "b", "p_max", "u_r", "h_min",
               "lambda", "regime", "mu", "slip_speed", "srr", "friction_force")
NDIAG = len(DIAG_FIELDS)
#: Global diagnostics per sample, in order.
GLOBAL_FIELDS = ("omega", "ring_fx", "ring_fy", "ring_fz", "ring_torque", "friction_power",
                 "max_overlap_ratio", "outer_fx", "outer_fy", "outer_fz", "outer_torque")
NGLOBAL = len(GLOBAL_FIELDS)


@kernel
def omega_profile(t, w_max, t_up, t_steady, t_down):
    """Inner-ring speed of the protocol: ramp up, hold, ramp down, rest [rad/s]."""
    if t < 0.0:
        return 0.0
    if t < t_up:
        return w_max * t / t_up
    t = t - t_up
    if t < t_steady:
        return w_max
    t = t - t_steady
    if t < t_down:
        return w_max * (1.0 - t / t_down)
    return 0.0


@kernel(inline="always")
def _cross(a0, a1, a2, b0, b1, b2):
    return a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0


@kernel
def forces(p, table, xb, vb, wb, xc, vc, rings, hist, hist_out, dt_hist, hz, fb, tb, fc, fr, glob, diag,
           cage_load, want):
    """All contact forces (one call for the whole bearing).

    ``hist`` is the Cundall-Strack state at the last committed time and
    ``dt_hist`` the time since then; the updated state goes to ``hist_out``
    (the same array when every evaluation is a committed step, as in the
    reference engine). ``rings`` (2, RING_N) holds the pose of the inner (0) and outer (1) ring:
    centre, velocity, rotation matrix (row-major; the bearing axis is the
    ring's local z) and angular velocity, all in the world frame. Writes fb,
    tb (balls), fc (cage balls), fr (2, 6: force and torque about its centre
    that the balls exert on each ring); with ``want`` also glob (NGLOBAL),
    diag (Z, 2, NDIAG) and cage_load (Z, 2). Returns the largest overlap / R_b.

    The contact laws are the scalar physics functions of exudyn_bearing.physics
    (scalar arguments, so numba compiles them into the loop); the loops avoid
    calls that pass arrays, which carry a per-call overhead comparable to a
    frictionless contact check.
    """
    z = xb.shape[0]
    fb[:, :] = 0.0
    tb[:, :] = 0.0
    fc[:, :] = 0.0
    fr[:, :] = 0.0
    power_sum = 0.0
    worst = 0.0
    # -- ball / raceway contacts: race 0 the inner groove on ring 0, race 1 the
    # outer groove on ring 1 (PHYSICS.md sec. 2-6)
    for j in range(z):
        for race in range(2):
            inner = race == 0
            ox, oy, oz = rings[race, 0], rings[race, 1], rings[race, 2]
            uvx, uvy, uvz = rings[race, 3], rings[race, 4], rings[race, 5]
            a00, a01, a02 = rings[race, 6], rings[race, 7], rings[race, 8]
            a10, a11, a12 = rings[race, 9], rings[race, 10], rings[race, 11]
            a20, a21, a22 = rings[race, 12], rings[race, 13], rings[race, 14]
            wrx, wry, wrz = rings[race, 15], rings[race, 16], rings[race, 17]
            if inner:
                rho, zg, rc = p[P_RHO_I], p[P_ZG_I], p[P_RCI]
            else:
                rho, zg, rc = p[P_RHO_O], p[P_ZG_O], p[P_RCO]
            rb = p[P_RB]
            # ball centre relative to the ring centre: world (d) and ring frame (c = A^T d)
            dxw = xb[j, 0] - ox
            dyw = xb[j, 1] - oy
            dzw = xb[j, 2] - oz
            rotated = not (a00 == 1.0 and a11 == 1.0 and a22 == 1.0)
            if rotated:
                cx = a00 * dxw + a10 * dyw + a20 * dzw
                cy = a01 * dxw + a11 * dyw + a21 * dzw
                cz = a02 * dxw + a12 * dyw + a22 * dzw
            else:  # unrotated ring (the reference engine): skip the transformation
                cx, cy, cz = dxw, dyw, dzw
            delta, nlx, nly, nlz, ca, sa, r_contact = _groove_geometry(cx, cy, cz, rho, zg, rc, rb, inner)
            if delta <= 0.0:
                hist_out[j, race, 0] = 0.0
                hist_out[j, race, 1] = 0.0
                hist_out[j, race, 2] = 0.0
                if want:
                    for k in range(diag.shape[2]):
                        diag[j, race, k] = 0.0
                    diag[j, race, 1] = delta
                    diag[j, race, 2] = math.atan2(sa, ca)
                    diag[j, race, 7] = np.nan
                    diag[j, race, 8] = np.nan
                    diag[j, race, 9] = -1.0
                    diag[j, race, 10] = np.nan
                continue
            ratio = delta / rb
            if ratio > worst:
                worst = ratio
            # contact normal in the world frame, n = A n_local
            if rotated:
                nx = a00 * nlx + a01 * nly + a02 * nlz
                ny = a10 * nlx + a11 * nly + a12 * nlz
                nz = a20 * nlx + a21 * nly + a22 * nlz
            else:
                nx, ny, nz = nlx, nly, nlz
            # Hertz (PHYSICS.md sec. 3) at the current contact angle; k, F, E are
            # re-evaluated when R_y/R_x moved by more than 1e-6 (relative) since the
            # last evaluation for this contact, K from them and the current radii
            rx, ry = _raceway_radii_cos(rb, rc, r_contact, ca, inner)
            e_prime = p[P_EPRIME]
            aspect = ry / rx
            if abs(aspect - hz[j, race, 0]) > 1e-6 * aspect:
                kappa, ell_f, ell_e = _kfe_fast(rx, ry, int(p[P_HERTZ]), table)
                hz[j, race, 0] = aspect
                hz[j, race, 1] = kappa
                hz[j, race, 2] = ell_f
                hz[j, race, 3] = ell_e
            else:
                kappa = hz[j, race, 1]
                ell_f = hz[j, race, 2]
                ell_e = hz[j, race, 3]
            rr = _curvature_sum_radius(rx, ry)
            power_law = p[P_LAW] > 0.5
            if power_law:
                q_el = p[P_LAW_K] * delta ** p[P_LAW_N]
                k_n = p[P_LAW_N] * q_el / delta
                c_hyst = 0.0  # the power law has its own linear damping
            else:
                kst = _stiffness(kappa, ell_f, ell_e, rr, e_prime)
                sq = math.sqrt(delta)
                q_el = kst * delta * sq
                k_n = 1.5 * kst * sq
                c_hyst = _damping_hysteretic(kst, delta, p[P_ALPHA_E])
            need_axes = want or p[P_LUB] > 0.5
            if need_axes:
                major, minor = _semi_axes(kappa, ell_e, rr, e_prime, q_el)
            else:
                major = minor = 0.0
            # contact point: middle of the overlap, lever from the ball centre
            lev = rb - 0.5 * delta
            # (n points from the groove centre to the ball centre; the groove surface
            # p + R_c n lies beyond the ball centre along n, for both races)
            lx, ly, lz = lev * nx, lev * ny, lev * nz
            # surface velocities at the contact point
            bx, by, bz = _cross(wb[j, 0], wb[j, 1], wb[j, 2], lx, ly, lz)
            vbs_x = vb[j, 0] + bx
            vbs_y = vb[j, 1] + by
            vbs_z = vb[j, 2] + bz
            # contact point relative to the ring centre, and the ring's surface velocity there
            px = dxw + lx
            py = dyw + ly
            pz = dzw + lz
            rwx, rwy, rwz = _cross(wrx, wry, wrz, px, py, pz)
            vrs_x = uvx + rwx
            vrs_y = uvy + rwy
            vrs_z = uvz + rwz
            # normal approach rate d(delta)/dt = n . (v_ball - v_ring - w_ring x d)
            ex, ey, ez = _cross(wrx, wry, wrz, dxw, dyw, dzw)
            vrx = vb[j, 0] - uvx
            vry = vb[j, 1] - uvy
            vrz = vb[j, 2] - uvz
            ddot = (vrx - ex) * nx + (vry - ey) * ny + (vrz - ez) * nz
            # slip (tangential relative velocity) and rolling speed
            sx = vbs_x - vrs_x
            sy = vbs_y - vrs_y
            sz = vbs_z - vrs_z
            sn = sx * nx + sy * ny + sz * nz
            sx -= sn * nx
            sy -= sn * ny
            sz -= sn * nz
            slip = math.sqrt(sx * sx + sy * sy + sz * sz)
            # rolling speed: mean surface velocity relative to the contact point,
            # which is carried by the ball's orbital motion about the ring axis e
            r2 = cx * cx + cy * cy
            tx_, ty_, tz_ = _cross(dxw, dyw, dzw, vrx, vry, vrz)
            w_orb = (a02 * tx_ + a12 * ty_ + a22 * tz_) / r2 if r2 > 0.0 else 0.0
            ox_, oy_, oz_ = _cross(a02, a12, a22, lx, ly, lz)
            mx = 0.5 * (vbs_x + vrs_x) - (vb[j, 0] + w_orb * ox_)
            my = 0.5 * (vbs_y + vrs_y) - (vb[j, 1] + w_orb * oy_)
            mz = 0.5 * (vbs_z + vrs_z) - (vb[j, 2] + w_orb * oz_)
            mn = mx * nx + my * ny + mz * nz
            mx -= mn * nx
            my -= mn * ny
            mz -= mn * nz
            u_r = math.sqrt(mx * mx + my * my + mz * mz)
            # lubrication (PHYSICS.md sec. 4-5)
            if power_law:
                h = 0.0
                lam = 0.0
                regime = 0
                c_n = p[P_LAW_D]
                mu = p[P_MU_DRY]
            elif p[P_LUB] > 0.5:
                h = _film_thickness(int(p[P_FILM]), u_r, q_el, rx, kappa, e_prime, p[P_ETA], p[P_XI])
                lam = h / p[P_SIGMA]
                regime = lubrication_regime(lam, p[P_L1], p[P_L3])
                if regime == 0:
                    c_n = c_hyst
                else:
                    c_fl = _damping_fluid(p[P_ETA], major, rb, h)
                    c_n = damping_coefficient(lam, c_hyst, c_fl, p[P_L1], p[P_L3])
                mu = friction_coefficient(lam, p[P_MU_B], p[P_MU_F], p[P_L1], p[P_L3])
            else:
                h = 0.0
                lam = 0.0
                regime = 0
                c_n = c_hyst
                mu = p[P_MU_DRY]
            f_n = q_el + c_n * ddot
            if f_n < 0.0:
                f_n = 0.0
            # tangential force (PHYSICS.md sec. 6)
            ftx = fty = ftz = 0.0
            fric = int(p[P_FRIC])
            if fric == FRIC_HISTORY:
                hx, hy, hzt = hist[j, race, 0], hist[j, race, 1], hist[j, race, 2]
                hmag = math.sqrt(hx * hx + hy * hy + hzt * hzt)
                if hmag > 0.0:
                    hn = hx * nx + hy * ny + hzt * nz
                    hx -= hn * nx
                    hy -= hn * ny
                    hzt -= hn * nz
                    hm2 = math.sqrt(hx * hx + hy * hy + hzt * hzt)
                    if hm2 > 0.0:
                        s = hmag / hm2
                        hx *= s
                        hy *= s
                        hzt *= s
                hx += sx * dt_hist
                hy += sy * dt_hist
                hzt += sz * dt_hist
                dt = p[P_DT]
                k_t = p[P_KT_RATIO] * k_n
                if p[P_KT_IMPLICIT] > 0.5:
                    k_t = _implicit_tangential_stiffness(k_t, dt, _sphere_tangential_mass(p[P_MB]))
                ftx = -k_t * hx
                fty = -k_t * hy
                ftz = -k_t * hzt
                fmag = math.sqrt(ftx * ftx + fty * fty + ftz * ftz)
                cap = mu * f_n
                if fmag > cap:
                    s = cap / fmag
                    ftx *= s
                    fty *= s
                    ftz *= s
                    hx = -ftx / k_t
                    hy = -fty / k_t
                    hzt = -ftz / k_t
                hist_out[j, race, 0] = hx
                hist_out[j, race, 1] = hy
                hist_out[j, race, 2] = hzt
            elif fric == FRIC_REGULARIZED and slip > 0.0:
                fmag = _regularized_coulomb(slip, f_n, mu, p[P_VREG])
                ftx = -fmag * sx / slip
                fty = -fmag * sy / slip
                ftz = -fmag * sz / slip
            # forces on the ball: normal pushes it back towards the groove centre
            fb[j, 0] += -f_n * nx + ftx
            fb[j, 1] += -f_n * ny + fty
            fb[j, 2] += -f_n * nz + ftz
            mx_, my_, mz_ = _cross(lx, ly, lz, ftx, fty, ftz)
            tb[j, 0] += mx_
            tb[j, 1] += my_
            tb[j, 2] += mz_
            power_sum -= ftx * sx + fty * sy + ftz * sz
            # reaction on the ring, at the contact point
            frx = f_n * nx - ftx
            fry = f_n * ny - fty
            frz = f_n * nz - ftz
            fr[race, 0] += frx
            fr[race, 1] += fry
            fr[race, 2] += frz
            mx_, my_, mz_ = _cross(px, py, pz, frx, fry, frz)
            fr[race, 3] += mx_
            fr[race, 4] += my_
            fr[race, 5] += mz_
            if want:
                ft = math.sqrt(ftx * ftx + fty * fty + ftz * ftz)
                if ry >= rx:
                    a_ax, b_ax = major, minor
                else:
                    a_ax, b_ax = minor, major
                diag[j, race, 0] = f_n
                diag[j, race, 1] = delta
                diag[j, race, 2] = math.atan2(sa, ca)
                diag[j, race, 3] = a_ax
                diag[j, race, 4] = b_ax
                diag[j, race, 5] = 1.5 * q_el / (math.pi * a_ax * b_ax) if a_ax * b_ax > 0.0 else 0.0
                diag[j, race, 6] = u_r
                diag[j, race, 7] = h
                diag[j, race, 8] = lam if p[P_LUB] > 0.5 else np.nan
                diag[j, race, 9] = regime
                diag[j, race, 10] = mu
                diag[j, race, 11] = slip
                diag[j, race, 12] = slip / u_r if u_r > 0.0 else 0.0
                diag[j, race, 13] = ft
    # -- ball / cage-ball (or, without cage, ball / ball) contacts: frictionless
    # Hertz spheres with critical damping (PHYSICS.md sec. 4)
    cage = p[P_CAGE] > 0.5
    if cage:
        px_, pv_, pf_ = xc, vc, fc
        r_sum = p[P_RB] + p[P_RZ]
        k_pair = p[P_K_BZ]
        m_pair = p[P_MB] * p[P_MZ] / (p[P_MB] + p[P_MZ])
        n_pair = 2
    else:
        px_, pv_, pf_ = xb, vb, fb
        r_sum = 2.0 * p[P_RB]
        k_pair = p[P_K_BB]
        m_pair = 0.5 * p[P_MB]
        n_pair = 1
    r_sum2 = r_sum * r_sum
    for k in range(z):
        k2 = k + 1 if k + 1 < z else 0
        for m in range(n_pair):
            ia = k if m == 0 else k2          # ball
            ib = k if cage else k2            # cage ball k, or the next ball
            dx = xb[ia, 0] - px_[ib, 0]
            dy = xb[ia, 1] - px_[ib, 1]
            dz = xb[ia, 2] - px_[ib, 2]
            d2 = dx * dx + dy * dy + dz * dz
            f = 0.0
            if d2 < r_sum2 and d2 > 0.0:
                dist = math.sqrt(d2)
                delta = r_sum - dist
                inv = 1.0 / dist
                nx, ny, nz = dx * inv, dy * inv, dz * inv
                sq = math.sqrt(delta)
                c = _damping_critical(m_pair, 1.5 * k_pair * sq)
                ddot = -((vb[ia, 0] - pv_[ib, 0]) * nx + (vb[ia, 1] - pv_[ib, 1]) * ny
                         + (vb[ia, 2] - pv_[ib, 2]) * nz)
                f = k_pair * delta * sq + c * ddot
                if f < 0.0:
                    f = 0.0
                fb[ia, 0] += f * nx
                fb[ia, 1] += f * ny
                fb[ia, 2] += f * nz
                pf_[ib, 0] -= f * nx
                pf_[ib, 1] -= f * ny
                pf_[ib, 2] -= f * nz
            if want:
                cage_load[k, m] = f
        if want and not cage:
            cage_load[k, 1] = 0.0
        if cage:
            # cage ball k in its guide torus, fixed to the outer ring (ring 1): tube-
            # centre circle r_p in the ring's radial plane, tube radius R_z + clearance;
            # frictionless Hertz, R_eq = R_z, critical damping
            rz = p[P_RZ]
            free = p[P_RGUIDE] - rz
            dxw = xc[k, 0] - rings[1, 0]
            dyw = xc[k, 1] - rings[1, 1]
            dzw = xc[k, 2] - rings[1, 2]
            a00, a01, a02 = rings[1, 6], rings[1, 7], rings[1, 8]
            a10, a11, a12 = rings[1, 9], rings[1, 10], rings[1, 11]
            a20, a21, a22 = rings[1, 12], rings[1, 13], rings[1, 14]
            if a00 == 1.0 and a11 == 1.0 and a22 == 1.0:
                cx, cy, cz = dxw, dyw, dzw
            else:
                cx = a00 * dxw + a10 * dyw + a20 * dzw
                cy = a01 * dxw + a11 * dyw + a21 * dzw
                cz = a02 * dxw + a12 * dyw + a22 * dzw
            dr = math.sqrt(cx * cx + cy * cy) - p[P_RP]
            if dr * dr + cz * cz > free * free:
                delta, nlx, nly, nlz, _ca, _sa, _rc = _groove_geometry(cx, cy, cz, p[P_RP], 0.0, p[P_RGUIDE],
                                                                       rz, False)
                if delta > 0.0:
                    nx = a00 * nlx + a01 * nly + a02 * nlz
                    ny = a10 * nlx + a11 * nly + a12 * nlz
                    nz = a20 * nlx + a21 * nly + a22 * nlz
                    ex, ey, ez = _cross(rings[1, 15], rings[1, 16], rings[1, 17], dxw, dyw, dzw)
                    vn = ((vc[k, 0] - rings[1, 3] - ex) * nx + (vc[k, 1] - rings[1, 4] - ey) * ny
                          + (vc[k, 2] - rings[1, 5] - ez) * nz)
                    sq = math.sqrt(delta)
                    kst = p[P_K_GUIDE]
                    c = _damping_critical(p[P_MZ], 1.5 * kst * sq)
                    f = kst * delta * sq + c * vn
                    if f > 0.0:
                        fc[k, 0] -= f * nx
                        fc[k, 1] -= f * ny
                        fc[k, 2] -= f * nz
                        fr[1, 0] += f * nx
                        fr[1, 1] += f * ny
                        fr[1, 2] += f * nz
                        mx_, my_, mz_ = _cross(dxw, dyw, dzw, f * nx, f * ny, f * nz)
                        fr[1, 3] += mx_
                        fr[1, 4] += my_
                        fr[1, 5] += mz_
    if want:
        # inner ring: spin about its axis, force of the balls, torque about its axis
        ex, ey, ez = rings[0, 8], rings[0, 11], rings[0, 14]
        glob[0] = ex * rings[0, 15] + ey * rings[0, 16] + ez * rings[0, 17]
        glob[1] = fr[0, 0]
        glob[2] = fr[0, 1]
        glob[3] = fr[0, 2]
        glob[4] = ex * fr[0, 3] + ey * fr[0, 4] + ez * fr[0, 5]
        glob[5] = power_sum
        glob[6] = worst
        # outer ring: force of the balls and cage balls, torque about its axis
        ex, ey, ez = rings[1, 8], rings[1, 11], rings[1, 14]
        glob[7] = fr[1, 0]
        glob[8] = fr[1, 1]
        glob[9] = fr[1, 2]
        glob[10] = ex * fr[1, 3] + ey * fr[1, 4] + ez * fr[1, 5]
    return worst


#: Length of a ring pose row: centre (3), velocity (3), rotation matrix (9), angular velocity (3).
RING_N = 18


@kernel
def ring_poses():
    """Ring pose array (2, RING_N): both rings at the origin, at rest, unrotated."""
    rings = np.zeros((2, RING_N))
    for r in range(2):
        rings[r, 6] = 1.0
        rings[r, 10] = 1.0
        rings[r, 14] = 1.0
    return rings


@kernel
def _set_inner_ring(t, p, ring, rings):
    """Reference engine: the inner ring translates (state ``ring``: position,
    velocity) and spins at the protocol speed; the outer ring stays fixed."""
    for d in range(6):
        rings[0, d] = ring[d]
    rings[0, 17] = omega_profile(t, p[P_W_MAX], p[P_T_UP], p[P_T_STEADY], p[P_T_DOWN])


@kernel
def _inner_ring_force(p, fr, fring):
    """Force that accelerates the inner ring: applied load plus the ball reactions."""
    fring[0] = p[P_FR] + fr[0, 0]
    fring[1] = fr[0, 1]
    fring[2] = (p[P_FA] + fr[0, 2]) if p[P_AXIAL_FREE] > 0.5 else 0.0


@kernel
def _evaluate(t, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring,
              glob, diag, cage_load, want):
    """Reference-engine force evaluation at time t (see :func:`_set_inner_ring`)."""
    _set_inner_ring(t, p, ring, rings)
    worst = forces(p, table, xb, vb, wb, xc, vc, rings, hist, hist, p[P_DT], hz, fb, tb, fc, fr, glob, diag,
                   cage_load, want)
    _inner_ring_force(p, fr, fring)
    return worst


@kernel
def _store(k, t, glob, diag, cage_load, xb, vb, wb, xc, vc, ring,
           s_t, s_glob, s_diag, s_cage, s_xb, s_vb, s_wb, s_xc, s_vc, s_ring):
    """Copy the state and diagnostics into row k of the sample buffers."""
    s_t[k] = t
    s_glob[k] = glob
    s_diag[k] = diag
    s_cage[k] = cage_load
    s_xb[k] = xb
    s_vb[k] = vb
    s_wb[k] = wb
    s_xc[k] = xc
    s_vc[k] = vc
    s_ring[k] = ring


@kernel
def kick_drift(h, dt, xb, vb, wb, xc, vc, fb, tb, fc, inv_mb, inv_ib, inv_mz):
    """Velocity-Verlet half kick of balls and cage balls by h, then a drift by dt."""
    for j in range(xb.shape[0]):
        for d in range(3):
            vb[j, d] += h * fb[j, d] * inv_mb
            wb[j, d] += h * tb[j, d] * inv_ib
            xb[j, d] += dt * vb[j, d]
            vc[j, d] += h * fc[j, d] * inv_mz
            xc[j, d] += dt * vc[j, d]


@kernel
def run_verlet(n_steps, t0, p, table, xb, vb, wb, xc, vc, ring, hist, hz, fb, tb, fc, fring,
               sample_every, step0, s_t, s_glob, s_diag, s_cage, s_xb, s_vb, s_wb, s_xc, s_vc, s_ring):
    """Velocity-Verlet (the DEM papers' scheme) for ``n_steps`` steps from t0.

    Forces must hold the values at t0 on entry; damping and friction see the
    half-step velocity. Every ``sample_every``-th step (counted from
    ``step0``) the state and diagnostics go to the next row of the s_*
    buffers. Returns (steps done, samples written, status): status 0 ok,
    1 non-finite state, 2 runaway overlap (> P_MAX_OVERLAP R_b).
    """
    dt = p[P_DT]
    h = 0.5 * dt
    z = xb.shape[0]
    inv_mb = 1.0 / p[P_MB]
    inv_ib = 1.0 / p[P_IB]
    inv_mz = 1.0 / p[P_MZ] if p[P_CAGE] > 0.5 else 0.0
    inv_mr = 1.0 / p[P_MR]
    glob = np.zeros(s_glob.shape[1])
    diag = np.zeros((z, 2, s_diag.shape[3]))
    cage_load = np.zeros((z, 2))
    rings = ring_poses()
    fr = np.zeros((2, 6))
    n_samp = 0
    t = t0
    for step in range(n_steps):
        kick_drift(h, dt, xb, vb, wb, xc, vc, fb, tb, fc, inv_mb, inv_ib, inv_mz)
        for d in range(3):
            ring[3 + d] += h * fring[d] * inv_mr
            ring[d] += dt * ring[3 + d]
        t = t0 + (step + 1) * dt
        want = (step0 + step + 1) % sample_every == 0 and n_samp < s_t.shape[0]
        # the three calls of _evaluate, inlined in this hottest loop (the
        # extra array-passing call measured a few per cent slower)
        _set_inner_ring(t, p, ring, rings)
        worst = forces(p, table, xb, vb, wb, xc, vc, rings, hist, hist, dt, hz, fb, tb, fc, fr, glob, diag,
                       cage_load, want)
        _inner_ring_force(p, fr, fring)
        for j in range(z):
            for d in range(3):
                vb[j, d] += h * fb[j, d] * inv_mb
                wb[j, d] += h * tb[j, d] * inv_ib
                vc[j, d] += h * fc[j, d] * inv_mz
        for d in range(3):
            ring[3 + d] += h * fring[d] * inv_mr
        if want:
            _store(n_samp, t, glob, diag, cage_load, xb, vb, wb, xc, vc, ring,
                   s_t, s_glob, s_diag, s_cage, s_xb, s_vb, s_wb, s_xc, s_vc, s_ring)
            n_samp += 1
            if not (np.all(np.isfinite(xb)) and np.all(np.isfinite(vb)) and np.all(np.isfinite(ring))):
                return step + 1, n_samp, 1
        if worst > p[P_MAX_OVERLAP] or not math.isfinite(worst):
            return step + 1, n_samp, 2
    if not (np.all(np.isfinite(xb)) and np.all(np.isfinite(vb)) and np.all(np.isfinite(wb))):
        return n_steps, n_samp, 1
    return n_steps, n_samp, 0


@kernel
def _rk_stage(t, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag, cage_load,
              kx, kv, kw, kxc, kvc, kr, stage):
    """Derivatives of the state at (t, state) into stage ``stage`` of the k
    arrays; returns the largest overlap ratio."""
    worst = _evaluate(t, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag,
                      cage_load, False)
    inv_mz = 1.0 / p[P_MZ] if p[P_CAGE] > 0.5 else 0.0
    for j in range(xb.shape[0]):
        for d in range(3):
            kx[stage, j, d] = vb[j, d]
            kv[stage, j, d] = fb[j, d] / p[P_MB]
            kw[stage, j, d] = tb[j, d] / p[P_IB]
            kxc[stage, j, d] = vc[j, d]
            kvc[stage, j, d] = fc[j, d] * inv_mz
    for d in range(3):
        kr[stage, d] = ring[3 + d]
        kr[stage, 3 + d] = fring[d] / p[P_MR]
    return worst


@kernel
def _rk_set(y0x, y0v, y0w, y0xc, y0vc, y0r, kx, kv, kw, kxc, kvc, kr, stage, f,
            xb, vb, wb, xc, vc, ring):
    """state = y0 + f k[stage]."""
    for j in range(xb.shape[0]):
        for d in range(3):
            xb[j, d] = y0x[j, d] + f * kx[stage, j, d]
            vb[j, d] = y0v[j, d] + f * kv[stage, j, d]
            wb[j, d] = y0w[j, d] + f * kw[stage, j, d]
            xc[j, d] = y0xc[j, d] + f * kxc[stage, j, d]
            vc[j, d] = y0vc[j, d] + f * kvc[stage, j, d]
    for d in range(6):
        ring[d] = y0r[d] + f * kr[stage, d]


@kernel
def run_rk4(n_steps, t0, p, table, xb, vb, wb, xc, vc, ring, hist, hz, fb, tb, fc, fring,
            sample_every, step0, s_t, s_glob, s_diag, s_cage, s_xb, s_vb, s_wb, s_xc, s_vc, s_ring):
    """Classical fourth-order Runge-Kutta, for history-free scenes (same
    interface and status codes as :func:`run_verlet`)."""
    dt = p[P_DT]
    z = xb.shape[0]
    glob = np.zeros(s_glob.shape[1])
    diag = np.zeros((z, 2, s_diag.shape[3]))
    cage_load = np.zeros((z, 2))
    rings = ring_poses()
    fr = np.zeros((2, 6))
    kx = np.zeros((4, z, 3))
    kv = np.zeros((4, z, 3))
    kw = np.zeros((4, z, 3))
    kxc = np.zeros((4, z, 3))
    kvc = np.zeros((4, z, 3))
    kr = np.zeros((4, 6))
    y0x = xb.copy()
    y0v = vb.copy()
    y0w = wb.copy()
    y0xc = xc.copy()
    y0vc = vc.copy()
    y0r = ring.copy()
    n_samp = 0
    for step in range(n_steps):
        t = t0 + step * dt
        y0x[:, :] = xb
        y0v[:, :] = vb
        y0w[:, :] = wb
        y0xc[:, :] = xc
        y0vc[:, :] = vc
        y0r[:] = ring
        worst = _rk_stage(t, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag,
                          cage_load, kx, kv, kw, kxc, kvc, kr, 0)
        if worst > p[P_MAX_OVERLAP] or not math.isfinite(worst):
            return step, n_samp, 2
        _rk_set(y0x, y0v, y0w, y0xc, y0vc, y0r, kx, kv, kw, kxc, kvc, kr, 0, 0.5 * dt, xb, vb, wb, xc, vc, ring)
        _rk_stage(t + 0.5 * dt, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag,
                  cage_load, kx, kv, kw, kxc, kvc, kr, 1)
        _rk_set(y0x, y0v, y0w, y0xc, y0vc, y0r, kx, kv, kw, kxc, kvc, kr, 1, 0.5 * dt, xb, vb, wb, xc, vc, ring)
        _rk_stage(t + 0.5 * dt, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag,
                  cage_load, kx, kv, kw, kxc, kvc, kr, 2)
        _rk_set(y0x, y0v, y0w, y0xc, y0vc, y0r, kx, kv, kw, kxc, kvc, kr, 2, dt, xb, vb, wb, xc, vc, ring)
        _rk_stage(t + dt, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag,
                  cage_load, kx, kv, kw, kxc, kvc, kr, 3)
        c = dt / 6.0
        for j in range(z):
            for d in range(3):
                xb[j, d] = y0x[j, d] + c * (kx[0, j, d] + 2 * kx[1, j, d] + 2 * kx[2, j, d] + kx[3, j, d])
                vb[j, d] = y0v[j, d] + c * (kv[0, j, d] + 2 * kv[1, j, d] + 2 * kv[2, j, d] + kv[3, j, d])
                wb[j, d] = y0w[j, d] + c * (kw[0, j, d] + 2 * kw[1, j, d] + 2 * kw[2, j, d] + kw[3, j, d])
                xc[j, d] = y0xc[j, d] + c * (kxc[0, j, d] + 2 * kxc[1, j, d] + 2 * kxc[2, j, d] + kxc[3, j, d])
                vc[j, d] = y0vc[j, d] + c * (kvc[0, j, d] + 2 * kvc[1, j, d] + 2 * kvc[2, j, d] + kvc[3, j, d])
        for d in range(6):
            ring[d] = y0r[d] + c * (kr[0, d] + 2 * kr[1, d] + 2 * kr[2, d] + kr[3, d])
        want = (step0 + step + 1) % sample_every == 0 and n_samp < s_t.shape[0]
        if want:
            _evaluate(t + dt, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag,
                   cage_load, True)
            _store(n_samp, t + dt, glob, diag, cage_load, xb, vb, wb, xc, vc, ring,
                   s_t, s_glob, s_diag, s_cage, s_xb, s_vb, s_wb, s_xc, s_vc, s_ring)
            n_samp += 1
        if not (np.all(np.isfinite(xb)) and np.all(np.isfinite(vb)) and np.all(np.isfinite(ring))):
            return step + 1, n_samp, 1
    return n_steps, n_samp, 0
