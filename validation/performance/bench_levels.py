"""Wall time per simulated second of the three bearing levels (``eb.CreateBallBearing(model=...)``).

1. One-bearing test shaft: a 2.5 kg shaft on one 6208 under F_r = 3000 N, spinning at 500 rad/s, started at
   the quasi-static pose: the ball element (body and fast mode, VelocityVerlet at 3.5 us with the implicit
   tangential spring, the README's example), the
   quasi-static level (Hertz "exact" and "hamrock_brewe", the default node formulation; exact Hertz also with
   ``formulation="connector"``) and the linear level (speed table through the
   user function, and one speed as Exudyn's own connector), GeneralizedAlpha at 1e-4 s. Medians of
   ``--repeat`` runs (after one warm-up run that compiles).
2. The rotor of scenarios/rotor_two_6208.py run up from 0 to 1000 rad/s in about 1 s (motor torque 0.5 N m)
   at the two levels without ball DOFs (the quasi-static level also with ``formulation="connector"``): wall
   time of the 1 s run.
3. Where an evaluation of the quasi-static level goes (``--skip-cost`` leaves it out): Exudyn's
   Python boundary (a connector whose user function returns zeros, against the same connector without a
   user function), the level's Python wrapper and its compiled kernel (smallest of 15 repeats each), the
   connector formulation's user function, and the node formulation's force call (the object's
   forceUserFunction for the one bearing) and Jacobian call.
4. Newton's relative tolerance (``--skip-newton`` leaves it out): on the test shaft and on the
   varying-compliance case of validation/consistency/levels_checks.py (500 N, 20 um clearance), the largest difference
   of the shaft's x and y from a run at relative tolerance 1e-10, against the difference that halving the
   step makes, and the evaluations per step; with the node formulation (the default) and the connector.

    python validation/performance/bench_levels.py [--repeat 3] [--skip-shaft] [--skip-runup] [--skip-cost] [--skip-newton]

Prints the table and writes bench_levels.json into --out (default validation/out/levels).
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time
import warnings
from pathlib import Path


import exudyn_bearing as eb
from exudyn_bearing.simulate import quasistatic_start

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "consistency"))  # levels_checks.py, peer_builtin.py
from levels_checks import ROOT, load_rotor_scenario, shaft, solve_timed  # noqa: E402

FR, OMEGA = 3000.0, 500.0

#: (label, model, options, solver, step [s], simulated time [s])
CASES = (("balls, body mode", "balls", {"tangential": "implicit"}, "VelocityVerlet", 3.5e-6, 0.01),
         ("balls, fast mode", "balls", {"mode": "fast", "tangential": "implicit"}, "VelocityVerlet", 3.5e-6, 0.01),
         ("quasistatic, exact Hertz", "quasistatic", {}, "GeneralizedAlpha", 1e-4, 0.05),
         ("quasistatic, hamrock_brewe", "quasistatic", {"hertzModel": "hamrock_brewe"}, "GeneralizedAlpha", 1e-4,
          0.05),
         ("quasistatic, exact Hertz, connector", "quasistatic", {"formulation": "connector"}, "GeneralizedAlpha",
          1e-4, 0.05),
         ("linear, speed table", "linear", {}, "GeneralizedAlpha", 1e-4, 0.05),
         ("linear, one speed (Exudyn connector)", "linear", {"coefficientSpeeds": [OMEGA]}, "GeneralizedAlpha",
          1e-4, 0.05))


def one_bearing(model, options, solver, h, t_end):
    """A function that builds and runs the test shaft once; returns it and the built system's keepalive."""
    if model == "balls":
        start = [*quasistatic_start("6208", eb.Scenario(Fr=FR, omega=OMEGA))["ring"][:3], 0.0, 0.0]
    else:
        start = None

    def run():
        sc, mbs, node, m_b, m_g, pos = shaft((FR, 0.0, 0.0), omega=OMEGA, damper=False, start=start)
        if model == "balls":
            br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, initialLoad=(FR, 0.0), initialOmega=OMEGA,
                                      initial="quasistatic", stepSize=h, sampleInterval=1e-3, **options)
            ss = br.SimulationSettings(t_end)
        else:
            br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model=model, initialLoad=(FR, 0.0), initialOmega=OMEGA,
                                      sampleInterval=1e-3, **options)
            mbs.SetNodeParameter(node, "initialCoordinates", [*br.initialRingDisplacement, 0.0])
            ss = br.SimulationSettings(t_end, stepSize=h, solverType=solver)
        run.solve = solve_timed(mbs, ss)
        run.evaluations = (br.samples()["evaluations"] / round(t_end / h)
                           if model != "balls" and options.get("coefficientSpeeds") is None else None)
    return run


