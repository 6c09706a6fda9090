"""Bearing stiffness matrix at the operating point by central differences.

K_ij = -d G_i / d u_j, G the balls' generalized force on the inner ring
(:func:`.balls.ring_forces`) and u = (delta_x, delta_y, delta_a, tilt_x,
tilt_y); the ball positions are re-solved at every perturbed pose, the ball
kinematics (centrifugal and traction forces) are held at the operating
point. The step is h = 1e-4 of the largest contact overlap (tilts: h over
the inner groove radius); the matrix is computed with h and h/2 and the
largest difference relative to the largest entry is reported as evidence
that the step is converged. At zero speed the balls' forces derive from the
Hertz potential and K is symmetric; at speed the traction that carries the
gyroscopic moment is not conservative and K may be slightly asymmetric.
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["stiffness_matrix"]


def _central(prob, u, h):
    k = np.zeros((5, 5))
    for j in range(5):
        e = np.zeros(5)
        e[j] = h[j]
        gp = prob.residual(u + e)[0] - prob.loads
        gm = prob.residual(u - e)[0] - prob.loads
        k[:, j] = -(gp - gm) / (2.0 * h[j])
    return k


def stiffness_matrix(prob, u, balls):
    """(K (5, 5), check dict with ``step`` [m], ``relative_change_half_step``, ``asymmetry``)."""
    dmax = float(max(np.max(balls[:, 4]), np.max(balls[:, 5]), 1e-9))
    h0 = 1e-4 * dmax
    arm = prob.arm
    h = np.array([h0, h0, h0, h0 / arm, h0 / arm])
    k1 = _central(prob, u, h)
    k2 = _central(prob, u, 0.5 * h)
    scale = max(np.abs(k2).max(), 1e-300)
    # compare in consistent units: moments / arm, tilts * arm
    w = np.array([1.0, 1.0, 1.0, 1.0 / arm, 1.0 / arm])
    kk = k2 * np.outer(w, w)
    change = float(np.abs((k1 - k2) * np.outer(w, w)).max() / max(np.abs(kk).max(), 1e-300))
    asym = float(np.abs(kk - kk.T).max() / max(np.abs(kk).max(), 1e-300))
    return k2, {"step": h0, "relative_change_half_step": change, "asymmetry": asym,
                "largest_entry": float(scale), "finite": bool(np.all(np.isfinite(k2))) and math.isfinite(change)}
