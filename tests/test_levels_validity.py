"""The linear level's validity and the levels' checks of ``loadAngle`` and ``coefficients``: the run-time
warning off the operating point and its silence at it, the limits of each criterion on both sides, the refusal
of a coefficient table made for another bearing or of no table, the table's JSON round trip."""
import json
import math
import warnings

import numpy as np
import pytest

exu = pytest.importorskip("exudyn")
import exudyn_bearing as eb  # noqa: E402
import test_levels  # noqa: E402  (pytest puts tests/ on the path)
from exudyn_bearing.solvers.quasistatic.levels import linear  # noqa: E402
from exudyn_bearing.solvers.quasistatic.levels.linear import LinearValidityWarning  # noqa: E402

FR = 3000.0
SPEEDS = [0.0, 250.0, 500.0]  # a short table keeps the set-up quick


def shaft(load=(FR, 0.0, 0.0), moment=None, omega=0.0):
    """The 2.5 kg shaft of tests/test_levels.py (Rxyz node, pure damper to ground), optionally a moment on it."""
    _sc, mbs, node, m_b, m_g = test_levels.shaft(load, omega, moment)
    return mbs, node, m_b, m_g


def run(t_end=0.01, start_at_operating_point=False, load=(FR, 0.0, 0.0), moment=None, omega=0.0, **options):
    """The linear level on the shaft, run for ``t_end`` (GeneralizedAlpha 1e-4 s); (level, validity warnings)."""
    mbs, node, m_b, m_g = shaft(load, moment, omega)
    options.setdefault("initialLoad", (FR, 0.0))
    options.setdefault("coefficientSpeeds", SPEEDS)
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="linear", **options)
    if start_at_operating_point:
        mbs.SetNodeParameter(node, "initialCoordinates", list(br.initialCoordinates))
    mbs.Assemble()
    ss = br.SimulationSettings(t_end)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    return br, [w for w in caught if issubclass(w.category, LinearValidityWarning)]


# the cases a user tried: a load the linearisation about +3000 N along x cannot represent
@pytest.mark.parametrize("case, kw, flag, words", [
    ("reversed load", {"load": (-FR, 0.0, 0.0)}, linear.FLAG_DIRECTION, "180.0 deg"),
    ("load along +y, loadAngle 0", {"load": (0.0, FR, 0.0), "loadAngle": 0.0}, linear.FLAG_DIRECTION, "deg away"),
    ("moment 20 N m about y", {"moment": (0.0, 20.0, 0.0)}, linear.FLAG_POSE, "ring pose"),
    ("speed beyond the table", {"omega": 2000.0, "start_at_operating_point": True}, linear.FLAG_SPEED,
     "2000 rad/s lies outside the coefficient table's 0 to 500 rad/s"),
])
def test_warning_fires_off_the_operating_point(case, kw, flag, words):
    br, caught = run(**kw)
    assert len(caught) == 1, case  # once per run
    msg = str(caught[0].message)
    assert msg.startswith("linear: ") and words in msg and "model='quasistatic'" in msg
    v = br.validity
    assert v["left"] and v["flags"] & flag and 0.0 < v["time"] < 0.01
    assert br.samples()["validity_flags"][-1] & flag  # still outside at the end: not a transient


def test_no_warning_at_the_operating_point():
    # started at the operating pose under initialLoad and spinning inside the table: never outside
    br, caught = run(start_at_operating_point=True, omega=400.0)
    assert not caught
    v = br.validity
    assert not v["left"] and v["outside_share"] == 0.0 and v["worst"]["speed"] == pytest.approx(400.0, rel=1e-6)


def test_start_transient_from_rest_is_seen_but_not_reported():
    # the shaft started at rest at the origin under initialLoad is outside while it settles (force 0 at first),
    # shorter than the warning's 3.5 ms, and inside at the end
    br, caught = run(t_end=0.02)
    v = br.validity
    assert not caught and not v["left"]
    assert 0.0 < v["outside_share"] < 0.5
    assert br.samples()["validity_flags"][0] != 0 and br.samples()["validity_flags"][-1] == 0


