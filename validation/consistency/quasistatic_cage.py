"""The quasi-static solver with the rigid cage against the reference engine's (docs/theory/quasistatic.md).

The 7208 under F_r = F_a = 3000 N at 500 rad/s, the estimated outer-land-guided brass cage
(``estimated_cage``: pocket friction 0.1) in both:

* quasi-static: ``solve_quasistatic(..., control="equilibrium", cage="rigid")`` (tilts held, as the
  command line and the dynamic engines' translating ring), and without the cage for reference;
* reference engine (DEM): ``Scenario(cage="rigid", traction_level="ellipse", initial="quasistatic",
  control="equilibrium", cage_damping="implicit")`` at each step of ``--dt`` for ``--t-end``, summaries
  over the default window (the last part of the run, named in the output).

and the orbit march on the caged quasi-static solution (``march_orbit``: one ball followed along its orbit
with its inertia, docs/theory/quasistatic.md#the-orbit-march).

Printed side by side: the dissipation (the quasi-static traction + pocket + land; the DEM's ``dissipation``,
which also holds the contacts' normal damping), the cage speed, the cage losses by kind, the pocket and land
forces, Q_max. The target: the two dissipations within 5 %. ``--land-feedback``: the quasi-static cage's
displacement on its land fed back into the pocket play (docs/theory/quasistatic.md#the-cages-displacement).

With ``--pocket-film`` instead the ball / pocket oil film (docs/theory/quasistatic.md#the-pocket-film): the
6208 radial case (F_r = 3000 N, 500 rad/s, its estimated rigid cage, the scenario's oil), quasi-static
(``solve_quasistatic(..., cage="rigid", pocket_film=...)``) and reference engine (``Scenario(...,
pocket_film=...)``, the settings above, its quasi-static start with the film) each dry and with the film, at the
first ``--dt``: the cage speed, the pocket loss (and the film's part), the land loss and the dissipation side by
side, and the differences of the quasi-static solution with the film from the engine's.

    python validation/consistency/quasistatic_cage.py [--t-end 0.5] [--dt 1.5e-6 0.75e-6] [--case FR FA ...]
        [--land-feedback] [--out validation/out/quasistatic_cage]
    python validation/consistency/quasistatic_cage.py --pocket-film [--t-end 0.2] [--dt 1.5e-6]
    python validation/consistency/quasistatic_cage.py --cost REPEATS [--case FR FA ...]

``--cost``: the quasi-static solve's wall time without and with ``--land-feedback`` (medians of REPEATS runs),
on the 6208 radial case, the 7208 case above and each ``--case``; no DEM.
"""
from __future__ import annotations

import argparse
import json
import time
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.solvers.quasistatic import solve_quasistatic
from exudyn_bearing.solvers.quasistatic.losses import power_losses
from exudyn_bearing.outputs.plotting_quasistatic import plot_orbit_march
from exudyn_bearing.solvers.quasistatic.orbit import march_orbit

ROOT = Path(__file__).resolve().parents[2]
CASE = {"Fr": 3000.0, "Fa": 3000.0, "omega": 500.0}
#: The pocket film's case (--pocket-film): the papers' 6208 radial case.
FILM_CASE = {"Fr": 3000.0, "Fa": 0.0, "omega": 500.0}
#: Azimuth bins of the per-azimuth comparison [deg].
BINS = np.linspace(-180.0, 180.0, 13)


def orbit_march(s):
    """The orbit march on the caged solution ``s`` (docs/theory/quasistatic.md#the-orbit-march), in the keys of
    :func:`quasistatic`."""
    t0 = time.perf_counter()
    m = march_orbit(s)
    return {"march": m, "wall_s": time.perf_counter() - t0, "dissipation": m["dissipation"],
            "dissipation_contacts": m["dissipation_contacts"], "cage_power_pocket": m["power_pocket"],
            "cage_power_land": m["power_land"], "cage_speed": m["cage_speed"], "land_force": m["land_force"],
            "pocket_force_max": float(np.max(np.abs(m["profile"]["pocket_force"]))),
            "pocket_force_mean": float(np.mean(np.abs(m["profile"]["pocket_force"]))),
            "q_max_inner": float(np.max(m["profile"]["q_inner"])), "q_max_outer": float(np.max(m["profile"]["q_outer"])),
            "energy_residual": m["energy_residual"], "drive_power": m["drive_power"],
            "pocket_contact_fraction": m["pocket_contact_fraction"], "steps_per_revolution": m["steps_per_revolution"],
            "revolutions": m["revolutions"]}


