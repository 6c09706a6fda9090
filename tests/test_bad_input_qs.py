"""Bad input to the quasi-static solver, its thermal loop, the analytic entry points and the CLI:
loads beyond the elastic contact limit, the thermal network at rest, catalogue names, CLI flags."""
import math

import pytest

import exudyn_bearing as eb
from exudyn_bearing import InputError
from exudyn_bearing.cli import main
from exudyn_bearing.data import load_bearing
from exudyn_bearing.physics import thermal as th
from exudyn_bearing.solvers.analytic import bearing_info, static_analysis
from exudyn_bearing.solvers.quasistatic.thermal import solve_thermal
from conftest import error_lines

JET = {"oil_inlet_temperature": 353.15, "oil_flow": 6e-5}


@pytest.mark.parametrize("fr", [1e5, 2e5, 1e6])
def test_loads_beyond_the_elastic_limit_are_refused_by_the_api(fr):
    # 6208: 4.2 GPa (ISO 76) is reached at 21.8 kN radial (model/load_range.py); 1e5 N gives about 7 GPa,
    # 2e5 N leaves no equilibrium (a singular system), 1e6 N is refused before the solve
    with pytest.raises(InputError, match=r"^Fr: .*4\.2 GPa"):
        eb.solve_quasistatic("6208", Fr=fr, omega=500.0)


def test_a_load_inside_the_limit_still_solves():
    # 1e4 N: p_max about 2.2 GPa * (1e4 / 3e3)^(1/3) = 3.3 GPa (p ~ Q^(1/3)) at low speed, below 4.2 GPa
    s = eb.solve_quasistatic("6208", Fr=1e4, omega=50.0, stiffness=False)
    assert max(s.balls["p_max_inner"].max(), s.balls["p_max_outer"].max()) < 4.2e9


@pytest.mark.parametrize("fr", [3e4, 1e6])
def test_thermal_loop_names_the_load_not_a_runaway(fr):
    with pytest.raises(InputError, match=r"^Fr: .*4\.2 GPa"):
        solve_thermal("6208", fr, omega=500.0, **JET)


@pytest.mark.parametrize("argv", [
    ["quasistatic", "6208", "--Fr", "1e6", "--omega", "500"],
    ["quasistatic", "6208", "--Fr", "3e4", "--omega", "500", "--thermal", "--oil-inlet-temperature", "353.15",
     "--oil-flow", "6e-5"],
    ["stiffness", "6208", "--Fr", "1e6", "--rpm", "3000"],
])
def test_cli_names_the_load_and_the_limit(argv, capsys):
    assert main(argv) == 2
    err = error_lines(capsys.readouterr().err)
    assert len(err) == 1 and "Fr:" in err[0] and "4.2 GPa" in err[0]


def test_through_flow_speed_is_flow_over_the_free_annulus():
    # Q / (pi (r_o^2 - r_i^2) - Z pi R_b^2): rings 1 and 2 m, one ball of 0.5 m: area 3 pi - pi / 4
    assert th.oil_through_flow_speed(1.0, 1.0, 2.0, 1, 0.5) == pytest.approx(1.0 / (2.75 * math.pi), rel=1e-12)


def test_thermal_network_is_continuous_at_rest():
    rest = solve_thermal("6208", 3000.0, omega=0.0, **JET)
    slow = solve_thermal("6208", 3000.0, omega=0.1, **JET)
    assert rest.converged and slow.converged
    # 0.1 rad/s moves the 6208's inner ring surface at 2.4 mm/s, below the oil's through-flow
    # (6e-5 m^3/s over 1.25e-3 m^2: 48 mm/s) and adds microwatts of loss: the same network within 1 K
    for k in rest.temperatures:
        assert rest.temperatures[k] == pytest.approx(slow.temperatures[k], abs=1.0)
    # at rest the oil washes the rings: they lie between the ambient air and the oil
    t = rest.temperatures
    for ring in ("inner", "outer"):
        assert rest.ambient_temperature + 1.0 < t[ring] < t["oil"]


def test_analytic_entry_points_accept_catalogue_names():
    b = load_bearing("6208")
    assert static_analysis("6208", 3000.0)["q_max"] == static_analysis(b, 3000.0)["q_max"]
    assert bearing_info("6208")["K_inner"] == bearing_info(b)["K_inner"]


@pytest.mark.parametrize("argv, word", [
    (["quasistatic", "6208", "--Fr", "3000", "--omega", "100", "--oil-flow", "6e-5"], "--thermal"),
    (["quasistatic", "6208", "--Fr", "3000", "--omega", "100", "--Pd", "-1e-3"], "Pd:"),
    (["stiffness", "6208", "--Fr", "3000", "--Pd", "-1e-3"], "Pd:"),
])
def test_cli_flags_are_named(argv, word, capsys):
    assert main(argv) == 2
    err = error_lines(capsys.readouterr().err)
    assert len(err) == 1 and word in err[0] and "outer_race_radius" not in err[0]
