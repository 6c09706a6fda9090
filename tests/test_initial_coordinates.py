"""``initialCoordinates`` of every bearing level is in world components: a rotor whose bearing axis is not the
world z axis (the outer ring's body turned) starts at the operating point from the documented
``mbs.SetNodeParameter(node, "initialCoordinates", list(bearing.initialCoordinates))``."""
import warnings

import numpy as np
import pytest

import exudyn_bearing as eb

FR, OMEGA = 3000.0, 500.0


def _turn():
    """Local z onto the world x axis (a horizontal shaft along x), local x onto the world y axis."""
    return np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])


def _rotor(rot, model, **kw):
    """A 2.5 kg shaft (a Lie-group rotation-vector node turned by ``rot``: an Rxyz node along x sits at its
    angles' singularity) in a 6208 whose outer ring is ground turned by ``rot``,
    under FR along the outer ring's x axis; the bearing at ``model``."""
    import exudyn as exu
    from exudyn.itemInterface import (LoadForceVector, MarkerBodyRigid, NodeRigidBodyRotVecLG, ObjectGround,
                                      ObjectRigidBody)
    from exudyn.rigidBodyUtilities import RotationMatrix2RotationVector

    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    m_out = mbs.AddMarker(MarkerBodyRigid(bodyNumber=mbs.AddObject(ObjectGround(referenceRotation=rot)),
                                          localPosition=[0.0] * 3))
    node = mbs.AddNode(NodeRigidBodyRotVecLG(referenceCoordinates=[0.0] * 3 + list(RotationMatrix2RotationVector(rot)),
                                             initialVelocities=[0.0] * 5 + [OMEGA]))  # the body's own z
    body = mbs.AddObject(ObjectRigidBody(nodeNumber=node, mass=2.5, inertia=[0.02, 0.02, 0.0005, 0, 0, 0]))
    m_in = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body, localPosition=[0.0] * 3))
    mbs.AddLoad(LoadForceVector(markerNumber=m_in, loadVector=list(rot @ [FR, 0.0, 0.0])))
    br = eb.CreateBallBearing(mbs, "6208", m_in, m_out, model=model, initialLoad=(FR, 0.0), initialOmega=OMEGA,
                              **kw)
    return sc, mbs, node, br


@pytest.mark.parametrize("model", ["balls", "linear", "quasistatic", "reduced"])
def test_initial_coordinates_are_world_components(model):
    kw = {"cage": "none"} if model == "reduced" else {}
    _sc, _mbs, _node, straight = _rotor(np.eye(3), model, **kw)
    _sc, _mbs, _node, turned = _rotor(_turn(), model, **kw)
    d = np.asarray(straight.initialRingDisplacement, float)
    assert d[0] > 1e-6  # the inner ring sits off centre along the load
    np.testing.assert_allclose(straight.initialCoordinates[:3], d[:3], rtol=0, atol=1e-15)
    np.testing.assert_allclose(turned.initialCoordinates[:3], _turn() @ d[:3], rtol=0, atol=1e-12 * d[0])


LEVEL_OPTIONS = {"balls": {"mode": "fast", "stepSize": 5e-6, "sampleInterval": 1e-4},
                 "quasistatic": {}, "reduced": {"cage": "none"}}


@pytest.mark.parametrize("model", list(LEVEL_OPTIONS))
def test_a_rotor_along_x_started_from_initial_coordinates_is_at_its_operating_point(model):
    # the turned rotor started from initialCoordinates: the ball loads of the straight rotor (before, the
    # displacement went in along the world x axis, the shaft's axis, and the ball element's Q_max came out twice
    # the operating point's)
    out = {}
    for name, rot in (("straight", np.eye(3)), ("turned", _turn())):
        sc, mbs, node, br = _rotor(rot, model, **LEVEL_OPTIONS[model])
        mbs.SetNodeParameter(node, "initialCoordinates", list(br.initialCoordinates))
        mbs.Assemble()
        ss = br.SimulationSettings(0.004)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
            out[name] = br.results().summary()
    a, b = out["straight"], out["turned"]
    assert a["q_max_inner"] == pytest.approx(1470.0, rel=0.02)
    assert b["q_max_inner"] == pytest.approx(a["q_max_inner"], rel=1e-3)


@pytest.mark.parametrize("model", ["quasistatic", "linear"])
def test_the_level_samples_the_converged_step(model):
    # the samples of a level are the converged state of their step: the ringDisplacement sensor (written after
    # the step) at the same times, to round-off (the first evaluation of a step, Newton's predictor, was up to
    # 16 nm off the converged 24.6 um)
    sc, mbs, node, br = _rotor(np.eye(3), model)
    mbs.SetNodeParameter(node, "initialCoordinates", list(br.initialCoordinates))
    mbs.SetLoadParameter(0, "loadVector", [1.2 * FR, 0.3 * FR, 0.0])  # off the operating point: the ring moves
    mbs.Assemble()
    ss = br.SimulationSettings(0.01)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    smp = br.samples()
    sensor = mbs.GetSensorStoredData(br.sensors["ringDisplacement"])
    assert np.ptp(smp["displacement"][:, 1]) > 1e-7  # the ring moved (tenths of a micrometre and more)
    for k, t in enumerate(smp["t"][1:], start=1):
        row = np.flatnonzero(np.isclose(sensor[:, 0], t, rtol=0, atol=1e-9))
        assert row.size == 1, t
        np.testing.assert_allclose(smp["displacement"][k, :2], sensor[row[0], 1:3], rtol=0, atol=1e-13)
