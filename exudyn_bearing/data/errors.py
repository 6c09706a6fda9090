"""The input error of the package and the checks that raise it.

Every check names the parameter first, so that a message reads
``"ball_radius: must be > 0, got -0.001"`` wherever it surfaces (API, JSON
file or command line).
"""
from __future__ import annotations

import math
import numbers

import numpy as np

__all__ = ["InputError", "check_number", "check_finite", "check_positive", "check_nonnegative", "check_integer",
           "check_bool", "check_text", "check_keys"]


class InputError(ValueError):
    """Invalid bearing, material, lubricant or scenario input.

    The message starts with the parameter name.
    """


def check_number(name: str, value) -> float:
    """``value`` as a float if it is a real number (Python or numpy, also a
    0-d array), else InputError naming ``name``. Strings and booleans are
    not numbers: a ``"2.1e11"`` from a JSON file would pass ``float()`` here
    and fail far away."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise InputError(f"{name}: expected a number, got {value!r} ({type(value).__name__})")
    return float(value)


def check_finite(name: str, value) -> float:
    """``value`` as a finite float, else InputError naming ``name``."""
    v = check_number(name, value)
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


def check_integer(name: str, value) -> int:
    """``value`` as an int if it is an integer (Python or numpy, or a float
    with an integral value), else InputError naming ``name``."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    if isinstance(value, (bool, np.bool_)):
        raise InputError(f"{name}: expected an integer, got {value!r}")
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real) and math.isfinite(float(value)) and float(value).is_integer():
        return int(value)
    raise InputError(f"{name}: expected an integer, got {value!r}")


def check_bool(name: str, value) -> bool:
    """``value`` as a bool if it is True or False (also numpy's), else
    InputError naming ``name`` (a string such as ``'no'`` would be truthy)."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise InputError(f"{name}: must be True or False, got {value!r}")


def check_text(name: str, value) -> str:
    """``value`` if it is a string, else InputError naming ``name``."""
    if not isinstance(value, str):
        raise InputError(f"{name}: expected a string, got {value!r}")
    return value


def check_keys(what: str, given, valid) -> None:
    """InputError naming the first key of ``given`` that is not in ``valid``
    (``what``: e.g. "material parameter"), with the valid ones."""
    unknown = sorted(set(given) - set(valid))
    if unknown:
        raise InputError(f"{unknown[0]}: unknown {what} (valid: {', '.join(sorted(valid))})")
