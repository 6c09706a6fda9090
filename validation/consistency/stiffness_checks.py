"""Linearised bearing stiffness and damping (quasi-static solver) against the
DEM reference engine, and the 3-DOF vibration model against the linearised
full model.

1. Stiffness, DEM against quasi-static (6208, F_r = 3000 N, P_d = 0; also
   P_d = +12.6 um at 500 rad/s): the reference engine's inner ring
   translates in x, y, z (no tilt). Static load increments at the operating
   point: F_r = 3000 -+ 150 N (radial) and F_a = 25 N (axial; the
   deep-groove bearing is symmetric, z(-F_a) = -z(F_a), so F_a / z is the
   central difference about F_a = 0). Each run starts from the analytic
   state, settles for max(20 ms, 3 ball passes) and averages the ring
   position over whole ball-pass periods 2 pi / (Z omega_cage) (the
   stiffness varies with the ball-set position). The quasi-static value
   compared is the same mean: the compliance of the translational block
   (K[:3, :3] inverted: the DEM ring cannot tilt) averaged over Z ball-set
   positions within one ball pitch, k = 1 / mean(compliance). Rigid rings
   in the quasi-static solver (the DEM rings do not grow). Speeds 100 rad/s
   (low), 500 rad/s (the DEM papers') and 3000 rad/s (centrifugal ball
   force 3.1 times that at 1700 rad/s: a model check above the 6208's
   catalogue speed); at 3000 rad/s also an axial increment of 100 N and a
   run without friction (friction="none"), because the DEM's axial
   stiffness at that speed depends on its friction, and the matrix holds
   the ball kinematics (the gyroscopic traction) at the operating point
   while the secants re-solve them.
2. Damping, DEM free decay against the damping matrix: the ring starts with a
   small velocity (0.02 m/s in x or y) and the same run without it is
   subtracted (the difference is the ring's free vibration); damping ratio
   from the logarithmic decrement of 15 peaks, against
   zeta = C_ii / (2 sqrt(K_ii m)) and sqrt(K_ii / m) with the DEM's ring
   mass m, phase 0. With the DEM's friction (Cundall-Strack spring) and
   without it (friction="none"): the matrix holds the normal damping of the
   contacts only.
3. 3-DOF model (El Had et al. 2014; derived 6004, 500 N, 3000 rpm,
   P_d = 12.5 um, contact-model damping) against the quasi-static 6004 at
   the same point: the most loaded ball's Hertz tangent stiffness and
   normal damping at both contacts, the bearing's radial stiffness K_xx
   against the 3-DOF's one-ball series link, and the rigid inner ring
   (the 3-DOF's ring mass) on the 5x5 stiffness and damping against the
   3-DOF's modes.

    python validation/consistency/stiffness_checks.py      # writes validation/out/stiffness_checks.json and stiffness_*.png/.csv
"""
import json
import math
import time
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.model.layout import P_MR
from exudyn_bearing.outputs.jsonio import to_jsonable
from exudyn_bearing.outputs.plotting import pyplot, save_figure
from exudyn_bearing.physics import kinematics
from exudyn_bearing.solvers.reference import ReferenceEngine
from exudyn_bearing.solvers.vibration import linear
from exudyn_bearing.solvers.vibration import three_dof as td

HERE = Path(__file__).resolve().parent
OUT = HERE.parent / "out"
FR = 3000.0
D_FR = 150.0
D_FA = 25.0
DT = 3.5e-6            # below the 6208's stable-step estimate (3.9 us)
TOLERANCE = 0.05       # the target: the DEM gives the same radial and axial stiffness within 5 %


def ball_pass_period(bearing, omega):
    wc = float(kinematics.cage_speed(omega, 0.0, bearing.ball_radius, bearing.pitch_radius,
                                     bearing.free_contact_angle))
    return 2.0 * math.pi / (bearing.n_balls * wc)


