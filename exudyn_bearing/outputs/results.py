"""Sampled time series of a bearing simulation and the summary both engines report.

Arrays (n = samples, Z balls, race 0 inner / 1 outer):

* ``t`` (n,) [s]; ``glob`` (n, NGLOBAL): omega, force of the balls on the
  inner ring (x, y, z), friction torque on the ring about its axis, total
  frictional power, largest overlap / R_b, force of the balls and cage
  balls on the outer ring (x, y, z) and torque about its axis
  (``GLOBAL_FIELDS``; the ring reactions, ``global_series("outer_fx")``);
* ``diag`` (n, Z, 2, NDIAG): per contact load, overlap, contact angle, a,
  b, p_max, u_r, h_min, Lambda, regime, mu, slip speed, slide-to-roll
  ratio, friction force (``DIAG_FIELDS``);
* ``cage_load`` (n, Z, 2): ball / cage-ball contact forces (or ball / ball);
* ``xb, vb, wb, xc, vc`` (n, Z, 3): balls and cage balls; ``ring`` (n, 6);
* with ``Scenario.signal_dt``: ``signal_t`` (m,) [s] and ``signal`` (m,
  NSIGNAL), the condition-monitoring signals (``SIGNAL_FIELDS``: housing
  force, inner-ring acceleration and speed; ``signal(name)``), processed
  by :mod:`.signals`.
"""
from __future__ import annotations

import dataclasses
import json
import math
import warnings
from pathlib import Path

import numpy as np

from ..data import Lubricant, load_bearing
from ..model import layout as L
from ..model.layout import DIAG_FIELDS, GLOBAL_FIELDS, GLOBAL_UNITS, SIGNAL_FIELDS
from ..model.parameters import scene_parameters
from ..model.record import RunRecord
from ..model.scenario import Scenario
from ..physics.damping import REGIME_NAMES
from .cage_summary import (CAGE_LOSSES_NOT_MODELLED, CAGE_LOSSES_NOT_MODELLED_FILM, CAGE_SUMMARY_UNITS,
                           rigid_cage_summary)
from .contact_summary import CONTACT_SUMMARY_UNITS, contact_summary
from .jsonio import to_jsonable
from .whole_loss import WHOLE_LOSS_DESCRIPTIONS, WHOLE_LOSS_KEYS, WHOLE_LOSS_UNITS, whole_loss
from .tables import NOT_CONVERGED_MARK, Summary
from .window_checks import (LOSS_FLOOR_MU, EnergyBalanceWarning, sample_window, SPEED_FLOOR, SteadyStateWarning,
                            energy_balance, energy_check, energy_floor, q_max_at_psi0, load_at_psi0, steadiness)

__all__ = ["Results", "EnergyBalanceWarning", "SUMMARY_KEYS", "SUMMARY_UNITS", "SUMMARY_DESCRIPTIONS", "PHASE_NAMES", "LOSSES_MODELLED",
           "LOSSES_NOT_MODELLED", "DYNAMIC_LOSS_COMPONENTS", "DYNAMIC_NOT_MODELLED", "DYNAMIC_SWITCHED_LOSSES",
           "SteadyStateWarning", "POINT_STEP_DEPENDENT", "NOT_CONVERGED_MARK",
           "protocol_phases"]

#: Keys every engine's summary has.
SUMMARY_KEYS = ("q_max_inner", "q_max_outer", "q_max_method", "q_psi0_inner", "q_psi0_outer", "q_max_inner_mean",
                "q_max_outer_mean", "cage_speed",
                "ball_spin", "lambda_outer_psi0", "lambda_inner_psi0", "regime_fraction", "window", "steady",
                "friction_torque", "friction_power", "friction_outputs_converged", "not_converged",
                "drive_power", "load_power", "dissipation",
                "kinetic_energy_change", "contact_energy_change", "energy_residual", "energy_source", "power_loss", "power_loss_total",
                *WHOLE_LOSS_KEYS, "not_modelled", "energy_check", "lubricant", "traction_model",
                "traction_level", "losses_modelled", "losses_not_modelled", "steps", "dt", "wall_s", "units",
                "descriptions")

#: Losses each traction level models (docs/theory/dynamics.md, "Losses and the energy balance").
LOSSES_MODELLED = {
    "point": ("sliding friction at the contact centre (Cundall-Strack spring capped at mu(Lambda) Q, or "
              "regularised Coulomb)", "normal damping of all contacts (hysteretic / squeeze film by Lambda; "
                                      "critical damping of the cage contacts)"),
    "ellipse": ("sliding (rolling-direction and transverse slip) integrated over the Hertz ellipse",
                "spin (pivoting) friction over the ellipse", "curvature (Heathcote) slip over the ellipse",
                "normal damping of all contacts (hysteretic / squeeze film by Lambda; critical damping of the "
                "cage contacts)"),
}
_POCKET = ("cage pocket friction (the ball / cage-ball contacts are frictionless; their normal damping is part "
           "of contact_damping)")
#: What ``losses_modelled`` adds with the rigid cage.
RIGID_CAGE_LOSSES = ("rigid cage: Coulomb friction and normal damping of the ball / pocket contacts, the land's "
                     "film (short-bearing pressure and shear) and contact")
#: What ``losses_modelled`` adds with the pockets' oil film (Scenario.pocket_film).
POCKET_FILM_LOSSES = ("the pockets' oil film: the work of its hydrodynamic and squeeze forces and its shear "
                      "(flooded, sphere on plane; physics/pocket_film.py)")
#: Losses each traction level leaves out.
LOSSES_NOT_MODELLED = {
    "point": ("rolling losses: curvature (Heathcote) slip", "spin (pivoting) friction", "EHL rolling resistance",
              "ball drag and churning", _POCKET),
    "ellipse": ("EHL rolling resistance", "ball drag and churning", _POCKET),
}
#: Components of a dynamic summary's ``power_loss`` [W] (time means of the recorded series over the
#: window): the tangential power of the ball / raceway contacts per race (the per-contact
#: ``dissipation`` diagnostic summed over the balls) and the normal damping of every contact (the
#: engine's ``damping_power``: ball / raceway, ball / cage ball and cage ball / guide together; the
#: record does not separate them).
DYNAMIC_LOSS_COMPONENTS = ("contact_traction_inner", "contact_traction_outer", "contact_damping")
#: Components a dynamic summary's ``power_loss`` adds when the scenario switches them on (docs/theory/losses.md,
#: "In the dynamic engines"): the scenario switch, the recorded power (``GLOBAL_FIELDS``), the entry of
#: ``LOSSES_NOT_MODELLED`` it replaces and what ``losses_modelled`` then says.
DYNAMIC_SWITCHED_LOSSES = {
    "ehl_rolling": ("rolling_resistance", "ehl_rolling_power", "EHL rolling resistance",
                    "EHL rolling resistance 2 F_R R_x |roll| as a moment pair at every loaded contact (isothermal, "
                    "fully flooded; with lubrication)"),
    "hysteresis": ("rolling_resistance", "hysteresis_power", None,
                   "elastic hysteresis rolling resistance F_h R_x |roll| as a moment pair at every loaded contact"),
    "drag": ("ball_drag", "drag_power", "ball drag and churning",
             "drag of the oil-air mixture (at rest with the outer ring) on every ball centre"),
}
#: What ``not_modelled`` says instead of "ball drag and churning" when the ball drag is on.
CHURNING_NOT_MODELLED = "churning in an oil bath (the drag through the oil-air mixture is modelled)"
#: Loss sources no dynamic engine represents (``not_modelled`` of every dynamic summary, after the
#: level's own ``losses_not_modelled``).
DYNAMIC_NOT_MODELLED = ("cage land friction (the cage balls' guide contact is frictionless)",
                        "seal friction (open bearing)")
