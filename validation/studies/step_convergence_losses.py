"""Step convergence of the dynamic summary's friction and damping outputs at
the two traction levels (docs/theory/dynamics.md, "What each traction level
models").

The ACBB-120 under 22,240 N thrust at 2618 rad/s (25,000 rpm, no cage) is run
by the reference engine at dt = 4, 2, 1 and 0.5 us, at the point level
(Cundall-Strack spring, the default) and at the ellipse level, and the
summary's friction_torque, friction_power, contact damping and dissipation
are printed per step. At the point level friction_power falls in proportion
to dt and the damping with dt^2 (step noise: the summary says
``friction_outputs_converged: false``); the ellipse level's friction torque
and power move by well under 1 % from 2 us down.

    python validation/studies/step_convergence_losses.py [--t-end-point 0.01] [--t-end-ellipse 0.005]

About 3 minutes on the 2-core machine.
"""
from __future__ import annotations

import argparse
import warnings

import exudyn_bearing as eb

STEPS = (4e-6, 2e-6, 1e-6, 0.5e-6)


def run(level: str, dt: float, t_end: float) -> dict:
    sc = eb.Scenario(Fr=0.0, Fa=22240.0, omega=2618.0, t_end=t_end, dt=dt, sample_dt=5e-5, cage=False,
                     traction_level=level)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return eb.simulate("ACBB-120", sc, progress=False).summary()


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--t-end-point", type=float, default=0.01, help="simulated time of the point-level runs [s]")
    p.add_argument("--t-end-ellipse", type=float, default=0.005, help="simulated time of the ellipse runs [s]")
    args = p.parse_args(argv)
    print(f"{'level':8} {'dt [us]':>7} {'friction_torque [N m]':>22} {'friction_power [W]':>19} "
          f"{'contact_damping [W]':>20} {'dissipation [W]':>16}  converged")
    for level, t_end in (("point", args.t_end_point), ("ellipse", args.t_end_ellipse)):
        for dt in STEPS:
            s = run(level, dt, t_end)
            print(f"{level:8} {dt * 1e6:7.2g} {s['friction_torque']:22.4g} {s['friction_power']:19.4g} "
                  f"{s['power_loss']['contact_damping']:20.4g} {s['dissipation']:16.4g}  "
                  f"{s['friction_outputs_converged']}", flush=True)


if __name__ == "__main__":
    main()
