"""The quasi-static level's node formulation (``formulation="node"``, solvers/quasistatic/levels/nodes.py) against
its connector formulation: the same connector quantities from the nodes' coordinates, the same motion within
Newton's tolerance, the level's own Jacobian equal to the derivatives of its force, fewer evaluations per step,
one call for the bearings between the same nodes, and the option's errors."""
import math
import warnings

import numpy as np
import pytest

exu = pytest.importorskip("exudyn")
from exudyn.itemInterface import (  # noqa: E402
    LoadForceVector,
    MarkerBodyRigid,
    MarkerNodeRigid,
    NodeRigidBodyRotVecLG,
    NodeRigidBodyRxyz,
    ObjectGround,
    ObjectRigidBody,
    SensorNode,
)

import exudyn_bearing as eb  # noqa: E402
from exudyn_bearing.data import InputError  # noqa: E402
from exudyn_bearing.model.rigid_nodes import rot_xyz  # noqa: E402
from exudyn_bearing.solvers.quasistatic.levels import base as level_base  # noqa: E402

LOAD, OMEGA, HALF_SPAN = 6000.0, 500.0, 0.1


def rotor(formulation, t_end=None, relative_tolerance=None, step=1e-4):
    """The 2.5 kg shaft on two 6208 (z = -+0.1 m) under 6000 N at 500 rad/s of
    validation/consistency/levels_damping.py, started at the bearings' static pose; run for ``t_end`` if given
    (GeneralizedAlpha at ``step``, Newton's relative tolerance ``relative_tolerance`` if given, else the
    bearings' SimulationSettings'). Returns (mbs, bearings, position sensor, Python calls of the run)."""
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    node = mbs.AddNode(NodeRigidBodyRxyz(referenceCoordinates=[0.0] * 6, initialVelocities=[0, 0, 0, 0, 0, OMEGA]))
    body = mbs.AddObject(ObjectRigidBody(nodeNumber=node, mass=2.5, inertia=[0.0135, 0.0135, 5e-4, 0, 0, 0]))
    mbs.AddLoad(LoadForceVector(markerNumber=mbs.AddMarker(MarkerBodyRigid(bodyNumber=body)), loadVector=[LOAD, 0, 0]))
    bearings = []
    for z in (-HALF_SPAN, HALF_SPAN):
        m_in = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body, localPosition=[0.0, 0.0, z]))
        m_out = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground, localPosition=[0.0, 0.0, z]))
        bearings.append(eb.CreateBallBearing(mbs, "6208", m_in, m_out, model="quasistatic", initialOmega=OMEGA,
                                             initialLoad=(0.5 * LOAD, 0.0), formulation=formulation))
    q0 = np.array(bearings[0].initialCoordinates, float)
    q0[3:] = 0.0
    mbs.SetNodeParameter(node, "initialCoordinates", list(q0))
    sensor = mbs.AddSensor(SensorNode(nodeNumber=node, outputVariableType=exu.OutputVariableType.Position,
                                      storeInternal=True, writeToFile=False))
    mbs.Assemble()
    calls = 0
    if t_end is not None:
        ss = bearings[0].SimulationSettings(t_end, stepSize=step)
        ss.solution.sensors.writePeriod = 1e-4
        if relative_tolerance is not None:
            ss.timeIntegration.newton.relativeTolerance = relative_tolerance
        n0 = level_base.python_calls[0]
        with eb.filter_exudyn_notes():
            mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
        calls = level_base.python_calls[0] - n0
    return mbs, bearings, sensor, calls


@pytest.fixture(scope="module")
def runs():
    """5 ms of the rotor at both formulations and, as the yardsticks, at Newton's relative tolerance 1e-10 with
    the step and with half of it."""
    out = {}
    for key, form, rel, step in (("connector", "connector", None, 1e-4), ("node", "node", None, 1e-4),
                                 ("tight", "connector", 1e-10, 1e-4), ("half", "connector", 1e-10, 5e-5)):
        mbs, bearings, sensor, calls = rotor(form, t_end=5e-3, relative_tolerance=rel, step=step)
        out[key] = {"pos": mbs.GetSensorStoredData(sensor), "bearings": bearings, "calls": calls,
                    "evaluations": bearings[0].samples()["evaluations"], "mbs": mbs}
    return out


def test_auto_takes_the_node_formulation_on_rxyz_nodes_and_ground():
    mbs, bearings, sensor, _ = rotor("auto")
    assert [b.formulationUsed for b in bearings] == ["node", "node"]
    assert bearings[0].object == bearings[1].object  # one object, one call for both bearings
    mbs, bearings, sensor, _ = rotor("connector")
    assert [b.formulationUsed for b in bearings] == ["connector", "connector"]
    assert bearings[0].object != bearings[1].object


