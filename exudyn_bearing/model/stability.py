"""Stable time steps of the explicit integrators and the checks that go with
them: the ball contacts (normal, tangential, friction, cage), the ring bodies
of the Exudyn element's fast mode, and the cage loads a run reached.

Every estimate linearises the contacts at their quasi-static loads
(:func:`exudyn_bearing.physics.load_distribution.static_equilibrium`) with the
Hertz tangent stiffness (:func:`exudyn_bearing.physics.hertz.tangent_stiffness`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..data import BallBearing, InputError, Lubricant, default_lubricant
from ..physics import hertz, kinematics
from ..physics.friction import sphere_tangential_mass
from ..physics.hertz import material_reduced_modulus
from ..physics.load_distribution import race_stiffness
from .load_range import MAX_CONTACT_PRESSURE, check_load_range
from .scenario import Scenario, ellipse_rolling_floor, resolve_cage

__all__ = ["ellipse_traction_damping", "SimulationError", "StepSizeWarning", "StableStep", "STABILITY_SAFETY", "START_UP_CAGE_LOAD",
           "STEADY_CAGE_LOAD", "CAGE_BLOW_UP_RATIO", "CAGE_BLOW_UP_RATIO_IMPLICIT", "explicit_step_factor", "expected_cage_load", "stable_step",
           "step_warning", "cage_load_check", "land_step_check", "land_film_step", "rigid_cage_step",
           "LAND_DESIGN_ECCENTRICITY", "ring_contact_stiffness", "ring_stable_step", "runaway_error"]


class SimulationError(RuntimeError):
    """The integration produced a non-finite or runaway state."""


class StepSizeWarning(UserWarning):
    """The time step exceeds the stable-step estimate of the scene."""


#: Factor between the linearised single-ball limit and the reported stable
#: step: the two races, the ring and load peaks couple the modes (the 6208 at
#: 500 rad/s with the implicit tangential spring blows up at 0.93 of the
#: linearised normal limit; validation/performance/bench_reference.py measures it).
STABILITY_SAFETY = 0.85

#: Ball / cage-ball contact load [fraction of the largest ball load] the
#: a-priori estimate assumes where the scene loads the cage: start-up and
#: slow-down, starts from rest, and loaded balls at unequal contact angles
#: (they roll at different kinematic speeds and push the cage until they
#: slide, mu Q). Measured (validation/studies/cage_step_checks.py, step_limits.py):
#: up to 72 N at 2 us in the 6208 protocol (5 % of Q), 257 N for the 7208
#: under F_r = F_a (19 %), 180 N for the 6208 under F_r = 3000 N, F_a = 500 N.
START_UP_CAGE_LOAD = 0.1
#: The same for steady runs from the analytic state whose loaded balls all
#: have one contact angle (nothing drives the cage): 0.1 % of the ball load,
#: the *settled* cage load, not the start transient's peak. What it trades:
#: measured at 2 us over 50 ms (``python validation/studies/step_limits.py``, its
#: ``steady_cage_loads``), the nine such scenes settle in the second half of
#: the run at 0-1 N, below this assumption in eight (the 6208 at F_r = 200 N,
#: P_d = 40 um, 300 rad/s: 0.62 N against 0.20 N assumed); but in their first
#: milliseconds five of the nine exceed it, by up to 7.9 times (6208 under
#: F_a = 2000 N: 6.9 N against 0.88 N, 0.8 % of the ball load; F_r = 1000 N:
#: 2.3 N against 0.50 N; 1700 rad/s: 4.4 N against 1.6 N). Since the cage
#: contacts' step scales with load^-1/6, the peak puts their limit up to 1.41
#: times lower (7.6 us for the F_a = 2000 N scene, against the 8.9 us
#: estimate); basing the assumption on the peak (0.8 %) would lower the 6208's
#: steady estimate from 8.2 us (normal contacts) to about 5.9 us (cage) and
#: make the README's 8 us step warn. Kept at the settled load: a step above
#: the transient's cage limit makes the cage loads chatter during the
#: transient (the blow-up ratio, :data:`CAGE_BLOW_UP_RATIO`, is 1.6, above
#: the 1.41), and the engines check the loads a run actually reached
#: (:func:`cage_load_check`) and warn when they put the cage's step below dt.
STEADY_CAGE_LOAD = 1e-3
#: Ratio of the step to the cage contacts' estimate from which runs may blow
#: up (validation/studies/step_limits.py: the 7208 blew up at 1.60, the 6208 protocol
#: at 1.81 with the implicit and 2.07 with the explicit spring; runs at 1.28,
#: 1.29 and 1.55 only chattered, and so did the explicit 6208 protocol at 1.81).
CAGE_BLOW_UP_RATIO = 1.6
#: The same with ``cage_damping="implicit"``: its damping at the step is smaller, and an instability of its
#: contacts is an oscillation that grows rather than a chatter held by the damping; the 7208 of
#: validation/studies/cage_step_checks.py blew up at 1.26 times its estimate and chattered at 0.84 of it. A step above
#: the implicit cage estimate may blow up.
CAGE_BLOW_UP_RATIO_IMPLICIT = 1.0


def explicit_step_factor(zeta=0.0, integrator="verlet", damping="explicit"):
    """Stable step of a linear oscillator x'' + 2 zeta omega x' + omega^2 x = 0
    under the engines' explicit integrators, in units of 1/omega.

    Velocity Verlet with the damping force evaluated at the half-step
    velocity (as the kernels do): 2 (sqrt(1 + zeta^2) - zeta), where the
    spectral radius of the step's amplification matrix reaches 1 (2 without
    damping, 0.83 at critical damping; tests/test_reference.py checks it
    against that matrix). With ``damping="implicit"`` the damper acts with
    the backward-Euler coefficient c / (1 + c dt / m)
    (:func:`~exudyn_bearing.physics.damping.implicit_damping`), a damping
    ratio zeta / (1 + 2 zeta omega dt) at the step: the factor x solves
    x = 2 (sqrt(1 + z^2) - z), z = zeta / (1 + 2 zeta x) (1.58 at critical
    damping; velocity Verlet only). Classical RK4: 2.83 (2 sqrt 2) on the
    imaginary axis without damping; for zeta >= 1 the real eigenvalue
    -omega (zeta + sqrt(zeta^2 - 1)) must stay within the real-axis limit
    2.785 of RK4's stability polynomial (Hairer & Wanner, Solving ODEs II,
    sec. IV.2).
    """
    zeta = float(zeta)
    if not zeta >= 0.0:
        raise InputError(f"zeta: the damping ratio must be >= 0, got {zeta}")
    if damping not in ("explicit", "implicit"):
        raise InputError(f"damping: must be 'explicit' or 'implicit', got {damping!r}")
    if integrator == "verlet":
        if damping == "explicit" or zeta == 0.0:
            return 2.0 * (math.sqrt(1.0 + zeta * zeta) - zeta)
        # x < f(x) is x^2 + 4 z(x) x < 4, whose left side grows with x (from 0 at x = 0 to above 4 at x = 2):
        # one root in (0, 2), found by bisection to round-off
        lo, hi = 0.0, 2.0
        for _ in range(200):
            x = 0.5 * (lo + hi)
            z = zeta / (1.0 + 2.0 * zeta * x)
            if x < 2.0 * (math.sqrt(1.0 + z * z) - z):
                lo = x
            else:
                hi = x
            if hi - lo <= 1e-15:
                break
        return 0.5 * (lo + hi)
    if integrator != "rk4":
        raise InputError(f"integrator: must be 'verlet' or 'rk4', got {integrator!r}")
    if damping == "implicit":
        raise InputError("damping: the implicit damping is given for velocity Verlet only, not rk4")
    if zeta == 0.0:
        return 2.0 * math.sqrt(2.0)
    if zeta < 1.0:
        raise InputError(f"zeta: the RK4 bound is given for zeta = 0 or zeta >= 1, got {zeta}")
    return 2.785 / (zeta + math.sqrt(zeta * zeta - 1.0))


@dataclass
class StableStep:
    """Stable-step estimate of a scene [s] and what sets it."""

    dt: float
    normal: float
    tangential: float
    friction: float
    cage: float
    limited_by: str
    #: ball / cage-ball contact load [N] the cage limit was taken at, and why
    cage_load: float = math.nan
    cage_basis: str = ""
    #: the scene's ``cage_damping`` the cage limit was taken with
    cage_damping: str = "explicit"
    #: the scene's cage model (Scenario.cage): "torus", "rigid" or "none"
    cage_kind: str = "torus"
    #: the scene's traction level (Scenario.traction_level): the "friction" limit is the regularised point friction
    #: at "point", the low-slip slope of the traction law over the ellipse at "ellipse"
    traction_level: str = "point"

    @property
    def cage_blow_up(self) -> float:
        """Ratio of a step to the cage limit (with ``STABILITY_SAFETY``) from which a run may blow up."""
        return CAGE_BLOW_UP_RATIO_IMPLICIT if self.cage_damping == "implicit" else CAGE_BLOW_UP_RATIO


def _static_solution(b: BallBearing, scenario: Scenario):
    """Quasi-static solution under the scenario's F_r, F_a (None for an
    unloaded bearing with clearance, which has no equilibrium to solve);
    InputError for loads outside the elastic contact model
    (:func:`~exudyn_bearing.model.load_range.check_load_range`)."""
    return check_load_range(b, scenario.Fr, scenario.Fa, scenario.hertz)


def _static_ball_loads(b: BallBearing, scenario: Scenario) -> np.ndarray:
    """Quasi-static ball loads [N] under the scenario's F_r, F_a (zeros without an equilibrium)."""
    sol = _static_solution(b, scenario)
    return np.zeros(b.n_balls) if sol is None else sol.q


