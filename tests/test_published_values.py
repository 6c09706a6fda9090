"""Independent checks of the physics relations: published values, closed forms
and hand calculations written here from the sources' equations, never the
code's own output. Each tolerance says why it is that wide; each is far
below the 2 % planted errors of validation/consistency/mutation_run.py."""
import math

import pytest
from scipy import integrate

import exudyn_bearing as eb
from exudyn_bearing.data import TractionModel, default_lubricant
from exudyn_bearing.physics import ehl, kinematics
from exudyn_bearing.physics.contact_slip import contact_traction, spin_moment_coulomb
from conftest import hertz_stiffness_by_hand

E_PRIME = 210e9 / (1 - 0.3 ** 2)  # catalogue steel, E' = E / (1 - nu^2)
ETA, XI = 0.04, 2.3e-8            # the DEM papers' lubricant (Guessasma & Machado 2018, sec. 2)
# two contacts of the 6208 at 500 rad/s (docs/theory/lubrication.md#film-thickness): R_x, k, u_r, Q
OUTER = (7.6099e-3, 7.2486, 7.2475, 1457.0)
INNER = (4.990e-3, 9.374, 7.2475, 1462.0)
#: Two evaluations of one formula that differ only in floating-point order
#: (exp of a sum of logs in the code, powers here) agree to ~1e-15; 1e-9
#: leaves room for that and catches any change of a printed constant.
SAME_FORMULA = 1e-9


# -- film thickness ----------------------------------------------------------------------------------------
def _groups(u_r, q, r_x):
    return ETA * u_r / (E_PRIME * r_x), XI * E_PRIME, q / (E_PRIME * r_x ** 2)


@pytest.mark.parametrize("contact", [OUTER, INNER])
def test_masjedi_khonsari_film_by_hand_from_the_published_constants(contact):
    # Masjedi & Khonsari, Tribol. Int. 82 (2015) 228-244, smooth-surface minimum film of a point
    # contact, with the constants as the digital-twin DEM paper prints them (Omar Farah et al.,
    # eq. 6, quoting Masjedi & Khonsari): prefactor 1.637; exponents of U, G, W from (0.711, 0.023),
    # (0.65, 0.045), (0.09, 0.15); ellipticity factor 1 - 0.974 exp(-0.676 k). The printed
    # exponents "a k - b" are read as a k^-b (docs/theory/lubrication.md#masjedi-khonsari-reading;
    # the original paper's text was not available to the project).
    r_x, k, u_r, q = contact
    U, G, W = _groups(u_r, q, r_x)
    h = r_x * 1.637 * U ** (0.711 * k ** -0.023) * G ** (0.65 * k ** -0.045) * W ** (-0.09 * k ** -0.15) \
        * (1.0 - 0.974 * math.exp(-0.676 * k))
    assert float(ehl.film_thickness_masjedi_khonsari(u_r, q, r_x, k, E_PRIME, ETA, XI)) == \
        pytest.approx(h, rel=SAME_FORMULA)
    assert float(ehl.film_thickness(u_r, q, r_x, k, E_PRIME, ETA, XI, "mk")) == pytest.approx(h, rel=SAME_FORMULA)
    assert float(ehl._film_thickness(1, u_r, q, r_x, k, E_PRIME, ETA, XI)) == pytest.approx(h, rel=SAME_FORMULA)


@pytest.mark.parametrize("contact", [OUTER, INNER])
def test_hamrock_dowson_central_and_minimum_films_by_hand(contact):
    # Hamrock & Dowson, J. Lubr. Technol. 99 (1977) 264-275: h_c / R_x = 2.69 U^0.67 G^0.53 W^-0.067
    # (1 - 0.61 exp(-0.73 k)), h_min / R_x = 3.63 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.68 k))
    r_x, k, u_r, q = contact
    U, G, W = _groups(u_r, q, r_x)
    h_c = r_x * 2.69 * U ** 0.67 * G ** 0.53 * W ** -0.067 * (1.0 - 0.61 * math.exp(-0.73 * k))
    h_min = r_x * 3.63 * U ** 0.68 * G ** 0.49 * W ** -0.073 * (1.0 - math.exp(-0.68 * k))
    assert float(ehl.film_thickness_central_hamrock_dowson(u_r, q, r_x, k, E_PRIME, ETA, XI)) == \
        pytest.approx(h_c, rel=SAME_FORMULA)
    assert float(ehl._film_thickness(0, u_r, q, r_x, k, E_PRIME, ETA, XI)) == pytest.approx(h_min, rel=SAME_FORMULA)
    # the film parameter of the DEM papers (Guessasma & Machado 2018, eq. 7): h_min / 3.75e-7 m
    assert float(ehl.film_parameter(h_min, 3.75e-7)) == pytest.approx(h_min / (1.25 * 3e-7), rel=SAME_FORMULA)


