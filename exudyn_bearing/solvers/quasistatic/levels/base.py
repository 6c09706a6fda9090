"""What the bearing levels without ball DOFs share: options, the operating
point, the Exudyn connector between the ring markers, the cage angle,
sensors, samples and the recommended solver settings.

Coordinates: the connector's joint frame is the outer ring marker's frame
(marker 0), the bearing axis its local z. Exudyn hands the user function the
inner ring's displacement d and Tait-Bryan angles (theta_x, theta_y, phi)
relative to the outer ring in that frame, the relative velocity v and the
relative angular velocity w. The quasi-static solver's ring pose is
u = (d_x, d_y, d_z, theta_x, theta_y) (small tilts: the inner ring axis is
(theta_y, -theta_x, 1), independent of the spin angle phi), the relative
spin is w_z, and the tilt rates are (w_x - w_z theta_y, w_y + w_z theta_x)
(w contains the spin about the tilted axis). The user function returns the
connector's "spring force" f, which Exudyn applies as -f to the inner ring
and +f to the outer ring: f = -F with F the force and moment of the bearing
on the inner ring.
"""
from __future__ import annotations

import math

import numpy as np

from ...._jit import kernel
from ....data import InputError, Lubricant, load_bearing, load_lubricant
from ....data.errors import check_finite, check_positive
from ....model.level_items import (  # noqa: F401 (shared with the reduced level; re-exported)
    NEWTON_RELATIVE_TOLERANCE,
    _load_pair,
    _sensor_function,
    check_solver,
    level_settings,
    marker_start_rotation,
    rigid_marker,
    world_initial_coordinates,
)
from ....model.load_angle import LOAD_ANGLE_RANGE, check_load_angle, load_rotation  # noqa: F401 (re-exported)
from ....model.load_range import MAX_CONTACT_PRESSURE, check_load_range
from ....model.solver_types import IMPLICIT_SOLVERS, settings_solver
from ....physics import kinematics as _kin
from ...quasistatic.solve import solve_quasistatic

asarray = np.asarray

__all__ = ["IMPLICIT_SOLVERS", "LEVEL_OPTIONS", "WS_HEADER", "LevelBearing"]

#: Options every level takes (the ball element's names).
LEVEL_OPTIONS = ("lubricant", "initialLoad", "loadAngle", "initialOmega", "ringGrowth", "temperatures", "hertzModel",
                 "sampleInterval", "coefficients", "coefficientSpeeds", "show", "operatingTilt")
#: ``operatingTilt`` -> the tilts the operating point and the level's own tables hold (solve_quasistatic's
#: ``fixed``): "free" (a single bearing's own equilibrium), "held" (at zero: a bearing in a rotor whose other
#: supports hold the shaft's tilt; solve_quasistatic's default)
OPERATING_TILT = {"free": {}, "held": {"tilt_x": 0.0, "tilt_y": 0.0}}
#: Default speeds [rad/s] of the coefficient table (damping, linear level): up to the larger of 1000 rad/s and
#: 1.5 times the initial speed.
DEFAULT_SPEEDS = (0.0, 100.0, 250.0, 500.0, 750.0, 1000.0)


def entry_point(dispatcher, args):
    """The compiled entry point of a numba kernel for the types of ``args`` (skips numba's per-call type
    dispatch, a large share of a small kernel's call); the dispatcher itself where numba offers none."""
    try:
        import numba

        sig = tuple(numba.typeof(a) for a in args)
        dispatcher.compile(sig)
        return dispatcher.overloads[sig].entry_point
    except Exception:  # noqa: BLE001 - JIT disabled or another numba: the dispatcher works too
        return dispatcher


#: Calls from Exudyn into the levels' Python (user functions of every level in this process; [count]): the
#: benchmarks' calls per step (validation/performance/bench_qs_rotor.py)
python_calls = [0]
#: Header of a level's work array: out = -(F, 0) (6), F (5), pose u (5), cage (angle, speed) (2), q_max (3).
WS_OUT, WS_FORCE, WS_POSE, WS_CAGE, WS_QMAX, WS_HEADER = 0, 6, 11, 16, 18, 21
#: Length of a sample row's common part (:func:`sample_header`): t, pose (5), F (5), cage (2), q_max inner and outer
SAMPLE_HEADER = 15


