"""Strip integration of slip and traction over a Hertz ellipse against closed forms."""
import math

import numpy as np
import pytest

from exudyn_bearing.data import TractionModel
from exudyn_bearing.physics.contact_slip import (contact_traction, deformed_contact_radius, pure_rolling_points,
                                                 spin_moment_coulomb)

A, B, Q, MU = 2.0e-3, 0.3e-3, 1000.0, 0.1
COULOMB = TractionModel("constant", {"mu": MU, "regularizing_srr": 0.0})


def test_pure_rolling_transmits_nothing():
    r = contact_traction(A, B, Q, 0.0, 0.0, 0.0, model=COULOMB, n_strips=16, n_across=3)
    assert r == (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)


@pytest.mark.parametrize("model", [COULOMB, TractionModel("constant", {"mu": MU, "regularizing_srr": 0.02}),
                                   TractionModel("curve", {"A": -0.02, "B": 2.0, "C": 40.0, "D": 0.02})])
@pytest.mark.parametrize("n_strips, n_across", [(1, 1), (16, 1), (9, 4)])
def test_applied_resultant_takes_exactly_the_dissipation(model, n_strips, n_across):
    # tau . v summed over the points = F_x v0 + F_y v_t + M_z w_n + M_y omega_roll (an identity of
    # the slip field v_x = v0 - w_n y + c2 y^2, v_y = v_t + w_n x with c2 = omega_roll / (2 R_d)), and
    # tau . v = -mu p |v| dA: the force and the two moments applied to the bodies take exactly P
    r_d, roll = 6.4e-3, 900.0
    c2 = roll / (2.0 * r_d)
    v0, wn, vt = 0.03, 40.0, -0.01
    r = contact_traction(A, B, Q, v0, wn, c2, v_t=vt, u_roll=15.0, model=model, n_strips=n_strips,
                         n_across=n_across, r_d=r_d)
    work = r.force_x * v0 + r.force_y * vt + r.moment_z * wn + r.moment_y * roll
    assert r.dissipation > 0.0
    assert -work == pytest.approx(r.dissipation, rel=1e-12)
    # without the curvature moment the forces would take less than the dissipation (the old defect);
    # one strip samples the slip at y = 0 only, where the curvature slip vanishes
    if n_strips > 1:
        assert -(work - r.moment_y * roll) < r.dissipation


def test_curvature_moment_of_a_fully_sliding_coulomb_contact():
    # curvature slip alone, far larger than any other slip (c2 y^2 >= 0 everywhere: v_x > 0): tau_x = -mu p,
    # M_y = -mu int p y^2/(2 R_d) dA = -mu Q a^2 / (10 R_d) (int p y^2 dA = Q a^2 / 5 for Hertz pressure)
    r_d, c2 = 6.4e-3, 1e4
    r = contact_traction(A, B, Q, 1e-9, 0.0, c2, model=COULOMB, n_strips=4000, n_across=1, r_d=r_d)
    assert r.moment_y == pytest.approx(-MU * Q * A * A / (10.0 * r_d), rel=1e-5)


@pytest.mark.parametrize("n_strips, n_across", [(1, 1), (7, 2), (40, 5)])
def test_uniform_sliding_gives_coulomb_force_for_any_strip_count(n_strips, n_across):
    # the strip loads add up to Q exactly: F_x = -mu Q, P = mu Q |v|, QV = Q |v|
    r = contact_traction(A, B, Q, -0.7, 0.0, model=COULOMB, n_strips=n_strips, n_across=n_across)
    assert r.force_x == pytest.approx(MU * Q, rel=1e-12)
    assert r.dissipation == pytest.approx(MU * Q * 0.7, rel=1e-12) and r.qv == pytest.approx(Q * 0.7, rel=1e-12)
    assert abs(r.force_y) < 1e-12 and abs(r.moment_z) < 1e-12


