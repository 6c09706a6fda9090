"""``info BEARING``: geometry, Hertz constants and kinematics of a bearing."""
from __future__ import annotations

import json

from ..outputs.jsonio import to_jsonable
from ..outputs.units import INFO_UNITS, with_units
from ..physics.hertz import METHODS
from ..physics.rating_life import RATING_UNITS, rating_life
from ..solvers.analytic import bearing_info
from ..solvers.quasistatic.solve import check_operating_fit
from .common import (RING_GROWTH, add_bearing_argument, add_speed_arguments, bearing_from_args, omega_from_args,
                     print_table)
from .static import warn_speed

#: Load-rating keys of ``info`` (:func:`exudyn_bearing.physics.rating_life.rating_life` without load).
RATING_KEYS = ("C", "C_method", "C0", "C0_method", "C0_iso76", "C0_hertz", "C_u")


def add_parser(sub):
    p = sub.add_parser("info", help="geometry, Hertz constants and kinematics of a bearing",
                       description="Geometry, Hertz constants and, with a speed, kinematics and defect "
                                   "frequencies [Hz] of a bearing.")
    add_bearing_argument(p)
    add_speed_arguments(p, what="none: geometry and Hertz constants only")
    p.add_argument("--hertz", choices=METHODS, default="exact", help="Hertz fidelity level")
    p.add_argument("--json", action="store_true", help="print JSON (with a units map) instead of a table")


def run(args):
    b = bearing_from_args(args)
    omega = omega_from_args(args)
    if omega is not None:  # the speed limit of quasistatic: the rings grown by the speed must hold the balls
        check_operating_fit(b, omega, ring_growth=RING_GROWTH)
        warn_speed(b, omega)
    info = bearing_info(b, omega, args.hertz)
    ratings = rating_life(b, (0.0, 0.0), warn=False).to_dict()
    info.update({k: ratings[k] for k in RATING_KEYS})
    units = {**INFO_UNITS, **RATING_UNITS}
    if args.json:
        print(json.dumps(to_jsonable(with_units(info, units)), indent=2))
        return
    print_table([(k, v, units.get(k)) for k, v in info.items() if k != "source"])
    print(f"source: {info['source']}")
