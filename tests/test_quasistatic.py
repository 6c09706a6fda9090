"""Quasi-static solver: the zero-speed Harris solution, free tilt and moments against an independent
solver, symmetry, stiffness, race-control kinematics, the ACBB-120 case and bad input."""
import json
import math

import numpy as np
import pytest
from scipy import optimize

import exudyn_bearing as eb
from exudyn_bearing import InputError, catalog
from exudyn_bearing.cli import main
from exudyn_bearing.physics import load_distribution as ld
from exudyn_bearing.solvers.quasistatic import solve_quasistatic
from conftest import baseline, error_lines, manual_text

RPM_25000 = 25000 * math.pi / 30


# -- an independent zero-speed solver (no code shared with the package's ring and ball kernels) ------
def independent_reactions(b, u):
    """Force and moment (about the ring centre) of the balls on an inner ring at pose u, zero speed:
    3-D vectors, small rotation theta x p of the groove-centre points (Jones' linearisation, as the
    package), ball on the line between the groove centres, the series Hertz constant K_n(alpha) of
    physics.load_distribution.race_stiffness, moment p0 x F."""
    rho_i, z_i = b.inner_groove_center
    rho_o, z_o = b.outer_groove_center
    a_touch = b.groove_distance
    theta = np.array([u[3], u[4], 0.0])
    d = np.array(u[:3])
    f_tot, m_tot = np.zeros(3), np.zeros(3)
    for j in range(b.n_balls):
        psi = 2 * math.pi * j / b.n_balls
        er = np.array([math.cos(psi), math.sin(psi), 0.0])
        p0 = np.array([rho_i * er[0], rho_i * er[1], z_i])
        p = p0 + d + np.cross(theta, p0)
        wr, wz = p @ er - rho_o, p[2] - z_o
        dist = math.hypot(wr, wz)
        delta = dist - a_touch
        if delta <= 0:
            continue
        q = ld.race_stiffness(b, math.atan2(wz, wr))[2] * delta ** 1.5
        f = -q * (wr * er + np.array([0, 0, wz])) / dist
        f_tot += f
        m_tot += np.cross(p0, f)
    return np.concatenate([f_tot, m_tot[:2]])


def independent_solve(b, loads, guess, held=()):
    free = [k for k in range(5) if k not in held]

    def res(x):
        u = np.array(guess, float)
        u[free] = x * np.array([1e-5, 1e-5, 1e-5, 1e-3, 1e-3])[free]
        r = independent_reactions(b, u) + loads
        return r[free] / np.array([1e3, 1e3, 1e3, 1e1, 1e1])[free]

    x0 = np.asarray(guess, float)[free] / np.array([1e-5, 1e-5, 1e-5, 1e-3, 1e-3])[free]
    x = optimize.fsolve(res, x0 * 1.05 + 0.01, xtol=1e-13)
    u = np.array(guess, float)
    u[free] = x * np.array([1e-5, 1e-5, 1e-5, 1e-3, 1e-3])[free]
    assert np.abs(res(x)).max() < 1e-8
    return u, independent_reactions(b, u) + loads


# -- zero speed: the existing discrete Harris solution ------------------------------------------------
@pytest.mark.parametrize("name, fr, fa", [("6208", 3000.0, 0.0), ("6208", 1000.0, 0.0), ("7208", 3000.0, 3000.0),
                                          ("7208", 0.0, 2000.0)])
@pytest.mark.parametrize("omega", [0.0, 1.0])
def test_low_speed_reproduces_the_discrete_harris_solution(name, fr, fa, omega):
    # static_equilibrium holds the tilt at zero: so does this comparison (tilt held, reaction reported)
    b = catalog[name]
    st = ld.static_equilibrium(b, fr, fa)
    s = solve_quasistatic(b, fr, fa, omega=omega, fixed={"tilt_x": 0.0, "tilt_y": 0.0}, stiffness=False)
    rtol = 1e-9 if omega == 0 else 1e-6   # at 1 rad/s: centrifugal force m r_p omega_c^2 ~ 1e-4 N
    np.testing.assert_allclose(s.balls["q_inner"], st.q, rtol=rtol, atol=rtol * st.q.max())
    np.testing.assert_allclose(s.balls["q_outer"], st.q, rtol=rtol, atol=rtol * st.q.max())
    loaded = st.q > 0  # an unloaded ball's contact angle is a matter of definition (at speed it rides outside)
    np.testing.assert_allclose(s.balls["alpha_inner"][loaded], st.contact_angle[loaded], atol=1e-9 if omega == 0 else 1e-6)
    np.testing.assert_allclose(s.displacement[:3], st.displacement, rtol=1e-6, atol=1e-12 if omega == 0 else 1e-10)
    np.testing.assert_allclose([s.reactions["tilt_x"], s.reactions["tilt_y"]], st.reaction_moment, atol=1e-6)


