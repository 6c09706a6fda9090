"""``simulate [BEARING]``: dynamic simulation with the reference engine, the Exudyn element or the reduced engine."""
from __future__ import annotations

import argparse
import json
import warnings
from pathlib import Path

from ..data import InputError
from ..model.record import RunInterrupted
from ..model.scenario import CONTROLS, INITIAL_STATES, TOLERANCE_MIN, TRACTION_LEVELS, Scenario
from ..outputs.jsonio import to_jsonable
from ..outputs.tables import summary_rows
from ..physics.hertz import METHODS
from ..simulate import ENGINES, simulate
from .common import (add_strip_arguments, add_bearing_argument, add_lubricant_argument, add_ring_growth_argument, add_speed_arguments,
                     add_traction_argument, bearing_from_args, finite_float, lubricant_from_args,
                     omega_from_args, print_table, add_outer_speed_arguments, omega_outer_from_args)

#: Simulated time [s] without --t-end and --ramp.
DEFAULT_T_END = 0.02


def add_parser(sub):
    p = sub.add_parser("simulate", help="dynamic simulation (numba DEM reference engine or Exudyn element)",
                       description="Dynamic simulation of a bearing ball by ball; prints the summary over the "
                                   "steady phase of a --ramp protocol (else over the last quarter of the run) "
                                   "and its window.")
    add_bearing_argument(p, default="6208")
    p.add_argument("--engine", default="reference", choices=ENGINES,
                   help="numba DEM reference core, the same scene in Exudyn with the bearing element, or the "
                        "reduced engine (ball centres on their force balance, steps of tens of us: --dt 2e-5; "
                        "takes --cage none or rigid, and --traction-level ellipse or --friction regularized)")
    p.add_argument("--Fr", type=finite_float, default=0.0, help="radial load [N] (default 0; the README's example: "
                                                               "--Fr 3000 --omega 500)")
    p.add_argument("--Fa", type=finite_float, default=0.0, help="axial load [N]")
    p.add_argument("--Pd", type=finite_float, help="diametral clearance [m] (negative: preload, e.g. -12.6e-6); "
                                                    "default: the bearing's own")
    add_speed_arguments(p, what="none: a dynamic run needs a speed (--omega 0: at rest)")
    add_outer_speed_arguments(p, " under the same --ramp protocol (the reference engine)")
    add_lubricant_argument(p)
    p.add_argument("--t-end", type=finite_float,
                   help=f"simulated time [s] (default: the sum of the --ramp durations, else {DEFAULT_T_END:g})")
    p.add_argument("--ramp", type=finite_float, nargs=3, metavar=("UP", "STEADY", "DOWN"),
                   help="speed protocol [s]: ramp-up, steady and slow-down durations (from rest; "
                        "default: none, the run starts at speed)")
    p.add_argument("--dt", type=finite_float, default=1e-6, help="time step [s] (with --tolerance: the first step)")
    p.add_argument("--tolerance", type=finite_float, default=None,
                   help="the reduced engine's step error control: each step's local error of the speeds below "
                        "TOLERANCE times the inner ring's speed at the pitch radius (e.g. 1e-5, at least "
                        f"{TOLERANCE_MIN:g}; "
                        "docs/theory/reduced.md); default: the fixed step --dt. Its drive power needs 1e-6 or "
                        "below, and a start or ramp from rest stops at the least step: use the fixed --dt there")
    p.add_argument("--sample-dt", type=finite_float, default=1e-4, help="output interval [s]")
    p.add_argument("--integrator", choices=("verlet", "rk4"), default="verlet",
                   help="explicit integrator (rk4 needs a history-free --friction)")
    p.add_argument("--friction", choices=("history", "regularized", "none"), default="history",
                   help="tangential force: Cundall-Strack spring with contact history, regularised Coulomb, none")
    p.add_argument("--tangential", choices=("explicit", "implicit"), default="explicit",
                   help="update of the Cundall-Strack spring")
    p.add_argument("--cage-damping", choices=("explicit", "implicit"), default="explicit",
                   help="damping of the ball / cage-ball contacts: explicit (the papers'), or implicit (backward "
                        "Euler over the step: lifts the cage contacts' step limit about 1.9 times; verlet only)")
    p.add_argument("--hertz", choices=METHODS, default="exact", help="Hertz fidelity level")
    p.add_argument("--film", choices=("hd", "mk"), default="hd",
                   help="film model: Hamrock-Dowson or Masjedi-Khonsari reading")
    p.add_argument("--cage", nargs="?", const="torus", default="auto", choices=("auto", "torus", "rigid", "none"),
                   help="cage model: the DEM papers' torus of cage balls, a rigid cage body with pockets "
                        "and a guiding land (both engines; geometry estimated from the ball diameter, "
                        "docs/theory/cage.md), or none; default auto: the torus where the bearing has cage balls "
                        "(the papers' bearings), else the rigid cage (ACBB-120); a bare --cage is the torus")
    p.add_argument("--no-cage", dest="cage", action="store_const", const="none", help="the same as --cage none")
    p.add_argument("--pocket-film", action="store_true",
                   help="the oil film between each ball and its rigid-cage pocket (hydrodynamic and squeeze forces "
                        "and the film's viscous shear; docs/theory/cage.md#pocket-oil-film); needs --cage rigid")
    p.add_argument("--lubrication", action=argparse.BooleanOptionalAction, default=True,
                   help="Lambda-switched damping and friction on/off")
    p.add_argument("--initial", choices=INITIAL_STATES, default="analytic",
                   help="start from the analytic load distribution at kinematic speeds, from rest (--ramp with "
                        "UP > 0: rest), or from the quasi-static solver's solution (ball positions, contact angles, "
                        "orbital and ball speeds by --control)")
    p.add_argument("--control", choices=CONTROLS, default="auto",
                   help="kinematics of the quasi-static start: race control (auto by Jones' criterion, outer, "
                        "inner), minimum energy (Gupta), or traction equilibrium")
    p.add_argument("--traction-level", choices=TRACTION_LEVELS, default="point",
                   help="tangential force: point-contact law (--friction) or traction integrated over the Hertz "
                        "ellipse (slip from rolling, spin and curvature; --traction model)")
    add_traction_argument(p, "traction model of the ellipse level")
    add_strip_arguments(p)
    add_ring_growth_argument(p)
    p.add_argument("--rolling-resistance", action=argparse.BooleanOptionalAction, default=False,
                   help="rolling resistance (elastic hysteresis and, with lubrication, the EHL rolling force) as a "
                        "moment pair at every loaded ball / raceway contact (docs/theory/losses.md); default off")
    p.add_argument("--ball-drag", action=argparse.BooleanOptionalAction, default=False,
                   help="drag of the oil-air mixture (at rest with the outer ring) on every ball; default off")
    p.add_argument("--oil-volume-fraction", type=finite_float, default=0.0,
                   help="oil's share of the free volume the balls move through, 0-1, for --ball-drag (0: air)")
    p.add_argument("--hysteresis-loss-factor", type=finite_float, default=Scenario.hysteresis_loss_factor,
                   help="hysteresis loss factor alpha_h of --rolling-resistance [-] (default %(default)g, "
                        "hardened bearing steel)")
    p.add_argument("--out", metavar="DIR", help="write run.npz, run.json, run.png and run.csv into DIR")
    p.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                   help="progress on stderr (default: for runs over 2 million steps or estimated to take over a "
                        "minute, which say so first)")
    p.add_argument("--json", action="store_true", help="print the summary as JSON (with its units map)")


