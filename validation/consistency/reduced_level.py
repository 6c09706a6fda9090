"""The reduced level of ``eb.CreateBallBearing(model="reduced")`` against the engines and the other levels.

(a) The 6208 under F_r = 3000 N at 500 rad/s, traction over the ellipse, the inner ring a rigid shaft of the
    reduced engine's ring mass on the level (so that the scene is the engines' own), started at the quasi-static
    state: the level's steady state (Q_max inner and outer, the cage's speed, the dissipation, the energy residual)
    against the reference engine (2 us) and the reduced engine standalone (its step) on the same scene, without
    cage (0.05 s, window the second half) and with the bearing's rigid cage (0.2 s, window 0.05-0.2 s, the reduced
    engine's test window), for Exudyn steps of 20 us (one reduced step each), 100 us (one reduced step of
    100 us, or five of 20 us: ``reducedStep=2e-5``), 200 and 500 us (reduced steps of 20 us); the reduced engine's criteria (docs/theory/reduced.md): loads 0.5 %, orbital speed 0.2 %,
    dissipation 1 %; the lag check of the level (``lagForceMax``: the largest share of the ring force that the
    slow states' lag of one step changed, after the first step).
(b) A 2.5 kg shaft (the mass of validation/consistency/levels_checks.py's test shaft, a polar inertia of 1 kg m^2
    so that the friction torque leaves its speed; the outer ring on ground, 3000 N, 500 rad/s): the reduced level
    (no cage, rigid cage) against the quasi-static level (Q_max, cage speed), 0.05 s.
(c) Wall time per simulated second on that shaft, medians of ``--repeat`` runs in the same session (after one
    warm-up run each): the reduced level at 20 us (no cage and rigid cage) and at 100 us with reducedStep 20 us
    (rigid cage), the quasi-static level at its default 100 us, the ball element (fast mode, VelocityVerlet at
    3.5 us, the implicit tangential spring: validation/performance/bench_levels.py's).

    python validation/consistency/reduced_level.py [--out validation/out/levels] [--repeat 3] [--skip-bench]

Writes reduced_level.json into --out.
"""
from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
import warnings
from pathlib import Path

import exudyn as exu
from exudyn.itemInterface import (
    LoadForceVector,
    MarkerBodyRigid,
    NodeRigidBodyRxyz,
    ObjectGround,
    ObjectRigidBody,
)

import exudyn_bearing as eb
from exudyn_bearing.model.layout import P_MR
from exudyn_bearing.simulate import quasistatic_start
from exudyn_bearing.solvers.reduced import ReducedEngine

sys.path.insert(0, str(Path(__file__).resolve().parent))
from levels_checks import ROOT  # noqa: E402
from levels_checks import shaft as test_shaft
from levels_checks import solve_timed

FR, OMEGA = 3000.0, 500.0
KEYS = ("q_max_inner", "q_max_outer", "cage_speed", "dissipation")
CRITERIA = {"q_max_inner": 0.005, "q_max_outer": 0.005, "cage_speed": 0.002, "dissipation": 0.01}
#: cage -> (run [s], summary window [s])
RUNS = {"none": (0.05, (0.025, 0.05)), "rigid": (0.2, (0.05, 0.2))}
#: (label, Exudyn step [s], reducedStep [s] or None)
LEVEL_STEPS = (("level, Exudyn 20 us", 2e-5, None), ("level, Exudyn 100 us, reducedStep 20 us", 1e-4, 2e-5),
               ("level, Exudyn 100 us", 1e-4, None), ("level, Exudyn 200 us, reducedStep 20 us", 2e-4, 2e-5),
               ("level, Exudyn 500 us, reducedStep 20 us", 5e-4, 2e-5))


def scene(cage, t_end, dt):
    return eb.Scenario(Fr=FR, omega=OMEGA, cage=cage, traction_level="ellipse", initial="quasistatic",
                       sample_dt=1e-4, t_end=t_end, dt=dt)


def ring_shaft(mass, izz=1.0):
    """A rigid shaft (Rxyz node) at the origin turning at OMEGA under F_r, the outer-ring marker on ground (polar
    inertia ``izz``: 1 kg m^2 holds the speed against the friction torque within 1e-5)."""
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    node = mbs.AddNode(NodeRigidBodyRxyz(referenceCoordinates=[0.0] * 6, initialVelocities=[0, 0, 0, 0, 0, OMEGA]))
    body = mbs.AddObject(ObjectRigidBody(nodeNumber=node, mass=mass, inertia=[0.01, 0.01, izz, 0, 0, 0]))
    m_g = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground))
    m_b = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body))
    mbs.AddLoad(LoadForceVector(markerNumber=m_b, loadVector=[FR, 0.0, 0.0]))
    return sc, mbs, node, m_b, m_g


