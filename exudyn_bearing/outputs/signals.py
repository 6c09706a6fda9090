"""Condition-monitoring signal processing: spectrum, envelope spectrum, order
tracking, and the bearing's defect frequencies marked on a plot.

The signals are the series a run records at ``Scenario.signal_dt``
(``Results.signal("outer_fx")``, ``Results.signal_t``; layout
``model.layout.SIGNAL_FIELDS``), or any measured series.

* :func:`spectrum`: one-sided amplitude spectrum with a window (Hann by
  default), amplitudes of sinusoids (window's coherent gain removed),
  optionally zero-padded to interpolate the lines.
* :func:`envelope_spectrum`: envelope analysis (the high-frequency
  resonance technique, McFadden & Smith [1]_; Randall & Antoni [2]_ sec. 3):
  zero-phase Butterworth band-pass around a resonance the impacts excite,
  the envelope as the modulus of the analytic signal (Hilbert transform),
  and the spectrum of the envelope, in which a localized fault shows as
  lines at its defect frequency and harmonics, with sidebands at the
  frequency that modulates the impacts (shaft speed for the inner race,
  cage speed for a ball).
* :func:`select_band`: the band for the envelope, chosen automatically as the
  band whose complex envelope has the largest spectral kurtosis (the
  kurtogram of Antoni [3]_, here on a dyadic grid of bands with the bands
  shifted by a third, Butterworth filters instead of Antoni's filter bank):
  impacts ringing a resonance give a peaky envelope, a smooth or stationary
  signal a flat one. In the simulated bearing this finds the contact
  resonance of the inner ring on the ball contacts.
* :func:`order_spectrum`, :func:`order_track`: the signal resampled at equal
  increments of the shaft angle (integral of the shaft-speed series), so
  that lines tied to the shaft stay sharp when the speed changes (orders =
  cycles per shaft revolution; Randall & Antoni [2]_ sec. 4.1).
* :func:`defect_lines`, :func:`plot_defect_spectrum`: FTF, BPFO, BPFI and
  2 BSF (the ball fault hits both races each ball revolution), their
  harmonics and sidebands (BPFI +- shaft frequency, 2 BSF +- FTF) marked on
  a spectrum; :func:`run_defect_frequencies` computes them for a run at its
  speed and operating contact angle (Harris & Kotzalas, ch. 8, via
  :func:`exudyn_bearing.physics.kinematics.defect_frequencies`).

References
----------
.. [1] P. D. McFadden and J. D. Smith, "Model for the vibration produced by a
   single point defect in a rolling element bearing," J. Sound Vib., vol.
   96, no. 1, pp. 69-82, 1984, doi:10.1016/0022-460X(84)90595-9.
.. [2] R. B. Randall and J. Antoni, "Rolling element bearing diagnostics - A
   tutorial," Mech. Syst. Signal Process., vol. 25, no. 2, pp. 485-520,
   2011, doi:10.1016/j.ymssp.2010.07.017.
.. [3] J. Antoni, "Fast computation of the kurtogram for the detection of
   transient faults," Mech. Syst. Signal Process., vol. 21, no. 1,
   pp. 108-124, 2007, doi:10.1016/j.ymssp.2005.12.002.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..physics import kinematics

__all__ = ["spectrum", "bandpass", "envelope", "select_band", "envelope_spectrum", "EnvelopeSpectrum",
           "order_track", "order_spectrum", "strongest_line", "defect_lines", "run_defect_frequencies",
           "plot_defect_spectrum", "DEFECT_LINES", "defect_range", "envelope_signature", "FAULT_FREQUENCY"]

#: Defect frequency of each fault kind (``run_defect_frequencies`` keys).
FAULT_FREQUENCY = {"outer": "bpfo", "inner": "bpfi", "ball": "2bsf"}

#: Defect-frequency keys marked on plots, with their labels.
DEFECT_LINES = {"ftf": "FTF", "bpfo": "BPFO", "bpfi": "BPFI", "2bsf": "2 BSF"}


def _as_signal(x, fs):
    x = np.asarray(x, float)
    if x.ndim != 1 or x.size < 8:
        raise ValueError(f"x: expected a 1-D series of at least 8 samples, got shape {x.shape}")
    if not np.all(np.isfinite(x)):
        raise ValueError("x: the series contains NaN or inf")
    fs = float(fs)
    if not fs > 0.0:
        raise ValueError(f"fs: the sample rate must be > 0, got {fs}")
    return x, fs


def spectrum(x, fs, window="hann", pad=1, detrend=True):
    """One-sided amplitude spectrum of ``x`` sampled at ``fs`` [Hz].

    Parameters
    ----------
    x : array_like
        Uniformly sampled series.
    fs : float
        Sample rate [Hz].
    window : str or None
        scipy.signal window name ("hann" default; None: rectangular).
    pad : int
        Zero-padding factor (>= 1): 4 evaluates the spectrum on a 4 times
        finer frequency grid (interpolates lines, adds no resolution).
    detrend : bool
        Remove the mean first.

    Returns
    -------
    f : ndarray [Hz]
    amplitude : ndarray
        Amplitude of a sinusoid at f, in the unit of x (window gain removed).
    """
    from scipy.signal import get_window

    x, fs = _as_signal(x, fs)
    if detrend:
        x = x - x.mean()
    w = np.ones(x.size) if window is None else get_window(window, x.size)
    n = int(max(1, pad)) * x.size
    amp = np.abs(np.fft.rfft(x * w, n)) * 2.0 / w.sum()
    amp[0] *= 0.5
    return np.fft.rfftfreq(n, 1.0 / fs), amp


def bandpass(x, fs, band, order=4):
    """Zero-phase (forward-backward) Butterworth band-pass of ``x`` [1]_:
    ``band = (f_low, f_high)`` [Hz], 0 < f_low < f_high < fs/2."""
    from scipy.signal import butter, sosfiltfilt

    x, fs = _as_signal(x, fs)
    lo, hi = (float(v) for v in band)
    if not 0.0 < lo < hi < 0.5 * fs:
        raise ValueError(f"band: need 0 < f_low < f_high < fs/2 = {0.5 * fs:g} Hz, got ({lo:g}, {hi:g})")
    sos = butter(order, [lo, hi], btype="bandpass", fs=fs, output="sos")
    return sosfiltfilt(sos, x)


def envelope(x, fs, band, order=4):
    """Envelope of ``x`` in ``band``: modulus of the analytic signal (Hilbert
    transform) of the zero-phase band-passed series [2]_."""
    from scipy.signal import hilbert

    return np.abs(hilbert(bandpass(x, fs, band, order)))


def _kurtosis(env):
    """Spectral kurtosis of a complex envelope |z|: E|z|^4 / (E|z|^2)^2 - 2
    (0 for a stationary Gaussian signal, > 0 for impacts) [3]_."""
    m2 = np.mean(env ** 2)
    return float(np.mean(env ** 4) / (m2 * m2) - 2.0) if m2 > 0.0 else 0.0


def select_band(x, fs, f_min=None, method="energy", width=None, levels=6, order=4):
    """Band for envelope analysis, chosen from the signal.

    ``method="energy"`` (default): the band of ``width`` (default fs/16) with
    the largest signal energy above ``f_min`` (Welch spectrum summed over
    the band; candidate centres every width/4): the resonance the impacts
    ring, above the defect frequencies and their low harmonics ([2]_ sec.
    3.2; in the simulated bearing the contact resonance of the inner ring on
    the ball contacts). ``method="kurtosis"``: the band whose complex
    envelope has the largest spectral kurtosis [3]_ on Antoni's 1/3-binary
    grid (for k = 1..``levels`` the band [0, fs/2] cut into 2^k bands, and
    the same shifted by a third of their width); it favours the most
    impulsive band, which can be one of rare strong events rather than of
    the periodic fault impacts. ``f_min`` defaults to fs/50.

    Returns
    -------
    band : (float, float) [Hz]
    kurtosis : float
        Spectral kurtosis of the envelope in that band.
    """
    x, fs = _as_signal(x, fs)
    nyq = 0.5 * fs
    f_min = fs / 50.0 if f_min is None else float(f_min)
    if method == "energy":
        from scipy.signal import welch

        width = fs / 16.0 if width is None else float(width)
        if not 0.0 < width < nyq - f_min:
            raise ValueError(f"width: need 0 < width < fs/2 - f_min = {nyq - f_min:g} Hz, got {width:g}")
        f, pxx = welch(x - x.mean(), fs, nperseg=min(x.size, 1024))
        cum = np.concatenate([[0.0], np.cumsum(pxx)])
        best, best_e = None, -math.inf
        lo = f_min
        while lo + width < nyq * (1.0 - 1e-9):
            i0, i1 = np.searchsorted(f, [lo, lo + width])
            e = cum[i1] - cum[i0]
            if e > best_e:
                best, best_e = (lo, lo + width), e
            lo += 0.25 * width
        if best is None:
            raise ValueError(f"f_min: no band of {width:g} Hz between {f_min:g} Hz and fs/2 = {nyq:g} Hz")
        return best, _kurtosis(envelope(x, fs, best, order))
    if method != "kurtosis":
        raise ValueError(f"method: must be 'energy' or 'kurtosis', got {method!r}")
    best, best_k = None, -math.inf
    for level in range(1, int(levels) + 1):
        bw = nyq / 2 ** level
        for shift in (0.0, bw / 3.0):
            lo = shift
            while lo + bw < nyq * (1.0 - 1e-9):
                if lo >= f_min:
                    k = _kurtosis(envelope(x, fs, (lo, lo + bw), order))
                    if k > best_k:
                        best, best_k = (lo, lo + bw), k
                lo += bw
    if best is None:
        raise ValueError(f"f_min: no band between {f_min:g} Hz and fs/2 = {nyq:g} Hz at {levels} levels")
    return best, best_k


@dataclass
class EnvelopeSpectrum:
    """Result of :func:`envelope_spectrum`."""

    f: np.ndarray          #: frequencies [Hz]
    amplitude: np.ndarray  #: envelope amplitude spectrum [unit of x]
    band: tuple            #: band-pass band used [Hz]
    kurtosis: float        #: spectral kurtosis of the envelope in that band [-]

    def line(self, f_range):
        """(frequency, amplitude) of the strongest line in ``f_range`` [Hz]."""
        return strongest_line(self.f, self.amplitude, f_range)

    def at(self, f0, rel_tol=0.01):
        """Largest amplitude within f0 (1 +- rel_tol), at least at the
        frequency nearest f0 [unit of x]."""
        sel = (self.f >= f0 * (1.0 - rel_tol)) & (self.f <= f0 * (1.0 + rel_tol))
        sel[int(np.argmin(np.abs(self.f - f0)))] = True
        return float(self.amplitude[sel].max())


def envelope_spectrum(x, fs, band=None, f_min=None, method="energy", pad=4, window="hann", order=4, squared=False):
    """Envelope spectrum of ``x`` [2]_.

    Parameters
    ----------
    x, fs : series and its sample rate [Hz].
    band : (float, float) or None
        Band-pass band [Hz]; None chooses it from the signal
        (:func:`select_band` with ``f_min`` and ``method``).
    pad, window : see :func:`spectrum` (applied to the envelope, mean removed).
    squared : bool
        Spectrum of the squared envelope instead ([2]_ sec. 3.3).

    Returns
    -------
    EnvelopeSpectrum
    """
    x, fs = _as_signal(x, fs)
    if band is None:
        band, kurt = select_band(x, fs, f_min=f_min, method=method, order=order)
    else:
        kurt = None
    env = envelope(x, fs, band, order)
    if squared:
        env = env * env
    if kurt is None:
        kurt = _kurtosis(env)
    f, amp = spectrum(env, fs, window=window, pad=pad)
    return EnvelopeSpectrum(f, amp, tuple(float(b) for b in band), float(kurt))


def strongest_line(f, amplitude, f_range):
    """(frequency [Hz], amplitude) of the largest value of ``amplitude`` with
    f in ``f_range = (f_low, f_high)``."""
    f = np.asarray(f)
    sel = np.nonzero((f >= f_range[0]) & (f <= f_range[1]))[0]
    if sel.size == 0:
        raise ValueError(f"f_range: no frequencies in {f_range}")
    i = sel[np.argmax(np.asarray(amplitude)[sel])]
    return float(f[i]), float(amplitude[i])


def order_track(x, t, omega, samples_per_rev=None):
    """Resample ``x(t)`` at equal increments of the shaft angle.

    Parameters
    ----------
    x, t : array_like
        Series and its sample times [s] (uniform or not).
    omega : array_like or float
        Shaft speed at ``t`` [rad/s] (a series, e.g. ``Results.signal("omega")``,
        or a constant), > 0 throughout.
    samples_per_rev : int, optional
        Samples per revolution of the result (default: the mean number of
        time samples per revolution, rounded up to a power of two).

    Returns
    -------
    theta : ndarray [rad]
        Shaft angle of the resampled series, from 0.
    x_theta : ndarray
        The series at those angles (linear interpolation in angle).
    samples_per_rev : int
    """
    x = np.asarray(x, float)
    t = np.asarray(t, float)
    w = np.broadcast_to(np.asarray(omega, float), t.shape)
    if x.shape != t.shape or x.ndim != 1:
        raise ValueError(f"x, t: expected 1-D series of equal length, got {x.shape} and {t.shape}")
    if not np.all(w > 0.0):
        raise ValueError("omega: the shaft speed must stay > 0 for order tracking")
    theta = np.concatenate([[0.0], np.cumsum(0.5 * (w[1:] + w[:-1]) * np.diff(t))])
    revs = theta[-1] / (2.0 * math.pi)
    if samples_per_rev is None:
        samples_per_rev = int(2 ** math.ceil(math.log2(max(x.size / max(revs, 1e-12), 2.0))))
    samples_per_rev = int(samples_per_rev)
    n = int(math.floor(revs * samples_per_rev)) + 1
    th = np.arange(n) * (2.0 * math.pi / samples_per_rev)
    return th, np.interp(th, theta, x), samples_per_rev


def order_spectrum(x, t, omega, samples_per_rev=None, envelope_band=None, pad=4, window="hann"):
    """Order spectrum of ``x(t)`` against the shaft speed ``omega`` (:func:`order_track`).

    With ``envelope_band = (f_low, f_high)`` [Hz] the envelope of x in that
    band (:func:`envelope`, in time before resampling) is tracked instead:
    the envelope order spectrum, whose fault lines sit at the defect
    frequencies divided by the shaft frequency, whatever the speed does.

    Returns
    -------
    orders : ndarray [cycles per revolution]
    amplitude : ndarray
    """
    x = np.asarray(x, float)
    if envelope_band is not None:
        t_arr = np.asarray(t, float)
        fs = 1.0 / float(np.median(np.diff(t_arr)))
        x = envelope(x, fs, envelope_band)
    _th, xr, spr = order_track(x, t, omega, samples_per_rev)
    return spectrum(xr, spr, window=window, pad=pad)


def run_defect_frequencies(results, fraction=0.5) -> dict:
    """Defect frequencies [Hz] of a run (keys ``ftf``, ``bpfo``, ``bpfi``,
    ``bsf``, ``2bsf``, ``shaft``): Harris & Kotzalas' kinematics
    (:func:`exudyn_bearing.physics.kinematics.defect_frequencies`) at the
    run's mean inner- and outer-ring speeds and its operating contact angle, the mean
    contact angle of the loaded outer contacts over the last ``fraction``
    of the samples (the free contact angle if none is loaded)."""
    b = results.bearing
    w = results.window(fraction)
    omega = float(np.mean(results.global_series("omega")[w]))
    omega_o = float(np.mean(results.omega_outer_series()[w]))
    load = results.contact("load", "outer")[w]
    angle = results.contact("contact_angle", "outer")[w]
    alpha = float(np.mean(angle[load > 0.0])) if np.any(load > 0.0) else b.free_contact_angle
    f = kinematics.defect_frequencies(omega, omega_o, b.n_balls, b.ball_radius, b.pitch_radius, alpha)
    f["2bsf"] = 2.0 * f["bsf"]
    f["shaft"] = omega / (2.0 * math.pi)
    f["contact_angle"] = alpha
    return f


def defect_range(freqs: dict, margin=0.25):
    """Frequency range [Hz] of the fault lines: (1 - margin) times the lowest
    to (1 + margin) times the highest of BPFO, BPFI and 2 BSF. Its strongest
    envelope line tells which of the three faults a spectrum points at; it
    leaves out the slower modulation lines (shaft speed, FTF and their
    first harmonics), which a narrow load zone makes about as strong as the
    fault line itself (McFadden & Smith [1]_)."""
    fs_ = [freqs[k] for k in ("bpfo", "bpfi", "2bsf")]
    return (1.0 - margin) * min(fs_), (1.0 + margin) * max(fs_)


def envelope_signature(results, name="outer_fx", skip=0.1, band=None, **kw) -> dict:
    """Envelope analysis of a run's signal ``name`` without its first ``skip``
    seconds (the start-up transient).

    Returns a dict: ``freqs`` (:func:`run_defect_frequencies`), ``envelope``
    (:class:`EnvelopeSpectrum`, band from :func:`select_band` unless given;
    ``kw`` go to :func:`envelope_spectrum`), ``range`` (:func:`defect_range`),
    ``line`` (frequency, amplitude) of the strongest line in that range, and
    ``at`` the envelope amplitude at FTF, BPFO, BPFI and 2 BSF (largest value
    within 1 % of each).
    """
    t = results.signal_t
    x = results.signal(name)[t > skip]
    fs = 1.0 / float(np.median(np.diff(t)))
    freqs = run_defect_frequencies(results)
    es = envelope_spectrum(x, fs, band=band, **kw)
    rng = defect_range(freqs)
    return {"freqs": freqs, "envelope": es, "range": rng, "line": es.line(rng), "fs": fs,
            "at": {k: es.at(freqs[k]) for k in DEFECT_LINES}}


def defect_lines(freqs: dict, f_max, harmonics=3, sidebands=1):
    """Lines to mark on a spectrum: (label, frequency [Hz], kind, key) for
    FTF, BPFO, BPFI and 2 BSF (``key`` in ``DEFECT_LINES``) and their
    harmonics up to ``harmonics`` (kind "line", labels like ``2xBPFO``), and
    their sidebands (kind "sideband"): BPFI harmonics +- k times the shaft
    frequency (``fr``) and 2 BSF harmonics +- k FTF, k = 1..``sidebands``
    (the modulation of inner-race and ball impacts by the load zone they
    pass, McFadden & Smith [1]_); only lines below ``f_max``."""
    out = []
    for key, label in DEFECT_LINES.items():
        if key not in freqs:
            continue
        mod_key = {"bpfi": "shaft", "2bsf": "ftf"}.get(key)
        mod = freqs.get(mod_key) if mod_key else None
        for h in range(1, int(harmonics) + 1):
            fh = h * freqs[key]
            name = label.replace(" ", "") if h == 1 else f"{h}x{label.replace(' ', '')}"
            if fh <= f_max:
                out.append((name, fh, "line", key))
            if mod:
                for k in range(1, int(sidebands) + 1):
                    for sgn in (-1, 1):
                        fsb = fh + sgn * k * mod
                        if 0.0 < fsb <= f_max:
                            tag = f"{k if k > 1 else ''}{'fr' if key == 'bpfi' else 'FTF'}"
                            out.append((f"{name}{'-' if sgn < 0 else '+'}{tag}", fsb, "sideband", key))
    return out


_COLORS = {"ftf": "tab:gray", "bpfo": "tab:red", "bpfi": "tab:blue", "2bsf": "tab:green"}


def plot_defect_spectrum(panels, png, freqs: dict, f_max=None, harmonics=3, sidebands=1, title=None,
                         ylabel="amplitude"):
    """Spectra with the defect frequencies, harmonics (dashed) and sidebands
    (dotted) marked (:func:`defect_lines`).

    Parameters
    ----------
    panels : list of (label, f, amplitude)
        One axis per entry (e.g. the envelope spectra of several cases).
    png : path
        PNG to write; the CSV beside it holds every panel's (f, amplitude)
        up to ``f_max`` (columns ``f_<label>``, ``a_<label>``).
    freqs : dict
        Defect frequencies [Hz] (:func:`run_defect_frequencies`).
    f_max : float, optional
        Upper frequency of the plot (default 3.5 BPFI).

    Returns
    -------
    Path of the PNG.
    """
    from .plotting import _pyplot, save_figure

    plt = _pyplot()
    png = Path(png)
    png.parent.mkdir(parents=True, exist_ok=True)
    f_max = float(f_max or 3.5 * freqs["bpfi"])
    lines = defect_lines(freqs, f_max, harmonics, sidebands)
    fig, axes = plt.subplots(len(panels), 1, figsize=(10, 2.3 * len(panels) + 0.6), sharex=True, squeeze=False)
    columns = {}
    for ax, (label, f, amp) in zip(axes[:, 0], panels):
        f = np.asarray(f)
        amp = np.asarray(amp)
        sel = f <= f_max
        ax.plot(f[sel], amp[sel], lw=0.8, color="k")
        top = float(np.max(amp[sel])) if sel.any() else 1.0
        for name, fl, kind, key in lines:
            color = _COLORS[key]
            if kind == "line":
                ax.axvline(fl, color=color, lw=0.9, ls="--", alpha=0.8)
                ax.text(fl, top, name, rotation=90, fontsize=6, color=color, ha="right", va="top")
            else:
                ax.axvline(fl, color=color, lw=0.6, ls=":", alpha=0.6)
        ax.set_ylabel(ylabel)
        ax.set_title(label, fontsize=9, loc="left")
        ax.grid(alpha=0.3)
        key = "".join(c if c.isalnum() else "_" for c in label)
        columns[f"f_{key}"] = f[sel]
        columns[f"a_{key}"] = amp[sel]
    axes[-1, 0].set_xlabel("frequency [Hz] (dashed: FTF grey, BPFO red, BPFI blue, 2 BSF green and harmonics; "
                           "dotted: sidebands)")
    axes[-1, 0].set_xlim(0.0, f_max)
    if title:
        fig.suptitle(title, fontsize=10)
    return save_figure(fig, png, columns, trim=True)
