"""Run-time check of the quasi-static hypothesis along the orbit: can each ball follow the solution's kinematics
from one ball position to the next?

The quasi-static solution gives every ball position psi_j its own ball kinematics (angular velocity in the orbit
frame, orbital speed), each the steady state of a ball that stays there. A real ball passes the positions in
turn, one ball pitch 2 pi / Z in dt = 2 pi / (Z |omega_m|), and must change its angular velocity and orbital
speed between them; the solution leaves out the inertia this takes (Harris & Kotzalas, *Rolling Bearing
Analysis*, 5th ed., 2007, vol. 2, ch. 1 and 4: quasi-static analysis neglects the balls' accelerations; Gupta,
*Advanced Dynamics of Rolling Elements*, 1984, ch. 1: dynamic analysis is needed where they matter). Bringing a
body's speed to that of a much heavier surface by friction dissipates the relative kinetic energy, whatever the
friction law: the change ``dw`` of angular velocity costs ``J |dw|^2 / 2`` and the change ``d omega_m`` of
orbital speed ``m (r dw_m)^2 / 2`` when the ball makes it by sliding. Once per ball pitch, that is the power

    P = sum_j [J |w_(j+1) - w_j|^2 + m r_j^2 (omega_m,(j+1) - omega_m,j)^2] / (2 dt_j),

an estimate of the transient slip loss the solution does not contain (exact when the ball makes every change by
gross sliding; less when it follows in creep). Where P is a noticeable share of the solution's dissipation, the
balls' inertia matters and the quasi-static solution is outside its range: the caged 7208 under F_r = F_a =
3000 N at 500 rad/s, whose lightly loaded balls leave and re-enter the load zone, gives P = 23 W against 64 W
of dissipation, and the reference engine dissipates 35 % more than the quasi-static solution
(``python validation/consistency/quasistatic_cage.py``; docs/theory/quasistatic.md).
"""
from __future__ import annotations

import math
import warnings

import numpy as np

__all__ = ["BallInertiaWarning", "INERTIA_TOLERANCE", "ball_mass_inertia", "check_ball_inertia"]

#: Share of the dissipation above which the balls' inertia along the orbit is judged to matter [-] (the 1 % of
#: the traction-resolution check, :data:`~exudyn_bearing.solvers.quasistatic.solve.RESOLUTION_TOLERANCE`).
INERTIA_TOLERANCE = 0.01


class BallInertiaWarning(UserWarning):
    """The balls cannot follow the quasi-static kinematics from one position to the next without a transient
    slip loss that is a noticeable share of the dissipation: the quasi-static hypothesis does not hold; run the
    case in a dynamic engine (``simulate``)."""


def ball_mass_inertia(bearing, ball_radius):
    """Mass [kg] and polar moment of inertia [kg m^2] of one ball of ``bearing`` grown to ``ball_radius`` [m]
    (thermal growth; a solid sphere: J = 2 m r^2 / 5)."""
    mass = bearing.ball_mass * (ball_radius / bearing.ball_radius) ** 3
    return mass, 0.4 * mass * ball_radius ** 2


def check_ball_inertia(sol, bearing, tolerance=INERTIA_TOLERANCE, warn=True) -> dict | None:
    """The transient slip power P [W] (module docstring) of the quasi-static solution ``sol`` against its
    dissipation (contacts and cage).

    Parameters
    ----------
    sol : QuasiStaticSolution
    bearing : BallBearing
        The solution's bearing (its balls' mass and inertia, grown as the solution's ``geometry`` says).
    tolerance : float
        Share of the dissipation above which the check fails (default :data:`INERTIA_TOLERANCE`).
    warn : bool
        Issue a :class:`BallInertiaWarning` when the check fails.

    Returns
    -------
    dict or None
        ``{"power" [W], "dissipation" [W], "share" [-], "ball" (the position j whose step j -> j + 1
        contributes most), "tolerance", "valid"}``; None without relative speed of the rings (no orbit) or
        without kinematics.
    """
    kin = sol.kinematics
    if kin is None or sol.omega == sol.omega_outer or kin.shape[0] < 2:
        return None
    ball_mass, ball_inertia = ball_mass_inertia(bearing, bearing.ball_radius
                                                + sol.geometry.get("ball_thermal_growth", 0.0))
    r = np.asarray(sol.balls["ball_center_r"], float)
    nxt = np.roll(np.arange(kin.shape[0]), -1)
    w_m = 0.5 * (np.abs(kin[:, 0]) + np.abs(kin[nxt, 0]))
    dt = 2.0 * math.pi / (kin.shape[0] * np.maximum(w_m, 1e-300))
    dw2 = (kin[nxt, 1] - kin[:, 1]) ** 2 + (kin[nxt, 2] - kin[:, 2]) ** 2
    dv2 = (0.5 * (r + r[nxt]) * (kin[nxt, 0] - kin[:, 0])) ** 2
    terms = (ball_inertia * dw2 + ball_mass * dv2) / (2.0 * dt)
    lost = float(sol.dissipation_total + sol.cage_power)
    power = float(terms.sum())
    if power <= 1e-12 * max(lost, 1e-300):  # round-off of alike balls' speeds
        power = 0.0
        terms = np.zeros_like(terms)
    share = power / lost if lost > 0.0 else (0.0 if power == 0.0 else math.inf)
    ball = int(np.argmax(terms))
    out = {"power": power, "dissipation": lost, "share": share, "ball": ball, "tolerance": float(tolerance),
           "valid": bool(share <= tolerance)}
    if warn and not out["valid"]:
        warnings.warn(BallInertiaWarning(
            f"the balls cannot follow the quasi-static kinematics along the orbit: changing each ball's angular "
            f"velocity and orbital speed from one position to the next by sliding costs about {power:.3g} W, "
            f"{100 * share:.3g} % of the solution's traction and cage losses ({lost:.4g} W: its ball / race "
            f"contacts' traction {sol.dissipation_total:.4g} W and its cage {sol.cage_power:.4g} W, without the "
            f"rolling losses of its power loss; the largest step from ball {ball} at "
            f"psi = {math.degrees(float(sol.balls['psi'][ball])):.1f} deg), more than {100 * tolerance:g} %: "
            "the balls' inertia matters (lightly loaded balls entering and leaving the load zone), which the "
            "quasi-static solution leaves out; its losses may be low. March the balls along the orbit with their "
            "inertia (with the rigid cage: exudyn_bearing.solvers.quasistatic.orbit.march_orbit, or quasistatic "
            "--orbit-march) or run the case dynamically (exudyn_bearing.simulate, or the command line's simulate)"), stacklevel=3)
    return out
