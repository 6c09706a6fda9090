"""The ball / pocket oil film (physics/pocket_film.py, Scenario(pocket_film=True); docs/theory/cage.md#pocket-oil-film)."""
import math
import warnings

import numpy as np
import pytest
from scipy import integrate

import exudyn_bearing as eb
from exudyn_bearing.data import InputError
from exudyn_bearing.model.stability import pocket_film_step, rigid_cage_step
from exudyn_bearing.physics import pocket_film as pf


def test_isoviscous_rigid_constant_by_hand():
    # Brewe, Hamrock & Taylor's fit, evaluated by hand: alpha_r = 1, lambda_b = 0.6,
    # 0.131 atan(0.5) + 1.683 = 1.74373; 128 * 0.36 * 1.74373^2 = 140.11
    assert float(pf.isoviscous_rigid_film_constant(1.0)) == pytest.approx(140.11, abs=0.01)
    # the long-ellipsoid limit: lambda_b -> 1, atan -> pi/2: 128 alpha_r (0.131 pi / 2 + 1.683)^2
    a = 1e6
    assert float(pf.isoviscous_rigid_film_constant(a)) / a == pytest.approx(
        128.0 * (0.131 * math.pi / 2 + 1.683) ** 2, rel=1e-5)


def test_hydrodynamic_force_inverts_the_film_formula():
    # the load the function returns, put into H_hat = (h / R_x) (W / U)^2 with any E', gives the fit's H_hat
    eta, u, r_x, alpha, h, e_prime = 0.02, 3.0, 6e-3, 25.0, 1e-6, 2.2e11
    w = float(pf.hydrodynamic_film_force(eta, u, r_x, alpha, h))
    big_u, big_w = eta * u / (e_prime * r_x), w / (e_prime * r_x ** 2)
    assert (h / r_x) * (big_w / big_u) ** 2 == pytest.approx(float(pf.isoviscous_rigid_film_constant(alpha)), rel=1e-12)
    # a thinner film carries more, as h^-1/2; the entraining direction does not matter
    assert float(pf.hydrodynamic_film_force(eta, -u, r_x, alpha, h / 4)) == pytest.approx(2.0 * w, rel=1e-12)


def test_squeeze_force_against_reynolds_equation():
    # Reynolds' equation for a sphere approaching a plane, axisymmetric gap h(r) = h0 + r^2 / (2 R):
    # d/dr (r h^3 dp/dr) = 12 eta r (dh/dt), p(inf) = 0, integrated numerically: the closed form's load
    eta, radius, h0, v = 0.05, 6e-3, 2e-6, 1e-3   # approach speed v = -dh/dt

    def dpdr(r):
        return -6.0 * eta * v * r / (h0 + r * r / (2.0 * radius)) ** 3

    def p(r):
        return -integrate.quad(dpdr, r, np.inf, limit=200)[0]

    split = 50.0 * math.sqrt(2.0 * radius * h0)  # fifty times the film's width
    load = sum(integrate.quad(lambda r: 2.0 * math.pi * r * p(r), a, b, limit=400)[0]
               for a, b in ((0.0, split), (split, np.inf)))
    assert load == pytest.approx(float(pf.squeeze_film_force(eta, radius, h0, v)), rel=1e-4)
    assert float(pf.squeeze_film_force(eta, radius, h0, -v)) == 0.0  # separating: the film cavitates


def test_shear_resistance_is_reciprocal_and_gives_the_quarter_rolling_limit():
    # Goldman, Cox & Brenner's two coupling coefficients, the force per rotation 6 pi eta R^2 (2/15 L + 0.2526)
    # and the moment per translation 8 pi eta R^2 (1/10 L + 0.1895), are one by the reciprocal theorem
    eta, radius = 0.04, 6e-3
    for h in (1e-7, 1e-6, 1e-5):
        big_l = math.log(radius / h)
        _, b, _ = pf.shear_resistance(eta, radius, h)
        assert 6.0 * math.pi * eta * radius ** 2 * (2.0 / 15.0 * big_l + 0.2526) == pytest.approx(b, rel=3e-4)
    # a moment-free sphere sliding along the wall turns in the rolling sense at Omega R / U = B R / C,
    # which tends to 1/4 as the gap closes (GCB 1967); slowly, as 1 / ln(R / h)
    ratios = [float(b * radius / c) for _, b, c in (pf.shear_resistance(eta, radius, h) for h in (1e-5, 1e-12, 1e-40))]
    assert ratios[0] > ratios[1] > ratios[2] > 0.25 and ratios[2] == pytest.approx(0.25, abs=0.01)