def dem_mean_position(bearing, fr, fa, omega, n_periods, friction="history"):
    """Mean ring position (x, y, z) [m] over n_periods ball passes after settling, and the run's wall [s]."""
    tbp = ball_pass_period(bearing, omega)
    settle = max(0.02, 3.0 * tbp)
    t_end = settle + n_periods * tbp
    sc = eb.Scenario(Fr=fr, Fa=fa, omega=omega, t_end=t_end, dt=DT, sample_dt=DT * 3, friction=friction)
    rec = ReferenceEngine(bearing, sc).run()
    t, ring = rec.data["t"], rec.data["ring"]
    m = t > t_end - n_periods * tbp
    return ring[m, :3].mean(axis=0), ring[m, :3].std(axis=0), rec.wall_s, t_end


def quasistatic_mean(bearing, omega, dfa=D_FA):
    """Phase-averaged compliance of the translational block (tilts held), the phase-0 matrices, the
    secant axial stiffness at dfa and the radial secant over +-D_FR (secants: each load solved with its
    own kinematics, where the matrix holds them)."""
    z = bearing.n_balls
    comp, kxx0 = [], []
    z_fa, x_p, x_m = [], [], []
    held = {"tilt_x": 0.0, "tilt_y": 0.0}
    for ph in 2.0 * math.pi / z * np.arange(z) / z:
        s = eb.solve_quasistatic(bearing, FR, omega=omega, phase=ph, ring_growth=False)
        comp.append(np.linalg.inv(s.stiffness[:3, :3]))
        kxx0.append(s.stiffness[0, 0])
        z_fa.append(eb.solve_quasistatic(bearing, FR, dfa, omega=omega, phase=ph, ring_growth=False,
                                         stiffness=False, fixed=held).displacement[2])
        x_p.append(eb.solve_quasistatic(bearing, FR + D_FR, omega=omega, phase=ph, ring_growth=False,
                                        stiffness=False).displacement[0])
        x_m.append(eb.solve_quasistatic(bearing, FR - D_FR, omega=omega, phase=ph, ring_growth=False,
                                        stiffness=False).displacement[0])
    c = np.mean(comp, axis=0)
    s0 = eb.solve_quasistatic(bearing, FR, omega=omega, ring_growth=False)
    return {"k_xx": 1.0 / c[0, 0], "k_zz": 1.0 / c[2, 2], "k_xx_phase0_entry": float(s0.stiffness[0, 0]),
            "k_zz_phase0_entry": float(s0.stiffness[2, 2]), "k_xx_entry_range": [min(kxx0), max(kxx0)],
            "k_xx_secant": 2.0 * D_FR / (np.mean(x_p) - np.mean(x_m)), "k_zz_secant": dfa / np.mean(z_fa),
            "stiffness_phase0": s0.stiffness, "damping_phase0": s0.damping}


def stiffness_case(name, bearing, omega, n_periods, friction="history", dfa=D_FA):
    t0 = time.perf_counter()
    xm, sm, w1, te = dem_mean_position(bearing, FR - D_FR, 0.0, omega, n_periods, friction)
    xp, sp, w2, _ = dem_mean_position(bearing, FR + D_FR, 0.0, omega, n_periods, friction)
    xa, sa, w3, _ = dem_mean_position(bearing, FR, dfa, omega, n_periods, friction)
    dem = {"k_xx": 2.0 * D_FR / (xp[0] - xm[0]), "k_zz": dfa / xa[2], "x_minus": xm.tolist(), "x_plus": xp.tolist(),
           "x_axial": xa.tolist(), "ripple_x_std": float(sp[0]), "wall_s": w1 + w2 + w3, "t_end": te,
           "n_periods": n_periods, "ball_pass_period": ball_pass_period(bearing, omega)}
    qs = quasistatic_mean(bearing, omega, dfa)
    err = {"k_xx": dem["k_xx"] / qs["k_xx"] - 1.0, "k_zz": dem["k_zz"] / qs["k_zz"] - 1.0}
    row = {"case": name, "omega": omega, "Pd": bearing.diametral_clearance, "friction": friction, "dFa": dfa,
           "dem": dem, "quasistatic": qs,
           "relative_difference": err, "within_tolerance": bool(max(abs(v) for v in err.values()) < TOLERANCE),
           "wall_s": time.perf_counter() - t0}
    print(f"{name:>22}: k_xx DEM {dem['k_xx']:.5g} QS {qs['k_xx']:.5g} ({100 * err['k_xx']:+.2f} %), k_zz DEM "
          f"{dem['k_zz']:.5g} QS {qs['k_zz']:.5g} ({100 * err['k_zz']:+.2f} %; QS secant {qs['k_zz_secant']:.5g}); "
          f"DEM wall {dem['wall_s']:.1f} s")
    return row