# -- traction over the Hertz ellipse -------------------------------------------------------------------------
A_AX, B_AX, Q = 2e-3, 0.25e-3, 1500.0  # semi-axes along e_y, e_x [m], load [N]
P0 = 3.0 * Q / (2.0 * math.pi * A_AX * B_AX)  # Hertz peak pressure, p0 = 3 Q / (2 pi a b)
MU = 0.1  # the catalogue's "coulomb_0.1"


@pytest.mark.parametrize("n_strips, n_across", [(1, 1), (7, 1), (32, 1), (16, 5), (64, 8)])
def test_fully_sliding_coulomb_contact_transmits_mu_q(n_strips, n_across):
    # uniform slip (0.3, 0.4) m/s, no spin, constant mu: every point slides along -v, so the force
    # is mu Q against the slip and the dissipation mu Q |v|, for any discretisation (the strip
    # loads are exact integrals of the Hertz pressure). Only round-off separates them: 1e-12.
    v0, v_t = 0.3, 0.4
    r = contact_traction(A_AX, B_AX, Q, v0, 0.0, v_t=v_t, u_roll=10.0, model="coulomb_0.1",
                         n_strips=n_strips, n_across=n_across)
    assert r.force_x == pytest.approx(-MU * Q * 0.6, rel=1e-12)
    assert r.force_y == pytest.approx(-MU * Q * 0.8, rel=1e-12)
    assert r.dissipation == pytest.approx(MU * Q * 0.5, rel=1e-12)
    assert abs(r.moment_z) <= 1e-12 * MU * Q * A_AX  # symmetric pressure, uniform slip: no moment


def _spin_moment_quadrature(mu, q, a, b):
    """int mu p rho dA over the ellipse, p = p0 sqrt(1 - x^2/b^2 - y^2/a^2) (Hertz), rho = |(x, y)|,
    by scipy in elliptic polar coordinates x = b s cos t, y = a s sin t, dA = a b s ds dt."""
    p0 = 3.0 * q / (2.0 * math.pi * a * b)

    def f(s, t):
        return mu * p0 * math.sqrt(1.0 - s * s) * math.hypot(b * s * math.cos(t), a * s * math.sin(t)) * a * b * s
    return integrate.dblquad(f, 0.0, 2.0 * math.pi, 0.0, 1.0, epsabs=0.0, epsrel=1e-11)[0]


def test_pure_spin_coulomb_moment_against_quadrature_of_the_hertz_pressure():
    m_quad = _spin_moment_quadrature(MU, Q, A_AX, B_AX)
    # closed form (3/8) mu Q a E(e) (Jones 1959): the quadrature's own error (< 1e-10) sets 1e-9
    assert float(spin_moment_coulomb(MU, Q, A_AX, B_AX)) == pytest.approx(m_quad, rel=1e-9)
    # circular contact: E = pi/2, (3 pi / 16) mu Q a
    assert float(spin_moment_coulomb(MU, Q, 1e-3, 1e-3)) == pytest.approx(3 * math.pi / 16 * MU * Q * 1e-3,
                                                                          rel=1e-12)
    # the strip integration with points across: measured discretisation error 4.5e-5 at 128 x 16
    # (2.0e-4 at 64 x 8, falling as 1/n^2); 2e-4 is four times the error it has
    r = contact_traction(A_AX, B_AX, Q, 0.0, 100.0, model="coulomb_0.1", n_strips=128, n_across=16)
    assert abs(r.moment_z) == pytest.approx(m_quad, rel=2e-4)
    assert r.dissipation == pytest.approx(100.0 * m_quad, rel=2e-4)  # P = M w for pure spin
    # classical strip theory (slip on the major axis only): |M| -> (3/4) Q a mu int |v| (1 - v^2) dv
    # = (3/8) mu Q a; the midpoint error at 400 strips is 8.3e-6 (measured), 3e-5 allows four times
    r = contact_traction(A_AX, B_AX, Q, 0.0, 100.0, model="coulomb_0.1", n_strips=400, n_across=1)
    assert abs(r.moment_z) == pytest.approx(0.375 * MU * Q * A_AX, rel=3e-5)