def solve(mbs, br, node, t_end, step):
    mbs.SetNodeParameter(node, "initialCoordinates", [*br.initialCoordinates[:3], 0.0, 0.0, 0.0])
    return solve_timed(mbs, br.SimulationSettings(t_end, stepSize=step), write_period=None)


def pick(s):
    return {k: float(s[k]) for k in (*KEYS, "energy_residual")}


def check_engines(out):
    res = {}
    for cage, (t_end, window) in RUNS.items():
        mass = float(ReducedEngine("6208", scene(cage, t_end, 2e-5)).params[P_MR])
        rows = {}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            for label, engine, dt in (("reference engine 2 us", "reference", 2e-6),
                                      ("reduced engine 20 us", "reduced", 2e-5)):
                t0 = time.perf_counter()
                r = eb.simulate("6208", scene(cage, t_end, dt), engine=engine)
                rows[label] = {**pick(r.summary(t_window=window)), "wall_s": time.perf_counter() - t0}
        for label, step, sub in LEVEL_STEPS:
            sc, mbs, node, m_b, m_g = ring_shaft(mass)
            br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="reduced", initialLoad=(FR, 0.0),
                                      initialOmega=OMEGA, cage=cage, sampleInterval=1e-4, reducedStep=sub)
            wall = solve(mbs, br, node, t_end, step)
            with warnings.catch_warnings():  # the steadiness verdict is the summary's; the table compares windows
                warnings.simplefilter("ignore")
                s = br.results().summary(t_window=window)
            rows[label] = {**pick(s), "wall_s": wall, "lag_force_max": br.lagForceMax,
                           "lag_force_mean": br.lagForceMean, "lag_force_start": br.lagForceStart,
                           "slip_time": br.slip_time(), "evaluations_per_step": br.evaluations / s["steps"] * 1.0,
                           "unconverged_steps": s["reduced_work"]["unconverged_steps"], "steps": s["steps"]}
        ref = rows["reference engine 2 us"]
        print(f"\n(a) 6208, F_r = {FR:g} N, {OMEGA:g} rad/s, cage {cage!r}, {t_end:g} s, window {window[0]:g}-"
              f"{window[1]:g} s, ring mass {mass:.4g} kg; differences from the reference engine (2 us):")
        print(f"    {'run':42s} {'Q_max in':>9s} {'Q_max out':>9s} {'cage':>9s} {'dissip.':>9s} {'E resid.':>9s} "
              f"{'lag max, mean':>15s} {'within':>7s}")
        for label, row in rows.items():
            d = {k: (row[k] - ref[k]) / abs(ref[k]) for k in KEYS}
            row["diff_reference"] = d
            ok = all(abs(d[k]) <= CRITERIA[k] for k in KEYS)
            row["within_criteria"] = ok
            lag = (f"{100 * row['lag_force_max']:6.2f}% {100 * row['lag_force_mean']:6.3f}%" if "lag_force_max" in row
                   else " " * 15)
            print(f"    {label:42s} " + " ".join(f"{100 * d[k]:+8.3f}%" for k in KEYS)
                  + f" {100 * row['energy_residual']:+8.3f}% {lag} {'yes' if ok else 'NO':>7s}")
        for label, row in rows.items():
            if "lag_force_start" in row:
                print(f"    {label:42s} lag at the first step {100 * row['lag_force_start']:.3f} %, slip relaxation "
                      f"time {row['slip_time'] * 1e6:.3g} us, unconverged balance steps {row['unconverged_steps']}")
        red = rows["reduced engine 20 us"]
        lv = rows["level, Exudyn 20 us"]
        d = {k: (lv[k] - red[k]) / abs(red[k]) for k in KEYS}
        print("    level at 20 us against the reduced engine at 20 us: "
              + ", ".join(f"{k} {100 * v:+.4f} %" for k, v in d.items()))
        res[cage] = {"t_end": t_end, "window": window, "ring_mass": mass, "rows": rows, "level_vs_reduced": d}
    return res


