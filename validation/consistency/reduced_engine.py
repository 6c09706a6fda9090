"""The reduced engine against the reference engine: steady states and cost (docs/theory/reduced.md).

The cases, both engines in this session, without cage unless named, traction over the Hertz ellipse
(each bearing's default traction model and lubricant):

* the 6208 radial, the DEM papers' case: F_r = 3000 N, 500 rad/s, from the analytic start;
* the 6208 under thrust: F_a = 3000 N, 500 rad/s, from the quasi-static start (control 'equilibrium'); every
  ball is loaded alike, so both engines are also compared with the quasi-static traction equilibrium;
* the high-speed case: Gupta's ACBB-120 at 25,000 rpm under F_a = 22,240 N (cageless as its source, its
  catalogue lubricant and EHL traction, the inner ring growing with speed, as
  validation/consistency/highspeed_acbb120.py), 40 ms from the quasi-static race-control (Jones) start, so
  that both engines move to the steady state rather than start on it; compared with the reference engine and
  with the quasi-static traction equilibrium;
* the 6208 radial with its rigid cage (its estimated cage, outer-land guided), 0.5 s (cage_speed: the
  cage's);
* a transient: the 6208 under thrust, run up from rest to 500 rad/s in 20 ms (:func:`runup`).

Printed per case and engine: Q_max inner / outer at psi = 0 (the steady value, the mean load of the balls
passing psi = 0, summary q_psi0_*, with the criterion; and the window's sampled peak, q_max_*, without one: the
reduced engine leaves out the contacts' vibration, whose peaks the reference engine's q_max_* include), the
contact angles, the mean orbital speed of the
balls (the summary's cage_speed), the dissipation and the drive power of the summary window (the second half of
the run), the energy residual, the step and the steps taken (the reduced engine: its force evaluations and
Newton iterations per step); then the differences of the reduced engine from the reference engine against the
criteria (loads 0.5 %, contact angles 0.1 deg, orbital speeds 0.2 %, dissipation 1 %) and those of the peaks
and the drive power (no criterion), and the wall time per
simulated second of each engine (median of ``--repeats`` runs; the integration alone, the compiled kernels
loaded before the clock starts) and their ratio. ``--dt`` lists the reduced engine's steps (default 2e-5, 4e-5
and 1e-4 s, the largest step a Scenario takes); the reference engine takes 2e-6 s. ``--case`` runs the cases
whose name contains one of its words (the run-up with "run-up"); ``--jac-every`` and ``--ring-every`` set
how long the reduced engine keeps its Jacobians (:data:`exudyn_bearing.solvers.reduced.engine.JAC_EVERY`,
``RING_EVERY``: fewer force evaluations per step, at the accuracy the printout shows). In the cases compared
with the quasi-static equilibrium the reference engine also runs once at 1 and 0.5 us, untimed (its difference
from the equilibrium shrinks with its step: its step error). ``--tolerance`` adds runs of the reduced engine
under its step error control (``Scenario.tolerance``, first step 20 us; docs/theory/reduced.md, "Step error
control"), one per tolerance, with the steps they took.

    python validation/consistency/reduced_engine.py [--repeats 3] [--dt 2e-5 4e-5 1e-4] [--quick] [--case ACBB]
        [--jac-every 2] [--ring-every 1] [--tolerance 1e-5 1e-6]
"""
from __future__ import annotations

import argparse
import statistics
import warnings

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.model.stability import SimulationError
from exudyn_bearing.simulate import quasistatic_start
from exudyn_bearing.solvers.reduced import engine as reduced

