"""The rigid cage in the reference engine (docs/theory/cage.md) against the torus cage, and what it costs.

(a) The DEM papers' radial 6208 case (F_r = 3000 N at 500 rad/s, steady from the analytic state): the
    torus cage against a rigid cage with the torus cage's two properties, ball-guided and frictionless
    (the estimated cage's geometry): Q_max of both races, cage speed and ball spin after --t-end, the
    relative differences against 0.5 % (the rigid cage's acceptance criterion, docs/theory/cage.md).
(b) The same 6208 with the estimated outer-land-guided brass cage (pocket friction 0.1, the DEM oil on
    the land): cage slip, whirl of the cage centre, pocket and land forces, the cage's losses and the
    energy balance.
(c) The 7208 under F_r = F_a = 3000 N at 500 rad/s: the torus cage at its stable step (0.5 us; the
    estimate 0.62 us) against the estimated rigid cage at --rigid-dt (5 us; cage_damping='implicit': the
    land's force linearly implicit), both --cost-t-end long (default --t-end): wall time per simulated
    second of the whole simulate call and of the integration alone (median of --repeat runs of each,
    interleaved, same session; every run solves its own static equilibrium, as a single run does), their
    ratio, whether the rigid cage stays at or below 1 s per simulated second, the stable-step estimates
    and their parts (normal, tangential, friction, cage), loads, cage speed, dissipation and energy
    residual.
(d) Step convergence of the rigid cage on the 7208: 5 us (implicit cage damping) against 1 us (explicit),
    3 --t-end long, summaries over the last quarter, with the regularised ball / race friction (the
    point level's Cundall-Strack spring is itself not converged in the step, so its runs would hide the
    cage's convergence): loads, cage speed, pocket and land losses.
(e) The orbit of the cage centre of (b) and (c) in a plot, with its data.
(f) With --profile instead: where the time of the rigid cage's 7208 step at --rigid-dt goes. On a state
    advanced 10 ms from the analytic start, the compiled contact kernel is timed with stages switched off
    through the parameter vector (the same compiled code): the ball / raceway contacts alone (no cage), the
    pockets (no land), the land's film, the land's linearly implicit solve (cage_damping explicit: the four
    extra evaluations of the film for its Jacobians); and the whole velocity-Verlet step, whose excess over
    the frozen kernel is the integration's own work and the per-contact caches' misses of the moving state
    (their rates printed). Thread CPU time, medians of --repeat rounds (at least 5), ns per step.
(g) With --compare-dt DT [DT ...]: the rigid cage's 7208 run of (c) (its last run) against runs at those steps,
    equally long: the relative differences of the loads, cage and ball speeds, dissipation and cage losses over
    the summary's window, and each run's energy balance (the summary's energy_check: residual, closes within
    1 %), which tell whether a larger step keeps the run's results (0.5 % and a closed balance).

    python validation/studies/rigid_cage.py [--t-end 0.1] [--repeat 3] [--cost-t-end T] [--rigid-dt 5e-6]
                                            [--out validation/out/rigid_cage]
    python validation/studies/rigid_cage.py --profile [--rigid-dt 5e-6] [--repeat 7]
    python validation/studies/rigid_cage.py --cost-t-end 0.3 --compare-dt 6e-6 7e-6

Writes rigid_cage.json, rigid_cage_orbit.png and rigid_cage_orbit.npz into --out.
"""
from __future__ import annotations

import argparse
import json
import time
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.data.cages import estimated_cage
from exudyn_bearing.model import layout as L
from exudyn_bearing.model.stability import stable_step
from exudyn_bearing.outputs.plotting import pyplot, save_figure
from exudyn_bearing.physics import load_distribution

ROOT = Path(__file__).resolve().parents[2]
KEYS = ("q_max_inner", "q_max_outer", "cage_speed", "ball_spin")


