"""Bad-input and hard-case fuzz of the command line and the Python API, as a new user would try them.

Each case runs in a fresh process (so a hang, a crash or a stray traceback is seen as a user sees it) and is
classified by what came out:

* ``error``     exit status 2 or 3 with the CLI's one-line ``exudyn-bearing: error: ...`` (CLI), or an
                ``InputError`` / ``SimulationError`` message (API cases print ``REFUSED: <message>``);
* ``warning``   finished, with a warning on stderr;
* ``ok``        finished without a warning;
* ``nan``       finished and printed a NaN or inf where a number belongs;
* ``traceback`` an exception other than the package's own errors reached the user;
* ``hang``      did not end within the case's time limit (``--timeout``).

A case states what a user should get: ``refuse`` (an error naming ``word``), ``flag`` (an error or a warning
naming ``word``: the input is outside what the model represents, and the run says so) or ``clean`` (it runs,
no warning, no NaN). A case passes when the outcome matches and ``word`` is in the message. The cases are
those of the robustness rounds (the third round lists them by item: item1 ... item11); add new ones to ``CASES``.

    python validation/consistency/fuzz_inputs.py                 # all cases, a table, out/fuzz_inputs.json
    python validation/consistency/fuzz_inputs.py --only item1    # the cases whose id starts with item1
    python validation/consistency/fuzz_inputs.py --list          # ids and what each case expects

Exit status: the number of failed cases (capped at 100), 0 when all pass.
"""
from __future__ import annotations

import argparse
import json
import re
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]

#: Python run before every API case: the package, and a 2.5 kg shaft on an outer-ring marker on ground
#: (tests/test_levels.py's rotor) for the bearing levels; ``report(f)`` runs f and prints REFUSED on the
#: package's errors so that they are told apart from internal exceptions.
PRELUDE = r'''
import math, sys, warnings
import numpy as np
import exudyn as exu
from exudyn.itemInterface import (LoadForceVector, LoadTorqueVector, MarkerBodyRigid, NodeRigidBodyRxyz,
                                  ObjectConnectorRigidBodySpringDamper, ObjectGround, ObjectRigidBody)
import exudyn_bearing as eb
from exudyn_bearing.data import InputError
from exudyn_bearing.model.stability import SimulationError
warnings.simplefilter("default")

def shaft(force=(3000.0, 0.0, 0.0), torque=(0.0, 0.0, 0.0), omega=0.0):
    sc = exu.SystemContainer(); mbs = sc.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    node = mbs.AddNode(NodeRigidBodyRxyz(referenceCoordinates=[0.0] * 6,
                                         initialVelocities=[0, 0, 0, 0, 0, omega]))
    body = mbs.AddObject(ObjectRigidBody(nodeNumber=node, mass=2.5, inertia=[0.01, 0.01, 5e-4, 0, 0, 0]))
    m_g = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground)); m_b = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body))
    mbs.AddLoad(LoadForceVector(markerNumber=m_b, loadVector=list(force)))
    if any(torque):
        mbs.AddLoad(LoadTorqueVector(markerNumber=m_b, loadVector=list(torque)))
    mbs.AddObject(ObjectConnectorRigidBodySpringDamper(markerNumbers=[m_g, m_b],
                  damping=np.diag([2e4, 2e4, 2e4, 20.0, 20.0, 0.0])))
    return sc, mbs, node, m_b, m_g

def run_level(model="linear", force=(3000.0, 0.0, 0.0), torque=(0.0, 0.0, 0.0), omega=0.0, t_end=0.03,
              bearing="6208", **options):
    sc, mbs, node, m_b, m_g = shaft(force, torque, omega)
    br = eb.CreateBallBearing(mbs, bearing, m_b, m_g, model=model, **options)
    mbs.Assemble()
    ss = br.SimulationSettings(t_end)
    mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    pos = mbs.GetNodeOutput(node, exu.OutputVariableType.Position)
    print("position [um]:", [round(1e6 * x, 3) for x in pos])

def report(f):
    try:
        f()
    except (InputError, SimulationError) as exc:
        print("REFUSED:", exc)
'''


@dataclass(frozen=True)
class Case:
    id: str           #: item of the round and a short name
    expect: str       #: refuse | flag | clean
    word: str         #: a word the message must contain (case-insensitive); "" for clean
    cli: tuple = ()   #: arguments of ``python -m exudyn_bearing`` ...
    api: str = ""     #: ... or Python run after PRELUDE
    timeout: float = 0.0  #: own time limit [s] (0: the command line's --timeout)


