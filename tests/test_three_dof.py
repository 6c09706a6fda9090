"""3-DOF vibration model (El Had et al. 2014): the ring-mode and short-bearing
relations, the eigen-analysis against independent calculations, the source's
eigenvalues, frequency and time response, and the CLI."""
import json
import math

import numpy as np
import pytest
import scipy.linalg as sla

from exudyn_bearing.cli import main
from exudyn_bearing.data import InputError, catalog
from exudyn_bearing.physics import hertz
from exudyn_bearing.physics.load_distribution import static_equilibrium
from exudyn_bearing.physics.ring_vibration import (rectangular_ring_section, ring_flexural_frequency,
                                                   ring_mode_factor, ring_modal_stiffness)
from exudyn_bearing.physics.short_bearing import (film_coefficients, film_eccentricity,
                                                  short_bearing_attitude_angle, short_bearing_damping,
                                                  short_bearing_load_number, short_bearing_stiffness)
from exudyn_bearing.solvers.vibration import linear
from exudyn_bearing.solvers.vibration import three_dof as td

from conftest import manual_text

EPS = np.array([0.1, 0.3, 0.5, 0.7, 0.9, 0.96])


# -- ring mode (El Had et al. eqs. 1-4) -------------------------------------------
def test_ring_mode_factor_is_the_sources_2_68():
    # El Had et al. 2014, eq. 4: omega_n = 2.68 sqrt(EI/(mu R^4)) for n = 2
    assert ring_mode_factor(2) == pytest.approx(2.68, abs=0.005)
    # eq. 3 for n = 3, 4: 3*8/sqrt(10), 4*15/sqrt(17)
    np.testing.assert_allclose(ring_mode_factor(np.array([3, 4])), [24 / math.sqrt(10), 60 / math.sqrt(17)])


def test_ring_stiffness_with_the_whole_ring_mass_is_mass_free():
    # k = M omega_2^2 with M = 2 pi R mu equals 2 pi n^2 (n^2-1)^2/(1+n^2) EI/R^3 = 2 pi 36/5 EI/R^3
    e, r = 210e9, 0.0198
    area, i = rectangular_ring_section(0.012, 0.0023)
    for mu in (7850.0 * area, 3.0 * 7850.0 * area):
        w = ring_flexural_frequency(e, i, mu, r, 2)
        k = ring_modal_stiffness(2 * math.pi * r * mu, w)
        assert k == pytest.approx(2 * math.pi * 36 / 5 * e * i / r ** 3, rel=1e-12)


def test_source_ring_stiffnesses_follow_from_its_masses():
    # El Had et al.: k1 = 1e7 N/m on 25 g is 2e4 rad/s; the printed 1e8 on 23 g is sqrt(1e8/0.023)
    assert ring_modal_stiffness(0.025, 2e4) == pytest.approx(1e7)
    assert ring_modal_stiffness(0.023, math.sqrt(1e8 / 0.023)) == pytest.approx(1e8)


@pytest.mark.parametrize("call", [
    lambda: ring_mode_factor(1), lambda: ring_mode_factor(2.5),
    lambda: ring_flexural_frequency(-1.0, 1.0, 1.0, 1.0), lambda: ring_flexural_frequency(1.0, 1.0, 0.0, 1.0),
    lambda: ring_modal_stiffness(0.02, float("nan")), lambda: rectangular_ring_section(0.01, -1e-3)])
def test_ring_bad_input(call):
    with pytest.raises(InputError):
        call()


# -- short-bearing film (El Had et al. eqs. 5-6) ------------------------------------
def _ocvirk_force(x, y):
    """Short-bearing (Ocvirk) film force on the journal at (x, y) / c, spin +z,
    in units of mu omega R L^3 / c^2: radial eps^2/(1-eps^2)^2 back to the
    centre, tangential pi eps / (4 (1-eps^2)^1.5) along the spin."""
    e = math.hypot(x, y)
    er = np.array([x, y]) / e
    et = np.array([-er[1], er[0]])
    return -e * e / (1 - e * e) ** 2 * er + math.pi * e / (4 * (1 - e * e) ** 1.5) * et


