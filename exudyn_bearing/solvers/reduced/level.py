"""The reduced engine as a level of :func:`exudyn_bearing.CreateBallBearing` (``model="reduced"``,
docs/theory/levels.md#reduced-level): the balls' skidding and the rigid cage's motion inside an Exudyn rotor model,
at a step near the rotor's, without ball bodies.

A staggered scheme:

1. **Inside Exudyn's Newton iteration** the level is an ``ObjectConnectorRigidBodySpringDamper`` between the ring
   markers (marker 0 the outer ring, the joint frame its frame, the bearing axis its z; the connector's quantities
   as the other levels', :mod:`exudyn_bearing.solvers.quasistatic.levels.base`). Its force on the rings is a
   function of the inner ring's displacement d and velocity v relative to the outer ring and of the relative spin
   w_z, with the balls' *slow states* frozen at the last Exudyn step t_n: orbital angles and speeds, the balls'
   angular velocities and the rigid cage's state. Each ball centre is solved on its normal force balance at the
   proposed ring pose (:func:`.coupled.frozen_ring_force`: the reduced engine's own balance,
   :func:`.stepper._balance`, over the shared contact kernel), its rate (q - q_n) / h; the force is the sum of the
   balls' contact forces on the inner ring, and the moment about the axis their friction torque.
2. **After each converged Exudyn step** (Exudyn's ``PostStepUserFunction``) the slow states advance from t_n to
   t_{n+1} by the reduced engine's linearly implicit BDF2 step (:func:`.stepper.run_reduced`, the ring not free),
   with the inner ring held at Exudyn's converged relative pose and velocity of t_{n+1} and its spin at the
   converged w_z, in ``k`` equal steps (the Exudyn step divided so that none exceeds ``reducedStep``).

The approximation is the lag: the Exudyn step t_n -> t_{n+1} sees the balls' speeds and angles and the cage of
t_n. The level measures it at every step (:meth:`ReducedBearing.check_lag`: the ring force Exudyn used against
the force at the same pose with the slow states advanced) and warns above :data:`LAG_FORCE_WARNING`; the balls'
slip relaxation time (:meth:`ReducedBearing.slip_time`, about 1.3 us on the 6208) is far below any rotor step,
which the reduced engine's implicit step allows, so it is reported, not used as the check.

What it leaves out: the inner ring's tilt relative to the outer ring (the reduced engine holds it): the level's
moments about x and y are zero, and a relative tilt above ``tiltWarning`` (default :data:`TILT_WARNING`) warns
once naming ``tilt``; the outer ring's own spin (the reduced engine refuses ``omega_outer``; the level works in
the outer ring's frame and leaves out the frame's rotation).
"""
from __future__ import annotations

import math
import time
import warnings

import numpy as np

from ...data import InputError, load_bearing
from ...data.errors import check_positive
from ...model.layout import (
    D_LOAD,
    HIST_N,
    NDIAG,
    NGLOBAL,
    P_FA,
    P_FR,
    P_T_DOWN,
    P_T_STEADY,
    P_T_UP,
    P_W_MAX,
    P_W_OUTER,
)
from ...model.level_items import (
    check_solver,
    level_settings,
    marker_start_rotation,
    rigid_marker,
    sensor_function,
    world_initial_coordinates,
)
from ...model.load_angle import check_load_angle, load_rotation
from ...model.motion import ring_poses
from ...model.record import RunRecord
from ...model.solver_types import settings_solver
from ...model.stability import SimulationError
from . import stepper as _st
from .coupled import frozen_ring_force
from .engine import BALANCE_TOL, MAX_ITER, MAX_STEP, ReducedEngine

#: The balance's tolerance [m] inside Exudyn's Newton iteration: the balance leaves out a centre's last correction
#: below its tolerance (stepper._balance_sampled), so the ring force it returns carries up to K tol of the
#: balance's history (the kept Jacobians); Exudyn differentiates the connector numerically over perturbations of
#: about 1e-9 m, where BALANCE_TOL's K tol (1e-4 to 1e-3 N) spoilt its Newton (step reductions) and made a turned
#: scene differ by 1e-5 (tests/test_levels_reduced.py). A thousandth of it keeps that share below 1e-6.
LEVEL_BALANCE_TOL = 1e-3 * BALANCE_TOL

