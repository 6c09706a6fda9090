"""The reduced engine against the reference engine: steady states and cost (docs/theory/reduced.md).

The cases, both engines in this session, without cage unless named, traction over the
Hertz ellipse (the DEM papers' mu(Lambda) traction model, the 6208's default):

* the 6208 radial, the DEM papers' case: F_r = 3000 N, 500 rad/s, from the analytic start;
* the 6208 under thrust: F_a = 3000 N, 500 rad/s, from the quasi-static start (control 'equilibrium'); every
  ball is loaded alike, so both engines are also compared with the quasi-static traction equilibrium;
* the 6208 radial with its rigid cage (its estimated cage, outer-land guided), 0.5 s (cage_speed: the cage's);
* a transient: the same thrust, run up from rest to 500 rad/s in 20 ms (:func:`runup`).

Printed per case and engine: Q_max inner / outer at psi = 0, the mean orbital speed of the balls (the summary's
cage_speed), the dissipation and the drive power of the summary window (the second half of the run), the
energy residual, the step and the steps taken (the reduced engine: its force evaluations and Newton
iterations per step); then the relative differences of the reduced engine from the
reference engine against the criteria (loads 0.5 %, orbital speeds 0.2 %, dissipation 1 %), and the wall time
per simulated second of each engine (median of ``--repeats`` runs; the integration alone, the compiled kernels
loaded before the clock starts) and their ratio. ``--dt`` lists the reduced engine's steps (default 2e-5, 4e-5
and 1e-4 s, the largest step a Scenario takes); the reference engine takes 2e-6 s.

    python validation/consistency/reduced_engine.py [--repeats 3] [--dt 2e-5 4e-5 1e-4] [--quick]
"""
from __future__ import annotations

import argparse
import statistics
import warnings

import numpy as np

import exudyn_bearing as eb

#: name: (scenario fields, simulated time [s], compared with the quasi-static traction equilibrium)
CASES = {
    "6208 radial (Fr 3000 N, 500 rad/s)": (dict(Fr=3000.0, omega=500.0), 0.06, False),
    "6208 thrust (Fa 3000 N, 500 rad/s)": (dict(Fa=3000.0, omega=500.0, initial="quasistatic",
                                                control="equilibrium"), 0.02, True),
    # the rigid cage (the 6208's estimated, outer-land guided): its cage whirls irregularly in the land clearance
    # in both engines, so 0.5 s, the summary over the second half averaging the whirl
    "6208 radial, rigid cage (Fr 3000 N, 500 rad/s)": (dict(Fr=3000.0, omega=500.0, cage="rigid"), 0.5, False),
}
COMMON = dict(cage="none", traction_level="ellipse", sample_dt=1e-4)
REFERENCE_DT = 2e-6
#: The criteria (relative): loads, orbital speeds, dissipation.
CRITERIA = {"q_max_inner": 0.005, "q_max_outer": 0.005, "cage_speed": 0.002, "dissipation": 0.01}
#: The run-up's check: the mean orbital speed within RUNUP_TOL of the reference engine's from RUNUP_FROM [s] on
#: (the cage's first revolution ends near 40 ms; the check starts a quarter into the ramp).
RUNUP_TOL = 0.02
RUNUP_FROM = 0.005
KEYS = ("q_max_inner", "q_max_outer", "cage_speed", "dissipation", "drive_power", "energy_residual")


def run(fields, t_end, engine, dt):
    sc = eb.Scenario(**{**COMMON, **fields}, t_end=t_end, dt=dt)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = eb.simulate("6208", sc, engine=engine)
        return res, res.summary(fraction=0.5)


