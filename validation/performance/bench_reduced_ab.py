"""Reduced-engine wall time of this code against a baseline version, runs interleaved in one process.

The cases of validation/consistency/reduced_engine.py (the 6208 radial, the ACBB-120 at 25,000 rpm, the 6208
radial with its rigid cage; traction over the ellipse) at the reduced engine's steps, shortened to ``--t-end``
where given. The baseline package (``--baseline``: a git revision of this repository, exported with ``git
archive``, or a folder holding a checkout) is imported beside this one under another name
(``bench_defects.import_baseline``); in each of ``--rounds`` rounds every case runs the baseline, the new code
and the new code again (the control: its ratio to the first new run is the noise floor) in rotating order
(``_bench.interleaved_ab``), so that the load of a shared host drifts over all three alike. Printed per case:
the medians of the wall seconds per simulated second (``RunRecord.wall_s``, compilation excluded), the median
of the per-round ratios new/baseline and new/new, and the force evaluations per step of both (counted, exact).

    python validation/performance/bench_reduced_ab.py [--baseline 7a33c62] [--rounds 5]
"""
from __future__ import annotations

import argparse
import sys
import warnings
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "consistency"))

import exudyn_bearing as eb  # noqa: E402

from _bench import interleaved_ab  # noqa: E402  (validation/performance/ is on sys.path)
from bench_defects import import_baseline  # noqa: E402
from reduced_engine import CASES, COMMON  # noqa: E402

#: The code before the changes to the reduced engine's cost (Jacobians' age, the balance's iterations).
BASELINE_REV = "7a33c62"
#: (label, case name in reduced_engine.CASES, step [s], simulated time [s] or None for the case's)
RUNS = [("6208 radial, 20 us", "6208 radial (Fr 3000 N, 500 rad/s)", 2e-5, None),
        ("6208 radial, 100 us", "6208 radial (Fr 3000 N, 500 rad/s)", 1e-4, None),
        ("ACBB-120, 100 us", "ACBB-120 thrust (Fa 22240 N, 25000 rpm)", 1e-4, None),
        ("6208 rigid cage, 20 us, 0.1 s", "6208 radial, rigid cage (Fr 3000 N, 500 rad/s)", 2e-5, 0.1)]


def run(pkg, name, dt, t_end):
    bearing, fields, t_case, _ = CASES[name]
    sc = pkg.Scenario(**{**COMMON, **fields}, t_end=t_end or t_case, dt=dt)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return pkg.simulate(bearing, sc, engine="reduced")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--baseline", default=BASELINE_REV, help="a git revision of this repository or a folder")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--out", default=str(HERE.parent / "out"))
    args = ap.parse_args(argv)
    Path(args.out).mkdir(parents=True, exist_ok=True)
    base = import_baseline(args.baseline, args.out)
    pkgs = {"baseline": base, "new": eb}
    print(f"reduced engine: baseline {args.baseline} and this code in one process, {args.rounds} interleaved rounds "
          "(baseline, new, new again as control, rotating order)")
    print(f"{'case':32s} {'baseline':>9s} {'new':>9s} {'new/base':>9s} {'new/new':>8s} {'evaluations/step':>17s}  "
          "(wall s per simulated s: medians; ratios: medians of the per-round ratios)")
    for pkg in pkgs.values():  # compile / load the caches
        for _, name, dt, _t in RUNS:
            run(pkg, name, dt, 1e-3)
    for label, name, dt, t_end in RUNS:
        def one(which, name=name, dt=dt, t_end=t_end):
            res = run(pkgs["baseline" if which == "baseline" else "new"], name, dt, t_end)
            return res.record.wall_s / float(res.t[-1]), res

        _walls, med, ratio, control, last = interleaved_ab(one, args.rounds)
        ev = [last[k].record.reduced_stats["evaluations_per_step"] for k in ("baseline", "new")]
        print(f"{label:32s} {med['baseline']:9.3f} {med['new']:9.3f} {ratio:9.3f} {control:8.3f} "
              f"{ev[0]:8.2f} -> {ev[1]:.2f}", flush=True)


if __name__ == "__main__":
    raise SystemExit(main())
