"""exudyn_bearing: rolling-element ball bearings for the Exudyn multibody simulator.

Layers (each imports only the ones above it in this list): :mod:`.data`
(bearings, materials, lubricants) -> :mod:`.physics` (pure relations) ->
:mod:`.model` (the compiled bearing model) -> :mod:`.solvers` -> :mod:`.outputs`
-> :mod:`.simulate`, :mod:`.sweep` and :mod:`.cli`. See README, "Architecture".

>>> import exudyn_bearing as eb
>>> run = eb.simulate("6208", eb.Scenario(Fr=3000, omega=500, t_end=0.004, dt=2e-6))  # doctest: +SKIP
>>> run.plot("6208.png"); print(run.summary())                                        # doctest: +SKIP
"""
from __future__ import annotations

import sys
import types
from importlib import import_module
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # the public names, imported on first use by __getattr__ below (the same modules)
    from .data import (BallBearing, Defect, InputError, Lubricant, Material, catalog, get_bearing, load_bearing,
                       load_lubricant, lubricants, materials)
    from .data.cages import CageMaterial, CageTemperatureWarning, RigidCage, estimated_cage
    from .model.coefficients import BearingCoefficients
    from .model.scenario import Scenario
    from .model.stability import SimulationError, StepSizeWarning
    from .outputs.results import EnergyBalanceWarning, Results, SteadyStateWarning
    from .simulate import CreateBallBearing, simulate
    from .solvers.element.console import filter_exudyn_notes
    from .solvers.quasistatic import QuasiStaticSolution, bearing_coefficients, solve_quasistatic
    from .physics.rating_life import RatingLife, rating_life
    from .solvers.quasistatic.levels.linear import LinearValidityWarning
    from .solvers.quasistatic.pair import PairSolution, solve_pair
    from .solvers.quasistatic.inertia import BallInertiaWarning
    from .solvers.quasistatic.solve import KinematicsIterationWarning, TractionResolutionWarning
    from .solvers.quasistatic.thermal import ThermalSolution, solve_thermal

#: Module of each public name. ``import exudyn_bearing`` loads none of them (numba, scipy, the
#: compiled kernels' dispatchers): ``python -m exudyn_bearing --help`` and every command import only
#: what they use; the first ``exudyn_bearing.NAME`` imports them all (what this file imported before).
_PUBLIC = {
    ".data": ("BallBearing", "Defect", "InputError", "Lubricant", "Material", "catalog", "get_bearing", "load_bearing",
              "load_lubricant", "lubricants", "materials"),
    ".data.cages": ("CageMaterial", "CageTemperatureWarning", "RigidCage", "estimated_cage"),
    ".model.coefficients": ("BearingCoefficients",),
    ".model.scenario": ("Scenario",),
    ".model.stability": ("SimulationError", "StepSizeWarning"),
    ".outputs.results": ("EnergyBalanceWarning", "Results", "SteadyStateWarning"),
    ".simulate": ("CreateBallBearing", "simulate"),
    ".solvers.element.console": ("filter_exudyn_notes",),
    ".solvers.quasistatic": ("QuasiStaticSolution", "bearing_coefficients", "solve_quasistatic"),
    ".physics.rating_life": ("RatingLife", "rating_life"),
    ".solvers.quasistatic.levels.linear": ("LinearValidityWarning",),
    ".solvers.quasistatic.pair": ("PairSolution", "solve_pair"),
    ".solvers.quasistatic.inertia": ("BallInertiaWarning",),
    ".solvers.quasistatic.solve": ("KinematicsIterationWarning", "TractionResolutionWarning"),
    ".solvers.quasistatic.thermal": ("ThermalSolution", "solve_thermal"),
}
_MODULE_OF = {name: module for module, names in _PUBLIC.items() for name in names}
#: Submodules reachable as attributes (``eb.data.lubricants``).
_SUBMODULES = ("cli", "data", "datasets", "model", "outputs", "physics", "solvers", "sweep")

__version__ = "0.1.0"

__all__ = ["CreateBallBearing", "filter_exudyn_notes", "BallBearing", "Defect", "InputError", "Lubricant", "Material",
           "EnergyBalanceWarning", "Results", "Scenario", "SimulationError", "SteadyStateWarning", "StepSizeWarning", "catalog", "get_bearing", "load_bearing",
           "load_lubricant", "lubricants", "materials", "simulate", "solve_quasistatic", "QuasiStaticSolution",
           "bearing_coefficients", "BearingCoefficients", "solve_thermal", "ThermalSolution", "LinearValidityWarning",
           "TractionResolutionWarning", "KinematicsIterationWarning", "BallInertiaWarning", "RatingLife", "rating_life", "solve_pair", "PairSolution",
           "CageMaterial", "CageTemperatureWarning", "RigidCage", "estimated_cage"]


def __getattr__(name):
    if name not in _SUBMODULES and name not in _MODULE_OF:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    # the first access loads what the eager import loaded (so that eb.model.scenario and the like are
    # there as before); the import binds each submodule to the package
    for module in _PUBLIC:
        import_module(module, __name__)
    if name in _SUBMODULES:
        return import_module(f".{name}", __name__)
    value = getattr(import_module(_MODULE_OF[name], __name__), name)
    setattr(sys.modules[__name__], name, value)
    return value


def __dir__():
    return sorted(set(globals()) | set(__all__))


class _Package(types.ModuleType):
    """The package module. Importing the submodule ``exudyn_bearing.simulate`` binds it to the package's
    attribute ``simulate``; the package's ``simulate`` stays the function (as when this file imported it)."""

    def __setattr__(self, name, value):
        if name == "simulate" and isinstance(value, types.ModuleType):
            value = value.simulate
        super().__setattr__(name, value)


sys.modules[__name__].__class__ = _Package
