"""``--arrangement DB|DF|DT``: a pair of identical angular-contact bearings on one shaft in ``static``,
``quasistatic`` and ``stiffness`` (:func:`exudyn_bearing.solvers.quasistatic.pair.solve_pair`,
docs/theory/pairs.md). Each command adds :func:`add_pair_arguments` and, in ``run``, hands a pair to
:func:`run_pair`. The JSON has ``bearings``, one entry per bearing with its own loads (``Fr``, ``Fa``) and
results, the pair's ``stiffness`` and shaft displacement, and (static, quasistatic) each bearing's load
ratings and rating lives with the pair's ``system_life``."""
from __future__ import annotations

import json
import warnings

import numpy as np

from ..data import InputError
from ..data.errors import check_unused
from ..outputs.jsonio import to_jsonable
from .common import finite_float

ARRANGEMENTS = ("DB", "DF", "DT")
PRELOAD_CLASSES = ("light", "medium", "heavy")


def add_pair_arguments(p):
    """The argument group of a bearing pair."""
    g = p.add_argument_group("bearing pair", "two identical angular-contact bearings on one shaft, loads at the "
                                             "pair's centre (docs/theory/pairs.md)")
    g.add_argument("--arrangement", choices=ARRANGEMENTS,
                   help="DB back-to-back, DF face-to-face, DT tandem (default: one bearing)")
    pre = g.add_mutually_exclusive_group()
    pre.add_argument("--preload", type=finite_float, metavar="N", help="DB / DF: axial preload per bearing at rest [N]")
    pre.add_argument("--preload-displacement", type=finite_float, metavar="M",
                     help="DB / DF: axial interference of the set at rest [m] (both bearings' deflections)")
    pre.add_argument("--preload-class", choices=PRELOAD_CLASSES,
                     help="manufacturer's preload class: refused, no cited values are held (give --preload)")
    g.add_argument("--spacing", type=finite_float, metavar="M",
                   help="distance between the two ball-set planes [m] (adjacent pair: the bearing width); "
                        "without it the shaft's tilt is held and the pair has no tilt stiffness")


def pair_requested(args) -> bool:
    """Whether the command solves a pair; the pair's options without ``--arrangement`` are refused."""
    if args.arrangement is not None:
        return True
    check_unused("--arrangement", False, (("--preload", args.preload, None),
                                          ("--preload-displacement", args.preload_displacement, None),
                                          ("--preload-class", args.preload_class, None),
                                          ("--spacing", args.spacing, None)), "add --arrangement DB|DF|DT")
    return False


def _preload(args):
    if args.preload is not None:
        return args.preload
    if args.preload_displacement is not None:
        return ("displacement", args.preload_displacement)
    return args.preload_class


def _named(exc, args) -> InputError:
    """A solver's message in the command line's words (preload_displacement -> --preload-displacement)."""
    msg = str(exc)
    preload = "--preload-class:" if args.preload_class is not None else "--preload:"
    for api, cli in (("preload_displacement:", "--preload-displacement:"), ("preload:", preload),
                     ("spacing:", "--spacing:"), ("arrangement:", "--arrangement:")):
        if msg.startswith(api):
            return InputError(cli + msg[len(api):])
    return InputError(msg)


def _phase_mean_stiffness(b, args, p, omega, loads, common, opts):
    """(phases, spread, K): the pair's stiffness averaged over ``args.phases`` ball-set positions within one ball
    pitch (the first is ``p``'s; solvers.quasistatic.coefficients' rule and spread: largest range of an entry
    over the positions relative to the largest entry); the spread None with one position."""
    from ..solvers.quasistatic.pair import solve_pair

    n = args.phases
    if not 1 <= n <= 64:
        raise InputError(f"--phases: expected an integer in [1, 64], got {n}")
    if n == 1:
        return 1, None, p.stiffness
    ks = [np.asarray(p.stiffness, float)]
    for m in range(1, n):
        try:
            q = solve_pair(b, args.arrangement, omega=omega, phase=2.0 * np.pi / b.n_balls * m / n, **loads,
                           **common, **opts)
        except InputError as exc:
            raise _named(exc, args) from None
        ks.append(np.asarray(q.stiffness, float))
    ks = np.array(ks)
    finite = np.isfinite(ks).all(axis=0)  # NaN where a DOF is held (no spacing)
    scale = max(float(np.abs(ks[0][finite]).max()) if finite.any() else 0.0, 1e-300)
    spread = float(np.ptp(np.where(finite, ks, 0.0), axis=0).max() / scale)
    return n, spread, ks.mean(axis=0)


