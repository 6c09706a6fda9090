"""Output a person reads at a glance: a run's summary prints as the command line's table (units on
every row that has one) and stays a dict; the three-mass model's parameters print with units."""
import json

import pytest

import exudyn_bearing as eb
from exudyn_bearing.cli import main
from exudyn_bearing.outputs.jsonio import to_jsonable
from exudyn_bearing.outputs.tables import Summary


@pytest.fixture(scope="module")
def short_run():
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)  # 4 ms: too short to judge steady
        run = eb.simulate("6208", eb.Scenario(Fr=3000, omega=500, t_end=0.004, dt=5e-6))
        return run, run.summary()


def test_summary_is_a_dict_that_prints_as_a_table_with_units(short_run):
    _, s = short_run
    assert isinstance(s, dict) and isinstance(s, Summary)
    assert json.loads(json.dumps(to_jsonable(s))) == json.loads(json.dumps(to_jsonable(dict(s))))
    text = str(s)
    assert repr(s) == text and "{" not in text.splitlines()[0]
    rows = {line.split()[0]: line for line in text.splitlines()}
    for key, unit in s["units"].items():
        if isinstance(s.get(key), float) and unit not in ("-", ""):
            assert f" {unit}" in rows[key], (key, rows[key])
    assert rows["cage_speed"].split()[-1] == "rad/s" and rows["q_max_inner"].split()[-1] == "N"
    assert len(text) < len(repr(dict(s)))  # a table, not the nested dict


@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")  # a 4 ms run
def test_the_command_line_prints_the_same_table(short_run, capsys):
    _, s = short_run
    assert main(["simulate", "6208", "--Fr", "3000", "--omega", "500", "--t-end", "0.004", "--dt", "5e-6"]) in (0, None)
    printed = capsys.readouterr().out.splitlines()
    # the command line adds the lubricant, traction and ring-growth rows; every row of the summary's table is there
    missing = [line for line in str(s).splitlines() if line not in printed and not line.startswith("wall_s ")]
    assert missing == []


def test_three_mass_model_parameters_print_with_units(capsys):
    assert main(["vibration", "three-dof", "6208", "--Fr", "500", "--rpm", "3000"]) in (0, None)
    rows = {line.split()[0]: line.split() for line in capsys.readouterr().out.splitlines() if line.strip()}
    assert rows["mass_ball"][-1] == "kg"
    assert rows["k_outer_contact"][-1] == "N/m"
    assert rows["c_inner_contact"][-2:] == ["N", "s/m"]
    assert rows["damping_row"][-1] == "symmetric"  # a setting: no unit
