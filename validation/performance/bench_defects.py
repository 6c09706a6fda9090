"""Speed of defective-bearing runs, the resolution of their signals, and what
the defect feature costs a scene without defects.

1. The speed target: one simulated second of each defective 6205 case in under 2 s
   (outer race, inner race, ball; 1797 rpm, 1 kN, the spall of
   ``datasets.fault_defects``) in the reference engine at dt = 1/(4 x 48 kHz)
   = 5.2 us with the 48 kHz signals, wall time of the integration, median of
   ``--repeat`` runs.
2. Resolution: the same cases at half the step (0.5 s simulated): relative
   change of the envelope line at the defect frequency and of the rms of
   the housing force's variation.
3. No-defect cost against ``--baseline`` (default: the last commit before the
   defect feature, exported with ``git archive``; or a folder holding a
   checkout):
   the 6208 scene (F_r = 3000 N, 500 rad/s, dt = 5 us, explicit spring,
   T = 0.5 s) run by this package and by the baseline's (imported in the
   same process under another name), in ``--pairs`` rounds of three runs
   (baseline, new, and new again as a control, in rotating order):
   medians, minima, the median of the per-round ratios new/baseline and, as
   the noise floor, of new/new; and every sampled array of the two
   compared (the new diagnostic column aside).

Usage::

    python validation/performance/bench_defects.py [--repeat 3] [--baseline REV|DIR|none] [--pairs 15] [--out validation/out]

Writes ``bench_defects.json`` into the output folder.
"""
from __future__ import annotations

import argparse
import dataclasses
import json
import os
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.datasets import signal_scenario
from exudyn_bearing.outputs.jsonio import to_jsonable
from exudyn_bearing.outputs.signals import FAULT_FREQUENCY, envelope_signature

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
FAULTS = ("outer", "inner", "ball")

#: Last commit before the defect feature (main at the time it branched off).
BASELINE_REV = "6ba181c"
#: Name under which the baseline package is imported beside this one.
BASELINE_NAME = "exudyn_bearing_baseline"


def baseline_source(spec, out):
    """Folder holding the baseline's ``exudyn_bearing``: ``spec`` itself if it
    is a folder, else a git revision of this repository exported with
    ``git archive`` into ``out/baseline_src/<rev>`` (the work tree is not
    touched)."""
    import io
    import tarfile

    if Path(spec).is_dir():
        return Path(spec).resolve()
    dst = Path(out) / "baseline_src" / spec
    if not (dst / "exudyn_bearing" / "__init__.py").exists():
        tar = subprocess.run(["git", "-C", str(REPO), "archive", spec, "exudyn_bearing"], capture_output=True,
                             check=True).stdout
        dst.mkdir(parents=True, exist_ok=True)
        with tarfile.open(fileobj=io.BytesIO(tar)) as tf:
            tf.extractall(dst, filter="data")
    return dst


def import_baseline(checkout, out):
    """The package of a baseline checkout, copied to ``out/baseline_pkg`` as
    ``exudyn_bearing_baseline`` (its imports are relative) and imported in
    this process, so that both versions run interleaved in one process. Its
    numba cache lives beside the copy (compiled once, on the first run)."""
    import importlib
    import shutil

    src = baseline_source(checkout, out) / "exudyn_bearing"
    if not (src / "__init__.py").exists():
        raise SystemExit(f"--baseline: {checkout} holds no exudyn_bearing package")
    dst_root = Path(out) / "baseline_pkg"
    dst = dst_root / BASELINE_NAME
    stamp = dst_root / "source.txt"
    if not (dst.exists() and stamp.exists() and stamp.read_text() == str(src)):
        shutil.rmtree(dst_root, ignore_errors=True)
        shutil.copytree(src, dst, ignore=shutil.ignore_patterns("__pycache__"))
        stamp.write_text(str(src))
    sys.path.insert(0, str(dst_root))
    return importlib.import_module(BASELINE_NAME)


def run_case(fault, t_end, steps_per_sample=4):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.StepSizeWarning)
        return eb.simulate("6205", signal_scenario(fault, 1797.0, 1000.0, t_end=t_end,
                                                   steps_per_sample=steps_per_sample))


def scene_6208(pkg, t_end):
    kw = dict(Fr=3000.0, omega=500.0, t_end=t_end, dt=5e-6, sample_dt=1e-3)
    if "ring_growth" in {f.name for f in dataclasses.fields(pkg.Scenario)}:
        kw["ring_growth"] = False  # the same scene as the baseline's, which has no ring growth
    return pkg.Scenario(**kw)


