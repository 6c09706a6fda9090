"""Two 6208 at the quasi-static level against one 6208 in the reference engine, in one process.

Level: the 2.5 kg shaft on two 6208 (z = -+0.1 m) carrying 6000 N radially between them at 500 rad/s of
validation/consistency/levels_damping.py, started at the bearings' static pose, ``model="quasistatic"``,
GeneralizedAlpha at 1e-4 s with the bearings' ``SimulationSettings`` (Newton's relative tolerance 1e-4), once
per ``--formulations`` entry (the level's ``formulation`` option: "connector", Exudyn's
ObjectConnectorRigidBodySpringDamper per bearing with its numerical Jacobian computed once per run; "node", one
ObjectGenericODE2 on the shaft's node for both bearings with the level's own Jacobian every step).
Reference: one 6208 in the reference engine at its fast setting, the implicit tangential spring at dt = 8 us
(bench_reference.py's scene: 3000 N, 500 rad/s, cage, lubrication, tangential history).

Printed per formulation: wall seconds per simulated second (median of ``--repeat`` runs after a warm-up run,
solver time only), the ratio to the reference engine's bearing, the calls into Python per step (both bearings),
the evaluations per step and bearing, Newton iterations and Jacobians per step, the microseconds per step and
per call (wall per step over calls per step: Exudyn's own step included), the shaft's final x and its
difference from the first formulation's (the results agree within Newton's tolerance). The runs alternate
between the formulations and the reference, so that a change of the machine's load falls on all alike. Then one
more run per formulation splits its step into the level's calls and the rest, Exudyn's.

    python validation/performance/bench_qs_rotor.py [--repeat 5] [--t-end 0.2] [--formulations connector node]

Writes bench_qs_rotor.json into --out (default validation/out/levels).
"""
from __future__ import annotations

import argparse
import json
import sys
import time
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "consistency"))  # levels_damping.py
sys.path.insert(0, str(HERE))  # bench_reference.py
from bench_reference import run as reference_run  # noqa: E402
from levels_damping import LEVEL, ROOT, rotor  # noqa: E402

STEP = 1e-4
REFERENCE = {"dt": 8e-6, "tangential": "implicit"}


def level_run(formulation, t_end):
    """One run of the two-bearing shaft at the quasi-static level: dict of the measured quantities."""
    options = dict(LEVEL) if formulation is None else dict(LEVEL, formulation=formulation)
    mbs, bearing, sensor = rotor("quasistatic", **options)
    ss = bearing.SimulationSettings(t_end, stepSize=STEP)
    ss.solution.sensors.writePeriod = 1e-3
    calls = eb.solvers.quasistatic.levels.base.python_calls  # counter of calls into the levels' Python
    n0 = calls[0]
    with eb.filter_exudyn_notes(), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        t0 = time.perf_counter()
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
        wall = time.perf_counter() - t0
    steps = round(t_end / STEP)
    it = mbs.sys["dynamicSolver"].it
    pos = mbs.GetSensorStoredData(sensor)
    return {"wall_per_sim_s": wall / t_end, "calls_per_step": (calls[0] - n0) / steps,
            "evaluations_per_step": bearing.samples()["evaluations"] / steps,
            "newton_per_step": it.newtonStepsCount / steps, "jacobians": int(it.newtonJacobiCount),
            "us_per_step": wall / steps * 1e6, "x_end": float(pos[-1, 1]), "y_end": float(pos[-1, 2])}


