"""3-DOF outer ring / ball / inner ring model of El Had et al. 2014: the
source's printed values, where its eigenvalues come from, and the physically
derived model of the SKF 6004.

1. Source values: the eigenvalues of its printed state matrix (it prints
   V = 2e4, -2e4, -6.5763e4, 6.6178e4, 4948, -0.1 1/s), of the same state
   matrix rebuilt from its printed matrices, and the correct eigen-analysis
   of those matrices under each reading of the source's inconsistencies.
2. The sign error: the source's state matrix has +A^-1 C and +A^-1 B where
   the equation of motion gives -A^-1 C and -A^-1 B. A spring k on a mass M
   then yields lambda^2 = +k/M, two real roots +-sqrt(k/M), instead of
   +-i sqrt(k/M): numbers for both rings.
3. The source's ball-race values 0.9925 N/m and 9.9072 N s/m against its
   film expressions (eqs. 5-6) read as dimensionless numbers.
4. The derived 6004 model (500 N, 3000 rpm, P_d = 12.5 um): ring stiffness
   from the oval mode, Hertz tangent stiffness in series with the film
   stiffness, and either the source's short-bearing film damping or the
   contact model's damping; eigenvalues, natural frequencies, damping
   ratios, mode shapes.
5. Figures (PNG + CSV): FRF, time response to a BPFO force train, mode
   shapes.

    python validation/published/three_dof.py       # writes validation/out/three_dof.json and three_dof_*.png/.csv
"""
import itertools
import json
import math
import time
from pathlib import Path

import numpy as np
from scipy import optimize

from exudyn_bearing.outputs.jsonio import to_jsonable
from exudyn_bearing.outputs.plotting import pyplot, save_figure
from exudyn_bearing.physics.short_bearing import short_bearing_damping, short_bearing_stiffness
from exudyn_bearing.solvers.vibration import linear
from exudyn_bearing.solvers.vibration import three_dof as td

HERE = Path(__file__).resolve().parent
OUT = HERE.parent / "out"
OMEGA = 2.0 * math.pi * 50.0   # 3000 rpm


def pairs(z):
    return [[float(np.real(x)), float(np.imag(x))] for x in np.atleast_1d(z)]


def modal_rows(res):
    m = res.modal
    return [{"eigenvalue": [float(lam.real), float(lam.imag)], "f_n_hz": float(f), "zeta": float(z),
             "shape_abs": [float(x) for x in np.abs(s)],
             "shape_sign": [float(np.sign(np.real(x))) for x in s]}
            for lam, f, z, s in zip(m.eigenvalues, m.natural_frequencies, m.damping_ratios, m.mode_shapes)]


def source_part():
    s = td.source_printed_system()
    printed = np.sort(np.array(td.SOURCE_EIGENVALUES))
    lam_printed_L = np.sort(np.linalg.eigvals(s["state_matrix"]).real)
    rebuilt = td.source_state_matrix(s["mass_inverse"], s["damping"], s["stiffness"])
    lam_rebuilt = np.sort_complex(np.linalg.eigvals(rebuilt))
    correct = linear.modal_analysis(s["mass"], s["damping"], s["stiffness"])
    sign = {}
    for name, k, m in (("outer ring", 1e7, 0.025), ("inner ring (printed 1e8)", 1e8, 0.023),
                       ("inner ring (list 1e7)", 1e7, 0.023)):
        sign[name] = {"k": k, "M": m, "sqrt_k_over_M": math.sqrt(k / m), "f_hz": math.sqrt(k / m) / (2 * math.pi)}
    # the inner-ring pair of the printed L: r^2 - b r - k/M = 0 with b = 413.25, k/M = 435e7
    r_hi, r_lo = lam_printed_L[-1], lam_printed_L[0]
    lam_in = correct.eigenvalues[np.argmax(np.abs(correct.eigenvalues.imag))]
    pair = {"source_roots": [float(r_lo), float(r_hi)], "product": float(-r_lo * r_hi), "sum": float(r_lo + r_hi),
            "correct_eigenvalue": [float(lam_in.real), float(lam_in.imag)],
            "correct_modulus_squared": float(abs(lam_in) ** 2), "correct_minus_twice_real": float(-2 * lam_in.real)}
    readings = {}
    for combo in itertools.product(*td.READINGS.values()):
        kw = dict(zip(td.READINGS, combo))
        p = td.source_parameters(**kw)
        r = td.analyse(p)
        readings[", ".join(f"{k}={v}" for k, v in kw.items())] = {"reading": kw, "modes": modal_rows(r)}
    return {"printed_eigenvalues": printed.tolist(), "printed_state_matrix_eigenvalues": lam_printed_L.tolist(),
            "rebuilt_state_matrix_eigenvalues": pairs(lam_rebuilt),
            "rebuilt_vs_printed_entries": {"A^-1 B [5,5] printed": float(s["state_matrix"][5, 5]),
                                           "A^-1 B [5,5] = 43.5 * 9.9": float(rebuilt[5, 5])},
            "printed_polynomial": np.poly(s["state_matrix"]).tolist(),
            "correct_printed_matrices": modal_rows(td.ThreeDofResult(
                None, s["mass"], s["damping"], s["stiffness"], correct)),
            "sqrt_k_over_M": sign, "inner_pair": pair, "readings": readings}