@kernel(no_runtime=True)
def sample_header(t, ws, row):
    """A sample row's common part from the work array's header: t, pose u, F, cage (angle, speed), the largest
    inner and outer ball load (one compiled call: a level samples at every step by default)."""
    row[0] = t
    for k in range(5):
        row[1 + k] = ws[WS_POSE + k]
        row[6 + k] = ws[WS_FORCE + k]
    row[11] = ws[WS_CAGE]
    row[12] = ws[WS_CAGE + 1]
    row[13] = ws[WS_QMAX]
    row[14] = ws[WS_QMAX + 1]


class LevelBearing:
    """Base of the levels (module docstring). Subclasses set ``model`` and
    implement ``_workspace_size()`` (their part of the work array ``self._ws``
    after the WS_* header), ``_setup()`` and ``_evaluate(d, r, v, w)``
    (sequences of 3; fills ``self._out`` (6,), ``self._force`` (5,),
    ``self._cage`` (angle, speed), views of the header)."""

    model = ""
    #: whether the level knows its ball loads (sensors qMaxInner and qMaxOuter, samples q_max_*)
    ballLoads = True

    def __init__(self, mbs, bearing, markerInnerRing, markerOuterRing, lubricant: Lubricant | str | None = None,
                 initialLoad=(0.0, 0.0), loadAngle=0.0, initialOmega=0.0, ringGrowth=True, temperatures=None,
                 hertzModel="exact", sampleInterval=1e-4, coefficients=None, coefficientSpeeds=None, show=False,
                 operatingTilt="free"):
        self.mbs = mbs
        self.bearing = b = load_bearing(bearing)
        #: the lubricant (None: the quasi-static solver's default)
        self.lubricant = None if lubricant is None else load_lubricant(lubricant)
        self.initialLoad = _load_pair(initialLoad)
        self.initialOmega = check_finite("initialOmega", initialOmega)
        self.ringGrowth = bool(ringGrowth)
        self.temperatures = temperatures
        self.hertzModel = hertzModel
        self.sampleInterval = check_positive("sampleInterval", sampleInterval)
        self.markers = (rigid_marker(mbs, markerInnerRing, "markerInnerRing"),
                        rigid_marker(mbs, markerOuterRing, "markerOuterRing"))
        if self.markers[0] == self.markers[1]:
            raise InputError(f"markerOuterRing: marker {markerOuterRing} is also markerInnerRing")
        #: the outer ring's world rotation at t = 0 (initialCoordinates turns its frame's pose by it)
        self._outer_rotation = marker_start_rotation(mbs, self.markers[1])
        if operatingTilt not in OPERATING_TILT:
            raise InputError(f"operatingTilt: must be one of {', '.join(map(repr, OPERATING_TILT))}, got "
                             f"{operatingTilt!r}")
        #: the tilts the operating point and the level's own tables hold (OPERATING_TILT); at run time the
        #: tilt is always a DOF of the user's model
        self.operatingTilt = operatingTilt
        fr, fa = self.initialLoad
        # loads beyond the elastic contact model are refused before anything is solved
        check_load_range(b, fr, fa, hertzModel, names=("initialLoad", "initialLoad", "bearing"))
        #: quasi-static solution at initialLoad and initialOmega (the operating point)
        self.operatingPoint = self._operating_point(temperatures)
        #: inner-ring pose (d_x, d_y, d_z, theta_x, theta_y) at the operating point (outer-ring frame):
        #: place the inner ring there to start in equilibrium
        self.loadAngle = check_load_angle(loadAngle)
        self.initialRingDisplacement = self.rotation() @ np.array(self.operatingPoint.displacement, float)
        self.coefficients = self._table(coefficientSpeeds) if coefficients is None else self._given_table(coefficients)
        a0 = b.free_contact_angle
        #: cage and ball-spin speeds per unit relative ring speed (kinematic, free contact angle)
        self.cageRatio = float(_kin.cage_speed(1.0, 0.0, b.ball_radius, b.pitch_radius, a0))
        self.spinRatio = float(_kin.ball_spin_relative(1.0, 0.0, b.ball_radius, b.pitch_radius, a0))
        self._q_limit = self._ball_load_limit()
        # one work array for the kernel (each array argument of a compiled call costs its unboxing): the
        # header of every level (WS_*), then the level's own part (_workspace_size())
        self._ws = np.zeros(WS_HEADER + self._workspace_size())
        self._out = self._ws[WS_OUT:WS_OUT + 6]
        self._force = self._ws[WS_FORCE:WS_FORCE + 5]
        self._pose = self._ws[WS_POSE:WS_POSE + 5]
        self._cage = self._ws[WS_CAGE:WS_CAGE + 2]
        self._qmax = self._ws[WS_QMAX:WS_QMAX + 3]
        self._rot0 = None  # the joint frame's rotation of the last sample (None: the identity, _ring_force)
        self._t_last = -math.inf
        self._t_start = -math.inf
        self.restarts = 0
        self._samples = []
        self._next_sample = 0.0
        self._evaluations = 0
        self._setup()
        self._add_items(mbs, show)

    def _operating_point(self, temperatures):
        """solve_quasistatic at initialLoad and initialOmega with the tilt of ``operatingTilt``; its refusal
        names ``initialLoad``, and says so where the free tilt alone puts the contacts out of range (a single
        angular-contact bearing under a radial and an axial load tilts until a contact passes the shoulder,
        which the held tilt of a rotor's other supports prevents)."""
        fr, fa = self.initialLoad
        kw = dict(Fr=fr, Fa=fa, omega=abs(self.initialOmega), ring_growth=self.ringGrowth, temperatures=temperatures,
                  lubricant=self.lubricant, hertz_method=self.hertzModel, stiffness=False,
                  # the level takes forces and damping from it, not the balls' kinematics and losses that the
                  # inertia check judges
                  inertia_check=False)
        try:
            return solve_quasistatic(self.bearing, fixed=dict(OPERATING_TILT[self.operatingTilt]), **kw)
        except InputError as exc:
            reason = str(exc).partition(": ")[2]
            if self.operatingTilt == "free":
                try:
                    solve_quasistatic(self.bearing, fixed=dict(OPERATING_TILT["held"]), **kw)
                except InputError:
                    pass
                else:
                    raise InputError(f"initialLoad: with the inner ring's tilt free (operatingTilt='free', the "
                                     f"equilibrium of a single bearing) {reason}; with the tilt held at zero it "
                                     "solves: a bearing in a rotor whose other supports hold the shaft's tilt takes "
                                     "operatingTilt='held'") from None
            raise InputError(f"initialLoad: {reason}") from None

    @property
    def initialCoordinates(self):
        """The 6 initial coordinates of the inner ring's rigid-body node at the operating point, in world
        components: the pose ``initialRingDisplacement`` (outer ring's frame) turned by the outer ring's world
        rotation at t = 0, displacement [m] and the tilt as a small rotation about the world axes [rad]
        (Tait-Bryan angles of a NodeRigidBodyRxyz, as small angles also the rotation vector of a
        RotationRotationVector node, whose reference rotation is the identity; model.level_items.
        world_initial_coordinates); the ball element's property has the same meaning and length."""
        return world_initial_coordinates(self._outer_rotation, self.initialRingDisplacement)

    def rotation(self):
        """5x5 map from the quasi-static solver's axes (radial load along x) to the outer-ring frame, where the
        radial load points at ``loadAngle`` from x: translations and tilts turn about z."""
        c, s = math.cos(self.loadAngle), math.sin(self.loadAngle)
        t = np.eye(5)
        t[np.ix_([0, 1], [0, 1])] = t[np.ix_([3, 4], [3, 4])] = [[c, -s], [s, c]]
        return t

    # -- set-up -------------------------------------------------------------
    def _table(self, speeds):
        """Coefficient table (stiffness, damping, operating pose) at ``speeds`` (default: DEFAULT_SPEEDS, up to
        1.5 times the initial speed) under initialLoad."""
        from ..coefficients import bearing_coefficients

        given = speeds is not None
        if speeds is None:
            top = max(DEFAULT_SPEEDS[-1], 1.5 * abs(self.initialOmega))
            speeds = [s * top / DEFAULT_SPEEDS[-1] for s in DEFAULT_SPEEDS]
        fr, fa = self.initialLoad
        try:
            return bearing_coefficients(self.bearing, speeds, Fr=fr, Fa=fa, ring_growth=self.ringGrowth,
                                        temperatures=self.temperatures, lubricant=self.lubricant,
                                        hertz_method=self.hertzModel, fixed=dict(OPERATING_TILT[self.operatingTilt]))
        except InputError as exc:
            if str(exc).startswith("speeds"):
                raise InputError(f"coefficientSpeeds{str(exc)[len('speeds'):]}") from None
            if str(exc).startswith("omega") and (not given or max(map(abs, speeds)) > abs(self.initialOmega)):
                # a speed of the table above the run's initial speed, where the bearing does not carry the load
                raise InputError(f"coefficientSpeeds: the level's table of stiffness and damping at "
                                 f"{', '.join(f'{w:g}' for w in speeds)} rad/s: {str(exc).partition(': ')[2]}; give "
                                 "coefficientSpeeds that end at the run's highest speed"
                                 + ("" if given else " (the default table reaches 1000 rad/s or 1.5 initialOmega)")
                                 ) from None
            raise

    def _given_table(self, coefficients):
        """The user's ``coefficients`` if it is a table (or its to_dict dict) made for this bearing, else InputError
        naming ``coefficients`` (..coefficients.check_table; both levels read it)."""
        from ..coefficients import check_table

        return check_table(coefficients, self.bearing)

    def _ball_load_limit(self):
        """Ball load [N] at which the Hertz pressure reaches MAX_CONTACT_PRESSURE (free contact angle)."""
        from ....model.load_range import _pressure_at

        b, lo, hi = self.bearing, 0.0, 1.0
        while _pressure_at(b, hi, b.free_contact_angle, self.hertzModel) < MAX_CONTACT_PRESSURE:
            hi *= 2.0
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if _pressure_at(b, mid, b.free_contact_angle, self.hertzModel) < \
                MAX_CONTACT_PRESSURE else (lo, mid)
        return hi

    def _add_items(self, mbs, show):
        from exudyn.itemInterface import SensorUserFunction

        self.object = self._add_object(mbs, show)
        self._sys = mbs.sys
        self._run = None
        # lists of Python floats (tolist; a list of NumPy scalars costs Exudyn a conversion per entry), the joint
        # frame's rotation only where the connector handed one (Exudyn evaluates these at every sensor write)
        defs = {"innerRingForce": lambda: (-self._ring_force()).tolist(),
                "outerRingForce": lambda: self._ring_force().tolist(),
                "ringDisplacement": self._pose.tolist,
                "cageSpeed": self._cage[1:2].tolist}
        if self.ballLoads:
            defs.update(qMaxInner=self._qmax[0:1].tolist, qMaxOuter=self._qmax[1:2].tolist)
        self.sensors = {k: mbs.AddSensor(SensorUserFunction(
            sensorNumbers=[], factors=[], storeInternal=True, writeToFile=False,
            sensorUserFunction=_sensor_function(fn))) for k, fn in defs.items()}
        self.items = {"object": self.object, "sensors": dict(self.sensors)}

    def _ring_force(self):
        """The sensors' force on the outer ring, A0 f (-A0 f: on the inner ring), f the connector's force f_force of
        the last evaluation and A0 the joint frame's rotation the connector handed at the last sample (None: none
        handed, the identity: the node formulation's samples)."""
        rot = self._rot0
        return self._out[:3] if rot is None else rot @ self._out[:3]

    def _add_object(self, mbs, show):
        """The Exudyn object of the bearing (default: the connector between the ring markers); its number."""
        from exudyn.itemInterface import (
            ObjectConnectorRigidBodySpringDamper,
            VObjectConnectorRigidBodySpringDamper,
        )

        inner, outer = self.markers
        kw = self._connector_parameters()
        return mbs.AddObject(ObjectConnectorRigidBodySpringDamper(
            markerNumbers=[outer, inner], visualization=VObjectConnectorRigidBodySpringDamper(show=bool(show)), **kw))

    def _workspace_size(self):
        return 0

    def _connector_parameters(self):
        """Keyword arguments of the connector (default: the user function)."""
        return {"springForceTorqueUserFunction": self._user_function}

    # -- evaluation ---------------------------------------------------------
    def _user_function(self, mbs, t, itemNumber, displacement, rotation, velocity, angularVelocity, stiffness,
                       damping, rotJ0, rotJ1, offset):
        python_calls[0] += 1
        self._call(t, displacement, rotation, velocity, angularVelocity, rotJ0)
        return self._out

    def _call(self, t, displacement, rotation, velocity, angularVelocity, rotJ0=None):
        """One evaluation at time t for the connector's quantities (module docstring): a new run starts over,
        samples are taken every sample interval (``rotJ0``: the joint frame's rotation the sensors turn the forces
        by; None: the identity). Fills ``self._out``."""
        self._begin(t)
        self._evaluate(displacement, rotation, velocity, angularVelocity)
        self._end(t, rotJ0)

    def _begin(self, t):
        """Before an evaluation at time t: a new SolveDynamic, or back to the run's start time, starts over."""
        solver = self._sys.get("dynamicSolver")
        # a step the solver repeats with a smaller size goes back in time too, but not to the start
        if solver is not self._run or (t < self._t_last - 1e-12 and t <= self._t_start + 1e-12):
            self._run = solver
            self._t_start = t
            check_solver(settings_solver(self._sys.get("simulationSettings")))
            self._restart(t)
        elif t > self._t_last + 1e-12 and self._t_last >= self._next_sample - 1e-12:
            self._step_done(self._t_last)
        self._t_last = t
        self._evaluations += 1

    def _end(self, t, rotJ0=None):
        """After an evaluation at time t: at a sample time, the joint frame's rotation the sensors turn the
        forces by (the sample itself is taken when the solver moves on, :meth:`_step_done`)."""
        if rotJ0 is not None and t >= self._next_sample - 1e-12:
            self._rot0 = asarray(rotJ0, float)

    def _step_done(self, t):
        """The solver moved on from time t (a sample time): the last evaluation at t, still in the work arrays,
        is the step's converged state (Newton's last iterate; an explicit solver's committed state), and it is
        the sample. Called at the first evaluation of a later time, before it overwrites them, and by
        :meth:`samples` for the run's last step. A step the solver takes again from an earlier time leaves its
        attempt unsampled. (Before, the first evaluation of a sample time was kept: Newton's predictor, 0.4 um
        off on a loaded rotor.)"""
        self._samples.append(self._sample_row(t))
        self._next_sample = t + self.sampleInterval

    def _restart(self, t):
        self.restarts += 1
        self._samples.clear()
        self._next_sample = t
        self._evaluations = 0

    def _sample_row(self, t):
        row = np.empty(SAMPLE_HEADER)
        sample_header(t, self._ws, row)
        return row

    def _check_ball_load(self, t, q_max):
        if not q_max <= self._q_limit:  # also NaN
            from ....model.stability import SimulationError

            raise SimulationError(f"load: a ball load of {q_max:.4g} N at t = {t:.6g} s exceeds {self._q_limit:.4g} "
                                  f"N, where the Hertz pressure reaches {MAX_CONTACT_PRESSURE / 1e9:g} GPa, the "
                                  "limit of the elastic contact model (ISO 76); reduce the loads or check the step")

    # -- user-facing --------------------------------------------------------
    def SimulationSettings(self, endTime, stepSize=1e-4, solverType="GeneralizedAlpha"):
        """Fixed-step settings (default: GeneralizedAlpha at 1e-4 s), no solution file, sensors written every
        sample interval, Newton's absolute tolerance 1e-8 and relative tolerance NEWTON_RELATIVE_TOLERANCE
        (docs/theory/levels.md)."""
        return level_settings(endTime, stepSize, solverType, self.sampleInterval)

    def samples(self) -> dict:
        """The sampled series: ``t``, ``displacement`` (n, 5) (inner ring against the outer ring, outer-ring
        frame), ``force`` (n, 5) (force and moment of the bearing on the inner ring, same frame), ``cage_angle``,
        ``cage_speed``, ``q_max_inner``, ``q_max_outer`` (NaN on a level without ball loads, ``ballLoads``) and the
        level's own fields."""
        if self._evaluations and self._t_last >= self._next_sample - 1e-12:
            self._step_done(self._t_last)  # the run's last step
        if not self._samples:
            raise RuntimeError("samples: no samples yet; run mbs.SolveDynamic first")
        a = np.array(self._samples)
        out = {"t": a[:, 0], "displacement": a[:, 1:6], "force": a[:, 6:11], "cage_angle": a[:, 11],
               "cage_speed": a[:, 12], "q_max_inner": a[:, 13], "q_max_outer": a[:, 14]}
        out.update(self._extra_fields(a[:, SAMPLE_HEADER:]))
        out["evaluations"] = self._evaluations
        return out

    def _extra_fields(self, rest):
        return {}
