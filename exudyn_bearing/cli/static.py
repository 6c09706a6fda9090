"""``static BEARING --Fr N``: the zero-speed special case of ``quasistatic`` (load distribution,
inner-ring displacement and tilt) with the lubrication map at a given speed."""
from __future__ import annotations

import json
import math
import sys
import warnings

import numpy as np

from ..data import InputError, load_lubricant
from ..model.load_range import check_load_range
from ..outputs.jsonio import to_jsonable
from ..outputs.plotting import plot_static
from ..outputs.units import REGIME_CODES, STATIC_UNITS, with_units
from ..physics.hertz import METHODS
from ..physics.load_distribution import StaticSolution, load_zone_parameter
from ..physics.rating_life import RATING_UNITS, RatingLifeWarning, check_speed_limit, rating_life
from ..solvers.analytic import stribeck_and_lubrication
from ..solvers.quasistatic import solve_quasistatic
from ..solvers.quasistatic.solve import axial_load_as_fa
from .common import (add_bearing_argument, add_hold_arguments, add_lubricant_argument, add_speed_arguments,
                     bearing_from_args, explained, finite_float, fixed_from_args, format_value, lubricant_from_args,
                     omega_from_args)
from .pair import add_pair_arguments, pair_requested, run_pair

HELP = ("zero-speed special case of 'quasistatic': 5-DOF inner-ring equilibrium without centrifugal or "
        "gyroscopic loads, rigid rings; the tilt is held at zero unless --tilt free (its reaction moment is "
        "printed); --omega only sets the speed of the lubrication map")


#: The sign convention of the reactions of held DOFs (solvers/quasistatic/solve.py: reaction = -residual).
REACTION_CONVENTION = ("reaction sign: the force [N] or moment [N m] the constraint applies to the inner ring, "
                       "positive along +x, +y, +z (axial) and about +x, +y; applied loads + ball forces + reaction = 0")


def add_rating_arguments(p, temperature=False):
    """``--reliability``, ``--contamination`` (and, for ``static``, ``--temperature``) of the rating life
    (:func:`exudyn_bearing.physics.rating_life.rating_life`)."""
    from ..data.iso281 import CONTAMINATION
    from ..physics.rating_life import DEFAULT_CONTAMINATION, DEFAULT_RELIABILITY

    p.add_argument("--reliability", type=finite_float, default=DEFAULT_RELIABILITY,
                   help="reliability of the rating life [%%], 90 to 99.95 (ISO 281 a_1)")
    p.add_argument("--contamination", default=DEFAULT_CONTAMINATION,
                   help=f"ISO 281 Table 13 contamination class ({', '.join(CONTAMINATION)}) or e_C in [0, 1]")
    if temperature:
        p.add_argument("--temperature", type=finite_float, metavar="K",
                       help="lubricant temperature [K] for kappa of the modified rating life (default: the "
                            "temperature at which the lubricant has the viscosity the films use)")


def rating_options(args) -> dict:
    """Keyword arguments of rating_life from the options of :func:`add_rating_arguments`."""
    c = args.contamination
    try:
        c = float(c)
    except ValueError:
        pass
    out = {"reliability": args.reliability, "contamination": c}
    t = getattr(args, "temperature", None)
    if isinstance(t, float):
        out["temperature"] = t
    return out


def warn_speed(b, omega, omega_outer=0.0):
    """The limiting-speed check (:func:`~exudyn_bearing.physics.rating_life.check_speed_limit`) as a warning
    line on stderr."""
    for m in check_speed_limit(b, omega, omega_outer, warn=False):
        print(f"exudyn-bearing: warning: {m}", file=sys.stderr)


def print_reaction_convention(held):
    """The sign convention of the reactions, once, when a DOF is held."""
    if held:
        print(REACTION_CONVENTION)