#: What an engine leaves out beyond its losses (``not_modelled`` of its summaries).
#: The integrator an engine runs whatever ``Scenario.integrator`` says (the summary's ``integrator``): the reduced
#: engine's own step (docs/theory/reduced.md); the others take the scenario's.
ENGINE_INTEGRATORS = {"reduced": "linearly implicit BDF2 (reduced engine)"}
ENGINE_NOT_MODELLED = {
    "reduced": ("the ball / race contact vibration (reduced engine: the ball centres sit on their normal force "
                "balance; no impacts at the contact's frequency, so defect signals stay with the reference engine)",),
}
#: Note of a point-level summary on its losses, by friction law.
POINT_LEVEL_NOTES = {
    "history": ("point traction level: no rolling losses; the tangential Cundall-Strack spring stores energy, so "
                "friction_torque and friction_power are mostly its exchange with the balls, a step artefact that "
                "falls about in proportion to dt (friction_outputs_converged: false); traction_level='ellipse' "
                "models sliding, spin and curvature losses"),
    "regularized": ("point traction level: no rolling losses; the regularised Coulomb force at the contact centre "
                    "acts on gross sliding only; traction_level='ellipse' models sliding, spin and curvature losses"),
    "none": "point traction level without friction: no tangential losses at all, only the normal damping",
}

#: Summary entries that are step noise at the point level with the Cundall-Strack spring (friction="history"),
#: not converged losses: its friction power falls about in proportion to dt, the normal damping with dt^2
#: (docs/theory/dynamics.md, "What each traction level models"; python validation/studies/step_convergence_losses.py).
#: Such a summary says
#: ``friction_outputs_converged: False``, lists them under ``not_converged`` and marks their descriptions;
#: ``power_loss.X`` is the component X of ``power_loss``.
POINT_STEP_DEPENDENT = ("friction_torque", "friction_power", "dissipation", "dissipation_inner", "dissipation_outer",
                        "power_loss.contact_traction_inner", "power_loss.contact_traction_outer",
                        "power_loss.contact_damping", "power_loss_total")

#: Unit of every scalar summary entry (speeds are angular speeds in rad/s).
SUMMARY_UNITS = {
    "Fr": "N", "Fa": "N", "Pd": "m", "omega": "rad/s", "omega_outer": "rad/s", "q_max_inner": "N", "q_max_outer": "N",
    "q_psi0_inner": "N", "q_psi0_outer": "N", "q_max_inner_mean": "N", "q_max_outer_mean": "N", "cage_speed": "rad/s", "ball_spin": "rad/s",
    "lambda_outer_psi0": "-", "lambda_inner_psi0": "-", "regime_fraction": "-", "srr_mean": "-",
    "ring_displacement": "m", "friction_torque": GLOBAL_UNITS["ring_torque"] + " (inner ring)",
    "friction_power": GLOBAL_UNITS["friction_power"], **CONTACT_SUMMARY_UNITS, "steps": "-", "dt": "s", "t_end": "s", "wall_s": "s", "stable_dt": "s",
    "window.t0": "s", "window.t1": "s", "drive_power": "W", "load_power": "W", "dissipation": "W",
    "kinetic_energy_change": "J", "contact_energy_change": "J", "energy_residual": "-",
    "power_loss": "W per component",
    "power_loss_total": "W", "not_modelled": "text", "energy_check": "W, - (residual), text",
    "friction_outputs_converged": "-", "not_converged": "summary keys", "reduced_work": "-", **WHOLE_LOSS_UNITS}