def quasistatic(cage, case=CASE, bearing="7208", pocket_film=False, land_feedback=False, march=False):
    t0 = time.perf_counter()
    s = solve_quasistatic(bearing, case["Fr"], case["Fa"], omega=case["omega"], control="equilibrium", cage=cage,
                          fixed={"tilt_x": 0.0, "tilt_y": 0.0}, stiffness=False, pocket_film=pocket_film,
                          land_feedback=land_feedback)
    wall = time.perf_counter() - t0
    pl = power_losses(s)["power_loss"]
    c = s.cage or {}
    by = {race: {"psi": np.degrees(np.angle(np.exp(1j * s.balls["psi"]))).tolist(),
                 "load": s.balls[f"q_{race}"].tolist(), "dissipation": s.balls[f"dissipation_{race}_ball"].tolist()}
          for race in ("inner", "outer")}
    return {"by_ball": by, "wall_s": wall, "dissipation": s.dissipation_total + pl["cage_pocket"] + pl["cage_land"],
            "dissipation_contacts": s.dissipation_total, "cage_power_pocket": pl["cage_pocket"],
            "cage_power_land": pl["cage_land"], "cage_power_pocket_film": power_losses(s)["cage_pocket_film"],
            "cage_speed": c.get("speed", float(np.mean(s.kinematics[:, 0]))),
            "orbital_speed_min": float(np.min(s.kinematics[:, 0])), "orbital_speed_max": float(np.max(s.kinematics[:, 0])),
            "pocket_force_max": float(np.max(np.abs(s.balls.get("pocket_force", [0.0])))),
            "pocket_force_mean": float(np.mean(np.abs(s.balls.get("pocket_force", [0.0])))),
            "land_force": c.get("land_force"), "land_eccentricity": c.get("land_eccentricity"),
            "q_max_inner": s.q_max_inner, "q_max_outer": s.q_max_outer, "energy_residual": s.energy_residual,
            "torque_residual": c.get("torque_residual"),
            "land_feedback_converged": c.get("land_feedback_converged"),
            "land_feedback_roots": c.get("land_feedback_roots"),
            # the solver's own check of the balls' inertia along the orbit (solvers/quasistatic/inertia.py)
            "inertia_power": (s.inertia_check or {}).get("power"), "inertia_share": (s.inertia_check or {}).get("share"),
            "orbit_march": orbit_march(s) if march else None}


def dem(dt, t_end, case=CASE, bearing="7208", pocket_film=False):
    sc = eb.Scenario(**case, cage="rigid", traction_level="ellipse", initial="quasistatic", control="equilibrium",
                     cage_damping="implicit", dt=dt, t_end=t_end, sample_dt=1e-4, pocket_film=pocket_film)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        t0 = time.perf_counter()
        rec = eb.simulate(bearing, sc, progress=False)
        wall = time.perf_counter() - t0
    s = rec.summary()
    keys = ("dissipation", "cage_speed", "cage_power_pocket", "cage_power_land", "pocket_force_max",
            "pocket_force_mean", "land_force_mean", "land_eccentricity_max", "q_max_inner", "q_max_outer",
            "energy_residual")
    out = {k: s.get(k) for k in keys}
    window = s.get("window") or {}
    out["window.t0"], out["window.t1"] = window.get("t0"), window.get("t1")
    out["power_loss"] = s.get("power_loss")
    pl = out["power_loss"] or {}
    out["dissipation_contacts"] = pl.get("contact_traction_inner", 0.0) + pl.get("contact_traction_outer", 0.0)
    out["wall_s"] = wall
    # per azimuth (30 deg bins, over the summary's window): the contacts' load, dissipation and slide-to-roll ratio
    r = rec if hasattr(rec, "contact") else rec.results
    w = r.window(0.25)
    psi = np.degrees(r.azimuth()[w]).ravel()
    idx = np.digitize(psi, BINS)
    out["by_azimuth"] = {race: {f: [float(np.mean(r.contact(f, race)[w].ravel()[idx == k])) for k in range(1, len(BINS))]
                                for f in ("load", "dissipation", "srr")} for race in ("inner", "outer")}
    return out


