"""``solve_thermal``: the quasi-static bearing and a lumped thermal network solved together.

docs/theory/thermal.md. Nodes: inner ring, outer ring, balls (one node for all), oil (the bearing
cavity, fully mixed: the oil leaves at the node's temperature), and the cage when the bearing has one
(the loss module's cage guidance not "none"). Boundaries: the oil inlet temperature (through
m_dot c_p) and the ambient (through the shaft and the housing).

Each iteration (a fixed point, relaxed by the secant slope of the mean temperature: Wegstein's method):

1. the lubricant at the contact temperature (the mean of the rings and twice the balls, the
   surfaces that form each contact inlet) by :func:`~exudyn_bearing.physics.lubricant_properties.lubricant_at`,
   and the traction model with that viscosity (an ``ehl`` model; other kinds follow the film);
2. :func:`~.solve.solve_quasistatic` with the part temperatures (thermal growth) and that
   lubricant, started from the previous iteration's solution;
3. :func:`~.losses.power_losses` (every component it reports);
4. heat at the nodes: the traction, EHL rolling and hysteresis loss of each contact, half to the
   ball and half to the ring (Blok's partition for two steel surfaces moving through the contact
   at the same rolling speed, :func:`~exudyn_bearing.physics.thermal.contact_heat_share`); the cage
   pocket friction ``cage_pocket_heat_share`` (default 1/2) to the cage and the rest to the balls, the
   cage land friction half to the cage and half to its guiding ring (the Couette film between them);
   every other component (drag, churning) to the oil;
5. conductances (ball-ring contacts by constriction, the surfaces to the oil by convection at the
   larger of their speed relative to the oil and the oil's through-flow speed, the
   rings to the ambient; the cage to the balls through the pocket oil films, to its guiding land
   through the land film, to the oil by convection) and the steady network
   (:func:`~exudyn_bearing.physics.thermal.network_temperatures`).

With the rigid cage (``cage="rigid"``, a keyword of :func:`~.solve.solve_quasistatic`) the cage's losses are
those of the solver's cage balance (:func:`~.losses.power_losses` reads them) and the cage node's pocket
clearance, land and surface come from its RigidCage; ``cage_pocket_clearance`` and the loss options'
``cage_*`` values then conflict and are refused by name.

It stops when the temperatures change by less than ``tolerance`` [K] between iterations. A
iterate beyond the lubricant's range is clamped to its top; one beyond it again is a
:class:`ThermalRunawayError` naming the temperature reached; no convergence within ``max_iterations`` is a :class:`ThermalConvergenceWarning` with
the temperatures reached, and ``converged`` False in the result.
"""
from __future__ import annotations

import inspect
import math
import re
import time
import warnings
from dataclasses import dataclass, field

import numpy as np

from ...data import InputError, TractionModel, get_traction_model, load_bearing
from ...data.errors import (LENGTH_MISTAKES, check_finite, check_integer, check_number, check_plausible,
                            check_temperature)
from ...data import lubricants_temperature as _lt
from ...data.cages import check_cage_temperature
from ...physics import thermal as th
from ...physics.lubricant_properties import lubricant_at, properties_at
from .losses import cage_land_geometry, power_losses
from .solution import QuasiStaticSolution
from .solve import check_traction_resolution, solve_quasistatic
from .inertia import check_ball_inertia

__all__ = ["CAGE_NODE", "NODES", "THERMAL_UNITS", "ThermalConvergenceWarning", "ThermalRunawayError", "ThermalSolution",
           "solve_thermal", "thermal_lubricant"]

#: Nodes of the network, in the order of its matrices; a bearing with a cage adds :data:`CAGE_NODE` last.
NODES = ("inner", "outer", "ball", "oil")
#: The cage's node (present when the loss module's cage guidance is not "none").
CAGE_NODE = "cage"

#: Units of the keys :meth:`ThermalSolution.to_dict` adds.
THERMAL_UNITS = {
    "temperatures": "K per node (inner ring, outer ring, balls, oil = outlet: fully mixed cavity; cage when the "
                    "bearing has one)",
    "contact_temperature": "K (the lubricant's temperature in the contacts: (T_inner + T_outer + 2 T_ball) / 4)",
    "heat": "W generated at each node",
    "heat_out": "W leaving through the oil (m_dot c_p (T_out - T_in)) and to the ambient",
    "conductances": "W/K between the nodes and to the boundaries",
    "thermal_energy_residual": "W (heat generated - heat out)",
    "cage_temperature_limit": "the rigid cage's material, its permissible temperature [K] and whether the cage node "
                              "stays within it (None without a rigid cage)",
}