__all__ = ["LAG_FORCE_WARNING", "TILT_WARNING", "ReducedBearing"]

#: Relative tilt [rad] of the inner ring above which the level warns (once per run) that it leaves the tilt out:
#: 1e-4 rad moves the inner groove axially by 1e-4 x the pitch radius at the ball set's edge (3.0 um on the 6208,
#: an eighth of the 24.7 um its inner ring moves under 3000 N, docs/theory/levels.md).
TILT_WARNING = 1e-4
#: The lag's share of the ring force (:meth:`ReducedBearing.check_lag`: the force Exudyn's step used, with the slow
#: states of the step's start, against the force at the same ring pose with the slow states advanced) above which
#: the level warns (once per run) that the slow states' lag of one step is not small. On the 6208 radial (3000 N,
#: 500 rad/s) the largest share after the start was 0.76 % at 20 us, 2.5 % at 100 us and at 200 us with the steady
#: state within the criteria of issue 37 (validation/consistency/reduced_level.py); 5 % is twice the largest seen.
LAG_FORCE_WARNING = 0.05


def check_reduced_step(value):
    """``reducedStep`` [s]: None (one reduced step per Exudyn step, at most MAX_STEP) or a positive step up to
    MAX_STEP, the largest step the reduced engine's checks ran; else InputError naming it."""
    if value is None:
        return None
    value = check_positive("reducedStep", value)
    if value > MAX_STEP:
        raise InputError(f"reducedStep: {value:g} s is above the largest step the reduced engine's checks ran, "
                         f"{MAX_STEP:g} s (docs/theory/reduced.md)")
    return value


