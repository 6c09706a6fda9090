"""Power-loss components (exudyn_bearing.physics.losses) against their sources' equations, closed
forms and published values; the quasi-static solver's loss report (solvers.quasistatic.losses)."""
import math

import numpy as np
import pytest

from exudyn_bearing.data import InputError
from exudyn_bearing.physics import losses as ls

# A 6208 inner contact near Q_max at 500 rad/s with the DEM papers' oil (numbers typed from the
# catalogue geometry; the hand calculations below use only these and the sources' equations).
E_PRIME = 2.26e11      # Pa
ETA, XI = 0.04, 2.3e-8
Q, RX, KAPPA, U_R = 1460.0, 5.0e-3, 9.4, 7.25


def test_ehl_rolling_force_hand_calculation():
    # Harris & Kotzalas, Advanced Concepts, ch. 5: F_R = 2.86 E' R_x^2 k^0.348 G^0.022 U^0.66 W^0.47
    u = ETA * U_R / (E_PRIME * RX)
    g = XI * E_PRIME
    w = Q / (E_PRIME * RX ** 2)
    hand = 2.86 * E_PRIME * RX ** 2 * KAPPA ** 0.348 * g ** 0.022 * u ** 0.66 * w ** 0.47
    assert ls.ehl_rolling_force(U_R, Q, RX, KAPPA, E_PRIME, ETA, XI) == pytest.approx(hand, rel=1e-12)
    # about 0.41 N here (written out by hand: 1.616e7 * 2.18 * 1.207 * 4.70e-7 * 0.0206), to 3 %
    assert hand == pytest.approx(0.41, rel=0.03)


def test_ehl_rolling_force_scales_like_palmgren_viscous_moment():
    # the rolling force grows as (eta u)^0.66: Palmgren's viscous moment grows as (nu n)^(2/3)
    f1 = ls.ehl_rolling_force(U_R, Q, RX, KAPPA, E_PRIME, ETA, XI)
    f2 = ls.ehl_rolling_force(8 * U_R, Q, RX, KAPPA, E_PRIME, ETA, XI)
    assert math.log(f2 / f1) / math.log(8) == pytest.approx(2.0 / 3.0, abs=0.01)  # 0.66 against 2/3
    assert ls.ehl_rolling_force(0.0, Q, RX, KAPPA, E_PRIME, ETA, XI) == 0.0
    assert ls.ehl_rolling_force(U_R, 0.0, RX, KAPPA, E_PRIME, ETA, XI) == 0.0


def test_hysteresis_force_is_alpha_times_the_hertz_front_half_moment():
    # Johnson 1985 sec. 9.2: the resistance is alpha times the moment of the pressure on the leading
    # half of the contact about its centre, over R. Integrate the Hertz ellipse numerically.
    a, b = 1.74e-3, 0.185e-3           # across / along rolling [m]
    p0 = 3 * Q / (2 * math.pi * a * b)
    n = 801
    x = np.linspace(0.0, b, n)          # leading half, along rolling
    y = np.linspace(-a, a, 2 * n)
    xx, yy = np.meshgrid(x, y)
    p = p0 * np.sqrt(np.clip(1 - (xx / b) ** 2 - (yy / a) ** 2, 0.0, None))
    moment = np.trapezoid(np.trapezoid(p * xx, y, axis=0), x)
    alpha = 0.007
    # closed form of the integral: 3 Q b / 16; the grid loses the sqrt edge, 0.3 % at n = 801
    assert moment == pytest.approx(3 * Q * b / 16, rel=3e-3)
    assert ls.hysteresis_rolling_force(Q, b, RX, alpha) == pytest.approx(alpha * moment / RX, rel=3e-3)


