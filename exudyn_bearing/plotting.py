"""Figures (matplotlib, Agg backend), each saved as PNG next to a CSV of its data."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

__all__ = ["plot_static", "save_csv"]


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def save_csv(path, columns: dict) -> Path:
    """Write equal-length 1-D columns to a CSV with a header line."""
    path = Path(path)
    names = list(columns)
    data = np.column_stack([np.asarray(columns[n], float) for n in names])
    np.savetxt(path, data, delimiter=",", header=",".join(names), comments="", fmt="%.10g")
    return path


def plot_static(res: dict, png) -> tuple[Path, Path]:
    """Q(psi) (and with a speed, Lambda(psi) of both races) of a static analysis.

    Parameters
    ----------
    res : dict
        Output of :func:`exudyn_bearing.analysis.static_analysis`.
    png : path
        PNG file to write; the CSV goes beside it with the same stem.

    Returns
    -------
    (png_path, csv_path)
    """
    from .physics.load_distribution import stribeck_load

    plt = _pyplot()
    png = Path(png)
    png.parent.mkdir(parents=True, exist_ok=True)
    psi = np.asarray(res["psi"], float)
    psi_deg = np.degrees((psi + math.pi) % (2.0 * math.pi) - math.pi)
    order = np.argsort(psi_deg)
    has_film = "lambda_outer" in res
    fig, axes = plt.subplots(1, 2 if has_film else 1, figsize=(11 if has_film else 6, 4.2), squeeze=False)
    ax = axes[0, 0]
    grid = np.linspace(-180.0, 180.0, 721)
    ax.plot(psi_deg[order], np.asarray(res["q"])[order], "o", color="C0", label="discrete balls (exact geometry)")
    if math.isfinite(res.get("eps", math.nan)) and res["q_max"] > 0 and res.get("Fa", 0.0) == 0.0:
        ax.plot(grid, stribeck_load(np.radians(grid), res["q_max"], res["eps"]), "-", color="C0", alpha=0.5,
                label=f"Stribeck law, eps = {res['eps']:.3f}")
    ax.set_xlabel("azimuth psi [deg] (0 = load direction)")
    ax.set_ylabel("ball load Q [N]")
    ax.set_title(f"{res['bearing']}: Fr = {res['Fr']:g} N, Fa = {res['Fa']:g} N, "
                 f"Pd = {res['Pd'] * 1e6:.1f} um")
    ax.set_xlim(-180, 180)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    cols = {"psi_rad": psi, "q_N": res["q"], "overlap_m": res["overlap"],
            "contact_angle_rad": res["contact_angle"]}
    if has_film:
        ax2 = axes[0, 1]
        for race, color in (("inner", "C1"), ("outer", "C2")):
            lam = np.asarray(res[f"lambda_{race}"], float)
            ax2.plot(psi_deg[order], lam[order], "s-", color=color, label=f"Lambda {race}")
            cols[f"h_min_{race}_m"] = res[f"h_min_{race}"]
            cols[f"lambda_{race}"] = lam
        for y, text in ((1.0, "boundary | mixed"), (3.0, "mixed | full film")):
            ax2.axhline(y, color="k", lw=0.8, ls="--")
            ax2.text(-175, y, text, va="bottom", fontsize=8)
        ax2.set_xlabel("azimuth psi [deg]")
        ax2.set_ylabel("film parameter Lambda [-]")
        ax2.set_title(f"omega = {res['omega']:g} rad/s, film {res['film']} (unloaded contacts omitted)")
        ax2.set_xlim(-180, 180)
        ax2.grid(True, alpha=0.3)
        ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    plt.close(fig)
    csv = save_csv(png.with_suffix(".csv"), cols)
    return png, csv


def plot_run(run, png) -> Path:
    """Overview of a simulation: speeds, largest ball loads, Lambda and h_min
    against azimuth (coloured by time). Writes the PNG and a CSV of the time
    series beside it; returns the PNG path."""
    plt = _pyplot()
    png = Path(png)
    png.parent.mkdir(parents=True, exist_ok=True)
    t = run.t
    s = run.scenario
    b = run.bearing
    omega = run.global_series("omega")
    cage = run.cage_speed_series()
    spin = run.ball_spin_series().mean(axis=1)
    q_in = run.contact("load", "inner").max(axis=1)
    q_out = run.contact("load", "outer").max(axis=1)
    fig, ax = plt.subplots(2, 2, figsize=(12, 8))
    a = ax[0, 0]
    a.plot(t, omega, label="inner ring omega")
    a.plot(t, spin, label="ball |omega| (mean)")
    a.plot(t, cage, label="cage speed")
    if s.omega > 0:
        from .physics import kinematics

        a.axhline(float(kinematics.ball_spin_absolute(s.omega, 0.0, b.ball_radius, b.pitch_radius,
                                                      b.free_contact_angle)),
                  color="k", ls=":", lw=0.8, label="kinematic ball spin")
    a.set_xlabel("t [s]")
    a.set_ylabel("angular speed [rad/s]")
    a.legend(fontsize=8)
    a.grid(alpha=0.3)
    a = ax[0, 1]
    a.plot(t, q_in, label="max inner load")
    a.plot(t, q_out, label="max outer load")
    a.set_xlabel("t [s]")
    a.set_ylabel("ball load [N]")
    a.legend(fontsize=8)
    a.grid(alpha=0.3)
    psi = np.degrees(run.azimuth())
    tt = np.broadcast_to(t[:, None], psi.shape)
    for a, name, label in ((ax[1, 0], "lambda", "film parameter Lambda (outer)"),
                           (ax[1, 1], "h_min", "h_min outer [um]")):
        y = run.contact(name, "outer") * (1e6 if name == "h_min" else 1.0)
        sc = a.scatter(psi.ravel(), y.ravel(), c=tt.ravel(), s=4, cmap="viridis")
        a.set_xlabel("azimuth psi [deg]")
        a.set_ylabel(label)
        a.set_xlim(-180, 180)
        a.grid(alpha=0.3)
    if name == "h_min":
        fig.colorbar(sc, ax=ax[1, :], label="t [s]")
    ax[1, 0].axhline(1.0, color="k", lw=0.7, ls="--")
    ax[1, 0].axhline(3.0, color="k", lw=0.7, ls="--")
    fig.suptitle(f"{b.name}: Fr = {s.Fr:g} N, Fa = {s.Fa:g} N, omega = {s.omega:g} rad/s, "
                 f"{run.engine} engine, {s.integrator}, dt = {s.dt:g} s")
    fig.savefig(png, dpi=110)
    plt.close(fig)
    save_csv(png.with_suffix(".csv"), {"t_s": t, "omega_rad_s": omega, "cage_speed_rad_s": cage,
                                       "ball_spin_mean_rad_s": spin, "q_max_inner_N": q_in,
                                       "q_max_outer_N": q_out})
    return png
