"""The 120-mm bore angular-contact ball bearing of NASA TN D-7870 with its thermal network: power loss,
temperatures and operating contact angle over speed and thrust (solve_thermal, docs/theory/thermal.md).

    python validation/published/thermal_nasa_d7870.py [--oil-flow M3_S] [--oil-inlet-temperature K]
        [--cage-guidance {ball,outer_land,inner_land} --cage-pocket-clearance M]

Prints a table and writes validation/out/thermal_nasa_d7870.csv, thermal_nasa_d7870.png (power loss,
outer-ring temperature and contact angles against speed for three thrust loads) and
thermal_nasa_d7870_components.png (losses by component and node temperatures against speed at
22 240 N).

The source: E. N. Bamberger, E. V. Zaretsky and H. Signer, "Effect of speed and load on
ultra-high-speed ball bearings," NASA TN D-7870, January 1975 (120-mm bore angular-contact ball
bearings, speeds to 25 000 rpm (3 million DN), thrust to 22 240 N, jet lubrication). What could be
retrieved of it here is its abstract (NASA TN D-7870 report page and catalogue records): bearing
temperature and power consumption increased with load and speed; the effect of load on both was
small relative to the effect of speed; the measured operating contact angles agreed with theory;
skidding grew with speed, to 6 % at 25 000 rpm. Its tables and figures (the measured power, the
ring temperatures, the contact angles, the oil flow and the oil inlet temperature) could NOT be
retrieved, so this script compares with those four statements only, not with measured numbers, and
calibrates nothing (no traction parameter is fitted: there is no measured point to fit to).

Assumed (not from the report): the geometry is the catalogue's ACBB-120 (Gupta, Tribol. Trans.
2020: 15 balls of 20.6375 mm, pitch diameter 155 mm, f_i = 0.54, f_o = 0.52, 24 deg, M-50,
cageless, zero clearance); the oil is the catalogue entry with temperature ``MIL-L-23699``; the oil
flow 6e-5 m^3/s (3.6 l/min) and the inlet temperature 394 K are assumptions of the order used for
jet-lubricated mainshaft bearing tests, changed with the flags; the traction model is the bearing's
``ehl_mil_l_23699_492K`` with the viscosity of the oil at the contact temperature; the balls orbit
through air (oil volume fraction 0: the loss module's default; the oil-air mixture of the real
bearing, not known here, would add drag); no cage by default (the catalogue's ACBB-120 has none; the
test bearing had one, of a design not retrieved): ``--cage-guidance`` with ``--cage-pocket-clearance``
adds the loss module's cage friction and the network's cage node for an assumed cage; the quasi-static
solver stays cageless, so the skidding is not compared.
"""
import argparse
import csv
import math
import time
from pathlib import Path

import numpy as np

import exudyn_bearing as eb

OUT = Path(__file__).resolve().parents[1] / "out"
RPM = (7500.0, 10000.0, 12500.0, 15000.0, 17500.0, 20000.0, 22500.0, 25000.0)
THRUST = (4448.0, 13345.0, 22240.0)  # 1000, 3000, 5000 lbf: the script's grid (the report's matrix not retrieved)


def solve_grid(oil_flow, t_in, rpms=RPM, thrusts=THRUST, cage=None):
    """The grid's thermal solutions as table rows; ``cage``: keywords of solve_thermal for a cage
    (cage_guidance, cage_pocket_clearance), none by default."""
    rows = []
    for fa in thrusts:
        prev = None
        for rpm in rpms:
            t0 = time.perf_counter()
            r = eb.solve_thermal("ACBB-120", Fa=fa, omega=rpm * math.pi / 30.0, oil_inlet_temperature=t_in,
                                 oil_flow=oil_flow, start=prev, **(cage or {}))
            prev = r
            if fa == thrusts[-1] and rpm == rpms[-1]:
                print(f"conductances at {fa:g} N, {rpm:g} rpm [W/K]: " + ", ".join(
                    f"{k} {v:.4g}" for k, v in r.conductances.items() if k != "n_balls"))
            s, pl = r.quasistatic, r.losses["power_loss"]
            rows.append({"Fa_N": fa, "rpm": rpm, "power_loss_W": r.power_loss_total,
                         **{f"{k}_W": pl[k] for k in pl if isinstance(pl[k], float)},
                         **{f"T_{k}_K": v for k, v in r.temperatures.items()},
                         "T_contact_K": r.contact_temperature,
                         "alpha_inner_deg": math.degrees(float(np.mean(s.balls["alpha_inner"]))),
                         "alpha_outer_deg": math.degrees(float(np.mean(s.balls["alpha_outer"]))),
                         "heat_out_oil_W": r.heat_out["oil"], "heat_out_ambient_W": r.heat_out["ambient"],
                         "energy_residual_W": r.energy_residual, "iterations": r.iterations,
                         "converged": r.converged, "wall_s": time.perf_counter() - t0})
    return rows


