"""The contact kernel of the compiled bearing model (numba, cache=True):
every contact force of the bearing in one call, shared by the reference
engine and the Exudyn element.

:func:`forces` loops over the contacts and calls one function per contact
kind, each inlined by numba (``inline="always"``), so the split costs no
calls in the hot loop (it allocates nothing and is compiled without numba's
memory runtime, so that the inlined array arguments carry no reference
counting: ``exudyn_bearing._jit.kernel``). Functions that take arrays and
run for every contact are inlined; the ones that take scalars
(:func:`_normal_law`, :func:`_lubrication`, :func:`_cross`; LLVM inlines
the small ones) or run only in some scenes or on sampled steps (defects,
the ellipse level, the diagnostics) are called: numba's inlining of them
made the kernel's compilation take about 19 s of CPU time on every cold
start, about 9 s without it, at an unchanged step time and bitwise
unchanged results (``validation/performance/profile_reference.py --compile``). The
defect and ellipse-traction code is compiled only into the
specialisations of :func:`forces` that ask for it (``defect_path``,
``ellipse_path``; :func:`scene_paths`). Constants of the scene that
every contact would recompute (ln(xi E') of the film) are computed once
per call:

* :func:`_race_contact`: ball / raceway (elliptic Hertz or the peer power
  law, Lambda-switched damping and friction, Cundall-Strack or regularised
  tangential force), built from :func:`_ring_frame`, :func:`_hertz_constants`,
  :func:`_normal_law`, :func:`_surface_kinematics`, :func:`_lubrication` and
  :func:`_tangential_force`;
* :func:`_pair_contact`: ball / cage ball (or ball / ball without cage),
  frictionless Hertz spheres with critical damping;
* :func:`_guide_contact`: cage ball / its guide torus on the outer ring;
* :func:`_defect_drop`: the drop of a ball / raceway contact into the
  localized defects of the scene (spalls on the races or on the ball,
  :mod:`exudyn_bearing.physics.defects`), subtracted from the overlap;
  :func:`_turn_ball_frame` turns the body frame of a ball that carries a
  defect. A scene without defects (``P_NDEF`` 0) takes one branch per
  contact past them.

The physics relations are the scalar kernels of :mod:`exudyn_bearing.physics`.
Inputs (all float64, world frame):

* ``p`` (N_PARAMS,): parameter vector, layout :mod:`.layout` (``P_*``);
* ``table``: the tabulated exact Hertz solution (:func:`~exudyn_bearing.physics.hertz.exact_table`);
* ``xb, vb, wb`` (Z, 3): ball centres, velocities, angular velocities;
  ``xc, vc`` (Z, 3): cage balls (cage ball k sits between balls k and k+1);
* ``rings`` (2, RING_N): pose of the inner (0) and outer (1) ring (:mod:`.layout`, ``R_*``);
* ``hist`` (Z, HIST_N, 3): contact history at the last committed time
  (layout ``H_*``): the Cundall-Strack tangential displacement of the inner
  (0) and outer (1) contact of every ball and, for balls with a defect, the
  ball's body frame; ``dt_hist`` the time since then, ``hist_out`` where the
  updated state goes;
* ``hz`` (Z, 2, :data:`HZ_N`): per-contact cache (columns ``HZ_*`` of
  :mod:`.layout`): R_y/R_x, k, F, E and the ellipticity factor of the HD
  film (``ehl.film_hd_ellipticity_factor``), re-evaluated when R_y/R_x
  moves; the anchors from which the HD film takes its two logarithms and
  its exponential (:func:`_film_hd_anchored`: ln x = ln x_0 + ln(1 + r),
  exp(e) = exp(e_0) exp(d) by short series near the anchor, the library
  functions and a new anchor beyond; equal to the direct relation to
  round-off); and the scratch of the contact geometry, which
  :func:`forces` computes for all contacts first (:func:`_race_geometry`,
  in a short loop whose square roots and divisions the processor
  overlaps). Any content is valid (zeros: nothing cached yet); only the
  speed depends on it. A narrower array is refused (the kernel returns NaN,
  which every caller stops on).

Outputs: ``fb, tb`` (Z, 3) force and moment on the balls, ``fc`` (Z, 3) on
the cage balls, ``fr`` (2, 6) force and moment about its centre that balls
and cage balls exert on each ring; with ``want`` also ``glob`` (NGLOBAL),
``diag`` (Z, 2, NDIAG) and ``cage_load`` (Z, 2) (layouts in :mod:`.layout`).
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel
from .motion import rotate_frame
from ..physics.damping import (_damping_critical, _damping_fluid, _damping_hysteretic, _implicit_damping,
                               damping_coefficient, lubrication_regime)
from ..data.traction import N_TRACTION_PARAMS
from ..physics.contact_slip import _contact_traction
from ..physics.defects import _spall_drop_k
from ..physics.ehl import (HAMROCK_DOWSON, HD_ELLIPTICITY_DECAY, _film_central_hd, _film_hd_ellipticity_factor,
                           _film_thickness_ln_g_k, film_groups, film_hd_exponent, film_hd_from_exponent)
from ..physics.traction import EHL as TRACTION_EHL
from ..physics.friction import (_implicit_tangential_stiffness, _regularized_coulomb, _sphere_tangential_mass,
                                friction_coefficient)
from ..physics.geometry import _groove_geometry, _raceway_radii_cos
from ..physics.hertz import EXACT as HERTZ_EXACT
from ..physics.hertz import (_axes_ratio, _curvature_sum_radius, _kfe_fast, _kfe_table_ln, _semi_axes,
                             _semi_axes_overlap, _stiffness)
from ..physics.losses import _ehl_rolling_force, _hysteresis_rolling_force, ball_drag_force
from ..physics.pocket_film import _hydrodynamic_film_load, _sphere_wall_shear, _squeeze_film_damping
from ..physics.short_bearing import _short_bearing_xy
from .layout import (POCKET_ESCAPE, G_CAGE_LOAD_POWER, G_LAND_ECC, G_LAND_FX, G_LAND_FY, G_LAND_POWER, G_POCKET_POWER, P_GUIDANCE, P_IC, P_K_LAND,
                     P_K_POCKET, P_LAND_C, P_LAND_EPS, P_LAND_ETA, P_LAND_L, P_LAND_R, P_MC, P_MU_POCKET,
                     P_CAGE_HALF_SECTION, P_POCKET_ETA, P_POCKET_FILM, P_POCKET_FILM_FLOOR, P_POCKET_FILM_HHAT,
                     P_POCKET_FILM_RX, P_POCKET_GAP, P_POCKET_SHAPE, P_POCKET_SPACING, P_POCKET_VREG, P_RIGID, P_GX, P_GY, P_GZ,
                     P_UNBALANCE, P_CAGE_FRAME)
from .layout import (HZ_E, HZ_EXP, HZ_EXP_FILM, HZ_EXP_K, HZ_F, HZ_FILM_K, HZ_GEO, HZ_K, HZ_LN_RATIO, HZ_LN_U, HZ_LN_W,
                     HZ_N, HZ_RATIO)
from .layout import (D_ROLLRES, G_DRAG_POWER, G_EHL_POWER, G_HYST_POWER, P_ALPHA_H, P_DRAG, P_ETA_MIX, P_RHO_MIX,
                     P_ROLLRES)
from .layout import (D_POWER, D_ROLL, D_SPIN, D_SPIN_MOMENT, P_GROWTH_I, P_GROWTH_O, P_N_ACROSS, P_N_STRIPS,
                     P_RD_I, P_RD_O, P_TRACTION_CODE, P_TRACTION_LEVEL, P_TRACTION_PARAMS)
from .layout import (G_POWER_INNER, G_W_DAMPING, G_W_DRAG, G_W_EHL, G_W_HYST, G_W_LAND, G_W_POCKET,
                     G_W_TRACTION_INNER, G_W_TRACTION_OUTER)
from .layout import (D_A, D_ANGLE, D_B, D_DEFECT, D_FRICTION, D_HMIN, D_LAMBDA, D_LOAD, D_MU, D_OVERLAP, D_PMAX,
                     D_REGIME, D_SLIP, D_SRR, D_UR, DEF_BALL, DEF_N, DF_ACROSS, DF_BALL, DF_DEPTH, DF_DIR, DF_EDGE,
                     G_CONTACT_ENERGY, G_DAMP_POWER, G_DISS_WORK, G_DRIVE_POWER, G_DRIVE_WORK, G_KINETIC, P_IB,
                     DF_HL, DF_HW, DF_POS, DF_RACE, FRIC_HISTORY, H_E1, H_E2, P_DEF0, P_NDEF, R_ANGLE, FRIC_REGULARIZED, G_OMEGA, G_OUTER_FX, G_OUTER_FY,
                     G_OUTER_FZ, G_OUTER_TORQUE, G_POWER, G_RING_FX, G_RING_FY, G_RING_FZ, G_RING_TORQUE, G_WORST,
                     P_ALPHA_E, P_CAGE, P_CAGE_TAU, P_DT, P_EPRIME, P_ETA, P_FILM, P_FRIC, P_HERTZ, P_K_BB, P_K_BZ,
                     P_K_GUIDE, P_KT_IMPLICIT, P_KT_RATIO, P_L1, P_L3, P_LAW, P_LAW_D, P_LAW_K, P_LAW_N, P_LUB,
                     P_MAX_OVERLAP, P_MB, P_MU_B, P_MU_DRY, P_MU_F, P_MZ, P_RB, P_RCI, P_RCO, P_RGUIDE, P_RHO_I,
                     P_RHO_O, P_RP, P_RZ, P_SIGMA, P_VREG, P_XI, P_ZG_I, P_ZG_O)

__all__ = ["forces", "accumulate_energy", "scene_paths", "scene_loss_path", "HZ_N"]

#: Relative distance |x/x_0 - 1| from its anchor up to which :func:`_ln_anchored` takes ln x from the
#: anchor's logarithm and a series; the series' first omitted term, x^8/8, is below 1.3e-17 there.
LN_REACH = 1e-2
#: Distance |e - e_0| from its anchor up to which :func:`_exp_anchored` takes exp(e) from the anchor's
#: exponential and a series; its first omitted term, (e - e_0)^8 / 8!, is below 1.7e-17 there.
EXP_REACH = 3e-2


@kernel(internal=True)
def _cross(a0, a1, a2, b0, b1, b2):
    """a x b of two vectors given by their components. Called, not inlined by
    numba (LLVM inlines it): numba's inlining of its many call sites cost
    about 5 s of the cold start's compilation (``profile_reference.py --compile``)."""
    return a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0


