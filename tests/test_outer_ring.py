"""Outer-ring rotation in the dynamic engines (Scenario.omega_outer): the reference engine spins the outer
ring at the protocol's outer speed; the balls then orbit at the kinematic cage speed of a turning outer ring, the
drive power is the outer ring's, the energy balance closes, the quasi-static solver agrees; the Exudyn and reduced
engines refuse it by name."""
import math
import warnings

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing import InputError
from exudyn_bearing.cli import main
from exudyn_bearing.outputs import signals
from exudyn_bearing.physics import kinematics

# the settings of tests/test_reference.py's steady500: within the normal-contact limit, 40 ms at 500 rad/s
FAST = dict(Fr=3000.0, dt=4e-6, tangential="implicit", t_end=0.04, sample_dt=5e-5)
W = 500.0


@pytest.fixture(scope="module")
def runs():
    """The 6208 at 3000 N with the inner ring alone and the outer ring alone turning at 500 rad/s."""
    return {ring: eb.simulate("6208", eb.Scenario(**FAST, **kw))
            for ring, kw in (("inner", {"omega": W}), ("outer", {"omega_outer": W}))}


def test_outer_ring_alone_orbits_at_the_kinematic_cage_speed(runs):
    # omega_c = omega_i (1 - gamma)/2 + omega_o (1 + gamma)/2 (Harris & Kotzalas eq. 8.22; gamma = D/d_m at
    # alpha = 0): 301.98 rad/s with the outer ring alone; within 0.5 %, the tolerance of the inner-ring
    # test (test_reference.py::test_kinematics_at_500_rad_s: 198.0 rad/s)
    b = eb.catalog["6208"]
    s = runs["outer"].summary()
    expected = float(kinematics.cage_speed(0.0, W, b.ball_radius, b.pitch_radius))
    assert s["cage_speed"] == pytest.approx(expected, rel=5e-3)
    assert s["omega"] == 0.0 and s["omega_outer"] == pytest.approx(W, rel=1e-12)
    # the summary's kinematic references take the outer ring's speed (at the run's operating contact angle)
    assert s["kinematic_cage_speed"] == pytest.approx(expected, rel=1e-3)
    assert s["ball_spin"] == pytest.approx(float(kinematics.ball_spin_absolute(0.0, W, b.ball_radius, b.pitch_radius)),
                                           rel=5e-3)
    # the defect frequencies of the run: the cage's (FTF) and the balls' passing over the turning outer race
    # (BPFO = Z |f_c - f_o|, below the fixed-frame passing rate Z f_c)
    f = signals.run_defect_frequencies(runs["outer"])
    assert f["ftf"] == pytest.approx(expected / (2.0 * np.pi), rel=1e-3)
    assert f["bpfo"] == pytest.approx(b.n_balls * (W - expected) / (2.0 * np.pi), rel=1e-3)


def test_outer_ring_rotation_turns_the_cage_faster_in_its_direction(runs):
    # gamma > 0: (1 + gamma)/2 of the outer ring's speed against (1 - gamma)/2 of the inner ring's
    b = eb.catalog["6208"]
    gamma = b.ball_radius / b.pitch_radius
    wo, wi = runs["outer"].summary()["cage_speed"], runs["inner"].summary()["cage_speed"]
    assert wo > 0.5 * W > wi > 0.0
    assert wo / wi == pytest.approx((1.0 + gamma) / (1.0 - gamma), rel=5e-3)
    # the same direction for a reversed outer ring: the cage follows it
    r = eb.simulate("6208", eb.Scenario(**dict(FAST, t_end=0.004), omega_outer=-W))
    assert np.mean(r.cage_speed_series()[len(r.t) // 2:]) == pytest.approx(-wo, rel=0.01)


def test_outer_ring_rotation_agrees_with_the_quasistatic_solver(runs):
    # the same operating point in the quasi-static solver (race control, tilts held as in the engines): Q_max of
    # both races and the cage speed within 0.5 % (the engines' centrifugal load and outer ring growth included)
    sol = eb.solve_quasistatic("6208", Fr=3000.0, omega=0.0, omega_outer=W, fixed={"tilt_x": 0.0, "tilt_y": 0.0},
                               stiffness=False)
    s = runs["outer"].summary()
    assert s["q_max_inner"] == pytest.approx(sol.q_max_inner, rel=5e-3)
    assert s["q_max_outer"] == pytest.approx(sol.q_max_outer, rel=5e-3)
    assert s["cage_speed"] == pytest.approx(float(sol.balls["orbital_speed"][0]), rel=5e-3)
    # the outer ring's centrifugal growth loosens the bearing: Q_max above the inner-ring case's
    assert s["q_max_outer"] > runs["inner"].summary()["q_max_outer"]


def test_energy_balance_closes_with_the_outer_ring_driving():
    # ellipse level (losses converged in the step): drive power = dissipation + kinetic energy change within the
    # summary's 1 % check, as with the inner ring turning; the drive is the outer ring's torque times its speed
    out = {}
    for ring, kw in (("inner", {"omega": W}), ("outer", {"omega_outer": W})):
        sc = eb.Scenario(Fr=3000.0, t_end=0.02, dt=1.25e-6, sample_dt=5e-4, cage="none", traction_level="ellipse",
                         **kw)  # dt within the stable step of the regularised traction (1.47 us)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", eb.SteadyStateWarning)  # 20 ms: the ellipse level's slow transient
            run = eb.simulate("6208", sc)
            out[ring] = (run, run.summary())
    run, s = out["outer"]
    assert s["drive_power"] > 1.0
    assert s["energy_check"]["passed"] and abs(s["energy_residual"]) < 0.01
    w = run.summary_window()[0]
    outer_drive = -float(np.mean(run.global_series("outer_torque")[w])) * W
    assert outer_drive == pytest.approx(s["drive_power"], rel=0.02)
    # the inner ring does not turn: its torque drives nothing, and it is held against the balls' drag
    assert float(np.max(np.abs(run.global_series("omega")))) == 0.0
    assert s["friction_torque"] < 0.0 < out["inner"][1]["friction_torque"]
    # same loss scale as the inner ring driving at the same speed (the same rolling speeds at the contacts)
    assert s["drive_power"] == pytest.approx(out["inner"][1]["drive_power"], rel=0.1)


def test_omega_outer_follows_the_speed_protocol():
    sc = eb.Scenario(omega=100.0, omega_outer=-300.0, t_ramp_up=0.01, t_steady=0.02, t_ramp_down=0.01)
    for t, factor in ((0.0, 0.0), (0.005, 0.5), (0.02, 1.0), (0.035, 0.5), (0.05, 0.0)):
        assert sc.omega_outer_at(t) == pytest.approx(-300.0 * factor, abs=1e-12)
        assert sc.omega_at(t) == pytest.approx(100.0 * factor, abs=1e-12)


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), "500", True])
def test_scenario_refuses_a_bad_omega_outer_by_name(bad):
    with pytest.raises(InputError, match="omega_outer"):
        eb.Scenario(omega_outer=bad)


