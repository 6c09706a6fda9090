"""Speed of the Exudyn bearing element against the reference core and Exudyn's built-in bearing.

All measured in one run on one core (medians of ``--repeat``):

* reference: the numba DEM core on the 6208 scene (F_r = 3000 N, 500 rad/s,
  cage, lubrication, Cundall-Strack history, analytic start), dt = 5 us;
* element, body mode: the same scene built in Exudyn (balls as Exudyn
  nodes), VelocityVerlet at 5 us;
* element, fast mode: balls integrated in compiled sub-steps (1 x 5 us per
  Exudyn step, and as many 5 us sub-steps as the fast mode's step limit
  allows: ``FAST_STEP_SHARE`` of the ring's stable-step estimate, one on the
  81 g ring of this scene);
* the same scene with a ring of 1.25 kg (a ring carrying half of a 2.5 kg
  rotor): the reference core and the fast mode with as many sub-steps as
  its limit allows;
* Exudyn's ``exudyn.machines.CreateBallBearing`` on a 6208-sized bearing
  (GetBallBearingData: 80 x 40 x 18 mm, 9 balls of 6.3 mm, grooves 6.552 mm)
  with the same Hertz stiffness (k = mean of our exact K_inner and K_outer,
  exponent 1.5), damping 200 N s/m, mu = 0.1, cage springs, inner ring a free
  rigid body spun at 500 rad/s, the load ramped over 5 ms (a sudden load
  stops its solver), GeneralizedAlpha: the largest of the tried steps whose
  cage speed is within 0.5 % of the finest step.

Errors of our engines: q_max_inner and cage_speed against the reference
engine at a quarter of the step.

    python validation/performance/bench_element.py [--t-end 0.1] [--repeat 3] [--ga]

Wall times are the solves alone (integration loop, SolveDynamic), not the
model set-up.
"""
from __future__ import annotations

import argparse
import json
import sys
import time
import warnings
from pathlib import Path

import numpy as np

import exudyn as exu
import exudyn_bearing as eb
from exudyn_bearing.solvers.element.engine import ExudynEngine, solve_dynamic
from exudyn_bearing.physics.load_distribution import race_stiffness
from exudyn_bearing.solvers.reference import ReferenceEngine
from exudyn_bearing.model.initial_state import ring_mass_estimate
from exudyn_bearing.model.stability import FAST_STEP_SHARE, ring_stable_step

SCENE = dict(Fr=3000.0, omega=500.0, sample_dt=1e-3)
#: Ring mass [kg] of the second scene: a ring carrying half of a 2.5 kg rotor.
HEAVY_RING = 1.25


def timed(fn, repeat):
    """Median of the runs' own solve times (Results.wall_s: the integration,
    not the model set-up) and the last result."""
    walls, out = [], None
    for _ in range(repeat):
        out = fn()
        walls.append(out.wall_s)
    return float(np.median(walls)), out


