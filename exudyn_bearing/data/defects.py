"""Localized defects (spalls) of a bearing: data, validated on construction
and against the bearing they sit in.

A :class:`Defect` is a pit in a rolling surface: on the outer race (fixed in
the outer ring), on the inner race (turning with the inner ring) or on one
ball (turning with that ball). It is a rectangle in the surface, ``length``
along the rolling direction and ``width`` across it, ``depth`` deep, with
sharp or rounded edges. How far a ball drops into it is the relation
:func:`exudyn_bearing.physics.defects.spall_drop`; the theory note is
``docs/theory/defects.md``.

Positions (angles in rad, counted about the bearing axis +z of the ring):

* outer or inner race: ``position`` is the azimuth of the spall centre in the
  ring's own frame, from its x axis (the radial load direction +x at t = 0;
  the outer ring does not turn, the inner ring frame turns with the ring).
  Across the raceway the spall is centred on the free contact angle.
* ball: ``ball`` is the ball index (ball j starts at azimuth 2 pi j / Z, ball
  0 in the load direction) and ``position`` the angle of the spall centre on
  the ball's rolling circle at t = 0, from the ball's contact point with the
  outer race towards the orbital direction (pi: the inner-race contact
  point). From then on the spall turns with the ball.

Example: an EDM pit like the 0.021 in fault of the CWRU 6205 test rig, in the
middle of the load zone of the outer race::

    Defect("outer", position=0.0, length=0.533e-3, width=0.533e-3, depth=0.279e-3)
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

from .bearings import MAX_FREE_CONTACT_ANGLE, BallBearing
from .errors import InputError, check_finite, check_positive

__all__ = ["Defect", "RACES", "EDGES", "GROOVE_DEPTH_FRACTION", "as_defect"]

#: Surfaces a defect can sit on.
RACES = ("inner", "outer", "ball")
#: Edge shapes: a sharp corner or a round of radius ``edge_radius``.
EDGES = ("sharp", "rounded")
#: Deepest defect accepted, as a fraction of the ball diameter D: the groove
#: shoulder height of a deep-groove ring, 0.25 D (the groove the limit
#: ``MAX_FREE_CONTACT_ANGLE`` of :mod:`.bearings` is derived from). A pit
#: deeper than the groove would cut through the shoulder.
GROOVE_DEPTH_FRACTION = 0.25


@dataclass(frozen=True)
class Defect:
    """A localized defect (spall, pit) on a race or a ball (see the module docstring).

    Parameters
    ----------
    race : {"outer", "inner", "ball"}
        Surface that carries the defect.
    position : float
        Outer/inner race: azimuth of the spall centre in the ring frame [rad];
        ball: angle on the ball's rolling circle at t = 0 from its outer-race
        contact point [rad].
    length : float
        Extent along the rolling direction [m] (opening at the surface).
    width : float
        Extent across the rolling direction [m].
    depth : float
        Depth below the intact surface [m].
    edge : {"sharp", "rounded"}
        Edge shape.
    edge_radius : float
        Radius of a rounded edge [m] (0 for a sharp edge); at most
        ``depth``, ``length / 2`` and ``width / 2``.
    ball : int
        Index of the defective ball (ball defects only).
    """

    race: str
    position: float
    length: float
    width: float
    depth: float
    edge: str = "sharp"
    edge_radius: float = 0.0
    ball: int = 0

    def __post_init__(self):
        if self.race not in RACES:
            raise InputError(f"race: must be one of {', '.join(RACES)}, got {self.race!r}")
        object.__setattr__(self, "position", check_finite("position", self.position))
        for name in ("length", "width", "depth"):
            object.__setattr__(self, name, check_positive(name, getattr(self, name)))
        if self.edge not in EDGES:
            raise InputError(f"edge: must be one of {', '.join(EDGES)}, got {self.edge!r}")
        r_e = check_finite("edge_radius", self.edge_radius)
        object.__setattr__(self, "edge_radius", r_e)
        if self.edge == "sharp" and r_e != 0.0:
            raise InputError(f"edge_radius: a sharp edge has no radius (use edge='rounded'), got {r_e}")
        if self.edge == "rounded":
            limit = min(self.depth, 0.5 * self.length, 0.5 * self.width)
            if not 0.0 < r_e <= limit:
                raise InputError(f"edge_radius: a rounded edge needs 0 < edge_radius <= min(depth, length/2, "
                                 f"width/2) = {limit:.4g} m, got {r_e}")
        k = self.ball
        if isinstance(k, bool) or not (isinstance(k, int) or (isinstance(k, float) and float(k).is_integer())):
            raise InputError(f"ball: must be an integer ball index, got {k!r}")
        object.__setattr__(self, "ball", int(k))
        if self.ball < 0:
            raise InputError(f"ball: must be >= 0, got {self.ball}")
        if self.race != "ball" and self.ball != 0:
            raise InputError(f"ball: only a ball defect has a ball index (race is {self.race!r}), got {self.ball}")

    @property
    def half_length(self) -> float:
        return 0.5 * self.length

    @property
    def half_width(self) -> float:
        return 0.5 * self.width

    def check(self, bearing: BallBearing) -> "Defect":
        """Validate the defect against ``bearing``; returns itself.

        Limits (InputError naming the field): a race spall shorter than the
        race circumference at the groove bottom and narrower than the groove
        between its shoulders (arc 2 R_c MAX_FREE_CONTACT_ANGLE); a ball spall
        within half the ball's circumference in both directions; depth at most
        the groove shoulder height ``GROOVE_DEPTH_FRACTION`` D; a ball index
        below the number of balls.
        """
        b = bearing
        depth_limit = GROOVE_DEPTH_FRACTION * b.ball_diameter
        if self.depth > depth_limit:
            raise InputError(f"depth: {self.depth:.4g} m is deeper than the groove shoulder "
                             f"({GROOVE_DEPTH_FRACTION:g} D = {depth_limit:.4g} m) of bearing {b.name}")
        if self.race == "ball":
            if self.ball >= b.n_balls:
                raise InputError(f"ball: index {self.ball} but bearing {b.name} has {b.n_balls} balls (0 to "
                                 f"{b.n_balls - 1})")
            half_circ = math.pi * b.ball_radius
            for name in ("length", "width"):
                if getattr(self, name) > half_circ:
                    raise InputError(f"{name}: {getattr(self, name):.4g} m exceeds half the ball's circumference "
                                     f"(pi R_b = {half_circ:.4g} m)")
            return self
        if self.race == "outer":
            r_race, r_groove = b.outer_race_radius, b.outer_groove_radius
        else:
            r_race, r_groove = b.inner_race_radius, b.inner_groove_radius
        circumference = 2.0 * math.pi * r_race
        if self.length >= circumference:
            raise InputError(f"length: {self.length:.4g} m is not shorter than the {self.race} race's "
                             f"circumference {circumference:.4g} m")
        groove_width = 2.0 * r_groove * MAX_FREE_CONTACT_ANGLE
        if self.width > groove_width:
            raise InputError(f"width: {self.width:.4g} m is wider than the {self.race} groove between its "
                             f"shoulders ({groove_width:.4g} m)")
        return self

    def to_dict(self) -> dict:
        return dataclasses.asdict(self)


def as_defect(spec) -> Defect:
    """A :class:`Defect` from a Defect or a dict of its fields (JSON, sweeps)."""
    if isinstance(spec, Defect):
        return spec
    if isinstance(spec, dict):
        known = {f.name for f in dataclasses.fields(Defect)}
        unknown = sorted(set(spec) - known)
        if unknown:
            raise InputError(f"{unknown[0]}: unknown defect field (valid: {', '.join(sorted(known))})")
        for name in ("race", "position", "length", "width", "depth"):
            if name not in spec:
                raise InputError(f"{name}: missing in defect {spec!r}")
        return Defect(**spec)
    raise InputError(f"defects: expected Defect objects or dicts, got {type(spec).__name__}")