def film_values_part():
    """At which eccentricity do eqs. 5-6, as dimensionless numbers, give the source's values?"""
    out = {}
    for label, printed in (("printed prefactor", True), ("corrected prefactor", False)):
        row = {}
        for name, fn, target in (("k 0.9925", short_bearing_stiffness, 0.9925),
                                 ("C 9.9072", short_bearing_damping, 9.9072)):
            g = lambda e: float(fn(e, printed_prefactor=printed)) - target  # noqa: E731
            grid = np.linspace(1e-4, 1 - 1e-9, 20001)
            vals = fn(grid, printed_prefactor=printed) - target
            roots = [float(optimize.brentq(g, grid[i], grid[i + 1])) for i in np.nonzero(np.diff(np.sign(vals)))[0]]
            row[name] = roots
        out[label] = row
    return out


def derived_part():
    sets = {}
    for damping in ("short_bearing", "contact_model"):
        p = td.derived_parameters("6004", radial_load=500.0, omega=OMEGA, diametral_clearance=12.5e-6,
                                  film_damping=damping)
        r = td.analyse(p)
        sets[damping] = {"parameters": {k: v for k, v in p.to_dict().items() if k not in ("derivation",)},
                         "derivation": p.derivation, "modes": modal_rows(r), "_params": p, "_result": r}
    return sets


def plot_frf(sets, source):
    plt = pyplot()
    f = np.logspace(1, 5.3, 3000)
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.4), sharey=True)
    cols = {"f_hz": f}
    cases = [("source, printed matrices", td.source_parameters()),
             ("derived, short-bearing film damping", sets["short_bearing"]["_params"]),
             ("derived, contact-model damping", sets["contact_model"]["_params"])]
    for ax, (title, p) in zip(axes, cases):
        h = td.frequency_response(p, f)
        for i, dof in enumerate(td.DOFS):
            ax.loglog(f, np.abs(h[:, i, i]), label=f"|H| {dof}")
            cols[f"{title.split(',')[0]}_{title.split(', ')[1].replace(' ', '_')}_H_{dof}_m_per_N"] = np.abs(h[:, i, i])
        for fn, z in zip(td.analyse(p).modal.natural_frequencies, td.analyse(p).modal.damping_ratios):
            if z < 0.99 and f[0] < fn < f[-1]:
                ax.axvline(fn, color="k", lw=0.6, ls=":")
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("frequency [Hz]")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("direct receptance |H_ii| [m/N]")
    axes[0].legend(fontsize=8)
    save_figure(fig, OUT / "three_dof_frf.png", cols)


