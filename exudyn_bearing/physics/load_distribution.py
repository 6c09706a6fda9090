"""Quasi-static load distribution among the balls (Stribeck / Harris).

docs/theory/reference_cases.md. Two levels:

* The continuous Stribeck-Sjovall integrals: with the loaded-zone parameter
  eps, Q(psi) = Q_max [1 - (1 - cos psi)/(2 eps)]^(3/2) and
  J_r(eps) = (1/2pi) int Q/Q_max cos psi dpsi, J_a(eps) = (1/2pi) int Q/Q_max dpsi
  over the loaded zone; F_r = Z Q_max J_r cos alpha, F_a = Z Q_max J_a sin alpha
  (Harris & Kotzalas [1]_ ch. 7; J_r(0.5) = 0.2288).
  Radial bearing: eps = (1 - P_d/(2 delta_r))/2; angular contact:
  eps = (1 + delta_a tan(alpha)/delta_r)/2.
* The discrete solution for Z balls at any phase: the inner ring displacement
  (dx, dy, dz) is solved so that the ball loads balance the applied force.
  The groove geometry is exact (torus groove centres of
  :class:`~exudyn_bearing.data.BallBearing`): in the half-plane of ball j
  at azimuth psi_j the inner groove centre moves by
  (dx cos psi_j + dy sin psi_j, dz) (small-displacement projection, as in
  Harris ch. 7), the total overlap is delta_j = |p_i - p_o| - A with
  A = R_ci + R_co - 2 R_b, the contact line and angle alpha_j follow from
  p_i - p_o, and Q_j = K_n(alpha_j) delta_j^(3/2) with the two races in
  series, K_n = (K_i^(-2/3) + K_o^(-2/3))^(-3/2) (exact Hertz at alpha_j).
  For alpha_0 = 0 and P_d = 0 this reduces to delta_j = delta_r cos psi_j to
  first order. No centrifugal or gyroscopic load (omega -> 0): the quasi-static
  reference of the DEM papers' Appendix A (omega = 1 rad/s).
  The inner ring only translates (its tilt is held at zero, as in the DEM
  engines); the moment that holding it takes is reported as
  ``StaticSolution.reaction_moment``. Free tilt, moment loads and speed
  effects: :func:`exudyn_bearing.solvers.quasistatic.solve_quasistatic`.
* A single angular-contact bearing carries a radial load only together with
  an axial load of at least F_r tan(alpha) (one ball loaded); half the balls
  are loaded at the induced axial force F_r tan(alpha) J_a(0.5)/J_r(0.5)
  = 1.216 F_r tan(alpha) (:func:`induced_axial_force`, Harris & Kotzalas
  [1]_ ch. 7). :func:`static_equilibrium` refuses smaller axial loads.

Azimuth psi is measured from the applied radial load direction (x), so
psi = 0 is the most loaded ball; the inner ring carries +x radial and +z
axial force.

References
----------
.. [1] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed.,
   CRC Press, 2006, ch. 7 (Table 7.1: J_r, J_a).
.. [2] S. Guessasma and C. Machado, Lubricants 6 (2018) 46, Appendix A.
"""
from __future__ import annotations

import copy
import math
from dataclasses import dataclass, field, fields

import numpy as np

from .._jit import kernel
from scipy import integrate, optimize

from ..data import BallBearing, InputError
from . import hertz as _hz
from .geometry import _raceway_radii_cos

__all__ = [
    "load_zone_parameter",
    "stribeck_load",
    "load_integral_radial",
    "load_integral_axial",
    "StribeckSolution",
    "stribeck_solution",
    "StaticSolution",
    "static_equilibrium",
    "race_stiffness",
    "induced_axial_force",
    "check_axial_load",
]


def stribeck_load(psi, q_max, eps):
    """Ball load Q(psi) = Q_max [1 - (1 - cos psi)/(2 eps)]^(3/2), 0 outside
    the loaded zone [N] (Harris & Kotzalas [1]_ eq. 7.27)."""
    if type(psi) is float and type(q_max) is float and type(eps) is float:
        # the load integrals' integrand (scipy's quad calls it with floats, thousands of times per static
        # solve): the same operations on floats, without NumPy's per-call overhead (5 us against 0.3 us)
        x = 1.0 - (1.0 - math.cos(psi)) / (2.0 * eps)
        return q_max * (abs(x) ** 1.5 if x > 0.0 else 0.0)
    x = 1.0 - (1.0 - np.cos(psi)) / (2.0 * eps)
    return q_max * np.where(x > 0.0, np.abs(x) ** 1.5, 0.0)