class _KickedEngine(ReferenceEngine):
    """The reference engine with an initial ring velocity added (the free-decay check)."""

    kick = np.zeros(3)

    def initial_state(self):
        st = super().initial_state()
        st["ring"][3:6] += self.kick
        return st


def decay_fit(t, d, n_peaks=15):
    """Damped natural frequency [rad/s], undamped frequency and damping ratio from the positive peaks."""
    i = np.flatnonzero((d[1:-1] > d[:-2]) & (d[1:-1] >= d[2:]) & (d[1:-1] > 0.0)) + 1
    i = i[:n_peaks]
    tp, ap = t[i], d[i]
    sigma = -np.polyfit(tp, np.log(ap), 1)[0]
    wd = 2.0 * math.pi / np.mean(np.diff(tp))
    wn = math.hypot(wd, sigma)
    return wd, wn, sigma / wn, len(i)


def damping_case(omega, axis, friction, v0=0.02, t_end=0.006, dt=1e-6):
    b = eb.catalog["6208"]
    sc = eb.Scenario(Fr=FR, omega=omega, t_end=t_end, dt=dt, sample_dt=dt, friction=friction)
    runs = []
    for k in (0.0, v0):
        e = _KickedEngine(b, sc)
        e.kick = np.zeros(3)
        e.kick[axis] = k
        runs.append(e.run())
    t = runs[0].data["t"]
    d = runs[1].data["ring"][:, axis] - runs[0].data["ring"][:, axis]
    wd, wn, zeta, n = decay_fit(t, d)
    m = float(e.params[P_MR])
    s = eb.solve_quasistatic(b, FR, omega=omega, ring_growth=False)
    k, c = s.stiffness[axis, axis], s.damping[axis, axis]
    qs = {"omega_n": math.sqrt(k / m), "zeta": c / (2.0 * math.sqrt(k * m)), "k": k, "c": c}
    row = {"omega": omega, "axis": "xyz"[axis], "friction": friction, "kick_m_s": v0, "ring_mass": m,
           "dem": {"omega_d": wd, "omega_n": wn, "zeta": zeta, "peaks": n, "amplitude_m": float(np.abs(d).max())},
           "quasistatic": qs, "zeta_ratio": zeta / qs["zeta"], "omega_ratio": wn / qs["omega_n"],
           "signal": {"t": t, "d": d}}
    print(f"decay {omega:6.0f} rad/s {'xyz'[axis]} friction {friction:8s}: zeta DEM {zeta:.5f} QS {qs['zeta']:.5f} "
          f"(ratio {zeta / qs['zeta']:.3f}), omega_n DEM {wn:.0f} QS {qs['omega_n']:.0f} 1/s (ratio "
          f"{wn / qs['omega_n']:.3f})")
    return row


def ring_section_inertia(mass, r_in, r_out, width):
    """Moment of inertia of a rectangular-section ring about a diameter [kg m^2]."""
    return mass * (r_in ** 2 + r_out ** 2) / 4.0 + mass * width ** 2 / 12.0


