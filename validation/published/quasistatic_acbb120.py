"""The ACBB-120 of Gupta (2020) at 25,000 rpm under 22,240 N thrust, cageless: race control against
minimum energy, rigid against growing rings, dissipation against beta, slip along both contacts, and a
combined radial + moment case against azimuth.

    python validation/published/quasistatic_acbb120.py

Writes validation/out/quasistatic_acbb120.json and PNG + CSV plots beside it. The traction models are
the catalogue's ``ester_curve_illustrative`` (the form of Gupta's traction curve, parameters NOT his
Fig. 6, which is not available) and ``ehl_mil_l_23699_492K`` (this project's EHL parameters); the film
thicknesses use the ``MIL-L-23699_492K`` lubricant.
"""
import json
import math
from pathlib import Path

import numpy as np

from exudyn_bearing.outputs.plotting_quasistatic import plot_dissipation_beta, plot_loads_angles, plot_slip
from exudyn_bearing.solvers.quasistatic import solve_quasistatic
from exudyn_bearing.solvers.quasistatic import kinematics as km
from exudyn_bearing.solvers.quasistatic.solve import beta_scan

OUT = Path(__file__).resolve().parents[1] / "out"
W = 25000 * math.pi / 30
FA = 22240.0
LUB = "MIL-L-23699_492K"
TRACTIONS = ("ester_curve_illustrative", "ehl_mil_l_23699_492K")


def row(s):
    b = s.balls
    return {"alpha_inner_deg": math.degrees(b["alpha_inner"][0]), "alpha_outer_deg": math.degrees(b["alpha_outer"][0]),
            "q_inner_N": float(b["q_inner"][0]), "q_outer_N": float(b["q_outer"][0]),
            "p_max_inner_GPa": float(b["p_max_inner"][0]) / 1e9, "p_max_outer_GPa": float(b["p_max_outer"][0]) / 1e9,
            "centrifugal_force_N": float(b["centrifugal_force"][0]),
            "gyroscopic_moment_Nm": float(b["gyroscopic_moment"][0]),
            "orbital_speed_rad_s": float(b["orbital_speed"][0]), "ball_speed_rad_s": float(b["ball_speed"][0]),
            "beta_deg": math.degrees(b["beta"][0]), "spin_roll_inner": float(b["spin_roll_inner"][0]),
            "spin_roll_outer": float(b["spin_roll_outer"][0]),
            "x1_over_a_outer": float(b["rolling_point_outer"][0] / b["a_outer"][0]),
            "x2_over_a_inner": float(b["rolling_point_inner"][0] / b["a_inner"][0]),
            "dissipation_inner_W": s.dissipation_inner, "dissipation_outer_W": s.dissipation_outer,
            "dissipation_total_W": s.dissipation_total,
            "qv_total": float(np.sum(b["qv_inner_ball"]) + np.sum(b["qv_outer_ball"])),
            "traction_drag_N": float(b["traction_drag"][0]),
            "gyro_traction_inner": float(b["gyro_traction_inner"][0]),
            "gyro_traction_outer": float(b["gyro_traction_outer"][0]),
            "h_central_inner_um": float(b["h_central_inner"][0]) * 1e6,
            "h_central_outer_um": float(b["h_central_outer"][0]) * 1e6,
            "delta_a_um": float(s.displacement[2]) * 1e6, "inner_ring_growth_um": s.geometry["inner_ring_growth"] * 1e6,
            "operating_clearance_um": s.geometry["operating_clearance"] * 1e6,
            "control_used": str(b["control_used"][0]), "iterations": s.iterations, "wall_s": s.wall_s,
            "k_axial_N_per_m": float(s.stiffness[2, 2]),
            "stiffness_half_step_change": s.stiffness_check.get("relative_change_half_step"),
            "minimum_check": s.minimum_checks[0] if s.minimum_checks else None}