def run(bearing, scenario, fresh=False):
    """(wall [s], summary, record) of one reference-engine run (steadiness warnings kept in the summary);
    ``fresh``: without the static equilibria earlier runs of this process solved (a timed run pays for its
    own, as a single run does)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        if fresh:
            load_distribution._SOLVED.clear()
        t0 = time.perf_counter()
        rec = eb.simulate(bearing, scenario, progress=False)
        wall = time.perf_counter() - t0
        return wall, rec.summary(), rec


def pick(summary, keys):
    return {k: summary.get(k) for k in keys}


def step_parts(bearing, scenario):
    """The stable-step estimate of the scene and its parts [s] (model.stability.stable_step)."""
    st = stable_step(bearing, scenario)
    return {"dt": st.dt, "normal": st.normal, "tangential": st.tangential, "friction": st.friction,
            "cage": st.cage, "limited_by": st.limited_by}


def _us(x):
    return "-" if x is None or not np.isfinite(x) else f"{1e6 * x:.4g}"


def step_line(parts):
    """``dt 7.39 us (normal 11.2, tangential 8.69, friction -, cage 9.1; set by tangential)``."""
    return (f"dt {_us(parts['dt'])} us (normal {_us(parts['normal'])}, tangential {_us(parts['tangential'])}, "
            f"friction {_us(parts['friction'])}, cage {_us(parts['cage'])}; set by {parts['limited_by']})")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--t-end", type=float, default=0.1, help="simulated time of every run [s]")
    ap.add_argument("--repeat", type=int, default=3, help="runs of each 7208 variant for the wall-time median")
    ap.add_argument("--cost-t-end", type=float, default=None,
                    help="simulated time of the timed 7208 runs of (c) [s] (default: --t-end)")
    ap.add_argument("--rigid-dt", type=float, default=5e-6, help="step of the rigid cage's 7208 runs (c), (f) [s]")
    ap.add_argument("--profile", action="store_true", help="only (f): where the rigid cage's step time goes")
    ap.add_argument("--compare-dt", type=float, nargs="*", default=(),
                    help="(g): steps [s] whose rigid-cage 7208 runs are compared with the one of (c)")
    ap.add_argument("--out", default=str(ROOT / "validation" / "out" / "rigid_cage"))
    args = ap.parse_args(argv)
    if args.profile:
        profile_step(args.rigid_dt, max(args.repeat, 5))
        return 0
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    report = {"t_end_s": args.t_end}

    # (a) torus against the frictionless ball-guided rigid cage
    b = eb.catalog["6208"]
    base = {"Fr": 3000.0, "omega": 500.0, "t_end": args.t_end, "dt": 3e-6, "sample_dt": 1e-4}
    _, torus, _ = run(b, eb.Scenario(**base))
    ideal = estimated_cage(b, guidance="ball", pocket_friction=0.0)
    _, rigid, _ = run(b, eb.Scenario(**base, cage="rigid", rigid_cage=ideal))
    diff = {k: rigid[k] / torus[k] - 1.0 for k in KEYS}
    report["a_6208_torus_vs_ideal_rigid"] = {"torus": pick(torus, KEYS), "rigid": pick(rigid, KEYS),
                                             "relative_difference": diff,
                                             "within_0.5_percent": all(abs(v) < 5e-3 for v in diff.values())}
    print(f"(a) 6208, {args.t_end} s at 3 us: rigid (ball-guided, frictionless) / torus - 1:")
    for k, v in diff.items():
        print(f"    {k:12s} {100 * v:+.3f} %   (torus {torus[k]:.5g}, rigid {rigid[k]:.5g})")

    # (b) the estimated outer-land-guided brass cage
    land_keys = ("cage_speed", "cage_slip", "cage_whirl_radius", "cage_whirl_ratio", "pocket_force_max",
                 "land_force_mean", "land_eccentricity_max", "cage_power_pocket", "cage_power_land",
                 "dissipation", "energy_residual")
    _, land, rec6208 = run(b, eb.Scenario(**{**base, "dt": 4e-6}, cage="rigid"))
    report["b_6208_land_guided"] = pick(land, land_keys + KEYS)
    print("(b) 6208, estimated outer-land-guided brass cage, 4 us:")
    for k in land_keys:
        print(f"    {k:22s} {land[k]}")

    # (c) the 7208: torus at 0.5 us against rigid at --rigid-dt, interleaved
    b7 = eb.catalog["7208"]
    t_cost = args.cost_t_end or args.t_end
    sc7 = {"Fr": 3000.0, "Fa": 3000.0, "omega": 500.0, "t_end": t_cost, "sample_dt": 1e-4}
    rigid = f"rigid_{args.rigid_dt * 1e6:g}us"
    variants = {"torus_0.5us": eb.Scenario(**sc7, dt=0.5e-6),
                rigid: eb.Scenario(**sc7, dt=args.rigid_dt, cage="rigid", cage_damping="implicit")}
    walls = {k: [] for k in variants}   # whole simulate() call, set-up and summary included
    engine_walls = {k: [] for k in variants}   # the engine's integration alone (the summary's wall_s)
    summaries, records = {}, {}
    for i in range(args.repeat):
        for name in (list(variants) if i % 2 == 0 else list(variants)[::-1]):
            wall, summary, rec = run(b7, variants[name], fresh=True)
            walls[name].append(wall / t_cost)
            engine_walls[name].append(summary["wall_s"] / t_cost)
            summaries[name], records[name] = summary, rec
            print(f"    7208 {name}, {t_cost:g} s: {wall / t_cost:.3g} s per simulated second "
                  f"({summary['wall_s'] / t_cost:.3g} s integrating)", flush=True)
    med = {k: float(np.median(v)) for k, v in walls.items()}
    med_engine = {k: float(np.median(v)) for k, v in engine_walls.items()}
    parts = {name: step_parts(b7, sc) for name, sc in variants.items()}
    keys7 = KEYS + ("dissipation", "energy_residual", "stable_dt", "cage_power_pocket", "cage_power_land",
                    "land_eccentricity_max")
    report["c_7208"] = {name: {"dt_s": variants[name].dt, "wall_per_simulated_second_median": med[name],
                               "walls": walls[name],
                               "integration_wall_per_simulated_second_median": med_engine[name],
                               "integration_walls": engine_walls[name], "stable_step": parts[name],
                               **pick(summaries[name], keys7)} for name in variants}
    report["c_7208"]["cost_t_end_s"] = t_cost
    report["c_7208"]["repeat"] = args.repeat
    report["c_7208"]["rigid"] = rigid
    report["c_7208"]["cost_ratio_rigid_over_torus"] = med[rigid] / med["torus_0.5us"]
    report["c_7208"]["integration_cost_ratio_rigid_over_torus"] = med_engine[rigid] / med_engine["torus_0.5us"]
    report["c_7208"]["rigid_at_most_1s_per_simulated_second"] = bool(med[rigid] <= 1.0)
    report["c_7208"]["rigid_integration_at_most_1s_per_simulated_second"] = bool(med_engine[rigid] <= 1.0)
    print(f"(c) 7208, {t_cost:g} s runs, wall per simulated second, median of {args.repeat} (interleaved):")
    for name in variants:
        print(f"    {name:12s} step {variants[name].dt * 1e6:g} us: {med[name]:.3g} s per s ({med_engine[name]:.3g} s "
              "integrating)")
    print(f"    ratio rigid / torus: {med[rigid] / med['torus_0.5us']:.3g} "
          f"({med_engine[rigid] / med_engine['torus_0.5us']:.3g} integrating)")
    print(f"    rigid cage at {args.rigid_dt * 1e6:g} us within 1 s per simulated second: "
          f"{'yes' if med[rigid] <= 1.0 else 'no'} ({med[rigid]:.3g} s; integrating "
          f"{'yes' if med_engine[rigid] <= 1.0 else 'no'}, {med_engine[rigid]:.3g} s)")
    # the table of docs/theory/dynamics.md#stable-step: both cages with either cage damping (no runs)
    for name, sc in (("torus, implicit cage damping", eb.Scenario(**sc7, dt=0.5e-6, cage_damping="implicit")),
                     ("rigid, explicit cage damping", eb.Scenario(**sc7, dt=args.rigid_dt, cage="rigid"))):
        parts[name] = step_parts(b7, sc)
    report["c_7208"]["stable_steps"] = parts
    print("    stable-step estimates and their parts [us]:")
    for name in parts:
        print(f"    {name:30s} {step_line(parts[name])}")

    # (g) the rigid cage's 7208 run at other steps against the one at --rigid-dt
    if args.compare_dt:
        ref = summaries[rigid]
        g_keys = ("q_max_inner", "q_max_outer", "cage_speed", "ball_spin", "dissipation", "cage_power_pocket",
                  "cage_power_land", "pocket_force_mean")
        g = {}
        print(f"(g) 7208 rigid cage, {t_cost:g} s: runs at other steps / the one at {args.rigid_dt * 1e6:g} us - 1, "
              "and the energy balance over the summary's window:")
        print(f"    {args.rigid_dt * 1e6:g} us: energy residual {100 * ref['energy_check']['residual']:+.2f} % "
              f"({'closes' if ref['energy_check']['passed'] else 'does not close'} within 1 %)")
        for dt in args.compare_dt:
            s_dt = run(b7, variants[rigid].replace(dt=dt), fresh=True)[1]
            rel = {k: s_dt[k] / ref[k] - 1.0 for k in g_keys}
            ok = all(abs(rel[k]) <= 5e-3 for k in g_keys) and bool(s_dt["energy_check"]["passed"])
            g[f"{dt * 1e6:g}us"] = {"relative_difference": rel, **pick(s_dt, g_keys),
                                   "energy_residual_relative": s_dt["energy_check"]["residual"],
                                   "energy_closes": bool(s_dt["energy_check"]["passed"]),
                                   "within_0.5_percent_and_closed": ok}
            print(f"    {dt * 1e6:g} us: " + ", ".join(f"{k} {100 * v:+.2f} %" for k, v in rel.items())
                  + f"; energy residual {100 * s_dt['energy_check']['residual']:+.2f} % "
                  f"({'closes' if s_dt['energy_check']['passed'] else 'does not close'} within 1 %); "
                  f"{'keeps' if ok else 'does not keep'} the results within 0.5 %", flush=True)
        report["g_7208_rigid_step_comparison"] = {"reference_dt_s": args.rigid_dt, "t_end_s": t_cost,
                                                  "reference_energy_residual_relative": ref["energy_check"]["residual"],
                                                  "steps": g}

    # (d) step convergence of the rigid cage
    conv_keys = ("q_max_inner", "cage_speed", "ball_spin", "cage_power_pocket", "cage_power_land",
                 "pocket_force_mean", "land_eccentricity_max", "energy_residual")
    long = {**sc7, "t_end": 3 * args.t_end, "cage": "rigid", "friction": "regularized"}
    fine = run(b7, eb.Scenario(**long, dt=1e-6))[1]
    coarse = run(b7, eb.Scenario(**long, dt=5e-6, cage_damping="implicit"))[1]
    conv = {k: coarse[k] / fine[k] - 1.0 for k in conv_keys[:-2]}
    report["d_7208_step_convergence"] = {"1us": pick(fine, conv_keys), "5us_implicit": pick(coarse, conv_keys),
                                         "relative_difference": conv}
    print(f"(d) 7208 rigid cage, regularised friction, {3 * args.t_end:g} s: 5 us (implicit) / 1 us - 1:")
    for k, v in conv.items():
        print(f"    {k:18s} {100 * v:+.2f} %   (1 us {fine[k]:.5g}, 5 us {coarse[k]:.5g})")
    print(f"    energy residual: 1 us {fine['energy_residual']:.3g}, 5 us {coarse['energy_residual']:.3g} (the ball / "
          "race regularised friction's own step limit)")

    # (e) orbits of the cage centre
    fig, ax = pyplot().subplots(1, 2, figsize=(10, 4.6))
    arrays = {}
    for k, (name, rec) in enumerate((("6208 (b)", rec6208), ("7208 (c)", records[rigid]))):
        xy = rec.data["xc"][:, 0, :2] * 1e6
        arrays[f"t_{k}"], arrays[f"xy_um_{k}"] = rec.data["t"], xy
        ax[k].plot(xy[:, 0], xy[:, 1], lw=0.6)
        c = rec.model_parameters()[L.P_LAND_C] * 1e6
        th = np.linspace(0, 2 * np.pi, 200)
        ax[k].plot(c * np.cos(th), c * np.sin(th), "k--", lw=0.8, label=f"land clearance {c:.0f} um")
        ax[k].set_aspect("equal")
        ax[k].set_xlabel("cage centre x [um]")
        ax[k].set_ylabel("cage centre y [um]")
        ax[k].set_title(f"{name}, 0 - {rec.data['t'][-1]:.3g} s")
        ax[k].legend(loc="upper right", fontsize=8)
    save_figure(fig, out / "rigid_cage_orbit.png")
    np.savez(out / "rigid_cage_orbit.npz", **arrays)
    (out / "rigid_cage.json").write_text(json.dumps(report, indent=1, default=float))
    print(f"wrote {out / 'rigid_cage.json'}, rigid_cage_orbit.png/.npz")
    return 0 if report["a_6208_torus_vs_ideal_rigid"]["within_0.5_percent"] else 1


def profile_step(dt, repeat):
    """(f): the rigid cage's 7208 step at ``dt`` by stages (module docstring), printed."""
    from exudyn_bearing._jit import kernel
    from exudyn_bearing.model.contact import forces, scene_loss_path, scene_paths
    from exudyn_bearing.model.motion import ring_poses
    from exudyn_bearing.solvers.reference import ReferenceEngine
    from exudyn_bearing.solvers.reference.integrators import evaluate, run_verlet

    @kernel(cache=False)
    def time_forces(reps, p, table, xb, vb, wb, xc, vc, rings, hist, hz, fb, tb, fc, fr, glob, diag, cage_load,
                    defect_path, ellipse_path, loss_path):
        acc = 0.0
        for _ in range(reps):  # dt_hist 0: the frozen state's springs stay as they are
            acc += forces(p, table, xb, vb, wb, xc, vc, rings, hist, hist, 0.0, hz, fb, tb, fc, fr, glob, diag,
                          cage_load, False, defect_path, ellipse_path, loss_path)
        return acc

    settle = 0.01
    sc = eb.Scenario(Fr=3000.0, Fa=3000.0, omega=500.0, t_end=settle, sample_dt=settle, dt=dt, cage="rigid",
                     cage_damping="implicit")
    eng = ReferenceEngine("7208", sc)
    st = eng.initial_state()
    p, table = eng.params, eng.table
    xb, vb, wb, xc, vc, ring, hist, hz = (st[k] for k in ("xb", "vb", "wb", "xc", "vc", "ring", "hist", "hz"))
    z = xb.shape[0]
    fb, tb, fc, fring, glob = np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((z, 3)), np.zeros(3), np.zeros(L.NGLOBAL)
    fr, rings, diag, cage_load = np.zeros((2, 6)), ring_poses(), np.zeros((z, 2, L.NDIAG)), np.zeros((z, 2))
    paths = scene_paths(p) + (scene_loss_path(p),)
    frames = hist[:, L.H_E1:].copy()
    evaluate.py_func(0.0, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag,
                     cage_load, False, *paths)
    hist[:, L.H_E1:] = frames
    clock = {"t": 0.0}

    def step(n):
        e3 = np.zeros((0, z, 3))
        run_verlet(n, clock["t"], p, table, xb, vb, wb, xc, vc, ring, hist, hz, fb, tb, fc, fring, 1 << 40, 0,
                   np.zeros(0), np.zeros((0, L.NGLOBAL)), np.zeros((0, z, 2, L.NDIAG)), np.zeros((0, z, 2)), e3, e3,
                   e3, e3, e3, np.zeros((0, 6)), 0, np.zeros(L.NSIGNAL + 1), np.zeros((0, L.NSIGNAL + 1)), glob,
                   diag, cage_load, rings, fr, paths[0], paths[1], None, paths[2])
        clock["t"] += n * dt

    step(round(settle / dt))
    variants = {"full": p}
    q = p.copy()
    q[L.P_CAGE_TAU] = 0.0  # explicit cage damping: no implicit land solve
    variants["explicit"] = q
    q = p.copy()
    q[L.P_GUIDANCE] = 0.0  # no land
    variants["pockets"] = q
    q = q.copy()
    q[L.P_RIGID] = 0.0  # no cage at all: the ball / raceway contacts (and the open ball / ball checks)
    variants["races"] = q

    def kernel_time(q, reps):
        return time_forces(reps, q, table, xb.copy(), vb, wb, xc, vc, rings, hist.copy(), hz, fb, tb, fc, fr, glob,
                           diag, cage_load, *paths)

    for q in variants.values():
        kernel_time(q, 10)
    step(10)
    reps, n_step = 20000, 4000
    samples = {k: [] for k in list(variants) + ["step"]}
    for _ in range(repeat):  # interleaved rounds (the machine's load drifts)
        for k, q in variants.items():
            t0 = time.thread_time()
            kernel_time(q, reps)
            samples[k].append(1e9 * (time.thread_time() - t0) / reps)
        t0 = time.thread_time()
        step(n_step)
        samples["step"].append(1e9 * (time.thread_time() - t0) / n_step)
    t = {k: float(np.median(v)) for k, v in samples.items()}
    # the caches' misses per closed ball / raceway contact and step of the running engine
    cols = (L.HZ_RATIO, L.HZ_LN_U, L.HZ_LN_W, L.HZ_EXP)
    miss, closed = np.zeros(len(cols)), 0
    for _ in range(400):
        before = hz[:, :, cols].copy()
        step(1)
        miss += np.sum(hz[:, :, cols] != before, axis=(0, 1))
        closed += int(np.sum(hz[:, :, L.HZ_GEO + 6] > 0.0))
    miss /= max(closed, 1)
    rows = [("ball / raceway contacts and the kernel's frame (no cage)", t["races"]),
            (f"{z} pockets", t["pockets"] - t["races"]),
            ("land film (one evaluation)", t["explicit"] - t["pockets"]),
            ("land's linearly implicit solve (four more film evaluations, 2x2 solve)", t["full"] - t["explicit"]),
            ("rest of the step: kick/drift, ring, energy, cache misses of the moving state", t["step"] - t["full"])]
    print(f"(f) 7208, rigid cage, dt {dt * 1e6:g} us, state after {settle * 1e3:g} ms: whole step {t['step']:.0f} ns "
          f"({t['step'] * 1e-9 / dt:.3f} s CPU per simulated s), contact kernel on the frozen state {t['full']:.0f} ns "
          f"(thread CPU time, medians of {repeat} rounds)")
    print(f"    {'stage':76s} {'ns/step':>8s} {'share':>6s}")
    for label, ns in rows:
        print(f"    {label:76s} {ns:8.0f} {100 * ns / t['step']:5.1f}%")
    print(f"    cache misses per closed contact and step: Hertz {miss[0]:.3f}, film ln U {miss[1]:.3f}, ln W {miss[2]:.3f}, "
          f"exp E {miss[3]:.3f} ({closed / 400:.1f} closed contacts per step)")
    return t


