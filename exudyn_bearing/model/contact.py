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
from .layout import (FRIC_HISTORY, FRIC_REGULARIZED, P_ALPHA_E, P_CAGE, P_DT, P_EPRIME, P_ETA, P_FILM, P_FRIC,
                     P_HERTZ, P_K_BB, P_K_BZ, P_K_GUIDE, P_KT_IMPLICIT, P_KT_RATIO, P_L1, P_L3, P_LAW, P_LAW_D,
                     P_LAW_K, P_LAW_N, P_LUB, P_MB, P_MU_B, P_MU_DRY, P_MU_F, P_MZ, P_RB, P_RCI, P_RCO, P_RGUIDE,
                     P_RHO_I, P_RHO_O, P_RP, P_RZ, P_SIGMA, P_VREG, P_XI, P_ZG_I, P_ZG_O)

__all__ = ["forces"]


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
