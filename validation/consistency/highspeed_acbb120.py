"""High-speed dynamics with traction over the contact ellipse, against the quasi-static solutions.

Scene: the ACBB-120 of Gupta (2020) (15 balls, cageless) at 25,000 rpm under
22,240 N thrust, its own oil (MIL-L-23699 at its test temperature, catalogue
``MIL-L-23699_492K``), the inner ring growing with speed, traction integrated
over each Hertz ellipse (the solvers' default strips x points across) with
two traction models of the catalogue:
the illustrative traction curve and the EHL model with shear thinning and a
limiting shear stress (docs/theory/quasistatic.md). For each model:

* quasi-static solutions: outer-race control (Jones), minimum energy
  (Gupta) and traction equilibrium (the ball's steady Newton-Euler equations
  with the traction of both contacts, yaw pivoting for the gyroscopic moment:
  no kinematic hypothesis);
* dynamic runs of 40 ms at dt = 2 us started from the race-control and the
  minimum-energy solution, in the reference engine (both models) and the
  Exudyn element (EHL model);
* the steady state (last 5 ms) against the three quasi-static solutions:
  contact loads, contact angles, orbital and ball speed, beta, spin-to-roll
  ratios and dissipation; spin-to-roll ratios and dissipation against time
  from both starts (the form of Gupta's Figs. 15 and 16).

Also: the 6208 under 3000 N thrust at 500 rad/s from the analytic and the
rest start with the point-contact and the ellipse traction level (one
steady state or two), and the DEM papers' 6208 radial case (3000 N,
500 rad/s) at both levels (how much the papers' numbers move).

    python validation/consistency/highspeed_acbb120.py      # about 1-2 minutes

Writes validation/out/highspeed.json and PNG + CSV plots.
"""
from __future__ import annotations

import json
import time
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.model.layout import D_ANGLE, D_LOAD, D_POWER, D_ROLL, D_SPIN
from exudyn_bearing.outputs.contact_summary import spin_axis_angles
from exudyn_bearing.outputs.jsonio import to_jsonable
from exudyn_bearing.outputs.plotting import pyplot, save_figure
from exudyn_bearing.physics.contact_slip import DEFAULT_N_ACROSS, DEFAULT_N_STRIPS
from exudyn_bearing.simulate import quasistatic_start
from exudyn_bearing.solvers.element.engine import ExudynEngine
from exudyn_bearing.solvers.reference import ReferenceEngine

OUT = Path(__file__).resolve().parents[1] / "out"
LUBRICANT = "MIL-L-23699_492K"
MODELS = ("ehl_mil_l_23699_492K", "ester_curve_illustrative")
T_END, DT = 0.04, 2e-6
KEYS = ("q_inner", "q_outer", "alpha_inner", "alpha_outer", "orbital_speed", "ball_speed", "beta",
        "spin_roll_inner", "spin_roll_outer", "dissipation")


def acbb_scenario(traction, control):
    return eb.Scenario(Fa=22240.0, Fr=0.0, omega=2618.0, t_end=T_END, dt=DT, cage=False, traction_level="ellipse",
                       traction=traction, ring_growth=True, initial="quasistatic",
                       control=control, sample_dt=5e-4)


def qs_values(sol) -> dict:
    """Ball 0 of a quasi-static solution (all balls alike under thrust); dissipation of the bearing."""
    b = sol.balls
    return {"q_inner": b["q_inner"][0], "q_outer": b["q_outer"][0], "alpha_inner": np.degrees(b["alpha_inner"][0]),
            "alpha_outer": np.degrees(b["alpha_outer"][0]), "orbital_speed": b["orbital_speed"][0],
            "ball_speed": b["ball_speed"][0], "beta": np.degrees(b["beta"][0]),
            "spin_roll_inner": b["spin_roll_inner"][0], "spin_roll_outer": b["spin_roll_outer"][0],
            "dissipation": sol.dissipation_total}


