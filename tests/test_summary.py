"""The dynamic summary's checks on synthetic records (no simulation): steadiness measured against its
thresholds, q_max at psi = 0 interpolated when no ball passes it, the energy balance from the engine's
fields or from the sampled series, the sign of friction_torque, and the loss/lubricant/traction entries."""
import math
import warnings

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing.data import lubricants
from exudyn_bearing.model.layout import DIAG_FIELDS, GLOBAL_FIELDS
from exudyn_bearing.model.record import RunRecord
from exudyn_bearing.outputs import results as results_module
from exudyn_bearing.outputs.window_checks import (DRIFT_DEG, DRIFT_REL, PSI0_TOLERANCE, SteadyStateWarning,
                                                  load_at_psi0, q_max_at_psi0)

# synthetic records and short runs: their energy does not close, which these tests do not judge
pytestmark = pytest.mark.filterwarnings("ignore::exudyn_bearing.EnergyBalanceWarning")

Q0 = 1462.0          # N, load of the ball at psi = 0
OMEGA = 500.0        # rad/s
CAGE = 198.0         # rad/s
SPIN = 950.0         # rad/s
TORQUE = 0.04        # N m that drives the ring (the balls' torque on the ring is -TORQUE)
POWER = 19.0         # W of friction
#: the engines' energy fields (model.layout), taken out of the synthetic records unless a test puts them in
ENERGY_FIELDS = ("damping_power", "drive_power", "drive_work", "dissipated_work", "kinetic_energy")
BASE_FIELDS = tuple(f for f in GLOBAL_FIELDS if f not in ENERGY_FIELDS)
WITH_ENERGY = BASE_FIELDS + ENERGY_FIELDS


@pytest.fixture(autouse=True)
def base_fields(monkeypatch):
    """Records without the energy fields by default (the layout of the summary module patched to match)."""
    monkeypatch.setattr(results_module, "GLOBAL_FIELDS", BASE_FIELDS)


def _record(n=401, t1=0.1, offset_deg=0.0, alpha_deg=lambda t: 0.0 * t, ring_x=lambda t: 2.5e-5 + 0.0 * t,
            spin=lambda t: SPIN + 0.0 * t, fields=BASE_FIELDS, glob_extra=None, scenario=None, engine="reference",
            cage_speed=CAGE, outer_unloaded_zone=0.0):
    """A 6208 record with Z = 9 balls orbiting at ``cage_speed`` from ``offset_deg``, loads Q0 cos(psi)^1.5 on
    both races, the given contact angle [deg], ring x displacement [m] and ball spin [rad/s] as functions of t."""
    b = eb.catalog["6208"]
    z = b.n_balls
    t = np.linspace(0.0, t1, n)
    sc = scenario or eb.Scenario(Fr=3000.0, omega=OMEGA, t_end=t1, sample_dt=t1 / (n - 1), dt=5e-6)
    psi = math.radians(offset_deg) + 2 * np.pi * np.arange(z)[None, :] / z + cage_speed * t[:, None]
    psic = psi + np.pi / z
    rp = b.pitch_radius

    def on_circle(a):
        return np.stack([rp * np.cos(a), rp * np.sin(a), np.zeros_like(a)], axis=-1)

    def velocity(a):
        return np.stack([-rp * cage_speed * np.sin(a), rp * cage_speed * np.cos(a), np.zeros_like(a)], axis=-1)

    c = np.cos(np.angle(np.exp(1j * psi)))
    load = Q0 * np.clip(c, 0.0, None) ** 1.5
    diag = np.zeros((n, z, 2, len(DIAG_FIELDS)))
    for race in (0, 1):
        diag[:, :, race, DIAG_FIELDS.index("load")] = load if race == 0 else np.where(load > 0, load,
                                                                                     outer_unloaded_zone)
        diag[:, :, race, DIAG_FIELDS.index("contact_angle")] = np.radians(alpha_deg(t))[:, None]
        diag[:, :, race, DIAG_FIELDS.index("regime")] = np.where(load > 0, 1, -1)
        diag[:, :, race, DIAG_FIELDS.index("lambda")] = 2.0
    glob = np.zeros((n, len(fields)))
    glob[:, fields.index("omega")] = OMEGA
    glob[:, fields.index("ring_torque")] = -TORQUE
    glob[:, fields.index("friction_power")] = POWER
    for name, series in (glob_extra or {}).items():
        glob[:, fields.index(name)] = series(t)
    wb = np.zeros((n, z, 3))
    wb[..., 2] = spin(t)[:, None]
    ring = np.zeros((n, 6))
    ring[:, 0] = ring_x(t)
    data = {"t": t, "glob": glob, "diag": diag, "cage_load": np.zeros((n, z, 2)), "xb": on_circle(psi),
            "vb": velocity(psi), "wb": wb, "xc": on_circle(psic), "vc": velocity(psic), "ring": ring}
    return eb.Results(RunRecord(b, sc, lubricants["guessasma2018"], data, steps=n, wall_s=1.0, engine=engine))


