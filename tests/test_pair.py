"""Bearing pairs (DB, DF, DT) over the single-bearing quasi-static solver: solvers/quasistatic/pair.py,
docs/theory/pairs.md."""
import json
import math

import numpy as np
import pytest

from exudyn_bearing import solve_quasistatic
from exudyn_bearing.data import InputError
from exudyn_bearing.outputs.jsonio import to_jsonable
from exudyn_bearing.solvers.quasistatic.pair import pressure_centre_offset, solve_pair

B = "7208"
F0 = 500.0          # preload per bearing [N]
L = 0.018           # ball-set planes one 72xx width apart (adjacent pair, no spacer) [m]


@pytest.fixture(scope="module")
def single():
    """The single bearing under the preload as axial load: the operating point of both bearings of an
    unloaded preloaded DB / DF pair."""
    return solve_quasistatic(B, Fa=F0)


def test_db_pure_radial_load_is_shared_symmetrically():
    p = solve_pair(B, "DB", Fr=3000.0, preload=F0, spacing=L)
    b0, b1 = p.bearing_dict(0), p.bearing_dict(1)
    assert b0["Fr"] == pytest.approx(1500.0, rel=1e-8) and b1["Fr"] == pytest.approx(1500.0, rel=1e-8)
    # each carries more axial load than the preload (the radial load's induced axial force), the same in both
    assert b0["Fa"] > F0 and b0["Fa"] == pytest.approx(b1["Fa"], rel=1e-8)
    # on the shaft the two axial forces are equal and opposite
    assert b0["loads_global"]["Fa"] == pytest.approx(-b1["loads_global"]["Fa"], rel=1e-8)
    assert abs(p.displacement[2]) < 1e-6 * p.displacement[0]
    assert abs(p.displacement[4]) * L < 1e-6 * p.displacement[0]
    assert not b0["unloaded"] and not b1["unloaded"]


def test_db_axial_stiffness_is_the_sum_of_both_bearings(single):
    """Unloaded preloaded DB pair: both bearings sit at the single bearing's point under F0 and the shaft's
    axial motion x moves them by +x and -x, so k_aa(pair) = k_aa(1) + k_aa(2) = 2 k_aa(single, F0). With a
    fixed contact angle and Q ~ delta^1.5 a bearing's k_aa = 1.5 F0/delta_0 (delta_0 its preload
    deflection); the 7208's contact angle grows from 40.0 to 40.15 deg under F0, which stiffens it slightly."""
    p = solve_pair(B, "DB", preload=F0, spacing=L)
    assert p.stiffness[2, 2] == pytest.approx(2.0 * single.stiffness[2, 2], rel=1e-6)
    delta0 = single.displacement[2]  # the 7208 has no clearance: the balls touch at delta_a = 0
    assert p.stiffness[2, 2] == pytest.approx(2.0 * 1.5 * F0 / delta0, rel=0.01)
    assert p.preload_displacement == pytest.approx(2.0 * delta0, rel=1e-9)


def test_tilt_stiffness_db_exceeds_df(single):
    """A bearing's radial stiffness k_r acts at its pressure centre, z_pc = K_x,tilt_y / k_r from its ball-set
    plane (-25.5 mm for the 7208), plus a small tilt stiffness of its own about it,
    k_own = K_tilt - K_x,tilt_y^2 / k_r. Two bearings with ball-set planes L apart give
    K_tilt = 2 (k_r (L/2 + e)^2 + k_own) for DB (pressure centres outside) and 2 (k_r (L/2 - e)^2 + k_own)
    for DF, e = |z_pc|: their ratio is about ((L + 2e)/(L - 2e))^2, 4.4 for an adjacent pair (4.32 with
    k_own)."""
    db = solve_pair(B, "DB", preload=F0, spacing=L)
    df = solve_pair(B, "DF", preload=F0, spacing=L)
    k = single.stiffness
    h = 0.5 * L
    for tilt, radial in ((4, 0), (3, 1)):  # tilt_y with delta_x, tilt_x with delta_y
        kr, kc = k[radial, radial], 0.5 * (k[radial, tilt] + k[tilt, radial])  # (FD: K is symmetric to 1e-5)
        e = abs(kc / kr)
        assert e == pytest.approx(abs(pressure_centre_offset(B)), rel=0.01)  # the contact line at 40 deg
        # k_r (h +- e)^2 + k_own = k_r h^2 +- 2 |K_x,tilt| h + K_tilt
        for p, sign in ((db, 1.0), (df, -1.0)):
            expect = 2.0 * (kr * h * h + sign * 2.0 * abs(kc) * h + k[tilt, tilt])
            assert p.stiffness[tilt, tilt] == pytest.approx(expect, rel=1e-9)
    assert db.stiffness[3, 3] > 4.0 * df.stiffness[3, 3]
    assert db.pressure_centre_spacing == pytest.approx(L + 2.0 * abs(pressure_centre_offset(B)))


