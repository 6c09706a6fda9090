"""The series catalogue: deep-groove 60, 62, 63 and angular-contact 70, 72, 73 ball bearings of bore codes 00-20
(10-100 mm) from their ISO 15 boundary dimensions (``iso15.json``) and an internal geometry estimated by a stated
rule (docs/theory/geometry.md#series-catalogue).

Names: the designation followed by ``-ISO`` (:data:`SERIES_SUFFIX`), with the contact-angle suffix for the
angular-contact series: ``6310-ISO``, ``6004-ISO``, ``7208B-ISO`` (40 deg), ``7210AC-ISO`` (25 deg),
``7005C-ISO`` (15 deg). The papers' validated bearings keep their plain names (``6208``, ``7208``, ``6004``,
``6205``, ``ACBB-120``); ``6208-ISO`` is the rule's estimate of a 6208, not the papers' bearing.

The rule (lengths in mm here; :func:`estimate_internal_geometry`):

* pitch diameter d_m = (d + D) / 2;
* ball diameter D_w = :data:`BALL_FACTOR` (D - d) rounded to the nearest :data:`BALL_STEP` (1/64 in);
* ball count: deep groove (Conrad assembly) the most balls that fill at most :data:`CONRAD_FILL_DEG` of the
  pitch circle before the rings are centred, (Z - 1) 2 asin(D_w / d_m) <= 192 deg; angular contact (the outer
  ring's low shoulder lets the balls in) the most that fill at most :data:`ANGULAR_FILL_DEG` with the balls
  themselves, Z 2 asin(D_w / d_m) <= 330 deg;
* groove conformities 0.52 inner, 0.53 outer (ISO 281's assumption, :data:`.iso281.STANDARD_CONFORMITY`);
* diametral clearance: deep groove the middle of ISO 5753-1's normal group CN for the bore (unmounted);
  angular contact 0 (set by the mounting against the opposite bearing);
* torus-cage balls filling the gap between neighbours on the pitch circle less a pocket clearance of
  :data:`POCKET_CLEARANCE` D_w.

Every value so estimated is listed in the bearing's ``estimated``.
"""
from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass
from importlib import resources

from .bearings import BallBearing
from .errors import InputError
from .iso281 import STANDARD_CONFORMITY
from .materials import Material

__all__ = ["SERIES_SUFFIX", "C_DEVIATION", "C_DEVIATION_10MM", "BALL_FACTOR", "BALL_STEP", "CONRAD_FILL_DEG", "ANGULAR_FILL_DEG", "POCKET_CLEARANCE",
           "ESTIMATED", "ISO15", "SeriesEntry", "series_names", "series_entry", "parse_series_name",
           "is_series_name", "boundary_dimensions", "designation_dimensions", "cn_clearance", "estimate_internal_geometry", "series_bearing"]

#: Name suffix of the series catalogue's bearings.
SERIES_SUFFIX = "-ISO"
#: D_w / (D - d) of the rule: the mean (0.302) of the bearings of known internal geometry, 0.289-0.318: the
#: papers' 6208 (9 x 12.6 mm), the CWRU 6205 (9 x 7.94 mm) and 6203 (8 x 6.747 mm), the catalogue's 6004
#: (9 x 6.35 mm), Harris & Kotzalas' 209 (9 x 12.7 mm) (docs/theory/geometry.md#series-catalogue).
BALL_FACTOR = 0.30
#: Ball-size step [m]: 1/64 in. Bearing balls come in inch fractions (the anchors' 6.35, 6.747, 7.938, 12.7 and
#: 22.225 mm are 16/64, 17/64, 20/64, 32/64 and 56/64 in).
BALL_STEP = 25.4e-3 / 64.0
#: Largest arc of the pitch circle [deg] the Conrad-assembled balls of a deep-groove bearing may fill,
#: (Z - 1) 2 asin(D_w / d_m) <= 192 deg: the largest value of the anchors (180.3 to 192.0 deg).
CONRAD_FILL_DEG = 192.0
#: Largest arc [deg] the balls of an angular-contact bearing may fill, Z 2 asin(D_w / d_m) <= 330 deg, leaving
#: the rest for the cage bars: Harris & Kotzalas' 218 (16 x 22.225 mm on 125.26 mm: 327 deg) and the papers'
#: 7208 (13 x 12.6 mm on 60.6 mm: 312 deg) both satisfy it with the largest count.
ANGULAR_FILL_DEG = 330.0
#: Pocket clearance of the estimated torus cage, per ball diameter: about the papers' 6208 (33.1 um / 12.6 mm)
#: and the 6205 entry (29 um / 7.94 mm).
POCKET_CLEARANCE = 0.003
#: Expected deviation of the ISO 281 basic dynamic load rating C of an estimated geometry from manufacturers'
#: published C, (lowest, highest) as fractions: measured on the anchors of docs/theory/geometry.md#series-catalogue
#: (SKF's 6005, 6010, 6205, 6208, 6305, 6308, 7208 BECBP: -12.1 % to -3.7 %); for the 10 mm bores, whose balls the
#: 1/64 in step resolves coarsely, against NTN's 6000, 6200, 6300: -5.8 % to +17.2 %.
C_DEVIATION = (-0.13, -0.03)
C_DEVIATION_10MM = (-0.07, 0.18)
#: Quantities every series entry estimates (the boundary dimensions and the nominal contact angle are not).
ESTIMATED = ("n_balls", "ball_diameter", "pitch_diameter", "inner_conformity", "outer_conformity",
             "diametral_clearance", "cage_ball_radius")

