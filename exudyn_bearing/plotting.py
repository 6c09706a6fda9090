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
