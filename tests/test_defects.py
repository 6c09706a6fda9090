"""Localized defects, condition-monitoring signals, their processing and the dataset generator (issue #13)."""
import json
import math
import os
import warnings
from pathlib import Path

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing.data import Defect, InputError
from exudyn_bearing.datasets import build_dataset, fault_defects, load_case_signals, read_index, signal_scenario
from exudyn_bearing.model import layout as L
from exudyn_bearing.model.initial_state import ring_mass_estimate
from exudyn_bearing.model.motion import omega_profile, rotate_frame, spin_angle
from exudyn_bearing.model.parameters import scene_parameters
from exudyn_bearing.outputs import signals as S
from exudyn_bearing.outputs.results import Results
from exudyn_bearing.physics import kinematics
from exudyn_bearing.physics.defects import edge_drop, max_spall_drop, spall_drop
from exudyn_bearing.physics.geometry import raceway_radii

from conftest import manual_text

ROOT = Path(__file__).resolve().parents[1]
W1797 = 1797.0 * math.pi / 30.0


def _quiet(fn, *a, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.StepSizeWarning)
        return fn(*a, **kw)


# -- the 6205 and its defect frequencies -------------------------------------------------------------
def test_6205_defect_frequencies_match_the_cwru_rig():
    # CWRU bearing data centre, drive-end 6205-2RS JEM: defect frequencies in multiples of the shaft
    # speed BPFI 5.4152, BPFO 3.5848, FTF 0.39828, BSF 4.7135 (their BSF is twice the ball spin: 2 BSF)
    b = eb.catalog["6205"]
    assert (b.n_balls, b.ball_diameter, b.pitch_diameter) == (9, pytest.approx(7.94e-3), pytest.approx(39.04e-3))
    f = kinematics.defect_frequencies(2 * math.pi, 0.0, b.n_balls, b.ball_radius, b.pitch_radius, 0.0)
    assert f["bpfi"] == pytest.approx(5.4152, abs=1e-4)
    assert f["bpfo"] == pytest.approx(3.5848, abs=1e-4)
    assert f["ftf"] == pytest.approx(0.39828, abs=1e-4)
    assert 2 * f["bsf"] == pytest.approx(4.7135, abs=1e-4)


# -- defect data -------------------------------------------------------------------------------------
@pytest.mark.parametrize("kw, field", [
    (dict(race="cage"), "race"),
    (dict(position=math.nan), "position"),
    (dict(length=0.0), "length"),
    (dict(width=-1e-3), "width"),
    (dict(depth=0.0), "depth"),
    (dict(edge="chamfer"), "edge"),
    (dict(edge_radius=1e-5), "edge_radius"),                     # sharp edge with a radius
    (dict(edge="rounded"), "edge_radius"),                       # rounded without a radius
    (dict(edge="rounded", edge_radius=2e-4), "edge_radius"),     # larger than the depth
    (dict(ball=1), "ball"),                                      # ball index on a race defect
    (dict(race="ball", ball=-1), "ball"),
    (dict(race="ball", ball=1.5), "ball"),
])
def test_defect_rejects_impossible_values_naming_the_field(kw, field):
    base = dict(race="outer", position=0.0, length=1e-3, width=1e-3, depth=1e-4)
    with pytest.raises(InputError, match=f"^{field}:"):
        Defect(**{**base, **kw})


@pytest.mark.parametrize("kw, field", [
    (dict(depth=2.1e-3), "depth"),                         # 0.25 D = 1.985 mm for the 6205
    (dict(length=2 * math.pi * 23.49e-3), "length"),       # the whole outer race
    (dict(width=9.0e-3), "width"),                         # wider than the groove between its shoulders
    (dict(race="ball", ball=9), "ball"),                   # the 6205 has balls 0..8
    (dict(race="ball", length=13e-3), "length"),           # more than half the ball's circumference
])
def test_defect_checked_against_the_bearing(kw, field):
    d = Defect(**{**dict(race="outer", position=0.0, length=1e-3, width=1e-3, depth=1e-4), **kw})
    with pytest.raises(InputError, match=f"^{field}:"):
        d.check(eb.catalog["6205"])
    with pytest.raises(InputError, match=f"^{field}:"):
        eb.simulate("6205", eb.Scenario(Fr=3000.0, omega=500.0, defects=(d,), t_end=1e-5, dt=5e-6, sample_dt=1e-5))


