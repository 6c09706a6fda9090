"""Measurements behind the limits stated for the fast mode, the 7208 cage and the peer check.

1. (The fast mode against sub-steps and ring mass: validation/studies/fast_mode_limits.py.)
2. Fast mode on a rigid rotor (2.5 kg) held by two 6208 bearings 0.2 m
   apart, motor torque 5 N m from rest, radial load 24.5 / 600 / 3000 N:
   mean cage speed of bearing A over 10-20 ms (sampled every 20 us) and at
   20 ms, in the body mode at three steps and in the fast mode for 1, 2
   and 4 sub-steps of 5 us and 2 and 4 of 4 us. The body mode's own spread
   over its step sizes is the yardstick: at 24.5 N the rotor rattles near the
   centre and the run-up is chaotic.
3. The run-up of scenarios/rotor_two_6208.py (gravity, unbalance, no load)
   over 50 ms: whether the shaft whirls (orbit radius
   and largest outer ball load over 40-50 ms) in the body mode at four steps
   and in the fast mode with 1-4 sub-steps of 5 us.
4. Explicit solvers on the 6208 test scene (10 ms, 2 us steps): body mode
   and fast mode (1 and 3 sub-steps) under VelocityVerlet and ExplicitEuler
   (Cundall-Strack history, implicit spring) and RK44 (regularised
   friction), errors of q_max_inner and cage speed against the reference
   core with the same friction model.
5. The 7208 with its torus cage under F_r = F_a = 3000 N at 500 rad/s: the
   largest cage-ball load at dt = 0.5 us, and what happens at dt = 1 us.
6. Exudyn's built-in bearing with the inner ring's own polar inertia: the
   ring speed and cage speed after 40 ms (the peer check gives the ring a
   large inertia instead).

7. A lightly loaded rotor (50 N and 5 N on two 6208, 500 rad/s, started
   from the analytic state): bearing A's cage speed and orbit in the body
   mode at 5 us (and 2.5 us: its own step error) and in the fast mode with
   1, 2, 4 and 8 sub-steps of 5 us and 4, 8 and 16 of 2.5 us
   (``--light-load`` runs only this).

    python validation/consistency/fast_mode_checks.py [--light-load]
"""
import json
import math
import sys
import warnings
from pathlib import Path

import numpy as np

import exudyn as exu
from exudyn.itemInterface import (LoadForceVector, LoadTorqueVector, MarkerBodyRigid, NodeRigidBodyRxyz, ObjectGround,
                                  ObjectRigidBody)

import exudyn_bearing as eb
from exudyn_bearing.solvers.element.engine import ExudynEngine, solve_dynamic
from exudyn_bearing.model.stability import SimulationError
from exudyn_bearing.solvers.reference import ReferenceEngine

HERE = Path(__file__).resolve().parent


def _first_error_line(exc):
    """The element's own message (the line naming stepSize) out of Exudyn's wrapped error."""
    lines = [ln for ln in str(exc).splitlines() if "stepSize" in ln] or str(exc).splitlines() or ["failed"]
    return lines[0].replace("RuntimeError: ", "").strip()[:200]


def rotor(load, sub, dt=5e-6):
    """Cage speed of bearing A: mean over 10-20 ms and at 20 ms; ``sub``
    sub-steps of ``dt`` in the fast mode, 0 for the body mode at ``dt``."""
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
        bearings.append(eb.CreateBallBearing(mbs, "6208", mi, mo, stepSize=dt, tangential="implicit",
                                             sampleInterval=2e-5, **mode))
    mbs.Assemble()
    solve_dynamic(mbs, bearings[0].SimulationSettings(0.02))
    r = bearings[0].results()
    cage = r.cage_speed_series()
    return {"mean_10_20ms": float(cage[r.t >= 0.01].mean()), "at_20ms": float(cage[-1])}


#: (label, sub-steps (0: body mode), step or sub-step [s])
ROTOR_RUNS = [("bodies 2.5 us", 0, 2.5e-6), ("bodies 4 us", 0, 4e-6), ("bodies 5 us", 0, 5e-6),
              ("fast 1 x 5 us", 1, 5e-6), ("fast 2 x 5 us", 2, 5e-6), ("fast 4 x 5 us", 4, 5e-6),
              ("fast 2 x 4 us", 2, 4e-6), ("fast 4 x 4 us", 4, 4e-6)]


