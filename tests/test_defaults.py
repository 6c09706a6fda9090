"""One set of defaults (docs/defaults.md, exudyn_bearing.defaults): the generated table is current, no two
entry points default one quantity differently without a documented reason, and the rules of issue 36 on the
command line and in the API: loads and speeds zero, tilt held, the stiffness averaged over the same ball-set
phases, simulate refuses a missing speed, dataset takes its bearing first."""
import json
from pathlib import Path

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing import defaults
from exudyn_bearing.cli import _parser, main
from exudyn_bearing.solvers.quasistatic.coefficients import DEFAULT_N_PHASES

ROOT = Path(__file__).resolve().parent.parent


def test_committed_defaults_table_is_current():
    text = (ROOT / "docs" / "defaults.md").read_text()
    assert text == defaults.render(), "docs/defaults.md is stale: run python -m exudyn_bearing.defaults"


def test_no_quantity_has_two_defaults_without_a_reason():
    assert defaults.conflicts() == []


@pytest.mark.parametrize("entry, name, value", [("Scenario", "Fr", 3000.0),
                                                ("stiffness (CLI)", "phases", ("--phases", 1)),
                                                ("solve_quasistatic (API)", "fixed", {})])
def test_the_conflict_check_sees_a_difference(monkeypatch, entry, name, value):
    # planted differences: the old defaults (Scenario's 3000 N, one phase on the CLI, the API's free tilt)
    real = defaults.collect

    def planted():
        out = real()
        out[entry] = dict(out[entry], **{name: value})
        return out

    monkeypatch.setattr(defaults, "collect", planted)
    quantity = {"Fr": "Fr", "phases": "n_phases", "fixed": "tilt"}[name]
    assert any(line.startswith(f"{quantity}:") for line in defaults.conflicts())


def test_an_allowed_difference_needs_its_reason(monkeypatch):
    monkeypatch.setitem(defaults.ALLOWED_DIFFERENCES, "Fr", {})
    assert any(line.startswith("Fr:") for line in defaults.conflicts())


def test_loads_and_speeds_default_to_zero_outside_the_papers_protocols():
    sc = eb.Scenario()
    assert sc.Fr == sc.Fa == sc.omega == 0.0
    papers = eb.Scenario.papers_protocol()
    assert (papers.Fr, papers.omega) == (3000.0, 500.0)
    q = defaults.quantities()
    for name in ("Fr", "Fa", "omega"):
        vals = {v for e, (_, v) in q[name].items() if v not in (None, "(required)")
                and e not in defaults.ALLOWED_DIFFERENCES.get(name, {})}
        assert vals == {0.0}, (name, q[name])


def test_simulate_acbb120_under_thrust_has_no_radial_load():
    from exudyn_bearing.cli.simulate import scenario_from_args

    sc = scenario_from_args(_parser().parse_args(["simulate", "ACBB-120", "--Fa", "22240", "--rpm", "25000"]))
    assert (sc.Fr, sc.Fa) == (0.0, 22240.0)


@pytest.mark.filterwarnings("ignore::exudyn_bearing.BallInertiaWarning")  # expected: lightly loaded balls
def test_tilt_is_held_alike_in_the_api_and_on_the_command_line(capsys):
    # the 7208 under F_r = F_a = 3000 N at 500 rad/s: refused with a free tilt (shoulder), solved held
    with pytest.raises(eb.InputError, match="shoulder"):
        eb.solve_quasistatic("7208", Fr=3000.0, Fa=3000.0, omega=500.0, stiffness=False, fixed={})
    s = eb.solve_quasistatic("7208", Fr=3000.0, Fa=3000.0, omega=500.0, stiffness=False)
    assert s.held["tilt_x"] == s.held["tilt_y"] == "fixed"
    assert main(["quasistatic", "7208", "--Fr", "3000", "--Fa", "3000", "--omega", "500", "--json"]) == 0
    cli = json.loads(capsys.readouterr().out)
    got = [cli[k] for k in ("delta_x", "delta_y", "delta_a", "tilt_x", "tilt_y")]
    np.testing.assert_allclose(got, s.displacement, rtol=1e-9, atol=1e-15)
    assert got[3] == got[4] == 0.0
    with pytest.raises(eb.InputError, match="^Mx: a moment load needs the free tilt"):
        eb.solve_quasistatic("6208", Fr=3000.0, Mx=1.0, stiffness=False)


def test_stiffness_averages_the_same_phases_in_the_api_and_on_the_command_line(capsys):
    assert DEFAULT_N_PHASES > 1
    c = eb.bearing_coefficients("6208", [500.0], Fr=3000.0)
    assert c.operating_point["n_phases"] == DEFAULT_N_PHASES
    assert main(["stiffness", "6208", "--Fr", "3000", "--omega", "500", "--json"]) == 0
    cli = json.loads(capsys.readouterr().out)
    assert cli["phases"] == DEFAULT_N_PHASES
    np.testing.assert_allclose(cli["stiffness"], c.stiffness[0], rtol=1e-9, atol=1e-6)
    # the spread over the phases is reported, and it is what makes one phase a poor default on the 6208
    assert cli["phase_spread_stiffness"] == pytest.approx(c.operating_point["phase_spread_stiffness"][0])
    one = eb.bearing_coefficients("6208", [500.0], Fr=3000.0, n_phases=1).stiffness[0]
    assert abs(one[1, 1] / c.stiffness[0][1, 1] - 1.0) > cli["phase_spread_stiffness"] / 4


def test_simulate_cli_refuses_a_missing_speed(capsys):
    assert main(["simulate", "6208", "--Fr", "3000", "--t-end", "0.001"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("exudyn-bearing: error: omega: simulate needs a speed") and "--omega" in err


def test_dataset_takes_the_bearing_first_and_the_old_order_with_a_note(capsys):
    from exudyn_bearing.cli.dataset import bearing_and_out

    assert bearing_and_out(_parser().parse_args(["dataset", "6208", "out"])) == ("6208", "out")
    assert capsys.readouterr().err == ""
    for argv in (["dataset", "out"], ["dataset", "out", "6205"]):
        assert bearing_and_out(_parser().parse_args(argv)) == ("6205", "out")
        assert "deprecated" in capsys.readouterr().err
    assert bearing_and_out(_parser().parse_args(["dataset", "out", "--bearing", "6208"])) == ("6208", "out")
    # a bearing without its folder is not taken for the old form's folder
    with pytest.raises(eb.InputError, match="^OUT: dataset needs an output folder"):
        bearing_and_out(_parser().parse_args(["dataset", "6208"]))