def test_node_run_is_the_connector_run_within_newtons_tolerance(runs):
    # both formulations stop Newton at the relative tolerance 1e-4 of SimulationSettings on the same residual,
    # with different Jacobians. That tolerance was chosen to move the motion by less than 0.5 % of what halving
    # the step moves it (0.036 % and 0.05 % on the one-bearing shaft: docs/theory/levels.md, "Cost"); both runs
    # stay within 1 % of the step's own error of the run at 1e-10, and so within 2 % of each other.
    tight = runs["tight"]["pos"]
    half = runs["half"]["pos"]
    step_error = np.array([np.abs(np.interp(tight[:, 0], half[:, 0], half[:, i]) - tight[:, i]).max()
                           for i in (1, 2)])
    conn, node = (runs[k]["pos"][:, 1:3] for k in ("connector", "node"))
    assert np.all(np.abs(conn - tight[:, 1:3]).max(axis=0) < 0.01 * step_error)
    assert np.all(np.abs(node - tight[:, 1:3]).max(axis=0) < 0.01 * step_error)
    assert np.all(np.abs(node - conn).max(axis=0) < 0.02 * step_error)


def test_node_formulation_needs_fewer_evaluations_and_one_call_per_evaluation(runs):
    steps = round(5e-3 / 1e-4)
    per_step = {k: runs[k]["evaluations"] / steps for k in ("connector", "node")}
    # the connector's Jacobian is computed once (modified Newton): about 3.6 evaluations per step; the level's
    # own Jacobian every step: about 2.2 (measured 3.63 and 2.19 on 0.2 s, bench_qs_rotor.py)
    assert per_step["node"] < per_step["connector"] - 1.0
    assert per_step["node"] < 2.6
    # the connector calls Python once per evaluation and bearing; the node formulation once per evaluation for
    # both bearings, plus once per step for the Jacobian
    assert runs["connector"]["calls"] == 2 * runs["connector"]["evaluations"]
    assert runs["node"]["calls"] == runs["node"]["evaluations"] + steps


def test_node_samples_are_the_connector_samples(runs):
    # the sensors' and samples' quantities agree as the motion does (the force through the ring pose: stiffness
    # 1.8e8 N/m times the motion's bound of the test above, 2 % of the load here)
    a, b = (runs[k]["bearings"][0].samples() for k in ("connector", "node"))
    assert a["t"] == pytest.approx(b["t"])
    assert np.abs(a["force"][:, 0] - b["force"][:, 0]).max() < 0.02 * 0.5 * LOAD
    assert np.abs(a["cage_angle"] - b["cage_angle"]).max() < 1e-6
    assert np.abs(a["q_max_inner"] - b["q_max_inner"]).max() < 0.02 * a["q_max_inner"].max()


def _housing_system(formulation):
    """A shaft (Rxyz node with non-zero reference coordinates, tilted and turned) in a housing on its own Rxyz
    node (moving, turned), one 6208 between markers with local positions: every term of the kinematics."""
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    housing_ref = [0.01, -0.02, 0.03, 0.02, -0.01, 0.3]
    local = np.array([0.0, 0.0, 0.02])
    centre = np.array(housing_ref[:3]) + np.reshape(rot_xyz(*housing_ref[3:]), (3, 3)) @ local
    hn = mbs.AddNode(NodeRigidBodyRxyz(referenceCoordinates=housing_ref,
                                       initialVelocities=[0.01, -0.02, 0.005, 0.3, -0.2, 0.1]))
    hb = mbs.AddObject(ObjectRigidBody(nodeNumber=hn, mass=5.0, inertia=[0.05, 0.05, 0.05, 0, 0, 0]))
    sn = mbs.AddNode(NodeRigidBodyRxyz(referenceCoordinates=[*centre, *housing_ref[3:]],
                                       initialCoordinates=[2e-6, -1e-6, 1e-6, 2e-5, -1e-5, 1.0],
                                       initialVelocities=[0.02, 0.01, -0.01, 0.5, 0.1, 400.0]))
    sb = mbs.AddObject(ObjectRigidBody(nodeNumber=sn, mass=2.5, inertia=[0.0135, 0.0135, 5e-4, 0, 0, 0]))
    m_out = mbs.AddMarker(MarkerBodyRigid(bodyNumber=hb, localPosition=list(local)))
    m_in = mbs.AddMarker(MarkerBodyRigid(bodyNumber=sb, localPosition=[0.0, 0.0, 0.0]))
    br = eb.CreateBallBearing(mbs, "6208", m_in, m_out, model="quasistatic", initialOmega=400.0,
                              formulation=formulation)
    mbs.Assemble()
    return mbs, br


