"""Exudyn ball-bearing element: a lubricated DEM ball bearing between two ring markers.

::

    import exudyn_bearing as eb
    bearing = eb.CreateBallBearing(mbs, eb.catalog["6208"], markerInnerRing=mShaft,
                                   markerOuterRing=mHousing)
    mbs.Assemble(); mbs.SolveDynamic(bearing.SimulationSettings(endTime=0.1), solverType=...)
    bearing.results().summary()

The balls and cage balls are Exudyn nodes (6
coordinates each: position and an integrated global rotation vector whose
rate is the angular velocity, with the constant mass matrix of a sphere:
exact Newton-Euler for a homogeneous sphere, whose orientation never enters
the forces, and free of rotation-parameter singularities at 1000 rad/s) of
two ObjectGenericODE2. The first (``items["object"]``) holds the first ball
and the nodes of the ring bodies (with zero mass there: their mass is in
their own bodies); its ``forceUserFunction`` reads the coordinates of all
balls and rings from the system at once, makes one compiled call per force
evaluation into the same contact kernel as the reference engine (elliptic
Hertz, Lambda-switched damping and friction, Cundall-Strack history, torus
cage), returns the first ball's forces and the ring reactions as
generalized forces of the ring nodes, and writes the other balls' forces
into the force vector of the second object (``items["ballObject"]``),
which Exudyn evaluates after it: consistent within every evaluation, and
without Exudyn's per-coordinate conversion of a large object's coordinates
and forces to and from Python (validation/performance/profile_element.py). The body
mode therefore needs ``parallel.numberOfThreads = 1`` and, under an
implicit solver, the system-wide numerical Jacobian
(``newton.numericalDifferentiation.doSystemWideDifferentiation``, which
``SimulationSettings`` sets); other settings raise InputError naming them.

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
``subSteps=1`` (default) it reproduces the body mode at about 0.6 of its cost.
More sub-steps spread the per-step overhead further; the Exudyn step H =
subSteps * stepSize then also integrates the ring bodies against the contact
stiffness, staggered with the balls: with two or more sub-steps keep it below
``fastStepLimit``, 0.25 of ``ringStableStep`` (estimated from the ring
bodies' mass matrices and the contact stiffness of all bearings on them at
their ``initialLoad``; one sub-step is the body mode's scheme, bounded by
``ringStableStep``); a larger step warns. Heavy rings (a ring on a rotor) take more sub-steps than
a bare ring, which takes one or two. See validation/REPORT.md for the
measured limits (``validation/studies/fast_mode_limits.py``).

Rigid cage (``cage="rigid"``, ``rigidCage``, ``gravity``; both modes): the
contact kernel's rigid cage (docs/theory/cage.md). In the body mode an
Exudyn rigid body (``cageNode``, ``cageBody``, ``cageMarker``: a
NodeRigidBodyRxyz with an ObjectRigidBody, its tilts held by
CoordinateConstraints) whose node joins the ball object with zero mass, so
that the user function reads its state and returns its force and moment as
for the balls; in the fast mode it is integrated with the balls in their
sub-steps. The bearing axis may point anywhere (a shaft along the world x
axis included): the cage moves in ``cageFrame``, the outer ring's frame at
t = 0, where gravity (given in the world) acts and the samples report it
(docs/theory/cage.md#in-the-exudyn-element).

Defects and signals (both modes): ``defects`` (:class:`exudyn_bearing.data.Defect`
objects or dicts) puts localized spalls into the contact model; an
inner-race spall turns with the ring body's rotation, or with the integrated
``innerRingSpeed`` of a mass-point ring; a ball spall turns with its ball's
body frame, advanced at the committed evaluations like the Cundall-Strack
history. ``signalInterval`` records the housing force and the inner-ring
acceleration and speed as series (VelocityVerlet; ``results().signal(name)``).

Solvers, both modes: VelocityVerlet (recommended; one force evaluation per
step, so the Cundall-Strack history is exactly the reference engine's) and
RK44 with ``friction="regularized"`` (history-free; the fast mode advances
the balls at RK44's increasing stage times): with ``friction="history"``
the body mode refuses the explicit solvers that evaluate more than once per
step (RK44, ExplicitMidpoint, ...; InputError naming ``solverType``), the
rule and message of ``Scenario(integrator="rk4")``
(:func:`~exudyn_bearing.model.scenario.history_friction_error`). ExplicitEuler is refused
(InputError naming ``solverType``, in ``SimulationSettings`` and at a run's
first evaluation): its stability region leaves out the undamped contact
oscillation, which it holds only at about 1/16 of the stable step.
ExplicitMidpoint in the body mode takes at most half the stable-step
estimate (InputError naming ``stepSize``; above it the ball loads end
wrong).
Implicit solvers work in the body mode with the numerical Jacobian but are
not recommended (EXUDYN_NOTES: an order of magnitude slower for Hertz
contact: several force evaluations per step, plus those of the numerical
Jacobian; validation/performance/bench_element.py --ga times it). The fast mode needs
an explicit solver whose evaluations never go back in time (its balls
advance at the first evaluation of a new time and ignore Newton iterations
there): ``SimulationSettings`` and the first
evaluation of a run under an implicit solver, or under RK67, ODE23, DOPRI5
or DVERK6 (stage times out of order, rejected adaptive steps), raise
InputError naming ``mode``, and so does an evaluation back in time within a
run.

Repeated solves: Exudyn starts every ``mbs.SolveDynamic`` at
``startTime`` from the initial state. A run that starts where the
element's last one ended (``startTime`` equal to its last time, with the end
state copied into the initial state, ``mbs.systemData.SetSystemState(
mbs.systemData.GetSystemState(exu.ConfigurationType.Current),
exu.ConfigurationType.Initial)``) continues it: samples append, the contact
history and the fast mode's balls carry on. Any other run starts over: the
element's samples, step count, contact history and the fast mode's balls
return to their initial state, so the same run twice gives the same results.
Errors inside a solve: a blow-up raises ``SimulationError``; Exudyn
re-raises a user function's exception as its ModelError (a ValueError)
with the original as ``__cause__``;
:func:`~exudyn_bearing.solvers.element.engine.solve_dynamic` hands on the
original.
"""
from __future__ import annotations