def test_linear_creep_limit_of_the_traction_curve():
    # mu(s) = (A + B s) exp(-C s) + D (ADORE's form, Gupta 1984) with A = -D has the initial slope
    # d mu/ds(0) = B - C A; for the catalogue's ester curve (A = -0.02, B = 2, C = 40, D = 0.02)
    # 2 + 40 * 0.02 = 2.8. Uniform slide-to-roll ratio s = 1e-5: F = 2.8 s Q. The curve's quadratic
    # term -(B C + C^2 D / 2) s^2 = -96 s^2 makes it 3.4e-4 smaller (relative): 1e-3 covers that.
    s, u = 1e-5, 5.0
    r = contact_traction(A_AX, B_AX, Q, s * u, 0.0, u_roll=u, model="ester_curve_illustrative")
    assert -r.force_x == pytest.approx(2.8 * s * Q, rel=1e-3)
    assert r.dissipation == pytest.approx(2.8 * s * Q * s * u, rel=1e-3)


def _newtonian_ehl(xi):
    # an EHL film far below thinning and the limiting stress: tau = eta exp(xi p) |v| / h (Barus)
    return TractionModel(kind="ehl", parameters=dict(viscosity=0.01, pressure_viscosity=xi, shear_modulus=1e15,
                                                     thinning_exponent=1.0, limiting_shear_coefficient=0.5))


def test_newtonian_ehl_traction_integrates_the_hertz_pressure():
    # uniform slip v, Newtonian Barus film: F = (eta v / h) int exp(xi p) dA over the ellipse, and with
    # p = p0 sqrt(1 - s^2) in elliptic polar coordinates, t = sqrt(1 - s^2):
    #   int exp(xi p) dA = 2 pi a b int_0^1 t exp(k t) dt = 2 pi a b (e^k (k - 1) + 1) / k^2,  k = xi p0.
    # The traction depends on the local pressure here (a pressure scaled by 2/3 or by 1.02 changes F
    # by -53 % or -8 %). Measured discretisation error at 128 strips x 16 points: 1.2e-4 (4.2e-4 at
    # 64 x 8, falling as 1/n^2); 5e-4 is four times the error it has.
    eta, v, h, xi = 0.01, 1e-3, 1e-6, 3e-9
    k = xi * P0
    f_exact = eta * v / h * 2.0 * math.pi * A_AX * B_AX * (math.exp(k) * (k - 1.0) + 1.0) / k ** 2
    r = contact_traction(A_AX, B_AX, Q, v, 0.0, u_roll=5.0, h_central=h, model=_newtonian_ehl(xi),
                         n_strips=128, n_across=16)
    assert -r.force_x == pytest.approx(f_exact, rel=5e-4)
    assert r.dissipation == pytest.approx(v * f_exact, rel=5e-4)
    # classical strip theory (one point per strip, its load dQ at the pressure on the major axis,
    # p0 sqrt(1 - v^2)) converges to F = (eta v / h) (pi a b / 2) int_-1^1 sqrt(1 - v^2) exp(k sqrt(1 - v^2)) dv
    # (dQ = Q (3/4) (1 - v^2) dv, divided by that pressure): it overrates the Newtonian traction by
    # 39 % at k = 4.3 (the pressure across each strip is taken at its peak). Measured midpoint error
    # at 64 strips: below 1e-4; 5e-4 as above.
    strip = eta * v / h * math.pi * A_AX * B_AX / 2.0 * integrate.quad(
        lambda w: math.sqrt(1.0 - w * w) * math.exp(k * math.sqrt(1.0 - w * w)), -1.0, 1.0, epsabs=0.0,
        epsrel=1e-12)[0]
    r = contact_traction(A_AX, B_AX, Q, v, 0.0, u_roll=5.0, h_central=h, model=_newtonian_ehl(xi),
                         n_strips=64, n_across=1)
    assert -r.force_x == pytest.approx(strip, rel=5e-4)


# -- the contact kernel's normal law, damping, film and traction paths ---------------------------------------
@pytest.fixture(scope="module")
def kernel_params():
    from exudyn_bearing.model.parameters import scene_parameters

    sc = eb.Scenario(Fr=3000.0, omega=500.0, traction_level="ellipse", traction="coulomb_0.1")
    return scene_parameters(eb.catalog["6208"], sc, default_lubricant())


