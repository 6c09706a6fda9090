"""3-DOF vibration model of a ball bearing: outer ring, one ball, inner ring.

El Had et al. [1]_ reduce a bearing to three masses on one radial line:
the outer ring M1 and the inner ring M3, each on a spring k1, k3 to ground
that stands for the ring's first bending mode (:mod:`exudyn_bearing.physics.
ring_vibration`), and between them the ball M2, tied to the outer race by
k22, C22 and to the inner race by k21, C21. Coordinates y = (y1, y2, y3),
radial displacements along the line of the most loaded ball::

    M = diag(M1, M2, M3)
    K = [[k1 + k22, -k22,       0       ],
         [-k22,      k22 + k21, -k21     ],
         [0,         -k21,      k3 + k21 ]]
    C = the same pattern with C22, C21 (and optional ring dampers c1, c3)

The eigen-analysis is that of the 6-state first-order system
(:mod:`.linear`), solved with ``scipy.linalg.eig``.

Two parameter sets
------------------
:func:`source_parameters`: the source's printed values. The source is not
self-consistent; each inconsistency is a reading chosen by name, and every
run states its readings (``ThreeDofParameters.reading``):

* ``inner_ring``: ``"printed_matrix"`` (default) takes k3 = 1e8 N/m, the
  value in the source's numeric stiffness matrix (its A^-1 C entry
  435e7 = 43.5 x 1e8); ``"parameter_list"`` takes k3 = 1e7 N/m of its list.
* ``outer_link``: ``"printed_matrix"`` (default): the numeric damping and
  stiffness matrices couple the ball only to the inner ring (no C22, no
  k22); ``"eq7"``: the outer link of eq. 7, k22 = 0.9925 N/m, C22 = 9.9072
  N s/m (the list's k23, C23).
* ``damping_row``: ``"symmetric"`` (default) is the matrix form, ball row
  (-C22, C22 + C21, -C21); ``"eq7_literal"`` reads eq. 7's second line as
  printed, -C22 y2' + (C22 + C21) y2' - C21 y3', which counts C22 twice on
  y2' and drops the coupling to y1': ball row (0, C21, -C21), a
  non-symmetric damping matrix. It matters only with the outer link.

The ball links are the list's k21 = 0.9925 N/m and C21 = 9.9072 N s/m (its
matrices print them rounded to 0.99 and 9.9); masses 25 g, 2 g, 23 g.
:func:`source_printed_system` returns the matrices exactly as printed, and
:func:`source_state_matrix` the source's state matrix with its sign error,
for the comparison of its eigenvalues only.

:func:`derived_parameters`: every value from the bearing and an operating
point. Rings: rectangular sections between race bottom and bore or outside
diameter over the ring width (:func:`ring_dimensions`: the bearing's data,
the catalogue's published dimensions, or an estimate from the ball and
pitch diameters), stiffness k = M omega_2^2 with M = 2 pi R mu, the whole ring
(:func:`~exudyn_bearing.physics.ring_vibration.ring_flexural_frequency`).
Ball: mass 4/3 pi R_b^3 rho. Ball-race links: the Hertz tangent stiffness
dQ/d delta at the load Q of the most loaded ball (discrete quasi-static
solution, centrifugal force added on the outer race), in series with the
film stiffness of the short-bearing expressions (source eq. 5, corrected
prefactor) at eps_0 = 1 - h_min/c, h_min the Hamrock-Dowson film thickness
and c = P_d/2 the radial clearance; damping the film damping of eq. 6,
normalised with the shaft speed. ``link="hertz"`` or ``"film"`` keeps one
spring only.

References
----------
.. [1] K. El Had, A. Hachim, A. Chouairi, M. El Ghorba, "Improved analytical
   approach of vibration behavior destined to ball bearings in the case of
   angular contact," Rev. Energy Technol. Policy Res. 1(2) (2014) 56-68.
   doi:10.18488/journal.77/2014.1.2/77.2.56.68
.. [2] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed.,
   CRC Press, 2006 (Hertz load-deflection, load distribution, kinematics).
.. [3] B. J. Hamrock and D. Dowson, J. Lubr. Technol. 99(2) (1977) 264-275.
   doi:10.1115/1.3453074
.. [4] SKF, Rolling bearings (general catalogue), 2018: 6004 dimensions
   20 x 42 x 12 mm; radial internal clearance of deep groove ball bearings,
   Normal group for bores over 18 up to 24 mm: 5-20 um.
.. [5] P. D. McFadden and J. D. Smith, "Model for the vibration produced by
   a single point defect in a rolling element bearing," J. Sound Vib. 96(1)
   (1984) 69-82. doi:10.1016/0022-460X(84)90595-9
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field

import numpy as np

from ...data import BallBearing, InputError, Lubricant, default_lubricant, load_bearing
from ...physics import damping, ehl, hertz, kinematics
from ...physics.geometry import raceway_radii
from ...model.load_range import check_load_range
from ...physics.load_distribution import race_stiffness
from ...physics.ring_vibration import (rectangular_ring_section, ring_flexural_frequency,
                                       ring_modal_stiffness)
from ...physics.short_bearing import film_coefficients, film_eccentricity
from . import linear

__all__ = ["ThreeDofParameters", "ThreeDofResult", "READINGS", "DOFS", "SKF_6004", "RingDimensions",
           "CATALOGUE_DIMENSIONS", "BALL_TO_SECTION", "ring_dimensions",
           "source_parameters", "derived_parameters", "source_printed_system", "source_state_matrix",
           "SOURCE_EIGENVALUES", "assemble", "analyse", "frequency_response", "ball_pass_force",
           "ball_pass_response", "bpfo"]

#: Coordinates of the model, in order.
DOFS = ("outer_ring", "ball", "inner_ring")

#: Readings of the source's inconsistencies: name -> allowed values (default first).
READINGS = {
    "inner_ring": ("printed_matrix", "parameter_list"),
    "outer_link": ("printed_matrix", "eq7"),
    "damping_row": ("symmetric", "eq7_literal"),
}

#: Eigenvalues printed by El Had et al. [1/s] (V1 ... V6), those of their
#: printed state matrix, which has the sign error (:func:`source_printed_system`).
SOURCE_EIGENVALUES = (2.0e4, -2.0e4, -6.5763e4, 6.6178e4, 4.948e3, -0.1)

_SOURCE = dict(mass_outer=25e-3, mass_ball=2e-3, mass_inner=23e-3, k_outer_ring=1e7,
               k_inner_ring_list=1e7, k_inner_ring_matrix=1e8, k_contact=0.9925, c_contact=9.9072)


@dataclass(frozen=True)
class RingDimensions:
    """Boundary dimensions of a bearing for the ring sections [m]: bore d,
    outside diameter D, width B (axial)."""

    bore: float
    outer_diameter: float
    width: float

    def __post_init__(self):
        for name in ("bore", "outer_diameter", "width"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0.0):
                raise InputError(f"{name}: must be finite and > 0 [m], got {v!r}")
        if self.outer_diameter <= self.bore:
            raise InputError(f"outer_diameter: must exceed the bore ({self.bore}), got {self.outer_diameter}")


#: SKF 6004: 20 x 42 x 12 mm [4]_.
SKF_6004 = RingDimensions(bore=20e-3, outer_diameter=42e-3, width=12e-3)

#: Published boundary dimensions (bore x outside diameter x width) of the
#: catalogue's bearings by name: SKF 6004 20 x 42 x 12 mm, 6205 25 x 52 x
#: 15 mm, 6208 and 7208 40 x 80 x 18 mm (SKF [4]_; ISO 15 dimension series
#: 02 for the 62xx and 72xx, 10 for the 60xx).
CATALOGUE_DIMENSIONS = {
    "6004": SKF_6004,
    "6205": RingDimensions(bore=25e-3, outer_diameter=52e-3, width=15e-3),
    "6208": RingDimensions(bore=40e-3, outer_diameter=80e-3, width=18e-3),
    "7208": RingDimensions(bore=40e-3, outer_diameter=80e-3, width=18e-3),
}
#: Estimate of the section where no dimension is known: ball diameter D_w =
#: BALL_TO_SECTION (D - d) and width B = (D - d) / 2, centred on the pitch
#: diameter (D + d = 2 d_m). The proportions of the published bearings: D_w / (D - d) =
#: 0.289 (6004), 0.294 (6205), 0.315 (6208), 0.295 (ACBB-120, Gupta 2020: 120 x
#: 190 mm); B / ((D - d) / 2) = 1.09, 1.11, 0.90.
BALL_TO_SECTION = 0.3


def ring_dimensions(bearing) -> tuple[RingDimensions, dict]:
    """Bore, outside diameter and width of a bearing's rings, and where each
    comes from: the bearing's own ``bore`` / ``outer_diameter`` (data file),
    else :data:`CATALOGUE_DIMENSIONS` by name, else the estimate of
    :data:`BALL_TO_SECTION` from the ball and pitch diameters (module
    docstring).

    Examples
    --------
    >>> d, src = ring_dimensions("6208")
    >>> round(d.outer_diameter * 1e3), src["outer_diameter"]
    (80, 'catalogue (SKF): 6208')
    """
    b = bearing if isinstance(bearing, BallBearing) else load_bearing(bearing)
    table = CATALOGUE_DIMENSIONS.get(b.name)
    section = 2.0 * b.ball_radius / BALL_TO_SECTION  # D - d
    estimate = {"bore": 2.0 * b.pitch_radius - 0.5 * section, "outer_diameter": 2.0 * b.pitch_radius + 0.5 * section,
                "width": 0.5 * section}
    values, source = {}, {}
    for key in ("bore", "outer_diameter", "width"):
        own = getattr(b, key, None)
        if own is not None:
            values[key], source[key] = float(own), f"bearing data: {b.name}"
        elif table is not None:
            values[key], source[key] = getattr(table, key), f"catalogue (SKF): {b.name}"
        else:
            values[key] = estimate[key]
            source[key] = (f"estimate: D_w = {BALL_TO_SECTION:g} (D - d), B = (D - d)/2 about the pitch diameter")
    return RingDimensions(**values), source


@dataclass(frozen=True)
class ThreeDofParameters:
    """Masses, springs and dampers of the 3-DOF model (module docstring).

    Parameters
    ----------
    mass_outer, mass_ball, mass_inner : float
        M1, M2, M3 [kg] (> 0).
    k_outer_ring, k_inner_ring : float
        k1, k3 [N/m], rings to ground (>= 0).
    k_outer_contact, k_inner_contact : float
        k22 (ball - outer race), k21 (ball - inner race) [N/m] (>= 0).
    c_outer_contact, c_inner_contact : float
        C22, C21 [N s/m] (>= 0).
    c_outer_ring, c_inner_ring : float
        Ring dampers to ground [N s/m] (>= 0; 0 in the source).
    damping_row : {"symmetric", "eq7_literal"}
        Ball row of the damping matrix (module docstring).
    label : str
        Name of the set.
    reading : dict
        The readings and choices behind the values (for the record).
    derivation : dict
        Intermediate values of a derived set (loads, films, frequencies).
    """

    mass_outer: float
    mass_ball: float
    mass_inner: float
    k_outer_ring: float
    k_inner_ring: float
    k_outer_contact: float
    k_inner_contact: float
    c_outer_contact: float
    c_inner_contact: float
    c_outer_ring: float = 0.0
    c_inner_ring: float = 0.0
    damping_row: str = "symmetric"
    label: str = "custom"
    reading: dict = field(default_factory=dict, compare=False)
    derivation: dict = field(default_factory=dict, compare=False)

    def __post_init__(self):
        for name in ("mass_outer", "mass_ball", "mass_inner"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0.0):
                raise InputError(f"{name}: must be finite and > 0 [kg], got {v!r}")
        for name in ("k_outer_ring", "k_inner_ring", "k_outer_contact", "k_inner_contact",
                     "c_outer_contact", "c_inner_contact", "c_outer_ring", "c_inner_ring"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v >= 0.0):
                raise InputError(f"{name}: must be finite and >= 0, got {v!r}")
        if self.damping_row not in READINGS["damping_row"]:
            raise InputError(f"damping_row: expected one of {', '.join(READINGS['damping_row'])}, "
                             f"got {self.damping_row!r}")
        if self.k_outer_contact == 0.0 and self.k_inner_contact == 0.0:
            raise InputError("k_inner_contact: the ball needs a spring to at least one race "
                             "(both contact stiffnesses are 0)")
        if self.k_outer_ring == 0.0 and self.k_inner_ring == 0.0:
            raise InputError("k_outer_ring: at least one ring must be tied to ground")
        if (self.k_outer_ring == 0.0 and self.k_outer_contact == 0.0) or (
                self.k_inner_ring == 0.0 and self.k_inner_contact == 0.0):
            raise InputError("k_outer_ring: a ring with neither a ground spring nor a contact spring is free")

    def to_dict(self) -> dict:
        return asdict(self)


def source_parameters(inner_ring="printed_matrix", outer_link="printed_matrix",
                      damping_row="symmetric") -> ThreeDofParameters:
    """The source's printed values under the named readings (module docstring).

    Examples
    --------
    >>> p = source_parameters()
    >>> p.k_inner_ring, p.k_outer_contact, p.c_inner_contact
    (100000000.0, 0.0, 9.9072)
    """
    for name, value in (("inner_ring", inner_ring), ("outer_link", outer_link), ("damping_row", damping_row)):
        if value not in READINGS[name]:
            raise InputError(f"{name}: expected one of {', '.join(READINGS[name])}, got {value!r}")
    s = _SOURCE
    k3 = s["k_inner_ring_matrix"] if inner_ring == "printed_matrix" else s["k_inner_ring_list"]
    outer = outer_link == "eq7"
    return ThreeDofParameters(
        mass_outer=s["mass_outer"], mass_ball=s["mass_ball"], mass_inner=s["mass_inner"],
        k_outer_ring=s["k_outer_ring"], k_inner_ring=k3,
        k_outer_contact=s["k_contact"] if outer else 0.0, k_inner_contact=s["k_contact"],
        c_outer_contact=s["c_contact"] if outer else 0.0, c_inner_contact=s["c_contact"],
        damping_row=damping_row, label="El Had et al. 2014, printed values",
        reading={"inner_ring": inner_ring, "outer_link": outer_link, "damping_row": damping_row})


def source_printed_system():
    """The source's matrices exactly as printed: mass A, damping B, stiffness
    C, its inverse mass matrix (rounded to 40, 500, 43.5 1/kg) and its state
    matrix L.

    L is [[0, I], [A^-1 C, A^-1 B]] (:func:`source_state_matrix`, with the
    sign error) of the printed matrices except two entries: A^-1 B prints
    413.25 where 43.5 x 9.9 = 430.65. The source's eigenvalues
    (:data:`SOURCE_EIGENVALUES`) are those of this L.

    Returns
    -------
    dict with ``mass``, ``damping``, ``stiffness``, ``mass_inverse`` (3x3),
    ``state_matrix`` (6x6).
    """
    state = np.zeros((6, 6))
    state[:3, 3:] = np.eye(3)
    state[3:, :3] = [[40e7, 0.0, 0.0], [0.0, 495.0, -495.0], [0.0, -43.0, 435e7]]
    state[3:, 3:] = [[0.0, 0.0, 0.0], [0.0, 4950.0, -4950.0], [0.0, -413.25, 413.25]]
    return {
        "mass": np.diag([25e-3, 2e-3, 23e-3]),
        "damping": np.array([[0.0, 0.0, 0.0], [0.0, 9.9, -9.9], [0.0, -9.9, 9.9]]),
        "stiffness": np.array([[1e7, 0.0, 0.0], [0.0, 0.99, -0.99], [0.0, -0.99, 1e8]]),
        "mass_inverse": np.diag([40.0, 500.0, 43.5]),
        "state_matrix": state,
    }


def source_state_matrix(mass_inverse, damping, stiffness):
    """The source's state matrix V = [[0, I], [A^-1 C, A^-1 B]] (A mass, B
    damping, C stiffness in its notation): the correct one has minus signs on
    both lower blocks. Kept for the comparison with its eigenvalues only.

    With +A^-1 C a spring k on a mass M gives lambda^2 = +k/M, two real
    roots +-sqrt(k/M), where the correct -k/M gives +-i sqrt(k/M).
    """
    mi = np.asarray(mass_inverse, float)
    n = mi.shape[0]
    v = np.zeros((2 * n, 2 * n))
    v[:n, n:] = np.eye(n)
    v[n:, :n] = mi @ np.asarray(stiffness, float)
    v[n:, n:] = mi @ np.asarray(damping, float)
    return v


def _ring_section(radius_a, radius_b, width, material):
    """Mass, radius, I, mu and bending frequency of a ring between two radii."""
    r_in, r_out = min(radius_a, radius_b), max(radius_a, radius_b)
    thickness = r_out - r_in
    area, second_moment = rectangular_ring_section(width, thickness)
    mu = material.density * float(area)
    radius = 0.5 * (r_in + r_out)
    omega = float(ring_flexural_frequency(material.youngs_modulus, second_moment, mu, radius, 2))
    mass = 2.0 * math.pi * radius * mu
    return {"thickness": thickness, "radius": radius, "second_moment": float(second_moment),
            "mass_per_length": mu, "mass": mass, "omega_2": omega, "f_2_hz": omega / (2.0 * math.pi),
            "stiffness": float(ring_modal_stiffness(mass, omega))}


def derived_parameters(bearing="6004", radial_load=500.0, omega=2.0 * math.pi * 50.0,
                       diametral_clearance=12.5e-6, lubricant: Lubricant | None = None,
                       dimensions: RingDimensions | None = None, link="series", film_damping="short_bearing",
                       hertz_method="exact", film="hd", axial_load=0.0) -> ThreeDofParameters:
    """Physically derived 3-DOF parameters at an operating point (module
    docstring).

    Parameters
    ----------
    bearing : str, path or BallBearing
        Default the catalogue's 6004 (the source's SKF 6004).
    radial_load : float
        F_r on the inner ring [N] (> 0). Default 500 N, a tenth of the
        6004's static load rating C0 = 5 kN (SKF [4]_); the source gives none.
    omega : float
        Inner-ring speed [rad/s] (> 0), outer ring fixed. Default 50 Hz
        (3000 rpm); the source gives none.
    diametral_clearance : float
        P_d [m] (> 0: the film model needs a clearance). Default 12.5 um,
        the middle of SKF's Normal clearance group for the 6004 (5-20 um [4]_).
    lubricant : Lubricant
        Default the catalogue's lubricant (eta = 0.04 Pa s).
    dimensions : RingDimensions, optional
        Bore, outside diameter and width of the rings; default those of the
        bearing (:func:`ring_dimensions`: its data, the catalogue, or an
        estimate; the source of each is in ``derivation``).
    link : {"series", "hertz", "film"}
        Ball-race spring: Hertz and film in series (default), or one of them.
    film_damping : {"short_bearing", "contact_model"}
        Ball-race damper: the source's short-bearing film damping (eq. 6,
        default), or the normal damping of this package's contact model
        (Hunt-Crossley hysteretic and EHL squeeze-film damping switched by
        the film parameter Lambda, :func:`~exudyn_bearing.physics.damping.
        damping_coefficient`), for comparison.
    hertz_method, film : str
        Hertz fidelity level and film-thickness model ("hd" or "mk").
    axial_load : float
        F_a [N] (>= 0); an angular-contact bearing needs one that holds the
        radial load. The contact springs and dampers act along the contact
        normal at the angle alpha of the most loaded ball; the model's
        radial line sees them times cos^2 alpha.

    Returns
    -------
    ThreeDofParameters with every intermediate value in ``derivation``.
    """
    b = bearing if isinstance(bearing, BallBearing) else load_bearing(bearing)
    if link not in ("series", "hertz", "film"):
        raise InputError(f"link: expected series, hertz or film, got {link!r}")
    if film_damping not in ("short_bearing", "contact_model"):
        raise InputError(f"film_damping: expected short_bearing or contact_model, got {film_damping!r}")
    fr = float(radial_load)
    if not (math.isfinite(fr) and fr > 0.0):
        raise InputError(f"radial_load: must be finite and > 0 [N], got {radial_load!r}")
    w = float(omega)
    if not (math.isfinite(w) and w > 0.0):
        raise InputError(f"omega: must be finite and > 0 [rad/s] (the film needs rolling), got {omega!r}")
    pd = float(diametral_clearance)
    if not (math.isfinite(pd) and pd > 0.0):
        raise InputError(f"diametral_clearance: must be finite and > 0 [m] (the film model needs a "
                         f"clearance), got {diametral_clearance!r}")
    fa = float(axial_load)
    if not (math.isfinite(fa) and fa >= 0.0):
        raise InputError(f"axial_load: must be finite and >= 0 [N], got {axial_load!r}")
    if dimensions is None:
        dimensions, dim_source = ring_dimensions(b)
    elif isinstance(dimensions, RingDimensions):
        dim_source = dict.fromkeys(("bore", "outer_diameter", "width"), "given")
    else:
        raise InputError(f"dimensions: expected a RingDimensions, got {type(dimensions).__name__}")
    b = b.with_clearance(pd)
    lub = default_lubricant(b) if lubricant is None else lubricant
    if 0.5 * dimensions.bore >= b.inner_race_radius:
        raise InputError(f"bore: {dimensions.bore * 1e3:.4g} mm ({dim_source['bore']}) is not smaller than the inner "
                         f"race diameter of {b.name}, {2e3 * b.inner_race_radius:.4g} mm: give the bore of this "
                         "bearing")
    if 0.5 * dimensions.outer_diameter <= b.outer_race_radius:
        raise InputError(f"outer_diameter: {dimensions.outer_diameter * 1e3:.4g} mm ({dim_source['outer_diameter']}) "
                         f"is not larger than the outer race diameter of {b.name}, {2e3 * b.outer_race_radius:.4g} "
                         "mm: give the outside diameter of this bearing")
    mat = b.material
    outer = _ring_section(b.outer_race_radius, 0.5 * dimensions.outer_diameter, dimensions.width, mat)
    inner = _ring_section(0.5 * dimensions.bore, b.inner_race_radius, dimensions.width, mat)

    # load of the most loaded ball (discrete quasi-static solution, within the elastic contact model's range)
    sol = check_load_range(b, fr, fa, hertz_method, names=("radial_load", "axial_load", "diametral_clearance"))
    j = int(np.argmax(sol.q))
    q = float(sol.q[j])
    alpha = float(sol.contact_angle[j])
    wc = float(kinematics.cage_speed(w, 0.0, b.ball_radius, b.pitch_radius, alpha))
    f_c = float(kinematics.centrifugal_force(b.ball_mass, b.pitch_radius, wc))
    loads = {"inner": q, "outer": q + f_c}
    k_i, k_o, _ = race_stiffness(b, alpha, hertz_method)
    e_prime = hertz.material_reduced_modulus(mat)
    u_i, u_o = kinematics.rolling_speeds(w, 0.0, b.ball_radius, b.pitch_radius, alpha)
    ca = math.cos(alpha)
    contacts = {}
    c_radial = 0.5 * pd
    for race, kh, u, r_c, groove, is_inner in (
            ("inner", k_i, u_i, b.pitch_radius - b.ball_radius * ca, b.inner_groove_radius, True),
            ("outer", k_o, u_o, b.pitch_radius + b.ball_radius * ca, b.outer_groove_radius, False)):
        load = loads[race]
        rx, ry = raceway_radii(b.ball_radius, groove, r_c, alpha, is_inner)
        kappa = float(hertz.ellipticity(rx, ry, hertz_method)[0])
        h = float(ehl.film_thickness(u, load, rx, kappa, e_prime, lub.viscosity, lub.pressure_viscosity, film))
        eps = float(film_eccentricity(h, c_radial))
        k_film, c_film = (float(x) for x in film_coefficients(eps, load, c_radial, w))
        k_hertz = float(hertz.tangent_stiffness(kh, load))
        k_link = {"series": 1.0 / (1.0 / k_hertz + 1.0 / k_film), "hertz": k_hertz, "film": k_film}[link] * ca * ca
        # the contact model's normal damping at this load and film, for comparison
        overlap = (load / kh) ** (2.0 / 3.0)
        semi_major = float(hertz.contact_ellipse(rx, ry, e_prime, load, hertz_method)[0])
        c_hyst = float(damping.damping_hysteretic(kh, overlap, mat.hysteretic_damping))
        c_fluid = float(damping.damping_fluid(lub.viscosity, semi_major, b.ball_radius, h))
        lam = float(ehl.film_parameter(h, lub.composite_roughness))
        c_contact = float(damping.damping_coefficient(lam, c_hyst, c_fluid, lub.lambda_mixed,
                                                      lub.lambda_full_film))
        contacts[race] = {"load": load, "hertz_K": kh, "k_hertz": k_hertz, "rolling_speed": float(u),
                          "R_x": float(rx), "kappa": kappa, "h_min": h, "eccentricity": eps,
                          "k_film": k_film, "c_film": c_film, "k_link": k_link, "film_parameter": lam,
                          "c_hysteretic": c_hyst, "c_squeeze": c_fluid, "c_contact_model": c_contact,
                          "c_link": (c_film if film_damping == "short_bearing" else c_contact) * ca * ca}
    derivation = {"bearing": b.name, "radial_load": fr, "axial_load": fa, "radial_projection": ca * ca, "omega": w, "diametral_clearance": pd,
                  "radial_clearance": c_radial, "contact_angle": alpha, "q_max": q, "centrifugal_force": f_c,
                  "cage_speed": wc, "ball_mass": b.ball_mass, "outer_ring": outer, "inner_ring": inner,
                  "contacts": contacts, "dimensions": asdict(dimensions), "dimensions_source": dim_source,
                  "lubricant": lub.name,
                  "viscosity": lub.viscosity, "film_model": film, "hertz_method": hertz_method}
    return ThreeDofParameters(
        mass_outer=outer["mass"], mass_ball=b.ball_mass, mass_inner=inner["mass"],
        k_outer_ring=outer["stiffness"], k_inner_ring=inner["stiffness"],
        k_outer_contact=contacts["outer"]["k_link"], k_inner_contact=contacts["inner"]["k_link"],
        c_outer_contact=contacts["outer"]["c_link"], c_inner_contact=contacts["inner"]["c_link"],
        damping_row="symmetric", label=f"derived: {b.name}, Fr = {fr:g} N" + (f", Fa = {fa:g} N" if fa else "") + f", omega = {w:g} rad/s",
        reading={"link": link, "film_damping": film_damping, "film_prefactor": "corrected (4 / W_bar)",
                 "damping_row": "symmetric",
                 "film_normalisation": "C = C_bar W / (c omega), omega the shaft speed, c = P_d / 2"},
        derivation=derivation)


def assemble(p: ThreeDofParameters):
    """Mass [kg], damping [N s/m] and stiffness [N/m] matrices (3x3) of a
    parameter set, in the coordinate order :data:`DOFS`."""
    if not isinstance(p, ThreeDofParameters):
        raise InputError(f"parameters: expected ThreeDofParameters, got {type(p).__name__}")
    m = np.diag([p.mass_outer, p.mass_ball, p.mass_inner])
    k22, k21 = p.k_outer_contact, p.k_inner_contact
    k = np.array([[p.k_outer_ring + k22, -k22, 0.0],
                  [-k22, k22 + k21, -k21],
                  [0.0, -k21, p.k_inner_ring + k21]])
    c22, c21 = p.c_outer_contact, p.c_inner_contact
    c = np.array([[p.c_outer_ring + c22, -c22, 0.0],
                  [-c22, c22 + c21, -c21],
                  [0.0, -c21, p.c_inner_ring + c21]])
    if p.damping_row == "eq7_literal":
        c[1] = [0.0, c21, -c21]
    return m, c, k


@dataclass
class ThreeDofResult:
    """Eigen-analysis of one parameter set: the parameters, the matrices and
    the :class:`~.linear.ModalResult`."""

    parameters: ThreeDofParameters
    mass: np.ndarray
    damping: np.ndarray
    stiffness: np.ndarray
    modal: linear.ModalResult

    def to_dict(self) -> dict:
        d = self.modal.to_dict()
        d["dofs"] = list(DOFS)
        d["label"] = self.parameters.label
        d["reading"] = dict(self.parameters.reading)
        d["parameters"] = {k: v for k, v in self.parameters.to_dict().items()
                           if k not in ("reading", "derivation", "label")}
        d["matrices"] = {"mass": self.mass.tolist(), "damping": self.damping.tolist(),
                         "stiffness": self.stiffness.tolist()}
        d["units"].update({"mass": "kg", "damping": "N s/m", "stiffness": "N/m"})
        return d


def analyse(p: ThreeDofParameters) -> ThreeDofResult:
    """Assemble and solve the eigenproblem of the 6-state system.

    Examples
    --------
    The source's printed values: the outer ring (undamped in that reading)
    at sqrt(1e7 / 0.025) = 2e4 rad/s:

    >>> r = analyse(source_parameters())
    >>> [round(float(z.imag)) for z in r.modal.eigenvalues[2:4]]
    [20000, -20000]
    """
    m, c, k = assemble(p)
    try:
        modal = linear.modal_analysis(m, c, k)
    except InputError as exc:
        d = p.derivation
        if not (str(exc).startswith("damping:") and d.get("contacts")):
            raise
        race = max(d["contacts"], key=lambda r: d["contacts"][r]["c_link"])
        ct = d["contacts"][race]
        raise InputError(
            f"omega: at {d['omega']:.4g} rad/s and {d['radial_load']:g} N the {race} film is {ct['h_min'] * 1e9:.3g} nm "
            f"thick in a {d['radial_clearance'] * 1e6:.3g} um radial clearance (eccentricity {ct['eccentricity']:.6f}), "
            f"which gives a ball-race damper of {ct['c_link']:.3g} N s/m against springs of {ct['k_link']:.3g} N/m; "
            + str(exc)[len("damping: "):] + ": raise the speed, or use the contact model's damping "
            "(film_damping='contact_model', --film-damping contact_model)") from None
    return ThreeDofResult(p, m, c, k, modal)


def frequency_response(p: ThreeDofParameters, frequencies):
    """Receptance matrix H(f) [m/N] of a parameter set at the frequencies
    [Hz]; shape (len(frequencies), 3, 3), coordinates :data:`DOFS`."""
    m, c, k = assemble(p)
    return linear.frequency_response(m, c, k, frequencies)


def bpfo(bearing="6004", omega=2.0 * math.pi * 50.0) -> float:
    """Ball-pass frequency of the outer race [Hz] at an inner-ring speed
    [rad/s], outer ring fixed
    (:func:`~exudyn_bearing.physics.kinematics.defect_frequencies`)."""
    b = bearing if isinstance(bearing, BallBearing) else load_bearing(bearing)
    return kinematics.defect_frequencies(float(omega), 0.0, b.n_balls, b.ball_radius, b.pitch_radius,
                                         b.free_contact_angle)["bpfo"]


def ball_pass_force(t, frequency, amplitude, pulse_duration, phase=0.0):
    """A train of half-sine pulses, one per ball pass [N].

    f(t) = A sin(pi tau / T_p) for 0 <= tau < T_p, else 0, with tau the time
    since the last pass, passes at (k + phase) / frequency. This is the
    impulse train of a localised race defect struck by each ball (McFadden &
    Smith [5]_), with a finite pulse instead of a Dirac impulse.

    Parameters
    ----------
    t : array
        Times [s].
    frequency : float
        Ball-pass frequency [Hz] (> 0).
    amplitude : float
        Peak force A [N].
    pulse_duration : float
        T_p [s], 0 < T_p < 1/frequency.
    phase : float
        Fraction of a period before the first pass [-].
    """
    f = float(frequency)
    if not (math.isfinite(f) and f > 0.0):
        raise InputError(f"frequency: must be finite and > 0 [Hz], got {frequency!r}")
    tp = float(pulse_duration)
    if not (math.isfinite(tp) and 0.0 < tp < 1.0 / f):
        raise InputError(f"pulse_duration: must lie in (0, 1/frequency = {1.0 / f:.3g} s), got {pulse_duration!r}")
    a = float(amplitude)
    if not math.isfinite(a):
        raise InputError(f"amplitude: must be finite [N], got {amplitude!r}")
    tau = np.mod(np.asarray(t, float) - float(phase) / f, 1.0 / f)
    return np.where(tau < tp, a * np.sin(np.pi * tau / tp), 0.0)


def ball_pass_response(p: ThreeDofParameters, frequency, t_end, amplitude=1.0, pulse_duration=None,
                       distribution=(1.0, -1.0, 0.0), samples_per_pulse=40, dt=None):
    """Time response to a ball-pass force train.

    The pulse acts with the weights ``distribution`` on (outer ring, ball,
    inner ring); the default (1, -1, 0) is a defect on the outer race: each
    passing ball and the outer ring are pushed apart. Integrated exactly for
    the sampled (piecewise-linear) force (:func:`~.linear.time_response`).

    Parameters
    ----------
    p : ThreeDofParameters
    frequency : float
        Ball-pass frequency [Hz], e.g. :func:`bpfo`.
    t_end : float
        Duration [s].
    amplitude : float
        Peak pulse force [N] (the system is linear: responses scale with it).
    pulse_duration : float, optional
        Pulse length [s]; default a tenth of the ball-pass period.
    distribution : 3 floats
        Weights of the pulse on the coordinates.
    samples_per_pulse : int
        Time step = pulse_duration / samples_per_pulse unless ``dt`` is given.

    Returns
    -------
    dict with ``t`` [s], ``force`` (N, 3) [N], ``q`` (N, 3) [m], ``v`` (N, 3)
    [m/s], ``energy`` [J], ``dt`` [s].
    """
    f = float(frequency)
    tp = 0.1 / f if pulse_duration is None else float(pulse_duration)
    te = float(t_end)
    if not (math.isfinite(te) and te > 0.0):
        raise InputError(f"t_end: must be finite and > 0 [s], got {t_end!r}")
    h = tp / int(samples_per_pulse) if dt is None else float(dt)
    if not (math.isfinite(h) and 0.0 < h < te):
        raise InputError(f"dt: must lie in (0, t_end), got {h!r}")
    d = np.asarray(distribution, float)
    if d.shape != (3,) or not np.all(np.isfinite(d)):
        raise InputError(f"distribution: expected 3 finite weights, got {distribution!r}")
    n = int(round(te / h)) + 1
    t = np.arange(n) * h
    force = ball_pass_force(t, f, amplitude, tp)[:, None] * d[None, :]
    m, c, k = assemble(p)
    q, v = linear.time_response(m, c, k, t, force)
    return {"t": t, "force": force, "q": q, "v": v, "energy": linear.mechanical_energy(m, k, q, v), "dt": h,
            "pulse_duration": tp, "frequency": f}
