"""``static BEARING --Fr N``: quasi-static load distribution and lubrication map."""
from __future__ import annotations

import json
import math

from ..outputs.jsonio import to_jsonable
from ..outputs.plotting import plot_static
from ..outputs.units import REGIME_CODES, STATIC_UNITS, with_units
from ..physics.hertz import METHODS
from ..solvers.analytic import static_analysis
from .common import (add_bearing_argument, add_lubricant_argument, add_speed_arguments, bearing_from_args,
                     finite_float, lubricant_from_args, omega_from_args)


def add_parser(sub):
    p = sub.add_parser("static", help="quasi-static load distribution and lubrication map",
                       description="Quasi-static load distribution of the balls and, with a speed, the film "
                                   "thickness, film parameter and lubrication regime of every contact.")
    add_bearing_argument(p)
    p.add_argument("--Fr", type=finite_float, required=True, help="radial load [N] on the inner ring")
    p.add_argument("--Fa", type=finite_float, default=0.0, help="axial load [N] on the inner ring")
    p.add_argument("--Pd", type=finite_float, help="diametral clearance [m] (negative: preload, e.g. -12.6e-6); "
                                                    "default: the bearing's own")
    add_speed_arguments(p, what="none: no lubrication map")
    add_lubricant_argument(p)
    p.add_argument("--film", choices=("hd", "mk"), default="hd",
                   help="film model: Hamrock-Dowson or Masjedi-Khonsari reading")
    p.add_argument("--hertz", choices=METHODS, default="exact", help="Hertz fidelity level")
    p.add_argument("--phase", type=finite_float, default=0.0, help="azimuth of ball 0 [rad], taken modulo 2 pi")
    p.add_argument("--plot", metavar="FILE.png", help="save Q(psi) and Lambda(psi) plot (+ CSV beside)")
    p.add_argument("--json", action="store_true", help="print JSON (with units and regime_codes) instead of a table")


def run(args):
    b = bearing_from_args(args)
    if args.Pd is not None:
        b = b.with_clearance(args.Pd)
    omega = omega_from_args(args)
    res = static_analysis(b, args.Fr, args.Fa, omega=omega, film=args.film, hertz_method=args.hertz,
                          phase=args.phase, lubricant=lubricant_from_args(args))
    if args.plot:
        png, csv = plot_static(res, args.plot)
        res["plot"] = str(png)
        res["data"] = str(csv)
    if args.json:
        out = with_units(res, STATIC_UNITS)
        if omega is not None:
            out["regime_codes"] = REGIME_CODES
        print(json.dumps(to_jsonable(out), indent=2))
        return
    print(f"{b.name}: Fr = {res['Fr']:g} N, Fa = {res['Fa']:g} N, Pd = {res['Pd'] * 1e6:.2f} um, "
          f"Hertz {res['hertz_method']}" + (f", omega = {omega:g} rad/s" if omega is not None else ""))
    print(f"q_max = {res['q_max']:.1f} N (continuous Stribeck {res.get('q_max_stribeck', float('nan')):.1f} N), "
          f"eps = {res['eps']:.4f}, delta_r = {res['delta_r'] * 1e6:.3f} um, "
          f"delta_a = {res['delta_a'] * 1e6:.3f} um")
    head = f"{'ball':>4} {'psi deg':>8} {'Q N':>9} {'delta um':>9} {'alpha deg':>9}"
    if omega is not None:
        head += f" {'h_in um':>8} {'L_in':>6} {'h_out um':>8} {'L_out':>6} {'regime out':>10}"
    print(head)
    for j in range(len(res["q"])):
        line = (f"{j:>4} {math.degrees(res['psi'][j]):8.1f} {res['q'][j]:9.1f} "
                f"{res['overlap'][j] * 1e6:9.3f} {math.degrees(res['contact_angle'][j]):9.2f}")
        if omega is not None:
            reg = str(int(res["regime_outer"][j]))
            line += (f" {res['h_min_inner'][j] * 1e6:8.3f} {res['lambda_inner'][j]:6.2f}"
                     f" {res['h_min_outer'][j] * 1e6:8.3f} {res['lambda_outer'][j]:6.2f}"
                     f" {REGIME_CODES[reg]:>10}")
        print(line)
    if args.plot:
        print(f"plot: {res['plot']}  data: {res['data']}")
