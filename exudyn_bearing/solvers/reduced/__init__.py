"""The reduced engine: ball centres on their force balance, a linearly implicit step (docs/theory/reduced.md)."""
from .engine import ReducedEngine

__all__ = ["ReducedEngine"]
