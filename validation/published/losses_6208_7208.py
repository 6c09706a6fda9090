"""Power loss of the 6208 and the 7208 over speed and load: the quasi-static solver's loss components
(solvers/quasistatic/losses.py) against SKF's catalogue friction model and Palmgren's M0 + M1.

    python validation/published/losses_6208_7208.py [--quick]

Prints per-term tables of friction torques [N mm] (rolling, sliding, drag / churning, cage, totals) and
writes validation/out/losses_6208_7208.csv and .png.

Case: the DEM papers' oil (``guessasma2018``, eta = 0.04 Pa s at its one temperature; kinematic
viscosity nu = eta / 860 kg/m^3 = 46.5 mm^2/s for the catalogue models), the solver's default traction
(``lambda_dem``) and kinematics (``auto``), balls orbiting through air (no oil bath, no oil-air mixture
given: the scene is point-lubricated). SKF: open bearings (no seals), no oil bath (drag term 0),
K_rs = 3e-8 (oil jet / low oil level), mu_EHL = 0.05 (mineral oil), d = 40 mm, D = 80 mm for both
bearings, C0 = 19 kN (6208; SKF product table, quoted). Palmgren: f0 = 1 and 2 (the range for deep
groove and single-row angular contact ball bearings from oil mist to oil bath, Harris & Kotzalas
vol. 2 ch. 6), f1 = z (P0/C0)^y with z = 0.0005, y = 0.55, P0 = F_r, P1 = F_r (6208, radial);
z = 0.001, y = 0.33, P0 = max(F_r, 0.5 F_r + 0.26 F_a), P1 = F_a - 0.1 F_r, C0 = 24 kN (7208 B; quoted).
Oil bath (churning, the second case of every point, no new solve): oil level H = D_w/2 above the
lowest point of the outer raceway (SKF's guidance for an oil bath: the middle of the lowest ball),
the project's churning (balls dragging through the bath over their immersed share) against SKF's
drag term with V_M = 0 (SKF's first, ball-drag term needs V_M from a diagram not reproduced here: SKF's
drag is then its second term only). Cage: ball-guided (the standard cages of the 6208 and 7208 B are;
SKF's model holds the cage in its fitted constants), pocket friction mu_c = 0.1; the Petroff torque of
an outer-land-guided cage with the default land geometry is printed for information and is not in the
totals compared with SKF.
The 7208 runs under pure thrust: a single 40 deg bearing under the combined loads tried (F_r = 1000-3000 N,
F_a = F_r-2 F_r) tilts so far that the unloaded-side contacts ride over the inner shoulder above
about 900 rad/s, which the solver refuses.
"""
import argparse
import csv
import math
import time
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.physics import losses as ls
from exudyn_bearing.solvers.quasistatic.losses import power_losses

OUT = Path(__file__).resolve().parents[1] / "out"
RHO_OIL = 860.0
D_BORE, D_OUT = 0.040, 0.080
CASES = {  # bearing: (SKF series, C0 [N], Palmgren z, y, [(Fr, Fa), ...])
    "6208": ("62", 19000.0, 0.0005, 0.55, [(1000.0, 0.0), (3000.0, 0.0), (6000.0, 0.0)]),
    "7208": ("72B", 24000.0, 0.001, 0.33, [(0.0, 1000.0), (0.0, 3000.0), (0.0, 6000.0)]),
}
SPEEDS = (100.0, 300.0, 500.0, 900.0, 1300.0, 1700.0)
BALL_DIAMETER = 12.6e-3   # both catalogue bearings' balls (eb.catalog[...].ball_diameter), m
H_BATH = BALL_DIAMETER / 2  # oil level of the bath case, m


def palmgren(bearing, omega, nu, fr, fa, f0):
    _series, c0, z, y, _loads = CASES[bearing]
    d_m = 0.5 * (D_BORE + D_OUT)
    if bearing == "6208":
        p0, p1 = max(fr, 0.6 * fr + 0.5 * fa), max(fr, 3 * fa - 0.1 * fr)
    else:
        p0, p1 = max(fr, 0.5 * fr + 0.26 * fa), max(fa - 0.1 * fr, 0.0)
    return ls.palmgren_viscous_moment(omega, nu, d_m, f0) + \
        ls.palmgren_load_moment(ls.palmgren_load_factor(p0, c0, z, y), p1, d_m)


