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

For each run: largest and 99.9th-percentile sampled cage load, q_max_inner,
cage speed, and whether the engine warned.

    python validation/cage_step_checks.py
"""
import json
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.model.stability import StepSizeWarning, stable_step

HERE = Path(__file__).resolve().parent

SCENES = {
    "6208 main job": ("6208", eb.Scenario(Fr=3000.0, omega=500.0, t_ramp_up=0.05, t_steady=0.2, t_ramp_down=0.05,
                                          t_end=0.3, initial="rest", sample_dt=1e-4), (2e-6, 3e-6, 4e-6, 5e-6)),
    "7208": ("7208", eb.Scenario(Fr=3000.0, Fa=3000.0, omega=500.0, t_end=0.05, sample_dt=1e-4),
             (0.4e-6, 0.5e-6, 0.55e-6, 0.6e-6)),
}


def main():
    out = {}
    for name, (bearing, sc, steps) in SCENES.items():
        est = stable_step(eb.catalog[bearing], sc.replace(dt=steps[0]))
        rows = {"estimate_s": est.dt, "estimate_limited_by": est.limited_by, "runs": {}}
        for dt in steps:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                r = eb.simulate(bearing, sc.replace(dt=dt))
            cl = r.data["cage_load"]
            s = r.summary()
            said = [str(w.message) for w in caught if issubclass(w.category, StepSizeWarning)]
            rows["runs"][f"{dt * 1e6:g} us"] = {
                "max_cage_load_N": float(cl.max()), "p99_9_cage_load_N": float(np.percentile(cl, 99.9)),
                "q_max_inner": s["q_max_inner"], "cage_speed": s["cage_speed"],
                "a_priori_warning": any(m.startswith("dt =") for m in said),
                "cage_load_warning": any("contacts reached" in m for m in said)}
            print(f"{name}, dt {dt * 1e6:g} us: {rows['runs'][f'{dt * 1e6:g} us']}", flush=True)
        out[name] = rows
    (HERE / "out").mkdir(exist_ok=True)
    (HERE / "out" / "cage_step_checks.json").write_text(json.dumps(out, indent=2))


if __name__ == "__main__":
    main()