def film_comparison(dt, t_end, out):
    """--pocket-film: the 6208 radial case dry and with the pocket film, quasi-static and reference engine."""
    report = {"case": FILM_CASE, "bearing": "6208", "t_end_s": t_end, "dt_s": dt}
    for film in (False, True):
        tag = "film" if film else "dry"
        report[f"quasistatic_{tag}"] = quasistatic("rigid", FILM_CASE, "6208", film)
        report[f"dem_{tag}"] = dem(dt, t_end, FILM_CASE, "6208", film)
        print(f"DEM {tag} done ({report[f'dem_{tag}']['wall_s']:.0f} s wall)", flush=True)
    cols = ("quasistatic_dry", "dem_dry", "quasistatic_film", "dem_film")
    print(f"6208, F_r = 3000 N, 500 rad/s, estimated rigid cage, pockets dry and with the oil film; DEM at dt = "
          f"{dt:g} s for {t_end:g} s, window " + ", ".join(f"{report[c]['window.t0']:.3g}-{report[c]['window.t1']:.3g} s"
                                                          for c in ("dem_dry", "dem_film")))
    rows = ("dissipation", "dissipation_contacts", "cage_power_pocket", "cage_power_pocket_film", "cage_power_land",
            "cage_speed", "pocket_force_max", "pocket_force_mean", "q_max_inner", "energy_residual")
    print(f"{'':24s}" + "".join(f"{c:>18s}" for c in cols))
    for r in rows:
        print(f"{r:24s}" + "".join(f"{report[c].get(r) if report[c].get(r) is not None else float('nan'):18.5g}"
                                   for c in cols))
    for tag in ("dry", "film"):
        q, d = report[f"quasistatic_{tag}"], report[f"dem_{tag}"]
        diff = {k: q[k] / d[k] - 1.0 for k in ("cage_speed", "cage_power_pocket", "cage_power_land", "dissipation")}
        report[f"quasistatic_over_dem_minus_1_{tag}"] = diff
        print(f"{tag}: quasi-static / DEM - 1: cage speed {100 * diff['cage_speed']:+.3f} %, pocket loss "
              f"{100 * diff['cage_power_pocket']:+.1f} %, land loss {100 * diff['cage_power_land']:+.1f} %, "
              f"dissipation {100 * diff['dissipation']:+.1f} %")
    for src in ("quasistatic", "dem"):
        print(f"the film's change (film - dry), {src}: pocket loss "
              f"{report[f'{src}_film']['cage_power_pocket'] - report[f'{src}_dry']['cage_power_pocket']:+.3f} W, "
              f"dissipation {report[f'{src}_film']['dissipation'] - report[f'{src}_dry']['dissipation']:+.3f} W, "
              f"cage speed {report[f'{src}_film']['cage_speed'] - report[f'{src}_dry']['cage_speed']:+.4f} rad/s")
    (out / "quasistatic_cage_film.json").write_text(json.dumps(report, indent=2, default=float))
    print(f"wrote {out / 'quasistatic_cage_film.json'}")


def cost(repeats, cases, out):
    """--cost: the quasi-static solve's wall time without and with the land feedback (medians of ``repeats``
    runs, alternating, after one solve that loads the compiled kernels) and the feedback's state."""
    quasistatic("rigid", FILM_CASE, "6208")
    report = []
    for bearing, case in cases:
        runs = {False: [], True: []}
        for _ in range(repeats):
            for fb in (False, True):
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    q = quasistatic("rigid", case, bearing, land_feedback=fb)
                runs[fb].append(q["wall_s"])
        off, on = float(np.median(runs[False])), float(np.median(runs[True]))
        report.append({"bearing": bearing, "case": case, "wall_s_without": runs[False], "wall_s_with": runs[True],
                       "land_feedback_converged": q["land_feedback_converged"],
                       "land_feedback_roots": q["land_feedback_roots"]})
        print(f"{bearing} F_r {case['Fr']:g} N, F_a {case['Fa']:g} N: QS solve without the land feedback {off:.2f} s, "
              f"with {on:.2f} s (x{on / off:.1f}; medians of {repeats}); with: converged "
              f"{q['land_feedback_converged']}, roots {q['land_feedback_roots']}", flush=True)
    (out / "quasistatic_cage_cost.json").write_text(json.dumps(report, indent=2, default=float))
    print(f"wrote {out / 'quasistatic_cage_cost.json'}")


