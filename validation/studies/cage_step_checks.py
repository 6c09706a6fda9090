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


def report_section(run):
    """The report's section on the cage contacts' stable step, from cage_step_checks.json."""
    d = run.load("cage_step_checks.json")
    lines = ["## Stable step of the cage contacts", "",
             f"Command: `{run.command}`. The ball / cage-ball contacts are critically damped, "
             "and velocity Verlet with the damping force at the half-step velocity is stable up to "
             "2 (sqrt(1 + zeta^2) - zeta) / omega, 0.83 / omega at zeta = 1 (tests/test_reference.py checks this "
             "against the amplification matrix). Above it the cage loads chatter at about twice their value; from "
             "1.6 times the estimate runs blew up (`python validation/studies/step_limits.py`). With "
             "`cage_damping=\"implicit\"` the damping acts with C / (1 + C dt / m), backward Euler of the "
             "contact's own damping over the step: stable up to 1.58 / omega (tests/test_cage_damping.py checks it "
             "against the amplification matrix), 1.9 times the explicit limit; the main job's implicit runs take "
             "the implicit tangential spring too (the explicit one limits at 6.3 us). Sampled cage loads, and "
             "what the engine said (a priori: dt above "
             "`stable_step`; after the run: the loads reached put the contacts' stable step below dt), and the "
             "integration's wall time (one run each, on the machine of the header):", "",
             "| scene | cage damping | tangential spring | dt | dt / estimate | largest cage load [N] | "
             "99.9 % cage load [N] | q_max_inner [N] | cage [rad/s] | a-priori warning | cage-load warning | "
             "wall [s] |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for scene, rows in d.items():
        for r in rows["runs"].values():
            head = (f"| {scene} | {r['cage_damping']} | {r['tangential']} | {r['dt_s'] * 1e6:g} us | "
                    f"{r['dt_over_estimate']:.2f} |")
            if "blew_up" in r:
                lines.append(head + f" blew up: {r['blew_up']} | | | | | | |")
                continue
            lines.append(head + f" {r['max_cage_load_N']:.1f} | {r['p99_9_cage_load_N']:.1f} | "
                         f"{r['q_max_inner']:.1f} | {r['cage_speed']:.2f} | {'yes' if r['a_priori_warning'] else 'no'} "
                         f"| {'yes' if r['cage_load_warning'] else 'no'} | {r['wall_s']:.2f} |")

    def spread(scene_rows, key):
        v = [r[key] for r in scene_rows["runs"].values()
             if r["cage_damping"] == "explicit" and r["tangential"] == "explicit"]
        return 100.0 * (max(v) - min(v)) / min(v)

    def implicit(scene_rows):
        runs = [r for r in scene_rows["runs"].values() if r["cage_damping"] == "implicit"]
        quiet = [r for r in runs if "blew_up" not in r and not r["cage_load_warning"] and not r["a_priori_warning"]]
        text = "no run within the estimate without a warning"
        if quiet:
            dev = {k: 100.0 * max(abs(r["difference"][k]) for r in quiet)
                   for k in ("q_max_inner", "cage_speed", "p99_9_cage_load_N")}
            text = (f"up to {max(r['dt_s'] for r in quiet) * 1e6:g} us "
                    f"({max(r['dt_over_estimate'] for r in quiet):.2f} of its estimate) without a warning, at most "
                    f"{dev['q_max_inner']:.2f} % off in q_max_inner, {dev['cage_speed']:.3f} % in cage speed and "
                    f"{dev['p99_9_cage_load_N']:.1f} % in the 99.9 % cage load from the "
                    f"{quiet[0]['compared_with']} run")
        chatter = [r for r in runs if "blew_up" not in r and r["cage_load_warning"]]
        blown = [r for r in runs if "blew_up" in r]
        return (text + "; first cage-load warning at "
                + (f"{chatter[0]['dt_over_estimate']:.2f}" if chatter else "-") + ", first blow-up at "
                + (f"{blown[0]['dt_over_estimate']:.2f}" if blown else "- (none up to "
                   f"{max(r['dt_over_estimate'] for r in runs):.2f})") + " of the estimate")

    def drift(scene_rows):
        return 100 * max(abs(r["q_max_inner_drift"]) for r in scene_rows["runs"].values() if "blew_up" not in r)

    lines += ["", "Estimates (`stable_step`; cage contacts at a tenth of the ball load in start-up, slow-down, from "
              "rest and with the loaded balls at unequal contact angles, at 0.1 % in steady runs from the analytic "
              "state): " + "; ".join(
                  f"{scene}, {group}: {e['dt_s'] * 1e6:.2f} us (limited by the {e['limited_by']} contact)"
                  for scene, rows in d.items() for group, e in rows["estimates"].items())
              + ". The check of the loads a run reached flags the runs whose "
              "cage loads doubled. Over the explicit steps (explicit spring) q_max_inner (the largest ball load) "
              "spreads by "
              + ", ".join(f"{spread(rows, 'q_max_inner'):.2f} % ({scene})" for scene, rows in d.items())
              + " and the cage speed by "
              + ", ".join(f"{spread(rows, 'cage_speed'):.3f} % ({scene})" for scene, rows in d.items()) + ".", "",
              "Implicit cage damping: " + "; ".join(f"{scene}: {implicit(rows)}" for scene, rows in d.items())
              + ". Runs whose summary window is not steady (the steady-state check of the summary): "
              + "; ".join(f"{scene}: {sum(1 for r in rows['runs'].values() if r.get('steady') is False)} of "
                          f"{len(rows['runs'])}, q_max_inner drifting by up to {drift(rows):.2f} % over the window"
                          for scene, rows in d.items())
              + "; their differences include that drift.", ""]
    return "\n".join(lines)


if __name__ == "__main__":
    main()
