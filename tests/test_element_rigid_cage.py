"""The rigid cage in the Exudyn element (docs/theory/cage.md, docs/theory/dynamics.md#the-exudyn-element): both
modes against the reference engine on the same scene from the same analytic state, the energy balance, the
summary's cage outputs, the cage as an Exudyn rigid body a user can put sensors on, the bearing axis off the world z
axis (the same model turned), and the refusals.

The scene: the 6208 under F_r = 3000 N at 500 rad/s on a horizontal shaft (gravity on the cage) with a cage
unbalance of 2 g mm, 6 ms at the reference engine's 4 us, with the estimated cage's clearances narrowed
(pockets 60 um, land 30 um) so that the balls reach their pockets and the cage its land within the short run,
guided by the outer land (its reaction on the fixed ring) or the inner land (on the moving inner ring); the
land is taken linearly implicit (cage_damping="implicit"), as its 30 um film needs below 1 us explicitly.

Tolerances. The fast mode integrates the cage with the balls in the reference engine's velocity-Verlet
sub-steps on the same kernel: it is the reference scheme, equal up to rounding (measured: 3e-15 m in the
cage centre, 1e-10 rad/s in its speed); asserted at 1e-6 of the body mode's tolerances. The body mode
evaluates the same kernel at the half-step velocities Exudyn's velocity Verlet passes, but Exudyn integrates
the cage body (a mass-matrix solve) and rounds otherwise; the pocket impacts amplify rounding (the inner-land
cage's orbit is irregular), and its samples hold the half-step velocities. Measured (outer land / inner land;
the module's _run with prints): cage centre within 1.2e-8 / 2.2e-8 m (0.04 / 0.07 % of the land clearance),
cage angle 1e-6 / 2e-6 rad (0.05 / 0.1 % of c_p / r_p), sampled cage speed 0.054 / 0.065 rad/s, its mean 4e-6 /
3e-6, Q_max 1e-6 / 4e-6, every ball's load at every sample 0.08 / 0.09 % of Q_max, pocket and land losses and
the mean land force 0.8 / 0.1 %, the 99.9th percentile of the pocket forces 1.0 / 1.4 %; without the unbalance
the inner land's ran to 0.4 % of the clearance, 0.34 % of Q_max and 0.8 % in the losses. Asserted: the centre
within 1 % of the land clearance and the angle within 1 % of c_p / r_p, the sampled speed within 1e-3 of the
ring speed, the mean cage speed within 0.1 % and Q_max within 0.5 % (the cross-engine checks of the torus
cage, tests/test_cage_damping.py), the ball loads within 1 % of Q_max, the losses and the land force within
2 % (means over the window of an impacting cage), the pocket forces' 99.9th percentile within 15 % (as in
tests/test_cage_damping.py: impacts)."""
import dataclasses
import warnings

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing.data import InputError
from exudyn_bearing.data.cages import estimated_cage
from exudyn_bearing.model import layout as L

B = eb.catalog["6208"]
CAGE = dataclasses.replace(estimated_cage(B), pocket_clearance=60e-6, land_clearance=30e-6, unbalance=2e-6)
SCENE = eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.006, dt=4e-6, sample_dt=1e-4, cage="rigid", rigid_cage=CAGE,
                    gravity=(0.0, -9.81, 0.0), cage_damping="implicit")


def _scene(guidance):
    return SCENE.replace(rigid_cage=dataclasses.replace(CAGE, guidance=guidance))


def _run(engine, mode=None, guidance="outer_land"):
    from exudyn_bearing.solvers.element.engine import ExudynEngine

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        warnings.simplefilter("error", eb.StepSizeWarning)
        if engine == "reference":
            return eb.simulate(B, _scene(guidance))
        return eb.Results(ExudynEngine(B, _scene(guidance), mode=mode).run())


@pytest.fixture(scope="module", params=["outer_land", "inner_land"])
def runs(request):
    # the outer land's reaction goes to the fixed outer ring, the inner land's to the moving inner ring
    g = request.param
    return {"reference": _run("reference", guidance=g), "bodies": _run("exudyn", "bodies", g),
            "fast": _run("exudyn", "fast", g)}