import inspect
import math
import warnings

import numpy as np

from ..._jit import announce_compilation
from ...data import InputError, Lubricant, default_traction, load_bearing, load_lubricant
from ...data.errors import check_finite, check_positive
from ...data.traction import DEFAULT_REGULARIZING_SRR
from ...model import layout as L
from ...model.contact import forces
from ...model.initial_state import initial_state
from ...model.level_items import world_initial_coordinates
from ...model.load_angle import check_load_angle, load_rotation
from ...model.motion import ring_poses
from ...model.parameters import scene_parameters
from ...physics.losses import HYSTERESIS_LOSS_FACTOR_STEEL
from ...model.scenario import Scenario, resolve_cage
from ...model.stability import (FAST_STEP_SHARE, StepSizeWarning, ring_contact_stiffness, stable_step,
                                step_warning)
from ...physics import hertz
from ...physics.contact_slip import DEFAULT_N_ACROSS, DEFAULT_N_STRIPS
from . import kernels as EK
from .items import ItemsMixin
from .markers import RING_REGISTRY, initial_ring_pose, ring_from_marker, ring_mobility
from .sensors import SensorsMixin
from .signals import SignalsMixin
from .userfunctions import UserFunctionsMixin, solver_error

__all__ = ["BallBearingElement", "OPTION_NAMES"]

#: Scenario field -> the element's option of the same meaning (for error messages).
OPTION_NAMES = {"Fr": "initialLoad", "Fa": "initialLoad", "omega": "initialOmega", "dt": "stepSize",
                "sample_dt": "sampleInterval", "hertz": "hertzModel", "guide_clearance": "guideClearance",
                "mu_dry": "muDry", "regularizing_speed": "regularizingSpeed", "cage_damping": "cageDamping",
                "tangential_stiffness_ratio": "tangentialStiffnessRatio", "contact_law": "contactLaw",
                "power_law": "powerLaw", "traction_level": "tractionLevel", "n_strips": "nStrips",
                "n_across": "nAcross", "traction_regularizing_srr": "tractionRegularizingSrr",
                "ring_growth": "ringGrowth", "signal_dt": "signalInterval",
                "rolling_resistance": "rollingResistance", "ball_drag": "ballDrag",
                "oil_volume_fraction": "oilVolumeFraction", "hysteresis_loss_factor": "hysteresisLossFactor",
                "rigid_cage": "rigidCage", "pocket_film": "pocketFilm"}