def test_scenario_defect_and_signal_inputs():
    d = dict(race="outer", position=0.0, length=1e-3, width=1e-3, depth=1e-4)
    assert eb.Scenario(Fr=3000.0, omega=500.0, defects=[d]).defects == (Defect(**d),)
    with pytest.raises(InputError, match="^defects:"):
        eb.Scenario(Fr=3000.0, omega=500.0, defects=[d] * (L.MAX_DEFECTS + 1))
    with pytest.raises(InputError, match="^color:"):
        eb.Scenario(Fr=3000.0, omega=500.0, defects=[dict(d, color="red")])
    with pytest.raises(InputError, match="^depth:"):
        eb.Scenario(Fr=3000.0, omega=500.0, defects=[{k: v for k, v in d.items() if k != "depth"}])
    with pytest.raises(InputError, match="^integrator:"):
        eb.Scenario(Fr=3000.0, omega=500.0, defects=[dict(d, race="ball")], integrator="rk4", friction="regularized")
    with pytest.raises(InputError, match="^signal_dt:.*integer multiple"):
        eb.Scenario(Fr=3000.0, omega=500.0, dt=5e-6, signal_dt=1.2e-5)
    with pytest.raises(InputError, match="^signal_dt:"):
        eb.Scenario(Fr=3000.0, omega=500.0, dt=5e-6, signal_dt=2e-5, integrator="rk4", friction="regularized")
    assert eb.Scenario(Fr=3000.0, omega=500.0, dt=1 / 48000 / 4, signal_dt=1 / 48000).signal_every == 4


def test_parameter_slots_and_ball_defect_direction():
    b = eb.catalog["6205"]
    sc = eb.Scenario(Fr=3000.0, omega=500.0, defects=(Defect("inner", 1.0, 1e-3, 2e-3, 1e-4, edge="rounded", edge_radius=5e-5),
                              Defect("ball", 0.5 * math.pi, 1e-3, 1e-3, 1e-4, ball=3)))
    p = scene_parameters(b, sc, eb.lubricants["guessasma2018"])
    assert p[L.P_NDEF] == 2
    s0, s1 = L.P_DEF0, L.P_DEF0 + L.DEF_N
    assert (p[s0 + L.DF_RACE], p[s0 + L.DF_POS], p[s0 + L.DF_HW], p[s0 + L.DF_EDGE]) == (L.DEF_INNER, 1.0, 1e-3, 5e-5)
    # ball 3 sits at azimuth 2 pi 3/9; position pi/2 on its rolling circle: the orbital direction
    psi = 2 * math.pi * 3 / 9
    np.testing.assert_allclose(p[s1 + L.DF_DIR:s1 + L.DF_DIR + 3], [-math.sin(psi), math.cos(psi), 0.0], atol=1e-15)
    assert L.describe_parameters(p)["defect1_ball"] == (3.0, "-")


