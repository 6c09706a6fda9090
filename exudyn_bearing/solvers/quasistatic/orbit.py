"""Quasi-dynamic orbit march: one ball followed around its orbit through the quasi-static solution's contact
states, with its inertia (docs/theory/quasistatic.md#the-orbit-march).

The quasi-static solution gives every ball position psi_j the steady kinematics of a ball that stays there.
Where a ball cannot follow them from one position to the next (``check_ball_inertia``: lightly loaded balls
leaving and entering the load zone, whose spin relaxes over a time comparable with their passage), the march
integrates the ball's own equations of motion along the orbit instead, the way Gupta's dynamic codes and
Walters' cage model do with the contact loads given:

* the contact geometry at the ball's azimuth under the solution's ring pose: the ball's own equilibrium
  between the rings there (the solver's, with the centrifugal force and the transverse tractions of the
  solution's balls linear between their positions), its Hertz ellipses and films (:func:`orbit_geometry`; at
  the solution's ball positions exactly its contacts);
* the ball's orbital speed omega_m, its angular velocity (w_r, w_z) and its yaw slip v_t = R_b w_psi in the
  orbit frame under the tractions of both contacts (the same traction over the ellipse as the solution,
  :func:`.kinematics._ball_contacts`) and the gyroscopic terms of the turning frame (Newton-Euler in the frame
  turning at omega_m about the axis, J dw/dt + omega_m e_z x J w = M):

      m c_r d omega_m / dt = F_x,o + F_x,i + Q_p
      J dw_r / dt   = M_r + J omega_m w_psi
      J dw_psi / dt = R_b (F_y,o + F_y,i) - J omega_m w_r
      J dw_z / dt   = M_z

  whose steady state is the traction equilibrium of :func:`.kinematics.traction_equilibrium`;
* the ball's place s in its pocket's play (``RigidCage.pocket_clearance`` c_p either side),
  ds/dt = c_r (omega_m - omega_c): free inside, on a wall the pocket holds it at the cage speed with the force
  Q_p that the orbit equation needs (a unilateral constraint, Moreau's time stepping [1]_: the step that would
  pass the wall ends on it, and the change of speed this takes is an inelastic impact), and the pocket's
  Coulomb friction mu_c |Q_p| opposes the ball's surface sliding R_b |w| over the wall (its moment
  -mu_c |Q_p| R_b w / |w|, as in the solver's held balls).

The step is implicit Euler (each step's four or three unknowns by Newton's method with a difference Jacobian):
stable for the traction's steep creep slope, where it settles on the traction equilibrium, and dissipative by
m (dv)^2 / 2 per step, the impact loss on the wall and an error of order dt elsewhere, which the energy
balance names (``energy_residual``). The march runs revolutions until the ball's state at a revolution's start
repeats (the steady state of a ball in a steady bearing is periodic in its orbit, and every ball follows the
same path one pitch apart); the cage speed is the root of the cage's torque (pocket forces, their friction and
the land's shear at the Ocvirk eccentricity of the mean net pocket force, as the solver's
:func:`~.solve._land_state`), each trial speed a march from the last one's periodic state.

What it keeps from the solution: the contact loads and the ring's displacement (the balls' inertia and their
transient tractions do not feed back into the ring's equilibrium, which a ball's few newtons of transient
traction change by little); the cage concentric (no whirl: the land's eccentricity is the mean force's). What it
leaves out: the contacts' vibration (the normal approach on the solution's), impacts' rebound (inelastic), drag.

References
----------
.. [1] J. J. Moreau, "Unilateral contact and dry friction in finite freedom dynamics," in Nonsmooth Mechanics
   and Applications, CISM Courses and Lectures 302, Springer, 1988, pp. 1-82.
.. [2] P. K. Gupta, Advanced Dynamics of Rolling Elements, Springer, 1984, ch. 5-6 (ball and cage equations of
   motion with the contact loads).
.. [3] C. T. Walters, "The dynamics of ball bearings," J. Lubr. Technol. 93 (1971) 1-10.
   doi:10.1115/1.3451516
"""
from __future__ import annotations

