"""Driver of the numba DEM reference engine: scene set-up, chunked
integration with progress, the sampled record.

The engine simulates a complete ball bearing ball by ball
(docs/theory/dynamics.md): Z balls and Z cage balls with 6 DOF, the inner ring translating
freely under the applied loads and spun at the prescribed omega(t), the outer
ring fixed. It does not import exudyn.
"""
from __future__ import annotations

import sys
import time
import warnings

import numpy as np

from ..._jit import announce_compilation
from ...data import InputError, Lubricant, default_lubricant, load_bearing
from ...model.contact import forces, scene_loss_path, scene_paths
from ...model.initial_state import initial_state
from ...model.layout import G_LAND_ECC, G_WORST, H_E1, NDIAG, NGLOBAL, NSIGNAL, POCKET_ESCAPE
from ...model.memory import ESTIMATE_AFTER_S, wall_time_message
from ...model.motion import ring_poses
from ...model.parameters import scene_parameters
from ...model.record import RunInterrupted, RunRecord, sample_buffers
from ...model.scenario import Scenario, fixed_step_error, resolve_cage
from ...model.stability import SimulationError, StepSizeWarning, cage_load_check, land_step_check, runaway_error, stable_step, step_warning
from ...physics import hertz
from ...physics.contact_slip import DEFAULT_N_ACROSS, DEFAULT_N_STRIPS
from .integrators import evaluate, run_rk4, run_verlet

__all__ = ["ReferenceEngine", "PROBE_STEPS", "CHUNK_BALL_STEPS", "ELLIPSE_STEP_COST"]

