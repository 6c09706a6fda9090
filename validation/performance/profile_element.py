"""Where an Exudyn step of the bearing element's body mode spends its time (6208, F_r = 3000 N, 500 rad/s, 5 us).

Per Exudyn step (VelocityVerlet, the body mode's solver), medians of
``--repeat`` runs of ``--t-end`` seconds, all in one process:

* the full element: wall time per step, force evaluations per step, and
  Exudyn's own timers (``mbs.sys['dynamicSolver'].timer``: ODE2RHS, which
  holds the user-function calls, the linear solve, the rest);
* the element's user function from entry to return (``element._wall``:
  Python wrapper plus compiled kernel);
* the compiled kernel alone (the user function's compiled call,
  ``kernels.body_step`` through numba's entry point, on the element's state
  at the end of a run, timed with ``timeit``);
* the shared contact kernel alone on the same arrays, as the element calls
  it and as it did before (all paths compiled; Hertz cache without the
  film column) (``contact_kernel_times``);
* the parts of the Python wrapper, each timed alone at the end of a run
  (``wrapper_parts``): copying the system's coordinates (replaced by
  views), handing the other
  balls' forces to their object, converting the returned forces, the ring
  speed functions, numba's unboxing of the compiled call's arguments (part
  of the kernel's time; also for the 25 separate arguments the call took
  before ``kernels.ElementState``); the rest is Python bookkeeping;
* Exudyn alone: the same items with a user function that returns the last
  force vector at once (Exudyn's step, its Python call and the conversion of
  the coordinates and of the returned forces, no bearing), and with no user
  function at all (Exudyn's integration of the nodes);
* the reference engine on the same scene and step (``validation/performance/bench_reference.py``'s scene).

The Exudyn boundary per step is the difference "Exudyn alone (constant user function)" - "no user
function"; the Python wrapper is "user function" - "kernel". The floor is the cheaper Exudyn-alone step
plus the reference engine's whole step: what the body mode would cost with the physics at the reference
engine's speed and no wrapper at all.

    python validation/performance/profile_element.py [--t-end 0.02] [--repeat 5]
"""
from __future__ import annotations

import argparse
import json
import timeit
import warnings
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.solvers.element.engine import ExudynEngine, solve_dynamic
from exudyn_bearing.solvers.reference import ReferenceEngine

HERE = Path(__file__).resolve().parent
SCENE = dict(Fr=3000.0, omega=500.0, sample_dt=1e-3, dt=5e-6)
TIMERS = ("ODE2RHS", "newtonIncrement", "massMatrix", "integrationFormula", "writeSolution", "python", "overhead",
          "total")


def body_run(t_end, variant="full"):
    """One body-mode run; ``variant``: "full", "constant" (a user function returning the last forces) or
    "none" (no force user function). Returns a dict of per-step times [s] and counts."""
    eng = ExudynEngine("6208", eb.Scenario(t_end=t_end, **SCENE))
    el = eng.element
    mbs = eng.mbs
    ss = el.SimulationSettings(t_end)
    ss.show.computationTime = True  # fills Exudyn's timers (printed only with Exudyn's output, kept off here)
    n = ss.timeIntegration.numberOfSteps
    if variant != "full":
        obj = el.items["object"]
        # what the user function returns: the forces of its object's coordinates (a list in the two-object
        # layout, the whole array in the single-object one)
        ret = el._out[el._out_uf_index].tolist() if el.items.get("ballObject") is not None else el._out
        mbs.SetObjectParameter(obj, "forceUserFunction",
                               (lambda mbs_, t, i, q, q_t: ret) if variant == "constant" else 0)
    t0 = timeit.default_timer()
    try:
        solve_dynamic(mbs, ss)
    except Exception:  # noqa: BLE001 - without the bearing's forces the ring may leave the balls
        pass
    wall = timeit.default_timer() - t0
    timer = mbs.sys["dynamicSolver"].timer
    row = dict(step=wall / n, evaluations=el._evaluations / n, uf=el._wall / n)
    row.update({k: getattr(timer, k) / n for k in TIMERS})
    if variant == "full":
        row["kernel"] = kernel_time(el)
        row.update(wrapper_parts(el))
        row.update(contact_kernel_times(el))
    return row


def _body_args(el):
    """The arguments of the body mode's compiled call (kernels.body_step) at the end of a run: the system's
    coordinates, the element's state, its last evaluated time (no commit, no energy step) and the paths."""
    sd = el.mbs.systemData
    return (sd.GetODE2Coordinates(), sd.GetODE2Coordinates_t(), el._state, el._t_trial, el.n_cage, *el._paths)


def kernel_time(el, number=2000):
    """Seconds per call of the body mode's compiled call (kernels.body_step through numba's entry point, as
    the user function calls it) on the element's state at the end of the run."""
    from exudyn_bearing.solvers.element import kernels as EK
    from exudyn_bearing.solvers.element.userfunctions import entry_point

    args = _body_args(el)
    step = entry_point(EK.body_step, args)
    return _best(lambda: step(*args), number)


