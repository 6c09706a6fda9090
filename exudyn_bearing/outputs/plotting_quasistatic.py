"""Figures of the quasi-static solver (matplotlib, Agg), each a PNG with its CSV beside it."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from .plotting import _pyplot, label_azimuth_axes, save_figure

__all__ = ["plot_loads_angles", "plot_slip", "plot_dissipation_beta", "plot_orbit_march"]


def _azimuth_deg(psi):
    d = (np.degrees(np.asarray(psi, float)) + 180.0) % 360.0 - 180.0
    return d, np.argsort(d)


def _two_panels(png):
    """A figure of two panels side by side, and the PNG path with its folder made."""
    png = Path(png)
    png.parent.mkdir(parents=True, exist_ok=True)
    fig, ax = _pyplot().subplots(1, 2, figsize=(11.5, 4.3))
    return fig, ax, png


def _as_dicts(solutions: dict):
    """(label, dict) pairs of QuasiStaticSolutions or their ``to_dict()``."""
    return [(label, s.to_dict() if hasattr(s, "to_dict") else s) for label, s in solutions.items()]


def plot_loads_angles(solutions: dict, png) -> Path:
    """Contact loads and contact angles of both races against azimuth, one line style per solution.

    ``solutions`` maps a label to a QuasiStaticSolution (or its ``to_dict()``).
    """
    fig, ax, png = _two_panels(png)
    cols = {}
    for i, (label, d) in enumerate(_as_dicts(solutions)):
        az, order = _azimuth_deg(np.radians(d["psi"]))
        for race, ls in (("inner", "-o"), ("outer", "--s")):
            ax[0].plot(az[order], np.asarray(d[f"q_{race}"])[order], ls, color=f"C{i}", ms=4, label=f"{label}: {race}")
            ax[1].plot(az[order], np.asarray(d[f"alpha_{race}"])[order], ls, color=f"C{i}", ms=4,
                       label=f"{label}: {race}")
            key = label.replace(" ", "_")
            cols[f"{key}_q_{race}_N"] = np.asarray(d[f"q_{race}"])[order]
            cols[f"{key}_alpha_{race}_deg"] = np.asarray(d[f"alpha_{race}"])[order]
        cols[f"{label.replace(' ', '_')}_psi_deg"] = az[order]
    label_azimuth_axes(ax, ("contact load Q [N]", "contact angle alpha [deg]"), legend_fontsize=7)
    return save_figure(fig, png, cols, trim=True)


def plot_slip(solutions: dict, png, ball=0) -> Path:
    """Rolling-direction slip along the major axis of both contacts of one ball, per solution."""
    fig, ax, png = _two_panels(png)
    cols = {}
    for i, (label, d) in enumerate(_as_dicts(solutions)):
        y = np.asarray(d["slip_y"])
        for k, race in enumerate(("outer", "inner")):
            v = np.asarray(d[f"slip_{race}"])[ball]
            ax[k].plot(y, v, "-", color=f"C{i}", label=f"{label} (beta {np.asarray(d['beta'])[ball]:.2f} deg)")
            cols[f"{label.replace(' ', '_')}_slip_{race}_m_s"] = v
        cols["y_over_a"] = y
    for k, race in enumerate(("outer", "inner")):
        ax[k].axhline(0.0, color="k", lw=0.8)
        ax[k].set_xlabel("y / a along the major axis [-]")
        ax[k].set_ylabel("slip of the ball against the race [m/s]")
        ax[k].set_title(f"{race} contact, ball {ball}")
        ax[k].grid(alpha=0.3)
        ax[k].legend(fontsize=7)
    return save_figure(fig, png, cols)


def plot_dissipation_beta(beta_deg, dissipation, points: dict, png, title="") -> Path:
    """Least dissipation against the spin-axis angle beta, with marked solution points.

    ``points`` maps a label to (beta [deg], dissipation [W]).
    """
    plt = _pyplot()
    png = Path(png)
    png.parent.mkdir(parents=True, exist_ok=True)
    fig, ax = plt.subplots(figsize=(6.5, 4.3))
    ax.plot(beta_deg, dissipation, "-", color="C0", label="least dissipation at fixed beta")
    for i, (label, (bb, q)) in enumerate(points.items()):
        ax.plot([bb], [q], "o^sD"[i % 4], color=f"C{i + 1}", ms=8, label=f"{label}: {q:.4g} W at {bb:.2f} deg")
    ax.set_xlabel("spin-axis angle beta [deg]")
    ax.set_ylabel("dissipation of one ball, both contacts [W]")
    ax.set_title(title, fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    return save_figure(fig, png, {"beta_deg": beta_deg, "dissipation_W": dissipation})


def plot_orbit_march(march: dict, png, points: dict | None = None) -> Path:
    """The orbit march's ball along its last revolution (``march``, a result of
    :func:`~exudyn_bearing.solvers.quasistatic.orbit.march_orbit`): left its contacts' dissipation per ball [W]
    against azimuth, with ``points`` (label ->
    (azimuths [deg], dissipation per ball [W]): the quasi-static solution's balls, another engine's azimuth
    bins); right its pocket force [N] and its place in the pocket's play."""
    fig, ax, png = _two_panels(png)
    p = march["profile"]
    az, order = _azimuth_deg(p["psi"])
    ax[0].plot(az[order], np.asarray(p["dissipation"])[order], "-", color="C0", label="orbit march")
    cols = {"psi_deg": az[order], "march_dissipation_W": np.asarray(p["dissipation"])[order],
            "march_pocket_force_N": np.asarray(p["pocket_force"])[order],
            "march_pocket_offset_um": 1e6 * np.asarray(p["pocket_offset"])[order],
            "march_orbital_speed_rad_s": np.asarray(p["omega_m"])[order]}
    for i, (label, (deg, values)) in enumerate((points or {}).items()):
        d = (np.asarray(deg, float) + 180.0) % 360.0 - 180.0
        o = np.argsort(d)
        ax[0].plot(d[o], np.asarray(values, float)[o], "os"[i % 2] + "--", color=f"C{i + 1}", ms=4, label=label)
    ax[1].plot(az[order], np.asarray(p["pocket_force"])[order], "-", color="C0",
               label="pocket force [N] (+: pushes the ball forward; spikes: an impact's impulse over one step)")
    ax[1].plot(az[order], 1e4 * np.asarray(p["pocket_offset"])[order], "--", color="C3",
               label="place in the play [100 um] (+: ahead of the pocket's centre)")
    label_azimuth_axes(ax, ("contacts' dissipation per ball [W]", "pocket force [N], place in the play [100 um]"),
                       legend_fontsize=7)
    ax[0].set_title(f"cage speed {march['cage_speed']:.5g} rad/s, dissipation {march['dissipation']:.4g} W "
                    "(the march's last revolution)", fontsize=8)
    return save_figure(fig, png, cols, trim=True)