def _ocvirk_squeeze(x, y, vx, vy, n=4001):
    """Squeeze-film force on the journal for a journal velocity (vx, vy), in
    units mu R L^3 / c^3 times the velocity / c. Short-bearing Reynolds
    equation without rotation: int p dz = -mu L^3 h'/h^3 with h' = -v.n, the
    force -int p n R d(angle); film on the converging half that the spinning
    journal loads, from the thickest point (angle phi0 + pi) on along the spin."""
    e = math.hypot(x, y)
    phi0 = math.atan2(y, x)
    th = np.linspace(0.0, math.pi, n)
    ang = phi0 + math.pi + th          # direction of the film point; h = c (1 + e cos th)
    nx, ny = np.cos(ang), np.sin(ang)
    hdot = -(vx * nx + vy * ny)
    pz = -hdot / (1 + e * np.cos(th)) ** 3   # int over z of the pressure
    return -np.array([np.trapezoid(pz * nx, th), np.trapezoid(pz * ny, th)])


@pytest.mark.parametrize("eps", [0.3, 0.5, 0.8])
def test_short_bearing_coefficients_are_the_load_line_derivatives_of_ocvirks_film(eps):
    # independent: finite differences of the film force at the equilibrium of a load along -y
    # (attitude angle phi from the load line); k c / W along the load line must equal eq. 5
    phi = float(short_bearing_attitude_angle(eps))
    x0, y0 = eps * math.sin(phi), -eps * math.cos(phi)  # journal below the centre, shifted with the spin
    f0 = _ocvirk_force(x0, y0)
    assert abs(f0[0]) < 1e-12 * abs(f0[1])  # the film force is along the load line
    w = f0[1]
    assert w == pytest.approx(short_bearing_load_number(eps) / 4)
    h = 1e-6
    k_yy = -(_ocvirk_force(x0, y0 + h)[1] - _ocvirk_force(x0, y0 - h)[1]) / (2 * h)
    assert k_yy / w == pytest.approx(float(short_bearing_stiffness(eps)), rel=1e-6)
    # damping: the squeeze force of a velocity along the load line, the film
    # taken over the half from the thickest point in the spin direction
    c_yy = -_ocvirk_squeeze(x0, y0, 0.0, 1.0)[1]  # per unit velocity; omega = 1 in these units
    assert c_yy / w == pytest.approx(float(short_bearing_damping(eps)), rel=1e-5)


def test_short_bearing_coefficients_match_the_published_closed_forms():
    # Friswell et al. 2010, ch. 5, load-direction coefficients of the short bearing with
    # h0 = (pi^2 (1 - e^2) + 16 e^2)^-1.5
    e = EPS
    h0 = 1 / (np.pi ** 2 * (1 - e * e) + 16 * e * e) ** 1.5
    k = 4 * h0 * (np.pi ** 2 + (32 + np.pi ** 2) * e * e + (32 - 2 * np.pi ** 2) * e ** 4) / (1 - e * e)
    c = 2 * np.pi * h0 * (np.pi ** 2 + 2 * (24 - np.pi ** 2) * e * e + np.pi ** 2 * e ** 4) / (e * np.sqrt(1 - e * e))
    np.testing.assert_allclose(short_bearing_stiffness(e), k, rtol=1e-12)
    np.testing.assert_allclose(short_bearing_damping(e), c, rtol=1e-12)


def test_printed_prefactor_is_cos2_over_4_of_the_corrected_one():
    # the source prints 4/(W_r lambda^2) without the 4 and with cos^2(phi)
    ratio = np.cos(short_bearing_attitude_angle(EPS)) ** 2 / 4
    np.testing.assert_allclose(short_bearing_stiffness(EPS, printed_prefactor=True),
                               ratio * short_bearing_stiffness(EPS), rtol=1e-12)
    np.testing.assert_allclose(short_bearing_damping(EPS, printed_prefactor=True),
                               ratio * short_bearing_damping(EPS), rtol=1e-12)