def compare(old_npz, new_npz):
    with np.load(old_npz) as a, np.load(new_npz) as b:
        rows = {}
        for k in a.files:
            x, y = a[k], b[k]
            if k in ("diag", "glob"):
                # fields added since (diag: defect_drop, rolling_resistance; glob: the rolling-resistance and
                # drag powers) are appended last: compare the baseline's columns
                y = y[..., :x.shape[-1]]
            same_shape = x.shape == y.shape
            rows[k] = {"equal": bool(same_shape and np.array_equal(x, y, equal_nan=True)),
                       "max_abs_diff": float(np.nanmax(np.abs(x - y))) if same_shape else None}
        return rows


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--baseline", default=BASELINE_REV,
                    help="code before the defect feature for the no-defect comparison: a folder holding "
                         f"exudyn_bearing or a git revision of this repository (default {BASELINE_REV}); "
                         "'none' skips the comparison")
    ap.add_argument("--pairs", type=int, default=15, help="rounds of baseline / new / new (control) runs")
    ap.add_argument("--t-end-6208", type=float, default=0.5)
    ap.add_argument("--skip", nargs="*", default=[], choices=("speed", "resolution"),
                    help="parts to leave out (their entries stay out of the JSON)")
    ap.add_argument("--out", default=str(HERE.parent / "out"))
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    report = {"machine": dict(cpu_count=os.cpu_count(), python=sys.version.split()[0]),
              "date": time.strftime("%Y-%m-%d %H:%M")}
    run_case("outer", 1e-3)  # compile / load the cache
    # 1. speed at 5.2 us, one simulated second
    speed = {}
    if "speed" not in args.skip:
        print("6205, 1797 rpm, Fr = 1000 N, dt = 5.21 us, signals at 48 kHz, T = 1 s, reference engine, "
              f"median of {args.repeat}")
    for fault in (FAULTS if "speed" not in args.skip else ()):
        walls = [run_case(fault, 1.0).wall_s for _ in range(args.repeat)]
        speed[fault] = {"walls": walls, "median_wall_per_sim_s": float(np.median(walls))}
        print(f"  {fault:6s} wall per simulated second: {np.median(walls):.3f} s (runs {', '.join(f'{w:.3f}' for w in walls)})")
    if speed:
        report["speed"] = speed
    # 2. resolution: half the step
    res = {}
    if "resolution" not in args.skip:
        print("resolution: dt = 5.21 us against 2.60 us, T = 0.5 s (envelope line at the defect frequency, rms of F_x)")
    for fault in (FAULTS if "resolution" not in args.skip else ()):
        rows = {}
        for k in (4, 8):
            r = run_case(fault, 0.5, steps_per_sample=k)
            sig = envelope_signature(r, "outer_fx")
            x = r.signal("outer_fx")[r.signal_t > 0.1]
            rows[k] = {"line_Hz": sig["line"][0], "defect_Hz": sig["freqs"][FAULT_FREQUENCY[fault]],
                       "defect_amplitude": sig["at"][FAULT_FREQUENCY[fault]],
                       "rms_N": float(np.std(x)), "wall_s": r.wall_s}
        rel_line = rows[4]["defect_amplitude"] / rows[8]["defect_amplitude"] - 1.0
        rel_rms = rows[4]["rms_N"] / rows[8]["rms_N"] - 1.0
        res[fault] = {"dt_5.21us": rows[4], "dt_2.60us": rows[8], "rel_change_line": rel_line,
                      "rel_change_rms": rel_rms}
        print(f"  {fault:6s} line {rows[4]['line_Hz']:.2f} / {rows[8]['line_Hz']:.2f} Hz, amplitude "
              f"{rows[4]['defect_amplitude']:.3g} / {rows[8]['defect_amplitude']:.3g} N ({100 * rel_line:+.1f} %), "
              f"rms {rows[4]['rms_N']:.3g} / {rows[8]['rms_N']:.3g} N ({100 * rel_rms:+.1f} %)")
    if res:
        report["resolution"] = res
    # 3. no-defect cost against the baseline, both versions in this process, runs alternating
    if args.baseline and args.baseline != "none":
        base = import_baseline(args.baseline, out)
        pkgs = {"baseline": base, "new": eb}
        last = {}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            for pkg in pkgs.values():
                pkg.simulate("6208", scene_6208(pkg, 1e-3))  # compile / load the caches
            # each round runs the baseline, the new code and the new code again (the control: the
            # spread of its ratio to the first new run is the noise floor), in rotating order
            walls = {"baseline": [], "new": [], "control": []}
            names = ("baseline", "new", "control")
            for i in range(args.pairs):
                for name in names[i % 3:] + names[:i % 3]:
                    pkg = pkgs["baseline" if name == "baseline" else "new"]
                    r = pkg.simulate("6208", scene_6208(pkg, args.t_end_6208))
                    walls[name].append(r.wall_s)
                    if name != "control":
                        last[name] = r.data
        with tempfile.TemporaryDirectory() as tmp:
            for name, data in last.items():
                np.savez(Path(tmp) / f"{name}.npz", **data)
            cmp = compare(Path(tmp) / "baseline.npz", Path(tmp) / "new.npz")
        med = {k: float(np.median(v)) for k, v in walls.items()}
        ratio = float(np.median(np.array(walls["new"]) / np.array(walls["baseline"])))
        control = float(np.median(np.array(walls["control"]) / np.array(walls["new"])))
        report["no_defect"] = {"scene": "6208, Fr 3000 N, 500 rad/s, dt 5 us, explicit spring, cage, lubrication",
                               "t_end": args.t_end_6208, "walls": walls, "median_wall_s": med,
                               "min_wall_s": {k: float(np.min(v)) for k, v in walls.items()},
                               "median_pair_ratio": ratio, "median_control_ratio": control, "arrays": cmp,
                               "all_equal": all(r["equal"] for r in cmp.values()), "baseline": args.baseline}
        print(f"no defects, 6208 scene, T = {args.t_end_6208} s, {args.pairs} rounds in one process: median wall "
              f"baseline {med['baseline']:.4f} s, new {med['new']:.4f} s; median of the per-round ratios "
              f"new/baseline {ratio:.3f}, control new/new {control:.3f} (noise floor); minima "
              f"{min(walls['baseline']):.4f} / {min(walls['new']):.4f} s")
        def verdict(r):
            if r["equal"]:
                return "yes"
            if r["max_abs_diff"] is None:  # e.g. the global diagnostics gained the energy columns
                return "no (other shape)"
            return "no (max diff %.3g)" % r["max_abs_diff"]

        print("  arrays bitwise equal: " + ", ".join(f"{k} {verdict(r)}" for k, r in cmp.items()))
    (out / "bench_defects.json").write_text(json.dumps(to_jsonable(report), indent=2))
    print(f"written {out / 'bench_defects.json'}")