def test_dt_pair_shares_axial_load():
    p = solve_pair(B, "DT", Fa=2000.0, spacing=L)
    for k in range(2):
        assert p.bearing_dict(k)["Fa"] == pytest.approx(1000.0, rel=1e-8)
    alone = solve_quasistatic(B, Fa=1000.0)
    assert p.displacement[2] == pytest.approx(alone.displacement[2], rel=1e-6)
    assert p.stiffness[2, 2] == pytest.approx(2.0 * alone.stiffness[2, 2], rel=1e-5)


def test_lift_off_of_the_unloaded_bearing(single):
    """Axial load F_a on a DB pair preloaded to F0: the shaft moves by x, bearing 0 to delta_0 + x, bearing 1
    to delta_0 - x; bearing 1 unloads at x = delta_0, where F_a = F(2 delta_0) = 2^1.5 F0 = 2.83 F0 for
    Q ~ delta^1.5 at a fixed contact angle (the 7208's angle grows from 40.15 to 40.3 deg: a little more)."""
    d0 = single.displacement[2]
    f_lift = solve_quasistatic(B, fixed={"delta_x": 0.0, "delta_y": 0.0, "delta_a": 2.0 * d0, "tilt_x": 0.0,
                                         "tilt_y": 0.0}).reactions["delta_a"]
    assert f_lift / F0 == pytest.approx(2.0 ** 1.5, rel=0.01)
    below = solve_pair(B, "DB", Fa=0.98 * f_lift, preload=F0, spacing=L)
    above = solve_pair(B, "DB", Fa=1.02 * f_lift, preload=F0, spacing=L)
    assert not below.unloaded(1) and below.bearing_dict(1)["Fa"] > 0.0
    assert above.unloaded(1) and above.bearing_dict(1)["Fa"] == 0.0
    assert above.bearing_dict(0)["Fa"] == pytest.approx(1.02 * f_lift, rel=1e-8)
    assert any("unloaded" in n for n in above.notes)
    # the other direction unloads bearing 0 (DB carries axial load both ways, one bearing each)
    assert solve_pair(B, "DB", Fa=-1.02 * f_lift, preload=F0, spacing=L).unloaded(0)


def test_preload_as_displacement_matches_the_force():
    p = solve_pair(B, "DF", preload=F0, spacing=L)
    q = solve_pair(B, "DF", preload=("displacement", p.preload_displacement), spacing=L)
    assert q.preload == pytest.approx(F0, rel=1e-6)
    assert q.bearing_dict(0)["Fa"] == pytest.approx(F0, rel=1e-6)


def test_pair_at_speed_is_symmetric():
    """The second bearing of a DB pair is solved in a frame turned by pi about x (ring speeds -omega):
    under preload alone at speed both bearings must come out alike."""
    p = solve_pair(B, "DB", preload=F0, spacing=L, omega=500.0)
    b0, b1 = p.bearing_dict(0), p.bearing_dict(1)
    assert b0["Fa"] == pytest.approx(b1["Fa"], rel=1e-6) and b0["Fa"] > F0  # centrifugal growth of the preload
    assert b0["friction_torque"] == pytest.approx(b1["friction_torque"], rel=1e-6) and b0["friction_torque"] > 0.0
    assert any("position preload" in n for n in p.notes)


def test_to_dict_has_one_entry_per_bearing():
    d = solve_pair(B, "DB", Fr=1000.0, Fa=800.0, My=5.0, preload=F0, spacing=L).to_dict()
    json.dumps(to_jsonable(d))
    assert d["arrangement"] == "DB" and len(d["bearings"]) == 2
    for e in d["bearings"]:
        assert {"Fr", "Fa", "unloaded", "q_max_inner", "stiffness"} <= set(e)
    assert np.asarray(d["stiffness"]).shape == (5, 5)
    # the bearings' loads, moved to the shaft frame and the pair's centre, balance the applied loads
    total = np.zeros(5)
    for e in d["bearings"]:
        g = np.array([e["loads_global"][k] for k in ("Fx", "Fy", "Fa", "Mx", "My")])
        z = e["position"]
        total += g + np.array([0.0, 0.0, 0.0, -z * g[1], z * g[0]])
    assert total == pytest.approx([1000.0, 0.0, 800.0, 0.0, 5.0], abs=1e-6)