def rotor_sub_steps():
    rows = {}
    for load in (24.5, 600.0, 3000.0):
        rows[f"{load:g}"] = r = {label: rotor(load, sub, dt) for label, sub, dt in ROTOR_RUNS}
        print(f"rotor on two 6208, load {load:g} N, cage speed mean over 10-20 ms: "
              + ", ".join(f"{k} {v['mean_10_20ms']:.2f}" for k, v in r.items()), flush=True)
    return rows


def light_rotor(sub, dt=5e-6, load=50.0, omega=500.0, t_end=0.02):
    """A lightly loaded rotor (2.5 kg on two 6208 0.2 m apart, radial load ``load`` [N] at its centre,
    spinning at ``omega`` [rad/s] with a large polar inertia, both bearings started from their analytic
    state): bearing A's mean cage speed and mean shaft-centre displacement (the orbit's centre, x and y
    in the outer-ring frame) and its mean distance from that centre over the second half of the run, with
    ``sub`` sub-steps of ``dt`` in the fast mode, 0 for the body mode at ``dt``."""
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    d0 = ReferenceEngine("6208", eb.Scenario(Fr=0.5 * load, omega=omega)).initial_state()["ring"][:3]
    node = mbs.AddNode(NodeRigidBodyRxyz(referenceCoordinates=[*d0, 0, 0, 0], initialVelocities=[0, 0, 0, 0, 0, omega]))
    body = mbs.AddObject(ObjectRigidBody(nodeNumber=node, mass=2.5, inertia=[1.3e-2, 1.3e-2, 1.0, 0, 0, 0]))
    mc = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body, localPosition=[0, 0, 0]))
    mbs.AddLoad(LoadForceVector(markerNumber=mc, loadVector=[load, 0, 0]))
    bearings = []
    for z in (-0.1, 0.1):
        mi = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body, localPosition=[0, 0, z]))
        mo = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground, localPosition=[0, 0, z]))
        mode = dict(mode="fast", subSteps=sub) if sub else dict(mode="bodies")
        bearings.append(eb.CreateBallBearing(mbs, "6208", mi, mo, stepSize=dt, initialOmega=omega,
                                             initialLoad=(0.5 * load, 0.0), sampleInterval=2e-5, **mode))
    mbs.Assemble()
    solve_dynamic(mbs, bearings[0].SimulationSettings(t_end))
    r = bearings[0].results()
    late = r.t >= 0.5 * t_end
    ring = r.record.data["ring"][late, :2]
    centre = ring.mean(axis=0)
    return {"cage_speed": float(r.cage_speed_series()[late].mean()), "centre_x_um": float(1e6 * centre[0]),
            "fast_step_limit_us": float(1e6 * bearings[0].fastStepLimit),
            "centre_y_um": float(1e6 * centre[1]),
            "orbit_radius_um": float(1e6 * np.hypot(*(ring - centre).T).mean())}


#: Light-load cases: (sub-steps, sub-step [s]) of the fast mode; 0 sub-steps: the body mode at that step.
LIGHT_CASES = ((0, 2.5e-6), (1, 5e-6), (2, 5e-6), (4, 5e-6), (8, 5e-6), (4, 2.5e-6), (8, 2.5e-6), (16, 2.5e-6))


def _case_label(sub, dt):
    return f"bodies {dt * 1e6:g} us" if sub == 0 else f"fast {sub} x {dt * 1e6:g} us"


def light_load_sub_steps(load=50.0, cases=LIGHT_CASES):
    """Body mode at 5 us against ``cases`` ((sub-steps, sub-step) of the fast mode, 0 sub-steps: the body
    mode at another step) on :func:`light_rotor`: relative deviation of the cage speed and of the orbit
    centre's distance from the bearing centre. The body mode at 2.5 us is its own step error; the fast
    mode's ring (the rotor) advances by Exudyn steps of sub-steps x sub-step."""
    rows = {"bodies 5 us": light_rotor(0, load=load)}
    body = rows["bodies 5 us"]
    print(f"light rotor, {load:g} N, bodies 5 us: {body}", flush=True)
    for sub, dt in cases:
        label = _case_label(sub, dt)
        try:
            r = light_rotor(sub, dt=dt, load=load)
        except Exception as exc:  # a blow-up is a result here
            rows[label] = {"error": _first_error_line(exc)}
            print(f"light rotor, {load:g} N, {label}: {rows[label]}", flush=True)
            continue
        r["dev_cage_speed"] = r["cage_speed"] / body["cage_speed"] - 1
        r["dev_centre"] = (math.hypot(r["centre_x_um"], r["centre_y_um"])
                           / math.hypot(body["centre_x_um"], body["centre_y_um"]) - 1)
        r["exudyn_step_us"] = (sub or 1) * dt * 1e6
        rows[label] = r
        print(f"light rotor, {load:g} N, {label} (Exudyn step {r['exudyn_step_us']:g} us, the fast mode's limit "
              f"{r['fast_step_limit_us']:.1f} us): cage speed "
              f"{r['cage_speed']:.3f} rad/s ({100 * r['dev_cage_speed']:+.3f} %), orbit centre ({r['centre_x_um']:.3f}, "
              f"{r['centre_y_um']:.3f}) um ({100 * r['dev_centre']:+.3f} % in distance), orbit radius "
              f"{r['orbit_radius_um']:.4f} um (body mode {body['orbit_radius_um']:.4f})", flush=True)
    return rows


