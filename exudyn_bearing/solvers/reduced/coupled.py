"""Compiled entry points of the reduced level of :func:`exudyn_bearing.CreateBallBearing` (``model="reduced"``,
:mod:`.level`, docs/theory/levels.md#reduced-level): the force of the balls on the inner ring at a ring pose and
velocity that Exudyn's Newton iteration proposes, with the balls' slow states (orbital angles and speeds, ball
angular velocities, the rigid cage) frozen and each ball centre on its normal force balance
(:func:`.stepper._balance`, the reduced engine's own balance over the shared contact kernel: no physics of its
own here). The slow states are advanced between Exudyn steps by :func:`.stepper.run_reduced` with the ring held.
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel
from ...model.layout import NDIAG, NGLOBAL
from .stepper import _balance

__all__ = ["frozen_ring_force"]


@kernel
def frozen_ring_force(t, dt, p, table, phi, om, wo, q, q_old, ring, xc, vc, rings, hist, hz, g, tol, max_iter, fresh,
                      work, out, defect_path, ellipse_path, loss_path):
    """The force and moment of the balls on the inner ring (``out`` (6,), about its centre, outer-ring frame) at
    time t with the inner ring at ``ring`` (position, velocity (6,)) and its spin the protocol's of ``p``; the balls'
    angles ``phi``, orbital speeds ``om``, angular velocities ``wo`` and the cage ``xc``, ``vc`` are read, not
    changed. Each ball centre ``q`` (warm start on entry, the solution on exit) is solved on its normal force
    balance with its rate (q - q_old) / dt, ``g`` the balance's kept Jacobians (retaken when ``fresh`` or when a
    residual grows, :func:`.stepper._balance`). Returns (Newton iterations, converged, the largest overlap
    ratio)."""
    z = phi.shape[0]
    wb = np.zeros((z, 3))
    xb = np.zeros((z, 3))
    vb = np.zeros((z, 3))
    fb = np.zeros((z, 3))
    tb = np.zeros((z, 3))
    fc = np.zeros((z, 3))
    fr = np.zeros((2, 6))
    fring = np.zeros(3)
    glob = np.zeros(NGLOBAL)
    diag = np.zeros((z, 2, NDIAG))
    cage_load = np.zeros((z, 2))
    res = np.zeros((z, 2))
    acc = np.zeros((z, 4))
    r0 = np.zeros((z, 2))
    done = np.zeros(z)
    qref = np.zeros((z, 2))
    it, ok, worst = _balance(t, dt, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb, tb,
                             fc, fr, fring, glob, diag, cage_load, res, acc, g, r0, done, tol, max_iter, work, fresh,
                             qref, 0.0, defect_path, ellipse_path, loss_path)
    for k in range(6):
        out[k] = fr[0, k]
    return it, ok, worst
