"""Checks of the window a dynamic summary averages over: is it steady (drift
and oscillation of the reported quantities against stated thresholds), the
largest ball load at psi = 0 (interpolated when no ball passes psi = 0), and
the energy balance of the window (docs/theory/dynamics.md, "Losses and the
energy balance"). Pure functions of sampled arrays; :class:`.results.Results`
feeds them.
"""
from __future__ import annotations

import math

import numpy as np

from ..data import InputError
from ..physics.losses import LOSS_FLOOR_MU  # noqa: F401 (the summaries' loss floor; one definition)

__all__ = ["sample_window", "STEADY_BLOCKS", "MIN_STEADY_SAMPLES", "DRIFT_REL", "OSCILLATION_REL", "DRIFT_DEG", "OSCILLATION_DEG",
           "LOSS_DRIFT_REL", "LOSS_OSCILLATION_REL", "LOSS_FLOOR_MU", "SPEED_FLOOR", "PSI0_TOLERANCE", "load_at_psi0",
           "STEADY_THRESHOLDS", "SteadyStateWarning", "drift_and_oscillation", "passage_average", "steadiness", "q_max_at_psi0",
           "energy_balance", "EnergyBalanceWarning", "ENERGY_TOLERANCE", "ENERGY_FLOOR_OMEGA", "energy_check", "energy_floor"]

#: Blocks the window is cut into for the oscillation measure: the standard
#: deviation of the block means (after removing the linear trend) shows a
#: slow oscillation that the linear trend misses; eight blocks of the main
#: job's 0.1 s window are 12.5 ms long, and the series are averaged over the
#: ball passage first (:func:`passage_average`).
STEADY_BLOCKS = 8
#: Fewest samples in which steadiness is measured (two per block); a shorter
#: window is reported as not steady, "too short to measure".
MIN_STEADY_SAMPLES = 2 * STEADY_BLOCKS
#: Largest relative drift (linear-trend slope times the window length, over
#: the mean) of ball loads, speeds and the ring displacement: half the 1 %
#: within which issue 18 compares a DEM steady state with the quasi-static
#: equilibrium, so that a window that passes can be compared at that
#: tolerance. The README main job's steady window drifts by 0.19 % (q_max),
#: the 7208 run of issue 18 (0.05 s, no cage) by 4.3 % (q_max) and 2.0 % (cage)
#: (``simulate ... --json``, ``steady.drift``).
DRIFT_REL = 0.005
#: Largest relative standard deviation of the detrended block means of ball
#: loads, speeds and ring displacement: the 1 % comparison tolerance itself
#: (the window mean is then known to about 1 %/sqrt(8)). The main job's
#: largest is 0.21 % (q_max_inner), the 7208's 0.7 %.
OSCILLATION_REL = 0.01
#: Largest drift of a contact angle [deg] (absolute: a radial deep-groove
#: bearing runs at 0 deg, where a relative measure means nothing): half the
#: 0.5 deg within which issue 18 compares the spin-axis angle beta. The 7208
#: run of issue 18 drifts by 0.71 deg in alpha_inner over its last quarter.
DRIFT_DEG = 0.25
#: Largest standard deviation of the detrended block means of a contact
#: angle [deg]: the 0.5 deg comparison tolerance of issue 18.
OSCILLATION_DEG = 0.5
#: Largest relative drift of the losses (friction torque, dissipation): half
#: the 3 % within which issue 18 compares the dissipation of the solvers.
LOSS_DRIFT_REL = 0.015
#: Largest relative standard deviation of the detrended block means of the
#: losses: the 3 % comparison tolerance of issue 18.
LOSS_OSCILLATION_REL = 0.03
#: Speeds are judged against at least this fraction of the scenario's
#: speed (a run coasting to rest has mean speeds near zero).
SPEED_FLOOR = 1e-3
#: A ball is "at psi = 0" when a sampled azimuth of a loaded ball lies this
#: close to psi = 0 [rad] (1 deg): the load of a rigid ring's distribution
#: Q0 (1 - (1 - cos psi)/(2 eps))^1.5 is then at most 0.05 % below Q0 for a
#: load-zone factor eps >= 0.25; farther, q_max is interpolated.
PSI0_TOLERANCE = math.radians(1.0)

