"""Reference-engine step time of this code against a baseline version, runs interleaved in one process.

Scene and settings: the two headline rows of ``bench_reference.py`` (6208,
F_r = 3000 N, 500 rad/s, cage, lubrication, Cundall-Strack history,
analytic start; implicit spring at dt 8 us and explicit spring at 5 us).
The baseline package (``--baseline``: a git revision of this repository,
exported with ``git archive``, or a folder holding a checkout) is imported
beside this one under another name (``bench_defects.import_baseline``), so
that both run in the same process, alternately: in each of ``--rounds``
rounds every setting runs the baseline, the new code and the new code
again (the control, whose ratio to the first new run is the noise floor),
in rotating order. It prints per setting the medians of the wall seconds
per simulated second of the integration (``RunRecord.wall_s``, compilation
excluded), the median of the per-round ratios new/baseline and new/new, and
whether the sampled arrays of the last baseline and new runs are bitwise
equal (else the relative differences of the summary quantities, beside
the largest of those of the baseline run again with F_r changed by a
relative +-1, 2, 3, 5, 7 and 10 x 1e-15 (``--perturbations``): the
round-off floor, the differences a
reordering of floating-point operations makes in this scene).

``--scene 7208-rigid`` times instead the 7208 under F_r = F_a = 3000 N at
500 rad/s with its estimated rigid cage (outer-land-guided, implicit cage
damping) at 5 us, the scene of ``validation/studies/rigid_cage.py`` (c)
(its JSON: ``bench_kernel_ab_7208_rigid.json``). That run is chaotic: a
change of the last bits grows to the percent within 0.1 s, so its
round-off floor is of the size of the summary's own scatter.

With ``--cold N`` it measures instead the cold start of both versions: the
``profile_reference.py --compile`` job (import, then the README's main job
for 2 ms, which compiles the kernels) in a fresh process with an empty numba
cache (``NUMBA_CACHE_DIR`` a new temporary folder), N times each version,
alternately; medians of the wall and CPU seconds of the first run and of
import + first run.

Usage::

    python validation/performance/bench_kernel_ab.py [--baseline e61f1e5] [--rounds 9] [--t-end 0.2] [--out validation/out]
    python validation/performance/bench_kernel_ab.py --scene 7208-rigid --baseline f79cc7f [--rounds 9] [--t-end 0.2]
    python validation/performance/bench_kernel_ab.py --cold 3

Writes ``bench_kernel_ab.json`` into the output folder.
"""
from __future__ import annotations

import argparse
import importlib
import json
import os
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.outputs.jsonio import to_jsonable

from _bench import interleaved_ab  # validation/ (the script's folder is on sys.path)
from bench_defects import baseline_source, compare, import_baseline  # validation/ (the script's folder is on sys.path)
from bench_reference import KEYS, SCENE
from profile_reference import _COLD, COLD_SCENES

HERE = Path(__file__).resolve().parent
#: main before this step-time work (the semi-axes by a square root, ln(xi E') once per evaluation).
BASELINE_REV = "e61f1e5"
SETTINGS = {"implicit spring, dt 8 us": {"dt": 8e-6, "tangential": "implicit"},
            "explicit spring, dt 5 us": {"dt": 5e-6, "tangential": "explicit"}}
SUMMARY_KEYS = (*KEYS, "friction_power", "friction_torque", "ball_spin")
#: the scenes: (bearing, scenario, settings)
SCENES = {"6208": ("6208", SCENE, SETTINGS),
          "7208-rigid": ("7208", dict(Fr=3000.0, Fa=3000.0, omega=500.0, cage="rigid", cage_damping="implicit",
                                      initial="analytic"), {"rigid cage, dt 5 us": {"dt": 5e-6}})}
#: relative moves of F_r whose summary differences from the unmoved baseline make the round-off floor: the last
#: bits of the input (1e-15 is about 5 units of the last place), both signs, up to 1e-14
PERTURBATIONS = tuple(s * k * 1e-15 for k in (1, 2, 3, 5, 7, 10) for s in (1.0, -1.0))


def _moves(n):
    eps = sorted(abs(e) for e in PERTURBATIONS[:n])
    return f"{n} relative amounts (+- {eps[0]:.0e} ... {eps[-1]:.0e})"