def test_hysteresis_force_sphere_hand_calculation():
    # Johnson eq. (9.19) for a sphere on a flat, circular Hertz contact a = (3 W R / (4 E*))^(1/3)
    r, w, e_star = 0.01, 100.0, 1.15e11
    a = (3 * w * r / (4 * e_star)) ** (1 / 3)
    assert ls.hysteresis_rolling_force(w, a, r, 0.01) == pytest.approx(3 / 16 * 0.01 * w * a / r, rel=1e-12)


def test_rolling_resistance_power():
    assert ls.rolling_resistance_power(0.5, -4.0) == 2.0
    assert ls.rolling_resistance_power(0.5, 4.0, surfaces=2) == 4.0


def test_sphere_drag_coefficient_standard_curve():
    # Clift, Grace & Weber 1978, Table 5.2 / the standard drag curve: C_D(Re = 100) = 1.09 (the
    # Schiller-Naumann fit is within 5 % of the measured curve up to Re = 800)
    assert ls.sphere_drag_coefficient(100.0) == pytest.approx(1.09, rel=0.01)
    assert ls.sphere_drag_coefficient(1e4) == 0.44
    # continuous at the switch Re = 1000 within 1 %
    assert ls.sphere_drag_coefficient(1000.0) == pytest.approx(0.44, rel=0.01)


def test_ball_drag_force_limits():
    d, rho, eta = 12.7e-3, 860.0, 0.04
    v = 1e-10                                  # Stokes: 3 pi eta D v (Re = 3e-8: the Re^0.687 term 1e-6)
    assert ls.ball_drag_force(v, d, rho, eta) == pytest.approx(3 * math.pi * eta * d * v, rel=1e-5)
    # Newton regime: Harris & Kotzalas' F_D = pi C_D rho D^2 (d_m omega_m)^2 / 32 with v = d_m omega_m / 2
    d_m, w_m = 0.0606, 200.0
    v = d_m * w_m / 2
    re = 1.2 * v * d / 1.8e-5
    assert re > 1000
    assert ls.ball_drag_force(v, d, 1.2, 1.8e-5) == pytest.approx(math.pi * 0.44 * 1.2 * d ** 2 * (d_m * w_m) ** 2
                                                                   / 32, rel=1e-12)


def test_mixture_properties():
    assert ls.mixture_density(0.0, 860.0) == ls.AIR_DENSITY
    assert ls.mixture_density(0.05, 860.0, 1.2) == pytest.approx(0.05 * 860 + 0.95 * 1.2)
    assert ls.mixture_viscosity(1.0, 0.04) == 0.04


# ---- SKF and Palmgren: hand calculations in catalogue units (N mm, r/min, mm^2/s, mm) --------------
D6208, d6208 = 0.080, 0.040
NU = 46.5e-6                      # m^2/s
W = 500.0                         # rad/s


def test_skf_6208_radial_hand_calculation():
    n = W * 30 / math.pi
    dm, nu = 60.0, 46.5
    g_rr = 3.9e-7 * dm ** 1.96 * 3000 ** 0.54                     # SKF 2018, G_rr of a deep groove, F_a = 0
    g_sl = 3.23e-3 * dm ** -0.26 * 3000 ** (5 / 3)
    phi_ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu ** 0.64)
    phi_rs = math.exp(-3e-8 * nu * n * (40 + 80) * math.sqrt(3.1 / (2 * (80 - 40))))
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    mu_sl = phi_bl * 0.12 + (1 - phi_bl) * 0.05
    m_rr = phi_ish * phi_rs * g_rr * (nu * n) ** 0.6
    m = ls.skf_frictional_moment("62", d6208, D6208, 3000.0, 0.0, W, NU)
    assert m["rolling"] == pytest.approx(m_rr * 1e-3, rel=1e-12)
    assert m["sliding"] == pytest.approx(g_sl * mu_sl * 1e-3, rel=1e-12)
    assert m["drag"] == 0.0                                      # no oil bath
    assert m["total"] == pytest.approx((m_rr + g_sl * mu_sl) * 1e-3, rel=1e-12)