ISO15 = json.loads(resources.files(__package__).joinpath("iso15.json").read_text())
_SUFFIXES = {k: v for k, v in ISO15["contact_angle_suffixes"].items() if k != "source"}
_NAME = re.compile(r"^(6[023]|7[023])(\d\d)(AC|B|C)?" + re.escape(SERIES_SUFFIX) + "$", re.IGNORECASE)


@dataclass(frozen=True)
class SeriesEntry:
    """One bearing of the series catalogue: its name, series, bore code, type, boundary dimensions d, D, B [m]
    (ISO 15) and nominal contact angle [deg]."""

    name: str
    series: str
    bore_code: str
    kind: str
    bore: float
    outer_diameter: float
    width: float
    contact_angle_deg: float


def _rows(series: str) -> dict:
    spec = ISO15["series"][series]
    return ISO15["series"][spec["same_as"]]["D_B"] if "same_as" in spec else spec["D_B"]


def boundary_dimensions(series: str, bore_code: str) -> tuple[float, float, float]:
    """(d, D, B) [m] of ISO 15 for a bearing series (60, 62, 63, 70, 72, 73) and a bore code (00-20)."""
    if series not in ISO15["series"]:
        raise InputError(f"bearing: series {series!r} is not in the series catalogue (valid: "
                         f"{', '.join(ISO15['series'])})")
    rows = _rows(series)
    if bore_code not in rows:
        raise InputError(f"bearing: bore code {bore_code!r} is not in the series catalogue (00 to 20: 10 to 100 mm)")
    big_d, width = rows[bore_code]
    return 1e-3 * ISO15["bore_codes"][bore_code], 1e-3 * big_d, 1e-3 * width


def designation_dimensions(designation: str) -> tuple[float, float, float] | None:
    """(d, D, B) [m] of ISO 15 for a plain designation of the covered series (``6208``, ``7208``, ``7208 BECBP``:
    the first four digits), None for any other name (``ACBB-120``)."""
    m = re.match(r"^(6[023]|7[023])(\d\d)(?!\d)", str(designation).strip())
    if m is None or m.group(2) not in _rows(m.group(1)):
        return None
    return boundary_dimensions(m.group(1), m.group(2))


def series_names() -> list[str]:
    """Every name of the series catalogue, deep-groove series first."""
    names = []
    for series, spec in ISO15["series"].items():
        for code in _rows(series):
            if spec["type"] == "angular-contact":
                names += [f"{series}{code}{s}{SERIES_SUFFIX}" for s in _SUFFIXES]
            else:
                names.append(f"{series}{code}{SERIES_SUFFIX}")
    return names


def is_series_name(name) -> bool:
    """Whether ``name`` is spelt like a series-catalogue name (``6310-ISO``, ``7208B-ISO``, any case)."""
    return isinstance(name, str) and _NAME.match(name.strip()) is not None


def parse_series_name(name: str) -> tuple[str, str, str | None]:
    """(series, bore code, suffix) of a series-catalogue name; an InputError names what is wrong (a missing or
    needless contact-angle suffix, a bore code outside 00-20)."""
    m = _NAME.match(str(name).strip())
    if m is None:
        raise InputError(f"bearing: {name!r} is not a series-catalogue name (SERIES + BORE CODE [+ C|AC|B] + "
                         f"{SERIES_SUFFIX}, e.g. 6310{SERIES_SUFFIX}, 7208B{SERIES_SUFFIX})")
    series, code, suffix = m.group(1), m.group(2), (m.group(3) or "").upper() or None
    kind = ISO15["series"][series]["type"]
    if kind == "angular-contact" and suffix is None:
        raise InputError(f"bearing: {name!r} needs a contact-angle suffix: " + ", ".join(
            f"{series}{code}{s}{SERIES_SUFFIX} ({a:g} deg)" for s, a in _SUFFIXES.items()))
    if kind == "deep-groove" and suffix is not None:
        raise InputError(f"bearing: {name!r}: deep-groove series take no contact-angle suffix "
                         f"({series}{code}{SERIES_SUFFIX})")
    if code not in _rows(series):
        raise InputError(f"bearing: {name!r}: bore code {code} is outside the series catalogue (00 to 20: 10 to "
                         "100 mm bore)")
    return series, code, suffix