@pytest.fixture(scope="module")
def level():
    """A linear level at (3000, 0) N, its table turned by loadAngle 0.3 rad, for direct evaluations."""
    mbs, _node, m_b, m_g = shaft()
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="linear", initialLoad=(FR, 0.0), loadAngle=0.3,
                              coefficientSpeeds=SPEEDS)
    br._restart(0.0)
    return br


def _flags_for_force(br, force, speed=0.0):
    """Flags of the kernel at the static pose where the linear force is ``force`` (F = -L - K (u - u0)) at
    ``speed``: 0 or beyond the table's top (its first or last row)."""
    row = 0 if speed == 0.0 else -1
    k = br._table[row, :25].reshape(5, 5)
    u0 = br._table[row, 50:]
    target = np.zeros(5)
    target[:3] = force
    du = np.linalg.solve(k, -np.asarray(br._loads) - target)
    u = u0 + du
    br._evaluate(u[:3], np.array([u[3], u[4], 0.0]), np.zeros(3), np.array([0.0, 0.0, speed]))
    assert br._force[:3] == pytest.approx(np.asarray(force), abs=1e-6 * FR)
    return int(br._vstate[0]), u


def test_each_criterion_on_both_sides_of_its_limit(level):
    f0 = -np.asarray(level._loads[:3])
    assert np.linalg.norm(f0) == pytest.approx(FR) and math.atan2(-f0[1], -f0[0]) == pytest.approx(0.3)

    def turned(deg):
        c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
        return np.array([c * f0[0] - s * f0[1], s * f0[0] + c * f0[1], 0.0])

    assert _flags_for_force(level, f0)[0] == 0
    assert _flags_for_force(level, turned(8.0))[0] == 0
    assert _flags_for_force(level, turned(12.0))[0] == linear.FLAG_DIRECTION
    assert _flags_for_force(level, 1.2 * f0)[0] == 0
    assert _flags_for_force(level, 1.3 * f0)[0] == linear.FLAG_MAGNITUDE
    # the pose: a tilt alone moving the pitch circle by 20 % and 30 % of |u0|
    u0 = level._table[0, 50:]
    scale = np.linalg.norm(u0[:3])
    r_p = level.bearing.pitch_radius
    for share, expected in ((0.2, 0), (0.3, linear.FLAG_POSE)):
        u = u0.copy()
        u[3] += share * scale / r_p
        level._evaluate(u[:3], np.array([u[3], u[4], 0.0]), np.zeros(3), np.zeros(3))
        assert int(level._vstate[0]) & linear.FLAG_POSE == expected
        assert level._vstate[3] == pytest.approx(share / linear.VALIDITY_POSE, rel=1e-9)
    # the speed: the table's top (500 rad/s) plus 0.5 % passes, plus 2 % does not (either spin direction)
    assert _flags_for_force(level, f0, speed=-502.5)[0] == 0
    assert _flags_for_force(level, f0, speed=510.0)[0] == linear.FLAG_SPEED
    assert _flags_for_force(level, f0, speed=-510.0)[0] == linear.FLAG_SPEED


# -- coefficient tables made for another bearing -----------------------------------------------------------
@pytest.fixture(scope="module")
def table_6208():
    return eb.bearing_coefficients("6208", [0.0], Fr=FR)


def test_table_made_for_another_bearing_is_refused(table_6208):
    mbs, _node, m_b, m_g = shaft()
    t7208 = eb.bearing_coefficients("7208", [0.0], Fr=1000.0, Fa=2000.0)
    with pytest.raises(eb.InputError, match=r"^coefficients: the table was made for another bearing \('7208'\)"):
        eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="linear", initialLoad=(1000.0, 2000.0), coefficients=t7208)
    # the same name, another clearance: the geometry decides, not the name
    with pytest.raises(eb.InputError, match=r"^coefficients: .*outer_race_radius"):
        eb.CreateBallBearing(mbs, eb.catalog["6208"].with_clearance(20e-6), m_b, m_g, model="quasistatic",
                             initialLoad=(FR, 0.0), coefficients=table_6208)


