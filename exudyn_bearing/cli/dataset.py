"""``dataset BEARING OUT``: labelled healthy / defective signals over a grid of speeds, loads and defect sizes.

Exit status 0 when every case finished, 3 when some failed (listed on
stderr and in OUT/index.json; the index.csv of the others is written, and
the same command runs the failed ones again), 130 after Ctrl-C and 143
after SIGTERM (one line on stderr; the same command resumes).

BEARING comes first, as in every command. The older ``dataset OUT`` (the
bearing then defaulted to 6205) and ``dataset OUT BEARING`` still run, with
a deprecation note on stderr.
"""
from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from pathlib import Path

from ..datasets import FAULTS, build_dataset
from ..sweep import INDEX, SweepInterrupted
from ..outputs.jsonio import to_jsonable
from ..data import InputError, catalog
from .common import BEARING_HELP, finite_float, print_table

#: The bearing of the deprecated ``dataset OUT`` form (the old default).
OLD_DEFAULT_BEARING = "6205"


def bearing_and_out(args) -> tuple[str, str]:
    """(BEARING, OUT) of the arguments: ``dataset BEARING OUT``; the older ``dataset OUT [--bearing B]`` and
    ``dataset OUT BEARING`` with a deprecation note on stderr."""
    first, second, option = args.bearing, args.out, args.bearing_option
    if second is None and (first in catalog or first.endswith(".json")):
        raise InputError(f"OUT: dataset needs an output folder after the bearing: 'dataset {first} OUT'")
    if second is None or (second in catalog and first not in catalog and not first.endswith(".json")):
        bearing = second or option or OLD_DEFAULT_BEARING
        print(f"exudyn-bearing: note: 'dataset OUT [BEARING]' is deprecated: give the bearing first, "
              f"'dataset {bearing} {first}' (as every command)", file=sys.stderr)
        return bearing, first
    if option is not None and option != first:
        raise InputError(f"bearing: given twice ({first!r} and --bearing {option!r})")
    return first, second


def add_parser(sub):
    p = sub.add_parser("dataset", help="labelled condition-monitoring signals (NPZ per case, index.csv), resumable")
    p.add_argument("bearing", metavar="BEARING", help=BEARING_HELP)
    p.add_argument("out", metavar="OUT", nargs="?", help="output folder (an interrupted run resumes there)")
    p.add_argument("--bearing", dest="bearing_option", metavar="BEARING", help=argparse.SUPPRESS)
    p.add_argument("--rpm", type=finite_float, nargs="+", default=[1797.0], help="inner-ring speeds [1/min]")
    p.add_argument("--load", type=finite_float, nargs="+", default=[1000.0], help="radial loads [N]")
    p.add_argument("--size", type=finite_float, nargs=3, action="append", metavar=("LENGTH", "WIDTH", "DEPTH"),
                   help="defect size [m] (repeat for several; default 1e-3 1.5e-3 1e-4)")
    p.add_argument("--faults", nargs="+", choices=FAULTS, default=list(FAULTS),
                   help="cases per grid point: healthy and the spall locations")
    p.add_argument("--fs", type=finite_float, default=48000.0, help="signal sample rate [Hz]")
    p.add_argument("--steps-per-sample", type=int, default=4,
                   help="time steps per signal sample, at least (a case whose stable step needs more takes more)")
    p.add_argument("--t-end", type=finite_float, default=0.5, help="simulated time per case [s]")
    p.add_argument("--workers", type=int, help="local processes (default: all cores)")
    p.add_argument("--progress", action="store_true", help="progress line on stderr")
    p.add_argument("--json", action="store_true", help="print the index rows as JSON")


def run(args):
    bearing, args.out = bearing_and_out(args)
    try:
        rows = build_dataset(args.out, bearing=bearing, speeds_rpm=tuple(args.rpm),
                             loads=tuple(args.load), sizes=tuple(tuple(s) for s in (args.size or [(1e-3, 1.5e-3, 1e-4)])),
                             faults=tuple(args.faults), fs=args.fs, t_end=args.t_end,
                             steps_per_sample=args.steps_per_sample, workers=args.workers, progress=args.progress)
    except SweepInterrupted as exc:
        counts = _sweep_counts(args.out)
        print(f"exudyn-bearing: {exc}: {counts.get('done', 0)} of {sum(counts.values())} cases done in {args.out}; "
              "the same command resumes", file=sys.stderr)
        raise SystemExit(exc.exit_status) from None
    except KeyboardInterrupt:  # before the sweep started
        print("exudyn-bearing: dataset stopped by SIGINT before its first case", file=sys.stderr)
        raise SystemExit(130) from None
    failed = _sweep_counts(args.out).get("failed", 0)
    if args.json:
        print(json.dumps(to_jsonable(rows), indent=2))
    else:
        counts = Counter(r["fault"] for r in rows)
        print_table([("cases", len(rows)), *((f"cases.{f}", counts[f]) for f in FAULTS if counts[f]),
                     *([("cases.failed", f"{failed} (see {args.out}/{INDEX[0]})")] if failed else []),
                     ("index", f"{args.out}/index.csv")])
    if failed:
        raise SystemExit(3)


def _sweep_counts(out) -> dict:
    """Case counts by status of the sweep index in ``out`` (empty if unreadable)."""
    try:
        return json.loads((Path(out) / INDEX[0]).read_text())["counts"]
    except (OSError, ValueError, KeyError, TypeError):
        return {}
