"""The energy balance in a transient with and without the elastic energy stored in the contacts
(docs/theory/dynamics.md, "Losses and the energy balance").

The 6208 under 3000 N radial load at 500 rad/s, started from the analytic state (the balls not yet
rolling), is run by the reference engine for 4 ms at dt = 2, 1, 0.5 and 0.25 us; the summary window is
the last quarter (3-4 ms), where the balls still settle and the contacts' overlaps change. Printed per
step [W]: the drive power, the dissipation, the kinetic energy's rate, the stored energy's rate
(``contact_energy_change`` over the window length) and the balance's error
drive - dissipation - dKE/T - dE/T with and without the stored energy's term. A term the balance needs
shows as an error that stays as the step falls when it is left out, and one that falls with the step
when it is counted.

    python validation/studies/energy_stored.py [--t-end 0.004] [--dt 2e-6 1e-6 5e-7 2.5e-7]

About a minute on the 2-core machine.
"""
from __future__ import annotations

import argparse
import warnings

import exudyn_bearing as eb


def run(dt: float, t_end: float) -> dict:
    sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=t_end, dt=dt, sample_dt=2e-5)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # a settling window: not steady, and its check is not judged
        return eb.simulate("6208", sc, progress=False).summary()


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--t-end", type=float, default=0.004, help="simulated time [s]")
    p.add_argument("--dt", type=float, nargs="+", default=[2e-6, 1e-6, 5e-7, 2.5e-7], help="steps [s]")
    args = p.parse_args(argv)
    print(f"6208, 3000 N, 500 rad/s from the analytic start, reference engine, {1e3 * args.t_end:g} ms; "
          "window: the last quarter; powers in W")
    print(f"{'dt [us]':>8} {'drive':>10} {'dissipation':>12} {'dKE/T':>10} {'dE/T':>10} "
          f"{'error with dE':>14} {'error without':>14}")
    for dt in args.dt:
        s = run(dt, args.t_end)
        t = s["window"]["t1"] - s["window"]["t0"]
        rest = s["drive_power"] - s["dissipation"] - s["kinetic_energy_change"] / t
        stored = s["contact_energy_change"] / t
        print(f"{1e6 * dt:8.3g} {s['drive_power']:10.4g} {s['dissipation']:12.4g} "
              f"{s['kinetic_energy_change'] / t:10.4g} {stored:10.4g} {rest - stored:14.3g} {rest:14.3g}", flush=True)


if __name__ == "__main__":
    main()
