"""``quasistatic BEARING``: 5-DOF inner-ring equilibrium at speed, ball kinematics, slip and dissipation."""
from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

from ..data import InputError, lubricants, traction_models
from ..outputs.jsonio import to_jsonable
from ..outputs.plotting_quasistatic import plot_loads_angles, plot_slip
from ..physics.hertz import METHODS
from ..solvers.quasistatic import solve_quasistatic
from ..solvers.quasistatic.kinematics import CONTROLS
from ..solvers.quasistatic.losses import LOSS_COMPONENTS
from ..solvers.quasistatic.ring import DOF_NAMES
from .common import add_bearing_argument, add_load_arguments, bearing_from_args, finite_float


def add_parser(sub):
    p = sub.add_parser("quasistatic", help="quasi-static equilibrium at speed: 5-DOF inner ring, ball kinematics "
                                           "(race control or minimum energy), slip, dissipation, stiffness")
    add_bearing_argument(p)
    add_load_arguments(p)
    speed = p.add_mutually_exclusive_group()
    speed.add_argument("--omega", type=finite_float, help="inner-ring speed [rad/s]")
    speed.add_argument("--rpm", type=finite_float, help="inner-ring speed [1/min]")
    p.add_argument("--omega-outer", type=finite_float, default=0.0, help="outer-ring speed [rad/s] (default fixed)")
    p.add_argument("--control", choices=CONTROLS, default="auto",
                   help="ball kinematics: race control (outer, inner, auto = Jones' criterion) or min-energy (Gupta)")
    p.add_argument("--traction", default="lambda_dem", help=f"traction model ({', '.join(traction_models)})")
    p.add_argument("--lubricant", default=None, help=f"lubricant for the films ({', '.join(lubricants)})")
    p.add_argument("--ring-growth", action=argparse.BooleanOptionalAction, default=True,
                   help="centrifugal growth of the rotating rings (default on)")
    p.add_argument("--fit", type=finite_float, default=0.0, help="diametral interference of the inner ring on a "
                                                                 "solid shaft [m]")
    p.add_argument("--temperature", type=finite_float, nargs=3, metavar=("T_INNER", "T_OUTER", "T_BALL"),
                   help="part temperatures [K] for uniform thermal growth (default 293.15 K)")
    p.add_argument("--fix", action="append", default=[], metavar="DOF=VALUE",
                   help=f"hold a DOF ({', '.join(DOF_NAMES)}) at a value [m or rad]; its reaction is reported")
    p.add_argument("--hertz", choices=METHODS, default="exact", help="Hertz fidelity level")
    p.add_argument("--strips", type=int, default=32, help="strips along each contact ellipse")
    p.add_argument("--plot", metavar="FILE.png", help="loads and contact angles against azimuth (+ CSV, and "
                                                      "FILE_slip.png with the slip along ball 0's contacts)")
    p.add_argument("--json", action="store_true", help="print JSON")


def parse_fixed(items):
    fixed = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep:
            raise InputError(f"fix: expected DOF=VALUE, got {item!r}")
        try:
            fixed[name.strip()] = float(value)
        except ValueError:
            raise InputError(f"fix: {name.strip()}: expected a number, got {value!r}") from None
    return fixed


def run(args):
    b = bearing_from_args(args)
    if args.Pd is not None:
        b = b.with_clearance(args.Pd)
    omega = args.omega if args.omega is not None else (args.rpm * math.pi / 30.0 if args.rpm is not None else 0.0)
    temps = dict(zip(("inner", "outer", "ball"), args.temperature)) if args.temperature else None
    s = solve_quasistatic(b, args.Fr, args.Fa, args.Mx, args.My, Fy=args.Fy, omega=omega,
                          omega_outer=args.omega_outer, control=args.control, traction=args.traction,
                          lubricant=args.lubricant, ring_growth=args.ring_growth, fit=args.fit, temperatures=temps,
                          fixed=parse_fixed(args.fix), hertz_method=args.hertz, n_strips=args.strips)
    d = s.to_dict()
    if args.plot:
        png = plot_loads_angles({b.name: s}, args.plot)
        d["plot"] = str(png)
        if s.contact_geometry is not None:
            d["plot_slip"] = str(plot_slip({b.name: s}, Path(args.plot).with_name(Path(args.plot).stem + "_slip.png")))
    if args.json:
        for k in ("slip_inner", "slip_outer"):
            d[k] = d[k].tolist()
        print(json.dumps(to_jsonable(d), indent=2))
        return
    print(s.summary())
    if d["power_loss"] is not None:  # solvers/quasistatic/losses.py
        pl = d["power_loss"]
        print(f"power loss {d['power_loss_total']:.4g} W (" + ", ".join(f"{k} {pl[k]:.4g}" for k in LOSS_COMPONENTS)
              + f"), friction torque {d['friction_torque_total']:.4g} N m; cage and seals not modelled")
    bl = s.balls
    print(f"{'ball':>4} {'psi':>6} {'Q_in N':>9} {'Q_out N':>9} {'a_in':>6} {'a_out':>6} {'pmax_in':>8} "
          f"{'w_m':>8} {'beta':>6} {'sr_in':>7} {'sr_out':>7} {'P_in W':>8} {'P_out W':>8}")
    for j in range(len(bl["psi"])):
        print(f"{j:>4} {math.degrees(bl['psi'][j]):6.1f} {bl['q_inner'][j]:9.1f} {bl['q_outer'][j]:9.1f} "
              f"{math.degrees(bl['alpha_inner'][j]):6.2f} {math.degrees(bl['alpha_outer'][j]):6.2f} "
              f"{bl['p_max_inner'][j] / 1e9:7.3f}G {bl['orbital_speed'][j]:8.2f} {math.degrees(bl['beta'][j]):6.2f} "
              f"{bl['spin_roll_inner'][j]:7.4f} {bl['spin_roll_outer'][j]:7.4f} "
              f"{bl['dissipation_inner_ball'][j]:8.3g} {bl['dissipation_outer_ball'][j]:8.3g}")
    if args.plot:
        print(f"plot: {d['plot']}")
