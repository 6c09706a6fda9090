"""Figures (matplotlib, Agg backend), each saved as PNG next to a CSV of its data."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

__all__ = ["plot_static", "plot_run", "plot_speeds", "plot_srr", "plot_film_by_phase",
           "plot_quasi_static", "save_csv", "save_figure", "pyplot", "loaded_ball_mask", "label_regime_lines"]


def pyplot():
    """``matplotlib.pyplot`` on the non-interactive Agg backend (figures are
    written to files; no display needed). Scripts draw their own figures with
    it and save them with :func:`save_figure`."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


_pyplot = pyplot  # the name used inside this module


def save_csv(path, columns: dict) -> Path:
    """Write equal-length 1-D columns to a CSV with a header line."""
    path = Path(path)
    names = list(columns)
    data = np.column_stack([np.asarray(columns[n], float) for n in names])
    np.savetxt(path, data, delimiter=",", header=",".join(names), comments="", fmt="%.10g")
    return path


def save_figure(fig, png, columns: dict | None = None, dpi=110, layout=True, trim=False) -> Path:
    """Save ``fig`` as ``png`` (tight layout unless ``layout`` is False), close
    it, and write ``columns`` (if given) to the CSV beside it; ``trim`` cuts
    the columns to the shortest one first."""
    png = Path(png)
    if layout:
        fig.tight_layout()
    fig.savefig(png, dpi=dpi)
    _pyplot().close(fig)
    if columns is not None:
        if trim:
            n = min(len(v) for v in columns.values())
            columns = {k: v[:n] for k, v in columns.items()}
        save_csv(png.with_suffix(".csv"), columns)
    return png


def label_azimuth_axes(ax, ylabels, legend_fontsize=8, legend_axes=None):
    """A row of plots against the azimuth: x label, grid, the ``ylabels``,
    legends on ``legend_axes`` (default all)."""
    for a, label in zip(ax, ylabels):
        a.set_xlabel("azimuth psi [deg]")
        a.set_ylabel(label)
        a.grid(alpha=0.3)
    for a in (ax if legend_axes is None else legend_axes):
        a.legend(fontsize=legend_fontsize)


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
    from ..physics.load_distribution import stribeck_load

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
    return png, save_figure(fig, png, cols, dpi=120).with_suffix(".csv")


def loaded_ball_mask(run) -> np.ndarray:
    """(n, Z) True where a ball carries load at both races (it is in the loaded
    zone); False for balls held by the centrifugal force alone or out of contact."""
    return (run.contact("load", "inner") > 0.0) & (run.contact("load", "outer") > 0.0)


def label_regime_lines(ax, x=178.0, fontsize=8, ha="right"):
    """Dashed lines at Lambda = 1 and 3 with the regimes they separate, text ending at ``x``."""
    for y, text in ((1.0, "boundary | mixed"), (3.0, "mixed | full film")):
        ax.axhline(y, color="k", lw=0.7, ls="--")
        ax.text(x, y, text, va="bottom", ha=ha, fontsize=fontsize)


def _legend_above(ax, ncol=2):
    """A legend in the band above the axes, where it covers no data."""
    ax.legend(fontsize=8, loc="lower left", bbox_to_anchor=(0.0, 1.01), ncol=ncol, frameon=False,
              borderaxespad=0.0, handlelength=1.8)