def test_pure_spin_strip_theory_gives_three_eighths_mu_q_a():
    # classical strip theory (slip on the major axis): M_s = (3/8) mu Q a, converging as 1/n^2
    errs = []
    for n in (50, 100, 200):  # even counts (an odd count puts a strip on the spin centre)
        m = contact_traction(A, B, Q, 0.0, 50.0, model=COULOMB, n_strips=n, n_across=1).moment_z
        errs.append(abs(-m - 0.375 * MU * Q * A))
    assert errs[-1] < 2e-4 * 0.375 * MU * Q * A
    assert errs[0] / errs[1] == pytest.approx(4.0, rel=0.05) and errs[1] / errs[2] == pytest.approx(4.0, rel=0.05)


def test_pure_spin_resolved_across_gives_jones_spin_moment():
    # Jones (1959): M_s = (3/8) mu Q a E(e), e^2 = 1 - b^2/a^2 (the integral of mu p rho over the ellipse)
    jones = spin_moment_coulomb(MU, Q, A, B)
    m = contact_traction(A, B, Q, 0.0, 50.0, model=COULOMB, n_strips=800, n_across=64).moment_z
    assert -m == pytest.approx(jones, rel=2e-5)
    assert jones / (0.375 * MU * Q * A) == pytest.approx(1.0315, abs=1e-3)  # E(e) at b/a = 0.15
    # circular contact: (3 pi / 16) mu Q a
    assert spin_moment_coulomb(MU, Q, A, A) == pytest.approx(3 * math.pi / 16 * MU * Q * A, rel=1e-12)
    # the spin moment opposes the spin
    assert contact_traction(A, B, Q, 0.0, -50.0, model=COULOMB).moment_z > 0


def test_heathcote_points_carry_no_net_force():
    # Johnson, Contact Mechanics, sec. 8: with Coulomb friction, curvature slip v0 + c2 y^2 has no net
    # rolling-direction force when the pure-rolling lines are at y = +-0.347 a (v0 - v0^3/3 = 1/3)
    y0 = 0.34730 * A
    c2 = 100.0
    for n, tol in ((256, 1.5e-2), (4096, 1e-3)):
        f = contact_traction(A, B, Q, -c2 * y0 ** 2, 0.0, c2, model=COULOMB, n_strips=n).force_x
        assert abs(f) < tol * MU * Q
    # with the pure-rolling point at the centre the force is far from zero
    assert abs(contact_traction(A, B, Q, 0.0, 0.0, c2, model=COULOMB, n_strips=256).force_x) > 0.5 * MU * Q
    np.testing.assert_allclose(pure_rolling_points(A, -c2 * y0 ** 2, 0.0, c2), [-y0, y0], rtol=1e-12)


def test_dissipation_converges_with_the_strip_count():
    model = TractionModel("curve", {"A": -0.02, "B": 2.0, "C": 40.0, "D": 0.02})
    args = (A, B, Q, 0.05, 30.0, 400.0)
    p = [contact_traction(*args, u_roll=20.0, model=model, n_strips=n, n_across=4).dissipation
         for n in (8, 16, 32, 64, 256)]
    ref = p[-1]
    errs = [abs(x - ref) / ref for x in p[:-1]]
    assert errs[0] > errs[1] > errs[2] > errs[3] and errs[2] < 2e-3


def test_linear_traction_spin_moment_closed_form():
    # a traction proportional to slip (mu = k s, Coulomb regularised with s_r above every slip):
    # tau = -(mu_0 / s_r) p v / u, so M_z = -(mu_0/(s_r u)) w_n int p (x^2 + y^2) dA = -(mu_0/(s_r u)) w_n Q (a^2 + b^2)/5
    mu0, sr, u, wn = 0.1, 0.01, 100.0, 30.0
    model = TractionModel("constant", {"mu": mu0, "regularizing_srr": sr})
    m = contact_traction(A, B, Q, 0.0, wn, u_roll=u, model=model, n_strips=2000, n_across=12).moment_z
    assert m == pytest.approx(-(mu0 / (sr * u)) * wn * Q * (A ** 2 + B ** 2) / 5.0, rel=1e-5)


def test_deformed_radius_lies_between_ball_and_groove():
    # Harris & Kotzalas: 2 r D / (2 r + D) with r = f D
    d, f = 12.6e-3, 0.52
    assert deformed_contact_radius(d / 2, f * d) == pytest.approx(2 * f * d * d / (2 * f * d + d), rel=1e-12)