def plot_time(sets):
    plt = pyplot()
    f_bp = td.bpfo("6004", OMEGA)
    fig, axes = plt.subplots(2, 2, figsize=(13, 7), sharex=True)
    cols = {}
    walls = {}
    for col, damping in enumerate(("short_bearing", "contact_model")):
        p = sets[damping]["_params"]
        t0 = time.perf_counter()
        res = td.ball_pass_response(p, f_bp, t_end=6 / f_bp, amplitude=100.0, samples_per_pulse=200)
        walls[damping] = time.perf_counter() - t0
        t = res["t"] * 1e3
        axes[0, col].plot(t, res["force"][:, 0], color="k", lw=0.8, label="pulse on outer ring (ball: -)")
        axes[0, col].set_ylabel("force [N]")
        axes[0, col].set_title(f"derived 6004, {damping.replace('_', ' ')} damping; BPFO {f_bp:.2f} Hz", fontsize=10)
        for i, dof in enumerate(td.DOFS):
            axes[1, col].plot(t, res["q"][:, i] * 1e9, lw=0.8, label=dof)
        axes[1, col].set_ylabel("displacement [nm]")
        axes[1, col].set_xlabel("time [ms]")
        axes[1, col].legend(fontsize=8)
        axes[0, col].legend(fontsize=8)
        for a in axes[:, col]:
            a.grid(alpha=0.3)
        cols[f"{damping}_t_s"] = res["t"]
        cols[f"{damping}_force_N"] = res["force"][:, 0]
        for i, dof in enumerate(td.DOFS):
            cols[f"{damping}_q_{dof}_m"] = res["q"][:, i]
        sets[damping]["time_response"] = {
            "bpfo_hz": f_bp, "pulse_duration_s": res["pulse_duration"], "dt_s": res["dt"], "amplitude_N": 100.0,
            "peak_displacement_m": [float(np.abs(res["q"][:, i]).max()) for i in range(3)],
            "static_ball_outer_deflection_m": float(np.linalg.solve(td.assemble(p)[2], [100.0, -100.0, 0.0])[0]),
            "wall_s": walls[damping]}
    save_figure(fig, OUT / "three_dof_time_response.png", cols, trim=True)


def plot_modes(sets):
    plt = pyplot()
    cases = [("source, printed matrices", td.analyse(td.source_parameters())),
             ("derived, contact-model damping", sets["contact_model"]["_result"]),
             ("derived, short-bearing damping", sets["short_bearing"]["_result"])]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2), sharey=True)
    cols = {"dof": np.arange(3)}
    for ax, (title, res) in zip(axes, cases):
        rows = res.modal.modes()
        for j, row in enumerate(rows):
            shape = np.real(row["shape"]) if row["real_root"] else np.abs(row["shape"]) * np.sign(
                np.real(row["shape"]) + 1e-300)
            lam = row["eigenvalue"]
            lab = (f"{row['frequency_hz']:.4g} Hz, zeta {row['damping_ratio']:.3g}" if not row["real_root"]
                   else f"real root {lam.real:.3g} 1/s")
            ax.plot(range(3), shape, "o-", label=lab)
            cols[f"{title.replace(' ', '_').replace(',', '')}_mode{j}"] = shape
        ax.set_xticks(range(3), td.DOFS)
        ax.axhline(0, color="k", lw=0.6)
        ax.set_title(title, fontsize=10)
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("mode shape (largest entry 1; |phi| with the sign of Re)")
    save_figure(fig, OUT / "three_dof_modes.png", cols)


def main():
    OUT.mkdir(exist_ok=True)
    t0 = time.perf_counter()
    src = source_part()
    film = film_values_part()
    sets = derived_part()
    plot_frf(sets, src)
    plot_time(sets)
    plot_modes(sets)
    out = {"source": src, "source_film_values": film,
           "derived": {k: {kk: vv for kk, vv in v.items() if not kk.startswith("_")} for k, v in sets.items()},
           "wall_s": time.perf_counter() - t0}
    (OUT / "three_dof.json").write_text(json.dumps(to_jsonable(out), indent=2))
    print("source: printed eigenvalues", src["printed_eigenvalues"])
    print("source: eigenvalues of its printed state matrix", np.round(src["printed_state_matrix_eigenvalues"], 2))
    print("source: correct eigenvalues of its printed matrices",
          [r["eigenvalue"] for r in src["correct_printed_matrices"]])
    print("inner pair:", src["inner_pair"])
    print("film values:", film)
    for k, v in sets.items():
        print(f"derived ({k}):", [(round(r["f_n_hz"], 2), round(r["zeta"], 5)) for r in v["modes"]])
    print(f"written {OUT / 'three_dof.json'} ({out['wall_s']:.1f} s)")