@kernel(inline="always")
def _ring_frame(rings, r, x, y, z):
    """Point (x, y, z) relative to ring r's centre in the world frame (d) and
    in the ring frame (c = A^T d); ``rotated`` False when the ring's rotation
    matrix is the identity (the reference engine), which skips the products."""
    dxw = x - rings[r, 0]
    dyw = y - rings[r, 1]
    dzw = z - rings[r, 2]
    rotated = not (rings[r, 6] == 1.0 and rings[r, 10] == 1.0 and rings[r, 14] == 1.0)
    if rotated:
        cx = rings[r, 6] * dxw + rings[r, 9] * dyw + rings[r, 12] * dzw
        cy = rings[r, 7] * dxw + rings[r, 10] * dyw + rings[r, 13] * dzw
        cz = rings[r, 8] * dxw + rings[r, 11] * dyw + rings[r, 14] * dzw
    else:
        cx, cy, cz = dxw, dyw, dzw
    return dxw, dyw, dzw, cx, cy, cz, rotated


@kernel(inline="always")
def _hertz_constants(p, table, hz, j, race, rx, ry):
    """k, F, E of contact (j, race) (hertz.py), re-evaluated only when R_y/R_x
    moved by more than 1e-6 (relative) since the last evaluation (cache ``hz``).
    The test |R_y/R_x - a| > 1e-6 R_y/R_x is taken times R_x > 0, without the
    division (which then runs only on a miss). A contact whose angle changes
    (a combined load) misses at almost every step; at the exact level the
    re-evaluation then takes ln a_r, k = exp(ln k) and the film's
    exp(-0.68 k) from the contact's anchors (:func:`_ln_anchored`,
    :func:`_exp_anchored`; equal to ``hertz._kfe_tabulated`` and
    ``ehl.film_hd_ellipticity_factor`` to round-off), not from the C
    library's log and exp (the three were about a sixth of the 7208 rigid cage's step,
    ``python validation/studies/rigid_cage.py --profile``)."""
    if abs(ry - hz[j, race, HZ_RATIO] * rx) > 1e-6 * ry:
        method = int(p[P_HERTZ])
        if method == HERTZ_EXACT:
            lk, ell_f, ell_e = _kfe_table_ln(_ln_anchored(_axes_ratio(rx, ry), hz, j, race, HZ_LN_RATIO), table)
            kappa = _exp_anchored(lk, hz, j, race, HZ_EXP_K)
            film_k = 1.0 - _exp_anchored(-HD_ELLIPTICITY_DECAY * kappa, hz, j, race, HZ_EXP_FILM)
        else:
            kappa, ell_f, ell_e = _kfe_fast(rx, ry, method, table)
            film_k = _film_hd_ellipticity_factor(kappa)
        hz[j, race, HZ_RATIO] = ry / rx
        hz[j, race, HZ_K] = kappa
        hz[j, race, HZ_F] = ell_f
        hz[j, race, HZ_E] = ell_e
        hz[j, race, HZ_FILM_K] = film_k
        return kappa, ell_f, ell_e
    return hz[j, race, HZ_K], hz[j, race, HZ_F], hz[j, race, HZ_E]


@kernel(inline="always")
def _ln_anchored(x, hz, j, race, col):
    """ln x of an x > 0 (at least 1e-300) from the anchor of contact (j, race) in the cache columns
    (col, col + 1) = (1/x_0, ln x_0): within :data:`LN_REACH` of x_0, ln x = ln x_0 + ln(1 + r)
    with r = x/x_0 - 1 and ln(1 + r) by its series to r^7 (truncation below 1.3e-17, so the result is
    that of ``math.log`` to round-off); else ``math.log`` and x becomes the anchor. A zero anchor
    (the cache's initial state) is never within reach. The anchor's reciprocal keeps the division off
    the steady path."""
    r = x * hz[j, race, col] - 1.0
    if abs(r) < LN_REACH:
        r2 = r * r  # Estrin's scheme: the same sum, a shorter chain of dependent operations than Horner's
        return hz[j, race, col + 1] + (r + r2 * ((-1.0 / 2.0 + r * (1.0 / 3.0)) + r2 * (
            (-1.0 / 4.0 + r * (1.0 / 5.0)) + r2 * (-1.0 / 6.0 + r * (1.0 / 7.0)))))
    ln_x = math.log(x)
    hz[j, race, col] = 1.0 / x if x < 1e300 else 0.0  # no subnormal reciprocal: a huge x is never anchored
    hz[j, race, col + 1] = ln_x
    return ln_x


@kernel(inline="always")
def _exp_anchored(e, hz, j, race, col):
    """exp(e) from the anchor of contact (j, race) in the cache columns (col, col + 1) = (e_0,
    exp(e_0)): within :data:`EXP_REACH` of e_0, exp(e) = exp(e_0) exp(d), d = e - e_0, exp(d) by its
    series to d^7 (truncation below 1.7e-17 relative: the result is that of ``math.exp`` to
    round-off); else ``math.exp`` and e becomes the anchor. An anchor whose exp(e_0) is not positive
    (the cache's initial zeros) is never within reach."""
    d = e - hz[j, race, col]
    ex0 = hz[j, race, col + 1]
    if abs(d) < EXP_REACH and ex0 > 0.0:
        d2 = d * d  # Estrin's scheme, as in _ln_anchored
        return ex0 * (1.0 + d + d2 * ((1.0 / 2.0 + d * (1.0 / 6.0)) + d2 * (
            (1.0 / 24.0 + d * (1.0 / 120.0)) + d2 * (1.0 / 720.0 + d * (1.0 / 5040.0)))))
    ex = math.exp(e)
    hz[j, race, col] = e
    hz[j, race, col + 1] = ex
    return ex


@kernel(inline="always")
def _film_hd_anchored(hz, j, race, u_r, q_el, rx, e_prime, eta, ln_g):
    """h_min [m] of contact (j, race) by the Hamrock-Dowson film (``ehl.film_hd_ln_g_k``, from its
    parts ``film_groups``, ``film_hd_exponent``, ``film_hd_from_exponent``) with ln U, ln W and exp(E)
    from the contact's anchors in ``hz`` (:func:`_ln_anchored`, :func:`_exp_anchored`; equal to the
    direct relation to round-off) and the ellipticity factor cached with its Hertz constants."""
    u, w = film_groups(u_r, q_el, rx, e_prime, eta)
    e = film_hd_exponent(_ln_anchored(u, hz, j, race, HZ_LN_U), _ln_anchored(w, hz, j, race, HZ_LN_W), ln_g)
    on = (q_el > 0.0) * (u_r != 0.0)  # no load or no rolling: no film
    return on * film_hd_from_exponent(_exp_anchored(e, hz, j, race, HZ_EXP), hz[j, race, HZ_FILM_K], rx)


@kernel(no_runtime=True)
def _normal_law(p, delta, kappa, ell_f, ell_e, rr):
    """Elastic normal load Q [N], tangent stiffness dQ/d delta [N/m] and
    hysteretic damping C_hyst [N s/m] at the overlap delta: Hertz
    Q = K delta^1.5 with the Hunt-Crossley damping, or the peer power law
    k delta^n (whose own linear damping replaces C_hyst)."""
    if p[P_LAW] > 0.5:
        q_el = p[P_LAW_K] * delta ** p[P_LAW_N]
        return q_el, p[P_LAW_N] * q_el / delta, 0.0
    kst = _stiffness(kappa, ell_f, ell_e, rr, p[P_EPRIME])
    sq = math.sqrt(delta)
    return kst * delta * sq, 1.5 * kst * sq, _damping_hysteretic(kst, delta, p[P_ALPHA_E])


@kernel(inline="always")
def _hertz_energy(f_el, delta):
    """Elastic energy [J] stored in a Hertz contact of overlap ``delta`` [m] carrying the elastic force
    ``f_el`` = K delta^1.5 [N]: the integral of K d^1.5 over d from 0 to delta, K delta^2.5 / 2.5 =
    0.4 f_el delta (Johnson, Contact Mechanics, 1985, sec. 4.2; docs/theory/dynamics.md, "Losses and the
    energy balance")."""
    return 0.4 * f_el * delta


@kernel(inline="always")
def _surface_kinematics(rings, r, xb, vb, wb, j, dxw, dyw, dzw, cx, cy, nx, ny, nz, lev):
    """Velocities at the contact point, lever ``lev`` from the ball centre
    along the normal n: approach rate d(delta)/dt, tangential slip velocity
    (s, |s|), rolling (entrainment) speed u_r = |mean surface velocity
    relative to the contact point|, the contact point carried by the ball's
    orbital motion about the ring axis, and that mean velocity m; also the
    lever l and the contact point relative to the ring centre."""
    lx, ly, lz = lev * nx, lev * ny, lev * nz
    bx, by, bz = _cross(wb[j, 0], wb[j, 1], wb[j, 2], lx, ly, lz)
    vbs_x = vb[j, 0] + bx
    vbs_y = vb[j, 1] + by
    vbs_z = vb[j, 2] + bz
    px = dxw + lx
    py = dyw + ly
    pz = dzw + lz
    wrx, wry, wrz = rings[r, 15], rings[r, 16], rings[r, 17]
    rwx, rwy, rwz = _cross(wrx, wry, wrz, px, py, pz)
    vrs_x = rings[r, 3] + rwx
    vrs_y = rings[r, 4] + rwy
    vrs_z = rings[r, 5] + rwz
    # normal approach rate d(delta)/dt = n . (v_ball - v_ring - w_ring x d)
    ex, ey, ez = _cross(wrx, wry, wrz, dxw, dyw, dzw)
    vrx = vb[j, 0] - rings[r, 3]
    vry = vb[j, 1] - rings[r, 4]
    vrz = vb[j, 2] - rings[r, 5]
    ddot = (vrx - ex) * nx + (vry - ey) * ny + (vrz - ez) * nz
    # slip: tangential relative velocity of the surfaces
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
    a02, a12, a22 = rings[r, 8], rings[r, 11], rings[r, 14]
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
    return ddot, sx, sy, sz, slip, u_r, mx, my, mz, lx, ly, lz, px, py, pz


@kernel(no_runtime=True)
def _lubrication(p, u_r, q_el, rx, kappa, major, c_hyst):
    """Film h_min [m], Lambda, regime code, normal damping C_n [N s/m] and
    friction coefficient mu of a contact: the Lambda-switched model of the
    DEM papers (ehl.py, damping.py, friction.py), constant mu_dry and C_hyst
    without lubrication, or the peer power law's own damping and mu."""
    return _lubrication_ln_g(p, u_r, q_el, rx, kappa, major, c_hyst, math.log(p[P_XI] * p[P_EPRIME]), -1.0)