import math
import warnings

import numpy as np
from scipy import optimize as _opt

from ...data import InputError, load_bearing, load_lubricant
from ...data.errors import check_finite, check_integer
from ...physics import losses as _ls
from . import kinematics as km
from .inertia import ball_mass_inertia
from .solve import _land_state, pocket_net_force

__all__ = ["OrbitMarchWarning", "MARCH_UNITS", "ORBIT_STEPS_PER_PITCH", "orbit_geometry", "march_orbit", "march_summary"]

#: Implicit Euler steps per ball pitch (2 pi / Z of the orbit) of :func:`march_orbit`.
ORBIT_STEPS_PER_PITCH = 80
#: The march is periodic when a revolution's mean powers change by less than this share of the drive power
#: from the revolution before.
PERIODIC_TOLERANCE = 1e-3
#: Largest number of revolutions of one march.
MAX_REVOLUTIONS = 12
#: Largest relative residual of the cage's torque balance (against its terms and the tractions' torques) before
#: :func:`march_orbit` warns.
TORQUE_TOLERANCE = 1e-3
#: Newton's tolerance on a step's scaled residual [-] and its largest number of iterations.
STEP_TOLERANCE = 1e-10
STEP_ITERATIONS = 30


#: Units of a :func:`march_orbit` result's keys and of its ``profile``'s (the JSON's ``units["orbit_march"]``).
MARCH_UNITS = {
    "cage_speed": "rad/s", "solution_dissipation": "W", "drive_power": "W", "dissipation_contacts": "W",
    "power_pocket": "W", "power_land": "W", "dissipation": "W (contacts + pocket + land: traction and cage losses, "
    "without the rolling losses)", "step_loss": "W (drive power - dissipation: the implicit steps' loss, impacts "
    "included)", "energy_residual": "- (step_loss / drive_power)", "pocket_contact_fraction": "-",
    "land_force": "N", "land_eccentricity": "-", "land_crushed": "bool", "torque_residual": "-",
    "revolutions": "-", "periodic": "bool", "periodic_change": "- (of the drive power)",
    "unconverged_steps": "-", "steps_per_revolution": "-", "step": "s",
    "profile": {"psi": "rad (the pocket's azimuth)", "omega_m": "rad/s", "w_r": "rad/s", "w_z": "rad/s",
                "v_t": "m/s", "pocket_offset": "m (+: ahead of the pocket's centre)",
                "pocket_force": "N (+: pushes the ball forward; at an arrival the impulse over one step)",
                "dissipation": "W (one ball's contacts)", "q_inner": "N", "q_outer": "N"}}


class OrbitMarchWarning(UserWarning):
    """The orbit march did not reach a periodic state, or some of its steps did not converge."""


def orbit_geometry(sol, psi):
    """Packed contact geometry rows (len(psi), len(GEO_FIELDS)) of :mod:`.kinematics` of a ball at the azimuths
    ``psi`` [rad] under the quasi-static solution ``sol``'s ring pose (its ``geometry_at``: the ball's own
    equilibrium between the rings there, with the centrifugal and transverse traction forces of the solution's
    balls, linear between them); at the solution's azimuths its own rows."""
    if getattr(sol, "geometry_at", None) is None:
        raise InputError("sol: the orbit march needs the contact geometry along the orbit of a solution of "
                         "solve_quasistatic with the rings turning relative to each other")
    return sol.geometry_at(psi)