def plot_run(run, png) -> Path:
    """Overview of a simulation: speeds, largest ball loads, Lambda and h_min
    of the outer contacts of the balls in the loaded zone against azimuth
    (coloured by time; balls held by the centrifugal force alone are left
    out). Writes the PNG and a CSV of the time series beside it; returns the
    PNG path."""
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
    fig, ax = plt.subplots(2, 2, figsize=(12, 8.6))
    fig.subplots_adjust(left=0.07, right=0.9, top=0.88, bottom=0.07, hspace=0.42, wspace=0.22)
    a = ax[0, 0]
    a.plot(t, omega, label="inner ring omega")
    a.plot(t, spin, label="ball |omega| (mean)")
    a.plot(t, cage, label="cage speed")
    if s.omega > 0 or s.omega_outer != 0:
        from ..physics import kinematics

        a.axhline(float(kinematics.ball_spin_absolute(s.omega, s.omega_outer, b.ball_radius, b.pitch_radius,
                                                      b.free_contact_angle)),
                  color="k", ls=":", lw=0.8, label="kinematic ball spin")
    a.set_xlabel("t [s]")
    a.set_ylabel("angular speed [rad/s]")
    _legend_above(a)
    a.grid(alpha=0.3)
    a = ax[0, 1]
    a.plot(t, q_in, label="largest inner ball load")
    a.plot(t, q_out, label="largest outer ball load")
    a.set_xlabel("t [s]")
    a.set_ylabel("ball load [N]")
    _legend_above(a)
    a.grid(alpha=0.3)
    psi = np.degrees(run.azimuth())
    tt = np.broadcast_to(t[:, None], psi.shape)
    loaded = loaded_ball_mask(run)
    for a, name, label in ((ax[1, 0], "lambda", "film parameter Lambda, outer contact [-]"),
                           (ax[1, 1], "h_min", "h_min, outer contact [um]")):
        y = run.contact(name, "outer") * (1e6 if name == "h_min" else 1.0)
        sc = a.scatter(psi[loaded], y[loaded], c=tt[loaded], s=4, cmap="viridis", vmin=t[0], vmax=t[-1])
        a.set_xlabel("azimuth psi [deg]")
        a.set_ylabel(label)
        a.set_xlim(-180, 180)
        a.grid(alpha=0.3)
        a.set_title("balls in the loaded zone (outside: centrifugal load only, omitted)", fontsize=8, loc="left")
        if not loaded.any():
            a.text(0.5, 0.5, "no ball carries load at both races", transform=a.transAxes, ha="center")
    label_regime_lines(ax[1, 0])
    cax = fig.add_axes([0.92, 0.07, 0.015, 0.33])
    fig.colorbar(sc, cax=cax, label="t [s]")
    outer = s.omega_outer
    fig.suptitle(f"{b.name}: Fr = {s.Fr:g} N, Fa = {s.Fa:g} N, omega = {s.omega:g} rad/s"
                 + (f", omega_outer = {outer:g} rad/s" if outer else "")
                 + f", {run.engine} engine, {s.integrator}, dt = {s.dt:g} s")
    columns = {"t_s": t, "omega_rad_s": omega}
    if outer:  # the outer ring's speed beside the inner's when it turns
        columns["omega_outer_rad_s"] = np.array([s.omega_outer_at(x) for x in t])
    save_figure(fig, png, {**columns, "cage_speed_rad_s": cage, "ball_spin_mean_rad_s": spin,
                           "q_max_inner_N": q_in, "q_max_outer_N": q_out}, layout=False)
    return png


def _phases(run):
    """Protocol phase of every sample: 0 start-up, 1 steady, 2 slow-down, 3 rest."""
    s = run.scenario
    t = run.t
    t1 = s.t_ramp_up
    t2 = t1 + s.t_steady
    t3 = t2 + s.t_ramp_down
    return np.where(t < t1, 0, np.where(t < t2, 1, np.where(t < t3, 2, 3)))


PHASE_NAMES = ("start-up", "steady", "slow-down", "rest")