def _qs(*args):
    return ("quasistatic", *args)


#: simulate on the DEM papers' case (loads and speed default to 0; a dynamic run needs a speed)
_SIM = ("simulate", "6208", "--Fr", "3000", "--omega", "500", "--no-progress")
_TAB500 = "coefficientSpeeds=[0.0, 250.0, 500.0]"

CASES = [
    # 1. the linear level away from its operating point
    Case("item1_linear_at_point", "clean", "",
         api=f"report(lambda: run_level(initialLoad=(3000, 0), {_TAB500}))"),
    Case("item1_linear_reversed_load", "flag", "quasistatic",
         api=f"report(lambda: run_level(force=(-3000.0, 0, 0), initialLoad=(3000, 0), {_TAB500}))"),
    Case("item1_linear_load_along_y", "flag", "quasistatic",
         api=f"report(lambda: run_level(force=(0, 3000.0, 0), initialLoad=(3000, 0), loadAngle=0.0, {_TAB500}))"),
    Case("item1_linear_moment", "flag", "quasistatic",
         api=f"report(lambda: run_level(torque=(0, 20.0, 0), initialLoad=(3000, 0), {_TAB500}))"),
    Case("item1_linear_speed_beyond_table", "flag", "quasistatic",
         api=f"report(lambda: run_level(omega=2000.0, initialLoad=(3000, 0), initialOmega=2000.0, {_TAB500}))"),
    Case("item1_linear_foreign_table", "refuse", "coefficients",
         api="report(lambda: run_level(initialLoad=(1000, 2000), coefficients=eb.bearing_coefficients('7208', "
             "[0.0, 100.0], Fr=1000.0, Fa=2000.0)))"),
    Case("item1_load_angle_100", "refuse", "loadAngle",
         api=f"report(lambda: run_level(initialLoad=(3000, 0), loadAngle=100.0, {_TAB500}))"),
    # 3. traction resolution
    Case("item3_strips_1", "flag", "strips",
         cli=_qs("ACBB-120", "--Fa", "22240", "--rpm", "25000", "--strips", "1")),
    Case("item3_strips_2", "flag", "strips",
         cli=_qs("ACBB-120", "--Fa", "22240", "--rpm", "25000", "--strips", "2")),
    Case("item3_strips_5000", "refuse", "strips", cli=_qs("6208", "--Fr", "3000", "--strips", "5000")),
    Case("item3_simulate_strips_300", "refuse", "strips",
         cli=(*_SIM, "--traction-level", "ellipse", "--strips", "300", "--t-end", "1e-4")),
    Case("item3_thermal_points_across_1", "flag", "points",
         cli=_qs("ACBB-120", "--Fa", "22240", "--rpm", "25000", "--thermal", "--oil-inlet-temperature", "350",
                 "--oil-flow", "6e-5", "--points-across", "1")),
    # 4. interrupts and limits
    Case("item4_memory_under_ulimit", "refuse", "sample",
         api="import resource; resource.setrlimit(resource.RLIMIT_AS, (3 * 2**30, 3 * 2**30))\n"
             "from exudyn_bearing.cli import main\n"
             "sys.exit(main(['simulate', '6208', '--Fr', '3000', '--omega', '500', '--t-end', '2', '--sample-dt', '1e-6', '--dt', '1e-6', "
             "'--no-progress']))"),
    # 5. zero relative speed
    Case("item5_rings_same_speed", "clean", "",
         cli=_qs("6208", "--Fr", "3000", "--omega", "500", "--omega-outer", "500")),
    Case("item5_omega_0", "clean", "", cli=_qs("6208", "--Fr", "3000", "--omega", "0")),
    # 6. options accepted and ignored
    Case("item6_oil_fraction_without_drag", "refuse", "ball-drag",
         cli=(*_SIM, "--oil-volume-fraction", "0.05", "--t-end", "1e-4")),
    Case("item6_hysteresis_without_rolling_resistance", "refuse", "rolling",
         cli=(*_SIM, "--hysteresis-loss-factor", "0.01", "--no-rolling-resistance", "--t-end", "1e-4")),
    Case("item6_ambient_without_thermal", "refuse", "thermal",
         cli=_qs("6208", "--Fr", "3000", "--ambient-temperature", "300")),
    Case("item6_ambient_20K", "refuse", "ambient",
         cli=_qs("6208", "--Fr", "3000", "--omega", "500", "--thermal", "--oil-inlet-temperature", "320",
                 "--oil-flow", "1e-5", "--ambient-temperature", "20")),
    Case("item6_fix_twice", "refuse", "fix",
         cli=_qs("6208", "--Fr", "3000", "--fix", "delta_a=0", "--fix", "delta_a=1e-6")),
    # 7. the ball element: RK44 with history friction
    Case("item7_element_rk44_history", "refuse", "history",
         api="def f():\n"
             "    sc, mbs, node, m_b, m_g = shaft()\n"
             "    br = eb.CreateBallBearing(mbs, '6208', m_b, m_g, model='balls', friction='history')\n"
             "    mbs.Assemble()\n"
             "    ss = br.SimulationSettings(1e-4, solverType='RK44')\n"
             "    mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)\n"
             "report(f)"),
    # 8. API calls that ended in internal exceptions
    Case("item8_thermal_start_str", "refuse", "start",
         api="report(lambda: eb.solve_thermal('6208', 3000.0, omega=500.0, oil_inlet_temperature=320.0, "
             "oil_flow=1e-5, start='abc'))"),
    Case("item8_thermal_start_solution", "clean", "",  # accepted: a quasi-static solution is a start
         api="s = eb.solve_quasistatic('6208', 3000.0, omega=500.0)\n"
             "report(lambda: eb.solve_thermal('6208', 3000.0, omega=500.0, oil_inlet_temperature=320.0, "
             "oil_flow=1e-5, start=s))"),
    Case("item8_thermal_loss_options_str", "refuse", "loss_options",
         api="report(lambda: eb.solve_thermal('6208', 3000.0, omega=500.0, oil_inlet_temperature=320.0, "
             "oil_flow=1e-5, loss_options='abc'))"),
    Case("item8_thermal_temperatures", "refuse", "temperatures",
         api="report(lambda: eb.solve_thermal('6208', 3000.0, omega=500.0, oil_inlet_temperature=320.0, "
             "oil_flow=1e-5, temperatures={'inner': 300.0}))"),
    Case("item8_power_losses_str", "refuse", "solution",
         api="from exudyn_bearing.solvers.quasistatic.losses import power_losses\n"
             "report(lambda: power_losses('abc'))"),
    Case("item8_linear_coefficients_str", "refuse", "coefficients",
         api="report(lambda: run_level(initialLoad=(3000, 0), coefficients='abc'))"),
    Case("item8_quasistatic_coefficients_str", "refuse", "coefficients",
         api="report(lambda: run_level(model='quasistatic', initialLoad=(3000, 0), coefficients='abc'))"),
    # 9. values without a range
    Case("item9_mu_boundary_5", "refuse", "mu_boundary",
         api="import dataclasses\n"
             "report(lambda: dataclasses.replace(eb.data.load_lubricant('guessasma2018'), mu_boundary=5.0))"),
    Case("item9_power_losses_other_bearing", "refuse", "bearing",
         api="from exudyn_bearing.solvers.quasistatic.losses import power_losses\n"
             "s = eb.solve_quasistatic('6208', 3000.0, omega=500.0)\n"
             "report(lambda: power_losses(s, bearing='7208'))"),
    Case("item9_ambient_conductance_key", "refuse", "ambient_conductance",
         api="report(lambda: eb.solve_thermal('6208', 3000.0, omega=500.0, oil_inlet_temperature=320.0, "
             "oil_flow=1e-5, ambient_conductance={'innr': 1.0}))"),
    Case("item9_thermal_pocket_clearance_33", "refuse", "cage_pocket_clearance",
         api="report(lambda: eb.solve_thermal('6208', 3000.0, omega=500.0, oil_inlet_temperature=320.0, "
             "oil_flow=1e-5, cage_pocket_clearance=33.0))"),
    Case("item9_coefficients_speed_str", "refuse", "speeds",
         api="report(lambda: eb.bearing_coefficients('6208', '500'))"),
    Case("item9_info_omega_1e9", "refuse", "omega", cli=("info", "6208", "--omega", "1e9")),
    Case("item9_clearance_in_um", "refuse", "Pd", cli=_qs("6208", "--Fr", "3000", "--Pd", "12")),
    # 10. the cause named
    Case("item10_shoulder_by_speed", "refuse", "speed",
         cli=_qs("7208", "--Fr", "3000", "--Fa", "3000", "--rpm", "8000")),
    # 11. step-dependent friction outputs of the point level
    Case("item11_point_level_friction_marked", "flag", "converged",
         cli=(*_SIM, "--t-end", "2e-3", "--dt", "4e-6", "--ramp", "1e-3", "1e-3", "0", "--json")),
    # the quasi-static solver, its thermal loop, the losses and their commands (round three, items 3-10)
    Case("qs_simulate_strips_257", "refuse", "--strips", cli=("simulate", "--strips", "257")),
    Case("qs_points_across_0", "refuse", "--points-across", cli=_qs("6208", "--Fr", "3000", "--points-across", "0")),
    Case("qs_ambient_without_thermal", "refuse", "--ambient-temperature",
         cli=_qs("6208", "--Fr", "3000", "--omega", "100", "--ambient-temperature", "20")),
    Case("qs_oil_flow_without_thermal", "refuse", "--oil-flow",
         cli=_qs("6208", "--Fr", "3000", "--omega", "100", "--oil-flow", "6e-5")),
    Case("qs_fix_delta_y_twice", "refuse", "--fix delta_y",
         cli=_qs("6208", "--Fr", "3000", "--fix", "delta_y=0", "--fix", "delta_y=1e-6")),
    Case("qs_pd_20", "refuse", "Pd", cli=_qs("6208", "--Fr", "3000", "--Pd", "20")),
    Case("qs_7208_radial_only", "refuse", "Fa", cli=_qs("7208", "--Fr", "3000")),
    Case("static_7208_radial_only", "refuse", "Fa", cli=("static", "7208", "--Fr", "3000")),
    Case("static_negative_fr", "refuse", "Fr", cli=("static", "6208", "--Fr", "-5")),
    Case("qs_fix_unknown_dof", "refuse", "--fix", cli=_qs("6208", "--Fr", "100", "--fix", "tilt_z=0")),
    Case("stiffness_phases_0", "refuse", "--phases", cli=("stiffness", "6208", "--Fr", "3000", "--phases", "0")),
    Case("qs_power_losses_oil_density", "refuse", "oil_density",
         api="from exudyn_bearing.solvers.quasistatic.losses import power_losses\n"
             "report(lambda: power_losses(eb.solve_quasistatic('6208', 3000.0, omega=500.0), oil_density=0.85))"),
    Case("qs_power_losses_pocket_friction", "refuse", "cage_pocket_friction",
         api="from exudyn_bearing.solvers.quasistatic.losses import power_losses\n"
             "report(lambda: power_losses(eb.solve_quasistatic('6208', 3000.0, omega=500.0), "
             "cage_pocket_friction=5.0))"),
    Case("data_race_radius_1000km", "refuse", "outer_race_radius",
         api="report(lambda: eb.load_bearing('6208').replace(outer_race_radius=1e6))"),
    Case("data_pitch_diameter_mm", "refuse", "pitch_diameter",
         api="report(lambda: eb.BallBearing.from_dimensions(9, 12.7e-3, 60.6, 0.52, 0.52))"),
    Case("data_clearance_um", "refuse", "diametral_clearance",
         api="report(lambda: eb.BallBearing.from_dimensions(9, 12.7e-3, 60.6e-3, 0.52, 0.52, "
             "diametral_clearance=20))"),
    Case("data_roughness_1e-15", "refuse", "roughness_race", api="report(lambda: eb.Lubricant(roughness_race=1e-15))"),
    Case("scenario_oil_fraction_without_drag", "refuse", "oil_volume_fraction",
         api="report(lambda: eb.Scenario(oil_volume_fraction=0.05))"),
    Case("scenario_hysteresis_without_rolling_resistance", "refuse", "hysteresis_loss_factor",
         api="report(lambda: eb.Scenario(hysteresis_loss_factor=0.01))"),
    Case("qs_api_strips_4096", "refuse", "n_strips",
         api="report(lambda: eb.solve_quasistatic('6208', Fr=3000.0, n_strips=4096))"),
    Case("qs_zero_relative_speed_defined", "clean", "",
         api="for w, wo in ((500.0, 500.0), (0.0, 0.0)):\n"
             "    d = eb.solve_quasistatic('6208', Fr=3000.0, omega=w, omega_outer=wo, stiffness=False).to_dict()\n"
             "    assert d['friction_torque_total'] == 0.0 and d['power_loss_total'] == 0.0, d\n"
             "    assert d['energy_residual'] == 0.0, d"),
    Case("qs_api_coarse_resolution_warned", "flag", "TractionResolutionWarning",
         api="eb.solve_quasistatic('ACBB-120', Fa=22240.0, omega=25000 * math.pi / 30, n_strips=2, n_across=4, "
             "stiffness=False)"),
    # this session: the reduced engine's refusals and the quasi-static solver's inertia check
    Case("s37_reduced_torus_cage", "refuse", "cage", cli=(*_SIM, "--engine", "reduced", "--cage", "torus")),
    Case("s37_reduced_history_friction", "refuse", "friction", cli=(*_SIM, "--engine", "reduced", "--cage", "none")),
    Case("s37_reduced_cageless_runup_collides", "refuse", "reference engine",
         cli=(*_SIM, "--engine", "reduced", "--cage", "none", "--traction-level", "ellipse", "--ramp", "0.01", "0.01",
              "0", "--dt", "2e-5")),
    Case("s37_reduced_nan_load", "refuse", "Fr",
         api="report(lambda: eb.simulate('6208', eb.Scenario(Fr=float('nan'), omega=500.0, cage='none', "
             "traction_level='ellipse'), engine='reduced', progress=False))"),
    Case("s37_simulate_absurd_speed_names_omega", "refuse", "omega",
         cli=("simulate", "6208", "--Fr", "3000", "--omega", "1e9", "--no-progress")),
    Case("s37_reduced_defaults_name_both_changes", "refuse", "friction",
         cli=(*_SIM, "--engine", "reduced")),
    Case("s34_quasistatic_light_balls_flagged", "flag", "inertia",
         cli=_qs("7208", "--Fr", "3000", "--Fa", "3000", "--omega", "500", "--control", "equilibrium", "--cage",
                 "rigid")),
    # outer-ring rotation of the dynamic engines (Scenario.omega_outer): a non-finite speed, an engine that refuses it
    Case("o34_scenario_nan_omega_outer", "refuse", "omega_outer",
         api="report(lambda: eb.Scenario(Fr=3000.0, omega=0.0, omega_outer=float('nan')))"),
    Case("o34_simulate_inf_omega_outer", "refuse", "omega-outer",
         cli=("simulate", "6208", "--Fr", "3000", "--omega", "0", "--omega-outer", "inf", "--no-progress")),
    Case("o34_reduced_refuses_omega_outer", "refuse", "omega_outer",
         cli=(*_SIM, "--engine", "reduced", "--cage", "none", "--traction-level", "ellipse", "--dt", "2e-5",
              "--omega-outer", "100")),
    # the rigid cage's pocket film: on a scene whose cage is the torus, without oil, not a bool
    Case("p34_pocket_film_on_the_torus_cage", "refuse", "pocket_film",
         cli=("simulate", "6208", "--Fr", "3000", "--omega", "500", "--t-end", "0.001", "--pocket-film",
              "--no-progress")),
    Case("p34_pocket_film_without_oil", "refuse", "pocket_film",
         api="report(lambda: eb.Scenario(Fr=3000.0, omega=500.0, cage='rigid', lubrication=False, pocket_film=True))"),
    Case("p34_pocket_film_not_a_bool", "refuse", "pocket_film",
         api="report(lambda: eb.Scenario(Fr=3000.0, omega=500.0, cage='rigid', pocket_film='yes'))"),
    # a start's kinematic hypothesis given without the quasi-static start it chooses
    Case("c34_control_without_quasistatic_start", "refuse", "control",
         cli=("simulate", "6208", "--Fr", "3000", "--omega", "500", "--t-end", "0.001", "--control", "equilibrium",
              "--no-progress")),
    # the reduced engine's step control: a tolerance out of range, and one the reference engine does not take
    Case("t37_tolerance_negative", "refuse", "tolerance",
         api="report(lambda: eb.Scenario(Fr=3000.0, omega=500.0, tolerance=-1e-3))"),
    Case("t37_reference_refuses_tolerance", "refuse", "tolerance",
         cli=("simulate", "6208", "--Fr", "3000", "--omega", "500", "--t-end", "0.001", "--tolerance", "1e-4",
              "--no-progress")),
    # a tolerance below what the step control can meet, a first step below its least step, a lubricant without
    # its viscosity, an --out that is a file: refused before the run, by name
    Case("u38_tolerance_below_floor", "refuse", "tolerance",
         api="report(lambda: eb.Scenario(Fr=3000.0, omega=500.0, tolerance=1e-9))"),
    Case("u38_first_step_below_least", "refuse", "dt",
         cli=("simulate", "6208", "--Fr", "3000", "--omega", "500", "--engine", "reduced", "--cage", "none",
              "--traction-level", "ellipse", "--dt", "1e-8", "--tolerance", "1e-5", "--t-end", "0.001",
              "--no-progress")),
    Case("u38_lubricant_without_viscosity", "refuse", "viscosity",
         api="report(lambda: eb.load_lubricant({'name': 'x', 'pressure_viscosity': 2e-8}))"),
    Case("u38_out_is_a_file", "refuse", "--out",
         cli=("simulate", "6208", "--Fr", "3000", "--omega", "500", "--t-end", "0.001", "--no-progress", "--out",
              "README.md")),
]