#: name: (bearing, scenario fields (over COMMON), simulated time [s], compared with the quasi-static traction
#: equilibrium); the ACBB-120 sampled as highspeed_acbb120.py (at the 100 us step a sample every step would add
#: a force evaluation to each)
CASES = {
    "6208 radial (Fr 3000 N, 500 rad/s)": ("6208", dict(Fr=3000.0, omega=500.0), 0.06, False),
    "6208 thrust (Fa 3000 N, 500 rad/s)": ("6208", dict(Fa=3000.0, omega=500.0, initial="quasistatic",
                                                        control="equilibrium"), 0.02, True),
    "ACBB-120 thrust (Fa 22240 N, 25000 rpm)": ("ACBB-120", dict(Fa=22240.0, omega=2618.0, ring_growth=True,
                                                                 initial="quasistatic", control="outer",
                                                                 sample_dt=5e-4), 0.04, True),
    # the rigid cage (the 6208's estimated, outer-land guided): its cage whirls irregularly in the land clearance
    # in both engines, so 0.5 s, the summary over the second half averaging the whirl
    "6208 radial, rigid cage (Fr 3000 N, 500 rad/s)": ("6208", dict(Fr=3000.0, omega=500.0, cage="rigid"), 0.5,
                                                       False),
    # the same with the pockets' oil film (Scenario.pocket_film): the film's forces through the shared kernel, 0.2 s
    "6208 radial, rigid cage, pocket film (Fr 3000 N, 500 rad/s)": ("6208", dict(Fr=3000.0, omega=500.0, cage="rigid",
                                                                             pocket_film=True), 0.2, False),
    # the caged 7208 under combined load (the rigid cage's check case): its lightly loaded balls leave and
    # re-enter the load zone, from the caged quasi-static equilibrium, 0.1 s
    "7208 combined, rigid cage (Fr = Fa = 3000 N, 500 rad/s)": ("7208", dict(Fr=3000.0, Fa=3000.0, omega=500.0,
                                                                          cage="rigid", initial="quasistatic",
                                                                          control="equilibrium"), 0.1, False),
}
COMMON = dict(cage="none", traction_level="ellipse", sample_dt=1e-4)
#: The reference engine's step of a case whose stable step is below REFERENCE_DT (the caged 7208 at the ellipse
#: level: 1.7 us, set by its regularised friction)
CASE_REFERENCE_DT = {"7208 combined, rigid cage (Fr = Fa = 3000 N, 500 rad/s)": 1.5e-6}
REFERENCE_DT = 2e-6
#: Finer steps of the reference engine in the cases compared with the quasi-static equilibrium (one run each,
#: untimed): whether the reference engine's difference from it is its own step error.
FINE_REFERENCE_DT = (1e-6, 5e-7)
#: The criteria (relative): loads, orbital speeds, dissipation.
#: The loads' criterion is on the steady Q_max, the mean load of the balls passing psi = 0 over the window
#: (summary q_psi0_*): the reduced engine leaves out the contacts' vibration, which the reference engine resolves
#: and its sampled peak q_max_* includes (the caged 7208's pocket impacts set its rings ringing: its peak lies
#: 1.1 % above its passes' mean, where the reduced engine's lies 0.5 % above at 20 us: the report's run).
CRITERIA = {"q_psi0_inner": 0.005, "q_psi0_outer": 0.005, "cage_speed": 0.002, "dissipation": 0.01}
#: Differences printed without a criterion: the sampled peaks of the loads and the drive power.
INFO_KEYS = ("q_max_inner", "q_max_outer", "drive_power")
#: The criteria of the contact angles (absolute) [deg].
ANGLE_CRITERIA = {"alpha_inner": 0.1, "alpha_outer": 0.1}
#: The run-up's check: the mean orbital speed within RUNUP_TOL of the reference engine's from RUNUP_FROM [s] on
#: (the cage's first revolution ends near 40 ms; the check starts a quarter into the ramp).
RUNUP_TOL = 0.02
RUNUP_FROM = 0.005
#: The first step of the runs under the step error control [s].
ADAPTIVE_FIRST_DT = 2e-5
KEYS = ("q_psi0_inner", "q_psi0_outer", "q_max_inner", "q_max_outer", "alpha_inner", "alpha_outer", "cage_speed",
        "dissipation", "drive_power", "energy_residual")


def run(bearing, fields, t_end, engine, dt, tolerance=None):
    sc = eb.Scenario(**{**COMMON, **fields}, t_end=t_end, dt=dt, tolerance=tolerance)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = eb.simulate(bearing, sc, engine=engine)
        return res, res.summary(fraction=0.5)


def quasistatic_equilibrium(bearing, fields):
    """The quasi-static traction equilibrium of a case (control 'equilibrium', the inner ring's tilt held, the
    traction model, lubricant and ring growth of the dynamic engines:
    :func:`exudyn_bearing.simulate.quasistatic_start`),
    as the summary's keys: Q_max (steady: q_psi0_* and q_max_* alike), contact angles [deg] and orbital speed of
    ball 0 (every ball alike under
    thrust), the bearing's dissipation."""
    sc = eb.Scenario(**{**COMMON, **fields, "initial": "quasistatic", "control": "equilibrium"}, t_end=1e-3, dt=1e-5)
    sol = quasistatic_start(bearing, sc)["static"]
    b = sol.balls
    return {"q_psi0_inner": sol.q_max_inner, "q_psi0_outer": sol.q_max_outer,
            "q_max_inner": sol.q_max_inner, "q_max_outer": sol.q_max_outer,
            "alpha_inner": float(np.degrees(b["alpha_inner"][0])),
            "alpha_outer": float(np.degrees(b["alpha_outer"][0])),
            "cage_speed": float(b["orbital_speed"][0]), "dissipation": sol.dissipation_total}


