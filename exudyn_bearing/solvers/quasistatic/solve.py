"""``solve_quasistatic``: ring equilibrium, ball equilibrium and ball kinematics together.

Procedure (Jones [1]_, Harris & Kotzalas [2]_; Gupta [3]_ for the minimum
energy):

1. geometry at the operating point (:mod:`.geometry`);
2. start from pure-rolling kinematics at the free contact angle;
3. repeat until the orbital and ball speeds stop changing (relative 1e-10):
   centrifugal force m omega_m^2 r_c and gyroscopic moment
   J omega_m w_r per ball from the current kinematics; ring and ball
   equilibrium (:mod:`.ring`, :mod:`.balls`); contact ellipses and films;
   race-control kinematics of every ball (:mod:`.kinematics`);
4. with ``control="min-energy"``: the same loop with the minimum-energy
   kinematics, from the race-control solution, until the speeds change by
   less than 1e-7 (the minimiser's resolution);
5. slip, traction and dissipation of every contact, the stiffness matrix
   (:mod:`.stiffness`), the contacts' normal damping and the equivalent
   damping matrix (:mod:`.damping`) and the checks (shoulder, convergence,
   minimum).

Choices where the sources leave room (also in docs/theory/quasistatic.md):
balls are independent (each its own orbital speed: no cage, as the
ACBB-120), unless ``cage="rigid"`` (all balls at the cage's speed, pocket forces and the cage's torque
balance: docs/theory/quasistatic.md#the-rigid-cage); unloaded balls (a contact without load) take outer-race-control
kinematics (with ``control="equilibrium"``: the cage's orbital speed, the mean of the balls in
equilibrium, rolling on the outer race, as every ball without a traction equilibrium of its own); films by Hamrock & Dowson at the race-control rolling speed.

References
----------
.. [1] A. B. Jones, J. Basic Eng. 82 (1960) 309-320. doi:10.1115/1.3662587
.. [2] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed.,
   CRC Press, 2006.
.. [3] P. K. Gupta, Tribol. Trans. (2020).
"""
from __future__ import annotations

import math
import time
import warnings
from contextlib import contextmanager

import numpy as np
from scipy import optimize as _opt

from ...data import (MAX_FREE_CONTACT_ANGLE, BallBearing, InputError, Lubricant, get_traction_model, load_bearing,
                     load_lubricant)
from ..._jit import kernel
from ...data.cages import RigidCage, estimated_cage
from ...data.errors import check_bool, check_finite, check_nonnegative, check_temperatures
from ...physics import ehl
from ...physics import hertz as _hz
from ...physics import kinematics as _kin
from ...physics import losses as _ls
from ...data.traction import DEFAULT_REGULARIZING_SRR, regularized
from ...physics.contact_slip import (DEFAULT_N_ACROSS, DEFAULT_N_STRIPS, MAX_N_ACROSS, MAX_N_STRIPS, check_resolution,
                                     deformed_contact_radius)
from ...physics.geometry import _raceway_radii_cos
from ...physics.load_distribution import check_axial_load
from ...physics.losses import LOSS_FLOOR_MU
from ...physics import short_bearing as _sb
from ...physics.short_bearing import short_bearing_load_number, short_bearing_shear_torque
from . import kinematics as km
from .balls import B_CR, B_CZ, B_DI, B_DO, B_NIR, B_NIZ, B_NOR, B_NOZ, B_QI, B_QO, ring_forces
from ...model.load_range import MAX_CONTACT_PRESSURE, check_load_estimate, check_pressures, pressure_excess
from ...model.operating_geometry import operating_geometry
from ...model.scenario import cage_model as _cage_model
from ...model.scenario import rolling_speed_floor as _rolling_floor
from .damping import condensed_matrices, contact_damping
from .inertia import ball_mass_inertia, check_ball_inertia
from .pocket_film import PocketFilm
from .ring import DOF_NAMES, LOAD_NAMES, RingProblem, solve_ring
from .solution import QuasiStaticSolution
from .stiffness import stiffness_matrix

__all__ = ["solve_quasistatic", "beta_scan", "check_operating_fit", "check_traction_resolution",
           "TractionResolutionWarning", "RESOLUTION_TOLERANCE", "MAX_OPERATING_INTERFERENCE"]

#: Largest relative change of the total dissipation when the strips and the points across are doubled that
#: counts as converged: the criterion of ``python validation/studies/traction_convergence.py`` (1 %).
RESOLUTION_TOLERANCE = 0.01


#: Iterations of race control's kinematics with half steps after its plain ones where they left a change above
#: UNSETTLED_WARNING times the tolerance (a cycling fixed point). The equilibrium and minimum-energy stages
#: keep their plain iterations (half steps there made the pocket film's case diverge).
RELAXED_ITERATIONS = 40
#: Race control that has not settled after its half steps warns when its last change exceeds this many times
#: its tolerance.
UNSETTLED_WARNING = 100.0


class KinematicsIterationWarning(UserWarning):
    """The quasi-static solver's iteration between the ring equilibrium and the ball kinematics did not settle:
    the solution is its last iterate."""


class TractionResolutionWarning(UserWarning):
    """The traction integration over the contact ellipses (``n_strips`` x ``n_across``) is coarser than the
    dissipation's convergence needs (:func:`check_traction_resolution`)."""


#: Largest held displacement of the inner ring (``fixed``), as a fraction of the ball radius: the
#: contacts of a ring moved further leave the elastic range long before (overlaps of 1 % R_b).
MAX_HELD_DISPLACEMENT = 0.1


#: DOFs ``solve_quasistatic`` holds when ``fixed`` is None: the tilts at zero (one rule in every entry point).
HELD_TILT = {"tilt_x": 0.0, "tilt_y": 0.0}


def _check_fixed(fixed, b, moments=(0.0, 0.0)):
    """``fixed`` as a dict DOF name -> float, each value finite and within
    ``MAX_HELD_DISPLACEMENT`` R_b (tilts: times the groove radius), else InputError naming ``fixed.DOF``.
    None: :data:`HELD_TILT`, refused with a moment load ``moments`` (Mx, My), which needs the free tilt."""
    if fixed is None:
        for name, m in zip(("Mx", "My"), moments):
            if m != 0.0:
                raise InputError(f"{name}: a moment load needs the free tilt; the default holds the tilt at zero "
                                 "(pass fixed={} to free it, as the CLI's --tilt free)")
        return dict(HELD_TILT)
    if not isinstance(fixed, dict):
        raise InputError(f"fixed: expected a dict of DOF name -> value, got {fixed!r}")
    out = {}
    limit = MAX_HELD_DISPLACEMENT * b.ball_radius
    arm = math.hypot(*b.inner_groove_center)
    for k, v in fixed.items():
        if k not in DOF_NAMES:
            raise InputError(f"fixed: unknown DOF {k!r} (valid: {', '.join(DOF_NAMES)})")
        v = check_finite(f"fixed.{k}", v)
        tilt = k.startswith("tilt")
        if abs(v) * (arm if tilt else 1.0) > limit:
            bound = f"{limit / arm:.3g} rad" if tilt else f"{limit:.3g} m"
            raise InputError(f"fixed.{k}: {v:g} {'rad' if tilt else 'm'} moves the inner ring by more than "
                             f"{MAX_HELD_DISPLACEMENT:g} R_b (|{k}| <= {bound}); the contacts would leave the elastic "
                             + ("range (angles are in radians)" if tilt else "range (lengths are in metres: "
                                f"{v:g} um is {v * 1e-6:g} m)"))
        out[k] = v
    return out


def _interference_cause(b, w_i, w_o, ring_growth, fit, temperatures, limit):
    """The input that alone closes the clearance beyond ``limit`` (fit, temperatures), else the speed: the
    inner ring's (``omega``) where its growth alone does it, else the outer ring's (``omega_outer``)."""
    if fit > 0.0 and operating_geometry(b, 0.0, 0.0, False, fit, None).operating_clearance < limit:
        return "fit"
    if temperatures and operating_geometry(b, 0.0, 0.0, False, 0.0, temperatures).operating_clearance < limit:
        return "temperatures"
    if w_o == 0.0 or operating_geometry(b, w_i, 0.0, ring_growth, 0.0, None).operating_clearance < limit:
        return "omega"
    return "omega_outer"


#: Largest operating interference accepted, -P_d,op / 2 over the ball radius: the balls no longer fit
#: between the grown rings beyond it (the contacts would leave the elastic range).
MAX_OPERATING_INTERFERENCE = 0.01


def check_operating_fit(b, omega, omega_outer=0.0, ring_growth=True, fit=0.0, temperatures=None):
    """The operating geometry (:func:`~exudyn_bearing.model.operating_geometry.operating_geometry`) of ``b``
    at the ring speeds [rad/s], the shaft fit [m] and the part temperatures [K]; InputError naming the input
    that closes the clearance (``omega``, ``omega_outer``, ``fit`` or ``temperatures``) when the operating
    interference exceeds 2 MAX_OPERATING_INTERFERENCE R_b (diametral): the speed limit of every command
    (quasistatic, stiffness, info)."""
    geom = operating_geometry(b, omega, omega_outer, ring_growth, fit, temperatures)
    limit = -2.0 * MAX_OPERATING_INTERFERENCE * geom.r_b
    if geom.operating_clearance < limit:
        cause = _interference_cause(b, omega, omega_outer, ring_growth, fit, temperatures, limit)
        why = {"fit": f"shaft fit {fit:g} m", "temperatures": f"thermal growth at {temperatures} K"}.get(
            cause, f"centrifugal ring growth at omega = {omega:g} rad/s ({omega * 30.0 / math.pi:.4g} rpm), "
                   f"omega_outer = {omega_outer:g} rad/s")
        raise InputError(f"{cause}: the operating interference {-geom.operating_clearance:.3e} m ({why}) exceeds 2 % "
                         f"of the ball radius: the balls do not fit between the grown rings; reduce {cause}")
    return geom


@contextmanager
def axial_load_as_fa():
    """InputErrors of the block about ``axial_load`` (physics.load_distribution's name) named ``Fa``, the
    argument of solve_quasistatic and the command line's --Fa."""
    try:
        yield
    except InputError as exc:
        if not str(exc).startswith("axial_load:"):
            raise
        raise InputError("Fa:" + str(exc).removeprefix("axial_load:")) from None


def _contact_state(geom, balls, e_prime, method):
    """Hertz ellipse (a, b, p_max, kappa, R_x) of both contacts of every ball."""
    z = balls.shape[0]
    res = {k: np.zeros(z) for k in ("a_o", "b_o", "p_o", "k_o", "rx_o", "a_i", "b_i", "p_i", "k_i", "rx_i")}
    for j in range(z):
        nor, nir = balls[j, B_NOR], balls[j, B_NIR]
        r_ref = geom.rho_o + (geom.r_co - geom.r_b) * nor
        for tag, r_c, ca, inner, d in (("o", geom.r_co, nor, False, balls[j, B_DO]),
                                       ("i", geom.r_ci, -nir, True, balls[j, B_DI])):
            ca = max(ca, 1e-12)
            r_contact = r_ref - geom.r_b * ca if inner else r_ref + geom.r_b * ca
            rx, ry = _raceway_radii_cos(geom.r_b, r_c, r_contact, ca, inner)
            q, _k, kap, a, b, pm, _kn = _hz._hertz(rx, ry, e_prime, max(d, 0.0), method)
            # a: across rolling (the major axis for ball / groove contacts)
            res[f"a_{tag}"][j], res[f"b_{tag}"][j], res[f"p_{tag}"][j] = a, b, pm
            res[f"k_{tag}"][j], res[f"rx_{tag}"][j] = kap, rx
    return res