def test_sphere_wall_shear_directions_and_dissipation():
    eta, radius, h = 0.04, 6e-3, 2e-6
    a, b, c = pf.shear_resistance(eta, radius, h)
    # the wall below (n = -z), the ball sliding along +x: drag along -x, and a moment about +y, the sense in
    # which it would roll along +x; a velocity toward the wall is the squeeze film's, not the shear's
    fx, fy, fz, mx, my, mz = pf.sphere_wall_shear(eta, radius, h, 0.0, 0.0, -1.0, 1.0, 0.0, -5.0, 0.0, 0.0, 0.0)
    assert (fx, fy, fz) == pytest.approx((-a, 0.0, 0.0)) and (mx, my, mz) == pytest.approx((0.0, b, 0.0))
    # spinning about the normal: no shear (left out); rolling about +y: the surface at the gap moves along -x,
    # the film pushes the ball along +x and brakes the rotation
    assert pf.sphere_wall_shear(eta, radius, h, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 7.0) == (0.0,) * 6
    fx, _, _, _, my, _ = pf.sphere_wall_shear(eta, radius, h, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0)
    assert fx == pytest.approx(b) and my == pytest.approx(-c)
    # any motion dissipates: -(F.u + T.omega) > 0 (the resistance is positive definite)
    rng = np.random.default_rng(1)
    for _ in range(50):
        n = rng.normal(size=3)
        n /= np.linalg.norm(n)
        u, w = rng.normal(size=3), rng.normal(size=3) * 300.0
        f = pf.sphere_wall_shear(eta, radius, h, *n, *u, *w)
        assert -(np.dot(f[:3], u) + np.dot(f[3:], w)) > 0.0


def test_pocket_film_radii():
    rb, c = 6e-3, 2.5e-4
    conform = rb * (rb + c) / c
    assert pf.pocket_film_radii(rb, c, True) == pytest.approx((rb, conform / rb))
    assert pf.pocket_film_radii(rb, c, False) == pytest.approx((conform, 1.0))


@pytest.mark.parametrize("kw", [dict(cage="none"), dict(cage="rigid", lubrication=False), dict(cage="torus")])
def test_pocket_film_needs_the_rigid_cage_and_oil(kw):
    with pytest.raises(InputError, match="^pocket_film: "):
        eb.Scenario(Fr=3000.0, omega=500.0, pocket_film=True, **kw)


def test_pocket_film_on_a_torus_caged_bearing_is_refused_by_name():
    # cage='auto' is the 6208's torus cage, known only with the bearing
    with pytest.raises(InputError, match="^pocket_film: .*cage='torus' .*set cage='rigid'"):
        eb.simulate("6208", eb.Scenario(Fr=3000.0, omega=500.0, t_end=1e-4, dt=2e-6, pocket_film=True),
                    progress=False)


def test_stable_step_of_the_pocket_film():
    from exudyn_bearing.data.catalog import default_lubricant

    b = eb.catalog["6208"]
    lub = default_lubricant(b)
    dry = eb.Scenario(Fr=3000.0, omega=500.0, cage="rigid")
    wet = eb.Scenario(Fr=3000.0, omega=500.0, cage="rigid", pocket_film=True)
    assert pocket_film_step(b, dry, lub) == math.inf
    step = pocket_film_step(b, wet, lub)
    assert 0.0 < step < math.inf
    # it enters the rigid cage's limit only where it is the smallest
    dt, _, basis = rigid_cage_step(b, wet, lub, 1500.0, None)
    assert dt <= step and (dt < step or basis.startswith("pocket film"))


@pytest.fixture(scope="module")
def film_runs():
    """The 6208 radial case (3000 N, 500 rad/s) with its estimated rigid cage, 60 ms at 2 us, dry and with the
    pocket film."""
    out = {}
    for film in (False, True):
        sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.06, dt=2e-6, cage="rigid", pocket_film=film,
                         sample_dt=1e-4)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", eb.SteadyStateWarning)
            run = eb.simulate("6208", sc, progress=False)
            out[film] = run.summary(fraction=0.5)
            out[film, "run"] = run
    return out


def test_pocket_film_run_closes_its_energy_balance_and_says_what_it_leaves_out(film_runs):
    wet, dry = film_runs[True], film_runs[False]
    assert abs(wet["energy_residual"]) < 2e-3
    assert any("a starved pocket" in x for x in wet["not_modelled"])
    assert any("Scenario(pocket_film=True)" in x for x in dry["not_modelled"])
    assert wet["pocket_film"] is True and dry["pocket_film"] is False  # the summary says which it ran
    # the cage speed is the races' business: the film moves it little (0.14 % over 0.2 s,
    # validation/studies/pocket_film.py); the Q_max read at psi = 0 moves with the phase of the cage's irregular
    # whirl (1.1 % over 0.2 s there), so it is held to the whirl's scale, not to the film's
    assert wet["cage_speed"] == pytest.approx(dry["cage_speed"], rel=0.005)
    assert wet["q_max_inner"] == pytest.approx(dry["q_max_inner"], rel=0.03)