def expected_cage_load(bearing: BallBearing, scenario: Scenario, solution=None) -> tuple[float, str]:
    """(fraction of the ball load, reason): the ball / cage-ball contact load
    the a-priori stable step assumes for the scene.

    :data:`STEADY_CAGE_LOAD` for a run that starts from the analytic state
    at its speed (``initial="analytic"``, no start-up ramp), ends before any
    slow-down and whose loaded balls share one contact angle (their
    kinematic cage speeds agree within 1e-6); :data:`START_UP_CAGE_LOAD`
    otherwise. ``solution``: the scene's quasi-static solution if known.
    """
    s = scenario
    reasons = []
    if s.t_ramp_up > 0.0:
        reasons.append("start-up")
    elif s.initial != "analytic":
        reasons.append("start from rest")
    if s.t_end > s.t_ramp_up + s.t_steady:
        reasons.append("slow-down")
    if reasons:
        return START_UP_CAGE_LOAD, " and ".join(reasons)
    b = bearing if s.Pd is None else bearing.with_clearance(s.Pd)
    sol = _static_solution(b, s) if solution is None else solution
    if sol is not None:
        loaded = sol.q > 0.0
        if loaded.any():
            wc = kinematics.cage_speed(1.0, 0.0, b.ball_radius, b.pitch_radius, sol.contact_angle[loaded])
            if np.ptp(wc) > 1e-6 * np.max(np.abs(wc)):
                return START_UP_CAGE_LOAD, "loaded balls at unequal contact angles"
    return STEADY_CAGE_LOAD, "steady run from the analytic state"