def main():
    OUT.mkdir(exist_ok=True)
    res = {"case": {"bearing": "ACBB-120", "rpm": 25000, "omega_rad_s": W, "Fa_N": FA, "lubricant": LUB,
                    "cageless": True}, "tractions": {}}
    sols = {}
    for tr in TRACTIONS:
        d = {}
        for label, kw in (("rigid_race_control", dict(control="auto", ring_growth=False)),
                          ("race_control", dict(control="auto")),
                          ("outer_control", dict(control="outer")),
                          ("inner_control", dict(control="inner")),
                          ("min_energy", dict(control="min-energy")),
                          ("rigid_min_energy", dict(control="min-energy", ring_growth=False)),
                          ("min_energy_492K", dict(control="min-energy",
                                                   temperatures={"inner": 492.0, "outer": 492.0, "ball": 492.0}))):
            s = solve_quasistatic("ACBB-120", 0.0, FA, omega=W, traction=tr, lubricant=LUB, **kw)
            sols[(tr, label)] = s
            d[label] = row(s)
            print(f"{tr:28s} {label:20s} alpha_i {d[label]['alpha_inner_deg']:6.2f} alpha_o "
                  f"{d[label]['alpha_outer_deg']:6.2f} beta {d[label]['beta_deg']:6.3f} "
                  f"P {d[label]['dissipation_total_W']:8.1f} W  ({d[label]['control_used']}, "
                  f"{d[label]['wall_s']:.2f} s)")
        d["min_energy_change"] = d["min_energy"]["dissipation_total_W"] / d["race_control"]["dissipation_total_W"] - 1
        print(f"{tr}: minimum energy changes the total dissipation by {100 * d['min_energy_change']:+.1f} % "
              f"against race control ({d['race_control']['control_used']})")
        # dissipation against beta on the minimum-energy geometry (Gupta's Fig. 9 / 17), ball 0
        me = sols[(tr, "min_energy")]
        rc = sols[(tr, "race_control")]
        b_me = float(me.balls["beta"][0])
        b_rc = float(rc.balls["beta"][0])
        lo, hi = min(b_me, b_rc) - math.radians(3), max(b_me, b_rc) + math.radians(3)
        betas = np.linspace(lo, hi, 41)
        q = beta_scan(me, betas, ball=0)
        geo = me.contact_geometry[0]
        k_rc = km.race_control(geo, "outer")
        q_rc_here = float(km.ball_contacts(k_rc, geo, me.traction_model, me.n_strips, me.n_across)[:, 9].sum())
        points = {"outer-race control (same contact geometry)": (math.degrees(km.spin_axis_angle(k_rc[1], k_rc[2])),
                                                                 q_rc_here),
                  "minimum energy": (math.degrees(b_me), float(me.balls["dissipation_inner_ball"][0]
                                                              + me.balls["dissipation_outer_ball"][0]))}
        png = plot_dissipation_beta(np.degrees(betas), q, points, OUT / f"qs_acbb120_beta_{tr}.png",
                                    title=f"ACBB-120, 25,000 rpm, 22,240 N, traction {tr}")
        d["beta_scan"] = {"beta_deg": np.degrees(betas).tolist(), "dissipation_ball_W": q.tolist(),
                          "points": {k: list(v) for k, v in points.items()}, "plot": str(png)}
        d["plot_slip"] = str(plot_slip({"outer-race control": rc, "minimum energy": me},
                                       OUT / f"qs_acbb120_slip_{tr}.png"))
        res["tractions"][tr] = d
    tr0 = TRACTIONS[0]
    conv = []
    for ns, na in ((16, 2), (32, 4), (64, 8), (128, 8)):
        p = [solve_quasistatic("ACBB-120", 0.0, FA, omega=W, traction=tr0, lubricant=LUB, control=c, n_strips=ns,
                               n_across=na, stiffness=False).dissipation_total for c in ("outer", "min-energy")]
        conv.append({"n_strips": ns, "n_across": na, "race_control_W": p[0], "min_energy_W": p[1],
                     "change": p[1] / p[0] - 1})
        print(f"strips {ns:3d} x {na}: race control {p[0]:.1f} W, minimum energy {p[1]:.1f} W ({100 * (p[1] / p[0] - 1):+.2f} %)")
    res["strip_convergence"] = conv
    res["plot_rigid_vs_growing"] = str(plot_loads_angles(
        {"rigid rings": sols[(tr0, "rigid_race_control")], "growing rings": sols[(tr0, "race_control")]},
        OUT / "qs_acbb120_rigid_vs_growing.png"))
    # a combined radial + moment case: loads and contact angles against azimuth (the tilt free: a moment load
    # needs it, solve_quasistatic holds it by default)
    comb = {}
    for label, kw in (("thrust only", dict()), ("Fr 3 kN + My 150 N m", dict(Fr=3000.0, My=150.0))):
        comb[label] = solve_quasistatic("ACBB-120", kw.get("Fr", 0.0), FA, 0.0, kw.get("My", 0.0), omega=W,
                                        traction=tr0, lubricant=LUB, control="auto", fixed={})
    s = comb["Fr 3 kN + My 150 N m"]
    res["combined"] = {"displacement": s.displacement.tolist(), "held": s.held,
                       "q_inner_N": s.balls["q_inner"].tolist(), "q_outer_N": s.balls["q_outer"].tolist(),
                       "alpha_inner_deg": np.degrees(s.balls["alpha_inner"]).tolist(),
                       "alpha_outer_deg": np.degrees(s.balls["alpha_outer"]).tolist(),
                       "orbital_speed_rad_s": s.balls["orbital_speed"].tolist(),
                       "control_used": [str(c) for c in s.balls["control_used"]],
                       "dissipation_total_W": s.dissipation_total,
                       "stiffness_asymmetry": s.stiffness_check["asymmetry"], "wall_s": s.wall_s,
                       "plot": str(plot_loads_angles(comb, OUT / "qs_acbb120_combined.png"))}
    print(f"combined: delta = {np.round(s.displacement * 1e6, 3).tolist()} (um, urad), q_inner "
          f"{s.balls['q_inner'].min():.0f}..{s.balls['q_inner'].max():.0f} N, controls "
          f"{sorted(set(res['combined']['control_used']))}")
    (OUT / "quasistatic_acbb120.json").write_text(json.dumps(res, indent=2, default=float))
    print(f"wrote {OUT / 'quasistatic_acbb120.json'}")


