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
  iteration started from its last solution moved to first order with its inner groove centre, a ball outside
  the load zone kept without an iteration while its inner contact stays open (:func:`..balls._ball_equilibrium`);
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
generalized force) is one compiled call. With ``formulation="connector"``
Exudyn's implicit solvers differentiate the connector numerically for their
Jacobian (modified Newton keeps it; see
:meth:`.base.LevelBearing.SimulationSettings` for the tolerances); the node
formulation (:mod:`.nodes`, the default where the markers allow it) has the
same call return the balls' K and C for a Jacobian at every step. The
explicit solvers call it once per stage.
"""
from __future__ import annotations

import math

import numpy as np

from ...._jit import kernel
from ....data import MAX_FREE_CONTACT_ANGLE, load_lubricant
from ....data.errors import check_finite
from ....model.operating_geometry import operating_geometry
from ....physics import hertz as _hz
from ..balls import B_NIR, B_NIZ, B_QI, B_QO, NB, WARM_START, _ring_forces
from ..damping import ring_damping_force
from .base import (SAMPLE_HEADER, WS_CAGE, WS_FORCE, WS_HEADER, WS_OUT, WS_POSE, WS_QMAX, LevelBearing,
                   entry_point, sample_header)
from .nodes import (N_BAND, N_CONN, N_FIXED, N_LOCAL, N_MATS, N_OFFS, N_QLIMIT, N_QMAX, N_REFS, N_SHARE, NodeGroup,
                    check_formulation, node_force, node_formulation_markers, node_kinematics, refuse_node)

__all__ = ["QuasiStaticBearing", "group_level_forces", "level_forces", "node_level_forces"]

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
# generalized force (5), the pose rates (5), the damping force (5), then per ball psi, m omega_c^2, F_to, F_ti,
# cos psi, sin psi (Z each)
_STATE = WS_HEADER
_GEO = _STATE + 3
_KC, _KR, _SIN_A0, _MASS, _INERTIA, _EPRIME = range(_GEO + 7, _GEO + 13)
_ALPHA_E, _ETA, _LN_G, _SIGMA, _L1, _L3 = range(_GEO + 13, _GEO + 19)
_GEN = _GEO + 19
_RATES = _GEN + 5
_DAMP = _RATES + 5
_BALLS = _DAMP + 5


@kernel(no_runtime=True)
def level_forces(d0, d1, d2, r0, r1, r2, v0, v1, v2, w0, w1, w2, method, ws, table, start, balls, mats):
    """One evaluation of the quasi-static level (module docstring) for the connector's displacement d,
    Tait-Bryan angles r, velocity v and angular velocity w (.base).

    ws: the work array (layout above; state = [last Tait-Bryan spin angle, unwrapped spin angle, cage angle
    at zero spin angle]); table, start: Hertz constants and warm starts of :func:`..balls._ring_forces`; balls
    (Z, NB); mats: size 50 for the stiffness K = -dG/du and damping C of the balls' current state as well
    (:func:`..damping.ring_damping_force`; the node formulation's Jacobian), size 0 for the force alone.
    Writes the header (pose u, ``out`` = -(F, 0), F, cage (angle, speed), q_max = (largest inner and outer
    ball load, largest loaded inner contact angle)) and the balls table; returns the largest ball load."""
    z = balls.shape[0]
    psi = ws[_BALLS:_BALLS + z]
    m_w2 = ws[_BALLS + z:_BALLS + 2 * z]
    fto = ws[_BALLS + 2 * z:_BALLS + 3 * z]
    fti = ws[_BALLS + 3 * z:_BALLS + 4 * z]
    cos_psi = ws[_BALLS + 4 * z:_BALLS + 5 * z]
    sin_psi = ws[_BALLS + 5 * z:_BALLS + 6 * z]
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
                 ws[_GEO + 6], m_w2, fto, fti, ws[_EPRIME], method, table, start, balls, gen, cos_psi, sin_psi)
    rates[0] = v0
    rates[1] = v1
    rates[2] = v2
    rates[3] = w0 - w2 * r1
    rates[4] = w1 + w2 * r0
    ring_damping_force(rates, cos_psi, sin_psi, ws[_GEO], ws[_GEO + 1], ws[_GEO + 2], ws[_GEO + 3], ws[_GEO + 4],
                       ws[_GEO + 5], ws[_GEO + 6], balls, m_w2, fto, fti, wc, w2, ws[_EPRIME], method, table,
                       ws[_ALPHA_E], ws[_ETA], ws[_LN_G], ws[_SIGMA], ws[_L1], ws[_L3], damp, mats)
    q_in = 0.0
    q_out = 0.0
    alpha = 0.0
    steep = -1.0
    j_steep = 0
    for j in range(z):
        q_in = max(q_in, balls[j, B_QI])
        q_out = max(q_out, balls[j, B_QO])
        if balls[j, B_QI] > 0.0:  # contact angle from the groove bottom, inner race: |atan2(-n_z, -n_r)|
            # ranked by 1 - x / (|x| + |y|) (x = -n_r, y = -n_z), which grows with |atan2(y, x)| over [0, pi]:
            # one atan2 for the largest
            x = -balls[j, B_NIR]
            key = 1.0 - x / (abs(x) + abs(balls[j, B_NIZ]))
            if key > steep:
                steep = key
                j_steep = j
    if steep >= 0.0:
        alpha = abs(math.atan2(-balls[j_steep, B_NIZ], -balls[j_steep, B_NIR]))
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


@kernel(no_runtime=True)
def node_level_forces(q, qt, nws, method, ws, table, start, balls, gen):
    """One evaluation of a bearing in the node formulation: :func:`.nodes.node_kinematics`, the level's
    :func:`level_forces` (with K and C, into the node work array ``nws``), the generalized force of its f
    (:func:`.nodes.node_force`) into the bearing's share, added to ``gen``. Returns the largest ball load."""
    node_kinematics(q, qt, nws)
    conn = nws[N_CONN:N_CONN + 12]
    qmax = level_forces(conn[0], conn[1], conn[2], conn[3], conn[4], conn[5], conn[6], conn[7], conn[8], conn[9],
                        conn[10], conn[11], method, ws, table, start, balls, nws[N_MATS:N_MATS + 50])
    share = nws[N_SHARE:]
    for k in range(share.size):
        share[k] = 0.0
    node_force(ws[WS_OUT:WS_OUT + 6], nws, share)
    for k in range(share.size):
        gen[k] += share[k]
    return qmax


@kernel(no_runtime=True)
def group_level_forces(qq, gen, table, methods, nwss, wss, starts, ballss):
    """:func:`node_level_forces` for each bearing of a node group (the tuples: their arguments; ``qq``: the
    object's coordinates q and then their rates q_t, each of the length of ``gen``), ``gen`` their summed
    generalized force: one compiled call per evaluation for all. Each bearing's largest ball load goes to
    its node work array (N_QMAX). Returns True where a bearing needs the steps after the kernel
    (:meth:`QuasiStaticBearing._node_after`): its relative speed left the band of its grooves' last update
    (N_BAND), a ball load is beyond its limit (N_QLIMIT) or not a number, or a loaded contact sits beyond
    MAX_FREE_CONTACT_ANGLE."""
    for k in range(gen.size):
        gen[k] = 0.0
    q = qq[:gen.size]
    qt = qq[gen.size:]
    more = False
    for i in range(len(nwss)):
        nws = nwss[i]
        ws = wss[i]
        qmax = node_level_forces(q, qt, nws, methods[i], ws, table, starts[i], ballss[i], gen)
        nws[N_QMAX] = qmax
        w = abs(nws[N_CONN + 11])
        if not (nws[N_BAND] <= w <= nws[N_BAND + 1] and qmax <= nws[N_QLIMIT]) \
                or ws[WS_QMAX + 2] > MAX_FREE_CONTACT_ANGLE:
            more = True
    return more


@kernel(no_runtime=True)
def sample_row(t, ws, balls, row):
    """The level's sample row (:meth:`QuasiStaticBearing._sample_row`): the common part (:func:`.base.sample_header`),
    then per ball the inner and outer load and (-n_z, -n_r) of the inner contact's normal, whose angle (the contact
    angle from the groove bottom) :meth:`QuasiStaticBearing._extra_fields` takes when the samples are read."""
    sample_header(t, ws, row)
    z = balls.shape[0]
    for j in range(z):
        row[SAMPLE_HEADER + j] = balls[j, B_QI]
        row[SAMPLE_HEADER + z + j] = balls[j, B_QO]
        row[SAMPLE_HEADER + 2 * z + j] = -balls[j, B_NIZ]
        row[SAMPLE_HEADER + 3 * z + j] = -balls[j, B_NIR]


class QuasiStaticBearing(LevelBearing):
    """The quasi-static level (module docstring); options of :class:`.base.LevelBearing`,
    ``cageAngle`` (cage angle [rad] at the start: azimuth of ball 0) and ``formulation`` (the Exudyn object:
    "connector", an ObjectConnectorRigidBodySpringDamper between the markers with Exudyn's numerical Jacobian;
    "node", an ObjectGenericODE2 on the ring nodes, shared by the bearings between the same nodes, with the
    level's own Jacobian every step (:mod:`.nodes`); "auto" (default): "node" where the markers allow it (ground,
    or a RigidBody with a NodeRigidBodyRxyz node), else "connector"). ``formulationUsed`` says which."""

    model = "quasistatic"

    def __init__(self, *args, cageAngle=0.0, formulation="auto", **options):
        self._cage0 = check_finite("cageAngle", cageAngle)
        self.formulation = check_formulation(formulation)
        super().__init__(*args, **options)

    def _add_object(self, mbs, show):
        rings = [node_formulation_markers(mbs, m) for m in (self.markers[1], self.markers[0])]  # outer, inner
        why = next(((r, w) for r, w in zip(rings, ("markerOuterRing", "markerInnerRing")) if isinstance(r, str)),
                   None)
        if why is None and rings[0][0] == rings[1][0]:
            why = (f"both ring markers sit on {'ground' if rings[0][0] < 0 else f'node {rings[0][0]}'}",
                   "markerOuterRing")
        if self.formulation == "connector" or (why is not None and self.formulation == "auto"):
            self.formulationUsed = "connector"
            self._mats = np.zeros(0)
            return super()._add_object(mbs, show)
        if why is not None:
            raise refuse_node(*why)
        group = NodeGroup.of(mbs, tuple(sorted({r[0] for r in rings if r[0] >= 0})))
        self.formulationUsed = "node"
        self._group = group
        nws = self._nws = np.zeros(N_SHARE + 6 * len(group.nodes))
        for i, (node, local, fixed) in enumerate(rings):
            nws[N_OFFS + i] = group.offset(node)
            if node >= 0:
                nws[N_REFS + 6 * i:N_REFS + 6 * i + 6] = mbs.GetNode(node)["referenceCoordinates"]
            nws[N_LOCAL + 3 * i:N_LOCAL + 3 * i + 3] = local
            nws[N_FIXED + 12 * i:N_FIXED + 12 * i + 12] = fixed
        nws[N_BAND:N_BAND + 2] = self._geo_band
        nws[N_QLIMIT] = self._q_limit
        self._conn = nws[N_CONN:N_CONN + 12]
        self._mats = nws[N_MATS:N_MATS + 50]
        self._share = nws[N_SHARE:]
        self._mats_ready = False
        q0 = np.zeros(6 * len(group.nodes))
        self._node_kinematics = entry_point(node_kinematics, (q0, q0, nws))
        #: the node kernel's arguments after the coordinates (all but ``gen``)
        self._node_args = (nws, self._method, self._ws, self._hz_table, self._start, self._balls)
        self._node_kernel = entry_point(node_level_forces, (q0, q0, *self._node_args, q0))
        group.kernel = group_level_forces
        group.add(self)
        return group.object

    def _node_evaluation(self, t, q, q_t, gen):
        """One evaluation of the node formulation (:mod:`.nodes`) for this bearing alone: the connector's
        quantities from the nodes' coordinates, the level's evaluation and its generalized force, added to ``gen``,
        in one compiled call (:func:`node_level_forces`), with the steps of the connector's :meth:`_evaluate`
        around it (:meth:`_node_before`, :meth:`_node_after`). The group's force call makes the same evaluation
        for all its bearings in one compiled call (:func:`group_level_forces`)."""
        self._node_before(t, q, q_t)
        self._nws[N_QMAX] = self._node_kernel(q, q_t, *self._node_args, gen)
        self._node_after(q, q_t, gen)
        if t >= self._next_sample - 1e-12:
            self._end(t)
        self._mats_ready = True

    def _node_before(self, t, q, q_t):
        """Before the node kernel: a new run starts over (:meth:`.base.LevelBearing._begin`); the first
        evaluation's spin angle is the cage angle's zero."""
        self._begin(t)
        if self._first:
            c = self._conn
            self._node_kinematics(q, q_t, self._nws)
            self._prepare(abs(c[11]), c[5])

    def _node_after(self, q, q_t, gen):
        """After the node kernel (its largest ball load in the node work array): where the speed left the band of
        the grooves' last update, the evaluation again with the grooves at this speed; then the checks of the
        ball loads and contact angles (:meth:`_check`)."""
        c = self._conn
        lo, hi = self._geo_band
        qmax = float(self._nws[N_QMAX])
        if not lo <= abs(c[11]) <= hi:
            gen -= self._share
            self._prepare(abs(c[11]), c[5])
            qmax = self._node_kernel(q, q_t, *self._node_args, gen)
        if not qmax <= self._q_limit or self._qmax[2] > MAX_FREE_CONTACT_ANGLE:
            self._check(qmax)

    def SimulationSettings(self, endTime, stepSize=1e-4, solverType="GeneralizedAlpha"):
        """:meth:`.base.LevelBearing.SimulationSettings`; with the node formulation also Newton's Jacobian
        recomputed at every step (``modifiedNewtonJacUpdatePerStep``: the level's own Jacobian, :mod:`.nodes`)."""
        ss = super().SimulationSettings(endTime, stepSize=stepSize, solverType=solverType)
        if self.formulationUsed == "node":
            ss.timeIntegration.newton.modifiedNewtonJacUpdatePerStep = True
        return ss

    def _workspace_size(self):
        return _BALLS - WS_HEADER + 6 * self.bearing.n_balls

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
        self._start = np.zeros((z, WARM_START))  # the balls' warm starts (balls._ball_equilibrium)
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
        if getattr(self, "formulation", "connector") == "connector":
            self._mats = np.zeros(0)  # K and C only for the node formulation's Jacobian (.nodes)
        else:  # "node" or "auto": sized now, the kernel's argument types do not change
            self._mats = np.zeros(50)
        self._sampler = entry_point(sample_row, (0.0, ws, self._balls, np.empty(SAMPLE_HEADER + 4 * z)))
        self._kernel = entry_point(level_forces, (*[0.0] * 12, self._method, ws, self._hz_table, self._start,
                                                  self._balls, self._mats))

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
        nws = getattr(self, "_nws", None)
        if nws is not None:  # the node formulation's compiled check of the band (group_level_forces)
            nws[N_BAND:N_BAND + 2] = self._geo_band

    def _restart(self, t):
        super()._restart(t)
        self._state[:] = [0.0, 0.0, self._cage0]
        self._start[:] = 0.0
        self._first = True

    def _evaluate(self, d, r, v, w):
        self._prepare(abs(w[2]), r[2])
        qmax = self._kernel(d[0], d[1], d[2], r[0], r[1], r[2], v[0], v[1], v[2], w[0], w[1], w[2], self._method,
                            self._ws, self._hz_table, self._start, self._balls, self._mats)
        self._check(qmax)

    def _prepare(self, speed, spin_angle):
        """Before the kernel: the grooves at this speed (:meth:`_update_geometry`), and the first evaluation's spin
        angle as the zero of the cage angle."""
        lo, hi = self._geo_band
        if not lo <= speed <= hi:
            self._update_geometry(speed)
        if self._first:
            self._state[0] = spin_angle
            self._first = False

    def _check(self, qmax):
        """After the kernel: the ball loads within the elastic limit, the contacts within the grooves."""
        if not qmax <= self._q_limit:
            self._check_ball_load(self._t_last, qmax)
        if self._qmax[2] > MAX_FREE_CONTACT_ANGLE:
            from ....model.stability import SimulationError

            raise SimulationError(f"tilt: at t = {self._t_last:.6g} s a loaded contact sits "
                                  f"{math.degrees(self._qmax[2]):.1f} deg from the groove bottom, beyond the "
                                  f"{math.degrees(MAX_FREE_CONTACT_ANGLE):.0f} deg the grooves take (tilt "
                                  f"{math.degrees(math.hypot(self._pose[3], self._pose[4])):.3g} deg, axial "
                                  f"{self._pose[2]:.3g} m); reduce the moment or axial load, or hold the shaft's tilt (a single "
                                  "angular-contact bearing under a radial and an axial load tilts until a contact "
                                  "passes the shoulder; operatingTilt='held' assumes other supports hold it)")

    def _sample_row(self, t):
        row = np.empty(SAMPLE_HEADER + 4 * self.bearing.n_balls)
        self._sampler(t, self._ws, self._balls, row)
        return row

    def _extra_fields(self, rest):
        z = self.bearing.n_balls
        return {"ball_load_inner": rest[:, :z], "ball_load_outer": rest[:, z:2 * z],
                "contact_angle_inner": np.arctan2(rest[:, 2 * z:3 * z], rest[:, 3 * z:4 * z])}