@kernel(no_runtime=True, internal=True)
def _lubrication_ln_g(p, u_r, q_el, rx, kappa, major, c_hyst, ln_g, factor_k):
    """:func:`_lubrication` with ``ln_g`` = ln(xi E') given: the kernel
    computes it once per evaluation (:func:`forces`), not per contact; and
    ``factor_k`` the HD film's ellipticity factor of ``kappa`` (cached with
    the Hertz constants; negative: computed here)."""
    if p[P_LAW] > 0.5:
        return 0.0, 0.0, 0, p[P_LAW_D], p[P_MU_DRY]
    if p[P_LUB] > 0.5:
        h = _film_thickness_ln_g_k(int(p[P_FILM]), u_r, q_el, rx, kappa, factor_k, p[P_EPRIME], p[P_ETA], ln_g)
        lam, regime, c_n, mu = _lubrication_film(p, h, major, c_hyst)
        return h, lam, regime, c_n, mu
    return 0.0, 0.0, 0, c_hyst, p[P_MU_DRY]


@kernel(no_runtime=True)
def _lubrication_film(p, h, major, c_hyst):
    """Lambda, regime code, normal damping C_n [N s/m] and friction coefficient mu of a lubricated
    Hertz contact with the film h_min = h [m] (:func:`_lubrication_ln_g`)."""
    lam = h * (1.0 / p[P_SIGMA])  # the reciprocal off the chain of h
    regime = lubrication_regime(lam, p[P_L1], p[P_L3])
    if regime == 0:
        c_n = c_hyst
    else:
        c_fl = _damping_fluid(p[P_ETA], major, p[P_RB], h)
        c_n = damping_coefficient(lam, c_hyst, c_fl, p[P_L1], p[P_L3])
    return lam, regime, c_n, friction_coefficient(lam, p[P_MU_B], p[P_MU_F], p[P_L1], p[P_L3])


@kernel(inline="always")
def _tangential_force(p, hist, hist_out, dt_hist, j, race, nx, ny, nz, sx, sy, sz, slip, k_n, f_n, mu):
    """Tangential force on the ball (friction.py): the Cundall-Strack spring
    with Coulomb cap (the spring kept in ``hist``, rotated into the current
    tangent plane, incremented by the slip over ``dt_hist``, rescaled when
    sliding; explicit K_t or its implicit step-consistent value), regularised
    Coulomb on the slip velocity, or none."""
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
        k_t = p[P_KT_RATIO] * k_n
        if p[P_KT_IMPLICIT] > 0.5:
            k_t = _implicit_tangential_stiffness(k_t, p[P_DT], _sphere_tangential_mass(p[P_MB]))
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
        return ftx, fty, ftz
    if fric == FRIC_REGULARIZED and slip > 0.0:
        fmag = _regularized_coulomb(slip, f_n, mu, p[P_VREG])
        return -fmag * sx / slip, -fmag * sy / slip, -fmag * sz / slip
    return 0.0, 0.0, 0.0


@kernel(no_runtime=True, internal=True)
def _contact_frame(rings, r, wb, j, dxw, dyw, dzw, nx, ny, nz):
    """Rolling frame of a contact and the ball's angular velocity relative to
    the race: e_x the rolling (circumferential) direction at the ball, e_y =
    e_x x n, and (spin, roll) = (w_ball - w_ring) . (n, e_y) [rad/s]."""
    ax, ay, az = rings[r, 8], rings[r, 11], rings[r, 14]
    exx, exy, exz = _cross(ax, ay, az, dxw, dyw, dzw)
    e_n = math.sqrt(exx * exx + exy * exy + exz * exz)
    if e_n > 0.0:
        exx /= e_n
        exy /= e_n
        exz /= e_n
    eyx, eyy, eyz = _cross(exx, exy, exz, nx, ny, nz)
    wx = wb[j, 0] - rings[r, 15]
    wy = wb[j, 1] - rings[r, 16]
    wz = wb[j, 2] - rings[r, 17]
    return (wx * nx + wy * ny + wz * nz, wx * eyx + wy * eyy + wz * eyz, exx, exy, exz, eyx, eyy, eyz)


@kernel(no_runtime=True)
def _ellipse_traction(p, rx, kappa, a_ax, b_ax, f_n, sx, sy, sz, mx, my, mz, h_min, spin, roll, inner,
                      exx, exy, exz, eyx, eyy, eyz):
    """Traction of a ball / raceway contact integrated over its Hertz ellipse
    (:func:`~exudyn_bearing.physics.contact_slip._contact_traction`, the
    quasi-static solver's relation): slip v0, v_t at the centre along e_x,
    e_y, spin w_n = -spin about e_z = -n, curvature-induced slip c2 =
    roll / (2 R_d), rolling speed |m . e_x| (at least the regularising speed
    ``P_VREG``, so that a slide-to-roll traction law stays finite at
    start-up). Returns the force on the ball
    (world), the moment on it about e_z, the curvature moment about e_y
    (:mod:`~exudyn_bearing.physics.contact_slip`: with it the applied forces
    take exactly the dissipation from the bodies) and the dissipation [W].
    Called, not inlined: the point level's hot loop stays as small as without it.
    """
    v0 = sx * exx + sy * exy + sz * exz
    v_t = sx * eyx + sy * eyy + sz * eyz
    # rolling speed of the slide-to-roll ratio, at least the regularising speed (start-up from rest)
    u_roll = max(abs(mx * exx + my * exy + mz * exz), p[P_VREG])
    r_d = p[P_RD_I] if inner else p[P_RD_O]
    code = int(p[P_TRACTION_CODE])
    h_c = 0.0
    if code == TRACTION_EHL:
        h_c = _film_central_hd(u_roll, f_n, rx, kappa, p[P_EPRIME], p[P_ETA], p[P_XI])
    f_x, f_y, m_z, power, _qv, m_y = _contact_traction(
        a_ax, b_ax, f_n, v0, -spin, roll / (2.0 * r_d), r_d, v_t, u_roll, h_c, h_min, code,
        p[P_TRACTION_PARAMS:P_TRACTION_PARAMS + N_TRACTION_PARAMS], int(p[P_N_STRIPS]), int(p[P_N_ACROSS]))
    return (f_x * exx + f_y * eyx, f_x * exy + f_y * eyy, f_x * exz + f_y * eyz, m_z, m_y, power)


@kernel(inline="always")
def _moment_pair(tb, fr, j, race, mx, my, mz):
    """Moment (mx, my, mz) on ball j and its reaction on ring ``race``: a couple pair, no net force."""
    tb[j, 0] += mx
    tb[j, 1] += my
    tb[j, 2] += mz
    fr[race, 3] -= mx
    fr[race, 4] -= my
    fr[race, 5] -= mz


@kernel(no_runtime=True, internal=True)
def _rolling_resistance(p, f_n, u_r, rx, kappa, b_roll, roll):
    """Rolling-resistance moment of a ball / raceway contact (docs/theory/losses.md, "In the dynamic
    engines"): magnitude (F_h + 2 F_R) R_x, F_h the hysteresis force (Johnson) at the normal force f_n and
    the semi-axis b_roll along the rolling direction, F_R the EHL rolling force (Harris & Kotzalas;
    with lubrication and the Hertz law only) at the rolling speed u_r, opposing ``roll`` = (w_ball -
    w_ring) . e_y; its sign regularised linearly below R_x |roll| = ``P_VREG`` (the engines'
    regularising speed, as the regularised Coulomb friction). Returns the moment on the ball along
    e_y (the ring takes minus it) and its dissipation split into the EHL rolling and hysteresis
    parts [W]. Called, not inlined, and compiled only with a ``loss_path`` (:func:`forces`)."""
    f_h = _hysteresis_rolling_force(f_n, b_roll, rx, p[P_ALPHA_H])
    f_r = 0.0
    if p[P_LUB] > 0.5 and p[P_LAW] < 0.5:
        f_r = _ehl_rolling_force(u_r, f_n, rx, kappa, p[P_EPRIME], p[P_ETA], p[P_XI])
    tot = f_h + 2.0 * f_r
    m_act = _regularized_coulomb(rx * roll, tot * rx, 1.0, p[P_VREG])
    power = m_act * abs(roll)
    p_h = power * f_h / tot if tot > 0.0 else 0.0
    return (-m_act if roll > 0.0 else m_act), power - p_h, p_h


@kernel(no_runtime=True, internal=True)
def _ball_drag(p, xb, vb, rings, fb, fr):
    """Drag of the oil-air mixture on every ball centre (docs/theory/losses.md): F_D = 1/2 C_D(Re)
    rho A |v| v against the ball's velocity v relative to the mixture, which moves with the outer
    ring (ring 1; :func:`~exudyn_bearing.physics.losses.ball_drag_force`, mixture density and
    viscosity ``P_RHO_MIX``, ``P_ETA_MIX``); the reaction acts on the outer ring at the ball centre.
    Returns the dissipation [W]. Called only with a ``loss_path`` (:func:`forces`)."""
    total = 0.0
    d_ball = 2.0 * p[P_RB]
    for j in range(xb.shape[0]):
        dx = xb[j, 0] - rings[1, 0]
        dy = xb[j, 1] - rings[1, 1]
        dz = xb[j, 2] - rings[1, 2]
        ex, ey, ez = _cross(rings[1, 15], rings[1, 16], rings[1, 17], dx, dy, dz)
        vx = vb[j, 0] - rings[1, 3] - ex
        vy = vb[j, 1] - rings[1, 4] - ey
        vz = vb[j, 2] - rings[1, 5] - ez
        v = math.sqrt(vx * vx + vy * vy + vz * vz)
        if v > 0.0:
            f = ball_drag_force(v, d_ball, p[P_RHO_MIX], p[P_ETA_MIX])
            fx, fy, fz = -f * vx / v, -f * vy / v, -f * vz / v
            fb[j, 0] += fx
            fb[j, 1] += fy
            fb[j, 2] += fz
            fr[1, 0] -= fx
            fr[1, 1] -= fy
            fr[1, 2] -= fz
            mx_, my_, mz_ = _cross(dx, dy, dz, -fx, -fy, -fz)
            fr[1, 3] += mx_
            fr[1, 4] += my_
            fr[1, 5] += mz_
            total += f * v
    return total


@kernel(inline="always")
def _open_contact(hist_out, diag, j, race, delta, ca, sa, drop, want):
    """A ball / raceway contact without overlap: its tangential spring is
    reset; diagnostics zero, the gap, the contact angle, the defect drop, no
    film (NaN) and regime -1."""
    hist_out[j, race, 0] = 0.0
    hist_out[j, race, 1] = 0.0
    hist_out[j, race, 2] = 0.0
    if want:
        for k in range(diag.shape[2]):
            diag[j, race, k] = 0.0
        diag[j, race, D_OVERLAP] = delta
        diag[j, race, D_DEFECT] = drop
        diag[j, race, D_ANGLE] = math.atan2(sa, ca)
        diag[j, race, D_HMIN] = np.nan
        diag[j, race, D_LAMBDA] = np.nan
        diag[j, race, D_REGIME] = -1.0
        diag[j, race, D_MU] = np.nan