def report_section(run):
    """The report's section: the rigid cage against the torus cage, its step convergence and its cost."""
    try:
        r = run.load("rigid_cage/rigid_cage.json")
    except FileNotFoundError:
        return ""
    from _report import pct

    a, c, d = r["a_6208_torus_vs_ideal_rigid"], r["c_7208"], r["d_7208_step_convergence"]
    rigid = c.get("rigid", "rigid_5us")
    tor, rig = c["torus_0.5us"], c[rigid]
    lines = ["## The rigid cage against the torus cage, and its cost", "",
             "The rigid cage of the reference engine (docs/theory/cage.md) with the torus cage's two properties "
             "(ball-guided, frictionless) against the torus cage on the papers' 6208 "
             f"({r['t_end_s']:g} s at 3 us), and the 7208 under F_r = F_a = 3000 N at 500 rad/s: the torus cage at "
             f"0.5 us against the estimated rigid cage at {rig['dt_s'] * 1e6:g} us ({c['cost_t_end_s']:g} s runs, "
             f"median of {c['repeat']}, interleaved in one session).", "",
             f"Command: `{run.command}`", "",
             "| 6208 | " + " | ".join(KEYS) + " |", "|---|" + "---|" * len(KEYS),
             "| rigid / torus - 1 | " + " | ".join(pct(a["relative_difference"][k], 3) for k in KEYS) + " |", "",
             "| 7208 | step [us] | wall per simulated s [s] | integrating [s] | stable-step estimate [us] "
             "| normal | tangential | cage | set by |", "|---|---|---|---|---|---|---|---|---|"]
    for name, v in (("torus cage", tor), ("rigid cage", rig)):
        sp = v["stable_step"]
        lines.append(f"| {name} | {v['dt_s'] * 1e6:g} | {v['wall_per_simulated_second_median']:.3g} | "
                     f"{v['integration_wall_per_simulated_second_median']:.3g} | {_us(sp['dt'])} | {_us(sp['normal'])} | "
                     f"{_us(sp['tangential'])} | {_us(sp['cage'])} | {sp['limited_by']} |")
    lines += ["", f"Rigid over torus: {c['cost_ratio_rigid_over_torus']:.3g} of the wall time "
              f"({c['integration_cost_ratio_rigid_over_torus']:.3g} integrating); the rigid cage "
              f"{'stays within' if c['rigid_at_most_1s_per_simulated_second'] else 'exceeds'} 1 s per simulated "
              "second in this run. Step convergence of the rigid cage (regularised friction, 5 us implicit against "
              "1 us): " + ", ".join(f"{k} {pct(v, 2)}" for k, v in d["relative_difference"].items()) + ".", ""]
    g = r.get("g_7208_rigid_step_comparison")
    if g:
        lines += [f"The rigid cage's 7208 run at other steps against the one at {g['reference_dt_s'] * 1e6:g} us "
                  f"(energy residual {pct(g['reference_energy_residual_relative'], 2)}): "
                  + "; ".join(f"{dt}: Q_max {pct(v['relative_difference']['q_max_inner'], 2)}, cage speed "
                              f"{pct(v['relative_difference']['cage_speed'], 2)}, pocket loss "
                              f"{pct(v['relative_difference']['cage_power_pocket'], 2)}, energy residual "
                              f"{pct(v['energy_residual_relative'], 2)}" for dt, v in g["steps"].items()) + ".", ""]
    lines += run.figure("rigid_cage/rigid_cage_orbit.png", "The orbits of the cage centre of (b) and (c).")
    return "\n".join(lines)


if __name__ == "__main__":
    raise SystemExit(main())