def builtin_run(t_end, h, k):
    """Exudyn's built-in ball bearing; returns (wall, cage speed at the end, ok)."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "consistency"))  # levels_checks.py, peer_builtin.py
    from peer_builtin import build_builtin, gen_alpha_settings

    SC, mbs, items = build_builtin(k=k, damping=200.0, mu=0.1, v_reg=None)
    mbs.Assemble()
    ss = gen_alpha_settings(t_end, h)
    t0 = time.perf_counter()
    try:
        solve_dynamic(mbs, ss, exu.DynamicSolverType.GeneralizedAlpha)
        ok = True
    except Exception:
        ok = False
    wall = time.perf_counter() - t0
    cage = mbs.GetObjectOutputBody(items["objectCage"], exu.OutputVariableType.AngularVelocity, [0, 0, 0])[2]
    return wall, float(cage), ok


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--t-end", type=float, default=0.1)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--out", default=str(Path(__file__).resolve().parents[1] / "out"))
    ap.add_argument("--ga", action="store_true", help="also time the element under GeneralizedAlpha (slow)")
    args = ap.parse_args(argv)
    T = args.t_end
    warnings.simplefilter("ignore")
    sc = eb.Scenario(t_end=T, dt=5e-6, **SCENE)
    fine = eb.simulate("6208", sc.replace(dt=1.25e-6)).summary()
    # warm-up (compilation)
    ReferenceEngine("6208", sc.replace(t_end=1e-3)).run()
    ExudynEngine("6208", sc.replace(t_end=1e-3)).run()
    ExudynEngine("6208", sc.replace(t_end=1e-3), mode="fast").run()
    b = eb.catalog["6208"]
    n_fast = max(1, int(FAST_STEP_SHARE * ring_stable_step(b, sc, ring_mass_estimate(b)) / sc.dt))
    fast_name = f"element fast mode, {n_fast} x 5 us sub-steps"
    heavy = sc.replace(ring_mass=HEAVY_RING)
    fine_heavy = eb.simulate("6208", heavy.replace(dt=1.25e-6)).summary()
    n_heavy = max(1, int(FAST_STEP_SHARE * ring_stable_step(b, heavy, HEAVY_RING) / sc.dt))
    ref_heavy = f"reference, ring {HEAVY_RING:g} kg, dt 5 us"
    fast_heavy = f"element fast mode, ring {HEAVY_RING:g} kg, {n_heavy} x 5 us sub-steps"
    rows = {}
    runs = {
        "reference, dt 5 us": (lambda: eb.Results(ReferenceEngine("6208", sc).run()), fine),
        "element body mode, VelocityVerlet 5 us": (lambda: eb.Results(ExudynEngine("6208", sc).run()), fine),
        "element fast mode, 1 x 5 us sub-step": (
            lambda: eb.Results(ExudynEngine("6208", sc, mode="fast", sub_steps=1).run()), fine),
        fast_name: (lambda: eb.Results(ExudynEngine("6208", sc, mode="fast", sub_steps=n_fast).run()), fine),
        ref_heavy: (lambda: eb.Results(ReferenceEngine("6208", heavy).run()), fine_heavy),
        fast_heavy: (lambda: eb.Results(ExudynEngine("6208", heavy, mode="fast", sub_steps=n_heavy).run()),
                     fine_heavy),
    }
    print(f"6208, Fr = 3000 N, 500 rad/s, cage + lubrication + history, T = {T} s, median of {args.repeat}")
    print(f"{'engine':52s} {'wall/sim s':>10s} {'err q_in %':>10s} {'err cage %':>10s}")
    for name, (fn, truth) in runs.items():
        if name == fast_name and n_fast == 1:
            continue  # the row above
        wall, res = timed(fn, args.repeat)
        s = res.summary()
        rows[name] = dict(wall_per_sim_s=wall / T, err_q_max_inner=abs(s["q_max_inner"] / truth["q_max_inner"] - 1),
                          err_cage_speed=abs(s["cage_speed"] / truth["cage_speed"] - 1))
        print(f"{name:52s} {wall / T:10.3f} {100 * rows[name]['err_q_max_inner']:10.3f} "
              f"{100 * rows[name]['err_cage_speed']:10.3f}")
    ki, ko, _ = race_stiffness(eb.catalog["6208"])
    k = 0.5 * (ki + ko)
    t_b = 0.02
    finest = builtin_run(t_b, 5e-6, k)
    best = None
    for h in (4e-5, 2e-5, 1e-5):
        wall, cage, ok = builtin_run(t_b, h, k)
        err = abs(cage / finest[1] - 1) if ok else float("nan")
        print(f"built-in CreateBallBearing, GeneralizedAlpha h = {h:g}: ok = {ok}, wall/sim {wall / t_b:.2f} s, "
              f"cage error against h = 5e-6: {100 * err:.3f} %")
        if ok and err <= 5e-3 and (best is None or wall < best[0]):
            best = (wall, h, err)
    if best is None:
        print("built-in bearing: no tried step met 0.5 %")
        ratio = float("nan")
    else:
        rows["built-in CreateBallBearing"] = dict(wall_per_sim_s=best[0] / t_b, h=best[1], err_cage_speed=best[2])
        ratio = rows["element body mode, VelocityVerlet 5 us"]["wall_per_sim_s"] / (best[0] / t_b)
    fast_ratio = (rows[fast_name if n_fast > 1 else "element fast mode, 1 x 5 us sub-step"]["wall_per_sim_s"]
                  / rows["reference, dt 5 us"]["wall_per_sim_s"])
    heavy_ratio = rows[fast_heavy]["wall_per_sim_s"] / rows[ref_heavy]["wall_per_sim_s"]
    print(f"ratio body mode / built-in bearing (best step): {ratio:.3f} (target <= 0.5)")
    fast1_body = (rows["element fast mode, 1 x 5 us sub-step"]["wall_per_sim_s"]
                  / rows["element body mode, VelocityVerlet 5 us"]["wall_per_sim_s"])
    print(f"ratio fast mode ({n_fast} x 5 us) / reference core: {fast_ratio:.2f} (target <= 2); ring "
          f"{HEAVY_RING:g} kg ({n_heavy} x 5 us): {heavy_ratio:.2f}")
    print(f"ratio fast mode (1 sub-step) / body mode: {fast1_body:.2f}")
    if args.ga:
        # implicit: Exudyn's numerical Jacobian of the whole bearing object, modified Newton
        eng = ExudynEngine("6208", eb.Scenario(t_end=2e-3, dt=1e-5, friction="regularized",
                                               **dict(SCENE, sample_dt=1e-4)))
        ss = eng.element.SimulationSettings(2e-3, 1e-5)
        ss.timeIntegration.newton.useModifiedNewton = True
        t0 = time.perf_counter()
        solve_dynamic(eng.mbs, ss, exu.DynamicSolverType.GeneralizedAlpha)
        wall = time.perf_counter() - t0
        rows["element body mode, GeneralizedAlpha 10 us"] = dict(wall_per_sim_s=wall / 2e-3,
                                                                  evaluations=eng.element._evaluations)
        print(f"element body mode, GeneralizedAlpha h = 1e-5 (regularized friction): wall/sim {wall / 2e-3:.0f} s, "
              f"{eng.element._evaluations} force evaluations for 200 steps")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "bench_element.json").write_text(json.dumps(dict(
        rows=rows, ratio_body_builtin=ratio, ratio_fast_reference=fast_ratio, ratio_fast1_body=fast1_body,
        fast_sub_steps=n_fast, heavy_ring=HEAVY_RING, heavy_sub_steps=n_heavy, ratio_fast_reference_heavy=heavy_ratio,
        fast_step_share=FAST_STEP_SHARE, t_end=T, k_builtin=k), indent=2))


if __name__ == "__main__":
    main()