def stable_step(bearing: BallBearing, scenario: Scenario, lubricant: Lubricant | None = None,
                cage_load: float | None = None, land_eccentricity: float | None = None) -> StableStep:
    """Largest stable time step of the explicit integrator for a scene [s] (the scene's cage model on
    ``bearing``: :func:`~.scenario.resolve_cage`).

    ``STABILITY_SAFETY`` times the smallest of the limits below, linearised at
    the largest expected ball load (quasi-static Q_max plus the
    centrifugal force m r_p omega_c^2 at the top speed); the limits are
    f/omega with f = :func:`explicit_step_factor` (2 for Verlet, 2.83 for RK4
    without damping) for
    the normal Hertz springs of both races (omega^2 = (k_i + k_o)/m_b), the
    Cundall-Strack tangential springs (the ball's rocking mode, omega^2 =
    (k_ti + k_to) R_b^2 / I_b = 2.5 (k_ti + k_to)/m_b; an explicit spring
    above this step does not blow up, its force saturates at mu F_n and
    chatters, which validation/performance/bench_reference.py shows in the slip), the
    regularised-friction damping
    (dt < 2 m_eff / c resp. 2.83 m_eff / c, c = 2 mu Q / v_reg) and the
    traction over the ellipse (``traction_level="ellipse"``: its linear
    slope at small slip acts as a viscous damper,
    :func:`ellipse_traction_damping`, counted as the friction limit), the
    critically damped ball / cage-ball contacts (two per cage ball, f at
    zeta = 1: 0.83 for Verlet, 1.58 with ``cage_damping="implicit"``) at ``cage_load`` [N] (default
    :func:`expected_cage_load`: a tenth of the ball load in start-up,
    slow-down, from rest or at unequal contact angles, 0.1 % in steady runs
    from the analytic state; the engines check the loads a run reaches,
    :func:`cage_load_check`). With the rigid cage the cage limit is
    :func:`rigid_cage_step`'s (pockets and land).

    What happens above each limit (validation/studies/step_limits.py): above the
    normal limit the run blows up; above the tangential (explicit spring)
    or regularised-friction limit the friction forces may chatter at their
    Coulomb cap (slip and frictional power wrong; the explicit spring did at
    1.26 times its limit, the regularised friction, whose estimate takes
    mu_boundary, at 3.7 times but not at 2.2 times); above the cage limit the
    cage loads chatter at about twice their value, and from about
    :data:`CAGE_BLOW_UP_RATIO` times it runs may blow up (with the implicit
    cage damping, :data:`CAGE_BLOW_UP_RATIO_IMPLICIT`: right above it). The implicit
    tangential spring sets no limit.
    """
    scenario = resolve_cage(scenario, bearing)
    b = bearing if scenario.Pd is None else bearing.with_clearance(scenario.Pd)
    lub = default_lubricant(b) if lubricant is None else lubricant
    mb = b.ball_mass
    wc = float(kinematics.cage_speed(scenario.omega, scenario.omega_outer, b.ball_radius, b.pitch_radius,
                                     b.free_contact_angle))
    q_cf = float(kinematics.centrifugal_force(mb, b.pitch_radius, wc))
    sol = _static_solution(b, scenario)
    q_static = 0.0 if sol is None else float(sol.q.max())
    q = max(q_static + q_cf, 10.0)
    ki, ko, _kn = race_stiffness(b, b.free_contact_angle, scenario.hertz)
    kt_i = float(hertz.tangent_stiffness(ki, q))
    kt_o = float(hertz.tangent_stiffness(ko, q))
    factor = explicit_step_factor(0.0, scenario.integrator)
    dt_n = factor / math.sqrt((kt_i + kt_o) / mb)
    dt_t = math.inf
    dt_f = math.inf
    mu = lub.mu_boundary if scenario.lubrication else scenario.mu_dry
    if scenario.friction == "history" and scenario.tangential == "explicit":
        dt_t = factor / math.sqrt(scenario.tangential_stiffness_ratio * (kt_i + kt_o) * 2.5 / mb)
    elif scenario.friction == "regularized" and mu > 0:
        dt_f = factor * sphere_tangential_mass(mb) / (2.0 * mu * q / scenario.regularizing_speed)
    if scenario.traction_level == "ellipse":
        dt_t = math.inf  # no tangential spring at the ellipse level
        dt_f = factor * sphere_tangential_mass(mb) / ellipse_traction_damping(b, scenario, lub, q)
    dt_c = math.inf
    load_c, basis = math.nan, ""
    if scenario.cage == "torus" and b.has_cage:
        mz = b.cage_ball_mass
        em = material_reduced_modulus(b.material)
        kbz = float(hertz.sphere_sphere_stiffness(b.ball_radius, b.cage_ball_radius, em))
        if cage_load is None:
            fraction, basis = expected_cage_load(b, scenario.replace(Pd=None), sol)
            load_c = fraction * q
        else:
            load_c, basis = max(float(cage_load), 1e-3), "given"
        kc = float(hertz.tangent_stiffness(kbz, load_c))
        dt_c = (explicit_step_factor(1.0, scenario.integrator, scenario.cage_damping)
                / math.sqrt(2.0 * kc * (mb + mz) / (mb * mz)))
    if scenario.cage == "rigid":
        dt_c, load_c, basis = rigid_cage_step(b, scenario, lub, q, sol, cage_load, land_eccentricity)
    parts = {"normal": dt_n, "tangential": dt_t, "friction": dt_f, "cage": dt_c}
    name = min(parts, key=parts.get)
    return StableStep(STABILITY_SAFETY * parts[name], dt_n, dt_t, dt_f, dt_c, name, load_c, basis,
                      scenario.cage_damping, scenario.cage, scenario.traction_level)


