"""``vibration three-dof``: eigen-analysis of the 3-DOF outer ring / ball /
inner ring model (El Had et al. 2014).

Without ``--source-parameters`` the parameters are derived from the bearing
(default 6004) at an operating point (``--Fr``, ``--rpm`` or ``--omega``,
``--Pd``); with it, the source's printed values under the readings chosen
by ``--inner-ring``, ``--outer-link`` and ``--damping-row``. ``--json``
prints ``eigenvalues`` ([re, im] pairs, 1/s), ``natural_frequencies`` (Hz),
``damping_ratios``, ``mode_shapes`` ([re, im] per coordinate outer ring,
ball, inner ring) and ``units``; otherwise a table.
"""
from __future__ import annotations

import json
import math

import numpy as np

from ..outputs.jsonio import to_jsonable
from ..solvers.vibration import three_dof
from .common import add_bearing_argument, bearing_spec_from_args, finite_float, print_table


def add_parser(sub):
    p = sub.add_parser("vibration", help="linear vibration models of a bearing")
    models = p.add_subparsers(dest="model", required=True, parser_class=type(p), metavar="MODEL",
                              help="the vibration model ('MODEL --help' for its options)")
    t = models.add_parser("three-dof", help="3-DOF outer ring / ball / inner ring model (El Had et al. 2014)")
    t.add_argument("--source-parameters", action="store_true",
                   help="the source's printed values instead of values derived from the bearing")
    for name, values in three_dof.READINGS.items():
        t.add_argument(f"--{name.replace('_', '-')}", choices=values, default=values[0],
                       help=f"reading of the source (with --source-parameters; default {values[0]})")
    add_bearing_argument(t, default="6004")
    t.add_argument("--Fr", type=finite_float, default=500.0, help="radial load [N] (default 500)")
    speed = t.add_mutually_exclusive_group()
    speed.add_argument("--rpm", type=finite_float, help="inner-ring speed [rpm] (default 3000)")
    speed.add_argument("--omega", type=finite_float, help="inner-ring speed [rad/s]")
    t.add_argument("--Pd", type=finite_float, default=12.5e-6, help="diametral clearance [m] (default 12.5e-6)")
    t.add_argument("--link", choices=("series", "hertz", "film"), default="series",
                   help="ball-race spring: Hertz and film in series (default) or one of them")
    t.add_argument("--film-damping", choices=("short_bearing", "contact_model"), default="short_bearing",
                   help="ball-race damper: the source's short-bearing film (default) or the contact model's")
    t.add_argument("--json", action="store_true", help="print JSON")


def _parameters(args):
    if args.source_parameters:
        return three_dof.source_parameters(args.inner_ring, args.outer_link, args.damping_row)
    if args.omega is not None:
        omega = args.omega
    else:
        omega = (3000.0 if args.rpm is None else args.rpm) * 2.0 * math.pi / 60.0
    return three_dof.derived_parameters(bearing_spec_from_args(args), radial_load=args.Fr, omega=omega,
                                        diametral_clearance=args.Pd, link=args.link,
                                        film_damping=args.film_damping)


def run(args):
    p = _parameters(args)
    res = three_dof.analyse(p)
    if args.json:
        print(json.dumps(to_jsonable(res.to_dict()), indent=2))
        return
    print(f"{p.label}")
    print("reading: " + ", ".join(f"{k} = {v}" for k, v in p.reading.items()))
    print_table([(k, v) for k, v in res.to_dict()["parameters"].items()])
    print()
    head = f"{'eigenvalue [1/s]':>34}  {'f_n [Hz]':>11}  {'zeta':>9}  |shape| outer, ball, inner"
    print(head)
    m = res.modal
    for lam, f, z, shape in zip(m.eigenvalues, m.natural_frequencies, m.damping_ratios, m.mode_shapes):
        mags = ", ".join(f"{x:.3g}" for x in np.abs(shape))
        print(f"{lam.real:>16.6g} {lam.imag:+16.6g}j  {f:>11.5g}  {z:>9.4g}  {mags}")
