"""``vibration three-dof``: eigen-analysis of the 3-DOF outer ring / ball /
inner ring model (El Had et al. 2014).

Without ``--source-parameters`` the parameters are derived from the bearing
(default 6004) at an operating point (``--Fr``, ``--Fa``, ``--rpm`` or
``--omega``, ``--Pd``), the ring sections from the bearing's bore, outside
diameter and width (its data, the catalogue's published dimensions or an
estimate; ``--bore``, ``--outer-diameter``, ``--width`` set them); with it,
the source's printed values under the readings chosen by ``--inner-ring``,
``--outer-link`` and ``--damping-row`` (a bearing or an operating point is
then refused: the printed values are the source's 6004 at its own point). ``--json``
prints ``eigenvalues`` ([re, im] pairs, 1/s), ``natural_frequencies`` (Hz),
``damping_ratios``, ``mode_shapes`` ([re, im] per coordinate outer ring,
ball, inner ring) and ``units``; otherwise a table.
"""
from __future__ import annotations

import json
import math

import numpy as np

from ..data import InputError
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
    t.add_argument("--Fr", type=finite_float, help=f"radial load [N] (default {DEFAULTS['Fr']:g})")
    t.add_argument("--Fa", type=finite_float, help="axial load [N] (default 0; an angular-contact bearing needs one)")
    speed = t.add_mutually_exclusive_group()
    speed.add_argument("--rpm", type=finite_float, help=f"inner-ring speed [rpm] (default {DEFAULTS['rpm']:g})")
    speed.add_argument("--omega", type=finite_float, help="inner-ring speed [rad/s]")
    t.add_argument("--Pd", type=finite_float, help=f"diametral clearance [m] (default {DEFAULTS['Pd']:g})")
    for name, what in (("bore", "bore d"), ("outer-diameter", "outside diameter D"), ("width", "ring width B")):
        t.add_argument(f"--{name}", type=finite_float, metavar="M",
                       help=f"{what} [m] of the ring sections (default: the bearing's data, the catalogue's "
                            "published dimensions, or an estimate from ball and pitch diameter)")
    t.add_argument("--link", choices=("series", "hertz", "film"),
                   help="ball-race spring: Hertz and film in series (default) or one of them")
    t.add_argument("--film-damping", choices=("short_bearing", "contact_model"),
                   help="ball-race damper: the source's short-bearing film (default) or the contact model's")
    t.add_argument("--json", action="store_true", help="print JSON")


#: Operating point of a derived parameter set without options.
DEFAULTS = {"Fr": 500.0, "Fa": 0.0, "rpm": 3000.0, "Pd": 12.5e-6, "link": "series", "film_damping": "short_bearing"}
#: Options of a derived set (dest -> option), refused with --source-parameters.
DERIVED_OPTIONS = {"bearing": "BEARING", "bearing_option": "--bearing", "Fr": "--Fr", "Fa": "--Fa", "rpm": "--rpm",
                   "omega": "--omega", "Pd": "--Pd", "bore": "--bore", "outer_diameter": "--outer-diameter",
                   "width": "--width", "link": "--link", "film_damping": "--film-damping"}


def _parameters(args):
    if args.source_parameters:
        given = [opt for dest, opt in DERIVED_OPTIONS.items() if getattr(args, dest, None) is not None]
        if given:
            raise InputError(f"source_parameters: the printed values are El Had et al.'s 6004 at their own operating "
                             f"point; {', '.join(given)} would be ignored (leave out --source-parameters to derive "
                             "the parameters from a bearing)")
        return three_dof.source_parameters(args.inner_ring, args.outer_link, args.damping_row)
    val = {k: (getattr(args, k) if getattr(args, k) is not None else v) for k, v in DEFAULTS.items()}
    omega = args.omega if args.omega is not None else val["rpm"] * 2.0 * math.pi / 60.0
    bearing = bearing_spec_from_args(args)
    dims = None
    if any(getattr(args, k) is not None for k in ("bore", "outer_diameter", "width")):
        auto, _source = three_dof.ring_dimensions(bearing)
        dims = three_dof.RingDimensions(**{k: getattr(args, k) if getattr(args, k) is not None else getattr(auto, k)
                                           for k in ("bore", "outer_diameter", "width")})
    return three_dof.derived_parameters(bearing, radial_load=val["Fr"], axial_load=val["Fa"], omega=omega,
                                        diametral_clearance=val["Pd"], link=val["link"],
                                        film_damping=val["film_damping"], dimensions=dims)


#: Unit key of the three-mass model's parameters by the start of their name (the JSON's ``units`` map).
_PARAMETER_UNITS = {"mass_": "mass", "k_": "stiffness", "c_": "damping"}


def _parameter_unit(name, units):
    """Unit of the parameter ``name`` of a three-mass model (kg, N/m, N s/m); None for a setting."""
    return next((units[key] for prefix, key in _PARAMETER_UNITS.items() if name.startswith(prefix)), None)


def run(args):
    p = _parameters(args)
    res = three_dof.analyse(p)
    if args.json:
        print(json.dumps(to_jsonable(res.to_dict()), indent=2))
        return
    print(f"{p.label}")
    print("reading: " + ", ".join(f"{k} = {v}" for k, v in p.reading.items()))
    d = res.to_dict()
    print_table([(k, v, _parameter_unit(k, d["units"])) for k, v in d["parameters"].items()])
    print()
    head = f"{'eigenvalue [1/s]':>34}  {'f_n [Hz]':>11}  {'zeta':>9}  |shape| outer, ball, inner"
    print(head)
    m = res.modal
    for lam, f, z, shape in zip(m.eigenvalues, m.natural_frequencies, m.damping_ratios, m.mode_shapes):
        mags = ", ".join(f"{x:.3g}" for x in np.abs(shape))
        print(f"{lam.real:>16.6g} {lam.imag:+16.6g}j  {f:>11.5g}  {z:>9.4g}  {mags}")