# -- the profile relation ----------------------------------------------------------------------------
def test_spall_drop_limits():
    rx, ry = raceway_radii(3.97e-3, 4.1288e-3, 23.49e-3, 0.0, False)
    hl, hw = 0.5e-3, 6e-3
    # a short, wide, deep spall: the ball rests on the entry and exit edges, R_x - sqrt(R_x^2 - (L/2)^2)
    assert spall_drop(0.0, 0.0, hl, hw, 1e-3, 0.0, rx, ry) == pytest.approx(rx - math.sqrt(rx * rx - hl * hl),
                                                                               rel=1e-12)
    # shallow: the floor
    assert spall_drop(0.0, 0.0, hl, hw, 1e-6, 0.0, rx, ry) == 1e-6
    # narrow: the side edges across the rolling direction (R_y) hold it
    assert spall_drop(0.0, 0.0, 5e-3, 0.2e-3, 1e-3, 0.0, rx, ry) == pytest.approx(float(edge_drop(0.2e-3, ry)))
    # nothing outside the pit, 0 on its rim, symmetric entry and exit
    for s, w in ((hl, 0.0), (-hl, 0.0), (0.0, hw), (2 * hl, 0.0)):
        assert spall_drop(s, w, hl, hw, 1e-3, 0.0, rx, ry) == 0.0
    s = np.linspace(-hl, hl, 41)
    e = spall_drop(s, 0.0, hl, hw, 1e-3, 0.0, rx, ry)
    np.testing.assert_allclose(e, e[::-1], rtol=1e-12)
    assert np.all(np.diff(e[:21]) > 0) and np.all(np.diff(e[20:]) < 0)
    # a rounded edge lets the ball down more gently: less drop everywhere inside the pit
    er = spall_drop(s[1:-1], 0.0, hl, hw, 1e-3, 1e-4, rx, ry)
    assert np.all(er < e[1:-1])
    assert max_spall_drop(2 * hl, 2 * hw, 1e-3, 0.0, rx, ry) == pytest.approx(e[20])


def test_spin_angle_is_the_integral_of_the_protocol():
    args = (500.0, 0.02, 0.05, 0.03)
    t = np.linspace(0.0, 0.12, 120001)
    w = np.array([omega_profile(x, *args) for x in t])
    integral = np.concatenate([[0.0], np.cumsum(0.5 * (w[1:] + w[:-1]) * np.diff(t))])
    got = np.array([spin_angle(x, *args) for x in t])
    np.testing.assert_allclose(got, integral, atol=1e-6)


def test_ball_frame_turns_exactly_and_stays_orthonormal():
    frames = np.zeros((1, 4, 3))
    frames[0, 2], frames[0, 3] = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)
    w = np.array([300.0, -200.0, 900.0])
    dt, n = 5e-6, 20000
    step = rotate_frame.py_func if hasattr(rotate_frame, "py_func") else rotate_frame
    for _ in range(n):
        step(frames, frames, 0, 2, 3, *w, dt)
    # exact rotation by |w| n dt about w (Rodrigues)
    k = w / np.linalg.norm(w)
    phi = np.linalg.norm(w) * n * dt
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    rot = np.eye(3) + math.sin(phi) * kx + (1 - math.cos(phi)) * kx @ kx
    np.testing.assert_allclose(frames[0, 2], rot[:, 0], atol=1e-9)
    np.testing.assert_allclose(frames[0, 3], rot[:, 1], atol=1e-9)
    assert abs(frames[0, 2] @ frames[0, 3]) < 1e-14


# -- no defect, no change ----------------------------------------------------------------------------
def test_a_defect_no_ball_reaches_and_signals_leave_the_run_unchanged():
    # the defect code path must not perturb a scene: a spall in the unloaded half of the outer race
    # (P_d = 0: no ball touches it there) and the signal recording leave every sampled array equal
    sc = eb.Scenario(Fr=1000.0, omega=W1797, t_end=0.004, dt=5e-6, sample_dt=5e-5, tangential="implicit")
    base = _quiet(eb.simulate, "6205", sc)
    far = _quiet(eb.simulate, "6205", sc.replace(defects=(Defect("outer", math.pi, 1e-3, 1.5e-3, 1e-4),),
                                                 signal_dt=2e-5))
    for k in base.data:
        np.testing.assert_array_equal(base.data[k], far.data[k], err_msg=k)
    assert np.all(far.contact("defect_drop", "outer") == 0.0)


