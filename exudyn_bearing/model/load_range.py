"""The load range of the elastic contact model.

Hertz contact is elastic: above the yield of the races it no longer describes
the contact (plastic flow takes load off the peak pressure and leaves dents),
and at absurd loads its overlaps exceed the radii it linearises about (a
6208 under 1e9 N: 75 mm). :func:`check_load_range` refuses scenes whose
quasi-static contact pressure exceeds :data:`MAX_CONTACT_PRESSURE`, 4.2 GPa:
the contact stress of ISO 76 for the static load rating C_0 of ball
bearings, at which bearing steel takes a permanent dent of 1e-4 of the ball
diameter (the accepted limit of elastic behaviour in bearing practice).
Radial loads that reach it: 6208 21.8 kN (the DEM papers' 3000 N give
2.2 GPa), 6004 5.6 kN, 7208 6.0 kN, ACBB-120 58 kN.
"""
from __future__ import annotations

import math

import numpy as np

import warnings

from ..data import BallBearing, InputError
from ..physics import hertz
from ..physics.geometry import raceway_radii
from ..physics.load_distribution import StaticSolution, static_equilibrium

__all__ = ["MAX_CONTACT_PRESSURE", "contact_pressures", "check_load_range", "check_load_estimate", "pressure_excess", "check_pressures",
           "check_run_pressures", "ContactPressureWarning", "SUSTAINED_FRACTION"]

#: Largest accepted Hertz pressure [Pa] (ISO 76: 4200 MPa, the contact stress of
#: the static load rating of ball bearings other than self-aligning).
MAX_CONTACT_PRESSURE = 4.2e9


def contact_pressures(solution: StaticSolution) -> tuple[np.ndarray, np.ndarray]:
    """Hertz p_max [Pa] of every ball at the inner and outer race of a quasi-static solution."""
    b = solution.bearing
    em = hertz.material_reduced_modulus(b.material)
    alpha = np.asarray(solution.contact_angle, float)
    out = []
    for r_c, sign, inner in ((b.inner_groove_radius, -1.0, True), (b.outer_groove_radius, 1.0, False)):
        rx, ry = raceway_radii(b.ball_radius, r_c, b.pitch_radius + sign * b.ball_radius * np.cos(alpha), alpha,
                               inner)
        out.append(np.asarray(hertz.hertz_contact(rx, ry, em, load=solution.q, method=solution.hertz_method).p_max,
                              float))
    return out[0], out[1]


def _load_name(radial_load, axial_load, names):
    if radial_load > 0.0:
        return names[0]
    return names[1] if axial_load > 0.0 else names[2]


def check_load_range(bearing: BallBearing, radial_load: float, axial_load: float = 0.0,
                     hertz_method: str = "exact", names=("Fr", "Fa", "Pd"), phase: float = 0.0,
                     solution: StaticSolution | None = None) -> StaticSolution | None:
    """The quasi-static solution under the loads (None for an unloaded
    bearing with clearance), or InputError when a contact pressure exceeds
    :data:`MAX_CONTACT_PRESSURE`. The message starts with the load's name
    (``names``: radial, axial, preload) and states the limit.

    A load far outside (an estimate of the pressure above three times the
    limit) is refused before the equilibrium is solved, which may not
    converge there."""
    b = bearing
    fr, fa = float(radial_load), float(axial_load)
    name = _load_name(fr, fa, names)
    limit = MAX_CONTACT_PRESSURE
    if solution is None:
        if not (fr > 0.0 or fa > 0.0 or b.diametral_clearance < 0.0):
            return None
        check_load_estimate(b, fr, fa, hertz_method, names)
        try:
            solution = static_equilibrium(b, fr, fa, phase=phase, hertz_method=hertz_method)
        except InputError as exc:  # the load's own name in the caller's spelling (names), not the solver's
            head, sep, rest = str(exc).partition(": ")
            spelled = {"radial_load": names[0], "axial_load": names[1]}.get(head)
            if spelled is None or not sep:
                raise
            raise InputError(f"{spelled}: {rest}") from None
    p_in, p_out = contact_pressures(solution)
    worst = max(float(np.max(p_in, initial=0.0)), float(np.max(p_out, initial=0.0)))
    if worst > limit:
        race = "inner" if np.max(p_in, initial=0.0) >= np.max(p_out, initial=0.0) else "outer"
        pd = b.diametral_clearance
        loads = f"F_r = {fr:g} N, F_a = {fa:g} N" + (f", P_d = {pd * 1e6:.3g} um" if pd < 0.0 else "")
        raise InputError(f"{name}: {loads} give a contact pressure of {worst / 1e9:.3g} GPa at the {race} race (ball load "
                         f"{float(np.max(solution.q)):.4g} N), above {limit / 1e9:g} GPa, the limit of the elastic "
                         "contact model (ISO 76 static load rating): reduce the load")
    return solution


