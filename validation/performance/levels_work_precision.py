"""Work-precision of the three bearing levels: wall time against orbit error on one loaded test shaft.

Scene: the 2.5 kg shaft of levels_checks.shaft on one catalogue 6208 (outer ring on ground), spinning at
500 rad/s, under a static load of 1000 N along x plus a force of 300 N turning with the shaft (an
unbalance at 80 Hz), with the shaft's damper to ground (2e4 N s/m: without it the free vibration at the
shaft's natural frequency on the bearing, about 1 kHz, that the suddenly applied force starts would
dominate the orbit, and the error would measure how each integrator damps it), every level started at its
own static pose under the 1000 N. Reference: the ball
element (body mode, VelocityVerlet) at 1 us. For each level a few steps: balls in body and fast mode
(VelocityVerlet), quasistatic and linear under GeneralizedAlpha at 1e-5 .. 5e-4 s.

Error: RMS over the window 10-20 ms of the distance between the inner ring's (x, y) and the reference's,
divided by the reference's RMS orbit radius about its mean over that window. Wall: median of --repeat
solves. Where the error stops falling as the step shrinks, the rest is model error (the level's physics
differs from the balls'), not step error: the script prints those plateaus as such.

    python validation/performance/levels_work_precision.py [--out validation/out/levels] [--repeat 3]

Writes levels_work_precision.csv/.png and levels_work_precision.json into --out.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numpy as np
from exudyn.itemInterface import LoadForceVector

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "consistency"))  # levels_checks.py, peer_builtin.py
from levels_checks import shaft  # noqa: E402

import exudyn_bearing as eb
from exudyn_bearing.outputs.plotting import pyplot, save_figure
from exudyn_bearing.simulate import quasistatic_start

ROOT = Path(__file__).resolve().parents[2]
OMEGA, F_STATIC, F_TURN, T_END = 500.0, 1000.0, 300.0, 0.02
WINDOW = (0.010, 0.020)  # s
GRID = np.arange(WINDOW[0], WINDOW[1] + 1e-9, 1e-4)
REFERENCE = ("balls", "bodies", 1e-6, 1)
RUNS = [("balls", "bodies", 2e-6, 1), ("balls", "bodies", 3.5e-6, 1),
        ("balls", "fast", 3.5e-6, 1), ("balls", "fast", 3.5e-6, 4)]
RUNS += [(lvl, None, h, 1) for lvl in ("quasistatic", "linear") for h in (1e-5, 3e-5, 1e-4, 2.5e-4, 5e-4)]


def label(level, mode, step, sub):
    if level != "balls":
        return f"{level}, GeneralizedAlpha {step:g} s"
    return f"balls ({mode}{f', {sub} sub-steps' if sub > 1 else ''}), VelocityVerlet {step:g} s"


def run(level, mode, step, sub):
    """One solve; returns (t, x, y) of the shaft centre and the solve's wall time."""
    b = eb.catalog["6208"]
    start = quasistatic_start(b, eb.Scenario(Fr=F_STATIC, omega=OMEGA))["ring"][:3]
    _sc, mbs, node, m_b, m_g, pos = shaft((F_STATIC, 0.0, 0.0), omega=OMEGA, damper=True,
                                         start=[*start, 0.0, 0.0])
    mbs.AddLoad(LoadForceVector(markerNumber=m_b, loadVector=[0.0, 0.0, 0.0], loadVectorUserFunction=(
        lambda mbs, t, load: [F_TURN * math.cos(OMEGA * t), F_TURN * math.sin(OMEGA * t), 0.0])))
    if level == "balls":
        br = eb.CreateBallBearing(mbs, b, m_b, m_g, initialLoad=(F_STATIC, 0.0), initialOmega=OMEGA, mode=mode,
                                  subSteps=sub, stepSize=step, sampleInterval=1e-3, initial="quasistatic")
        mbs.Assemble()
        ss = br.SimulationSettings(T_END)
    else:
        br = eb.CreateBallBearing(mbs, b, m_b, m_g, model=level, initialLoad=(F_STATIC, 0.0), initialOmega=OMEGA,
                                  sampleInterval=1e-3)
        mbs.SetNodeParameter(node, "initialCoordinates", [*br.initialRingDisplacement, 0.0])
        mbs.Assemble()
        ss = br.SimulationSettings(T_END, stepSize=step)
    ss.solution.sensors.writePeriod = min(1e-5, step * sub)
    t0 = time.perf_counter()
    with eb.filter_exudyn_notes():
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    wall = time.perf_counter() - t0
    p = mbs.GetSensorStoredData(pos)
    return p[:, 0], p[:, 1], p[:, 2], wall