def load_zone_parameter(delta_r, diametral_clearance=0.0, delta_a=0.0, contact_angle=0.0):
    """Loaded-zone parameter eps [-].

    eps = (1/2) (1 + (delta_a sin alpha - P_d/2) / (delta_r cos alpha)), which
    gives (1 - P_d/(2 delta_r))/2 for a radial bearing and
    (1 + delta_a tan(alpha)/delta_r)/2 for angular contact without clearance
    (docs/theory/reference_cases.md, Harris [1]_ eq. 7.25 and 7.43).
    """
    return 0.5 * (1.0 + (delta_a * np.sin(contact_angle) - 0.5 * diametral_clearance)
                  / (delta_r * np.cos(contact_angle)))


def _zone_integral(eps, weight):
    if eps <= 0.0:
        return 0.0
    psi_l = math.pi if eps >= 1.0 else math.acos(1.0 - 2.0 * eps)

    def f(psi):
        return stribeck_load(psi, 1.0, eps) * weight(psi)

    val, _err = integrate.quad(f, 0.0, psi_l, epsabs=1e-13, epsrel=1e-12, limit=200)
    return val / math.pi  # (1/2pi) * 2 * integral over half the zone


def load_integral_radial(eps):
    """Radial integral J_r(eps) = (1/2pi) int [1-(1-cos psi)/(2eps)]^1.5 cos psi dpsi.

    Harris & Kotzalas [1]_ Table 7.1: J_r(0.5) = 0.2288.

    Examples
    --------
    >>> round(float(load_integral_radial(0.5)), 4)
    0.2288
    """
    return np.vectorize(lambda e: _zone_integral(float(e), math.cos), otypes=[float])(eps)


def load_integral_axial(eps):
    """Axial integral J_a(eps) = (1/2pi) int [1-(1-cos psi)/(2eps)]^1.5 dpsi.

    Harris & Kotzalas [1]_ Table 7.1: J_a(0.5) = 0.2782.

    Examples
    --------
    >>> round(float(load_integral_axial(0.5)), 4)
    0.2782
    """
    return np.vectorize(lambda e: _zone_integral(float(e), lambda p: 1.0), otypes=[float])(eps)


def induced_axial_force(radial_load, contact_angle, eps=0.5):
    """Axial force [N] that a radial load induces in an angular-contact bearing.

    F_a = F_r tan(alpha) J_a(eps) / J_r(eps) (Harris & Kotzalas [1]_ ch. 7,
    eq. 7.41-7.42 at a fixed contact angle): the axial load with which the
    loaded zone spans the fraction given by eps; at eps = 0.5 (half the
    balls loaded) F_a = 1.216 F_r tan(alpha). As eps -> 0 (a single ball)
    it falls to F_r tan(alpha), the least axial load that can hold F_r.

    Examples
    --------
    7208 (alpha = 40 deg) at F_r = 3000 N:

    >>> round(float(induced_axial_force(3000.0, math.radians(40.0))))
    3061
    """
    return (np.asarray(radial_load, float) * np.tan(contact_angle) * load_integral_axial(eps)
            / load_integral_radial(eps))


def check_axial_load(bearing: BallBearing, radial_load: float, axial_load: float) -> None:
    """InputError unless an angular-contact bearing's axial load can hold its radial load.

    Needs F_a > F_r tan(alpha_f) with alpha_f the free contact angle after the
    axial shift (:attr:`BallBearing.free_contact_angle_max`); the message
    gives that limit and the induced axial force of :func:`induced_axial_force`.
    Deep-groove bearings (alpha_0 = 0) carry radial load without axial load.
    """
    a0 = bearing.free_contact_angle
    if a0 <= 0.0 or radial_load <= 0.0:
        return
    af = bearing.free_contact_angle_max
    need = radial_load * math.tan(af)
    if axial_load <= need:
        ind = float(induced_axial_force(radial_load, af))
        raise InputError(
            f"axial_load: {axial_load:g} N cannot hold the radial load {radial_load:g} N of the "
            f"angular-contact bearing {bearing.name} (alpha = {math.degrees(af):.1f} deg): it needs "
            f"F_a > F_r tan(alpha) = {need:.0f} N; the induced axial force with half the balls "
            f"loaded is {ind:.0f} N (Harris & Kotzalas)")