def scenario_from_args(args) -> Scenario:
    """The Scenario of the arguments: --ramp sets the protocol and, without --t-end, the run length."""
    t_end = args.t_end
    omega = omega_from_args(args)
    if omega is None:  # no default speed (docs/defaults.md): a run needs one, the README's example is 500 rad/s
        raise InputError("omega: simulate needs a speed: give --omega RAD_S or --rpm RPM (the README's example: "
                         "--Fr 3000 --omega 500; --omega 0 for a run at rest)")
    kw = dict(Fr=args.Fr, Fa=args.Fa, omega=omega, omega_outer=omega_outer_from_args(args), Pd=args.Pd, dt=args.dt,
              tolerance=args.tolerance,
              sample_dt=args.sample_dt, integrator=args.integrator, friction=args.friction,
              tangential=args.tangential, cage_damping=args.cage_damping, hertz=args.hertz, film=args.film,
              cage=args.cage, pocket_film=args.pocket_film,
              lubrication=args.lubrication, initial=args.initial, control=args.control,
              traction_level=args.traction_level, traction=args.traction, n_strips=args.strips, n_across=args.points_across,
              ring_growth=args.ring_growth, rolling_resistance=args.rolling_resistance, ball_drag=args.ball_drag,
              oil_volume_fraction=args.oil_volume_fraction, hysteresis_loss_factor=args.hysteresis_loss_factor)
    if args.ramp:
        up, steady, down = args.ramp
        kw.update(t_ramp_up=up, t_steady=steady, t_ramp_down=down)
        if args.initial == "analytic" and up > 0:
            kw["initial"] = "rest"
        if t_end is None:
            t_end = up + steady + down
    kw["t_end"] = DEFAULT_T_END if t_end is None else t_end
    return Scenario(**kw)


