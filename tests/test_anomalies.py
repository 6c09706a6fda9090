"""The two explained anomalies (validation/consistency/anomaly_checks.py): the quasi-static solver's least rolling
speed of the traction law (the dynamic engines' floor), and race-control orbital speeds above
(1 - gamma cos alpha) / 2 when centrifugal force turns the contact angles apart."""
import math

import pytest

import exudyn_bearing as eb
from exudyn_bearing.solvers.quasistatic import kinematics as km

HELD = {"tilt_x": 0.0, "tilt_y": 0.0}


# the default 16 x 4 traction grid, expected not converged to 1 % here
@pytest.mark.filterwarnings("ignore::exudyn_bearing.solvers.quasistatic.solve.TractionResolutionWarning")
def test_rolling_speed_floor_scales_a_linear_traction_law():
    # the 6208's lambda law, regularised below slide-to-roll ratio s_r = DEFAULT_REGULARIZING_SRR, is linear,
    # mu = mu_b s / s_r with s = slip / u: where every slip is below s_r u_floor, the traction is
    # mu_b Q slip / (s_r u_floor), the force balance of the traction equilibrium is homogeneous in the slips
    # (same kinematics for any floor) and the dissipation, the integral of traction times slip, scales as
    # 1 / u_floor: doubling the floor halves it. At 1 rad/s the rolling speed is 0.015 m/s, below both floors.
    srr = eb.data.traction.DEFAULT_REGULARIZING_SRR
    sols = [eb.solve_quasistatic("6208", Fr=3000.0, omega=1.0, control="equilibrium", fixed=HELD, stiffness=False,
                                 rolling_speed_floor=f) for f in (0.2, 0.4)]
    for s, f in zip(sols, (0.2, 0.4)):
        assert max(s.balls["u_roll_inner"].max(), s.balls["u_roll_outer"].max()) < f
        for j in range(len(s.balls["psi"])):
            for tag in ("inner", "outer"):   # the precondition: every slip in the linear range
                assert abs(s.balls[f"slip_{tag}"][j]).max() < srr * f
    # 1e-6: the equilibrium's speeds converge to 1e-7 relative (solve.py), the dissipation to the same order
    assert sols[1].dissipation_total / sols[0].dissipation_total == pytest.approx(0.5, rel=1e-6)
    assert sols[1].balls["orbital_speed"][0] == pytest.approx(sols[0].balls["orbital_speed"][0], rel=1e-6)


def test_rolling_speed_floor_checked():
    with pytest.raises(eb.InputError, match="rolling_speed_floor"):
        eb.solve_quasistatic("6208", Fr=3000.0, omega=1.0, rolling_speed_floor=-0.1)


# the default 16 x 4 traction grid, expected not converged to 1 % here
@pytest.mark.filterwarnings("ignore::exudyn_bearing.solvers.quasistatic.solve.TractionResolutionWarning")
def test_quasistatic_default_floor_is_the_engines_floor():
    # one default in every solver: without rolling_speed_floor the quasi-static solver takes the engines'
    # ellipse-level floor, min(regularizing speed, half the kinematic inner rolling speed). Hand value for the
    # 6208 (alpha = 0) at 1 rad/s, outer ring at rest: omega_c = omega (1 - R_b / r_p) / 2, the inner race moves
    # at (omega - omega_c)(r_p - R_b) relative to the cage (Harris & Kotzalas), half of it ~ 0.0073 m/s
    b = eb.load_bearing("6208")
    omega = 1.0
    w_c = 0.5 * omega * (1.0 - b.ball_radius / b.pitch_radius)
    hand = 0.5 * (omega - w_c) * (b.pitch_radius - b.ball_radius)
    floor = eb.model.scenario.rolling_speed_floor(b, omega)
    assert floor == pytest.approx(hand, rel=1e-12)
    assert eb.model.scenario.ellipse_rolling_floor(b, eb.Scenario(Fr=3000.0, omega=omega)) == floor
    # at 500 rad/s half the rolling speed (3.6 m/s) is above 0.1 m/s: the regularizing speed is the floor
    assert eb.model.scenario.rolling_speed_floor(b, 500.0) == eb.Scenario(Fr=3000.0, omega=500.0).regularizing_speed
    # the solver's default is that floor: the same solution as passing it, not as passing a larger one
    kw = dict(Fr=3000.0, omega=omega, control="equilibrium", fixed=HELD, stiffness=False)
    s_default = eb.solve_quasistatic("6208", **kw)
    s_floor = eb.solve_quasistatic("6208", rolling_speed_floor=floor, **kw)
    s_large = eb.solve_quasistatic("6208", rolling_speed_floor=0.1, **kw)
    assert s_default.dissipation_total == s_floor.dissipation_total
    assert abs(s_large.dissipation_total / s_default.dissipation_total - 1.0) > 0.5