def runup(model, t_end=1.0, options=None):
    mod = load_rotor_scenario()
    original = eb.CreateBallBearing
    weight = 7850.0 * math.pi * 0.02 ** 2 * 0.25 * 9.81 / 2.0

    def level(mbs, bearing, m_in, m_out, **kw):
        return original(mbs, bearing, m_in, m_out, model=model, initialLoad=(weight, 0.0), loadAngle=-0.5 * math.pi,
                        sampleInterval=1e-3, **(options or {}))

    eb.CreateBallBearing = level
    try:
        sc, mbs, bearings, sensor, speed = mod.build(torque_max=0.5)
    finally:
        eb.CreateBallBearing = original
    ss = bearings["A"].SimulationSettings(t_end, stepSize=1e-4)
    ss.solution.sensors.writePeriod = 1e-3
    t0 = time.perf_counter()
    mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    wall = time.perf_counter() - t0
    w = mbs.GetSensorStoredData(speed)
    return wall, float(w[-1, 3]), bearings["A"].samples()["evaluations"] / round(t_end / 1e-4)


def boundary_cost(repeat=5, steps=2000):
    """[us] per step of the test shaft on Exudyn's connector without and with a user function returning zeros
    (one Newton iteration per step: two calls), smallest of ``repeat`` runs; returns (without, with)."""
    import exudyn as exu
    import numpy as np
    from exudyn.itemInterface import ObjectConnectorRigidBodySpringDamper

    zeros = np.zeros(6)
    best = {}
    for _ in range(repeat):
        for kind in ("plain", "user function"):
            sc, mbs, node, m_b, m_g, pos = shaft((FR, 0.0, 0.0), omega=OMEGA, damper=False)
            kw = {"springForceTorqueUserFunction": lambda *a: zeros} if kind != "plain" else {}
            mbs.AddObject(ObjectConnectorRigidBodySpringDamper(markerNumbers=[m_g, m_b], stiffness=np.eye(6) * 1e8,
                                                               damping=np.eye(6) * 1e2, **kw))
            mbs.Assemble()
            ss = exu.SimulationSettings()
            ss.timeIntegration.numberOfSteps = steps
            ss.timeIntegration.endTime = steps * 1e-4
            ss.timeIntegration.verboseMode = 0
            ss.solution.file.write = False
            t0 = time.perf_counter()
            mbs.SolveDynamic(ss)
            per = (time.perf_counter() - t0) / steps * 1e6
            best[kind] = min(best.get(kind, math.inf), per)
            calls = mbs.sys["dynamicSolver"].it.newtonStepsCount / steps + 1.0
    return best["plain"], best["user function"], calls