#: Width of a ring over which the oil washes it, in ball diameters (B / D_w about 1.4 for
#: the 62 and 72 series: 6208 18 / 12.7 mm).
RING_WIDTH_PER_BALL_DIAMETER = 1.4


class ThermalRunawayError(InputError):
    """The thermal loop left the lubricant's temperature range: runaway or too little cooling."""


class ThermalConvergenceWarning(UserWarning):
    """The thermal loop did not converge within its iterations."""


@dataclass
class ThermalSolution:
    """Result of :func:`solve_thermal` (SI units, temperatures in K)."""

    quasistatic: object
    temperatures: dict
    contact_temperature: float
    heat: dict
    heat_out: dict
    conductances: dict
    losses: dict
    lubricant: object
    iterations: int
    converged: bool
    oil_inlet_temperature: float
    ambient_temperature: float
    oil_flow: float
    history: list = field(default_factory=list)
    wall_s: float = 0.0
    #: the rigid cage's material check: {"material", "temperature_limit" [K], "within"}; None without a
    #: rigid cage (the loss module's cage has no material)
    cage_limit: dict | None = None

    @property
    def energy_residual(self) -> float:
        """Heat generated minus heat leaving [W] (zero to the linear solve's round-off at each
        iteration's losses; the losses of the last quasi-static solve are the ones balanced)."""
        return float(sum(self.heat.values()) - sum(self.heat_out.values()))

    @property
    def power_loss_total(self) -> float:
        return float(self.losses["power_loss_total"])

    def to_dict(self) -> dict:
        """The quasi-static solution's dict, its loss keys from this solution's losses, and the
        thermal keys of :data:`THERMAL_UNITS`."""
        d = self.quasistatic.to_dict()
        d.update({k: v for k, v in self.losses.items()})
        d["temperatures"] = dict(self.temperatures)
        d["contact_temperature"] = self.contact_temperature
        d["heat"] = dict(self.heat)
        d["heat_out"] = dict(self.heat_out)
        d["conductances"] = dict(self.conductances)
        d["thermal_energy_residual"] = self.energy_residual
        d["thermal"] = {"iterations": self.iterations, "converged": self.converged,
                        "oil_inlet_temperature": self.oil_inlet_temperature, "oil_flow": self.oil_flow,
                        "ambient_temperature": self.ambient_temperature, "wall_s": self.wall_s}
        d["cage_temperature_limit"] = dict(self.cage_limit) if self.cage_limit else None
        d["units"] = {**d.get("units", {}), **THERMAL_UNITS}
        return d


def thermal_lubricant(bearing, lubricant=None):
    """The lubricant with temperature (``lubricants_temperature.json``) of a thermal solve: the
    name or entry given, else the bearing's lubricant name, or that name without a ``_<T>K`` suffix
    (the catalogue's ``MIL-L-23699_492K`` is ``MIL-L-23699`` at 492 K)."""
    if lubricant is not None:
        return _lt.get_lubricant_temperature(lubricant)
    name = getattr(bearing, "lubricant", None) or "guessasma2018"
    for cand in (name, re.sub(r"_\d+(\.\d+)?K$", "", name)):
        if cand in _lt.lubricants_temperature:
            return _lt.lubricants_temperature[cand]
    raise InputError(f"lubricant: the bearing's lubricant {name!r} has no entry with temperature; pass "
                     f"lubricant= one of {', '.join(_lt.lubricants_temperature)}")


def _default_ambient_conductance(b) -> dict:
    """Rings to the ambient [W/K]: free convection (AIR_FREE_CONVECTION) from a housing of twice the
    outer raceway radius and four ball diameters long, and from a shaft of the inner raceway radius
    exposed over four ball diameters (an order of magnitude; pass measured values when known)."""
    d = 2.0 * b.ball_radius
    r_i, r_o = b.pitch_radius - b.ball_radius, b.pitch_radius + b.ball_radius
    return {"inner": th.AIR_FREE_CONVECTION * 2.0 * math.pi * r_i * 4.0 * d,
            "outer": th.AIR_FREE_CONVECTION * 2.0 * math.pi * 2.0 * r_o * 4.0 * d}