@kernel(no_runtime=True, internal=True)
def _defect_drop(p, hist_out, rings, j, race, rotated, cx, cy, nlx, nly, nlz, ca, sa, r_contact, rb, rc, inner):
    """Drop [m] of ball j's contact with race ``race`` into the scene's
    defects (:func:`exudyn_bearing.physics.defects.spall_drop`; the deepest
    where several overlap), in the ring frame (c: ball centre, n_l: normal).

    Race spall: s = r_contact times the azimuth of the contact relative to
    the spall centre (ring-frame azimuth minus the ring's ``R_ANGLE``), w =
    R_c times the contact angle relative to the spall's. Ball spall: its
    centre direction d = c1 e1 + c2 e2 + c3 e1 x e2 from the ball's body
    frame in ``hist_out``; with theta the angle between d and the contact
    direction n, s = R_b atan2(d . e_psi, cos theta) along the orbital
    direction e_psi, w = R_b atan2(d . (n x e_psi), cos theta) across; a
    spall facing away (cos theta <= 0) is not in contact."""
    drop = 0.0
    have_radii = False
    rx = 0.0
    ry = 0.0
    for k in range(int(p[P_NDEF])):
        base = P_DEF0 + k * DEF_N
        kind = int(p[base + DF_RACE])
        hl = p[base + DF_HL]
        if kind == race:
            dpsi = math.atan2(cy, cx) - rings[race, R_ANGLE] - p[base + DF_POS]
            dpsi -= 2.0 * math.pi * math.floor((dpsi + math.pi) / (2.0 * math.pi))
            s = r_contact * dpsi
            if s >= hl or s <= -hl:
                continue
            w = rc * (math.atan2(sa, ca) - p[base + DF_ACROSS])
        elif kind == DEF_BALL and int(p[base + DF_BALL]) == j and hist_out.shape[1] > H_E2:
            e1x, e1y, e1z = hist_out[j, H_E1, 0], hist_out[j, H_E1, 1], hist_out[j, H_E1, 2]
            e2x, e2y, e2z = hist_out[j, H_E2, 0], hist_out[j, H_E2, 1], hist_out[j, H_E2, 2]
            e3x, e3y, e3z = _cross(e1x, e1y, e1z, e2x, e2y, e2z)
            c1, c2, c3 = p[base + DF_DIR], p[base + DF_DIR + 1], p[base + DF_DIR + 2]
            dx = c1 * e1x + c2 * e2x + c3 * e3x
            dy = c1 * e1y + c2 * e2y + c3 * e3y
            dz = c1 * e1z + c2 * e2z + c3 * e3z
            if rotated:  # into the ring frame, d_l = A^T d
                dx, dy, dz = (rings[race, 6] * dx + rings[race, 9] * dy + rings[race, 12] * dz,
                              rings[race, 7] * dx + rings[race, 10] * dy + rings[race, 13] * dz,
                              rings[race, 8] * dx + rings[race, 11] * dy + rings[race, 14] * dz)
            cos_t = dx * nlx + dy * nly + dz * nlz
            r_xy = math.sqrt(cx * cx + cy * cy)
            if cos_t <= 0.0 or r_xy == 0.0:
                continue
            tx = -cy / r_xy
            ty = cx / r_xy
            s = rb * math.atan2(dx * tx + dy * ty, cos_t)
            if s >= hl or s <= -hl:
                continue
            ax, ay, az = _cross(nlx, nly, nlz, tx, ty, 0.0)
            w = rb * math.atan2(dx * ax + dy * ay + dz * az, cos_t)
        else:
            continue
        if not have_radii:
            rx, ry = _raceway_radii_cos(rb, rc, r_contact, ca, inner)
            have_radii = True
        e = _spall_drop_k(s, w, hl, p[base + DF_HW], p[base + DF_DEPTH], p[base + DF_EDGE], rx, ry)
        if e > drop:
            drop = e
    return drop


@kernel(no_runtime=True, internal=True)
def _turn_ball_frame(p, hist, hist_out, dt_hist, wb, j):
    """If ball j carries a defect, turn its body frame (hist rows H_E1, H_E2)
    from the committed state by its angular velocity over ``dt_hist`` into
    ``hist_out`` (:func:`exudyn_bearing.model.motion.rotate_frame`)."""
    if hist.shape[1] <= H_E2:
        return
    for k in range(int(p[P_NDEF])):
        base = P_DEF0 + k * DEF_N
        if int(p[base + DF_RACE]) == DEF_BALL and int(p[base + DF_BALL]) == j:
            rotate_frame(hist, hist_out, j, H_E1, H_E2, wb[j, 0], wb[j, 1], wb[j, 2], dt_hist)
            return


@kernel(inline="always")
def _race_geometry(p, rings, xb, j, race):
    """Ball j in the groove of race ``race``: its centre relative to the ring (:func:`_ring_frame`) and the
    groove geometry (``geometry._groove_geometry``) at the groove centre circle, grown by the ring's
    centrifugal growth."""
    inner = race == 0
    if inner:
        rho, zg, rc, growth = p[P_RHO_I], p[P_ZG_I], p[P_RCI], p[P_GROWTH_I]
    else:
        rho, zg, rc, growth = p[P_RHO_O], p[P_ZG_O], p[P_RCO], p[P_GROWTH_O]
    if growth != 0.0:
        # centrifugal growth of a spinning ring: the groove moves out by growth * omega^2
        w_ax = rings[race, 8] * rings[race, 15] + rings[race, 11] * rings[race, 16] + rings[race, 14] * rings[race, 17]
        rho += growth * w_ax * w_ax
    dxw, dyw, dzw, cx, cy, cz, rotated = _ring_frame(rings, race, xb[j, 0], xb[j, 1], xb[j, 2])
    delta, nlx, nly, nlz, ca, sa, r_contact = _groove_geometry(cx, cy, cz, rho, zg, rc, p[P_RB], inner)
    return dxw, dyw, dzw, cx, cy, rotated, delta, nlx, nly, nlz, ca, sa, r_contact


@kernel(inline="always")
def _race_contact(j, race, p, table, xb, vb, wb, rings, hist, hist_out, dt_hist, hz, fb, tb, fr, diag, want, ln_g,
                  defect_path, ellipse_path, loss_path):
    """Ball j on the inner (race 0, ring 0) or outer (race 1, ring 1) groove.

    Adds the contact force and moment to ball j (fb, tb) and the reaction to
    the ring (fr); writes the spring to ``hist_out`` and, with ``want``, the
    diagnostics. Returns (overlap / R_b, frictional power [W], dissipation of
    the normal damping [W], of the EHL rolling and of the hysteresis rolling
    resistance [W], the elastic energy stored in the contact [J]: the
    integral of the elastic load over the overlap); zeros when the contact is open. ``ln_g`` = ln(xi E');
    ``defect_path``, ``ellipse_path``, ``loss_path``: None compiles the contact
    without the defect drop, the ellipse traction or the rolling resistance
    (:func:`forces`)."""
    inner = race == 0
    rc = p[P_RCI] if inner else p[P_RCO]
    rb = p[P_RB]
    g = HZ_GEO  # the geometry, computed by forces before the contacts, for all of them
    dxw, dyw, dzw, cx, cy = hz[j, race, g], hz[j, race, g + 1], hz[j, race, g + 2], hz[j, race, g + 3], hz[j, race, g + 4]
    rotated = hz[j, race, g + 5] != 0.0
    delta, nlx, nly, nlz = hz[j, race, g + 6], hz[j, race, g + 7], hz[j, race, g + 8], hz[j, race, g + 9]
    ca, sa, r_contact = hz[j, race, g + 10], hz[j, race, g + 11], hz[j, race, g + 12]
    drop = 0.0
    if defect_path is not None:  # pruned at compile time when None
        if p[P_NDEF] > 0.0 and delta > 0.0:
            drop = _defect_drop(p, hist_out, rings, j, race, rotated, cx, cy, nlx, nly, nlz, ca, sa, r_contact, rb,
                                rc, inner)
            delta -= drop
    if delta <= 0.0:
        _open_contact(hist_out, diag, j, race, delta, ca, sa, drop, want)
        return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    # contact normal in the world frame, n = A n_local
    if rotated:
        nx = rings[race, 6] * nlx + rings[race, 7] * nly + rings[race, 8] * nlz
        ny = rings[race, 9] * nlx + rings[race, 10] * nly + rings[race, 11] * nlz
        nz = rings[race, 12] * nlx + rings[race, 13] * nly + rings[race, 14] * nlz
    else:
        nx, ny, nz = nlx, nly, nlz
    # elliptic Hertz at the current contact angle
    rx, ry = _raceway_radii_cos(rb, rc, r_contact, ca, inner)
    kappa, ell_f, ell_e = _hertz_constants(p, table, hz, j, race, rx, ry)
    rr = _curvature_sum_radius(rx, ry)
    q_el, k_n, c_hyst = _normal_law(p, delta, kappa, ell_f, ell_e, rr)
    ellipse = p[P_TRACTION_LEVEL] > 0.5
    rolling_resistance = False
    if loss_path is not None:  # pruned at compile time when None
        rolling_resistance = p[P_ROLLRES] > 0.5
    if want or ellipse or p[P_LUB] > 0.5 or rolling_resistance:
        if p[P_LAW] > 0.5:
            major, minor = _semi_axes(kappa, ell_e, rr, p[P_EPRIME], q_el)
        else:  # at the Hertz load q_el of this overlap: the same axes by a square root
            major, minor = _semi_axes_overlap(kappa, ell_f, ell_e, rr, delta)
    else:
        major = minor = 0.0
    # contact point: middle of the overlap (n points from the groove centre to the
    # ball centre; the groove surface p + R_c n lies beyond the ball centre along n);
    # the ellipse level takes the slip on the undeformed ball surface, X = c + R_b n,
    # as the quasi-static solver's kinematics do (Harris & Kotzalas)
    ddot, sx, sy, sz, slip, u_r, mx, my, mz, lx, ly, lz, px, py, pz = _surface_kinematics(
        rings, race, xb, vb, wb, j, dxw, dyw, dzw, cx, cy, nx, ny, nz, rb if ellipse else rb - 0.5 * delta)
    if p[P_LUB] > 0.5 and p[P_LAW] < 0.5 and int(p[P_FILM]) == HAMROCK_DOWSON:
        # the steady path of the default film: its logarithms and exponential from the contact's anchors
        h = _film_hd_anchored(hz, j, race, u_r, q_el, rx, p[P_EPRIME], p[P_ETA], ln_g)
        lam, regime, c_n, mu = _lubrication_film(p, h, major, c_hyst)
    else:
        h, lam, regime, c_n, mu = _lubrication_ln_g(p, u_r, q_el, rx, kappa, major, c_hyst, ln_g,
                                                    hz[j, race, HZ_FILM_K])
    f_n = q_el + c_n * ddot
    if f_n < 0.0:
        f_n = 0.0
    spin = roll = m_z = 0.0
    exx = exy = exz = eyx = eyy = eyz = 0.0
    framed = ellipse or rolling_resistance  # the rolling frame, once per contact for both users
    if framed:
        spin, roll, exx, exy, exz, eyx, eyy, eyz = _contact_frame(rings, race, wb, j, dxw, dyw, dzw, nx, ny, nz)
    if ellipse:
        if ry >= rx:
            a_ax, b_ax = major, minor
        else:
            a_ax, b_ax = minor, major
        if ellipse_path is not None:  # pruned at compile time when None (forces never gets here then)
            ftx, fty, ftz, m_z, m_y, power = _ellipse_traction(p, rx, kappa, a_ax, b_ax, f_n, sx, sy, sz, mx, my,
                                                               mz, h, spin, roll, inner, exx, exy, exz, eyx, eyy,
                                                               eyz)
        else:
            ftx = fty = ftz = m_z = m_y = power = 0.0
        # the spin moment m_z about e_z = -n and the curvature moment m_y about
        # e_y: on the ball, and their reaction on the ring
        _moment_pair(tb, fr, j, race, m_y * eyx - m_z * nx, m_y * eyy - m_z * ny, m_y * eyz - m_z * nz)
        hist_out[j, race, 0] = 0.0
        hist_out[j, race, 1] = 0.0
        hist_out[j, race, 2] = 0.0
    else:
        ftx, fty, ftz = _tangential_force(p, hist, hist_out, dt_hist, j, race, nx, ny, nz, sx, sy, sz, slip, k_n,
                                          f_n, mu)
        power = -(ftx * sx + fty * sy + ftz * sz)
    p_ehl = p_hyst = 0.0
    if loss_path is not None:  # pruned at compile time when None
        if rolling_resistance:
            # the rolling-resistance moment pair about e_y: on the ball, and its reaction on the ring
            m_rr, p_ehl, p_hyst = _rolling_resistance(p, f_n, u_r, rx, kappa, minor if ry >= rx else major, roll)
            _moment_pair(tb, fr, j, race, m_rr * eyx, m_rr * eyy, m_rr * eyz)
    # forces on the ball: the normal pushes it back towards the groove centre
    fb[j, 0] += -f_n * nx + ftx
    fb[j, 1] += -f_n * ny + fty
    fb[j, 2] += -f_n * nz + ftz
    mx_, my_, mz_ = _cross(lx, ly, lz, ftx, fty, ftz)
    tb[j, 0] += mx_
    tb[j, 1] += my_
    tb[j, 2] += mz_
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
        if not framed:
            spin, roll, _x, _y, _z, _u, _v, _w = _contact_frame(rings, race, wb, j, dxw, dyw, dzw, nx, ny, nz)
        if ry >= rx:
            a_ax, b_ax = major, minor
        else:
            a_ax, b_ax = minor, major
        diag[j, race, D_LOAD] = f_n
        diag[j, race, D_OVERLAP] = delta
        diag[j, race, D_ANGLE] = math.atan2(sa, ca)
        diag[j, race, D_A] = a_ax
        diag[j, race, D_B] = b_ax
        diag[j, race, D_PMAX] = 1.5 * q_el / (math.pi * a_ax * b_ax) if a_ax * b_ax > 0.0 else 0.0
        diag[j, race, D_UR] = u_r
        diag[j, race, D_HMIN] = h
        diag[j, race, D_LAMBDA] = lam if p[P_LUB] > 0.5 else np.nan
        diag[j, race, D_REGIME] = regime
        diag[j, race, D_MU] = mu
        diag[j, race, D_SLIP] = slip
        diag[j, race, D_SRR] = slip / u_r if u_r > 0.0 else 0.0
        diag[j, race, D_FRICTION] = math.sqrt(ftx * ftx + fty * fty + ftz * ftz)
        diag[j, race, D_DEFECT] = drop
        diag[j, race, D_SPIN] = spin
        diag[j, race, D_ROLL] = roll
        diag[j, race, D_POWER] = power
        diag[j, race, D_SPIN_MOMENT] = m_z
        diag[j, race, D_ROLLRES] = p_ehl + p_hyst
    # dissipation of the normal damping: the applied normal force beyond the elastic one times the approach rate
    # the elastic energy: Hertz's 0.4 Q delta, or the power law's Q delta / (n + 1)
    stored = q_el * delta / (1.0 + p[P_LAW_N]) if p[P_LAW] > 0.5 else _hertz_energy(q_el, delta)
    return delta / rb, power, (f_n - q_el) * ddot, p_ehl, p_hyst, stored


