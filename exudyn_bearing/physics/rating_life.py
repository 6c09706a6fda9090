"""Load ratings and rating life of radial and angular-contact ball bearings: ISO 281:2007, ISO 76:2006,
ISO/TR 1281-1 and ISO/TS 16281; the limiting-speed check.

docs/theory/rating_life.md. One relation per function. Inputs and outputs are SI (N, m, m^2/s, rad/s, K);
the standards work in N and mm (and mm^2/s, r/min), and each function converts at its boundary: a factor
such as f_c carries the standards' units (N/mm^1.8) and is used only inside these functions. Lives are in
10^6 revolutions (the standards' unit) and hours.

References
----------
.. [1] ISO 281:2007, Rolling bearings -- Dynamic load ratings and rating life.
.. [2] ISO 76:2006, Rolling bearings -- Static load ratings.
.. [3] ISO/TR 1281-1:2008 (2nd ed. 2021), Rolling bearings -- Explanatory notes on ISO 281 -- Part 1: Basic
   dynamic load rating and basic rating life (the Lundberg-Palmgren relations behind f_c).
.. [4] ISO/TS 16281:2008, Rolling bearings -- Methods for calculating the modified reference rating life for
   universally loaded bearings.
.. [5] G. Lundberg and A. Palmgren, Dynamic capacity of rolling bearings, Acta Polytechnica, Mech. Eng. Ser.
   1(3) (1947); T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., 2006 (Vol. 2, ch. 8: f_c,
   Q_c, the load integrals J_r, J_1, J_2).
"""
from __future__ import annotations

import math
import re
import warnings
from dataclasses import MISSING, asdict, dataclass, field, fields

import numpy as np
from scipy.optimize import brentq

from ..data import InputError
from ..data import iso281 as T
from ..data.errors import check_finite, check_nonnegative, check_positive, check_temperature, lookup
from ..data.lubricants_temperature import get_lubricant_temperature, lubricants_temperature
from . import hertz
from .geometry import raceway_radii
from .lubricant_properties import properties_at

__all__ = ["RatingLife", "RatingLifeWarning", "RatingScopeError", "SpeedLimitWarning", "RATING_UNITS", "DEFAULT_RELIABILITY",
           "DEFAULT_CONTAMINATION", "B_M", "MAX_A_ISO", "SPEED_LIMITS", "MAX_CONTACT_PRESSURE_C0",
           "load_rating_factor", "conformity_factor", "dynamic_load_rating", "static_load_rating",
           "static_load_rating_hertz", "equivalent_dynamic_load", "equivalent_static_load", "basic_rating_life",
           "life_hours", "reliability_factor", "rated_viscosity", "contamination_factor", "fatigue_load_limit",
           "life_modification_factor", "load_integrals", "raceway_contact_ratings", "reference_rating_life",
           "lubricant_viscosity", "speed_factor", "check_speed_limit", "rating_life"]

#: Rating factor b_m of radial ball bearings (ISO 281:2007 Table 1): the contemporary steel's improvement.
B_M = 1.3
#: Cap of a_ISO (ISO 281:2007 clause 6.5.3).
MAX_A_ISO = 50.0
#: Reliability [%] of the basic rating life.
DEFAULT_RELIABILITY = 90.0
#: Contamination class used when none is given (ISO 281:2007 Table 13): normal cleanliness, the class of
#: bearings with good sealing and filtered oil (the common default of calculation programs).
DEFAULT_CONTAMINATION = "normal-cleanliness"
#: Contact stress of the static load rating of ball bearings (ISO 76:2006 clause 5.1) [Pa].
MAX_CONTACT_PRESSURE_C0 = 4.2e9
#: Rated-viscosity range of kappa in a_ISO (ISO 281:2007 clause 6.5.3): kappa above 4 counts as 4; below 0.1
#: the standard does not apply.
KAPPA_RANGE = (0.1, 4.0)
#: Operating temperature above which ISO 281's ratings (standard bearing steel, dimensionally stabilised to
#: 150 C) do not hold without a reduction [K] (ISO 281:2007 clause 1, scope; manufacturers' stabilisation
#: class S0 to 150 C).
MAX_TEMPERATURE_ISO281 = 423.15
#: Centrifugal force over the largest inner contact load above which the load distribution is called
#: dominated by ball inertia (ISO 281 assumes a distribution without it) [-].
CENTRIFUGAL_DOMINANCE = 0.1
#: Speed factor n d_m limits [mm/min] (rev/min times mm): (limit, what it is, source).
SPEED_LIMITS = (
    (1.0e6, "the limit of standard deep-groove and angular-contact bearings with pressed steel or polyamide cages "
            "and oil-bath or circulating-oil lubrication (catalogue limiting speeds of the 62 and 72 series lie "
            "at n d_m = 0.5-1.0e6, e.g. SKF's 6208: 9500 r/min on d_m = 60 mm; Harris & Kotzalas, Rolling "
            "Bearing Analysis, 5th ed., 2006, on limiting speeds); above it, jet lubrication and a machined, "
            "ring-guided cage are needed"),
    (4.0e6, "the limit of jet-lubricated aircraft mainshaft ball bearings of M-50 steel (3 million DN, bore "
            "times r/min: n d_m about 3.5-4e6; Zaretsky (ed.), STLE Life Factors for Rolling Bearings, 1992; "
            "Harris & Kotzalas 2006)"),
)