def three_dof_comparison():
    """The 3-DOF model's derived 6004 against the quasi-static 6004 at the same operating point."""
    fr, omega, pd = 500.0, 2.0 * math.pi * 50.0, 12.5e-6
    p = td.derived_parameters("6004", radial_load=fr, omega=omega, diametral_clearance=pd,
                              film_damping="contact_model")
    p_hertz = td.derived_parameters("6004", radial_load=fr, omega=omega, diametral_clearance=pd, link="hertz",
                                    film_damping="contact_model")
    dv = p.derivation
    b = eb.catalog["6004"].with_clearance(pd)
    s = eb.solve_quasistatic(b, fr, omega=omega, ring_growth=False)
    bl = s.balls
    j = int(np.argmax(bl["q_inner"]))
    kt = {r: 1.5 * bl[f"q_{r}"][j] / bl[f"delta_{r}"][j] for r in ("inner", "outer")}
    # one ball: inner and outer Hertz contacts in series
    k_ball = {k: 1.0 / (1.0 / a + 1.0 / c) for k, a, c in (
        ("quasistatic_hertz", kt["inner"], kt["outer"]),
        ("three_dof_hertz", dv["contacts"]["inner"]["k_hertz"], dv["contacts"]["outer"]["k_hertz"]),
        ("three_dof_series_film", p.k_inner_contact, p.k_outer_contact))}
    # the bearing's radial stiffness as the sum over balls of the series stiffness times cos^2 psi
    ki = 1.5 * bl["q_inner"] / np.where(bl["delta_inner"] > 0, bl["delta_inner"], 1.0)
    ko = 1.5 * bl["q_outer"] / np.where(bl["delta_outer"] > 0, bl["delta_outer"], 1.0)
    loaded = (bl["q_inner"] > 0) & (bl["q_outer"] > 0)
    k_sum = float(np.sum(np.where(loaded, ki * ko / (ki + ko), 0.0) * np.cos(bl["psi"]) ** 2))
    kxx = float(s.stiffness[0, 0])
    # rigid inner ring of the 3-DOF model's mass on the 5x5 matrices (outer ring fixed)
    ring = dv["inner_ring"]
    m = ring["mass"]
    r_in, r_out = ring["radius"] - 0.5 * ring["thickness"], ring["radius"] + 0.5 * ring["thickness"]
    i_d = ring_section_inertia(m, r_in, r_out, dv["dimensions"]["width"])
    mass = np.diag([m, m, m, i_d, i_d])
    full = linear.modal_analysis(mass, s.damping, s.stiffness)
    res3 = td.analyse(p)
    shapes = np.abs(res3.modal.mode_shapes)
    # the oscillating mode in which the inner ring has the largest share of the motion
    upper = [i for i in range(shapes.shape[0]) if res3.modal.eigenvalues[i].imag > 0.0]
    inner_mode = max(upper, key=lambda i: shapes[i, 2] / shapes[i].sum())
    out = {
        "operating_point": {"bearing": "6004", "Fr": fr, "omega": omega, "Pd": pd, "ring_growth": False},
        "q_max": {"quasistatic": float(bl["q_inner"][j]), "three_dof": dv["q_max"],
                  "three_dof_outer": dv["contacts"]["outer"]["load"], "quasistatic_outer": float(bl["q_outer"][j])},
        "k_hertz": {"quasistatic_inner": kt["inner"], "quasistatic_outer": kt["outer"],
                    "three_dof_inner": dv["contacts"]["inner"]["k_hertz"],
                    "three_dof_outer": dv["contacts"]["outer"]["k_hertz"]},
        "k_film": {"inner": dv["contacts"]["inner"]["k_film"], "outer": dv["contacts"]["outer"]["k_film"]},
        "c_contact": {"quasistatic_inner": float(bl["c_normal_inner"][j]),
                      "quasistatic_outer": float(bl["c_normal_outer"][j]),
                      "three_dof_inner": dv["contacts"]["inner"]["c_contact_model"],
                      "three_dof_outer": dv["contacts"]["outer"]["c_contact_model"],
                      "lambda_quasistatic_inner": float(bl["film_parameter_inner"][j]),
                      "lambda_three_dof_inner": dv["contacts"]["inner"]["film_parameter"],
                      "h_min_quasistatic_inner": float(bl["h_min_inner"][j]),
                      "h_min_three_dof_inner": dv["contacts"]["inner"]["h_min"]},
        "k_ball": k_ball, "k_xx": kxx, "k_yy": float(s.stiffness[1, 1]), "k_xx_sum_over_balls": k_sum,
        "c_xx": float(s.damping[0, 0]), "c_yy": float(s.damping[1, 1]),
        "effective_balls": kxx / k_ball["three_dof_hertz"],
        "stiffness": s.stiffness, "damping": s.damping,
        "ring": {"mass": m, "inertia_diametral": i_d, "radius": ring["radius"]},
        "full_modes": [{"f_n_hz": float(f), "zeta": float(z), "shape_abs": np.abs(sh).tolist()}
                       for f, z, sh in zip(full.natural_frequencies, full.damping_ratios, full.mode_shapes)],
        "three_dof_modes": [{"f_n_hz": float(f), "zeta": float(z), "shape_abs": np.abs(sh).tolist()}
                            for f, z, sh in zip(res3.modal.natural_frequencies, res3.modal.damping_ratios,
                                                res3.modal.mode_shapes)],
        "three_dof_inner_mode": inner_mode,
        "three_dof_hertz_link_modes": [float(f) for f in td.analyse(p_hertz).modal.natural_frequencies],
        "ring_on_one_ball_hz": math.sqrt((p.k_inner_ring + k_ball["three_dof_series_film"]) / m) / (2 * math.pi),
        "ring_on_bearing_x_hz": math.sqrt(kxx / m) / (2 * math.pi),
    }
    print(f"6004: Q_max QS {out['q_max']['quasistatic']:.2f} N, 3-DOF {dv['q_max']:.2f} N; Hertz k inner QS "
          f"{kt['inner']:.4g} 3-DOF {dv['contacts']['inner']['k_hertz']:.4g} N/m; one-ball series link "
          f"{k_ball['three_dof_series_film']:.4g} N/m vs K_xx {kxx:.4g} N/m (sum over balls {k_sum:.4g}); effective "
          f"balls {out['effective_balls']:.3f}")
    print("6004 rigid inner ring on the 5x5: " + ", ".join(f"{m_['f_n_hz']:.0f} Hz (zeta {m_['zeta']:.3g})"
                                                          for m_ in out["full_modes"][::2]))
    print("3-DOF modes: " + ", ".join(f"{m_['f_n_hz']:.0f} Hz" for m_ in out["three_dof_modes"][::2]))
    return out


