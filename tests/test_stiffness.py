"""Linearised bearing stiffness and damping from the quasi-static solver
(issue #12): the damping matrix, the coefficient table, the CLI, the check
against the DEM reference engine and the comparison with the 3-DOF model.

Independent numbers each test checks are named in its docstring."""
import json
import math
import warnings

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing.cli import main
from exudyn_bearing.data import InputError, default_lubricant
from exudyn_bearing.model.coefficients import AXES, BearingCoefficients
from exudyn_bearing.model.layout import P_MR
from exudyn_bearing.physics import kinematics
from exudyn_bearing.solvers.quasistatic import bearing_coefficients, solve_quasistatic
from exudyn_bearing.solvers.reference import ReferenceEngine
from exudyn_bearing.solvers.vibration import three_dof as td
from conftest import error_lines, manual_text

W_ARM = np.array([1.0, 1.0, 1.0, 1.0 / 0.03, 1.0 / 0.03])  # moments / arm ~ forces, tilts x arm ~ lengths


def _rel(a, b):
    w = np.outer(W_ARM, W_ARM)
    return float(np.abs((a - b) * w).max() / np.abs(b * w).max())


# -- the matrices --------------------------------------------------------------------------------------
@pytest.mark.parametrize("name, loads, omega, tol", [
    ("6208", dict(Fr=3000.0), 0.0, 1e-7),
    ("6208", dict(Fr=3000.0), 3000.0, 1e-7),
    ("6208", dict(Fr=3000.0, Fa=1000.0, My=5.0), 500.0, 1e-4),
    ("7208", dict(Fr=1000.0, Fa=3000.0), 500.0, 1e-3),
])
def test_condensed_stiffness_equals_the_central_differences(name, loads, omega, tol):
    """The analytic condensation of every ball (the machinery of the damping matrix) against the
    solver's central-difference K: the same matrix up to the contact-angle dependence of the Hertz
    constant, which only the differences hold (measured 3e-9 at zero contact angle, 3e-5 and 2.5e-4
    with it)."""
    s = solve_quasistatic(name, **loads, omega=omega, fixed={}, inertia_check=False)
    assert s.stiffness_check["condensed_difference"] < tol


def test_damping_of_collinear_contacts_is_two_kelvin_voigt_contacts_in_series():
    """6208 at rest, radial load: every contact is boundary-lubricated (no film), so C_n = C_hyst =
    (3/2) alpha_e Q (Hunt & Crossley), the two contacts of a ball lie on one radial line, and
    C_xx = sum_j cos^2 psi_j (c_i k_o^2 + c_o k_i^2) / (k_i + k_o)^2 with k = (3/2) Q / delta."""
    b = eb.catalog["6208"]
    s = solve_quasistatic(b, 3000.0)
    bl = s.balls
    alpha_e = b.material.hysteretic_damping
    loaded = bl["q_inner"] > 0
    np.testing.assert_allclose(bl["c_normal_inner"][loaded], 1.5 * alpha_e * bl["q_inner"][loaded], rtol=1e-12)
    ki = 1.5 * bl["q_inner"][loaded] / bl["delta_inner"][loaded]
    ko = 1.5 * bl["q_outer"][loaded] / bl["delta_outer"][loaded]
    ci, co = 1.5 * alpha_e * bl["q_inner"][loaded], 1.5 * alpha_e * bl["q_outer"][loaded]
    cos2 = np.cos(bl["psi"][loaded]) ** 2
    expected = float(np.sum(cos2 * (ci * ko ** 2 + co * ki ** 2) / (ki + ko) ** 2))
    assert s.damping[0, 0] == pytest.approx(expected, rel=1e-9)
    sin2 = np.sin(bl["psi"][loaded]) ** 2
    assert s.damping[1, 1] == pytest.approx(float(np.sum(sin2 * (ci * ko ** 2 + co * ki ** 2) / (ki + ko) ** 2)),
                                            rel=1e-9)
    # radial normals carry no axial or tilt damping; the matrix is symmetric
    assert np.abs(s.damping[2:, :]).max() < 1e-12 * s.damping[0, 0]
    np.testing.assert_allclose(s.damping, s.damping.T, atol=1e-12 * s.damping[0, 0])


