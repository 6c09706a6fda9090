"""Summary of a run: Q_max as the largest ball load, the window (steady phase of a
protocol, named in the output), per-phase summaries, units, and runs too short to sample."""
import warnings

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing.physics.load_distribution import static_equilibrium

STEADY = dict(Fr=3000.0, omega=500.0, dt=4e-6, tangential="implicit", sample_dt=5e-5)


@pytest.fixture(scope="module")
def steady():
    return eb.simulate("6208", eb.Scenario(t_end=0.02, **STEADY))


@pytest.fixture(scope="module")
def protocol():
    # start-up 10 ms, steady 20 ms, slow-down 10 ms, 5 ms at rest; from rest, below the cage limit
    sc = eb.Scenario(Fr=3000.0, omega=500.0, t_ramp_up=0.01, t_steady=0.02, t_ramp_down=0.01, t_end=0.045,
                     initial="rest", dt=3e-6, sample_dt=5e-5, tangential="implicit")
    return eb.simulate("6208", sc)


def test_q_max_is_the_largest_ball_load_of_the_window(steady):
    # Harris / the DEM papers: Q_max is the load of the ball at psi = 0 (1462 N for the discrete
    # 6208 at 3000 N); the time mean of the per-sample maximum lies about 3 % below it
    s = steady.summary()
    w, _ = steady.summary_window()
    assert s["q_max_inner"] == steady.contact("load", "inner")[w].max()
    assert s["q_max_outer"] == steady.contact("load", "outer")[w].max()
    assert s["q_max_inner_mean"] == pytest.approx(np.mean(steady.contact("load", "inner")[w].max(axis=1)))
    q_static = static_equilibrium(steady.bearing, 3000.0).q_max
    assert s["q_max_inner"] == pytest.approx(q_static, rel=0.01)
    assert s["q_max_inner_mean"] < 0.99 * q_static < s["q_max_inner"]


def test_steady_run_summarises_its_last_quarter(steady):
    s = steady.summary()
    assert s["window"]["rule"] == "last 25 % of the run" and s["window"]["phase"] == "steady"
    assert s["window"]["t1"] == steady.t[-1] and s["window"]["t0"] == pytest.approx(0.015, abs=1e-4)
    assert "phases" not in s


# a short run: its summary window is not steady, as expected
@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")
def test_protocol_summarises_its_steady_phase_and_each_phase(protocol):
    # the old summary averaged the last quarter: the slow-down and rest (cage far below 198 rad/s)
    s = protocol.summary()
    assert s["window"]["phase"] == "steady" and s["window"]["rule"] == "second half of the steady phase"
    assert 0.02 <= s["window"]["t0"] < 0.021 and 0.0295 < s["window"]["t1"] <= 0.03
    assert s["omega"] == pytest.approx(500.0)
    assert s["cage_speed"] == pytest.approx(s["kinematic_cage_speed"], rel=5e-3)
    # the balls outside the loaded zone catch up with the ring slowly (10 ms after the ramp: 1 % behind)
    assert s["ball_spin"] == pytest.approx(s["kinematic_ball_spin"], rel=0.02)
    ph = s["phases"]
    assert list(ph) == ["start-up", "steady", "slow-down", "rest"]
    assert ph["steady"]["t0"] == 0.01 and ph["steady"]["t1"] == pytest.approx(0.03)
    assert ph["start-up"]["omega"] == pytest.approx(250.0, rel=0.02)
    assert ph["rest"]["omega"] == 0.0 and ph["rest"]["cage_speed"] < 0.2 * s["cage_speed"]
    # an explicit fraction or t_window overrides the steady phase, and says so
    last = protocol.summary(fraction=0.25)["window"]
    assert last["rule"] == "last 25 % of the run" and last["phase"] == "slow-down, rest"
    user = protocol.summary(t_window=(0.002, 0.008))["window"]
    assert user["phase"] == "start-up" and user["rule"].startswith("t_window")