@kernel(inline="always")
def _pair_contact(ia, ib, xb, vb, fb, px_, pv_, pf_, r_sum, k_pair, m_pair, tau):
    """Ball ia against sphere ib of (px_, pv_) (a cage ball, or the next ball
    without cage): frictionless Hertz with critical damping, taken implicit
    over the step ``tau`` (:func:`_implicit_damping`; 0: explicit); adds the
    force to fb[ia] and its reaction to pf_[ib]; returns the contact force
    [N], the dissipation of its damping [W], its overlap [m] (for the
    runaway measure of :func:`forces`) and its elastic energy [J]."""
    dx = xb[ia, 0] - px_[ib, 0]
    dy = xb[ia, 1] - px_[ib, 1]
    dz = xb[ia, 2] - px_[ib, 2]
    d2 = dx * dx + dy * dy + dz * dz
    if not (d2 < r_sum * r_sum and d2 > 0.0):
        return 0.0, 0.0, 0.0, 0.0
    dist = math.sqrt(d2)
    delta = r_sum - dist
    inv = 1.0 / dist
    nx, ny, nz = dx * inv, dy * inv, dz * inv
    sq = math.sqrt(delta)
    c = _damping_critical(m_pair, 1.5 * k_pair * sq)
    if tau > 0.0:  # a scene constant: the explicit damping's arithmetic stays as it was (fastmath may fuse)
        c = _implicit_damping(c, m_pair, tau)
    ddot = -((vb[ia, 0] - pv_[ib, 0]) * nx + (vb[ia, 1] - pv_[ib, 1]) * ny + (vb[ia, 2] - pv_[ib, 2]) * nz)
    f_el = k_pair * delta * sq
    f = f_el + c * ddot
    if f < 0.0:
        f = 0.0
    fb[ia, 0] += f * nx
    fb[ia, 1] += f * ny
    fb[ia, 2] += f * nz
    pf_[ib, 0] -= f * nx
    pf_[ib, 1] -= f * ny
    pf_[ib, 2] -= f * nz
    return f, (f - f_el) * ddot, delta, _hertz_energy(f_el, delta)


@kernel(inline="always")
def _guide_contact(k, p, xc, vc, rings, fc, fr):
    """Cage ball k in its guide torus, fixed to the outer ring (ring 1): tube-
    centre circle r_p in the ring's radial plane, tube radius R_z + guide
    clearance; frictionless Hertz, R_eq = R_z, critical damping. Adds the
    force to fc[k] and its reaction to fr[1]; returns the dissipation of its
    damping [W], the overlap [m] (for the runaway measure of :func:`forces`;
    NaN for a non-finite cage ball) and its elastic energy [J]."""
    rz = p[P_RZ]
    free = p[P_RGUIDE] - rz
    dxw, dyw, dzw, cx, cy, cz, _rot = _ring_frame(rings, 1, xc[k, 0], xc[k, 1], xc[k, 2])
    dr = math.sqrt(cx * cx + cy * cy) - p[P_RP]
    if dr * dr + cz * cz <= free * free:  # False for a non-finite cage ball: its NaN reaches the ratio
        return 0.0, 0.0, 0.0
    delta, nlx, nly, nlz, _ca, _sa, _rc = _groove_geometry(cx, cy, cz, p[P_RP], 0.0, p[P_RGUIDE], rz, False)
    if delta <= 0.0:
        return 0.0, 0.0, 0.0
    nx = rings[1, 6] * nlx + rings[1, 7] * nly + rings[1, 8] * nlz
    ny = rings[1, 9] * nlx + rings[1, 10] * nly + rings[1, 11] * nlz
    nz = rings[1, 12] * nlx + rings[1, 13] * nly + rings[1, 14] * nlz
    ex, ey, ez = _cross(rings[1, 15], rings[1, 16], rings[1, 17], dxw, dyw, dzw)
    vn = ((vc[k, 0] - rings[1, 3] - ex) * nx + (vc[k, 1] - rings[1, 4] - ey) * ny
          + (vc[k, 2] - rings[1, 5] - ez) * nz)
    sq = math.sqrt(delta)
    kst = p[P_K_GUIDE]
    c = _damping_critical(p[P_MZ], 1.5 * kst * sq)
    if p[P_CAGE_TAU] > 0.0:
        c = _implicit_damping(c, p[P_MZ], p[P_CAGE_TAU])
    f_el = kst * delta * sq
    f = f_el + c * vn
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
        return (f - f_el) * vn, delta, _hertz_energy(f_el, delta)
    return 0.0, delta, _hertz_energy(f_el, delta)


@kernel(inline="always")
def _land_force(p, ex, ey, evx, evy, omega_sum):
    """(F_x, F_y, crush force) of the land on the cage at the cage's offset (ex, ey) and velocity (evx, evy)
    relative to the land, the surfaces turning at omega_sum together: the short-bearing film
    (:func:`~exudyn_bearing.physics.short_bearing._short_bearing_xy`) and, beyond the crush eccentricity
    ``P_LAND_EPS``, the film's force there along the same line plus the land contact k_land (e - eps_c c)."""
    cl = p[P_LAND_C]
    eps_c = p[P_LAND_EPS]
    e = math.sqrt(ex * ex + ey * ey)
    k = 1.0 if e <= eps_c * cl else eps_c * cl / e
    fx, fy = _short_bearing_xy(ex * k, ey * k, evx, evy, omega_sum, p[P_LAND_ETA], p[P_LAND_R], p[P_LAND_L], cl)
    pen = 0.0
    if k < 1.0:
        pen = p[P_K_LAND] * (e - eps_c * cl)
        fx -= pen * ex / e
        fy -= pen * ey / e
    return fx, fy, pen


@kernel(no_runtime=True, inline="always")
def _pocket_film_gaps(p, h, floor):
    """(near, far) [m]: the pocket film's gaps at the wall the ball approaches (``h`` = c_p - offset) and at the
    opposite wall (2 c_p - h = c_p + offset: the walls are 2 c_p apart across the ball), each at least ``floor``
    (the composite roughness)."""
    near = h if h > floor else floor
    far = 2.0 * p[P_POCKET_GAP] - h
    if far < floor:
        far = floor
    return near, far