# -- signals -----------------------------------------------------------------------------------------
def test_signals_are_interval_means_of_the_step_values():
    # sampling every step, the signal rows must be the means of the four steps' housing force and ring
    # force / mass; over the run the housing carries the applied load and the ring does not accelerate
    dt = 5e-6
    sc = eb.Scenario(Fr=1000.0, omega=W1797, t_end=0.01, dt=dt, sample_dt=dt, signal_dt=4 * dt,
                     tangential="implicit", defects=fault_defects("outer"))
    r = _quiet(eb.simulate, "6205", sc)
    np.testing.assert_allclose(r.signal_t, 4 * dt * np.arange(1, len(r.signal_t) + 1), rtol=1e-12)
    fx = r.global_series("outer_fx").reshape(-1, 4).mean(axis=1)
    np.testing.assert_allclose(r.signal("outer_fx"), fx, rtol=1e-12)
    m = ring_mass_estimate(r.bearing)
    ax = ((1000.0 + r.global_series("ring_fx")) / m).reshape(-1, 4).mean(axis=1)
    np.testing.assert_allclose(r.signal("inner_ax"), ax, rtol=1e-9, atol=1e-9 * np.abs(ax).max())
    assert np.all(r.signal("omega") == pytest.approx(W1797))
    assert np.mean(r.signal("outer_fx")) == pytest.approx(1000.0, rel=0.01)


def test_signals_and_defects_survive_save_and_load(tmp_path):
    sc = signal_scenario("inner", t_end=0.003, fs=48000.0)
    r = _quiet(eb.simulate, "6205", sc)
    npz, _ = r.save(tmp_path)
    back = Results.load(npz)
    assert back.scenario == r.scenario and back.scenario.defects[0].race == "inner"
    np.testing.assert_array_equal(back.signal("inner_ax"), r.signal("inner_ax"))
    with np.load(npz) as f:
        assert list(f["signal_fields"]) == list(L.SIGNAL_FIELDS)


# -- impacts at the right places, both engines ------------------------------------------------------
def _drop_onsets(res, race, ball):
    d = res.contact("defect_drop", race)[:, ball] > 0.0
    return res.t[1:][d[1:] & ~d[:-1]]


def test_defect_impacts_where_the_kinematics_put_them():
    b = eb.catalog["6205"]
    fs = 48000.0
    # 5 steps per 48 kHz sample (4.17 us), a fifth below the balls' stable step: the impact times are ball
    # kinematics; the cage loads, which chatter at this step (StepSizeWarning, silenced), are not asserted
    kw = dict(Fr=1000.0, omega=W1797, t_end=0.06, dt=1 / fs / 5, sample_dt=1 / fs / 5, tangential="implicit")
    f = kinematics.defect_frequencies(W1797, 0.0, 9, b.ball_radius, b.pitch_radius, 0.0)
    # outer race, position 0.3 rad: a ball enters the spall when its azimuth reaches 0.3 - L/(2 r_o)
    ro = _quiet(eb.simulate, "6205", eb.Scenario(defects=(Defect("outer", 0.3, 1e-3, 1.5e-3, 1e-4),), **kw))
    hit = ro.contact("defect_drop", "outer") > 0
    psi = ro.azimuth()
    assert np.all(np.abs(psi[hit] - 0.3) <= 0.5e-3 / b.outer_race_radius + 1e-3)
    onsets = np.sort(np.concatenate([_drop_onsets(ro, "outer", j) for j in range(9)]))
    assert np.median(np.diff(onsets)) == pytest.approx(1.0 / f["bpfo"], rel=0.01)
    # inner race: the spall turns with the ring (closed-form spin angle); hits where psi - omega t = position
    ri = _quiet(eb.simulate, "6205", eb.Scenario(defects=(Defect("inner", 0.0, 1e-3, 1.5e-3, 1e-4),), **kw))
    hit = ri.contact("defect_drop", "inner") > 0
    rel = (ri.azimuth() - W1797 * ri.t[:, None] + math.pi) % (2 * math.pi) - math.pi
    assert hit.sum() > 0 and np.all(np.abs(rel[hit]) <= 0.5e-3 / b.inner_race_radius + 1e-3)
    # ball: the spall meets the outer race once per ball revolution (relative to the cage, 1/BSF), and
    # the inner race half a revolution later (only in the load zone: elsewhere the inner contact is open)
    rb = _quiet(eb.simulate, "6205", eb.Scenario(defects=fault_defects("ball"), **kw))
    t_o, t_i = _drop_onsets(rb, "outer", 0), _drop_onsets(rb, "inner", 0)
    assert len(t_o) >= 3 and len(t_i) >= 1
    np.testing.assert_allclose(np.diff(t_o), 1.0 / f["bsf"], rtol=0.02)
    for ti in t_i:
        before = t_o[t_o < ti].max()
        assert ti - before == pytest.approx(0.5 / f["bsf"], rel=0.03)


