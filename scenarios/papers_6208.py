"""The DEM papers' 6208 test with the reference engine
===================================================

The inner ring driven to 500 rad/s (start-up ramp, steady phase, slow-down)
under F_r = 3000 N, P_d = 0.

Writes into ``--out`` (default scenarios/out/papers_6208): the run (NPZ +
JSON summary) and the figures of docs/theory/reference_cases.md, each PNG with a CSV:
speeds against time, slide-to-roll ratio of one ball, h_min and Lambda of the
outer contact against azimuth by phase, and the overview.

Command::

    python scenarios/papers_6208.py [--up 0.05 --steady 0.2 --down 0.05] [--dt 3e-6] [--engine exudyn]

Tangential force: Cundall-Strack spring with contact history (explicit,
the papers' model).
"""
import argparse
from pathlib import Path

import exudyn_bearing as eb
from exudyn_bearing.outputs import plotting


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--up", type=float, default=0.05, help="start-up ramp [s]")
    ap.add_argument("--steady", type=float, default=0.2, help="steady phase [s]")
    ap.add_argument("--down", type=float, default=0.05, help="slow-down ramp [s]")
    ap.add_argument("--dt", type=float, default=3e-6, help="time step [s] (cage-contact limit 3.9 us)")
    ap.add_argument("--engine", choices=("reference", "exudyn"), default="reference")
    ap.add_argument("--out", default=str(Path(__file__).parent / "out" / "papers_6208"))
    args = ap.parse_args(argv)
    sc = eb.Scenario.papers_protocol(omega=500.0, t_ramp_up=args.up, t_steady=args.steady,
                                     t_ramp_down=args.down, Fr=3000.0, dt=args.dt, sample_dt=1e-4)
    run = eb.simulate("6208", sc, engine=args.engine, progress=args.engine == "reference")
    out = Path(args.out)
    run.save(out, stem="run")
    figs = [run.plot(out / "overview.png"), plotting.plot_speeds(run, out / "speeds.png"),
            plotting.plot_srr(run, out / "srr_ball0.png"), plotting.plot_film_by_phase(run, out / "film_outer.png")]
    # summary over the second half of the steady phase
    s = run.summary(t_window=(args.up + 0.5 * args.steady, args.up + args.steady))
    print(f"6208, Fr = 3000 N, 500 rad/s protocol {args.up}/{args.steady}/{args.down} s, dt = {args.dt} s, "
          f"{args.engine} engine: "
          f"{run.steps} steps in {run.wall_s:.1f} s")
    print(f"steady phase: cage {s['cage_speed']:.2f} rad/s (kinematic {s['kinematic_cage_speed']:.2f}), "
          f"ball spin {s['ball_spin']:.2f} rad/s (kinematic {s['kinematic_ball_spin']:.2f}), "
          f"q_max inner/outer {s['q_max_inner']:.0f}/{s['q_max_outer']:.0f} N, "
          f"Lambda_out(psi=0) {s['lambda_outer_psi0']:.2f}, Lambda_in(psi=0) {s['lambda_inner_psi0']:.2f}")
    for f in figs:
        print("figure:", f)


if __name__ == "__main__":
    main()
