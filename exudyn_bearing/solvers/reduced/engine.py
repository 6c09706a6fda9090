"""Driver of the reduced engine (docs/theory/reduced.md): the ball centres on their normal force balance
at every step (the reduction of Walters 1971 and of Gupta's ADORE), the ball speeds, the rigid cage and the inner ring
advanced by a linearly implicit (BDF2) step, so that the step is not bound by the ball / race contact
vibration. Same contact kernel, parameter vector, initial state, samples and
:class:`~exudyn_bearing.model.record.RunRecord` as the reference engine
(:mod:`exudyn_bearing.solvers.reference`), so :class:`~exudyn_bearing.outputs.results.Results`, the summary,
the energy balance and the steady-state verdict read it unchanged.
"""
from __future__ import annotations

import sys
import time

import numpy as np

from ..._jit import announce_compilation
from ...data import InputError, Lubricant, default_lubricant, load_bearing
from ...model.contact import forces, scene_loss_path, scene_paths
from ...model.initial_state import initial_state
from ...model.layout import HIST_N, NDIAG, NGLOBAL
from ...model.motion import ring_poses
from ...model.parameters import scene_parameters
from ...model.record import RunInterrupted, RunRecord, sample_buffers
from ...model.scenario import Scenario, engine_speed_error, resolve_cage
from ...model.stability import SimulationError
from ...physics import hertz
from . import stepper as _st
from .stepper import (N_CAGE, N_CORR, N_WORK, W_CORR, W_EVALS, W_ITER, W_ITER_MAX, W_JAC, W_REFRESH, W_UNCONVERGED,
                      run_reduced)

__all__ = ["ReducedEngine", "reduced_support_error", "BALANCE_TOL", "MAX_ITER", "CHUNK_STEPS", "MIN_STEP", "MAX_STEP"]

#: Newton tolerance of the balls' force balance [m]: the centre's last correction (1e-7 of the 1e-5 m
#: overlap of a loaded ball; its load to about 1.5e-7).
BALANCE_TOL = 1e-12
#: Newton iterations of a step's force balance at most (a step that needs more is counted in the summary's
#: ``reduced.unconverged_steps`` and goes on from the last iterate); the balance at a run's start, from a state
#: that may be far off it, takes up to :data:`~exudyn_bearing.solvers.reduced.stepper.START_ITER` times as many.
MAX_ITER = 12
#: Steps over which the Jacobians of the ball speeds and of the ring are kept at most: in a steady state
#: with every ball loaded alike (the 6208 under thrust, the ACBB-120) nothing else retakes them, so this sets
#: the cost (docs/theory/reduced.md, "The step").
JAC_EVERY = 8
#: Change of a ball's load proxy (its overlaps^1.5), relative to its own at the last retaking (at least
#: :data:`~exudyn_bearing.solvers.reduced.stepper.LOAD_FLOOR` of the largest ball's), that retakes the Jacobians
#: before JAC_EVERY steps (a ball passing through the load zone, entering or leaving it); a change of a ball's
#: speeds by :data:`~exudyn_bearing.solvers.reduced.stepper.SPEED_TOL` of its orbital surface speed also
#: retakes them (a run-up).
JAC_TOL = 0.1
#: The ring's Jacobians are retaken at every RING_EVERY-th retaking of the balls' (the ring's stiffness moves
#: little as the balls pass: the 6208 radial's Q_max moved by 0.001 % at 100 us with 2 against 1).
RING_EVERY = 2
#: Steps of a chunk (the progress line's and Ctrl-C's granularity).
CHUNK_STEPS = 2000

#: The least step [s] of the step error control (``Scenario.tolerance``): a step rejected at it stops the run
#: naming the tolerance. A tenth of the reference engine's steps (1-2 us): a start off the speeds' balance (the
#: analytic start) relaxes its slips within microseconds, which a tolerance of 1e-6 resolves with steps below
#: 1 us for the first tens of microseconds (tests/test_reduced_engine.py).
MIN_STEP = 1e-7
#: The largest step [s] of the step error control, also at most the sample interval: the largest step a
#: Scenario takes (its dt), the largest the reduced engine's checks ran (docs/theory/reduced.md).
MAX_STEP = 1e-4

#: A command line the reduced engine runs (its docs and its refusals quote it).
EXAMPLE_COMMAND = ("python -m exudyn_bearing simulate 6208 --Fr 3000 --omega 500 --engine reduced --cage none "
                   "--traction-level ellipse --dt 2e-5")