def run_pair(args, command, rating=None, warn_speed=None, print_matrix=None):
    """``static``, ``quasistatic`` or ``stiffness`` of a pair: solve, print JSON or text. The command hands
    over its own pieces (no import back into the commands): ``rating`` the keyword arguments of rating_life
    (static, quasistatic), ``warn_speed(bearing, omega)`` the limiting-speed check, ``print_matrix`` the
    stiffness command's matrix printer."""
    from ..solvers.quasistatic.pair import solve_pair
    from .common import (
        bearing_from_args,
        fixed_from_args,
        lubricant_from_args,
        traction_from_args,
    )

    b = bearing_from_args(args)
    if getattr(args, "Pd", None) is not None:
        b = b.with_clearance(args.Pd, name="Pd")
    loads = {"Fr": args.Fr, "Fa": args.Fa, "Mx": args.Mx, "My": args.My, "Fy": getattr(args, "Fy", 0.0)}
    common = {"preload": _preload(args), "spacing": args.spacing, "fixed": fixed_from_args(args)}
    rating_opts = dict(rating) if rating is not None else None
    if command == "static":
        from .common import omega_from_args

        omega = omega_from_args(args)  # the speed of the rating's hours and kappa only (zero-speed solve)
        opts = {"ring_growth": False, "hertz_method": args.hertz, "phase": args.phase}
        if omega is None:
            rating_opts.pop("temperature", None)
        solve_omega = 0.0
    elif command == "quasistatic":
        import math

        if args.thermal:
            raise InputError("--thermal: not available for a pair (--arrangement); solve each bearing with its "
                             "thermal network")
        omega = args.omega if args.omega is not None else (args.rpm * math.pi / 30.0 if args.rpm is not None
                                                           else 0.0)
        temps = dict(zip(("inner", "outer", "ball"), args.temperature)) if args.temperature else None
        opts = {"omega_outer": args.omega_outer, "control": args.control, "traction": traction_from_args(args, b),
                    "lubricant": lubricant_from_args(args, b), "ring_growth": args.ring_growth, "fit": args.fit,
                    "temperatures": temps, "hertz_method": args.hertz, "n_strips": args.strips, "n_across": args.points_across}
        solve_omega = omega
    else:
        if args.speeds is not None or args.rpms is not None:
            raise InputError("--arrangement: a pair's stiffness at one speed only (--omega or --rpm), not a table "
                             "over --speeds / --rpms")
        from .common import RPM_TO_RAD_S

        omega = args.omega if args.omega is not None else (args.rpm * RPM_TO_RAD_S if args.rpm is not None
                                                           else 0.0)
        opts = {"control": args.control, "traction": traction_from_args(args, b),
                    "lubricant": lubricant_from_args(args, b), "ring_growth": args.ring_growth}
        solve_omega = omega
    try:
        p = solve_pair(b, args.arrangement, omega=solve_omega, **loads, **common, **opts)
        rating = None
        if rating_opts is not None:
            ref = None
            if solve_omega != 0.0:  # ISO/TS 16281's distributions at rest beside those at speed
                rest = {k: v for k, v in opts.items() if k not in ("omega_outer", "control", "traction", "n_strips",
                                                                  "n_across", "ring_growth")}
                try:
                    ref = solve_pair(b, args.arrangement, **loads, **common, **rest, stiffness=False)
                except InputError:
                    ref = None
            from ..physics.rating_life import RatingLifeWarning

            with warnings.catch_warnings():
                warnings.simplefilter("ignore", RatingLifeWarning)  # each bearing's rating_warnings in the JSON
                rating = p.rating(reference=ref, omega=omega, **rating_opts)
    except InputError as exc:
        raise _named(exc, args) from None
    if warn_speed is not None and omega:
        warn_speed(b, omega)  # after the solve: a refusal stays the one line on stderr
    d = p.to_dict(rating=rating)
    kmat = p.stiffness
    if command == "stiffness":  # the pair's stiffness averaged over --phases ball-set positions, as one bearing's
        d["phases"], d["phase_spread_stiffness"], kmat = _phase_mean_stiffness(b, args, p, solve_omega, loads,
                                                                               common, opts)
        d["stiffness"] = kmat
    d["command"] = command
    d["tilt"] = args.tilt
    if args.json:
        print(json.dumps(to_jsonable(d), indent=2))
        return
    print(p.summary())
    if rating is not None:
        life = rating[1]
        print("rating: " + ", ".join(f"bearing {k} L10 {r.L10:.4g}" if r.L10 is not None else f"bearing {k} L10 -"
                                     for k, r in enumerate(rating[0]))
              + (f"; system L10 {life['L10']:.4g} (10^6 rev)" if life.get("L10") is not None else ""))
    if print_matrix is not None:
        from ..model.coefficients import STIFFNESS_UNITS

        spread = d.get("phase_spread_stiffness")
        print_matrix("pair stiffness K = -dF/dq (shaft at the pair's centre" + (
            f"; mean of {d['phases']} ball-set phases, spread {100 * spread:.3g} %)" if spread is not None else ")"),
            np.asarray(kmat) + 0.0, STIFFNESS_UNITS)

