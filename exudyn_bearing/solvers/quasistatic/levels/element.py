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
  when the speed squared moved by more than 2 % plus (10 rad/s)^2: about 1 %
  of the speed); the exact Hertz constants from the tabulated exact solution
  (:func:`exudyn_bearing.physics.hertz.exact_table`) and each ball's Newton
  iteration started from its last solution (:func:`..balls._ball_equilibrium`);
* the damping force -C u' of the balls in their current state
  (:func:`..damping.ring_damping_force`): each loaded ball's normal contact
  damping (hysteretic, squeeze film, switched by Lambda: the contact law of
  the ball element and of :func:`..solve.solve_quasistatic`) at its load,
  overlap and film (Hamrock-Dowson at the rolling speed of the kinematic
  cage), condensed over its two contacts in series as in
  :func:`..damping.condensed_matrices`; no operating point enters, so
  ``initialLoad`` only places the ring (``coefficients`` and
  ``coefficientSpeeds`` only fill ``coefficients``, the linearised table kept
  for reference).

The force F = G(u, psi) - C(u, psi, w_z) u' on the inner ring (G: the balls'
generalized force) is one compiled call. Exudyn's implicit solvers
differentiate the connector numerically for their Jacobian (modified Newton
keeps it; see :meth:`.base.LevelBearing.SimulationSettings` for the
tolerances); the explicit ones call it once per stage.
"""
from __future__ import annotations

import math

import numpy as np

from ...._jit import kernel
from ....data import MAX_FREE_CONTACT_ANGLE, load_lubricant
from ....data.errors import check_finite
from ....model.operating_geometry import operating_geometry
from ....physics import hertz as _hz
from ..balls import B_NIR, B_NIZ, B_QI, B_QO, NB, _ring_forces
from ..damping import ring_damping_force
from .base import WS_CAGE, WS_FORCE, WS_HEADER, WS_OUT, WS_POSE, WS_QMAX, LevelBearing, entry_point

__all__ = ["QuasiStaticBearing", "level_forces"]

_TWO_PI = 2.0 * math.pi
#: Speed [rad/s] below which the ring growth (proportional to the speed squared) is not updated again
GROWTH_SPEED_FLOOR = 10.0


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


# the quasi-static level's part of the work array (after the header WS_HEADER of .base): spin-angle state (3),
# geometry (rho_i, z_i, rho_o, z_o, r_ci, r_co, r_b), constants (k_c, k_r, sin alpha_0, ball mass, ball inertia, E'),
# the contact damping law's (alpha_e, eta, ln(xi E'), composite roughness, Lambda breakpoints), the balls'
# generalized force (5), the pose rates (5), the damping force (5), then per ball psi, m omega_c^2, F_to, F_ti (Z each)
_STATE = WS_HEADER
_GEO = _STATE + 3
_KC, _KR, _SIN_A0, _MASS, _INERTIA, _EPRIME = range(_GEO + 7, _GEO + 13)
_ALPHA_E, _ETA, _LN_G, _SIGMA, _L1, _L3 = range(_GEO + 13, _GEO + 19)
_GEN = _GEO + 19
_RATES = _GEN + 5
_DAMP = _RATES + 5
_BALLS = _DAMP + 5


@kernel
def level_forces(d0, d1, d2, r0, r1, r2, v0, v1, v2, w0, w1, w2, method, ws, table, start, balls):
    """One evaluation of the quasi-static level (module docstring) for the connector's displacement d,
    Tait-Bryan angles r, velocity v and angular velocity w (.base).

    ws: the work array (layout above; state = [last Tait-Bryan spin angle, unwrapped spin angle, cage angle
    at zero spin angle]); table, start: Hertz constants and warm starts of :func:`..balls._ring_forces`; balls
    (Z, NB).
    Writes the header (pose u, ``out`` = -(F, 0), F, cage (angle, speed), q_max = (largest inner and outer
    ball load, largest loaded inner contact angle)) and the balls table; returns the largest ball load."""
    z = balls.shape[0]
    psi = ws[_BALLS:_BALLS + z]
    m_w2 = ws[_BALLS + z:_BALLS + 2 * z]
    fto = ws[_BALLS + 2 * z:_BALLS + 3 * z]
    fti = ws[_BALLS + 3 * z:_BALLS + 4 * z]
    gen = ws[_GEN:_GEN + 5]
    rates = ws[_RATES:_RATES + 5]
    damp = ws[_DAMP:_DAMP + 5]
    u = ws[WS_POSE:WS_POSE + 5]
    kc = ws[_KC]
    dc = r2 - ws[_STATE]
    dc -= _TWO_PI * math.floor(dc / _TWO_PI + 0.5)
    ws[_STATE] = r2
    ws[_STATE + 1] += dc
    wc = kc * w2
    theta = ws[_STATE + 2] + kc * ws[_STATE + 1]
    g = ws[_INERTIA] * wc * (-ws[_KR] * w2 * ws[_SIN_A0]) / ws[_GEO + 6]
    for j in range(z):
        psi[j] = theta + _TWO_PI * j / z
        m_w2[j] = ws[_MASS] * wc * wc
        fto[j] = g
        fti[j] = 0.0
    u[0] = d0
    u[1] = d1
    u[2] = d2
    u[3] = r0
    u[4] = r1
    _ring_forces(u, psi, ws[_GEO], ws[_GEO + 1], ws[_GEO + 2], ws[_GEO + 3], ws[_GEO + 4], ws[_GEO + 5],
                 ws[_GEO + 6], m_w2, fto, fti, ws[_EPRIME], method, table, start, balls, gen)
    rates[0] = v0
    rates[1] = v1
    rates[2] = v2
    rates[3] = w0 - w2 * r1
    rates[4] = w1 + w2 * r0
    ring_damping_force(rates, psi, ws[_GEO], ws[_GEO + 1], ws[_GEO + 2], ws[_GEO + 3], ws[_GEO + 4], ws[_GEO + 5],
                       ws[_GEO + 6], balls, m_w2, fto, fti, wc, w2, ws[_EPRIME], method, table, ws[_ALPHA_E],
                       ws[_ETA], ws[_LN_G], ws[_SIGMA], ws[_L1], ws[_L3], damp)
    q_in = 0.0
    q_out = 0.0
    alpha = 0.0
    for j in range(z):
        q_in = max(q_in, balls[j, B_QI])
        q_out = max(q_out, balls[j, B_QO])
        if balls[j, B_QI] > 0.0:  # contact angle from the groove bottom, inner race
            alpha = max(alpha, abs(math.atan2(-balls[j, B_NIZ], -balls[j, B_NIR])))
    ws[WS_QMAX] = q_in
    ws[WS_QMAX + 1] = q_out
    ws[WS_QMAX + 2] = alpha
    for i in range(5):
        ws[WS_OUT + i] = -gen[i] - damp[i]
        ws[WS_FORCE + i] = gen[i] + damp[i]
    ws[WS_OUT + 5] = 0.0
    ws[WS_CAGE] = theta
    ws[WS_CAGE + 1] = wc
    return max(q_in, q_out)


class QuasiStaticBearing(LevelBearing):
    """The quasi-static level (module docstring); options of :class:`.base.LevelBearing` and
    ``cageAngle`` (cage angle [rad] at the start: azimuth of ball 0)."""

    model = "quasistatic"

    def __init__(self, *args, cageAngle=0.0, **options):
        self._cage0 = check_finite("cageAngle", cageAngle)
        super().__init__(*args, **options)

    def _workspace_size(self):
        return _BALLS - WS_HEADER + 4 * self.bearing.n_balls

    def _setup(self):
        b = self.bearing
        z = b.n_balls
        ws = self._ws
        self._state = ws[_STATE:_STATE + 3]
        self._state[2] = self._cage0
        self._geo = ws[_GEO:_GEO + 7]
        self._psi, self._m_w2, self._fto, self._fti = (ws[_BALLS + k * z:_BALLS + (k + 1) * z] for k in range(4))
        self._gen = ws[_GEN:_GEN + 5]
        self._damp = ws[_DAMP:_DAMP + 5]
        self._balls = np.zeros((z, NB))
        self._start = np.zeros((z, 3))  # the balls' warm starts (balls._ball_equilibrium)
        self._hz_table = _hz.exact_table()
        self._e_prime = ws[_EPRIME] = _hz.material_reduced_modulus(b.material)
        # the contact damping law's parameters: the lubricant solve_quasistatic takes (None: the bearing's)
        lub = load_lubricant(self.lubricant, bearing=b)
        ws[_ALPHA_E], ws[_ETA], ws[_SIGMA] = b.material.hysteretic_damping, lub.viscosity, lub.composite_roughness
        g = lub.pressure_viscosity * self._e_prime
        ws[_LN_G] = math.log(g) if g > 0.0 else -math.inf  # xi = 0: no film (ehl.film_thickness_hamrock_dowson)
        ws[_L1], ws[_L3] = lub.lambda_mixed, lub.lambda_full_film
        self._method = _hz.method_code(self.hertzModel)
        ws[_KC], ws[_KR], ws[_SIN_A0] = self.cageRatio, self.spinRatio, math.sin(b.free_contact_angle)
        self._geo_band = (math.inf, -math.inf)
        self._update_geometry(abs(self.initialOmega))
        self._first = True
        self._kernel = entry_point(level_forces, (*[0.0] * 12, self._method, ws, self._hz_table, self._start,
                                                  self._balls))

    def _update_geometry(self, speed):
        """Grooves, ball mass and inertia at ``speed`` (rigid rings: once; growing rings, whose growth goes with
        the speed squared: again when the speed squared left the band of 2 % plus (GROWTH_SPEED_FLOOR)^2 about
        the last one, about 1 % of the speed well above the floor)."""
        lo, hi = self._geo_band
        if lo <= speed <= hi:
            return
        g = operating_geometry(self.bearing, speed if self.ringGrowth else 0.0, 0.0, self.ringGrowth, 0.0,
                               self.temperatures)
        self.geometry = g
        self._geo[:] = [g.rho_i, g.z_i, g.rho_o, g.z_o, g.r_ci, g.r_co, g.r_b]
        self._mass = self._ws[_MASS] = self.bearing.ball_mass * (g.r_b / self.bearing.ball_radius) ** 3
        self._inertia = self._ws[_INERTIA] = 0.4 * self._mass * g.r_b ** 2
        band = 0.02 * speed * speed + GROWTH_SPEED_FLOOR ** 2
        self._geo_band = (math.sqrt(max(speed * speed - band, 0.0)) if speed * speed > band else -math.inf,
                          math.sqrt(speed * speed + band)) if self.ringGrowth else (-math.inf, math.inf)

    def _restart(self, t):
        super()._restart(t)
        self._state[:] = [0.0, 0.0, self._cage0]
        self._start[:] = 0.0
        self._first = True

    def _evaluate(self, d, r, v, w):
        speed = abs(w[2])
        lo, hi = self._geo_band
        if not lo <= speed <= hi:
            self._update_geometry(speed)
        if self._first:  # the spin angle of the first evaluation is the zero of the cage angle
            self._state[0] = r[2]
            self._first = False
        qmax = self._kernel(d[0], d[1], d[2], r[0], r[1], r[2], v[0], v[1], v[2], w[0], w[1], w[2], self._method,
                            self._ws, self._hz_table, self._start, self._balls)
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