def reduced_support_error(scenario: Scenario, bearing) -> InputError | None:
    """The InputError naming what ``scenario`` asks of the reduced engine that it does not model on ``bearing``
    (None when it models all of it): the first such parameter leads the message, which lists every one of them
    (the defaults cage='auto' and friction='history' need two changes at once) and a command that runs."""
    s = resolve_cage(scenario, bearing)
    problems = []
    if s.cage == "torus":
        given = "" if scenario.cage == "torus" else f" (cage={scenario.cage!r} gives the {bearing.name} its torus cage)"
        problems.append(("cage", f"the reduced engine does not take the torus cage{given}: its light cage balls on "
                                 "their own contacts would set the step again; use cage='none' or 'rigid'"))
    if s.cage == "rigid" and s.cage_damping == "implicit":
        problems.append(("cage_damping", "'implicit' is the reference engine's backward-Euler damping over its "
                                         "step; the reduced engine takes the rigid cage's contacts into its own "
                                         "implicit step: cage_damping='explicit'"))
    if s.traction_level == "point" and s.friction == "history":
        problems.append(("friction", "'history' (the Cundall-Strack spring, the point level's default) is "
                                     "non-smooth and stays with the reference engine; the reduced engine takes "
                                     "traction_level='ellipse', or friction='regularized' or 'none'"))
    if s.defects:
        problems.append(("defects", "the reduced engine leaves out the ball / race contact vibration, so defect "
                                    "impacts and their signals stay with the reference engine"))
    if s.tolerance is not None and s.dt < MIN_STEP:
        problems.append(("dt", f"with a tolerance, dt is the first step and must be at least the step control's "
                               f"least step {MIN_STEP:g} s (got {s.dt:g} s)"))
    if s.signal_dt is not None:
        problems.append(("signal_dt", "the condition-monitoring signals (contact vibration) are recorded by the "
                                      "reference engine only"))
    if not problems:
        return None
    text = "; ".join(f"{name}: {why}" if k else why for k, (name, why) in enumerate(problems))
    return InputError(f"{problems[0][0]}: {text} (a run it takes: {EXAMPLE_COMMAND}; docs/theory/reduced.md)")


def _orbital(wb, phi):
    """World-frame angular velocities (Z, 3) in the orbital frames (e_r, e_t, e_z) at the angles ``phi``."""
    c, s = np.cos(phi), np.sin(phi)
    return np.stack([wb[:, 0] * c + wb[:, 1] * s, -wb[:, 0] * s + wb[:, 1] * c, wb[:, 2]], axis=1)


