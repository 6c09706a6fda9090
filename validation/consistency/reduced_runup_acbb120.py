"""A run-up of the high-speed bearing in the reduced engine against the reference engine (docs/theory/reduced.md).

Gupta's ACBB-120 under F_a = 22,240 N thrust (cageless as its source, its catalogue lubricant and EHL traction,
the inner ring growing with speed, traction over the ellipse) run up from rest to 25,000 rpm (2618 rad/s) in
--ramp seconds, then held --hold seconds; the reference engine at 2 us, the reduced engine at each --dt (and,
with --tolerance, under its step control).

Printed:

* the cage speed (the balls' mean orbital speed) of each reduced run against the reference engine's at every
  sample from --from on (interpolated to the reference's sample times), against the criterion 2 %; the first
  cage revolution ends at the time printed (the criterion counts from there; --from is earlier);
* the skidding along the run-up in both engines at 25, 50, 75 and 100 % of the top speed: the mean
  |slide-to-roll ratio| of the loaded inner and outer contacts, and the cage slip 1 - cage speed / kinematic
  cage speed (at the sample's mean operating contact angle and ring speed, as the summaries'); along the ramp
  the tractions also accelerate the balls, so the trend check takes steady states: each engine at the four
  speeds from the race-control start (--steady-t-end), the mean inner |SRR| over the second half. Under a
  constant thrust, high-speed bearing tests see the balls skid more as the speed grows (NASA's 120-mm bearing
  tests); the trend, not the values, is the check;
* the wall time per simulated second of each run (the numba kernels loaded before, median of --repeats).

    python validation/consistency/reduced_runup_acbb120.py [--ramp 0.05] [--hold 0.02] [--dt 2e-5 5e-5]
        [--tolerance 1e-3] [--repeats 1] [--from 0.01]
"""
from __future__ import annotations

import argparse
import statistics
import warnings

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.model import layout as L
from exudyn_bearing.outputs.contact_summary import contact_summary

REFERENCE_DT = 2e-6
CRITERION = 0.02
#: Fractions of the top speed at which the skidding is read.
FRACTIONS = (0.25, 0.5, 0.75, 1.0)
TOP = 2618.0


def scene(ramp, hold, dt, tolerance=None):
    extra = {} if tolerance is None else {"tolerance": tolerance}
    return eb.Scenario(Fa=22240.0, omega=TOP, cage="none", traction_level="ellipse", ring_growth=True,
                       t_ramp_up=ramp, t_end=ramp + hold, sample_dt=5e-4, dt=dt,   # held at the top to the end
                       **extra)


def run(engine, sc, repeats):
    walls = []
    for _ in range(repeats):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            res = eb.simulate("ACBB-120", sc, engine=engine, progress=False)
        walls.append(res.wall_s / float(res.t[-1]))
    return res, statistics.median(walls)


def cage_slip(res, sc):
    """1 - cage speed / kinematic cage speed at each sample, the kinematic one at the sample's mean operating
    contact angle (the summaries' ``kinematic_cage_speed``, :func:`~exudyn_bearing.outputs.contact_summary.
    contact_summary` of that one sample); NaN below 5 % of the top speed. Also the ring speed of each sample."""
    b = eb.catalog["ACBB-120"]
    w = np.array([sc.omega_at(float(t)) for t in res.t])
    cage = res.cage_speed_series()
    slip = np.full(len(w), np.nan)
    for k in np.flatnonzero(w > 0.05 * TOP):
        kin = contact_summary(res.data, slice(k, k + 1), float(w[k]), b)["kinematic_cage_speed"]
        slip[k] = 1.0 - cage[k] / kin
    return slip, w


def srr_series(res, race):
    """The mean |slide-to-roll ratio| of the loaded contacts of ``race`` (0 inner, 1 outer) at each sample."""
    d = res.data["diag"]
    load, srr = d[:, :, race, L.D_LOAD], np.abs(d[:, :, race, L.D_SRR])
    n = np.sum(load > 0.0, axis=1)
    return np.where(n > 0, np.sum(np.where(load > 0.0, srr, 0.0), axis=1) / np.maximum(n, 1), np.nan)


