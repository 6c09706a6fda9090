"""Driver of the numba DEM reference engine: scene set-up, initial state,
stable-step estimate, chunked integration with progress, results.

The engine simulates a complete ball bearing ball by ball (PHYSICS.md
sec. 2-7): Z balls and Z cage balls with 6 DOF, the inner ring translating
freely under the applied loads and spun at the prescribed omega(t), the outer
ring fixed. It does not import exudyn.
"""
from __future__ import annotations

import math
import sys
import time
import warnings
from dataclasses import dataclass

import numpy as np

from ..analysis import default_lubricant, e_prime_of
from ..data import BallBearing, InputError, Lubricant, load_bearing
from ..physics import hertz, kinematics
from ..physics.ehl import film_model_code
from ..physics.friction import sphere_tangential_mass
from ..physics.load_distribution import race_stiffness, static_equilibrium
from ..scenario import FRICTION_MODELS, Scenario
from . import kernels as K

__all__ = ["ReferenceEngine", "SimulationError", "StepSizeWarning", "stable_step", "ring_stable_step",
           "ring_contact_stiffness", "ring_mass_estimate", "scene_parameters", "explicit_step_factor",
           "cage_load_check", "step_warning"]


class SimulationError(RuntimeError):
    """The integration produced a non-finite or runaway state."""


class StepSizeWarning(UserWarning):
    """The time step exceeds the stable-step estimate of the scene."""


def ring_mass_estimate(bearing: BallBearing) -> float:
    """Approximate inner-ring mass [kg]: an annulus from R_i - 0.65 R_b to R_i,
    2.9 R_b wide (proportions of a 62xx ring).

    >>> from exudyn_bearing import catalog
    >>> round(1e3 * ring_mass_estimate(catalog["6208"]))  # g
    81
    """
    ri, rb = bearing.inner_race_radius, bearing.ball_radius
    return bearing.material.density * math.pi * (ri ** 2 - (ri - 0.65 * rb) ** 2) * 2.9 * rb


#: Factor between the linearised single-ball limit and the reported stable
#: step: the two races, the ring and load peaks couple the modes (the 6208 at
#: 500 rad/s with the implicit tangential spring blows up at 0.93 of the
#: linearised normal limit; validation/bench_reference.py measures it).
STABILITY_SAFETY = 0.85


def explicit_step_factor(zeta=0.0, integrator="verlet"):
    """Stable step of a linear oscillator x'' + 2 zeta omega x' + omega^2 x = 0
    under the engines' explicit integrators, in units of 1/omega.

    Velocity Verlet with the damping force evaluated at the half-step
    velocity (as the kernels do): 2 (sqrt(1 + zeta^2) - zeta), where the
    spectral radius of the step's amplification matrix reaches 1 (2 without
    damping, 0.83 at critical damping; tests/test_reference.py checks it
    against that matrix). Classical RK4: 2.83 (2 sqrt 2) on the imaginary
    axis without damping; for zeta >= 1 the real eigenvalue
    -omega (zeta + sqrt(zeta^2 - 1)) must stay within the real-axis limit
    2.785 of RK4's stability polynomial (Hairer & Wanner, Solving ODEs II,
    sec. IV.2).
    """
    zeta = float(zeta)
    if not zeta >= 0.0:
        raise InputError(f"zeta: the damping ratio must be >= 0, got {zeta}")
    if integrator == "verlet":
        return 2.0 * (math.sqrt(1.0 + zeta * zeta) - zeta)
    if integrator != "rk4":
        raise InputError(f"integrator: must be 'verlet' or 'rk4', got {integrator!r}")
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


def _static_ball_loads(b: BallBearing, scenario: Scenario) -> np.ndarray:
    """Quasi-static ball loads [N] under the scenario's F_r, F_a (zeros for an
    unloaded bearing with clearance, which has no equilibrium to solve)."""
    if scenario.Fr > 0 or scenario.Fa > 0 or b.diametral_clearance < 0:
        return static_equilibrium(b, scenario.Fr, scenario.Fa, hertz_method=scenario.hertz).q
    return np.zeros(b.n_balls)