def check_load_estimate(bearing: BallBearing, radial_load: float, axial_load: float = 0.0,
                        hertz_method: str = "exact", names=("Fr", "Fa", "Pd")) -> None:
    """InputError (starting with the load's name, ``names`` as in
    :func:`check_load_range`) when an estimate of the contact pressure, Stribeck's
    5 F / Z on one ball at the free contact angle (at least 10 degrees for the
    axial load), exceeds three times :data:`MAX_CONTACT_PRESSURE`: loads so far
    outside that an equilibrium solver may not converge there. No solve; the
    loads in range are checked on the solution."""
    b = bearing
    fr, fa = float(radial_load), float(axial_load)
    limit = MAX_CONTACT_PRESSURE
    a0 = b.free_contact_angle
    q_est = 5.0 * (abs(fr) / math.cos(a0) + abs(fa) / math.sin(max(a0, math.radians(10.0)))) / b.n_balls
    if q_est > 0.0:
        p_est = _pressure_at(b, q_est, a0, hertz_method)
        if p_est > 3.0 * limit:
            raise InputError(f"{_load_name(abs(fr), abs(fa), names)}: F_r = {fr:g} N, F_a = {fa:g} N put about "
                             f"{p_est / 1e9:.3g} GPa on the races, far above {limit / 1e9:g} GPa, the limit of the "
                             "elastic contact model (ISO 76 static load rating): reduce the load")


def _pressure_at(b: BallBearing, q: float, alpha: float, hertz_method: str) -> float:
    """Hertz p_max [Pa] of one ball load ``q`` at contact angle ``alpha``, the larger of both races."""
    em = hertz.material_reduced_modulus(b.material)
    worst = 0.0
    for r_c, sign, inner in ((b.inner_groove_radius, -1.0, True), (b.outer_groove_radius, 1.0, False)):
        rx, ry = raceway_radii(b.ball_radius, r_c, b.pitch_radius + sign * b.ball_radius * math.cos(alpha), alpha,
                               inner)
        worst = max(worst, float(hertz.hertz_contact(rx, ry, em, load=q, method=hertz_method).p_max))
    return worst


class ContactPressureWarning(UserWarning):
    """A dynamic run reached contact pressures above the elastic limit for a
    short time (impacts, a transient); sustained excess is an error."""


#: Share of a run's samples above the limit (or its last sample) from which
#: :func:`check_run_pressures` refuses the run instead of warning.
SUSTAINED_FRACTION = 0.1


def pressure_excess(p_inner, p_outer, limit: float = MAX_CONTACT_PRESSURE):
    """(p_max [Pa], race, ball) of the highest contact pressure when it exceeds
    ``limit``, else None. ``p_inner``, ``p_outer``: p_max per ball (or any
    array whose last axis is the ball)."""
    p_i = np.nan_to_num(np.asarray(p_inner, float), nan=0.0)
    p_o = np.nan_to_num(np.asarray(p_outer, float), nan=0.0)
    worst_i, worst_o = float(np.max(p_i, initial=0.0)), float(np.max(p_o, initial=0.0))
    worst = max(worst_i, worst_o)
    if worst <= limit:
        return None
    race, p = ("inner", p_i) if worst_i >= worst_o else ("outer", p_o)
    ball = int(np.unravel_index(int(np.argmax(p)), p.shape)[-1])
    return worst, race, ball


def _limit_text(worst, race, ball, limit):
    return (f"a contact pressure of {worst / 1e9:.3g} GPa at the {race} race of ball {ball}, above "
            f"{limit / 1e9:g} GPa, the limit of the elastic contact model (ISO 76 static load rating)")


def check_pressures(p_inner, p_outer, name: str, what: str, limit: float = MAX_CONTACT_PRESSURE) -> None:
    """InputError starting with ``name`` (the load or speed to change) when a
    contact pressure of a solution (p_max per ball at the inner and outer
    race, e.g. a quasi-static solution's) exceeds ``limit``; ``what``
    describes the case ("F_r = 1e5 N at 500 rad/s")."""
    excess = pressure_excess(p_inner, p_outer, limit)
    if excess is not None:
        raise InputError(f"{name}: {what} gives {_limit_text(*excess, limit)}: reduce the load or the speed")


def check_run_pressures(p_max, t, name: str = "omega", limit: float = MAX_CONTACT_PRESSURE) -> None:
    """The contact pressures a dynamic run sampled, ``p_max`` (samples, balls,
    2 races: inner, outer) at times ``t``: InputError starting with ``name``
    when the limit is exceeded at the last sample or in at least
    :data:`SUSTAINED_FRACTION` of the samples (loads the speed brings:
    centrifugal force, ring growth), a :class:`ContactPressureWarning` when
    it is exceeded only briefly (impacts, transients); both name the contact,
    the time and the limit."""
    p = np.asarray(p_max, float)
    if p.size == 0:
        return
    over = np.nanmax(p.reshape(p.shape[0], -1), axis=1) > limit
    if not over.any():
        return
    k = int(np.nanargmax(np.nanmax(p.reshape(p.shape[0], -1), axis=1)))
    worst, race, ball = pressure_excess(p[k, :, 0], p[k, :, 1], limit)
    share = float(over.mean())
    text = (f"the run reached {_limit_text(worst, race, ball, limit)} at t = {float(t[k]):.6g} s "
            f"({share:.0%} of the samples above it)")
    if over[-1] or share >= SUSTAINED_FRACTION:
        raise InputError(f"{name}: {text}; the loads this speed brings (centrifugal force, ring growth) or the "
                         "applied loads leave the elastic contact model: reduce the speed or the load")
    warnings.warn(f"{name}: {text}, briefly (an impact or a transient); the contact model is elastic",
                  ContactPressureWarning, stacklevel=3)