#: Largest |residual| of the energy check of a window (issue 22, item 4c): the rings' drive power
#: equals the sum of the reported losses plus the rate of change of the balls' kinetic energy within
#: 1 % of the drive power. The engines integrate the powers with the step's end value (an O(dt)
#: quadrature) and the elastic energy stored in the contacts returns only over whole ball passages,
#: so a steady window closes to well below this; a window that does not is either not steady or its
#: losses are misreported.
ENERGY_TOLERANCE = 0.01
#: Least speed [rad/s] of the power scale below which the energy check of a window does not judge:
#: the floor is the loss-floor torque LOSS_FLOOR_MU (|Fr| + |Fa|) r_p times max(|omega|, this), the
#: slowest speed of the papers' quasi-static protocol (1 rad/s). At rest the balance drive = losses +
#: dKE/T leaves out the elastic energy of the contacts, which a settling ring changes by as much as its
#: losses (6208, 3000 N at omega 0 with rolling resistance: -1.8e-4 W drive against 5.1e-5 W of losses,
#: a "residual" of 128 %; the floor there is 9.1e-3 W).
ENERGY_FLOOR_OMEGA = 1.0

#: Thresholds of :func:`steadiness` by kind of quantity: (drift, oscillation,
#: unit of both).
STEADY_THRESHOLDS = {
    "relative": (DRIFT_REL, OSCILLATION_REL, "- (of the mean)"),
    "angle": (DRIFT_DEG, OSCILLATION_DEG, "deg"),
    "loss": (LOSS_DRIFT_REL, LOSS_OSCILLATION_REL, "- (of the mean, at least the loss floor)"),
}


class SteadyStateWarning(UserWarning):
    """The window of a dynamic summary is not steady."""


class EnergyBalanceWarning(UserWarning):
    """The energy check of a dynamic summary's window fails: the drive power is not the sum of the reported
    losses and the rate of change of the kinetic energy (:func:`energy_check`)."""


def drift_and_oscillation(t, x, blocks: int = STEADY_BLOCKS, length: float | None = None) -> tuple[float, float]:
    """(drift, oscillation) of a series x(t) over its window, in its unit:
    drift = least-squares slope times the window length (``length``, else
    t[-1] - t[0]);
    oscillation = standard deviation (ddof 1) of the means of ``blocks``
    equal blocks of the series with its linear trend removed."""
    t = np.asarray(t, float)
    x = np.asarray(x, float)
    tc = t - t.mean()
    den = float(np.dot(tc, tc))
    slope = float(np.dot(tc, x - x.mean()) / den) if den > 0.0 else 0.0
    resid = x - x.mean() - slope * tc
    means = np.array([b.mean() for b in np.array_split(resid, blocks) if b.size])
    osc = float(np.std(means, ddof=1)) if means.size > 1 else 0.0
    return slope * float(t[-1] - t[0] if length is None else length), osc


def passage_average(t, x, period: float | None):
    """(t, x) averaged over a moving window of one ball-passage ``period`` [s]
    (the nearest whole number of samples; the valid part only): the largest
    ball load, the ring's vibration and the speeds repeat with the passage of
    the balls, and a linear trend fitted over a window that is not a whole
    number of passages picks up a slope from it (0.85 % in q_max over seven
    passes). Unchanged when the period is unknown, shorter than two samples
    or leaves fewer than :data:`MIN_STEADY_SAMPLES` averages."""
    t = np.asarray(t, float)
    x = np.asarray(x, float)
    if period is None or not math.isfinite(period) or len(t) < 2:
        return t, x
    k = int(round(period / float(np.median(np.diff(t)))))
    if k < 2 or len(t) - k + 1 < MIN_STEADY_SAMPLES:
        return t, x
    box = np.ones(k) / k
    return np.convolve(t, box, mode="valid"), np.convolve(x, box, mode="valid")


