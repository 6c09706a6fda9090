"""Where a step of the reduced engine goes: its force evaluations by purpose, and the cost of one evaluation.

A step of the reduced engine (docs/theory/reduced.md, "The step") is a handful of evaluations of the shared
contact kernel and small dense solves (5 x 5 per ball, 6 x 6 for the ring, 8 x 8 for a rigid cage); the
evaluations are nearly all of it. From the engine's work counters (``RunRecord.reduced_stats``) this splits a
run's evaluations per step into:

* the Jacobians of the balls' speeds (om', w') in (phi, om, w), five evaluations per retaking, and with the
  rigid cage its eight columns and rows (thirteen), counted at each retaking (``jacobian_steps``);
* the inner ring's stiffness and damping, six evaluations at every RING_EVERY-th retaking;
* the Jacobians of the balls' force balance, two evaluations each time the balance takes them;
* the rest: the balance's Newton iterations, each one evaluation, its committed evaluation, the samples that
  the committed evaluation could not carry, and with the rigid cage the pocket corrections.

The wall time per evaluation is the run's wall time over its evaluations (the integration alone, the kernels
compiled before the clock starts); ``--point`` also runs each case with the point traction (regularised
Coulomb), whose evaluation is cheaper, to show what the traction over the ellipse costs per evaluation.
One run each on a shared host: the split is exact (counted), the wall times are not.

    python validation/performance/profile_reduced.py [--case radial ACBB cage] [--dt 2e-5 1e-4] [--point]
"""
from __future__ import annotations

import argparse
import math
import sys
import warnings
from pathlib import Path

import exudyn_bearing as eb
from exudyn_bearing.solvers.reduced import engine as reduced

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "consistency"))
from reduced_engine import CASES, COMMON  # noqa: E402  (the cases of the reduced engine's checks)


def profile(bearing, fields, t_end, dt, traction):
    """One run of the reduced engine: (wall per simulated second, wall per evaluation [us], evaluations per
    step by purpose, the run's reduced_stats)."""
    extra = {} if traction == "ellipse" else {"traction_level": "point", "friction": "regularized"}
    sc = eb.Scenario(**{**COMMON, **fields, **extra}, t_end=t_end, dt=dt)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rec = eb.simulate(bearing, sc, engine="reduced").record
    st = rec.reduced_stats
    steps = max(rec.steps, 1)
    evals = st["evaluations_per_step"] * steps
    per_jac = 5 + (8 if sc.cage == "rigid" else 0)
    n_ref = st["jacobian_steps"]
    parts = {"speed Jacobians": per_jac * n_ref / steps,
             "ring": 6 * math.ceil(n_ref / reduced.RING_EVERY) / steps}
    if "balance_jacobians" in st:  # (a version of the engine without the counter: in the rest)
        parts["balance Jacobians"] = 2 * st["balance_jacobians"] / steps
    parts["balance, committed, rest"] = st["evaluations_per_step"] - sum(parts.values())
    wall = rec.wall_s
    return wall / t_end, 1e6 * wall / max(evals, 1.0), parts, st


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--case", nargs="+", default=["6208 radial (", "ACBB", "6208 radial, rigid cage ("],
                    help="cases of validation/consistency/reduced_engine.py whose name contains one of these")
    ap.add_argument("--dt", type=float, nargs="+", default=[2e-5, 1e-4])
    ap.add_argument("--point", action="store_true", help="also with the point traction (cost per evaluation)")
    args = ap.parse_args(argv)
    print(f"reduced engine: JAC_EVERY {reduced.JAC_EVERY}, JAC_TOL {reduced.JAC_TOL}, RING_EVERY "
          f"{reduced.RING_EVERY}; force evaluations per step by purpose, one run each")
    for name, (bearing, fields, t_end, _) in CASES.items():
        if not any(w.lower() in name.lower() for w in args.case):
            continue
        for dt in args.dt:
            for traction in ("ellipse", "point") if args.point else ("ellipse",):
                wall, per_eval, parts, st = profile(bearing, fields, t_end, dt, traction)
                split = "  ".join(f"{k} {v:.2f}" for k, v in parts.items())
                print(f"{name[:48]:48s} dt {dt * 1e6:5.0f} us {traction:7s}: {st['evaluations_per_step']:.2f} "
                      f"evaluations/step ({split}); Newton iterations/step {st['newton_per_step']:.2f}, "
                      f"unconverged steps {st['unconverged_steps']}; {per_eval:.1f} us per evaluation, "
                      f"{wall:.3g} s per simulated second", flush=True)


if __name__ == "__main__":
    raise SystemExit(main())