def report_section(run):
    """The report's section on the quasi-static ACBB-120, from quasistatic_acbb120.json and its figures
    (bench_quasistatic.py's part, the solver's speed, follows it)."""
    from exudyn_bearing.physics.contact_slip import DEFAULT_N_ACROSS, DEFAULT_N_STRIPS

    d = run.load("quasistatic_acbb120.json")
    lines = ["## Quasi-static solver: the ACBB-120 of Gupta (2020)", "",
             f"Command: `{run.command}` (solver: `solve_quasistatic`). ACBB-120, "
             "25,000 rpm, 22,240 N thrust, cageless, M-50, films with the MIL-L-23699 entry at 492 K. Traction: "
             "`ester_curve_illustrative` (the form of Gupta's traction curve with illustrative parameters, not his "
             "Fig. 6) and `ehl_mil_l_23699_492K` (this project's EHL parameters). Ball 0 (all balls are equal).", "",
             "| traction | case | control | alpha_i [deg] | alpha_o [deg] | Q_i [N] | Q_o [N] | omega_m [rad/s] | "
             "omega_b [rad/s] | beta [deg] | spin/roll i | spin/roll o | P_i [W] | P_o [W] | P total [W] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for tr, v in d["tractions"].items():
        for case in ("rigid_race_control", "race_control", "inner_control", "min_energy", "rigid_min_energy",
                     "min_energy_492K"):
            r = v[case]
            lines.append(f"| {tr} | {case} | {r['control_used']} | {r['alpha_inner_deg']:.2f} | "
                         f"{r['alpha_outer_deg']:.2f} | {r['q_inner_N']:.0f} | {r['q_outer_N']:.0f} | "
                         f"{r['orbital_speed_rad_s']:.1f} | {r['ball_speed_rad_s']:.0f} | {r['beta_deg']:.3f} | "
                         f"{r['spin_roll_inner']:.4f} | {r['spin_roll_outer']:.4f} | {r['dissipation_inner_W']:.0f} | "
                         f"{r['dissipation_outer_W']:.0f} | {r['dissipation_total_W']:.0f} |")
    lines.append("")
    for tr, v in d["tractions"].items():
        me = v["min_energy"]
        lines.append(f"- {tr}: minimum energy changes the total dissipation by **{100 * v['min_energy_change']:+.1f} %** "
                     f"against race control ({v['race_control']['control_used']} race by Jones' criterion; Gupta "
                     f"reports about -24 % with his traction curve); minimum check: Hessian eigenvalues "
                     f"{', '.join(f'{x:.3g}' for x in me['minimum_check']['hessian_eigenvalues'])}, neighbours higher "
                     f"{me['minimum_check']['neighbours_higher']}; pure-rolling points x1/a = "
                     f"{me['x1_over_a_outer']:.3f} (outer), x2/a = {me['x2_over_a_inner']:.3f} (inner); net rolling-"
                     f"direction traction on a ball (zero in a cageless steady state) {v['race_control']['traction_drag_N']:.1f} N "
                     f"under race control, {me['traction_drag_N']:.1f} N under minimum energy; traction coefficient "
                     f"the outer race must supply for the gyroscopic moment under race control "
                     f"{v['race_control']['gyro_traction_outer']:.4f}. Plots: "
                     f"`{Path(v['beta_scan']['plot']).name}`, `{Path(v['plot_slip']).name}`.")
    cv = d["strip_convergence"]
    lines.append(f"- Strip integration (default {DEFAULT_N_STRIPS} strips x {DEFAULT_N_ACROSS} points): total dissipation with the curve, race control / "
                 "minimum energy: " + "; ".join(f"{c['n_strips']}x{c['n_across']}: {c['race_control_W']:.1f} / "
                                                f"{c['min_energy_W']:.1f} W ({100 * c['change']:+.2f} %)" for c in cv)
                 + ".")
    rc, rg = d["tractions"]["ester_curve_illustrative"]["rigid_race_control"], \
        d["tractions"]["ester_curve_illustrative"]["race_control"]
    c = d["combined"]
    lines += [f"- Inner-ring growth at 25,000 rpm: {rg['inner_ring_growth_um']:.1f} um (rotating annular disc); "
              f"contact angles rigid -> growing rings: inner {rc['alpha_inner_deg']:.2f} -> {rg['alpha_inner_deg']:.2f}"
              f" deg, outer {rc['alpha_outer_deg']:.2f} -> {rg['alpha_outer_deg']:.2f} deg "
              "(`qs_acbb120_rigid_vs_growing.png`).",
              f"- Combined case F_r = 3 kN, M_y = 150 N m with the thrust: tilt_y = {c['displacement'][4] * 1e3:.3f} "
              f"mrad, inner loads {min(c['q_inner_N']):.0f} to {max(c['q_inner_N']):.0f} N, inner contact angles "
              f"{min(c['alpha_inner_deg']):.1f} to {max(c['alpha_inner_deg']):.1f} deg (`qs_acbb120_combined.png`).",
              ""]
    for tr, v in d["tractions"].items():
        lines += run.figure(Path(v["beta_scan"]["plot"]).name, f"Dissipation of one ball against the spin-axis angle "
                            f"beta with traction {tr}: the least dissipation at each fixed beta, the race-control "
                            "solution and the minimum-energy solution.")
        lines += run.figure(Path(v["plot_slip"]).name, f"Slip of ball 0 against its race along the major axis of the "
                            f"outer (left) and inner (right) contact ellipse, race control and minimum energy, traction "
                            f"{tr}.")
    lines += run.figure("qs_acbb120_rigid_vs_growing.png", "Contact loads (left) and contact angles (right) of all balls "
                        "against azimuth with rigid and with growing rings.")
    lines += run.figure("qs_acbb120_combined.png", "Contact loads (left) and contact angles (right) against azimuth under "
                        "the thrust alone and with F_r = 3 kN and M_y = 150 N m added.")
    return "\n".join(lines)


if __name__ == "__main__":
    main()
