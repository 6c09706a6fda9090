"""Where an Exudyn step of the bearing element spends its time (6208 scene, F_r = 3000 N, 500 rad/s).

Per Exudyn step, medians of ``--repeat`` runs of ``--t-end`` seconds:

* Exudyn alone: the element's object with a user function that returns a
  constant vector (Exudyn's integration, its Python call, no bearing);
* the full element, body mode (5 us) and fast mode (4 x 5 us sub-steps);
* converting Exudyn's coordinate lists to arrays for the body mode's 111
  coordinates (what a user function over all of them pays twice per
  evaluation, besides Exudyn's own conversions; the body mode reads them from
  the system at once instead, validation/performance/profile_element.py);
* one sample of the element's state (``_store``, compiled);
* the reference engine's step on the same scene (5 us), and from it the
  floor of the fast mode with 4 sub-steps: Exudyn's step with a constant
  user function (Exudyn alone) plus four reference steps, over four
  reference steps, the best ratio to the reference core any compiled
  physics could reach behind Exudyn's own step.

    python validation/performance/bench_overhead.py [--t-end 0.02] [--repeat 5]
"""
import json
import timeit
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.solvers.element.engine import ExudynEngine, solve_dynamic
from exudyn_bearing.solvers.reference import ReferenceEngine

from profile_element import step_args  # validation/ (the script's folder is on sys.path)

HERE = Path(__file__).resolve().parent


def per_step(mode, sub, t_end, constant):
    sc = eb.Scenario(Fr=3000.0, omega=500.0, sample_dt=1e-3, t_end=t_end, dt=5e-6)
    eng = ExudynEngine("6208", sc, mode=mode, sub_steps=sub)
    el = eng.element
    if constant:
        # the forces of the user function's object: in the body mode the first ball and the rings
        out = el._out[el._out_uf_index].tolist() if el.items["ballObject"] is not None else el._out
        eng.mbs.SetObjectParameter(el.items["object"], "forceUserFunction", lambda mbs, t, i, q, q_t: out)
    ss = el.SimulationSettings(t_end)
    n = ss.timeIntegration.numberOfSteps
    t0 = timeit.default_timer()
    try:
        solve_dynamic(eng.mbs, ss)
    except Exception:  # noqa: BLE001 - with a constant force the unloaded ring may leave the balls
        pass
    return (timeit.default_timer() - t0) / n, el


def main(argv=None):
    args = step_args(argv, __doc__)
    per_step("fast", 4, 1e-3, False)  # compile / load the caches
    per_step("bodies", 1, 1e-3, False)
    rows = {}
    for name, mode, sub in (("body mode, 5 us", "bodies", 1), ("fast mode, 4 x 5 us", "fast", 4)):
        for constant in (True, False):
            key = f"{name}, {'Exudyn alone' if constant else 'full element'}"
            rows[key] = float(np.median([per_step(mode, sub, args.t_end, constant)[0]
                                         for _ in range(args.repeat)]))
            print(f"{key:45s} {rows[key] * 1e6:7.2f} us per Exudyn step", flush=True)
    _, el = per_step("bodies", 1, 1e-3, False)
    q = [0.1] * int(el.ref.size)
    conv = min(timeit.repeat(lambda: np.asarray(q, float), number=20000, repeat=5)) / 20000
    rows["list to array, body-mode coordinates"] = conv
    rows["coordinates"] = int(el.ref.size)
    print(f"list -> array of the {el.ref.size} body-mode coordinates: {conv * 1e6:.2f} us (avoided: read from "
          "the system)")
    sample = min(timeit.repeat(lambda: el._store(0.0, el._rings), number=2000, repeat=5)) / 2000
    rows["one sample"] = sample
    print(f"one sample of the element state: {sample * 1e6:.2f} us")
    sc = eb.Scenario(Fr=3000.0, omega=500.0, sample_dt=1e-3, t_end=args.t_end, dt=5e-6)
    ref = float(np.median([ReferenceEngine("6208", sc).run().wall_s / round(args.t_end / 5e-6)
                           for _ in range(args.repeat)]))
    rows["reference step"] = ref
    exudyn_fast = rows["fast mode, 4 x 5 us, Exudyn alone"]
    rows["fast mode floor ratio"] = (exudyn_fast + 4 * ref) / (4 * ref)
    print(f"reference engine step (5 us): {ref * 1e6:.2f} us; fast mode, 4 sub-steps, floor: (Exudyn alone "
          f"{exudyn_fast * 1e6:.2f} + 4 x {ref * 1e6:.2f}) / (4 x {ref * 1e6:.2f}) = {rows['fast mode floor ratio']:.2f} "
          f"x the reference core; measured {rows['fast mode, 4 x 5 us, full element'] / (4 * ref):.2f}")
    (HERE.parent / "out").mkdir(exist_ok=True)
    (HERE.parent / "out" / "bench_overhead.json").write_text(json.dumps(rows, indent=2))


if __name__ == "__main__":
    main()