def _cage_surface_area(b) -> float:
    """Oil-washed area of the cage [m^2]: both cylindrical faces of a ring at the pitch radius as wide as
    the rings (RING_WIDTH_PER_BALL_DIAMETER D), less the Z pockets of the ball's diameter on each face
    (an assumed shape: the catalogue gives no cage dimensions)."""
    d = 2.0 * b.ball_radius
    return 2.0 * (2.0 * math.pi * b.pitch_radius * RING_WIDTH_PER_BALL_DIAMETER * d
                  - b.n_balls * math.pi * b.ball_radius ** 2)


def _cage_options(b, guidance, pocket_clearance, pocket_share, loss_options, rigid=None) -> dict | None:
    """The cage's thermal data for a cage guidance of the loss module: None without a cage, else the
    pocket clearance [m] (given, else the bearing's ``cage_pocket_clearance``), the pocket heat share
    and the land geometry (``cage_land_geometry`` with the loss options' land values) of a land-guided
    cage. With the quasi-static solution's rigid cage (``rigid``, a RigidCage) its pocket clearance, land
    and surface are the RigidCage's (a given ``cage_pocket_clearance`` conflicts: InputError). InputError
    naming the parameter for a clearance <= 0 or a share outside [0, 1]."""
    if guidance == "none":
        return None
    if rigid is not None:
        if pocket_clearance is not None:
            raise InputError("cage_pocket_clearance: the solution has the rigid cage, whose RigidCage gives the "
                             "pocket clearance (solve_quasistatic's rigid_cage); leave it out")
        pocket_clearance = rigid.pocket_clearance
    if pocket_clearance is None:
        pocket_clearance = b.cage_pocket_clearance
        if pocket_clearance is None:
            raise InputError(f"cage_pocket_clearance: bearing {b.name!r} has no cage geometry in the catalogue but "
                             f"cage_guidance {guidance!r}; give the pocket clearance per side [m]")
    c_p = check_number("cage_pocket_clearance", pocket_clearance)
    if not c_p > 0.0:  # infinity allowed: no pocket film
        raise InputError(f"cage_pocket_clearance: must be > 0 m (the oil gap per side between a ball and its "
                         f"pocket), got {pocket_clearance!r}")
    if math.isfinite(c_p):  # a gap up to the ball radius (pockets are some 0.1-1 mm larger than the ball)
        check_plausible("cage_pocket_clearance", c_p, 1e-7, b.ball_radius, "m", "lengths are in metres (the gap "
                        "per side, at most the ball radius; infinity: no pocket film)", LENGTH_MISTAKES)
    share = check_finite("cage_pocket_heat_share", pocket_share)
    if not 0.0 <= share <= 1.0:
        raise InputError(f"cage_pocket_heat_share: must lie in [0, 1] (the cage's share of the pocket friction "
                         f"heat), got {pocket_share!r}")
    land = None
    if rigid is not None:
        area = _rigid_cage_surface_area(b, rigid)
        if guidance != "ball":
            land = {"radius": rigid.guide_radius, "width": rigid.land_width, "clearance": rigid.land_clearance,
                    "source": "the solution's RigidCage"}
    else:
        area = _cage_surface_area(b)
        if guidance in ("outer_land", "inner_land"):
            land = cage_land_geometry(b, guidance, loss_options.get("cage_land_radius"),
                                      loss_options.get("cage_land_width"), loss_options.get("cage_land_clearance"))
    return {"guidance": guidance, "pocket_clearance": c_p, "pocket_share": share, "land": land, "area": area}


def _rigid_cage_surface_area(b, rc) -> float:
    """Oil-washed area of a rigid cage [m^2]: its two cylindrical faces (R_ci and R_co, the width w) less
    the Z pockets' openings (pi (R_b + c_p)^2 on each face)."""
    pocket = math.pi * (b.ball_radius + rc.pocket_clearance) ** 2
    return 2.0 * math.pi * (rc.inner_radius + rc.outer_radius) * rc.width - 2.0 * b.n_balls * pocket


