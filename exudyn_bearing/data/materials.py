"""Elastic solids of balls and rings (data, SI units)."""
from __future__ import annotations

from dataclasses import dataclass

from .errors import InputError, check_finite, check_nonnegative, check_plausible, check_positive, check_text

__all__ = ["Material", "YOUNGS_MODULUS_RANGE", "DENSITY_RANGE"]

#: Young's moduli accepted [Pa]: engineering polymers (about 1 GPa) to
#: diamond (about 1.2e12 Pa); a value outside is a unit mistake (MPa, GPa).
YOUNGS_MODULUS_RANGE = (1e9, 1.2e12)
#: Densities accepted [kg/m^3]: polymers (about 900) to tungsten carbide
#: (about 15,600), with margin; a value outside is a unit mistake (g/cm^3).
DENSITY_RANGE = (500.0, 25000.0)


@dataclass(frozen=True)
class Material:
    """Elastic solid [docs/theory/geometry.md].

    Parameters
    ----------
    youngs_modulus : float
        E [Pa]. Default 210 GPa (bearing steel).
    poisson_ratio : float
        nu [-], in (-1, 0.5). Default 0.3.
    density : float
        rho [kg/m^3]. Default 7850.
    hysteretic_damping : float
        Hunt-Crossley coefficient alpha_e [s/m] of docs/theory/lubrication.md#normal-damping.
        Default 0.08 (steel).
    thermal_expansion : float
        Linear thermal expansion coefficient [1/K]. Default 12.5e-6, the
        handbook value of AISI 52100 bearing steel near room temperature
        (T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed.,
        CRC Press, 2006, Essential Concepts, ch. 'Bearing materials').
    """

    youngs_modulus: float = 210e9
    poisson_ratio: float = 0.3
    density: float = 7850.0
    hysteretic_damping: float = 0.08
    thermal_expansion: float = 12.5e-6
    name: str = "steel"
    source: str = "docs/theory/geometry.md"

    def __post_init__(self):
        e = check_positive("youngs_modulus", self.youngs_modulus)
        rho = check_positive("density", self.density)
        values = {"youngs_modulus": check_plausible("youngs_modulus", e, *YOUNGS_MODULUS_RANGE, "Pa",
                                                    "Young's modulus is in Pa", ((1e6, "MPa"), (1e9, "GPa"))),
                  "poisson_ratio": check_finite("poisson_ratio", self.poisson_ratio),
                  "density": check_plausible("density", rho, *DENSITY_RANGE, "kg/m^3", "density is in kg/m^3",
                                             ((1e3, "g/cm^3"),)),
                  "hysteretic_damping": check_nonnegative("hysteretic_damping", self.hysteretic_damping)}
        nu = values["poisson_ratio"]
        if not -1.0 < nu < 0.5:
            raise InputError(f"poisson_ratio: must lie in (-1, 0.5), got {nu}")
        te = values["thermal_expansion"] = check_finite("thermal_expansion", self.thermal_expansion)
        if not 0.0 <= te < 1e-4:
            raise InputError(f"thermal_expansion: must lie in [0, 1e-4) 1/K, got {te}")
        check_text("name", self.name)
        check_text("source", self.source)
        for key, v in values.items():  # plain floats from here on (numpy scalars, ints)
            object.__setattr__(self, key, v)

    @property
    def shear_modulus(self) -> float:
        """G = E / (2 (1 + nu)) [Pa]."""
        return self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
