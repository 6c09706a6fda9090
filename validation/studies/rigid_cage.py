"""The rigid cage in the reference engine (docs/theory/cage.md) against the torus cage, and what it costs.

(a) The DEM papers' radial 6208 case (F_r = 3000 N at 500 rad/s, steady from the analytic state): the
    torus cage against a rigid cage with the torus cage's two properties, ball-guided and frictionless
    (the estimated cage's geometry): Q_max of both races, cage speed and ball spin after --t-end, the
    relative differences against 0.5 % (the rigid cage's acceptance criterion, docs/theory/cage.md).
(b) The same 6208 with the estimated outer-land-guided brass cage (pocket friction 0.1, the DEM oil on
    the land): cage slip, whirl of the cage centre, pocket and land forces, the cage's losses and the
    energy balance.
(c) The 7208 under F_r = F_a = 3000 N at 500 rad/s: the torus cage at its stable step (0.5 us; the
    estimate 0.62 us) against the estimated rigid cage at 5 us (cage_damping='implicit': the land's force
    linearly implicit), both --t-end long: wall time per simulated second (median of --repeat runs of
    each, interleaved, same session), their ratio, the stable-step estimates, loads, cage speed,
    dissipation and energy residual.
(d) Step convergence of the rigid cage on the 7208: 5 us (implicit cage damping) against 1 us (explicit),
    3 --t-end long, summaries over the last quarter, with the regularised ball / race friction (the
    point level's Cundall-Strack spring is itself not converged in the step, so its runs would hide the
    cage's convergence): loads, cage speed, pocket and land losses.
(e) The orbit of the cage centre of (b) and (c) in a plot, with its data.

    python validation/studies/rigid_cage.py [--t-end 0.1] [--repeat 3] [--out validation/out/rigid_cage]

Writes rigid_cage.json, rigid_cage_orbit.png and rigid_cage_orbit.npz into --out.
"""
from __future__ import annotations

import argparse
import json
import time
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.data.cages import estimated_cage
from exudyn_bearing.model import layout as L
from exudyn_bearing.outputs.plotting import pyplot, save_figure

ROOT = Path(__file__).resolve().parents[2]
KEYS = ("q_max_inner", "q_max_outer", "cage_speed", "ball_spin")


