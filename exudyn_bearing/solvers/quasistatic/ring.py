"""Inner-ring equilibrium in five degrees of freedom.

Unknowns u = (delta_x, delta_y, delta_a, tilt_x, tilt_y) [m, m, m, rad, rad]
of the inner ring against the fixed outer ring; equations: the generalized
force of the balls (:func:`.balls.ring_forces`) plus the applied loads
(F_x, F_y, F_a, M_x, M_y) vanish in every free DOF (Jones [1]_). A DOF can be
held at a given value by the caller; its reaction (what the constraint must
add) is returned. A DOF is also held where symmetry fixes it and the
equations are singular there: the axial DOF and both tilts of a deep-groove
bearing (grooves in one radial plane) without axial load or moment, and the
radial DOFs and tilts under pure thrust. The solution record lists these DOFs
and their residuals (zero by symmetry).

The start comes from one-dimensional bracketed solves along the axial, the
radial-load and the moment directions (Brent), then all free DOFs together
with scipy's ``root`` (hybrid Powell, Levenberg-Marquardt as fallback).

References
----------
.. [1] A. B. Jones, "A general theory of elastically constrained ball and
   roller bearings under arbitrary load and speed conditions," J. Basic Eng.
   82 (1960) 309-320. doi:10.1115/1.3662587
"""
from __future__ import annotations

import math

import numpy as np
from scipy import optimize

from ...data import InputError
from .balls import ring_forces

__all__ = ["DOF_NAMES", "LOAD_NAMES", "RingProblem", "solve_ring"]

DOF_NAMES = ("delta_x", "delta_y", "delta_a", "tilt_x", "tilt_y")
LOAD_NAMES = ("Fr", "Fy", "Fa", "Mx", "My")  # the parameter names of solve_quasistatic


class RingProblem:
    """Ring equilibrium for fixed ball kinematics (centrifugal and traction forces per ball)."""

    def __init__(self, psi, geom, m_w2, fto, fti, e_prime, method, loads):
        self.psi, self.geom = psi, geom
        self.m_w2, self.fto, self.fti = m_w2, fto, fti
        self.e_prime, self.method = e_prime, method
        self.loads = np.asarray(loads, float)
        self.arm = max(math.hypot(geom.rho_i, geom.z_i), 1e-9)  # moment arm: moments / arm ~ forces

    def residual(self, u):
        """Balls' generalized force + applied loads (5,) [N, N, N, N m, N m], and the per-ball table."""
        gen, balls = ring_forces(u, self.psi, self.geom, self.m_w2, self.fto, self.fti, self.e_prime, self.method)
        return gen + self.loads, balls


def _bracket_root(f, lo, step, limit):
    """Root of a function falling through zero above lo: expand the bracket, then Brent."""
    f_lo = f(lo)
    if f_lo == 0.0:
        return lo
    hi = lo + step
    while f(hi) * f_lo > 0.0:
        hi = lo + 2.0 * (hi - lo)
        if abs(hi - lo) > limit:
            return None
    return optimize.brentq(f, lo, hi, xtol=1e-15, rtol=1e-13, maxiter=200)


def _start(prob, u, free, bearing):
    """1-D bracketed solves along the axial, radial-load and moment directions."""
    g = prob.geom
    loads = prob.loads
    u = np.array(u, float)
    size = 1e-3 * bearing.ball_radius
    limit = 0.2 * bearing.ball_radius
    angular = g.z_i - g.z_o > 0.0
    if free[2] and (loads[2] != 0.0 or angular):
        # the balls' axial force falls as the ring moves along the load: bracket from the unloaded side
        sgn = 1.0 if (angular or loads[2] > 0.0) else -1.0
        lo = -0.999 * (g.z_i - g.z_o) if angular else 0.0

        def fz(d):
            v = u.copy()
            v[2] = sgn * d
            return sgn * prob.residual(v)[0][2]
        root = _bracket_root(fz, lo, size, abs(lo) + limit)
        if root is not None:
            u[2] = sgn * root
    fr = math.hypot(loads[0], loads[1])
    if (free[0] or free[1]) and fr > 0.0:
        _root_along(prob, u, (0, 1), (loads[0] / fr, loads[1] / fr), size, limit)
    mm = math.hypot(loads[3], loads[4])
    if (free[3] or free[4]) and mm > 0.0:
        _root_along(prob, u, (3, 4), (loads[3] / mm, loads[4] / mm), size / prob.arm, limit / prob.arm)
    return u


