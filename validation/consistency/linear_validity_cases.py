"""The linear level away from its operating point: the cases a user tried, at the linear and
the quasi-static level, and whether the linear level's validity check warned.

A 2.5 kg shaft on one 6208 (the shaft of validation/consistency/levels_checks.py: Rxyz node, pure damper to ground
2e4 N s/m, 20 N m s), GeneralizedAlpha at 1e-4 s, 0.03 s, linearised at initialLoad = (3000, 0) N, table
0-500 rad/s:

* the load reversed (-3000 N along x);
* the load along +y with loadAngle = 0;
* 3000 N along x and a moment of 20 N m about y;
* 3000 N along x, spinning at 2000 rad/s (beyond the table);
* at the operating point (3000 N along x, and (3000, 1000) N), from rest and from initialCoordinates (no warning
  expected: a start transient from rest is outside for a while, shorter than the warning's 3.5 ms);
* a 7208's table at (1000, 2000) N given to a 6208 (refused).

Prints the final pose (x, y, z [um], tilt_x, tilt_y [mrad]) of both levels and the linear level's ``validity``.

    python validation/consistency/linear_validity_cases.py
"""
from __future__ import annotations

import warnings

import numpy as np
from levels_checks import shaft


import exudyn_bearing as eb
from exudyn_bearing.solvers.quasistatic.levels.linear import LinearValidityWarning

FR = 3000.0
SPEEDS = [0.0, 250.0, 500.0]
SCALE = np.array([1e6, 1e6, 1e6, 1e3, 1e3])
T_END = 0.03


def run(model, load=(FR, 0.0, 0.0), moment=None, omega=0.0, at_operating_point=False, t_end=T_END, **options):
    sc, mbs, node, m_b, m_g, _pos = shaft(load, omega, moment=moment)
    options.setdefault("initialLoad", (FR, 0.0))
    options.setdefault("coefficientSpeeds", SPEEDS)
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model=model, **options)
    if at_operating_point:
        mbs.SetNodeParameter(node, "initialCoordinates", list(br.initialCoordinates))
    mbs.Assemble()
    ss = br.SimulationSettings(t_end)
    with warnings.catch_warnings(record=True) as caught, eb.filter_exudyn_notes():
        warnings.simplefilter("always")
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    warned = [str(w.message) for w in caught if issubclass(w.category, LinearValidityWarning)]
    return br, br.samples()["displacement"][-1] * SCALE, warned


def main():
    np.set_printoptions(precision=4, suppress=True, linewidth=160)
    cases = {"load reversed (-3000 N along x)": {"load": (-FR, 0.0, 0.0)},
             "load along +y, loadAngle 0": {"load": (0.0, FR, 0.0), "loadAngle": 0.0},
             "moment 20 N m about y": {"moment": (0.0, 20.0, 0.0)},
             "2000 rad/s, table to 500 rad/s": {"omega": 2000.0, "at_operating_point": True},
             "at the operating point, from rest": {},
             "at the operating point (3000, 1000) N, from rest": {"load": (FR, 0.0, 1000.0),
                                                                  "initialLoad": (FR, 1000.0)},
             "at the operating point, from initialCoordinates, 400 rad/s": {"omega": 400.0,
                                                                            "at_operating_point": True}}
    for name, kw in cases.items():
        br, lin, warned = run("linear", **kw)
        _, qs, _ = run("quasistatic", **{k: v for k, v in kw.items() if k != "at_operating_point"})
        v = br.validity
        print(f"{name}:\n    linear      {lin}\n    quasistatic {qs}\n    linear validity: left {v['left']} at "
              f"t = {v['time']}, flags {v['flags']}, outside share {v['outside_share']:.3f} "
              f"({1e3 * v['outside_share'] * T_END:.2f} ms); "
              f"{len(warned)} warning(s)")
        for w in warned:
            print(f"    warning: {w}")
    try:
        t7208 = eb.bearing_coefficients("7208", [0.0], Fr=1000.0, Fa=2000.0)
        run("linear", load=(1000.0, 0.0, 2000.0), initialLoad=(1000.0, 2000.0), coefficients=t7208)
        print("a 6208 given the 7208's table: accepted")
    except eb.InputError as exc:
        print(f"a 6208 given the 7208's table: refused: {exc}")


if __name__ == "__main__":
    main()
