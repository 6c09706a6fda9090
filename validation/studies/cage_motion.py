"""Cage motion of the rigid cage in the reference engine (docs/theory/cage.md#cage-motion): the 6208 with its
estimated outer-land-guided brass cage, a horizontal shaft (gravity -y on the cage), the regularised ball /
race friction at 1 us (within its stable step; the point level's Cundall-Strack spring is not converged in the step), implicit cage
damping, --t-end long, summaries over the last quarter.

(a) Whirl at speed: F_r = 300 N at 1000 rad/s, balanced and with an unbalance U = 2e-5 kg m (the centrifugal
    force U omega_c^2 about 8 N): orbit size against the land clearance, whirl ratio, class.
(b) Pocket friction sweep: mu_c = 0 ... 0.5 at a high load and low speed (F_r = 3000 N, 100 rad/s) and at a
    low load and high speed (F_r = 300 N, 1000 rad/s): class, orbit, centre speed and the largest pocket
    force of each run, to see whether and where the cage's motion turns irregular as mu_c grows (the
    published trend: more readily at high load and low speed, where the balls slide less on the races).
(c) Gravity at low speed: where the cage rides (its offset against the land clearance) at 20 rad/s.
(e) Unequal pocket spacing: the 6208 under F_r = 3000 N at 500 rad/s with its estimated ball-guided cage
    (spherical pockets), equal pockets and a once-per-revolution spacing error of 0.4 of the pocket clearance
    (``RigidCage.pocket_spacing_error``), --t-end-spacing long at 2 us: the strongest lines of the cage centre's
    whirl spectrum over the last half (frequency over the cage speed; + in the cage's direction of rotation);
    with the inner ring turning at 500 rad/s and, the same settings otherwise, with the outer ring turning at
    500 rad/s and the inner ring at rest (``Scenario.omega_outer``; --spacing-rings chooses).
(f) The whirl line of an irregular orbit: the 6208 papers' radial case (F_r = 3000 N, the scene's defaults:
    its estimated outer-land cage, point traction with the Cundall-Strack spring, no gravity), --t-end-whirl long,
    at 300, 500 and 800 rad/s at 1 us and at 500 rad/s also at 2 and 0.5 us: the class, the orbit, the mean
    turning rate over the cage speed (``outputs.cage_summary.whirl``, what ``cage_whirl_ratio`` is for a
    circling orbit) and the strongest line of the whirl spectrum (``whirl_line``: frequency over the cage speed,
    its share of the orbit's power, the resolution), beside (omega - omega_c) / omega_c.
(d) High speed: Gupta's ACBB-120 at 25,000 rpm under 22,240 N thrust (its oil and EHL traction, the estimated
    outer-land brass cage, its default cage, 2 us, ellipse traction from the quasi-static start, --t-end-hs),
    balanced and with an unbalance U = 2e-6 kg m (U omega_c^2 about 2.8 N): orbit, whirl ratio, class, land loss.

    python validation/studies/cage_motion.py [--t-end 0.2] [--t-end-hs 0.06] [--t-end-spacing 1.2]
        [--t-end-whirl 0.6] [--only a b c d e f]
        [--spacing-rings inner outer] [--out validation/out/cage_motion]

Writes cage_motion.json, cage_motion_orbits.png and cage_motion_orbits.npz into --out.
"""
from __future__ import annotations

import argparse
import dataclasses
import json
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.data.cages import estimated_cage
from exudyn_bearing.model import layout as L
from exudyn_bearing.outputs.cage_summary import whirl, whirl_line
from exudyn_bearing.outputs.cage_summary import whirl_spectrum as cage_whirl_spectrum
from exudyn_bearing.outputs.plotting import pyplot, save_figure

ROOT = Path(__file__).resolve().parents[2]
KEYS = ("cage_speed", "cage_slip", "cage_motion", "cage_orbit_ratio", "cage_orbit_variation", "cage_centre_speed",
        "cage_whirl_ratio", "cage_whirl_line", "cage_whirl_line_share", "cage_whirl_resolution", "cage_offset", "land_eccentricity_max", "pocket_force_max", "cage_power_pocket",
        "cage_power_land", "energy_residual")


def s_keys(s):
    """The summary ``s``'s values of :data:`KEYS`."""
    return {k: s.get(k) for k in KEYS}


