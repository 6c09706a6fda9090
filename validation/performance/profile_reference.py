"""Where the time of a reference-engine step goes, stage by stage.

Scene: the bench_reference.py scene (6208, F_r = 3000 N, 500 rad/s, cage,
lubrication, Cundall-Strack tangential history, analytic start) at dt 8 us
with the implicit spring and at 5 us with the explicit one, advanced by
``--settle`` seconds so that the state is a steady-running one.

Method: on that frozen state, the compiled contact kernel
:func:`exudyn_bearing.model.contact.forces` is called ``--reps`` times in a
compiled loop with stages switched off through the parameter vector (the
same compiled code, no recompilation):

* full: the kernel as the engine calls it (no diagnostics);
* no lubrication (``P_LUB`` 0): without film, Lambda, regime, fluid damping,
  mu(Lambda) and the semi-axes; the difference is the lubrication stage;
* no friction (``P_FRIC`` none): without the Cundall-Strack spring; the
  difference is the tangential stage;
* neither, and all races open (groove radii of 1 m): the ring frame and
  groove geometry of every ball / raceway contact, the open-contact branch,
  the cage-pair and guide contacts and the zeroing of the outputs;
* and every cage pair and guide contact open at its first check (cage-ball
  radius -R_b, guide radius 1 m): what remains is the kernel's frame;
* with diagnostics (``want``): the cost of a sampled step's extra work.

The rest of a step (integration kick/drift, the ring, the energy
bookkeeping, the step loop) is the whole step (``run_verlet`` without
sampling, on the same state) minus the full kernel; the velocity-Verlet
kick/drift and the energy integrals (``accumulate_energy``) are timed
alone too; the ring drive power and the always-written ``glob`` entries are
part of the kernel's frame.
The Hertz cache (k, F, E re-evaluated when R_y/R_x moved by more than 1e-6)
and the anchors of the HD film's ln U, ln W and exp(E) (``hz`` columns
``HZ_LN_U``, ``HZ_LN_W``, ``HZ_EXP``: a miss calls the C library's log or
exp) are measured in the running engine: how often they miss per closed
contact and step (each Hertz miss is a table look-up of k, F, E). On the
frozen state of the stage timings every anchor hits: the lubrication stage
there is its cost without misses; the whole step carries them.

The kernel and the step are the specialisations the engine runs for this
scene (:func:`exudyn_bearing.model.contact.scene_paths`: without the defect
and ellipse-traction code). The timing kernels are compiled without numba's on-disk cache (a cached
copy would keep the inlined contact functions of an older contact.py).
All times are medians of ``--repeat`` timings of the thread's CPU time
(``time.thread_time``: on a shared machine the wall clock also counts the
time other processes hold the core), in ns per step (per call of the
kernel); read them as proportions.

With ``--compile`` it measures instead what a cold start compiles: the
README's main job (a 2 ms run of it; ``--scene rk4``: the test suite's
RK4 run, regularised friction, dt 1.5 us, 1 ms) in a fresh process with an
empty numba cache (``NUMBA_CACHE_DIR`` a new temporary folder outside the
repository), every numba compilation timed through numba's event API
(``numba:compile``): per function the number of specialisations and the
CPU seconds spent in it (exclusive of the functions it compiled in turn),
and the whole first ``simulate`` call (wall and CPU). ``--cold-runs N``
repeats that in N fresh processes and prints the medians. ``--after-readme``
fills the cache with the README's job first (as CI does before pytest) and
measures the scene's first run on that cache.

    python validation/performance/profile_reference.py [--reps 20000] [--repeat 15] [--settle 0.01]
    python validation/performance/profile_reference.py --compile [--scene readme|rk4] [--cold-runs 3] [--after-readme]
"""
from __future__ import annotations

import argparse
import time
import warnings

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing._jit import kernel
from exudyn_bearing.model.contact import accumulate_energy, forces, scene_paths
from exudyn_bearing.model.layout import (
    D_LOAD,
    FRIC_NONE,
    H_E1,
    HZ_EXP,
    HZ_LN_U,
    HZ_LN_W,
    HZ_RATIO,
    NDIAG,
    NGLOBAL,
    P_CAGE,
    P_FRIC,
    P_LUB,
    P_RB,
    P_RCI,
    P_RCO,
    P_RGUIDE,
    P_RZ,
)
from exudyn_bearing.model.motion import kick_drift, ring_poses
from exudyn_bearing.solvers.reference import ReferenceEngine
from exudyn_bearing.solvers.reference.integrators import evaluate, run_verlet