def test_film_coefficients_scale_and_bad_input():
    k, c = film_coefficients(0.5, 200.0, 5e-6, 300.0)
    assert k == pytest.approx(short_bearing_stiffness(0.5) * 200 / 5e-6)
    assert c == pytest.approx(short_bearing_damping(0.5) * 200 / (5e-6 * 300))
    assert film_eccentricity(1e-6, 4e-6) == pytest.approx(0.75)
    for call, word in [(lambda: film_eccentricity(5e-6, 4e-6), "film_thickness"),
                       (lambda: film_eccentricity(1e-6, 0.0), "clearance"),
                       (lambda: short_bearing_stiffness(1.0), "eccentricity"),
                       (lambda: short_bearing_damping(float("nan")), "eccentricity"),
                       (lambda: film_coefficients(0.5, 100.0, 1e-5, 0.0), "omega")]:
        with pytest.raises(InputError, match=f"^{word}"):
            call()


# -- eigen-analysis ----------------------------------------------------------------
def _params(**kw):
    base = dict(mass_outer=0.025, mass_ball=0.002, mass_inner=0.023, k_outer_ring=1e7, k_inner_ring=8e7,
                k_outer_contact=5e7, k_inner_contact=6e7, c_outer_contact=0.0, c_inner_contact=0.0)
    base.update(kw)
    return td.ThreeDofParameters(**base)


def test_undamped_eigenvalues_are_sqrt_of_the_generalised_eigenproblem():
    p = _params()
    r = td.analyse(p)
    m, _c, k = td.assemble(p)
    w2 = sla.eigh(k, m, eigvals_only=True)
    lam = r.modal.eigenvalues
    np.testing.assert_allclose(np.abs(lam.real), 0.0, atol=1e-9 * np.abs(lam).max())
    np.testing.assert_allclose(np.sort(lam.imag[lam.imag > 0]), np.sqrt(w2), rtol=1e-10)
    np.testing.assert_allclose(r.modal.damping_ratios, 0.0, atol=1e-12)
    # mode shapes: the undamped ones are the real eigenvectors of K phi = w^2 M phi
    for lam_i, phi in zip(lam, r.modal.mode_shapes):
        assert np.abs(phi).max() == pytest.approx(1.0) and np.allclose(phi.imag, 0.0, atol=1e-10)
        np.testing.assert_allclose(k @ phi.real, lam_i.imag ** 2 * (m @ phi.real), rtol=1e-8,
                                   atol=1e-8 * np.abs(k @ phi.real).max())


def test_one_dof_closed_form():
    # m x'' + c x' + k x = 0: lambda = -zeta w_n +- i w_n sqrt(1 - zeta^2)
    m, k = 0.002, 8e7
    wn = math.sqrt(k / m)
    for zeta in (0.01, 0.3, 0.9):
        r = linear.modal_analysis([[m]], [[2 * zeta * math.sqrt(k * m)]], [[k]])
        assert r.natural_frequencies[0] == pytest.approx(wn / (2 * math.pi), rel=1e-12)
        assert r.damping_ratios[0] == pytest.approx(zeta, rel=1e-10)
        assert r.eigenvalues[0] == pytest.approx(complex(-zeta * wn, wn * math.sqrt(1 - zeta ** 2)), rel=1e-12)
    # overdamped: two real roots -w_n (zeta -+ sqrt(zeta^2 - 1)), damping ratio 1 each
    r = linear.modal_analysis([[m]], [[2 * 3.0 * math.sqrt(k * m)]], [[k]])
    roots = sorted(-wn * (3.0 + s * math.sqrt(8.0)) for s in (-1, 1))
    np.testing.assert_allclose(sorted(r.eigenvalues.real), roots, rtol=1e-10)
    np.testing.assert_allclose(r.damping_ratios, 1.0)


def test_proportional_damping_gives_the_modal_damping_ratios():
    # C = beta K: zeta_i = beta w_i / 2 for each undamped mode w_i (Rayleigh damping)
    beta = 2e-6
    p0 = _params()
    p = _params(c_outer_contact=beta * 5e7, c_inner_contact=beta * 6e7, c_outer_ring=beta * 1e7,
                c_inner_ring=beta * 8e7)
    m, c, k = td.assemble(p)
    np.testing.assert_allclose(c, beta * td.assemble(p0)[2])
    w = np.sqrt(sla.eigh(k, m, eigvals_only=True))
    modes = td.analyse(p).modal.modes()
    np.testing.assert_allclose([row["damping_ratio"] for row in modes], beta * w / 2, rtol=1e-9)
    np.testing.assert_allclose([row["frequency_hz"] for row in modes], w / (2 * np.pi), rtol=1e-9)