def race_stiffness(bearing: BallBearing, contact_angle=None, method="exact"):
    """Hertz constants (K_inner, K_outer, K_n) [N/m^1.5] at a contact angle.

    Contacts at the ball's inner and outer points r_p -+ R_b cos(alpha);
    K_n = (K_i^(-2/3) + K_o^(-2/3))^(-3/2), both races in series
    (Harris [1]_ eq. 7.3). Default angle: the free contact angle.
    """
    alpha = bearing.free_contact_angle if contact_angle is None else contact_angle
    return tuple(float(x) for x in _race_stiffness(
        bearing.pitch_radius, bearing.ball_radius, bearing.inner_groove_radius,
        bearing.outer_groove_radius, float(alpha), _hz.material_reduced_modulus(bearing.material), _hz.method_code(method)))


@kernel
def _race_stiffness(r_p, r_b, r_ci, r_co, alpha, e_prime, method):
    ca = math.cos(alpha)
    rxi, ryi = _raceway_radii_cos(r_b, r_ci, r_p - r_b * ca, ca, True)
    rxo, ryo = _raceway_radii_cos(r_b, r_co, r_p + r_b * ca, ca, False)
    ki = _hz._hertz(rxi, ryi, e_prime, 0.0, method)[1]
    ko = _hz._hertz(rxo, ryo, e_prime, 0.0, method)[1]
    kn = (ki ** (-2.0 / 3.0) + ko ** (-2.0 / 3.0)) ** -1.5
    return ki, ko, kn


@dataclass
class StribeckSolution:
    """Continuous (integral) solution of :func:`stribeck_solution`."""

    eps: float
    q_max: float
    j_r: float
    j_a: float
    contact_angle: float


def stribeck_solution(n_balls, radial_load, axial_load=0.0, contact_angle=0.0,
                      eps=None) -> StribeckSolution:
    """Q_max and eps of the continuous Stribeck/Harris distribution.

    Radial bearing (alpha = 0, F_a = 0): give ``eps`` (0.5 for P_d = 0);
    Q_max = F_r / (Z J_r(eps)) (docs/theory/reference_cases.md: 1457 N for the 6208 at
    F_r = 3000 N). Combined load at fixed alpha: eps solves
    F_r tan(alpha) / F_a = J_r(eps) / J_a(eps), then
    Q_max = F_a / (Z J_a sin alpha) (Harris [1]_ eq. 7.41-7.42).
    """
    fr = float(radial_load)
    fa = float(axial_load)
    if fa == 0.0:
        eps = 0.5 if eps is None else float(eps)
        jr = float(load_integral_radial(eps))
        ja = float(load_integral_axial(eps))
        return StribeckSolution(eps, fr / (n_balls * jr * math.cos(contact_angle)), jr, ja, contact_angle)
    if contact_angle <= 0.0:
        raise InputError("contact_angle: a combined radial and axial load needs alpha > 0")
    target = fr * math.tan(contact_angle) / fa

    def ratio(e):
        return float(load_integral_radial(e) / load_integral_axial(e)) - target

    if fr == 0.0:
        eps = math.inf
        return StribeckSolution(eps, fa / (n_balls * math.sin(contact_angle)), 0.0, 1.0, contact_angle)
    # J_r/J_a falls from 1 (eps -> 0) to 0 (eps -> inf)
    if target >= 1.0:
        raise InputError(f"axial_load: F_a = {fa} N is too small to keep any ball loaded at "
                         f"alpha = {math.degrees(contact_angle):.1f} deg (F_r tan(alpha)/F_a >= 1)")
    hi = 1.0
    while ratio(hi) > 0.0:
        hi *= 2.0
    eps = optimize.brentq(ratio, 1e-6, hi, xtol=1e-12)
    jr = float(load_integral_radial(eps))
    ja = float(load_integral_axial(eps))
    return StribeckSolution(eps, fa / (n_balls * ja * math.sin(contact_angle)), jr, ja, contact_angle)