SCENE = {"Fr": 3000.0, "omega": 500.0, "cage": True, "lubrication": True, "friction": "history", "initial": "analytic"}
SETTINGS = {"implicit spring, dt 8 us": {"dt": 8e-6, "tangential": "implicit"},
            "explicit spring, dt 5 us": {"dt": 5e-6, "tangential": "explicit"}}


@kernel(cache=False)
def _time_forces(reps, p, table, xb, vb, wb, xc, vc, rings, hist, dt, hz, fb, tb, fc, fr, glob, diag, cage_load,
                 want, defect_path, ellipse_path):
    acc = 0.0
    for _ in range(reps):
        acc += forces(p, table, xb, vb, wb, xc, vc, rings, hist, hist, dt, hz, fb, tb, fc, fr, glob, diag,
                      cage_load, want, defect_path, ellipse_path)
    return acc


@kernel(no_runtime=True, cache=False)
def _time_kick_drift(reps, xb, vb, wb, xc, vc, fb, tb, fc):
    for _ in range(reps):
        kick_drift(0.0, 0.0, xb, vb, wb, xc, vc, fb, tb, fc, 1.0, 1.0, 1.0)
    return xb[0, 0]


@kernel(no_runtime=True, cache=False)
def _time_energy(reps, glob):
    for _ in range(reps):
        accumulate_energy(glob, 0.0)
    return glob[0]


def _median_ns(fn, n, repeat):
    walls = []
    for _ in range(repeat):
        t0 = time.thread_time()
        fn()
        walls.append(time.thread_time() - t0)
    return 1e9 * float(np.median(walls)) / n


class Scene:
    """The engine's arrays advanced to a steady state (the set-up of ReferenceEngine.run)."""

    def __init__(self, settle, **kw):
        sc = eb.Scenario(t_end=settle, sample_dt=settle, **dict(SCENE, **kw))
        self.eng = ReferenceEngine("6208", sc)
        st = self.eng.initial_state()
        self.p, self.table, self.dt = self.eng.params, self.eng.table, sc.dt
        self.xb, self.vb, self.wb, self.xc, self.vc, self.ring, self.hist, self.hz = (
            st[k] for k in ("xb", "vb", "wb", "xc", "vc", "ring", "hist", "hz"))
        z = self.xb.shape[0]
        self.fb, self.tb, self.fc = np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((z, 3))
        self.fring, self.glob = np.zeros(3), np.zeros(NGLOBAL)
        self.fr, self.rings = np.zeros((2, 6)), ring_poses()
        self.diag, self.cage_load = np.zeros((z, 2, NDIAG)), np.zeros((z, 2))
        self.paths = scene_paths(self.p)  # the specialisation the engine runs (no defect, no ellipse code)
        frames = self.hist[:, H_E1:].copy()
        evaluate(0.0, self.p, self.table, self.xb, self.vb, self.wb, self.xc, self.vc, self.ring, self.rings,
                 self.hist, self.hz, self.fb, self.tb, self.fc, self.fr, self.fring, self.glob, self.diag,
                 self.cage_load, False, *self.paths)
        self.hist[:, H_E1:] = frames
        self.t = 0.0
        self.step(round(settle / self.dt))

    def step(self, n, sample_every=1 << 40):
        e = np.zeros((0,))
        e2 = np.zeros((0, NGLOBAL))
        z = self.xb.shape[0]
        e3 = np.zeros((0, z, 3))
        run_verlet(n, self.t, self.p, self.table, self.xb, self.vb, self.wb, self.xc, self.vc, self.ring,
                   self.hist, self.hz, self.fb, self.tb, self.fc, self.fring, sample_every, 0, e, e2,
                   np.zeros((0, z, 2, NDIAG)), np.zeros((0, z, 2)), e3, e3, e3, e3, e3, np.zeros((0, 6)),
                   0, np.zeros(8), np.zeros((0, 8)), self.glob, self.diag, self.cage_load, self.rings, self.fr,
                   *self.paths, None)
        self.t += n * self.dt

    def forces(self, p, reps, want=False):
        # dt_hist 0: the repeated calls on the frozen state keep the springs of the running engine (with dt they
        # would grow call by call up to the Coulomb cap and time the sliding branch instead)
        return _time_forces(reps, p, self.table, self.xb.copy(), self.vb, self.wb, self.xc, self.vc, self.rings,
                            self.hist.copy(), 0.0, self.hz, self.fb, self.tb, self.fc, self.fr, self.glob,
                            self.diag, self.cage_load, want, *self.paths)

    def closed(self):
        self.forces(self.p, 1, True)
        return int(np.sum(self.diag[:, :, D_LOAD] > 0.0))


