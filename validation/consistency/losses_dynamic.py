"""Rolling resistance and ball drag as forces in both dynamic engines, against the quasi-static loss report.

    python validation/consistency/losses_dynamic.py [--quick] [--repeats N]

Cases (docs/theory/losses.md, "In the dynamic engines"; both switches on, oil volume fraction 0.05):

* the DEM papers' 6208 under 3000 N radial load at 500 rad/s (point traction level, cage, the papers'
  oil ``guessasma2018``), from the analytic start;
* the 6208 under 3000 N thrust at 500 rad/s, cageless, traction over the Hertz ellipse (16 x 4 points),
  from the quasi-static traction equilibrium (the scene of tests/test_energy.py; the point level's
  thrust run from the analytic start is still spinning its balls up after 10 ms, its energy balance
  then open by the kinetic and spring energy it stores, with the switches off as on);
* Gupta's ACBB-120 under 22,240 N thrust at 25,000 rpm (2618 rad/s), its oil MIL-L-23699 at 492 K,
  traction over the Hertz ellipse with ``ehl_mil_l_23699_492K``, grooves growing with speed, from the
  quasi-static minimum-energy solution (the scene of validation/consistency/highspeed_acbb120.py, shorter).

For each case: the reference engine and the Exudyn element report ``ehl_rolling``, ``hysteresis`` and
``drag`` (time means over the last half of the run, ``Results.summary(fraction=0.5)``) and the energy
check; the quasi-static solver at the same loads, speed, lubricant and kinematics (race control
``auto`` for the radial 6208, the traction equilibrium for the thrust 6208, ``min-energy`` for the
ACBB-120) reports the same components from
``solvers.quasistatic.losses.power_losses(oil_volume_fraction=0.05)``. Cost: the integration wall
time per simulated second (``RunRecord.wall_s / t_end``, compilation excluded), median of
``--repeats`` runs with the switches off and on (run in turn), and the median of the pairs' ratios.
The machine's load changes between runs: the ratios, not the absolute times, are the result.

Prints one table of powers [W] and one of costs; writes validation/out/losses_dynamic.csv and .png.
"""
from __future__ import annotations

import argparse
import csv
import statistics
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.outputs.plotting import pyplot, save_figure
from exudyn_bearing.solvers.quasistatic.losses import power_losses

OUT = Path(__file__).resolve().parents[1] / "out"
PHI = 0.05
COMPONENTS = ("ehl_rolling", "hysteresis", "drag")
ENGINES = ("reference", "exudyn")
#: name: (bearing, scenario fields, quasi-static keywords, lubricant or None)
CASES = {
    "6208 radial": ("6208", dict(Fr=3000.0, Fa=0.0, omega=500.0, t_end=0.01, dt=2e-6, sample_dt=1e-4),
                    dict(Fr=3000.0, omega=500.0), None),
    "6208 thrust": ("6208", dict(Fr=0.0, Fa=3000.0, omega=500.0, cage=False, traction_level="ellipse", n_strips=16,
                                 n_across=4, initial="quasistatic", control="equilibrium", t_end=0.01, dt=2e-6,
                                 sample_dt=2e-4),
                    dict(Fa=3000.0, omega=500.0, control="equilibrium", n_strips=16, n_across=4,
                         fixed={"tilt_x": 0.0, "tilt_y": 0.0}), None),
    "ACBB-120": ("ACBB-120", dict(Fr=0.0, Fa=22240.0, omega=2618.0, cage=False, traction_level="ellipse",
                                  traction="ehl_mil_l_23699_492K", ring_growth=True, initial="quasistatic",
                                  control="min-energy", t_end=0.01, dt=2e-6, sample_dt=2e-4),
                 dict(Fa=22240.0, omega=2618.0, control="min-energy", traction="ehl_mil_l_23699_492K",
                      lubricant="MIL-L-23699_492K"), "MIL-L-23699_492K"),
}