#: Eccentricity ratio of the land film at which the a-priori stable step of a land-guided rigid cage is taken
#: (the engines check the eccentricity a run reaches: :func:`land_step_check`).
LAND_DESIGN_ECCENTRICITY = 0.9


def land_film_step(bearing: BallBearing, scenario: Scenario, lubricant: Lubricant, eccentricity: float) -> float:
    """Explicit stable step [s] of a land-guided rigid cage on its film at the eccentricity ratio eps: the
    cage mass m_c on the film's radial stiffness k = (mu R L^3 omega_c / c^3) 2 eps (1 + eps^2) / (1 - eps^2)^3
    (the derivative of Ocvirk's radial force at the kinematic cage speed, plus the outer ring's speed for an
    outer-land guided cage) and its squeeze damping
    C = (pi/2) (mu R L^3 / c^3) (1 + 2 eps^2) / (1 - eps^2)^(5/2) (docs/theory/cage.md#land-film), by
    :func:`explicit_step_factor` at zeta = C / (2 sqrt(k m_c)). inf for a ball-guided cage, and with
    ``cage_damping='implicit'``, which takes the land's force linearly implicit (stiffness and damping:
    no step limit of its linearisation)."""
    rc = scenario.rigid_cage_of(bearing)
    if rc.guidance == "ball" or scenario.cage_damping == "implicit":
        return math.inf
    b = bearing
    e = min(max(float(eccentricity), 1e-3), 1.0 - 1e-9)
    wc = float(kinematics.cage_speed(scenario.omega, scenario.omega_outer, b.ball_radius, b.pitch_radius,
                                     b.free_contact_angle))
    if rc.guidance == "outer":  # the film's surfaces turn together: cage and a rotating outer ring (the kernel's)
        wc += scenario.omega_outer
    wc = abs(wc)
    sc = lubricant.viscosity * rc.guide_radius * rc.land_width ** 3 / rc.land_clearance ** 3
    k = sc * wc * 2.0 * e * (1.0 + e * e) / (1.0 - e * e) ** 3
    c = 0.5 * math.pi * sc * (1.0 + 2.0 * e * e) / (1.0 - e * e) ** 2.5
    m = rc.mass(b)
    if k <= 0.0:  # a cage at rest: the squeeze alone, stable below 2 m / C
        return 2.0 * m / c
    zeta = c / (2.0 * math.sqrt(k * m))
    if scenario.integrator == "rk4" and 0.0 < zeta < 1.0:
        zeta = 1.0  # RK4's bound is given at zeta >= 1: the critically damped one, a lower bound
    return explicit_step_factor(zeta, scenario.integrator, scenario.cage_damping) / math.sqrt(k / m)


