"""``quasistatic BEARING``: 5-DOF inner-ring equilibrium at speed, ball kinematics, slip and dissipation."""
from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import numpy as np


from ..data import InputError
from ..data.errors import check_unused
from ..outputs.jsonio import to_jsonable
from ..outputs.plotting_quasistatic import plot_loads_angles, plot_orbit_march, plot_slip
from ..physics.hertz import METHODS
from ..solvers.quasistatic import solve_quasistatic
from ..solvers.quasistatic.kinematics import CONTROLS
from ..solvers.quasistatic.orbit import MARCH_UNITS, ORBIT_STEPS_PER_PITCH, march_orbit, march_summary
from .common import (CONTROL_HELP, add_strip_arguments, add_bearing_argument, add_hold_arguments, add_lubricant_argument, add_load_arguments,
                     add_ring_growth_argument, add_traction_argument, bearing_from_args, explained, finite_float,
                     fixed_from_args, format_value, lubricant_from_args, omega_from_args, solver_header,
                     traction_from_args, add_outer_speed_arguments, omega_outer_from_args)
from .pair import add_pair_arguments, pair_requested, run_pair
from ..solvers.quasistatic.losses import LOSS_COMPONENTS
from ..solvers.quasistatic.thermal import solve_thermal
from ..physics.rating_life import RATING_UNITS, RatingLifeWarning, rating_life
from .static import add_rating_arguments, print_reaction_convention, rating_options, warn_speed


def add_parser(sub):
    p = sub.add_parser("quasistatic", help="quasi-static equilibrium at speed: 5-DOF inner ring, ball kinematics "
                                           "(race control or minimum energy), slip, dissipation, stiffness")
    add_bearing_argument(p)
    add_load_arguments(p)
    speed = p.add_mutually_exclusive_group()
    speed.add_argument("--omega", type=finite_float, help="inner-ring speed [rad/s] (default 0)")
    speed.add_argument("--rpm", type=finite_float, help="inner-ring speed [1/min]")
    p.set_defaults(omega_default=0.0)  # omega_from_args: at rest without --omega / --rpm (docs/defaults.md)
    add_outer_speed_arguments(p)
    p.add_argument("--control", choices=CONTROLS, default="auto",
                   help=CONTROL_HELP)
    # the rigid cage (solve_quasistatic cage=, docs/theory/quasistatic.md#the-rigid-cage)
    p.add_argument("--cage", choices=("none", "rigid"), default="none",
                   help="none: each ball its own orbital speed; rigid: the bearing's estimated rigid cage "
                        "(estimated_cage): balls at the cage speed within their pocket play, pocket forces, land "
                        "film (race control, --control equilibrium or min-energy)")
    p.add_argument("--pocket-film", action="store_true",
                   help="the oil film between each ball and its rigid-cage pocket (its shear and hydrodynamic "
                        "pressure, as simulate --pocket-film; docs/theory/quasistatic.md#the-pocket-film); needs "
                        "--cage rigid")
    p.add_argument("--orbit-march", nargs="?", type=int, const=ORBIT_STEPS_PER_PITCH, metavar="STEPS_PER_PITCH",
                   help="follow one ball along its orbit with its inertia through the solution's contact loads "
                        "(march_orbit: the balls' transient that the quasi-static hypothesis leaves out, with the "
                        f"cage's torque balance; docs/theory/quasistatic.md#the-orbit-march); implicit steps per "
                        f"ball pitch, default {ORBIT_STEPS_PER_PITCH}; needs --cage rigid, not with --pocket-film "
                        "or --land-feedback; with --plot also FILE_orbit.png and its CSV")
    p.add_argument("--land-feedback", action="store_true",
                   help="feed the land-guided rigid cage's displacement on its land back into the pocket play "
                        "(docs/theory/quasistatic.md#the-cages-displacement; a warning and the solution without it "
                        "when it does not converge); needs --cage rigid")
    add_traction_argument(p)
    add_lubricant_argument(p, "lubricant for the films: ")
    add_ring_growth_argument(p)
    p.add_argument("--fit", type=finite_float, default=0.0, help="diametral interference of the inner ring on a "
                                                                 "solid shaft [m]")
    p.add_argument("--temperature", type=finite_float, nargs=3, metavar=("T_INNER", "T_OUTER", "T_BALL"),
                   help="part temperatures [K] for uniform thermal growth (default 293.15 K)")
    p.add_argument("--thermal", action="store_true",
                   help="solve the bearing with its thermal network (jet lubrication): temperatures of the rings, "
                        "balls, oil and cage (a bearing with a cage) consistent with the losses (needs --oil-inlet-temperature and --oil-flow; "
                        "--lubricant then names an entry with temperature, default the bearing's)")
    p.add_argument("--oil-inlet-temperature", type=finite_float, metavar="K", help="oil inlet temperature [K] (--thermal)")
    p.add_argument("--oil-flow", type=finite_float, metavar="M3_S", help="oil flow through the bearing [m^3/s] "
                                                                         "(--thermal; 1 l/min = 1.667e-5)")
    p.add_argument("--ambient-temperature", type=finite_float, metavar="K",
                   help="air around shaft and housing [K] (--thermal; default: solve_thermal's, 293.15)")
    add_hold_arguments(p)
    add_rating_arguments(p)
    p.add_argument("--hertz", choices=METHODS, default="exact", help="Hertz fidelity level")
    add_strip_arguments(p)
    p.add_argument("--plot", metavar="FILE.png", help="loads and contact angles against azimuth (+ CSV, and "
                                                      "FILE_slip.png with the slip along ball 0's contacts)")
    p.add_argument("--json", action="store_true", help="print JSON")
    add_pair_arguments(p)  # --arrangement, --preload, --spacing (cli/pair.py)