def solve_quasistatic(bearing, Fr=0.0, Fa=0.0, Mx=0.0, My=0.0, *, Fy=0.0, omega=0.0, omega_outer=0.0,
                      control="auto", traction=None, lubricant: Lubricant | str | None = None,
                      ring_growth=True, fit=0.0, temperatures=None, fixed=None, hertz_method="exact",
                      phase=0.0, n_strips=DEFAULT_N_STRIPS, n_across=DEFAULT_N_ACROSS,
                      traction_regularizing_srr=DEFAULT_REGULARIZING_SRR, rolling_speed_floor=None,
                      shoulder_angle=MAX_FREE_CONTACT_ANGLE, stiffness=True, start=None,
                      resolution_check=True, cage=None, rigid_cage=None, inertia_check=True,
                      pocket_film=False, land_feedback=False) -> QuasiStaticSolution:
    """Quasi-static equilibrium of a ball bearing with free inner-ring DOFs, speed effects and kinematics.

    Parameters
    ----------
    bearing : BallBearing or str
        Geometry (catalogue name or JSON file); its ``diametral_clearance``
        (negative: preload) applies.
    Fr, Fy, Fa : float
        Loads on the inner ring [N]: radial along +x (psi = 0) and +y, axial along +z.
    Mx, My : float
        Moments on the inner ring about x and y [N m].
    omega, omega_outer : float
        Inner- and outer-ring speeds [rad/s] (outer ring fixed by default).
    control : {"auto", "outer", "inner", "min-energy", "equilibrium"}
        Ball kinematics: race control (Jones; ``auto`` by his spin-moment
        criterion), minimum frictional dissipation (Gupta) or the traction
        equilibrium of every ball (no kinematic hypothesis).
    traction : str or TractionModel, optional
        Traction model for slip, dissipation and the minimum energy
        (default: the bearing's, :func:`exudyn_bearing.data.default_traction`).
    lubricant : Lubricant or str, optional
        For the film thicknesses: a Lubricant, catalogue name, JSON file or
        dict (default: the bearing's, :func:`exudyn_bearing.data.default_lubricant`).
    ring_growth : bool
        Centrifugal growth of the rotating rings (False: rigid rings).
    fit : float
        Diametral interference of the inner ring on a solid shaft [m].
    temperatures : dict, optional
        ``{"inner", "outer", "ball"}`` temperatures [K] for uniform thermal growth.
    fixed : dict, optional
        DOFs to hold, name -> value (names ``delta_x, delta_y, delta_a,
        tilt_x, tilt_y``); their reactions are reported. Default (None):
        the tilts held at zero (:data:`HELD_TILT`, as the CLI's ``--tilt
        fixed`` and the dynamic engines' translating ring); ``fixed={}``
        frees every DOF (moment loads need their tilt free).
    hertz_method : str
        Hertz fidelity level.
    phase : float
        Azimuth of ball 0 [rad].
    n_strips, n_across : int
        Strip integration of slip and traction over each ellipse (defaults:
        :data:`~exudyn_bearing.physics.contact_slip.DEFAULT_N_STRIPS` x
        ``DEFAULT_N_ACROSS``, the same in the dynamic engines).
    traction_regularizing_srr : float
        Slide-to-roll ratio below which a Coulomb-type traction law without
        its own regularisation rises linearly (as in the dynamic engines:
        :data:`~exudyn_bearing.data.traction.DEFAULT_REGULARIZING_SRR`; 0
        keeps it discontinuous).
    rolling_speed_floor : float, optional
        Least rolling speed [m/s] of the slide-to-roll ratio the traction
        law sees. Default (None): the dynamic engines' ellipse-level floor,
        :func:`~exudyn_bearing.model.scenario.rolling_speed_floor` (0.1 m/s,
        but at most half the kinematic inner rolling speed, so that a
        steady state keeps its slide-to-roll ratios); 0 takes the rolling
        speed itself. A floor above the rolling speeds lowers the traction
        and the dissipation: the 6208 at 1 rad/s rolls at 0.015 m/s, and
        0.1 m/s cut its dissipation five-fold
        (``python validation/consistency/anomaly_checks.py``).
    shoulder_angle : float
        Largest angle from the groove bottom that a contact ellipse may reach [rad].
    stiffness : bool
        Compute the 5x5 stiffness matrix and the equivalent damping matrix
        (:mod:`.damping`).
    start : QuasiStaticSolution, optional
        A solution of the same bearing at a nearby operating point (e.g. the
        previous speed of a sweep): its ring pose and its ball speeds, scaled
        by the ratio of the ring speeds, start the iteration (a failed warm
        ring solve is retried from the bracketed start).
    resolution_check : bool
        Check the traction integration at the solution (:func:`check_traction_resolution`: a
        :class:`TractionResolutionWarning` when doubling ``n_strips`` and ``n_across`` changes the
        dissipation by more than 1 %); its result is the solution's ``resolution_check``.
    cage : {None, "none", False, "rigid"}
        None (or "none", False, as :class:`~exudyn_bearing.model.scenario.Scenario` spells it): no cage,
        each ball its own orbital speed; "torus" is refused (a dynamic model); "auto" is "rigid" when
        ``rigid_cage`` is given, else no cage. ``"rigid"``: a rigid cage
        (docs/theory/quasistatic.md#the-rigid-cage): every ball at the cage's
        orbital speed, a pocket force per ball balancing its tractions along the
        orbit, the cage speed from the cage's torque balance (pocket forces, pocket
        friction, land shear). With race control, ``"equilibrium"`` and
        ``"min-energy"`` (each held ball's spin minimises its contacts' dissipation
        at the cage speed).
    rigid_cage : RigidCage, optional
        Geometry, material and pocket friction of the rigid cage (default:
        :func:`~exudyn_bearing.data.cages.estimated_cage` of the bearing, as the
        dynamic engines).
    inertia_check : bool
        Check that the balls can follow the solution's kinematics along the orbit
        (:func:`~exudyn_bearing.solvers.quasistatic.inertia.check_ball_inertia`: a
        :class:`~exudyn_bearing.solvers.quasistatic.inertia.BallInertiaWarning` when the
        slip power of their changes of speed from one ball position to the next exceeds
        1 % of the dissipation); its result is the solution's ``inertia_check``.
    pocket_film : bool
        The oil film between each ball and its rigid-cage pocket (docs/theory/quasistatic.md#the-pocket-film,
        as the dynamic engines' ``Scenario(pocket_film=True)``; :mod:`.pocket_film`): its shear on the balls'
        rotation relative to the cage enters the balls' and the cage's balances and the pocket loss, its
        hydrodynamic pressure carries the pocket force where it can (the friction acts on the rest). Needs
        ``cage="rigid"``; the film's oil is ``lubricant``.
    land_feedback : bool
        Feed the land-guided cage's steady displacement on its land back into the pocket play
        (docs/theory/quasistatic.md#the-cages-displacement): the pockets move with the cage, so the balls meet
        their walls elsewhere and the net pocket force the land carries changes; solved by pseudo-transient
        continuation, a ``CageLandWarning`` and the solution without it when that does not converge or the
        cage's torque does not balance with it (the cage's ``land_feedback_converged``); the displacement's
        roots at the solution surveyed from 17 starts, a ``CageLandWarning`` when more than one (the cage's
        ``land_feedback_roots``). Off by default (the solution with the centred cage's pockets); needs a
        land-guided ``cage="rigid"``.

    Returns
    -------
    QuasiStaticSolution

    Examples
    --------
    >>> import exudyn_bearing as eb
    >>> s = eb.solve_quasistatic("6208", Fr=3000.0)
    >>> round(s.q_max_inner, 1)
    1461.7
    """
    call = dict(locals())  # the arguments, for the solve without the land feedback where it does not converge
    t0 = time.perf_counter()
    b: BallBearing = load_bearing(bearing)
    # argument checks: one path for API and CLI (data.errors: no booleans or strings as numbers)
    loads = np.array([check_finite(k, v) for k, v in (("Fr", Fr), ("Fy", Fy), ("Fa", Fa), ("Mx", Mx), ("My", My))])
    w_i = check_finite("omega", omega)
    w_o = check_finite("omega_outer", omega_outer)
    if control not in km.CONTROLS:
        raise InputError(f"control: must be one of {', '.join(km.CONTROLS)}, got {control!r}")
    rc = _check_cage(cage, rigid_cage, control, b)
    pocket_film = check_bool("pocket_film", pocket_film)
    land_feedback = check_bool("land_feedback", land_feedback)
    if land_feedback and (rc is None or rc.guidance == "ball"):
        raise InputError("land_feedback: the cage's displacement on its guiding land is a land-guided rigid cage's "
                         "(cage='rigid' with guidance 'outer_land' or 'inner_land')")
    if pocket_film and rc is None:
        raise InputError("pocket_film: the film between ball and pocket is the rigid cage's (cage='rigid'), "
                         "not for a cageless solution")
    srr = check_finite("traction_regularizing_srr", traction_regularizing_srr)
    if rolling_speed_floor is None:  # the dynamic engines' floor (one function for every solver)
        u_min = _rolling_floor(b, w_i, w_o)
    else:
        u_min = check_nonnegative("rolling_speed_floor", rolling_speed_floor)
    if not 0.0 <= srr <= 1.0:
        raise InputError(f"traction_regularizing_srr: must lie in [0, 1], got {srr:g}")
    # None: the bearing's traction model (catalogue), else the DEM papers'; Coulomb-type laws regularised
    model = regularized(get_traction_model(traction, b), srr)
    lub = load_lubricant(lubricant, bearing=b)
    n_strips, n_across = check_resolution(n_strips, n_across)  # one range in every solver and command
    resolution_check = check_bool("resolution_check", resolution_check)
    method = _hz.method_code(hertz_method)
    phase = check_finite("phase", phase)
    ring_growth = check_bool("ring_growth", ring_growth)
    stiffness = check_bool("stiffness", stiffness)
    fit = check_nonnegative("fit", fit)
    temperatures = check_temperatures(temperatures)
    shoulder_angle = check_finite("shoulder_angle", shoulder_angle)
    if not 0.0 < shoulder_angle <= 0.5 * math.pi:
        raise InputError(f"shoulder_angle: must lie in (0, pi/2] rad, got {shoulder_angle:g}")
    fixed = _check_fixed(fixed, b, (loads[3], loads[4]))
    # the same case at rest, to tell a refusal the speed causes from one the loads cause (_speed_cause)
    rest = dict(fixed=fixed, hertz_method=hertz_method, phase=phase, fit=fit, temperatures=temperatures,
                shoulder_angle=shoulder_angle, lubricant=lub, cage=cage, rigid_cage=rigid_cage)
    angular = b.free_contact_angle > 0.0
    fr = math.hypot(loads[0], loads[1])
    if angular and "delta_a" not in fixed:
        if loads[2] < 0.0:
            raise InputError(f"Fa: an angular-contact bearing carries axial load along +z only, got {loads[2]:g} N")
        with axial_load_as_fa():
            check_axial_load(b, fr, loads[2])
        if loads[2] == 0.0:
            raise InputError("Fa: a single angular-contact bearing needs an axial load to locate its inner ring "
                             "axially (got 0 N; or hold delta_a with fixed=)")
    # loads far beyond the elastic contact model, before the solve (which may not converge there)
    check_load_estimate(b, fr, loads[2], hertz_method)
    what = f"F_r = {fr:g} N, F_a = {loads[2]:g} N at omega = {w_i:g} rad/s"
    geom = check_operating_fit(b, w_i, w_o, ring_growth, fit, temperatures)
    film = PocketFilm.of(rc, lub, geom.r_b) if pocket_film else None
    e_prime = _hz.material_reduced_modulus(b.material)
    z = b.n_balls
    psi = phase + 2.0 * math.pi * np.arange(z) / z

    # DOFs held: by the caller, or by symmetry where the equations are singular
    held, values = {}, np.zeros(5)
    for k, v in fixed.items():
        held[k] = "fixed"
        values[DOF_NAMES.index(k)] = v
    deep = abs(geom.z_i) < 1e-15 and abs(geom.z_o) < 1e-15
    if deep and loads[2] == 0.0 and loads[3] == 0.0 and loads[4] == 0.0:
        for k in ("delta_a", "tilt_x", "tilt_y"):
            held.setdefault(k, "symmetry")
    if fr == 0.0 and loads[3] == 0.0 and loads[4] == 0.0 and not fixed:
        for k in ("delta_x", "delta_y", "tilt_x", "tilt_y"):
            held.setdefault(k, "symmetry")
    free = np.array([k not in held for k in DOF_NAMES])
    if (loads == 0.0).all() and b.diametral_clearance >= 0.0 and not angular and w_i == w_o:
        free[:] = False
        for k in DOF_NAMES:
            held.setdefault(k, "symmetry")

    # kinematics: start at pure rolling at the free contact angle
    a0 = b.free_contact_angle
    wm0 = float(_kin.cage_speed(w_i, w_o, geom.r_b, b.pitch_radius, a0))
    wr0 = float(_kin.ball_spin_relative(w_i, w_o, geom.r_b, b.pitch_radius, a0))
    # ball angular velocity w_R (-sin alpha, cos alpha) in the orbit frame
    # (orbital speed, w_r, w_z, transverse pivot slip v_t: zero but for the equilibrium stage)
    kin = np.tile([wm0, -wr0 * math.sin(a0), wr0 * math.cos(a0), 0.0], (z, 1))
    moving = w_i != w_o
    mass, inertia = ball_mass_inertia(b, geom.r_b)
    rd_o = float(deformed_contact_radius(geom.r_b, geom.r_co))
    rd_i = float(deformed_contact_radius(geom.r_b, geom.r_ci))
    wref = max(abs(w_i - w_o), 1e-300)
    u = values.copy()
    controls = np.array(["outer"] * z, dtype=object)
    checks = [None] * z
    cold = True
    if start is not None:
        if not isinstance(start, QuasiStaticSolution):
            raise InputError(f"start: expected a QuasiStaticSolution, got {type(start).__name__}")
        if start.bearing_name != b.name or np.asarray(start.balls["psi"]).size != z:
            raise InputError(f"start: a solution of {start.bearing_name} cannot start {b.name}")
        u = np.where(free, start.displacement, values)
        cold = False
        w_start = start.omega - start.omega_outer
        if moving and start.kinematics is not None and w_start != 0.0:
            kin = np.array(start.kinematics, float) * ((w_i - w_o) / w_start)
    it_total = 0
    phases = ["race"] + ([control] if control in ("min-energy", "equilibrium") and moving else [])
    prob = balls = geo = cs = cage_info = None
    loaded_all = np.zeros(z, dtype=bool)
    settled, refused = False, None  # the last stage's loop converged; why the land feedback was not taken
    try:  # a singular ring or kinematics system: loads far beyond what the contacts carry
        for stage in phases:
            settled = False
            # the rigid cage: 1e-9, as its energy balance, the held and free balls mixed by the fractions of the
            # last cage balance, amplifies the last change (the traction's creep stiffness): at 1e-7 the 6208
            # radial case closed it to 1.9e-8, with the land feedback to 2.3e-8 at 1e-8; at 1e-9 to 4e-11, 6e-12
            tol = 1e-10 if stage == "race" else (1e-7 if rc is None else 1e-9)
            plain = 40 if stage == "race" else 12
            for _it in range(plain + (RELAXED_ITERATIONS if stage == "race" else 0)):
                it_total += 1
                g_mom = inertia * kin[:, 0] * kin[:, 1]        # J omega_m w_r: moment about e_psi [N m]
                fto = np.zeros(z)
                fti = np.zeros(z)
                for j in range(z):
                    if stage == "equilibrium":
                        # the transverse tractions the traction model gives at the current kinematics
                        c = km.ball_contacts(kin[j], geo[j], model, n_strips, n_across)
                        fto[j], fti[j] = c[0, 7], c[1, 7]
                    elif stage == "min-energy":
                        fto[j] = fti[j] = 0.5 * g_mom[j] / geom.r_b
                    elif controls[j] == "inner":
                        fti[j] = g_mom[j] / geom.r_b
                    else:
                        fto[j] = g_mom[j] / geom.r_b
                prob = RingProblem(psi, geom, mass * kin[:, 0] ** 2, fto, fti, e_prime, method, loads)
                u, resid, balls = solve_ring(prob, free, values, u, b, cold=cold)
                cold = False
                cs = _contact_state(geom, balls, e_prime, method)
                if not moving:  # no race turns relative to the other: the balls turn with both rings as one body
                    kin[:] = (w_i, 0.0, 0.0, 0.0)
                    break
                new = kin.copy()
                geo = np.zeros((z, len(km.GEO_FIELDS)))
                for j in range(z):
                    geo[j] = _geo_vector(w_o, w_i, balls[j], geom, rd_o, rd_i, cs, j, kin[j], lub, e_prime, u_min)
                    loaded = balls[j, B_QO] > 0.0 and balls[j, B_QI] > 0.0
                    race = control if control in ("outer", "inner") else (
                        "outer" if (not loaded or km.jones_outer_controls(geo[j])) else "inner")
                    if rc is not None:  # the cage's balance below, all balls together
                        loaded_all[j] = loaded
                        controls[j] = race if loaded else "outer"
                        continue
                    if stage == "race":
                        controls[j] = race if loaded else "outer"
                        new[j, :3] = km.race_control(geo[j], controls[j])
                    elif stage == "equilibrium":
                        if not loaded:
                            controls[j], checks[j] = "cage", None
                            continue
                        same = _alike(geo, j)
                        if same is not None:
                            new[j], checks[j] = new[same], checks[same]
                        else:
                            new[j], checks[j] = km.traction_equilibrium(geo[j], model, n_strips, n_across, kin[j],
                                                                        inertia)
                        controls[j] = "equilibrium" if checks[j]["converged"] else "cage"
                    elif loaded:
                        controls[j] = "min-energy"
                        same = _alike(geo, j)
                        if same is not None:
                            new[j], checks[j] = new[same], checks[same]
                        else:
                            new[j, :3], checks[j] = km.minimum_energy(geo[j], model, n_strips, n_across, kin[j])
                if rc is not None:
                    # the land feedback in the last stage only (the earlier one is the start of its iterations)
                    new, cage_info = _solve_cage(geo, loaded_all, controls.copy(), stage, kin, rc, model, n_strips,
                                                 n_across, inertia, lub, w_i, w_o, psi, film,
                                                 land_feedback and stage == phases[-1])
                    controls[:] = cage_info["controls"]
                    feedback = cage_info.get("land_feedback")
                    refused = None if feedback is None or feedback["converged"] else feedback["why"]
                    if stage in ("equilibrium", "min-energy"):
                        checks = list(cage_info["checks"])
                elif stage == "equilibrium":
                    _carry_by_cage(new, controls, geo)
                change = np.abs(new - kin).max() / wref
                # past the plain iterations (a fixed point that cycles, as the caged ACBB-120 under race control
                # between two cage speeds 10 % apart): half steps, which keep the fixed point and damp the cycle
                kin = new if _it < plain else kin + 0.5 * (new - kin)
                if change < tol:
                    settled = True
                    break
                if _it == plain - 1 and change <= UNSETTLED_WARNING * tol:
                    break  # near the stage's own precision (min-energy's minimisation): no half steps
    except np.linalg.LinAlgError:
        speed = _speed_cause(b, loads, w_i, w_o, rest)
        raise InputError(f"{speed or _load_name(loads, fixed)}: the quasi-static equilibrium is singular at {what} "
                         "(no ring pose or ball kinematics carries it): "
                         + (_SPEED_CAUSE if speed else "loads this far exceed the limit of the elastic contact "
                            f"model, {MAX_CONTACT_PRESSURE / 1e9:g} GPa (ISO 76 static load rating): reduce the "
                            "load")) from None
    except InputError as exc:  # the ring equilibrium did not converge (solve_ring names the largest load)
        speed = _speed_cause(b, loads, w_i, w_o, rest)
        if speed is None and loads.any():
            raise
        raise InputError(f"{speed or _load_name(loads, fixed)}: {str(exc).partition(': ')[2]} at {what}"
                         + (f"; {_SPEED_CAUSE}" if speed else "")) from None
    if moving and not settled and stage == "race" and change > UNSETTLED_WARNING * max(tol, 1e-300):
        warnings.warn(KinematicsIterationWarning(
            f"control: the ball kinematics did not settle at {what} ({control}"
            + (", rigid cage" if rc is not None else "") + f"): after {_it + 1} iterations of its last stage "
            f"({stage}) the speeds still changed by {change:.2g} of the ring speed (tolerance {tol:g}); the "
            "solution is the last iterate"), stacklevel=2)
    if land_feedback and moving and (refused is not None or not settled):
        # the land feedback not taken at the end, or the iterations not settled with it (the cage speed jumping
        # between the balance with it and without): the whole solution without it, and it says so
        why = refused or (f"the iterations with it did not settle: the speeds still changed by {change:.2g} "
                          f"(relative) after {_it + 1} iterations of the last stage")
        sol = solve_quasistatic(**{**call, "land_feedback": False})
        sol.cage["land_feedback_converged"] = False
        warnings.warn(CageLandWarning(
            f"rigid_cage: the cage's displacement on its land and the pocket play it shifts did not converge ({why}): "
            "the solution is the one without the feedback (the pockets of the centred cage, the land carrying their "
            "net force)"), stacklevel=2)
        return sol
    # final contact results
    out = _ball_results(b, geom, psi, balls, cs, kin, geo, model, n_strips, n_across, w_i, w_o, rd_o, rd_i,
                        lub, e_prime, mass, inertia, controls, moving, prob.fto, prob.fti)
    if rc is not None and moving and cage_info is not None and cage_info.get("free_kinematics") is not None:
        # pocket play: each ball's outputs the time mixture of the held ball (kin) and the free one
        f = cage_info["pocket_contact_fraction"]
        if np.any(f < 1.0):
            free_out = _ball_results(b, geom, psi, balls, cs, cage_info["free_kinematics"], geo, model, n_strips,
                                     n_across, w_i, w_o, rd_o, rd_i, lub, e_prime, mass, inertia, controls, moving,
                                     prob.fto, prob.fti)
            _mix_ball_results(out, free_out, f)
    cage_out = None if rc is None else _cage_result(rc, cage_info, out, moving, w_i, film)
    if control == "equilibrium" and moving and not np.any(controls == "equilibrium"):
        bad = next((j for j, c in enumerate(checks) if c is not None), 0)
        raise InputError(f"control: no ball reaches a traction equilibrium (ball {bad}: scaled residual "
                         f"{checks[bad]['residual'] if checks[bad] else float('nan'):.2g}); the traction model "
                         "may be too steep or too weak to hold the balls: try more regularisation, or "
                         "control='min-energy'")
    over = _shoulder_excess(geom, balls, cs, shoulder_angle)
    if over is not None:
        speed = _speed_cause(b, loads, w_i, w_o, rest)
        raise InputError(f"{speed or _largest_load(loads, prob)}: {over} at {what}: "
                         + (_SPEED_CAUSE if speed else "the load puts the contact over the shoulder"))
    # the elastic-contact limit on the load sharing found (one ball may carry more than the estimate)
    name = _load_name(loads, fixed)
    if pressure_excess(out["p_max_inner"], out["p_max_outer"]) is not None:
        name = _speed_cause(b, loads, w_i, w_o, rest) or name
    check_pressures(out["p_max_inner"], out["p_max_outer"], name, what)
    # normal damping of every contact (the contact model's, at its load and film) and the 5x5 matrices
    out.update(contact_damping(balls, cs["a_i"], cs["a_o"], out["h_min_inner"], out["h_min_outer"], geom.r_b,
                               b.material.hysteretic_damping, lub))
    if stiffness:
        kmat, kcheck = stiffness_matrix(prob, u, balls)
        k_cond, cmat = condensed_matrices(psi, geom, u, balls, prob.m_w2, prob.fto, prob.fti,
                                          out["c_normal_inner"], out["c_normal_outer"])
        w = np.array([1.0, 1.0, 1.0, 1.0 / prob.arm, 1.0 / prob.arm])
        kw = kmat * np.outer(w, w)
        kcheck["condensed_difference"] = float(np.abs(k_cond * np.outer(w, w) - kw).max()
                                               / max(np.abs(kw).max(), 1e-300))
    else:
        kmat, kcheck = np.full((5, 5), np.nan), {}
        cmat = np.full((5, 5), np.nan)
    resid = prob.residual(u)[0]
    reactions = {k: float(-resid[DOF_NAMES.index(k)]) for k in held}
    rho_i, z_i = b.inner_groove_center
    rho_o, z_o = b.outer_groove_center
    geometry = {"inner_ring_growth": geom.inner_ring_growth, "outer_ring_growth": geom.outer_ring_growth,
                "inner_thermal_growth": geom.inner_thermal_growth, "outer_thermal_growth": geom.outer_thermal_growth,
                "ball_thermal_growth": geom.ball_thermal_growth, "fit_pressure": geom.fit_pressure,
                "operating_clearance": geom.operating_clearance, "axial_play": _axial_play(geom),
                "diametral_clearance": b.diametral_clearance}
    sol = QuasiStaticSolution(
        bearing_name=b.name, loads=loads, omega=w_i, omega_outer=w_o, control=control, traction=model.name,
        lubricant=lub.name, displacement=u, residual=resid, free=free, held=held, reactions=reactions, balls=out,
        geometry=geometry, stiffness=kmat, stiffness_check=kcheck, damping=cmat,
        minimum_checks=[c for c in checks] if control in ("min-energy", "equilibrium") else [], iterations=it_total,
        n_strips=n_strips, n_across=n_across, wall_s=time.perf_counter() - t0,
        contact_geometry=geo, kinematics=kin, traction_model=model, cage=cage_out)
    if moving and geo is not None:
        sol.geometry_at = _geometry_at(psi, u, geom, mass, kin, prob.fto, prob.fti, e_prime, method, rd_o, rd_i,
                                       lub, u_min, w_i, w_o)
    if resolution_check:
        sol.resolution_check = check_traction_resolution(sol)
    if inertia_check:
        sol.inertia_check = check_ball_inertia(sol, b)
    return sol


