"""Compiled time integrators of the reference engine: velocity Verlet (the
DEM papers' scheme) and classical RK4, over the shared contact kernel
:func:`exudyn_bearing.model.contact.forces`.

State: ``xb, vb, wb`` (Z, 3) ball centre, velocity, angular velocity;
``xc, vc`` (Z, 3) cage balls (or the rigid cage in their first two rows, :mod:`...model.layout`); ``ring`` (6,) inner-ring position and velocity
(the ring translates, its spin follows the protocol, the outer ring is the
fixed frame); ``hist`` (Z, 2, 3) Cundall-Strack displacements; ``hz``
(Z, 2, HZ_N) the per-contact cache of the contact kernel. Sample buffers ``s_*`` get
one row per sample.

Condition-monitoring signals (velocity Verlet): every ``sig_every`` steps
(counted from step 0; 0: none) one row of ``s_sig`` (n, 1 + NSIGNAL): the
time and the means over the interval's force evaluations of the layout's
``SIGNAL_FIELDS`` (outer-ring force, inner-ring acceleration = ring force /
ring mass, inner-ring speed). ``sig_acc`` (NSIGNAL + 1,) carries the running
sums and, in its last entry, the number of rows written, across calls.
"""
from __future__ import annotations

import math

import numpy as np

from ..._jit import kernel
from ...model.contact import accumulate_energy, forces
from ...model.layout import (NSIGNAL, P_CAGE, P_DT, P_IB, P_MAX_OVERLAP, P_MB, P_MR,
                             P_MZ, P_RIGID)
from ...model.engine_steps import finite as _finite
from ...model.engine_steps import finite_ring as _finite_ring
from ...model.engine_steps import inner_ring_force as _inner_ring_force
from ...model.engine_steps import set_inner_ring as _set_inner_ring
from ...model.engine_steps import store_sample as _store
from ...model.motion import kick_drift

__all__ = ["run_verlet", "run_rk4", "evaluate"]


@kernel
def evaluate(t, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring,
              glob, diag, cage_load, want, defect_path=True, ellipse_path=True, loss_path=True):
    """Reference-engine force evaluation at time t (see :func:`_set_inner_ring`;
    the paths as in :func:`~exudyn_bearing.model.contact.forces`)."""
    _set_inner_ring(t, p, ring, rings, defect_path)
    worst = forces(p, table, xb, vb, wb, xc, vc, rings, hist, hist, p[P_DT], hz, fb, tb, fc, fr, glob, diag,
                   cage_load, want, defect_path, ellipse_path, loss_path)
    _inner_ring_force(p, fr, fring)
    return worst


@kernel(internal=True)
def _signal_step(k_step, t, p, rings, fr, fring, sig_every, sig_acc, s_sig):
    """Add this evaluation to the running signal sums; every ``sig_every``-th
    step write their means with the time into the next row of ``s_sig``."""
    inv_mr = 1.0 / p[P_MR]
    for d in range(3):
        sig_acc[d] += fr[1, d]
        sig_acc[3 + d] += fring[d] * inv_mr
    sig_acc[6] += rings[0, 17]
    if k_step % sig_every == 0:
        row = int(sig_acc[NSIGNAL])
        if row < s_sig.shape[0]:
            s_sig[row, 0] = t
            for c in range(NSIGNAL):
                s_sig[row, 1 + c] = sig_acc[c] / sig_every
            sig_acc[NSIGNAL] = row + 1
        for c in range(NSIGNAL):
            sig_acc[c] = 0.0