class _Ball:
    """One ball's step equations (module docstring) on a contact geometry row."""

    def __init__(self, model, n_strips, n_across, mass, inertia, mu_c):
        self.code, self.vec = model.code, model.vector
        self.ns, self.na = n_strips, n_across
        self.m, self.j, self.mu_c = mass, inertia, mu_c
        self.out = np.zeros((2, km.NC))

    def forces(self, y, geo):
        """Generalised forces [F_x, M_r / R_b, M_z / R_b, M_psi / R_b] (N) of the contacts and the frame's
        gyroscopic terms at y = (omega_m, w_r, w_z, v_t); the contacts' dissipation [W]."""
        wm, wr, wz, vt = y
        out = self.out
        p = km._ball_contacts(wm, wr, wz, vt, geo, self.code, self.vec, self.ns, self.na, out)
        rb = geo[km.G_RB]
        m_r, m_z = km.in_plane_moments(out, geo)
        m_r += self.j * wm * vt / rb
        m_psi = rb * (out[0, 7] + out[1, 7]) - self.j * wm * wr
        return np.array([out[0, 6] + out[1, 6], m_r / rb, m_z / rb, m_psi / rb]), p

    def mass_row(self, geo):
        rb = geo[km.G_RB]
        return np.array([self.m * geo[km.G_CR], self.j / rb, self.j / rb, self.j / (rb * rb)])

    def residual(self, y, y0, geo, dt, held):
        """The implicit Euler residual [N] (four equations; ``held``: the orbit equation gives the pocket
        force, whose friction moment enters the others) and (Q_p, contacts' dissipation)."""
        f, p = self.forces(y, geo)
        mrow = self.mass_row(geo)
        r = mrow * (y - y0) / dt - f
        q_p = 0.0
        if held:
            q_p = r[0]
            r[0] = 0.0
            w = math.hypot(y[1], y[2])
            if w > 0.0:
                fr = self.mu_c * abs(q_p)  # the friction moment / R_b
                r[1] += fr * y[1] / w
                r[2] += fr * y[2] / w
        return r, q_p, p


def _newton(ball, y, y0, geo, dt, held, scale):
    """One implicit Euler step by Newton's method with a difference Jacobian (the held step keeps omega_m);
    returns (y, Q_p, contacts' dissipation, converged), ``ball.out`` holding the contacts at that y (each
    residual is evaluated once: the accepted line-search point's serves the next iteration)."""
    idx = [1, 2, 3] if held else [0, 1, 2, 3]
    y = y.copy()
    fscale = max(abs(geo[km.G_QO]), abs(geo[km.G_QI]), 1.0)
    ok = False
    r, q_p, p = ball.residual(y, y0, geo, dt, held)
    for _ in range(STEP_ITERATIONS):
        rr = r[idx]
        if np.max(np.abs(rr)) < STEP_TOLERANCE * fscale:
            ok = True
            break
        jac = np.zeros((len(idx), len(idx)))
        for c, i in enumerate(idx):
            h = 1e-7 * scale
            yh = y.copy()
            yh[i] += h
            jac[:, c] = (ball.residual(yh, y0, geo, dt, held)[0][idx] - rr) / h
        try:
            dy = np.linalg.solve(jac, -rr)
        except np.linalg.LinAlgError:
            r, q_p, p = ball.residual(y, y0, geo, dt, held)  # ball.out back at y (the Jacobian's moved it)
            break
        lam = 1.0
        base = np.max(np.abs(rr))
        for _ls_it in range(20):  # backtracking on the largest residual
            yt = y.copy()
            yt[idx] += lam * dy
            r, q_p, p = ball.residual(yt, y0, geo, dt, held)
            if np.max(np.abs(r[idx])) < base or lam < 1e-4:
                break
            lam *= 0.5
        y = yt
    return y, q_p, p, ok


