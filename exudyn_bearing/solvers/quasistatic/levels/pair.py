"""``CreateBallBearing(..., model="quasistatic", arrangement="DB"|"DF"|"DT", preload=..., spacing=...)``: a pair
of identical angular-contact bearings between two ring markers, as one 5-DOF force element.

The connector's pose u (shaft against housing at the pair's centre, the outer-ring marker's frame, as in
:mod:`.base`) moves bearing k, with its ball-set plane at z_k and possibly turned round (frame rotated by pi
about x), exactly as in :func:`~exudyn_bearing.solvers.quasistatic.pair.solve_pair` (docs/theory/pairs.md):
displacement (d_x + theta_y z_k, d_y - theta_x z_k, d_z), the same Tait-Bryan angles, velocity
(v_x + w_y z_k, v_y - w_x z_k, v_z) and angular velocity w; turned: (x, y, z) -> (x, -y, -z) for all four
(Tait-Bryan angles (a, b, c) -> (a, -b, -c) exactly), plus the preload offset of its inner ring along its own
axis. Each bearing is the quasi-static level's evaluation (:class:`.element.QuasiStaticBearing`: ball
equilibrium, kinematic cage, contact damping); the pair's force is sum_k T_k^T F_k. Sensors and samples are
those of :class:`.base.LevelBearing` (force and pose of the pair, q_max the larger of the two bearings').
"""
from __future__ import annotations

import math

import numpy as np

from ....data import InputError, load_bearing, load_lubricant
from ....data.errors import check_finite, check_plausible, check_positive
from ..pair import solve_pair
from .base import (
    LOAD_ANGLE_RANGE,
    WS_CAGE,
    WS_FORCE,
    WS_HEADER,
    WS_OUT,
    WS_POSE,
    WS_QMAX,
    LevelBearing,
    _load_pair,
    rigid_marker,
)
from .element import QuasiStaticBearing

__all__ = ["PAIR_OPTIONS", "PairBearing", "create_pair_level"]

#: Options of a pair level (besides those of the quasi-static level without its coefficient table).
PAIR_OPTIONS = ("arrangement", "preload", "spacing")


class _Member(QuasiStaticBearing):
    """One bearing of a pair: the quasi-static level's evaluation without a connector, markers or table."""

    def __init__(self, bearing, lubricant, initialOmega, ringGrowth, temperatures, hertzModel, cageAngle):
        self.bearing = bearing
        self.lubricant = lubricant
        self.initialOmega, self.ringGrowth, self.temperatures = initialOmega, ringGrowth, temperatures
        self.hertzModel = hertzModel
        self._cage0 = cageAngle
        from ....physics import kinematics as _kin

        a0 = bearing.free_contact_angle
        self.cageRatio = float(_kin.cage_speed(1.0, 0.0, bearing.ball_radius, bearing.pitch_radius, a0))
        self.spinRatio = float(_kin.ball_spin_relative(1.0, 0.0, bearing.ball_radius, bearing.pitch_radius, a0))
        self._q_limit = self._ball_load_limit()
        self._ws = np.zeros(WS_HEADER + self._workspace_size())
        self._out, self._force = self._ws[WS_OUT:WS_OUT + 6], self._ws[WS_FORCE:WS_FORCE + 5]
        self._pose, self._cage = self._ws[WS_POSE:WS_POSE + 5], self._ws[WS_CAGE:WS_CAGE + 2]
        self._qmax = self._ws[WS_QMAX:WS_QMAX + 3]
        self._t_last = 0.0
        self.restarts, self._samples, self._next_sample, self._evaluations = 0, [], 0.0, 0
        self._setup()


