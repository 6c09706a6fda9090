"""Ball-bearing geometry (data, not a model).

Every quantity is SI (m, Pa, kg, s, rad). Definitions are frozen dataclasses,
validated on construction: an impossible value raises :class:`InputError`
whose message starts with the name of the offending parameter.

Catalogue entries (``catalog["6208"]`` ...) are read from ``catalog.json``
beside this file; each carries its ``source``. See docs/theory/geometry.md.

Groove construction
-------------------
Each raceway is a torus whose tube is the groove; the ball sits inside the
tube. In the (radial r, axial z) half-plane of one ball the two tube-centre
points ("groove centres") lie on a line through the ball centre at the pitch
radius, inclined at the free contact angle ``alpha_0`` to the radial plane,
separated by ``A - P_d/2`` where ``A = R_ci + R_co - 2 R_b`` is the distance at
which a ball touches both grooves and ``P_d = 2 (R_o - R_i - 2 R_b)`` the
diametral clearance (measured along the contact line)::

    n   = (cos alpha_0, sin alpha_0)
    p_o = (r_p, 0) - (R_co - R_b - P_d/4) n        outer groove centre
    p_i = (r_p, 0) + (R_ci - R_b - P_d/4) n        inner groove centre

For ``alpha_0 = 0`` this gives the deep-groove values of docs/theory/geometry.md,
``rho_i = R_i + R_ci`` and ``rho_o = R_o - R_co``. For ``alpha_0 > 0``
(angular contact, the 7208 construction of docs/theory/geometry.md#groove-construction) ``R_i`` and ``R_o`` are
the race radii of the equivalent radial construction. The inner groove
centre lies at ``+z`` and the outer one at ``-z``, so the bearing carries an
axial force on the inner ring along ``+z`` (inner ring displaced along ``+z``).
"""
from __future__ import annotations

import dataclasses
import math
import warnings
from dataclasses import dataclass, field

from .errors import (LENGTH_MISTAKES, InputError, check_finite, check_integer, check_plausible, check_positive,
                     check_text)
from .iso281 import STANDARD_CONFORMITY
from .materials import Material

__all__ = ["BallBearing", "EstimatedGeometryWarning", "MAX_CLEARANCE_PER_BALL_DIAMETER", "MAX_FREE_CONTACT_ANGLE", "MAX_PRELOAD_INTERFERENCE",
           "PITCH_DIAMETER_RANGE", "RACE_RADIUS_RANGE", "check_clearance", "free_contact_angle_from_degrees",
           "check_free_contact_angle"]

#: Largest free contact angle accepted [rad]. A ball whose free contact angle
#: (rings shifted axially until the ball touches both grooves) exceeds it is
#: taken to ride over the shoulder and leave the grooves. 60 deg is about the
#: half-angle of a groove of conformity 0.52 whose shoulders are 0.25 D deep
#: (acos(0.27/0.52) = 58.7 deg), a deep-groove design value.
MAX_FREE_CONTACT_ANGLE = math.radians(60.0)

#: Largest preload interference -P_d/2 accepted, as a fraction of the ball
#: radius. Hertz theory needs overlaps small against the radii.
MAX_PRELOAD_INTERFERENCE = 0.01

#: Ball diameters accepted [m]: 0.2 mm (miniature bearings) to 200 mm (large
#: slewing bearings); a value outside is a unit mistake (mm, cm, um).
BALL_DIAMETER_RANGE = (2e-4, 0.2)
#: Race radii accepted [m] (R_i, R_o of the radial construction): 0.1 mm to 5 m (miniature bearings to large
#: slewing rings); pitch diameters d_m accepted [m]: 0.5 mm to 10 m. A value outside is a unit mistake.
RACE_RADIUS_RANGE = (1e-4, 5.0)
PITCH_DIAMETER_RANGE = (5e-4, 10.0)
#: Largest diametral clearance accepted, in ball diameters: radial internal clearances of ball bearings are
#: some 0.1-0.5 % of D (ISO 5753-1, groups 2 to 5); ten times the largest is a unit mistake (a clearance in um).
#: The smallest is the preload of :data:`MAX_PRELOAD_INTERFERENCE`.
MAX_CLEARANCE_PER_BALL_DIAMETER = 0.05
#: Conformities f = R_c / D accepted: above 0.5 (the groove must be larger
#: than the ball) up to 0.6; ball bearings have 0.505-0.58 (Harris & Kotzalas,
#: Rolling Bearing Analysis, 5th ed., 2006, on osculation).
MAX_CONFORMITY = 0.6


