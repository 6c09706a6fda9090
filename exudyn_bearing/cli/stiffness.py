"""``stiffness BEARING``: linearised stiffness and damping (5x5) at an
operating point from the quasi-static solver, or a table over speeds.

One speed (``--omega`` or ``--rpm``; default 0): ``--json`` prints
``stiffness`` and ``damping`` (5x5, order x, y, axial, tilt x, tilt y),
``axes``, ``units`` (per entry), the operating point (``bearing``, loads,
``omega``, ``rpm``, ``diametral_clearance``, ``displacement``), the
contacts' normal damping, ``phases`` (ball-set positions averaged, default
3 as ``bearing_coefficients``) and ``phase_spread_stiffness`` /
``phase_spread_damping`` (largest spread over them relative to the largest
entry; None with ``--phases 1``). Several speeds (``--speeds`` in rad/s or ``--rpms``):
``speeds`` and ``stiffness``, ``damping`` per speed (the
:class:`~exudyn_bearing.model.coefficients.BearingCoefficients` dict);
``--plot`` draws the lateral and axial entries against speed (PNG + CSV).
"""
from __future__ import annotations

import json
import math

import numpy as np

from ..data import InputError
from ..model.coefficients import AXES, DAMPING_UNITS, STIFFNESS_UNITS
from ..outputs.jsonio import to_jsonable
from ..outputs.plotting import save_figure
from ..solvers.quasistatic import bearing_coefficients, solve_quasistatic
from ..solvers.quasistatic.coefficients import DEFAULT_N_PHASES
from ..solvers.quasistatic.kinematics import CONTROLS
from .common import (CONTROL_HELP, add_bearing_argument, add_hold_arguments, add_lubricant_argument, add_load_arguments,
                     add_ring_growth_argument, add_traction_argument, bearing_from_args, explained, finite_float,
                     fixed_from_args, lubricant_from_args, omega_from_args, solver_header, traction_from_args)
from .pair import add_pair_arguments, pair_requested, run_pair

RPM = 2.0 * math.pi / 60.0


def add_parser(sub):
    p = sub.add_parser("stiffness", help="linearised 5x5 stiffness and damping of a bearing at an operating point "
                                         "(quasi-static solver), or a table over speeds")
    add_bearing_argument(p)
    add_load_arguments(p)
    speed = p.add_mutually_exclusive_group()
    speed.add_argument("--omega", type=finite_float, help="inner-ring speed [rad/s] (default 0)")
    speed.add_argument("--rpm", type=finite_float, help="inner-ring speed [1/min]")
    speed.add_argument("--speeds", type=finite_float, nargs="+", metavar="W",
                       help="table over these speeds [rad/s] (increasing)")
    speed.add_argument("--rpms", type=finite_float, nargs="+", metavar="N",
                       help="table over these speeds [1/min] (increasing)")
    p.set_defaults(omega_default=0.0)  # omega_from_args: at rest without a speed (docs/defaults.md)
    p.add_argument("--phases", type=int, default=DEFAULT_N_PHASES,
                   help="average over this many ball-set positions within one ball pitch (default "
                        f"{DEFAULT_N_PHASES}, as bearing_coefficients; 1: the balls at psi = 2 pi j / Z only)")
    p.add_argument("--control", choices=CONTROLS, default="auto",
                   help=CONTROL_HELP)
    add_traction_argument(p)
    add_lubricant_argument(p)
    add_ring_growth_argument(p)
    add_hold_arguments(p)
    p.add_argument("--plot", metavar="FILE.png", help="with a table: entries against speed (+ CSV beside)")
    p.add_argument("--json", action="store_true", help="print JSON")
    add_pair_arguments(p)  # --arrangement, --preload, --spacing (cli/pair.py)


def _units():
    return {"stiffness": [list(r) for r in STIFFNESS_UNITS], "damping": [list(r) for r in DAMPING_UNITS],
            "omega": "rad/s", "rpm": "1/min", "loads": "N, N m", "diametral_clearance": "m",
            "displacement": "m, m, m, rad, rad (delta_x, delta_y, delta_a, tilt_x, tilt_y)",
            "c_normal_inner": "N s/m", "c_normal_outer": "N s/m", "speeds": "rad/s",
            "phase_spread_stiffness": "-", "phase_spread_damping": "-"}


def _print_matrix(name, m, units):
    print(f"{name} (rows: force/moment on the shaft; columns: {', '.join(AXES)})")
    for i, row in enumerate(m):
        print("  " + " ".join(f"{v:12.5g}" for v in row) + "   [" + ", ".join(units[i]) + "]")


def _plot(c, png):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rpm = c.rpm()
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    cols = {"speed_rad_s": c.speeds, "speed_rpm": rpm}
    for name, (i, j) in (("xx", (0, 0)), ("yy", (1, 1)), ("xy", (0, 1)), ("yx", (1, 0)), ("zz", (2, 2))):
        ax[0].plot(rpm, c.stiffness[:, i, j], label=f"k_{name}")
        ax[1].plot(rpm, c.damping[:, i, j], label=f"c_{name}")
        cols[f"k_{name}_N_per_m"] = c.stiffness[:, i, j]
        cols[f"c_{name}_Ns_per_m"] = c.damping[:, i, j]
    ax[0].set_ylabel("stiffness [N/m]")
    ax[1].set_ylabel("damping [N s/m]")
    for a in ax:
        a.set_xlabel("shaft speed [rpm]")
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    op = c.operating_point
    fig.suptitle(f"{op['bearing']}: Fr = {op['Fr']:g} N, Fa = {op['Fa']:g} N, P_d = "
                 f"{op['diametral_clearance'] * 1e6:g} um", fontsize=10)
    return save_figure(fig, png, cols)


