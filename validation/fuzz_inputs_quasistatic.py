"""Bad-input cases of the quasi-static solver, its thermal loop, the losses and their commands (round
three: resolution, zero speed, unused options, argument types, ranges, names), to re-run later: each case
must end in one clean line naming the input (exit status 2 for a command, InputError for the API), a named
warning, or a defined number.

    python validation/fuzz_inputs_quasistatic.py

Prints one line per case (OK or FAIL with what happened) and exits 1 if any case fails. The fast ones
are tests (tests/test_bad_input_round3.py); this script keeps the list whole.
"""
from __future__ import annotations

import contextlib
import io
import math
import sys
import warnings

import exudyn_bearing as eb
from exudyn_bearing import InputError
from exudyn_bearing.cli import main
from exudyn_bearing.data import Lubricant, load_bearing
from exudyn_bearing.data.bearings import BallBearing
from exudyn_bearing.solvers.quasistatic.losses import power_losses
from exudyn_bearing.solvers.quasistatic.solve import TractionResolutionWarning
from exudyn_bearing.solvers.quasistatic.thermal import solve_thermal

JET = ["--thermal", "--oil-inlet-temperature", "353.15", "--oil-flow", "6e-5"]
JET_API = {"oil_inlet_temperature": 353.15, "oil_flow": 6e-5}

#: Commands that must exit 2 with one error line starting with the name given.
COMMANDS = [
    (["quasistatic", "ACBB-120", "--Fa", "22240", "--rpm", "25000", "--strips", "4097"], "argument --strips"),
    (["simulate", "--strips", "257"], "argument --strips"),
    (["quasistatic", "6208", "--Fr", "3000", "--points-across", "0"], "argument --points-across"),
    (["quasistatic", "6208", "--Fr", "3000", "--omega", "100", "--ambient-temperature", "20"],
     "--ambient-temperature"),
    (["quasistatic", "6208", "--Fr", "3000", "--omega", "100", "--ambient-temperature", "20"] + JET,
     "ambient_temperature"),
    (["quasistatic", "6208", "--Fr", "3000", "--omega", "100", "--oil-flow", "6e-5"], "--oil-flow"),
    (["quasistatic", "6208", "--Fr", "3000", "--fix", "delta_y=0", "--fix", "delta_y=1e-6"], "--fix delta_y"),
    (["simulate", "--oil-volume-fraction", "0.05"], "oil_volume_fraction"),
    (["simulate", "--hysteresis-loss-factor", "0.01"], "hysteresis_loss_factor"),
    (["info", "6208", "--omega", "1e9"], "omega"),
    (["quasistatic", "6208", "--Fr", "3000", "--Pd", "20"], "Pd"),
    (["quasistatic", "7208", "--Fr", "3000", "--Fa", "3000", "--rpm", "8000"], "omega"),
    (["quasistatic", "7208", "--Fr", "3000"], "Fa"),
    (["static", "7208", "--Fr", "3000"], "Fa"),
    (["static", "6208", "--Fr", "-5"], "Fr"),
    (["quasistatic", "6208", "--Fr", "100", "--fix", "tilt_z=0"], "--fix"),
    (["stiffness", "6208", "--Fr", "3000", "--phases", "0"], "--phases"),
]


def _sol():
    return eb.solve_quasistatic("6208", Fr=3000.0, omega=500.0, stiffness=False)


