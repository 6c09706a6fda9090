"""Power loss of the 6208 and the 7208 over speed and load: the quasi-static solver's loss components
(solvers/quasistatic/losses.py) against SKF's catalogue friction model and Palmgren's M0 + M1.

    python validation/losses_6208_7208.py [--quick]

Prints a table of friction torques [N mm] and writes validation/out/losses_6208_7208.csv and .png.

Case: the DEM papers' oil (``guessasma2018``, eta = 0.04 Pa s at its one temperature; kinematic
viscosity nu = eta / 860 kg/m^3 = 46.5 mm^2/s for the catalogue models), the solver's default traction
(``lambda_dem``) and kinematics (``auto``), balls orbiting through air (no oil bath, no oil-air mixture
given: the scene is point-lubricated). SKF: open bearings (no seals), no oil bath (drag term 0),
K_rs = 3e-8 (oil jet / low oil level), mu_EHL = 0.05 (mineral oil), d = 40 mm, D = 80 mm for both
bearings, C0 = 19 kN (6208; SKF product table, quoted). Palmgren: f0 = 1 and 2 (the range for deep
groove and single-row angular contact ball bearings from oil mist to oil bath, Harris & Kotzalas
vol. 2 ch. 6), f1 = z (P0/C0)^y with z = 0.0005, y = 0.55, P0 = F_r, P1 = F_r (6208, radial);
z = 0.001, y = 0.33, P0 = max(F_r, 0.5 F_r + 0.26 F_a), P1 = F_a - 0.1 F_r, C0 = 24 kN (7208 B; quoted).
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

OUT = Path(__file__).resolve().parent / "out"
RHO_OIL = 860.0
D_BORE, D_OUT = 0.040, 0.080
CASES = {  # bearing: (SKF series, C0 [N], Palmgren z, y, [(Fr, Fa), ...])
    "6208": ("62", 19000.0, 0.0005, 0.55, [(1000.0, 0.0), (3000.0, 0.0), (6000.0, 0.0)]),
    "7208": ("72B", 24000.0, 0.001, 0.33, [(0.0, 1000.0), (0.0, 3000.0), (0.0, 6000.0)]),
}
SPEEDS = (100.0, 300.0, 500.0, 900.0, 1300.0, 1700.0)


def palmgren(bearing, omega, nu, fr, fa, f0):
    _series, c0, z, y, _loads = CASES[bearing]
    d_m = 0.5 * (D_BORE + D_OUT)
    if bearing == "6208":
        p0, p1 = max(fr, 0.6 * fr + 0.5 * fa), max(fr, 3 * fa - 0.1 * fr)
    else:
        p0, p1 = max(fr, 0.5 * fr + 0.26 * fa), max(fa - 0.1 * fr, 0.0)
    return ls.palmgren_viscous_moment(omega, nu, d_m, f0) + \
        ls.palmgren_load_moment(ls.palmgren_load_factor(p0, c0, z, y), p1, d_m)


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
                p = pl["power_loss"]
                skf = ls.skf_frictional_moment(series, D_BORE, D_OUT, fr, fa, w, nu, C0=c0)
                rows.append({
                    "bearing": name, "Fr_N": fr, "Fa_N": fa, "omega_rad_s": w, "rpm": w * 30 / math.pi,
                    "traction_W": p["traction"], "ehl_rolling_W": p["ehl_rolling"],
                    "hysteresis_W": p["hysteresis"], "drag_W": p["drag"], "total_W": pl["power_loss_total"],
                    "torque_Nmm": pl["friction_torque_total"] * 1e3,
                    "traction_drive_torque_Nmm": s.friction_torque * 1e3, "energy_residual": s.energy_residual,
                    "skf_rolling_Nmm": skf["rolling"] * 1e3, "skf_sliding_Nmm": skf["sliding"] * 1e3,
                    "skf_drag_Nmm": skf["drag"] * 1e3, "skf_total_Nmm": skf["total"] * 1e3,
                    "skf_phi_ish": skf["phi_ish"], "skf_phi_rs": skf["phi_rs"],
                    "palmgren_f0_1_Nmm": palmgren(name, w, nu, fr, fa, 1.0) * 1e3,
                    "palmgren_f0_2_Nmm": palmgren(name, w, nu, fr, fa, 2.0) * 1e3,
                    "ehl_rolling_Nmm": p["ehl_rolling"] / w * 1e3,
                    "traction_Nmm": p["traction"] / w * 1e3,
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


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="three speeds only")
    args = ap.parse_args()
    speeds = SPEEDS[::2] if args.quick else SPEEDS
    OUT.mkdir(exist_ok=True)
    rows, nu = run(speeds)
    print(f"oil guessasma2018: nu = {nu * 1e6:.1f} mm^2/s at its one temperature; balls through air; "
          "torques in N mm (project = power_loss_total / omega)")
    print(f"{'brg':>4} {'Fr':>5} {'Fa':>5} {'w':>5} {'trac':>7} {'ehl':>7} {'hyst':>6} {'drag':>6} {'proj':>7} "
          f"{'SKFrr':>7} {'SKFsl':>7} {'SKF':>7} {'Pg f0=1':>8} {'Pg f0=2':>8} {'proj/SKF':>8}")
    for r in rows:
        w = r["omega_rad_s"]
        print(f"{r['bearing']:>4} {r['Fr_N']:5.0f} {r['Fa_N']:5.0f} {w:5.0f} {r['traction_W'] / w * 1e3:7.1f} "
              f"{r['ehl_rolling_W'] / w * 1e3:7.1f} {r['hysteresis_W'] / w * 1e3:6.2f} {r['drag_W'] / w * 1e3:6.3f} "
              f"{r['torque_Nmm']:7.1f} {r['skf_rolling_Nmm']:7.1f} {r['skf_sliding_Nmm']:7.1f} "
              f"{r['skf_total_Nmm']:7.1f} {r['palmgren_f0_1_Nmm']:8.1f} {r['palmgren_f0_2_Nmm']:8.1f} "
              f"{r['torque_Nmm'] / r['skf_total_Nmm']:8.2f}")
    ratio = np.array([r["torque_Nmm"] / r["skf_total_Nmm"] for r in rows])
    ehl_rr = np.array([r["ehl_rolling_Nmm"] / r["skf_rolling_Nmm"] for r in rows])
    print(f"project / SKF total: {ratio.min():.2f} - {ratio.max():.2f} (median {np.median(ratio):.2f}); "
          f"project EHL rolling / SKF rolling: {ehl_rr.min():.2f} - {ehl_rr.max():.2f} (median {np.median(ehl_rr):.2f})")
    lo = np.array([r["palmgren_f0_1_Nmm"] for r in rows])
    hi = np.array([r["palmgren_f0_2_Nmm"] for r in rows])
    tq = np.array([r["torque_Nmm"] for r in rows])
    print(f"project total against Palmgren's band f0 = 1-2: {np.sum((tq >= lo) & (tq <= hi))} of {len(rows)} inside, "
          f"{np.sum(tq > hi)} above, {np.sum(tq < lo)} below")
    print("where they part (lowest and highest speed of each load):")
    for g in sorted({(r["bearing"], r["Fr_N"], r["Fa_N"]) for r in rows}):
        rr = [r for r in rows if (r["bearing"], r["Fr_N"], r["Fa_N"]) == g]
        for r in (rr[0], rr[-1]):
            red = r["skf_phi_ish"] * r["skf_phi_rs"]
            print(f"  {g[0]} Fr {g[1]:g} Fa {g[2]:g} at {r['omega_rad_s']:g} rad/s: EHL rolling / SKF rolling "
                  f"{r['ehl_rolling_Nmm'] / r['skf_rolling_Nmm']:.2f} (SKF phi_ish phi_rs = {red:.2f}; "
                  f"without them {r['ehl_rolling_Nmm'] / (r['skf_rolling_Nmm'] / red):.2f}), traction / SKF sliding "
                  f"{r['traction_Nmm'] / r['skf_sliding_Nmm']:.2f}, drag {r['drag_W'] / r['total_W'] * 100:.2f} % "
                  f"of the project total")
    print(f"wall per solve: median {np.median([r['wall_s'] for r in rows]):.2f} s")
    csv_path = OUT / "losses_6208_7208.csv"
    with csv_path.open("w", newline="") as f:
        wr = csv.DictWriter(f, fieldnames=list(rows[0]))
        wr.writeheader()
        wr.writerows(rows)
    png = OUT / "losses_6208_7208.png"
    plot(rows, png)
    print(f"wrote {csv_path} and {png}")


if __name__ == "__main__":
    main()
