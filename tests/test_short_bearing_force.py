"""The nonlinear short-bearing (Ocvirk) film force of a cage land: closed forms, an independent quadrature of
the pressure, and its linearisation against the load-line coefficients of El Had et al. / Friswell et al."""
import math

import numpy as np
import pytest

from exudyn_bearing.data import InputError
from exudyn_bearing.physics.short_bearing import (short_bearing_attitude_angle, short_bearing_damping,
                                                  short_bearing_force, short_bearing_force_xy,
                                                  short_bearing_shear_torque, short_bearing_stiffness)

MU, R, L, C = 0.02, 0.035, 0.008, 80e-6   # a land of a cage: viscosity, radius, width, radial clearance
SCALE = MU * R * L ** 3 / C ** 2


def quadrature(eps, eps_rate, whirl, omega_sum, n=200001):
    """The force by brute force: the pressure of the short-bearing Reynolds equation on a fine grid, clipped
    at zero (cavitation), integrated with the trapezoidal rule (independent of the closed forms)."""
    th = np.linspace(0.0, 2.0 * math.pi, n)
    b = eps * (0.5 * omega_sum - whirl) * np.sin(th) - eps_rate * np.cos(th)
    p = np.maximum(-(MU * L ** 3 / C ** 2) * b / (1.0 - eps * np.cos(th)) ** 3, 0.0)
    return -R * np.trapezoid(p * np.cos(th), th), -R * np.trapezoid(p * np.sin(th), th)


@pytest.mark.parametrize("eps", [0.1, 0.5, 0.9, 0.99])
def test_steady_force_is_ocvirks(eps):
    w = 300.0
    fr, ft = short_bearing_force(eps, 0.0, 0.0, w, MU, R, L, C)
    assert fr == pytest.approx(-SCALE * w * eps ** 2 / (1 - eps ** 2) ** 2, rel=1e-10)
    assert ft == pytest.approx(SCALE * w * math.pi * eps / (4 * (1 - eps ** 2) ** 1.5), rel=1e-10)
    # the attitude angle between load and line of centres: tan phi = pi sqrt(1 - eps^2) / (4 eps)
    assert math.atan2(ft, -fr) == pytest.approx(float(short_bearing_attitude_angle(eps)), rel=1e-10)


@pytest.mark.parametrize("eps", [0.2, 0.7, 0.95])
def test_pure_squeeze_force(eps):
    # omega_sum = 2 phi': no wedge. Approaching (eps' > 0) and receding (eps' < 0) journals carry pressure on
    # the two complementary halves of the film, so the difference of their forces is the full (Sommerfeld)
    # film's squeeze force, -pi mu R L^3 eps' (1 + 2 eps^2) / (c^2 (1 - eps^2)^(5/2)) along the line of
    # centres and none across it [5]; the approaching one is pushed back, harder than the receding one is
    # pulled (the pressure builds where the film is thin)
    rate = 3.0
    fr, ft = short_bearing_force(eps, rate, 50.0, 100.0, MU, R, L, C)
    gr, gt = short_bearing_force(eps, -rate, 50.0, 100.0, MU, R, L, C)
    assert fr - gr == pytest.approx(-math.pi * SCALE * rate * (1 + 2 * eps ** 2) / (1 - eps ** 2) ** 2.5, rel=1e-10)
    assert ft - gt == pytest.approx(0.0, abs=1e-12 * abs(fr))
    assert fr < -abs(gr) < 0.0


@pytest.mark.parametrize("eps, rate, whirl, w", [(0.3, 40.0, -100.0, 400.0), (0.8, -5.0, 150.0, 300.0),
                                                 (0.6, 200.0, 0.0, 10.0), (0.95, -0.3, 900.0, 250.0),
                                                 (0.0, 10.0, 0.0, 100.0), (0.5, -30.0, 0.0, 200.0),
                                                 (0.7, 30.0, 300.0, 200.0), (0.9, 0.0, 250.0, 100.0),
                                                 (0.4, 0.0, 50.0, 100.0)])
def test_general_motion_against_quadrature(eps, rate, whirl, w):
    # any squeeze and whirl: the half film where the pressure is positive moves round; the closed form's
    # limits must follow it (whirl above half the surface speed turns the wedge force round)
    # (the cases cover the four sign quadrants of the wedge a = eps (omega_sum/2 - phi') and squeeze b = -eps',
    # which place the film's start theta0 in each quadrant, and a = b = 0: no pressure)
    fr, ft = short_bearing_force(eps, rate, whirl, w, MU, R, L, C)
    qr, qt = quadrature(eps, rate, whirl, w)
    if rate == 0.0 and whirl == 0.5 * w:
        assert (fr, ft) == (0.0, 0.0) and max(abs(qr), abs(qt)) == 0.0
        return
    scale = max(abs(qr), abs(qt))
    assert fr == pytest.approx(qr, abs=2e-6 * scale)
    assert ft == pytest.approx(qt, abs=2e-6 * scale)


