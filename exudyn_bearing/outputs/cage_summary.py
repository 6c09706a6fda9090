"""What a run with the rigid cage reports about the cage (docs/theory/cage.md#outputs): its speed against
the kinematic one, the orbit of its centre (whirl radius and whirl ratio), the pocket and land forces and
the cage losses by kind."""
from __future__ import annotations

import math

import numpy as np

from ..model import layout as L

__all__ = ["rigid_cage_summary", "whirl", "whirl_spectrum", "whirl_line", "WHIRL_LINE_MIN_BINS", "cage_motion", "CAGE_SUMMARY_UNITS", "CAGE_LOSSES_NOT_MODELLED",
           "CAGE_LOSSES_NOT_MODELLED_FILM",
           "CENTRED_ORBIT", "REGULAR_RADIUS_VARIATION", "REGULAR_DIRECTION_SHARE"]

#: Units of the keys of :func:`rigid_cage_summary`.
CAGE_SUMMARY_UNITS = {
    "cage_slip": "- (1 - cage speed / kinematic cage speed at the mean operating contact angle)",
    "cage_whirl_radius": "m (RMS distance of the cage centre from its mean position over the window)",
    "cage_whirl_ratio": "- (mean rate of the cage centre's orbit angle about its mean position over the cage speed, "
                        "for a circling orbit; None for a centred or irregular one, whose mean turning rate is no "
                        "frequency: see cage_whirl_line)",
    "cage_whirl_line": "- (frequency of the strongest line of the cage centre's whirl spectrum over the window, over "
                       "the cage speed; + in the cage's direction of rotation; None when the window holds fewer "
                       "than WHIRL_LINE_MIN_BINS periods of it: not resolved from the orbit's mean)",
    "cage_whirl_line_share": "- (share of the orbit's power, about its mean position, in that line and its two "
                             "neighbouring bins)",
    "cage_whirl_resolution": "- (the spectrum's frequency resolution, 2 pi / window length, over the cage speed)",
    "cage_offset": "m (mean position of the cage centre, x and y)",
    "cage_axial_offset": "m (mean axial position of the cage)",
    "pocket_force_max": "N (largest ball / pocket normal force over the window)",
    "pocket_force_mean": "N (time mean of the normal forces of all pockets, per ball)",
    "land_force_mean": "N (time mean of the magnitude of the land's force on the cage)",
    "land_eccentricity_max": "- (largest offset of the cage from the land over the land clearance)",
    "cage_power_pocket": "W (time mean: friction and damping of the ball / pocket contacts, and the work of the "
                         "pocket film's forces and its shear with pocket_film)",
    "cage_power_land": "W (time mean: land film and contact)",
    "cage_motion": "centred, circling or irregular (docs/theory/cage.md#cage-motion)",
    "cage_orbit_ratio": "- (mean distance of the cage centre from its mean position over the land clearance, or "
                        "the pocket clearance of a ball-guided cage)",
    "cage_orbit_variation": "- (standard deviation of that distance over its mean)",
    "cage_centre_speed": "- (RMS speed of the cage centre over the clearance times the cage speed)",
    "rigid_cage_estimated": "the run's rigid-cage fields that are estimates, not a data sheet's "
                            "(docs/theory/cage.md#estimated-geometry; info BEARING lists their values)",
}

#: :func:`whirl_line`: a line is reported when it lies at least this many bins from zero frequency (the window
#: holds that many of its periods); nearer, the Hann window's main lobe about the removed mean (two bins wide)
#: takes it, as in a window of a few cage revolutions.
WHIRL_LINE_MIN_BINS = 3
#: :func:`cage_motion`: an orbit whose mean radius is below this share of the clearance is ``centred``;
CENTRED_ORBIT = 0.02
#: a larger one is ``circling`` when its radius varies by less than this share of its mean
REGULAR_RADIUS_VARIATION = 0.5
#: and at least this share of its steps turns in the orbit's mean direction; otherwise ``irregular``.
REGULAR_DIRECTION_SHARE = 0.9


