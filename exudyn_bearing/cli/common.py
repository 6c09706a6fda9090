"""Shared pieces of the sub-commands: the parser class, the options every
sub-command spells the same way (bearing, speed, lubricant), number parsing,
tables and the units of JSON output."""
from __future__ import annotations

import argparse
import math
import re
from contextlib import contextmanager

from ..data import InputError, catalog, default_traction, load_bearing, load_lubricant, lubricants, traction_models
from ..physics.contact_slip import DEFAULT_N_ACROSS, DEFAULT_N_STRIPS, MAX_N_ACROSS, MAX_N_STRIPS
from ..outputs.tables import format_table, format_value
from ..solvers.quasistatic.ring import DOF_NAMES

__all__ = ["Parser", "HelpFormatter", "finite_float", "print_table", "BEARING_HELP", "add_bearing_argument",
           "bearing_from_args", "bearing_spec_from_args", "add_load_arguments", "add_speed_arguments",
           "omega_from_args", "add_outer_speed_arguments", "omega_outer_from_args", "add_lubricant_argument", "lubricant_from_args", "RPM_TO_RAD_S", "add_traction_argument",
           "traction_from_args", "add_ring_growth_argument", "RING_GROWTH", "add_hold_arguments", "parse_fixed",
           "fixed_from_args", "explained", "solver_header", "format_value", "add_strip_arguments"]

#: Default of --ring-growth in every command that has a speed (quasistatic, stiffness, simulate), as in
#: Scenario and solve_quasistatic (README, "Defaults").
RING_GROWTH = True

#: Help text of a bearing argument.
BEARING_HELP = (f"catalogue name ({', '.join(catalog)}; or a series estimate such as 6310-ISO, 7208B-ISO: "
                "info --list) or a JSON file: one bearing (race radii as in "
                "catalog.json, or dimensions: n_balls, ball_diameter, pitch_diameter, inner_conformity, "
                "outer_conformity, ...) or a catalogue-shaped file (FILE.json#NAME picks a bearing)")

#: rev/min -> rad/s.
RPM_TO_RAD_S = 2.0 * math.pi / 60.0

#: Numbers argparse must read as values, not options: -5, -0.5, -.5, -12.6e-6, -1E3 (argparse's own
#: pattern misses the exponent, so "--Pd -12.6e-6" failed with "expected one argument").
_NEGATIVE_NUMBER = re.compile(r"^-(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?$")


#: Help of the quasi-static commands' --control (quasistatic, stiffness; simulate's quasi-static start says the
#: same for its start).
CONTROL_HELP = ("ball kinematics: race control (outer, inner, auto = Jones' criterion; the default), min-energy "
                "(Gupta), or equilibrium (each ball on its own traction balance, no kinematic hypothesis; what the "
                "dynamic engines settle to: docs/theory/quasistatic.md)")


def finite_float(text):
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None
    if not math.isfinite(v):
        raise argparse.ArgumentTypeError(f"must be finite, got {text!r}")
    return v


class HelpFormatter(argparse.ArgumentDefaultsHelpFormatter):
    """Shows every option's default ("(default: ...)") unless it has none
    (None, a flag's False) or its help text states it already."""

    def _get_help_string(self, action):
        text = action.help or ""
        if ("%(default)" in text or "default" in text or action.default is None or action.default is False
                or action.default is argparse.SUPPRESS):
            return text
        if action.option_strings or action.nargs in (argparse.OPTIONAL, argparse.ZERO_OR_MORE):
            return text + " (default: %(default)s)"
        return text


class Parser(argparse.ArgumentParser):
    """One-line errors (no usage dump), exit status 2; defaults shown in
    --help; negative numbers in any notation are values."""

    def __init__(self, *args, **kwargs):
        kwargs.setdefault("formatter_class", HelpFormatter)
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = _NEGATIVE_NUMBER

    def error(self, message):
        self.exit(2, f"exudyn-bearing: error: {message} (see --help)\n")


def add_bearing_argument(p, default: str | None = None):
    """The bearing as the positional BEARING. With a ``default`` (simulate)
    it may be left out, and ``--bearing BEARING`` is accepted as well (the
    older spelling of simulate); read it with :func:`bearing_from_args`."""
    if default is None:
        p.add_argument("bearing", metavar="BEARING", help=BEARING_HELP)
        return
    p.add_argument("bearing", metavar="BEARING", nargs="?", default=None,
                   help=f"{BEARING_HELP} (default: {default})")
    p.add_argument("--bearing", dest="bearing_option", metavar="BEARING",
                   help="the same as the positional BEARING (older spelling)")
    p.set_defaults(bearing_default=default)


def bearing_spec_from_args(args) -> str:
    """The bearing the arguments name (positional, --bearing or the default), as given."""
    given = [v for v in (args.bearing, getattr(args, "bearing_option", None)) if v is not None]
    if len(given) == 2 and given[0] != given[1]:
        raise InputError(f"bearing: given twice ({given[0]!r} and --bearing {given[1]!r})")
    return given[0] if given else args.bearing_default