def checks(rows):
    """The report's abstract statements, tested on the computed grid."""
    out = []
    for fa in THRUST:
        rr = [r for r in rows if r["Fa_N"] == fa]
        for key, what in (("power_loss_W", "power loss"), ("T_outer_K", "outer-ring temperature")):
            v = [r[key] for r in rr]
            out.append((f"{what} rises with speed at {fa:g} N", bool(np.all(np.diff(v) > 0))))
    for rpm in (RPM[0], RPM[-1]):
        rr = sorted((r for r in rows if r["rpm"] == rpm), key=lambda r: r["Fa_N"])
        for key, what in (("power_loss_W", "power loss"), ("T_outer_K", "outer-ring temperature")):
            v = [r[key] for r in rr]
            out.append((f"{what} rises with thrust at {rpm:g} rpm", bool(np.all(np.diff(v) > 0))))
    # load effect small against the speed effect: the change over the thrust range at the top speed
    # against the change over the speed range at the top thrust
    top = [r for r in rows if r["rpm"] == RPM[-1]]
    full = [r for r in rows if r["Fa_N"] == THRUST[-1]]
    for key, what in (("power_loss_W", "power loss"), ("T_outer_K", "outer-ring temperature")):
        d_load = max(r[key] for r in top) - min(r[key] for r in top)
        d_speed = max(r[key] for r in full) - min(r[key] for r in full)
        out.append((f"{what}: change over the thrust range at {RPM[-1]:g} rpm ({d_load:.4g}) is "
                    f"{d_load / d_speed:.0%} of the change over the speed range at {THRUST[-1]:g} N "
                    f"({d_speed:.4g}); the report calls the load effect small", bool(d_load < d_speed)))
    return out