def cage_motion(t, xy, clearance, cage_speed) -> dict:
    """Classify the orbit ``xy`` (n, 2) [m] of the cage centre sampled at ``t`` (docs/theory/cage.md#cage-motion):
    ``centred`` (mean distance r from the orbit's mean position below :data:`CENTRED_ORBIT` of the
    ``clearance``), ``circling`` (a regular orbit: r varies by less than :data:`REGULAR_RADIUS_VARIATION` of its
    mean and at least :data:`REGULAR_DIRECTION_SHARE` of the steps turn the same way) or ``irregular``; with
    the measures ``orbit_ratio`` (mean r / clearance), ``orbit_variation`` (std r / mean r) and
    ``centre_speed`` (RMS speed of the centre / (clearance |cage speed|))."""
    t = np.asarray(t, float)
    d = np.asarray(xy, float) - np.mean(xy, axis=0)
    r = np.hypot(d[:, 0], d[:, 1])
    mean_r = float(np.mean(r))
    out = {"orbit_ratio": mean_r / clearance, "orbit_variation": math.nan, "centre_speed": math.nan}
    if len(t) > 2 and cage_speed:
        v = np.diff(xy, axis=0) / np.diff(t)[:, None]
        out["centre_speed"] = float(np.sqrt(np.mean(np.sum(v * v, axis=1)))) / (clearance * abs(cage_speed))
    if mean_r < CENTRED_ORBIT * clearance or len(t) < 3:
        return {"type": "centred", **out}
    out["orbit_variation"] = float(np.std(r)) / mean_r
    turn = np.diff(np.unwrap(np.arctan2(d[:, 1], d[:, 0])))
    share = float(np.mean(np.sign(turn) == np.sign(np.sum(turn)))) if np.any(turn) else 0.0
    regular = out["orbit_variation"] < REGULAR_RADIUS_VARIATION and share >= REGULAR_DIRECTION_SHARE
    return {"type": "circling" if regular else "irregular", **out}

#: Cage losses the rigid cage leaves out (part of ``not_modelled``).
CAGE_LOSSES_NOT_MODELLED = ("cage windage and the oil's churning by the cage",
                            "the pocket's oil film (the ball / pocket contact is dry Hertz with Coulomb friction; "
                            "Scenario(pocket_film=True) adds the film's forces and its shear)")
#: The same with ``Scenario(pocket_film=True)``: the film's normal forces and its shear are modelled, for a
#: flooded pocket and a sphere facing a plane wall (physics/pocket_film.py).
CAGE_LOSSES_NOT_MODELLED_FILM = ("cage windage and the oil's churning by the cage",
                                 "a starved pocket (the pocket film is taken flooded at both walls) and the wall's "
                                 "conformity (the film's forces and shear are a sphere's facing a plane: a lower "
                                 "bound); the film's moment on the ball's rotation about the wall's normal")


def whirl(t, xy, cage_speed):
    """(radius [m], ratio [-]) of the orbit of the cage centre ``xy`` (n, 2) sampled at ``t`` (n,): the RMS
    distance from its mean position, and the mean rate of the orbit angle about it (unwrapped, end minus
    start over the duration) over ``cage_speed`` [rad/s] (NaN when the cage does not turn or the orbit is
    below 1e-12 m)."""
    t = np.asarray(t, float)
    xy = np.asarray(xy, float)
    d = xy - xy.mean(axis=0)
    radius = float(np.sqrt(np.mean(np.sum(d * d, axis=1))))
    if radius < 1e-12 or len(t) < 3 or not cage_speed:
        return radius, math.nan
    angle = np.unwrap(np.arctan2(d[:, 1], d[:, 0]))
    rate = float(angle[-1] - angle[0]) / float(t[-1] - t[0])
    return radius, rate / cage_speed


def whirl_spectrum(t, xy, cage_speed):
    """(f [rad/s], a [m]) of the whirl of the cage centre ``xy`` (n, 2) [m], sampled at the equally spaced times
    ``t`` (n,) [s]: the FFT of x + i y about the mean position with a Hann window, its angular frequencies
    signed + in the cage's direction of rotation (the sign of ``cage_speed``), the amplitude of each line. The
    frequency resolution is 2 pi / the window's length (the line of a whirl at the frequency f_0 spreads over
    the bins next to it). ValueError when the times are not equally spaced (within 1e-6 of the step)."""
    t = np.asarray(t, float)
    xy = np.asarray(xy, float)
    step = np.diff(t)
    if len(t) < 2 or not np.all(np.abs(step - step.mean()) <= 1e-6 * step.mean()):
        raise ValueError("whirl_spectrum: the samples are not equally spaced in time")
    zc = (xy[:, 0] - xy[:, 0].mean()) + 1j * (xy[:, 1] - xy[:, 1].mean())
    f = np.fft.fftfreq(zc.size, d=step.mean()) * 2.0 * np.pi * (1.0 if cage_speed >= 0.0 else -1.0)
    return f, np.abs(np.fft.fft(zc * np.hanning(zc.size)))