def run(fr, omega, t_end, mu=0.1, unbalance=0.0):
    b = eb.catalog["6208"]
    cage = dataclasses.replace(estimated_cage(b), pocket_friction=mu, unbalance=unbalance)
    sc = eb.Scenario(Fr=fr, omega=omega, t_end=t_end, dt=1e-6, sample_dt=2e-5, cage="rigid", rigid_cage=cage,
                     cage_damping="implicit", friction="regularized", gravity=(0.0, -9.81, 0.0))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        rec = eb.simulate(b, sc, progress=False)
        s = rec.summary(fraction=0.25)
    return {k: s.get(k) for k in KEYS}, rec


def run_high_speed(t_end, unbalance=0.0):
    """(d): the ACBB-120 at 25,000 rpm, 22,240 N thrust, its estimated outer-land cage with ``unbalance``."""
    b = eb.catalog["ACBB-120"]
    cage = dataclasses.replace(estimated_cage(b), unbalance=unbalance)
    sc = eb.Scenario(Fa=22240.0, omega=2618.0, t_end=t_end, dt=2e-6, sample_dt=2e-5, rigid_cage=cage,
                     traction_level="ellipse", traction="ehl_mil_l_23699_492K", n_strips=16, n_across=4,
                     initial="quasistatic", control="equilibrium", cage_damping="implicit")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        rec = eb.simulate(b, sc, lubricant="MIL-L-23699_492K", progress=False)
        s = rec.summary(fraction=0.25)
    return {k: s.get(k) for k in KEYS + ("steady",)}, rec


def whirl_spectrum(rec, cage_speed):
    """(f, a) of the cage centre's whirl over the last half of ``rec``
    (:func:`exudyn_bearing.outputs.cage_summary.whirl_spectrum`): angular frequency [rad/s], + in the cage's
    direction of rotation, and amplitude (Hann window; the resolution is 2 pi / the window's length)."""
    t = rec.data["t"]
    w = t >= 0.5 * t[-1]
    return cage_whirl_spectrum(t[w], rec.data["xc"][w, 0, :2], cage_speed)


#: Band of the faster whirls (:func:`faster_whirls`): above FASTER_FROM and up to FASTER_UPTO times the cage speed.
FASTER_FROM, FASTER_UPTO = 1.05, 4.0


def faster_whirls(rec, cage_speed):
    """The strongest line of the cage centre's whirl faster than the ball set, FASTER_FROM to FASTER_UPTO times the
    cage speed and more than 3 bins from the strongest line, in the cage's direction of rotation ("+") and
    against it ("-"): (frequency over the cage speed, amplitude over the strongest line of the spectrum) each.
    Nogi et al. 2018 (from its abstract): unequal pocket spacing adds a faster whirl, in the cage's direction
    for inner-ring rotation and against it for outer-ring rotation."""
    f, a = whirl_spectrum(rec, cage_speed)
    r = f / abs(cage_speed)
    # a line within 3 bins of the strongest is its window's skirt, not a whirl of its own (as in whirl_lines)
    apart = np.abs(f - f[int(np.argmax(a))]) > 3.0 * abs(f[1] - f[0])
    out = {}
    for sign, key in ((1.0, "+"), (-1.0, "-")):
        band = (sign * r > FASTER_FROM) & (sign * r <= FASTER_UPTO) & apart
        i = int(np.argmax(np.where(band, a, -1.0)))
        out[key] = (float(r[i]), float(a[i] / a.max()))
    return out


def whirl_lines(rec, cage_speed, n=5):
    """The ``n`` strongest lines of the cage centre's whirl over the last half of ``rec`` (:func:`whirl_spectrum`):
    (frequency over the cage speed, + in the cage's direction of rotation; amplitude over the strongest)."""
    f, a = whirl_spectrum(rec, cage_speed)
    picked = []
    for i in np.argsort(a)[::-1]:
        if all(abs(f[i] - f[k]) > 3.0 * abs(f[1] - f[0]) for k in picked):
            picked.append(int(i))
        if len(picked) == n:
            break
    return [(float(f[i] / abs(cage_speed)), float(a[i] / a[picked[0]])) for i in picked], \
        float(abs(f[1] - f[0]) / abs(cage_speed))


