"""Bad input, round three, quasi-static side: the traction resolution checked, outputs at zero
relative speed, options accepted and ignored, API arguments of the wrong type, values without a range, and
refusals that name the input the user can change."""
import warnings

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing import InputError
from exudyn_bearing.cli import main
from exudyn_bearing.data import Lubricant, load_bearing
from exudyn_bearing.data.bearings import BallBearing
from exudyn_bearing.outputs.window_checks import ENERGY_FLOOR_OMEGA, energy_check, energy_floor
from exudyn_bearing.physics import losses as ls
from exudyn_bearing.physics.contact_slip import DEFAULT_N_ACROSS, DEFAULT_N_STRIPS, MAX_N_ACROSS, MAX_N_STRIPS
from exudyn_bearing.solvers.quasistatic.losses import power_losses
from exudyn_bearing.solvers.quasistatic.solve import TractionResolutionWarning
from exudyn_bearing.solvers.quasistatic.thermal import ThermalRunawayError, solve_thermal
from conftest import error_lines

JET = {"oil_inlet_temperature": 353.15, "oil_flow": 6e-5}
THERMAL = ["--thermal", "--oil-inlet-temperature", "353.15", "--oil-flow", "6e-5"]


def _solve(**kw):
    """The 6208 under 3000 N at 500 rad/s (race control), warnings recorded: (solution, warnings)."""
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        s = eb.solve_quasistatic("6208", Fr=3000.0, omega=500.0, stiffness=False, **kw)
    return s, [w for w in rec if issubclass(w.category, TractionResolutionWarning)]


@pytest.fixture(scope="module")
def sol6208():
    return _solve()[0]


def _cli(argv, capsys):
    """Exit status and the one error line of a command that must fail."""
    try:
        rc = main(argv)
    except SystemExit as exc:
        rc = exc.code
    err = error_lines(capsys.readouterr().err)
    assert len(err) == 1, err
    return rc, err[0]


# -- item 3: the traction resolution --------------------------------------------------------------------
def test_the_default_resolution_is_converged_and_silent(sol6208):
    _s, warned = _solve()
    assert not warned
    r = sol6208.resolution_check
    assert r["converged"] and abs(r["change"]) <= 0.01
    assert (r["n_strips"], r["n_across"]) == (DEFAULT_N_STRIPS, DEFAULT_N_ACROSS)
    assert r["doubled"] == (2 * DEFAULT_N_STRIPS, 2 * DEFAULT_N_ACROSS)


def test_a_coarse_resolution_warns_with_the_resolution_needed():
    s, warned = _solve(n_strips=4)
    assert len(warned) == 1 and str(warned[0].message).startswith("n_strips, n_across:")
    r = s.resolution_check
    assert not r["converged"] and abs(r["change"]) > 0.01
    # the estimate holds: solved at the resolution it names, the check passes
    s2, warned2 = _solve(n_strips=r["needed"][0], n_across=r["needed"][1])
    assert not warned2 and s2.resolution_check["converged"]


def test_the_thermal_loop_checks_its_last_solution_once():
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        r = solve_thermal("6208", 3000.0, omega=500.0, n_strips=2, n_across=1, **JET)
    assert r.iterations > 1
    assert sum(issubclass(w.category, TractionResolutionWarning) for w in rec) == 1
    assert not r.quasistatic.resolution_check["converged"]


def test_one_range_of_strips_in_every_entry_point(capsys):
    for kw, name, hi in ((dict(n_strips=MAX_N_STRIPS + 1), "n_strips", MAX_N_STRIPS),
                         (dict(n_across=MAX_N_ACROSS + 1), "n_across", MAX_N_ACROSS)):
        with pytest.raises(InputError, match=rf"^{name}: must be an integer in \[1, {hi}\]"):
            eb.solve_quasistatic("6208", Fr=3000.0, omega=500.0, **kw)
        with pytest.raises(InputError, match=rf"^{name}: must be an integer in \[1, {hi}\]"):
            eb.Scenario(**kw)
    for cmd in (["quasistatic", "6208", "--Fr", "3000"], ["simulate"]):
        rc, err = _cli(cmd + ["--strips", str(MAX_N_STRIPS + 1)], capsys)
        assert rc == 2 and "--strips" in err and f"[1, {MAX_N_STRIPS}]" in err
        rc, err = _cli(cmd + ["--points-across", "0"], capsys)
        assert rc == 2 and "--points-across" in err