def _dissipation_at(sol, n_strips, n_across):
    """Total dissipation [W] of ``sol``'s contacts, kinematics held, integrated over n_strips x n_across."""
    return float(sum(km.ball_contacts(sol.kinematics[j], sol.contact_geometry[j], sol.traction_model, n_strips,
                                      n_across)[:, 9].sum() for j in range(sol.kinematics.shape[0])))


def check_traction_resolution(sol, tolerance=RESOLUTION_TOLERANCE, warn=True) -> dict | None:
    """Is the traction integration of ``sol`` (its ``n_strips`` x ``n_across``) converged in the dissipation?

    The dissipation of the solution's contacts, its ball kinematics held, is integrated again with twice the
    strips and twice the points across (each at most MAX_N_STRIPS, MAX_N_ACROSS); a relative change above
    ``tolerance`` (1 %, the criterion of ``validation/studies/traction_convergence.py``) is a
    :class:`TractionResolutionWarning` (``warn``) with the resolution from which doubling changes it by
    less: the estimate of what the case needs (the first such level of the doublings, or the default
    DEFAULT_N_STRIPS x DEFAULT_N_ACROSS when it passes the same test with fewer points). A change below
    1e-9 of the rolling-power scale sum Q |u_roll| over the contacts (round-off), and dissipations below
    the loss floor LOSS_FLOOR_MU F r_p max(|omega - omega_outer|, 1 rad/s) (the dynamic summaries' floor;
    F the applied |F_r| + |F_a|, or the outer contacts' load sum if larger: an unloaded bearing's
    centrifugal loads; a loss no one uses, e.g. 6e-5 W of an unloaded 6208 at 500 rad/s against 0.13 W),
    count as converged. The kinematics of ``control="min-energy"`` or ``"equilibrium"`` also follow the
    integration; this check holds them, so its
    estimate is the least resolution needed. A solution without relative speed (no contact geometry)
    and one at the largest resolution return None.

    Returns {"n_strips", "n_across", "dissipation" [W], "doubled" (n_strips, n_across), "dissipation_doubled"
    [W], "change" (relative), "converged", "needed" (n_strips, n_across) or None}.
    """
    if sol.contact_geometry is None or sol.kinematics is None:
        return None
    levels = [(sol.n_strips, sol.n_across)]
    while True:
        ns, na = levels[-1]
        nxt = (min(2 * ns, MAX_N_STRIPS), min(2 * na, MAX_N_ACROSS))
        if nxt == (ns, na):
            break
        levels.append(nxt)
    if len(levels) == 1:
        return None
    geo = sol.contact_geometry
    scale = float(np.sum(geo[:, km.G_QO] * np.abs(sol.balls["u_roll_outer"]))
                  + np.sum(geo[:, km.G_QI] * np.abs(sol.balls["u_roll_inner"])))
    # below the loss floor (LOSS_FLOOR_MU (|F_r| + |F_a|) r_p max(|omega|, 1 rad/s), the dynamic summaries'
    # floor) a dissipation is no result anyone uses: its relative change is not judged
    # the load: the applied one, or (an unloaded bearing at speed) the outer contacts' centrifugal loads
    loads = max(abs(float(sol.loads[0])) + abs(float(sol.loads[2])), float(np.sum(geo[:, km.G_QO])))
    pitch_radius = float(np.mean(sol.balls["ball_center_r"]))
    floor = 1e-9 * scale
    negligible = LOSS_FLOOR_MU * loads * pitch_radius * max(abs(sol.omega - sol.omega_outer), 1.0)

    def close(p, q):
        return abs(q - p) <= max(tolerance * abs(q), floor) or max(abs(p), abs(q)) < negligible

    p = [_dissipation_at(sol, *levels[0]), _dissipation_at(sol, *levels[1])]
    change = (p[1] - p[0]) / p[1] if p[1] != 0.0 else 0.0
    ok = close(p[0], p[1])
    needed = levels[0] if ok else None
    k = 1
    while needed is None and k + 1 < len(levels):
        p.append(_dissipation_at(sol, *levels[k + 1]))
        if close(p[k], p[k + 1]):
            needed = levels[k]
        k += 1
    default = (DEFAULT_N_STRIPS, DEFAULT_N_ACROSS)
    if not ok and default not in levels[:k] and (needed is None or default[0] * default[1] < needed[0] * needed[1]):
        if close(_dissipation_at(sol, *default), _dissipation_at(sol, 2 * default[0], 2 * default[1])):
            needed = default  # the default, off the path of doublings, is converged and cheaper
    out = {"n_strips": levels[0][0], "n_across": levels[0][1], "dissipation": p[0], "doubled": levels[1],
           "dissipation_doubled": p[1], "change": float(change), "converged": bool(ok), "needed": needed}
    if not ok and warn:
        need = (f"about {needed[0]} x {needed[1]} (n_strips={needed[0]}, n_across={needed[1]}; the command line's "
                f"--strips {needed[0]} --points-across {needed[1]})" if needed else
                f"more than {MAX_N_STRIPS} x {MAX_N_ACROSS}, the largest accepted")
        warnings.warn(TractionResolutionWarning(
            f"n_strips, n_across: the dissipation changes by {100 * change:+.3g} % ({p[0]:.4g} W at {levels[0][0]} x "
            f"{levels[0][1]}, {p[1]:.4g} W at {levels[1][0]} x {levels[1][1]}) when the strips and points across "
            f"of the traction integration are doubled, more than {100 * tolerance:g} %: converged from {need} "
            f"(default {DEFAULT_N_STRIPS} x {DEFAULT_N_ACROSS}; kinematics held, so this is the least needed)"),
            stacklevel=3)
    return out


