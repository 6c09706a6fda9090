"""Checks of the three bearing levels of ``eb.CreateBallBearing(model=...)``: "balls", "quasistatic", "linear".

(a) static: a 2.5 kg shaft on one 6208 under F_r = 3000 N, F_a = 1000 N (with a pure damper to ground that
    settles it without moving its equilibrium) ends where ``solve_quasistatic`` puts the inner ring; the
    ball element at zero speed (its contact damping settles the balls), the two levels without ball DOFs
    under GeneralizedAlpha at 1e-4 s;
(b) varying compliance: the same shaft spinning at 500 rad/s under a radial load of 500 N on one 6208 with
    20 um diametral clearance and with the catalogue clearance (0), quasi-static level: the spectrum of the
    shaft's displacement along the load peaks at Z omega_c (Sunnersjo 1978: the ball-pass varying-compliance
    frequency) and its harmonics;
(c) the rotor of scenarios/rotor_two_6208.py (gravity, unbalance, run-up to 1000 rad/s) at the three levels:
    orbit radius, bearing force and cage speed by windows.

    python validation/consistency/levels_checks.py [--out validation/out/levels] [--t-end 0.3]

Writes levels_static.csv, levels_vc.png/.csv, levels_rotor.png/.csv and levels_checks.json into --out.
Wall times per simulated second are measured in validation/performance/bench_levels.py.
"""
from __future__ import annotations

import argparse
import importlib.util
import inspect
import json
import math
import time
import warnings
from pathlib import Path

import numpy as np

import exudyn as exu
from exudyn.itemInterface import (LoadForceVector, LoadTorqueVector, MarkerBodyRigid, NodeRigidBodyRxyz,
                                  ObjectConnectorRigidBodySpringDamper, ObjectGround, ObjectRigidBody, SensorNode)

import exudyn_bearing as eb
from exudyn_bearing.simulate import BallBearingElement, quasistatic_start
from exudyn_bearing.outputs.plotting import pyplot, save_csv, save_figure

ROOT = Path(__file__).resolve().parents[2]
FR, FA = 3000.0, 1000.0


def shaft(load, omega=0.0, damper=True, start=None, moment=None):
    """A 2.5 kg shaft (Rxyz node) carrying ``load`` (and ``moment``) at its centre, an outer-ring marker on ground,
    optionally a pure damper to ground; ``start``: initial pose (x, y, z, tilt_x, tilt_y)."""
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    q0 = [0.0] * 6
    if start is not None:
        q0[:5] = list(start)
    node = mbs.AddNode(NodeRigidBodyRxyz(referenceCoordinates=[0.0] * 6, initialCoordinates=q0,
                                         initialVelocities=[0, 0, 0, 0, 0, omega]))
    body = mbs.AddObject(ObjectRigidBody(nodeNumber=node, mass=2.5, inertia=[0.01, 0.01, 5e-4, 0, 0, 0]))
    m_g = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground))
    m_b = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body))
    mbs.AddLoad(LoadForceVector(markerNumber=m_b, loadVector=list(load)))
    if moment is not None:
        mbs.AddLoad(LoadTorqueVector(markerNumber=m_b, loadVector=list(moment)))
    if damper:
        mbs.AddObject(ObjectConnectorRigidBodySpringDamper(markerNumbers=[m_g, m_b],
                                                           damping=np.diag([2e4, 2e4, 2e4, 20.0, 20.0, 0.0])))
    pos = mbs.AddSensor(SensorNode(nodeNumber=node, outputVariableType=exu.OutputVariableType.Position,
                                   storeInternal=True, writeToFile=False))
    return sc, mbs, node, m_b, m_g, pos


def solve_timed(mbs, ss, write_period=1e-3):
    """Assemble ``mbs``, write its sensors every ``write_period`` [s] (None: as ``ss`` says) and solve it with
    the settings ``ss`` (Exudyn's notes filtered, the package's warnings silenced: the scripts print their own
    checks); the wall time of the solve [s]."""
    mbs.Assemble()
    if write_period is not None:
        ss.solution.sensors.writePeriod = write_period
    t0 = time.perf_counter()
    with eb.filter_exudyn_notes(), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    return time.perf_counter() - t0