@kernel
def _ball_loads(dx, dy, dz, psi, rho_i, z_i, rho_o, z_o, r_b, r_ci, r_co, e_prime, method,
                q, delta, alpha, nvec):
    """Per-ball total overlap, contact angle and load for an inner-ring
    displacement; fills q, delta, alpha and the unit contact line nvec (Z, 3)."""
    a_touch = r_ci + r_co - 2.0 * r_b
    for j in range(psi.size):
        c = math.cos(psi[j])
        s = math.sin(psi[j])
        wr = rho_i + dx * c + dy * s - rho_o
        wz = z_i + dz - z_o
        dist = math.sqrt(wr * wr + wz * wz)
        nr = wr / dist
        nz = wz / dist
        d = dist - a_touch
        al = math.atan2(nz, nr)
        delta[j] = d
        alpha[j] = al
        nvec[j, 0] = nr * c
        nvec[j, 1] = nr * s
        nvec[j, 2] = nz
        if d > 0.0:
            # ball centre on the contact line, at its groove-centre distance
            r_ball_c = rho_o + (r_co - r_b) * nr
            ca = math.cos(al)
            rxi, ryi = _raceway_radii_cos(r_b, r_ci, r_ball_c - r_b * ca, ca, True)
            rxo, ryo = _raceway_radii_cos(r_b, r_co, r_ball_c + r_b * ca, ca, False)
            ki = _hz._hertz(rxi, ryi, e_prime, 0.0, method)[1]
            ko = _hz._hertz(rxo, ryo, e_prime, 0.0, method)[1]
            kn = (ki ** (-2.0 / 3.0) + ko ** (-2.0 / 3.0)) ** -1.5
            q[j] = kn * d * math.sqrt(d)
        else:
            q[j] = 0.0


@dataclass
class StaticSolution:
    """Discrete quasi-static solution (:func:`static_equilibrium`).

    Arrays have one entry per ball, ball 0 at ``psi[0] = phase``.
    """

    bearing: BallBearing
    radial_load: float
    axial_load: float
    psi: np.ndarray              #: azimuth [rad]
    q: np.ndarray                #: ball load, inner = outer (no centrifugal) [N]
    overlap: np.ndarray          #: total overlap delta_i + delta_o [m] (< 0: gap)
    overlap_inner: np.ndarray    #: [m]
    overlap_outer: np.ndarray    #: [m]
    contact_angle: np.ndarray    #: [rad]
    displacement: np.ndarray     #: inner ring (dx, dy, dz) [m]
    delta_r: float               #: radial displacement along the load [m]
    delta_a: float               #: axial displacement [m]
    eps: float                   #: loaded-zone parameter [-]
    hertz_method: str = "exact"
    #: moment (M_x, M_y) [N m] that holding the inner ring's tilt at zero
    #: takes: minus the moment of the ball forces about the bearing centre
    reaction_moment: np.ndarray = field(default_factory=lambda: np.zeros(2))
    extra: dict = field(default_factory=dict)

    @property
    def q_max(self) -> float:
        """Largest ball load [N]."""
        return float(self.q.max())