def _march(sol, ball, omega_c, clearance, state, steps_per_pitch, revolutions, tables):
    """March one ball at the cage speed ``omega_c`` from ``state`` (y, s) for up to ``revolutions`` until
    periodic; returns the last revolution's profile (per step: y, s, Q_p, the contacts' dissipation, the
    pocket friction's power, the drive power, the friction's moment about the axis, held, the tractions' torques
    about the axis |F_x,o| + |F_x,i| times c_r), the state at its
    end, the revolutions taken, the last change of the revolution's means, the unconverged steps and whether
    it is periodic."""
    geo_tab, psi_tab = tables
    n = psi_tab.size
    direction = 1.0 if omega_c >= 0.0 else -1.0
    dt = 2.0 * math.pi / (n * abs(omega_c))
    y, s = state
    scale = max(abs(omega_c), float(np.max(np.abs(sol.kinematics[:, 1:3]))))
    last = None
    wi, wo = sol.omega, sol.omega_outer
    change = math.nan
    for rev in range(revolutions):
        prof = np.zeros((n, 12))
        fails = 0
        s_start = s
        for i in range(n):
            geo = geo_tab[i]
            y0 = y.copy()
            yn, q_p, p, ok = _newton(ball, y0, y0, geo, dt, False, scale)
            held = 0.0
            s_new = s + dt * geo[km.G_CR] * (yn[0] - omega_c) * direction
            if abs(s_new) > clearance:
                wall = math.copysign(clearance, s_new)
                yh = y0.copy()
                yh[0] = omega_c + direction * (wall - s) / (dt * geo[km.G_CR])
                yn, q_p, p, ok = _newton(ball, yh, y0, geo, dt, True, scale)
                s_new, held = wall, 1.0
            fails += 0 if ok else 1
            # drive power of the rings: the contacts' torques about the axis on the ball, reversed on the races
            c = ball.out  # the contacts at yn (_newton's last evaluation)
            t_o = km.axial_torque_on_ball(c[0], geo[km.G_CR], geo[km.G_RB], geo[km.G_NOR], geo[km.G_NOZ])
            t_i = km.axial_torque_on_ball(c[1], geo[km.G_CR], geo[km.G_RB], geo[km.G_NIR], geo[km.G_NIZ])
            w = math.hypot(yn[1], yn[2])
            friction = float(_ls.cage_pocket_friction_power(q_p, w, 2.0 * geo[km.G_RB], ball.mu_c))
            wz_unit = yn[2] / w if w > 0.0 else 0.0
            prof[i] = (yn[0], yn[1], yn[2], yn[3], s_new, q_p, p, friction, t_i * wi + t_o * wo,
                       ball.mu_c * abs(q_p) * geo[km.G_RB] * wz_unit, held,
                       (abs(c[0, 6]) + abs(c[1, 6])) * geo[km.G_CR])
            y, s = yn, s_new
        means = prof.mean(axis=0)
        drift = s - s_start
        if not prof[:, 10].any() and drift != 0.0:
            # free all the revolution: the ball's speeds do not depend on its place in the play, so the same
            # revolution repeats, shifted by its drift, until a wall is reached; jump there
            room = clearance - (np.max(prof[:, 4]) if drift > 0.0 else -np.min(prof[:, 4]))
            jumps = math.floor(room / abs(drift))
            if jumps >= 1:
                s += jumps * drift
                last, change = None, math.nan
                continue
        if last is not None and abs(means[8]) > 0.0:
            change = float(np.max(np.abs(means[5:9] - last[5:9])) / abs(means[8]))
            if change < PERIODIC_TOLERANCE and abs(drift) < PERIODIC_TOLERANCE * clearance:
                return prof, (y, s), rev + 1, change, fails, True
        last = means
    return prof, (y, s), revolutions, change, fails, False