def series(data) -> dict:
    """Per-sample means over the balls (speeds, beta, spin-to-roll ratios) and the bearing's dissipation."""
    d = data["diag"]
    xb, vb, wb = data["xb"], data["vb"], data["wb"]
    r2 = xb[..., 0] ** 2 + xb[..., 1] ** 2
    wm = (xb[..., 0] * vb[..., 1] - xb[..., 1] * vb[..., 0]) / r2
    w = wb.copy()
    w[..., 2] -= wm
    return {"t": data["t"], "q_inner": d[:, :, 0, D_LOAD].mean(1), "q_outer": d[:, :, 1, D_LOAD].mean(1),
            "alpha_inner": np.degrees(d[:, :, 0, D_ANGLE]).mean(1), "alpha_outer": np.degrees(d[:, :, 1, D_ANGLE]).mean(1),
            "orbital_speed": wm.mean(1), "ball_speed": np.linalg.norm(w, axis=-1).mean(1),
            "beta": np.degrees(spin_axis_angles(data)).mean(1),
            "spin_roll_inner": (d[:, :, 0, D_SPIN] / np.abs(d[:, :, 0, D_ROLL])).mean(1),
            "spin_roll_outer": (d[:, :, 1, D_SPIN] / np.abs(d[:, :, 1, D_ROLL])).mean(1),
            "dissipation": d[:, :, :, D_POWER].sum(axis=(1, 2))}


def steady(s: dict) -> dict:
    sel = s["t"] >= T_END - 5e-3
    return {k: float(np.mean(s[k][sel])) for k in KEYS}


def compare(dyn: dict, ref: dict) -> dict:
    """Differences: relative for loads, speeds and dissipation, absolute [deg] for angles, absolute for ratios."""
    out = {}
    for k in KEYS:
        if k in ("alpha_inner", "alpha_outer", "beta") or k.startswith("spin_roll"):
            out[k] = dyn[k] - ref[k]
        else:
            out[k] = dyn[k] / ref[k] - 1.0
    return out


def run_acbb():
    res = {}
    for model in MODELS:
        entry = {"quasistatic": {}, "dynamic": {}}
        starts = {}
        for control in ("outer", "min-energy", "equilibrium"):
            t0 = time.perf_counter()
            start = quasistatic_start("ACBB-120", acbb_scenario(model, control), eb.load_lubricant(LUBRICANT))
            starts[control] = start
            entry["quasistatic"][control] = dict(qs_values(start["static"]), wall_s=time.perf_counter() - t0)
        engines = (("reference", ReferenceEngine), ("exudyn", ExudynEngine)) if model == MODELS[0] else \
            (("reference", ReferenceEngine),)
        for engine, cls in engines:
            for control in ("outer", "min-energy"):
                t0 = time.perf_counter()
                rec = cls("ACBB-120", acbb_scenario(model, control), eb.load_lubricant(LUBRICANT),
                          start=starts[control]).run()
                s = series(rec.data)
                st = steady(s)
                name = f"{engine}, {control} start"
                entry["dynamic"][name] = {
                    "steady": st, "wall_s": time.perf_counter() - t0,
                    "vs_equilibrium": compare(st, entry["quasistatic"]["equilibrium"]),
                    "vs_min_energy": compare(st, entry["quasistatic"]["min-energy"]),
                    "series": {k: s[k] for k in ("t", "spin_roll_inner", "spin_roll_outer", "dissipation", "beta")}}
                print(f"{model}, {name}: {st}", flush=True)
        res[model] = entry
        plot_histories(model, entry)
    return res


def plot_histories(model, entry):
    plt = pyplot()
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    cols = {}
    for i, (name, d) in enumerate(entry["dynamic"].items()):
        s = d["series"]
        t = np.asarray(s["t"]) * 1e3
        for a, key in zip(ax, ("spin_roll_outer", "spin_roll_inner", "dissipation")):
            a.plot(t, s[key], color=f"C{i}", label=name)
        cols[f"t_ms_{i}"] = t
        for key in ("spin_roll_outer", "spin_roll_inner", "dissipation"):
            cols[f"{key}_{i}"] = s[key]
    for a, key, label in zip(ax, ("spin_roll_outer", "spin_roll_inner", "dissipation"),
                             ("spin-to-roll ratio, outer race", "spin-to-roll ratio, inner race",
                              "frictional dissipation, whole bearing [W]")):
        for control, ls in (("outer", ":"), ("min-energy", "--"), ("equilibrium", "-")):
            q = entry["quasistatic"][control]
            a.axhline(q[key], color="k", ls=ls, lw=0.8, label=f"quasi-static, {control}")
        a.set_xlabel("t [ms]")
        a.set_ylabel(label)
        a.grid(alpha=0.3)
    ax[2].legend(fontsize=7, loc="upper right")
    fig.suptitle(f"ACBB-120, 25,000 rpm, 22,240 N, {LUBRICANT}, traction {model} ({DEFAULT_N_STRIPS} x "
                 f"{DEFAULT_N_ACROSS} points): dynamics from two quasi-static starts")
    save_figure(fig, OUT / f"highspeed_acbb120_{model}.png", cols, trim=True)


