"""Gupta's high-speed ACBB-120 with a rigid cage: the reference engine against the quasi-static traction
equilibrium with the cage (docs/theory/quasistatic.md#the-rigid-cage).

The ACBB-120 (15 balls of 20.6 mm, 24 deg) at 25,000 rpm under 22,240 N thrust, its oil MIL-L-23699 at 492 K with
its EHL traction model, the inner ring growing with speed, tilts held, the estimated outer-land-guided brass cage
(``estimated_cage``: pocket friction 0.1; the bearing's default cage, it has no cage balls):

* quasi-static: ``solve_quasistatic(..., control="equilibrium", cage="rigid")`` at 16 x 4 traction points;
* reference engine: ``Scenario(traction_level="ellipse", initial="quasistatic", control="equilibrium",
  cage_damping="implicit")`` at ``--dt`` for ``--t-end`` (the cage needs some 15 ms to lag into its pockets against
  the land's drag), summary over the last quarter.

Printed: Q_max of both races, the cage speed, the dissipation (quasi-static: traction + pocket + land; engine:
``dissipation``, which also holds the contacts' normal damping, and its parts), the cage's motion class. The
targets: 1 % in loads and cage speed, 3 % in dissipation.

    python validation/consistency/acbb120_rigid_cage.py [--t-end 0.06] [--dt 2e-6] [--out validation/out/acbb120_rigid_cage]
"""
from __future__ import annotations

import argparse
import json
import time
import warnings
from pathlib import Path

import exudyn_bearing as eb
from exudyn_bearing.solvers.quasistatic import solve_quasistatic
from exudyn_bearing.solvers.quasistatic.losses import power_losses

ROOT = Path(__file__).resolve().parents[2]
TRACTION, LUBRICANT = "ehl_mil_l_23699_492K", "MIL-L-23699_492K"
CASE = {"Fa": 22240.0, "omega": 2618.0}
RESOLUTION = {"n_strips": 16, "n_across": 4}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--t-end", type=float, default=0.06, help="simulated time of the engine's run [s]")
    ap.add_argument("--dt", type=float, default=2e-6, help="engine step [s]")
    ap.add_argument("--out", default=str(ROOT / "validation" / "out" / "acbb120_rigid_cage"))
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    s = solve_quasistatic("ACBB-120", 0.0, CASE["Fa"], omega=CASE["omega"], control="equilibrium", cage="rigid",
                          traction=TRACTION, lubricant=LUBRICANT, fixed={"tilt_x": 0.0, "tilt_y": 0.0},
                          stiffness=False, **RESOLUTION)
    pl = power_losses(s)["power_loss"]
    qs = {"q_max_inner": s.q_max_inner, "q_max_outer": s.q_max_outer, "cage_speed": s.cage["speed"],
          "dissipation": s.dissipation_total + pl["cage_pocket"] + pl["cage_land"],
          "dissipation_contacts": s.dissipation_total, "cage_power_pocket": pl["cage_pocket"],
          "cage_power_land": pl["cage_land"], "wall_s": time.perf_counter() - t0}
    sc = eb.Scenario(**CASE, t_end=args.t_end, dt=args.dt, traction_level="ellipse", traction=TRACTION,
                     initial="quasistatic", control="equilibrium", cage_damping="implicit", sample_dt=1e-4,
                     **RESOLUTION)
    t0 = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        d = eb.simulate("ACBB-120", sc, lubricant=LUBRICANT, progress=False).summary()
    pw = d["power_loss"]
    dem = {"q_max_inner": d["q_max_inner"], "q_max_outer": d["q_max_outer"], "cage_speed": d["cage_speed"],
           "dissipation": d["dissipation"],
           "dissipation_contacts": pw.get("contact_traction_inner", 0.0) + pw.get("contact_traction_outer", 0.0),
           "cage_power_pocket": d["cage_power_pocket"], "cage_power_land": d["cage_power_land"],
           "wall_s": time.perf_counter() - t0}
    w = d["window"]
    print(f"ACBB-120, F_a = {CASE['Fa']:g} N, 25000 rpm, {TRACTION}, estimated outer-land brass cage; engine "
          f"{args.t_end:g} s at {args.dt:g} s, window {w['t0']:.4g}-{w['t1']:.4g} s, steady "
          f"{d['steady']['steady']}, cage motion {d['cage_motion']}")
    print(f"{'':22s}{'quasi-static':>14s}{'engine':>14s}{'engine/QS - 1':>16s}")
    for k, q in qs.items():
        if k != "wall_s":
            print(f"{k:22s}{q:14.6g}{dem[k]:14.6g}{100 * (dem[k] / q - 1):15.3f} %")
    print(f"wall: quasi-static {qs['wall_s']:.1f} s, engine {dem['wall_s']:.1f} s")
    report = {"case": CASE, "t_end": args.t_end, "dt": args.dt, "window": w, "quasistatic": qs, "engine": dem,
              "cage_motion": d["cage_motion"], "steady": d["steady"]["steady"]}
    (out / "acbb120_rigid_cage.json").write_text(json.dumps(report, indent=2, default=float))
    print(f"wrote {out / 'acbb120_rigid_cage.json'}")


if __name__ == "__main__":
    main()