def march_orbit(sol, bearing=None, *, steps_per_pitch=ORBIT_STEPS_PER_PITCH, revolutions=MAX_REVOLUTIONS,
                lubricant=None, cage_speed=None):
    """The quasi-dynamic orbit march (module docstring) on the quasi-static solution ``sol`` with the rigid
    cage: one ball followed along its orbit with its inertia, the cage speed from the cage's torque balance.

    Parameters
    ----------
    sol : QuasiStaticSolution
        Solved with ``cage="rigid"`` and relative speed of the rings.
    bearing : BallBearing or str, optional
        The solution's bearing (its balls' mass; default: the solution's by name).
    steps_per_pitch : int
        Implicit Euler steps per ball pitch.
    revolutions : int
        Largest number of revolutions of a march (it stops once periodic, :data:`PERIODIC_TOLERANCE`).
    lubricant : Lubricant or str, optional
        The land film's oil (default: the solution's, by its name: pass the Lubricant the solution was solved
        with when it is not one of the catalogue's).
    cage_speed : float, optional
        Hold the cage at this speed [rad/s] instead of its torque balance (a study of one speed: the torque
        that holds it, ``torque_residual``, then works on the cage, and the energy balance shows it).

    Returns
    -------
    dict
        ``cage_speed`` [rad/s]; the whole bearing's means over the last revolution [W]: ``drive_power``,
        ``dissipation_contacts`` (the traction over both ellipses), ``power_pocket`` (the pockets' Coulomb
        friction), ``power_land`` (the land's shear), ``dissipation`` (their sum), ``step_loss`` (the implicit
        steps' loss, impacts on the walls included: drive minus the rest), ``energy_residual`` (step_loss over
        the drive power); ``pocket_contact_fraction`` (share of the time on a wall), ``land_force`` [N],
        ``land_eccentricity``, ``land_crushed``, ``torque_residual`` (the cage torque relative to its terms and
        the tractions' torques), ``revolutions``, ``periodic`` (bool), ``periodic_change``,
        ``unconverged_steps``, ``steps_per_revolution``, ``step`` [s]; ``solution_dissipation`` [W] (the
        solution's traction and cage losses, the same parts as ``dissipation``: neither holds the rolling losses
        of ``power_losses``); and ``profile``: per
        step of the last revolution the ball's azimuth ``psi`` [rad] (cage frame, from the solution's ball 0),
        ``omega_m``, ``w_r``, ``w_z`` [rad/s], ``v_t`` [m/s], ``pocket_offset`` s [m], ``pocket_force`` [N]
        (where the ball arrives at a wall the impact's impulse over that one step: it grows as the step
        shrinks), ``dissipation`` [W], ``q_inner``, ``q_outer`` [N].
    """
    if sol.cage is None or sol.cage.get("rigid_cage") is None:
        raise InputError("sol: the orbit march needs a quasi-static solution with the rigid cage (cage='rigid')")
    if sol.cage.get("pocket_film"):
        raise InputError("sol: solved with the pocket oil film, which the orbit march does not model (its ball "
                         "meets a dry pocket wall); march a solution without it (pocket_film=False)")
    if any(v != 0.0 for v in sol.cage.get("land_displacement", (0.0, 0.0))):
        raise InputError("sol: solved with the land feedback (the cage displaced on its land, its pockets shifted), "
                         "which the orbit march does not take (its cage stays centred); march a solution without it "
                         "(land_feedback=False)")
    if sol.omega == sol.omega_outer:
        raise InputError("sol: the orbit march needs relative speed of the rings (omega != omega_outer)")
    steps_per_pitch = check_integer("steps_per_pitch", steps_per_pitch)
    if steps_per_pitch < 4:
        raise InputError(f"steps_per_pitch: at least 4, got {steps_per_pitch}")
    revolutions = check_integer("revolutions", revolutions)
    if revolutions < 2:
        raise InputError(f"revolutions: at least 2 (periodicity is judged between two), got {revolutions}")
    if cage_speed is not None:
        cage_speed = check_finite("cage_speed", cage_speed)
    b = load_bearing(bearing if bearing is not None else sol.bearing_name)
    if b.n_balls != np.asarray(sol.balls["psi"]).size or b.name != sol.bearing_name:
        raise InputError(f"bearing: {b.name} is not the solution's bearing ({sol.bearing_name}); leave it out to take "
                         "the solution's")
    rc = sol.cage["rigid_cage"]
    lub = load_lubricant(lubricant if lubricant is not None else sol.lubricant, bearing=b)
    geo_b = np.asarray(sol.contact_geometry, float)
    z = geo_b.shape[0]
    r_b = float(geo_b[0, km.G_RB])
    mass, inertia = ball_mass_inertia(b, r_b)
    ball = _Ball(sol.traction_model, sol.n_strips, sol.n_across, mass, inertia, rc.pocket_friction)
    n = z * steps_per_pitch
    psi0 = float(sol.balls["psi"][0])
    w_c0 = float(sol.cage["speed"])
    direction = 1.0 if w_c0 >= 0.0 else -1.0
    psi_tab = psi0 + direction * 2.0 * math.pi * (np.arange(n) + 1.0) / n
    geo_tab = orbit_geometry(sol, psi_tab)
    kin0 = np.asarray(sol.kinematics[0], float)
    state = [(np.array([w_c0, kin0[1], kin0[2], kin0[3]]), 0.0)]
    w_ring = 0.0
    if rc.guidance != "ball":
        w_ring = sol.omega_outer if rc.guidance == "outer_land" else sol.omega
    runs = {}

    def run(wc):
        prof, st, revs, change, fails, periodic = _march(sol, ball, wc, rc.pocket_clearance, state[0], steps_per_pitch,
                                               revolutions, (geo_tab, psi_tab))
        state[0] = st
        qp = prof[:, 5]
        cr = geo_tab[:, km.G_CR]
        fr = np.sign(qp) * prof[:, 9] / geo_tab[:, km.G_RB]  # the friction's radial force on the cage
        # the cage's torque: the pockets' reactions at the ball centres and the friction's moment, every ball
        t_pockets = z * float(np.mean(-qp * cr + prof[:, 9]))
        fx, fy = (z / n * f for f in pocket_net_force(qp, fr, psi_tab))  # the revolution's mean, every ball
        eps, t_land, crushed = 0.0, 0.0, False
        if rc.guidance != "ball":
            eps, t_land, crushed = _land_state(rc, lub, wc, w_ring, math.hypot(fx, fy))
        runs[wc] = dict(prof=prof, revs=revs, change=change, fails=fails, periodic=periodic, t_land=t_land, eps=eps,
                        crushed=crushed, land_force=math.hypot(fx, fy),
                        torque=t_pockets + t_land,
                        # the torque's scale: its terms and the tractions' own torques along the orbit, whose
                        # difference the pockets carry (as the solver's cage balance)
                        scale=z * float(np.mean(np.abs(qp * cr) + np.abs(prof[:, 9]) + prof[:, 11])) + abs(t_land))
        return runs[wc]["torque"]

    if cage_speed is not None:
        wc = float(cage_speed)
        run(wc)
    else:
        ref = abs(sol.omega - sol.omega_outer)
        lo, hi = w_c0 - 2e-3 * ref, w_c0 + 2e-3 * ref
        t_lo, t_hi = run(lo), run(hi)
        for _ in range(20):
            if t_lo >= 0.0 >= t_hi:
                break
            if t_lo < 0.0:
                lo, hi, t_hi = lo - 2.0 * (hi - lo), lo, t_lo
                t_lo = run(lo)
            else:
                hi, lo, t_lo = hi + 2.0 * (hi - lo), hi, t_hi
                t_hi = run(hi)
        else:
            raise InputError("sol: no cage speed balances the marched cage's torque")
        wc = _opt.brentq(run, lo, hi, xtol=1e-7 * ref, rtol=1e-12)
        if wc not in runs:
            run(wc)
    r = runs[wc]
    prof = r["prof"]
    residual = r["torque"] / r["scale"] if r["scale"] > 0.0 else 0.0
    if cage_speed is None and abs(residual) > TORQUE_TOLERANCE:
        warnings.warn(OrbitMarchWarning(
            f"march_orbit: the cage's torque does not balance at the cage speed found, {wc:.8g} rad/s (relative "
            f"residual {residual:.2g} of its terms and the tractions' torques, limit {TORQUE_TOLERANCE:g}): it jumps "
            "there between neighbouring speeds (a ball that meets one pocket wall at one speed and the other at the "
            "next); the march's cage speed and cage losses are not a balance's"), stacklevel=2)
    if not r["periodic"] or r["fails"]:
        warnings.warn(OrbitMarchWarning(
            f"march_orbit: the marched ball is {'not periodic' if not r['periodic'] else 'periodic'} after "
            f"{r['revs']} revolutions (change of the revolution's mean powers {r['change']:.2g} of the drive "
            f"power, limit {PERIODIC_TOLERANCE:g}) and {r['fails']} of its steps did not converge: its means are "
            "not a steady state's; raise revolutions or steps_per_pitch"), stacklevel=2)
    drive = z * float(np.mean(prof[:, 8])) + r["t_land"] * w_ring  # the land's share: QuasiStaticSolution.drive_power
    contacts = z * float(np.mean(prof[:, 6]))
    pocket = z * float(np.mean(prof[:, 7]))
    land = -r["t_land"] * (wc - w_ring)
    lost = contacts + pocket + land
    return {"cage_speed": wc, "solution_dissipation": float(sol.dissipation_total + sol.cage_power), "drive_power": drive, "dissipation_contacts": contacts, "power_pocket": pocket,
            "power_land": land, "dissipation": lost, "step_loss": drive - lost,
            "energy_residual": (drive - lost) / drive if drive != 0.0 else math.nan,
            "pocket_contact_fraction": float(np.mean(prof[:, 10])), "land_force": r["land_force"],
            "land_eccentricity": r["eps"], "land_crushed": r["crushed"],
            "torque_residual": residual,
            "revolutions": r["revs"], "periodic": r["periodic"], "periodic_change": r["change"], "unconverged_steps": r["fails"],
            "steps_per_revolution": n, "step": 2.0 * math.pi / (n * abs(wc)),
            "profile": {"psi": psi_tab, "omega_m": prof[:, 0], "w_r": prof[:, 1], "w_z": prof[:, 2],
                        "v_t": prof[:, 3], "pocket_offset": prof[:, 4], "pocket_force": prof[:, 5],
                        "dissipation": prof[:, 6], "q_inner": geo_tab[:, km.G_QI], "q_outer": geo_tab[:, km.G_QO]}}