@pytest.fixture(scope="module")
def summaries(runs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        return {k: r.summary() for k, r in runs.items()}


def test_the_scene_loads_pockets_and_land(summaries):
    # the comparison means something only if the cage meets its pockets and its land and moves off centre
    s = summaries["reference"]
    assert s["pocket_force_max"] > 1.0 and s["land_force_mean"] > 0.5 * CAGE.mass(B) * 9.81
    assert s["cage_power_pocket"] > 0.0 and s["cage_power_land"] > 0.0
    assert 0.05 < s["land_eccentricity_max"] < 1.0


@pytest.mark.parametrize("mode, rel", [("bodies", 1.0), ("fast", 1e-6)])
def test_the_element_runs_the_rigid_cage_as_the_reference_engine(runs, summaries, mode, rel):
    # rel: 1 for the body mode's tolerances of the module docstring, 1e-6 of them for the fast mode (the
    # reference scheme)
    ref, ex = runs["reference"].data, runs[mode].data
    a, b = summaries["reference"], summaries[mode]
    assert ex["t"] == pytest.approx(ref["t"], abs=1e-9)
    centre = np.abs(ex["xc"][:, 0] - ref["xc"][:, 0]).max()
    assert centre < rel * 0.01 * CAGE.land_clearance
    assert np.abs(ref["xc"][:, 0, :2]).max() > 0.05 * CAGE.land_clearance   # the centre moved
    for key, tol in (("cage_speed", 1e-3), ("q_max_inner", 5e-3), ("q_max_outer", 5e-3),
                     ("cage_power_pocket", 0.02), ("cage_power_land", 0.02), ("land_force_mean", 0.02)):
        assert b[key] == pytest.approx(a[key], rel=rel * tol), key
    # the ball loads of every ball at every sample
    q_ref, q_ex = ref["diag"][..., L.D_LOAD], ex["diag"][..., L.D_LOAD]
    assert np.abs(q_ex - q_ref).max() < rel * 0.01 * q_ref.max()
    p_a, p_b = (np.percentile(d["cage_load"][:, :, 0], 99.9) for d in (ref, ex))
    assert p_b == pytest.approx(p_a, rel=rel * 0.15)
    # the cage's angle and speed in the samples: relative to the outer ring, as the reference engine's
    assert np.abs(ex["xc"][:, 1, 0] - ref["xc"][:, 1, 0]).max() < rel * 0.01 * CAGE.pocket_clearance / B.pitch_radius
    assert np.abs(ex["vc"][:, 1, 0] - ref["vc"][:, 1, 0]).max() < rel * 1e-3 * SCENE.omega
    assert not ex["xc"][:, 2:].any() and not ex["xc"][:, 1, 1:].any()


@pytest.mark.parametrize("mode", ["reference", "bodies", "fast"])
def test_energy_closes_with_the_rigid_cage_in_the_element(runs, mode):
    # drive work (the rings' and gravity's) = dissipated work (contacts, pockets, land) + the change of the
    # kinetic energy of balls and cage, over the run, within 1 % of the dissipation (the contacts' elastic
    # energy is left out, as in tests/test_cage_damping.py)
    g = runs[mode].data["glob"]
    drive, diss, ke = (g[-1, L.GLOBAL_FIELDS.index(k)] - g[0, L.GLOBAL_FIELDS.index(k)]
                       for k in ("drive_work", "dissipated_work", "kinetic_energy"))
    assert diss > 0.0
    assert abs(drive - diss - ke) < 0.01 * diss
    # the cage's spin is part of the kinetic energy the kernel counts
    d = runs[mode].data
    assert g[-1, L.G_KINETIC] > 0.5 * CAGE.polar_inertia(B) * d["vc"][-1, 1, 0] ** 2


def test_the_summaries_have_the_same_cage_outputs(summaries):
    a, b, c = summaries["reference"], summaries["bodies"], summaries["fast"]
    assert set(a) == set(b) == set(c)
    for key in ("cage_slip", "cage_whirl_radius", "cage_whirl_resolution", "cage_motion", "cage_power_pocket",
                "cage_power_land", "land_eccentricity_max"):
        assert key in b["units"] or key == "cage_motion"
        assert b[key] is not None and c[key] is not None
    assert a["cage_motion"] == b["cage_motion"] == c["cage_motion"]
    # the mean turning rate is a whirl ratio only for a circling orbit; the whirl line needs three bins of the
    # window (6 ms: about one cage revolution, so none)
    assert (b["cage_whirl_ratio"] is None) == (b["cage_motion"] != "circling")
    assert (b["cage_whirl_line"] is None) == (c["cage_whirl_line"] is None)
    assert b["power_loss"]["cage_pocket"] == pytest.approx(b["cage_power_pocket"], rel=1e-12)
    assert b["cage_slip"] == pytest.approx(a["cage_slip"], abs=1e-4)


def _user_model(turn=0.0, **options):
    """A user's model: outer ring on ground (turned by ``turn`` [rad] about the world z axis), inner ring a mass
    point under F_r = 3000 N along the outer ring's x axis, started at its static displacement, the bearing
    with the rigid cage between them."""
    import exudyn as exu
    from exudyn.itemInterface import (LoadForceVector, MarkerBodyRigid, MarkerNodePosition, NodePoint, ObjectGround,
                                      ObjectMassPoint)
    from exudyn.rigidBodyUtilities import RotationMatrixZ

    from exudyn_bearing.model.initial_state import initial_state, ring_mass_estimate

    rot = np.asarray(RotationMatrixZ(turn))
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    m_outer = mbs.AddMarker(MarkerBodyRigid(bodyNumber=mbs.AddObject(ObjectGround(referenceRotation=rot)),
                                            localPosition=[0.0] * 3))
    d0 = rot @ initial_state(B, eb.Scenario(Fr=3000.0, omega=500.0))["ring"][:3]
    node = mbs.AddNode(NodePoint(referenceCoordinates=[0.0] * 3, initialCoordinates=list(d0)))
    mbs.AddObject(ObjectMassPoint(mass=ring_mass_estimate(B), nodeNumber=node))
    m_inner = mbs.AddMarker(MarkerNodePosition(nodeNumber=node))
    mbs.AddLoad(LoadForceVector(markerNumber=m_inner, loadVector=list(rot @ [3000.0, 0.0, 0.0])))
    bearing = eb.CreateBallBearing(mbs, B, m_inner, m_outer, cage="rigid", initialLoad=(3000.0, 0.0),
                                   initialOmega=500.0, innerRingSpeed=lambda t: 500.0, stepSize=4e-6,
                                   tangential="implicit", **options)
    return sc, mbs, bearing


def _solve(mbs, bearing, t_end):
    import exudyn as exu

    mbs.Assemble()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        mbs.SolveDynamic(bearing.SimulationSettings(t_end), solverType=exu.DynamicSolverType.VelocityVerlet)
    return bearing.results()


def test_the_cage_is_an_exudyn_rigid_body_with_sensors_and_markers():
    import exudyn as exu
    from exudyn.itemInterface import SensorBody, SensorMarker

    _sc, mbs, bearing = _user_model(sampleInterval=2e-4)
    assert bearing.items["cageBody"] == bearing.cageBody and bearing.items["cageMarker"] == bearing.cageMarker
    assert mbs.GetObject(bearing.cageBody)["objectType"] == "RigidBody"
    assert mbs.GetNode(bearing.cageNode)["nodeType"] == "RigidBodyRxyz"
    p = bearing.params
    assert mbs.GetObject(bearing.cageBody)["mass"] == pytest.approx(p[L.P_MC], rel=1e-12)
    assert mbs.GetObject(bearing.cageBody)["inertia"][2] == pytest.approx(p[L.P_IC], rel=1e-12)
    s_w = mbs.AddSensor(SensorBody(bodyNumber=bearing.cageBody, storeInternal=True,
                                   outputVariableType=exu.OutputVariableType.AngularVelocity))
    s_x = mbs.AddSensor(SensorMarker(markerNumber=bearing.cageMarker, storeInternal=True,
                                     outputVariableType=exu.OutputVariableType.Position))
    rec = _solve(mbs, bearing, 2e-3)
    assert len(bearing._graphics(mbs, bearing.items["object"])) == 4   # balls, the cage's section, two grooves
    w = mbs.GetSensorStoredData(s_w)
    x = mbs.GetSensorStoredData(s_x)
    # the body turns about the bearing axis at the cage speed the results report, its tilts held at zero
    assert np.abs(w[:, 1:3]).max() < 1e-9 * abs(w[-1, 3])
    assert w[-1, 3] == pytest.approx(rec.cage_speed_series()[-1], rel=1e-4)
    assert x[-1, 1:] == pytest.approx(rec.data["xc"][-1, 0], abs=1e-9)
    assert rec.cage_speed_series()[-1] == pytest.approx(mbs.GetSensorStoredData(bearing.sensors["cageSpeed"])[-1, 1],
                                                        rel=1e-4)


def test_element_options_of_the_rigid_cage():
    from exudyn_bearing.solvers.element.element import element_scenario

    s = element_scenario("6208", cage="rigid", rigidCage=CAGE, gravity=(0.0, -9.81, 0.0))
    assert (s.cage, s.rigid_cage, s.gravity) == ("rigid", CAGE, (0.0, -9.81, 0.0))
    with pytest.raises(InputError, match="^gravity: acts on the rigid cage only"):
        element_scenario("6208", gravity=(0.0, -9.81, 0.0))           # the 6208's default cage is the torus
    assert element_scenario("ACBB-120", gravity=(0.0, -9.81, 0.0)).cage == "rigid"   # the ACBB-120's the rigid one
    assert element_scenario("6208", rigidCage=CAGE).cage == "rigid"   # a RigidCage chooses the rigid cage
    with pytest.raises(InputError, match="^rigidCage: given with cage='torus'"):
        element_scenario("6208", cage=True, rigidCage=CAGE)
    with pytest.raises(InputError, match="^cage: bearing ACBB-120 has no cage balls; use cage='rigid'"):
        _user_model_on("ACBB-120", cage=True)


def _user_model_on(name, **options):
    import exudyn as exu
    from exudyn.itemInterface import MarkerBodyRigid, MarkerNodePosition, NodePoint, ObjectGround, ObjectMassPoint

    mbs = exu.SystemContainer().AddSystem()
    m_outer = mbs.AddMarker(MarkerBodyRigid(bodyNumber=mbs.AddObject(ObjectGround()), localPosition=[0.0] * 3))
    node = mbs.AddNode(NodePoint(referenceCoordinates=[0.0] * 3))
    mbs.AddObject(ObjectMassPoint(mass=0.1, nodeNumber=node))
    return eb.CreateBallBearing(mbs, name, mbs.AddMarker(MarkerNodePosition(nodeNumber=node)), m_outer, **options)


def test_the_cage_node_turns_about_the_bearing_axis():
    # the rigid cage's Exudyn body for an outer ring turned about z (the world z axis), about x (an oblique axis)
    # and onto the world x axis (Tait-Bryan angles singular there: the node turns by its first angle): at t = 0
    # the body's axis of spin is the bearing axis, the outer ring body's local z, and about z the cage's angle
    # in the world is the analytic state's plus the outer ring's turn
    import exudyn as exu
    from exudyn.itemInterface import MarkerBodyRigid, ObjectGround
    from exudyn.rigidBodyUtilities import RotationMatrixX, RotationMatrixY, RotationMatrixZ, RotXYZ2RotationMatrix

    from exudyn_bearing.model.initial_state import initial_state

    for rot, local_axis in ((RotationMatrixZ(0.4), 2), (RotationMatrixX(0.3), 2), (RotationMatrixY(0.5 * np.pi), 0)):
        rot = np.asarray(rot)
        mbs = exu.SystemContainer().AddSystem()
        m_outer, m_inner = (mbs.AddMarker(MarkerBodyRigid(bodyNumber=mbs.AddObject(ObjectGround(referenceRotation=rot)),
                                                          localPosition=[0.0] * 3)) for _ in range(2))
        el = eb.CreateBallBearing(mbs, B, m_inner, m_outer, cage="rigid")
        ref = np.asarray(mbs.GetNode(el.cageNode)["referenceCoordinates"], float)
        assert np.asarray(RotXYZ2RotationMatrix(ref[3:]))[:, local_axis] == pytest.approx(rot[:, 2], abs=1e-12)
        assert el.cageFrame[:, 2] == pytest.approx(rot[:, 2], abs=1e-12)
        assert mbs.GetObject(el.cageBody)["inertia"][local_axis] == pytest.approx(el.params[L.P_IC], rel=1e-12)
        if local_axis == 2 and rot[2, 2] == 1.0:
            angle = initial_state(B, el.scenario)["xc"][1, 0]
            assert ref[5] == pytest.approx(angle + 0.4, abs=1e-12)


def _axis_model(rot, mode):
    """A rotor on the bearing axis ``rot`` @ z: the outer ring on ground turned by ``rot``, the inner ring a heavy
    rigid body (Lie-group node, turned by ``rot``, spinning at 500 rad/s) under F_r = 3000 N along the outer ring's
    x axis, started at its static displacement, with gravity along the outer ring's -y axis (radial), the rigid
    cage of the module (narrowed clearances, unbalance) guided by the inner land; 1.5 ms at 4 us."""
    import exudyn as exu
    from exudyn.itemInterface import (LoadForceVector, MarkerBodyRigid, NodeRigidBodyRotVecLG, ObjectGround,
                                      ObjectRigidBody)
    from exudyn.rigidBodyUtilities import RotationMatrix2RotationVector

    from exudyn_bearing.model.initial_state import initial_state, ring_mass_estimate

    mbs = exu.SystemContainer().AddSystem()
    m_outer = mbs.AddMarker(MarkerBodyRigid(bodyNumber=mbs.AddObject(ObjectGround(referenceRotation=rot)),
                                            localPosition=[0.0] * 3))
    d0 = rot @ initial_state(B, eb.Scenario(Fr=3000.0, omega=500.0))["ring"][:3]
    node = mbs.AddNode(NodeRigidBodyRotVecLG(referenceCoordinates=[*d0, *RotationMatrix2RotationVector(rot)],
                                             initialVelocities=[0.0] * 5 + [500.0]))
    body = mbs.AddObject(ObjectRigidBody(nodeNumber=node, mass=ring_mass_estimate(B), inertia=[0.5, 0.5, 1.0, 0, 0, 0]))
    m_inner = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body, localPosition=[0.0] * 3))
    mbs.AddLoad(LoadForceVector(markerNumber=m_inner, loadVector=list(rot @ [3000.0, 0.0, 0.0])))
    bearing = eb.CreateBallBearing(mbs, B, m_inner, m_outer, cage="rigid",
                                   rigidCage=dataclasses.replace(CAGE, guidance="inner_land"),
                                   gravity=tuple(rot @ [0.0, -9.81, 0.0]), initialLoad=(3000.0, 0.0),
                                   initialOmega=500.0, stepSize=4e-6, cageDamping="implicit", sampleInterval=1e-4,
                                   mode=mode)
    # the start the bearing offers the shaft's node is the placed one, in world components
    np.testing.assert_allclose(bearing.initialCoordinates[:3], d0, rtol=0, atol=1e-12 * np.abs(d0).max())
    rec = _solve(mbs, bearing, 1.5e-3)
    out = {k: rec.data[k] for k in ("xc", "vc", "xb", "vb", "wb", "ring", "cage_load")}
    out["load"] = rec.data["diag"][..., L.D_LOAD]
    out["land"] = rec.data["glob"][:, [L.G_LAND_FX, L.G_LAND_FY]]
    out["cageSpeed"] = mbs.GetSensorStoredData(bearing.sensors["cageSpeed"])[:, 1]
    if mode == "bodies":  # the cage body's world state, turned back into the outer ring's frame
        out["node_position"] = rot.T @ mbs.GetNodeOutput(bearing.cageNode, exu.OutputVariableType.Position)
        out["node_omega"] = rot.T @ mbs.GetNodeOutput(bearing.cageNode, exu.OutputVariableType.AngularVelocity)
        assert len(bearing._graphics(mbs, bearing.items["object"])) == 4
    return out