def test_source_eigenvalues_come_from_a_sign_error():
    # El Had et al. 2014 print V = 2e4, -2e4, -6.5763e4, 6.6178e4, 4.948e3, -0.1 (1/s): the eigenvalues
    # of their printed state matrix L, which is [[0, I], [+A^-1 C, +A^-1 B]] (both signs wrong) of their
    # printed matrices with A^-1 = diag(40, 500, 43.5), except A^-1 B = 413.25 where 43.5 * 9.9 = 430.65
    s = td.source_printed_system()
    lam = np.sort(np.linalg.eigvals(s["state_matrix"]).real)
    np.testing.assert_allclose(lam, np.sort(td.SOURCE_EIGENVALUES), rtol=1e-4)
    rebuilt = td.source_state_matrix(s["mass_inverse"], s["damping"], s["stiffness"])
    differ = np.argwhere(~np.isclose(rebuilt, s["state_matrix"], rtol=2e-3))
    assert differ.tolist() == [[5, 4], [5, 5]] and rebuilt[5, 5] == pytest.approx(430.65)
    # the correct system oscillates at +-i sqrt(k/M) where the source has real +-sqrt(k/M)
    r = td.analyse(td.source_parameters())
    osc = r.modal.eigenvalues[r.modal.eigenvalues.imag > 0]
    assert osc[0].imag == pytest.approx(math.sqrt(1e7 / 0.025), rel=1e-9)   # 2e4, undamped outer ring
    assert osc[0].real == 0.0
    assert osc[1].imag == pytest.approx(6.6e4, rel=2e-3)                    # sqrt(1e8/0.023) = 6.594e4
    assert osc[1].real < 0.0
    # each source pair r1, r2 solves r^2 - b r - k/M = 0, the correct one l^2 + b l + k/M = 0:
    # product -r1 r2 = |l|^2, sum r1 + r2 = -2 Re(l) (up to the source's rounding and 413.25)
    assert -lam[0] * lam[-1] == pytest.approx(abs(osc[1]) ** 2, rel=3e-3)
    assert -lam[1] * lam[-2] == pytest.approx(abs(osc[0]) ** 2, rel=1e-9)
    assert lam[0] + lam[-1] == pytest.approx(-2 * osc[1].real, rel=0.05)


def test_source_readings_change_what_they_say():
    base = td.source_parameters()
    assert (base.k_inner_ring, base.k_outer_contact, base.c_outer_contact) == (1e8, 0.0, 0.0)
    lst = td.source_parameters(inner_ring="parameter_list")
    r = td.analyse(lst).modal.eigenvalues
    assert r[r.imag > 0][-1].imag == pytest.approx(math.sqrt(1e7 / 0.023), rel=5e-3)
    eq7 = td.source_parameters(outer_link="eq7")
    assert eq7.k_outer_contact == 0.9925 and eq7.c_outer_contact == 9.9072
    lit = td.source_parameters(outer_link="eq7", damping_row="eq7_literal")
    c = td.assemble(lit)[1]
    np.testing.assert_array_equal(c[1], [0.0, 9.9072, -9.9072])       # C22 counted twice, y1' lost
    assert not np.allclose(c, c.T)
    # without the outer link the literal row equals the symmetric one
    np.testing.assert_array_equal(td.assemble(td.source_parameters(damping_row="eq7_literal"))[1],
                                  td.assemble(base)[1])
    with pytest.raises(InputError, match="^inner_ring"):
        td.source_parameters(inner_ring="1e9")