def _initial_load(load):
    """(Fr, Fa) of ``initialLoad``: a pair (Fr, Fa) or a number Fr (radial only)."""
    if isinstance(load, (str, bytes)) or not hasattr(load, "__len__"):
        return check_finite("initialLoad", load), 0.0
    if len(load) != 2:
        raise InputError(f"initialLoad: expected (Fr, Fa) [N] or a radial load Fr, got {load!r}")
    return check_finite("initialLoad", load[0]), check_finite("initialLoad", load[1])


def rename_option_error(exc: InputError) -> InputError:
    """The InputError of a Scenario field with the element's option name (``OPTION_NAMES``)."""
    name, _, rest = str(exc).partition(":")
    head, dot, tail = name.partition(".")
    return InputError(f"{OPTION_NAMES.get(head, head)}{dot}{tail}:{rest}")


def _scenario_from_options(o: dict, bearing) -> Scenario:
    """The Scenario of the element's options ``o`` (all of them, by name) on ``bearing``: model switches are
    validated there, their messages renamed to the options; loads come from the model; the traction model
    defaults to the bearing's."""
    fr, fa = _initial_load(o["initialLoad"])
    step = check_positive("stepSize", o["stepSize"])
    sample = check_positive("sampleInterval", o["sampleInterval"])
    try:
        return Scenario(Fr=fr, Fa=fa, omega=check_finite("initialOmega", o["initialOmega"]), cage=o["cage"],
                        rigid_cage=o["rigidCage"], gravity=o["gravity"], pocket_film=o["pocketFilm"],
                        lubrication=o["lubrication"], friction=o["friction"], tangential=o["tangential"],
                        cage_damping=o["cageDamping"],
                        hertz=o["hertzModel"], film=o["film"], guide_clearance=o["guideClearance"], mu_dry=o["muDry"],
                        regularizing_speed=o["regularizingSpeed"],
                        tangential_stiffness_ratio=o["tangentialStiffnessRatio"], dt=step,
                        sample_dt=max(sample, step), initial=o["initial"], contact_law=o["contactLaw"],
                        power_law=o["powerLaw"], traction_level=o["tractionLevel"],
                        traction=o["traction"] if o["traction"] is not None else default_traction(bearing),
                        n_strips=o["nStrips"], n_across=o["nAcross"],
                        traction_regularizing_srr=o["tractionRegularizingSrr"], ring_growth=o["ringGrowth"],
                        temperatures=o["temperatures"], control=o["control"], defects=o["defects"],
                        signal_dt=o["signalInterval"], rolling_resistance=o["rollingResistance"],
                        ball_drag=o["ballDrag"], oil_volume_fraction=o["oilVolumeFraction"],
                        hysteresis_loss_factor=o["hysteresisLossFactor"],
                        t_end=max(0.05, sample, step))  # the run's end is the solver's
    except InputError as exc:
        raise rename_option_error(exc) from None


def element_scenario(bearing=None, **options) -> Scenario:
    """The Scenario the element builds from ``options`` (those of
    :class:`BallBearingElement`, defaults filled in), validated as the element
    validates them; an unknown option raises InputError naming it."""
    sig = inspect.signature(BallBearingElement.__init__)
    names = [n for n in sig.parameters if n not in ("self", "mbs", "bearing", "markerInnerRing", "markerOuterRing")]
    unknown = sorted(set(options) - set(names))
    if unknown:
        raise InputError(f"{unknown[0]}: unknown option of the bearing element (valid: {', '.join(names)})")
    o = {n: sig.parameters[n].default for n in names}
    o.update(options)
    if bearing is None:
        return _scenario_from_options(o, None)
    b = load_bearing(bearing)
    try:
        return resolve_cage(_scenario_from_options(o, b), b)
    except InputError as exc:  # the resolved cage refused with the element's option names
        raise InputError(str(exc).replace("rigid_cage", "rigidCage")) from None