def contact_kernel_times(el, number=2000):
    """Seconds per call of the shared contact kernel alone (model.contact.forces through numba's entry
    point) on the element's arrays at the end of a run: as the element calls it (its scene's paths, the
    Hertz cache with the film column), and with every path compiled (defect, ellipse and loss code, as the
    element compiled it before)."""
    from exudyn_bearing.model.contact import forces
    from exudyn_bearing.solvers.element.userfunctions import entry_point

    w, z = el._work, el.z

    def args(hz, paths):
        return (el.params, el.table, w[0, :z], w[1, :z], w[2, :z], w[3], w[4], el._rings, el._hist,
                el._hist_trial.copy(), 5e-6, hz.copy(), w[5, :z].copy(), w[6, :z].copy(), w[7].copy(), el._fr.copy(),
                el._glob.copy(), el._diag.copy(), el._cage_load.copy(), False, *paths)

    times = {}
    for name, hz, paths in (("contact_kernel", el._hz, el._paths), ("contact_kernel_all_paths", el._hz, ())):
        a = args(hz, paths)
        call = entry_point(forces, a)
        times[name] = _best(lambda call=call, a=a: call(*a), number)
    return times


def _best(fn, number):
    fn()
    return min(timeit.repeat(fn, number=number, repeat=5)) / number


def wrapper_parts(el, number=20000):
    """Seconds per call of the parts of the body mode's user function outside the compiled physics, each
    timed alone (timeit, best of 5) on the element at the end of a run: reading copies of the system's
    coordinates and velocities (two GetODE2Coordinates calls, which the user function no longer makes: it
    reads views of Exudyn's vectors taken at the run's start), handing the other balls' forces to their object
    (SetObjectParameter), converting the returned forces to a list, the prescribed ring speed functions,
    and numba's entry point unboxing the compiled call's arguments (a compiled function that does nothing,
    with the arguments of kernels.body_step: the element's state as one structure, and for comparison with
    the 25 separate arrays and scalars the user function passed before kernels.ElementState, into a
    function compiled with numba's memory runtime as that call was: the runtime's reference counting of
    every array argument is most of its cost)."""
    import numba

    from exudyn_bearing.solvers.element.userfunctions import entry_point

    sd, mbs = el.mbs.systemData, el.mbs
    ball, out_balls, out_uf = el._ball_object, el._out_balls, el._out_uf
    t = el._t_trial
    speeds = el._speeds
    args = _body_args(el)
    args25 = (args[0], args[1], el._sys_index, np.zeros(el.ref.size), np.zeros(el.ref.size), el.ref, el.params, el.table, el.z,
              el.n_cage, el._ring_kind, el._ring_data, el._hist, el._hist_trial, 5e-6, el._hz, el._work, el._rings,
              el._fr, el._glob, el._diag, el._cage_load, False, 0.0, el._out)

    @numba.njit
    def nothing(qs, qs_t, st, t, n_cage, defect_path, ellipse_path, loss_path):
        return 0.0

    @numba.njit
    def nothing25(qs, qs_t, index, q, q_t, ref, p, table, z, n_cage, ring_kind, ring_data, hist, hist_out, dt_hist,
                  hz, work, rings, fr, glob, diag, cage_load, want, dt_energy, out):
        return 0.0

    unbox = entry_point(nothing, args)
    unbox25 = entry_point(nothing25, args25)
    return {"get_coordinates": _best(lambda: (sd.GetODE2Coordinates(), sd.GetODE2Coordinates_t()), number),
            "set_force_vector": _best(lambda: mbs.SetObjectParameter(ball, "forceVector", out_balls), number),
            "return_list": _best(out_uf.tolist, number),
            "speed_functions": _best(lambda: [f(t) for _r, f in speeds], number),
            "unbox_state": _best(lambda: unbox(*args), number),
            "unbox_25": _best(lambda: unbox25(*args25), number)}


def step_args(argv, doc):
    """--t-end and --repeat of the per-step scripts (this one and bench_overhead.py), warnings off."""
    ap = argparse.ArgumentParser(description=doc.split("\n")[0])
    ap.add_argument("--t-end", type=float, default=0.02)
    ap.add_argument("--repeat", type=int, default=5)
    warnings.simplefilter("ignore")
    return ap.parse_args(argv)