# -- frequency and time response ---------------------------------------------------
def test_frf_peaks_at_the_natural_frequency_and_starts_at_the_flexibility():
    p = _params(c_outer_contact=5.0, c_inner_contact=5.0, c_outer_ring=5.0, c_inner_ring=5.0)
    r = td.analyse(p)
    m, c, k = td.assemble(p)
    np.testing.assert_allclose(td.frequency_response(p, [0.0])[0].real, np.linalg.inv(k), rtol=1e-10)
    for row in r.modal.modes():
        fn, z = row["frequency_hz"], row["damping_ratio"]
        assert 1e-3 < z < 0.05
        f = np.linspace(fn * (1 - 4 * z), fn * (1 + 4 * z), 8001)
        h = td.frequency_response(p, f)
        j = int(np.argmax(np.abs(row["shape"])))
        peak = f[np.argmax(np.abs(h[:, j, j]))]
        # well separated, lightly damped modes: the receptance peaks at the natural frequency, within
        # 1 % of the half-power bandwidth 2 zeta f_n (a single-DOF receptance: at f_n sqrt(1 - 2 zeta^2))
        assert peak == pytest.approx(fn * math.sqrt(1 - 2 * z * z), abs=0.01 * 2 * z * fn)
        # and the half-power bandwidth of the peak is 2 zeta f_n
        mag = np.abs(h[:, j, j])
        above = f[mag >= mag.max() / math.sqrt(2)]
        assert above[-1] - above[0] == pytest.approx(2 * z * fn, rel=0.02)


def test_undamped_free_vibration_conserves_energy():
    p = _params()
    m, c, k = td.assemble(p)
    t = np.linspace(0.0, 5e-3, 20001)
    q, v = linear.time_response(m, c, k, t, np.zeros((t.size, 3)), q0=[1e-6, -2e-6, 0.5e-6])
    e = linear.mechanical_energy(m, k, q, v)
    assert np.ptp(e) < 1e-9 * e[0]


def test_damped_free_decay_dissipates_exactly_the_damper_work():
    p = _params(c_outer_contact=30.0, c_inner_contact=10.0, c_outer_ring=5.0)
    m, c, k = td.assemble(p)
    t = np.linspace(0.0, 4e-3, 40001)
    q, v = linear.time_response(m, c, k, t, np.zeros((t.size, 3)), v0=[0.01, -0.02, 0.005])
    e = linear.mechanical_energy(m, k, q, v)
    assert np.all(np.diff(e) <= 1e-12 * e[0])                     # never gains energy
    power = np.einsum("ti,ij,tj->t", v, c, v)
    dissipated = np.concatenate([[0.0], np.cumsum(0.5 * (power[1:] + power[:-1]) * np.diff(t))])
    np.testing.assert_allclose(e[0] - e, dissipated, atol=1e-4 * e[0])
    assert e[-1] < 0.5 * e[0]


def test_harmonic_steady_state_amplitude_equals_the_frf():
    p = _params(c_outer_contact=40.0, c_inner_contact=40.0, c_outer_ring=40.0, c_inner_ring=40.0)
    m, c, k = td.assemble(p)
    f0 = 2000.0
    t = np.arange(0.0, 0.06, 1.0 / (f0 * 200))
    force = np.zeros((t.size, 3))
    force[:, 0] = np.sin(2 * np.pi * f0 * t)
    q, _v = linear.time_response(m, c, k, t, force)
    h = td.frequency_response(p, [f0])[0]
    last = t > 0.05  # transients decayed (slowest mode decays with exp(-zeta w t))
    for i in range(3):
        assert np.max(np.abs(q[last, i])) == pytest.approx(abs(h[i, 0]), rel=2e-3)


def test_ball_pass_response_is_periodic_at_the_ball_pass_frequency():
    p = td.derived_parameters(film_damping="contact_model")
    f = td.bpfo("6004", 2 * math.pi * 50)
    # kinematic BPFO of the 6004 at 50 Hz: Z/2 (1 - D/d_m) f_shaft
    b = catalog["6004"]
    assert f == pytest.approx(9 / 2 * (1 - b.ball_diameter / b.pitch_diameter) * 50, rel=1e-12)
    res = td.ball_pass_response(p, f, t_end=30 / f, samples_per_pulse=60)
    t, q = res["t"], res["q"]
    period = int(round(1 / f / res["dt"]))
    assert period * res["dt"] == pytest.approx(1 / f, rel=1e-9)
    tail = t > 28 / f
    idx = np.nonzero(tail)[0]
    idx = idx[idx + period < t.size]
    np.testing.assert_allclose(q[idx + period], q[idx], atol=1e-3 * np.abs(q).max())
    # outer-race defect: the pulse pushes outer ring and ball apart
    assert q[:, 0].max() > 0 and q[:, 1].min() < 0
    assert np.all(np.isfinite(q))


