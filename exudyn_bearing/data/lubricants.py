"""Lubricant, surface roughness and the lubrication-regime breakpoints (data, SI units)."""
from __future__ import annotations

import math
from dataclasses import dataclass

from .errors import (LENGTH_MISTAKES, InputError, check_finite, check_nonnegative, check_plausible, check_positive,
                     check_text)

__all__ = ["Lubricant", "LubricantDefaultsWarning", "MIN_COMPOSITE_ROUGHNESS", "PLAUSIBLE"]


class LubricantDefaultsWarning(UserWarning):
    """A lubricant read from a file or dict that leaves out some of its values: those are the papers' oil's
    (the defaults of :class:`Lubricant`, guessasma2018), named in the warning."""

#: Plausible ranges of a lubricant's values and the unit mistakes they catch:
#: (field, low, high, unit, rule, mistakes). Viscosities of bearing oils at
#: operating temperature: about 1 mPa s (jet oils hot) to 1 Pa s (cold gear
#: oils); pressure-viscosity coefficients 0.5e-8 to 4e-8 1/Pa; roughness up to
#: a few um rms.
PLAUSIBLE = (
    ("viscosity", 1e-5, 10.0, "Pa s", "viscosity is in Pa s", ((1e-3, "mPa s (cP)"),)),
    ("pressure_viscosity", 0.0, 1e-7, "1/Pa", "the pressure-viscosity coefficient is in 1/Pa (m^2/N)",
     ((1e-9, "1/GPa"), (1e-6, "1/MPa"))),
    ("roughness_race", 0.0, 1e-5, "m", "roughness is in metres", LENGTH_MISTAKES),
    ("roughness_ball", 0.0, 1e-5, "m", "roughness is in metres", LENGTH_MISTAKES),
    ("mu_boundary", 0.0, 1.0, "", "a friction coefficient is a ratio (boundary friction of lubricated steel "
     "about 0.1)", ((1e-2, "%"),)),
    ("mu_full_film", 0.0, 1.0, "", "a friction coefficient is a ratio (full-film traction about 0.01-0.08)",
     ((1e-2, "%"),)),
)
#: Smallest composite rms roughness sqrt(sigma_1^2 + sigma_2^2) accepted [m]: superfinished raceways and
#: grade-5 balls have some 0.01-0.05 um rms (Harris & Kotzalas, Rolling Bearing Analysis, 5th ed., 2006, on the
#: film parameter); 1 nm is below any bearing surface and keeps Lambda within a physical range.
MIN_COMPOSITE_ROUGHNESS = 1e-9


@dataclass(frozen=True)
class Lubricant:
    """Lubricant, surface roughness and the regime switch [docs/theory/lubrication.md].

    Parameters
    ----------
    viscosity : float
        Dynamic viscosity eta at operating temperature [Pa s]. Default 0.04.
    pressure_viscosity : float
        Barus pressure-viscosity coefficient xi [m^2/N]. Default 2.3e-8.
    roughness_race, roughness_ball : float
        RMS roughness sigma_1, sigma_2 [m]. Defaults 3e-7 and 0.
    roughness_factor : float
        Factor c in Lambda = h_min / (c sqrt(sigma_1^2 + sigma_2^2)).
        Default 1.25 (the DEM papers' definition, docs/theory/lubrication.md#film-thickness).
    lambda_mixed, lambda_full_film : float
        Film-parameter breakpoints: boundary for Lambda <= lambda_mixed,
        full film for Lambda > lambda_full_film. Defaults 1 and 3.
    mu_boundary, mu_full_film : float
        Friction coefficient in boundary and full-film lubrication; linear in
        Lambda between the breakpoints. Defaults 0.1 and 0.01.
    """

    viscosity: float = 0.04
    pressure_viscosity: float = 2.3e-8
    roughness_race: float = 3.0e-7
    roughness_ball: float = 0.0
    roughness_factor: float = 1.25
    lambda_mixed: float = 1.0
    lambda_full_film: float = 3.0
    mu_boundary: float = 0.1
    mu_full_film: float = 0.01
    name: str = "guessasma2018"
    source: str = "docs/theory/lubrication.md"

    def __post_init__(self):
        values = {}
        for key, check in (("viscosity", check_positive), ("pressure_viscosity", check_nonnegative),
                           ("roughness_race", check_nonnegative), ("roughness_ball", check_nonnegative),
                           ("roughness_factor", check_positive), ("lambda_mixed", check_nonnegative),
                           ("lambda_full_film", check_finite), ("mu_boundary", check_nonnegative),
                           ("mu_full_film", check_nonnegative)):
            values[key] = check(key, getattr(self, key))
        for key, lo, hi, unit, rule, mistakes in PLAUSIBLE:
            values[key] = check_plausible(key, values[key], lo, hi, unit, rule, mistakes)
        check_text("name", self.name)
        check_text("source", self.source)
        for key, v in values.items():  # plain floats from here on (numpy scalars, ints)
            object.__setattr__(self, key, v)
        if self.composite_roughness <= 0.0:
            raise InputError("roughness_race: race and ball roughness are both zero; Lambda is undefined")
        sigma = math.hypot(values["roughness_race"], values["roughness_ball"])
        if sigma < MIN_COMPOSITE_ROUGHNESS:
            raise InputError(f"roughness_race: the composite roughness sqrt(roughness_race^2 + roughness_ball^2) = "
                             f"{sigma:.3g} m is below {MIN_COMPOSITE_ROUGHNESS:g} m, smoother than any bearing "
                             "surface (superfinished raceways some 0.01-0.05 um rms); roughness is in metres")
        l1, l3 = values["lambda_mixed"], values["lambda_full_film"]
        if l3 <= l1:
            raise InputError(f"lambda_full_film: must exceed lambda_mixed ({l1}), got {l3}")

    @property
    def composite_roughness(self) -> float:
        """c sqrt(sigma_1^2 + sigma_2^2) [m], the denominator of Lambda."""
        return self.roughness_factor * math.hypot(self.roughness_race, self.roughness_ball)
