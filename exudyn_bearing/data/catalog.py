"""The catalogue: materials, lubricants, traction models and bearings of
``catalog.json``, and bearing look-up by name, JSON file or dict.

Each entry of ``catalog.json`` carries its ``source``. See PHYSICS.md sec. 2.
"""
from __future__ import annotations

import dataclasses
import json
import math
from importlib import resources
from pathlib import Path
from typing import Mapping

from .bearings import BallBearing
from .errors import InputError, check_finite
from .lubricants import Lubricant
from .materials import Material
from .traction import TractionModel

__all__ = ["catalog", "materials", "lubricants", "traction_models", "get_bearing", "load_bearing",
           "default_lubricant", "get_traction_model"]


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


def get_traction_model(spec) -> TractionModel:
    """A traction model by catalogue name (or a TractionModel passed through);
    an unknown name lists the valid ones."""
    if isinstance(spec, TractionModel):
        return spec
    try:
        return traction_models[str(spec)]
    except KeyError:
        raise InputError(f"traction: unknown traction model {spec!r} "
                         f"(catalogue: {', '.join(traction_models)})") from None


def _bearing_from_dict(name: str, d: Mapping) -> BallBearing:
    d = dict(d)
    known = {f.name for f in dataclasses.fields(BallBearing)}
    unknown = sorted(set(d) - known)
    if unknown:
        raise InputError(f"{unknown[0]}: unknown bearing parameter (valid: {', '.join(sorted(known))})")
    mat = d.pop("material", "steel")
    if isinstance(mat, str):
        if mat not in materials:
            raise InputError(f"material: unknown material {mat!r} (valid: {', '.join(materials)})")
        mat = materials[mat]
    elif isinstance(mat, Mapping):
        mat = Material(**mat)
    for required in ("n_balls", "ball_radius", "inner_race_radius", "outer_race_radius",
                     "inner_groove_radius", "outer_groove_radius"):
        if required not in d:
            raise InputError(f"{required}: missing")
    d["free_contact_angle"] = math.radians(check_finite("free_contact_angle", d.get("free_contact_angle", 0.0)))
    d.setdefault("name", name)
    return BallBearing(material=mat, **d)


catalog: Mapping[str, BallBearing] = {
    k: _bearing_from_dict(k, v) for k, v in _RAW["bearings"].items()}


def get_bearing(name: str) -> BallBearing:
    """Catalogue bearing by name; an unknown name lists the valid ones."""
    try:
        return catalog[name]
    except KeyError:
        raise InputError(f"bearing: unknown bearing {name!r} (catalogue: {', '.join(catalog)})") from None


def load_bearing(spec) -> BallBearing:
    """A BallBearing from a catalogue name, a JSON file path or a dict.

    The JSON format is that of a ``bearings`` entry of ``catalog.json``:
    lengths in metres, ``free_contact_angle`` in degrees, ``material`` a
    catalogue name or a dict of Material fields.
    """
    if isinstance(spec, BallBearing):
        return spec
    if isinstance(spec, Mapping):
        return _bearing_from_dict(str(spec.get("name", "custom")), spec)
    spec = str(spec)
    if spec in catalog:
        return catalog[spec]
    path = Path(spec)
    if path.suffix.lower() == ".json" or path.exists():
        if not path.is_file():
            raise InputError(f"bearing: no such file {spec!r}")
        try:
            d = json.loads(path.read_text())
        except json.JSONDecodeError as exc:
            raise InputError(f"bearing: {spec} is not valid JSON ({exc})") from None
        if not isinstance(d, Mapping):
            raise InputError(f"bearing: {spec} must hold a JSON object")
        return _bearing_from_dict(d.get("name", path.stem), d)
    return get_bearing(spec)


def default_lubricant() -> Lubricant:
    """The DEM papers' lubricant (PHYSICS.md sec. 5)."""
    return lubricants["guessasma2018"]