def _network(b, sol, losses, oil, t_inlet, t_amb, m_dot, q_vol, g_amb, k_solid, cage=None):
    """Heat sources, conductance matrices and boundaries of the network at one quasi-static solution
    (four nodes, five with ``cage``: the dict of :func:`_cage_options`)."""
    bl = sol.balls
    r_b = b.ball_radius
    d = 2.0 * r_b
    z = b.n_balls
    # heat: each contact's traction + EHL rolling + hysteresis, shared between ball and ring
    q_in = np.asarray(bl["dissipation_inner_ball"], float) + np.asarray(losses["power_loss_inner_ball"], float)
    q_out = np.asarray(bl["dissipation_outer_ball"], float) + np.asarray(losses["power_loss_outer_ball"], float)
    s_in = th.contact_heat_share(bl["u_roll_inner"], bl["u_roll_inner"])  # ring share (same speed: 1/2)
    s_out = th.contact_heat_share(bl["u_roll_outer"], bl["u_roll_outer"])
    heat_inner = float(np.sum(s_in * q_in))
    heat_outer = float(np.sum(s_out * q_out))
    heat_ball = float(np.sum((1.0 - s_in) * q_in) + np.sum((1.0 - s_out) * q_out))
    heat_cage = 0.0
    if cage is not None:  # pocket friction: the given share to the cage; land friction: half to each wall
        p_pocket, p_land = float(losses["power_loss"]["cage_pocket"]), float(losses["power_loss"]["cage_land"])
        heat_cage = cage["pocket_share"] * p_pocket + 0.5 * p_land
        heat_ball += (1.0 - cage["pocket_share"]) * p_pocket
        if cage["guidance"] == "inner_land":
            heat_inner += 0.5 * p_land
        elif cage["guidance"] == "outer_land":
            heat_outer += 0.5 * p_land
    heat_oil = float(losses["power_loss_total"]) - heat_inner - heat_outer - heat_ball - heat_cage  # drag, churning
    # conductances: contacts (constriction), convection to the oil, ambient, oil outflow
    g_ib = float(np.sum(th.constriction_conductance(bl["a_inner"], bl["b_inner"], k_solid, k_solid)))
    g_ob = float(np.sum(th.constriction_conductance(bl["a_outer"], bl["b_outer"], k_solid, k_solid)))
    pr = th.prandtl_number(oil["viscosity"], oil["specific_heat"], oil["thermal_conductivity"])
    w_m = float(np.mean(bl["orbital_speed"]))  # the oil in the cavity turns with the balls
    r_i, r_o = b.pitch_radius - r_b, b.pitch_radius + r_b
    width = RING_WIDTH_PER_BALL_DIAMETER * d

    # the oil's through-flow washes the surfaces also at rest: the larger of it and the rotation's speed
    u_flow = th.oil_through_flow_speed(q_vol, r_i, r_o, z, r_b)

    def h(speed):
        return th.flat_plate_heat_transfer(oil["thermal_conductivity"], np.maximum(np.abs(speed), u_flow),
                                           oil["kinematic_viscosity"], pr, d)

    g_io = h((sol.omega - w_m) * r_i) * 2.0 * math.pi * r_i * width
    g_oo = h((sol.omega_outer - w_m) * r_o) * 2.0 * math.pi * r_o * width
    v_ball = np.abs(np.asarray(bl["ball_speed"], float)) * r_b
    g_bo = float(np.sum(h(v_ball) * 4.0 * math.pi * r_b * r_b))
    g_oil_out = m_dot * oil["specific_heat"]
    links = {(0, 2): g_ib, (1, 2): g_ob, (0, 3): g_io, (1, 3): g_oo, (2, 3): g_bo}
    cond = {"inner_ball": g_ib, "outer_ball": g_ob, "inner_oil": float(g_io), "outer_oil": float(g_oo),
            "ball_oil": g_bo}
    heat = [heat_inner, heat_outer, heat_ball, heat_oil]
    if cage is not None:
        # pocket films (two walls per ball, each at the pocket clearance), the land film, convection at the
        # cage's speed relative to the oil (both turn at the balls' mean orbital speed: the through-flow speed)
        k_oil = oil["thermal_conductivity"]
        g_cb = float(2.0 * z * th.sphere_wall_gap_conductance(k_oil, r_b, cage["pocket_clearance"]))
        g_co = float(h(0.0) * cage["area"])
        links[(2, 4)], links[(3, 4)] = g_cb, g_co
        cond.update({"ball_cage": g_cb, "cage_oil": g_co})
        if cage["land"] is not None:
            land = cage["land"]
            ring = 0 if cage["guidance"] == "inner_land" else 1
            g_cl = float(th.film_conductance(k_oil, 2.0 * math.pi * land["radius"] * land["width"], land["clearance"]))
            links[(ring, 4)] = g_cl
            cond[f"{NODES[ring]}_cage"] = g_cl
        heat.append(heat_cage)
    n = len(heat)
    G = np.zeros((n, n))
    for (i, j), g in links.items():
        G[i, j] = G[j, i] = g
    gb = np.zeros((n, 2))  # boundaries: ambient, oil inlet
    gb[0, 0], gb[1, 0], gb[3, 1] = g_amb["inner"], g_amb["outer"], g_oil_out
    cond.update({"inner_ambient": g_amb["inner"], "outer_ambient": g_amb["outer"], "oil_outflow": float(g_oil_out),
                 "n_balls": z})
    return np.array(heat), G, gb, np.array([t_amb, t_inlet]), cond