def test_table_survives_the_json_round_trip_and_old_tables_are_refused(table_6208):
    d = json.loads(json.dumps(table_6208.to_dict()))
    assert d["operating_point"]["bearing_geometry"]["n_balls"] == 9
    mbs, _node, m_b, m_g = shaft()
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="linear", initialLoad=(FR, 0.0), coefficients=d)
    assert np.array_equal(br.coefficients.stiffness, table_6208.stiffness)
    del d["operating_point"]["bearing_geometry"]
    with pytest.raises(eb.InputError, match=r"^coefficients: the table does not say which bearing"):
        eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="linear", initialLoad=(FR, 0.0), coefficients=d)


def test_table_of_the_stiffness_command_is_accepted(capsys):
    # the table the CLI writes (stiffness --speeds --json) carries the fingerprint: a level takes it as it is
    from exudyn_bearing.cli import main

    assert main(["stiffness", "6208", "--Fr", "3000", "--speeds", "0", "500", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    mbs, _node, m_b, m_g = shaft()
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="linear", initialLoad=(FR, 0.0), coefficients=d)
    assert list(br.coefficients.speeds) == [0.0, 500.0]
    with pytest.raises(eb.InputError, match=r"^coefficients: the table was made for another bearing \('6208'\)"):
        eb.CreateBallBearing(mbs, "6205", m_b, m_g, model="linear", initialLoad=(FR, 0.0), coefficients=d)


@pytest.mark.parametrize("model", ["linear", "quasistatic"])
@pytest.mark.parametrize("bad", ["abc", 3.0, [1.0, 2.0], {"speeds": [0.0]}])
def test_coefficients_of_a_wrong_type_are_refused(model, bad):
    mbs, _node, m_b, m_g = shaft()
    with pytest.raises(eb.InputError, match=r"^coefficients: "):
        eb.CreateBallBearing(mbs, "6208", m_b, m_g, model=model, initialLoad=(FR, 0.0), coefficients=bad)


# -- loadAngle ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("model", ["linear", "quasistatic"])
def test_load_angle_outside_one_turn_is_refused(model):
    mbs, _node, m_b, m_g = shaft()
    with pytest.raises(eb.InputError, match=r"^loadAngle: 100 rad is not plausible \(-6.28319 to 6.28319 rad\); "
                                            r"the azimuth of the radial load is in radians: 100 deg is 1.74533 rad"):
        eb.CreateBallBearing(mbs, "6208", m_b, m_g, model=model, initialLoad=(FR, 0.0), loadAngle=100.0,
                             coefficientSpeeds=[0.0])
    with pytest.raises(eb.InputError, match=r"^loadAngle: "):
        eb.CreateBallBearing(mbs, "6208", m_b, m_g, model=model, loadAngle="0", coefficientSpeeds=[0.0])
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model=model, initialLoad=(FR, 0.0), loadAngle=-2.0 * math.pi,
                              coefficientSpeeds=[0.0])
    assert br.initialRingDisplacement[0] == pytest.approx(br.operatingPoint.displacement[0], rel=1e-12)


def test_a_linearisation_without_stiffness_is_refused():
    # the default initialLoad (0, 0) on a bearing without clearance: Hertz contacts have no stiffness at zero
    # load, so the table's K is zero and a loaded shaft would fall through the bearing (3 m in 0.05 s)
    mbs, _node, m_b, m_g = shaft()
    with pytest.raises(eb.InputError, match="initialLoad.*no radial or axial stiffness"):
        eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="linear", coefficientSpeeds=[0.0, 500.0])
