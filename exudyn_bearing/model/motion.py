"""Motion helpers shared by the solvers' compiled loops: the speed protocol,
the velocity-Verlet kick and drift of balls and cage balls, and the ring pose
array at rest (layout :data:`~exudyn_bearing.model.layout.RING_N`)."""
from __future__ import annotations

import numpy as np

from .._jit import kernel
from .layout import RING_N

__all__ = ["omega_profile", "kick_drift", "ring_poses"]


@kernel
def omega_profile(t, w_max, t_up, t_steady, t_down):
    """Inner-ring speed of the protocol: ramp up, hold, ramp down, rest [rad/s]."""
    if t < 0.0:
        return 0.0
    if t < t_up:
        return w_max * t / t_up
    t = t - t_up
    if t < t_steady:
        return w_max
    t = t - t_steady
    if t < t_down:
        return w_max * (1.0 - t / t_down)
    return 0.0


@kernel
def kick_drift(h, dt, xb, vb, wb, xc, vc, fb, tb, fc, inv_mb, inv_ib, inv_mz):
    """Velocity-Verlet half kick of balls and cage balls by h, then a drift by dt."""
    for j in range(xb.shape[0]):
        for d in range(3):
            vb[j, d] += h * fb[j, d] * inv_mb
            wb[j, d] += h * tb[j, d] * inv_ib
            xb[j, d] += dt * vb[j, d]
            vc[j, d] += h * fc[j, d] * inv_mz
            xc[j, d] += dt * vc[j, d]


@kernel
def ring_poses():
    """Ring pose array (2, RING_N): both rings at the origin, at rest, unrotated."""
    rings = np.zeros((2, RING_N))
    for r in range(2):
        rings[r, 6] = 1.0
        rings[r, 10] = 1.0
        rings[r, 14] = 1.0
    return rings
