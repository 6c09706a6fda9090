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
           "check_bool", "check_text", "check_keys", "check_plausible", "check_temperature", "check_temperatures",
           "check_unused",
           "LENGTH_MISTAKES", "KELVIN"]

#: 0 degC in kelvin.
KELVIN = 273.15
#: Lengths typed in mm, cm or um where metres belong: (value -> metres, unit typed).
LENGTH_MISTAKES = ((1e-3, "mm"), (1e-2, "cm"), (1e-6, "um"))


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


def check_unused(switch: str, on: bool, options, enable: str | None = None) -> None:
    """InputError naming the first of ``options`` ((name, value, default) triples) that was given (a value
    other than its default) while ``switch``, which uses it, is off: an option accepted and ignored is a
    silent wrong answer. ``enable``: how to switch it on (default "set <switch>")."""
    if on:
        return
    for name, value, default in options:
        if value is not None and value != default:
            leave = "out" if default is None else f"at {default:g}"
            raise InputError(f"{name}: used with {switch} only; {enable or 'set ' + switch} (or leave {name} "
                             f"{leave})")


def lookup(table, key, unknown: str, label: str = "catalogue"):
    """``table[key]``; else InputError "<unknown> 'key' (<label>: the valid names)", ``unknown`` naming the
    parameter and what was looked for (e.g. "bearing: unknown bearing")."""
    try:
        return table[key]
    except KeyError:
        raise InputError(f"{unknown} {key!r} ({label}: {', '.join(table)})") from None


def check_plausible(name: str, value, lo: float, hi: float, unit: str, rule: str, mistakes=()) -> float:
    """``value`` as a float if it lies in the plausible range ``[lo, hi]``
    (in ``unit``), else InputError naming ``name``. ``mistakes``: pairs
    (factor or function, unit typed) of likely unit mistakes; the first that
    brings the value into the range is named in the message after ``rule``,
    e.g. ``"ball_diameter: 12.7 m is not plausible for a ball bearing (2e-4 to
    0.2 m); lengths are in metres: 12.7 mm is 0.0127 m"``."""
    v = check_finite(name, value)
    if lo <= v <= hi:
        return v
    u = f" {unit}" if unit else ""  # "" for a ratio: "5 is not plausible (0 to 1)"
    for convert, typed in mistakes:
        w = convert(v) if callable(convert) else v * convert
        if lo <= w <= hi:
            raise InputError(f"{name}: {v:g}{u} is not plausible ({lo:g} to {hi:g}{u}); {rule}: "
                             f"{v:g} {typed} is {w:.6g}{u}")
    raise InputError(f"{name}: {v:g}{u} is not plausible ({lo:g} to {hi:g}{u}); {rule}")


#: Temperatures accepted [K]: -123 degC to 527 degC. The thermal expansion of
#: the catalogue materials is a room-temperature value, and a value below
#: 150 K is far more likely a temperature typed in degrees Celsius.
TEMPERATURE_RANGE = (150.0, 800.0)


def check_temperature(name: str, value) -> float:
    """An absolute temperature [K] in :data:`TEMPERATURE_RANGE`, else InputError
    naming ``name`` (``"temperatures are in kelvin: 20 degC is 293.15 K"``)."""
    lo, hi = TEMPERATURE_RANGE
    return check_plausible(name, value, lo, hi, "K", "temperatures are in kelvin",
                           ((lambda t: t + KELVIN, "degC"),))


def check_temperatures(temperatures) -> dict | None:
    """The part temperatures ``{"inner", "outer", "ball"}`` [K] of a scenario or
    a quasi-static solve, each checked by :func:`check_temperature` (None
    passes through)."""
    if temperatures is None:
        return None
    if not isinstance(temperatures, dict):
        raise InputError(f"temperatures: expected a dict of inner, outer, ball [K], got {temperatures!r}")
    for k in temperatures:
        if k not in ("inner", "outer", "ball"):
            raise InputError(f"temperatures: unknown part {k!r} (valid: inner, outer, ball)")
    return {k: check_temperature(f"temperatures.{k}", v) for k, v in temperatures.items()}