#: The bearing axes of the turned models: the world x axis (the node's first angle turns the cage), the world y
#: axis and an oblique one.
AXIS_TURNS = {"x": ("Y", 0.5 * np.pi), "y": ("X", -0.5 * np.pi), "oblique": ("ZYX", (0.3, 1.1, 0.5))}


def _turn(name):
    from exudyn.rigidBodyUtilities import RotationMatrixX, RotationMatrixY, RotationMatrixZ

    axes, angles = AXIS_TURNS[name]
    mats = {"X": RotationMatrixX, "Y": RotationMatrixY, "Z": RotationMatrixZ}
    rot = np.eye(3)
    for a, phi in zip(axes, np.atleast_1d(angles)):
        rot = rot @ np.asarray(mats[a](phi))
    return rot


@pytest.mark.parametrize("mode", ["bodies", "fast"])
def test_a_bearing_axis_off_the_world_z_gives_the_same_rigid_cage(mode):
    # the same model with the bearing axis along the world z axis and turned onto the world x axis, the world y
    # axis and an oblique one (gravity turned with it, radial): the samples in the outer ring's frame (cage
    # centre, angle and speed, balls, ring, ball and pocket loads), the land force in the cage's bearing frame,
    # the cage-speed sensor and (body mode) the cage body's world position and angular velocity turned back
    # agree. Measured (this module's _axis_model and _turn, 1.5 ms): within 2.3e-9 of each quantity's largest
    # value in both modes, the land force the farthest, the samples of the balls and cage within 3e-12 (the turns
    # round); asserted 1e-6. Gravity left in the world components for the y-axis model (then along its bearing
    # axis instead of radial) moves the cage's centre by 9e-5 of its largest value, the ball loads by 4e-3 and
    # the pocket loads by 0.14.
    base = _axis_model(np.eye(3), mode)
    assert base["cage_load"][..., 0].max() > 1.0 and np.abs(base["land"]).max() > 0.0  # pockets and land act
    for name in AXIS_TURNS:
        turned = _axis_model(_turn(name), mode)
        assert set(turned) == set(base)
        for key, a in base.items():
            assert np.abs(turned[key] - a).max() <= 1e-6 * np.abs(a).max(), (name, key)


@pytest.mark.parametrize("mode", ["bodies", "fast"])
def test_a_model_turned_about_the_axis_reports_the_same_cage(mode):
    # the same model turned by 0.4 rad about the bearing axis: the cage moves 0.4 rad further in the world, and
    # the samples (the outer ring's frame, as the reference engine's) are those of the model not turned
    runs = [_solve(*_user_model(turn, sampleInterval=2e-4, mode=mode)[1:], 1e-3) for turn in (0.0, 0.4)]
    a, b = (r.data for r in runs)
    assert b["xc"][:, 1, 0] == pytest.approx(a["xc"][:, 1, 0], abs=1e-9)
    assert b["vc"][:, 1, 0] == pytest.approx(a["vc"][:, 1, 0], rel=1e-9)
    assert np.abs(b["xc"][:, 0] - a["xc"][:, 0]).max() < 1e-12
    assert b["diag"][..., L.D_LOAD] == pytest.approx(a["diag"][..., L.D_LOAD], rel=1e-6, abs=1e-6)