def report_section(run):
    """The report's section on the 3-DOF model of El Had et al., from three_dof.json and its figures."""
    d = run.load("three_dof.json")
    s = d["source"]
    ev = lambda z: f"{z[0]:.4g} {'+' if z[1] >= 0 else '-'} {abs(z[1]):.5g}i"  # noqa: E731
    pair = s["inner_pair"]
    lines = ["## 3-DOF vibration model (El Had et al. 2014)", "",
             f"Command: `{run.command}` (figures `out/three_dof_frf.png`, "
             "`out/three_dof_time_response.png`, `out/three_dof_modes.png`, each with its CSV). Theory and "
             "readings: docs/theory/vibration.md.", "",
             "**Where the source's eigenvalues come from.** It prints V = "
             + ", ".join(f"{v:g}" for v in s["printed_eigenvalues"]) + " 1/s. Its printed state matrix L has "
             "eigenvalues " + ", ".join(f"{v:.5g}" for v in s["printed_state_matrix_eigenvalues"])
             + " (the printed values to their 4-5 digits; its characteristic polynomial starts "
             f"X^6 {s['printed_polynomial'][1]:+.6g} X^5, the source prints -5,363 X^5). L is "
             "[[0, I], [+A^-1 C, +A^-1 B]]: both lower blocks carry the wrong sign (M y'' + B y' + C y = 0 gives "
             "-A^-1 C and -A^-1 B), and A^-1 B holds 413.25 where 43.5 x 9.9 = "
             f"{s['rebuilt_vs_printed_entries']['A^-1 B [5,5] = 43.5 * 9.9']:.2f}. With +k/M a ring on its spring "
             "has lambda^2 = +k/M, real roots +-sqrt(k/M), instead of +-i sqrt(k/M): "
             + "; ".join(f"{k}: sqrt(k/M) = {v['sqrt_k_over_M']:.5g} 1/s ({v['f_hz']:.5g} Hz)"
                         for k, v in s["sqrt_k_over_M"].items())
             + f". The inner-ring pair of L, {pair['source_roots'][0]:.6g} and {pair['source_roots'][1]:.6g}, "
             f"solves r^2 - b r - k/M = 0: product {pair['product']:.5g} against |lambda|^2 = "
             f"{pair['correct_modulus_squared']:.5g} of the correct root {ev(pair['correct_eigenvalue'])}, sum "
             f"{pair['sum']:.4g} against -2 Re(lambda) = {pair['correct_minus_twice_real']:.4g} (the source's "
             "rounded A^-1 and its 413.25 make the difference).", "",
             "Correct eigenvalues of the printed matrices (scipy.linalg.eig of [[0, I], [-M^-1 K, -M^-1 C]]): "
             + ", ".join(ev(r["eigenvalue"]) for r in s["correct_printed_matrices"]) + " 1/s.", "",
             "Each reading of the source's printed values (ball links k21 = 0.9925 N/m, C21 = 9.9072 N s/m, "
             "masses 25, 2, 23 g):", "",
             "| reading | eigenvalues [1/s] | f_n [Hz] | zeta |", "|---|---|---|---|"]
    for name, r in s["readings"].items():
        lines.append(f"| {name} | " + ", ".join(ev(m["eigenvalue"]) for m in r["modes"]) + " | "
                     + ", ".join(f"{m['f_n_hz']:.5g}" for m in r["modes"]) + " | "
                     + ", ".join(f"{m['zeta']:.3g}" for m in r["modes"]) + " |")
    fv = d["source_film_values"]
    lines += ["", "Real roots have zeta = 1 and f_n = |lambda| / 2 pi. The readings: inner_ring printed_matrix "
              "k3 = 1e8 N/m (its numeric matrix), parameter_list 1e7; outer_link printed_matrix: no ball / outer "
              "race link (its numeric matrices), eq7: k22 = 0.9925 N/m, C22 = 9.9072 N s/m; damping_row "
              "eq7_literal: the ball row of eq. 7 as printed (C22 on y2' twice, no y1' term).", "",
              "The source's ball-race values are not dimensional film coefficients. Read as the dimensionless "
              "values of its eqs. 5-6 with its printed prefactor, 0.9925 needs eps_0 = "
              + ", ".join(f"{e:.4f}" for e in fv["printed prefactor"]["k 0.9925"]) + " and 9.9072 needs eps_0 = "
              + ", ".join(f"{e:.4f}" for e in fv["printed prefactor"]["C 9.9072"])
              + "; with the corrected prefactor 0.9925 is reached at no eccentricity ("
              + (", ".join(f"{e:.4f}" for e in fv["corrected prefactor"]["k 0.9925"]) or "none")
              + ") and 9.9072 at " + ", ".join(f"{e:.4f}" for e in fv["corrected prefactor"]["C 9.9072"])
              + ". No single film gives both.", ""]
    for key, title in (("contact_model", "contact-model damping"), ("short_bearing", "short-bearing film damping")):
        v = d["derived"][key]
        dv = v["derivation"]
        ci, co = dv["contacts"]["inner"], dv["contacts"]["outer"]
        lines += [f"**Derived 6004, {title}** (F_r = {dv['radial_load']:g} N, {dv['omega'] * 30 / 3.141592653589793:.0f} "
                  f"rpm, P_d = {dv['diametral_clearance'] * 1e6:g} um, eta = {dv['viscosity']:g} Pa s): "
                  f"outer ring {dv['outer_ring']['mass'] * 1e3:.2f} g, oval mode {dv['outer_ring']['f_2_hz']:.0f} Hz, "
                  f"k1 = {dv['outer_ring']['stiffness']:.4g} N/m; inner ring {dv['inner_ring']['mass'] * 1e3:.2f} g, "
                  f"{dv['inner_ring']['f_2_hz']:.0f} Hz, k3 = {dv['inner_ring']['stiffness']:.4g} N/m; ball "
                  f"{dv['ball_mass'] * 1e3:.3f} g, Q = {dv['q_max']:.1f} N; inner / outer contact: Hertz "
                  f"{ci['k_hertz']:.4g} / {co['k_hertz']:.4g} N/m, h_min {ci['h_min'] * 1e9:.0f} / "
                  f"{co['h_min'] * 1e9:.0f} nm, eps_0 {ci['eccentricity']:.4f} / {co['eccentricity']:.4f}, film "
                  f"{ci['k_film']:.3g} / {co['k_film']:.3g} N/m, series link {ci['k_link']:.4g} / "
                  f"{co['k_link']:.4g} N/m; damping short-bearing {ci['c_film']:.3g} / {co['c_film']:.3g} N s/m, "
                  f"contact model {ci['c_contact_model']:.3g} / {co['c_contact_model']:.3g} N s/m (Lambda "
                  f"{ci['film_parameter']:.2f} / {co['film_parameter']:.2f}).", "",
                  "| eigenvalue [1/s] | f_n [Hz] | zeta | abs(shape) outer, ball, inner |", "|---|---|---|---|"]
        for m in v["modes"]:
            lines.append(f"| {ev(m['eigenvalue'])} | {m['f_n_hz']:.6g} | {m['zeta']:.4g} | "
                         + ", ".join(f"{x:.3g}" for x in m["shape_abs"]) + " |")
        tr = v["time_response"]
        lines += ["", f"Ball-pass train at BPFO = {tr['bpfo_hz']:.2f} Hz (half-sine pulses of {tr['amplitude_N']:g} N, "
                  f"{tr['pulse_duration_s'] * 1e3:.3f} ms, pushing outer ring and ball apart): peak displacements "
                  + ", ".join(f"{x * 1e9:.1f}" for x in tr["peak_displacement_m"]) + " nm (outer, ball, inner).", ""]
    ci = d["derived"]["short_bearing"]["derivation"]["contacts"]["inner"]
    lines += ["The source's short-bearing film damping, normalised with the load, the radial clearance and the "
              f"shaft speed, is {ci['c_film']:.3g} N s/m at the inner contact, {ci['c_film'] / ci['c_contact_model']:.2g} "
              f"times the contact model's damping there ({ci['c_contact_model']:.3g} N s/m, hysteretic at Lambda < 1; "
              f"its squeeze-film term alone is {ci['c_squeeze']:.3g} N s/m): it locks the ball to the rings, leaves "
              "one oscillating mode (the two rings and the ball moving together on k1 + k3) and turns the rest into "
              "real roots. The contact-model run keeps three lightly damped modes.", ""]
    lines += run.figure("three_dof_frf.png", "Direct receptances of the outer ring, ball and inner ring against "
                        "frequency: the source's printed matrices (left), the derived 6004 with short-bearing film "
                        "damping (middle) and with the contact model's damping (right); thin vertical lines at the "
                        "natural frequencies.")
    lines += run.figure("three_dof_time_response.png", "Response of the derived 6004 to the ball-pass force train at "
                        "BPFO (top: force, bottom: displacements), short-bearing damping (left) and contact-model "
                        "damping (right).")
    lines += run.figure("three_dof_modes.png", "Mode shapes (largest entry 1, signed by the real part) with their "
                        "eigenvalues or natural frequencies and damping ratios, for the same three models.")
    return "\n".join(lines)


if __name__ == "__main__":
    main()
