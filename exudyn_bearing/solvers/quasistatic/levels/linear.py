"""``model="linear"``: speed-dependent 5x5 stiffness and damping about an operating point.

From the coefficient table of :func:`..coefficients.bearing_coefficients`
(the table the ROSS export writes) at ``initialLoad`` = (F_r, F_a): speeds
omega_k, stiffness K_k, damping C_k and the inner-ring pose u0_k of the
quasi-static equilibrium at each speed. At the relative speed w_z of an
evaluation K, C and u0 are interpolated linearly in |w_z| (clamped at the
table's ends) and the bearing's force and moment on the inner ring are

    F = -L - K (u - u0) - C u',   L = (F_r, 0, F_a, 0, 0),

the reaction to the operating loads plus the linear restoring force about
the operating point (``loadAngle`` turns the table's axes, radial load along
x, to a radial load at that azimuth in the outer-ring frame: T K T^T, T u0,
T L) (valid for small motions about it; a rotor whose
static loads differ from ``initialLoad`` is outside the linearisation).
``operatingPoint`` holds the quasi-static solution, ``coefficients`` the table.

With one speed in the table (``coefficientSpeeds=[omega]``) the connector is
Exudyn's own spring-damper with constant 6x6 matrices and offset (no user
function; the spin and its damping row are zero). Otherwise a user function
makes one compiled call per evaluation and checks the state: a ring force
F = (F_x, F_y, F_z) whose magnitude exceeds ``forceLimit`` (or is not
finite: a run-away integration) stops the run with a SimulationError.
``forceLimit`` is the load along the operating load's direction (F_r, F_a)
(radial and axial at the free contact angle if unloaded) at which the
quasi-static load distribution's largest ball load
(:func:`exudyn_bearing.physics.load_distribution.static_equilibrium`, zero
speed) reaches the elastic limit of the contacts (Hertz pressure
MAX_CONTACT_PRESSURE, the quasi-static level's ``_check_ball_load``);
applied to the force's magnitude in any direction, an approximation for
forces turned away from the operating load. The one-speed connector has no
user function and no such check.

The linear level has no ball loads: it creates no ``qMaxInner`` and
``qMaxOuter`` sensors, and its samples' ``q_max_inner``, ``q_max_outer``
are NaN (the operating point's values would be wrong away from it).
"""
from __future__ import annotations

import math

import numpy as np

from ...._jit import kernel
from ....data import InputError
from ....model.load_range import MAX_CONTACT_PRESSURE
from ....model.stability import SimulationError
from ....physics.load_distribution import static_equilibrium
from .base import WS_FORCE, WS_HEADER, WS_OUT, WS_POSE, LevelBearing, entry_point
from .element import _interp_row

__all__ = ["LinearBearing", "linear_forces"]


# the linear level's part of the work array (after the header WS_HEADER of .base): the table row interpolated
# at the current speed (K (25), C (25), u0 (5)), the operating loads L (5) and the table's speeds (n)
_ROW = WS_HEADER
_LOADS = _ROW + 55
_SPEEDS = _LOADS + 5


@kernel
def linear_forces(d0, d1, d2, r0, r1, r2, v0, v1, v2, w0, w1, w2, ws, table):
    """out = -(F, 0) with F of the module docstring for the connector's displacement d, Tait-Bryan angles r,
    velocity v and angular velocity w (.base); ``table`` (n, 55): K (25), C (25), u0 (5) per speed; ``ws``
    the work array (layout above). Writes the pose u and F into its header."""
    row = ws[_ROW:_ROW + 55]
    _interp_row(ws[_SPEEDS:], table, w2, row)
    u = ws[WS_POSE:WS_POSE + 5]
    u[0] = d0
    u[1] = d1
    u[2] = d2
    u[3] = r0
    u[4] = r1
    rate = (v0, v1, v2, w0 - w2 * r1, w1 + w2 * r0)
    for i in range(5):
        f = ws[_LOADS + i]
        for j in range(5):
            f += row[5 * i + j] * (u[j] - row[50 + j]) + row[25 + 5 * i + j] * rate[j]
        ws[WS_OUT + i] = f
        ws[WS_FORCE + i] = -f
    ws[WS_OUT + 5] = 0.0