def rigid_cage_step(b: BallBearing, scenario: Scenario, lub: Lubricant, q: float, sol, cage_load=None,
                    land_eccentricity=None) -> tuple[float, float, str]:
    """(limit [s], pocket load [N], basis) of the rigid cage: the smaller of the critically damped ball /
    pocket contact (the reduced mass of ball and cage on the tangent Hertz stiffness at the pocket load:
    ``cage_load`` or :func:`expected_cage_load` of the ball load ``q``) and the land film
    (:func:`land_film_step` at ``land_eccentricity``, default :data:`LAND_DESIGN_ECCENTRICITY`)."""
    rc = scenario.rigid_cage_of(b)
    e_pocket = hertz.reduced_modulus(b.material.youngs_modulus, b.material.poisson_ratio, rc.material.youngs_modulus,
                                     rc.material.poisson_ratio)
    kp = float(hertz.ball_in_pocket_stiffness(b.ball_radius, rc.pocket_clearance, rc.pocket_shape == "cylindrical",
                                              float(e_pocket), scenario.hertz))
    if cage_load is None:
        fraction, basis = expected_cage_load(b, scenario.replace(Pd=None), sol)
        load = fraction * q
    else:
        load, basis = max(float(cage_load), 1e-3), "given"
    mb, mc = b.ball_mass, rc.mass(b)
    kt = float(hertz.tangent_stiffness(kp, load))
    pocket = explicit_step_factor(1.0, scenario.integrator, scenario.cage_damping) / math.sqrt(kt * (mb + mc) / (mb * mc))
    ecc = LAND_DESIGN_ECCENTRICITY if land_eccentricity is None else float(land_eccentricity)
    land = land_film_step(b, scenario, lub, ecc)
    if land < pocket:
        basis = f"land film at eccentricity {ecc:.3g}"
    film = pocket_film_step(b, scenario, lub)
    if film < min(pocket, land):
        basis = "pocket film at its thinnest (the composite roughness)"
    return min(pocket, land, film), load, basis


def pocket_film_step(bearing: BallBearing, scenario: Scenario, lubricant: Lubricant) -> float:
    """Explicit stable step [s] of the ball / pocket film (``Scenario.pocket_film``; inf without it) at its
    thinnest, h = the composite roughness: the reduced mass of ball and cage on the hydrodynamic force's
    stiffness k = w / (2 h) (:func:`~exudyn_bearing.physics.pocket_film.hydrodynamic_film_force`, w ~ h^-1/2;
    the entraining speed half the ball's kinematic spin speed R_b |omega_R| at ``scenario.omega``) and the
    squeeze damping C = 6 pi eta R_b^2 / h, by :func:`explicit_step_factor` at zeta = C / (2 sqrt(k m)); with
    ``cage_damping='implicit'`` the squeeze is backward Euler and only the stiffness limits the step."""
    if not scenario.pocket_film:
        return math.inf
    from ..physics import pocket_film as pf

    b = bearing
    rc = scenario.rigid_cage_of(b)
    h = lubricant.composite_roughness
    r_x, alpha_r = pf.pocket_film_radii(b.ball_radius, rc.pocket_clearance, rc.pocket_shape == "cylindrical")
    spin = abs(float(kinematics.ball_spin_relative(scenario.omega, 0.0, b.ball_radius, b.pitch_radius,
                                                   b.free_contact_angle)))
    k = float(pf.hydrodynamic_film_force(lubricant.viscosity, 0.5 * b.ball_radius * spin, r_x, alpha_r, h)) / (2.0 * h)
    c = float(pf.squeeze_film_damping(lubricant.viscosity, b.ball_radius, h))
    mb, mc = b.ball_mass, rc.mass(b)
    m = mb * mc / (mb + mc)
    if k <= 0.0:  # the rings at rest: the squeeze alone, stable below 2 m / C unless backward Euler
        return math.inf if scenario.cage_damping == "implicit" else 2.0 * m / c
    zeta = c / (2.0 * math.sqrt(k * m))
    return explicit_step_factor(zeta, scenario.integrator, scenario.cage_damping) / math.sqrt(k / m)


