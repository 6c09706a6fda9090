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
  v = r_c (omega_m - omega_outer), the mixture turning with the outer ring as in the dynamic engines
  (:func:`~exudyn_bearing.physics.losses.ball_drag_force`);
  with ``oil_volume_fraction = 0`` (default) the balls move through air;
* ``churning``: the extra drag of the balls through an oil bath of level
  ``oil_level`` (a flooded bearing): the drag at the density of the bath's
  orbit-mean immersed share
  (:func:`~exudyn_bearing.physics.losses.bath_immersion_fraction`) minus
  ``drag``; 0 without a bath (default);
* ``cage_pocket``: mu_c Q_c (D/2) |omega_R| of every ball sliding in its
  pocket, Q_c from the drag the cage carries and its land torque
  (:func:`~exudyn_bearing.physics.losses.cage_pocket_loads`,
  :func:`~exudyn_bearing.physics.losses.cage_pocket_friction_power`);
* ``cage_land``: Petroff's torque of the cage on its guiding land times the
  cage's speed relative to that ring
  (:func:`~exudyn_bearing.physics.losses.petroff_torque`); 0 for a
  ball-guided cage (the default for a bearing with a cage).

A solution without a cage (``cage=None``): the cage components are computed
from its ball speeds and loads (the ``cage_*`` options), they do not act back
on the equilibrium. A solution with the rigid cage (``cage="rigid"``) carries
its own: ``cage_pocket`` the pocket forces' Coulomb friction mu_c |Q_p| R_b
|w| and ``cage_land`` the land film's shear torque times the cage's speed
relative to its guiding ring, both from the cage's balance in the solver and
its RigidCage (docs/theory/quasistatic.md#the-rigid-cage); the ``cage_*``
options are then refused (one geometry source). Seals are not modelled; ``not_modelled`` lists what is left
out in every result.
``friction_torque_total`` = power_loss_total / |omega - omega_outer|, the
torque the driven ring needs when the other ring stands still (the inner
ring for the default outer ring at rest; the outer ring when the inner ring
is held). With no relative speed (omega = omega_outer, also both at rest)
nothing moves relative to anything, every component is 0 and so is the
torque (the breakaway torque of a start is not modelled). The traction component is the solver's dissipation; its drive
torque (``friction_torque``) equals it divided by the speed only in the
traction equilibrium (``energy_residual`` 0).
"""
from __future__ import annotations

import math

import numpy as np

from ...data import BallBearing, InputError, Lubricant, load_bearing, lubricants
from ...data.errors import check_finite, check_plausible
from ...data.lubricants_temperature import lubricants_temperature
from ...physics import hertz as _hz
from ...physics import losses as _ls
from ...physics.geometry import raceway_radii
from ...physics.lubricant_properties import lubricant_at

__all__ = ["CAGE_GUIDANCES", "CAGE_LAND_CLEARANCE_RATIO", "CAGE_LAND_SHOULDER_RATIO", "CAGE_LAND_WIDTH_RATIO",
           "LOSS_COMPONENTS", "LOSS_UNITS", "NOT_MODELLED", "NOT_MODELLED_LIST", "cage_land_geometry", "loss_keys",
           "power_losses"]

#: Components of ``power_loss`` [W], in order.
LOSS_COMPONENTS = ("traction", "ehl_rolling", "hysteresis", "drag", "churning", "cage_pocket", "cage_land")
#: Loss sources the quasi-static solver does not represent (reported as text in ``power_loss_notes``).
NOT_MODELLED = {"seals": "not modelled", "cage": "modelled as cage_pocket and cage_land from the cageless "
                "solution's ball speeds and loads (no pocket loads from orbital speed variation or gyroscopic "
                "moments, no cage windage)"}
#: The cage's note for a solution with the rigid cage (``sol.cage``).
NOT_MODELLED_RIGID_CAGE = ("rigid cage in the solver's balance: cage_pocket and cage_land from its pocket forces and "
                           "land film (no cage windage, weight or unbalance; the pocket's oil film not modelled)")
#: The same with the pocket film (``solve_quasistatic(..., pocket_film=True)``).
NOT_MODELLED_RIGID_CAGE_FILM = ("rigid cage in the solver's balance: cage_pocket and cage_land from its pocket forces, "
                                "the pocket oil film (flooded, a sphere facing a plane wall) and the land film (no "
                                "cage windage, weight or unbalance)")
#: What the pocket film leaves out (``solve_quasistatic(..., pocket_film=True)``, as the dynamic engines' film).
POCKET_FILM_NOT_MODELLED = ("the pocket oil film's rotation about the wall's normal, a starved pocket and the "
                            "pocket's conformity (a flooded sphere facing a plane wall)")
#: What ``not_modelled`` lists in every result.
NOT_MODELLED_LIST = ("seal friction (open bearing)",
                     "cage windage (drag of the cage in the oil-air mixture)",
                     "cage pocket loads from the variation of the balls' orbital speed, gyroscopic moments, the "
                     "cage's weight and unbalance",
                     "drag of the rings' faces and of the oil carried along (only the balls churn)",
                     "inlet-shear heating and starvation reduction of the EHL rolling force")
#: Cage guidances: "ball" (ball-guided, no land friction), "outer_land", "inner_land" (the cage rides on
#: that ring's land), "none" (no cage: no pocket and no land friction).
CAGE_GUIDANCES = ("ball", "outer_land", "inner_land", "none")
#: Default cage-land geometry, as multiples of the ball diameter D and of the land radius (assumed
#: proportions of machined, land-guided cages; give the bearing's values when known): the land lies a
#: quarter ball diameter off the race bottom towards the pitch circle (shoulder height 0.25 D), both
#: rails together are half a ball diameter wide, the radial land clearance is 0.4 % of the land radius
#: (a diametral clearance of 0.4 % of the land diameter).
CAGE_LAND_SHOULDER_RATIO = 0.25
CAGE_LAND_WIDTH_RATIO = 0.5
CAGE_LAND_CLEARANCE_RATIO = 0.004
#: Units of the keys :func:`loss_keys` adds to the solution's dict.
LOSS_UNITS = {
    "power_loss": "W per component (traction, ehl_rolling, hysteresis, drag, churning, cage_pocket, cage_land); "
                  "text for seals and the cage's note",
    "not_modelled": "list of the loss sources left out (text)",
    "power_loss_total": "W (sum of the modelled components)",
    "friction_torque_total": "N m (power_loss_total / |omega - omega_outer|: the torque on the driven ring, "
                             "the other ring at rest; 0 without relative speed, where every loss is 0)",
    "power_loss_inner_ball": "W (ehl_rolling + hysteresis at each ball's inner contact)",
    "power_loss_outer_ball": "W (ehl_rolling + hysteresis at each ball's outer contact)",
    "drag_ball": "W (drag power of each ball, without churning)",
    "churning_ball": "W (churning power of each ball in the oil bath)",
    "cage_guidance": "text (ball, outer_land, inner_land or none)",
    "cage_land_torque": "N m (Petroff's torque of the cage on its land, 0 without land guidance; with the rigid "
                        "cage the land film's shear torque on the cage)",
    "cage_pocket_load": "N (normal load of each ball on its pocket; with the rigid cage |pocket_force|)",
    "cage_pocket_film": "W (the rigid cage's pocket oil film shear, part of power_loss cage_pocket; 0 without "
                        "the film)",
}

#: Density of the oil for the drag when the lubricant carries none [kg/m^3]
#: (:data:`~exudyn_bearing.physics.losses.OIL_DENSITY`, shared with the dynamic engines).
DEFAULT_OIL_DENSITY = _ls.OIL_DENSITY


#: Plausible oil densities [kg/m^3]: bearing oils 800-1000 (synthetic esters to 1000, fluorinated oils
#: to 1900); a value near 1 is a density typed in g/cm^3 (kg/l).
OIL_DENSITY_RANGE = (500.0, 2000.0)
#: Largest cage pocket friction coefficient accepted [-]: dry steel on steel reaches some 0.8.
MAX_CAGE_POCKET_FRICTION = 1.0


#: Fields of a QuasiStaticSolution that power_losses reads.
_SOLUTION_FIELDS = ("bearing_name", "balls", "geometry", "omega", "omega_outer", "lubricant", "dissipation_total")


def _bearing(sol, bearing):
    """The bearing of ``sol``: ``bearing`` (a BallBearing or a catalogue name) when given, checked to be the
    one solved (its name and ball count), else the catalogue's entry of the solution's name."""
    if bearing is not None:
        if not isinstance(bearing, (str, BallBearing)):
            raise InputError(f"bearing: expected a BallBearing or a catalogue name, got {bearing!r}")
        b = load_bearing(bearing) if isinstance(bearing, str) else bearing
        z = len(sol.balls["psi"])
        if b.name != sol.bearing_name or b.n_balls != z:
            raise InputError(f"bearing: the solution is of bearing {sol.bearing_name!r} ({z} balls), got "
                             f"{b.name!r} ({b.n_balls} balls); pass the bearing the solution was computed for")
        return b
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


def cage_land_geometry(bearing, guidance, radius=None, width=None, clearance=None) -> dict:
    """Land radius, width and radial clearance [m] of a land-guided cage: the given values, else the
    defaults of :data:`CAGE_LAND_SHOULDER_RATIO`, :data:`CAGE_LAND_WIDTH_RATIO`,
    :data:`CAGE_LAND_CLEARANCE_RATIO` (outer land at R_o - 0.25 D, inner land at R_i + 0.25 D, width
    0.5 D, radial clearance 0.004 r_land). ``source`` says which were defaults."""
    d_w = 2.0 * bearing.ball_radius
    given = {"radius": radius, "width": width, "clearance": clearance}
    if radius is None:
        radius = (bearing.outer_race_radius - CAGE_LAND_SHOULDER_RATIO * d_w if guidance == "outer_land"
                  else bearing.inner_race_radius + CAGE_LAND_SHOULDER_RATIO * d_w)
    width = CAGE_LAND_WIDTH_RATIO * d_w if width is None else width
    clearance = CAGE_LAND_CLEARANCE_RATIO * radius if clearance is None else clearance
    for name, v in (("cage_land_radius", radius), ("cage_land_width", width), ("cage_land_clearance", clearance)):
        if not (math.isfinite(float(v)) and float(v) > 0.0):
            raise InputError(f"{name}: must be > 0 and finite, got {v!r}")
    defaults = [k for k, v in given.items() if v is None]
    return {"radius": float(radius), "width": float(width), "clearance": float(clearance),
            "source": ("defaults (CAGE_LAND_*_RATIO) for " + ", ".join(defaults)) if defaults else "given"}


def power_losses(sol, bearing=None, lubricant=None, *, hysteresis_loss_factor=_ls.HYSTERESIS_LOSS_FACTOR_STEEL,
                 oil_volume_fraction=0.0, oil_density=DEFAULT_OIL_DENSITY, air_density=_ls.AIR_DENSITY,
                 air_viscosity=_ls.AIR_VISCOSITY, oil_level=0.0, cage_guidance=None,
                 cage_pocket_friction=None, cage_land_radius=None, cage_land_width=None,
                 cage_land_clearance=None) -> dict:
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
    oil_level : float
        Level H of an oil bath above the lowest point of the outer raceway [m] (SKF's reference);
        0 (default): no bath, no churning.
    cage_guidance : str, optional
        One of :data:`CAGE_GUIDANCES`; default "ball" for a bearing with a cage (the pressed-steel
        and polyamide cages of standard 62 and 72 B bearings are ball-guided), "none" for a cageless
        one. "outer_land" / "inner_land" add the land's Petroff torque.
    cage_pocket_friction : float, optional
        mu_c of the ball in its pocket [-] (default 0.1, assumed).
    cage_land_radius, cage_land_width, cage_land_clearance : float, optional
        The land's radius, width (both rails) and radial clearance [m]; defaults
        :func:`cage_land_geometry`.

    A solution with the rigid cage (``sol.cage``) takes its cage losses, pocket loads, land torque and
    guidance from the solver and its RigidCage; the ``cage_*`` options conflict with it (InputError naming
    the option).

    Returns
    -------
    dict
        ``power_loss`` {component: W, and the not-modelled sources as text},
        ``power_loss_total`` [W], ``friction_torque_total`` [N m] (0 with
        the rings at the same speed, where every component is 0), per-ball arrays ``power_loss_inner_ball``,
        ``power_loss_outer_ball``, ``drag_ball`` [W], and ``power_loss_notes``.
    """
    if not all(hasattr(sol, k) for k in _SOLUTION_FIELDS):  # (the solution module imports this one)
        raise InputError(f"sol: expected a QuasiStaticSolution (of solve_quasistatic), got {sol!r}")
    oil_volume_fraction = check_finite("oil_volume_fraction", oil_volume_fraction)
    if not 0.0 <= oil_volume_fraction <= 1.0:
        raise InputError(f"oil_volume_fraction: must lie in [0, 1], got {oil_volume_fraction!r}")
    oil_density = check_plausible("oil_density", oil_density, *OIL_DENSITY_RANGE, "kg/m^3", "density is in kg/m^3",
                                  ((1e3, "g/cm^3"),))
    for name, v in (("air_density", air_density), ("air_viscosity", air_viscosity)):
        if not check_finite(name, v) > 0.0:
            raise InputError(f"{name}: must be > 0 and finite, got {v!r}")
    if not check_finite("oil_level", oil_level) >= 0.0:
        raise InputError(f"oil_level: must be >= 0 and finite (m above the lowest point of the outer raceway), "
                         f"got {oil_level!r}")
    rigid = getattr(sol, "cage", None)
    if rigid is not None:
        given = {"cage_pocket_friction": cage_pocket_friction, "cage_land_radius": cage_land_radius,
                 "cage_land_width": cage_land_width, "cage_land_clearance": cage_land_clearance}
        for name, v in given.items():
            if v is not None:
                raise InputError(f"{name}: the solution has the rigid cage, whose RigidCage gives its pocket "
                                 "friction and land geometry (solve_quasistatic's rigid_cage); leave it out")
        if cage_guidance is not None and cage_guidance != rigid["guidance"]:
            raise InputError(f"cage_guidance: {cage_guidance!r} conflicts with the solution's rigid cage, guided "
                             f"{rigid['guidance']!r} (its RigidCage); leave it out")
    if cage_pocket_friction is None:
        cage_pocket_friction = _ls.CAGE_POCKET_FRICTION
    cage_pocket_friction = check_plausible("cage_pocket_friction", cage_pocket_friction, 0.0,
                                           MAX_CAGE_POCKET_FRICTION, "", "a friction coefficient is a ratio "
                                           "(lubricated sliding in a pocket about 0.05-0.15)", ((1e-2, "%"),))
    if cage_guidance is not None and cage_guidance not in CAGE_GUIDANCES:
        raise InputError(f"cage_guidance: one of {', '.join(CAGE_GUIDANCES)}, got {cage_guidance!r}")
    if not 0.0 <= check_finite("hysteresis_loss_factor", hysteresis_loss_factor) < 1.0:
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
    # ball centre speed relative to the mixture, which turns with the outer ring (the dynamic engines' drag)
    v = cr * (np.asarray(bl["orbital_speed"], float) - sol.omega_outer)
    f_drag = np.atleast_1d(_ls.ball_drag_force(v, 2.0 * r_b, rho, eta))
    drag = f_drag * np.abs(v)
    # churning: the balls through the bath over their immersed share phi_b (oil in the bath, the mixture above)
    phi_b = _ls.bath_immersion_fraction(oil_level, b.pitch_radius, 2.0 * r_b) if oil_level > 0.0 else 0.0
    f_bath = np.atleast_1d(_ls.ball_drag_force(v, 2.0 * r_b, _ls.mixture_density(phi_b, oil_density, rho),
                                               _ls.mixture_viscosity(phi_b, lub.viscosity, eta)))
    churning = np.maximum(f_bath - f_drag, 0.0) * np.abs(v)
    # cage: guidance, land torque (Petroff), pocket loads and sliding
    if rigid is not None:
        guidance = rigid["guidance"]
    else:
        guidance = cage_guidance or ("ball" if b.has_cage else "none")
    omega_c = float(np.mean(np.asarray(bl["orbital_speed"], float)))
    land = None
    t_land = 0.0
    if rigid is not None:  # the solver's cage balance (one geometry source: its RigidCage)
        rc = rigid["rigid_cage"]
        t_land, p_land = float(rigid["land_torque"]), float(rigid["power_land"])
        if guidance != "ball":
            land = {"radius": rc.guide_radius, "width": rc.land_width, "clearance": rc.land_clearance,
                    "source": "the solution's RigidCage" + (" (estimated)" if rc.estimated else "")}
    elif guidance in ("outer_land", "inner_land"):
        land = cage_land_geometry(b, guidance, cage_land_radius, cage_land_width, cage_land_clearance)
        rel = omega_c - sol.omega_outer if guidance == "outer_land" else sol.omega - omega_c
        t_land = float(_ls.petroff_torque(lub.viscosity, land["radius"], land["width"], land["clearance"], rel))
        p_land = abs(t_land * rel)
    else:
        p_land = 0.0
    film_power = 0.0
    if rigid is not None:
        q_c = np.abs(np.asarray(bl["pocket_force"], float))
        # the ball's spin while its pocket holds it (pocket_sliding_speed / R_b; ball_speed is the time mean of
        # held and free with the pocket play)
        w_held = np.asarray(bl["pocket_sliding_speed"], float) / r_b
        # the friction on the wall's contact force (the pocket force less what the pocket film's pressure
        # carries), and the film's shear (zero without the film)
        q_contact = np.abs(np.asarray(bl.get("pocket_contact_force", bl["pocket_force"]), float))
        pocket = np.atleast_1d(_ls.cage_pocket_friction_power(q_contact, w_held, 2.0 * r_b,
                                                              rigid["pocket_friction"]))
        if rigid.get("pocket_film"):
            film_ball = np.asarray(bl["pocket_film_power"], float)
            film_power = float(np.sum(film_ball))
            pocket = pocket + film_ball
    elif guidance == "none":
        q_c = np.zeros_like(drag)
        pocket = np.zeros_like(drag)
    else:
        loaded = np.asarray(bl["q_inner"], float) > 0.0
        q_c = _ls.cage_pocket_loads(f_bath, loaded, abs(t_land), b.pitch_radius)
        pocket = np.atleast_1d(_ls.cage_pocket_friction_power(q_c, np.asarray(bl["ball_speed"], float), 2.0 * r_b,
                                                              cage_pocket_friction))
    p = {"traction": float(sol.dissipation_total),
         "ehl_rolling": float(np.sum(per["inner"][0]) + np.sum(per["outer"][0])),
         "hysteresis": float(np.sum(per["inner"][1]) + np.sum(per["outer"][1])),
         "drag": float(np.sum(drag)), "churning": float(np.sum(churning)),
         "cage_pocket": float(np.sum(pocket)), "cage_land": float(p_land)}
    total = float(sum(p.values()))
    dw = abs(sol.omega - sol.omega_outer)
    notes = dict(NOT_MODELLED)
    if rigid is not None:  # the cage is in the solver's balance: its note is the rigid cage's
        notes["cage"] = NOT_MODELLED_RIGID_CAGE_FILM if rigid.get("pocket_film") else NOT_MODELLED_RIGID_CAGE
    notes["ehl_rolling"] = "isothermal, fully flooded (no inlet-shear heating or starvation reduction)"
    notes["drag"] = (f"balls orbiting through a mixture of oil volume fraction {float(oil_volume_fraction):g} "
                     f"(density {rho:.4g} kg/m^3)")
    notes["churning"] = (f"oil bath of level {float(oil_level):g} m: orbit-mean immersed share {phi_b:.4g} of the "
                         "balls' frontal area, bath at rest (an upper value)" if oil_level > 0.0 else
                         "no oil bath (oil_level 0)")
    notes["cage_pocket"] = (f"rigid cage: mu_c = {rigid['pocket_friction']:g} on the pocket forces of the cage's "
                            "balance in the solver" + (f" (on the part the pocket film's pressure leaves to the "
                                                       f"contact), and the pocket film's shear {film_power:.4g} W "
                                                       "(cage_pocket_film)" if rigid.get("pocket_film") else "")
                            if rigid is not None else "no cage" if guidance == "none" else
                            f"mu_c = {float(cage_pocket_friction):g}; pocket loads from the balls' drag and the "
                            "cage's land torque (loaded balls drive the cage, the cage drives the unloaded balls)")
    notes["cage_land"] = (f"rigid cage, {guidance} guidance: the land film's shear torque at eccentricity "
                          f"{rigid['land_eccentricity']:.3g}, land radius {land['radius']:.4g} m, width "
                          f"{land['width']:.4g} m, radial clearance {land['clearance']:.4g} m ({land['source']})"
                          if rigid is not None and land else
                          f"{guidance} guidance: Petroff's torque, land radius {land['radius']:.4g} m, width "
                          f"{land['width']:.4g} m, radial clearance {land['clearance']:.4g} m ({land['source']})"
                          if land else f"{guidance} guidance: no land friction")
    cage_note = (NOT_MODELLED["cage"] if rigid is None else
                 NOT_MODELLED_RIGID_CAGE_FILM if rigid.get("pocket_film") else NOT_MODELLED_RIGID_CAGE)
    out = {"power_loss": {**p, "cage": cage_note, "seals": NOT_MODELLED["seals"]},
           "power_loss_total": total,
           # no relative speed: every component is 0 (nothing moves relative to the rings or the mixture)
           "friction_torque_total": total / dw if dw > 0.0 else 0.0,
           "power_loss_inner_ball": per["inner"][0] + per["inner"][1],
           "power_loss_outer_ball": per["outer"][0] + per["outer"][1],
           "drag_ball": drag, "churning_ball": churning, "cage_pocket_load": q_c, "cage_land_torque": t_land,
           "cage_guidance": guidance, "power_loss_notes": notes, "cage_pocket_film": film_power,
           "not_modelled": list(NOT_MODELLED_LIST) if rigid is None else
           [x for x in NOT_MODELLED_LIST if not x.startswith("cage pocket loads")]
           + (["the rigid cage's weight and unbalance", POCKET_FILM_NOT_MODELLED]
              if rigid.get("pocket_film") else ["the rigid cage's weight, unbalance and pocket oil film"])}
    return out


def loss_keys(sol) -> dict:
    """The loss keys for :meth:`QuasiStaticSolution.to_dict` with the catalogue's bearing and
    lubricant of the solution's names; a solution of a bearing or lubricant outside the catalogue
    gets ``power_loss`` None and the reason in ``power_loss_notes``."""
    try:
        return power_losses(sol)
    except InputError as err:
        return {"power_loss": None, "power_loss_total": None, "friction_torque_total": None,
                "not_modelled": list(NOT_MODELLED_LIST),
                "power_loss_notes": {"error": f"{err}: call solvers.quasistatic.losses.power_losses(sol, "
                                              "bearing, lubricant)"}}
