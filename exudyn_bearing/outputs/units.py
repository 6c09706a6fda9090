"""Units of the JSON outputs of the analyses (SI; angular speeds in rad/s,
frequencies in Hz) and the names of the lubrication-regime codes."""
from __future__ import annotations

from ..model.layout import DIAG_UNITS
from ..physics.damping import REGIME_NAMES

__all__ = ["INFO_UNITS", "STATIC_UNITS", "REGIME_CODES", "with_units"]

_LENGTHS = ("ball_radius", "inner_race_radius", "outer_race_radius", "inner_groove_radius", "outer_groove_radius",
            "cage_ball_radius", "pitch_radius", "diametral_clearance", "cage_pocket_clearance", "R_x_inner",
            "R_y_inner", "R_x_outer", "R_y_outer")

#: Units of :func:`exudyn_bearing.solvers.analytic.bearing_info` (angular speeds
#: in rad/s, the defect frequencies ftf, bpfo, bpfi, bsf in Hz).
INFO_UNITS = dict({k: "m" for k in _LENGTHS}, n_balls="-", inner_conformity="-", outer_conformity="-",
                  conformity_sum="-", free_contact_angle_deg="deg", ball_mass="kg", e_prime="Pa",
                  K_inner="N/m^1.5", K_outer="N/m^1.5", K_n="N/m^1.5", kappa_inner="-", kappa_outer="-",
                  omega="rad/s", omega_outer="rad/s", cage_speed="rad/s", ball_spin="rad/s", ball_spin_relative="rad/s",
                  rolling_speed="m/s", ftf="Hz", bpfo="Hz", bpfi="Hz", bsf="Hz")

#: Regime codes of the per-contact arrays and their names (-1: unloaded contact).
REGIME_CODES = {"-1": "no contact", **{str(code): name for code, name in enumerate(REGIME_NAMES)}}

#: Units of :func:`exudyn_bearing.solvers.analytic.static_analysis` (per-ball
#: arrays share the unit of their key).
STATIC_UNITS = dict(
    Fr="N", Fa="N", Mx="N m", My="N m", Pd="m", phase="rad", psi="rad", tilt_x="rad", tilt_y="rad",
    reaction_moment="N m", q="N", q_max="N", overlap="m", overlap_inner="m", overlap_outer="m",
    contact_angle="rad", displacement="m", delta_r="m", delta_a="m", eps="-", q_max_stribeck="N",
    eps_stribeck="-", omega="rad/s",
    **{f"{name}_{race}": unit for race in ("inner", "outer")
       for name, unit in (("u_r", "m/s"), ("r_x", "m"), ("kappa", "-"), ("a", DIAG_UNITS["a"]),
                          ("b", DIAG_UNITS["b"]), ("p_max", DIAG_UNITS["p_max"]), ("h_min", DIAG_UNITS["h_min"]),
                          ("lambda", "-"), ("regime", "code (regime_codes)"), ("mu", "-"))})


def with_units(d: dict, units: dict) -> dict:
    """``d`` with a ``units`` entry: the unit of each of its keys that ``units`` knows."""
    out = dict(d)
    out["units"] = {k: units[k] for k in d if k in units}
    return out