def v_m_equivalent(churning_nmm, skf_drag_nmm, omega, k_z):
    """SKF's drag-loss factor V_M that would make SKF's drag term (0.4 V_M K_ball d_m^5 n^2 + its second
    term, catalogue units) equal the project's churning; to be read against SKF's diagram of V_M over
    H / d_m, not reproduced here."""
    n = omega * 30 / math.pi
    d_m = 0.5 * (D_BORE + D_OUT) * 1e3
    k_ball = k_z * (D_BORE + D_OUT) / (D_OUT - D_BORE) * 1e-12
    return (churning_nmm - skf_drag_nmm) / (0.4 * k_ball * d_m ** 5 * n ** 2)


def run(speeds):
    lub = eb.data.lubricants["guessasma2018"]
    nu = lub.viscosity / RHO_OIL
    rows = []
    for name, (series, c0, _z, _y, loads) in CASES.items():
        for fr, fa in loads:
            start = None
            for w in speeds:
                t0 = time.perf_counter()
                try:
                    s = eb.solve_quasistatic(name, Fr=fr, Fa=fa, omega=w, stiffness=False, start=start)
                except eb.InputError as err:  # e.g. a contact over the shoulder: said, not tabulated
                    print(f"{name} Fr = {fr:g} N, Fa = {fa:g} N, omega = {w:g} rad/s refused: {err}")
                    continue
                start = s
                pl = power_losses(s, oil_density=RHO_OIL)
                bath = power_losses(s, oil_density=RHO_OIL, oil_level=H_BATH)
                land = power_losses(s, oil_density=RHO_OIL, cage_guidance="outer_land")
                p, pb = pl["power_loss"], bath["power_loss"]
                skf = ls.skf_frictional_moment(series, D_BORE, D_OUT, fr, fa, w, nu, C0=c0)
                skf_bath = ls.skf_frictional_moment(series, D_BORE, D_OUT, fr, fa, w, nu, C0=c0, oil_level=H_BATH)

                def nmm(power, w=w):
                    return power / w * 1e3
                rows.append({
                    "bearing": name, "Fr_N": fr, "Fa_N": fa, "omega_rad_s": w, "rpm": w * 30 / math.pi,
                    "traction_W": p["traction"], "ehl_rolling_W": p["ehl_rolling"],
                    "hysteresis_W": p["hysteresis"], "drag_W": p["drag"], "cage_pocket_W": p["cage_pocket"],
                    "total_W": pl["power_loss_total"],
                    "torque_Nmm": pl["friction_torque_total"] * 1e3,
                    "traction_drive_torque_Nmm": s.friction_torque * 1e3, "energy_residual": s.energy_residual,
                    "skf_rolling_Nmm": skf["rolling"] * 1e3, "skf_sliding_Nmm": skf["sliding"] * 1e3,
                    "skf_drag_Nmm": skf["drag"] * 1e3, "skf_total_Nmm": skf["total"] * 1e3,
                    "skf_phi_ish": skf["phi_ish"], "skf_phi_rs": skf["phi_rs"], "skf_mu_sl": skf["mu_sl"],
                    "palmgren_f0_1_Nmm": palmgren(name, w, nu, fr, fa, 1.0) * 1e3,
                    "palmgren_f0_2_Nmm": palmgren(name, w, nu, fr, fa, 2.0) * 1e3,
                    "ehl_rolling_Nmm": nmm(p["ehl_rolling"]), "hysteresis_Nmm": nmm(p["hysteresis"]),
                    "traction_Nmm": nmm(p["traction"]), "drag_Nmm": nmm(p["drag"]),
                    "cage_pocket_Nmm": nmm(p["cage_pocket"]),
                    "bath_churning_Nmm": nmm(pb["churning"]), "bath_cage_pocket_Nmm": nmm(pb["cage_pocket"]),
                    "bath_torque_Nmm": bath["friction_torque_total"] * 1e3,
                    "skf_bath_drag_Nmm": skf_bath["drag"] * 1e3,
                    "skf_v_m_equivalent": v_m_equivalent(nmm(pb["churning"]), skf_bath["drag"] * 1e3, w,
                                                         ls.SKF_CONSTANTS[series]["K_z"]),
                    "skf_bath_total_Nmm": skf_bath["total"] * 1e3,
                    "land_cage_land_Nmm": nmm(land["power_loss"]["cage_land"]),
                    "land_cage_pocket_Nmm": nmm(land["power_loss"]["cage_pocket"]),
                    "land_torque_Nmm": land["friction_torque_total"] * 1e3,
                    "control_used": ",".join(sorted(set(map(str, s.balls["control_used"])))),
                    "wall_s": time.perf_counter() - t0})
    return rows, nu


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    groups = sorted({(r["bearing"], r["Fr_N"], r["Fa_N"]) for r in rows})
    fig, axes = plt.subplots(2, 3, figsize=(15, 8.5), squeeze=False)
    for ax, g in zip(axes.ravel(), groups):
        rr = [r for r in rows if (r["bearing"], r["Fr_N"], r["Fa_N"]) == g]
        w = np.array([r["omega_rad_s"] for r in rr])
        ax.plot(w, [r["torque_Nmm"] for r in rr], "k-o", label="project total")
        ax.plot(w, [r["ehl_rolling_Nmm"] for r in rr], "b--", label="project EHL rolling")
        ax.plot(w, [r["traction_Nmm"] for r in rr], "g--", label="project traction")
        ax.plot(w, [r["skf_total_Nmm"] for r in rr], "r-s", label="SKF total")
        ax.plot(w, [r["skf_rolling_Nmm"] for r in rr], "r:", label="SKF rolling")
        ax.plot(w, [r["bath_torque_Nmm"] for r in rr], "m-^", label=f"project total, oil bath H = {H_BATH * 1e3:g} mm")
        ax.plot(w, [r["skf_bath_total_Nmm"] for r in rr], "m:", label="SKF total, oil bath (V_M = 0)")
        ax.fill_between(w, [r["palmgren_f0_1_Nmm"] for r in rr], [r["palmgren_f0_2_Nmm"] for r in rr],
                        color="0.8", label="Palmgren f0 = 1-2")
        ax.set_title(f"{g[0]}  Fr = {g[1]:g} N, Fa = {g[2]:g} N")
        ax.set_xlabel("inner-ring speed [rad/s]")
        ax.set_ylabel("friction torque [N mm]")
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def _range(x, fmt=".2f"):
    x = np.asarray(x, float)
    return f"{x.min():{fmt}} - {x.max():{fmt}} (median {np.median(x):{fmt}})"


