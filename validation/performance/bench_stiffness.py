"""Speed of the linearised bearing coefficients (targets: a matrix in 0.2 s, a 20-speed table in 5 s; medians measured in one run).

    python validation/performance/bench_stiffness.py

Targets (wall time on this machine): one stiffness and damping matrix under 0.2 s, a 20-speed
coefficient table under 5 s. Cases: the 6208 at F_r = 3000 N and 500 rad/s (one matrix: the full
quasi-static solution with its 5x5 stiffness and damping, as the ``stiffness`` command computes it),
the 7208 at F_r = 1000 N, F_a = 3000 N (free tilts), and 20-speed tables 0 ... 2000 rad/s of the 6208
(one ball-set position, and averaged over three) and of the ACBB-120 (22,240 N thrust, 2,500 ...
30,000 rpm, race control), each also as 20 cold solves for the effect of the warm start. Writes validation/out/bench_stiffness.json.
"""
import json
import math
from pathlib import Path

import numpy as np

from exudyn_bearing.solvers.quasistatic import bearing_coefficients, solve_quasistatic

from _bench import median_wall, speed_table  # validation/performance/_bench.py (the script's folder is on sys.path)

OUT = Path(__file__).resolve().parents[1] / "out"
TARGETS = {"matrix_6208_s": 0.2, "matrix_7208_s": 0.2, "table20_6208_s": 5.0, "table20_6208_3phases_s": 5.0,
           "table20_acbb120_s": 5.0}


def main():
    OUT.mkdir(exist_ok=True)
    # warm-up: numba kernels from the disk cache, first scipy calls
    solve_quasistatic("6208", 3000.0, omega=500.0)
    solve_quasistatic("ACBB-120", 0.0, 22240.0, omega=2618.0)
    speeds = np.linspace(0.0, 2000.0, 20)
    acbb_speeds = np.linspace(2500.0, 30000.0, 20) * math.pi / 30.0
    cases = {
        "matrix_6208_s": (lambda: solve_quasistatic("6208", 3000.0, omega=500.0), 9),
        "matrix_7208_s": (lambda: solve_quasistatic("7208", 1000.0, 3000.0, omega=500.0), 9),
        "table20_6208_s": (lambda: bearing_coefficients("6208", speeds, Fr=3000.0), 5),
        "table20_6208_cold_s": (lambda: [solve_quasistatic("6208", 3000.0, omega=w) for w in speeds], 5),
        "table20_6208_3phases_s": (lambda: bearing_coefficients("6208", speeds, Fr=3000.0, n_phases=3), 3),
        "table20_acbb120_s": (lambda: bearing_coefficients("ACBB-120", acbb_speeds, Fa=22240.0), 3),
        "table20_acbb120_cold_s": (lambda: [solve_quasistatic("ACBB-120", 0.0, 22240.0, omega=w)
                                            for w in acbb_speeds], 3),
    }
    out = {"targets_s": TARGETS, "walls": {}}
    for name, (fn, repeat) in cases.items():
        med, walls = median_wall(fn, repeat)
        out[name] = med
        out["walls"][name] = walls
        target = f"target {1e3 * TARGETS[name]:.0f} ms" if name in TARGETS else "no target: 20 cold solves"
        print(f"{name[:-2]:>24}: median {1e3 * med:8.1f} ms over {repeat} ({target})")
    out["all_within_targets"] = all(out[k] < t for k, t in TARGETS.items())
    (OUT / "bench_stiffness.json").write_text(json.dumps(out, indent=1))
    print(f"all within targets: {out['all_within_targets']}; written {OUT / 'bench_stiffness.json'}")


def report_section(run):
    """The speed table that ends the report's stiffness section, from bench_stiffness.json."""
    return "\n".join(speed_table(run, "bench_stiffness.json") + [""])


if __name__ == "__main__":
    main()
