"""Analyses without time integration: bearing data sheet and quasi-static
load distribution with a lubrication map.

These compose the physics functions and add none of their own (as pvlib's
ModelChain): every relation used here lives in :mod:`exudyn_bearing.physics`.
"""
from __future__ import annotations

import math

import numpy as np

from ..data import BallBearing, InputError, Lubricant, default_lubricant, load_bearing
from ..model.load_range import check_load_range
from ..physics import damping, ehl, friction, hertz, kinematics
from ..physics.geometry import raceway_radii
from ..physics.load_distribution import (StaticSolution, race_stiffness, static_equilibrium,
                                        stribeck_solution)

__all__ = ["bearing_info", "lubrication_map", "static_analysis", "stribeck_and_lubrication"]


def _check_speed(name, value):
    v = float(value)
    if not math.isfinite(v):
        raise InputError(f"{name}: must be finite, got {v}")
    return v


def bearing_info(bearing: BallBearing | str, omega=None, hertz_method="exact", omega_outer=0.0) -> dict:
    """Geometry, derived values, Hertz constants and (at speed) kinematics.

    Parameters
    ----------
    bearing : BallBearing or str
        Geometry (catalogue name or JSON file, :func:`~exudyn_bearing.data.load_bearing`).
    omega : float, optional
        Inner-ring speed [rad/s]; with it the kinematics.
    omega_outer : float
        Outer-ring speed [rad/s] of the kinematics (default 0: fixed).
    hertz_method : str
        Hertz fidelity level for ``K_inner``, ``K_outer``.

    Returns
    -------
    dict
        Geometry [m], ``K_inner``, ``K_outer``, ``K_n`` [N/m^1.5],
        ``kappa_inner``, ``kappa_outer`` [-] at the free contact angle and,
        with ``omega``, ``cage_speed``, ``ball_spin`` [rad/s] (absolute),
        ``ball_spin_relative`` [rad/s], ``rolling_speed`` [m/s] and ``ftf``,
        ``bpfo``, ``bpfi``, ``bsf`` [Hz].
    """
    b = load_bearing(bearing)
    alpha = b.free_contact_angle
    ki, ko, kn = race_stiffness(b, alpha, hertz_method)
    ca = math.cos(alpha)
    rxi, ryi = raceway_radii(b.ball_radius, b.inner_groove_radius, b.pitch_radius - b.ball_radius * ca,
                             alpha, True)
    rxo, ryo = raceway_radii(b.ball_radius, b.outer_groove_radius, b.pitch_radius + b.ball_radius * ca,
                             alpha, False)
    kap_i = hertz.ellipticity(rxi, ryi, hertz_method)[0]
    kap_o = hertz.ellipticity(rxo, ryo, hertz_method)[0]
    info = {
        "name": b.name,
        "n_balls": b.n_balls,
        "ball_radius": b.ball_radius,
        "inner_race_radius": b.inner_race_radius,
        "outer_race_radius": b.outer_race_radius,
        "inner_groove_radius": b.inner_groove_radius,
        "outer_groove_radius": b.outer_groove_radius,
        "cage_ball_radius": b.cage_ball_radius,
        "pitch_radius": b.pitch_radius,
        "diametral_clearance": b.diametral_clearance,
        "inner_conformity": b.inner_conformity,
        "outer_conformity": b.outer_conformity,
        "conformity_sum": b.conformity_sum,
        "free_contact_angle_deg": math.degrees(alpha),
        "cage_pocket_clearance": b.cage_pocket_clearance,
        "ball_mass": b.ball_mass,
        "e_prime": hertz.material_reduced_modulus(b.material),
        "hertz_method": hertz_method,
        "R_x_inner": float(rxi), "R_y_inner": float(ryi),
        "R_x_outer": float(rxo), "R_y_outer": float(ryo),
        "K_inner": ki,
        "K_outer": ko,
        "K_n": kn,
        "kappa_inner": float(kap_i),
        "kappa_outer": float(kap_o),
        "source": b.source,
    }
    if omega is not None:
        w = _check_speed("omega", omega)
        w_o = _check_speed("omega_outer", omega_outer)
        args = (w, w_o, b.ball_radius, b.pitch_radius, alpha)
        u_i, _u_o = kinematics.rolling_speeds(*args)
        info.update({
            "omega": w,
            "omega_outer": w_o,
            "cage_speed": float(kinematics.cage_speed(*args)),
            "ball_spin": float(kinematics.ball_spin_absolute(*args)),
            "ball_spin_relative": float(kinematics.ball_spin_relative(*args)),
            "rolling_speed": float(u_i),
        })
        info.update(kinematics.defect_frequencies(w, w_o, b.n_balls, b.ball_radius, b.pitch_radius, alpha))
    return info