def beta_scan(solution: QuasiStaticSolution, betas, ball=0):
    """Least dissipation of one ball [W] at each spin-axis angle in ``betas`` [rad], over its
    orbital and ball speed, on the solution's contact geometry (Gupta's Fig. 9 curve).

    Returns an array of the dissipation of that ball (both contacts) for each beta.
    """
    if solution.contact_geometry is None:
        raise InputError("solution: a beta scan needs a solution at speed (omega != omega_outer)")
    g = solution.contact_geometry[ball]
    start = solution.kinematics[ball]
    return np.array([km.dissipation_at_beta(g, solution.traction_model, solution.n_strips, solution.n_across,
                                            float(bt), start)[0] for bt in np.asarray(betas, float)])


def _carry_by_cage(kin, controls, geo):
    """Balls without a traction equilibrium of their own (``controls`` "cage": a contact without load,
    which nothing drives, or a gyroscopic moment that the traction of its loads cannot hold) orbit at the
    mean orbital speed of the balls in equilibrium, the speed a cage would impose, rolling on the outer
    race (:func:`.kinematics.cage_kinematics`); in place. Their outer-contact dissipation is what the cage
    would draw from the balls in equilibrium, which a cageless balance does not carry: it shows in
    ``energy_residual``."""
    cage = controls == "cage"
    if not cage.any() or cage.all():
        return
    omega_cage = float(np.mean(kin[~cage, 0]))
    for j in np.flatnonzero(cage):
        kin[j] = km.cage_kinematics(geo[j], omega_cage)


def _geo_vector(w_o, w_i, ball, geom, rd_o, rd_i, cs, j, kin, lub, e_prime, u_min=0.0):
    """Packed per-ball geometry for :mod:`.kinematics` (films at the current rolling speeds; ``u_min`` the
    least rolling speed of the traction law)."""
    g = np.zeros(len(km.GEO_FIELDS))
    g[km.G_UMIN] = u_min
    g[km.G_WO], g[km.G_WI] = w_o, w_i
    g[km.G_CR], g[km.G_CZ] = ball[B_CR], ball[B_CZ]
    g[km.G_NOR], g[km.G_NOZ], g[km.G_NIR], g[km.G_NIZ] = ball[B_NOR], ball[B_NOZ], ball[B_NIR], ball[B_NIZ]
    g[km.G_RB], g[km.G_RDO], g[km.G_RDI] = geom.r_b, rd_o, rd_i
    g[km.G_AO], g[km.G_BO], g[km.G_QO] = cs["a_o"][j], cs["b_o"][j], ball[B_QO]
    g[km.G_AI], g[km.G_BI], g[km.G_QI] = cs["a_i"][j], cs["b_i"][j], ball[B_QI]
    c = km.ball_contacts(kin, g, _DUMMY, 1, 1)
    for k, tag in ((0, "o"), (1, "i")):
        u_r = c[k, 3]
        q = ball[B_QO] if k == 0 else ball[B_QI]
        rx, kap = cs[f"rx_{tag}"][j], cs[f"k_{tag}"][j]
        kap = kap if kap >= 1.0 else 1.0 / kap
        hc = float(ehl.film_thickness_central_hamrock_dowson(u_r, q, rx, kap, e_prime, lub.viscosity,
                                                             lub.pressure_viscosity))
        hm = float(ehl.film_thickness_hamrock_dowson(u_r, q, rx, kap, e_prime, lub.viscosity,
                                                     lub.pressure_viscosity))
        if k == 0:
            g[km.G_HCO], g[km.G_HMO] = hc, hm
        else:
            g[km.G_HCI], g[km.G_HMI] = hc, hm
    return g


_DUMMY = get_traction_model("coulomb_0.1")


def _geometry_at(psi_b, u, geom, mass, kin, fto, fti, e_prime, method, rd_o, rd_i, lub, u_min, w_i, w_o):
    """The function psi -> contact geometry rows (len(psi), len(GEO_FIELDS)) of balls at the azimuths psi [rad]
    under the ring pose ``u``: each ball's own equilibrium between the rings (:func:`.balls.ring_forces`) with
    the centrifugal force and the tractions' transverse forces of the solution's balls (``kin``, ``fto``,
    ``fti`` at their azimuths ``psi_b``, linear between them), the Hertz ellipses and films as the solution's
    (:func:`_contact_state`, :func:`_geo_vector`). At ``psi_b`` it gives the solution's rows."""
    z = psi_b.size
    tab = np.column_stack([kin, fto, fti])
    psi0 = float(psi_b[0])

    def at(psi):
        psi = np.atleast_1d(np.asarray(psi, float))
        x = np.mod(psi - psi0, 2.0 * math.pi) * z / (2.0 * math.pi)
        i = np.floor(x).astype(int) % z
        f = (x - np.floor(x))[:, None]
        row = (1.0 - f) * tab[i] + f * tab[(i + 1) % z]
        k = row[:, :4]
        _gen, balls = ring_forces(u, psi, geom, mass * k[:, 0] ** 2, row[:, 4].copy(), row[:, 5].copy(), e_prime,
                                  method)
        cs = _contact_state(geom, balls, e_prime, method)
        return np.array([_geo_vector(w_o, w_i, balls[j], geom, rd_o, rd_i, cs, j, k[j], lub, e_prime, u_min)
                         for j in range(psi.size)])
    return at


def _axial_play(geom):
    """Axial shift between the two positions where a ball touches both grooves [m] (rings concentric,
    operating geometry); 0 with interference."""
    a = geom.groove_distance
    dr = geom.rho_i - geom.rho_o
    if abs(dr) >= a:
        return 0.0
    return 2.0 * math.sqrt(a * a - dr * dr)