class PairBearing(LevelBearing):
    """A bearing pair as one quasi-static level (module docstring). ``initialLoad`` (Fr, Fa) on the shaft
    at the pair's centre (Fa either sign for DB / DF), ``arrangement``, ``preload`` and ``spacing`` (required:
    the shaft tilts) as in solve_pair; ``initialRingDisplacement`` / ``initialCoordinates`` the pair's
    equilibrium under initialLoad; ``operatingPoint`` its PairSolution."""

    model = "quasistatic"

    def __init__(self, mbs, bearing, markerInnerRing, markerOuterRing, arrangement="DB", preload=None,
                 spacing=None, lubricant=None, initialLoad=(0.0, 0.0), loadAngle=0.0, initialOmega=0.0,
                 ringGrowth=True, temperatures=None, hertzModel="exact", sampleInterval=1e-4, show=False,
                 cageAngle=0.0):
        self.mbs = mbs
        self.bearing = b = load_bearing(bearing)
        if spacing is None:
            raise InputError("spacing: a pair between two markers needs the distance between the two bearings' "
                             "ball-set planes [m] (the shaft tilts)")
        self.lubricant = None if lubricant is None else load_lubricant(lubricant)
        fr, fa = self.initialLoad = _signed_load(initialLoad)
        self.initialOmega = check_finite("initialOmega", initialOmega)
        self.ringGrowth, self.temperatures, self.hertzModel = bool(ringGrowth), temperatures, hertzModel
        self.sampleInterval = check_positive("sampleInterval", sampleInterval)
        self.markers = (rigid_marker(mbs, markerInnerRing, "markerInnerRing"),
                        rigid_marker(mbs, markerOuterRing, "markerOuterRing"))
        if self.markers[0] == self.markers[1]:
            raise InputError(f"markerOuterRing: marker {markerOuterRing} is also markerInnerRing")
        try:
            self.operatingPoint = p = solve_pair(b, arrangement, Fr=fr, Fa=fa, preload=preload, spacing=spacing,
                                                 omega=abs(self.initialOmega), ring_growth=self.ringGrowth,
                                                 temperatures=temperatures, lubricant=self.lubricant,
                                                 hertz_method=hertzModel, stiffness=False)
        except InputError as exc:
            msg = str(exc)
            name, _, rest = msg.partition(": ")
            raise InputError(f"initialLoad: {rest}" if name in ("Fr", "Fa") else msg) from None
        self.loadAngle = check_plausible("loadAngle", loadAngle, -LOAD_ANGLE_RANGE, LOAD_ANGLE_RANGE, "rad",
                                         "the azimuth of the radial load is in radians", ((math.radians, "deg"),))
        self.initialRingDisplacement = self.rotation() @ np.array(p.displacement, float)
        self.coefficients = None
        self.positions, self.turned = p.positions, p.turned
        self._transforms = p.transforms  # T_k, and the offsets of the inner rings along their own axes
        self._offsets = [float(s.displacement[2] - (t @ p.displacement)[2]) for s, t in zip(p.solutions,
                                                                                          p.transforms)]
        self.members = [_Member(b, self.lubricant, self.initialOmega, self.ringGrowth, temperatures, hertzModel,
                                check_finite("cageAngle", cageAngle)) for _ in range(2)]
        self._ws = np.zeros(WS_HEADER)
        self._out, self._force = self._ws[WS_OUT:WS_OUT + 6], self._ws[WS_FORCE:WS_FORCE + 5]
        self._pose, self._cage = self._ws[WS_POSE:WS_POSE + 5], self._ws[WS_CAGE:WS_CAGE + 2]
        self._qmax = self._ws[WS_QMAX:WS_QMAX + 3]
        self._rot0 = np.eye(3)
        self._t_last = self._t_start = -math.inf
        self.restarts = 0
        self._samples = []
        self._next_sample = 0.0
        self._evaluations = 0
        self._add_items(mbs, show)

    def _restart(self, t):
        super()._restart(t)
        for m in self.members:
            m._restart(t)

    def _evaluate(self, d, r, v, w):
        force = np.zeros(5)
        q = np.zeros(3)
        for k, m in enumerate(self.members):
            z = self.positions[k]
            dk = np.array([d[0] + r[1] * z, d[1] - r[0] * z, d[2]])
            rk = np.array([r[0], r[1], r[2]], float)
            vk = np.array([v[0] + w[1] * z, v[1] - w[0] * z, v[2]])
            wk = np.array([w[0], w[1], w[2]], float)
            if self.turned[k]:
                dk[1:] *= -1.0
                rk[1:] *= -1.0
                vk[1:] *= -1.0
                wk[1:] *= -1.0
            dk[2] += self._offsets[k]
            m._t_last = self._t_last
            m._evaluate(dk, rk, vk, wk)
            force += self._transforms[k].T @ m._force
            q = np.maximum(q, m._qmax)
        self._force[:] = force
        self._out[:5] = -force
        self._out[5] = 0.0
        self._pose[:] = [d[0], d[1], d[2], r[0], r[1]]
        self._cage[:] = self.members[0]._cage
        self._qmax[:] = q


def _signed_load(load):
    """(Fr, Fa) of ``initialLoad`` for a pair: Fa of either sign (DB, DF carry both directions)."""
    try:
        fr, fa = load if not isinstance(load, (int, float)) else (load, 0.0)
    except (TypeError, ValueError):
        raise InputError(f"initialLoad: expected (Fr, Fa) [N] or a radial load Fr, got {load!r}") from None
    fr, fa = check_finite("initialLoad", fr), check_finite("initialLoad", fa)
    _load_pair((fr, abs(fa)))  # Fr >= 0
    return fr, fa


def create_pair_level(mbs, bearing, markerInnerRing, markerOuterRing, model, options):
    """``CreateBallBearing`` with ``arrangement``: the quasi-static pair level; InputError naming ``model`` for
    the other levels and naming an option the pair level does not take."""
    if model != "quasistatic":
        raise InputError(f"model: a bearing pair (arrangement) is available as model='quasistatic' only, got "
                         f"{model!r}")
    from .base import LEVEL_OPTIONS

    allowed = tuple(k for k in LEVEL_OPTIONS if k not in ("coefficients", "coefficientSpeeds")) + PAIR_OPTIONS \
        + ("cageAngle",)
    for key in options:
        if key not in allowed:
            raise InputError(f"{key}: not an option of a bearing pair (valid: {', '.join(allowed)})")
    return PairBearing(mbs, bearing, markerInnerRing, markerOuterRing, **options)
