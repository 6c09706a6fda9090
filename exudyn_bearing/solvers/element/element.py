"""Exudyn ball-bearing element: a lubricated DEM ball bearing between two ring markers.

::

    import exudyn_bearing as eb
    bearing = eb.CreateBallBearing(mbs, eb.catalog["6208"], markerInnerRing=mShaft,
                                   markerOuterRing=mHousing)
    mbs.Assemble(); mbs.SolveDynamic(bearing.SimulationSettings(endTime=0.1), solverType=...)
    bearing.results().summary()

The balls and cage balls are Exudyn nodes of one ObjectGenericODE2 (6
coordinates each: position and an integrated global rotation vector whose
rate is the angular velocity, with the constant mass matrix of a sphere:
exact Newton-Euler for a homogeneous sphere, whose orientation never enters
the forces, and free of rotation-parameter singularities at 1000 rad/s). The
nodes of the ring bodies belong to the same object (with zero mass there:
their mass is in their own bodies), so its ``forceUserFunction`` sees the
ring motion in its coordinates and returns the ring reactions as generalized
forces of the ring nodes, consistently within every evaluation. It makes one
compiled call per force evaluation into the same contact kernel as the
reference engine (elliptic Hertz, Lambda-switched damping and friction,
Cundall-Strack history, torus cage).

Rings: a marker on ground (fixed ring), a MarkerBodyRigid / MarkerNodeRigid on
a body with a NodeRigidBodyRxyz or NodeRigidBodyRotVecLG node (``nodeType=
exu.NodeType.RotationRxyz`` or ``RotationRotationVector`` in
``mbs.CreateRigidBody``; the bearing axis is the body's local z; Euler
parameters are not usable with explicit solvers), or a position marker on a
mass point (axes parallel to the world, spin prescribed by
``innerRingSpeed`` / ``outerRingSpeed``).

Fast mode (``mode="fast"``): the balls are integrated inside the element in
compiled velocity-Verlet sub-steps between Exudyn steps (``subSteps`` of
``stepSize`` each) and only the ring reactions cross into Exudyn. The
sub-steps of one call are centred on the Exudyn time t (they run from
t - H/2 to t + H/2, the ring poses interpolated from the previous step and
extrapolated with the ring velocity beyond t), and the ring receives their
mean reaction: the impulse Exudyn's velocity-Verlet step gives the ring then
equals the sum of the impulses the balls received, without lag. With
``subSteps=1`` (default) it reproduces the body mode at about 0.4 of its cost.
More sub-steps spread the per-step overhead further; the Exudyn step H =
subSteps * stepSize then also has to integrate the ring bodies against the
contact stiffness: keep it below ``ringStableStep`` (estimated from the ring
bodies' mass matrices and the contact stiffness of all bearings on them at
their ``initialLoad``; a larger step warns). See validation/REPORT.md for
the measured limits.

Solvers, both modes: VelocityVerlet (recommended; one force evaluation per
step, so the Cundall-Strack history is exactly the reference engine's) and
RK44 with ``friction="regularized"`` (history-free; the fast mode advances
the balls at RK44's increasing stage times). ExplicitEuler is not usable:
not symplectic, it drives the stiff contacts unstable (validation/REPORT.md).
Implicit solvers work in the body mode with the numerical Jacobian but are
not recommended (EXUDYN_NOTES: an order of magnitude slower for Hertz
contact); the fast mode needs an explicit solver (its balls advance at the
first evaluation of a new time and ignore Newton iterations there; an
evaluation back in time raises).
"""
from __future__ import annotations

import math
import time
import warnings

import numpy as np

from ...data import InputError, Lubricant, default_lubricant, load_bearing
from ...model import layout as L
from ...model.contact import forces
from ...model.initial_state import initial_state
from ...model.motion import ring_poses
from ...model.parameters import scene_parameters
from ...model.record import RunRecord
from ...model.scenario import Scenario
from ...model.stability import StepSizeWarning, cage_load_check, ring_contact_stiffness, stable_step, step_warning
from ...physics import hertz
from . import kernels as EK

__all__ = ["BallBearingElement", "RING_REGISTRY"]