#: Units of :meth:`RatingLife.to_dict`.
RATING_UNITS = {
    "C": "N (basic dynamic radial load rating, ISO 281)", "C0": "N (basic static load rating used for s0)",
    "C0_iso76": "N (ISO 76 table, grooves of the standard)", "C0_hertz": "N (4.2 GPa with the bearing's grooves)",
    "C_u": "N (fatigue load limit)", "P": "N (equivalent dynamic load, ISO 281)",
    "P0": "N (equivalent static load, ISO 76)", "X": "-", "Y": "-", "e": "-", "s0": "-",
    "s0_pressure": "- ((4.2 GPa / p_max)^3 of the computed load distribution)", "p_max": "Pa",
    "L10": "10^6 revolutions", "L10h": "h (at the given speed)", "L10m": "10^6 revolutions",
    "L10mh": "h", "L10r": "10^6 revolutions (ISO/TS 16281, without speed effects)",
    "L10mr": "10^6 revolutions (ISO/TS 16281, without speed effects)", "L10mrh": "h",
    "L10r_speed": "10^6 revolutions (ISO/TS 16281 on the distribution at speed: centrifugal loads and contact "
                  "angles; not in the standard)",
    "L10mr_speed": "10^6 revolutions (as L10r_speed)", "a1": "-", "a_iso": "-", "a_iso_r": "- (a_ISO of L10mr)",
    "kappa": "-", "nu": "m^2/s (kinematic viscosity at the operating temperature)", "nu1": "m^2/s (rated viscosity)",
    "e_C": "-", "reliability": "%", "n": "r/min (relative speed of the rings)", "n_dm": "mm/min",
    "temperature": "K (lubricant temperature of kappa)", "f_c": "N/mm^1.8 (ISO 281 units)",
    "f_0": "N/mm^2 (ISO 76 units)", "P_ref": "N (equivalent load of L10r, C L10r^(-1/3))",
    "Fr_bearing": "N (radial load the bearing carries: applied plus held DOFs' reactions)",
    "Fa_bearing": "N (axial load the bearing carries)",
}


class RatingLifeWarning(UserWarning):
    """A bearing or operating point outside the assumptions of ISO 281 / ISO/TS 16281."""


class SpeedLimitWarning(UserWarning):
    """A speed factor n d_m above the limits of :data:`SPEED_LIMITS`."""


class RatingScopeError(InputError):
    """A bearing the standards' tables do not cover (D_w cos(alpha) / D_pw beyond the tables, a contact angle
    above 45 deg): :func:`rating_life` reports no rating for it instead of failing the run."""


def _mm(x):
    return 1e3 * float(x)


def _interp(table, x, name, what):
    xs, ys = np.array([r[0] for r in table]), np.array([r[1] for r in table])
    if not xs[0] - 1e-12 <= x <= xs[-1] + 1e-12:
        raise RatingScopeError(f"{name}: {what} = {x:.4g} lies outside the standard's table ({xs[0]:g} to {xs[-1]:g})")
    return float(np.interp(x, xs, ys))


def load_rating_factor(gamma):
    """f_c [N/mm^1.8] of ISO 281:2007 Table 2 [1]_ (single-row deep-groove and angular-contact ball bearings)
    at gamma = D_w cos(alpha) / D_pw, linearly interpolated; the table assumes groove radii of at most 0.52 D_w
    (inner) and 0.53 D_w (outer)."""
    return _interp(T.FC_TABLE, float(gamma), "ball_diameter", "D_w cos(alpha) / D_pw")


def conformity_factor(gamma, inner_conformity, outer_conformity):
    """The conformity-dependent part of f_c from Lundberg and Palmgren as stated in ISO/TR 1281-1 [3]_ [5]_:

    f_c ~ [1 + (1.04 ((1 - g)/(1 + g))^1.72 (f_i (2 f_e - 1) / (f_e (2 f_i - 1)))^0.41)^(10/3)]^(-0.3)
          g^0.3 (1 - g)^1.39 / (1 + g)^(1/3) (2 f_i / (2 f_i - 1))^0.41

    (g = D_w cos(alpha) / D_pw, f = groove radius / D_w). Its ratio at the bearing's conformities to the ratio
    at the standard's (0.52, 0.53) scales ISO 281's tabulated f_c to looser grooves."""
    g, fi, fe = float(gamma), float(inner_conformity), float(outer_conformity)
    ratio = fi * (2.0 * fe - 1.0) / (fe * (2.0 * fi - 1.0))
    bracket = (1.0 + (1.04 * ((1.0 - g) / (1.0 + g)) ** 1.72 * ratio ** 0.41) ** (10.0 / 3.0)) ** -0.3
    return bracket * g ** 0.3 * (1.0 - g) ** 1.39 / (1.0 + g) ** (1.0 / 3.0) * (2.0 * fi / (2.0 * fi - 1.0)) ** 0.41


def _diameter_term(d_mm):
    """D_w^1.8 (D_w <= 25.4 mm) or 3.647 D_w^1.4 (larger balls), ISO 281:2007 eq. (2), (3), D_w in mm."""
    return d_mm ** 1.8 if d_mm <= 25.4 else 3.647 * d_mm ** 1.4


def dynamic_load_rating(n_balls, ball_diameter, pitch_diameter, contact_angle=0.0, inner_conformity=0.52,
                        outer_conformity=0.53):
    """Basic dynamic radial load rating C_r [N] of a single-row radial or angular-contact ball bearing
    (ISO 281:2007 eq. (2), (3) [1]_): C_r = b_m f_c (i cos(alpha))^0.7 Z^(2/3) D_w^1.8 (D_w <= 25.4 mm), or
    b_m f_c (i cos(alpha))^0.7 Z^(2/3) 3.647 D_w^1.4, in N with D_w in mm, b_m = 1.3, i = 1.

    Lengths in m (converted to the standard's mm here). f_c from ISO 281 Table 2 where the grooves are not looser
    than the table assumes (0.52 / 0.53); otherwise the table's f_c times the ratio of
    :func:`conformity_factor` at the bearing's conformities to that at 0.52 / 0.53 (ISO/TR 1281-1 [3]_).
    Tighter grooves do not raise the rating (ISO 281 clause 6.1.1). Returns (C_r, f_c, method)."""
    z = int(n_balls)
    d, dm = _mm(check_positive("ball_diameter", ball_diameter)), _mm(check_positive("pitch_diameter",
                                                                                       pitch_diameter))
    ca = math.cos(check_finite("free_contact_angle", contact_angle))
    gamma = d * ca / dm
    fc = load_rating_factor(gamma)
    fi0, fe0 = T.STANDARD_CONFORMITY
    fi, fe = max(float(inner_conformity), fi0), max(float(outer_conformity), fe0)
    if fi > fi0 + 1e-9 or fe > fe0 + 1e-9:
        fc *= conformity_factor(gamma, fi, fe) / conformity_factor(gamma, fi0, fe0)
        method = (f"ISO 281 Table 2 f_c scaled to the grooves f_i = {fi:.3g}, f_e = {fe:.3g} by ISO/TR 1281-1's "
                  "conformity relation (looser than the table's 0.52 / 0.53)")
    else:
        method = "ISO 281:2007 Table 2 f_c (grooves within 0.52 / 0.53)"
    return B_M * fc * ca ** 0.7 * z ** (2.0 / 3.0) * _diameter_term(d), fc, method