def test_skf_angular_contact_and_axial_deep_groove_hand_calculation():
    n = W * 30 / math.pi
    dm = 60.0
    fg_r, fg_s = 1.90e-12 * dm ** 4 * n ** 2, 1.91e-12 * dm ** 4 * n ** 2
    g_rr = 5.03e-7 * dm ** 1.97 * (1000 + fg_r + 1.97 * 2000) ** 0.54
    g_sl = 1.30e-2 * dm ** 0.26 * ((1000 + fg_s) ** (4 / 3) + 0.68 * 2000 ** (4 / 3))
    assert ls.skf_rolling_variable("72B", 0.06, 1000.0, 2000.0, W) == pytest.approx(g_rr, rel=1e-12)
    assert ls.skf_sliding_variable("72B", 0.06, 1000.0, 2000.0, W) == pytest.approx(g_sl, rel=1e-12)
    alpha_f = math.radians(24.6 * (2000 / 19000) ** 0.24)
    g_rr = 3.9e-7 * dm ** 1.96 * (1000 + 1.7 / math.sin(alpha_f) * 2000) ** 0.54
    assert ls.skf_rolling_variable("62", 0.06, 1000.0, 2000.0, W, C0=19000.0) == pytest.approx(g_rr, rel=1e-12)
    with pytest.raises(InputError, match="C0"):
        ls.skf_rolling_variable("62", 0.06, 1000.0, 2000.0, W)
    with pytest.raises(InputError, match="series"):
        ls.skf_rolling_variable("99", 0.06, 1000.0)
    with pytest.raises(InputError, match="nu"):
        ls.skf_frictional_moment("62", d6208, D6208, 3000.0, 0.0, W, -1.0)


def test_skf_drag_moment_hand_calculation():
    # oil level at the centre of the lowest ball (H = D_w/2 = 6.3 mm), V_M = 0: the viscous term only
    n = W * 30 / math.pi
    dm, h, kz = 60.0, 6.3, 3.1
    t = 2 * math.acos((0.6 * dm - h) / (0.6 * dm))
    f_t = math.sin(t / 2)
    r_s = 0.36 * dm ** 2 * (t - math.sin(t)) * 0.05 * kz * (80 + 40) / (80 - 40)
    hand = 1.093e-7 * n ** 2 * dm ** 3 * (n * dm ** 2 * f_t / 46.5) ** -1.379 * r_s
    assert ls.skf_drag_moment(W, NU, d6208, D6208, kz, 6.3e-3) == pytest.approx(hand * 1e-3, rel=1e-12)


def test_palmgren_hand_calculation():
    n = W * 30 / math.pi
    m0 = 1e-7 * 2.0 * (46.5 * n) ** (2 / 3) * 60.0 ** 3            # N mm, nu n >= 2000
    assert ls.palmgren_viscous_moment(W, NU, 0.06, 2.0) == pytest.approx(m0 * 1e-3, rel=1e-12)
    # below nu n = 2000: 160e-7 f0 d_m^3
    assert ls.palmgren_viscous_moment(0.5, 10e-6, 0.06, 2.0) == pytest.approx(160e-7 * 2 * 60.0 ** 3 * 1e-3)
    f1 = ls.palmgren_load_factor(3000.0, 19000.0, 0.0005, 0.55)
    assert f1 == pytest.approx(0.0005 * (3000 / 19000) ** 0.55)
    assert ls.palmgren_load_moment(f1, 3000.0, 0.06) == pytest.approx(f1 * 3000 * 0.06)


# ---- the quasi-static solver's loss report ----------------------------------------------------------
@pytest.fixture(scope="module")
def sol6208():
    import exudyn_bearing as eb
    return eb.solve_quasistatic("6208", Fr=3000.0, omega=500.0, stiffness=False)


