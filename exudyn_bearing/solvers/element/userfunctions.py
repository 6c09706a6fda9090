"""Force user functions of the bearing element: one compiled call per Exudyn
evaluation (body mode), or compiled ball sub-steps per Exudyn step (fast
mode); step and runaway checks."""
from __future__ import annotations

import math
import time
import warnings

import numpy as np

from ...data import InputError
from ...model.contact import forces
from ...model.layout import H_E1, POCKET_ESCAPE
from ...model.load_range import pressure_excess
from ...model.scenario import history_friction_error
from ...model.solver_types import IMPLICIT_SOLVERS, UNSTABLE_SOLVERS, settings_solver, unstable_solver_error
from ...model.stability import FAST_STEP_SHARE, SimulationError, StepSizeWarning, runaway_error, step_warning
from ...physics import hertz
from ...physics.geometry import raceway_radii
from . import kernels as EK

#: UNSTABLE_SOLVERS (..model.solver_types): an undamped oscillation grows at every step, and only the
#: contacts' damping holds it below a step limit. ExplicitEuler: refused (on the
#: 6208 scene at 3000 N it runs away at 5 us and ends 48 % off in q_max at 1 us, 0.12 of the stable-step
#: estimate; it needs about 1/16 of it, at first order). ExplicitMidpoint in the body mode: at most
#: MIDPOINT_STEP_RATIO of the stable-step estimate (there: right at 0.49 and 0.55 of it, a quarter of the
#: ball load at 0.61, unnoticed); the fast mode integrates only the rings with it, and runs right at 5 us.
MIDPOINT_STEP_RATIO = 0.5
#: Explicit solvers that evaluate back in time within a run: RK67 and DVERK6 (stage times out of order),
#: ODE23 and DOPRI5 (a rejected adaptive step is repeated from its start). The fast mode's balls only advance.
BACKWARD_SOLVERS = ("RK67", "ODE23", "DOPRI5", "DVERK6")
#: Times closer than this [s] are the same time.
_T_EPS = 1e-12


def implicit_solver_error(solver):
    """The fast mode's InputError for an implicit ``solver`` (a name)."""
    return InputError(f"mode: the fast mode integrates the balls forward in time and needs an explicit solver "
                      f"(VelocityVerlet, or RK44 with friction='regularized'), not {solver}; use mode='bodies' for "
                      "implicit solvers")


def solver_error(mode, solver, step=None, stable=None, cage_damping="explicit", friction=None):
    """The InputError for a ``solver`` (a name) the element in ``mode`` cannot run with at the Exudyn step
    ``step`` [s] (None: not known yet) and the stable-step estimate ``stable`` [s], else None.
    ``cage_damping="implicit"`` (the backward-Euler damping of one velocity-Verlet step of the balls) needs
    VelocityVerlet in the body mode; the fast mode's balls always take velocity-Verlet sub-steps.
    ``friction="history"`` refuses, in the body mode (where the solver integrates the balls), the explicit
    solvers with several evaluations per step (:func:`~exudyn_bearing.model.scenario.history_friction_error`,
    the rule ``Scenario`` applies to ``integrator="rk4"``); the fast mode's balls take velocity-Verlet
    sub-steps under any solver. None: not checked."""
    err = unstable_solver_error(solver, "the ball contacts", "VelocityVerlet (recommended), RK33 or RK44",
                                " unless the step is about 1/16 of the stable-step estimate")
    if err is not None:
        return err
    err = None if friction is None or mode == "fast" else history_friction_error(friction, solver, "solverType")
    if err is not None:
        return err
    if solver == "ExplicitMidpoint" and mode != "fast" and step is not None and step > MIDPOINT_STEP_RATIO * stable:
        return InputError(f"stepSize: ExplicitMidpoint needs a step of at most {MIDPOINT_STEP_RATIO:g} of the "
                          f"stable-step estimate, {MIDPOINT_STEP_RATIO * stable:.3g} s, got {step:.3g} s (above it the "
                          "ball loads end wrong); use VelocityVerlet (recommended) or a smaller step")
    if mode != "fast" and cage_damping == "implicit" and solver != "VelocityVerlet":
        return InputError(f"cageDamping: 'implicit' is the backward-Euler damping of one velocity-Verlet step and "
                          f"needs the VelocityVerlet solver in the body mode (or mode='fast'), not {solver}")
    if mode == "fast" and solver in IMPLICIT_SOLVERS:
        return implicit_solver_error(solver)
    if mode == "fast" and solver in BACKWARD_SOLVERS:
        return InputError(f"mode: the fast mode integrates the balls forward in time and needs a fixed-step solver "
                          f"whose evaluations never go back in time (VelocityVerlet, RK33 or RK44), not {solver} "
                          "(stage times out of order, or rejected adaptive steps repeated); use mode='bodies' for it")
    return None


