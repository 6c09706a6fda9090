"""The input error of the package and the checks that raise it.

Every check names the parameter first, so that a message reads
``"ball_radius: must be > 0, got -0.001"`` wherever it surfaces (API, JSON
file or command line).
"""
from __future__ import annotations

import math

__all__ = ["InputError", "check_finite", "check_positive", "check_nonnegative"]


class InputError(ValueError):
    """Invalid bearing, material, lubricant or scenario input.

    The message starts with the parameter name.
    """


def check_finite(name: str, value) -> float:
    """``value`` as a finite float, else InputError naming ``name``."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{name}: expected a number, got {value!r}") from None
    if not math.isfinite(v):
        raise InputError(f"{name}: must be finite, got {v}")
    return v


def check_positive(name: str, value) -> float:
    """``value`` as a float > 0, else InputError naming ``name``."""
    v = check_finite(name, value)
    if v <= 0.0:
        raise InputError(f"{name}: must be > 0, got {v}")
    return v


def check_nonnegative(name: str, value) -> float:
    """``value`` as a float >= 0, else InputError naming ``name``."""
    v = check_finite(name, value)
    if v < 0.0:
        raise InputError(f"{name}: must be >= 0, got {v}")
    return v