#: API calls that must raise InputError starting with the name given.
CALLS = [
    ("solve_thermal(start='abc')", lambda: solve_thermal("6208", 3000.0, omega=500.0, start="abc", **JET_API), "start"),
    ("solve_thermal(loss_options='abc')",
     lambda: solve_thermal("6208", 3000.0, omega=500.0, loss_options="abc", **JET_API), "loss_options"),
    ("solve_thermal(temperatures=...)", lambda: solve_thermal(
        "6208", 3000.0, omega=500.0, temperatures={"inner": 300.0, "outer": 300.0, "ball": 300.0}, **JET_API),
     "temperatures"),
    ("solve_thermal(cage_pocket_clearance=33)",
     lambda: solve_thermal("6208", 3000.0, omega=500.0, cage_pocket_clearance=33.0, **JET_API),
     "cage_pocket_clearance"),
    ("solve_thermal(ambient_conductance={'innr': 1})",
     lambda: solve_thermal("6208", 3000.0, omega=500.0, ambient_conductance={"innr": 1.0}, **JET_API),
     "ambient_conductance"),
    ("power_losses('abc')", lambda: power_losses("abc"), "sol"),
    ("power_losses(bearing='7208')", lambda: power_losses(_sol(), bearing="7208"), "bearing"),
    ("power_losses(oil_density=0.85)", lambda: power_losses(_sol(), oil_density=0.85), "oil_density"),
    ("power_losses(cage_pocket_friction=5)", lambda: power_losses(_sol(), cage_pocket_friction=5.0),
     "cage_pocket_friction"),
    ("race radius 1000 km", lambda: load_bearing("6208").replace(outer_race_radius=1e6), "outer_race_radius"),
    ("pitch diameter in mm", lambda: BallBearing.from_dimensions(9, 12.7e-3, 60.6, 0.52, 0.52), "pitch_diameter"),
    ("clearance in um", lambda: BallBearing.from_dimensions(9, 12.7e-3, 60.6e-3, 0.52, 0.52, diametral_clearance=20),
     "diametral_clearance"),
    ("mu_boundary=5", lambda: Lubricant(mu_boundary=5.0), "mu_boundary"),
    ("roughness_race=1e-15", lambda: Lubricant(roughness_race=1e-15), "roughness_race"),
    ("bearing_coefficients('6208', '500')", lambda: eb.bearing_coefficients("6208", "500", Fr=3000.0), "speeds"),
    ("Scenario(oil_volume_fraction=0.05)", lambda: eb.Scenario(oil_volume_fraction=0.05), "oil_volume_fraction"),
    ("Scenario(hysteresis_loss_factor=0.01)", lambda: eb.Scenario(hysteresis_loss_factor=0.01),
     "hysteresis_loss_factor"),
    ("solve_quasistatic(n_strips=4096)", lambda: eb.solve_quasistatic("6208", Fr=3000.0, n_strips=4096), "n_strips"),
]


def _command(argv, name):
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            rc = main(argv)
        except SystemExit as exc:
            rc = exc.code
    lines = [x for x in err.getvalue().splitlines() if x.startswith("exudyn-bearing: error:")]
    ok = rc == 2 and len(lines) == 1 and lines[0].split("error: ", 1)[1].startswith(name)
    return ok, f"exit {rc}: {lines[0] if lines else err.getvalue().strip()[-200:]}"


def _call(fn, name):
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            fn()
    except InputError as exc:
        return str(exc).startswith(name), str(exc)[:160]
    except Exception as exc:  # noqa: BLE001 (a traceback is the failure this script looks for)
        return False, f"{type(exc).__name__}: {exc}"
    return False, "accepted"


def _defined():
    """Outputs that must be numbers: zero relative speed, a coarse resolution warned."""
    out = []
    for w, wo in ((500.0, 500.0), (0.0, 0.0)):
        d = eb.solve_quasistatic("6208", Fr=3000.0, omega=w, omega_outer=wo, stiffness=False).to_dict()
        good = d["friction_torque_total"] == 0.0 and d["power_loss_total"] == 0.0 and d["energy_residual"] == 0.0
        out.append((f"omega {w:g}, omega_outer {wo:g}: torque {d['friction_torque_total']}", good))
    for ns, na in ((1, 4), (2, 4), (1, 1)):
        with warnings.catch_warnings(record=True) as rec:
            warnings.simplefilter("always")
            s = eb.solve_quasistatic("ACBB-120", Fa=22240.0, omega=25000 * math.pi / 30, n_strips=ns, n_across=na,
                                     stiffness=False)
        warned = any(issubclass(x.category, TractionResolutionWarning) for x in rec)
        out.append((f"ACBB-120 {ns} x {na}: {s.dissipation_total:.4g} W, warned {warned}, needed "
                    f"{s.resolution_check['needed']}", warned))
    return out


def main_(argv=None) -> int:
    fails = 0
    for argv_, name in COMMANDS:
        ok, what = _command(argv_, name)
        fails += not ok
        print(f"{'OK  ' if ok else 'FAIL'} {' '.join(argv_)}: {what}")
    for label, fn, name in CALLS:
        ok, what = _call(fn, name)
        fails += not ok
        print(f"{'OK  ' if ok else 'FAIL'} {label}: {what}")
    for label, ok in _defined():
        fails += not ok
        print(f"{'OK  ' if ok else 'FAIL'} {label}")
    print(f"{fails} failed of {len(COMMANDS) + len(CALLS) + 5}")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main_())