def run_spacing(t_end, error, ring="inner"):
    """(e): the 6208's ball-guided cage with a pocket spacing error ``error`` [m], the ``ring`` ("inner" or
    "outer") turning at 500 rad/s, the other at rest."""
    b = eb.catalog["6208"]
    cage = dataclasses.replace(estimated_cage(b, guidance="ball"), pocket_spacing_error=error)
    speeds = {"omega": 500.0} if ring == "inner" else {"omega": 0.0, "omega_outer": 500.0}
    sc = eb.Scenario(Fr=3000.0, **speeds, t_end=t_end, dt=2e-6, sample_dt=2e-5, rigid_cage=cage,
                     cage_damping="implicit", friction="regularized")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        warnings.simplefilter("ignore", eb.StepSizeWarning)
        rec = eb.simulate(b, sc, progress=False)
        s = rec.summary(fraction=0.5)
    return {k: s.get(k) for k in KEYS}, rec


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--t-end", type=float, default=0.2)
    ap.add_argument("--t-end-hs", type=float, default=0.06, help="run length of the high-speed runs (d) [s]")
    ap.add_argument("--t-end-spacing", type=float, default=1.2, help="run length of the spacing runs (e) [s]")
    ap.add_argument("--t-end-whirl", type=float, default=0.6, help="run length of the whirl-line runs (f) [s]")
    ap.add_argument("--only", nargs="+", choices=("a", "b", "c", "d", "e", "f"), default=["a", "b", "c", "d", "e", "f"])
    ap.add_argument("--spacing-rings", nargs="+", choices=("inner", "outer"), default=["inner", "outer"],
                    help="the turning ring of the spacing runs (e)")
    ap.add_argument("--out", default=str(ROOT / "validation" / "out" / "cage_motion"))
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    report, orbits = {"t_end_s": args.t_end, "dt_s": 1e-6}, {}

    if "a" in args.only:
        print("(a) whirl at 300 N, 1000 rad/s")
    for name, u in (("balanced", 0.0), ("unbalance_2e-5", 2e-5)) if "a" in args.only else ():
        s, rec = run(300.0, 1000.0, args.t_end, unbalance=u)
        report[f"a_{name}"] = s
        orbits[f"a_{name}"] = rec
        print(f"    {name:16s} {s['cage_motion']:9s} orbit/clearance {s['cage_orbit_ratio']:.3f} whirl ratio "
              f"{s['cage_whirl_ratio']} offset {np.round(np.array(s['cage_offset']) * 1e6, 1)} um")

    report["b_sweep"] = []
    if "b" in args.only:
        print("(b) pocket friction sweep")
    for fr, omega in ((3000.0, 100.0), (300.0, 1000.0)) if "b" in args.only else ():
        for mu in (0.0, 0.05, 0.1, 0.2, 0.3, 0.5):
            s, rec = run(fr, omega, args.t_end, mu=mu)
            report["b_sweep"].append({"Fr": fr, "omega": omega, "pocket_friction": mu, **s})
            if mu in (0.0, 0.5):
                orbits[f"b_{fr:g}N_{omega:g}_mu{mu:g}"] = rec
            print(f"    Fr {fr:6g} N omega {omega:6g} rad/s mu_c {mu:4.2f}: {s['cage_motion']:9s} orbit "
                  f"{s['cage_orbit_ratio']:.3f} variation {s['cage_orbit_variation']} centre speed "
                  f"{s['cage_centre_speed']:.3g} pocket max {s['pocket_force_max']:.3g} N energy "
                  f"{s['energy_residual']:.3g}", flush=True)

    if "c" in args.only:
        print("(c) gravity at 20 rad/s, 3000 N")
        s, rec = run(3000.0, 20.0, args.t_end)
        report["c_low_speed"] = s
        orbits["c_low_speed"] = rec
        print(f"    offset {np.round(np.array(s['cage_offset']) * 1e6, 1)} um, land clearance "
              f"{rec.model_parameters()[L.P_LAND_C] * 1e6:.0f} um, eccentricity max {s['land_eccentricity_max']:.3f}")

    for name, u in (("balanced", 0.0), ("unbalance_2e-6", 2e-6)) if "d" in args.only else ():
        if name == "balanced":
            print(f"(d) ACBB-120 at 25000 rpm, 22240 N thrust, {args.t_end_hs:g} s")
        s, rec = run_high_speed(args.t_end_hs, unbalance=u)
        report[f"d_{name}"] = s
        orbits[f"d_{name}"] = rec
        print(f"    {name:16s} {s['cage_motion']:9s} orbit/clearance {s['cage_orbit_ratio']:.3f} whirl ratio "
              f"{s['cage_whirl_ratio']} land eccentricity max {s['land_eccentricity_max']:.3f}, land loss "
              f"{s['cage_power_land']:.1f} W, pocket loss {s['cage_power_pocket']:.1f} W, cage "
              f"{s['cage_speed']:.1f} rad/s, steady {s['steady']['steady']}", flush=True)

    clearance = estimated_cage(eb.catalog["6208"], guidance="ball").pocket_clearance
    cases = [(ring, name, e) for ring in args.spacing_rings for name, e in (("equal", 0.0),
                                                                          ("unequal_0.4", 0.4 * clearance))]
    for ring, name, e in cases if "e" in args.only else ():
        if name == "equal":
            print(f"(e) 6208 ball-guided cage, 3000 N, {ring} ring at 500 rad/s, {args.t_end_spacing:g} s: pocket "
                  "spacing")
        s, rec = run_spacing(args.t_end_spacing, e, ring)
        lines, resolution = whirl_lines(rec, s["cage_speed"])
        faster = faster_whirls(rec, s["cage_speed"])
        key = f"e_{name}" if ring == "inner" else f"e_{name}_outer_ring"  # the inner ring's keys as before
        report[key] = {**s, "whirl_lines": lines, "resolution": resolution, "pocket_spacing_error": e,
                       "turning_ring": ring, "faster_whirls": faster}
        orbits[key] = rec
        print(f"    {name:12s} {s['cage_motion']:9s} orbit/clearance {s['cage_orbit_ratio']:.3f} pocket max "
              f"{s['pocket_force_max']:.1f} N; whirl lines (f / cage speed: amplitude, resolution "
              f"{resolution:.3f}): " + ", ".join(f"{fq:+.3f}: {amp:.2f}" for fq, amp in lines), flush=True)
        print(f"    {'':12s} strongest faster whirl ({FASTER_FROM:g}-{FASTER_UPTO:g} times the cage speed): "
              + ", ".join(f"{'with' if k == '+' else 'against'} the cage {fq:+.3f}: {amp:.3f}"
                          for k, (fq, amp) in faster.items()), flush=True)

    if "f" in args.only:
        print(f"(f) 6208 radial 3000 N, its estimated outer-land cage, the scene's defaults, {args.t_end_whirl:g} s, "
              "window the last quarter: mean turning rate against the whirl spectrum's strongest line")
        report["f_whirl_line"] = []
    for omega, dt in ((300.0, 1e-6), (500.0, 2e-6), (500.0, 1e-6), (500.0, 0.5e-6), (800.0, 1e-6)) \
            if "f" in args.only else ():
        sc = eb.Scenario(Fr=3000.0, omega=omega, t_end=args.t_end_whirl, dt=dt, sample_dt=2e-5, cage="rigid")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", eb.SteadyStateWarning)
            rec = eb.simulate("6208", sc, progress=False)
            s = rec.summary()
        w = rec.t >= s["window"]["t0"]
        cs = s["cage_speed"]
        rate = whirl(rec.t[w], rec.data["xc"][w, 0, :2], cs)[1]
        line, share, res = whirl_line(rec.t[w], rec.data["xc"][w, 0, :2], cs)
        report["f_whirl_line"].append({"omega": omega, "dt": dt, "mean_turning_ratio": rate, **s_keys(s)})
        print(f"    {omega:5g} rad/s {1e6 * dt:4g} us: cage {cs:6.1f} rad/s {s['cage_motion']:9s} orbit/clearance "
              f"{s['cage_orbit_ratio']:.3f}; mean turning rate {rate:+.3f}, line {line:+.3f} (share {share:.2f}, "
              f"resolution {res:.3f}); (omega - omega_c) / omega_c {(omega - cs) / cs:.3f}", flush=True)

    cols = max(1, min(4, len(orbits)))
    rows = max(1, -(-len(orbits) // cols))
    fig, axes = pyplot().subplots(rows, cols, figsize=(3.4 * cols, 3.6 * rows), squeeze=False)
    arrays = {}
    for ax, (name, rec) in zip(axes.ravel(), orbits.items()):
        xy = rec.data["xc"][:, 0, :2] * 1e6
        arrays[f"{name}_t"], arrays[f"{name}_xy_um"] = rec.data["t"], xy
        c = rec.model_parameters()[L.P_LAND_C] * 1e6
        th = np.linspace(0.0, 2.0 * np.pi, 200)
        ax.plot(c * np.cos(th), c * np.sin(th), "k--", lw=0.8)
        ax.plot(xy[:, 0], xy[:, 1], lw=0.5)
        ax.set_aspect("equal")
        ax.set_title(name, fontsize=9)
        ax.set_xlabel("x [um]")
        ax.set_ylabel("y [um]")
    save_figure(fig, out / "cage_motion_orbits.png")
    np.savez(out / "cage_motion_orbits.npz", **arrays)
    (out / "cage_motion.json").write_text(json.dumps(report, indent=1, default=float))
    print(f"wrote {out / 'cage_motion.json'}, cage_motion_orbits.png/.npz")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