def plot_speeds(run, png, ball=0) -> Path:
    """Shaft and ball angular speed against time with the kinematic ball-spin
    line (docs/theory/reference_cases.md, 952.38 rad/s at 500 rad/s), and the cage speed."""
    from ..physics import kinematics

    plt = _pyplot()
    png = Path(png)
    png.parent.mkdir(parents=True, exist_ok=True)
    b, s = run.bearing, run.scenario
    t = run.t
    spin = run.ball_spin_series()
    omega = run.global_series("omega")
    cage = run.cage_speed_series()
    w_kin = float(kinematics.ball_spin_absolute(s.omega, s.omega_outer, b.ball_radius, b.pitch_radius,
                                                b.free_contact_angle))
    fig, ax = plt.subplots(figsize=(7, 4.2))
    ax.plot(t, omega, label="shaft (inner ring)")
    ax.plot(t, spin[:, ball], label=f"ball {ball} |omega|")
    ax.plot(t, spin.mean(axis=1), lw=0.8, label="ball |omega|, mean of all balls")
    ax.plot(t, cage, label="cage")
    ax.axhline(w_kin, color="k", ls=":", lw=0.8, label=f"kinematic ball spin {w_kin:.2f} rad/s")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("angular speed [rad/s]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"{b.name}: Fr = {s.Fr:g} N, {run.engine} engine")
    save_figure(fig, png, {"t_s": t, "omega_rad_s": omega, f"ball{ball}_spin_rad_s": spin[:, ball],
                           "ball_spin_mean_rad_s": spin.mean(axis=1), "cage_rad_s": cage}, dpi=120)
    return png


def plot_srr(run, png, ball=0) -> Path:
    """Slide-to-roll ratio of one ball at its inner and outer contact against time."""
    plt = _pyplot()
    png = Path(png)
    png.parent.mkdir(parents=True, exist_ok=True)
    t = run.t
    cols = {"t_s": t}
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for race in ("inner", "outer"):
        srr = run.contact("srr", race)[:, ball].copy()
        srr[run.contact("load", race)[:, ball] <= 0.0] = np.nan
        ax.semilogy(t, srr, ".", ms=2, label=f"{race} contact")
        cols[f"srr_{race}"] = srr
    ax.set_xlabel("t [s]")
    ax.set_ylabel(f"slide-to-roll ratio of ball {ball} [-]")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    save_figure(fig, png, cols, dpi=120)
    return png


def plot_film_by_phase(run, png, race="outer") -> Path:
    """h_min and Lambda of one race against azimuth, coloured by protocol phase."""
    plt = _pyplot()
    png = Path(png)
    png.parent.mkdir(parents=True, exist_ok=True)
    phase = np.broadcast_to(_phases(run)[:, None], run.azimuth().shape)
    psi = np.degrees(run.azimuth())
    loaded = loaded_ball_mask(run)
    h = np.where(loaded, run.contact("h_min", race) * 1e6, np.nan)
    lam = np.where(loaded, run.contact("lambda", race), np.nan)
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for code, name in enumerate(PHASE_NAMES[:3]):
        sel = (phase == code) & loaded
        if sel.any():
            ax[0].plot(psi[sel], h[sel], ".", ms=2, label=name)
            ax[1].plot(psi[sel], lam[sel], ".", ms=2, label=name)
    label_regime_lines(ax[1])
    fig.suptitle("balls in the loaded zone (balls under centrifugal load only omitted)", fontsize=9)
    ax[0].set_ylabel(f"h_min {race} [um]")
    ax[1].set_ylabel(f"Lambda {race} [-]")
    for a in ax:
        a.set_xlabel("azimuth psi [deg]")
        a.set_xlim(-180, 180)
        a.grid(alpha=0.3)
        a.legend(fontsize=8, markerscale=4)
    save_figure(fig, png, {"psi_deg": psi.ravel(), "phase": phase.ravel(),
                           "h_min_um": h.ravel(), "lambda": lam.ravel()}, dpi=120)
    return png


def plot_quasi_static(run, png) -> Path:
    """Q(psi) and delta(psi) of the last sample against the discrete analytic solution."""
    from ..physics.load_distribution import static_equilibrium

    plt = _pyplot()
    png = Path(png)
    png.parent.mkdir(parents=True, exist_ok=True)
    psi = run.azimuth()[-1]
    st = static_equilibrium(run.bearing, run.scenario.Fr, run.scenario.Fa, phase=float(psi[0]),
                            hertz_method=run.scenario.hertz)
    q_in = run.contact("load", "inner")[-1]
    q_out = run.contact("load", "outer")[-1]
    delta = run.contact("overlap", "inner")[-1] + run.contact("overlap", "outer")[-1]
    order = np.argsort(psi)
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    d = np.degrees(psi)
    ax[0].plot(d[order], st.q[order], "k-", label="analytic (discrete)")
    ax[0].plot(d[order], q_in[order], "o", mfc="none", label=f"{run.engine}: inner")
    ax[0].plot(d[order], q_out[order], "x", label=f"{run.engine}: outer")
    ax[1].plot(d[order], st.overlap[order] * 1e6, "k-", label="analytic")
    ax[1].plot(d[order], delta[order] * 1e6, "o", mfc="none", label=run.engine)
    label_azimuth_axes(ax, ("ball load Q [N]", "total overlap delta [um]"))
    fig.suptitle(f"{run.bearing.name}: Fr = {run.scenario.Fr:g} N, Pd = "
                 f"{run.bearing.diametral_clearance * 1e6:.1f} um, omega = {run.scenario.omega:g} rad/s")
    save_figure(fig, png, {"psi_rad": psi, "q_analytic_N": st.q, "q_inner_N": q_in, "q_outer_N": q_out,
                           "delta_analytic_m": st.overlap, "delta_m": delta}, dpi=120)
    return png