class ReducedEngine:
    """The reduced engine for one bearing, lubricant and scenario (``Scenario.dt`` its step, typically
    10-50 us, or with ``Scenario.tolerance`` its first step, the steps then chosen by the step error control,
    docs/theory/reduced.md; the scenario's ``integrator`` names the reference engine's scheme and is not used).

    Parameters as :class:`~exudyn_bearing.solvers.reference.ReferenceEngine`; a scenario asking for what the
    engine does not model raises InputError naming it (:func:`reduced_support_error`).
    """

    name = "reduced"

    def __init__(self, bearing, scenario: Scenario, lubricant: Lubricant | None = None, start: dict | None = None):
        b = load_bearing(bearing)
        if scenario.Pd is not None:
            b = b.with_clearance(scenario.Pd)
        err = reduced_support_error(scenario, b) or engine_speed_error(scenario, self.name)
        if err is not None:
            raise err
        announce_compilation(forces, run_reduced)
        self.bearing = b
        self.start = start
        self.scenario = scenario = resolve_cage(scenario, b)
        self.lubricant = default_lubricant(b) if lubricant is None else lubricant
        self.params = scene_parameters(b, scenario, self.lubricant)
        self.table = hertz.exact_table()
        self.work = np.zeros(N_WORK)
        self.jac_every, self.jac_tol, self.ring_every = JAC_EVERY, JAC_TOL, RING_EVERY
        #: Newton corrections of a step with the rigid cage at most (stepper.N_CORR)
        self.n_corr = N_CORR
        self._adapt = np.zeros(_st.N_ADAPT)  # the step control's vector of the last run (step_control)

    def initial_state(self):
        """The reduced state at t = 0 from the scene's initial state
        (:func:`exudyn_bearing.model.initial_state.initial_state`): orbital angle, radius and axial position,
        orbital speed of each ball centre, the ball angular velocities and the ring."""
        st = initial_state(self.bearing, self.scenario, self.start)
        xb, vb = st["xb"], st["vb"]
        r = np.hypot(xb[:, 0], xb[:, 1])
        return {"phi": np.arctan2(xb[:, 1], xb[:, 0]), "om": (xb[:, 0] * vb[:, 1] - xb[:, 1] * vb[:, 0]) / r ** 2,
                "wo": _orbital(st["wb"], np.arctan2(xb[:, 1], xb[:, 0])), "q": np.stack([r, xb[:, 2]], axis=1), "ring": st["ring"].copy(),
                "hz": st["hz"], "static": st["static"], "xc": st["xc"].copy(), "vc": st["vc"].copy()}

    def step_control(self) -> np.ndarray:
        """The step error control's vector (:data:`~exudyn_bearing.solvers.reduced.stepper.N_ADAPT`) at the
        run's start: tolerance 0 (the fixed step ``Scenario.dt``) without ``Scenario.tolerance``, else the first
        step dt, the least step :data:`MIN_STEP`, the largest min(:data:`MAX_STEP`, sample_dt), and the speed
        scale of the tolerance: the inner ring's speed at the pitch radius, |omega| r_p, at least the
        scenario's regularizing_speed (a run at rest)."""
        s = self.scenario
        a = np.zeros(_st.N_ADAPT)
        if s.tolerance is None:
            return a
        a[_st.A_TOL] = s.tolerance
        a[_st.A_H] = a[_st.A_HPREV] = a[_st.A_HPREV2] = s.dt
        a[_st.A_HMIN] = min(MIN_STEP, s.dt)
        a[_st.A_HMAX] = max(min(MAX_STEP, s.sample_dt), s.dt)
        a[_st.A_TEND] = s.t_end
        a[_st.A_SDT] = s.sample_dt
        a[_st.A_U] = max(abs(s.omega) * self.bearing.pitch_radius, s.regularizing_speed)
        return a

    def run(self, progress=None, chunk_steps=None):
        """Integrate the scenario; returns the :class:`~exudyn_bearing.model.record.RunRecord` (``progress``
        True prints progress on stderr; Ctrl-C between chunks raises RunInterrupted with the samples so
        far). With ``Scenario.tolerance`` the steps are chosen by the step error control (the samples still
        every sample_dt, steps landing on them); the record's ``step_sizes`` lists the steps taken."""
        s = self.scenario
        p = self.params
        dt = s.dt
        adapt = self._adapt = self.step_control()
        adaptive = s.tolerance is not None
        n_steps = int(round(s.t_end / dt))
        every = max(1, int(round(s.sample_dt / dt)))
        n_samples = n_steps // every
        if adaptive:  # a sample every sample_dt up to t_end; the steps as the error control takes them
            n_samples = int(np.floor(s.t_end / s.sample_dt + 1e-9))
            n_steps = 2 ** 62
        z = self.bearing.n_balls
        st = self.initial_state()
        phi, om, wo, q, ring, hz = st["phi"], st["om"], st["wo"], st["q"], st["ring"], st["hz"]
        wb = np.zeros((z, 3))
        q_old = q.copy()
        qd = np.zeros((z, 2))  # the centres' radial and axial rates at the last balance's start (their inertia)
        prev, ring_prev = np.zeros((z, 5)), np.zeros(6)  # the state of the step before (BDF2)
        xb, vb = np.zeros((z, 3)), np.zeros((z, 3))
        cage_free = self.scenario.cage == "rigid"
        if cage_free:  # the rigid cage's rows (model/layout.py): integrated with the balls
            xc, vc = st["xc"], st["vc"]
        else:  # no cage: rows the kernel does not read
            xc, vc = np.zeros((z, 3)), np.zeros((z, 3))
        cage_prev = np.zeros(N_CAGE)
        fb, tb, fc = np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((z, 3))
        fr, fring = np.zeros((2, 6)), np.zeros(3)
        hist = np.zeros((z, HIST_N, 3))
        rings = ring_poses()
        glob = np.zeros(NGLOBAL)
        diag, cage_load = np.zeros((z, 2, NDIAG)), np.zeros((z, 2))
        buf = sample_buffers(n_samples, z)
        defect_path, ellipse_path = scene_paths(p)
        loss_path = scene_loss_path(p)
        work = self.work
        ys = np.zeros((3, _st.state_count(z)))
        chunk = chunk_steps or CHUNK_STEPS
        h_log = np.zeros(chunk if adaptive else 0)
        steps_taken = []

        def call(m, done, k_samp):
            sl = slice(k_samp, n_samples)
            return run_reduced(m, done * dt, dt, p, self.table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings,
                               hist, hz, fb, tb, fc, fr, fring, glob, diag, cage_load, BALANCE_TOL, MAX_ITER, every,
                               done, buf["t"][sl], buf["glob"][sl], buf["diag"][sl], buf["cage_load"][sl],
                               buf["xb"][sl], buf["vb"][sl], buf["wb"][sl], buf["xc"][sl], buf["vc"][sl],
                               buf["ring"][sl], work, True, self.jac_every, self.jac_tol, self.ring_every, prev,
                               ring_prev, cage_free, cage_prev, self.n_corr, adapt, ys, h_log, qd,
                               defect_path, ellipse_path, loss_path)

        # compile (or load from the cache) before the clock starts: zero steps on copies of the state
        kept = (phi, om, wo, q, q_old, ring, hz, glob, work, prev, ring_prev, xc, vc, cage_prev, adapt, ys, qd)
        saved = [a.copy() for a in kept]
        call(0, 0, 0)
        for a, b in zip(kept, saved):
            a[...] = b
        done = 0
        k_samp = 0
        wall0 = time.perf_counter()
        last = wall0
        line_open = False

        def reached():
            return float(adapt[_st.A_T]) if adaptive else done * dt

        def finished():
            return reached() >= s.t_end - 1e-9 * s.sample_dt if adaptive else done >= n_steps

        try:
            while not finished():
                m = min(chunk, n_steps - done)
                steps, ns, status = call(m, done, k_samp)
                if adaptive:
                    steps_taken.append(h_log[:steps].copy())
                done += steps
                k_samp += ns
                if status == 3:
                    raise SimulationError(
                        f"tolerance: the reduced engine's step error control rejected a step of the least size "
                        f"{adapt[_st.A_HMIN]:.3g} s at t = {reached():.6g} s (its error {adapt[_st.A_ERR]:.3g} "
                        f"times tolerance = {s.tolerance:g}); a looser tolerance, the fixed step (no tolerance: "
                        f"dt = {s.dt:g} s), or the reference engine")
                if status != 0:
                    what = ("non-finite state" if status == 1 else
                            "runaway overlap (above 5 % of the ball radius, at a ball / race, ball / ball or "
                            "ball / pocket contact, or a ball out of its pocket)")
                    smaller = "a tighter tolerance" if adaptive else "a smaller dt"
                    why = ("its ball / ball contacts (no cage) are explicit, so balls that collide (a run-up from "
                           f"rest) need the reference engine; else {smaller}" if not cage_free else
                           f"{smaller}, or the reference engine")
                    step_text = (f"tolerance = {s.tolerance:g}, last step {adapt[_st.A_HPREV]:.3g} s" if adaptive
                                 else f"dt = {dt:.3g} s")
                    raise SimulationError(f"reduced engine: {what} at t = {reached():.4g} s with {step_text}; "
                                          + why)
                if progress and (time.perf_counter() - last > 0.5 or finished()):
                    last = time.perf_counter()
                    print(f"\r[reduced] t = {reached():.4f}/{s.t_end:.4f} s  wall {last - wall0:6.1f} s", end="",
                          file=sys.stderr, flush=True)
                    line_open = True
            wall = time.perf_counter() - wall0
        except KeyboardInterrupt:
            raise RunInterrupted(reached(), s.t_end, self._record(buf, k_samp, done, time.perf_counter() - wall0,
                                                                  st, steps_taken)) from None
        finally:
            if line_open:
                print(file=sys.stderr)
        return self._record(buf, k_samp, done, wall, st, steps_taken)

    def stats(self, steps: int, sizes=None) -> dict:
        """Work of the run: Newton iterations of the force balance per step (mean, worst), force evaluations
        per step (the rejected steps' included), steps whose balance did not converge within MAX_ITER, the
        steps that retook the speeds' Jacobians and the balance's Jacobians taken; the
        step control: the tolerance (None: the fixed step), the steps rejected, the least, median and largest
        step taken [s] (``sizes``, the steps taken; the fixed step's dt without the tolerance)."""
        w = self.work
        n = max(steps, 1)
        s = self.scenario
        if s.tolerance is None or sizes is None or len(sizes) == 0:
            sizes = np.full(1, s.dt)
        return {"newton_per_step": float(w[W_ITER]) / n, "newton_max": int(w[W_ITER_MAX]),
                "evaluations_per_step": float(w[W_EVALS]) / n, "unconverged_steps": int(w[W_UNCONVERGED]),
                "jacobian_steps": int(w[W_REFRESH]), "balance_jacobians": int(w[W_JAC]),
                "pocket_corrections": int(w[W_CORR]),
                "tolerance": s.tolerance, "steps_rejected": int(self._adapt[_st.A_NREJ]),
                "restarts": int(self._adapt[_st.A_NRESTART]),
                "dt_min": float(np.min(sizes)), "dt_median": float(np.median(sizes)),
                "dt_max": float(np.max(sizes))}

    def _record(self, buf, k_samp, done, wall, st, steps_taken=()) -> RunRecord:
        data = {k: v[:k_samp] for k, v in buf.items()}
        rec = RunRecord(self.bearing, self.scenario, self.lubricant, data, steps=done, wall_s=wall,
                        engine=self.name, stable_dt=None, static=st["static"])
        sizes = np.concatenate(steps_taken) if len(steps_taken) else np.zeros(0)
        rec.reduced_stats = self.stats(done, sizes)  # the engine's work (not a sampled series)
        rec.step_sizes = sizes if self.scenario.tolerance is not None else None  # the steps taken [s]
        return rec