def test_outer_race_control_orbital_speed_closed_form():
    # pure rolling at both contact centres of an inner-ring-rotating ball (Harris & Kotzalas, Rolling Bearing
    # Analysis, 5th ed.): omega_m / omega = 1 / (1 + K), K = cos(beta - a_i) (1 + g cos a_o) /
    # (cos(beta - a_o) (1 - g cos a_i)), g = R_b / r_c; outer control: tan beta = sin a_o / (cos a_o + g).
    # With a_i = a_o this is (1 - g cos a) / 2 < 1/2; the 7208 under light thrust at 1700 rad/s has a_i - a_o
    # of about 40 deg from centrifugal force and an orbital speed above omega / 2.
    w = 1700.0
    s = eb.solve_quasistatic("7208", Fa=1000.0, omega=w, control="outer", stiffness=False)
    b = s.balls
    ai, ao = float(b["alpha_inner"][0]), float(b["alpha_outer"][0])
    g = s.contact_geometry[0][km.G_RB] / float(b["ball_center_r"][0])
    beta = math.atan2(math.sin(ao), math.cos(ao) + g)
    k = math.cos(beta - ai) * (1 + g * math.cos(ao)) / (math.cos(beta - ao) * (1 - g * math.cos(ai)))
    # 1e-9: the same three linear equations solved two ways (round-off only)
    assert b["beta"][0] == pytest.approx(beta, rel=1e-9)
    assert b["orbital_speed"][0] / w == pytest.approx(1.0 / (1.0 + k), rel=1e-9)
    assert ai - ao > math.radians(30.0)
    assert b["orbital_speed"][0] / w > 0.5 > (1 - g * math.cos(ai)) / 2


def test_ellipse_rolling_floor_stays_below_the_rolling_speed():
    # the engines' least rolling speed at the ellipse level: the scenario's regularizing_speed, but at most half
    # the kinematic inner rolling speed u_i = (omega - omega_c) (r_p - R_b cos a) with omega_c = omega (1 - g)/2,
    # g = R_b cos a / r_p (radial 6208: a = 0), so a steady run keeps its slide-to-roll ratios
    from exudyn_bearing.data import load_bearing
    from exudyn_bearing.model.scenario import ellipse_rolling_floor

    b = load_bearing("6208")
    g = b.ball_radius / b.pitch_radius
    for omega, expected in ((1.0, None), (500.0, 0.1)):
        u_i = (omega - omega * (1 - g) / 2) * (b.pitch_radius - b.ball_radius)
        floor = ellipse_rolling_floor(b, eb.Scenario(Fr=3000.0, omega=omega, traction_level="ellipse"))
        assert floor == pytest.approx(expected if expected is not None else 0.5 * u_i, rel=1e-12)
        assert floor <= 0.5 * u_i
    # at rest the floor is the regularising speed (start-up from rest)
    assert ellipse_rolling_floor(b, eb.Scenario(Fr=3000.0, omega=0.0)) == 0.1
