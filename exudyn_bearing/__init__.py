"""exudyn_bearing: rolling-element ball bearings for the Exudyn multibody simulator.

Layers (each imports only the ones above it in this list): :mod:`.data`
(bearings, materials, lubricants) -> :mod:`.physics` (pure relations) ->
:mod:`.model` (the compiled bearing model) -> :mod:`.solvers` -> :mod:`.outputs`
-> :mod:`.simulate`, :mod:`.sweep` and :mod:`.cli`. See README, "Architecture".

>>> import exudyn_bearing as eb
>>> run = eb.simulate("6208", eb.Scenario(Fr=3000, omega=500, t_end=0.004, dt=2e-6))  # doctest: +SKIP
>>> run.plot("6208.png"); print(run.summary())                                        # doctest: +SKIP
"""
from .data import (BallBearing, Defect, InputError, Lubricant, Material, catalog, get_bearing, load_bearing, load_lubricant,
                   lubricants, materials)
from .model.scenario import Scenario
from .model.stability import SimulationError, StepSizeWarning
from .outputs.results import Results, SteadyStateWarning
from .simulate import CreateBallBearing, simulate
from .model.coefficients import BearingCoefficients
from .solvers.element.console import filter_exudyn_notes
from .solvers.quasistatic import QuasiStaticSolution, bearing_coefficients, solve_quasistatic
from .solvers.quasistatic.thermal import ThermalSolution, solve_thermal

__version__ = "0.1.0"

__all__ = ["CreateBallBearing", "filter_exudyn_notes", "BallBearing", "Defect", "InputError", "Lubricant", "Material",
           "Results", "Scenario", "SimulationError", "SteadyStateWarning", "StepSizeWarning", "catalog", "get_bearing", "load_bearing",
           "load_lubricant", "lubricants", "materials", "simulate", "solve_quasistatic", "QuasiStaticSolution",
           "bearing_coefficients", "BearingCoefficients", "solve_thermal", "ThermalSolution"]
