"""Speed and accuracy of the numba DEM reference engine against its requirement: at most 0.5 s of
wall time per simulated second with q_max and cage speed within 0.5 % and the tangential springs resolved.

Scene: 6208, F_r = 3000 N, 500 rad/s, full torus cage, lubrication on,
Cundall-Strack tangential history on, started from the analytic state.

For each setting it prints the wall seconds per simulated second (median of
``--repeat`` runs, one core), steps per second, and the relative errors of
q_max_inner, q_max_outer and cage_speed against a run of the same setting
at a quarter of the step, and the mean frictional power: in steady rolling
it is noise around zero (below 1e-3 W) when the tangential springs are
resolved, and large when an explicit spring chatters at its Coulomb cap. It also measures

* the largest step that does not blow up (bisection on short runs),
* the start-up time of a second process (numba cache),
* the memory of the sample buffers for a short and a 4x longer run at the
  same number of samples (memory does not grow with the number of steps).

Usage::

    python validation/performance/bench_reference.py [--t-end 0.2] [--repeat 3] [--out validation/out]

Writes ``bench_reference.json`` into the output folder.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import time
import tracemalloc
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.model.stability import SimulationError
from exudyn_bearing.solvers.reference import ReferenceEngine

SCENE = dict(Fr=3000.0, omega=500.0, cage=True, lubrication=True, friction="history", initial="analytic")

SETTINGS = {
    "explicit spring, dt 1 us (papers)": dict(dt=1e-6, tangential="explicit"),
    "explicit spring, dt 5 us": dict(dt=5e-6, tangential="explicit"),
    "explicit spring, dt 8 us": dict(dt=8e-6, tangential="explicit"),
    "implicit spring, dt 5 us": dict(dt=5e-6, tangential="implicit"),
    "implicit spring, dt 8 us": dict(dt=8e-6, tangential="implicit"),
    "regularized friction, verlet, dt 1 us": dict(dt=1e-6, friction="regularized"),
    "regularized friction, rk4, dt 2 us": dict(dt=2e-6, friction="regularized", integrator="rk4"),
}
KEYS = ("q_max_inner", "q_max_outer", "cage_speed")


def run(t_end, sample_dt, **kw):
    sc = eb.Scenario(t_end=t_end, sample_dt=sample_dt, **dict(SCENE, **kw))
    return eb.Results(ReferenceEngine("6208", sc).run(progress=False))


def largest_stable_step(tangential, lo=1e-6, hi=3e-5, t_end=0.01):
    """Bisection on dt: largest step whose short run neither blows up nor
    raises (within 2 % of the step)."""
    import warnings

    while hi / lo > 1.02:
        mid = math.sqrt(lo * hi)
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                run(t_end, 1e-3, dt=mid, tangential=tangential)
            lo = mid
        except SimulationError:
            hi = mid
    return lo


def second_start_seconds():
    code = ("import time; t = time.perf_counter(); import exudyn_bearing as eb; "
            "eb.simulate('6208', eb.Scenario(Fr=3000.0, omega=500.0, t_end=1e-3, dt=5e-6, tangential='implicit')); "
            "print(time.perf_counter() - t)")
    subprocess.run([sys.executable, "-c", code], check=True, capture_output=True)  # fills the cache
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True)
    return float(out.stdout.strip())


def buffer_memory(t_end, n_samples, dt):
    tracemalloc.start()
    run(t_end, t_end / n_samples, dt=dt, tangential="implicit")
    _cur, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    return peak


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--t-end", type=float, default=0.2, help="simulated time per run [s]")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--out", default=str(Path(__file__).resolve().parents[1] / "out"))
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    run(1e-3, 1e-4, dt=5e-6, tangential="implicit")  # compile / load the cache
    sample_dt = 1e-3
    rows = {}
    print(f"6208, Fr = 3000 N, 500 rad/s, cage + lubrication + tangential history, analytic start, "
          f"T = {args.t_end} s, one core, median of {args.repeat}")
    print(f"{'setting':40s} {'wall/sim s':>10s} {'steps/s':>10s} {'err q_in %':>10s} {'err q_out %':>11s} "
          f"{'err cage %':>10s} {'P_fric W':>10s}")
    for name, kw in SETTINGS.items():
        walls = []
        res = None
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the explicit 8 us row is above the estimate on purpose
            for _ in range(args.repeat):
                res = run(args.t_end, sample_dt, **kw)
                walls.append(res.wall_s)
        fine = run(args.t_end, sample_dt, **dict(kw, dt=kw["dt"] / 4)).summary()
        s = res.summary()
        errs = {k: abs(s[k] / fine[k] - 1.0) for k in KEYS}
        wall = float(np.median(walls))
        rows[name] = dict(kw, wall_per_sim_s=wall / args.t_end, steps_per_s=res.steps / wall,
                          **{f"err_{k}": v for k, v in errs.items()}, summary=s, fine=fine)
        print(f"{name:40s} {wall / args.t_end:10.3f} {res.steps / wall:10.3g} "
              f"{100 * errs['q_max_inner']:10.3f} {100 * errs['q_max_outer']:11.3f} "
              f"{100 * errs['cage_speed']:10.3f} {s['friction_power']:10.2g}")
    est = {t: ReferenceEngine("6208", eb.Scenario(**SCENE, tangential=t)).stable for t in ("explicit", "implicit")}
    limits = {t: largest_stable_step(t) for t in ("explicit", "implicit")}
    for t in ("explicit", "implicit"):
        e = est[t]
        print(f"stable step, {t} spring: estimate {e.dt * 1e6:.2f} us (limited by {e.limited_by}), "
              f"measured largest {limits[t] * 1e6:.2f} us; limits before the safety factor: normal "
              f"{e.normal * 1e6:.2f} us, tangential {e.tangential * 1e6:.2f} us, friction {e.friction * 1e6:.2f} us, "
              f"cage {e.cage * 1e6:.2f} us (cage load {e.cage_load:.2f} N: {e.cage_basis})")
    start = second_start_seconds()
    print(f"second process start-up and a 1 ms run: {start:.2f} s (numba cache)")
    m1 = buffer_memory(0.05, 50, 8e-6)
    m4 = buffer_memory(0.2, 50, 8e-6)
    print(f"peak traced memory, 50 samples: T = 0.05 s {m1 / 1e6:.2f} MB, T = 0.2 s {m4 / 1e6:.2f} MB "
          f"(ratio {m4 / m1:.2f})")
    report = dict(scene=SCENE, t_end=args.t_end, repeat=args.repeat, settings=rows,
                  stable_step_estimate={t: est[t].dt for t in est}, stable_step_measured=limits,
                  stable_step_limits={t: dict(normal=est[t].normal, tangential=est[t].tangential,
                                              friction=est[t].friction, cage=est[t].cage,
                                              limited_by=est[t].limited_by, cage_load=est[t].cage_load,
                                              cage_basis=est[t].cage_basis) for t in est},
                  second_start_s=start, memory_bytes={"T=0.05": m1, "T=0.2": m4},
                  machine=dict(cpu_count=os.cpu_count(), python=sys.version.split()[0]),
                  date=time.strftime("%Y-%m-%d %H:%M"))
    from exudyn_bearing.outputs.jsonio import to_jsonable

    (out / "bench_reference.json").write_text(json.dumps(to_jsonable(report), indent=2))
    print(f"written {out / 'bench_reference.json'}")


def report_section(run):
    """The report's section on the reference engine's speed against error, from bench_reference.json."""
    from _report import pct

    d = run.load("bench_reference.json")
    lines = ["## Reference core: speed against error", "",
             f"Command: `{run.command}` (engine: reference core; T = "
             f"{d['t_end']} s per run, median of {d['repeat']}). Scene: 6208, F_r = 3000 N, 500 rad/s, cage, "
             "lubrication and Cundall-Strack history on, analytic start. Errors: the summary over the last "
             "quarter against the same setting at a quarter of the step.", "",
             "| setting | wall s per simulated s | steps/s | err q_max_inner | err q_max_outer | err cage_speed | "
             "mean frictional power [W] |", "|---|---|---|---|---|---|---|"]
    for name, r in d["settings"].items():
        lines.append(f"| {name} | {r['wall_per_sim_s']:.3f} | {r['steps_per_s']:.3g} | {pct(r['err_q_max_inner'])} | "
                     f"{pct(r['err_q_max_outer'])} | {pct(r['err_cage_speed'])} | "
                     f"{r['summary']['friction_power']:.2g} |")
    est, meas = d["stable_step_estimate"], d["stable_step_measured"]
    ok = [f"{n} ({r['wall_per_sim_s']:.2f} s)" for n, r in d["settings"].items()
          if r["wall_per_sim_s"] <= 0.5 and max(r["err_q_max_inner"], r["err_q_max_outer"], r["err_cage_speed"]) <= 5e-3
          and r["summary"]["friction_power"] < 1.0]
    lines += ["", "- Requirement (at most 0.5 s per simulated second, errors of q_max and cage_speed <= 0.5 %, "
              "tangential springs resolved): met in this run by " + ("; ".join(ok) if ok else "no setting") + "."]
    lim = d["stable_step_limits"]

    def limits_text(t):
        names = {"normal": "normal Hertz mode of a ball between its races",
                 "tangential": "rocking mode of the Cundall-Strack springs", "friction": "regularised friction",
                 "cage": f"critically damped ball / cage-ball contacts at {lim[t]['cage_load']:.2f} N "
                         f"({lim[t]['cage_basis']})"}
        return ", ".join(f"{names[k]} {lim[t][k] * 1e6:.2f} us" for k in names
                         if lim[t][k] is not None and math.isfinite(lim[t][k]))  # inf is null in the JSON

    imp = lim["implicit"]
    lines += [
              f"- Stable step: estimate {est['explicit'] * 1e6:.2f} us (explicit spring, limited by "
              f"{lim['explicit']['limited_by']}) and {est['implicit'] * 1e6:.2f} us (implicit, limited by "
              f"{imp['limited_by']}): `stable_step`, the safety factor times the smallest of its limits (explicit "
              f"spring: {limits_text('explicit')}; implicit: {limits_text('implicit')}). The largest step that did "
              f"not blow up (bisection on 10 ms runs) was {meas['explicit'] * 1e6:.2f} and "
              f"{meas['implicit'] * 1e6:.2f} us. The explicit Cundall-Strack spring does not blow up above its "
              "rocking-mode limit because its force is capped at mu F_n, but it chatters at the cap (the large "
              "frictional power of the explicit 8 us row, against about 1e-4 W when resolved); the implicit spring "
              "(K_t / (1 + K_t dt^2 / m_t)) removes that limit. Beyond the normal mode the cage contacts come next, "
              f"at {imp['cage'] / imp['normal']:.2f} times its limit in this steady scene (their loads are small "
              "here; in start-up and slow-down they limit first: next section): a step twice as large needs both "
              "integrated implicitly.",
              "- Cost: one kernel call per force evaluation, the contact laws being scalar physics functions "
              "compiled into the force loop (no calls that pass arrays inside it), the exact Hertz level "
              "tabulated (relative error "
              "<= 1e-7) and re-evaluated per contact only when R_y/R_x moves by more than 1e-6.",
              "- RK4 (history-free friction only) costs four evaluations per step; it is the most accurate per "
              "step, not the fast choice.",
              f"- Numba cache: a second process starts and runs 1 ms in {d['second_start_s']:.2f} s.",
              f"- Memory does not grow with the number of steps: peak traced memory for 50 samples "
              f"{d['memory_bytes']['T=0.05'] / 1e6:.2f} MB for T = 0.05 s and "
              f"{d['memory_bytes']['T=0.2'] / 1e6:.2f} MB for T = 0.2 s.", ""]
    return "\n".join(lines)


if __name__ == "__main__":
    main()