def classify(rc, out, err, timed_out):
    """(outcome, message) of a finished (or timed-out) case; module docstring."""
    if timed_out:
        return "hang", ""
    if "Traceback (most recent call last)" in err:
        last = [ln for ln in err.strip().splitlines() if ln.strip()]
        return "traceback", last[-1] if last else ""
    m = re.search(r"exudyn-bearing: error: (.*)", err) or re.search(r"REFUSED: (.*)", out)
    if m:
        return "error", m.group(1).strip()
    if rc not in (0, None):
        return "traceback", (err.strip().splitlines() or [f"exit status {rc}"])[-1]
    if re.search(r"(?<![A-Za-z_])(nan|inf)(?![A-Za-z_])", out, re.IGNORECASE):
        return "nan", next(ln for ln in out.splitlines() if re.search(r"\b(nan|inf)\b", ln, re.IGNORECASE))
    warn = [ln for ln in err.splitlines() if "Warning" in ln or "warning" in ln]
    if warn:
        return "warning", " | ".join(warn)[:400]
    return "ok", ""


def verdict(case, outcome, message, out):
    """True when the outcome is what the case expects (module docstring)."""
    word = case.word.lower()
    if case.expect == "clean":
        return outcome == "ok"
    named = word in message.lower() or (case.expect == "flag" and word in out.lower())
    if case.expect == "refuse":
        return outcome == "error" and named
    return outcome in ("error", "warning", "ok") and named  # flag: said in a message or in the output