def test_quasistatic_power_loss_components_and_torque(sol6208):
    from exudyn_bearing.solvers.quasistatic.losses import power_losses
    import exudyn_bearing as eb

    s = sol6208
    out = power_losses(s)
    p = out["power_loss"]
    assert p["traction"] == s.dissipation_total
    assert p["seals"] == "not modelled" and any(x.startswith("seal") for x in out["not_modelled"])
    assert out["power_loss_total"] == pytest.approx(sum(p[k] for k in ("traction", "ehl_rolling", "hysteresis",
                                                                       "drag", "churning", "cage_pocket",
                                                                       "cage_land")), rel=1e-14)
    # defaults: no bath, a ball-guided cage (no land)
    assert p["churning"] == 0.0 and p["cage_land"] == 0.0 and out["cage_guidance"] == "ball"
    assert out["friction_torque_total"] == pytest.approx(out["power_loss_total"] / 500.0, rel=1e-14)
    # ball 0 (psi = 0) by hand: Harris & Kotzalas' R_x of the inner race, R_x = (D/2)(1 - gamma),
    # gamma = D cos(alpha) / d_m at the ball centre's orbit; F_R from the source's equation, 2 F_R u_r
    b = eb.catalog["6208"]
    bl = s.balls
    dw, dm = b.ball_diameter, 2 * bl["ball_center_r"][0]
    rx = dw / 2 * (1 - dw / dm)
    e_prime = b.material.youngs_modulus / (1 - b.material.poisson_ratio ** 2)   # E' of two equal steels
    q, a_, b_, u = bl["q_inner"][0], bl["a_inner"][0], bl["b_inner"][0], bl["u_roll_inner"][0]
    lub = eb.data.lubricants[s.lubricant]
    uu, g, w = lub.viscosity * u / (e_prime * rx), lub.pressure_viscosity * e_prime, q / (e_prime * rx ** 2)
    f_r = 2.86 * e_prime * rx ** 2 * (a_ / b_) ** 0.348 * g ** 0.022 * uu ** 0.66 * w ** 0.47
    f_h = 3 / 16 * 0.007 * q * b_ / rx
    # the solver's R_x uses the contact point's radius (ball centre - r_b cos alpha): the same to 1e-9
    assert out["power_loss_inner_ball"][0] == pytest.approx(2 * f_r * u + f_h * u, rel=1e-6)
    # drag in air of ball 0 at the orbit speed, Newton regime: pi C_D rho D^2 (d_m omega_m)^2 / 32 times v
    v = bl["ball_center_r"][0] * bl["orbital_speed"][0]
    f_d = math.pi * 0.44 * ls.AIR_DENSITY * dw ** 2 * (2 * v) ** 2 / 32
    assert out["drag_ball"][0] == pytest.approx(f_d * v, rel=1e-12)


def test_quasistatic_losses_in_to_dict(sol6208):
    d = sol6208.to_dict()
    for k in ("power_loss", "power_loss_total", "friction_torque_total"):
        assert k in d and k in d["units"]
    assert set(d["power_loss"]) >= {"traction", "ehl_rolling", "hysteresis", "drag", "churning", "cage_pocket",
                                    "cage_land", "cage", "seals"}
    assert "not_modelled" in d and "not_modelled" in d["units"]


def test_quasistatic_losses_outer_ring_driven_and_at_rest():
    import exudyn_bearing as eb
    from exudyn_bearing.solvers.quasistatic.losses import power_losses

    s = eb.solve_quasistatic("6208", Fr=3000.0, omega=0.0, omega_outer=300.0, stiffness=False)
    out = power_losses(s)
    assert out["power_loss"]["ehl_rolling"] > 0.0
    assert out["friction_torque_total"] == pytest.approx(out["power_loss_total"] / 300.0, rel=1e-14)
    s0 = eb.solve_quasistatic("6208", Fr=3000.0, omega=0.0, stiffness=False)
    out0 = power_losses(s0)
    assert out0["power_loss_total"] == 0.0 and out0["friction_torque_total"] == 0.0  # no relative speed: no loss