def run(args):
    args.omega_outer = omega_outer_from_args(args)  # --omega-outer or --rpm-outer, in rad/s from here on
    if pair_requested(args):  # a bearing pair (cli/pair.py)
        return run_pair(args, "quasistatic", rating=rating_options(args), warn_speed=warn_speed)
    b = bearing_from_args(args)
    if args.Pd is not None:
        b = b.with_clearance(args.Pd, name="Pd")
    omega = omega_from_args(args)
    temps = dict(zip(("inner", "outer", "ball"), args.temperature)) if args.temperature else None
    traction = traction_from_args(args, b)
    check_unused("--thermal", args.thermal, (("--oil-flow", args.oil_flow, None),
                                             ("--oil-inlet-temperature", args.oil_inlet_temperature, None),
                                             ("--ambient-temperature", args.ambient_temperature, None)),
                 "add --thermal")
    if args.orbit_march is not None:
        if args.cage != "rigid":
            raise InputError("--orbit-march: the march follows a ball in its rigid-cage pocket; add --cage rigid")
        if args.orbit_march < 4:
            raise InputError(f"--orbit-march: at least 4 steps per ball pitch, got {args.orbit_march}")
        for flag, on in (("--pocket-film", args.pocket_film), ("--land-feedback", args.land_feedback)):
            if on:
                raise InputError(f"--orbit-march: not with {flag} (the march's ball meets a dry pocket wall of a "
                                 "centred cage)")
    if args.thermal:
        if args.orbit_march is not None:
            raise InputError("--orbit-march: not with --thermal (the march follows the quasi-static solution at "
                             "given temperatures; give them with --temperature)")
        return run_thermal(args, b, omega, traction)
    lub = lubricant_from_args(args, b)
    with explained(b):
        s = solve_quasistatic(b, args.Fr, args.Fa, args.Mx, args.My, Fy=args.Fy, omega=omega,
                              omega_outer=args.omega_outer, control=args.control, traction=traction,
                              lubricant=lub, ring_growth=args.ring_growth, fit=args.fit, temperatures=temps,
                              fixed=fixed_from_args(args), hertz_method=args.hertz, n_strips=args.strips, n_across=args.points_across,
                              cage=None if args.cage == "none" else args.cage, pocket_film=args.pocket_film,
                              land_feedback=args.land_feedback)
    warn_speed(b, omega, args.omega_outer)  # after the solve: a refusal stays the one line on stderr
    t_lub = None if temps is None else (temps["inner"] + temps["outer"] + 2.0 * temps["ball"]) / 4.0
    rating = rating_of(args, b, s, lub, t_lub, temps)
    d = s.to_dict(rating)
    d["ring_growth"] = args.ring_growth
    d["tilt"] = args.tilt
    march = None
    if args.orbit_march is not None:
        march = march_orbit(s, b, steps_per_pitch=args.orbit_march, lubricant=lub)
        d["orbit_march"] = {k: v for k, v in march.items() if k != "profile"}
        d["orbit_march"]["profile"] = {k: np.asarray(v).tolist() for k, v in march["profile"].items()}
        d["units"]["orbit_march"] = MARCH_UNITS
    if args.plot:
        png = plot_loads_angles({b.name: s}, args.plot)
        d["plot"] = str(png)
        if s.contact_geometry is not None:
            d["plot_slip"] = str(plot_slip({b.name: s}, Path(args.plot).with_name(Path(args.plot).stem + "_slip.png")))
        if march is not None:
            d["plot_orbit_march"] = str(plot_orbit_march(
                march, Path(args.plot).with_name(Path(args.plot).stem + "_orbit.png"),
                {"quasi-static solution": (np.degrees(s.balls["psi"]),
                                           s.balls["dissipation_inner_ball"] + s.balls["dissipation_outer_ball"])}))
    if args.json:
        for k in ("slip_inner", "slip_outer"):
            d[k] = d[k].tolist()
        print(json.dumps(to_jsonable(d), indent=2))
        return
    print_summary(s)
    print(solver_header(lub, traction, args.ring_growth))
    if d["power_loss"] is not None:  # solvers/quasistatic/losses.py
        print(loss_line(d, s) + "; not modelled: seals and more (--json not_modelled)")
    print_ball_table(s.balls)
    if march is not None:
        print(march_summary(march))
    print("\n".join(rating.summary()))
    if args.plot:
        print(f"plot: {d['plot']}" + (f", {d['plot_orbit_march']}" if "plot_orbit_march" in d else ""))