def _ball_results(b, geom, psi, balls, cs, kin, geo, model, n_strips, n_across, w_i, w_o, rd_o, rd_i, lub,
                  e_prime, mass, inertia, controls, moving, fto, fti):
    z = psi.size
    out = {"psi": psi, "q_inner": balls[:, B_QI].copy(), "q_outer": balls[:, B_QO].copy(),
           "alpha_inner": np.arctan2(-balls[:, B_NIZ], -balls[:, B_NIR]),
           "alpha_outer": np.arctan2(balls[:, B_NOZ], balls[:, B_NOR]),
           "a_inner": cs["a_i"], "b_inner": cs["b_i"], "a_outer": cs["a_o"], "b_outer": cs["b_o"],
           "p_max_inner": cs["p_i"], "p_max_outer": cs["p_o"],
           "delta_inner": balls[:, B_DI].copy(), "delta_outer": balls[:, B_DO].copy(),
           "ball_center_r": balls[:, B_CR].copy(), "ball_center_z": balls[:, B_CZ].copy()}
    out["centrifugal_force"] = mass * kin[:, 0] ** 2 * balls[:, B_CR]
    out["gyroscopic_moment"] = inertia * kin[:, 0] * kin[:, 1]
    out["orbital_speed"] = kin[:, 0].copy()
    out["pivot_slip"] = kin[:, 3].copy()
    out["ball_speed"] = np.hypot(kin[:, 1], kin[:, 2])
    out["ball_speed_absolute"] = np.hypot(kin[:, 1], kin[:, 2] + kin[:, 0])
    out["beta"] = np.array([km.spin_axis_angle(kin[j, 1], kin[j, 2]) for j in range(z)])
    names = ("spin_roll_inner", "spin_roll_outer", "rolling_point_outer", "rolling_point_inner",
             "dissipation_inner_ball", "dissipation_outer_ball", "qv_inner_ball", "qv_outer_ball",
             "traction_drag", "gyro_traction_inner", "gyro_traction_outer", "h_central_inner", "h_central_outer", "h_min_inner",
             "h_min_outer", "u_roll_inner", "u_roll_outer", "drive_torque_inner_ball", "drive_torque_outer_ball")
    for n in names:
        out[n] = np.zeros(z)
    ys = -1.0 + (2.0 * np.arange(n_strips) + 1.0) / n_strips
    out["slip_y"] = ys
    out["slip_inner"] = np.zeros((z, n_strips))
    out["slip_outer"] = np.zeros((z, n_strips))
    out["control_used"] = np.array(controls if moving else ["none"] * z, dtype=object)
    if not moving:
        out["beta"][:] = 0.0
        return out
    for j in range(z):
        c = km.ball_contacts(kin[j], geo[j], model, n_strips, n_across)
        for k, tag in ((0, "outer"), (1, "inner")):
            v0, wn, c2, u_r, spin, roll = c[k, :6]
            out[f"spin_roll_{tag}"][j] = spin / abs(roll) if roll != 0.0 else math.nan
            out[f"dissipation_{tag}_ball"][j] = c[k, 9]
            out[f"qv_{tag}_ball"][j] = c[k, 10]
            out[f"u_roll_{tag}"][j] = u_r
            a = geo[j, km.G_AO] if k == 0 else geo[j, km.G_AI]
            y = a * ys
            out[f"slip_{tag}"][j] = v0 - wn * y + c2 * y * y
        x1, x2 = km.rolling_points(c, geo[j])
        out["rolling_point_outer"][j], out["rolling_point_inner"][j] = x1, x2
        out["traction_drag"][j] = c[0, 6] + c[1, 6]
        for k, tag, nr, nz in ((0, "outer", geo[j, km.G_NOR], geo[j, km.G_NOZ]),
                               (1, "inner", geo[j, km.G_NIR], geo[j, km.G_NIZ])):
            out[f"drive_torque_{tag}_ball"][j] = km.axial_torque_on_ball(c[k], geo[j, km.G_CR], geo[j, km.G_RB], nr, nz)
        # friction coefficient the hypothesis asks of each race to hold the gyroscopic moment
        out["gyro_traction_outer"][j] = abs(fto[j]) / balls[j, B_QO] if balls[j, B_QO] > 0 else 0.0
        out["gyro_traction_inner"][j] = abs(fti[j]) / balls[j, B_QI] if balls[j, B_QI] > 0 else 0.0
        out["h_central_outer"][j], out["h_min_outer"][j] = geo[j, km.G_HCO], geo[j, km.G_HMO]
        out["h_central_inner"][j], out["h_min_inner"][j] = geo[j, km.G_HCI], geo[j, km.G_HMI]
    return out


#: Outputs of _ball_results that depend on a ball's kinematics (the time mixture of the pocket play).
_KINEMATIC_OUTPUTS = ("centrifugal_force", "gyroscopic_moment", "orbital_speed", "pivot_slip", "ball_speed",
                      "ball_speed_absolute", "beta", "spin_roll_inner", "spin_roll_outer", "rolling_point_outer",
                      "rolling_point_inner", "dissipation_inner_ball", "dissipation_outer_ball", "qv_inner_ball",
                      "qv_outer_ball", "traction_drag", "u_roll_inner", "u_roll_outer", "drive_torque_inner_ball",
                      "drive_torque_outer_ball", "slip_inner", "slip_outer")


def _mix_ball_results(out, free_out, f):
    """``out`` (the held balls) becomes the time mean f held + (1 - f) free of every kinematic output; a ball
    held all the time (f = 1) keeps its values as they are (NaN included)."""
    for k in _KINEMATIC_OUTPUTS:
        held, free = np.asarray(out[k], float), np.asarray(free_out[k], float)
        w = f.reshape((-1,) + (1,) * (held.ndim - 1))
        out[k] = np.where(w >= 1.0, held, w * held + (1.0 - w) * free)


def _load_name(loads, fixed):
    """The input to name when the contacts leave the elastic range: the largest load (N and N m as given),
    else the held DOFs or the speed."""
    if np.any(loads != 0.0):
        return LOAD_NAMES[int(np.argmax(np.abs(loads)))]
    return "fixed" if fixed else "omega"


def _shoulder_excess(geom, balls, cs, limit) -> str | None:
    """Where a loaded contact ellipse reaches past the groove shoulder (text), else None."""
    for tag, qk, nr, nz, r_c, sgn in (("inner", B_QI, B_NIR, B_NIZ, geom.r_ci, -1.0),
                                      ("outer", B_QO, B_NOR, B_NOZ, geom.r_co, 1.0)):
        alpha = np.arctan2(sgn * balls[:, nz], sgn * balls[:, nr])
        half = cs[f"a_{tag[0]}"] / r_c
        reach = np.abs(alpha) + half
        bad = (balls[:, qk] > 0.0) & (reach > limit)
        if bad.any():
            j = int(np.argmax(np.where(bad, reach, -1.0)))
            return (f"the {tag} contact ellipse of ball {j} reaches {math.degrees(reach[j]):.1f} deg from the groove "
                    f"bottom (contact angle {math.degrees(alpha[j]):.1f} deg + half-width "
                    f"{math.degrees(half[j]):.1f} deg) > shoulder {math.degrees(limit):.0f} deg")
    return None


def _largest_load(loads, prob):
    """The name of the largest load (moments over the groove-centre arm), as the solver names a load."""
    arm = prob.arm if prob is not None else 1.0
    return LOAD_NAMES[int(np.argmax(np.abs(loads) * np.array([1, 1, 1, 1 / arm, 1 / arm])))]


def _speed_cause(b, loads, w_i, w_o, rest) -> str | None:
    """``"omega"`` (``"omega_outer"`` with the inner ring at rest) when the speed causes a refusal: the same
    loads at rest (``rest``: the other arguments of solve_quasistatic) pass every check of the solver; else
    None (the loads alone are refused, or there is no speed)."""
    if w_i == 0.0 and w_o == 0.0:
        return None
    try:
        solve_quasistatic(b, loads[0], loads[2], loads[3], loads[4], Fy=loads[1], omega=0.0, omega_outer=0.0,
                          stiffness=False, resolution_check=False, **rest)
    except InputError:
        return None
    return "omega" if w_i != 0.0 else "omega_outer"


#: Why a refusal names the speed: the same loads at rest pass.
_SPEED_CAUSE = ("the speed causes it (centrifugal force, gyroscopic moment and ring growth; the same loads at "
                "rest are carried): reduce the speed")


#: Relative tolerance of the cage speed in the cage's torque balance (brentq's xtol over the speed scale).
CAGE_SPEED_TOLERANCE = 1e-13


class CageLandWarning(UserWarning):
    """The rigid cage's land film cannot carry the net pocket force within the crush eccentricity: the land
    touches (the reference engine's rigid cage models that contact; the quasi-static solution does not); or the
    cage's displacement on the land and the pocket play it shifts did not converge (:func:`_land_feedback`)."""


def _check_cage(cage, rigid_cage, control, b):
    """The RigidCage of ``cage`` / ``rigid_cage`` (None: cageless), or InputError naming the argument. ``cage``
    is spelt as :class:`~exudyn_bearing.model.scenario.Scenario`'s (None, False and "none" are no cage), and
    the models this solver does not have are refused by name."""
    cage = _cage_model(cage)
    if cage == "auto":
        cage = "rigid" if rigid_cage is not None else "none"
    if cage == "none":
        if rigid_cage is not None:
            raise InputError("rigid_cage: given without cage='rigid'; it is the geometry of the rigid cage")
        return None
    if cage != "rigid":
        raise InputError(f"cage: the quasi-static solver has no {cage!r} cage (the torus cage's cage balls are a "
                         f"dynamic model); use 'rigid' or None (no cage)")
    if rigid_cage is None:
        return estimated_cage(b)
    if not isinstance(rigid_cage, RigidCage):
        raise InputError(f"rigid_cage: expected a RigidCage (exudyn_bearing.data.cages), got "
                         f"{type(rigid_cage).__name__}")
    rigid_cage.check_fits(b)
    if rigid_cage.pocket_spacing_error != 0.0:
        raise InputError("rigid_cage: its pocket_spacing_error (unequal pockets) is not for the quasi-static solver, "
                         "which sees one ball at every azimuth of equally spaced pockets; run it in the dynamic "
                         "engines (eb.simulate(..., Scenario(rigid_cage=...)))")
    return rigid_cage


def _land_state(rc, lub, omega_c, omega_ring, force):
    """Eccentricity, shear torque on the cage [N m] and crush flag of the land film of ``rc`` carrying the
    net in-plane pocket force ``force`` [N] at the cage speed ``omega_c`` and its guiding ring's
    ``omega_ring``: eps from Ocvirk's steady load (W = W_bar(eps) mu (omega_c + omega_ring) R L^3 / (4 c^2),
    :func:`~exudyn_bearing.physics.short_bearing.short_bearing_load_number`), at most the crush eccentricity
    eps_c = max(0.5, 1 - sigma / c) of the reference engine; the torque
    :func:`~exudyn_bearing.physics.short_bearing.short_bearing_shear_torque` at that eps (docs/theory/cage.md)."""
    mu, r, length, c = lub.viscosity, rc.guide_radius, rc.land_width, rc.land_clearance
    eps_c = max(0.5, 1.0 - lub.composite_roughness / c)
    scale = mu * abs(omega_c + omega_ring) * r * length ** 3 / (4.0 * c * c)
    crushed = False
    tiny = 1e-12  # W_bar(eps) ~ pi eps near the centre
    if force <= scale * float(short_bearing_load_number(tiny)):
        eps = 0.0
    elif scale * float(short_bearing_load_number(eps_c)) <= force:
        eps, crushed = eps_c, True
    else:
        eps = _opt.brentq(lambda e: scale * float(_sb._load_number(e)) - force, tiny, eps_c, xtol=1e-14)
    torque = float(short_bearing_shear_torque(eps, omega_c - omega_ring, mu, r, length, c))
    return eps, torque, crushed


def _land_displacement(rc, lub, omega_c, omega_ring, fx, fy):
    """The cage centre's steady displacement (e_x, e_y) [m] from its guiding land's centre at which the land
    film carries the net in-plane pocket force (``fx``, ``fy``) [N] on the cage, with :func:`_land_state`'s
    (eps, torque, crushed): eps = |e| / c from Ocvirk's load number (:func:`_land_state`), and e at the short
    bearing's attitude angle phi, tan phi = pi sqrt(1 - eps^2) / (4 eps) (Ocvirk; Hamrock et al., ch. 10),
    from the pocket force, ahead in the sense of ``omega_c`` + ``omega_ring``: there the reference engine's
    land force at zero rates (:func:`~exudyn_bearing.physics.short_bearing.short_bearing_force_xy`) is
    -(fx, fy). Crushed (eps at the crush eccentricity): the direction at that eps. With no film force (no
    speed) e is along (fx, fy)."""
    eps, torque, crushed = _land_state(rc, lub, omega_c, omega_ring, math.hypot(fx, fy))
    if eps == 0.0:
        return 0.0, 0.0, eps, torque, crushed
    c, spin = rc.land_clearance, omega_c + omega_ring
    turn = math.atan2(fy, fx) + (0.0 if spin == 0.0 else math.copysign(float(_sb._attitude(eps)), spin))
    return eps * c * math.cos(turn), eps * c * math.sin(turn), eps, torque, crushed