def test_quasistatic_losses_bad_input(sol6208):
    from dataclasses import replace

    from exudyn_bearing.solvers.quasistatic.losses import loss_keys, power_losses

    with pytest.raises(InputError, match="oil_volume_fraction"):
        power_losses(sol6208, oil_volume_fraction=2.0)
    with pytest.raises(InputError, match="lubricant"):
        power_losses(sol6208, lubricant="no_such_oil")
    other = replace(sol6208, bearing_name="not_in_catalogue")
    keys = loss_keys(other)
    assert keys["power_loss"] is None and "not_in_catalogue" in keys["power_loss_notes"]["error"]


# ---- churning, cage pocket and cage land ------------------------------------------
def test_bath_immersion_fraction_limits_and_symmetry():
    r_p, d = 0.0303, 12.6e-3
    assert ls.bath_immersion_fraction(0.0, r_p, d) == 0.0
    assert ls.bath_immersion_fraction(2 * r_p + d, r_p, d) == pytest.approx(1.0, abs=1e-12)
    # level through the bearing axis: a ball at height +y above it and its mirror at -y have
    # complementary immersed shares, so the orbit mean is exactly 1/2
    assert ls.bath_immersion_fraction(r_p + d / 2, r_p, d) == pytest.approx(0.5, abs=1e-6)
    with pytest.raises(InputError, match="oil_level"):
        ls.bath_immersion_fraction(-1e-3, r_p, d)


def test_bath_immersion_fraction_against_a_point_count():
    # an independent count: points of a fine grid over the ball's cross-section, at 360 azimuths,
    # below the level H = D (the lowest ball just covered). Grid of 400 x 400 over the disc: the
    # edge cells give an error of about 1/400 of the share, so 0.5 % is the tolerance.
    r_p, d, h = 0.0303, 12.6e-3, 12.6e-3
    r = d / 2
    g = (np.arange(400) + 0.5) / 400 * d - r
    xx, yy = np.meshgrid(g, g)
    disc = xx ** 2 + yy ** 2 <= r * r
    shares = []
    for th in (np.arange(360) + 0.5) * 2 * math.pi / 360:
        y_c = r + r_p * (1 - math.cos(th))                 # centre height above the race bottom
        shares.append(np.sum(disc & (y_c + yy <= h)) / np.sum(disc))
    assert ls.bath_immersion_fraction(h, r_p, d) == pytest.approx(np.mean(shares), rel=5e-3)


def test_cage_pocket_loads_torque_balance():
    # Harris & Kotzalas ch. 6: the loaded balls drive the cage against its land torque and the drag of
    # the balls it pushes; 3 loaded balls, 2 unloaded with drag 0.2 and 0.3 N, land torque 0.05 N m
    f_d = np.array([0.1, 0.1, 0.1, 0.2, 0.3])
    loaded = np.array([True, True, True, False, False])
    r_p, t_cage = 0.03, 0.05
    q = ls.cage_pocket_loads(f_d, loaded, t_cage, r_p)
    assert q[3] == 0.2 and q[4] == 0.3                     # the cage pushes the unloaded balls
    hand = (0.05 / 0.03 + 0.5) / 3                          # = 0.7222 N per loaded ball
    assert q[:3] == pytest.approx([hand] * 3, rel=1e-12)
    # torque balance of the cage about the axis
    assert np.sum(q[:3]) * r_p - np.sum(q[3:]) * r_p == pytest.approx(t_cage, rel=1e-12)
    # no loaded ball: drag only
    assert np.array_equal(ls.cage_pocket_loads(f_d, np.zeros(5, bool), t_cage, r_p), f_d)


