"""The whole loss and friction torque of a dynamic run: its modelled losses plus a labelled
quasi-static estimate of each loss the run does not model (docs/theory/losses.md, "The whole loss
of a dynamic run").

A dynamic run models only some of the bearing's losses (``losses_modelled`` of its summary): the
point traction level leaves out the rolling losses (spin and curvature slip), both levels the EHL
rolling and hysteresis resistance unless ``rolling_resistance``, the ball drag unless ``ball_drag``,
the cage pockets and land unless the rigid cage. Its ``power_loss_total`` is the sum of what it
models. :func:`whole_loss` adds, for each loss it leaves out, the component of the quasi-static
loss model (:func:`~exudyn_bearing.solvers.quasistatic.losses.power_losses` of a
:func:`~exudyn_bearing.solvers.quasistatic.solve_quasistatic` at the run's operating point: the
scenario's loads, the window's mean speed, its lubricant, traction model, ring growth and
temperatures, tilt held as in the dynamic engines), under separate keys.
"""
from __future__ import annotations

from ..data import InputError

__all__ = ["WHOLE_LOSS_DESCRIPTIONS", "WHOLE_LOSS_KEYS", "WHOLE_LOSS_UNITS", "basis_text", "estimate_losses",
           "quasistatic_estimate", "whole_loss"]

#: Keys :func:`whole_loss` adds to a dynamic summary.
WHOLE_LOSS_KEYS = ("power_loss_whole", "power_loss_whole_basis", "power_loss_estimated", "friction_torque_whole",
                   "friction_torque_estimated")
WHOLE_LOSS_UNITS = {"power_loss_whole": "W", "power_loss_whole_basis": "text", "power_loss_estimated":
                    "W per component", "friction_torque_whole": "N m (driven ring)",
                    "friction_torque_estimated": "N m (driven ring)"}
WHOLE_LOSS_DESCRIPTIONS = {
    "power_loss_whole": "the bearing's whole power loss: power_loss_total (the components the run models) plus "
                        "power_loss_estimated (the quasi-static estimate of each loss it leaves out); "
                        "power_loss_whole_basis says which is which; None when the estimate failed",
    "power_loss_whole_basis": "modelled: the run's components; estimated: the quasi-static components added and "
                              "their source; not_estimated: sources neither model represents; operating_point: "
                              "the loads and speed of the estimate",
    "power_loss_estimated": "quasi-static estimate [W] of each loss the run does not model (solve_quasistatic and "
                            "power_losses at the scenario's loads and the window's mean speed); traction_rolling "
                            "at the point level: the quasi-static traction dissipation (sliding, spin, curvature "
                            "over the ellipse) minus the run's contact traction, at least 0",
    "friction_torque_whole": "power_loss_whole / |omega - omega_outer|: the torque the driven ring needs for the "
                             "whole loss (as the quasi-static friction_torque_total; the run's "
                             "friction_torque is the ring torque of the modelled losses only)",
    "friction_torque_estimated": "sum of power_loss_estimated / |omega - omega_outer|",
}
#: Loss sources neither the dynamic engines nor the quasi-static model represent.
NOT_ESTIMATED = ("seal friction (open bearing)", "cage windage", "churning in an oil bath (no bath level given)")


def estimate_losses(bearing, lubricant, Fr, Fa, omega, *, omega_outer=0.0, traction=None, ring_growth=True, temperatures=None,
                    hertz="exact", n_strips=None, n_across=None, traction_regularizing_srr=None,
                    hysteresis_loss_factor=None, oil_volume_fraction=0.0, cage_guidance=None) -> dict:
    """``power_losses`` of the quasi-static solution of ``bearing`` under (Fr, Fa) [N] at ``omega``
    (and the outer ring at ``omega_outer``) [rad/s], tilt held (the dynamic engines' inner ring translates only); None keywords take the
    solvers' defaults."""
    from ..solvers.quasistatic import solve_quasistatic
    from ..solvers.quasistatic.losses import power_losses

    kw = {k: v for k, v in (("n_strips", n_strips), ("n_across", n_across),
                            ("traction_regularizing_srr", traction_regularizing_srr)) if v is not None}
    sol = solve_quasistatic(bearing, Fr=Fr, Fa=Fa, omega=omega, omega_outer=omega_outer, traction=traction, lubricant=lubricant,
                            ring_growth=ring_growth, temperatures=temperatures, fixed={"tilt_x": 0.0, "tilt_y": 0.0},
                            hertz_method=hertz, stiffness=False, resolution_check=False,
                            # an estimate of the parts a dynamic run does not model, beside that run: the balls'
                            # inertia along the orbit is the run's own (no quasi-static inertia check here)
                            inertia_check=False, **kw)
    lkw = {} if hysteresis_loss_factor is None else {"hysteresis_loss_factor": hysteresis_loss_factor}
    return power_losses(sol, bearing, lubricant, oil_volume_fraction=oil_volume_fraction,
                        cage_guidance=cage_guidance, **lkw)