def stable_step(bearing: BallBearing, scenario: Scenario, lubricant: Lubricant | None = None,
                cage_load: float | None = None) -> StableStep:
    """Largest stable time step of the explicit integrator for a scene [s].

    ``STABILITY_SAFETY`` times the smallest of the limits below, linearised at
    the largest expected ball load (quasi-static Q_max plus the
    centrifugal force m r_p omega_c^2 at the top speed); the limits are
    f/omega with f = :func:`explicit_step_factor` (2 for Verlet, 2.83 for RK4
    without damping) for
    the normal Hertz springs of both races (omega^2 = (k_i + k_o)/m_b), the
    Cundall-Strack tangential springs (the ball's rocking mode, omega^2 =
    (k_ti + k_to) R_b^2 / I_b = 2.5 (k_ti + k_to)/m_b; an explicit spring
    above this step does not blow up, its force saturates at mu F_n and
    chatters, which validation/bench_reference.py shows in the slip), the
    regularised-friction damping
    (dt < 2 m_eff / c resp. 2.83 m_eff / c, c = 2 mu Q / v_reg) and the
    critically damped ball / cage-ball contacts (two per cage ball, f at
    zeta = 1: 0.83 for Verlet) at ``cage_load`` [N] (default a tenth of the
    ball load, the order of the start-up and slow-down loads of the 6208;
    the engines check the loads a run reaches, :func:`cage_load_check`).
    Above the cage limit a run need not blow up: the cage loads grow about
    twofold and chatter (validation/REPORT.md). The implicit tangential
    spring sets no limit.
    """
    b = bearing if scenario.Pd is None else bearing.with_clearance(scenario.Pd)
    lub = default_lubricant() if lubricant is None else lubricant
    mb = b.ball_mass
    wc = float(kinematics.cage_speed(scenario.omega, 0.0, b.ball_radius, b.pitch_radius, b.free_contact_angle))
    q_cf = float(kinematics.centrifugal_force(mb, b.pitch_radius, wc))
    q = max(float(_static_ball_loads(b, scenario).max()) + q_cf, 10.0)
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
    dt_c = math.inf
    if scenario.cage and b.has_cage:
        mz = b.cage_ball_mass
        em = e_prime_of(b)
        kbz = float(hertz.sphere_sphere_stiffness(b.ball_radius, b.cage_ball_radius, em))
        kc = float(hertz.tangent_stiffness(kbz, 0.1 * q if cage_load is None else max(float(cage_load), 1e-3)))
        dt_c = explicit_step_factor(1.0, scenario.integrator) / math.sqrt(2.0 * kc * (mb + mz) / (mb * mz))
    parts = {"normal": dt_n, "tangential": dt_t, "friction": dt_f, "cage": dt_c}
    name = min(parts, key=parts.get)
    return StableStep(STABILITY_SAFETY * parts[name], dt_n, dt_t, dt_f, dt_c, name)


def step_warning(label: str, dt: float, stable: StableStep) -> str | None:
    """The warning text for a step ``dt`` above the estimate ``stable.dt``
    (``label`` names the step, e.g. "dt = 5e-06 s"), else None."""
    if dt <= stable.dt:
        return None
    what = ("the cage loads may be unreliable in start-up and slow-down (the loads a run reaches are checked at "
            "its end)" if stable.limited_by == "cage" else "the run may blow up")
    return (f"{label} exceeds the stable-step estimate {stable.dt:.3g} s (limited by the {stable.limited_by} "
            f"contact stiffness); {what}")


