"""Power-loss components of a ball bearing and two catalogue reference models.

docs/theory/losses.md. One relation per function, plain numpy arithmetic on
scalars or arrays, SI units in and out (the catalogue models convert to
their own units inside and say so).

Contact-level losses (they need the load, ellipse and rolling speed of each
contact, which the solvers compute):

* :func:`ehl_rolling_force` - the film's hydrodynamic rolling force of an
  elliptic EHL contact (Harris & Kotzalas [1]_), isothermal, fully flooded;
* :func:`hysteresis_rolling_force` - rolling resistance from elastic
  hysteresis (Johnson [2]_);
* :func:`rolling_resistance_power` - the power of a rolling resistance force.

Bearing-level drag:

* :func:`sphere_drag_coefficient`, :func:`mixture_density`,
  :func:`mixture_viscosity`, :func:`ball_drag_force` - drag of a ball
  orbiting through an oil-air mixture (Harris & Kotzalas [1]_ with the
  standard sphere drag curve of Clift, Grace & Weber [5]_).

Churning in an oil bath (flooded bearing):

* :func:`bath_immersion_fraction` - the orbit-mean share of a ball's frontal
  area below the oil level; with it as the oil fraction of
  :func:`mixture_density` the ball drag of [1]_ becomes the churning drag of
  the balls through the bath (the project's reading of [1]_ ch. 6 for a
  bath, see the function).

Cage friction:

* :func:`cage_pocket_loads` - ball-pocket normal loads from the drag the
  cage carries (Harris & Kotzalas [1]_ ch. 6: the cage drives the balls of
  the unloaded zone against their drag, the loaded balls drive the cage);
* :func:`cage_pocket_friction_power` - sliding of the ball surface in its
  pocket;
* :func:`petroff_torque` - the hydrodynamic drag of a lightly loaded short
  journal bearing (Petroff [6]_), the cage riding on its guiding land.

Reference models of the whole bearing (frictional moment [N m]):

* SKF's catalogue model [3]_: :func:`skf_rolling_variable`,
  :func:`skf_sliding_variable`, :func:`skf_inlet_shear_factor`,
  :func:`skf_replenishment_factor`, :func:`skf_sliding_coefficient`,
  :func:`skf_drag_moment`, :func:`skf_frictional_moment`;
* Palmgren [4]_: :func:`palmgren_viscous_moment`, :func:`palmgren_load_factor`,
  :func:`palmgren_load_moment`.

What is checked and what is not: each function's docstring says which
constants could be compared with a second public copy of the source during
the writing of this module and which are quoted from the cited text without
such a check.

References
----------
.. [1] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed.,
   Vol. 2: Advanced Concepts of Bearing Technology, CRC Press, 2007,
   ch. 5 (friction in rolling contacts) and ch. 6 (friction in bearings).
.. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press, 1985,
   sec. 9.2 (hysteresis losses in rolling).
.. [3] SKF, Rolling bearings (catalogue PUB BU/P1 17000/1 EN), 2018, section
   "Friction": the SKF model for calculating the frictional moment.
.. [4] A. Palmgren, Ball and Roller Bearing Engineering, 3rd ed., SKF
   Industries, 1959; as given in Harris & Kotzalas [1]_ ch. 6.
.. [5] R. Clift, J. R. Grace and M. E. Weber, Bubbles, Drops and Particles,
   Academic Press, 1978, Table 5.2 (standard drag curve of a sphere).
.. [6] N. P. Petroff, "Friction in machines and the effect of the
   lubricant," Inzhenernii Zhurnal, St. Petersburg, 1883; as given in
   B. J. Hamrock, S. R. Schmid and B. O. Jacobson, Fundamentals of Fluid
   Film Lubrication, 2nd ed., Marcel Dekker, 2004, sec. 8.2 (Petroff's
   equation).
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel, lazy_ufunc
from ..data.errors import InputError

__all__ = [
    "AIR_DENSITY",
    "AIR_VISCOSITY",
    "HYSTERESIS_LOSS_FACTOR_STEEL",
    "OIL_DENSITY",
    "SKF_CONSTANTS",
    "SKF_K_RS",
    "SKF_MU_BOUNDARY",
    "SKF_MU_EHL",
    "CAGE_POCKET_FRICTION",
    "ball_drag_force",
    "bath_immersion_fraction",
    "cage_pocket_friction_power",
    "cage_pocket_loads",
    "ehl_rolling_force",
    "ehl_rolling_force_expr",
    "hysteresis_rolling_force",
    "hysteresis_rolling_force_expr",
    "mixture_density",
    "mixture_viscosity",
    "palmgren_load_factor",
    "palmgren_load_moment",
    "palmgren_viscous_moment",
    "petroff_torque",
    "rolling_resistance_power",
    "skf_drag_moment",
    "skf_frictional_moment",
    "skf_inlet_shear_factor",
    "skf_replenishment_factor",
    "skf_rolling_variable",
    "skf_sliding_coefficient",
    "skf_sliding_variable",
    "sphere_drag_coefficient",
    "LOSS_FLOOR_MU",
]

#: Friction coefficient of the smallest loss whose steadiness is judged: a
#: friction torque below LOSS_FLOOR_MU (|F_r| + |F_a|) r_p, or a dissipation
#: below that times omega, is measured against that floor and reported, but
#: does not decide (the dynamic summaries' steadiness and energy checks, the
#: quasi-static solver's traction-resolution check). 1e-4 is an order below the friction coefficients of ball
#: bearings in manufacturers' torque estimates (about 0.001-0.002): a loss
#: below it is no result anyone uses, and the point traction level's
#: tangential springs exchange energy about zero (the main job: 2e-4 N m
#: against a floor of 9e-3 N m, sign changing from 10 ms to 10 ms at 1 rad/s).
LOSS_FLOOR_MU = 1e-4

#: Hysteresis loss factor alpha_h of hardened bearing steel [-]: the value Harris & Kotzalas [1]_
#: ch. 5 use (0.007); Johnson [2]_ sec. 9.2 gives loss factors below 1 % for hard metals in
#: elastic rolling. Not re-checked against the printed page here.
HYSTERESIS_LOSS_FACTOR_STEEL = 0.007
#: Air at 20 C and 1 atm: density [kg/m^3] and dynamic viscosity [Pa s].
AIR_DENSITY = 1.204
AIR_VISCOSITY = 1.81e-5
#: Density of the oil for the ball drag when the lubricant carries none [kg/m^3]: a mineral oil near
#: 40 C (ISO VG 32-68 oils are 850-880 kg/m^3 at 15 C); the quasi-static losses and the dynamic
#: engines' drag use it.
OIL_DENSITY = 860.0
#: Sliding friction coefficient of a lubricated ball in its cage pocket [-]: an assumed boundary /
#: mixed-film value (steel ball on a steel or brass pocket wetted by the oil; lubricated sliding
#: of these pairs lies at about 0.05-0.15). Not a value of a table in the cited sources.
CAGE_POCKET_FRICTION = 0.1

#: Geometry constants of SKF's model [3]_ (units of the catalogue: N, mm, r/min), by series:
#: ``kind`` "deep_groove" (R1, R2, S1, S2) or "angular_contact" (R1, R2, R3, S1, S2, S3), and the
#: bearing-type constant K_z. The 62 series row matched an independent public copy of the table;
#: the 72 B row is quoted from the catalogue's table without a second copy to compare.
SKF_CONSTANTS = {
    "62": {"kind": "deep_groove", "R1": 3.9e-7, "R2": 1.7, "S1": 3.23e-3, "S2": 36.5, "K_z": 3.1},
    "63": {"kind": "deep_groove", "R1": 3.7e-7, "R2": 1.7, "S1": 2.84e-3, "S2": 92.8, "K_z": 3.1},
    "60": {"kind": "deep_groove", "R1": 4.1e-7, "R2": 1.7, "S1": 3.73e-3, "S2": 14.6, "K_z": 3.1},
    "72B": {"kind": "angular_contact", "R1": 5.03e-7, "R2": 1.97, "R3": 1.90e-12, "S1": 1.30e-2, "S2": 0.68,
            "S3": 1.91e-12, "K_z": 4.4},
}
#: SKF's mu_EHL [3]_: full-film sliding friction coefficient by oil type.
SKF_MU_EHL = {"mineral": 0.05, "synthetic": 0.04, "transmission": 0.1}
#: SKF's boundary friction coefficient mu_bl for n > 0 [3]_.
SKF_MU_BOUNDARY = 0.12
#: SKF's K_rs [3]_: 3e-8 for a low oil level bath and oil jet, 6e-8 for grease and oil-air.
SKF_K_RS = {"oil_jet": 3e-8, "low_oil_level": 3e-8, "grease": 6e-8, "oil_air": 6e-8}


# ----------------------------------------------------------------------------------------------------
# contact-level rolling resistance
# ----------------------------------------------------------------------------------------------------
def ehl_rolling_force(u_r, load, r_x, kappa, e_prime, eta, xi):
    """Hydrodynamic (EHL) rolling force F_R [N] of an elliptic contact, Harris & Kotzalas [1]_.

    F_R = 2.86 E' R_x^2 k^0.348 G^0.022 U^0.66 W^0.47          ([1] ch. 5, point-contact form)

    with U = eta u_r / (E' R_x), G = xi E', W = Q / (E' R_x^2) (the
    groups of :mod:`exudyn_bearing.physics.ehl`). It is the force the film
    puts on each of the two surfaces against their rolling, from the
    pressure build-up and Poiseuille shear in the inlet (Goksem & Hargreaves'
    "rolling traction" generalised to point contacts).

    Left out, and said here because the source offers them: the inlet shear
    heating (thermal) reduction factor and the starvation reduction factor
    ([1] ch. 5; Houpert, Tribol. Trans. 45 (2002) 345); both lower F_R at
    high speed, so this is the isothermal, fully flooded upper value.

    Validity: isothermal fully flooded EHL of steel contacts, the range of
    the Hamrock-Dowson fits (k 1-8, U 1e-12 - 1e-9, W 1e-7 - 1e-4 roughly);
    outside it an extrapolation. The coefficient 2.86 and the exponents are
    quoted from [1]; a second public copy to compare them with was not found.

    Parameters
    ----------
    u_r : float or ndarray
        Rolling (entrainment) speed [m/s]; its magnitude is used.
    load : float or ndarray
        Contact load Q [N].
    r_x : float or ndarray
        Effective radius in the rolling direction [m].
    kappa : float or ndarray
        Ellipticity k = a/b >= 1 [-] (major over minor semi-axis).
    e_prime : float
        Effective modulus E' [Pa].
    eta : float
        Viscosity at the inlet temperature [Pa s].
    xi : float
        Pressure-viscosity coefficient [m^2/N].

    Returns
    -------
    float or ndarray
        F_R [N], 0 where u_r or load is 0.
    """
    f = ehl_rolling_force_expr(np.asarray(u_r, dtype=float), np.asarray(load, dtype=float),
                               np.asarray(r_x, dtype=float), np.asarray(kappa, dtype=float), e_prime, eta, xi)
    return f if np.ndim(f) else float(f)


def ehl_rolling_force_expr(u_r, load, r_x, kappa, e_prime, eta, xi):
    """The relation of :func:`ehl_rolling_force` on plain numbers or arrays (no conversion): the one
    implementation, compiled for the contact kernel as ``_ehl_rolling_force``."""
    u = np.abs(u_r)
    q = np.maximum(load, 0.0)
    big_u = eta * u / (e_prime * r_x)
    big_g = xi * e_prime
    big_w = q / (e_prime * r_x * r_x)
    return 2.86 * e_prime * r_x * r_x * kappa ** 0.348 * big_g ** 0.022 * big_u ** 0.66 * big_w ** 0.47


_ehl_rolling_force = kernel(ehl_rolling_force_expr)


def hysteresis_rolling_force(load, b, r_x, alpha_h=HYSTERESIS_LOSS_FACTOR_STEEL):
    """Rolling resistance from elastic hysteresis F_h [N], Johnson [2]_ sec. 9.2.

    F_h = (3/16) alpha_h Q b / R_x

    Johnson's result for a sphere (circular contact of radius a, eq. (9.19)
    there: F = (3/16) alpha W a / R): the work of the elastic compression per
    unit distance rolled, (3/16) W a / R, of which the fraction alpha_h is
    lost. For the ellipse of a ball on a race the semi-axis along the rolling
    direction b and the radius R_x of that direction take the place of a and
    R (the form used by Harris & Kotzalas [1]_ ch. 5).

    Validity: elastic rolling (p_max below the elastic limit, the range this
    package refuses above 4.2 GPa), small slip; alpha_h from rolling tests of
    the material (:data:`HYSTERESIS_LOSS_FACTOR_STEEL`, 0.007 for hardened
    bearing steel).

    Parameters
    ----------
    load : float or ndarray
        Contact load Q [N].
    b : float or ndarray
        Semi-axis of the contact ellipse along the rolling direction [m].
    r_x : float or ndarray
        Effective radius in the rolling direction [m].
    alpha_h : float
        Hysteresis loss factor [-].

    Returns
    -------
    float or ndarray
        F_h [N].
    """
    f = hysteresis_rolling_force_expr(np.asarray(load, dtype=float), np.asarray(b, dtype=float),
                                      np.asarray(r_x, dtype=float), alpha_h)
    return f if np.ndim(f) else float(f)


def hysteresis_rolling_force_expr(load, b, r_x, alpha_h):
    """The relation of :func:`hysteresis_rolling_force` on plain numbers or arrays (no conversion): the
    one implementation, compiled for the contact kernel as ``_hysteresis_rolling_force``."""
    return 3.0 / 16.0 * alpha_h * np.maximum(load, 0.0) * b / r_x


_hysteresis_rolling_force = kernel(hysteresis_rolling_force_expr)


def rolling_resistance_power(force, u_r, surfaces=1):
    """Power dissipated by a rolling resistance force [W]: surfaces * F * |u_r|.

    A force F that opposes the motion of a surface moving at u_r relative to
    the contact takes F |u_r| from it. The hysteresis force of Johnson [2]_ is
    the force that keeps the pair rolling (``surfaces=1``: F_h |u_r| is the
    whole dissipation); the EHL rolling force acts on each of the two
    surfaces (``surfaces=2``: the film's dissipation in steady state equals
    the power both surfaces deliver, F_R u_1 + F_R u_2 = 2 F_R u_r in rolling).
    """
    p = surfaces * np.asarray(force, dtype=float) * np.abs(np.asarray(u_r, dtype=float))
    return p if np.ndim(p) else float(p)


# ----------------------------------------------------------------------------------------------------
# ball drag in an oil-air mixture
# ----------------------------------------------------------------------------------------------------
@lazy_ufunc("float64(float64)")
def sphere_drag_coefficient(reynolds):
    """Drag coefficient C_D [-] of a sphere against its Reynolds number Re = rho v D / eta.

    Standard drag curve (Clift, Grace & Weber [5]_, Schiller-Naumann up to
    Re = 1000, Newton's regime above):

    C_D = 24/Re (1 + 0.15 Re^0.687)  for Re <= 1000;   C_D = 0.44  for 1000 < Re < 2e5

    Validity: a smooth sphere in a uniform stream, Re < 2e5 (below the drag
    crisis; above it C_D drops to about 0.1-0.2, not modelled: 0.44 is kept
    and is then an upper value). Re = 0 gives C_D = inf (the drag force
    stays finite: use :func:`ball_drag_force`). A ufunc built on first use
    (:class:`~exudyn_bearing._jit.LazyUfunc`): the contact kernel calls it on numbers, numpy on
    arrays (one implementation).
    """
    if reynolds <= 0.0:
        return math.inf
    if reynolds <= 1000.0:
        return 24.0 / reynolds * (1.0 + 0.15 * reynolds ** 0.687)
    return 0.44


def mixture_density(oil_fraction, oil_density, air_density=AIR_DENSITY):
    """Effective density of a homogeneous oil-air mixture [kg/m^3]: phi rho_oil + (1 - phi) rho_air.

    Harris & Kotzalas [1]_ ch. 6 take the density of the mixture the balls
    churn through as the oil's density times the oil's volume fraction phi in
    the bearing's free space (jet or mist lubrication: phi of the order of
    0.01-0.1, from the oil flow); the air term is added here for phi -> 0.
    """
    phi = np.asarray(oil_fraction, dtype=float)
    r = phi * oil_density + (1.0 - phi) * air_density
    return r if np.ndim(r) else float(r)


def mixture_viscosity(oil_fraction, oil_viscosity, air_viscosity=AIR_VISCOSITY):
    """Effective dynamic viscosity of an oil-air mixture [Pa s]: phi eta_oil + (1 - phi) eta_air.

    A volume-weighted mean (the homogeneous-mixture assumption of [1]_ ch. 6
    applied to the viscosity, which enters only through Re and so C_D; the
    drag is nearly independent of it in Newton's regime, Re > 1000, where the
    balls of a running bearing are).
    """
    phi = np.asarray(oil_fraction, dtype=float)
    r = phi * oil_viscosity + (1.0 - phi) * air_viscosity
    return r if np.ndim(r) else float(r)


@lazy_ufunc("float64(float64, float64, float64, float64)")
def ball_drag_force(speed, ball_diameter, density, viscosity):
    """Drag force on a ball moving through a fluid [N], Harris & Kotzalas [1]_ ch. 6.

    F_D = (1/2) C_D(Re) rho v^2 (pi D^2 / 4),   Re = rho v D / eta

    For a ball orbiting at omega_m on the pitch diameter d_m, v = d_m omega_m / 2
    relative to a mixture at rest: F_D = pi C_D rho D^2 (d_m omega_m)^2 / 32
    ([1] ch. 6). At Re -> 0 it tends to Stokes' 3 pi eta D v.

    Parameters
    ----------
    speed : float or ndarray
        Speed of the ball centre relative to the fluid [m/s] (magnitude used).
    ball_diameter : float
        D [m].
    density, viscosity : float
        Of the fluid or mixture (:func:`mixture_density`,
        :func:`mixture_viscosity`) [kg/m^3], [Pa s].

    A ufunc built on first use (:class:`~exudyn_bearing._jit.LazyUfunc`; the contact kernel calls it on
    numbers, numpy on arrays)
    with C_D from :func:`sphere_drag_coefficient`; 0 at rest.
    """
    v = abs(speed)
    if v == 0.0:
        return 0.0
    return 0.5 * sphere_drag_coefficient(density * v * ball_diameter / viscosity) * density * v * v \
        * (math.pi * ball_diameter * ball_diameter / 4.0)


def bath_immersion_fraction(oil_level, pitch_radius, ball_diameter, n_points=720):
    """Orbit-mean share of a ball's frontal area that lies below the oil level of a bath [-].

    A ball whose centre is at azimuth theta from the lowest point of its
    orbit has its centre at the height
    h_c = D/2 + r_p (1 - cos theta) above the lowest point of the outer
    raceway (SKF's reference of the oil level H [3]_, the ball touching the
    race bottom). The part of its circular cross-section (radius D/2) below
    H is a circular segment of depth s = H - (h_c - D/2), 0 <= s <= D:

    A(s) / (pi R^2) = [R^2 acos(1 - s/R) - (R - s) sqrt(2 R s - s^2)] / (pi R^2),   R = D/2,

    averaged over theta in [0, 2 pi) (midpoint rule, ``n_points`` azimuths:
    the integrand is continuous with two kinks, the error of 720 points is
    below 1e-5).

    Used as the oil fraction phi of :func:`mixture_density` it turns the
    ball drag of Harris & Kotzalas [1]_ ch. 6 (a ball orbiting through a
    fluid of effective density rho_e) into the churning drag of the balls of
    a bath-lubricated bearing: each ball drags through oil over the part of
    its frontal area and orbit that is immersed and through air elsewhere
    (in Newton's regime the drag is linear in the density, so the mean over
    the orbit is the drag at the mean density). This orbit average is the
    project's reading; [1]_ gives the effective density of the free space
    without a rule for a partly filled bath.

    Validity: the oil in the bath at rest (an upper value: the bath is
    dragged along by the cage and the balls, which lowers the relative
    speed), a flat free surface (no splashing, no oil thrown off), a
    horizontal shaft. H = 0: 0; H >= 2 r_p + D (the whole orbit
    immersed): 1; H at the bearing axis (r_p + D/2): 1/2 by symmetry.

    Parameters
    ----------
    oil_level : float
        H above the lowest point of the outer raceway [m], >= 0.
    pitch_radius : float
        r_p [m] (radius of the ball centres' orbit).
    ball_diameter : float
        D [m].
    n_points : int
        Azimuths of the average.
    """
    for name, v in (("pitch_radius", pitch_radius), ("ball_diameter", ball_diameter)):
        _check(name, v)
    _check("oil_level", oil_level, positive=False)
    r = 0.5 * ball_diameter
    theta = (np.arange(n_points) + 0.5) * (2.0 * math.pi / n_points)
    s = np.clip(oil_level - pitch_radius * (1.0 - np.cos(theta)), 0.0, 2.0 * r)
    seg = r * r * np.arccos(1.0 - s / r) - (r - s) * np.sqrt(np.maximum(2.0 * r * s - s * s, 0.0))
    return float(np.mean(seg) / (math.pi * r * r))


# ----------------------------------------------------------------------------------------------------
# cage friction
# ----------------------------------------------------------------------------------------------------
def cage_pocket_loads(drag_force, loaded, cage_torque, pitch_radius):
    """Normal loads between the balls and their cage pockets [N], from the loads the cage carries.

    Harris & Kotzalas [1]_ ch. 6 (ball-cage interaction): in steady
    operation the balls of the loaded zone, driven by the race traction,
    push the cage; the cage pushes the balls of the unloaded zone, which
    carry no traction to overcome their drag. The torque balance of the
    cage about the bearing axis gives

    Q_c,j = F_D,j                                     (unloaded ball j)
    Q_c,j = (T_cage / r_p + sum_unloaded F_D) / n_L   (each of the n_L loaded balls)

    with F_D the drag (and churning) force of each ball and T_cage the
    torque resisting the cage (its land friction, :func:`petroff_torque`).
    The share of the loaded balls is taken equal (the project's reading; the
    source resolves it per ball with the dynamics of each ball). Left out:
    the pocket loads from the variation of a ball's orbital speed around
    the bearing (misalignment, combined loads), from a gyroscopic moment the
    race traction does not carry, and from the cage's weight and
    unbalance; a quasi-static model does not know them.

    Parameters
    ----------
    drag_force : ndarray (Z,)
        F_D of each ball [N] (>= 0).
    loaded : ndarray of bool (Z,)
        Balls whose contacts carry the traction that drives them.
    cage_torque : float
        Torque resisting the cage about the bearing axis [N m] (>= 0).
    pitch_radius : float
        r_p [m].

    Returns
    -------
    ndarray (Z,)
        Q_c [N]; with no loaded ball, the cage and every ball carry drag
        only: F_D (the cage torque cannot be carried and is left out).
    """
    f = np.abs(np.asarray(drag_force, dtype=float))
    on = np.asarray(loaded, dtype=bool)
    n_l = int(np.sum(on))
    if n_l == 0:
        return f.copy()
    share = (abs(float(cage_torque)) / pitch_radius + float(np.sum(f[~on]))) / n_l
    return np.where(on, share, f)


def cage_pocket_friction_power(pocket_load, ball_speed, ball_diameter, mu=CAGE_POCKET_FRICTION):
    """Frictional power of a ball sliding in its cage pocket [W]: mu Q_c (D/2) |omega_R|.

    The pocket touches the ball on its equator in the orbital direction;
    the ball turns about an axis in the plane of the bearing axis and the
    radius (normal to the orbital direction), at omega_R relative to the
    cage, so its surface slides over the pocket at (D/2) |omega_R|; Coulomb
    friction mu Q_c opposes it (Harris & Kotzalas [1]_ ch. 6, cage pocket
    friction). Validity: a pocket contact in boundary or mixed lubrication
    (a hydrodynamic pocket film would give a viscous force instead), mu
    from :data:`CAGE_POCKET_FRICTION` unless given.

    Parameters
    ----------
    pocket_load : float or ndarray
        Q_c [N] (:func:`cage_pocket_loads`).
    ball_speed : float or ndarray
        omega_R [rad/s], the ball's angular speed about its own axis in the
        cage's frame (magnitude used).
    ball_diameter : float
        D [m].
    mu : float
        Friction coefficient [-].
    """
    p = mu * np.abs(np.asarray(pocket_load, dtype=float)) * 0.5 * ball_diameter \
        * np.abs(np.asarray(ball_speed, dtype=float))
    return p if np.ndim(p) else float(p)


def petroff_torque(viscosity, radius, width, clearance, speed):
    """Petroff's viscous torque of a concentric journal bearing [N m]: T = 2 pi eta r^3 L omega / c.

    Couette shear of a full film of viscosity eta in the radial clearance
    c between a journal of radius r and length L turning at omega relative
    to its sleeve: shear stress eta r omega / c over the area 2 pi r L, at
    the arm r (Petroff [6]_). For a cage riding on a guiding ring land: r
    the land radius, L the land width (both rails together), c the radial
    land clearance, omega the cage speed relative to that ring. The power is
    T |omega|. Validity: a lightly loaded (concentric) journal, laminar
    Couette flow (Taylor number below about 1700), a full film; an
    eccentric cage pressed on its land by its weight or unbalance loses
    more, a starved land less.

    Parameters
    ----------
    viscosity : float
        eta [Pa s].
    radius, width, clearance : float
        r, L, c [m] (c > 0).
    speed : float or ndarray
        omega relative [rad/s] (the sign carries through: T opposes it).
    """
    for name, v in (("viscosity", viscosity), ("radius", radius), ("width", width), ("clearance", clearance)):
        _check(name, v)
    t = 2.0 * math.pi * viscosity * radius ** 3 * width * np.asarray(speed, dtype=float) / clearance
    return t if np.ndim(t) else float(t)


# ----------------------------------------------------------------------------------------------------
# SKF's model (catalogue units inside: n [r/min], nu [mm^2/s], d_m [mm], loads [N], moments [N mm])
# ----------------------------------------------------------------------------------------------------
def _rpm(omega):
    return np.abs(np.asarray(omega, dtype=float)) * 30.0 / math.pi


def _check(name, value, positive=True):
    v = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(v)) or (np.any(v <= 0.0) if positive else np.any(v < 0.0)):
        raise InputError(f"{name}: must be {'> 0' if positive else '>= 0'} and finite, got {value!r}")


def _series(series):
    try:
        return SKF_CONSTANTS[str(series)]
    except KeyError:
        raise InputError(f"series: no SKF geometry constants for {series!r} (known: "
                         f"{', '.join(SKF_CONSTANTS)})") from None


def skf_rolling_variable(series, d_m, Fr, Fa=0.0, omega=0.0, C0=None):
    """SKF's rolling frictional variable G_rr (catalogue units) [3]_ (table 'geometric and load dependent
    variables', radial bearings).

    Deep groove ball bearings: G_rr = R1 d_m^1.96 F_r^0.54 (F_a = 0), else
    G_rr = R1 d_m^1.96 (F_r + R2 / sin(alpha_F) F_a)^0.54 with
    alpha_F = 24.6 (F_a / C_0)^0.24 [deg].
    Angular contact ball bearings: G_rr = R1 d_m^1.97 (F_r + F_g + R2 F_a)^0.54,
    F_g = R3 d_m^4 n^2.

    ``d_m`` [m], loads [N], ``omega`` [rad/s], ``C0`` basic static load
    rating [N] (deep groove with axial load). The formulas and the 62-series
    constants matched a second public copy of the catalogue table.
    """
    c = _series(series)
    dm = d_m * 1e3
    if c["kind"] == "deep_groove":
        if Fa <= 0.0:
            return c["R1"] * dm ** 1.96 * Fr ** 0.54
        if C0 is None:
            raise InputError("C0: the SKF deep groove model needs the basic static load rating C0 [N] "
                             "with an axial load")
        sin_af = math.sin(math.radians(24.6 * (Fa / C0) ** 0.24))
        return c["R1"] * dm ** 1.96 * (Fr + c["R2"] / sin_af * Fa) ** 0.54
    n = _rpm(omega)
    fg = c["R3"] * dm ** 4 * n ** 2
    return c["R1"] * dm ** 1.97 * (Fr + fg + c["R2"] * Fa) ** 0.54


def skf_sliding_variable(series, d_m, Fr, Fa=0.0, omega=0.0, C0=None):
    """SKF's sliding frictional variable G_sl (catalogue units) [3]_.

    Deep groove: G_sl = S1 d_m^-0.26 F_r^(5/3) (F_a = 0), else
    G_sl = S1 d_m^-0.145 (F_r^5 + S2 d_m^1.5 / sin(alpha_F) F_a^4)^(1/3).
    Angular contact: G_sl = S1 d_m^0.26 ((F_r + F_g)^(4/3) + S2 F_a^(4/3)),
    F_g = S3 d_m^4 n^2. Arguments as :func:`skf_rolling_variable`.
    """
    c = _series(series)
    dm = d_m * 1e3
    if c["kind"] == "deep_groove":
        if Fa <= 0.0:
            return c["S1"] * dm ** -0.26 * Fr ** (5.0 / 3.0)
        if C0 is None:
            raise InputError("C0: the SKF deep groove model needs the basic static load rating C0 [N] "
                             "with an axial load")
        sin_af = math.sin(math.radians(24.6 * (Fa / C0) ** 0.24))
        return c["S1"] * dm ** -0.145 * (Fr ** 5 + c["S2"] * dm ** 1.5 / sin_af * Fa ** 4) ** (1.0 / 3.0)
    n = _rpm(omega)
    fg = c["S3"] * dm ** 4 * n ** 2
    return c["S1"] * dm ** 0.26 * ((Fr + fg) ** (4.0 / 3.0) + c["S2"] * Fa ** (4.0 / 3.0))


def skf_inlet_shear_factor(omega, d_m, nu):
    """SKF's inlet shear heating reduction factor phi_ish [-] [3]_:
    phi_ish = 1 / (1 + 1.84e-9 (n d_m)^1.28 nu^0.64), n [r/min], d_m [mm], nu [mm^2/s].

    ``omega`` [rad/s], ``d_m`` [m], ``nu`` kinematic viscosity [m^2/s]. The
    constants matched a second public implementation of the catalogue model.
    """
    n = _rpm(omega)
    return 1.0 / (1.0 + 1.84e-9 * (n * d_m * 1e3) ** 1.28 * (nu * 1e6) ** 0.64)


def skf_replenishment_factor(omega, nu, d, D, K_z, K_rs=SKF_K_RS["oil_jet"]):
    """SKF's kinematic replenishment / starvation reduction factor phi_rs [-] [3]_:
    phi_rs = exp(-K_rs nu n (d + D) sqrt(K_z / (2 (D - d)))), catalogue units.

    ``d``, ``D`` bore and outside diameter [m]; ``K_rs`` 3e-8 (low oil level
    bath, oil jet) or 6e-8 (grease, oil-air); ``K_z`` the bearing-type
    constant (3.1 deep groove, 4.4 angular contact).
    """
    n = _rpm(omega)
    return np.exp(-K_rs * nu * 1e6 * n * (d + D) * 1e3 * np.sqrt(K_z / (2.0 * (D - d) * 1e3)))


def skf_sliding_coefficient(omega, nu, d_m, mu_ehl=SKF_MU_EHL["mineral"], mu_bl=SKF_MU_BOUNDARY):
    """SKF's sliding friction coefficient mu_sl [-] [3]_: mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL,
    phi_bl = exp(-2.6e-8 (n nu)^1.4 d_m), catalogue units; mu_bl = 0.12 (n > 0), mu_EHL 0.05 mineral
    oil, 0.04 synthetic, 0.1 transmission fluid (:data:`SKF_MU_EHL`)."""
    n = _rpm(omega)
    phi_bl = np.exp(-2.6e-8 * (n * nu * 1e6) ** 1.4 * d_m * 1e3)
    return phi_bl * mu_bl + (1.0 - phi_bl) * mu_ehl


def skf_drag_moment(omega, nu, d, D, K_z, oil_level, V_M=0.0, rows=1):
    """SKF's drag loss moment of a bearing in an oil bath [N m] [3]_ (section "drag losses").

    M_drag = 0.4 V_M K_ball d_m^5 n^2 + 1.093e-7 n^2 d_m^3 (n d_m^2 f_t / nu)^-1.379 R_s   [N mm]

    K_ball = i_rw K_z (d + D)/(D - d) 1e-12, f_A = 0.05 K_z (D + d)/(D - d),
    R_s = 0.36 d_m^2 (t - sin t) f_A, t = 2 acos((0.6 d_m - H)/(0.6 d_m)) (H <= 1.2 d_m),
    f_t = sin(t/2) for t <= pi, else 1.

    ``oil_level`` H from the lowest point of the outer raceway [m]; ``V_M``
    the drag-loss factor read from SKF's diagram against H/d_m (not
    reproduced here: give it, 0 leaves the first, hydrodynamic term out);
    ``rows`` i_rw. For oil-jet lubrication SKF's guidance is this model with
    the oil level at half the lowest ball, doubled. A bearing without bath
    (H = 0) has no drag term in this model. The second term's constants
    matched a second public implementation; the diagram for V_M is not
    available here.
    """
    _check("oil_level", oil_level, positive=False)
    n = _rpm(omega)
    dm = 0.5 * (d + D) * 1e3
    h = min(oil_level * 1e3, 1.2 * dm)
    if h <= 0.0 or np.all(n == 0.0):
        return 0.0 * n
    t = 2.0 * math.acos((0.6 * dm - h) / (0.6 * dm))
    f_t = math.sin(0.5 * t) if t <= math.pi else 1.0
    f_a = 0.05 * K_z * (D + d) / (D - d)
    r_s = 0.36 * dm ** 2 * (t - math.sin(t)) * f_a
    k_ball = rows * K_z * (d + D) / (D - d) * 1e-12
    with np.errstate(divide="ignore", invalid="ignore"):
        visc = np.where(n > 0, 1.093e-7 * n ** 2 * dm ** 3 * (n * dm ** 2 * f_t / (nu * 1e6)) ** -1.379 * r_s, 0.0)
    m = 0.4 * V_M * k_ball * dm ** 5 * n ** 2 + visc
    return m * 1e-3


def skf_frictional_moment(series, d, D, Fr, Fa, omega, nu, *, C0=None, mu_ehl=SKF_MU_EHL["mineral"],
                          K_rs=SKF_K_RS["oil_jet"], oil_level=0.0, V_M=0.0):
    """Frictional moment of a ball bearing by SKF's model [3]_ [N m], by component.

    M = phi_ish phi_rs M_rr + M_sl + M_drag (+ M_seal, left out: open bearings),
    M_rr = G_rr (nu n)^0.6, M_sl = G_sl mu_sl (catalogue units, N mm).

    Parameters
    ----------
    series : str
        Key of :data:`SKF_CONSTANTS` ("62" for the 6208, "72B" for the 7208 B).
    d, D : float
        Bore and outside diameter [m] (d_m = (d + D)/2).
    Fr, Fa : float
        Radial and axial load [N].
    omega : float
        Speed of the rotating ring [rad/s].
    nu : float
        Kinematic viscosity at the operating temperature [m^2/s].

    Returns
    -------
    dict
        ``rolling`` (phi_ish phi_rs M_rr), ``sliding``, ``drag``, ``total`` [N m],
        and the factors ``phi_ish``, ``phi_rs``, ``mu_sl``.

    Validity: SKF states the model for steady conditions, full film or mixed
    lubrication with mineral or synthetic oils, loads above the minimum load,
    speeds below the limiting speed, operating viscosity from the bearing's
    temperature.
    """
    for name, v in (("d", d), ("D", D), ("nu", nu)):
        _check(name, v)
    for name, v in (("Fr", Fr), ("Fa", Fa)):
        _check(name, v, positive=False)
    if D <= d:
        raise InputError(f"D: the outside diameter must exceed the bore {d}, got {D}")
    c = _series(series)
    d_m = 0.5 * (d + D)
    n = _rpm(omega)
    g_rr = skf_rolling_variable(series, d_m, Fr, Fa, omega, C0)
    g_sl = skf_sliding_variable(series, d_m, Fr, Fa, omega, C0)
    phi_ish = skf_inlet_shear_factor(omega, d_m, nu)
    phi_rs = skf_replenishment_factor(omega, nu, d, D, c["K_z"], K_rs)
    mu_sl = skf_sliding_coefficient(omega, nu, d_m, mu_ehl)
    m_rr = phi_ish * phi_rs * g_rr * (nu * 1e6 * n) ** 0.6 * 1e-3
    m_sl = g_sl * mu_sl * 1e-3
    m_drag = skf_drag_moment(omega, nu, d, D, c["K_z"], oil_level, V_M)
    return {"rolling": m_rr, "sliding": m_sl, "drag": m_drag, "total": m_rr + m_sl + m_drag,
            "phi_ish": phi_ish, "phi_rs": phi_rs, "mu_sl": mu_sl}


# ----------------------------------------------------------------------------------------------------
# Palmgren (catalogue units inside: N mm, r/min, mm^2/s, mm)
# ----------------------------------------------------------------------------------------------------
def palmgren_viscous_moment(omega, nu, d_m, f0):
    """Palmgren's load-independent (viscous) friction moment M_0 [N m] [4]_:

    M_0 = 1e-7 f_0 (nu n)^(2/3) d_m^3 [N mm]  for nu n >= 2000,   160e-7 f_0 d_m^3  below,

    n [r/min], nu [mm^2/s], d_m [mm]. ``f0`` by bearing type and lubrication
    ([1]_ ch. 6 table; deep groove ball bearings about 1 (oil mist), 1.5-2
    (oil bath), 0.7-2 (grease), up to 4 with oil jet or a vertical shaft;
    single-row angular contact 2 (oil bath)). Quoted from [1]; a second
    copy of the table was not found.
    """
    vn = nu * 1e6 * _rpm(omega)
    dm = d_m * 1e3
    m = np.where(vn >= 2000.0, 1e-7 * f0 * np.abs(vn) ** (2.0 / 3.0) * dm ** 3, 160e-7 * f0 * dm ** 3)
    m = np.where(vn == 0.0, 0.0, m)
    return (m if np.ndim(m) else float(m)) * 1e-3


def palmgren_load_factor(P0, C0, z, y):
    """Palmgren's load factor f_1 = z (P_0 / C_0)^y [-] [4]_ ([1]_ ch. 6 table: deep groove ball
    bearings z = 0.0004-0.0006, y = 0.55; single-row angular contact z = 0.001, y = 0.33)."""
    return z * (P0 / C0) ** y


def palmgren_load_moment(f1, P1, d_m):
    """Palmgren's load-dependent friction moment M_1 = f_1 P_1 d_m [N m] [4]_ (P_1 [N]: F_r, or
    3 F_a - 0.1 F_r if larger, for deep groove; F_a - 0.1 F_r for single-row angular contact)."""
    return f1 * P1 * d_m
