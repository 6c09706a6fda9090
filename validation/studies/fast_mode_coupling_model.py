"""A linear model of the fast mode's staggered coupling: why its step limit lies below the ring's own.

The element's fast mode (docs/theory/dynamics.md) integrates the ring in
Exudyn with velocity Verlet at the step H and the balls in n compiled
velocity-Verlet sub-steps of dt = H / n per Exudyn step. The balls see the
ring's pose interpolated linearly from the pose they saw last to the
current Exudyn pose and extrapolated beyond it with the half-step velocity
Exudyn passes; the ring gets the mean of the sub-steps' reactions (the
window of sub-steps centred on the Exudyn time). This script builds that
scheme for the smallest system that has it, one degree of freedom each:

    ring (mass M) --k-- ball (mass m) --k-- ground (the outer ring)

with M, m and k chosen like the 6208 test scene at 3000 N: k = 6.2e8 N/m,
the tangent stiffness of the inner race that gives the 81 g ring its
22.8 us stable step (``ring_contact_stiffness``); m = 3.5 balls of 8.2 g,
the loaded balls' share, so that the ball's normal mode between its races
has the reference engine's 9.6 us limit. No damping. The scheme is linear,
so one Exudyn step is a matrix; its spectral radius above 1 means a mode
that grows by that factor per step. The script prints it against n for ring
masses of 81 g to 5 kg and dt = 5 us, the same for the monolithic scheme
(ring and ball both at dt) as the control (radius 1: velocity Verlet
conserves a discrete energy), and for three other weightings of the
sub-step reactions, and for the variant that holds the ring at its Exudyn
pose through the window (not what the element does: tried on the element,
it was better beyond the limit on heavy rings and worse within it at light
load).

It is a model, not the bearing: the real contacts are damped (hysteresis,
lubricant), which holds a slowly growing mode down at short H, and the
fast mode's measured limits are those of ``validation/studies/fast_mode_limits.py``.

    python validation/studies/fast_mode_coupling_model.py
"""
from __future__ import annotations

import math

import numpy as np

K = 6.2e8            # N/m, ring-ball and ball-ground
M_BALL = 3.5 * 8.2e-3  # kg
DT = 5e-6            # s, the ball sub-step


def weights(kind, n):
    """Weights of the n sub-step reactions in the ring's force."""
    i = np.arange(n)
    if kind == "mean":
        return np.ones(n)
    if kind == "triangle":
        return np.minimum(i + 1, n - i).astype(float)
    if kind == "hann":
        return np.sin(math.pi * (i + 0.5) / n) ** 2
    if kind == "centre":
        return np.isin(i, ((n - 1) // 2, n // 2)).astype(float)
    raise ValueError(kind)


def step_matrix(m_ring, n, kind="mean", held=False):
    """One Exudyn step of the staggered scheme as a matrix on the state
    (X, V, A, x, v, a, X_last): ring position, velocity, acceleration; ball
    position, velocity, acceleration; the ring position the balls saw last.
    ``held``: the balls see the ring at its Exudyn pose through the whole
    window instead of interpolated and extrapolated (a variant, not the element's)."""
    h = n * DT
    w = weights(kind, n)
    span = h / 2 + DT / 2  # from the last sub-step of the previous window to the Exudyn time
    cols = []
    for e in np.eye(7):
        X, V, A, x, v, a, x_last = e
        vh = V + 0.5 * h * A  # Exudyn's velocity Verlet: half-step velocity, new position
        xn = X + h * vh
        fsum = 0.0
        for i in range(n):
            v += 0.5 * DT * a
            x += DT * v
            u = (i + 1) * DT
            if held:
                xr = xn
            else:
                xr = x_last + u / span * (xn - x_last) if u < span else xn + (u - span) * vh
            f = K * (x - xr)  # on the ring; the ball gets -f and the ground spring
            a = (-f - K * x) / M_BALL
            v += 0.5 * DT * a
            fsum += w[i] * f
        a_ring = fsum / w.sum() / m_ring
        cols.append([xn, vh + 0.5 * h * a_ring, a_ring, x, v, a, xr])
    return np.array(cols).T


def monolithic_matrix(m_ring):
    """Ring and ball both in velocity Verlet at DT (the body mode): the control."""
    kmat = np.array([[-K, K], [K, -2 * K]])
    minv = np.diag([1.0 / m_ring, 1.0 / M_BALL])
    cols = []
    for e in np.eye(4):
        q, p = e[:2], e[2:]
        a = minv @ kmat @ q
        ph = p + 0.5 * DT * a
        q1 = q + DT * ph
        p1 = ph + 0.5 * DT * (minv @ kmat @ q1)
        cols.append([*q1, *p1])
    return np.array(cols).T


def radius(mat):
    return float(max(abs(np.linalg.eigvals(mat))))


def main():
    from exudyn_bearing.model.stability import FAST_STEP_SHARE

    print(f"one ring (M) -- k -- one ball (m = {M_BALL * 1e3:.1f} g) -- k -- ground, k = {K:.2g} N/m, ball sub-step "
          f"{DT * 1e6:g} us, no damping; spectral radius of one Exudyn step minus 1 (above 0: a mode grows by that "
          "factor per step)")
    ns = (1, 2, 3, 4, 6, 8, 12, 16)
    for m_ring in (0.081, 0.3, 1.25, 5.0):
        h_ring = 2.0 / math.sqrt(K / m_ring)
        print(f"ring {m_ring:g} kg (its own Verlet limit 2/omega = {h_ring * 1e6:.1f} us, the element's limit "
              f"{FAST_STEP_SHARE:g} of it = {FAST_STEP_SHARE * h_ring * 1e6:.1f} us); monolithic at {DT * 1e6:g} us: "
              f"{radius(monolithic_matrix(m_ring)) - 1:+.1e}")
        for kind in ("mean", "triangle", "hann", "centre"):
            vals = "  ".join(f"n={n}: {radius(step_matrix(m_ring, n, kind)) - 1:+.4f}" for n in ns)
            print(f"  {kind:8s} {vals}")
        vals = "  ".join(f"n={n}: {radius(step_matrix(m_ring, n, held=True)) - 1:+.4f}" for n in ns)
        print(f"  {'held':8s} {vals}   (mean reaction, the ring held at its Exudyn pose through the window)")


if __name__ == "__main__":
    main()