def series_entry(name: str) -> SeriesEntry:
    """The :class:`SeriesEntry` of a series-catalogue name."""
    series, code, suffix = parse_series_name(name)
    d, big_d, width = boundary_dimensions(series, code)
    kind = ISO15["series"][series]["type"]
    angle = _SUFFIXES[suffix] if suffix else 0.0
    return SeriesEntry(f"{series}{code}{suffix or ''}{SERIES_SUFFIX}", series, code, kind, d, big_d, width, angle)


def cn_clearance(bore: float) -> tuple[float, float]:
    """(min, max) [m] of the normal radial internal clearance group CN of ISO 5753-1 (radial contact groove ball
    bearings, unmounted) for a bore ``bore`` [m] of 6 to 100 mm (``iso15.json``, ``clearance_CN``)."""
    d = 1e3 * float(bore)
    for over, incl, lo, hi in ISO15["clearance_CN"]["rows"]:
        if over < d <= incl + 1e-9:
            return 1e-6 * lo, 1e-6 * hi
    raise InputError(f"bore: {d:g} mm lies outside the CN table of the series catalogue (over 6 up to 100 mm)")


def estimate_internal_geometry(bore: float, outer_diameter: float, angular: bool) -> dict:
    """The rule's internal geometry (module docstring) of a bearing of bore ``bore`` and outside diameter
    ``outer_diameter`` [m]: ``n_balls``, ``ball_diameter``, ``pitch_diameter``, ``inner_conformity``,
    ``outer_conformity``, ``diametral_clearance``, ``cage_ball_radius`` (SI).

    >>> g = estimate_internal_geometry(25e-3, 52e-3, angular=False)   # the CWRU 6205: 9 x 7.94 mm
    >>> g["n_balls"], round(g["ball_diameter"] * 1e3, 3), round(g["pitch_diameter"] * 1e3, 2)
    (9, 7.938, 38.5)
    """
    d, big_d = float(bore), float(outer_diameter)
    dm = 0.5 * (d + big_d)
    dw = round(BALL_FACTOR * (big_d - d) / BALL_STEP) * BALL_STEP
    arc = 2.0 * math.asin(dw / dm)
    if angular:
        z = math.floor(math.radians(ANGULAR_FILL_DEG) / arc + 1e-9)
        pd = 0.0
    else:
        z = 1 + math.floor(math.radians(CONRAD_FILL_DEG) / arc + 1e-9)
        pd = sum(cn_clearance(d)) / 2.0
    rz = dm * math.sin(math.pi / (2 * z)) - 0.5 * dw - POCKET_CLEARANCE * dw
    fi, fo = STANDARD_CONFORMITY
    return {"n_balls": z, "ball_diameter": dw, "pitch_diameter": dm, "inner_conformity": fi,
            "outer_conformity": fo, "diametral_clearance": pd, "cage_ball_radius": rz}


def series_bearing(name: str, material: Material | None = None) -> BallBearing:
    """The BallBearing of a series-catalogue name (module docstring), built from its ISO 15 boundary dimensions
    and the rule's internal geometry, every estimated quantity listed in ``estimated``."""
    e = series_entry(name)
    g = estimate_internal_geometry(e.bore, e.outer_diameter, e.kind == "angular-contact")
    ds = ISO15["series"][e.series]["dimension_series"]
    angle = f", nominal contact angle {e.contact_angle_deg:g} deg" if e.contact_angle_deg else ""
    source = (f"{e.kind} ball bearing {e.bore * 1e3:g} x {e.outer_diameter * 1e3:g} x {e.width * 1e3:g} mm: "
              f"ISO 15:2017 boundary dimensions (dimension series {ds}){angle}. ESTIMATED internal geometry (not a "
              f"manufacturer's design; {', '.join(ESTIMATED)}) by the series rule of "
              "docs/theory/geometry.md#series-catalogue: "
              f"{g['n_balls']} balls of {g['ball_diameter'] * 1e3:.3f} mm on d_m = {g['pitch_diameter'] * 1e3:g} mm, "
              "conformities 0.52 / 0.53 (ISO 281's), "
              + (f"diametral clearance {g['diametral_clearance'] * 1e6:g} um (middle of ISO 5753-1 group CN)"
                 if e.kind == "deep-groove" else "diametral clearance 0 (set by mounting)")
              + "; load ratings from it lie within the band stated there of manufacturers' values")
    return BallBearing.from_dimensions(
        n_balls=g["n_balls"], ball_diameter=g["ball_diameter"], pitch_diameter=g["pitch_diameter"],
        inner_conformity=g["inner_conformity"], outer_conformity=g["outer_conformity"],
        diametral_clearance=g["diametral_clearance"], free_contact_angle=math.radians(e.contact_angle_deg),
        material=material, cage_ball_radius=g["cage_ball_radius"], name=e.name, source=source, bore=e.bore,
        outer_diameter=e.outer_diameter, estimated=ESTIMATED)