#: What the loss and energy keys of the summary mean (docs/theory/dynamics.md,
#: "Losses and the energy balance"); every summary carries it as ``descriptions``.
SUMMARY_DESCRIPTIONS = {
    "srr_mean": "mean slide-to-roll ratio of the loaded contacts that roll (rolling speed at least the scenario's "
                "regularizing_speed) over the window; None (n/a) when none rolls, as at rest",
    "q_max_inner": "load of the ball at psi = 0 over the window, inner race (q_max_method: how it was obtained)",
    "q_max_outer": "load of the ball at psi = 0 over the window, outer race (q_max_method: how it was obtained)",
    "q_psi0_inner": "mean load of the loaded balls within 1 deg of psi = 0 over the window, inner race: the steady "
                    "Q_max, without the contact vibration that the sampled peak q_max_inner includes; None when no "
                    "sampled ball comes within 1 deg",
    "q_psi0_outer": "mean load of the loaded balls within 1 deg of psi = 0 over the window, outer race (balls whose "
                    "inner contact is loaded, as q_max_outer); None when no sampled ball comes within 1 deg",
    "friction_torque": "torque that drives the inner ring about its axis, time mean: minus the torque of the balls "
                       "on the ring; positive when the ring must be driven, negative when it must be held back (the "
                       "inner ring when only the outer ring is driven); the modelled losses only (the driven "
                       "ring's whole torque, always >= 0, is friction_torque_whole)",
    "friction_power": "frictional (tangential) power of all ball / raceway contacts, time mean; at the point level "
                      "it includes the rate of the energy stored in the tangential springs",
    "dissipation_inner": "frictional power of the inner contacts of all balls, time mean (a part of friction_power)",
    "dissipation_outer": "frictional power of the outer contacts of all balls, time mean (a part of friction_power)",
    "drive_power": "power the rings put into the balls and cage balls over the window (translation and rotation of "
                   "both rings: the engine's drive_work); without that field the drive of the inner ring's spin "
                   "(-ring_torque times omega, mean) plus load_power when known",
    "load_power": "without the engine's drive fields only: net power the applied loads pass on through the inner "
                  "ring's translation, their work minus the change of the ring's translational kinetic energy over "
                  "the window length (reference engine; None for the element, whose loads belong to the user's "
                  "model, and None when drive_power already counts it)",
    "dissipation": "dissipated power over the window: frictional power plus the normal damping of all contacts "
                   "(energy_source says which terms were available)",
    "kinetic_energy_change": "kinetic energy of balls and cage balls (translation and rotation) at the window's end "
                             "minus that at its start",
    "contact_energy_change": "elastic energy stored in the normal contacts (ball / race, cage contacts) at the "
                             "window's end minus that at its start (the engine's contact_energy; None for a record "
                             "without it): a transient that unloads the contacts turns it into kinetic energy",
    "energy_residual": "(drive_power - dissipation - (kinetic_energy_change + contact_energy_change) / window "
                       "length) / drive_power",
    "power_loss": "mean power of each modelled loss over the window, from the engine's work of that loss (every "
                  "step, end minus start over the window length; a record without the works: the time means of "
                  "the sampled powers): contact_traction_inner, contact_traction_outer (tangential power of the "
                  "ball / raceway contacts per race), contact_damping (normal damping of all contacts); with "
                  "Scenario.rolling_resistance also ehl_rolling and hysteresis (the rolling-resistance moment "
                  "pairs), with Scenario.ball_drag also drag (the ball drag); with the rigid cage cage_pocket and "
                  "cage_land",
    "power_loss_total": "modelled components only: sum of the power_loss components [W] (the split of the engine's "
                        "dissipation); the whole loss is power_loss_whole",
    "not_modelled": "loss sources the dynamic engines leave out at this traction level",
    "energy_check": "drive_power = sum of power_loss + (kinetic_energy_change + contact_energy_change) / window "
                    "length within 1 % of "
                    "drive_power (residual, passed; split_error: the components against the engine's "
                    "cumulative dissipated_work, round-off when the run recorded the works by loss)",
    "steady": "drift and oscillation of the reported quantities over the window against the thresholds named in it",
    "friction_outputs_converged": "False at the point level with friction='history': its friction and damping "
                                  "outputs (listed under not_converged) are step noise that falls about in "
                                  "proportion to dt, not a converged loss; use traction_level='ellipse' for losses",
    "not_converged": "summary keys whose values are not converged in the step (see friction_outputs_converged)",
    "reduced_work": "the reduced engine's work over the whole run: Newton iterations of the balls' force balance per "
                    "step (mean, most), force evaluations per step, steps whose balance did not converge within "
                    "its iteration limit (the run went on from the last iterate), steps that retook the Jacobians; "
                    "its step error control (Scenario.tolerance; None: the fixed step dt): the steps rejected, the "
                    "restarts, the least, median and largest step taken [s] (the steps taken: steps)",
    **WHOLE_LOSS_DESCRIPTIONS,
}

#: Protocol phases (Scenario: start-up ramp, steady phase, slow-down ramp, rest).
PHASE_NAMES = ("start-up", "steady", "slow-down", "rest")


def protocol_phases(scenario: Scenario, t_end: float) -> list[tuple[str, float, float]]:
    """The protocol phases that lie in [0, t_end]: (name, t0, t1) [s] each."""
    s = scenario
    edges = (0.0, s.t_ramp_up, s.t_ramp_up + s.t_steady, s.t_ramp_up + s.t_steady + s.t_ramp_down, math.inf)
    out = []
    for k, name in enumerate(PHASE_NAMES):
        t0, t1 = edges[k], min(edges[k + 1], t_end)
        if t1 > t0:
            out.append((name, t0, t1))
    return out