def march_summary(march) -> str:
    """The lines of a :func:`march_orbit` result: its window (the last revolution), step, cage speed [rad/s]
    and the whole bearing's mean powers [W] with the energy balance."""
    return (f"orbit march (one ball followed along its orbit with its inertia through the solution's contact "
            f"loads; means over its last revolution of {march['revolutions']}, {march['steps_per_revolution']} "
            f"implicit steps of {1e6 * march['step']:.3g} us): cage speed {march['cage_speed']:.6g} rad/s; "
            f"traction and cage losses {march['dissipation']:.4g} W (contacts {march['dissipation_contacts']:.4g}, "
            f"pocket {march['power_pocket']:.4g}, land {march['power_land'] + 0.0:.4g}; the steady solution's "
            f"{march['solution_dissipation']:.4g} W; without the rolling losses of the power loss); drive power "
            f"{march['drive_power']:.4g} W, the steps' loss {march['step_loss']:.3g} W (energy residual "
            f"{march['energy_residual']:.2g}, impacts on the walls included); on a pocket wall "
            f"{100 * march['pocket_contact_fraction']:.3g} % of the time; land force {march['land_force']:.3g} N "
            f"(eccentricity {march['land_eccentricity']:.3g})"
            + ("" if march["unconverged_steps"] == 0 else
               f"; {march['unconverged_steps']} steps did not converge")
            + ("" if march["periodic"] else
               f"; NOT periodic after {march['revolutions']} revolutions (change {march['periodic_change']:.2g})")
            + ("" if abs(march["torque_residual"]) <= TORQUE_TOLERANCE else
               f"; the cage's torque NOT balanced (relative residual {march['torque_residual']:.2g})"))
