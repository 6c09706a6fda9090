"""Linearised bearing coefficients over a speed range from the quasi-static
solver: the 5x5 stiffness (:mod:`.stiffness`) and equivalent damping
(:mod:`.damping`) at each speed, as a
:class:`~exudyn_bearing.model.coefficients.BearingCoefficients` record (the
input of rotordynamics exports such as :mod:`exudyn_bearing.outputs.ross`).

Each speed is solved from the solution at the previous speed (ring pose and
ball speeds scaled with the speed: ``solve_quasistatic(..., start=)``).

The stiffness and damping of a bearing vary with the position of the ball
set (period: one ball pitch 2 pi/Z of the cage); ``n_phases`` > 1 averages
them over that many evenly spaced ball-set positions (the time average a
linear time-invariant rotor model sees), 1 takes the balls at psi_j = phase
+ 2 pi j/Z. The spread over the phases is returned in ``operating_point``.
The default, :data:`DEFAULT_N_PHASES` = 3 in every entry point (the API,
``stiffness --phases``, the linear level's tables; docs/defaults.md): one
position lies up to 15 % from the 16-position mean of the diagonal entries
(6208 at 300 and 3000 N, 6205 at 1000 N, 500 rad/s), three within 2.0 %.

The record carries the bearing it was made for: ``operating_point["bearing"]``
(name) and ``operating_point["bearing_geometry"]`` (:func:`bearing_identity`:
ball set, race and groove radii, free contact angle, elastic constants), kept
by ``to_dict``/``from_dict`` (the JSON of ``stiffness --speeds --json``).
:func:`check_table` compares it with the bearing a level is built for.

Axes and signs are those of :mod:`exudyn_bearing.model.coefficients`
(x the radial load direction, z the bearing axis, K = -dF/dq and
C = -dF/dq' of the force on the shaft); the quasi-static solver's DOFs
(delta_x, delta_y, delta_a, tilt_x, tilt_y) are the inner ring's pose against
the outer ring, in that order, so no mapping is needed.
Theory notes: docs/theory/vibration.md, "Linearised bearing".
"""
from __future__ import annotations

import math

import numpy as np

from ...data import InputError, load_bearing
from ...data.errors import check_number
from ...model.coefficients import BearingCoefficients, speed_array
from .solve import solve_quasistatic

__all__ = ["DEFAULT_N_PHASES", "METHOD", "bearing_coefficients", "bearing_identity", "check_table"]

#: Description stored in the record's ``method``.
METHOD = ("quasi-static 5-DOF equilibrium (exudyn_bearing.solve_quasistatic): stiffness by central differences "
          "of the balls' force on the inner ring; damping: normal damping of the contact model (hysteretic, "
          "squeeze film, Lambda-switched) condensed over each ball's two contacts in series")


#: Fields of :func:`bearing_identity` taken from the bearing (the rest from its material).
IDENTITY_FIELDS = ("n_balls", "ball_radius", "inner_race_radius", "outer_race_radius", "inner_groove_radius",
                   "outer_groove_radius", "free_contact_angle")
#: Relative tolerance of :func:`check_table`'s comparison of geometries (a JSON round trip keeps 17 digits).
IDENTITY_RTOL = 1e-9
#: Ball-set positions ``bearing_coefficients`` averages by default (module docstring; ``stiffness --phases``).
DEFAULT_N_PHASES = 3


def bearing_identity(bearing) -> dict:
    """The geometry fingerprint of a bearing that a coefficient table carries (``operating_point
    ["bearing_geometry"]``): the fields of :data:`IDENTITY_FIELDS` [m, rad] and the material's Young's modulus
    [Pa] and Poisson ratio, all that the stiffness depends on besides the loads and options."""
    b = load_bearing(bearing)
    out = {k: (int(getattr(b, k)) if k == "n_balls" else float(getattr(b, k))) for k in IDENTITY_FIELDS}
    out.update(youngs_modulus=float(b.material.youngs_modulus), poisson_ratio=float(b.material.poisson_ratio))
    return out


def check_table(coefficients, bearing, name: str = "coefficients") -> BearingCoefficients:
    """``coefficients`` (a :class:`BearingCoefficients` or its ``to_dict`` dict, e.g. read from JSON) as a
    record, if it was made for ``bearing``; else InputError naming ``name``: a wrong type, a table without the
    bearing's fingerprint (``operating_point["bearing_geometry"]``, written by :func:`bearing_coefficients`
    since it exists; older or hand-made tables are refused, not guessed: make them again), or one made for
    another geometry (:func:`bearing_identity`, relative tolerance :data:`IDENTITY_RTOL`)."""
    if isinstance(coefficients, dict):
        try:
            coefficients = BearingCoefficients.from_dict(coefficients)
        except InputError as exc:
            raise InputError(f"{name}: not a coefficient table ({exc})") from None
    if not isinstance(coefficients, BearingCoefficients):
        raise InputError(f"{name}: expected a coefficient table (exudyn_bearing.bearing_coefficients(...) or its "
                         f"to_dict() dict), got {coefficients!r} ({type(coefficients).__name__})")
    b = load_bearing(bearing)
    op = coefficients.operating_point
    made_for = op.get("bearing_geometry")
    if not isinstance(made_for, dict):
        raise InputError(f"{name}: the table does not say which bearing it was made for (no operating_point"
                         f"['bearing_geometry']; tables before it or made by hand); make it with "
                         f"exudyn_bearing.bearing_coefficients({b.name!r}, ...)")
    own = bearing_identity(b)
    differ = []
    for key, value in own.items():
        other = made_for.get(key)
        try:
            same = other is not None and math.isclose(float(other), value, rel_tol=IDENTITY_RTOL, abs_tol=1e-15)
        except (TypeError, ValueError):
            same = False
        if not same:
            differ.append(f"{key} {other!r} against {value:.6g}")
    if differ:
        raise InputError(f"{name}: the table was made for another bearing ({op.get('bearing', '?')!r}) than this "
                         f"{b.name!r}: {'; '.join(differ[:3])}; make it with "
                         f"exudyn_bearing.bearing_coefficients(bearing, ...) for the bearing it is used with")
    return coefficients