def lubrication_map(solution: StaticSolution, omega_inner: float, omega_outer: float = 0.0,
                    lubricant: Lubricant | None = None, film: str = "hd") -> dict:
    """h_min, Lambda, regime, mu and the Hertz ellipse of every contact.

    Pure-rolling speeds of :func:`~exudyn_bearing.physics.kinematics.rolling_speeds`
    at each ball's contact angle, the ball loads of a quasi-static solution,
    Hertz at the solution's fidelity level, film model ``film`` ('hd' or 'mk').
    No time integration (docs/theory/lubrication.md).

    Returns
    -------
    dict of ndarray (one entry per ball) with keys ``{name}_inner`` and
    ``{name}_outer`` for name in u_r [m/s], r_x [m], kappa [-], a, b [m],
    p_max [Pa], h_min [m], lambda [-], regime (0 boundary, 1 mixed,
    2 full film, -1 no contact), mu [-]. Unloaded contacts have NaN film
    values.
    """
    b = solution.bearing
    lub = default_lubricant(b) if lubricant is None else lubricant
    wi = _check_speed("omega", omega_inner)
    wo = _check_speed("omega_outer", omega_outer)
    film_code = ehl.film_model_code(film)
    em = hertz.material_reduced_modulus(b.material)
    alpha = solution.contact_angle
    ca = np.cos(alpha)
    u_in, u_out = kinematics.rolling_speeds(wi, wo, b.ball_radius, b.pitch_radius, alpha)
    out = {}
    for race, r_c, u, inner in (("inner", b.inner_groove_radius, u_in, True),
                                ("outer", b.outer_groove_radius, u_out, False)):
        r_contact = b.pitch_radius + (-1.0 if inner else 1.0) * b.ball_radius * ca
        rx, ry = raceway_radii(b.ball_radius, r_c, r_contact, alpha, inner)
        hc = hertz.hertz_contact(rx, ry, em, load=solution.q, method=solution.hertz_method)
        loaded = solution.q > 0.0
        h = ehl.film_thickness(u, solution.q, rx, hc.kappa, em, lub.viscosity,
                               lub.pressure_viscosity, film_code)
        lam = ehl.film_parameter(h, lub.composite_roughness)
        regime = damping.lubrication_regime(lam, lub.lambda_mixed, lub.lambda_full_film)
        mu = friction.friction_coefficient(lam, lub.mu_boundary, lub.mu_full_film,
                                           lub.lambda_mixed, lub.lambda_full_film)
        nan = np.full(loaded.shape, np.nan)
        out.update({
            f"u_r_{race}": np.broadcast_to(u, loaded.shape).astype(float),
            f"r_x_{race}": np.asarray(rx, float),
            f"kappa_{race}": np.asarray(hc.kappa, float),
            f"a_{race}": np.asarray(hc.a, float),
            f"b_{race}": np.asarray(hc.b, float),
            f"p_max_{race}": np.asarray(hc.p_max, float),
            f"h_min_{race}": np.where(loaded, h, nan),
            f"lambda_{race}": np.where(loaded, lam, nan),
            f"regime_{race}": np.where(loaded, regime, -1).astype(int),
            f"mu_{race}": np.where(loaded, mu, nan),
        })
    return out