def steadiness(t, quantities: dict, ramp: str | None = None, period: float | None = None) -> dict:
    """Is the window steady? ``quantities``: name -> (series (n,), kind,
    scale) or (series, kind, scale, why_not_judged); kind a key of
    :data:`STEADY_THRESHOLDS`; scale the value drift and oscillation are
    divided by (ignored for "angle", judged in deg); a quantity with a
    ``why_not_judged`` text is measured and reported but does not decide.
    ``ramp``: the ramp phase the window covers (then not steady by
    definition). ``period``: the ball-passage period [s]; each series is
    first averaged over it (:func:`passage_average`). Non-finite samples are
    left out of a series.

    Returns {"steady": bool, "flagged": [names], "reason": str or None,
    "drift": {name: value}, "oscillation": {name: value}, "not_judged":
    {name: why}, "thresholds": {kind: {"drift", "oscillation", "unit"}},
    "measure": text}; drift and oscillation relative to the scale (angles
    in deg).
    """
    t = np.asarray(t, float)
    drift, osc, flagged, why, skipped = {}, {}, [], [], {}
    for name, (x, kind, scale, *note) in quantities.items():
        x = np.asarray(x, float)
        ok = np.isfinite(x)
        if ok.sum() < MIN_STEADY_SAMPLES:
            continue
        d, o = drift_and_oscillation(*passage_average(t[ok], x[ok], period), length=float(np.ptp(t[ok])))
        if kind != "angle":
            d, o = d / scale, o / scale
        drift[name], osc[name] = d, o
        if note and note[0]:
            skipped[name] = note[0]
            continue
        d_max, o_max, _unit = STEADY_THRESHOLDS[kind]
        if abs(d) > d_max:
            flagged.append(name)
            why.append(f"{name} drifts by {_fmt(d, kind)} over the window (threshold {_fmt(d_max, kind)})")
        elif o > o_max:
            flagged.append(name)
            why.append(f"{name} oscillates by {_fmt(o, kind)} (std of block means; threshold {_fmt(o_max, kind)})")
    if len(t) < MIN_STEADY_SAMPLES:
        why.insert(0, f"window too short to measure ({len(t)} samples, fewer than {MIN_STEADY_SAMPLES})")
    if ramp:
        why.insert(0, f"the window covers the {ramp} ramp (the speed changes: not steady by definition)")
    return {
        "steady": not why,
        "flagged": flagged,
        "reason": "; ".join(why) if why else None,
        "drift": drift,
        "oscillation": osc,
        "not_judged": skipped,
        "thresholds": {k: {"drift": d, "oscillation": o, "unit": u} for k, (d, o, u) in STEADY_THRESHOLDS.items()},
        "passage_period": period,
        "measure": (f"each series averaged over the ball-passage period (passage_period, s); drift: least-squares "
                    f"slope times the window length; oscillation: std of the means of "
                    f"{STEADY_BLOCKS} blocks of the detrended series; both over the scale of the quantity (its "
                    f"mean, a speed's at least {SPEED_FLOOR:g} of the rings' speed and regularizing_speed / r_p; "
                    f"the norm of the mean ring displacement; a loss below {LOSS_FLOOR_MU:g} (|Fr| + |Fa|) "
                    f"r_p [N m] (times max(|omega|, {ENERGY_FLOOR_OMEGA:g} rad/s) [W]) is measured against that floor "
                    f"and not judged), angles in deg"),
    }


def _fmt(v, kind):
    return f"{v:.3g} deg" if kind == "angle" else f"{100 * v:.3g} %"