class ReducedBearing:
    """The reduced level between two ring markers (module docstring). Built by
    :func:`exudyn_bearing.CreateBallBearing` with ``model="reduced"`` from a validated ``scenario`` (the ball
    element's options, its ``dt`` the largest reduced-engine step, its ``sample_dt`` the sample interval) and the
    quasi-static ``start``.

    Attributes: ``engine`` (the :class:`~.engine.ReducedEngine` of the scene, its parameters and work counters),
    ``object`` (the connector), ``sensors`` (``innerRingForce``, ``outerRingForce`` (world frame),
    ``ringDisplacement``, ``cageSpeed``, ``qMaxInner``, ``qMaxOuter``; the last three at the last sample),
    ``initialCoordinates``, ``loadAngle``, ``record()`` (the samples as a
    :class:`~exudyn_bearing.model.record.RunRecord`, ``results()`` in :func:`exudyn_bearing.CreateBallBearing`).
    """

    model = "reduced"
    ballLoads = True

    def __init__(self, mbs, bearing, markerInnerRing, markerOuterRing, scenario, lubricant=None, start=None,
                 loadAngle=0.0, reducedStep=None, tiltWarning=TILT_WARNING, show=False):
        self.mbs = mbs
        self.markers = (rigid_marker(mbs, markerInnerRing, "markerInnerRing"),
                        rigid_marker(mbs, markerOuterRing, "markerOuterRing"))
        if self.markers[0] == self.markers[1]:
            raise InputError(f"markerOuterRing: marker {markerOuterRing} is also markerInnerRing")
        #: the outer ring's world rotation at t = 0 (initialCoordinates turns its frame's pose by it)
        self._outer_rotation = marker_start_rotation(mbs, self.markers[1])
        self.loadAngle = check_load_angle(loadAngle)
        #: the largest reduced-engine step [s] (None: one step per Exudyn step, at most MAX_STEP)
        self.reducedStep = check_reduced_step(reducedStep)
        self.tiltWarning = check_positive("tiltWarning", tiltWarning)
        self.engine = eng = ReducedEngine(load_bearing(bearing), scenario, lubricant, start=start)
        self.bearing, self.scenario, self.lubricant = eng.bearing, eng.scenario, eng.lubricant
        self.sampleInterval = self.scenario.sample_dt
        self.cage_free = self.scenario.cage == "rigid"
        self._initial = self._turned_state(eng.initial_state())
        ring = self._initial["ring"]
        #: inner-ring pose (d_x, d_y, d_z, theta_x, theta_y) of the start (outer-ring frame), as the other levels'
        self.initialRingDisplacement = np.array([ring[0], ring[1], ring[2], 0.0, 0.0])
        self._add_items(mbs, show)
        self._run = None
        self._reset(0.0)

    # -- the state --------------------------------------------------------------------------------------------------
    def _turned_state(self, st):
        """The engine's initial state with the radial load along ``loadAngle`` instead of +x (turned about z)."""
        a = self.loadAngle
        if a == 0.0:
            return st
        rz = load_rotation(a)
        st["phi"] = st["phi"] + a
        ring = st["ring"].copy()
        ring[:3], ring[3:] = rz @ ring[:3], rz @ ring[3:]
        st["ring"] = ring
        if self.cage_free:
            st["xc"][0] = rz @ st["xc"][0]
            st["vc"][0] = rz @ st["vc"][0]
            st["xc"][1, 0] += a
        return st

    def _reset(self, t):
        """The slow states at the start of a run (time t)."""
        st = self._initial
        z = self.bearing.n_balls
        self.p = self.engine.params.copy()
        p = self.p
        # the inner ring's spin is Exudyn's: a constant protocol speed set at every call; loads are the model's
        p[P_T_UP] = 0.0
        p[P_T_STEADY] = 1e300
        p[P_T_DOWN] = 0.0
        p[P_W_OUTER] = 0.0
        p[P_FR] = 0.0
        p[P_FA] = 0.0
        p[P_W_MAX] = self.scenario.omega
        self.phi, self.om, self.wo = st["phi"].copy(), st["om"].copy(), st["wo"].copy()
        self.q = st["q"].copy()
        self.q_old = self.q.copy()
        self.qd = np.zeros((z, 2))  # the centres' rates at the last balance's start (run_reduced: their inertia)
        self.ring = st["ring"].copy()
        self.hz = st["hz"].copy()
        if self.cage_free:
            self.xc, self.vc = st["xc"].copy(), st["vc"].copy()
        else:
            self.xc, self.vc = np.zeros((z, 3)), np.zeros((z, 3))
        self.wb, self.xb, self.vb = np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((z, 3))
        self.fb, self.tb, self.fc = np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((z, 3))
        self.fr, self.fring = np.zeros((2, 6)), np.zeros(3)
        self.hist = np.zeros((z, HIST_N, 3))
        self.rings = ring_poses()
        self.glob = np.zeros(NGLOBAL)
        self.diag, self.cage_load = np.zeros((z, 2, NDIAG)), np.zeros((z, 2))
        self.prev, self.ring_prev, self.cage_prev = np.zeros((z, 5)), np.zeros(6), np.zeros(_st.N_CAGE)
        self.engine.work[:] = 0.0
        self.adapt = np.zeros(_st.N_ADAPT)  # tolerance 0: the fixed step
        self.ys = np.zeros((3, _st.state_count(z)))
        self.h_log = np.zeros(0)
        # the evaluations' own copies: the centres' trial positions, their balance's Jacobians, the ring, caches
        self.q_trial = self.q.copy()
        self.g = np.zeros((z, 2, 2))
        self.fresh = True
        self.ring_trial = self.ring.copy()
        self.rings_trial = ring_poses()
        self.hz_trial = self.hz.copy()
        self.p_trial = p.copy()
        self.work_trial = np.zeros(_st.N_WORK)
        self.out6 = np.zeros(6)
        self._used = np.zeros(6)  # the force of the last evaluation (the converged pose's at a step's end)
        #: the largest and the mean lag share of the ring force over the run's steps (check_lag) and the step
        #: of the largest
        self.lagForceMax, self._lag_sum, self._lag_n, self.lagForceMaxTime = 0.0, 0.0, 0, None
        #: the lag share of the first step (the start's own relaxation, check_lag)
        self.lagForceStart = None
        self._out = np.zeros(6)  # the connector's f = -(F, M)
        self._t_slow = t
        self._h_last = None
        # the centres on their balance at the start's ring pose (a start from another hypothesis, the analytic
        # one, is not on it): the evaluations' centre rates (q - q_n) / h then start from rest
        self.ring_trial[:] = self.ring
        frozen_ring_force(t, MAX_STEP, self.p_trial, self.engine.table, self.phi, self.om, self.wo,
                          self.q_trial, self.q, self.ring_trial, self.xc, self.vc, self.rings_trial, self.hist,
                          self.hz_trial, self.g, BALANCE_TOL, _st.START_ITER * MAX_ITER, True, self.work_trial,
                          self.out6, *self._paths)
        self.q[...] = self.q_trial
        self.q_old[...] = self.q_trial
        self._used[:] = self.out6
        self.steps = 0
        self.evaluations = 0
        self._chunks = []
        self._buf = None
        self._k_buf = 0
        self._next_sample = t + self.sampleInterval
        self._sample_w = []
        self._warned = set()
        self._wall = 0.0
        self._qmax = [0.0, 0.0]
        self._w_z = self.scenario.omega
        self._rot0 = np.eye(3)
        self._t_last = -math.inf
        self._t_start = t

    # -- Exudyn items -----------------------------------------------------------------------------------------------
    def _add_items(self, mbs, show):
        import exudyn as exu
        from exudyn.itemInterface import (
            ObjectConnectorRigidBodySpringDamper,
            SensorUserFunction,
            VObjectConnectorRigidBodySpringDamper,
        )

        inner, outer = self.markers
        self.object = mbs.AddObject(ObjectConnectorRigidBodySpringDamper(
            markerNumbers=[outer, inner], springForceTorqueUserFunction=self._user_function,
            visualization=VObjectConnectorRigidBodySpringDamper(show=bool(show))))
        self._sys = mbs.sys
        self._ovt = exu.OutputVariableType
        defs = {"innerRingForce": lambda: list(-self._rot0 @ self._out[:3]),
                "outerRingForce": lambda: list(self._rot0 @ self._out[:3]),
                "ringDisplacement": lambda: [*self.ring[:3], 0.0, 0.0],
                "cageSpeed": lambda: [self.cage_speed()],
                "qMaxInner": lambda: [self._qmax[0]], "qMaxOuter": lambda: [self._qmax[1]]}
        self.sensors = {k: mbs.AddSensor(SensorUserFunction(
            sensorNumbers=[], factors=[], storeInternal=True, writeToFile=False,
            sensorUserFunction=sensor_function(fn))) for k, fn in defs.items()}
        self.items = {"object": self.object, "sensors": dict(self.sensors)}
        _register_post_step(mbs, self)

    @property
    def initialCoordinates(self):
        """The 6 initial coordinates of the inner ring's rigid-body node at the start, in world components: the
        displacement (d_x, d_y, d_z) [m] of ``initialRingDisplacement`` (outer ring's frame) turned by the outer
        ring's world rotation at t = 0, and rotation (0, 0, 0) (the reduced engine holds the tilt;
        model.level_items.world_initial_coordinates); the other levels' property has the same meaning and
        length."""
        return world_initial_coordinates(self._outer_rotation, [*self.initialRingDisplacement[:3], 0.0, 0.0])

    def cage_speed(self):
        """The cage's speed [rad/s]: the rigid cage's, else the balls' mean orbital speed."""
        return float(self.vc[1, 0]) if self.cage_free else float(np.mean(self.om))

    def SimulationSettings(self, endTime, stepSize=2e-5, solverType="GeneralizedAlpha"):
        """Fixed-step settings (default: GeneralizedAlpha at 2e-5 s, a step of the reduced engine's checks), no
        solution file, sensors written every sample interval, Newton's absolute tolerance 1e-8 and relative
        tolerance NEWTON_RELATIVE_TOLERANCE, as the other levels (docs/theory/levels.md)."""
        return level_settings(endTime, stepSize, solverType, self.sampleInterval)

    # -- evaluation (inside Newton) ---------------------------------------------------------------------------------
    def _begin(self, t):
        """A new SolveDynamic, or back to the run's start time, starts over."""
        solver = self._sys.get("dynamicSolver")
        if solver is not self._run or (t < self._t_last - 1e-12 and t <= self._t_start + 1e-12):
            self._run = solver
            check_solver(settings_solver(self._sys.get("simulationSettings")))
            self._reset(t)
        self._t_last = t

    def _user_function(self, mbs, t, itemNumber, displacement, rotation, velocity, angularVelocity, stiffness,
                       damping, rotJ0, rotJ1, offset):
        self._begin(t)
        self._rot0 = np.asarray(rotJ0, float)
        r = self.ring_trial
        r[0], r[1], r[2] = displacement
        r[3], r[4], r[5] = velocity
        self.p_trial[P_W_MAX] = angularVelocity[2]
        h = t - self._t_slow
        if self._h_last is not None and h < 0.5 * self._h_last:
            h = self._h_last  # an evaluation at the slow states' own time (the start's accelerations)
        elif h <= 0.0:
            # the start's initial accelerations (t at the slow states' own time, q_trial = q_n: no centre rate): the
            # step enters only the rule of balls without contact (m_b / dt^2); MAX_STEP as the start's balance.
            # A reducedStep of 20 us here instead gave Exudyn's GeneralizedAlpha initial accelerations from which
            # its first 100 us step failed and the step stayed at a quarter (development run)
            h = MAX_STEP
        it, ok, worst = frozen_ring_force(t, h, self.p_trial, self.engine.table, self.phi, self.om, self.wo,
                                          self.q_trial, self.q, r, self.xc, self.vc, self.rings_trial, self.hist,
                                          self.hz_trial, self.g, LEVEL_BALANCE_TOL, MAX_ITER, self.fresh,
                                          self.work_trial, self.out6, self._paths[0], self._paths[1], self._paths[2])
        self.fresh = False
        self.evaluations += 1
        self._used[:] = self.out6
        if not math.isfinite(worst) or not np.all(np.isfinite(self.out6)):
            raise SimulationError(f"reduced level: non-finite ring force at t = {t:.6g} s (relative displacement "
                                  f"{list(displacement)} m); a smaller Exudyn step")
        f = self.out6
        # the connector's f = -(F, M) with F the balls' force on the inner ring; the moments about x and y are
        # left out (the tilt is held in the reduced engine), the friction torque about the axis kept
        o = self._out
        o[0], o[1], o[2] = -f[0], -f[1], -f[2]
        o[3] = o[4] = 0.0
        o[5] = -f[5]
        return o

    @property
    def _paths(self):
        from ...model.contact import scene_loss_path, scene_paths

        if not hasattr(self, "_paths_cache"):
            d, e = scene_paths(self.engine.params)
            self._paths_cache = (d, e, scene_loss_path(self.engine.params))
        return self._paths_cache

    # -- the slow states (after each step) --------------------------------------------------------------------------
    def post_step(self, mbs, t):
        """Advance the balls' and the cage's states from the last step to t with the inner ring at Exudyn's
        converged relative pose and velocity (module docstring, step 2); a sample every sample interval."""
        h = t - self._t_slow
        if h <= 1e-15:
            return True
        ovt = self._ovt
        d = mbs.GetObjectOutput(self.object, ovt.DisplacementLocal)
        v = mbs.GetObjectOutput(self.object, ovt.VelocityLocal)
        rot = mbs.GetObjectOutput(self.object, ovt.Rotation)
        w = mbs.GetObjectOutput(self.object, ovt.AngularVelocityLocal)
        tilt = max(abs(rot[0]), abs(rot[1]))
        if tilt > self.tiltWarning and "tilt" not in self._warned:
            self._warned.add("tilt")
            warnings.warn(f"tilt: the inner ring's tilt relative to the outer ring reached {tilt:.3g} rad at t = "
                          f"{t:.6g} s, above tiltWarning = {self.tiltWarning:g} rad; the reduced level holds the "
                          "tilt (the reduced engine's inner ring translates only): its ball loads are those of the "
                          "untilted ring and it applies no moment about x and y (use model='quasistatic' or "
                          "'balls' for a tilting ring; docs/theory/levels.md#reduced-level)", UserWarning,
                          stacklevel=2)
        self.ring[:3] = d
        self.ring[3:] = v
        self._w_z = float(w[2])
        self.p[P_W_MAX] = self._w_z
        cap = MAX_STEP if self.reducedStep is None else self.reducedStep
        k = max(1, math.ceil(h / cap - 1e-9))
        dt = h / k
        if self._h_last is not None and abs(dt - self._h_last / max(1, self._k_last)) > 1e-9 * dt:
            self.engine.work[_st.W_HAVE_PREV] = 0.0  # another step size: the BDF2 history restarts (Euler step)
        sample = t >= self._next_sample - 1e-6 * self.sampleInterval
        buf, rows = self._sample_rows(sample)
        t0 = time.perf_counter()
        eng = self.engine
        steps, ns, status = _st.run_reduced(
            k, self._t_slow, dt, self.p, eng.table, self.phi, self.om, self.wo, self.wb, self.q, self.q_old, self.ring,
            self.xb, self.vb, self.xc, self.vc, self.rings, self.hist, self.hz, self.fb, self.tb, self.fc, self.fr,
            self.fring, self.glob, self.diag, self.cage_load, BALANCE_TOL, MAX_ITER, k, 0, buf["t"][rows],
            buf["glob"][rows], buf["diag"][rows], buf["cage_load"][rows], buf["xb"][rows], buf["vb"][rows],
            buf["wb"][rows], buf["xc"][rows], buf["vc"][rows], buf["ring"][rows], eng.work, False, eng.jac_every,
            eng.jac_tol, eng.ring_every, self.prev, self.ring_prev, self.cage_free, self.cage_prev, eng.n_corr,
            self.adapt, self.ys, self.h_log, self.qd, self._paths[0], self._paths[1], self._paths[2])
        self._wall += time.perf_counter() - t0
        if status != 0:
            what = "non-finite state" if status == 1 else "runaway overlap (above 5 % of the ball radius)"
            raise SimulationError(f"reduced level: {what} at t = {t:.6g} s with reduced steps of {dt:.3g} s; a "
                                  "smaller Exudyn step (or reducedStep)")
        self.steps += steps
        self._t_slow = t
        self._h_last, self._k_last = h, k
        self.q_trial[...] = self.q
        self.check_lag(t)
        # the balls moved along the load zone: the next evaluation retakes its balance's Jacobians (a kept one
        # converges slowly, 4.3 iterations per evaluation against about 2 in the development run)
        self.fresh = True
        if ns:
            self._k_buf += ns
            self._sample_w.append(self._w_z)
            # the next sample on the grid t_start + k sampleInterval (the reduced engine's sample times)
            k_next = math.floor((t - self._t_start) / self.sampleInterval + 1e-6) + 1
            self._next_sample = self._t_start + k_next * self.sampleInterval
            loads = self.diag[:, :, D_LOAD]
            self._qmax = [float(loads[:, 0].max()), float(loads[:, 1].max())]
        return True

    def _sample_rows(self, sample):
        """The sample buffers and the slice of the next row (empty when no sample is due)."""
        from ...model.record import sample_buffers

        z = self.bearing.n_balls
        if self._buf is None or (sample and self._k_buf >= len(self._buf["t"])):
            new = sample_buffers(max(256, 2 * (0 if self._buf is None else len(self._buf["t"]))), z)
            if self._buf is not None:
                for key, a in self._buf.items():
                    new[key][:self._k_buf] = a[:self._k_buf]
            self._buf = new
        return self._buf, slice(self._k_buf, self._k_buf + (1 if sample else 0))

    def slip_time(self):
        """The balls' slip relaxation time [s] at the last sample: m_eff / k_t, k_t the largest secant slope
        |F_t| / |u_slip| = |mu| Q / |u_slip| of a loaded ball / race contact (the traction's slope at the operating
        slip; its initial slope for a traction curve that flattens with slip) and m_eff = m_b / (1 + m_b R_b^2 /
        I_b) = 2/7 m_b the mass of a solid sphere's surface speed under a tangential force at its surface (its
        orbital and spin accelerations together). A ball's slip relaxes as exp(-t k_t / m_eff) (Walters 1971;
        Gupta 1984); an estimate whose order matters, inf without a loaded contact."""
        from ...model.layout import D_MU, D_SLIP, P_IB, P_MB, P_RB

        d = self.diag
        q, mu, u = d[:, :, D_LOAD], np.abs(d[:, :, D_MU]), np.abs(d[:, :, D_SLIP])
        loaded = q > 0.0
        if not loaded.any():
            return math.inf
        k_t = float(np.max(mu[loaded] * q[loaded] / np.maximum(u[loaded], 1e-9)))
        mb, rb, ib = float(self.p[P_MB]), float(self.p[P_RB]), float(self.p[P_IB])
        m_eff = mb / (1.0 + mb * rb * rb / ib)
        return m_eff / k_t if k_t > 0.0 else math.inf

    def check_lag(self, t):
        """The slow states' lag at the step just taken: the ring force Exudyn's step used (its last evaluation, at
        the converged pose, with the balls and cage of the step's start) against the force at the same pose with
        the slow states advanced to the step's end (the reduced engine's committed evaluation of its step), as a
        share of the latter's size; kept as ``lagForceMax`` (and its time) and in the mean, and warned (once per
        run) above :data:`LAG_FORCE_WARNING` naming ``stepSize``; the first step's apart (``lagForceStart``)."""
        new = self.fr[0, :3]
        size = float(np.linalg.norm(new))
        if size <= 0.0:
            return
        lag = float(np.linalg.norm(self._used[:3] - new)) / size
        if self.lagForceStart is None:
            # the first step: the start (a quasi-static state, race-control kinematics) is not on the dynamics'
            # balance of the speeds, whose slips relax within it (on the 6208 radial, 1.9 % at 20 us to
            # 3.2 % at 500 us, validation/consistency/reduced_level.py); kept apart, not warned
            self.lagForceStart = lag
            return
        self._lag_sum += lag
        self._lag_n += 1
        if lag > self.lagForceMax:
            self.lagForceMax, self.lagForceMaxTime = lag, t
        if lag > LAG_FORCE_WARNING and "lag" not in self._warned:
            self._warned.add("lag")
            tau = self.slip_time()
            warnings.warn(f"stepSize: at t = {t:.6g} s the ring force of the Exudyn step (the balls and cage frozen "
                          f"at its start) differs by {100 * lag:.3g} % from the force with them advanced to its end, "
                          f"above {100 * LAG_FORCE_WARNING:g} %: the slow states' lag of one step "
                          f"({self._h_last:.3g} s; the balls' slip relaxation time {tau:.3g} s) is not small there; "
                          "a smaller Exudyn step (docs/theory/levels.md#reduced-level)", UserWarning, stacklevel=3)

    @property
    def lagForceMean(self):
        """The mean lag share of the ring force over the run's steps (:meth:`check_lag`)."""
        return self._lag_sum / self._lag_n if self._lag_n else 0.0

    # -- outputs ----------------------------------------------------------------------------------------------------
    def record(self) -> RunRecord:
        """The samples of the run as a :class:`~exudyn_bearing.model.record.RunRecord` (the reduced engine's
        layouts; engine ``"reduced-level"``): the scenario's speed is the mean relative spin of the samples."""
        if not self._k_buf:
            raise RuntimeError("record: no samples yet; run mbs.SolveDynamic first")
        data = {k: v[:self._k_buf].copy() for k, v in self._buf.items()}
        dt = self.scenario.dt if self._h_last is None else self._h_last / self._k_last
        sc = self.scenario.replace(omega=float(np.mean(self._sample_w)), t_end=float(data["t"][-1]), dt=dt)
        rec = RunRecord(self.bearing, sc, self.lubricant, data, steps=self.steps, wall_s=self._wall,
                        engine="reduced", stable_dt=None, static=self._initial["static"], load_angle=self.loadAngle)
        rec.reduced_stats = self.engine.stats(self.steps)
        rec.reduced_stats.update(dt_min=dt, dt_median=dt, dt_max=dt, exudyn_evaluations=self.evaluations,
                                 lag_force_max=self.lagForceMax, lag_force_mean=self.lagForceMean,
                                 lag_force_start=self.lagForceStart)
        return rec


_POST_STEP = {}


def _register_post_step(mbs, level):
    """One PostStepUserFunction per mbs that advances the slow states of every reduced level on it, after a
    user's own post-step function (kept when it was set before the level)."""
    key = id(mbs)
    entry = _POST_STEP.get(key)
    if entry is None or entry["mbs"] is not mbs:
        try:
            user = mbs.GetPostStepUserFunction()
        except Exception:  # noqa: BLE001 - none set
            user = None
        if isinstance(user, dict):  # Exudyn 1.13: {"function": f, "type": "Python"}
            user = user.get("function")
        if not callable(user):  # 0: none set
            user = None
        entry = _POST_STEP[key] = {"mbs": mbs, "levels": [], "user": user}

        def post_step(mbs_, t):
            ok = True
            for lv in entry["levels"]:
                lv.post_step(mbs_, t)
            if entry["user"] is not None:
                ok = entry["user"](mbs_, t)
            return ok

        mbs.SetPostStepUserFunction(post_step)
    entry["levels"].append(level)