def static_load_rating(n_balls, ball_diameter, pitch_diameter, contact_angle=0.0):
    """Basic static radial load rating C_0r [N] = f_0 i Z D_w^2 cos(alpha) (ISO 76:2006 eq. (1) [2]_, N and mm,
    i = 1), f_0 from ISO 76 Table 1 at D_w cos(alpha) / D_pw (grooves of at most 0.52 / 0.53 D_w). Lengths in m.
    Returns (C_0r, f_0)."""
    d, dm = _mm(ball_diameter), _mm(pitch_diameter)
    ca = math.cos(contact_angle)
    f0 = _interp(T.F0_TABLE, d * ca / dm, "ball_diameter", "D_w cos(alpha) / D_pw")
    return f0 * int(n_balls) * d * d * ca, f0


def contact_load_at_pressure(bearing, pressure=MAX_CONTACT_PRESSURE_C0, contact_angle=None):
    """The ball load [N] at which the inner and the outer contact reach the Hertz pressure ``pressure`` [Pa]
    (docs/theory/hertz.md; p_max grows as Q^(1/3)), at the free contact angle: (Q_inner, Q_outer)."""
    b = bearing
    a = b.free_contact_angle if contact_angle is None else contact_angle
    em = hertz.material_reduced_modulus(b.material)
    out = []
    for r_c, sign, inner in ((b.inner_groove_radius, -1.0, True), (b.outer_groove_radius, 1.0, False)):
        rx, ry = raceway_radii(b.ball_radius, r_c, b.pitch_radius + sign * b.ball_radius * math.cos(a), a, inner)
        p1 = float(hertz.hertz_contact(rx, ry, em, load=1.0).p_max)
        out.append((pressure / p1) ** 3)
    return out[0], out[1]


def static_load_rating_hertz(bearing, pressure=MAX_CONTACT_PRESSURE_C0):
    """C_0 [N] by the criterion ISO 76's f_0 is built on [2]_, with the bearing's own grooves and material: the
    radial load whose most heavily loaded ball, Q_max = 5 F_r / (Z cos(alpha)) (Stribeck's factor of ISO 76),
    reaches ``pressure`` (4.2 GPa) at its inner or outer contact (exact Hertz, docs/theory/hertz.md)."""
    q = min(contact_load_at_pressure(bearing, pressure))
    return q * bearing.n_balls * math.cos(bearing.free_contact_angle) / 5.0


def _angle_deg(contact_angle):
    return math.degrees(float(contact_angle))


def equivalent_dynamic_load(radial_load, axial_load, contact_angle, c0, f0):
    """Equivalent dynamic radial load P_r = X F_r + Y F_a [N] (ISO 281:2007 eq. (8), Table 3 [1]_) of a single-row
    deep-groove (alpha = 0) or angular-contact ball bearing: X = 1, Y = 0 for F_a / F_r <= e. Deep-groove and
    15 deg: e and Y interpolated in f_0 F_a / C_0r (above the last row its values); 20-45 deg: the rows by
    contact angle, interpolated linearly; 0 < alpha < 15 deg: interpolated between the deep-groove (alpha = 0)
    and 15 deg results (an approximation, stated in the method). Returns (P, X, Y, e)."""
    fr, fa = float(radial_load), abs(float(axial_load))
    deg = _angle_deg(contact_angle)
    if deg > 45.0 + 1e-9:
        raise RatingScopeError(f"free_contact_angle: ISO 281 Table 3 covers angular-contact ball bearings up to 45 deg, "
                         f"got {deg:.3g} deg")
    rel = f0 * fa / c0 if c0 > 0 else 0.0

    def grooved(rows, x_big):
        xs = [r[0] for r in rows]
        e = float(np.interp(rel, xs, [r[1] for r in rows]))
        y = float(np.interp(rel, xs, [r[2] for r in rows]))
        return (1.0, 0.0, e) if fa <= e * fr else (x_big, y, e)

    if deg >= 20.0 - 1e-9:
        ang = [r[0] for r in T.XYE_ANGULAR]
        e = float(np.interp(deg, ang, [r[3] for r in T.XYE_ANGULAR]))
        x, y = ((1.0, 0.0) if fa <= e * fr else
                (float(np.interp(deg, ang, [r[1] for r in T.XYE_ANGULAR])),
                 float(np.interp(deg, ang, [r[2] for r in T.XYE_ANGULAR]))))
    elif deg >= 15.0 - 1e-9:
        x15 = grooved(T.XYE_ANGULAR_15, T.X_ANGULAR_15)
        x20 = (1.0, 0.0, 0.57) if fa <= 0.57 * fr else (0.43, 1.00, 0.57)
        w = (deg - 15.0) / 5.0
        x, y, e = ((1 - w) * a + w * b for a, b in zip(x15, x20))
    elif deg > 1e-9:
        x0 = grooved(T.XYE_DEEP_GROOVE, T.X_DEEP_GROOVE)
        x15 = grooved(T.XYE_ANGULAR_15, T.X_ANGULAR_15)
        w = deg / 15.0
        x, y, e = ((1 - w) * a + w * b for a, b in zip(x0, x15))
    else:
        x, y, e = grooved(T.XYE_DEEP_GROOVE, T.X_DEEP_GROOVE)
    return x * fr + y * fa, x, y, e