def test_node_kinematics_are_the_connectors():
    # one evaluation at the initial state, with a moving, turned housing: the ring pose (d, tilts), the relative
    # spin and the force the level computed from them agree with what Exudyn's connector handed its user function
    got = {}
    for form in ("connector", "node"):
        mbs, br = _housing_system(form)
        ss = br.SimulationSettings(1e-4)
        ss.timeIntegration.numberOfSteps = 1
        ss.timeIntegration.generalizedAlpha.computeInitialAccelerations = True
        ss.solution.sensors.writePeriod = 1e-4
        with eb.filter_exudyn_notes(), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
        got[form] = br.samples()
    a, b = got["connector"], got["node"]
    assert np.abs(a["displacement"][0] - b["displacement"][0]).max() < 1e-12  # [m, rad]: round-off
    assert a["cage_speed"][0] == pytest.approx(b["cage_speed"][0], rel=1e-9)
    assert np.allclose(a["force"][0], b["force"][0], rtol=1e-6, atol=1e-6 * np.abs(a["force"][0]).max())


def _body(node_item):
    """A system with a 2.5 kg body on ``node_item`` and ground: (system container, mbs, node, body marker, ground
    marker, node-rigid marker)."""
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    node = mbs.AddNode(node_item)
    body = mbs.AddObject(ObjectRigidBody(nodeNumber=node, mass=2.5, inertia=[0.01, 0.01, 5e-4, 0, 0, 0]))
    return (sc, mbs, node, mbs.AddMarker(MarkerBodyRigid(bodyNumber=body)),
            mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground)), mbs.AddMarker(MarkerNodeRigid(nodeNumber=node)))


def test_level_jacobian_is_the_derivative_of_its_force():
    # K and C of the kernel (mats) against central differences of the level's force at the 6208's operating pose
    sc, mbs, node, m_b, m_g, _ = _body(NodeRigidBodyRxyz(referenceCoordinates=[0.0] * 6))
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="quasistatic", initialLoad=(3000.0, 500.0),
                              initialOmega=OMEGA, formulation="node")
    u0 = np.array(br.initialRingDisplacement)

    def force(u, rates=None):
        rates = np.zeros(5) if rates is None else rates
        br._evaluate(list(u[:3]), [u[3], u[4], 0.4], list(rates[:3]), [rates[3], rates[4], OMEGA])
        return br._force.copy()

    num_k, num_c = np.zeros((5, 5)), np.zeros((5, 5))
    for j in range(5):
        e = np.zeros(5)
        e[j] = 1e-9 if j < 3 else 1e-7
        num_k[:, j] = -(force(u0 + e) - force(u0 - e)) / (2.0 * e[j])
        num_c[:, j] = -(force(u0, 1e3 * e) - force(u0, -1e3 * e)) / (2e3 * e[j])
    force(u0)
    k, c = br._mats[:25].reshape(5, 5), br._mats[25:].reshape(5, 5)
    # the condensation holds each contact's Hertz constant at its contact angle (its change with the angle, which
    # the differences see, is left out): 9e-5 of the largest entry under this axial load, 6e-10 under a radial
    # load alone; a Jacobian off by 1e-3 would still take Newton to its tolerance in one or two iterations
    assert np.abs(k - num_k).max() < 5e-4 * np.abs(num_k).max()
    # C: the damping force is linear in the rates; the differences' round-off (force 1e-13 relative over rate
    # steps of 1e-6 m/s) is 4e-6 of the largest entry here
    assert np.abs(c - num_c).max() < 2e-5 * np.abs(num_c).max()


def test_formulation_option_errors_and_fallback():
    sc, mbs, node, m_b, m_g, m_n = _body(NodeRigidBodyRotVecLG(referenceCoordinates=[0.0] * 6))
    with pytest.raises(InputError, match="^formulation: must be one of"):
        eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="quasistatic", formulation="generic")
    with pytest.raises(InputError, match="^formulation: 'node' needs .*RotVecLG"):
        eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="quasistatic", formulation="node")
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="quasistatic")  # auto: the connector here
    assert br.formulationUsed == "connector"
    with pytest.raises(InputError, match="^formulation: not an option of model='linear'"):
        eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="linear", formulation="node")


