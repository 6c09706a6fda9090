"""Power loss of a quasi-static solution by component, and the friction torque that carries it.

docs/theory/losses.md. From the contact loads, Hertz ellipses, rolling
speeds and orbital speeds of a :class:`~.solution.QuasiStaticSolution`:

* ``traction``: the dissipation of the traction model over every Hertz
  ellipse (sliding, spin, curvature), the solver's ``dissipation_total``;
* ``ehl_rolling``: 2 F_R |u_r| at every lubricated contact
  (:func:`~exudyn_bearing.physics.losses.ehl_rolling_force`, isothermal and
  fully flooded: no thermal or starvation reduction);
* ``hysteresis``: F_h |u_r| at every contact
  (:func:`~exudyn_bearing.physics.losses.hysteresis_rolling_force`);
* ``drag``: F_D v of every ball orbiting through the oil-air mixture at
  v = r_c omega_m (:func:`~exudyn_bearing.physics.losses.ball_drag_force`);
  with ``oil_volume_fraction = 0`` (default) the balls move through air.

Cage friction is not modelled (the quasi-static solver is cageless) and
seals are not modelled; ``power_loss_notes`` says so in every result.
``friction_torque_total`` = power_loss_total / |omega - omega_outer|, the
torque the driven ring needs when the other ring stands still (the inner
ring for the default outer ring at rest; the outer ring when the inner ring
is held). The traction component is the solver's dissipation; its drive
torque (``friction_torque``) equals it divided by the speed only in the
traction equilibrium (``energy_residual`` 0).
"""
from __future__ import annotations

import math

import numpy as np

from ...data import InputError, Lubricant, load_bearing, lubricants
from ...data.lubricants_temperature import lubricants_temperature
from ...physics import hertz as _hz
from ...physics import losses as _ls
from ...physics.geometry import raceway_radii
from ...physics.lubricant_properties import lubricant_at

__all__ = ["LOSS_COMPONENTS", "LOSS_UNITS", "NOT_MODELLED", "loss_keys", "power_losses"]

#: Components of ``power_loss`` [W], in order.
LOSS_COMPONENTS = ("traction", "ehl_rolling", "hysteresis", "drag")
#: Loss sources the quasi-static solver does not represent (reported as text).
NOT_MODELLED = {"cage": "not modelled (cageless quasi-static)", "seals": "not modelled",
                "churning": "not modelled (no oil bath)"}
#: Units of the keys :func:`loss_keys` adds to the solution's dict.
LOSS_UNITS = {
    "power_loss": "W per component (traction, ehl_rolling, hysteresis, drag); text for what is not modelled",
    "power_loss_total": "W (sum of the modelled components)",
    "friction_torque_total": "N m (power_loss_total / |omega - omega_outer|: the torque on the driven ring, "
                             "the other ring at rest)",
    "power_loss_inner_ball": "W (ehl_rolling + hysteresis at each ball's inner contact)",
    "power_loss_outer_ball": "W (ehl_rolling + hysteresis at each ball's outer contact)",
    "drag_ball": "W (drag power of each ball)",
}

#: Density of the oil for the drag when the lubricant carries none [kg/m^3]: a mineral oil near
#: 40 C (ISO VG 32-68 oils are 850-880 kg/m^3 at 15 C).
DEFAULT_OIL_DENSITY = 860.0


def _bearing(sol, bearing):
    if bearing is not None:
        return bearing if not isinstance(bearing, str) else load_bearing(bearing)
    try:
        return load_bearing(sol.bearing_name)
    except InputError:
        raise InputError(f"bearing: {sol.bearing_name!r} is not in the catalogue; pass the BallBearing "
                         "the solution was computed for") from None


def _lubricant(sol, lubricant):
    if isinstance(lubricant, Lubricant):
        return lubricant
    name = sol.lubricant if lubricant is None else str(lubricant)
    base, at, temp = name.rpartition("@")[0], "@" in name, name.rpartition("@")[2].removesuffix("K")
    if name not in lubricants and at and base in lubricants_temperature:  # lubricant_at(base, T)'s name
        try:
            return lubricant_at(base, float(temp))
        except ValueError:
            pass
    if name not in lubricants:
        raise InputError(f"lubricant: {name!r} is not in the catalogue; pass the Lubricant the solution was "
                         "computed with")
    return lubricants[name]


def _contact_rx(bearing, r_b, center_r, alpha, inner):
    """R_x [m] at the contact (ball centre radius, contact angle), the solver's geometry."""
    ca = np.cos(alpha)
    r_contact = center_r - r_b * ca if inner else center_r + r_b * ca
    r_groove = bearing.inner_groove_radius if inner else bearing.outer_groove_radius
    return raceway_radii(r_b, r_groove, r_contact, alpha, inner)[0]