def q_max_at_psi0(psi, q, tolerance: float = PSI0_TOLERANCE) -> tuple[float | None, str, float | None]:
    """The largest ball load of a window as the load at psi = 0.

    ``psi`` (any shape) [rad] ball azimuths from the load direction, ``q``
    (same shape) [N] their loads. When a loaded ball comes within
    ``tolerance`` of psi = 0, the largest sampled load ("ball at psi=0").
    Otherwise the peak of the rigid-ring load distribution fitted to the
    loaded samples ("interpolated"): the deflection of a ball between rings
    displaced rigidly by delta_r (radial) and delta_a (axial) is
    delta_a sin(alpha) + delta_r cos(alpha) cos(psi - psi_0) minus the
    clearance (Harris & Kotzalas, Rolling Bearing Analysis, 5th ed., 2006,
    vol. 1 ch. 7; docs/theory/load_distribution.md), and Q = K delta^1.5, so Q^(2/3) = A + C cos(psi)
    + S sin(psi), linear in (A, C, S): a least-squares fit, exact for the
    Stribeck shape Q0 cos(psi)^1.5 and for every load-zone factor; its peak
    Q0 = (A + sqrt(C^2 + S^2))^1.5 lies at psi_0 = atan2(S, C). Fewer than
    three loaded azimuths 0.5 deg apart cannot be fitted: then the largest
    sampled load ("largest sampled load: too few loaded azimuths to
    interpolate").

    Returns (q_max [N] or None without a loaded ball, method, psi_0 [rad] of
    the fitted peak or None).
    """
    psi = np.asarray(psi, float).ravel()
    q = np.asarray(q, float).ravel()
    loaded = q > 0.0
    if not loaded.any():
        return None, "no loaded ball", None
    psi, q = np.angle(np.exp(1j * psi[loaded])), q[loaded]
    if np.min(np.abs(psi)) <= tolerance:
        return float(q.max()), "ball at psi=0", None
    if np.unique(np.round(psi / math.radians(0.5))).size < 3:
        return float(q.max()), "largest sampled load: too few loaded azimuths to interpolate", None
    m = np.stack([np.ones_like(psi), np.cos(psi), np.sin(psi)], axis=1)
    (a, c, s), *_ = np.linalg.lstsq(m, q ** (2.0 / 3.0), rcond=None)
    peak = a + math.hypot(c, s)
    return float(max(peak, 0.0) ** 1.5), "interpolated", float(math.atan2(s, c))


def load_at_psi0(psi, q, tolerance: float = PSI0_TOLERANCE) -> float | None:
    """The mean load of the loaded balls that pass psi = 0: the steady Q_max of a window.

    ``psi`` (any shape) [rad] ball azimuths from the load direction, ``q``
    (same shape) [N] their loads. The mean of the loads of the loaded balls
    within ``tolerance`` of psi = 0 over the window's samples (each pass of a
    ball through psi = 0 counts once per sample it spends there): the load of
    the ball at psi = 0 of the steady distribution (Harris & Kotzalas, Rolling
    Bearing Analysis, 5th ed., 2006, vol. 1 ch. 7; docs/theory/load_distribution.md)
    where :func:`q_max_at_psi0` takes the largest sampled load, which in an
    engine that resolves the contacts' vibration (the reference engine, the
    element) includes its peaks. None when no loaded ball comes within
    ``tolerance`` (a coarsely sampled window: :func:`q_max_at_psi0` then
    interpolates).
    """
    psi = np.angle(np.exp(1j * np.asarray(psi, float).ravel()))
    q = np.asarray(q, float).ravel()
    near = (q > 0.0) & (np.abs(psi) <= tolerance)
    return float(np.mean(q[near])) if near.any() else None


def energy_balance(duration: float, drive: float, loads: float | None, dissipation: float, ke0: float,
                   ke1: float, stored_change: float | None = None) -> dict:
    """Energy balance of a window of ``duration`` [s]: ``drive`` the mean
    power that spins the inner ring [W], ``loads`` the mean net power of the
    applied loads through the ring's translation [W] (None: unknown, left
    out), ``dissipation`` the mean dissipated power [W], ``ke0``, ``ke1`` the
    kinetic energy of balls and cage balls at the window's ends [J],
    ``stored_change`` the change of the elastic energy stored in the contacts
    over the window [J] (None: not recorded, left out).

    Returns drive_power (drive + loads), load_power, dissipation,
    kinetic_energy_change (ke1 - ke0), contact_energy_change (``stored_change``)
    and energy_residual = (drive_power - dissipation - (kinetic_energy_change
    + contact_energy_change) / duration) / drive_power (None when there is no
    drive power or no duration)."""
    p_in = drive + (loads or 0.0)
    dke = ke1 - ke0
    res = None
    if duration > 0.0 and p_in != 0.0 and math.isfinite(p_in):
        res = (p_in - dissipation - (dke + (stored_change or 0.0)) / duration) / p_in
    return {"drive_power": float(p_in), "load_power": None if loads is None else float(loads),
            "dissipation": float(dissipation), "kinetic_energy_change": float(dke),
            "contact_energy_change": None if stored_change is None else float(stored_change),
            "energy_residual": None if res is None else float(res)}