@kernel(no_runtime=True)
def run_verlet(n_steps, t0, p, table, xb, vb, wb, xc, vc, ring, hist, hz, fb, tb, fc, fring,
               sample_every, step0, s_t, s_glob, s_diag, s_cage, s_xb, s_vb, s_wb, s_xc, s_vc, s_ring,
               sig_every, sig_acc, s_sig, glob, diag, cage_load, rings, fr, defect_path=True, ellipse_path=True,
               signal_path=True, loss_path=True):
    """Velocity-Verlet (the DEM papers' scheme) for ``n_steps`` steps from t0.

    Forces must hold the values at t0 on entry; damping and friction see the
    half-step velocity. Every ``sample_every``-th step (counted from
    ``step0``) the state and diagnostics go to the next row of the s_*
    buffers; with ``sig_every`` > 0 the signals go to ``s_sig`` (module
    docstring). ``glob`` (NGLOBAL) is kept by the caller for the whole run:
    its drive_work and dissipated_work accumulate the powers of every step.
    ``diag`` (Z, 2, NDIAG), ``cage_load`` (Z, 2), ``rings`` (2, RING_N, from
    :func:`~exudyn_bearing.model.motion.ring_poses`) and ``fr`` (2, 6) are
    the force evaluation's work arrays, allocated by the caller (every entry
    is written before it is read; numba's own np.zeros compiled for about
    0.4 s of a cold start).
    Returns (steps done, samples written, status): status 0 ok,
    1 non-finite state found at a sample or at the end, 2 runaway overlap
    (> P_MAX_OVERLAP R_b, or a cage contact beyond P_MAX_OVERLAP of its radius)
    or a NaN overlap (a non-finite ball or cage ball between samples).
    ``defect_path``, ``ellipse_path``, ``loss_path`` as in :func:`~exudyn_bearing.model.contact.forces`;
    ``signal_path`` None compiles the loop without the signals (then
    ``sig_every`` must be 0).
    """
    dt = p[P_DT]
    h = 0.5 * dt
    z = xb.shape[0]
    inv_mb = 1.0 / p[P_MB]
    inv_ib = 1.0 / p[P_IB]
    inv_mz = 1.0 / p[P_MZ] if (p[P_CAGE] > 0.5 or p[P_RIGID] > 0.5) else 0.0
    inv_mr = 1.0 / p[P_MR]
    n_samp = np.int64(0)  # not the literal 0: that compiled a second copy of _store
    t = t0
    for step in range(n_steps):
        kick_drift(h, dt, xb, vb, wb, xc, vc, fb, tb, fc, inv_mb, inv_ib, inv_mz)
        for d in range(3):
            ring[3 + d] += h * fring[d] * inv_mr
            ring[d] += dt * ring[3 + d]
        t = t0 + (step + 1) * dt
        want = (step0 + step + 1) % sample_every == 0 and n_samp < s_t.shape[0]
        # the three calls of _evaluate, inlined in this hottest loop (the
        # extra array-passing call measured a few per cent slower)
        _set_inner_ring(t, p, ring, rings, defect_path)
        worst = forces(p, table, xb, vb, wb, xc, vc, rings, hist, hist, dt, hz, fb, tb, fc, fr, glob, diag,
                       cage_load, want, defect_path, ellipse_path, loss_path)
        _inner_ring_force(p, fr, fring)
        accumulate_energy(glob, dt)
        if signal_path is not None:  # pruned at compile time when None
            if sig_every > 0:
                _signal_step(step0 + step + 1, t, p, rings, fr, fring, sig_every, sig_acc, s_sig)
        for j in range(z):
            for d in range(3):
                vb[j, d] += h * fb[j, d] * inv_mb
                wb[j, d] += h * tb[j, d] * inv_ib
                vc[j, d] += h * fc[j, d] * inv_mz
        for d in range(3):
            ring[3 + d] += h * fring[d] * inv_mr
        if want:
            _store(n_samp, t, glob, diag, cage_load, xb, vb, wb, xc, vc, ring,
                   s_t, s_glob, s_diag, s_cage, s_xb, s_vb, s_wb, s_xc, s_vc, s_ring)
            n_samp += 1
            if not (_finite(xb) and _finite(vb) and _finite_ring(ring) and _finite(xc) and _finite(vc)):
                return step + 1, n_samp, 1
        if worst > p[P_MAX_OVERLAP] or not math.isfinite(worst):
            return step + 1, n_samp, 2
    if not (_finite(xb) and _finite(vb) and _finite(wb) and _finite(xc) and _finite(vc)):
        return n_steps, n_samp, 1
    return n_steps, n_samp, 0