#: Tolerance of the cage's displacement on its land (:func:`_land_feedback`): the residual |G(F(e)) - e| of
#: its balance below this share of the land clearance (the steep F(e) leaves the last Newton steps at a few 1e-9:
#: the 6208 at 3000 N radial, race control, stalled at 3e-9 against 1e-10).
LAND_FEEDBACK_TOLERANCE = 1e-8
#: Relative residual of the cage's torque (:func:`_cage_balance`) above which the balance with the land
#: feedback is not taken (the torque jumped between roots of the displacement at the cage speed found).
LAND_FEEDBACK_TORQUE_TOLERANCE = 1e-9
#: Pseudo-transient steps of :func:`_land_feedback` before its fallback.
LAND_FEEDBACK_STEPS = 60
#: Iterations of the damped fixed point that is :func:`_land_feedback`'s fallback.
LAND_FEEDBACK_ITERATIONS = 400


def _relax(land, v, r, limit, c, best, tol):
    """Pseudo-transient continuation of v' = R(v) for :func:`_land_feedback` (its ``land``: G of e [m]; v = e /
    c, r = R(v) / c), LAND_FEEDBACK_STEPS steps at most, until ``best`` (the best residual, kept by ``land``)
    meets ``tol``."""
    dt = 1.0
    for _ in range(LAND_FEEDBACK_STEPS):
        h = 1e-7
        jac = np.empty((2, 2))
        for k in range(2):
            w = v.copy()
            w[k] += h
            gk = land(w[0] * c, w[1] * c)
            jac[:, k] = ((np.array(gk[:2]) / c - w) - r) / h
        try:
            w = v + np.linalg.solve(np.eye(2) / dt - jac, r)
        except np.linalg.LinAlgError:
            return
        size = float(np.hypot(*w))
        if size > limit:
            w *= limit / size
        gw = land(w[0] * c, w[1] * c)
        if best[0] <= tol:
            return
        rw = np.array(gw[:2]) / c - w
        norm, new = float(np.hypot(*r)), float(np.hypot(*rw))
        if new > 2.0 * norm:
            dt *= 0.25
            continue
        dt = min(dt * norm / max(new, 1e-300), 1e12)
        v, r = w, rw


def _land_feedback(rc, lub, omega_c, omega_ring, net_force, start=(0.0, 0.0), alone=False):
    """The cage's displacement e on its land balanced with the net pocket force it causes
    (docs/theory/quasistatic.md#the-cages-displacement): the root of R(e) = G(F(e)) - e, F = ``net_force(e)``
    the net in-plane pocket force [N] (the pocket play with the pockets displaced by e . e_psi), G the land's
    displacement that carries it (:func:`_land_displacement`). R is continuous and G stays inside the crush
    circle, so a root exists there (Brouwer), but the fixed point e <- G(F(e)) is no contraction (its Jacobian's
    eigenvalues lie far outside the unit circle: a few um of displacement change the fractions by tens of %),
    and Newton's
    method stalls in local minima of |R| (the fractions' kinks): pseudo-transient continuation of the cage's
    overdamped relaxation de/dt = R(e) (implicit Euler steps whose step grows as |R| falls, ending in Newton's;
    Kelley & Keyes 1998) from ``start`` [m] (the root at the balls' mean speed, :func:`_solve_cage`), then from
    e = 0, the state
    without the feedback, each for LAND_FEEDBACK_STEPS; failing both, the
    damped fixed point e <- e + a R(e), a halved from 1 whenever |R| grows (to at least 2^-12), for
    LAND_FEEDBACK_ITERATIONS. Converged: |R| below LAND_FEEDBACK_TOLERANCE
    times the land clearance c; else the state without the feedback (e = 0, the land carrying F(0)), which
    the solution's CageLandWarning reports. A zero net force at e = 0 (a pure axial load) gives e = 0 at once. Returns
    (ex, ey, eps, torque, crushed, dict with converged, evaluations, residual [m]); eps, torque and crushed are
    the land's carrying F(e) (:func:`_land_displacement`). ``alone``: the continuation from ``start`` only (no
    second start, no fixed point; :func:`_land_roots`)."""
    c = rc.land_clearance
    tol = LAND_FEEDBACK_TOLERANCE * c
    count = [0]
    best = [math.inf, 0.0, 0.0, None]

    def land(x, y):
        count[0] += 1
        g = _land_displacement(rc, lub, omega_c, omega_ring, *net_force(x, y))
        res = math.hypot(g[0] - x, g[1] - y)
        if res < best[0]:
            best[:] = [res, x, y, g]
        return g

    def done():
        res, x, y, g = best
        if res > tol:  # not converged: the state without the feedback (the pockets at e = 0), and it says so
            x, y, g = 0.0, 0.0, g0
        return x, y, *g[2:], {"converged": res <= tol, "evaluations": count[0], "residual": res}

    g0 = land(0.0, 0.0)
    if best[0] <= tol:
        return done()
    # pseudo-transient continuation of the relaxation v' = R(v) / c, v = e / c (Kelley & Keyes, SIAM J. Numer.
    # Anal. 35 (1998) 508-523): implicit Euler steps (I / dt - J) dv = R / c, J by forward differences (step
    # 1e-7), dt from 1 grown by |R| falling (switched evolution relaxation) up to Newton's steps; a step that
    # more than doubles |R| is retaken at dt / 4; kept inside the crush circle
    limit = max(0.5, 1.0 - lub.composite_roughness / c)
    for first in dict.fromkeys(((start[0] / c, start[1] / c),) + (() if alone else ((0.0, 0.0),))):
        if first == (0.0, 0.0):
            v, r = np.zeros(2), np.array([g0[0], g0[1]]) / c
        else:
            v = np.array(first)
            gv = land(v[0] * c, v[1] * c)
            if best[0] <= tol:
                return done()
            r = np.array(gv[:2]) / c - v
        _relax(land, v, r, limit, c, best, tol)
        if best[0] <= tol:
            return done()
    if alone:
        return done()
    ex = ey = 0.0
    g, a, last = g0, 1.0, math.inf
    for _ in range(LAND_FEEDBACK_ITERATIONS):
        res = math.hypot(g[0] - ex, g[1] - ey)
        if res <= tol:
            break
        if res > last:
            a = max(0.5 * a, 2.0 ** -12)
        last = res
        ex, ey = ex + a * (g[0] - ex), ey + a * (g[1] - ey)
        g = land(ex, ey)
    return done()


#: The starts of :func:`_land_roots`: the centre and 8 azimuths at these eccentricities.
LAND_SURVEY_ECCENTRICITIES = (0.4, 0.8)
#: Two roots of :func:`_land_roots` are one where they lie closer than this share of the land clearance.
LAND_ROOT_SEPARATION = 1e-6


def _land_roots(rc, lub, omega_c, omega_ring, net_force, root):
    """The roots of the cage's displacement balance (:func:`_land_feedback`) at one cage speed reached from a
    survey of starts spread over the land clearance c (the centre and 8 azimuths at each of
    LAND_SURVEY_ECCENTRICITIES times c), each by the continuation from it alone; with the solution's ``root``
    [m] the distinct ones (apart by more than LAND_ROOT_SEPARATION c), as an (n, 2) array [m], ``root``
    first. More than one: the balance is not unique there, the solution's root the one its starts reach."""
    c = rc.land_clearance
    roots = [np.asarray(root, float)]
    starts = [(0.0, 0.0)] + [(eps * c * math.cos(a), eps * c * math.sin(a)) for eps in LAND_SURVEY_ECCENTRICITIES
                             for a in np.arange(8) * np.pi / 4.0]
    for st in starts:
        ex, ey, *_, info = _land_feedback(rc, lub, omega_c, omega_ring, net_force, st, alone=True)
        if info["converged"] and all(math.hypot(ex - r[0], ey - r[1]) > LAND_ROOT_SEPARATION * c for r in roots):
            roots.append(np.array([ex, ey]))
    return np.array(roots)


def pocket_net_force(q_p, f_r, psi):
    """(F_x, F_y) [N] of pocket forces on the cage: ``q_p`` along the orbit (+: the pocket pushes its ball
    forward, the cage takes -q_p e_psi) and ``f_r`` radial (on the cage) at the azimuths ``psi`` [rad], summed;
    the force its land carries (the solver's balls, the orbit march's steps)."""
    return (float(np.sum(q_p * np.sin(psi) + f_r * np.cos(psi))),
            float(np.sum(-q_p * np.cos(psi) + f_r * np.sin(psi))))


def _alike(geo, j):
    """The first ball before ``j`` whose contact geometry equals ball j's (rtol 1e-12: balls alike by symmetry,
    solved once), else None."""
    return next((i for i in range(j) if np.allclose(geo[i], geo[j], rtol=1e-12, atol=0.0)), None)


@kernel
def _first_wall(s, r, k, span, clearance):
    """The first time tau in (0, ``span``] at which the ball at ``s`` [m], moving at the rate r + k tau [m/s],
    reaches a wall at +-``clearance`` moving outward; -1 if none (:func:`_play_walls`)."""
    best = -1.0
    for wall in (clearance, -clearance):
        d = s - wall                                   # s(tau) - wall = d + r tau + k tau^2 / 2
        roots = (-1.0, -1.0)
        if k == 0.0:
            if r != 0.0:
                roots = (-d / r, -1.0)
        else:
            disc = r * r - 2.0 * k * d
            if disc >= 0.0:
                q = -0.5 * (r + math.copysign(math.sqrt(disc), r))    # the stable pair of roots
                roots = (q / (0.5 * k), d / q if q != 0.0 else -1.0)
        for tau in roots:
            rate = r + k * tau
            if 0.0 < tau <= span and rate * wall > 0.0 and (best < 0.0 or tau < best):
                best = tau
    return best


@kernel
def _play_walls(a, b, dt, start, s, clearance, on):
    """The play operator of :func:`pocket_contact_fraction` (compiled): the ball at ``s`` [m] from its pocket's
    centre moves at a rate linear in time over each sub-step of ``dt`` [s], from ``a`` to ``b`` [m/s], the walls
    at +-``clearance``; from sub-step ``start`` (cyclically) two revolutions, of which the second's time on a
    wall per sub-step goes to ``on``. Exact for that rate: the ball reaches a wall where its quadratic path does,
    and rests on it while the rate pushes it outward, leaving where the rate turns (so the time on a wall is
    continuous in the rates, which a rate constant over each sub-step would not make it at the instant it
    leaves)."""
    n = a.size
    for i in range(2 * n):
        m = (start + i) % n
        h = dt[m]
        k = (b[m] - a[m]) / h if h > 0.0 else 0.0
        t, held = 0.0, 0.0
        for _ in range(8):                             # at most a few segments per sub-step (the rate is linear)
            if t >= h:
                break
            r = a[m] + k * t
            side = 1.0 if s >= clearance else (-1.0 if s <= -clearance else 0.0)
            if side != 0.0 and (r * side > 0.0 or (r == 0.0 and k * side > 0.0)):
                turn = -a[m] / k if k != 0.0 else h    # on the wall until the rate turns inward
                end = turn if t < turn < h else h
                held += end - t
                s, t = side * clearance, end
                if end < h:                            # leaving: one free segment from the turn
                    r = 0.0
                    hit = _first_wall(s, r, k, h - t, clearance)
                    if hit < 0.0:
                        s += 0.5 * k * (h - t) ** 2
                        t = h
                    else:
                        s, t = math.copysign(clearance, k), t + hit
                continue
            hit = _first_wall(s, r, k, h - t, clearance)
            if hit < 0.0:                              # free to the sub-step's end
                s += r * (h - t) + 0.5 * k * (h - t) ** 2
                t = h
            else:
                s = clearance if r + k * hit > 0.0 else -clearance
                t += hit
        s = min(max(s, -clearance), clearance)
        if i >= n:
            on[m] = held


