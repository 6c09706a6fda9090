"""Wall time per simulated second of the three bearing levels (``eb.CreateBallBearing(model=...)``).

1. One-bearing test shaft: a 2.5 kg shaft on one 6208 under F_r = 3000 N, spinning at 500 rad/s, started at
   the quasi-static pose: the ball element (body and fast mode, VelocityVerlet at 3.5 us with the implicit
   tangential spring, the README's example), the
   quasi-static level (Hertz "exact" and "hamrock_brewe") and the linear level (speed table through the
   user function, and one speed as Exudyn's own connector), GeneralizedAlpha at 1e-4 s. Medians of
   ``--repeat`` runs (after one warm-up run that compiles).
2. The rotor of scenarios/rotor_two_6208.py run up from 0 to 1000 rad/s in about 1 s (motor torque 0.5 N m)
   at the two levels without ball DOFs: wall time of the 1 s run.

    python validation/bench_levels.py [--repeat 3] [--skip-runup]

Prints the table and writes bench_levels.json into --out (default validation/out/levels).
"""
from __future__ import annotations

import argparse
import json
import math
import time
import warnings
from pathlib import Path


import exudyn_bearing as eb
from exudyn_bearing.simulate import quasistatic_start

from levels_checks import ROOT, load_rotor_scenario, shaft  # noqa: E402 - validation/ is on the path

FR, OMEGA = 3000.0, 500.0

#: (label, model, options, solver, step [s], simulated time [s])
CASES = (("balls, body mode", "balls", {"tangential": "implicit"}, "VelocityVerlet", 3.5e-6, 0.01),
         ("balls, fast mode", "balls", {"mode": "fast", "tangential": "implicit"}, "VelocityVerlet", 3.5e-6, 0.01),
         ("quasistatic, exact Hertz", "quasistatic", {}, "GeneralizedAlpha", 1e-4, 0.05),
         ("quasistatic, hamrock_brewe", "quasistatic", {"hertzModel": "hamrock_brewe"}, "GeneralizedAlpha", 1e-4,
          0.05),
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
        mbs.Assemble()
        ss.solution.sensors.writePeriod = 1e-3
        t0 = time.perf_counter()
        with eb.filter_exudyn_notes(), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
        run.solve = time.perf_counter() - t0
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


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--skip-runup", action="store_true")
    ap.add_argument("--out", default=str(ROOT / "validation" / "out" / "levels"))
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    res = {}
    print(f"one 6208 on a 2.5 kg shaft, F_r = {FR:g} N, {OMEGA:g} rad/s; median of {args.repeat} runs, solver time")
    print(f"  {'level':40s} {'solver':17s} {'step':>7s} {'sim':>7s} {'wall/sim s':>11s} {'evals/step':>10s}")
    for label, model, options, solver, h, t_end in CASES:
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
    ref = res["balls, fast mode"]["wall_per_sim_s"]
    for label in res:
        res[label]["cheaper_than_balls_fast"] = ref / res[label]["wall_per_sim_s"]
    print("  ratio to the ball element (fast mode): " + ", ".join(
        f"{k} {v['cheaper_than_balls_fast']:.2g}x" for k, v in res.items() if not k.startswith("balls")))
    if not args.skip_runup:
        print("rotor of scenarios/rotor_two_6208.py, run-up 0 -> 1000 rad/s with 0.5 N m (about 1 s), 1 s simulated, "
              "GeneralizedAlpha 1e-4 s:")
        for label, model, options in (("quasistatic, hamrock_brewe", "quasistatic", {"hertzModel": "hamrock_brewe"}),
                                      ("quasistatic, exact Hertz", "quasistatic", {}),
                                      ("linear, speed table", "linear", {})):
            wall, w_end, per = runup(model, options=options)
            res[f"runup {label}"] = {"wall_s": wall, "final_speed": w_end, "evaluations_per_step": per}
            print(f"  {label:40s} {wall:7.1f} s wall, final speed {w_end:.0f} rad/s, {per:.2f} evaluations per "
                  "step and bearing")
    (out / "bench_levels.json").write_text(json.dumps(res, indent=1))
    print("written:", out / "bench_levels.json")


if __name__ == "__main__":
    main()
