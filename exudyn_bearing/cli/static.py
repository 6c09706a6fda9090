"""``static BEARING --Fr N``: quasi-static load distribution and lubrication map."""
from __future__ import annotations

import json
import math

from ..data import load_bearing
from ..outputs.jsonio import to_jsonable
from ..outputs.plotting import plot_static
from ..physics.hertz import METHODS
from ..solvers.analytic import static_analysis
from .common import BEARING_HELP, finite_float


def add_parser(sub):
    p = sub.add_parser("static", help="quasi-static load distribution and lubrication map")
    p.add_argument("bearing", help=BEARING_HELP)
    p.add_argument("--Fr", type=finite_float, required=True, help="radial load [N] on the inner ring")
    p.add_argument("--Fa", type=finite_float, default=0.0, help="axial load [N] on the inner ring")
    p.add_argument("--Pd", type=finite_float, help="diametral clearance [m] (negative: preload); "
                                                    "default: the bearing's own")
    p.add_argument("--omega", type=finite_float, help="inner-ring speed [rad/s] for the lubrication map")
    p.add_argument("--film", choices=("hd", "mk"), default="hd",
                    help="film model: Hamrock-Dowson (default) or Masjedi-Khonsari reading")
    p.add_argument("--hertz", choices=METHODS, default="exact", help="Hertz fidelity level")
    p.add_argument("--phase", type=finite_float, default=0.0, help="azimuth of ball 0 [rad]")
    p.add_argument("--plot", metavar="FILE.png", help="save Q(psi) and Lambda(psi) plot (+ CSV beside)")
    p.add_argument("--json", action="store_true", help="print JSON")


def run(args):
    b = load_bearing(args.bearing)
    if args.Pd is not None:
        b = b.with_clearance(args.Pd)
    res = static_analysis(b, args.Fr, args.Fa, omega=args.omega, film=args.film,
                          hertz_method=args.hertz, phase=args.phase)
    if args.plot:
        png, csv = plot_static(res, args.plot)
        res["plot"] = str(png)
        res["data"] = str(csv)
    if args.json:
        print(json.dumps(to_jsonable(res), indent=2))
        return
    print(f"{b.name}: Fr = {res['Fr']:g} N, Fa = {res['Fa']:g} N, Pd = {res['Pd'] * 1e6:.2f} um, "
          f"Hertz {res['hertz_method']}")
    print(f"q_max = {res['q_max']:.1f} N (continuous Stribeck {res.get('q_max_stribeck', float('nan')):.1f} N), "
          f"eps = {res['eps']:.4f}, delta_r = {res['delta_r'] * 1e6:.3f} um, "
          f"delta_a = {res['delta_a'] * 1e6:.3f} um")
    head = f"{'ball':>4} {'psi deg':>8} {'Q N':>9} {'delta um':>9} {'alpha deg':>9}"
    if args.omega is not None:
        head += f" {'h_in um':>8} {'L_in':>6} {'h_out um':>8} {'L_out':>6} {'regime out':>10}"
    print(head)
    names = ("boundary", "mixed", "full_film")
    for j in range(len(res["q"])):
        line = (f"{j:>4} {math.degrees(res['psi'][j]):8.1f} {res['q'][j]:9.1f} "
                f"{res['overlap'][j] * 1e6:9.3f} {math.degrees(res['contact_angle'][j]):9.2f}")
        if args.omega is not None:
            reg = int(res["regime_outer"][j])
            line += (f" {res['h_min_inner'][j] * 1e6:8.3f} {res['lambda_inner'][j]:6.2f}"
                     f" {res['h_min_outer'][j] * 1e6:8.3f} {res['lambda_outer'][j]:6.2f}"
                     f" {names[reg] if reg >= 0 else 'no contact':>10}")
        print(line)
    if args.plot:
        print(f"plot: {res['plot']}  data: {res['data']}")