def check_ball_diameter(name, value, factor=1.0) -> float:
    """A ball diameter (``factor`` 1) or radius (0.5) [m] within
    :data:`BALL_DIAMETER_RANGE`, else InputError naming ``name`` and the
    likely unit mistake ("lengths are in metres: 12.7 mm is 0.0127 m")."""
    v = check_positive(name, value)
    return check_plausible(name, v, factor * BALL_DIAMETER_RANGE[0], factor * BALL_DIAMETER_RANGE[1], "m",
                           "lengths are in metres", LENGTH_MISTAKES)


def check_clearance(name, value, ball_diameter) -> float:
    """A diametral clearance P_d [m] (negative: preload) between -2 MAX_PRELOAD_INTERFERENCE R_b and
    MAX_CLEARANCE_PER_BALL_DIAMETER D, else InputError naming ``name`` and the likely unit mistake
    ("lengths are in metres: 20 um is 2e-05 m")."""
    pd = check_finite(name, value)
    lo, hi = -MAX_PRELOAD_INTERFERENCE * ball_diameter, MAX_CLEARANCE_PER_BALL_DIAMETER * ball_diameter
    return check_plausible(name, pd, lo, hi, "m", "lengths are in metres (ball bearing clearances are some "
                           "0.1-0.5 % of the ball diameter; negative: preload)", LENGTH_MISTAKES)


def check_conformity(name, value) -> float:
    """A groove conformity f = R_c / D in (0.5, MAX_CONFORMITY], else
    InputError naming ``name`` (a percentage says so)."""
    f = check_finite(name, value)
    if 0.5 < f <= MAX_CONFORMITY + 1e-12:
        return f
    if 50.0 < f <= 100.0 * MAX_CONFORMITY:
        raise InputError(f"{name}: {f:g} is a percentage; the conformity is the ratio f = groove radius / ball "
                         f"diameter: {f:g} % is {f / 100:g}")
    raise InputError(f"{name}: must lie in (0.5, {MAX_CONFORMITY:g}] (groove radius f D above the ball radius D/2; "
                     f"ball bearings have 0.505-0.58), got {f:g}")

class EstimatedGeometryWarning(UserWarning):
    """A bearing built with estimated values in place of missing data (:meth:`BallBearing.from_dimensions`
    without conformities); the bearing's ``estimated`` lists them."""


#: Smallest nonzero free contact angle accepted in degrees [deg]: a value
#: below pi/2 given in degrees is far more likely an angle in radians (angular-
#: contact bearings have 15-40 deg; deep-groove bearings 0).
MIN_FREE_CONTACT_ANGLE_DEG = 0.5 * math.pi


def check_free_contact_angle(a0, name: str = "free_contact_angle") -> float:
    """``a0`` [rad] as a float in [0, MAX_FREE_CONTACT_ANGLE], else InputError
    naming ``name``; a value that reads as degrees (1.6 to 90) says so.

    Angles are in radians everywhere in Python and under the key
    ``free_contact_angle`` of a bearing file; ``free_contact_angle_deg``
    (files, :meth:`BallBearing.to_dict`) carries degrees."""
    a0 = check_finite(name, a0)
    if 0.5 * math.pi <= a0 <= 90.0:
        raise InputError(f"{name}: {a0:g} rad is not a free contact angle; angles are in radians "
                         f"({a0:g} deg is {math.radians(a0):.6g} rad; a bearing file may give "
                         f"free_contact_angle_deg instead)")
    if not 0.0 <= a0 <= MAX_FREE_CONTACT_ANGLE:
        raise InputError(f"{name}: must lie in [0, {MAX_FREE_CONTACT_ANGLE:.6g}] rad (0 to "
                         f"{math.degrees(MAX_FREE_CONTACT_ANGLE):.0f} deg), got {a0:g}")
    return a0