def check_quasistatic(out):
    res = {}
    print("\n(b) a 2.5 kg shaft (polar inertia 1 kg m^2: the friction torque leaves its speed), 0.05 s, window "
          "0.025-0.05 s: the reduced level against the quasi-static level")
    for label, model, opts, step in (("quasistatic", "quasistatic", {"coefficientSpeeds": [0.0, OMEGA]}, 1e-4),
                                     ("reduced, no cage", "reduced", {"cage": "none"}, 2e-5),
                                     ("reduced, rigid cage", "reduced", {"cage": "rigid"}, 2e-5)):
        sc, mbs, node, m_b, m_g = ring_shaft(2.5)
        br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model=model, initialLoad=(FR, 0.0), initialOmega=OMEGA,
                                  sampleInterval=1e-4, **opts)
        solve(mbs, br, node, 0.05, step)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            s = br.results().summary(t_window=(0.025, 0.05))
        res[label] = {"q_max_inner": float(s["q_max_inner"]), "q_max_outer": float(s["q_max_outer"]),
                      "cage_speed": float(s["cage_speed"])}
    qs = res["quasistatic"]
    for label, row in res.items():
        d = {k: (row[k] - qs[k]) / qs[k] for k in row}
        row["diff_quasistatic"] = d
        print(f"    {label:22s} Q_max inner {row['q_max_inner']:8.2f} N ({100 * d['q_max_inner']:+.3f} %), outer "
              f"{row['q_max_outer']:8.2f} N ({100 * d['q_max_outer']:+.3f} %), cage {row['cage_speed']:8.3f} rad/s "
              f"({100 * d['cage_speed']:+.3f} %)")
    return res


#: (label, model, options, solver, Exudyn step [s], simulated time [s])
BENCH = (("reduced, no cage, 20 us", "reduced", {"cage": "none"}, "GeneralizedAlpha", 2e-5, 0.02),
         ("reduced, rigid cage, 20 us", "reduced", {"cage": "rigid"}, "GeneralizedAlpha", 2e-5, 0.02),
         ("reduced, rigid cage, 100 us, reducedStep 20 us", "reduced", {"cage": "rigid", "reducedStep": 2e-5},
          "GeneralizedAlpha", 1e-4, 0.02),
         ("reduced, no cage, 200 us, reducedStep 20 us", "reduced", {"cage": "none", "reducedStep": 2e-5},
          "GeneralizedAlpha", 2e-4, 0.02),
         ("quasistatic, 100 us", "quasistatic", {}, "GeneralizedAlpha", 1e-4, 0.05),
         ("balls, fast mode, 3.5 us", "balls", {"mode": "fast", "tangential": "implicit"}, "VelocityVerlet", 3.5e-6,
          0.01))


def bench(repeat):
    start = [*quasistatic_start("6208", eb.Scenario(Fr=FR, omega=OMEGA))["ring"][:3], 0.0, 0.0]
    res = {}
    print(f"\n(c) wall time per simulated second on the 2.5 kg test shaft, 3000 N, 500 rad/s (median of {repeat} runs "
          "after a warm-up, same session):")
    for label, model, opts, solver, step, t_end in BENCH:
        walls = []
        for k in range(repeat + 1):
            sc, mbs, node, m_b, m_g, pos = test_shaft((FR, 0.0, 0.0), omega=OMEGA, damper=False,
                                                      start=start if model == "balls" else None)
            if model == "balls":
                br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, initialLoad=(FR, 0.0), initialOmega=OMEGA,
                                          initial="quasistatic", stepSize=step, sampleInterval=1e-3, **opts)
                ss = br.SimulationSettings(t_end)
            else:
                br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model=model, initialLoad=(FR, 0.0),
                                          initialOmega=OMEGA, sampleInterval=1e-3, **opts)
                mbs.SetNodeParameter(node, "initialCoordinates", [*br.initialCoordinates[:3], 0.0, 0.0, 0.0])
                ss = br.SimulationSettings(t_end, stepSize=step, solverType=solver)
            wall = solve_timed(mbs, ss)
            if k:  # the first run compiles
                walls.append(wall / t_end)
        res[label] = {"wall_per_sim_s": statistics.median(walls), "runs": walls, "step": step, "t_end": t_end}
        print(f"    {label:48s} {res[label]['wall_per_sim_s']:8.2f} s per simulated second "
              f"(runs {', '.join(f'{w:.2f}' for w in walls)})")
    return res


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default=str(ROOT / "validation" / "out" / "levels"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--skip-bench", action="store_true")
    a = ap.parse_args(argv)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    res = {"engines": check_engines(out), "quasistatic": check_quasistatic(out)}
    if not a.skip_bench:
        res["bench"] = bench(a.repeat)
    (out / "reduced_level.json").write_text(json.dumps(res, indent=1))
    print(f"\nwrote {out / 'reduced_level.json'}")


def report_section(run) -> str:
    """The level's checks and costs as this run printed them."""
    return run.printed(
        "The reduced level in Exudyn",
        "`CreateBallBearing(model=\"reduced\")`: the reduced engine's balls and rigid cage inside an Exudyn rotor "
        "model, their slow states one rotor step behind (docs/theory/levels.md, \"Reduced level\"), against the "
        "reference and reduced engines on the same scene, against the quasi-static level, and its cost per "
        "simulated second against the other levels.", last_lines=60)


if __name__ == "__main__":
    main()