def rotor_scenario_whirl():
    sys.path.insert(0, str(HERE.parents[1] / "scenarios"))
    import rotor_two_6208

    rows = {}
    for label, sub, dt in [("bodies 1.25 us", 0, 1.25e-6), ("bodies 2.5 us", 0, 2.5e-6), ("bodies 4 us", 0, 4e-6),
                           ("bodies 5 us", 0, 5e-6), ("fast 1 x 5 us", 1, 5e-6), ("fast 2 x 5 us", 2, 5e-6),
                           ("fast 3 x 5 us", 3, 5e-6), ("fast 4 x 5 us", 4, 5e-6)]:
        SC, mbs, bearings, sensor, speed = rotor_two_6208.build(dt=dt, mode="fast" if sub else "bodies",
                                                                sub_steps=max(sub, 1))
        ss = bearings["A"].SimulationSettings(0.05)
        ss.solution.sensors.writePeriod = 2e-4
        solve_dynamic(mbs, ss)
        pos = mbs.GetSensorStoredData(sensor)
        r = bearings["A"].results()
        late = pos[:, 0] >= 0.04
        rows[label] = {"orbit_radius_um": float(1e6 * np.hypot(pos[late, 1], pos[late, 2]).mean()),
                       "q_max_outer_N": float(r.contact("load", "outer")[r.t >= 0.04].max(axis=1).mean()),
                       "cage_speed_50ms": float(r.cage_speed_series()[-1])}
        print(f"rotor scenario run-up, {label}: {rows[label]}", flush=True)
    return rows


def solvers_6208():
    rows = {}
    for solver, friction in (("VelocityVerlet", "history"), ("RK44", "regularized"), ("ExplicitEuler", "history")):
        sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.01, dt=2e-6, tangential="implicit", friction=friction,
                         sample_dt=1e-4)
        ref = eb.simulate("6208", sc).summary()
        for mode, sub in (("bodies", 1), ("fast", 1), ("fast", 3)):
            label = f"{solver}, {mode}" + (f" {sub}" if mode == "fast" else "")
            eng = ExudynEngine("6208", sc, mode=mode, sub_steps=sub)
            try:
                solve_dynamic(eng.mbs, eng.element.SimulationSettings(sc.t_end, solverType=solver))
                s = eb.Results(eng.element.record()).summary()
                rows[label] = {k: abs(s[k] / ref[k] - 1) for k in ("q_max_inner", "cage_speed")}
            except Exception as exc:  # a blow-up is a result here
                rows[label] = {"error": _first_error_line(exc)}
            print(f"6208 scene, {label}: {rows[label]}", flush=True)
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
    if sys.argv[1:] == ["--light-load"]:  # only the light-load comparison of body and fast mode
        out = HERE.parent / "out"
        out.mkdir(exist_ok=True)
        (out / "fast_mode_light_load.json").write_text(json.dumps(
            {f"{load:g} N": light_load_sub_steps(load) for load in (50.0, 5.0)}, indent=2))
        return
    report = {"light_load_sub_steps": light_load_sub_steps(), "light_load_5N": light_load_sub_steps(5.0),
              "rotor_sub_steps": rotor_sub_steps(),
              "rotor_scenario_whirl": rotor_scenario_whirl(), "solvers_6208": solvers_6208(),
              "cage_7208": cage_7208(),
              "builtin_own_inertia": builtin_own_inertia()}
    out = HERE.parent / "out"
    out.mkdir(exist_ok=True)
    (out / "fast_mode_checks.json").write_text(json.dumps(report, indent=2))


if __name__ == "__main__":
    main()