def check_static(out):
    rows, res = [], {}
    for fr, fa in ((FR, 0.0), (FR, FA)):
        ref = eb.solve_quasistatic("6208", Fr=fr, Fa=fa, ring_growth=False, fixed={})  # the shaft tilts freely
        u = ref.displacement
        print(f"(a) static, F_r = {fr:g} N, F_a = {fa:g} N: solve_quasistatic puts the inner ring at "
              f"x = {u[0] * 1e6:.3f} um, axial {u[2] * 1e6:.3f} um, tilt_y {u[4] * 1e3:.4f} mrad")
        for model in ("quasistatic", "linear", "balls"):
            start = None
            if model == "balls":  # the element starts from the quasi-static state with the tilt held at zero
                start = [*quasistatic_start("6208", eb.Scenario(omega=500.0, Fr=fr, Fa=fa))["ring"][:3], 0.0, 0.0]
            sc, mbs, node, m_b, m_g, pos = shaft((fr, 0.0, fa), start=start)
            rot = mbs.AddSensor(SensorNode(nodeNumber=node, outputVariableType=exu.OutputVariableType.Rotation,
                                           storeInternal=True, writeToFile=False))
            if model == "balls":
                br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, initialLoad=(fr, fa), stepSize=1e-6,
                                          sampleInterval=1e-3, initial="quasistatic")
                t_end = 0.03
            else:
                br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model=model, initialLoad=(fr, fa))
                t_end = 0.05
            mbs.Assemble()
            ss = br.SimulationSettings(t_end)
            ss.solution.sensors.writePeriod = 1e-4
            t0 = time.perf_counter()
            with eb.filter_exudyn_notes():
                mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
            wall = time.perf_counter() - t0
            p = mbs.GetSensorStoredData(pos)
            r = mbs.GetSensorStoredData(rot)
            late = p[:, 0] >= 0.8 * t_end
            last = p[late, 1:4].mean(axis=0)
            tilt = r[late, 2].mean()
            err = (last[0] - u[0]) / u[0], ((last[2] - u[2]) / u[2] if fa > 0 else last[2] / u[0])
            rows.append((fr, fa, last[0], last[2], tilt, err[0], err[1], wall))
            res[f"{model}_Fa{fa:g}"] = {"rel_err_x": err[0], "rel_err_axial": err[1], "tilt_y": tilt}
            print(f"    {model:12s} x = {last[0] * 1e6:.3f} um ({100 * err[0]:+.3f} %), axial {last[2] * 1e6:.3f} um "
                  f"({100 * err[1]:+.3f} %{'' if fa > 0 else ' of x'}), tilt_y {tilt * 1e3:.4f} mrad; mean of the last "
                  f"20 % of {t_end:g} s; {wall:.1f} s wall")
    names = ("Fr_N", "Fa_N", "x_m", "axial_m", "tilt_y_rad", "rel_err_x", "rel_err_axial", "wall_s")
    cols = {n: [r[i] for r in rows] for i, n in enumerate(names)}
    cols["level"] = [i % 3 for i in range(len(rows))]
    save_csv(out / "levels_static.csv", cols)
    print("    levels_static.csv: level 0 quasistatic, 1 linear, 2 balls")
    return res


def spectrum(t, x):
    x = x - x.mean()
    win = np.hanning(x.size)
    amp = 2.0 * np.abs(np.fft.rfft(x * win)) / win.sum()
    return np.fft.rfftfreq(x.size, t[1] - t[0]), amp


