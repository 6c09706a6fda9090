"""Step time of the Exudyn bearing element (body mode) of this code against a baseline version, runs interleaved.

Scene: 6208, F_r = 3000 N, 500 rad/s, cage, lubrication, Cundall-Strack
history, analytic start (``bench_element.py``'s), the element's body mode
built by ``ExudynEngine``: VelocityVerlet at 5 us and RK44 (regularized
friction) at 2 us. The baseline package (``--baseline``: a git revision of
this repository or a folder holding a checkout) is imported beside this one
(``bench_defects.import_baseline``); in each of ``--rounds`` rounds every
setting runs the baseline, the new code and the new code again (the
control, whose ratio to the first new run is the noise floor), in rotating
order. Printed per setting: medians of the wall seconds per simulated second
of the solve (``RunRecord.wall_s``), the medians of the per-round ratios
new/baseline and new/new, and whether the sampled arrays of the last
baseline and new runs are bitwise equal.

    python validation/performance/bench_element_ab.py [--baseline b8c12a7] [--rounds 7] [--t-end 0.02] [--mode bodies]

Writes ``bench_element_ab.json`` into the output folder.
"""
from __future__ import annotations

import argparse
import importlib
import json
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.outputs.jsonio import to_jsonable

from _bench import interleaved_ab  # validation/ (the script's folder is on sys.path)
from bench_defects import compare, import_baseline  # validation/ (the script's folder is on sys.path)

HERE = Path(__file__).resolve().parent
#: main before the body mode's two-object layout (validation/performance/profile_element.py)
BASELINE_REV = "b8c12a7"
SCENE = dict(Fr=3000.0, omega=500.0, cage=True, lubrication=True, friction="history", initial="analytic")
SETTINGS = {"VelocityVerlet, dt 5 us": {"dt": 5e-6},
            "RK44, regularized friction, dt 2 us": {"dt": 2e-6, "friction": "regularized", "integrator": "rk4"}}


def run(pkg, t_end, kw, mode):
    sc = pkg.Scenario(t_end=t_end, sample_dt=1e-3, **dict(SCENE, **kw))
    engine = importlib.import_module(pkg.__name__ + ".solvers.element.engine").ExudynEngine
    return engine("6208", sc, mode=mode).run()


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--baseline", default=BASELINE_REV)
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--t-end", type=float, default=0.02, help="simulated time per run [s]")
    ap.add_argument("--mode", default="bodies", choices=("bodies", "fast"))
    ap.add_argument("--settings", nargs="*", default=list(SETTINGS), choices=list(SETTINGS))
    ap.add_argument("--out", default=str(HERE.parent / "out"))
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    pkgs = {"baseline": import_baseline(args.baseline, out), "new": eb}
    report = {"baseline": args.baseline, "t_end": args.t_end, "rounds": args.rounds, "mode": args.mode,
              "settings": {}, "date": time.strftime("%Y-%m-%d %H:%M")}
    print(f"6208, Fr = 3000 N, 500 rad/s, element {args.mode} mode, T = {args.t_end} s per run; baseline "
          f"{args.baseline} and this code in one process, {args.rounds} interleaved rounds")
    print(f"{'setting':38s} {'baseline':>9s} {'new':>9s} {'new/base':>9s} {'new/new':>8s}  "
          "(wall s per simulated s: medians; ratios: medians of the per-round ratios)")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for pkg in pkgs.values():
            for label in args.settings:
                run(pkg, 1e-3, SETTINGS[label], args.mode)  # compile / load the caches
        for label in args.settings:
            kw = SETTINGS[label]
            def one(name, kw=kw):
                rec = run(pkgs["baseline" if name == "baseline" else "new"], args.t_end, kw, args.mode)
                return rec.wall_s / args.t_end, rec

            walls, med, ratio, control, last = interleaved_ab(one, args.rounds)
            with tempfile.TemporaryDirectory() as tmp:
                for name, rec in last.items():
                    np.savez(Path(tmp) / f"{name}.npz", **rec.data)
                arrays = compare(Path(tmp) / "baseline.npz", Path(tmp) / "new.npz")
            equal = all(r["equal"] for r in arrays.values())
            report["settings"][label] = dict(kw, walls=walls, median=med, ratio=ratio, control=control,
                                             arrays_equal=equal, arrays=arrays)
            print(f"{label:38s} {med['baseline']:9.3f} {med['new']:9.3f} {ratio:9.3f} {control:8.3f}  sampled "
                  f"arrays {'bitwise equal' if equal else 'NOT bitwise equal'}", flush=True)
    (out / "bench_element_ab.json").write_text(json.dumps(to_jsonable(report), indent=2))
    print(f"written {out / 'bench_element_ab.json'}")


def report_section(run):
    """The report's section on each run of this script (``run.tag``: which): what it printed, introduced."""
    if run.tag == "session":
        return run.printed(
            "Element step against the start of this work",
            "The element's body and fast modes against 58652e8: before one compiled call on one structure of the "
            "element's arrays, views of Exudyn's coordinate vectors instead of copies, the element's kernels "
            "without numba's memory runtime and the scene's contact-kernel paths only; interleaved rounds, "
            "medians; sampled arrays compared bit for bit.",
            last_lines=20)
    if run.tag == "session_fast":
        return run.printed(
            "Element fast mode against the start of this work",
            "As above, the fast mode (one sub-step per Exudyn step).",
            last_lines=20)
    return run.printed(
        "Element body mode against the one-object layout",
        "The body mode of this code against b8c12a7 (one ObjectGenericODE2 holding all balls), both in one "
        "process, interleaved rounds, medians; new/new is the noise floor; the sampled arrays compared bit "
        "for bit (equal on the branch that changed the layout; not since the contact kernel's divisions were "
        "reordered, whose summary differences bench_kernel_ab.py shows within the round-off floor).",
        last_lines=15)


if __name__ == "__main__":
    main()
