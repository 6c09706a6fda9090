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
from ...model.layout import G_LAND_ECC, H_E1, NDIAG, NGLOBAL, NSIGNAL
from ...model.motion import ring_poses
from ...model.parameters import scene_parameters
from ...model.record import RunRecord
from ...model.scenario import Scenario
from ...model.stability import StepSizeWarning, cage_load_check, land_step_check, runaway_error, stable_step, step_warning
from ...physics import hertz
from .integrators import evaluate, run_rk4, run_verlet

__all__ = ["ReferenceEngine"]


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
        announce_compilation(forces, run_verlet if scenario.integrator == "verlet" else run_rk4)
        b = load_bearing(bearing)
        if scenario.Pd is not None:
            b = b.with_clearance(scenario.Pd)
        self.bearing = b
        self.start = start
        self.scenario = scenario
        self.lubricant = default_lubricant(b) if lubricant is None else lubricant  # None: the bearing's
        if scenario.cage == "torus" and not b.has_cage:
            raise InputError(f"cage: bearing {b.name} has no torus cage (cage_ball_radius is None); "
                             "use cage='rigid' (a rigid cage body) or cage='none'")
        self.params = scene_parameters(b, scenario, self.lubricant)
        self.table = hertz.exact_table()
        self.stable = stable_step(b, scenario, self.lubricant)

    def initial_state(self):
        """The scene's initial state (:func:`exudyn_bearing.model.initial_state.initial_state`)."""
        return initial_state(self.bearing, self.scenario, self.start)

    # -- run -----------------------------------------------------------
    def run(self, progress=None, chunk_steps=None):
        """Integrate the scenario; returns the :class:`~exudyn_bearing.model.record.RunRecord`.

        ``progress``: True to print progress on stderr, None for automatic
        (runs over 2 million steps).
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
        buf = {
            "t": np.zeros(n_samples), "glob": np.zeros((n_samples, NGLOBAL)),
            "diag": np.zeros((n_samples, z, 2, NDIAG)), "cage_load": np.zeros((n_samples, z, 2)),
            "xb": np.zeros((n_samples, z, 3)), "vb": np.zeros((n_samples, z, 3)),
            "wb": np.zeros((n_samples, z, 3)), "xc": np.zeros((n_samples, z, 3)),
            "vc": np.zeros((n_samples, z, 3)), "ring": np.zeros((n_samples, 6)),
        }
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
        # cold start, python validation/profile_reference.py --compile)
        frames = hist[:, H_E1:].copy()
        first = getattr(evaluate, "py_func", evaluate)  # evaluate itself where numba's JIT is disabled
        diag, cage_load, rings, fr = work
        first(0.0, p, self.table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring,
              np.zeros(NGLOBAL), diag, cage_load, False, defect_path, ellipse_path, loss_path)
        hist[:, H_E1:] = frames
        wall0 = time.perf_counter()
        last_print = wall0
        line_open = False  # a progress line printed, not yet ended
        try:
            while done < n_steps:
                m = min(chunk, n_steps - done)
                sl = slice(k_samp, n_samples)
                steps, ns, status = integrate(
                    m, done * s.dt, p, self.table, xb, vb, wb, xc, vc, ring, hist, hz, fb, tb, fc, fring,
                    every, done, buf["t"][sl], buf["glob"][sl], buf["diag"][sl], buf["cage_load"][sl],
                    buf["xb"][sl], buf["vb"][sl], buf["wb"][sl], buf["xc"][sl], buf["vc"][sl], buf["ring"][sl],
                    sig_every, sig_acc, s_sig, glob, *work, defect_path, ellipse_path, signal_path, loss_path)
                done += steps
                k_samp += ns
                if status != 0:
                    t_fail = done * s.dt
                    what = ("non-finite" if status == 1 else
                            "runaway (overlap above 5 % of the radius of a ball or cage ball)")
                    raise runaway_error("dt", t_fail, self.stable, what, step=f" with dt = {s.dt:.3g} s", remedy="dt")
                if progress and (time.perf_counter() - last_print > 0.5 or done >= n_steps):
                    last_print = time.perf_counter()
                    el = time.perf_counter() - wall0
                    frac = done / n_steps
                    eta = el / frac * (1 - frac) if frac > 0 else float("nan")
                    print(f"\r[reference] t = {done * s.dt:.4f}/{s.t_end:.4f} s  {100 * frac:5.1f} %  "
                          f"wall {el:6.1f} s  eta {eta:6.1f} s", end="", file=sys.stderr, flush=True)
                    line_open = True
            wall = time.perf_counter() - wall0
        finally:  # end the progress line, also when an error or Ctrl-C stops the run (what follows starts a line)
            if line_open:
                print(file=sys.stderr)
        for k in buf:
            buf[k] = buf[k][:k_samp]
        if sig_every:
            n_sig = int(sig_acc[NSIGNAL])
            buf["signal_t"] = s_sig[:n_sig, 0].copy()
            buf["signal"] = s_sig[:n_sig, 1:].copy()
        msg = cage_load_check(self.bearing, s, self.lubricant, float(buf["cage_load"].max(initial=0.0)), s.dt)
        if msg:
            warnings.warn(msg, StepSizeWarning, stacklevel=2)
        if s.cage == "rigid" and len(buf["glob"]):
            msg = land_step_check(self.bearing, s, self.lubricant, float(buf["glob"][:, G_LAND_ECC].max()), s.dt)
            if msg:
                warnings.warn(msg, StepSizeWarning, stacklevel=2)
        return RunRecord(self.bearing, s, self.lubricant, buf, steps=done, wall_s=wall,
                         engine=self.name, stable_dt=self.stable.dt, static=st["static"])
