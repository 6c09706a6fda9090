"""Numba DEM reference engine (does not import exudyn)."""
from .engine import ReferenceEngine

__all__ = ["ReferenceEngine"]
