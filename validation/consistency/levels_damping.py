"""Contact damping of the quasi-static level (``CreateBallBearing(..., model="quasistatic")``) against the ball
element's, on a 2.5 kg shaft on two 6208 (z = -+0.1 m) carrying 6000 N radially (+x) between them at 500 rad/s.

(a) settling: the quasi-static level (GeneralizedAlpha at 1e-4 s) started at rest at the origin, with and without
    an operating point ``initialLoad``: the level damps from the state of its balls, so both settle alike, to the
    same static position (mean and half peak-to-peak of the shaft's x over the last 50 ms);
(b) the shaft's axial mode (about 375 Hz: the shaft on the two bearings' axial stiffness, which a radially loaded
    deep-groove bearing at zero clearance gets from the balls' small contact angles): the shaft starts at its static
    pose with an axial velocity ``--vz``, at the ball element (``model="balls"``, fast mode, VelocityVerlet at 5 us,
    quasi-static start; and with ``friction="none"``, which shows how much of its damping its tangential contact
    forces make) and at the quasi-static level (GeneralizedAlpha at 1e-4 s with its default spectral radius and
    with 1: without the integrator's numerical damping), ``initialLoad`` only to start it at the static pose;
(c) the radial mode (about 1.9 kHz) likewise from a radial velocity ``--vx``, the level also at 2e-5 s (at 1e-4 s
    GeneralizedAlpha has five steps per period), against C_xx / m of solve_quasistatic's condensed damping matrix.

In (b) and (c): the decay rate sigma [1/s] by a least-squares fit of m + A exp(-sigma t) cos(omega t + phi) to the
position over the run, the damping ratio sigma / omega, and the ratio of the level's decay rate to the balls'.

    python validation/consistency/levels_damping.py [--out validation/out/levels_damping] [--t-settle 0.4] [--t-decay 0.3]
                                        [--t-radial 0.06] [--skip settle axial radial]

Writes levels_damping.png (the amplitudes per period of the free decays of (b) and (c)), levels_damping.npz (their
series) and levels_damping.json into --out.
"""
from __future__ import annotations

import argparse
import json
import time
import warnings
from pathlib import Path

import numpy as np
from scipy.optimize import curve_fit

import exudyn as exu
from exudyn.itemInterface import (LoadForceVector, MarkerBodyRigid, NodeRigidBodyRxyz, ObjectGround, ObjectRigidBody,
                                  SensorNode)

import exudyn_bearing as eb
from exudyn_bearing.outputs.plotting import pyplot, save_figure

ROOT = Path(__file__).resolve().parents[2]
MASS, RADIUS, LENGTH, HALF_SPAN = 2.5, 0.02, 0.25, 0.1
LOAD, OMEGA = 6000.0, 500.0
#: the ball element's options for this rotor (those of scenarios/rotor_two_6208.py, started in equilibrium)
BALLS = {"stepSize": 5e-6, "tangential": "implicit", "mode": "fast", "initial": "quasistatic",
         "initialOmega": OMEGA, "initialLoad": (0.5 * LOAD, 0.0)}
#: the level's: its damping needs no operating point, initialLoad only gives the start (initialCoordinates)
LEVEL = {"initialOmega": OMEGA, "initialLoad": (0.5 * LOAD, 0.0)}


def rotor(model, start=True, velocity=(0.0, 0.0, 0.0), **options):
    """The shaft on two 6208 at ``model``; ``start``: at the bearings' static pose under LOAD / 2 each (else at the
    origin), with the initial ``velocity`` [m/s]. Returns (mbs, bearing A, position sensor)."""
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    jx = MASS * (3.0 * RADIUS ** 2 + LENGTH ** 2) / 12.0
    node = mbs.AddNode(NodeRigidBodyRxyz(referenceCoordinates=[0.0] * 6, initialVelocities=[*velocity, 0, 0, OMEGA]))
    jz = 0.5 * MASS * RADIUS ** 2
    body = mbs.AddObject(ObjectRigidBody(nodeNumber=node, mass=MASS, inertia=[jx, jx, jz, 0, 0, 0]))
    mbs.AddLoad(LoadForceVector(markerNumber=mbs.AddMarker(MarkerBodyRigid(bodyNumber=body)), loadVector=[LOAD, 0, 0]))
    bearings = []
    for z in (-HALF_SPAN, HALF_SPAN):
        m_in = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body, localPosition=[0.0, 0.0, z]))
        m_out = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground, localPosition=[0.0, 0.0, z]))
        bearings.append(eb.CreateBallBearing(mbs, "6208", m_in, m_out, model=model, **options))
    if start:
        q0 = np.array(bearings[0].initialCoordinates, float)
        q0[3:] = 0.0  # both bearings alike: no tilt
        mbs.SetNodeParameter(node, "initialCoordinates", list(q0))
    sensor = mbs.AddSensor(SensorNode(nodeNumber=node, outputVariableType=exu.OutputVariableType.Position,
                                      storeInternal=True, writeToFile=False))
    mbs.Assemble()
    return mbs, bearings[0], sensor