def whirl_line(t, xy, cage_speed):
    """(line [-], share [-], resolution [-]) of the cage centre's whirl (:func:`whirl_spectrum`): the frequency
    of its strongest line over the cage speed (+ in the cage's direction of rotation), the share of the
    spectrum's power in that bin and its two neighbours, and the bin width over the cage speed; NaNs when the
    cage does not turn, the orbit is below 1e-12 m or the samples are too few or not equally spaced, and a NaN
    line (share and resolution kept) when the strongest line lies fewer than :data:`WHIRL_LINE_MIN_BINS` bins from
    zero frequency. Unlike the
    mean turning rate of :func:`whirl`, the line stays where it is in an irregular orbit: on the 6208's
    land-guided cage (3000 N, 500 rad/s, last 0.15 s of 0.6 s) the mean rate was 0.86, 0.82 and 1.41 of the
    cage speed at steps of 2, 1 and 0.5 us, the line +1.49 at all three (docs/theory/cage.md#cage-motion)."""
    nan = (math.nan, math.nan, math.nan)
    xy = np.asarray(xy, float)
    if len(t) < 8 or not cage_speed or float(np.sqrt(np.mean(np.sum((xy - xy.mean(axis=0)) ** 2, axis=1)))) < 1e-12:
        return nan
    try:
        f, a = whirl_spectrum(t, xy, cage_speed)
    except ValueError:
        return nan
    power = a * a
    i = int(np.argmax(power))
    near = power[[(i - 1) % len(a), i, (i + 1) % len(a)]].sum()  # the FFT's bins wrap around
    resolution = float(abs(f[1] - f[0]) / abs(cage_speed))
    line = float(f[i] / abs(cage_speed))
    if abs(line) < WHIRL_LINE_MIN_BINS * resolution * (1.0 - 1e-9):
        line = math.nan
    return line, float(near / power.sum()), resolution


def rigid_cage_summary(data, w: slice, params, cage_speed: float, kinematic_cage_speed: float | None) -> dict:
    """The rigid cage's summary over the samples ``w`` (keys of :data:`CAGE_SUMMARY_UNITS`); ``data`` the
    run's sampled arrays (``xc``, ``vc``, ``cage_load``, ``glob``), ``params`` its parameter vector."""
    t = data["t"][w]
    xc = data["xc"][w]
    glob = data["glob"][w]
    radius, ratio = whirl(t, xc[:, 0, :2], cage_speed)
    line, share, resolution = whirl_line(t, xc[:, 0, :2], cage_speed)
    pocket = data["cage_load"][w][:, :, 0]
    out = {
        "cage_slip": (1.0 - cage_speed / kinematic_cage_speed) if kinematic_cage_speed else None,
        "cage_whirl_radius": radius,
        "cage_whirl_ratio": None if math.isnan(ratio) else ratio,
        "cage_whirl_line": None if math.isnan(line) else line,
        "cage_whirl_line_share": None if math.isnan(share) else share,
        "cage_whirl_resolution": None if math.isnan(resolution) else resolution,
        "cage_offset": [float(x) for x in xc[:, 0, :2].mean(axis=0)],
        "cage_axial_offset": float(xc[:, 0, 2].mean()),
        "pocket_force_max": float(pocket.max()),
        "pocket_force_mean": float(pocket.mean()),
        "land_force_mean": float(np.mean(np.hypot(glob[:, L.G_LAND_FX], glob[:, L.G_LAND_FY]))),
        "land_eccentricity_max": float(glob[:, L.G_LAND_ECC].max()),
        "cage_power_pocket": float(glob[:, L.G_POCKET_POWER].mean()),
        "cage_power_land": float(glob[:, L.G_LAND_POWER].mean()),
    }
    if params[L.P_GUIDANCE] < 0.5:
        for key in ("land_force_mean", "land_eccentricity_max", "cage_power_land"):
            out[key] = None
    clearance = params[L.P_LAND_C] if params[L.P_GUIDANCE] > 0.5 else params[L.P_POCKET_GAP]
    motion = cage_motion(t, xc[:, 0, :2], clearance, cage_speed)
    out["cage_motion"] = motion["type"]
    if motion["type"] != "circling":  # the mean turning rate of a centred or irregular orbit is no frequency
        out["cage_whirl_ratio"] = None
    for key in ("orbit_ratio", "orbit_variation", "centre_speed"):
        out[f"cage_{key}"] = None if math.isnan(motion[key]) else motion[key]
    return out