@pytest.mark.parametrize("fault, mode", [("inner", "bodies"), ("ball", "bodies"), ("ball", "fast")])
def test_element_sees_the_same_defect_impacts(fault, mode):
    # the Exudyn element (mass-point inner ring with the prescribed spin; balls as Exudyn nodes, or
    # integrated inside the element in the fast mode) on the same scene: the spall passages start at the
    # same steps and the signals agree
    from exudyn_bearing.solvers.element.engine import ExudynEngine

    fs = 48000.0
    sc = eb.Scenario(Fr=1000.0, omega=W1797, t_end=0.02, dt=1 / fs / 4, sample_dt=1 / fs / 4, signal_dt=1 / fs,
                     tangential="implicit", defects=fault_defects(fault))
    ref = _quiet(eb.simulate, "6205", sc)
    exu = Results(_quiet(ExudynEngine("6205", sc, mode=mode).run))
    for race in ("inner", "outer"):
        for j in range(9):
            a, b_ = _drop_onsets(ref, race, j), _drop_onsets(exu, race, j)
            assert len(a) == len(b_)
            np.testing.assert_allclose(a, b_, atol=1.01 * sc.dt)
    assert any(len(_drop_onsets(ref, race, j)) for race in ("inner", "outer") for j in range(9))
    n = len(exu.signal_t)  # the element's last window closes one evaluation after the end
    assert n == len(ref.signal_t) - 1
    np.testing.assert_allclose(exu.signal_t, ref.signal_t[:n], rtol=1e-12)
    # within 1 % of the range over the first 10 ms (measured 0.1 %); later the impacts amplify the engines'
    # small differences (the ball bounces: a 1e-12 change of the load grows 1e4-fold in the reference
    # engine between 10 and 20 ms), so over the whole run the rms difference only stays below 10 % of the
    # signal's standard deviation (measured 6 %)
    early = exu.signal_t <= 0.01
    for name in ("outer_fx", "inner_ax"):
        x, y = ref.signal(name)[:n], exu.signal(name)[:n]
        assert np.max(np.abs(x - y)[early]) < 0.01 * np.ptp(x), name
        assert np.sqrt(np.mean((x - y) ** 2)) < 0.1 * np.std(x), name


def test_element_signal_inputs():
    import exudyn as exu
    from exudyn.utilities import MarkerBodyRigid, MarkerNodePosition, NodePoint, ObjectGround, ObjectMassPoint

    def element(**kw):
        mbs = exu.SystemContainer().AddSystem()
        node = mbs.AddNode(NodePoint(referenceCoordinates=[0.0, 0.0, 0.0]))
        mbs.AddObject(ObjectMassPoint(mass=0.02, nodeNumber=node))
        m_in = mbs.AddMarker(MarkerNodePosition(nodeNumber=node))
        m_out = mbs.AddMarker(MarkerBodyRigid(bodyNumber=mbs.AddObject(ObjectGround()), localPosition=[0, 0, 0]))
        return eb.CreateBallBearing(mbs, "6205", m_in, m_out, stepSize=5e-6, innerRingSpeed=lambda t: 100.0,
                                    initialOmega=100.0, **kw)

    with pytest.raises(InputError, match="^signalInterval:.*integer multiple"):
        element(signalInterval=1.2e-5)
    with pytest.raises(InputError, match="^signalInterval:.*Exudyn step"):
        element(signalInterval=1.5e-5, mode="fast", subSteps=2)
    for kw in (dict(signalInterval=2e-5, defects=fault_defects("inner")), dict(defects=fault_defects("ball"))):
        with pytest.raises(InputError, match="^solverType:"):
            element(**kw).SimulationSettings(0.01, solverType="RK44")


