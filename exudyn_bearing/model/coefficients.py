"""Linearised bearing coefficients over a speed range: the record that a
solver hands to rotordynamics exports (:mod:`exudyn_bearing.outputs.ross`).

Axes and signs
--------------
Coordinates of the inner ring (the shaft journal) relative to the outer
ring (the housing), in the outer ring's frame: bearing axis z, radial x
(the direction of the applied radial load, psi = 0) and y completing a
right-handed frame, the shaft spinning about +z at the positive speed::

    q = (x [m], y [m], axial z [m], tilt about x [rad], tilt about y [rad])

With F the force and moment the bearing exerts on the shaft,
``stiffness[k, i, j] = -dF_i/dq_j`` and ``damping[k, i, j] = -dF_i/dq'_j``
at speed ``speeds[k]``: the bearing adds +K q + C q' to the left-hand side
of the shaft's equation of motion, as a rotordynamics code's bearing
element does. Units follow from the pair of axes: force per displacement
[N/m], force per tilt [N/rad], moment per displacement [N m/m = N], moment
per tilt [N m/rad]; damping the same per velocity.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..data import InputError

__all__ = ["BearingCoefficients", "AXES", "STIFFNESS_UNITS", "DAMPING_UNITS", "speed_array"]

#: Coordinate order of the 5x5 matrices.
AXES = ("x", "y", "axial", "tilt_x", "tilt_y")
_TRANSLATION = (True, True, True, False, False)


def _unit_table(suffix):
    rows = []
    for ti in _TRANSLATION:
        row = []
        for tj in _TRANSLATION:
            if ti and tj:
                u = "N/m"
            elif ti:
                u = "N/rad"
            elif tj:
                u = "N"
            else:
                u = "N m/rad"
            row.append(u if not suffix else {"N/m": "N s/m", "N/rad": "N s/rad", "N": "N s",
                                             "N m/rad": "N m s/rad"}[u])
        rows.append(tuple(row))
    return tuple(rows)


#: Unit of each entry of the stiffness matrix (rows: force/moment, columns: displacement/tilt).
STIFFNESS_UNITS = _unit_table(False)
#: Unit of each entry of the damping matrix.
DAMPING_UNITS = _unit_table(True)


def speed_array(speeds) -> np.ndarray:
    """``speeds`` [rad/s] as a 1-D float array; InputError unless finite, >= 0 and strictly increasing."""
    try:
        s = np.array(speeds, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise InputError(f"speeds: expected numbers [rad/s], got {speeds!r}") from None
    if s.size == 0:
        raise InputError("speeds: at least one speed is needed")
    if not np.all(np.isfinite(s)) or np.any(s < 0.0):
        raise InputError("speeds: must be finite and >= 0 [rad/s]")
    if s.size > 1 and np.any(np.diff(s) <= 0.0):
        raise InputError("speeds: must be strictly increasing")
    return s


@dataclass(frozen=True)
class BearingCoefficients:
    """Speed-dependent 5x5 stiffness and damping of a bearing (module docstring).

    Parameters
    ----------
    speeds : array (n,)
        Shaft speeds [rad/s], finite, >= 0, strictly increasing.
    stiffness : array (n, 5, 5)
        K at each speed, axis order :data:`AXES` [N/m, N/rad, N, N m/rad].
    damping : array (n, 5, 5)
        C at each speed [N s/m, N s/rad, N s, N m s/rad].
    operating_point : dict
        What the coefficients were computed for (bearing, loads [N],
        clearance [m], ...), JSON-able.
    method : str
        How they were obtained (solver and model).

    Examples
    --------
    >>> k = np.zeros((2, 5, 5)); k[:, 0, 0] = k[:, 1, 1] = 1e8
    >>> c = BearingCoefficients([0.0, 100.0], k, np.zeros((2, 5, 5)))
    >>> c.n_speeds, c.axes[2], c.units["stiffness"][3][3]
    (2, 'axial', 'N m/rad')
    """

    speeds: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    operating_point: dict = field(default_factory=dict, compare=False)
    method: str = ""

    def __post_init__(self):
        s = speed_array(self.speeds)
        try:
            k = np.array(self.stiffness, dtype=float)
            c = np.array(self.damping, dtype=float)
        except (TypeError, ValueError) as exc:
            raise InputError(f"stiffness: coefficients must be numeric arrays ({exc})") from None
        for name, a in (("stiffness", k), ("damping", c)):
            if a.shape != (s.size, 5, 5):
                raise InputError(f"{name}: expected shape ({s.size}, 5, 5) (one 5x5 matrix per speed, axes "
                                 f"{', '.join(AXES)}), got {a.shape}")
            if not np.all(np.isfinite(a)):
                raise InputError(f"{name}: entries must be finite")
        if not isinstance(self.operating_point, dict):
            raise InputError(f"operating_point: expected a dict, got {type(self.operating_point).__name__}")
        for a in (s, k, c):
            a.setflags(write=False)
        object.__setattr__(self, "speeds", s)
        object.__setattr__(self, "stiffness", k)
        object.__setattr__(self, "damping", c)

    @property
    def axes(self) -> tuple:
        """Axis order of the matrices, :data:`AXES`."""
        return AXES

    @property
    def n_speeds(self) -> int:
        return int(self.speeds.size)

    @property
    def units(self) -> dict:
        """Units of speeds and of every matrix entry."""
        return {"speeds": "rad/s", "stiffness": [list(r) for r in STIFFNESS_UNITS],
                "damping": [list(r) for r in DAMPING_UNITS]}

    def index(self, axis: str) -> int:
        """Position of an axis name in :data:`AXES`."""
        try:
            return AXES.index(axis)
        except ValueError:
            raise InputError(f"axis: unknown axis {axis!r} (valid: {', '.join(AXES)})") from None

    def rpm(self) -> np.ndarray:
        """Speeds in revolutions per minute."""
        return self.speeds * 60.0 / (2.0 * math.pi)

    def to_dict(self) -> dict:
        """JSON-able dict (lists), with ``axes`` and ``units``."""
        return {"speeds": self.speeds.tolist(), "stiffness": self.stiffness.tolist(),
                "damping": self.damping.tolist(), "axes": list(AXES), "units": self.units,
                "operating_point": dict(self.operating_point), "method": self.method}

    @classmethod
    def from_dict(cls, d: dict) -> "BearingCoefficients":
        """Inverse of :meth:`to_dict` (axes must be :data:`AXES`)."""
        if "axes" in d and tuple(d["axes"]) != AXES:
            raise InputError(f"axes: expected {list(AXES)}, got {d['axes']!r}")
        missing = [k for k in ("speeds", "stiffness", "damping") if k not in d]
        if missing:
            raise InputError(f"{missing[0]}: missing from the coefficient dict")
        return cls(d["speeds"], d["stiffness"], d["damping"], dict(d.get("operating_point", {})),
                   str(d.get("method", "")))
