"""Traction (friction) models of a lubricated ball / race contact, as data.

A :class:`TractionModel` names one of four kinds and carries its parameters,
the range in which it is meant to be used and its source. The relations
themselves live in :mod:`exudyn_bearing.physics.traction`; compiled code
selects them by :attr:`TractionModel.code` and reads the parameters from
:attr:`TractionModel.vector` (the order of :data:`PARAMETER_NAMES`).

Kinds and parameters (SI units; s is the local slide-to-roll ratio, the
slip speed over the rolling speed):

``"constant"``
    ``mu`` [-], ``regularizing_srr`` [-]: Coulomb friction mu, made linear
    in s below ``regularizing_srr`` (0: pure Coulomb).
``"curve"``
    ``A``, ``B``, ``C``, ``D`` [-]: the traction-slip curve
    mu(s) = (A + B s) exp(-C s) + D (A = -D makes it start at zero).
``"ehl"``
    ``viscosity`` eta_0 [Pa s], ``pressure_viscosity`` xi [1/Pa],
    ``shear_modulus`` G [Pa], ``thinning_exponent`` n [-],
    ``limiting_shear_coefficient`` Lambda_L [-]: Newtonian film
    tau_N = eta_0 exp(xi p) v/h, shear thinning
    tau_e = tau_N (1 + (tau_N/G)^2)^((n-1)/2), limited by tau_L = Lambda_L p.
``"lambda"``
    ``mu_boundary``, ``mu_full_film``, ``lambda_mixed``,
    ``lambda_full_film`` [-], ``composite_roughness`` [m],
    ``regularizing_srr`` [-]: the DEM papers' mu(Lambda), Lambda = h_min /
    composite roughness, Coulomb with that mu.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping

import numpy as np

from .errors import InputError, check_finite

__all__ = ["TractionModel", "TRACTION_KINDS", "PARAMETER_NAMES", "DEFAULT_REGULARIZING_SRR", "regularized"]

#: Slide-to-roll ratio below which a Coulomb-type law (``constant``,
#: ``lambda``) without its own regularisation rises linearly, in every solver
#: (quasi-static and both dynamic engines): a discontinuous law has neither a
#: stable explicit step nor a smooth traction equilibrium.
DEFAULT_REGULARIZING_SRR = 0.01

#: Kinds of traction model, in the order of their integer codes.
TRACTION_KINDS = ("constant", "curve", "ehl", "lambda")

#: Parameter names of each kind, in the order of :attr:`TractionModel.vector`.
PARAMETER_NAMES = {
    "constant": ("mu", "regularizing_srr"),
    "curve": ("A", "B", "C", "D"),
    "ehl": ("viscosity", "pressure_viscosity", "shear_modulus", "thinning_exponent",
            "limiting_shear_coefficient"),
    "lambda": ("mu_boundary", "mu_full_film", "lambda_mixed", "lambda_full_film", "composite_roughness",
               "regularizing_srr"),
}

#: Length of every parameter vector (the longest kind; shorter ones are padded with 0).
N_TRACTION_PARAMS = max(len(v) for v in PARAMETER_NAMES.values())


def _range(name, value, lo=None, hi=None, lo_open=False, hi_open=False):
    v = check_finite(name, value)
    if lo is not None and (v < lo or (lo_open and v == lo)):
        raise InputError(f"{name}: must be {'>' if lo_open else '>='} {lo:g}, got {v:g}")
    if hi is not None and (v > hi or (hi_open and v == hi)):
        raise InputError(f"{name}: must be {'<' if hi_open else '<='} {hi:g}, got {v:g}")
    return v


@dataclass(frozen=True)
class TractionModel:
    """A traction model: kind, parameters, validity and source.

    Parameters
    ----------
    kind : {"constant", "curve", "ehl", "lambda"}
        Which relation (module docstring).
    parameters : mapping
        Exactly the names of ``PARAMETER_NAMES[kind]``, SI units.
    name, validity, source : str
        Catalogue name, the range of use, where the numbers come from.

    Examples
    --------
    >>> m = TractionModel("constant", {"mu": 0.1, "regularizing_srr": 0.0})
    >>> m.code, m.vector[:2].tolist()
    (0, [0.1, 0.0])
    """

    kind: str
    parameters: Mapping[str, float] = field(default_factory=dict)
    name: str = "custom"
    validity: str = ""
    source: str = ""

    def __post_init__(self):
        if self.kind not in TRACTION_KINDS:
            raise InputError(f"kind: unknown traction kind {self.kind!r} (valid: {', '.join(TRACTION_KINDS)})")
        if not isinstance(self.parameters, Mapping):
            raise InputError(f"parameters: expected a mapping of names to numbers, got {type(self.parameters).__name__}")
        names = PARAMETER_NAMES[self.kind]
        unknown = sorted(set(self.parameters) - set(names))
        if unknown:
            raise InputError(f"{unknown[0]}: not a parameter of a '{self.kind}' traction model "
                             f"(valid: {', '.join(names)})")
        missing = [n for n in names if n not in self.parameters]
        if missing:
            raise InputError(f"{missing[0]}: missing (a '{self.kind}' traction model needs {', '.join(names)})")
        p = {n: check_finite(n, self.parameters[n]) for n in names}
        getattr(self, f"_check_{self.kind}")(p)
        object.__setattr__(self, "parameters", MappingProxyType(p))

    # -- validation per kind ----------------------------------------------------
    @staticmethod
    def _check_constant(p):
        _range("mu", p["mu"], 0.0, 2.0)
        _range("regularizing_srr", p["regularizing_srr"], 0.0, 1.0)

    @staticmethod
    def _check_curve(p):
        _range("C", p["C"], 0.0)
        s = np.linspace(0.0, 2.0, 401)
        mu = (p["A"] + p["B"] * s) * np.exp(-p["C"] * s) + p["D"]
        if mu.min() < -1e-12:
            raise InputError(f"A: the curve (A + B s) exp(-C s) + D goes below zero "
                             f"(min {mu.min():.3g} on 0 <= s <= 2); traction must oppose slip")
        if mu.max() > 2.0:
            raise InputError(f"B: the curve exceeds mu = 2 on 0 <= s <= 2 (max {mu.max():.3g})")

    @staticmethod
    def _check_ehl(p):
        _range("viscosity", p["viscosity"], 0.0, lo_open=True)
        _range("pressure_viscosity", p["pressure_viscosity"], 0.0, 1e-7)
        _range("shear_modulus", p["shear_modulus"], 0.0, lo_open=True)
        _range("thinning_exponent", p["thinning_exponent"], 0.0, 1.0, lo_open=True)
        _range("limiting_shear_coefficient", p["limiting_shear_coefficient"], 0.0, 0.5, lo_open=True)

    @staticmethod
    def _check_lambda(p):
        _range("mu_boundary", p["mu_boundary"], 0.0, 2.0)
        _range("mu_full_film", p["mu_full_film"], 0.0, 2.0)
        l1 = _range("lambda_mixed", p["lambda_mixed"], 0.0)
        l3 = _range("lambda_full_film", p["lambda_full_film"])
        if l3 <= l1:
            raise InputError(f"lambda_full_film: must exceed lambda_mixed ({l1:g}), got {l3:g}")
        _range("composite_roughness", p["composite_roughness"], 0.0, lo_open=True)
        _range("regularizing_srr", p["regularizing_srr"], 0.0, 1.0)

    # -- what compiled code reads ---------------------------------------------------
    @property
    def code(self) -> int:
        """Integer code of the kind (index into :data:`TRACTION_KINDS`)."""
        return TRACTION_KINDS.index(self.kind)

    @property
    def vector(self) -> np.ndarray:
        """Parameters as a float64 array in :data:`PARAMETER_NAMES` order, zero-padded
        to :data:`N_TRACTION_PARAMS`."""
        v = np.zeros(N_TRACTION_PARAMS)
        for i, n in enumerate(PARAMETER_NAMES[self.kind]):
            v[i] = self.parameters[n]
        return v

    def replace(self, **parameters) -> "TractionModel":
        """A copy with some parameters changed (validated again)."""
        p = dict(self.parameters)
        p.update(parameters)
        return TractionModel(self.kind, p, self.name, self.validity, self.source)

    def to_dict(self) -> dict:
        """Plain JSON-able dict (the format of a ``traction_models`` entry of ``catalog.json``)."""
        return {"kind": self.kind, "parameters": dict(self.parameters), "validity": self.validity,
                "source": self.source}


def regularized(model: TractionModel, regularizing_srr: float = DEFAULT_REGULARIZING_SRR) -> TractionModel:
    """The model every solver uses: a Coulomb-type law (``constant``,
    ``lambda``) whose own ``regularizing_srr`` is 0 gets ``regularizing_srr``
    (0 keeps it discontinuous); other kinds unchanged."""
    if "regularizing_srr" in PARAMETER_NAMES[model.kind] and model.parameters["regularizing_srr"] <= 0.0:
        return model.replace(regularizing_srr=regularizing_srr)
    return model
