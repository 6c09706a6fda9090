"""``info BEARING``: geometry, Hertz constants and kinematics of a bearing; ``info --list``: the catalogue."""
from __future__ import annotations

import json

from ..data import InputError
from ..data.cages import estimated_cage
from ..data.catalog import catalog_listing
from ..model.scenario import bearing_cage
from ..outputs.jsonio import to_jsonable
from ..outputs.units import INFO_UNITS, with_units
from ..physics.hertz import METHODS
from ..physics.rating_life import RATING_UNITS, rating_life
from ..solvers.analytic import bearing_info
from ..solvers.quasistatic.solve import check_operating_fit
from .common import (BEARING_HELP, RING_GROWTH, add_outer_speed_arguments, add_speed_arguments, bearing_from_args,
                     omega_from_args, omega_outer_from_args,
                     print_table)
from .static import warn_speed

#: Load-rating keys of ``info`` (:func:`exudyn_bearing.physics.rating_life.rating_life` without load).
RATING_KEYS = ("C", "C_method", "C0", "C0_method", "C0_iso76", "C0_hertz", "C_u")
#: Units of the rows of ``info --list --json``.
LIST_UNITS = {"bore": "m", "outer_diameter": "m", "width": "m (ISO 15; null where unknown)", "n_balls": "-",
              "ball_diameter": "m", "free_contact_angle_deg": "deg",
              "geometry": "data sheet (the papers' validated entries) or estimated (ISO 15 series rule, "
                          "docs/theory/geometry.md#series-catalogue)"}


def add_parser(sub):
    p = sub.add_parser("info", help="geometry, Hertz constants and kinematics of a bearing; --list: the catalogue",
                       description="Geometry, Hertz constants and, with a speed, kinematics and defect "
                                   "frequencies [Hz] of a bearing; --list prints the catalogue, one bearing a "
                                   "line.")
    p.add_argument("bearing", metavar="BEARING", nargs="?", help=f"{BEARING_HELP} (not with --list)")
    p.set_defaults(bearing_default=None)
    p.add_argument("--list", action="store_true",
                   help="print the catalogue, one bearing a line: name, type, d x D x B [mm], Z x D_w [mm], "
                        "contact angle [deg], data-sheet or estimated geometry")
    add_speed_arguments(p, what="none: geometry and Hertz constants only")
    add_outer_speed_arguments(p, " of the kinematics and defect frequencies (with --omega or --rpm)")
    p.add_argument("--hertz", choices=METHODS, default="exact", help="Hertz fidelity level")
    p.add_argument("--json", action="store_true", help="print JSON (with a units map) instead of a table")


def _mm(x) -> str:
    return "-" if x is None else f"{x * 1e3:g}"


def print_list(as_json: bool) -> None:
    """The catalogue, one bearing a line (:func:`exudyn_bearing.data.catalog.catalog_listing`)."""
    rows = catalog_listing()
    if as_json:
        print(json.dumps({"bearings": rows, "units": LIST_UNITS}, indent=2))
        return
    table = [("name", "type", "d x D x B [mm]", "Z x D_w [mm]", "alpha_0 [deg]", "geometry")]
    for r in rows:
        table.append((r["name"], r["type"], f"{_mm(r['bore'])} x {_mm(r['outer_diameter'])} x {_mm(r['width'])}",
                      f"{r['n_balls']} x {r['ball_diameter'] * 1e3:.3f}", f"{r['free_contact_angle_deg']:g}",
                      r["geometry"]))
    widths = [max(len(row[i]) for row in table) for i in range(len(table[0]))]
    for row in table:
        print("  ".join(v.ljust(w) for v, w in zip(row, widths)).rstrip())
    print("data sheet: the papers' validated bearings; estimated: ISO 15 boundary dimensions with the internal "
          "geometry of the series rule (docs/theory/geometry.md#series-catalogue)")


def run(args):
    if args.list:
        if args.bearing is not None or args.omega is not None or getattr(args, "rpm", None) is not None:
            raise InputError("list: --list prints the whole catalogue; give no BEARING or speed with it")
        print_list(args.json)
        return
    if args.bearing is None:
        raise InputError("bearing: missing; give a BEARING (catalogue name or JSON file) or --list")
    b = bearing_from_args(args)
    omega, omega_outer = omega_from_args(args), omega_outer_from_args(args)
    if omega is None and omega_outer:
        raise InputError("omega: --omega-outer / --rpm-outer need the inner ring's speed too (--omega 0: at rest)")
    if omega is not None:  # the speed limit of quasistatic: the rings grown by the speed must hold the balls
        check_operating_fit(b, omega, omega_outer, ring_growth=RING_GROWTH)
        warn_speed(b, omega, omega_outer)
    info = bearing_info(b, omega, args.hertz, omega_outer=omega_outer)
    ratings = rating_life(b, (0.0, 0.0), warn=False).to_dict()
    info.update({k: ratings[k] for k in RATING_KEYS})
    info["estimated"] = list(b.estimated)
    info["default_cage"] = bearing_cage("auto", b)
    info["rigid_cage"] = rigid_cage_info(b)
    units = {**INFO_UNITS, **RATING_UNITS, "default_cage": "the cage model of cage='auto' (the default)",
             "rigid_cage": RIGID_CAGE_UNITS}
    if args.json:
        print(json.dumps(to_jsonable(with_units(info, units)), indent=2))
        return
    print_table([(k, v, units.get(k)) for k, v in info.items() if k not in ("source", "estimated", "rigid_cage")])
    print(f"source: {info['source']}")
    if b.estimated:
        print(f"estimated (not from a data sheet): {', '.join(b.estimated)}")
    rc = info["rigid_cage"]
    print(f"rigid cage (cage='rigid'{' and the default' if info['default_cage'] == 'rigid' else ''}): "
          + ", ".join(f"{k} {v:.4g} {RIGID_CAGE_UNITS[k]}" if isinstance(v, float) else f"{k} {v}"
                      for k, v in rc.items() if k not in ("estimated", "source"))
          + f"; ESTIMATED: {', '.join(rc['estimated'])} ({rc['source']})")


#: Units of ``info``'s rigid-cage fields.
RIGID_CAGE_UNITS = {"guidance": "", "pocket_shape": "", "material": "", "pocket_clearance": "m",
                    "inner_radius": "m", "outer_radius": "m", "width": "m", "land_clearance": "m", "land_width": "m",
                    "pocket_friction": "-", "mass": "kg", "polar_inertia": "kg m^2"}


def rigid_cage_info(b) -> dict:
    """The rigid cage a run with cage='rigid' (or the default, where it resolves to it) takes for ``b``: the
    bearing's estimated cage (docs/theory/cage.md#estimated-geometry), each estimated field named."""
    rc = estimated_cage(b)
    return {"guidance": rc.guidance, "pocket_shape": rc.pocket_shape, "material": rc.material.name,
            "pocket_clearance": rc.pocket_clearance, "inner_radius": rc.inner_radius, "outer_radius": rc.outer_radius,
            "width": rc.width, "land_clearance": rc.land_clearance, "land_width": rc.land_width,
            "pocket_friction": rc.pocket_friction, "mass": rc.mass(b), "polar_inertia": rc.polar_inertia(b),
            "estimated": list(rc.estimated), "source": rc.source}