#: Steps of the first chunk; the chunks double from it up to :meth:`ReferenceEngine.chunk_cap`.
PROBE_STEPS = 1000
#: Ball-steps of a chunk at the point level: about half a second of wall time, the progress line's and Ctrl-C's
#: granularity (the chunks are fixed by step counts, not by the clock, so that a run does not depend on the
#: machine's speed: with a speed protocol the chunk boundaries change the run at round-off, 1e-9 of the ring
#: displacement). Step costs on the 2-core machine (``ReferenceEngine(...).run()``'s wall_s / steps, dt = 2 us,
#: t_end = 4 ms, 6208 at F_r = 3000 N and 500 rad/s, ACBB-120 at F_a = 22240 N and 2618 rad/s without cage):
#: 1.9 and 4.5 us at the point level, 21 and 18 us at the ellipse level with the default strips.
CHUNK_BALL_STEPS = 9 * 2 ** 18
#: Cost of a step at the ellipse level with the default strips and points across, relative to the point level.
ELLIPSE_STEP_COST = 10.0
class ReferenceEngine:
    """The numba DEM engine for one bearing, lubricant and scenario.

    Parameters
    ----------
    bearing : BallBearing or str
        Bearing or catalogue name / JSON path.
    scenario : Scenario
    lubricant : Lubricant, optional
        Default: the DEM papers' lubricant.
    start : dict, optional
        Initial state (:func:`~exudyn_bearing.model.initial_state.state_from_ball_kinematics`,
        e.g. a quasi-static solution's ``dynamic_start``); required with
        ``scenario.initial == "quasistatic"``.
    """

    name = "reference"

    def __init__(self, bearing, scenario: Scenario, lubricant: Lubricant | None = None, start: dict | None = None):
        if scenario.tolerance is not None:  # its step is fixed: the step error control is the reduced engine's
            raise fixed_step_error(scenario, "reference")
        announce_compilation(forces, run_verlet if scenario.integrator == "verlet" else run_rk4)
        b = load_bearing(bearing)
        if scenario.Pd is not None:
            b = b.with_clearance(scenario.Pd)
        self.bearing = b
        self.start = start
        self.scenario = scenario = resolve_cage(scenario, b)  # "auto": the bearing's own cage
        self.lubricant = default_lubricant(b) if lubricant is None else lubricant  # None: the bearing's
        if scenario.cage == "torus" and not b.has_cage:
            raise InputError(f"cage: bearing {b.name} has no torus cage (cage_ball_radius is None); "
                             "use cage='rigid' (a rigid cage body) or cage='none'")
        self.params = scene_parameters(b, scenario, self.lubricant)
        self.table = hertz.exact_table()
        self.stable = stable_step(b, scenario, self.lubricant)

    def chunk_cap(self) -> int:
        """Steps of the longest chunk of the run: CHUNK_BALL_STEPS over the balls, over ELLIPSE_STEP_COST times
        the strips and points across relative to their defaults at the ellipse level (at least PROBE_STEPS)."""
        s = self.scenario
        cost = 1.0 if s.traction_level == "point" else (ELLIPSE_STEP_COST * s.n_strips * s.n_across
                                                         / (DEFAULT_N_STRIPS * DEFAULT_N_ACROSS))
        return max(PROBE_STEPS, int(CHUNK_BALL_STEPS / (self.bearing.n_balls * cost)))

    def initial_state(self):
        """The scene's initial state (:func:`exudyn_bearing.model.initial_state.initial_state`)."""
        return initial_state(self.bearing, self.scenario, self.start)

    # -- run -----------------------------------------------------------
    def run(self, progress=None, chunk_steps=None):
        """Integrate the scenario; returns the :class:`~exudyn_bearing.model.record.RunRecord`.

        ``progress``: True to print progress on stderr, None for automatic
        (runs over 2 million steps, or estimated to take over LONG_RUN_S),
        False for none. Unless False, a run whose wall time, estimated from the
        step cost of its first ESTIMATE_AFTER_S, exceeds LONG_RUN_S says so on
        stderr (:func:`~exudyn_bearing.model.memory.wall_time_message`). The run goes in chunks of PROBE_STEPS
        doubling up to :meth:`chunk_cap`, about half a second each
        (``chunk_steps``: fixed chunks instead); Ctrl-C between
        them raises :class:`~exudyn_bearing.model.record.RunInterrupted` with the
        samples so far.
        """
        s = self.scenario
        p = self.params
        msg = step_warning(f"dt = {s.dt:.3g} s", s.dt, self.stable)
        if msg:
            warnings.warn(msg, StepSizeWarning, stacklevel=2)
        n_steps = int(round(s.t_end / s.dt))
        every = max(1, int(round(s.sample_dt / s.dt)))
        n_samples = n_steps // every
        z = self.bearing.n_balls
        st = self.initial_state()
        xb, vb, wb, xc, vc, ring, hist, hz = (st[k] for k in ("xb", "vb", "wb", "xc", "vc", "ring", "hist", "hz"))
        fb = np.zeros((z, 3))
        tb = np.zeros((z, 3))
        fc = np.zeros((z, 3))
        fring = np.zeros(3)
        buf = sample_buffers(n_samples, z)
        sig_every = s.signal_every
        s_sig = np.zeros((n_steps // sig_every if sig_every else 0, 1 + NSIGNAL))
        sig_acc = np.zeros(NSIGNAL + 1)
        glob = np.zeros(NGLOBAL)  # the run's energy integrals accumulate here
        work = (np.zeros((z, 2, NDIAG)), np.zeros((z, 2)), ring_poses(), np.zeros((2, 6)))  # diag, cage_load, rings, fr
        # compile only the code paths the scene uses (defects, ellipse traction, signals)
        defect_path, ellipse_path = scene_paths(p)
        loss_path = scene_loss_path(p)
        signal_path = True if sig_every else None
        integrate = run_verlet if s.integrator == "verlet" else run_rk4
        quiet = progress is False  # an explicit False: no progress and no wall-time estimate
        if progress is None:
            progress = n_steps > 2_000_000
        chunk = chunk_steps or max(every, (max(n_steps // 50, 1) // every + 1) * every)
        done = 0
        k_samp = 0
        # compile (or load from the cache) before the clock starts: wall_s is the integration alone
        integrate(0, 0.0, p, self.table, xb, vb, wb, xc, vc, ring, hist, hz, fb, tb, fc, fring, every, 0,
                  buf["t"][:0], buf["glob"][:0], buf["diag"][:0], buf["cage_load"][:0], buf["xb"][:0],
                  buf["vb"][:0], buf["wb"][:0], buf["xc"][:0], buf["vc"][:0], buf["ring"][:0],
                  sig_every, sig_acc, s_sig, glob, *work, defect_path, ellipse_path, signal_path, loss_path)
        # forces at t = 0 (Verlet needs them on entry); the ball body frames start the first step unturned.
        # evaluate's Python body: its three calls run the specialisations the integrator has just compiled
        # (a compiled evaluate linked, optimised and compiled the contact kernel once more: 0.8 s of CPU of a
        # cold start, python validation/performance/profile_reference.py --compile)
        frames = hist[:, H_E1:].copy()
        first = getattr(evaluate, "py_func", evaluate)  # evaluate itself where numba's JIT is disabled
        diag, cage_load, rings, fr = work
        first(0.0, p, self.table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring,
              np.zeros(NGLOBAL), diag, cage_load, False, defect_path, ellipse_path, loss_path)
        hist[:, H_E1:] = frames
        wall0 = time.perf_counter()
        last_print = wall0
        line_open = False  # a progress line printed, not yet ended
        estimated = quiet  # the wall-time estimate said (or not to be said)
        # chunks from PROBE_STEPS doubling up to chunk_cap() (about half a second): the estimate and the progress
        # come within seconds, and Ctrl-C (handled between chunks) stops the run within a chunk
        cap = chunk if chunk_steps else min(chunk, self.chunk_cap())
        m_next = chunk if chunk_steps else min(cap, PROBE_STEPS)
        try:
            while done < n_steps:
                m = min(m_next, n_steps - done)
                sl = slice(k_samp, n_samples)
                steps, ns, status = integrate(
                    m, done * s.dt, p, self.table, xb, vb, wb, xc, vc, ring, hist, hz, fb, tb, fc, fring,
                    every, done, buf["t"][sl], buf["glob"][sl], buf["diag"][sl], buf["cage_load"][sl],
                    buf["xb"][sl], buf["vb"][sl], buf["wb"][sl], buf["xc"][sl], buf["vc"][sl], buf["ring"][sl],
                    sig_every, sig_acc, s_sig, glob, *work, defect_path, ellipse_path, signal_path, loss_path)
                done += steps
                k_samp += ns
                if status == 2 and glob[G_WORST] >= POCKET_ESCAPE:
                    raise SimulationError(
                        f"rigid_cage: at t = {done * s.dt:.4g} s a ball left its pocket (its centre moved beyond the "
                        "cage's section along the pocket's axis): the cage drifted off its balls, which this model "
                        "cannot represent; a ball-guided cage needs spherical pockets, a land-guided one a land "
                        "clearance below its pocket clearance")
                if status != 0:
                    t_fail = done * s.dt
                    what = ("non-finite" if status == 1 else
                            "runaway (overlap above 5 % of the radius of a ball or cage ball)")
                    raise runaway_error("dt", t_fail, self.stable, what, step=f" with dt = {s.dt:.3g} s", remedy="dt")
                m_next = min(cap, 2 * m_next)
                el = time.perf_counter() - wall0
                if not estimated and (el >= ESTIMATE_AFTER_S or done >= n_steps):
                    estimated = True
                    msg = wall_time_message(n_steps, done, el, s, self.stable.dt)
                    if msg:
                        if line_open:
                            print(file=sys.stderr)
                            line_open = False
                        print(f"[reference] {msg}", file=sys.stderr, flush=True)
                        progress = True  # a long run shows its progress
                if progress and (time.perf_counter() - last_print > 0.5 or done >= n_steps):
                    last_print = time.perf_counter()
                    el = time.perf_counter() - wall0
                    frac = done / n_steps
                    eta = el / frac * (1 - frac) if frac > 0 else float("nan")
                    print(f"\r[reference] t = {done * s.dt:.4f}/{s.t_end:.4f} s  {100 * frac:5.1f} %  "
                          f"wall {el:6.1f} s  eta {eta:6.1f} s", end="", file=sys.stderr, flush=True)
                    line_open = True
            wall = time.perf_counter() - wall0
        except KeyboardInterrupt:  # Ctrl-C between chunks: the samples so far go with the exception
            rec = self._record(buf, k_samp, sig_acc, s_sig, sig_every, done, time.perf_counter() - wall0, st)
            raise RunInterrupted(done * s.dt, s.t_end, rec) from None
        finally:  # end the progress line, also when an error or Ctrl-C stops the run (what follows starts a line)
            if line_open:
                print(file=sys.stderr)
        rec = self._record(buf, k_samp, sig_acc, s_sig, sig_every, done, wall, st)
        msg = cage_load_check(self.bearing, s, self.lubricant, float(rec.data["cage_load"].max(initial=0.0)), s.dt)
        if msg:
            warnings.warn(msg, StepSizeWarning, stacklevel=2)
        if s.cage == "rigid" and len(rec.data["glob"]):
            msg = land_step_check(self.bearing, s, self.lubricant, float(rec.data["glob"][:, G_LAND_ECC].max()), s.dt)
            if msg:
                warnings.warn(msg, StepSizeWarning, stacklevel=2)
        return rec

    def _record(self, buf, k_samp, sig_acc, s_sig, sig_every, done, wall, st) -> RunRecord:
        """The RunRecord of the first ``k_samp`` samples of the buffers ``buf`` after ``done`` steps."""
        data = {k: v[:k_samp] for k, v in buf.items()}
        if sig_every:
            n_sig = int(sig_acc[NSIGNAL])
            data["signal_t"] = s_sig[:n_sig, 0].copy()
            data["signal"] = s_sig[:n_sig, 1:].copy()
        return RunRecord(self.bearing, self.scenario, self.lubricant, data, steps=done, wall_s=wall,
                         engine=self.name, stable_dt=self.stable.dt, static=st["static"])