def pocket_contact_fraction(u, psi, omega_c, radius, clearance, substeps=64, offset=None):
    """Share of the time each ball rests on a pocket wall, the balls moving freely inside their pockets' play
    (docs/theory/quasistatic.md#pocket-play).

    A ball whose own orbital speed (its cageless equilibrium) differs from the cage's by ``u`` [rad/s] drifts
    along the orbit at ds/dt = ``radius`` u sign(omega_c) relative to its pocket's centre; the pocket stops it
    at s = +-``clearance`` [m] (a play operator: while it rests on a wall and u pushes it outward it moves with
    the cage, the pocket holding it at the cage's speed). ``u`` is sampled at the balls' azimuths ``psi`` [rad]
    (one ball seen at every azimuth: the quasi-static solution is steady in the cage's frame), linear between
    them, integrated over ``substeps`` steps per spacing, exactly for that rate linear in time
    (:func:`_play_walls`: the wall reached and left where the path and the rate say, so that the fraction is
    continuous in ``u``). The periodic solution: with a net drift D per
    revolution of the free path S(t), the ball rests on the front wall (D > 0; the back wall for D < 0) where S
    reaches its largest (smallest) value of the revolution, so the second revolution from there is periodic;
    with no net drift it floats when S spans less than the play 2 ``clearance``. Returns the fraction in [0, 1] per
    ball: the time on a wall within half a spacing either side of its azimuth.

    ``offset`` [m] (None: none): the pocket centre's displacement along e_psi (the +psi tangent) at each
    ball's azimuth, a displaced cage's e . e_psi(psi) (docs/theory/quasistatic.md#the-cages-displacement). The
    ball's position relative to its pocket is then S(t) minus that offset at its azimuth at time t (sampled
    as ``u``, linear between the azimuths); the offset is periodic, so the net drift D is unchanged."""
    u = np.asarray(u, float)
    z = u.size
    direction = 1.0 if omega_c >= 0.0 else -1.0
    ang_all = np.mod(direction * np.asarray(psi, float), 2.0 * np.pi)
    order = np.argsort(ang_all, kind="stable")
    ang = ang_all[order]
    gaps = np.diff(np.append(ang, ang[0] + 2.0 * np.pi))
    rate = radius * u[order] * direction                  # ds/dt [m/s] at each azimuth, in travel order
    x = (np.arange(substeps) + 0.5) / substeps
    x0, x1 = np.arange(substeps) / substeps, np.arange(1, substeps + 1) / substeps
    a = ((1.0 - x0)[None, :] * rate[:, None] + x0[None, :] * np.roll(rate, -1)[:, None])   # the rate at each
    b = ((1.0 - x1)[None, :] * rate[:, None] + x1[None, :] * np.roll(rate, -1)[:, None])   # sub-step's ends
    dt = np.repeat(gaps / max(abs(omega_c), 1e-300) / substeps, substeps)
    owner = np.where(x[None, :] < 0.5, np.arange(z)[:, None], (np.arange(z)[:, None] + 1) % z).ravel()
    if offset is not None:                                # the pocket's own motion along the travel, subtracted
        o = direction * np.asarray(offset, float)[order]
        moving = ((np.roll(o, -1) - o) * max(abs(omega_c), 1e-300) / gaps)[:, None]
        a, b = a - moving, b - moving
    a, b = a.ravel(), b.ravel()
    step = 0.5 * (a + b) * dt
    path = np.cumsum(step)                                # the free path S over one revolution
    on = np.zeros(a.size)
    if abs(path[-1]) > 1e-12 * clearance or np.ptp(np.append(path, 0.0)) > 2.0 * clearance:
        side = 1.0 if path[-1] >= 0.0 else -1.0
        start = int(np.argmax(path) if side > 0.0 else np.argmin(path)) + 1
        _play_walls(a, b, dt, start % a.size, side * clearance, clearance, on)
    time = np.bincount(owner, weights=dt, minlength=z)
    held = np.bincount(owner, weights=on, minlength=z)
    out = np.empty(z)
    out[order] = np.divide(held, time, out=np.ones(z), where=time > 0.0)
    return out


def _free_balls(geo, loaded, races, stage, kin, model, n_strips, n_across, inertia, film=None):
    """Each ball's own kinematics without the cage (z x 4; NaN rows for a ball without them: no inner load, or
    a traction equilibrium that does not converge): the traction equilibrium of a cageless ball, its minimum
    energy (stage "min-energy"), or race control by ``races[j]``. With the pocket ``film`` (a PocketFilm) the traction equilibrium has the moment of
    the film of a ball floating centred in its pocket, its rotation taken relative to the cage at the balls'
    present mean orbital speed (the cage's, once the iteration has converged)."""
    z = geo.shape[0]
    free = np.full((z, 4), np.nan)
    moment = None
    if film is not None and stage == "equilibrium":
        omega_c = float(np.mean(kin[:, 0]))

        def moment(wm, wr, wz, _q):
            c = film.centred(wr, wz + wm - omega_c)
            return 0.0, c["m_r"], c["m_z"]
    for j in range(z):
        if not loaded[j]:
            continue
        same = _alike(geo, j)
        if same is not None:
            free[j] = free[same]
        elif stage == "equilibrium":
            k, chk = km.traction_equilibrium(geo[j], model, n_strips, n_across, kin[j], inertia,
                                             pocket_film=moment)
            if chk["converged"]:
                free[j] = k
        elif stage == "min-energy":
            free[j, :3] = km.minimum_energy(geo[j], model, n_strips, n_across, kin[j])[0]
            free[j, 3] = 0.0
        else:
            free[j, :3] = km.race_control(geo[j], races[j])
            free[j, 3] = 0.0
    return free


def _caged_balls(omega_c, geo, loaded, races, stage, kin, rc, model, n_strips, n_across, inertia, lub, w_i, w_o,
                 psi, free=None, film=None, land_hint=None):
    """Every ball at the cage speed ``omega_c`` (docs/theory/quasistatic.md#the-rigid-cage): its kinematics
    (race control at the cage speed by ``races[j]``, the traction equilibrium of its moments with the pocket
    force and its friction, the minimum of its contacts' dissipation over its spin (stage "min-energy"), or,
    without an inner load, rolling on the outer race), its pocket force
    Q_p = -(F_x,o + F_x,i) and the cage's torque: sum_j (-Q_p,j c_r,j + mu_c |Q_p,j| R_b w_z,j / |w_j|) + the
    land's shear torque. With the pocket ``film`` (a PocketFilm; docs/theory/quasistatic.md#the-pocket-film)
    the friction acts on the contact force the film's pressure leaves, and the film's shear adds its moment to
    the balls' equilibrium and, reversed, the torque -M_z to the cage's. Returns (kin, dict of the cage's
    quantities)."""
    z = geo.shape[0]
    mu_c = rc.pocket_friction
    held_film = None
    if film is not None:
        def held_film(_wm, wr, wz, q):
            st = film.held(q, wr, wz)
            return st["contact_force"], st["m_r"], st["m_z"]
    new = kin.copy()
    q_p = np.zeros(z)
    checks = [None] * z
    used = np.array(["outer"] * z, dtype=object)
    for j in range(z):
        same = _alike(geo, j)
        if same is not None:
            new[j], q_p[j], checks[j], used[j] = new[same], q_p[same], checks[same], used[same]
            continue
        if stage == "equilibrium" and (geo[j, km.G_QO] > 0.0 or geo[j, km.G_QI] > 0.0):
            start = np.array([omega_c, kin[j, 1], kin[j, 2], kin[j, 3]])
            k, chk = km.traction_equilibrium(geo[j], model, n_strips, n_across, start, inertia, omega_m=omega_c,
                                             pocket_friction=mu_c, pocket_film=held_film)
            if chk["converged"]:
                new[j], q_p[j], checks[j], used[j] = k, chk["pocket_force"], chk, "equilibrium"
                continue
            checks[j] = chk
            used[j] = "cage"
        if stage == "min-energy" and loaded[j]:
            # Gupta's minimum over the ball's spin at the orbital speed its pocket imposes; the pocket carries the
            # tractions' net force along the orbit, as with race control
            new[j, :3], checks[j] = km.minimum_energy(geo[j], model, n_strips, n_across, kin[j], omega_m=omega_c)
            new[j, 3] = 0.0
            used[j] = "min-energy"
            c = km.ball_contacts(new[j], geo[j], model, n_strips, n_across)
            q_p[j] = -(c[0, 6] + c[1, 6])
            continue
        race = races[j] if loaded[j] and stage not in ("equilibrium", "min-energy") else "outer"
        if stage not in ("equilibrium", "min-energy"):
            used[j] = race
        new[j] = km.cage_kinematics(geo[j], omega_c, race)
        c = km.ball_contacts(new[j], geo[j], model, n_strips, n_across)
        q_p[j] = -(c[0, 6] + c[1, 6])
    # pocket play: a ball with an orbit of its own (free[j]) rests on a pocket wall only the fraction f of the
    # time (pocket_contact_fraction); the cage feels the time mean f Q_p of its force
    q_held = q_p.copy()
    cr = geo[:, km.G_CR]
    rb = geo[:, km.G_RB]
    w = np.hypot(new[:, 1], new[:, 2])
    wz_unit = np.divide(new[:, 2], w, out=np.zeros(z), where=w > 0.0)
    wr_unit = np.divide(new[:, 1], w, out=np.zeros(z), where=w > 0.0)
    has = np.zeros(z, bool) if free is None else np.isfinite(free[:, 0])
    u = np.where(has, free[:, 0] - omega_c, 0.0) if has.any() else None

    def pockets(ex, ey):
        """The pockets' state with the cage displaced by (ex, ey) [m] on its land: the fractions, the weighted
        pocket forces, the contact's part, the film's state, the radial force on the cage and the net force."""
        f = np.ones(z)
        if u is not None:
            offset = None if ex == 0.0 and ey == 0.0 else -ex * np.sin(psi) + ey * np.cos(psi)  # e . e_psi
            f = np.where(has, pocket_contact_fraction(u, psi, omega_c, float(np.mean(cr)), rc.pocket_clearance,
                                                      offset=offset), 1.0)
        q_p = f * q_held
        q_contact = q_p                                    # the part of the pocket force the wall's contact carries
        film_out = None
        if film is not None:
            q_contact, film_out = _pocket_film_state(film, new, q_held, f, omega_c, free)
        # the net in-plane force of the pockets on the cage: -Q_p e_psi and the friction's radial part
        s = -np.sign(q_p)                                  # side of the ball the wall touches, along e_psi
        f_r = -mu_c * np.abs(q_contact) * s * wz_unit      # radial friction on the cage
        if film_out is not None:  # the film's shear: its radial force, reversed
            f_r = f_r - film_out["f_r"]
        fx, fy = pocket_net_force(q_p, f_r, psi)
        return f, q_p, q_contact, film_out, fx, fy

    eps, t_land, crushed, w_ring, ex, ey, feedback = 0.0, 0.0, False, 0.0, 0.0, 0.0, None
    if rc.guidance != "ball":
        # the land carries the net pocket force at the cage's displacement e, which moves the pockets (the play)
        w_ring = w_o if rc.guidance == "outer_land" else w_i
        # the start: the first root found in this cage balance (``land_hint``), kept for every later cage speed so
        # that the torque is a function of the cage speed alone (R may have several roots)
        if land_hint is None:  # no feedback: the centred cage's pockets, the land carrying their net force
            eps, t_land, crushed = _land_state(rc, lub, omega_c, w_ring, math.hypot(*pockets(0.0, 0.0)[4:]))
        else:
            ex, ey, eps, t_land, crushed, feedback = _land_feedback(rc, lub, omega_c, w_ring,
                                                                    lambda x, y: pockets(x, y)[4:],
                                                                    land_hint.get("e", (0.0, 0.0)))
            if "e" not in land_hint:  # the first call's root (or e = 0 without one) starts every later one
                land_hint["e"] = (ex, ey) if feedback["converged"] else (0.0, 0.0)
            if feedback["converged"]:  # is it unique? asked of the solution's balance only (_cage_result)
                feedback["survey"] = lambda: _land_roots(rc, lub, omega_c, w_ring, lambda x, y: pockets(x, y)[4:],
                                                         (ex, ey))
    f, q_p, q_contact, film_out, fx, fy = pockets(ex, ey)
    t_normal = -q_p * cr
    t_friction = mu_c * np.abs(q_contact) * rb * wz_unit
    t_film = 0.0 if film_out is None else -film_out["m_z"]  # the film's moment about the axis, reversed
    torque = float(np.sum(t_normal) + np.sum(t_friction) + t_land)
    scale = float(np.sum(np.abs(t_normal)) + np.sum(np.abs(t_friction)) + abs(t_land))
    friction_power = np.atleast_1d(_ls.cage_pocket_friction_power(q_contact, w, 2.0 * rb, mu_c))
    film_power = np.zeros(z)
    if film_out is not None:
        torque += float(np.sum(t_film))
        scale += float(np.sum(np.abs(t_film)))
        film_power = film_out["power"]
    sliding = rb * w
    return new, {"speed": float(omega_c), "pocket_force": q_p, "pocket_sliding_speed": sliding,
                 "pocket_power_ball": friction_power + film_power, "pocket_film_power_ball": film_power,
                 "pocket_contact_force": np.asarray(q_contact, float),
                 "pocket_film_gap": None if film_out is None else film_out["gap"],
                 "land_torque": t_land,
                 "land_power": -t_land * (omega_c - w_ring), "land_eccentricity": eps, "land_crushed": crushed,
                 "land_force": math.hypot(fx, fy), "land_displacement": (ex, ey), "land_feedback": feedback,
                 "ring_speed": w_ring, "torque": torque,
                 "torque_scale": scale, "checks": checks, "controls": used,
                 "wr_unit": wr_unit, "pocket_contact_fraction": f, "pocket_force_held": q_held,
                 "free_kinematics": None if free is None else np.where(np.isfinite(free), free, new)}