def _summary_no_warning(r, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("error", SteadyStateWarning)
        return r.summary(**kw)


# -- steadiness ------------------------------------------------------------------------
def test_constant_record_is_steady():
    s = _summary_no_warning(_record())
    st = s["steady"]
    assert st["steady"] is True and st["flagged"] == [] and st["reason"] is None
    for name in ("cage_speed", "ball_spin", "alpha_inner", "ring_displacement.x", "friction_torque", "dissipation"):
        assert abs(st["drift"][name]) < 1e-9, name   # constant series: no trend
    # the largest load repeats with every ball passage (3.53 ms, 14.1 samples, averaged over 14): without the
    # passage average its trend over the 7.1 passes of the window is 0.85 %, with it a residue far below 0.5 %
    assert abs(st["drift"]["q_max_inner"]) < 0.1 * DRIFT_REL
    assert st["passage_period"] == pytest.approx(2 * math.pi / (9 * CAGE), rel=1e-9)
    assert st["thresholds"]["angle"]["drift"] == DRIFT_DEG


def test_drifting_contact_angle_is_flagged_by_name():
    # alpha = 40 deg + 40 deg/s t, 1 deg over the 25 ms window: the least-squares slope times the window
    # length is 1 deg exactly for a linear series (and after the moving average); the threshold is 0.25 deg
    r = _record(alpha_deg=lambda t: 40.0 + 40.0 * t)
    w, _ = r.summary_window()
    length = r.t[w][-1] - r.t[w][0]
    with pytest.warns(SteadyStateWarning, match="alpha_inner drifts by"):
        s = r.summary()
    st = s["steady"]
    assert st["steady"] is False and st["flagged"] == ["alpha_inner", "alpha_outer"]
    assert st["drift"]["alpha_inner"] == pytest.approx(40.0 * length, rel=1e-9)
    assert "alpha_inner drifts by" in st["reason"]


def test_drifting_ring_displacement_is_flagged_relative_to_its_mean():
    # x = d (1 + 0.02 (t - t_c) / T) over the window [t0, t1]: drift 2 % of the mean d, above 0.5 %;
    # a drift of 0.2 % passes
    def record(a):
        r0 = _record()
        w, _ = r0.summary_window()
        t0, t1 = r0.t[w][0], r0.t[w][-1]
        return _record(ring_x=lambda t: 2.5e-5 * (1.0 + a * (t - 0.5 * (t0 + t1)) / (t1 - t0)))

    with pytest.warns(SteadyStateWarning, match="ring_displacement.x"):
        st = record(0.02).summary()["steady"]
    assert st["flagged"] == ["ring_displacement.x"]
    assert st["drift"]["ring_displacement.x"] == pytest.approx(0.02, rel=1e-9)
    assert 0.002 < DRIFT_REL
    assert _summary_no_warning(record(0.002))["steady"]["steady"] is True


def test_window_over_a_ramp_is_not_steady_by_definition():
    sc = eb.Scenario(Fr=3000.0, omega=OMEGA, t_ramp_up=0.05, t_steady=0.05, t_end=0.1, sample_dt=0.1 / 400, dt=5e-6,
                     initial="rest")
    r = _record(scenario=sc)
    with pytest.warns(SteadyStateWarning, match="start-up ramp"):
        st = r.summary(t_window=(0.0, 0.04))["steady"]
    assert st["steady"] is False and st["flagged"] == []   # the series themselves are constant
    assert _summary_no_warning(r)["steady"]["steady"] is True   # second half of the steady phase


def test_loss_below_the_floor_is_measured_but_not_judged():
    # a point-level spring exchange: friction torque alternating +-2e-3 N m about zero
    r = _record(glob_extra={"ring_torque": lambda t: 2e-3 * np.sign(np.sin(300.0 * t))})
    st = _summary_no_warning(r)["steady"]
    assert "friction_torque" in st["not_judged"] and "friction_torque" in st["drift"]


# -- q_max at psi = 0 ------------------------------------------------------------------------
@pytest.mark.parametrize("eps", [0.5, 0.35, 0.8])
def test_q_max_interpolated_from_azimuths_that_miss_psi0(eps):
    # Harris's rigid-ring distribution Q0 (1 - (1 - cos psi) / (2 eps))^1.5 (eps = 0.5: Q0 cos^1.5) sampled at
    # 9 balls 20 deg off psi = 0: Q^(2/3) is linear in cos psi, so the fit returns Q0 to round-off
    psi = np.radians(20.0 + 40.0 * np.arange(9))
    psi = np.angle(np.exp(1j * psi))
    q = Q0 * np.clip(1.0 - (1.0 - np.cos(psi)) / (2.0 * eps), 0.0, None) ** 1.5
    assert q.max() < 0.95 * Q0      # the largest sampled load misses Q0 by over 5 %
    value, method, peak = q_max_at_psi0(psi, q)
    assert method == "interpolated"
    assert value == pytest.approx(Q0, rel=1e-9) and peak == pytest.approx(0.0, abs=1e-9)


def test_q_max_takes_the_ball_at_psi0_when_one_passes():
    psi = np.radians([-40.0, 0.5 * math.degrees(PSI0_TOLERANCE), 40.0])
    q = Q0 * np.cos(psi) ** 1.5
    assert q_max_at_psi0(psi, q)[:2] == (q.max(), "ball at psi=0")


def test_load_at_psi0_is_the_passes_mean_where_q_max_takes_the_peak():
    # balls passing psi = 0 in every sample, their loads the steady Q0 cos(psi)^1.5 with a vibration of
    # +-2 % alternating from sample to sample: q_max takes the peak (2 % above Q0), load_at_psi0 the mean
    rng = np.random.default_rng(1)
    psi = np.radians(np.repeat(rng.uniform(-0.9, 0.9, 100), 2))  # each azimuth twice: once up, once down
    steady = Q0 * np.cos(psi) ** 1.5
    q = steady * (1.0 + 0.02 * np.where(np.arange(200) % 2 == 0, 1.0, -1.0))
    assert q_max_at_psi0(psi, q)[0] > 1.015 * Q0
    assert load_at_psi0(psi, q) == pytest.approx(np.mean(steady), rel=1e-12)
    # the balls outside the tolerance and the unloaded ones do not count; none inside: None
    far = np.radians([-40.0, 30.0, 0.2])
    assert load_at_psi0(far, np.array([900.0, 800.0, 0.0])) is None
    assert load_at_psi0(far, np.array([900.0, 800.0, 1000.0])) == 1000.0


def test_summary_q_max_says_how_it_was_obtained():
    # balls frozen 20 deg off psi = 0 (cage speed 0, the quasi-static 1 rad/s case): interpolated to Q0;
    # passing balls: the largest load, a ball at psi = 0
    s = _summary_no_warning(_record(offset_deg=20.0, cage_speed=0.0))
    assert s["q_max_method"] == {"inner": "interpolated", "outer": "interpolated"}
    assert s["q_max_inner"] == pytest.approx(Q0, rel=1e-9) and s["q_max_inner_mean"] == pytest.approx(Q0 * math.cos(math.radians(20.0)) ** 1.5)
    # balls outside the loaded zone pressed on the outer race by a centrifugal force of 50 N: the outer
    # distribution is fitted over the balls whose inner contact is loaded, and is again Q0
    s = _summary_no_warning(_record(offset_deg=20.0, cage_speed=0.0, outer_unloaded_zone=50.0))
    assert s["q_max_outer"] == pytest.approx(Q0, rel=1e-9)
    s = _summary_no_warning(_record())
    # a sample within PSI0_TOLERANCE (1 deg) of psi = 0: at most 1 - cos(1 deg)^1.5 = 2.3e-4 below Q0
    assert s["q_max_method"]["inner"] == "ball at psi=0" and Q0 * (1 - 2.3e-4) < s["q_max_inner"] <= Q0
    # the summary's passes' mean: the same bound (no vibration), never above the peak
    assert Q0 * (1 - 2.3e-4) < s["q_psi0_inner"] <= s["q_max_inner"]


# -- energy -------------------------------------------------------------------------------
def _ball_spin_energy(b, w):
    m = 4.0 / 3.0 * math.pi * b.ball_radius ** 3 * b.material.density
    return 0.5 * b.n_balls * 0.4 * m * b.ball_radius ** 2 * w ** 2


def test_energy_balance_from_the_sampled_series():
    # drive TORQUE * OMEGA = 20 W, friction 19 W, the balls spin up by 40 rad/s per second: the fallback
    # path (no energy fields in the record) gives the hand balance
    r = _record(spin=lambda t: SPIN + 40.0 * t)
    s = _summary_no_warning(r)
    w, win = r.summary_window()
    t0, t1 = win["t0"], win["t1"]
    b = r.bearing
    dke = _ball_spin_energy(b, SPIN + 40.0 * t1) - _ball_spin_energy(b, SPIN + 40.0 * t0)
    assert s["drive_power"] == pytest.approx(TORQUE * OMEGA, rel=1e-12)
    assert s["load_power"] == 0.0 and s["dissipation"] == pytest.approx(POWER, rel=1e-12)
    assert s["kinetic_energy_change"] == pytest.approx(dke, rel=1e-9)
    assert s["energy_residual"] == pytest.approx((TORQUE * OMEGA - POWER - dke / (t1 - t0)) / (TORQUE * OMEGA),
                                                 rel=1e-9)
    assert "sampled" in s["energy_source"]["drive_power"] and "not recorded" in s["energy_source"]["dissipation"]


def test_energy_balance_from_the_engine_fields(monkeypatch):
    # the engine's cumulative drive_work and dissipated_work and its kinetic_energy, when recorded, win over
    # the sampled series (set here to other values); the load power is in the engine's drive power
    monkeypatch.setattr(results_module, "GLOBAL_FIELDS", WITH_ENERGY)
    r = _record(fields=WITH_ENERGY, glob_extra={"drive_work": lambda t: 30.0 * t,
                                                "dissipated_work": lambda t: 29.0 * t,
                                                "kinetic_energy": lambda t: 0.2 + 5.0 * t,
                                                "drive_power": lambda t: 99.0 + 0.0 * t,
                                                "damping_power": lambda t: 10.0 + 0.0 * t})
    s = _summary_no_warning(r)
    _, win = r.summary_window()
    length = win["t1"] - win["t0"]
    assert s["drive_power"] == pytest.approx(30.0, rel=1e-9) and s["dissipation"] == pytest.approx(29.0, rel=1e-9)
    assert s["load_power"] is None and s["energy_source"]["load_power"].startswith("included")
    assert s["kinetic_energy_change"] == pytest.approx(5.0 * length, rel=1e-9)
    assert s["energy_residual"] == pytest.approx((30.0 - 29.0 - 5.0) / 30.0, rel=1e-9)
    assert s["energy_source"]["drive_power"].startswith("drive_work")
    assert r.kinetic_energy_series()[0] == pytest.approx(0.2)


def test_sampled_drive_power_and_damping_join_without_the_cumulative_fields(monkeypatch):
    fields = BASE_FIELDS + ("damping_power", "drive_power")
    monkeypatch.setattr(results_module, "GLOBAL_FIELDS", fields)
    s = _summary_no_warning(_record(fields=fields, glob_extra={"damping_power": lambda t: 0.5 + 0.0 * t,
                                                               "drive_power": lambda t: 21.0 + 0.0 * t}))
    assert s["dissipation"] == pytest.approx(POWER + 0.5, rel=1e-12)
    assert s["drive_power"] == pytest.approx(21.0, rel=1e-12) and s["load_power"] is None


def test_load_power_is_the_work_of_the_radial_load_on_the_ring():
    # the ring moves by 1 nm along the 3000 N load at constant speed over the window: 3e-6 J more drive
    r0 = _record()
    w, win = r0.summary_window()
    t0, t1 = win["t0"], win["t1"]
    s = _summary_no_warning(_record(ring_x=lambda t: 2.5e-5 + 1e-9 * (t - t0) / (t1 - t0)))
    assert s["load_power"] == pytest.approx(3000.0 * 1e-9 / (t1 - t0), rel=1e-6)
    assert s["drive_power"] == pytest.approx(TORQUE * OMEGA + s["load_power"], rel=1e-12)


def test_element_record_has_no_load_power_but_the_same_keys():
    a, b = _summary_no_warning(_record()), _summary_no_warning(_record(engine="exudyn"))
    assert set(a) == set(b) and b["load_power"] is None and b["drive_power"] == pytest.approx(TORQUE * OMEGA)
    assert set(results_module.SUMMARY_KEYS) <= set(a)


# -- definitions, sign, lubricant and traction -------------------------------------------
def test_friction_torque_is_positive_when_the_ring_must_be_driven():
    # glob ring_torque is the torque of the balls on the ring about its axis: -TORQUE brakes the ring
    # spinning at +OMEGA, so the drive must supply +TORQUE
    s = _summary_no_warning(_record())
    assert s["friction_torque"] == pytest.approx(TORQUE) and s["drive_power"] == pytest.approx(TORQUE * OMEGA)


def test_summary_names_losses_lubricant_and_traction():
    s = _summary_no_warning(_record())
    assert s["lubricant"] == "guessasma2018" and s["traction_level"] == "point"
    assert "mu(Lambda) of lubricant guessasma2018" in s["traction_model"]
    assert any("Heathcote" in x for x in s["losses_not_modelled"]) and "no rolling losses" in s["note"]
    for key in ("friction_torque", "friction_power", "dissipation_inner", "dissipation_outer", "drive_power",
                "dissipation", "kinetic_energy_change", "energy_residual"):
        assert key in s["units"] and key in s["descriptions"], key
    assert s["units"]["kinetic_energy_change"] == "J" and s["units"]["energy_residual"] == "-"
    sc = eb.Scenario(Fr=3000.0, omega=OMEGA, t_end=0.1, sample_dt=0.1 / 400, dt=5e-6, traction_level="ellipse",
                     traction="ehl_mil_l_23699_492K")
    e = _summary_no_warning(_record(scenario=sc))
    assert e["traction_model"] == "ehl_mil_l_23699_492K" and "note" not in e
    assert any("Heathcote" in x for x in e["losses_modelled"])


def test_cli_prints_a_steady_line_naming_the_quantity():
    from exudyn_bearing.outputs.tables import summary_rows as _table  # the CLI's rows (cli/simulate.py prints them)

    with pytest.warns(SteadyStateWarning):
        s = _record(alpha_deg=lambda t: 40.0 + 40.0 * t).summary()
    rows = {r[0]: r[1] for r in _table(s)}
    assert rows["steady"].startswith("NO: alpha_inner drifts")
    rows = {r[0]: r[1] for r in _table(_summary_no_warning(_record()))}
    assert rows["steady"].startswith("yes") and rows["q_max_method"] == "inner: ball at psi=0, outer: ball at psi=0"


def test_saved_json_holds_the_checks_and_warns_once(tmp_path):
    import json

    r = _record(alpha_deg=lambda t: 40.0 + 40.0 * t)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        _npz, js = r.save(tmp_path)          # the summary written to the file does not warn again
    assert not [w for w in caught if issubclass(w.category, SteadyStateWarning)]
    d = json.loads(js.read_text())
    assert d["steady"]["steady"] is False and d["steady"]["flagged"] == ["alpha_inner", "alpha_outer"]
    assert d["q_max_method"]["inner"] == "ball at psi=0" and d["units"]["drive_power"] == "W"