def run(mbs, bearing, sensor, t_end, spectral_radius=None, step=None):
    """Solve (the bearing's SimulationSettings; a level at ``step`` [s] if given, GeneralizedAlpha's
    ``spectral_radius`` if given); returns (position samples (n, 4): t, x, y, z; wall time [s])."""
    with eb.filter_exudyn_notes(), warnings.catch_warnings():
        # the ball element's note on its cage contacts' step (cage loads, which this check does not use)
        warnings.simplefilter("ignore")
        ss = bearing.SimulationSettings(t_end) if step is None else bearing.SimulationSettings(t_end, stepSize=step)
        if spectral_radius is not None:
            ss.timeIntegration.generalizedAlpha.spectralRadius = spectral_radius
        ss.solution.sensors.writePeriod = 1e-5
        t0 = time.perf_counter()
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    return mbs.GetSensorStoredData(sensor), time.perf_counter() - t0


def check_settling(t_end):
    print(f"(a) settling from rest at the origin, quasi-static level, GeneralizedAlpha 1e-4 s, {t_end:g} s: shaft x "
          "over the last 50 ms")
    res = {}
    for label, options in (("without initialLoad", {}), ("initialLoad=(3000, 100)", {"initialLoad": (3000.0, 100.0)})):
        pos, wall = run(*rotor("quasistatic", start=False, **options), t_end)
        last = pos[:, 0] >= pos[-1, 0] - 0.05
        x = pos[last, 1]
        res[label] = {"mean_um": 1e6 * x.mean(), "half_peak_to_peak_um": 0.5e6 * (x.max() - x.min()), "wall_s": wall}
        print(f"    {label:26s} x = {1e6 * x.mean():8.3f} um +- {0.5e6 * (x.max() - x.min()):.3f} um  "
              f"(wall {wall:.1f} s)")
    return res


def decay_fit(t, z):
    """Least-squares fit of m + A exp(-sigma t) cos(omega t + phi) to z(t): (sigma [1/s], omega [rad/s], fit)."""
    zc = z - z.mean()
    spec = np.abs(np.fft.rfft(zc * np.hanning(zc.size)))
    freq = np.fft.rfftfreq(zc.size, t[1] - t[0])
    w0 = 2.0 * np.pi * freq[1 + np.argmax(spec[1:])]
    a0 = 0.5 * (zc.max() - zc.min())
    c0 = np.cos(w0 * t) * zc
    s0 = np.sin(w0 * t) * zc
    phi0 = np.arctan2(-s0.sum(), c0.sum())

    def model(tt, m, a, sigma, w, phi):
        return m + a * np.exp(-sigma * tt) * np.cos(w * tt + phi)

    p, _ = curve_fit(model, t, z, p0=[z.mean(), a0, 1.0, w0, phi0], maxfev=20000)
    return float(p[2]), float(p[3]), model(t, *p)


#: the runs of (b) and (c): label -> (model, options, GeneralizedAlpha's spectral radius, level step [s])
RUNS = {"axial": {"balls (fast mode, VelocityVerlet 5 us)": ("balls", BALLS, None, None),
                  "balls, friction='none'": ("balls", {**BALLS, "friction": "none"}, None, None),
                  "quasistatic (GeneralizedAlpha 1e-4 s)": ("quasistatic", LEVEL, None, None),
                  "quasistatic (GeneralizedAlpha 1e-4 s, spectral radius 1)": ("quasistatic", LEVEL, 1.0, None)},
        "radial": {"balls (fast mode, VelocityVerlet 5 us)": ("balls", BALLS, None, None),
                   "quasistatic (GeneralizedAlpha 1e-4 s)": ("quasistatic", LEVEL, None, None),
                   "quasistatic (GeneralizedAlpha 2e-5 s)": ("quasistatic", LEVEL, None, 2e-5)}}


def envelope(t, q, omega):
    """Half the peak-to-peak of q per period 2 pi / omega: (window centres [s], amplitudes)."""
    edges = np.arange(t[0], t[-1], 2.0 * np.pi / omega)
    k = np.searchsorted(t, edges)
    amp = [0.5 * (q[i:j].max() - q[i:j].min()) for i, j in zip(k[:-1], k[1:])]
    return 0.5 * (edges[:-1] + edges[1:]), np.array(amp)