# -- derived parameters ---------------------------------------------------------------
def test_derived_parameters_follow_from_bearing_and_load():
    p = td.derived_parameters("6004", radial_load=500.0, omega=2 * math.pi * 50, diametral_clearance=12.5e-6)
    d = p.derivation
    b = catalog["6004"].with_clearance(12.5e-6)
    assert p.mass_ball == pytest.approx(4 / 3 * math.pi * b.ball_radius ** 3 * 7850)
    assert d["q_max"] == pytest.approx(static_equilibrium(b, 500.0).q_max, rel=1e-9)
    for race in ("inner", "outer"):
        cd = d["contacts"][race]
        # tangent stiffness: numerical derivative of Q = K delta^1.5 at the load
        delta = (cd["load"] / cd["hertz_K"]) ** (2 / 3)
        dq = (cd["hertz_K"] * (delta * 1.0001) ** 1.5 - cd["hertz_K"] * (delta * 0.9999) ** 1.5) / (2e-4 * delta)
        assert cd["k_hertz"] == pytest.approx(dq, rel=1e-6)
        assert 1 / cd["k_link"] == pytest.approx(1 / cd["k_hertz"] + 1 / cd["k_film"], rel=1e-12)
        assert cd["eccentricity"] == pytest.approx(1 - cd["h_min"] / 6.25e-6)
    # rings: 2 pi 36/5 E I / R^3 with the rectangular section
    for ring in ("outer_ring", "inner_ring"):
        r = d[ring]
        assert r["stiffness"] == pytest.approx(2 * math.pi * 36 / 5 * 210e9 * r["second_moment"] / r["radius"] ** 3,
                                               rel=1e-12)
    assert p.k_outer_ring == d["outer_ring"]["stiffness"]
    # 6004: R_o = 18.675 mm to 21 mm, R_i = 12.325 mm from 10 mm
    assert d["outer_ring"]["thickness"] == pytest.approx(21e-3 - b.outer_race_radius)
    assert d["inner_ring"]["thickness"] == pytest.approx(12.325e-3 - 10e-3)
    assert hertz.tangent_stiffness(d["contacts"]["inner"]["hertz_K"], d["q_max"]) == pytest.approx(
        d["contacts"]["inner"]["k_hertz"])


@pytest.mark.parametrize("kw, word", [
    (dict(radial_load=0.0), "radial_load"), (dict(omega=-1.0), "omega"),
    (dict(diametral_clearance=0.0), "diametral_clearance"), (dict(link="rigid"), "link"),
    (dict(film_damping="none"), "film_damping"), (dict(diametral_clearance=0.3e-6), "film_thickness"),
    (dict(bearing="6309"), "bearing")])
def test_derived_parameters_bad_input(kw, word):
    with pytest.raises(InputError, match=f"^{word}"):
        td.derived_parameters(**kw)


@pytest.mark.parametrize("kw, word", [
    (dict(mass_ball=0.0), "mass_ball"), (dict(k_inner_ring=-1.0), "k_inner_ring"),
    (dict(c_inner_contact=float("nan")), "c_inner_contact"), (dict(damping_row="x"), "damping_row"),
    (dict(k_outer_contact=0.0, k_inner_contact=0.0), "k_inner_contact"),
    (dict(k_outer_ring=0.0, k_outer_contact=0.0), "k_outer_ring")])
def test_parameter_record_validation(kw, word):
    with pytest.raises(InputError, match=f"^{word}"):
        _params(**kw)


