"""Motion helpers shared by the solvers' compiled loops: the speed protocol
and its integral (the ring's spin angle), the velocity-Verlet kick and drift
of balls and cage balls, the turning of a ball's body frame, and the ring
pose array at rest (layout :data:`~exudyn_bearing.model.layout.RING_N`)."""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel
from .layout import RING_N

__all__ = ["omega_profile", "spin_angle", "kick_drift", "ring_poses", "rotate_frame", "HOLD_END_TOLERANCE"]

#: :func:`omega_profile` without a ramp down: a time within this share of the hold's end (t_up + t_steady) is
#: still held (the round-off of the engines' accumulated times; 1e-9 of a 10 s protocol is 1e-8 s, below the
#: least step 1e-7 s).
HOLD_END_TOLERANCE = 1e-9


@kernel
def omega_profile(t, w_max, t_up, t_steady, t_down):
    """Inner-ring speed of the protocol: ramp up, hold, ramp down, rest [rad/s]. Without a ramp down the hold
    includes its end (within HOLD_END_TOLERANCE of it, far below any step): a run that ends there ends at speed,
    and its last sample is not taken after an instantaneous stop."""
    if t < 0.0:
        return 0.0
    if t < t_up:
        return w_max * t / t_up
    t = t - t_up
    if t < t_steady or (t_down == 0.0 and t <= t_steady + HOLD_END_TOLERANCE * (t_up + t_steady)):
        return w_max
    t = t - t_steady
    if t < t_down:
        return w_max * (1.0 - t / t_down)
    return 0.0


@kernel
def spin_angle(t, w_max, t_up, t_steady, t_down):
    """Angle [rad] the inner ring has turned at time t under the protocol of
    :func:`omega_profile`: its integral from 0, in closed form (quadratic on
    the ramps, linear while steady, constant at rest)."""
    if t <= 0.0:
        return 0.0
    if t < t_up:
        return 0.5 * w_max * t * t / t_up
    angle = 0.5 * w_max * t_up
    t = t - t_up
    if t < t_steady:
        return angle + w_max * t
    angle += w_max * t_steady
    t = t - t_steady
    if t < t_down:
        return angle + w_max * (t - 0.5 * t * t / t_down)
    return angle + 0.5 * w_max * t_down


@kernel(inline="always")
def rotate_frame(src, dst, j, r1, r2, wx, wy, wz, dt):
    """Turn the body-frame axes ``src[j, r1]``, ``src[j, r2]`` (unit vectors,
    world frame) by the rotation of angle |w| dt about w (Rodrigues' formula,
    exact for a constant angular velocity over dt) into ``dst[j, r1]``,
    ``dst[j, r2]`` (which may be ``src``), then make them orthonormal again
    (Gram-Schmidt) so round-off cannot accumulate. Zero axes stay zero."""
    wn = math.sqrt(wx * wx + wy * wy + wz * wz)
    phi = wn * dt
    if phi > 0.0:
        kx, ky, kz = wx / wn, wy / wn, wz / wn
        c, sn = math.cos(phi), math.sin(phi)
    else:
        kx, ky, kz, c, sn = 0.0, 0.0, 1.0, 1.0, 0.0
    for r in (r1, r2):
        vx, vy, vz = src[j, r, 0], src[j, r, 1], src[j, r, 2]
        kv = kx * vx + ky * vy + kz * vz
        cx = ky * vz - kz * vy
        cy = kz * vx - kx * vz
        cz = kx * vy - ky * vx
        dst[j, r, 0] = vx * c + cx * sn + kx * kv * (1.0 - c)
        dst[j, r, 1] = vy * c + cy * sn + ky * kv * (1.0 - c)
        dst[j, r, 2] = vz * c + cz * sn + kz * kv * (1.0 - c)
    n1 = math.sqrt(dst[j, r1, 0] ** 2 + dst[j, r1, 1] ** 2 + dst[j, r1, 2] ** 2)
    if n1 == 0.0:
        return
    for d in range(3):
        dst[j, r1, d] /= n1
    p12 = dst[j, r1, 0] * dst[j, r2, 0] + dst[j, r1, 1] * dst[j, r2, 1] + dst[j, r1, 2] * dst[j, r2, 2]
    for d in range(3):
        dst[j, r2, d] -= p12 * dst[j, r1, d]
    n2 = math.sqrt(dst[j, r2, 0] ** 2 + dst[j, r2, 1] ** 2 + dst[j, r2, 2] ** 2)
    if n2 > 0.0:
        for d in range(3):
            dst[j, r2, d] /= n2


@kernel(inline="always")
def kick_drift(h, dt, xb, vb, wb, xc, vc, fb, tb, fc, inv_mb, inv_ib, inv_mz):
    """Velocity-Verlet half kick of balls and cage balls by h, then a drift by dt."""
    for j in range(xb.shape[0]):
        for d in range(3):
            vb[j, d] += h * fb[j, d] * inv_mb
            wb[j, d] += h * tb[j, d] * inv_ib
            xb[j, d] += dt * vb[j, d]
            vc[j, d] += h * fc[j, d] * inv_mz
            xc[j, d] += dt * vc[j, d]


def ring_poses():
    """Ring pose array (2, RING_N): both rings at the origin, at rest, unrotated (plain NumPy: the
    compiled callers get it from Python)."""
    rings = np.zeros((2, RING_N))
    for r in range(2):
        rings[r, 6] = 1.0
        rings[r, 10] = 1.0
        rings[r, 14] = 1.0
    return rings
