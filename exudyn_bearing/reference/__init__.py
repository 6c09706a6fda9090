"""Numba DEM reference engine (does not import exudyn)."""
from .engine import ReferenceEngine, SimulationError, StepSizeWarning, ring_mass_estimate, stable_step

__all__ = ["ReferenceEngine", "SimulationError", "StepSizeWarning", "stable_step", "ring_mass_estimate"]