def _rolling(row):
    """The project's rolling resistance torque [N mm]: EHL rolling + hysteresis."""
    return row["ehl_rolling_Nmm"] + row["hysteresis_Nmm"]


def _slope(rows, key):
    """Least-squares slope of log(torque) against log(speed) over ``rows``."""
    w = np.log([r["omega_rad_s"] for r in rows])
    return float(np.polyfit(w, np.log([r[key] for r in rows]), 1)[0])


def print_tables(rows):
    """The per-term tables and the summaries of where the project and SKF part."""
    head = f"{'brg':>4} {'Fr':>5} {'Fa':>5} {'w':>5}"

    def key(r):
        return f"{r['bearing']:>4} {r['Fr_N']:5.0f} {r['Fa_N']:5.0f} {r['omega_rad_s']:5.0f}"

    print("\n[rolling] project EHL rolling + hysteresis against SKF's phi_ish phi_rs M_rr")
    print(f"{head} {'ehl':>7} {'hyst':>6} {'proj':>7} {'SKF':>7} {'phi':>5} {'SKF/phi':>7} {'ratio':>6} {'r/phi':>6}")
    for r in rows:
        red = r["skf_phi_ish"] * r["skf_phi_rs"]
        proj = _rolling(r)
        print(f"{key(r)} {r['ehl_rolling_Nmm']:7.1f} {r['hysteresis_Nmm']:6.2f} {proj:7.1f} "
              f"{r['skf_rolling_Nmm']:7.1f} "
              f"{red:5.2f} {r['skf_rolling_Nmm'] / red:7.1f} {proj / r['skf_rolling_Nmm']:6.2f} "
              f"{proj / (r['skf_rolling_Nmm'] / red):6.2f}")
    print("\n[sliding] project traction (sliding, spin, curvature) against SKF's G_sl mu_sl")
    print(f"{head} {'trac':>7} {'SKF':>7} {'mu_sl':>6} {'ratio':>6}")
    for r in rows:
        print(f"{key(r)} {r['traction_Nmm']:7.1f} {r['skf_sliding_Nmm']:7.1f} {r['skf_mu_sl']:6.3f} "
              f"{r['traction_Nmm'] / r['skf_sliding_Nmm']:6.2f}")
    print(f"\n[drag] balls through air (no bath; SKF: none) and an oil bath of level H = {H_BATH * 1e3:g} mm: "
          "project churning against SKF's drag term (V_M = 0)")
    print(f"{head} {'air':>7} {'churn':>7} {'SKFdrag':>7} {'ratio':>6} {'V_M eq':>8}")
    for r in rows:
        print(f"{key(r)} {r['drag_Nmm']:7.3f} {r['bath_churning_Nmm']:7.2f} {r['skf_bath_drag_Nmm']:7.2f} "
              f"{r['bath_churning_Nmm'] / r['skf_bath_drag_Nmm']:6.2f} {r['skf_v_m_equivalent']:8.2e}")
    print("\n[cage] ball-guided pocket friction (in the totals); outer-land guided (Petroff, default land "
          "geometry; for information, not in the totals)")
    print(f"{head} {'pocket':>7} {'land':>7} {'pocket@land':>11}")
    for r in rows:
        print(f"{key(r)} {r['cage_pocket_Nmm']:7.3f} {r['land_cage_land_Nmm']:7.1f} {r['land_cage_pocket_Nmm']:11.3f}")
    print("\n[total] jet / air, ball-guided cage; oil bath; against SKF and Palmgren f0 = 1-2")
    print(f"{head} {'proj':>7} {'SKF':>7} {'ratio':>6} {'bath':>7} {'SKFbath':>7} {'ratio':>6} {'Pg f0=1':>8} "
          f"{'Pg f0=2':>8}")
    for r in rows:
        print(f"{key(r)} {r['torque_Nmm']:7.1f} {r['skf_total_Nmm']:7.1f} {r['torque_Nmm'] / r['skf_total_Nmm']:6.2f} "
              f"{r['bath_torque_Nmm']:7.1f} {r['skf_bath_total_Nmm']:7.1f} "
              f"{r['bath_torque_Nmm'] / r['skf_bath_total_Nmm']:6.2f} {r['palmgren_f0_1_Nmm']:8.1f} "
              f"{r['palmgren_f0_2_Nmm']:8.1f}")
    print("\nsummary (ranges over the points; per bearing where they differ):")
    for brg in sorted({r["bearing"] for r in rows}):
        rr = [r for r in rows if r["bearing"] == brg]
        lo_w = [r for r in rr if r["omega_rad_s"] == min(x["omega_rad_s"] for x in rr)]
        hi_w = [r for r in rr if r["omega_rad_s"] == max(x["omega_rad_s"] for x in rr)]
        for label, sel in (("lowest speed", lo_w), ("highest speed", hi_w)):
            print(f"  {brg} {label} ({sel[0]['omega_rad_s']:g} rad/s): rolling / SKF rolling "
                  f"{_range([_rolling(r) / r['skf_rolling_Nmm'] for r in sel])}, without SKF's phi_ish phi_rs "
                  f"{_range([_rolling(r) * r['skf_phi_ish'] * r['skf_phi_rs'] / r['skf_rolling_Nmm'] for r in sel])}; "
                  f"traction / SKF sliding {_range([r['traction_Nmm'] / r['skf_sliding_Nmm'] for r in sel])}; "
                  f"total / SKF total {_range([r['torque_Nmm'] / r['skf_total_Nmm'] for r in sel])}")
        print(f"  {brg} churning (H = {H_BATH * 1e3:g} mm) / SKF drag (V_M = 0): "
              f"{_range([r['bath_churning_Nmm'] / r['skf_bath_drag_Nmm'] for r in rr])}; churning share of the bath "
              f"total {_range([r['bath_churning_Nmm'] / r['bath_torque_Nmm'] * 100 for r in rr])} %; log-log slope "
              f"over speed: churning {_slope(rr, 'bath_churning_Nmm'):.2f}, "
              f"SKF drag {_slope(rr, 'skf_bath_drag_Nmm'):.2f}; "
              f"V_M equivalent {_range([r['skf_v_m_equivalent'] for r in rr if r['skf_v_m_equivalent'] > 0], '.2e')} "
              "(where churning exceeds SKF's second term)")
        print(f"  {brg} cage pocket (ball-guided) share of the total "
              f"{_range([r['cage_pocket_Nmm'] / r['torque_Nmm'] * 100 for r in rr])} %; outer-land Petroff torque "
              f"{_range([r['land_cage_land_Nmm'] for r in rr])} N mm = "
              f"{_range([r['land_cage_land_Nmm'] / r['torque_Nmm'] * 100 for r in rr])} % of the total")
    ratio = np.array([r["torque_Nmm"] / r["skf_total_Nmm"] for r in rows])
    ehl_rr = np.array([r["ehl_rolling_Nmm"] / r["skf_rolling_Nmm"] for r in rows])
    print(f"project / SKF total: {_range(ratio)}; project EHL rolling / SKF rolling: {_range(ehl_rr)}; "
          f"bath: project / SKF total {_range([r['bath_torque_Nmm'] / r['skf_bath_total_Nmm'] for r in rows])}")
    lo = np.array([r["palmgren_f0_1_Nmm"] for r in rows])
    hi = np.array([r["palmgren_f0_2_Nmm"] for r in rows])
    for label, tq in (("jet / air", np.array([r["torque_Nmm"] for r in rows])),
                      ("oil bath", np.array([r["bath_torque_Nmm"] for r in rows]))):
        print(f"project total ({label}) against Palmgren's band f0 = 1-2: {np.sum((tq >= lo) & (tq <= hi))} of "
              f"{len(rows)} inside, {np.sum(tq > hi)} above, {np.sum(tq < lo)} below")


