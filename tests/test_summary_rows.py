"""Summary rows that must not mislead: the steady-state verdict at rest, the point friction model's row at the
ellipse level, and which ring each friction torque belongs to."""
import warnings

import pytest

import exudyn_bearing as eb
from exudyn_bearing.outputs.window_checks import SteadyStateWarning


@pytest.fixture(scope="module")
def at_rest():
    sc = eb.Scenario(Fr=3000.0, omega=0.0, t_end=4e-3, dt=2e-6, sample_dt=5e-5, cage="none")
    with warnings.catch_warnings():
        warnings.simplefilter("error", SteadyStateWarning)  # the settling speeds at rest are no unsteadiness
        res = eb.simulate("6208", sc)
        return res.summary()


def test_a_ring_at_rest_is_steady_although_its_speeds_are_settling_noise(at_rest):
    st = at_rest["steady"]
    assert st["steady"], st["reason"]
    # the speeds are tiny, not zero: the verdict comes from the floor, not from exact rest
    assert 0.0 < abs(at_rest["ball_spin"]) < 1.0
    assert at_rest["srr_mean"] is None  # nothing rolls: no slide-to-roll ratio of two noises


def test_the_point_friction_model_is_not_named_at_the_ellipse_level(at_rest):
    assert at_rest["friction"] == "history"  # the point level (the default) uses it
    sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=4e-4, dt=2e-6, sample_dt=1e-4, cage="none",
                     traction_level="ellipse")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        s = eb.simulate("6208", sc).summary()
    assert s["friction"].startswith("not used")


def test_each_friction_torque_says_its_ring(at_rest):
    assert "inner ring" in at_rest["units"]["friction_torque"]
    assert "driven ring" in at_rest["units"]["friction_torque_whole"]
    assert "held back" in at_rest["descriptions"]["friction_torque"]


@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")  # a 2 ms run: its window is short
def test_a_failed_energy_check_is_said_on_its_row_and_warned(monkeypatch):
    from exudyn_bearing.outputs import results as res_mod
    from exudyn_bearing.outputs.tables import summary_rows

    sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=2e-3, dt=2e-6, sample_dt=5e-5, cage="none")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        run = eb.simulate("6208", sc)
    real = res_mod.energy_check

    def failing(*args, **kwargs):  # the run's own check, with its verdict turned to a failure
        out = dict(real(*args, **kwargs))
        out.update(passed=False, residual=-0.05, statement="drive_power = ...: FAILS (residual -5 %, tolerance 1 %)")
        return out

    monkeypatch.setattr(res_mod, "energy_check", failing)
    with pytest.warns(eb.EnergyBalanceWarning, match="FAILS"):
        s = run.summary()
    row = next(r[1] for r in summary_rows(s) if r[0] == "energy_residual")
    assert "energy check FAILS" in row and "-5 %" in row
    monkeypatch.setattr(res_mod, "energy_check", real)
    with warnings.catch_warnings():
        warnings.simplefilter("error", eb.EnergyBalanceWarning)  # a passing or unjudged check does not warn
        warnings.simplefilter("ignore", SteadyStateWarning)
        s = run.summary()
    assert s["energy_check"]["passed"] is not False


@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")  # 2 ms runs: their windows are short
def test_what_is_not_modelled_follows_the_cage_and_reaches_the_table():
    from exudyn_bearing.outputs.tables import summary_rows

    def summary(**kw):
        sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=2e-3, dt=2e-6, sample_dt=5e-5, **kw)
        return eb.simulate("6208", sc).summary()

    torus, none, film = summary(cage="torus"), summary(cage="none"), summary(cage="rigid", pocket_film=True)
    assert any(x.startswith("cage pocket friction") for x in torus["not_modelled"])  # frictionless cage balls
    assert not any("cage pocket" in x for x in none["not_modelled"])                # no cage, no pocket
    assert any(x.startswith("the pockets' oil film") for x in film["losses_modelled"])
    assert any("a starved pocket" in x for x in film["not_modelled"])
    row = next(r[1] for r in summary_rows(film) if r[0] == "not_modelled")          # in the printed table too
    assert "a starved pocket" in row