def test_without_spacing_the_tilt_is_held():
    p = solve_pair(B, "DB", Fr=2000.0, preload=F0)
    assert p.held == {"tilt_x": "no spacing", "tilt_y": "no spacing"}
    assert math.isnan(p.stiffness[3, 3]) and math.isfinite(p.stiffness[0, 0])


@pytest.mark.parametrize("kwargs, name", [
    ({"arrangement": "DT", "Fa": 1000.0, "preload": 200.0}, "preload"),
    ({"arrangement": "DB", "My": 10.0, "preload": 200.0}, "spacing"),
    ({"arrangement": "DB", "preload": -100.0, "spacing": L}, "preload"),
    ({"arrangement": "DB", "preload": ("displacement", -1e-6), "spacing": L}, "preload_displacement"),
    ({"arrangement": "DB", "preload": "light", "spacing": L}, "preload"),
    ({"arrangement": "DX", "spacing": L}, "arrangement"),
    ({"arrangement": "DB", "spacing": -0.01}, "spacing"),
    ({"arrangement": "DT", "Fa": -1000.0, "spacing": L}, "Fa"),
    ({"arrangement": "DT", "Fr": 3000.0, "Fa": 1000.0, "spacing": L}, "Fa"),
])
def test_refusals_name_the_parameter(kwargs, name):
    with pytest.raises(InputError, match=rf"^{name}:"):
        solve_pair(B, **kwargs)


def test_deep_groove_bearing_refused():
    with pytest.raises(InputError, match=r"^bearing: .*deep-groove"):
        solve_pair("6208", "DB", preload=200.0, spacing=L)


def _cli_json(capsys, *argv):
    from exudyn_bearing.cli import main

    assert main([*argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("command", ["static", "quasistatic", "stiffness"])
def test_cli_pair_json(capsys, command):
    """The interface: --arrangement DB --preload N gives ``bearings``, one entry per bearing with its own
    loads (Fr, Fa) and results, and the pair's stiffness; static and quasistatic add the rating lives."""
    d = _cli_json(capsys, command, B, "--Fr", "2000", "--Fa", "600", "--arrangement", "DB", "--preload", "500",
                  "--spacing", "0.018", "--tilt", "free")
    assert d["arrangement"] == "DB" and d["preload"] == 500.0 and len(d["bearings"]) == 2
    fr = [e["Fr"] for e in d["bearings"]]
    fa = [e["Fa"] for e in d["bearings"]]
    assert sum(fr) == pytest.approx(2000.0, rel=1e-6)  # both push along +x: the shares add up to F_r
    assert fa[0] - fa[1] == pytest.approx(600.0, rel=1e-6)  # bearing 0 carries +z: the difference is F_a
    assert np.asarray(d["stiffness"]).shape == (5, 5)
    if command == "stiffness":  # averaged over the ball-set phases as a single bearing's (docs/defaults.md)
        from exudyn_bearing.solvers.quasistatic.coefficients import DEFAULT_N_PHASES

        assert d["phases"] == DEFAULT_N_PHASES and d["phase_spread_stiffness"] > 0.0
    if command != "stiffness":
        assert all(e["C"] > 0.0 and e["L10"] > 0.0 for e in d["bearings"])
        lives = [e["L10"] for e in d["bearings"]]
        assert d["system_life"]["L10"] < min(lives)  # the set fails before its weaker bearing alone
        assert d["system_life"]["L10"] == pytest.approx(sum(v ** (-10 / 9) for v in lives) ** -0.9, rel=1e-12)


@pytest.mark.parametrize("argv, flag", [
    (["--preload", "100"], "--preload"),
    (["--arrangement", "DB", "--preload-class", "light"], "--preload-class"),
    (["--arrangement", "DT", "--Fa", "500", "--preload", "100"], "--preload"),
    (["--arrangement", "DB", "--My", "2", "--tilt", "free"], "--spacing"),
    (["--arrangement", "DB", "--preload-displacement", "0.01"], "--preload-displacement"),
])
def test_cli_pair_refusals(capsys, argv, flag):
    from exudyn_bearing.cli import main

    assert main(["static", B, "--Fr", "100", *argv]) != 0
    err = capsys.readouterr().err
    assert f"error: {flag}:" in err


def _shaft(load, torque=(0.0, 0.0, 0.0)):
    """A 2.5 kg shaft at the origin with its load, a ground marker and a pure damper that settles it (as in
    tests/test_levels.py)."""
    exu = pytest.importorskip("exudyn")
    from exudyn.itemInterface import (
        LoadForceVector,
        LoadTorqueVector,
        MarkerBodyRigid,
        NodeRigidBodyRxyz,
        ObjectConnectorRigidBodySpringDamper,
        ObjectGround,
        ObjectRigidBody,
    )

    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    node = mbs.AddNode(NodeRigidBodyRxyz(referenceCoordinates=[0.0] * 6))
    body = mbs.AddObject(ObjectRigidBody(nodeNumber=node, mass=2.5, inertia=[0.01, 0.01, 5e-4, 0, 0, 0]))
    m_g = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground))
    m_b = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body))
    mbs.AddLoad(LoadForceVector(markerNumber=m_b, loadVector=list(load)))
    mbs.AddLoad(LoadTorqueVector(markerNumber=m_b, loadVector=list(torque)))
    mbs.AddObject(ObjectConnectorRigidBodySpringDamper(markerNumbers=[m_g, m_b],
                                                       damping=np.diag([2e4, 2e4, 2e4, 20.0, 20.0, 0.0])))
    return exu, sc, mbs, node, m_b, m_g


