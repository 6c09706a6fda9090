"""The solution record of the quasi-static solver and its JSON form."""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ...data import InputError
from ...model.initial_state import state_from_ball_kinematics
from .losses import LOSS_UNITS, loss_keys

__all__ = ["QuasiStaticSolution", "UNITS"]

#: Units of the keys of :meth:`QuasiStaticSolution.to_dict`.
UNITS = {
    "delta_x": "m", "delta_y": "m", "delta_a": "m (axial, from the centred ring)", "tilt_x": "rad",
    "tilt_y": "rad", "psi": "deg", "q_inner": "N", "q_outer": "N", "alpha_inner": "deg", "alpha_outer": "deg",
    "a_inner": "m", "b_inner": "m", "a_outer": "m", "b_outer": "m", "p_max_inner": "Pa", "p_max_outer": "Pa",
    "delta_inner": "m", "delta_outer": "m", "centrifugal_force": "N", "gyroscopic_moment": "N m",
    "orbital_speed": "rad/s", "pivot_slip": "m/s (transverse slip of the ball's yaw, control equilibrium)", "ball_speed": "rad/s (about its own axis, in the orbiting frame)",
    "ball_speed_absolute": "rad/s", "beta": "deg", "spin_roll_inner": "-", "spin_roll_outer": "-",
    "rolling_point_outer": "m (x1, along the major axis from the centre)",
    "rolling_point_inner": "m (x2)", "dissipation_inner": "W (whole bearing)",
    "dissipation_outer": "W (whole bearing)", "dissipation_total": "W (whole bearing)",
    "dissipation_inner_ball": "W", "dissipation_outer_ball": "W",
    "friction_torque": "N m (the whole bearing's friction torque: friction_torque_total, every modelled loss over "
                       "the relative ring speed, as the text output prints; None when the losses are not computed)",
    "traction_drive_torque": "N m (axial torque of the inner contacts' tractions on the balls; the traction "
                             "dissipation over omega only in the traction equilibrium: a kinematic hypothesis "
                             "leaves a net traction on the balls, energy_residual)",
    "drive_power": "W (traction_drive_torque omega + outer-ring torque omega_outer; with the rigid cage + the land "
                   "film's torque on the cage times its guiding ring's speed)",
    "energy_residual": "- ((drive_power - dissipation_total) / drive_power; 0 in the traction equilibrium and "
                       "without relative speed of the rings)",
    "drive_torque_inner_ball": "N m (axial torque of the inner contact's traction on the ball)",
    "drive_torque_outer_ball": "N m (axial torque of the outer contact's traction on the ball)", "qv_inner_ball": "N m/s",
    "qv_outer_ball": "N m/s", "qv_total": "N m/s (whole bearing)", "traction_drag": "N (sum of the rolling-direction traction on the ball: zero in a true steady state without cage)",
    "gyro_traction_inner": "- (traction / load the inner race must supply for the gyroscopic moment)",
    "gyro_traction_outer": "-", "h_central_inner": "m", "h_central_outer": "m", "u_roll_inner": "m/s",
    "u_roll_outer": "m/s", "slip_y": "- (y/a at the strip centres)", "slip_inner": "m/s", "slip_outer": "m/s",
    "inner_ring_growth": "m", "outer_ring_growth": "m", "inner_thermal_growth": "m", "outer_thermal_growth": "m",
    "ball_thermal_growth": "m", "fit_pressure": "Pa", "operating_clearance": "m", "axial_play": "m",
    "control_used": "kinematics per ball (outer, inner, min-energy, equilibrium, cage: carried at the cage speed, "
                    "no traction equilibrium of its own; none)",
    "stiffness": "N/m, N/rad, N m/m, N m/rad (order delta_x, delta_y, delta_a, tilt_x, tilt_y)",
    "damping": "N s/m, N s/rad, N s, N m s/rad (order delta_x, delta_y, delta_a, tilt_x, tilt_y)",
    "h_min_inner": "m", "h_min_outer": "m",
    "c_normal_inner": "N s/m (normal damping of the contact model at the contact)", "c_normal_outer": "N s/m",
    "c_hysteretic_inner": "N s/m", "c_hysteretic_outer": "N s/m",
    "c_squeeze_inner": "N s/m (NaN without film)", "c_squeeze_outer": "N s/m (NaN without film)",
    "film_parameter_inner": "-", "film_parameter_outer": "-",
    "regime_inner": "code (0 boundary, 1 mixed, 2 full film, -1 no contact)", "regime_outer": "code",
    "traction_resolution": "dissipation [W] at n_strips x n_across and at twice both, relative change, "
                           "converged (within 1 %), needed (n_strips, n_across) (None: no relative speed)",
    "reactions": "N or N m", "residual": "N or N m", "loads": "N or N m", "omega": "rad/s", "omega_outer": "rad/s",
    "cage": "text (rigid, or None: no cage, each ball its own orbital speed)",
    "cage_speed": "rad/s (the rigid cage's and every ball's orbital speed)",
    "pocket_force": "N (pocket force on each ball along its orbit, positive pushing it forward; rigid cage)",
    "pocket_sliding_speed": "m/s (the ball's surface against its pocket at the contact point; rigid cage)",
    "cage_power_pocket": "W (rigid cage: pocket friction, mu_c |Q_p| times the sliding speed, and with the pocket "
                         "film its shear, cage_power_pocket_film)",
    "pocket_film": "bool (rigid cage: the ball / pocket oil film modelled, solve_quasistatic's pocket_film)",
    "cage_power_pocket_film": "W (rigid cage with the pocket film: the film's shear, part of cage_power_pocket)",
    "pocket_contact_force": "N (the part of pocket_force the pocket wall's contact carries, the rest the pocket "
                            "film's pressure; rigid cage)",
    "pocket_film_power": "W (each ball's pocket film shear; rigid cage)",
    "pocket_film_gap": "m (the pocket film's gap at the wall a held ball presses on; rigid cage with the film)",
    "cage_power_land": "W (rigid cage: land shear torque times the cage's speed relative to its ring)",
    "cage_land_force": "N (net in-plane pocket force the land film carries)",
    "cage_land_eccentricity": "- (land film eccentricity ratio carrying cage_land_force)",
    "cage_torque_residual": "- (cage torque balance over the absolute torques on the cage and the tractions' "
                            "torques along the orbit)",
    "rigid_cage": "the RigidCage's fields (m; material by name)",
}