def test_inner_race_spall_turns_with_a_rigid_shaft():
    # the README's rigid shaft (Lie-group node) on a 6208 element with an inner-race spall: the ring frame
    # is the body's, so the balls meet the spall where their azimuth equals the shaft's turned angle
    import exudyn as exu
    from exudyn.utilities import InertiaCylinder, LoadForceVector, MarkerBodyRigid, ObjectGround

    from exudyn_bearing.solvers.element.engine import solve_dynamic

    sc_ = exu.SystemContainer()
    mbs = sc_.AddSystem()
    shaft = mbs.CreateRigidBody(inertia=InertiaCylinder(7850.0, 0.25, 0.02, axis=2),
                                nodeType=exu.NodeType.RotationRotationVector, initialAngularVelocity=[0, 0, 500.0])
    m_shaft = mbs.AddMarker(MarkerBodyRigid(bodyNumber=shaft, localPosition=[0, 0, 0]))
    m_house = mbs.AddMarker(MarkerBodyRigid(bodyNumber=mbs.AddObject(ObjectGround()), localPosition=[0, 0, 0]))
    mbs.AddLoad(LoadForceVector(markerNumber=m_shaft, loadVector=[3000.0, 0, 0]))
    spall = Defect("inner", 0.0, 1e-3, 2e-3, 1e-4)
    bearing = eb.CreateBallBearing(mbs, "6208", markerInnerRing=m_shaft, markerOuterRing=m_house,
                                   initialOmega=500.0, initialLoad=(3000.0, 0.0), stepSize=3.5e-6,
                                   tangential="implicit", sampleInterval=3.5e-6, defects=(spall,))
    mbs.SetNodeParameter(mbs.GetObject(shaft)["nodeNumber"], "initialCoordinates",
                         [*bearing.initialRingDisplacement, 0, 0, 0])
    mbs.Assemble()
    _quiet(solve_dynamic, mbs, bearing.SimulationSettings(endTime=0.012))
    r = bearing.results()
    omega = r.global_series("omega")
    theta = np.concatenate([[omega[0] * r.t[0]], omega[0] * r.t[0] + np.cumsum(0.5 * (omega[1:] + omega[:-1])
                                                                                * np.diff(r.t))])
    hit = r.contact("defect_drop", "inner") > 0
    rel = (r.azimuth() - theta[:, None] + math.pi) % (2 * math.pi) - math.pi
    assert hit.sum() >= 10
    assert np.all(np.abs(rel[hit]) <= 0.5e-3 / eb.catalog["6208"].inner_race_radius + 2e-3)


# -- envelope analysis of the four cases (issue #13, item 3) -----------------------------------------
@pytest.fixture(scope="module")
def four_cases(load_script):
    mod = load_script("scenarios/defects_6205.py")
    runs = mod.run_cases(t_end=0.5)
    return mod, runs, mod.analyse(runs)[1]


@pytest.mark.parametrize("fault", ["outer", "inner", "ball"])
def test_strongest_envelope_line_at_the_defect_frequency(four_cases, fault):
    # housing force, band by energy (the contact resonance), 0.4 s after the transient: the strongest
    # line between 0.75 BPFO and 1.25 BPFI lies within 1 % of BPFO, BPFI or 2 BSF
    _mod, runs, table = four_cases
    row = table[fault]
    b = eb.catalog["6205"]
    f = kinematics.defect_frequencies(W1797, 0.0, 9, b.ball_radius, b.pitch_radius, 0.0)
    f0 = {"outer": f["bpfo"], "inner": f["bpfi"], "ball": 2 * f["bsf"]}[fault]
    assert row["line_Hz"] == pytest.approx(f0, rel=0.01)
    assert 7000.0 < row["band_Hz"][0] < row["band_Hz"][1] < 14000.0  # around the contact resonance


def test_healthy_envelope_has_no_defect_lines(four_cases):
    mod, _runs, table = four_cases
    h = table["healthy"]
    # the pass level is the test's own, not the script's: 40 dB below the weakest fault line
    # (amplitude ratio 0.01), where a measured line would be lost in sensor noise
    assert h["ratio_to_weakest_fault_line"] < 10 ** (-40 / 20)


