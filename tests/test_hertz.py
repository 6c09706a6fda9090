"""Elliptic Hertz contact against exact values and published numbers."""
import math

import numpy as np
import pytest
import scipy.special as sp

from exudyn_bearing.physics import hertz
from exudyn_bearing.physics.geometry import raceway_radii

E_PRIME = 210e9 / (1 - 0.3 ** 2)


def test_agm_elliptic_integrals_match_scipy():
    m = np.concatenate([np.linspace(0, 0.99, 50), 1 - np.geomspace(1e-2, 1e-10, 20)])
    k, e = hertz.complete_elliptic_integrals(m)
    np.testing.assert_allclose(k, sp.ellipk(m), rtol=1e-13)
    np.testing.assert_allclose(e, sp.ellipe(m), rtol=1e-13)


def test_6208_inner_contact_exact_values():
    # docs/theory/hertz.md: R_y/R_x = 32.8, k = 9.37, E = 1.018, F = 3.63
    rx, ry = raceway_radii(6.3e-3, 6.552e-3, 24e-3, 0.0, True)
    assert ry / rx == pytest.approx(32.8, abs=0.05)
    k, f, e = hertz.ellipticity(rx, ry, "exact")
    assert k == pytest.approx(9.37, abs=0.005)
    assert e == pytest.approx(1.018, abs=0.0005)
    assert f == pytest.approx(3.63, abs=0.005)


def test_exact_ellipticity_satisfies_the_hertz_relation_with_scipy():
    # Harris & Kotzalas eq. 6.27: F(rho) = ((k^2+1)E - 2F)/((k^2-1)E), F(rho) = (a_r-1)/(a_r+1)
    for ratio in (1.5, 5.0, 32.8, 80.0):
        k, _f, _e = hertz.ellipticity(1.0, ratio)
        m = 1 - 1 / k ** 2
        ek, ee = sp.ellipk(m), sp.ellipe(m)
        assert ((k ** 2 + 1) * ee - 2 * ek) / ((k ** 2 - 1) * ee) == pytest.approx(
            (ratio - 1) / (ratio + 1), rel=1e-10)


def test_circular_contact_limit_is_sphere_on_sphere():
    # R_x = R_y = R': k = 1, E = F = pi/2, K = (4/3) E* sqrt(R') (Johnson eq. 4.22)
    r = 4e-3  # effective radius R' = 2 r
    k, f, e = hertz.ellipticity(2 * r, 2 * r)
    assert (k, f, e) == pytest.approx((1.0, math.pi / 2, math.pi / 2))
    assert hertz.hertz_stiffness(2 * r, 2 * r, E_PRIME) == pytest.approx(4 / 3 * E_PRIME / 2 * math.sqrt(2 * r))


def test_sphere_sphere_closed_form():
    # docs/theory/hertz.md: for equal steels K = 4 G sqrt(R_eq) / (3 (1 - nu))
    e, nu = 210e9, 0.3
    g = e / (2 * (1 + nu))
    r1, r2 = 6.3e-3, 4.19e-3
    req = r1 * r2 / (r1 + r2)
    assert hertz.sphere_sphere_stiffness(r1, r2, hertz.reduced_modulus(e, nu)) == pytest.approx(
        4 * g * math.sqrt(req) / (3 * (1 - nu)), rel=1e-12)


def test_tangent_stiffness_is_the_slope_of_the_load_deflection_curve():
    # dQ/d delta of Q = K delta^1.5, by central differences of hertz_contact
    rx, ry, d, h = 5e-3, 160e-3, 20e-6, 1e-9
    qp, qm = hertz.hertz_contact(rx, ry, E_PRIME, overlap=np.array([d + h, d - h])).load
    c = hertz.hertz_contact(rx, ry, E_PRIME, overlap=d)
    assert hertz.tangent_stiffness(c.stiffness, c.load) == pytest.approx((qp - qm) / (2 * h), rel=1e-6)
    assert hertz.tangent_stiffness(c.stiffness, -1.0) == 0.0


