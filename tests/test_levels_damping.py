"""Contact damping of the quasi-static level (CreateBallBearing(..., model="quasistatic")): from the state of its
balls (no operating point), linear in the ring's velocity, zero for unloaded balls, the condensed damping matrix of
solve_quasistatic at its operating pose, and a shaft's free decay at the rate that matrix gives."""
import math

import numpy as np
import pytest

exu = pytest.importorskip("exudyn")
from exudyn.itemInterface import (LoadForceVector, MarkerBodyRigid, NodeRigidBodyRxyz,  # noqa: E402
                                  ObjectGround, ObjectRigidBody, SensorNode)

import exudyn_bearing as eb  # noqa: E402

FR = 3000.0
MASS = 2.5


def shaft(bearing="6208", load=0.0, start=None, velocity=(0.0, 0.0, 0.0), omega=0.0, **options):
    """A 2.5 kg shaft (Rxyz node) on one bearing at the quasi-static level, ``load`` along +x on it, started at
    ``start`` (x, y, z, tilt_x, tilt_y) with ``velocity``; returns (system container, mbs, level, position sensor)."""
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    q0 = [0.0] * 6 if start is None else [*start, 0.0]
    node = mbs.AddNode(NodeRigidBodyRxyz(referenceCoordinates=[0.0] * 6, initialCoordinates=q0,
                                         initialVelocities=[*velocity, 0.0, 0.0, omega]))
    body = mbs.AddObject(ObjectRigidBody(nodeNumber=node, mass=MASS, inertia=[0.01, 0.01, 5e-4, 0, 0, 0]))
    m_g = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground))
    m_b = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body))
    mbs.AddLoad(LoadForceVector(markerNumber=m_b, loadVector=[load, 0.0, 0.0]))
    options.setdefault("coefficientSpeeds", [0.0])  # the table is not the level's damping: a short one
    br = eb.CreateBallBearing(mbs, bearing, m_b, m_g, model="quasistatic", **options)
    sensor = mbs.AddSensor(SensorNode(nodeNumber=node, outputVariableType=exu.OutputVariableType.Position,
                                      storeInternal=True, writeToFile=False))
    return sc, mbs, br, sensor


def force(br, pose, rates, omega):
    """The level's force and moment on the inner ring (5,) at ``pose`` with the pose ``rates`` (the angular velocity
    of a ring spinning at ``omega`` about its tilted axis plus the tilt rates)."""
    d = np.asarray(pose, float)
    w = [rates[3] + omega * d[4], rates[4] - omega * d[3], omega]
    br._evaluate(list(d[:3]), [d[3], d[4], 0.0], list(rates[:3]), w)
    return br._force.copy()


def damping_matrix(br, pose, omega):
    """C = -dF/du' of the level at ``pose`` (columns from unit pose rates; F is linear in them)."""
    f0 = force(br, pose, np.zeros(5), omega)
    return np.array([-(force(br, pose, np.eye(5)[k], omega) - f0) for k in range(5)]).T


@pytest.mark.parametrize("omega", [0.0, 500.0])
def test_damping_force_without_operating_point_is_linear_in_the_ring_velocity(omega):
    # no initialLoad (the operating point at zero load, whose table has no damping): the balls loaded by a radial
    # displacement of 20 um damp the ring; the damping part is linear in the pose rates (F(2v) - F(0) = 2 (F(v) -
    # F(0)) to the ball equilibrium's repeatability, 1e-9 of the ring force, tests/test_levels.py) and dissipates
    _sc, _mbs, br, _s = shaft(initialOmega=omega)
    br._restart(0.0)
    pose = [20e-6, 2e-6, 1e-6, 1e-5, -2e-5]
    rates = np.array([0.01, -0.004, 0.002, 0.3, 0.1])
    f0 = force(br, pose, np.zeros(5), omega)
    f1 = force(br, pose, rates, omega) - f0
    f2 = force(br, pose, 2.0 * rates, omega) - f0
    assert np.abs(f1[:3]).max() > 1e-6 * np.abs(f0[:3]).max()
    assert np.abs(f2 - 2.0 * f1).max() <= 1e-9 * np.abs(f0[:3]).max()
    assert f1 @ rates < 0.0