def level_call_cost(number=500, repeat=15):
    """[us] per call of the quasi-static level at its operating pose (warm balls): the connector formulation's
    user function, the level's _evaluate and the compiled kernel alone, the node formulation's force and
    Jacobian calls; smallest of ``repeat``."""
    import timeit

    import numpy as np

    sc, mbs, node, m_b, m_g, pos = shaft((FR, 0.0, 0.0), omega=OMEGA, damper=False)
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="quasistatic", initialLoad=(FR, 0.0), initialOmega=OMEGA,
                              formulation="connector")
    sc2, mbs2, node2, m_b2, m_g2, pos2 = shaft((FR, 0.0, 0.0), omega=OMEGA, damper=False)
    nb = eb.CreateBallBearing(mbs2, "6208", m_b2, m_g2, model="quasistatic", initialLoad=(FR, 0.0),
                              initialOmega=OMEGA, formulation="node")
    mbs.Assemble()
    mbs2.Assemble()
    q = [*(float(x) for x in nb.initialRingDisplacement), 0.3]
    qt = [0.0] * 5 + [OMEGA]
    group = nb._group
    u = [float(x) for x in br.initialRingDisplacement]
    d, r, v, w = u[:3], [u[3], u[4], 0.3], [0.0] * 3, [0.0, 0.0, OMEGA]
    m6, m3 = [[0.0] * 6 for _ in range(6)], [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    args = (*d, *r, *v, *w, br._method, br._ws)
    cold = np.zeros_like(br._start)
    direct = np.empty((3, 0))  # an empty Hertz table: the kernel solves the exact constants directly

    def kernel_cold_direct():  # what the kernel did before: direct exact Hertz constants, cold starts
        cold[:] = 0.0
        br._kernel(*args, direct, cold, br._balls, br._mats)

    calls = {"user function": lambda: br._user_function(mbs, 1e-3, 0, d, r, v, w, m6, m6, m3, m3, [0.0] * 6),
             "_evaluate": lambda: br._evaluate(d, r, v, w),
             "kernel": lambda: br._kernel(*args, br._hz_table, br._start, br._balls, br._mats),
             "kernel, direct Hertz, cold starts": kernel_cold_direct,
             "node force call": lambda: group._force(mbs2, 1e-3, 0, q, qt),
             "node Jacobian call": lambda: group._jacobian(mbs2, 1e-3, 0, q, qt, 1e9, 1e5)}
    for f in calls.values():
        f()
    return {k: min(timeit.repeat(f, number=number, repeat=repeat)) / number * 1e6 for k, f in calls.items()}


def newton_study(case, t_end, tolerances, formulation="auto"):
    """Largest |x|, |y| differences [m] from a run at relative tolerance 1e-10 (and of a run at half the step),
    evaluations per step, per relative tolerance."""
    import numpy as np

    def run(rel, h):
        bearing, load = ("6208", FR) if case == "shaft" else (eb.catalog["6208"].with_clearance(20e-6), 500.0)
        sc, mbs, node, m_b, m_g, pos = shaft((load, 0.0, 0.0), omega=OMEGA, damper=False)
        br = eb.CreateBallBearing(mbs, bearing, m_b, m_g, model="quasistatic", initialLoad=(load, 0.0),
                                  initialOmega=OMEGA, sampleInterval=1e-3, formulation=formulation)
        mbs.SetNodeParameter(node, "initialCoordinates", [*br.initialRingDisplacement, 0.0])
        ss = br.SimulationSettings(t_end, stepSize=h)
        ss.timeIntegration.newton.relativeTolerance = rel
        ss.solution.sensors.writePeriod = 1e-4
        mbs.Assemble()
        with eb.filter_exudyn_notes(), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
        jacobians = mbs.sys["dynamicSolver"].it.newtonJacobiCount
        return mbs.GetSensorStoredData(pos), br.samples()["evaluations"] / round(t_end / h), jacobians

    ref, _, _ = run(1e-10, 1e-4)

    def diff(p):
        return [float(np.abs(np.interp(ref[:, 0], p[:, 0], p[:, i]) - ref[:, i]).max()) for i in (1, 2)]

    half, _, _ = run(1e-10, 5e-5)
    out = {"step_halving": diff(half), "ptp": [float(np.ptp(ref[:, i])) for i in (1, 2)]}
    for rel in tolerances:
        p, per, jacobians = run(rel, 1e-4)
        out[rel] = (*diff(p), per, jacobians)
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--skip-shaft", action="store_true")
    ap.add_argument("--skip-runup", action="store_true")
    ap.add_argument("--skip-cost", action="store_true")
    ap.add_argument("--skip-newton", action="store_true")
    ap.add_argument("--out", default=str(ROOT / "validation" / "out" / "levels"))
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    res = {}
    print(f"one 6208 on a 2.5 kg shaft, F_r = {FR:g} N, {OMEGA:g} rad/s; median of {args.repeat} runs, solver time")
    print(f"  {'level':40s} {'solver':17s} {'step':>7s} {'sim':>7s} {'wall/sim s':>11s} {'evals/step':>10s}")
    for label, model, options, solver, h, t_end in () if args.skip_shaft else CASES:
        run = one_bearing(model, options, solver, h, t_end)
        run()  # warm-up: compiles the kernels
        walls = []
        for _ in range(args.repeat):
            run()
            walls.append(run.solve)
        med = sorted(walls)[len(walls) // 2]
        res[label] = {"wall_per_sim_s": med / t_end, "walls": walls, "step": h, "t_end": t_end, "solver": solver,
                      "evaluations_per_step": run.evaluations}
        per = f"{run.evaluations:10.2f}" if run.evaluations is not None else f"{'-':>10s}"
        print(f"  {label:40s} {solver:17s} {h:7.1e} {t_end:7.3f} {med / t_end:11.3f} {per}")
    body, fast = (res[k]["wall_per_sim_s"] if k in res else math.nan for k in ("balls, body mode", "balls, fast mode"))
    print("  times cheaper per simulated second than the ball element (same run):")
    for label in list(res):
        res[label]["cheaper_than_balls_body"] = body / res[label]["wall_per_sim_s"]
        res[label]["cheaper_than_balls_fast"] = fast / res[label]["wall_per_sim_s"]
        if not label.startswith("balls"):
            print(f"    {label:40s} {res[label]['cheaper_than_balls_body']:7.1f} x body mode, "
                  f"{res[label]['cheaper_than_balls_fast']:6.1f} x fast mode")
    if not args.skip_runup:
        print("rotor of scenarios/rotor_two_6208.py, run-up 0 -> 1000 rad/s with 0.5 N m (about 1 s), 1 s simulated, "
              "GeneralizedAlpha 1e-4 s:")
        for label, model, options in (("quasistatic, hamrock_brewe", "quasistatic", {"hertzModel": "hamrock_brewe"}),
                                      ("quasistatic, exact Hertz", "quasistatic", {}),
                                      ("quasistatic, exact Hertz, connector", "quasistatic",
                                       {"formulation": "connector"}),
                                      ("linear, speed table", "linear", {})):
            wall, w_end, per = runup(model, options=options)
            res[f"runup {label}"] = {"wall_s": wall, "final_speed": w_end, "evaluations_per_step": per}
            print(f"  {label:40s} {wall:7.1f} s wall, final speed {w_end:.0f} rad/s, {per:.2f} evaluations per "
                  "step and bearing")
    if not args.skip_cost:
        plain, user, calls = boundary_cost()
        per_call = (user - plain) / calls
        level = level_call_cost()
        res["cost"] = {"exudyn_step_us": plain, "boundary_us_per_call": per_call, **{f"{k}_us": v for k, v in
                                                                                      level.items()}}
        print("one evaluation of the quasi-static level (exact Hertz) on the test shaft, smallest of repeats:")
        print(f"  Exudyn step with its own connector {plain:.1f} us; a user function returning zeros adds "
              f"{per_call:.1f} us per call (Exudyn's Python boundary)")
        print(f"  the level's user function (connector formulation) {level['user function']:.1f} us per call at its operating pose, of "
              f"which _evaluate {level['_evaluate']:.1f} us and the compiled kernel {level['kernel']:.1f} us (with "
              f"direct exact Hertz constants and cold-started balls {level['kernel, direct Hertz, cold starts']:.1f} "
              "us)")
        print(f"  node formulation: the object's force call {level['node force call']:.1f} us (kernel included), "
              f"its Jacobian call {level['node Jacobian call']:.1f} us")
    if not args.skip_newton:
        print("Newton's relative tolerance (quasi-static level, exact Hertz, GeneralizedAlpha 1e-4 s): largest "
              "difference of the shaft's x, y from the run at 1e-10")
        for case, t_end, form in (("shaft", 0.05, "node"), ("clearance 20 um, 500 N", 0.1, "node"),
                                  ("shaft, connector", 0.05, "connector"),
                                  ("clearance 20 um, 500 N, connector", 0.1, "connector")):
            st = newton_study("shaft" if case.startswith("shaft") else "vc", t_end, (1e-8, 1e-5, 1e-4, 1e-3), form)
            res[f"newton {case}"] = {str(k): v for k, v in st.items()}
            print(f"  {case}, {t_end:g} s (peak-to-peak x {st['ptp'][0] * 1e9:.0f} nm, y {st['ptp'][1] * 1e9:.0f} nm):"
                  f" halving the step changes x by {st['step_halving'][0] * 1e9:.3g} nm, y by "
                  f"{st['step_halving'][1] * 1e9:.3g} nm")
            for rel in (1e-8, 1e-5, 1e-4, 1e-3):
                dx, dy, per, jacobians = st[rel]
                print(f"    relative tolerance {rel:g}: x {dx * 1e9:.3g} nm ({100 * dx / st['step_halving'][0]:.2g} % "
                      f"of the step halving's), y {dy * 1e9:.3g} nm ({100 * dy / st['step_halving'][1]:.2g} %), "
                      f"{per:.2f} evaluations per step, {jacobians} Jacobian(s)")
    (out / "bench_levels.json").write_text(json.dumps(res, indent=1))
    print("written:", out / "bench_levels.json")


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced."""
    return run.printed(
        "Cost of the bearing levels",
        "Wall time per simulated second of the ball element (body and fast mode) and of the two levels "
        "without ball degrees of freedom on a 2.5 kg shaft on one 6208 at 3000 N and 500 rad/s, medians of "
        "three runs, and the two-bearing run-up of scenarios/rotor_two_6208.py built with each level.",
        last_lines=70)


if __name__ == "__main__":
    main()
