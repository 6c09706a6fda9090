"""``simulate --bearing B``: dynamic simulation with the reference engine or the Exudyn element."""
from __future__ import annotations

import argparse
import json
from pathlib import Path

from ..model.scenario import Scenario
from ..outputs.jsonio import to_jsonable
from ..physics.hertz import METHODS
from ..simulate import simulate
from .common import BEARING_HELP, finite_float, print_table


def add_parser(sub):
    p = sub.add_parser("simulate", help="dynamic simulation (numba DEM reference engine or Exudyn element)")
    p.add_argument("--bearing", default="6208", help=BEARING_HELP)
    p.add_argument("--engine", default="reference", choices=("reference", "exudyn"))
    p.add_argument("--Fr", type=finite_float, default=3000.0, help="radial load [N]")
    p.add_argument("--Fa", type=finite_float, default=0.0, help="axial load [N]")
    p.add_argument("--Pd", type=finite_float, help="diametral clearance [m]")
    p.add_argument("--omega", type=finite_float, default=500.0, help="inner-ring speed [rad/s]")
    p.add_argument("--t-end", type=finite_float, default=0.02, help="simulated time [s]")
    p.add_argument("--ramp", type=finite_float, nargs=3, metavar=("UP", "STEADY", "DOWN"),
                    help="speed protocol [s]: ramp-up, steady and slow-down durations (start from rest)")
    p.add_argument("--dt", type=finite_float, default=1e-6, help="time step [s]")
    p.add_argument("--sample-dt", type=finite_float, default=1e-4, help="output interval [s]")
    p.add_argument("--integrator", choices=("verlet", "rk4"), default="verlet")
    p.add_argument("--friction", choices=("history", "regularized", "none"), default="history")
    p.add_argument("--tangential", choices=("explicit", "implicit"), default="explicit",
                    help="update of the Cundall-Strack spring")
    p.add_argument("--hertz", choices=METHODS, default="exact")
    p.add_argument("--film", choices=("hd", "mk"), default="hd")
    p.add_argument("--cage", action=argparse.BooleanOptionalAction, default=True, help="torus cage on/off")
    p.add_argument("--lubrication", action=argparse.BooleanOptionalAction, default=True,
                    help="Lambda-switched damping and friction on/off")
    p.add_argument("--initial", choices=("analytic", "rest"), default="analytic")
    p.add_argument("--out", metavar="DIR", help="write run.npz, run.json and run.png into DIR")
    p.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None)
    p.add_argument("--json", action="store_true", help="print the summary as JSON")


def run(args):
    kw = dict(Fr=args.Fr, Fa=args.Fa, omega=args.omega, t_end=args.t_end, Pd=args.Pd, dt=args.dt,
              sample_dt=args.sample_dt, integrator=args.integrator, friction=args.friction,
              tangential=args.tangential, hertz=args.hertz, film=args.film, cage=args.cage,
              lubrication=args.lubrication, initial=args.initial)
    if args.ramp:
        kw.update(t_ramp_up=args.ramp[0], t_steady=args.ramp[1], t_ramp_down=args.ramp[2])
        if args.initial == "analytic" and args.ramp[0] > 0:
            kw["initial"] = "rest"
    run = simulate(args.bearing, Scenario(**kw), engine=args.engine, progress=args.progress)
    summary = run.summary()
    if args.out:
        npz, js = run.save(args.out)
        png = run.plot(Path(args.out) / "run.png")
        summary.update(npz=str(npz), json=str(js), plot=str(png))
    if args.json:
        print(json.dumps(to_jsonable(summary), indent=2))
        return
    rows = [(k, v) for k, v in summary.items() if not isinstance(v, (dict, list))]
    rows += [(f"regime_fraction.{k}", v) for k, v in summary["regime_fraction"].items()]
    print_table(rows)