def add_parser(sub):
    p = sub.add_parser("static", help="load distribution and lubrication map (zero-speed quasi-static)",
                       description=HELP)
    add_bearing_argument(p)
    p.add_argument("--Fr", type=finite_float, default=0.0, help="radial load [N] on the inner ring (default 0)")
    p.add_argument("--Fa", type=finite_float, default=0.0, help="axial load [N] on the inner ring")
    p.add_argument("--Mx", type=finite_float, default=0.0, help="moment [N m] about x (needs --tilt free)")
    p.add_argument("--My", type=finite_float, default=0.0, help="moment [N m] about y (needs --tilt free)")
    add_hold_arguments(p)
    p.add_argument("--Pd", type=finite_float, help="diametral clearance [m] (negative: preload, e.g. -12.6e-6); "
                                                    "default: the bearing's own")
    add_speed_arguments(p, what="none: no lubrication map; the speed sets the lubrication map only")
    add_lubricant_argument(p)
    p.add_argument("--film", choices=("hd", "mk"), default="hd",
                   help="film model: Hamrock-Dowson or Masjedi-Khonsari reading")
    p.add_argument("--hertz", choices=METHODS, default="exact", help="Hertz fidelity level")
    p.add_argument("--phase", type=finite_float, default=0.0, help="azimuth of ball 0 [rad], taken modulo 2 pi")
    add_rating_arguments(p, temperature=True)
    p.add_argument("--plot", metavar="FILE.png", help="save Q(psi) and Lambda(psi) plot (+ CSV beside)")
    p.add_argument("--json", action="store_true", help="print JSON (with units and regime_codes) instead of a table")
    add_pair_arguments(p)  # --arrangement, --preload, --spacing (cli/pair.py)


def static_result(b, fr, fa, mx=0.0, my=0.0, tilt="fixed", omega=None, film="hd", hertz="exact", phase=0.0,
                  lubricant=None, fixed=None, rating=None):
    """The dict of ``static`` (keys of :func:`exudyn_bearing.solvers.analytic.static_analysis`, plus the
    tilt, the held DOFs and their reactions). ``fixed``: held DOFs (default: the tilts at zero with
    ``tilt="fixed"``). ``phase`` is taken modulo 2 pi; loads beyond the elastic contact model
    (:mod:`exudyn_bearing.model.load_range`) raise InputError. ``rating``: keyword arguments of
    :func:`exudyn_bearing.physics.rating_life.rating_life` (reliability, contamination, temperature); with it
    the dict carries the load ratings and rating lives (keys of ``RATING_UNITS``; hours, kappa and the modified
    lives need ``omega``, the speed of the rating)."""
    for name, v in (("Fr", fr), ("Fa", fa)):
        if v < 0.0:
            raise InputError(f"{name}: must be >= 0 (the bearing carries +x radial and +z axial load on the "
                             f"inner ring), got {v}")
    if fixed is None:
        fixed = {"tilt_x": 0.0, "tilt_y": 0.0} if tilt == "fixed" else {}
    for moment, t in (("Mx", "tilt_x"), ("My", "tilt_y")):
        if (mx if moment == "Mx" else my) != 0.0 and t in fixed:
            raise InputError(f"{moment}: a moment load needs the free tilt (--tilt free)")
    phase = math.remainder(phase, 2.0 * math.pi)  # the same balls; a huge phase loses their spacing in cos/sin
    names = ("Fr", "Fa", "Pd")  # the options the user gives (--Fr, --Fa, --Pd)
    translating = set(fixed) <= {"tilt_x", "tilt_y"}  # the classical distribution: only the tilts held
    if translating:
        with axial_load_as_fa():  # before the solve: far-off loads do not converge
            check_load_range(b, fr, fa, hertz, names=names, phase=phase)
    s = solve_quasistatic(b, fr, fa, mx, my, omega=0.0, fixed=fixed, hertz_method=hertz, phase=phase,
                          stiffness=False)
    bl = s.balls
    q = bl["q_inner"]
    u = s.displacement
    a0 = float(bl["alpha_inner"][int(np.argmax(q))]) if q.max() > 0 else b.free_contact_angle
    pd = b.diametral_clearance
    eps = float(load_zone_parameter(u[0], pd, u[2], a0)) if u[0] > 0 else (
        math.inf if (u[2] > 0 or pd < 0) else 0.0)
    sol = StaticSolution(b, fr, fa, bl["psi"], q, bl["delta_inner"] + bl["delta_outer"], bl["delta_inner"],
                         bl["delta_outer"], bl["alpha_inner"], u[:3].copy(), float(u[0]), float(u[2]), eps,
                         hertz_method=hertz,
                         reaction_moment=np.array([s.reactions.get("tilt_x", 0.0), s.reactions.get("tilt_y", 0.0)]))
    if mx != 0.0 or my != 0.0 or not translating:
        check_load_range(b, fr, fa, hertz, names=names, solution=sol)
    res = {"bearing": b.name, "model": "zero-speed quasi-static (quasistatic at omega = 0, rigid rings)",
           "Fr": fr, "Fa": fa, "Mx": mx, "My": my, "Pd": pd, "hertz_method": hertz, "phase": phase, "psi": sol.psi,
           "q": q,
           "q_max": sol.q_max, "overlap": sol.overlap, "overlap_inner": sol.overlap_inner,
           "overlap_outer": sol.overlap_outer, "contact_angle": sol.contact_angle, "displacement": u[:3],
           "delta_r": sol.delta_r, "delta_a": sol.delta_a, "tilt_x": float(u[3]), "tilt_y": float(u[4]),
           "eps": eps, "tilt": tilt, "held_dofs": dict(s.held), "reactions": dict(s.reactions),
           "reaction_moment": sol.reaction_moment}
    lub = load_lubricant(lubricant, bearing=b)
    res["lubricant"] = lub.name
    res["traction"] = None  # zero speed: no slip, no traction model
    res.update(stribeck_and_lubrication(sol, omega, film, lub, stribeck=translating and fixed == {"tilt_x": 0.0,
                                                                                                  "tilt_y": 0.0}))
    if rating is not None:
        res.update(rating_life(b, s, omega, lubricant=lubricant, **rating).to_dict())
    return res


