"""Bearing geometry at the operating point: rings grown by speed, fit and temperature.

The groove construction is that of :class:`exudyn_bearing.data.BallBearing`
(tube-centre circles of the two grooves at ``inner_groove_center`` and
``outer_groove_center``). At speed and temperature:

* the rotating inner ring grows radially by the rotating annular disc
  (bore to raceway radius, plane stress) plus the Lame growth of its shaft
  fit pressure (:func:`exudyn_bearing.physics.ring_growth.inner_ring_raceway_growth`);
  the groove cross-section moves outward rigidly by that amount;
* a rotating outer ring grows by the free rotating disc from its raceway to
  its outside radius (no housing fit modelled);
* each part expands uniformly with its temperature (rings: every length of
  the groove construction, i.e. the tube-centre radius, its axial position
  and the groove radius; balls: their radius), from a reference of 293.15 K.

Where the catalogue gives no bore or outside diameter, the ring section is
estimated as in :func:`.initial_state.ring_mass_estimate`
(0.65 R_b below the inner raceway, 0.65 R_b above the outer one).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from ..data import BallBearing, InputError
from ..data.errors import check_temperatures
from ..physics import ring_growth as rg

__all__ = ["OperatingGeometry", "operating_geometry", "REFERENCE_TEMPERATURE", "start_geometry"]

#: Temperature at which the catalogue dimensions hold [K].
REFERENCE_TEMPERATURE = 293.15


@dataclass(frozen=True)
class OperatingGeometry:
    """Groove construction at the operating point (SI units)."""

    rho_i: float        #: inner tube-centre circle radius [m]
    z_i: float          #: its axial position [m]
    rho_o: float        #: outer tube-centre circle radius [m]
    z_o: float          #: its axial position [m]
    r_ci: float         #: inner groove radius [m]
    r_co: float         #: outer groove radius [m]
    r_b: float          #: ball radius [m]
    inner_ring_growth: float   #: radial growth of the inner raceway (speed + fit) [m]
    outer_ring_growth: float   #: radial growth of the outer raceway (speed) [m]
    inner_thermal_growth: float  #: thermal growth of the inner tube-centre radius [m]
    outer_thermal_growth: float  #: thermal growth of the outer tube-centre radius [m]
    ball_thermal_growth: float   #: thermal growth of the ball radius [m]
    fit_pressure: float  #: shaft fit pressure at speed [Pa]
    bore_radius: float   #: inner ring bore radius used [m]

    @property
    def groove_distance(self) -> float:
        """A = R_ci + R_co - 2 R_b [m]."""
        return self.r_ci + self.r_co - 2.0 * self.r_b

    @property
    def operating_clearance(self) -> float:
        """Diametral clearance along the contact line at the operating point [m]:
        2 (A - |p_i - p_o|) with the rings centred (negative: interference)."""
        return 2.0 * (self.groove_distance - math.hypot(self.rho_i - self.rho_o, self.z_i - self.z_o))


def operating_geometry(bearing: BallBearing, omega_inner=0.0, omega_outer=0.0, ring_growth=True, fit=0.0,
                       temperatures=None) -> OperatingGeometry:
    """Grooves and ball at speed, fit and temperature (module docstring).

    Parameters
    ----------
    bearing : BallBearing
    omega_inner, omega_outer : float
        Ring speeds [rad/s].
    ring_growth : bool
        Apply the centrifugal growth of the rotating rings (and the fall of
        the fit pressure with speed); False keeps rigid rings.
    fit : float
        Diametral interference of the inner ring on a solid shaft of the same
        material [m] (>= 0).
    temperatures : dict, optional
        ``{"inner": T_i, "outer": T_o, "ball": T_b}`` [K]; missing ones at
        293.15 K.
    """
    b = bearing
    mat = b.material
    fit = float(fit)
    if not math.isfinite(fit) or fit < 0.0:
        raise InputError(f"fit: the diametral interference must be >= 0 m, got {fit!r}")
    temps = {"inner": REFERENCE_TEMPERATURE, "outer": REFERENCE_TEMPERATURE, "ball": REFERENCE_TEMPERATURE}
    temps.update(check_temperatures(temperatures) or {})
    bore = 0.5 * b.bore if b.bore is not None else b.inner_race_radius - 0.65 * b.ball_radius
    outside = 0.5 * b.outer_diameter if b.outer_diameter is not None else b.outer_race_radius + 0.65 * b.ball_radius
    if not 0.0 < bore < b.inner_race_radius:
        raise InputError(f"bore: the bore radius {bore:g} m must lie below the inner raceway radius "
                         f"{b.inner_race_radius:g} m")
    if fit > 0.0 and fit > 0.01 * bore:
        raise InputError(f"fit: interference {fit:g} m exceeds 1 % of the bore diameter ({0.02 * bore:g} m): "
                         f"not a shrink fit")
    kw = dict(density=mat.density, youngs_modulus=mat.youngs_modulus, poisson_ratio=mat.poisson_ratio)
    w_i = float(omega_inner) if ring_growth else 0.0
    w_o = float(omega_outer) if ring_growth else 0.0
    p_fit = float(rg.fit_pressure(fit, bore, b.inner_race_radius, w_i, **kw))
    yield_limit = 0.5 * mat.youngs_modulus * 1e-2
    if p_fit > yield_limit:
        raise InputError(f"fit: {fit:g} m gives a fit pressure of {p_fit / 1e6:.0f} MPa, above "
                         f"{yield_limit / 1e6:.0f} MPa (E/200, beyond an elastic press fit)")
    u_i = float(rg.inner_ring_raceway_growth(b.inner_race_radius, bore, w_i, fit, **kw))
    u_o = float(rg.rotating_disc_displacement(b.outer_race_radius, b.outer_race_radius, outside, w_o,
                                              mat.density, mat.youngs_modulus, mat.poisson_ratio))
    alpha_t = mat.thermal_expansion
    s_i = alpha_t * (temps["inner"] - REFERENCE_TEMPERATURE)
    s_o = alpha_t * (temps["outer"] - REFERENCE_TEMPERATURE)
    s_b = alpha_t * (temps["ball"] - REFERENCE_TEMPERATURE)
    rho_i, z_i = b.inner_groove_center
    rho_o, z_o = b.outer_groove_center
    return OperatingGeometry(
        rho_i=rho_i * (1.0 + s_i) + u_i, z_i=z_i * (1.0 + s_i),
        rho_o=rho_o * (1.0 + s_o) + u_o, z_o=z_o * (1.0 + s_o),
        r_ci=b.inner_groove_radius * (1.0 + s_i), r_co=b.outer_groove_radius * (1.0 + s_o),
        r_b=b.ball_radius * (1.0 + s_b),
        inner_ring_growth=u_i, outer_ring_growth=u_o,
        inner_thermal_growth=rho_i * s_i, outer_thermal_growth=rho_o * s_o,
        ball_thermal_growth=b.ball_radius * s_b, fit_pressure=p_fit, bore_radius=bore)


def start_geometry(bearing: BallBearing, scenario) -> BallBearing:
    """The bearing as a dynamic run sees it at t = 0: with ``scenario.ring_growth``
    the raceways grown with the rings' start speeds (the engines' growth
    coefficients times omega^2, :func:`operating_geometry`: the inner raceway
    with ``omega``, the outer one with ``omega_outer``), so that the analytic
    start and the a-priori stable step use the loads the run starts with."""
    w0, w0_o = scenario.omega_at(0.0), scenario.omega_outer_at(0.0)
    if not scenario.ring_growth or (w0 == 0.0 and w0_o == 0.0):
        return bearing
    geom = operating_geometry(bearing, omega_inner=w0, omega_outer=w0_o)
    return bearing.replace(inner_race_radius=bearing.inner_race_radius + geom.inner_ring_growth,
                           outer_race_radius=bearing.outer_race_radius + geom.outer_ring_growth)