def solve_thermal(bearing, Fr=0.0, Fa=0.0, *, omega, oil_inlet_temperature, oil_flow,
                  ambient_temperature=293.15, lubricant=None, traction=None, lubrication="jet",
                  oil_volume_fraction=0.0, ambient_conductance=None,
                  solid_conductivity=th.BEARING_STEEL_CONDUCTIVITY, tolerance=0.01, max_iterations=60,
                  relaxation=1.0, start=None, cage_guidance=None, cage_pocket_clearance=None,
                  cage_pocket_heat_share=0.5, loss_options=None, **quasistatic) -> ThermalSolution:
    """Temperatures and losses of a bearing at speed, consistent with each other.

    Parameters
    ----------
    bearing : BallBearing or str
    Fr, Fa : float
        Radial and axial load on the inner ring [N].
    omega : float
        Inner-ring speed [rad/s].
    oil_inlet_temperature : float
        Temperature of the oil entering the bearing [K] (within the lubricant's range).
    oil_flow : float
        Volume flow of oil through the bearing [m^3/s] (> 0: a jet-lubricated bearing is cooled
        by it).
    ambient_temperature : float
        Air around the housing and the shaft [K].
    lubricant : str or LubricantTemperatureData, optional
        An entry of ``lubricants_temperature.json`` (default: the bearing's, :func:`thermal_lubricant`).
    traction : str or TractionModel, optional
        As in :func:`~.solve.solve_quasistatic`; an ``ehl`` model takes the viscosity and
        pressure-viscosity coefficient of the lubricant at the contact temperature.
    lubrication : {"jet"}
        The lubrication method (jet: the oil flow carries the heat out).
    oil_volume_fraction : float
        Oil's share of the cavity the balls orbit through, for the drag (power_losses).
    ambient_conductance : dict, optional
        ``{"inner": W/K, "outer": W/K}`` from the rings to the ambient through the shaft and the
        housing (default, also for a key left out: free convection from a nominal housing and shaft;
        another key is refused).
    solid_conductivity : float
        Thermal conductivity of rings and balls [W/(m K)].
    tolerance : float
        Largest temperature change between iterations at convergence [K].
    max_iterations : int
    relaxation : float
        Relaxation of the first temperature update, 0 < w <= 1 (later steps: the secant slope).
    start : ThermalSolution or QuasiStaticSolution, optional
        A solution at a nearby operating point (the previous speed of a sweep): its temperatures and
        its quasi-static solution start the iteration (a QuasiStaticSolution: the quasi-static
        iteration only; the temperatures start at the oil inlet's).
    cage_guidance : str, optional
        As in :func:`~.losses.power_losses` (default "ball" for a bearing with a cage, "none" without);
        any guidance but "none" adds the cage node.
    cage_pocket_clearance : float, optional
        Oil gap per side between a ball and its pocket [m] for the pocket films' conductance (default
        the bearing's ``cage_pocket_clearance``; needed for a bearing without cage geometry; infinity:
        no pocket film).
    cage_pocket_heat_share : float
        Share of the pocket friction heat that enters the cage [-], the rest the balls (default 1/2,
        docs/theory/thermal.md).
    loss_options : dict, optional
        Further keywords of :func:`~.losses.power_losses` (``cage_pocket_friction``,
        ``cage_land_radius``, ``cage_land_width``, ``cage_land_clearance``, ``hysteresis_loss_factor``,
        ...); the land values also set the land film's conductance.
    **quasistatic
        Further arguments of :func:`~.solve.solve_quasistatic` (``control``, ``fit``, ...; not
        ``temperatures``, which the network sets). The traction resolution and the balls' inertia are
        checked once, at the last solution (:func:`~.solve.check_traction_resolution`,
        :func:`~.inertia.check_ball_inertia`).

    Returns
    -------
    ThermalSolution
    """
    t0 = time.perf_counter()
    b = load_bearing(bearing)
    if lubrication != "jet":
        raise InputError(f"lubrication: only 'jet' (oil flow through the bearing) is modelled, got {lubrication!r}")
    q_vol = check_finite("oil_flow", oil_flow)
    if not q_vol > 0.0:
        raise InputError(f"oil_flow: a jet-lubricated bearing needs an oil flow > 0 m^3/s to carry its heat out, "
                         f"got {q_vol:g} (1 l/min is 1.667e-5 m^3/s)")
    if q_vol > 1e-2:
        raise InputError(f"oil_flow: {q_vol:g} m^3/s is over 600 l/min through one bearing (flows are in m^3/s: "
                         f"1 l/min is 1.667e-5 m^3/s)")
    lt = thermal_lubricant(b, lubricant)
    lo, hi = lt.temperature_range
    t_in = check_temperature("oil_inlet_temperature", oil_inlet_temperature)
    if not lo <= t_in <= hi:
        raise InputError(f"oil_inlet_temperature: {t_in:g} K is outside the range of lubricant {lt.name!r} "
                         f"({lo:g}-{hi:g} K)")
    t_amb = check_temperature("ambient_temperature", ambient_temperature)
    w = check_finite("relaxation", relaxation)
    if not 0.0 < w <= 1.0:
        raise InputError(f"relaxation: must lie in (0, 1], got {w!r}")
    n_iter = check_integer("max_iterations", max_iterations)
    tol = check_finite("tolerance", tolerance)
    if n_iter < 1 or not tol > 0.0:
        raise InputError(f"max_iterations, tolerance: need >= 1 and > 0 K, got {max_iterations!r}, {tolerance!r}")
    k_solid = check_finite("solid_conductivity", solid_conductivity)
    if not k_solid > 0.0:
        raise InputError(f"solid_conductivity: must be > 0 W/(m K), got {k_solid!r}")
    if ambient_conductance is not None and not isinstance(ambient_conductance, dict):
        raise InputError(f"ambient_conductance: expected a dict {{'inner': W/K, 'outer': W/K}}, got "
                         f"{ambient_conductance!r}")
    _check_names("ambient_conductance", "key", ambient_conductance or {}, ("inner", "outer"))
    g_amb = {**_default_ambient_conductance(b), **(ambient_conductance or {})}  # a key left out: its default
    for k in ("inner", "outer"):
        g_amb[k] = check_finite(f"ambient_conductance.{k}", g_amb[k])
        if g_amb[k] < 0.0:
            raise InputError(f"ambient_conductance.{k}: must be >= 0 W/K, got {g_amb[k]!r}")
    if loss_options is not None and not isinstance(loss_options, dict):
        raise InputError(f"loss_options: expected a dict of power_losses keywords, got {loss_options!r}")
    _check_names("loss_options", "keyword of power_losses", loss_options or {}, _LOSS_KEYWORDS)
    if start is not None and not isinstance(start, (ThermalSolution, QuasiStaticSolution)):
        raise InputError(f"start: expected a ThermalSolution (or a QuasiStaticSolution) at a nearby operating "
                         f"point, got {start!r}")
    if "temperatures" in quasistatic:
        raise InputError("temperatures: set by the thermal network in solve_thermal (the part temperatures are "
                         "its result); leave it out, or call solve_quasistatic with fixed temperatures")
    _check_names("solve_thermal", "keyword argument", quasistatic, _QUASISTATIC_KEYWORDS)
    final_check = quasistatic.pop("resolution_check", True)
    final_inertia = quasistatic.pop("inertia_check", True)
    loss_options = dict(loss_options or {})
    for k in ("oil_volume_fraction", "oil_density", "cage_guidance", "lubricant", "bearing"):
        if k in loss_options:
            raise InputError(f"loss_options: {k!r} is set by solve_thermal (its own argument, or the oil's "
                             "properties at its temperature), not in loss_options")
    loss_options.update(oil_volume_fraction=oil_volume_fraction, cage_guidance=cage_guidance)
    tm0 = get_traction_model(traction, b)
    quasistatic.setdefault("stiffness", False)
    rho_in = properties_at(lt, t_in)["density"]
    m_dot = rho_in * q_vol

    sol, cage, nodes = None, None, NODES
    temps = np.full(len(nodes), t_in)
    if isinstance(start, QuasiStaticSolution):
        sol = start
    elif start is not None:
        temps = np.minimum(np.array([start.temperatures[n] for n in NODES], float), hi)
        sol = start.quasistatic
    history, converged, it, clamped, prev = [], False, 0, False, None
    for it in range(1, n_iter + 1):
        t_contact = float((temps[0] + temps[1] + 2.0 * temps[2]) / 4.0)
        lub = lubricant_at(lt, t_contact)
        tm = _traction_at(tm0, lub, t_contact)
        oil = properties_at(lt, temps[3])
        sol = solve_quasistatic(b, Fr, Fa, omega=omega, traction=tm, lubricant=lub, start=sol,
                                temperatures={"inner": float(temps[0]), "outer": float(temps[1]),
                                              "ball": float(temps[2])}, resolution_check=False, inertia_check=False,
                                **quasistatic)
        losses = power_losses(sol, b, lub, oil_density=oil["density"], **loss_options)
        if it == 1:  # the cage node: its data once, its start temperature the previous solution's or the oil's
            rigid = sol.cage["rigid_cage"] if sol.cage is not None else None
            cage = _cage_options(b, losses["cage_guidance"], cage_pocket_clearance, cage_pocket_heat_share,
                                 loss_options, rigid)
            if cage is not None:
                nodes = NODES + (CAGE_NODE,)
                t_cage = (start.temperatures.get(CAGE_NODE, temps[3]) if isinstance(start, ThermalSolution)
                          else temps[3])
                temps = np.append(temps, min(float(t_cage), hi))
        heat, G, gb, tb, cond = _network(b, sol, losses, oil, t_in, t_amb, m_dot, q_vol, g_amb, k_solid, cage)
        try:
            t_new = th.network_temperatures(G, heat, gb, tb)
        except np.linalg.LinAlgError:
            raise InputError("thermal network: a node has no path for its heat to the oil or the ambient "
                             f"(conductances {cond}); a bearing at rest without load has none") from None
        step = float(np.max(np.abs(t_new - temps)))
        history.append({"iteration": it, "temperatures": dict(zip(nodes, map(float, t_new))),
                        "power_loss_total": float(losses["power_loss_total"]), "change": step})
        if not np.all(np.isfinite(t_new)):
            raise ThermalRunawayError(f"oil_flow: the thermal loop's temperatures are not finite at iteration {it} "
                                      f"(power loss {losses['power_loss_total']:.4g} W): more oil_flow, a lower "
                                      "oil_inlet_temperature or a lower speed")
        if step < tol:
            converged = True
            temps = t_new
            break
        # secant relaxation of the mean temperature x -> g(x): slope lam of g from the last two iterates,
        # step 1 / (1 - lam) (Wegstein), bounded to [relaxation / 2, 2]; the first step is the plain relaxation.
        # The mean is over the four nodes of the cageless network (the cage's temperature enters neither the
        # quasi-static solve nor the losses)
        x, gx = float(np.mean(temps[:4])), float(np.mean(t_new[:4]))
        step_w = w
        if prev is not None and abs(x - prev[0]) > 1e-9:
            lam = (gx - prev[1]) / (x - prev[0])
            step_w = float(np.clip(1.0 / (1.0 - lam), 0.5 * w, 2.0)) if lam < 1.0 else w
        prev = (x, gx)
        temps = temps + step_w * (t_new - temps)
        hot = temps > hi
        if np.any(hot):  # an overshoot is clamped to the range's top; the same again is runaway
            if clamped:
                _runaway(lt, t_new, it, nodes)
            temps = np.minimum(temps, hi)
        clamped = bool(np.any(hot))
    out_heat = th.network_heat_out(temps, gb, tb)
    if final_check:  # the traction integration, once at the last quasi-static solution
        sol.resolution_check = check_traction_resolution(sol)
    if final_inertia:  # the balls' inertia along the orbit, once at the last quasi-static solution
        sol.inertia_check = check_ball_inertia(sol, b)
    temperatures = dict(zip(nodes, map(float, temps)))
    cage_limit = None
    if cage is not None and sol.cage is not None and sol.cage.get("rigid_cage") is not None:
        # the rigid cage's material has a permissible temperature (the loss module's cage has no material)
        mat = sol.cage["rigid_cage"].material
        cage_limit = {"material": mat.name, "temperature_limit": mat.temperature_limit,
                      "within": check_cage_temperature(temperatures[CAGE_NODE], mat, "cage temperature")}
    if not converged:
        warnings.warn(ThermalConvergenceWarning(
            f"thermal loop: not converged in {it} iterations (last change {step:.3g} K > {tol:g} K); "
            "temperatures reached " + ", ".join(f"{n} {t:.1f} K" for n, t in zip(nodes, temps))), stacklevel=2)
    return ThermalSolution(
        quasistatic=sol, temperatures=temperatures, contact_temperature=t_contact, cage_limit=cage_limit,
        heat=dict(zip(nodes, map(float, heat))), heat_out={"oil": float(out_heat[1]), "ambient": float(out_heat[0])},
        conductances=cond, losses=losses, lubricant=lub, iterations=it, converged=converged,
        oil_inlet_temperature=t_in, ambient_temperature=t_amb, oil_flow=q_vol, history=history,
        wall_s=time.perf_counter() - t0)