def test_scenario_script_writes_its_figures(tmp_path, capsys, load_script):
    mod = load_script("scenarios/defects_6205.py")
    mod.main(["--t-end", "0.12", "--out", str(tmp_path)])
    for name in ("time_signals", "spectra", "envelope_spectra"):
        assert (tmp_path / f"{name}.png").stat().st_size > 0 and (tmp_path / f"{name}.csv").exists()
    js = json.loads((tmp_path / "defects_6205.json").read_text())
    assert set(js["cases"]) == {"healthy", "outer", "inner", "ball"}
    assert "strongest line" in capsys.readouterr().out


# -- signal processing on synthetic signals ------------------------------------------------------------
def _impacts(fs, t_end, rate, f_res, decay, mod=None, seed=0):
    t = np.arange(int(t_end * fs)) / fs
    x = np.zeros_like(t)
    for k, t0 in enumerate(np.arange(0.01, t_end, 1.0 / rate)):
        a = 1.0 if mod is None else mod(t0)
        m = t >= t0
        x[m] += a * np.exp(-(t[m] - t0) / decay) * np.sin(2 * np.pi * f_res * (t[m] - t0))
    rng = np.random.default_rng(seed)
    return t, x + 0.05 * rng.standard_normal(t.size) + 0.5 * np.sin(2 * np.pi * 37.0 * t)


def test_spectrum_amplitude_of_a_sinusoid():
    fs = 10000.0
    t = np.arange(20000) / fs
    f, a = S.spectrum(2.5 * np.sin(2 * np.pi * 123.4 * t), fs, pad=8)
    i = np.argmax(a)
    assert f[i] == pytest.approx(123.4, abs=0.1) and a[i] == pytest.approx(2.5, rel=0.002)


def test_envelope_spectrum_finds_the_impact_rate_and_the_resonance_band():
    fs = 48000.0
    t, x = _impacts(fs, 1.0, 97.0, 9000.0, 4e-4)
    es = S.envelope_spectrum(x, fs)
    assert es.band[0] < 9000.0 < es.band[1]
    assert es.line((50.0, 400.0))[0] == pytest.approx(97.0, rel=0.005)
    # the plain spectrum of the same signal has its largest low-frequency line at the 37 Hz tone
    f, a = S.spectrum(x, fs)
    assert S.strongest_line(f, a, (20.0, 400.0))[0] == pytest.approx(37.0, rel=0.02)
    # spectral kurtosis picks an impulsive band (the ringing or its sharp onsets), not the tone or the noise
    band, kurt = S.select_band(x, fs, method="kurtosis")
    assert kurt > 1.0 and band[0] > 1000.0
    f_line = S.envelope_spectrum(x, fs, band=band).line((50.0, 400.0))[0]
    assert f_line / 97.0 == pytest.approx(round(f_line / 97.0), rel=0.005)  # the rate or a harmonic


def test_order_tracking_keeps_a_shaft_order_sharp_during_a_run_up():
    # impacts 3.2 times per revolution while the shaft runs up from 20 to 40 Hz: in the envelope order
    # spectrum the line stays at order 3.2, in the envelope spectrum it smears over 64-128 Hz
    fs, t_end = 48000.0, 2.0
    t = np.arange(int(t_end * fs)) / fs
    fr = 20.0 + 10.0 * t
    theta = 2 * np.pi * (20.0 * t + 5.0 * t * t)
    x = np.zeros_like(t)
    hits = np.searchsorted(theta, 2 * np.pi / 3.2 * np.arange(1, int(theta[-1] / (2 * np.pi) * 3.2)))
    for i in hits:
        n = min(400, t.size - i)
        x[i:i + n] += np.exp(-np.arange(n) / fs / 3e-4) * np.sin(2 * np.pi * 8000.0 * np.arange(n) / fs)
    orders, a = S.order_spectrum(x, t, 2 * np.pi * fr, envelope_band=(6000.0, 10000.0))
    o, amp = S.strongest_line(orders, a, (1.0, 10.0))
    assert o == pytest.approx(3.2, rel=0.005)
    es = S.envelope_spectrum(x, fs, band=(6000.0, 10000.0))
    assert es.line((40.0, 200.0))[1] < 0.3 * amp


