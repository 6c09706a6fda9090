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
  ``n_balls``, ``ball_diameter``, ``pitch_diameter``, ``inner_conformity``,
  ``outer_conformity``, optional ``diametral_clearance`` (default 0); the
  same keys may also sit in a ``"dimensions"`` object.

A JSON file holds one bearing, or is shaped like ``catalog.json``
(``"bearings"``, optional ``"materials"`` and ``"lubricants"``): its only
bearing is used, or the one named after ``#`` (``my_bearings.json#6205``);
its materials can be named by its bearings. Lubricants load alike
(:func:`load_lubricant`).
"""
from __future__ import annotations

import dataclasses
import json
from importlib import resources
from pathlib import Path
from typing import Mapping

from .bearings import BallBearing, free_contact_angle_from_degrees
from .errors import InputError, check_keys, lookup
from .lubricants import Lubricant
from .materials import Material
from .traction import TractionModel

__all__ = ["catalog", "materials", "lubricants", "traction_models", "get_bearing", "load_bearing", "load_lubricant",
           "default_lubricant", "default_traction", "get_traction_model", "BEARING_KEYS", "DIMENSION_KEYS",
           "PAPERS_LUBRICANT", "PAPERS_TRACTION"]

#: Keys of a bearing in the race-radii form (the fields of BallBearing).
BEARING_KEYS = tuple(f.name for f in dataclasses.fields(BallBearing)) + ("free_contact_angle_deg",)
#: Keys of a bearing in the dimensions form (:meth:`BallBearing.from_dimensions`).
DIMENSION_KEYS = ("n_balls", "ball_diameter", "pitch_diameter", "inner_conformity", "outer_conformity",
                  "diametral_clearance", "free_contact_angle", "free_contact_angle_deg", "material", "cage_ball_radius", "name", "source",
                  "bore", "outer_diameter", "lubricant", "traction")
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


def _lubricant_from_dict(name: str, d) -> Lubricant:
    if not isinstance(d, Mapping):
        raise InputError(f"lubricant: expected an object of lubricant parameters, got {d!r}")
    check_keys("lubricant parameter", d, _LUBRICANT_KEYS)
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
        required = ("n_balls", "ball_diameter", "pitch_diameter", "inner_conformity", "outer_conformity")
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


def get_bearing(name: str) -> BallBearing:
    """Catalogue bearing by name; an unknown name lists the valid ones."""
    return lookup(catalog, name, "bearing: unknown bearing")


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
