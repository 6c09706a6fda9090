"""The catalogue: materials, lubricants, traction models and bearings of
``catalog.json``, and bearing and lubricant look-up by name, JSON file or dict.

Each entry of ``catalog.json`` carries its ``source``. See docs/theory/geometry.md.

A bearing is given in one of two forms (lengths in metres, the free contact
angle as ``free_contact_angle_deg`` in degrees or ``free_contact_angle`` in
radians as in Python, not both; a value that reads in the other unit is
refused), ``material`` a material name or a dict of
:class:`~.materials.Material` fields, optional ``name``, ``source``,
``cage_ball_radius``, ``bore``, ``outer_diameter``):

* race radii, as in ``catalog.json``: ``n_balls``, ``ball_radius``,
  ``inner_race_radius``, ``outer_race_radius``, ``inner_groove_radius``,
  ``outer_groove_radius``;
* dimensions of a data sheet (:meth:`BallBearing.from_dimensions`):
  ``n_balls``, ``ball_diameter``, ``pitch_diameter``, optional
  ``inner_conformity``, ``outer_conformity`` (not given: ISO 281's 0.52 /
  0.53, marked as estimated, with a warning) and ``diametral_clearance``
  (default 0); the same keys may also sit in a ``"dimensions"`` object.

Either form may list ``estimated`` quantities (names of the fields).

Besides the papers' validated bearings of ``catalog.json`` (``catalog``:
6208, 7208, 6004, 6205, ACBB-120), the series catalogue
(:mod:`.series`, ``series_catalog``) holds the deep-groove 60, 62, 63 and
angular-contact 70, 72, 73 series of bore codes 00-20 under names such as
``6310-ISO`` and ``7208B-ISO``: ISO 15 boundary dimensions and an estimated
internal geometry (docs/theory/geometry.md#series-catalogue).

A JSON file holds one bearing, or is shaped like ``catalog.json``
(``"bearings"``, optional ``"materials"`` and ``"lubricants"``): its only
bearing is used, or the one named after ``#`` (``my_bearings.json#6205``);
its materials can be named by its bearings. Lubricants load alike
(:func:`load_lubricant`).
"""
from __future__ import annotations

import dataclasses
import json
import warnings
import math
from importlib import resources
from pathlib import Path
from typing import Mapping

from .bearings import BallBearing, free_contact_angle_from_degrees
from .errors import InputError, check_keys, lookup
from .lubricants import Lubricant, LubricantDefaultsWarning
from .materials import Material
from .series import SERIES_SUFFIX, designation_dimensions, is_series_name, series_bearing, series_entry, series_names
from .traction import TractionModel

__all__ = ["catalog", "series_catalog", "catalog_listing", "materials", "lubricants", "traction_models", "get_bearing", "load_bearing", "load_lubricant",
           "default_lubricant", "default_traction", "get_traction_model", "BEARING_KEYS", "DIMENSION_KEYS",
           "PAPERS_LUBRICANT", "PAPERS_TRACTION"]

#: Keys of a bearing in the race-radii form (the fields of BallBearing).
BEARING_KEYS = tuple(f.name for f in dataclasses.fields(BallBearing)) + ("free_contact_angle_deg",)
#: Keys of a bearing in the dimensions form (:meth:`BallBearing.from_dimensions`).
DIMENSION_KEYS = ("n_balls", "ball_diameter", "pitch_diameter", "inner_conformity", "outer_conformity",
                  "diametral_clearance", "free_contact_angle", "free_contact_angle_deg", "material", "cage_ball_radius", "name", "source",
                  "bore", "outer_diameter", "lubricant", "traction", "estimated")
_MATERIAL_KEYS = tuple(f.name for f in dataclasses.fields(Material))
_LUBRICANT_KEYS = tuple(f.name for f in dataclasses.fields(Lubricant))


def _read_catalog() -> dict:
    text = resources.files(__package__).joinpath("catalog.json").read_text()
    return json.loads(text)


_RAW = _read_catalog()
materials: Mapping[str, Material] = {
    k: Material(name=k, **v) for k, v in _RAW["materials"].items()}
lubricants: Mapping[str, Lubricant] = {
    k: Lubricant(name=k, **v) for k, v in _RAW["lubricants"].items()}
traction_models: Mapping[str, TractionModel] = {
    k: TractionModel(name=k, **v) for k, v in _RAW.get("traction_models", {}).items()}


#: The DEM papers' lubricant and traction model: the defaults of a bearing that names none.
PAPERS_LUBRICANT, PAPERS_TRACTION = "guessasma2018", "lambda_dem"