def plot_stiffness(rows, png):
    plt = pyplot()
    fig, ax = plt.subplots(1, 2, figsize=(11, 3.8), sharey=True)
    labels = [f"{r['case']}, dF_a {r['dFa']:g} N" for r in rows]
    y = np.arange(len(rows))[::-1]
    cols = {"case_index": np.arange(len(rows))}
    for a, key, title in ((ax[0], "k_xx", "radial k_xx"), (ax[1], "k_zz", "axial k_zz")):
        dem = np.array([r["dem"][key] for r in rows])
        qs = np.array([r["quasistatic"][key] for r in rows])
        diff = 100.0 * (dem / qs - 1.0)
        a.axvspan(-100 * TOLERANCE, 100 * TOLERANCE, color="0.9", label=f"+-{100 * TOLERANCE:.0f} % (target)")
        a.barh(y, diff, 0.6, color=["C0" if abs(d) < 100 * TOLERANCE else "C3" for d in diff])
        for yi, d_, q_ in zip(y, diff, qs):
            a.annotate(f"{d_:+.2f} % (QS {q_:.4g} N/m)", (0.0, yi), xytext=(4 if d_ <= 0 else -4, 0),
                       textcoords="offset points", ha="left" if d_ <= 0 else "right", va="center", fontsize=7)
        a.axvline(0.0, color="k", lw=0.8)
        a.set_xlim(-10, 10)
        a.set_xlabel(f"DEM / quasi-static - 1 [%], {title}")
        a.grid(alpha=0.3, axis="x")
        a.legend(fontsize=7, loc="lower left")
        cols[f"{key}_quasistatic_N_per_m"] = qs
        cols[f"{key}_dem_N_per_m"] = dem
    ax[0].set_yticks(y)
    ax[0].set_yticklabels(labels, fontsize=8)
    fig.suptitle("6208, F_r = 3000 N: DEM load increments against the quasi-static matrix (phase mean)", fontsize=10)
    return save_figure(fig, png, cols)