def equivalent_static_load(radial_load, axial_load, contact_angle):
    """Equivalent static radial load P_0r = max(X_0 F_r + Y_0 F_a, F_r) [N] (ISO 76:2006 eq. (5), (6),
    Table 2 [2]_): deep groove X_0 = 0.6, Y_0 = 0.5; angular contact X_0 = 0.5, Y_0 by contact angle
    (interpolated; below 15 deg between the deep-groove and the 15 deg values)."""
    fr, fa = float(radial_load), abs(float(axial_load))
    deg = _angle_deg(contact_angle)
    ang = [r[0] for r in T.X0Y0_ANGULAR]
    if deg >= 15.0:
        x0, y0 = 0.5, float(np.interp(deg, ang, [r[2] for r in T.X0Y0_ANGULAR]))
    else:
        w = deg / 15.0
        x0 = (1 - w) * T.X0Y0_DEEP_GROOVE[0] + w * 0.5
        y0 = (1 - w) * T.X0Y0_DEEP_GROOVE[1] + w * T.X0Y0_ANGULAR[0][2]
    return max(x0 * fr + y0 * fa, fr)


def basic_rating_life(c, p):
    """L_10 = (C / P)^3 [10^6 revolutions] of ball bearings (ISO 281:2007 eq. (15) [1]_); inf without load."""
    return math.inf if p <= 0.0 else (float(c) / float(p)) ** 3


def life_hours(life, speed_rpm):
    """A life in 10^6 revolutions as hours at ``speed_rpm`` [r/min]: L 10^6 / (60 n); None without speed."""
    if life is None or not speed_rpm:
        return None
    return life * 1e6 / (60.0 * abs(speed_rpm))


def reliability_factor(reliability):
    """a_1 (ISO 281:2007 clause 6.2, Table 12 [1]_) for a reliability [%] of 90 to 99.95:
    a_1 = 0.95 (ln(100 / R) / ln(100 / 90))^(2/3) + 0.05 (the Weibull relation the table is computed from,
    slope 1.5, with the standard's minimum life 0.05 L_10)."""
    r = check_finite("reliability", reliability)
    if 0.0 < r < 1.0:
        raise InputError(f"reliability: {r:g} reads as a fraction; give per cent (e.g. 90, 99)")
    if not 90.0 <= r <= 99.95:
        raise InputError(f"reliability: ISO 281's a_1 covers 90 to 99.95 %, got {r:g}")
    return 0.95 * (math.log(100.0 / r) / math.log(100.0 / 90.0)) ** (2.0 / 3.0) + 0.05


def rated_viscosity(speed_rpm, pitch_diameter):
    """Rated (reference) kinematic viscosity nu_1 [m^2/s] (ISO 281:2007 eq. (26), (27) [1]_), in the standard's
    mm^2/s with n [r/min] and D_pw [mm]: 45000 n^-0.83 D_pw^-0.5 for n < 1000 r/min, 4500 n^-0.5 D_pw^-0.5
    otherwise."""
    n, dm = abs(float(speed_rpm)), _mm(pitch_diameter)
    if n <= 0.0:
        raise InputError("omega: the rated viscosity needs a speed (kappa is undefined at rest)")
    nu1 = 45000.0 * n ** -0.83 * dm ** -0.5 if n < 1000.0 else 4500.0 * n ** -0.5 * dm ** -0.5
    return nu1 * 1e-6


def contamination_factor(contamination, pitch_diameter):
    """e_C [-] of an ISO 281:2007 Table 13 class [1]_ (:data:`exudyn_bearing.data.iso281.CONTAMINATION`: the
    midpoint of the class's range, the range for D_pw < 100 mm or >= 100 mm), or a number in [0, 1] taken as
    e_C itself."""
    if isinstance(contamination, (int, float)) and not isinstance(contamination, bool):
        e = check_nonnegative("contamination", contamination)
        if e > 1.0:
            raise InputError(f"contamination: e_C lies in [0, 1], got {e:g}")
        return e
    key = str(contamination).strip().lower().replace("_", "-").replace(" ", "-")
    small, large = lookup(T.CONTAMINATION, key, "contamination: unknown ISO 281 class", "valid")
    lo, hi = small if _mm(pitch_diameter) < 100.0 else large
    return 0.5 * (lo + hi)


def fatigue_load_limit(c0, pitch_diameter):
    """Fatigue load limit C_u [N] of a ball bearing by ISO 281:2007 Annex B's approximation (B.3.2.2 [1]_):
    C_u = C_0 / 27 for D_pw <= 100 mm, times (100 / D_pw)^0.5 above (D_pw in mm)."""
    dm = _mm(pitch_diameter)
    cu = float(c0) / 27.0
    return cu if dm <= 100.0 else cu * (100.0 / dm) ** 0.5


def life_modification_factor(kappa, ec_cu_p):
    """a_ISO [-] of radial ball bearings (ISO 281:2007 clause 6.5.3, eq. for radial ball bearings, Figure 2 [1]_):
    a_ISO = 0.1 [1 - (2.5671 - c / kappa^k)^0.83 (e_C C_u / P)^(1/3)]^(-9.3) with (c, k) = (2.2649, 0.054381)
    for 0.1 <= kappa < 0.4, (1.9987, 0.19087) for 0.4 <= kappa < 1, (1.9987, 0.071739) for 1 <= kappa <= 4;
    kappa above 4 counts as 4, and a_ISO is capped at 50 (also where the bracket vanishes). kappa below 0.1 is
    outside the standard: evaluated with the first branch (callers warn)."""
    k = min(check_positive("kappa", kappa), KAPPA_RANGE[1])
    x = check_nonnegative("e_C C_u / P", ec_cu_p)
    c, ex = (2.2649, 0.054381) if k < 0.4 else ((1.9987, 0.19087) if k < 1.0 else (1.9987, 0.071739))
    base = 2.5671 - c / k ** ex
    term = (max(base, 0.0) ** 0.83) * x ** (1.0 / 3.0)
    if term >= 1.0:
        return MAX_A_ISO
    return min(0.1 * (1.0 - term) ** -9.3, MAX_A_ISO)


