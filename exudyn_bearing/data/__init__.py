"""Bearings, materials, lubricants and the catalogue: data, not models.

Every quantity is SI (m, Pa, kg, s, rad). Definitions are frozen dataclasses,
validated on construction: an impossible value raises :class:`InputError`
whose message starts with the name of the offending parameter.

Modules: :mod:`.errors` (InputError and the checks), :mod:`.materials`,
:mod:`.lubricants`, :mod:`.traction` (traction models), :mod:`.bearings` (BallBearing and its groove
construction), :mod:`.catalog` (``catalog.json``, look-up by name or file),
:mod:`.defects` (Defect: localized spalls on a race or a ball).
"""
from .bearings import MAX_FREE_CONTACT_ANGLE, MAX_PRELOAD_INTERFERENCE, BallBearing
from .catalog import (catalog, default_lubricant, default_traction, get_bearing, get_traction_model, load_bearing, load_lubricant,
                      lubricants, materials, traction_models)
from .defects import Defect
from .errors import InputError
from .lubricants import Lubricant, LubricantDefaultsWarning
from .materials import Material
from .traction import PARAMETER_NAMES as TRACTION_PARAMETERS, TRACTION_KINDS, TractionModel

__all__ = ["InputError", "Material", "Lubricant", "LubricantDefaultsWarning", "BallBearing", "catalog", "materials", "lubricants",
           "get_bearing", "load_bearing", "load_lubricant", "default_lubricant", "default_traction",
           "TractionModel", "TRACTION_KINDS", "TRACTION_PARAMETERS", "traction_models", "get_traction_model", "MAX_FREE_CONTACT_ANGLE", "MAX_PRELOAD_INTERFERENCE",
           "Defect"]
