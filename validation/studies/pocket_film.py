"""The ball / pocket oil film against the dry pocket (docs/theory/cage.md#pocket-oil-film).

Two scenes, each run dry (the validated default: Hertz contact with Coulomb friction) and with
``Scenario(pocket_film=True)`` (the film's hydrodynamic and squeeze forces inside the pocket clearance), in the
reference engine:

* the 6208 radial case (F_r = 3000 N, 500 rad/s) with its estimated outer-land brass cage, 2 us, point
  traction (the scene's defaults), from the analytic start, --t-end;
* the 7208 at F_r = F_a = 3000 N, 500 rad/s, its estimated rigid cage, point traction with the regularised
  friction (the point level's Cundall-Strack spring is not converged in the step on this case), implicit cage
  damping, from the analytic start, at --dt-7208 (default 1 us, the fine step of
  validation/studies/rigid_cage.py's step convergence), --t-end;
* with --energy-steps, the 7208 scene of validation/studies/rigid_cage.py's cost comparison (the scene's
  defaults, the Cundall-Strack spring) at 5, 2.5 and 1.25 us, dry and with the film: the energy residual,
  the pocket loss and the dissipation at each step (how the film's explicit force converges in the step).

Printed per run (summary over the second half of the run, named): the stable step, the pocket film's own
stable step (``model.stability.pocket_film_step``, inf when dry), the
pocket force (largest and time mean), the pocket and land losses, the dissipation, the cage speed, the cage
motion's class and orbit, the energy residual, and the wall time. Writes pocket_film.json into --out.

    python validation/studies/pocket_film.py [--t-end 0.2] [--dt-7208 1e-6] [--energy-steps]
        [--out validation/out/pocket_film]
"""
from __future__ import annotations

import argparse
import json
import time
import warnings
from pathlib import Path

import exudyn_bearing as eb
from exudyn_bearing.data.catalog import default_lubricant
from exudyn_bearing.model.stability import pocket_film_step

ROOT = Path(__file__).resolve().parents[2]
KEYS = ("stable_dt", "pocket_film_step", "pocket_force_max", "pocket_force_mean", "cage_power_pocket", "cage_power_land", "dissipation",
        "cage_speed", "cage_motion", "cage_orbit_ratio", "q_max_inner", "energy_residual")


def scenes(dt_7208):
    return {
        "6208 radial, Fr 3000 N, 500 rad/s, 2 us": ("6208", dict(Fr=3000.0, omega=500.0, dt=2e-6)),
        f"7208 Fr = Fa = 3000 N, 500 rad/s, {dt_7208 * 1e6:g} us": (
            "7208", dict(Fr=3000.0, Fa=3000.0, omega=500.0, dt=dt_7208, cage_damping="implicit",
                         friction="regularized")),
    }


def run(bearing, fields, t_end, film):
    sc = eb.Scenario(**fields, cage="rigid", pocket_film=film, t_end=t_end, sample_dt=1e-4)
    b = eb.catalog[bearing]
    film_step = pocket_film_step(b, sc, default_lubricant(b))
    t0 = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        res = eb.simulate(bearing, sc, progress=False)
        s = res.summary(fraction=0.5)
    out = {k: s.get(k) for k in KEYS if k != "pocket_film_step"}
    out["window"] = s.get("window")
    out["pocket_film_step"] = film_step
    out["wall_s"] = time.perf_counter() - t0
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--t-end", type=float, default=0.2)
    ap.add_argument("--dt-7208", type=float, default=1e-6)
    ap.add_argument("--energy-steps", action="store_true", help="also the 7208's energy residual against the step")
    ap.add_argument("--out", type=Path, default=ROOT / "validation" / "out" / "pocket_film")
    a = ap.parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)
    rows = {}
    for name, (bearing, fields) in scenes(a.dt_7208).items():
        for film in (False, True):
            label = f"{name}, {'pocket film' if film else 'dry pockets'}"
            rows[label] = r = run(bearing, fields, a.t_end, film)
            print(f"{label}: window {r['window']}", flush=True)
            for k in KEYS:
                print(f"    {k:18s} {r[k]}")
            print(f"    {'wall_s':18s} {r['wall_s']:.1f}", flush=True)
    if a.energy_steps:
        print("7208, the scene's defaults (Cundall-Strack spring), implicit cage damping: energy residual, pocket "
              "loss [W], dissipation [W] against the step")
        for dt in (5e-6, 2.5e-6, 1.25e-6):
            for film in (False, True):
                fields = dict(Fr=3000.0, Fa=3000.0, omega=500.0, dt=dt, cage_damping="implicit")
                r = run("7208", fields, a.t_end, film)
                rows[f"7208 energy, {dt * 1e6:g} us, {'pocket film' if film else 'dry pockets'}"] = r
                print(f"    {dt * 1e6:5.3g} us {'film' if film else 'dry '}  energy residual {r['energy_residual']:+.2e}  "
                      f"pocket {r['cage_power_pocket']:.4g}  dissipation {r['dissipation']:.4g}", flush=True)
    (a.out / "pocket_film.json").write_text(json.dumps(rows, indent=1, default=str))
    print(f"wrote {a.out / 'pocket_film.json'}")


if __name__ == "__main__":
    main()
