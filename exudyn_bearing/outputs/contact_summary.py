"""Contact kinematics of a run in the quasi-static solver's terms: operating
contact angles, the spin-axis angle beta, spin-to-roll ratios, frictional
dissipation per race, and the kinematic reference speeds at the operating
contact angles (the keys of ``quasistatic --json`` where they mean the same).
"""
from __future__ import annotations

import numpy as np

from ..model.layout import D_ANGLE, D_LOAD, D_POWER, D_ROLL, D_SPIN
from ..physics import kinematics

__all__ = ["contact_summary", "CONTACT_SUMMARY_UNITS", "spin_axis_angles"]

#: Units of the keys of :func:`contact_summary`.
CONTACT_SUMMARY_UNITS = {
    "alpha_inner": "deg (mean over loaded contacts)", "alpha_outer": "deg (mean over loaded contacts)",
    "beta": "deg (mean over balls: spin axis to the bearing axis, in the frame orbiting with the ball)",
    "spin_roll_inner": "- (mean over loaded contacts)", "spin_roll_outer": "- (mean over loaded contacts)",
    "dissipation_inner": "W (whole bearing, time mean)", "dissipation_outer": "W (whole bearing, time mean)",
    "kinematic_cage_speed": "rad/s (pure rolling at the mean operating contact angle)",
    "kinematic_ball_spin": "rad/s (pure rolling at the mean operating contact angle)",
}


def spin_axis_angles(data) -> np.ndarray:
    """beta (n, Z) [rad]: angle of each ball's spin axis to the bearing axis in
    the frame orbiting with the ball, w = omega_ball - omega_m e_z, beta =
    atan2(-sigma w_r, sigma w_z), sigma = sign(w_z) (the quasi-static
    solver's definition, :func:`exudyn_bearing.solvers.quasistatic.kinematics.spin_axis_angle`)."""
    xb, vb, wb = data["xb"], data["vb"], data["wb"]
    r2 = xb[..., 0] ** 2 + xb[..., 1] ** 2
    wm = (xb[..., 0] * vb[..., 1] - xb[..., 1] * vb[..., 0]) / r2
    r = np.sqrt(r2)
    w_r = (wb[..., 0] * xb[..., 0] + wb[..., 1] * xb[..., 1]) / r
    w_z = wb[..., 2] - wm
    sigma = np.where(w_z < 0.0, -1.0, 1.0)
    return np.arctan2(-sigma * w_r, sigma * w_z)


def contact_summary(data, window: slice, omega: float, bearing, omega_outer: float = 0.0) -> dict:
    """Contact kinematics over the samples ``window`` of a run's arrays (keys
    and units in :data:`CONTACT_SUMMARY_UNITS`); ``omega``, ``omega_outer`` the inner- and outer-ring
    speeds [rad/s] for the kinematic references (:mod:`exudyn_bearing.physics.kinematics`). Unloaded contacts are left
    out of the means; a quantity with no loaded contact is None."""
    diag = data["diag"][window]
    loaded = diag[..., D_LOAD] > 0.0
    out = {}

    def mean(x, sel):
        return float(np.mean(x[sel])) if np.any(sel) else None

    for race, tag in ((0, "inner"), (1, "outer")):
        sel = loaded[:, :, race]
        ang = diag[:, :, race, D_ANGLE]
        roll = diag[:, :, race, D_ROLL]
        spin = diag[:, :, race, D_SPIN]
        a = mean(ang, sel)
        out[f"alpha_{tag}"] = None if a is None else float(np.degrees(a))
        ok = sel & (np.abs(roll) > 0.0)
        out[f"spin_roll_{tag}"] = mean(spin / np.where(ok, np.abs(roll), 1.0), ok)
        out[f"dissipation_{tag}"] = float(np.mean(np.sum(diag[:, :, race, D_POWER], axis=1))) if len(diag) else None
    beta = spin_axis_angles({k: data[k][window] for k in ("xb", "vb", "wb")})
    out["beta"] = float(np.degrees(np.mean(beta))) if beta.size else None
    angles = [out[k] for k in ("alpha_inner", "alpha_outer") if out[k] is not None]
    alpha = np.radians(np.mean(angles)) if angles else bearing.free_contact_angle
    out["kinematic_cage_speed"] = float(kinematics.cage_speed(omega, omega_outer, bearing.ball_radius, bearing.pitch_radius,
                                                              alpha))
    out["kinematic_ball_spin"] = float(kinematics.ball_spin_absolute(omega, omega_outer, bearing.ball_radius,
                                                                     bearing.pitch_radius, alpha))
    return out
