"""Rigid cages: material and geometry (data, SI units) [docs/theory/cage.md].

A rigid cage is a ring of the cage material (section from ``inner_radius``
to ``outer_radius``, ``width`` wide) with one pocket per ball on the pitch
circle, guided by the balls, by a land of the inner ring or by a land of the
outer ring. Its pockets are cylindrical (axis radial) or spherical; the
pocket clearance is the radial gap between pocket and ball (pocket radius
minus ball radius); the land clearance the radial gap between the cage's
guiding surface and the land. Mass and polar inertia follow from the
section less the pockets (:meth:`RigidCage.mass`, :meth:`RigidCage.polar_inertia`).

The papers' bearings give no cage geometry (the DEM papers model the cage
as a torus of cage balls; the high-speed bearing's source names none), so
:func:`estimated_cage` derives one from proportions of the ball diameter D
and pitch radius r_p stated in docs/theory/cage.md#estimated-geometry; every
value it sets is listed in ``estimated``.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

from .errors import InputError, check_finite, check_positive, check_text
from .materials import DENSITY_RANGE, YOUNGS_MODULUS_RANGE

__all__ = ["CageMaterial", "CAGE_MATERIALS", "CageTemperatureWarning", "check_cage_temperature", "RigidCage", "GUIDANCES", "POCKET_SHAPES", "estimated_cage",
           "cage_material"]

#: Guidance of a rigid cage: by the balls, by a land of the inner ring, by a land of the outer ring.
GUIDANCES = ("ball", "inner_land", "outer_land")
#: Pocket shapes: cylindrical (axis along the cage radius) or spherical.
POCKET_SHAPES = ("cylindrical", "spherical")


@dataclass(frozen=True)
class CageMaterial:
    """Material of a rigid cage.

    Parameters
    ----------
    name : str
    density : float
        rho [kg/m^3].
    youngs_modulus : float
        E [Pa] (of the ball / pocket contact).
    poisson_ratio : float
        nu [-].
    temperature_limit : float
        Highest permissible operating temperature of the cage [K] (a run or a thermal solution whose cage
        is hotter warns).
    source : str
    """

    name: str
    density: float
    youngs_modulus: float
    poisson_ratio: float
    temperature_limit: float
    source: str = ""

    def __post_init__(self):
        check_text("name", self.name)
        rho = check_positive("density", self.density)
        if not DENSITY_RANGE[0] <= rho <= DENSITY_RANGE[1]:
            raise InputError(f"density: {rho:g} kg/m^3 is not a cage material's (density is in kg/m^3: "
                             f"{DENSITY_RANGE[0]:g} to {DENSITY_RANGE[1]:g})")
        e = check_positive("youngs_modulus", self.youngs_modulus)
        if not YOUNGS_MODULUS_RANGE[0] <= e <= YOUNGS_MODULUS_RANGE[1]:
            raise InputError(f"youngs_modulus: {e:g} Pa is not plausible (Young's modulus is in Pa: "
                             f"{YOUNGS_MODULUS_RANGE[0]:g} to {YOUNGS_MODULUS_RANGE[1]:g})")
        nu = check_finite("poisson_ratio", self.poisson_ratio)
        if not 0.0 <= nu < 0.5:
            raise InputError(f"poisson_ratio: must lie in [0, 0.5), got {nu}")
        t = check_positive("temperature_limit", self.temperature_limit)
        if not 300.0 <= t <= 800.0:
            raise InputError(f"temperature_limit: {t:g} K is not plausible for a cage (300 to 800 K; temperatures "
                             "are in kelvin: 120 degC is 393.15 K)")
        for key, v in (("density", rho), ("youngs_modulus", e), ("poisson_ratio", nu), ("temperature_limit", t)):
            object.__setattr__(self, key, v)


class CageTemperatureWarning(UserWarning):
    """A cage hotter than its material's ``temperature_limit`` (a thermal solution's cage node)."""


def check_cage_temperature(temperature: float, material: CageMaterial, where: str = "cage") -> bool:
    """Whether ``temperature`` [K] lies within ``material.temperature_limit``; else a
    :class:`CageTemperatureWarning` naming the material, its limit and its source (SKF's permissible
    operating temperatures, :data:`CAGE_MATERIALS`)."""
    if temperature <= material.temperature_limit:
        return True
    warnings.warn(CageTemperatureWarning(
        f"{where}: {temperature:.1f} K ({temperature - 273.15:.0f} degC) is above the {material.name} cage's "
        f"permissible {material.temperature_limit:.2f} K ({material.temperature_limit - 273.15:.0f} degC; "
        f"{material.source}): a cage of another material, more oil flow or a lower speed"), stacklevel=3)
    return False


_SKF = ("SKF, Rolling bearings (catalogue PUB BU/P1 17000, 2018), 'Cages': permissible operating temperature "
        "of the cage material")
#: Cage materials: temperature limits as the catalogue states them for the material; densities and moduli
#: typical handbook values of the material (docs/theory/cage.md#materials).
CAGE_MATERIALS = {
    "steel": CageMaterial("steel", 7850.0, 200e9, 0.30, 573.15, _SKF + " (sheet steel, 300 degC)"),
    "brass": CageMaterial("brass", 8500.0, 100e9, 0.34, 523.15, _SKF + " (machined brass, 250 degC)"),
    "PA66": CageMaterial("PA66", 1350.0, 8e9, 0.40, 393.15, _SKF + " (glass-fibre reinforced polyamide 66, "
                         "120 degC); density and modulus of PA66-GF25, typical"),
    "phenolic": CageMaterial("phenolic", 1350.0, 7e9, 0.35, 393.15, _SKF + " (cotton-fabric reinforced phenolic "
                             "resin, 120 degC); density and modulus typical"),
}


def cage_material(spec) -> CageMaterial:
    """A CageMaterial, or a name of :data:`CAGE_MATERIALS`."""
    if isinstance(spec, CageMaterial):
        return spec
    if isinstance(spec, str) and spec in CAGE_MATERIALS:
        return CAGE_MATERIALS[spec]
    raise InputError(f"cage material: {spec!r} is neither a CageMaterial nor one of {', '.join(CAGE_MATERIALS)}")


@dataclass(frozen=True)
class RigidCage:
    """Geometry and material of a rigid cage (module docstring).

    Parameters
    ----------
    guidance : {"ball", "inner_land", "outer_land"}
    pocket_shape : {"cylindrical", "spherical"}
    pocket_clearance : float
        Radial gap between pocket and ball [m] (> 0).
    inner_radius, outer_radius : float
        Radii of the cage section [m]; the pitch circle lies between them.
    width : float
        Axial width of the cage [m].
    land_clearance : float
        Radial clearance between the guiding surface (the outer radius for ``outer_land``, the inner radius
        for ``inner_land``) and the ring land [m]; smaller than ``pocket_clearance`` (the cage must reach the
        land before its pockets reach the balls). Ignored for ``guidance='ball'``.
    land_width : float
        Width of the guiding surface facing the land [m] (the film's length L), at most ``width``.
    material : CageMaterial or str
    pocket_friction : float
        Coulomb coefficient mu_c of the ball / pocket contact [-].
    unbalance : float
        U [kg m]: the cage's mass times the offset of its centre of mass from its geometric centre, along
        the cage's angle 0 (default 0: balanced).
    pocket_spacing_error : float
        e [m]: unequal pocket spacing, the once-per-revolution harmonic of the pockets' position errors
        along the pitch circle: pocket j sits at the cage angle + 2 pi j / Z + (e / r_p) sin(2 pi j / Z)
        (default 0: equal spacing). Its size is at most half the pocket clearance (the balls, which the
        races space equally, start in their pockets). Dynamic engines only: the quasi-static solver takes
        equally spaced pockets.
    estimated : tuple of str
        Names of the fields that are estimates (:func:`estimated_cage`), not a data sheet's values.
    """

    guidance: str
    pocket_clearance: float
    inner_radius: float
    outer_radius: float
    width: float
    land_clearance: float = 0.0
    land_width: float = 0.0
    pocket_shape: str = "cylindrical"
    material: CageMaterial | str = "brass"
    pocket_friction: float = 0.1
    unbalance: float = 0.0
    pocket_spacing_error: float = 0.0
    estimated: tuple = field(default=())
    source: str = ""

    def __post_init__(self):
        if self.guidance not in GUIDANCES:
            raise InputError(f"guidance: must be one of {', '.join(GUIDANCES)}, got {self.guidance!r}")
        if self.pocket_shape not in POCKET_SHAPES:
            raise InputError(f"pocket_shape: must be one of {', '.join(POCKET_SHAPES)}, got {self.pocket_shape!r}")
        object.__setattr__(self, "material", cage_material(self.material))
        for key in ("pocket_clearance", "inner_radius", "outer_radius", "width"):
            object.__setattr__(self, key, check_positive(key, getattr(self, key)))
        if self.outer_radius <= self.inner_radius:
            raise InputError(f"outer_radius: must exceed inner_radius ({self.inner_radius:g} m), "
                             f"got {self.outer_radius:g}")
        mu = check_finite("pocket_friction", self.pocket_friction)
        if not 0.0 <= mu <= 0.5:
            raise InputError(f"pocket_friction: {mu:g} is not a friction coefficient of a lubricated pocket "
                             "(0 to 0.5)")
        object.__setattr__(self, "pocket_friction", mu)
        u = check_finite("unbalance", self.unbalance)
        if u < 0.0:
            raise InputError(f"unbalance: must be >= 0 (mass times offset of the centre of mass, kg m), got {u}")
        object.__setattr__(self, "unbalance", u)
        e = check_finite("pocket_spacing_error", self.pocket_spacing_error)
        if abs(e) > 0.5 * self.pocket_clearance:
            raise InputError(f"pocket_spacing_error: {e:.3e} m is more than half the pocket clearance "
                             f"({self.pocket_clearance:.3e} m): the balls, spaced equally by the races, would not "
                             "start inside their pockets (lengths are in metres)")
        object.__setattr__(self, "pocket_spacing_error", e)
        object.__setattr__(self, "estimated", tuple(str(x) for x in self.estimated))
        check_text("source", self.source)
        if self.guidance == "ball":
            if self.pocket_shape == "cylindrical":
                raise InputError("pocket_shape: a ball-guided cage needs spherical pockets: cylindrical pockets (axis "
                                 "radial) do not hold the cage radially on its balls, which move along the orbit, and "
                                 "it drifts off them (use pocket_shape='spherical', or a land-guided cage)")
            return
        for key in ("land_clearance", "land_width"):
            object.__setattr__(self, key, check_positive(key, getattr(self, key)))
        if self.land_width > self.width:
            raise InputError(f"land_width: {self.land_width:g} m exceeds the cage width {self.width:g} m")
        if self.land_clearance >= self.pocket_clearance:
            raise InputError(f"land_clearance: {self.land_clearance:.3e} m is not smaller than the pocket clearance "
                             f"{self.pocket_clearance:.3e} m: the cage would touch the balls before its "
                             f"{self.guidance.replace('_', ' ')} (use guidance='ball' for a ball-guided cage)")

    @property
    def guide_radius(self) -> float:
        """Radius of the guiding surface [m]: outer radius (outer land), inner radius (inner land), 0 (balls)."""
        return {"outer_land": self.outer_radius, "inner_land": self.inner_radius}.get(self.guidance, 0.0)

    def check_fits(self, bearing) -> None:
        """InputError unless the cage fits the bearing: the pitch circle inside the section, pockets that hold
        the balls and do not cut the cage into pieces, a land within the rings, a mass below that of the
        solid annulus."""
        rp, rb, z = bearing.pitch_radius, bearing.ball_radius, bearing.n_balls
        if not self.inner_radius < rp < self.outer_radius:
            raise InputError(f"inner_radius, outer_radius: the cage section {self.inner_radius:g} ... "
                             f"{self.outer_radius:g} m does not contain the pitch circle (r_p = {rp:g} m)")
        pocket = rb + self.pocket_clearance
        if self.pocket_clearance > 0.25 * rb:
            raise InputError(f"pocket_clearance: {self.pocket_clearance:.3e} m is more than a quarter of the ball "
                             f"radius ({rb:.3e} m): the pocket does not hold the ball (lengths are in metres)")
        if 2.0 * pocket >= 2.0 * self.inner_radius * math.sin(math.pi / z):
            raise InputError(f"pocket_clearance: pockets of radius {pocket:.4g} m cut the cage's bars between "
                             f"the {z} balls through")
        if not 2.0 * pocket < self.width <= 4.0 * 2.0 * rb:
            raise InputError(f"width: a cage {self.width:g} m wide does not hold pockets {2 * pocket:.4g} m wide "
                             "(it must be wider than the pockets, so that side rails join the bars, and at most "
                             "four ball diameters)")
        if self.guidance != "ball" and self.land_width > self.width - 2.0 * pocket + 1e-12:
            raise InputError(f"land_width: {self.land_width:g} m exceeds the side rails' width "
                             f"{self.width - 2.0 * pocket:.4g} m (cage width less the pocket diameter)")
        if self.guidance == "outer_land" and self.outer_radius + self.land_clearance >= bearing.outer_race_radius:
            raise InputError(f"outer_radius: the outer land ({self.outer_radius + self.land_clearance:g} m) is not "
                             f"inside the outer race ({bearing.outer_race_radius:g} m)")
        if self.guidance == "inner_land" and self.inner_radius - self.land_clearance <= bearing.inner_race_radius:
            raise InputError(f"inner_radius: the inner land ({self.inner_radius - self.land_clearance:g} m) is not "
                             f"outside the inner race ({bearing.inner_race_radius:g} m)")
        annulus = self.material.density * math.pi * (self.outer_radius ** 2 - self.inner_radius ** 2) * self.width
        if self.unbalance > self.mass(bearing) * self.pocket_clearance:
            raise InputError(f"unbalance: {self.unbalance:.3g} kg m puts the cage's centre of mass more than the pocket "
                             f"clearance ({self.pocket_clearance:.3g} m) off its centre (mass {self.mass(bearing):.3g} kg; "
                             "an unbalance is in kg m: 1 g mm is 1e-6 kg m)")
        if not 0.0 < self.mass(bearing) < annulus:
            raise InputError(f"pocket_clearance: the cage's mass {self.mass(bearing):.4g} kg is not between zero "
                             f"and the solid annulus' {annulus:.4g} kg")

    def _pocket_volume(self, bearing) -> float:
        """Material removed by one pocket [m^3]: a cylinder of the pocket radius through the section
        (cylindrical), or the sphere's part within the section (spherical, taken as the cylinder's too)."""
        pocket = bearing.ball_radius + self.pocket_clearance
        return math.pi * pocket ** 2 * (self.outer_radius - self.inner_radius)

    def mass(self, bearing) -> float:
        """m_c [kg]: the annulus rho pi (R_o^2 - R_i^2) w less Z pockets (:meth:`_pocket_volume`)."""
        annulus = math.pi * (self.outer_radius ** 2 - self.inner_radius ** 2) * self.width
        return self.material.density * (annulus - bearing.n_balls * self._pocket_volume(bearing))

    def polar_inertia(self, bearing) -> float:
        """I_c about the bearing axis [kg m^2]: the annulus rho pi w (R_o^4 - R_i^4)/2 less the pockets as
        masses at the pitch radius (their own inertia about their centres left out)."""
        annulus = 0.5 * math.pi * self.width * (self.outer_radius ** 4 - self.inner_radius ** 4)
        pockets = bearing.n_balls * self._pocket_volume(bearing) * bearing.pitch_radius ** 2
        return self.material.density * (annulus - pockets)


#: Proportions of :func:`estimated_cage` (docs/theory/cage.md#estimated-geometry), in ball diameters D.
ESTIMATE = {"pocket_clearance": 0.02, "land_clearance": 0.01, "half_section": 0.22, "width": 1.3}


def estimated_cage(bearing, guidance: str = "outer_land", material="brass", pocket_shape=None,
                   pocket_friction=0.1) -> RigidCage:
    """A rigid cage for a bearing without cage data, from the proportions :data:`ESTIMATE` of the ball
    diameter D: radial pocket clearance 0.02 D, radial land clearance 0.01 D, a section r_p +- 0.22 D
    (a land-guided cage's guiding surface then lies 0.22 D from the pitch circle, within the ring
    shoulders, which stand about 0.25 D off the pitch circle for grooves about 0.25 D deep), width 1.3 D
    (side rails of 0.13 D beside the pockets), the guiding surface the two rails (width less the pocket
    diameter). Pockets: cylindrical (axis radial) for a land-guided cage, spherical for a ball-guided one
    (``pocket_shape=None``; cylindrical pockets do not locate a cage radially). Every geometric field is
    marked estimated.

    >>> from exudyn_bearing import catalog
    >>> c = estimated_cage(catalog["6208"])
    >>> round(c.pocket_clearance * 1e6), round(1e3 * c.mass(catalog["6208"]))   # um, g
    (252, 90)
    """
    d = 2.0 * bearing.ball_radius
    rp = bearing.pitch_radius
    e = ESTIMATE
    if pocket_shape is None:
        pocket_shape = "spherical" if guidance == "ball" else "cylindrical"
    cage = RigidCage(guidance=guidance, pocket_clearance=e["pocket_clearance"] * d,
                     inner_radius=rp - e["half_section"] * d, outer_radius=rp + e["half_section"] * d,
                     width=e["width"] * d, land_clearance=e["land_clearance"] * d if guidance != "ball" else 0.0,
                     land_width=(e["width"] - 1.0 - 2.0 * e["pocket_clearance"]) * d if guidance != "ball" else 0.0,
                     pocket_shape=pocket_shape,
                     material=material, pocket_friction=pocket_friction,
                     estimated=("pocket_clearance", "inner_radius", "outer_radius", "width", "land_clearance",
                                "land_width"),
                     source="estimated from the ball diameter (docs/theory/cage.md#estimated-geometry)")
    cage.check_fits(bearing)
    return cage
