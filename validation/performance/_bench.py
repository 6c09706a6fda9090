"""Timing helpers shared by the benchmark scripts of this folder, and their report table."""
from __future__ import annotations

import time

import numpy as np


def median_wall(fn, repeat):
    """Median wall time [s] of ``repeat`` calls of ``fn()``, and the list of all of them."""
    walls = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        walls.append(time.perf_counter() - t0)
    return float(np.median(walls)), walls


def interleaved_ab(run_one, rounds):
    """A/B timing in one process: in each of ``rounds`` rounds run ``run_one(which)`` for the baseline
    (``which`` "baseline"), the new code ("new") and the new code again ("control"), in an order rotating by
    round, so that the machine's load drifts over all three alike. ``run_one`` returns (wall per simulated
    second, result). Returns (walls per name, medians per name, median of the per-round new/baseline ratios,
    median of the control/new ratios (the noise floor), the last result of "baseline" and "new")."""
    names = ("baseline", "new", "control")
    walls = {n: [] for n in names}
    last = {}
    for i in range(rounds):
        for name in names[i % 3:] + names[:i % 3]:
            wall, res = run_one(name)
            walls[name].append(wall)
            if name != "control":
                last[name] = res
    med = {k: float(np.median(v)) for k, v in walls.items()}
    ratio = float(np.median(np.array(walls["new"]) / np.array(walls["baseline"])))
    control = float(np.median(np.array(walls["control"]) / np.array(walls["new"])))
    return walls, med, ratio, control, last


def speed_table(run, name):
    """The report's lines on a benchmark's median wall times against its targets: each ``<case>_s`` of the JSON
    ``name`` under ``run.out`` with ``targets_s[<case>_s]`` [s], under the command of ``run``
    (validation/_report.py's Run)."""
    d = run.load(name)
    lines = [f"Speed (`{run.command}`, medians, one run):", "", "| case | wall [ms] | target [ms] |", "|---|---|---|"]
    for k, v in d.items():
        if k.endswith("_s") and isinstance(v, float):
            t = d["targets_s"].get(k)
            lines.append(f"| {k[:-2]} | {1e3 * v:.1f} | {'' if t is None else f'{1e3 * t:.0f}'} |")
    return lines