def _marker_ring(mbs, marker, which):
    """(kind, node, local position, fixed (12,)) of a ring marker, or InputError."""
    name = f"marker{which}Ring"
    try:
        m = mbs.GetMarker(int(marker))
    except Exception:
        raise InputError(f"{name}: {marker!r} is not a marker of this mbs") from None
    mtype = m["markerType"]
    ht = np.asarray(m.get("localHT", np.eye(4)), float)
    if not np.allclose(ht[:3, :3], np.eye(3)):
        raise InputError(f"{name}: the marker has a rotation offset; the bearing axis is the local z "
                         "axis of the ring body, use a marker without rotation")
    local = np.asarray(m.get("localPosition", np.zeros(3)), float)
    fixed = np.zeros(12)
    fixed[3:] = np.eye(3).ravel()
    if mtype in ("BodyRigid", "BodyPosition"):
        obj = mbs.GetObject(m["bodyNumber"])
        otype = obj["objectType"]
        if otype == "Ground":
            fixed[:3] = np.asarray(obj["referencePosition"], float) + np.asarray(
                obj.get("referenceRotation", np.eye(3)), float) @ local
            fixed[3:] = np.asarray(obj.get("referenceRotation", np.eye(3)), float).ravel()
            return EK.RING_FIXED, -1, np.zeros(3), fixed
        if "nodeNumber" not in obj:
            raise InputError(f"{name}: body type {otype} is not supported (use a RigidBody with a "
                             "NodeRigidBodyRxyz or NodeRigidBodyRotVecLG node, a MassPoint, or ground)")
        node = obj["nodeNumber"]
    elif mtype in ("NodeRigid", "NodePosition"):
        node = m["nodeNumber"]
    else:
        raise InputError(f"{name}: marker type {mtype} is not a rigid-body or position marker")
    ntype = mbs.GetNode(node)["nodeType"]
    if ntype == "RigidBodyRxyz":
        return EK.RING_RXYZ, int(node), local, fixed
    if ntype == "RigidBodyRotVecLG":
        return EK.RING_ROTVEC, int(node), local, fixed
    if ntype == "Point":
        fixed[:3] = local
        return EK.RING_POINT, int(node), np.zeros(3), fixed
    hint = (" (Euler-parameter nodes carry an algebraic constraint, which Exudyn's explicit solvers refuse; "
            "use nodeType=exu.NodeType.RotationRxyz or RotationRotationVector)" if ntype == "RigidBodyEP" else "")
    raise InputError(f"{name}: node type {ntype} is not supported (NodeRigidBodyRxyz, NodeRigidBodyRotVecLG, "
                     f"NodePoint or ground){hint}")


def _skew(v):
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def _ring_mobility(mbs, marker, kind, local):
    """Largest eigenvalue of B M^-1 B^T [1/kg] for the ring centre of a ring
    marker: M the mass matrix of the body it sits on (found through the
    marker's body or its node; Exudyn's rigid-body inertia is taken about the
    node, with the centre of mass at ``centerOfMass``), B the map from the
    body's velocity and angular velocity to the ring centre's velocity.
    None for ground or an unknown body."""
    if kind == EK.RING_FIXED:
        return None
    m = mbs.GetMarker(int(marker))
    obj = None
    if "bodyNumber" in m:
        obj = mbs.GetObject(m["bodyNumber"])
    else:
        node = int(m["nodeNumber"])
        for i in range(mbs.systemData.NumberOfObjects()):
            o = mbs.GetObject(i)
            if "nodeNumber" in o and int(o["nodeNumber"]) == node and o.get("mass"):
                obj = o
                break
    if obj is None or not obj.get("mass"):
        return None
    mass = float(obj["mass"])
    if kind == EK.RING_POINT or "inertia" not in obj:
        return 1.0 / mass
    jv = np.asarray(obj["inertia"], float)  # Jxx, Jyy, Jzz, Jyz, Jxz, Jxy about the node
    j = np.array([[jv[0], jv[5], jv[4]], [jv[5], jv[1], jv[3]], [jv[4], jv[3], jv[2]]])
    mc = mass * _skew(np.asarray(obj.get("centerOfMass", np.zeros(3)), float))
    mm = np.block([[mass * np.eye(3), mc.T], [mc, j]])
    bb = np.hstack([np.eye(3), _skew(np.asarray(local, float)).T])  # v + w x o
    return float(np.linalg.eigvalsh(bb @ np.linalg.solve(mm, bb.T)).max())


def _entry_point(dispatcher, args):
    """numba's compiled entry point of ``dispatcher`` for the types of
    ``args`` (compiled or loaded from the cache now): calling it skips
    numba's per-call type dispatch. The dispatcher itself where numba does not
    offer it (JIT disabled, another numba version)."""
    try:
        import numba

        sig = tuple(numba.typeof(a) for a in args)
        dispatcher.compile(sig)
        return dispatcher.overloads[sig].entry_point
    except Exception:  # noqa: BLE001 - any failure falls back to the dispatcher
        return dispatcher