def test_cage_pocket_friction_power_hand_calculation():
    # mu Q (D/2) omega_R: 0.1 * 2 N * 6.3 mm * 1150 rad/s = 1.449 W
    assert ls.cage_pocket_friction_power(2.0, -1150.0, 12.6e-3, 0.1) == pytest.approx(1.449, rel=1e-12)


def test_petroff_torque_hand_calculation():
    # Petroff: shear stress eta r omega / c on the area 2 pi r L at the arm r. Outer land of a 6208-size
    # cage: eta 0.04 Pa s, r 33.45 mm, L 6.3 mm, c 0.134 mm, cage at 198 rad/s.
    eta, r, l_w, c, w = 0.04, 0.03345, 6.3e-3, 1.338e-4, 198.0
    tau = eta * r * w / c
    hand = tau * 2 * math.pi * r * l_w * r
    assert ls.petroff_torque(eta, r, l_w, c, w) == pytest.approx(hand, rel=1e-12)
    assert hand == pytest.approx(0.0877, rel=2e-3)          # typed: 0.04*0.03345^3*6.3e-3*198*2pi/1.338e-4
    assert ls.petroff_torque(eta, r, l_w, c, -w) == pytest.approx(-hand, rel=1e-12)
    with pytest.raises(InputError, match="clearance"):
        ls.petroff_torque(eta, r, l_w, 0.0, w)


def test_quasistatic_churning_full_bath_hand_calculation(sol6208):
    from exudyn_bearing.solvers.quasistatic.losses import power_losses
    import exudyn_bearing as eb

    s, b = sol6208, eb.catalog["6208"]
    dw = b.ball_diameter
    out = power_losses(s, oil_level=2 * b.pitch_radius + dw, oil_density=860.0)   # the whole orbit in oil
    lub = eb.data.lubricants[s.lubricant]
    v = s.balls["ball_center_r"][0] * s.balls["orbital_speed"][0]
    assert 860.0 * v * dw / lub.viscosity > 1000            # Newton's regime in the oil too
    f_oil = math.pi * 0.44 * 860.0 * dw ** 2 * (2 * v) ** 2 / 32
    f_air = math.pi * 0.44 * ls.AIR_DENSITY * dw ** 2 * (2 * v) ** 2 / 32
    assert out["churning_ball"][0] == pytest.approx((f_oil - f_air) * v, rel=1e-9)
    assert out["power_loss"]["drag"] == power_losses(s)["power_loss"]["drag"]   # drag stays that of the mixture


def test_quasistatic_cage_land_and_pocket_hand_calculation(sol6208):
    from exudyn_bearing.solvers.quasistatic.losses import power_losses
    import exudyn_bearing as eb

    s, b = sol6208, eb.catalog["6208"]
    out = power_losses(s, cage_guidance="outer_land", cage_land_radius=0.0335, cage_land_width=6e-3,
                       cage_land_clearance=1.5e-4)
    lub = eb.data.lubricants[s.lubricant]
    w_c = float(np.mean(s.balls["orbital_speed"]))            # the cage speed, outer ring at rest
    t = 2 * math.pi * lub.viscosity * 0.0335 ** 3 * 6e-3 * w_c / 1.5e-4
    assert out["cage_land_torque"] == pytest.approx(t, rel=1e-12)
    assert out["power_loss"]["cage_land"] == pytest.approx(t * w_c, rel=1e-12)
    # the cage's torque balance: the loaded balls' pocket loads carry the land torque and the drag of the
    # unloaded balls the cage pushes
    q_c, loaded = out["cage_pocket_load"], s.balls["q_inner"] > 0
    f_d = out["drag_ball"] / np.abs(s.balls["ball_center_r"] * s.balls["orbital_speed"])
    assert np.sum(q_c[loaded]) - np.sum(q_c[~loaded]) == pytest.approx(t / b.pitch_radius, rel=1e-9)
    assert q_c[~loaded] == pytest.approx(f_d[~loaded], rel=1e-9)
    hand = np.sum(0.1 * q_c * b.ball_radius * np.abs(s.balls["ball_speed"]))
    assert out["power_loss"]["cage_pocket"] == pytest.approx(hand, rel=1e-9)
    assert out["friction_torque_total"] == pytest.approx(out["power_loss_total"] / 500.0, rel=1e-14)
    none = power_losses(s, cage_guidance="none")
    assert none["power_loss"]["cage_pocket"] == 0.0 and none["power_loss"]["cage_land"] == 0.0