def power_losses(sol, bearing=None, lubricant=None, *, hysteresis_loss_factor=_ls.HYSTERESIS_LOSS_FACTOR_STEEL,
                 oil_volume_fraction=0.0, oil_density=DEFAULT_OIL_DENSITY, air_density=_ls.AIR_DENSITY,
                 air_viscosity=_ls.AIR_VISCOSITY) -> dict:
    """Power loss by component [W] and the friction torque of a quasi-static solution.

    Parameters
    ----------
    sol : QuasiStaticSolution
    bearing : BallBearing or str, optional
        The bearing solved (default: the catalogue entry named like the solution's bearing).
    lubricant : Lubricant or str, optional
        The lubricant solved with (default: the catalogue entry of the solution's name, or
        ``lubricant_at(name, T)`` for the name ``"name@TK"`` it gives).
    hysteresis_loss_factor : float
        alpha_h [-] (default 0.007, hardened bearing steel).
    oil_volume_fraction : float
        Oil's share of the free volume the balls orbit through [-], 0-1
        (0: air; jet or mist lubrication some 0.01-0.1, from the oil flow).
    oil_density : float
        [kg/m^3] (default 860, a mineral oil near 40 C).
    air_density, air_viscosity : float
        [kg/m^3], [Pa s] (air at 20 C).

    Returns
    -------
    dict
        ``power_loss`` {component: W, and the not-modelled sources as text},
        ``power_loss_total`` [W], ``friction_torque_total`` [N m] (NaN with
        the rings at the same speed), per-ball arrays ``power_loss_inner_ball``,
        ``power_loss_outer_ball``, ``drag_ball`` [W], and ``power_loss_notes``.
    """
    if not (0.0 <= float(oil_volume_fraction) <= 1.0):
        raise InputError(f"oil_volume_fraction: must lie in [0, 1], got {oil_volume_fraction!r}")
    for name, v in (("oil_density", oil_density), ("air_density", air_density), ("air_viscosity", air_viscosity)):
        if not (math.isfinite(float(v)) and float(v) > 0.0):
            raise InputError(f"{name}: must be > 0 and finite, got {v!r}")
    if not (math.isfinite(float(hysteresis_loss_factor)) and 0.0 <= float(hysteresis_loss_factor) < 1.0):
        raise InputError(f"hysteresis_loss_factor: must lie in [0, 1), got {hysteresis_loss_factor!r}")
    b = _bearing(sol, bearing)
    lub = _lubricant(sol, lubricant)
    bl = sol.balls
    e_prime = _hz.material_reduced_modulus(b.material)
    r_b = b.ball_radius + sol.geometry.get("ball_thermal_growth", 0.0)
    cr = np.asarray(bl["ball_center_r"], float)
    per = {}
    for tag, inner in (("inner", True), ("outer", False)):
        q = np.asarray(bl[f"q_{tag}"], float)
        a = np.asarray(bl[f"a_{tag}"], float)      # across rolling (major)
        bb = np.asarray(bl[f"b_{tag}"], float)     # along rolling (minor)
        u = np.asarray(bl[f"u_roll_{tag}"], float)
        rx = _contact_rx(b, r_b, cr, np.asarray(bl[f"alpha_{tag}"], float), inner)
        loaded = (q > 0.0) & (bb > 0.0)
        kappa = np.where(loaded, a / np.where(loaded, bb, 1.0), 1.0)
        f_ehl = np.where(loaded, _ls.ehl_rolling_force(u, q, rx, np.maximum(kappa, 1.0), e_prime, lub.viscosity,
                                                       lub.pressure_viscosity), 0.0)
        f_h = np.where(loaded, _ls.hysteresis_rolling_force(q, bb, rx, hysteresis_loss_factor), 0.0)
        per[tag] = (_ls.rolling_resistance_power(f_ehl, u, surfaces=2), _ls.rolling_resistance_power(f_h, u))
    rho = _ls.mixture_density(oil_volume_fraction, oil_density, air_density)
    eta = _ls.mixture_viscosity(oil_volume_fraction, lub.viscosity, air_viscosity)
    v = cr * np.asarray(bl["orbital_speed"], float)  # ball centre speed, mixture at rest
    drag = np.atleast_1d(_ls.ball_drag_force(v, 2.0 * r_b, rho, eta)) * np.abs(v)
    p = {"traction": float(sol.dissipation_total),
         "ehl_rolling": float(np.sum(per["inner"][0]) + np.sum(per["outer"][0])),
         "hysteresis": float(np.sum(per["inner"][1]) + np.sum(per["outer"][1])),
         "drag": float(np.sum(drag))}
    total = float(sum(p.values()))
    dw = abs(sol.omega - sol.omega_outer)
    notes = dict(NOT_MODELLED)
    notes["ehl_rolling"] = "isothermal, fully flooded (no inlet-shear heating or starvation reduction)"
    notes["drag"] = (f"balls orbiting through a mixture of oil volume fraction {float(oil_volume_fraction):g} "
                     f"(density {rho:.4g} kg/m^3)")
    out = {"power_loss": {**p, "cage": NOT_MODELLED["cage"], "seals": NOT_MODELLED["seals"]},
           "power_loss_total": total,
           "friction_torque_total": total / dw if dw > 0.0 else float("nan"),
           "power_loss_inner_ball": per["inner"][0] + per["inner"][1],
           "power_loss_outer_ball": per["outer"][0] + per["outer"][1],
           "drag_ball": drag, "power_loss_notes": notes}
    return out


def loss_keys(sol) -> dict:
    """The loss keys for :meth:`QuasiStaticSolution.to_dict` with the catalogue's bearing and
    lubricant of the solution's names; a solution of a bearing or lubricant outside the catalogue
    gets ``power_loss`` None and the reason in ``power_loss_notes``."""
    try:
        return power_losses(sol)
    except InputError as err:
        return {"power_loss": None, "power_loss_total": None, "friction_torque_total": None,
                "power_loss_notes": {"error": f"{err}: call solvers.quasistatic.losses.power_losses(sol, "
                                              "bearing, lubricant)"}}