def static_equilibrium(bearing: BallBearing, radial_load: float, axial_load: float = 0.0,
                       phase: float = 0.0, hertz_method: str = "exact",
                       tol: float = 1e-10) -> StaticSolution:
    """Discrete quasi-static load distribution of Z balls (module docstring).

    The inner ring translates (dx, dy, dz); its tilt is held at zero and the
    moment this takes is returned as ``reaction_moment`` (zero for radial or
    axial load alone on a symmetric bearing, not zero for combined load).
    Angular-contact bearings need an axial load that can hold the radial one
    (:func:`check_axial_load`).

    Parameters
    ----------
    bearing : BallBearing
    radial_load : float
        F_r >= 0 [N] on the inner ring along +x (psi = 0).
    axial_load : float
        F_a >= 0 [N] on the inner ring along +z (angular contact direction).
    phase : float
        Azimuth of ball 0 [rad] (0: a ball under the load).
    hertz_method : str
        Hertz fidelity level (``"exact"`` default).

    Returns
    -------
    StaticSolution

    Examples
    --------
    6208 at F_r = 3000 N, P_d = 0 (docs/theory/reference_cases.md: about 1462 N for nine
    discrete balls, 1457 N from the continuous integral):

    >>> from exudyn_bearing import catalog
    >>> round(static_equilibrium(catalog["6208"], 3000.0).q_max)
    1462
    """
    fr = _check_load("radial_load", radial_load)
    fa = _check_load("axial_load", axial_load)
    phase = float(phase)
    if not math.isfinite(phase):
        raise InputError(f"phase: must be finite, got {phase}")
    check_axial_load(bearing, fr, fa)
    method = _hz.method_code(hertz_method)
    try:
        key = (bearing, fr, fa, phase, method, float(tol))
        hash(key)
    except TypeError:  # a bearing that cannot be a key: solved every time
        key = None
    sol = _SOLVED.get(key) if key is not None else None
    if sol is None:
        sol = _static_equilibrium(bearing, fr, fa, phase, method, tol)
        if key is not None:
            if len(_SOLVED) >= _SOLVED_MAX:
                _SOLVED.pop(next(iter(_SOLVED)))
            _SOLVED[key] = sol
    return _copy_solution(sol)


#: The last solutions of :func:`static_equilibrium` by their inputs (bearing, loads, phase, Hertz level,
#: tolerance): one simulate call solved the same equilibrium three times (its load-range check, the engine's
#: stable step before the run and its cage-load check after it), 20-30 ms each, as much as a 0.1 s run of the
#: 7208 with the rigid cage integrates in (``python validation/studies/rigid_cage.py``). Each caller gets its own
#: copy of the arrays.
_SOLVED: dict = {}
_SOLVED_MAX = 16


def _copy_solution(sol: StaticSolution) -> StaticSolution:
    """A copy of ``sol`` whose arrays and ``extra`` are its own."""
    out = copy.copy(sol)
    for f in fields(sol):
        v = getattr(sol, f.name)
        if isinstance(v, np.ndarray):
            setattr(out, f.name, v.copy())
    out.extra = copy.deepcopy(sol.extra)
    return out


def _static_equilibrium(bearing: BallBearing, fr: float, fa: float, phase: float, method: int,
                        tol: float) -> StaticSolution:
    """The solve of :func:`static_equilibrium` (checked inputs, the Hertz level's code)."""
    b = bearing
    z = b.n_balls
    psi = phase + 2.0 * math.pi * np.arange(z) / z
    rho_i, z_i = b.inner_groove_center
    rho_o, z_o = b.outer_groove_center
    e_prime = _hz.material_reduced_modulus(b.material)
    q = np.zeros(z)
    delta = np.zeros(z)
    alpha = np.zeros(z)
    nvec = np.zeros((z, 3))
    pd = b.diametral_clearance
    axial_free = b.free_contact_angle > 0.0 or fa > 0.0
    target = np.array([fr, 0.0, fa])

    def evaluate(d3):
        _ball_loads(d3[0], d3[1], d3[2], psi, rho_i, z_i, rho_o, z_o, b.ball_radius,
                    b.inner_groove_radius, b.outer_groove_radius, e_prime, method,
                    q, delta, alpha, nvec)
        return q @ nvec  # force of the balls on the ring, opposite the reaction

    scale = max(fr, fa, 1.0)

    def residual(x):
        d3 = np.array([x[0], x[1], x[2] if axial_free else 0.0])
        r = (evaluate(d3) - target) / scale
        return r if axial_free else r[:2]

    if fr == 0.0 and fa == 0.0:
        x = np.zeros(3)
        if pd < 0.0 and axial_free and b.free_contact_angle > 0.0:
            x = _solve(residual, np.zeros(3), tol)
    else:
        x0 = _initial_guess(b, fr, fa, e_prime, method)
        x = _solve(residual, x0 if axial_free else x0[:2], tol)
        if not axial_free:
            x = np.array([x[0], x[1], 0.0])
    evaluate(x)
    if b.free_contact_angle > 0.0 and np.any((q > 0.0) & (alpha <= 0.0)):
        raise InputError(f"axial_load: {fa:g} N is too small for the radial load {fr:g} N: loaded balls of "
                         f"{b.name} are pushed across the groove bottom to the low shoulder (alpha <= 0)")
    # moment of the ball forces on the ring (-q nvec at the inner groove centres) held by the tilt constraint
    pts = np.stack([rho_i * np.cos(psi), rho_i * np.sin(psi), np.full(z, z_i)], axis=1)
    reaction = np.cross(pts, q[:, None] * nvec).sum(axis=0)[:2]
    # split of the total overlap between the races (equal loads)
    ki_ko = np.array([_race_stiffness(b.pitch_radius, b.ball_radius, b.inner_groove_radius,
                                      b.outer_groove_radius, float(al), e_prime, method)[:2]
                      for al in alpha])
    di = np.where(delta > 0.0, (q / ki_ko[:, 0]) ** (2.0 / 3.0), 0.5 * delta)
    do = np.where(delta > 0.0, (q / ki_ko[:, 1]) ** (2.0 / 3.0), 0.5 * delta)
    a0 = float(alpha[int(np.argmax(q))]) if q.max() > 0 else b.free_contact_angle
    delta_r, delta_a = float(x[0]), float(x[2])
    eps = float(load_zone_parameter(delta_r, pd, delta_a, a0)) if delta_r > 0 else (
        math.inf if (delta_a > 0 or pd < 0) else 0.0)
    return StaticSolution(b, fr, fa, psi, q.copy(), delta.copy(), di, do, alpha.copy(),
                          np.asarray(x, float), delta_r, delta_a, eps,
                          hertz_method=_hz.METHODS[method], reaction_moment=reaction)