def body_settings_error(solver, settings):
    """The InputError for Exudyn settings the body mode cannot run with, else None (``solver``: Exudyn's
    solver object of the run). Its user function computes all ball forces from the system's coordinates
    and hands most of them to a second object (:meth:`UserFunctionsMixin._make_body_uf`): that object's forces
    must be evaluated after it (one thread), and an implicit solver's numerical Jacobian must perturb
    every system coordinate and evaluate the whole system (system-wide differentiation; object-wise, it
    would miss the ball coupling: Newton then needs about 25 times the evaluations and ends elsewhere)."""
    import exudyn as exu

    threads = getattr(getattr(settings, "parallel", None), "numberOfThreads", 1)
    if threads > 1:
        return InputError(f"numberOfThreads: the bearing element's body mode needs simulationSettings.parallel."
                          f"numberOfThreads = 1 (its forces are evaluated in order), got {threads}")
    newton = getattr(getattr(settings, "timeIntegration", None), "newton", None)
    if (solver is not None and not isinstance(solver, exu.MainSolverExplicit) and newton is not None
            and not newton.numericalDifferentiation.doSystemWideDifferentiation):
        return InputError("doSystemWideDifferentiation: the bearing element's body mode under an implicit solver "
                          "needs simulationSettings.timeIntegration.newton.numericalDifferentiation."
                          "doSystemWideDifferentiation = True (its forces couple all balls; the element's "
                          "SimulationSettings sets it)")
    return None


__all__ = ["UserFunctionsMixin", "body_settings_error", "IMPLICIT_SOLVERS", "UNSTABLE_SOLVERS", "MIDPOINT_STEP_RATIO", "BACKWARD_SOLVERS",
           "implicit_solver_error", "solver_error", "entry_point"]


def overlap_contacts(bearing, overlap, method="exact"):
    """((load [N], p_max [Pa]) at the inner race, the same at the outer race)
    of one ball contact at ``overlap`` [m] (Hertz at the free contact angle,
    docs/theory/hertz.md): what a largest overlap the element saw means in
    ball load and contact pressure."""
    b = bearing
    a0 = b.free_contact_angle
    em = hertz.material_reduced_modulus(b.material)
    out = []
    for r_c, sign, inner in ((b.inner_groove_radius, -1.0, True), (b.outer_groove_radius, 1.0, False)):
        rx, ry = raceway_radii(b.ball_radius, r_c, b.pitch_radius + sign * b.ball_radius * math.cos(a0), a0, inner)
        c = hertz.hertz_contact(rx, ry, em, overlap=overlap, method=method)
        out.append((float(c.load), float(c.p_max)))
    return out[0], out[1]


#: Columns of a ring pose row (model.layout RING_N) that belong to the marker's position (centre, rotation
#: matrix) and to its velocity (velocity, angular velocity).
_POSE_POSITION = np.r_[0:3, 6:15]
_POSE_VELOCITY = np.r_[3:6, 15:18]


def entry_point(dispatcher, args):
    """numba's compiled entry point of ``dispatcher`` for the types of
    ``args`` (compiled or loaded from the cache now): calling it skips
    numba's per-call type dispatch. The dispatcher itself where numba does not
    offer it (JIT disabled, another numba version)."""
    try:
        import numba

        sig = tuple(numba.typeof(a) for a in args)
        dispatcher.compile(sig)
        return dispatcher.overloads[sig].entry_point
    except Exception:  # noqa: BLE001 - any failure falls back to the dispatcher
        return dispatcher


