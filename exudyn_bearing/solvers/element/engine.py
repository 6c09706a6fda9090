"""The reference engine's standard scene built in Exudyn with the bearing element.

Outer ring on ground, inner ring a mass point (the translating ring mass of
the scenario) carrying the applied loads and spun at the protocol speed
omega(t): the same scene as :class:`exudyn_bearing.solvers.reference.ReferenceEngine`,
so both engines can be compared on identical input.
"""
from __future__ import annotations

import sys
import time

from ...data import InputError, Lubricant, load_bearing
from ...model.initial_state import initial_state, ring_mass_estimate
from ...model.memory import ESTIMATE_AFTER_S, wall_time_message
from ...model.record import RunInterrupted
from ...model.scenario import INTEGRATOR_SOLVERS, Scenario, engine_speed_error, fixed_step_error
from ...model.stability import SimulationError, stable_step
from .console import filter_exudyn_notes
from .element import BallBearingElement

__all__ = ["ExudynEngine", "SOLVERS", "solve_dynamic"]

#: Scenario integrator -> Exudyn explicit solver.
SOLVERS = INTEGRATOR_SOLVERS


def _element_error(exc):
    """The SimulationError, InputError or KeyboardInterrupt (Ctrl-C during
    the user function) a user function of the element raised, found in the
    chain of the exception Exudyn raised instead (Exudyn re-raises a user
    function's exception as its own ModelError, a ValueError, with the
    original as the cause); None if there is none."""
    seen = set()
    while exc is not None and id(exc) not in seen:
        if isinstance(exc, (SimulationError, InputError, KeyboardInterrupt)):
            return exc
        seen.add(id(exc))
        exc = exc.__cause__ or exc.__context__
    return None


def solve_dynamic(mbs, settings, solverType=None, quiet=True):
    """``mbs.SolveDynamic`` with ``settings`` (solver: ``solverType``, default
    the one in the settings) inside :func:`~.console.filter_exudyn_notes`:
    ``quiet`` keeps all of Exudyn's solver output off stdout (which must stay
    clean for --json); otherwise its known-benign notes are dropped.

    A blow-up of the bearing element raises
    :class:`~exudyn_bearing.model.stability.SimulationError`, bad input it
    detects during the solve :class:`~exudyn_bearing.data.InputError` and
    Ctrl-C KeyboardInterrupt, not the ModelError Exudyn wraps them in."""
    with filter_exudyn_notes(quiet=quiet):
        try:
            return mbs.SolveDynamic(settings, solverType=solverType or settings.timeIntegration.solverType)
        except Exception as exc:
            err = _element_error(exc.__cause__ or exc.__context__)
            if err is None:
                raise
            raise err from None