@pytest.mark.parametrize("eps0", [0.3, 0.6, 0.85])
def test_linearisation_is_the_load_line_coefficients(eps0):
    # the journal in equilibrium under a load W; the derivative of the force along the load line by a small
    # displacement and velocity gives k c / W and C c omega / W of short_bearing_stiffness / _damping
    w = 500.0
    fx0, fy0 = short_bearing_force_xy(eps0 * C, 0.0, 0.0, 0.0, w, MU, R, L, C)
    load = math.hypot(fx0, fy0)
    u = np.array([-fx0, -fy0]) / load  # the external load's direction (opposite to the film force)
    h = 1e-7 * C
    fp = np.array(short_bearing_force_xy(eps0 * C + h * u[0], h * u[1], 0.0, 0.0, w, MU, R, L, C))
    fm = np.array(short_bearing_force_xy(eps0 * C - h * u[0], -h * u[1], 0.0, 0.0, w, MU, R, L, C))
    k = -(fp - fm) @ u / (2 * h)
    v = 1e-7 * C * w
    gp = np.array(short_bearing_force_xy(eps0 * C, 0.0, v * u[0], v * u[1], w, MU, R, L, C))
    gm = np.array(short_bearing_force_xy(eps0 * C, 0.0, -v * u[0], -v * u[1], w, MU, R, L, C))
    damping = -(gp - gm) @ u / (2 * v)
    assert k * C / load == pytest.approx(float(short_bearing_stiffness(eps0)), rel=1e-5)
    assert damping * C * w / load == pytest.approx(float(short_bearing_damping(eps0)), rel=1e-5)


def test_concentric_film_squeeze_limit_is_continuous():
    # at the centre the force of a moving journal is the concentric squeeze force, the limit of eps -> 0
    v = (0.02, -0.01)
    at_centre = np.array(short_bearing_force_xy(0.0, 0.0, *v, 200.0, MU, R, L, C))
    near = np.array(short_bearing_force_xy(1e-9 * C * v[0], 1e-9 * C * v[1], *v, 200.0, MU, R, L, C))
    assert at_centre == pytest.approx(near, rel=1e-6)
    assert at_centre == pytest.approx(-0.5 * math.pi * MU * R * L ** 3 / C ** 3 * np.array(v), rel=1e-12)


def test_rotation_invariance_and_direction_of_whirl_force():
    # the same state turned by an angle gives the turned force; the tangential force leads by +90 deg in
    # the sense of the surfaces' rotation (forward whirl) and changes sign with it
    a = 0.7
    rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    r, v = np.array([0.5 * C, 0.0]), np.array([0.1, 0.3]) * C * 100
    f = np.array(short_bearing_force_xy(*r, *v, 300.0, MU, R, L, C))
    g = np.array(short_bearing_force_xy(*(rot @ r), *(rot @ v), 300.0, MU, R, L, C))
    assert g == pytest.approx(rot @ f, rel=1e-10)
    assert short_bearing_force_xy(0.5 * C, 0.0, 0.0, 0.0, 300.0, MU, R, L, C)[1] > 0
    assert short_bearing_force_xy(0.5 * C, 0.0, 0.0, 0.0, -300.0, MU, R, L, C)[1] < 0


def test_shear_torque_is_petroff_at_the_centre_and_grows_with_eccentricity():
    t0 = short_bearing_shear_torque(0.0, 100.0, MU, R, L, C)
    assert t0 == pytest.approx(-2 * math.pi * MU * R ** 3 * L * 100.0 / C, rel=1e-12)
    assert short_bearing_shear_torque(0.6, 100.0, MU, R, L, C) == pytest.approx(t0 / 0.8, rel=1e-12)


@pytest.mark.parametrize("kw, name", [({"eccentricity": 1.0}, "eccentricity"), ({"eccentricity": -0.1}, "eccentricity"),
                                      ({"clearance": 0.0}, "clearance"), ({"viscosity": -1.0}, "viscosity"),
                                      ({"whirl_rate": math.nan}, "whirl_rate")])
def test_bad_input_names_the_parameter(kw, name):
    args = dict(eccentricity=0.5, eccentricity_rate=0.0, whirl_rate=0.0, omega_sum=100.0, viscosity=MU,
                radius=R, length=L, clearance=C)
    args.update(kw)
    with pytest.raises(InputError, match=name):
        short_bearing_force(**args)