def check_decay(direction, t_end, speed, ax, series):
    """Free decay of the shaft's mode along ``direction`` ("axial": z, "radial": x, along the load) from its static
    pose with the initial ``speed`` [m/s] along it; fit, print, plot into ``ax``, series into ``series``."""
    k_dof = 3 if direction == "axial" else 1
    velocity = [0.0, 0.0, 0.0]
    velocity[k_dof - 1] = speed
    print(f"({'b' if direction == 'axial' else 'c'}) {direction} mode: shaft started at its static pose with "
          f"{speed:g} m/s along {'z' if direction == 'axial' else 'x'}, {t_end:g} s; decay rate sigma of a fit of "
          "m + A exp(-sigma t) cos(omega t + phi)")
    res = {}
    for k, (label, (model, options, rho, step)) in enumerate(RUNS[direction].items()):
        pos, wall = run(*rotor(model, velocity=velocity, **options), t_end, rho, step)
        t, q = pos[:, 0], pos[:, k_dof]
        sigma, omega, _fit = decay_fit(t, q)
        res[label] = {"sigma_per_s": sigma, "frequency_Hz": omega / (2.0 * np.pi), "damping_ratio": sigma / omega,
                      "wall_s": wall}
        print(f"    {label:58s} sigma = {sigma:8.3f} 1/s, f = {omega / (2 * np.pi):6.1f} Hz, zeta = "
              f"{sigma / omega:.3e}  (wall {wall:.1f} s)")
        te, amp = envelope(t, q, omega)
        ax.plot(te, 1e6 * amp, lw=1.0, color=f"C{k}", label=f"{label}: zeta = {sigma / omega:.2e}")
        series[f"{direction}_{k}_t_s"] = t
        series[f"{direction}_{k}_position_m"] = q
    balls = next(iter(res))
    for label in res:
        if label.startswith("quasistatic"):
            ratio = res[label]["sigma_per_s"] / res[balls]["sigma_per_s"]
            res[label]["sigma_ratio_to_balls"] = ratio
            print(f"    decay rate {label} / {balls}: {ratio:.3f}")
    ax.set_xlabel("t [s]")
    ax.set_ylabel(f"{direction} amplitude per period [um]")
    ax.set_title(f"{direction} mode")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    return res


def radial_prediction():
    """sigma = C_xx / m [1/s] of the shaft's radial mode (two bearings, C_xx = solve_quasistatic's damping
    matrix at LOAD / 2 and OMEGA)."""
    c_xx = float(eb.solve_quasistatic("6208", Fr=0.5 * LOAD, omega=OMEGA).damping[0, 0])
    return c_xx / MASS, c_xx


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=str(ROOT / "validation" / "out" / "levels_damping"))
    ap.add_argument("--t-settle", type=float, default=0.4, help="length of the settling runs (a) [s]")
    ap.add_argument("--t-decay", type=float, default=0.3, help="length of the axial runs (b) [s]")
    ap.add_argument("--vz", type=float, default=5e-3, help="initial axial velocity of the shaft in (b) [m/s]")
    ap.add_argument("--t-radial", type=float, default=0.06, help="length of the radial runs (c) [s]")
    ap.add_argument("--vx", type=float, default=0.02, help="initial radial velocity of the shaft in (c) [m/s]")
    ap.add_argument("--skip", nargs="*", default=[], choices=("settle", "axial", "radial"))
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    res = {}
    if "settle" not in args.skip:
        res["settling"] = check_settling(args.t_settle)
    plt = pyplot()
    fig, ax = plt.subplots(1, 2, figsize=(14, 4.6))
    series = {}
    if "axial" not in args.skip:
        res["axial_decay"] = check_decay("axial", args.t_decay, args.vz, ax[0], series)
    if "radial" not in args.skip:
        res["radial_decay"] = check_decay("radial", args.t_radial, args.vx, ax[1], series)
        sigma, c_xx = radial_prediction()
        res["radial_decay"]["condensed damping C_xx / m"] = {"sigma_per_s": sigma, "c_xx_N_s_per_m": c_xx}
        print(f"    condensed damping matrix (solve_quasistatic): C_xx = {c_xx:.1f} N s/m per bearing, "
              f"sigma = 2 C_xx / (2 m) = {sigma:.2f} 1/s")
    fig.suptitle(f"2.5 kg shaft on two 6208 ({LOAD:g} N radial, {OMEGA:g} rad/s): free decay at the ball element and "
                 "the quasi-static level")
    save_figure(fig, out / "levels_damping.png")
    np.savez_compressed(out / "levels_damping.npz", **series)
    (out / "levels_damping.json").write_text(json.dumps(res, indent=1, default=float))
    print("written:", out)


if __name__ == "__main__":
    main()
