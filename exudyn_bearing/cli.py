"""Command line: ``python -m exudyn_bearing`` / ``exudyn-bearing``.

Sub-commands (``--json`` for scripts, tables otherwise):

* ``info BEARING [--omega W]``: geometry, Hertz constants, kinematics.
* ``static BEARING --Fr N [--Fa N] [--Pd M] [--omega W] [--film hd|mk]
  [--plot FILE.png]``: quasi-static load distribution and lubrication map.
* ``simulate --bearing B --Fr N --omega W --engine reference --t-end T
  [--out DIR] [--json]``: dynamic simulation; summary keys of
  :meth:`exudyn_bearing.outputs.results.Results.summary`.

BEARING is a catalogue name (6208, 7208, 6004, ACBB-120) or a JSON file with
the geometry (format of ``exudyn_bearing/data/catalog.json``). Bad input
exits with status 2 and a one-line message naming the parameter.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path


from .data import InputError, catalog, load_bearing
from .model.stability import SimulationError
from .outputs.jsonio import to_jsonable
from .physics.hertz import METHODS

__all__ = ["main", "to_jsonable"]


def _finite_float(text):
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None
    if not math.isfinite(v):
        raise argparse.ArgumentTypeError(f"must be finite, got {text!r}")
    return v


class _Parser(argparse.ArgumentParser):
    """One-line errors (no usage dump), exit status 2."""

    def error(self, message):
        self.exit(2, f"exudyn-bearing: error: {message} (see --help)\n")


def _parser() -> argparse.ArgumentParser:
    p = _Parser(prog="exudyn-bearing", description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="command", required=True, parser_class=_Parser)
    bearing_help = f"catalogue name ({', '.join(catalog)}) or a JSON file"

    pi = sub.add_parser("info", help="geometry, Hertz constants and kinematics of a bearing")
    pi.add_argument("bearing", help=bearing_help)
    pi.add_argument("--omega", type=_finite_float, help="inner-ring speed [rad/s], outer ring fixed")
    pi.add_argument("--hertz", choices=METHODS, default="exact", help="Hertz fidelity level")
    pi.add_argument("--json", action="store_true", help="print JSON")

    ps = sub.add_parser("static", help="quasi-static load distribution and lubrication map")
    ps.add_argument("bearing", help=bearing_help)
    ps.add_argument("--Fr", type=_finite_float, required=True, help="radial load [N] on the inner ring")
    ps.add_argument("--Fa", type=_finite_float, default=0.0, help="axial load [N] on the inner ring")
    ps.add_argument("--Pd", type=_finite_float, help="diametral clearance [m] (negative: preload); "
                                                    "default: the bearing's own")
    ps.add_argument("--omega", type=_finite_float, help="inner-ring speed [rad/s] for the lubrication map")
    ps.add_argument("--film", choices=("hd", "mk"), default="hd",
                    help="film model: Hamrock-Dowson (default) or Masjedi-Khonsari reading")
    ps.add_argument("--hertz", choices=METHODS, default="exact", help="Hertz fidelity level")
    ps.add_argument("--phase", type=_finite_float, default=0.0, help="azimuth of ball 0 [rad]")
    ps.add_argument("--plot", metavar="FILE.png", help="save Q(psi) and Lambda(psi) plot (+ CSV beside)")
    ps.add_argument("--json", action="store_true", help="print JSON")
    pr = sub.add_parser("simulate", help="dynamic simulation (numba DEM reference engine or Exudyn element)")
    pr.add_argument("--bearing", default="6208", help=bearing_help)
    pr.add_argument("--engine", default="reference", choices=("reference", "exudyn"))
    pr.add_argument("--Fr", type=_finite_float, default=3000.0, help="radial load [N]")
    pr.add_argument("--Fa", type=_finite_float, default=0.0, help="axial load [N]")
    pr.add_argument("--Pd", type=_finite_float, help="diametral clearance [m]")
    pr.add_argument("--omega", type=_finite_float, default=500.0, help="inner-ring speed [rad/s]")
    pr.add_argument("--t-end", type=_finite_float, default=0.02, help="simulated time [s]")
    pr.add_argument("--ramp", type=_finite_float, nargs=3, metavar=("UP", "STEADY", "DOWN"),
                    help="speed protocol [s]: ramp-up, steady and slow-down durations (start from rest)")
    pr.add_argument("--dt", type=_finite_float, default=1e-6, help="time step [s]")
    pr.add_argument("--sample-dt", type=_finite_float, default=1e-4, help="output interval [s]")
    pr.add_argument("--integrator", choices=("verlet", "rk4"), default="verlet")
    pr.add_argument("--friction", choices=("history", "regularized", "none"), default="history")
    pr.add_argument("--tangential", choices=("explicit", "implicit"), default="explicit",
                    help="update of the Cundall-Strack spring")
    pr.add_argument("--hertz", choices=METHODS, default="exact")
    pr.add_argument("--film", choices=("hd", "mk"), default="hd")
    pr.add_argument("--cage", action=argparse.BooleanOptionalAction, default=True, help="torus cage on/off")
    pr.add_argument("--lubrication", action=argparse.BooleanOptionalAction, default=True,
                    help="Lambda-switched damping and friction on/off")
    pr.add_argument("--initial", choices=("analytic", "rest"), default="analytic")
    pr.add_argument("--out", metavar="DIR", help="write run.npz, run.json and run.png into DIR")
    pr.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None)
    pr.add_argument("--json", action="store_true", help="print the summary as JSON")
    return p


def _cmd_simulate(args):
    from .model.scenario import Scenario
    from .simulate import simulate

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
    _print_table(rows)


def _print_table(rows):
    width = max(len(k) for k, _ in rows)
    for k, v in rows:
        if isinstance(v, float):
            v = f"{v:.6g}"
        print(f"{k:<{width}}  {v}")


_LENGTHS = ("ball_radius", "inner_race_radius", "outer_race_radius", "inner_groove_radius",
            "outer_groove_radius", "cage_ball_radius", "pitch_radius", "diametral_clearance",
            "cage_pocket_clearance", "R_x_inner", "R_y_inner", "R_x_outer", "R_y_outer")
_INFO_UNITS = dict({k: "m" for k in _LENGTHS}, K_inner="N/m^1.5", K_outer="N/m^1.5", K_n="N/m^1.5",
                   cage_speed="rad/s", ball_spin="rad/s", ball_spin_relative="rad/s", omega="rad/s",
                   ftf="Hz", bpfo="Hz", bpfi="Hz", bsf="Hz", rolling_speed="m/s", e_prime="Pa",
                   ball_mass="kg", free_contact_angle_deg="deg")


def _cmd_info(args):
    from .solvers.analytic import bearing_info

    b = load_bearing(args.bearing)
    info = bearing_info(b, args.omega, args.hertz)
    if args.json:
        print(json.dumps(to_jsonable(info), indent=2))
        return
    rows = [(k, f"{v:.6g} {_INFO_UNITS.get(k, '')}".rstrip() if isinstance(v, float) else v)
            for k, v in info.items() if k != "source"]
    _print_table(rows)
    print(f"source: {info['source']}")


def _cmd_static(args):
    from .solvers.analytic import static_analysis

    b = load_bearing(args.bearing)
    if args.Pd is not None:
        b = b.with_clearance(args.Pd)
    res = static_analysis(b, args.Fr, args.Fa, omega=args.omega, film=args.film,
                          hertz_method=args.hertz, phase=args.phase)
    if args.plot:
        from .outputs.plotting import plot_static

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


def main(argv=None) -> int:
    """Entry point; returns the exit status."""
    args = _parser().parse_args(argv)
    try:
        if args.command == "info":
            _cmd_info(args)
        elif args.command == "static":
            _cmd_static(args)
        elif args.command == "simulate":
            _cmd_simulate(args)
    except (InputError, ValueError) as exc:
        print(f"exudyn-bearing: error: {exc}", file=sys.stderr)
        return 2
    except SimulationError as exc:
        print(f"exudyn-bearing: error: {exc}", file=sys.stderr)
        return 3
    except OSError as exc:
        print(f"exudyn-bearing: error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