def run(args):
    if pair_requested(args):  # a bearing pair (cli/pair.py)
        return run_pair(args, "static", rating=rating_options(args), warn_speed=warn_speed)
    b = bearing_from_args(args)
    if args.Pd is not None:
        b = b.with_clearance(args.Pd, name="Pd")
    omega = omega_from_args(args)
    if omega is None and args.temperature is not None:
        raise InputError("--temperature: sets the lubricant temperature of kappa, which needs a speed; add --omega "
                         "or --rpm (or leave --temperature out)")
    with explained(b), warnings.catch_warnings():
        warnings.simplefilter("ignore", RatingLifeWarning)  # printed below (rating_warnings)
        res = static_result(b, args.Fr, args.Fa, args.Mx, args.My, args.tilt, omega, args.film, args.hertz,
                            args.phase, lubricant_from_args(args, b), fixed_from_args(args),
                            rating=rating_options(args))
    if omega is not None:
        warn_speed(b, omega)  # after the solve: a refusal stays the one line on stderr
    if args.plot:
        png, csv = plot_static(res, args.plot)
        res["plot"] = str(png)
        res["data"] = str(csv)
    if args.json:
        out = with_units(res, {**STATIC_UNITS, **RATING_UNITS})
        if omega is not None:
            out["regime_codes"] = REGIME_CODES
        print(json.dumps(to_jsonable(out), indent=2))
        return
    print(f"{b.name}: Fr = {res['Fr']:g} N, Fa = {res['Fa']:g} N, Pd = {res['Pd'] * 1e6:.2f} um, "
          f"Hertz {res['hertz_method']} (zero-speed quasi-static, tilt {args.tilt})"
          + (f", omega = {omega:g} rad/s" if omega is not None else ""))
    print(f"lubricant {res['lubricant']}" + (" (lubrication map)" if omega is not None else " (no speed: no "
                                               "lubrication map)") + ", no traction model (zero speed: no slip)")
    stribeck = (f"continuous Stribeck {res['q_max_stribeck']:.1f} N" if "q_max_stribeck" in res else
                "continuous Stribeck not applicable: " + ("tilt free" if args.tilt == "free" else "held DOFs"
                                                          if args.fix else "no continuous solution"))
    print(f"q_max = {res['q_max']:.1f} N ({stribeck}), "
          f"eps = {res['eps']:.4f}, delta_r = {res['delta_r'] * 1e6:.3f} um, "
          f"delta_a = {res['delta_a'] * 1e6:.3f} um, tilt_y = {res['tilt_y'] * 1e3:.4f} mrad")
    for name, why in res["held_dofs"].items():
        unit = "N m" if "tilt" in name else "N"
        print(f"{name} held ({why}): reaction {format_value(res['reactions'][name], unit, 4)} {unit}"
              + (" (--tilt free releases it)" if why == "fixed" and "tilt" in name else ""))
    print_reaction_convention(res["held_dofs"])
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
    print_rating(res)
    if args.plot:
        print(f"plot: {res['plot']}  data: {res['data']}")


def print_rating(d):
    """The load ratings and rating lives of a result dict (keys of RATING_UNITS) as text lines."""
    from ..physics.rating_life import RatingLife
    import dataclasses

    names = {f.name for f in dataclasses.fields(RatingLife)}
    print("\n".join(RatingLife(**{k: d[k] for k in names}).summary()))
