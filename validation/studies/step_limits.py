"""What happens above each stable-step limit, and what the engines say about it.

``stable_step`` has four limits (normal contacts, explicit tangential
springs, regularised friction, ball / cage-ball contacts); ``step_warning``
names every one a step exceeds and what to expect. This script runs the
reference core on:

1. the 6208 at F_r = 3000 N, 500 rad/s from the analytic state (steady,
   0.2 s), explicit and implicit spring, dt = 5, 8, 9 us (README's
   recommended steady settings are 5 us explicit and 8 us implicit);
2. README's main job, the 6208 protocol (0 -> 500 rad/s in 50 ms, 200 ms
   steady, 50 ms down, from rest), explicit and implicit spring, 5-8 us;
3. the 7208 under F_r = F_a = 3000 N at 500 rad/s (50 ms, analytic state,
   unequal contact angles), 0.6-1 us;
4. the 6208 steady with regularised friction (20 ms), verlet 1.3-5 us;
5. the largest ball / cage-ball loads of steady runs from the analytic
   state at a small step (2 us; 0.4 us for the 7208), against the
   a-priori assumption of ``stable_step`` (0.1 % of the ball load for equal
   contact angles, a tenth otherwise).

For each run: blow-up or not (and when), the largest cage load, the mean
frictional power (noise below 1e-3 W when the friction forces are resolved,
large when they chatter), and which limits the a-priori warning named.

    python validation/studies/step_limits.py

Writes ``out/step_limits.json``.
"""
import json
import warnings
from pathlib import Path


import exudyn_bearing as eb
from exudyn_bearing.model.stability import SimulationError, StepSizeWarning, expected_cage_load, stable_step

HERE = Path(__file__).resolve().parent

STEADY = eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.2, sample_dt=1e-4)
PROTOCOL = eb.Scenario(Fr=3000.0, omega=500.0, t_ramp_up=0.05, t_steady=0.2, t_ramp_down=0.05, t_end=0.3,
                       initial="rest", sample_dt=1e-4)
B7208 = eb.Scenario(Fr=3000.0, Fa=3000.0, omega=500.0, t_end=0.05, sample_dt=1e-4)
REGULARIZED = eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.02, friction="regularized", sample_dt=1e-4)

RUNS = ([("6208 steady", "6208", STEADY.replace(tangential=t, dt=d)) for t in ("explicit", "implicit")
         for d in (5e-6, 8e-6, 9e-6)]
        + [("6208 protocol", "6208", PROTOCOL.replace(tangential=t, dt=d)) for t in ("explicit", "implicit")
           for d in (5e-6, 6e-6, 7e-6, 8e-6)]
        + [("7208", "7208", B7208.replace(dt=d)) for d in (0.6e-6, 0.7e-6, 0.8e-6, 1e-6)]
        + [("6208 regularized", "6208", REGULARIZED.replace(dt=d)) for d in (1.3e-6, 2e-6, 3e-6, 5e-6)])

STEADY_SCENES = [("6208", dict(Fr=3000.0)), ("6208", dict(Fr=1000.0)), ("6208", dict(Fr=3000.0, omega=1700.0)),
                 ("6208", dict(Fr=3000.0, omega=100.0)), ("6208", dict(Fr=3000.0, Pd=12.6e-6)),
                 ("6208", dict(Fr=3000.0, Pd=-12.6e-6)), ("6208", dict(Fr=200.0, omega=300.0, Pd=40e-6)),
                 ("6208", dict(Fr=0.0, Fa=2000.0)), ("7208", dict(Fr=0.0, Fa=3000.0)),
                 ("6208", dict(Fr=3000.0, Fa=500.0)), ("7208", dict(Fr=3000.0, Fa=3000.0))]


def limits_named(message):
    head = message.split(". ")[0]
    return [k for k, word in (("normal", "normal contacts"), ("tangential", "tangential"),
                              ("friction", "regularised friction"), ("cage", "cage-ball")) if word in head]


def one_run(bearing, sc):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            r = eb.simulate(bearing, sc)
        except SimulationError as exc:
            r, failure = None, str(exc)
    said = [str(w.message) for w in caught if issubclass(w.category, StepSizeWarning)]
    prior = [m for m in said if m.startswith("dt =")]
    row = {"a_priori_limits": limits_named(prior[0]) if prior else [],
           "a_priori_expects_blow_up": bool(prior) and "blow up" in prior[0],
           "cage_load_warning": any("contacts reached" in m for m in said)}
    if r is None:
        row.update(blew_up=True, failure=failure.split(";")[0])
    else:
        s = r.summary()
        row.update(blew_up=False, max_cage_load_N=float(r.data["cage_load"].max()),
                   q_max_inner=s["q_max_inner"], cage_speed=s["cage_speed"], friction_power_W=s["friction_power"])
    return row


def main():
    out = {"runs": {}, "steady_cage_loads": {}}
    for name, bearing, sc in RUNS:
        est = stable_step(eb.catalog[bearing], sc)
        key = f"{name}, {sc.tangential} spring, {sc.friction} friction, dt {sc.dt * 1e6:g} us"
        row = one_run(bearing, sc)
        row["estimate_s"] = {"dt": est.dt, "limited_by": est.limited_by, "cage_load_N": est.cage_load,
                             "cage_basis": est.cage_basis}
        out["runs"][key] = row
        print(key, row, flush=True)
    for bearing, kw in STEADY_SCENES:
        sc = eb.Scenario(**dict(dict(omega=500.0), **kw), t_end=0.05, dt=2e-6 if bearing == "6208" else 0.4e-6,
                         sample_dt=5e-5, tangential="implicit")
        b = eb.catalog[bearing] if sc.Pd is None else eb.catalog[bearing].with_clearance(sc.Pd)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            r = eb.simulate(bearing, sc)
        st = stable_step(b, sc)
        fraction, basis = expected_cage_load(b, sc)
        cl = r.data["cage_load"]
        key = f"{bearing} " + ", ".join(f"{k} {v:g}" for k, v in kw.items())
        out["steady_cage_loads"][key] = {
            "max_cage_load_N": float(cl.max()), "max_cage_load_second_half_N": float(cl[len(cl) // 2:].max()),
            "assumed_cage_load_N": st.cage_load, "assumed_fraction": fraction, "basis": basis}
        print(key, out["steady_cage_loads"][key], flush=True)
    (HERE.parent / "out").mkdir(exist_ok=True)
    (HERE.parent / "out" / "step_limits.json").write_text(json.dumps(out, indent=2))


if __name__ == "__main__":
    main()