def test_defect_lines_and_plot(tmp_path):
    freqs = {"ftf": 11.93, "bpfo": 107.36, "bpfi": 162.19, "2bsf": 141.17, "shaft": 29.95}
    lines = S.defect_lines(freqs, 400.0, harmonics=2, sidebands=1)
    got = {round(f, 2): (label, kind) for label, f, kind, _key in lines}
    assert got[162.19] == ("BPFI", "line") and got[round(162.19 - 29.95, 2)] == ("BPFI-fr", "sideband")
    assert got[round(141.17 + 11.93, 2)] == ("2BSF+FTF", "sideband") and got[round(2 * 107.36, 2)] == ("2xBPFO", "line")
    assert all(f <= 400.0 for _l, f, _k, _key in lines)
    png = S.plot_defect_spectrum([("a", np.linspace(0, 500, 501), np.ones(501))], tmp_path / "e.png", freqs)
    assert png.stat().st_size > 0 and png.with_suffix(".csv").exists()


# -- dataset generator ---------------------------------------------------------------------------------
def test_dataset_is_labelled_resumable_and_has_the_signals(tmp_path):
    kw = dict(speeds_rpm=(1797.0,), loads=(1000.0,), sizes=((1e-3, 1.5e-3, 1e-4),), faults=("healthy", "outer"),
              t_end=0.01, workers=1, progress=False)
    rows = _quiet(build_dataset, tmp_path, **kw)
    assert [r["fault"] for r in rows] == ["healthy", "outer"] and [r["label"] for r in rows] == [0, 1]
    back = read_index(tmp_path)
    assert back[1]["length_m"] == 1e-3 and back[1]["bpfo_Hz"] == pytest.approx(rows[1]["bpfo_Hz"])
    t, x, labels = load_case_signals(tmp_path, rows[1]["name"], "outer_fx")
    assert len(t) == len(x) == back[1]["n_samples"] == 480 and labels["fault"] == "outer"
    stamp = os.path.getmtime(tmp_path / f"{rows[0]['name']}.json")
    (tmp_path / f"{rows[1]['name']}.json").unlink()
    _quiet(build_dataset, tmp_path, **kw)
    assert os.path.getmtime(tmp_path / f"{rows[0]['name']}.json") == stamp
    assert (tmp_path / f"{rows[1]['name']}.json").exists()


def test_dataset_cli(tmp_path, capsys):
    from exudyn_bearing.cli import main

    rc = _quiet(main, ["dataset", "6205", str(tmp_path), "--faults", "inner", "--t-end", "0.005", "--workers", "1",
                       "--json"])
    assert rc == 0
    rows = json.loads(capsys.readouterr().out)
    assert rows[0]["fault"] == "inner" and (tmp_path / "index.csv").exists()
    assert main(["dataset", "6205", str(tmp_path), "--faults", "inner", "--size", "1e-3", "1e-3", "5e-3"]) == 2
    assert capsys.readouterr().err.startswith("exudyn-bearing: error: depth:")


# -- README -----------------------------------------------------------------------------------------------
def _readme_block(start):
    text = manual_text()
    i = text.index(start)
    return text[i:text.index("```\n", i)]


def test_readme_defect_example_runs_as_printed(capsys):
    code = _readme_block("import exudyn_bearing as eb\nfrom exudyn_bearing.outputs import signals")
    scope = {}
    _quiet(exec, compile(code, "README.md", "exec"), scope)
    f, _a = scope["es"].line((80.0, 200.0))
    assert f == pytest.approx(S.run_defect_frequencies(scope["run"])["bpfo"], rel=0.01)
    assert "(" in capsys.readouterr().out


def test_readme_dataset_command_runs(tmp_path):
    from exudyn_bearing.cli import main

    line = _readme_block("python -m exudyn_bearing dataset").splitlines()[0]
    args = line.split()[3:]  # after "python -m exudyn_bearing"
    assert args[:3] == ["dataset", "6205", "out/ds"] and "--t-end" in args   # the bearing first, as every command
    args[2] = str(tmp_path)
    args[args.index("--t-end") + 1] = "0.003"  # shortened: the grid as printed, 3 ms per case
    assert _quiet(main, args + ["--workers", "1"]) == 0
    assert len(read_index(tmp_path)) == 16