def main(argv=None):
    args = step_args(argv, __doc__)
    body_run(1e-3)  # compile / load the caches
    ReferenceEngine("6208", eb.Scenario(t_end=1e-3, **SCENE)).run()
    rows = {v: [] for v in ("full", "constant", "none")}
    ref = []
    for _ in range(args.repeat):  # interleaved: the machine's load moves all alike
        for v in rows:
            rows[v].append(body_run(args.t_end, v))
        rec = ReferenceEngine("6208", eb.Scenario(t_end=args.t_end, **SCENE)).run()
        ref.append(rec.wall_s / round(args.t_end / SCENE["dt"]))
    med = {v: {k: float(np.median([r[k] for r in rs])) for k in rs[0]} for v, rs in rows.items()}
    f, c, n = med["full"], med["constant"], med["none"]
    us = 1e6
    print(f"6208, Fr = 3000 N, 500 rad/s, body mode, VelocityVerlet 5 us, T = {args.t_end} s, medians of "
          f"{args.repeat} interleaved runs; per Exudyn step [us]:")
    print(f"  full element step                       {f['step'] * us:7.2f}   ({f['step'] / SCENE['dt']:.2f} s wall "
          "per simulated s)")
    print(f"  force evaluations per step              {f['evaluations']:7.3f}")
    print(f"  Exudyn timer ODE2RHS (holds the UF)     {f['ODE2RHS'] * us:7.2f}")
    print(f"  Exudyn timer newtonIncrement (M solve)  {f['newtonIncrement'] * us:7.2f}")
    print("  Exudyn timers massMatrix, integration, writeSolution, python, overhead: "
          + ", ".join(f"{f[k] * us:.2f}" for k in ("massMatrix", "integrationFormula", "writeSolution", "python",
                                                    "overhead")))
    print(f"  user function, entry to return          {f['uf'] * us:7.2f}")
    print(f"  compiled kernel alone                   {f['kernel'] * us:7.2f}")
    print(f"    of it the contact kernel alone        {f['contact_kernel'] * us:7.2f}   (all paths compiled: "
          f"{f['contact_kernel_all_paths'] * us:.2f})")
    print(f"  Python wrapper (UF - kernel)            {(f['uf'] - f['kernel'] * f['evaluations']) * us:7.2f}")
    print("  its parts, each timed alone at the run's end:")
    print(f"    two GetODE2Coordinates calls          {f['get_coordinates'] * us:7.2f}   (not made: the user function "
          "reads views taken at the run's start)")
    print(f"    SetObjectParameter(forceVector)       {f['set_force_vector'] * us:7.2f}")
    print(f"    returned forces to a list             {f['return_list'] * us:7.2f}")
    print(f"    ring speed functions                  {f['speed_functions'] * us:7.2f}")
    print(f"    entry point, unboxing the arguments   {f['unbox_state'] * us:7.2f}   (25 separate ones: "
          f"{f['unbox_25'] * us:.2f}; in the kernel's time)")
    rest = f["uf"] - f["evaluations"] * (f["kernel"] + f["set_force_vector"] + f["return_list"]
                                         + f["speed_functions"])
    print(f"    the rest (Python bookkeeping)         {rest * us:7.2f}")
    print(f"  Exudyn alone, constant user function    {c['step'] * us:7.2f}")
    print(f"  Exudyn alone, no user function          {n['step'] * us:7.2f}")
    print(f"  Exudyn boundary (constant UF - none)    {(c['step'] - n['step']) * us:7.2f}")
    print("  no user function, Exudyn timers ODE2RHS, newtonIncrement, writeSolution, overhead: "
          + ", ".join(f"{n[k] * us:.2f}" for k in ("ODE2RHS", "newtonIncrement", "writeSolution", "overhead")))
    print(f"  rest (full - UF - constant-UF step)     {(f['step'] - f['uf'] - c['step']) * us:7.2f}")
    print(f"  reference engine, same scene and step   {np.median(ref) * us:7.2f}   "
          f"({np.median(ref) / SCENE['dt']:.2f} s wall per simulated s)")
    # the floor: Exudyn's own step (the cheaper of "no user function" and "constant user function") plus the
    # reference engine's whole step for the physics, with no wrapper at all
    exudyn_step = min(c["step"], n["step"])
    floor = exudyn_step + np.median(ref)
    print(f"  floor: Exudyn's own step {exudyn_step * us:.2f} + the reference step = {floor * us:.2f} us "
          f"({floor / SCENE['dt']:.2f} s wall per simulated s; Exudyn's step alone "
          f"{exudyn_step / SCENE['dt']:.2f})")
    (HERE.parent / "out").mkdir(exist_ok=True)
    (HERE.parent / "out" / "profile_element.json").write_text(json.dumps(dict(median=med, reference=float(np.median(ref)), floor=float(floor),
                                                                       t_end=args.t_end), indent=2))


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced."""
    return run.printed(
        "Where the element's step time goes",
        "The Exudyn element's body mode on the bench_element scene (6208, 3000 N, 500 rad/s, VelocityVerlet "
        "5 us): per step, the compiled kernel, the Python user function around it, Exudyn's conversion of "
        "coordinates and forces, Exudyn's own step without a user function, against the reference engine's "
        "step on the same scene (medians of repeats).",
        last_lines=30)


if __name__ == "__main__":
    main()