def check_varying_compliance(out, omega=500.0, load=500.0, t_end=0.4):
    print(f"(b) varying compliance: shaft at {omega:g} rad/s, radial load {load:g} N, quasi-static level, "
          "GeneralizedAlpha 1e-4 s")
    b0 = eb.catalog["6208"]
    res = {}
    plt = pyplot()
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.2))
    cols = {}
    for k, pd in enumerate((20e-6, 0.0)):
        b = b0.with_clearance(pd)
        sc, mbs, node, m_b, m_g, pos = shaft((load, 0.0, 0.0), omega=omega, damper=False)
        br = eb.CreateBallBearing(mbs, b, m_b, m_g, model="quasistatic", initialLoad=(load, 0.0),
                                  initialOmega=omega, sampleInterval=1e-4)
        # start at the quasi-static pose: the transient is the ball-pass excitation, not a drop
        mbs.SetNodeParameter(node, "initialCoordinates", [*br.initialRingDisplacement, 0.0])
        mbs.Assemble()
        ss = br.SimulationSettings(t_end)
        t0 = time.perf_counter()
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
        wall = time.perf_counter() - t0
        s = br.samples()
        keep = s["t"] >= 0.25 * t_end
        f, a = spectrum(s["t"][keep], s["displacement"][keep, 0])
        f_vc = b.n_balls * br.cageRatio * omega / (2.0 * math.pi)
        band = f > 0.5 * f_vc
        peak = float(f[band][np.argmax(a[band])])
        df = f[1] - f[0]
        harm = [float(a[np.argmin(np.abs(f - n * f_vc))]) for n in (1, 2, 3)]
        k_xx = float(np.interp(omega, br.coefficients.speeds, br.coefficients.stiffness[:, 0, 0]))
        f_n = math.sqrt(k_xx / 2.5) / (2.0 * math.pi)
        print(f"    P_d = {pd * 1e6:4.0f} um: linearised k_xx {k_xx:.3g} N/m, shaft natural frequency "
              f"sqrt(k_xx/m)/2 pi = {f_n:.0f} Hz")
        res[f"Pd_{pd * 1e6:g}um"] = {"natural_frequency_Hz": f_n, "f_vc_Hz": f_vc, "peak_Hz": peak, "resolution_Hz": float(df),
                                     "amplitude_m": harm, "x_ptp_m": float(np.ptp(s["displacement"][keep, 0])),
                                     "wall_s": wall}
        print(f"    P_d = {pd * 1e6:4.0f} um: Z omega_c / 2 pi = {f_vc:.1f} Hz; spectrum peak above it/2 at "
              f"{peak:.1f} Hz (resolution {df:.1f} Hz); amplitudes at 1, 2, 3 x Z f_c: "
              f"{', '.join(f'{1e9 * h:.3g}' for h in harm)} nm; peak-to-peak x {1e9 * np.ptp(s['displacement'][keep, 0]):.3g}"
              f" nm; {wall:.1f} s wall for {t_end:g} s")
        ax[k].semilogy(f, a * 1e9 + 1e-9)
        for n in (1, 2, 3):
            ax[k].axvline(n * f_vc, color="C3", lw=0.8, ls="--")
        ax[k].set_xlim(0, 4 * f_vc)
        ax[k].set_xlabel("frequency [Hz]")
        ax[k].set_ylabel("x amplitude [nm]")
        ax[k].set_title(f"P_d = {pd * 1e6:g} um (dashed: n Z f_c)")
        cols[f"f_Hz_Pd{pd * 1e6:g}"] = f
        cols[f"amp_m_Pd{pd * 1e6:g}"] = a
    fig.suptitle(f"6208, quasi-static level, {omega:g} rad/s, {load:g} N: shaft displacement spectrum")
    save_figure(fig, out / "levels_vc.png", cols, trim=True)
    return res