@kernel(inline="always")
def _pocket_film_force(p, qx, qy, qz, nx, ny, nz, sx, sy, sz, near, far, ddot, m_eff, tau):
    """The net force [N] of a ball's pocket film along -n (off the wall the ball approaches: docs/theory/cage.md,
    "Pocket oil film"): the film at the near wall (gap ``near``) less the film at the opposite wall (gap
    ``far``; :func:`_pocket_film_gaps`), each hydrodynamic (the entraining speed: half the ball's sliding ``s``
    on the wall less the contact point's own speed in the cage, the ball centre's velocity ``q`` relative to
    the cage across n) plus squeeze (approach speed ``ddot`` toward the near wall, -ddot toward the far one;
    backward-Euler over ``tau`` with implicit cage damping). Net zero for a centred, still ball; continuous as
    the ball crosses the pocket's centre."""
    rb = p[P_RB]
    qn = qx * nx + qy * ny + qz * nz
    ue_x, ue_y, ue_z = 0.5 * sx - (qx - qn * nx), 0.5 * sy - (qy - qn * ny), 0.5 * sz - (qz - qn * nz)
    u = math.sqrt(ue_x * ue_x + ue_y * ue_y + ue_z * ue_z)
    eta, r_x, h_hat = p[P_POCKET_ETA], p[P_POCKET_FILM_RX], p[P_POCKET_FILM_HHAT]
    w1, c1 = _hydrodynamic_film_load(eta, u, r_x, h_hat, near), _squeeze_film_damping(eta, rb, near)
    w2, c2 = _hydrodynamic_film_load(eta, u, r_x, h_hat, far), _squeeze_film_damping(eta, rb, far)
    if tau > 0.0:
        c1 = _implicit_damping(c1, m_eff, tau)
        c2 = _implicit_damping(c2, m_eff, tau)
    f = w1 - w2
    if ddot > 0.0:
        f += c1 * ddot
    else:
        f += c2 * ddot
    return f


@kernel(inline="always")
def _pocket_film_shear(p, qx, qy, qz, ox, oy, oz, nx, ny, nz, near, far):
    """The film's shear force and moment (about the ball's centre) on a ball in its pocket (docs/theory/cage.md,
    "Pocket oil film"): :func:`~exudyn_bearing.physics.pocket_film.sphere_wall_shear` at the near wall (normal
    n, gap ``near``) and at the far wall (normal -n, gap ``far``; :func:`_pocket_film_gaps`), for the ball's
    velocity ``q`` and angular velocity ``o`` relative to the cage (the wall's point under the ball's centre
    moves with the cage's translation and spin). Returns the force (3), the moment (3) and the power it
    dissipates [W]."""
    eta, rb = p[P_POCKET_ETA], p[P_RB]
    f1x, f1y, f1z, m1x, m1y, m1z = _sphere_wall_shear(eta, rb, near, nx, ny, nz, qx, qy, qz, ox, oy, oz)
    f2x, f2y, f2z, m2x, m2y, m2z = _sphere_wall_shear(eta, rb, far, -nx, -ny, -nz, qx, qy, qz, ox, oy, oz)
    fx, fy, fz, mx, my, mz = f1x + f2x, f1y + f2y, f1z + f2z, m1x + m2x, m1y + m2y, m1z + m2z
    # dissipated: minus the power of the pair (ball and cage) on the relative motion
    return fx, fy, fz, mx, my, mz, -(fx * qx + fy * qy + fz * qz + mx * ox + my * oy + mz * oz)


@kernel(inline="always")
def _to_cage_frame(p, turned, v0, v1, v2):
    """The components of the world vector v in the rigid cage's bearing frame (``P_CAGE_FRAME``: B^T v); v
    itself unless ``turned`` (the frame is the identity)."""
    if not turned:
        return v0, v1, v2
    f = P_CAGE_FRAME
    return (p[f] * v0 + p[f + 3] * v1 + p[f + 6] * v2, p[f + 1] * v0 + p[f + 4] * v1 + p[f + 7] * v2,
            p[f + 2] * v0 + p[f + 5] * v1 + p[f + 8] * v2)


@kernel(inline="always")
def _from_cage_frame(p, turned, u0, u1, u2):
    """The world vector of the components u in the rigid cage's bearing frame (``P_CAGE_FRAME``: B u); u itself
    unless ``turned`` (the frame is the identity)."""
    if not turned:
        return u0, u1, u2
    f = P_CAGE_FRAME
    return (p[f] * u0 + p[f + 1] * u1 + p[f + 2] * u2, p[f + 3] * u0 + p[f + 4] * u1 + p[f + 5] * u2,
            p[f + 6] * u0 + p[f + 7] * u1 + p[f + 8] * u2)