def _pocket_film_state(film, kin, q_held, f, omega_c, free):
    """(contact force [N] per ball, dict of the film's time means per ball) of the pocket ``film`` (a
    PocketFilm) at the cage speed ``omega_c``: a ball held on its wall the share ``f`` of the time (the pocket
    play) with the pocket force ``q_held`` and the kinematics ``kin`` (w_r, w_z relative to the cage), floating
    centred the rest with its own kinematics ``free`` (rotation relative to the cage: w_r, w_z + omega_m -
    omega_c). The dict: f_r, m_z (the shear's radial force and axial moment on the ball), power [W] and the
    held ball's near gap [m]."""
    z = kin.shape[0]
    contact, f_r, m_z, power, gap = (np.zeros(z) for _ in range(5))
    for j in range(z):
        h = film.held(q_held[j], kin[j, 1], kin[j, 2])
        contact[j] = math.copysign(f[j] * h["contact_force"], q_held[j])
        f_r[j], m_z[j], power[j], gap[j] = f[j] * h["f_r"], f[j] * h["m_z"], f[j] * h["power"], h["gap"]
        if f[j] < 1.0:
            c = film.centred(free[j, 1], free[j, 2] + free[j, 0] - omega_c)
            f_r[j] += (1.0 - f[j]) * c["f_r"]
            m_z[j] += (1.0 - f[j]) * c["m_z"]
            power[j] += (1.0 - f[j]) * c["power"]
    return contact, {"f_r": f_r, "m_z": m_z, "power": power, "gap": gap}


def _solve_cage(geo, loaded, races, stage, kin, rc, model, n_strips, n_across, inertia, lub, w_i, w_o, psi,
                film=None, land_feedback=False):
    """The cage speed that balances the cage's torque (:func:`_caged_balls`; brentq on a bracket widened from
    the balls' present orbital speeds: the torque falls with the cage speed) and the balls at it; ``film``
    the pocket film (a PocketFilm) or None; ``land_feedback``: the cage's displacement on its land fed back into
    the pocket play (:func:`_land_feedback`)."""
    free = _free_balls(geo, loaded, races, stage, kin, model, n_strips, n_across, inertia, film)
    if not land_feedback:
        return _cage_balance(None, free, geo, loaded, races, stage, kin, rc, model, n_strips, n_across, inertia, lub,
                             w_i, w_o, psi, film)
    try:
        k, info = _cage_balance({}, free, geo, loaded, races, stage, kin, rc, model, n_strips, n_across, inertia, lub,
                                w_i, w_o, psi, film)
        feedback = info["land_feedback"]
        if feedback["converged"] and abs(info["torque_residual"]) <= LAND_FEEDBACK_TORQUE_TOLERANCE:
            return k, info
        why = (f"the cage's torque with the displacement fed back does not balance at the cage speed found "
               f"(relative residual {info['torque_residual']:.2g}: a jump between roots of the displacement)"
               if feedback["converged"] else
               f"{feedback['evaluations']} evaluations, residual {feedback['residual']:.3e} m, tolerance "
               f"{LAND_FEEDBACK_TOLERANCE:g} of the land clearance {rc.land_clearance:.3e} m")
    except (ValueError, InputError):
        # with the feedback the cage's torque need not be one function of the cage speed (the displacement's
        # balance can have several roots, or converge at some cage speeds and not at others): no bracketed root
        why = "the cage's torque with the displacement fed back has no bracketed root in the cage speed"
    # the balance without the feedback, and the solution says so (CageLandWarning)
    k, info = _cage_balance(None, free, geo, loaded, races, stage, kin, rc, model, n_strips, n_across, inertia,
                            lub, w_i, w_o, psi, film)
    info["land_feedback"] = {"converged": False, "evaluations": 0, "residual": math.nan, "why": why}
    return k, info


def _cage_balance(hint, free, geo, loaded, races, stage, kin, rc, model, n_strips, n_across, inertia, lub, w_i, w_o,
                  psi, film):
    """The cage speed and balls of :func:`_solve_cage` for the land's displacement ``hint`` (None: the centred
    cage's pockets; a dict: fed back, its start kept there)."""
    last = {}

    def torque(wc):
        k, info = _caged_balls(wc, geo, loaded, races, stage, last.get("kin", kin), rc, model, n_strips, n_across,
                               inertia, lub, w_i, w_o, psi, free, film, hint)
        last["kin"], last["info"], last["wc"] = k, info, wc
        return info["torque"]

    ref = max(abs(w_i - w_o), 1e-300)
    lo, hi = float(np.min(kin[:, 0])), float(np.max(kin[:, 0]))
    if hint is not None:  # the land's displacement at the balls' mean speed: the start of every later one
        torque(float(np.mean(kin[:, 0])))
        last.clear()
    pad = 1e-3 * ref + 0.5 * (hi - lo)
    lo, hi = lo - pad, hi + pad
    t_lo, t_hi = torque(lo), torque(hi)
    for _ in range(60):
        if t_lo >= 0.0 >= t_hi:
            break
        if t_lo < 0.0:
            lo, hi, t_hi = lo - 2.0 * pad, lo, t_lo
            t_lo = torque(lo)
        else:
            hi, lo, t_lo = hi + 2.0 * pad, hi, t_hi
            t_hi = torque(hi)
        pad *= 2.0
    else:
        raise InputError("cage: no cage speed balances the cage's torque (pocket forces and land) between "
                         f"{lo:g} and {hi:g} rad/s")
    if t_lo == 0.0 or t_hi == 0.0:
        wc = lo if t_lo == 0.0 else hi
    else:
        wc = _opt.brentq(torque, lo, hi, xtol=CAGE_SPEED_TOLERANCE * ref, rtol=1e-15)
    if last.get("wc") != wc:
        torque(wc)
    # the residual relative to the torques that act: the pocket, friction and land torques and the tractions'
    # own torques along the orbit, sum_j (|F_x,o| + |F_x,i|) c_r (the pocket forces are their difference: with
    # no net force on the pockets, the tractions set the round-off)
    info, k = last["info"], last["kin"]
    scale = info["torque_scale"]
    for j in range(geo.shape[0]):
        c = km.ball_contacts(k[j], geo[j], model, n_strips, n_across)
        scale += (abs(c[0, 6]) + abs(c[1, 6])) * geo[j, km.G_CR]
    info["torque_residual"] = info["torque"] / scale if scale > 0.0 else 0.0
    return k, info


def _cage_result(rc, info, out, moving, w_i, film=None):
    """The solution's ``cage`` dict (and the per-ball ``pocket_force``, ``pocket_sliding_speed`` in ``out``):
    speed [rad/s], losses [W] by kind, land torque [N m], force [N] and eccentricity, the torque balance's
    relative residual; a CageLandWarning when the land film is crushed. With the pocket ``film`` also the film's
    part of the pocket loss (``power_pocket_film``, per ball ``pocket_film_power``), the contact force the film
    leaves (``pocket_contact_force``) and the held balls' near gap (``pocket_film_gap``)."""
    z = out["psi"].size
    if not moving or info is None:  # the rings turn together: the cage with them, no pocket or land force
        info = {"speed": float(w_i), "pocket_force": np.zeros(z), "pocket_sliding_speed": np.zeros(z),
                "pocket_contact_fraction": np.zeros(z),
                "pocket_power_ball": np.zeros(z), "land_torque": 0.0, "land_power": 0.0, "land_eccentricity": 0.0,
                "land_crushed": False, "land_force": 0.0, "torque_residual": 0.0}
    out["pocket_force"] = np.asarray(info["pocket_force"], float).copy()
    out["pocket_sliding_speed"] = np.asarray(info["pocket_sliding_speed"], float).copy()
    out["pocket_force_held"] = np.asarray(info.get("pocket_force_held", info["pocket_force"]), float).copy()
    out["pocket_contact_fraction"] = np.asarray(info.get("pocket_contact_fraction", np.ones(z)), float).copy()
    out["pocket_contact_force"] = np.asarray(info.get("pocket_contact_force", info["pocket_force"]), float).copy()
    film_power = np.asarray(info.get("pocket_film_power_ball", np.zeros(z)), float)
    out["pocket_film_power"] = film_power.copy()
    if film is not None:
        gap = info.get("pocket_film_gap")
        out["pocket_film_gap"] = np.full(z, film.clearance) if gap is None else np.asarray(gap, float).copy()
    feedback = info.get("land_feedback")
    found = None if feedback is None or not feedback["converged"] else feedback["survey"]()
    roots = 1 if found is None else len(found)
    if roots > 1:  # (a feedback that did not converge: solve_quasistatic's solution without it, warned there)
        others = "; ".join(f"({x / rc.land_clearance:+.3f}, {y / rc.land_clearance:+.3f})"
                           for x, y in found[1:])
        warnings.warn(CageLandWarning(
            f"rigid_cage: the cage's displacement on its land is not unique at the cage speed found: {roots} roots "
            f"from {1 + 8 * len(LAND_SURVEY_ECCENTRICITIES)} starts over the land clearance (e / c: the solution's "
            f"({found[0][0] / rc.land_clearance:+.3f}, {found[0][1] / rc.land_clearance:+.3f}),"
            f" others {others}); the solution's is the one its relaxation from the balls' mean speed reaches"),
            stacklevel=3)
    if info["land_crushed"]:
        warnings.warn(CageLandWarning(
            f"rigid_cage: the land film cannot carry the net pocket force {info['land_force']:.4g} N within the "
            f"crush eccentricity {info['land_eccentricity']:.3g} (land clearance {rc.land_clearance:.3e} m): the "
            "cage touches its land, which the quasi-static solution does not model (its land torque is the film's "
            "at the crush eccentricity); the reference engine's rigid cage (eb.simulate(..., "
            "Scenario(cage='rigid'))) models the land contact"), stacklevel=3)
    return {"model": "rigid", "guidance": rc.guidance, "pocket_friction": rc.pocket_friction,
            "speed": info["speed"], "power_pocket": float(np.sum(info["pocket_power_ball"])),
            "pocket_film": film is not None, "power_pocket_film": float(np.sum(film_power)),
            "power_land": float(info["land_power"]), "land_torque": float(info["land_torque"]),
            "land_force": float(info["land_force"]), "land_eccentricity": float(info["land_eccentricity"]),
            "land_crushed": bool(info["land_crushed"]), "torque_residual": float(info["torque_residual"]),
            "land_displacement": tuple(float(v) for v in info.get("land_displacement", (0.0, 0.0))),
            "land_feedback_converged": bool(feedback is None or feedback["converged"]),
            "land_feedback_evaluations": 0 if feedback is None else int(feedback["evaluations"]),
            "land_feedback_roots": int(roots),
            "ring_speed": float(info.get("ring_speed", w_i)), "rigid_cage": rc}