def rating_of(args, b, s, lubricant, temperature, temps=None):
    """The rating life of solution ``s`` (:func:`exudyn_bearing.physics.rating_life.rating_life`): at speed
    with the zero-speed solution of the same loads, clearance and held DOFs as ISO/TS 16281's distribution
    (``L10mr``) beside the one at speed (``L10mr_speed``). ``temperature``: the lubricant's [K] for kappa."""
    ref, why = None, None
    if s.omega or s.omega_outer:
        try:
            ref = solve_quasistatic(b, args.Fr, args.Fa, args.Mx, args.My, Fy=args.Fy, omega=0.0, fit=args.fit,
                                    temperatures=temps, fixed=fixed_from_args(args), hertz_method=args.hertz,
                                    stiffness=False)
        except InputError as exc:  # the loads need the speed's equilibrium (e.g. over the shoulder at rest)
            why = f"L10r, L10mr: the zero-speed load distribution of these loads is not solved ({exc})"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RatingLifeWarning)  # printed with the summary (rating_warnings)
        r = rating_life(b, s, reference=ref, temperature=temperature, lubricant=lubricant, **rating_options(args))
    if why:
        r.rating_warnings.append(why)
    return r


def run_thermal(args, b, omega, traction):
    """``--thermal``: solve_thermal (solvers/quasistatic/thermal.py), its temperatures and losses."""
    for flag, v in (("--oil-inlet-temperature", args.oil_inlet_temperature), ("--oil-flow", args.oil_flow)):
        if v is None:
            raise InputError(f"{flag}: needed with --thermal")
    if args.temperature:
        raise InputError("--temperature: the part temperatures come from the thermal network with --thermal")
    amb = {} if args.ambient_temperature is None else {"ambient_temperature": args.ambient_temperature}
    with explained(b):
        r = solve_thermal(b, args.Fr, args.Fa, omega=omega, oil_inlet_temperature=args.oil_inlet_temperature,
                          oil_flow=args.oil_flow, **amb,
                          lubricant=args.lubricant, traction=traction, Mx=args.Mx, My=args.My, Fy=args.Fy,
                          omega_outer=args.omega_outer, control=args.control, ring_growth=args.ring_growth,
                          fit=args.fit, fixed=fixed_from_args(args), hertz_method=args.hertz,
                          n_strips=args.strips, n_across=args.points_across,
                          cage=None if args.cage == "none" else args.cage, pocket_film=args.pocket_film,
                          land_feedback=args.land_feedback)
    s = r.quasistatic
    warn_speed(b, omega, args.omega_outer)
    rating = rating_of(args, b, s, r.lubricant, r.contact_temperature)
    if args.json:
        d = r.to_dict()
        d.update(rating.to_dict())
        d["units"] = {**d.get("units", {}), **RATING_UNITS}
        d["ring_growth"] = args.ring_growth
        d["tilt"] = args.tilt
        for k in ("slip_inner", "slip_outer"):
            d[k] = d[k].tolist()
        print(json.dumps(to_jsonable(d), indent=2))
        return
    print_summary(s)
    print(solver_header(r.lubricant, s.traction, args.ring_growth))
    print("temperatures [K]: " + ", ".join(f"{k} {v:.1f}" for k, v in r.temperatures.items())
          + f" (oil in {r.oil_inlet_temperature:.1f}, contacts {r.contact_temperature:.1f}); "
          + f"{r.iterations} iterations, {'converged' if r.converged else 'NOT converged'}")
    print(loss_line(r.losses, s) + f"; heat out: oil {r.heat_out['oil']:.4g} W, ambient {r.heat_out['ambient']:.4g} W")
    print_ball_table(s.balls)
    print("\n".join(rating.summary()))