def _below(limit: float, dt: float) -> str:
    """"LIMIT s < dt = DT s" with as many digits as it takes for the two to read apart (3 to 6)."""
    for digits in (3, 4, 5, 6):
        a, b = f"{limit:.{digits}g}", f"{dt:.{digits}g}"
        if a != b:
            break
    return f"{a} s < dt = {b} s"


def land_step_check(bearing: BallBearing, scenario: Scenario, lubricant: Lubricant | None, eccentricity: float,
                    dt: float) -> str | None:
    """A warning text when the land film at the largest eccentricity a run reached has a stable step
    (:func:`land_film_step`, with ``STABILITY_SAFETY``) below the run's step ``dt``, else None."""
    scenario = resolve_cage(scenario, bearing)
    if scenario.cage != "rigid" or not eccentricity > 0.0:
        return None
    b = bearing if scenario.Pd is None else bearing.with_clearance(scenario.Pd)
    lub = default_lubricant(b) if lubricant is None else lubricant
    limit = STABILITY_SAFETY * land_film_step(b, scenario, lub, min(eccentricity, 1.0 - 1e-9))
    if dt <= limit:
        return None
    return (f"dt: the rigid cage reached a land eccentricity of {eccentricity:.3g}, where the land film's stable "
            f"step is {_below(limit, dt)}; the cage's motion and land force of this run are unreliable: "
            "reduce dt or use cage_damping='implicit'")


def ellipse_traction_damping(bearing: BallBearing, scenario: Scenario, lubricant: Lubricant, load: float) -> float:
    """Viscous coefficient [N s/m] of the ellipse-level traction of a ball on
    both races for a small uniform slip: c = 2 Q mu'(0) / u, the traction
    slope mu'(0) taken as the secant mu(s)/s at s = 1e-3 of the scenario's
    (regularised) traction model at the inner contact (pressure p_max, Hamrock
    & Dowson films at the kinematic rolling speed u, at least the
    :func:`ellipse_rolling_floor` the kernel uses as the least rolling speed). The
    explicit step must stay below 2 m_t / c (velocity Verlet), m_t the
    sphere's tangential mass."""
    from ..physics import ehl
    from ..physics.geometry import raceway_radii
    from ..physics.traction import traction_coefficient
    from .parameters import dynamic_traction_model

    b = bearing
    a0 = b.free_contact_angle
    u_i, _u_o = kinematics.rolling_speeds(scenario.omega, scenario.omega_outer, b.ball_radius, b.pitch_radius, a0)
    u = max(float(u_i), ellipse_rolling_floor(b, scenario))
    em = material_reduced_modulus(b.material)
    rx, ry = raceway_radii(b.ball_radius, b.inner_groove_radius, b.pitch_radius - b.ball_radius * math.cos(a0), a0,
                           True)
    hc = hertz.hertz_contact(rx, ry, em, load=load, method=scenario.hertz)
    kappa = max(float(hc.kappa), 1.0 / float(hc.kappa))
    hm = float(ehl.film_thickness_hamrock_dowson(u, load, rx, kappa, em, lubricant.viscosity,
                                                 lubricant.pressure_viscosity))
    hcen = float(ehl.film_thickness_central_hamrock_dowson(u, load, rx, kappa, em, lubricant.viscosity,
                                                           lubricant.pressure_viscosity))
    s = 1e-3
    mu = float(traction_coefficient(dynamic_traction_model(scenario), s * u, u, float(hc.p_max), hcen, hm))
    return max(2.0 * load * (mu / s) / u, 1e-12)