def run(args):
    from .static import warn_speed

    if pair_requested(args):  # a bearing pair (cli/pair.py)
        return run_pair(args, "stiffness", warn_speed=warn_speed, print_matrix=_print_matrix)
    if not 1 <= args.phases <= 64:
        raise InputError(f"--phases: expected an integer in [1, 64], got {args.phases}")
    if args.plot and args.speeds is None and args.rpms is None:
        raise InputError("--plot: draws a table over speeds; give --speeds or --rpms")
    b = bearing_from_args(args)
    if args.Pd is not None:
        b = b.with_clearance(args.Pd, name="Pd")
    lub, traction = lubricant_from_args(args, b), traction_from_args(args, b)
    # the stiffness does not depend on the balls' inertia along the orbit (kinematics and losses,
    # solvers/quasistatic/inertia.py): the command that prints them, quasistatic, checks it
    opts = dict(control=args.control, traction=traction, lubricant=lub, ring_growth=args.ring_growth,
                fixed=fixed_from_args(args), inertia_check=False)
    loads = dict(Fr=args.Fr, Fa=args.Fa, Mx=args.Mx, My=args.My, Fy=args.Fy)
    header = solver_header(lub, traction, args.ring_growth)
    if args.speeds is not None or args.rpms is not None:
        speeds = np.array(args.speeds) if args.speeds is not None else np.array(args.rpms) * RPM
        with explained(b):
            c = bearing_coefficients(b, speeds, n_phases=args.phases, **loads, **opts)
        warn_speed(b, float(np.max(np.abs(speeds))))  # the limiting-speed check (physics/rating_life.py)
        d = c.to_dict()
        d["rpm"] = c.rpm().tolist()
        d["units"]["rpm"] = "1/min"
        d.update(lubricant=lub.name, traction=traction, ring_growth=args.ring_growth, tilt=args.tilt)
        if args.plot:
            d["plot"] = str(_plot(c, args.plot))
        if args.json:
            print(json.dumps(to_jsonable(d), indent=2))
            return
        print(f"{b.name}: Fr = {args.Fr:g} N, Fa = {args.Fa:g} N, P_d = {b.diametral_clearance * 1e6:g} um, "
              f"{args.phases} ball-set phase(s)" + (f" (spread of K up to "
                                                    f"{100 * max(c.operating_point['phase_spread_stiffness']):.3g} %)"
                                                    if args.phases > 1 else "") + f"; {header}")
        print(f"{'rpm':>9} {'k_xx N/m':>11} {'k_yy N/m':>11} {'k_xy N/m':>11} {'k_zz N/m':>11} "
              f"{'c_xx Ns/m':>10} {'c_yy Ns/m':>10} {'c_zz Ns/m':>10}")
        for i, r in enumerate(c.rpm()):
            k, cm = c.stiffness[i], c.damping[i]
            print(f"{r:9.1f} {k[0, 0]:11.4g} {k[1, 1]:11.4g} {k[0, 1]:11.4g} {k[2, 2]:11.4g} "
                  f"{cm[0, 0]:10.4g} {cm[1, 1]:10.4g} {cm[2, 2]:10.4g}")
        if args.plot:
            print(f"plot: {d['plot']}")
        return
    omega = omega_from_args(args)
    with explained(b):
        if args.phases != 1:
            c = bearing_coefficients(b, [omega], n_phases=args.phases, **loads, **opts)
            kmat, cmat = c.stiffness[0], c.damping[0]
        else:
            c = None
        s = solve_quasistatic(b, omega=omega, **loads, **opts)
    warn_speed(b, omega)  # the limiting-speed check (physics/rating_life.py), after the solve
    if c is None:
        kmat, cmat = s.stiffness, s.damping
    kmat, cmat = np.asarray(kmat) + 0.0, np.asarray(cmat) + 0.0   # no signed zeros in the output
    d = {"bearing": b.name, "loads": {"Fr": args.Fr, "Fy": args.Fy, "Fa": args.Fa, "Mx": args.Mx, "My": args.My},
         "omega": omega, "rpm": omega / RPM, "diametral_clearance": b.diametral_clearance, "phases": args.phases,
         "phase_spread_stiffness": c.operating_point["phase_spread_stiffness"][0] if c else None,
         "phase_spread_damping": c.operating_point["phase_spread_damping"][0] if c else None,
         "control": args.control, "traction": s.traction, "lubricant": s.lubricant,
         "ring_growth": args.ring_growth, "tilt": args.tilt, "axes": list(AXES), "stiffness": kmat, "damping": cmat,
         "displacement": s.displacement, "held_dofs": dict(s.held),
         "c_normal_inner": s.balls["c_normal_inner"], "c_normal_outer": s.balls["c_normal_outer"],
         "stiffness_check": s.stiffness_check, "units": _units()}
    if args.json:
        print(json.dumps(to_jsonable(d), indent=2))
        return
    print(f"{b.name}: Fr = {args.Fr:g} N, Fa = {args.Fa:g} N, omega = {omega:g} rad/s ({omega / RPM:g} rpm), "
          f"P_d = {b.diametral_clearance * 1e6:g} um" + (f", mean of {args.phases} ball-set phases (spread of K "
                                                          f"{100 * d['phase_spread_stiffness']:.3g} %)" if c else
                                                          ", one ball-set phase"))
    print(header)
    _print_matrix("stiffness K = -dF/dq", kmat, STIFFNESS_UNITS)
    _print_matrix("damping C = -dF/dq'", cmat, DAMPING_UNITS)