def _clock_entry(k, doc):
    """A property for entry ``k`` of the element's clock array ``_times`` (kernels.CLK_*), which the body mode's
    compiled call keeps."""
    def get(self):
        return float(self._times[k])

    def set_(self, value):
        self._times[k] = value

    return property(get, set_, doc=doc)


class UserFunctionsMixin:
    """Part of :class:`~.element.BallBearingElement`: the user functions."""

    #: Called with the time of every sample while set (the Exudyn engine's wall-time estimate), else None.
    _on_sample = None

    _t_trial = _clock_entry(EK.CLK_TRIAL, "Body mode: the latest time evaluated [s] (-inf: none yet).")
    _t_commit = _clock_entry(EK.CLK_COMMIT, "Body mode: the time of the committed Cundall-Strack history [s].")
    _t_energy = _clock_entry(EK.CLK_ENERGY, "Body mode: the last time whose powers entered the energy integrals [s].")
    _next_sample = _clock_entry(EK.CLK_NEXT_SAMPLE, "The next sample time [s] (both modes).")

    def _new_run(self, t, t_last):
        """First evaluation of a SolveDynamic (Exudyn's solver object in
        ``mbs.sys`` changed, or the time went back to the run's first time).

        A run that starts where the element's last one ended (its start time
        equal to the last evaluated time ``t_last``) continues it: samples
        append, the contact history and the fast mode's balls carry on, as
        the ring states do when the caller copied the end state into the
        initial state. Any other start is a new run from the model's initial
        state, as Exudyn starts it: samples, evaluations, contact history and
        the fast mode's balls are reset. The fast mode refuses implicit
        solvers (its balls would ignore their Newton iterations)."""
        run = self._run
        run[0] = self._sys.get("dynamicSolver")
        settings = self._sys.get("simulationSettings")
        self._sys_index[:] = self._system_index()
        self._take_coordinates()
        if self.mode != "fast":
            err = body_settings_error(run[0], settings)
            if err is not None:
                raise err
        solver = settings_solver(settings)
        ti = getattr(settings, "timeIntegration", None)
        step = ((ti.endTime - ti.startTime) / max(1, ti.numberOfSteps)) if ti is not None else None
        err = solver_error(self.mode, solver, step, self.stable.dt, self.scenario.cage_damping, self.scenario.friction)
        if err is not None:
            raise err
        if self.scenario.cage_damping == "implicit" and step is not None:
            # the kernel takes the cage damping implicit over stepSize: the balls must step by it, within 1 % (a
            # run's end rounds the solver's step; the fast mode fits whole sub-steps into it, as
            # _check_fast_step does)
            n_sub = self._sub_steps_in(step) if self.mode == "fast" else 1
            ball_step = step / n_sub
            if abs(ball_step - self.scenario.dt) > 0.01 * self.scenario.dt:
                raise InputError(f"cageDamping: 'implicit' takes the cage contacts' damping over stepSize = "
                                 f"{self.scenario.dt:.6g} s, but the balls step by {ball_step:.6g} s (the solver's "
                                 f"step {step:.6g} s{f' in {n_sub} sub-steps' if self.mode == 'fast' else ''}); set "
                                 "stepSize to the balls' step or use the element's SimulationSettings")
        evidence = self._runaway_evidence()
        if self.mode != "fast":  # the fast mode's steps are checked at its first step (_check_fast_step)
            evidence[1] = step is not None and step > self.stable.dt
        first = run[1] == math.inf
        run[1] = t
        if first:
            evidence[0] = 0.0
            self._t_commit = t
            self._t_energy = t
            return
        if abs(t - t_last) <= _T_EPS:
            return
        self._restart(t)

    def _runaway_evidence(self):
        """[largest overlap / R_b of the evaluations that passed the runaway
        check, whether the step exceeds its stable-step estimate]: what
        :meth:`_check_worst` weighs when a run blows up (one list per element,
        changed in place: the fast mode's closure holds it)."""
        evidence = self.__dict__.get("_evidence")
        if evidence is None:
            evidence = self._evidence = [0.0, False]
        return evidence

    def _restart(self, t):
        """Reset the element to its initial state for a run starting at t."""
        self._runaway_evidence()[0] = 0.0
        self._reset_defects_and_signals(t)
        self._hz[:] = 0.0
        self._t_commit = t
        self._t_trial = -math.inf
        self._t_energy = t
        self._work[:] = self._work0
        self._sample_t.clear()
        self._sample_rows.clear()
        self._next_sample = t + self.sampleInterval
        self._evaluations = 0
        self._wall = 0.0
        for a in (self._fr, self._glob, self._diag, self._cage_load, self._out):
            a[...] = 0.0
        if self.mode == "fast":
            self._clock[:] = [math.nan, t, t + self.sampleInterval, False, 0]

    def _check_run(self, t):
        """Start a new run (:meth:`_new_run`) if ``t`` is the first time of a
        new SolveDynamic; for the sensors, which Exudyn evaluates at the start
        time before the first force evaluation."""
        if self._sys.get("dynamicSolver") is not self._run[0] or t <= self._run[1] + _T_EPS:
            self._new_run(t, self._clock[0] if self.mode == "fast" else self._t_trial)

    def _take_coordinates(self):
        """Views of the system's current ODE2 coordinates and velocities (``GetODE2Coordinates(copy=False)``:
        Exudyn's own vectors, no copy), taken at each run's start and kept in ``_coordinates`` [coordinates,
        velocities, system index of the first coordinate of the user function's object: the first ball's in
        the body mode, the first ring node's in the fast mode].

        Exudyn allocates these vectors when it assembles and initializes a solve and writes every state of the
        run into them in place: a view taken at the run's first evaluation shows the state of each later one
        (checked at every evaluation of VelocityVerlet, RK44, RK67, ODE23, DOPRI5, GeneralizedAlpha with its
        numerical Jacobian and TrapezoidalIndex2 runs: equal to the copy, the same memory throughout;
        tests/test_element_state.py checks VelocityVerlet and GeneralizedAlpha). It replaces two copying calls
        per evaluation (in the fast mode two conversions of
        Exudyn's lists). The views do not keep the vectors alive, so the user functions compare the first
        coordinate Exudyn hands them with the view's at every evaluation and take them anew when they differ."""
        sd = self.mbs.systemData
        cell = self.__dict__.setdefault("_coordinates", [None, None, 0])
        cell[:] = [sd.GetODE2Coordinates(copy=False), sd.GetODE2Coordinates_t(copy=False), int(self._sys_index[0])]

    def _system_index(self):
        """System ODE2 index of each object-layout coordinate (after ``mbs.Assemble``)."""
        mbs = self.mbs
        return np.concatenate([mbs.GetNodeODE2Index(nd) + np.arange(size, dtype=np.int64)
                               for nd, size in self._layout_nodes]).astype(np.int64)

    def _make_body_uf(self):
        """The body mode's force user function, a closure over the element's
        state and the compiled call's entry point (:func:`~.kernels.body_step`).

        Per evaluation it computes the forces of all balls, cage balls and
        rings from the system's current coordinates (its arguments ``q``,
        ``q_t`` hold only the first ball and the rings: Exudyn converts them
        per coordinate), returns the first ball's and the rings' and writes
        the other balls' into the force vector of the ball object. The
        system index of each coordinate is set at each run's start
        (:meth:`_new_run`), and so are the views of the system's coordinate
        vectors it reads (:meth:`_take_coordinates`). The Cundall-Strack commit, the sample and energy
        clocks and the gathering of the returned forces run in the compiled
        call, which takes the element's arrays as one structure
        (:class:`~.kernels.ElementState`); bound locals instead of attribute
        look-ups and the entry point instead of numba's type dispatch
        (validation/performance/profile_element.py times the parts)."""
        st, n_cage, paths = self._state, self.n_cage, self._paths
        rdata, rings, times, out_balls, out_uf = self._ring_data, self._rings, self._times, self._out_balls, self._out_uf
        speeds, spin = self._speeds, EK.RD_SPIN
        spin_angles = self._spin_angles if self._track_angle else None
        run, sysd, new_run = self._run, self._sys, self._new_run
        self._runaway_evidence()  # created here: _after_advance updates it
        after_advance, want_at = self._after_advance, EK.CLK_WANT
        perf_counter = time.perf_counter
        step = entry_point(EK.body_step, (self._out, self._out, st, 0.0, n_cage, *paths))
        take_coordinates = self._take_coordinates
        coordinates = self.__dict__.setdefault("_coordinates", [None, None, 0])  # set at each run's start

        def force_uf(mbs, t, itemNumber, q_object, q_t_object):
            t0 = perf_counter()
            if sysd.get("dynamicSolver") is not run[0] or t <= run[1] + _T_EPS:
                new_run(t, times[EK.CLK_TRIAL])
            for r, f in speeds:
                rdata[r, spin] = f(t)
            if spin_angles is not None:
                spin_angles(t)
            qs, qs_t, first = coordinates
            if qs[first] != q_object[0]:  # not Exudyn's current vectors (never seen within a run): take them anew
                take_coordinates()
                qs, qs_t, first = coordinates
            worst = step(qs, qs_t, st, t, n_cage, *paths)
            mbs.SetObjectParameter(self._ball_object, "forceVector", out_balls)
            after_advance(worst, t, times[want_at], t, rings)
            self._evaluations += 1
            self._wall += perf_counter() - t0
            return out_uf.tolist()

        return force_uf

    def _make_fast_uf(self):
        """The fast mode's force user function, a closure over the element's
        arrays and the compiled step's entry point.

        Per Exudyn evaluation it advances the balls in compiled sub-steps to
        t + (H - dt)/2 and returns the mean ring reactions of those sub-steps
        as generalized ring forces (the sub-step windows are centred on the
        Exudyn times, so the ring's and the balls' impulses match:
        :func:`~.kernels.advance_balls`). It runs once per Exudyn step, and its
        Python cost is a large share of the step: bound locals instead of
        attribute look-ups and the compiled entry point instead of numba's
        type dispatch take about a tenth off the step
        (validation/performance/bench_element.py times the result)."""
        st, paths, rdata, rings, rings_sub, out = (self._state, self._paths, self._ring_data, self._rings,
                                                   self._rings_sub, self._out)
        ref, params, table, kind, work, rings0, hist, hz = (self.ref, self.params, self.table, self._ring_kind,
                                                            self._work, self._rings0, self._hist, self._hz)
        fr, glob, diag, cload = self._fr, self._glob, self._diag, self._cage_load
        speeds, dt_sub, spin = self._speeds, self._dt_sub, EK.RD_SPIN
        spin_angles = self._spin_angles if self._track_angle else None
        # [t of the last Exudyn evaluation (nan: none yet), tau, next sample, step checked, Exudyn steps]
        clock = self._clock
        run, sysd, new_run = self._run, self._sys, self._new_run
        self._runaway_evidence()  # created here: _after_advance updates it
        asarray = np.asarray
        perf_counter = time.perf_counter
        step = entry_point(EK.fast_step, (out, out, st, 1, 0.0, 0.0, 0.0, False, *paths))
        take_coordinates = self._take_coordinates
        coordinates = self.__dict__.setdefault("_coordinates", [None, None, 0])  # set at each run's start

        def force_uf_fast(mbs, t, itemNumber, q, q_t):
            t0 = perf_counter()
            for r, f in speeds:
                rdata[r, spin] = f(t)
            if spin_angles is not None:
                spin_angles(t)
            t_int = clock[0]
            if t > t_int + 1e-15:  # False before the first evaluation (nan)
                qs, qs_t, first = coordinates
                if qs[first] != q[0]:  # not Exudyn's current vectors (never seen within a run): take them anew
                    take_coordinates()
                    qs, qs_t, first = coordinates
                big = t - t_int
                if not clock[3]:
                    self._check_fast_step(big)
                m = int(big / dt_sub + 0.5) or 1
                t_end = t + 0.5 * (big - big / m)
                tau = clock[1]
                n_sub = int((t_end - tau) * m / big + 0.5) or 1
                want = t >= clock[2] - 1e-12
                worst = step(qs, qs_t, st, n_sub, tau, t, t_end, want, *paths)
                clock[0] = t
                clock[1] = t_end
                clock[4] += 1
                self._after_advance(worst, t, want, t_end, rings_sub)
                if want:
                    clock[2] = self._next_sample
                self._wall += perf_counter() - t0
                return out
            # a new SolveDynamic starts at or before the last time (a run that starts later continues this one)
            if sysd.get("dynamicSolver") is not run[0] or t <= run[1] + 1e-12:
                new_run(t, t_int)
                t_int = clock[0]
            # Exudyn's lists as contiguous float64 arrays
            q = asarray(q, float)
            q_t = asarray(q_t, float)
            if t_int != t_int:
                # first evaluation: forces at the initial state, nothing to integrate yet (the balls' body
                # frames start the first sub-step unturned, as in the reference engine)
                EK.ring_poses_from(q, q_t, ref, kind, rdata, rings)
                frames = hist[:, H_E1:].copy()
                forces(params, table, work[0], work[1], work[2], work[3], work[4], rings, hist, hist, dt_sub, hz,
                         work[5], work[6], work[7], fr, glob, diag, cload, False)
                hist[:, H_E1:] = frames
                rings0[:] = rings
                clock[0] = clock[1] = t
            elif t < t_int - 1e-15:
                raise InputError(f"mode: an evaluation at t = {t:.9g} s after one at {t_int:.9g} s; the fast mode "
                                 "integrates the balls forward in time and needs an explicit fixed-step solver "
                                 "(VelocityVerlet, or RK44 with friction='regularized'); a new SolveDynamic starts "
                                 "at the first run's start time (restart) or at its end time (continuation)")
            # no time advance: the last reactions at the current ring poses
            qs, qs_t, first = coordinates
            if qs[first] != q[0]:
                take_coordinates()
                qs, qs_t, first = coordinates
            step(qs, qs_t, st, 0, clock[1], t, t, False, *paths)
            self._wall += perf_counter() - t0
            return out

        return force_uf_fast

    def _after_advance(self, worst, t, want, t_sample, rings):
        """After an evaluation at t that advanced the balls (both modes): the runaway check of its largest
        overlap / R_b ``worst``, the evidence kept for it, a sample at ``t_sample`` of the ring poses
        ``rings`` the balls saw (when ``want``) and the signal series."""
        if not worst <= self._max_overlap:  # also catches NaN
            self._check_worst(worst, t)
        evidence = self._evidence
        if worst > evidence[0]:
            evidence[0] = worst
        if want:
            self._sample(t_sample, rings)
            if self._on_sample is not None:
                self._on_sample(t_sample)
        if self._sig is not None:
            self._signal_sample(t)

    def _sub_steps_in(self, h):
        """The fast mode's number of ball sub-steps in an Exudyn step ``h`` [s]: the whole number nearest
        h / stepSize, at least one."""
        return max(1, int(h / self._dt_sub + 0.5))

    def _check_fast_step(self, h, stacklevel=4):
        """Warn (once) when the fast mode's Exudyn step ``h`` exceeds its limit
        or its ball sub-step the balls' stable step. With two or more
        sub-steps the limit is ``fastStepLimit`` (the staggered coupling); one
        sub-step is the body mode's scheme, bounded by ``ringStableStep``."""
        self._clock[3] = True
        n_sub = self._sub_steps_in(h)
        dt = h / n_sub
        self._staggered = n_sub > 1  # the bound the runaway message names (_check_worst)
        limit = self.fastStepLimit if self._staggered else self.ringStableStep
        self._runaway_evidence()[1] = h > limit or dt > self.stable.dt
        if h > limit and n_sub > 1:
            fits = max(1, int(limit / dt))  # one sub-step is the body mode's scheme, not staggered
            warnings.warn(f"subSteps: the Exudyn step {h:.3g} s exceeds the fast mode's limit {limit:.3g} s "
                          f"({FAST_STEP_SHARE:g} of the ring bodies' stable-step estimate {self.ringStableStep:.3g} s: "
                          "their inertia against their bearings' contact stiffness at initialLoad); beyond it the "
                          "staggered coupling of ring and balls can put the ball loads more than 0.5 % off (measured "
                          "from 0.3 of the estimate on) and, from about half of it on, grows a ring vibration that "
                          "multiplies them or blows the run up (validation/studies/fast_mode_limits.py): use at most "
                          f"{fits} sub-step{'s' if fits > 1 else ''} of {dt:.3g} s", StepSizeWarning,
                          stacklevel=stacklevel)
        elif h > limit:
            warnings.warn(f"stepSize: the Exudyn step {h:.3g} s (one sub-step) exceeds the ring bodies' stable-step "
                          f"estimate {limit:.3g} s (their inertia against their bearings' contact stiffness at "
                          "initialLoad): the ring motion will be wrong or blow up; use a smaller stepSize",
                          StepSizeWarning, stacklevel=stacklevel)
        msg = step_warning(f"stepSize: the ball sub-step {dt:.3g} s", dt, self.stable)
        if msg:
            warnings.warn(msg, StepSizeWarning, stacklevel=stacklevel)

    def _check_worst(self, worst, t):
        """SimulationError when the largest overlap / R_b ``worst`` of the
        evaluation at ``t`` is non-finite or above the runaway limit, naming
        what the evidence shows (:func:`~exudyn_bearing.model.stability.runaway_error`):
        a ring marker's state handed over by Exudyn non-finite (the input);
        else, with the step within its estimate, the ball loads the run
        reached before (the largest overlap of the evaluations that passed the
        check, as load and pressure at the race where they are lower) above
        the elastic contact limit (the loads); else the step."""
        if math.isfinite(worst) and worst <= self._max_overlap:
            return
        if worst >= POCKET_ESCAPE:
            raise SimulationError(
                f"rigidCage: at t = {t:.4g} s a ball left its pocket (its centre moved beyond the cage's section "
                "along the pocket's axis): the cage drifted off its balls, which this model cannot represent; a "
                "ball-guided cage needs spherical pockets, a land-guided one a land clearance below its pocket "
                "clearance")
        what = "non-finite or runaway"
        for r, ring in enumerate(("inner", "outer")):
            parts = [name for name, cols in (("position", _POSE_POSITION), ("velocity", _POSE_VELOCITY))
                     if not np.isfinite(self._rings[r, cols]).all()]
            if parts:
                option = "markerInnerRing" if r == 0 else "markerOuterRing"
                raise runaway_error(option, t, self.stable, "non-finite", bad_input=(
                    option, f"the {ring} ring marker's {' and '.join(parts)}"))
        peak, step_over = self._runaway_evidence()
        if peak > 0.0 and not step_over:
            contacts = overlap_contacts(self.bearing, peak * self.bearing.ball_radius, self.scenario.hertz)
            low = 0 if contacts[0][1] <= contacts[1][1] else 1
            # the lower of both races: the overlap was reached at one of them
            excess = pressure_excess([contacts[0][1] if low == 0 else 0.0], [contacts[1][1] if low == 1 else 0.0])
            if excess is not None:
                raise runaway_error("load", t, self.stable, what, excess=(contacts[low][0], excess[0], excess[1]))
        ring = ((f" and the fast mode's limit {self.fastStepLimit:.3g} s for its Exudyn step (subSteps * stepSize; "
                 f"{FAST_STEP_SHARE:g} of the ring bodies' stable-step estimate)"
                 if self.__dict__.get("_staggered", self.subSteps > 1) else
                 f" and the ring bodies' {self.ringStableStep:.3g} s for the fast mode's Exudyn step")
                if self.mode == "fast" and math.isfinite(self.ringStableStep) else "")
        raise runaway_error("stepSize", t, self.stable, what, ring=ring)