def _save_partial(results, out):
    """Write the samples of an interrupted run into ``out`` (run.npz, run.json); the folder, or None when
    they do not make a summary (too few samples)."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            results.save(out)
    except (ValueError, IndexError, OSError):
        return None
    return str(out)


def _check_out(out):
    """The --out folder, made before the run (a run is not lost to a folder it cannot write): an InputError
    naming --out when it is a file or cannot be made or written."""
    path = Path(out)
    if path.exists() and not path.is_dir():
        raise InputError(f"--out: {out} is a file, not a folder (the run writes run.npz, run.json, run.png and "
                         "run.csv into it)")
    try:
        path.mkdir(parents=True, exist_ok=True)
        probe = path / ".exudyn_bearing_write_check"
        probe.write_text("")
        probe.unlink()
    except OSError as exc:
        raise InputError(f"--out: cannot write into {out} ({exc.strerror or exc})") from None


def run(args):
    sc = scenario_from_args(args)
    b = bearing_from_args(args)
    if args.out:
        _check_out(args.out)
    try:
        run = simulate(b, sc, engine=args.engine, lubricant=lubricant_from_args(args, b), progress=args.progress)
    except RunInterrupted as exc:  # Ctrl-C: --out keeps the samples so far; the caller prints one line
        if args.out and exc.results is not None:
            exc.saved = _save_partial(exc.results, args.out)
        raise
    summary = run.summary()
    # the lubricant and traction model in use (the bearing's unless given), unless the summary names them
    summary.setdefault("lubricant", run.lubricant.name)
    sc = run.scenario
    mu = "mu(Lambda) of the lubricant" if sc.lubrication else f"mu_dry = {sc.mu_dry:g}"
    summary.setdefault("traction", sc.traction if sc.traction_level == "ellipse" else
                       f"point-contact law ({sc.friction}, {mu})" if sc.friction != "none" else "none (friction off)")
    summary.setdefault("ring_growth", sc.ring_growth)
    if args.out:
        npz, js = run.save(args.out)
        png = run.plot(Path(args.out) / "run.png")
        summary.update(npz=str(npz), json=str(js), plot=str(png))
    if args.json:
        print(json.dumps(to_jsonable(summary), indent=2))
        return
    print_table(summary_rows(summary, sc.t_end))