def plot(rows, t_in, path, path_components):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    for fa, style in zip(THRUST, ("b-o", "g-s", "r-^")):
        rr = [r for r in rows if r["Fa_N"] == fa]
        rpm = [r["rpm"] for r in rr]
        axes[0].plot(rpm, [r["power_loss_W"] / 1e3 for r in rr], style, label=f"Fa = {fa:g} N")
        axes[1].plot(rpm, [r["T_outer_K"] for r in rr], style, label=f"Fa = {fa:g} N")
        axes[2].plot(rpm, [r["alpha_inner_deg"] for r in rr], style, label=f"inner, Fa = {fa:g} N")
        axes[2].plot(rpm, [r["alpha_outer_deg"] for r in rr], style.replace("-", "--"), mfc="none",
                     label=f"outer, Fa = {fa:g} N")
    for ax, lab in zip(axes, ("power loss [kW]", "outer-ring temperature [K]", "contact angle [deg]")):
        ax.set_xlabel("inner-ring speed [rpm]")
        ax.set_ylabel(lab)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("ACBB-120 (the 120-mm bearing of NASA TN D-7870) with its thermal network: computed power loss, "
                 "outer-ring temperature and contact angles; the report's measured values could not be retrieved "
                 "and are not shown.", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)

    rr = [r for r in rows if r["Fa_N"] == THRUST[-1]]
    rpm = np.array([r["rpm"] for r in rr])
    comps = [k[:-2] for k in rr[0] if k.endswith("_W") and k[:-2] not in
             ("power_loss", "heat_out_oil", "heat_out_ambient", "energy_residual")]
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.6))
    axes[0].stackplot(rpm, [[r[f"{c}_W"] / 1e3 for r in rr] for c in comps], labels=comps, alpha=0.8)
    axes[0].set_ylabel("power loss [kW]")
    for node, style in (("inner", "r-o"), ("outer", "b-s"), ("ball", "k-^"), ("oil", "g--"), ("cage", "m-d")):
        if f"T_{node}_K" in rr[0]:  # the cage node only with a cage
            axes[1].plot(rpm, [r[f"T_{node}_K"] for r in rr], style, label=node)
    axes[1].axhline(t_in, color="0.5", ls=":", label="oil inlet")
    axes[1].set_ylabel("temperature [K]")
    for ax in axes:
        ax.set_xlabel("inner-ring speed [rpm]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="upper left")
    fig.suptitle(f"ACBB-120 at Fa = {THRUST[-1]:g} N, thermal network: losses by component (stacked) and node "
                 "temperatures against speed.", fontsize=9)
    fig.tight_layout()
    fig.savefig(path_components, dpi=90)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--oil-flow", type=float, default=6e-5, help="m^3/s (assumed default 6e-5)")
    ap.add_argument("--oil-inlet-temperature", type=float, default=394.0, help="K (assumed default 394)")
    ap.add_argument("--cage-guidance", choices=("none", "ball", "outer_land", "inner_land"), default="none",
                    help="an assumed cage (default none: the catalogue's ACBB-120 is cageless)")
    ap.add_argument("--cage-pocket-clearance", type=float, help="m, oil gap per side in the pockets (with a cage)")
    args = ap.parse_args(argv)
    cage = None if args.cage_guidance == "none" else {"cage_guidance": args.cage_guidance,
                                                       "cage_pocket_clearance": args.cage_pocket_clearance}
    rows = solve_grid(args.oil_flow, args.oil_inlet_temperature, cage=cage)
    caged = "T_cage_K" in rows[0]
    print(f"ACBB-120, MIL-L-23699, oil in {args.oil_inlet_temperature:g} K at {args.oil_flow:g} m^3/s (assumed), "
          "traction ehl_mil_l_23699_492K at the contact temperature, balls in air, "
          + (f"assumed {args.cage_guidance} cage, pocket clearance {args.cage_pocket_clearance:g} m" if caged
             else "cageless"))
    print(f"{'Fa [N]':>7} {'rpm':>6} {'P [W]':>8} {'trac':>7} {'ehl':>7} {'hyst':>6} {'drag':>6} {'T_in':>6} "
          f"{'T_out':>6} {'T_ball':>6} {'T_oil':>6} " + (f"{'cage':>6} {'T_cage':>6} " if caged else "")
          + f"{'a_i':>6} {'a_o':>6} {'it':>3}")
    for r in rows:
        cage_cols = (f"{r['cage_pocket_W'] + r['cage_land_W']:6.1f} {r['T_cage_K']:6.1f} " if caged else "")
        print(f"{r['Fa_N']:7.0f} {r['rpm']:6.0f} {r['power_loss_W']:8.1f} {r['traction_W']:7.1f} "
              f"{r['ehl_rolling_W']:7.1f} {r['hysteresis_W']:6.1f} {r['drag_W']:6.1f} {r['T_inner_K']:6.1f} "
              f"{r['T_outer_K']:6.1f} {r['T_ball_K']:6.1f} {r['T_oil_K']:6.1f} {cage_cols}{r['alpha_inner_deg']:6.2f} "
              f"{r['alpha_outer_deg']:6.2f} {r['iterations']:3d}")
    print("largest |energy residual| of the networks: "
          f"{max(abs(r['energy_residual_W']) for r in rows):.3g} W; all converged: {all(r['converged'] for r in rows)}")
    print("NASA TN D-7870 abstract statements on the computed grid (no measured numbers retrieved; nothing calibrated):")
    for text, ok in checks(rows):
        print(f"  {'yes' if ok else 'NO '}  {text}")
    print("  n/a  operating contact angle against the measured angles (not retrieved); computed above (a_i, a_o)")
    print("  n/a  skidding to 6 % at 25000 rpm (the quasi-static solver is cageless: race-control kinematics)")
    OUT.mkdir(exist_ok=True)
    csv_path = OUT / "thermal_nasa_d7870.csv"
    with csv_path.open("w", newline="") as f:
        wr = csv.DictWriter(f, fieldnames=list(rows[0]))
        wr.writeheader()
        wr.writerows(rows)
    png, png_c = OUT / "thermal_nasa_d7870.png", OUT / "thermal_nasa_d7870_components.png"
    plot(rows, args.oil_inlet_temperature, png, png_c)
    print(f"wrote {csv_path}, {png} and {png_c}")
    return rows


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced."""
    return run.printed(
        "Thermal network: the 120-mm bearing of NASA TN D-7870",
        "The quasi-static ACBB-120 solved with its lumped thermal network (docs/theory/thermal.md) over speed "
        "and thrust. Only the report's abstract was available here: the script checks its statements, not its "
        "measured values, and nothing is calibrated.",
        [("thermal_nasa_d7870.png", "power loss, outer-ring temperature and operating contact angles against "
                                    "speed at three thrust loads."),
         ("thermal_nasa_d7870_components.png", "losses by component and node temperatures against speed.")],
        last_lines=40)


if __name__ == "__main__":
    main()
