"""exudyn_bearing: rolling-element ball bearings for the Exudyn multibody simulator.

>>> import exudyn_bearing as eb
>>> run = eb.simulate("6208", eb.Scenario(Fr=3000, omega=500, t_end=0.004, dt=2e-6))  # doctest: +SKIP
>>> run.plot("6208.png"); print(run.summary())                                        # doctest: +SKIP
"""
from .data import (BallBearing, InputError, Lubricant, Material, catalog, get_bearing,
                   load_bearing, lubricants, materials)
from .scenario import Scenario
from .simulate import simulate


def CreateBallBearing(mbs, bearing, markerInnerRing, markerOuterRing, **options):
    """Add a lubricated DEM ball bearing between two ring markers of an Exudyn
    ``mbs`` (see :func:`exudyn_bearing.element.CreateBallBearing`)."""
    from .element import CreateBallBearing as create

    return create(mbs, bearing, markerInnerRing, markerOuterRing, **options)

__version__ = "0.1.0"

__all__ = ["CreateBallBearing", "BallBearing", "InputError", "Lubricant", "Material", "Scenario", "catalog", "get_bearing",
           "load_bearing", "lubricants", "materials", "simulate"]