def _rigid_cage_dict(rc) -> dict:
    """JSON-ready fields of a RigidCage (the material by name, ``estimated`` as a list)."""
    return {"guidance": rc.guidance, "pocket_shape": rc.pocket_shape, "pocket_clearance": rc.pocket_clearance,
            "inner_radius": rc.inner_radius, "outer_radius": rc.outer_radius, "width": rc.width,
            "land_clearance": rc.land_clearance, "land_width": rc.land_width, "material": rc.material.name,
            "pocket_friction": rc.pocket_friction, "estimated": list(rc.estimated), "source": rc.source}


@dataclass
class QuasiStaticSolution:
    """Quasi-static equilibrium of a ball bearing: per-ball arrays in psi order and totals.

    Angles are stored in radians; :meth:`to_dict` gives degrees where its
    units map says so.
    """

    bearing_name: str
    loads: np.ndarray            #: (F_x, F_y, F_a, M_x, M_y) [N, N, N, N m, N m]
    omega: float                 #: inner-ring speed [rad/s]
    omega_outer: float           #: outer-ring speed [rad/s]
    control: str                 #: kinematic hypothesis asked for
    traction: str                #: traction model name
    lubricant: str               #: lubricant name
    displacement: np.ndarray     #: (delta_x, delta_y, delta_a, tilt_x, tilt_y)
    residual: np.ndarray         #: balls' generalized force + loads at the solution (5,)
    free: np.ndarray             #: which DOFs were solved (5,) bool
    held: dict                   #: DOF name -> why held ("fixed" or "symmetry")
    reactions: dict              #: DOF name -> reaction of the held DOF [N or N m]
    balls: dict                  #: per-ball arrays (module UNITS), radians for angles
    geometry: dict               #: operating geometry (growth, clearance, fit)
    stiffness: np.ndarray        #: (5, 5) = -d(balls' generalized force)/du
    stiffness_check: dict        #: step and convergence of the central differences
    damping: np.ndarray | None = None  #: (5, 5) = -d(balls' generalized force)/du' (:mod:`.damping`)
    minimum_checks: list = field(default_factory=list)  #: per-ball minimum-energy checks
    contact_geometry: np.ndarray | None = None  #: packed per-ball contact data (kinematics.GEO_FIELDS)
    kinematics: np.ndarray | None = None        #: per-ball (omega_m, w_r, w_z) [rad/s], pivot slip v_t [m/s]
    traction_model: object = None               #: the TractionModel used
    iterations: int = 0
    n_strips: int = 0
    n_across: int = 0
    wall_s: float = 0.0
    resolution_check: dict | None = None  #: check of the traction integration (solve.check_traction_resolution)
    cage: dict | None = None  #: the rigid cage's speed, losses, land (solve._cage_result); None: no cage
    inertia_check: dict | None = None  #: can the balls follow the kinematics along the orbit (inertia.check_ball_inertia)
    #: psi -> packed contact geometry rows (kinematics.GEO_FIELDS) of a ball at the azimuths psi [rad] under the
    #: solution's ring pose (solve._geometry_at; the orbit march's, orbit.py); None where not solved
    geometry_at: object = field(default=None, repr=False, compare=False)

    # convenient totals -------------------------------------------------------------
    @property
    def dissipation_inner(self) -> float:
        return float(np.sum(self.balls["dissipation_inner_ball"]))

    @property
    def dissipation_outer(self) -> float:
        return float(np.sum(self.balls["dissipation_outer_ball"]))

    @property
    def dissipation_total(self) -> float:
        """Frictional power of all ball / race contacts [W]."""
        return self.dissipation_inner + self.dissipation_outer

    @property
    def friction_torque(self) -> float:
        """Torque that drives the inner ring [N m] (whole bearing; positive when it must be driven):
        the axial torque of the tractions of the inner contacts on the balls (``traction_drive_torque`` of
        :meth:`to_dict`, whose ``friction_torque`` is the whole loss's ``friction_torque_total``). It carries
        the traction dissipation only in the traction equilibrium; under a kinematic hypothesis
        (race control, minimum energy) it includes the net traction the hypothesis leaves on the balls
        (``energy_residual``)."""
        return float(np.sum(self.balls["drive_torque_inner_ball"]))

    @property
    def cage_power(self) -> float:
        """Power lost in the rigid cage's pockets and land [W] (0 without the cage)."""
        return 0.0 if self.cage is None else self.cage["power_pocket"] + self.cage["power_land"]

    @property
    def drive_power(self) -> float:
        """Power the turning rings put into the bearing [W]: friction_torque omega + outer torque omega_outer,
        and with the rigid cage the power that holds the guiding ring's speed against the land film: the film
        puts -T_land on the ring (T_land, ``cage["land_torque"]``, the film's torque on the cage), so the ring's
        drive supplies T_land times the ring's speed (the film dissipates -T_land (omega_c - omega_ring), the
        cage's share -T_land omega_c coming through the pockets)."""
        p = (self.friction_torque * self.omega
             + float(np.sum(self.balls["drive_torque_outer_ball"])) * self.omega_outer)
        if self.cage is not None:
            p += self.cage["land_torque"] * self.cage["ring_speed"]
        return p

    @property
    def energy_residual(self) -> float:
        """(drive power - dissipation - cage_power) / drive power [-]: zero to round-off when every ball is in
        its steady traction equilibrium (control ``equilibrium``, with or without the rigid cage); a kinematic
        hypothesis (race control, minimum energy) leaves a net traction on the ball and shows here. 0 without
        drive power and without dissipation (no relative speed of the rings: nothing to balance); NaN only for
        a dissipation without drive power."""
        p = self.drive_power
        lost = self.dissipation_total + self.cage_power
        if p == 0.0:
            return 0.0 if lost == 0.0 else float("nan")
        return (p - lost) / p

    @property
    def q_max_inner(self) -> float:
        return float(np.max(self.balls["q_inner"]))

    @property
    def q_max_outer(self) -> float:
        return float(np.max(self.balls["q_outer"]))

    def to_dict(self, rating=None) -> dict:
        """JSON-ready dict with the keys of :data:`UNITS` (and ``units``). ``rating``: a
        :class:`~exudyn_bearing.physics.rating_life.RatingLife` of this solution
        (:func:`~exudyn_bearing.physics.rating_life.rating_life`) whose keys (``C``, ``C0``, ``s0``, ``L10``,
        ``L10h``, ``L10m``, ``L10mr``, ``a_iso``, ``kappa``, ...) and units are added."""
        b = self.balls
        deg = {"psi", "alpha_inner", "alpha_outer", "beta"}
        d = {"bearing": self.bearing_name, "control": self.control, "traction": self.traction,
             "lubricant": self.lubricant, "omega": self.omega, "omega_outer": self.omega_outer,
             "loads": dict(zip(("Fx", "Fy", "Fa", "Mx", "My"), map(float, self.loads)))}
        for k, v in zip(("delta_x", "delta_y", "delta_a", "tilt_x", "tilt_y"), self.displacement):
            d[k] = float(v)
        for k, v in b.items():
            arr = np.asarray(v)
            if arr.dtype == object:
                d[k] = [str(x) for x in arr]
                continue
            arr = arr.astype(float)
            d[k] = np.degrees(arr) if k in deg else arr
        d["dissipation_inner"] = self.dissipation_inner
        d["dissipation_outer"] = self.dissipation_outer
        d["dissipation_total"] = self.dissipation_total
        d["traction_drive_torque"] = self.friction_torque
        d["drive_power"] = self.drive_power
        d["energy_residual"] = self.energy_residual
        d["qv_total"] = float(np.sum(b["qv_inner_ball"]) + np.sum(b["qv_outer_ball"]))
        d["cage"] = "rigid" if self.cage is not None else None
        if self.cage is not None:
            c = self.cage
            d.update({"cage_speed": c["speed"],
                      "cage_power_pocket": c["power_pocket"], "cage_power_land": c["power_land"],
                      "pocket_film": bool(c.get("pocket_film", False)),
                      "cage_power_pocket_film": float(c.get("power_pocket_film", 0.0)),
                      "cage_land_force": c["land_force"],
                      "cage_land_eccentricity": c["land_eccentricity"], "cage_torque_residual": c["torque_residual"],
                      "rigid_cage": _rigid_cage_dict(c["rigid_cage"])})
        d.update(loss_keys(self))  # power_loss by component, power_loss_total, friction_torque_total (.losses)
        # the key means what the text output prints: the whole modelled loss's torque, not the traction's drive
        # torque of a kinematic hypothesis (95-99 % of which is its residual on the 6208 and 7208 under auto)
        d["friction_torque"] = d["friction_torque_total"]
        d.update(self.geometry)
        d["stiffness"] = self.stiffness
        d["stiffness_check"] = self.stiffness_check
        if self.damping is not None:
            d["damping"] = self.damping
        d["residual"] = dict(zip(("Fx", "Fy", "Fa", "Mx", "My"), map(float, self.residual)))
        d["held_dofs"] = dict(self.held)
        d["reactions"] = dict(self.reactions)
        d["minimum_checks"] = self.minimum_checks
        d["iterations"] = self.iterations
        d["n_strips"], d["n_across"] = self.n_strips, self.n_across
        d["traction_resolution"] = self.resolution_check
        d["ball_inertia"] = self.inertia_check
        d["wall_s"] = self.wall_s
        d["units"] = {**UNITS, **LOSS_UNITS}
        if rating is not None:
            from ...physics.rating_life import RATING_UNITS

            d.update(rating.to_dict())
            d["units"].update(RATING_UNITS)
        return d

    def dynamic_start(self, bearing) -> dict:
        """The solution as the initial state of a dynamic run (ball centres,
        orbital speeds and angular velocities, inner-ring displacement x, y,
        axial; :func:`exudyn_bearing.model.initial_state.state_from_ball_kinematics`).
        The dynamic engines' inner ring does not tilt: a solution with tilt
        is refused."""
        if np.any(np.abs(self.displacement[3:]) > 1e-12):
            raise InputError("initial: the quasi-static solution has a tilted inner ring, which the dynamic engines "
                             "cannot represent (their inner ring translates only): solve with the tilts fixed")
        b = self.balls
        r_b = bearing.ball_radius + self.geometry.get("ball_thermal_growth", 0.0)
        return state_from_ball_kinematics(bearing, b["psi"], b["ball_center_r"], b["ball_center_z"],
                                          self.kinematics[:, 0], self.kinematics[:, 1], self.kinematics[:, 2],
                                          self.displacement[:3], w_psi=self.kinematics[:, 3] / r_b,
                                          max_overlap=float(np.max(np.maximum(b["delta_outer"], b["delta_inner"]))))

    def summary(self) -> str:
        """A few lines for the command line."""
        g = self.geometry
        lines = [
            f"{self.bearing_name}: Fr = {self.loads[0]:g} N (x), Fy = {self.loads[1]:g} N, Fa = {self.loads[2]:g} N, "
            f"Mx = {self.loads[3]:g} N m, My = {self.loads[4]:g} N m, omega = {self.omega:g} rad/s, "
            + (f"omega_outer = {self.omega_outer:g} rad/s, " if self.omega_outer else "")
            + f"control {self.control}, traction {self.traction}",
            f"delta_x = {self.displacement[0] * 1e6:.3f} um, delta_y = {self.displacement[1] * 1e6:.3f} um, "
            f"delta_a = {self.displacement[2] * 1e6:.3f} um, tilt_x = {self.displacement[3] * 1e3:.4f} mrad, "
            f"tilt_y = {self.displacement[4] * 1e3:.4f} mrad",
            f"inner ring growth {g['inner_ring_growth'] * 1e6:.2f} um, operating clearance "
            f"{g['operating_clearance'] * 1e6:.2f} um, contact traction dissipation {self.dissipation_total:.4g} W "
            f"(inner {self.dissipation_inner:.4g}, outer {self.dissipation_outer:.4g}"
            + (f"; with the cage's pocket and land {self.dissipation_total + self.cage_power:.4g} W" if self.cage
               is not None else "") + ")",
        ]
        if self.cage is not None:
            c = self.cage
            lines.append(f"rigid cage ({c['guidance']}): speed {c['speed']:.6g} rad/s, largest steady pocket force "
                         f"{np.max(np.abs(self.balls['pocket_force'])):.4g} N (time mean per ball: the held force "
                         "times its share of the time; the dynamic engines' pocket_force_max is the largest impact), "
                         f"losses pocket {c['power_pocket']:.4g} W "
                         + (f"(of it the pocket film's shear {c['power_pocket_film']:.4g} W), " if c.get("pocket_film")
                            else "(no pocket film), ")
                         + f"land {c['power_land']:.4g} W (land torque {c['land_torque']:.4g} N m, eccentricity "
                         f"{c['land_eccentricity']:.3g})")
            lines.append("pocket force per ball [N] (+: pushes the ball forward): "
                         + " ".join(f"{q + 0.0:.4g}" for q in self.balls["pocket_force"]))  # + 0.0: no "-0"
        if self.inertia_check is not None:
            c = self.inertia_check
            lines.append(f"quasi-static hypothesis (the balls' inertia along the orbit): their changes of speed from one position to the next "
                         f"cost about {c['power']:.3g} W sliding, {100 * c['share']:.3g} % of the traction and "
                         f"cage losses ({c['dissipation']:.4g} W, the contacts' traction and the cage; the power "
                         f"loss adds the rolling losses; limit {100 * c['tolerance']:g} %): "
                         + ("holds" if c["valid"] else
                            "OUTSIDE it (the balls' inertia matters; march the orbit, --orbit-march with the "
                            "rigid cage, or run the case dynamically)"))
        for name, why in self.held.items():
            lines.append(f"{name} held ({why}); reaction {self.reactions.get(name, 0.0):.6g} "
                         f"{'N m' if name.startswith('tilt') else 'N'}")
        return "\n".join(lines)