def step_warning(label: str, dt: float, stable: StableStep) -> str | None:
    """The warning text for a step ``dt`` above the estimate ``stable.dt``
    (``label`` names the step, e.g. "dt = 5e-06 s"), else None.

    Names every limit the step exceeds (each ``STABILITY_SAFETY`` times the
    linearised one) and what follows from it: the normal contacts blow up;
    the tangential springs and the regularised friction may chatter at
    their Coulomb cap; the cage loads may chatter and, from
    :data:`CAGE_BLOW_UP_RATIO` times their limit, the run may blow up
    (measured in validation/studies/step_limits.py)."""
    if not dt > stable.dt:
        return None
    limits = {k: STABILITY_SAFETY * getattr(stable, k) for k in ("normal", "tangential", "friction", "cage")}
    over = [k for k, v in limits.items() if dt > v]
    names = {"normal": "normal contacts of the balls", "tangential": "explicit tangential (Cundall-Strack) springs",
             "friction": ("regularised friction" if stable.traction_level == "point" else
                          "traction over the ellipse (its low-slip slope, the traction model's)"),
             "cage": ("rigid cage's pocket and land contacts" if stable.cage_kind == "rigid" else
                      "ball / cage-ball contacts")}
    extra = {k: "" for k in names}
    if math.isfinite(stable.cage_load):
        extra["cage"] = f" at {stable.cage_load:.3g} N, {stable.cage_basis}"
    listed = [f"the {names[k]} ({limits[k]:.3g} s{extra[k]})" for k in over]
    text = (f"{label} exceeds the stable step of " + ", ".join(listed[:-1]) + (" and " if len(listed) > 1 else "")
            + listed[-1] + ". ")
    blow = [k for k in over if k == "normal" or (k == "cage" and dt >= stable.cage_blow_up * limits[k])]
    if blow:
        text += "The run " + ("will" if "normal" in blow else "may") + " blow up (" + " and ".join(
            "normal contacts" if k == "normal" else f"cage contacts, dt >= {stable.cage_blow_up:g} times their limit"
            for k in blow) + "). "
    if "tangential" in over or "friction" in over:
        text += (("The friction forces may chatter at their Coulomb cap" if stable.traction_level == "point" else
                  "The tractions may chatter about their low-slip slope") + ": slip and frictional power wrong"
                 + (" (tangential='implicit' lifts the springs' limit)" if "tangential" in over else "") + ". ")
    if "cage" in over and "cage" not in blow:
        text += ("The cage loads may chatter at about twice their value (ball loads and speeds are not "
                 "affected; the loads the run reaches are checked at its end). ")
    if "cage" in over and stable.cage_damping == "explicit":
        text += "cage_damping='implicit' lifts the cage contacts' limit about 1.9 times. "
    return text + "Reduce the step."


def runaway_error(option: str, t: float, stable: StableStep, what: str = "non-finite or runaway", step: str = "",
                  ring: str = "", remedy: str = "the solver step", bad_input: tuple[str, str] | None = None,
                  excess: tuple[float, float, str] | None = None) -> SimulationError:
    """The :class:`SimulationError` of an engine whose state became ``what``
    at ``t`` [s], naming the cause the evidence shows (one text for both
    engines and both element modes).

    ``bad_input``: (option, description) when the state handed to the engine
    was already non-finite (e.g. ``("markerInnerRing", "the inner ring
    marker's position and velocity")``): the input, not the step. ``excess``:
    (ball load [N], contact pressure [Pa], race) when the loads the run
    reached before the runaway exceed the elastic contact limit
    (:data:`~exudyn_bearing.model.load_range.MAX_CONTACT_PRESSURE`, found with
    :func:`~exudyn_bearing.model.load_range.pressure_excess`) and the step is
    within the estimate: the loads are the likely cause. Otherwise the step:
    ``option`` names it, ``step`` (" with dt = ... s") and ``ring`` (a further
    limit) are added to the estimate ``stable``, ``remedy`` is what to reduce."""
    head = f"the bearing state became {what} at t = {t:.6g} s"
    if bad_input is not None:
        name, text = bad_input
        return SimulationError(f"{name}: {head}: {text} handed to the bearing element from the Exudyn model "
                               "became non-finite (check the model's loads, initial values and user functions); "
                               "the input is non-finite, not the step")
    if excess is not None:
        q, p, race = excess
        return SimulationError(f"load: {head}{step}: before it, the ball loads reached at least {q:.4g} N, a contact "
                               f"pressure of {p / 1e9:.3g} GPa at the {race} race, above {MAX_CONTACT_PRESSURE / 1e9:g} "
                               "GPa, the limit of the elastic contact model (ISO 76 static load rating): the loads on "
                               "the bearing are the likely cause, not the step; reduce the load")
    return SimulationError(f"{option}: {head}{step}; the stable-step estimate is {stable.dt:.3g} s (limited by the "
                           f"{stable.limited_by} contact){ring}: reduce {remedy}")


