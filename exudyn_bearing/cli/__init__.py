"""Command line: ``python -m exudyn_bearing`` / ``exudyn-bearing``.

Sub-commands (``--json`` for scripts, with a ``units`` map; tables otherwise):

* ``info BEARING [--omega W | --rpm N]``: geometry, Hertz constants, kinematics.
* ``static BEARING --Fr N [--Fa N] [--tilt fixed|free] [--fix DOF=V] [--Pd M]
  [--omega W | --rpm N] [--lubricant L] [--film hd|mk] [--plot FILE.png]``:
  the zero-speed special case of ``quasistatic`` (load distribution, held
  DOFs with their reactions) and the lubrication map.
* ``quasistatic BEARING [--Fr N] [--Fa N] [--Mx NM] [--My NM] [--omega W |
  --rpm N] [--control outer|inner|auto|min-energy] [--traction NAME]
  [--lubricant L] [--ring-growth | --no-ring-growth] [--tilt fixed|free]
  [--fix DOF=V] [--fit M] [--json] [--plot FILE.png]``: 5-DOF equilibrium at
  speed, ball kinematics, slip, dissipation, stiffness.
* ``simulate [BEARING] --Fr N [--omega W | --rpm N] [--ramp UP STEADY DOWN]
  [--t-end T] [--engine reference|exudyn] [--out DIR]``: dynamic simulation;
  summary keys of :meth:`exudyn_bearing.outputs.results.Results.summary`.
* ``stiffness BEARING [--Fr N] [--Fa N] [--omega W | --rpm N | --speeds W.. |
  --rpms N..] [--phases N] [--tilt fixed|free] [--fix DOF=V] [--json]
  [--plot FILE.png]``: linearised 5x5
  stiffness and damping (x, y, axial, tilt x, tilt y) from the quasi-static
  solver, or a table over speeds.
* ``vibration three-dof [--source-parameters] [--json]``: eigenvalues,
  natural frequencies, damping ratios and mode shapes of the 3-DOF
  outer ring / ball / inner ring model.
* ``dataset OUT [--rpm ...] [--load ...] [--size L W H ...] [--t-end T]``:
  labelled healthy and defective signals (:mod:`exudyn_bearing.datasets`).

``static``, ``quasistatic`` and ``stiffness`` hold the inner-ring tilt at
zero unless ``--tilt free``; the lubricant and traction model default to the
bearing's, ring growth is on (README, "Defaults"); ``--version`` prints the
version.

BEARING is a catalogue name (6208, 7208, 6004, 6205, ACBB-120) or a JSON file
(:mod:`exudyn_bearing.data.catalog`: one bearing by race radii or dimensions,
or a catalogue-shaped file). Shared options live in :mod:`.common`. Bad
input exits with status 2 and a one-line message naming the parameter;
Ctrl-C (SIGINT) with status 130 and one line (``simulate --out DIR`` writes
the samples taken so far there).
"""
from __future__ import annotations

import sys
import warnings
from importlib import import_module
from typing import TYPE_CHECKING

from ..data import InputError
from ..model.stability import SimulationError
from .common import Parser

if TYPE_CHECKING:  # the sub-command modules, imported by name below (a run imports only its own)
    from . import dataset, info, quasistatic, simulate, static, stiffness, vibration  # noqa: F401

__all__ = ["main"]

#: Text of ``exudyn-bearing --help``.
DESCRIPTION = ("Rolling-element ball bearings: data sheet (info), load distribution and lubrication map at "
               "zero speed (static), quasi-static equilibrium at speed (quasistatic), dynamic simulation ball by "
               "ball (simulate), linear vibration models (vibration). BEARING is a catalogue name or a JSON file; "
               "'exudyn-bearing COMMAND --help' lists a command's options.")
#: The exit statuses of :func:`main` (``exudyn-bearing --help`` lists them).
EXIT_STATUSES = {0: "done", 2: "bad input or an unreadable file (the message names the parameter)",
                 3: "a run that failed (SimulationError: what was written is named)", 130: "stopped by Ctrl-C"}
EPILOG = "exit status: " + "; ".join(f"{k} {v}" for k, v in EXIT_STATUSES.items())

#: Sub-commands: name -> module (of this package) with ``add_parser(subparsers)`` and ``run(args)``.
COMMANDS = {"info": ".info", "static": ".static", "quasistatic": ".quasistatic", "simulate": ".simulate",
            "stiffness": ".stiffness", "vibration": ".vibration", "dataset": ".dataset"}


def command_module(name):
    """The module of sub-command ``name`` (imported on first use)."""
    return import_module(COMMANDS[name], __name__)


def _parser(argv=None) -> Parser:
    """The command line parser; given ``argv`` whose first word is a sub-command, with that one
    sub-command only (its options and help are the same; the others' modules stay unimported)."""
    from .. import __version__

    p = Parser(prog="exudyn-bearing", description=DESCRIPTION, epilog=EPILOG)
    p.add_argument("--version", action="version", version=f"exudyn-bearing {__version__}", default=None,
                   help="print the version and exit")
    sub = p.add_subparsers(dest="command", required=True, parser_class=Parser, metavar="COMMAND",
                           help="one of the sub-commands below ('COMMAND --help' for its options)")
    names = [argv[0]] if argv and argv[0] in COMMANDS else COMMANDS
    for name in names:
        command_module(name).add_parser(sub)
    for command in sub.choices.values():  # every command's --help ends with the exit statuses
        command.epilog = EPILOG
    return p


def main(argv=None) -> int:
    """Entry point; returns the exit status."""
    argv = sys.argv[1:] if argv is None else list(argv)
    args = None
    shown = warnings.formatwarning
    warnings.formatwarning = _format_warning
    try:
        args = _parser(argv).parse_args(argv)
        command_module(args.command).run(args)
    except KeyboardInterrupt as exc:  # Ctrl-C: one line and the conventional status, not a traceback
        what = getattr(args, "command", None) or "exudyn-bearing"
        print(f"exudyn-bearing: {what} stopped by SIGINT{_interrupted_detail(exc)}", file=sys.stderr)
        return 130
    except (InputError, ValueError) as exc:
        print(f"exudyn-bearing: error: {exc}", file=sys.stderr)
        return 2
    except SimulationError as exc:
        print(f"exudyn-bearing: error: {exc}", file=sys.stderr)
        return 3
    except OSError as exc:
        print(f"exudyn-bearing: error: {exc}", file=sys.stderr)
        return 2
    finally:
        warnings.formatwarning = shown
    return 0


def _format_warning(message, category, filename, lineno, line=None) -> str:
    """A warning as the command line prints it: one line with its kind, without the source file and line that
    Python's default adds (meant for programmers, not for the command's user)."""
    return f"exudyn-bearing: warning ({category.__name__}): {message}\n"


def _interrupted_detail(exc) -> str:
    """What an interrupted run kept (``simulate``: the time reached, the samples and where they went)."""
    if not hasattr(exc, "t_end"):
        return ""
    kept = getattr(exc, "saved", None)
    return (f" at t = {exc.t:.6g} of {exc.t_end:.6g} s ({exc.samples} samples"
            + (f", written to {kept}" if kept else "") + ")")


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