def test_full_film_contacts_take_the_squeeze_film_damping():
    """6208 at 3000 rad/s: Lambda > 3 at the loaded contacts, where the contact model's damping is the
    squeeze film alone, C = (3 pi eta a / sqrt 2) (R_b / h_min)^(3/2) (Guessasma & Machado), computed
    here from the solution's semi-axis and film."""
    b = eb.catalog["6208"]
    lub = default_lubricant()
    s = solve_quasistatic(b, 3000.0, omega=3000.0)
    bl = s.balls
    full = bl["regime_inner"] == 2
    assert full.sum() >= 3 and np.all(bl["film_parameter_inner"][full] > lub.lambda_full_film)
    a, h = bl["a_inner"][full], bl["h_min_inner"][full]
    c = 3 * math.pi * lub.viscosity * a / math.sqrt(2) * (b.ball_radius / h) ** 1.5
    np.testing.assert_allclose(bl["c_normal_inner"][full], c, rtol=1e-12)
    # unloaded contacts carry no damping
    assert np.all(bl["c_normal_inner"][bl["q_inner"] == 0] == 0.0)


def test_damping_regimes_follow_lambda_at_500_rad_s():
    """Mixed regime (1 < Lambda <= 3) at the 6208's loaded contacts at 500 rad/s: the series
    combination C_h C_f / (C_h + C_f) of the two damping terms, each below both."""
    s = solve_quasistatic("6208", 3000.0, omega=500.0)
    bl = s.balls
    mixed = bl["regime_inner"] == 1
    assert mixed.sum() >= 3
    ch, cf = bl["c_hysteretic_inner"][mixed], bl["c_squeeze_inner"][mixed]
    np.testing.assert_allclose(bl["c_normal_inner"][mixed], ch * cf / (ch + cf), rtol=1e-12)
    assert np.all(bl["c_normal_inner"][mixed] < np.minimum(ch, cf))


# -- the coefficient table ----------------------------------------------------------------------------
def test_coefficient_table_equals_independent_solves():
    """Each speed of the warm-started table against a cold solve at that speed (same matrices to the
    solver's tolerance); the phase average against the mean of the individual phases."""
    speeds = [0.0, 300.0, 1000.0, 2500.0]
    c = bearing_coefficients("6208", speeds, Fr=3000.0, n_phases=1)
    assert isinstance(c, BearingCoefficients) and c.n_speeds == 4 and c.axes == AXES
    for i, w in enumerate(speeds):
        s = solve_quasistatic("6208", 3000.0, omega=w)
        assert _rel(c.stiffness[i], s.stiffness) < 1e-6
        np.testing.assert_allclose(c.damping[i, :2, :2], s.damping[:2, :2], rtol=1e-6, atol=1e-9 * s.damping[0, 0])
    assert c.operating_point["bearing"] == "6208" and c.operating_point["Fr"] == 3000.0
    assert c.operating_point["diametral_clearance"] == 0.0
    assert c.stiffness[-1, 0, 0] > c.stiffness[0, 0, 0]  # the centrifugal force stiffens the radial direction
    avg = bearing_coefficients("6208", [500.0], Fr=3000.0)  # the default: three phases (docs/defaults.md)
    assert avg.operating_point["n_phases"] == 3
    z = eb.catalog["6208"].n_balls
    ks = [solve_quasistatic("6208", 3000.0, omega=500.0, phase=2 * math.pi / z * m / 3).stiffness for m in range(3)]
    assert _rel(avg.stiffness[0], np.mean(ks, axis=0)) < 1e-6
    assert avg.operating_point["phase_spread_stiffness"][0] > 0.0


@pytest.mark.parametrize("kw, word", [
    (dict(speeds=[100.0, 50.0]), "speeds"),
    (dict(speeds=[]), "speeds"),
    (dict(speeds=[-1.0]), "speeds"),
    (dict(speeds=[100.0], n_phases=0), "n_phases"),
    (dict(speeds=[100.0], omega=5.0), "omega"),
])
def test_coefficient_table_bad_input(kw, word):
    with pytest.raises(InputError) as e:
        bearing_coefficients("6208", Fr=3000.0, **kw)
    assert str(e.value).startswith(word) and "\n" not in str(e.value)


def test_warm_start_rejects_another_bearing():
    s = solve_quasistatic("6208", 3000.0, omega=100.0, stiffness=False)
    with pytest.raises(InputError, match="^start"):
        solve_quasistatic("6004", 500.0, omega=100.0, start=s)


