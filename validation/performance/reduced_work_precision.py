"""Work-precision of the reduced engine and the reference engine: wall time per simulated second against the
error of the steady state, both engines on one figure.

Scene: the 6208 radial steady state of validation/consistency/reduced_engine.py (the DEM papers' F_r = 3000 N,
500 rad/s, no cage, traction over the ellipse, 0.06 s from the analytic start, summary over the second half).
Reference: the reference engine at 0.5 us. Runs: the reference engine at 1, 2, 4 and 8 us (a step it refuses
or that diverges is printed and left out) and the reduced engine at 10, 20, 40 and 100 us. Error: the relative
difference of the summary's dissipation and of Q_max at the inner race (psi = 0) from the reference run's.
Wall: the integration's wall time per simulated second (the compiled kernels loaded before the clock starts),
median of --repeat runs, every run in this session. Where an engine's error stays put as its step shrinks,
the rest is not step error: for the reduced engine the reduction's own difference from the resolved
dynamics (the contact vibration left out), for the reference engine the fine reference's own step error.

    python validation/performance/reduced_work_precision.py [--repeat 3]

Writes reduced_work_precision.png/.csv (wall, errors per engine and step) and reduced_work_precision.json into
validation/out/.
"""
from __future__ import annotations

import argparse
import json
import statistics
import warnings
from pathlib import Path

import exudyn_bearing as eb
from exudyn_bearing.data import InputError
from exudyn_bearing.model.stability import SimulationError
from exudyn_bearing.outputs.plotting import pyplot, save_figure

OUT = Path(__file__).resolve().parents[1] / "out"
FIELDS = dict(Fr=3000.0, omega=500.0, cage="none", traction_level="ellipse", sample_dt=1e-4)
T_END = 0.06
FINE = ("reference", 5e-7)
RUNS = [("reference", h) for h in (1e-6, 2e-6, 4e-6, 8e-6)] + [("reduced", h) for h in (1e-5, 2e-5, 4e-5, 1e-4)]
#: summary keys whose relative error is measured (dissipation first: the figure's left panel)
KEYS = ("dissipation", "q_max_inner", "cage_speed", "drive_power")


def run(engine, dt):
    """One run: (summary over the second half, wall time per simulated second)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = eb.simulate("6208", eb.Scenario(**FIELDS, t_end=T_END, dt=dt), engine=engine)
        return res.summary(fraction=0.5), res.wall_s / T_END


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3, help="timed runs per engine and step (median)")
    args = ap.parse_args(argv)
    OUT.mkdir(exist_ok=True)
    print(f"6208, Fr {FIELDS['Fr']:g} N, {FIELDS['omega']:g} rad/s, no cage, ellipse traction, {T_END:g} s, summary "
          f"over the second half; error against the {FINE[0]} engine at {FINE[1] * 1e6:g} us; wall per simulated "
          f"second: median of {args.repeat}")
    fine, fine_wall = run(*FINE)
    print(f"  fine reference {FINE[1] * 1e6:g} us: " + "  ".join(f"{k} {fine[k]:.7g}" for k in KEYS)
          + f"  wall/simulated s {fine_wall:.3g}")
    rows = []
    for engine, dt in RUNS:
        walls, s = [], None
        try:
            for _ in range(max(1, args.repeat)):
                s, w = run(engine, dt)
                walls.append(w)
        except (SimulationError, InputError) as e:
            print(f"  {engine:9s} {dt * 1e6:5g} us: left out ({type(e).__name__}: {str(e)[:120]})")
            continue
        err = {k: abs(s[k] / fine[k] - 1.0) for k in KEYS}
        wall = statistics.median(walls)
        rows.append({"engine": engine, "dt": dt, "wall_per_s": wall, **{f"err_{k}": v for k, v in err.items()},
                     **{k: s[k] for k in KEYS}})
        print(f"  {engine:9s} {dt * 1e6:5g} us: wall/simulated s {wall:7.3g}  errors: "
              + "  ".join(f"{k} {100 * err[k]:.3g} %" for k in KEYS))
    for engine in ("reference", "reduced"):
        sel = [r for r in rows if r["engine"] == engine]
        if sel:
            e = [r["err_dissipation"] for r in sel]
            print(f"{engine}: dissipation error {100 * min(e):.3g} - {100 * max(e):.3g} % at "
                  f"{sel[0]['dt'] * 1e6:g} - {sel[-1]['dt'] * 1e6:g} us, wall/simulated s "
                  f"{min(r['wall_per_s'] for r in sel):.3g} - {max(r['wall_per_s'] for r in sel):.3g}")
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6))
    for ax, key, name in zip(axes, ("dissipation", "q_max_inner"), ("dissipation", "Q_max, inner race")):
        for engine, mark in (("reference", "o"), ("reduced", "s")):
            sel = [r for r in rows if r["engine"] == engine]
            ax.loglog([r["wall_per_s"] for r in sel], [max(r[f"err_{key}"], 1e-9) for r in sel], marker=mark,
                      label=f"{engine} engine")
            for r in sel:
                ax.annotate(f"{r['dt'] * 1e6:g} us", (r["wall_per_s"], max(r[f"err_{key}"], 1e-9)), fontsize=7,
                            xytext=(3, 3), textcoords="offset points")
        ax.set_xlabel("wall time per simulated second [s] (median)")
        ax.set_ylabel(f"relative error of the {name}")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    fig.suptitle(f"6208, {FIELDS['Fr']:g} N radial, {FIELDS['omega']:g} rad/s, no cage, traction over the ellipse: "
                 f"steady state against the reference engine at {FINE[1] * 1e6:g} us", fontsize=9)
    cols = {"engine": [0 if r["engine"] == "reference" else 1 for r in rows], "dt_s": [r["dt"] for r in rows],
            "wall_per_simulated_s": [r["wall_per_s"] for r in rows]}
    cols.update({f"err_{k}": [r[f"err_{k}"] for r in rows] for k in KEYS})
    save_figure(fig, OUT / "reduced_work_precision.png", cols)
    report = {"fine": {"engine": FINE[0], "dt": FINE[1], "wall_per_s": fine_wall, **{k: fine[k] for k in KEYS}},
              "runs": rows, "repeat": args.repeat, "t_end": T_END, "fields": FIELDS}
    (OUT / "reduced_work_precision.json").write_text(json.dumps(report, indent=1, default=float))
    print(f"written {OUT / 'reduced_work_precision.png'} (.csv: engine 0 reference, 1 reduced) and .json")
    return report


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced, with its figure."""
    return run.printed(
        "Work-precision of the reduced engine",
        "Wall time per simulated second against the error of the steady state (dissipation, Q_max, orbital "
        "speed, drive power) on the 6208 radial case without cage, traction over the ellipse, for the "
        "reference engine at 1-8 us and the reduced engine at 10-100 us, against the reference engine at "
        "0.5 us; every run in one session (medians).",
        [("reduced_work_precision.png", ("relative error of the dissipation and of Q_max against wall time per "
                                         "simulated second, per engine and step."))], last_lines=16)


if __name__ == "__main__":
    main()