def test_engines_without_the_outer_ring_refuse_it_by_name():
    sc = eb.Scenario(Fr=3000.0, omega_outer=W, cage="none", traction_level="ellipse", dt=2e-5, t_end=0.001)
    with pytest.raises(InputError, match=r"^omega_outer: the reduced engine .*reference"):
        eb.simulate("6208", sc, engine="reduced")
    from exudyn_bearing.solvers.reduced import ReducedEngine

    with pytest.raises(InputError, match=r"^omega_outer: the reduced engine"):
        ReducedEngine("6208", sc)
    pytest.importorskip("exudyn")
    from exudyn_bearing.solvers.element.engine import ExudynEngine

    sc = sc.replace(traction_level="point", dt=1e-6)
    with pytest.raises(InputError, match=r"^omega_outer: the exudyn engine .*reference"):
        eb.simulate("6208", sc, engine="exudyn")
    with pytest.raises(InputError, match=r"^omega_outer: the exudyn engine"):
        ExudynEngine("6208", sc)
    # a fixed outer ring (the default) passes the check in every engine
    assert eb.Scenario().omega_outer == 0.0


def test_simulate_cli_takes_the_outer_ring_speed(capsys):
    import json

    args = ["simulate", "6208", "--Fr", "3000", "--omega", "0", "--rpm-outer", "-3000", "--t-end", "0.004",
            "--dt", "4e-6", "--tangential", "implicit", "--json", "--no-progress"]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        assert main(args) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["omega_outer"] == pytest.approx(-3000.0 * np.pi / 30.0, rel=1e-9)
    assert d["units"]["omega_outer"] == "rad/s"
    assert d["cage_speed"] < 0.0  # the cage follows the outer ring backwards


def test_an_outer_race_spall_turns_with_the_outer_ring():
    # the settings of test_defects.py::test_defect_impacts_where_the_kinematics_put_them (the 6205, 1000 N, 1797 rpm,
    # 5 steps per 48 kHz sample) with the outer ring turning instead of the inner one: the spall turns with the
    # ring (the protocol's spin angle), so the balls drop into it where psi - omega_o t = its position, and they
    # meet it at BPFO = Z |f_c - f_o| (107.4 Hz), not at the fixed race's passing rate Z f_c (162.2 Hz)
    from exudyn_bearing.data import Defect

    b = eb.catalog["6205"]
    w, fs = 1797.0 * np.pi / 30.0, 48000.0
    sc = eb.Scenario(Fr=1000.0, omega=0.0, omega_outer=w, t_end=0.06, dt=1 / fs / 5, sample_dt=1 / fs / 5,
                     tangential="implicit", defects=(Defect("outer", 0.3, 1e-3, 1.5e-3, 1e-4),))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the cage loads chatter at this step (StepSizeWarning), not asserted
        r = eb.simulate("6205", sc)
    hit = r.contact("defect_drop", "outer") > 0.0
    rel = (r.azimuth() - w * r.t[:, None] - 0.3 + np.pi) % (2.0 * np.pi) - np.pi
    assert hit.sum() > 0 and np.all(np.abs(rel[hit]) <= 0.5e-3 / b.outer_race_radius + 1e-3)
    d = r.contact("defect_drop", "outer") > 0.0
    onsets = np.sort(np.concatenate([r.t[1:][d[1:, j] & ~d[:-1, j]] for j in range(b.n_balls)]))
    f = kinematics.defect_frequencies(0.0, w, b.n_balls, b.ball_radius, b.pitch_radius, 0.0)
    assert len(onsets) >= 4
    assert np.median(np.diff(onsets)) == pytest.approx(1.0 / f["bpfo"], rel=0.01)