def test_6208_radial_q_max_published():
    # docs/theory/reference_cases.md: nine discrete balls at F_r = 3000 N, P_d = 0: about 1462 N; load free of tilt by symmetry
    s = solve_quasistatic("6208", 3000.0, fixed={})  # free: the tilts are held by symmetry
    assert s.q_max_inner == pytest.approx(1462, abs=1.0)
    assert s.held == {"delta_a": "symmetry", "tilt_x": "symmetry", "tilt_y": "symmetry"}
    assert max(abs(v) for v in s.reactions.values()) < 1e-6


# -- free tilt and moments against the independent solver --------------------------------------------
@pytest.mark.parametrize("name, loads", [
    ("6208", [3000.0, 0.0, 1000.0, 0.0, 0.0]),     # combined load, free tilt
    ("6208", [0.0, 0.0, 0.0, 0.0, 20.0]),          # moment only
    ("7208", [0.0, 0.0, 3000.0, 10.0, 0.0]),       # thrust and moment
    ("7208", [2000.0, 300.0, 6000.0, -5.0, 4.0]),  # everything
])
def test_free_tilt_and_moments_against_an_independent_solver(name, loads):
    b = catalog[name]
    s = solve_quasistatic(b, loads[0], loads[2], loads[3], loads[4], Fy=loads[1], fixed={})
    u, r = independent_solve(b, np.array(loads), s.displacement)
    # the two differ only in where the Hertz curvature radii are taken (r_p against the ball centre)
    w = np.array([1.0, 1.0, 1.0, b.pitch_radius, b.pitch_radius])
    np.testing.assert_allclose(u * w, s.displacement * w, atol=1e-4 * np.abs(s.displacement * w).max())
    assert abs(s.displacement[3:]).max() > 1e-4  # the tilt is free and used


def test_combined_load_free_tilt_against_held_tilt_6208():
    # the held tilt needs the reaction moment; releasing it more than doubles the radial displacement
    free = solve_quasistatic("6208", 3000.0, 1000.0, fixed={})
    held = solve_quasistatic("6208", 3000.0, 1000.0, fixed={"tilt_x": 0.0, "tilt_y": 0.0})
    u, r = independent_solve(catalog["6208"], np.array([3000.0, 0, 1000.0, 0, 0]), held.displacement, held=(3, 4))
    assert held.reactions["tilt_y"] == pytest.approx(-r[4], rel=2e-3)
    assert abs(held.reactions["tilt_y"]) > 10.0
    assert free.displacement[0] > 2.0 * held.displacement[0]
    assert abs(free.displacement[4]) > 1e-3


# -- symmetry and stiffness ------------------------------------------------------------------------------
@pytest.mark.parametrize("phase", [0.0, 0.1])
def test_symmetric_thrust_gives_identical_balls(phase):
    s = solve_quasistatic("ACBB-120", 0.0, 22240.0, omega=RPM_25000, phase=phase, traction="ester_curve_illustrative",
                          lubricant="MIL-L-23699_492K", stiffness=False)
    for key in ("q_inner", "q_outer", "alpha_inner", "alpha_outer", "orbital_speed", "beta",
                "dissipation_inner_ball"):
        v = np.asarray(s.balls[key])
        assert np.ptp(v) <= 1e-9 * np.abs(v).max()
    # the axial balance holds
    q, a = s.balls["q_inner"], s.balls["alpha_inner"]
    assert (q * np.sin(a)).sum() == pytest.approx(22240.0, rel=1e-8)


@pytest.mark.parametrize("name, loads", [("6208", (3000.0, 1000.0, 0.0, 0.0)), ("7208", (2000.0, 6000.0, 10.0, 0.0))])
def test_stiffness_is_symmetric_and_equals_finite_differences_of_reactions(name, loads):
    s = solve_quasistatic(name, *loads, fixed={})
    k = s.stiffness
    arm = catalog[name].pitch_radius
    w = np.array([1, 1, 1, 1 / arm, 1 / arm])
    kn = k * np.outer(w, w)
    # symmetric up to the change of the Hertz constant with the contact angle (Q = K(alpha) delta^1.5 is not
    # exactly a potential force): measured 5e-5 of the largest entry
    assert np.abs(kn - kn.T).max() < 2e-4 * np.abs(kn).max()
    assert s.stiffness_check["relative_change_half_step"] < 1e-5
    # reactions of all five DOFs held at u +- h (public API), central differences with another step
    u = s.displacement
    for j in range(5):
        h = (5e-9 if j < 3 else 5e-9 / arm)
        r = []
        for sgn in (1, -1):
            v = u.copy()
            v[j] += sgn * h
            fx = dict(zip(("delta_x", "delta_y", "delta_a", "tilt_x", "tilt_y"), v))
            t = solve_quasistatic(name, *loads, fixed=fx, stiffness=False)
            r.append([t.reactions[n] for n in ("delta_x", "delta_y", "delta_a", "tilt_x", "tilt_y")])
        col = (np.array(r[0]) - np.array(r[1])) / (2 * h)
        np.testing.assert_allclose(col, k[:, j], rtol=1e-4, atol=1e-4 * np.abs(k[:, j]).max())