def on_grid(t, x, y):
    return np.interp(GRID, t, x), np.interp(GRID, t, y)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=str(ROOT / "validation" / "out" / "levels"))
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    print(f"6208, shaft 2.5 kg at {OMEGA:g} rad/s, {F_STATIC:g} N static + {F_TURN:g} N turning with the shaft, "
          f"{T_END:g} s; error window {1e3 * WINDOW[0]:g}-{1e3 * WINDOW[1]:g} ms; wall: median of {args.repeat}")
    t, x, y, w_ref = run(*REFERENCE)
    xr, yr = on_grid(t, x, y)
    orbit_rms = float(np.sqrt(np.mean((xr - xr.mean()) ** 2 + (yr - yr.mean()) ** 2)))
    print(f"reference: {label(*REFERENCE)}, {w_ref:.1f} s wall; RMS orbit radius {orbit_rms * 1e9:.1f} nm about "
          f"({xr.mean() * 1e6:.3f}, {yr.mean() * 1e6:.3f}) um")
    rows = []
    for spec in RUNS:
        walls, err = [], None
        for _ in range(args.repeat):
            t, x, y, w = run(*spec)
            walls.append(w)
            if err is None:
                xs, ys = on_grid(t, x, y)
                err = float(np.sqrt(np.mean((xs - xr) ** 2 + (ys - yr) ** 2))) / orbit_rms
        wall = float(np.median(walls))
        rows.append((*spec, wall, err))
        print(f"    {label(*spec):48s} wall {wall:7.2f} s ({wall / T_END:7.1f} s per simulated s), error {err:.3g}")
    res = {"reference": label(*REFERENCE), "orbit_rms_m": orbit_rms, "runs": [], "plateaus": {}}
    for r in rows:
        res["runs"].append({"label": label(*r[:4]), "level": r[0], "mode": r[1], "step_s": r[2], "sub_steps": r[3],
                            "wall_s": r[4], "error": r[5]})
    for level in ("quasistatic", "linear"):
        errs = sorted((r[2], r[5]) for r in rows if r[0] == level)
        fine = [e for h, e in errs if h <= 1e-4]
        if max(fine) < 1.5 * min(fine):
            res["plateaus"][level] = float(min(fine))
            print(f"{level}: the error stays at {min(fine):.3g} - {max(fine):.3g} for steps <= 1e-4 s: a plateau, "
                  f"the level's model error against the balls, not step error")
        else:
            print(f"{level}: the error still falls with the step ({', '.join(f'{h:g}: {e:.3g}' for h, e in errs)})")
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 5.2))
    marks = {"balls": "o", "quasistatic": "s", "linear": "^"}
    for level in ("balls", "quasistatic", "linear"):
        for mode in ((None,) if level != "balls" else ("bodies", "fast")):
            sel = [r for r in rows if r[0] == level and r[1] == mode]
            name = level if mode is None else f"balls, {mode} mode"
            ax.loglog([r[4] for r in sel], [r[5] for r in sel], marker=marks[level], ls="-", label=name)
            for r in sel:
                ax.annotate(f"{r[2]:g}" + (f" x{r[3]}" if r[3] > 1 else ""), (r[4], r[5]), fontsize=6,
                            xytext=(3, 3), textcoords="offset points")
    ax.set_xlabel("wall time [s] (median)")
    ax.set_ylabel("RMS orbit error / RMS orbit radius")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    ax.set_title(f"6208 test shaft, {OMEGA:g} rad/s, {F_STATIC:g} N + {F_TURN:g} N turning: work-precision of\n"
                 "the three levels against the ball element (body mode) at 1 us.", fontsize=9)
    names = ("step_s", "sub_steps", "wall_s", "error")
    cols = {n: [r[2 + i] for r in rows] for i, n in enumerate(names)}
    cols["level"] = [("balls", "quasistatic", "linear").index(r[0]) + (r[1] == "fast") * 10 for r in rows]
    save_figure(fig, out / "levels_work_precision.png", cols)
    print("    levels_work_precision.csv: level 0 balls (bodies), 10 balls (fast), 1 quasistatic, 2 linear")
    (out / "levels_work_precision.json").write_text(json.dumps(res, indent=1, default=float))
    print("written:", out)
    return res


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced."""
    return run.printed(
        "Work-precision of the bearing levels",
        "Wall time against orbit error of the three levels on a loaded test shaft, against the ball element "
        "at 1 us; a plateau is the level's model error.",
        [("levels/levels_work_precision.png", "wall time against orbit error, per level and step.")],
        last_lines=25)


if __name__ == "__main__":
    main()