def test_load_and_overlap_are_inverse_and_ellipse_consistent():
    rx, ry = 5e-3, 160e-3
    c = hertz.hertz_contact(rx, ry, E_PRIME, load=np.array([10.0, 1457.0, 5000.0]))
    back = hertz.hertz_contact(rx, ry, E_PRIME, overlap=c.overlap)
    np.testing.assert_allclose(back.load, [10.0, 1457.0, 5000.0], rtol=1e-12)
    np.testing.assert_allclose(c.a / c.b, c.kappa, rtol=1e-12)
    np.testing.assert_allclose(c.p_max, 1.5 * c.load / (math.pi * c.a * c.b), rtol=1e-12)
    # Q ~ delta^1.5 and a, b ~ Q^(1/3)
    np.testing.assert_allclose(c.load / c.overlap ** 1.5, c.stiffness, rtol=1e-12)
    assert c.a[2] / c.a[1] == pytest.approx((5000 / 1457) ** (1 / 3))


def test_ellipse_orientation_follows_the_larger_radius():
    c1 = hertz.hertz_contact(5e-3, 150e-3, E_PRIME, load=1000.0)
    c2 = hertz.hertz_contact(150e-3, 5e-3, E_PRIME, load=1000.0)
    assert c1.stiffness == pytest.approx(c2.stiffness)
    assert c1.a == pytest.approx(c2.b) and c1.b == pytest.approx(c2.a)
    assert c1.kappa > 1 > c2.kappa


def test_no_contact_gives_zero_load_and_ellipse():
    c = hertz.hertz_contact(5e-3, 150e-3, E_PRIME, overlap=np.array([-1e-6, 0.0]))
    assert np.all(c.load == 0) and np.all(c.a == 0) and np.all(c.p_max == 0)


# Measured error bounds of the fits against the exact solution for
# 1 <= R_y/R_x <= 40 (the ball-bearing range; the 6208 inner contact is 32.8).
# Stated in the hertz module docstring.
FIT_BOUNDS = {
    "hamrock_brewe": dict(stiffness=0.09, kappa=0.035, a=0.03, b=0.01, p_max=0.025),
    "simplified": dict(stiffness=0.04, kappa=0.04, a=0.03, b=0.015, p_max=0.02),
}


@pytest.mark.parametrize("method", ["hamrock_brewe", "simplified"])
def test_fits_within_their_stated_error_of_exact(method):
    ry = np.geomspace(1.0, 40.0, 300) * 5e-3
    exact = hertz.hertz_contact(5e-3, ry, E_PRIME, load=1000.0)
    fit = hertz.hertz_contact(5e-3, ry, E_PRIME, load=1000.0, method=method)
    for name, bound in FIT_BOUNDS[method].items():
        err = np.max(np.abs(getattr(fit, name) / getattr(exact, name) - 1))
        assert err < bound, (method, name, err)


def test_simplified_f_typo_would_make_k_thirty_percent_too_stiff():
    # docs/theory/hertz.md: printed F = 1 + (pi/2-1) ln a_r gives 2.99 at the 6208 inner
    # contact and K about 30 % too stiff; the corrected pi/2 + ... gives 3.56.
    rx, ry = raceway_radii(6.3e-3, 6.552e-3, 24e-3, 0.0, True)
    k, f, e = hertz.ellipticity(rx, ry, "simplified")
    assert f == pytest.approx(3.56, abs=0.01)
    f_typo = 1 + (math.pi / 2 - 1) * math.log(ry / rx)
    assert f_typo == pytest.approx(2.99, abs=0.01)
    k_exact = hertz.hertz_stiffness(rx, ry, E_PRIME)
    k_typo = hertz.hertz_stiffness(rx, ry, E_PRIME, "simplified") * (f / f_typo) ** 1.5
    assert 1.25 < k_typo / k_exact < 1.40


def test_unknown_method_is_rejected():
    with pytest.raises(ValueError, match="method"):
        hertz.hertz_stiffness(5e-3, 150e-3, E_PRIME, method="fast")


def test_tabulated_exact_level_matches_the_direct_solution():
    table = hertz.exact_table()
    for ratio in np.concatenate([[1.0, 1.0001], np.geomspace(1.001, 5000, 97)]):
        direct = hertz._kfe_exact(ratio)
        tab = hertz._kfe_tabulated(ratio, table)
        np.testing.assert_allclose(tab, direct, rtol=1e-7)