def dynamic_energy_check():
    """The energy check of a dynamic run: the 6208 under 3 kN thrust at 500 rad/s at the ellipse traction
    level from the quasi-static traction equilibrium (the scene of tests/test_energy.py), its summary's
    power_loss by component and energy_check over the default window (the last quarter)."""
    import warnings

    sc = eb.Scenario(Fa=3000.0, Fr=0.0, omega=500.0, t_end=0.01, dt=2e-6, sample_dt=5e-4, cage=False,
                     traction_level="ellipse", n_strips=16, n_across=4, initial="quasistatic", control="equilibrium")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        s = eb.simulate("6208", sc).summary()
    c = s["energy_check"]
    print("\n[dynamic] 6208, Fa = 3000 N, 500 rad/s, ellipse level, reference engine, window "
          f"{s['window']['t0']:.4g}-{s['window']['t1']:.4g} s: power_loss "
          + ", ".join(f"{k} {v:.4g} W" for k, v in s["power_loss"].items() if v is not None)
          + f"; total {s['power_loss_total']:.4g} W; drive {c['drive_power']:.4g} W; kinetic energy rate "
          f"{c['kinetic_energy_rate']:.3g} W")
    print(f"  {c['statement']}; split error against dissipated_work {c['split_error']:.2g}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="three speeds only")
    args = ap.parse_args()
    speeds = SPEEDS[::2] if args.quick else SPEEDS
    OUT.mkdir(exist_ok=True)
    rows, nu = run(speeds)
    print(f"oil guessasma2018: nu = {nu * 1e6:.1f} mm^2/s at its one temperature; torques in N mm "
          "(project = power / inner-ring speed); ratios project / SKF")
    print_tables(rows)
    dynamic_energy_check()
    print(f"wall per solve: median {np.median([r['wall_s'] for r in rows]):.2f} s")
    csv_path = OUT / "losses_6208_7208.csv"
    with csv_path.open("w", newline="") as f:
        wr = csv.DictWriter(f, fieldnames=list(rows[0]))
        wr.writeheader()
        wr.writerows(rows)
    png = OUT / "losses_6208_7208.png"
    plot(rows, png)
    print(f"wrote {csv_path} and {png}")


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced."""
    return run.printed(
        "Power loss against SKF's and Palmgren's models",
        "The quasi-static solver's loss components (traction, EHL rolling, hysteresis, drag; "
        "docs/theory/losses.md) for the 6208 (radial) and the 7208 (thrust) against SKF's catalogue friction "
        "model and Palmgren's M0 + M1 (per term: rolling, sliding, drag and churning, cage), the DEM papers' oil "
        "at its one temperature, for balls in air and in an oil bath; the dynamic energy check by component.",
        [("losses_6208_7208.png", "friction torque of the project's components, SKF's model and Palmgren's "
                                  "band over speed and load.")],
        last_lines=30)


if __name__ == "__main__":
    main()