def run_6208_axial():
    out = {}
    for level in ("point", "ellipse"):
        for initial in ("analytic", "rest"):
            sc = eb.Scenario(Fr=0.0, Fa=3000.0, omega=500.0, t_end=0.1, dt=1.5e-6, tangential="implicit",
                             traction_level=level, initial=initial, sample_dt=1e-3)
            s = eb.simulate("6208", sc).summary(t_window=(0.08, 0.1))
            out[f"{level}, {initial}"] = {k: s[k] for k in ("cage_speed", "ball_spin", "beta", "dissipation_inner",
                                                            "dissipation_outer")}
            print(f"6208 axial, {level}, {initial}: {out[f'{level}, {initial}']}", flush=True)
    sol = eb.solve_quasistatic("6208", Fa=3000.0, omega=500.0, control="equilibrium", stiffness=False)
    out["quasistatic equilibrium"] = {"orbital_speed": float(sol.balls["orbital_speed"][0]),
                                      "ball_spin": float(sol.balls["ball_speed_absolute"][0]),
                                      "beta": float(np.degrees(sol.balls["beta"][0]))}
    return out


def run_6208_papers():
    out = {}
    for level in ("point", "ellipse"):
        sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.05, dt=1.5e-6, tangential="implicit", traction_level=level,
                         sample_dt=1e-4)
        s = eb.simulate("6208", sc).summary(t_window=(0.025, 0.05))
        out[level] = {k: s[k] for k in ("q_max_inner", "q_max_outer", "cage_speed", "ball_spin", "lambda_outer_psi0",
                                        "friction_power", "dissipation_inner", "dissipation_outer")}
        print(f"6208 radial, {level}: {out[level]}", flush=True)
    return out


def main():
    OUT.mkdir(exist_ok=True)
    warnings.simplefilter("ignore")
    report = {"acbb120": run_acbb(), "6208_axial": run_6208_axial(), "6208_papers": run_6208_papers(),
              "settings": {"t_end": T_END, "dt": DT, "lubricant": LUBRICANT, "n_strips": DEFAULT_N_STRIPS,
                           "n_across": DEFAULT_N_ACROSS}}
    (OUT / "highspeed.json").write_text(json.dumps(to_jsonable(report), indent=1))
    print(f"written {OUT / 'highspeed.json'}")