def load_integrals(eps=0.5, n=20001):
    """Sjovall's integrals of a Stribeck load zone q(psi) = (1 - (1 - cos psi) / (2 eps))^(3/2) (Lundberg and
    Palmgren [5]_): J_r = mean(q cos psi), J_1 = mean(q^3)^(1/3) (rotating ring), J_2 = mean(q^(10/3))^(3/10)
    (stationary ring), means over the circle (trapezoidal rule on ``n`` points). At eps = 0.5 (zero clearance)
    Lundberg and Palmgren give J_r = 0.2288 and J_1 = 0.5625."""
    psi = np.linspace(-np.pi, np.pi, n)
    q = np.clip(1.0 - (1.0 - np.cos(psi)) / (2.0 * eps), 0.0, None) ** 1.5
    mean = (lambda f: float(np.trapezoid(f, psi)) / (2.0 * np.pi)) if hasattr(np, "trapezoid") else \
        (lambda f: float(np.trapz(f, psi)) / (2.0 * np.pi))
    return mean(q * np.cos(psi)), mean(q ** 3) ** (1.0 / 3.0), mean(q ** (10.0 / 3.0)) ** 0.3


def raceway_contact_ratings(ball_diameter, pitch_diameter, n_balls, contact_angle, inner_conformity,
                            outer_conformity):
    """Shape of the basic dynamic load ratings of a ball-raceway contact, inner and outer (Lundberg and Palmgren
    [5]_, ISO/TR 1281-1 [3]_, the form ISO/TS 16281 [4]_ uses), without the constant:

    q_ci = (2 f_i / (2 f_i - 1))^0.41 (1 - g)^1.39 / (1 + g)^(1/3) (D_w / D_pw)^0.3 D_w^1.8 Z^(-1/3)
    q_ce = (2 f_e / (2 f_e - 1))^0.41 (1 + g)^1.39 / (1 - g)^(1/3) (D_w / D_pw)^0.3 D_w^1.8 Z^(-1/3)

    g = D_w cos(alpha) / D_pw per ball (``contact_angle`` may be an array), D_w in mm (D_w^1.8 -> 3.647 D_w^1.4
    above 25.4 mm as in ISO 281). The constant follows from C in :func:`reference_rating_life`."""
    d, dm = _mm(ball_diameter), _mm(pitch_diameter)
    g = d * np.cos(np.asarray(contact_angle, float)) / dm
    common = (d / dm) ** 0.3 * _diameter_term(d) * int(n_balls) ** (-1.0 / 3.0)
    fi, fe = float(inner_conformity), float(outer_conformity)
    qi = (2 * fi / (2 * fi - 1)) ** 0.41 * (1 - g) ** 1.39 / (1 + g) ** (1 / 3) * common
    qe = (2 * fe / (2 * fe - 1)) ** 0.41 * (1 + g) ** 1.39 / (1 - g) ** (1 / 3) * common
    return qi, qe


def reference_rating_life(bearing, c, q_inner, alpha_inner, q_outer, alpha_outer, rotating="inner"):
    """Basic reference rating life L_10r [10^6 revolutions] of a ball bearing from its load distribution
    (ISO/TS 16281 [4]_): per race the equivalent reference load of the ball loads Q_j against the contact
    ratings Q_c,j (:func:`raceway_contact_ratings` at each ball's contact angle),

    rotating race:   L = [ (1/Z) sum (Q_j / Q_c,j)^3 ]^-1
    stationary race: L = [ (1/Z) sum (Q_j / Q_c,j)^(10/3) ]^(-9/10)

    and L_10r = (L_i^(-10/9) + L_e^(-10/9))^(-9/10). The constant of Q_ci and Q_ce is fixed by ISO 281: a
    radial load F_r = C on the bearing at zero clearance (Stribeck zone eps = 0.5, :func:`load_integrals`, at the
    free contact angle) gives L_10r = 1, as the two standards' ratings are defined alike. Loads in N, angles
    in rad. Returns (L_10r, L_i, L_e, constant [N per unit of q_c])."""
    b = bearing
    z = b.n_balls
    d, dm = b.ball_diameter, b.pitch_diameter
    fi, fe = b.inner_conformity, b.outer_conformity
    a0 = b.free_contact_angle
    jr, j1, j2 = load_integrals(0.5)
    qmax = c / (z * jr * math.cos(a0))
    qi0, qe0 = raceway_contact_ratings(d, dm, z, a0, fi, fe)
    lo_i, lo_e = (qmax * j1, qmax * j2) if rotating == "inner" else (qmax * j2, qmax * j1)
    const = ((lo_i / float(qi0)) ** (10 / 3) + (lo_e / float(qe0)) ** (10 / 3)) ** 0.3
    qci, qce = raceway_contact_ratings(d, dm, z, alpha_inner, fi, fe)
    qce = raceway_contact_ratings(d, dm, z, alpha_outer, fi, fe)[1]
    ri = np.asarray(q_inner, float) / (const * qci)
    re_ = np.asarray(q_outer, float) / (const * qce)

    def life(r, rot):
        s = float(np.mean(r ** (3.0 if rot else 10.0 / 3.0)))
        if s <= 0.0:
            return math.inf
        return 1.0 / s if rot else s ** -0.9

    li, le = life(ri, rotating == "inner"), life(re_, rotating != "inner")
    total = (li ** (-10 / 9) + le ** (-10 / 9)) ** (-0.9) if math.isfinite(li) or math.isfinite(le) else math.inf
    return total, li, le, const


def _entry_and_temperature(bearing, lubricant):
    """The lubricant with temperature (``lubricants_temperature.json``) of ``lubricant`` (a name of either
    catalogue, or an entry) or of the bearing's lubricant, and the temperature its name carries
    (``MIL-L-23699_492K``: 492 K) or None."""
    if lubricant is not None and not isinstance(lubricant, str) and not hasattr(lubricant, "viscosity"):
        return get_lubricant_temperature(lubricant), None
    name = getattr(lubricant, "name", lubricant) or getattr(bearing, "lubricant", None) or "guessasma2018"
    name = name.split("@")[0]  # lubricant_at's "<entry>@<T>K"
    m = re.search(r"_(\d+(?:\.\d+)?)K$", name)
    base = re.sub(r"_\d+(\.\d+)?K$", "", name)
    for cand in (name, base):
        if cand in lubricants_temperature:
            return lubricants_temperature[cand], (float(m.group(1)) if m else None)
    return None, None