def runup(dts, repeats):
    """The 6208 under 3000 N thrust run up from rest to 500 rad/s in 20 ms (the DEM papers' ramp; no cage, every
    ball loaded alike, so the balls do not collide): the balls' mean orbital speed of each reduced run against
    the reference engine's at every sample from RUNUP_FROM on (interpolated to the reference's sample times);
    returns the failed checks."""
    print(f"\n== 6208 thrust run-up 0 -> 500 rad/s in 20 ms, then 20 ms steady: mean orbital speed against the "
          f"reference engine from {1e3 * RUNUP_FROM:g} ms on (criterion {100 * RUNUP_TOL:g} %)")
    failed = []
    fields = dict(Fr=0.0, Fa=3000.0, cage="none", traction_level="ellipse", t_steady=0.02, t_ramp_down=0.0,
                  sample_dt=5e-4)
    runs = {}
    for engine, dt in [("reference", REFERENCE_DT)] + [("reduced", d) for d in dts]:
        walls = []
        for _ in range(repeats):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                res = eb.simulate("6208", eb.Scenario.papers_protocol(**fields, dt=dt), engine=engine)
            walls.append(res.wall_s / float(res.t[-1]))
        runs[(engine, dt)] = (res.t, res.cage_speed_series(), statistics.median(walls))
    t, ref, ref_wall = runs[("reference", REFERENCE_DT)]
    late = t >= RUNUP_FROM
    for (engine, dt), (t2, speed, wall) in runs.items():
        if engine == "reference":
            print(f"{'reference dt=' + format(dt, 'g'):>22}: wall/simulated s {wall:.3g}")
            continue
        rel = (np.interp(t, t2, speed) - ref) / ref
        worst = float(np.max(np.abs(rel[late])))
        ok = worst <= RUNUP_TOL
        if not ok:
            failed.append(f"run-up reduced dt={dt:g}")
        k = int(np.argmax(np.abs(rel) * late))
        print(f"{'reduced dt=' + format(dt, 'g'):>22}: largest |difference| {100 * worst:.3f} % at {1e3 * t[k]:.1f} ms "
              f"({'ok' if ok else 'FAILS'} {100 * RUNUP_TOL:g} %)  wall/simulated s {wall:.3g} "
              f"(reference/reduced {ref_wall / wall:.3g})")
    return failed


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeats", type=int, default=3, help="timed runs per engine and case (median)")
    ap.add_argument("--dt", type=float, nargs="+", default=[2e-5, 4e-5, 1e-4], help="steps of the reduced engine [s]")
    ap.add_argument("--quick", action="store_true", help="one run each")
    args = ap.parse_args(argv)
    repeats = 1 if args.quick else max(1, args.repeats)
    failed = []
    for name, (fields, t_end, with_qs) in CASES.items():
        print(f"\n== {name}, {t_end:g} s simulated, summary over the second half")
        rows = {}
        walls = {}
        for engine, dt in [("reference", REFERENCE_DT)] + [("reduced", d) for d in args.dt]:
            tag = f"{engine} dt={dt:g}"
            times = []
            for _ in range(repeats):
                res, s = run(fields, t_end, engine, dt)
                times.append(res.wall_s / t_end)
            rows[tag] = s
            walls[tag] = statistics.median(times)
            stats = getattr(res.record, "reduced_stats", None)
            work = (f"  force evaluations/step {stats['evaluations_per_step']:.3g}  Newton iterations/step "
                    f"{stats['newton_per_step']:.3g}") if stats else ""
            print(f"{tag:>22}: " + "  ".join(f"{k} {s[k]:.6g}" for k in KEYS)
                  + f"  steps {s['steps']}  wall/simulated s {walls[tag]:.3g}{work}")
        ref_tag = f"reference dt={REFERENCE_DT:g}"
        ref = rows[ref_tag]
        for tag, s in rows.items():
            if tag == ref_tag:
                continue
            parts = []
            for k, tol in CRITERIA.items():
                d = (s[k] - ref[k]) / ref[k]
                ok = abs(d) <= tol
                if not ok:
                    failed.append(f"{name} {tag} {k}")
                parts.append(f"{k} {100 * d:+.4f} % ({'ok' if ok else 'FAILS'} {100 * tol:g} %)")
            d_drive = (s["drive_power"] - ref["drive_power"]) / ref["drive_power"]
            print(f"{tag:>22} - reference: " + "  ".join(parts) + f"  drive_power {100 * d_drive:+.3f} % (no criterion)")
            print(f"{'':>22}   cost: {walls[tag]:.3g} s per simulated second against {walls[ref_tag]:.3g} "
                  f"(reference/reduced {walls[ref_tag] / walls[tag]:.3g}); median of {repeats}")
        if with_qs:  # every ball loaded alike: the quasi-static traction equilibrium is the steady state
            qs = eb.solve_quasistatic("6208", Fr=fields.get("Fr", 0.0), Fa=fields.get("Fa", 0.0), omega=fields["omega"],
                                      control="equilibrium", fixed={"tilt_x": 0.0, "tilt_y": 0.0}, stiffness=False)
            qs_vals = {"q_max_inner": qs.q_max_inner, "q_max_outer": qs.q_max_outer, "dissipation": qs.dissipation_total}
            print(f"{'quasi-static':>22}: " + "  ".join(f"{k} {v:.6g}" for k, v in qs_vals.items())
                  + " (traction equilibrium, control='equilibrium', tilt held)")
            for tag, s in rows.items():
                parts = []
                for k, v in qs_vals.items():
                    d = (s[k] - v) / v
                    ok = abs(d) <= CRITERIA[k]
                    if not ok and tag != ref_tag:
                        failed.append(f"{name} {tag} {k} against the quasi-static equilibrium")
                    parts.append(f"{k} {100 * d:+.4f} %")
                print(f"{tag:>22} - quasi-static: " + "  ".join(parts))
    failed += runup(args.dt, repeats)
    print("\nall criteria hold" if not failed else "\nFAILS: " + "; ".join(failed))
    return 1 if failed else 0


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced."""
    return run.printed(
        "The reduced engine against the reference engine",
        "The reduced engine (ball centres on their normal force balance, linearly implicit step; "
        "docs/theory/reduced.md) against the reference engine on the 6208 radial (the DEM papers' case) and "
        "under 3 kN thrust, no cage, and the 6208 radial with its rigid cage, traction over the ellipse: "
        "Q_max, orbital speed, dissipation and drive power, the criteria (0.5 %, 0.2 %, 1 %), and the wall time "
        "per simulated second of both engines in one session (medians).", last_lines=20)


if __name__ == "__main__":
    raise SystemExit(main())
