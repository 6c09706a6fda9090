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
``--tolerance`` adds runs of the reduced engine under its step error control (``Scenario.tolerance``, first
step 20 us; docs/theory/reduced.md, "Step error control"), one per tolerance, with the steps they took (rejected,
least / median / largest step).

    python validation/performance/reduced_work_precision.py [--repeat 3] [--tolerance 1e-5 3e-6 1e-6]

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
#: The first step of the runs under the step error control [s].
ADAPTIVE_FIRST_DT = 2e-5


def run(engine, dt, tolerance=None):
    """One run: (summary over the second half, wall time per simulated second); ``tolerance`` the reduced
    engine's step error control (dt its first step)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = eb.simulate("6208", eb.Scenario(**FIELDS, t_end=T_END, dt=dt, tolerance=tolerance), engine=engine)
        return res.summary(fraction=0.5), res.wall_s / T_END


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3, help="timed runs per engine and step (median)")
    ap.add_argument("--tolerance", type=float, nargs="+", default=[],
                    help="also the reduced engine under its step error control at these tolerances")
    args = ap.parse_args(argv)
    OUT.mkdir(exist_ok=True)
    print(f"6208, Fr {FIELDS['Fr']:g} N, {FIELDS['omega']:g} rad/s, no cage, ellipse traction, {T_END:g} s, summary "
          f"over the second half; error against the {FINE[0]} engine at {FINE[1] * 1e6:g} us; wall per simulated "
          f"second: median of {args.repeat}")
    fine, fine_wall = run(*FINE)
    print(f"  fine reference {FINE[1] * 1e6:g} us: " + "  ".join(f"{k} {fine[k]:.7g}" for k in KEYS)
          + f"  wall/simulated s {fine_wall:.3g}")
    rows = []
    for engine, dt, tol in [(e, h, None) for e, h in RUNS] + [("reduced", ADAPTIVE_FIRST_DT, t) for t in args.tolerance]:
        walls, s = [], None
        name = f"{dt * 1e6:5g} us" if tol is None else f"tolerance {tol:g}"
        try:
            for _ in range(max(1, args.repeat)):
                s, w = run(engine, dt, tol)
                walls.append(w)
        except (SimulationError, InputError) as e:
            print(f"  {engine:9s} {name}: left out ({type(e).__name__}: {str(e)[:120]})")
            continue
        err = {k: abs(s[k] / fine[k] - 1.0) for k in KEYS}
        wall = statistics.median(walls)
        row = {"engine": engine if tol is None else "reduced, step control", "dt": dt, "tolerance": tol,
               "wall_per_s": wall, "steps": s["steps"], **{f"err_{k}": v for k, v in err.items()},
               **{k: s[k] for k in KEYS}}
        steps = ""
        if tol is not None:
            w_ = s["reduced_work"]
            row.update({k: w_[k] for k in ("steps_rejected", "restarts", "dt_min", "dt_median", "dt_max")})
            steps = (f"  steps {s['steps']} (rejected {w_['steps_rejected']}, restarts {w_['restarts']}; dt min / "
                     f"median / max {w_['dt_min'] * 1e6:.3g} / {w_['dt_median'] * 1e6:.3g} / "
                     f"{w_['dt_max'] * 1e6:.3g} us)")
        rows.append(row)
        print(f"  {engine:9s} {name}: wall/simulated s {wall:7.3g}  errors: "
              + "  ".join(f"{k} {100 * err[k]:.3g} %" for k in KEYS) + steps)
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
        for engine, mark in (("reference", "o"), ("reduced", "s"), ("reduced, step control", "^")):
            sel = [r for r in rows if r["engine"] == engine]
            if not sel:
                continue
            ax.loglog([r["wall_per_s"] for r in sel], [max(r[f"err_{key}"], 1e-9) for r in sel], marker=mark,
                      label=f"{engine} engine" if engine != "reduced, step control" else "reduced engine, tolerance")
            for r in sel:
                label = f"{r['dt'] * 1e6:g} us" if r["tolerance"] is None else f"tol {r['tolerance']:g}"
                ax.annotate(label, (r["wall_per_s"], max(r[f"err_{key}"], 1e-9)), fontsize=7,
                            xytext=(3, 3), textcoords="offset points")
        ax.set_xlabel("wall time per simulated second [s] (median)")
        ax.set_ylabel(f"relative error of the {name}")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    fig.suptitle(f"6208, {FIELDS['Fr']:g} N radial, {FIELDS['omega']:g} rad/s, no cage, traction over the ellipse: "
                 f"steady state against the reference engine at {FINE[1] * 1e6:g} us", fontsize=9)
    codes = {"reference": 0, "reduced": 1, "reduced, step control": 2}
    cols = {"engine": [codes[r["engine"]] for r in rows], "dt_s": [r["dt"] for r in rows],
            "tolerance": [r["tolerance"] or 0.0 for r in rows], "steps": [r["steps"] for r in rows],
            "wall_per_simulated_s": [r["wall_per_s"] for r in rows]}
    cols.update({f"err_{k}": [r[f"err_{k}"] for r in rows] for k in KEYS})
    save_figure(fig, OUT / "reduced_work_precision.png", cols)
    report = {"fine": {"engine": FINE[0], "dt": FINE[1], "wall_per_s": fine_wall, **{k: fine[k] for k in KEYS}},
              "runs": rows, "repeat": args.repeat, "t_end": T_END, "fields": FIELDS}
    (OUT / "reduced_work_precision.json").write_text(json.dumps(report, indent=1, default=float))
    print(f"written {OUT / 'reduced_work_precision.png'} (.csv: engine 0 reference, 1 reduced, 2 reduced under the "
          f"step control; tolerance 0: the fixed step) and .json")
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