def static_analysis(bearing: BallBearing | str, radial_load: float, axial_load: float = 0.0,
                    omega: float | None = None, film: str = "hd",
                    lubricant: Lubricant | None = None, hertz_method: str = "exact",
                    phase: float = 0.0, moment=(0.0, 0.0)) -> dict:
    """Quasi-static load distribution of a translating inner ring, and with ``omega`` the lubrication map.

    The inner ring translates only: its tilt is held at zero (the classical
    Harris distribution of :func:`~exudyn_bearing.physics.load_distribution.static_equilibrium`,
    as in the DEM engines) and the moment this takes is returned as
    ``reaction_moment`` [N m]. For a free tilt, moment loads and speed
    effects use :func:`exudyn_bearing.solvers.quasistatic.solve_quasistatic`
    (the ``static`` and ``quasistatic`` commands); a nonzero ``moment``
    here is refused.

    ``bearing``: a BallBearing, catalogue name or JSON file. ``phase``
    (azimuth of ball 0) is taken modulo 2 pi. Loads whose contact
    pressure exceeds the elastic range (:mod:`exudyn_bearing.model.load_range`)
    raise InputError.

    Returns a dict with ``phase`` [rad], ``psi`` [rad], ``q`` [N], ``q_max`` [N],
    ``overlap`` [m], ``contact_angle`` [rad] (per ball), ``delta_r``,
    ``delta_a`` [m], ``eps`` [-], the continuous Stribeck ``q_max_stribeck``
    and ``eps_stribeck``, and with ``omega`` the per-ball keys
    ``h_min_inner``, ``h_min_outer`` [m], ``lambda_inner``, ``lambda_outer``
    and the rest of :func:`lubrication_map`.
    """
    bearing = load_bearing(bearing)  # a BallBearing, catalogue name or JSON file
    mx, my = (float(v) for v in moment)
    if mx != 0.0 or my != 0.0:
        raise InputError("moment: static_analysis holds the inner ring's tilt at zero (translation-only "
                         "distribution); moment loads need the free tilt of "
                         "exudyn_bearing.solve_quasistatic(..., Mx=..., My=..., fixed={})")
    phase = float(phase)
    if not math.isfinite(phase):
        raise InputError(f"phase: must be finite, got {phase}")
    phase = math.remainder(phase, 2.0 * math.pi)  # the same balls; a huge phase loses their spacing in cos/sin
    sol = check_load_range(bearing, radial_load, axial_load, hertz_method, phase=phase,
                           names=("radial_load", "axial_load", "diametral_clearance"))
    if sol is None:  # unloaded, with clearance
        sol = static_equilibrium(bearing, radial_load, axial_load, phase=phase, hertz_method=hertz_method)
    res = {
        "bearing": bearing.name,
        "Fr": sol.radial_load,
        "Fa": sol.axial_load,
        "Pd": bearing.diametral_clearance,
        "hertz_method": sol.hertz_method,
        "phase": phase,
        "psi": sol.psi,
        "q": sol.q,
        "q_max": sol.q_max,
        "overlap": sol.overlap,
        "overlap_inner": sol.overlap_inner,
        "overlap_outer": sol.overlap_outer,
        "contact_angle": sol.contact_angle,
        "displacement": sol.displacement,
        "delta_r": sol.delta_r,
        "delta_a": sol.delta_a,
        "eps": sol.eps,
        "tilt": "held at zero",
        "reaction_moment": sol.reaction_moment,
    }
    res.update(stribeck_and_lubrication(sol, omega, film, lubricant))
    return res


def stribeck_and_lubrication(sol: StaticSolution, omega: float | None = None, film: str = "hd",
                             lubricant: Lubricant | None = None, stribeck: bool = True) -> dict:
    """The keys a static result adds to its load distribution ``sol``: the
    continuous Stribeck ``q_max_stribeck`` [N] and ``eps_stribeck`` [-] of
    the same loads (where the loads are nonzero, ``stribeck`` is on and the
    continuous solution exists), and with ``omega`` [rad/s] the keys
    ``omega``, ``film`` and those of :func:`lubrication_map`."""
    res = {}
    b = sol.bearing
    if stribeck and (sol.radial_load > 0.0 or sol.axial_load > 0.0):
        try:
            st = stribeck_solution(b.n_balls, sol.radial_load, sol.axial_load, b.free_contact_angle,
                                   eps=sol.eps if sol.axial_load == 0.0 and math.isfinite(sol.eps) else None)
            res["q_max_stribeck"] = st.q_max
            res["eps_stribeck"] = st.eps
        except InputError:
            pass
    if omega is not None:
        res["omega"] = float(omega)
        res["film"] = film
        res.update(lubrication_map(sol, omega, 0.0, lubricant, film))
    return res
