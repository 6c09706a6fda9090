"""Lubricant properties against temperature: viscosity (ASTM D341 / Walther), pressure-viscosity
coefficient (Gold's alpha = s nu^t), density, thermal conductivity and specific heat (Cragoe).

docs/theory/losses.md#lubricants-with-temperature. Temperatures in K, kinematic viscosity in m^2/s
(the standards' mm^2/s = cSt inside), SI otherwise. One relation per function, plain numpy.

References
----------
.. [1] ASTM D341-09, Standard Practice for Viscosity-Temperature Charts for Liquid Petroleum
   Products, ASTM International (Walther's equation with the low-viscosity terms of Z).
.. [2] P. W. Gold, A. Schmidt, H. Dicke, J. Loos and C. Assmann, "Viscosity-pressure-temperature
   behaviour of mineral and synthetic oils," J. Synth. Lubr. 18(1) (2001) 51-79.
   doi:10.1002/jsl.3000180105
.. [3] C. S. Cragoe, Thermal Properties of Petroleum Products, U.S. Bureau of Standards
   Miscellaneous Publication 97, 1929.
"""
from __future__ import annotations

import math

import numpy as np

from ..data.lubricants import Lubricant
from ..data.lubricants_temperature import get_lubricant_temperature

__all__ = ["density_linear", "gold_constants", "kinematic_viscosity_walther", "lubricant_at", "properties_at",
           "pressure_viscosity_gold", "specific_heat_cragoe", "thermal_conductivity_cragoe", "walther_constants",
           "walther_nu", "walther_z"]


def walther_z(nu):
    """ASTM D341 [1]_ Z(nu) = nu + 0.7 + exp(-1.47 - 1.84 nu - 0.51 nu^2), nu in mm^2/s (cSt).

    The exponential term extends Walther's nu + 0.7 below 2 mm^2/s (it is
    below 1e-3 above 2 mm^2/s); the standard states the relation down to
    about 0.21 mm^2/s.
    """
    v = np.asarray(nu, dtype=float)
    z = v + 0.7 + np.exp(-1.47 - 1.84 * v - 0.51 * v * v)
    return z if np.ndim(z) else float(z)


def walther_nu(z):
    """Inverse of :func:`walther_z` by ASTM D341 [1]_:
    nu = (Z - 0.7) - exp(-0.7487 - 3.295 (Z - 0.7) + 0.6119 (Z - 0.7)^2 - 0.3193 (Z - 0.7)^3), mm^2/s."""
    w = np.asarray(z, dtype=float) - 0.7
    v = w - np.exp(-0.7487 - 3.295 * w + 0.6119 * w * w - 0.3193 * w ** 3)
    return v if np.ndim(v) else float(v)


def walther_constants(t1, nu1, t2, nu2):
    """A, B of Walther's equation log10 log10 Z = A - B log10 T [1]_ through two points
    (T [K], nu [m^2/s])."""
    y1 = math.log10(math.log10(walther_z(nu1 * 1e6)))
    y2 = math.log10(math.log10(walther_z(nu2 * 1e6)))
    b = (y1 - y2) / (math.log10(t2) - math.log10(t1))
    return y1 + b * math.log10(t1), b


def kinematic_viscosity_walther(temperature, a, b):
    """Kinematic viscosity [m^2/s] at T [K] from Walther's A, B (:func:`walther_constants`) [1]_.

    Validity (ASTM D341): petroleum and synthetic oils as homogeneous
    liquids, between the cloud point and the initial boiling point;
    extrapolation beyond the two points is what the charts are for, within
    that range.
    """
    z = 10.0 ** (10.0 ** (a - b * np.log10(np.asarray(temperature, dtype=float))))
    v = walther_nu(z) * 1e-6
    return v if np.ndim(v) else float(v)


def density_linear(temperature, t_ref, rho_ref, slope):
    """Density [kg/m^3]: rho = rho_ref - slope (T - T_ref), the linear expansion of lubricating oils
    (slope about 0.6-0.7 kg/m^3/K, the ASTM D1250 expansion coefficient of about 7e-4 1/K)."""
    r = rho_ref - slope * (np.asarray(temperature, dtype=float) - t_ref)
    return r if np.ndim(r) else float(r)