#: Key in ``mbs.variables``: ring node -> [(element, ring index)] of every
#: bearing element on it (the fast mode's stable Exudyn step adds them up).
RING_REGISTRY = "exudyn_bearing.ringNodes"


def _initial_node_pose(mbs, kind, node, local, fixed):
    """Ring centre, rotation matrix, velocity and angular velocity at t = 0."""
    if kind == EK.RING_FIXED:
        return fixed[:3].copy(), fixed[3:].reshape(3, 3), np.zeros(3), np.zeros(3)
    n = mbs.GetNode(node)
    q = np.asarray(n["referenceCoordinates"], float) + np.asarray(n["initialCoordinates"], float)
    v = np.asarray(n.get("initialVelocities", n.get("initialCoordinates_t", np.zeros(q.size))), float)
    if kind == EK.RING_POINT:
        return q[:3] + fixed[:3], fixed[3:].reshape(3, 3), v[:3], np.zeros(3)
    a = np.array(EK.node_rotation(kind, q)).reshape(3, 3)
    g = np.array(EK._g_xyz(q[3], q[4])).reshape(3, 3) if kind == EK.RING_RXYZ else a  # Lie group: local omega
    w = g @ v[3:6]
    o = a @ local
    return q[:3] + o, a, v[:3] + np.cross(w, o), w