def test_kernel_normal_law_is_hertz_with_hunt_crossley_damping(kernel_params):
    # Q = K delta^1.5, K = pi k E' sqrt(2 E R / (9 F^3)) (Hamrock & Brewe 1983), R = R_x R_y / (R_x + R_y);
    # C_hyst = (3/2) alpha_e K delta^1.5 (Hunt & Crossley 1975: F = K d^1.5 (1 + (3/2) alpha_e d')),
    # alpha_e = 0.08 s/m (the DEM papers' steel). 6208 inner contact: R_x = 4.990 mm, R_y = 163.8 mm.
    from exudyn_bearing.model.contact import _normal_law

    p = kernel_params
    rx, ry, delta, alpha_e = 4.990e-3, 163.8e-3, 1.2e-5, 0.08
    kst, k, f, e = hertz_stiffness_by_hand(rx, ry, E_PRIME)
    rr = rx * ry / (rx + ry)
    q, k_t, c = _normal_law(p, delta, k, f, e, rr)
    # the scipy integrals and the kernel's agree to ~1e-13: 1e-9 as for one formula
    assert q == pytest.approx(kst * delta ** 1.5, rel=SAME_FORMULA)
    assert k_t == pytest.approx(1.5 * kst * delta ** 0.5, rel=SAME_FORMULA)
    assert c == pytest.approx(1.5 * alpha_e * kst * delta ** 1.5, rel=SAME_FORMULA)


@pytest.mark.parametrize("u_r, regime", [(0.5, 0), (7.2475, 1), (40.0, 2)])
def test_kernel_lubrication_path_by_hand(kernel_params, u_r, regime):
    # film: Hamrock-Dowson h_min; Lambda = h_min / 3.75e-7 m (Guessasma & Machado eq. 7); regime:
    # boundary up to Lambda 1, mixed up to 3, full film above; damping: C_hyst (boundary), the series
    # C_hyst C_fl / (C_hyst + C_fl) (mixed), C_fl = (3 pi eta a / sqrt 2) (R_b / h)^1.5 (full film);
    # mu: 0.1 up to Lambda 1, linear to 0.01 at 3, 0.01 above (the DEM papers' Stribeck fit)
    from exudyn_bearing.model.contact import _lubrication

    rx, k, _, q = OUTER
    major, r_b, c_hyst = 1.7e-3, 6.3e-3, 35.0
    h, lam, reg, c_n, mu = _lubrication(kernel_params, u_r, q, rx, k, major, c_hyst)
    U, G, W = _groups(u_r, q, rx)
    h_hand = rx * 3.63 * U ** 0.68 * G ** 0.49 * W ** -0.073 * (1.0 - math.exp(-0.68 * k))
    lam_hand = h_hand / 3.75e-7
    c_fl = 3.0 * math.pi * ETA * major / math.sqrt(2.0) * (r_b / h_hand) ** 1.5
    c_hand = {0: c_hyst, 1: c_hyst * c_fl / (c_hyst + c_fl), 2: c_fl}[regime]
    mu_hand = 0.1 if lam_hand <= 1.0 else (0.01 if lam_hand >= 3.0 else 0.1 + (lam_hand - 1.0) / 2.0 * (0.01 - 0.1))
    assert reg == regime
    assert (h, lam, c_n, mu) == pytest.approx((h_hand, lam_hand, c_hand, mu_hand), rel=SAME_FORMULA)


def test_kernel_ellipse_traction_of_a_sliding_contact(kernel_params):
    # the kernel's ellipse path (model/contact.py _ellipse_traction) for a contact sliding at 0.5 m/s
    # along e_x in the world x-y plane, rolling at 10 m/s: Coulomb mu = 0.1 of the catalogue model
    # (slide-to-roll 0.05, above the dynamic regularisation 0.01), so F = mu Q against the slip and
    # P = mu Q |v| (round-off only: 1e-12)
    from exudyn_bearing.model.contact import _ellipse_traction
    from exudyn_bearing.model.layout import P_RD_O

    c = math.cos(0.3)
    s = math.sin(0.3)
    ex, ey = (c, s, 0.0), (-s, c, 0.0)  # rolling direction and e_y = e_x x n, n = -e_z
    v = 0.5
    fx, fy, fz, mz, my, power = _ellipse_traction(kernel_params, 7.6e-3, 7.25, A_AX, B_AX, Q, v * ex[0], v * ex[1],
                                                  0.0, 10.0 * ex[0], 10.0 * ex[1], 0.0, 8e-7, 0.0, 0.0, False, *ex,
                                                  *ey)
    assert (fx, fy, fz) == pytest.approx((-MU * Q * ex[0], -MU * Q * ex[1], 0.0), rel=1e-12, abs=1e-9)
    assert power == pytest.approx(MU * Q * v, rel=1e-12)
    # no spin: no spin moment
    assert abs(mz) <= 1e-12 * MU * Q * A_AX
    # the sliding traction acts on the pressed surface, curved across the rolling direction (radius R_d): at
    # y it lies y^2 / (2 R_d) below the contact plane, so it turns about e_y by
    # M_y = -mu int p y^2 dA / (2 R_d) = -mu Q a^2 / (10 R_d) (int p y^2 dA = Q a^2 / 5 for Hertz pressure);
    # the default 16 strips take y^2 at their mid-points: 2 % covers that quadrature (measured 0.4 %)
    r_d = kernel_params[P_RD_O]
    assert my == pytest.approx(-MU * Q * A_AX ** 2 / (10.0 * r_d), rel=0.02)


