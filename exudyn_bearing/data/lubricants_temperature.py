"""Lubricants with temperature (data): ``lubricants_temperature.json``.

Each entry holds the catalogue points its temperature relations are fitted
to (docs/theory/losses.md#lubricants-with-temperature): two kinematic
viscosities, the density at a reference temperature and its slope, two
pressure-viscosity coefficients, the temperature range the entry is used
in, the surface roughness for the film parameter, and its source. The
relations themselves are in :mod:`exudyn_bearing.physics.lubricant_properties`
(:func:`~exudyn_bearing.physics.lubricant_properties.lubricant_at` turns an
entry and a temperature into a :class:`~.lubricants.Lubricant`). The
fixed-temperature lubricants of ``catalog.json`` stay as they are.
"""
from __future__ import annotations

import json
import math
from collections.abc import Mapping
from dataclasses import dataclass, fields
from importlib import resources

from .errors import InputError, check_keys, lookup, check_nonnegative, check_positive, check_text

__all__ = ["LubricantTemperatureData", "lubricants_temperature", "get_lubricant_temperature"]


def _points(name, value):
    try:
        pts = tuple((float(t), float(v)) for t, v in value)
    except (TypeError, ValueError):
        raise InputError(f"{name}: expected two [temperature K, value] pairs, got {value!r}") from None
    if len(pts) != 2:
        raise InputError(f"{name}: expected two [temperature K, value] pairs, got {len(pts)}")
    for t, v in pts:
        check_positive(f"{name} temperature", t)
        check_positive(f"{name} value", v)
    if not pts[0][0] < pts[1][0]:
        raise InputError(f"{name}: the temperatures must increase, got {pts[0][0]} and {pts[1][0]}")
    return pts


@dataclass(frozen=True)
class LubricantTemperatureData:
    """Catalogue points of a lubricant over temperature (SI units).

    Parameters
    ----------
    viscosity_points : ((T1, nu1), (T2, nu2))
        Kinematic viscosity [m^2/s] at two temperatures [K] (ASTM D341 fit).
    density_reference : (T_ref, rho_ref)
        Density [kg/m^3] at a reference temperature [K].
    density_slope : float
        Fall of the density per kelvin [kg/m^3/K] (rho = rho_ref - slope (T - T_ref)).
    pressure_viscosity_points : ((T1, alpha1), (T2, alpha2))
        Pressure-viscosity coefficient [1/Pa] at two temperatures [K] (Gold's
        alpha = s nu^t through both).
    temperature_range : (T_min, T_max)
        Temperatures [K] the entry may be used at; outside is an InputError.
    roughness_race, roughness_ball, roughness_factor : float
        As in :class:`~.lubricants.Lubricant`.
    """

    viscosity_points: tuple
    density_reference: tuple
    density_slope: float
    pressure_viscosity_points: tuple
    temperature_range: tuple
    roughness_race: float = 3.0e-7
    roughness_ball: float = 0.0
    roughness_factor: float = 1.25
    name: str = "custom"
    source: str = ""

    def __post_init__(self):
        object.__setattr__(self, "viscosity_points", _points("viscosity_points", self.viscosity_points))
        object.__setattr__(self, "pressure_viscosity_points",
                           _points("pressure_viscosity_points", self.pressure_viscosity_points))
        try:
            t_ref, rho = (float(x) for x in self.density_reference)
        except (TypeError, ValueError):
            raise InputError(f"density_reference: expected [temperature K, density kg/m^3], got "
                             f"{self.density_reference!r}") from None
        object.__setattr__(self, "density_reference", (check_positive("density_reference temperature", t_ref),
                                                       check_positive("density_reference density", rho)))
        object.__setattr__(self, "density_slope", check_nonnegative("density_slope", self.density_slope))
        try:
            t_lo, t_hi = (float(x) for x in self.temperature_range)
        except (TypeError, ValueError):
            raise InputError(f"temperature_range: expected [T_min, T_max] in K, got {self.temperature_range!r}") \
                from None
        if not (math.isfinite(t_lo) and math.isfinite(t_hi) and 0.0 < t_lo < t_hi):
            raise InputError(f"temperature_range: expected 0 < T_min < T_max, got {self.temperature_range!r}")
        object.__setattr__(self, "temperature_range", (t_lo, t_hi))
        for key in ("roughness_race", "roughness_ball"):
            object.__setattr__(self, key, check_nonnegative(key, getattr(self, key)))
        object.__setattr__(self, "roughness_factor", check_positive("roughness_factor", self.roughness_factor))
        check_text("name", self.name)
        check_text("source", self.source)
        t_max_density = t_ref + rho / self.density_slope if self.density_slope > 0 else math.inf
        if t_hi >= t_max_density:
            raise InputError(f"temperature_range: the density would reach zero at {t_max_density:.0f} K, "
                             f"inside the range up to {t_hi} K")

    def check_temperature(self, temperature) -> float:
        """The temperature as a float, or an InputError naming the entry's range."""
        t = float(temperature)
        lo, hi = self.temperature_range
        if not (lo <= t <= hi):
            raise InputError(f"temperature: {t:g} K is outside the range of lubricant {self.name!r} "
                             f"({lo:g}-{hi:g} K)")
        return t


_KEYS = tuple(f.name for f in fields(LubricantTemperatureData))


def _read() -> Mapping[str, LubricantTemperatureData]:
    raw = json.loads(resources.files(__package__).joinpath("lubricants_temperature.json").read_text())
    out = {}
    for name, entry in raw["lubricants"].items():
        check_keys("lubricant parameter", entry, _KEYS)
        out[name] = LubricantTemperatureData(name=name, **entry)
    return out


#: The entries of ``lubricants_temperature.json`` by name.
lubricants_temperature: Mapping[str, LubricantTemperatureData] = _read()


def get_lubricant_temperature(name) -> LubricantTemperatureData:
    """The entry ``name`` of ``lubricants_temperature.json`` (InputError listing the names otherwise)."""
    if isinstance(name, LubricantTemperatureData):
        return name
    return lookup(lubricants_temperature, str(name), "lubricant: unknown lubricant with temperature", "valid")