# -- kinematics ---------------------------------------------------------------------------------------------
def test_outer_race_control_spin_axis_follows_harris():
    # Harris & Kotzalas, outer raceway control: tan beta = sin alpha_o / (cos alpha_o + D/d_m),
    # d_m the ball-centre orbit diameter; no spin and pure rolling at the outer contact centre
    s = solve_quasistatic("ACBB-120", 0.0, 22240.0, omega=RPM_25000, control="outer", stiffness=False)
    bl = s.balls
    ao, dm = bl["alpha_outer"][0], 2 * bl["ball_center_r"][0]
    d = 2 * catalog["ACBB-120"].ball_radius
    assert bl["beta"][0] == pytest.approx(math.atan(math.sin(ao) / (math.cos(ao) + d / dm)), rel=1e-9)
    assert abs(bl["spin_roll_outer"][0]) < 1e-12
    assert abs(bl["rolling_point_outer"][0]) < 1e-6 * bl["a_outer"][0]  # the root of a round-off slip


# the default 16 x 4 traction grid, expected not converged to 1 % here
@pytest.mark.filterwarnings("ignore::exudyn_bearing.solvers.quasistatic.solve.TractionResolutionWarning")
def test_pure_rolling_kinematics_of_a_deep_groove_bearing():
    # 6208 at 500 rad/s, light load: cage 198.0 rad/s, ball spin 952.38 rad/s (docs/theory/reference_cases.md)
    s = solve_quasistatic("6208", 100.0, omega=500.0, ring_growth=False, stiffness=False)
    assert s.balls["orbital_speed"][0] == pytest.approx(198.0, rel=2e-3)
    assert s.balls["ball_speed_absolute"][0] == pytest.approx(952.38, rel=2e-3)
    assert abs(s.balls["beta"][0]) < 1e-9


def test_acbb120_outer_race_controlled_and_minimum_energy_lowers_dissipation():
    # Gupta (2020): the ACBB-120 at 25,000 rpm and 22,240 N thrust is outer-race controlled, and the
    # minimum-energy kinematics dissipate less than outer-race control (about a quarter with his traction)
    kw = dict(omega=RPM_25000, traction="ester_curve_illustrative", lubricant="MIL-L-23699_492K", stiffness=False)
    auto = solve_quasistatic("ACBB-120", 0.0, 22240.0, control="auto", **kw)
    assert set(auto.balls["control_used"]) == {"outer"}
    me = solve_quasistatic("ACBB-120", 0.0, 22240.0, control="min-energy", **kw)
    assert me.dissipation_total < auto.dissipation_total
    chk = me.minimum_checks[0]
    assert chk["is_minimum"] and chk["neighbours_higher"] and min(chk["hessian_eigenvalues"]) > 0
    # both contacts spin under minimum energy (outer-race control has none on the outer race)
    assert abs(me.balls["spin_roll_outer"][0]) > 1e-3 and abs(auto.balls["spin_roll_outer"][0]) < 1e-12


def test_ring_growth_moves_the_contact_angles():
    kw = dict(omega=RPM_25000, stiffness=False)
    rigid = solve_quasistatic("ACBB-120", 0.0, 22240.0, ring_growth=False, **kw)
    grown = solve_quasistatic("ACBB-120", 0.0, 22240.0, **kw)
    assert rigid.geometry["inner_ring_growth"] == 0.0 and grown.geometry["inner_ring_growth"] > 30e-6
    # the inner ring grows outward: less operating clearance, a smaller inner contact angle
    assert grown.balls["alpha_inner"][0] < rigid.balls["alpha_inner"][0] - math.radians(3)


