"""Initial state of a bearing scene, shared by the reference engine and the
Exudyn element: balls at the quasi-static loaded positions, the inner ring at
its static displacement, and the ring mass the reference engine translates."""
from __future__ import annotations

import math

import numpy as np

from ..data import BallBearing, InputError
from ..physics import kinematics
from ..physics.load_distribution import static_equilibrium
from .contact import HZ_N
from .layout import H_E1, H_E2, HIST_N
from .operating_geometry import start_geometry
from .scenario import resolve_cage

__all__ = ["initial_state", "initial_history", "ring_mass_estimate", "rigid_cage_state", "state_from_ball_kinematics"]


def ring_mass_estimate(bearing: BallBearing) -> float:
    """Approximate inner-ring mass [kg]: an annulus from R_i - 0.65 R_b to R_i,
    2.9 R_b wide (proportions of a 62xx ring).

    >>> from exudyn_bearing import catalog
    >>> round(1e3 * ring_mass_estimate(catalog["6208"]))  # g
    81
    """
    ri, rb = bearing.inner_race_radius, bearing.ball_radius
    return bearing.material.density * math.pi * (ri ** 2 - (ri - 0.65 * rb) ** 2) * 2.9 * rb


def initial_state(bearing: BallBearing, scenario, start: dict | None = None) -> dict:
    """Balls at the quasi-static loaded positions (the analytic solution),
    ring at its static displacement; with ``initial='analytic'`` balls and
    cage balls at their kinematic (pure-rolling) speeds, else at rest.

    ``start``: a state of :func:`state_from_ball_kinematics` (from the
    quasi-static solver, ``initial='quasistatic'``) used instead (copied)."""
    b, s = bearing, resolve_cage(scenario, bearing)
    if start is not None:
        state = {k: (np.array(v, float) if isinstance(v, np.ndarray) else v) for k, v in start.items()}
        return rigid_cage_state(state) if s.cage == "rigid" else state
    if s.initial == "quasistatic":
        raise InputError("initial: the quasi-static start needs the quasi-static solution; exudyn_bearing.simulate "
                         "and CreateBallBearing compute it, the engines take it as start=")
    z = b.n_balls
    w0, w0_o = s.omega_at(0.0), s.omega_outer_at(0.0)
    # the grooves as the run sees them at t = 0 (grown with the rings' speeds), so that the start has
    # no extra overlap to shed; the balls placed in the grown outer groove
    g = start_geometry(b, s)
    sol = static_equilibrium(g, s.Fr, s.Fa, hertz_method=s.hertz)
    rho_o, z_o = g.outer_groove_center
    a0 = b.free_contact_angle
    xb = np.zeros((z, 3))
    for j in range(z):
        if sol.q[j] > 0.0:
            al = sol.contact_angle[j]
            d = b.outer_groove_radius - b.ball_radius + sol.overlap_outer[j]
        else:
            al = a0
            d = b.outer_groove_radius - b.ball_radius
        r = rho_o + d * math.cos(al)
        xb[j] = (r * math.cos(sol.psi[j]), r * math.sin(sol.psi[j]), z_o + d * math.sin(al))
    psi_c = sol.psi + math.pi / z
    xc = np.stack([b.pitch_radius * np.cos(psi_c), b.pitch_radius * np.sin(psi_c), np.zeros(z)], axis=1)
    vb = np.zeros((z, 3))
    wb = np.zeros((z, 3))
    vc = np.zeros((z, 3))
    ring = np.zeros(6)
    ring[:3] = sol.displacement
    if s.initial == "analytic" and (w0 != 0.0 or w0_o != 0.0):
        wc = float(kinematics.cage_speed(w0, w0_o, b.ball_radius, b.pitch_radius, a0))
        wr = float(kinematics.ball_spin_relative(w0, w0_o, b.ball_radius, b.pitch_radius, a0))
        for j in range(z):
            vb[j] = (-wc * xb[j, 1], wc * xb[j, 0], 0.0)
            c, sn = math.cos(sol.psi[j]), math.sin(sol.psi[j])
            # rolling axis perpendicular to the contact line: (-sin a) e_r + cos a e_z
            wb[j] = (-wr * math.sin(a0) * c, -wr * math.sin(a0) * sn, wr * math.cos(a0) + wc)
        vc[:, 0] = -wc * xc[:, 1]
        vc[:, 1] = wc * xc[:, 0]
    state = {"xb": xb, "vb": vb, "wb": wb, "xc": xc, "vc": vc, "ring": ring,
             "hist": initial_history(z), "hz": np.zeros((z, 2, HZ_N)), "static": sol,
             "max_overlap": float(np.max(sol.overlap_outer))}
    return rigid_cage_state(state) if s.cage == "rigid" else state