def run_case(case, timeout):
    """(outcome, message, stdout, stderr, wall [s]) of one case in a fresh process."""
    cmd = [sys.executable, "-m", "exudyn_bearing", *case.cli] if case.cli else [sys.executable, "-c",
                                                                                PRELUDE + "\n" + case.api]
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=case.timeout or timeout, cwd=ROOT,
                           stdin=subprocess.DEVNULL)
        rc, out, err, timed_out = p.returncode, p.stdout, p.stderr, False
    except subprocess.TimeoutExpired as exc:
        rc, timed_out = None, True
        out = exc.stdout.decode() if isinstance(exc.stdout, bytes) else (exc.stdout or "")
        err = exc.stderr.decode() if isinstance(exc.stderr, bytes) else (exc.stderr or "")
    outcome, message = classify(rc, out, err, timed_out)
    return outcome, message, out, err, time.perf_counter() - t0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--only", default="", help="run the cases whose id starts with this")
    ap.add_argument("--timeout", type=float, default=300.0, help="time limit of a case [s] (default 300)")
    ap.add_argument("--list", action="store_true", help="list the cases and exit")
    ap.add_argument("--out", default=str(ROOT / "out" / "fuzz_inputs.json"), help="JSON record of the run")
    args = ap.parse_args(argv)
    cases = [c for c in CASES if c.id.startswith(args.only)]
    if args.list:
        for c in cases:
            print(f"{c.id:45s} {c.expect:7s} {c.word}")
        return 0
    records, failed = [], 0
    for i, c in enumerate(cases, 1):
        outcome, message, out, err, wall = run_case(c, args.timeout)
        ok = verdict(c, outcome, message, out)
        failed += not ok
        print(f"[{i:2d}/{len(cases)}] {'pass' if ok else 'FAIL'} {c.id:42s} expect {c.expect:6s} got "
              f"{outcome:9s} {wall:6.1f} s  {message[:110]}", flush=True)
        records.append({"id": c.id, "expect": c.expect, "word": c.word, "outcome": outcome, "pass": ok,
                        "message": message, "wall_s": round(wall, 2), "stdout_tail": out[-2000:],
                        "stderr_tail": err[-2000:]})
    Path(args.out).parent.mkdir(parents=True, exist_ok=True)
    Path(args.out).write_text(json.dumps({"cases": records, "failed": failed, "total": len(cases)}, indent=1))
    print(f"{len(cases) - failed} passed, {failed} failed (record: {args.out})")
    return min(failed, 100)


if __name__ == "__main__":
    sys.exit(main())