def run(pkg, t_end, kw, scene="6208"):
    bearing, base, _settings = SCENES[scene]
    sc = pkg.Scenario(t_end=t_end, sample_dt=1e-3, **dict(base, **kw))
    engine = importlib.import_module(pkg.__name__ + ".solvers.reference").ReferenceEngine
    return pkg.Results(engine(bearing, sc).run(progress=False))


def cold_starts(baseline, out, n):
    """Cold start (empty numba cache) of the baseline and of this code, ``n``
    times each, alternately: medians of the wall and CPU seconds of the first
    run and of import + first run (the README job of ``profile_reference.py
    --compile``)."""
    import re
    import subprocess

    roots = {"baseline": str(baseline_source(baseline, out)), "new": str(HERE.parents[1])}
    job = f"SCENE = {COLD_SCENES['readme']!r}\n" + _COLD
    times = {k: [] for k in roots}
    for i in range(n):
        for name in (("baseline", "new") if i % 2 == 0 else ("new", "baseline")):
            with tempfile.TemporaryDirectory() as cache:
                env = dict(os.environ, NUMBA_CACHE_DIR=cache, PYTHONPATH=roots[name])
                res = subprocess.run([sys.executable, "-c", job], env=env, capture_output=True, text=True,
                                     check=True, cwd=cache)
            m = re.search(r"import: ([\d.]+) s wall, ([\d.]+) s CPU; first simulate: ([\d.]+) s wall, ([\d.]+) s CPU",
                          res.stdout)
            w_imp, c_imp, w_run, c_run = (float(x) for x in m.groups())
            times[name].append((w_run, c_run, w_imp + w_run, c_imp + c_run))
    print(f"cold start (first 2 ms run of the 6208 scene {COLD_SCENES['readme']}, empty numba cache), {n} fresh "
          "processes each, alternately; medians [s]:")
    for name, rows in times.items():
        w, c, wt, ct = np.median(np.array(rows), axis=0)
        runs = ", ".join(f"{a:.1f}/{b:.1f}" for a, b, _, _ in rows)
        print(f"  {name:8s} first simulate: wall {w:6.1f}  CPU {c:6.1f};  import + first simulate: wall {wt:6.1f}  "
              f"CPU {ct:6.1f}   (first simulate per process, wall/CPU: {runs})")
    return times