class BallBearingElement(ItemsMixin, UserFunctionsMixin, SensorsMixin, SignalsMixin):
    """A DEM ball bearing inside an Exudyn model (see the module docstring).

    Attributes
    ----------
    items : dict
        Created Exudyn items: ``ballNodes``, ``cageNodes``, ``object`` (the
        object with the force user function), ``ballObject`` (body mode: the
        other balls' object, None in the fast mode), ``ringNodes`` (ring nodes
        that joined the object), ``cageNode``, ``cageBody``, ``cageMarker``,
        ``cageConstraints`` (the rigid cage, below), ``sensors``.
    cageNode, cageBody, cageMarker : int or None
        With ``cage="rigid"`` in the body mode: the rigid cage's
        NodeRigidBodyRxyz, its ObjectRigidBody (mass and polar inertia of
        ``rigidCage``, the bearing's estimated cage when None) and a
        MarkerBodyRigid at its centre, for the user's sensors, markers and
        connectors; its tilts are held by two CoordinateConstraints
        (``items["cageConstraints"]``). None otherwise (the fast mode
        integrates the cage inside the element; docs/theory/cage.md#in-the-exudyn-element).
        The body turns about the bearing axis by its node's third angle (about
        its local z), or by its first (about its local x) when the axis is the
        world x axis (docs/theory/cage.md#in-the-exudyn-element).
    cageFrame : ndarray (3, 3) or None
        With ``cage="rigid"``: the rigid cage's bearing frame, its axes in the
        columns (the third the bearing axis): the outer ring's frame at t = 0.
        The cage moves in it, gravity acts in it (``scenario.gravity`` holds the
        option's world gravity in its components) and the land force of the
        samples (``glob``) is in it. None otherwise.
    sensors : dict
        Sensor numbers (``cageSpeed``: mean orbital speed of the cage balls, the rigid cage's spin about the
        bearing axis; ``qMaxInner``, ``qMaxOuter``,
        ``lambdaOuterPsi0``, ``innerRingForce``, ``outerRingForce``: force of
        the balls on the ring [N]), stored internally: use
        ``mbs.PlotSensor`` or ``mbs.GetSensorStoredData``.
    initialRingDisplacement : ndarray
        Displacement of the inner ring (outer-ring frame) in the analytic
        initial state; place the inner ring there to start in equilibrium.
    stable : StableStep
        Stable-step estimate of the ball contacts (``stable.dt``).
    ringStableStep : float
        Fast mode: the largest stable Verlet step [s] of the ring bodies alone
        on the ball contacts of all bearings on them (property, see its docstring).
    fastStepLimit : float
        Fast mode with two or more sub-steps: the largest Exudyn step [s] that
        keeps the ball loads, 0.25 of ``ringStableStep`` (property).

    Options are those of :func:`exudyn_bearing.CreateBallBearing`;
    ``cage`` is "torus" (True), "rigid" or "none" (False), ``rigidCage`` the
    :class:`~exudyn_bearing.data.cages.RigidCage` of ``cage="rigid"`` (None:
    the bearing's estimated cage) and ``gravity`` (g_x, g_y, g_z) [m/s^2,
    world frame] the gravity the element applies on the rigid cage (give it
    here rather than as a load on ``cageBody``: the element's energy balance
    counts it as drive), ``pocketFilm`` the oil film between ball and pocket
    (``Scenario.pocket_film``);
    ``initialLoad`` is (Fr, Fa) [N] or a radial load Fr, its radial part along ``loadAngle`` [rad] from
    the outer ring's x axis (default 0, as the levels); an invalid option
    raises InputError naming it (``stepSize``, ``sampleInterval``,
    ``initialLoad``, ``markerOuterRing``, ...).
    """

    def __init__(self, mbs, bearing, markerInnerRing, markerOuterRing, lubricant: Lubricant | None = None,
                 cage="auto", lubrication=True, friction="history", tangential="explicit", hertzModel="exact",
                 film="hd", guideClearance=50e-6, muDry=0.1, regularizingSpeed=0.1,
                 tangentialStiffnessRatio=2.0 / 3.0, stepSize=1e-6, innerRingSpeed=None, outerRingSpeed=None,
                 initialOmega=0.0, initialLoad=(0.0, 0.0), initial="analytic", sampleInterval=1e-4,
                 mode="bodies", subSteps=1, contactLaw="hertz", powerLaw=(0.0, 1.5, 0.0), tractionLevel="point",
                 traction=None, nStrips=DEFAULT_N_STRIPS, nAcross=DEFAULT_N_ACROSS,
                 tractionRegularizingSrr=DEFAULT_REGULARIZING_SRR, ringGrowth=True,
                 temperatures=None, control="auto", initialState=None, defects=(),
                 signalInterval=None, rollingResistance=False, ballDrag=False, oilVolumeFraction=0.0,
                 hysteresisLossFactor=HYSTERESIS_LOSS_FACTOR_STEEL, cageDamping="explicit", rigidCage=None,
                 gravity=(0.0, 0.0, 0.0), pocketFilm=False, show=False, loadAngle=0.0):
        announce_compilation(forces, EK.fast_step if mode == "fast" else EK.body_step)
        self.mbs = mbs
        self.bearing = b = load_bearing(bearing)
        self.lubricant = load_lubricant(lubricant, bearing=b)   # None: the bearing's
        for name, f in (("innerRingSpeed", innerRingSpeed), ("outerRingSpeed", outerRingSpeed)):
            if f is not None and not callable(f):
                raise InputError(f"{name}: must be a function of time t [s] returning rad/s")
        self.speed = (innerRingSpeed, outerRingSpeed)
        self._initial_state = initialState
        #: azimuth of the radial load in the outer-ring frame [rad] (the levels' option): the initial state's
        #: balls and ring displacement are turned about z from +x to it
        self.loadAngle = check_load_angle(loadAngle)
        self.scenario = resolve_cage(_scenario_from_options(dict(locals()), b), b)  # "auto": the bearing's cage
        sampleInterval = check_positive("sampleInterval", sampleInterval)
        if self.scenario.cage == "torus" and not b.has_cage:
            raise InputError(f"cage: bearing {b.name} has no cage balls; use cage='rigid' (a rigid cage body) or "
                             "cage=False")
        self.rigid = self.scenario.cage == "rigid"
        # the kernel's rigid cage (model.parameters): the scenario's, or the bearing's estimated one
        self._cage_geometry = self.scenario.rigid_cage_of(b) if self.rigid else None
        self.table = hertz.exact_table()
        self.sampleInterval = float(sampleInterval)
        # rings
        self.rings_spec = [ring_from_marker(mbs, markerInnerRing, "Inner"),
                           ring_from_marker(mbs, markerOuterRing, "Outer")]
        self.markers = (markerInnerRing, markerOuterRing)
        (kind_i, node_i, *_), (kind_o, node_o, *_) = self.rings_spec
        if int(markerInnerRing) == int(markerOuterRing):
            raise InputError(f"markerOuterRing: marker {markerOuterRing} is also markerInnerRing; the rings need "
                             "their own markers (the outer ring on ground or on a housing body)")
        if kind_i != EK.RING_FIXED and node_i == node_o:
            raise InputError(f"markerOuterRing: on node {node_o}, the node of markerInnerRing; both rings on one "
                             "body would carry the bearing's forces on itself")
        poses = [initial_ring_pose(mbs, *spec) for spec in self.rings_spec]
        #: the outer ring's world rotation at t = 0 (its frame is the engine's: initialCoordinates turns by it)
        self._outer_rotation = np.asarray(poses[1][1], float)
        axis_i, axis_o = poses[0][1][:, 2], poses[1][1][:, 2]
        if abs(float(axis_i @ axis_o)) < 1.0 - 1e-9:
            raise InputError("markerInnerRing: the ring axes (local z of both ring bodies) are not parallel "
                             f"(angle {math.degrees(math.acos(min(1.0, abs(float(axis_i @ axis_o))))):.3g} deg)")
        #: the rigid cage's bearing frame (columns: its axes in the world, the third the bearing axis: the outer
        #: ring's frame at t = 0; None without the rigid cage), its node's angles and the cage's angle where the
        #: node's turning angle is 0 (kernels.cage_frame)
        self.cageFrame, self._cage_angles, self._cage_offset = (EK.cage_frame(poses[1][1]) if self.rigid
                                                                else (None, None, 0.0))
        if self.rigid:  # gravity, given in the world, in the bearing frame the kernel takes it in
            self.scenario = self.scenario.replace(gravity=tuple(float(g) for g in self.cageFrame.T
                                                                @ np.asarray(self.scenario.gravity, float)))
        self.params = scene_parameters(b, self.scenario, self.lubricant)
        if self.rigid:
            self.params[L.P_CAGE_FRAME:L.P_CAGE_FRAME + 9] = self.cageFrame.ravel()
            self.params[L.P_CAGE_ANGLE0] = self._cage_offset
        self.stable = stable_step(b, self.scenario, self.lubricant)
        xb, vb, wb, xc, vc = self._place_balls(poses)
        n_cage = b.n_balls if self.scenario.cage == "torus" else 0
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
        self._ring_mobility = [ring_mobility(mbs, mk, sp[0], sp[2]) for mk, sp in zip(self.markers, self.rings_spec)]
        self._ring_stiffness = [ring_contact_stiffness(b, self.scenario, race) for race in ("inner", "outer")]
        registry = mbs.variables.setdefault(RING_REGISTRY, {})
        for r, sp in enumerate(self.rings_spec):
            if sp[0] != EK.RING_FIXED:
                registry.setdefault(int(sp[1]), []).append((self, r))
        nodes, cage_nodes, ring_nodes, obj = self._add_items(mbs, xb, vb, wb, xc, vc, n_cage, fast, show)
        self._add_sensors(mbs, n_cage)
        self.items = {"ballNodes": nodes, "cageNodes": cage_nodes, "ringNodes": ring_nodes, "object": obj,
                      "ballObject": self._ball_object, "cageNode": self.cageNode, "cageBody": self.cageBody,
                      "cageMarker": self.cageMarker, "cageConstraints": self._cage_constraints,
                      "sensors": dict(self.sensors)}
        import exudyn

        self._exu = exudyn

    def _place_balls(self, poses):
        """Balls and cage balls of the analytic initial state (outer-ring frame)
        placed in the world at the rings' poses; checks that the rings are
        concentric within the play and that no ball overlaps beyond the
        preload. Returns (xb, vb, wb, xc, vc)."""
        b = self.bearing
        st = dict(initial_state(b, self.scenario, self._initial_state))
        if self.loadAngle != 0.0:  # the load along loadAngle instead of +x: the state turned about z
            rz = load_rotation(self.loadAngle)
            rigid = self.scenario.cage == "rigid"  # its cage rows hold (axial position, angle, speed): turn the angle
            for k in ("xb", "vb", "wb") + (() if rigid else ("xc", "vc")):
                st[k] = np.asarray(st[k], float) @ rz.T
            if rigid:
                st["xc"] = np.array(st["xc"], float)
                st["xc"][1, 0] += self.loadAngle
            ring = np.asarray(st["ring"], float)
            st["ring"] = np.concatenate([rz @ ring[:3], rz @ ring[3:6], ring[6:]])
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
        xb = st["xb"] @ a_o.T + x_o
        vb = st["vb"] @ a_o.T + v_o + np.cross(w_o, xb - x_o)
        wb = st["wb"] @ a_o.T + w_o
        xc = st["xc"] @ a_o.T + x_o
        vc = st["vc"] @ a_o.T + v_o + np.cross(w_o, xc - x_o)
        if self.scenario.cage == "rigid":
            # the rigid cage's rows (model.layout): its centre as a point, its angle and spin about the bearing
            # axis in the bearing frame offset by the outer ring's
            xc[1:], vc[1:] = 0.0, 0.0
            angle, spin = self._outer_ring_turn(a_o[:, 0], w_o)
            xc[1, 0] = st["xc"][1, 0] + angle
            vc[1, 0] = st["vc"][1, 0] + spin
        allowed = max(0.0, -0.5 * b.diametral_clearance) + 2.0 * max(float(st.get("max_overlap", 0.0)), 0.0) + 1e-7
        self._check_overlap(xb, poses, allowed)
        return xb, vb, wb, xc, vc

    def _outer_ring_turn(self, x_axis, omega):
        """(angle [rad], spin [rad/s]) of the outer ring about the bearing axis in the rigid cage's bearing frame
        (``cageFrame``): the angle from e1 of the ring's x axis ``x_axis`` (world), and its angular velocity
        ``omega`` (world) along e3. The frame is the outer ring's at t = 0: its angle is 0 until it turns."""
        u = self.cageFrame.T @ np.asarray(x_axis, float)
        return math.atan2(u[1], u[0]), float(self.cageFrame[:, 2] @ np.asarray(omega, float))

    @property
    def initialCoordinates(self):
        """The 6 initial coordinates of the inner ring's rigid-body node in the analytic initial state, in
        world components: the displacement ``initialRingDisplacement`` [m] (outer ring's frame) turned by the
        outer ring's world rotation at t = 0, and rotation (0, 0, 0) (any rotation parameters: the initial
        state has no tilt); for ``mbs.SetNodeParameter(node, "initialCoordinates", ...)`` of the shaft's node
        (model.level_items.world_initial_coordinates). The bearing levels' property has the same meaning and
        length."""
        return world_initial_coordinates(self._outer_rotation, [*self.initialRingDisplacement, 0.0, 0.0])

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

    @property
    def fastStepLimit(self):
        """Largest Exudyn step [s] of the fast mode with two or more sub-steps (subSteps * stepSize) that
        keeps the ball loads: ``FAST_STEP_SHARE`` (0.25) of ``ringStableStep`` (the staggered coupling of
        ring and balls, not the ring's own Verlet limit, sets it: ``model.stability.FAST_STEP_SHARE``); a
        larger step warns. One sub-step is the body mode's scheme, bounded by ``ringStableStep`` alone."""
        return FAST_STEP_SHARE * self.ringStableStep

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
                 np.zeros((z, 3)), rings, np.zeros((z, 2, 3)), np.zeros((z, 2, 3)), 0.0, np.zeros((z, 2, L.HZ_N)),
                 np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((2, 6)), np.zeros(L.NGLOBAL),
                 diag, np.zeros((z, 2)), True)
        worst = float(np.max(diag[:, :, 1]))
        if worst > allowed:
            raise InputError(f"markerInnerRing: the initial ring placement overlaps balls by {worst:.3e} m, beyond "
                             f"the preload and load overlap {allowed:.3e} m; check the ring positions")

    # -- user-facing ------------------------------------------------------
    def SimulationSettings(self, endTime, stepSize=None, solverType="VelocityVerlet"):
        """Recommended explicit settings: fixed step ``stepSize`` (default: the
        element's step, times ``subSteps`` in the fast mode), no solution file,
        sensors written every sample interval, sparse linear solver.
        ``solverType``: a name of ``exudyn.DynamicSolverType`` or one of its
        values; the fast mode refuses the implicit solvers."""
        exu = self._exu
        name = solverType if isinstance(solverType, str) else getattr(solverType, "name", str(solverType))
        if not isinstance(getattr(exu.DynamicSolverType, name, None), exu.DynamicSolverType):
            raise InputError(f"solverType: {solverType!r} is not an exudyn.DynamicSolverType")
        check_positive("endTime", endTime)
        if stepSize is not None:
            check_positive("stepSize", stepSize)
        ss = exu.SimulationSettings()
        h = float(stepSize or self.scenario.dt * (self.subSteps if self.mode == "fast" else 1))
        err = solver_error(self.mode, name, h, self.stable.dt, self.scenario.cage_damping, self.scenario.friction)
        if err is not None:
            raise err
        if solverType != "VelocityVerlet" and (self._sig is not None
                                               or any(d.race == "ball" for d in self.scenario.defects)):
            raise InputError(f"solverType: signals (signalInterval) and ball defects need VelocityVerlet (one force "
                             f"evaluation per step), got {solverType!r}")
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
        # implicit solvers: the body mode's numerical Jacobian over the whole system (userfunctions.body_settings_error)
        ss.timeIntegration.newton.numericalDifferentiation.doSystemWideDifferentiation = True
        ss.timeIntegration.solverType = getattr(exu.DynamicSolverType, name)
        ss.solution.file.write = False
        ss.solution.sensors.writePeriod = self.sampleInterval
        return ss