@pytest.mark.parametrize("arrangement, load, torque", [("DB", (3000.0, 0.0, 1000.0), (0.0, 20.0, 0.0)),
                                                       ("DF", (3000.0, 0.0, -1000.0), (0.0, 20.0, 0.0)),
                                                       ("DT", (0.0, 0.0, 2000.0), (0.0, 0.0, 0.0))])
def test_create_ball_bearing_pair_settles_at_solve_pair(arrangement, load, torque):
    """CreateBallBearing(model="quasistatic", arrangement=...) between a shaft and ground: the shaft settles
    where solve_pair puts it (0.5 %, the levels' tolerance in tests/test_levels.py)."""
    import exudyn_bearing as eb

    exu, _sc, mbs, node, m_b, m_g = _shaft(load, torque)  # _sc keeps the system alive
    preload = None if arrangement == "DT" else F0
    br = eb.CreateBallBearing(mbs, B, m_b, m_g, model="quasistatic", arrangement=arrangement, preload=preload,
                              spacing=L, initialLoad=(load[0], load[2]))
    mbs.Assemble()
    ss = br.SimulationSettings(0.03)
    mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    pos = mbs.GetNodeOutput(node, exu.OutputVariableType.Position)
    rot = mbs.GetNodeOutput(node, exu.OutputVariableType.Rotation)
    ref = solve_pair(B, arrangement, Fr=load[0], Fa=load[2], My=torque[1], preload=preload, spacing=L,
                     ring_growth=False).displacement
    scale = np.abs(ref[:3]).max()
    assert pos[2] == pytest.approx(ref[2], rel=5e-3)
    assert pos[0] == pytest.approx(ref[0], abs=5e-3 * scale)
    assert rot[1] * L == pytest.approx(ref[4] * L, abs=5e-3 * scale)
    # the force of the bearings on the shaft balances the load
    assert br.samples()["force"][-1][2] == pytest.approx(-load[2], rel=5e-3)


def test_create_ball_bearing_pair_refusals():
    import exudyn_bearing as eb

    _exu, _sc, mbs, _node, m_b, m_g = _shaft((0.0, 0.0, 0.0))
    with pytest.raises(InputError, match="^spacing: "):
        eb.CreateBallBearing(mbs, B, m_b, m_g, model="quasistatic", arrangement="DB", preload=F0)
    with pytest.raises(InputError, match="^model: "):
        eb.CreateBallBearing(mbs, B, m_b, m_g, model="linear", arrangement="DB", preload=F0, spacing=L)
    with pytest.raises(InputError, match="^coefficientSpeeds: "):
        eb.CreateBallBearing(mbs, B, m_b, m_g, model="quasistatic", arrangement="DB", spacing=L,
                             coefficientSpeeds=[0.0])
    with pytest.raises(InputError, match="^preload: "):
        eb.CreateBallBearing(mbs, B, m_b, m_g, model="quasistatic", arrangement="DT", preload=F0, spacing=L,
                             initialLoad=(0.0, 1000.0))


def test_summary_without_spacing_says_why_there_is_no_tilt_stiffness():
    p = solve_pair(B, "DB", Fr=2000.0, Fa=600.0, preload=F0)
    text = p.summary()
    assert "nan" not in text and "k_tilt = n/a (the tilt is held without a spacing" in text
    assert "tilt_x held (no spacing); reaction 0 N m" in text      # round-off of the symmetric case shown as 0