def hertz_misses(sc, n):
    """Misses of the Hertz cache and of the film's anchors (ln U, ln W, exp E) per closed contact and step over
    n single steps of the running engine: a cache column that changed in a step was re-evaluated."""
    cols = (HZ_RATIO, HZ_LN_U, HZ_LN_W, HZ_EXP)
    misses = np.zeros(len(cols))
    closed = 0
    for _ in range(n):
        before = sc.hz[:, :, cols].copy()
        sc.step(1)
        misses += np.sum(sc.hz[:, :, cols] != before, axis=(0, 1))
        closed += sc.closed()
    return misses / max(closed, 1)


def profile(name, kw, reps, repeat, settle):
    sc = Scene(settle, **kw)
    p = sc.p
    p_nolub = p.copy()
    p_nolub[P_LUB] = 0.0
    p_nofric = p.copy()
    p_nofric[P_FRIC] = FRIC_NONE
    p_bare = p_nolub.copy()
    p_bare[P_FRIC] = FRIC_NONE
    p_open = p_bare.copy()
    p_open[P_RCI] = p_open[P_RCO] = 1.0
    p_empty = p_open.copy()  # and every cage pair and guide contact open at its first check
    p_empty[P_RZ] = -p[P_RB]
    p_empty[P_RGUIDE] = 1.0
    assert p[P_CAGE] > 0.5
    for q in (p, p_nolub, p_nofric, p_bare, p_open, p_empty):  # compile / warm
        sc.forces(q, 10)
    xb, vb, xc, vc = sc.xb.copy(), sc.vb.copy(), sc.xc.copy(), sc.vc.copy()
    fb, fc = np.zeros_like(xb), np.zeros_like(xc)
    wb, tb = sc.wb.copy(), np.zeros_like(xb)
    g = np.zeros(NGLOBAL)
    n_step = max(reps // 10, 1)
    every = round(1e-4 / sc.dt)
    # every timing once per round, the rounds interleaved (the machine's load drifts)
    timed = {
        "full": (lambda: sc.forces(p, reps), reps),
        "want": (lambda: sc.forces(p, reps, True), reps),
        "nolub": (lambda: sc.forces(p_nolub, reps), reps),
        "nofric": (lambda: sc.forces(p_nofric, reps), reps),
        "bare": (lambda: sc.forces(p_bare, reps), reps),
        "open": (lambda: sc.forces(p_open, reps), reps),
        "empty": (lambda: sc.forces(p_empty, reps), reps),
        "kick": (lambda: _time_kick_drift(reps, xb, vb, wb, xc, vc, fb, tb, fc), reps),
        "energy": (lambda: _time_energy(reps, g), reps),
        "step": (lambda: sc.step(n_step), n_step),
        "step_sampled": (lambda: sc.step(n_step, every), n_step),
    }
    _time_kick_drift(10, xb, vb, wb, xc, vc, fb, tb, fc)
    _time_energy(10, g)
    sc.step(10)
    samples = {k: [] for k in timed}
    for _ in range(repeat):
        for k, (fn, n) in timed.items():
            samples[k].append(_median_ns(fn, n, 1))
    t = {k: float(np.median(v)) for k, v in samples.items()}
    n_closed = sc.closed()
    miss = hertz_misses(sc, 400)
    z = xb.shape[0]
    rows = [
        (f"kernel frame: zeroing, {2 * z} ball / raceway geometries, first checks of {3 * z} cage contacts, glob",
         t["empty"]),
        ("cage pairs and guide contacts beyond their first check", t["open"] - t["empty"]),
        (f"ball / raceway, {n_closed} closed: Hertz (cached) + normal law + kinematics + force assembly",
         t["bare"] - t["open"]),
        ("ball / raceway: lubrication (film, Lambda, regime, C_fluid, mu, semi-axes)", t["full"] - t["nolub"]),
        ("ball / raceway: tangential force (Cundall-Strack spring, cap)", t["full"] - t["nofric"]),
        ("energy integrals (accumulate_energy)", t["energy"]),
        ("kick/drift of balls and cage balls (one call)", t["kick"]),
        ("rest of the step (ring, second kick, loop, checks)",
         t["step"] - t["full"] - t["kick"] - t["energy"]),
    ]
    print(f"\n{name}: {n_closed} of {2 * z} ball / raceway contacts closed; "
          f"contact kernel {t['full']:.0f} ns, whole step {t['step']:.0f} ns "
          f"({t['step'] * 1e-9 / sc.dt:.3f} s CPU per simulated s), "
          f"sampled every {every} steps {t['step_sampled']:.0f} ns per step; "
          f"kernel with diagnostics {t['want']:.0f} ns; misses per closed contact and step: Hertz cache "
          f"{miss[0]:.3f}, film anchors ln U {miss[1]:.3f}, ln W {miss[2]:.3f}, exp E {miss[3]:.3f}")
    print(f"{'stage':88s} {'ns/step':>8s} {'share':>6s}")
    for label, ns in rows:
        print(f"{label:88s} {ns:8.0f} {100 * ns / t['step']:5.1f}%")
    print(f"(interaction of lubrication and friction: full - nolub - nofric + bare = "
          f"{t['full'] - t['nolub'] - t['nofric'] + t['bare']:.0f} ns)")
    return t


_COLD = """
import sys, time
from collections import defaultdict
from numba.core import event

stack, excl, count = [], defaultdict(float), defaultdict(int)


class Timer(event.Listener):
    def on_start(self, ev):
        stack.append([ev.data["dispatcher"].py_func, time.thread_time(), 0.0])

    def on_end(self, ev):
        fn, t0, inner = stack.pop()
        dt = time.thread_time() - t0
        name = fn.__module__.replace("exudyn_bearing.", "") + "." + fn.__qualname__
        excl[name] += dt - inner
        count[name] += 1
        if stack:
            stack[-1][2] += dt


event.register("numba:compile", Timer())

# LLVM's share: each library's final module is optimised after its callees' modules are linked in, then
# turned into machine code (numba.core.codegen.CPUCodeLibrary); timed per library
from numba.core import codegen

llvm = defaultdict(float)


def _timed(stage, orig):
    def run(self):
        t0 = time.thread_time()
        out = orig(self)
        llvm[(stage, self.name)] += time.thread_time() - t0
        return out
    return run


codegen.CPUCodeLibrary._optimize_final_module = _timed("optimise", codegen.CPUCodeLibrary._optimize_final_module)
codegen.CPUCodeLibrary._finalize_final_module = _timed("machine code", codegen.CPUCodeLibrary._finalize_final_module)
w0, c0 = time.perf_counter(), time.process_time()
import exudyn_bearing as eb
w1, c1 = time.perf_counter(), time.process_time()
eb.simulate("6208", eb.Scenario(**SCENE))
w2, c2 = time.perf_counter(), time.process_time()
print(f"import: {w1 - w0:.1f} s wall, {c1 - c0:.1f} s CPU; first simulate: {w2 - w1:.1f} s wall, {c2 - c1:.1f} s CPU")
print(f"TOTALS {w1 - w0} {c1 - c0} {w2 - w1} {c2 - c1}")
print(f"{'compiled function':60s} {'specs':>5s} {'CPU s':>6s}")
for name in sorted(excl, key=excl.get, reverse=True):
    print(f"{name:60s} {count[name]:5d} {excl[name]:6.2f}")
print(f"{'total':60s} {sum(count.values()):5d} {sum(excl.values()):6.2f}")
libs = sorted({name for _stage, name in llvm}, key=lambda n: -(llvm[("optimise", n)] + llvm[("machine code", n)]))
print("of it LLVM, per library (its final module: optimised with the linked callees, then machine code), CPU s:")
for name in libs[:6]:
    print(f"  {name[:58]:58s} optimise {llvm[('optimise', name)]:5.2f}  machine code {llvm[('machine code', name)]:5.2f}")
print(f"  {'all ' + str(len(libs)) + ' libraries':58s} optimise {sum(v for (st, _n), v in llvm.items() if st == 'optimise'):5.2f}"
      f"  machine code {sum(v for (st, _n), v in llvm.items() if st == 'machine code'):5.2f}")
"""


#: Scenarios of ``--compile``: the README's main job (2 ms of it) and the suite's RK4 run (1 ms of it).
COLD_SCENES = {"readme": {"Fr": 3000, "omega": 500, "t_end": 0.002, "dt": 5e-6},
               "rk4": {"Fr": 3000.0, "omega": 500.0, "t_end": 0.001, "dt": 1.5e-6, "friction": "regularized",
                       "integrator": "rk4"}}


def cold_start(scene="readme", runs=1, after_readme=False):
    """Run :data:`_COLD` for ``scene`` in ``runs`` fresh processes, each with an empty numba cache (filled
    by the README's job first with ``after_readme``), print the table of the first run and the medians."""
    import os
    import subprocess
    import sys
    import tempfile

    totals = []
    for k in range(runs):
        with tempfile.TemporaryDirectory(prefix="numba_cold_") as cache:
            env = dict(os.environ, NUMBA_CACHE_DIR=cache)
            if after_readme:
                subprocess.run([sys.executable, "-c", f"SCENE = {COLD_SCENES['readme']!r}\n" + _COLD], env=env,
                               capture_output=True, text=True, check=True)
            out = subprocess.run([sys.executable, "-c", f"SCENE = {COLD_SCENES[scene]!r}\n" + _COLD], env=env,
                                 capture_output=True, text=True, check=True)
        lines = out.stdout.splitlines()
        totals.append([float(x) for x in next(li for li in lines if li.startswith("TOTALS")).split()[1:]])
        if k == 0:
            print(f"cold start of {scene!r} {COLD_SCENES[scene]}, numba cache "
                  f"{'filled by the README job only' if after_readme else 'empty'}")
            print("\n".join(li for li in lines if not li.startswith("TOTALS")))
    if runs > 1:
        med = np.median(np.array(totals), axis=0)
        print(f"median of {runs} fresh processes: import {med[0]:.1f} s wall, {med[1]:.1f} s CPU; first simulate "
              f"{med[2]:.1f} s wall, {med[3]:.1f} s CPU (each: " +
              ", ".join(f"{t[2]:.1f}/{t[3]:.1f}" for t in totals) + " s wall/CPU)")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--compile", action="store_true", help="measure what a cold start compiles instead")
    ap.add_argument("--scene", choices=sorted(COLD_SCENES), default="readme", help="with --compile: the run")
    ap.add_argument("--cold-runs", type=int, default=1, help="with --compile: fresh processes (medians)")
    ap.add_argument("--after-readme", action="store_true",
                    help="with --compile: the cache filled by the README job first (as on CI)")
    ap.add_argument("--reps", type=int, default=20000)
    ap.add_argument("--repeat", type=int, default=15)
    ap.add_argument("--settle", type=float, default=0.01)
    args = ap.parse_args(argv)
    if args.compile:
        cold_start(args.scene, args.cold_runs, args.after_readme)
        return
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for name, kw in SETTINGS.items():
            profile(name, kw, args.reps, args.repeat, args.settle)


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced."""
    return run.printed(
        "Where the reference engine's step time goes",
        "The bench_reference scene (6208, 3000 N, 500 rad/s, cage, lubrication, tangential history) in steady "
        "running: the compiled contact kernel timed with stages switched off through the parameter vector on "
        "a frozen state (CPU time per step, interleaved rounds, medians). The cold start is measured by "
        "`python validation/performance/profile_reference.py --compile` (a fresh process, empty numba cache).",
        last_lines=40)


if __name__ == "__main__":
    main()
