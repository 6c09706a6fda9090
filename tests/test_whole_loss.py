"""The whole loss of a dynamic run (outputs.whole_loss): the modelled components plus a labelled
quasi-static estimate of each loss the run leaves out; power_loss_total stays the modelled sum."""
import warnings

import pytest

import exudyn_bearing as eb
from exudyn_bearing.solvers.quasistatic.losses import power_losses

OMEGA = 500.0


@pytest.fixture(scope="module")
def point_run():
    sc = eb.Scenario(Fr=3000.0, omega=OMEGA, t_end=0.004, dt=2e-6, sample_dt=1e-4)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        run = eb.simulate("6208", sc)
        return run, run.summary(fraction=0.5)


def test_point_level_whole_loss_is_near_the_quasistatic_total(point_run):
    _run, s = point_run
    # the point level models almost nothing of the rolling losses: its modelled total is far below
    sol = eb.solve_quasistatic("6208", Fr=3000.0, omega=s["omega"], fixed={"tilt_x": 0.0, "tilt_y": 0.0})
    qs = power_losses(sol)
    assert s["power_loss_total"] < 0.1 * qs["power_loss_total"]
    # the whole loss: modelled + estimated, within 10 % of the quasi-static total at the same point (the
    # run's contact damping and its small traction stand beside the quasi-static traction)
    assert s["power_loss_whole"] == pytest.approx(s["power_loss_total"] + sum(s["power_loss_estimated"].values()))
    assert s["power_loss_whole"] == pytest.approx(qs["power_loss_total"], rel=0.10)
    assert s["friction_torque_whole"] == pytest.approx(s["power_loss_whole"] / s["omega"])
    assert s["friction_torque_whole"] == pytest.approx(qs["friction_torque_total"], rel=0.10)
    basis = s["power_loss_whole_basis"]
    assert {"traction_rolling", "ehl_rolling", "hysteresis", "drag", "cage_pocket"} <= set(basis["estimated"])
    assert "contact_damping" in basis["modelled"] and basis["operating_point"]["Fr"] == 3000.0
    assert "whole loss is power_loss_whole" in s["descriptions"]["power_loss_total"]
    # the energy check stays on the modelled components
    assert s["energy_check"]["power_loss_total"] == s["power_loss_total"]


def test_cli_table_prints_the_whole_loss_first(point_run):
    from exudyn_bearing.outputs.tables import summary_rows  # the command line's table (cli.simulate)

    _run, s = point_run
    names = [r[0] for r in summary_rows(s)]
    assert names.index("power_loss_whole") < names.index("power_loss_whole_basis") < names.index("power_loss_total")
    assert names.index("power_loss_whole") < names.index("q_max_inner")


def test_switched_on_losses_are_not_estimated_again(point_run):
    from exudyn_bearing.outputs.whole_loss import whole_loss

    run, _s = point_run
    run.scenario = run.scenario.replace(rolling_resistance=True, ball_drag=True, traction_level="ellipse")
    try:
        out = whole_loss(run, {"contact_traction_inner": 1.0}, 1.0, OMEGA)
    finally:
        run.scenario = run.scenario.replace(rolling_resistance=False, ball_drag=False, traction_level="point")
    assert set(out["power_loss_estimated"]) == {"cage_pocket", "cage_land"}


def test_quasistatic_json_friction_torque_is_the_total_the_text_prints():
    # under a kinematic hypothesis the traction's drive torque holds the hypothesis' residual: the JSON key
    # is the whole modelled loss over the speed, as the text output prints (cli/quasistatic.py)
    sol = eb.solve_quasistatic("6208", Fa=3000.0, omega=OMEGA, control="auto", fixed={"tilt_x": 0.0, "tilt_y": 0.0},
                               stiffness=False)
    d = sol.to_dict()
    assert d["friction_torque"] == d["friction_torque_total"] == pytest.approx(d["power_loss_total"] / OMEGA)
    assert d["traction_drive_torque"] == sol.friction_torque
    assert sol.energy_residual > 0.5 and d["traction_drive_torque"] > 5.0 * d["friction_torque"]