# -- item 5: zero relative speed -----------------------------------------------------------------------
@pytest.mark.parametrize("omega, omega_outer", [(500.0, 500.0), (0.0, 0.0)])
def test_no_relative_speed_no_loss_no_nan(omega, omega_outer):
    s = eb.solve_quasistatic("6208", Fr=3000.0, omega=omega, omega_outer=omega_outer, stiffness=False)
    d = s.to_dict()
    assert d["power_loss_total"] == 0.0 and d["friction_torque_total"] == 0.0
    assert d["power_loss"]["drag"] == 0.0  # the mixture turns with the outer ring
    assert d["energy_residual"] == 0.0


def test_cli_says_what_the_torque_is_without_relative_speed(capsys):
    assert main(["quasistatic", "6208", "--Fr", "3000", "--omega", "500", "--omega-outer", "500"]) == 0
    out = capsys.readouterr().out
    line = next(x for x in out.splitlines() if x.startswith("power loss"))
    assert "nan" not in line.lower() and "friction torque 0 N m (no relative speed" in line


def test_drag_is_relative_to_the_outer_ring():
    # the outer ring alone at 300 rad/s: the balls orbit at about 0.6 of it, the mixture turns with the outer
    # ring, so the balls move through it at r_c (omega_m - 300) (backwards), not at r_c omega_m
    s = eb.solve_quasistatic("6208", Fr=3000.0, omega=0.0, omega_outer=300.0, stiffness=False)
    bl = s.balls
    v = bl["ball_center_r"] * (bl["orbital_speed"] - 300.0)
    d_ball = 2.0 * load_bearing("6208").ball_radius
    f = ls.ball_drag_force(np.abs(v), d_ball, ls.AIR_DENSITY, ls.AIR_VISCOSITY)
    assert power_losses(s)["drag_ball"] == pytest.approx(f * np.abs(v), rel=1e-12)


def test_energy_check_is_not_judged_below_the_floor_at_rest():
    floor = energy_floor(9.1e-3, 0.0)
    assert floor == pytest.approx(9.1e-3 * ENERGY_FLOOR_OMEGA)
    assert energy_floor(9.1e-3, -500.0) == pytest.approx(9.1e-3 * 500.0)
    # the numbers of a 6208 at omega 0 with rolling resistance: two powers near zero
    c = energy_check(-1.8e-4, {"traction": 5.1e-5}, -5e-10, 0.005, floor=floor)
    assert c["passed"] is None and "below the loss floor" in c["reason"]
    # well above the floor the check judges
    c = energy_check(10.0, {"traction": 5.0}, 0.0, 0.005, floor=floor)
    assert c["passed"] is False


# -- item 6: options accepted and ignored -------------------------------------------------------------
@pytest.mark.parametrize("argv, words", [
    (["quasistatic", "6208", "--Fr", "3000", "--omega", "100", "--ambient-temperature", "300"],
     ("--ambient-temperature", "--thermal")),
    (["quasistatic", "6208", "--Fr", "3000", "--omega", "100", "--fix", "delta_y=0", "--fix", "delta_y=1e-6"],
     ("--fix delta_y", "twice")),
    (["quasistatic", "6208", "--Fr", "3000", "--omega", "100", "--ambient-temperature", "20"] + THERMAL,
     ("ambient_temperature", "20 degC")),
    (["simulate", "--Fr", "3000", "--omega", "500", "--oil-volume-fraction", "0.05"], ("oil_volume_fraction", "--ball-drag")),
    (["simulate", "--Fr", "3000", "--omega", "500", "--hysteresis-loss-factor", "0.01"], ("hysteresis_loss_factor", "--rolling-resistance")),
])
def test_options_without_their_switch_are_refused(argv, words, capsys):
    rc, err = _cli(argv, capsys)
    assert rc == 2 and all(w in err for w in words), err