def default_traction(bearing=None) -> str:
    """Name of the default traction model of ``bearing`` (its ``traction``),
    else the DEM papers' mu(Lambda), ``lambda_dem``."""
    return getattr(bearing, "traction", None) or PAPERS_TRACTION


def get_traction_model(spec, bearing=None) -> TractionModel:
    """A traction model by catalogue name (or a TractionModel passed through);
    None: the default of ``bearing`` (:func:`default_traction`). An unknown
    name lists the valid ones."""
    if spec is None:
        spec = default_traction(bearing)
    if isinstance(spec, TractionModel):
        return spec
    return lookup(traction_models, str(spec), "traction: unknown traction model")


def _material_from_dict(name: str, d) -> Material:
    if not isinstance(d, Mapping):
        raise InputError(f"material: expected a material name or an object of material parameters, got {d!r}")
    check_keys("material parameter", d, _MATERIAL_KEYS)
    return Material(**dict({"name": name}, **d))


#: The values a lubricant file or dict leaves out are the papers' oil's (Lubricant's defaults); these are named
#: when left out (what sets the film and the friction), the others (name, source) are not.
_LUBRICANT_PHYSICAL = tuple(k for k in _LUBRICANT_KEYS if k not in ("name", "source"))


def _lubricant_from_dict(name: str, d) -> Lubricant:
    """A Lubricant from a file's or a dict's values: the viscosity is needed (a lubricant without it is no
    lubricant), the other values left out are the papers' oil's, named in a :class:`LubricantDefaultsWarning`."""
    if not isinstance(d, Mapping):
        raise InputError(f"lubricant: expected an object of lubricant parameters, got {d!r}")
    check_keys("lubricant parameter", d, _LUBRICANT_KEYS)
    if "viscosity" not in d:
        raise InputError(f"viscosity: the lubricant {name!r} gives no viscosity [Pa s] (its values: "
                         f"{', '.join(d) or 'none'}); a lubricant needs at least its viscosity at the operating "
                         "temperature")
    missing = [k for k in _LUBRICANT_PHYSICAL if k not in d]
    if missing:
        base = Lubricant()
        warnings.warn(LubricantDefaultsWarning(
            f"lubricant {name!r}: {', '.join(f'{k} = {getattr(base, k):g}' for k in missing)} not given, taken from "
            f"the papers' oil ({base.name}, docs/theory/lubrication.md)"), stacklevel=3)
    return Lubricant(**dict({"name": name}, **d))


def _bearing_from_dict(name: str, d: Mapping, extra_materials: Mapping | None = None) -> BallBearing:
    d = dict(d)
    if isinstance(d.get("dimensions"), Mapping):
        dims = d.pop("dimensions")
        both = sorted(set(dims) & set(d))
        if both:
            raise InputError(f"{both[0]}: given both inside and outside 'dimensions'")
        d.update(dims)
    dimensions = "pitch_diameter" in d or "ball_diameter" in d
    if dimensions:
        radii = sorted(set(d) & (set(BEARING_KEYS) - set(DIMENSION_KEYS)))
        if radii:
            raise InputError(f"{radii[0]}: give the race radii (inner_race_radius, ...) or the dimensions "
                             "(ball_diameter, pitch_diameter, inner_conformity, ...) of a bearing, not both")
        check_keys("bearing parameter (dimensions form)", d, DIMENSION_KEYS)
        required = ("n_balls", "ball_diameter", "pitch_diameter")
    else:
        check_keys("bearing parameter", d, BEARING_KEYS)
        required = ("n_balls", "ball_radius", "inner_race_radius", "outer_race_radius",
                    "inner_groove_radius", "outer_groove_radius")
    mat = d.pop("material", "steel")
    if isinstance(mat, str):
        known = dict(materials, **(extra_materials or {}))
        if mat not in known:
            raise InputError(f"material: unknown material {mat!r} (valid: {', '.join(known)})")
        mat = known[mat]
    else:
        mat = _material_from_dict(str(mat.get("name", "custom")) if isinstance(mat, Mapping) else "custom", mat)
    for key in required:
        if key not in d:
            raise InputError(f"{key}: missing")
    if "free_contact_angle_deg" in d:
        if "free_contact_angle" in d:
            raise InputError("free_contact_angle: given both in radians (free_contact_angle) and in degrees "
                             "(free_contact_angle_deg); give one")
        d["free_contact_angle"] = free_contact_angle_from_degrees(d.pop("free_contact_angle_deg"))
    d.setdefault("name", name)
    if d.get("lubricant") is not None and d["lubricant"] not in lubricants:
        raise InputError(f"lubricant: unknown lubricant {d['lubricant']!r} (catalogue: {', '.join(lubricants)})")
    if d.get("traction") is not None:
        get_traction_model(d["traction"])
    if dimensions:
        return BallBearing.from_dimensions(material=mat, **d)
    return BallBearing(material=mat, **d)