def test_pocket_film_shear_dissipates_at_least_what_centred_balls_would(film_runs):
    # a ball centred in its pocket shears both films at the gap c_p: per ball 2 C(c_p) |w_rel|^2, w_rel the
    # ball's angular velocity relative to the cage (about the axis; along the pocket's normal it is small). An
    # offset ball shears more (ln(R/h1) + ln(R/h2) >= 2 ln(R/c_p) for h1 + h2 = 2 c_p): the run's pocket loss,
    # the shear plus the friction where a ball touches, is at least the centred value
    run = film_runs[True, "run"]
    b = eb.get_bearing("6208")
    c_p = run.scenario.rigid_cage_of(b).pocket_clearance
    _, _, c = pf.shear_resistance(run.lubricant.viscosity, b.ball_radius, c_p)
    w = run.window(0.5)
    w_rel = run.data["wb"][w].copy()
    w_rel[..., 2] -= run.cage_speed_series()[w][:, None]
    centred = float(np.mean(np.sum(2.0 * c * np.sum(w_rel * w_rel, axis=-1), axis=1)))
    pocket = film_runs[True]["power_loss"]["cage_pocket"]
    assert centred > 3.0 * film_runs[False]["power_loss"]["cage_pocket"]  # the shear dominates the pockets' loss
    assert 0.97 * centred <= pocket <= 1.5 * centred


@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")  # a 2 ms run: its window is short
@pytest.mark.filterwarnings("ignore::exudyn_bearing.EnergyBalanceWarning")  # a 2 ms run
def test_the_element_and_the_command_line_take_the_pocket_film(capsys, tmp_path):
    from exudyn_bearing.cli import main
    from exudyn_bearing.solvers.element.element import element_scenario

    assert element_scenario("6208", cage="rigid", pocketFilm=True).pocket_film
    with pytest.raises(InputError, match="^pocketFilm: "):
        element_scenario("6208", cage="none", pocketFilm=True)
    rc = main(["simulate", "6208", "--Fr", "3000", "--omega", "500", "--cage", "rigid", "--pocket-film",
               "--t-end", "0.002", "--dt", "2e-6", "--json", "--out", str(tmp_path)])
    assert rc == 0
    out = capsys.readouterr().out
    assert "a starved pocket" in out


def test_the_exudyn_element_has_the_same_pocket_film():
    # one physics implementation: the element's fast mode (the reference scheme) runs the pocket film as the
    # reference engine does (the scene of tests/test_element_rigid_cage.py, with the film)
    import dataclasses

    from exudyn_bearing.data.cages import estimated_cage
    from exudyn_bearing.solvers.element.engine import ExudynEngine

    b = eb.catalog["6208"]
    cage = dataclasses.replace(estimated_cage(b), pocket_clearance=60e-6, land_clearance=30e-6)
    sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.006, dt=4e-6, sample_dt=1e-4, cage="rigid", rigid_cage=cage,
                     cage_damping="implicit", pocket_film=True)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        ref = eb.simulate(b, sc, progress=False)
        ex = eb.Results(ExudynEngine(b, sc, mode="fast").run())
        a, c = ref.summary(), ex.summary()
    assert a["pocket_force_max"] > 0.0
    for key in ("cage_speed", "q_max_inner", "pocket_force_max", "cage_power_pocket"):
        assert c[key] == pytest.approx(a[key], rel=1e-6), key


def test_the_kernel_takes_the_far_gap_across_the_pocket():
    # the walls are 2 c_p apart across the ball: a ball offset x from the pocket's centre has gaps c_p - x and
    # c_p + x, so a centred ball turning in its pocket gets no net film force, and the force of an offset ball
    # shrinks to zero as it returns to the centre (the kernel's far gap was h + 2 c_p: w(c_p) - w(3 c_p) there)
    from exudyn_bearing.model import layout as L
    from exudyn_bearing.model.contact import _pocket_film_force, _pocket_film_gaps
    from exudyn_bearing.solvers.reference.engine import ReferenceEngine

    eng = ReferenceEngine("6208", eb.Scenario(Fr=3000.0, omega=500.0, cage="rigid", pocket_film=True))
    p = eng.params
    cp = p[L.P_POCKET_GAP]
    for x in (0.0, 0.3 * cp, 0.9 * cp):
        near, far = _pocket_film_gaps(p, cp - x, 1e-9)
        assert near == pytest.approx(cp - x, rel=1e-12) and far == pytest.approx(cp + x, rel=1e-12)

    def force(x):  # a ball sliding 2 m/s on its walls, its centre still in the cage, offset x toward n = e_x
        near, far = _pocket_film_gaps(p, cp - x, 1e-9)
        return _pocket_film_force(p, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 2.0, 0.0, near, far, 0.0, 1e-3, 0.0)

    assert force(0.3 * cp) > 0.0  # off the near wall
    assert abs(force(0.0)) < 1e-12 * force(0.3 * cp)  # zero to round-off
    assert abs(force(1e-4 * cp)) < 1e-3 * force(0.3 * cp)  # continuous through the centre
