"""Speed of the quasi-static solver and of the compiled contact-slip integration (medians, one run).

    python validation/performance/bench_quasistatic.py

Targets (wall time on this machine): the full ACBB-120 solution with minimum energy
under 0.5 s, a sweep over 20 speeds under 5 s, a 6208 radial case under 50 ms. Also the cost of one
call of ``physics.contact_slip._contact_traction`` (what the dynamics engines would call per contact
and step) for several strip counts and traction models, timed inside a compiled loop. Writes
validation/out/bench_quasistatic.json.
"""
import json
import math
from pathlib import Path

import numpy as np

from exudyn_bearing._jit import kernel
from exudyn_bearing.data import traction_models
from exudyn_bearing.physics.contact_slip import _contact_traction
from exudyn_bearing.solvers.quasistatic import solve_quasistatic

from _bench import median_wall, speed_table  # validation/performance/_bench.py (the script's folder is on sys.path)

OUT = Path(__file__).resolve().parents[1] / "out"
W = 25000 * math.pi / 30
ACBB = dict(traction="ester_curve_illustrative", lubricant="MIL-L-23699_492K")


@kernel(no_runtime=True)  # as the DEM contact kernel is compiled
def _loop(n, a, b, load, u, code, params, n_strips, n_across):
    acc = 0.0
    for i in range(n):
        v0 = 0.01 * (i % 7 - 3)
        fx, fy, mz, p, qv, my = _contact_traction(a, b, load, v0, 40.0 + (i % 5), 300.0, 6.4e-3, 0.0, u, 2e-7,
                                                  1.5e-7, code, params, n_strips, n_across)
        acc += p
    return acc


def kernel_cost():
    res = {}
    n = 200_000
    for name in ("coulomb_0.1", "ester_curve_illustrative", "ehl_mil_l_23699_492K"):
        m = traction_models[name]
        for ns, na in ((8, 1), (16, 1), (32, 1), (16, 2), (32, 4)):
            _loop(10, 2e-3, 3e-4, 3000.0, 20.0, m.code, m.vector, ns, na)  # compile / warm
            wall, _ = median_wall(lambda: _loop(n, 2e-3, 3e-4, 3000.0, 20.0, m.code, m.vector, ns, na), 5)
            res[f"{name}|{ns}x{na}"] = 1e9 * wall / n
            print(f"contact_traction {name:26s} {ns:3d} strips x {na} across: {1e9 * wall / n:7.1f} ns per call")
    return res


def main():
    OUT.mkdir(exist_ok=True)
    # warm-up (numba compilation from the disk cache, first scipy calls)
    solve_quasistatic("ACBB-120", 0.0, 22240.0, omega=W, control="min-energy", **ACBB)
    solve_quasistatic("6208", 3000.0, omega=500.0)
    out = {}
    out["acbb120_min_energy_s"], w1 = median_wall(
        lambda: solve_quasistatic("ACBB-120", 0.0, 22240.0, omega=W, control="min-energy", **ACBB), 5)
    out["acbb120_race_control_s"], _ = median_wall(
        lambda: solve_quasistatic("ACBB-120", 0.0, 22240.0, omega=W, control="auto", **ACBB), 5)
    speeds = np.linspace(2500, 30000, 20) * math.pi / 30
    out["sweep20_min_energy_s"], _ = median_wall(
        lambda: [solve_quasistatic("ACBB-120", 0.0, 22240.0, omega=w, control="min-energy", **ACBB) for w in speeds],
        3)
    out["sweep20_race_control_s"], _ = median_wall(
        lambda: [solve_quasistatic("ACBB-120", 0.0, 22240.0, omega=w, control="auto", **ACBB) for w in speeds], 3)
    out["6208_radial_s"], _ = median_wall(lambda: solve_quasistatic("6208", 3000.0, omega=500.0), 7)
    out["6208_radial_min_energy_s"], _ = median_wall(
        lambda: solve_quasistatic("6208", 3000.0, omega=500.0, control="min-energy"), 3)
    out["6208_combined_free_tilt_s"], _ = median_wall(lambda: solve_quasistatic("6208", 3000.0, 1000.0, omega=500.0),
                                                      7)
    targets = {"acbb120_min_energy_s": 0.5, "sweep20_min_energy_s": 5.0, "6208_radial_s": 0.05}
    for k, v in out.items():
        t = targets.get(k)
        print(f"{k:28s} {v * 1e3:9.1f} ms" + (f"   target {t * 1e3:.0f} ms: {'met' if v < t else 'MISSED'}" if t else ""))
    out["targets_s"] = targets
    out["kernel_ns_per_call"] = kernel_cost()
    (OUT / "bench_quasistatic.json").write_text(json.dumps(out, indent=2))
    print(f"wrote {OUT / 'bench_quasistatic.json'}")


def report_section(run):
    """The speed tables that end the report's quasi-static ACBB-120 section, from bench_quasistatic.json."""
    lines = speed_table(run, "bench_quasistatic.json")
    bq = run.load("bench_quasistatic.json")
    lines += ["", "Compiled contact-slip integration (`physics.contact_slip._contact_traction`, one call, "
              "timed in a compiled loop):", "", "| traction model | strips x points across | ns per call |",
              "|---|---|---|"]
    for k, v in bq["kernel_ns_per_call"].items():
        name, grid = k.split("|")
        lines.append(f"| {name} | {grid} | {v:.0f} |")
    return "\n".join(lines + [""])


if __name__ == "__main__":
    main()