def test_linear_tools_reject_bad_matrices():
    with pytest.raises(InputError, match="^mass"):
        linear.modal_analysis([[0.0]], [[0.0]], [[1.0]])
    with pytest.raises(InputError, match="^stiffness"):
        linear.modal_analysis(np.eye(2), np.zeros((2, 2)), [[1.0, -1.0], [-1.0, 1.0]])  # rigid-body mode
    with pytest.raises(InputError, match="^t"):
        linear.time_response([[1.0]], [[0.0]], [[1.0]], [0.0, 1.0, 3.0], np.zeros((3, 1)))
    with pytest.raises(InputError, match="^pulse_duration"):
        td.ball_pass_force(np.zeros(3), 100.0, 1.0, 0.02)


# -- CLI ---------------------------------------------------------------------------------
def test_cli_three_dof_source_parameters_json(capsys):
    assert main(["vibration", "three-dof", "--source-parameters", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    for key in ("eigenvalues", "natural_frequencies", "damping_ratios", "mode_shapes", "units"):
        assert key in d
    assert len(d["eigenvalues"]) == 6 and all(len(z) == 2 for z in d["eigenvalues"])
    assert len(d["mode_shapes"]) == 6 and all(len(s) == 3 for s in d["mode_shapes"])
    assert d["units"]["eigenvalues"].startswith("1/s") and d["units"]["natural_frequencies"] == "Hz"
    ims = sorted(abs(z[1]) for z in d["eigenvalues"])
    assert ims[-1] == pytest.approx(6.6e4, rel=2e-3) and ims[-3] == pytest.approx(2e4, rel=1e-9)
    assert d["reading"] == {"inner_ring": "printed_matrix", "outer_link": "printed_matrix",
                            "damping_row": "symmetric"}
    assert main(["vibration", "three-dof", "--source-parameters", "--inner-ring", "parameter_list",
                 "--json"]) == 0
    d2 = json.loads(capsys.readouterr().out)
    assert max(abs(z[1]) for z in d2["eigenvalues"]) == pytest.approx(math.sqrt(1e7 / 0.023), rel=5e-3)


def test_cli_three_dof_derived_table_and_errors(capsys):
    assert main(["vibration", "three-dof", "--rpm", "3000", "--film-damping", "contact_model"]) == 0
    out = capsys.readouterr().out
    assert "f_n [Hz]" in out and "derived: 6004" in out
    assert main(["vibration", "three-dof", "--Fr", "-1", "--json"]) == 2
    assert capsys.readouterr().err.startswith("exudyn-bearing: error: radial_load")
    with pytest.raises(SystemExit) as exc:
        main(["vibration", "three-dof", "--rpm", "100", "--omega", "10"])
    assert exc.value.code == 2


# -- every catalogue bearing: ring sections from the bearing, the real cause in errors ----------------------
SKF = {"6004": (20e-3, 42e-3, 12e-3), "6205": (25e-3, 52e-3, 15e-3), "6208": (40e-3, 80e-3, 18e-3)}


@pytest.mark.parametrize("name", sorted(SKF))
def test_ring_section_estimate_is_close_to_the_published_dimensions(name):
    # SKF catalogue boundary dimensions d x D x B; the estimate from ball and pitch diameter alone
    # (D_w = 0.3 (D - d), B = (D - d)/2): bore and outside diameter within 4 %, width within 20 % (the published
    # D_w / (D - d) are 0.289, 0.294, 0.315, which put the 6205's bore 3.2 % off; B / ((D - d)/2) 1.09, 1.11, 0.90)
    import dataclasses

    b = dataclasses.replace(catalog[name], bore=None, outer_diameter=None, name="unnamed")
    dims, source = td.ring_dimensions(b)
    d, big_d, width = SKF[name]
    assert dims.bore == pytest.approx(d, rel=0.04) and dims.outer_diameter == pytest.approx(big_d, rel=0.04)
    assert dims.width == pytest.approx(width, rel=0.20)
    assert all(v.startswith("estimate") for v in source.values())
    # by name the published values themselves
    pub, source = td.ring_dimensions(name)
    assert (pub.bore, pub.outer_diameter, pub.width) == (d, big_d, width)


def test_6208_outer_ring_stiffness_from_its_own_section():
    # 6208 (SKF 40 x 80 x 18 mm): outer ring between the race bottom R_o (36.6 mm with the default 12.5 um
    # clearance) and D/2 = 40 mm, 18 mm wide; Hoppe n = 2 with the whole ring mass:
    # k = 2 pi n^2 (n^2 - 1)^2 / (1 + n^2) E I / R^3 = 14.4 pi E I / R^3
    p = td.derived_parameters("6208")
    r_o = catalog["6208"].with_clearance(12.5e-6).outer_race_radius
    assert r_o == pytest.approx(36.6e-3, abs=10e-6)
    t, width = 40e-3 - r_o, 18e-3
    r = 0.5 * (40e-3 + r_o)
    i = width * t ** 3 / 12.0
    assert p.k_outer_ring == pytest.approx(14.4 * math.pi * 210e9 * i / r ** 3, rel=1e-12)
    assert p.derivation["dimensions_source"]["outer_diameter"] == "catalogue (SKF): 6208"


@pytest.mark.parametrize("argv", [["6205"], ["6208"], ["7208", "--Fa", "1000"], ["ACBB-120", "--Fa", "3000"],
                                  ["6208", "--outer-diameter", "0.082", "--width", "0.02"]])
def test_cli_three_dof_runs_for_every_catalogue_bearing(argv, capsys):
    assert main(["vibration", "three-dof", *argv, "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["label"].startswith(f"derived: {argv[0]}") and len(d["natural_frequencies"]) == 6
    assert all(z > 0 for z in d["damping_ratios"])


def test_angular_contact_links_act_along_the_contact_normal():
    # the contact spring along the normal at alpha seen on the radial line: k cos^2(alpha)
    p = td.derived_parameters("7208", axial_load=1000.0)
    d = p.derivation
    alpha = d["contact_angle"]
    assert math.degrees(alpha) > 30.0
    for race, k in (("inner", p.k_inner_contact), ("outer", p.k_outer_contact)):
        c = d["contacts"][race]
        assert k == pytest.approx(math.cos(alpha) ** 2 / (1.0 / c["k_hertz"] + 1.0 / c["k_film"]), rel=1e-12)


@pytest.mark.parametrize("argv, start, words", [
    (["--source-parameters", "--bearing", "6208"], "source_parameters", ("--bearing",)),
    (["--source-parameters", "--Fr", "800"], "source_parameters", ("--Fr",)),
    (["--Fr", "1e5"], "radial_load", ("4.2 GPa", "elastic")),
    (["--rpm", "1"], "omega", ("film", "--film-damping contact_model")),
    (["6208", "--outer-diameter", "0.07"], "outer_diameter", ("outer race", "6208")),
    (["7208"], "axial_load", ("F_a >",))])
def test_cli_three_dof_names_the_real_cause(argv, start, words, capsys):
    assert main(["vibration", "three-dof", *argv]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"exudyn-bearing: error: {start}:")
    assert all(w in err[0] for w in words) and "zero eigenvalue" not in err[0]


def test_eigenvalues_beyond_double_precision_are_refused():
    # one mass m = 1e-3 kg on k = 1e8 N/m with c = 1e11 N s/m: roots about -c/m = -1e14 and -k/c = -1e-3 1/s,
    # a span of 1e17 that double precision cannot resolve; the stiffness is regular (not a rigid-body mode)
    with pytest.raises(InputError, match="^damping: the eigenvalues span"):
        linear.modal_analysis([[1e-3]], [[1e11]], [[1e8]])
    # a heavily but resolvably overdamped one passes: roots -c/m and -k/c to 1e-6 (span 1e10)
    r = linear.modal_analysis([[1e-3]], [[1e4]], [[1e2]])
    assert sorted(abs(r.eigenvalues)) == pytest.approx([1e-2, 1e7], rel=1e-6)


def test_readme_three_dof_commands_run(capsys):
    text = manual_text()
    lines = [x for x in text.splitlines() if x.startswith("python -m exudyn_bearing vibration three-dof")]
    assert len(lines) == 2
    for line in lines:
        assert main(line.split("python -m exudyn_bearing ", 1)[1].split()) == 0
    assert "derived: 7208, Fr = 500 N, Fa = 1000 N" in capsys.readouterr().out