def test_node_rigid_marker_takes_the_node_formulation():
    sc, mbs, node, m_b, m_g, m_n = _body(NodeRigidBodyRxyz(referenceCoordinates=[0.0] * 6))
    br = eb.CreateBallBearing(mbs, "6208", m_n, m_g, model="quasistatic")
    assert br.formulationUsed == "node"
    assert math.isfinite(br.initialCoordinates[0])
    # the rings on one body: the connector under "auto", an error naming formulation under "node"
    assert eb.CreateBallBearing(mbs, "6208", m_n, m_b, model="quasistatic").formulationUsed == "connector"
    with pytest.raises(InputError, match="^formulation: 'node' needs .* both ring markers sit on node"):
        eb.CreateBallBearing(mbs, "6208", m_n, m_b, model="quasistatic", formulation="node")


def test_moving_housing_run_is_within_newtons_tolerance():
    # the housing on its own moving node (two nodes in the object, the outer ring's Jacobian blocks): 5 ms of the
    # shaft's motion at the node formulation within 1 % of the step's own error of the connector run at Newton's
    # relative tolerance 1e-10, as in the rotor test above; fewer evaluations per step than the connector's
    runs = {}
    for key, form, rel, step in (("node", "node", None, 1e-4), ("connector", "connector", None, 1e-4),
                                 ("tight", "connector", 1e-10, 1e-4), ("half", "connector", 1e-10, 5e-5)):
        mbs, br = _housing_system(form)
        sensor = mbs.AddSensor(SensorNode(nodeNumber=1, outputVariableType=exu.OutputVariableType.Position,
                                          storeInternal=True, writeToFile=False))  # node 1: the shaft
        mbs.Assemble()
        ss = br.SimulationSettings(5e-3, stepSize=step)
        ss.solution.sensors.writePeriod = 1e-4
        if rel is not None:
            ss.timeIntegration.newton.relativeTolerance = rel
        with eb.filter_exudyn_notes():
            mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
        runs[key] = (mbs.GetSensorStoredData(sensor), br.samples()["evaluations"] / round(5e-3 / step))
    tight, half = runs["tight"][0], runs["half"][0]
    step_error = np.array([np.abs(np.interp(tight[:, 0], half[:, 0], half[:, i]) - tight[:, i]).max()
                           for i in (1, 2, 3)])
    assert np.all(np.abs(runs["node"][0][:, 1:] - tight[:, 1:]).max(axis=0) < 0.01 * step_error)
    assert runs["node"][1] < runs["connector"][1] - 1.0


def test_node_jacobian_is_the_matrix_product_of_its_docstring():
    # node_jacobian's products (loops over the node work array's scratch, no allocation) against NumPy's of the
    # module docstring's d(lhs_i)/dq_j = f2 B_i^T K6 B_j + f2t B_i^T C6 B_j with both rings on moving, turned nodes
    # (all four blocks), K6 and C6 from the level's K and C of one evaluation: equal to round-off
    from exudyn_bearing.solvers.quasistatic.levels import nodes

    mbs, br = _housing_system("node")
    group = br._group
    n = 6 * len(group.nodes)
    q = np.array([2e-6, -1e-6, 1e-6, 2e-5, -1e-5, 1.0, 1e-6, 3e-6, -2e-6, 1e-5, 2e-5, 0.5])[:n]
    qt = np.array([0.02, 0.01, -0.01, 0.5, 0.1, 400.0, 0.01, -0.02, 0.005, 0.3, -0.2, 0.1])[:n]
    group._force(mbs, 0.0, group.object, q, qt)
    f2, f2t = 0.7, 0.3
    jac = np.zeros((n, n))
    nodes.node_jacobian(br._nws, f2, f2t, jac)
    nws = br._nws
    kk, cc = nws[nodes.N_MATS:nodes.N_MATS + 25].reshape(5, 5), nws[nodes.N_MATS + 25:nodes.N_MATS + 50].reshape(5, 5)
    conn = nws[nodes.N_CONN:nodes.N_CONN + 12]
    m = np.zeros((6, 6))
    m[:5, :5] = f2 * kk + f2t * cc
    m[:5, 4] -= f2 * cc[:, 3] * conn[11]
    m[:5, 3] += f2 * cc[:, 4] * conn[11]
    m[:5, 5] = f2t * (-cc[:, 3] * conn[4] + cc[:, 4] * conn[3])
    s0 = nws[nodes.N_STATES:nodes.N_STATES + nodes._NS]
    b = []
    for i in range(2):
        bi = np.zeros(36)
        nodes._b_matrix(s0, nws[nodes.N_STATES + nodes._NS * i:nodes.N_STATES + nodes._NS * (i + 1)],
                        1.0 if i == 1 else -1.0, bi)
        b.append(bi.reshape(6, 6))
    want = np.zeros((n, n))
    offs = [int(nws[nodes.N_OFFS + i]) for i in range(2)]
    assert sorted(offs) == [0, 6]  # both rings on nodes
    for i in range(2):
        for j in range(2):
            want[offs[i]:offs[i] + 6, offs[j]:offs[j] + 6] += b[i].T @ m @ b[j]
    assert np.abs(want).max() > 0.0
    assert np.abs(jac - want).max() <= 1e-12 * np.abs(want).max()