def energy_floor(loss_floor_torque: float, omega_mean: float) -> float:
    """Drive power [W] below which :func:`energy_check` does not judge: the loss-floor torque [N m]
    times max(|omega_mean|, :data:`ENERGY_FLOOR_OMEGA`)."""
    return float(loss_floor_torque) * max(abs(float(omega_mean)), ENERGY_FLOOR_OMEGA)


def energy_check(drive_power: float, losses: dict, kinetic_energy_change: float, duration: float,
                 recorded_dissipation: float | None = None, floor: float = 0.0,
                 tolerance: float = ENERGY_TOLERANCE, contact_energy_change: float | None = None) -> dict:
    """Does the drive power of a window equal the sum of its reported losses plus the rate of change of
    the kinetic energy (and of the elastic energy stored in the contacts, ``contact_energy_change`` [J],
    when recorded), within ``tolerance`` of the drive power?

    ``losses``: component name -> mean power [W] over the window (None: not available, left out and
    named); ``kinetic_energy_change`` [J] over ``duration`` [s]; ``recorded_dissipation`` [W]: the
    engine's own total dissipation of the window (its cumulative ``dissipated_work``), against which
    the sum of the components is compared (``split_error``: round-off for components from the engines'
    works by loss, the sampling error of the split for time means of samples; not part of the check); ``floor`` [W]: a drive power below it is not judged (noise).

    Returns {"statement", "components" (names summed), "missing" (names without data), "drive_power",
    "power_loss_total", "kinetic_energy_rate", "contact_energy_rate" (None when not recorded), "residual"
    ((drive - losses - (dKE + dE_contact)/T) / drive), "tolerance", "passed" (None when not judged),
    "split_error", "reason"}."""
    used = [k for k, v in losses.items() if v is not None]
    missing = [k for k, v in losses.items() if v is None]
    total = float(sum(losses[k] for k in used))
    rate = kinetic_energy_change / duration if duration > 0.0 else float("nan")
    stored_rate = None
    if contact_energy_change is not None:
        stored_rate = contact_energy_change / duration if duration > 0.0 else float("nan")
    residual, passed, reason = None, None, None
    if not (duration > 0.0 and math.isfinite(drive_power) and drive_power != 0.0):
        reason = "no drive power or a window of one sample: not judged"
    else:
        residual = float((drive_power - total - rate - (stored_rate or 0.0)) / drive_power)
        if abs(drive_power) < floor:
            reason = f"drive power {drive_power:.3g} W below the loss floor {floor:.3g} W: not judged"
        else:
            passed = bool(abs(residual) <= tolerance)
    split = None
    if recorded_dissipation is not None and recorded_dissipation != 0.0 and not missing:
        split = float((total - recorded_dissipation) / recorded_dissipation)
    names = " + ".join(used) if used else "(no losses)"
    verdict = ("not judged" if passed is None else
               f"{'holds' if passed else 'FAILS'} (residual {100 * residual:.3g} %, tolerance {100 * tolerance:g} %)")
    change = ("kinetic_energy_change" if stored_rate is None else
              "(kinetic_energy_change + contact_energy_change)")
    return {"statement": f"drive_power = {names} + {change} / window length: {verdict}",
            "components": used, "missing": missing, "drive_power": float(drive_power), "power_loss_total": total,
            "kinetic_energy_rate": float(rate),
            "contact_energy_rate": None if stored_rate is None else float(stored_rate), "residual": residual, "tolerance": tolerance, "passed": passed,
            "split_error": split, "reason": reason}


def sample_window(t, fraction: float = 0.25, t_window=None) -> slice:
    """Slice of the last ``fraction`` of the sample times ``t``, or of those in ``t_window = (t0, t1)``
    (t0 <= t < t1); InputError for an empty ``t_window`` or a fraction outside (0, 1]. The window of the
    dynamic runs' and of the bearing levels' results."""
    t = np.asarray(t)
    n = len(t)
    if t_window is not None:
        idx = np.nonzero((t >= t_window[0]) & (t < t_window[1]))[0]
        if idx.size == 0:
            raise InputError(f"t_window: no samples in {t_window}")
        return slice(int(idx[0]), int(idx[-1]) + 1)
    if not 0.0 < fraction <= 1.0:
        raise InputError(f"fraction: must lie in (0, 1], got {fraction!r}")
    return slice(max(0, n - max(1, round(fraction * n))), n)
