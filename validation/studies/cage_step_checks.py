"""Stable step of the critically damped ball / cage-ball contacts: the estimate against measured cage loads.

Above the cage contacts' stable step a run does not blow up at once: the
cage loads grow about twofold and chatter while ball loads and speeds stay
put. This script measures that on two scenes and records what the engines
say about it (the a-priori estimate ``stable_step`` and the check of the
loads a run reached, ``cage_load_check``):

1. the README's main job, the 6208 protocol (F_r = 3000 N, 0 -> 500 rad/s
   in 50 ms, 200 ms steady, 50 ms down, from rest) at dt = 2-5 us;
2. the 7208 under F_r = F_a = 3000 N at 500 rad/s, 50 ms from the analytic
   state, at dt = 0.4-0.6 us.

Each scene also runs with the implicit cage damping (``cage_damping="implicit"``,
backward Euler of the contacts' damping over the step) at steps up to about
twice the explicit ones, past its own limit (a blow-up is recorded as such);
the main job's with the implicit tangential spring (the explicit one limits
at 6.3 us), against an explicit-damping run with that spring at 2 us.

For each run: largest and 99.9th-percentile sampled cage load, q_max_inner,
cage speed, and whether the engine warned; for the implicit runs their
differences from the scene's smallest explicit-damping step with the same
tangential spring.

    python validation/studies/cage_step_checks.py
"""
import json
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.model.stability import SimulationError, StepSizeWarning, stable_step

HERE = Path(__file__).resolve().parent

#: scene -> (bearing, scenario, runs): (cage damping, scenario overrides, steps). The main job's implicit-damping
#: runs take the implicit tangential spring (the explicit one limits at 6.3 us) and are compared with the
#: explicit-damping run with that spring at the smallest step.
SCENES = {
    "6208 main job": ("6208", eb.Scenario(Fr=3000.0, omega=500.0, t_ramp_up=0.05, t_steady=0.2, t_ramp_down=0.05,
                                          t_end=0.3, initial="rest", sample_dt=1e-4),
                      [("explicit", {}, (2e-6, 3e-6, 4e-6, 5e-6)),
                       ("explicit", {"tangential": "implicit"}, (2e-6,)),
                       ("implicit", {"tangential": "implicit"}, (5e-6, 6e-6, 7e-6, 8e-6))]),
    "7208": ("7208", eb.Scenario(Fr=3000.0, Fa=3000.0, omega=500.0, t_end=0.05, sample_dt=1e-4),
             [("explicit", {}, (0.4e-6, 0.5e-6, 0.55e-6, 0.6e-6)),
              ("implicit", {}, (0.6e-6, 0.8e-6, 1.0e-6, 1.2e-6, 1.5e-6))]),
}


def one_run(bearing, sc):
    """What a run gave and what the engine said about its step."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            r = eb.simulate(bearing, sc)
        except SimulationError as exc:  # a blow-up is a result here
            return {"blew_up": str(exc).split(";")[0]}
    cl = r.data["cage_load"]
    s = r.summary()
    said = [str(w.message) for w in caught if issubclass(w.category, StepSizeWarning)]
    return {"max_cage_load_N": float(cl.max()), "p99_9_cage_load_N": float(np.percentile(cl, 99.9)),
            "q_max_inner": s["q_max_inner"], "cage_speed": s["cage_speed"], "steady": s["steady"]["steady"],
            "q_max_inner_drift": s["steady"]["drift"]["q_max_inner"], "wall_s": r.wall_s,
            "a_priori_warning": any(m.startswith("dt =") for m in said),
            "cage_load_warning": any("contacts reached" in m for m in said)}


def main():
    out = {}
    for name, (bearing, sc, groups) in SCENES.items():
        rows = {"estimates": {}, "runs": {}}
        for damping, over, dts in groups:
            spring = over.get("tangential", sc.tangential)
            group = f"{damping} damping, {spring} spring"
            est = stable_step(eb.catalog[bearing], sc.replace(dt=dts[0], cage_damping=damping, **over))
            rows["estimates"][group] = {"dt_s": est.dt, "limited_by": est.limited_by, "cage_s": est.cage}
            for dt in dts:
                r = one_run(bearing, sc.replace(dt=dt, cage_damping=damping, **over))
                r.update(cage_damping=damping, tangential=spring, dt_s=dt, dt_over_estimate=dt / est.dt)
                rows["runs"][f"{group} {dt * 1e6:g} us"] = r
                print(f"{name}, {group}, dt {dt * 1e6:g} us: {r}", flush=True)
        for r in rows["runs"].values():
            if r["cage_damping"] == "implicit" and "blew_up" not in r:
                ref = min((q for q in rows["runs"].values() if q["cage_damping"] == "explicit"
                           and q["tangential"] == r["tangential"]), key=lambda q: q["dt_s"])
                r["compared_with"] = f"explicit damping, {ref['tangential']} spring, {ref['dt_s'] * 1e6:g} us"
                r["difference"] = {k: r[k] / ref[k] - 1.0 for k in ("q_max_inner", "cage_speed", "p99_9_cage_load_N")}
        out[name] = rows
    (HERE.parent / "out").mkdir(exist_ok=True)
    (HERE.parent / "out" / "cage_step_checks.json").write_text(json.dumps(out, indent=2))


if __name__ == "__main__":
    main()