class BallBearingElement:
    """A DEM ball bearing inside an Exudyn model (see the module docstring).

    Attributes
    ----------
    items : dict
        Created Exudyn items: ``ballNodes``, ``cageNodes``, ``object``,
        ``ringNodes`` (ring nodes that joined the object), ``sensors``.
    sensors : dict
        Sensor numbers (``cageSpeed``, ``qMaxInner``, ``qMaxOuter``,
        ``lambdaOuterPsi0``, ``innerRingForce``, ``outerRingForce``: force of
        the balls on the ring [N]), stored internally: use
        ``mbs.PlotSensor`` or ``mbs.GetSensorStoredData``.
    initialRingDisplacement : ndarray
        Displacement of the inner ring (outer-ring frame) in the analytic
        initial state; place the inner ring there to start in equilibrium.
    stable : StableStep
        Stable-step estimate of the ball contacts (``stable.dt``).
    ringStableStep : float
        Fast mode: the largest Exudyn step [s] for the ring bodies on the
        ball contacts of all bearings on them (property, see its docstring).
    """

    def __init__(self, mbs, bearing, markerInnerRing, markerOuterRing, lubricant: Lubricant | None = None,
                 cage=True, lubrication=True, friction="history", tangential="explicit", hertzModel="exact",
                 film="hd", guideClearance=50e-6, muDry=0.1, regularizingSpeed=0.1,
                 tangentialStiffnessRatio=2.0 / 3.0, stepSize=1e-6, innerRingSpeed=None, outerRingSpeed=None,
                 initialOmega=0.0, initialLoad=(0.0, 0.0), initial="analytic", sampleInterval=1e-4,
                 mode="bodies", subSteps=1, contactLaw="hertz", powerLaw=(0.0, 1.5, 0.0), show=False):
        self.mbs = mbs
        self.bearing = b = load_bearing(bearing)
        self.lubricant = default_lubricant() if lubricant is None else lubricant
        for name, f in (("innerRingSpeed", innerRingSpeed), ("outerRingSpeed", outerRingSpeed)):
            if f is not None and not callable(f):
                raise InputError(f"{name}: must be a function of time t [s] returning rad/s")
        self.speed = (innerRingSpeed, outerRingSpeed)
        # model switches go through Scenario (validated there); loads come from the model
        self.scenario = Scenario(Fr=float(initialLoad[0]), Fa=float(initialLoad[1]), omega=float(initialOmega),
                                 cage=cage, lubrication=lubrication, friction=friction, tangential=tangential,
                                 hertz=hertzModel, film=film, guide_clearance=guideClearance, mu_dry=muDry,
                                 regularizing_speed=regularizingSpeed,
                                 tangential_stiffness_ratio=tangentialStiffnessRatio, dt=stepSize,
                                 sample_dt=max(sampleInterval, stepSize), initial=initial, contact_law=contactLaw,
                                 power_law=tuple(powerLaw))
        if cage and not b.has_cage:
            raise InputError(f"cage: bearing {b.name} has no cage balls; use cage=False")
        self.params = scene_parameters(b, self.scenario, self.lubricant)
        self.table = hertz.exact_table()
        self.stable = stable_step(b, self.scenario, self.lubricant)
        self.sampleInterval = float(sampleInterval)
        # rings
        self.rings_spec = [_marker_ring(mbs, markerInnerRing, "Inner"), _marker_ring(mbs, markerOuterRing, "Outer")]
        self.markers = (markerInnerRing, markerOuterRing)
        poses = [_initial_node_pose(mbs, *spec) for spec in self.rings_spec]
        axis_i, axis_o = poses[0][1][:, 2], poses[1][1][:, 2]
        if abs(float(axis_i @ axis_o)) < 1.0 - 1e-9:
            raise InputError("markerInnerRing: the ring axes (local z of both ring bodies) are not parallel "
                             f"(angle {math.degrees(math.acos(min(1.0, abs(float(axis_i @ axis_o))))):.3g} deg)")
        # initial ball state in the outer-ring frame, then in the world
        st = initial_state(b, self.scenario)
        self.initialRingDisplacement = np.asarray(st["ring"][:3], float)
        x_o, a_o, v_o, w_o = poses[1]
        rel = poses[0][0] - x_o
        rel_local = a_o.T @ rel
        expected = self.initialRingDisplacement
        gap = np.linalg.norm(rel_local - expected)
        if gap > 0.5 * b.groove_distance:
            raise InputError(f"markerInnerRing: the inner ring centre is {np.linalg.norm(rel_local):.3e} m from "
                             f"the outer ring centre; the rings must be concentric within the ball play "
                             f"(expected {np.linalg.norm(expected):.3e} m)")
        z = b.n_balls
        n_cage = z if (cage and b.has_cage) else 0
        xb = st["xb"] @ a_o.T + x_o
        vb = st["vb"] @ a_o.T + v_o + np.cross(w_o, xb - x_o)
        wb = st["wb"] @ a_o.T + w_o
        xc = st["xc"] @ a_o.T + x_o
        vc = st["vc"] @ a_o.T + v_o + np.cross(w_o, xc - x_o)
        allowed = max(0.0, -0.5 * b.diametral_clearance) + 2.0 * max(
            float(np.max(st["static"].overlap_outer)), 0.0) + 1e-7
        self._check_overlap(xb, poses, allowed)
        import exudyn as exu
        from exudyn.itemInterface import NodeGenericODE2, ObjectGenericODE2, SensorUserFunction, VObjectGenericODE2

        if mode not in ("bodies", "fast"):
            raise InputError(f"mode: must be 'bodies' or 'fast', got {mode!r}")
        self.mode = mode
        fast = mode == "fast"
        if fast and all(spec[0] == EK.RING_FIXED for spec in self.rings_spec):
            raise InputError("mode: the fast mode couples through ring nodes, but both rings are fixed")
        if int(subSteps) < 1:
            raise InputError(f"subSteps: must be >= 1, got {subSteps}")
        self.subSteps = int(subSteps)
        # the fast mode's Exudyn step also integrates the ring bodies against the ball contacts
        self._ring_mobility = [_ring_mobility(mbs, mk, sp[0], sp[2]) for mk, sp in zip(self.markers, self.rings_spec)]
        self._ring_stiffness = [ring_contact_stiffness(b, self.scenario, race) for race in ("inner", "outer")]
        registry = mbs.variables.setdefault(RING_REGISTRY, {})
        for r, sp in enumerate(self.rings_spec):
            if sp[0] != EK.RING_FIXED:
                registry.setdefault(int(sp[1]), []).append((self, r))
        nodes = []
        mass = []
        mb, ib = b.ball_mass, 0.4 * b.ball_mass * b.ball_radius ** 2
        for j in range(0 if fast else z):
            nodes.append(mbs.AddNode(NodeGenericODE2(
                referenceCoordinates=[*xb[j], 0.0, 0.0, 0.0], initialCoordinates=[0.0] * 6,
                initialCoordinates_t=[*vb[j], *wb[j]], numberOfODE2Coordinates=6)))
            mass += [mb] * 3 + [ib] * 3
        cage_nodes = []
        if n_cage and not fast:
            mz = b.cage_ball_mass
            iz = 0.4 * mz * b.cage_ball_radius ** 2
            for k in range(n_cage):
                cage_nodes.append(mbs.AddNode(NodeGenericODE2(
                    referenceCoordinates=[*xc[k], 0.0, 0.0, 0.0], initialCoordinates=[0.0] * 6,
                    initialCoordinates_t=[*vc[k], 0.0, 0.0, 0.0], numberOfODE2Coordinates=6)))
                mass += [mz] * 3 + [iz] * 3
        self.z, self.n_cage = z, n_cage
        # ring nodes join the object after the balls (once, if both rings share a node)
        self._ring_kind = np.array([sp[0] for sp in self.rings_spec], np.int64)
        ring_nodes = []
        self._ring_data = np.zeros((2, EK.RD_N))
        n = 0 if fast else 6 * (z + n_cage)
        ref = [np.zeros(n)]
        if not fast:
            for j in range(z):
                ref[0][6 * j:6 * j + 3] = xb[j]
            for k in range(n_cage):
                ref[0][6 * (z + k):6 * (z + k) + 3] = xc[k]
        offsets = {}
        for r, (kind, node, local, fixed) in enumerate(self.rings_spec):
            self._ring_data[r, EK.RD_OFF] = -1
            if kind != EK.RING_FIXED:
                if node not in offsets:
                    rc = np.asarray(mbs.GetNode(node)["referenceCoordinates"], float)
                    offsets[node] = n
                    ring_nodes.append(node)
                    ref.append(rc)
                    mass += [0.0] * rc.size
                    n += rc.size
                self._ring_data[r, EK.RD_OFF] = offsets[node]
            self._ring_data[r, EK.RD_LOCAL:EK.RD_LOCAL + 3] = local
            self._ring_data[r, EK.RD_FIXED:EK.RD_FIXED + 12] = fixed
        self.ref = np.concatenate(ref)
        self._hist = np.zeros((z, 2, 3))
        self._hist_trial = np.zeros((z, 2, 3))
        self._t_commit = 0.0
        self._t_trial = -1.0
        self._hz = np.zeros((z, 2, 4))
        self._work = np.zeros((8, z, 3))  # xb, vb, wb, xc, vc, fb, tb, fc
        if fast:  # the balls live here, not in Exudyn
            self._work[0], self._work[1], self._work[2] = xb, vb, wb
            self._work[3, :n_cage], self._work[4, :n_cage] = xc[:n_cage], vc[:n_cage]
            self._rings0 = ring_poses()
            self._rings_sub = ring_poses()
            self._clock = [math.nan, 0.0, self.sampleInterval, False]
        self._rings = ring_poses()
        self._fr = np.zeros((2, 6))
        self._glob = np.zeros(L.NGLOBAL)
        self._diag = np.zeros((z, 2, L.NDIAG))
        self._cage_load = np.zeros((z, 2))
        self._out = np.zeros(n)
        # samples: times and flat rows filled by compiled code (kernels.sample_row)
        self._sample_t, self._sample_rows = [], []
        self._row = np.zeros(sum(int(np.prod(shape)) for _name, shape in EK.sample_layout(z)))
        self._next_sample = self.sampleInterval
        self._evaluations = 0
        self._wall = 0.0
        self._speeds = [(r, f) for r, f in enumerate(self.speed) if f is not None]
        self._dt_sub = float(self.scenario.dt)
        self._max_overlap = float(self.params[L.P_MAX_OVERLAP])
        self._status = 0.0
        if fast:
            self._force_uf_fast = self._make_fast_uf()
        obj = mbs.AddObject(ObjectGenericODE2(nodeNumbers=nodes + cage_nodes + ring_nodes, massMatrix=np.diag(mass),
                                              forceUserFunction=self._force_uf_fast if fast else self._force_uf,
                                              visualization=VObjectGenericODE2(
                                                  show=bool(show),
                                                  graphicsDataUserFunction=self._graphics if show else 0)))
        self.sensors = {}
        sensor_defs = {
            "cageSpeed": lambda: [float(np.mean(self._orbital(self._work[3, :n_cage], self._work[4, :n_cage])))
                                  if n_cage else float(np.mean(self._orbital(self._work[0], self._work[1])))],
            "qMaxInner": lambda: [float(self._diag[:, 0, 0].max())],
            "qMaxOuter": lambda: [float(self._diag[:, 1, 0].max())],
            "lambdaOuterPsi0": lambda: [float(self._diag[self._psi0(), 1, 8])],
            "innerRingForce": lambda: list(self._fr[0, :3]),
            "outerRingForce": lambda: list(self._fr[1, :3]),
        }
        for key, fn in sensor_defs.items():
            self.sensors[key] = mbs.AddSensor(SensorUserFunction(
                sensorNumbers=[], factors=[], storeInternal=True, writeToFile=False,
                sensorUserFunction=(lambda f: (lambda mbs_, t, sn, fac, conf: f()))(fn)))
        self.items = {"ballNodes": nodes, "cageNodes": cage_nodes, "ringNodes": ring_nodes, "object": obj,
                      "sensors": dict(self.sensors)}
        self._exu = exu

    @property
    def ringStableStep(self):
        """Largest stable Exudyn step [s] of the fast mode for the ring bodies:
        2/omega with omega^2 <= sum over the bearings on the ring's body of
        k_b * lambda_max(B_b M^-1 B_b^T) (k_b: ring_contact_stiffness of that
        bearing's race at its initialLoad; B_b, M: see _ring_mobility), a
        bound of the body's highest frequency on its bearings. inf for rings
        on ground or on bodies of unknown mass. No safety factor (see
        reference.engine.ring_stable_step)."""
        registry = self.mbs.variables.get(RING_REGISTRY, {})
        best = math.inf
        for r, sp in enumerate(self.rings_spec):
            if sp[0] == EK.RING_FIXED or self._ring_mobility[r] is None:
                continue
            w2 = sum(el._ring_stiffness[rr] * el._ring_mobility[rr] for el, rr in registry.get(int(sp[1]), [])
                     if el._ring_mobility[rr] is not None)
            best = min(best, 2.0 / math.sqrt(w2))
        return best

    # -- checks --------------------------------------------------------
    def _check_overlap(self, xb, poses, allowed):
        """Initial overlaps must not exceed what the analytic state (preload) gives."""
        rings = ring_poses()
        for r in range(2):
            x, a, v, w = poses[r]
            rings[r, :3] = x
            rings[r, 6:15] = a.ravel()
        z = self.bearing.n_balls
        diag = np.zeros((z, 2, L.NDIAG))
        forces(self.params, self.table, xb, np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((z, 3)),
                 np.zeros((z, 3)), rings, np.zeros((z, 2, 3)), np.zeros((z, 2, 3)), 0.0, np.zeros((z, 2, 4)),
                 np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((2, 6)), np.zeros(L.NGLOBAL),
                 diag, np.zeros((z, 2)), True)
        worst = float(np.max(diag[:, :, 1]))
        if worst > allowed:
            raise InputError(f"markerInnerRing: the initial ring placement overlaps balls by {worst:.3e} m, beyond "
                             f"the preload and load overlap {allowed:.3e} m; check the ring positions")

    # -- user functions --------------------------------------------------
    def _force_uf(self, mbs, t, itemNumber, q, q_t):
        t0 = time.perf_counter()
        for r, f in self._speeds:
            self._ring_data[r, EK.RD_SPIN] = f(t)
        # Cundall-Strack history: commit the last trial state when time advances
        if t > self._t_trial:
            if self._t_trial >= 0.0:
                self._hist[:] = self._hist_trial
                self._t_commit = self._t_trial
            self._t_trial = t
        want = t >= self._next_sample - 1e-12
        worst = EK.element_rhs(np.asarray(q, float), np.asarray(q_t, float), self.ref, self.params, self.table,
                               self.z, self.n_cage, self._ring_kind, self._ring_data, self._hist, self._hist_trial,
                               t - self._t_commit, self._hz, self._work, self._rings, self._fr, self._glob,
                               self._diag, self._cage_load, want, self._out)
        return self._after_step(t, t0, worst, want, True)

    def _make_fast_uf(self):
        """The fast mode's force user function, a closure over the element's
        arrays and the compiled step's entry point.

        Per Exudyn evaluation it advances the balls in compiled sub-steps to
        t + (H - dt)/2 and returns the mean ring reactions of those sub-steps
        as generalized ring forces (the sub-step windows are centred on the
        Exudyn times, so the ring's and the balls' impulses match:
        :func:`~.kernels.advance_balls`). It runs once per Exudyn step, and its
        Python cost is a large share of the step: bound locals instead of
        attribute look-ups and the compiled entry point instead of numba's
        type dispatch take about a tenth off the step
        (validation/bench_element.py times the result)."""
        ref, params, table, kind, rdata = self.ref, self.params, self.table, self._ring_kind, self._ring_data
        work, rings0, rings, rings_sub = self._work, self._rings0, self._rings, self._rings_sub
        hist, hz, fr, glob, diag, cload, out = (self._hist, self._hz, self._fr, self._glob, self._diag,
                                                self._cage_load, self._out)
        speeds, dt_sub, max_overlap, spin = self._speeds, self._dt_sub, self._max_overlap, EK.RD_SPIN
        clock = self._clock  # [t of the last Exudyn evaluation (nan: none yet), tau, next sample, step checked]
        asarray = np.asarray
        step = _entry_point(EK.fast_step, (asarray(np.zeros(1)), asarray(np.zeros(1)), ref, params, table, kind,
                                           rdata, 1, 0.0, 0.0, 0.0, work, rings0, rings, rings_sub, hist, hz, fr,
                                           glob, diag, cload, False, out))

        def force_uf_fast(mbs, t, itemNumber, q, q_t):
            for r, f in speeds:
                rdata[r, spin] = f(t)
            # Exudyn's vectors become contiguous float64 arrays (one compiled signature)
            q = asarray(q, float)
            q_t = asarray(q_t, float)
            t_int = clock[0]
            if t > t_int + 1e-15:  # False before the first evaluation (nan)
                big = t - t_int
                if not clock[3]:
                    self._check_fast_step(big)
                m = int(big / dt_sub + 0.5) or 1
                t_end = t + 0.5 * (big - big / m)
                tau = clock[1]
                n_sub = int((t_end - tau) * m / big + 0.5) or 1
                want = t >= clock[2] - 1e-12
                worst = step(q, q_t, ref, params, table, kind, rdata, n_sub, tau, t, t_end, work, rings0, rings,
                             rings_sub, hist, hz, fr, glob, diag, cload, want, out)
                clock[0] = t
                clock[1] = t_end
                if not worst <= max_overlap:  # also catches NaN
                    self._check_worst(worst, t)
                if want:
                    self._sample(t_end, rings_sub)
                    clock[2] = self._next_sample
                return out
            if t_int != t_int:
                # first evaluation: forces at the initial state, nothing to integrate yet
                EK.ring_poses_from(q, q_t, ref, kind, rdata, rings)
                forces(params, table, work[0], work[1], work[2], work[3], work[4], rings, hist, hist, dt_sub, hz,
                         work[5], work[6], work[7], fr, glob, diag, cload, False)
                rings0[:] = rings
                clock[0] = clock[1] = t
            elif t < t_int - 1e-15:
                raise RuntimeError("mode: the fast mode integrates the balls forward in time and needs an explicit "
                                   "fixed-step solver (VelocityVerlet, or RK44 with friction='regularized')")
            # no time advance: the last reactions at the current ring poses
            step(q, q_t, ref, params, table, kind, rdata, 0, clock[1], t, t, work, rings0, rings, rings_sub, hist,
                 hz, fr, glob, diag, cload, False, out)
            return out

        return force_uf_fast

    def _after_step(self, t, t0, worst, want, advanced):
        """Runaway check, sampling and bookkeeping after a force evaluation."""
        if advanced:
            if not worst <= self._max_overlap:  # also catches NaN
                self._check_worst(worst, t)
            if want:
                self._sample(t, self._rings)
        self._evaluations += 1
        self._wall += time.perf_counter() - t0
        return self._out

    def _check_fast_step(self, h, stacklevel=4):
        """Warn (once) when the fast mode's Exudyn step ``h`` exceeds the ring
        bodies' stable step or its ball sub-step the balls' stable step."""
        self._clock[3] = True
        dt = h / max(1, int(h / self._dt_sub + 0.5))
        if h > self.ringStableStep:
            warnings.warn(f"subSteps: the Exudyn step {h:.3g} s exceeds the ring bodies' stable-step estimate "
                          f"{self.ringStableStep:.3g} s (ring bodies' inertia against their bearings' contact "
                          "stiffness at initialLoad); the ring motion will be wrong or blow up: use fewer sub-steps",
                          StepSizeWarning, stacklevel=stacklevel)
        msg = step_warning(f"stepSize: the ball sub-step {dt:.3g} s", dt, self.stable)
        if msg:
            warnings.warn(msg, StepSizeWarning, stacklevel=stacklevel)

    def _check_worst(self, worst, t):
        if not math.isfinite(worst) or worst > self.params[L.P_MAX_OVERLAP]:
            ring = (f" and the ring bodies' {self.ringStableStep:.3g} s for the fast mode's Exudyn step (subSteps * "
                    "stepSize)" if self.mode == "fast" and math.isfinite(self.ringStableStep) else "")
            raise RuntimeError(
                f"stepSize: the bearing state became non-finite or runaway at t = {t:.6g} s; the stable-step "
                f"estimate is {self.stable.dt:.3g} s (limited by the {self.stable.limited_by} contact){ring}: "
                "reduce the solver step")

    def _sample(self, t, rings):
        self._store(t, rings)
        self._next_sample += self.sampleInterval * max(1.0, math.floor((t - self._next_sample)
                                                                       / self.sampleInterval) + 1.0)

    def _graphics(self, mbs, itemNumber):
        """Graphics for Exudyn's renderer: balls, cage balls and the two groove
        tori at the last evaluated state (world frame)."""
        import exudyn.graphics as gr

        b = self.bearing
        w = self._work
        data = [gr.Spheres(points=list(w[0]), radii=b.ball_radius, colors=[0.6, 0.6, 0.65, 1.0], nTiles=16)]
        if self.n_cage:
            data.append(gr.Spheres(points=list(w[3, :self.n_cage]), radii=b.cage_ball_radius,
                                   colors=[0.8, 0.6, 0.2, 1.0], nTiles=12))
        for r, ((rho, zg), rc) in enumerate(((b.inner_groove_center, b.inner_groove_radius),
                                             (b.outer_groove_center, b.outer_groove_radius))):
            a = self._rings[r, 6:15].reshape(3, 3)
            centre = self._rings[r, :3] + a[:, 2] * zg
            data.append(gr.Torus(point=list(centre), axis=list(a[:, 2]), radiusMajor=rho, radiusMinor=rc,
                                 color=[0.5, 0.5, 0.55, 0.3], nTilesMajor=48, nTilesMinor=12))
        return data

    def _store(self, t, rings):
        """Sample at t; ``rings``: the ring poses the balls saw there."""
        EK.sample_row(rings, self._work, self._glob, self._diag, self._cage_load, self._row)
        self._sample_t.append(t)
        self._sample_rows.append(self._row.copy())

    @staticmethod
    def _orbital(x, v):
        r2 = x[:, 0] ** 2 + x[:, 1] ** 2
        return (x[:, 0] * v[:, 1] - x[:, 1] * v[:, 0]) / np.where(r2 > 0.0, r2, np.inf)

    def _psi0(self):
        return int(np.argmin(np.abs(np.arctan2(self._work[0, :, 1], self._work[0, :, 0]))))

    # -- user-facing ------------------------------------------------------
    def SimulationSettings(self, endTime, stepSize=None, solverType="VelocityVerlet"):
        """Recommended explicit settings: fixed step ``stepSize`` (default: the
        element's step, times ``subSteps`` in the fast mode), no solution file,
        sensors written every sample interval, sparse linear solver."""
        exu = self._exu
        ss = exu.SimulationSettings()
        h = float(stepSize or self.scenario.dt * (self.subSteps if self.mode == "fast" else 1))
        if self.mode == "fast":
            self._check_fast_step(h, stacklevel=3)
        else:
            msg = step_warning(f"stepSize: {h:.3g} s", h, self.stable)
            if msg:
                warnings.warn(msg, StepSizeWarning, stacklevel=2)
        ss.timeIntegration.numberOfSteps = int(round(endTime / h))
        ss.timeIntegration.endTime = float(endTime)
        ss.timeIntegration.verboseMode = 0
        ss.timeIntegration.explicit.computeMassMatrixInversePerBody = False  # not available for ObjectGenericODE2
        ss.linearSolver.solverType = exu.LinearSolverType.EigenSparse
        ss.timeIntegration.explicit.computeEndOfStepAccelerations = False
        ss.timeIntegration.solverType = getattr(exu.DynamicSolverType, solverType)
        ss.solution.file.write = False
        ss.solution.sensors.writePeriod = self.sampleInterval
        return ss

    def record(self, wall_s=None, steps=None) -> RunRecord:
        """The sampled series of the run as a :class:`~exudyn_bearing.model.record.RunRecord`
        (the same layout as the reference engine's: positions, velocities and
        ring displacement in the outer-ring frame, ball angular velocity
        relative to the outer ring). ``exudyn_bearing.CreateBallBearing``'s
        element also has ``results()``, the same wrapped in
        :class:`~exudyn_bearing.outputs.results.Results`."""
        if not self._sample_t:
            raise RuntimeError("results: no samples yet; run mbs.SolveDynamic first")
        rows = np.array(self._sample_rows)
        data, k = {"t": np.array(self._sample_t)}, 0
        for name, shape in EK.sample_layout(self.z):
            size = int(np.prod(shape))
            data[name] = rows[:, k:k + size].reshape((len(rows), *shape))
            k += size
        steps = self._evaluations if steps is None else steps
        msg = cage_load_check(self.bearing, self.scenario, self.lubricant,
                              float(data["cage_load"].max(initial=0.0)), self.scenario.dt)
        if msg:
            warnings.warn(msg, StepSizeWarning, stacklevel=3)
        return RunRecord(self.bearing, self.scenario, self.lubricant, data, steps=steps,
                         wall_s=self._wall if wall_s is None else wall_s, engine="exudyn", stable_dt=self.stable.dt)