#: Keywords of power_losses that loss_options may carry, and of solve_quasistatic that **quasistatic may.
_LOSS_KEYWORDS = tuple(k for k in inspect.signature(power_losses).parameters if k != "sol")
_QUASISTATIC_KEYWORDS = tuple(k for k in inspect.signature(solve_quasistatic).parameters
                              if k not in ("bearing", "Fr", "Fa", "omega", "traction", "lubricant", "start",
                                           "temperatures"))


def _check_names(name, what, given, valid):
    """InputError "name: unknown what 'key' (valid: ...)" for the first key of ``given`` not in ``valid``."""
    unknown = sorted(set(given) - set(valid), key=str)
    if unknown:
        raise InputError(f"{name}: unknown {what} {unknown[0]!r} (valid: {', '.join(sorted(valid))})")


def _traction_at(model, lub, t_contact):
    """An ``ehl`` traction model with the viscosity and pressure-viscosity coefficient of the lubricant
    at the contact temperature (named ``name@TK``); other kinds unchanged (they follow the film)."""
    if model.kind != "ehl":
        return model
    p = {**model.parameters, "viscosity": lub.viscosity, "pressure_viscosity": lub.pressure_viscosity}
    return TractionModel(model.kind, p, f"{model.name}@{t_contact:.5g}K", model.validity,
                         f"{model.source}; viscosity and pressure-viscosity of {lub.name}")


def _runaway(lt, temps, iteration: int, nodes=NODES):
    """ThermalRunawayError naming the hottest node and the temperature the network reached."""
    lo, hi = lt.temperature_range
    k = int(np.argmax(temps))
    raise ThermalRunawayError(
        f"oil_flow: thermal runaway, the {nodes[k]} node reached {temps[k]:.1f} K at iteration {iteration} "
        f"with the lubricant at the top of its range, above the range of lubricant {lt.name!r} ({lo:g}-{hi:g} K); "
        "more oil_flow, a lower oil_inlet_temperature or a lower speed")