@kernel(no_runtime=True, internal=True)
def _rigid_cage(p, xb, vb, wb, xc, vc, rings, fb, tb, fc, fr, glob, cage_load, want):
    """The rigid cage (docs/theory/cage.md): ball j in pocket j, and the cage on its land.

    The cage's centre is ``xc[0]``, its angle ``xc[1, 0]``, their rates ``vc[0]``, ``vc[1, 0]``
    (:mod:`.layout`); pocket j sits on the pitch circle at the cage angle + 2 pi j / Z (+ the unequal spacing
    P_POCKET_SPACING sin(2 pi j / Z)), at the cage's
    axial position. A ball that leaves the pocket's clearance c_p (its centre farther than c_p from the
    pocket's axis, cylindrical pockets, or from its centre, spherical) presses on the wall: Hertz with the
    constant ``P_K_POCKET``, critical damping of the reduced mass of ball and cage (backward-Euler over the
    step with ``cage_damping='implicit'``), Coulomb friction mu_c on the sliding velocity of the contact
    point, regularised below ``P_POCKET_VREG``. A land-guided cage rides on the land's film
    (:func:`~exudyn_bearing.physics.short_bearing._short_bearing_xy`, the surfaces' speeds the cage's and
    the ring's) with its shear torque; beyond the crush eccentricity the film's force stays at its value
    there and a linear contact (``P_K_LAND``) takes the rest (:func:`_land_force`). With
    ``cage_damping='implicit'`` the land's force is taken linearly implicit over the step (its stiffness and
    damping both; docs/theory/cage.md#stable-step), as the pocket damping is backward Euler. Forces and moments go to the balls
    (fb, tb), to the cage (``fc[0]`` the force, ``fc[1, 0]`` the moment about the axis times m_c / I_c, so
    that the integrators' common 1/m_c turns it into the angular acceleration) and to the guiding ring
    (fr). Returns the largest overlap of a pocket over R_b (for the runaway measure) and writes the
    dissipation of pockets and land and the elastic energy of their contacts to ``glob``.

    The cage moves in its bearing frame (``P_CAGE_FRAME``, columns e1, e2, e3 in the world, e3 the bearing
    axis; the identity in the reference engine): the balls' and rings' states and the cage's centre and
    velocity (world vectors) are taken in its components, the cage's angle is about e3 from e1, gravity
    (``P_GX`` to ``P_GZ``) is in it, and the forces and moments go back to the world (B u); the land's force
    in ``glob`` stays in the frame. With the identity they are skipped."""
    z = xb.shape[0]
    rb = p[P_RB]
    rp = p[P_RP]
    gap = p[P_POCKET_GAP]
    kp = p[P_K_POCKET]
    mu = p[P_MU_POCKET]
    vreg = p[P_POCKET_VREG]
    tau = p[P_CAGE_TAU]
    mc = p[P_MC]
    m_eff = p[P_MB] * mc / (p[P_MB] + mc)
    # the bearing frame turned off the world (in the element, an outer ring turned at t = 0): the states and forces
    # are turned; with the identity (its diagonal exactly 1: the reference engine) they are used as they are
    turned = not (p[P_CAGE_FRAME] == 1.0 and p[P_CAGE_FRAME + 4] == 1.0 and p[P_CAGE_FRAME + 8] == 1.0)
    cx, cy, cz = _to_cage_frame(p, turned, xc[0, 0], xc[0, 1], xc[0, 2])
    ux, uy, uz = _to_cage_frame(p, turned, vc[0, 0], vc[0, 1], vc[0, 2])
    wc = vc[1, 0]
    cyl = p[P_POCKET_SHAPE] < 0.5
    fcx, fcy, fcz, tcz = 0.0, 0.0, 0.0, 0.0
    pocket_power = 0.0
    stored = 0.0  # the elastic energy of the pocket and land contacts [J]
    worst = 0.0
    pitch = 2.0 * math.pi / z
    spacing = p[P_POCKET_SPACING]
    half_section = p[P_CAGE_HALF_SECTION]
    film = p[P_POCKET_FILM] > 0.5
    film_floor = p[P_POCKET_FILM_FLOOR]
    # the pockets' directions (cos, sin) of phi_j = theta + j pitch (+ spacing sin(j pitch)) by turning the cage's
    # direction (cos theta, sin theta) by the pitch's rotation pocket after pocket (equal to the direct
    # cos(phi_j), sin(phi_j) to round-off, about j ulp): four transcendental calls per evaluation instead of three
    # per pocket, which were a tenth of the rigid cage's step (python validation/studies/rigid_cage.py --profile)
    c_th, s_th = math.cos(xc[1, 0]), math.sin(xc[1, 0])
    c_p, s_p = math.cos(pitch), math.sin(pitch)
    c_j, s_j = 1.0, 0.0  # cos, sin of j pitch
    for j in range(z):
        if want:
            cage_load[j, 0] = 0.0
            cage_load[j, 1] = 0.0
        co, si = c_th * c_j - s_th * s_j, s_th * c_j + c_th * s_j
        if spacing != 0.0:  # unequal spacing: turned further by spacing sin(j pitch)
            c_s, s_s = math.cos(spacing * s_j), math.sin(spacing * s_j)
            co, si = co * c_s - si * s_s, si * c_s + co * s_s
        c_j, s_j = c_j * c_p - s_j * s_p, s_j * c_p + c_j * s_p
        # the ball's position, velocity and angular velocity in the bearing frame
        bx, by, bz = _to_cage_frame(p, turned, xb[j, 0], xb[j, 1], xb[j, 2])
        bvx, bvy, bvz = _to_cage_frame(p, turned, vb[j, 0], vb[j, 1], vb[j, 2])
        bwx, bwy, bwz = _to_cage_frame(p, turned, wb[j, 0], wb[j, 1], wb[j, 2])
        dx = bx - (cx + rp * co)
        dy = by - (cy + rp * si)
        dz = bz - cz
        dr = dx * co + dy * si  # along the pocket's (radial) axis
        if abs(dr) > half_section:  # the ball's centre is outside the cage's section: it has left its pocket
            worst = POCKET_ESCAPE
        if cyl:  # the offset from the pocket's (radial) axis
            dx -= dr * co
            dy -= dr * si
        d2 = dx * dx + dy * dy + dz * dz
        if not d2 > gap * gap:
            if d2 != d2:
                worst = d2  # a non-finite ball or cage: the engines stop on NaN
            if not (film and d2 > 0.0):
                continue
        dist = math.sqrt(d2)
        delta = dist - gap
        if delta / rb > worst:
            worst = delta / rb
        nx, ny, nz = dx / dist, dy / dist, dz / dist
        # the contact point relative to the cage's centre, and the sliding velocity of ball against pocket there
        px, py = bx + rb * nx - cx, by + rb * ny - cy
        ex, ey, ez = _cross(bwx, bwy, bwz, rb * nx, rb * ny, rb * nz)
        vrx = bvx + ex - (ux - wc * py)
        vry = bvy + ey - (uy + wc * px)
        vrz = bvz + ez - uz
        ddot = vrx * nx + vry * ny + vrz * nz
        f_el = 0.0
        f = 0.0
        if delta > 0.0:  # the ball touches the wall: Hertz with its damping
            sq = math.sqrt(delta)
            c = _damping_critical(m_eff, 1.5 * kp * sq)
            if tau > 0.0:
                c = _implicit_damping(c, m_eff, tau)
            f_el = kp * delta * sq
            f = f_el + c * ddot
            if f < 0.0:
                f = 0.0
            stored += _hertz_energy(f_el, delta)
        sx, sy, sz = vrx - ddot * nx, vry - ddot * ny, vrz - ddot * nz
        slip = math.sqrt(sx * sx + sy * sy + sz * sz)
        tx, ty, tz = 0.0, 0.0, 0.0
        if slip > 0.0 and f > 0.0:
            ft = _regularized_coulomb(slip, f, mu, vreg) / slip
            tx, ty, tz = -ft * sx, -ft * sy, -ft * sz
        # the film's shear (near wall along n, far wall along -n), as force and moment about the ball's centre
        shx = shy = shz = smx = smy = smz = sh_power = 0.0
        if film:
            # the ball centre's velocity and angular velocity relative to the cage, and the two films' gaps
            qx = bvx - (ux - wc * (by - cy))
            qy = bvy - (uy + wc * (bx - cx))
            qz = bvz - uz
            near, far = _pocket_film_gaps(p, -delta, film_floor)
            f += _pocket_film_force(p, qx, qy, qz, nx, ny, nz, sx, sy, sz, near, far, ddot, m_eff, tau)
            shx, shy, shz, smx, smy, smz, sh_power = _pocket_film_shear(p, qx, qy, qz, bwx, bwy, bwz - wc,
                                                                        nx, ny, nz, near, far)
        gx, gy, gz = tx - f * nx, ty - f * ny, tz - f * nz  # the pocket's force on the ball, at the contact point
        # the ball's force and moment in the world
        wx, wy, wz = _from_cage_frame(p, turned, gx + shx, gy + shy, gz + shz)
        fb[j, 0] += wx
        fb[j, 1] += wy
        fb[j, 2] += wz
        mx, my, mz = _cross(rb * nx, rb * ny, rb * nz, tx, ty, tz)
        wx, wy, wz = _from_cage_frame(p, turned, mx + smx, my + smy, mz + smz)
        tb[j, 0] += wx
        tb[j, 1] += wy
        tb[j, 2] += wz
        fcx -= gx + shx
        fcy -= gy + shy
        fcz -= gz + shz
        # the cage's moment about its axis: the contact force at the contact point, the shear's force at the
        # ball's centre with its moment there
        tcz -= px * gy - py * gx + (bx - cx) * shy - (by - cy) * shx + smz
        # dissipated: the normal damping's work, the friction's (minus the pair's power on the sliding) and the
        # shear's (minus its power on the ball's motion relative to the cage)
        pocket_power += (f - f_el) * ddot - (tx * vrx + ty * vry + tz * vrz) + sh_power
        if want:
            cage_load[j, 0] = abs(f)  # a net film force may point either way
            cage_load[j, 1] = math.sqrt((tx + shx) ** 2 + (ty + shy) ** 2 + (tz + shz) ** 2)
    land_power = 0.0
    flx, fly, t_sh, ecc = 0.0, 0.0, 0.0, 0.0
    if p[P_GUIDANCE] > 0.5:
        r = 0 if p[P_GUIDANCE] < 1.5 else 1
        rx, ry, _ = _to_cage_frame(p, turned, rings[r, 0], rings[r, 1], rings[r, 2])
        rvx, rvy, _ = _to_cage_frame(p, turned, rings[r, 3], rings[r, 4], rings[r, 5])
        ex, ey = cx - rx, cy - ry
        evx, evy = ux - rvx, uy - rvy
        w_r = _to_cage_frame(p, turned, rings[r, 15], rings[r, 16], rings[r, 17])[2]  # its spin about the bearing axis
        cl = p[P_LAND_C]
        eps_c = p[P_LAND_EPS]
        e = math.sqrt(ex * ex + ey * ey)
        ecc = e / cl
        flx, fly, pen = _land_force(p, ex, ey, evx, evy, wc + w_r)
        if tau > 0.0:
            # linearly implicit (Rosenbrock-Euler) over the step tau: m dv = tau F(r + tau dv, v + dv), F the
            # cage's whole force (pockets and land), linearised in the land's Jacobians in the cage's position
            # (K_r) and velocity (K_v) by differences, so the cage gets F_eff = (I - (tau / m) K_v -
            # (tau^2 / m) K_r)^-1 F (the implicit damping's C / (1 + C tau / m) for a damper,
            # k / (1 + k tau^2 / m) for a spring; F_eff = F = 0 in equilibrium), the land's share of it
            # F_eff - F_pockets
            hr = 1e-7 * cl
            hv = 1e-7 * cl * (abs(wc) + abs(w_r) + 1.0)
            a1, a2, _ = _land_force(p, ex + hr, ey, evx, evy, wc + w_r)
            b1, b2, _ = _land_force(p, ex, ey + hr, evx, evy, wc + w_r)
            c1, c2, _ = _land_force(p, ex, ey, evx + hv, evy, wc + w_r)
            d1, d2, _ = _land_force(p, ex, ey, evx, evy + hv, wc + w_r)
            g = tau / mc
            m11 = 1.0 - g * (c1 - flx) / hv - g * tau * (a1 - flx) / hr
            m12 = -g * (d1 - flx) / hv - g * tau * (b1 - flx) / hr
            m21 = -g * (c2 - fly) / hv - g * tau * (a2 - fly) / hr
            m22 = 1.0 - g * (d2 - fly) / hv - g * tau * (b2 - fly) / hr
            det = m11 * m22 - m12 * m21
            if det > 0.0:
                tx, ty = fcx + flx, fcy + fly
                flx, fly = (m22 * tx - m12 * ty) / det - fcx, (m11 * ty - m21 * tx) / det - fcy
        ee = ecc if ecc < eps_c else eps_c
        t_sh = (-2.0 * math.pi * p[P_LAND_ETA] * p[P_LAND_R] ** 3 * p[P_LAND_L] * (wc - w_r)
                / (cl * math.sqrt(1.0 - ee * ee)))
        # the ring takes -F and the moment that balances the pair's angular momentum: -T - (e x F)
        exf = ex * fly - ey * flx
        wx, wy, wz = _from_cage_frame(p, turned, flx, fly, 0.0)
        fr[r, 0] -= wx
        fr[r, 1] -= wy
        fr[r, 2] -= wz
        wx, wy, wz = _from_cage_frame(p, turned, 0.0, 0.0, t_sh + exf)
        fr[r, 3] -= wx
        fr[r, 4] -= wy
        fr[r, 5] -= wz
        # dissipated: minus the pair's power, less the rate of the land contact's elastic energy
        land_power = -(flx * evx + fly * evy) - t_sh * (wc - w_r) + exf * w_r
        if pen > 0.0:
            land_power -= pen * (ex * evx + ey * evy) / e
            stored += 0.5 * pen * (e - eps_c * cl)  # the linear land contact's k (e - eps_c c)^2 / 2
    # gravity and the unbalance's centrifugal force U omega_c^2 along the cage's angle 0 (its angular
    # acceleration's share, U omega_c', is left out), at the cage's centre; their power counts as drive
    un = p[P_UNBALANCE] * wc * wc
    gx = mc * p[P_GX] + un * math.cos(xc[1, 0])
    gy = mc * p[P_GY] + un * math.sin(xc[1, 0])
    gz = mc * p[P_GZ]
    glob[G_CAGE_LOAD_POWER] = gx * ux + gy * uy + gz * uz
    fc[0, 0], fc[0, 1], fc[0, 2] = _from_cage_frame(p, turned, fcx + flx + gx, fcy + fly + gy, fcz + gz)
    fc[1, 0] = (tcz + t_sh) * mc / p[P_IC]
    glob[G_POCKET_POWER] = pocket_power
    glob[G_LAND_POWER] = land_power
    glob[G_CONTACT_ENERGY] = stored
    if want:
        glob[G_LAND_FX] = flx
        glob[G_LAND_FY] = fly
        glob[G_LAND_ECC] = ecc
    return worst


@kernel(inline="always")
def _drive_power(rings, fr):
    """Power both rings put into the balls and cage balls [W]: minus the power
    of their forces and moments on the rings (``fr``, about the ring centres)
    at the rings' velocities and angular velocities."""
    total = 0.0
    for r in range(2):
        total -= (fr[r, 0] * rings[r, 3] + fr[r, 1] * rings[r, 4] + fr[r, 2] * rings[r, 5]
                  + fr[r, 3] * rings[r, 15] + fr[r, 4] * rings[r, 16] + fr[r, 5] * rings[r, 17])
    return total


@kernel(inline="always")
def _kinetic_energy(p, vb, wb, vc):
    """Kinetic energy of the balls (translation, rotation) and cage balls (translation), or of the rigid
    cage (translation, rotation about the axis) [J]."""
    e = 0.0
    for j in range(vb.shape[0]):
        e += 0.5 * p[P_MB] * (vb[j, 0] * vb[j, 0] + vb[j, 1] * vb[j, 1] + vb[j, 2] * vb[j, 2])
        e += 0.5 * p[P_IB] * (wb[j, 0] * wb[j, 0] + wb[j, 1] * wb[j, 1] + wb[j, 2] * wb[j, 2])
    if p[P_CAGE] > 0.5:
        for k in range(vb.shape[0]):
            e += 0.5 * p[P_MZ] * (vc[k, 0] * vc[k, 0] + vc[k, 1] * vc[k, 1] + vc[k, 2] * vc[k, 2])
    elif p[P_RIGID] > 0.5:
        e += 0.5 * p[P_MC] * (vc[0, 0] * vc[0, 0] + vc[0, 1] * vc[0, 1] + vc[0, 2] * vc[0, 2])
        e += 0.5 * p[P_IC] * vc[1, 0] * vc[1, 0]
    return e


