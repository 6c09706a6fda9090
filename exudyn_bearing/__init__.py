"""exudyn_bearing: rolling-element ball bearings for the Exudyn multibody simulator."""
from .data import (BallBearing, InputError, Lubricant, Material, catalog, get_bearing,
                   load_bearing, lubricants, materials)

__version__ = "0.1.0"