def pressure_viscosity_gold(nu, s, t):
    """Pressure-viscosity coefficient alpha [1/Pa] = s nu^t, nu in mm^2/s (Gold et al. [2]_).

    Gold et al. fit alpha against the kinematic viscosity at the same
    temperature for each oil class; here ``s`` [1/Pa] and ``t`` [-] come
    from two catalogue points of the oil (:func:`gold_constants`), so alpha
    follows the viscosity's temperature dependence.
    """
    a = s * np.asarray(nu, dtype=float) ** t
    return a if np.ndim(a) else float(a)


def gold_constants(nu1, alpha1, nu2, alpha2):
    """s [1/Pa], t [-] of alpha = s nu^t (nu in mm^2/s) through two points (nu [m^2/s], alpha [1/Pa])."""
    t = math.log(alpha2 / alpha1) / math.log(nu2 / nu1)
    return alpha1 / (nu1 * 1e6) ** t, t


def thermal_conductivity_cragoe(temperature, rho15):
    """Thermal conductivity of a petroleum oil [W/(m K)], Cragoe [3]_:
    k = 0.1167 (1 - 0.00054 theta) / d, theta in C, d the specific gravity at 15 C (rho15 / 1000).

    Validity: petroleum oils, 0-200 C, about 10 %; esters are some 10-20 %
    higher (not covered by the relation)."""
    theta = np.asarray(temperature, dtype=float) - 273.15
    k = 0.1167 * (1.0 - 0.00054 * theta) / (rho15 / 1000.0)
    return k if np.ndim(k) else float(k)


def specific_heat_cragoe(temperature, rho15):
    """Specific heat of a petroleum oil [J/(kg K)], Cragoe [3]_:
    c_p = (1.685 + 0.00339 theta) / sqrt(d) kJ/(kg K), theta in C, d the specific gravity at 15 C.

    Validity: petroleum oils, 0-200 C, a few per cent."""
    theta = np.asarray(temperature, dtype=float) - 273.15
    c = (1.685 + 0.00339 * theta) / np.sqrt(rho15 / 1000.0) * 1e3
    return c if np.ndim(c) else float(c)


def properties_at(lubricant, temperature) -> dict:
    """Properties of a lubricant with temperature (a name of ``lubricants_temperature.json`` or a
    :class:`~exudyn_bearing.data.lubricants_temperature.LubricantTemperatureData`) at T [K]:
    ``kinematic_viscosity`` [m^2/s], ``density`` [kg/m^3], ``viscosity`` [Pa s],
    ``pressure_viscosity`` [1/Pa], ``thermal_conductivity`` [W/(m K)], ``specific_heat``
    [J/(kg K)]. A temperature outside the entry's range is an InputError."""
    d = get_lubricant_temperature(lubricant)
    t = d.check_temperature(temperature)
    (t1, nu1), (t2, nu2) = d.viscosity_points
    a, b = walther_constants(t1, nu1, t2, nu2)
    nu = kinematic_viscosity_walther(t, a, b)
    (ta1, al1), (ta2, al2) = d.pressure_viscosity_points
    s, ex = gold_constants(kinematic_viscosity_walther(ta1, a, b), al1, kinematic_viscosity_walther(ta2, a, b), al2)
    t_ref, rho_ref = d.density_reference
    rho = density_linear(t, t_ref, rho_ref, d.density_slope)
    rho15 = density_linear(288.15, t_ref, rho_ref, d.density_slope)
    return {"temperature": t, "kinematic_viscosity": nu, "density": rho, "viscosity": nu * rho,
            "pressure_viscosity": pressure_viscosity_gold(nu * 1e6, s, ex),
            "thermal_conductivity": thermal_conductivity_cragoe(t, rho15),
            "specific_heat": specific_heat_cragoe(t, rho15)}


def lubricant_at(lubricant, temperature, **overrides) -> Lubricant:
    """A fixed-temperature :class:`~exudyn_bearing.data.Lubricant` (what the solvers take) of a
    lubricant with temperature at T [K]: its viscosity and pressure-viscosity coefficient at T, its
    roughness; ``overrides`` set further Lubricant fields (regime breakpoints, friction)."""
    d = get_lubricant_temperature(lubricant)
    p = properties_at(d, temperature)
    fields = {"viscosity": p["viscosity"], "pressure_viscosity": p["pressure_viscosity"],
              "roughness_race": d.roughness_race, "roughness_ball": d.roughness_ball,
              "roughness_factor": d.roughness_factor, "name": f"{d.name}@{p['temperature']:g}K",
              "source": f"{d.name} at {p['temperature']:g} K (lubricants_temperature.json): {d.source}"}
    fields.update(overrides)
    return Lubricant(**fields)