def _split_name(spec: str) -> tuple[str, str | None]:
    """'file.json#name' -> ('file.json', 'name'); no '#': (spec, None)."""
    if "#" in spec:
        path, name = spec.rsplit("#", 1)
        if Path(path).suffix.lower() == ".json" or Path(path).is_file():
            return path, name
    return spec, None


def _read_json(what: str, path: Path) -> Mapping:
    if not path.is_file():
        raise InputError(f"{what}: no such file {str(path)!r}")
    try:
        d = json.loads(path.read_text())
    except json.JSONDecodeError as exc:
        raise InputError(f"{what}: {path} is not valid JSON ({exc})") from None
    if not isinstance(d, Mapping):
        raise InputError(f"{what}: {path} must hold a JSON object")
    return d


def _pick(what: str, section: str, entries, name: str | None, source: str):
    """The entry ``name`` of a catalogue section, or its only entry."""
    if not isinstance(entries, Mapping) or not entries:
        raise InputError(f"{what}: {source} has no entries under {section!r}")
    if name is None:
        if len(entries) > 1:
            raise InputError(f"{what}: {source} holds {len(entries)} entries under {section!r} "
                             f"({', '.join(entries)}); pick one with {source}#NAME")
        name = next(iter(entries))
    if name not in entries:
        raise InputError(f"{what}: no {name!r} in {source} (valid: {', '.join(entries)})")
    return name, entries[name]


catalog: Mapping[str, BallBearing] = {
    k: _bearing_from_dict(k, v) for k, v in _RAW["bearings"].items()}


class _SeriesCatalog(Mapping):
    """The series catalogue (:mod:`.series`) as a read-only mapping name -> BallBearing; an entry is built from
    the ISO 15 table and the rule when first asked for (names in any case: ``6310-iso``)."""

    def __init__(self):
        self._names = tuple(series_names())
        self._known = frozenset(self._names)
        self._built: dict[str, BallBearing] = {}

    def __getitem__(self, name) -> BallBearing:
        key = str(name).strip().upper()
        if key not in self._known:
            raise KeyError(name)
        if key not in self._built:
            self._built[key] = series_bearing(key, material=materials["steel"])
        return self._built[key]

    def __contains__(self, name) -> bool:
        return isinstance(name, str) and name.strip().upper() in self._known

    def __iter__(self):
        return iter(self._names)

    def __len__(self) -> int:
        return len(self._names)


#: The series catalogue: ``6000-ISO`` ... ``6320-ISO``, ``7000C-ISO`` ... ``7320B-ISO`` (:mod:`.series`).
series_catalog: Mapping[str, BallBearing] = _SeriesCatalog()


def get_bearing(name: str) -> BallBearing:
    """Catalogue bearing by name: a validated entry of ``catalog.json`` or a series-catalogue name
    (``6310-ISO``, ``7208B-ISO``); an unknown name lists the valid ones."""
    if name in catalog:
        return catalog[name]
    if name in series_catalog:
        return series_catalog[name]
    if is_series_name(name):  # spelt like one but not in it: say what is wrong
        series_bearing(name)
    raise InputError(f"bearing: unknown bearing {name!r} (catalogue: {', '.join(catalog)}; series catalogue: "
                     f"60NN, 62NN, 63NN{SERIES_SUFFIX} and 70NN, 72NN, 73NN + C|AC|B + {SERIES_SUFFIX}, bore codes "
                     f"NN 00-20, e.g. 6310{SERIES_SUFFIX}, 7208B{SERIES_SUFFIX}; `info --list` lists them)")


def catalog_listing() -> list[dict]:
    """One row per catalogue bearing, the validated entries first, then the series catalogue: ``name``,
    ``type`` (deep-groove / angular-contact), ``bore``, ``outer_diameter``, ``width`` [m] (the entry's, else
    ISO 15's for its designation; None where unknown), ``n_balls``, ``ball_diameter`` [m],
    ``free_contact_angle_deg``, ``geometry`` ("data sheet" for the papers' validated entries, "estimated" for
    the series rule's) and ``estimated`` (the estimated fields)."""
    rows = []
    for name, b in list(catalog.items()) + list(series_catalog.items()):
        iso = series_entry(name) if name in series_catalog else None
        dims = (iso.bore, iso.outer_diameter, iso.width) if iso else designation_dimensions(name)
        bore = b.bore if b.bore is not None else (dims[0] if dims else None)
        outside = b.outer_diameter if b.outer_diameter is not None else (dims[1] if dims else None)
        width = dims[2] if dims and abs(dims[0] - bore) < 1e-9 and abs(dims[1] - outside) < 1e-9 else None
        nm = (lambda x: None if x is None else round(x, 9))  # lengths to the nanometre (no float noise)
        rows.append({"name": name, "type": "angular-contact" if b.free_contact_angle > 0.0 else "deep-groove",
                     "bore": nm(bore), "outer_diameter": nm(outside), "width": nm(width), "n_balls": b.n_balls,
                     "ball_diameter": nm(b.ball_diameter),
                     "free_contact_angle_deg": round(math.degrees(b.free_contact_angle), 9),
                     "geometry": "estimated" if b.estimated else "data sheet", "estimated": list(b.estimated)})
    return rows


