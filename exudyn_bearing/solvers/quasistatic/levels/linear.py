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

Validity
--------
A linearisation about (F_r, F_a) cannot represent another load: the
6208 linearised at +3000 N and loaded with -3000 N settles at -8.3 um,
where the bearing puts the ring at -24.7 um (the quasi-static level).
Every evaluation therefore also computes (a few flops in the kernel) how
far the state is from the operating point: the force (F_x, F_y, F_z)
against the operating force -L (more than VALIDITY_DIRECTION = 10 deg
apart, or magnitudes differing by more than VALIDITY_MAGNITUDE = 25 %),
the pose u against u0 (|(u - u0)_xyz, r_p (theta - theta_0)| beyond
VALIDITY_POSE = 25 % of |u0_xyz|, r_p the pitch radius: a moment or an
axial load the operating point did not have moves the pose long before
it moves the force's direction), and the speed |w_z| against the table's
speeds (beyond them by more than 1 % of the top speed: the coefficients
are clamped at the table's ends, not extrapolated). At each sample a
running share of the samples outside (time constant VALIDITY_TIME = 5 ms)
is updated; when it exceeds 1/2 (after 3.5 ms outside: a start transient
from rest passes) the run warns once with a :class:`LinearValidityWarning`
naming what left and model='quasistatic'. ``validity`` says whether and
when the run left, the share of samples outside and the largest
deviations; the samples carry ``validity_flags`` (FLAG_* bits) and the
deviations. The one-speed connector has no user function and no check.
"""
from __future__ import annotations

import math
import warnings

import numpy as np

from ...._jit import kernel
from ....data import InputError
from ....model.load_range import MAX_CONTACT_PRESSURE
from ....model.stability import SimulationError
from ....physics.load_distribution import static_equilibrium
from .base import WS_FORCE, WS_HEADER, WS_OUT, WS_POSE, LevelBearing, entry_point
from .element import _interp_row

__all__ = ["LinearBearing", "LinearValidityWarning", "linear_forces"]


class LinearValidityWarning(UserWarning):
    """A run of the linear level left the operating point it was linearised about (module docstring,
    "Validity"): its forces there are not the bearing's."""


#: Validity of the linearisation (module docstring, "Validity"): the ring force (F_x, F_y, F_z) at most this many
#: rad from the operating load's direction,
VALIDITY_DIRECTION = math.radians(10.0)
#: its magnitude within this share of the operating load's,
VALIDITY_MAGNITUDE = 0.25
#: the pose within this share of the operating displacement |(u0_x, u0_y, u0_z)| of the operating pose u0: the
#: displacement and the tilt at the pitch circle, |(u_x, u_y, u_z, r_p theta_x, r_p theta_y) - (u0 likewise)|,
VALIDITY_POSE = 0.25
#: the speed |w_z| within the table's speeds, give or take this share of the top speed;
VALIDITY_SPEED = 0.01
#: forces below this share of ``forceLimit`` count as zero (no direction; the magnitude's scale at least this)
VALIDITY_FORCE_FLOOR = 1e-4
#: the operating displacement's scale is at least this [m] (an unloaded operating point without clearance)
VALIDITY_DISPLACEMENT_FLOOR = 1e-7
#: time constant [s] of the running share of samples outside: the warning fires when it exceeds 1/2, after
#: ln 2 VALIDITY_TIME = 3.5 ms outside; a shorter start transient passes (the damped test shaft of
#: tests/test_levels.py started from rest under (3000, 1000) N is outside for 1.7 ms:
#: validation/consistency/linear_validity_cases.py)
VALIDITY_TIME = 5e-3

# the linear level's part of the work array (after the header WS_HEADER of .base): the table row interpolated
# at the current speed (K (25), C (25), u0 (5)), the operating loads L (5), the validity limits (|L_xyz|, force
# floor, cos of the direction limit, magnitude limit, r_p, VALIDITY_POSE, displacement floor, lowest and highest
# speed, table size), the validity state of the last evaluation (flags, direction cosine, relative magnitude
# deviation, pose deviation over its limit, |w_z|) and the table's speeds (n)
_ROW = WS_HEADER
_LOADS = _ROW + 55
_LIMITS = _LOADS + 5
_STATE = _LIMITS + 10
_SPEEDS = _STATE + 5
#: bits of the validity flags (samples' ``validity_flags``)
FLAG_MAGNITUDE, FLAG_DIRECTION, FLAG_POSE, FLAG_SPEED = 1, 2, 4, 8


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
    # validity (a few flops): the force F = -out against the operating force -L, the pose against u0, the speed
    lim = ws[_LIMITS:_LIMITS + 10]
    fx = ws[WS_FORCE]
    fy = ws[WS_FORCE + 1]
    fz = ws[WS_FORCE + 2]
    fm = math.sqrt(fx * fx + fy * fy + fz * fz)
    f0 = lim[0]
    mag = abs(fm - f0) / max(f0, lim[1])
    cos = 1.0
    if fm > lim[1] and f0 > lim[1]:
        cos = -(fx * ws[_LOADS] + fy * ws[_LOADS + 1] + fz * ws[_LOADS + 2]) / (fm * f0)
    scale = lim[5] * max(math.sqrt(row[50] * row[50] + row[51] * row[51] + row[52] * row[52]), lim[6])
    pose = math.sqrt((u[0] - row[50]) ** 2 + (u[1] - row[51]) ** 2 + (u[2] - row[52]) ** 2
                     + lim[4] * lim[4] * ((u[3] - row[53]) ** 2 + (u[4] - row[54]) ** 2)) / scale
    speed = abs(w2)
    flags = 0.0
    if mag > lim[3]:
        flags += FLAG_MAGNITUDE
    if cos < lim[2]:
        flags += FLAG_DIRECTION
    if pose > 1.0:
        flags += FLAG_POSE
    if lim[9] > 1.0 and (speed < lim[7] or speed > lim[8]):
        flags += FLAG_SPEED
    ws[_STATE] = flags
    ws[_STATE + 1] = cos
    ws[_STATE + 2] = mag
    ws[_STATE + 3] = pose
    ws[_STATE + 4] = speed


class LinearBearing(LevelBearing):
    """The linear level (module docstring); options of :class:`.base.LevelBearing`. Sensors
    ``innerRingForce``, ``outerRingForce``, ``ringDisplacement``, ``cageSpeed``: no ``qMaxInner`` or
    ``qMaxOuter`` (no ball loads); ``forceLimit`` [N]: the ring force of its validity; ``validity``: whether
    the run stayed near the operating point (module docstring, "Validity")."""

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
        stiff = np.array(c.stiffness)
        if not np.all(np.abs(np.diagonal(stiff, axis1=1, axis2=2)[:, :3]).max(axis=1) > 0.0):
            # an unloaded bearing without clearance: Hertz contacts carry nothing and have no stiffness at zero
            # load, so the linearisation has none (a shaft on it falls through: 3 m in 0.05 s)
            raise InputError(f"initialLoad: the linear level's table at {self.initialLoad} N has no radial or axial "
                             "stiffness at some speed (Hertz contacts have none at zero load); give the operating "
                             "load the rotor puts on the bearing, or use model='quasistatic'")
        k = np.einsum("ij,njk,lk->nil", t, stiff, t)
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
        lim = ws[_LIMITS:_LIMITS + 10]
        f0 = float(np.linalg.norm(self._loads[:3]))
        top, low = float(c.speeds[-1]), float(c.speeds[0])
        lim[:] = [f0, VALIDITY_FORCE_FLOOR * self.forceLimit, math.cos(VALIDITY_DIRECTION), VALIDITY_MAGNITUDE,
                  self.bearing.pitch_radius, VALIDITY_POSE, VALIDITY_DISPLACEMENT_FLOOR,
                  low - VALIDITY_SPEED * top if low > 0.0 else -1.0, top * (1.0 + VALIDITY_SPEED), c.n_speeds]
        self._vstate = ws[_STATE:_STATE + 5]
        self._reset_validity(0.0)
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

    # -- validity (module docstring, "Validity") ------------------------------
    def _reset_validity(self, t):
        self._v_rows = []  # the validity state (flags, cos, magnitude, pose, speed) at each sample
        self._v_share = 0.0  # running share of samples outside (time constant VALIDITY_TIME)
        self._v_last = t
        self._v_left = None  # (t, flags) of the sample at which the run left its validity

    def _restart(self, t):
        super()._restart(t)
        self._reset_validity(t)

    def _sample_row(self, t):
        st = self._vstate
        dt = t - self._v_last
        self._v_last = t
        flags = float(st[0])
        self._v_share += (1.0 - math.exp(-dt / VALIDITY_TIME)) * ((1.0 if flags else 0.0) - self._v_share)
        self._v_rows.append(st.copy())
        if self._v_share > 0.5 and self._v_left is None:
            self._v_left = (t, int(flags))
            warnings.warn(self._validity_message(t, int(flags), st), LinearValidityWarning, stacklevel=2)
        return super()._sample_row(t)

    def _extra_fields(self, rest):
        v = np.array(self._v_rows).reshape(-1, 5)
        return {"validity_flags": v[:, 0].astype(int),
                "force_direction_deviation": np.arccos(np.clip(v[:, 1], -1.0, 1.0)),
                "force_magnitude_deviation": v[:, 2], "pose_deviation": v[:, 3]}

    def _validity_message(self, t, flags, st):
        """The warning of a run that left the operating point (module docstring, "Validity")."""
        lim = self._ws[_LIMITS:_LIMITS + 10]
        f, f0, why = self._force[:3] + 0.0, -self._loads[:3] + 0.0, []
        vec = "({:.4g}, {:.4g}, {:.4g}) N".format
        if flags & FLAG_DIRECTION:
            why.append(f"the bearing's force on the inner ring {vec(*f)} points "
                       f"{math.degrees(math.acos(min(max(st[1], -1.0), 1.0))):.1f} deg away from its force at the "
                       f"operating point {vec(*f0)} (limit {math.degrees(VALIDITY_DIRECTION):g} deg)")
        if flags & FLAG_MAGNITUDE:
            share = f"by {100.0 * st[2]:.0f} % " if lim[0] > lim[1] else ""
            why.append(f"the force's magnitude {np.linalg.norm(f):.4g} N differs from the operating point's "
                       f"{lim[0]:.4g} N {share}(limit {100 * VALIDITY_MAGNITUDE:g} %)")
        if flags & FLAG_POSE:
            why.append(f"the ring pose (x, y, z, tilt_x, tilt_y) = ({', '.join(f'{x:.3g}' for x in self._pose)}) "
                       f"(m, rad) is {st[3] * 100 * VALIDITY_POSE:.3g} % of the operating displacement "
                       f"{max(np.linalg.norm(self._row[50:53]), VALIDITY_DISPLACEMENT_FLOOR):.3g} m away from the "
                       f"operating pose (tilts at the pitch radius; limit {100 * VALIDITY_POSE:g} %)")
        if flags & FLAG_SPEED:
            why.append(f"the speed |w_z| = {st[4]:.4g} rad/s lies outside the coefficient table's "
                       f"{self._speeds[0]:g} to {self._speeds[-1]:g} rad/s, whose end values are used (not "
                       "extrapolated; coefficientSpeeds)")
        return (f"linear: from t = {t:.6g} s the run has left the operating point it is linearised about "
                f"(initialLoad {self.initialLoad} N, loadAngle {self.loadAngle:g} rad): {'; '.join(why)}. The linear "
                "level's forces are not the bearing's there: use model='quasistatic' (or a table at this load and "
                "speed; a start away from the operating point: set the node's initial coordinates to the level's "
                "initialCoordinates)")

    @property
    def validity(self) -> dict:
        """Whether the run so far stayed near the operating point (module docstring, "Validity"): ``left``
        (bool), ``time`` [s] when the warning fired (None), ``flags`` then (FLAG_*), ``outside_share`` (share
        of the samples outside), ``worst``: the largest force direction deviation [rad], relative magnitude
        deviation, pose deviation (1 at the limit) and speed [rad/s] over the samples."""
        rows = np.array(self._v_rows).reshape(-1, 5)
        left = self._v_left
        worst = {"force_direction": float(np.arccos(np.clip(rows[:, 1].min(), -1.0, 1.0))) if len(rows) else 0.0,
                 "force_magnitude": float(rows[:, 2].max(initial=0.0)), "pose": float(rows[:, 3].max(initial=0.0)),
                 "speed": float(rows[:, 4].max(initial=0.0))}
        return {"left": left is not None, "time": None if left is None else left[0],
                "flags": 0 if left is None else left[1],
                "outside_share": float((rows[:, 0] != 0.0).mean()) if len(rows) else 0.0, "worst": worst}

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