@kernel(internal=True)
def _rk_stage(t, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag, cage_load,
              kx, kv, kw, kxc, kvc, kr, stage, defect_path, ellipse_path, loss_path):
    """Derivatives of the state at (t, state) into stage ``stage`` of the k
    arrays; returns the largest overlap ratio."""
    # want as a bool value, not the literal False: the literal compiled a copy of evaluate and of the
    # contact kernel (about 15 s of CPU each on a cold cache); as a value it is the specialisation
    # the engine's first evaluation (and velocity Verlet) already compiled
    worst = evaluate(t, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag,
                     cage_load, np.bool_(False), defect_path, ellipse_path, loss_path)
    inv_mz = 1.0 / p[P_MZ] if (p[P_CAGE] > 0.5 or p[P_RIGID] > 0.5) else 0.0
    for j in range(xb.shape[0]):
        for d in range(3):
            kx[stage, j, d] = vb[j, d]
            kv[stage, j, d] = fb[j, d] / p[P_MB]
            kw[stage, j, d] = tb[j, d] / p[P_IB]
            kxc[stage, j, d] = vc[j, d]
            kvc[stage, j, d] = fc[j, d] * inv_mz
    for d in range(3):
        kr[stage, d] = ring[3 + d]
        kr[stage, 3 + d] = fring[d] / p[P_MR]
    return worst


@kernel(no_runtime=True, internal=True)
def _rk_save(xb, vb, wb, xc, vc, ring, y0x, y0v, y0w, y0xc, y0vc, y0r):
    """y0 = state (element by element: numba's slice assignment ``y0x[:, :] = xb`` compiled its
    shape-mismatch error message, about 4 s of a cold start)."""
    for j in range(xb.shape[0]):
        for d in range(3):
            y0x[j, d] = xb[j, d]
            y0v[j, d] = vb[j, d]
            y0w[j, d] = wb[j, d]
            y0xc[j, d] = xc[j, d]
            y0vc[j, d] = vc[j, d]
    for d in range(6):
        y0r[d] = ring[d]


@kernel(internal=True)
def _rk_set(y0x, y0v, y0w, y0xc, y0vc, y0r, kx, kv, kw, kxc, kvc, kr, stage, f,
            xb, vb, wb, xc, vc, ring):
    """state = y0 + f k[stage]."""
    for j in range(xb.shape[0]):
        for d in range(3):
            xb[j, d] = y0x[j, d] + f * kx[stage, j, d]
            vb[j, d] = y0v[j, d] + f * kv[stage, j, d]
            wb[j, d] = y0w[j, d] + f * kw[stage, j, d]
            xc[j, d] = y0xc[j, d] + f * kxc[stage, j, d]
            vc[j, d] = y0vc[j, d] + f * kvc[stage, j, d]
    for d in range(6):
        ring[d] = y0r[d] + f * kr[stage, d]