# -- kinematics: published defect frequencies ---------------------------------------------------------------
def test_cwru_6205_defect_frequencies():
    # Case Western Reserve University bearing data center, drive-end SKF 6205-2RS JEM: 9 balls,
    # ball diameter 0.3126 in, pitch diameter 1.537 in; published defect frequencies (multiples of
    # the shaft speed): BPFI 5.4152, BPFO 3.5848, BSF 2.357. Each is printed to its last digit, so
    # half a unit of that digit is the tolerance (5e-5, 5e-5, 5e-4).
    inch = 0.0254
    f = kinematics.defect_frequencies(2.0 * math.pi, 0.0, 9, 0.3126 * inch / 2.0, 1.537 * inch / 2.0)
    assert f["bpfi"] == pytest.approx(5.4152, abs=5e-5)
    assert f["bpfo"] == pytest.approx(3.5848, abs=5e-5)
    assert f["bsf"] == pytest.approx(2.357, abs=5e-4)


def test_cage_speed_and_ball_spin_from_rolling_without_slip():
    # Harris & Kotzalas eq. 8.11 written from rolling without slip at both contacts, inner ring at
    # w_i, outer at rest, D = 2 R_b, d_m = 2 R_p: w_c = (w_i / 2) (1 - D cos(a) / d_m),
    # ball spin about its own axis relative to the cage w_R = (d_m w_i / (2 D)) (1 - (D cos(a) / d_m)^2)
    r_b, r_p, w_i = 6.3e-3, 30.3e-3, 500.0
    for a in (0.0, math.radians(25.0)):
        g = r_b * math.cos(a) / r_p
        assert float(kinematics.cage_speed(w_i, 0.0, r_b, r_p, a)) == pytest.approx(w_i / 2.0 * (1.0 - g),
                                                                                  rel=SAME_FORMULA)
        assert abs(float(kinematics.ball_spin_relative(w_i, 0.0, r_b, r_p, a))) == pytest.approx(
            r_p * w_i / (2.0 * r_b) * (1.0 - g * g), rel=SAME_FORMULA)
    # centrifugal force m r w_c^2 of a 6208 ball (33.4 g) orbiting at 198 rad/s: 39.7 N
    assert float(kinematics.centrifugal_force(0.0334, r_p, 198.0)) == pytest.approx(0.0334 * r_p * 198.0 ** 2,
                                                                                   rel=SAME_FORMULA)


# -- load distribution: Harris' table --------------------------------------------------------------------------
@pytest.mark.parametrize("eps, j_r", [(0.1, 0.1156), (0.3, 0.1892), (0.5, 0.2288), (0.8, 0.2559), (1.0, 0.2546),
                                      (1.25, 0.2289), (2.5, 0.1339), (5.0, 0.0711)])
def test_load_integrals_against_harris_table(eps, j_r):
    # Harris & Kotzalas, Rolling Bearing Analysis, Table 7.1 (point contact), J_r to four decimals:
    # half a unit of the last digit (5e-5) is the table's rounding. J_a from its definition,
    # (1/2 pi) int [1 - (1 - cos psi) / (2 eps)]^1.5 dpsi over the load zone, by scipy (its error
    # < 1e-11 sets 1e-9); J_a(0.5) = 0.2782 and J_a(1) = 4 / (3 pi) are in test_load_distribution.py
    from exudyn_bearing.physics import load_distribution as ld

    assert float(ld.load_integral_radial(eps)) == pytest.approx(j_r, abs=5e-5)
    psi_l = math.acos(max(-1.0, 1.0 - 2.0 * eps))
    j_a = integrate.quad(lambda psi: (1.0 - (1.0 - math.cos(psi)) / (2.0 * eps)) ** 1.5, -psi_l, psi_l,
                         epsabs=0.0, epsrel=1e-12)[0] / (2.0 * math.pi)
    assert float(ld.load_integral_axial(eps)) == pytest.approx(j_a, rel=SAME_FORMULA)
