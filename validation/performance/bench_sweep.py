"""Speed-up of the sweep runner with 1 and 2 local worker processes (one run each).

Eight cases of the load sweep (6208, 500 rad/s, T = 0.1 s, dt = 5 us),
each run once with 1 worker and once with 2 workers into fresh folders.

    python validation/performance/bench_sweep.py
"""
import json
import tempfile
import time
from pathlib import Path

import numpy as np

from exudyn_bearing.sweep import run_sweep


def main():
    cases = {f"Fr{fr:.0f}": dict(bearing="6208", scenario=dict(Fr=float(fr), omega=500.0, t_end=0.1, dt=5e-6,
                                                              tangential="implicit", sample_dt=1e-3))
             for fr in np.geomspace(750, 7500, 8)}
    run_sweep({"warm": cases["Fr750"]}, tempfile.mkdtemp(), workers=1, progress=False)  # compile
    walls = {}
    for w in (1, 2):
        t0 = time.perf_counter()
        run_sweep(cases, tempfile.mkdtemp(), workers=w, progress=False)
        walls[w] = time.perf_counter() - t0
        print(f"{w} worker(s): {walls[w]:.2f} s for {len(cases)} cases")
    print(f"speed-up 2 workers / 1 worker: {walls[1] / walls[2]:.2f}")
    out = Path(__file__).resolve().parents[1] / "out"
    out.mkdir(exist_ok=True)
    (out / "bench_sweep.json").write_text(json.dumps({"walls": walls, "speedup": walls[1] / walls[2],
                                                      "cases": len(cases)}, indent=2))


def report_section(run):
    """The report's section on the sweep runner, from bench_sweep.json."""
    d = run.load("bench_sweep.json")
    return "\n".join(["## Sweep runner", "",
                      f"Command: `{run.command}`: {d['cases']} cases (T = 0.1 s each) took "
                      f"{d['walls']['1']:.2f} s with one worker and {d['walls']['2']:.2f} s with two: speed-up "
                      f"**{d['speedup']:.2f}** on the 2-core machine. Cases are written atomically, so an interrupted "
                      "sweep resumes (tests/test_sweep.py); a case whose spec changed runs again, a failing case is "
                      "recorded with its error while the others finish; `scheduler=` sends them to a Dask cluster.", ""])


if __name__ == "__main__":
    main()