def bearing_coefficients(bearing, speeds, Fr=0.0, Fa=0.0, Mx=0.0, My=0.0, *, Fy=0.0, n_phases=DEFAULT_N_PHASES,
                         phase=0.0, **options) -> BearingCoefficients:
    """Stiffness and damping of a bearing at each speed (module docstring).

    Parameters
    ----------
    bearing : BallBearing or str
        Geometry (catalogue name or JSON file), with its clearance.
    speeds : array
        Inner-ring speeds [rad/s], >= 0, strictly increasing.
    Fr, Fy, Fa, Mx, My : float
        Loads on the inner ring [N, N m] (:func:`~.solve.solve_quasistatic`).
    n_phases : int
        Ball-set positions averaged over one ball pitch (1: none; default
        :data:`DEFAULT_N_PHASES`).
    phase : float
        Azimuth of ball 0 [rad] of the first position.
    **options
        Passed to :func:`~.solve.solve_quasistatic` (``control``,
        ``traction``, ``lubricant``, ``ring_growth``, ``fit``,
        ``temperatures``, ``fixed``, ``hertz_method``, ``omega_outer``, ...).

    Returns
    -------
    BearingCoefficients
        ``speeds``, ``stiffness`` and ``damping`` (n, 5, 5), ``method`` and
        ``operating_point`` (bearing name and geometry fingerprint
        (:func:`bearing_identity`), loads, clearance, solver options, the
        ring displacement at each speed, the largest relative spread of K
        and C over the phases, the solver's stiffness checks).

    Examples
    --------
    >>> import exudyn_bearing as eb
    >>> c = eb.bearing_coefficients("6208", [100.0, 500.0], Fr=3000.0)
    >>> [round(float(k) / 1e8, 3) for k in c.stiffness[:, 0, 0]]   # k_xx [1e8 N/m], mean of 3 ball-set phases
    [1.818, 1.821]
    >>> c.operating_point["n_phases"]
    3
    """
    for w in np.ravel(np.asarray(speeds, dtype=object)):  # a "500" is not a speed (float() would read it)
        check_number("speeds", w)
    s = speed_array(speeds)
    b = load_bearing(bearing)
    if isinstance(n_phases, bool) or not isinstance(n_phases, (int, np.integer)) or not 1 <= n_phases <= 64:
        raise InputError(f"n_phases: expected an integer in [1, 64], got {n_phases!r}")
    for bad in ("omega", "phase", "start", "stiffness"):
        if bad in options:
            raise InputError(f"{bad}: set by bearing_coefficients, not an option")
    phases = float(phase) + 2.0 * math.pi / b.n_balls * np.arange(n_phases) / n_phases
    # stiffness and damping do not depend on the balls' inertia along the orbit (which concerns the kinematics
    # and losses, solvers/quasistatic/inertia.py): no check per table entry unless asked for
    options = {"inertia_check": False, **options}
    n = s.size
    kk = np.zeros((n, 5, 5))
    cc = np.zeros((n, 5, 5))
    disp = np.zeros((n, 5))
    spread_k = np.zeros(n)
    spread_c = np.zeros(n)
    checks = []
    prev = [None] * n_phases
    for i, w in enumerate(s):
        ks, cs = [], []
        for m, ph in enumerate(phases):
            sol = solve_quasistatic(b, Fr, Fa, Mx, My, Fy=Fy, omega=float(w), phase=float(ph), start=prev[m],
                                    **options)
            prev[m] = sol
            ks.append(sol.stiffness)
            cs.append(sol.damping)
            if m == 0:
                disp[i] = sol.displacement
                checks.append({k: sol.stiffness_check[k] for k in
                               ("relative_change_half_step", "asymmetry", "condensed_difference")})
        ks, cs = np.array(ks), np.array(cs)
        kk[i], cc[i] = ks.mean(axis=0), cs.mean(axis=0)
        spread_k[i] = float(np.ptp(ks, axis=0).max() / max(np.abs(kk[i]).max(), 1e-300))
        spread_c[i] = float(np.ptp(cs, axis=0).max() / max(np.abs(cc[i]).max(), 1e-300))
    op = {"bearing": b.name, "bearing_geometry": bearing_identity(b), "Fr": float(Fr), "Fy": float(Fy), "Fa": float(Fa), "Mx": float(Mx), "My": float(My),
          "diametral_clearance": b.diametral_clearance, "n_phases": int(n_phases), "phase": float(phase),
          "options": {k: (v if isinstance(v, (int, float, str, bool, dict, type(None))) else str(v))
                      for k, v in options.items()},
          "displacement": disp.tolist(), "displacement_axes": ["delta_x", "delta_y", "delta_a", "tilt_x", "tilt_y"],
          "phase_spread_stiffness": spread_k.tolist(), "phase_spread_damping": spread_c.tolist(),
          "stiffness_checks": checks}
    return BearingCoefficients(s, kk, cc, op, METHOD)