def _check_load(name, value):
    v = float(value)
    if not math.isfinite(v):
        raise InputError(f"{name}: must be finite, got {v}")
    if v < 0.0:
        raise InputError(f"{name}: must be >= 0 (the bearing carries +x radial and +z axial "
                         f"load on the inner ring), got {v}")
    return v


def _initial_guess(b, fr, fa, e_prime, method):
    alpha = b.free_contact_angle
    kn = _race_stiffness(b.pitch_radius, b.ball_radius, b.inner_groove_radius,
                         b.outer_groove_radius, alpha, e_prime, method)[2]
    pd = b.diametral_clearance
    if fa == 0.0 or alpha == 0.0 and fr > 0.0:
        sol = stribeck_solution(b.n_balls, fr, 0.0, 0.0, eps=0.5)
        dmax = (sol.q_max / kn) ** (2.0 / 3.0)
        dz = 0.0
        if fa > 0.0:
            dz = (fa / (b.n_balls * kn)) ** (2.0 / 3.0) * 10.0
        return np.array([dmax + 0.5 * max(pd, 0.0), 0.0, dz])
    if fr == 0.0:
        q = fa / (b.n_balls * math.sin(max(alpha, 0.2)))
        d = (q / kn) ** (2.0 / 3.0) + 0.5 * max(pd, 0.0)
        dz = d / math.sin(max(alpha, 0.2))
        return np.array([0.0, 0.0, dz])
    sol = stribeck_solution(b.n_balls, fr, fa, alpha)
    dmax = (sol.q_max / kn) ** (2.0 / 3.0) + 0.5 * max(pd, 0.0)
    # delta_max = delta_a sin a + delta_r cos a, eps = (1 + delta_a tan a/delta_r)/2
    t = 2.0 * sol.eps - 1.0  # = delta_a tan a / delta_r
    delta_r = dmax / (math.cos(alpha) * (1.0 + t))
    delta_a = t * delta_r / math.tan(alpha)
    return np.array([delta_r, 0.0, delta_a])


def _solve(residual, x0, tol):
    scale = np.maximum(np.abs(x0).max(), 1e-6)
    sol = optimize.root(lambda u: residual(u * scale), x0 / scale, method="hybr",
                        options={"xtol": tol})
    if not sol.success or np.max(np.abs(residual(sol.x * scale))) > 1e-6:
        sol2 = optimize.root(lambda u: residual(u * scale), x0 / scale, method="lm",
                             options={"xtol": tol, "ftol": tol})
        if np.max(np.abs(residual(sol2.x * scale))) > 1e-6:
            raise RuntimeError(f"static_equilibrium: the ring equilibrium did not converge ({sol.message})")
        sol = sol2
    x = sol.x * scale
    return np.concatenate([x, np.zeros(3 - x.size)])