class LinearBearing(LevelBearing):
    """The linear level (module docstring); options of :class:`.base.LevelBearing`. Sensors
    ``innerRingForce``, ``outerRingForce``, ``ringDisplacement``, ``cageSpeed``: no ``qMaxInner`` or
    ``qMaxOuter`` (no ball loads); ``forceLimit`` [N]: the ring force of its validity."""

    model = "linear"
    ballLoads = False

    def _setup(self):
        c = self.coefficients
        disp = np.array(c.operating_point.get("displacement", []), float)
        if disp.shape != (c.n_speeds, 5):
            raise InputError("coefficients: the table has no operating pose per speed (operating_point"
                             "['displacement']); make it with exudyn_bearing.bearing_coefficients")
        op = c.operating_point
        table_load = (float(op.get("Fr", 0.0)), float(op.get("Fa", 0.0)))
        if not np.allclose(table_load, self.initialLoad, rtol=1e-9, atol=1e-9):
            raise InputError(f"initialLoad: {self.initialLoad} differs from the coefficient table's operating load "
                             f"{table_load}; the linear level is linearised about the table's load")
        ws = self._ws
        self._speeds = ws[_SPEEDS:]
        self._speeds[:] = c.speeds
        t = self.rotation()
        k = np.einsum("ij,njk,lk->nil", t, np.array(c.stiffness), t)
        cc = np.einsum("ij,njk,lk->nil", t, np.array(c.damping), t)
        self._table = np.ascontiguousarray(np.concatenate([k.reshape(-1, 25), cc.reshape(-1, 25), disp @ t.T],
                                                          axis=1))
        self._row = ws[_ROW:_ROW + 55]
        self._cage[0] = math.nan  # the linear level has no ball set: no cage angle, only the kinematic cage speed
        self._qmax[:] = math.nan  # nor ball loads
        #: largest ring force magnitude [N] of the linear level's validity (module docstring)
        self.forceLimit = self._force_limit()
        self._loads = ws[_LOADS:_LOADS + 5]
        self._loads[:] = t @ np.array([self.initialLoad[0], float(op.get("Fy", 0.0)), self.initialLoad[1],
                                       float(op.get("Mx", 0.0)), float(op.get("My", 0.0))])
        self._kernel = entry_point(linear_forces, (*[0.0] * 12, ws, self._table))

    def _force_limit(self):
        """The load [N] along the operating load's direction at which static_equilibrium's largest ball load
        reaches the elastic limit self._q_limit: q_max grows about as a power p of the load (p = 1 without
        clearance), so each step takes the power from the last two solutions (log-log secant)."""
        b = self.bearing
        fr, fa = self.initialLoad
        if fr == 0.0 and fa == 0.0:
            fr, fa = math.cos(b.free_contact_angle), math.sin(b.free_contact_angle)
        unit = np.array([fr, fa]) / math.hypot(fr, fa)

        def q_max(load):
            return float(np.max(static_equilibrium(b, *(load * unit), hertz_method=self.hertzModel).q))

        load = self._q_limit * b.n_balls / 5.0  # Stribeck: q_max = 5 F_r / Z
        q, power, last = q_max(load), 1.0, None
        for _ in range(40):
            if abs(q / self._q_limit - 1.0) < 1e-6:
                break
            new = load * (self._q_limit / q) ** (1.0 / power)
            last, (load, q) = (load, q), (new, q_max(new))
            if q != last[1] and load != last[0]:
                power = min(max(math.log(q / last[1]) / math.log(load / last[0]), 0.2), 2.0)
        return load

    def _workspace_size(self):
        return _SPEEDS - WS_HEADER + len(self.coefficients.speeds)

    def _connector_parameters(self):
        if self._speeds.size > 1:
            return super()._connector_parameters()
        # one speed: Exudyn's own connector, K (u - offset) + C u' = L + K (u - u0) + C u'
        k, c, u0 = self._table[0, :25].reshape(5, 5), self._table[0, 25:50].reshape(5, 5), self._table[0, 50:]
        try:
            off = u0 - np.linalg.solve(k, self._loads)
        except np.linalg.LinAlgError:
            return super()._connector_parameters()
        k6, c6, o6 = np.zeros((6, 6)), np.zeros((6, 6)), np.zeros(6)
        k6[:5, :5], c6[:5, :5], o6[:5] = k, c, off
        return {"stiffness": k6, "damping": c6, "offset": o6}

    def samples(self):
        if self._speeds.size == 1 and not self._samples:
            raise RuntimeError("samples: the one-speed linear level is Exudyn's own connector without a user "
                               "function; record its force with a SensorObject (OutputVariableType.Force)")
        return super().samples()

    def _evaluate(self, d, r, v, w):
        self._kernel(d[0], d[1], d[2], r[0], r[1], r[2], v[0], v[1], v[2], w[0], w[1], w[2], self._ws, self._table)
        self._cage[1] = self.cageRatio * w[2]
        f = self._force
        force = math.sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2])
        if not force <= self.forceLimit:  # also NaN
            self._check_state(force)

    def _check_state(self, force):
        t = self._t_last
        if not (math.isfinite(force) and np.isfinite(self._pose).all()):
            raise SimulationError(f"linear: at t = {t:.6g} s the ring displacement {list(self._pose)} or force is not "
                                  "finite: the integration ran away; check the solver and the step")
        raise SimulationError(f"linear: at t = {t:.6g} s the ring force of {force:.4g} N (displacement "
                              f"{np.linalg.norm(self._pose[:3]):.3g} m) exceeds {self.forceLimit:.4g} N, where the "
                              f"quasi-static largest ball load reaches {self._q_limit:.4g} N (Hertz pressure "
                              f"{MAX_CONTACT_PRESSURE / 1e9:g} GPa, the limit of the elastic contact model): the "
                              "linear level left its validity; use model='quasistatic' (or 'balls')")