def load_rotor_scenario():
    spec = importlib.util.spec_from_file_location("rotor_two_6208", ROOT / "scenarios" / "rotor_two_6208.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def run_rotor(model, t_end):
    """The scenario's rotor with its bearings at ``model``; returns sensors and wall time."""
    mod = load_rotor_scenario()
    original = eb.CreateBallBearing
    weight = 7850.0 * math.pi * 0.02 ** 2 * 0.25 * 9.81 / 2.0  # per bearing, the scenario's shaft

    # ring growth as the ball element has it by default, so that the levels see the same grooves
    growth = inspect.signature(BallBearingElement.__init__).parameters["ringGrowth"].default

    def level(mbs, bearing, m_in, m_out, **kw):
        # the scenario's ball-element options do not apply; the operating point is the static weight along -y
        return original(mbs, bearing, m_in, m_out, model=model, initialLoad=(weight, 0.0), loadAngle=-0.5 * math.pi,
                        sampleInterval=kw.get("sampleInterval", 2e-4), ringGrowth=growth)

    if model != "balls":
        eb.CreateBallBearing = level
    try:
        sc, mbs, bearings, sensor, speed = mod.build()
    finally:
        eb.CreateBallBearing = original
    b = bearings["A"]
    ss = b.SimulationSettings(t_end) if model == "balls" else b.SimulationSettings(t_end, stepSize=1e-4)
    ss.solution.sensors.writePeriod = 2e-4
    t0 = time.perf_counter()
    with eb.filter_exudyn_notes(), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    wall = time.perf_counter() - t0
    pos = mbs.GetSensorStoredData(sensor)
    w = mbs.GetSensorStoredData(speed)
    f_in = mbs.GetSensorStoredData(b.sensors["innerRingForce"])
    cage = mbs.GetSensorStoredData(b.sensors["cageSpeed"])
    return {"pos": pos, "omega": w, "force": f_in, "cage": cage, "wall": wall}


def check_rotor(out, t_end):
    growth = inspect.signature(BallBearingElement.__init__).parameters["ringGrowth"].default
    print(f"(c) rotor on two 6208 (scenarios/rotor_two_6208.py), {t_end:g} s: balls (fast mode, VelocityVerlet "
          f"5 us), quasistatic and linear (GeneralizedAlpha 1e-4 s); ring growth {growth} at every level")
    runs = {m: run_rotor(m, t_end) for m in ("balls", "quasistatic", "linear")}
    edges = [0.0, 0.027, 0.055, 0.109, 0.205, t_end + 1e-9]
    table = {}
    print("    window [ms]   " + "   ".join(f"{m:>30s}" for m in runs))
    print("                  " + "   ".join(f"{'orbit um / |F| N / cage rad/s':>30s}" for _ in runs))
    for a, bnd in zip(edges[:-1], edges[1:]):
        row = f"    {1e3 * a:4.0f}-{1e3 * min(bnd, t_end):4.0f}    "
        for m, r in runs.items():
            tp = r["pos"][:, 0]
            k = (tp >= a) & (tp < bnd)
            kf = (r["force"][:, 0] >= a) & (r["force"][:, 0] < bnd)
            kc = (r["cage"][:, 0] >= a) & (r["cage"][:, 0] < bnd)
            orbit = 1e6 * np.hypot(r["pos"][k, 1], r["pos"][k, 2]).mean()
            fmag = np.linalg.norm(r["force"][kf, 1:3], axis=1).mean()
            cage = r["cage"][kc, 1].mean()
            table.setdefault(m, []).append((a, bnd, orbit, fmag, cage))
            row += f"   {orbit:9.2f} / {fmag:7.1f} / {cage:7.1f}  "
        print(row.rstrip())
    for m, r in runs.items():
        print(f"    {m:12s} wall {r['wall']:.1f} s for {t_end:g} s ({r['wall'] / t_end:.1f} s per simulated s)")
    plt = pyplot()
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.4))
    cols = {}
    for m, r in runs.items():
        ax[0].plot(r["pos"][:, 1] * 1e6, r["pos"][:, 2] * 1e6, lw=0.6, label=m)
        ax[1].plot(r["force"][:, 0], np.linalg.norm(r["force"][:, 1:3], axis=1), lw=0.8, label=m)
        ax[2].plot(r["cage"][:, 0], r["cage"][:, 1], lw=0.8, label=m)
        n = min(len(r["pos"]), len(r["force"]), len(r["cage"]))
        cols[f"t_s_{m}"] = r["pos"][:n, 0]
        cols[f"x_m_{m}"] = r["pos"][:n, 1]
        cols[f"y_m_{m}"] = r["pos"][:n, 2]
        cols[f"force_N_{m}"] = np.linalg.norm(r["force"][:n, 1:3], axis=1)
        cols[f"cage_rad_s_{m}"] = r["cage"][:n, 1]
    ax[0].set_xlabel("x [um]")
    ax[0].set_ylabel("y [um]")
    ax[0].set_title("orbit of the shaft centre")
    ax[0].set_aspect("equal", adjustable="datalim")
    ax[1].set_xlabel("t [s]")
    ax[1].set_ylabel("|force on inner ring A| [N]")
    ax[2].set_xlabel("t [s]")
    ax[2].set_ylabel("cage speed, bearing A [rad/s]")
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.suptitle("rigid rotor on two 6208: the three bearing levels")
    save_figure(fig, out / "levels_rotor.png", cols, trim=True)
    return {m: {"wall_s": r["wall"], "windows": table[m]} for m, r in runs.items()}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=str(ROOT / "validation" / "out" / "levels"))
    ap.add_argument("--t-end", type=float, default=0.3, help="rotor run length [s]")
    ap.add_argument("--skip", nargs="*", default=[], choices=("static", "vc", "rotor"))
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    res = {}
    if "static" not in args.skip:
        res["static"] = check_static(out)
    if "vc" not in args.skip:
        res["varying_compliance"] = check_varying_compliance(out)
    if "rotor" not in args.skip:
        res["rotor"] = check_rotor(out, args.t_end)
    (out / "levels_checks.json").write_text(json.dumps(res, indent=1, default=float))
    print("written:", out)


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced."""
    return run.printed(
        "Bearing levels in Exudyn",
        "The ball element, the quasi-static level and the linear level in Exudyn (docs/theory/levels.md): "
        "static equilibrium against solve_quasistatic, the ball-pass varying compliance, the rotor scenario "
        "at the three levels.",
        [("levels/levels_vc.png", "varying-compliance vibration of the quasi-static level: spectrum with the "
                                  "ball-pass frequency and its harmonics."),
         ("levels/levels_rotor.png", "the rotor scenario at the three levels.")],
        last_lines=40)


if __name__ == "__main__":
    main()
