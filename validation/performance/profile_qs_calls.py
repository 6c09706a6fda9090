"""The quasi-static level's calls from Exudyn on the two-6208 rotor of bench_qs_rotor.py, replayed: what one call
costs without Exudyn's step around it.

One run of the 2.5 kg shaft on two 6208 under 6000 N at 500 rad/s (validation/consistency/levels_damping.py) at
the quasi-static level, node formulation, GeneralizedAlpha at 1e-4 s, records the arguments of every force and
Jacobian call Exudyn makes (as Exudyn hands them: q and q_t as lists); the calls are then made again in the
same order (the bearings start over at the run's first time, as a new run does), and each kind alone. Printed:
the thread CPU time (not disturbed by another process taking the core; the smallest and the median of
``--repeat``) per force call (both bearings, the samples included), per Jacobian call, per bearing for the node
kernel called alone (the single-bearing path, ``_node_kernel``), for a Python function that only returns an
array (the floor of a call from Python), and for all of a step's calls; then the generalized force and the Jacobian of the last recorded call (to compare two
versions of the code: the same forces to the last digit printed).

    python validation/performance/profile_qs_calls.py [--t-end 0.05] [--repeat 15]
"""
from __future__ import annotations

import argparse
import sys
import time
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.solvers.quasistatic.levels import base

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "consistency"))  # levels_damping.py
from levels_damping import LEVEL, rotor  # noqa: E402

STEP = 1e-4


def record(t_end):
    """One run; (mbs, group, the calls in order: ("f", t, q, q_t) or ("j", t, q, q_t, f, f_t))."""
    mbs, bearing, _sensor = rotor("quasistatic", **dict(LEVEL, formulation="node"))
    group = bearing._group
    calls = []
    force, jacobian = group._force, group._jacobian

    # the arguments as Exudyn hands them (lists: their conversion is part of a call's cost)
    def rec_force(mbs_, t, item, q, q_t):
        calls.append(("f", t, list(q), list(q_t)))
        return force(mbs_, t, item, q, q_t)

    def rec_jacobian(mbs_, t, item, q, q_t, f, f_t):
        calls.append(("j", t, list(q), list(q_t), f, f_t))
        return jacobian(mbs_, t, item, q, q_t, f, f_t)

    mbs.SetObjectParameter(group.object, "forceUserFunction", rec_force)
    mbs.SetObjectParameter(group.object, "jacobianUserFunction", rec_jacobian)
    ss = bearing.SimulationSettings(t_end, stepSize=STEP)
    with eb.filter_exudyn_notes(), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    return mbs, group, calls


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--t-end", type=float, default=0.05, help="simulated time of the recorded run [s]")
    ap.add_argument("--repeat", type=int, default=15)
    args = ap.parse_args(argv)
    mbs, group, calls = record(args.t_end)
    forces = [c for c in calls if c[0] == "f"]
    jacobians = [c for c in calls if c[0] == "j"]
    bearings = group.bearings
    steps = round(args.t_end / STEP)

    def replay():
        for c in calls:
            if c[0] == "f":
                group._force(mbs, c[1], group.object, c[2], c[3])
            else:
                group._jacobian(mbs, c[1], group.object, *c[2:])

    def replay_forces():
        for c in forces:
            group._force(mbs, c[1], group.object, c[2], c[3])

    def replay_jacobians():
        for c in jacobians:
            group._jacobian(mbs, c[1], group.object, *c[2:])

    arrays = [(np.array(c[2], float), np.array(c[3], float)) for c in forces]

    def node_kernels():
        gen = np.zeros_like(group._gen)
        for q, q_t in arrays:
            for b in bearings:
                b._node_kernel(q, q_t, *b._node_args, gen)

    def floor():
        gen = np.zeros_like(group._gen)

        def fn(mbs_, t, item, q, q_t):
            base.python_calls[0] += 1
            return gen

        for c in forces:
            fn(mbs, c[1], group.object, c[2], c[3])

    def timed(fn):
        fn()  # the first replay starts the bearings over (and compiles what is not compiled yet)
        times = []
        for _ in range(args.repeat):
            t0 = time.thread_time()
            fn()
            times.append(time.thread_time() - t0)
        return min(times), float(np.median(times))

    rows = (("force call (both bearings, samples included)", replay_forces, len(forces)),
            ("Jacobian call", replay_jacobians, len(jacobians)),
            ("node kernel alone, per bearing evaluation", node_kernels, len(forces) * len(bearings)),
            ("a Python function returning an array (floor)", floor, len(forces)),
            ("all of a step's calls, per step", replay, steps))
    print(f"two 6208 at the quasi-static level (node formulation), {len(forces)} force and {len(jacobians)} "
          f"Jacobian calls over {steps} steps, replayed; thread CPU time [us], smallest and median of "
          f"{args.repeat}:")
    for label, fn, n in rows:
        lo, med = timed(fn)
        print(f"  {label:48s} {lo / n * 1e6:7.2f} {med / n * 1e6:7.2f}")
    replay()
    last_f, last_j = forces[-1], jacobians[-1]
    jac = group._jacobian(mbs, last_j[1], group.object, *last_j[2:]).copy()
    gen = group._force(mbs, last_f[1], group.object, last_f[2], last_f[3]).copy()
    print("  generalized force of the last force call:", " ".join(f"{x:.17g}" for x in gen))
    print(f"  Jacobian of the last Jacobian call: largest entry {np.abs(jac).max():.17g}, sum {jac.sum():.17g}")


if __name__ == "__main__":
    main()