def land_line(q, d):
    """The cage on its land, quasi-static (steady) against the DEM (over its window): the land force [N] (the
    DEM's mean), the eccentricity (the DEM's largest), the quasi-static solve's wall time and, with the
    feedback, its displacement's roots at the solution."""
    return (f"land force QS {q['land_force']:.3g} / DEM mean {d['land_force_mean']:.3g} N, eccentricity QS "
            f"{q['land_eccentricity']:.3g} / DEM max {d['land_eccentricity_max']:.3g}; QS solve {q['wall_s']:.1f} s"
            + ("" if q.get("land_feedback_roots") in (None, 1) else
               f"; the displacement has {q['land_feedback_roots']} roots at the QS solution"))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--t-end", type=float, default=0.5, help="simulated time of each DEM run [s]")
    ap.add_argument("--dt", type=float, nargs="+", default=[1.5e-6, 0.75e-6], help="DEM steps [s]")
    ap.add_argument("--case", type=float, nargs=2, action="append", metavar=("FR", "FA"),
                    help="a further load case [N] (repeatable), e.g. --case 0 3000 --case 3000 10000")
    ap.add_argument("--pocket-film", action="store_true",
                    help="instead: the 6208 radial case dry and with the pocket oil film, quasi-static and DEM at the "
                         "first --dt")
    ap.add_argument("--land-feedback", action="store_true",
                    help="the quasi-static cage's displacement on its land fed back into the pocket play "
                         "(solve_quasistatic(..., land_feedback=True)); the DEM is the same")
    ap.add_argument("--cost", type=int, metavar="REPEATS",
                    help="instead: the quasi-static solve's wall time without and with --land-feedback, medians of "
                         "REPEATS runs each (alternating), on the 6208 radial case (F_r = 3000 N, its estimated "
                         "cage), the 7208 case above and each --case; no DEM")
    ap.add_argument("--out", default=str(ROOT / "validation" / "out" / "quasistatic_cage"))
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    if args.pocket_film:
        return film_comparison(args.dt[0], args.t_end, out)
    if args.cost:
        return cost(args.cost, [("6208", FILM_CASE), ("7208", CASE)]
                    + [("7208", {"Fr": fr, "Fa": fa, "omega": CASE["omega"]}) for fr, fa in args.case or []], out)
    report = {"case": CASE, "t_end_s": args.t_end, "quasistatic_cageless": quasistatic(None),
              "quasistatic_rigid": quasistatic("rigid", land_feedback=args.land_feedback, march=True),
              "land_feedback": args.land_feedback}
    report["orbit_march"] = report["quasistatic_rigid"]["orbit_march"]
    for dt in args.dt:
        report[f"dem_rigid_{dt:g}"] = dem(dt, args.t_end)
        print(f"DEM at dt = {dt:g} s done ({report[f'dem_rigid_{dt:g}']['wall_s']:.0f} s wall)", flush=True)
    cols = ["quasistatic_cageless", "quasistatic_rigid", "orbit_march"] + [f"dem_rigid_{dt:g}" for dt in args.dt]
    rows = ("dissipation", "dissipation_contacts", "cage_power_pocket", "cage_power_land", "cage_speed", "pocket_force_max",
            "pocket_force_mean", "q_max_inner", "q_max_outer", "energy_residual")
    print(f"7208, F_r = F_a = 3000 N, 500 rad/s, estimated outer-land brass cage"
          + (" (quasi-static: the cage's displacement fed back into the pocket play)" if args.land_feedback else "")
          + f"; DEM {args.t_end} s, window "
          + ", ".join(f"{report[c]['window.t0']:.3g}-{report[c]['window.t1']:.3g} s" for c in cols[3:])
          + f"; orbit march {report['orbit_march']['steps_per_revolution']} steps per revolution, last of "
            f"{report['orbit_march']['revolutions']}")
    print(f"{'':20s}" + "".join(f"{c:>22s}" for c in cols))
    print(land_line(report["quasistatic_rigid"], report[cols[-1]]))
    for r in rows:
        print(f"{r:20s}" + "".join(f"{report[c].get(r) if report[c].get(r) is not None else float('nan'):22.5g}"
                                   for c in cols))
    q = report["quasistatic_rigid"]["dissipation"]
    qm = report["orbit_march"]["dissipation"]
    for c in cols[3:]:
        d = report[c]["dissipation"]
        report[c]["quasistatic_over_dem_minus_1"] = q / d - 1.0
        report[c]["orbit_march_over_dem_minus_1"] = qm / d - 1.0
        print(f"quasistatic (rigid cage) / {c} - 1 in the dissipation: {100 * (q / d - 1.0):+.2f} %, orbit march "
              f"{100 * (qm / d - 1.0):+.2f} % (target 5 %)")
    last = cols[-1]
    print(f"per azimuth, {last} (mean per contact over the window) and the quasi-static rigid-cage balls:")
    for race in ("inner", "outer"):
        a = report[last]["by_azimuth"][race]
        for k in range(len(BINS) - 1):
            print(f"  {race} psi {BINS[k]:5.0f} .. {BINS[k + 1]:4.0f} deg: DEM Q {a['load'][k]:7.1f} N, "
                  f"P {a['dissipation'][k]:6.3f} W, srr {a['srr'][k]:+.3f}")
        q = report["quasistatic_rigid"]["by_ball"][race]
        print(f"  quasi-static {race}: " + ", ".join(f"psi {p:.0f}: Q {x:.1f} N P {y:.3f} W"
                                                    for p, x, y in zip(q["psi"], q["load"], q["dissipation"])))
    # further load cases (--case FR FA): the dissipation and its parts, quasi-static against the DEM at the
    # first --dt
    report["cases"] = []
    for fr, fa in args.case or []:
        case = {"Fr": fr, "Fa": fa, "omega": CASE["omega"]}
        q = quasistatic("rigid", case, land_feedback=args.land_feedback, march=True)
        d = dem(args.dt[0], args.t_end, case)
        report["cases"].append({"case": case, "quasistatic_rigid": q, "dem": d})
        m = q["orbit_march"]
        print(f"F_r {fr:g} N, F_a {fa:g} N: dissipation QS {q['dissipation']:.2f} / DEM {d['dissipation']:.2f} W "
              f"({100 * (q['dissipation'] / d['dissipation'] - 1):+.1f} %); contacts {q['dissipation_contacts']:.2f} / "
              f"{d['dissipation_contacts']:.2f}, pocket {q['cage_power_pocket']:.2f} / {d['cage_power_pocket']:.2f}, "
              f"land {q['cage_power_land']:.2f} / {d['cage_power_land']:.2f} W; cage {q['cage_speed']:.3f} / "
              f"{d['cage_speed']:.3f} rad/s; QS ball-inertia check {q['inertia_power']:.3g} W "
              f"({100 * q['inertia_share']:.3g} % of its dissipation); orbit march: dissipation {m['dissipation']:.2f} W "
              f"({100 * (m['dissipation'] / d['dissipation'] - 1):+.1f} %), contacts {m['dissipation_contacts']:.2f}, "
              f"pocket {m['cage_power_pocket']:.2f}, land {m['cage_power_land']:.2f} W, cage {m['cage_speed']:.3f} "
              f"rad/s, energy residual {m['energy_residual']:.2g}; " + land_line(q, d)
              + ("" if q["land_feedback_converged"] in (None, True) else
                 "; the cage's displacement did NOT converge: the quasi-static row is the solution without it"),
              flush=True)
    # the marched ball's dissipation along its orbit against the DEM's per azimuth (inner + outer contact: per ball)
    a = report[last]["by_azimuth"]
    march = report["orbit_march"].pop("march")
    qs = report["quasistatic_rigid"]["by_ball"]
    png = plot_orbit_march(march, out / "quasistatic_cage_orbit.png", {
        "quasi-static solution": (qs["inner"]["psi"], np.add(qs["inner"]["dissipation"], qs["outer"]["dissipation"])),
        f"DEM ({last}, window mean per 30 deg)": (0.5 * (BINS[:-1] + BINS[1:]),
                                                  np.add(a["inner"]["dissipation"], a["outer"]["dissipation"]))})
    print(f"wrote {png} (and its CSV)")
    for c in report["cases"]:
        c["quasistatic_rigid"]["orbit_march"].pop("march")
    (out / "quasistatic_cage.json").write_text(json.dumps(report, indent=2, default=float))
    print(f"wrote {out / 'quasistatic_cage.json'}")


if __name__ == "__main__":
    main()