def bearing_from_args(args):
    """The BallBearing the arguments name (positional, --bearing or the default)."""
    return load_bearing(bearing_spec_from_args(args))


def add_load_arguments(p):
    """Loads on the inner ring in five DOFs and the clearance (quasistatic, stiffness)."""
    p.add_argument("--Fr", type=finite_float, default=0.0, help="radial load [N] on the inner ring along +x")
    p.add_argument("--Fy", type=finite_float, default=0.0, help="radial load [N] along +y")
    p.add_argument("--Fa", type=finite_float, default=0.0, help="axial load [N] along +z")
    p.add_argument("--Mx", type=finite_float, default=0.0, help="moment [N m] about x")
    p.add_argument("--My", type=finite_float, default=0.0, help="moment [N m] about y")
    p.add_argument("--Pd", type=finite_float, help="diametral clearance [m] (negative: preload); default: the "
                                                   "bearing's")


def add_speed_arguments(p, default: float | None = None, what: str = ""):
    """``--omega RAD_S`` or ``--rpm RPM`` (one of them): the inner-ring speed (the outer ring's is
    ``--omega-outer`` where a command takes it); read it in rad/s with :func:`omega_from_args`."""
    g = p.add_mutually_exclusive_group()
    tail = f" (default: {default:g} rad/s)" if default is not None else (f" (default: {what})" if what else "")
    g.add_argument("--omega", type=finite_float, metavar="RAD_S",
                   help=f"inner-ring speed [rad/s] (the outer ring's: --omega-outer where the command takes it, "
                        f"else fixed){tail}")
    g.add_argument("--rpm", type=finite_float, metavar="RPM",
                   help="inner-ring speed [rev/min] instead of --omega (omega = rpm * 2 pi / 60)")
    p.set_defaults(omega_default=default)


def omega_from_args(args):
    """Inner-ring speed [rad/s] from --omega or --rpm (None when neither is given and there is no default)."""
    if args.rpm is not None:
        return args.rpm * RPM_TO_RAD_S
    return args.omega if args.omega is not None else args.omega_default


def add_outer_speed_arguments(p, what=""):
    """``--omega-outer RAD_S`` or ``--rpm-outer RPM`` (one of them, default 0: the outer ring fixed); read it in
    rad/s with :func:`omega_outer_from_args`. ``what``: a note for the help (the protocol it follows)."""
    g = p.add_mutually_exclusive_group()
    g.add_argument("--omega-outer", type=finite_float, default=0.0, metavar="RAD_S",
                   help=f"outer-ring speed [rad/s]{what} (default 0: fixed)")
    g.add_argument("--rpm-outer", type=finite_float, metavar="RPM",
                   help="outer-ring speed [rev/min] instead of --omega-outer")


def omega_outer_from_args(args) -> float:
    """Outer-ring speed [rad/s] from --omega-outer or --rpm-outer."""
    return args.omega_outer if args.rpm_outer is None else args.rpm_outer * RPM_TO_RAD_S


def _count_in(hi: int):
    """An argparse type: an integer in [1, hi]."""
    def parse(text):
        try:
            v = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected an integer, got {text!r}") from None
        if not 1 <= v <= hi:
            raise argparse.ArgumentTypeError(f"must be an integer in [1, {hi}], got {v}")
        return v
    return parse


def add_strip_arguments(p):
    """``--strips`` and ``--points-across`` of the traction integration over each contact ellipse, with the
    defaults and the ranges every solver shares (:data:`exudyn_bearing.physics.contact_slip.DEFAULT_N_STRIPS`,
    ``MAX_N_STRIPS``; quasistatic and simulate)."""
    p.add_argument("--strips", type=_count_in(MAX_N_STRIPS), default=DEFAULT_N_STRIPS,
                   help=f"strips along the major axis of each contact ellipse, 1-{MAX_N_STRIPS} (default "
                        f"{DEFAULT_N_STRIPS}; fewer than the dissipation's convergence needs: a warning)")
    p.add_argument("--points-across", type=_count_in(MAX_N_ACROSS), default=DEFAULT_N_ACROSS,
                   help=f"points across each strip, 1-{MAX_N_ACROSS} (default {DEFAULT_N_ACROSS}; 1: classical "
                        "strip theory)")


def add_lubricant_argument(p, what: str = ""):
    """``--lubricant NAME|FILE.json`` (default: the bearing's); read it with :func:`lubricant_from_args`."""
    p.add_argument("--lubricant", metavar="NAME|FILE.json", default=None,
                   help=f"{what}catalogue lubricant ({', '.join(lubricants)}) or a JSON file with the Lubricant "
                        "fields (or a catalogue-shaped file, FILE.json#NAME); default: the bearing's (catalogue: "
                        "ACBB-120 MIL-L-23699_492K, the others the DEM papers' guessasma2018)")


