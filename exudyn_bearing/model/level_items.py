"""What the Exudyn bearing levels of every solver share (the quasi-static and linear levels,
:mod:`exudyn_bearing.solvers.quasistatic.levels`, and the reduced level, :mod:`exudyn_bearing.solvers.reduced.level`):
the checks of their ring markers, solver and initial load, their sensors' user function and Newton's relative
tolerance (docs/theory/levels.md). Plain Python on Exudyn's MainSystem; no physics."""
from __future__ import annotations

import numpy as np

from ..data import InputError
from ..data.errors import check_finite
from .solver_types import unstable_solver_error

__all__ = ["NEWTON_RELATIVE_TOLERANCE", "check_solver", "load_pair", "rigid_marker", "sensor_function"]

#: Newton's relative tolerance in the levels' ``SimulationSettings`` (Exudyn's default: 1e-8)
NEWTON_RELATIVE_TOLERANCE = 1e-4


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
