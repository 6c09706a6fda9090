"""Speed of the thermal quasi-static solve (solve_thermal: bearing and thermal network together).

    python validation/performance/bench_thermal.py [--repeat 5]

Targets (wall time on this machine): one thermal solution of the ACBB-120 (22 240 N thrust,
25 000 rpm, MIL-L-23699 in at 394 K, 6e-5 m^3/s) under 1 s; a thermal sweep over 20 speeds
(2 500-25 000 rpm, each started from the previous speed's solution) under 20 s; the single solution
again with an assumed outer-land-guided cage (the network's fifth node; the catalogue's ACBB-120 is
cageless, pocket clearance 0.25 mm assumed). Prints medians
of ``--repeat`` runs after one warm-up run (numba compilation and cache loading excluded) and
writes validation/out/bench_thermal.json. docs/theory/thermal.md.
"""
import argparse
import json
import math
from pathlib import Path

import numpy as np

import exudyn_bearing as eb

from _bench import median_wall  # validation/performance/_bench.py (the script's folder is on sys.path)

OUT = Path(__file__).resolve().parents[1] / "out"
CASE = {"Fa": 22240.0, "oil_inlet_temperature": 394.0, "oil_flow": 6e-5}
RPM = np.linspace(2500.0, 25000.0, 20)
#: An assumed cage for the ACBB-120 (the catalogue entry has none): outer-land guided, 0.25 mm pocket clearance.
CAGE = {"cage_guidance": "outer_land", "cage_pocket_clearance": 2.5e-4}


def one(rpm=25000.0, **cage):
    return eb.solve_thermal("ACBB-120", omega=rpm * math.pi / 30.0, **CASE, **cage)


def sweep():
    prev, out = None, []
    for rpm in RPM:
        prev = eb.solve_thermal("ACBB-120", omega=rpm * math.pi / 30.0, start=prev, **CASE)
        out.append(prev)
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args(argv)
    r = one()  # warm-up: compilation / cache
    sweep()
    t_one, walls_one = median_wall(one, args.repeat)
    t_low, _ = median_wall(lambda: one(5000.0), args.repeat)
    rc = one(**CAGE)
    t_cage, _ = median_wall(lambda: one(**CAGE), args.repeat)
    t_sweep, walls_sweep = median_wall(sweep, max(1, args.repeat // 2))
    its = [s.iterations for s in sweep()]
    print(f"thermal solution ACBB-120, 25000 rpm: median {t_one:.3f} s ({r.iterations} iterations; target < 1 s)")
    print(f"thermal solution ACBB-120,  5000 rpm: median {t_low:.3f} s")
    print(f"thermal solution ACBB-120, 25000 rpm, assumed outer-land cage (5 nodes): median {t_cage:.3f} s "
          f"({rc.iterations} iterations; target < 1 s)")
    print(f"thermal sweep, 20 speeds 2500-25000 rpm (warm started): median {t_sweep:.2f} s "
          f"(iterations per speed {min(its)}-{max(its)}; target < 20 s)")
    OUT.mkdir(exist_ok=True)
    res = {"one_25000rpm_s": t_one, "one_5000rpm_s": t_low, "one_25000rpm_cage_s": t_cage, "sweep_20_speeds_s": t_sweep,
           "walls_one": walls_one, "walls_sweep": walls_sweep, "iterations_sweep": its}
    (OUT / "bench_thermal.json").write_text(json.dumps(res, indent=2))
    return res


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced."""
    return run.printed(
        "Speed of the thermal solution",
        "One thermal quasi-static solution and a warm-started 20-speed sweep (medians).",
        last_lines=5)


if __name__ == "__main__":
    main()