def free_contact_angle_from_degrees(deg, name: str = "free_contact_angle_deg") -> float:
    """The free contact angle [rad] of a value in degrees (``free_contact_angle_deg``
    of a bearing file); a nonzero value below pi/2 reads as radians and is
    refused, naming ``name``."""
    v = check_finite(name, deg)
    if 0.0 < v < MIN_FREE_CONTACT_ANGLE_DEG:
        raise InputError(f"{name}: {v:g} deg looks like an angle in radians ({v:g} rad = "
                         f"{math.degrees(v):.4g} deg); give degrees here, or the key free_contact_angle "
                         "in radians")
    if not 0.0 <= v <= math.degrees(MAX_FREE_CONTACT_ANGLE):
        raise InputError(f"{name}: must lie in [0, {math.degrees(MAX_FREE_CONTACT_ANGLE):.0f}] deg, got {v:g}")
    return math.radians(v)


@dataclass(frozen=True)
class BallBearing:
    """Geometry of a ball bearing [docs/theory/geometry.md].

    Parameters
    ----------
    n_balls : int
        Number of balls Z (>= 3).
    ball_radius : float
        R_b [m].
    inner_race_radius, outer_race_radius : float
        Race bottom radii R_i, R_o [m] (of the radial construction, see the
        module docstring for angular-contact bearings).
    inner_groove_radius, outer_groove_radius : float
        Groove cross-section radii R_ci, R_co [m], larger than R_b.
    cage_ball_radius : float or None
        R_z [m] of the torus-cage balls between neighbouring balls; None for
        a cageless bearing.
    free_contact_angle : float
        alpha_0 [rad] at which the groove centres are placed (0 for deep
        groove), at most ``MAX_FREE_CONTACT_ANGLE``; a value that reads as
        degrees is refused. Bearing files give it in radians under this
        key or in degrees as ``free_contact_angle_deg``.
    material : Material
        Material of balls and rings.
    lubricant, traction : str or None
        Catalogue names of the bearing's default lubricant and traction
        model (``exudyn_bearing.data.lubricants``, ``traction_models``), used
        by every solver when none is given; None: the DEM papers' oil
        ``guessasma2018`` and their mu(Lambda) ``lambda_dem``
        (:func:`~exudyn_bearing.data.catalog.default_lubricant`).
    estimated : tuple of str
        Names of the quantities estimated by a rule rather than taken from a data sheet or paper (the
        series catalogue's ``6310-ISO`` ..., :meth:`from_dimensions` without conformities), e.g.
        ``("n_balls", "ball_diameter", ...)``; empty for data-sheet geometry
        (docs/theory/geometry.md#series-catalogue).
    """

    n_balls: int
    ball_radius: float
    inner_race_radius: float
    outer_race_radius: float
    inner_groove_radius: float
    outer_groove_radius: float
    cage_ball_radius: float | None = None
    free_contact_angle: float = 0.0
    material: Material = field(default_factory=Material)
    name: str = "custom"
    source: str = ""
    bore: float | None = None
    outer_diameter: float | None = None
    lubricant: str | None = None
    traction: str | None = None
    estimated: tuple = ()

    def __post_init__(self):
        z = check_integer("n_balls", self.n_balls)
        if z < 3:
            raise InputError(f"n_balls: at least 3 balls are needed, got {z}")
        object.__setattr__(self, "n_balls", z)
        rb = check_ball_diameter("ball_radius", self.ball_radius, 0.5)
        ri, ro = (check_plausible(k, check_positive(k, getattr(self, k)), *RACE_RADIUS_RANGE, "m",
                                  "lengths are in metres", LENGTH_MISTAKES)
                  for k in ("inner_race_radius", "outer_race_radius"))
        rci = check_positive("inner_groove_radius", self.inner_groove_radius)
        rco = check_positive("outer_groove_radius", self.outer_groove_radius)
        a0 = check_free_contact_angle(self.free_contact_angle)
        if not isinstance(self.material, Material):
            raise InputError(f"material: expected a Material, got {type(self.material).__name__}")
        check_text("name", self.name)
        check_text("source", self.source)
        for key in ("lubricant", "traction"):
            if getattr(self, key) is not None:
                check_text(key, getattr(self, key))
        if not isinstance(self.estimated, (tuple, list)) or not all(isinstance(k, str) for k in self.estimated):
            raise InputError(f"estimated: expected a list of quantity names, got {self.estimated!r}")
        object.__setattr__(self, "estimated", tuple(self.estimated))
        # plain floats from here on (numpy scalars and ints are numbers too)
        for key, v in (("ball_radius", rb), ("inner_race_radius", ri), ("outer_race_radius", ro),
                       ("inner_groove_radius", rci), ("outer_groove_radius", rco), ("free_contact_angle", a0)):
            object.__setattr__(self, key, v)
        for key in ("cage_ball_radius", "bore", "outer_diameter"):
            if getattr(self, key) is not None:
                object.__setattr__(self, key, check_positive(key, getattr(self, key)))
        if ro <= ri:
            raise InputError(f"outer_race_radius: must exceed inner_race_radius ({ri}), got {ro}")
        if rci <= rb:
            raise InputError(
                f"inner_groove_radius: the ball (R_b = {rb}) must be smaller than the groove, got {rci}")
        if rco <= rb:
            raise InputError(
                f"outer_groove_radius: the ball (R_b = {rb}) must be smaller than the groove, got {rco}")
        for key, r_c in (("inner_groove_radius", rci), ("outer_groove_radius", rco)):
            if r_c > (2.0 * MAX_CONFORMITY + 1e-12) * rb:
                raise InputError(f"{key}: {r_c:g} m is {r_c / (2.0 * rb):.4g} ball diameters; a groove radius "
                                 f"lies between 0.5 and {MAX_CONFORMITY:g} D (conformity), here "
                                 f"{MAX_CONFORMITY * 2.0 * rb:.4g} m at most")
        pd = self.diametral_clearance
        if pd < 0.0 and -0.5 * pd > MAX_PRELOAD_INTERFERENCE * rb:
            raise InputError(
                f"outer_race_radius: preload interference -P_d/2 = {-0.5 * pd:.3e} m exceeds "
                f"{MAX_PRELOAD_INTERFERENCE:g} R_b; the ball does not fit between the races")
        if 0.5 * pd >= self.groove_distance:
            raise InputError(
                f"outer_race_radius: clearance P_d = {pd:.3e} m leaves the groove centres crossed "
                f"(P_d/2 >= A = {self.groove_distance:.3e} m): balls can leave the grooves")
        if self.free_contact_angle_max > MAX_FREE_CONTACT_ANGLE:
            raise InputError(
                f"outer_race_radius: clearance P_d = {pd:.3e} m gives a free contact angle of "
                f"{math.degrees(self.free_contact_angle_max):.1f} deg > "
                f"{math.degrees(MAX_FREE_CONTACT_ANGLE):.0f} deg: balls can leave the grooves")
        if self.inner_groove_center[0] - rci <= 0.0:
            raise InputError("inner_groove_radius: the inner groove reaches the bearing axis")
        # neighbouring balls must not overlap on the pitch circle
        if 2.0 * self.pitch_radius * math.sin(math.pi / self.n_balls) <= 2.0 * rb:
            raise InputError(
                f"n_balls: {self.n_balls} balls of radius {rb} do not fit on the pitch circle "
                f"(radius {self.pitch_radius})")
        if self.cage_ball_radius is not None:
            rz = check_positive("cage_ball_radius", self.cage_ball_radius)
            if self.cage_pocket_clearance <= 0.0:
                raise InputError(
                    f"cage_ball_radius: cage balls of radius {rz} overlap the rolling balls "
                    f"(pocket clearance {self.cage_pocket_clearance:.3e} m)")
            if rz >= 0.5 * (ro - ri):
                raise InputError(
                    f"cage_ball_radius: {rz} does not fit between the races (gap {ro - ri})")

    @classmethod
    def from_dimensions(cls, n_balls, ball_diameter, pitch_diameter, inner_conformity=None, outer_conformity=None,
                        diametral_clearance=0.0, free_contact_angle=0.0, material: Material | None = None,
                        cage_ball_radius=None, name: str = "custom", source: str = "", bore=None,
                        outer_diameter=None, lubricant=None, traction=None, estimated=()) -> "BallBearing":
        """A bearing from the dimensions of a data sheet.

        Parameters
        ----------
        n_balls : int
            Z.
        ball_diameter, pitch_diameter : float
            D and d_m [m].
        inner_conformity, outer_conformity : float, optional
            f_i = R_ci / D and f_o = R_co / D [-], in (0.5, 0.6] (typically 0.51-0.54). Not given (None): the
            groove radii ISO 281 assumes for its load ratings, 0.52 inner and 0.53 outer
            (:data:`~exudyn_bearing.data.iso281.STANDARD_CONFORMITY`, ISO 281:2007 clause 6.1.1), which a
            data sheet rarely states; the bearing then lists them in ``estimated``, says so in ``source``,
            and an :class:`EstimatedGeometryWarning` is issued.
        diametral_clearance : float
            P_d [m] (negative: preload).
        free_contact_angle : float
            alpha_0 [rad] (0 for deep-groove bearings).
        material, cage_ball_radius, name, source, bore, outer_diameter, lubricant, traction, estimated
            As in the class.

        The race radii follow as R_i = d_m/2 - D/2 - P_d/4 and
        R_o = d_m/2 + D/2 + P_d/4 (the radial construction of the module
        docstring, also for alpha_0 > 0), the groove radii as f D.

        >>> b = BallBearing.from_dimensions(9, 12.6e-3, 60.6e-3, 0.52, 0.52, cage_ball_radius=4.19e-3)
        >>> round(b.inner_race_radius * 1e3, 6), round(b.outer_groove_radius * 1e3, 6)
        (24.0, 6.552)
        """
        d = check_ball_diameter("ball_diameter", ball_diameter)
        dm = check_plausible("pitch_diameter", check_positive("pitch_diameter", pitch_diameter),
                             *PITCH_DIAMETER_RANGE, "m", "lengths are in metres", LENGTH_MISTAKES)
        if not d < dm:
            raise InputError(f"ball_diameter: must be smaller than pitch_diameter ({dm}), got {d}")
        estimated = tuple(estimated)
        missing = [k for k, v in (("inner_conformity", inner_conformity), ("outer_conformity", outer_conformity))
                   if v is None]
        if missing:
            rule = dict(zip(("inner_conformity", "outer_conformity"), STANDARD_CONFORMITY))
            inner_conformity = rule["inner_conformity"] if inner_conformity is None else inner_conformity
            outer_conformity = rule["outer_conformity"] if outer_conformity is None else outer_conformity
            note = (f"{' and '.join(missing)} not given: {', '.join(f'{rule[k]:g}' for k in missing)} assumed "
                    "(the groove radii ISO 281 assumes for its load ratings, inner 0.52 D, outer 0.53 D)")
            source = f"{source}; {note}" if source else note
            estimated += tuple(k for k in missing if k not in estimated)
            warnings.warn(f"bearing {name}: {note}", EstimatedGeometryWarning, stacklevel=2)
        fi = check_conformity("inner_conformity", inner_conformity)
        fo = check_conformity("outer_conformity", outer_conformity)
        pd = check_clearance("diametral_clearance", diametral_clearance, d)
        return cls(n_balls=n_balls, ball_radius=0.5 * d, inner_race_radius=0.5 * dm - 0.5 * d - 0.25 * pd,
                   outer_race_radius=0.5 * dm + 0.5 * d + 0.25 * pd, inner_groove_radius=fi * d,
                   outer_groove_radius=fo * d, cage_ball_radius=cage_ball_radius,
                   free_contact_angle=free_contact_angle, material=Material() if material is None else material,
                   name=name, source=source, bore=bore, outer_diameter=outer_diameter, lubricant=lubricant,
                   traction=traction, estimated=estimated)

    # -- derived quantities -------------------------------------------------
    @property
    def pitch_radius(self) -> float:
        """r_p = (R_i + R_o) / 2 [m]."""
        return 0.5 * (self.inner_race_radius + self.outer_race_radius)

    @property
    def pitch_diameter(self) -> float:
        """d_m = 2 r_p [m]."""
        return 2.0 * self.pitch_radius

    @property
    def ball_diameter(self) -> float:
        """D = 2 R_b [m]."""
        return 2.0 * self.ball_radius

    @property
    def diametral_clearance(self) -> float:
        """P_d = 2 (R_o - R_i - 2 R_b) [m]; negative is preload."""
        return 2.0 * (self.outer_race_radius - self.inner_race_radius - 2.0 * self.ball_radius)

    @property
    def inner_conformity(self) -> float:
        """f_i = R_ci / (2 R_b) [-]."""
        return self.inner_groove_radius / (2.0 * self.ball_radius)

    @property
    def outer_conformity(self) -> float:
        """f_o = R_co / (2 R_b) [-]."""
        return self.outer_groove_radius / (2.0 * self.ball_radius)

    @property
    def conformity_sum(self) -> float:
        """B = (R_ci + R_co) / (2 R_b) - 1 [-]."""
        return (self.inner_groove_radius + self.outer_groove_radius) / (2.0 * self.ball_radius) - 1.0

    @property
    def groove_distance(self) -> float:
        """A = R_ci + R_co - 2 R_b [m], groove-centre distance at touching."""
        return self.inner_groove_radius + self.outer_groove_radius - 2.0 * self.ball_radius

    @property
    def _line(self):
        return math.cos(self.free_contact_angle), math.sin(self.free_contact_angle)

    @property
    def inner_groove_center(self) -> tuple[float, float]:
        """(rho_i, z_i) [m]: radius and axial position of the inner tube-centre circle."""
        c, s = self._line
        d = self.inner_groove_radius - self.ball_radius - 0.25 * self.diametral_clearance
        return self.pitch_radius + d * c, d * s

    @property
    def outer_groove_center(self) -> tuple[float, float]:
        """(rho_o, z_o) [m]: radius and axial position of the outer tube-centre circle."""
        c, s = self._line
        d = self.outer_groove_radius - self.ball_radius - 0.25 * self.diametral_clearance
        return self.pitch_radius - d * c, -d * s

    @property
    def free_contact_angle_max(self) -> float:
        """Free contact angle after the rings are shifted axially until the
        ball touches both grooves [rad]: cos = (1 - P_d/(2A)) cos alpha_0
        (Harris & Kotzalas, eq. 2.8, extended to the inclined construction).
        For preload (P_d < 0) it is alpha_0."""
        pd = self.diametral_clearance
        if pd <= 0.0:
            return self.free_contact_angle
        c = (1.0 - pd / (2.0 * self.groove_distance)) * math.cos(self.free_contact_angle)
        return math.acos(max(-1.0, min(1.0, c)))

    @property
    def cage_pocket_clearance(self) -> float:
        """2 r_p sin(pi/(2Z)) - (R_b + R_z) [m]: gap between a ball and a cage
        ball when both sit on the pitch circle at equal spacing. None if cageless."""
        if self.cage_ball_radius is None:
            return None
        return 2.0 * self.pitch_radius * math.sin(math.pi / (2 * self.n_balls)) - (
            self.ball_radius + self.cage_ball_radius)

    @property
    def ball_mass(self) -> float:
        """m_b = 4/3 pi R_b^3 rho [kg]."""
        return 4.0 / 3.0 * math.pi * self.ball_radius ** 3 * self.material.density

    @property
    def cage_ball_mass(self) -> float | None:
        """m_z = 4/3 pi R_z^3 rho [kg], None if cageless."""
        if self.cage_ball_radius is None:
            return None
        return 4.0 / 3.0 * math.pi * self.cage_ball_radius ** 3 * self.material.density

    @property
    def has_cage(self) -> bool:
        return self.cage_ball_radius is not None

    def replace(self, **changes) -> "BallBearing":
        """A copy with some fields changed (validated again)."""
        return dataclasses.replace(self, **changes)

    def with_clearance(self, diametral_clearance: float, name: str | None = None) -> "BallBearing":
        """A copy with the outer race radius changed to give P_d [m]. An InputError on that radius
        names ``name`` when given (the parameter the caller was given: the CLI's ``Pd``), else the
        radius."""
        pd = check_clearance(name or "diametral_clearance", diametral_clearance, self.ball_diameter)
        ro = self.inner_race_radius + 2.0 * self.ball_radius + 0.5 * pd
        try:
            return self.replace(outer_race_radius=ro)
        except InputError as e:
            msg = str(e)
            if name is None or not msg.startswith("outer_race_radius:"):
                raise
            raise InputError(f"{name}: {pd:g} m;" + msg[len("outer_race_radius:"):]) from None

    def to_dict(self) -> dict:
        """Plain JSON-able dict (the format of ``catalog.json``; the angle in
        degrees as ``free_contact_angle_deg``)."""
        d = {f.name: getattr(self, f.name) for f in dataclasses.fields(self)}
        d["free_contact_angle_deg"] = math.degrees(d.pop("free_contact_angle"))
        d["material"] = dataclasses.asdict(self.material)
        return d