def load_bearing(spec, name: str | None = None) -> BallBearing:
    """A BallBearing from a catalogue name, a JSON file path or a dict.

    A dict or file holds one bearing (race radii or dimensions, module
    docstring) or is shaped like ``catalog.json`` (``"bearings"``, with
    optional ``"materials"``): then its only bearing, or the one named by
    ``name`` or after ``#`` in the path (``file.json#6205``).

    >>> load_bearing({"n_balls": 9, "ball_diameter": 12.6e-3, "pitch_diameter": 60.6e-3,
    ...               "inner_conformity": 0.52, "outer_conformity": 0.52}).outer_race_radius
    0.0366
    """
    if isinstance(spec, BallBearing):
        return spec
    if isinstance(spec, Mapping):
        return _bearing_from_mapping(spec, name, "the bearing dict", str(spec.get("name", "custom")))
    spec = str(spec)
    if spec in catalog and name is None:
        return catalog[spec]
    if spec in series_catalog and name is None and not Path(spec).exists():
        return series_catalog[spec]
    path, picked = _split_name(spec)
    path = Path(path)
    if path.suffix.lower() == ".json" or path.exists():
        return _bearing_from_mapping(_read_json("bearing", path), picked or name, str(path), path.stem)
    return get_bearing(spec)


def _bearing_from_mapping(d: Mapping, name, source: str, default_name: str) -> BallBearing:
    if "bearings" in d:
        check_keys("catalogue section", d, ("bearings", "materials", "lubricants", "traction_models"))
        extra = {k: _material_from_dict(k, v) for k, v in (d.get("materials") or {}).items()}
        name, entry = _pick("bearing", "bearings", d["bearings"], name, source)
        if not isinstance(entry, Mapping):
            raise InputError(f"bearing: the entry {name!r} of {source} must be an object")
        return _bearing_from_dict(name, entry, extra)
    return _bearing_from_dict(str(d.get("name", default_name)), d)


def load_lubricant(spec=None, name: str | None = None, bearing=None) -> Lubricant:
    """A Lubricant from a catalogue name, a JSON file path or a dict: one
    lubricant's fields (:class:`~.lubricants.Lubricant`), or a
    catalogue-shaped ``{"lubricants": {...}}`` whose only entry, or the one
    named by ``name`` or after ``#``, is used. None: the default lubricant of
    ``bearing`` (:func:`default_lubricant`)."""
    if spec is None:
        return default_lubricant(bearing)
    if isinstance(spec, Lubricant):
        return spec
    if isinstance(spec, Mapping):
        d, source, default_name = spec, "the lubricant dict", "custom"
    else:
        spec = str(spec)
        if spec in lubricants and name is None:
            return lubricants[spec]
        path, picked = _split_name(spec)
        path = Path(path)
        if not (path.suffix.lower() == ".json" or path.exists()):
            raise InputError(f"lubricant: unknown lubricant {spec!r} (catalogue: {', '.join(lubricants)}; "
                             "or a JSON file)")
        d, source, default_name, name = _read_json("lubricant", path), str(path), path.stem, picked or name
    if "lubricants" in d:
        check_keys("catalogue section", d, ("bearings", "materials", "lubricants", "traction_models"))
        key, entry = _pick("lubricant", "lubricants", d["lubricants"], name, source)
        return _lubricant_from_dict(key, entry)
    d = dict(d)
    return _lubricant_from_dict(str(d.pop("name", default_name)), d)


def default_lubricant(bearing=None) -> Lubricant:
    """The lubricant ``bearing`` names (its ``lubricant``, a catalogue name),
    else the DEM papers' (``guessasma2018``, docs/theory/lubrication.md#film-thickness)."""
    name = getattr(bearing, "lubricant", None) or PAPERS_LUBRICANT
    return lookup(lubricants, name, f"lubricant: bearing {getattr(bearing, 'name', '')} names the unknown lubricant")