def test_scenario_refuses_loss_options_without_their_switch():
    with pytest.raises(InputError, match="^oil_volume_fraction: used with ball_drag only"):
        eb.Scenario(Fr=3000.0, omega=500.0, oil_volume_fraction=0.05)
    with pytest.raises(InputError, match="^hysteresis_loss_factor: used with rolling_resistance only"):
        eb.Scenario(Fr=3000.0, omega=500.0, hysteresis_loss_factor=0.01)
    assert eb.Scenario(Fr=3000.0, omega=500.0, ball_drag=True, oil_volume_fraction=0.05).oil_volume_fraction == 0.05
    assert eb.Scenario(Fr=3000.0, omega=500.0, rolling_resistance=True, hysteresis_loss_factor=0.01).hysteresis_loss_factor == 0.01


# -- item 8: API arguments of the wrong type ----------------------------------------------------------
@pytest.mark.parametrize("kw, match", [
    (dict(start="abc"), r"^start: expected a ThermalSolution"),
    (dict(loss_options="abc"), r"^loss_options: expected a dict"),
    (dict(loss_options={"cage_pocket_frction": 0.1}), r"^loss_options: unknown keyword of power_losses "
                                                       r"'cage_pocket_frction'"),
    (dict(temperatures={"inner": 300.0, "outer": 300.0, "ball": 300.0}), r"^temperatures: set by the thermal"),
    (dict(contrl="outer"), r"^solve_thermal: unknown keyword argument 'contrl'"),
])
def test_solve_thermal_names_a_bad_argument(kw, match):
    with pytest.raises(InputError, match=match):
        solve_thermal("6208", 3000.0, omega=500.0, **JET, **kw)


def test_solve_thermal_starts_from_a_quasistatic_solution(sol6208):
    r = solve_thermal("6208", 3000.0, omega=500.0, start=sol6208, **JET)
    ref = solve_thermal("6208", 3000.0, omega=500.0, **JET)
    assert r.converged
    for k in ref.temperatures:
        assert r.temperatures[k] == pytest.approx(ref.temperatures[k], abs=0.05)  # 5 times the tolerance


def test_power_losses_names_a_bad_solution():
    with pytest.raises(InputError, match=r"^sol: expected a QuasiStaticSolution"):
        power_losses("abc")


# -- item 9: values without a range -------------------------------------------------------------------
@pytest.mark.parametrize("make, match", [
    (lambda: load_bearing("6208").replace(outer_race_radius=1e6), r"^outer_race_radius: 1e\+06 m is not plausible"),
    (lambda: BallBearing.from_dimensions(9, 12.7e-3, 60.6, 0.52, 0.52), r"^pitch_diameter: .*60\.6 mm is 0\.0606 m"),
    (lambda: BallBearing.from_dimensions(9, 12.7e-3, 60.6e-3, 0.52, 0.52, diametral_clearance=20),
     r"^diametral_clearance: .*20 um is 2e-05 m"),
    (lambda: load_bearing("6208").with_clearance(20.0, name="Pd"), r"^Pd: .*20 um is 2e-05 m"),
    (lambda: Lubricant(mu_boundary=5.0), r"^mu_boundary: 5 is not plausible \(0 to 1\)"),
    (lambda: Lubricant(roughness_race=1e-15), r"^roughness_race: the composite roughness"),
])
def test_data_values_have_ranges(make, match):
    with pytest.raises(InputError, match=match):
        make()


def test_plausible_data_still_pass():
    b = BallBearing.from_dimensions(9, 12.7e-3, 60.6e-3, 0.52, 0.52, diametral_clearance=20e-6)
    assert b.diametral_clearance == pytest.approx(20e-6)
    assert Lubricant(mu_boundary=0.12, roughness_race=5e-8).mu_boundary == 0.12


@pytest.mark.parametrize("kw, match", [
    (dict(oil_density=0.85), r"^oil_density: .*0\.85 g/cm\^3 is 850 kg/m\^3"),
    (dict(cage_pocket_friction=5.0), r"^cage_pocket_friction: 5 is not plausible"),
    (dict(bearing="7208"), r"^bearing: the solution is of bearing '6208'"),
])
def test_power_losses_ranges_and_bearing(sol6208, kw, match):
    with pytest.raises(InputError, match=match):
        power_losses(sol6208, **kw)