def lubricant_viscosity(bearing, temperature=None, lubricant=None):
    """Kinematic viscosity nu [m^2/s] of the bearing's lubricant at its operating temperature for kappa, with
    the temperature [K] and a note on where both come from.

    ``temperature`` given: the lubricant with temperature (``lubricants_temperature.json``; the name without a
    ``_<T>K`` suffix) at that temperature (ASTM D341, :func:`~.lubricant_properties.properties_at`). None: the
    temperature the name carries (``MIL-L-23699_492K``: 492 K), else the temperature at which the entry's
    dynamic viscosity equals that of the fixed-temperature lubricant the solvers use (the catalogue's
    ``guessasma2018``, 0.04 Pa s: 313 K), the same oil state the films were computed with. A lubricant without
    an entry with temperature is an InputError naming ``lubricant``."""
    from ..data.catalog import load_lubricant  # data layer; imported here as catalog imports much

    entry, t_name = _entry_and_temperature(bearing, lubricant)
    if entry is None:
        raise InputError(f"lubricant: {getattr(lubricant, 'name', lubricant) or bearing.lubricant!r} has no entry "
                         f"with temperature for kappa; the lubricants with temperature are "
                         f"{', '.join(lubricants_temperature)}: the catalogue's MIL-L-23699_492K is one of them at "
                         f"492 K, and any of them at a temperature T comes from Python as "
                         f"exudyn_bearing.physics.lubricant_properties.lubricant_at(name, T)")
    if temperature is not None:
        t = entry.check_temperature(check_temperature("temperature", temperature))
        how = f"{entry.name} at the given {t:.2f} K"
    elif t_name is not None:
        t = entry.check_temperature(t_name)
        how = f"{entry.name} at {t:.2f} K (the temperature of the lubricant's name)"
    else:
        fixed = load_lubricant(lubricant if lubricant is not None and hasattr(lubricant, "viscosity") else
                               (lubricant if isinstance(lubricant, str) else None), bearing=bearing)
        lo, hi = entry.temperature_range
        f = lambda tt: math.log(properties_at(entry, tt)["viscosity"] / fixed.viscosity)
        if f(lo) * f(hi) > 0.0:
            raise InputError(f"temperature: the viscosity {fixed.viscosity:g} Pa s of lubricant {fixed.name!r} is "
                             f"not reached by {entry.name!r} in {lo:g}-{hi:g} K; give the lubricant temperature")
        t = brentq(f, lo, hi, xtol=1e-6)
        how = (f"{entry.name} at {t:.2f} K, where its viscosity equals the {fixed.viscosity:g} Pa s of "
               f"{fixed.name!r} the films use (no temperature given)")
    return float(properties_at(entry, t)["kinematic_viscosity"]), float(t), how


def speed_factor(bearing, omega, omega_outer=0.0):
    """n d_m [mm/min]: the relative speed of the rings [r/min] times the pitch diameter [mm]."""
    return abs(float(omega) - float(omega_outer)) * 30.0 / math.pi * _mm(bearing.pitch_diameter)


def check_speed_limit(bearing, omega, omega_outer=0.0, warn=True):
    """The limits of :data:`SPEED_LIMITS` that n d_m (:func:`speed_factor`) exceeds, as messages (a
    :class:`SpeedLimitWarning` each when ``warn``). The model itself has no such limit: the check says where
    the bearing's lubrication and cage leave ordinary practice."""
    ndm = speed_factor(bearing, omega, omega_outer)
    msgs = []
    for limit, what in SPEED_LIMITS:
        if ndm > limit:
            msgs.append(f"speed: n d_m = {ndm:.3g} mm/min ({abs(omega - omega_outer) * 30 / math.pi:.0f} r/min on "
                        f"d_m = {_mm(bearing.pitch_diameter):.1f} mm) exceeds {limit:.2g} mm/min, {what}")
    msgs = msgs[-1:]  # the highest limit exceeded says the most
    if warn:
        for m in msgs:
            warnings.warn(SpeedLimitWarning(m), stacklevel=2)
    return msgs