def run(bearing, fields, engine, on, lubricant):
    sc = eb.Scenario(**fields, rolling_resistance=on, ball_drag=on, oil_volume_fraction=PHI if on else 0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = eb.simulate(bearing, sc, engine=engine, lubricant=lubricant)
        return res, res.summary(fraction=0.5)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="runs of a quarter of the length, one repeat")
    ap.add_argument("--repeats", type=int, default=5, help="timed runs per engine, case and switch (median)")
    args = ap.parse_args(argv)
    repeats = 1 if args.quick else max(1, args.repeats)
    rows = []
    costs = []
    for name, (bearing, fields, qs_kw, lub) in CASES.items():
        fields = dict(fields)
        if args.quick:
            fields["t_end"] = fields["t_end"] / 4
        sol = eb.solve_quasistatic(bearing, **qs_kw, stiffness=False)
        qs = power_losses(sol, oil_volume_fraction=PHI)["power_loss"]
        rows.append({"case": name, "solver": "quasistatic", **{k: qs[k] for k in COMPONENTS},
                     "traction": qs["traction"], "energy_residual": None})
        for engine in ENGINES:
            walls = {False: [], True: []}
            for k in range(repeats + 1):  # the first pair compiles (or loads) the scene's kernels
                for on in (False, True):  # off and on in turn: a change of the machine's load hits both
                    res, s = run(bearing, fields, engine, on, lub)
                    if k > 0:
                        walls[on].append(res.wall_s / float(res.t[-1]))
            p = s["power_loss"]
            rows.append({"case": name, "solver": engine, **{k: p[k] for k in COMPONENTS},
                         "traction": p["contact_traction_inner"] + p["contact_traction_outer"],
                         "energy_residual": s["energy_check"]["residual"]})
            costs.append({"case": name, "engine": engine, "wall_per_s_off": statistics.median(walls[False]),
                          "wall_per_s_on": statistics.median(walls[True]),
                          "ratio": statistics.median([b / a for a, b in zip(walls[False], walls[True])])})
    print(f"Power [W] by component (oil volume fraction {PHI:g}; dynamic: last half of the run)")
    print(f"{'case':12s} {'solver':12s} {'ehl_rolling':>12s} {'hysteresis':>11s} {'drag':>9s} "
          f"{'vs QS (ehl, hyst, drag)':>26s} {'energy res.':>12s}")
    for r in rows:
        qs = next(x for x in rows if x["case"] == r["case"] and x["solver"] == "quasistatic")
        rel = "" if r["solver"] == "quasistatic" else ", ".join(f"{100 * (r[k] / qs[k] - 1):+.2f} %"
                                                                for k in COMPONENTS)
        res = "" if r["energy_residual"] is None else f"{100 * r['energy_residual']:+.3f} %"
        print(f"{r['case']:12s} {r['solver']:12s} {r['ehl_rolling']:12.4g} {r['hysteresis']:11.4g} "
              f"{r['drag']:9.4g} {rel:>26s} {res:>12s}")
    print(f"\nCost: integration wall time per simulated second [s/s], median of {repeats} run(s)")
    print(f"{'case':12s} {'engine':10s} {'off':>10s} {'on':>10s} {'on/off (median of pairs)':>25s}")
    for c in costs:
        print(f"{c['case']:12s} {c['engine']:10s} {c['wall_per_s_off']:10.4g} {c['wall_per_s_on']:10.4g} "
              f"{c['ratio']:25.3f}")
    OUT.mkdir(exist_ok=True)
    plt = pyplot()
    fig, axes = plt.subplots(1, len(CASES), figsize=(4.2 * len(CASES), 3.6))
    solvers = ("quasistatic",) + ENGINES
    for ax, name in zip(np.atleast_1d(axes), CASES):
        x = np.arange(len(COMPONENTS))
        for k, solver in enumerate(solvers):
            r = next(x_ for x_ in rows if x_["case"] == name and x_["solver"] == solver)
            ax.bar(x + (k - 1) * 0.27, [r[c] for c in COMPONENTS], 0.27, label=solver)
        ax.set_xticks(x, COMPONENTS)
        ax.set_yscale("log")
        ax.set_title(name)
        ax.set_ylabel("power [W]")
    np.atleast_1d(axes)[0].legend(fontsize=8)
    png = save_figure(fig, OUT / "losses_dynamic.png")
    with open(png.with_suffix(".csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["case", "solver", *(f"{k}_W" for k in COMPONENTS), "energy_residual", "wall_per_s_off",
                    "wall_per_s_on"])
        for r in rows:
            c = next((c for c in costs if c["case"] == r["case"] and c["engine"] == r["solver"]), None)
            w.writerow([r["case"], r["solver"], *(f"{r[k]:.6g}" for k in COMPONENTS),
                        "" if r["energy_residual"] is None else f"{r['energy_residual']:.6g}",
                        "" if c is None else f"{c['wall_per_s_off']:.6g}", "" if c is None else f"{c['wall_per_s_on']:.6g}"])
    print(f"\nwrote {png} and {png.with_suffix('.csv')}")


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced."""
    return run.printed(
        "Rolling resistance and ball drag in the dynamic engines",
        "The switches `rolling_resistance` (hysteresis + EHL rolling force as a moment pair at every loaded "
        "ball / raceway contact) and `ball_drag` (drag of each ball in the oil-air mixture, oil volume "
        "fraction 0.05) of both dynamic engines against the quasi-static loss report of the same case "
        "(docs/theory/losses.md, \"In the dynamic engines\"), and their cost (switches off against on, run "
        "in turn, medians).",
        [("losses_dynamic.png", "EHL rolling, hysteresis and drag power of both engines against the "
                                "quasi-static report, per case.")],
        last_lines=30)


if __name__ == "__main__":
    main()