@pytest.mark.parametrize("kw, match", [
    (dict(cage_pocket_clearance=33.0), r"^cage_pocket_clearance: 33 m is not plausible.*33 um"),
    (dict(ambient_conductance={"innr": 1.0}), r"^ambient_conductance: unknown key 'innr'"),
    (dict(loss_options={"cage_pocket_friction": 5.0}), r"^cage_pocket_friction: 5 is not plausible"),
])
def test_solve_thermal_ranges(kw, match):
    with pytest.raises(InputError, match=match):
        solve_thermal("6208", 3000.0, omega=500.0, **JET, **kw)


def test_a_speed_given_as_text_is_refused():
    with pytest.raises(InputError, match=r"^speeds: expected a number, got '500'"):
        eb.bearing_coefficients("6208", "500", Fr=3000.0)


def test_info_has_the_speed_limit_of_quasistatic(capsys):
    rc, err = _cli(["info", "6208", "--omega", "1e9"], capsys)
    assert rc == 2 and err.startswith("exudyn-bearing: error: omega:") and "grown rings" in err
    rc2, err2 = _cli(["quasistatic", "6208", "--Fr", "3000", "--omega", "1e9"], capsys)
    assert rc2 == 2 and err2.split("(")[0] == err.split("(")[0]  # the same refusal
    assert main(["info", "6208", "--rpm", "3000"]) == 0


# -- item 10: refusals name the input the user can change ---------------------------------------------
def test_a_shoulder_overrun_the_speed_causes_names_the_speed(capsys):
    rc, err = _cli(["quasistatic", "7208", "--Fr", "3000", "--Fa", "3000", "--rpm", "8000"], capsys)
    assert rc == 2 and err.startswith("exudyn-bearing: error: omega:") and "shoulder" in err
    assert "reduce the speed" in err
    # the same loads at rest are carried
    s = eb.solve_quasistatic("7208", 3000.0, 3000.0, omega=0.0, fixed={"tilt_x": 0.0, "tilt_y": 0.0},
                             stiffness=False)
    assert np.all(np.isfinite(s.balls["q_inner"]))


@pytest.mark.parametrize("argv, start", [
    (["quasistatic", "7208", "--Fr", "3000"], "Fa:"),
    (["static", "6208", "--Fr", "-5"], "Fr:"),
    (["static", "6208", "--Fr", "1e9"], "Fr:"),
    (["quasistatic", "6208", "--Fr", "100", "--fix", "tilt_z=0"], "--fix:"),
    (["stiffness", "6208", "--Fr", "3000", "--phases", "0"], "--phases:"),
])
def test_cli_refusals_name_the_option(argv, start, capsys):
    rc, err = _cli(argv, capsys)
    assert rc == 2 and err.startswith(f"exudyn-bearing: error: {start}"), err


def test_thermal_runaway_names_the_oil_flow():
    with pytest.raises(ThermalRunawayError, match=r"^oil_flow: thermal runaway"):
        solve_thermal("6208", 3000.0, omega=1500.0, oil_inlet_temperature=353.15, oil_flow=1e-8)


def test_ambient_conductance_keeps_the_default_of_a_key_left_out():
    from exudyn_bearing.solvers.quasistatic.thermal import _default_ambient_conductance

    r = solve_thermal("6208", 3000.0, omega=500.0, ambient_conductance={"inner": 1.0}, **JET)
    assert r.conductances["inner_ambient"] == 1.0
    assert r.conductances["outer_ambient"] == _default_ambient_conductance(load_bearing("6208"))["outer"] > 0.0


def test_a_dissipation_below_the_loss_floor_is_not_judged():
    # the unloaded 6208 at 500 rad/s dissipates micro-watts (its balls pressed outward by their centrifugal
    # force alone), far below the loss floor LOSS_FLOOR_MU (sum of the outer contact loads) r_p omega: a 1 %
    # change of it is no result anyone uses and is not judged
    from exudyn_bearing.physics.losses import LOSS_FLOOR_MU

    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        s = eb.solve_quasistatic("6208", omega=500.0, stiffness=False)
    assert not [w for w in rec if issubclass(w.category, TractionResolutionWarning)]
    r = s.resolution_check
    floor = LOSS_FLOOR_MU * float(np.sum(s.balls["q_outer"])) * 0.0303 * 500.0
    assert r["converged"] and 0.0 < abs(r["dissipation"]) < floor