def cage_load_check(bearing: BallBearing, scenario: Scenario, lubricant: Lubricant | None, max_cage_load: float,
                    dt: float) -> str | None:
    """A warning text when the largest ball / cage-ball load a run reached
    puts those contacts' stable step (:func:`stable_step` at that load, with
    ``STABILITY_SAFETY``) below its step ``dt``, else None."""
    if not max_cage_load > 0.0 or not (scenario.cage and bearing.has_cage):
        return None
    limit = STABILITY_SAFETY * stable_step(bearing, scenario, lubricant, cage_load=max_cage_load).cage
    if dt <= limit:
        return None
    return (f"dt: the ball / cage-ball contacts reached {max_cage_load:.3g} N, where their stable step is "
            f"{limit:.3g} s < dt = {dt:.3g} s; the cage loads of this run are unreliable (they chatter at about "
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
        wc = float(kinematics.cage_speed(scenario.omega, 0.0, b.ball_radius, b.pitch_radius, b.free_contact_angle))
        q = q + float(kinematics.centrifugal_force(b.ball_mass, b.pitch_radius, wc))
    return float(np.sum(hertz.tangent_stiffness(ki if race == "inner" else ko, q)))


def ring_stable_step(bearing: BallBearing, scenario: Scenario, ring_mass: float, race: str = "inner") -> float:
    """Largest stable velocity-Verlet step [s] for a ring of mass ``ring_mass``
    on the ball contacts of its race (the Exudyn step of the fast mode).

    2/omega with omega^2 = :func:`ring_contact_stiffness` / m_ring. No safety
    factor: the 81 g ring of the 6208 test scene at F_r = 3000 N gets
    22.8 us; the fast mode runs at 20 us, is 59 % off at 25 us and blows up
    at 30 us (validation/fast_mode_checks.py). For a ring on a rigid body
    with several bearings the element uses the body's mass matrix and all
    its bearings (``BallBearingElement.ringStableStep``).
    """
    if not ring_mass > 0.0 or not math.isfinite(ring_mass):
        raise InputError(f"ring_mass: must be a positive finite mass [kg], got {ring_mass}")
    return 2.0 / math.sqrt(ring_contact_stiffness(bearing, scenario, race) / ring_mass)


def scene_parameters(bearing: BallBearing, scenario: Scenario, lubricant: Lubricant) -> np.ndarray:
    """Kernel parameter vector (layout ``kernels.P_*``) of a bearing, a
    scenario's model switches and loads, and a lubricant; shared by the
    reference engine and the Exudyn element."""
    b, s, lub = bearing, scenario, lubricant
    p = np.zeros(K.N_PARAMS)
    em = e_prime_of(b)
    rho_i, z_i = b.inner_groove_center
    rho_o, z_o = b.outer_groove_center
    cage = bool(s.cage and b.has_cage)
    rz = b.cage_ball_radius if cage else b.ball_radius
    p[K.P_Z] = b.n_balls
    p[K.P_RB] = b.ball_radius
    p[K.P_RCI] = b.inner_groove_radius
    p[K.P_RCO] = b.outer_groove_radius
    p[K.P_RHO_I], p[K.P_ZG_I] = rho_i, z_i
    p[K.P_RHO_O], p[K.P_ZG_O] = rho_o, z_o
    p[K.P_RZ] = rz
    p[K.P_RP] = b.pitch_radius
    p[K.P_RGUIDE] = rz + s.guide_clearance
    p[K.P_EPRIME] = em
    p[K.P_MB] = b.ball_mass
    p[K.P_IB] = 0.4 * b.ball_mass * b.ball_radius ** 2
    p[K.P_MZ] = b.cage_ball_mass if cage else 1.0
    p[K.P_MR] = s.ring_mass if s.ring_mass is not None else ring_mass_estimate(b)
    p[K.P_ALPHA_E] = b.material.hysteretic_damping
    p[K.P_ETA] = lub.viscosity
    p[K.P_XI] = lub.pressure_viscosity
    p[K.P_SIGMA] = lub.composite_roughness
    p[K.P_L1] = lub.lambda_mixed
    p[K.P_L3] = lub.lambda_full_film
    p[K.P_MU_B] = lub.mu_boundary
    p[K.P_MU_F] = lub.mu_full_film
    p[K.P_HERTZ] = hertz.method_code(s.hertz)
    p[K.P_FILM] = film_model_code(s.film)
    p[K.P_LUB] = 1.0 if s.lubrication else 0.0
    p[K.P_MU_DRY] = s.mu_dry
    p[K.P_FRIC] = FRICTION_MODELS.index(s.friction)
    p[K.P_VREG] = s.regularizing_speed
    p[K.P_KT_RATIO] = s.tangential_stiffness_ratio
    p[K.P_CAGE] = 1.0 if cage else 0.0
    p[K.P_FR] = s.Fr
    p[K.P_FA] = s.Fa
    p[K.P_W_MAX] = s.omega
    p[K.P_T_UP] = s.t_ramp_up
    p[K.P_T_STEADY] = s.t_steady if math.isfinite(s.t_steady) else 1e300
    p[K.P_T_DOWN] = s.t_ramp_down
    p[K.P_K_BZ] = float(hertz.sphere_sphere_stiffness(b.ball_radius, rz, em))
    p[K.P_K_BB] = float(hertz.sphere_sphere_stiffness(b.ball_radius, b.ball_radius, em))
    p[K.P_K_GUIDE] = 2.0 / 3.0 * em * math.sqrt(rz)
    p[K.P_DT] = s.dt
    p[K.P_AXIAL_FREE] = 1.0
    p[K.P_MAX_OVERLAP] = 0.05
    p[K.P_KT_IMPLICIT] = 1.0 if s.tangential == "implicit" else 0.0
    p[K.P_LAW] = K.LAW_POWER if s.contact_law == "power" else K.LAW_HERTZ
    p[K.P_LAW_K], p[K.P_LAW_N], p[K.P_LAW_D] = (float(x) for x in s.power_law)
    return p


class ReferenceEngine:
    """The numba DEM engine for one bearing, lubricant and scenario.

    Parameters
    ----------
    bearing : BallBearing or str
        Bearing or catalogue name / JSON path.
    scenario : Scenario
    lubricant : Lubricant, optional
        Default: the DEM papers' lubricant.
    """

    name = "reference"

    def __init__(self, bearing, scenario: Scenario, lubricant: Lubricant | None = None):
        b = load_bearing(bearing)
        if scenario.Pd is not None:
            b = b.with_clearance(scenario.Pd)
        self.bearing = b
        self.scenario = scenario
        self.lubricant = default_lubricant() if lubricant is None else lubricant
        if scenario.cage and not b.has_cage:
            raise InputError(f"cage: bearing {b.name} has no cage balls (cage_ball_radius is None); "
                             "use cage=False")
        self.params = scene_parameters(b, scenario, self.lubricant)
        self.table = hertz.exact_table()
        self.stable = stable_step(b, scenario, self.lubricant)

    # -- set-up --------------------------------------------------------
    def initial_state(self):
        """Balls at the quasi-static loaded positions (the analytic solution),
        ring at its static displacement; with ``initial='analytic'`` balls and
        cage balls at their kinematic (pure-rolling) speeds, else at rest."""
        b, s = self.bearing, self.scenario
        z = b.n_balls
        sol = static_equilibrium(b, s.Fr, s.Fa, hertz_method=s.hertz)
        rho_o, z_o = b.outer_groove_center
        a0 = b.free_contact_angle
        xb = np.zeros((z, 3))
        for j in range(z):
            if sol.q[j] > 0.0:
                al = sol.contact_angle[j]
                d = b.outer_groove_radius - b.ball_radius + sol.overlap_outer[j]
            else:
                al = a0
                d = b.outer_groove_radius - b.ball_radius
            r = rho_o + d * math.cos(al)
            xb[j] = (r * math.cos(sol.psi[j]), r * math.sin(sol.psi[j]), z_o + d * math.sin(al))
        psi_c = sol.psi + math.pi / z
        xc = np.stack([b.pitch_radius * np.cos(psi_c), b.pitch_radius * np.sin(psi_c), np.zeros(z)], axis=1)
        vb = np.zeros((z, 3))
        wb = np.zeros((z, 3))
        vc = np.zeros((z, 3))
        ring = np.zeros(6)
        ring[:3] = sol.displacement
        w0 = s.omega_at(0.0)
        if s.initial == "analytic" and w0 != 0.0:
            wc = float(kinematics.cage_speed(w0, 0.0, b.ball_radius, b.pitch_radius, a0))
            wr = float(kinematics.ball_spin_relative(w0, 0.0, b.ball_radius, b.pitch_radius, a0))
            for j in range(z):
                vb[j] = (-wc * xb[j, 1], wc * xb[j, 0], 0.0)
                c, sn = math.cos(sol.psi[j]), math.sin(sol.psi[j])
                # rolling axis perpendicular to the contact line: (-sin a) e_r + cos a e_z
                wb[j] = (-wr * math.sin(a0) * c, -wr * math.sin(a0) * sn, wr * math.cos(a0) + wc)
            vc[:, 0] = -wc * xc[:, 1]
            vc[:, 1] = wc * xc[:, 0]
        return {"xb": xb, "vb": vb, "wb": wb, "xc": xc, "vc": vc, "ring": ring,
                "hist": np.zeros((z, 2, 3)), "hz": np.zeros((z, 2, 4)), "static": sol}

    # -- run -----------------------------------------------------------
    def run(self, progress=None, chunk_steps=None):
        """Integrate the scenario; returns :class:`~exudyn_bearing.results.Results`.

        ``progress``: True to print progress on stderr, None for automatic
        (runs over 2 million steps).
        """
        from ..results import Results

        s = self.scenario
        p = self.params
        msg = step_warning(f"dt = {s.dt:.3g} s", s.dt, self.stable)
        if msg:
            warnings.warn(msg, StepSizeWarning, stacklevel=2)
        n_steps = int(round(s.t_end / s.dt))
        every = max(1, int(round(s.sample_dt / s.dt)))
        n_samples = n_steps // every
        z = self.bearing.n_balls
        st = self.initial_state()
        xb, vb, wb, xc, vc, ring, hist, hz = (st[k] for k in ("xb", "vb", "wb", "xc", "vc", "ring", "hist", "hz"))
        fb = np.zeros((z, 3))
        tb = np.zeros((z, 3))
        fc = np.zeros((z, 3))
        fring = np.zeros(3)
        buf = {
            "t": np.zeros(n_samples), "glob": np.zeros((n_samples, K.NGLOBAL)),
            "diag": np.zeros((n_samples, z, 2, K.NDIAG)), "cage_load": np.zeros((n_samples, z, 2)),
            "xb": np.zeros((n_samples, z, 3)), "vb": np.zeros((n_samples, z, 3)),
            "wb": np.zeros((n_samples, z, 3)), "xc": np.zeros((n_samples, z, 3)),
            "vc": np.zeros((n_samples, z, 3)), "ring": np.zeros((n_samples, 6)),
        }
        # forces at t = 0 (Verlet needs them on entry)
        K._evaluate(0.0, p, self.table, xb, vb, wb, xc, vc, ring, K.ring_poses(), hist, hz, fb, tb, fc,
                    np.zeros((2, 6)), fring, np.zeros(K.NGLOBAL), np.zeros((z, 2, K.NDIAG)), np.zeros((z, 2)),
                    False)
        integrate = K.run_verlet if s.integrator == "verlet" else K.run_rk4
        if progress is None:
            progress = n_steps > 2_000_000
        chunk = chunk_steps or max(every, (max(n_steps // 50, 1) // every + 1) * every)
        done = 0
        k_samp = 0
        # compile (or load from the cache) before the clock starts: wall_s is the integration alone
        integrate(0, 0.0, p, self.table, xb, vb, wb, xc, vc, ring, hist, hz, fb, tb, fc, fring, every, 0,
                  buf["t"][:0], buf["glob"][:0], buf["diag"][:0], buf["cage_load"][:0], buf["xb"][:0],
                  buf["vb"][:0], buf["wb"][:0], buf["xc"][:0], buf["vc"][:0], buf["ring"][:0])
        wall0 = time.perf_counter()
        last_print = wall0
        while done < n_steps:
            m = min(chunk, n_steps - done)
            sl = slice(k_samp, n_samples)
            steps, ns, status = integrate(
                m, done * s.dt, p, self.table, xb, vb, wb, xc, vc, ring, hist, hz, fb, tb, fc, fring,
                every, done, buf["t"][sl], buf["glob"][sl], buf["diag"][sl], buf["cage_load"][sl],
                buf["xb"][sl], buf["vb"][sl], buf["wb"][sl], buf["xc"][sl], buf["vc"][sl], buf["ring"][sl])
            done += steps
            k_samp += ns
            if status != 0:
                t_fail = done * s.dt
                what = "non-finite" if status == 1 else "runaway (overlap above 5 % of the ball radius)"
                raise SimulationError(
                    f"dt: the state became {what} at t = {t_fail:.6g} s with dt = {s.dt:.3g} s; "
                    f"the stable-step estimate is {self.stable.dt:.3g} s (limited by the "
                    f"{self.stable.limited_by} contact): reduce dt")
            if progress and (time.perf_counter() - last_print > 0.5 or done >= n_steps):
                last_print = time.perf_counter()
                el = time.perf_counter() - wall0
                frac = done / n_steps
                eta = el / frac * (1 - frac) if frac > 0 else float("nan")
                print(f"\r[reference] t = {done * s.dt:.4f}/{s.t_end:.4f} s  {100 * frac:5.1f} %  "
                      f"wall {el:6.1f} s  eta {eta:6.1f} s", end="", file=sys.stderr, flush=True)
        wall = time.perf_counter() - wall0
        if progress:
            print(file=sys.stderr)
        for k in buf:
            buf[k] = buf[k][:k_samp]
        msg = cage_load_check(self.bearing, s, self.lubricant, float(buf["cage_load"].max(initial=0.0)), s.dt)
        if msg:
            warnings.warn(msg, StepSizeWarning, stacklevel=2)
        return Results(self.bearing, s, self.lubricant, buf, steps=done, wall_s=wall,
                       engine=self.name, stable_dt=self.stable.dt, static=st["static"])