def test_summary_carries_units(steady):
    s = steady.summary()
    units = s["units"]
    for key in ("q_max_inner", "q_max_inner_mean", "cage_speed", "ball_spin", "omega", "dt", "wall_s"):
        assert key in units
    assert units["cage_speed"] == units["omega"] == "rad/s" and units["q_max_inner"] == "N"


def test_saved_summary_json_has_units_and_window(steady, tmp_path):
    import json

    _npz, js = steady.save(tmp_path)
    d = json.loads(js.read_text())
    assert d["units"]["cage_speed"] == "rad/s" and d["window"]["rule"] == "last 25 % of the run"


def test_run_shorter_than_one_sample_is_refused():
    with pytest.raises(eb.InputError, match=r"^t_end: must be >= sample_dt \(0.0001 s\)"):
        eb.Scenario(Fr=3000.0, omega=500.0, t_end=5e-5, sample_dt=1e-4)
    eb.Scenario(Fr=3000.0, omega=500.0, t_end=1e-4, sample_dt=1e-4)  # one sample is enough


# a short run: its summary window is not steady, as expected
@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")
def test_fast_mode_element_counts_its_steps():
    # the fast mode's user function integrates the balls: its record counts the Exudyn steps (it reported
    # steps = 0), one per fast-mode step of sub * dt, and the summary carries the record's counts. Bookkeeping
    # only: what the run's clock reads is left to the benchmarks (validation/performance/bench_element.py)
    from exudyn_bearing.solvers.element.engine import ExudynEngine, solve_dynamic

    t_end, dt = 0.002, 2.5e-6  # two sub-steps of 2.5 us: within the fast mode's 5.7 us limit (no warning)
    for sub in (1, 2):
        eng = ExudynEngine("6208", eb.Scenario(Fr=3000.0, omega=500.0, t_end=t_end, dt=dt, tangential="implicit"), mode="fast",
                           sub_steps=sub)
        with warnings.catch_warnings():
            warnings.simplefilter("error", eb.StepSizeWarning)
            solve_dynamic(eng.mbs, eng.element.SimulationSettings(t_end))
        r = eb.Results(eng.element.record())
        assert r.steps == round(t_end / (sub * dt))
        assert r.summary()["steps"] == r.steps


def test_run_plot_masks_unloaded_balls_and_keeps_legends_off_the_data(steady, tmp_path, monkeypatch):
    # run.png drew Lambda and h_min of balls held by the centrifugal force alone (a flat band
    # at Lambda = 3.05 outside the loaded zone) and its legends covered data
    from exudyn_bearing.outputs import plotting

    figs = []
    original = plotting.save_figure

    def keep(fig, png, *args, **kw):
        # no draw of its own: the save draws the figure, and the extents below are the same after it
        # (an extra draw before the save gave the same legend and axes extents, and cost a second draw)
        figs.append(fig)
        return original(fig, png, *args, **kw)

    monkeypatch.setattr(plotting, "save_figure", keep)
    steady.plot(tmp_path / "run.png")
    fig = figs[0]
    ax = fig.axes
    mask = plotting.loaded_ball_mask(steady)
    assert 0 < mask.sum() < mask.size  # the steady 6208 has balls outside the loaded zone
    for a in ax[2:4]:
        assert len(a.collections[0].get_offsets()) == mask.sum()
    psi = np.degrees(steady.azimuth())
    assert np.all(np.abs(psi[mask]) < 100.0)  # the loaded zone of the 6208 at P_d = 0
    texts = " ".join(t.get_text() for t in ax[2].texts)
    assert "boundary | mixed" in texts and "mixed | full film" in texts
    for a in ax[:2]:
        leg, box = a.get_legend().get_window_extent(), a.get_window_extent()
        assert leg.y0 >= box.y1 - 1.0  # above the axes, not on the curves
    assert (tmp_path / "run.png").stat().st_size > 10_000