def report_section(run):
    """The report's section on localized defects, from bench_defects.json."""
    d = run.load("bench_defects.json")
    lines = ["## Localized defects and vibration signals", "",
             f"Command: `{run.command}` (engine: reference core; 6205 at 1797 rpm, F_r = 1000 N, "
             "1 x 1.5 x 0.1 mm spall of `datasets.fault_defects`, dt = 1/(4 x 48 kHz) = 5.21 us, implicit tangential "
             "spring, housing force and inner-ring acceleration at 48 kHz).", ""]
    if "speed" in d:
        lines += ["| defect | wall per simulated second (median) | runs |", "|---|---|---|"]
        for k, v in d["speed"].items():
            lines.append(f"| {k} | {v['median_wall_per_sim_s']:.3f} s | {', '.join(f'{w:.3f}' for w in v['walls'])} |")
        lines.append("")
    if "resolution" in d:
        lines += ["Resolution: the same cases over 0.5 s at 5.21 us and at half that step; the strongest envelope "
                  "line of the housing force (band chosen by energy, first 0.1 s left out) and its amplitude at the "
                  "defect frequency:", "",
                  "| defect | defect frequency | line at 5.21 us / 2.60 us | amplitude change | rms change |",
                  "|---|---|---|---|---|"]
        for k, v in d["resolution"].items():
            a, b = v["dt_5.21us"], v["dt_2.60us"]
            lines.append(f"| {k} | {a['defect_Hz']:.2f} Hz | {a['line_Hz']:.2f} / {b['line_Hz']:.2f} Hz | "
                         f"{100 * v['rel_change_line']:+.1f} % | {100 * v['rel_change_rms']:+.1f} % |")
        lines.append("")
    if "no_defect" in d:
        n = d["no_defect"]
        shape = [k for k, v in n["arrays"].items() if not v["equal"] and v["max_abs_diff"] is None]
        differ = {k: v["max_abs_diff"] for k, v in n["arrays"].items()
                  if not v["equal"] and v["max_abs_diff"] is not None}
        if not differ:
            eq = "bitwise equal"
        elif max(differ.values()) <= 1e-12:
            eq = ("bitwise equal except " + ", ".join(f"{k} (largest difference {d:.3g}, round-off of the code "
                                                      f"changed since)" for k, d in differ.items()))
        else:
            eq = ("not bitwise equal: " + ", ".join(f"{k} (max diff {d:.3g})" for k, d in differ.items())
                  + "; the compiled arithmetic changed since (energy bookkeeping, which functions the kernel "
                  "inlines), and this 0.5 s run is chaotic: last-bit differences grow as under the 1e-15 "
                  "perturbations of the round-off section")
        if shape:
            eq += (" (" + ", ".join(shape) + ": other shape, the global diagnostics gained the energy columns "
                   "since; not compared)")
        lines += [f"No defects: the 6208 scene ({n['scene']}, T = {n['t_end']} s) run by this code and by the code "
                  f"before the defect feature ({n['baseline']}), both in one process in rotating order: median wall "
                  f"{n['median_wall_s']['baseline']:.3f} s (before) and {n['median_wall_s']['new']:.3f} s (now), median "
                  f"per-round ratio {n['median_pair_ratio']:.3f}, against {n['median_control_ratio']:.3f} for the new "
                  f"code against itself (the noise floor); every sampled array {eq}.", ""]
    return "\n".join(lines)


if __name__ == "__main__":
    main()