@pytest.mark.filterwarnings("ignore::exudyn_bearing.StepSizeWarning")  # as the inner-ring protocol test
@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")  # the unloaded balls still catching up
@pytest.mark.filterwarnings("ignore::exudyn_bearing.EnergyBalanceWarning")  # a window over the stop: not steady
def test_outer_ring_start_up_and_full_stop_from_rest():
    # test_reference.py::test_start_up_and_full_stop_from_rest with the outer ring turning: 0 -> 500 rad/s,
    # hold, ramp to 0 under the same ramp factor (Scenario.omega_outer_at)
    b = eb.catalog["6208"]
    sc = eb.Scenario(Fr=3000.0, omega_outer=W, t_ramp_up=0.01, t_steady=0.01, t_ramp_down=0.01, t_end=0.032,
                     initial="rest", sample_dt=1e-4, dt=4e-6, tangential="implicit")
    assert [sc.omega_outer_at(t) for t in (0.005, 0.015, 0.025, 0.031)] == pytest.approx([0.5 * W, W, 0.5 * W, 0.0])
    r = eb.simulate("6208", sc)
    assert np.all(np.isfinite(r.data["wb"]))
    spin = r.ball_spin_series()
    # the loaded balls roll with the outer ring at the end of the steady phase: the kinematic absolute spin
    k = np.argmin(np.abs(r.t - 0.02))
    loaded = r.contact("load", "inner")[k] > 0
    np.testing.assert_allclose(spin[k][loaded], float(kinematics.ball_spin_absolute(0.0, W, b.ball_radius,
                                                                                    b.pitch_radius)), rtol=0.01)
    # after the stop the balls held by the load (above 50 N: not a ball grazing the load zone's edge, which the
    # stopped balls no longer carry through it) come to rest with the ring
    held = r.contact("load", "inner")[-1] > 50.0
    assert held.sum() >= 2
    assert np.all(spin[-1][held] < 0.05 * spin[k].mean())
    # the phases' outer-ring speed: the summary's mean over the steady phase's second half
    assert r.summary(t_window=(0.015, 0.02))["omega_outer"] == pytest.approx(W, rel=1e-12)


def test_quasistatic_takes_the_outer_speed_in_rpm_as_simulate_does(capsys):
    # one pair of options for the outer ring's speed on both commands (cli.common.add_outer_speed_arguments)
    import json
    import math

    from exudyn_bearing.cli import main

    out = []
    for flag, value in (("--omega-outer", "300"), ("--rpm-outer", repr(300.0 * 30.0 / math.pi))):
        assert main(["quasistatic", "6208", "--Fr", "3000", "--omega", "0", flag, value, "--json"]) == 0
        out.append(json.loads(capsys.readouterr().out))
    assert out[0]["omega_outer"] == pytest.approx(300.0, rel=1e-12)
    assert out[1]["omega_outer"] == pytest.approx(out[0]["omega_outer"], rel=1e-12)
    with pytest.raises(SystemExit) as exc:  # argparse: the two are exclusive
        main(["quasistatic", "6208", "--Fr", "3000", "--omega-outer", "1", "--rpm-outer", "1"])
    assert exc.value.code == 2


def test_info_takes_the_outer_ring_speed(capsys):
    # the defect frequencies depend on the rings' relative speed: the same with either ring turning; the cage
    # frequency is f_o (1 + gamma) / 2 with the outer ring turning against f_i (1 - gamma) / 2 with the inner
    import json

    from exudyn_bearing.cli import main

    out = {}
    for name, args in (("inner", ["--rpm", "1797"]), ("outer", ["--rpm", "0", "--rpm-outer", "1797"])):
        assert main(["info", "6205", *args, "--json"]) == 0
        out[name] = json.loads(capsys.readouterr().out)
    for k in ("bpfo", "bpfi", "bsf"):
        assert out["outer"][k] == pytest.approx(out["inner"][k], rel=1e-12), k
    f = 1797.0 / 60.0
    b = eb.catalog["6205"]
    gamma = 2.0 * b.ball_radius * math.cos(b.free_contact_angle) / (2.0 * b.pitch_radius)
    assert out["inner"]["ftf"] == pytest.approx(f * (1.0 - gamma) / 2.0, rel=1e-12)
    assert out["outer"]["ftf"] == pytest.approx(f * (1.0 + gamma) / 2.0, rel=1e-12)
    assert main(["info", "6205", "--rpm-outer", "1797"]) == 2   # the inner ring's speed is needed too
