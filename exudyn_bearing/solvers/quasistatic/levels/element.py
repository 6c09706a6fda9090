"""``model="quasistatic"``: the bearing as a 5-DOF force element without ball DOFs.

At every evaluation, for the inner ring's pose u = (d_x, d_y, d_z, theta_x,
theta_y) and relative spin w_z against the outer ring (:mod:`.base`):

* the cage angle theta_c = theta_c0 + k_c phi, phi the relative spin angle
  (unwrapped from the connector's Tait-Bryan angle) and k_c = (1 - gamma)/2
  the kinematic cage ratio (:func:`exudyn_bearing.physics.kinematics.cage_speed`,
  free contact angle): the balls sit at psi_j = theta_c + 2 pi j / Z, so the
  stiffness varies with the ball-set position and the ball-pass vibration
  at Z omega_c appears;
* the quasi-static ball equilibrium of the quasi-static solver
  (:func:`..balls._ring_forces`, exact groove geometry, Hertz at each ball's
  contact angle, clearance or preload, tilt) with the centrifugal force
  m omega_c^2 r_c and the gyroscopic moment J omega_c omega_R (-sin alpha_0)
  carried at the outer race (outer-race control) at the current speed, the
  grooves grown by the current speed when ``ringGrowth`` (geometry updated
  when the speed moved by more than 1 %);
* the damping matrix C of :mod:`..damping` (normal contact and film damping
  condensed over each ball's contacts) interpolated in the speed from the
  coefficient table at ``initialLoad``, times the pose rates.

The force F = G(u, psi) - C u' on the inner ring (G: the balls' generalized
force) is one compiled call. Exudyn's implicit solvers differentiate the
connector numerically for their Jacobian; the explicit ones call it once per
stage.
"""
from __future__ import annotations

import math

import numpy as np

from ...._jit import kernel
from ....data import MAX_FREE_CONTACT_ANGLE
from ....model.operating_geometry import operating_geometry
from ....physics import hertz as _hz
from ..balls import B_NIR, B_NIZ, B_QI, B_QO, NB, _ring_forces
from .base import LevelBearing, entry_point

__all__ = ["QuasiStaticBearing", "level_forces"]

_TWO_PI = 2.0 * math.pi


@kernel
def _interp_row(speeds, table, w, out):
    """out = table interpolated linearly at |w| over ``speeds`` (clamped at the ends); table (n, m)."""
    a = abs(w)
    n = speeds.size
    if n == 1 or a <= speeds[0]:
        out[:] = table[0]
        return
    if a >= speeds[n - 1]:
        out[:] = table[n - 1]
        return
    k = np.searchsorted(speeds, a) - 1
    s = (a - speeds[k]) / (speeds[k + 1] - speeds[k])
    for i in range(out.size):
        out[i] = (1.0 - s) * table[k, i] + s * table[k + 1, i]


@kernel
def level_forces(d, r, v, w, state, geo, kc, kr, sin_a0, mass, inertia, e_prime, method, speeds, ctab, cflat,
                 psi, m_w2, fto, fti, balls, gen, u, out, force, cage, qmax):
    """One evaluation of the quasi-static level (module docstring).

    state: [last Tait-Bryan spin angle, unwrapped spin angle, cage angle at zero spin angle];
    geo: (rho_i, z_i, rho_o, z_o, r_ci, r_co, r_b); ctab (n, 25): damping matrices at ``speeds``.
    Writes u (5,), the balls table, ``out`` (6,) = -(F, 0), ``force`` = F (5,), ``cage`` (angle, speed) and
    ``qmax`` (largest inner and outer ball load, largest loaded inner contact angle); returns the largest ball
    load."""
    dc = r[2] - state[0]
    dc -= _TWO_PI * math.floor(dc / _TWO_PI + 0.5)
    state[0] = r[2]
    state[1] += dc
    ws = w[2]
    wc = kc * ws
    theta = state[2] + kc * state[1]
    z = psi.size
    g = inertia * wc * (-kr * ws * sin_a0) / geo[6]
    for j in range(z):
        psi[j] = theta + _TWO_PI * j / z
        m_w2[j] = mass * wc * wc
        fto[j] = g
        fti[j] = 0.0
    u[0] = d[0]
    u[1] = d[1]
    u[2] = d[2]
    u[3] = r[0]
    u[4] = r[1]
    _ring_forces(u, psi, geo[0], geo[1], geo[2], geo[3], geo[4], geo[5], geo[6], m_w2, fto, fti, e_prime, method,
                 balls, gen)
    _interp_row(speeds, ctab, ws, cflat)
    rate0, rate1, rate2 = v[0], v[1], v[2]
    rate3 = w[0] - ws * r[1]
    rate4 = w[1] + ws * r[0]
    qmax[0] = 0.0
    qmax[1] = 0.0
    qmax[2] = 0.0
    for j in range(z):
        qmax[0] = max(qmax[0], balls[j, B_QI])
        qmax[1] = max(qmax[1], balls[j, B_QO])
        if balls[j, B_QI] > 0.0:  # contact angle from the groove bottom, inner race
            qmax[2] = max(qmax[2], abs(math.atan2(-balls[j, B_NIZ], -balls[j, B_NIR])))
    for i in range(5):
        c = (cflat[5 * i] * rate0 + cflat[5 * i + 1] * rate1 + cflat[5 * i + 2] * rate2 + cflat[5 * i + 3] * rate3
             + cflat[5 * i + 4] * rate4)
        out[i] = -gen[i] + c
        force[i] = -out[i]
    out[5] = 0.0
    cage[0] = theta
    cage[1] = wc
    return max(qmax[0], qmax[1])


