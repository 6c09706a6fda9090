"""What the Exudyn bearing levels of every solver share (the quasi-static and linear levels,
:mod:`exudyn_bearing.solvers.quasistatic.levels`, and the reduced level, :mod:`exudyn_bearing.solvers.reduced.level`):
the checks of their ring markers, solver and initial load, their sensors' user function and Newton's relative
tolerance (docs/theory/levels.md). Plain Python on Exudyn's MainSystem; no physics."""
from __future__ import annotations

import numpy as np

from ..data import InputError
from ..data.errors import check_finite
from .solver_types import unstable_solver_error

__all__ = ["NEWTON_RELATIVE_TOLERANCE", "check_solver", "load_pair", "level_settings", "rigid_marker",
           "sensor_function"]

#: Newton's relative tolerance in the levels' ``SimulationSettings`` (Exudyn's default: 1e-8)
NEWTON_RELATIVE_TOLERANCE = 1e-4


def level_settings(endTime, stepSize, solverType, sample_interval):
    """A level's fixed-step ``exudyn.SimulationSettings``: ``solverType`` (a name or an
    ``exudyn.DynamicSolverType``; one that does not integrate the levels is refused, :func:`check_solver`),
    ``endTime`` / ``stepSize`` steps, no solution file, sensors written every ``sample_interval``, Newton's
    absolute tolerance 1e-8 and relative tolerance NEWTON_RELATIVE_TOLERANCE (docs/theory/levels.md)."""
    import exudyn as exu

    from ..data.errors import check_positive

    name = solverType if isinstance(solverType, str) else getattr(solverType, "name", str(solverType))
    if not isinstance(getattr(exu.DynamicSolverType, name, None), exu.DynamicSolverType):
        raise InputError(f"solverType: {solverType!r} is not an exudyn.DynamicSolverType")
    check_solver(name)
    h = check_positive("stepSize", stepSize)
    ss = exu.SimulationSettings()
    ss.timeIntegration.endTime = check_positive("endTime", endTime)
    ss.timeIntegration.numberOfSteps = max(1, round(endTime / h))
    ss.timeIntegration.verboseMode = 0
    ss.timeIntegration.solverType = getattr(exu.DynamicSolverType, name)
    # Newton's default absolute tolerance (1e-10) lies below the round-off of the ball equilibrium's forces
    # near a static equilibrium, where the Newton iterations then stall and the step is cut again and again
    ss.timeIntegration.newton.absoluteTolerance = 1e-8
    # modified Newton keeps one Jacobian, which the turning ball set makes stale; 1e-4 instead of the
    # default 1e-8 saves about two evaluations per step, and the motion it changes is below 0.5 % of what
    # halving the step changes (validation/performance/bench_levels.py; docs/theory/levels.md, "Cost")
    ss.timeIntegration.newton.relativeTolerance = NEWTON_RELATIVE_TOLERANCE
    ss.solution.file.write = False
    ss.solution.sensors.writePeriod = sample_interval
    return ss


def load_pair(load):
    """(Fr, Fa) [N] of ``initialLoad``: a pair or a radial load."""
    if isinstance(load, (int, float, np.integer, np.floating)) and not isinstance(load, bool):
        pair = [load, 0.0]
    else:
        try:
            pair = list(load)
        except TypeError:
            pair = []
        if len(pair) != 2:
            raise InputError(f"initialLoad: expected (Fr, Fa) [N] or a radial load Fr, got {load!r}")
    fr, fa = (check_finite("initialLoad", x) for x in pair)
    if fr < 0.0 or fa < 0.0:
        raise InputError(f"initialLoad: Fr and Fa must be >= 0 (+x radial, +z axial on the inner ring), got {load!r}")
    return fr, fa


def rigid_marker(mbs, marker, name):
    """The marker number if it is a rigid-body marker (position and orientation), else InputError."""
    try:
        m = mbs.GetMarker(int(marker))
    except Exception:  # noqa: BLE001 - Exudyn raises its own types for a bad index
        raise InputError(f"{name}: {marker!r} is not a marker of this mbs") from None
    if m["markerType"] not in ("BodyRigid", "NodeRigid"):
        raise InputError(f"{name}: the {m['markerType']} marker has no orientation; the bearing levels connect two "
                         "rigid-body markers (MarkerBodyRigid or MarkerNodeRigid; ground: MarkerBodyRigid on "
                         "ObjectGround)")
    return int(marker)


def marker_start_rotation(mbs, marker):
    """World rotation matrix (3, 3) of the body or node a rigid marker sits on, at t = 0: ground's
    ``referenceRotation``; a node's from its reference plus initial coordinates (Tait-Bryan angles of an Rxyz
    node, the rotation vector of a rotation-vector node, Euler parameters); the identity for a node without
    rotation (a point). What turns the bearings' outer-ring-frame quantities into world components
    (``initialCoordinates``)."""
    from exudyn.rigidBodyUtilities import (EulerParameters2RotationMatrix, RotationVector2RotationMatrix,
                                           RotXYZ2RotationMatrix)

    m = mbs.GetMarker(int(marker))
    if "bodyNumber" in m:
        obj = mbs.GetObject(m["bodyNumber"])
        if obj["objectType"] == "Ground":
            return np.asarray(obj.get("referenceRotation", np.eye(3)), float).reshape(3, 3)
        if "nodeNumber" not in obj:
            return np.eye(3)
        node = obj["nodeNumber"]
    else:
        node = m["nodeNumber"]
    n = mbs.GetNode(int(node))
    q = np.asarray(n["referenceCoordinates"], float) + np.asarray(n.get("initialCoordinates", 0.0), float)
    ntype = n["nodeType"]
    if ntype == "RigidBodyRxyz":
        return np.asarray(RotXYZ2RotationMatrix(q[3:6]), float)
    if ntype == "RigidBodyEP":
        return np.asarray(EulerParameters2RotationMatrix(q[3:7]), float)
    if ntype.startswith("RigidBodyRotVec"):
        return np.asarray(RotationVector2RotationMatrix(q[3:6]), float)
    return np.eye(3)


def world_initial_coordinates(rotation, pose):
    """The 6 initial coordinates of an inner ring's rigid-body node in world components: the ring pose
    ``pose`` (d_x, d_y, d_z, theta_x, theta_y) of the outer ring's frame turned by that frame's world
    ``rotation`` (3, 3): the displacement R d, and the tilt as the small rotation R (theta_x, theta_y, 0) about
    the world axes (the Tait-Bryan or rotation-vector increments of a node whose reference rotation is the
    identity; a turned node takes its tilt in its own parameters)."""
    r = np.asarray(rotation, float)
    d = np.asarray(pose, float)
    return np.array([*(r @ d[:3]), *(r @ np.array([d[3], d[4], 0.0]))])


def check_solver(solver):
    """InputError for a ``solver`` (a name) the levels cannot run with: UNSTABLE_SOLVERS (..model.solver_types),
    which the bearing's stiffness drives unstable (the linear level at 1e-4 s ran away to forces of 1e50 N)."""
    err = unstable_solver_error(solver, "the rings on the bearing's stiffness",
                                "GeneralizedAlpha (recommended), TrapezoidalIndex2, RK44 or VelocityVerlet")
    if err is not None:
        raise err


def sensor_function(value):
    """An Exudyn SensorUserFunction returning ``value()``."""
    return lambda mbs, t, sensorNumbers, factors, configuration: value()


#: the levels' older private names
_load_pair = load_pair
_sensor_function = sensor_function
