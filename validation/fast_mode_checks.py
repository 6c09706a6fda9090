"""Measurements behind the limits stated for the fast mode, the 7208 cage and the peer check.

1. Fast mode against sub-steps on the 6208 test scene (point-mass ring of
   78 g, prescribed spin): q_max_inner and cage speed for 1-4 sub-steps.
2. Fast mode on a rigid rotor held by two 6208 bearings 0.2 m apart, motor
   torque 5 N m, radial load 24.5 / 600 / 3000 N: cage speed after 20 ms
   in the body mode and for 1, 2 and 4 sub-steps per Exudyn step.
3. The 7208 with its torus cage under F_r = F_a = 3000 N at 500 rad/s: the
   largest cage-ball load at dt = 0.5 us, and what happens at dt = 1 us.
4. Exudyn's built-in bearing with the inner ring's own polar inertia: the
   ring speed and cage speed after 40 ms (the peer check gives the ring a
   large inertia instead).

    python validation/fast_mode_checks.py
"""
import json
import sys
import warnings
from pathlib import Path

import numpy as np

import exudyn as exu
from exudyn.itemInterface import (LoadForceVector, LoadTorqueVector, MarkerBodyRigid, NodeRigidBodyRxyz, ObjectGround,
                                  ObjectRigidBody)

import exudyn_bearing as eb
from exudyn_bearing.element.engine import ExudynEngine
from exudyn_bearing.reference import SimulationError

HERE = Path(__file__).resolve().parent


def substeps_6208():
    sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.04, dt=5e-6, tangential="implicit", sample_dt=1e-4)
    ref = eb.simulate("6208", sc).summary()
    rows = {"reference": {k: ref[k] for k in ("q_max_inner", "cage_speed")}}
    for sub in (1, 2, 3, 4):
        try:
            s = ExudynEngine("6208", sc, mode="fast", sub_steps=sub).run().summary()
            rows[f"fast {sub}"] = {k: s[k] for k in ("q_max_inner", "cage_speed")}
        except Exception as exc:  # a blow-up is a result here
            rows[f"fast {sub}"] = {"error": str(exc).splitlines()[0][:200]}
        print(f"6208 scene, fast mode {sub} sub-step(s): {rows[f'fast {sub}']}")
    return rows


def rotor(load, sub):
    """Cage speed of bearing A after 20 ms; ``sub`` sub-steps of the fast mode, 0 for the body mode."""
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    node = mbs.AddNode(NodeRigidBodyRxyz(referenceCoordinates=[0.0] * 6))
    body = mbs.AddObject(ObjectRigidBody(nodeNumber=node, mass=2.5, inertia=[1.3e-2, 1.3e-2, 4.9e-4, 0, 0, 0]))
    mc = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body, localPosition=[0, 0, 0]))
    mbs.AddLoad(LoadForceVector(markerNumber=mc, loadVector=[0, -load, 0]))
    mbs.AddLoad(LoadTorqueVector(markerNumber=mc, loadVector=[0, 0, 5.0], bodyFixed=True))
    bearings = []
    for z in (-0.1, 0.1):
        mi = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body, localPosition=[0, 0, z]))
        mo = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground, localPosition=[0, 0, z]))
        mode = dict(mode="fast", subSteps=sub) if sub else dict(mode="bodies")
        bearings.append(eb.CreateBallBearing(mbs, "6208", mi, mo, stepSize=5e-6, tangential="implicit",
                                             sampleInterval=2e-4, **mode))
    mbs.Assemble()
    ss = bearings[0].SimulationSettings(0.02)
    printing = exu.config.printToConsole
    exu.config.printToConsole = False
    try:
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    finally:
        exu.config.printToConsole = printing
    return float(bearings[0].results().cage_speed_series()[-1])


def rotor_light_load():
    rows = {}
    for load in (24.5, 600.0, 3000.0):
        rows[f"{load:g}"] = {("bodies" if sub == 0 else str(sub)): rotor(load, sub) for sub in (0, 1, 2, 4)}
        print(f"rotor on two 6208, load {load:g} N: cage after 20 ms, body mode and fast mode by sub-steps "
              f"{rows[f'{load:g}']}")
    return rows


def cage_7208():
    out = {}
    sc = eb.Scenario(Fr=3000.0, Fa=3000.0, omega=500.0, t_end=0.05, dt=0.5e-6, sample_dt=1e-4)
    r = eb.simulate("7208", sc)
    out["max_cage_load_N_dt0.5us"] = float(r.data["cage_load"].max())
    try:
        eb.simulate("7208", sc.replace(dt=1e-6))
        out["dt1us"] = "ran"
    except SimulationError as exc:
        out["dt1us"] = str(exc)
    print(f"7208 with cage: {out}")
    return out


def builtin_own_inertia():
    sys.path.insert(0, str(HERE))
    import exudyn.machines as mach
    import peer_builtin

    keep = {}
    create = mach.CreateBallBearing

    def spy(mbs, bd, m_in, m_out, **kw):
        keep["mbs"], keep["m_in"] = mbs, m_in
        return create(mbs, bd, m_in, m_out, **kw)

    # the peer check's bearing, but with the 6208 inner ring's own polar inertia
    from exudyn.rigidBodyUtilities import InertiaCylinder

    ring = InertiaCylinder(density=7850.0, length=0.018, outerRadius=0.024, innerRadius=0.02, axis=2)
    mach.CreateBallBearing = spy
    try:
        res = peer_builtin.builtin(0.04, ring_polar_inertia=float(ring.Inertia()[2, 2]))
    finally:
        mach.CreateBallBearing = create
    w = keep["mbs"].GetMarkerOutput(keep["m_in"], exu.OutputVariableType.AngularVelocity)[2]
    out = {"ring_speed": float(w), "cage_speed": res["cage_speed"],
           "kinematic_cage_at_ring_speed": float(w) * (1 - 6.3 / 30.0) / 2}
    print(f"built-in bearing, ring with its own inertia: {out}")
    return out


def main():
    warnings.simplefilter("ignore")
    report = {"substeps_6208": substeps_6208(), "rotor_light_load": rotor_light_load(), "cage_7208": cage_7208(),
              "builtin_own_inertia": builtin_own_inertia()}
    out = HERE / "out"
    out.mkdir(exist_ok=True)
    (out / "fast_mode_checks.json").write_text(json.dumps(report, indent=2))


if __name__ == "__main__":
    main()