class ExudynEngine:
    """Run a :class:`~exudyn_bearing.model.scenario.Scenario` with the Exudyn element; ``run()`` returns the
    :class:`~exudyn_bearing.model.record.RunRecord`."""

    name = "exudyn"

    def __init__(self, bearing, scenario: Scenario, lubricant: Lubricant | None = None, mode: str = "bodies",
                 sub_steps: int = 1, start: dict | None = None):
        err = engine_speed_error(scenario, self.name)  # its outer ring is the ground: omega_outer refused by name
        if err is not None:
            raise err
        import exudyn as exu
        from exudyn.itemInterface import (LoadForceVector, MarkerBodyRigid, MarkerNodePosition, NodePoint,
                                          ObjectGround, ObjectMassPoint)

        self.exu = exu
        if scenario.tolerance is not None:  # its step is fixed: the step error control is the reduced engine's
            raise fixed_step_error(scenario, "exudyn")
        b = load_bearing(bearing)
        if scenario.Pd is not None:
            b = b.with_clearance(scenario.Pd)
        self.bearing, self.scenario = b, scenario
        s = scenario
        # the reference engine's initial state (with ramps: the speed at t = 0), handed to the element
        start = initial_state(b, s, start)
        d0 = start["ring"][:3]
        self.SC = exu.SystemContainer()
        mbs = self.mbs = self.SC.AddSystem()
        ground = mbs.AddObject(ObjectGround())
        m_outer = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground, localPosition=[0.0, 0.0, 0.0]))
        node = mbs.AddNode(NodePoint(referenceCoordinates=[0.0, 0.0, 0.0], initialCoordinates=list(d0)))
        mass = s.ring_mass if s.ring_mass is not None else ring_mass_estimate(b)
        mbs.AddObject(ObjectMassPoint(mass=mass, nodeNumber=node))
        m_inner = mbs.AddMarker(MarkerNodePosition(nodeNumber=node))
        mbs.AddLoad(LoadForceVector(markerNumber=m_inner, loadVector=[s.Fr, 0.0, s.Fa]))
        self.element = BallBearingElement(
            mbs, b, m_inner, m_outer, lubricant=lubricant, cage=s.cage, rigidCage=s.rigid_cage, gravity=s.gravity,
            pocketFilm=s.pocket_film,
            lubrication=s.lubrication,
            friction=s.friction, tangential=s.tangential, cageDamping=s.cage_damping, hertzModel=s.hertz, film=s.film,
            guideClearance=s.guide_clearance, muDry=s.mu_dry, regularizingSpeed=s.regularizing_speed,
            tangentialStiffnessRatio=s.tangential_stiffness_ratio, stepSize=s.dt, innerRingSpeed=s.speed_function(),
            initialOmega=s.omega, initialLoad=(s.Fr, s.Fa), initial=s.initial, sampleInterval=s.sample_dt,
            mode=mode, subSteps=sub_steps, contactLaw=s.contact_law, powerLaw=s.power_law,
            tractionLevel=s.traction_level, traction=s.traction, nStrips=s.n_strips, nAcross=s.n_across,
            tractionRegularizingSrr=s.traction_regularizing_srr, ringGrowth=s.ring_growth,
            temperatures=s.temperatures, control=s.control, initialState=start,
            defects=s.defects, signalInterval=s.signal_dt, rollingResistance=s.rolling_resistance,
            ballDrag=s.ball_drag, oilVolumeFraction=s.oil_volume_fraction,
            hysteresisLossFactor=s.hysteresis_loss_factor)
        # the element knows loads and switches only: its step estimate takes the protocol from the scenario
        self.element.stable = stable_step(b, s, self.element.lubricant)
        mbs.Assemble()
        self.stable = self.element.stable

    def _estimator(self, n_steps):
        """The element's per-sample hook that measures the step cost (``n_steps`` steps of the balls in the
        run) from the first sample on and, once ESTIMATE_AFTER_S have passed, says a long run's estimated wall
        time (once) and removes itself."""
        s, first = self.scenario, []

        def on_sample(t):
            now = time.perf_counter()
            if not first:
                first[:] = [now, t]
                return
            wall = now - first[0]
            if wall < ESTIMATE_AFTER_S:
                return
            self.element._on_sample = None
            msg = wall_time_message(n_steps, max(1, round((t - first[1]) / s.dt)), wall, s, self.stable.dt)
            if msg:
                print(f"[exudyn] {msg}", file=sys.stderr, flush=True)

        return on_sample

    def run(self, progress=None):
        """Solve the scenario; returns the RunRecord. ``progress``: Exudyn's progress output when True; unless
        False, a run estimated to take over LONG_RUN_S says so on stderr (the step cost measured over its
        first ESTIMATE_AFTER_S, :func:`~exudyn_bearing.model.memory.wall_time_message`). Ctrl-C raises
        :class:`~exudyn_bearing.model.record.RunInterrupted` with the samples so far."""
        s = self.scenario
        settings = self.element.SimulationSettings(s.t_end, solverType=SOLVERS[s.integrator])
        if progress:
            settings.timeIntegration.verboseMode = 1
        if progress is not False:
            self.element._on_sample = self._estimator(int(round(s.t_end / s.dt)))  # the balls' steps
        wall0 = time.perf_counter()
        try:
            solve_dynamic(self.mbs, settings, quiet=not progress)
        except SimulationError as exc:  # the scenario names the element's stepSize dt
            msg = str(exc)
            raise SimulationError("dt" + msg[len("stepSize"):] if msg.startswith("stepSize") else msg) from None
        except KeyboardInterrupt:  # Ctrl-C: the samples so far go with it (the reference engine's RunInterrupted)
            try:
                rec = self.element.record(wall_s=time.perf_counter() - wall0)
                rec.scenario = self.scenario
            except RuntimeError:  # no sample yet
                rec = None
            t = float(rec.data["t"][-1]) if rec is not None and len(rec.data["t"]) else 0.0
            raise RunInterrupted(t, s.t_end, rec) from None
        finally:
            self.element._on_sample = None
        rec = self.element.record(wall_s=time.perf_counter() - wall0,
                                  steps=settings.timeIntegration.numberOfSteps)
        rec.scenario = self.scenario  # the run's protocol and solver, not the element's model options only
        return rec
