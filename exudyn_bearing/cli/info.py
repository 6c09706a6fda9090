"""``info BEARING``: geometry, Hertz constants and kinematics of a bearing."""
from __future__ import annotations

import json

from ..data import load_bearing
from ..outputs.jsonio import to_jsonable
from ..physics.hertz import METHODS
from ..solvers.analytic import bearing_info
from .common import BEARING_HELP, finite_float, print_table


def add_parser(sub):
    p = sub.add_parser("info", help="geometry, Hertz constants and kinematics of a bearing")
    p.add_argument("bearing", help=BEARING_HELP)
    p.add_argument("--omega", type=finite_float, help="inner-ring speed [rad/s], outer ring fixed")
    p.add_argument("--hertz", choices=METHODS, default="exact", help="Hertz fidelity level")
    p.add_argument("--json", action="store_true", help="print JSON")


_LENGTHS = ("ball_radius", "inner_race_radius", "outer_race_radius", "inner_groove_radius",
            "outer_groove_radius", "cage_ball_radius", "pitch_radius", "diametral_clearance",
            "cage_pocket_clearance", "R_x_inner", "R_y_inner", "R_x_outer", "R_y_outer")
_INFO_UNITS = dict({k: "m" for k in _LENGTHS}, K_inner="N/m^1.5", K_outer="N/m^1.5", K_n="N/m^1.5",
                   cage_speed="rad/s", ball_spin="rad/s", ball_spin_relative="rad/s", omega="rad/s",
                   ftf="Hz", bpfo="Hz", bpfi="Hz", bsf="Hz", rolling_speed="m/s", e_prime="Pa",
                   ball_mass="kg", free_contact_angle_deg="deg")


def run(args):
    b = load_bearing(args.bearing)
    info = bearing_info(b, args.omega, args.hertz)
    if args.json:
        print(json.dumps(to_jsonable(info), indent=2))
        return
    rows = [(k, f"{v:.6g} {_INFO_UNITS.get(k, '')}".rstrip() if isinstance(v, float) else v)
            for k, v in info.items() if k != "source"]
    print_table(rows)
    print(f"source: {info['source']}")