def skidding_at(res, sc):
    """(cage slip, |SRR| inner, |SRR| outer) at the samples nearest FRACTIONS of the top speed (the last sample
    for the top)."""
    slip, w = cage_slip(res, sc)
    srr = (srr_series(res, 0), srr_series(res, 1))
    out = []
    for f in FRACTIONS:
        k = int(np.argmin(np.abs(w - f * TOP))) if f < 1.0 else len(w) - 1
        out.append((float(slip[k]), float(srr[0][k]), float(srr[1][k])))
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ramp", type=float, default=0.05)
    ap.add_argument("--hold", type=float, default=0.02)
    ap.add_argument("--dt", type=float, nargs="+", default=[2e-5, 5e-5])
    ap.add_argument("--tolerance", type=float, nargs="*", default=[],
                    help="the reduced engine's step-control tolerances to run as well (Scenario.tolerance)")
    ap.add_argument("--repeats", type=int, default=1)
    ap.add_argument("--steady-t-end", type=float, default=0.02, help="length of each steady run [s]")
    ap.add_argument("--from", dest="t_from", type=float, default=0.01, help="compare from this time on [s]")
    a = ap.parse_args(argv)
    # load the compiled kernels of both engines before any clock starts
    for engine, dt in (("reference", REFERENCE_DT), ("reduced", a.dt[0])):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            eb.simulate("ACBB-120", scene(1e-3, 0.0, dt), engine=engine, progress=False)
    runs = {}
    sc_ref = scene(a.ramp, a.hold, REFERENCE_DT)
    runs["reference, 2 us"] = (*run("reference", sc_ref, a.repeats), sc_ref)
    for dt in a.dt:
        sc = scene(a.ramp, a.hold, dt)
        runs[f"reduced, {dt * 1e6:g} us"] = (*run("reduced", sc, a.repeats), sc)
    for tol in a.tolerance:
        sc = scene(a.ramp, a.hold, a.dt[0], tol)
        runs[f"reduced, tolerance {tol:g}"] = (*run("reduced", sc, a.repeats), sc)
    ref, ref_wall, _ = runs["reference, 2 us"]
    t = ref.t
    angle = np.concatenate([[0.0], np.cumsum(0.5 * (ref.cage_speed_series()[1:] + ref.cage_speed_series()[:-1])
                                             * np.diff(t))])
    first_rev = float(np.interp(2.0 * np.pi, angle, t)) if angle[-1] >= 2.0 * np.pi else float("nan")
    print(f"ACBB-120, F_a = 22,240 N, 0 -> 25,000 rpm in {a.ramp * 1e3:g} ms, held {a.hold * 1e3:g} ms, ellipse "
          f"traction, no cage. The cage's first revolution ends at {first_rev * 1e3:.1f} ms (reference engine).")
    print(f"\ncage speed against the reference engine from {a.t_from * 1e3:g} ms on (criterion "
          f"{100 * CRITERION:g} %), and the cost:")
    late = t >= a.t_from
    failed = []
    for name, (res, wall, sc) in runs.items():
        steps = getattr(res, "steps", None)
        if name.startswith("reference"):
            print(f"  {name:26s} wall per simulated s {wall:.3g}")
            continue
        rel = (np.interp(t, res.t, res.cage_speed_series()) - ref.cage_speed_series()) / ref.cage_speed_series()
        worst = float(np.max(np.abs(rel[late])))
        k = int(np.argmax(np.abs(rel) * late))
        ok = worst <= CRITERION
        if not ok:
            failed.append(name)
        print(f"  {name:26s} largest |difference| {100 * worst:.3f} % at {t[k] * 1e3:.1f} ms "
              f"({'ok' if ok else 'FAILS'}); wall per simulated s {wall:.3g} (reference / this {ref_wall / wall:.3g})"
              + (f"; steps {steps}" if steps else ""))
    print("\nalong the run-up at " + ", ".join(f"{100 * f:g} %" for f in FRACTIONS) + " of the top speed: the mean "
          "|slide-to-roll ratio| of the loaded inner and outer contacts (the balls' sliding on the races), and "
          "the cage slip 1 - cage speed / kinematic cage speed (information: at high speed the inner and outer "
          "contact angles part, and pure rolling at their mean is no longer the balls' rolling speed):")
    for name, (res, _, sc) in runs.items():
        s = skidding_at(res, sc)
        print(f"  {name:26s} |SRR| inner " + "  ".join(f"{x[1]:.4f}" for x in s)
              + ";  outer " + "  ".join(f"{x[2]:.4f}" for x in s)
              + ";  cage slip " + "  ".join(f"{100 * x[0]:.2f} %" for x in s))
    print("  (along the ramp the tractions also accelerate the balls: the sliding there is the run-up's, not the "
          "steady skidding; the trend check below takes steady states)")
    print(f"\nsteady skidding at {', '.join(f'{100 * f:g} %' for f in FRACTIONS)} of the top speed (each from the "
          f"race-control start, --steady-t-end long, the mean |SRR| of the loaded inner contacts over its second "
          f"half):")
    trends = {}
    for engine, dt in [("reference", REFERENCE_DT), ("reduced", a.dt[-1])]:
        inner = []
        for f in FRACTIONS:
            sc = eb.Scenario(Fa=22240.0, omega=f * TOP, cage="none", traction_level="ellipse", ring_growth=True,
                             initial="quasistatic", control="outer", t_end=a.steady_t_end, sample_dt=5e-4, dt=dt)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                res = eb.simulate("ACBB-120", sc, engine=engine, progress=False)
            inner.append(float(np.nanmean(srr_series(res, 0)[len(res.t) // 2:])))
        name = f"{engine}, {dt * 1e6:g} us"
        trends[name] = all(y > x for x, y in zip(inner, inner[1:]))
        print(f"  {name:26s} " + "  ".join(f"{x:.5f}" for x in inner)
              + f"   ({'grows with speed' if trends[name] else 'does NOT grow at every step'})")
    print("\nchecks: " + ("all pass" if not failed and all(trends.values()) else
                          "FAIL: " + ", ".join(failed + [n + " skidding trend" for n, ok in trends.items() if not ok])))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