class Results:
    """Output of one run (reference or Exudyn engine): the series of a
    :class:`~exudyn_bearing.model.record.RunRecord`, their summary, files and plots."""

    def __init__(self, record: RunRecord):
        self.record = record
        self.bearing = record.bearing
        self.scenario = record.scenario
        self.lubricant = record.lubricant
        self.data = record.data
        self.steps = int(record.steps)
        self.wall_s = float(record.wall_s)
        self.engine = record.engine
        self.stable_dt = record.stable_dt
        self.static = record.static
        self._parameters = None

    # -- accessors -------------------------------------------------------
    @property
    def t(self) -> np.ndarray:
        return self.data["t"]

    def contact(self, name: str, race: str | int) -> np.ndarray:
        """Per-contact series (n, Z) of a ``DIAG_FIELDS`` entry; race 'inner'/'outer'."""
        r = {"inner": 0, "outer": 1}.get(race, race)
        return self.data["diag"][:, :, r, DIAG_FIELDS.index(name)]

    def global_series(self, name: str) -> np.ndarray:
        return self.data["glob"][:, GLOBAL_FIELDS.index(name)]

    def has_global(self, name: str) -> bool:
        """True when the run recorded the ``GLOBAL_FIELDS`` entry ``name`` (a
        record of an engine without that field has fewer columns)."""
        return name in GLOBAL_FIELDS and self.data["glob"].shape[1] > GLOBAL_FIELDS.index(name)

    def model_parameters(self) -> np.ndarray:
        """The scene's kernel parameter vector (:func:`~exudyn_bearing.model.parameters.scene_parameters`:
        masses, switches; layout :mod:`exudyn_bearing.model.layout`)."""
        if self._parameters is None:
            self._parameters = scene_parameters(self.bearing, self.scenario, self.lubricant)
        return self._parameters

    def kinetic_energy_series(self) -> np.ndarray:
        """Kinetic energy (n,) [J] of the balls and cage balls, translation and
        rotation: the engine's ``kinetic_energy`` field when recorded, else from
        the sampled velocities ``vb``, ``wb``, ``vc`` with the ball mass and
        inertia and the cage-ball mass of the model parameters (the cage-ball
        contacts are frictionless: a cage ball's spin, and its energy, never
        change, and the reference engine does not integrate it)."""
        if self.has_global("kinetic_energy"):
            return self.global_series("kinetic_energy")
        p, d = self.model_parameters(), self.data
        ke = 0.5 * p[L.P_MB] * np.sum(d["vb"] ** 2, axis=(1, 2)) + 0.5 * p[L.P_IB] * np.sum(d["wb"] ** 2, axis=(1, 2))
        if p[L.P_CAGE] > 0.5:
            ke = ke + 0.5 * p[L.P_MZ] * np.sum(d["vc"] ** 2, axis=(1, 2))
        return ke

    def dissipation_series(self) -> np.ndarray:
        """Dissipated power (n,) [W]: ``friction_power`` plus the engine's
        ``damping_power``, rolling-resistance and drag powers when recorded."""
        out = self.global_series("friction_power")
        out = out + self.global_series("damping_power") if self.has_global("damping_power") else out
        for name in ("ehl_rolling_power", "hysteresis_power", "drag_power", "pocket_power",
                     "land_power"):  # 0 unless switched on (the last two: the rigid cage)
            if self.has_global(name):
                out = out + self.global_series(name)
        return out

    @property
    def signal_t(self) -> np.ndarray:
        """Times [s] of the condition-monitoring signal samples (``Scenario.signal_dt``)."""
        if "signal_t" not in self.data:
            raise ValueError("signal_dt: this run recorded no signals (set Scenario.signal_dt)")
        return self.data["signal_t"]

    def signal(self, name: str) -> np.ndarray:
        """Condition-monitoring signal (m,) of a ``SIGNAL_FIELDS`` entry
        (outer_fx/fy/fz [N], inner_ax/ay/az [m/s^2], omega [rad/s])."""
        t = self.signal_t
        if name not in SIGNAL_FIELDS:
            raise ValueError(f"name: unknown signal {name!r} (valid: {', '.join(SIGNAL_FIELDS)})")
        return self.data["signal"][:len(t), SIGNAL_FIELDS.index(name)]

    def azimuth(self) -> np.ndarray:
        """Ball azimuth psi (n, Z) [rad] from the load direction (``record.load_angle`` from x), in (-pi, pi]."""
        xb = self.data["xb"]
        psi = np.arctan2(xb[..., 1], xb[..., 0])
        a = getattr(self.record, "load_angle", 0.0)
        return psi if a == 0.0 else np.angle(np.exp(1j * (psi - a)))

    def azimuth_scatter(self, name: str = "load", race: str | int = "outer", fraction: float = 0.5):
        """(psi [deg], values) of a ``DIAG_FIELDS`` entry at every ball and
        sample of the last ``fraction`` of the run, flattened (for Q(psi)
        scatter plots)."""
        w = self.window(fraction)
        return np.degrees(self.azimuth()[w]).ravel(), self.contact(name, race)[w].ravel()

    def orbital_speed(self, which: str = "balls") -> np.ndarray:
        """Angular speed about the bearing axis (n, Z) [rad/s] of balls or cage balls."""
        x, v = (self.data["xb"], self.data["vb"]) if which == "balls" else (self.data["xc"], self.data["vc"])
        r2 = x[..., 0] ** 2 + x[..., 1] ** 2
        return (x[..., 0] * v[..., 1] - x[..., 1] * v[..., 0]) / r2

    def cage_speed_series(self) -> np.ndarray:
        """Cage speed (n,) [rad/s]: mean orbital speed of the cage balls (of the balls without cage)."""
        if self.scenario.cage == "rigid":
            return np.asarray(self.data["vc"][:, 1, 0], float)
        cage = self.scenario.cage == "torus" and self.bearing.has_cage
        return self.orbital_speed("cage" if cage else "balls").mean(axis=1)

    def omega_outer_series(self) -> np.ndarray:
        """Outer-ring speed (n,) [rad/s] at the sample times: the scenario's prescribed ``omega_outer`` under
        its protocol (:meth:`~exudyn_bearing.model.scenario.Scenario.omega_outer_at`, the engines' outer ring;
        zeros for a fixed outer ring)."""
        if self.scenario.omega_outer == 0.0:
            return np.zeros(len(self.t))
        return np.array([self.scenario.omega_outer_at(t) for t in self.t], float)

    def relative_speed_series(self) -> np.ndarray:
        """Inner-ring speed relative to the outer ring, omega - omega_outer (n,) [rad/s]: the speed that
        rolls the balls and scales the losses (the recorded inner-ring speed minus :meth:`omega_outer_series`)."""
        return self.global_series("omega") - self.omega_outer_series()

    def ball_spin_series(self) -> np.ndarray:
        """|omega| of every ball (n, Z) [rad/s]."""
        return np.linalg.norm(self.data["wb"], axis=-1)

    def window(self, fraction: float = 0.25, t_window=None) -> slice:
        """Slice of the last ``fraction`` of the samples, or of the samples
        with t in ``t_window = (t0, t1)`` when given (:func:`.window_checks.sample_window`)."""
        return sample_window(self.t, fraction, t_window)

    def nearest_psi0(self) -> np.ndarray:
        """Index of the ball nearest psi = 0 at every sample (n,)."""
        return np.argmin(np.abs(self.azimuth()), axis=1)

    # -- checks of the summary window -----------------------------------
    def energy(self, w: slice) -> dict:
        """Energy balance of the samples ``w``
        (:func:`~.window_checks.energy_balance`; ``energy_source`` names where
        each term comes from). The engine's cumulative ``drive_work`` and
        ``dissipated_work`` (end minus start over the window length) and its
        ``kinetic_energy`` when recorded; else the time means of the sampled
        -ring_torque * omega and :meth:`dissipation_series`, and
        :meth:`kinetic_energy_series`. The engine's drive power counts both
        rings, translation and rotation; the sampled fallback counts the inner
        ring's spin and adds ``load_power`` (reference engine only):
        F_applied . (x_ring(t1) - x_ring(t0)) minus the change of the ring's
        translational kinetic energy, over the window length."""
        t = self.t[w]
        i0, i1 = w.start, w.stop - 1
        dur = float(t[-1] - t[0])
        src = {}
        loads = None
        if self.has_global("drive_work") and dur > 0.0:
            g = self.global_series("drive_work")
            drive = float(g[i1] - g[i0]) / dur
            src["drive_power"] = ("drive_work (engine field: the power of both rings on the balls and cage balls, "
                                  "translation and rotation), end minus start over the window length")
        elif self.has_global("drive_power"):
            drive = float(np.mean(self.global_series("drive_power")[w]))
            src["drive_power"] = "time mean of the sampled drive_power (engine field: both rings, all motions)"
        else:
            drive = float(np.mean(-self.global_series("ring_torque")[w] * self.global_series("omega")[w]))
            src["drive_power"] = "time mean of the sampled -ring_torque * omega, plus load_power"
            if self.engine == "reference" and dur > 0.0:
                ring = self.data["ring"]
                f = np.array([self.scenario.Fr, 0.0, self.scenario.Fa])
                v0, v1 = ring[i0, 3:6], ring[i1, 3:6]
                work = float(f @ (ring[i1, :3] - ring[i0, :3]) - 0.5 * self.model_parameters()[L.P_MR]
                             * (v1 @ v1 - v0 @ v0))
                loads = work / dur
        if loads is not None:
            src["load_power"] = "work of the applied loads on the inner ring's translation minus its kinetic energy"
        elif src["drive_power"].startswith("time mean of the sampled -ring_torque"):
            src["load_power"] = "unknown (element: the loads belong to the user's model)"
        else:
            src["load_power"] = "included in drive_power (the engine field counts the rings' translation)"
        if self.has_global("dissipated_work") and dur > 0.0:
            g = self.global_series("dissipated_work")
            diss = float(g[i1] - g[i0]) / dur
            src["dissipation"] = ("dissipated_work (engine field: friction_power + damping_power, and the rolling-resistance and "
                                  "drag powers when switched on, the rigid cage's pocket and land powers, integrated), "
                                  "end minus start over the window length")
        else:
            diss = float(np.mean(self.dissipation_series()[w]))
            src["dissipation"] = ("time mean of the sampled friction_power + damping_power"
                                  if self.has_global("damping_power") else
                                  "time mean of the sampled friction_power; the normal damping is not recorded by "
                                  "this run and is left out")
        ke = self.kinetic_energy_series()
        src["kinetic_energy_change"] = ("kinetic_energy (engine field)" if self.has_global("kinetic_energy") else
                                        "from the sampled ball and cage-ball velocities")
        stored = None
        if self.has_global("contact_energy"):
            g = self.global_series("contact_energy")
            stored = float(g[i1] - g[i0])
            src["contact_energy_change"] = ("contact_energy (engine field: the elastic energy of the normal "
                                            "contacts), end minus start")
        else:
            src["contact_energy_change"] = "not recorded by this run (a record from before the field): left out"
        out = energy_balance(dur, drive, loads, diss, float(ke[i0]), float(ke[i1]), stored)
        floor = energy_floor(self._loss_floor(), np.mean(self.relative_speed_series()[w]))
        if out["energy_residual"] is None:
            src["energy_residual"] = "no drive power or a window of one sample: no residual"
        elif abs(out["drive_power"]) < floor:
            src["energy_residual"] = (f"drive power below the loss floor {floor:.3g} W (LOSS_FLOOR_MU (|Fr| + |Fa|) r_p "
                                      f"max(|omega - omega_outer|, 1 rad/s)): the residual compares noise and "
                                      "means little")
        else:
            src["energy_residual"] = ("(drive_power - dissipation - (kinetic_energy_change + contact_energy_change) "
                                      "/ window length) / drive_power")
        out["energy_source"] = src
        return out

    def power_loss(self, w: slice, energy: dict) -> dict:
        """Losses of the samples ``w`` by component (:data:`DYNAMIC_LOSS_COMPONENTS`, time means [W] of
        the recorded series), their total, what is not modelled, and the energy check of the window
        (:func:`~.window_checks.energy_check`) against the drive power and kinetic energy change of
        ``energy`` (:meth:`energy`)."""
        t = self.t[w]
        dur = float(t[-1] - t[0])

        def loss(work, power=None):
            """The window's mean of a loss [W]: its engine work, end minus start over the window length, when
            recorded (every step counted); else the time mean of its sampled power (None: neither)."""
            if self.has_global(work) and dur > 0.0:
                g = self.global_series(work)
                return float(g[w.stop - 1] - g[w.start]) / dur
            return float(np.mean(self.global_series(power)[w])) if power and self.has_global(power) else None

        diag = self.data["diag"][w]
        comp = {}
        for race, tag in ((0, "inner"), (1, "outer")):  # without the works: the samples' per-contact powers
            exact = loss(f"traction_work_{tag}")
            comp[f"contact_traction_{tag}"] = (exact if exact is not None else
                                               float(np.mean(np.sum(diag[:, :, race, L.D_POWER], axis=1))))
        comp["contact_damping"] = loss("damping_work", "damping_power")
        for name, (switch, field, _off, _on) in DYNAMIC_SWITCHED_LOSSES.items():
            if getattr(self.scenario, switch):
                comp[name] = loss(field.replace("_power", "_work"), field)
        if self.scenario.cage == "rigid":
            comp["cage_pocket"] = loss("pocket_work", "pocket_power")
            comp["cage_land"] = loss("land_work", "land_power")
        recorded = None
        if self.has_global("dissipated_work") and dur > 0.0:
            g = self.global_series("dissipated_work")
            recorded = float(g[w.stop - 1] - g[w.start]) / dur
        floor = energy_floor(self._loss_floor(), np.mean(self.relative_speed_series()[w]))
        check = energy_check(energy["drive_power"], comp, energy["kinetic_energy_change"], dur, recorded, floor,
                             contact_energy_change=energy["contact_energy_change"])
        return {"power_loss": comp, "power_loss_total": check["power_loss_total"],
                "not_modelled": (self.losses_lists()[1] + list(self.cage_not_modelled())
                                 + list(ENGINE_NOT_MODELLED.get(self.engine, ()))),
                "energy_check": check}

    def cage_not_modelled(self) -> tuple:
        """Loss sources of the cage and the bearing that the run's cage model leaves out: those of
        :data:`DYNAMIC_NOT_MODELLED` for the torus cage (or none), the rigid cage's own
        (:data:`~.cage_summary.CAGE_LOSSES_NOT_MODELLED`, or ``CAGE_LOSSES_NOT_MODELLED_FILM`` with the pocket
        film) and the seals for the rigid cage."""
        if self.scenario.cage == "rigid":
            own = CAGE_LOSSES_NOT_MODELLED_FILM if self.scenario.pocket_film else CAGE_LOSSES_NOT_MODELLED
            return own + DYNAMIC_NOT_MODELLED[1:]
        return DYNAMIC_NOT_MODELLED

    def losses_lists(self) -> tuple[list, list]:
        """(losses_modelled, losses_not_modelled) of the scenario: its traction level's
        (:data:`LOSSES_MODELLED`, :data:`LOSSES_NOT_MODELLED`) with the rolling resistance and ball
        drag moved to the modelled ones when switched on (:data:`DYNAMIC_SWITCHED_LOSSES`)."""
        level = self.scenario.traction_level
        modelled, not_modelled = list(LOSSES_MODELLED[level]), list(LOSSES_NOT_MODELLED[level])
        for switch, _field, off, on in DYNAMIC_SWITCHED_LOSSES.values():
            if getattr(self.scenario, switch):
                modelled.append(on)
                if off in not_modelled:
                    k = not_modelled.index(off)
                    if switch == "ball_drag":
                        not_modelled[k] = CHURNING_NOT_MODELLED
                    else:
                        del not_modelled[k]
        if self.scenario.cage == "rigid":  # the pockets' friction and the land are the rigid cage's
            not_modelled.remove(_POCKET)
            modelled.append(RIGID_CAGE_LOSSES)
            if self.scenario.pocket_film:
                modelled.append(POCKET_FILM_LOSSES)
        elif self.scenario.cage == "none" or not self.bearing.has_cage:  # no cage: no pocket to leave out
            not_modelled.remove(_POCKET)
        return modelled, not_modelled

    def _loss_floor(self) -> float:
        """LOSS_FLOOR_MU (|Fr| + |Fa|) r_p [N m]: the smallest friction torque judged (:mod:`.window_checks`)."""
        return LOSS_FLOOR_MU * (abs(self.scenario.Fr) + abs(self.scenario.Fa)) * self.bearing.pitch_radius

    def steadiness(self, w: slice, window: dict) -> dict:
        """Is the window ``w`` steady (:func:`~.window_checks.steadiness`)?
        Each series is first averaged over the passage period of the balls,
        2 pi / (Z |cage speed|) (the outer ring at rest). Quantities: the
        per-sample largest ball load of each race (q_max_*),
        cage speed and mean ball spin (judged against at least SPEED_FLOOR of
        the rings' speed and regularizing_speed / r_p), mean contact angle of
        each race over the loaded contacts, the ring displacement (judged
        against the norm of its mean), friction torque and dissipation (judged
        against at least ``LOSS_FLOOR_MU (|Fr| + |Fa|) r_p`` and that times
        max(|omega|, ENERGY_FLOOR_OMEGA), the energy check's floor; judged
        only when their mean is above that floor). A window
        over the start-up or slow-down ramp is not steady by definition."""
        t = self.t[w]
        diag = self.data["diag"][w]
        q = {}
        for race, tag in ((0, "inner"), (1, "outer")):
            load = diag[:, :, race, DIAG_FIELDS.index("load")]
            if np.any(load > 0.0):
                q[f"q_max_{tag}"] = (load.max(axis=1), "relative", abs(float(np.mean(load.max(axis=1)))))
        # speeds are judged against at least SPEED_FLOOR of the rings' speed and the speed whose surface speed at
        # the pitch radius is the regularising speed (slower motion is inside the friction's regularisation, not
        # resolved): at rest the settling leaves speeds of 1e-11 to 1e-3 rad/s whose drift is no unsteadiness
        omega_ref = max(abs(self.scenario.omega), abs(self.scenario.omega_outer))
        speed_floor = max(SPEED_FLOOR * omega_ref, self.scenario.regularizing_speed / self.bearing.pitch_radius)
        for name, x in (("cage_speed", self.cage_speed_series()[w]), ("ball_spin", self.ball_spin_series()[w].mean(1))):
            q[name] = (x, "relative", max(abs(float(np.mean(x))), speed_floor))
        for race, tag in ((0, "inner"), (1, "outer")):
            loaded = diag[:, :, race, DIAG_FIELDS.index("load")] > 0.0
            ang = np.where(loaded, diag[:, :, race, DIAG_FIELDS.index("contact_angle")], 0.0).sum(axis=1)
            n = loaded.sum(axis=1)
            q[f"alpha_{tag}"] = (np.degrees(np.where(n > 0, ang / np.maximum(n, 1), np.nan)), "angle", None)
        ring = self.data["ring"][w, :3]
        norm = float(np.linalg.norm(ring.mean(axis=0)))
        if norm > 0.0:
            for k, axis in enumerate("xyz"):
                q[f"ring_displacement.{axis}"] = (ring[:, k], "relative", norm)
        torque_floor = self._loss_floor()
        omega = self.relative_speed_series()[w]
        for name, x, floor in (("friction_torque", -self.global_series("ring_torque")[w], torque_floor),
                               ("dissipation", self.dissipation_series()[w],
                                energy_floor(torque_floor, float(np.mean(omega))))):
            mean = abs(float(np.mean(x)))
            if max(mean, floor) > 0.0:
                below = f"mean below the loss floor {floor:.3g} {SUMMARY_UNITS[name]}" if mean < floor else None
                if below is None and name in POINT_STEP_DEPENDENT and not self.friction_outputs_converged():
                    below = ("step noise of the point level's Cundall-Strack spring (not converged: "
                             "friction_outputs_converged)")
                q[name] = (x, "loss", max(mean, floor), below)
        ramps = [p for p in ("start-up", "slow-down") if p in window["phase"].split(", ")]
        cage = abs(float(np.mean(q["cage_speed"][0])))
        period = 2.0 * math.pi / (self.bearing.n_balls * cage) if cage > 0.0 else None
        return steadiness(t, q, ramp=" and ".join(ramps) or None, period=period)

    def friction_outputs_converged(self) -> bool:
        """False at the point level with the Cundall-Strack spring (``friction="history"``), whose friction and
        damping outputs (:data:`POINT_STEP_DEPENDENT`) are step noise; True otherwise (the ellipse level's
        friction torque moves by 0.3 % from 2 to 0.5 us, docs/theory/dynamics.md)."""
        return not (self.scenario.traction_level == "point" and self.scenario.friction == "history")

    def traction_model_name(self) -> str:
        """The tangential law in use: the catalogue traction model of the
        ellipse level, or the point level's friction law and its mu."""
        s = self.scenario
        if s.traction_level == "ellipse":
            return s.traction
        if s.friction == "none":
            return "none (frictionless)"
        law = {"history": "Cundall-Strack spring capped at mu Q", "regularized": "regularised Coulomb"}[s.friction]
        lam = s.lubrication and s.contact_law != "power"
        mu = f"mu(Lambda) of lubricant {self.lubricant.name}" if lam else f"mu_dry = {s.mu_dry:g}"
        return f"{law}, {mu}"

    # -- summary -------------------------------------------------------
    def has_protocol(self) -> bool:
        """True when the run changes speed (a start-up ramp or a slow-down within the run)."""
        t_end = float(self.t[-1]) if len(self.t) else float(self.scenario.t_end)
        return len(protocol_phases(self.scenario, t_end)) > 1

    def summary_window(self, fraction: float | None = None, t_window=None) -> tuple[slice, dict]:
        """(slice, description) of the samples :meth:`summary` averages over.

        ``t_window = (t0, t1)`` when given; else the last ``fraction`` of the
        run when given; else, for a protocol with a steady phase in the run,
        the second half of that phase (after the start-up transient, before
        the slow-down); else the last quarter of the run. The description
        names the times of its first and last sample, the protocol phases it
        covers and the rule that chose it.
        """
        t = self.t
        if len(t) == 0:
            raise ValueError("t_end: the run has no samples (t_end below sample_dt)")
        rule = None
        if t_window is not None:
            w, rule = self.window(t_window=t_window), f"t_window = ({t_window[0]:g}, {t_window[1]:g}) s"
        elif fraction is None and self.has_protocol():
            steady = [(a, b) for name, a, b in protocol_phases(self.scenario, float(t[-1]) + 1e-12)
                      if name == "steady"]
            if steady:
                a, b = steady[0]
                idx = np.nonzero((t >= 0.5 * (a + b)) & (t <= b))[0]
                if idx.size >= 2:
                    w, rule = slice(int(idx[0]), int(idx[-1]) + 1), "second half of the steady phase"
        if rule is None:
            f = 0.25 if fraction is None else fraction
            w, rule = self.window(f), f"last {100 * f:g} % of the run"
        tw = t[w]
        eps = 0.5 * self.scenario.dt
        phases = [name for name, a, b in protocol_phases(self.scenario, math.inf) if tw[-1] > a + eps and tw[0] < b - eps]
        return w, {"t0": float(tw[0]), "t1": float(tw[-1]), "samples": int(len(tw)),
                   "phase": ", ".join(phases), "rule": rule}

    def _phase_summaries(self) -> dict:
        """Per protocol phase in the run: times, mean speeds and the largest ball loads."""
        out = {}
        t = self.t
        cage, spin = self.cage_speed_series(), self.ball_spin_series().mean(axis=1)
        omega = self.global_series("omega")
        load_i, load_o = self.contact("load", "inner"), self.contact("load", "outer")
        for name, a, b in protocol_phases(self.scenario, math.inf):
            sel = (t > a) & (t <= b) if a > 0 else (t <= b)
            if not sel.any():
                continue
            out[name] = {"t0": float(a), "t1": float(min(b, t[-1])), "omega": float(np.mean(omega[sel])),
                         "cage_speed": float(np.mean(cage[sel])), "ball_spin": float(np.mean(spin[sel])),
                         "q_max_inner": float(load_i[sel].max()), "q_max_outer": float(load_o[sel].max())}
            if self.scenario.omega_outer:  # the outer ring's mean speed in the phase, when it turns
                out[name]["omega_outer"] = float(np.mean([self.scenario.omega_outer_at(x) for x in t[sel]]))
        return out

    def summary(self, fraction: float | None = None, t_window=None) -> Summary:
        """Scalar results over a window of the run (docs/theory/reference_cases.md keys).

        The window (:meth:`summary_window`, described under ``window``): the
        second half of the steady phase of a protocol, else the last quarter
        of the run, or the last ``fraction`` or ``t_window = (t0, t1)`` when
        given.

        q_max_inner/outer: the load of the ball at psi = 0 [N] (the Q_max of
        Harris and the DEM papers): the largest ball load of the window when
        a loaded ball comes within 1 deg of psi = 0, else interpolated over
        the window's ball positions (:func:`~.window_checks.q_max_at_psi0`;
        ``q_max_method`` says which); q_max_inner/outer_mean: the time mean
        of the largest ball load of each sample [N] (below q_max as the balls
        pass psi = 0); cage_speed, ball_spin: mean angular speeds [rad/s];
        q_psi0_inner/outer: the mean load of the balls within 1 deg of
        psi = 0 over the window (:func:`~.window_checks.load_at_psi0`: the
        steady Q_max, without the vibration peaks that q_max takes in the
        engines that resolve the contacts' vibration; None when no sampled
        ball comes within 1 deg); lambda_{outer,inner}_psi0: mean Lambda of the contact nearest psi =
        0; regime_fraction: share of loaded contacts (both races) in
        boundary / mixed / full film; steady: is the window steady
        (:meth:`steadiness`; a :class:`SteadyStateWarning` names the
        quantities when not); friction_torque (positive when the inner ring
        must be driven), friction_power and the energy balance (drive_power,
        load_power, dissipation, kinetic_energy_change, energy_residual,
        energy_source; :meth:`energy`); lubricant, traction_model,
        traction_level, losses_modelled, losses_not_modelled (and a note at
        the point level); phases (protocols only): per phase mean speeds and
        largest loads; units and descriptions of the entries; steps, dt,
        wall_s.
        """
        w, window = self.summary_window(fraction, t_window)
        b = self.bearing
        load_i = self.contact("load", "inner")[w]
        load_o = self.contact("load", "outer")[w]
        psi = self.azimuth()[w]
        q_i, method_i, _ = q_max_at_psi0(psi, load_i)
        # the outer race's balls outside the loaded zone press on it by their centrifugal force alone: the
        # outer distribution is taken where the inner contact of the ball is loaded
        load_o_zone = np.where(load_i > 0.0, load_o, 0.0) if np.any(load_i > 0.0) else load_o
        q_o, method_o, _ = q_max_at_psi0(psi, load_o_zone)
        idx = self.nearest_psi0()[w]
        rows = np.arange(len(idx))
        lam_i = self.contact("lambda", "inner")[w][rows, idx]
        lam_o = self.contact("lambda", "outer")[w][rows, idx]
        reg = np.stack([self.contact("regime", "inner")[w], self.contact("regime", "outer")[w]])
        loaded = reg >= 0
        n_loaded = max(int(loaded.sum()), 1)
        frac = {name: float(np.sum(reg == code)) / n_loaded for code, name in enumerate(REGIME_NAMES)}
        srr = np.stack([self.contact("srr", "inner")[w], self.contact("srr", "outer")[w]])
        # the slide-to-roll ratio of contacts that roll: a rolling speed below the regularising speed (at rest, a
        # ball leaving the load zone at rest) makes the ratio of two noises
        rolling = loaded & (np.stack([self.contact("u_r", "inner")[w], self.contact("u_r", "outer")[w]])
                            >= self.scenario.regularizing_speed)
        omega = float(np.mean(self.global_series("omega")[w]))
        omega_outer = float(np.mean(self.omega_outer_series()[w]))
        level = self.scenario.traction_level

        def nanmean(x):
            x = np.asarray(x, float)
            return float(np.nanmean(x)) if np.any(np.isfinite(x)) else None

        steady = self.steadiness(w, window)
        energy = self.energy(w)
        losses = self.power_loss(w, energy)
        loss = losses["power_loss"]  # the window's losses by component: every other mean of a loss is one of them
        out = {
            "engine": self.engine,
            "bearing": b.name,
            "Fr": self.scenario.Fr,
            "Fa": self.scenario.Fa,
            "Pd": b.diametral_clearance,
            "window": window,
            "steady": steady,
            "omega": omega,
            "omega_outer": omega_outer,
            "q_max_inner": q_i,
            "q_max_outer": q_o,
            "q_max_method": {"inner": method_i, "outer": method_o},
            "q_psi0_inner": load_at_psi0(psi, load_i),
            "q_psi0_outer": load_at_psi0(psi, load_o_zone),
            "q_max_inner_mean": float(np.mean(load_i.max(axis=1))),
            "q_max_outer_mean": float(np.mean(load_o.max(axis=1))),
            "cage_speed": float(np.mean(self.cage_speed_series()[w])),
            "ball_spin": float(np.mean(self.ball_spin_series()[w])),
            "lambda_outer_psi0": nanmean(lam_o),
            "lambda_inner_psi0": nanmean(lam_i),
            "regime_fraction": frac,
            "srr_mean": float(np.mean(srr[rolling])) if rolling.any() else None,
            "ring_displacement": [float(x) for x in np.mean(self.data["ring"][w, :3], axis=0)],
            "friction_torque": -float(np.mean(self.global_series("ring_torque")[w])),
            "friction_power": loss["contact_traction_inner"] + loss["contact_traction_outer"],
            **energy,
            **losses,
            "steps": self.steps,
            "dt": self.scenario.dt,
            "t_end": float(self.t[-1]),
            "wall_s": self.wall_s,
            "stable_dt": self.stable_dt,
            "integrator": ENGINE_INTEGRATORS.get(self.engine, self.scenario.integrator),
            # the point level's tangential model; over the ellipse the traction law replaces it (not used)
            "friction": self.scenario.friction if level == "point" else "not used (traction_level 'ellipse')",
            "hertz": self.scenario.hertz,
            "film": self.scenario.film,
            "cage": self.scenario.cage if (self.scenario.cage != "torus" or b.has_cage) else "none",
            "pocket_film": self.scenario.pocket_film,
            "lubrication": self.scenario.lubrication,
            "lubricant": self.lubricant.name,
            "traction_model": self.traction_model_name(),
            "traction_level": level,
            "losses_modelled": self.losses_lists()[0],
            "losses_not_modelled": self.losses_lists()[1],
        }
        # the whole loss: the modelled components plus the quasi-static estimate of the others (.whole_loss)
        out.update(whole_loss(self, out["power_loss"], out["power_loss_total"], omega, omega_outer))
        converged = self.friction_outputs_converged()
        out["friction_outputs_converged"] = converged
        out["not_converged"] = [] if converged else list(POINT_STEP_DEPENDENT)
        if level == "point":
            out["note"] = POINT_LEVEL_NOTES[self.scenario.friction]
            if self.scenario.rolling_resistance:
                out["note"] += ("; the rolling resistance (hysteresis and EHL rolling) acts as a moment pair "
                                "(Scenario.rolling_resistance)")
        out.update(contact_summary(self.data, w, omega, b, omega_outer))
        out["dissipation_inner"], out["dissipation_outer"] = loss["contact_traction_inner"], loss["contact_traction_outer"]
        if self.scenario.cage == "rigid":
            out.update(rigid_cage_summary(self.data, w, self.model_parameters(), out["cage_speed"],
                                          out.get("kinematic_cage_speed")))
            out["cage_power_pocket"], out["cage_power_land"] = loss["cage_pocket"], loss["cage_land"]
            # the cage the run took (the scenario's, else the bearing's estimated one): its estimated fields
            out["rigid_cage_estimated"] = list(self.scenario.rigid_cage_of(b).estimated)
        if self.has_protocol():
            out["phases"] = self._phase_summaries()
        work = getattr(self.record, "reduced_stats", None)
        if work is not None:  # the reduced engine's work, and the steps whose force balance did not converge
            out["reduced_work"] = dict(work)
        out["units"] = dict(SUMMARY_UNITS, **(CAGE_SUMMARY_UNITS if self.scenario.cage == "rigid" else {}))
        out["descriptions"] = dict(SUMMARY_DESCRIPTIONS)
        for key in out["not_converged"]:
            text = out["descriptions"].get(key.split(".")[0], "")
            out["descriptions"][key] = f"({NOT_CONVERGED_MARK}) {text}".rstrip()
        check = out["energy_check"]
        if check["passed"] is False:  # an invariant of every run: said, not only stored
            warnings.warn(f"summary window {window['t0']:.6g} - {window['t1']:.6g} s of the {self.engine} run: "
                          f"{check['statement']} (summary['energy_check']; a smaller step or tolerance, or a "
                          f"steady window)", EnergyBalanceWarning, stacklevel=2)
        if not steady["steady"]:
            reasons = steady["reason"].split("; ")
            more = f"; and {len(reasons) - 3} more (summary['steady'])" if len(reasons) > 3 else ""
            warnings.warn(f"summary window {window['t0']:.6g} - {window['t1']:.6g} s of the {self.engine} run is not "
                          f"steady: {'; '.join(reasons[:3])}{more}", SteadyStateWarning, stacklevel=2)
        return Summary(out)

    # -- persistence ---------------------------------------------------
    def save(self, directory, stem: str = "run") -> tuple[Path, Path]:
        """Write ``stem.npz`` (all arrays) and ``stem.json`` (summary) into directory."""
        d = Path(directory)
        d.mkdir(parents=True, exist_ok=True)
        npz = d / f"{stem}.npz"
        js = d / f"{stem}.json"
        np.savez_compressed(npz, diag_fields=np.array(DIAG_FIELDS), global_fields=np.array(GLOBAL_FIELDS),
                            **({"signal_fields": np.array(SIGNAL_FIELDS)} if "signal" in self.data else {}),
                            **self.data)
        with warnings.catch_warnings():  # the summary's own call has warned; the file holds its "steady" entry
            warnings.simplefilter("ignore", SteadyStateWarning)
            warnings.simplefilter("ignore", EnergyBalanceWarning)
            summary = self.summary()
        summary["meta"] = {"bearing": self.bearing.to_dict(), "load_angle": getattr(self.record, "load_angle", 0.0),
                           "scenario": dataclasses.asdict(self.scenario),
                           "lubricant": dataclasses.asdict(self.lubricant)}
        js.write_text(json.dumps(to_jsonable(summary), indent=2))
        return npz, js

    @classmethod
    def load(cls, npz) -> "Results":
        """A run saved by :meth:`save` (the NPZ, with its JSON beside it)."""
        npz = Path(npz)
        meta = json.loads(npz.with_suffix(".json").read_text())
        with np.load(npz) as f:
            data = {k: f[k] for k in f.files if k not in ("diag_fields", "global_fields", "signal_fields")}
        bearing = load_bearing(meta["meta"]["bearing"])
        scenario = Scenario(**{k: (math.inf if v is None and k == "t_steady" else v)
                               for k, v in meta["meta"]["scenario"].items()})
        lub = Lubricant(**meta["meta"]["lubricant"])
        return cls(RunRecord(bearing, scenario, lub, data, steps=meta["steps"], wall_s=meta["wall_s"],
                             engine=meta["engine"], stable_dt=meta.get("stable_dt"),
                             load_angle=meta["meta"].get("load_angle", 0.0)))

    def plot(self, png):
        """Overview figure (speeds, loads, Lambda) saved as PNG; returns the path."""
        from .plotting import plot_run

        return plot_run(self, png)

    def __repr__(self):
        return (f"Results(engine={self.engine!r}, bearing={self.bearing.name!r}, samples={len(self.t)}, "
                f"steps={self.steps}, wall_s={self.wall_s:.3g})")