def print_summary(s):
    """The solution's summary lines with each held DOF's reaction in its unit (round-off shown as 0), then the
    sign convention of the reactions."""
    lines = s.summary().splitlines()
    print("\n".join(lines[:len(lines) - len(s.held)]))  # the held DOFs' lines below, round-off shown as 0
    for name, why in s.held.items():
        unit = "N m" if name.startswith("tilt") else "N"
        print(f"{name} held ({why}); reaction {format_value(s.reactions.get(name, 0.0), unit)} {unit}")
    print_reaction_convention(s.held)


def loss_line(losses, s) -> str:
    """The line of the total power loss [W], its components [W] and the friction torque [N m] of a
    losses dict (solvers/quasistatic/losses.py: ``power_loss``, ``power_loss_total``,
    ``friction_torque_total``)."""
    pl = losses["power_loss"]
    return (f"power loss {losses['power_loss_total']:.4g} W (" + ", ".join(f"{k} {pl[k]:.4g}" for k in LOSS_COMPONENTS)
            + f" W), friction torque {losses['friction_torque_total']:.4g} N m" + _still(s))


def _still(s) -> str:
    """What the friction torque is without relative speed of the rings (solvers/quasistatic/losses.py)."""
    if s.omega != s.omega_outer:
        return ""
    return " (no relative speed of the rings: nothing rolls or slides, every loss and the torque are 0)"


def _nonneg_zero(x, half_digit=0.00005):
    """``x`` with a value that prints as zero at the column's digits (below ``half_digit`` in size) given as
    +0.0, so that round-off prints no "-0.00"."""
    return 0.0 if abs(x) < half_digit else x


#: Columns of the ball table: (header, width, unit) and the value of ball j.
_COLUMNS = (
    ("psi", "deg", 6, lambda bl, j: f"{math.degrees(bl['psi'][j]):.1f}"),
    ("Q_in", "N", 8, lambda bl, j: f"{bl['q_inner'][j]:.1f}"),
    ("Q_out", "N", 8, lambda bl, j: f"{bl['q_outer'][j]:.1f}"),
    ("alpha_in", "deg", 8, lambda bl, j: f"{_nonneg_zero(math.degrees(bl['alpha_inner'][j]), 0.005):.2f}"),
    ("alpha_out", "deg", 9, lambda bl, j: f"{_nonneg_zero(math.degrees(bl['alpha_outer'][j]), 0.005):.2f}"),
    ("pmax_in", "GPa", 7, lambda bl, j: f"{bl['p_max_inner'][j] / 1e9:.3f}"),
    ("pmax_out", "GPa", 8, lambda bl, j: f"{bl['p_max_outer'][j] / 1e9:.3f}"),
    ("w_orbit", "rad/s", 8, lambda bl, j: f"{bl['orbital_speed'][j]:.2f}"),
    ("w_ball", "rad/s", 8, lambda bl, j: f"{bl['ball_speed'][j]:.2f}"),
    ("beta", "deg", 6, lambda bl, j: f"{_nonneg_zero(math.degrees(bl['beta'][j]), 0.005):.2f}"),
    ("spin_in", "-", 7, lambda bl, j: f"{_nonneg_zero(bl['spin_roll_inner'][j]):.4f}"),
    ("spin_out", "-", 8, lambda bl, j: f"{_nonneg_zero(bl['spin_roll_outer'][j]):.4f}"),
    ("P_in", "W", 8, lambda bl, j: f"{bl['dissipation_inner_ball'][j]:.3g}"),
    ("P_out", "W", 8, lambda bl, j: f"{bl['dissipation_outer_ball'][j]:.3g}"),
)


def print_ball_table(bl):
    """Per-ball table with a unit line under the header (w_orbit: orbital speed, w_ball: ball speed about its
    own spin axis relative to the orbit frame, spin: spin-to-roll ratio, P: dissipation)."""
    print(f"{'ball':>4} " + " ".join(f"{h:>{w}}" for h, _u, w, _f in _COLUMNS))
    print(f"{'':>4} " + " ".join(f"{'[' + u + ']':>{w}}" for _h, u, w, _f in _COLUMNS))
    for j in range(len(bl["psi"])):
        print(f"{j:>4} " + " ".join(f"{f(bl, j):>{w}}" for _h, _u, w, f in _COLUMNS))
    print("w_ball: the ball's spin about its own axis in the frame orbiting with the ball (the dynamic summaries' "
          "ball_spin is taken in the fixed frame: w_ball - w_orbit for a radial bearing); spin_in, spin_out: the "
          "spin-to-roll ratio at the contact (spin about its normal over the rolling speed), not the "
          "slide-to-roll ratio (--json: the slip across each ellipse, slip_inner, slip_outer [m/s] at the strips of "
          "slip_y, and the rolling speeds u_roll_inner, u_roll_outer)")