@pytest.mark.parametrize("omega", [0.0, 3000.0])
def test_damping_vanishes_for_unloaded_balls(omega):
    # 20 um clearance, ring centred: no ball touches the inner ring (at speed the balls press on the outer race
    # only), so whatever the ring's velocity the level puts no force on it
    _sc, _mbs, br, _s = shaft(eb.catalog["6208"].with_clearance(20e-6), initialOmega=omega)
    br._restart(0.0)
    for rates in (np.zeros(5), np.array([0.1, -0.05, 0.02, 1.0, 0.5])):
        assert not force(br, [1e-6, 0.0, 0.0, 0.0, 0.0], rates, omega).any()
    assert br._qmax[0] == 0.0


def test_damping_is_the_same_with_and_without_an_operating_point():
    # the damping comes from the balls' state: a level built at an operating point (initialLoad, which only places
    # the ring) and one built without give the same force at the same pose and velocity (both balls cold-started)
    pose = [22e-6, -3e-6, 4e-6, 2e-5, 1e-5]
    rates = np.array([0.02, 0.01, -0.005, 0.2, -0.4])
    forces = []
    for options in ({}, {"initialLoad": (FR, 100.0)}):
        _sc, _mbs, br, _s = shaft(initialOmega=500.0, **options)
        br._restart(0.0)
        forces.append(force(br, pose, rates, 500.0) - force(br, pose, np.zeros(5), 500.0))
    assert np.abs(forces[0]).max() > 0.0
    assert np.abs(forces[1] - forces[0]).max() <= 1e-9 * np.abs(forces[0]).max()


@pytest.mark.parametrize("omega, tol", [(0.0, 1e-6), (500.0, 2e-4)])
def test_damping_at_the_operating_pose_is_the_condensed_matrix(omega, tol):
    # at the pose solve_quasistatic finds under Fr, the level's damping (built without initialLoad) is the solver's
    # condensed damping matrix: the same contact law and condensation on the same balls. At rest (no film) to the
    # tabulated Hertz constants' 3e-7 (tests/test_levels.py); at speed the films differ through the rolling
    # speed, the level's kinematic cage (free contact angle) against the solver's race control: 1e-4 apart in the
    # cage speed (198.02 against 198.04 rad/s), and the squeeze-film damping goes with h^-1.5, h with u^0.68
    sol = eb.solve_quasistatic("6208", Fr=FR, omega=omega)
    _sc, _mbs, br, _s = shaft(initialOmega=omega)
    br._restart(0.0)
    c = damping_matrix(br, sol.displacement, omega)
    assert np.abs(c - sol.damping).max() <= tol * np.abs(sol.damping).max()


def test_shaft_decays_at_the_rate_of_the_condensed_damping():
    # a 2.5 kg shaft on one 6208 under 3000 N at rest, without initialLoad, started at its static pose with a
    # radial velocity of 5 mm/s (0.4 um, 2 % of the static deflection: linear): its radial oscillation decays at
    # sigma = C_xx / (2 m) of solve_quasistatic's damping matrix (GeneralizedAlpha without numerical damping at
    # 40 steps per period; the peaks sampled at 1/80 of a period, the Hertz stiffness and damping varying by 2 % over
    # the cycle: below 1 % each). With the damping of the table at zero load it would not decay at all (C = 0).
    sol = eb.solve_quasistatic("6208", Fr=FR)
    start = sol.displacement
    _sc, mbs, br, sensor = shaft(load=FR, start=start, velocity=(5e-3, 0.0, 0.0))
    mbs.Assemble()
    ss = br.SimulationSettings(0.03, stepSize=2e-5)
    ss.timeIntegration.generalizedAlpha.spectralRadius = 1.0
    ss.solution.sensors.writePeriod = 1e-5
    with eb.filter_exudyn_notes():
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    t, x = mbs.GetSensorStoredData(sensor)[:, :2].T
    x = x - start[0]
    # peaks of |x| per half period: log-linear fit of the envelope
    k = np.flatnonzero((np.abs(x[1:-1]) >= np.abs(x[:-2])) & (np.abs(x[1:-1]) > np.abs(x[2:]))) + 1
    sigma = -np.polyfit(t[k], np.log(np.abs(x[k])), 1)[0]
    expected = sol.damping[0, 0] / (2.0 * MASS)
    assert sigma == pytest.approx(expected, rel=0.02)
    assert math.isfinite(sigma)