@dataclass
class RatingLife:
    """Load ratings, static safety and rating lives of a ball bearing at one operating point (SI, lives in
    10^6 revolutions and h); :meth:`to_dict` with :data:`RATING_UNITS`. None where the input does not give a
    value (no speed: no hours and no kappa)."""

    C: float | None
    C0: float | None
    C0_iso76: float | None
    C0_hertz: float | None
    C0_method: str | None
    C_method: str | None
    f_c: float | None
    f_0: float | None
    C_u: float | None
    Fr_bearing: float | None
    Fa_bearing: float | None
    P: float | None
    X: float | None
    Y: float | None
    e: float | None
    P0: float | None
    s0: float | None
    s0_pressure: float | None
    p_max: float | None
    L10: float | None
    L10h: float | None
    reliability: float
    a1: float
    contamination: str
    e_C: float
    n: float | None
    n_dm: float | None
    temperature: float | None
    nu: float | None
    nu1: float | None
    kappa: float | None
    a_iso: float | None
    L10m: float | None
    L10mh: float | None
    L10r: float | None = None
    L10mr: float | None = None
    L10mrh: float | None = None
    P_ref: float | None = None
    a_iso_r: float | None = None
    L10r_speed: float | None = None
    L10mr_speed: float | None = None
    rotating_ring: str = "inner"
    viscosity_source: str = ""
    rating_warnings: list = field(default_factory=list)

    def to_dict(self) -> dict:
        """The fields as a dict (keys of :data:`RATING_UNITS` and the methods, notes and inputs)."""
        return asdict(self)

    def summary(self) -> list:
        """Lines for the command line."""
        def f(v, fmt=".4g"):
            return "n/a" if v is None else format(v, fmt)
        if self.C is None:
            return ["load ratings and rating lives: not computed"] + [f"warning: {w}" for w in self.rating_warnings]
        lines = [f"load ratings: C = {self.C / 1e3:.2f} kN ({self.C_method}), C0 = {self.C0 / 1e3:.2f} kN "
                 f"({self.C0_method}); ISO 76 table {self.C0_iso76 / 1e3:.2f} kN, 4.2 GPa with the bearing's "
                 f"grooves {self.C0_hertz / 1e3:.2f} kN; C_u = {self.C_u / 1e3:.3g} kN (C0/27, ISO 281 B.3.2.2)",
                 f"static: P0 = {self.P0:.4g} N, s0 = C0/P0 = {self.s0:.3g}; project's check (4.2 GPa / p_max)^3 = "
                 f"{f(self.s0_pressure, '.3g')} (p_max {f(None if self.p_max is None else self.p_max / 1e9, '.3f')}"
                 " GPa of the computed distribution)",
                 f"ISO 281: P = {self.P:.4g} N (X {self.X:.3g}, Y {self.Y:.3g}, e {self.e:.3g}), L10 = {f(self.L10)}"
                 f" 10^6 rev, L10h = {f(self.L10h)} h at {f(self.n, '.0f')} r/min; reliability {self.reliability:g} %"
                 f" (a1 {self.a1:.3g}), {self.contamination} (e_C {self.e_C:.3g}), kappa = {f(self.kappa, '.3g')}"
                 f" (nu {f(None if self.nu is None else self.nu * 1e6, '.3g')} mm^2/s at "
                 f"{f(self.temperature, '.1f')} K, nu1 {f(None if self.nu1 is None else self.nu1 * 1e6, '.3g')} "
                 f"mm^2/s), a_ISO = {f(self.a_iso, '.3g')}, L10m = {f(self.L10m)} 10^6 rev ({f(self.L10mh)} h)"]
        if self.L10r is not None:
            lines.append(f"ISO/TS 16281 (computed load distribution, {self.rotating_ring} ring rotating): L10r = "
                         f"{f(self.L10r)}, L10mr = {f(self.L10mr)} 10^6 rev ({f(self.L10mrh)} h, a_ISO "
                         f"{f(self.a_iso_r, '.3g')} at P_ref {f(self.P_ref)} N)"
                         + (f"; with speed effects (centrifugal loads, contact angles at speed; not in the "
                            f"standard): L10r_speed = {f(self.L10r_speed)}, L10mr_speed = {f(self.L10mr_speed)}"
                            if self.L10r_speed is not None else ""))
        lines += [f"warning: {w}" for w in self.rating_warnings]
        return lines


def _distribution(solution):
    bl = solution.balls
    return (np.asarray(bl["q_inner"], float), np.asarray(bl["alpha_inner"], float),
            np.asarray(bl["q_outer"], float), np.asarray(bl["alpha_outer"], float))


def _carried_loads(solution):
    """(F_r, F_a) the bearing carries: the applied loads plus the reactions of held translational DOFs."""
    lo = np.asarray(solution.loads, float)
    r = getattr(solution, "reactions", {}) or {}
    fx = lo[0] + r.get("delta_x", 0.0)
    fy = lo[1] + r.get("delta_y", 0.0)
    fa = lo[2] + r.get("delta_a", 0.0)
    return math.hypot(fx, fy), abs(fa)