def rigid_cage_state(state: dict) -> dict:
    """``state`` with the rigid cage in the cage rows (layout of :mod:`.layout`): centred on the bearing
    axis at the balls' mean axial position, its pocket j at ball j (the circular mean of psi_j - 2 pi j/Z),
    turning at the balls' mean orbital speed."""
    xb, vb = state["xb"], state["vb"]
    z = xb.shape[0]
    psi = np.arctan2(xb[:, 1], xb[:, 0])
    lag = psi - 2.0 * math.pi * np.arange(z) / z
    theta = math.atan2(float(np.mean(np.sin(lag))), float(np.mean(np.cos(lag))))
    r2 = xb[:, 0] ** 2 + xb[:, 1] ** 2
    orbit = (xb[:, 0] * vb[:, 1] - xb[:, 1] * vb[:, 0]) / r2
    xc, vc = np.zeros((z, 3)), np.zeros((z, 3))
    xc[0, 2] = float(np.mean(xb[:, 2]))
    xc[1, 0] = theta
    vc[1, 0] = float(np.mean(orbit))
    return {**state, "xc": xc, "vc": vc}


def state_from_ball_kinematics(bearing: BallBearing, psi, center_r, center_z, orbital_speed, w_r, w_z,
                               ring_displacement, static=None, max_overlap=0.0, w_psi=0.0) -> dict:
    """Initial state (the format of :func:`initial_state`) from a steady ball
    motion given per ball: azimuth psi [rad], centre (r, z) in its radial
    plane [m], orbital speed omega_m [rad/s] and angular velocity (w_r, w_z)
    in the frame orbiting with it [rad/s] (the quasi-static solver's
    kinematics), its yaw w_psi about the orbit direction [rad/s]; the inner ring at ``ring_displacement`` (x, y, z)
    [m]. Cage balls, if any, sit midway between neighbouring balls on the
    pitch circle, orbiting at the balls' mean orbital speed. ``max_overlap``:
    the largest ball / race overlap of the state [m] (the Exudyn element
    checks the ring placement against it)."""
    b = bearing
    z = b.n_balls
    psi = np.asarray(psi, float)
    if psi.shape != (z,):
        raise ValueError(f"psi: expected {z} ball azimuths, got shape {psi.shape}")
    c, s = np.cos(psi), np.sin(psi)
    cr, cz = np.asarray(center_r, float), np.asarray(center_z, float)
    wm, wr, wz = (np.asarray(x, float) for x in (orbital_speed, w_r, w_z))
    xb = np.stack([cr * c, cr * s, cz], axis=1)
    vb = np.stack([-wm * xb[:, 1], wm * xb[:, 0], np.zeros(z)], axis=1)
    wp = np.broadcast_to(np.asarray(w_psi, float), (z,))
    wb = np.stack([wr * c - wp * s, wr * s + wp * c, wz + wm], axis=1)
    # cage ball k between balls k and k+1 (their azimuths unwrapped)
    gap = np.mod(np.roll(psi, -1) - psi, 2.0 * math.pi)
    psi_c = psi + 0.5 * gap
    xc = np.stack([b.pitch_radius * np.cos(psi_c), b.pitch_radius * np.sin(psi_c), np.zeros(z)], axis=1)
    w_mean = float(np.mean(wm))
    vc = np.stack([-w_mean * xc[:, 1], w_mean * xc[:, 0], np.zeros(z)], axis=1)
    ring = np.zeros(6)
    ring[:3] = np.asarray(ring_displacement, float)[:3]
    return {"xb": xb, "vb": vb, "wb": wb, "xc": xc, "vc": vc, "ring": ring,
            "hist": initial_history(z), "hz": np.zeros((z, 2, HZ_N)), "static": static,
            "max_overlap": float(max_overlap)}


def initial_history(z: int, axes=None) -> np.ndarray:
    """Contact history (Z, HIST_N, 3) at t = 0 (layout ``H_*``): tangential
    springs relaxed, every ball's body frame e1, e2 along the first two
    columns of ``axes`` (the outer ring's rotation matrix; default the
    identity: x and y of the outer-ring frame)."""
    hist = np.zeros((z, HIST_N, 3))
    a = np.eye(3) if axes is None else np.asarray(axes, float)
    hist[:, H_E1] = a[:, 0]
    hist[:, H_E2] = a[:, 1]
    return hist