def differences(s, ref, failed, what, check=True):
    """The printed differences of summary ``s`` from ``ref`` against the criteria (relative, angles absolute);
    the failed ones appended to ``failed`` as ``what`` and the key (when ``check``)."""
    parts = []
    for k, tol in {**CRITERIA, **ANGLE_CRITERIA}.items():
        if k in ANGLE_CRITERIA:
            d = s[k] - ref[k]
            text = f"{k} {d:+.4f} deg"
        else:
            d = (s[k] - ref[k]) / ref[k]
            text = f"{k} {100 * d:+.4f} %"
        ok = abs(d) <= tol
        if check and not ok:
            failed.append(f"{what} {k}")
        tol_text = f"{tol:g} deg" if k in ANGLE_CRITERIA else f"{100 * tol:g} %"
        parts.append(text + (f" ({'ok' if ok else 'FAILS'} {tol_text})" if check else ""))
    return parts


def info_text(s, ref):
    """The differences of the :data:`INFO_KEYS` (no criterion)."""
    return "  ".join(f"{k} {100 * (s[k] - ref[k]) / ref[k]:+.3f} %" for k in INFO_KEYS) + " (no criterion)"


def runs_of(dts, tolerances, reference_dt=REFERENCE_DT):
    """(engine, dt, tolerance, tag) of the runs of a case: the reference engine (at ``reference_dt``), the reduced
    engine at each step, then under its step control at each tolerance (first step ADAPTIVE_FIRST_DT)."""
    return ([("reference", reference_dt, None, f"reference dt={reference_dt:g}")]
            + [("reduced", d, None, f"reduced dt={d:g}") for d in dts]
            + [("reduced", ADAPTIVE_FIRST_DT, t, f"reduced tol={t:g}") for t in tolerances])


def repeated(call, repeats, tol, tag, failed, what):
    """(the last result, its summary, the median wall time per simulated second) of ``repeats`` runs of
    ``call`` (returning (result, summary)); None when the step control stops at a tolerance it cannot hold:
    said, appended to ``failed`` as ``what`` and ``tag``, and the other runs go on (a fixed step re-raises)."""
    walls = []
    try:
        for _ in range(repeats):
            res, summary = call()
            walls.append(res.wall_s / float(res.t[-1]))
    except SimulationError as exc:
        if tol is None:
            raise
        print(f"{tag:>22}: stopped: {exc}")
        failed.append(f"{what} {tag} stopped")
        return None
    return res, summary, statistics.median(walls)


def steps_text(res):
    """The steps a run under the step control took (empty for a fixed step)."""
    w = getattr(res.record, "reduced_stats", None)
    if not w or w.get("tolerance") is None:
        return ""
    return (f"  steps {res.steps} (rejected {w['steps_rejected']}, restarts {w['restarts']}; dt min / median / max "
            f"{w['dt_min'] * 1e6:.3g} / {w['dt_median'] * 1e6:.3g} / {w['dt_max'] * 1e6:.3g} us)")