def plot_decay(row, png):
    plt = pyplot()
    t, d = row["signal"]["t"], row["signal"]["d"]
    qs = row["quasistatic"]
    amp = np.abs(d).max()
    env = amp * np.exp(-qs["zeta"] * qs["omega_n"] * t)
    fig, ax = plt.subplots(figsize=(8, 3.8))
    ax.plot(t * 1e3, d * 1e9, lw=0.8, label=f"DEM, friction {row['friction']} (kicked - unkicked run)")
    ax.plot(t * 1e3, env * 1e9, "k--", lw=1, label=f"quasi-static zeta = {qs['zeta']:.4f} envelope")
    ax.plot(t * 1e3, -env * 1e9, "k--", lw=1)
    ax.set_xlabel("time [ms]")
    ax.set_ylabel(f"ring {row['axis']} [nm]")
    ax.set_title(f"6208, F_r = 3000 N, {row['omega']:g} rad/s: free decay of the inner ring; DEM zeta = "
                 f"{row['dem']['zeta']:.4f}", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return save_figure(fig, png, {"t_s": t, "ring_m": d, "quasistatic_envelope_m": env})


def main():
    OUT.mkdir(exist_ok=True)
    warnings.simplefilter("ignore", eb.StepSizeWarning)
    t0 = time.perf_counter()
    b = eb.catalog["6208"]
    cases = [("100 rad/s", b, 100.0, 6), ("500 rad/s", b, 500.0, 20),
             ("500 rad/s, Pd +12.6 um", b.with_clearance(12.6e-6), 500.0, 20), ("3000 rad/s", b, 3000.0, 40),
             ("3000 rad/s", b, 3000.0, 40, "history", 100.0),
             ("3000 rad/s, no friction", b, 3000.0, 40, "none")]
    stiff = [stiffness_case(*c) for c in cases]
    decay = [damping_case(w, ax, fr) for w, ax, fr in (
        (100.0, 0, "history"), (500.0, 0, "history"), (500.0, 1, "history"), (3000.0, 0, "history"),
        (100.0, 0, "none"), (500.0, 0, "none"), (500.0, 1, "none"), (3000.0, 0, "none"))]
    png_k = plot_stiffness(stiff, OUT / "stiffness_dem_check.png")
    png_d = plot_decay(decay[1], OUT / "stiffness_decay_500.png")
    three = three_dof_comparison()
    for r in decay:
        r.pop("signal")
    out = {"stiffness": stiff, "damping": decay, "three_dof": three, "tolerance": TOLERANCE,
           "increments": {"dFr": D_FR, "dFa": D_FA, "dt": DT},
           "plots": [str(png_k), str(png_d)], "wall_s": time.perf_counter() - t0}
    (OUT / "stiffness_checks.json").write_text(json.dumps(to_jsonable(out), indent=1))
    print(f"all stiffness cases within {100 * TOLERANCE:.0f} %: {all(r['within_tolerance'] for r in stiff)}; "
          f"wall {out['wall_s']:.0f} s; written {OUT / 'stiffness_checks.json'}")


def report_section(run):
    """The report's section on the linearised stiffness and damping, from stiffness_checks.json and its
    figures (bench_stiffness.py's part, the speed table, follows it)."""
    d = run.load("stiffness_checks.json")
    lines = ["## Linearised bearing stiffness and damping (quasi-static solver)", "",
             f"Command: `{run.command}` (figures below, each with its CSV in "
             "validation/out). Matrices: `solve_quasistatic(...).stiffness` "
             "(central differences) and `.damping` (the contact model's normal damping condensed over each ball's "
             "two contacts in series); theory: docs/theory/vibration.md, sec. 8.", "",
             f"**Stiffness against the DEM** (6208, F_r = 3000 N; reference engine, dt = {d['increments']['dt'] * 1e6:g} "
             f"us; static increments F_r -+ {d['increments']['dFr']:g} N and F_a as given; ring position averaged "
             "over whole ball-pass periods after settling). Quasi-static value: the compliance of the translational "
             "block (the DEM ring cannot tilt) averaged over Z ball-set positions, rigid rings. The target is agreement within "
             f"{100 * d['tolerance']:.0f} %.", "",
             "| case | friction | dF_a [N] | k_xx DEM [N/m] | k_xx QS [N/m] | diff | k_zz DEM [N/m] | k_zz QS [N/m] | diff "
             "| k_zz QS secant [N/m] | within | DEM wall [s] |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in d["stiffness"]:
        dm, q, e = r["dem"], r["quasistatic"], r["relative_difference"]
        lines.append(f"| {r['case']} | {r['friction']} | {r['dFa']:g} | {dm['k_xx']:.5g} | {q['k_xx']:.5g} | "
                     f"{100 * e['k_xx']:+.2f} % | {dm['k_zz']:.5g} | {q['k_zz']:.5g} | {100 * e['k_zz']:+.2f} % | "
                     f"{q['k_zz_secant']:.5g} | {'yes' if r['within_tolerance'] else '**no**'} | {dm['wall_s']:.1f} |")
    fast = [r for r in d["stiffness"] if r["omega"] == 3000.0]
    lines += ["", "The matrix holds the ball kinematics (and so the gyroscopic traction) at the operating point; the "
              "secant column re-solves them at F_a. At 100 and 500 rad/s DEM and matrix agree within "
              + f"{100 * max(max(abs(v) for v in r['relative_difference'].values()) for r in d['stiffness'] if r['omega'] < 3000):.2f} %. "
              "At 3000 rad/s the radial stiffness agrees; the DEM's axial stiffness depends on its friction: "
              + "; ".join(f"friction {r['friction']}, dF_a {r['dFa']:g} N: {r['dem']['k_zz']:.4g} N/m" for r in fast)
              + f" against the matrix's {fast[0]['quasistatic']['k_zz']:.4g} N/m. Without friction the DEM reproduces "
              "the matrix; with it, its axial stiffness depends on the increment, so its tangential contact forces "
              "(Cundall-Strack springs, Coulomb friction) take part in the axial balance at this speed, which the "
              "matrix (normal contact forces and the gyroscopic traction, kinematics held) does not model. The "
              "mechanism inside the DEM was not isolated.", "",
              "**Damping against the DEM** (free decay: the ring kicked with 0.02 m/s, minus the same run without "
              "kick; logarithmic decrement of 15 peaks; dt = 1 us; prediction zeta = C_ii / (2 sqrt(K_ii m)), "
              "omega_n = sqrt(K_ii / m), m the DEM's ring mass, phase 0):", "",
              "| omega [rad/s] | axis | friction | zeta DEM | zeta matrix | ratio | omega_n DEM [1/s] | omega_n matrix "
              "[1/s] | ratio |", "|---|---|---|---|---|---|---|---|---|"]
    for r in d["damping"]:
        lines.append(f"| {r['omega']:g} | {r['axis']} | {r['friction']} | {r['dem']['zeta']:.5f} | "
                     f"{r['quasistatic']['zeta']:.5f} | {r['zeta_ratio']:.3f} | {r['dem']['omega_n']:.0f} | "
                     f"{r['quasistatic']['omega_n']:.0f} | {r['omega_ratio']:.3f} |")
    none = [r for r in d["damping"] if r["friction"] == "none"]
    lines += ["", "The matrix holds the contacts' normal damping only. With friction off the DEM's damping ratio is "
              f"within {100 * max(abs(r['zeta_ratio'] - 1) for r in none):.1f} % of it; with the DEM's friction "
              "the ratio grows with speed (friction damps the ring through the balls' tangential forces). The "
              "DEM's frequencies are lower because the condensation neglects the balls' inertia (friction off: "
              f"{100 * (1 - min(r['omega_ratio'] for r in none)):.1f} % at most) and, with friction, the balls' "
              "rolling inertia that the tangential forces couple to the ring.", ""]
    lines += run.figure("stiffness_dem_check.png", "Relative difference of the DEM's radial (left) and axial (right) "
                        "stiffness from the quasi-static matrix for each case and increment, with the 5 % target band.")
    lines += run.figure("stiffness_decay_500.png", "Free decay of the kicked inner ring at 500 rad/s in the DEM (kicked "
                        "minus unkicked run) against the envelope of the matrix's damping ratio.")
    t = d["three_dof"]
    op = t["operating_point"]
    r_ring = t["ring"].get("radius", 0.011)
    scale = np.array([1.0, 1.0, 1.0, r_ring, r_ring])
    names = ("x", "y", "axial", "tilt_x", "tilt_y")

    def dominant(m):
        a = np.array(m["shape_abs"]) * scale    # tilts times the ring radius: lengths like the translations
        order = np.argsort(a)[::-1]
        return " + ".join(names[i] for i in order if a[i] > 0.3 * a[order[0]])

    def zeta(z):
        return f"{z:.3g}" if abs(z) > 1e-9 else "0"
    inner = t["three_dof_modes"][t["three_dof_inner_mode"]]
    lines += [f"**3-DOF model against the linearised full model** (6004, F_r = {op['Fr']:g} N, "
              f"{op['omega'] * 30 / np.pi:.0f} rpm, P_d = {op['Pd'] * 1e6:g} um, rigid rings): most loaded ball "
              f"Q = {t['q_max']['quasistatic']:.2f} N (3-DOF {t['q_max']['three_dof']:.2f} N); Hertz tangent "
              f"stiffness inner / outer {t['k_hertz']['quasistatic_inner']:.4g} / {t['k_hertz']['quasistatic_outer']:.4g} "
              f"N/m (3-DOF {t['k_hertz']['three_dof_inner']:.4g} / {t['k_hertz']['three_dof_outer']:.4g}); contact "
              f"damping {t['c_contact']['quasistatic_inner']:.4g} / {t['c_contact']['quasistatic_outer']:.4g} N s/m "
              f"(3-DOF contact-model reading {t['c_contact']['three_dof_inner']:.4g} / "
              f"{t['c_contact']['three_dof_outer']:.4g}; Lambda {t['c_contact']['lambda_quasistatic_inner']:.3f}). "
              f"One ball, inner and outer Hertz in series: {t['k_ball']['quasistatic_hertz']:.4g} N/m; the 3-DOF "
              f"link with the film in series {t['k_ball']['three_dof_series_film']:.4g} N/m. The bearing: K_xx = "
              f"{t['k_xx']:.4g} N/m (sum over the balls of the series stiffness times cos^2 psi: "
              f"{t['k_xx_sum_over_balls']:.4g}), K_yy = {t['k_yy']:.4g} N/m, C_xx = {t['c_xx']:.4g}, C_yy = "
              f"{t['c_yy']:.4g} N s/m: the 3-DOF model's one-ball line holds 1/{t['effective_balls']:.3f} of the "
              "bearing's radial stiffness.", "",
              f"Rigid inner ring of the 3-DOF model's mass ({t['ring']['mass'] * 1e3:.2f} g, diametral inertia "
              f"{t['ring']['inertia_diametral']:.3g} kg m^2) on the 5x5 matrices, outer ring fixed: "
              + ", ".join(f"{m['f_n_hz']:.0f} Hz ({dominant(m)}, zeta {zeta(m['zeta'])})" for m in t["full_modes"][::2])
              + f". The 3-DOF model's inner-ring mode: {inner['f_n_hz']:.0f} Hz (zeta {inner['zeta']:.3g}), carried "
              f"by its ring-bending spring to ground k3 and one ball link (sqrt((k3 + k_link)/M3) = "
              f"{t['ring_on_one_ball_hz']:.0f} Hz), where the rigid ring on the bearing's K_xx alone gives "
              f"{t['ring_on_bearing_x_hz']:.0f} Hz; all 3-DOF modes: "
              + ", ".join(f"{m['f_n_hz']:.0f} Hz" for m in t["three_dof_modes"][::2])
              + ". The full model adds the bearing's y, axial and tilt modes, which the 3-DOF line cannot have; its "
              "axial and tilt modes are undamped here (radial contact normals carry no damping across them).", ""]
    return "\n".join(lines)


if __name__ == "__main__":
    main()