def quasistatic_estimate(results, omega: float, omega_outer: float = 0.0) -> dict:
    """:func:`estimate_losses` at the run's operating point (the scenario's Fr, Fa, the speeds ``omega``,
    ``omega_outer``,
    its lubricant, traction model, growth, temperatures and loss options), cached on ``results`` by
    operating point."""
    sc = results.scenario
    key = (float(sc.Fr), float(sc.Fa), round(float(omega), 9), round(float(omega_outer), 9))
    cache = results.__dict__.setdefault("_quasistatic_estimates", {})
    if key not in cache:
        b = results.bearing if sc.Pd is None else results.bearing.with_clearance(sc.Pd)
        guidance = "none" if (sc.cage in (False, "none") or not b.has_cage) else None
        cache[key] = estimate_losses(b, results.lubricant, sc.Fr, sc.Fa, omega, omega_outer=omega_outer,
                                     traction=sc.traction,
                                     ring_growth=sc.ring_growth, temperatures=sc.temperatures, hertz=sc.hertz,
                                     n_strips=sc.n_strips, n_across=sc.n_across,
                                     traction_regularizing_srr=sc.traction_regularizing_srr,
                                     hysteresis_loss_factor=sc.hysteresis_loss_factor,
                                     oil_volume_fraction=sc.oil_volume_fraction, cage_guidance=guidance)
    return cache[key]


def _estimated_components(sc, power_loss: dict, qs: dict) -> dict:
    """{component: (W, what it stands for)} of the losses the run leaves out, from the quasi-static
    ``qs = power_losses(...)``."""
    p = qs["power_loss"]
    out = {}
    if sc.traction_level == "point":
        run = sum(v for k, v in power_loss.items() if k.startswith("contact_traction_") and v is not None)
        out["traction_rolling"] = (max(p["traction"] - run, 0.0),
                                   "rolling losses (spin and curvature slip): quasi-static traction dissipation "
                                   "minus the run's contact traction")
    if not sc.rolling_resistance:
        if sc.lubrication:
            out["ehl_rolling"] = (p["ehl_rolling"], "EHL rolling resistance (isothermal, fully flooded)")
        out["hysteresis"] = (p["hysteresis"], "elastic hysteresis rolling resistance")
    if not sc.ball_drag:
        out["drag"] = (p["drag"], "ball drag in the oil-air mixture")
    if sc.cage != "rigid":
        out["cage_pocket"] = (p["cage_pocket"], "cage pocket friction")
        out["cage_land"] = (p["cage_land"], f"cage land friction ({qs['cage_guidance']} guidance)")
    return out


def whole_loss(results, power_loss: dict, power_loss_total, omega: float, omega_outer: float = 0.0) -> dict:
    """The keys :data:`WHOLE_LOSS_KEYS` of a dynamic summary: the run's modelled ``power_loss``
    (its total ``power_loss_total``) plus the quasi-static estimate
    (:func:`quasistatic_estimate` at the window's mean speeds ``omega``, ``omega_outer``) of each loss it
    leaves out; the torques divide by the relative speed |omega - omega_outer|.
    An operating point the quasi-static solver refuses gives None for the whole loss and the
    reason in the basis."""
    sc = results.scenario
    modelled = [k for k, v in power_loss.items() if v is not None]
    point = {"Fr": float(sc.Fr), "Fa": float(sc.Fa), "omega": float(omega)}
    if omega_outer != 0.0:
        point["omega_outer"] = float(omega_outer)
    basis = {"modelled": modelled, "estimated": {}, "not_estimated": list(NOT_ESTIMATED), "operating_point": point,
             "source": "solvers.quasistatic.losses.power_losses of solve_quasistatic at the scenario's Fr, Fa and "
                       "the window's mean omega (tilt held, the run's lubricant and traction model)"}
    try:
        qs = quasistatic_estimate(results, omega, omega_outer)
    except (InputError, ValueError, ArithmeticError) as err:
        basis["error"] = f"no quasi-static estimate at this operating point: {err}"
        return {"power_loss_whole": None, "power_loss_whole_basis": basis, "power_loss_estimated": None,
                "friction_torque_whole": None, "friction_torque_estimated": None}
    est = _estimated_components(sc, power_loss, qs)
    estimated = {k: float(v) for k, (v, _) in est.items()}
    basis["estimated"] = {k: text for k, (_, text) in est.items()}
    s = float(sum(estimated.values()))
    whole = None if power_loss_total is None else float(power_loss_total) + s
    dw = abs(omega - omega_outer)
    return {"power_loss_whole": whole, "power_loss_whole_basis": basis, "power_loss_estimated": estimated,
            "friction_torque_whole": None if whole is None else (whole / dw if dw > 0.0 else 0.0),
            "friction_torque_estimated": s / dw if dw > 0.0 else 0.0}


def basis_text(basis: dict) -> str:
    """One line of ``power_loss_whole_basis`` for a table."""
    if "error" in basis:
        return basis["error"]
    est = ", ".join(basis["estimated"]) or "nothing"
    op = basis["operating_point"]
    outer = f", omega_outer {op['omega_outer']:.4g} rad/s" if "omega_outer" in op else ""
    return (f"modelled: {', '.join(basis['modelled'])}; estimated (quasi-static at Fr {op['Fr']:g} N, Fa "
            f"{op['Fa']:g} N, omega {op['omega']:.4g} rad/s{outer}): {est}; not estimated: "
            f"{'; '.join(basis['not_estimated'])}")