def runup(dts, repeats, tolerances=()):
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
    for engine, dt, tol, tag in runs_of(dts, tolerances):
        def one():
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                res = eb.simulate("6208", eb.Scenario.papers_protocol(**fields, dt=dt, tolerance=tol), engine=engine)
            return res, None
        done = repeated(one, repeats, tol, tag, failed, "run-up")
        if done is None:
            continue
        res, _, wall = done
        runs[tag] = (res.t, res.cage_speed_series(), wall, steps_text(res))
    t, ref, ref_wall, _ = runs[f"reference dt={REFERENCE_DT:g}"]
    late = t >= RUNUP_FROM
    for tag, (t2, speed, wall, steps) in runs.items():
        if tag.startswith("reference"):
            print(f"{tag:>22}: wall/simulated s {wall:.3g}")
            continue
        rel = (np.interp(t, t2, speed) - ref) / ref
        worst = float(np.max(np.abs(rel[late])))
        ok = worst <= RUNUP_TOL
        if not ok:
            failed.append(f"run-up {tag}")
        k = int(np.argmax(np.abs(rel) * late))
        print(f"{tag:>22}: largest |difference| {100 * worst:.3f} % at {1e3 * t[k]:.1f} ms "
              f"({'ok' if ok else 'FAILS'} {100 * RUNUP_TOL:g} %)  wall/simulated s {wall:.3g} "
              f"(reference/reduced {ref_wall / wall:.3g}){steps}")
    return failed


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeats", type=int, default=3, help="timed runs per engine and case (median)")
    ap.add_argument("--dt", type=float, nargs="+", default=[2e-5, 4e-5, 1e-4], help="steps of the reduced engine [s]")
    ap.add_argument("--quick", action="store_true", help="one run each")
    ap.add_argument("--jac-every", type=int, default=None,
                    help=f"the reduced engine's JAC_EVERY (steps a Jacobian is kept; default {reduced.JAC_EVERY})")
    ap.add_argument("--ring-every", type=int, default=None,
                    help=f"the reduced engine's RING_EVERY (default {reduced.RING_EVERY})")
    ap.add_argument("--tolerance", type=float, nargs="+", default=[],
                    help="also the reduced engine under its step error control at these tolerances")
    ap.add_argument("--case", nargs="+", default=None,
                    help="run only the cases whose name contains one of these words ('run-up': the transient)")
    args = ap.parse_args(argv)
    repeats = 1 if args.quick else max(1, args.repeats)
    if args.jac_every is not None or args.ring_every is not None:  # the engines built below take them
        reduced.JAC_EVERY = args.jac_every or reduced.JAC_EVERY
        reduced.RING_EVERY = args.ring_every or reduced.RING_EVERY
        print(f"reduced engine: Jacobians kept for up to JAC_EVERY = {reduced.JAC_EVERY} steps, the ring's at every "
              f"RING_EVERY = {reduced.RING_EVERY}-th retaking")

    def chosen(name):
        return args.case is None or any(w.lower() in name.lower() for w in args.case)

    failed = []
    for name, (bearing, fields, t_end, with_qs) in CASES.items():
        if not chosen(name):
            continue
        print(f"\n== {name}, {t_end:g} s simulated, summary over the second half")
        rows = {}
        walls = {}
        reference_dt = CASE_REFERENCE_DT.get(name, REFERENCE_DT)
        for engine, dt, tol, tag in runs_of(args.dt, args.tolerance, reference_dt):
            done = repeated(lambda: run(bearing, fields, t_end, engine, dt, tol), repeats, tol, tag, failed, name)
            if done is None:
                continue
            res, s, walls[tag] = done
            rows[tag] = s
            stats = getattr(res.record, "reduced_stats", None)
            work = (f"  force evaluations/step {stats['evaluations_per_step']:.3g}  Newton iterations/step "
                    f"{stats['newton_per_step']:.3g} (most {stats['newton_max']}, unconverged steps "
                    f"{stats['unconverged_steps']})") if stats else ""
            print(f"{tag:>22}: " + "  ".join(f"{k} {s[k]:.6g}" if s[k] is not None else f"{k} -" for k in KEYS)
                  + f"  steps {s['steps']}  wall/simulated s {walls[tag]:.3g}{work}{steps_text(res)}")
        ref_tag = f"reference dt={reference_dt:g}"
        ref = rows[ref_tag]
        for tag, s in rows.items():
            if tag == ref_tag:
                continue
            parts = differences(s, ref, failed, f"{name} {tag}")
            print(f"{tag:>22} - reference: " + "  ".join(parts) + "  " + info_text(s, ref))
            print(f"{'':>22}   cost: {walls[tag]:.3g} s per simulated second against {walls[ref_tag]:.3g} "
                  f"(reference/reduced {walls[ref_tag] / walls[tag]:.3g}); median of {repeats}")
        if with_qs:  # every ball loaded alike: the quasi-static traction equilibrium is the steady state
            qs_vals = quasistatic_equilibrium(bearing, fields)
            print(f"{'quasi-static':>22}: " + "  ".join(f"{k} {v:.6g}" for k, v in qs_vals.items())
                  + " (traction equilibrium, control='equilibrium', tilt held)")
            for dt in FINE_REFERENCE_DT:
                rows[f"reference dt={dt:g}"] = run(bearing, fields, t_end, "reference", dt)[1]
            for tag, s in rows.items():
                parts = differences(s, qs_vals, failed, f"{name} {tag} against the quasi-static equilibrium",
                                    check=tag.startswith("reduced"))
                print(f"{tag:>22} - quasi-static: " + "  ".join(parts))
    if chosen("run-up"):
        failed += runup(args.dt, repeats, args.tolerance)
    print("\nall criteria hold" if not failed else "\nFAILS: " + "; ".join(failed))
    return 1 if failed else 0


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced."""
    return run.printed(
        "The reduced engine against the reference engine",
        "The reduced engine (ball centres on their normal force balance, linearly implicit step; "
        "docs/theory/reduced.md) against the reference engine on the 6208 radial (the DEM papers' case), the 6208 "
        "under 3 kN thrust, the 6208 radial with its rigid cage and the ACBB-120 at 25,000 rpm under 22,240 N "
        "thrust (from the race-control start), without cage unless named, traction over the ellipse: Q_max (the "
        "steady value, the mean load of the balls passing psi = 0, with the criterion; the sampled peak without), "
        "contact angles, orbital speed, dissipation and drive power, the criteria (0.5 %, 0.1 deg, 0.2 %, 1 %), under thrust also against the quasi-static traction "
        "equilibrium, a thrust run-up, and the wall time per simulated second of both engines "
        "in one session (medians).", last_lines=120)


if __name__ == "__main__":
    raise SystemExit(main())