def _rel(a, b):
    return abs(a / b - 1.0) if b != 0.0 else abs(a - b)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--baseline", default=BASELINE_REV,
                    help=f"a git revision of this repository or a folder holding exudyn_bearing "
                         f"(default {BASELINE_REV})")
    ap.add_argument("--rounds", type=int, default=9)
    ap.add_argument("--t-end", type=float, default=0.2, help="simulated time per run [s]")
    ap.add_argument("--perturbations", type=int, default=len(PERTURBATIONS), choices=range(1, len(PERTURBATIONS) + 1),
                    metavar=f"1..{len(PERTURBATIONS)}",
                    help="moves of F_r that make the round-off floor (default all: +-1, 2, 3, 5, 7, 10 x 1e-15)")
    ap.add_argument("--cold", type=int, default=0, help="measure N cold starts of each version instead")
    ap.add_argument("--scene", choices=sorted(SCENES), default="6208", help="the scene (module docstring)")
    ap.add_argument("--out", default=str(HERE.parent / "out"))
    args = ap.parse_args(argv)
    _bearing, scene, settings = SCENES[args.scene]
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    if args.cold:
        times = cold_starts(args.baseline, out, args.cold)
        (out / "bench_kernel_ab_cold.json").write_text(json.dumps(to_jsonable(
            {"baseline": args.baseline, "runs_wall_cpu_s": times, "date": time.strftime("%Y-%m-%d %H:%M")}), indent=2))
        return
    base = import_baseline(args.baseline, out)
    pkgs = {"baseline": base, "new": eb}
    report = {"baseline": args.baseline, "t_end": args.t_end, "rounds": args.rounds, "scene": scene, "settings": {},
              "machine": dict(cpu_count=os.cpu_count(), python=sys.version.split()[0]),
              "date": time.strftime("%Y-%m-%d %H:%M")}
    what = ("6208, Fr = 3000 N, 500 rad/s, cage + lubrication + tangential history, analytic start" if args.scene == "6208"
            else "7208, Fr = Fa = 3000 N, 500 rad/s, estimated rigid cage (implicit cage damping), lubrication + "
                 "tangential history, analytic start")
    print(f"{what}, T = {args.t_end} s per run; baseline {args.baseline} and this code in one process, {args.rounds} "
          "interleaved rounds (baseline, new, new again as control, rotating order)")
    print(f"{'setting':28s} {'baseline':>9s} {'new':>9s} {'new/base':>9s} {'new/new':>8s}  "
          "(wall s per simulated s: medians; ratios: medians of the per-round ratios)")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for pkg in pkgs.values():
            for kw in settings.values():
                run(pkg, 2e-3, kw, args.scene)  # compile / load the caches
        for label, kw in settings.items():
            def one(name, kw=kw):
                res = run(pkgs["baseline" if name == "baseline" else "new"], args.t_end, kw, args.scene)
                return res.record.wall_s / args.t_end, res

            walls, med, ratio, control, last = interleaved_ab(one, args.rounds)
            with tempfile.TemporaryDirectory() as tmp:
                for name, res in last.items():
                    np.savez(Path(tmp) / f"{name}.npz", **res.record.data)
                arrays = compare(Path(tmp) / "baseline.npz", Path(tmp) / "new.npz")
            sb, sn = last["baseline"].summary(), last["new"].summary()
            rel = {k: _rel(float(sn[k]), float(sb[k])) for k in SUMMARY_KEYS}
            # round-off floor: the baseline again with F_r moved by its last bits (the largest of the moves)
            floor = dict.fromkeys(SUMMARY_KEYS, 0.0)
            for eps in PERTURBATIONS[:args.perturbations]:
                sp = run(base, args.t_end, dict(kw, Fr=scene["Fr"] * (1.0 + eps)), args.scene).summary()
                floor = {k: max(floor[k], _rel(float(sp[k]), float(sb[k]))) for k in SUMMARY_KEYS}
            equal = all(r["equal"] for r in arrays.values())
            report["settings"][label] = dict(kw, walls=walls, median=med, ratio=ratio, control=control,
                                             arrays_equal=equal, arrays=arrays, summary_rel_diff=rel,
                                             roundoff_rel_diff=floor)
            print(f"{label:28s} {med['baseline']:9.3f} {med['new']:9.3f} {ratio:9.3f} {control:8.3f}")
            what = "bitwise equal" if equal else "not bitwise equal"
            beyond = [k for k in SUMMARY_KEYS if rel[k] > floor[k]]
            report["settings"][label]["beyond_roundoff"] = beyond
            print(f"  sampled arrays {what}; summary, relative difference new/baseline (in brackets: the largest "
                  f"difference of the baseline with F_r moved by {_moves(args.perturbations)} against the "
                  "baseline: the round-off floor): "
                  + ", ".join(f"{k} {v:.1e} [{floor[k]:.1e}]" for k, v in rel.items()))
            print("  beyond the round-off floor: " + (", ".join(beyond) if beyond else "none"))
    name = "bench_kernel_ab.json" if args.scene == "6208" else f"bench_kernel_ab_{args.scene.replace('-', '_')}.json"
    (out / name).write_text(json.dumps(to_jsonable(report), indent=2))
    print(f"written {out / name}")


def report_section(run):
    """The report's section on each run of this script (``run.tag``: which): what it printed, introduced."""
    if run.tag == "session":
        return run.printed(
            "Step time against the start of this work",
            "As above, against 58652e8: before the HD film's logarithms and exponential came from per-contact "
            "anchors (series near the anchor, equal to the library functions to round-off: "
            "tests/test_kernel_cache.py) and before the ball / raceway geometry was computed for all contacts "
            "first.",
            last_lines=20)
    if run.tag == "cold":
        return run.printed(
            "Cold start against the start of this work",
            "The README's first run on an empty numba cache (a fresh process with a new NUMBA_CACHE_DIR: import, "
            "then a 2 ms run of the 6208 scene, which compiles the kernels it uses), this code against 58652e8 "
            "(before numba's inlining copied a callee's scope once per block, before one specialisation per "
            "argument type and kernels without the wrappers nothing calls), the two alternately; medians of the "
            "wall and CPU seconds. Per compiled function: `python validation/performance/profile_reference.py --compile`.",
            last_lines=8)
    return run.printed(
        "Step time against the code before the kernel work",
        "The reference engine's step on the two headline settings of bench_reference.py, this code against "
        "e61f1e5 (before the semi-axes from the overlap, ln(xi E') once per evaluation, the divisions off the "
        "dependency chains and the cached film ellipticity factor), both in one "
        "process, interleaved rounds, medians; the new/new control is the noise floor.",
        last_lines=20)


if __name__ == "__main__":
    main()
