"""Experiment definition: loads, speed protocol, model switches and solver settings.

A :class:`Scenario` is data (as a PyBaMM Experiment): it names what is done to
the bearing, not how the engine does it. Combine it with a bearing and a
lubricant through :func:`exudyn_bearing.simulate`.
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from ..data import InputError, get_traction_model
from ..data.cages import RigidCage, estimated_cage
from ..data.errors import check_bool, check_keys, check_number, check_temperatures, check_unused
from ..data.defects import Defect, as_defect
from ..data.traction import DEFAULT_REGULARIZING_SRR
from ..physics.contact_slip import DEFAULT_N_ACROSS, DEFAULT_N_STRIPS, check_resolution
from ..physics.ehl import film_model_code
from ..physics import kinematics as _kin
from ..physics.hertz import method_code
from ..physics.losses import HYSTERESIS_LOSS_FACTOR_STEEL
from .layout import MAX_DEFECTS
from .motion import omega_profile

__all__ = ["Scenario", "FRICTION_MODELS", "INTEGRATORS", "INTEGRATOR_SOLVERS", "MULTI_EVALUATION_SOLVERS",
           "TRACTION_LEVELS", "INITIAL_STATES", "CONTROLS", "history_friction_error", "fixed_step_error",
           "ellipse_rolling_floor", "rolling_speed_floor", "DEFAULT_REGULARIZING_SPEED", "OUTER_RING_ENGINES",
           "OUTER_RING_REFUSALS", "engine_speed_error"]

#: Tangential force models: Cundall-Strack spring with Coulomb cap (contact
#: history), regularised Coulomb on the slip velocity (history-free), none.
FRICTION_MODELS = ("history", "regularized", "none")
#: Tangential force levels of the ball / raceway contacts.
TRACTION_LEVELS = ("point", "ellipse")
#: Initial states of a dynamic run.
INITIAL_STATES = ("analytic", "rest", "quasistatic")
#: Default ``Scenario.regularizing_speed`` [m/s]: the slip speed of regularised friction and the least
#: rolling speed of the ellipse traction law at start-up (:func:`rolling_speed_floor`).
DEFAULT_REGULARIZING_SPEED = 0.1
#: The least ``tolerance`` of the reduced engine's step control. The error estimate's own round-off is about
#: 2e-9 of the speed scale at the least step, 1e-7 s (the 6208 radial case from the quasi-static start at 2e-5 s:
#: tolerances 1e-10 and 1e-13 both stopped at an error of 2.04e-9); within a factor of ten of it the control
#: still runs into it (1e-9 stopped at once, 1e-8 after 0.84 ms), where 1e-7 ran (530 steps over 2 ms).
TOLERANCE_MIN = 1e-7
#: Kinematic hypotheses of the quasi-static start (those of the quasi-static solver).
CONTROLS = ("auto", "outer", "inner", "min-energy", "equilibrium")
#: Time integrators of the reference engine.
INTEGRATORS = ("verlet", "rk4")
#: Scenario integrator -> the Exudyn explicit solver of the same scheme (the Exudyn engine's solver).
INTEGRATOR_SOLVERS = {"verlet": "VelocityVerlet", "rk4": "RK44"}
#: Exudyn's explicit solvers that evaluate the forces more than once per step (stages, rejected adaptive steps).
MULTI_EVALUATION_SOLVERS = ("ExplicitMidpoint", "RK33", "RK44", "RK67", "ODE23", "DOPRI5", "DVERK6")


def fixed_step_error(scenario, engine: str):
    """The InputError of a ``scenario`` with a ``tolerance`` (the reduced engine's step error control) given to
    ``engine``, whose step is fixed (the reference engine, the Exudyn engine); None without a tolerance."""
    if scenario.tolerance is None:
        return None
    return InputError(f"tolerance: the {engine} engine takes the fixed step dt ({scenario.dt:g} s) and has no step "
                      "error control; the tolerance is the reduced engine's (engine='reduced', --engine reduced), or "
                      "give dt alone")


def history_friction_error(friction: str, solver: str, parameter: str = "solverType"):
    """The InputError for ``friction="history"`` under ``solver`` (an Exudyn
    solver name, or a Scenario integrator of :data:`INTEGRATOR_SOLVERS`) that
    evaluates the forces more than once per step, else None; the message
    names ``parameter`` ("integrator" for a Scenario, "solverType" for the
    Exudyn element). The one rule of both engines: the Cundall-Strack spring
    is advanced once per committed step (docs/theory/tangential.md), so under
    a multi-stage scheme its history takes the slip of the stages'
    intermediate states instead of the step's (docs/theory/dynamics.md,
    "Classical RK4")."""
    name = INTEGRATOR_SOLVERS.get(solver, solver)
    if friction != "history" or name not in MULTI_EVALUATION_SOLVERS:
        return None
    use = "integrator='verlet'" if parameter == "integrator" else "solverType VelocityVerlet"
    return InputError(f"{parameter}: {solver} evaluates the forces several times per step, but friction='history' "
                      "advances the Cundall-Strack spring once per step (its history would take the slip of the "
                      f"intermediate stages); use {use} (one evaluation per step) or a history-free friction "
                      "(friction='regularized' or 'none')")


#: Cage models of a scene (:class:`Scenario` ``cage``): True is an alias of "torus", False and None of "none";
#: "auto" (the default) is the bearing's own: the torus where it has cage balls, else the rigid cage.
CAGE_MODELS = ("torus", "rigid", "none", "auto")


def cage_model(cage) -> str:
    """The cage model's name of a ``cage`` option: one of :data:`CAGE_MODELS`, or True ("torus") / False or
    None ("none", the spelling the quasi-static solver takes too); InputError otherwise."""
    if cage is None:
        return "none"
    if cage is True or cage is False or isinstance(cage, np.bool_):
        return "torus" if cage else "none"
    if isinstance(cage, str) and cage in CAGE_MODELS:
        return cage
    raise InputError(f"cage: must be one of {', '.join(CAGE_MODELS)} (True: torus, False or None: none), "
                     f"got {cage!r}")


def bearing_cage(cage: str, bearing) -> str:
    """The cage model ``cage`` means on ``bearing``: "auto" is the torus where the bearing has cage balls (the
    DEM papers' bearings, whose validated numbers use it) and the rigid cage where it has none (the
    ACBB-120: the rigid cage's estimated geometry, docs/theory/cage.md); any other name as it is."""
    if cage != "auto":
        return cage
    return "torus" if bearing.has_cage else "rigid"


def resolve_cage(scenario: Scenario, bearing) -> Scenario:
    """``scenario`` with its cage model for ``bearing`` (:func:`bearing_cage`); the same object when there is
    nothing to resolve."""
    cage = bearing_cage(scenario.cage, bearing)
    return scenario if cage == scenario.cage else dataclasses.replace(scenario, cage=cage)


@dataclass(frozen=True)
class Scenario:
    """What happens to the bearing (docs/theory/dynamics.md).

    Parameters
    ----------
    Fr, Fa : float
        Radial load on the inner ring along +x and axial load along +z [N]
        (default 0, as in every entry point: docs/defaults.md).
    omega : float
        Inner-ring speed [rad/s] of the steady phase (default 0: a run at
        rest; the DEM papers' case is Fr=3000, omega=500).
    omega_outer : float
        Outer-ring speed [rad/s] of the steady phase about the bearing axis
        (default 0: the outer ring fixed), under the same protocol as
        ``omega`` (the same ramp factor); positive in the sense of ``omega``.
        The outer ring turns in place (it does not translate); its surface
        speed enters the outer contacts (slip, traction, spin, film
        entrainment) and its torque the drive power (docs/theory/dynamics.md).
        The reference engine takes it; the Exudyn and reduced engines refuse a
        nonzero value by name (:func:`engine_speed_error`).
    t_end : float
        Simulated time [s].
    t_ramp_up, t_steady, t_ramp_down : float
        Speed protocol [s]: linear ramp 0 -> omega over ``t_ramp_up``, hold
        for ``t_steady``, linear ramp to 0 over ``t_ramp_down``, then rest.
        ``t_ramp_up = 0`` starts at omega; ``t_steady = inf`` (default) never
        slows down; without a ramp down the hold includes its end, so a run
        ending there ends at speed (the rest begins after it).
    Pd : float or None
        Diametral clearance override [m] (None: the bearing's own).
    cage : {"auto", "torus", "rigid", "none"} or bool
        The cage: the DEM papers' torus cage (cage balls between the balls;
        True is an alias), a rigid cage body with pockets and a guiding land
        (``rigid_cage``; reference engine and Exudyn element,
        docs/theory/cage.md) or none (False is an alias): the balls kept apart
        by ball / ball contact only. "auto" (default): the torus where the
        bearing has cage balls, else the rigid cage (:func:`bearing_cage`;
        the engines resolve it, their records carry the resolved name). A
        ``rigid_cage`` given with "auto" means "rigid". Read back as one of
        the four names.
    rigid_cage : RigidCage or None
        Geometry and material of the rigid cage (``exudyn_bearing.data.cages``);
        None: :func:`~exudyn_bearing.data.cages.estimated_cage` of the bearing
        (outer-land guided brass, every geometric value estimated).
    gravity : (g_x, g_y, g_z)
        Acceleration of gravity [m/s^2] in the outer-ring frame (the bearing
        axis is z: a horizontal shaft with gravity along -y is (0, -9.81, 0),
        a vertical one (0, 0, -9.81)), acting on the rigid cage (its weight
        decides where it rides at low speed); the balls' and rings' weights,
        far below their contact loads, are left out. Default none.
    pocket_film : bool
        The oil film between each ball and its rigid-cage pocket
        (docs/theory/cage.md#pocket-oil-film, :mod:`exudyn_bearing.physics.pocket_film`):
        inside the pocket's clearance the film's hydrodynamic force (rigid,
        isoviscous: Brewe, Hamrock & Taylor) and squeeze force (sphere on a
        plane, a lower bound for the conforming pocket) push the ball off the
        wall, at the lubricant's viscosity; the pocket friction mu_c acts on
        the film's force as on the contact's. Default False: the dry Hertz
        contact only (the validated runs). Needs ``cage='rigid'`` and
        ``lubrication``.
    lubrication : bool
        Lambda-switched damping and friction (True) or constant mu and
        hysteretic damping (False).
    mu_dry : float
        Friction coefficient when ``lubrication`` is False.
    friction : {"history", "regularized", "none"}
        Tangential force model (docs/theory/tangential.md).
    regularizing_speed : float
        Slip speed [m/s] below which regularised friction is linear; at the
        ellipse traction level, the least rolling speed of the slide-to-roll
        ratios (start-up from rest), at most half the kinematic inner
        rolling speed at ``omega``
        (:func:`ellipse_rolling_floor`).
    tangential_stiffness_ratio : float
        K_t / K_n of the Cundall-Strack spring, in [2/3, 1].
    tangential : {"explicit", "implicit"}
        Update of the Cundall-Strack spring: explicit (the DEM papers; its
        stiffness limits the step) or implicit, where the spring acts with
        K_t / (1 + K_t dt^2 / m_t), m_t = m_b / 3.5 the tangential mass of a
        solid sphere at its surface: the backward-Euler response of the
        contact to its own force over one step. Stable at any step and equal
        to the explicit spring as dt -> 0; lifts the tangential step limit.
    cage_damping : {"explicit", "implicit"}
        Damping of the critically damped ball / cage-ball and cage-ball /
        guide contacts: explicit (the DEM papers' C = 2 sqrt(m k_t), whose
        step limit is 0.83/omega under velocity Verlet and limits start-up,
        slow-down and the 7208 under combined load) or implicit, where the
        contact damps with C / (1 + C dt / m), m the contact's reduced mass:
        the backward-Euler response of the contact's approach speed to its
        own damping over one step. Equal to the explicit damping as dt -> 0;
        stable up to 1.58/omega (docs/theory/dynamics.md#implicit-cage-damping).
        ``integrator='verlet'`` and a scene with cage only.
    hertz : {"exact", "hamrock_brewe", "simplified"}
        Hertz fidelity level (exact is tabulated in the kernels).
    contact_law : {"hertz", "power"}
        Ball / raceway law: elliptic Hertz with lubrication (default), or the
        power law of Exudyn's ObjectContactSphereTorus, F = k delta^n + d
        d(delta)/dt with constant ``mu_dry`` (``power_law = (k, n, d)``; no
        lubrication), for peer checks against exudyn.machines.
    film : {"hd", "mk"}
        Film-thickness model.
    guide_clearance : float
        Radial and axial clearance [m] of the cage balls in their guide torus.
    ring_mass : float or None
        Translating mass of the inner ring (and what it carries) [kg];
        None: the ring's own mass estimated from the bearing geometry.
    traction_level : {"point", "ellipse"}
        Tangential force of the ball / raceway contacts: ``"point"`` (the
        point-contact law chosen by ``friction``: Cundall-Strack spring or
        regularised Coulomb with mu(Lambda) or ``mu_dry``, the DEM
        papers' laws) or ``"ellipse"``: the slip field over the Hertz ellipse
        (rolling, spin about the normal, curvature-induced slip) integrated
        over ``n_strips`` strips with the traction model ``traction``,
        giving the tangential force and the spin moment about the contact
        normal (:func:`exudyn_bearing.physics.contact_slip._contact_traction`;
        the quasi-static solver's relation). ``friction``,
        ``tangential`` and ``mu_dry`` then do not apply.
    traction : str or None
        Traction model of the ellipse level, a name of
        ``exudyn_bearing.data.traction_models``; None (default): the
        bearing's (:func:`exudyn_bearing.data.default_traction`: the ACBB-120's
        EHL model of its oil, the DEM papers' mu(Lambda) ``"lambda_dem"`` for
        the others), filled in by :func:`exudyn_bearing.simulate` and the
        element.
    n_strips, n_across : int
        Strips along the major axis and points across each strip of the
        ellipse integration; default 16 x 4, the same in every solver
        (:data:`~exudyn_bearing.physics.contact_slip.DEFAULT_N_STRIPS`,
        chosen by validation/studies/traction_convergence.py).
    traction_regularizing_srr : float
        Slide-to-roll ratio below which a Coulomb-type traction model
        (``constant``, ``lambda``) whose own ``regularizing_srr`` is 0 rises
        linearly from zero in the dynamic engines (a discontinuous law has no
        stable explicit step); reported in the summary.
    ring_growth : bool
        Groove geometry follows the ring speeds during the run: the
        centrifugal growth of a rotating ring (rotating annular disc,
        :mod:`exudyn_bearing.physics.ring_growth`, the quasi-static solver's
        relation) moves its groove outward in proportion to omega^2.
        Default True, as in the quasi-static solver (README, "Defaults").
    temperatures : dict or None
        ``{"inner", "outer", "ball"}`` temperatures [K] for the uniform
        thermal growth of rings and balls (from 293.15 K).
    initial : {"analytic", "rest", "quasistatic"}
        Start from the quasi-static load distribution with balls and cage at
        their kinematic speeds, from rest, or from the quasi-static solver's
        solution at the scenario's loads and speed (ball positions, contact
        angles, orbital and ball angular velocities by ``control``; with the
        rigid cage, the solution with that cage: balls at the cage's speed).
    control : {"auto", "outer", "inner", "min-energy", "equilibrium"}
        Kinematic hypothesis of the quasi-static start (``initial="quasistatic"``;
        another value with another start is refused, not silently unused).
    integrator : {"verlet", "rk4"}
    dt : float
        Time step [s] (default 1 us, the DEM papers' step); with
        ``tolerance``, the first step.
    tolerance : float or None
        The reduced engine's step error control (docs/theory/reduced.md,
        "Step error control"): the steps are chosen so that each step's
        estimated local error of every speed (the balls' orbital speeds and
        angular velocities, the inner ring's and the rigid cage's, as
        surface speeds) stays below ``tolerance`` times the inner ring's
        speed at the pitch radius; ``dt`` is then the first step, the steps
        lie between 0.1 us and min(1e-4 s, ``sample_dt``) and land on the
        sample times. A number in [1e-7, 1) (the error estimate's round-off
        floor is about 2e-9; tolerances near it stop at the least step);
        None (default): the fixed step
        ``dt``. The other engines have fixed steps and refuse it.
    sample_dt : float
        Output interval [s].
    defects : tuple of Defect (or dicts of their fields), or one of them
        Localized defects (spalls) on the races or balls
        (:class:`exudyn_bearing.data.Defect`, at most ``MAX_DEFECTS``);
        empty (default): a healthy bearing, and the kernels skip the defect
        code. Ball defects need ``integrator='verlet'`` (the ball orientation
        is advanced once per step).
    signal_dt : float or None
        Sample interval [s] of the condition-monitoring signals (housing
        force, inner-ring acceleration and speed; layout
        ``model.layout.SIGNAL_FIELDS``), an integer multiple of ``dt``
        (48 kHz: ``signal_dt=1/48000, dt=signal_dt/4``); each sample is the
        mean over its interval's steps. None (default): no signals. Needs
        ``integrator='verlet'``.
    rolling_resistance : bool
        Rolling resistance as a force (docs/theory/losses.md, "In the dynamic
        engines"): at every loaded ball / raceway contact a moment pair of
        magnitude (F_h + 2 F_R) R_x opposing the ball's rolling relative to
        the race, on the ball and, reversed, on the ring (no net force):
        elastic hysteresis F_h always, the EHL rolling force F_R with
        ``lubrication`` (the quasi-static losses' relations). Default False
        (the DEM papers' model).
    ball_drag : bool
        Drag of the oil-air mixture on every ball centre against the ball's
        velocity relative to the mixture, which is taken at rest with the
        outer ring; the reaction acts on the outer ring. Default False.
    oil_volume_fraction : float
        Oil's share of the free volume the balls move through [-], 0-1, for
        ``ball_drag`` (0: air; the quasi-static ``power_losses`` keyword).
    hysteresis_loss_factor : float
        alpha_h [-] of the hysteresis rolling resistance, in [0, 1) (default
        0.007, hardened bearing steel; the quasi-static ``power_losses`` keyword).
    """

    Fr: float = 0.0
    Fa: float = 0.0
    omega: float = 0.0
    omega_outer: float = 0.0
    t_end: float = 0.05
    t_ramp_up: float = 0.0
    t_steady: float = math.inf
    t_ramp_down: float = 0.0
    Pd: float | None = None
    cage: bool | str = "auto"
    rigid_cage: object = None
    gravity: tuple = (0.0, 0.0, 0.0)
    pocket_film: bool = False
    lubrication: bool = True
    mu_dry: float = 0.1
    friction: str = "history"
    regularizing_speed: float = DEFAULT_REGULARIZING_SPEED
    tangential_stiffness_ratio: float = 2.0 / 3.0
    tangential: str = "explicit"
    cage_damping: str = "explicit"
    hertz: str = "exact"
    contact_law: str = "hertz"
    power_law: tuple = (0.0, 1.5, 0.0)
    film: str = "hd"
    guide_clearance: float = 50e-6
    ring_mass: float | None = None
    traction_level: str = "point"
    traction: str | None = None
    n_strips: int = DEFAULT_N_STRIPS
    n_across: int = DEFAULT_N_ACROSS
    traction_regularizing_srr: float = DEFAULT_REGULARIZING_SRR
    ring_growth: bool = True
    temperatures: dict | None = None
    initial: str = "analytic"
    control: str = "auto"
    integrator: str = "verlet"
    dt: float = 1e-6
    tolerance: float | None = None
    sample_dt: float = 1e-4
    defects: tuple = ()
    signal_dt: float | None = None
    rolling_resistance: bool = False
    ball_drag: bool = False
    oil_volume_fraction: float = 0.0
    hysteresis_loss_factor: float = HYSTERESIS_LOSS_FACTOR_STEEL

    def __post_init__(self):
        # numbers as plain floats (numpy scalars are numbers; strings and booleans are not)
        for name in ("Fr", "Fa", "omega", "omega_outer", "t_end", "t_ramp_up", "t_ramp_down", "mu_dry",
                     "regularizing_speed", "guide_clearance", "dt", "sample_dt", "tangential_stiffness_ratio"):
            v = check_number(name, getattr(self, name))
            if not math.isfinite(v):
                raise InputError(f"{name}: must be a finite number, got {v!r}")
            object.__setattr__(self, name, v)
        ts = check_number("t_steady", self.t_steady)
        if math.isnan(ts) or ts < 0:
            raise InputError(f"t_steady: must be >= 0 (inf allowed), got {ts!r}")
        object.__setattr__(self, "t_steady", ts)
        for name in ("Pd", "ring_mass"):
            if getattr(self, name) is not None:
                object.__setattr__(self, name, check_number(name, getattr(self, name)))
        object.__setattr__(self, "cage", cage_model(self.cage))
        if self.rigid_cage is not None and self.cage == "auto":  # a rigid cage's geometry chooses the rigid cage
            object.__setattr__(self, "cage", "rigid")
        try:
            grav = tuple(check_number("gravity", x) for x in self.gravity)
        except TypeError:
            raise InputError(f"gravity: expected (g_x, g_y, g_z) [m/s^2], got {self.gravity!r}") from None
        if len(grav) != 3 or not all(math.isfinite(x) for x in grav) or math.hypot(*grav) > 100.0:
            raise InputError(f"gravity: expected three finite components [m/s^2] of at most 100 m/s^2 in magnitude "
                             f"(Earth: 9.81), got {self.gravity!r}")
        if any(grav) and self.cage not in ("rigid", "auto"):
            raise InputError("gravity: acts on the rigid cage only (cage='rigid'); the balls' and rings' weights are "
                             "left out")
        object.__setattr__(self, "gravity", grav)
        if self.rigid_cage is not None:
            if not isinstance(self.rigid_cage, RigidCage):
                raise InputError(f"rigid_cage: expected a RigidCage (exudyn_bearing.data.cages), got "
                                 f"{type(self.rigid_cage).__name__}")
            if self.cage != "rigid":
                raise InputError(f"rigid_cage: given with cage={self.cage!r}; it is the geometry of cage='rigid'")
        for name in ("lubrication", "rolling_resistance", "ball_drag"):
            object.__setattr__(self, name, check_bool(name, getattr(self, name)))
        object.__setattr__(self, "pocket_film", check_bool("pocket_film", self.pocket_film))
        if self.pocket_film and self.cage not in ("rigid", "auto"):
            raise InputError(f"pocket_film: the film between ball and pocket is the rigid cage's (cage='rigid'), "
                             f"and the scene has cage={self.cage!r} (with cage='auto' a bearing with cage balls takes "
                             f"the torus cage): set cage='rigid'")
        if self.pocket_film and not self.lubrication:
            raise InputError("pocket_film: needs an oil (lubrication=True); without it the pockets are dry")
        for name in ("Fr", "Fa", "t_ramp_up", "t_ramp_down", "mu_dry"):
            if getattr(self, name) < 0:
                raise InputError(f"{name}: must be >= 0, got {getattr(self, name)}")
        for name in ("t_end", "dt", "sample_dt", "regularizing_speed", "guide_clearance"):
            if getattr(self, name) <= 0:
                raise InputError(f"{name}: must be > 0, got {getattr(self, name)}")
        if self.dt > 1e-4:  # first: a huge dt is the mistake, not the sample interval below it
            raise InputError(f"dt: {self.dt:g} s is far above any stable step of a Hertz contact (at most 1e-4 s; "
                             "typical 1e-6 to 8e-6 s; the reduced engine's 1e-5 to 1e-4 s)")
        if self.tolerance is not None:
            tol = self.tolerance
            if isinstance(tol, bool) or not isinstance(tol, (int, float)) or not math.isfinite(tol) \
                    or not 0.0 < tol < 1.0:
                raise InputError(f"tolerance: the reduced engine's local error per step, relative, must be a number "
                                 f"in (0, 1) (e.g. 1e-4), or None for the fixed step dt; got {tol!r}")
            if tol < TOLERANCE_MIN:
                raise InputError(f"tolerance: {tol:g} is below {TOLERANCE_MIN:g}: the step control's error estimate "
                                 "has a round-off floor of about 2e-9 of the speed scale at the least step (1e-7 s), "
                                 "and tolerances within a few times of it stop there (on the 6208, 1e-8 after "
                                 "0.84 ms); 1e-6 resolves the drive power (docs/theory/reduced.md)")
            object.__setattr__(self, "tolerance", float(tol))
        if self.sample_dt < self.dt:
            raise InputError(f"sample_dt: must be >= dt ({self.dt}), got {self.sample_dt}")
        if self.t_end < self.sample_dt:
            raise InputError(f"t_end: must be >= sample_dt ({self.sample_dt:g} s) so that the run has a sample, "
                             f"got {self.t_end:g}")
        if not 2.0 / 3.0 - 1e-12 <= self.tangential_stiffness_ratio <= 1.0:
            raise InputError("tangential_stiffness_ratio: must lie in [2/3, 1] (docs/theory/tangential.md), "
                             f"got {self.tangential_stiffness_ratio}")
        if self.friction not in FRICTION_MODELS:
            raise InputError(f"friction: unknown model {self.friction!r} (valid: {', '.join(FRICTION_MODELS)})")
        if self.tangential not in ("explicit", "implicit"):
            raise InputError(f"tangential: must be 'explicit' or 'implicit', got {self.tangential!r}")
        if self.integrator not in INTEGRATORS:
            raise InputError(f"integrator: unknown {self.integrator!r} (valid: {', '.join(INTEGRATORS)})")
        if self.cage_damping not in ("explicit", "implicit"):
            raise InputError(f"cage_damping: must be 'explicit' or 'implicit', got {self.cage_damping!r}")
        if self.cage_damping == "implicit" and self.integrator != "verlet":
            raise InputError("cage_damping: 'implicit' is the backward-Euler damping of one velocity-Verlet step "
                             f"and needs integrator='verlet', got {self.integrator!r}")
        if self.cage_damping == "implicit" and self.cage == "none":
            raise InputError("cage_damping: 'implicit' damps the ball / cage-ball and guide contacts, and the scene "
                             "has no cage (cage=False; its ball / ball contacts keep the explicit damping)")
        err = history_friction_error(self.friction, self.integrator, "integrator")
        if err is not None:
            raise err
        try:
            law = tuple(float(x) for x in self.power_law)
        except (TypeError, ValueError):
            raise InputError(f"power_law: expected (k, n, d), got {self.power_law!r}") from None
        if len(law) != 3:
            raise InputError(f"power_law: expected (k, n, d), got {self.power_law!r}")
        object.__setattr__(self, "power_law", law)
        if self.contact_law not in ("hertz", "power"):
            raise InputError(f"contact_law: must be 'hertz' or 'power', got {self.contact_law!r}")
        if self.contact_law == "power":
            k, n, d = self.power_law
            if not (k > 0 and n >= 1 and d >= 0):
                raise InputError(f"power_law: need k > 0, n >= 1, d >= 0, got {self.power_law}")
        if self.initial not in INITIAL_STATES:
            raise InputError(f"initial: must be one of {', '.join(INITIAL_STATES)}, got {self.initial!r}")
        if self.control not in CONTROLS:
            raise InputError(f"control: must be one of {', '.join(CONTROLS)}, got {self.control!r}")
        if self.control != "auto" and self.initial != "quasistatic":  # not silently unused
            raise InputError(f"control: {self.control!r} chooses the kinematics of the quasi-static start "
                             f"(initial='quasistatic'), and the scene starts from {self.initial!r}: set "
                             f"initial='quasistatic' (command line: --initial quasistatic) or leave control at 'auto'")
        if self.traction_level not in TRACTION_LEVELS:
            raise InputError(f"traction_level: must be one of {', '.join(TRACTION_LEVELS)}, got "
                             f"{self.traction_level!r}")
        get_traction_model(self.traction)  # an unknown name raises, listing the catalogue
        ns, na = check_resolution(self.n_strips, self.n_across)  # the range of every entry point
        object.__setattr__(self, "n_strips", ns)
        object.__setattr__(self, "n_across", na)
        srr = self.traction_regularizing_srr
        if isinstance(srr, bool) or not isinstance(srr, (int, float)) or not 0.0 < srr <= 1.0:
            raise InputError(f"traction_regularizing_srr: must lie in (0, 1], got {srr!r}")
        if self.traction_level == "ellipse" and self.friction == "none":
            raise InputError("friction: 'none' switches the tangential forces off; the ellipse traction level "
                             "replaces the friction law (use traction_level='point' for a frictionless run)")
        if self.traction_level == "ellipse" and self.contact_law == "power":
            raise InputError("contact_law: the peer power law has no Hertz ellipse; use traction_level='point'")
        if not isinstance(self.ring_growth, (bool, np.bool_)):
            raise InputError(f"ring_growth: must be True or False, got {self.ring_growth!r}")
        object.__setattr__(self, "temperatures", check_temperatures(self.temperatures))
        try:
            method_code(self.hertz)
        except ValueError as exc:
            raise InputError(f"hertz: {exc}") from None
        try:
            film_model_code(self.film)
        except ValueError as exc:
            raise InputError(f"film: {exc}") from None
        if self.ring_mass is not None and (not math.isfinite(self.ring_mass) or self.ring_mass <= 0):
            raise InputError(f"ring_mass: must be > 0, got {self.ring_mass}")
        if self.Pd is not None and not math.isfinite(self.Pd):
            raise InputError(f"Pd: must be finite, got {self.Pd}")
        defects = self.defects
        if isinstance(defects, (Defect, dict)):  # one defect: a sequence of one
            defects = (defects,)
        if isinstance(defects, (str, bytes)) or not hasattr(defects, "__iter__"):
            raise InputError(f"defects: expected a Defect, a dict of its fields or a sequence of them, got "
                             f"{defects!r}")
        defects = tuple(as_defect(d) for d in defects)
        if len(defects) > MAX_DEFECTS:
            raise InputError(f"defects: at most {MAX_DEFECTS} defects per scene, got {len(defects)}")
        object.__setattr__(self, "defects", defects)
        if self.integrator != "verlet" and any(d.race == "ball" for d in defects):
            raise InputError("integrator: a ball defect needs integrator='verlet' (the ball orientation is "
                             f"advanced once per step), got {self.integrator!r}")
        for name, ok, limit in (("oil_volume_fraction", lambda v: 0.0 <= v <= 1.0, "lie in [0, 1]"),
                                ("hysteresis_loss_factor", lambda v: 0.0 <= v < 1.0, "lie in [0, 1)")):
            v = check_number(name, getattr(self, name))
            if not (math.isfinite(v) and ok(v)):
                raise InputError(f"{name}: must {limit}, got {v!r}")
            object.__setattr__(self, name, v)
        check_unused("ball_drag", self.ball_drag, (("oil_volume_fraction", self.oil_volume_fraction, 0.0),),
                     "set ball_drag=True (--ball-drag)")
        check_unused("rolling_resistance", self.rolling_resistance,
                     (("hysteresis_loss_factor", self.hysteresis_loss_factor, HYSTERESIS_LOSS_FACTOR_STEEL),),
                     "set rolling_resistance=True (--rolling-resistance)")
        if self.rolling_resistance and self.contact_law == "power":
            raise InputError("rolling_resistance: the peer power law has no Hertz ellipse to size the rolling "
                             "resistance; use contact_law='hertz'")
        if self.signal_dt is not None:
            sd = self.signal_dt
            if isinstance(sd, bool) or not isinstance(sd, (int, float)) or not math.isfinite(sd) or sd <= 0:
                raise InputError(f"signal_dt: must be a number > 0 (or None), got {sd!r}")
            ratio = sd / self.dt
            if ratio < 1.0 - 1e-9 or abs(ratio - round(ratio)) > 1e-9 * ratio:
                raise InputError(f"signal_dt: must be an integer multiple of dt = {self.dt:.6g} s, got {sd:.6g} s "
                                 f"(ratio {ratio:.6g}); e.g. dt = signal_dt / {max(1, math.ceil(ratio))}")
            if self.integrator != "verlet":
                raise InputError("signal_dt: signals are recorded by integrator='verlet' (one force evaluation "
                                 f"per step), got {self.integrator!r}")
            object.__setattr__(self, "signal_dt", float(sd))

    @property
    def signal_every(self) -> int:
        """Steps per signal sample (0: no signals)."""
        return 0 if self.signal_dt is None else int(round(self.signal_dt / self.dt))

    def _profile(self):
        """(omega, t_ramp_up, t_steady, t_ramp_down) as floats: the protocol's arguments of
        :func:`~exudyn_bearing.model.motion.omega_profile`."""
        return float(self.omega), float(self.t_ramp_up), float(self.t_steady), float(self.t_ramp_down)

    def omega_at(self, t):
        """Prescribed inner-ring speed omega(t) [rad/s] of the protocol (the
        kernels' :func:`~exudyn_bearing.model.motion.omega_profile`)."""
        return float(omega_profile(float(t), *self._profile()))

    def omega_outer_at(self, t):
        """Prescribed outer-ring speed [rad/s] at time t: ``omega_outer`` times the protocol's ramp factor
        (:func:`~exudyn_bearing.model.motion.omega_profile` of ``omega_outer``, as the kernels' outer ring)."""
        _w, up, steady, down = self._profile()
        return float(omega_profile(float(t), float(self.omega_outer), up, steady, down))

    def rigid_cage_of(self, bearing) -> RigidCage:
        """The rigid cage's geometry of this scene on ``bearing``: ``rigid_cage``, or the bearing's estimated cage
        (:func:`~exudyn_bearing.data.cages.estimated_cage`) when None."""
        return self.rigid_cage if self.rigid_cage is not None else estimated_cage(bearing)

    def speed_function(self):
        """omega(t) [rad/s] of the protocol as a closure over its numbers: the values of
        :meth:`omega_at`, without its attribute look-ups and conversions at every call (about half
        of its 0.6 us), for a caller that evaluates it at every step (the Exudyn element's
        ``innerRingSpeed``, or a user's own speed function)."""
        w, up, steady, down = self._profile()
        return lambda t: omega_profile(float(t), w, up, steady, down)

    def replace(self, **changes) -> "Scenario":
        return dataclasses.replace(self, **changes)

    @classmethod
    def from_dict(cls, d) -> "Scenario":
        """A Scenario from a dict of its fields (sweep specs, JSON); an
        unknown key raises InputError naming it, with the valid ones."""
        if isinstance(d, Scenario):
            return d
        if not isinstance(d, dict):
            raise InputError(f"scenario: expected a dict of Scenario fields, got {d!r}")
        check_keys("scenario field", d, [f.name for f in dataclasses.fields(cls)])
        return cls(**d)

    @classmethod
    def papers_protocol(cls, omega=500.0, t_ramp_up=0.02, t_steady=0.06, t_ramp_down=0.02, Fr=3000.0, **kw):
        """Start-up ramp, steady phase and slow-down (the DEM papers' protocol, with their case's 3000 N and
        500 rad/s as its defaults; a Scenario's own loads and speed default to 0)."""
        return cls(Fr=Fr, omega=omega, t_ramp_up=t_ramp_up, t_steady=t_steady, t_ramp_down=t_ramp_down,
                   t_end=kw.pop("t_end", t_ramp_up + t_steady + t_ramp_down), initial="rest"
                   if kw.pop("initial", "rest") == "rest" else "analytic", **kw)

    @classmethod
    def quasi_static(cls, Fr=3000.0, **kw):
        """Quasi-static protocol of the DEM papers' Appendix A: omega = 1 rad/s (their 3000 N by default)."""
        kw.setdefault("t_end", 0.01)
        return cls(Fr=Fr, omega=1.0, **kw)


#: Dynamic engines that spin the outer ring at ``Scenario.omega_outer`` (the ring poses of
#: :func:`~exudyn_bearing.model.engine_steps.set_inner_ring`).
OUTER_RING_ENGINES = ("reference",)
#: Why an engine refuses a turning outer ring (``omega_outer`` != 0).
OUTER_RING_REFUSALS = {
    "exudyn": "its outer ring is the ground of the Exudyn scene, and the element reports the balls and the cage "
              "in the outer ring's frame, whose summaries take that ring as fixed",
    "reduced": "its linearly implicit step does not yet close the energy balance with the outer ring turning (a "
               "drive-power error proportional to the step)",
}


def engine_speed_error(scenario: Scenario, engine: str) -> InputError | None:
    """The InputError naming ``omega_outer`` when ``engine`` does not spin the outer ring and the scenario
    asks for it (nonzero ``omega_outer``), saying why and which engine takes it; else None. Never ignored
    silently."""
    if scenario.omega_outer == 0.0 or engine in OUTER_RING_ENGINES:
        return None
    why = OUTER_RING_REFUSALS.get(engine, "it holds the outer ring fixed")
    return InputError(f"omega_outer: the {engine} engine cannot take omega_outer = {scenario.omega_outer:g} rad/s: "
                      f"{why}; the {' and '.join(OUTER_RING_ENGINES)} engine takes it (engine='reference', "
                      "simulate --engine reference)")


#: Least rolling speed of the ellipse traction law as a fraction of the kinematic inner rolling speed at the
#: scenario's speed: a steady run, whose loaded contacts roll at about that speed, keeps its slide-to-roll ratios.
ELLIPSE_ROLLING_FLOOR_FRACTION = 0.5


def rolling_speed_floor(bearing, omega, omega_outer=0.0, regularizing_speed=DEFAULT_REGULARIZING_SPEED) -> float:
    """Least rolling speed [m/s] the ellipse-level traction law sees, in every solver: ``regularizing_speed``
    (start-up from rest), at most ``ELLIPSE_ROLLING_FLOOR_FRACTION`` times the kinematic inner rolling speed
    at the ring speeds ``omega``, ``omega_outer`` [rad/s] (Harris & Kotzalas' rolling speeds,
    :func:`~exudyn_bearing.physics.kinematics.rolling_speeds`). A floor above the rolling speed shrinks the
    slide-to-roll ratios: the 6208 at 1 rad/s rolls at 0.0145 m/s, and 0.1 m/s lowered its dissipation
    five-fold (validation/consistency/anomaly_checks.py). The dynamic engines' kernel takes it as ``P_VREG``
    (:func:`ellipse_rolling_floor`), the quasi-static solver as its default ``rolling_speed_floor``."""
    b = bearing
    u_i, _u_o = _kin.rolling_speeds(float(omega), float(omega_outer), b.ball_radius, b.pitch_radius,
                                    b.free_contact_angle)
    u = ELLIPSE_ROLLING_FLOOR_FRACTION * abs(float(u_i))
    return min(regularizing_speed, u) if u > 0.0 else regularizing_speed


def ellipse_rolling_floor(bearing, scenario: Scenario) -> float:
    """:func:`rolling_speed_floor` of a scenario (kernel ``P_VREG``, ``model.contact._ellipse_traction``):
    its ``regularizing_speed`` at most half the kinematic inner rolling speed at its ``omega`` and
    ``omega_outer``."""
    return rolling_speed_floor(bearing, scenario.omega, scenario.omega_outer, scenario.regularizing_speed)
