"""Varying-compliance (VC) vibration of a radially loaded ball bearing against the published quasi-static theory.

Sunnersjo (J. Sound Vib. 58 (1978) 363-373) explains the VC vibration with rigid rings and balls that are
Hertz springs: as the ball set turns with the cage, the load is carried alternately by a ball under the
load line and by two balls straddling it, so the ring centre moves with the ball-pass frequency
Z f_c = Z k_c f_s and its harmonics. Tomovic (Appl. Sci. 10 (2020) 670) computes the peak-to-peak
amplitude from exactly these two boundary positions. The papers' own rotor data (Sunnersjo's test rig, the
6306-type bearings of Fukata et al., Bull. JSME 28 (1985) 899-904) were not available to this project, so
the published numbers themselves are not compared; what is compared is the published theory, evaluated
here in closed form for the catalogue 6208 (docs/theory/varying_compliance.md):

(a) closed form: the two boundary positions give the centre displacement
    delta(theta) = (F / (K_n S(theta)))^(2/3), S(theta) = sum_j max(cos(theta + 2 pi j/Z), 0)^(5/2)
    (zero clearance), so the peak-to-peak displacement along the load is |delta(0) - delta(pi/Z)|, and
    its relative size depends on Z alone; the full orbit over a ball passage (x along the load, y across
    it, any clearance) solves the two force balances at each cage angle;
(b) the quasi-static level (GeneralizedAlpha) on a 2.5 kg shaft at 50 rad/s (Z f_c far below the shaft's
    natural frequency on the bearing): peak-to-peak x and y and the extremes of x against (a). The shaft's
    damper to ground (2e4 N s/m, levels_checks.shaft) settles the lateral vibration that the start excites;
    at Z f_c = 28 Hz its force is c 2 pi Z f_c / k = 4 % (x) and 5 % (y) of the elastic one, in quadrature,
    which changes the amplitudes by about 0.1 %;
(c) the same without the damper at higher speeds: the first-harmonic amplitude at Z f_c against (a) times the one-degree-of-
    freedom amplification 1/|1 - (Z f_c / f_n)^2| (f_n from the level's linearised k_xx), and the speed at
    which Z f_c meets f_n;
(d) 20 um diametral clearance at 50 rad/s (with the damper) against (a) with clearance;
(e) a short ball-element run (fast mode, VelocityVerlet) at 500 rad/s: its spectrum peak against Z times
    its own mean cage speed.

    python validation/published/levels_published_vc.py [--out validation/out/levels] [--no-balls] [--periods 6]

Writes levels_published_vc.csv/.png and levels_published_vc.json into --out.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "consistency"))  # levels_checks.py, peer_builtin.py
from levels_checks import shaft, spectrum  # noqa: E402
from scipy import optimize

import exudyn_bearing as eb
from exudyn_bearing.outputs.plotting import pyplot, save_csv, save_figure
from exudyn_bearing.physics.kinematics import cage_speed
from exudyn_bearing.physics.load_distribution import race_stiffness
from exudyn_bearing.simulate import quasistatic_start

ROOT = Path(__file__).resolve().parents[2]
MASS = 2.5  # kg, the shaft of levels_checks.shaft
LOAD = 500.0  # N


# -- (a) closed form ------------------------------------------------------------------------------------------
def s_sum(n_balls, theta):
    """S(theta) = sum_j max(cos(theta + 2 pi j/Z), 0)^(5/2): the radial load of Z Hertz balls at unit
    approach of rigid rings without clearance (Sunnersjo 1978) is K_n delta^(3/2) S(theta)."""
    c = np.cos(theta + 2.0 * np.pi * np.arange(n_balls) / n_balls)
    return float(np.sum(np.clip(c, 0.0, None) ** 2.5))


def boundary_displacements(n_balls, kn, load):
    """Centre displacement along the load [m] with a ball under the load (theta = 0) and with two balls
    straddling it (theta = pi/Z), zero clearance: (F / (K_n S))^(2/3) (Tomovic 2020's two positions)."""
    return tuple((load / (kn * s_sum(n_balls, th))) ** (2.0 / 3.0) for th in (0.0, math.pi / n_balls))


def relative_ptp(n_balls):
    """Peak-to-peak displacement along the load over its mean, zero clearance: depends on Z alone."""
    s0, s1 = s_sum(n_balls, 0.0), s_sum(n_balls, math.pi / n_balls)
    return abs(1.0 - (s0 / s1) ** (2.0 / 3.0))


def orbit(n_balls, kn, load, clearance=0.0, n=64):
    """Ring-centre position (x along the load, y across) [m] at n cage angles over one ball passage
    (0 .. 2 pi/Z): the two force balances sum_j K_n (x cos psi_j + y sin psi_j - P_d/2)_+^(3/2) (cos, sin)
    = (F, 0), rigid rings."""
    th = np.arange(n) * 2.0 * math.pi / n_balls / n
    out = np.zeros((n, 2))
    guess = np.array([boundary_displacements(n_balls, kn, load)[0] + 0.5 * clearance, 0.0])
    for k, t in enumerate(th):
        psi = t + 2.0 * np.pi * np.arange(n_balls) / n_balls
        c, s = np.cos(psi), np.sin(psi)

        def res(u, c=c, s=s):  # u in um: the solver works on numbers of order one
            d = np.clip(1e-6 * (u[0] * c + u[1] * s) - 0.5 * clearance, 0.0, None) ** 1.5
            return [kn * np.sum(d * c) / load - 1.0, kn * np.sum(d * s) / load]

        sol = optimize.root(res, 1e6 * guess, method="hybr", options={"xtol": 1e-13})
        if max(abs(r) for r in res(sol.x)) > 1e-10:
            raise RuntimeError(f"orbit: no force balance at cage angle {t:.4g} rad")
        guess = 1e-6 * sol.x
        out[k] = guess
    return th, out


def cage_ratio(b):
    """Kinematic cage speed per shaft speed, outer ring fixed (physics.kinematics.cage_speed)."""
    return float(cage_speed(1.0, 0.0, b.ball_radius, b.pitch_radius, b.free_contact_angle))


def first_harmonic(x):
    """Amplitude of the first Fourier harmonic of one period sampled uniformly."""
    return 2.0 * abs(np.fft.rfft(x)[1]) / x.size


# -- (b)-(d) the quasi-static level -----------------------------------------------------------------------------
def run_level(bearing, omega, t_end, step, damper=False):
    """The shaft of levels_checks under LOAD along x at ``omega`` on ``bearing`` at the quasi-static level,
    started at the quasi-static pose, with or without its damper to ground; returns (samples, level, wall)."""
    _sc, mbs, node, m_b, m_g, _pos = shaft((LOAD, 0.0, 0.0), omega=omega, damper=damper)
    br = eb.CreateBallBearing(mbs, bearing, m_b, m_g, model="quasistatic", initialLoad=(LOAD, 0.0),
                              initialOmega=omega, sampleInterval=step)
    mbs.SetNodeParameter(node, "initialCoordinates", [*br.initialRingDisplacement, 0.0])
    mbs.Assemble()
    ss = br.SimulationSettings(t_end, stepSize=step)
    t0 = time.perf_counter()
    with eb.filter_exudyn_notes():
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    return br.samples(), br, time.perf_counter() - t0


def last_periods(s, period, n):
    """Samples of the last n whole periods."""
    t = s["t"]
    return t >= t[-1] - n * period + 0.5 * (t[1] - t[0])


def harmonic_amplitude(t, x, f):
    """Amplitude of x at frequency f by projection over the given (whole-period) samples."""
    x = x - x.mean()
    return 2.0 * abs(np.mean(x * np.exp(-2j * math.pi * f * t)))


def check_low_speed(b, kn, omega=50.0, clearance=0.0, periods=3):
    bc = b.with_clearance(clearance)
    th, uv = orbit(b.n_balls, kn, LOAD, clearance)
    f_vc = b.n_balls * cage_ratio(b) * omega / (2.0 * math.pi)
    s, br, wall = run_level(bc, omega, (periods + 2) / f_vc, 1e-4, damper=True)
    k = last_periods(s, 1.0 / f_vc, periods)
    x, y = s["displacement"][k, 0], s["displacement"][k, 1]
    res = {"omega": omega, "clearance_m": clearance, "f_vc_Hz": f_vc, "wall_s": wall,
           "closed_x_ptp_m": float(np.ptp(uv[:, 0])), "level_x_ptp_m": float(np.ptp(x)),
           "closed_y_ptp_m": float(np.ptp(uv[:, 1])), "level_y_ptp_m": float(np.ptp(y)),
           "closed_x_max_m": float(uv[:, 0].max()), "level_x_max_m": float(x.max()),
           "closed_x_min_m": float(uv[:, 0].min()), "level_x_min_m": float(x.min())}
    print(f"({'b' if clearance == 0 else 'd'}) quasi-static level with the shaft's damper, {omega:g} rad/s, P_d = "
          f"{clearance * 1e6:g} um, GeneralizedAlpha 1e-4 s, last {periods} ball passages (Z f_c = {f_vc:.2f} Hz), {wall:.1f} s wall:")
    for name, unit, scale in (("x_ptp", "nm", 1e9), ("y_ptp", "nm", 1e9), ("x_max", "um", 1e6), ("x_min", "um", 1e6)):
        c, v = res[f"closed_{name}_m"], res[f"level_{name}_m"]
        print(f"    {name:6s} closed form {c * scale:10.4f} {unit}, level {v * scale:10.4f} {unit} "
              f"({100 * (v - c) / c:+.3f} %)")
    t = s["t"]
    each = [np.ptp(s["displacement"][(t >= n / f_vc) & (t < (n + 1) / f_vc), 0]) for n in range(periods + 2)]
    res["level_x_ptp_by_passage_m"] = [float(e) for e in each]
    print(f"    x_ptp by ball passage from the start: {', '.join(f'{1e9 * e:.2f}' for e in each)} nm (equal: settled)")
    return res, s, br, (th, uv)


def check_speeds(b, kn, speeds, periods=6):
    """First harmonic at Z f_c against closed form x amplification."""
    _th, uv = orbit(b.n_balls, kn, LOAD)
    a_qs = first_harmonic(uv[:, 0])
    rows = []
    for omega in speeds:
        f_vc = b.n_balls * cage_ratio(b) * omega / (2.0 * math.pi)
        step = min(1e-4, 1.0 / (40.0 * f_vc))
        s, br, wall = run_level(b, omega, 0.06 + periods / f_vc, step)
        k_xx = float(np.interp(omega, br.coefficients.speeds, br.coefficients.stiffness[:, 0, 0]))
        f_n = math.sqrt(k_xx / MASS) / (2.0 * math.pi)
        k = last_periods(s, 1.0 / f_vc, periods)
        amp = harmonic_amplitude(s["t"][k], s["displacement"][k, 0], f_vc)
        pred = a_qs / abs(1.0 - (f_vc / f_n) ** 2)
        rows.append((omega, f_vc, f_n, step, amp, pred, wall))
        print(f"(c) {omega:6.0f} rad/s: Z f_c = {f_vc:7.2f} Hz, f_n = {f_n:6.0f} Hz, step {step:.2g} s: x at Z f_c "
              f"{amp * 1e9:7.3f} nm, closed form x 1/|1-r^2| {pred * 1e9:7.3f} nm ({100 * (amp - pred) / pred:+.1f} %); "
              f"{wall:.1f} s wall")
    return rows, a_qs


def check_balls(b, omega=500.0, t_end=0.06):
    """Ball element, fast mode, VelocityVerlet: spectrum peak against Z times its own cage speed."""
    _sc, mbs, node, m_b, m_g, pos = shaft((LOAD, 0.0, 0.0), omega=omega, damper=False)
    br = eb.CreateBallBearing(mbs, b, m_b, m_g, initialLoad=(LOAD, 0.0), initialOmega=omega, mode="fast",
                              sampleInterval=5e-5, initial="quasistatic")
    mbs.SetNodeParameter(node, "initialCoordinates",
                         [*quasistatic_start(b, eb.Scenario(Fr=LOAD, omega=omega))["ring"][:3], 0.0, 0.0, 0.0])
    mbs.Assemble()
    ss = br.SimulationSettings(t_end)
    t0 = time.perf_counter()
    with eb.filter_exudyn_notes():
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    wall = time.perf_counter() - t0
    p = mbs.GetSensorStoredData(pos)
    cage = mbs.GetSensorStoredData(br.sensors["cageSpeed"])
    keep = p[:, 0] >= 0.3 * t_end
    f, a = spectrum(p[keep, 0], p[keep, 1])
    wc = float(cage[cage[:, 0] >= 0.3 * t_end, 1].mean())
    f_vc = b.n_balls * wc / (2.0 * math.pi)
    band = f > 0.5 * f_vc
    peak = float(f[band][np.argmax(a[band])])
    print(f"(e) ball element (fast mode, VelocityVerlet, {t_end:g} s, {wall:.1f} s wall) at {omega:g} rad/s: mean cage "
          f"speed {wc:.2f} rad/s, Z omega_c / 2 pi = {f_vc:.1f} Hz; x spectrum peak above it/2 at {peak:.1f} Hz "
          f"(resolution {f[1] - f[0]:.1f} Hz)")
    return {"cage_speed": wc, "f_vc_Hz": f_vc, "peak_Hz": peak, "resolution_Hz": float(f[1] - f[0]), "wall_s": wall}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=str(ROOT / "validation" / "out" / "levels"))
    ap.add_argument("--no-balls", action="store_true", help="skip the ball-element run (e)")
    ap.add_argument("--periods", type=int, default=6, help="ball passages averaged over in (c)")
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    b = eb.catalog["6208"]
    kn = race_stiffness(b)[2]
    z = b.n_balls
    d0, d1 = boundary_displacements(z, kn, LOAD)
    print(f"(a) closed form, 6208 (Z = {z}, K_n = {kn:.4g} N/m^1.5), F = {LOAD:g} N, zero clearance: delta(ball under "
          f"the load) = {d0 * 1e6:.4f} um, delta(two balls straddling) = {d1 * 1e6:.4f} um, peak-to-peak "
          f"{abs(d0 - d1) * 1e9:.2f} nm ({100 * relative_ptp(z):.3f} % of the mean)")
    zs = np.arange(6, 21)
    rel = np.array([relative_ptp(int(n)) for n in zs])
    slope = float(np.polyfit(np.log(zs), np.log(rel), 1)[0])
    print("    relative peak-to-peak against Z (depends on Z alone): "
          + ", ".join(f"{n}: {100 * r:.3g} %" for n, r in zip(zs[::2], rel[::2]))
          + f"; log-log slope {slope:.2f} (it falls like Z^{slope:.1f}, far faster than 1/Z)")
    res = {"closed_form": {"delta_ball_under_m": d0, "delta_straddle_m": d1, "relative_ptp": relative_ptp(z),
                           "Z": [int(n) for n in zs], "relative_ptp_by_Z": rel.tolist(), "slope_log_log": slope}}
    low, s_low, br_low, (th, uv) = check_low_speed(b, kn)
    res["low_speed"] = low
    k_c = br_low.cageRatio
    k_xx = float(np.interp(0.0, br_low.coefficients.speeds, br_low.coefficients.stiffness[:, 0, 0]))
    k_yy = float(np.interp(0.0, br_low.coefficients.speeds, br_low.coefficients.stiffness[:, 1, 1]))
    for name, k in (("x", k_xx), ("y", k_yy)):
        f_n = math.sqrt(k / MASS) / (2.0 * math.pi)
        w_res = 2.0 * math.pi * f_n / (z * k_c)
        res[f"resonance_{name}"] = {"f_n_Hz": f_n, "omega_rad_s": w_res}
        print(f"    Z f_c meets the shaft's natural frequency in {name} ({f_n:.0f} Hz, k_{name}{name} {k:.3g} N/m at "
              f"{LOAD:g} N) at omega = 2 pi f_n / (Z k_c) = {w_res:.0f} rad/s (k_c = {k_c:.4f})")
    rows, a_qs = check_speeds(b, kn, (50.0, 500.0, 1000.0, 1400.0), periods=args.periods)
    res["speeds"] = [dict(zip(("omega", "f_vc_Hz", "f_n_Hz", "step_s", "amp_m", "closed_m", "wall_s"), r)) for r in rows]
    clr, s_clr, _, (_th_c, uv_c) = check_low_speed(b, kn, clearance=20e-6)
    res["clearance_20um"] = clr
    if not args.no_balls:
        res["balls"] = check_balls(b)

    plt = pyplot()
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.4))
    f_vc = low["f_vc_Hz"]
    k = last_periods(s_low, 1.0 / f_vc, 3)
    ang = (s_low["cage_angle"][k] % (2 * math.pi / z)) * z / (2 * math.pi)
    order = np.argsort(ang)
    ax[0].plot(np.arange(th.size) / th.size, uv[:, 0] * 1e6, "k-", lw=2, label="closed form")
    ax[0].plot(ang[order], s_low["displacement"][k, 0][order] * 1e6, "C1.", ms=3, label="quasi-static level")
    ax[0].set_xlabel("cage angle [ball pitches]")
    ax[0].set_ylabel("x along the load [um]")
    ax[0].set_title(f"x over a ball passage, {low['omega']:g} rad/s, P_d = 0")
    ax[1].plot(uv[:, 0] * 1e6, uv[:, 1] * 1e9, "k-", lw=2, label="closed form, P_d = 0")
    ax[1].plot(s_low["displacement"][k, 0] * 1e6, s_low["displacement"][k, 1] * 1e9, "C1.", ms=3, label="level, P_d = 0")
    kc = last_periods(s_clr, 1.0 / f_vc, 3)
    ax[1].set_xlabel("x [um]")
    ax[1].set_ylabel("y [nm]")
    ax[1].set_title("orbit of the ring centre over a ball passage")
    ax2 = ax[1].twiny()
    ax2.plot(uv_c[:, 0] * 1e6, uv_c[:, 1] * 1e9, "k--", lw=1.5)
    ax2.plot(s_clr["displacement"][kc, 0] * 1e6, s_clr["displacement"][kc, 1] * 1e9, "C2.", ms=3)
    ax2.set_xlabel("x with P_d = 20 um [um] (dashed: closed form, green: level)")
    om = np.array([r[0] for r in rows])
    ax[2].semilogy(om, [r[4] * 1e9 for r in rows], "C1o", label="quasi-static level")
    w_grid = np.linspace(10.0, 1.05 * res["resonance_x"]["omega_rad_s"], 300)
    r2 = (w_grid / res["resonance_x"]["omega_rad_s"]) ** 2
    ax[2].semilogy(w_grid, a_qs * 1e9 / np.abs(1.0 - r2), "k-", label="closed form x 1/|1 - r^2|")
    ax[2].set_xlabel("shaft speed [rad/s]")
    ax[2].set_ylabel("x amplitude at Z f_c [nm]")
    ax[2].set_title("first harmonic against speed")
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.suptitle(f"6208 under {LOAD:g} N: varying-compliance motion, quasi-static level against the rigid-ring "
                 "Hertz theory (Sunnersjo 1978).")
    cols = {"cage_angle_pitches": np.arange(th.size) / th.size, "closed_x_m": uv[:, 0], "closed_y_m": uv[:, 1],
            "closed_x_Pd20um_m": uv_c[:, 0], "closed_y_Pd20um_m": uv_c[:, 1]}
    save_figure(fig, out / "levels_published_vc.png")
    save_csv(out / "levels_published_vc.csv", cols)
    save_csv(out / "levels_published_vc_speeds.csv",
             {n: [r[i] for r in rows] for i, n in enumerate(("omega_rad_s", "f_vc_Hz", "f_n_Hz", "step_s", "amp_m",
                                                             "closed_m", "wall_s"))})
    (out / "levels_published_vc.json").write_text(json.dumps(res, indent=1, default=float))
    print("written:", out)
    return res


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced."""
    return run.printed(
        "Varying compliance against the published theory",
        "The quasi-static level's ball-pass motion against the rigid-ring Hertz theory of Sunnersjo (1978) "
        "in closed form (docs/theory/varying_compliance.md): the two boundary positions, the orbit over a "
        "ball passage, the first harmonic against speed, and a short ball-element run.",
        [("levels/levels_published_vc.png", "ring-centre motion over a ball passage and its first harmonic "
                                            "against speed, quasi-static level against the closed form.")],
        last_lines=30)


if __name__ == "__main__":
    main()
