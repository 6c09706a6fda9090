"""Timing helper shared by the benchmark scripts of this folder."""
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