def _root_along(prob, u, dofs, e, size, limit):
    """Move the pose ``u`` (in place) along the unit direction ``e`` of the two DOFs ``dofs`` (x, y or the two
    tilts) to where the residual's component along ``e`` vanishes, if a bracket within ``limit`` holds a root."""
    i, j = dofs

    def f(s):
        v = u.copy()
        v[i], v[j] = s * e[0], s * e[1]
        r = prob.residual(v)[0]
        return r[i] * e[0] + r[j] * e[1]
    root = _bracket_root(f, 0.0, size, limit)
    if root is not None:
        u[i], u[j] = root * e[0], root * e[1]


def solve_ring(prob: RingProblem, free, held, u_start, bearing, tol=1e-10, cold=True):
    """Solve the free DOFs; ``held`` (5,) gives the values of the others.

    Returns (u (5,), residual (5,), balls table). Raises InputError when no
    equilibrium is found (message names the largest load). A warm start
    (``cold=False``) that fails is retried from the bracketed start.
    """
    try:
        return _solve_ring(prob, free, held, u_start, bearing, tol, cold)
    except InputError:
        if cold:
            raise
        return _solve_ring(prob, free, held, u_start, bearing, tol, True)


def _solve_ring(prob, free, held, u_start, bearing, tol, cold):
    free = np.asarray(free, bool)
    u = np.where(free, u_start, held).astype(float)
    if cold:
        # the 1-D starts move x and y (or both tilts) together: held DOFs keep their values
        u = np.where(free, _start(prob, np.where(free, 0.0, held).astype(float), free, bearing), held)
    if not free.any():
        r, balls = prob.residual(u)
        return u, r, balls
    lscale = max(np.abs(u[:3]).max(), np.abs(u[3:]).max() * prob.arm, 1e-7)
    colscale = np.array([1.0, 1.0, 1.0, 1.0 / prob.arm, 1.0 / prob.arm]) * lscale
    fscale = max(np.abs(prob.loads[:3]).max(), np.abs(prob.loads[3:]).max() / prob.arm, 1.0)
    rowscale = np.array([1.0, 1.0, 1.0, 1.0 / prob.arm, 1.0 / prob.arm]) / fscale
    idx = np.flatnonzero(free)

    def fun(x):
        v = u.copy()
        v[idx] = x * colscale[idx]
        return prob.residual(v)[0][idx] * rowscale[idx]

    x0 = u[idx] / colscale[idx]
    best = None
    for method, opts in (("hybr", {"xtol": tol}), ("lm", {"xtol": tol, "ftol": tol})):
        sol = optimize.root(fun, x0, method=method, options=opts)
        err = np.abs(fun(sol.x)).max()
        if best is None or err < best[1]:
            best = (sol.x, err)
        if err < 1e-9:
            break
    x, err = best
    u[idx] = x * colscale[idx]
    r, balls = prob.residual(u)
    if err > 1e-7 or not np.all(np.isfinite(u)):
        k = int(np.argmax(np.abs(prob.loads) * np.array([1, 1, 1, 1 / prob.arm, 1 / prob.arm])))
        raise InputError(f"{LOAD_NAMES[k]}: the 5-DOF inner-ring equilibrium did not converge (relative residual "
                         f"{err:.1e} > 1e-7): the loads {prob.loads.round(3).tolist()} may exceed what the bearing "
                         f"can carry in this configuration")
    if np.any(balls[:, -1] < 0.5):
        raise InputError(f"{LOAD_NAMES[int(np.argmax(np.abs(prob.loads)))]}: the equilibrium of ball "
                         f"{int(np.argmin(balls[:, -1]))} did not converge")
    return u, r, balls