def run(bearing, scenario):
    """(wall [s], summary, record) of one reference-engine run (steadiness warnings kept in the summary)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        t0 = time.perf_counter()
        rec = eb.simulate(bearing, scenario, progress=False)
        wall = time.perf_counter() - t0
        return wall, rec.summary(), rec


def pick(summary, keys):
    return {k: summary.get(k) for k in keys}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--t-end", type=float, default=0.1, help="simulated time of every run [s]")
    ap.add_argument("--repeat", type=int, default=3, help="runs of each 7208 variant for the wall-time median")
    ap.add_argument("--out", default=str(ROOT / "validation" / "out" / "rigid_cage"))
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    report = {"t_end_s": args.t_end}

    # (a) torus against the frictionless ball-guided rigid cage
    b = eb.catalog["6208"]
    base = {"Fr": 3000.0, "omega": 500.0, "t_end": args.t_end, "dt": 3e-6, "sample_dt": 1e-4}
    _, torus, _ = run(b, eb.Scenario(**base))
    ideal = estimated_cage(b, guidance="ball", pocket_friction=0.0)
    _, rigid, _ = run(b, eb.Scenario(**base, cage="rigid", rigid_cage=ideal))
    diff = {k: rigid[k] / torus[k] - 1.0 for k in KEYS}
    report["a_6208_torus_vs_ideal_rigid"] = {"torus": pick(torus, KEYS), "rigid": pick(rigid, KEYS),
                                             "relative_difference": diff,
                                             "within_0.5_percent": all(abs(v) < 5e-3 for v in diff.values())}
    print(f"(a) 6208, {args.t_end} s at 3 us: rigid (ball-guided, frictionless) / torus - 1:")
    for k, v in diff.items():
        print(f"    {k:12s} {100 * v:+.3f} %   (torus {torus[k]:.5g}, rigid {rigid[k]:.5g})")

    # (b) the estimated outer-land-guided brass cage
    land_keys = ("cage_speed", "cage_slip", "cage_whirl_radius", "cage_whirl_ratio", "pocket_force_max",
                 "land_force_mean", "land_eccentricity_max", "cage_power_pocket", "cage_power_land",
                 "dissipation", "energy_residual")
    _, land, rec6208 = run(b, eb.Scenario(**{**base, "dt": 4e-6}, cage="rigid"))
    report["b_6208_land_guided"] = pick(land, land_keys + KEYS)
    print("(b) 6208, estimated outer-land-guided brass cage, 4 us:")
    for k in land_keys:
        print(f"    {k:22s} {land[k]}")

    # (c) the 7208: torus at 0.5 us against rigid at 5 us, interleaved
    b7 = eb.catalog["7208"]
    sc7 = {"Fr": 3000.0, "Fa": 3000.0, "omega": 500.0, "t_end": args.t_end, "sample_dt": 1e-4}
    variants = {"torus_0.5us": eb.Scenario(**sc7, dt=0.5e-6),
                "rigid_5us": eb.Scenario(**sc7, dt=5e-6, cage="rigid", cage_damping="implicit")}
    walls = {k: [] for k in variants}   # whole simulate() call, set-up and summary included
    engine_walls = {k: [] for k in variants}   # the engine's integration alone (the summary's wall_s)
    summaries, records = {}, {}
    for i in range(args.repeat):
        for name in (list(variants) if i % 2 == 0 else list(variants)[::-1]):
            wall, summary, rec = run(b7, variants[name])
            walls[name].append(wall / args.t_end)
            engine_walls[name].append(summary["wall_s"] / args.t_end)
            summaries[name], records[name] = summary, rec
            print(f"    7208 {name}: {wall / args.t_end:.3g} s per simulated second ({summary['wall_s'] / args.t_end:.3g} "
                  "s integrating)", flush=True)
    med = {k: float(np.median(v)) for k, v in walls.items()}
    med_engine = {k: float(np.median(v)) for k, v in engine_walls.items()}
    keys7 = KEYS + ("dissipation", "energy_residual", "stable_dt", "cage_power_pocket", "cage_power_land",
                    "land_eccentricity_max")
    report["c_7208"] = {name: {"wall_per_simulated_second_median": med[name], "walls": walls[name],
                               "integration_wall_per_simulated_second_median": med_engine[name],
                               **pick(summaries[name], keys7)} for name in variants}
    report["c_7208"]["cost_ratio_rigid_over_torus"] = med["rigid_5us"] / med["torus_0.5us"]
    report["c_7208"]["integration_cost_ratio_rigid_over_torus"] = med_engine["rigid_5us"] / med_engine["torus_0.5us"]
    print(f"(c) 7208: wall per simulated second, median of {args.repeat}: torus at 0.5 us {med['torus_0.5us']:.3g} s, "
          f"rigid at 5 us {med['rigid_5us']:.3g} s (ratio {med['rigid_5us'] / med['torus_0.5us']:.3g}); integrating "
          f"alone {med_engine['torus_0.5us']:.3g} / {med_engine['rigid_5us']:.3g} s "
          f"(ratio {med_engine['rigid_5us'] / med_engine['torus_0.5us']:.3g}); "
          f"stable-step estimates {summaries['torus_0.5us']['stable_dt']:.3g} / {summaries['rigid_5us']['stable_dt']:.3g} s")

    # (d) step convergence of the rigid cage
    conv_keys = ("q_max_inner", "cage_speed", "ball_spin", "cage_power_pocket", "cage_power_land",
                 "pocket_force_mean", "land_eccentricity_max", "energy_residual")
    long = {**sc7, "t_end": 3 * args.t_end, "cage": "rigid", "friction": "regularized"}
    fine = run(b7, eb.Scenario(**long, dt=1e-6))[1]
    coarse = run(b7, eb.Scenario(**long, dt=5e-6, cage_damping="implicit"))[1]
    conv = {k: coarse[k] / fine[k] - 1.0 for k in conv_keys[:-2]}
    report["d_7208_step_convergence"] = {"1us": pick(fine, conv_keys), "5us_implicit": pick(coarse, conv_keys),
                                         "relative_difference": conv}
    print(f"(d) 7208 rigid cage, regularised friction, {3 * args.t_end:g} s: 5 us (implicit) / 1 us - 1:")
    for k, v in conv.items():
        print(f"    {k:18s} {100 * v:+.2f} %   (1 us {fine[k]:.5g}, 5 us {coarse[k]:.5g})")
    print(f"    energy residual: 1 us {fine['energy_residual']:.3g}, 5 us {coarse['energy_residual']:.3g} (the ball / "
          "race regularised friction's own step limit)")

    # (e) orbits of the cage centre
    fig, ax = pyplot().subplots(1, 2, figsize=(10, 4.6))
    arrays = {}
    for k, (name, rec) in enumerate((("6208 (b)", rec6208), ("7208 (c)", records["rigid_5us"]))):
        xy = rec.data["xc"][:, 0, :2] * 1e6
        arrays[f"t_{k}"], arrays[f"xy_um_{k}"] = rec.data["t"], xy
        ax[k].plot(xy[:, 0], xy[:, 1], lw=0.6)
        c = rec.model_parameters()[L.P_LAND_C] * 1e6
        th = np.linspace(0, 2 * np.pi, 200)
        ax[k].plot(c * np.cos(th), c * np.sin(th), "k--", lw=0.8, label=f"land clearance {c:.0f} um")
        ax[k].set_aspect("equal")
        ax[k].set_xlabel("cage centre x [um]")
        ax[k].set_ylabel("cage centre y [um]")
        ax[k].set_title(f"{name}, 0 - {args.t_end:g} s")
        ax[k].legend(loc="upper right", fontsize=8)
    save_figure(fig, out / "rigid_cage_orbit.png")
    np.savez(out / "rigid_cage_orbit.npz", **arrays)
    (out / "rigid_cage.json").write_text(json.dumps(report, indent=1, default=float))
    print(f"wrote {out / 'rigid_cage.json'}, rigid_cage_orbit.png/.npz")
    return 0 if report["a_6208_torus_vs_ideal_rigid"]["within_0.5_percent"] else 1


if __name__ == "__main__":
    raise SystemExit(main())