def cage_load_check(bearing: BallBearing, scenario: Scenario, lubricant: Lubricant | None, max_cage_load: float,
                    dt: float) -> str | None:
    """A warning text when the largest ball / cage-ball load a run reached
    puts those contacts' stable step (:func:`stable_step` at that load, with
    ``STABILITY_SAFETY``) below its step ``dt``, else None."""
    scenario = resolve_cage(scenario, bearing)
    if not max_cage_load > 0.0 or not ((scenario.cage == "torus" and bearing.has_cage) or scenario.cage == "rigid"):
        return None
    # the rigid cage's land has a check of its own (land_step_check): its film taken at a small eccentricity
    limit = STABILITY_SAFETY * stable_step(bearing, scenario, lubricant, cage_load=max_cage_load,
                                           land_eccentricity=1e-3).cage
    if dt <= limit:
        return None
    kind = "ball / pocket" if scenario.cage == "rigid" else "ball / cage-ball"
    return (f"dt: the {kind} contacts reached {max_cage_load:.3g} N, where their stable step is "
            f"{_below(limit, dt)}; the cage loads of this run are unreliable (they chatter at about "
            "twice their value), ball loads and speeds usually are not affected: reduce dt")


def ring_contact_stiffness(bearing: BallBearing, scenario: Scenario, race: str = "inner") -> float:
    """Sum of the tangent stiffnesses dQ/d delta of one race's ball contacts [N/m].

    Each contact at its quasi-static load under the scenario's F_r, F_a
    (10 N on every ball when no ball carries more; outer contacts plus the
    centrifugal force at the scenario's speed), summed as if all acted along
    one direction: an upper bound of the stiffness the ring body feels in
    any direction (Harris & Kotzalas tangent stiffness, :func:`hertz.tangent_stiffness`).
    """
    if race not in ("inner", "outer"):
        raise InputError(f"race: must be 'inner' or 'outer', got {race!r}")
    b = bearing if scenario.Pd is None else bearing.with_clearance(scenario.Pd)
    q = _static_ball_loads(b, scenario)
    if q.max() < 10.0:
        q = np.full(b.n_balls, 10.0)
    ki, ko, _kn = race_stiffness(b, b.free_contact_angle, scenario.hertz)
    if race == "outer":
        wc = float(kinematics.cage_speed(scenario.omega, scenario.omega_outer, b.ball_radius, b.pitch_radius,
                                         b.free_contact_angle))
        q = q + float(kinematics.centrifugal_force(b.ball_mass, b.pitch_radius, wc))
    return float(np.sum(hertz.tangent_stiffness(ki if race == "inner" else ko, q)))


#: Share of the ring's stable-step estimate (:func:`ring_stable_step`) that the fast mode's Exudyn step
#: may take with two or more sub-steps (one sub-step is the body mode's scheme). The fast mode couples
#: ring and balls staggered (the ring, in Exudyn, gets the mean reaction of the balls' sub-steps), and
#: that coupling, not the ring's own Verlet limit, sets the step: in
#: ``validation/studies/fast_mode_limits.py`` (6208, ring masses 81 g ... 5 kg at F_r = 3000 N, 81 g and 1.25 kg at
#: 600 N; it prints these figures) every run with H up to a quarter of the estimate kept q_max_inner within
#: 0.2 % of the reference engine, the first run off by more than 0.5 % came at 0.30 ... 0.80 of it, and
#: from 0.5 ... 1.1 of it a growing ring vibration put them more than 10 % off (several times, further out)
#: or blew the run up.
FAST_STEP_SHARE = 0.25


def ring_stable_step(bearing: BallBearing, scenario: Scenario, ring_mass: float, race: str = "inner") -> float:
    """Largest stable velocity-Verlet step [s] for a ring of mass ``ring_mass``
    on the ball contacts of its race, alone (the balls held).

    2/omega with omega^2 = :func:`ring_contact_stiffness` / m_ring, no safety
    factor: the 81 g ring of the 6208 test scene at F_r = 3000 N gets
    22.8 us. The fast mode's Exudyn step must stay well below it
    (:data:`FAST_STEP_SHARE`). For a ring on a rigid body
    with several bearings the element uses the body's mass matrix and all
    its bearings (``BallBearingElement.ringStableStep``).
    """
    if not ring_mass > 0.0 or not math.isfinite(ring_mass):
        raise InputError(f"ring_mass: must be a positive finite mass [kg], got {ring_mass}")
    return 2.0 / math.sqrt(ring_contact_stiffness(bearing, scenario, race) / ring_mass)
