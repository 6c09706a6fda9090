"""Shared pieces of the sub-commands: the parser class, the options every
sub-command spells the same way (bearing, speed, lubricant), number parsing,
tables and the units of JSON output."""
from __future__ import annotations

import argparse
import math
import re

from ..data import InputError, catalog, load_bearing, load_lubricant, lubricants

__all__ = ["Parser", "HelpFormatter", "finite_float", "print_table", "BEARING_HELP", "add_bearing_argument",
           "bearing_from_args", "bearing_spec_from_args", "add_load_arguments", "add_speed_arguments",
           "omega_from_args", "add_lubricant_argument", "lubricant_from_args", "RPM_TO_RAD_S"]

#: Help text of a bearing argument.
BEARING_HELP = (f"catalogue name ({', '.join(catalog)}) or a JSON file: one bearing (race radii as in "
                "catalog.json, or dimensions: n_balls, ball_diameter, pitch_diameter, inner_conformity, "
                "outer_conformity, ...) or a catalogue-shaped file (FILE.json#NAME picks a bearing)")

#: rev/min -> rad/s.
RPM_TO_RAD_S = 2.0 * math.pi / 60.0

#: Numbers argparse must read as values, not options: -5, -0.5, -.5, -12.6e-6, -1E3 (argparse's own
#: pattern misses the exponent, so "--Pd -12.6e-6" failed with "expected one argument").
_NEGATIVE_NUMBER = re.compile(r"^-(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?$")


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
    """``--omega RAD_S`` or ``--rpm RPM`` (one of them): the inner-ring speed,
    outer ring fixed; read it in rad/s with :func:`omega_from_args`."""
    g = p.add_mutually_exclusive_group()
    tail = f" (default: {default:g} rad/s)" if default is not None else (f" (default: {what})" if what else "")
    g.add_argument("--omega", type=finite_float, metavar="RAD_S",
                   help=f"inner-ring speed [rad/s], outer ring fixed{tail}")
    g.add_argument("--rpm", type=finite_float, metavar="RPM",
                   help="inner-ring speed [rev/min] instead of --omega (omega = rpm * 2 pi / 60)")
    p.set_defaults(omega_default=default)


def omega_from_args(args):
    """Inner-ring speed [rad/s] from --omega or --rpm (None when neither is given and there is no default)."""
    if args.rpm is not None:
        return args.rpm * RPM_TO_RAD_S
    return args.omega if args.omega is not None else args.omega_default


def add_lubricant_argument(p):
    """``--lubricant NAME|FILE.json``; read it with :func:`lubricant_from_args`."""
    p.add_argument("--lubricant", metavar="NAME|FILE.json", default=next(iter(lubricants)),
                   help=f"catalogue lubricant ({', '.join(lubricants)}) or a JSON file with the Lubricant "
                        "fields (or a catalogue-shaped file, FILE.json#NAME)")


def lubricant_from_args(args):
    return load_lubricant(args.lubricant)


def print_table(rows):
    """Rows of (name, value) or (name, value, unit), aligned."""
    width = max(len(r[0]) for r in rows)
    for r in rows:
        k, v = r[0], r[1]
        unit = r[2] if len(r) > 2 and r[2] not in (None, "", "-") else ""
        if isinstance(v, float):
            v = f"{v:.6g}"
        print(f"{k:<{width}}  {v}{'  ' + unit if unit else ''}".rstrip())