class QuasiStaticBearing(LevelBearing):
    """The quasi-static level (module docstring); options of :class:`.base.LevelBearing` and
    ``cageAngle`` (cage angle [rad] at the start: azimuth of ball 0)."""

    model = "quasistatic"

    def __init__(self, *args, cageAngle=0.0, **options):
        self._cage0 = float(cageAngle)
        super().__init__(*args, **options)

    def _setup(self):
        b = self.bearing
        z = b.n_balls
        self._state = np.array([0.0, 0.0, self._cage0])
        self._psi, self._m_w2, self._fto, self._fti = (np.zeros(z) for _ in range(4))
        self._balls = np.zeros((z, NB))
        self._gen = np.zeros(5)
        self._cflat = np.zeros(25)
        c = self.coefficients
        self._speeds = np.array(c.speeds, float)
        t = self.rotation()
        self._ctab = np.ascontiguousarray(np.einsum("ij,njk,lk->nil", t, np.array(c.damping, float), t)
                                          .reshape(-1, 25))
        self._e_prime = _hz.material_reduced_modulus(b.material)
        self._method = _hz.method_code(self.hertzModel)
        self._sin_a0 = math.sin(b.free_contact_angle)
        self._geo_speed = math.nan
        self._update_geometry(abs(self.initialOmega))
        self._first = True
        v3 = np.zeros(3)
        self._kernel = entry_point(level_forces, (
            v3, v3, v3, v3, self._state, self._geo, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, self._speeds, self._ctab,
            self._cflat, self._psi, self._m_w2, self._fto, self._fti, self._balls, self._gen, self._pose, self._out,
            self._force, self._cage, np.zeros(3)))

    def _update_geometry(self, speed):
        """Grooves, ball mass and inertia at ``speed`` (rigid rings: once)."""
        if self._geo_speed == self._geo_speed and (not self.ringGrowth or abs(speed - self._geo_speed)
                                                     <= 0.01 * max(self._geo_speed, 1.0)):
            return
        g = operating_geometry(self.bearing, speed if self.ringGrowth else 0.0, 0.0, self.ringGrowth, 0.0,
                               self.temperatures)
        self.geometry = g
        self._geo = np.array([g.rho_i, g.z_i, g.rho_o, g.z_o, g.r_ci, g.r_co, g.r_b])
        self._mass = self.bearing.ball_mass * (g.r_b / self.bearing.ball_radius) ** 3
        self._inertia = 0.4 * self._mass * g.r_b ** 2
        self._geo_speed = speed

    def _restart(self, t):
        super()._restart(t)
        self._state[:] = [0.0, 0.0, self._cage0]
        self._first = True

    def _evaluate(self, d, r, v, w):
        if self.ringGrowth:
            self._update_geometry(abs(float(w[2])))
        if self._first:  # the spin angle of the first evaluation is the zero of the cage angle
            self._state[0] = r[2]
            self._first = False
        qmax = self._kernel(d, r, v, w, self._state, self._geo, self.cageRatio, self.spinRatio, self._sin_a0,
                            self._mass, self._inertia, self._e_prime, self._method, self._speeds, self._ctab,
                            self._cflat, self._psi, self._m_w2, self._fto, self._fti, self._balls, self._gen,
                            self._pose, self._out, self._force, self._cage, self._qmax)
        if not qmax <= self._q_limit:
            self._check_ball_load(self._t_last, qmax)
        if self._qmax[2] > MAX_FREE_CONTACT_ANGLE:
            from ....model.stability import SimulationError

            raise SimulationError(f"tilt: at t = {self._t_last:.6g} s a loaded contact sits "
                                  f"{math.degrees(self._qmax[2]):.1f} deg from the groove bottom, beyond the "
                                  f"{math.degrees(MAX_FREE_CONTACT_ANGLE):.0f} deg the grooves take (tilt "
                                  f"{math.degrees(math.hypot(self._pose[3], self._pose[4])):.3g} deg, axial "
                                  f"{self._pose[2]:.3g} m); reduce the moment or axial load")

    def _sample_row(self, t):
        b = self._balls
        alpha = np.arctan2(-b[:, B_NIZ], -b[:, B_NIR])
        return np.concatenate([super()._sample_row(t), b[:, B_QI], b[:, B_QO], alpha])

    def _extra_fields(self, rest):
        z = self.bearing.n_balls
        return {"ball_load_inner": rest[:, :z], "ball_load_outer": rest[:, z:2 * z],
                "contact_angle_inner": rest[:, 2 * z:3 * z]}