@kernel(inline="always")
def _global_diagnostics(rings, fr, power, worst, glob):
    """Ring speeds, reactions and torques about the ring axes, frictional power, worst overlap."""
    ex, ey, ez = rings[0, 8], rings[0, 11], rings[0, 14]
    glob[G_OMEGA] = ex * rings[0, 15] + ey * rings[0, 16] + ez * rings[0, 17]
    glob[G_RING_FX] = fr[0, 0]
    glob[G_RING_FY] = fr[0, 1]
    glob[G_RING_FZ] = fr[0, 2]
    glob[G_RING_TORQUE] = ex * fr[0, 3] + ey * fr[0, 4] + ez * fr[0, 5]
    glob[G_POWER] = power
    glob[G_WORST] = worst
    ex, ey, ez = rings[1, 8], rings[1, 11], rings[1, 14]
    glob[G_OUTER_FX] = fr[1, 0]
    glob[G_OUTER_FY] = fr[1, 1]
    glob[G_OUTER_FZ] = fr[1, 2]
    glob[G_OUTER_TORQUE] = ex * fr[1, 3] + ey * fr[1, 4] + ez * fr[1, 5]


@kernel(no_runtime=True)
def forces(p, table, xb, vb, wb, xc, vc, rings, hist, hist_out, dt_hist, hz, fb, tb, fc, fr, glob, diag,
           cage_load, want, defect_path=True, ellipse_path=True, loss_path=True):
    """All contact forces of the bearing (one call; inputs and outputs in the
    module docstring). ``hist_out`` may be ``hist`` (every evaluation a
    committed step, as in the reference engine). Returns the largest
    overlap / R_b of the ball / raceway contacts (NaN for a non-finite ball), or
    the largest overlap of a cage contact over its sphere's radius (ball /
    cage-ball and guide: R_z; ball / ball: R_b) when that exceeds the runaway
    limit ``P_MAX_OVERLAP`` or is NaN (a non-finite cage ball): the engines stop
    on either.

    ``defect_path``, ``ellipse_path`` and ``loss_path`` choose what is
    compiled: None leaves the defect code (:func:`_defect_drop`,
    :func:`_turn_ball_frame`), the ellipse traction (:func:`_ellipse_traction`
    and the traction models) or the rolling resistance and ball drag
    (:func:`_rolling_resistance`, :func:`_ball_drag`) out of this
    specialisation (numba prunes the branches on ``is None`` before typing),
    which shortens a cold start of a scene without them (:func:`scene_paths`,
    :func:`scene_loss_path`); the defaults compile all. A scene that needs a
    path left out returns NaN (the engines stop on a non-finite state)."""
    z = xb.shape[0]
    # the outputs zeroed element by element: stores the compiler keeps inline, where the whole-array
    # assignments were calls of the C library's memset
    for k in range(6):
        fr[0, k] = 0.0
        fr[1, k] = 0.0
    for j in range(z):
        for k in range(3):
            fb[j, k] = 0.0
            tb[j, k] = 0.0
            fc[j, k] = 0.0
    power_sum = 0.0
    damp_sum = 0.0
    worst = 0.0
    defects = p[P_NDEF] > 0.0
    if defect_path is None:
        if defects:
            return np.nan  # compiled without the defect code
    if ellipse_path is None:
        if p[P_TRACTION_LEVEL] > 0.5:
            return np.nan  # compiled without the ellipse traction
    if loss_path is None:
        if p[P_ROLLRES] > 0.5 or p[P_DRAG] > 0.5:
            return np.nan  # compiled without the rolling resistance and ball drag
    ehl_sum = 0.0
    hyst_sum = 0.0
    drag_sum = 0.0
    stored_sum = 0.0  # the elastic energy of the contacts [J]
    power_inner = 0.0  # the inner race's part of power_sum
    ln_g = math.log(p[P_XI] * p[P_EPRIME]) if p[P_LUB] > 0.5 else 0.0  # the film's ln G, a scene constant
    if hz.shape[2] < HZ_N:
        return np.nan  # a cache without the geometry columns (the callers allocate HZ_N)
    # the geometry of every ball / raceway contact first: independent chains of square roots and
    # divisions, which the processor overlaps in this short loop
    for j in range(z):
        for race in range(2):
            (dxw, dyw, dzw, cx, cy, rotated, delta, nlx, nly, nlz, ca, sa,
             r_contact) = _race_geometry(p, rings, xb, j, race)
            g = HZ_GEO
            hz[j, race, g] = dxw
            hz[j, race, g + 1] = dyw
            hz[j, race, g + 2] = dzw
            hz[j, race, g + 3] = cx
            hz[j, race, g + 4] = cy
            hz[j, race, g + 5] = 1.0 if rotated else 0.0
            hz[j, race, g + 6] = delta
            hz[j, race, g + 7] = nlx
            hz[j, race, g + 8] = nly
            hz[j, race, g + 9] = nlz
            hz[j, race, g + 10] = ca
            hz[j, race, g + 11] = sa
            hz[j, race, g + 12] = r_contact
    for j in range(z):
        if defect_path is not None:
            if defects:
                _turn_ball_frame(p, hist, hist_out, dt_hist, wb, j)
        for race in range(2):
            ratio, power, damp, p_ehl, p_hyst, stored = _race_contact(j, race, p, table, xb, vb, wb, rings, hist, hist_out,
                                                              dt_hist, hz, fb, tb, fr, diag, want, ln_g, defect_path,
                                                              ellipse_path, loss_path)
            if ratio > worst or ratio != ratio:  # a NaN state is the worst: the engines stop on it
                worst = ratio
            power_sum += power
            if race == 0:
                power_inner += power
            damp_sum += damp
            ehl_sum += p_ehl
            hyst_sum += p_hyst
            stored_sum += stored
    if p[P_RIGID] > 0.5:  # the rigid cage: pockets and land
        ratio = _rigid_cage(p, xb, vb, wb, xc, vc, rings, fb, tb, fc, fr, glob, cage_load, want)
        if ratio > p[P_MAX_OVERLAP] or ratio != ratio:
            worst = ratio
        stored_sum += glob[G_CONTACT_ENERGY]
    else:
        # ball / cage-ball contacts (two per cage ball) or, without cage, ball / ball
        cage = p[P_CAGE] > 0.5
        if cage:
            px_, pv_, pf_ = xc, vc, fc
            r_sum = p[P_RB] + p[P_RZ]
            k_pair = p[P_K_BZ]
            m_pair = p[P_MB] * p[P_MZ] / (p[P_MB] + p[P_MZ])
            n_pair = 2
            tau = p[P_CAGE_TAU]
            r_ref = p[P_RZ]  # both contacts of a cage ball: their overlap over its radius
        else:
            px_, pv_, pf_ = xb, vb, fb
            r_sum = 2.0 * p[P_RB]
            k_pair = p[P_K_BB]
            m_pair = 0.5 * p[P_MB]
            n_pair = 1
            tau = 0.0  # the ball / ball contacts of a scene without cage: explicit
            r_ref = p[P_RB]
        cage_overlap = 0.0  # the largest overlap of the cage (or ball / ball) contacts [m]
        for k in range(z):
            k2 = k + 1 if k + 1 < z else 0
            for m in range(n_pair):
                ia = k if m == 0 else k2          # ball
                ib = k if cage else k2            # cage ball k, or the next ball
                f, damp, overlap, stored = _pair_contact(ia, ib, xb, vb, fb, px_, pv_, pf_, r_sum, k_pair, m_pair,
                                                         tau)
                damp_sum += damp
                stored_sum += stored
                if overlap > cage_overlap:
                    cage_overlap = overlap
                if want:
                    cage_load[k, m] = f
            if want and not cage:
                cage_load[k, 1] = 0.0
            if cage:
                damp, overlap, stored = _guide_contact(k, p, xc, vc, rings, fc, fr)
                damp_sum += damp
                stored_sum += stored
                if overlap > cage_overlap or overlap != overlap:  # NaN: a non-finite cage ball (stays the worst)
                    cage_overlap = overlap
        # a runaway (or non-finite) cage contact stops the engines like a ball contact
        if cage_overlap > p[P_MAX_OVERLAP] * r_ref or cage_overlap != cage_overlap:
            worst = cage_overlap / r_ref
    if loss_path is not None:  # pruned at compile time when None
        if p[P_DRAG] > 0.5:
            drag_sum = _ball_drag(p, xb, vb, rings, fb, fr)
    # the powers at every evaluation (the engines integrate them into drive_work and dissipated_work)
    glob[G_EHL_POWER] = ehl_sum
    glob[G_HYST_POWER] = hyst_sum
    glob[G_DRAG_POWER] = drag_sum
    glob[G_POWER] = power_sum
    glob[G_POWER_INNER] = power_inner
    glob[G_DAMP_POWER] = damp_sum
    glob[G_DRIVE_POWER] = _drive_power(rings, fr)
    if p[P_RIGID] > 0.5:
        glob[G_DRIVE_POWER] += glob[G_CAGE_LOAD_POWER]
    if want:
        _global_diagnostics(rings, fr, power_sum, worst, glob)
        glob[G_KINETIC] = _kinetic_energy(p, vb, wb, vc)
    glob[G_CONTACT_ENERGY] = stored_sum
    return worst


def scene_paths(p):
    """(defect_path, ellipse_path) of :func:`forces` for the parameter vector
    ``p`` of a scene: True where the scene uses the path, None where it does
    not (that code is then not compiled)."""
    return (True if p[P_NDEF] > 0.0 else None), (True if p[P_TRACTION_LEVEL] > 0.5 else None)


def scene_loss_path(p):
    """``loss_path`` of :func:`forces` for the parameter vector ``p``: True when the scene switches the
    rolling resistance or the ball drag on, None when not (that code is then not compiled)."""
    return True if (p[P_ROLLRES] > 0.5 or p[P_DRAG] > 0.5) else None


@kernel(inline="always")
def accumulate_energy(glob, dt):
    """Add the powers of the last evaluation over ``dt`` to the run's
    drive_work and dissipated_work (``glob``, kept by the engine for the whole run): friction,
    normal damping, rolling resistance, ball drag and the rigid cage's pockets and land."""
    glob[G_DRIVE_WORK] += glob[G_DRIVE_POWER] * dt
    glob[G_DISS_WORK] += (glob[G_POWER] + glob[G_DAMP_POWER]) * dt
    glob[G_DISS_WORK] += (glob[G_EHL_POWER] + glob[G_HYST_POWER] + glob[G_DRAG_POWER]) * dt
    glob[G_DISS_WORK] += (glob[G_POCKET_POWER] + glob[G_LAND_POWER]) * dt
    # the same by component (their sum is the dissipated work)
    glob[G_W_TRACTION_INNER] += glob[G_POWER_INNER] * dt
    glob[G_W_TRACTION_OUTER] += (glob[G_POWER] - glob[G_POWER_INNER]) * dt
    glob[G_W_DAMPING] += glob[G_DAMP_POWER] * dt
    glob[G_W_EHL] += glob[G_EHL_POWER] * dt
    glob[G_W_HYST] += glob[G_HYST_POWER] * dt
    glob[G_W_DRAG] += glob[G_DRAG_POWER] * dt
    glob[G_W_POCKET] += glob[G_POCKET_POWER] * dt
    glob[G_W_LAND] += glob[G_LAND_POWER] * dt