# -- output and bad input -----------------------------------------------------------------------------------
def test_cli_json_keys_and_units(capsys):
    assert main(["quasistatic", "ACBB-120", "--Fa", "22240", "--rpm", "25000", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    keys = ("delta_x", "delta_y", "delta_a", "tilt_x", "tilt_y", "psi", "q_inner", "q_outer", "alpha_inner",
            "alpha_outer", "p_max_inner", "p_max_outer", "centrifugal_force", "orbital_speed", "ball_speed", "beta",
            "spin_roll_inner", "spin_roll_outer", "dissipation_inner", "dissipation_outer", "dissipation_total",
            "inner_ring_growth", "stiffness")
    for k in keys:
        assert k in d and k in d["units"]
    assert len(d["q_inner"]) == 15 and np.array(d["stiffness"]).shape == (5, 5)
    assert d["dissipation_total"] == pytest.approx(d["dissipation_inner"] + d["dissipation_outer"])
    # centrifugal force m r_c omega_m^2 at the ball's own orbit radius
    b = catalog["ACBB-120"]
    s = solve_quasistatic(b, 0.0, 22240.0, omega=RPM_25000, stiffness=False)
    assert s.balls["centrifugal_force"][0] == pytest.approx(
        b.ball_mass * s.balls["ball_center_r"][0] * s.balls["orbital_speed"][0] ** 2, rel=1e-12)


@pytest.mark.parametrize("argv, word", [
    (["quasistatic", "7208", "--Fr", "3000"], "Fa:"),
    (["quasistatic", "6208", "--Fr", "3000", "--Fa", "60000"], "shoulder"),
    (["quasistatic", "6208", "--Fr", "1e6"], "Fr"),
    (["quasistatic", "ACBB-120", "--Fa", "1000", "--fit", "1e-2"], "fit"),
    (["quasistatic", "6208", "--Fr", "100", "--control", "middle"], "control"),
    (["quasistatic", "6208", "--Fr", "100", "--traction", "honey"], "traction"),
    (["quasistatic", "6208", "--Fr", "100", "--fix", "tilt_z=0"], "--fix:"),
    (["simulate", "--Fr", "3000", "--omega", "500", "--bearing", "7208", "--t-end", "0.001"], "Fa: 0 N cannot hold"),
    (["static", "7208", "--Fr", "3000"], "Fa:"),
])
def test_bad_input_is_a_one_line_error(argv, word, capsys):
    try:
        rc = main(argv)
    except SystemExit as exc:
        rc = exc.code
    assert rc == 2
    err = error_lines(capsys.readouterr().err)
    assert len(err) == 1 and word in err[0]


def test_static_says_what_it_holds(capsys):
    assert main(["static", "6208", "--Fr", "3000", "--Fa", "1000"]) == 0
    out = capsys.readouterr().out
    # the reaction's value is a regression baseline (tests/baselines.json), not validation
    line = next(x for x in out.splitlines() if x.startswith("tilt_y held (fixed): reaction "))
    assert float(line.split("reaction ")[1].split()[0]) == baseline("static_6208_tilt_y_reaction")
    assert "zero-speed quasi-static" in out
    assert main(["static", "6208", "--Fr", "3000", "--Fa", "1000", "--tilt", "free", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["held_dofs"] == {} and d["tilt_y"] > 1e-3


def test_top_level_export():
    assert eb.solve_quasistatic is solve_quasistatic


def test_readme_quasistatic_example_runs(capsys):
    text = manual_text()
    start = text.index("## Quasi-static solver")
    start = text.index("```python\n", start) + len("```python\n")
    code = text[start:text.index("```\n", start)]
    scope = {}
    exec(compile(code, "README.md", "exec"), scope)
    s = scope["s"]
    assert s.minimum_checks[0]["is_minimum"] and s.dissipation_total > 0


# the default 16 x 4 traction grid, expected not converged to 1 % here
@pytest.mark.filterwarnings("ignore::exudyn_bearing.solvers.quasistatic.solve.TractionResolutionWarning")
def test_angular_contact_needs_an_axial_load_to_locate_the_ring():
    # without axial load the ring of a single angular-contact bearing floats axially: refused, not guessed
    with pytest.raises(InputError, match="^Fa: .*axial load"):
        solve_quasistatic("ACBB-120", omega=RPM_25000)
    # a light thrust at speed (inner contacts nearly unloaded, outer ones carry the centrifugal force)
    s = solve_quasistatic("ACBB-120", 0.0, 100.0, omega=RPM_25000, stiffness=False)
    q, a = s.balls["q_inner"], s.balls["alpha_inner"]
    assert (q * np.sin(a)).sum() == pytest.approx(100.0, rel=1e-7)
    assert s.balls["q_outer"][0] > s.balls["centrifugal_force"][0] * 0.9


def test_induced_axial_force_published_factor():
    # Harris & Kotzalas ch. 7 (also bearing catalogues): with half the balls loaded (eps = 0.5),
    # F_a = 1.216 F_r tan(alpha) for point contact
    for deg in (15.0, 25.0, 40.0):
        a = math.radians(deg)
        assert ld.induced_axial_force(1000.0, a) / (1000.0 * math.tan(a)) == pytest.approx(1.216, abs=5e-4)