def report_section(run):
    """The report's section on high-speed dynamics, from highspeed.json and its figures
    (bench_traction.py's part, the cost and strip count, follows it)."""
    d = run.load("highspeed.json")
    lines = ["## High-speed dynamics: traction over the contact ellipse", "",
             f"Command: `{run.command}` (both engines; ACBB-120 of Gupta 2020, 25,000 rpm, "
             "22,240 N thrust, cageless, growing inner ring, traction over each ellipse with 16 strips, "
             f"dt = {d['settings']['dt'] * 1e6:g} us, {d['settings']['t_end'] * 1e3:g} ms from a quasi-static start; "
             "steady state = mean of the last 5 ms, ball 0 for loads and ratios, the whole bearing for the "
             "dissipation). Quasi-static solutions of the same traction model: outer-race control (Jones), minimum "
             "energy (Gupta) and the traction equilibrium (the ball's steady Newton-Euler equations, yaw pivoting "
             "for the gyroscopic moment, no hypothesis; docs/theory/quasistatic.md sec. 4).", ""]
    keys = ("q_inner", "q_outer", "alpha_inner", "alpha_outer", "orbital_speed", "ball_speed", "beta",
            "spin_roll_inner", "spin_roll_outer", "dissipation")
    head = "| traction | solution | Q_i [N] | Q_o [N] | alpha_i [deg] | alpha_o [deg] | omega_m [rad/s] | " \
           "omega_b [rad/s] | beta [deg] | spin/roll i | spin/roll o | P [W] |"
    lines += [head, "|" + "---|" * 12]
    for model, e in d["acbb120"].items():
        rows = [(f"quasi-static, {c}", v) for c, v in e["quasistatic"].items()]
        rows += [(f"dynamic: {n}", v["steady"]) for n, v in e["dynamic"].items()]
        for name, v in rows:
            lines.append(f"| {model} | {name} | " + " | ".join(
                f"{v[k]:.4g}" if not k.startswith("spin") else f"{v[k]:.4f}" for k in keys) + " |")
    lines.append("")
    for model, e in d["acbb120"].items():
        worst_eq = {k: max(abs(v["vs_equilibrium"][k]) for v in e["dynamic"].values()) for k in keys}
        me = e["quasistatic"]["min-energy"]
        dyn = next(iter(e["dynamic"].values()))["steady"]
        lines.append(
            f"- {model}: every dynamic run (both starts{', both engines' if len(e['dynamic']) > 2 else ''}) settles "
            f"on one steady state, the traction equilibrium: largest differences {100 * worst_eq['q_inner']:.2f} % "
            f"(Q_i), {100 * worst_eq['q_outer']:.2f} % (Q_o), {100 * worst_eq['orbital_speed']:.3f} % (omega_m), "
            f"{100 * worst_eq['ball_speed']:.3f} % (omega_b), {100 * worst_eq['dissipation']:.2f} % (P), "
            f"{worst_eq['alpha_inner']:.3f} / {worst_eq['alpha_outer']:.3f} deg (alpha_i / alpha_o), "
            f"{worst_eq['beta']:.3f} deg (beta), {worst_eq['spin_roll_inner']:.4f} / "
            f"{worst_eq['spin_roll_outer']:.4f} (spin/roll). Against the minimum-energy solution the steady state "
            f"dissipates {dyn['dissipation'] / me['dissipation']:.2f} times as much ({dyn['dissipation']:.0f} W "
            f"against {me['dissipation']:.0f} W), its spin axis tilts {dyn['beta']:.2f} deg instead of "
            f"{me['beta']:.2f} deg and its outer spin-to-roll ratio is {dyn['spin_roll_outer']:.3f} instead of "
            f"{me['spin_roll_outer']:.3f}: the gyroscopic moment needs transverse (pivot) slip at both contacts, "
            "which the minimum-energy hypothesis does not have. Gupta's finding that the dynamics settle on the "
            "minimum-energy solution is not reproduced with this traction model; from the race-control start the "
            "dissipation rises to the steady value rather than falling to the minimum-energy one.")
    lines.append("")
    for model in d["acbb120"]:
        lines += run.figure(f"highspeed_acbb120_{model}.png", f"Spin-to-roll ratios at the outer and inner race and the "
                            f"bearing's dissipation against time from the race-control and minimum-energy starts "
                            f"(traction {model}), with the three quasi-static solutions as horizontal lines (the form "
                            "of Gupta's Figs. 15 and 16).")
    ax = d["6208_axial"]
    lines += ["6208 under 3000 N thrust at 500 rad/s, 100 ms, steady window 80-100 ms (cage speed, ball spin "
              "[rad/s], beta [deg], dissipation [W]):", "", "| level, start | cage | ball spin | beta | P_i | P_o |",
              "|---|---|---|---|---|---|"]
    for k, v in ax.items():
        if k == "quasistatic equilibrium":
            continue
        lines.append(f"| {k} | {v['cage_speed']:.2f} | {v['ball_spin']:.2f} | {v['beta']:.2f} | "
                     f"{v['dissipation_inner']:.3g} | {v['dissipation_outer']:.3g} |")
    q = ax["quasistatic equilibrium"]
    lines += ["", f"The point-contact law leaves two steady states (from the analytic and the rest start); the ellipse "
              f"level reaches one, that of the quasi-static traction equilibrium (orbital speed {q['orbital_speed']:.2f} "
              f"rad/s, ball speed {q['ball_spin']:.2f} rad/s, beta {q['beta']:.2f} deg).", ""]
    pp = d["6208_papers"]
    lines += ["The DEM papers' 6208 case (3000 N radial, 500 rad/s, 50 ms, steady window 25-50 ms) at both levels:", "",
              "| level | q_max_inner [N] | q_max_outer [N] | cage [rad/s] | ball spin [rad/s] | Lambda_out(psi=0) | "
              "P_i [W] | P_o [W] |", "|---|---|---|---|---|---|---|---|"]
    for lvl, v in pp.items():
        lines.append(f"| {lvl} | {v['q_max_inner']:.1f} | {v['q_max_outer']:.1f} | {v['cage_speed']:.3f} | "
                     f"{v['ball_spin']:.2f} | {v['lambda_outer_psi0']:.3f} | {v['dissipation_inner']:.3g} | "
                     f"{v['dissipation_outer']:.3g} |")
    lines += ["", "The papers' numbers are those of the point level (the tests keep them). The ellipse level adds the "
              "rolling friction of the curvature-induced (Heathcote) slip across each ellipse: tens of watts "
              "where the point law, with no slip at the contact centre, gives none; the cage and the ball turn "
              "slightly faster, loads and Lambda move by about 0.1 %.", ""]
    return "\n".join(lines)


if __name__ == "__main__":
    main()