# -- command line ---------------------------------------------------------------------------------------
def test_cli_stiffness_json(capsys):
    """Keys and shapes of the JSON, the units map, and the matrices equal to the solver's (one phase)."""
    assert main(["stiffness", "6208", "--Fr", "3000", "--rpm", "3000", "--phases", "1", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    for k in ("stiffness", "damping", "units", "axes", "bearing", "loads", "omega", "rpm", "diametral_clearance"):
        assert k in d
    assert d["axes"] == ["x", "y", "axial", "tilt_x", "tilt_y"]
    k, c = np.array(d["stiffness"]), np.array(d["damping"])
    assert k.shape == c.shape == (5, 5)
    assert d["units"]["stiffness"][0][0] == "N/m" and d["units"]["damping"][4][4] == "N m s/rad"
    s = solve_quasistatic("6208", 3000.0, omega=3000 * math.pi / 30)
    assert d["omega"] == pytest.approx(3000 * math.pi / 30)
    np.testing.assert_allclose(k, s.stiffness, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(c, s.damping, rtol=1e-12, atol=1e-12)


def test_cli_stiffness_table(capsys, tmp_path):
    png = tmp_path / "k.png"
    assert main(["stiffness", "6208", "--Fr", "3000", "--rpms", "1000", "5000", "--plot", str(png), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert np.array(d["stiffness"]).shape == (2, 5, 5) and d["rpm"] == pytest.approx([1000.0, 5000.0])
    assert png.stat().st_size > 0 and png.with_suffix(".csv").exists()
    assert main(["stiffness", "6208", "--Fr", "3000", "--omega", "500"]) == 0
    assert "damping C" in capsys.readouterr().out


@pytest.mark.parametrize("argv, word", [
    (["stiffness", "6208", "--Fr", "3000", "--phases", "0"], "phases"),
    (["stiffness", "6208", "--Fr", "3000", "--speeds", "500", "100"], "speeds"),
    (["stiffness", "6208", "--Fr", "3000", "--plot", "x.png"], "plot"),
    (["stiffness", "7208", "--Fr", "3000"], "Fa:"),
])
def test_cli_stiffness_bad_input(argv, word, capsys):
    assert main(argv) == 2
    err = error_lines(capsys.readouterr().err)
    assert len(err) == 1 and word in err[0]


# -- against the dynamics --------------------------------------------------------------------------------
def _dem_mean(fr, fa, omega, t_end, t_avg, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.StepSizeWarning)
        rec = ReferenceEngine("6208", eb.Scenario(Fr=fr, Fa=fa, omega=omega, t_end=t_end, dt=3.5e-6,
                                                  sample_dt=1.05e-5, **kw)).run()
    t = rec.data["t"]
    return rec.data["ring"][t > t_end - t_avg, :3].mean(axis=0)


def test_dem_load_increments_give_the_quasistatic_stiffness():
    """Issue #12: small static load increments on the DEM's inner ring (6208, 3000 N, 500 rad/s;
    radial 3000 -+ 150 N, axial 25 N on the symmetric bearing) give the radial and axial stiffness of
    the quasi-static matrix within 5 % (validation/consistency/stiffness_checks.py measures -0.02 % and -0.65 %
    over 20 ball passes). The quasi-static value is the compliance of the translational block (the
    DEM ring cannot tilt) averaged over three ball-set positions; the DEM averages over 10 ball passes
    (35 ms) after 20 ms."""
    w = 500.0
    b = eb.catalog["6208"]
    wc = float(kinematics.cage_speed(w, 0.0, b.ball_radius, b.pitch_radius, 0.0))
    t_avg = 10 * 2 * math.pi / (b.n_balls * wc)
    xm = _dem_mean(2850.0, 0.0, w, 0.02 + t_avg, t_avg)
    xp = _dem_mean(3150.0, 0.0, w, 0.02 + t_avg, t_avg)
    xa = _dem_mean(3000.0, 25.0, w, 0.02 + t_avg, t_avg)
    k_dem = np.array([300.0 / (xp[0] - xm[0]), 25.0 / xa[2]])
    comp = np.mean([np.linalg.inv(solve_quasistatic("6208", 3000.0, omega=w, ring_growth=False,
                                                    phase=2 * math.pi / 9 * m / 3).stiffness[:3, :3])
                    for m in range(3)], axis=0)
    k_qs = 1.0 / np.array([comp[0, 0], comp[2, 2]])
    assert np.all(np.abs(k_dem / k_qs - 1.0) < 0.05), (k_dem, k_qs)


def test_dem_free_decay_gives_the_damping_ratio_of_the_matrix():
    """The DEM's inner ring kicked in x (0.02 m/s, 6208, 3000 N, 500 rad/s, friction off so that only
    the contacts' normal damping acts): the logarithmic decrement of its free vibration (kicked minus
    unkicked run) against zeta = C_xx / (2 sqrt(K_xx m)) of the matrices, within 10 % (measured 4 %;
    the condensation neglects the ball's inertia, which lowers the DEM's frequency by 2.6 %)."""

    class Kicked(ReferenceEngine):
        kick = 0.0

        def initial_state(self):
            st = super().initial_state()
            st["ring"][3] += self.kick
            return st

    sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.004, dt=1e-6, sample_dt=1e-6, friction="none")
    runs = []
    for v0 in (0.0, 0.02):
        e = Kicked("6208", sc)
        e.kick = v0
        runs.append(e.run())
    t = runs[0].data["t"]
    d = runs[1].data["ring"][:, 0] - runs[0].data["ring"][:, 0]
    i = np.flatnonzero((d[1:-1] > d[:-2]) & (d[1:-1] >= d[2:]) & (d[1:-1] > 0)) + 1
    i = i[:15]
    sigma = -np.polyfit(t[i], np.log(d[i]), 1)[0]
    wn = math.hypot(2 * math.pi / np.mean(np.diff(t[i])), sigma)
    m = float(e.params[P_MR])
    s = solve_quasistatic("6208", 3000.0, omega=500.0, ring_growth=False)
    zeta_qs = s.damping[0, 0] / (2 * math.sqrt(s.stiffness[0, 0] * m))
    assert sigma / wn == pytest.approx(zeta_qs, rel=0.10)
    assert wn == pytest.approx(math.sqrt(s.stiffness[0, 0] / m), rel=0.05)


# -- the 3-DOF model against the linearised full model --------------------------------------------------
def test_three_dof_ball_link_and_bearing_stiffness():
    """Derived 6004 (500 N, 3000 rpm, P_d = 12.5 um): the 3-DOF model's Hertz links and contact-model
    damping equal the quasi-static solver's most loaded ball (the same load from two solvers: 1e-3),
    and the bearing's K_xx is the sum over the balls of the series ball stiffness times cos^2 psi
    (1e-6): the 3-DOF's one-ball line holds half of it (measured 1.93 balls' worth)."""
    fr, w, pd = 500.0, 2 * math.pi * 50, 12.5e-6
    p = td.derived_parameters("6004", fr, w, pd, film_damping="contact_model")
    dv = p.derivation["contacts"]
    s = solve_quasistatic(eb.catalog["6004"].with_clearance(pd), fr, omega=w, ring_growth=False)
    bl = s.balls
    j = int(np.argmax(bl["q_inner"]))
    for race in ("inner", "outer"):
        assert 1.5 * bl[f"q_{race}"][j] / bl[f"delta_{race}"][j] == pytest.approx(dv[race]["k_hertz"], rel=1e-3)
        assert bl[f"c_normal_{race}"][j] == pytest.approx(dv[race]["c_contact_model"], rel=1e-3)
    loaded = bl["q_inner"] > 0
    ki = 1.5 * bl["q_inner"][loaded] / bl["delta_inner"][loaded]
    ko = 1.5 * bl["q_outer"][loaded] / bl["delta_outer"][loaded]
    k_sum = float(np.sum(ki * ko / (ki + ko) * np.cos(bl["psi"][loaded]) ** 2))
    assert s.stiffness[0, 0] == pytest.approx(k_sum, rel=1e-6)
    k_ball = 1.0 / (1.0 / dv["inner"]["k_hertz"] + 1.0 / dv["outer"]["k_hertz"])
    assert 1.5 < s.stiffness[0, 0] / k_ball < 2.5


def test_readme_stiffness_example_runs():
    """The README's example of "Bearing stiffness for rotordynamics" runs as printed; its k_xx at rest
    equals the solver's phase-averaged K_xx."""
    text = manual_text()
    start = text.index('```python\nimport exudyn_bearing as eb\nc = eb.bearing_coefficients')
    code = text[start + len("```python\n"):text.index("```\n", start + 10)]
    scope = {}
    exec(compile(code, "README.md", "exec"), scope)
    c = scope["c"]
    z = eb.catalog["6208"].n_balls
    k0 = np.mean([solve_quasistatic("6208", 3000.0, phase=2 * math.pi / z * m / 3).stiffness[0, 0] for m in range(3)])
    assert c.stiffness[0, 0, 0] == pytest.approx(k0, rel=1e-9)