def test_quasistatic_new_loss_inputs_refused(sol6208):
    from exudyn_bearing.solvers.quasistatic.losses import power_losses

    with pytest.raises(InputError, match="oil_level"):
        power_losses(sol6208, oil_level=-1.0)
    with pytest.raises(InputError, match="cage_guidance"):
        power_losses(sol6208, cage_guidance="rail")
    with pytest.raises(InputError, match="cage_land_clearance"):
        power_losses(sol6208, cage_guidance="inner_land", cage_land_clearance=0.0)
    with pytest.raises(InputError, match="cage_pocket_friction"):
        power_losses(sol6208, cage_pocket_friction=-0.1)


# ---- dynamic summaries: power_loss by component and the energy check ----------
def test_energy_check_hand_calculation():
    from exudyn_bearing.outputs.window_checks import energy_check

    # drive 30 W; losses 20 + 9 W; the balls gain 0.05 J in 0.1 s (0.5 W): residual (30 - 29 - 0.5)/30 = 1/60
    c = energy_check(30.0, {"a": 20.0, "b": 9.0, "c": None}, 0.05, 0.1)
    assert c["residual"] == pytest.approx(1 / 60, rel=1e-12) and c["passed"] is False
    assert c["components"] == ["a", "b"] and c["missing"] == ["c"] and "a + b" in c["statement"]
    c = energy_check(30.0, {"a": 20.0, "b": 9.4}, 0.05, 0.1, recorded_dissipation=29.0)
    assert c["residual"] == pytest.approx(0.1 / 30, rel=1e-9) and c["passed"] is True
    assert c["split_error"] == pytest.approx(0.4 / 29.0, rel=1e-12)
    assert energy_check(0.04, {"a": 0.01}, 0.0, 0.1, floor=4.5)["passed"] is None     # below the loss floor


def test_dynamic_summary_power_loss_closes_the_energy_balance():
    # the ellipse level from the quasi-static traction equilibrium (the scene of tests/test_energy.py, shorter):
    # the drive power equals the reported components (traction per race + contact damping) plus the
    # kinetic-energy rate within 1 %, and the traction components are the per-contact dissipation
    import warnings

    import exudyn_bearing as eb

    sc = eb.Scenario(Fa=3000.0, Fr=0.0, omega=500.0, t_end=0.004, dt=2e-6, sample_dt=2e-4, cage=False,
                     traction_level="ellipse", n_strips=16, n_across=4, initial="quasistatic", control="equilibrium")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        run = eb.simulate("6208", sc)
        s = run.summary(fraction=0.5)
    p = s["power_loss"]
    assert set(p) == {"contact_traction_inner", "contact_traction_outer", "contact_damping"}
    assert s["power_loss_total"] == pytest.approx(sum(p.values()), rel=1e-12)
    # the per-race split sums to the recorded friction_power (the same contacts)
    assert p["contact_traction_inner"] + p["contact_traction_outer"] == pytest.approx(s["friction_power"], rel=1e-9)
    c = s["energy_check"]
    assert c["passed"] is True and abs(c["residual"]) <= 0.01
    assert "contact_traction_inner + contact_traction_outer + contact_damping" in c["statement"]
    # without a cage there is no pocket friction to leave out (the torus cage's frictionless cage balls name it)
    assert not any(x.startswith("cage pocket friction") for x in s["not_modelled"])
    assert s["units"]["power_loss_total"] == "W"