@kernel
def run_rk4(n_steps, t0, p, table, xb, vb, wb, xc, vc, ring, hist, hz, fb, tb, fc, fring,
            sample_every, step0, s_t, s_glob, s_diag, s_cage, s_xb, s_vb, s_wb, s_xc, s_vc, s_ring,
            sig_every, sig_acc, s_sig, glob, diag, cage_load, rings, fr, defect_path=True, ellipse_path=True,
            signal_path=True, loss_path=True):
    """Classical fourth-order Runge-Kutta, for history-free scenes (same
    interface and status codes as :func:`run_verlet`; it records no signals
    and keeps no ball orientation: Scenario allows neither with rk4). The
    energy integrals take the stage powers with the method's weights. The
    work arrays ``diag``, ``cage_load``, ``rings``, ``fr`` as in run_verlet."""
    dt = p[P_DT]
    z = xb.shape[0]
    kx = np.zeros((4, z, 3))
    kv = np.zeros((4, z, 3))
    kw = np.zeros((4, z, 3))
    kxc = np.zeros((4, z, 3))
    kvc = np.zeros((4, z, 3))
    kr = np.zeros((4, 6))
    y0x = np.zeros((z, 3))
    y0v = np.zeros((z, 3))
    y0w = np.zeros((z, 3))
    y0xc = np.zeros((z, 3))
    y0vc = np.zeros((z, 3))
    y0r = np.zeros(6)
    n_samp = np.int64(0)  # not the literal 0: that compiled a second copy of _store
    # the stage numbers as int64 values, not literals: each literal compiled a copy of _rk_stage and _rk_set
    s0, s1, s2, s3 = np.int64(0), np.int64(1), np.int64(2), np.int64(3)
    for step in range(n_steps):
        t = t0 + step * dt
        _rk_save(xb, vb, wb, xc, vc, ring, y0x, y0v, y0w, y0xc, y0vc, y0r)
        worst = _rk_stage(t, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag,
                          cage_load, kx, kv, kw, kxc, kvc, kr, s0, defect_path, ellipse_path, loss_path)
        accumulate_energy(glob, dt / 6.0)
        if worst > p[P_MAX_OVERLAP] or not math.isfinite(worst):
            return step, n_samp, 2
        _rk_set(y0x, y0v, y0w, y0xc, y0vc, y0r, kx, kv, kw, kxc, kvc, kr, s0, 0.5 * dt, xb, vb, wb, xc, vc, ring)
        _rk_stage(t + 0.5 * dt, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag,
                  cage_load, kx, kv, kw, kxc, kvc, kr, s1, defect_path, ellipse_path, loss_path)
        accumulate_energy(glob, dt / 3.0)
        _rk_set(y0x, y0v, y0w, y0xc, y0vc, y0r, kx, kv, kw, kxc, kvc, kr, s1, 0.5 * dt, xb, vb, wb, xc, vc, ring)
        _rk_stage(t + 0.5 * dt, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag,
                  cage_load, kx, kv, kw, kxc, kvc, kr, s2, defect_path, ellipse_path, loss_path)
        accumulate_energy(glob, dt / 3.0)
        _rk_set(y0x, y0v, y0w, y0xc, y0vc, y0r, kx, kv, kw, kxc, kvc, kr, s2, dt, xb, vb, wb, xc, vc, ring)
        _rk_stage(t + dt, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag,
                  cage_load, kx, kv, kw, kxc, kvc, kr, s3, defect_path, ellipse_path, loss_path)
        accumulate_energy(glob, dt / 6.0)
        c = dt / 6.0
        for j in range(z):
            for d in range(3):
                xb[j, d] = y0x[j, d] + c * (kx[0, j, d] + 2 * kx[1, j, d] + 2 * kx[2, j, d] + kx[3, j, d])
                vb[j, d] = y0v[j, d] + c * (kv[0, j, d] + 2 * kv[1, j, d] + 2 * kv[2, j, d] + kv[3, j, d])
                wb[j, d] = y0w[j, d] + c * (kw[0, j, d] + 2 * kw[1, j, d] + 2 * kw[2, j, d] + kw[3, j, d])
                xc[j, d] = y0xc[j, d] + c * (kxc[0, j, d] + 2 * kxc[1, j, d] + 2 * kxc[2, j, d] + kxc[3, j, d])
                vc[j, d] = y0vc[j, d] + c * (kvc[0, j, d] + 2 * kvc[1, j, d] + 2 * kvc[2, j, d] + kvc[3, j, d])
        for d in range(6):
            ring[d] = y0r[d] + c * (kr[0, d] + 2 * kr[1, d] + 2 * kr[2, d] + kr[3, d])
        want = (step0 + step + 1) % sample_every == 0 and n_samp < s_t.shape[0]
        if want:
            evaluate(t + dt, p, table, xb, vb, wb, xc, vc, ring, rings, hist, hz, fb, tb, fc, fr, fring, glob, diag,
                     cage_load, want, defect_path, ellipse_path, loss_path)  # want (True here), not the literal: see _rk_stage
            _store(n_samp, t + dt, glob, diag, cage_load, xb, vb, wb, xc, vc, ring,
                   s_t, s_glob, s_diag, s_cage, s_xb, s_vb, s_wb, s_xc, s_vc, s_ring)
            n_samp += 1
        if not (_finite(xb) and _finite(vb) and _finite_ring(ring) and _finite(xc) and _finite(vc)):
            return step + 1, n_samp, 1
    return n_steps, n_samp, 0