def lubricant_from_args(args, bearing=None):
    """The Lubricant of --lubricant, else the bearing's."""
    return load_lubricant(args.lubricant, bearing=bearing)


def add_traction_argument(p, what: str = "traction model"):
    """``--traction NAME`` (default: the bearing's); read it with :func:`traction_from_args`."""
    p.add_argument("--traction", default=None, metavar="NAME",
                   help=f"{what} ({', '.join(traction_models)}); default: the bearing's (catalogue: ACBB-120 "
                        "ehl_mil_l_23699_492K, the others the DEM papers' lambda_dem)")


def traction_from_args(args, bearing=None) -> str:
    """Name of the traction model of --traction, else the bearing's."""
    return args.traction if args.traction is not None else default_traction(bearing)


def add_ring_growth_argument(p):
    """``--ring-growth / --no-ring-growth`` with the default of every solver (:data:`RING_GROWTH`)."""
    p.add_argument("--ring-growth", action=argparse.BooleanOptionalAction, default=RING_GROWTH,
                   help="centrifugal growth of the rotating rings (default on, in every solver)")


def add_hold_arguments(p):
    """``--tilt fixed|free`` and ``--fix DOF=VALUE`` (static, quasistatic, stiffness); read them with
    :func:`fixed_from_args`."""
    p.add_argument("--tilt", choices=("fixed", "free"), default="fixed",
                   help="inner-ring tilt held at zero (the default of static, quasistatic and stiffness: the "
                        "classical load distribution and the dynamic engines' translating ring; the reaction moment "
                        "is reported), or free (moment loads need it)")
    p.add_argument("--fix", action="append", default=[], metavar="DOF=VALUE",
                   help=f"hold a DOF ({', '.join(DOF_NAMES)}) at a value [m or rad]; its reaction is reported "
                        "(e.g. --fix delta_a=0: a lone angular-contact bearing held axially, as in a pair)")


def parse_fixed(items) -> dict:
    """``["delta_a=0", ...]`` -> ``{"delta_a": 0.0}``; InputError naming ``fix`` (a DOF given twice too)."""
    fixed = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep:
            raise InputError(f"fix: expected DOF=VALUE, got {item!r}")
        try:
            v = float(value)
        except ValueError:
            raise InputError(f"fix {name.strip()}: expected a number, got {value!r}") from None
        if name.strip() in fixed:
            raise InputError(f"--fix {name.strip()}: given twice ({fixed[name.strip()]:g} and {v:g}); give each DOF "
                             "once")
        fixed[name.strip()] = v
    return fixed


def fixed_from_args(args) -> dict:
    """The held DOFs of ``--tilt`` and ``--fix`` (``--fix tilt_x=...`` overrides ``--tilt fixed``); a moment
    load about a held tilt raises InputError naming the moment."""
    fixed = {"tilt_x": 0.0, "tilt_y": 0.0} if args.tilt == "fixed" else {}
    fixed.update(parse_fixed(args.fix))
    for moment, tilt in (("Mx", "tilt_x"), ("My", "tilt_y")):
        if getattr(args, moment, 0.0) != 0.0 and tilt in fixed:
            raise InputError(f"{moment}: a moment load needs the free tilt (--tilt free); {tilt} is held")
    return fixed


#: Message starts of a lone angular-contact bearing that cannot locate or carry its inner ring axially.
_AXIAL = ("Fa:", "axial_load:")


@contextmanager
def explained(bearing=None):
    """InputErrors of the block in the CLI's words: ``fixed.DOF`` becomes
    ``--fix DOF``, and a lone angular-contact bearing that cannot carry its
    loads points to ``--fix delta_a=...``."""
    try:
        yield
    except InputError as exc:
        msg = str(exc)
        if msg.startswith("fixed."):
            msg = "--fix " + msg[len("fixed."):]
        elif msg.startswith("fixed:"):
            msg = "--fix:" + msg[len("fixed:"):]
        angular = bearing is not None and bearing.free_contact_angle > 0.0
        if angular and (msg.startswith(_AXIAL) or "over the shoulder" in msg) and "--fix delta_a" not in msg:
            msg += ("; a bearing of a pair is held axially by its partner: --fix delta_a=0 (or the axial "
                    "displacement [m] of the pair) holds the inner ring and reports the axial reaction")
        raise InputError(msg) from None


def solver_header(lubricant, traction: str | None, ring_growth: bool | None = None) -> str:
    """One header line naming the lubricant and traction model in use (and the ring growth)."""
    parts = [f"lubricant {lubricant.name}", f"traction {traction}" if traction else "no traction model (zero "
             "speed: no slip)"]
    if ring_growth is not None:
        parts.append(f"ring growth {'on' if ring_growth else 'off'}")
    return ", ".join(parts)


def print_table(rows):
    """Rows of (name, value) or (name, value, unit), aligned (:func:`~exudyn_bearing.outputs.tables.format_table`)."""
    print(format_table(rows))