def rating_life(bearing, loads, omega=None, *, omega_outer=0.0, reliability=DEFAULT_RELIABILITY,
                contamination=DEFAULT_CONTAMINATION, temperature=None, lubricant=None, viscosity=None,
                reference=None, warn=True) -> RatingLife:
    """Load ratings, static safety, ISO 281 basic and modified rating life and, from a load distribution, the
    ISO/TS 16281 modified reference rating life of ``bearing`` (docs/theory/rating_life.md).

    Parameters
    ----------
    bearing : BallBearing or str
    loads : (F_r, F_a) [N] or a quasi-static solution
        A :class:`~exudyn_bearing.solvers.quasistatic.QuasiStaticSolution` gives the loads the bearing carries
        (applied plus held DOFs' reactions) and its load distribution: at zero speed it is the ISO/TS 16281
        distribution (``L10r``, ``L10mr``); at speed it gives the labelled variant with speed effects
        (``L10r_speed``, ``L10mr_speed``) and ``reference`` (the zero-speed solution of the same loads) the
        standard's.
    omega : float, optional
        Inner-ring speed [rad/s] for hours and kappa (default: the solution's); ``omega_outer`` the outer ring's.
    reliability : float
        Per cent, 90 to 99.95 (default 90: a_1 = 1).
    contamination : str or float
        ISO 281 Table 13 class (``exudyn_bearing.data.iso281.CONTAMINATION``; default normal-cleanliness) or e_C.
    temperature, lubricant, viscosity
        Lubricant temperature [K] and lubricant for kappa (:func:`lubricant_viscosity`), or the kinematic
        viscosity [m^2/s] itself.
    warn : bool
        Emit :class:`RatingLifeWarning` for each scope note (also in ``.warnings``).
    """
    if isinstance(bearing, str):
        from ..data.catalog import load_bearing
        bearing = load_bearing(bearing)
    b = bearing
    notes = []
    solution = None if isinstance(loads, (tuple, list)) else loads
    if solution is None:
        fr, fa = (check_nonnegative(n, abs(check_finite(n, v))) for n, v in zip(("Fr", "Fa"), loads))
    else:
        fr, fa = _carried_loads(solution)
        omega = solution.omega if omega is None else omega
        omega_outer = solution.omega_outer
    a0 = b.free_contact_angle
    a1 = reliability_factor(reliability)
    ec = contamination_factor(contamination, b.pitch_diameter)
    cname = contamination if isinstance(contamination, str) else "e_C given"
    n = None if omega is None else abs(float(omega) - float(omega_outer)) * 30.0 / math.pi
    n = n or None
    try:
        c, fc, c_method = dynamic_load_rating(b.n_balls, b.ball_diameter, b.pitch_diameter, a0,
                                              b.inner_conformity, b.outer_conformity)
        c0_iso, f0 = static_load_rating(b.n_balls, b.ball_diameter, b.pitch_diameter, a0)
        c0_h = static_load_rating_hertz(b)
        fi0, fe0 = T.STANDARD_CONFORMITY
        if b.inner_conformity <= fi0 + 1e-9 and b.outer_conformity <= fe0 + 1e-9:
            c0, c0_method = c0_iso, "ISO 76 Table 1"
        else:
            c0, c0_method = c0_h, ("4.2 GPa with the bearing's grooves (ISO 76's criterion; its table assumes "
                                   "grooves within 0.52 / 0.53)")
        p, x, y, e = equivalent_dynamic_load(fr, fa, a0, c0, f0)
    except RatingScopeError as exc:
        notes.append(f"no load rating or rating life: the bearing lies outside ISO 281 / ISO 76 ({exc})")
        none = {f.name: None for f in fields(RatingLife) if f.default is MISSING and f.default_factory is MISSING}
        r = RatingLife(**{**none, "Fr_bearing": fr, "Fa_bearing": fa, "reliability": float(reliability), "a1": a1,
                          "contamination": cname, "e_C": ec, "n": n,
                          "n_dm": None if n is None else n * _mm(b.pitch_diameter)})
        r.rating_warnings = notes
        if warn:
            for m in notes:
                warnings.warn(RatingLifeWarning(m), stacklevel=2)
        return r
    p0 = equivalent_static_load(fr, fa, a0)
    s0 = c0 / p0 if p0 > 0 else math.inf
    l10 = basic_rating_life(c, p)
    cu = fatigue_load_limit(c0, b.pitch_diameter)
    rotating = "inner" if omega is None or abs(omega) >= abs(omega_outer) else "outer"
    nu = nu1 = kappa = t = None
    source = ""
    if n is not None:
        nu1 = rated_viscosity(n, b.pitch_diameter)
        if viscosity is not None:
            nu, source = check_positive("viscosity", viscosity), "given"
            t = None if temperature is None else float(temperature)
        else:
            try:
                nu, t, source = lubricant_viscosity(b, temperature, lubricant)
            except InputError as exc:
                if temperature is not None:
                    raise
                notes.append(f"kappa and the modified lives not computed: {exc}")
        kappa = None if nu is None else nu / nu1
        if kappa is None:
            pass
        elif kappa < KAPPA_RANGE[0]:
            notes.append(f"kappa = {kappa:.3g} is below ISO 281's range (0.1): a_ISO is extrapolated")
        if t is not None and t > MAX_TEMPERATURE_ISO281:
            notes.append(f"temperature {t:.0f} K is above ISO 281's 150 C (423 K) for standard bearing steel: "
                         "the ratings need a temperature reduction the standard does not give")

    def a_iso_of(load):
        if kappa is None or load <= 0.0:
            return None
        return life_modification_factor(kappa, ec * cu / load)

    a_iso = a_iso_of(p)
    l10m = None if a_iso is None else a1 * a_iso * l10
    if b.material.name not in ("steel",):
        notes.append(f"material {b.material.name!r}: ISO 281's b_m, C_u and a_ISO are for through-hardened "
                     "bearing steel (AISI 52100 class); for other steels the manufacturer's life factors apply")
    r = RatingLife(C=c, C0=c0, C0_iso76=c0_iso, C0_hertz=c0_h, C0_method=c0_method, C_method=c_method, f_c=fc,
                   f_0=f0, C_u=cu, Fr_bearing=fr, Fa_bearing=fa, P=p, X=x, Y=y, e=e, P0=p0, s0=s0, s0_pressure=None, p_max=None,
                   L10=l10, L10h=life_hours(l10, n), reliability=float(reliability), a1=a1, contamination=cname,
                   e_C=ec, n=n, n_dm=None if n is None else n * _mm(b.pitch_diameter), temperature=t, nu=nu,
                   nu1=nu1, kappa=kappa, a_iso=a_iso, L10m=l10m, L10mh=life_hours(l10m, n), rotating_ring=rotating,
                   viscosity_source=source)
    if solution is not None:
        bl = solution.balls
        pmax = max(float(np.max(bl["p_max_inner"], initial=0.0)), float(np.max(bl["p_max_outer"], initial=0.0)))
        r.p_max = pmax
        r.s0_pressure = (MAX_CONTACT_PRESSURE_C0 / pmax) ** 3 if pmax > 0 else math.inf
        at_speed = bool(solution.omega or solution.omega_outer)
        ref = reference if at_speed else solution
        if at_speed:
            ls = reference_rating_life(b, c, *_distribution(solution), rotating=rotating)[0]
            r.L10r_speed = ls
            fc_max = float(np.max(bl.get("centrifugal_force", [0.0]), initial=0.0))
            qmax = float(np.max(bl["q_inner"], initial=0.0))
            if qmax > 0 and fc_max > CENTRIFUGAL_DOMINANCE * qmax or qmax == 0.0 and fc_max > 0.0:
                notes.append(f"centrifugal force {fc_max:.4g} N per ball against {qmax:.4g} N of the most loaded inner "
                             "contact: ball inertia shapes the load distribution, outside ISO 281's assumptions; "
                             "L10r_speed / L10mr_speed include it")
        if ref is not None:
            lr = reference_rating_life(b, c, *_distribution(ref), rotating=rotating)[0]
            r.L10r = lr
            r.P_ref = c * lr ** (-1.0 / 3.0) if math.isfinite(lr) and lr > 0 else 0.0
            r.a_iso_r = a_iso_of(r.P_ref)
            if r.a_iso_r is not None:
                r.L10mr = a1 * r.a_iso_r * lr
                r.L10mrh = life_hours(r.L10mr, n)
        if r.L10r_speed is not None and r.a_iso_r is not None:
            p_s = c * r.L10r_speed ** (-1.0 / 3.0) if r.L10r_speed > 0 and math.isfinite(r.L10r_speed) else 0.0
            a_s = a_iso_of(p_s)
            r.L10mr_speed = None if a_s is None else a1 * a_s * r.L10r_speed
    r.rating_warnings = notes
    if warn:
        for m in notes:
            warnings.warn(RatingLifeWarning(m), stacklevel=2)
    return r
