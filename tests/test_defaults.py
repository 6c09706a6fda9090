"""One set of defaults (docs/defaults.md, exudyn_bearing.defaults): the generated table is current, no two
entry points default one quantity differently without a documented reason, and the rules of issue 36:
loads and speeds zero, tilt held, simulate refuses a missing speed, dataset takes its bearing first."""
from pathlib import Path

import pytest

import exudyn_bearing as eb
from exudyn_bearing import defaults
from exudyn_bearing.cli import main

ROOT = Path(__file__).resolve().parent.parent


def test_committed_defaults_table_is_current():
    text = (ROOT / "docs" / "defaults.md").read_text()
    assert text == defaults.render(), "docs/defaults.md is stale: run python -m exudyn_bearing.defaults"


def test_no_quantity_has_two_defaults_without_a_reason():
    assert defaults.conflicts() == []


def test_the_conflict_check_sees_a_difference(monkeypatch):
    # a planted difference (Scenario's Fr at 3000 N, the old default) is reported
    real = defaults.collect

    def planted():
        out = real()
        out["Scenario"] = dict(out["Scenario"], Fr=3000.0)
        return out

    monkeypatch.setattr(defaults, "collect", planted)
    assert any(line.startswith("Fr:") for line in defaults.conflicts())


def test_loads_and_speeds_default_to_zero_and_tilt_is_held():
    sc = eb.Scenario()
    assert sc.Fr == sc.Fa == sc.omega == 0.0
    q = defaults.quantities()
    for name in ("Fr", "Fa", "omega"):
        vals = {v for e, (_, v) in q[name].items() if v not in (None, "(required)") and "dataset" not in e}
        assert vals == {0.0}, (name, q[name])
    s = eb.solve_quasistatic("7208", Fr=3000.0, Fa=3000.0, omega=500.0, stiffness=False)  # refused tilt-free
    assert set(s.held) >= {"tilt_x", "tilt_y"} and s.held["tilt_x"] == "fixed"
    with pytest.raises(eb.InputError, match="^Mx: a moment load needs the free tilt"):
        eb.solve_quasistatic("6208", Fr=3000.0, Mx=1.0, stiffness=False)


def test_simulate_cli_refuses_a_missing_speed(capsys):
    assert main(["simulate", "6208", "--Fr", "3000", "--t-end", "0.001"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("exudyn-bearing: error: omega: simulate needs a speed") and "--omega" in err


def test_dataset_takes_the_bearing_first_and_the_old_order_with_a_note():
    from exudyn_bearing.cli import _parser
    from exudyn_bearing.cli.dataset import bearing_and_out

    assert bearing_and_out(_parser().parse_args(["dataset", "6208", "out"])) == ("6208", "out")
    for argv in (["dataset", "out"], ["dataset", "out", "6205"]):
        assert bearing_and_out(_parser().parse_args(argv)) == ("6205", "out")