def test_group_call_is_each_bearings_own_evaluation():
    # the group's one compiled call for both bearings (element.group_level_forces) against each bearing's own
    # evaluation (node_level_forces with the steps around it in Python), on two fresh rotors at the same two
    # states, the second at a speed outside the band of the grooves' last update (the group's call hands that
    # back to Python, which evaluates again at the new grooves): the same generalized force, balls, K and C
    mbs_a, bs_a, _, _ = rotor("node")
    _, bs_b, _, _ = rotor("node")
    group = bs_a[0]._group
    q = np.array([24.7e-6, 1e-7, 2e-7, 1e-5, -2e-5, 0.3])
    states = ((0.0, q, np.array([1e-3, -2e-3, 1e-3, 0.1, 0.2, OMEGA])),
              (1e-4, 1.01 * q, np.array([2e-3, 1e-3, -1e-3, -0.1, 0.1, 1.3 * OMEGA])))
    for t, qq, qt in states:
        got = group._force(mbs_a, t, group.object, qq, qt).copy()
        want = np.zeros_like(got)
        for b in bs_b:
            b._node_evaluation(t, qq, qt, want)
    lo, hi = bs_a[0]._geo_band
    assert lo <= 1.3 * OMEGA <= hi and not lo <= OMEGA <= hi  # the grooves were updated
    scale = np.abs(want).max()
    assert scale > 1e3 and np.allclose(got, want, rtol=0.0, atol=1e-12 * scale)
    for a, b in zip(bs_a, bs_b):
        assert np.allclose(a._balls, b._balls, rtol=1e-12, atol=0.0)
        assert np.allclose(a._mats, b._mats, rtol=1e-12, atol=1e-12 * np.abs(b._mats).max())
        assert a._qmax[0] == pytest.approx(b._qmax[0], rel=1e-12)


def test_a_second_run_starts_over_and_repeats_the_first():
    # the group's force call takes the next step of a run without the per-bearing steps before the kernel
    # (LevelBearing._begin does nothing then but take the time and count); a second SolveDynamic on the same
    # mbs is a new run, which must start over (restart, samples, warm starts, cage angle) and repeat the first
    mbs, bearings, sensor, _ = rotor("node", t_end=3e-3)
    first = [(b.samples(), b.restarts) for b in bearings]
    pos = mbs.GetSensorStoredData(sensor)
    ss = bearings[0].SimulationSettings(3e-3, stepSize=1e-4)
    ss.solution.sensors.writePeriod = 1e-4
    with eb.filter_exudyn_notes():
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    assert np.array_equal(mbs.GetSensorStoredData(sensor), pos)
    for b, (smp, restarts) in zip(bearings, first):
        assert b.restarts == restarts + 1
        again = b.samples()
        assert again["evaluations"] == smp["evaluations"] > 2 * len(smp["t"])
        for key in ("t", "displacement", "force", "cage_angle", "ball_load_inner"):
            assert np.array_equal(again[key], smp[key]), key


@pytest.mark.parametrize("formulation", ["node", "connector"])
def test_sensors_read_the_last_evaluation(formulation):
    # the level's sensors (LevelBearing._add_items) at the run's last write: the force on the inner ring
    # -A0 f and on the outer ring A0 f (A0 the joint frame's rotation the connector handed at the last sample;
    # none in the node formulation), the pose, the cage speed and the largest ball loads of the last evaluation
    mbs, bearings, _, _ = rotor(formulation, t_end=2e-3)
    for b in bearings:
        last = {k: mbs.GetSensorStoredData(s)[-1, 1:] for k, s in b.sensors.items()}
        rot = np.eye(3) if b._rot0 is None else b._rot0
        assert (b._rot0 is None) == (formulation == "node")
        force = rot @ b._out[:3]
        assert np.abs(force).max() > 1e3
        assert np.array_equal(last["outerRingForce"], force)
        assert np.array_equal(last["innerRingForce"], -force)
        assert np.array_equal(last["ringDisplacement"], b._pose)
        assert last["cageSpeed"][0] == b._cage[1] != 0.0
        assert (last["qMaxInner"][0], last["qMaxOuter"][0]) == (b._qmax[0], b._qmax[1])
        assert b._qmax[0] > 0.0
