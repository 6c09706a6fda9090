"""Traction models: data validation, closed forms of each law, kernel dispatch."""
import math

import numpy as np
import pytest

from exudyn_bearing import InputError
from exudyn_bearing.data import TRACTION_KINDS, TractionModel, get_traction_model, traction_models
from exudyn_bearing.physics import friction
from exudyn_bearing.physics import traction as tr


def test_catalogue_models_have_source_and_validity():
    assert {m.kind for m in traction_models.values()} == set(TRACTION_KINDS)
    for m in traction_models.values():
        assert m.source and m.validity
        assert m.vector.dtype == float and m.code == TRACTION_KINDS.index(m.kind)


@pytest.mark.parametrize("kind, params, word", [
    ("viscous", {}, "kind"),
    ("constant", {"mu": 0.1}, "regularizing_srr"),
    ("constant", {"mu": -0.1, "regularizing_srr": 0.0}, "mu"),
    ("constant", {"mu": 0.1, "regularizing_srr": 0.0, "nu": 1.0}, "nu"),
    ("curve", {"A": 0.0, "B": -1.0, "C": 1.0, "D": 0.0}, "A"),
    ("ehl", {"viscosity": 1e-3, "pressure_viscosity": 1e-8, "shear_modulus": 1e7, "thinning_exponent": 1.5,
             "limiting_shear_coefficient": 0.05}, "thinning_exponent"),
    ("lambda", {"mu_boundary": 0.1, "mu_full_film": 0.01, "lambda_mixed": 3.0, "lambda_full_film": 1.0,
                "composite_roughness": 1e-7, "regularizing_srr": 0.0}, "lambda_full_film"),
])
def test_bad_models_are_refused_naming_the_parameter(kind, params, word):
    with pytest.raises(InputError, match=f"^{word}"):
        TractionModel(kind, params)


def test_unknown_catalogue_name_lists_the_valid_ones():
    with pytest.raises(InputError, match="^traction: .*coulomb_0.1"):
        get_traction_model("castor_oil")


def test_curve_starts_at_zero_and_peaks_where_its_derivative_vanishes():
    # mu = (A + B s) exp(-C s) + D: d mu/ds = 0 at s* = 1/C - A/B; mu(0) = A + D
    a, b, c, d = -0.02, 2.0, 40.0, 0.02
    s = np.linspace(0.0, 0.3, 300001)
    mu = tr.traction_curve(s, a, b, c, d)
    assert mu[0] == 0.0
    assert s[np.argmax(mu)] == pytest.approx(1 / c - a / b, abs=2e-6)
    assert tr.traction_curve(50.0, a, b, c, d) == pytest.approx(d, rel=1e-12)  # large-slip value D


def test_ehl_newtonian_thinning_and_limit():
    # Newtonian (n = 1, xi = 0, limit far): tau = eta v / h exactly
    assert tr.traction_ehl(0.2, 1e9, 1e-6, 2e-3, 0.0, 1e12, 1.0, 10.0) * 1e9 == pytest.approx(400.0, rel=1e-9)
    # Barus: the same stress at pressure p is exp(xi p) times larger
    r = tr.traction_ehl(0.2, 1e9, 1e-6, 2e-3, 1e-9, 1e12, 1.0, 10.0) / tr.traction_ehl(0.2, 1e9, 1e-6, 2e-3, 0.0,
                                                                                       1e12, 1.0, 10.0)
    assert r == pytest.approx(math.e, rel=1e-9)
    # Carreau-type thinning (Gupta eq. 6): tau_e ~ G^(1-n) tau_N^n well above G: log-log slope n
    v = np.array([1e3, 1e4])
    mu = tr.traction_ehl(v, 1e9, 1e-6, 1.0, 0.0, 1e3, 0.3, 10.0)
    assert np.diff(np.log(mu))[0] / np.diff(np.log(v))[0] == pytest.approx(0.3, abs=1e-3)
    # limiting shear stress: mu -> Lambda_L at large slip, never above
    big = tr.traction_ehl(np.array([1.0, 10.0, 1000.0]), 2e9, 1e-7, 1e-3, 1e-8, 1e7, 0.3, 0.05)
    assert np.all(big < 0.05) and big[-1] == pytest.approx(0.05, rel=1e-3)
    # no slip, no traction; a huge exp(xi p) does not overflow to NaN
    assert tr.traction_ehl(0.0, 2e9, 1e-7, 1e-3, 1e-8, 1e7, 0.3, 0.05) == 0.0
    assert math.isfinite(float(tr.traction_ehl(1.0, 5e9, 1e-9, 1.0, 1e-7, 1e7, 0.3, 0.05)))


def test_lambda_model_equals_the_dem_friction_coefficient():
    # Guessasma & Machado (2018) mu(Lambda), already implemented in physics.friction
    h = np.array([1e-7, 4e-7, 7.5e-7, 1e-6, 2e-6])
    mu = tr.traction_lambda(0.1, h, 0.1, 0.01, 1.0, 3.0, 3.75e-7)
    np.testing.assert_allclose(mu, friction.friction_coefficient(h / 3.75e-7, 0.1, 0.01, 1.0, 3.0), rtol=1e-12)


def test_constant_model_regularisation():
    np.testing.assert_allclose(tr.traction_constant(np.array([0.0, 1e-3, 5e-3, 0.5]), 0.08, 0.01),
                               [0.0, 0.008, 0.04, 0.08], rtol=1e-12)


@pytest.mark.parametrize("name", sorted(traction_models))
def test_kernel_dispatch_equals_the_public_functions(name):
    m = traction_models[name]
    slip, u, p, hc, hm = 0.3, 20.0, 1.5e9, 2e-7, 1.5e-7
    got = float(tr.traction_coefficient(m, slip, u, p, hc, hm))
    q = m.parameters
    want = {"constant": lambda: tr.traction_constant(slip / u, q["mu"], q["regularizing_srr"]),
            "curve": lambda: tr.traction_curve(slip / u, q["A"], q["B"], q["C"], q["D"]),
            "ehl": lambda: tr.traction_ehl(slip, p, hc, *[q[k] for k in ("viscosity", "pressure_viscosity",
                                                                          "shear_modulus", "thinning_exponent",
                                                                          "limiting_shear_coefficient")]),
            "lambda": lambda: tr.traction_lambda(slip / u, hm, q["mu_boundary"], q["mu_full_film"], q["lambda_mixed"],
                                                 q["lambda_full_film"], q["composite_roughness"],
                                                 q["regularizing_srr"])}[m.kind]()
    assert got == pytest.approx(float(want), rel=1e-12) and got > 0.0