def split_run(formulation, t_end):
    """One more run, its level's calls timed from inside (not one of the timed runs: the timers add their own
    cost): microseconds per step inside the level's Python calls (the node formulation's force and Jacobian calls,
    the connector's user function) and the rest of the step (Exudyn: its step, the calls' boundary, the Jacobian),
    wall time (the timers' own cost, two clock reads per call, falls into the level's share)."""
    from exudyn_bearing.solvers.quasistatic.levels import base, nodes

    inside = [0.0]

    def timed(fn):
        def wrapper(*args):
            t0 = time.perf_counter()
            out = fn(*args)
            inside[0] += time.perf_counter() - t0
            return out
        return wrapper

    saved = (nodes.NodeGroup._force, nodes.NodeGroup._jacobian, base.LevelBearing._user_function)
    nodes.NodeGroup._force, nodes.NodeGroup._jacobian, base.LevelBearing._user_function = map(timed, saved)
    try:
        mbs, bearing, sensor = rotor("quasistatic", **dict(LEVEL, formulation=formulation))
        ss = bearing.SimulationSettings(t_end, stepSize=STEP)
        ss.solution.sensors.writePeriod = 1e-3
        with eb.filter_exudyn_notes(), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            t0 = time.perf_counter()
            mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
            cpu = time.perf_counter() - t0
    finally:
        nodes.NodeGroup._force, nodes.NodeGroup._jacobian, base.LevelBearing._user_function = saved
    steps = round(t_end / STEP)
    return {"us_per_step": cpu / steps * 1e6, "level_us_per_step": inside[0] / steps * 1e6,
            "exudyn_us_per_step": (cpu - inside[0]) / steps * 1e6}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--t-end", type=float, default=0.2, help="simulated time per run [s] (level and reference)")
    ap.add_argument("--formulations", nargs="+", default=["connector", "node"])
    ap.add_argument("--out", default=str(ROOT / "validation" / "out" / "levels"))
    args = ap.parse_args(argv)
    forms = [None if f == "default" else f for f in args.formulations]
    reference_run(1e-3, 1e-4, **REFERENCE)  # compile / load the cache
    for f in forms:
        level_run(f, 0.01)  # warm-up: compiles the kernels
    runs = {str(f): [] for f in forms}
    ref = []
    for _ in range(args.repeat):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            res = reference_run(args.t_end, 1e-3, **REFERENCE)
        ref.append(res.wall_s / args.t_end)
        for f in forms:
            runs[str(f)].append(level_run(f, args.t_end))
    ref_med = float(np.median(ref))
    print(f"one 6208 in the reference engine (implicit spring, dt 8 us; 3000 N, 500 rad/s), T = {args.t_end:g} s: "
          f"{ref_med:.3f} s wall per simulated s (median of {args.repeat}: "
          + ", ".join(f"{w:.3f}" for w in ref) + ")")
    print(f"two 6208 at the quasi-static level (2.5 kg shaft, 6000 N, 500 rad/s, GeneralizedAlpha {STEP:g} s), "
          f"T = {args.t_end:g} s, median of {args.repeat}:")
    print(f"  {'formulation':12s} {'wall/sim s':>10s} {'/ DEM':>6s} {'calls/step':>10s} {'evals/step':>10s} "
          f"{'newton/step':>11s} {'jacobians':>9s} {'us/step':>8s} {'us/call':>8s} {'x end um':>10s} {'dx nm':>7s}")
    report = {"reference_wall_per_sim_s": ref_med, "reference_walls": ref, "t_end": args.t_end,
              "repeat": args.repeat, "levels": {}}
    first = None
    for key, rows in runs.items():
        med = {k: float(np.median([r[k] for r in rows])) for k in rows[0]}
        last = rows[-1]
        first = last if first is None else first
        per_call = med["us_per_step"] / med["calls_per_step"]
        print(f"  {key:12s} {med['wall_per_sim_s']:10.3f} {med['wall_per_sim_s'] / ref_med:6.2f} "
              f"{med['calls_per_step']:10.2f} {med['evaluations_per_step']:10.2f} {med['newton_per_step']:11.2f} "
              f"{last['jacobians']:9d} {med['us_per_step']:8.1f} {per_call:8.2f} {last['x_end'] * 1e6:10.5f} "
              f"{(last['x_end'] - first['x_end']) * 1e9:7.3f}")
        report["levels"][key] = {"median": med, "runs": rows, "ratio_to_reference": med["wall_per_sim_s"] / ref_med,
                                 "us_per_call": per_call}
    print("  where a step goes (one more run each, the level's calls timed from inside):")
    for f in forms:
        sp = split_run(f, args.t_end)
        report["levels"][str(f)]["split"] = sp
        print(f"    {str(f):12s} {sp['us_per_step']:6.1f} us per step: {sp['level_us_per_step']:5.1f} us in the "
              f"level's calls (compiled kernels and their Python), {sp['exudyn_us_per_step']:5.1f} us in Exudyn "
              "(its step, the calls' boundary, the Jacobian)")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "bench_qs_rotor.json").write_text(json.dumps(report, indent=1))
    print("written:", out / "bench_qs_rotor.json")


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced."""
    return run.printed(
        "Two bearings at the quasi-static level against the reference engine's bearing",
        "A 2.5 kg shaft on two 6208 under 6000 N at 500 rad/s (validation/consistency/levels_damping.py) at the "
        "quasi-static level, GeneralizedAlpha at 1e-4 s, in its connector and node formulations, against one "
        "6208 in the reference engine at its fast setting (implicit tangential spring, 8 us), in one process: "
        "wall time per simulated second (medians of seven runs), its ratio to the reference engine's, the "
        "calls into Python and the evaluations per step, the microseconds per step and per call, and where a "
        "step goes.",
        last_lines=12)


if __name__ == "__main__":
    main()
