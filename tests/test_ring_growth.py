"""Rings at speed, fit and temperature against Timoshenko & Goodier's elasticity solutions."""

import numpy as np
import pytest

from exudyn_bearing import InputError, catalog
from exudyn_bearing.physics import ring_growth as rg
from exudyn_bearing.model.operating_geometry import operating_geometry

STEEL = dict(density=7830.0, youngs_modulus=203e9, poisson_ratio=0.28)


def _stresses(u_fun, r, nu, e):
    """Plane-stress sigma_r, sigma_t from a displacement field by central differences."""
    h = 1e-7 * r
    dudr = (u_fun(r + h) - u_fun(r - h)) / (2 * h)
    u = u_fun(r)
    c = e / (1 - nu * nu)
    return c * (dudr + nu * u / r), c * (u / r + nu * dudr)


def test_thin_ring_limit():
    # docs/theory/quasistatic.md / Timoshenko & Goodier sec. 32: a thin rotating ring grows by rho omega^2 r^3 / E
    r, w = 67e-3, 2618.0
    thin = rg.thin_ring_displacement(r, w, STEEL["density"], STEEL["youngs_modulus"])
    disc = rg.rotating_disc_displacement(r, 0.9999 * r, r, w, *STEEL.values())
    assert disc == pytest.approx(thin, rel=1e-3)
    assert 50e-6 < thin < 100e-6  # "tens of micrometres" at 2618 rad/s


def test_solid_disc_rim_closed_form():
    # Timoshenko & Goodier sec. 32, solid disc: u(c) = (1 - nu) rho omega^2 c^3 / (4 E)
    c, w = 0.05, 3000.0
    nu, e, rho = 0.3, 210e9, 7850.0
    u = rg.rotating_disc_displacement(c, 0.0, c, w, rho, e, nu)
    assert u == pytest.approx((1 - nu) * rho * w ** 2 * c ** 3 / (4 * e), rel=1e-12)


def test_rotating_disc_edges_are_free_and_hoop_stress_matches():
    # independent check of u(r): sigma_r = 0 at both edges, sigma_t(b) = (3 + nu)/4 rho w^2 (c^2 + (1-nu)/(3+nu) b^2)
    b, c, w, nu, e, rho = 60e-3, 67.18e-3, 2618.0, 0.28, 203e9, 7830.0
    u = lambda r: rg.rotating_disc_displacement(r, b, c, w, rho, e, nu)  # noqa: E731
    for r in (b, c):
        sr, _ = _stresses(u, r, nu, e)
        assert abs(sr) < 1e-5 * rho * w ** 2 * c ** 2
    _, st = _stresses(u, b, nu, e)
    assert st == pytest.approx((3 + nu) / 4 * rho * w ** 2 * (c ** 2 + (1 - nu) / (3 + nu) * b ** 2), rel=1e-6)


def test_lame_pressure_boundary_conditions():
    # Timoshenko & Goodier sec. 28: sigma_r(b) = -p_i, sigma_r(c) = -p_o
    b, c, nu, e = 0.06, 0.07, 0.28, 203e9
    u = lambda r: rg.lame_displacement(r, b, c, 5e6, 1e6, e, nu)  # noqa: E731
    assert _stresses(u, b, nu, e)[0] == pytest.approx(-5e6, rel=1e-6)
    assert _stresses(u, c, nu, e)[0] == pytest.approx(-1e6, rel=1e-6)


def test_fit_pressure_at_rest_and_its_fall_with_speed():
    # solid shaft, same material: p = E (I/2) (c^2 - b^2) / (2 b c^2)
    b, c, i = 60e-3, 67.18e-3, 20e-6
    p0 = rg.fit_pressure(i, b, c, **STEEL)
    assert p0 == pytest.approx(STEEL["youngs_modulus"] * 0.5 * i * (c ** 2 - b ** 2) / (2 * b * c ** 2), rel=1e-12)
    w_loose = rg.fit_loosening_speed(i, b, c, **STEEL)
    w = np.array([0.0, 0.5, 0.9, 1.0, 1.2]) * w_loose
    p = rg.fit_pressure(i, b, c, w, **STEEL)
    # the interference lost grows with omega^2: p = p0 (1 - (omega/omega_loose)^2), zero beyond
    np.testing.assert_allclose(p, p0 * np.maximum(1 - (w / w_loose) ** 2, 0.0), rtol=1e-9, atol=1e-6)


def test_fit_raises_the_raceway_by_the_lame_displacement():
    b, c, i = 60e-3, 67.18e-3, 20e-6
    p = rg.fit_pressure(i, b, c, **STEEL)
    u = rg.inner_ring_raceway_growth(c, b, 0.0, i, **STEEL)
    assert u == pytest.approx(2 * p * b ** 2 * c / (STEEL["youngs_modulus"] * (c ** 2 - b ** 2)), rel=1e-12)


def test_thermal_growth_is_linear():
    assert rg.thermal_growth(0.1, 12e-6, 100.0) == pytest.approx(1.2e-4)


def test_operating_geometry_rigid_growing_and_heated():
    b = catalog["ACBB-120"]
    rho_i, z_i = b.inner_groove_center
    rigid = operating_geometry(b, 2618.0, ring_growth=False)
    assert rigid.rho_i == rho_i and rigid.inner_ring_growth == 0.0
    grown = operating_geometry(b, 2618.0)
    u = rg.inner_ring_raceway_growth(b.inner_race_radius, 0.5 * b.bore, 2618.0, density=b.material.density,
                                     youngs_modulus=b.material.youngs_modulus,
                                     poisson_ratio=b.material.poisson_ratio)
    assert grown.rho_i - rho_i == pytest.approx(u, rel=1e-12)
    # uniform heating of the whole bearing scales it: clearance scales, growth reported
    hot = operating_geometry(b, 0.0, temperatures={"inner": 492.0, "outer": 492.0, "ball": 492.0})
    s = b.material.thermal_expansion * (492.0 - 293.15)
    assert hot.r_b == pytest.approx(b.ball_radius * (1 + s)) and hot.rho_o == pytest.approx(
        b.outer_groove_center[0] * (1 + s))
    # a hotter inner ring takes clearance away
    warm = operating_geometry(b, 0.0, temperatures={"inner": 350.0})
    assert warm.operating_clearance < rigid.operating_clearance


@pytest.mark.parametrize("kw, word", [(dict(fit=-1e-6), "fit"), (dict(fit=5e-3), "fit"),
                                      (dict(temperatures={"inner": -3.0}), "temperatures.inner"),
                                      (dict(temperatures={"cage": 300.0}), "temperatures")])
def test_bad_geometry_input(kw, word):
    with pytest.raises(InputError, match=f"^{word}"):
        operating_geometry(catalog["ACBB-120"], 1000.0, **kw)
